"""The right-hand side of the tangential force over one span and its events (:mod:`.integrate` integrates them).

The force obeys

    dF_x/dt = 2G* [ (n₊ − n₋) dū/dt + (a − n₊ − n₋) dx/dt + (da/dt) u(a) ],

on a layer of finite thickness ``2G* [(n₊ − n₋) dū/dt + (M(a) − n₊ − n₋) dx/dt + w(a) (da/dt) u(a)]`` with the zones'
sizes their springs' measures ``n = ∫ w dξ``, ``M(a) = K_t(a)/(2G*)``, ``w = k_t/G*`` and ``ū = K a/Φ_t(a/h)``
(``layer_continuum_force_rate``; :mod:`.media`),

(``dū/dt = K ȧ + κ ∂d/∂t``: a pinned span's caps follow the depth, ``κ v_d`` while pressed, 0 in tension)

with ``n₊``, ``n₋`` the sizes of the slip zones at the caps ``u = +ū`` and ``u = −ū`` (their springs
follow the cap, the sticking ones the indenter; springs leave at the edge with their shift ``u(a)``),
integrated by :func:`scipy.integrate.solve_ivp` (DOP853, dense output). A pinned span is integrated
in time; a growing or shrinking one in the contact radius ``a`` (``dF/da = (dF/dt)/(da/dt)``), which
is regular where ``da/dt`` is not: at the first contact of a non-adhesive indenter and at the
pull-off fold ``∂d/∂a = 0``.

The right-hand side keeps each cap's slip zone as laid out at the span's start
(:class:`~mdr_events.models.continuum.zones.ZoneLayout`) and is continued smoothly past the span's
terminal events, as hybrid-system integration requires (as far as the fronts' pieces continue: below
the Δγ0 branch's fold a front stays at its piece's start, which is why a step covers at most
1/MIN_STEPS_PER_SPAN of a span): the solver locates a switch by root-finding
instead of shrinking its steps against a kink. The events (:class:`Trigger`): a cap's level reaching
its layout's target (a zone opens, grows into a new piece, or covers the contact), the shrinking
edge passing a front or a piece boundary, and a sliding cap's level turning back (re-stick). An event
already met at the start (e.g. at a path corner) fires at once, with zero length. A pinned span
whose slip zones hold whole pieces (no front inside a piece: fretting at a fixed contact) needs no
integration: its force is linear in time and its events are closed forms (:class:`LinearForce`).
"""

from __future__ import annotations

import enum
import math
from typing import Callable, NamedTuple

import numpy as np

from . import span_front_knots
from .anchors import AnchorMap
from .closed_form import Primitive
from .graded import Grading
from .media import HalfSpaceMedium
from .model import ContinuumModel
from .span_record import Span, root_key
from .state import Cap, Regime, Slip
from .tolerances import EPS, LEVEL_ULPS, MIN_STEPS_PER_SPAN, PIECE_SHARE
from .zones import EDGE_LEAVING_TOLERANCES, cap_travel, indenter_travel, lay_out_zones, length_scale


class Trigger(enum.Enum):
    """What an event function of a span watches (the transitions of ``solve`` turn them into logged events)."""

    ZONE_REACHES = "zone_reaches"            #: a cap's level reaches its layout's target (a zone opens or grows on)
    ZONE_LEAVES_EDGE = "zone_leaves_edge"    #: the shrinking edge passes a front whose zone lies at the edge
    LEVEL_TURNS = "level_turns"              #: a sliding cap's level turns back: its springs stick again
    EDGE_PASSES_PIECE = "edge_passes_piece"  #: the shrinking edge passes the start of its piece
    BOUNDARY_PASSES_PART = "boundary_passes_part"  #: ``x_c`` passes a part's boundary (:mod:`.split_span`)


#: A fired event: its trigger and the cap it concerns (``None`` for the edge passing a piece).
Fired = tuple[Trigger, Cap | None]


class SpanOutcome(NamedTuple):
    """How a span ended: the events that stopped it (none: it ran to its planned end)."""

    fired: frozenset[Fired]
    t_stop: float
    force: float
    #: the contact radius at ``t_stop`` (a moving radius: the integration variable itself, not recomputed
    #: from the time, so that the next span starts exactly where the event's root was found)
    radius: float
    #: the maps the span read its regions from (:class:`~.split_map.SpanMaps`; ``None``: the stored anchors)
    maps: object = None
    #: the slip in each region at the span's start as it was laid out (``None``: as given)
    sliding: dict | None = None


class EventFunction:
    """A terminal event function for ``solve_ivp``: ``function(var, y)`` crossing zero in ``direction``.

    ``settled``: its readings settle it, no crossing hides between two of them (it is monotone there, or convex with
    direction +1, concave with −1: :mod:`.closed_form`, which reads between the readings only the events not
    settled; default ``False``).
    """

    terminal = True

    def __init__(self, trigger: Trigger, cap: Cap | None, function: Callable[[float], float], direction: float,
                 settled: bool = False):
        self.trigger, self.cap = trigger, cap
        self.function = function
        self.direction = direction
        self.settled = settled

    @property
    def key(self) -> Fired:
        return (self.trigger, self.cap)

    def __call__(self, var: float, y=None) -> float:
        return self.function(var)


#: how many variables' rates a :class:`SpanIntegrator` keeps (:meth:`SpanIntegrator._rate_parts`): the span's two
#: ends, read again by each event, and the variable both caps' events read in turn, with one to spare
RATES_KEPT = 4


def variable_key(var: float) -> tuple[float, float] | None:
    """The key of an integration variable in :class:`SpanIntegrator`'s memos.

    Parameters
    ----------
    var : float
        The variable.

    Returns
    -------
    tuple of float or None
        ``var`` with its sign, so that ``-0.0`` and ``0.0`` are kept apart (as ``mdr_events.memo.exact_key`` keeps
        them: their readings may differ in their zeros' signs); ``None`` for a variable that is not a Python float
        (a NumPy scalar, an array: not kept).
    """
    return (var, math.copysign(1.0, var)) if type(var) is float else None


class SpanIntegrator:
    """The right-hand side and the event functions of one span (see the module docstring).

    Parameters
    ----------
    model : ContinuumModel
    anchors : AnchorMap
        The stored anchors of the springs in contact (read, not changed).
    span : Span
        The span to integrate, with its regime and (pinned) radius.
    sliding : dict of Cap to bool
        Whether springs slide at each cap at the start.
    """

    #: the force is a quadrature (:func:`~.span_panels.panels`), not DOP853's steps: the right-hand side and the events
    #: read the span's variable alone, never the force (:meth:`rhs`), so ``F_x = F_0 + ∫ rhs`` is exact to the panels'
    #: tolerances. A panel reads the right-hand side 8 times where a DOP853 step read it 12 times and 3 more for its
    #: dense output, and its error is the interpolant's own against one more reading, not an estimate of the solver's
    #: local error: scenario A at 20° took 442 readings, now 280, and B at 20° 213, now 56, while ``F_x`` moved nearer
    #: the run at ``rtol = 1e-13`` (A at 20°: 6.8e-11 of its largest value -> 1.6e-12; the zigzag 1.4e-11 -> 2.7e-13;
    #: A at 20° on a 41-point table, whose knots start a piece each: 1.1e-8 -> 3.5e-9). ``False`` marches DOP853's
    #: steps (:func:`~.integrate.solve_between_knots`, the route before, kept for the tests that compare both)
    quadrature = True
    #: the last variable :meth:`level` read at (its :func:`variable_key`), with its ``x`` and the caps' centre shift
    #: there: both caps' events read the same variable one after the other (the closed form's readings,
    #: ``solve_ivp``'s), and the second reads the first's numbers (the same operations, bit for bit)
    _last_level: tuple[object, float, float] = (None, math.nan, math.nan)
    #: :meth:`_rate_parts` of the last :data:`RATES_KEPT` variables by :func:`variable_key`, oldest first (made at the
    #: first reading: a dict of the integrator's own)
    _rates: dict[tuple[float, float], tuple[float, float]] | None = None
    #: a moving span without a front on the half-space is integrated in closed form (:meth:`primitive`,
    #: :mod:`.closed_form`); ``False`` integrates it as any other (the tests compare both)
    closed_form = True

    def __init__(self, model: ContinuumModel, anchors: AnchorMap, span: Span, sliding: dict[Cap, bool]):
        self.model, self.anchors, self.span = model, anchors, span
        self.segment = span.segment
        self.K = model.K
        #: the friction law's caps; Coulomb's cap per compression (0: ``τ0`` alone, the levels ``x ∓ K a``)
        self.caps, self.kappa = model.caps, model.caps.kappa
        #: what the springs are made of: their cap's slope ``dū/da``, measure and density (:mod:`.media`)
        self.medium = model.caps.medium
        self.G2 = 2.0 * model.params.G_star
        self.moving = span.regime in (Regime.GROWING, Regime.SHRINKING)
        self.shrinking = span.regime is Regime.SHRINKING
        self.branch = model.branch(span.regime)
        t0, t1 = span.t_start, span.t_end
        self.scale = 1.0
        if self.moving:
            rtol = model.tolerances.radius_rtol
            # the radius the state holds (an event's root, or the plan's jump): the radius of the depth at
            # t0 differs from it by the depth's rounding over the branch's slope, which near the end of a
            # contact (a depth of 1e-12 m, computed from 1e-4 m) is 1e-11 of it, beyond the slip criterion's
            # resolution of the level
            a_start = span.pinned_radius if span.pinned_radius > 0 else self._root(self.segment.d(t0), rtol)
            at_fold = self.shrinking and t1 == self.segment.time_at_depth(self.branch.jump_off_depth)
            a_stop = self.branch.jump_off_radius if at_fold else self._root(self.segment.d(t1), rtol)
            # the radius is integrated in units of its largest value on the span: solve_ivp finds an event's
            # root to an absolute 4 eps of the variable, which is then 4 eps relative (not 4e-16 m)
            self.scale = max(a_start, a_stop) if max(a_start, a_stop) > 0 else 1.0
            self.start, self.stop = a_start / self.scale, a_stop / self.scale
            self.a0 = a_start
        else:
            self.start, self.stop = t0, t1
            self.a0 = span.pinned_radius
        #: a pinned span's ``dd/dt`` where Coulomb's caps follow it: ``v_d`` while pressed (``d > 0``), 0 in tension
        #: (the planner ends a span where the depth crosses 0, so the span's middle tells)
        self.depth_rate = self.segment.vd if self.segment.d(0.5 * (t0 + t1)) > 0.0 else 0.0
        self.x0 = self.segment.x(t0)
        self.lay_out(anchors, sliding)

    def _root(self, depth: float, rtol: float) -> float:
        """The branch's radius at ``depth`` (``Branch.radius``), kept in the span's :attr:`~Span.roots`."""
        radius = self.branch.radius(depth, rtol)
        self.span.roots[root_key(depth, rtol)] = radius
        return radius

    def lay_out(self, anchors: AnchorMap, sliding: dict[Cap, bool]) -> None:
        """Each cap's slip zone at the span's start (:func:`~.zones.lay_out_zones`), and the tolerances of the levels.

        Parameters
        ----------
        anchors : AnchorMap
            The stored anchors of the springs in contact.
        sliding : dict of Cap to bool
            Whether springs slide at each cap at the start.
        """
        model, t0 = self.model, self.span.t_start
        depth_term = model.grow.depth_term
        # a moving radius is integrated in units of the span's largest radius, and an event's root is found to 4 eps
        # of that: the levels move by the travel up to it over that rounding, which the level offset must exceed
        # (a span growing from 3 mm to 61 m on a path to d_max = 1e5 m located its slip onset 1e-14 m off a level
        # resolved to 1e-18 m, and restarted there for ever); at a = 0 (a Hertz contact's first instant) every
        # local length is 0 and that travel keeps the level offset above zero
        reach = self.scale * max(self.start, self.stop) if self.moving else self.a0
        lengths = length_scale(anchors, model.caps.centre_shift(self.a0, self.segment.d(t0)), self.x0,
                               max(indenter_travel(self.segment, t0, reach, depth_term),
                                   cap_travel(model.caps.kappa, self.segment, max(abs(t0), abs(self.span.t_end)))),
                               model.caps.kappa)
        # Rising events cross a level a hair beyond zero: LEVEL_ULPS ulp of the lengths involved, just
        # above the rounding of x − Y ∓ ū (an event moves by about 1e-12 s at the paper's speed). A
        # function that starts at zero to rounding and first falls (the centre of a Hertz contact at
        # a = 0, the level right after a re-stick) is then not taken for a root at the start; one that
        # starts beyond it has crossed already and fires at once.
        self.offset = LEVEL_ULPS * EPS * lengths
        self.edge_margin = EDGE_LEAVING_TOLERANCES * PIECE_SHARE * lengths
        self.zones = lay_out_zones(anchors, model.caps, self.segment, t0, self.a0, sliding, depth_term,
                                   self.span.regime is Regime.GROWING)
        self.positive, self.negative = self.zones[Cap.POSITIVE], self.zones[Cap.NEGATIVE]
        self.sliding = dict(sliding)
        self.edge_start = anchors.pieces[-1].start if anchors.pieces else 0.0

    # --- the state along the span ------------------------------------------------------------
    def time_of(self, var: float) -> float:
        """The path time at the integration variable ``var`` (a moving radius: the time its depth is reached).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The time (s).
        """
        return self.segment.time_at_depth(self.branch.depth(var * self.scale)) if self.moving else var

    def radius_of(self, var: float) -> float:
        """The contact radius at the integration variable ``var`` (a pinned span: its radius).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The radius (m).
        """
        return var * self.scale if self.moving else self.span.pinned_radius

    def level(self, cap: Cap | float, var: float) -> float:
        """``x − cap · (K a + κ d)``: where the anchors of the springs at ``cap`` sit (as the cap sees them).

        Parameters
        ----------
        cap : Cap or float
            The side, +1 or −1.
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The level (m).
        """
        key = variable_key(var)
        last, x, shift = self._last_level
        if key is None or key != last:
            t = self.time_of(var)
            x, shift = self.segment.x(t), self.caps.centre_shift(self.radius_of(var), self.segment.d(t))
            if key is not None:
                self._last_level = (key, x, shift)
        return x - cap * shift

    def rate(self, cap: Cap | float, var: float) -> float:
        """A quantity with the sign of ``cap · d(level)/dt``: positive while the level pushes the springs
        at the cap (moving radius: ``cap · v_x · ∂d/∂a − K v_d − κ v_d ∂d/∂a``, the rate times ``∂d/∂a > 0``).

        Parameters
        ----------
        cap : Cap or float
            The side, +1 or −1.
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The signed rate (its sign is what counts).
        """
        if not self.moving:
            return cap * self.segment.vx - self.kappa * self.depth_rate
        if self.kappa and self.K == 0.0:
            # Coulomb's caps alone: the rate's sign is that of cap · v_x − κ v_d, constant on the segment (times
            # ∂d/∂a it would vanish at a = 0, where a contact without adhesion ends: no turn there)
            return cap * self.segment.vx - self.kappa * self.segment.vd
        slope, shift_slope = self._rate_parts(var)
        if self.kappa:
            return (cap * self.segment.vx - self.kappa * self.segment.vd) * slope - self.K * self.segment.vd
        # (layer_continuum_level_rate: σ v_x ∂d/∂a − ū'(a) v_d; ū' = K on the half-space)
        return cap * self.segment.vx * slope - shift_slope * self.segment.vd

    def _rate_parts(self, var: float) -> tuple[float, float]:
        """``∂d/∂a`` and ``dū/da`` (``nan`` under Coulomb's caps, which do not read it) at a moving span's
        variable, kept for the last :data:`RATES_KEPT` variables (:func:`variable_key`): both caps' :meth:`rate` read
        them, at the span's ends twice over (:meth:`met_at_start`, :meth:`event_functions`), the same numbers."""
        if self._rates is None:
            self._rates = {}
        key = variable_key(var)
        found = None if key is None else self._rates.get(key)
        if found is None:
            a = var * self.scale
            found = (self.branch.slope(a), math.nan if self.kappa else self.medium.shift_slope(self.K, a))
            if key is not None:
                if len(self._rates) >= RATES_KEPT:
                    del self._rates[next(iter(self._rates))]
                self._rates[key] = found
        return found

    def may_push(self, cap: Cap) -> bool:
        """Whether the cap's level can move towards its springs during the span: its rate is positive at
        either end (the rate is monotone in the radius: ``∂d/∂a`` increases along a branch).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        bool
            ``True`` if its :meth:`rate` is positive at the span's start or stop.
        """
        return self.rate(cap, self.start) > 0.0 or self.rate(cap, self.stop) > 0.0

    def knots(self) -> list[float]:
        """Where the right-hand side is not smooth inside the span, in its integration variable: the branch's knots
        (:attr:`~.branch.Branch.knots`, a moving span) and where a front crosses one (:meth:`front_knots`); the
        quadrature starts a piece at each.

        Returns
        -------
        list of float
            The knots strictly inside the span, ordered from its start to its stop (none: a smooth span).
        """
        knots = sorted(set(self._radius_knots() + self.front_knots()))
        return knots if self.start < self.stop else knots[::-1]

    def _radius_knots(self) -> list[float]:
        """:attr:`~.branch.Branch.knots` strictly inside a moving span, in its integration variable (a pinned span:
        none), increasing."""
        if not self.moving or not self.branch.knots:
            return []
        low, high = min(self.start, self.stop), max(self.start, self.stop)
        return [knot / self.scale for knot in self.branch.knots if low < knot / self.scale < high]

    def front_knots(self) -> list[float]:
        """Where a slip front crosses a knot of the anchors' branch inside the span (in its integration variable,
        increasing): the front ``ξ(level)`` is the inverse of its piece, ``Y = x0 + r (d0(ξ) − d_ref)``, whose
        ``d0`` is a table's PCHIP, so the zone's size, and the right-hand side with it, has a kink of its second
        derivative where ``ξ`` passes a knot. A panel across it is cut again and again (A at 20° on a 41-point
        table: 935 readings on the growing span with a front, 225 with these knots).

        The front is read at the span's ends and its radius knots (the level may turn between them: a knot it
        crosses twice between two readings is missed, which costs panels, not accuracy); a knot between two
        readings is where the level reaches the piece's value there, every knot's root at once
        (:func:`~.span_front_knots.front_knots`: the levels read as arrays, the roots by regula falsi to
        :data:`~.span_front_knots.ROOT_ULPS` ulp of the variable).

        Returns
        -------
        list of float
            The variables (none: no branch knots, or no front).
        """
        knots = self.anchors.attach.knots
        fronts = [(cap, p) for cap in Cap for p, _, _ in self.zones[cap].fronts if not p.constant]
        if not knots or not fronts:
            return []
        readings = np.array(sorted({self.start, self.stop, *self._radius_knots()}))
        return span_front_knots.front_knots(self, knots, fronts, readings)

    def primitive(self) -> Primitive | None:
        """The span's force in closed form (:mod:`.closed_form`): a moving span without a front on the half-space,
        whose zones' sizes are linear in the radius, or on a bonded layer under ``τ0``'s law, whose zones' measures are
        linear in ``M(a)`` (:mod:`.layer_closed_form`); the medium's :meth:`~.media.HalfSpaceMedium.span_primitive`.

        Returns
        -------
        Primitive or LayerPrimitive or None
            ``P``, with ``dF_x/da = 2G* dP/da`` (:meth:`rhs`); ``None`` where the span has no closed form here (or
            :attr:`closed_form` is off).
        """
        if not (self.closed_form and self.moving) or self.has_fronts():
            return None
        return self.medium.span_primitive(self)

    # --- the right-hand side ---------------------------------------------------------------
    def rhs(self, var: float, y) -> list[float]:
        """``dF_x/da`` (moving radius) or ``dF_x/dt`` (pinned).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.
        y : array_like
            ``[F_x]``, unused (the rate does not depend on the force).

        Returns
        -------
        list of float
            ``[dF_x/dvar]`` (N per unit of the variable).
        """
        segment, K = self.segment, self.K
        a = self.radius_of(var)
        t = self.time_of(var)
        x = segment.x(t)
        shift = self.caps.centre_shift(a, segment.d(t))
        key = variable_key(var)
        if key is not None:  # (level's memo: the events read a panel's end right after its check reading there)
            self._last_level = (key, x, shift)
        positive = self.positive.size(x - shift, a)
        negative = self.negative.size(x + shift, a)
        sticking = self.medium.measure(0.0, a) - positive - negative
        if not self.moving:  # a pinned radius: the caps follow the depth alone, κ v_d per spring at a cap while pressed
            total = sticking * segment.vx
            if self.kappa and self.depth_rate:
                total += (positive - negative) * self.kappa * self.depth_rate
            return [self.G2 * total]
        slope = self.branch.slope(a)
        # the springs at a cap carry K a + κ (d − g): d/da of it is K + κ ∂d/∂a (on a layer τ0's part ū'(a))
        cap_rate = K + self.kappa * slope if self.kappa else self.medium.shift_slope(K, a)
        # (a vertical segment drives no sticking spring, even where the slope is infinite: at a = 0 of a branch)
        drive = sticking * segment.vx * slope / segment.vd if segment.vx else 0.0
        total = (positive - negative) * cap_rate + drive
        if self.shrinking:  # springs leave the edge with their shift (weighed by their stiffness w(a))
            total += self.edge_shift(x, a) * self.medium.density(a)
        return [self.G2 * total * self.scale]

    def edge_shift(self, x: float, a: float) -> float:
        """The shift of the spring at the edge: ``±ū`` at a cap (``±K a``: the edge of a contact without
        adhesion holds no Coulomb shift), else ``x − Y(a)``.

        Parameters
        ----------
        x : float
            The indenter's tangential position (m).
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The shift (m).
        """
        # (both caps in Cap's order, without iterating the enum: a shrinking span reads this at every reading)
        if self.positive.edge_in_zone:
            return Cap.POSITIVE * self.medium.shift(self.K, a)
        if self.negative.edge_in_zone:
            return Cap.NEGATIVE * self.medium.shift(self.K, a)
        return x - self.anchors.piece_value(self.anchors.pieces[-1], a)

    # --- the event functions -----------------------------------------------------------------
    def reaches(self, cap: Cap) -> Callable[[float], float]:
        """The event function of ``cap``'s level reaching its zone layout's target (rising through 0).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        callable
            ``function(var)``, the event's value at the integration variable.
        """
        zone, sign = self.zones[cap], float(cap)
        return lambda var: sign * self.level(sign, var) - zone.target(self.radius_of(var)) - self.offset

    def leaves_edge(self, cap: Cap) -> Callable[[float], float]:
        """The event function of the shrinking edge passing the front of ``cap``'s zone at the edge (rising).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        callable
            ``function(var)``, the event's value at the integration variable.
        """
        zone, sign = self.zones[cap], float(cap)
        return lambda var: zone.edge_value(self.radius_of(var)) - sign * self.level(sign, var) - self.edge_margin

    def turns(self, cap: Cap) -> Callable[[float], float]:
        """The event function of ``cap``'s sliding level turning back (its :meth:`rate`, falling through 0).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        callable
            ``function(var)``, the event's value at the integration variable.
        """
        sign = float(cap)
        return lambda var: self.rate(sign, var)

    def passes_piece(self, var: float) -> float:
        """The event function of the shrinking edge passing the start of its piece (falling through 0).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The radius minus the piece's start (m), offset by the event tolerance.
        """
        return self.radius_of(var) - self.edge_start + self.offset

    def event_functions(self) -> list[EventFunction]:
        """The events that can end the span.

        Returns
        -------
        list of EventFunction
            Terminal event functions for ``solve_ivp``, each with its trigger and cap.
        """
        events, convex = [], self.levels_convex()
        for cap in Cap:
            zone = self.zones[cap]
            if zone.target(self.a0) < float("inf") and (self.sliding[cap] or self.may_push(cap)):
                # (a fixed target: the level's convex L(t) − ū(a(t)) against a constant; the edge's own is not)
                settled = convex and not zone.edge_is_target
                events.append(EventFunction(Trigger.ZONE_REACHES, cap, self.reaches(cap), 1.0, settled))
            if self.sliding[cap] and self.shrinking and zone.edge_front_outward:
                events.append(EventFunction(Trigger.ZONE_LEAVES_EDGE, cap, self.leaves_edge(cap), 1.0))
            if self.sliding[cap] and self.moving:  # (∂d/∂a monotone in the radius on a convex branch, ū' = K)
                events.append(EventFunction(Trigger.LEVEL_TURNS, cap, self.turns(cap), -1.0, convex))
        if self.shrinking and self.edge_start > 0.0:  # (the radius against a constant: linear in the variable)
            events.append(EventFunction(Trigger.EDGE_PASSES_PIECE, None, self.passes_piece, -1.0, True))
        return events

    def levels_convex(self) -> bool:
        """Whether the caps' levels ``cap·level = cap·x − ū(a) − κ max(d, 0)`` are convex in time and their rates
        monotone in the radius on this span, so that their events' readings settle them (:mod:`.closed_form`): a
        moving radius on a convex branch (:attr:`~.branch.Branch.convex`: the radius concave in the depth, the depth
        linear in time, so ``−K a(t)`` convex, and ``∂d/∂a`` increasing), a cap linear in the radius
        (:attr:`~.media.HalfSpaceMedium.linear_cap`: ``ū = K a``, ``ū' = K``) and Coulomb's ``κ max(d, 0)`` linear
        on the span (the depth keeps its sign; ``x`` is linear on a segment).

        Returns
        -------
        bool
            ``True`` where the proof holds; ``False`` leaves the events to the closed form's curvature guard.
        """
        if not (self.moving and self.branch.convex and self.medium.linear_cap):
            return False
        depths = self.segment.d(self.span.t_start), self.segment.d(self.span.t_end)
        return not self.kappa or min(depths) >= 0.0 or max(depths) <= 0.0

    def met_at_start(self) -> frozenset[Fired]:
        """Events that have already happened at the span's start (they fire at once): a level already
        beyond its target, a sliding level that does not push (e.g. after a corner).

        Returns
        -------
        frozenset of tuple
            The ``(Trigger, Cap)`` pairs met (empty: none).
        """
        met = set()
        if not self.model.caps.frictionless and self.a0 > 0:
            for cap in Cap:
                if (self.sliding[cap] or self.may_push(cap)) and self.reaches(cap)(self.start) > 0.0 \
                        and not self.edge_beside_full(cap):
                    met.add((Trigger.ZONE_REACHES, cap))
        if met:
            return frozenset(met)
        for cap in Cap:
            if self.sliding[cap]:
                rate = self.rate(cap, self.start)
                if rate < 0.0 or (self.moving and rate <= 0.0):
                    met.add((Trigger.LEVEL_TURNS, cap))
                elif self.shrinking and self.zones[cap].edge_front_outward and self.leaves_edge(cap)(self.start) > 0:
                    met.add((Trigger.ZONE_LEAVES_EDGE, cap))
        return frozenset(met)

    def edge_beside_full(self, cap: Cap) -> bool:
        """Whether ``cap``'s target at the start is the edge's own value while every spring sits at the other cap under
        Coulomb's law alone (``K = 0``): there the gap ``2κ (d − g(a))`` between the level and the target vanishes
        identically (:func:`~.solve.edge_zone_beside_full`, which lays the zone out as none), so a reading above 0 at
        the start is the rounding of ``g(a)``, not a zone reached (met again at once, for ever: a power law of n = 9
        or 12 under Coulomb's law at the corner of scenario A, 20 ulp of the level against an offset of 18).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        bool
            ``True`` where the start's reading of :meth:`reaches` is to be ignored.
        """
        zone = self.zones[cap]
        if self.model.caps.K != 0.0 or not zone.edge_is_target:
            return False
        radius = self.radius_of(self.start)
        return zone.edge_value(radius) <= zone.fixed_target \
            and self.zones[Cap(-cap)].summary(radius).slip is Slip.FULL

    def max_step(self) -> float:
        """The longest step of the solver (in the integration variable): with a front in a piece, a share
        1/:data:`MIN_STEPS_PER_SPAN` of the span (the front's smooth continuation ends where its piece meets the
        branch's fold, and one step across the whole span can reach it); else none.

        Returns
        -------
        float
            The step (``inf``: none).
        """
        return abs(self.stop - self.start) / MIN_STEPS_PER_SPAN if self.has_fronts() else math.inf

    def grading(self) -> Grading | None:
        """The span's variable graded towards a singular end (:mod:`.graded`; ``None``: not graded).

        Returns
        -------
        Grading or None
            ``None``: the force's rate is smooth up to the span's ends.
        """
        return None

    def finish(self, outcome: SpanOutcome) -> SpanOutcome:
        """What :func:`~.integrate.integrate_span` returns of the span's ``outcome`` (the outcome itself: the span
        read the stored anchors as they were given).

        Parameters
        ----------
        outcome : SpanOutcome
            How the span ended.

        Returns
        -------
        SpanOutcome
            ``outcome``.
        """
        return outcome

    def has_fronts(self) -> bool:
        """Whether a slip front lies inside a piece (the solver's steps are then limited:
        :func:`~.integrate.integrate_span`).

        Returns
        -------
        bool
            ``True`` if either cap's layout holds a front.
        """
        return bool(self.positive.fronts or self.negative.fronts)

    def force_is_linear(self) -> bool:
        """A pinned span without fronts: the slip zones hold whole pieces and keep their sizes until an
        event, so ``dF_x/dt = 2G* ((a − n₊ − n₋) v_x + (n₊ − n₋) κ ḋ)`` is constant and the events' times are
        closed forms (``ḋ``: :attr:`depth_rate`).

        Returns
        -------
        bool
            ``True`` for a pinned span whose zones have no front.
        """
        return not self.moving and not self.positive.fronts and not self.negative.fronts

    def linear_rate(self) -> float:
        """``dF_x/dt`` of a span whose force is linear in time (:meth:`force_is_linear`):
        ``2G* ((M(a) − n₊ − n₋) v_x + (n₊ − n₋) κ ḋ)``.

        Returns
        -------
        float
            The rate (N/s).
        """
        a = self.span.pinned_radius
        positive, negative = self.positive.size(0.0, a), self.negative.size(0.0, a)
        rate = self.G2 * (self.medium.measure(0.0, a) - positive - negative) * self.segment.vx
        if self.kappa and self.depth_rate:  # the springs at a cap follow κ d (the flat punch pressed in or out)
            rate += self.G2 * (positive - negative) * self.kappa * self.depth_rate
        return rate

    def linear_span(self, force: float) -> SpanOutcome:
        """:meth:`force_is_linear`: the force (:meth:`linear_rate`) and the first event in closed form (the levels
        are linear in time; each cap's target is fixed), the span's interpolant a :class:`LinearForce`.

        Parameters
        ----------
        force : float
            ``F_x`` (N) at the span's start.

        Returns
        -------
        SpanOutcome
            The events that stop it (none: its planned end), the time, force and radius there.
        """
        a = self.span.pinned_radius
        rate = self.linear_rate()
        t_stop, fired = self.stop, frozenset()
        for event in self.event_functions():  # only ZONE_REACHES in a pinned span: linear in time
            speed = event.trigger is Trigger.ZONE_REACHES and event.cap * self.segment.vx - self.kappa * self.depth_rate
            if speed and speed > 0.0:
                when = self.start - event(self.start) / speed
                if when < t_stop:
                    t_stop, fired = when, frozenset({event.key})
                elif when == t_stop and fired:
                    fired = fired | {event.key}
        self.span.interpolant = LinearForce(self.start, t_stop, force, rate)
        return SpanOutcome(fired, t_stop, force + rate * (t_stop - self.start), a)

    def force_is_constant(self) -> bool:
        """Nothing moves the force: a span of zero extent, or a pinned one without tangential motion or
        with every spring at one cap, whose caps keep still (no Coulomb part following the depth).

        Returns
        -------
        bool
            ``True`` if ``F_x`` stays what it is over the span.
        """
        full = any(self.zones[cap].summary(self.a0).slip is Slip.FULL for cap in Cap)
        still = not (self.kappa and self.depth_rate)
        return self.start == self.stop or (not self.moving and still and (self.segment.vx == 0.0 or full))


class LinearForce:
    """The force of a span where it is linear in time, ``F(t) = F0 + rate (t − t0)``, called like
    ``solve_ivp``'s dense output (``interpolant(t)[0]``) and with its breakpoints ``ts``."""

    def __init__(self, t0: float, t1: float, force: float, rate: float):
        self.t0, self.force, self.rate = t0, force, rate
        self.ts = [t0, t1]

    def __call__(self, t) -> np.ndarray:
        """Shape ``(1,)`` for a scalar ``t``, ``(1, n)`` for ``n`` times, as ``OdeSolution``."""
        return (self.force + self.rate * (np.asarray(t, dtype=float) - self.t0))[None, ...]
