"""The bound that replaces the probes before the slip onset (issue 34's performance, ``continuum/play_bound.py``):
along the first segment in contact no probe's distance outside its window exceeds ``β (t − t_c) − ū(a(t))``, so
where that is negative the per-spring route's :data:`~mdr_events.models.continuum.play_samples.PROBE_POINTS` probes
find no spring at a cap and are not read. Checked against the probes themselves (on the paper's layer and on springs
built to defeat the bound: their least ``μρ`` inside the contact, not at the centre, and a dip narrower than the
bound's grid spacing centred on a probe, which only ``μρ`` read at the probes themselves sees), for its reach (it
passes up to the onset's output spacing), where it must not pass, and the run against the route of before
(``play_samples.PROBE_BOUND = False``) at every output, bit for bit (the bound only skips readings whose answer it knows).
Beside it, the probes of the times on one part where every window is fixed but for ``x`` (a fretting stroke before its
slip onset) read in one evaluation of the anchors (``PlaySprings.caps_over``, ``play_probes.SHARED_PROBES``): their
labels against each time's own, the times that must not be read together (a clamp between them, a moving radius, a
pinned radius on a moving depth), and the fretting run against the route of before.

No tolerance is spent: the probes' labels are the route's own, and the runs are compared exactly.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.indenters import Paraboloid
from mdr_events.contact.layer import Layer
from mdr_events.models.continuum import play_bound, play_probes, play_samples
from mdr_events.models.continuum.play_bound import BOUND_GRID, _first_segment, sticking
from mdr_events.models.continuum.play_line import FlooredRatio
from mdr_events.models.continuum.play_reach import constant_part
from mdr_events.models.continuum.play_springs import PlaySprings
from mdr_events.theory.layer import LAMBDA_MAX
from mdr_events.theory.layer.spring_factors import SpringFactors
from play_recorders import made_plays

#: The paper's 5 mm layer on a bonded base.
LAYER = 5e-3
#: Output samples of the runs.
SAMPLES = 41
#: Times read along the first segment.
TIMES = 200
#: The probes, as :func:`~mdr_events.models.continuum.play_samples._probed_all` reads them (shares of the radius).
PROBES = np.linspace(0.0, 1.0 - play_samples.PROBE_SHARE, play_samples.PROBE_POINTS)
#: The dip built into the adversarial springs' ``μρ``: its depth (share), centre and width (shares of the radius).
DIP = (0.95, 0.15, 0.04)
#: The narrow dip's time (a share of :data:`TIMES`: after ``|ẋ|(t − t_c)`` outgrows ``ū(a)``, before the layer's onset
#: at some 0.85) and its width (a share of the bound's grid spacing: at a quarter spacing or more from its centre its
#: ``exp(−(δ/w)²)`` is below 1e-270, so the grid reads the layer's ratios bit for bit).
NARROW = (0.7, 0.01)
#: The share to which :func:`loosely_floored` lowers the layer's floor of ``μρ``.
LOOSE = 0.9
#: The thickness of :func:`beyond_the_tables`' layer, a share of the first segment's last radius.
THIN = 1e-8
#: The probes among which the narrow dip's centre is chosen (within 4 % of the radius of the centre: attached near the
#: first contact, so that with ``μρ = 0`` it slides before the layer's onset).
NEAR_CENTRE = 40


def contact_of(law: str, adhesive: bool = False) -> me.Contact:
    """The paper's contact on the layer under ``law`` (μ = 0.3), with the paper's adhesion or without."""
    friction = me.FrictionLaw(law, mu=0.3, tau0=None if law == "coulomb" else me.Parameters.paper().tau0)
    paper = me.Contact.paper() if adhesive else me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)
    return dataclasses.replace(paper, friction=friction).replace(h=LAYER)


def play_of(law: str, monkeypatch, adhesive: bool = False, motion=None) -> PlaySprings:
    """The springs ``simulate`` makes on the layer along ``motion`` (scenario A at 20°)."""
    made = made_plays(monkeypatch)
    me.simulate(contact_of(law, adhesive), motion or me.Scenario("A", alpha=[20.0]), "continuum", samples=SAMPLES)
    return made[0]


def at_cap(play: PlaySprings, times: np.ndarray) -> np.ndarray:
    """Whether any probe is at a cap at each of ``times`` (the route's own labels)."""
    return np.array([np.any(play.anchors(play.radius(float(t)) * PROBES, float(t))[1] < 0) for t in times])


def first_segment_times(play: PlaySprings) -> np.ndarray:
    t_c, t_end, _, _ = _first_segment(play)
    return np.linspace(t_c, t_end, TIMES + 1)[1:]


@pytest.fixture(scope="module")
def layer_play():
    with pytest.MonkeyPatch.context() as monkeypatch:
        return play_of("tau0+coulomb", monkeypatch)


def dipped(play: PlaySprings) -> PlaySprings:
    """The same springs with ``μρ`` dipped by :data:`DIP` inside the contact (nearly 0 at 0.15 of the segment's last
    radius, where a bound read at the centre alone would miss it): the first spring to slide lies inside."""
    depth, centre, width = DIP
    a_end = play.radius(_first_segment(play)[1])
    ratio = play.line.ratio

    def dipped_ratio(xi):
        xi = np.asarray(xi, dtype=float)
        return ratio(xi) * (1.0 - depth * np.exp(-(((xi / a_end) - centre) / width) ** 2))

    return PlaySprings(play.line._replace(ratio=dipped_ratio), play.path)


@pytest.mark.parametrize("springs", ["layer", "dipped"])
def test_no_probe_is_at_a_cap_where_the_bound_passes(springs, layer_play):
    """Wherever the bound passes, none of the probes is at a cap. On the layer it passes up to the slip onset: every
    time before the first with a probe at a cap but the last (the bound reads ``μρ``'s least value, the centre's, the
    first spring's own, less a share of 1e-6); on the dipped springs, whose least ``μρ`` is not the first spring's,
    earlier."""
    play = layer_play if springs == "layer" else dipped(layer_play)
    times = first_segment_times(play)
    passed, capped = sticking(play, times, PROBES), at_cap(play, times)
    assert np.any(capped), "the onset lies in the first segment"
    assert not np.any(passed & capped)
    onset = int(np.argmax(capped))
    reach = onset - 1 if springs == "layer" else onset // 2
    assert np.all(passed[:reach]) and not np.any(passed[onset:])


def test_the_dipped_springs_slide_first_inside(layer_play):
    """The adversarial springs defeat a bound read at the centre: their first spring at a cap lies inside the contact,
    and the centre's ``μρ`` alone would pass times at which probes are at a cap."""
    play = dipped(layer_play)
    times = first_segment_times(play)
    capped = at_cap(play, times)
    t = float(times[int(np.argmax(capped))])
    labels = play.anchors(play.radius(t) * PROBES, t)[1]
    first = PROBES[np.flatnonzero(labels < 0)]
    assert first.size and np.min(first) > 0.1
    central = PlaySprings(play.line._replace(ratio=lambda xi: np.full(np.shape(xi), float(play.line.ratio(0.0)))),
                          play.path)  # (the bound's springs: μρ the centre's everywhere, the probes the dipped ones')
    assert np.any(sticking(central, times, PROBES) & capped)


def narrowly_dipped(play: PlaySprings, times: np.ndarray) -> tuple[PlaySprings, int]:
    """The same springs with ``μρ`` dropped to 0 in a dip :data:`NARROW` narrower than the bound's grid spacing,
    centred on a probe near the centre at one of ``times`` (the probe farthest from the grid's points), and that
    time's index."""
    share, width = NARROW
    row = int(share * times.size)
    radius = play.radius(float(times[row]))
    spacing = play.radius(float(times[-1])) / (BOUND_GRID - 1)
    offsets = (radius * PROBES[:NEAR_CENTRE] / spacing) % 1.0
    centre = radius * PROBES[int(np.argmin(np.abs(offsets - 0.5)))]  # (the product the route reads)
    ratio = play.line.ratio

    def dipped_ratio(xi):
        xi = np.asarray(xi, dtype=float)
        return ratio(xi) * (1.0 - np.exp(-(((xi - centre) / (width * spacing)) ** 2)))

    return PlaySprings(play.line._replace(ratio=dipped_ratio), play.path), row


def test_a_dip_between_the_grid_s_points_is_read_at_the_probes(layer_play, monkeypatch):
    """A dip of ``μρ`` narrower than the bound's grid spacing, centred on a probe: the grid reads the layer's ratios,
    the probe is at a cap at its time, and the bound (``μρ`` read at the probes themselves) passes no time with a
    probe at a cap; the grid's estimate alone would pass that time. Before the dip the bound passes as on the layer."""
    times = first_segment_times(layer_play)
    play, row = narrowly_dipped(layer_play, times)
    grid = np.linspace(0.0, play.radius(float(times[-1])), BOUND_GRID)
    assert np.array_equal(play.line.ratio(grid), layer_play.line.ratio(grid))
    passed, capped = sticking(play, times, PROBES), at_cap(play, times)
    assert capped[row] and not np.any(capped[:row])
    assert not np.any(passed & capped)
    assert np.all(passed[:row // 2])
    monkeypatch.setattr(play_bound, "_probes_least", lambda play, radii, shares: np.full(np.shape(radii), np.inf))
    assert sticking(play, times, PROBES)[row]


def test_the_bound_passes_no_time_where_it_does_not_hold(layer_play, monkeypatch):
    """Under Coulomb's law alone (``ū = 0``), after the first segment and on a path that starts in contact the bound
    passes no time."""
    times = first_segment_times(layer_play)
    alone = PlaySprings(layer_play.line._replace(shift=lambda a: np.zeros(np.shape(a)), shifts=False), layer_play.path)
    assert not np.any(sticking(alone, times, PROBES))
    corner_t = layer_play.path_corners()[0]
    later = np.linspace(corner_t[-2], corner_t[-1], TIMES)
    assert not np.any(sticking(layer_play, later, PROBES))
    inside = me.Path(np.array([[0.0, 1e-5], [1e-4, 2e-4]]), me.Parameters.paper().v)
    inside_times = np.linspace(0.0, inside.duration, TIMES)
    assert not np.any(sticking(PlaySprings(layer_play.line, inside), inside_times, PROBES))


def fretting_in() -> me.Paths:
    """In to ``d_max`` with ``x`` at rest (``β = 0``), one tangential stroke and out."""
    d_max = me.Parameters.paper().d_max
    x, d = [0.0, 0.0, 1e-3, 1e-3], [0.0, d_max, d_max, -1e-5]
    return me.Paths({"in": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


def read_with_and_without(monkeypatch, module, switch: str, contact: me.Contact, motion) -> dict[bool, list[int]]:
    """The run of ``contact`` along ``motion`` with ``module.switch`` off and on, asserted the same at every output,
    bit for bit; for each, the springs of each evaluation of the anchors (one entry a call)."""
    runs, read = {}, {}
    anchors = PlaySprings.anchors
    for on in (False, True):
        monkeypatch.setattr(module, switch, on)
        counted = []

        def counting(self, xi, t, counted=counted):
            counted.append(np.size(xi))
            return anchors(self, xi, t)

        monkeypatch.setattr(PlaySprings, "anchors", counting)
        runs[on] = me.simulate(contact, motion, "continuum", samples=SAMPLES)
        read[on] = counted
    assert runs[True].identical(runs[False])
    return read


@pytest.mark.parametrize("adhesive, motion", [(False, "A 20°"), (False, "in"), (True, "A 20°")])
def test_the_run_is_the_route_of_before_at_every_output(adhesive, motion, monkeypatch):
    """The whole run with the bound against the route of before (the probes read at every time where no node is at a
    cap): the same at every output, bit for bit, and fewer probes read."""
    motions = {"A 20°": me.Scenario("A", alpha=[20.0]), "in": fretting_in()}
    read = read_with_and_without(monkeypatch, play_samples, "PROBE_BOUND", contact_of("tau0+coulomb", adhesive),
                                 motions[motion])
    assert sum(read[True]) < sum(read[False])


def counted_ratios(monkeypatch) -> list[int]:
    """The springs whose ``μρ`` the bound reads (:func:`~mdr_events.models.continuum.play_bound._ratio_floor`'s grid
    and radii, :func:`~mdr_events.models.continuum.play_bound._probes_least`'s probes), one entry a call."""
    counted, grid, least = [], play_bound._ratio_floor, play_bound._probes_least

    def counting_grid(play, radii, top):
        counted.append(BOUND_GRID + np.size(radii))
        return grid(play, radii, top)

    def counting_probes(play, radii, shares):
        counted.append(np.size(radii) * np.size(shares))
        return least(play, radii, shares)

    monkeypatch.setattr(play_bound, "_ratio_floor", counting_grid)
    monkeypatch.setattr(play_bound, "_probes_least", counting_probes)
    return counted


def loosely_floored(play: PlaySprings) -> PlaySprings:
    """The same springs with their floor of ``μρ`` lowered by :data:`LOOSE` (still a floor): the times near the onset
    it no longer settles, which the grid and the probes decide (those it fails with the centre's ``μρ`` dropped
    unread)."""
    ratio = play.line.ratio
    loose = FlooredRatio(ratio.ratio, lambda extent: LOOSE * ratio.floor(extent), ratio.centre)
    return PlaySprings(play.line._replace(ratio=loose), play.path)


@pytest.mark.parametrize("springs", ["layer", "dipped", "loose"])
def test_the_ratio_s_floor_decides_as_the_probes_do(springs, layer_play, monkeypatch):
    """The layer's floor of ``μρ`` from its tables' coefficients (``play_bound.RATIO_FLOOR``, a bound at or below the
    probes' own least value and the grid's) passes the same times as the grid's and the probes' reading along the
    first segment, and on the layer settles every one of them: neither is read. A line whose ratio is replaced (the
    dipped springs) has no floor and reads them as before; a looser floor settles fewer times, the grid and the probes
    decide the others near the onset (those its centre's ``μρ`` fails dropped unread: fewer springs read than
    before)."""
    play = {"layer": layer_play, "dipped": dipped(layer_play), "loose": loosely_floored(layer_play)}[springs]
    times = first_segment_times(play)
    counted = counted_ratios(monkeypatch)
    monkeypatch.setattr(play_bound, "RATIO_FLOOR", False)
    before, read_before = sticking(play, times, PROBES), sum(counted)
    monkeypatch.setattr(play_bound, "RATIO_FLOOR", True)
    counted.clear()
    assert np.array_equal(sticking(play, times, PROBES), before)
    assert read_before > 0
    assert (sum(counted) == 0) == (springs == "layer")
    assert (sum(counted) == read_before) == (springs == "dipped")


def test_the_bound_keeps_the_springs_last_reading(layer_play):
    """The bound reads the centre's ``μρ`` (``FlooredRatio.centre``: the springs' own value there, bit for bit) past
    the springs' memory of their last coordinates: after it the route's next reading of the same springs is the
    remembered array, not an evaluation of the tables again."""
    ratio = layer_play.line.ratio
    centre = ratio(np.zeros(1))
    times = first_segment_times(layer_play)
    last = ratio(layer_play.radius(float(times[-1])) * PROBES)
    assert np.any(sticking(layer_play, times, PROBES))
    assert np.shares_memory(ratio(layer_play.radius(float(times[-1])) * PROBES), last)  # (a view of the same array)
    assert np.array_equal(ratio.centre(), centre[0]) and np.signbit(ratio.centre()) == np.signbit(centre[0])


def beyond_the_tables(play: PlaySprings) -> PlaySprings:
    """The same springs with ``μρ`` and its floor those of a layer :data:`THIN` of the first segment's last radius
    thick (the paper's ``ν``), as :class:`~mdr_events.theory.layer.spring_factors.SpringFactors` reads them: past
    ``a/h = LAMBDA_MAX`` almost at once, where the tables' spline extrapolates (``μρ`` below the centre's past ``λ``
    some 4e6, nearly 0 from 1e7 on: the outer springs slide at once; a run's reach check refuses such a layer, the
    bound is asked here directly)."""
    params = me.Parameters.paper()
    mu = contact_of("tau0+coulomb").friction.coulomb_mu
    factors = SpringFactors(Paraboloid(params.R), params.E_star, params.G_star, params.nu,
                            Layer(THIN * play.radius(_first_segment(play)[1])))

    def ratio(xi):
        values = factors.values(xi)
        return mu * values.normal / values.tangential

    floored = FlooredRatio(ratio, lambda extent: mu * factors.ratio_floor(extent), lambda: float(ratio(np.zeros(1))[0]))
    return PlaySprings(play.line._replace(ratio=floored), play.path)


def test_beyond_the_tables_the_old_route_decides(layer_play, monkeypatch):
    """Where the radius lies beyond the tables the floor claims nothing (``0``): the decisions are the grid's and
    the probes', the route of before, and no time passes with a probe at a cap (a floor of the tables' pieces there
    passed some at which the extrapolated springs slide)."""
    play = beyond_the_tables(layer_play)
    times = first_segment_times(play)
    assert min(play.radius(float(t)) for t in times) > LAMBDA_MAX * THIN * play.radius(float(times[-1]))
    monkeypatch.setattr(play_bound, "RATIO_FLOOR", False)
    before = sticking(play, times, PROBES)
    monkeypatch.setattr(play_bound, "RATIO_FLOOR", True)
    passed = sticking(play, times, PROBES)
    assert np.array_equal(passed, before)
    assert not np.any(passed & at_cap(play, times))


def test_the_run_with_the_ratio_s_floor_is_the_route_of_before(monkeypatch):
    """The whole run along A at 20° (``τ0`` and Coulomb, the bound's row) with the floor against without: the same at
    every output, bit for bit, and neither the grid's nor the probes' ``μρ`` read with it."""
    counted, runs = counted_ratios(monkeypatch), {}
    for on in (False, True):
        monkeypatch.setattr(play_bound, "RATIO_FLOOR", on)
        counted.clear()
        runs[on] = me.simulate(contact_of("tau0+coulomb"), me.Scenario("A", alpha=[20.0]), "continuum",
                               samples=SAMPLES)
        assert (sum(counted) == 0) == on
    assert runs[True].identical(runs[False])


# -- the probes of a part where every window is fixed but for x, read in one evaluation (play_probes.SHARED_PROBES) --

def fretting() -> me.Paths:
    """In to ``d_max``, one tangential cycle of ±1 mm there, and out (the strokes' times before their slip onset have
    no node at a cap: their probes are read)."""
    d_max = me.Parameters.paper().d_max
    x, d = [0.0, 0.0, 1e-3, -1e-3, 0.0, 0.0], [0.0, d_max, d_max, d_max, d_max, -1e-5]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


@pytest.fixture(scope="module")
def fretting_play():
    with pytest.MonkeyPatch.context() as monkeypatch:
        return play_of("tau0+coulomb", monkeypatch, motion=fretting())


def stroke_times(play: PlaySprings, corner: int) -> np.ndarray:
    """Times inside the stroke that starts at the path's ``corner`` (a constant depth, ``x`` linear)."""
    corner_t = play.path_corners()[0]
    return np.linspace(corner_t[corner], corner_t[corner + 1], TIMES + 2)[1:-1]


@pytest.mark.parametrize("corner", [1, 2])
def test_the_caps_over_a_part_are_each_time_s_own(corner, fretting_play):
    """On a stroke (a part of ``constant_part``) the probes' labels read once for all its times are those each time's
    own evaluation gives, bit for bit, and the onset lies inside (both labels occur)."""
    play = fretting_play
    times = stroke_times(play, corner)
    assert constant_part(play, float(times[0]), float(times[-1])) == times[0]
    xi = play.radius(float(times[0])) * PROBES
    together = play.caps_over(xi, times)
    alone = np.array([play.anchors(xi, float(t))[1] < 0 for t in times])
    assert np.array_equal(together, alone)
    assert np.any(together) and not np.all(together)


def test_times_across_a_clamp_or_a_moving_radius_are_not_shared(fretting_play):
    """Times on both sides of a corner (a clamp of the chain between them), or where the radius moves (the way in),
    are each read on their own."""
    play = fretting_play
    corner_t = play.path_corners()[0]
    across = np.concatenate([stroke_times(play, 1)[-3:], stroke_times(play, 2)[:3]])
    edge = np.full(across.size, play.radius(float(across[0])))
    groups = play_probes.shared_parts(play, across, edge, np.arange(across.size))
    assert sorted(len(group) for group in groups) == [3, 3]
    moving = np.linspace(corner_t[0], corner_t[1], 8)[1:-1]
    edge = np.array([play.radius(float(t)) for t in moving])
    assert all(len(group) == 1 for group in play_probes.shared_parts(play, moving, edge, np.arange(moving.size)))


def test_the_fretting_run_with_shared_probes_is_the_route_of_before(monkeypatch):
    """The whole fretting run with the strokes' probes read together against each time's own: the same at every
    output, bit for bit, in fewer evaluations of the anchors."""
    read = read_with_and_without(monkeypatch, play_probes, "SHARED_PROBES", contact_of("tau0+coulomb"), fretting())
    assert len(read[True]) < len(read[False])


def test_times_of_a_pinned_radius_on_a_moving_depth_are_not_shared(monkeypatch):
    """With adhesion the radius rests (pinned) while the indenter starts out: the same probes at times with the same
    clamps of the chain before them, but the windows move with ``d`` (each spring's Coulomb part, its crossings of
    ``d = g``): each time is read on its own."""
    play = play_of("tau0+coulomb", monkeypatch, adhesive=True, motion=fretting())
    corner_t = play.path_corners()[0]
    times = np.linspace(corner_t[-2], corner_t[-1], 41)[1:4]
    edge = np.array([play.radius(float(t)) for t in times])
    keys = np.searchsorted(play.chain.times, times, side="left")
    assert np.all(edge == edge[0]) and np.all(keys == keys[0])  # (what the grouping reads first agrees)
    assert all(len(group) == 1 for group in play_probes.shared_parts(play, times, edge, np.arange(times.size)))
