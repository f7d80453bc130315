"""Each spring's time to reach its cap in closed form (issue 34's performance, ``continuum/play_reach.py``): along a
part of the path where every window is fixed but for ``x`` (a tangential segment at a constant depth) a spring's
distance outside its window is the larger of two lines in time, so its reach is one division; the events' search of
the per-spring route takes the first or last spring's time there in place of Brent's root, and the extrema of ``F_x``
skip their refinement where ``F_x`` is monotone. Checked against the route's own distances, against Brent's root on
the same readings, and the run against the route of before (``play_run.CLOSED_REACH = False``) at every output.

Tolerances, each from how the compared values are computed:

- a spring's distance is linear at the speed ``|ẋ|`` on either side of its reach: read :data:`STEP_SHARE` of the
  part's duration before and after, it lies ``|ẋ| δ`` (some 1e-9 m) inside and outside its window, far above the
  anchors' round-off (``eps`` of ``|x| ≤ 1 mm``): its sign decides, no tolerance is spent;
- Brent's root converges to ``xtol`` an ulp plus four epsilons of the time (:data:`BRENT_ULPS`), the closed form's
  to the window it reads the share in (``play_reach.reach_ulps``: the distances' round-off over the speed): their
  sum bounds the two apart;
- the events of both routes end brackets of ``EVENT_HALVINGS`` halvings of the same output spacing; the share at
  their ends reads radii inverted in other batches (to ``RADII_RTOL``, flipping a spring at the edge by round-off):
  :data:`EVENT_BRACKETS` brackets apart at most; their radius one ``RADII_RTOL`` apart and their ``x`` moved by
  ``|ẋ|`` times that time;
- ``F_x`` summed by Gauss–Legendre over some hundred nodes (each weighted ``x − Y`` of the springs rounded to ``eps``):
  :data:`FORCE_ROUND_OFF` of the largest force for its monotony.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import play_run
from mdr_events.models.continuum.layer_branch import RADII_RTOL
from mdr_events.models.continuum.play_reach import (REACH_ULPS, REACH_ULPS_CAP, constant_part, pressed_time,
                                                   reach_times, reach_ulps)
from mdr_events.models.continuum.play_search import EVENT_HALVINGS, searched
from mdr_events.models.continuum.play_springs import PlaySprings
from play_recorders import asked_readings, made_plays

#: The paper's 5 mm layer on a bonded base.
LAYER = 5e-3
D_MAX = me.Parameters.paper().d_max
#: Output samples of the runs.
SAMPLES = 41
#: A spring's distance read this share of its part's duration before and after its closed-form reach.
STEP_SHARE = 1e-7
#: Brent's root from the distance's own, in units in the last place: half its last bracket, ``xtol`` an ulp and
#: ``rtol`` four epsilons of the time (scipy's ``brentq``, ``play_search.brent``).
BRENT_ULPS = 5
#: Two routes' events apart, in brackets of ``EVENT_HALVINGS`` halvings of the output spacing.
EVENT_BRACKETS = 2.0
#: ``F_x``'s round-off relative to its largest value (a few hundred nodes' sums: some ``100 eps``).
FORCE_ROUND_OFF = 1e-12
#: Springs read along each part (as shares of the radius).
SPRINGS = np.linspace(0.0, 1.0 - 1e-9, 257)
LAWS = ("coulomb", "tau0+coulomb")


def fretting() -> me.Paths:
    """In to ``d_max``, one tangential cycle of ±1 mm there (full slip both ways), and out."""
    x, d = [0.0, 0.0, 1e-3, -1e-3, 0.0, 0.0], [0.0, D_MAX, D_MAX, D_MAX, D_MAX, -1e-5]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


MOTIONS = {"fretting": fretting(), "A 20°": me.Scenario("A", alpha=[20.0])}


def contact_of(law: str, adhesive: bool = False) -> me.Contact:
    """The paper's contact on the layer under ``law``, with the paper's adhesion or without."""
    friction = me.FrictionLaw(law, mu=0.3, tau0=None if law == "coulomb" else me.Parameters.paper().tau0)
    paper = me.Contact.paper() if adhesive else me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)
    return dataclasses.replace(paper, friction=friction).replace(h=LAYER)


def recorded(law: str, monkeypatch) -> tuple[PlaySprings, list]:
    """The route ``simulate`` ran on the layer along :func:`fretting` and the brackets its events were searched in
    (``(low, high, onset)``, path clock)."""
    made, brackets = made_plays(monkeypatch), []

    def bisect(low, high, reached, onset, play=None):
        brackets.append((low, high, onset))
        return (yield from bisected(low, high, reached, onset, play))

    bisected = play_run._bisect
    monkeypatch.setattr(play_run, "_bisect", bisect)
    me.simulate(contact_of(law), fretting(), "continuum", samples=SAMPLES)
    assert len(made) == 1
    return made[0], brackets


@pytest.fixture(scope="module")
def route():
    """``route(law)``: :func:`recorded` of ``law``, run once for the module (the tests read the route and its brackets,
    a patch of theirs undone at their end; six runs of ~0.05 s of CPU each no longer repeated)."""
    kept = {}

    def of(law: str) -> tuple[PlaySprings, list]:
        if law not in kept:
            with pytest.MonkeyPatch.context() as patch:
                kept[law] = recorded(law, patch)
        return kept[law]

    return of


def parts(play: PlaySprings) -> list[tuple[float, float]]:
    """The path's segments along which every window is fixed but for ``x``: those at a constant depth in contact (the
    others, where the radius moves, none)."""
    corners, depths = play.path.corner_times, play.path.waypoints[:, 1]
    found, level = [], []
    for k, (low, high) in enumerate(zip(corners[:-1].tolist(), corners[1:].tolist())):
        part = constant_part(play, low, high) if high > low else None
        assert part in (None, low)  # (no clamp time inside a segment without adhesion or τ0's convexity)
        if part is not None:
            found.append((low, high))
        level.append((part is not None, depths[k] == depths[k + 1] > 0.0))
    assert found and all(fixed == at_rest for fixed, at_rest in level), level
    return found


@pytest.mark.parametrize("law", LAWS)
def test_each_spring_reaches_its_cap_at_its_closed_form_time(law, route):
    """Every spring whose closed-form reach lies inside a part is inside its window just before it and outside just
    after, on the route's own distances (``PlaySprings.outside``); those past ``high`` stay inside up to it."""
    play, _ = route(law)
    checked = 0
    for low, high in parts(play):
        xi = SPRINGS * play.radius(high)
        first, last = reach_times(play, xi, low, high)
        step = STEP_SHARE * (high - low)
        inside = (first > low + step) & (first < high - step)
        assert np.array_equal(first[inside], last[inside])  # (one crossing: the side the motion pushes towards)
        for sign, outside in ((-1.0, False), (1.0, True)):
            for spring, time in zip(xi[inside].tolist(), first[inside].tolist()):
                distance = play.outside(time + sign * step, np.array([spring]))[2][0]
                assert bool(distance > 0.0) == outside, (low, high, spring, time, sign, distance)
        never = np.isinf(first)
        assert np.all(play.outside(high, xi[never])[2] < 0.0)
        checked += int(np.count_nonzero(inside))
    assert checked  # (slip fronts cross every part)


@pytest.mark.parametrize("law", LAWS)
def test_the_closed_form_root_is_brent_s(law, route, monkeypatch):
    """Each event's search of the run whose bracket ends in a part: the closed form's root of the springs' largest or
    least distance is Brent's root of it, to the route's window about the root (``ROOT_ULPS``)."""
    play, brackets = route(law)
    compared = 0
    for low, high, onset in brackets:
        if constant_part(play, low, high) is None:
            continue
        monkeypatch.setattr(play_run, "CLOSED_REACH", True)
        closed, ulps = searched(lambda asks: play_run._readings(play, asks), [play_run._root(low, high, onset, play)])[0]
        monkeypatch.setattr(play_run, "CLOSED_REACH", False)
        brent = searched(lambda asks: play_run._readings(play, asks), [play_run._root(low, high, onset, play)])[0][0]
        assert (closed is None) == (brent is None)
        if brent is not None:
            assert abs(closed - brent) <= (ulps + BRENT_ULPS) * np.spacing(brent), (low, high, onset, closed, brent)
            compared += 1
    assert compared


@pytest.mark.parametrize("law, adhesive, motion", [(law, False, "fretting") for law in LAWS]
                         + [("coulomb", True, "fretting"), ("tau0+coulomb", True, "fretting"),
                            ("coulomb", False, "A 20°"), ("coulomb", True, "A 20°")])
def test_the_run_is_the_route_of_brent_s_root_at_every_output(law, adhesive, motion, monkeypatch):
    """The whole run with the closed forms against the route of before (Brent's root everywhere, every extremum
    refined, a full slip from the first contact bisected on the guess): every output the same, the events' times to
    :data:`EVENT_BRACKETS` brackets (with adhesion the radius the spans' run's, at rest at ``d_max``)."""
    runs = {}
    for closed in (False, True):
        monkeypatch.setattr(play_run, "CLOSED_REACH", closed)
        runs[closed] = me.simulate(contact_of(law, adhesive), MOTIONS[motion], "continuum", samples=SAMPLES)
    before, now = runs[False], runs[True]
    spacing = float(np.max(np.diff(before["time"].values)))
    bracket = spacing * 2.0 ** -EVENT_HALVINGS
    params = contact_of(law, adhesive).parameters(D_MAX, me.Parameters.paper().v)
    path = MOTIONS[motion].cases(params, None, contact_of(law, adhesive).friction).paths[0]
    speed = float(np.max(np.abs(np.diff(path.waypoints[:, 0])) / np.maximum(np.diff(path.corner_times), 1e-300)))
    for name in before.data_vars:
        if name == "event_time":
            assert np.allclose(now[name].values, before[name].values, rtol=0.0, atol=EVENT_BRACKETS * bracket,
                               equal_nan=True)
        elif name == "event_radius":
            assert np.allclose(now[name].values, before[name].values, rtol=RADII_RTOL, atol=0.0, equal_nan=True)
        elif name == "event_x":
            assert np.allclose(now[name].values, before[name].values, rtol=0.0,
                               atol=speed * EVENT_BRACKETS * bracket, equal_nan=True)
        elif np.issubdtype(before[name].dtype, np.number):
            assert np.array_equal(now[name].values, before[name].values, equal_nan=True), name
        else:
            assert np.array_equal(now[name].values, before[name].values), name


@pytest.mark.parametrize("law", LAWS)
def test_the_force_is_monotone_where_the_windows_are_fixed(law, route):
    """Along a part of fixed windows ``F_x`` moves with ``x`` or rests (what lets the extrema skip their refinement
    there): read densely, it never moves against ``x`` by more than its round-off."""
    play, _ = route(law)
    for low, high in parts(play):
        times = np.linspace(low, high, 65)[1:]
        force = play.tangential_force(times)
        direction = np.sign(play._x(high) - play._x(low))
        assert np.all(direction * np.diff(force) >= -FORCE_ROUND_OFF * np.max(np.abs(force))), (low, high)
        assert np.ptp(force) > 0.0  # (the part is not all plateau: the check can fail)


def full_slip_asks(contact: me.Contact, monkeypatch) -> list:
    """The kinds of the readings the events' searches asked along scenario A at 20° on ``contact``
    (:func:`~play_recorders.asked_readings`), the run's log holding a full slip."""
    asked = asked_readings(monkeypatch)
    run = me.simulate(contact, MOTIONS["A 20°"], "continuum", samples=SAMPLES)
    assert "full_slip" in run["event_kind"].values[0].tolist()
    return asked


def test_a_full_slip_from_the_first_contact_is_found_on_the_compressed_nodes(monkeypatch):
    """Along scenario A at 20° under Coulomb's law alone every compressed spring slides from its attachment
    (``ẋ > μρ ḋ``): full slip holds from the first node counted as compressed on, which the nodes' depths alone locate
    (``play_run._compressed``); the share checks that bracket and takes it, no guess of the anchors read (the route of
    before bisected the guess 48 times)."""
    asked = full_slip_asks(contact_of("coulomb"), monkeypatch)
    assert play_run._Reading.COMPRESSED in asked and play_run._Reading.GUESS not in asked


def test_a_full_slip_from_an_adhesive_jump_in_is_found_on_the_centre_probe(monkeypatch):
    """With the paper's adhesion the contact jumps in to a radius with no spring compressed (``x_c = 0`` at ``d = 0``):
    along scenario A at 20° under Coulomb's law alone full slip holds from the first time the centre probe counts as
    compressed (the quadrature's nodes span the jump-in's radius and count later, which the share does not follow), a
    time in closed form on the depth (``play_reach.pressed_time``) the two readings about it check; the share takes
    that bracket, no guess of the anchors read (the route of before bisected the guess 48 times and, the guess turning
    back and forth at round-off near 3e-5 s, the share 48 times more)."""
    asked = full_slip_asks(contact_of("coulomb", adhesive=True), monkeypatch)
    assert play_run._Reading.COMPRESSED in asked and play_run._Reading.GUESS not in asked


@pytest.mark.parametrize("adhesive", [False, True])
def test_the_centre_probe_counts_as_compressed_from_its_closed_form_time(adhesive, monkeypatch):
    """``pressed_time`` along scenario A at 20° from the first contact (without adhesion at ``a = 0``, with it at the
    jump-in's radius) is where the route's own test of the centre probe (``PlaySprings.centre_pressed``) flips, to
    the window the events' search checks it in (``ROOT_ULPS``: the depth is rounded once by ``np.interp`` and once by
    the division, each an ulp or two of the time): bisected on that test to neighbouring doubles, the flip lies
    within it."""
    made = made_plays(monkeypatch)
    me.simulate(contact_of("coulomb", adhesive), MOTIONS["A 20°"], "continuum", samples=SAMPLES)
    play = made[0]
    low = float(play.path.first_contact_time())
    high = float(play.path.corner_times[play.path.corner_times > low][0])
    root = pressed_time(play, low, high)
    below, above = low, high
    assert not play.centre_pressed(below)[0] and play.centre_pressed(above)[0]
    while np.nextafter(below, above) < above:  # (the flip of the route's own test, to neighbouring doubles)
        middle = 0.5 * (below + above)
        below, above = (middle, above) if not play.centre_pressed(middle)[0] else (below, middle)
    assert abs(root - above) <= play_run.ROOT_ULPS * np.spacing(above), (root, above)
    assert above > low  # (not at the contact's start: the check can fail)


def test_the_reach_window_is_finite_at_time_zero(route):
    """``reach_ulps`` at ``time = 0`` (whose ulp is the least subnormal, 5e-324) and just above it: a finite window, at
    most ``REACH_ULPS_CAP``, never narrower than at a later time (the same round-off over a smaller ulp)."""
    play, _ = route("coulomb")
    low, high = parts(play)[0]
    windows = [reach_ulps(play, low, time) for time in (0.0, 5e-324, np.finfo(float).tiny, high)]
    assert all(REACH_ULPS <= window <= REACH_ULPS + REACH_ULPS_CAP for window in windows), windows
    assert windows == sorted(windows, reverse=True) and windows[0] == REACH_ULPS + REACH_ULPS_CAP


def test_a_jump_inside_rules_the_force_s_monotony_out(route, monkeypatch):
    """``play_run._monotone`` on a part of fixed windows is true, and false once the radius's history reports a jump
    inside the part or at its end (checked on its own, not on ``constant_part``'s word: here the springs' chain, made
    before the jump was added, does not know it)."""
    play, _ = route("coulomb")
    low, high = parts(play)[0]
    assert play_run._monotone(play, np.array([low, high]))
    for time in (0.5 * (low + high), high):
        monkeypatch.setattr(play.history, "jumps", [(time, play.radius(time), 1.5 * play.radius(time))])
        assert constant_part(play, low, high) == low  # (the part's word unchanged: the jump is what decides)
        assert not play_run._monotone(play, np.array([low, high])), time
