"""``solve_path``: the hybrid automaton's loop, plan → integrate → transition → log.

Each pass plans a span in closed form (:func:`~.plan.plan_span`), integrates the tangential force
over it up to its end or the first slip event (:func:`~.integrate.integrate_span`), and applies the
transition the plan or the events call for (the functions below; the slip transitions are the table
of :mod:`~.state`), logging the events. Path corners start a new plan.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits, values_in
from mdr_events.parameters import Parameters
from mdr_events.validation import check_count, check_output_times
from mdr_events.models.paths import Path
from mdr_events.models.indenters import SimulatedProfile, check_reach, check_simulated_profile
from mdr_events.contact.adhesion import AdhesionLaw
from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.models.kernel_model import KernelModel, as_kernel_model, check_kernel_run
from .anchors import AnchorMap, Piece
from .compressed import attach_compressed_zone
from .model import ContinuumModel, Segment, check_resolvable, kinematics
from .plan import Action, SpanPlan, plan_span
from .regions import Region
from .solution import PathSolution, evaluate
from .integrate import integrate_span
from .layer_reach import check_layer_reach
from .span import SpanIntegrator, SpanOutcome, Trigger
from .span_record import Span, root_key
from .split_map import SplitAnchorMap
from .split_solve import commit, new_anchors, split_slip_transition
from .split_span import SplitSpanIntegrator
from .state import CONTACT_ENDING, NO_ZONE, Cap, ContactState, Event, EventKind, Regime, Slip, ZoneSummary, zone_events
from .time_grid import sample_times
from .tolerances import MAX_CHATTER_SPANS, MAX_RESTARTS, SEGMENT_RESOLUTION, Tolerances, check_output, check_tolerances
from .zones import lay_out_zones


def solve_path(params: Parameters, path: Path, tolerances: Tolerances = Tolerances(),
               limits: Limits = DEFAULT_LIMITS, profile: SimulatedProfile = None,
               friction: FrictionLaw | str | None = None, adhesion: AdhesionLaw | None = None,
               layer: Layer = HALF_SPACE) -> PathSolution:
    """Integrate the continuum model along ``path`` (see :mod:`mdr_events.models.continuum`) for the indenter
    ``profile`` (``None``: the paper's paraboloid of ``params.R``), the friction law ``friction`` (``None``:
    the paper's ``"tau0"``; both parts with adhesion on a curved indenter: two regions, :mod:`.split_span`) and the
    adhesion law ``adhesion`` (``None``: the paper's, of ``params.dgamma0`` and ``params.dgamma1``); a path with more waypoints than
    ``limits.waypoints`` is refused before the work starts, a run that makes more spans than ``limits.spans`` as
    soon as it does.

    Parameters
    ----------
    params : Parameters
        The material, ``R``, ``τ0``, the works of adhesion and ``d_max``.
    path : Path
        The indenter's path.
    tolerances : Tolerances, optional
        The solver's and the roots' tolerances (default ``Tolerances()``).
    limits : Limits, optional
        The resource limits (default :data:`~mdr_events.limits.DEFAULT_LIMITS`).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter; ``None``: the paper's paraboloid of ``params.R``.
    friction : FrictionLaw or str, optional
        The friction law; ``None``: the paper's ``"tau0"``.
    adhesion : Adhesion, optional
        The adhesion law; ``None``: the paper's, of ``params.dgamma0`` and ``params.dgamma1``.
    layer : Layer, default the half-space
        The body (:mod:`.media`; on a layer of finite thickness the paraboloid or a power law with ``"tau0"``).

    Returns
    -------
    PathSolution
        The spans with their interpolants of ``F_x``, the event log, the first contact and the end of the run.

    Raises
    ------
    ValueError
        A path the continuum cannot resolve or reach, an indenter or law it does not take.
    ResourceLimitError
        More waypoints than ``limits.waypoints``, or more spans than ``limits.spans``.
    """
    limits = check_limits(limits)
    limits.check(f"the continuum run of a path with {len(path.waypoints)} waypoints",
                 waypoints=len(path.waypoints))
    profile = check_simulated_profile(profile)
    check_reach(params, path.max_depth, profile, "the path")
    check_layer_reach(params, path.max_depth, profile, layer)
    model = ContinuumModel(params, tolerances, profile, as_friction_law(friction), adhesion, layer)
    segments = kinematics(path)
    check_resolvable(model, path, segments)
    solution = PathSolution(model, t_contact=path.first_contact_time(), path=path)
    state = ContactState(t=solution.t_contact, anchors=_stored_anchors(model, path))
    entries = path.entry_times()
    heading = 0.0  # the sign of the last tangential motion
    for index, segment in enumerate(segments):
        if segment.vx != 0.0:
            if heading and math.copysign(1.0, segment.vx) != heading and state.running \
                    and segment.t0 >= solution.t_contact:
                log(solution, segment, (EventKind.TANGENTIAL_REVERSAL, segment.t0, state.radius, int(-heading)))
            heading = math.copysign(1.0, segment.vx)
        state.t = max(segment.t0, solution.t_contact)
        if not state.running or state.t >= segment.t1:
            continue
        guard = RestartGuard(model.friction)
        while state.running and state.t < segment.t1:
            guard.check(state)
            plan = plan_span(model, state, segment)
            for logged in advance(model, state, plan, segment, solution):
                log(solution, segment, logged)
            if len(solution.spans) > limits.spans:
                _refuse_spans(model, state, solution, limits)
            if not state.in_contact and state.running:
                state.running = bool(np.any(entries >= state.t))  # the path enters again: the run goes on
        if state.running and index < len(segments) - 1:
            log(solution, segment, (EventKind.CORNER, segment.t1, state.radius, 0))
    if state.running:
        log(solution, segments[-1], (EventKind.PATH_END, segments[-1].t1, state.radius, 0))
    solution.end_time = (solution.spans[-1].t_end if solution.spans else solution.t_contact) - solution.t_contact
    if model.zone_params is not None:  # Coulomb's law alone with adhesion: the compressed zone's force
        attach_compressed_zone(solution, solve_path(model.zone_params, path, tolerances, limits, profile,
                                                    model.friction, layer=layer))
    return solution


def _refuse_spans(model: ContinuumModel, state: ContactState, solution: PathSolution, limits: Limits) -> None:
    """Raise :class:`~mdr_events.limits.ResourceLimitError`: the run has made more spans than ``limits.spans``
    (counted as it goes; round 28 A1: ``tau0+coulomb`` with a small work of adhesion, spans ``~1/√Δγ``)."""
    cause = (" (tau0+coulomb with adhesion on a curved indenter: a receding contact makes ~1/sqrt(work of adhesion) "
             "spans)") if model.split else ""
    limits.check(f"the continuum run (stopped at t = {state.t - solution.t_contact:.6g} s after first contact, "
                 f"contact radius {state.radius:.3g} m{cause})", spans=len(solution.spans))


def _stored_anchors(model: ContinuumModel, path: Path) -> AnchorMap | SplitAnchorMap:
    """An empty map of the anchors of ``model``'s springs along ``path``: of formulas split at ``x_c`` with both
    parts of the cap and adhesion on a curved indenter (:func:`~.split_solve.new_anchors`), else of pieces."""
    return new_anchors(model, path) if model.split else AnchorMap(model.grow, model.tolerances.radius_rtol)


class RestartGuard:
    """Counts passes that do not advance in time, and passes in a row that advance by less than the event times are
    resolved to (``SEGMENT_RESOLUTION`` of the time): too many of the first mean the solver is
    stuck; of the second, that the slip zones chatter (a zone opening at an edge and leaving through it again and
    again, each a span of ~1e-12 of the time: the cone under Coulomb's law alone at mu = 1.5e6 in scenario B, 4e-9 s
    apart from t = 1177 s, 4e5 spans to the pull-off; tens of minutes, a zone of no width since laid out as none by
    ``edge_zone_beside_full``), which is refused with what to do instead."""

    def __init__(self, friction: FrictionLaw | None = None) -> None:
        self.stalled, self.last, self.chattering, self.friction = 0, -math.inf, 0, friction

    def check(self, state: ContactState) -> None:
        step = state.t - self.last
        if 0.0 < step < SEGMENT_RESOLUTION * abs(state.t):
            self.chattering += 1
        elif step > 0.0:
            self.chattering = 0
        if self.chattering > MAX_CHATTER_SPANS:
            raise ValueError(f"the friction law {self.friction!r} is not allowed for the continuum method on this "
                             f"path: from t = {state.t:.12g} s on its slip zones change every {step:.3g} s, below "
                             f"the {SEGMENT_RESOLUTION:g} of the time the events are resolved to ({MAX_CHATTER_SPANS} "
                             f"times in a row, contact radius {state.radius:.3g} m); allowed: method='discrete', or "
                             "a friction law whose zones the continuum resolves (another mu)")
        self.stalled = self.stalled + 1 if state.t <= self.last else 0
        if self.stalled > MAX_RESTARTS:
            zones = ", ".join(f"{cap.name.lower()} cap {state.zones[cap].slip.value}" for cap in Cap)
            fired = ", ".join(sorted(f"{key[0].value}" + (f" ({key[1].name.lower()} cap)" if key[1] else "")
                                     for key in state.last_fired)) or "none"
            raise RuntimeError(f"the continuum method made no progress at t = {state.t!r} s after {MAX_RESTARTS} "
                               f"event restarts (radius {state.radius!r} m, {zones}; last event: {fired}); please "
                               "report the parameters and path")
        self.last = state.t


#: What :func:`advance` reports: events to log as ``(kind, path time, radius, direction)``.
Logged = tuple[EventKind, float, float, int]


def log(solution: PathSolution, segment: Segment, logged: Logged) -> None:
    """Append an event at path time ``t`` (logged from first contact)."""
    kind, t, radius, direction = logged
    solution.events.append(Event(t - solution.t_contact, kind, segment.d(t), radius, segment.x(t), direction))


def advance(model: ContinuumModel, state: ContactState, plan: SpanPlan, segment: Segment,
            solution: PathSolution) -> list[Logged]:
    """Carry out ``plan``: the transition at its start, the span (appended to ``solution``), and the
    transition at its end."""
    if plan.action is Action.TOUCH:
        return touch(state, plan, segment)
    if plan.action is Action.APPROACH:
        solution.spans.append(Span(plan.t_start, plan.t_end, segment, Regime.NONE))
        state.t = plan.t_end
        return []
    if plan.action is Action.COME_OFF:
        solution.spans.append(Span(plan.t_start, plan.t_start, segment, Regime.PINNED, pinned_radius=plan.radius,
                                   force=plan.force, anchors=state.anchors.copy()))
        end_contact(state)
        return [(plan.end_kind, plan.t_start, plan.radius, 0)]
    logged = enter(model, state, plan, segment)
    span = Span(plan.t_start, plan.t_end, segment, plan.regime, pinned_radius=plan.radius,
                roots={root_key(depth, rtol): radius for depth, rtol, radius in plan.roots})
    if model.split:  # two regions: each cap of each, and the maps the span reads them from
        outcome = integrate_span(model, state.anchors, span, state.regions, plan.force, SplitSpanIntegrator)
        record = commit(state, outcome, span)
    else:
        outcome = integrate_span(model, state.anchors, span, state.sliding, plan.force, SpanIntegrator)
        record = None
    span.t_end = outcome.t_stop
    solution.spans.append(span)
    radius = outcome.radius
    if span.regime is Regime.GROWING:
        state.anchors.close(radius)
    span.anchors = record if record is not None else state.anchors.copy()
    if outcome.fired:
        if model.split:
            return logged + split_slip_transition(model, state, outcome, radius, segment)
        return logged + slip_transition(model, state, outcome, radius, segment, span.regime is Regime.GROWING)
    return logged + regime_ends(model, state, plan, outcome, radius)


def touch(state: ContactState, plan: SpanPlan, segment: Segment) -> list[Logged]:
    """Contact (first or again): the springs under the jump-in radius attach at the indenter's position,
    every one sticking (τ0 = 0: the plan also logs onset and full slip, and the force stays 0)."""
    state.anchors.reset()
    state.anchors.extend(0.0, Piece(0.0, plan.radius, segment.x(plan.t_start)))
    state.in_contact, state.radius, state.force, state.detaching = True, plan.radius, 0.0, False
    state.forget_slip()
    state.contacts += 1
    return [(kind, plan.t_start, plan.radius, 0) for kind in plan.entry_events]


def enter(model: ContinuumModel, state: ContactState, plan: SpanPlan, segment: Segment) -> list[Logged]:
    """The start of a span in contact: new springs stick (growth; springs may jump in), detachment may
    start at once, the radius may drop onto the Δγ1 branch (the springs beyond it are forgotten)."""
    logged = [(kind, plan.t_start, state.radius, 0) for kind in plan.entry_events]
    if plan.regime is Regime.GROWING:
        if plan.jumped_from is not None and any(state.sliding.values()):
            # the cap jumps up with the radius: the springs at the caps ū(a_before) now carry less than the cap
            # and stick again where they are (the old window materialised)
            before = plan.jumped_from
            x = segment.x(plan.t_start)
            state.anchors.clip_caps(x, model.caps, segment.d(plan.t_start), before)
            for cap in Cap:
                logged += [(kind, plan.t_start, before, int(cap)) for kind in zone_events(state.zones[cap], NO_ZONE,
                                                                                          restuck=True)]
            state.forget_slip()
        for piece in plan.growth:
            state.anchors.extend(piece.start, piece)
    else:
        state.anchors.truncate(plan.radius)
    state.detaching = plan.regime is Regime.SHRINKING
    if plan.regime is not Regime.GROWING and plan.radius < state.radius:
        return logged + drop_onto_branch(model, state, plan, segment)
    state.radius, state.force = plan.radius, plan.force
    return logged


def drop_onto_branch(model: ContinuumModel, state: ContactState, plan: SpanPlan, segment: Segment) -> list[Logged]:
    """The radius dropped onto the ``Δγ1`` branch at the start of ``plan`` (``Δγ1 < Δγ0``): the caps jumped in with it,
    and the play operators take the springs beyond them at once (the window materialised in the anchors), which then
    sit at the caps. Every cap's zone is laid out anew with each spring at a cap taken as sliding, and what changed is
    logged (the table of :mod:`.state`: full slip where every spring left is at a cap); the span then finds whether
    each level pushes on or turns back (a re-stick at once).

    Parameters
    ----------
    model : ContinuumModel
        The contact: its caps, and whether it is split at ``x_c``.
    state : ContactState
        The automaton's state, its anchors truncated to the new radius (changed).
    plan : SpanPlan
        The span's plan: its start, the radius on the ``Δγ1`` branch and the force of the clipped anchors.
    segment : Segment
        The path segment the span lies on.

    Returns
    -------
    list of tuple
        What the drop changed of each cap's zone, to log as ``(kind, path time, radius, direction)``.
    """
    t, radius = plan.t_start, plan.radius
    state.anchors.clip_caps(segment.x(t), model.caps, segment.d(t), radius)
    state.radius, state.force = radius, plan.force
    if model.split:
        reached = frozenset((Trigger.ZONE_REACHES, cap, region) for cap in Cap for region in Region)
        return split_slip_transition(model, state, SpanOutcome(reached, t, plan.force, radius), radius, segment)
    reached = frozenset((Trigger.ZONE_REACHES, cap) for cap in Cap)
    return slip_transition(model, state, SpanOutcome(reached, t, plan.force, radius), radius, segment)


def slip_transition(model: ContinuumModel, state: ContactState, outcome: SpanOutcome, radius: float,
                    segment: Segment, growing: bool = False) -> list[Logged]:
    """Events stopped the span (at radius ``radius``, on ``segment``; ``growing``: a span whose edge grew, its last
    springs attached with no shift): each cap's slip zone laid out anew, what changed logged (the table of
    :mod:`.state`), and a level that turned back re-sticks its springs (the window materialised in the anchors)."""
    state.force, state.radius, state.t = outcome.force, radius, outcome.t_stop
    state.last_fired = outcome.fired
    if (Trigger.EDGE_PASSES_PIECE, None) in outcome.fired:
        state.anchors.drop_edge_piece(radius)
    state.anchors.truncate(radius)
    fired = {cap: {trigger for trigger, which in outcome.fired if which is cap} for cap in Cap}
    for cap in Cap:
        if Trigger.ZONE_REACHES in fired[cap]:
            state.sliding[cap] = True
    x = segment.x(outcome.t_stop)
    layouts = lay_out_zones(state.anchors, model.caps, segment, outcome.t_stop, radius, state.sliding,
                            model.grow.depth_term, growing)
    logged: list[Logged] = []
    turned = [cap for cap in Cap if Trigger.LEVEL_TURNS in fired[cap]]
    if turned:
        state.anchors.clip_caps(x, model.caps, segment.d(outcome.t_stop), radius)
    summaries = {cap: layouts[cap].summary(radius) for cap in Cap}
    for cap in Cap:
        before, after = state.zones[cap], edge_zone_beside_full(model, summaries[cap], summaries[Cap(-cap)])
        events = zone_events(before, after)
        if after.slip is Slip.FULL and before.slip is not Slip.FULL:
            # every spring at the cap: F_x = ±2G* ū a = ±τ0 π a² exactly (and ± μ F_N with Coulomb's part);
            # taking it from here drops what the integration accumulated before (long, shallow paths)
            state.force = cap * full_slip_force(model, radius, segment.d(outcome.t_stop))
        if cap in turned:
            events += zone_events(after, NO_ZONE, restuck=True)
            after = NO_ZONE
        state.sliding[cap] = after.slip is not Slip.STICK
        state.zones[cap] = after
        logged += [(kind, outcome.t_stop, radius, int(cap)) for kind in events]
    return logged


def edge_zone_beside_full(model: ContinuumModel, summary: ZoneSummary, other: ZoneSummary) -> ZoneSummary:
    """``summary`` of one cap's zone, ``NO_ZONE`` where it is a zone at the edge alone while every spring
    sits at the other cap under Coulomb's law alone (``K = 0``; the chatter of issue 32, round seventeen R4).

    A spring at the other cap carries ``u = ∓ū(ξ)`` with ``ū = κ (d − g(ξ)) ≥ 0`` (13); it reaches this cap,
    ``u = ±ū``, only where ``ū = 0``: at the edge of the compressed zone, ``g(a) = d``, a single spring that carries no
    force. In the anchors as this cap sees them, ``Z = x − κ d + 2κ g`` against the level ``x + κ d``, the gap
    ``2κ (d − g(ξ))`` vanishes at the edge identically in time (``d = g(a(t))``), so the layout's tolerance laid a
    zone of no width there, which the shrinking edge left at once and which opened again: 4e5 spans of 4e-9 s (a cone
    at μ = 1.5e6, scenario B at 20°). With ``K > 0`` every cap is at least ``K a > 0`` and this cannot happen."""
    if model.caps.K == 0.0 and other.slip is Slip.FULL and summary.slip is Slip.PARTIAL and summary.edge \
            and not summary.centre:
        return NO_ZONE
    return summary


def full_slip_force(model: ContinuumModel, radius: float, depth: float) -> float:
    """``|F_x|`` with every spring at one cap: ``2G* K a² = τ0 π a²`` (on a layer too, ``K_t(a) ū(a)``; 0 on a
    frictionless base: :meth:`~.media.HalfSpaceMedium.full_slip_force`), plus ``μ F_N`` (10) with Coulomb's part (0 in
    tension: the adhesive flat punch above the surface, ``flat_punch_full_slip_force``)."""
    force = model.medium.full_slip_force(model.params.G_star, model.K, radius)
    if model.caps.kappa and depth > 0.0:
        force += model.friction.coulomb_mu * float(model.normal_force(depth, radius))
    return force


def regime_ends(model: ContinuumModel, state: ContactState, plan: SpanPlan, outcome: SpanOutcome,
                radius: float) -> list[Logged]:
    """The span ran to its planned end: the segment's end, or the regime's end event."""
    state.force = outcome.force
    if np.isfinite(radius):
        state.radius = radius
    if plan.end_kind is EventKind.PULL_OFF:
        state.radius = model.shrink.jump_off_radius
    state.t = plan.t_end
    if plan.end_kind is None:
        return []
    logged = [(plan.end_kind, plan.t_end, state.radius, 0)]
    if plan.end_kind is EventKind.DETACHMENT_STARTS:
        state.detaching = True
    if plan.end_kind in CONTACT_ENDING:
        end_contact(state)
    return logged


def end_contact(state: ContactState) -> None:
    """The contact has come apart: every spring forgets its state (the loop decides whether the run goes on)."""
    state.in_contact, state.radius, state.force = False, 0.0, 0.0
    state.anchors.reset()
    state.forget_slip()


#: Bytes the continuum method allocates per case and output time (the filled quantities and the dataset):
#: measured with tracemalloc, rounded up.
BYTES_PER_SAMPLE = 128


def run_continuum(model: KernelModel | Parameters, paths: list[Path], times: np.ndarray | int = 2001,
                  tolerances: Tolerances = Tolerances(), limits: Limits = DEFAULT_LIMITS) -> dict:
    """Solve every path (:func:`solve_path`) and fill a common time grid: the output ``times``, or as many samples
    as ``times`` says spread to the longest run.

    The output's size is checked against ``limits`` first.

    Parameters
    ----------
    model : KernelModel or Parameters
        The physical model (:class:`~mdr_events.models.kernel_model.KernelModel`: the material, ``R``, ``τ0``, the
        works of adhesion and ``d_max``; the indenter, ``None`` the paper's paraboloid of ``params.R``; the friction
        law, ``None`` the paper's ``"tau0"``; the adhesion law, ``None`` the paper's of ``params.dgamma0`` and
        ``params.dgamma1``; the body); a :class:`~mdr_events.Parameters` alone is the paper's model of its values.
    paths : list of Path
        One path per case.
    times : numpy.ndarray or int, default 2001
        The output times (s from first contact), or the number of samples from 0 to the end of the longest run.
    tolerances : Tolerances, optional
        The solver's and the roots' tolerances (default ``Tolerances()``).
    limits : Limits, optional
        The resource limits (default :data:`~mdr_events.limits.DEFAULT_LIMITS`).

    Returns
    -------
    dict
        The arrays of :func:`evaluate` stacked to (n_cases, n_time), ``time``, the event log ``events`` (one
        list of :class:`Event` per case) and the ``solutions`` (one :class:`PathSolution` per case).

    Raises
    ------
    ResourceLimitError
        More samples or memory than ``limits`` allows.
    """
    paths, limits = check_kernel_run(paths, limits)
    check_tolerances(tolerances)
    if isinstance(times, numbers.Integral) and not isinstance(times, (bool, np.bool_)):
        samples, times = check_count("times", times, 2), None
    else:  # (counted before they are read, as simulate counts its t: round twenty-three)
        check_output(limits, len(paths), values_in(times), BYTES_PER_SAMPLE)
        samples, times = None, check_output_times("times", times)
    n_time = samples if samples is not None else len(times)
    check_output(limits, len(paths), n_time, BYTES_PER_SAMPLE)
    params, profile, friction, adhesion, layer = as_kernel_model(model)
    solutions = [solve_path(params, path, tolerances, limits, profile, friction, adhesion, layer) for path in paths]
    if samples is not None:
        times = sample_times([solution.end_time for solution in solutions],
                             [path.duration - path.first_contact_time() for path in paths], samples)
    per_case = [evaluate(solution, times) for solution in solutions]
    out = {name: np.stack([case[name] for case in per_case]) for name in per_case[0]}
    out["time"] = times
    out["events"] = [solution.events for solution in solutions]
    out["solutions"] = solutions
    return out
