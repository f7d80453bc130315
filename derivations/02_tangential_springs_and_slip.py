# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 2. Tangential springs and the slip criterion, eqs. (11)–(13)
#
# The mean shear stress is the sum of the tangential spring forces over the
# contact area (11). In stationary sliding all `n` springs in contact carry
# the same shift `ū`, and `n Δx = 2a` (12); requiring the mean stress to be the
# measured `τ0` fixes the critical shift (13).

# %%
import math

import numpy as np

from mdr_events.theory import symbolic
from mdr_events.theory.symbolic import relation

G_STAR, TAU0 = 0.288e6, 42e3

# %%
relation("stationary_shear_stress").eq

# %%
critical_shift = relation("critical_shift")
critical_shift.eq

# %% [markdown]
# Check with discrete springs: any number `n` of springs at `ū(a)` over the
# diameter `2a` carries exactly `τ0 π a²`.

# %%
a = 2.5e-3
u_bar = critical_shift.numeric(a, TAU0, G_STAR)
for n in (7, 100, 10_000):
    dx = 2 * a / n
    force = np.sum(np.full(n, G_STAR * dx * u_bar))
    assert math.isclose(force / (math.pi * a**2), TAU0, rel_tol=1e-12)
print(f"ū({a * 1e3} mm) = {u_bar * 1e6:.3f} µm")

# %% [markdown]
# `ū` grows with the contact radius: springs that slid while the contact was
# small can stick again when it grows faster than the indenter moves
# sideways, and during pull-off the shrinking radius makes every spring slide
# eventually, so that `τ → τ0` (the paper's observation (3) in 4.2).

# %%
assert relation("critical_shift").rhs.diff(symbolic.a) > 0

# %% [markdown]
# ## The slip zone of scenario A at 20°
# The continuum (`Δx → 0`) simulation of scenario A (indentation at 20° to
# `d_max`, then vertical pull-off) gives the contact radius `a(t)` and the share
# of the springs in contact that sit at `ū(a)`. The springs attached first
# (in the middle) carry the largest shift, so the sliding springs form the zone
# `|x| < c(t)` with the slip front `c = sliding_fraction · a`. It opens at the
# slip onset (depth `d_crit(20°)` of (18)) at once to the jump-in radius: the
# springs caught by the jump-in all attached at the same instant, so they
# reach `ū` together. On the way out, while `a` shrinks, it spreads to the
# edge (full slip: `τ = τ0`).

# %%
import matplotlib.pyplot as plt

import mdr_events as me
from mdr_events.theory import analytic

contact = me.Contact.paper()
ds = me.simulate(contact, me.Scenario("A", 20.0), me.Continuum(samples=801)).sel(alpha=20.0)
time = ds["time"].values
radius = ds["contact_radius"].values
front = ds["sliding_fraction"].values * radius
events = dict(zip(ds["event_kind"].values, ds["event_time"].values))
event_depth = dict(zip(ds["event_kind"].values, ds["event_depth"].values))

# the slip front lies inside the contact, is closed before the slip onset, which happens at the
# depth of (18), and reaches the edge at full slip
in_contact = radius > 0
assert np.all(front[in_contact] <= radius[in_contact] * (1 + 1e-12))
assert np.all(front[time < events["slip_onset"]] == 0.0)
assert math.isclose(event_depth["slip_onset"], me.d_crit(20.0, contact, "A", adhesion=True), rel_tol=1e-7)
opened = front[time > events["slip_onset"]][0]
assert opened >= analytic.jump_in_radius(contact, contact.adhesion.dgamma0) * (1 - 1e-9)
after_full_slip = (time > events["full_slip"]) & in_contact
assert after_full_slip.any() and np.allclose(front[after_full_slip], radius[after_full_slip], rtol=1e-9)

# %%
fig, ax = plt.subplots(figsize=(7, 4.2), constrained_layout=True)
ax.plot(time, radius * 1e3, color="k", label="contact radius a(t)")
ax.plot(time, front * 1e3, color="tab:red", label="slip front c(t)")
ax.fill_between(time, 0, front * 1e3, color="tab:red", alpha=0.15, label="slip zone |x| < c")
for kind in ("slip_onset", "corner", "detachment_starts", "full_slip", "pull_off"):
    ax.axvline(events[kind], color="0.5", lw=0.7, ls=":")
    ax.text(events[kind], 1.02 * np.nanmax(radius) * 1e3, kind.replace("_", " "), rotation=90,
            ha="right", va="top", fontsize=7, color="0.3")
ax.set_xlabel("time t (s)")
ax.set_ylabel("radius (mm)")
ax.set_title("Scenario A at α = 20°: contact radius and slip front (continuum method)")
ax.legend(loc="center left", fontsize=8);  # the ; keeps the Legend object out of the output
