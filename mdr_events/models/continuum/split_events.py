"""The events of a span of ``"tau0+coulomb"`` with adhesion (:class:`~.split_span.SplitSpanIntegrator`), each keyed by
its cap and region: a level reaching its layout's target (the source's value at ``x_c`` among them), a zone leaving
through a receding end, a sliding level turning back, ``x_c`` passing a part's boundary, the edge passing a part; and
those met at the span's start.
"""

from __future__ import annotations

import math

from .regions import Region
from .span import EventFunction, Trigger
from .split_layouts import Key

__all__ = ["RegionEvent", "SplitEvents"]


class RegionEvent(EventFunction):
    """An event function of one cap in one region (its key names both)."""

    def __init__(self, trigger: Trigger, key: Key | None, function, direction: float):
        super().__init__(trigger, key[1] if key else None, function, direction)
        self.region = key[0] if key else None

    @property
    def key(self) -> tuple:
        """What the event is, with its region.

        Returns
        -------
        tuple
            ``(trigger, cap, region)``.
        """
        return (self.trigger, self.cap, self.region)


class SplitEvents:
    """The event functions of :class:`~.split_span.SplitSpanIntegrator` (a mixin: it reads the integrator's layouts,
    levels, rates, extents and tolerances)."""

    def reaches_in(self, key: Key):
        """The level of the cap of the region reaching its layout's target (rising through 0).

        Parameters
        ----------
        key : tuple of (Region, Cap)
            The region and the cap.

        Returns
        -------
        callable
            ``function(var)``.
        """
        layout, sign = self.layouts[key], float(key[1])
        return lambda var: (sign * self.region_level(key, var) - layout.target(*self.extent(key[0], var))
                            - self.offset)

    def leaves_in(self, key: Key, end: int):
        """A moving end of the region leaving the cap's zone that lies at it (rising through 0).

        Parameters
        ----------
        key : tuple of (Region, Cap)
            The region and the cap.
        end : int
            0 for the start, 1 for the end.

        Returns
        -------
        callable
            ``function(var)``.
        """
        layout, sign = self.layouts[key], float(key[1])
        return lambda var: (layout.end_value(end, *self.extent(key[0], var)) - sign * self.region_level(key, var)
                            - self.edge_margin)

    def recedes(self, region: Region, end: int) -> bool:
        """Whether the region's start (0) or end (1) moves into it during the span (springs leave the region there).

        Parameters
        ----------
        region : Region
            The region.
        end : int
            0 for the start, 1 for the end.

        Returns
        -------
        bool
            ``True`` if it moves into the region.
        """
        if region is Region.COMPRESSED:
            return end == 1 and (self.direction < 0 or (self.x_c_is_edge and self.shrinking))
        return (end == 0 and self.direction > 0) or (end == 1 and self.shrinking)

    def passes_break(self, var: float) -> float:
        """``x_c`` passing the next part boundary (rising through 0, in the depth: ``g(b)`` is where it passes).

        Parameters
        ----------
        var : float
            The integration variable: the time (s) of a pinned span, the radius over :attr:`scale` of a moving one.

        Returns
        -------
        float
            The event's value (m).
        """
        return self.direction * (self.depth_of(var) - self.break_depth) - self.depth_offset

    def event_functions(self) -> list[EventFunction]:
        """The events that can end the span (module docstring).

        Returns
        -------
        list of EventFunction
            Terminal event functions for ``solve_ivp``, each keyed by its trigger, cap and region.
        """
        events = []
        for key, layout in self.layouts.items():
            sliding = self.sliding[key]
            if layout.target(*self.extent(key[0], self.start)) < math.inf and (sliding or self.pushes(key)):
                events.append(RegionEvent(Trigger.ZONE_REACHES, key, self.reaches_in(key), 1.0))
            if sliding:
                events += [RegionEvent(Trigger.ZONE_LEAVES_EDGE, key, self.leaves_in(key, end), 1.0)
                           for end in layout.leaving if self.recedes(key[0], end)]
            if sliding and self.moving:
                events.append(RegionEvent(Trigger.LEVEL_TURNS, key, self._turns(key), -1.0))
        if self.next_break is not None:
            events.append(RegionEvent(Trigger.BOUNDARY_PASSES_PART, None, self.passes_break, 1.0))
        if self.shrinking and self.edge_start > 0.0:
            events.append(RegionEvent(Trigger.EDGE_PASSES_PIECE, None, self.passes_piece, -1.0))
        return events

    def _turns(self, key: Key):
        region, cap = key
        return lambda var: self.rate(region, cap, var)

    def met_at_start(self) -> frozenset:
        """Events that have already happened at the span's start: a pushing level beyond its target; else a sliding
        level that does not push, or a zone already gone through a receding end.

        Returns
        -------
        frozenset of tuple
            The keys met (empty: none).
        """
        # (a level moving away at the start reaches nothing there: beyond it by rounding only, after a re-stick)
        met = {(Trigger.ZONE_REACHES, key[1], key[0]) for key in self.layouts
               if self.rate(key[0], key[1], self.start) > 0.0 and self.reaches_in(key)(self.start) > 0.0}
        if met or self.a0 <= 0.0:
            return frozenset(met)
        for key, layout in self.layouts.items():
            if not self.sliding[key]:
                continue
            rate = self.rate(key[0], key[1], self.start)
            if rate < 0.0 or (self.moving and rate <= 0.0):
                met.add((Trigger.LEVEL_TURNS, key[1], key[0]))
            elif any(self.recedes(key[0], end) and self.leaves_in(key, end)(self.start) > 0.0
                     for end in layout.leaving):
                met.add((Trigger.ZONE_LEAVES_EDGE, key[1], key[0]))
        return frozenset(met)
