r"""SymPy derivation of what the continuum's spans and events assume of the springs' stiffness, on a layer (issue 34).

On the half-space every spring has ``E*`` and ``G*`` per length, so the continuum (:mod:`mdr_events.models.continuum`)
integrates ``F_x = 2G* ∫₀ᵃ u dξ`` with zone *lengths*, the cap ``ū = K a`` is linear in the radius and
``dF_N/da = 2E*(d + a d' − g)`` along a branch. On a layer of thickness ``h`` the springs' stiffness varies with
``ξ`` (``k = K'/2``, ``k_t = K_t'/2``, :mod:`mdr_events.theory.layer`, :mod:`mdr_events.theory.layer_tangential`). Each
of those assumptions is re-derived here for stiffness densities of any ``ξ``, the layer's factors left as functions of
``λ = a/h`` (``Φ_t`` the tangential punch's factor, ``K_t = 2G* a Φ_t``; ``Θ`` the normal edge factor,
``K' = 2E* Θ²``; ``γ`` the profile's factor, ``g = κₙ c aⁿ γ``), and each checked to give the half-space's relation
at ``Φ_t = Θ = γ = 1``. Nothing is typed in as a result. Sections (:func:`continuum_model_afresh`):

1. the cap (13) on the layer ``ū = π a² τ0/K_t`` in units of the half-space's ``K = π τ0/(2G*)`` (``critical_shift``):
   ``ū = K a/Φ_t``, its slope ``dū/da``, the springs' weight ``w = k_t/G* = d(ξΦ_t)/dξ`` and the weighted measure of
   the springs below ``ξ``, ``M(ξ) = K_t(ξ)/(2G*) = ξΦ_t``; full slip ``2G* ∫₀ᵃ w ū dξ = π a² τ0`` on any layer;
2. the force's rate (Leibniz's rule on ``F_x = 2G* ∫₀ᵃ w u dξ`` with a front ``ξ*`` between sticking springs,
   ``u̇ = v_x``, and springs at the cap, ``u = ū(a)``, ``u`` continuous at the front): the zones enter through their
   weighted measures, and the springs leaving the edge through ``w(a)``;
3. the level's rate: a cap's level ``x − σū(a)`` pushes its springs where ``σ v_x ∂d/∂a − ū'(a) v_d > 0`` (times the
   branch's slope, positive on its stable part);
4. the branch (generalised (9)) ``d = g − sqrt(4π a Δγ/K')`` and its slope with ``γ``, ``Θ`` and their derivatives;
5. the normal force's slope along a branch, ``dF_N/da = K'(a)(d − g(a)) + K(a) d'(a)``, from
   ``F_N = ∫₋ₐᵃ k (d − g) dx`` (the half-space's ``2E*(d + a d' − g)``);
6. Coulomb's cap on the layer (issue 26 and 34): a spring's tangential force ``k_t u`` at most ``μ`` times its normal
   one ``k (d − g)``, so its cap in shift units is ``μ ρ(ξ)(d − g(ξ))``, ``ρ = k/k_t = E*Θ²/(G* w)`` (``μE*/G*`` on
   the half-space); every spring at its cap gives ``2∫₀ᵃ k_t μρ(d − g) dξ = μ F_N``, full slip ``π a² τ0 + μ F_N``.
   ``ρ`` varies with ``ξ``: no level is shared by the springs (the half-space's ``x − σ(K a + κ d)``), and the
   continuum composes each spring's play operator on its own (:mod:`mdr_events.models.continuum.play_springs`).
   Along a path segment without adhesion ``d`` is linear in time, ``a = g⁻¹(d)``, and a spring's lower window edge
   ``L = x − ū(a(d)) − μρ(d − g)`` has ``d²L/dd² = −d²ū(a(d))/dd²``: where ``ū(a(d))`` is concave in ``d`` (the
   paraboloid's and the power laws' ``K a ∝ d^(1/n)``, ``n ≥ 1``) ``L`` is convex and ``U = x + ū + μρ(d − g)``
   concave, so their running extremes over a time interval lie at its ends (checked here on the half-space).

The relations are cached beside the paper's (:func:`continuum_cache_path`), keyed by this module's source.
"""

from __future__ import annotations

import functools
from pathlib import Path

import sympy as sp

from mdr_events.theory import symbolic
from mdr_events.theory.symbolic import Relation

__all__ = ["derive_continuum_model", "continuum_model_afresh", "continuum_cache_path", "CONTINUUM_KEYS"]

a, xi, d, R = (symbolic.SYMBOLS[name] for name in ("a", "x", "d", "R"))
E_star, G_star, tau0, dgamma = (symbolic.SYMBOLS[name] for name in ("E_star", "G_star", "tau0", "dgamma"))
h = sp.Symbol("h", positive=True)
K = sp.Symbol("K", positive=True)                 # the half-space's cap per radius, π τ0/(2G*)
lam = sp.Symbol("lambda", positive=True)
#: the factors at ``λ = a/h`` and their derivatives in ``λ``, as the numeric code hands them in
Phi, Theta, gam = sp.symbols("Phi_t Theta gamma_n", positive=True)
dPhi, dTheta, dgam = sp.symbols("dPhi_t dTheta dgamma_n", real=True)
#: the tangential punch's two factors (T2) and their derivatives in ``λ``
Phi_L, Phi_T = sp.symbols("Phi_L Phi_T", positive=True)
dPhi_L, dPhi_T = sp.symbols("dPhi_L dPhi_T", real=True)
nu = sp.Symbol("nu", positive=True)
kc, n = sp.symbols("kappa_c n", positive=True)    # the half-space's profile g∞ = κₙ c aⁿ
v_x, v_d, sigma = sp.symbols("v_x v_d sigma", real=True)

#: Keys of the relations (:func:`derive_continuum_model`).
CONTINUUM_KEYS = ("layer_continuum_tangential_factor", "layer_continuum_tangential_factor_slope", "layer_continuum_cap",
                  "layer_continuum_cap_slope", "layer_continuum_weight",
                  "layer_continuum_measure", "layer_continuum_force_rate", "layer_continuum_level_rate",
                  "layer_continuum_profile", "layer_continuum_profile_slope", "layer_continuum_branch_depth",
                  "layer_continuum_branch_slope", "layer_continuum_normal_force_slope",
                  "layer_continuum_tangential_factor_pair", "layer_continuum_branch_pair",
                  "layer_continuum_coulomb_ratio")

#: Hash of this module's source and SymPy's version: the key of :func:`continuum_cache_path`.
_SOURCE_DIGEST = symbolic.source_digest(__file__)


def continuum_cache_path() -> Path | None:
    """Where the relations are kept: beside :func:`mdr_events.theory.symbolic.cache_path` (``None``: off).

    Returns
    -------
    pathlib.Path or None
        ``layer-continuum-relations-<hash>.pickle`` in the cache directory, or ``None``.
    """
    return symbolic.sibling_cache_path("layer-continuum-relations", _SOURCE_DIGEST)


@functools.cache
def derive_continuum_model() -> dict[str, Relation]:
    """The relations (:data:`CONTINUUM_KEYS`), derived once per process and cached on disk.

    Returns
    -------
    dict of str to Relation
        The relations by key.
    """
    return symbolic.cached_relations("layer_continuum_model", continuum_model_afresh, continuum_cache_path)


#: Raises ``RuntimeError`` where a step of the derivation does not hold.
_check = symbolic.derivation_check("layer continuum derivation")


def _factor_symbols(expr: sp.Expr, function, value: sp.Symbol, slope: sp.Symbol, at: sp.Expr) -> sp.Expr:
    """``expr`` with ``f(at)`` and ``f'(at)`` (SymPy's ``Subs`` of the derivative) replaced by ``value``, ``slope``."""
    for subs in expr.atoms(sp.Subs):
        if subs.expr.has(function) and isinstance(subs.expr, sp.Derivative):
            expr = expr.subs(subs, slope)
    return expr.subs(function(at), value)


def continuum_model_afresh() -> dict[str, Relation]:
    """Run the derivations with SymPy, bypassing any cache.

    Returns
    -------
    dict of str to Relation
        The relations by key.

    Raises
    ------
    RuntimeError
        If a derived relation does not reduce to the half-space's.
    """
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    _derive_tangential_factor(add)
    _derive_cap(add)
    _derive_rates(add)
    _derive_branch(add)
    _derive_coulomb(add)
    return out


def _derive_tangential_factor(add) -> None:
    """``Φ_t = K_t/(2G* a)`` from the two factors of (T2) (``layer_tangential_stiffness``) and its slope in ``λ``."""
    from mdr_events.theory.layer_tangential_symbolic import derive_tangential_model

    relations = derive_tangential_model()  # K_t of the factors over the half-space's 8Ga/(2 − ν) = 2G* a
    factor = sp.simplify(relations["layer_tangential_stiffness"].rhs
                         / relations["layer_tangential_half_space_stiffness"].rhs)
    _check(factor.free_symbols <= {nu, Phi_L, Phi_T}, "Φ_t depends on more than ν and the two factors")
    _check(sp.simplify(factor.subs({Phi_L: 1, Phi_T: 1}) - 1) == 0, "Φ_t at h = inf")
    L, T = sp.Function("L")(lam), sp.Function("T")(lam)
    slope = sp.diff(factor.subs({Phi_L: L, Phi_T: T}), lam)
    slope = slope.subs({sp.Derivative(L, lam): dPhi_L, sp.Derivative(T, lam): dPhi_T}).subs({L: Phi_L, T: Phi_T})
    add(Relation("layer_continuum_tangential_factor", "(T3)", "Φ_t(λ) = K_t/(2G* a) from Φ_L and Φ_T",
                 sp.Symbol("Phi_t"), factor, (nu, Phi_L, Phi_T)))
    add(Relation("layer_continuum_tangential_factor_slope", "(T3)", "dΦ_t/dλ from Φ_L, Φ_T and their slopes",
                 sp.Symbol("dPhi_t"), sp.simplify(slope), (nu, Phi_L, Phi_T, dPhi_L, dPhi_T)))
    # (both at once, for the continuum's right-hand side: one compiled call sharing their subexpressions)
    add(Relation("layer_continuum_tangential_factor_pair", "(T3)", "(Φ_t, dΦ_t/dλ) from Φ_L, Φ_T and their slopes",
                 sp.Tuple(sp.Symbol("Phi_t"), sp.Symbol("dPhi_t")), sp.Tuple(factor, sp.simplify(slope)),
                 (nu, Phi_L, Phi_T, dPhi_L, dPhi_T)))


def _derive_cap(add) -> None:
    """Section 1: the cap, its slope, the springs' weight and measure; full slip; the half-space."""
    phi = sp.Function("Phi_t")
    stiffness = 2 * G_star * a * phi(a / h)                       # K_t (T3)
    half_space_K = symbolic.relation("critical_shift").rhs.subs(symbolic.SYMBOLS["a"], 1)  # ū/a of (13)
    cap = sp.simplify((sp.pi * a**2 * tau0 / stiffness).subs(tau0, sp.solve(sp.Eq(K, half_space_K), tau0)[0]))
    slope = sp.diff(cap, a)
    measure = stiffness.subs(a, xi) / (2 * G_star)                 # ∫₀^ξ k_t/G* = K_t(ξ)/(2G*)
    weight = sp.diff(measure, xi)                                 # k_t/G* = K_t'/(2G*)
    # every spring at the cap: 2G* ū(a) ∫₀ᵃ w dξ = 2G* ū(a) (M(a) − M(0)), M the antiderivative of w by construction
    full = 2 * G_star * cap * (measure.subs(xi, a) - measure.subs(xi, 0))
    _check(sp.simplify((full - sp.pi * a**2 * tau0).subs(K, half_space_K)) == 0, "full slip is not π a² τ0")
    parts = {"cap": (cap, a / h), "slope": (slope, a / h), "weight": (weight, xi / h), "measure": (measure, xi / h)}
    plain = {name: sp.simplify(_factor_symbols(expr, phi, Phi, dPhi, at)) for name, (expr, at) in parts.items()}
    for name, half in (("cap", K * a), ("slope", K), ("weight", 1), ("measure", xi)):
        _check(sp.simplify(plain[name].subs({Phi: 1, dPhi: 0}) - half) == 0, f"{name} at h = inf")
    _check(not plain["slope"].has(sp.Derivative) and not plain["weight"].has(sp.Derivative), "factor slopes left")
    add(Relation("layer_continuum_cap", "(13)", "the cap of τ0 on the layer, ū = π a² τ0/K_t = K a/Φ_t(a/h)",
                 sp.Symbol("ubar"), plain["cap"], (a, K, Phi)))
    add(Relation("layer_continuum_cap_slope", "(13)", "dū/da on the layer (K: on the half-space)",
                 sp.Symbol("dubar"), plain["slope"], (a, h, K, Phi, dPhi)))
    add(Relation("layer_continuum_weight", "(T4)", "the springs' tangential weight k_t/G* = d(ξ Φ_t)/dξ",
                 sp.Symbol("w"), plain["weight"], (xi, h, Phi, dPhi)))
    add(Relation("layer_continuum_measure", "(T3)", "the springs' weighted measure below ξ, K_t(ξ)/(2G*)",
                 sp.Symbol("M"), plain["measure"], (xi, Phi)))


def _derive_rates(add) -> None:
    """Sections 2–3: the force's rate with a front between sticking springs and springs at the cap; the level's."""
    t = sp.Symbol("t", real=True)
    X, A, S, D = (sp.Function(name)(t) for name in ("X", "A", "S", "D"))
    w, Y, U = sp.Function("w"), sp.Function("Y"), sp.Function("ubar")
    force = 2 * G_star * (sp.Integral(w(xi) * (X - Y(xi)), (xi, 0, S)) + sp.Integral(w(xi) * U(A), (xi, S, A)))
    rate = sp.diff(force, t).doit()
    rate = sp.expand(rate.subs(Y(S), X - U(A)))                   # u continuous at the front: x − Y(ξ*) = ū
    stick, slide = sp.Integral(w(xi), (xi, 0, S)), sp.Integral(w(xi), (xi, S, A))
    expected = 2 * G_star * (stick * sp.diff(X, t) + slide * sp.diff(U(A), t) + w(A) * U(A) * sp.diff(A, t))
    _check(sp.simplify(rate - sp.expand(expected.doit())) == 0, "the force's rate is not the zones' measures")
    M_stick, M_slide, w_edge, u_edge, a_dot, cap_slope = sp.symbols("M_stick M_slide w_a u_a a_dot dubar", real=True)
    add(Relation("layer_continuum_force_rate", "(15)", "dF_x/dt = 2G* [M_stick v_x + M_slide ū'(a) ȧ + w(a) u(a) ȧ]",
                 sp.Symbol("dF_x"),
                 2 * G_star * (M_stick * v_x + M_slide * cap_slope * a_dot + w_edge * u_edge * a_dot),
                 (G_star, M_stick, v_x, M_slide, cap_slope, a_dot, w_edge, u_edge)))
    depth_of = sp.Function("d_branch")
    level = X - sigma * U(A)
    rate_level = sigma * sp.diff(level, t)
    a_rate = sp.diff(D, t) / sp.diff(depth_of(A), A)               # (the branch ties A to D: Ȧ = Ḋ/d'(A))
    pushed = sp.expand(rate_level.subs(sp.Derivative(A, t), a_rate) * sp.diff(depth_of(A), A))
    slope_b = sp.Symbol("dd_da", real=True)
    pushed = pushed.subs({sp.Derivative(X, t): v_x, sp.Derivative(D, t): v_d}).subs(
        sp.diff(depth_of(A), A), slope_b).subs(sp.diff(U(A), A), cap_slope).subs(sigma**2, 1)
    _check(sp.simplify(pushed - (sigma * v_x * slope_b - cap_slope * v_d)) == 0, "the level's rate")
    add(Relation("layer_continuum_level_rate", "", "σ d(level)/dt × ∂d/∂a = σ v_x ∂d/∂a − ū'(a) v_d",
                 sp.Symbol("rate"), pushed, (sigma, v_x, slope_b, cap_slope, v_d)))


def _derive_branch(add) -> None:
    """Sections 4–5: the branch's depth and slope; the normal force's slope along it."""
    gamma_f, theta_f = sp.Function("gamma_n"), sp.Function("Theta")
    profile = kc * a**n * gamma_f(a / h)
    elongation = sp.sqrt(4 * sp.pi * a * dgamma / (2 * E_star * theta_f(a / h) ** 2))   # Δl with K' = 2E* Θ²
    depth = profile - elongation
    plain_profile = _factor_symbols(profile, gamma_f, gam, dgam, a / h)
    profile_slope = sp.expand(_factor_symbols(sp.diff(profile, a), gamma_f, gam, dgam, a / h))
    branch = _factor_symbols(_factor_symbols(depth, gamma_f, gam, dgam, a / h), theta_f, Theta, dTheta, a / h)
    branch_slope = _factor_symbols(_factor_symbols(sp.diff(depth, a), gamma_f, gam, dgam, a / h), theta_f, Theta,
                                   dTheta, a / h)
    half = {gam: 1, dgam: 0, Theta: 1, dTheta: 0, kc: 1 / R, n: 2}
    paper = symbolic.relation("jkr_depth_slope")
    _check(sp.simplify(branch_slope.subs(half) - paper.rhs) == 0, "the branch's slope at h = inf is not (9)'s")
    _check(sp.simplify(branch.subs(half) - symbolic.relation("jkr_depth").rhs) == 0, "the branch at h = inf")
    add(Relation("layer_continuum_profile", "(4)", "g(a) = κₙ c aⁿ γₙ(a/h) on the layer", sp.Symbol("g"),
                 plain_profile, (a, kc, n, gam)))
    add(Relation("layer_continuum_profile_slope", "(4)", "g'(a) on the layer", sp.Symbol("dg"), profile_slope,
                 (a, h, kc, n, gam, dgam)))
    add(Relation("layer_continuum_branch_depth", "(9)", "d(a) = g(a) − sqrt(4π a Δγ/K'(a)), K' = 2E* Θ²",
                 sp.Symbol("d"), branch, (a, kc, n, gam, E_star, dgamma, Theta)))
    add(Relation("layer_continuum_branch_slope", "(9)", "dd/da of the layer's branch", sp.Symbol("dd"), branch_slope,
                 (a, h, kc, n, gam, dgam, E_star, dgamma, Theta, dTheta)))
    # (both at once with Heß's half-space prefactor sqrt(2πΔγ/E*) of (8) taken out: one compiled call per radius)
    hess = sp.Symbol("c_H", positive=True)
    prefactor = symbolic.relation("hess_max_elongation").rhs.subs(a, 1)  # Δl_max = c_H √a (8)
    pair = sp.Tuple(branch, branch_slope).subs(dgamma, sp.solve(sp.Eq(hess, prefactor), dgamma)[0])
    _check(not pair.has(dgamma) and not pair.has(E_star), "the branch's pair keeps Δγ or E* beside Heß's prefactor")
    add(Relation("layer_continuum_branch_pair", "(9)", "(d(a), dd/da) of the layer's branch, c_H = sqrt(2π Δγ/E*)",
                 sp.Tuple(sp.Symbol("d"), sp.Symbol("dd")), sp.simplify(pair), (a, h, kc, n, gam, dgam, hess, Theta,
                                                                             dTheta)))
    k_fn, g_fn, d_fn = sp.Function("k"), sp.Function("g"), sp.Function("d")
    force = sp.Integral(2 * k_fn(xi) * (d_fn(a) - g_fn(xi)), (xi, 0, a))    # F_N = ∫₋ₐᵃ k (d − g), k even
    K_a, dK_a, d_a, g_a, dd_a = sp.symbols("K_a dK_a d_a g_a dd_a", real=True)
    slope = sp.diff(force, a).doit()
    # K(a) = ∫₋ₐᵃ k = 2∫₀ᵃ k and K'(a) = 2k(a) (k = K'/2 of the generalized MDR)
    slope = slope.subs(sp.Integral(k_fn(xi), (xi, 0, a)), K_a / 2).subs(k_fn(a), dK_a / 2)
    slope = slope.subs(sp.Derivative(d_fn(a), a), dd_a).subs({d_fn(a): d_a, g_fn(a): g_a})
    closed = dK_a * (d_a - g_a) + K_a * dd_a
    _check(sp.simplify(slope - closed) == 0, "dF_N/da is not K'(d − g) + K d'")
    half_force = closed.subs({K_a: 2 * E_star * a, dK_a: 2 * E_star})
    _check(sp.simplify(half_force - 2 * E_star * (d_a + a * dd_a - g_a)) == 0, "dF_N/da at h = inf")
    add(Relation("layer_continuum_normal_force_slope", "(10)", "dF_N/da along a branch = K'(a)(d − g(a)) + K(a) d'(a)",
                 sp.Symbol("dF_N"), closed, (K_a, dK_a, d_a, g_a, dd_a)))


def _derive_coulomb(add) -> None:
    """Section 6: Coulomb's cap per compression ``ρ = k/k_t``, full slip ``μ F_N``, the window edges' convexity."""
    w_fn, k_fn, g_fn = sp.Function("w"), sp.Function("k"), sp.Function("g")
    mu = sp.Symbol("mu", nonnegative=True)
    ratio = (E_star * Theta**2) / (G_star * sp.Symbol("w", positive=True))   # k/k_t with k = K'/2 = E*Θ², k_t = G* w
    _check(sp.simplify(ratio.subs({Theta: 1, sp.Symbol("w", positive=True): 1}) - E_star / G_star) == 0,
           "Coulomb's ratio at h = inf")
    # every spring at its cap: 2∫ k_t μ (k/k_t)(d − g) dξ = μ ∫₋ₐᵃ k (d − g) dx = μ F_N (10), whatever w is
    at_caps = 2 * sp.Integral(G_star * w_fn(xi) * mu * (k_fn(xi) / (G_star * w_fn(xi))) * (d - g_fn(xi)), (xi, 0, a))
    normal = sp.Integral(2 * k_fn(xi) * (d - g_fn(xi)), (xi, 0, a))
    _check(sp.simplify(at_caps.doit() - mu * normal.doit()) == 0, "full slip is not μ F_N")
    # the window edges along a segment without adhesion, in the depth e: L convex where ū(a(e)) is concave
    e, rho, slope_x = sp.symbols("e rho s_x", positive=True)
    n_sym, c_sym = sp.symbols("n c", positive=True)
    for shift, name in ((K * sp.sqrt(R * e), "the paraboloid"), (K * (e / c_sym)**(1 / n_sym), "a power law")):
        lower = slope_x * e - shift - mu * rho * (e - g_fn(xi))
        curvature = sp.simplify(sp.diff(lower, e, 2))
        _check(sp.simplify(curvature + sp.diff(shift, e, 2)) == 0, f"L's curvature on {name}")
        if name == "the paraboloid":
            _check(bool(sp.simplify(curvature).is_positive), "L is not convex on the paraboloid")
    add(Relation("layer_continuum_coulomb_ratio", "(13)", "Coulomb's cap per compression ρ = k/k_t = E*Θ²/(G* w)",
                 sp.Symbol("rho"), ratio, (E_star, G_star, Theta, sp.Symbol("w", positive=True))))
