"""The continuum method under a rate-dependent adhesion law: each path's run as ``simulate`` fills it.

:func:`run_rate_continuum` solves each path by :func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts` (the
radius an ODE state, the springs' shifts on top under ``τ0``'s cap; where the path's ``x`` turns back every anchor a
play operator of both levels, :class:`~mdr_events.models.continuum.rate_play.RatePlay`) and fills
what :func:`~mdr_events.models.continuum.solve.run_continuum` fills for the paper's law: the quantities of
:data:`~mdr_events.models.continuum.solution.EVALUATED_QUANTITIES` on a common grid of times from each path's first
contact, the event log and the extrema of ``F_N``, ``F_x`` and the contact area.

The log holds the edge's events (first contact and re-contact, growth resuming, detachment starting, the contact's
end), the path's corners in contact, and the springs' (the first contact's slip onset, full slip, a re-stick where the
level ``x − K a`` turns back and a slip onset again where it returns to its maximum; direction: the cap, the way
``x`` goes). Where the edge stops between pieces no event is logged (the paper's law has no such event); the switches
inside a step (full slip, a re-stick) are found on the springs' extent alone (:meth:`RateShifts.slip_radius
<mdr_events.models.continuum.rate_shifts.RateShifts.slip_radius>`, no quadrature). A run ends where its contact ends
for good (the samples after it ``nan``, the first one on the path's segment showing the contact gone) or at the path's
end. The extrema are found on the edge's solver steps (every step's ends and :data:`EXTREMUM_PROBES` points inside)
and refined between the neighbours of the largest or least by the stationary points of each interval's Chebyshev
interpolant of degree :data:`EXTREMUM_DEGREE` (:func:`~mdr_events.models.continuum.stationary.derivative_roots`, as
the paper's spans refine theirs): the quantities are smooth within a step. A stationary point better than the scan's
point by no more than rounding (:func:`~mdr_events.models.continuum.span_extrema.within_tie`:
:data:`~mdr_events.models.continuum.span_extrema.EXTREMUM_TIE` of the quantity's largest magnitude along the run) leaves
the scan's point, as the paper's extremum keeps the earliest of its ties by the same rule (a plateau such as ``F_x``
while the springs stick).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.layer import Layer
from mdr_events.limits import Limits
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters

from .extrema import EXTREMA_KINDS, EXTREMA_QUANTITIES, VALUE_AFTER_CONTACT, extremum_names
from .rate_edge import EdgeEventKind
from .rate_play import RatePlay
from .rate_shifts import RateShifts, solve_rate_shifts
from .time_grid import sample_times
from .span_extrema import first_tie, within_tie
from .solve import BYTES_PER_SAMPLE
from .state import Event, EventKind
from .stationary import chebyshev_nodes, derivative_roots
from .tolerances import Tolerances, check_output

__all__ = ["run_rate_continuum", "run_end", "check_rate_layer", "rate_quantities", "rate_events", "rate_extrema", "Scan", "scan_run",
           "scan_times", "evaluate_run",
           "EXTREMUM_PROBES", "EXTREMUM_DEGREE", "SWITCH_XTOL", "SWITCH_POINTS", "RUN_METHOD"]

#: Points inside each of the edge's solver steps at which the scan looks (besides the steps' ends and the level's
#: candidates): none, since a quantity's extremum inside a step lies between the scan's neighbours of its best, which
#: the refinement searches (the quantities are smooth within a step; their kinks, at the path's corners and the edge's
#: events, are steps' ends).
EXTREMUM_PROBES = 0
#: The degree of the interpolant whose stationary points :func:`rate_extrema` takes beside the scan's best
#: (``_stationary``): on each interval between the scan's times the radius is one step of the edge's dense output,
#: a polynomial of degree at most 12 (LSODA's Adams order; Radau's 3), which these 16 points read exactly; ``F_N``
#: and ``F_x`` are smooth functions of it and of the path's depth and ``x``, linear there.
EXTREMUM_DEGREE = 15
#: The bisection of a switch (full slip, a re-stick inside a step) ends at this share of the clock (the edge's ODE
#: resolves its times to about 1e-10 of themselves).
SWITCH_XTOL = 1e-13
#: The points a switch's bracket is cut into at once.
SWITCH_POINTS = 64
#: The edge's ``solve_ivp`` method in ``simulate``: LSODA, within 2e-9 of Radau's radius (the reference of
#: :func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts`) at a tenth to a twentieth of its time.
RUN_METHOD = "LSODA"
#: The edge's events and the kinds they are logged as.
_EDGE_KINDS = {EdgeEventKind.FIRST_CONTACT: EventKind.FIRST_CONTACT, EdgeEventKind.RE_CONTACT: EventKind.RE_CONTACT,
               EdgeEventKind.GROWTH_STARTS: EventKind.GROWTH_RESUMES,
               EdgeEventKind.RECEDING_STARTS: EventKind.DETACHMENT_STARTS,
               EdgeEventKind.CONTACT_ENDS: EventKind.CONTACT_ENDS}


def run_end(shifts: RateShifts) -> tuple[float, bool]:
    """The run's end on the path's clock and whether the contact ended there (for good: no contact after it).

    Parameters
    ----------
    shifts : RateShifts
        The run.

    Returns
    -------
    tuple of float and bool
        The end (s, path clock) and whether the contact ended there.
    """
    last = shifts.edge.events[-1]
    if last.kind is EdgeEventKind.CONTACT_ENDS:
        return float(last.time), True
    return float(shifts.path.duration), False


def rate_quantities(shifts: RateShifts, times: np.ndarray,
                    evaluated: tuple[np.ndarray, np.ndarray] | None = None) -> dict[str, np.ndarray]:
    """The quantities of :data:`~mdr_events.models.continuum.solution.EVALUATED_QUANTITIES` at ``times`` (s from the
    path's first contact); ``nan`` after the run's end but the first sample on the path once the contact ended.

    Parameters
    ----------
    shifts : RateShifts
        The run.
    times : numpy.ndarray
        The times (s from the first contact), one-dimensional.
    evaluated : tuple of numpy.ndarray, optional
        ``F_x`` and the sliding springs' extent at ``times`` where they are evaluated already (:func:`evaluate_run`).

    Returns
    -------
    dict of str to numpy.ndarray
        Depth, ``x``, ``F_N``, ``F_x``, the radius and the sliding fraction (``nan`` out of contact).
    """
    path = shifts.path
    clock = np.asarray(times, dtype=float) + path.first_contact_time()
    end, ended = run_end(shifts)
    x, depth = path.position(clock)
    radius = shifts._radius(clock)
    force, sliding = shifts._evaluate(clock) if evaluated is None else evaluated
    normal = shifts.normal_force(np.minimum(clock, path.duration))
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.where(radius > 0.0, np.minimum(sliding / np.where(radius > 0.0, radius, 1.0), 1.0), np.nan)
    out = {"indentation_depth": depth, "tangential_displacement": x, "normal_force": normal,
           "tangential_force": force, "contact_radius": radius, "sliding_fraction": share}
    after = np.flatnonzero(clock > end)
    for name in out:
        out[name] = np.asarray(out[name], dtype=float).copy()
        out[name][after] = np.nan
    if ended and after.size and clock[after[0]] <= path.duration:  # (the contact shown gone, as the paper's run)
        first = after[0]
        out["indentation_depth"][first], out["tangential_displacement"][first] = depth[first], x[first]
        for name in ("normal_force", "tangential_force", "contact_radius"):
            out[name][first] = 0.0
    return out


class Scan(NamedTuple):
    """A run's quantities on the times where its events and extrema are looked for: the level's candidates (every
    knot of the edge's steps, each step's interior maximum of ``x − K a``) and :data:`EXTREMUM_PROBES` points inside
    each step, from the first contact to the run's end (path clock).

    Parameters
    ----------
    times : numpy.ndarray
        The times (s, path clock), increasing.
    force, extent, radius, level, normal : numpy.ndarray
        ``F_x``, the springs at the cap's extent, the radius, ``x − K a`` (in ``σ``'s coordinates) and ``F_N`` there.
    """

    times: np.ndarray
    force: np.ndarray
    extent: np.ndarray
    radius: np.ndarray
    level: np.ndarray
    normal: np.ndarray


def scan_times(shifts: RateShifts) -> np.ndarray:
    """The times of the run's :class:`Scan` (path clock, increasing): the level's candidates and the edge's steps, with
    :data:`EXTREMUM_PROBES` points inside each, from the first contact to the run's end.

    Parameters
    ----------
    shifts : RateShifts
        The run.

    Returns
    -------
    numpy.ndarray
        The times (s, path clock).
    """
    start = shifts.path.first_contact_time()
    end, _ = run_end(shifts)
    knots = np.unique(np.concatenate([[view.t0, view.t1] for view in shifts.views]
                                     + [getattr(view.solution, "ts", []) for view in shifts.views]))
    knots = np.unique(np.concatenate([[start], knots[(knots >= start) & (knots <= end)]]))  # (radius 0 at the start)
    share = np.arange(EXTREMUM_PROBES + 1) / (EXTREMUM_PROBES + 1)
    stamps = shifts._candidates[0]
    return np.unique(np.concatenate([(knots[:-1, None] + np.diff(knots)[:, None] * share[None, :]).ravel(),
                                     knots[-1:], stamps[(stamps >= start) & (stamps <= end)]]))


def scan_run(shifts: RateShifts, times: np.ndarray | None = None,
             evaluated: tuple[np.ndarray, np.ndarray] | None = None) -> Scan:
    """The run's :class:`Scan` (one evaluation for the events and the extrema).

    Parameters
    ----------
    shifts : RateShifts
        The run.
    times : numpy.ndarray, optional
        Its :func:`scan_times`, where they are found already.
    evaluated : tuple of numpy.ndarray, optional
        ``F_x`` and the sliding springs' extent at ``times`` where they are evaluated already (:func:`evaluate_run`).

    Returns
    -------
    Scan
        The quantities on the scan's times.
    """
    times = scan_times(shifts) if times is None else times
    force, extent = shifts._evaluate(times) if evaluated is None else evaluated
    return Scan(times, force, extent, shifts._radius(times), shifts._level(times),
                shifts.normal_force(times))


def evaluate_run(shifts: RateShifts, times: np.ndarray) -> tuple[dict[str, np.ndarray], Scan]:
    """:func:`rate_quantities` at ``times`` and :func:`scan_run`, their ``F_x`` and sliding springs evaluated in one
    pass over the run's pieces where the run takes them together (``_evaluate_each``: each time's values its own, the
    same as asked alone).

    Parameters
    ----------
    shifts : RateShifts
        The run.
    times : numpy.ndarray
        The output times (s from the first contact), one-dimensional.

    Returns
    -------
    tuple of dict and Scan
        The quantities at ``times`` and the scan.
    """
    stamps = scan_times(shifts)
    at_samples, at_scan = shifts._evaluate_each(np.asarray(times, dtype=float) + shifts.path.first_contact_time(),
                                                stamps)
    return rate_quantities(shifts, times, at_samples), scan_run(shifts, stamps, at_scan)


def _at_cap(shifts: RateShifts, clock: np.ndarray) -> np.ndarray:
    return shifts.slip_radius(clock) > 0.0


def _full(shifts: RateShifts, clock: np.ndarray) -> np.ndarray:
    radius = shifts._radius(clock)
    return (shifts.slip_radius(clock) >= radius) & (radius > 0.0)


def _switch(predicate, low: float, high: float) -> float:
    """The time in ``[low, high]`` where ``predicate`` (vectorised; false at ``low``, true at ``high``) turns true: the
    bracket narrowed :data:`SWITCH_POINTS` times at once until it is :data:`SWITCH_XTOL` of the clock."""
    while high - low > SWITCH_XTOL * abs(high):
        grid = np.linspace(low, high, SWITCH_POINTS)
        inner = predicate(grid[1:-1])
        first = int(np.argmax(inner)) + 1 if np.any(inner) else SWITCH_POINTS - 1
        low, high = grid[first - 1], grid[first]
    return float(high)


def _play_events(play: RatePlay, scan: Scan) -> list[tuple[float, EventKind, int]]:
    """The springs' events along a path whose ``x`` turns back (path clock, direction): where springs come to a cap
    (slip onset), all of them are at one (full slip, once until they stick again) and none is any more (re-stick),
    each found between the scan's samples by :func:`_switch`; the direction is the cap's, +1 the lower one
    ``x − K a`` (pushing towards ``+x``). Samples at opposite caps have a stick between them (the window is ``2 K a``
    wide): its re-stick and the next onset are both found there."""
    lower, upper = play.sliding_sides(scan.times)
    side = np.where(lower >= upper, 1, -1)
    sliding, full = scan.extent > 0.0, (scan.extent >= scan.radius) & (scan.radius > 0.0)
    stamps, out, is_full = scan.times, [], False
    changed = (sliding[1:] != sliding[:-1]) | (full[1:] & ~full[:-1]) | (sliding[1:] & sliding[:-1]
                                                                         & (side[1:] != side[:-1]))
    for index in np.flatnonzero(changed) + 1:
        before, after = stamps[index - 1], stamps[index]
        turned = side[index] != side[index - 1]
        if sliding[index - 1] and (not sliding[index] or turned):
            before = _switch(lambda t: ~_at_cap(play, t), before, after)
            out.append((before, EventKind.RE_STICK, int(side[index - 1])))
            is_full = False
        if sliding[index] and (not sliding[index - 1] or turned):
            before = _switch(lambda t: _at_cap(play, t), before, after)
            out.append((before, EventKind.SLIP_ONSET, int(side[index])))
        if full[index] and (not full[index - 1] or turned) and not is_full:
            out.append((_switch(lambda t: _full(play, t), before, after), EventKind.FULL_SLIP, int(side[index])))
            is_full = True
    return out


def _reversals(path: Path, start: float, end: float, inside) -> list[tuple[float, EventKind, int]]:
    """Where the path's ``x`` turns back in contact (path clock, the new way), as the paper's run logs them."""
    out, heading = [], 0.0
    for corner, step in zip(path.corner_times[:-1], np.diff(path.waypoints[:, 0])):
        if step != 0.0:
            if heading and math.copysign(1.0, step) != heading and start < corner < end and inside(corner):
                out.append((float(corner), EventKind.TANGENTIAL_REVERSAL, int(math.copysign(1.0, step))))
            heading = math.copysign(1.0, step)
    return out


def _slip_events(shifts: RateShifts, scan: Scan) -> list[tuple[float, EventKind, int]]:
    """The springs' events (path clock, direction ``σ``): onsets, full slip and re-sticks, on the scan (module
    docstring): the springs are at the cap where the level equals its running maximum."""
    stamps, values = scan.times, scan.level
    running = np.maximum.accumulate(values)
    sliding, full = scan.extent > 0.0, (scan.extent >= scan.radius) & (scan.radius > 0.0)
    out = []
    onset = shifts.slip_onset_time()
    if math.isfinite(onset) and onset <= stamps[-1]:
        out.append((onset, EventKind.SLIP_ONSET))
    for index in np.flatnonzero((sliding[1:] != sliding[:-1]) | (full[1:] & ~full[:-1])) + 1:
        before, after = stamps[index - 1], stamps[index]
        if sliding[index - 1] and not sliding[index]:
            out.append((before if values[index - 1] >= running[index - 1] else _switch(
                lambda t: ~_at_cap(shifts, t), before, after), EventKind.RE_STICK))
        elif sliding[index] and not sliding[index - 1] and before > onset:
            held = running[index - 1]
            level = lambda t: float(shifts._level(np.array([t]))[0]) - held  # noqa: E731
            out.append((brentq(level, before, after) if level(before) < 0.0 < level(after) else after,
                        EventKind.SLIP_ONSET))
        if full[index] and not full[index - 1]:
            out.append((_switch(lambda t: _full(shifts, t), before, after), EventKind.FULL_SLIP))
    return [(time, kind, int(shifts.sign)) for time, kind in out]


#: The springs' events of a run by the type of its shifts: the closed form of a monotone ``x`` and the play of both
#: levels.
SLIP_EVENTS = {RateShifts: _slip_events, RatePlay: _play_events}


def rate_events(shifts: RateShifts, scan: Scan) -> list[Event]:
    """The run's event log (module docstring), times in s from the path's first contact.

    Parameters
    ----------
    shifts : RateShifts
        The run.
    scan : Scan
        Its quantities on the scan's times (:func:`scan_run`).

    Returns
    -------
    list of Event
        In time order.
    """
    path, start = shifts.path, shifts.path.first_contact_time()
    end, _ = run_end(shifts)
    timed = [(event.time, _EDGE_KINDS[event.kind], 0) for event in shifts.edge.events if event.kind in _EDGE_KINDS]
    corners = path.corner_times[1:-1]
    timed += [(float(t), EventKind.CORNER, 0) for t in corners
              if start < t < end and shifts._radius(np.array([t]))[0] > 0]
    timed += _reversals(path, start, end, lambda t: shifts._radius(np.array([t]))[0] > 0)
    timed += SLIP_EVENTS[type(shifts)](shifts, scan)
    log = []
    for clock, kind, direction in sorted(timed, key=lambda item: item[0]):
        x, depth = (float(value) for value in path.position(clock))
        log.append(Event(float(clock - start), kind, depth, float(shifts._radius(np.array([clock]))[0]), x, direction))
    return log


def _quantity(shifts: RateShifts, name: str, clock: np.ndarray) -> np.ndarray:
    if name == "normal_force":
        return shifts.normal_force(clock)
    if name == "tangential_force":
        return shifts._evaluate(clock)[0]
    return math.pi * shifts._radius(clock) ** 2


def _stationary(shifts: RateShifts, name: str, sign: float, ends: np.ndarray) -> tuple[float, float]:
    """The least of ``sign`` times quantity ``name`` at its stationary points between the scan's three times ``ends``
    (path clock; each of the two intervals within one solver step and one segment of the path, where the quantity is
    smooth but for a slip onset inside, where the interpolant is rougher and the point found only counts where the
    quantity there beats the scan's best): the roots of the derivative of its interpolant at :data:`EXTREMUM_DEGREE` + 1 Chebyshev points of each
    interval (:func:`~.stationary.derivative_roots`, as the paper's spans refine theirs), the quantity evaluated there;
    ``(nan, nan)`` where neither interval has one (the extremum is the scan's point; an interval with a value that is
    not finite has none)."""
    nodes = chebyshev_nodes(EXTREMUM_DEGREE)
    centres, halves = 0.5 * (ends[:-1] + ends[1:]), 0.5 * np.diff(ends)
    values = _quantity(shifts, name, (centres[:, None] + halves[:, None] * nodes).ravel()).reshape(len(halves), -1)
    roots = [centre + half * root for centre, half, row in zip(centres.tolist(), halves.tolist(), values)
             if np.all(np.isfinite(row)) for root in derivative_roots(row, EXTREMUM_DEGREE) if -1.0 <= root <= 1.0]
    if not roots:
        return math.nan, math.nan
    times = np.clip(np.array(roots), ends[0], ends[-1])
    found = _quantity(shifts, name, times)
    best = int(np.argmin(sign * found))
    return float(times[best]), float(found[best])


def rate_extrema(shifts: RateShifts, scan: Scan) -> dict[str, float]:
    """The largest and least ``F_N``, ``F_x`` and contact area of the run and their times (s from the first contact),
    as :func:`~mdr_events.models.continuum.extrema.solution_extrema` gives them for the paper's law: the scan's best,
    refined between its neighbours where it lies inside a step (not at the scan's ends) by the stationary points of
    ``_stationary`` where one is better beyond rounding (module docstring).

    Parameters
    ----------
    shifts : RateShifts
        The run.
    scan : Scan
        Its quantities on the scan's times (:func:`scan_run`).

    Returns
    -------
    dict of str to float
        ``q_max``, ``q_max_time``, ``q_min``, ``q_min_time`` of each quantity.
    """
    start = shifts.path.first_contact_time()
    end, ended = run_end(shifts)
    grid = scan.times
    scanned = {"normal_force": scan.normal, "tangential_force": scan.force, "contact_area": math.pi * scan.radius ** 2}
    out = {}
    for name in EXTREMA_QUANTITIES:
        values = scanned[name]
        size = float(np.fmax.reduce(np.abs(values), initial=0.0))  # (the quantity's largest magnitude: its rounding)
        for kind, largest in EXTREMA_KINDS.items():
            sign = -1.0 if largest else 1.0
            at = _earliest_tie(values, sign, size)
            time, value = float(grid[at]), float(values[at])
            if 0 < at < len(grid) - 1:
                found_time, found = _stationary(shifts, name, sign, grid[at - 1:at + 2])
                # (better beyond rounding alone: on a plateau the scan's point stays, as the paper's extremum keeps
                # the earliest of its ties, by the same rule)
                if sign * found < sign * value and not within_tie(-sign * value, -sign * found, size):
                    time, value = found_time, found
            if ended and sign * VALUE_AFTER_CONTACT < sign * value:
                time, value = end, VALUE_AFTER_CONTACT
            value_name, time_name = extremum_names(name, kind)
            out[value_name], out[time_name] = value, time - start
    return out


def _earliest_tie(values: np.ndarray, sign: float, size: float) -> int:
    """The index of the earliest scanned value that ties the scan's best (:func:`~.span_extrema.within_tie`), as the
    paper's law keeps the earliest of its ties: a plateau (``F_x`` held in stick after a corner) is read at its start,
    not at the sample its rounding happens to raise (round 29: the time of ``F_x``'s largest moved by 4e-4 of the
    run under a time scaling of the speeds and ``v_ref``, by 0.28 under a stress scaling)."""
    best = -sign * float(values[int(np.argmin(sign * values))])
    return first_tie(-sign * values, best, size)


def check_rate_layer(layer: Layer) -> None:
    """Refuse a layer of finite thickness under the rate-dependent law in the continuum: the edge's ODE is Heß's rule
    on the half-space (``Γ = E* (g − d)² / (2π a)``), which a layer's compliance ``K(a)`` changes.

    Parameters
    ----------
    layer : Layer
        The contact's layer.

    Raises
    ------
    ValueError
        A layer of finite thickness.
    """
    if not layer.is_half_space:
        raise ValueError(f"layer={layer!r} is not allowed with a rate-dependent law in the continuum; allowed: the "
                         "half-space (the edge's ODE is Heß's rule on the half-space; a layer's springs take the "
                         "rate-independent Adhesion)")


def run_rate_continuum(params: Parameters, paths: list[Path], times: np.ndarray | int, tolerances: Tolerances,
                       limits: Limits, profile: SimulatedProfile, friction: FrictionLaw,
                       law: RateDependentAdhesion) -> dict:
    """Solve every path under ``law`` and fill a common time grid (module docstring), as ``run_continuum`` does.

    Parameters
    ----------
    params : Parameters
        The material, ``τ0`` and the works of adhesion at rest (the law's).
    paths : list of Path
        One path per case.
    times : numpy.ndarray or int
        The output times (s from first contact), or the number of samples to the end of the longest run.
    tolerances : Tolerances
        Its ``rtol`` is the edge's ODE tolerance (by :data:`RUN_METHOD`).
    limits : Limits
        The resource limits the output is checked against first.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter.
    friction : FrictionLaw
        ``"tau0"``.
    law : RateDependentAdhesion
        The adhesion law.

    Returns
    -------
    dict
        The quantities stacked to (n_cases, n_time), ``time``, ``events`` (one list per case), ``extrema`` (one
        dict per case) and ``runs`` (each path's :class:`~mdr_events.models.continuum.rate_shifts.RateShifts`).

    Raises
    ------
    ValueError
        Output beyond ``limits``, or what :func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts`
        refuses.
    """
    samples = times if isinstance(times, int) else None
    n_time = samples if samples is not None else len(times)
    check_output(limits, len(paths), n_time, BYTES_PER_SAMPLE)
    runs = [solve_rate_shifts(params, path, law, profile=profile, friction=friction, rtol=tolerances.rtol,
                              method=RUN_METHOD) for path in paths]
    if samples is not None:
        times = sample_times([run_end(run)[0] - run.path.first_contact_time() for run in runs],
                             [run.path.duration - run.path.first_contact_time() for run in runs], samples)
    times = np.asarray(times, dtype=float)
    per_case, scans = zip(*(evaluate_run(run, times) for run in runs))
    out = {name: np.stack([case[name] for case in per_case]) for name in per_case[0]}
    out.update(time=times, events=[rate_events(run, scan) for run, scan in zip(runs, scans)],
               extrema=[rate_extrema(run, scan) for run, scan in zip(runs, scans)], runs=runs)
    return out
