# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 5. Coulomb's law on the springs: Cattaneo–Mindlin
#
# The paper caps every spring's shift at `ū(a) = π a τ0 / (2G*)` (13). With
# Coulomb's law instead, each spring holds a tangential force up to `μ` times
# its normal force. Every expression below is the one `mdr_events.mindlin`
# evaluates (`symbolic.derive_friction_model()`); each step ends with a check
# against the literature's closed form or an independent numerical route.

# %%
import math

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp
from scipy import integrate

import mdr_events as me
from mdr_events import FrictionLaw, mindlin
from mdr_events.theory import symbolic as S
from mdr_events.theory.symbolic import relation

hertz = me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)  # the flat record mindlin's closed forms take
coulomb = FrictionLaw("coulomb", mu=0.3)
# the same contact as one value (no adhesion: Hertz), for the simulations
contact = me.Contact(me.Elastomer(hertz.E, hertz.nu), me.Paraboloid(hertz.R), friction=coulomb)

# %% [markdown]
# ## Step 1 — the cap of one spring
# A spring of width `Δx` has the normal stiffness `E* Δx` (5) and the tangential
# stiffness `G* Δx` (6). It slides once `G* Δx u = μ E* Δx u_z`: its cap is
# `ū = μ (E*/G*) u_z`, proportional to its compression `u_z = d − g(ξ)`.

# %%
cap = relation("coulomb_critical_shift")
print(cap.pretty())
assert sp.simplify(cap.rhs - S.mu * S.E_star * S.u_z / S.G_star) == 0

# %% [markdown]
# ## Step 2 — loading from rest at a constant depth
# At the depth `d` of a power law `c rⁿ` without adhesion, a shift `u_x` of the
# indenter leaves the springs with a cap above `u_x` sticking: the stick radius
# `c*` has `g(c*) = d − u_x G*/(μ E*)`, and
# `F_x = 2G* (u_x c* + ∫_{c*}^a μ (E*/G*)(d − g) dξ)`. The derivation checked that
# this is `μ (F_N(d) − F_N(d − u_x G*/(μ E*)))` (Jäger 1998, Ciavarella 1998):
# for the sphere, Cattaneo–Mindlin's `μ F_N (1 − (1 − u_x/u*)^(3/2))`.

# %%
d = 1e-4
full = mindlin.full_slip_shift(d, coulomb, hertz)
shifts = np.linspace(0.0, full, 41)
force = mindlin.virgin_force(shifts, d, coulomb, hertz)
sphere = 4.0 / 3.0 * hertz.E_star * math.sqrt(hertz.R) * d**1.5  # Hertz's F_N
mindlin_1949 = 0.3 * sphere * (1.0 - (1.0 - shifts / full) ** 1.5)
assert np.max(np.abs(force - mindlin_1949)) < 1e-13 * 0.3 * sphere

# independently: the springs' caps integrated numerically, 2G* ∫ min(u_x, ū(ξ)) dξ
a = math.sqrt(hertz.R * d)
kappa = 0.3 * hertz.E_star / hertz.G_star
for u_x in shifts[1::10]:
    value = 2 * hertz.G_star * integrate.quad(lambda xi: min(u_x, kappa * (d - xi**2 / hertz.R)), 0, a,
                                              points=[math.sqrt(max(hertz.R * (d - u_x / kappa), 0.0))])[0]
    assert abs(value - mindlin.virgin_force(u_x, d, coulomb, hertz)) < 1e-10 * 0.3 * sphere

# %% [markdown]
# ## Step 3 — back and forth: Masing's rules
# Every spring is a play operator with a fixed cap, so after a reversal at
# `(x_r, F_r)` the force is `F_r + 2 F₀((x − x_r)/2)` (Mindlin & Deresiewicz
# 1953), and a branch that passes the start of its predecessor closes that loop.
# The continuum method follows any path; at a constant depth it meets these loops.

# %%
path = me.Path([(0, 0), (0, d), (0.6 * full, d), (-0.6 * full, d), (0.6 * full, d), (1.2 * full, d)], speed=1e-6)
start = path.first_contact_time()
times = np.union1d(np.linspace(0, path.duration - start, 1201), path.corner_times - start)
exact = me.simulate(contact, path, me.Continuum(t=times))
held = exact["indentation_depth"].values[0] == d
x = exact["tangential_displacement"].values[0][held]
closed = mindlin.tangential_force(x, d, coulomb, hertz)
assert np.max(np.abs(exact["tangential_force"].values[0][held] - closed)) < 1e-9 * 0.3 * sphere

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(x * 1e6, exact["tangential_force"].values[0][held] * 1e3, label="continuum")
ax.plot(x * 1e6, closed * 1e3, "k--", lw=0.8, label="Cattaneo–Mindlin, Masing")
ax.set_xlabel("x (µm)")
ax.set_ylabel("F_x (mN)")
ax.legend()

# %% [markdown]
# ## Step 4 — proportional loading: the angle of friction
# Along scenario A's path `x = d / tan α` a spring attached at depth `d_ξ` has
# the shift `(d − d_ξ)/tan α` and the cap `κ (d − d_ξ)`: they grow in
# proportion, so no spring slides where `tan α > 1/κ = G*/(μ E*)` and all slide
# from first contact below it, with `F_x = μ F_N`.

# %%
angle = mindlin.critical_angle_A(coulomb, hertz)
assert math.isclose(angle, math.degrees(math.atan(hertz.G_star / (0.3 * hertz.E_star))), rel_tol=1e-15)
below = me.simulate(contact, me.Scenario("A", 0.9 * angle), me.Continuum(samples=201))
pressed = below["normal_force"].values[0] > 0
ratio = below["tangential_force"].values[0][pressed] / below["normal_force"].values[0][pressed]
indenting = ratio[: len(ratio) // 3]  # (the path turns back at d_max, two thirds of the run from its end)
assert np.allclose(indenting, 0.3, rtol=1e-9)
print(f"angle of friction {angle:.3f}°; below it F_x / F_N = {indenting[-1]:.12f} while indenting")
