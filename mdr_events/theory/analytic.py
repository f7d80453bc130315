"""Closed-form layer: JKR contact, slip-onset depths ``d_crit(α)``, critical angles.

Every formula is evaluated through the SymPy-derived relations of
:mod:`mdr_events.theory.symbolic` (lambdified once). Where a relation is a
polynomial (the cubic of (18), the quartics of (9) and (21)), its unique
physical root is found by :func:`positive_polynomial_root`, a vectorised
safeguarded Newton iteration: no Python loop over angles.

Angles are in degrees, lengths in metres, forces in newtons.
"""

from __future__ import annotations

import math
from typing import Literal, NamedTuple

import numpy as np

from mdr_events.theory import symbolic
from mdr_events.parameters import Parameters
from mdr_events.validation import check_choice, check_flag, validate_alpha

__all__ = [
    "DimensionlessGroups",
    "dimensionless_groups",
    "d_crit",
    "critical_angle",
    "critical_shift",
    "jkr_depth",
    "jkr_contact_radius",
    "jkr_normal_force",
    "normal_force",
    "hertz_contact_radius",
    "pull_off_force",
    "jump_off",
    "jump_in_radius",
    "positive_polynomial_root",
    "SCENARIOS",
    "BRANCHES",
    "CRITICAL_ANGLE_SCENARIOS",
]

SCENARIOS = ("A", "B")
BRANCHES = ("pull-off", "indentation")

_EPS = np.finfo(float).eps
_FLOAT_EPS = float(_EPS)
#: Scalar types recognised at once for the Python-float path of :func:`positive_polynomial_root`
#: (``numpy.float64`` is a ``float``).
_SCALARS = (float, int)


def _rel(key: str):
    return symbolic.relation(key)


def _tan_degrees(alpha_deg: np.ndarray) -> np.ndarray:
    """tan α with α = 90° exactly mapped to +inf (no tangential motion)."""
    with np.errstate(divide="ignore"):
        return np.where(alpha_deg == 90.0, np.inf, np.tan(np.deg2rad(alpha_deg)))


def _as_output(values: np.ndarray, like: np.ndarray):
    return float(values) if np.ndim(like) == 0 else values


# ----------------------------------------------------------------------------
# polynomial roots
def _horner(coefficients, x):
    """Value and derivative of the polynomial at ``x`` (Horner's scheme)."""
    value = coefficients[0] * x + coefficients[1]
    slope = coefficients[0]
    for coefficient in coefficients[2:]:
        slope = slope * x + value
        value = value * x + coefficient
    return value, slope


_ROOTS = {1: lambda v: v, 2: np.sqrt, 3: np.cbrt}


def _upper_root_bound(coeffs: list) -> np.ndarray:
    """An upper bound of the positive roots of a monic polynomial, elementwise.

    For every positive term ``c_j s^j`` above which no coefficient is
    negative, ``p(s) > 0`` as soon as ``c_j s^j`` beats each of the ``m``
    lower terms ``m |c_i| s^i``, i.e. for
    ``s >= max_i (m |c_i| / c_j)^(1/(j-i))``; the smallest such bound is used.
    It is tight where one positive term dominates, e.g. ``P s²`` of (21) near
    α = 90°, where a bound on all root moduli (Fujiwara) would be orders of
    magnitude too large. Coefficients that are the scalar 0 are skipped.
    """
    present = [i for i, cf in enumerate(coeffs) if not (np.ndim(cf) == 0 and cf == 0)]
    bound = np.inf
    nothing_negative_above = True
    for j in present[:-1]:
        cj = coeffs[j]
        lower = [i for i in present if i > j]
        m = float(len(lower))
        candidate = 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            for i in lower:
                ratio = m * np.abs(coeffs[i]) / cj
                root = _ROOTS.get(i - j, lambda v, e=1.0 / (i - j): v**e)
                candidate = np.maximum(candidate, root(ratio))
        if j == 0:
            bound = candidate
        else:
            usable = nothing_negative_above & (cj > 0.0)
            bound = np.where(usable, np.minimum(bound, candidate), bound)
        nothing_negative_above = nothing_negative_above & (cj >= 0.0)
    return bound


def positive_polynomial_root(coefficients, lower=0.0, max_iterations: int = 100, rtol: float = 4 * _EPS):
    """Largest positive root of monic polynomials, vectorised over their coefficients.

    Parameters
    ----------
    coefficients : sequence of array_like
        ``[1, c_{n-1}, ..., c_0]`` (highest power first), each broadcastable
        to the common shape of the problem.
    lower : array_like
        A point with ``p(lower) <= 0``: the root sought is the largest root,
        which lies above it (0 where ``c_0 <= 0``; the minimum of ``p`` for a
        polynomial with two positive roots).
    max_iterations : int
        Safety bound; convergence takes 4–8 iterations in practice.
    rtol : float
        Relative step at which the iteration stops (default 4 ulp).

    Returns
    -------
    numpy.ndarray or float
        The root, converged to ``rtol``; a ``float`` when every coefficient and
        ``lower`` are scalars.

    Notes
    -----
    Newton's method starts from an upper bound of the roots
    (:func:`_upper_root_bound`). Where ``p`` is convex between the root and
    the start (true for every polynomial of this model), the iterates descend
    monotonically onto the largest root. An element whose iterate ever falls
    where ``p < 0`` (an overshoot, so not convex there) is solved again with
    a bracketed Newton–bisection iteration on ``[lower, bound]``.

    Scalars take the same iteration in Python floats (:func:`_scalar_root`), about
    50 times faster than NumPy on one element: the continuum method calls it from
    its right-hand side.
    """
    if len(coefficients) < 2:
        raise ValueError("positive_polynomial_root needs a polynomial of degree >= 1")
    if isinstance(lower, _SCALARS) and all(isinstance(cf, _SCALARS) for cf in coefficients) \
            or np.ndim(lower) == 0 and all(np.ndim(cf) == 0 for cf in coefficients):
        return _scalar_root([float(cf) for cf in coefficients], float(lower), max_iterations, rtol)
    coeffs = [np.asarray(cf, dtype=float) for cf in coefficients]
    shape = np.broadcast_shapes(*[cf.shape for cf in coeffs], np.shape(lower))
    lower = np.broadcast_to(np.asarray(lower, dtype=float), shape)
    start = np.maximum(_upper_root_bound(coeffs), lower) * (1.0 + 8 * _EPS)
    x = np.broadcast_to(start, shape).copy()
    # in-place buffers: for large arrays allocation, not arithmetic, is the cost
    value, slope, step, tolerance = (np.empty(shape) for _ in range(4))
    overshoot = np.zeros(shape, dtype=bool)
    for _ in range(max_iterations):
        np.multiply(x, coeffs[0], out=value)
        value += coeffs[1]
        slope[...] = coeffs[0]
        for coefficient in coeffs[2:]:
            slope *= x
            slope += value
            value *= x
            value += coefficient
        np.divide(value, slope, out=step)
        x -= step
        np.abs(x, out=tolerance)
        tolerance *= rtol
        overshoot |= step < -tolerance  # an upward step: p < 0 beyond rounding
        np.abs(step, out=step)
        if np.all(step <= tolerance):
            break
    redo = overshoot | ~np.isfinite(x)
    if np.any(redo):
        x[redo] = _bracketed_root([np.broadcast_to(cf, shape)[redo] for cf in coeffs],
                                  lower[redo], start[redo], max_iterations)
    return x


def _scalar_root(coeffs: list[float], lower: float, max_iterations: int, rtol: float) -> float:
    """:func:`positive_polynomial_root` for one polynomial, in Python floats.

    Newton's method descends from the bound of :func:`_upper_root_bound` (here for
    floats, :func:`_scalar_upper_root_bound`) and never below ``lower``; an iterate
    where ``p < 0`` (an overshoot) hands over to the bracketed iteration on
    ``[lower, bound]``.
    """
    rtol = float(rtol)  # Python floats throughout: NumPy scalars would make every step ten times dearer
    start = max(_scalar_upper_root_bound(coeffs), lower) * (1.0 + 8 * _FLOAT_EPS)
    x = start
    for _ in range(max_iterations):
        value, slope = _horner(coeffs, x)
        step = value / slope if slope > 0.0 else -math.inf
        if step < -rtol * abs(x):  # an upward step: p < 0 beyond rounding (an overshoot), or a fold
            root = _bracketed_root([np.array([cf]) for cf in coeffs], np.array([lower]), np.array([start]),
                                   max_iterations)
            return float(root[0])
        x_new = max(x - step, lower)
        if abs(x_new - x) <= rtol * abs(x_new):
            return x_new
        x = x_new
    return x


def _scalar_upper_root_bound(coeffs: list[float]) -> float:
    """:func:`_upper_root_bound` of one polynomial, in floats (the same rule, term by term)."""
    present = [i for i, cf in enumerate(coeffs) if cf != 0.0]
    bound = math.inf
    nothing_negative_above = True
    for j in present[:-1]:
        cj = coeffs[j]
        lower = [i for i in present if i > j]
        if cj > 0.0 and (nothing_negative_above or j == 0):
            candidate = max((len(lower) * abs(coeffs[i]) / cj) ** (1.0 / (i - j)) for i in lower)
            bound = candidate if j == 0 else min(bound, candidate)
        nothing_negative_above = nothing_negative_above and cj >= 0.0
    return bound


def _bracketed_root(coeffs, lo, hi, max_iterations):
    """Newton steps kept inside ``[lo, hi]`` (``p(lo) <= 0 < p(hi)``), bisection otherwise."""
    lo, hi = lo.copy(), hi.copy()
    x = hi.copy()
    for _ in range(4 * max_iterations):
        value, slope = _horner(coeffs, x)
        below = value <= 0.0
        lo = np.where(below, x, lo)
        hi = np.where(below, hi, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            candidate = x - value / slope
        inside = (candidate >= lo) & (candidate <= hi)
        candidate = np.where(inside, candidate, 0.5 * (lo + hi))
        # converged; or the bracket has closed, or p(x) is zero to its evaluation error (near a
        # double root, e.g. at the pull-off fold, Newton is slow and the root is only this accurate)
        noise, _ = _horner([np.abs(cf) for cf in coeffs], np.abs(x))
        done = np.all((np.abs(candidate - x) <= 4 * _EPS * np.abs(candidate)) | (hi - lo <= 4 * _EPS * np.abs(hi))
                      | (np.abs(value) <= 8 * _EPS * noise))
        x = candidate
        if done:
            break
    return x


# ----------------------------------------------------------------------------
# normal contact, eqs. (7)-(10), (16)
def jkr_depth(contact_radius, params: Parameters, work_of_adhesion: float):
    """Indentation depth of the adhesive contact of radius ``a``, eq. (9)."""
    return _rel("jkr_depth").numeric(contact_radius, params.R, params.E_star, work_of_adhesion)


def jkr_normal_force(contact_radius, params: Parameters, work_of_adhesion: float):
    """Normal force of the adhesive contact of radius ``a``, eq. (10)."""
    return _rel("jkr_normal_force").numeric(contact_radius, params.R, params.E_star, work_of_adhesion)


def normal_force(depth, contact_radius, params: Parameters):
    """Normal force of the springs in ``|x| < a`` at depth ``d`` (any, e.g. pinned ``a``), eq. (10)."""
    return _rel("normal_force").numeric(depth, contact_radius, params.R, params.E_star)


def hertz_contact_radius(depth, params: Parameters):
    """Non-adhesive contact radius ``a = sqrt(R d)``, eq. (16)."""
    return _rel("hertz_radius").numeric(np.maximum(depth, 0.0), params.R)


def jump_off(params: Parameters, work_of_adhesion: float) -> dict[str, float]:
    """Jump-off point under displacement control (``∂d/∂a = 0`` on the branch).

    Returns ``contact_radius``, ``depth`` and ``normal_force`` at the jump-off.
    """
    args = (params.R, params.E_star, work_of_adhesion)
    return {
        "contact_radius": float(_rel("jump_off_radius").numeric(*args)),
        "depth": float(_rel("jump_off_depth").numeric(*args)),
        "normal_force": float(_rel("jump_off_force").numeric(params.R, work_of_adhesion)),
    }


def jump_in_radius(params: Parameters, work_of_adhesion: float) -> float:
    """Contact radius on first touch (``d = 0`` on the stable branch of (9))."""
    return float(_rel("jump_in_radius").numeric(params.R, params.E_star, work_of_adhesion))


def pull_off_force(params: Parameters, work_of_adhesion: float) -> float:
    """JKR pull-off force ``−(3/2) π Δγ R``: the minimum of (10) along the branch."""
    return float(_rel("pull_off_force").numeric(params.R, work_of_adhesion))


def jkr_contact_radius(depth, params: Parameters, work_of_adhesion: float):
    """Contact radius on the stable branch of (9) for a depth ``d``.

    The stable branch is ``a >= a_jump-off`` (``∂d/∂a >= 0``). Depths below the
    jump-off depth have no contact: the result is ``nan`` there.
    """
    depth_arr = np.asarray(depth, dtype=float)
    if work_of_adhesion == 0.0:
        return _as_output(np.where(depth_arr >= 0, hertz_contact_radius(depth_arr, params), np.nan), depth_arr)
    rel = _rel("jkr_radius_quartic")
    coefficients = rel.coefficients(depth_arr, params.R, params.E_star, work_of_adhesion)
    point = jump_off(params, work_of_adhesion)
    s_min = np.sqrt(point["contact_radius"])
    root = positive_polynomial_root(coefficients, lower=s_min)
    radius = np.where(depth_arr >= point["depth"], root**2, np.nan)
    return _as_output(radius, depth_arr)


# ----------------------------------------------------------------------------
# tangential springs, eq. (13)
def critical_shift(contact_radius, params: Parameters):
    """Critical spring shift ``ū(a) = π a τ0 / (2 G*)``, eq. (13)."""
    return _rel("critical_shift").numeric(contact_radius, params.tau0, params.G_star)


def fretting_dissipated_energy(contact_radius, amplitude, params: Parameters):
    """Energy dissipated per cycle ``x: −X → X → −X`` by a fixed contact of radius ``a`` (J): the area
    ``4 π a² τ0 (X − ū)`` of the parallelogram ``F_x = 2G* a (x − Y)``, ``Y`` clipped to
    ``[x − ū, x + ū]`` (plateaus ``±π a² τ0``); for ``X > ū`` (smaller loops stick and dissipate nothing)."""
    return _rel("fretting_dissipated_energy").numeric(contact_radius, amplitude, params.tau0, params.G_star)


# ----------------------------------------------------------------------------
# slip onset, eqs. (17), (18), (20), (21)
def d_crit(
    alpha,
    params: Parameters,
    scenario: Literal["A", "B"] = "A",
    adhesion: bool = False,
    branch: Literal["pull-off", "indentation"] | None = None,
):
    """Indentation depth at which the springs start to slide, eqs. (17)–(21).

    Parameters
    ----------
    alpha : float or array_like
        Path angle to the surface in degrees, in [0, 90].
    params : Parameters
        Material, indenter and adhesion.
    scenario : {"A", "B"}
        ``"A"``: indentation at angle α from first contact, eqs. (14), (17),
        (18). ``"B"``: vertical indentation to ``d_max`` then motion at angle α,
        eqs. (19)–(21).
    adhesion : bool
        ``False``: non-adhesive contact radius (16), eqs. (17) and (20).
        ``True``: JKR radius (9), eqs. (18) and (21) with ``Δγ0`` on the way
        in and ``Δγ1`` on the way out.
    branch : {"pull-off", "indentation"}, optional
        Scenario B only (default "pull-off"): from ``d_max`` out at angle α (the "−" sign of (21),
        smaller root of (20)) or further in at angle α (the "+" sign, larger
        root of (20)).

    Returns
    -------
    float or numpy.ndarray
        ``d_crit`` in metres, the same shape as ``alpha``.

    Notes
    -----
    Root choice: each reduced polynomial (the cubic of (18) and the quartics
    of (21) in ``s = sqrt(a)``) has exactly one sign change, hence exactly one
    positive root (Descartes), and that is the one returned. In scenario A it
    lies on the stable JKR branch (``d = K a > 0``). On the pull-off branch of
    scenario B it may lie on the unstable branch ``a < a_jump-off(Δγ1)``: the
    contact then comes apart (jump-off at depth ``d_jump-off < 0``) before any
    spring slides, and ``-inf`` is returned.

    "Never slides" is encoded so that ``d > d_crit`` (indentation) or
    ``d < d_crit`` (pull-off) is the sliding region: α = 90° gives ``+inf``
    for scenario A and the indentation branch, ``-inf`` for the pull-off
    branch. α → 0 gives ``d_crit → 0`` (A) and ``→ d_max`` (B).

    Scenario B (21) assumes the contact radius follows (9) with ``Δγ1`` from
    the start of pull-off; in the model it is pinned first (see
    :mod:`mdr_events` docs on the continuum method).
    """
    check_choice("scenario", scenario, SCENARIOS)
    if scenario == "A" and branch is not None:
        raise ValueError(f"branch={branch!r} is not allowed with scenario 'A'; allowed: None (branch is for scenario B)")
    branch = "pull-off" if branch is None else branch
    check_choice("branch", branch, BRANCHES)
    check_flag("adhesion", adhesion)
    alpha_deg = validate_alpha(alpha)
    tan = _tan_degrees(alpha_deg)
    vertical = np.isinf(tan)
    tan_finite = np.where(vertical, 1.0, tan)
    p = params

    if scenario == "A":
        if not adhesion:
            depth = _rel("d_crit_A_hertz").numeric(tan_finite, p.R, p.tau0, p.G_star)
        else:
            coefficients = _rel("slip_A_jkr_cubic").coefficients(
                tan_finite, p.R, p.tau0, p.G_star, p.E_star, p.dgamma0)
            with np.errstate(invalid="ignore", divide="ignore"):  # 0/0 at the double root s = 0 (α = 0, Δγ = 0)
                root = positive_polynomial_root(coefficients)
            radius = np.where(np.isfinite(root), root, 0.0) ** 2
            depth = _rel("slip_depth_A").numeric(radius, tan_finite, p.tau0, p.G_star)
        result = np.where(vertical, np.inf, depth)
        return _as_output(result, alpha_deg)

    pulling = branch == "pull-off"
    never = -np.inf if pulling else np.inf
    key = "pull_off" if pulling else "indentation"
    if not adhesion:
        k = _rel("slip_B_hertz_k").numeric(tan_finite, p.R, p.tau0, p.G_star)
        depth = _rel(f"d_crit_B_hertz_{key}").numeric(p.d_max, k)
    else:
        work = p.dgamma1 if pulling else p.dgamma0
        coefficients = _rel(f"slip_B_jkr_quartic_{key}").coefficients(
            tan_finite, p.d_max, p.R, p.tau0, p.G_star, p.E_star, work)
        radius = positive_polynomial_root(coefficients) ** 2
        depth = _rel(f"slip_depth_B_{key}").numeric(radius, tan_finite, p.d_max, p.tau0, p.G_star)
        if pulling and work > 0.0:
            unstable = radius < jump_off(p, work)["contact_radius"]
            depth = np.where(unstable, never, depth)
    result = np.where(vertical, never, depth)
    return _as_output(result, alpha_deg)


#: Scenarios that have a critical angle (:func:`critical_angle`).
CRITICAL_ANGLE_SCENARIOS = ("A", "B", "B+")


def critical_angle(params: Parameters, scenario: Literal["A", "B", "B+"] = "A", adhesion: bool = True,
                   final_depth: float | None = None) -> float:
    """Critical path angle in degrees.

    Scenario A: the angle at which slip begins exactly at ``d_max``
    (``d_crit(α_c) = d_max``); for α < α_c the springs slide during
    indentation. Non-adhesive: eq. (17) at ``d_max``; adhesive: eq. (18) with
    the JKR radius at ``d_max`` on the ``Δγ0`` branch.

    Scenario B: ``d_crit`` of the pull-off branch equals ``d_max`` only at
    α = 0, so the meaningful threshold is the other end: the angle above which
    the contact comes apart (jump-off on the ``Δγ1`` branch) before any spring
    slides, eq. (21) at the jump-off point. Without adhesion the radius
    shrinks to zero and slip always comes first: 90°.

    Scenario B+ (the "+" branch of Fig. 9b, :meth:`mdr_events.Path.scenario_B_indentation`):
    vertically to ``d_max``, then further in at angle α to ``final_depth``
    (default ``2 d_max``, as the path). Every angle below 90° slides at some
    depth beyond ``d_max``; the critical angle is the one at which slip begins
    exactly at ``final_depth`` (the "+" sign of (21), or the larger root of (20), at
    the radius of ``final_depth`` on the ``Δγ0`` branch): for α < α_c the springs
    slide before the path turns back.
    """
    check_choice("scenario", scenario, CRITICAL_ANGLE_SCENARIOS)
    check_flag("adhesion", adhesion)
    p = params
    if final_depth is not None and scenario != "B+":
        raise ValueError(f"final_depth={final_depth!r} is not allowed with scenario {scenario!r}; "
                         "allowed: None (final_depth is for scenario 'B+')")
    if scenario == "B+":
        final = 2.0 * p.d_max if final_depth is None else final_depth
        if not (isinstance(final, (int, float)) and math.isfinite(final) and final > p.d_max):
            raise ValueError(f"final_depth={final!r} is not allowed; allowed: a finite depth > d_max = {p.d_max!r} m")
        if adhesion:
            radius = jkr_contact_radius(final, p, p.dgamma0)
        else:
            radius = float(hertz_contact_radius(final, p))
        with np.errstate(divide="ignore"):
            angle = _rel("critical_angle_B_indentation").numeric(radius, final, p.d_max, p.tau0, p.G_star)
        return float(np.rad2deg(angle))
    if scenario == "A":
        if adhesion:
            radius = jkr_contact_radius(p.d_max, p, p.dgamma0)
        else:
            radius = float(hertz_contact_radius(p.d_max, p))
        with np.errstate(divide="ignore"):
            angle = _rel("critical_angle_A").numeric(radius, p.d_max, p.tau0, p.G_star)
        return float(np.rad2deg(angle))
    if not adhesion or p.dgamma1 == 0.0:
        return 90.0
    point = jump_off(p, p.dgamma1)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B").numeric(point["contact_radius"], point["depth"], p.d_max, p.tau0, p.G_star)
    return float(np.rad2deg(angle))


class DimensionlessGroups(NamedTuple):
    """The three numbers the model's dimensionless results depend on (:func:`dimensionless_groups`)."""

    slip: float  #: S = π τ0 √R / (2 G* √d_max)
    adhesion_in: float  #: Γ0 = 2π Δγ0 √R / (E* d_max^(3/2))
    adhesion_out: float  #: Γ1 = 2π Δγ1 √R / (E* d_max^(3/2))


def dimensionless_groups(params: Parameters) -> DimensionlessGroups:
    """The slip parameter and the two adhesion parameters of the model.

    Measure depths in ``d_max`` (``d = d_max d̂``), radii in ``√(R d_max)`` (``a = √(R d_max) â``) and tangential
    lengths in ``d_max`` (the paths (14), (19) move ``x = d / tan α``). Then the branch (9) reads
    ``d̂ = â² − √(Γ â)`` with ``Γ = 2π Δγ √R / (E* d_max^(3/2))``, one per work of adhesion, and the cap (13)
    ``ū/d_max = S â`` with ``S = π τ0 √R / (2 G* √d_max)`` (the slip parameter ``k/(tan α √d_max)`` of (20)).
    The springs' forces scale as ``E* (R d_max)^(1/2) d_max`` (normal) and ``τ0 R d_max`` (tangential), so
    every angle, every depth over ``d_max`` and every ratio such as ``F_x / (π a² τ0)`` depends on
    ``(S, Γ0, Γ1)`` and the path's angle alone: two parameter sets with the same groups have the same
    critical angles (17), (18), (21).
    """
    root = math.sqrt(params.R)
    scale = params.E_star * params.d_max**1.5
    return DimensionlessGroups(math.pi * params.tau0 * root / (2.0 * params.G_star * math.sqrt(params.d_max)),
                               2.0 * math.pi * params.dgamma0 * root / scale,
                               2.0 * math.pi * params.dgamma1 * root / scale)
