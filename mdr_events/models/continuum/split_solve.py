"""The transitions of ``"tau0+coulomb"`` with adhesion on a curved indenter (:mod:`.split_span`), beside those of
:mod:`.solve` for one region.

After a span the maps it read its two regions from are joined at ``x_c`` into the stored anchors (:func:`commit`). At
an event every cap of every region is laid out anew; what is logged is the table of :mod:`.state` on each cap's zone
over the whole contact (:func:`~.regions.combined_summary`): a cap's zone re-sticks (RE_STICK) where a level that
turned back leaves it without springs in either region, and full slip is ``τ0 π a² + μ F_N^H(d)``, the compressed
springs' push (``adhesive_full_slip_force``).
"""

from __future__ import annotations

from mdr_events.models.paths import Path
from .formulas import Shape
from .model import ContinuumModel, Segment
from .regions import Region, combined_summary
from .span import SpanOutcome, Trigger
from .span_record import Span
from .split_map import SpanMaps, SplitAnchorMap
from .split_layouts import Instant, lay_out_regions, split_lengths
from .state import NO_ZONE, Cap, ContactState, EventKind, Slip, zone_events
from .tolerances import PIECE_SHARE
from .zones import cap_travel, indenter_travel

__all__ = ["new_anchors", "commit", "split_slip_transition", "split_full_slip_force"]

#: How far beyond the largest contact a front's smooth continuation may look for the turns of the anchors (a share
#: of that radius).
REACH_SHARE = 2.0


def new_anchors(model: ContinuumModel, path: Path) -> SplitAnchorMap:
    """An empty map of the anchors of ``model`` along ``path``: its :class:`~.formulas.Shape` reaches
    :data:`REACH_SHARE` times the largest contact the path makes (the radius of its deepest point).

    Parameters
    ----------
    model : ContinuumModel
        The contact.
    path : Path
        The path.

    Returns
    -------
    SplitAnchorMap
        The empty map.
    """
    rtol = model.tolerances.radius_rtol
    largest = model.grow.radius(max(path.max_depth, 0.0), rtol)
    reach = REACH_SHARE * largest
    table = getattr(getattr(model.hertz, "line", None), "shape", None)
    if table is not None:  # a table's g ends with it
        reach = min(reach, table.x_max)
    return SplitAnchorMap(Shape(model.hertz, model.grow, model.shrink, rtol, reach))


def commit(state: ContactState, outcome: SpanOutcome, span: Span) -> SpanMaps:
    """The span's maps joined at ``x_c`` into the stored anchors, and the slip it laid out kept; returns the maps,
    the span's record (its regions' anchors at every instant of it).

    Parameters
    ----------
    state : ContactState
        The automaton's state (its anchors and slip are set).
    outcome : SpanOutcome
        How the span ended.
    span : Span
        The span.

    Returns
    -------
    SpanMaps
        The span's maps.
    """
    maps = outcome.maps if outcome.maps is not None else state.anchors.maps()
    if outcome.sliding is not None:
        state.regions.update(outcome.sliding)
    depth = span.segment.d(outcome.t_stop)
    state.anchors = maps.joined(maps.boundary(depth, outcome.radius), outcome.t_stop)
    return maps


def split_full_slip_force(model: ContinuumModel, radius: float, depth: float) -> float:
    """``|F_x|`` with every spring at one cap: ``τ0 π a² + μ F_N^H(d)``, ``F_N^H`` the push of the compressed zone
    ``[0, x_c]`` (the normal force (10) of the depth on the radius ``x_c``; 0 in tension).

    Parameters
    ----------
    model : ContinuumModel
        The contact.
    radius : float
        The contact radius (m).
    depth : float
        The depth (m).

    Returns
    -------
    float
        ``|F_x|`` (N).
    """
    force = 2.0 * model.params.G_star * model.K * radius**2
    if depth > 0.0:
        boundary = model.hertz.radius(depth, model.tolerances.radius_rtol)
        force += model.friction.coulomb_mu * float(model.normal_force(depth, boundary))
    return force


def _layouts(model: ContinuumModel, state: ContactState, segment: Segment, t: float, radius: float) -> dict:
    """Every cap's zone in every region at ``t``, the ends still (an instant between spans)."""
    x, depth = segment.x(t), segment.d(t)
    anchors = state.anchors
    travel = max(indenter_travel(segment, t, radius, model.grow.depth_term), cap_travel(model.caps.kappa, segment, t))
    tolerance = PIECE_SHARE * split_lengths(anchors, model.caps.centre_shift(radius, depth), x, travel)
    boundary = min(anchors.shape.boundary(depth), radius)
    return lay_out_regions(anchors.maps(), model.caps, Instant(x, depth, radius, boundary), state.regions, tolerance)


def split_slip_transition(model: ContinuumModel, state: ContactState, outcome: SpanOutcome, radius: float,
                          segment: Segment) -> list[tuple[EventKind, float, float, int]]:
    """Events stopped the span: every cap of every region laid out anew, what changed of each cap's zone logged
    (the table of :mod:`.state`), and a level that turned back re-sticks its springs (the window materialised).

    Parameters
    ----------
    model : ContinuumModel
        The contact.
    state : ContactState
        The automaton's state (changed).
    outcome : SpanOutcome
        How the span ended.
    radius : float
        The contact radius there (m).
    segment : Segment
        The path segment.

    Returns
    -------
    list of tuple
        The events to log, ``(kind, path time, radius, direction)``.
    """
    state.force, state.radius, state.t = outcome.force, radius, outcome.t_stop
    state.last_fired = outcome.fired
    if (Trigger.EDGE_PASSES_PIECE, None, None) in outcome.fired:
        state.anchors.drop_edge_piece(radius)
    state.anchors.truncate(radius)
    for trigger, cap, region in outcome.fired:
        if trigger is Trigger.ZONE_REACHES:
            state.regions[(region, cap)] = True
    t = outcome.t_stop
    layouts = _layouts(model, state, segment, t, radius)
    turned = {(region, cap) for trigger, cap, region in outcome.fired if trigger is Trigger.LEVEL_TURNS}
    if turned:
        state.anchors.clip_caps(segment.x(t), model.caps, segment.d(t), radius)
    logged = []
    for cap in Cap:
        summaries = {region: layouts[(region, cap)].summary() if (region, cap) in layouts else None
                     for region in Region}
        after = combined_summary(summaries[Region.COMPRESSED], summaries[Region.TENSILE])
        before = state.zones[cap]
        events = zone_events(before, after)
        if after.slip is Slip.FULL and before.slip is not Slip.FULL:
            state.force = cap * split_full_slip_force(model, radius, segment.d(t))
        kept = {region: (NO_ZONE if (region, cap) in turned and summary is not None else summary)
                for region, summary in summaries.items()}
        remaining = combined_summary(kept[Region.COMPRESSED], kept[Region.TENSILE])
        if remaining.slip is Slip.STICK and after.slip is not Slip.STICK:
            events += zone_events(after, NO_ZONE, restuck=True)
        for region in Region:
            state.regions[(region, cap)] = kept[region] is not None and kept[region].slip is not Slip.STICK
        state.sliding[cap] = any(state.regions.get((region, cap), False) for region in Region)
        state.zones[cap] = remaining
        logged += [(kind, t, radius, int(cap)) for kind in events]
    return logged
