r"""SymPy derivation of the layer's tangential compliance and of its limits (issue 34, item 3).

Nothing is typed in as a result: the top's response of a layer (thickness ``h``, lengths in ``1/ξ``, ``t = ξh``) to a
pressure and a shear traction ``∝ e^{iξx}`` is solved from the Papkovich–Neuber representation
``2G u = ∇(φ + zψ) − 4(1 − ν)ψ e_z`` (harmonic ``φ``, ``ψ``; valid at ``ν = 0.5``), the anti-plane part from
``G(u_y'' − u_y) = 0``; base bonded or frictionless. Sections (:func:`tangential_model_afresh`):

1. the compliance matrix of the top, ``[u_z; u_x] = (1/G)[[(1 − ν)C_N, C_zx], [−C_zx, (1 − ν)C_L]] [p; q]``, and
   ``u_y = (C_T/G) q_y``; ``C_N`` is checked against Love's function of
   :func:`mdr_events.theory.layer_symbolic.love_compliance` (an independent route to the normal problem);
2. the half-space ``t → ∞``: ``C_L, C_T → 1``, ``|C_zx| → (1 − 2ν)/2``, and the flat punch's
   ``K_t = 8Ga/(2 − ν) = 2G* a`` from (T3) with ``Φ_L = Φ_T = 1``;
3. the thin bonded layer: ``(1 − ν)C_L ≈ t``, ``C_T ≈ t``: a Winkler foundation in shear ``q = (G/h) u``,
   ``K_t = π a² G/h``; the coupling at ``ν = 0.5``, ``C_zx/sqrt(C_zz C_xx) → √3/2``;
4. the frictionless base: ``(1 − ν)C_L`` and ``C_T`` grow as ``1/t``: no tangential stiffness at the layer's scale;
5. the decoupling of the punch's pair of equations into (T2) for ``P = Θ₀ + X`` and ``Q = Θ₀ − X`` and the stiffness
   (T3), by linear algebra on the operators' symbols.
"""

from __future__ import annotations

import functools
from pathlib import Path

import sympy as sp

from mdr_events.theory import layer_symbolic, symbolic
from mdr_events.theory.symbolic import Relation

__all__ = ["derive_tangential_model", "tangential_model_afresh", "tangential_cache_path", "TANGENTIAL_KEYS",
           "top_compliance"]

t = sp.Symbol("t", positive=True)
z = sp.Symbol("z", positive=True)
xs = sp.Symbol("x", real=True)
nu = sp.Symbol("nu", positive=True)
G = sp.Symbol("G", positive=True)
h = sp.Symbol("h", positive=True)
a = symbolic.SYMBOLS["a"]

#: Keys of the relations (:func:`derive_tangential_model`).
TANGENTIAL_KEYS = ("layer_compliance_longitudinal_bonded", "layer_compliance_transverse_bonded",
                   "layer_coupling_bonded", "layer_compliance_longitudinal_frictionless",
                   "layer_compliance_transverse_frictionless", "layer_tangential_half_space_stiffness",
                   "layer_shear_winkler_modulus", "layer_shear_winkler_stiffness", "layer_tangential_stiffness",
                   "layer_thin_sliding_cap", "layer_thin_onset_depth_A")

#: Hash of this module's source and SymPy's version: the key of :func:`tangential_cache_path`.
_SOURCE_DIGEST = symbolic.source_digest(__file__)


def tangential_cache_path() -> Path | None:
    """Where the relations are kept: beside :func:`mdr_events.theory.symbolic.cache_path` (``None``: off).

    Returns
    -------
    pathlib.Path or None
        ``layer-tangential-relations-<hash>.pickle`` in the cache directory, or ``None``.
    """
    return symbolic.sibling_cache_path("layer-tangential-relations", _SOURCE_DIGEST)


@functools.cache
def derive_tangential_model() -> dict[str, Relation]:
    """The relations (:data:`TANGENTIAL_KEYS`), derived once per process and cached on disk.

    Returns
    -------
    dict of str to Relation
        The relations by key.
    """
    return symbolic.cached_relations("layer_tangential_model", tangential_model_afresh, tangential_cache_path)


#: Raises ``RuntimeError`` where a step of the derivation does not hold.
_check = symbolic.derivation_check("tangential layer derivation")


def top_compliance(base: str) -> dict[str, sp.Expr]:
    r"""The top's compliances ``C_N``, ``C_L``, ``C_T`` and ``C_zx`` of a layer (section 1), ``ξ = G = 1``.

    ``σ_zz = −p``, ``σ_xz = −q`` at ``z = 0`` (``z`` into the layer), ``u_x = u_z = 0`` (bonded) or
    ``σ_xz = u_z = 0`` (frictionless) at ``z = t``; ``C_N = u_z/((1 − ν)p)``, ``C_L = u_x/((1 − ν)q)``,
    ``C_zx = u_z/q`` (imaginary: a factor ``i`` dropped), ``C_T = u_y/q_y``.

    Parameters
    ----------
    base : str
        ``"bonded"`` or ``"frictionless"``.

    Returns
    -------
    dict of str to sympy.Expr
        ``"normal"``, ``"longitudinal"``, ``"transverse"``, ``"coupling"`` in exponentials of ``t`` and ``ν``.

    Raises
    ------
    ValueError
        ``base`` not one of the two.
    """
    if base not in ("bonded", "frictionless"):
        raise ValueError(f"base={base!r} is not allowed; allowed: 'bonded', 'frictionless'")
    A, B, C, D, p, q = sp.symbols("A B C D p q")
    wave = sp.exp(sp.I * xs)
    phi, psi = (A * sp.exp(z) + B * sp.exp(-z)) * wave, (C * sp.exp(z) + D * sp.exp(-z)) * wave
    ux, uz = sp.diff(phi + z * psi, xs) / 2, (sp.diff(phi + z * psi, z) - 4 * (1 - nu) * psi) / 2
    szz = -2 * nu * sp.diff(psi, z) + 2 * sp.diff(uz, z)  # λ div u = −2ν ψ_z (G = 1)
    sxz = sp.diff(ux, z) + sp.diff(uz, xs)

    def at(field, depth):
        return sp.simplify((field / wave).subs(z, depth))

    bottom = (ux, uz) if base == "bonded" else (sxz, uz)
    equations = [sp.Eq(at(szz, 0), -p), sp.Eq(at(sxz, 0), -q)] + [sp.Eq(at(f, t), 0) for f in bottom]
    solution = sp.solve(equations, [A, B, C, D], dict=True)[0]
    uz0, ux0 = sp.expand(at(uz, 0).subs(solution)), sp.expand(at(ux, 0).subs(solution))
    V = sp.Function("V")
    shear = sp.dsolve(sp.diff(V(z), z, 2) - V(z), V(z)).rhs  # anti-plane: u_y = V(z) e^{ix}
    c1, c2 = sorted(shear.free_symbols - {z}, key=str)
    base_condition = shear.subs(z, t) if base == "bonded" else sp.diff(shear, z).subs(z, t)
    anti = sp.solve([sp.Eq(sp.diff(shear, z).subs(z, 0), -1), sp.Eq(base_condition, 0)], [c1, c2], dict=True)[0]

    def tidy(expr):
        return sp.simplify(sp.simplify(expr).rewrite(sp.exp))

    return {"normal": tidy(sp.diff(uz0, p) / (1 - nu)), "longitudinal": tidy(sp.diff(ux0, q) / (1 - nu)),
            "coupling": tidy(sp.diff(uz0, q) / sp.I), "transverse": tidy(shear.subs(anti).subs(z, 0))}


def tangential_model_afresh() -> dict[str, Relation]:
    """Run the derivations with SymPy, bypassing any cache.

    Returns
    -------
    dict of str to Relation
        The relations by key.

    Raises
    ------
    RuntimeError
        If a derived limit is not the one stated.
    """
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    bonded, free = top_compliance("bonded"), top_compliance("frictionless")
    for name, parts in (("bonded", bonded), ("frictionless", free)):
        love = layer_symbolic.love_compliance(name)
        _check(sp.simplify((parts["normal"] - love).rewrite(sp.exp)) == 0, f"C_N ({name}) is not Love's")
        for mode in ("longitudinal", "transverse"):
            add(Relation(f"layer_compliance_{mode}_{name}", "(T1)", f"tangential compliance C_{mode[0].upper()}(ξh), "
                         f"{name} base", sp.Function(f"C_{mode[0].upper()}")(t), parts[mode], (t, nu)))
    add(Relation("layer_coupling_bonded", "(T1)", "normal displacement per shear traction C_zx(ξh), bonded base",
                 sp.Function("C_zx")(t), bonded["coupling"], (t, nu)))
    _derive_limits(add, bonded, free)
    _derive_decoupling(add)
    return out


def _derive_limits(add, bonded: dict, free: dict) -> None:
    """Sections 2–4: the half-space, the thin bonded layer (shear Winkler, the coupling at ν = 0.5), the
    frictionless base."""
    for parts in (bonded, free):
        for mode in ("longitudinal", "transverse"):
            _check(sp.limit(parts[mode], t, sp.oo) == 1, f"C_{mode} does not tend to 1")
        _check(sp.simplify(sp.limit(parts["coupling"], t, sp.oo) + (1 - 2 * nu) / 2) == 0, "half-space coupling")
    longitudinal = sp.series((1 - nu) * bonded["longitudinal"], t, 0, 3).removeO()
    transverse = sp.series(bonded["transverse"], t, 0, 3).removeO()
    _check(sp.simplify(longitudinal - t) == 0 and sp.simplify(transverse - t) == 0, "thin layer: not û = (h/G)q̂")
    modulus = G / h  # û = (t/(Gξ)) q̂ = (h/G) q̂
    add(Relation("layer_shear_winkler_modulus", "", "thin bonded layer in shear: q = (G/h) u", sp.Symbol("kappa_t"),
                 modulus, (G, h)))
    thin_stiffness = sp.integrate(2 * sp.pi * sp.Symbol("r") * modulus, (sp.Symbol("r"), 0, a))
    add(Relation("layer_shear_winkler_stiffness", "(T3)", "thin bonded layer: K_t = π a² G/h", sp.Symbol("K_t"),
                 thin_stiffness, (a, G, h)))
    tau0, tan_alpha = symbolic.SYMBOLS["tau0"], symbolic.SYMBOLS["tan_alpha"]
    cap = sp.simplify(sp.pi * a**2 * tau0 / thin_stiffness)  # (13) on the layer, ū = π a² τ0 / K_t
    _check(cap.free_symbols == {tau0, h, G}, "thin layer: the cap depends on the radius")
    add(Relation("layer_thin_sliding_cap", "(13)", "thin bonded layer: ū = π a² τ0/K_t, the same for every radius",
                 sp.Symbol("ubar"), cap, (tau0, G, h)))
    add(Relation("layer_thin_onset_depth_A", "(17)", "thin bonded layer, scenario A: d/tan α = ū at any radius",
                 sp.Symbol("d_crit"), tan_alpha * cap, (tan_alpha, tau0, G, h)))
    half = {key: value.subs(nu, sp.Rational(1, 2)) for key, value in bonded.items()}
    ratio = half["coupling"] / ((1 - sp.Rational(1, 2)) * sp.sqrt(half["normal"] * half["longitudinal"]))
    _check(sp.simplify(sp.limit(sp.Abs(ratio), t, 0) - sp.sqrt(3) / 2) == 0, "ν = 0.5 coupling at t → 0")
    for mode in ("longitudinal", "transverse"):
        leading = sp.limit(t * free[mode], t, 0)
        _check(leading.is_positive, f"frictionless base: C_{mode} does not grow as 1/t")


def _derive_decoupling(add) -> None:
    """Section 5: with the half-space symbols ``(2 − ν) ± ν`` and the layers' ``(1 − ν)K_L + K_T``,
    ``(1 − ν)K_L − K_T`` the pair for ``(Θ₀, X)`` is the pair (T2) for ``P = Θ₀ + X`` and ``Q = Θ₀ − X``."""
    KL, KT, th, X, b = sp.symbols("K_L K_T Theta_0 X b")
    s = 2 - nu
    eq0 = s * th + nu * X - ((1 - nu) * KL + KT) * th + ((1 - nu) * KL - KT) * X - s
    eq2 = s * X + nu * th - ((1 - nu) * KL + KT) * X + ((1 - nu) * KL - KT) * th - b
    P, Q = th + X, th - X
    _check(sp.expand(eq0 + eq2 - (2 * (P - KT * P) - (s + b))) == 0, "P does not decouple")
    _check(sp.expand(eq0 - eq2 - (2 * (1 - nu) * (Q - KL * Q) - (s - b))) == 0, "Q does not decouple")
    phi_l, phi_t = sp.symbols("Phi_L Phi_T", positive=True)
    b_value = sp.solve(sp.Eq((s + b) / 2 * phi_t, (s - b) / (2 * (1 - nu)) * phi_l), b)[0]  # ∫X = 0
    phi = sp.simplify((s + b_value) / 2 * phi_t)  # ∫Θ₀ = ∫P
    stiffness = sp.simplify(8 * G * a * phi / s)  # F = 2π ∫φ₀ = (8Ga/s) ∫Θ₀ u₀
    _check(sp.simplify(stiffness.subs({phi_l: 1, phi_t: 1}) - 8 * G * a / s) == 0, "half-space K_t")
    add(Relation("layer_tangential_half_space_stiffness", "(T3)", "half-space: K_t = 8Ga/(2 − ν) = 2G* a",
                 sp.Symbol("K_t"), stiffness.subs({phi_l: 1, phi_t: 1}), (a, G, nu)))
    add(Relation("layer_tangential_stiffness", "(T3)", "K_t from the factors of (T2)", sp.Symbol("K_t"), stiffness,
                 (a, G, nu, phi_l, phi_t)))
