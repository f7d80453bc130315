"""The paraboloid's model of section 4, eqs. (3)–(21), derived in the paper's order (:func:`derive`)."""

from __future__ import annotations

import functools
from typing import Callable

import sympy as sp

from mdr_events.theory.symbolic.symbols import (
    a, alpha, d, d_max, dgamma, dl_max, dx, E_star, f, F_N, g, G_star, k, n_springs, R, r, s, t, tan_alpha, tau0,
    theta, u_bar, u_z, W, X, x,
)
from mdr_events.theory.symbolic.derived_relation import Relation
from mdr_events.theory.symbolic.cache import cached_relations

__all__ = ["abel_transform", "derive", "derive_afresh"]


# the Abel transform (3)
def abel_transform(profile: sp.Expr, radial: sp.Symbol = r, coordinate: sp.Symbol = x) -> sp.Expr:
    r"""MDR equivalent profile of an axisymmetric profile ``f(r)``, eq. (3).

    .. math:: g(x) = |x| \int_0^{|x|} \frac{f'(r)}{\sqrt{x^2 - r^2}}\, \mathrm{d}r \qquad (3)

    (for ``x > 0``), evaluated with the substitution ``r = x t`` so that SymPy meets a
    Beta-type integral for power laws.

    Parameters
    ----------
    profile : sympy.Expr
        ``f(r)``, an expression in ``radial``.
    radial : sympy.Symbol, optional
        The radius ``r`` of ``profile`` (default the module's ``r``).
    coordinate : sympy.Symbol, optional
        The springs' coordinate ``x`` of the result (default the module's ``x``).

    Returns
    -------
    sympy.Expr
        ``g(x)``, simplified.
    """
    integrand = sp.diff(profile, radial).subs(radial, coordinate * t) / sp.sqrt(1 - t**2)
    value = coordinate * sp.integrate(integrand, (t, 0, 1))
    return sp.simplify(sp.gammasimp(sp.hyperexpand(value)))


def _single_positive(solutions: list[sp.Expr], what: str) -> sp.Expr:
    nonzero = [sol for sol in solutions if sol != 0]
    if len(nonzero) != 1:
        raise RuntimeError(f"derivation of {what}: expected one nonzero solution, got {solutions}")
    return sp.simplify(nonzero[0])


@functools.cache
def derive() -> dict[str, Relation]:
    """Derive every relation once per process (and once per cache, see :func:`cache_path`).

    Returns the relations by key in derivation order.
    """
    return cached_relations("model", derive_afresh)


#: What a derivation section is handed: it files one relation (in derivation order) and returns it.
AddRelation = Callable[[Relation], Relation]


def derive_afresh() -> dict[str, Relation]:
    """Run every derivation with SymPy (about 4 s), bypassing any cache.

    The sections run in the paper's order, each adding its relations and handing on the expressions the
    next ones build on.

    Returns
    -------
    dict of str to Relation
        The relations of the model by key, in derivation order.
    """
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> Relation:
        out[rel.key] = rel
        return rel

    g_parab = _derive_profiles(add)
    displacement, depth_of_radius = _derive_adhesive_branch(add, g_parab)
    force_pinned, force_jkr = _derive_normal_forces(add, displacement, depth_of_radius)
    hertz_radius = _derive_branch_points(add, depth_of_radius, force_pinned, force_jkr)
    critical_shift = _derive_tangential_springs(add, depth_of_radius)
    _derive_scenario_A(add, depth_of_radius, hertz_radius, critical_shift)
    _derive_scenario_B(add, depth_of_radius, hertz_radius, critical_shift)
    return out


def _derive_profiles(add: AddRelation) -> sp.Expr:
    """(3), (4): the Abel transform and the profiles of the paraboloid and the cone; returns the paraboloid's."""
    g_abel = sp.Eq(
        g(x),
        x * sp.Integral(sp.Derivative(f(r), r) / sp.sqrt(x**2 - r**2), (r, 0, x)),
    )
    add(Relation("abel_transform", "(3)", "Abel transform to the MDR profile", g_abel.lhs, g_abel.rhs))
    g_parab = abel_transform(r**2 / (2 * R))
    add(Relation("profile_paraboloid", "(4)", "MDR profile of the paraboloid f = r^2/(2R)", g(x), g_parab, (x, R)))
    g_cone = abel_transform(r * sp.tan(theta))
    add(Relation("profile_cone", "(3)", "MDR profile of the cone f = r tan(theta)", g(x), g_cone, (x, theta)))
    return g_parab


def _derive_adhesive_branch(add: AddRelation, g_parab: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(7), (8), (9): Heß's rule gives JKR; returns the springs' displacement and the branch's depth ``d(a)``."""
    displacement = d - g_parab  # (7), positive = compressed
    add(Relation("normal_displacement", "(7)", "normal spring displacement u_z = d - g(x)",
                 u_z, displacement, (d, x, R)))
    hess = sp.sqrt(2 * sp.pi * a * dgamma / E_star)  # (8)
    add(Relation("hess_max_elongation", "(8)", "Heß: maximum elongation of the boundary spring",
                 dl_max, hess, (a, dgamma, E_star)))
    # the boundary spring at x = a is stretched by exactly Δl_max: -u_z(a) = Δl_max
    depth_of_radius = sp.solve(sp.Eq(-displacement.subs(x, a), hess), d)[0]
    add(Relation("jkr_depth", "(9)", "indentation depth of the adhesive contact of radius a",
                 d, depth_of_radius, (a, R, E_star, dgamma)))

    add(Relation("jkr_depth_slope", "(9)", "slope dd/da of the adhesive branch (9)",
                 sp.Derivative(d, a), sp.diff(depth_of_radius, a), (a, R, E_star, dgamma)))
    return displacement, depth_of_radius


def _derive_normal_forces(add: AddRelation, displacement: sp.Expr, depth_of_radius: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(10): the normal force at any depth and radius and on the adhesive branch; returns both."""
    force_pinned = sp.expand(2 * E_star * sp.integrate(displacement, (x, 0, a)))
    add(Relation("normal_force", "(10)", "normal force of the springs in contact, any d and a",
                 F_N, force_pinned, (d, a, R, E_star)))
    force_jkr = sp.simplify(sp.expand(force_pinned.subs(d, depth_of_radius)))
    add(Relation("jkr_normal_force", "(10)", "normal force of the adhesive contact of radius a",
                 F_N, force_jkr, (a, R, E_star, dgamma)))
    return force_pinned, force_jkr


def _derive_branch_points(add: AddRelation, depth_of_radius: sp.Expr, force_pinned: sp.Expr,
                          force_jkr: sp.Expr) -> sp.Expr:
    """Consequences of (9), (10): Hertz's contact, the jump-in, the pull-off and the jump-off; returns Hertz's
    radius ``a(d)``."""
    hertz_radius = sp.solve(sp.Eq(d, depth_of_radius.subs(dgamma, 0)), a)[0]
    add(Relation("hertz_radius", "(16)", "non-adhesive (Hertz) contact radius", a, hertz_radius, (d, R)))
    hertz_force = sp.simplify(force_pinned.subs(a, hertz_radius))
    add(Relation("hertz_normal_force", "", "Hertz normal force", F_N, hertz_force, (d, R, E_star)))
    jump_in = _single_positive(sp.solve(sp.Eq(depth_of_radius, 0), a), "jump-in radius")
    add(Relation("jump_in_radius", "", "contact radius at zero depth (JKR jump-in)",
                 a, jump_in, (R, E_star, dgamma)))
    a_force_control = _single_positive(sp.solve(sp.diff(force_jkr, a), a), "pull-off radius")
    add(Relation("pull_off_radius", "", "radius of minimal force, dF_N/da = 0 (force control)",
                 a, a_force_control, (R, E_star, dgamma)))
    add(Relation("pull_off_force", "", "JKR pull-off force (minimum of F_N on a branch)",
                 F_N, sp.simplify(force_jkr.subs(a, a_force_control)), (R, dgamma)))
    a_jump_off = _single_positive(sp.solve(sp.diff(depth_of_radius, a), a), "jump-off radius")
    add(Relation("jump_off_radius", "", "radius where dd/da = 0: jump-off under displacement control",
                 a, a_jump_off, (R, E_star, dgamma)))
    add(Relation("jump_off_depth", "", "depth at the jump-off under displacement control",
                 d, sp.simplify(depth_of_radius.subs(a, a_jump_off)), (R, E_star, dgamma)))
    add(Relation("jump_off_force", "", "normal force at the jump-off under displacement control",
                 F_N, sp.simplify(force_jkr.subs(a, a_jump_off)), (R, dgamma)))
    return hertz_radius


def _derive_tangential_springs(add: AddRelation, depth_of_radius: sp.Expr) -> sp.Expr:
    """(11)–(13): the tangential springs' critical shift, a fixed contact's fretting loop, and the branch's
    integral over the radius (for attach maps); returns the critical shift ``ū(a)``."""
    # (11) τ = Σ G* Δx u_x / (π a²); stationary sliding: n springs all at ū, n Δx = 2a
    tau_stationary = (G_star * dx * n_springs * u_bar / (sp.pi * a**2)).subs(n_springs, 2 * a / dx)
    add(Relation("stationary_shear_stress", "(12)", "mean shear stress with every spring at ū",
                 tau0, sp.simplify(tau_stationary), (u_bar, a, G_star)))
    critical_shift = sp.solve(sp.Eq(tau0, tau_stationary), u_bar)[0]
    jkr_depth_integral = sp.integrate(depth_of_radius.subs(a, x), (x, 0, a))
    add(Relation("critical_shift", "(13)", "critical spring shift ū(a)",
                 u_bar, critical_shift, (a, tau0, G_star)))
    add(Relation("fretting_dissipated_energy", "", "energy dissipated per cycle x: −X → X → −X of a fixed "
                 "contact (X > ū): the parallelogram's area", W, _fretting_loop_work(critical_shift),
                 (a, X, tau0, G_star)))
    add(Relation("jkr_depth_integral", "(9)", "integral of the branch (9) over the radius, for attach maps",
                 sp.Integral(d, (a, 0, a)), jkr_depth_integral, (a, R, E_star, dgamma)))
    return critical_shift


def _fretting_loop_work(critical_shift: sp.Expr) -> sp.Expr:
    """The work of one fretting cycle of a fixed contact: every spring shares one anchor, clipped to
    ``[x − ū, x + ū]``; ``x: −X → X → −X`` (``X > ū``). ``F_x = 2G* a (x − Y)`` rises from ``−P`` with slope
    ``2G* a`` to the plateau ``P = 2G* a ū``, and back."""
    plateau = 2 * G_star * a * u_bar
    rising = sp.integrate(-plateau + 2 * G_star * a * (x + X), (x, -X, -X + 2 * u_bar)) \
        + sp.integrate(plateau, (x, -X + 2 * u_bar, X))
    falling = sp.integrate(-plateau, (x, -X, X - 2 * u_bar)) \
        + sp.integrate(plateau - 2 * G_star * a * (X - x), (x, X - 2 * u_bar, X))
    return sp.factor(sp.simplify((rising - falling).subs(u_bar, critical_shift)))


def _derive_scenario_A(add: AddRelation, depth_of_radius: sp.Expr, hertz_radius: sp.Expr,
                       critical_shift: sp.Expr) -> None:
    """(14), (17), (18): slip onset in scenario A, the critical angles of both scenarios, and the branch's radius
    at a given depth as a quartic."""
    # on the path (14) x = d / tan α; slip starts when x reaches ū(a)
    onset_A = sp.Eq(d / tan_alpha, critical_shift)
    d_crit_A_hertz = _single_positive(sp.solve(onset_A.subs(a, hertz_radius), d), "(17)")
    add(Relation("d_crit_A_hertz", "(17)", "slip-onset depth, scenario A, non-adhesive",
                 d, d_crit_A_hertz, (tan_alpha, R, tau0, G_star)))
    cubic = _reduce_to_polynomial(tan_alpha * critical_shift, depth_of_radius, divide_by=s)
    add(Relation("slip_A_jkr_cubic", "(18)", "scenario A with adhesion, cubic in s = sqrt(a)",
                 cubic, sp.Integer(0), (s, tan_alpha, R, tau0, G_star, E_star, dgamma), variable=s))
    add(Relation("slip_A_jkr_cardano", "(18)", "positive root of the cubic (Cardano)",
                 s, _positive_cubic_root(cubic), (tan_alpha, R, tau0, G_star, E_star, dgamma)))
    add(Relation("slip_depth_A", "(18)", "depth of slip onset from its contact radius, scenario A",
                 d, tan_alpha * critical_shift, (a, tan_alpha, tau0, G_star)))
    critical_angle = sp.atan(sp.solve(sp.Eq(d_max / tan_alpha, critical_shift), tan_alpha)[0])
    add(Relation("critical_angle_A", "", "critical angle: slip onset exactly at d_max, scenario A",
                 alpha, critical_angle, (a, d_max, tau0, G_star)))
    critical_angle_B = sp.atan(sp.solve(sp.Eq(d, d_max - tan_alpha * critical_shift), tan_alpha)[0])
    add(Relation("critical_angle_B", "(21)",
                 "angle of a pull-off path (19) from d_max that reaches slip onset at (a, d)",
                 alpha, critical_angle_B, (a, d, d_max, tau0, G_star)))
    critical_angle_B_plus = sp.atan(sp.solve(sp.Eq(d, d_max + tan_alpha * critical_shift), tan_alpha)[0])
    add(Relation("critical_angle_B_indentation", "(21)",
                 "angle of an indentation path from d_max (the + sign) that reaches slip onset at (a, d)",
                 alpha, critical_angle_B_plus, (a, d, d_max, tau0, G_star)))
    depth_quartic = _reduce_to_polynomial(d, depth_of_radius)
    add(Relation("jkr_radius_quartic", "(9)", "contact radius at a given depth, quartic in s = sqrt(a)",
                 depth_quartic, sp.Integer(0), (s, d, R, E_star, dgamma), variable=s))


def _derive_scenario_B(add: AddRelation, depth_of_radius: sp.Expr, hertz_radius: sp.Expr,
                       critical_shift: sp.Expr) -> None:
    """(19), (20), (21): slip onset in scenario B, out of ``d_max`` (pull-off) and further in (indentation)."""
    onset_B = sp.Eq((d_max - d) / tan_alpha, critical_shift.subs(a, hertz_radius))
    kk = sp.pi * tau0 * sp.sqrt(R) * tan_alpha / (2 * G_star)
    squared = sp.expand((onset_B.lhs**2 - onset_B.rhs**2) * tan_alpha**2)
    quadratic = sp.expand(squared.subs(tau0, k * 2 * G_star / (sp.pi * sp.sqrt(R) * tan_alpha)))
    add(Relation("slip_B_hertz_quadratic", "(20)", "scenario B non-adhesive, squared slip condition",
                 sp.collect(quadratic, d), sp.Integer(0), (d, d_max, k), variable=d))
    add(Relation("slip_B_hertz_k", "(20)", "k of the quadratic (20)", k, kk, (tan_alpha, R, tau0, G_star)))
    roots = sp.solve(quadratic, d)
    lower, upper = sorted(roots, key=lambda e: float(e.subs({d_max: 1, k: 1})))
    add(Relation("d_crit_B_hertz_pull_off_textbook", "(20)", "smaller root of (20), as the quadratic formula gives it",
                 d, lower, (d_max, k)))
    # Vieta: the product of the roots is the constant coefficient d_max²; dividing it by the
    # larger root avoids the cancellation of the quadratic formula when k² >> d_max (α → 90°).
    product = sp.Poly(quadratic, d).all_coeffs()[-1]
    add(Relation("d_crit_B_hertz_pull_off", "(20)", "smaller root of (20): pull-off at angle α (Vieta form)",
                 d, product / upper, (d_max, k)))
    add(Relation("d_crit_B_hertz_indentation", "(20)", "larger root of (20): indentation at angle α from d_max",
                 d, upper, (d_max, k)))
    for sign, branch in ((-1, "pull_off"), (+1, "indentation")):
        quartic = _reduce_to_polynomial(d_max + sign * tan_alpha * critical_shift, depth_of_radius)
        add(Relation(f"slip_B_jkr_quartic_{branch}", "(21)",
                     f"scenario B with adhesion ({'−' if sign < 0 else '+'} sign), quartic in s = sqrt(a)",
                     quartic, sp.Integer(0), (s, tan_alpha, d_max, R, tau0, G_star, E_star, dgamma), variable=s))
        add(Relation(f"slip_depth_B_{branch}", "(21)", "depth of slip onset from its contact radius, scenario B",
                     d, d_max + sign * tan_alpha * critical_shift, (a, tan_alpha, d_max, tau0, G_star)))


def _reduce_to_polynomial(depth_a: sp.Expr, depth_b: sp.Expr, divide_by: sp.Expr | None = None) -> sp.Expr:
    """Eliminate ``d`` from ``d = depth_a(a)`` and ``d = depth_b(a)``.

    Returns the monic polynomial in ``s = sqrt(a)`` whose positive roots are
    the solutions, optionally divided by a trivial factor (``s``).
    """
    difference = (depth_a - depth_b).subs(a, s**2)
    poly_expr = sp.expand(sp.powsimp(difference, force=True))
    if divide_by is not None:
        poly_expr = sp.expand(sp.cancel(poly_expr / divide_by))
    poly = sp.Poly(poly_expr, s)
    monic = poly.monic()
    return sp.expand(monic.as_expr())


def _positive_cubic_root(cubic: sp.Expr) -> sp.Expr:
    """Cardano's root of the depressed cubic ``s³ − p s − q`` (p, q > 0) that is positive.

    Descartes' rule (one sign change) gives exactly one positive root. With
    principal complex branches it is ``u + p/(3u)``, ``u = (q/2 + sqrt(q²/4 − p³/27))^(1/3)``,
    also when all three roots are real (then it equals ``2 Re u``). Which of
    SymPy's three solutions that is depends on its ordering, so it is picked
    by evaluation at one point of each regime (three real roots, one real root).
    """
    free = sorted(cubic.free_symbols - {s}, key=lambda sym: sym.name)
    samples = [
        {sym: (3.0 if sym == tan_alpha else 1.0) for sym in free},   # three real roots
        {sym: (0.1 if sym == tan_alpha else 1.0) for sym in free},   # one real root
    ]
    for root in sp.solve(cubic, s):
        values = [complex(root.evalf(subs=sample)) for sample in samples]
        if all(abs(v.imag) < 1e-12 * abs(v) and v.real > 0 for v in values):
            return root
    raise RuntimeError("no Cardano root of the cubic (18) is positive in both regimes")
