"""The per-spring route's readings shared (issue 34's performance, the events' sequential readings): the output
samples, the contact's pieces' ends the events' searches start from and the extrema's scan read in one call
(``play_run.spring_run``, ``play_run.SHARED_SAMPLES``), and the kinks' bisection cutting only the brackets still open
(``PlaySprings._bisect``, ``play_springs.SETTLED_BRACKETS``), and an event's step's shares with and without the kink
search read in one call (``play_run.SHARED_READINGS``, ``PlaySprings.probed_states`` with one ``kinks`` a time). Each must give what the route of before gave, bit for bit:
no tolerance is derived because none is spent (each time's springs are read as a call at that time alone, each
group's radii in the call of before; a settled bracket's cuts are its two ends, so cutting it again keeps it).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import play_run, play_springs
from mdr_events.models.continuum.play_springs import KINK_CUTS, KINK_HALVINGS, PlaySprings
from play_recorders import made_plays

#: The paper's 5 mm layer on a bonded base.
LAYER = 5e-3
D_MAX = me.Parameters.paper().d_max
#: Output samples of the runs compared (enough for stick, slip and full slip in every piece).
SAMPLES = 41
#: The rate-dependent law of tests/models/test_rate_coulomb.py (the edge lags the indenter visibly).
RATE_LAW = me.RateDependentAdhesion(me.Parameters.paper().dgamma0, me.Parameters.paper().dgamma1, 1e-6, 0.6)


def fretting() -> me.Paths:
    """In to ``d_max``, one tangential cycle of ±1 mm there (full slip both ways), and out: a piece after each
    reversal, its end read before the searches, and radii at constant depth read in batches (the layer's branch)."""
    x, d = [0.0, 0.0, 1e-3, -1e-3, 0.0, 0.0], [0.0, D_MAX, D_MAX, D_MAX, D_MAX, -1e-5]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


def rate_fretting() -> me.Paths:
    """A fretting loop of ±30 µm for the rate law's edge (tests/models/test_rate_coulomb.py's)."""
    x, d = [0.0, 0.0, 3e-5, -3e-5, 3e-5, 0.0], [0.0, D_MAX, D_MAX, D_MAX, D_MAX, -2e-4]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


def layer_contact(law: str, adhesive: bool) -> me.Contact:
    """The paper's contact on the layer under ``law`` (μ = 0.3), with its adhesion or none."""
    paper = me.Contact.paper() if adhesive else me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)
    friction = me.FrictionLaw(law, mu=0.3, tau0=None if law == "coulomb" else me.Parameters.paper().tau0)
    return dataclasses.replace(paper, friction=friction).replace(h=LAYER)


def rate_contact() -> me.Contact:
    """The paper's half-space under Coulomb's law with the rate-dependent adhesion (:mod:`.rate_coulomb`'s route)."""
    base = me.Contact.paper()
    return me.Contact(base.elastomer, base.indenter, RATE_LAW, me.FrictionLaw("tau0+coulomb", mu=0.3,
                                                                              tau0=me.Parameters.paper().tau0))


#: name: the contact and the motion (without adhesion along a fretting loop, the events' pieces after reversals; with
#: the paper's adhesion along scenario A at 20°, the spans' radius; the rate law's edge, :mod:`.rate_coulomb`)
CASES = {"coulomb fretting": (lambda: layer_contact("coulomb", False), fretting),
         "tau0+coulomb fretting": (lambda: layer_contact("tau0+coulomb", False), fretting),
         "tau0+coulomb A 20° adhesive": (lambda: layer_contact("tau0+coulomb", True),
                                         lambda: me.Scenario("A", alpha=[20.0])),
         "rate law tau0+coulomb fretting": (rate_contact, rate_fretting)}


#: The flags of the route of before, each on in today's route.
FLAGS = ((play_run, "SHARED_SAMPLES"), (play_springs, "SETTLED_BRACKETS"), (play_run, "SHARED_READINGS"))


@pytest.fixture(scope="module")
def runs_now():
    """``case`` → its run by today's route (every flag of the test below on), made once for the module: the three
    flags' tests compare their route of before with the same run (the rate law's row ~0.5 s of CPU a run)."""
    made = {}

    def run(case: str):
        if case not in made:
            assert all(getattr(module, name) is True for module, name in FLAGS)  # (no test's flag left off)
            contact, motion = (make() for make in CASES[case])
            made[case] = me.simulate(contact, motion, "continuum", samples=SAMPLES)
        return made[case]

    return run


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("flag", FLAGS, ids=["shared samples", "settled brackets", "shared readings"])
def test_the_runs_are_the_route_s_of_before_bit_for_bit(case, flag, runs_now, monkeypatch):
    """Every output of ``simulate`` (the samples, the event log, the extrema) with the readings shared, or the settled
    brackets left, is the route's of before."""
    contact, motion = (make() for make in CASES[case])
    now = runs_now(case)
    monkeypatch.setattr(*flag, False)
    before = me.simulate(contact, motion, "continuum", samples=SAMPLES)
    assert now.identical(before), [name for name in now.data_vars if not now[name].identical(before[name])]


@pytest.mark.parametrize("case", ["coulomb fretting", "tau0+coulomb A 20° adhesive"])
def test_times_with_and_without_the_kink_search_read_together_are_each_time_s_own(case, monkeypatch):
    """The states and the probes' provenance at times read together, some with the kink search and some without
    (``PlaySprings.probed_states`` with one ``kinks`` a time: an event's step asking shares and guesses), are those
    of each time read alone with its own."""
    made = made_plays(monkeypatch)
    contact, motion = (make() for make in CASES[case])
    me.simulate(contact, motion, "continuum", samples=SAMPLES)
    play = made[0]
    start, end = play.path.first_contact_time(), play.path.corner_times[-1]
    times = np.array([time for time in np.union1d(np.linspace(start, end, SAMPLES), play.path.corner_times)
                      if play.radius(float(time)) > 0.0])
    kinks = np.arange(times.size) % 2 == 0
    probes = np.concatenate([play.radius(float(time)) * np.array([0.0, 0.5, 1.0 - 1e-12]) for time in times])
    probe_time = np.repeat(np.arange(times.size), 3)
    states, probed = play.probed_states(times, probes, probe_time, kinks)
    searched_kinks = 0
    for k, time in enumerate(times):
        alone, labels = play.probed_state(float(time), probes[probe_time == k], bool(kinks[k]))
        assert states[k] == alone, (time, kinks[k])
        assert probed[probe_time == k].tolist() == labels.tolist(), (time, kinks[k])
        searched_kinks += bool(kinks[k]) and alone != play.probed_state(float(time), probes[probe_time == k], False)[0]
    assert searched_kinks  # (the kink search changes some times' states: the two kinds differ there)


class _Steps:
    """A stand-in for :class:`PlaySprings` whose provenance is a step function of ``ξ`` (the same at every time):
    ``label[k]`` on ``[edges[k], edges[k + 1])``; it counts the springs each evaluation reads."""

    def __init__(self, edges: list[float], labels: list[int]):
        self.edges, self.labels, self.read = np.asarray(edges, dtype=float), np.asarray(labels), []

    def anchors(self, xi, t):
        xi = np.asarray(xi, dtype=float)
        self.read.append(xi.size)
        return xi, self.labels[np.searchsorted(self.edges, xi, side="right") - 1]

    def bisect(self, low, high, low_label, settled: bool, monkeypatch) -> np.ndarray:
        monkeypatch.setattr(play_springs, "SETTLED_BRACKETS", settled)
        return PlaySprings._bisect(self, 0.0, np.asarray(low, dtype=float), np.asarray(high, dtype=float),
                                   np.asarray(low_label))


#: An adversarial set of brackets searched together: a kink at 0.3 (settles in some 8 cuts), two kinks a hair apart
#: (4e-16: a zone of another provenance between two cuts of every step but the last), a kink at a bracket's high end
#: (its provenance differs only there), a bracket already settled (neighbouring doubles), and a kink near 0 whose
#: doubles are far finer than 60 halvings of its bracket reach (never settles: the others' cuts must stop, not it).
STEP_EDGES = [-1.0, 1e-300, 0.3, 0.6, 0.6 + 4e-16, 0.9]
STEP_LABELS = [7, 8, 9, 10, 11, 12]
BRACKETS = {"kink": (0.25, 0.35, 8), "hair apart": (0.55, 0.65, 9), "at the end": (0.85, 0.9, 11),
            "settled": (float(np.nextafter(0.6, 0.0)), 0.6, 9), "near 0": (0.0, 1e-290, 7)}


def test_a_settled_bracket_is_not_cut_again_and_every_kink_is_the_route_s_of_before(monkeypatch):
    """On the adversarial brackets each kink is the one cutting every bracket to the last gives, bit for bit, with
    fewer springs read; the kinks lie in their brackets, at a change of provenance (to a double where one is
    reachable)."""
    low, high, low_label = (np.array(column) for column in zip(*BRACKETS.values()))
    steps = _Steps(STEP_EDGES, STEP_LABELS)
    before = steps.bisect(low, high, low_label, False, monkeypatch)
    read_before, steps.read = sum(steps.read), []
    now = steps.bisect(low, high, low_label, True, monkeypatch)
    assert now.tolist() == before.tolist()
    assert sum(steps.read) < read_before
    assert np.all((now >= low) & (now <= high))
    for name, kink in zip(BRACKETS, now):
        if name != "near 0":  # (a change of provenance between the neighbouring doubles about the kink)
            below, above = steps.anchors(np.array([np.nextafter(kink, -1.0), np.nextafter(kink, 2.0)]), 0.0)[1]
            assert below != above, name
    assert now[list(BRACKETS).index("hair apart")] < 0.6 + 4e-16  # (the first change: the zone's start)


def test_a_bracket_alone_is_cut_as_often_as_before(monkeypatch):
    """A single bracket is cut :data:`KINK_CUTS` ways at each evaluation until settled, as before (its cuts' count:
    the evaluations saved are the other brackets' points, not its own steps)."""
    steps = _Steps(STEP_EDGES, STEP_LABELS)
    steps.bisect([0.25], [0.35], [8], True, monkeypatch)
    now = list(steps.read)
    steps.read = []
    steps.bisect([0.25], [0.35], [8], False, monkeypatch)
    assert now == steps.read and set(now) == {KINK_CUTS - 1}
    assert len(now) <= -(-KINK_HALVINGS // int(np.log2(KINK_CUTS)))
