"""The spans of the paraboloid on the half-space as polynomials, a moving one in ``s = √a``, a pinned one in time
(issue 28: the extrema's scan and refinement without the branch's closed forms read span by span).

On the paraboloid's branch (9) ``d = s⁴/R − k s`` with ``k = √(2πΔγ/E*)``, so its integral
``∫_0^a d = s⁶/(3R) − (2/3) k s³``, and (10) ``F_N = 2E* (a d − a³/(3R)) = 2E* (2 s⁶/(3R) − k s³)`` along it. A span's
force in closed form (:class:`~.closed_form.Primitive`: ``a``, ``a²``, ``d``, ``a d − ∫d``, ``∫d`` and the attachment
branch's ``∫d₀``, all polynomials in ``s``) is ``F_x = F₀ + 2G* (P(a) − P(a₀))``, a polynomial of degree 6 in ``s``.
On a pinned radius ``F_N`` is linear in the depth, hence in time, and so is a force constant or linear in time
(:class:`~.span.LinearForce`). :func:`span_polynomials` gives each such span's coefficients of ``F_x`` and ``F_N`` (a row of a matrix each),
:func:`polynomial_values` reads them at every span's scan at once (Horner's rule over the matrix), and
:func:`polynomial_stationary` finds where one is stationary inside a bracket (its derivative's sign read at
:data:`~.closed_form.STATIONARY_READINGS` equal parts, each change of sign solved by a safeguarded Newton iteration,
in Python floats): what :mod:`.span_extrema` reads instead of :func:`~.solution.evaluate_span`, the branch's NumPy
forms and :func:`~.stationary.stationary_points` (:data:`POLYNOMIAL_ROUTE`). The branch's radius at its fold, which
the scan of a run ending at pull-off reads, is kept for the next run (:func:`fold_radius`).

The values differ from those routes by rounding alone: Horner's rule over degree ``n`` errs by at most
``γ_2n Σ|c_k| s^k`` (``γ_m ≈ m ε``), the old route's sums of the branch's terms by a few ``ε`` of the same terms
(``tests/models/test_span_polynomials.py`` compares both within a tolerance derived from it). Only the spans this
holds for are read so (:func:`span_polynomials`: a moving span on the paraboloid's own :class:`~.branch.Branch` of the
half-space, its force a closed form in the radius); the others keep the routes of before.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from mdr_events.parameters import Parameters

from .branch import Branch
from .closed_form import STATIONARY_READINGS, ClosedForce, Primitive, equal_parts
from .media import HalfSpaceMedium
from .span import LinearForce
from .span_record import Variable
from .stationary import _time_of_radius
from .state import Regime
from .tolerances import EPS

__all__ = ["POLYNOMIAL_ROUTE", "DEGREE", "ROOT_ULPS", "SHIFT_ULPS", "NEWTON_STEPS", "SpanPolynomials",
           "span_polynomials", "polynomial_values", "polynomial_value", "polynomial_stationary", "horner",
           "polynomial_scan", "polynomial_points", "FOLD_RADII_KEPT", "fold_radius"]

#: Whether :mod:`.span_extrema` reads the moving spans that :func:`span_polynomials` takes as polynomials in ``s``
#: (``False``: the route of before, every span by :func:`~.solution.evaluate_span` and
#: :func:`~.stationary.stationary_points`; the tests compare both).
POLYNOMIAL_ROUTE = True
#: The degree in ``s`` of ``F_x`` and ``F_N`` on a moving span (``a d`` and ``∫d`` are of degree 6).
DEGREE = 6
#: :func:`polynomial_stationary`'s root in ``s`` is held to this many ulp of ``s`` (``brentq``'s ``4 ε`` of the route
#: of before).
ROOT_ULPS = 4
#: The rounding :func:`polynomial_stationary`'s proof of no root allows, in ulp of the terms of its Taylor shift:
#: Horner's ``γ_2n`` of the shift (``n = 5``, the derivative's degree: 10) and of the sum it is compared with (10),
#: rounded up.
SHIFT_ULPS = 32
#: At most this many steps of :func:`polynomial_stationary`'s safeguarded Newton iteration (each at least a bisection
#: of the bracket: 64 halve any bracket of doubles to its ulp).
NEWTON_STEPS = 64
#: How many of the paraboloid's radii at its jump-off depth :func:`fold_radius` keeps, by parameters object, work and
#: tolerance (the least recently used dropped first).
FOLD_RADII_KEPT = 16


class SpanPolynomials(NamedTuple):
    """The spans read as polynomials (:func:`span_polynomials`): their indices in ``solution.spans``, whether each
    moves (its variable ``s = √a``; else pinned, its variable the time since its own start, ``τ − origin``) and each
    one's coefficients, lowest power first, of ``F_x`` (``force``) and ``F_N`` (``normal``), rows of matrices
    ``(spans, DEGREE + 1)`` (N); ``origin`` (s from first contact, one per row) the pinned span's start (0 on a
    moving one). A pinned span's time from first contact made its constant term ``F₀ + r (t_c − t₀)`` cancel against
    ``r τ``: after a long contact (a 100 m slide) ``F_x``'s minimum was off by 8e-9 of ``|F_x|`` (issue 32 round 28
    A4)."""

    indices: list[int]
    moving: list[bool]
    force: np.ndarray
    normal: np.ndarray
    origin: np.ndarray


def _branch_terms(branch: Branch) -> tuple[np.ndarray, np.ndarray]:
    """The coefficients in ``s`` (lowest first, :data:`DEGREE` + 1) of the branch's depth ``d = s⁴/R − k s`` and of
    its integral ``∫_0^a d = s⁶/(3R) − (2/3) k s³`` (9), ``k = √2 √π √Δγ / √E*`` as the branch's relation reads it."""
    params = branch.params
    k = math.sqrt(2.0) * math.sqrt(math.pi) * math.sqrt(branch.work) / math.sqrt(params.E_star)
    depth, integral = np.zeros(DEGREE + 1), np.zeros(DEGREE + 1)
    depth[1], depth[4] = -k, 1.0 / params.R
    integral[3], integral[6] = -2.0 / 3.0 * k, 1.0 / (3.0 * params.R)
    return depth, integral


def _takes(solution, span) -> bool:
    """Whether ``span`` is read as a polynomial: pinned, its force constant or linear in time
    (:class:`~.span.LinearForce`); or moving on the paraboloid's own branch of the half-space, its force a closed form
    (:class:`~.closed_form.ClosedForce` of a :class:`~.closed_form.Primitive` on that branch, and on the paraboloid's
    branch of attachment where it reads one) in the radius over its scale, not graded."""
    if span.regime is Regime.PINNED:
        return span.interpolant is None or type(span.interpolant) is LinearForce
    if span.regime not in (Regime.GROWING, Regime.SHRINKING) or span.variable is not Variable.RADIUS \
            or span.grading is not None or type(span.interpolant) is not ClosedForce:
        return False
    primitive, branch = span.interpolant.primitive, solution.model.branch(span.regime)
    return (type(primitive) is Primitive and type(branch) is Branch and primitive.branch is branch
            and (not primitive.C0 or type(primitive.attach) is Branch))


def span_polynomials(solution) -> SpanPolynomials:
    """The spans of ``solution`` that are polynomials (a moving one in ``s = √a``, a pinned one in time) and the
    coefficients of their ``F_x`` and ``F_N`` (module docstring); none on another indenter or medium, in Coulomb's
    compressed zone's run or where :data:`POLYNOMIAL_ROUTE` is off.

    Parameters
    ----------
    solution : PathSolution
        A continuum run.

    Returns
    -------
    SpanPolynomials
        The spans taken (perhaps none) and their coefficients.
    """
    model = solution.model
    indices = []
    if POLYNOMIAL_ROUTE and solution.compressed is None and model.profile is None \
            and type(model.medium) is HalfSpaceMedium:
        indices = [index for index, span in enumerate(solution.spans) if _takes(solution, span)]
    force, normal = np.zeros((len(indices), DEGREE + 1)), np.zeros((len(indices), DEGREE + 1))
    origin = np.zeros(len(indices))
    moving = []
    for row, index in enumerate(indices):
        span = solution.spans[index]
        moving.append(span.regime is not Regime.PINNED)
        if moving[-1]:
            force[row], normal[row] = _moving_rows(span, model.params)
        else:
            force[row], normal[row] = _pinned_rows(span, model.params)
            origin[row] = span.t_start - solution.t_contact
    return SpanPolynomials(indices, moving, force, normal, origin)


def _moving_rows(span, params) -> tuple[np.ndarray, np.ndarray]:
    """``F_x`` and ``F_N`` of a moving span in ``s = √a``: its primitive's terms (module docstring) and (10) on its
    branch, ``F_N = 2E* (a d − a³/(3R))``."""
    closed = span.interpolant
    primitive = closed.primitive
    depth, integral = _branch_terms(primitive.branch)
    area_depth = np.zeros(DEGREE + 1)  # a d = s⁶/R − k s³
    area_depth[3], area_depth[6] = depth[1], depth[4]
    # P = A₀ a + A₁ a²/2 + B₀ d + B₁ (a d − ∫d) + C ∫d + C₀ ∫d₀
    terms = primitive.B0 * depth + primitive.B1 * (area_depth - integral) + primitive.C * integral
    terms[2] += primitive.A0
    terms[4] += 0.5 * primitive.A1
    if primitive.C0:
        terms = terms + primitive.C0 * _branch_terms(primitive.attach)[1]
    force = closed.G2 * terms
    force[0] += closed.force - closed.G2 * closed.origin
    normal = np.zeros(DEGREE + 1)
    E2 = 2.0 * params.E_star
    normal[3], normal[6] = E2 * depth[1], E2 * (depth[4] - 1.0 / (3.0 * params.R))
    return force, normal


def _pinned_rows(span, params) -> tuple[np.ndarray, np.ndarray]:
    """``F_x`` and ``F_N`` of a pinned span of radius ``a`` in the time ``u = t − t_s`` since its start ``t_s``: the
    force ``F₀ + r (u + t_s − t₀)`` (or constant) and (10), ``2E* a d − 2E* a³/(3R)`` with
    ``d = d_s + v_d (u + t_s − t₀)`` (the segment's start ``t₀``)."""
    force, normal = np.zeros(DEGREE + 1), np.zeros(DEGREE + 1)
    segment, a, E2, start = span.segment, span.pinned_radius, 2.0 * params.E_star, span.t_start
    if span.interpolant is None:
        force[0] = span.force
    else:
        linear = span.interpolant
        force[0], force[1] = linear.force + linear.rate * (start - linear.t0), linear.rate
    normal[0] = E2 * a * (segment.ds + segment.vd * (start - segment.t0)) - E2 * a**3 / (3.0 * params.R)
    normal[1] = E2 * a * segment.vd
    return force, normal


def horner(coefficients: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``Σ c_k s^k`` by Horner's rule, row by row: ``coefficients`` ``(..., rows, DEGREE + 1)`` lowest first, ``s``
    ``(rows, points)``; element by element, so each value is the one of its row alone.

    Parameters
    ----------
    coefficients : numpy.ndarray
        The coefficients, lowest power first, in the last axis.
    s : numpy.ndarray
        The points of each row.

    Returns
    -------
    numpy.ndarray
        The values, ``(..., rows, points)``.
    """
    value = np.empty((*coefficients.shape[:-1], s.shape[-1]))
    value[...] = coefficients[..., -1:]
    for k in range(coefficients.shape[-1] - 2, -1, -1):
        value *= s
        value += coefficients[..., k:k + 1]
    return value


def polynomial_values(polynomials: SpanPolynomials, radii: np.ndarray,
                      times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``F_x`` and ``F_N`` (N) of the spans of ``polynomials`` at the radii ``radii`` (m) and times ``times`` (s from
    first contact; a row per span, in their order), all at once (:func:`horner` of both matrices over ``s = √a`` on a
    moving span, the time since its start on a pinned one, ``times − origin``).

    Parameters
    ----------
    polynomials : SpanPolynomials
        The spans' coefficients.
    radii, times : numpy.ndarray
        ``(spans, points)`` radii and times.

    Returns
    -------
    tuple of numpy.ndarray
        ``F_x`` and ``F_N``, each ``(spans, points)``.
    """
    variable = np.sqrt(radii) if all(polynomials.moving) else \
        np.where(np.array(polynomials.moving)[:, None], np.sqrt(radii), times - polynomials.origin[:, None])
    values = horner(np.stack([polynomials.force, polynomials.normal]), variable)
    return values[0], values[1]


def _derivative(coefficients: list[float]) -> list[float]:
    """The coefficients of the derivative, lowest first."""
    return [k * c for k, c in enumerate(coefficients)][1:]


def polynomial_value(coefficients: list[float], s: float) -> float:
    """``Σ c_k s^k`` by Horner's rule in Python floats.

    Parameters
    ----------
    coefficients : list of float
        The coefficients, lowest power first.
    s : float
        The point.

    Returns
    -------
    float
        The value.
    """
    value = 0.0
    for c in reversed(coefficients):
        value = value * s + c
    return value


def polynomial_stationary(coefficients: list[float], low: float, high: float) -> list[float]:
    """The points in ``[low, high]`` (``s``) where the polynomial ``Σ c_k s^k`` is stationary: its derivative read at
    :data:`~.closed_form.STATIONARY_READINGS` equal parts of the interval (as :meth:`~.closed_form.ClosedForce.stationary`
    reads a closed form's rate), each change of sign solved by Newton's steps kept inside the bracket of the change
    (a step leaving it, or not halving it, replaced by a bisection), to :data:`ROOT_ULPS` ulp of ``s``.

    Parameters
    ----------
    coefficients : list of float
        The polynomial's coefficients, lowest power first.
    low, high : float
        The interval, ``low <= high``.

    Returns
    -------
    list of float
        The stationary points, increasing (none: monotone there).
    """
    slope = _derivative(coefficients)
    if _root_free(slope, float(low), float(high)):
        return []
    curvature = _derivative(slope)
    grid = equal_parts(float(low), float(high), STATIONARY_READINGS)
    rates = [polynomial_value(slope, s) for s in grid]
    # (a rate zero at a reading counts where it changes sign there, as closed_form's readings count it)
    roots = [grid[k] for k in range(1, len(grid) - 1) if rates[k] == 0.0 and rates[k - 1] * rates[k + 1] < 0.0]
    for k in range(len(grid) - 1):
        if rates[k] * rates[k + 1] < 0.0:
            roots.append(_newton(slope, curvature, grid[k], grid[k + 1], rates[k]))
    return sorted(roots)


def _root_free(slope: list[float], low: float, high: float) -> bool:
    """Whether ``slope`` provably keeps its sign on ``[low, high]``: about the middle ``m`` it is exactly
    ``Σ q_k x^k`` (``x = s − m``, ``|x| <= h``, the half-width, :func:`_centred`; the Taylor shift by synthetic division), which cannot
    vanish where ``|q₀| > Σ_{k≥1} |q_k| h^k``; each ``q_k`` is rounded by at most ``γ_2n`` of
    ``Σ_j C(j, k) |c_j| |m|^(j−k)``, whose sum over ``k`` weighted by ``h^k`` is ``Σ_j |c_j| (|m| + h)^j``, so the
    test asks :data:`SHIFT_ULPS` ε of that more (:func:`polynomial_stationary` then reads nothing)."""
    middle, half = _centred(low, high)
    shifted = list(slope)
    degree = len(shifted) - 1
    for start in range(degree):  # (synthetic division: the coefficients of slope(middle + x), lowest first)
        for k in range(degree - 1, start - 1, -1):
            shifted[k] += middle * shifted[k + 1]
    rest = 0.0
    for q in reversed(shifted[1:]):
        rest = (rest + abs(q)) * half
    rounding = SHIFT_ULPS * EPS * polynomial_value([abs(c) for c in slope], abs(middle) + half)
    return abs(shifted[0]) > rest + rounding


def _centred(low: float, high: float) -> tuple[float, float]:
    """The middle ``m`` of ``[low, high]`` and a half-width ``h`` with ``[m − h, m + h]`` covering it exactly
    (:func:`_root_free`'s interval): ``m`` is rounded, so ``h`` is the larger of ``high − m`` and ``m − low``, each
    rounded by at most half its ulp, raised by one ulp."""
    middle = 0.5 * (low + high)
    return middle, math.nextafter(max(high - middle, middle - low), math.inf)


def _newton(slope: list[float], curvature: list[float], low: float, high: float, at_low: float) -> float:
    """The root of ``slope`` in ``[low, high]`` (of opposite signs at the ends; ``at_low`` its value at ``low``) by
    safeguarded Newton steps (:func:`polynomial_stationary`)."""
    s = 0.5 * (low + high)
    for _ in range(NEWTON_STEPS):
        value = polynomial_value(slope, s)
        if value == 0.0:
            return s
        if (value > 0.0) == (at_low > 0.0):
            low = s
        else:
            high = s
        width = high - low
        if width <= ROOT_ULPS * EPS * abs(s):
            break
        derivative = polynomial_value(curvature, s)
        step = s - value / derivative if derivative != 0.0 else math.nan
        if low < step < high and abs(step - s) < 0.5 * width:  # (Newton's step: inside, at most half the bracket)
            if abs(step - s) <= ROOT_ULPS * EPS * abs(step):
                return step
            s = step
        else:  # (else a bisection)
            s = 0.5 * (low + high)
    return s


def polynomial_scan(solution, polynomials: SpanPolynomials, grids: list, radii: list, values: list) -> None:
    """The extrema's scan (:func:`~.span_extrema.scan_spans`) of the spans of ``polynomials``: the radius, ``F_x``
    and ``F_N`` written into ``values`` at their indices, the spans of as many points at once
    (:func:`polynomial_values`); a pinned span's radius its own, repeated.

    Parameters
    ----------
    solution : PathSolution
        The run.
    polynomials : SpanPolynomials
        Its spans read as polynomials (:func:`span_polynomials`).
    grids : list of numpy.ndarray
        Every span's scan times (s from first contact).
    radii : list
        Every moving span's scan radii (m; ``None`` elsewhere).
    values : list
        Every span's scan (a dict of its quantities by name), filled here at the spans of ``polynomials``.
    """
    spans = solution.spans
    radii = [radii[index] if moving else np.full(len(grids[index]), spans[index].pinned_radius)
             for index, moving in zip(polynomials.indices, polynomials.moving)]
    by_length: dict[int, list[int]] = {}
    for row, index in enumerate(polynomials.indices):
        by_length.setdefault(len(grids[index]), []).append(row)
    for rows in by_length.values():
        part = polynomials if len(rows) == len(polynomials.indices) else SpanPolynomials(
            [polynomials.indices[row] for row in rows], [polynomials.moving[row] for row in rows],
            polynomials.force[rows], polynomials.normal[rows], polynomials.origin[rows])
        force, normal = polynomial_values(part, np.array([radii[row] for row in rows]),
                                          np.array([grids[index] for index in part.indices]))
        for k, (row, index) in enumerate(zip(rows, part.indices)):
            values[index] = {"contact_radius": radii[row], "normal_force": normal[k], "tangential_force": force[k]}


def polynomial_points(solution, index: int, polynomials: SpanPolynomials, quantity: str, times: tuple[float, float],
                      radii: tuple[float, float]) -> list[tuple[float, float]]:
    """:func:`~.stationary.stationary_points` of a span read as a polynomial in ``s = √a`` (``F_x`` or ``F_N``): the
    stationary points of its coefficients between the bracket's radii (:func:`polynomial_stationary`),
    each with its value and the time of its radius (that of its depth on the branch), kept within the bracket.

    Parameters
    ----------
    solution : PathSolution
        The run.
    index : int
        A moving span of ``polynomials``.
    polynomials : SpanPolynomials
        The run's spans read as polynomials.
    quantity : str
        ``"normal_force"`` or ``"tangential_force"``.
    times : tuple of float
        The bracket's ends (s from first contact), increasing, within the span.
    radii : tuple of float
        The contact radius at those times (m).

    Returns
    -------
    list of (float, float)
        ``(time, value)`` of each stationary point inside the bracket (none: monotone there).
    """
    row = polynomials.indices.index(index)
    coefficients = (polynomials.force if quantity == "tangential_force" else polynomials.normal)[row].tolist()
    low, high = sorted(math.sqrt(radius) for radius in radii)
    points = []
    for s in polynomial_stationary(coefficients, low, high):
        time = _time_of_radius(solution, solution.spans[index], s * s)
        points.append((min(max(time, times[0]), times[1]), polynomial_value(coefficients, s)))
    return points


def fold_radius(branch: Branch, rtol: float) -> float:
    """:meth:`~.branch.Branch.radius` of the paraboloid's ``branch`` at its jump-off depth (the fold, where a run that
    ends at pull-off ends: the iteration meets a double root there and takes some thirty steps), kept for the next run
    of the same parameters (the same object: a run's job keeps it, :func:`~mdr_events.memo.kept`), the same work and
    tolerance: the same number bit for bit (:data:`FOLD_RADII_KEPT` of them, by ``functools.lru_cache``: safe under
    dask's threaded scheduler).

    Parameters
    ----------
    branch : Branch
        The paraboloid's branch (9) of a positive work of adhesion.
    rtol : float
        The radius's relative tolerance.

    Returns
    -------
    float
        The contact radius at the branch's jump-off depth (m).
    """
    params, radius = _kept_fold(_Fold(branch, rtol))
    # (the value keeps its parameters alive, so their id is not reused while kept; checked all the same)
    return radius if params is branch.params else branch.radius(branch.jump_off_depth, rtol)


class _Fold:
    """One call of :func:`fold_radius`, compared and hashed by (the parameters' ``id``, the work, the tolerance)
    alone: the branch rides along."""

    __slots__ = ("key", "branch", "rtol")

    def __init__(self, branch: Branch, rtol: float) -> None:
        self.key, self.branch, self.rtol = (id(branch.params), branch.work, rtol), branch, rtol

    def __hash__(self) -> int:
        return hash(self.key)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, _Fold) and self.key == other.key


@functools.lru_cache(maxsize=FOLD_RADII_KEPT)
def _kept_fold(call: _Fold) -> tuple[Parameters, float]:
    """:func:`fold_radius`'s parameters and radius of ``call``, kept."""
    branch = call.branch
    return branch.params, branch.radius(branch.jump_off_depth, call.rtol)
