# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
# ---

# %% [markdown]
# # 7. A layer of finite thickness: the generalized MDR on a rigid base
#
# The paper's experiment indents an elastomer layer `h = 5 mm` thick on a rigid base, its model a half-space. The
# generalized MDR (Machines 11(4):474, 2023) replaces `E*` by the layer's flat-punch stiffness `K(a)`. Every
# expression below is the one `mdr_events.theory.layer` and `mdr_events.theory.layer_tangential` evaluate
# (`layer_symbolic.derive_layer_model()`, `layer_tangential_symbolic.derive_tangential_model()`); each step ends with
# a check against an independent computation. The tables against `a/h` are built once and cached on disk.

# %%
import math

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

import mdr_events as me
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.theory import layer as L
from mdr_events.theory import layer_symbolic as LS
from mdr_events.theory import layer_tangential as T
from mdr_events.theory import layer_tangential_symbolic as TS
from mdr_events.theory import symbolic

rels = LS.derive_layer_model()
trels = TS.derive_tangential_model()
paper = me.Contact.paper(0.03)
R, E_STAR, NU = paper.indenter.R, paper.elastomer.E_star, paper.elastomer.nu
DGAMMA = paper.adhesion.dgamma1
G = paper.elastomer.E / (2 * (1 + NU))


def observed_order(errors, eps):
    """The order p of errors ≈ c eps^p, from the last two pairs."""
    return math.log(abs(errors[-1] / errors[-2])) / math.log(eps[-1] / eps[-2])


# %% [markdown]
# ## Step 1 — the layer's compliance `C(ξh)` from Love's strain function
# With `φ = Φ(z) J₀(ξr)`, `Φ = (A + Bz)eᶻ + (C + Dz)e⁻ᶻ`, a pressure `P J₀(ξr)` on a frictionless top and the base
# bonded (`u_r = u_z = 0`) or frictionless (`σ_rz = u_z = 0`) at `z = ξh = t`, the top moves by
# `ŵ = (2/E*) C(t) p̂`. SymPy solves the four conditions (`LS.love_compliance`):

# %%
t, nu = LS.t, LS.nu
bonded, frictionless = rels["layer_compliance_bonded"], rels["layer_compliance_frictionless"]
bonded.eq, frictionless.eq

# %% [markdown]
# Its limits: the half-space as `t → ∞` (`C → 1`); a thin layer, `C ≈ c₁ t`, is Winkler's foundation of modulus
# `κ = E*/(2c₁h)`: `2G(1 − ν)/((1 − 2ν)h)` bonded, `E*/h` on a frictionless base; the bonded incompressible layer has
# `c₁ = 0`, `C ≈ c₃ t³`: the thin-film equation `w = −(h³/3G)∇²p`.

# %%
for compliance in (bonded.rhs, frictionless.rhs):
    assert sp.limit(compliance.subs(nu, sp.Rational(3, 10)), t, sp.oo) == 1
c1 = sp.series(bonded.rhs, t, 0, 2).removeO().coeff(t, 1)
assert sp.simplify(c1 - (1 - 2 * nu) / (2 * (1 - nu) ** 2)) == 0
assert sp.simplify(sp.series(frictionless.rhs, t, 0, 2).removeO().coeff(t, 1) - sp.Rational(1, 2)) == 0
c3 = sp.series(bonded.rhs.subs(nu, sp.Rational(1, 2)), t, 0, 4).removeO().coeff(t, 3)
assert c3 == sp.Rational(2, 3)  # ŵ = (2c₃ξ²h³/E*) p̂ with E* = 4G: w = −(h³/3G) ∇²p
print("kappa (bonded) =", rels["layer_winkler_modulus"].rhs, "; thin film: m =", rels["layer_thin_film_mobility"].rhs)
# independent: the closed form the solver types in (κ = 3 − 4ν) against SymPy's, at several t and ν
t_values = np.array([0.05, 0.7, 2.0, 6.0])
for nu_value in (0.0, 0.3, 0.5):
    for base in ("bonded", "frictionless"):
        np.testing.assert_allclose(L.compliance_function(t_values, nu_value, base),
                                   rels[f"layer_compliance_{base}"].numeric(t_values, nu_value), rtol=1e-11)
assert abs(float(L.compliance_function(40.0, 0.5)) - 1.0) < 1e-15

# %% [markdown]
# ## Step 2 — the flat punch: Lebedev & Ufliand's Fredholm equation, solved by Nyström
# Writing `p̂(ξ) = ∫₀ᵃ θ(s) cos ξs ds` and inverting the Abel operator of `w = w₀` (`r < a`) gives, with `λ = a/h`,
#
# `Θ(τ) − (λ/π) ∫₀¹ Θ(σ)[k(λ(τ − σ)) + k(λ(τ + σ))] dσ = 1`, `k(v) = ∫₀^∞ [1 − C(u)] cos(uv) du`  (L1)
#
# a Fredholm equation of the second kind with a kernel analytic in a strip; `K(a) = 2E* a Φ(λ)`, `Φ = ∫₀¹ Θ` (L2).
# Gauss–Legendre Nyström converges spectrally with the nodes:

# %%
lam = 5.0
reference = L.solve_punch(lam, NU, "bonded", nodes=L.nystrom_nodes(lam) + 64).stiffness_factor
print(f"a/h = {lam}: default nodes {L.nystrom_nodes(lam)}, Phi = {reference:.15f}")
errors = {}
for nodes in (4, 8, 12, 16, 24, 32, L.nystrom_nodes(lam)):
    errors[nodes] = abs(L.solve_punch(lam, NU, "bonded", nodes=nodes).stiffness_factor / reference - 1)
    print(f"  {nodes:3d} nodes: relative error {errors[nodes]:.1e}")
assert errors[8] < errors[4] ** 1.5 and errors[16] < errors[8] ** 1.5  # faster than any power of the nodes
assert errors[L.nystrom_nodes(lam)] < 1e-12

# %% [markdown]
# The half-space as `a/h → 0`: `Φ − 1 ≈ (2k(0)/π) a/h`, first order (independently: `k(0)` by its own quadrature).

# %%
k0 = float(L.kernel(0.0, NU))
lams = np.array([4e-3, 2e-3, 1e-3])
excess = np.array([L.solve_punch(float(value), NU, "bonded").stiffness_factor - 1 for value in lams])
order = observed_order(excess, lams)
print(f"K/(2E* a) - 1 at a/h = {lams}: {excess}; observed order {order:.4f}; k(0) = {k0:.6f}")
assert abs(order - 1) < 0.01 and abs(excess[-1] / lams[-1] / (2 * k0 / np.pi) - 1) < 2e-3
assert L.solve_punch(0.0, NU).stiffness_factor == 1.0
np.testing.assert_array_equal(L.punch_stiffness(np.array([1e-4, 3e-3]), E_STAR, NU, HALF_SPACE),
                              2 * E_STAR * np.array([1e-4, 3e-3]))

# %% [markdown]
# The thin limits: `K → πκa²` (Winkler; `g = f`, so `g/g∞ → 1/2` for the paraboloid) and, bonded at `ν = 0.5`,
# `K → 3πGa⁴/(8h³)` (thin film; `g = x²/(4R)`, `g/g∞ → 1/4`), from SymPy; the numerics approach them at first order in
# `h/a` (an edge boundary layer of width `h`), and Richardson extrapolation in `h/a` reaches them to 1e-6.

# %%
def thin_stiffness_factor(lam, nu_value, base):
    """K_thin/(2E* a) at h = G = 1, from the derived relations."""
    e_star = 2.0 / (1.0 - nu_value)
    if base == "bonded" and nu_value == 0.5:
        stiffness = rels["layer_thin_film_stiffness"].numeric(lam, 1.0, 1.0)
    else:
        key = "layer_winkler_modulus" if base == "bonded" else "layer_winkler_modulus_frictionless"
        stiffness = rels["layer_winkler_stiffness"].numeric(lam, rels[key].numeric(1.0, nu_value, 1.0))
    return stiffness / (2.0 * e_star * lam)


for nu_value, base, profile_limit, thin_lams in ((0.5, "bonded", 0.25, (10.0, 20.0, 40.0, 80.0, 160.0)),
                                                 (0.3, "bonded", 0.5, (10.0, 20.0, 40.0, 80.0)),
                                                 (0.5, "frictionless", 0.5, (10.0, 20.0, 40.0, 80.0))):
    thin_lams = np.array(thin_lams)
    solutions = [L.solve_punch(float(value), nu_value, base) for value in thin_lams]
    ratios = {"K": np.array([s.stiffness_factor for s in solutions]) / thin_stiffness_factor(thin_lams, nu_value, base),
              "g": np.array([s.profile_factor() for s in solutions]) / profile_limit}
    for name, ratio in ratios.items():
        order = observed_order(ratio - 1, 1 / thin_lams)
        limit = np.polyfit(1 / thin_lams, ratio, len(thin_lams) - 1)[-1]
        print(f"nu = {nu_value}, {base:12s} {name}: ratio at a/h = {thin_lams[-1]:g}: {ratio[-1]:.6f}, "
              f"observed order {order:.3f}, extrapolated limit - 1 = {limit - 1:.1e}")
        assert abs(order - 1) < 0.06 and abs(limit - 1) < 1e-6

# %% [markdown]
# ## Step 3 — the generalized MDR: springs `k = K'/2`, the profile `g` from `f`, Heß's rule from Griffith
# A flat punch is `K(a) = ∫₋ₐᵃ k(x) dx`, so `k(x) = K'(|x|)/2`; the edge value of (L1) gives `K'(a) = 2E* Θ(1)²`
# (L3). The energy of a contact of radius `a` at depth `d` is the non-adhesive one at `g(a)` plus a flat punch moved
# by `d − g(a)`; SymPy differentiates it (`layer_energy_slope`) and Griffith's balance `∂U/∂a = 2πaΔγ` gives Heß's
# rule, `(8)` when `K' = 2E*`:

# %%
print(rels["layer_energy_slope"].pretty())
print(rels["layer_hess_elongation"].pretty())
K_prime = sp.Symbol("K_prime", positive=True)
elongation = rels["layer_hess_elongation"].rhs
released = rels["layer_energy_slope"].rhs.subs(sp.Derivative(sp.Function("K")(symbolic.a), symbolic.a), K_prime)
released = released.subs(symbolic.d, sp.Function("g")(symbolic.a) - elongation)
assert sp.simplify(released - 2 * sp.pi * symbolic.a * symbolic.dgamma) == 0  # Griffith's balance holds on Δl
assert sp.simplify(elongation.subs(K_prime, 2 * symbolic.E_star)
                   - symbolic.relation("hess_max_elongation").rhs) == 0  # (8) on the half-space
layer = Layer(5e-3)
a = np.array([1e-3, 3e-3, 6e-3])
np.testing.assert_allclose(L.hess_elongation(a, DGAMMA, E_STAR, NU, layer),
                           np.sqrt(4 * np.pi * a * DGAMMA / L.punch_stiffness_slope(a, E_STAR, NU, layer)), rtol=1e-14)

# %% [markdown]
# Independently of the tables: `d(λΦ)/dλ = Θ(1)²` by a central difference of direct solves, and
# `∫₋ₐᵃ k = K` by Gauss–Legendre.

# %%
for lam in (0.3, 2.0, 8.0):
    step = 1e-4 * lam
    upper, lower = (L.solve_punch(lam + s, NU, "bonded") for s in (step, -step))
    slope = ((lam + step) * upper.stiffness_factor - (lam - step) * lower.stiffness_factor) / (2 * step)
    assert abs(slope / L.solve_punch(lam, NU, "bonded").edge_factor ** 2 - 1) < 1e-7
nodes, weights = np.polynomial.legendre.leggauss(60)
a0 = 4e-3
x, w = a0 * (nodes + 1) / 2, a0 * weights / 2
springs = 2 * np.sum(w * L.spring_stiffness_density(x, E_STAR, NU, layer))
assert abs(springs / float(L.punch_stiffness(a0, E_STAR, NU, layer)) - 1) < 1e-8

# %% [markdown]
# The equivalent profile inverts the superposition of punches, `f(r) = ∫₀ʳ [1 − φ(r; ã)] g'(ã) dã`, with the surface
# outside a punch `φ` (L5) from the solution of (L1): the paraboloid's `r²/(2R)` comes back at `a/h ≈ 0.8`. And the
# force is the springs' sum, `F_N = ∫₋ₐᵃ k(x)(d − g(x)) dx = F₀(a) + K(a)(d − g(a))` (`layer_normal_force`).

# %%
r0 = 4e-3
nodes40, weights40 = np.polynomial.legendre.leggauss(40)
psi, wpsi = np.pi / 4 * (nodes40 + 1), np.pi / 4 * weights40
radii = r0 * np.cos(psi)
phi = np.array([float(L.surface_displacement(r0, radius, NU, layer)) for radius in radii])
back = np.sum(wpsi * (1 - phi) * L.power_law_profile_slope(radii, paper.indenter, NU, layer) * r0 * np.sin(psi))
print(f"f(r) from g and phi: {back:.12e}; r^2/(2R) = {r0**2 / (2 * R):.12e}")
assert abs(back / (r0**2 / (2 * R)) - 1) < 1e-8
print(rels["layer_normal_force"].pretty())
d0 = 1e-4
springs = 2 * np.sum(w * L.spring_stiffness_density(x, E_STAR, NU, layer)
                     * (d0 - L.power_law_profile(x, paper.indenter, NU, layer)))
assert abs(springs / float(L.normal_force(d0, a0, paper.indenter, E_STAR, NU, layer)) - 1) < 1e-8
# at h = inf every relation is the half-space's to round-off
np.testing.assert_allclose(L.branch_normal_force(a, paper.indenter, E_STAR, NU, DGAMMA, HALF_SPACE),
                           symbolic.relation("jkr_normal_force").numeric(a, R, E_STAR, DGAMMA), rtol=1e-14)

# %% [markdown]
# ## Step 4 — the tangential punch on a bonded layer
# A sticking punch moved by `u₀`: the tangential response splits into a longitudinal part (`C_L`) and a transverse one
# (`C_T = tanh t`), two Fredholm equations of the same type; `K_t = 2G* a Φ_t`,
# `(2 − ν)/Φ_t = (1 − ν)/Φ_L + 1/Φ_T` (`G* = 4G/(2 − ν)`), `k_t = K_t'/2`, the cap (13) becomes `ū = π a² τ0/K_t(a)`.

# %%
trels["layer_compliance_longitudinal_bonded"].eq, trels["layer_compliance_transverse_bonded"].eq

# %%
print(trels["layer_tangential_stiffness"].pretty())
for key in ("layer_compliance_longitudinal_bonded", "layer_compliance_transverse_bonded"):
    assert sp.limit(trels[key].rhs.subs(nu, sp.Rational(1, 2)), t, sp.oo) == 1  # the half-space
G_STAR = 4 * G / (2 - NU)
np.testing.assert_array_equal(T.tangential_punch_stiffness(a, G_STAR, NU, HALF_SPACE), 2 * G_STAR * a)
assert T.solve_tangential_punch(0.0, NU).stiffness_factor == 1.0

# %% [markdown]
# The thin layer is Winkler's foundation in shear, `K_t → π a² G/h` (SymPy), at first order in `h/a`:

# %%
thin_lams = np.array([10.0, 20.0, 40.0, 80.0])
winkler = trels["layer_shear_winkler_stiffness"].numeric(thin_lams, 1.0, 1.0)  # G = h = 1
g_star = 4.0 / (2.0 - NU)
ratio = np.array([2 * g_star * value * T.solve_tangential_punch(value, NU).stiffness_factor
                  for value in thin_lams]) / winkler
order = observed_order(ratio - 1, 1 / thin_lams)
limit = np.polyfit(1 / thin_lams, ratio, len(thin_lams) - 1)[-1]
print(f"K_t / (pi a^2 G/h) at a/h = {thin_lams}: {ratio}; observed order {order:.3f}; extrapolated - 1 = {limit - 1:.1e}")
assert abs(order - 1) < 0.06 and abs(limit - 1) < 1e-6

# %% [markdown]
# The reduction to the two equations checked without it: under the solved traction the top's displacement, by direct
# Hankel quadrature of `C_L` and `C_T`, is `u₀` (order 0) and has no order-2 part, uniformly inside the punch.
# The coupling the decoupled problem neglects is bounded by `m = |C_zx|/sqrt(C_zz C_xx)`
# (`K_t ≤ K_t,coupled ≤ K_t/(1 − m²)`): `(1 − 2ν)/(2(1 − ν))` on the half-space, up to `√3/2` on a thin
# incompressible bonded layer.

# %%
rho = np.array([0.0, 0.3, 0.7, 0.99])
for lam in (0.3, 1.0, 3.0):
    u0, u2 = T.contact_displacement(T.solve_tangential_punch(lam, NU), rho)
    worst = max(np.max(np.abs(u0 - 1)), np.max(np.abs(u2)))
    print(f"a/h = {lam}: largest departure from a uniform displacement {worst:.1e}")
    assert worst < 1e-12
for nu_value in (0.0, 0.2, 0.5):
    assert abs(T.coupling_ratio(1e3, nu_value) - (1 - 2 * nu_value) / (2 * (1 - nu_value))) < 1e-15
bound = T.coupling_bound(0.5)
print(f"coupling bound at nu = 0.5: m_max = {bound:.6f}, so K_t,coupled/K_t <= {1 / (1 - bound**2):.3f}")
assert abs(bound - math.sqrt(3) / 2) < 1e-9 * bound
tau0, a_t = 4.2e4, 3e-3
cap = T.sliding_cap(a_t, tau0, G_STAR, NU, layer)
assert abs(float(T.tangential_punch_stiffness(a_t, G_STAR, NU, layer) * cap) / (np.pi * a_t**2 * tau0) - 1) < 1e-14
assert cap < np.pi * a_t * tau0 / (2 * G_STAR)  # the layer is stiffer: a smaller cap than (13)

# %% [markdown]
# ## Step 5 — the pull-off against `a/h`
# Under force control the paraboloid pulls off at the minimum of the branch force `F₀(a) − K(a)Δl(a)` (10). SymPy
# minimises it on the thin layers (`layer_symbolic`, section 6): `−2πRΔγ` on Winkler's foundation (any `κ`), `−3πRΔγ`
# on the thin incompressible bonded film, against `−(3/2)πRΔγ` on the half-space.

# %%
print(rels["layer_winkler_pull_off"].pretty())
print(rels["layer_thin_film_pull_off"].pretty())
# by hand, on Winkler's foundation: g = f = x²/(2R), K = πκa², Δl = sqrt(2Δγ/κ)
kappa, radius = sp.symbols("kappa a_w", positive=True)
force_w = sp.integrate(2 * sp.pi * kappa * symbolic.x * (radius**2 / (2 * symbolic.R) - sp.sqrt(2 * symbolic.dgamma
                       / kappa) - symbolic.x**2 / (2 * symbolic.R)), (symbolic.x, 0, radius))
minimum = [root for root in sp.solve(sp.diff(force_w, radius), radius) if root.is_positive][0]
assert sp.simplify(force_w.subs(radius, minimum) - rels["layer_winkler_pull_off"].rhs) == 0
pull_offs = {}
for nu_value, base, key, thicknesses in ((0.5, "bonded", "layer_thin_film_pull_off", np.geomspace(7.3e-6, 1.8e-6, 6)),
                                         (0.5, "frictionless", "layer_winkler_pull_off",
                                          np.geomspace(2.3e-5, 8.5e-6, 6))):
    contact = paper.replace(nu=nu_value, **{"layer.base": base})
    limit = float(rels[key].numeric(R, DGAMMA))
    curve = me.layer_pull_off_curve(contact, thicknesses)
    force, eps = curve["pull_off_force"].values, 1.0 / curve["relative_radius"].values
    order = observed_order(force / limit - 1, eps)
    extrapolated = np.linalg.solve(np.vander(eps, 6), force)[-1]
    print(f"{base}: F_po/limit at a/h = {1 / eps.min():.1f}: {force[-1] / limit:.5f}, observed order {order:.3f}, "
          f"extrapolated/limit - 1 = {extrapolated / limit - 1:.1e}")
    assert abs(order - 1) < 0.05 and abs(extrapolated / limit - 1) < 1e-5

# %% [markdown]
# ## Step 6 — the flat punch on a layer: its contact recedes under the face where `a K″ > K′`
# Under the face `g = 0` and `F₀ = 0`, so the force is `K(a) d` (`layer_flat_punch_force`). Under depth control the
# contact of radius `a ≤ a₀` at depth `d` has the energy `Π(a; d) = ½K(a)d² − πa²Δγ` (`LS.receding_energy()`: the
# springs' energy less the adhesion's). SymPy differentiates it: `∂Π/∂d` is the springs' force, `∂Π/∂a = 0` exactly at
# Heß's limit `|d| = Δl(a)` (8), and there `∂²Π/∂a² = 2πΔγ(aK″ − K′)/K′`: the radius is a minimum of `Π` (a stable
# contact smaller than the face) where `aK″ > K′` (`layer_flat_punch_recedes`), i.e. where `Δl` falls with `a`.

# %%
Pi = LS.receding_energy()
a_s, d_s, K_a = symbolic.a, symbolic.d, sp.Function("K")(symbolic.a)
K1, K2 = sp.Symbol("K_prime", positive=True), sp.Symbol("K_second")
print("Pi =", Pi)
assert sp.simplify(sp.diff(Pi, d_s) - rels["layer_flat_punch_force"].rhs.subs(sp.Symbol("K", positive=True), K_a)) == 0
stationary = sp.solve(sp.diff(Pi, a_s), d_s)  # Π'(a) = 0: the depths at which the radius a is in equilibrium
hess_of_K = rels["layer_hess_elongation"].rhs.subs(K1, sp.diff(K_a, a_s))
assert len(stationary) == 2 and all(sp.simplify(root**2 - hess_of_K**2) == 0 for root in stationary)  # |d| = Δl(a)
curvature = sp.simplify(sp.diff(Pi, a_s, 2).subs(d_s, -hess_of_K))
print("Pi''(a) at d = -Dl(a):", curvature)
recedes = rels["layer_flat_punch_recedes"].rhs  # a K'' − K'
assert sp.simplify(curvature - (2 * sp.pi * symbolic.dgamma * recedes / K1).subs(
    {K2: sp.diff(K_a, a_s, 2), K1: sp.diff(K_a, a_s)})) == 0
# its sign on the three closed-form layers: the half-space never recedes, Winkler's foundation is neutral (Δl is one
# constant: every spring at its limit at once), the thin incompressible film recedes at every radius
for name, K_closed, sign in (("half-space", 2 * symbolic.E_star * a_s, -1),
                             ("Winkler", rels["layer_winkler_stiffness"].rhs, 0),
                             ("thin film", rels["layer_thin_film_stiffness"].rhs, 1)):
    value = sp.simplify(curvature.subs(K_a, K_closed).doit())
    print(f"{name:10s}: Pi'' = {value}")
    assert sp.sign(value) == sign
assert sp.diff(sp.simplify(hess_of_K.subs(K_a, rels["layer_winkler_stiffness"].rhs).doit()), a_s) == 0

# %% [markdown]
# On the tabulated layers `aK″ − K′` changes sign once at most: `Δl(a)` rises from the half-space's `√a` to one hump
# at `a_j/h` and falls beyond it. A face `a₀ > a_j` recedes from `d = −Δl(a₀)` along `d = −Δl(a)` to `a_j`, where the
# rest comes off at once (`punch_recession.receding_radius`, Brent's method on the tables' `Θ′/Θ`). Checked
# independently: `Δl` sampled densely from the stiffness's slope has its largest value at `a_j` (within one sample),
# and `Π″` by central differences of `Π` of the tables' `K(a)` has the sign and the value of `2πΔγ(aK″ − K′)/K′`
# (`K″` by a central difference of `K′`). Bonded at `ν = 0.5` and `0.45` the punch recedes; on a frictionless base
# and bonded at `ν = 0.3`, `Δl` rises at every radius of the tables: the whole face comes off at Kendall's depth on
# the layer, as on the half-space.

# %%
from mdr_events.theory.layer.punch_recession import receding_radius  # noqa: E402
from mdr_events.theory.layer.scalar_factors import NormalFactors  # noqa: E402

samples = np.geomspace(1e-2, L.LAMBDA_MAX, 4001)  # a/h, ratio 1.0021 between samples (lengths in h: h = 1)
jump_offs = {}
for nu_value, base in ((0.5, "bonded"), (0.45, "bonded"), (0.3, "bonded"), (0.5, "frictionless")):
    layer_nu = Layer(1.0, base=base)
    elongation_curve = L.hess_elongation(samples, DGAMMA, E_STAR, nu_value, layer_nu)
    jump = receding_radius(NormalFactors(nu_value, layer_nu, 2.0), L.LAMBDA_MAX)
    jump_offs[(nu_value, base)] = jump
    peak = samples[np.argmax(elongation_curve)]
    print(f"nu = {nu_value}, {base:12s}: a_j/h = {jump:.6f} (sampled peak of Dl at {peak:.6f})")
    if jump < L.LAMBDA_MAX:  # recedes: the hump of Δl within one sample of a_j, and no sample above Δl(a_j)
        assert abs(math.log(peak / jump)) <= math.log(samples[1] / samples[0])
        top = float(L.hess_elongation(jump, DGAMMA, E_STAR, nu_value, layer_nu))
        assert np.max(elongation_curve) <= top * (1 + 1e-12)
    else:  # never recedes on the tables: Δl rises at every sample
        assert np.all(np.diff(elongation_curve) > 0)
assert jump_offs[(0.5, "bonded")] < jump_offs[(0.45, "bonded")] < L.LAMBDA_MAX
assert jump_offs[(0.3, "bonded")] == jump_offs[(0.5, "frictionless")] == L.LAMBDA_MAX


def energy_curvature(a_value, depth, nu_value, layer_nu, step):
    """∂²Π/∂a² at fixed depth by a central difference of Π = ½K(a)d² − πa²Δγ (the tables' K)."""
    radii = a_value + step * np.array([-1.0, 0.0, 1.0])
    energy = 0.5 * L.punch_stiffness(radii, E_STAR, nu_value, layer_nu) * depth**2 - np.pi * radii**2 * DGAMMA
    return (energy[0] - 2 * energy[1] + energy[2]) / step**2


# central differences of step s = 1e-3 a: truncation ~ s² |fourth derivative|/12, ~1e-6 relative (Π smooth on the
# scale a); rounding ~ 4 eps |Π|/(s² |Π''|), ~1e-9 here; 1e-5 bounds both with room
FD_STEP, FD_RTOL = 1e-3, 1e-5
layer_incompressible = Layer(1.0)
jump = jump_offs[(0.5, "bonded")]
for a_value, sign in ((2.0 * jump, 1), (0.5 * jump, -1)):  # inside the recession: stable; inside a_j: unstable
    depth = -float(L.hess_elongation(a_value, DGAMMA, E_STAR, 0.5, layer_incompressible))
    step = FD_STEP * a_value
    numeric = energy_curvature(a_value, depth, 0.5, layer_incompressible, step)
    slopes = L.punch_stiffness_slope(a_value + step * np.array([-1.0, 0.0, 1.0]), E_STAR, 0.5, layer_incompressible)
    formula = 2 * np.pi * DGAMMA * (a_value * (slopes[2] - slopes[0]) / (2 * step) - slopes[1]) / slopes[1]
    print(f"a/h = {a_value:.4f}: Pi'' = {numeric:.6e} (finite differences), {formula:.6e} (2 pi Dg (aK'' - K')/K')")
    assert np.sign(numeric) == sign and abs(numeric / formula - 1) < FD_RTOL

# %% [markdown]
# ## The figure: pull-off against `a/h`, and the paper's 5 mm layer
# Left: `|F_po|/((3/2)πΔγR)` from the half-space (1) to the thin limits (4/3 on Winkler's foundation, 2 on the thin
# film), bonded and frictionless at `ν = 0.5`. Right: `F_N(d)` in and out to `d = 0.3 mm` (the paper's contact,
# `Δγ0` in, `Δγ1` out) on the 5 mm bonded layer beside the half-space.

# %%
figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
thicknesses = np.geomspace(1e-1, 2e-5, 25)
for base, style in (("bonded", "C0"), ("frictionless", "C1")):
    curve = me.layer_pull_off_curve(paper.replace(**{"layer.base": base}), thicknesses)
    scaled = -curve["pull_off_force"].values / (1.5 * np.pi * DGAMMA * R)
    pull_offs[base] = scaled
    left.semilogx(curve["relative_radius"].values, scaled, style, marker=".", label=f"{base} base, ν = 0.5")
for level, text in ((1.0, "half-space"), (4 / 3, "Winkler: 2πRΔγ"), (2.0, "thin film: 3πRΔγ")):
    left.axhline(level, color="k", ls="--", lw=0.8)
    left.text(0.02, level + 0.015, text, fontsize=8, transform=left.get_yaxis_transform())
left.set_xlabel("a/h at pull-off")
left.set_ylabel("|F_po| / ((3/2)πΔγR)")
left.legend(loc="upper left", bbox_to_anchor=(0.0, 0.9))
for contact, label in ((paper, "half-space"), (paper.replace(h=5e-3), "layer h = 5 mm, bonded")):
    cycle = me.layer_indentation_cycle(contact, 3e-4, 201)
    right.plot(cycle.depth.values * 1e6, cycle.normal_force.values * 1e3, label=label)
right.axhline(0.0, color="k", lw=0.5)
right.set_xlabel("depth d (µm)")
right.set_ylabel("F_N (mN)")
right.legend()
figure.tight_layout()
plt.show()
assert all(np.all(np.diff(scaled) > 0) for scaled in pull_offs.values())  # thinner, harder
assert abs(pull_offs["bonded"][0] - 1) < 1e-2 and pull_offs["bonded"][-1] < 2.0
assert pull_offs["frictionless"][-1] < 4 / 3
