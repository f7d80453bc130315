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
from .tolerances import DEPTH_SHARE, EPS, RADIUS_DROP_SHARE, TIME_ULPS


class Action(enum.Enum):
    """What a plan does."""

    TOUCH = "touch"        #: contact (first or again) at the plan's start; no span
    APPROACH = "approach"  #: out of contact until the plan's end (a span without force)
    CONTACT = "contact"    #: a span in contact, the force integrated
    COME_OFF = "come_off"  #: the held radius is inside the Δγ1 fold: the whole contact comes off at once


class SpanPlan(NamedTuple):
    """What happens from ``t_start`` on a segment, as far as closed forms can tell.

    Parameters
    ----------
    action : Action
        What the plan does.
    regime : Regime
        How the radius moves.
    t_start : float
        The start (s on the path's clock).
    t_end : float
        The planned end (s).
    end_kind : EventKind or None
        The regime's end event at ``t_end`` (``None``: the segment ends first).
    radius : float
        The radius (m) at the start.
    force : float
        ``F_x`` (N) at the start.
    entry_events : tuple of EventKind, default ()
        Events at ``t_start`` before the span.
    growth : tuple of Piece, default ()
        The springs attaching during a growing span.
    jumped_from : float or None, default None
        The radius before springs jumped in at the start (``None``: no jump).
    roots : tuple of (float, float, float), default ()
        The radius roots the plan took on the span's branch, each ``(depth, rtol, Branch.radius(depth, rtol))``
        (the span keeps them: :attr:`~.span_record.Span.roots`).
    """

    action: Action
    regime: Regime
    t_start: float
    t_end: float
    #: the regime's end event at ``t_end`` (``None``: the segment ends first)
    end_kind: EventKind | None
    #: radius and force at the start (after a drop onto the Δγ1 branch; at contact, the jump-in)
    radius: float
    force: float
    #: events at ``t_start`` before the span (contact, detachment that starts at once)
    entry_events: tuple[EventKind, ...] = ()
    #: the springs attaching during a growing span (those jumping in at its start first)
    growth: tuple[Piece, ...] = ()
    #: the radius before springs jumped in at the start (``None``: no jump)
    jumped_from: float | None = None
    #: the radius roots the plan took on the span's branch, ``(depth, rtol, radius)``
    roots: tuple[tuple[float, float, float], ...] = ()


def plan_span(model: ContinuumModel, state: ContactState, segment: Segment) -> SpanPlan:
    """The next span from ``state.t`` on ``segment``: regime, end time and end event.

    Parameters
    ----------
    model : ContinuumModel
        The contact's branches, caps and tolerances.
    state : ContactState
        The automaton's state.
    segment : Segment
        The path segment the state's time lies on.

    Returns
    -------
    SpanPlan
        The plan.
    """
    if not state.in_contact:
        return _plan_out_of_contact(model, state, segment)
    if segment.vd > 0:
        return _plan_inward(model, state, segment)
    if segment.vd < 0:
        return _plan_outward(model, state, segment)
    return SpanPlan(Action.CONTACT, Regime.PINNED, state.t, segment.t1, None, state.radius, state.force)


def _depth_scale(model: ContinuumModel, segment: Segment, t: float) -> float:
    """Depths this close count as equal: DEPTH_SHARE of ``d_max``, and the depth a few ulp of the time move
    the indenter by (a long path: at t = 1.7e7 s an ulp of t is 4e-9 s, a reached branch then lies up to
    ``|v_d|`` times that beyond the depth computed at the planned time)."""
    return DEPTH_SHARE * max(model.params.d_max, 1e-300) + TIME_ULPS * EPS * abs(t) * abs(segment.vd)


def _end_kind(t_end: float, segment: Segment, kind: EventKind) -> EventKind | None:
    """The regime's end event, unless the segment ends first."""
    return None if t_end >= segment.t1 else kind


def _at_surface(model: ContinuumModel, segment: Segment, t: float, t_end: float,
                kind: EventKind | None) -> tuple[float, EventKind | None]:
    """A pinned span's end where Coulomb's caps ``K a + κ max(d, 0)`` have their kink: the depth crossing 0 before
    ``t_end`` (the adhesive flat punch pulled into tension or pressed back), without an event (the next plan goes on
    from there, with the caps' new rate); else ``t_end`` and its event ``kind``."""
    if not model.caps.kappa or segment.vd == 0.0:
        return t_end, kind
    d, scale = segment.d(t), _depth_scale(model, segment, t)
    if (d < -scale if segment.vd > 0 else d > scale) and segment.time_at_depth(0.0) < t_end:
        return segment.time_at_depth(0.0), None
    return t_end, kind


def _plan_out_of_contact(model: ContinuumModel, state: ContactState, segment: Segment) -> SpanPlan:
    """Contact where the indenter reaches the surface going in, or at once if the path starts inside (the
    springs under the Δγ0 radius jump in); else approach until it reaches the surface."""
    t = state.t
    d = segment.d(t)
    scale = _depth_scale(model, segment, t)
    # reaching the surface the depth is 0 to its rounding (2e-22 m from a path starting 1e-6 m above): the contact
    # starts at the surface's radius then, not at that rounding's (a cone's 3e-21 m, where its slip from first
    # contact cannot be resolved)
    starts_inside = state.contacts == 0 and d > scale
    if (segment.vd > 0 and d >= -scale) or starts_inside:
        radius = model.grow.radius(d if starts_inside else 0.0, model.tolerances.radius_rtol)
        touch = (EventKind.FIRST_CONTACT if state.contacts == 0 else EventKind.RE_CONTACT,)
        if model.caps.frictionless:  # τ0 = 0 (μ = 0): no spring holds any shift, all slide from the start
            touch += (EventKind.SLIP_ONSET, EventKind.FULL_SLIP)
        return SpanPlan(Action.TOUCH, Regime.NONE, t, t, None, radius, 0.0, touch)
    t_next = segment.time_at_depth(0.0) if segment.vd > 0 else segment.t1
    return SpanPlan(Action.APPROACH, Regime.NONE, t, min(max(t_next, t), segment.t1), None, 0.0, 0.0)


def _plan_inward(model: ContinuumModel, state: ContactState, segment: Segment) -> SpanPlan:
    """Going in: growth on the Δγ0 branch (springs may jump in first), or pinned until the depth reaches it."""
    t, a = state.t, state.radius
    d = segment.d(t)
    threshold = model.grow.growth_depth(a)
    if d < threshold - _depth_scale(model, segment, t):
        t_end = min(segment.t1, segment.time_at_depth(threshold))
        t_end, kind = _at_surface(model, segment, t, t_end, _end_kind(t_end, segment, EventKind.GROWTH_RESUMES))
        return SpanPlan(Action.CONTACT, Regime.PINNED, t, t_end, kind, a, state.force)
    growth: tuple[Piece, ...] = ()
    jumped_from = None
    # an adhesive contact held above the surface (d < 0) presses in along the Δγ0 branch there, down to its fold
    rtol = model.tolerances.radius_rtol
    on_branch = model.grow.radius(max(d, model.grow.jump_off_depth), rtol)
    if on_branch > a * (1.0 + RADIUS_DROP_SHARE) and d > threshold + _depth_scale(model, segment, t):
        # the held radius is inside the Δγ0 branch (after a drop onto the Δγ1 branch): the springs up to
        # the branch jump in at once, at the indenter's position, as at first contact (not a radius off by the
        # depth's rounding: near first contact, a depth of 1e-17 m computed from 1e-6 m, its radius is 1e-5 off)
        growth = (Piece(a, on_branch, segment.x(t)),)
        jumped_from, a = a, on_branch
    growth += (Piece(a, math.inf, segment.xs, segment.vx / segment.vd, segment.ds),)
    t_end = _at_surface(model, segment, t, segment.t1, None)[0] if model.split else segment.t1
    if segment.d(t_end) > model.grow.edge_depth:  # (a flat face's edge reached: the radius stops, the next plan pins it)
        t_end = max(segment.time_at_depth(model.grow.edge_depth), t)
    return SpanPlan(Action.CONTACT, Regime.GROWING, t, t_end, None, a, state.force, (), growth, jumped_from,
                    ((max(d, model.grow.jump_off_depth), rtol, on_branch),))


def _plan_outward(model: ContinuumModel, state: ContactState, segment: Segment) -> SpanPlan:
    """Going out: pinned until the depth reaches the Δγ1 branch, then shrinking to the jump-off (or to
    zero without adhesion); a held radius inside the fold comes off at once."""
    t, a, force = state.t, state.radius, state.force
    d = segment.d(t)
    threshold = model.shrink.depth(a)
    touches_branch = d <= threshold + _depth_scale(model, segment, t)
    if touches_branch and a <= model.shrink.jump_off_radius:
        # every inner spring has a higher threshold than the boundary one: all come off at once
        return SpanPlan(Action.COME_OFF, Regime.PINNED, t, t, EventKind.PULL_OFF, a, force)
    if not touches_branch:
        t_end = min(segment.t1, segment.time_at_depth(threshold))
        t_end, kind = _at_surface(model, segment, t, t_end, _end_kind(t_end, segment, EventKind.DETACHMENT_STARTS))
        return SpanPlan(Action.CONTACT, Regime.PINNED, t, t_end, kind, a, force)
    t_end = min(segment.t1, segment.time_at_depth(model.shrink.jump_off_depth))
    ending = EventKind.PULL_OFF if model.shrink.work > 0 else EventKind.CONTACT_ENDS
    kind = _end_kind(t_end, segment, ending)
    if model.split:  # the compressed zone vanishes where the depth crosses 0: a span ends there
        t_end, kind = _at_surface(model, segment, t, t_end, kind)
    # the radius leaves the pinned or growing state at once (Δγ1 <= Δγ0)
    entry = () if state.detaching else (EventKind.DETACHMENT_STARTS,)
    rtol = model.tolerances.radius_rtol
    on_branch = model.shrink.radius(d, rtol)
    if on_branch == 0.0:  # (the branch has no contact left at d: the held radius comes off here, round thirty: a span
        # stopped by a slip event a rounding before the contact's end, 2e-11 m at tau0/E = 1e7, dropped onto radius 0
        # and laid out the slip zones of no springs, an IndexError)
        return SpanPlan(Action.COME_OFF, Regime.PINNED, t, t, ending, a, force)
    if on_branch < a * (1.0 - RADIUS_DROP_SHARE):
        # Δγ1 < Δγ0: the boundary springs are stretched beyond the Δγ1 limit and the radius drops onto the
        # Δγ1 branch at once; the springs it loses take their force with them and the smaller cap ū(a)
        # clips the rest (anchor map form)
        a = on_branch
        force = state.anchors.tangential_force(model.caps, model.params.G_star, segment.x(t), a, d)
    return SpanPlan(Action.CONTACT, Regime.SHRINKING, t, t_end, kind, a, force, entry, roots=((d, rtol, on_branch),))
