"""Unit tests of the continuum's parts: the branch, the anchor map, the slip zones, the table of logged zone
changes and the planner."""

import math

import numpy as np
import pytest
from scipy import integrate

import mdr_events as me
from continuum_maps import reversing_anchors
from mdr_events.models.continuum import (NO_ZONE, ZONE_EVENTS, AnchorMap, Branch, Cap, ContactState, ContinuumModel,
                                         EventKind, Piece, Regime, Segment, Slip, Tolerances, ZoneSummary, kinematics,
                                         lay_out_zones, plan_span, zone_events)
from mdr_events.models.continuum.branch import FOLD_SHARE
from mdr_events.models.continuum.caps import Caps
from mdr_events.models.continuum.plan import Action

RTOL = 1e-14
EPS = float(np.finfo(float).eps)


@pytest.fixture(scope="module")
def model(paper):
    return ContinuumModel(paper, Tolerances())


# --- the branch -------------------------------------------------------------------------------------
@pytest.mark.parametrize("work", [0.0, 0.01, 0.15])
def test_branch_radius_and_depth_are_inverse(paper, work):
    """radius(depth(a)) = a and depth(radius(d)) = d on the stable branch (a above the jump-off radius), to
    the root finder's accuracy; the scalar and vectorised evaluations agree."""
    branch = Branch(paper, work)
    radii = np.linspace(max(branch.jump_off_radius, 1e-5) * 1.01, 8e-3, 40)
    for a in radii:
        d = branch.depth(float(a))
        assert branch.radius(d, RTOL) == pytest.approx(a, rel=1e-12)
    depths = branch.depths(radii)
    np.testing.assert_allclose(branch.radii(depths), radii, rtol=1e-12)
    np.testing.assert_allclose([branch.depth(float(a)) for a in radii], depths, rtol=1e-15)


def test_branch_at_and_below_the_fold(paper):
    """At the jump-off depth the radius is the jump-off radius (a double root: accurate to sqrt(eps)); a
    rounding below it still is; further below there is no contact (nan)."""
    branch = Branch(paper, paper.dgamma1)
    fold = branch.jump_off_depth  # negative: the contact hangs on above the surface
    assert branch.radius(fold, RTOL) == pytest.approx(branch.jump_off_radius, rel=1e-7)
    assert branch.radius(fold * (1 + 0.5 * FOLD_SHARE), RTOL) == branch.jump_off_radius
    assert math.isnan(branch.radius(fold * (1 + 2 * FOLD_SHARE), RTOL))
    assert branch.slope(branch.jump_off_radius) == pytest.approx(0.0, abs=1e-10)


def test_branch_slope_and_integral_are_derivative_and_integral_of_the_depth(paper):
    branch = Branch(paper, paper.dgamma0)
    for a in (1e-3, 3e-3, 5e-3):
        h = 1e-7 * a
        assert branch.slope(a) == pytest.approx((branch.depth(a + h) - branch.depth(a - h)) / (2 * h), rel=1e-6)
        assert branch.integral(a) == pytest.approx(integrate.quad(branch.depth, 0.0, a, epsrel=1e-13)[0], rel=1e-10)


def test_hertz_branch_is_sqrt_R_d(paper):
    branch = Branch(paper, 0.0)
    assert branch.radius(2e-4, RTOL) == pytest.approx(math.sqrt(paper.R * 2e-4), rel=1e-15)
    assert branch.radius(-1e-12, RTOL) == 0.0 and branch.slope(0.0) == 0.0


# --- the anchor map ----------------------------------------------------------------------------------
@pytest.fixture
def anchors(model):
    """:func:`continuum_maps.reversing_anchors`: constant, rising and falling pieces."""
    return reversing_anchors(model, RTOL)


def fine_grid(anchors, radius, n=400_001):
    """Midpoints of a fine grid on [0, radius] and the anchors there (a brute-force reference)."""
    xi = (np.arange(n) + 0.5) * radius / n
    return xi, np.concatenate([anchors.piece_values(p, xi[(xi >= p.start) & (xi < p.end)]) for p in anchors.pieces])


def test_anchor_map_values_continue_across_pieces(anchors):
    branch = anchors.attach
    jump_in = anchors.pieces[0].end
    assert anchors.value(0.5 * jump_in) == 0.0
    for xi in (1.2 * jump_in, 2e-3, 2.9e-3):
        assert anchors.value(xi) == pytest.approx(2.0 * (branch.depth(xi) - branch.depth(jump_in)), rel=1e-13)
    assert anchors.value(3e-3) == pytest.approx(anchors.piece_value(anchors.pieces[1], 3e-3), rel=1e-13)
    assert anchors.value(3.5e-3) < anchors.value(3e-3)  # the falling piece


@pytest.mark.parametrize("share", [-0.2, 0.0, 0.3, 0.7, 1.2])
def test_zone_sizes_and_clipped_shift_integral_match_a_fine_grid(anchors, share):
    """Both caps' zone sizes |{ξ <= a: ±Y <= ±level}| and ∫ clip(x − Y, −ū, ū) dξ against the midpoint
    rule on 400 001 points: its error is below one cell per front (a / 400 001 ~ 1e-8 m) and its
    quadrature error O(h²)."""
    a = 3.8e-3
    xi, values = fine_grid(anchors, a)
    top = anchors.value(3e-3)
    level = share * top
    cell = a / len(xi)
    assert anchors.zone_size(Cap.POSITIVE, level, a) == pytest.approx(np.count_nonzero(values <= level) * cell,
                                                                       abs=3 * cell)
    assert anchors.zone_size(Cap.NEGATIVE, level, a) == pytest.approx(np.count_nonzero(values >= level) * cell,
                                                                       abs=3 * cell)
    x, cap_shift = level, 0.25 * top
    expected = np.clip(x - values, -cap_shift, cap_shift).sum() * cell
    assert anchors.clipped_shift_integral(x, cap_shift, a) == pytest.approx(expected, rel=1e-8,
                                                                             abs=1e-8 * top * a)


def test_clip_materialises_the_play_operator_and_merges_constants(anchors):
    """After clip(lower, upper), Y equals clip of the old Y everywhere; a window below the whole map leaves
    one constant piece."""
    a = 3.8e-3
    xi = np.linspace(0.0, a, 997)
    old = np.array([anchors.value(v) for v in xi])
    top = anchors.value(3e-3)
    clipped = anchors.copy()
    clipped.clip(0.3 * top, 0.8 * top, a)
    np.testing.assert_allclose([clipped.value(v) for v in xi], np.clip(old, 0.3 * top, 0.8 * top),
                               rtol=1e-12, atol=1e-12 * top)
    flat = anchors.copy()
    flat.clip(-2 * top, -top, a)
    assert flat.pieces == [Piece(0.0, a, -top)]


def test_extend_close_truncate(anchors):
    """Extending forgets what lies beyond its start and merges a resumed growth into one piece; closing
    fixes the growth's end; truncating forgets the springs beyond a radius."""
    rising = anchors.pieces[1]
    anchors.extend(2.5e-3, Piece(2.5e-3, math.inf, rising.x0, rising.ratio, rising.d_ref))
    assert len(anchors.pieces) == 2 and anchors.pieces[-1].end == math.inf
    anchors.close(3.4e-3)
    assert anchors.pieces[-1].end == 3.4e-3
    anchors.extend(3.0e-3, Piece(3.0e-3, math.inf, 1e-5))
    assert [p.end for p in anchors.pieces] == [anchors.pieces[0].end, 3.0e-3, math.inf]
    anchors.truncate(2e-3)
    assert [p.end for p in anchors.pieces] == [anchors.pieces[0].end, 2e-3]


def test_algebraic_force_of_a_uniform_field(model):
    """Springs all anchored at x0: F_x = 2G* a (x − x0) while it sticks, ±τ0 π a² once |x − x0| >= ū(a)."""
    anchors = AnchorMap(model.grow, RTOL, [Piece(0.0, 3e-3, 1e-6)])
    a, G, K = 3e-3, model.params.G_star, model.K
    assert anchors.tangential_force(Caps(K, 0.0), G, 1e-6 + 0.5 * K * a, a) == pytest.approx(2 * G * a * 0.5 * K * a, rel=1e-12)
    full = anchors.tangential_force(Caps(K, 0.0), G, 1e-6 + 2 * K * a, a)
    assert full == pytest.approx(model.params.tau0 * math.pi * a**2, rel=1e-12)
    assert anchors.tangential_force(Caps(K, 0.0), G, 1e-6 - 2 * K * a, a) == pytest.approx(-full, rel=1e-12)
    assert anchors.tangential_force(Caps(K, 0.0), G, 1.0, 0.0) == 0.0


@pytest.mark.parametrize("offset_per_cap", [1e6, 1e9])
def test_a_full_slip_far_from_the_origin_keeps_its_digits(model, offset_per_cap):
    """The springs all at the cap give ±τ0 π a² to rounding wherever the indenter is: at 1e-3° the indenter
    sits 1e9 ū from the origin, and ``x a − ∫ clip(Y)`` kept only ``1e-16 · 1e9`` of the force."""
    a, G, K = 3e-3, model.params.G_star, model.K
    x0 = offset_per_cap * K * a
    uniform = AnchorMap(model.grow, RTOL, [Piece(0.0, a, x0)])
    for sign in (1.0, -1.0):
        force = uniform.tangential_force(Caps(K, 0.0), G, x0 + sign * 3 * K * a, a)
        assert force == pytest.approx(sign * model.params.tau0 * math.pi * a**2, rel=8 * EPS)


def _resting_at(x: float) -> Segment:
    """A segment on which the indenter rests at ``x`` (no travel: the layout's tolerance is of the lengths alone)."""
    return Segment(0.0, 1.0, x, 1e-4, 0.0, 0.0)


# --- the slip zones --------------------------------------------------------------------------------
@pytest.mark.parametrize("share", [0.3, 0.9])
def test_a_zone_layout_starts_at_the_exact_size_and_ends_at_its_target(anchors, model, share):
    """Laid out at a level, a zone's (smooth) size is the exact zone size there; its target is the next
    value of the map the level reaches: a front leaving its piece or a new piece starting to slide."""
    a = 3.8e-3
    top = anchors.value(3e-3)
    level = share * top
    zones = lay_out_zones(anchors, model.caps, _resting_at(level + model.K * a), 0.0, a, {cap: True for cap in Cap}, model.grow.depth_term)
    positive = zones[Cap.POSITIVE]
    assert positive.size(level, a) == pytest.approx(anchors.zone_size(Cap.POSITIVE, level, a), rel=1e-12)
    # the rising piece's front reaches its end (top), or the falling piece starts to slide at its edge value
    assert positive.target(a) == pytest.approx(min(top, anchors.value(a)) if level < anchors.value(a) else top,
                                               rel=1e-12)
    assert positive.summary(a).slip is Slip.PARTIAL and positive.summary(a).centre
    resting = lay_out_zones(anchors, model.caps, _resting_at(level + model.K * a), 0.0, a, {cap: False for cap in Cap}, model.grow.depth_term)
    assert resting[Cap.POSITIVE].size(level, a) == 0.0 and resting[Cap.POSITIVE].summary(a) == NO_ZONE
    assert resting[Cap.POSITIVE].target(a) == 0.0  # the lowest anchor: slip onset


# --- the table of logged zone changes ---------------------------------------------------------------------
@pytest.mark.parametrize("before, after, expected", [
    (Slip.STICK, Slip.PARTIAL, (EventKind.SLIP_ONSET,)),
    (Slip.STICK, Slip.FULL, (EventKind.SLIP_ONSET, EventKind.FULL_SLIP)),
    (Slip.PARTIAL, Slip.FULL, (EventKind.FULL_SLIP,)),
    (Slip.PARTIAL, Slip.STICK, (EventKind.FRONT_AT_EDGE,)),
    (Slip.FULL, Slip.STICK, (EventKind.FRONT_AT_EDGE,)),
    (Slip.FULL, Slip.PARTIAL, ()),
])
def test_every_row_of_the_zone_table(before, after, expected):
    summary = {Slip.STICK: NO_ZONE, Slip.PARTIAL: ZoneSummary(Slip.PARTIAL, True, False),
               Slip.FULL: ZoneSummary(Slip.FULL, True, True)}
    assert zone_events(summary[before], summary[after]) == expected == ZONE_EVENTS[(before, after)]


def test_re_stick_and_fronts_reaching_the_centre_or_the_edge():
    partial = ZoneSummary(Slip.PARTIAL, False, False)
    assert zone_events(partial, NO_ZONE, restuck=True) == (EventKind.RE_STICK,)
    assert zone_events(NO_ZONE, NO_ZONE, restuck=True) == ()
    assert zone_events(partial, ZoneSummary(Slip.PARTIAL, True, False)) == (EventKind.FRONT_AT_CENTRE,)
    assert zone_events(partial, ZoneSummary(Slip.PARTIAL, True, True)) == (EventKind.FRONT_AT_CENTRE,
                                                                          EventKind.FRONT_AT_EDGE)
    assert zone_events(ZoneSummary(Slip.PARTIAL, True, True), ZoneSummary(Slip.PARTIAL, True, False)) == ()
    assert len(ZONE_EVENTS) == 6


# --- the planner ----------------------------------------------------------------------------------------
def segment_of(params, waypoints, index=0):
    return kinematics(me.Path(waypoints, params.v))[index]


def state_in_contact(model, radius, t=0.0):
    anchors = AnchorMap(model.grow, RTOL, [Piece(0.0, radius, 0.0)])
    return ContactState(t=t, anchors=anchors, in_contact=True, radius=radius)


def test_plan_out_of_contact(model):
    p = model.params
    above = segment_of(p, [(0, -1e-4), (0, 3e-4)])
    plan = plan_span(model, ContactState(t=0.0, anchors=AnchorMap(model.grow, RTOL)), above)
    assert plan.action is Action.APPROACH and plan.t_end == pytest.approx(1e-4 / p.v)
    touching = plan_span(model, ContactState(t=plan.t_end, anchors=AnchorMap(model.grow, RTOL)), above)
    assert touching.action is Action.TOUCH and touching.entry_events == (EventKind.FIRST_CONTACT,)
    assert touching.radius == pytest.approx(me.analytic.jump_in_radius(p, p.dgamma0), rel=1e-12)


def test_plan_growth_pinned_and_detachment(model):
    p = model.params
    down = segment_of(p, [(0, 0), (1e-4, 3e-4)])
    a_on = model.grow.radius(1e-4, RTOL)
    on_branch = plan_span(model, state_in_contact(model, a_on, t=down.time_at_depth(1e-4)), down)
    assert on_branch.regime is Regime.GROWING and on_branch.t_end == down.t1 and on_branch.end_kind is None
    assert on_branch.growth[-1].ratio == pytest.approx(1 / 3)
    held = plan_span(model, state_in_contact(model, model.grow.radius(2e-4, RTOL), t=down.time_at_depth(1e-4)), down)
    assert held.regime is Regime.PINNED and held.end_kind is EventKind.GROWTH_RESUMES
    assert held.t_end == pytest.approx(down.time_at_depth(2e-4), rel=1e-12)
    up = segment_of(p, [(0, 3e-4), (0, -1e-4)])
    a_max = model.grow.radius(3e-4, RTOL)
    pinned = plan_span(model, state_in_contact(model, a_max), up)
    assert pinned.regime is Regime.PINNED and pinned.end_kind is EventKind.DETACHMENT_STARTS
    assert up.d(pinned.t_end) == pytest.approx(model.shrink.depth(a_max), rel=1e-12)
    state = state_in_contact(model, a_max, t=pinned.t_end)
    state.detaching = True
    shrinking = plan_span(model, state, up)
    assert shrinking.regime is Regime.SHRINKING and shrinking.end_kind is EventKind.PULL_OFF and not shrinking.entry_events
    assert up.d(shrinking.t_end) == pytest.approx(model.shrink.jump_off_depth, rel=1e-12)


def test_plan_the_held_radius_inside_the_fold_comes_off(model):
    held = 0.9 * model.shrink.jump_off_radius
    threshold = model.shrink.depth(held)  # on the unstable part of the Δγ1 branch
    up = segment_of(model.params, [(0, threshold), (0, threshold - 1e-4)])
    plan = plan_span(model, state_in_contact(model, held), up)
    assert plan.action is Action.COME_OFF and plan.end_kind is EventKind.PULL_OFF


def test_plan_drop_onto_the_smaller_branch_and_jump_back_in(paper):
    """Δγ1 < Δγ0: going out, the radius drops onto the Δγ1 branch at once (detachment announced at once) and
    the force becomes that of the smaller contact; going in again, springs jump in up to the Δγ0 branch."""
    params = paper.replace(dgamma1=0.0)
    model = ContinuumModel(params, Tolerances())
    a_max = model.grow.radius(3e-4, RTOL)
    up = segment_of(params, [(0, 3e-4), (0, 2e-4)])
    state = state_in_contact(model, a_max)
    x_slid = 0.5 * model.K * a_max
    state.force = state.anchors.tangential_force(model.caps, params.G_star, x_slid, a_max)
    drop = plan_span(model, state, up)
    assert drop.regime is Regime.SHRINKING and drop.entry_events == (EventKind.DETACHMENT_STARTS,)
    assert drop.radius == pytest.approx(model.shrink.radius(3e-4, RTOL), rel=1e-15) and drop.radius < a_max
    down = segment_of(params, [(0, 2e-4), (1e-4, 3e-4)])
    small = model.shrink.radius(2e-4, RTOL)
    back = plan_span(model, state_in_contact(model, small), down)
    assert back.regime is Regime.GROWING and back.jumped_from == small
    assert back.radius == pytest.approx(model.grow.radius(2e-4, RTOL), rel=1e-15)
    assert back.growth[0].ratio == 0.0 and back.growth[0].x0 == 0.0 and back.growth[1].ratio == pytest.approx(1.0)
