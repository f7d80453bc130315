"""The per-spring route read at many times at once (issue 34's performance): Coulomb's part on a layer reads its
output times, the probes of its events' searches and the corners of its ``F_x`` extrema in batches
(``PlaySprings.probed_states``, ``PlaySprings.outsides``), searches its events side by side (``play_search.searched``),
two halvings a step (``play_search.halve``) and Brent's method as a generator (``play_search.brent``), and clamps the
shared times a column at a time (``PlaySprings._shared_clamps``). Each must give what the route read one time, one
search, one halving and one sorted column at a time gave, bit for bit: no tolerance is derived because none is
spent (the readings are spring by spring, the edges' round-off read per time, Brent's steps scipy's own).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.optimize import brentq

import mdr_events as me
from mdr_events.models.continuum import play_search
from mdr_events.models.continuum.play_line import _once_a_block
from mdr_events.models.continuum.play_springs import PlaySprings
from mdr_events.models.spring_media import springs_of
from mdr_events.theory.layer.spring_factors import SpringFactors
from play_recorders import made_plays

#: The paper's 5 mm layer on a bonded base.
LAYER = 5e-3
D_MAX = me.Parameters.paper().d_max
#: Output samples of the runs whose route is read again (enough for stick, slip and full slip in every piece).
SAMPLES = 41


def fretting() -> me.Paths:
    """In to ``d_max``, one tangential cycle of ±1 mm there (full slip both ways), and out."""
    x, d = [0.0, 0.0, 1e-3, -1e-3, 0.0, 0.0], [0.0, D_MAX, D_MAX, D_MAX, D_MAX, -1e-5]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


#: law, adhesive, motion: without adhesion along a fretting loop (the radius ``g⁻¹(d)``, shared clamp times alone)
#: and with the paper's adhesion along scenario A at 20° (the spans' radius, each spring's crossings of ``d = g``)
CASES = {"coulomb fretting": ("coulomb", False, fretting()),
         "tau0+coulomb A 20° adhesive": ("tau0+coulomb", True, me.Scenario("A", alpha=[20.0]))}


def route(case: str, monkeypatch) -> PlaySprings:
    """The route ``simulate`` ran for ``case`` on the layer (recorded as it was made)."""
    law, adhesive, motion = CASES[case]
    made = made_plays(monkeypatch)
    paper = me.Contact.paper() if adhesive else me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)
    friction = me.FrictionLaw(law, mu=0.3, tau0=None if law == "coulomb" else me.Parameters.paper().tau0)
    contact = dataclasses.replace(paper, friction=friction).replace(h=LAYER)
    me.simulate(contact, motion, "continuum", samples=SAMPLES)
    assert len(made) == 1
    return made[0]


def times_in_contact(play: PlaySprings) -> np.ndarray:
    """The samples in contact and the path's corners (where the anchors kink in time)."""
    start, end = play.path.first_contact_time(), play.path.corner_times[-1]
    times = np.union1d(np.linspace(start, end, SAMPLES), play.path.corner_times)
    return np.array([time for time in times if play.radius(float(time)) > 0.0])


@pytest.mark.parametrize("case", list(CASES))
def test_the_states_at_many_times_are_each_time_s_own(case, monkeypatch):
    """The force, the measures at a cap and the probes' provenance read for all the times at once are those read at
    each time alone (the kink search's breaks, rounds and bisections kept apart per time)."""
    play = route(case, monkeypatch)
    times = times_in_contact(play)
    probes = np.concatenate([play.radius(float(time)) * np.array([0.0, 0.5, 1.0 - 1e-12]) for time in times])
    probe_time = np.repeat(np.arange(times.size), 3)
    for kinks in (True, False):
        states, probed = play.probed_states(times, probes, probe_time, kinks)
        for k, time in enumerate(times):
            alone, labels = play.probed_state(float(time), probes[probe_time == k], kinks)
            assert states[k] == alone, (time, kinks)
            assert probed[probe_time == k].tolist() == labels.tolist(), (time, kinks)
    distance, pressed, group, at_probes = play.outsides(times, probes, probe_time)
    for k, time in enumerate(times):
        alone = play.outside(float(time), probes[probe_time == k])
        assert distance[group == k].tolist() == alone[0].tolist()
        assert pressed[group == k].tolist() == alone[1].tolist()
        assert at_probes[probe_time == k].tolist() == alone[2].tolist()


@pytest.mark.parametrize("case", list(CASES))
def test_the_shared_clamps_are_the_sorted_columns_clamps(case, monkeypatch):
    """Where no spring has extremes of its own, the clamps a shared time at a time (and each spring's crossings of
    ``d = g`` between them) give the anchors and provenance of the columns sorted spring by spring."""
    play = route(case, monkeypatch)
    assert not play._own_columns
    for time in times_in_contact(play):
        xi = play.radius(float(time)) * np.linspace(0.0, 1.0 - 1e-12, 257)
        shared = play._anchors(xi, float(time))
        play._own_columns = True
        try:
            sorted_ = play._anchors(xi, float(time))
        finally:
            play._own_columns = False
        for got, expected in zip(shared, sorted_):
            assert got.tolist() == expected.tolist(), time


def answered(search, reading):
    """Run one search of ``play_search.searched`` alone, answering each ask ``(kind, time)`` with ``reading(time)``; its
    result and the number of readings."""
    values, asked = None, 0
    while True:
        try:
            asks = search.send(values)
        except StopIteration as stop:
            return stop.value, asked
        values, asked = tuple(reading(time) for _, time in asks), asked + len(asks)


#: Functions and brackets Brent's method meets: smooth, steep, kinked, flat near the root, a root near 0.
ROOTS = [(lambda t: t ** 3 - 2.0 * t - 5.0, 2.0, 3.0), (lambda t: math.exp(40.0 * (t - 0.3)) - 1.0, 0.0, 1.0),
         (lambda t: min(t - 0.2, 0.5 * (t - 0.2) + 0.05), 0.0, 1.0), (lambda t: (t - 0.25) ** 5, 0.0, 0.9),
         (lambda t: t - 3e-12, 0.0, 5.9), (lambda t: math.tanh(1e6 * (t - 1.0)), 0.5, 1.0 + 1e-9)]


@pytest.mark.parametrize("function,low,high", ROOTS)
def test_brent_is_scipy_s_brentq(function, low, high):
    """The generator's root is scipy's ``brentq``'s at the route's tolerances, bit for bit (the events' guess is read
    within ``ROOT_ULPS`` of it), after as many readings (step for step), and none where ``brentq`` does not converge
    (the flat fifth power at an ulp of 0.9: the route's old call caught its error, the halvings alone then)."""
    root, result = brentq(function, low, high, xtol=np.spacing(high), rtol=4.0 * np.finfo(float).eps,
                          full_output=True, disp=False)
    got, asked = answered(play_search.brent("f", low, high, function(low), function(high)), function)
    assert got == (root if result.converged else None)
    assert asked + 2 == result.function_calls  # (the two ends' values given)


def test_brent_gives_up_where_brentq_raises():
    """A value ``nan`` (out of contact) or no change of sign: no root (the halvings alone then)."""
    assert answered(play_search.brent("f", 0.0, 1.0, -1.0, 1.0), lambda t: np.nan)[0] is None
    assert answered(play_search.brent("f", 0.0, 1.0, 1.0, 2.0), lambda t: 1.0)[0] is None


def test_searches_side_by_side_are_each_one_s_own():
    """Every function's Brent search run side by side with the others (each step's asks read together, the readings
    told apart by their kind) finds the root it finds alone."""
    functions = {str(k): function for k, (function, _, _) in enumerate(ROOTS)}
    searches = [play_search.brent(str(k), low, high, function(low), function(high))
                for k, (function, low, high) in enumerate(ROOTS)]
    together = play_search.searched(lambda asks: [functions[kind](time) for kind, time in asks], searches)
    alone = [answered(play_search.brent("f", low, high, function(low), function(high)), function)[0]
             for function, low, high in ROOTS]
    assert together == alone


def halved(low: float, high: float, reached) -> tuple[float, float]:
    """Halving one at a time (the route's bisection before it took two a step)."""
    for _ in range(play_search.EVENT_HALVINGS):
        middle = 0.5 * (low + high)
        if middle in (low, high):
            break
        if reached(middle):
            high = middle
        else:
            low = middle
    return low, high


#: Predicates the halvings meet: one change, several (the share turning back), a change near a bracket's end.
PREDICATES = [lambda t: t > 0.123456789, lambda t: math.sin(40.0 / (t + 0.01)) > 0.0, lambda t: t > 1.0 - 1e-13,
              lambda t: (t > 0.3) != (0.5 < t < 0.5 + 1e-9)]


@pytest.mark.parametrize("reached", PREDICATES)
@pytest.mark.parametrize("levels", [1, 2, 3])
def test_the_tree_of_halvings_is_one_halving_at_a_time(reached, levels, monkeypatch):
    """The halvings taken ``levels`` a step, every midpoint they can visit asked at once, walk to the bracket of
    halving one at a time, also where the predicate changes more than once; with fewer steps than halvings."""
    monkeypatch.setattr(play_search, "TREE_LEVELS", levels)

    def search(time):
        return reached((yield (("f", time),))[0])

    steps = []

    def reading(time):
        return time

    halving = play_search.halve(0.0, 1.0, search)
    values = None
    while True:
        try:
            asks = halving.send(values)
        except StopIteration as stop:
            got = stop.value
            break
        steps.append(len(asks))
        values = tuple(reading(time) for _, time in asks)
    assert got == halved(0.0, 1.0, reached)
    assert len(steps) <= -(-play_search.EVENT_HALVINGS // levels)


def test_the_springs_of_repeated_blocks_are_read_once_each_their_own_values():
    """The springs' ``g``, ``k_t/G*`` and ratios on a layer asked at the probes of many times, some at one radius
    (blocks equal to the one before: a fretting loop's times at rest in depth): each block's values those of the
    whole array read at once (bit for bit, every element its own), the tables' spline read for the distinct blocks
    alone; an array with no repeated block (scenario A's growing radius) read whole."""
    params = me.Parameters.paper()
    layer = me.Contact.paper().replace(h=LAYER).layer
    factors = SpringFactors(springs_of(params, None, None, layer).indenter, params.E_star, params.G_star, params.nu,
                            layer)
    asked = []

    def values(xi):
        asked.append(xi.size)
        return np.stack(factors.values(xi))

    grid = np.linspace(0.0, 1.0 - 1e-12, 1025)
    edges = np.array([1e-3, 1e-3, 1e-3, 1.2e-3, 1.2e-3, 1e-3, 0.5e-3])  # (runs of equal radii, one recurring later)
    points = (edges[:, None] * grid).ravel()
    once = _once_a_block(values)(points)
    assert np.array_equal(once, values(points))  # (bit for bit)
    assert asked[0] == 4 * grid.size  # (the blocks that differ from the one before: 1e-3, 1.2e-3, 1e-3, 0.5e-3)
    asked.clear()
    growing = (np.array([1e-3, 1.1e-3, 1.2e-3])[:, None] * grid).ravel()
    assert np.array_equal(_once_a_block(values)(growing), values(growing)) and asked[0] == growing.size
