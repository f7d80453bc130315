# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 1. Normal adhesive contact in the MDR: from the Abel transform to JKR, eqs. (3)–(10)
#
# Every expression below is the one `mdr_events` itself evaluates
# (`mdr_events.symbolic.relation(key)`); nothing is re-typed. Each step ends
# with a numeric check against an independent computation.

# %%
import math

import numpy as np
import sympy as sp
from scipy import integrate

from mdr_events.theory import symbolic
from mdr_events.theory.symbolic import relation

R, E_STAR, DGAMMA = 0.03, 0.432e6, 0.15

# %% [markdown]
# ## Step 1 — the Abel transform (3)
# `g(x) = |x| ∫_0^{|x|} f'(r) / sqrt(x² − r²) dr`.

# %%
relation("abel_transform").eq

# %% [markdown]
# For the power law `f = c rⁿ`, the substitution `r = x t` turns it into a
# Beta-type integral; SymPy evaluates it (a Gauss hypergeometric at 1):

# %%
power_law = relation("profile_power_law")
power_law.eq

# %%
c_, n_, x_ = 1.7, 1.5, 0.4
quadrature = x_ * integrate.quad(lambda phi: c_ * n_ * (x_ * np.sin(phi)) ** (n_ - 1), 0, np.pi / 2)[0]
assert math.isclose(float(power_law.numeric(x_, c_, n_)), quadrature, rel_tol=1e-11)

# %% [markdown]
# ## Step 2 — the paraboloid (4) and the cone
# `n = 2, c = 1/(2R)` gives `g = x²/R`; `n = 1, c = tan θ` gives `g = (π/2) x tan θ`.

# %%
paraboloid = relation("profile_paraboloid")
assert sp.simplify(power_law.rhs.subs({symbolic.n: 2, symbolic.c: 1 / (2 * symbolic.R)}) - paraboloid.rhs) == 0
paraboloid.eq, relation("profile_cone").eq

# %% [markdown]
# ## Step 3 — springs (7) and Heß's rule (8) give the JKR depth (9)
# The boundary spring at `x = a` is stretched by `−u_z(a) = g(a) − d`; it
# holds as long as that equals `Δl_max = sqrt(2π a Δγ / E*)`. Solving for `d`:

# %%
relation("normal_displacement").eq, relation("hess_max_elongation").eq

# %%
jkr_depth = relation("jkr_depth")
jkr_depth.eq

# %%
a = 2e-3
d = jkr_depth.numeric(a, R, E_STAR, DGAMMA)
assert math.isclose(-relation("normal_displacement").numeric(d, a, R),
                    relation("hess_max_elongation").numeric(a, DGAMMA, E_STAR), rel_tol=1e-13)

# %% [markdown]
# ## Step 4 — the normal force (10)
# Sum of the springs in contact, `F_N = 2E* ∫_0^a (d − g(x)) dx`, first for any
# `(d, a)` (needed while the radius is pinned), then on the JKR branch:

# %%
relation("normal_force").eq, relation("jkr_normal_force").eq

# %%
n_springs = 100_000
dx = 2 * a / n_springs
x = -a + dx * (np.arange(n_springs) + 0.5)
spring_sum = np.sum(E_STAR * dx * (d - x**2 / R))
assert math.isclose(relation("jkr_normal_force").numeric(a, R, E_STAR, DGAMMA), spring_sum, rel_tol=1e-8)

# %% [markdown]
# ## Step 5 — consequences: Hertz, jump-in, pull-off, jump-off
# `Δγ = 0` gives Hertz (16); `d = 0` the jump-in radius; `∂F/∂a = 0` the
# force-controlled pull-off `−(3/2)πΔγR`; `∂d/∂a = 0` the displacement-controlled
# jump-off (force `−(5/6)πΔγR`).

# %%
for key in ("hertz_radius", "hertz_normal_force", "jump_in_radius", "pull_off_radius",
            "pull_off_force", "jump_off_radius", "jump_off_depth", "jump_off_force"):
    print(key, "=", relation(key).rhs)

# %%
radii = np.linspace(1e-4, 5e-3, 200_001)
forces = relation("jkr_normal_force").numeric(radii, R, E_STAR, DGAMMA)
assert math.isclose(forces.min(), relation("pull_off_force").numeric(R, DGAMMA), rel_tol=1e-8)
print("pull-off force", forces.min(), "N")

# %% [markdown]
# ## Step 6 — the JKR curve with the paper's two works of adhesion
# With `mdr_events.Contact.paper()` (the elastomer, the paraboloid of `R = 30` mm, the
# two works of adhesion, `τ0`) and the paper's depth `d_max` (a motion's, `Scenario`): the springs attach with `Δγ0` on the
# way in and come off with `Δγ1` on the way out (Heß's rule with two works of
# adhesion). Each branch is traced parametrically in `a` by (9) and (10), up
# to `d_max`. Under displacement control the part with `∂d/∂a > 0` (`a` above
# the jump-off radius) is stable (solid), the rest unstable (dashed).
# Approaching, the contact jumps in at `d = 0` to the jump-in radius on the
# `Δγ0` branch and follows it to `d_max`; retracting, the radius stays pinned
# (grey: (10) at fixed `a`) until the boundary springs reach Heß's `Δγ1`
# limit, then it follows the `Δγ1` branch down to the jump-off point and comes
# apart there.

# %%
import matplotlib.pyplot as plt

import mdr_events as me
from mdr_events.theory import analytic

contact = me.Contact.paper()
d_max = me.Scenario("A").d_max  # the paper's 0.3 mm
dgamma0, dgamma1 = contact.adhesion.dgamma0, contact.adhesion.dgamma1
branches = {}
for name, work, colour in (("Δγ0 (in)", dgamma0, "tab:blue"), ("Δγ1 (out)", dgamma1, "tab:red")):
    radius = np.linspace(1e-6, float(me.jkr_contact_radius(d_max, contact, work)), 4001)
    branches[name] = dict(work=work, colour=colour, radius=radius, jump_off=me.jump_off(contact, work),
                          depth=me.jkr_depth(radius, contact, work), force=me.jkr_normal_force(radius, contact, work))
a_in = analytic.jump_in_radius(contact, dgamma0)
jump_in = dict(depth=float(me.jkr_depth(a_in, contact, dgamma0)),
               force=float(me.jkr_normal_force(a_in, contact, dgamma0)))
jump_off = me.jump_off(contact, dgamma1)
a_pinned = float(me.jkr_contact_radius(d_max, contact, dgamma0))
pinned_depth = np.linspace(float(me.jkr_depth(a_pinned, contact, dgamma1)), d_max, 200)
pinned_force = analytic.normal_force(pinned_depth, a_pinned, contact)

# the marked points lie where they should: jump-in at d = 0, jump-off at the minimum depth of its
# branch with the force −(5/6)πΔγ1 R; both branches end at d_max; the pinned line meets both branches
assert abs(jump_in["depth"]) < 1e-12 * d_max
out = branches["Δγ1 (out)"]
assert math.isclose(out["depth"].min(), jump_off["depth"], rel_tol=1e-6)
assert abs(out["radius"][out["depth"].argmin()] - jump_off["contact_radius"]) <= out["radius"][1] - out["radius"][0]
assert math.isclose(jump_off["normal_force"], -5 / 6 * math.pi * dgamma1 * contact.indenter.R, rel_tol=1e-12)
for branch in branches.values():
    assert math.isclose(branch["depth"][-1], d_max, rel_tol=1e-12)
assert math.isclose(pinned_force[-1], branches["Δγ0 (in)"]["force"][-1], rel_tol=1e-10)
assert math.isclose(pinned_force[0], float(me.jkr_normal_force(a_pinned, contact, dgamma1)), rel_tol=1e-10)

# %%
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
for ax, zoom in zip(axes, (False, True)):
    for name, branch in branches.items():
        stable = branch["radius"] >= branch["jump_off"]["contact_radius"]
        ax.plot(branch["depth"][stable] * 1e3, branch["force"][stable] * 1e3, color=branch["colour"],
                label=f"{name}, stable")
        ax.plot(branch["depth"][~stable] * 1e3, branch["force"][~stable] * 1e3, color=branch["colour"],
                ls="--", label=f"{name}, unstable")
    ax.plot(pinned_depth * 1e3, pinned_force * 1e3, color="0.5", ls=":", label="pinned radius (retracting)")
    ax.plot(jump_in["depth"] * 1e3, jump_in["force"] * 1e3, "o", color="tab:blue", label="jump-in (d = 0)")
    ax.plot(jump_off["depth"] * 1e3, jump_off["normal_force"] * 1e3, "s", color="tab:red",
            label="jump-off (∂d/∂a = 0)")
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.axvline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel("indentation depth d (mm)")
    ax.set_ylabel("normal force $F_N$ (mN)")
    if zoom:
        ax.set_xlim(-0.03, 0.015)
        ax.set_ylim(-25, 10)
        ax.set_title("zoom: jump-in and jump-off")
    else:
        ax.set_title(f"JKR branches (9), (10), R = {contact.indenter.R * 1e3:g} mm")
        ax.legend(fontsize=8)
