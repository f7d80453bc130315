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

from .model import ContinuumModel
from .regions import Region
from .span import SpanIntegrator
from .span_record import Span
from .split_events import SplitEvents
from .split_layouts import KEYS, Ends, Instant, Key, STILL, crossing_formula, lay_out_regions, split_lengths
from .split_map import SpanMaps, SplitAnchorMap
# (how a span is stepped, a module of its own; FRONT_STEPS_PER_SPAN kept here too)
from .split_span_steps import FRONT_STEPS_PER_SPAN, SplitSpanSteps  # noqa: F401
from .state import Cap, Regime
from .tolerances import EPS, LEVEL_ULPS, PIECE_SHARE
from .zones import EDGE_LEAVING_TOLERANCES, cap_travel, indenter_travel

__all__ = ["SplitSpanIntegrator", "FRONT_STEPS_PER_SPAN"]


class SplitSpanIntegrator(SplitSpanSteps, SplitEvents, SpanIntegrator):
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
