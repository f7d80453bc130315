r"""SymPy derivation of the generalized MDR for a layer on a rigid base (issue 34) and of its limits.

Nothing is typed in as a result: the layer's compliance function is solved from Love's strain function with the
boundary conditions, its limits taken, the thin layers' punch problems integrated, and Heß's rule obtained from
Griffith's energy balance. The numerical module :mod:`mdr_events.theory.layer` solves the punch equation with the
compliance derived here (the tests compare them) and evaluates the relations.

Sections (:func:`layer_model_afresh`):

1. the compliance ``C(t)`` of a layer with a frictionless top, base bonded or frictionless (Love's function
   ``Φ(z) J₀(ξr)``, ``Φ = (A + Bz)e^{z} + (C + Dz)e^{−z}``, lengths in ``1/ξ``, ``z`` into the layer);
2. the half-space limit ``t → ∞``: ``C → 1``, ``K = 2E* a``, ``k = E*``, Heß's rule (8), the inverse of (3);
3. the thin compressible layer: Winkler's foundation ``κ = 2G(1 − ν)/((1 − 2ν) h)`` (bonded) or ``E*/h``
   (frictionless base), ``K = π κ a²``, ``g = f``, ``Δl = sqrt(2Δγ/κ)``;
4. the thin incompressible bonded layer: ``w = −(h³/3G) ∇²p``, ``K = 3πG a⁴/(8h³)``, the punch's edge line
   displacement ``φ = −(ã/2) δ(r − ã)`` and the MDR profile ``g = x²/(4R)`` of the paraboloid, ``d = a²/(4R)``,
   ``F = πG a⁶/(32 R h³)`` (checked against the thin-film solution of the paraboloid itself);
5. Griffith's balance on any ``K(a)``: ``∂U/∂a|_d = ½ K'(a)(d − g(a))²`` so ``Δl = sqrt(4π a Δγ / K'(a))``, and
   ``F_N = ∂U/∂d = F₀(a) + K(a)(d − g(a))``.
6. the pull-off of the paraboloid under force control on the thin layers, from sections 3–5 (``F = ∫₀ᵃ K'(x)(d − g(x))
   dx`` on Heß's branch ``d = g(a) − Δl``, minimised over ``a``): ``−2πRΔγ`` on Winkler's foundation (any ``κ``:
   the compressible bonded layer, any layer on a frictionless base) and ``−3πRΔγ`` on the thin incompressible bonded
   film, against ``−(3/2)πRΔγ`` on the half-space (``Δγ`` the work of adhesion of Heß's rule (8)).
7. the flat punch of radius ``a`` on a layer: ``f = 0`` under the face makes ``g = 0`` and ``F₀ = 0``, so
   ``F_N = K(a) d`` (``π κ a² d`` on Winkler's foundation); the face's edge lets go at ``d = −Δl(a)`` of section 5,
   the half-space's flat punch (Kendall) at ``K' = 2E*``. Where ``a/K'(a)`` falls (``a K'' > K'``: the thin
   incompressible film, ``Δl ∝ 1/a``) a contact smaller than the face holds further out: under depth control the
   contact recedes under the face along ``d = −Δl(a)``; where it rises (the half-space) or stays (Winkler, every
   spring at one limit) the whole face comes off at once. Under force control the pull-off is ``−K Δl`` at the face's
   radius wherever ``a K²/K'`` rises (on all three).
8. the flat punch's receding branch under depth control: once ``d`` reaches ``−Δl(a₀)`` the edge follows
   ``d = −Δl(a)`` while ``dΔl/da < 0`` (``dd/da > 0``: stable recession, ``a K'' > K'``) and pulls off where
   ``dΔl/da = 0`` (``a K'' = K'``) or at ``a → 0``; its force is the springs' ``∫₀ᵃ K'(x)(d − 0) dx = K(a) d``, the
   springs let go beyond ``a`` storing none (``F₀ = ∫₀ᵃ K g' = 0``: the face is flat), so ``F_N = −K(a) Δl(a)``,
   continuous at the switch. On the half-space (``Δl ∝ √a``, ``dΔl/da > 0``) no radius below ``a₀`` holds: today's
   jump at Kendall's depth; on Winkler's foundation ``Δl`` is constant (neutral: every spring at one limit, the whole
   face at once); on the thin film ``Δl ∝ 1/a`` recedes to ``a → 0`` with ``F ∝ a³ → 0``.

The relations are cached beside the paper's (:func:`layer_cache_path`), keyed by this module's source.
"""

from __future__ import annotations

import functools
from pathlib import Path

import sympy as sp

from mdr_events.theory import symbolic
from mdr_events.theory.symbolic import Relation

__all__ = ["derive_layer_model", "layer_model_afresh", "layer_cache_path", "LAYER_KEYS", "love_compliance",
           "receding_energy"]

t = sp.Symbol("t", positive=True)              # ξ h
z = sp.Symbol("z", positive=True)
nu = sp.Symbol("nu", positive=True)
G = sp.Symbol("G", positive=True)
h = sp.Symbol("h", positive=True)
K_W = sp.Symbol("kappa_W", positive=True)
w0 = sp.Symbol("w_0", positive=True)
a_t = sp.Symbol("atilde", positive=True)
C_ = sp.Symbol("C")
a, r, x, R, d = (symbolic.SYMBOLS[name] for name in ("a", "r", "x", "R", "d"))
E_star, dgamma = symbolic.SYMBOLS["E_star"], symbolic.SYMBOLS["dgamma"]
F_N, dl_max = symbolic.F_N, symbolic.dl_max
K_fn, g_fn, F0_fn = sp.Function("K"), sp.Function("g"), sp.Function("F_0")

#: Keys of the layer's relations (:func:`derive_layer_model`).
LAYER_KEYS = ("layer_compliance_bonded", "layer_compliance_frictionless", "layer_half_space_stiffness",
              "layer_winkler_modulus", "layer_winkler_modulus_frictionless", "layer_winkler_stiffness",
              "layer_winkler_hess", "layer_thin_film_mobility", "layer_thin_film_stiffness",
              "layer_thin_film_edge_displacement", "layer_thin_film_profile", "layer_thin_film_depth",
              "layer_thin_film_force", "layer_energy_slope", "layer_hess_elongation", "layer_normal_force",
              "layer_winkler_pull_off_radius", "layer_winkler_pull_off", "layer_thin_film_pull_off_radius",
              "layer_thin_film_pull_off", "layer_flat_punch_force", "layer_flat_punch_winkler_force",
              "layer_flat_punch_hess", "layer_flat_punch_recedes", "layer_flat_punch_pull_off",
              "layer_flat_punch_receding_slope", "layer_flat_punch_receding_force")

#: Hash of this module's source and SymPy's version: the key of :func:`layer_cache_path`.
_SOURCE_DIGEST = symbolic.source_digest(__file__)


def layer_cache_path() -> Path | None:
    """Where the layer's relations are kept: beside :func:`mdr_events.theory.symbolic.cache_path` (``None``: off).

    Returns
    -------
    pathlib.Path or None
        ``layer-relations-<hash>.pickle`` in the cache directory, or ``None`` (``MDR_EVENTS_NO_CACHE=1``).
    """
    return symbolic.sibling_cache_path("layer-relations", _SOURCE_DIGEST)


@functools.cache
def derive_layer_model() -> dict[str, Relation]:
    """The layer's relations (:data:`LAYER_KEYS`), derived once per process and cache.

    Returns
    -------
    dict of str to Relation
        The relations by key, in derivation order.
    """
    return symbolic.cached_relations("layer_model", layer_model_afresh, layer_cache_path)


def layer_model_afresh() -> dict[str, Relation]:
    """Run the layer's derivations with SymPy (about 5 s), bypassing any cache.

    Returns
    -------
    dict of str to Relation
        The relations by key, in derivation order.

    Raises
    ------
    RuntimeError
        If a derived limit is not the one stated (a derivation that went wrong).
    """
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> Relation:
        out[rel.key] = rel
        return rel

    bonded, frictionless = love_compliance("bonded"), love_compliance("frictionless")
    add(Relation("layer_compliance_bonded", "(L1)", "compliance C(ξh) of a layer bonded to a rigid base",
                 sp.Function("C")(t), bonded, (t, nu)))
    add(Relation("layer_compliance_frictionless", "(L1)", "compliance C(ξh) of a layer on a frictionless base",
                 sp.Function("C")(t), frictionless, (t, nu)))
    _derive_half_space(add, bonded, frictionless)
    _derive_winkler(add, bonded, frictionless)
    _derive_thin_film(add, bonded)
    _derive_griffith(add)
    _derive_thin_pull_off(add, out)
    _derive_flat_punch(add, out)
    _derive_receding_punch(add, out)
    return out


def love_compliance(base: str) -> sp.Expr:
    r"""The compliance ``C(t)``, ``t = ξh``, of the layer from Love's strain function (section 1).

    With ``φ = Φ(z) J₀(ξr)`` (``ξ = 1``): ``2G u_r = Φ' J₁``, ``2G u_z = [(1 − 2ν)Φ'' − 2(1 − ν)Φ] J₀``,
    ``σ_zz = [(1 − ν)Φ''' − (2 − ν)Φ'] J₀``, ``σ_rz = [νΦ'' + (1 − ν)Φ] J₁``; ``σ_zz = −P``, ``σ_rz = 0`` at the
    top, ``u_r = u_z = 0`` (bonded) or ``σ_rz = u_z = 0`` (frictionless) at ``z = t``;
    ``C = E* u_z(0)/(2P)``, ``E* = 2G/(1 − ν)``.

    Parameters
    ----------
    base : str
        ``"bonded"`` or ``"frictionless"``.

    Returns
    -------
    sympy.Expr
        ``C(t)`` in exponentials of ``t`` and ``ν``.

    Raises
    ------
    ValueError
        ``base`` not one of the two.
    """
    A, B, C, D, P = sp.symbols("A B C D P")
    Phi = (A + B * z) * sp.exp(z) + (C + D * z) * sp.exp(-z)
    dz = [sp.diff(Phi, z, order) for order in range(4)]
    u_r, u_z = dz[1], (1 - 2 * nu) * dz[2] - 2 * (1 - nu) * dz[0]
    s_zz, s_rz = (1 - nu) * dz[3] - (2 - nu) * dz[1], nu * dz[2] + (1 - nu) * dz[0]
    bottoms = {"bonded": (u_r, u_z), "frictionless": (s_rz, u_z)}
    if base not in bottoms:
        raise ValueError(f"base={base!r} is not allowed; allowed: 'bonded', 'frictionless'")
    equations = [sp.Eq(s_zz.subs(z, 0), -P), sp.Eq(s_rz.subs(z, 0), 0)]
    equations += [sp.Eq(field.subs(z, t), 0) for field in bottoms[base]]
    solution = sp.solve(equations, [A, B, C, D], dict=True)[0]
    return sp.simplify((u_z.subs(z, 0).subs(solution) / (2 * (1 - nu) * P)).rewrite(sp.exp))


#: Raises ``RuntimeError`` where a step of the derivation does not hold.
_check = symbolic.derivation_check("layer derivation")


def _derive_half_space(add, bonded: sp.Expr, frictionless: sp.Expr) -> None:
    """Section 2: ``C → 1`` as ``t → ∞``; the flat punch of the Fredholm representation with ``C = 1`` has
    ``θ = E* w₀/π`` and ``K = 2E* a``; ``φ = (2/π) arcsin(ã/r)`` makes ``f = ∫[1 − φ] g'`` the inverse of (3)."""
    for name, compliance in (("bonded", bonded), ("frictionless", frictionless)):
        _check(sp.limit(compliance, t, sp.oo) == 1, f"C_{name} does not tend to 1 as t -> oo")
    # (2/E*)(2/π) ∫₀ʳ B dt/√(r² − t²) = w₀ for every r < a, B = (π/2) θ constant
    B = sp.Symbol("B")
    abel = (2 / E_star) * (2 / sp.pi) * B * sp.integrate(1 / sp.sqrt(r**2 - x**2), (x, 0, r))
    theta = 2 / sp.pi * sp.solve(sp.Eq(abel, w0), B)[0]
    stiffness = sp.simplify(2 * sp.pi * sp.integrate(theta, (x, 0, a)) / w0)
    _check(sp.simplify(stiffness - 2 * E_star * a) == 0, "the half-space punch is not K = 2E* a")
    add(Relation("layer_half_space_stiffness", "(L2)", "flat punch on the half-space (C = 1): K = 2E* a, k = K'/2 = E*",
                 sp.Symbol("K"), stiffness, (a, E_star)))
    g_parab = symbolic.derive()["profile_paraboloid"].rhs.subs(x, a_t)  # (4): g = x²/R
    phi = 2 / sp.pi * sp.asin(a_t / r)
    f_back = sp.integrate(sp.simplify((1 - phi) * sp.diff(g_parab, a_t)), (a_t, 0, r))
    _check(sp.simplify(f_back - r**2 / (2 * R)) == 0, "f = ∫[1 − φ] g' does not invert (3) on the half-space")


def _local_modulus(compliance: sp.Expr, order: int) -> sp.Expr:
    """The coefficient of ``t**order`` of ``C`` at ``t = 0`` (the leading term of a thin layer)."""
    series = sp.series(compliance, t, 0, order + 1).removeO()
    return sp.simplify(series.coeff(t, order))


def _derive_winkler(add, bonded: sp.Expr, frictionless: sp.Expr) -> None:
    """Section 3: ``C ≈ c₁ ξh`` makes ``ŵ = (2c₁h/E*) p̂``: a Winkler foundation of modulus ``κ = E*/(2c₁h)``."""
    E_of_G = 2 * G / (1 - nu)  # E* = E/(1 − ν²), E = 2G(1 + ν)
    kappa_bonded = sp.simplify(E_of_G / (2 * _local_modulus(bonded, 1) * h))
    _check(sp.simplify(kappa_bonded - 2 * G * (1 - nu) / ((1 - 2 * nu) * h)) == 0, "bonded Winkler modulus")
    add(Relation("layer_winkler_modulus", "", "thin compressible bonded layer: Winkler's modulus κ", K_W,
                 kappa_bonded, (G, nu, h)))
    kappa_free = sp.simplify(E_of_G / (2 * _local_modulus(frictionless, 1) * h))
    add(Relation("layer_winkler_modulus_frictionless", "", "thin layer on a frictionless base: Winkler's modulus "
                 "κ = E*/h", K_W, kappa_free, (G, nu, h)))
    stiffness = sp.integrate(2 * sp.pi * r * K_W, (r, 0, a))  # w = p/κ under the punch, nothing outside: g = f
    add(Relation("layer_winkler_stiffness", "(L2)", "Winkler punch stiffness K = π κ a² (g = f)", sp.Symbol("K"),
                 stiffness, (a, K_W)))
    hess = sp.sqrt(4 * sp.pi * a * dgamma / sp.diff(stiffness, a))
    local = sp.solve(sp.Eq(K_W * dl_max**2 / 2, dgamma), dl_max)  # the edge's own Griffith balance
    _check(any(sp.simplify(hess - root) == 0 for root in local), "Heß's rule on Winkler is not sqrt(2Δγ/κ)")
    add(Relation("layer_winkler_hess", "(8)", "Heß's rule on a Winkler foundation: Δl = sqrt(2Δγ/κ)", dl_max,
                 sp.simplify(hess), (dgamma, K_W)))


def _derive_thin_film(add, bonded: sp.Expr) -> None:
    """Section 4: the thin incompressible bonded layer, its punch, its edge line displacement, the paraboloid."""
    compliance = bonded.subs(nu, sp.Rational(1, 2))
    _check(_local_modulus(compliance, 1) == 0, "an incompressible layer is not stiffer than Winkler's")
    mobility = sp.simplify(2 * _local_modulus(compliance, 3) * h**3 / (4 * G))  # ŵ = (2c₃ξ²h³/E*) p̂, E* = 4G
    add(Relation("layer_thin_film_mobility", "", "thin incompressible layer: w = −m ∇²p", sp.Symbol("m"), mobility,
                 (G, h)))
    # punch: (1/r)(r p')' = −w₀/m, p(a) = 0, p bounded
    slope = -w0 * r / (2 * mobility)
    pressure = sp.integrate(slope, (r, a, r))
    stiffness = sp.simplify(2 * sp.pi * sp.integrate(pressure * r, (r, 0, a)) / w0)
    add(Relation("layer_thin_film_stiffness", "(L2)", "thin incompressible layer: K = 3πG a⁴/(8h³)", sp.Symbol("K"),
                 stiffness, (a, G, h)))
    line = sp.simplify(mobility * slope.subs(r, a) / w0)  # w = −m∇²p: the jump of p' at the edge, a line of w
    _check(sp.simplify(sp.pi * a**2 + 2 * sp.pi * a * line) == 0, "the thin film's punch does not keep the volume")
    add(Relation("layer_thin_film_edge_displacement", "(L5)", "φ outside a punch on the thin film: −(ã/2) δ(r − ã)",
                 sp.Symbol("phi_line"), line.subs(a, a_t), (a_t,)))
    f_parab = r**2 / (2 * R)
    # f(r) = ∫₀ʳ [1 − φ] g' dã = g(r) + (r/2) g'(r)  ⇔  (x² g)' = 2x f
    g_thin = sp.simplify(sp.integrate(2 * r * f_parab, (r, 0, x)) / x**2)
    add(Relation("layer_thin_film_profile", "(4)", "thin incompressible layer: MDR profile of the paraboloid",
                 sp.Function("g")(x), g_thin, (x, R)))
    _thin_film_paraboloid(add, mobility, stiffness, g_thin)


def _thin_film_paraboloid(add, mobility: sp.Expr, stiffness: sp.Expr, g_thin: sp.Expr) -> None:
    """The paraboloid on the thin film by the MDR and by the film's own equation (``p(a) = p'(a) = 0``)."""
    depth = g_thin.subs(x, a)
    force_mdr = sp.simplify(sp.integrate(sp.diff(stiffness, a).subs(a, x) * (depth - g_thin), (x, 0, a)))
    slope = -sp.integrate(r * (d - r**2 / (2 * R)), r) / (r * mobility)
    direct_depth = sp.solve(sp.Eq(slope.subs(r, a), 0), d)[0]
    pressure = sp.integrate(slope, (r, a, r)).subs(d, direct_depth)
    force_direct = sp.simplify(2 * sp.pi * sp.integrate(pressure * r, (r, 0, a)))
    _check(sp.simplify(direct_depth - depth) == 0, "the MDR depth is not the film's")
    _check(sp.simplify(force_direct - force_mdr) == 0, "the MDR force is not the film's")
    add(Relation("layer_thin_film_depth", "(16)", "thin incompressible layer: paraboloid's depth d = a²/(4R)", d, depth,
                 (a, R)))
    add(Relation("layer_thin_film_force", "(10)", "thin incompressible layer: paraboloid's force πG a⁶/(32R h³)", F_N,
                 force_mdr, (a, R, G, h)))


def _derive_griffith(add) -> None:
    """Section 5: the energy of the contact of radius ``a`` at depth ``d`` is the non-adhesive one at ``g(a)`` plus a
    flat punch of radius ``a`` moved by ``δ = d − g(a)``: ``U = U₀(a) + F₀(a) δ + ½K(a) δ²`` with
    ``U₀' = F₀ g'``, ``F₀' = K g'`` (the incremental punches)."""
    U0 = sp.Function("U_0")
    delta = d - g_fn(a)
    energy = U0(a) + F0_fn(a) * delta + K_fn(a) * delta**2 / 2
    slope = sp.diff(energy, a).subs({sp.Derivative(U0(a), a): F0_fn(a) * sp.diff(g_fn(a), a),
                                     sp.Derivative(F0_fn(a), a): K_fn(a) * sp.diff(g_fn(a), a)})
    slope = sp.factor(sp.expand(slope))
    _check(sp.simplify(slope - sp.diff(K_fn(a), a) * delta**2 / 2) == 0, "∂U/∂a is not ½K'δ²")
    add(Relation("layer_energy_slope", "(8)", "∂U/∂a at fixed depth: ½ K'(a) (d − g(a))²", sp.Symbol("dU_da"), slope))
    K_prime = sp.Symbol("K_prime", positive=True)
    released = sp.Eq(slope.subs(sp.Derivative(K_fn(a), a), K_prime), 2 * sp.pi * a * dgamma)  # Griffith
    roots = sp.solve(released.subs(d, g_fn(a) - dl_max), dl_max)
    hess = [root for root in roots if not sp.simplify(root).could_extract_minus_sign()]
    _check(len(hess) == 1, f"Griffith's balance gives {roots}")
    add(Relation("layer_hess_elongation", "(8)", "Heß's rule on a layer: Δl = sqrt(4π a Δγ / K'(a))", dl_max, hess[0],
                 (a, dgamma, K_prime)))
    _check(sp.simplify(hess[0].subs(K_prime, 2 * E_star) - symbolic.relation("hess_max_elongation").rhs) == 0,
           "Heß's rule on the layer is not (8) on the half-space")
    force = sp.diff(energy, d)
    add(Relation("layer_normal_force", "(10)", "F_N = ∂U/∂d = F₀(a) + K(a)(d − g(a)) = ∫ K'(x)(d − g(x)) dx", F_N, force))
    power_K, power_g = x**3, x**2  # the identity by parts, on one example
    by_parts = sp.integrate(sp.diff(power_K, x) * (d - power_g), (x, 0, a))
    _check(sp.simplify(by_parts - force.subs({F0_fn(a): sp.integrate(power_K * sp.diff(power_g, x), (x, 0, a)),
                                               K_fn(a): power_K.subs(x, a), g_fn(a): power_g.subs(x, a)})) == 0,
           "F₀ + K (d − g) is not ∫ K'(d − g)")


def _pull_off_of(stiffness: sp.Expr, profile: sp.Expr, hess: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """The radius and force of the minimum of ``F(a) = ∫₀ᵃ K'(x)(g(a) − Δl(a) − g(x)) dx`` (Heß's branch)."""
    K_prime = sp.Symbol("K_prime", positive=True)
    elongation = sp.simplify(hess.subs(K_prime, sp.diff(stiffness, a)))
    depth = profile.subs(x, a) - elongation
    force = sp.simplify(sp.integrate(sp.diff(stiffness.subs(a, x), x) * (depth - profile), (x, 0, a)))
    radii = [root for root in sp.solve(sp.diff(force, a), a) if root.is_positive]
    _check(len(radii) == 1, f"the branch force has the stationary radii {radii}")
    _check(sp.simplify(sp.diff(force, a, 2).subs(a, radii[0])).is_positive, "the stationary point is no minimum")
    return radii[0], sp.simplify(force.subs(a, radii[0]))


def _derive_thin_pull_off(add, out: dict) -> None:
    """Section 6: the paraboloid's pull-off on Winkler's foundation (``g = f = x²/(2R)``, ``K = πκa²``) and on the
    thin incompressible film (``g = x²/(4R)``, ``K = 3πGa⁴/(8h³)``), with Heß's rule of section 5."""
    hess = out["layer_hess_elongation"].rhs
    radius, force = _pull_off_of(out["layer_winkler_stiffness"].rhs, x**2 / (2 * R), hess)
    _check(sp.simplify(force + 2 * sp.pi * R * dgamma) == 0, f"Winkler's pull-off is {force}, not −2πRΔγ")
    add(Relation("layer_winkler_pull_off_radius", "(10)", "Winkler: pull-off radius a⁴ = 8R²Δγ/κ", a, radius,
                 (R, dgamma, K_W)))
    add(Relation("layer_winkler_pull_off", "(10)", "Winkler: pull-off force −2πRΔγ (any κ)", F_N, force, (R, dgamma)))
    radius, force = _pull_off_of(out["layer_thin_film_stiffness"].rhs, out["layer_thin_film_profile"].rhs, hess)
    _check(sp.simplify(force + 3 * sp.pi * R * dgamma) == 0, f"the thin film's pull-off is {force}, not −3πRΔγ")
    add(Relation("layer_thin_film_pull_off_radius", "(10)", "thin incompressible film: pull-off radius "
                 "a⁶ = 96R²Δγh³/G", a, radius, (R, dgamma, G, h)))
    add(Relation("layer_thin_film_pull_off", "(10)", "thin incompressible film: pull-off force −3πRΔγ", F_N, force,
                 (R, dgamma)))


def _derive_flat_punch(add, out: dict) -> None:
    """Section 7: the flat punch of radius ``a`` on a layer, from sections 3–5 (``g = 0``, ``F₀ = 0`` under the
    face), each checked against the half-space's flat punch (:func:`mdr_events.theory.symbolic.relation`)."""
    K_prime = sp.Symbol("K_prime", positive=True)
    K_second = sp.Symbol("K_second")
    stiffness = sp.Symbol("K", positive=True)
    force = out["layer_normal_force"].rhs.subs({F0_fn(a): 0, g_fn(a): 0}).subs(K_fn(a), stiffness)
    _check(sp.simplify(force - stiffness * d) == 0, f"the flat punch's force on a layer is {force}, not K d")
    add(Relation("layer_flat_punch_force", "(10)", "flat punch of radius a on a layer: F_N = K(a) d (g = 0, F₀ = 0)",
                 F_N, force, (stiffness, d)))
    half = symbolic.relation("flat_punch_normal_force").rhs
    _check(sp.simplify(force.subs(stiffness, 2 * E_star * a) - half) == 0, "K d is not the half-space's 2E* a d")
    winkler = sp.simplify(force.subs(stiffness, out["layer_winkler_stiffness"].rhs))
    add(Relation("layer_flat_punch_winkler_force", "(10)", "flat punch on Winkler's foundation: F_N = π κ a² d", F_N,
                 winkler, (d, a, K_W)))
    hess = out["layer_hess_elongation"].rhs
    depth = -hess  # (the face's edge at Heß's limit: g(a) = 0)
    add(Relation("layer_flat_punch_hess", "(8)", "flat punch on a layer: its edge lets go at d = −sqrt(4π a Δγ/K'(a))",
                 d, depth, (a, dgamma, K_prime)))
    _check(sp.simplify(depth.subs(K_prime, 2 * E_star) - symbolic.relation("flat_punch_pull_off_depth").rhs) == 0,
           "the layer's flat punch does not come off at the half-space's depth at K' = 2E*")
    # d(a/K'(a))/da = (K' − a K'')/K'²: Δl falls with the radius where a K'' > K' (a smaller contact holds further out)
    elongation_slope = sp.diff(a / K_fn(a).diff(a), a)
    recedes = sp.simplify(-elongation_slope * K_fn(a).diff(a) ** 2).subs(
        {sp.Derivative(K_fn(a), (a, 2)): K_second, sp.Derivative(K_fn(a), a): K_prime})
    add(Relation("layer_flat_punch_recedes", "", "flat punch on a layer: a K'' − K' > 0 where the contact recedes under "
                 "the face (Δl falls with a)", sp.Symbol("recedes"), recedes, (a, K_prime, K_second)))
    for name, K_of, sign in (("half-space", 2 * E_star * a, -1), ("Winkler", out["layer_winkler_stiffness"].rhs, 0),
                             ("thin film", out["layer_thin_film_stiffness"].rhs, 1)):
        value = sp.simplify(recedes.subs({K_second: sp.diff(K_of, a, 2), K_prime: sp.diff(K_of, a)}))
        _check(sp.sign(value) == sign, f"the flat punch on the {name} has a K'' − K' = {value}")
    pull_off = -stiffness * hess
    add(Relation("layer_flat_punch_pull_off", "", "flat punch on a layer: pull-off force −K(a) Δl(a) under force control",
                 F_N, pull_off, (stiffness, a, dgamma, K_prime)))
    _check(sp.simplify(pull_off.subs({stiffness: 2 * E_star * a, K_prime: 2 * E_star})
                       - symbolic.relation("flat_punch_pull_off_force").rhs) == 0,
           "the layer's flat punch does not come off with Kendall's force on the half-space")
    for name, K_of in (("half-space", 2 * E_star * a), ("Winkler", out["layer_winkler_stiffness"].rhs),
                       ("thin film", out["layer_thin_film_stiffness"].rhs)):  # |F| rises with a: force control at a
        held = sp.simplify(sp.diff((pull_off ** 2).subs({stiffness: K_of, K_prime: sp.diff(K_of, a)}), a))
        _check(held.is_positive, f"the flat punch's pull-off force on the {name} does not rise with its radius")


def receding_energy() -> sp.Expr:
    r"""The energy of the flat punch's contact of radius ``a`` under the face at depth ``d`` (section 8).

    .. math:: \Pi(a; d) = \tfrac12 K(a)\, d^2 - \pi a^2 \Delta\gamma

    the springs' elastic energy (``g = 0`` under the face, ``F₀ = 0``: section 5's ``U`` with ``δ = d``) less the
    adhesion's; ``K`` is SymPy's undefined ``K(a)``. Section 8 checks from it, not asserting them, that
    ``∂Π/∂d = K(a) d``, ``∂Π/∂a = 0`` at ``|d| = Δl(a)`` (8) and ``∂²Π/∂a² = 2πΔγ (a K″ − K′)/K′`` there.

    Returns
    -------
    sympy.Expr
        ``Π`` in the symbols ``a``, ``d``, ``dgamma`` and ``K(a)``.
    """
    return K_fn(a) * d ** 2 / 2 - sp.pi * a ** 2 * dgamma


def _check_receding_energy(force, elongation) -> None:
    """Section 8's stability from the energy, not asserted: under depth control the contact of radius ``a`` at depth
    ``d`` has ``Π(a) = ½ K(a) d² − π a² Δγ`` (:func:`receding_energy`). Its ``∂Π/∂d`` is the
    springs' force ``K(a) d``; ``Π′(a) = 0`` at ``|d| = Δl(a)`` (Heß's limit, (8)); there
    ``Π″(a) = 2π Δγ (a K″ − K′)/K′``, so the receding radius is a minimum of ``Π`` (stable) where ``a K″ > K′`` and the
    recession ends where ``a K″ = K′`` (``layer_flat_punch_receding_slope`` = 0)."""
    energy = receding_energy()
    _check(sp.simplify(sp.diff(energy, d) - force) == 0, f"∂Π/∂d = {sp.diff(energy, d)} is not the springs' {force}")
    for depth in (elongation, -elongation):
        _check(sp.simplify(sp.diff(energy, a).subs(d, depth)) == 0, f"Π'(a) is not 0 at d = {depth}")
        curvature = sp.diff(energy, a, 2).subs(d, depth)
        expected = 2 * sp.pi * dgamma * (a * K_fn(a).diff(a, 2) - K_fn(a).diff(a)) / K_fn(a).diff(a)
        _check(sp.simplify(curvature - expected) == 0, f"Π''(a) at |d| = Δl is {curvature}, not {expected}")


def _derive_receding_punch(add, out: dict) -> None:
    """Section 8: the flat punch's receding branch under depth control, from sections 5 and 7.

    The springs under the face all rest on ``g = 0``; once the edge's spring at ``a`` reaches Heß's limit
    (``d = −Δl(a)``) it lets go, and the next spring inside holds if its own limit is larger (``dΔl/da < 0``). The force
    is the springs' sum, those let go storing none: ``∫₀ᵃ K'(x)(d − 0) dx``, derived here, not assumed."""
    K_prime = sp.Symbol("K_prime", positive=True)
    K_second = sp.Symbol("K_second")
    stiffness = sp.Symbol("K", positive=True)
    hess = out["layer_hess_elongation"].rhs
    elongation = hess.subs(K_prime, K_fn(a).diff(a))  # Δl(a) of any K
    slope = sp.diff(-elongation, a)  # dd/da on the receding branch d = −Δl(a)
    # dd/da = Δl (a K'' − K')/(2 a K'): its sign is that of a K'' − K' (section 7's ``recedes``)
    ratio = sp.simplify(slope * 2 * a * K_fn(a).diff(a) / elongation
                        - (a * K_fn(a).diff(a, 2) - K_fn(a).diff(a)))
    _check(ratio == 0, f"dd/da on the receding branch is not Δl (a K'' − K')/(2 a K'): {ratio}")
    slope_symbols = {sp.Derivative(K_fn(a), (a, 2)): K_second, sp.Derivative(K_fn(a), a): K_prime}
    add(Relation("layer_flat_punch_receding_slope", "(8)", "flat punch on a layer: dd/da = Δl (a K'' − K')/(2 a K') on "
                 "the receding branch d = −Δl(a) (stable where > 0, pull-off where 0)", sp.Symbol("slope"),
                 sp.simplify(slope.subs(slope_symbols)), (a, dgamma, K_prime, K_second)))
    # the springs' force: those in |x| < a at elongation d (g = 0 under the face), those let go bear nothing
    force = sp.integrate(K_fn(x).diff(x) * (d - 0), (x, 0, a)).subs(K_fn(0), 0)  # (K(0) = 0: no contact)
    _check(sp.simplify(force - out["layer_normal_force"].rhs.subs({F0_fn(a): 0, g_fn(a): 0})) == 0,
           f"the receding punch's springs give {force}, not F₀ + K (d − g) with g = 0 (F₀ = ∫ K g' = 0)")
    _check_receding_energy(force, elongation)
    on_branch = force.subs(d, -hess).subs(K_fn(a), stiffness)
    add(Relation("layer_flat_punch_receding_force", "(10)", "flat punch on a layer, receding: F_N = K(a) d = −K(a) Δl(a) "
                 "at d = −Δl(a) (the springs let go store no force)", F_N, on_branch, (stiffness, a, dgamma, K_prime)))
    _check(sp.simplify(on_branch - out["layer_flat_punch_pull_off"].rhs) == 0,
           "the receding branch's force does not meet the held face's K(a₀) d at the switch")
    for name, K_of, sign in (("half-space", 2 * E_star * a, -1), ("Winkler", out["layer_winkler_stiffness"].rhs, 0),
                             ("thin film", out["layer_thin_film_stiffness"].rhs, 1)):
        value = sp.simplify(slope.subs(K_fn(a), K_of).doit())
        _check(sp.sign(sp.simplify(value)) == sign, f"the receding slope on the {name} is {value}")
    # the half-space: dd/da < 0 at every radius, so no contact smaller than the face holds: the face comes off at
    # Kendall's depth, today's jump (section 7); Winkler: Δl constant, every spring at one limit: the whole face at once
    winkler_dl = sp.simplify(elongation.subs(K_fn(a), out["layer_winkler_stiffness"].rhs).doit())
    _check(sp.diff(winkler_dl, a) == 0, f"Heß's limit on Winkler's foundation is {winkler_dl}, not a constant")
    film = out["layer_thin_film_stiffness"].rhs
    film_force = sp.simplify(on_branch.subs({stiffness: film, K_prime: sp.diff(film, a)}))
    _check(sp.limit(film_force, a, 0) == 0 and sp.limit(elongation.subs(K_fn(a), film).doit(), a, 0) == sp.oo,
           "the thin film's receding punch does not leave with F -> 0 as d -> -oo")
