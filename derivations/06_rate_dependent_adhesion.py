# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 6. Rate-dependent adhesion: the edge's equation of motion
#
# The paper's works of adhesion `Δγ0` (in) and `Δγ1` (out) are the rate-independent shadow of a work that depends on
# how fast the edge moves (Maugis & Barquins 1978). Every expression below is the one
# `mdr_events.theory.rate_adhesion` and `mdr_events.continuum.solve_edge` evaluate
# (`symbolic.derive_rate_dependent_adhesion()`); each step ends with a check.

# %%
import math

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import mdr_events as me
from mdr_events.theory import rate_adhesion
from mdr_events.theory import symbolic as S

rate = S.derive_rate_dependent_adhesion()
params = me.Parameters.paper()

# %% [markdown]
# ## Step 1 — the energy an edge releases
# Heß's rule (8) says how far the boundary spring stretches before it lets go, `Δl = sqrt(2π a Δγ / E*)`. Read the
# other way, an edge whose spring is stretched by `Δl = g(a) − d` releases `Γ = E* Δl² / (2π a)`.

# %%
release = rate["energy_release_rate"]
print(release.pretty())
hess = S.relation("hess_max_elongation")
assert sp.simplify(hess.rhs.subs(S.dgamma, release.rhs) - release.args[0]) == 0  # Δl back from Γ

# %% [markdown]
# ## Step 2 — the works at a speed and the speeds at a release rate
# Receding, `Δγ(ȧ) = Δγ1 [1 + (|ȧ|/v_ref)^n]`; advancing, `Δγ0 / [1 + (ȧ/v_ref)^n]`. Solved for the speed at which
# the edge releases what it needs; the edge rests while `Δγ0 <= Γ <= Δγ1`.

# %%
for key in ("receding_work_of_adhesion", "receding_edge_speed", "advancing_work_of_adhesion", "advancing_edge_speed"):
    print(key, ":", rate[key].pretty())
law = me.RateDependentAdhesion(params.dgamma0, params.dgamma1, v_ref=1e-6, n=0.6)
speeds = np.concatenate([-np.logspace(-10, -3, 8), np.logspace(-10, -3, 8)])
np.testing.assert_allclose(rate_adhesion.edge_speed(law, rate_adhesion.work_of_adhesion(law, speeds)), speeds,
                           rtol=1e-12)
assert np.all(rate_adhesion.edge_speed(law, np.linspace(law.dgamma0, law.dgamma1, 5)) == 0.0)

# %% [markdown]
# ## Step 3 — the paper's law as `v_ref → ∞`, the edge held as `v_ref → 0`
# At a fixed speed the works tend to `Δγ1` and `Δγ0`; at a fixed release rate outside the band the speed grows
# without bound (the edge snaps to the branch (9)), and vanishes as `v_ref → 0`. On the paraboloid, `Γ = Δγ` is the
# branch (9) itself.

# %%
speed, rest, v_ref, exponent = rate["receding_work_of_adhesion"].args
assert sp.limit(rate["receding_work_of_adhesion"].rhs, v_ref, sp.oo) == rest
gamma = rate["receding_edge_speed"].args[0]
assert sp.limit(rate["receding_edge_speed"].rhs.subs(gamma, 2 * rest), v_ref, 0, "+") == 0
depth = sp.Symbol("d_b", real=True)
branch = sp.solve(sp.Eq(rate["paraboloid_release_rate"].rhs.subs(S.d, depth), S.dgamma), depth)
jkr = S.relation("jkr_depth").rhs
assert any(sp.simplify(root - jkr) == 0 for root in branch), branch  # Γ = Δγ on the stretched side is (9)

# %% [markdown]
# ## Step 4 — the flat punch detaches in a finite time
# A flat punch of radius `a0` held at a depth `d` beyond Kendall's pull-off: under its face `g = 0`, so
# `Γ = E* d² / (2π a)` grows as the edge recedes; for `n = 1` the time to come apart is a closed form. It agrees with
# the integrated edge (`continuum.solve_edge`) to the ODE's tolerance.

# %%
print(rate["flat_punch_detachment_time"].pretty())
linear = me.RateDependentAdhesion(0.05, params.dgamma1, 1e-6, 1.0)
punch, held = me.FlatPunch(1.5e-3), -80e-6
held_params = params.replace(dgamma0=0.05)
path = me.Path(np.array([(0.0, 0.0), (0.0, 2e-6), (0.0, held), (0.05, held)]), speed=1e-6)
run = me.continuum.solve_edge(held_params, path, linear, profile=punch)
start = path.corner_times[2]
radius = float(run.radius(np.array([start]))[0])
ended = [event for event in run.events if event.kind.value == "contact_ends"][0]
closed = rate_adhesion.flat_punch_detachment_time(linear, radius, held, params.E_star, radius=ended.radius)
print(f"detachment after {ended.time - start:.4f} s held; closed form {closed:.4f} s")
assert abs((ended.time - start) - closed) <= 1e-8 * closed

# %% [markdown]
# ## Step 5 — where a receding edge lets go, and scenario B's angle at a speed
# At a fixed depth the release rate `Γ(a, d) = E* (g(a) − d)² / (2π a)` rises as the edge shrinks once `∂Γ/∂a <= 0`
# (Griffith's stability of the edge): from there it recedes ever faster and collapses whatever the path does. Solved
# for the depth, `d = g − 2a g'`; on the paraboloid `−3a²/R`, the turning point of every branch (9), which is the
# paper's jump-off (the limit `v_ref → ∞`). Scenario B's critical angle at a speed (`me.critical_angle_B_at_speed`)
# is the one at which the springs slide exactly where the edge lets go; it tends to (21) as `v_ref → ∞`, at the
# order 2/3 of a slow passage through the fold.

# %%
let_go = rate["let_go_depth"]
print(let_go.pretty())
g_a, g_slope, radius = let_go.args
parabolic = sp.simplify(let_go.rhs.subs({g_a: radius**2 / S.R, g_slope: 2 * radius / S.R}))
print("paraboloid:", parabolic)
off = S.relation("jump_off_radius").rhs
assert sp.simplify(parabolic.subs(radius, off) - S.relation("jump_off_depth").rhs) == 0
paper_B = me.critical_angle(params, "B", adhesion=True)
for v_ref in (1e-4, 1e-3, 1e-2):
    fast = me.RateDependentAdhesion(params.dgamma0, params.dgamma1, v_ref, 1.0)
    angle = me.critical_angle_B_at_speed(params, fast, params.v, method="LSODA")
    print(f"v_ref = {v_ref:g} m/s: critical angle of B {angle:.4f}°, (21) {paper_B:.4f}°, gap {paper_B - angle:.4f}°")

# %% [markdown]
# ## The normal force at three speeds
# In to `d_max` and out at the path's speed `v`: the faster, the harder the contact pulls and the further it holds.

# %%
figure, axes = plt.subplots(figsize=(6.4, 4.2))
for speed in (1e-8, 1e-7, 1e-6):
    way = me.Path(np.array([(0.0, 0.0), (0.0, params.d_max), (0.0, -200e-6)]), speed=speed)
    edge = me.continuum.solve_edge(params.replace(v=speed), way, law)
    times = np.linspace(way.first_contact_time(), way.duration, 3001)
    axes.plot(way.position(times)[1] * 1e6, edge.normal_force(times, way) * 1e3, label=f"v = {speed:g} m/s")
paper = me.continuum.solve_path(params, me.Path.scenario_A(90.0, params), friction=me.FrictionLaw("tau0", tau0=0.0))
filled = me.continuum.evaluate(paper, np.linspace(0.0, paper.end_time, 3001))
axes.plot(filled["indentation_depth"] * 1e6, filled["normal_force"] * 1e3, "k--", lw=0.9, label="the paper's law")
axes.set_xlabel("depth d (µm)")
axes.set_ylabel("F_N (mN)")
axes.legend()
plt.show()
