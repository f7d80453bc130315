"""Integrate the tangential force over one span, up to the first slip event.

The force obeys

    dF_x/dt = 2G* [ c dū/dt + (a − c) dx/dt + (da/dt) u(a) ],

(the slip zone follows the cap, the stick zone follows the indenter, springs leave at the edge
with their shift), integrated by :func:`scipy.integrate.solve_ivp` (DOP853, dense output). A pinned
span is integrated in time; a growing or shrinking one in the contact radius ``a``
(``dF/da = (dF/dt)/(da/dt)``), which is regular where ``da/dt`` is not: at the first contact of a
non-adhesive indenter and at the pull-off fold ``∂d/∂a = 0``.

The right-hand side keeps the slip state the span started in (all sticking, a slip zone ``[0, c]``
held in one piece of the anchor map, or full slip) and is continued smoothly past the span's
terminal events, as hybrid-system integration requires: the solver locates a switch by root-finding
instead of shrinking its steps against a kink. A slip event already met at the start (e.g. at a
path corner) fires at once, with zero length.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass
from typing import Callable, NamedTuple

from scipy.integrate import solve_ivp

from .anchors import AnchorMap
from .model import ContinuumModel, Segment
from .state import EventKind, Regime, Slip
from .tolerances import EPS, LEVEL_ULPS, PIECE_SHARE, SIMULTANEOUS_SHARE


class Variable(enum.Enum):
    """The integration variable of a span."""

    TIME = "time"
    RADIUS = "radius"


@dataclass
class Span:
    """An interval with one radius regime, as the solution keeps it.

    ``interpolant`` is ``solve_ivp``'s dense output of ``F_x`` in :attr:`variable` (``None`` where the
    force is the constant :attr:`force`); ``anchors`` is the anchor map during the span.
    """

    t_start: float
    t_end: float
    segment: Segment
    regime: Regime
    pinned_radius: float = 0.0
    interpolant: Callable | None = None
    force: float = 0.0
    anchors: AnchorMap | None = None
    variable: Variable = Variable.TIME


class SpanOutcome(NamedTuple):
    """How a span ended: the slip events that stopped it (none: it ran to its planned end)."""

    fired: frozenset[EventKind]
    t_stop: float
    force: float


class EventFunction:
    """A terminal event function for ``solve_ivp``: ``function(var, y)`` crossing zero in ``direction``."""

    terminal = True

    def __init__(self, kind: EventKind, function: Callable[[float, object], float], direction: float):
        self.kind = kind
        self.function = function
        self.direction = direction

    def __call__(self, var: float, y) -> float:
        return self.function(var, y)


class SpanIntegrator:
    """The right-hand side and the slip event functions of one span (see the module docstring).

    Parameters
    ----------
    model : ContinuumModel
    anchors : AnchorMap
        The anchor map of the springs in contact (read, not changed).
    span : Span
        The span to integrate, with its regime and (pinned) radius.
    slip : Slip
        The slip state the span starts in; the right-hand side keeps it.
    """

    def __init__(self, model: ContinuumModel, anchors: AnchorMap, span: Span, slip: Slip):
        self.model, self.anchors, self.span, self.slip = model, anchors, span, slip
        self.segment = span.segment
        self.K = model.K
        self.G2 = 2.0 * model.params.G_star
        self.moving = span.regime in (Regime.GROWING, Regime.SHRINKING)
        self.branch = model.branch(span.regime)
        t0, t1 = span.t_start, span.t_end
        if self.moving:
            rtol = model.tolerances.radius_rtol
            self.start = self.branch.radius(self.segment.d(t0), rtol)
            at_fold = span.regime is Regime.SHRINKING and t1 == self.segment.time_at_depth(self.branch.jump_off_depth)
            self.stop = self.branch.jump_off_radius if at_fold else self.branch.radius(self.segment.d(t1), rtol)
        else:
            self.start, self.stop = t0, t1
        self.a0 = self.start if self.moving else span.pinned_radius
        self.x0 = self.segment.x(t0)
        y0 = anchors.value(0.0)
        self.onset0 = self.x0 - y0 - self.K * self.a0
        self.full0 = self.x0 - anchors.value(self.a0) - self.K * self.a0
        # The rising slip events cross a level a hair above zero: LEVEL_ULPS ulp of the lengths
        # involved, just above the rounding of x − Y − ū (an event moves by about 1e-12 s at the
        # paper's speed). A slip function that starts at zero to rounding and first falls (the
        # centre of a Hertz contact at a = 0, the level right after a re-stick) is then not taken for
        # a root at the start; one that starts above it has crossed already and fires at once.
        self.level = LEVEL_ULPS * EPS * max(self.K * self.a0, abs(self.x0), abs(y0), model.params.d_max)
        self.piece = self.next_value = None
        self.waiting = self.crossing_inside = False
        if slip is Slip.PARTIAL:
            self._hold_front_piece()

    def _hold_front_piece(self) -> None:
        """The piece that holds the slip front at the start, and the level at which it leaves it.

        A front within PIECE_SHARE of the length scale of a piece's end (e.g. where the last event's
        root was found, a few ulp of the radius away) is in the next piece. The front waits at the
        piece's start while the piece starts above the level (``Y`` jumps up there, or the piece is
        constant: its springs all start sliding together); otherwise it moves inside the piece.
        Either way an internal event restarts the span when the level reaches the value that ends
        this (the piece's start value, or its end value).
        """
        level = self.x0 - self.K * self.a0
        scale = PIECE_SHARE * max(self.K * self.a0, abs(self.x0), self.model.params.d_max)
        self.piece = self.anchors.piece_of_front(level, self.a0, scale)
        current = self.anchors.pieces[self.piece]
        start_value = self.anchors.value(current.start)
        self.waiting = current.ratio == 0.0 or start_value > level + scale
        self.next_value = start_value if self.waiting else self.anchors.end_value(self.piece, self.a0)
        # the front can cross into a later piece: one inside the contact, or the growth piece starting
        # at the radius (after a corner, the piece of the front ends exactly there)
        followed = self.piece < len(self.anchors.pieces) - 1 and current.end <= self.a0
        self.crossing_inside = self.waiting or current.end < self.a0 or followed

    # --- the state along the span ------------------------------------------------------------
    def time_of(self, var: float) -> float:
        return self.segment.time_at_depth(self.branch.depth(var)) if self.moving else var

    def radius_of(self, var: float) -> float:
        return var if self.moving else self.span.pinned_radius

    def slip_zone(self, x: float, a: float) -> float:
        """The slip front ``c`` of the span's slip state (continued smoothly within its piece)."""
        if self.slip is Slip.STICK:
            return 0.0
        if self.slip is Slip.FULL:
            return a
        if self.waiting:
            return self.anchors.pieces[self.piece].start
        return self.anchors.front_in_piece(self.piece, x - self.K * a)

    # --- the right-hand side ---------------------------------------------------------------
    def rhs(self, var: float, y) -> list[float]:
        """``dF_x/da`` (moving radius) or ``dF_x/dt`` (pinned)."""
        segment, K = self.segment, self.K
        if not self.moving:
            a = self.span.pinned_radius
            return [self.G2 * (a - self.slip_zone(segment.x(var), a)) * segment.vx]
        a = var
        x = segment.x(self.time_of(a))
        c = self.slip_zone(x, a)
        total = c * K + (a - c) * segment.vx * self.branch.slope(a) / segment.vd
        if self.span.regime is Regime.SHRINKING:  # springs leave the edge with their shift
            total += K * a if self.slip is Slip.FULL else x - self.anchors.value(a)
        return [self.G2 * total]

    # --- the event functions -----------------------------------------------------------------
    def onset(self, var: float, y) -> float:
        """``x − Y(0) − ū`` (above the level): the centre spring reaches the cap."""
        return self.segment.x(self.time_of(var)) - self.anchors.value(0.0) - self.K * self.radius_of(var) - self.level

    def full(self, var: float, y) -> float:
        """``x − Y(a) − ū`` (above the level): the edge spring reaches the cap."""
        a = self.radius_of(var)
        return self.segment.x(self.time_of(var)) - self.anchors.value(a) - self.K * a - self.level

    def restick_rate(self, var: float, y) -> float:
        """``dx/dt − dū/dt`` of a growing radius: below zero the cap outgrows the indenter."""
        slope = self.branch.slope(var)
        return self.segment.vx - self.K * self.segment.vd / slope if slope > 0 else -math.inf

    def front_crosses(self, var: float, y) -> float:
        """The slip front starts into its piece, or leaves it."""
        return self.segment.x(self.time_of(var)) - self.K * self.radius_of(var) - self.next_value - self.level

    def event_functions(self) -> list[EventFunction]:
        """The events that can end the span from its slip state."""
        events = []
        if self.slip is Slip.STICK:
            events.append(EventFunction(EventKind.SLIP_ONSET, self.onset, 1.0))
        if self.slip is not Slip.FULL:
            events.append(EventFunction(EventKind.FULL_SLIP, self.full, 1.0))
        if self.slip is Slip.PARTIAL and self.span.regime is Regime.GROWING and self.restick_rate(self.start, None) > 0:
            events.append(EventFunction(EventKind.RE_STICK, self.restick_rate, -1.0))
        if self.slip is Slip.PARTIAL and self.crossing_inside:
            events.append(EventFunction(EventKind.FRONT_CROSSES_PIECE, self.front_crosses, 1.0))
        return events

    def met_at_start(self) -> frozenset[EventKind]:
        """Slip events that have already happened at the span's start (they fire at once)."""
        met = set()
        if self.K > 0 and self.a0 > 0:
            if self.slip is Slip.STICK and self.onset0 > self.level:
                met.add(EventKind.SLIP_ONSET)
            if self.slip is not Slip.FULL and self.full0 > self.level:
                met.add(EventKind.FULL_SLIP)
        if not met and self.slip is Slip.PARTIAL and self.span.regime is Regime.GROWING \
                and self.restick_rate(self.start, None) <= 0.0:
            met.add(EventKind.RE_STICK)  # the cap already grows faster than the indenter moves (e.g. after a corner)
        return frozenset(met)

    def force_is_constant(self) -> bool:
        """Nothing moves the force: a span of zero extent, or a pinned one without tangential motion or
        in full slip."""
        return self.start == self.stop or (not self.moving and (self.segment.vx == 0.0 or self.slip is Slip.FULL))


def fired_events(events: list[EventFunction], roots: list, start: float, level: float) -> tuple[float, frozenset]:
    """The first root among the events' ``roots`` (``solve_ivp``'s ``t_events``) and every event that fires
    with it: those whose roots coincide (to SIMULTANEOUS_SHARE), and the rising ones whose function is
    already zero to rounding there (the roots of identical functions, e.g. onset and full slip of a
    uniform field, differ by an ulp)."""
    hits = sorted((abs(found[0] - start), found[0], event.kind) for event, found in zip(events, roots) if len(found))
    first = hits[0][1]
    kinds = {kind for _, var, kind in hits if abs(var - first) <= SIMULTANEOUS_SHARE * max(abs(first), 1e-300)}
    for event in events:
        if event.kind not in kinds and event.direction > 0 and event(first, None) >= -2 * level:
            kinds.add(event.kind)
    return first, frozenset(kinds)


def integrate_span(model: ContinuumModel, anchors: AnchorMap, span: Span, slip: Slip, force: float) -> SpanOutcome:
    """Integrate ``F_x`` over ``span`` from ``force``, up to its end or the first slip event.

    Sets the span's interpolant (or constant force) and integration variable; the caller sets its
    end to the returned ``t_stop``.
    """
    t0, t1 = span.t_start, span.t_end
    span.force = force
    if t1 <= t0:
        return SpanOutcome(frozenset(), t0, force)
    if model.K == 0.0:  # τ0 = 0: ū ≡ 0, every spring slides with zero shift, F_x ≡ 0
        span.force = 0.0
        return SpanOutcome(frozenset(), t1, 0.0)
    integrator = SpanIntegrator(model, anchors, span, slip)
    span.variable = Variable.RADIUS if integrator.moving else Variable.TIME
    met = integrator.met_at_start()
    if met:
        return SpanOutcome(met, t0, force)
    if integrator.force_is_constant():
        return SpanOutcome(frozenset(), t1, force)
    start, stop = integrator.start, integrator.stop
    if not (math.isfinite(start) and math.isfinite(stop) and math.isfinite(force)):
        raise RuntimeError(f"the continuum method lost its state on [{t0!r}, {t1!r}] s ({span.regime.value}: from "
                           f"{start!r} to {stop!r}, F_x = {force!r}); please report the parameters and path")
    events = integrator.event_functions()
    tolerances = model.tolerances
    solution = solve_ivp(integrator.rhs, (start, stop), [force], method="DOP853", rtol=tolerances.rtol,
                         atol=tolerances.atol, dense_output=True, events=events or None)
    if solution.status < 0:
        raise RuntimeError(f"solve_ivp failed on [{start}, {stop}] ({span.regime.value}): {solution.message}")
    span.interpolant = solution.sol
    if solution.status == 1:
        first, kinds = fired_events(events, solution.t_events, start, integrator.level)
        return SpanOutcome(kinds, float(integrator.time_of(first)), float(solution.sol(first)[0]))
    return SpanOutcome(frozenset(), t1, float(solution.y[0, -1]))
