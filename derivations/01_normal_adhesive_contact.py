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

from mdr_events import symbolic
from mdr_events.symbolic import relation

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
