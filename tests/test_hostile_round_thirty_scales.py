"""Hostile round 30 (issue 32, class 2): exact scalings the earlier rounds did not check, and the times of flat
extrema.

The MDR is invariant under the stress scaling ``(E, τ0, Δγ0, Δγ1) → λ(...)`` (forces ``λ`` times, the rest unchanged)
and, under the rate law, the time scaling of the speeds (``v``, ``v_ref`` → ``s(...)``: times ``1/s`` times)
(EQUATIONS.md (5)–(21)). An extremum's time is determined within the conditioning of its maximum: where the quantity
is flat (a plateau the model holds exactly) every time on it reaches the value, and the package reports the earliest
time whose value ties the extremum to rounding (:func:`mdr_events.models.continuum.span_extrema.within_tie`:
:data:`~mdr_events.models.continuum.span_extrema.EXTREMUM_TIE` of the quantity's largest magnitude along the run), the
one rule of every extremum of the continuum.
"""

from __future__ import annotations

import functools
import warnings

import numpy as np
import pytest

import mdr_events as me
from mdr_events import FrictionLaw, Parameters
from mdr_events.models.continuum.span_extrema import EXTREMUM_TIE, within_tie

PAPER = Parameters.paper()
#: A time read at a point the run computes (a path's corner, a sample) is that point's time to rounding: the corner
#: ``d_max / (v cos α)`` divided by ``v`` and multiplied back under the time scaling (a few ulps of the run's length).
TIME_RTOL = 64 * float(np.finfo(float).eps)


@functools.lru_cache(maxsize=None)
def _rate_coulomb_run(stress: float, speed: float, samples: int, angle: float = 60.0):
    """The paper's set with the rate law (``v_ref`` 1 µm/s, ``n = 0.3``) and ``"tau0+coulomb"`` (μ 0.3), scenario A at
    ``angle``: the stresses ``stress`` times, the speeds ``speed`` times, ``samples`` output times."""
    contact = me.Contact(me.Elastomer(PAPER.E * stress, PAPER.nu), me.Paraboloid(PAPER.R),
                         me.RateDependentAdhesion(PAPER.dgamma0 * stress, PAPER.dgamma1 * stress,
                                                  v_ref=1e-6 * speed, n=0.3),
                         FrictionLaw("tau0+coulomb", mu=0.3, tau0=PAPER.tau0 * stress))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return me.simulate(contact, me.Scenario("A", alpha=(angle,), d_max=PAPER.d_max, v=PAPER.v * speed),
                           method="continuum", samples=samples)


@pytest.mark.parametrize(("stress", "speed", "samples"), [(1.0, 1.0, 51), (1e148, 1.0, 201), (1.0, 1e-3, 201)])
def test_rate_coulomb_plateau_is_read_at_its_start_under_every_scaling(stress, speed, samples):
    """The case that showed it: ``F_x`` is held in stick from A's corner (``x`` rests, the springs attaching at the
    growing edge carry nothing) while the rate law's radius relaxes; the per-spring quadrature reads the plateau to
    its rounding (1e-13 of ``F_x``), and the time of the largest ``F_x`` was the sample that rounding raised: with the
    default samples 351.67 s unscaled, 416.28 s with the stresses 1e148 times (9e-2 of the run), 415.58 s with the
    speeds 1e-3 times; it hung on the output times too (51 samples: 363.20 s; 201: 352.72 s). It is the plateau's
    start, the corner, at every scaling and sampling; the value is ``λ`` times the unscaled."""
    run = _rate_coulomb_run(stress, speed, samples)
    events = run.event_time.values[0][run.event_kind.values[0] == "corner"]
    corner, length = float(events[0]), float(run.time.values[-1] - run.time.values[0])
    assert run.tangential_force_max_time.values[0] == pytest.approx(corner, rel=0.0, abs=TIME_RTOL * length)
    if stress != 1.0 or speed != 1.0:
        reference = _rate_coulomb_run(1.0, 1.0, samples)
        np.testing.assert_allclose(run.tangential_force_max.values / stress, reference.tangential_force_max.values,
                                   rtol=1000 * me.Tolerances().rtol)


def test_first_tie_is_the_earliest_value_within_the_tie():
    """The rule itself: of values signed larger-is-better in time order, the first within ``EXTREMUM_TIE`` of the
    quantity's size of the best (a plateau's start), -1 where none is (nothing reached the best)."""
    from mdr_events.models.continuum.span_extrema import first_tie

    size = 2.0
    plateau = np.array([0.5, 1.0 - 0.6 * EXTREMUM_TIE * size, 1.0, 1.0 - 0.3 * EXTREMUM_TIE * size])
    assert first_tie(plateau, 1.0, size) == 1
    assert first_tie(np.array([0.5, 1.0 - 2 * EXTREMUM_TIE * size, 1.0]), 1.0, size) == 2
    assert first_tie(np.array([0.5, 0.9]), 1.0, size) == -1
    assert within_tie(1.0 - EXTREMUM_TIE * size, 1.0, size) and not within_tie(1.0 - 1.01 * EXTREMUM_TIE * size, 1.0,
                                                                                   size)
