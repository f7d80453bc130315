"""Unit tests of the continuum's parts: the branch, the anchor map, the transition table and the planner."""

import math

import numpy as np
import pytest
from scipy import integrate

import mdr_events as me
from mdr_events.models.continuum import (AnchorMap, Branch, ContactState, ContinuumModel, EventKind, Piece, Regime,
                                         SLIP_TRANSITIONS, Slip, Tolerances, kinematics, next_slip, plan_span)
from mdr_events.models.continuum.branch import FOLD_SHARE
from mdr_events.models.continuum.plan import Action

RTOL = 1e-14


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
    """A jump-in plateau at x = 0, growth at dx/dd = 2 from the jump-in depth, re-stuck slid springs."""
    branch = model.grow
    jump_in = me.analytic.jump_in_radius(model.params, model.params.dgamma0)
    growth = Piece(jump_in, 4e-3, 0.0, 2.0, branch.depth(jump_in))
    return AnchorMap(branch, RTOL, [Piece(0.0, jump_in, 0.0), growth])


def test_anchor_map_values_and_integral(anchors):
    branch = anchors.attach
    jump_in = anchors.pieces[0].end
    assert anchors.value(0.5 * jump_in) == 0.0
    for xi in (1.2 * jump_in, 2e-3, 3.9e-3):
        assert anchors.value(xi) == pytest.approx(2.0 * (branch.depth(xi) - branch.depth(jump_in)), rel=1e-13)
    for lower, upper in ((0.0, 4e-3), (0.3 * jump_in, 2.5e-3), (2e-3, 3e-3)):
        expected = integrate.quad(anchors.value, lower, upper, points=[jump_in], epsrel=1e-12)[0]
        assert anchors.integral(lower, upper) == pytest.approx(expected, rel=1e-10, abs=1e-22)


def test_slip_fronts_solve_their_definition(anchors):
    """c = sup{ξ <= a: Y(ξ) <= level}: 0 below Y(0), a above Y(a), Y(c) = level inside a growth piece; the
    scalar front is one point of the vectorised ones."""
    a = 3.5e-3
    top = anchors.value(a)
    levels = np.array([-1e-6, 0.0, 0.25 * top, 0.5 * top, 0.99 * top, 2 * top])
    fronts = anchors.fronts(levels, np.full(levels.shape, a))
    assert fronts[0] == 0.0 and fronts[-1] == a
    assert fronts[1] == anchors.pieces[0].end  # the plateau at Y = 0 slides as a whole
    for level, front in zip(levels[2:-1], fronts[2:-1]):
        assert anchors.value(front) == pytest.approx(level, rel=1e-10)
        assert anchors.front(level, a) == front


def test_restick_extend_close(anchors):
    """Re-sticking gives the slid springs one anchor and keeps the rest; extending forgets what lies beyond
    its start and merges a resumed growth into one piece; closing fixes the growth's end."""
    before = anchors.value(3e-3)
    anchors.restick(2e-3, -5e-6)
    assert anchors.value(1e-3) == -5e-6 and anchors.value(1.99e-3) == -5e-6
    assert anchors.value(3e-3) == before
    growth = anchors.pieces[-1]
    anchors.extend(3.2e-3, Piece(3.2e-3, math.inf, growth.x0, growth.ratio, growth.d_ref))
    assert len(anchors.pieces) == 2 and anchors.pieces[-1].end == math.inf
    anchors.close(3.4e-3)
    assert anchors.pieces[-1].end == 3.4e-3
    anchors.extend(3.0e-3, Piece(3.0e-3, math.inf, 1e-5))
    assert [p.end for p in anchors.pieces] == [2e-3, 3.0e-3, math.inf]


def test_algebraic_force_of_a_uniform_field(model):
    """Springs all anchored at x0: F_x = 2G* a (x − x0) while it sticks, τ0 π a² once x − x0 >= ū(a)."""
    anchors = AnchorMap(model.grow, RTOL, [Piece(0.0, 3e-3, 1e-6)])
    a, G, K = 3e-3, model.params.G_star, model.K
    assert anchors.tangential_force(K, G, 1e-6 + 0.5 * K * a, a) == pytest.approx(2 * G * a * 0.5 * K * a, rel=1e-12)
    full = anchors.tangential_force(K, G, 1e-6 + 2 * K * a, a)
    assert full == pytest.approx(model.params.tau0 * math.pi * a**2, rel=1e-12)
    assert anchors.tangential_force(K, G, 1.0, 0.0) == 0.0


# --- the transition table ----------------------------------------------------------------------------
@pytest.mark.parametrize("state, fired, expected", [
    (Slip.STICK, {EventKind.SLIP_ONSET}, Slip.PARTIAL),
    (Slip.STICK, {EventKind.SLIP_ONSET, EventKind.FULL_SLIP}, Slip.FULL),
    (Slip.PARTIAL, {EventKind.FULL_SLIP}, Slip.FULL),
    (Slip.PARTIAL, {EventKind.RE_STICK}, Slip.STICK),
    (Slip.STICK, {EventKind.FULL_SLIP}, Slip.FULL),
    (Slip.PARTIAL, {EventKind.FULL_SLIP, EventKind.RE_STICK}, Slip.STICK),
])
def test_every_row_of_the_transition_table(state, fired, expected):
    assert next_slip(state, frozenset(fired)) is expected
    assert SLIP_TRANSITIONS[(state, frozenset(fired))] is expected


def test_the_table_has_exactly_those_rows_and_refuses_the_rest():
    assert len(SLIP_TRANSITIONS) == 6
    for slip in Slip:
        assert next_slip(slip, frozenset()) is slip
        assert next_slip(slip, frozenset({EventKind.FRONT_CROSSES_PIECE})) is slip
    with pytest.raises(RuntimeError, match="does not allow"):
        next_slip(Slip.FULL, frozenset({EventKind.SLIP_ONSET}))
    with pytest.raises(RuntimeError, match="does not allow"):
        next_slip(Slip.STICK, frozenset({EventKind.RE_STICK}))


# --- the planner ----------------------------------------------------------------------------------------
def segment_of(params, waypoints, index=0):
    return kinematics(me.Path(waypoints, params.v)).segments[index]


def state_in_contact(model, radius, slip=Slip.STICK, t=0.0):
    anchors = AnchorMap(model.grow, RTOL, [Piece(0.0, radius, 0.0)])
    return ContactState(t=t, anchors=anchors, in_contact=True, radius=radius, slip=slip)


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
    state.force = state.anchors.tangential_force(model.K, params.G_star, x_slid, a_max)
    drop = plan_span(model, state, up)
    assert drop.regime is Regime.SHRINKING and drop.entry_events == (EventKind.DETACHMENT_STARTS,)
    assert drop.radius == pytest.approx(model.shrink.radius(3e-4, RTOL), rel=1e-15) and drop.radius < a_max
    down = segment_of(params, [(0, 2e-4), (1e-4, 3e-4)])
    small = model.shrink.radius(2e-4, RTOL)
    back = plan_span(model, state_in_contact(model, small), down)
    assert back.regime is Regime.GROWING and back.jumped_from == small
    assert back.radius == pytest.approx(model.grow.radius(2e-4, RTOL), rel=1e-15)
    assert back.growth[0].ratio == 0.0 and back.growth[0].x0 == 0.0 and back.growth[1].ratio == pytest.approx(1.0)
