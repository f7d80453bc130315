"""Heß's rule for the power law ``f = c rⁿ`` and the flat punch, derived as (7)–(10), (17) are for the paraboloid
(:func:`derive_power_law`, :func:`derive_power_law_model`)."""

from __future__ import annotations

import functools

import sympy as sp

from mdr_events.theory.symbolic.symbols import (
    a, c, d, dgamma, E_star, f, F_N, g, G_star, n, r, tan_alpha, tau0, theta, x,
)
from mdr_events.theory.symbolic.derived_relation import Relation
from mdr_events.theory.symbolic.cache import _cached, cached_relations
from mdr_events.theory.symbolic.paper import _single_positive, abel_transform, AddRelation, derive

__all__ = ["derive_power_law", "derive_power_law_model", "POWER_LAW_KEYS"]


@functools.cache
def derive_power_law() -> Relation:
    """The MDR profile of ``f = c r^n`` for general ``n`` (eq. (3)).

    Kept apart from :func:`derive` because SymPy needs several seconds for
    the general Beta-type integral; the paraboloid (4) and the cone are its
    cases ``n = 2, c = 1/(2R)`` and ``n = 1, c = tan θ`` (the tests check it).
    """
    return _cached("power_law", lambda: [power_law_afresh()])[0]


def power_law_afresh() -> Relation:
    """The derivation of :func:`derive_power_law` with SymPy (about 6 s), bypassing any cache."""
    return Relation("profile_power_law", "(3)", "MDR profile of f = c r^n", g(x),
                    abel_transform(c * r**n), (x, c, n))


#: Keys of the power-law relations (:func:`derive_power_law_model`), beside ``profile_power_law``.
POWER_LAW_KEYS = ("power_law_depth", "power_law_depth_slope", "power_law_depth_integral", "power_law_normal_force",
                  "power_law_branch_normal_force", "power_law_hertz_radius", "power_law_jump_in_radius",
                  "power_law_pull_off_radius", "power_law_pull_off_force", "power_law_jump_off_radius",
                  "power_law_jump_off_depth", "power_law_jump_off_force", "power_law_d_crit_A_hertz",
                  "flat_punch_normal_force", "flat_punch_pull_off_depth", "flat_punch_pull_off_force",
                  "flat_punch_d_crit_A", "abel_transform_angular")


@functools.cache
def derive_power_law_model() -> dict[str, Relation]:
    """Heß's rule for the power law ``f = c rⁿ`` and for the flat punch, derived as (7)–(10), (17) are for
    the paraboloid (their cases ``n = 2, c = 1/(2R)``; the tests check it).

    The depth of the adhesive contact of radius ``a`` is ``d = κ c aⁿ − sqrt(2π a Δγ / E*)`` (generalised
    (9)); the pull-off radius under force control ``a^(2n−1) = 9 Δγ / (2 E* n² κ² c²)``, ``κ = √π Γ(n/2 + 1) /
    Γ(n/2 + 1/2)`` (Heß, in Popov & Heß, *Method of Dimensionality Reduction in Contact Mechanics and
    Friction*, Springer 2015, ch. 6; Borodich, Galanov & Suarez-Alvarez, J. Mech. Phys. Solids 68 (2014) 14,
    for the JKR-type problem of power-law punches). The radius at a given depth has no closed form for
    general ``n`` (nor has the slip onset with adhesion, (18)): the analytic layer solves for it.
    """
    return cached_relations("power_law_model", power_law_model_afresh)


def power_law_model_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_power_law_model` with SymPy (about 8 s), bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> Relation:
        out[rel.key] = rel
        return rel

    profile = derive_power_law().rhs  # g(x) = κ c xⁿ
    _derive_angular_abel_transform(add, profile)
    hess, hertz_radius = _derive_power_law_branch(add, profile)
    # (17) for the power law: on the path (14) x = d / tan α slip starts when x reaches ū(a) = K a, a = a(d);
    # d^((n−1)/n) ∝ tan α: a closed form for n ≠ 1. The cone (n = 1) slides from first contact or never.
    critical_shift = derive()["critical_shift"].rhs  # (13)
    onset = sp.Eq(d / tan_alpha, critical_shift.subs(a, hertz_radius))
    add(Relation("power_law_d_crit_A_hertz", "(17)", "slip-onset depth, scenario A, non-adhesive power law "
                 "(n != 1)", d, _single_positive(sp.solve(onset, d), "power-law (17)"), (tan_alpha, c, n, tau0, G_star)))
    _derive_flat_punch(add, hess, critical_shift)
    return out


def _derive_angular_abel_transform(add: AddRelation, profile: sp.Expr) -> None:
    """(3) with ``r = x sin θ``: ``g(x) = x ∫_0^{π/2} f'(x sin θ) dθ``, no singularity at ``r = x`` (the tabulated
    profile's quadrature); checked against ``profile``, the power law's ``g(x)``, on whole exponents (SymPy
    integrates ``sinⁿ⁻¹ θ`` for those, not for a symbol ``n``)."""
    angular = x * sp.Integral(sp.Subs(sp.Derivative(f(r), r), r, x * sp.sin(theta)), (theta, 0, sp.pi / 2))
    for exponent in (1, 2, 3, 4):
        power = c * r**exponent
        on_power_law = x * sp.integrate(sp.diff(power, r).subs(r, x * sp.sin(theta)), (theta, 0, sp.pi / 2))
        if sp.simplify(on_power_law - profile.subs(n, exponent)) != 0:
            raise RuntimeError(f"the angular form of the Abel transform does not give g(x) of c r^{exponent}")
    add(Relation("abel_transform_angular", "(3)", "Abel transform with r = x sin(theta): no singular integrand",
                 g(x), angular))


def _derive_power_law_branch(add: AddRelation, profile: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(7)–(10) for the power law of MDR profile ``profile``: the adhesive branch, its forces, its jump-in,
    pull-off and jump-off; returns Heß's limit (8) and the non-adhesive radius ``a(d)``."""
    displacement = d - profile  # (7)
    hess = sp.sqrt(2 * sp.pi * a * dgamma / E_star)  # (8)
    depth_of_radius = sp.solve(sp.Eq(-displacement.subs(x, a), hess), d)[0]
    arguments = (a, c, n, E_star, dgamma)
    add(Relation("power_law_depth", "(9)", "indentation depth of the adhesive power-law contact of radius a",
                 d, depth_of_radius, arguments))
    add(Relation("power_law_depth_slope", "(9)", "slope dd/da of the adhesive power-law branch",
                 sp.Derivative(d, a), sp.diff(depth_of_radius, a), arguments))
    add(Relation("power_law_depth_integral", "(9)", "integral of the power-law branch over the radius",
                 sp.Integral(d, (a, 0, a)), sp.simplify(sp.integrate(depth_of_radius.subs(a, x), (x, 0, a))),
                 arguments))
    force_pinned = sp.expand(2 * E_star * sp.integrate(displacement, (x, 0, a)))  # (10)
    add(Relation("power_law_normal_force", "(10)", "normal force of the springs in contact under a power law, "
                 "any d and a", F_N, force_pinned, (d, a, c, n, E_star)))
    force_branch = sp.simplify(sp.expand(force_pinned.subs(d, depth_of_radius)))
    add(Relation("power_law_branch_normal_force", "(10)", "normal force of the adhesive power-law contact of "
                 "radius a", F_N, force_branch, arguments))
    hertz_radius = _single_positive(sp.solve(sp.Eq(d, depth_of_radius.subs(dgamma, 0)), a), "power-law radius")
    add(Relation("power_law_hertz_radius", "(16)", "non-adhesive contact radius of the power law",
                 a, hertz_radius, (d, c, n)))
    _derive_power_law_branch_points(add, depth_of_radius, force_branch)
    return hess, hertz_radius


def _derive_power_law_branch_points(add: AddRelation, depth_of_radius: sp.Expr, force_branch: sp.Expr) -> None:
    """The power law's jump-in, pull-off (force control) and jump-off (displacement control) on its branch."""
    fixed = (c, n, E_star, dgamma)
    add(Relation("power_law_jump_in_radius", "", "contact radius at zero depth (jump-in), power law",
                 a, _single_positive(sp.solve(sp.Eq(depth_of_radius, 0), a), "power-law jump-in"), fixed))
    a_force_control = _single_positive(sp.solve(sp.diff(force_branch, a), a), "power-law pull-off radius")
    add(Relation("power_law_pull_off_radius", "", "radius of minimal force dF_N/da = 0 (force control), power law",
                 a, a_force_control, fixed))
    add(Relation("power_law_pull_off_force", "", "pull-off force under force control, power law",
                 F_N, sp.simplify(force_branch.subs(a, a_force_control)), fixed))
    a_jump_off = _single_positive(sp.solve(sp.diff(depth_of_radius, a), a), "power-law jump-off radius")
    add(Relation("power_law_jump_off_radius", "", "radius where dd/da = 0: jump-off under displacement control, "
                 "power law", a, a_jump_off, fixed))
    add(Relation("power_law_jump_off_depth", "", "depth at the jump-off under displacement control, power law",
                 d, sp.simplify(depth_of_radius.subs(a, a_jump_off)), fixed))
    add(Relation("power_law_jump_off_force", "", "normal force at the jump-off under displacement control, "
                 "power law", F_N, sp.simplify(force_branch.subs(a, a_jump_off)), fixed))


def _derive_flat_punch(add: AddRelation, hess: sp.Expr, critical_shift: sp.Expr) -> None:
    """The flat punch of radius ``a``: ``g = 0`` under it, every spring compressed by ``d``; its force, Kendall's
    pull-off (Heß's limit ``hess`` at every spring at once) and scenario A's onset (``critical_shift`` (13))."""
    punch_force = 2 * E_star * sp.integrate(d, (x, 0, a))
    add(Relation("flat_punch_normal_force", "(10)", "normal force of a flat punch of radius a at depth d",
                 F_N, punch_force, (d, a, E_star)))
    pull_off_depth = sp.solve(sp.Eq(-d, hess), d)[0]  # the edge spring (as every spring) at Heß's limit (8)
    add(Relation("flat_punch_pull_off_depth", "", "depth at which the flat punch comes off (all springs at once)",
                 d, pull_off_depth, (a, E_star, dgamma)))
    add(Relation("flat_punch_pull_off_force", "", "pull-off force of the flat punch (Kendall 1971)",
                 F_N, sp.simplify(punch_force.subs(d, pull_off_depth)), (a, E_star, dgamma)))
    # every spring attaches at first contact at one x: all reach ū together (onset is full slip)
    add(Relation("flat_punch_d_crit_A", "(17)", "slip-onset (and full-slip) depth, scenario A, flat punch",
                 d, sp.solve(sp.Eq(d / tan_alpha, critical_shift), d)[0], (a, tan_alpha, tau0, G_star)))
