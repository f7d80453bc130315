"""Coulomb's law of the springs in an adhesive contact (:func:`derive_adhesive_friction_model`)."""

from __future__ import annotations

import functools

import sympy as sp

from mdr_events.theory.symbolic.symbols import (
    a, c, d, d_max, dgamma, E_star, F_N, F_x, G_star, mu, n, tau0, u_bar, u_x, u_z, W, X, x,
)
from mdr_events.theory.symbolic.derived_relation import Relation
from mdr_events.theory.symbolic.cache import cached_relations
from mdr_events.theory.symbolic.paper import _single_positive, AddRelation, derive
from mdr_events.theory.symbolic.power_law import derive_power_law, derive_power_law_model
from mdr_events.theory.symbolic.friction import derive_friction_model

__all__ = ["derive_adhesive_friction_model", "ADHESIVE_FRICTION_KEYS"]


#: Keys of the relations of Coulomb's law with adhesion (:func:`derive_adhesive_friction_model`).
ADHESIVE_FRICTION_KEYS = ("compression_boundary", "compression_boundary_rate", "adhesive_friction_cap",
                          "adhesive_virgin_force", "adhesive_full_slip_shift", "adhesive_full_slip_force",
                          "compressed_normal_force", "flat_punch_friction_cap", "flat_punch_full_slip_force",
                          "flat_punch_loop_energy", "adhesive_seen_piece_turn", "adhesive_compressed_level",
                          "adhesive_tensile_level", "adhesive_crossing_anchor", "adhesive_onset_excess_A",
                          "adhesive_onset_turn_A", "adhesive_onset_excess_B")


@functools.cache
def derive_adhesive_friction_model() -> dict[str, Relation]:
    """Coulomb's law of the springs in an adhesive contact (Heß's rule (8)–(9) with the caps of
    :func:`derive_friction_model`).

    A spring at ``ξ`` is compressed where ``d > g(ξ)``, in tension (the adhesive annulus) where ``d < g(ξ) <= g(a)``;
    its cap is ``ū(ξ) = K a + κ max(d − g(ξ), 0)``. The boundary ``x_c`` (``g(x_c) = d``) is the non-adhesive radius
    (16) of the depth, whatever the adhesive radius ``a >= x_c`` does: it moves with the depth alone,
    ``dx_c/dd = 1/g'(x_c)``. The cap is continuous there (``K a`` on both sides), so a spring crossing ``x_c`` keeps
    its shift. Under ``"coulomb"`` alone (``K = 0``) every spring in tension slides with zero shift (it follows the
    indenter) and enters compression at ``x_c`` with none, as a spring attaching to a contact without adhesion does:
    the compressed zone is the non-adhesive contact of the same depth history. At a constant depth, from rest,
    the derivation sums the springs (stick, compressed at the cap, tensile at ``K a``) and checks that
    ``F_x = τ0 π a² + μ (F_N^H(d) − F_N^H(d − (u_x − K a)/κ))`` for ``u_x >= K a``: the Coulomb part is
    Cattaneo–Mindlin's of the compressed zone, free of ``Δγ`` and of ``a``; full slip is ``τ0 π a² + μ F_N^H(d)``,
    ``F_N^H(d) = F_N(d, a) + 2E* ∫_{x_c}^a (g − d) dξ`` the compressed springs' push alone.
    """
    return cached_relations("adhesive_friction_model", adhesive_friction_model_afresh)


def adhesive_friction_model_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_adhesive_friction_model` with SymPy, bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    profile = derive_power_law().rhs  # g(ξ) = κ_n c ξⁿ
    model = derive_power_law_model()
    hertz_radius = model["power_law_hertz_radius"].rhs
    boundary = _single_positive(sp.solve(sp.Eq(profile, d), x), "compression boundary")
    if not _vanishes(boundary - hertz_radius):
        raise RuntimeError("the compression boundary g(x_c) = d is not the non-adhesive radius (16)")
    add(Relation("compression_boundary", "(7)", "boundary x_c between compressed and tensile springs, g(x_c) = d: the "
                 "non-adhesive radius of the depth", x, boundary, (d, c, n)))
    rate = sp.simplify(sp.diff(boundary, d))
    if not _vanishes(rate * sp.diff(profile, x).subs(x, boundary) - 1):
        raise RuntimeError("dx_c/dd is not 1/g'(x_c)")
    add(Relation("compression_boundary_rate", "(7)", "dx_c/dd: the boundary moves with the depth alone", 
                 sp.Derivative(x, d), rate, (d, c, n)))
    kappa = derive_friction_model()["coulomb_critical_shift"].rhs.subs(u_z, 1)  # κ = μ E*/G*
    tau0_cap = derive()["critical_shift"].rhs  # K a (13)
    cap = tau0_cap + kappa * sp.Max(d - profile, 0)
    if not (_vanishes(cap.subs(x, boundary) - tau0_cap) and _vanishes(cap.subs(x, 0) - tau0_cap - kappa * d)):
        raise RuntimeError("the cap is not K a at the compression boundary and K a + κ d at the centre")
    add(Relation("adhesive_friction_cap", "(13)", "the cap of the spring at x: K a + mu (E*/G*) max(d - g(x), 0)",
                 u_bar, cap, (x, d, a, tau0, mu, c, n, E_star, G_star)))
    _derive_adhesive_virgin_curve(add, profile, boundary, kappa, tau0_cap, model)
    _derive_flat_punch_friction(add, cap, kappa, tau0_cap)
    _derive_seen_piece_turn(add, profile, model)
    _derive_crossing_anchor(add, cap, profile, boundary, kappa, tau0_cap)
    _derive_adhesive_onset_A(add, profile, model, kappa, tau0_cap)
    _derive_adhesive_onset_B(add, cap, profile, model, tau0_cap)
    return out


def _derive_adhesive_onset_B(add: AddRelation, cap: sp.Expr, profile: sp.Expr, model: dict[str, Relation],
                             tau0_cap: sp.Expr) -> None:
    """Scenario B's pull-off at angle with both parts of the cap and adhesion, before any spring slides.

    After the vertical stroke every spring in contact is anchored at ``x = 0``: going out along
    ``x = (d_max − d) cot α`` all hold the same shift. On any adhesive branch (9) ``d = g(a) − Δl(a)`` with ``Δl >= 0``,
    so the edge is in tension (``d <= g(a)``) and its cap is ``K a``, the least of all (the caps rise inwards): the
    first spring to slide is the edge's, where ``(d_max − d) cot α = K a`` — (21) of ``τ0`` alone on the same branch,
    free of ``μ``. (The indentation branch, further in, is scenario A's springs about the contact of ``d_max``, the
    excess and turn of :func:`_derive_adhesive_onset_A`.)"""
    cot = sp.Symbol("cot_alpha", positive=True)
    branch = model["power_law_depth"].rhs  # d on the branch of the work dgamma at the radius a
    edge_cap = cap.subs(x, a).subs(d, branch)
    if not _vanishes(sp.simplify(edge_cap - tau0_cap)):
        raise RuntimeError("the edge of an adhesive contact is not in tension: its cap is not K a")
    excess = (d_max - d) * cot - edge_cap
    add(Relation("adhesive_onset_excess_B", "(21)", "shift over cap of the edge spring on scenario B's pull-off at "
                 "angle (every spring anchored at x = 0; the edge in tension, its cap K a): (d_max - d) cot - K a", X,
                 sp.simplify(excess), (d, d_max, a, cot, tau0, G_star)))


def _derive_adhesive_onset_A(add: AddRelation, profile: sp.Expr, model: dict[str, Relation], kappa: sp.Expr,
                             tau0_cap: sp.Expr) -> None:
    """Scenario A's springs with both parts of the cap and adhesion, before any slides.

    Along ``x = d cot α`` from the first contact at ``d = 0`` (the springs under the jump-in radius ``a_J`` attach
    there, ``d_ξ = 0``; the others at their depth on the ``Δγ0`` branch, ``d_ξ = d0(ξ)``) a spring holds the shift
    ``(d − d_ξ) cot α`` against its cap ``K a + κ max(d − g(ξ), 0)``. The excess of shift over cap is largest at
    ``a_J`` among the jump-in springs (their caps fall outwards), decreases outwards in the tensile annulus
    (``d0`` rises), and in the compressed grown springs has ``∂/∂ξ = cot α Δl0'(ξ) − (cot α − κ) g'(ξ)``: increasing
    where ``cot α <= κ``, else with one maximum, at ``ξ*`` (``adhesive_onset_turn_A``, free of ``d``). The onset is the
    least depth where the largest excess, over ``a_J``, ``x_c`` and ``ξ*`` where they lie in the contact, reaches 0."""
    cot = sp.Symbol("cot_alpha", positive=True)
    grown = model["power_law_depth"].rhs.subs(a, x)  # d0(ξ)
    excess = (d - grown) * cot - tau0_cap - kappa * (d - profile)
    add(Relation("adhesive_onset_excess_A", "(13)", "shift over cap of a compressed spring grown along the dgamma0 "
                 "branch in scenario A (cot alpha the path's): (d - d0(xi)) cot - K a - mu (E*/G*) (d - g(xi))", X,
                 excess, (x, d, a, cot, tau0, mu, dgamma, c, n, E_star, G_star)))
    slope = sp.diff(excess, x)
    if sp.diff(slope, d) != 0 or sp.diff(slope, a) != 0:
        raise RuntimeError("the excess's slope in xi depends on the depth or the radius")
    turns = sp.solve(sp.Eq(sp.expand(slope * sp.sqrt(x)), 0), x)
    if len(turns) != 1:
        raise RuntimeError(f"the scenario A excess has {len(turns)} turns, not one")
    add(Relation("adhesive_onset_turn_A", "(9)", "radius of the largest shift over cap of the compressed springs "
                 "grown along the dgamma0 branch in scenario A (exists where cot alpha > mu E*/G*)", x, turns[0],
                 (cot, mu, dgamma, c, n, E_star, G_star)))


def _derive_crossing_anchor(add: AddRelation, cap: sp.Expr, profile: sp.Expr, boundary: sp.Expr, kappa: sp.Expr,
                            tau0_cap: sp.Expr) -> None:
    """The levels of the two regions and the anchor a spring keeps crossing ``x_c`` at a cap.

    A spring at ``ξ`` is at the cap ``σ`` (``σ = ±1``) where ``σ (x − Y) >= ū(ξ)``, i.e. where its anchor is at or
    beyond ``x − σ ū(ξ)``. In the compressed zone (``g < d``) that bound is ``x − σ (K a + κ d) + σ κ g(ξ)``: the cap
    compares ``Y − σ κ g`` with the level ``x − σ (K a + κ d)``, one for all its springs; in the tensile annulus
    (``g > d``) the bound is the level ``x − σ K a`` itself. At ``x_c`` both are ``x − σ K a`` (the cap is continuous),
    so a spring crossing ``x_c`` at a cap keeps ``x(τ) − σ K a(τ)`` of the instant ``τ`` it crosses, ``d(τ) = g(ξ)``:
    on a path segment (``x = x_s + v_x (t − t_s)``, ``d = d_s + v_d (t − t_s)``)
    ``Y(ξ) = x_s + (v_x/v_d)(g(ξ) − d_s) − σ K a`` with ``a`` the radius at that depth (constant while pinned, on a
    branch of (9) while it moves), the anchor seen by either region at the level it had then.
    """
    sigma = sp.Symbol("sigma", real=True)
    position, x_s, d_s = sp.Symbol("x_i", real=True), sp.Symbol("x_s", real=True), sp.Symbol("d_s", real=True)
    v_x, v_d, time, t_s = (sp.Symbol(name, real=True) for name in ("v_x", "v_d", "t_cross", "t_s"))
    compressed_cap = tau0_cap + kappa * (d - profile)
    compressed_level = sp.simplify(position - sigma * compressed_cap - sigma * kappa * profile)
    if sp.diff(compressed_level, x) != 0:
        raise RuntimeError("the compressed zone's level depends on the spring")
    tensile_level = position - sigma * tau0_cap
    if not (_vanishes(cap.subs(x, boundary) - tau0_cap)
            and _vanishes(compressed_level + sigma * kappa * profile.subs(x, boundary) - tensile_level)):
        raise RuntimeError("the regions' bounds differ at x_c")
    arguments = (position, sigma, d, a, tau0, mu, E_star, G_star)
    add(Relation("adhesive_compressed_level", "(13)", "level of the cap sigma in the compressed zone, against which it "
                 "compares Y - sigma mu (E*/G*) g: x - sigma (K a + mu (E*/G*) d)", X, compressed_level, arguments))
    add(Relation("adhesive_tensile_level", "(13)", "level of the cap sigma in the tensile annulus: x - sigma K a",
                 X, tensile_level, (position, sigma, a, tau0, G_star)))
    crossing = sp.solve(sp.Eq(d_s + v_d * (time - t_s), profile), time)[0]  # d(τ) = g(ξ)
    anchor = sp.expand((x_s + v_x * (time - t_s)).subs(time, crossing) - sigma * tau0_cap)
    seen = compressed_level.subs({position: x_s + v_x * (crossing - t_s), d: profile})
    if not _vanishes(anchor - sigma * kappa * profile - seen):
        raise RuntimeError("the crossing anchor is not at the compressed level of its instant")
    add(Relation("adhesive_crossing_anchor", "(13)", "anchor a spring at xi keeps crossing x_c at the cap sigma on a "
                 "path segment: x_s + (v_x/v_d)(g(xi) - d_s) - sigma K a", X, anchor,
                 (x, x_s, d_s, v_x, v_d, sigma, a, tau0, c, n, G_star)))


def _derive_seen_piece_turn(add: AddRelation, profile: sp.Expr, model: dict[str, Relation]) -> None:
    """Where a piece of anchors laid along the ``Δγ0`` branch turns, as a cap sees it in the compressed zone.

    Springs attaching as the radius grows along the ``Δγ0`` branch ``d0(ξ)`` (9) get ``Y = x0 + r (d0(ξ) − d_ref)``
    (``r = v_x/v_d`` of the segment); once ``x_c`` passes them the cap ``±`` compares ``Z = Y − σ g(ξ)`` with its level
    (``σ = ±κ``). With adhesion ``d0 ≠ g``, so ``Z`` is no piece of the same kind and not monotone: ``dZ/dξ = 0`` where
    ``(r − σ) g'(ξ) = r sqrt(2π Δγ0/(E* ξ))/2``, one radius when ``r/(r − σ) > 0`` (none otherwise), derived here
    for the power law. (The groundwork of ``"tau0+coulomb"`` with adhesion in the continuum: the pieces split there.)
    """
    ratio, sigma = sp.Symbol("r_Y", real=True), sp.Symbol("sigma", real=True)
    attach = model["power_law_depth"].rhs.subs(a, x)
    seen = ratio * attach - sigma * profile  # Z up to the constant x0 − r d_ref
    slope = sp.simplify(sp.diff(seen, x) * sp.sqrt(x))
    roots = sp.solve(sp.Eq(slope, 0), x)
    if len(roots) != 1:
        raise RuntimeError(f"the seen piece's slope has {len(roots)} roots, not one")
    add(Relation("adhesive_seen_piece_turn", "(9)", "radius where a piece of anchors laid along the dgamma0 branch "
                 "turns as a cap sees it in the compressed zone, Y - sigma g with sigma = cap mu E*/G* (exists where "
                 "r_Y/(r_Y - sigma) > 0)", x, roots[0], (ratio, sigma, dgamma, c, n, E_star)))


def _derive_flat_punch_friction(add: AddRelation, cap: sp.Expr, kappa: sp.Expr, tau0_cap: sp.Expr) -> None:
    """The friction laws on the flat punch of radius ``a``: ``g = 0`` under the face, so every spring has the cap
    ``K a + κ max(d, 0)`` (the power law's ``cap`` at ``g = 0``; in tension at ``d < 0``, the adhesive punch held
    above the surface, ``K a`` alone) and, attached together at the first touch, one anchor history: the springs are
    one play operator ``u ← clip(u + Δx, −ū, ū)``, ``F_x = 2G* a u``, piecewise linear in time on a straight path
    segment (``ū`` linear in ``d`` on either side of ``d = 0``). Full slip is ``τ0 π a² + μ F_N^H``, ``F_N^H`` the
    punch's push ``2E* a max(d, 0)``; the loop ``−X → X → −X`` at a constant depth (``X >= ū``) is a parallelogram,
    checked against Masing's ``8 ∫_0^X F₀ − 4 X F₀(X)`` of the virgin curve ``F₀ = 2G* a min(u, ū)``."""
    punch_cap = cap.subs(x, 0)  # g(0) = 0: the cap of every spring under the face
    under_face = sp.Max(d, 0)
    if not _vanishes(punch_cap - tau0_cap - kappa * d) or sp.simplify(punch_cap.subs(d, -d_max) - tau0_cap) != 0:
        raise RuntimeError("the flat punch's cap is not K a + κ d when pressed and K a in tension")
    add(Relation("flat_punch_friction_cap", "(13)", "the cap of every spring under a flat punch of radius a: "
                 "K a + mu (E*/G*) max(d, 0)", u_bar, tau0_cap + kappa * under_face, (d, a, tau0, mu, E_star, G_star)))
    push = 2 * E_star * sp.integrate(under_face, (x, 0, a))  # the compressed springs' push, 0 in tension
    full = sp.simplify(2 * G_star * sp.integrate(tau0_cap + kappa * under_face, (x, 0, a)))
    if sp.simplify(full - sp.pi * tau0 * a**2 - mu * push) != 0:
        raise RuntimeError("the flat punch's full slip is not tau0 pi a^2 + mu 2 E* a max(d, 0)")
    add(Relation("flat_punch_full_slip_force", "", "tangential force of full slip of a flat punch of radius a: "
                 "tau0 pi a^2 + mu 2 E* a max(d, 0)", F_x, sp.pi * tau0 * a**2 + mu * push, (d, a, tau0, mu, E_star)))
    u = sp.Symbol("u", positive=True)
    virgin = 2 * G_star * a * sp.Min(u, u_bar)  # F₀ from rest: every spring sticks up to the common cap
    masing = sp.simplify(8 * sp.integrate(virgin.subs(u, x), (x, 0, X)) - 4 * X * virgin.subs(u, X))
    parallelogram = 4 * (2 * G_star * a * u_bar) * (X - u_bar)  # ± the full slip force over the sliding stroke
    excess = sp.Symbol("excess", positive=True)  # X − ū > 0: the sliding stroke
    if sp.simplify(masing.subs(X, u_bar + excess) - parallelogram.subs(X, u_bar + excess)) != 0:
        raise RuntimeError("the flat punch's Masing loop is not the parallelogram 8 G* a u_bar (X - u_bar)")
    add(Relation("flat_punch_loop_energy", "", "energy dissipated per cycle -X -> X -> -X of a flat punch of radius a "
                 "at a constant depth whose cap is u_bar, X >= u_bar", W, sp.expand(parallelogram), (X, a, u_bar, G_star)))


def _vanishes(expr: sp.Expr) -> bool:
    """Whether ``expr`` is identically 0 where the springs are compressed (``d > 0``: powers of ``d`` combine)."""
    depth = sp.Symbol("d_positive", positive=True)
    expr = sp.expand_power_base(sp.expand(expr.subs(d, depth)), force=True)
    return sp.simplify(sp.powsimp(expr, force=True)) == 0


def _derive_adhesive_virgin_curve(add: AddRelation, profile: sp.Expr, boundary: sp.Expr, kappa: sp.Expr,
                                  tau0_cap: sp.Expr, model: dict[str, Relation]) -> None:
    """The virgin curve at a constant depth ``d`` of a contact of radius ``a >= x_c`` from rest, summed over the
    springs: those sticking (``ξ < c'``, shift ``u_x``), the compressed ones at their caps (``c' < ξ < x_c``) and the
    tensile ones at ``K a`` (``x_c < ξ < a``); checked against Cattaneo–Mindlin's form of the compressed zone."""
    pinned_force = model["power_law_normal_force"].rhs  # F_N(d, a) (10), any a
    hertz_force = pinned_force.subs(a, boundary)  # F_N^H(d): the springs under x_c
    lowered = d - (u_x - tau0_cap) / kappa  # the compressed springs with K a + κ (d − g) > u_x stick
    stick = boundary.subs(d, lowered)
    springs = 2 * G_star * (u_x * stick + sp.integrate(tau0_cap + kappa * (d - profile), (x, stick, boundary))
                            + tau0_cap * (a - boundary))
    closed = sp.pi * tau0 * a**2 + mu * (hertz_force - hertz_force.subs(d, lowered))
    if not _vanishes(springs - closed):
        raise RuntimeError("the adhesive virgin curve of the springs is not tau0 pi a^2 + mu (F_H(d) - F_H(d'))")
    if sp.simplify(2 * G_star * tau0_cap * a - sp.pi * tau0 * a**2) != 0:
        raise RuntimeError("the tau0 part of full slip is not tau0 pi a^2")
    arguments = (u_x, d, a, tau0, mu, c, n, E_star, G_star)
    add(Relation("adhesive_virgin_force", "", "tangential force of an adhesive power-law contact of radius a at depth "
                 "d shifted by u_x from rest, K a <= u_x <= K a + mu (E*/G*) d (the Coulomb part is Cattaneo-Mindlin's "
                 "of the compressed zone, free of dgamma)", F_x, closed, arguments))
    add(Relation("adhesive_full_slip_shift", "", "shift from rest at which every spring of an adhesive contact slides: "
                 "the centre's cap K a + mu (E*/G*) d", u_x, sp.solve(sp.Eq(lowered, 0), u_x)[0],
                 (d, a, tau0, mu, E_star, G_star)))
    tension = 2 * E_star * sp.integrate(profile - d, (x, boundary, a))  # the tensile springs' pull
    if not _vanishes(pinned_force + tension - hertz_force):
        raise RuntimeError("F_N(d, a) plus the tensile springs' pull is not the compressed springs' push")
    add(Relation("compressed_normal_force", "(10)", "normal force of the compressed springs alone, F_N(d, a) + "
                 "2 E* int_{x_c}^a (g - d): the non-adhesive force of the depth", F_N, hertz_force, (d, c, n, E_star)))
    add(Relation("adhesive_full_slip_force", "", "tangential force of full slip of an adhesive contact: "
                 "tau0 pi a^2 + mu F_N^H(d)", F_x, sp.pi * tau0 * a**2 + mu * hertz_force, (d, a, tau0, mu, c, n, E_star)))
    if not _vanishes(closed.subs(u_x, tau0_cap + kappa * d) - sp.pi * tau0 * a**2 - mu * hertz_force):
        raise RuntimeError("the virgin curve at the centre's cap is not the force of full slip")
