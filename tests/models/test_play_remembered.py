"""``ū(a(t))`` of many times read in one call of the layer's cap table (``PlaySprings.remember_radii``,
``play_springs.REMEMBER_SHIFTS``): each time's value as a call on it alone gives it, bit for bit (elementwise
operations of the table), and the run against the route of before (one call a time) at every output. No tolerance
is spent: both are compared exactly.
"""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import play_springs
from mdr_events.models.continuum.play_springs import PlaySprings
from test_play_bound import SAMPLES, contact_of, fretting, play_of

#: Times read (the path's whole duration, out of contact at its ends: radius 0 there).
TIMES = 301


@pytest.mark.parametrize("adhesive", [False, True])
def test_the_shifts_read_together_are_each_time_s_own(adhesive, monkeypatch):
    """``ū`` of :data:`TIMES` times remembered in one call equals each time's own call (a fresh instance given the
    same radii, one time at a time), including the times out of contact (0) and repeated ones."""
    play = play_of("tau0+coulomb", monkeypatch, adhesive, fretting())
    times = np.linspace(0.0, float(play.path_corners()[0][-1]), TIMES)
    times = np.concatenate([times, times[::7]])
    together = PlaySprings(play.line, play.path, play.history)
    together.remember_radii(times)
    alone = PlaySprings(play.line, play.path, play.history)
    alone._radii.update(together._radii)  # (the radii of one inversion: a time's own differs by round-off)
    monkeypatch.setattr(play_springs, "REMEMBER_SHIFTS", False)
    each = np.array([alone.shift(float(time)) for time in times])
    read = np.array([together._shifts[(float(time), None)] for time in times])
    assert np.array_equal(read, each)
    assert np.any(each > 0.0) and (adhesive or np.any(each == 0.0))  # (adhesive: in contact to the path's end)


@pytest.mark.parametrize("motion", ["A 20°", "fretting"])
def test_the_run_is_the_route_of_before_at_every_output(motion, monkeypatch):
    """The whole run with the shifts read together against one call a time: the same at every output, bit for bit."""
    motions = {"A 20°": me.Scenario("A", alpha=[20.0]), "fretting": fretting()}
    runs = {}
    for together in (False, True):
        monkeypatch.setattr(play_springs, "REMEMBER_SHIFTS", together)
        runs[together] = me.simulate(contact_of("tau0+coulomb"), motions[motion], "continuum", samples=SAMPLES)
    assert runs[True].identical(runs[False])
