"""Scenario A's slip onset with adhesion for Coulomb's part (theory.mindlin.d_crit_A with ``adhesion``, the phase
diagram's adhesive curve): the non-adhesive onset for Coulomb's law alone (the compressed zone's, free of Δγ) and for
any law on the flat punch (all springs compressed while it is pressed in), against the continuum's first slip event
with the paper's adhesion and Δγ1 < Δγ0; "tau0+coulomb" on a curved indenter has none (nan), as the continuum refuses
it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.models.continuum import EventKind, solve_path
from mdr_events.theory import mindlin

ANGLES = [10.0, 40.0, 70.0]
#: The continuum's onset event against the closed form, as a share of d_max: the event is the root of a linear level
#: (the flat punch's pinned span) or logged at first contact (0): rounding of the level's root, SIMULTANEOUS_SHARE
ONSET_SHARE = 1e-9
ADHESIONS = [(0.01, 0.15), (0.15, 0.01)]


def _onset(params, alpha, friction, profile):
    """The depth of the continuum's first SLIP_ONSET at a cap (direction ±1) along scenario A while indenting (+inf:
    none before d_max); under Coulomb's law alone the tensile annulus slides from first contact at a zero cap
    (direction 0: models.continuum.compressed), which is no onset of friction."""
    path = me.Path.scenario_A(alpha, params, profile=profile)
    solution = solve_path(params, path, profile=profile, friction=friction)
    deepest = path.corner_times[1] - path.first_contact_time()  # the end of the indentation
    onsets = [event.depth for event in solution.events if event.kind is EventKind.SLIP_ONSET and event.direction
              and event.time <= deepest]
    return onsets[0] if onsets else math.inf


@pytest.mark.parametrize("adhesion", ADHESIONS, ids=["paper", "reversed"])
@pytest.mark.parametrize("friction, profile", [
    (FrictionLaw("coulomb", mu=0.3), None), (FrictionLaw("coulomb", mu=0.3), PowerLaw.cone(0.05)),
    (FrictionLaw("coulomb", mu=0.3), FlatPunch(1.5e-3)), (FrictionLaw("tau0+coulomb", mu=0.2), FlatPunch(1.5e-3)),
], ids=["coulomb-paraboloid", "coulomb-cone", "coulomb-punch", "combined-punch"])
def test_the_adhesive_onset_is_the_non_adhesive_one_and_the_continuums(adhesion, friction, profile):
    params = me.Parameters.paper().replace(dgamma0=adhesion[0], dgamma1=adhesion[1])
    expected = mindlin.d_crit_A(ANGLES, friction, params, profile, adhesion=True)
    np.testing.assert_array_equal(expected, mindlin.d_crit_A(ANGLES, friction, params, profile))
    assert mindlin.critical_angle_A(friction, params, profile, adhesion=True) == mindlin.critical_angle_A(
        friction, params, profile)
    diagram = me.phase_diagram(params, ANGLES, friction=friction, profile=profile)
    np.testing.assert_array_equal(diagram["d_crit_jkr"].values, diagram["d_crit_hertz"].values)
    for alpha, depth in zip(ANGLES, diagram["d_crit_jkr"].values):
        found = _onset(params, alpha, friction, profile)
        if np.isfinite(depth) and depth <= params.d_max:
            assert found == pytest.approx(depth, rel=0, abs=ONSET_SHARE * params.d_max), alpha
        else:
            assert found == math.inf, alpha
    # the three kinds of onset appear: from first contact, later, and none while indenting
    assert {0.0 if d == 0 else math.inf if not np.isfinite(d) or d > params.d_max else 1.0
            for d in diagram["d_crit_jkr"].values} >= ({0.0, math.inf} if not friction.uses_tau0 else {1.0})


def test_the_combined_law_on_a_curved_indenter_has_no_adhesive_onset():
    params = me.Parameters.paper()
    friction = FrictionLaw("tau0+coulomb", mu=0.2)
    assert np.all(np.isnan(mindlin.d_crit_A(ANGLES, friction, params, adhesion=True)))
    assert math.isnan(mindlin.critical_angle_A(friction, params, adhesion=True))
    diagram = me.phase_diagram(params, ANGLES, friction=friction)
    assert np.all(np.isnan(diagram["d_crit_jkr"].values))
    assert "no closed form" in diagram["d_crit_jkr"].attrs["long_name"]
