"""The exact extremes of one quantity over a continuum run, span by span: every span scanned at once
(:func:`scan_spans`), the best scanned point of each span that can reach the run's best refined by the roots of the
quantity's derivative (:func:`~.stationary.stationary_points`) or a bounded search (:func:`extremum`), and the rule of
ties (:func:`within_tie`) the rate run's extrema share."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy import optimize

from mdr_events.validation import shown

from .branch import Branch
from .graded import span_variable
from .solution import (PathSolution, _compressed_zone, _fill_normal_force, _fill_tangential_force, _pinned_kinematics,
                       evaluate_span)
from .span_polynomials import SpanPolynomials, fold_radius, polynomial_points, polynomial_scan, span_polynomials
from .span_record import Span, Variable, root_key
from .state import Regime
from .stationary import never_stationary, stationary_points

__all__ = ["EXTREMUM_QUANTITIES", "EXTREMUM_GRID", "EXTREMUM_TIE", "EXTREMUM_XTOL", "ExtremumScan", "ScanMatrix",
           "extremum", "first_tie", "scan_spans", "within_tie"]

#: Quantities :func:`extremum` finds the extremes of; the means are per contact area ``π a²``.
EXTREMUM_QUANTITIES = ("normal_force", "tangential_force", "contact_radius", "contact_area",
                       "mean_pressure", "mean_shear_stress")
#: Points per span at which :func:`extremum` brackets an extremum before refining it.
EXTREMUM_GRID = 65
#: Values within this share of the extremum are ties (rounding), of which :func:`extremum` reports the earliest.
EXTREMUM_TIE = 1e-12
#: Span-relative time accuracy of the refined extremum; the value is then exact to rounding
#: (it is flat there: its error is second order in the time error).
EXTREMUM_XTOL = 1e-12


def within_tie(value: float, best: float, size: float) -> bool:
    """Whether ``value`` ties ``best`` to rounding: within :data:`EXTREMUM_TIE` of the quantity's ``size`` along the
    run (or of ``|best|``, the larger), so that a value near 0 is held to its run's rounding, not to its own. The one
    rule of :func:`extremum` (the earliest of the spans' ties; a stationary point replaces a span's best scanned point
    only where that point does not tie it) and of the rate run's refinement
    (:func:`~mdr_events.models.continuum.rate_run.rate_extrema`: a stationary point that the scan's point ties leaves
    the scan's point).

    Parameters
    ----------
    value, best : float
        The value and the best one, signed so that larger is better.
    size : float
        The quantity's largest magnitude along the run.

    Returns
    -------
    bool
        ``True`` if ``value >= best − EXTREMUM_TIE · max(size, |best|)``.
    """
    return value >= best - EXTREMUM_TIE * max(size, abs(best))


def first_tie(values: np.ndarray, best: float, size: float) -> int:
    """The index of the first of ``values`` (signed so that larger is better, in time order) that ties ``best``
    (:func:`within_tie`), or ``-1`` if none does: where a run's extremum is read, the earliest of its ties."""
    tied = within_tie(np.asarray(values, dtype=float), best, size)
    return int(np.argmax(tied)) if tied.any() else -1


def _quantity(filled: dict[str, np.ndarray] | _ScanTables, quantity: str) -> np.ndarray:
    """``quantity`` of one span's scan (its dict) or of all spans' at once (:class:`_ScanTables`): one ``filled``
    holds (``in``; read by ``[]``), else the contact area ``π a²`` or a mean pressure or shear (the force over the
    area where it is positive, ``nan`` elsewhere), element by element."""
    if quantity in filled:
        return filled[quantity]
    area = np.pi * filled["contact_radius"] ** 2
    if quantity == "contact_area":
        return area
    force = filled["normal_force" if quantity == "mean_pressure" else "tangential_force"]
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(area > 0, force / area, np.nan)


class ExtremumScan(NamedTuple):
    """Every span sampled at :data:`EXTREMUM_GRID` times (s from first contact), with the quantities
    :func:`extremum` reads (the sliding fraction left out); ``matrices``: each quantity's scan reduced to what both
    extremes read of it (:class:`ScanMatrix`), filled as :func:`extremum` asks or at once by :meth:`prepare`
    (``None``: none kept); ``polynomials``: the spans read as polynomials in ``√a``
    (:func:`~.span_polynomials.span_polynomials`; ``None``: none), which :func:`extremum` refines by their
    coefficients."""

    times: list[np.ndarray]
    values: list[dict[str, np.ndarray]]
    matrices: dict[str, "ScanMatrix"] | None = None
    polynomials: SpanPolynomials | None = None

    def prepare(self, quantities: tuple[str, ...]) -> None:
        """Reduce the scan of several quantities at once (:func:`_scan_matrices`: one array for all of them and both
        signs), kept for :func:`extremum`; each value the one a quantity alone gives.

        Parameters
        ----------
        quantities : tuple of str
            Quantities of :data:`EXTREMUM_QUANTITIES`.
        """
        missing = tuple(quantity for quantity in quantities if quantity not in (self.matrices or {}))
        if missing and self.matrices is not None:
            self.matrices.update(_scan_matrices(self, missing))

    def matrix(self, quantity: str) -> "ScanMatrix":
        """``quantity``'s :class:`ScanMatrix`: the one kept, else reduced now (and kept where ``matrices`` is a dict).

        Parameters
        ----------
        quantity : str
            A quantity of :data:`EXTREMUM_QUANTITIES`.

        Returns
        -------
        ScanMatrix
            What both extremes of ``quantity`` read of the scan.
        """
        kept = self.matrices.get(quantity) if self.matrices is not None else None
        if kept is None:
            kept = _scan_matrices(self, (quantity,))[quantity]
            if self.matrices is not None:
                self.matrices[quantity] = kept
        return kept


class ScanMatrix(NamedTuple):
    """One quantity of an :class:`ExtremumScan`, reduced span by span to what :func:`extremum` reads: for the maximum
    (``[0]``: of ``q``) and the minimum (``[1]``: of ``−q``, larger is better) the best scanned value of each span
    (``nan`` where none is finite) and the index of its earliest scan point within :data:`EXTREMUM_TIE` of it; each
    span's largest change between neighbouring points (0 for one point; the same for either sign); the quantity's
    largest magnitude over the run. Python lists: what the loop over the spans reads."""

    best: tuple[list[float], list[float]]
    first: tuple[list[int], list[int]]
    reach: list[float]
    size: float


def scan_spans(solution: PathSolution) -> ExtremumScan:
    """Sample every span for :func:`extremum` (one scan serves every quantity and both extremes): evenly in
    time on a pinned radius, evenly in the radius on a moving one (the variable of its interpolant; the time
    of each radius that of its depth on the branch, which needs no root).

    The grids of all spans are built at once (:func:`_scan_grids`: each branch's depths in one call, the grids as the
    rows of one matrix). The spans of the paraboloid on the half-space that are polynomials (a moving one whose force
    is a closed form, in ``√a``; a pinned one whose force is constant or linear, in time:
    :func:`~.span_polynomials.span_polynomials`): their ``F_x`` and ``F_N`` read at once by Horner's rule over their
    coefficients (:func:`~.span_polynomials.polynomial_values`, to rounding the values of the route of before); every
    other span's kinematics by :func:`~.solution.evaluate_span`, ``F_x`` of all of them by the kinds of their
    interpolants (:func:`_fill_tangential_force`) and ``F_N`` in one call (:func:`_fill_normal_force`), each value the
    one a span alone would give."""
    grids, radii = _scan_grids(solution)
    polynomials = span_polynomials(solution)
    taken = set(polynomials.indices)
    rest = {index: grid for index, grid in enumerate(grids) if index not in taken}
    pinned = _pinned_kinematics(solution, rest) if solution.compressed is None else {}
    values: list = [None] * len(grids)
    for index, grid in rest.items():
        values[index] = pinned[index] if index in pinned else \
            evaluate_span(solution, index, grid, sliding=False, radii=radii[index], normal=False, tangential=False)
    polynomial_scan(solution, polynomials, grids, radii, values)
    _fill_tangential_force(solution, list(range(len(grids))), grids, values)
    _fill_normal_force(solution.model, values)
    return ExtremumScan(grids, values, {}, polynomials)


def _scan_grids(solution: PathSolution) -> tuple[list[np.ndarray], list[np.ndarray | None]]:
    """Each span's scan times (s from first contact) and, on a moving span, the radii there (``None`` elsewhere):
    :data:`EXTREMUM_GRID` points on a span of positive length, its start alone on one of none. A pinned span's times
    evenly spaced (``np.linspace``); a moving span's radii evenly spaced from the radius at its start to that at its
    end (roots of their depths: :meth:`~.branch.Branch.radius`, each depth once, a span's end being the next span's
    start; the roots the solve took, kept in the spans' :attr:`~.span_record.Span.roots`, read there: the same numbers) and
    the time of each radius that of its depth on the branch, made non-decreasing, as :func:`_radius_grid` gives them
    span by span (``tests/models/test_extremum_scan.py`` compares the two)."""
    spans, t_contact = solution.spans, solution.t_contact
    bounds = [(span.t_start - t_contact, span.t_end - t_contact) for span in spans]
    grids: list = [None] * len(spans)
    radii: list = [None] * len(spans)
    moving, ends = [], []  # (the moving spans of positive length, the radii at their ends)
    for regime in (Regime.GROWING, Regime.SHRINKING):
        members = [index for index, span in enumerate(spans) if span.regime is regime]
        if not members:
            continue
        branch, rtol = solution.model.branch(regime), solution.model.tolerances.radius_rtol
        roots: dict = {}  # (this branch's root_key of a depth) -> the radius: the solve's roots, at any of its spans
        for index in members:
            roots.update(spans[index].roots)

        def root(index: int, t: float) -> float:
            depth = max(float(spans[index].segment.d(t_contact + t)), branch.jump_off_depth)
            key = root_key(depth, rtol)
            if key not in roots:  # (the solve's root of this depth where it took one: the same number)
                roots[key] = fold_radius(branch, rtol) \
                    if depth == branch.jump_off_depth and type(branch) is Branch and branch.work != 0.0 \
                    else branch.radius(depth, rtol)
            return roots[key]

        for index in members:
            if bounds[index][1] > bounds[index][0]:
                moving.append(index)
                ends.append([root(index, t) for t in bounds[index]])
            else:  # (a span of no length: its start alone)
                grids[index], radii[index] = np.array([bounds[index][0]]), np.array([root(index, bounds[index][0])])
    taken = set(moving)
    rest = [index for index in range(len(spans)) if grids[index] is None and index not in taken
            and bounds[index][1] > bounds[index][0]]  # (the pinned spans and the approach: their times evenly spaced)
    if moving or rest:  # (the moving spans' radii and the others' times as the rows of one matrix)
        rows = _linspace_rows(np.array([end[0] for end in ends] + [bounds[index][0] for index in rest]),
                              np.array([end[1] for end in ends] + [bounds[index][1] for index in rest]), EXTREMUM_GRID)
        if moving:
            _moving_grids(solution, moving, rows[:len(moving)], grids, radii)
        for index, row in zip(rest, rows[len(moving):]):
            grids[index] = row
    for index in range(len(spans)):
        if grids[index] is None:  # (a span of no length: its start alone)
            grids[index] = np.array([bounds[index][0]])
    return grids, radii


def _moving_grids(solution: PathSolution, members: list[int], matrix: np.ndarray, grids: list, radii: list) -> None:
    """:func:`_scan_grids` of the moving spans ``members`` (of either branch) with their radii as the rows of
    ``matrix``: the depths of each branch's inner radii in one call of its :meth:`~.branch.Branch.depths` (element by
    element: the values of a call per span), the times of all as the rows of one matrix; each row stored in ``grids``
    and ``radii`` at its span's index."""
    spans, t_contact = solution.spans, solution.t_contact
    regimes = [spans[index].regime for index in members]
    depths = np.empty((len(members), matrix.shape[1] - 2))
    for regime in (Regime.GROWING, Regime.SHRINKING):
        rows = [row for row, each in enumerate(regimes) if each is regime]
        if len(rows) == len(members):  # (one branch: every row)
            depths = solution.model.branch(regime).depths(np.ascontiguousarray(matrix[:, 1:-1]).reshape(-1)) \
                .reshape(len(members), -1)
        elif rows:
            depths[rows] = solution.model.branch(regime).depths(matrix[rows, 1:-1].reshape(-1)).reshape(len(rows), -1)
    segments = [spans[index].segment for index in members]
    # (each span's segment's numbers and its ends, s from first contact, as the columns of one array)
    t0, ds, vd, lower, upper = np.array(
        [[segment.t0 for segment in segments], [segment.ds for segment in segments], [segment.vd for segment in segments],
         [spans[index].t_start - t_contact for index in members],
         [spans[index].t_end - t_contact for index in members]], dtype=float)[:, :, None]
    inner = (t0 + (depths - ds) / vd) - t_contact  # (Segment.time_at_depth, row by row)
    times = np.concatenate([lower, np.minimum(np.maximum(inner, lower), upper), upper], axis=1)  # (np.clip)
    np.maximum.accumulate(times, axis=1, out=times)
    for row, index in enumerate(members):
        grids[index], radii[index] = times[row], matrix[row]


def _linspace_rows(start: np.ndarray, stop: np.ndarray, count: int) -> np.ndarray:
    """``np.linspace(start[i], stop[i], count)`` as the rows of one matrix, each row the values ``np.linspace`` gives
    it alone (its own step: ``np.linspace`` of arrays takes the denormal route for every row if any row's step is 0)."""
    delta = stop - start
    positions = np.arange(count, dtype=float)
    step = delta / (count - 1)
    rows = positions[None, :] * step[:, None]
    zero = step == 0
    if zero.any():  # (np.linspace's route for a step of 0: the positions over the divisions, times the difference)
        rows[zero] = (positions / (count - 1))[None, :] * delta[zero][:, None]
    rows += start[:, None]
    rows[:, -1] = stop
    return rows


def _radius_grid(solution: PathSolution, span: Span, lower: float, upper: float,
                 count: int) -> tuple[np.ndarray, np.ndarray]:
    """``count`` radii evenly from the radius at ``lower`` to that at ``upper`` (s from first contact; the
    span's ends, whose radii are roots of their depths) along the span's branch, and their times (in
    ``[lower, upper]``, non-decreasing): a moving span's scan alone (:func:`_scan_grids` builds every span's at once;
    this one its reference in the tests)."""
    branch, rtol = solution.model.branch(span.regime), solution.model.tolerances.radius_rtol
    ends = [branch.radius(max(float(span.segment.d(solution.t_contact + t)), branch.jump_off_depth), rtol)
            for t in (lower, upper)]
    radii = np.linspace(ends[0], ends[1], count)
    inner = span.segment.time_at_depth(branch.depths(radii[1:-1])) - solution.t_contact
    grid = np.concatenate([[lower], np.clip(inner, lower, upper), [upper]]) if count > 1 else np.array([lower])
    return np.maximum.accumulate(grid), radii


def extremum(solution: PathSolution, quantity: str, largest: bool = True,
             scan: ExtremumScan | None = None) -> tuple[float, float]:
    """The largest (or smallest) value of ``quantity`` along the run and the time it is reached
    (s from first contact), from the solution itself, not from samples.

    Each span's quantities are smooth in time; the extremum of a span is at one of its ends or
    inside it. A scan of :data:`EXTREMUM_GRID` points per span (:func:`scan_spans`) brackets it
    (within one grid interval of the best point, at an end too); the spans that can hold the
    extremum (their best scanned value, raised by their largest change between neighbouring scan
    points, reaches the best scanned value of the run) are refined within one grid interval of the
    best point by the roots of the quantity's derivative (:func:`~.stationary.stationary_points`: the
    span's dense output and the branch's closed forms), the means by a bounded Brent search to
    :data:`EXTREMUM_XTOL` of the span's length; a refined point replaces the scanned one where it is better beyond
    the tie (:func:`within_tie`). Of values equal to :data:`EXTREMUM_TIE` (a plateau) the
    earliest time is reported, so that the time does not hang on rounding. The means (``mean_pressure``, ``mean_shear_stress``)
    are taken over the spans in contact.

    Parameters
    ----------
    solution : PathSolution
    quantity : str
        One of :data:`EXTREMUM_QUANTITIES`.
    largest : bool
        ``True`` for the maximum, ``False`` for the minimum.
    scan : ExtremumScan, optional
        :func:`scan_spans` of ``solution``, to share between several calls.

    Returns
    -------
    value : float
        The extremum (in the quantity's SI unit).
    time : float
        The earliest time it is reached (s from first contact).

    Raises
    ------
    ValueError
        A quantity not in :data:`EXTREMUM_QUANTITIES`.
    """
    if quantity not in EXTREMUM_QUANTITIES:
        raise ValueError(f"quantity={shown(quantity)} is not allowed; allowed: {', '.join(EXTREMUM_QUANTITIES)}")
    if quantity == "tangential_force" and solution.compressed is not None:  # the compressed zone's spans hold F_x
        return extremum(solution.compressed, quantity, largest)
    scan = scan_spans(solution) if scan is None else scan
    kept, side = scan.matrix(quantity), 0 if largest else 1
    return _extreme(solution, scan, quantity, 1.0 if largest else -1.0, kept.best[side], kept.first[side], kept)


def _extreme(solution: PathSolution, scan: ExtremumScan, quantity: str, sign: float, best: list[float],
             first: list[int], kept: ScanMatrix) -> tuple[float, float]:
    """:func:`extremum` of ``quantity`` from its reduced scan (each span's ``best`` signed value and ``first`` index of
    ``sign``; ``kept``: its :class:`ScanMatrix`): the spans that can hold it refined, the earliest of the ties."""
    spans = [index for index, value in enumerate(best) if math.isfinite(value)]
    if not spans:
        return math.nan, math.nan
    best_scanned, reach, size = max(best[index] for index in spans), kept.reach, kept.size
    # the radius is monotone on a span: the area's extremes are at the span's ends, which the scan holds
    monotone = quantity in ("contact_radius", "contact_area")
    results = []
    for index in spans:
        times, i, value = scan.times[index], first[index], best[index]
        time = float(times[i])
        if len(times) > 1 and value + reach[index] >= best_scanned and not monotone \
                and not never_stationary(solution, index, quantity):  # (else the scan's point stays)
            time, value = _refined(solution, scan, index, quantity, sign, (i, value), size)
        results.append((time, value))
    best_value = max(value for _, value in results)
    # the earliest time at which the extremum is reached, to rounding of the quantity's size along the run (a
    # plateau such as F_x in full slip, or a quantity that stays at zero, has ties that rounding would pick)
    best_time, best_value = min((time, value) for time, value in results
                                if within_tie(value, best_value, size))
    return best_time, sign * best_value


def _refined(solution: PathSolution, scan: ExtremumScan, index: int, quantity: str, sign: float,
             scanned: tuple[int, float], size: float) -> tuple[float, float]:
    """:func:`extremum`'s refinement of span ``index`` about its best scan point (``scanned``: its index and signed
    value): ``(time, signed value)`` of the stationary point (:func:`~.stationary.stationary_points`, or a bounded
    search for the means) better than it beyond the tie (:func:`within_tie`), else of the scan's point."""
    times, (i, value) = scan.times[index], scanned
    time = float(times[i])
    ends = (max(i - 1, 0), min(i + 1, len(times) - 1))
    radii = scan.values[index]["contact_radius"]
    bracket, radii = (float(times[ends[0]]), float(times[ends[1]])), (float(radii[ends[0]]), float(radii[ends[1]]))
    polynomials = scan.polynomials
    if polynomials is not None and index in polynomials.indices and quantity in ("normal_force", "tangential_force") \
            and polynomials.moving[polynomials.indices.index(index)]:
        points = polynomial_points(solution, index, polynomials, quantity, bracket, radii)
    else:
        points = stationary_points(solution, index, quantity, bracket, radii)
    if points is None:
        points = [_bounded_search(solution, index, quantity, sign, times, i)]
    for found_time, found in points:
        # (better beyond rounding alone, by the rule of ties: a point the scan's ties stays)
        if sign * found > value and not within_tie(value, sign * found, size):
            time, value = found_time, sign * found
    return time, value


def _scan_matrices(scan: ExtremumScan, quantities: tuple[str, ...]) -> dict[str, ScanMatrix]:
    """The :class:`ScanMatrix` of each of ``quantities``, from their scans as one array (quantity, span, point; each
    span's row padded with ``nan``) and its negative (the minimum's, exact): each row's largest magnitude and largest
    change between neighbouring points (0 for one point; ``|Δ(−q)| = |Δq|`` exactly, so both extremes share it), its
    best value of either sign and that value's earliest tie, and the largest magnitude over the run; every reduction
    element by element, so each value is the one a matrix per quantity and sign gives."""
    lengths = [len(times) for times in scan.times]
    width = max(lengths)
    tables = _ScanTables(scan.values, lengths, width)
    table = np.empty((len(quantities), len(scan.times), width))
    for k, quantity in enumerate(quantities):
        table[k] = _quantity(tables, quantity)
    with np.errstate(invalid="ignore"):
        largest = np.fmax.reduce(np.abs(table), axis=2)
        # (np.diff's subtraction of neighbours, and np.stack's copies of q and −q, written out: the same values)
        reach = np.fmax(np.fmax.reduce(np.abs(table[..., 1:] - table[..., :-1]), axis=2), 0.0) if width > 1 \
            else np.zeros(largest.shape)
        signed = np.empty((2, *table.shape))  # (the maximum's, the minimum's)
        signed[0] = table
        np.negative(table, out=signed[1])
        best = np.fmax.reduce(signed, axis=3)
        first = np.argmax(signed >= (best - EXTREMUM_TIE * largest)[..., None], axis=3)  # earliest tie
    sizes = np.fmax.reduce(np.where(np.isfinite(largest), largest, 0.0), axis=1, initial=0.0)  # (largest >= 0)
    best, first, reach = best.tolist(), first.tolist(), reach.tolist()
    return {quantity: ScanMatrix((best[0][k], best[1][k]), (first[0][k], first[1][k]), reach[k], float(sizes[k]))
            for k, quantity in enumerate(quantities)}


class _ScanTables:
    """The quantities every span's scan holds (``F_N``, ``F_x``, the radius, ...), each as a table (span, point) of
    ``width`` points, each row padded with ``nan``, made when first asked: read by :func:`_quantity` as it reads one
    span's scan (``in``: every span's scan holds it; ``[]``: its table), for all spans at once (its operations
    element by element, so each value is the one a span alone gives, and ``nan`` where padded). Not a dict: the
    tables made so far are not what it holds.

    Parameters
    ----------
    values : list of dict
        Each span's scan: its quantities by name.
    lengths : list of int
        Each span's points.
    width : int
        The longest span's points (the tables' width).
    """

    def __init__(self, values: list[dict[str, np.ndarray]], lengths: list[int], width: int):
        self.values, self.lengths, self.width = values, lengths, width
        self._made: dict[str, np.ndarray] = {}

    def __contains__(self, name: str) -> bool:
        return all(name in filled for filled in self.values)

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self._made:
            if all(length == self.width for length in self.lengths):  # (every span scanned at the grid: no padding)
                table = np.array([filled[name] for filled in self.values], dtype=float)
            else:
                table = np.full((len(self.values), self.width), np.nan)
                for row, filled in enumerate(self.values):
                    table[row, :self.lengths[row]] = filled[name]
            self._made[name] = table
        return self._made[name]


def _bounded_search(solution: PathSolution, index: int, quantity: str, sign: float, times: np.ndarray,
                    i: int) -> tuple[float, float]:
    """:func:`extremum`'s refinement of a quantity without a derivative route (:func:`~.stationary.stationary_points`:
    the means): a bounded Brent search of the time around scan point ``i``, to :data:`EXTREMUM_XTOL` of the span.
    Searched in the time from the bracket's start: the bounded search adds sqrt(eps) of the variable's size to its
    tolerance, 0.26 s at t = 1.7e7 s (a path at 1e-3°), where a force minimum lasts 0.03 s."""
    origin = float(times[max(i - 1, 0)])

    def objective(s: float) -> float:
        return -sign * _scalar_quantity(solution, index, origin + s, quantity)

    bracket = (0.0, float(times[min(i + 1, len(times) - 1)]) - origin)
    refined = optimize.minimize_scalar(objective, bounds=bracket, method="bounded",
                                       options={"xatol": EXTREMUM_XTOL * (times[-1] - times[0])})
    return origin + float(refined.x), -sign * float(refined.fun)


def _scalar_quantity(solution: PathSolution, index: int, time: float, quantity: str) -> float:
    """One quantity of span ``index`` at one time (s from first contact), with the scalar radius roots:
    :func:`extremum`'s objective (the same values as :func:`~.solution.evaluate_span`, to the root's accuracy)."""
    span, model = solution.spans[index], solution.model
    if span.regime is Regime.NONE:
        return 0.0 if quantity in ("normal_force", "tangential_force") else math.nan
    d = span.segment.d(solution.t_contact + time)
    rtol = model.tolerances.radius_rtol
    if span.regime is Regime.GROWING:
        a = model.grow.radius(max(d, model.grow.jump_off_depth), rtol)
    elif span.regime is Regime.SHRINKING:
        a = model.shrink.radius(max(d, model.shrink.jump_off_depth), rtol)
    else:
        a = span.pinned_radius
    if solution.compressed is not None:
        force = float(_compressed_zone(solution.compressed, np.array([time]), np.array([a]))[0][0])
    elif span.interpolant is None:
        force = span.force
    else:
        force = float(span.interpolant(span_variable(span, a / span.scale if span.variable is Variable.RADIUS
                                                     else solution.t_contact + time))[0])
    normal = float(model.normal_force(d, a))
    area = math.pi * a * a
    values = {"normal_force": normal, "tangential_force": force, "contact_radius": a, "contact_area": area,
              "mean_pressure": normal / area if area > 0 else math.nan,
              "mean_shear_stress": force / area if area > 0 else math.nan}
    return values[quantity]
