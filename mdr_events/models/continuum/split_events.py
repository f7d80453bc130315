"""The events of a span of ``"tau0+coulomb"`` with adhesion (:class:`~.split_span.SplitSpanIntegrator`), each keyed by
its cap and region, as small functions of the integrator and the integration variable (``solve_ivp``'s events are
these functions bound to the span, :class:`RegionEvent`): a level reaching its layout's target (the source's value at
``x_c`` among them, :func:`level_reaches`), a zone leaving through a receding end (:func:`zone_leaves`), a sliding
level turning back (:func:`level_turns`), ``x_c`` passing a part's boundary (:func:`boundary_passes`), the edge
passing a part; and those met at the span's start (``SplitEvents.met_at_start``).
"""

from __future__ import annotations

import math
from functools import partial

from .regions import Region
from .span import EventFunction, Trigger
from .split_layouts import Key

__all__ = ["RegionEvent", "SplitEvents", "level_reaches", "zone_leaves", "level_turns", "boundary_passes",
           "recedes"]


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


def level_reaches(span, key: Key, var: float) -> float:
    """The level of the cap of the region past its layout's target (rising through 0 where it reaches it).

    Parameters
    ----------
    span : SplitSpanIntegrator
        The span's integrator (its layouts, levels, extents and level offset).
    key : tuple of (Region, Cap)
        The region and the cap.
    var : float
        The integration variable.

    Returns
    -------
    float
        ``σ level − target − offset`` (m).
    """
    layout = span.layouts[key]
    return float(key[1]) * span.region_level(key, var) - layout.target(*span.extent(key[0], var)) - span.offset


def zone_leaves(span, key: Key, end: int, var: float) -> float:
    """A moving end of the region past the cap's zone that lies at it (rising through 0 where it leaves it).

    Parameters
    ----------
    span : SplitSpanIntegrator
        The span's integrator.
    key : tuple of (Region, Cap)
        The region and the cap.
    end : int
        0 for the region's start, 1 for its end.
    var : float
        The integration variable.

    Returns
    -------
    float
        ``σ Y(end) − σ level − margin`` (m).
    """
    layout = span.layouts[key]
    return (layout.end_value(end, *span.extent(key[0], var)) - float(key[1]) * span.region_level(key, var)
            - span.edge_margin)


def level_turns(span, key: Key, var: float) -> float:
    """The sliding level of the cap of the region turning back (its rate, falling through 0).

    Parameters
    ----------
    span : SplitSpanIntegrator
        The span's integrator.
    key : tuple of (Region, Cap)
        The region and the cap.
    var : float
        The integration variable.

    Returns
    -------
    float
        The signed rate (:meth:`~.split_span.SplitSpanIntegrator.rate`).
    """
    return span.rate(key[0], key[1], var)


def boundary_passes(span, var: float) -> float:
    """``x_c`` passing the next part boundary (rising through 0, in the depth: ``g(b)`` is where it passes).

    Parameters
    ----------
    span : SplitSpanIntegrator
        The span's integrator (its direction, next break's depth and depth offset).
    var : float
        The integration variable.

    Returns
    -------
    float
        The event's value (m).
    """
    return span.direction * (span.depth_of(var) - span.break_depth) - span.depth_offset


def recedes(span, region: Region, end: int) -> bool:
    """Whether the region's start (0) or end (1) moves into it during the span (springs leave the region there).

    Parameters
    ----------
    span : SplitSpanIntegrator
        The span's integrator.
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
        return end == 1 and (span.direction < 0 or (span.x_c_is_edge and span.shrinking))
    return (end == 0 and span.direction > 0) or (end == 1 and span.shrinking)


class SplitEvents:
    """The event functions of :class:`~.split_span.SplitSpanIntegrator` (a mixin: the module's functions bound to the
    integrator)."""

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
                events.append(RegionEvent(Trigger.ZONE_REACHES, key, partial(level_reaches, self, key), 1.0))
            if sliding:
                events += [RegionEvent(Trigger.ZONE_LEAVES_EDGE, key, partial(zone_leaves, self, key, end), 1.0)
                           for end in layout.leaving if recedes(self, key[0], end)]
            if sliding and self.moving:
                events.append(RegionEvent(Trigger.LEVEL_TURNS, key, partial(level_turns, self, key), -1.0))
        if self.next_break is not None:
            events.append(RegionEvent(Trigger.BOUNDARY_PASSES_PART, None, partial(boundary_passes, self), 1.0))
        if self.shrinking and self.edge_start > 0.0:
            events.append(RegionEvent(Trigger.EDGE_PASSES_PIECE, None, self.passes_piece, -1.0))
        return events

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
               if self.rate(key[0], key[1], self.start) > 0.0 and level_reaches(self, key, self.start) > 0.0}
        if met or self.a0 <= 0.0:
            return frozenset(met)
        for key, layout in self.layouts.items():
            if not self.sliding[key]:
                continue
            rate = self.rate(key[0], key[1], self.start)
            if rate < 0.0 or (self.moving and rate <= 0.0):
                met.add((Trigger.LEVEL_TURNS, key[1], key[0]))
            elif any(recedes(self, key[0], end) and zone_leaves(self, key, end, self.start) > 0.0
                     for end in layout.leaving):
                met.add((Trigger.ZONE_LEAVES_EDGE, key[1], key[0]))
        return frozenset(met)
