# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 4. Other indenters: power laws `f = c rⁿ` and the flat punch
#
# The MDR holds for any axisymmetric profile: the Abel transform (3) gives the
# springs' profile `g(x)`, and Heß's rule (8) does the rest as for the
# paraboloid in notebook 1. Every expression below is the one
# `mdr_events.power_law` evaluates (`symbolic.derive_power_law_model()`);
# each step ends with a check against the paper's paraboloid, a literature
# result or an independent numerical route.

# %%
import math

import numpy as np
import sympy as sp
from scipy import integrate, optimize

import mdr_events as me
from mdr_events import FlatPunch, PowerLaw, power_law
from mdr_events.theory import symbolic
from mdr_events.theory.symbolic import relation

S = symbolic
contact = me.Contact.paper()  # the paper's elastomer, paraboloid, adhesion and τ0
d_max = me.Scenario("A").d_max  # the paper's depth (0.3 mm), a motion's
p = contact.parameters(d_max, me.Scenario("A").v)  # the flat record mdr_events.power_law's functions take

# %% [markdown]
# ## Step 1 — the equivalent profile
# `g(x) = κₙ c xⁿ` with `κₙ = √π Γ(n/2 + 1) / Γ(n/2 + 1/2)`: 2 for the
# paraboloid, π/2 for the cone.

# %%
relation("profile_power_law").eq

# %%
kappa = relation("profile_power_law").rhs.subs({S.x: 1, S.c: 1})
assert sp.simplify(kappa.subs(S.n, 2) - 2) == 0 and sp.simplify(kappa.subs(S.n, 1) - sp.pi / 2) == 0

# %% [markdown]
# ## Step 2 — Heß's rule: the adhesive branch and its force
# The boundary spring holds while stretched by at most `sqrt(2π a Δγ / E*)`:

# %%
relation("power_law_depth").eq

# %%
relation("power_law_branch_normal_force").eq

# %% [markdown]
# At `n = 2, c = 1/(2R)` these are (9) and (10), exactly; at `n = 1,
# c = tan θ` without adhesion the cone's force is Sneddon's `(π/2) E* a² tan θ`.

# %%
paraboloid = {S.n: 2, S.c: 1 / (2 * S.R)}
assert sp.simplify(relation("power_law_depth").rhs.subs(paraboloid) - relation("jkr_depth").rhs) == 0
assert sp.simplify(relation("power_law_branch_normal_force").rhs.subs(paraboloid)
                   - relation("jkr_normal_force").rhs) == 0
cone = {S.n: 1, S.c: sp.tan(S.theta), S.dgamma: 0}
assert sp.simplify(relation("power_law_branch_normal_force").rhs.subs(cone)
                   - sp.pi / 2 * S.E_star * S.a**2 * sp.tan(S.theta)) == 0

# %% [markdown]
# ## Step 3 — jump-in, pull-off, jump-off
# `dF_N/da = 0` (force control) and `dd/da = 0` (displacement control) are
# powers of `a` against `√a`: closed forms with the exponent `1/(2n − 1)`.
# Under force control `a^(2n−1) = 9π Δγ / (2 E* n² (κc)²)` (JKR's
# `9πΔγR²/(8E*)` at `n = 2`).

# %%
relation("power_law_pull_off_radius").eq, relation("power_law_jump_off_radius").eq

# %% [markdown]
# An independent route: sum the springs numerically (the quadrature of
# `2E* ∫(d(a) − g(x)) dx`, `d(a)` by Heß's rule) and minimise over `a`.

# %%
profile = PowerLaw(2.0e3, 3.0)
work = p.dgamma1


def springs_force(a):
    depth = float(power_law.equivalent_profile(a, profile)) - math.sqrt(2 * math.pi * a * work / p.E_star)
    value = integrate.quad(lambda t: (depth - float(power_law.equivalent_profile(a * t * t, profile))) * 2 * a * t,
                           0.0, 1.0, epsabs=0.0, epsrel=1e-12)[0]
    return 2 * p.E_star * value


closed = power_law.pull_off_force(profile, p, work)
found = optimize.minimize_scalar(springs_force, bounds=(1e-5, 5e-3), method="bounded", options={"xatol": 1e-12})
print(f"pull-off force: closed form {closed:.9g} N, springs minimised {found.fun:.9g} N")
assert math.isclose(found.fun, closed, rel_tol=1e-9)

# %% [markdown]
# ## Step 4 — the flat punch: Kendall
# All springs have one length `d`; adhesion holds until that reaches Heß's
# limit, and then every spring lets go at once: `F = −sqrt(8π a³ E* Δγ)`.

# %%
relation("flat_punch_pull_off_force").eq

# %%
assert sp.simplify(relation("flat_punch_pull_off_force").rhs
                   + sp.sqrt(8 * sp.pi * S.a**3 * S.E_star * S.dgamma)) == 0

# %% [markdown]
# ## Step 5 — slip onset in scenario A
# On the path (14) the shift `d / tan α` meets the cap `K a(d)`. Without
# adhesion `a ∝ d^(1/n)`, so `d^((n−1)/n) ∝ tan α`: a closed form for
# `n ≠ 1`. The cone has none: its shift and cap grow in proportion, so it
# slides from first contact below `tan α_c = κ c / K` and never above. With
# adhesion the onset (18) has no closed form for general `n`; it is solved
# for (a Newton iteration on a convex function).

# %%
relation("power_law_d_crit_A_hertz").eq

# %%
assert sp.simplify(relation("power_law_d_crit_A_hertz").rhs.subs(paraboloid)
                   - relation("d_crit_A_hertz").rhs) == 0
alpha = 10.0
for n in (1.5, 3.0):
    shape = PowerLaw(2.0e3 if n == 3.0 else 20.0, n)
    depth = power_law.d_crit_A(alpha, shape, p, adhesion=True)
    radius = power_law.contact_radius(depth, shape, p, p.dgamma0)
    assert math.isclose(depth / math.tan(math.radians(alpha)), float(me.critical_shift(radius, contact)), rel_tol=1e-12)

# %% [markdown]
# ## The normal force and the critical angles of four indenters
# The paraboloid of the paper, a cone, a quartic and a flat punch of
# comparable size (each reaching the paraboloid's contact radius at `d_max`
# without adhesion): `F_N` along the `Δγ0` branch, and the critical angles of
# scenarios A and B.

# %%
import matplotlib.pyplot as plt

radius_max = math.sqrt(p.R * p.d_max)


shapes = {"cone (n = 1)": power_law.with_radius_at(1.0, radius_max, p.d_max),  # the paraboloid's radius at d_max
          "paraboloid (n = 2)": PowerLaw.paraboloid(p.R), "quartic (n = 4)": power_law.with_radius_at(4.0, radius_max,
                                                                                                     p.d_max)}
punch = FlatPunch(radius_max)
fig, (ax_force, ax_angle) = plt.subplots(1, 2, figsize=(12, 4.6), constrained_layout=True)
for name, shape in shapes.items():
    depth = np.linspace(power_law.jump_off(shape, p, p.dgamma0)["depth"], 1.3 * p.d_max, 300)
    a = power_law.contact_radius(depth, shape, p, p.dgamma0)
    ax_force.plot(depth * 1e3, power_law.branch_normal_force(a, shape, p, p.dgamma0), label=name)
depth = np.linspace(power_law.jump_off(punch, p, p.dgamma0)["depth"], 1.3 * p.d_max, 50)
ax_force.plot(depth * 1e3, power_law.normal_force(depth, None, punch, p), label="flat punch")
ax_force.set(xlabel="indentation depth d (mm)", ylabel="normal force F_N (N)", title="F_N on the Δγ0 branch")
ax_force.axhline(0.0, color="0.7", lw=0.8)
ax_force.legend()
names = [*shapes, "flat punch"]
angles_a = [power_law.critical_angle_A(shape, p) for shape in [*shapes.values(), punch]]
angles_b = [power_law.critical_angle_B(shape, p) for shape in [*shapes.values(), punch]]
positions = np.arange(len(names))
ax_angle.bar(positions - 0.2, angles_a, 0.4, label="scenario A: slides while indenting below")
ax_angle.bar(positions + 0.2, angles_b, 0.4, label="scenario B: comes apart before sliding above")
ax_angle.set_xticks(positions, names, rotation=15)
ax_angle.set(ylabel="critical angle (°)", title="critical angles, the paper's material and adhesion")
ax_angle.legend(loc="upper right", fontsize="small")
assert math.isclose(angles_a[1], me.critical_angle(contact, "A", d_max=d_max), rel_tol=1e-12)
assert math.isclose(angles_b[1], me.critical_angle(contact, "B", d_max=d_max), rel_tol=1e-12)
for shape, angle in zip([*shapes.values(), punch], angles_a):  # each indenter's contact draws its phase diagram
    shaped = me.Contact(contact.elastomer, shape, contact.adhesion, contact.friction)
    assert me.phase_diagram(shaped, [20.0], "A", d_max=d_max)["critical_angle_jkr"] == angle
print({name: (round(a_, 3), round(b_, 3)) for name, a_, b_ in zip(names, angles_a, angles_b)})
