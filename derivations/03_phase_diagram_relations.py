# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 3. Slip onset and the phase diagrams, eqs. (17), (18), (20), (21)
#
# On a straight path the indenter's tangential travel is tied to its depth,
# `x = d / tan α` (scenario A, (14)) or `x = (d_max − d) / tan α` (scenario B,
# (19)). The springs attached first carry the largest shift, so slip starts
# when that travel equals `ū(a)` (13), with `a` from Hertz (16) or JKR (9).

# %%
import math

import numpy as np

import mdr_events as me
from mdr_events.theory.symbolic import relation

contact = me.Contact.paper()  # the elastomer, the paraboloid (4), Δγ0, Δγ1 and τ0 of section 4
d_max = me.Scenario("B").d_max  # the paper's depth (0.3 mm): the motion's, given beside the contact
E_STAR, G_STAR = contact.elastomer.E_star, contact.elastomer.G_star
R, TAU0, DGAMMA0, DGAMMA1 = contact.indenter.R, contact.friction.tau0, contact.adhesion.dgamma0, contact.adhesion.dgamma1
tan = math.tan(math.radians(30.0))

# %% [markdown]
# ## (17): scenario A, non-adhesive — solved for `d`

# %%
relation("d_crit_A_hertz").eq

# %% [markdown]
# ## (18): scenario A with adhesion
# Eliminating `d` between `d = tan α · ū(a)` and (9) and writing `a = s²`
# leaves, after dividing by `s`, a cubic with one sign change, hence exactly
# one positive root (Descartes). Cardano's formula gives it in closed form.

# %%
cubic = relation("slip_A_jkr_cubic")
cubic.eq

# %%
relation("slip_A_jkr_cardano").eq

# %%
s = complex(relation("slip_A_jkr_cardano").numeric(complex(tan), R, TAU0, G_STAR, E_STAR, DGAMMA0)).real
a = s**2
assert math.isclose(tan * me.critical_shift(a, contact), float(me.jkr_depth(a, contact, DGAMMA0)), rel_tol=1e-10)
assert math.isclose(me.d_crit(30.0, contact, "A", adhesion=True), tan * me.critical_shift(a, contact), rel_tol=1e-10)

# %% [markdown]
# ## (20): scenario B, non-adhesive — a quadratic in `d`
# Squaring `(d_max − d)/tan α = ū(sqrt(R d))` gives
# `d² − (2 d_max + k²) d + d_max² = 0`; the smaller root is pull-off at α,
# the larger continued indentation at α from `d_max`. Their product is `d_max²`.

# %%
relation("slip_B_hertz_quadratic").eq, relation("slip_B_hertz_k").eq

# %%
lower = me.d_crit(30.0, contact, "B", branch="pull-off", d_max=d_max)
upper = me.d_crit(30.0, contact, "B", branch="indentation", d_max=d_max)
assert math.isclose(lower * upper, d_max**2, rel_tol=1e-12)

# %% [markdown]
# ## (21): scenario B with adhesion — a quartic in `s`
# `±(d − d_max)/tan α = ū(a)` with (9); "−" (pull-off) uses `Δγ1`, "+"
# (indentation) `Δγ0`. Each quartic again has exactly one positive root. On
# the pull-off branch it may lie below the jump-off radius: then the contact
# separates before anything slides.

# %%
relation("slip_B_jkr_quartic_pull_off").eq

# %%
relation("slip_B_jkr_quartic_indentation").eq

# %%
alpha = np.linspace(0, 90, 10)
print(np.round(me.d_crit(alpha, contact, "B", adhesion=True, d_max=d_max) * 1e3, 4), "mm")
d_pull = me.d_crit(40.0, contact, "B", adhesion=True, d_max=d_max)
a_pull = float(me.jkr_contact_radius(d_pull, contact, DGAMMA1))
assert math.isclose((d_max - d_pull) / math.tan(math.radians(40.0)), me.critical_shift(a_pull, contact), rel_tol=1e-9)

# %% [markdown]
# ## Critical angles
# Scenario A: `d_crit(α_c) = d_max` (the motion's depth, given as `d_max=` beside
# the contact; the paper's by default). With the inferred `E = 0.324 MPa`,
# `ν = 0.5`, both numbers the paper states come out:

# %%
print("alpha_c Hertz", round(me.critical_angle(contact, "A", adhesion=False, d_max=d_max), 3), "(paper 23.59)")
print("alpha_c JKR  ", round(me.critical_angle(contact, "A", adhesion=True, d_max=d_max), 3), "(paper 22.87)")
assert abs(me.critical_angle(contact, "A", adhesion=False, d_max=d_max) - 23.59) < 0.02
assert abs(me.critical_angle(contact, "A", adhesion=True, d_max=d_max) - 22.87) < 0.02

# %% [markdown]
# ## The phase diagrams (Fig. 9a, 9b)
# `mdr_events.phase_diagram` evaluates (17), (18) and (20), (21) on 0°, 0.1°,
# …, 90°, and `mdr_events.plotting.plot_phase_diagram` draws them. Scenario A:
# below the curve the springs stick during indentation, above it they slide;
# paths steeper than `α_c` reach `d_max` before anything slides. Scenario B:
# the pull-off branch (below `d_max`) and the indentation branch (above it);
# above its critical angle the contact comes apart (jump-off) before any
# spring slides.

# %%
import matplotlib.pyplot as plt

from mdr_events.plotting.figures import plot_phase_diagram

diagrams = {scenario: me.phase_diagram(contact, scenario=scenario, d_max=d_max) for scenario in ("A", "B")}

# the drawn curves cross d_max at the critical angles (scenario A), and the scenario-B pull-off
# curve ends at its critical angle (−inf beyond: jump-off first)
pd_a, pd_b = diagrams["A"], diagrams["B"]
for key in ("hertz", "jkr"):
    angle = float(pd_a[f"critical_angle_{key}"])
    crossing = np.interp(angle, pd_a["alpha"].values, pd_a[f"d_crit_{key}"].values)
    assert math.isclose(crossing, d_max, rel_tol=1e-3), (key, crossing)
pull_off = pd_b["d_crit_jkr"].sel(branch="pull-off")
assert float(pull_off["alpha"].where(np.isfinite(pull_off)).max()) <= float(pd_b["critical_angle_jkr"])
assert np.all(np.isneginf(pull_off.sel(alpha=slice(float(pd_b["critical_angle_jkr"]) + 0.1, 90))))

# %%
fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), constrained_layout=True)
for ax, scenario in zip(axes, ("A", "B")):
    plot_phase_diagram(diagrams[scenario], ax=ax)
