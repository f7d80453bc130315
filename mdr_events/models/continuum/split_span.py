"""One span of ``"tau0+coulomb"`` with adhesion on a curved indenter: two regions split at the moving ``x_c``.

The force obeys

    dF_x/dt = 2G* [ (n₊ − n₋) K ȧ + (n₊ᶜ − n₋ᶜ) κ ḋ + (a − n₊ − n₋) v_x + ȧ u(a) ],

with ``n±`` the springs at the caps ``±`` and ``n±ᶜ`` those of them in the compressed zone ``[0, x_c]`` (their cap
``K a + κ (d − g)`` follows the depth; in the tensile annulus ``[x_c, a]`` the cap is ``K a``), as
:mod:`.span` integrates it for one region. Each cap of each region is laid out at the span's start
(:class:`~.regions.RegionLayout`) with the region's ends: ``x_c`` moves with the depth (``dx_c/dd = 1/g'(x_c)``,
``compression_boundary_rate``), ``a`` with the radius. Springs cross ``x_c`` from the region ``x_c`` moves into
(the *source*) to the other (the *destination*); a spring at a cap of the source when it crosses keeps the window of
that instant, ``x(τ) − σ K a(τ)`` (both caps are ``K a`` at ``x_c``): the destination is read from the stored map with
those anchors over the interval ``x_c`` sweeps (:func:`~.split_layouts.crossing_formula`), and slides there from the
start if its level pushes. Whether the spring at ``x_c`` is at a cap is the source's to say: its value at ``x_c``
reaching or leaving the level is an event, and so is ``x_c`` passing the boundary of a part
(``Trigger.BOUNDARY_PASSES_PART``), besides the events of one region (a level reaching its target, a zone leaving
through the shrinking edge, a sliding level turning back, the edge passing a part: :mod:`.split_events`).
"""

from __future__ import annotations

import math

from .graded import Grading, grading_power
from .model import ContinuumModel
from .regions import Region, combined_summary
from .span import SpanIntegrator, SpanOutcome, Trigger
from .span_record import Span
from .split_events import SplitEvents
from .split_layouts import KEYS, Ends, Instant, Key, STILL, crossing_formula, lay_out_regions, split_lengths
from .split_map import SpanMaps, SplitAnchorMap
from .split_zones import SpanZones
from .state import Cap, Regime, Slip
from .tolerances import EPS, LEVEL_ULPS, MIN_STEPS_PER_SPAN, PIECE_SHARE
from .zones import EDGE_LEAVING_TOLERANCES, cap_travel, indenter_travel

__all__ = ["SplitSpanIntegrator", "FRONT_STEPS_PER_SPAN"]

#: A solver step covers at most 1/this of a span with a front reaching the centre (it moves as ``g⁻¹`` of a level,
#: ``∝ (t_end − t)^(1/n)``, whose end DOP853's error estimate can miss in one long step) or with ``x_c`` moving at the
#: surface: the τ0 integrator's share (:data:`~.tolerances.MIN_STEPS_PER_SPAN`). It was 32 (twice the solver's steps
#: of scenario A at 20°); at 8 the integrated F_x stays within 5e-10 of its run at rtol 1e-13 on scenarios A and B
#: at 20–70°, fretting, the cone, n = 1.5 and n = 3 with and without Δγ0, and within 9e-9 of the algebraic form on
#: 60 random paths of the property test, as at 32 (the 3e-7 once seen at 8 steps on n = 3 predates the roots taken
#: to an absolute share of their interval).
FRONT_STEPS_PER_SPAN = MIN_STEPS_PER_SPAN
#: The same share on a profile whose tip no whole power smooths (a table, the flat punch: no span is graded,
#: :func:`~.graded.grading_power`): 32 as before the grading, since at 8 a table's F_x on scenario B at 30° with
#: adhesion went from 2.0e-9 to 1.35e-8 of its run at rtol 1e-13 (the review of the graded spans).
UNGRADED_FRONT_STEPS_PER_SPAN = 32
#: A span whose depth at one end is this share of the other's starts or ends at the surface (the planner ends spans
#: where the depth crosses 0; the depth there carries the rounding of the time)
SURFACE_SHARE = 1e-6
class SplitSpanIntegrator(SplitEvents, SpanIntegrator):
    """The right-hand side and the events of one span with the compressed zone and the tensile annulus (module
    docstring); the interface of :class:`~.span.SpanIntegrator`, whose variable (time or radius) it keeps.

    Parameters
    ----------
    model : ContinuumModel
    anchors : SplitAnchorMap
        The stored anchors (read, not changed).
    span : Span
        The span to integrate.
    sliding : dict
        Whether springs slide at each cap in each region (keys ``(Region, Cap)``; missing: not).
    """

    #: the force is a quadrature (:func:`~.span_panels.panels`): the right-hand side and the events read the span's
    #: variable alone
    quadrature = True
    #: no closed form (:mod:`.closed_form` reads one region's zones, linear in the radius; a split span's regions move
    #: with ``x_c``)
    closed_form = False

    def __init__(self, model: ContinuumModel, anchors: SplitAnchorMap, span: Span, sliding: dict):
        #: ``(var, instant)`` of the last :meth:`instant` asked (``None``: none yet)
        self._last_instant = None
        #: the edge's region and the cap the spring there is at (:meth:`edge_shift`; ``None``: not yet asked)
        self._edge = None
        super().__init__(model, anchors, span, sliding)

    def front_knots(self) -> list[float]:
        """None: a split span's fronts are the parts of its regions' formulas (:mod:`.split_layouts`), read by its own
        events; only the branch's knots start its pieces.

        Returns
        -------
        list of float
            ``[]``.
        """
        return []

    def lay_out(self, anchors: SplitAnchorMap, sliding: dict) -> None:
        """The layouts of every cap in every region at the span's start, the crossing's anchors, the tolerances.

        Parameters
        ----------
        anchors : SplitAnchorMap
            The stored anchors.
        sliding : dict
            Whether springs slide at each cap in each region.
        """
        model, segment, t0 = self.model, self.segment, self.span.t_start
        self.shape = anchors.shape
        self.x_c_is_edge = self.moving and self.branch.work == 0.0  # (a branch without adhesion: d = g(a))
        self.pressed = segment.d(0.5 * (t0 + self.span.t_end)) > 0.0  # (a span ends where the depth crosses 0)
        self.direction = math.copysign(1.0, segment.vd) if (self.pressed and segment.vd and not self.x_c_is_edge) \
            else 0.0
        self.sliding = {key: bool(sliding.get(key, False)) for key in KEYS}
        depth = self.depth_of(self.start)
        reach = self.scale * max(self.start, self.stop) if self.moving else self.a0
        lengths = split_lengths(anchors, model.caps.centre_shift(self.a0, depth), self.x0,
                                max(indenter_travel(segment, t0, reach, model.grow.depth_term),
                                    cap_travel(model.caps.kappa, segment, max(abs(t0), abs(self.span.t_end)))))
        self.offset = LEVEL_ULPS * EPS * lengths
        self.edge_margin = EDGE_LEAVING_TOLERANCES * PIECE_SHARE * lengths
        self.tolerance = PIECE_SHARE * lengths
        # the depth's rounding: of its terms (g(a) on a branch), and of the time times the depth's rate
        self.depth_offset = 4 * LEVEL_ULPS * EPS * max(abs(depth), abs(self.depth_of(self.stop)),
                                                       model.grow.depth_term(reach),
                                                       abs(self.span.t_end * segment.vd))
        joined = anchors.joined_at
        self.start_boundary = joined[1] if joined is not None and joined[0] == t0 and self.pressed else None
        self.ends = self._ends()
        boundary = self.boundary(self.start)
        self.maps = anchors.maps()
        self.layouts = lay_out_regions(self.maps, model.caps, Instant(self.x0, depth, self.a0, boundary), self.sliding,
                                       self.tolerance, self.ends)
        if self.direction:
            self._cross(anchors, boundary, depth)
        edge = self._edge_region()  # the start of the edge's part, where it is a boundary between parts
        self.edge_start = max((self.layouts[(edge, cap)].parts[-1].start for cap in Cap
                               if (edge, cap) in self.layouts and len(self.layouts[(edge, cap)].parts) > 1),
                              default=0.0)
        self.next_break = self._next_break(boundary) if self.direction else None
        self.break_depth = self.shape.hertz.depth(self.next_break) if self.next_break is not None else math.nan
        # each layout with what its level and extent need, read once: (key, layout, σ, the region's weight, compressed,
        # whether its size is its fixed inner parts' alone: no front, no part with a moving end)
        self.keyed = [(key, layout, float(key[1]), key[0].weight, key[0] is Region.COMPRESSED,
                       not (layout.fronts or layout.moving_in)) for key, layout in self.layouts.items()]
        self.graded = self._grading()

    def _ends(self) -> dict[Region, Ends]:
        """How each region's ends move: ``x_c`` with the depth (the source's end recedes, the destination's grows and
        holds no target there), ``a`` with the radius."""
        crossing, growing = self.direction != 0.0, self.span.regime is Regime.GROWING
        edge_moves = self.x_c_is_edge and self.moving
        compressed = Ends((False, crossing or edge_moves), (False, self.direction > 0 or (edge_moves and growing)),
                          (True, not self.direction > 0), edge_moves and growing)
        if self.x_c_is_edge:
            return {Region.COMPRESSED: compressed, Region.TENSILE: STILL}
        tensile = Ends((crossing, self.moving), (self.direction < 0, growing), (not self.direction < 0, True), growing)
        return {Region.COMPRESSED: compressed, Region.TENSILE: tensile}

    def _cross(self, anchors: SplitAnchorMap, boundary: float, depth: float) -> None:
        """Where the spring at ``x_c`` is at a cap of the source, the destination reads the crossing's anchors over the
        swept interval (:func:`~.split_layouts.crossing_formula`) and slides there from the start if its level
        pushes."""
        source = Region.TENSILE if self.direction > 0 else Region.COMPRESSED
        destination = Region.COMPRESSED if source is Region.TENSILE else Region.TENSILE
        end = 0 if source is Region.TENSILE else 1
        for cap in Cap:
            layout = self.layouts.get((source, cap))
            if layout is not None and layout.at_cap(end):
                formula = crossing_formula(anchors, self.segment, self.span.regime, self.a0, cap, self.K)
                stop = self.boundary(self.stop)
                swept = anchors.replaced(min(boundary, stop), max(boundary, stop), formula)
                self.maps = SpanMaps(swept, anchors) if destination is Region.COMPRESSED else SpanMaps(anchors, swept)
                if self.rate(destination, cap, self.start) > 0.0:
                    self.sliding[(destination, cap)] = True
                self.layouts.update(lay_out_regions(self.maps, self.model.caps,
                                                    Instant(self.x0, depth, self.a0, boundary), self.sliding,
                                                    self.tolerance, self.ends, destination))
                return

    def _edge_region(self) -> Region:
        """The region that holds the contact's edge: the annulus, unless it holds no spring."""
        return Region.TENSILE if (Region.TENSILE, Cap.POSITIVE) in self.layouts else Region.COMPRESSED

    def _next_break(self, boundary: float) -> float | None:
        """The nearest part boundary beyond ``x_c`` in its direction, in either region's map and view, inside the
        interval ``x_c`` sweeps (``None``: none)."""
        stop, depth, g = self.boundary(self.stop), self.depth_of(self.start), self.shape.hertz.depth
        found = []
        for region, cap in KEYS:
            shift = region.view_shift(cap, self.kappa)
            found += self.maps.of(region).breaks(shift, boundary, stop)
        # passed already: within the depth's rounding of x_c (in the depth, g(b) against d)
        inside = [b for b in found if self.direction * (g(b) - depth) > self.depth_offset
                  and self.direction * (stop - b) > 0]
        return (min if self.direction > 0 else max)(inside) if inside else None

    # --- the state along the span ---------------------------------------------------------------
    def depth_of(self, var: float) -> float:
        """The depth (m) at the integration variable.

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The depth (m).
        """
        last = self._last_instant  # (the instant remembered, else the depth alone: lay_out asks before x_c is known)
        return last[1][3] if last is not None and last[0] == var else self.segment.d(self.time_of(var))

    def boundary(self, var: float) -> float:
        """``x_c`` at the integration variable: the radius on a branch without adhesion, 0 in tension (at the start
        where the stored map was joined, exactly there).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            ``x_c`` (m).
        """
        return self.instant(var)[4]

    def _boundary_at(self, var: float, a: float, depth: float) -> float:
        """:meth:`boundary` where the radius ``a`` and the depth at ``var`` are known."""
        if self.x_c_is_edge:
            return a
        if var == self.start and self.start_boundary is not None:
            return min(self.start_boundary, a)
        return min(self.shape.boundary(depth), a) if self.pressed else 0.0

    def instant(self, var: float) -> tuple[float, float, float, float, float]:
        """``(t, a, x, d, x_c)`` at the integration variable, each computed once (as the methods above give them).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        tuple of float
            The time (s), the radius, the indenter's position, the depth and ``x_c`` (m; the last variable's
            remembered: the event functions read the instant of the panel's end the right-hand side read last).
        """
        last = self._last_instant
        if last is not None and last[0] == var:
            return last[1]
        t = self.time_of(var)
        a = self.radius_of(var)
        depth = self.segment.d(t)
        found = (t, a, self.segment.x(t), depth, self._boundary_at(var, a, depth))
        self._last_instant = (var, found)
        return found

    def extent(self, region: Region, var: float) -> tuple[float, float]:
        """The region's springs ``[lower, upper]`` at the integration variable.

        Parameters
        ----------
        region : Region
            The region.
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        tuple of float
            ``(lower, upper)`` (m).
        """
        _, a, _, _, boundary = self.instant(var)
        return (0.0, boundary) if region is Region.COMPRESSED else (boundary, a)

    def region_level(self, key: Key, var: float) -> float:
        """The level of the cap of the region (:meth:`~.regions.Region.level`) at the integration variable.

        Parameters
        ----------
        key : tuple of (Region, Cap)
            The region and the cap.
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The level (m).
        """
        region, cap = key
        _, a, x, depth, _ = self.instant(var)
        return region.level(cap, x, self.K, self.kappa, a, depth)

    def rate(self, region: Region, cap: Cap | float, var: float) -> float:
        """A quantity with the sign of ``σ d(level)/dt`` of the region's cap (:meth:`~.span.SpanIntegrator.rate`).

        Parameters
        ----------
        region : Region
            The region.
        cap : Cap or float
            The side, +1 or −1.
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The signed rate (its sign is what counts).
        """
        coulomb = region.weight * self.kappa * (self.segment.vd if self.pressed else 0.0)
        if not self.moving:
            return cap * self.segment.vx - coulomb
        return (cap * self.segment.vx - coulomb) * self.branch.slope(var * self.scale) - self.K * self.segment.vd

    def pushes(self, key: Key) -> bool:
        """Whether the level of the cap of the region can move towards its springs during the span.

        Parameters
        ----------
        key : tuple of (Region, Cap)
            The region and the cap.

        Returns
        -------
        bool
            ``True`` if its rate is positive at the span's start or stop.
        """
        return self.rate(key[0], key[1], self.start) > 0.0 or self.rate(key[0], key[1], self.stop) > 0.0

    # --- the right-hand side ------------------------------------------------------------------
    def sizes(self, var: float) -> dict[Key, float]:
        """The zone of each cap in each region at the integration variable (m).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        dict
            The sizes (m), keyed ``(Region, Cap)``.
        """
        return self._sizes_at(self.instant(var))

    def _sizes_at(self, instant: tuple[float, float, float, float, float]) -> dict[Key, float]:
        """:meth:`sizes` at an :meth:`instant`."""
        _, a, x, depth, boundary = instant
        tau0_part, kappa = self.K * a, self.kappa  # (Region.level's terms, in its order)
        return {key: layout.size(x - sign * (tau0_part + weight * kappa * depth), *((0.0, boundary) if compressed
                                                                                   else (boundary, a)))
                for key, layout, sign, weight, compressed, _ in self.keyed}

    def rhs(self, var: float, y) -> list[float]:
        """``dF_x/da`` (moving radius) or ``dF_x/dt`` (pinned): module docstring.

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.
        y : array_like
            ``[F_x]``, unused.

        Returns
        -------
        list of float
            ``[dF_x/dvar]``.
        """
        segment = self.segment
        _, a, x, depth, boundary = self.instant(var)
        tau0_part, kappa = self.K * a, self.kappa  # (as _sizes_at, the sums in its order)
        at_caps = compressed = held = 0.0
        for _, layout, sign, weight, in_compressed, still in self.keyed:
            size = layout.inner if still else layout.size(x - sign * (tau0_part + weight * kappa * depth),
                                                          *((0.0, boundary) if in_compressed else (boundary, a)))
            at_caps += sign * size
            held += size
            if in_compressed:
                compressed += sign * size
        sticking = a - held
        if not self.moving:  # K a is still; the compressed caps follow the depth
            total = sticking * segment.vx + (compressed * self.kappa * segment.vd if self.pressed else 0.0)
            return [self.G2 * total]
        slope = self.branch.slope(a)
        drive = sticking * segment.vx * slope / segment.vd if segment.vx else 0.0
        total = at_caps * self.K + compressed * self.kappa * slope + drive
        if self.shrinking:
            total += self.edge_shift(x, a)
        return [self.G2 * total * self.scale]

    def edge_shift(self, x: float, a: float) -> float:
        """The shift of the spring at the edge: ``±K a`` at a cap (its compression is zero at most), else
        ``x − Y(a)``.

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
        if self._edge is None:  # (the edge's region and the cap it is at, if any: the layouts keep still)
            edge = self._edge_region()
            self._edge = (edge, next((cap for cap in Cap if (edge, cap) in self.layouts
                                      and self.layouts[(edge, cap)].at_cap(1)), None))
        edge, cap = self._edge
        if cap is not None:
            return cap * self.K * a
        return x - self.maps.of(edge).value(a)

    # --- spans without integration ----------------------------------------------------------------
    def has_fronts(self) -> bool:
        """Whether a slip front lies inside a part of some region.

        Returns
        -------
        bool
            ``True`` if a layout holds a front.
        """
        return any(layout.fronts for layout in self.layouts.values())

    def max_step(self) -> float:
        """The longest step of the solver: with a front in a part, or ``x_c`` moving on a span that starts or ends at
        the surface (``x_c ∝ d^(1/n)``, steep there, where a long step reaches: 2e-6 of F_x with four steps over a
        span ending at ``d = 0`` that an event stopped far before), a share 1/:data:`FRONT_STEPS_PER_SPAN` of the
        span (the τ0 integrator's).

        Returns
        -------
        float
            The step (``inf``: none).
        """
        depths = abs(self.depth_of(self.start)), abs(self.depth_of(self.stop))
        at_surface = min(depths) <= SURFACE_SHARE * max(depths)
        centre = any(layout.parts[index].low == 0.0 for layout in self.layouts.values() for index, _ in layout.fronts)
        graded = self.graded
        towards_centre = graded is not None and graded.event is not None  # (else graded towards the surface)
        limited = (centre and not towards_centre) or (self.direction != 0.0 and at_surface
                                                      and not (graded is not None and not towards_centre))
        steps = FRONT_STEPS_PER_SPAN if grading_power(self.shape.hertz.tip_power) is not None \
            else UNGRADED_FRONT_STEPS_PER_SPAN
        return abs(self.stop - self.start) / steps if limited else math.inf

    def grading(self) -> Grading | None:
        """The variable graded towards the span's stop where ``x_c`` moves and the stop is at the surface
        (:mod:`.graded`: ``x_c ∝ d^(1/n)`` steep there), or towards the time a front reaches the centre of its part on
        a pinned span (``∝ (t_e − t)^(1/n)``; the span ends there with that event).

        Returns
        -------
        Grading or None
            ``v = origin + (start − origin) u^p``; ``None`` for any other span, or a profile whose tip is not a
            power that a whole ``p`` smooths (:func:`~.graded.grading_power`).
        """
        return self.graded

    def _grading(self) -> Grading | None:
        """:meth:`grading`, found once at the span's start: towards the surface, else towards a front reaching the
        centre (:meth:`_centre_grading`)."""
        power = grading_power(self.shape.hertz.tip_power)
        if power is None:
            return None
        first, last = abs(self.depth_of(self.start)), abs(self.depth_of(self.stop))
        if self.direction != 0.0 and first > 0.0 and last <= SURFACE_SHARE * first:
            return Grading(self.stop, self.start - self.stop, power)
        return self._centre_grading(power)

    def _centre_grading(self, power: int) -> Grading | None:
        """On a pinned span, the earliest time a pushing level reaches the fixed target of a front moving to the centre
        of its part (the level linear in time: a closed form, inside the span), the variable graded towards it."""
        if self.moving:
            return None
        found = []
        for key, layout in self.layouts.items():
            rate = self.rate(key[0], key[1], self.start)  # (σ d(level)/dt, constant on a pinned span)
            if not rate > 0.0:
                continue
            centre = [index for index, at_start in layout.fronts if not at_start and layout.parts[index].start == 0.0]
            if any(layout.fixed_target == layout.sign * layout.parts[index].value(0.0) for index in centre):
                # (a moving end's target reached first stops the span before: solve_ivp finds it)
                excess = layout.sign * self.region_level(key, self.start) - layout.fixed_target - self.offset
                found.append((self.start - excess / rate, key))
        inside = [(time, key) for time, key in found if self.start < time < self.stop]
        if not inside:
            return None
        time, key = min(inside)
        return Grading(time, self.start - time, power, (Trigger.ZONE_REACHES, key[1], key[0]))

    def _still(self) -> bool:
        """A pinned span whose caps and regions keep still: ``x_c`` does not move (no Coulomb part follows a depth)."""
        return not self.moving and self.direction == 0.0

    def force_is_constant(self) -> bool:
        """A span of zero extent, or a still one (:meth:`_still`) without tangential motion or with every spring at one
        cap.

        Returns
        -------
        bool
            ``True`` if ``F_x`` stays what it is.
        """
        if self.start == self.stop:
            return True
        full = any(combined_summary(*(self.layouts[(region, cap)].summary() if (region, cap) in self.layouts else None
                                      for region in Region)).slip is Slip.FULL for cap in Cap)
        return self._still() and (self.segment.vx == 0.0 or full)

    def force_is_linear(self) -> bool:
        """A still span (:meth:`_still`) without fronts: ``dF_x/dt = 2G* (a − n₊ − n₋) v_x`` until an event.

        Returns
        -------
        bool
            ``True`` for a still span without fronts.
        """
        return self._still() and not self.has_fronts()

    def linear_rate(self) -> float:
        """:meth:`force_is_linear`: ``dF_x/dt = 2G* (a − n₊ − n₋) v_x``, the zones' sizes at the span's start (the
        first level reaching its target in closed form: :meth:`~.span.SpanIntegrator.linear_span`; the caps keep
        still, ``κ ḋ = 0``).

        Returns
        -------
        float
            The rate (N/s).
        """
        return self.G2 * (self.span.pinned_radius - sum(self.sizes(self.start).values())) * self.segment.vx

    def finish(self, outcome: SpanOutcome) -> SpanOutcome:
        """``outcome`` with the maps the span read and the slip it laid out (:class:`~.span.SpanOutcome`).

        Parameters
        ----------
        outcome : SpanOutcome
            How the span ended.

        Returns
        -------
        SpanOutcome
            With :attr:`~.span.SpanOutcome.maps` and :attr:`~.span.SpanOutcome.sliding` (the span keeps its layouts:
            ``Span.zones``, what its sliding fraction is read off).
        """
        self.span.zones = SpanZones(self.layouts, self.shape, self.pressed, self.x_c_is_edge)
        return outcome._replace(maps=self.maps, sliding=dict(self.sliding))
