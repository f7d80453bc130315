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

from mdr_events import symbolic
from mdr_events.symbolic import relation

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
