"""Heß's rule (8) with a work of adhesion that depends on the edge's speed (:func:`derive_rate_dependent_adhesion`)."""

from __future__ import annotations

import functools

import sympy as sp

from mdr_events.theory.symbolic.symbols import a, d, dgamma, E_star, F_x, G_star, LATEX_NAMES, n, R, t
from mdr_events.theory.symbolic.derived_relation import Relation
from mdr_events.theory.symbolic.cache import cached_relations
from mdr_events.theory.symbolic.paper import _single_positive, AddRelation, derive

__all__ = ["derive_rate_dependent_adhesion", "RATE_ADHESION_KEYS"]


#: Keys of the relations of the rate-dependent adhesion law (:func:`derive_rate_dependent_adhesion`).
RATE_ADHESION_KEYS = ("energy_release_rate", "receding_work_of_adhesion", "advancing_work_of_adhesion",
                      "receding_edge_speed", "advancing_edge_speed", "paraboloid_release_rate",
                      "flat_punch_detachment_time", "let_go_depth", "rate_springs_record_force")

#: The edge's reference speed and its speed ``|ȧ|`` (m/s), the energy release rate ``Γ`` (J/m²), the works at rest.
v_ref = sp.Symbol("v_ref", positive=True)
edge_speed = sp.Symbol("v_a", positive=True)
release = sp.Symbol("Gamma", positive=True)
dgamma0 = sp.Symbol("dgamma0", positive=True)
dgamma1 = sp.Symbol("dgamma1", positive=True)
LATEX_NAMES.update({v_ref: r"v_{\mathrm{ref}}", edge_speed: r"|\dot a|", release: r"\Gamma",
                    dgamma0: r"\Delta\gamma_{0}", dgamma1: r"\Delta\gamma_{1}"})


@functools.cache
def derive_rate_dependent_adhesion() -> dict[str, Relation]:
    """Heß's rule (8) with a work of adhesion that depends on the edge's speed: the edge's equation of motion.

    The boundary spring of a contact of radius ``a`` at depth ``d`` is stretched by ``Δl = g(a) − d``; Heß's rule (8)
    ``Δl = sqrt(2π a Δγ / E*)`` read the other way gives the energy the edge releases, ``Γ = E* Δl² / (2π a)``. The
    edge moves where ``Γ`` leaves the band of rest ``Δγ0 <= Γ <= Δγ1``: receding (``ȧ < 0``) where ``Γ > Δγ1`` at the
    speed that makes ``Δγ1 [1 + (|ȧ|/v_ref)^n] = Γ``, advancing where ``Γ < Δγ0`` at the speed that makes
    ``Δγ0 / [1 + (ȧ/v_ref)^n] = Γ``. Derived and checked: both speeds vanish at the band's edges; for ``v_ref → ∞``
    the works are ``Δγ1`` and ``Δγ0`` (the paper's law: the radius on the branches (9)); for ``v_ref → 0`` the works
    grow without bound receding and vanish advancing, and the speeds go to 0 (the edge held). For the flat punch held at
    a constant depth ``d < 0`` beyond Kendall's pull-off, ``n = 1``, the receding edge's time to reach ``a`` from
    ``a0`` is a closed form, and its time to detach (``a → 0``) is finite.
    """
    return cached_relations("rate_dependent_adhesion", rate_dependent_adhesion_afresh)


def rate_dependent_adhesion_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_rate_dependent_adhesion` with SymPy, bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    elongation = sp.Symbol("Delta_l", positive=True)
    hess = derive()["hess_max_elongation"].rhs  # Δl = sqrt(2π a Δγ / E*) (8)
    released = _single_positive(sp.solve(sp.Eq(elongation, hess), dgamma), "energy release rate")
    add(Relation("energy_release_rate", "(8)", "energy released per area by the edge whose spring is stretched by "
                 "Delta_l: Hess's rule (8) solved for the work of adhesion", release, released, (elongation, a, E_star)))
    ratio = (edge_speed / v_ref) ** n
    works = {"receding": dgamma1 * (1 + ratio), "advancing": dgamma0 / (1 + ratio)}
    at_rest = {"receding": dgamma1, "advancing": dgamma0}
    for way, work in works.items():
        if sp.limit(work, v_ref, sp.oo) != at_rest[way]:
            raise RuntimeError(f"the {way} work does not tend to the work at rest as v_ref -> oo")
        add(Relation(f"{way}_work_of_adhesion", "(8)", f"work of adhesion of a {way} edge moving at |da/dt| = v_a",
                     dgamma, work, (edge_speed, at_rest[way], v_ref, n)))
        speed = _single_positive(sp.solve(sp.Eq(work, release), edge_speed), f"{way} edge speed")
        if sp.simplify(speed.subs(release, at_rest[way])) != 0:
            raise RuntimeError(f"the {way} edge's speed does not vanish at the work at rest")
        held = sp.limit(speed.subs(release, 2 * dgamma1 if way == "receding" else dgamma0 / 2), v_ref, 0, "+")
        if held != 0:
            raise RuntimeError(f"the {way} edge's speed does not vanish as v_ref -> 0")
        add(Relation(f"{way}_edge_speed", "(8)", f"speed |da/dt| of a {way} edge that releases Gamma "
                     f"({'Gamma > dgamma1' if way == 'receding' else 'Gamma < dgamma0'})", edge_speed, speed,
                     (release, at_rest[way], v_ref, n)))
    if sp.limit(works["receding"], v_ref, 0, "+") != sp.oo or sp.limit(works["advancing"], v_ref, 0, "+") != 0:
        raise RuntimeError("the works do not diverge receding and vanish advancing as v_ref -> 0")
    parabolic = released.subs(elongation, a**2 / R - d)  # g(a) = a²/R (4)
    add(Relation("paraboloid_release_rate", "(8)", "energy release rate of a paraboloid's edge of radius a at depth d "
                 "(edge spring stretched, a^2/R > d)", release, parabolic, (a, d, R, E_star)))
    _derive_flat_punch_detachment(add, released, elongation)
    _derive_let_go(add, released, elongation)
    _derive_rate_springs_force(add)
    return out


def _derive_let_go(add: AddRelation, released: sp.Expr, elongation: sp.Symbol) -> None:
    """Where a receding edge lets go: the release rate ``Γ(a, d) = E* (g(a) − d)² / (2π a)`` at a fixed depth stops
    falling as the radius shrinks, ``∂Γ/∂a = 0`` (Griffith's stability of the edge: beyond it ``Γ`` rises as the edge
    recedes, and with it the speed, so the edge runs to 0 whatever the path does next). Solved for the depth with
    ``g`` and ``g'`` as symbols; on the paraboloid it is the jump-off of the branch (9) of any work, the paper's
    displacement-controlled pull-off (the limit ``v_ref → ∞``)."""
    profile, slope = sp.Symbol("g_a", real=True), sp.Symbol("g_slope", real=True)
    shape = sp.Function("g")
    rate = released.subs(elongation, shape(a) - d)
    roots = [root for root in sp.solve(sp.diff(rate, a), d) if sp.simplify(root - shape(a)) != 0]
    if len(roots) != 1:
        raise RuntimeError(f"the let-go depth is not one root of dGamma/da = 0: {roots}")
    depth = roots[0].subs(sp.Derivative(shape(a), a), slope).subs(shape(a), profile)
    paraboloid = depth.subs({profile: a**2 / R, slope: 2 * a / R})
    model = derive()
    off = model["jump_off_radius"].rhs
    if sp.simplify(paraboloid.subs(a, off) - model["jump_off_depth"].rhs) != 0:
        raise RuntimeError("the let-go depth of the paraboloid is not the jump-off of the branch (9)")
    add(Relation("let_go_depth", "(8)", "depth below which the edge of radius a lets go: dGamma/da = 0 at a fixed "
                 "depth, with g_a = g(a) and g_slope = g'(a) (on the paraboloid the jump-off of the branch (9))",
                 d, sp.expand(depth), (profile, slope, a)))


def _derive_rate_springs_force(add: AddRelation) -> None:
    """The tangential force of springs under one cap ``ū = K a`` whose anchors have only been pushed up (the play
    operator's lower level, its running maximum ``M``), attached at the times ``τ`` of an advancing edge with the
    anchors ``X(τ)`` (the path's ``x`` then, non-decreasing): ``2 G* ∫_0^a (x − max(X, M)) dξ`` over a record of
    springs ``[a(τ_lo), a(τ_hi)]``, cut at ``τ*`` where ``X = M``, by parts in ``τ``: the sliding ones carry
    ``M``, the sticking ones ``X a|_{τ*}^{τ_hi} − ∫ Ẋ a dτ``."""
    level, x_now = sp.Symbol("M", real=True), sp.Symbol("x", real=True)
    lo, star, hi = sp.symbols("a_lo a_star a_hi", positive=True)
    anchor_star, anchor_hi, swept = sp.symbols("X_star X_hi I_Xa", real=True)
    clock, start, end = sp.symbols("tau tau_star tau_hi", real=True)
    anchor, radius = sp.Function("X")(clock), sp.Function("A")(clock)
    by_parts = (anchor * radius).subs(clock, end) - (anchor * radius).subs(clock, start) \
        - sp.Integral(sp.diff(anchor, clock) * radius, (clock, start, end))
    if sp.simplify(sp.diff(by_parts, end) - (anchor * sp.diff(radius, clock)).subs(clock, end)) != 0:
        raise RuntimeError("the anchors' integral by parts does not differentiate back to X(tau) a'(tau)")
    held = level * (star - lo) + anchor_hi * hi - anchor_star * star - swept
    force = 2 * G_star * (x_now * (hi - lo) - held)
    add(Relation("rate_springs_record_force", "(11), (13)", "tangential force of the springs attached on [a_lo, a_hi] "
                 "at x = X(tau), those with X < M sliding at M: 2 G* int (x - max(X, M)) dxi, with I_Xa the integral "
                 "of X' a over the sticking ones' times", F_x, force,
                 (x_now, level, lo, star, hi, anchor_star, anchor_hi, swept, G_star)))


def _derive_flat_punch_detachment(add: AddRelation, released: sp.Expr, elongation: sp.Symbol) -> None:
    """The flat punch of radius ``a0`` held at ``d < 0`` with ``Γ(a0) > Δγ1`` and ``n = 1``: ``g = 0`` under the face,
    ``Γ = E* d² / (2π a)`` grows as the edge recedes, ``da/dt = −v_ref (Γ/Δγ1 − 1)``; separated and integrated."""
    depth = sp.Symbol("d_held", positive=True)  # |d|
    start, radius = sp.Symbol("a0", positive=True), sp.Symbol("a_t", positive=True)
    rate = released.subs(elongation, depth)  # Δl = g − d = |d| under the face
    speed = v_ref * (rate / dgamma1 - 1)  # n = 1
    reach = sp.solve(sp.Eq(rate, dgamma1), a)[0]  # c: the radius whose Γ is Δγ1 (a0 < c: the edge recedes)
    integral = sp.integrate(1 / speed, (a, radius, start))  # SymPy's antiderivative carries log(a − c), a < c
    # the same in logarithms of positive numbers (c − a > 0 on the way), so that it evaluates in real arithmetic
    time = ((start - radius) + reach * sp.log((reach - start) / (reach - radius))) / v_ref * -1
    checks = (sp.diff(time, radius) + 1 / speed.subs(a, radius), time.subs(radius, start),
              sp.diff(integral - time, radius))
    if any(sp.simplify(check) != 0 for check in checks):
        raise RuntimeError("the flat punch's detachment time is not the integral of the receding edge's law")
    add(Relation("flat_punch_detachment_time", "", "time for the edge of a flat punch of radius a0, held at depth "
                 "-d_held beyond Kendall's pull-off, to recede to a_t (n = 1; a_t -> 0: the detachment)", t, time,
                 (radius, start, depth, dgamma1, v_ref, E_star)))
