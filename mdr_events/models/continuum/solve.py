"""``solve_path``: the hybrid automaton's loop, plan → integrate → transition → log.

Each pass plans a span in closed form (:func:`~.plan.plan_span`), integrates the tangential force
over it up to its end or the first slip event (:func:`~.span.integrate_span`), and applies the
transition the plan or the events call for (the functions below; the slip transitions are the table
of :mod:`~.state`), logging the events. Path corners start a new plan.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.parameters import Parameters
from mdr_events.models.paths import Path
from .anchors import AnchorMap, Piece
from .model import ContinuumModel, Segment, kinematics
from .plan import Action, SpanPlan, plan_span
from .solution import PathSolution, evaluate
from .span import Span, SpanOutcome, integrate_span
from .state import CONTACT_ENDING, ContactState, Event, EventKind, Regime, Slip, next_slip
from .tolerances import MAX_RESTARTS, Tolerances


def solve_path(params: Parameters, path: Path, tolerances: Tolerances = Tolerances()) -> PathSolution:
    """Integrate the continuum model along ``path`` (see :mod:`mdr_events.models.continuum`)."""
    model = ContinuumModel(params, tolerances)
    segments, mirrored = kinematics(path)
    solution = PathSolution(model, mirrored=mirrored, t_contact=path.first_contact_time())
    state = ContactState(t=solution.t_contact, anchors=AnchorMap(model.grow, tolerances.radius_rtol))
    for index, segment in enumerate(segments):
        state.t = max(segment.t0, solution.t_contact)
        if not state.running or state.t >= segment.t1:
            continue
        guard = RestartGuard()
        while state.running and state.t < segment.t1:
            guard.check(state)
            plan = plan_span(model, state, segment)
            for kind, t, radius in advance(model, state, plan, segment, solution):
                log(solution, segment, kind, t, radius)
        if state.running and index < len(segments) - 1:
            log(solution, segment, EventKind.CORNER, segment.t1, state.radius)
    if state.running:
        log(solution, segments[-1], EventKind.PATH_END, segments[-1].t1, state.radius)
    solution.end_time = (solution.spans[-1].t_end if solution.spans else solution.t_contact) - solution.t_contact
    return solution


class RestartGuard:
    """Counts passes that do not advance in time; too many mean the solver is stuck."""

    def __init__(self) -> None:
        self.stalled, self.last = 0, -math.inf

    def check(self, state: ContactState) -> None:
        self.stalled = self.stalled + 1 if state.t <= self.last else 0
        if self.stalled > MAX_RESTARTS:
            raise RuntimeError(f"the continuum method made no progress at t = {state.t!r} s after {MAX_RESTARTS} "
                               f"event restarts (slip state {state.slip.value}); please report the parameters and path")
        self.last = state.t


def log(solution: PathSolution, segment: Segment, kind: EventKind, t: float, radius: float) -> None:
    """Append an event at path time ``t`` (logged from first contact, ``x`` in the path's own sign)."""
    solution.events.append(Event(t - solution.t_contact, kind, segment.d(t), radius, solution.sign * segment.x(t)))


#: What :func:`advance` reports: events to log as ``(kind, path time, radius)``.
Logged = list[tuple[EventKind, float, float]]


def advance(model: ContinuumModel, state: ContactState, plan: SpanPlan, segment: Segment,
            solution: PathSolution) -> Logged:
    """Carry out ``plan``: the transition at its start, the span (appended to ``solution``), and the
    transition at its end."""
    if plan.action is Action.TOUCH:
        return touch(model, state, plan, segment)
    if plan.action is Action.APPROACH:
        solution.spans.append(Span(plan.t_start, plan.t_end, segment, Regime.NONE))
        state.t = plan.t_end
        return []
    if plan.action is Action.COME_OFF:
        solution.spans.append(Span(plan.t_start, plan.t_start, segment, Regime.PINNED, pinned_radius=plan.radius,
                                   force=plan.force))
        logged = [(EventKind.PULL_OFF, plan.t_start, plan.radius)]
        end_contact(state)
        return logged
    logged = enter(model, state, plan, segment)
    span = Span(plan.t_start, plan.t_end, segment, plan.regime, pinned_radius=plan.radius)
    outcome = integrate_span(model, state.anchors, span, state.slip, plan.force)
    span.t_end = outcome.t_stop
    solution.spans.append(span)
    radius = radius_at(model, span, outcome.t_stop)
    if span.regime is Regime.GROWING:
        state.anchors.close(radius)
    span.anchors = state.anchors.copy()
    if outcome.fired:
        return logged + slip_transition(model, state, outcome, radius, segment.x(outcome.t_stop))
    return logged + regime_ends(model, state, plan, outcome, radius)


def touch(model: ContinuumModel, state: ContactState, plan: SpanPlan, segment: Segment) -> Logged:
    """First contact: the springs under the jump-in radius attach at the indenter's position."""
    state.anchors.reset()
    state.anchors.extend(0.0, Piece(0.0, plan.radius, segment.x(plan.t_start)))
    state.in_contact, state.radius, state.force, state.detaching = True, plan.radius, 0.0, False
    # τ0 = 0 (the plan then also logs onset and full slip): every spring slides from the start
    state.slip = Slip.FULL if EventKind.FULL_SLIP in plan.entry_events else Slip.STICK
    return [(kind, plan.t_start, plan.radius) for kind in plan.entry_events]


def enter(model: ContinuumModel, state: ContactState, plan: SpanPlan, segment: Segment) -> Logged:
    """The start of a span in contact: new springs stick (growth; springs may jump in), detachment may
    start at once, the radius may drop onto the Δγ1 branch."""
    logged = [(kind, plan.t_start, state.radius) for kind in plan.entry_events]
    if plan.regime is Regime.GROWING:
        if plan.jumped_from is not None and state.slip is not Slip.STICK:
            # the cap jumps up with the radius: the springs sliding at ū(a_before) now carry less than the
            # cap and stick again, anchored where their shift is ū(a_before)
            before = plan.jumped_from
            level = segment.x(plan.t_start) - model.K * before
            if state.slip is Slip.FULL:
                state.anchors.restick(before, level)
            else:
                state.anchors.restick_slip_zone(level, before)
            state.slip = Slip.STICK
        if state.slip is Slip.FULL:
            state.slip = Slip.PARTIAL  # the springs attaching now stick
        for piece in plan.growth:
            state.anchors.extend(piece.start, piece)
    state.detaching = plan.regime is Regime.SHRINKING
    state.radius, state.force = plan.radius, plan.force
    return logged


def slip_transition(model: ContinuumModel, state: ContactState, outcome: SpanOutcome, radius: float,
                    x: float) -> Logged:
    """Slip events stopped the span (at radius ``radius``, indenter at ``x``): the next slip state (the
    table of :mod:`.state`) and its effects."""
    fired = outcome.fired - {EventKind.FRONT_CROSSES_PIECE}  # internal: a restart, nothing to log
    state.slip = next_slip(state.slip, fired)
    state.force = outcome.force
    if EventKind.FULL_SLIP in fired:
        # every spring sits at the cap: F_x = 2G* ū a = τ0 π a² exactly; taking it from here drops what the
        # integration accumulated before (long, shallow paths)
        state.force = 2.0 * model.params.G_star * model.K * radius**2
    if EventKind.RE_STICK in fired:
        state.anchors.restick_slip_zone(x - model.K * radius, radius)
    state.radius, state.t = radius, outcome.t_stop
    return [(kind, outcome.t_stop, radius) for kind in EventKind if kind in fired]


def regime_ends(model: ContinuumModel, state: ContactState, plan: SpanPlan, outcome: SpanOutcome,
                radius: float) -> Logged:
    """The span ran to its planned end: the segment's end, or the regime's end event."""
    state.force = outcome.force
    if np.isfinite(radius):
        state.radius = radius
    if plan.end_kind is EventKind.PULL_OFF:
        state.radius = model.shrink.jump_off_radius
    state.t = plan.t_end
    if plan.end_kind is None:
        return []
    logged = [(plan.end_kind, plan.t_end, state.radius)]
    if plan.end_kind is EventKind.DETACHMENT_STARTS:
        state.detaching = True
    if plan.end_kind in CONTACT_ENDING:
        end_contact(state)
    return logged


def end_contact(state: ContactState) -> None:
    """The contact has come apart: the run ends."""
    state.in_contact, state.running, state.radius, state.force = False, False, 0.0, 0.0


def radius_at(model: ContinuumModel, span: Span, t: float) -> float:
    """The contact radius of ``span`` at path time ``t``."""
    if span.regime in (Regime.GROWING, Regime.SHRINKING):
        return model.branch(span.regime).radius(span.segment.d(t), model.tolerances.radius_rtol)
    return span.pinned_radius


def run_continuum(params: Parameters, paths: list[Path], times: np.ndarray | None = None,
                  samples: int = 2001, tolerances: Tolerances = Tolerances()) -> dict:
    """Solve every path and fill a common time grid (default: ``samples`` points to the longest run).

    Returns the arrays of :func:`evaluate` stacked to (n_cases, n_time), ``time``, the event
    log ``events`` (one list of :class:`Event` per case) and the ``solutions`` (one
    :class:`PathSolution` per case).
    """
    solutions = [solve_path(params, path, tolerances) for path in paths]
    if times is None:
        longest = max(solution.end_time for solution in solutions)
        times = np.linspace(0.0, longest * (1.0 + 1.0 / samples), samples)
    times = np.asarray(times, dtype=float)
    per_case = [evaluate(solution, times) for solution in solutions]
    out = {name: np.stack([case[name] for case in per_case]) for name in per_case[0]}
    out["time"] = times
    out["events"] = [solution.events for solution in solutions]
    out["solutions"] = solutions
    return out
