"""Plan a span: the radius regime from a time on a segment, and the span's end, in closed form.

Because the depth is linear on a segment, the time at which the radius regime ends (the depth
reaching a branch, the jump-off depth, or the end of the segment) is known before integrating.
:func:`plan_span` is pure: it reads the state and returns a :class:`SpanPlan`; the loop of
:func:`~mdr_events.models.continuum.solve.solve_path` applies it.
"""

from __future__ import annotations

import enum
import math
from typing import NamedTuple

from .anchors import Piece
from .model import ContinuumModel, Segment
from .state import ContactState, EventKind, Regime
from .tolerances import DEPTH_SHARE, RADIUS_DROP_SHARE


class Action(enum.Enum):
    """What a plan does."""

    TOUCH = "touch"        #: first contact at the plan's start; no span
    APPROACH = "approach"  #: out of contact until the plan's end (a span without force)
    CONTACT = "contact"    #: a span in contact, the force integrated
    COME_OFF = "come_off"  #: the held radius is inside the Δγ1 fold: the whole contact comes off at once


class SpanPlan(NamedTuple):
    """What happens from ``t_start`` on a segment, as far as closed forms can tell."""

    action: Action
    regime: Regime
    t_start: float
    t_end: float
    #: the regime's end event at ``t_end`` (``None``: the segment ends first)
    end_kind: EventKind | None
    #: radius and force at the start (after a drop onto the Δγ1 branch; at first contact, the jump-in)
    radius: float
    force: float
    #: events at ``t_start`` before the span (first contact, detachment that starts at once)
    entry_events: tuple[EventKind, ...] = ()
    #: the springs attaching during a growing span (those jumping in at its start first)
    growth: tuple[Piece, ...] = ()
    #: the radius before springs jumped in at the start (``None``: no jump)
    jumped_from: float | None = None


def plan_span(model: ContinuumModel, state: ContactState, segment: Segment) -> SpanPlan:
    """The next span from ``state.t`` on ``segment``: regime, end time and end event."""
    t = state.t
    d = segment.d(t)
    scale = DEPTH_SHARE * max(model.params.d_max, 1e-300)
    if not state.in_contact:
        if segment.vd > 0 and d >= -scale:
            radius = model.grow.radius(max(d, 0.0), model.tolerances.radius_rtol)
            touch = (EventKind.FIRST_CONTACT,)
            if model.K == 0.0:  # τ0 = 0: no spring holds any shift, all slide from the start
                touch += (EventKind.SLIP_ONSET, EventKind.FULL_SLIP)
            return SpanPlan(Action.TOUCH, Regime.NONE, t, t, None, radius, 0.0, touch)
        t_next = segment.time_at_depth(0.0) if segment.vd > 0 else segment.t1
        return SpanPlan(Action.APPROACH, Regime.NONE, t, min(max(t_next, t), segment.t1), None, 0.0, 0.0)
    a, force = state.radius, state.force
    growth: tuple[Piece, ...] = ()
    jumped_from = None
    end_kind = None
    if segment.vd > 0:
        threshold = model.grow.depth(a)
        if d >= threshold - scale:
            regime, t_end = Regime.GROWING, segment.t1
            on_branch = model.grow.radius(max(d, 0.0), model.tolerances.radius_rtol)
            if on_branch > a * (1.0 + RADIUS_DROP_SHARE):
                # the held radius is inside the Δγ0 branch (after a drop onto the Δγ1 branch): the springs
                # up to the branch jump in at once, at the indenter's position, as at first contact
                growth = (Piece(a, on_branch, segment.x(t)),)
                jumped_from, a = a, on_branch
            growth += (Piece(a, math.inf, segment.xs, segment.vx / segment.vd, segment.ds),)
        else:
            regime, t_end, end_kind = Regime.PINNED, min(segment.t1, segment.time_at_depth(threshold)), \
                EventKind.GROWTH_RESUMES
    elif segment.vd < 0:
        threshold = model.shrink.depth(a)
        if d <= threshold + scale and a <= model.shrink.jump_off_radius:
            # every inner spring has a higher threshold than the boundary one: all come off at once
            return SpanPlan(Action.COME_OFF, Regime.PINNED, t, t, EventKind.PULL_OFF, a, force)
        if d <= threshold + scale:
            regime = Regime.SHRINKING
            t_end = min(segment.t1, segment.time_at_depth(model.shrink.jump_off_depth))
            end_kind = EventKind.PULL_OFF if model.params.dgamma1 > 0 else EventKind.CONTACT_ENDS
        else:
            regime, t_end, end_kind = Regime.PINNED, min(segment.t1, segment.time_at_depth(threshold)), \
                EventKind.DETACHMENT_STARTS
    else:
        regime, t_end = Regime.PINNED, segment.t1
    if t_end >= segment.t1:
        end_kind = None  # the segment ends first
    entry: tuple[EventKind, ...] = ()
    if regime is Regime.SHRINKING:
        if not state.detaching:  # the radius leaves the pinned or growing state at once (Δγ1 <= Δγ0)
            entry = (EventKind.DETACHMENT_STARTS,)
        on_branch = model.shrink.radius(d, model.tolerances.radius_rtol)
        if on_branch < a * (1.0 - RADIUS_DROP_SHARE):
            # Δγ1 < Δγ0: the boundary springs are stretched beyond the Δγ1 limit and the radius drops
            # onto the Δγ1 branch at once; the springs it loses take their force with them and the
            # smaller cap ū(a) clips the rest (anchor map form)
            a = on_branch
            force = state.anchors.tangential_force(model.K, model.params.G_star, segment.x(t), a)
    return SpanPlan(Action.CONTACT, regime, t, t_end, end_kind, a, force, entry, growth, jumped_from)
