"""Scenario A's slip onset with adhesion for Coulomb's part (theory.mindlin.d_crit_A with ``adhesion``, the phase
diagram's adhesive curve): the non-adhesive onset for Coulomb's law alone (the compressed zone's, free of Δγ) and for
any law on the flat punch (all springs compressed while it is pressed in), against the continuum's first slip event
with the paper's adhesion and Δγ1 < Δγ0; "tau0+coulomb" on a curved indenter the first depth a spring reaches its
cap (theory.combined_onset), the continuum's too."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.models.continuum import EventKind, solve_path
from mdr_events.theory import mindlin, symbolic

from quick_round import grid

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
    # the end of the indentation: at the corner itself a radius dropping onto the Δγ1 branch (Δγ1 < Δγ0) lets the
    # springs beyond its smaller caps slide, which is no onset of the indentation
    deepest = path.corner_times[1] - path.first_contact_time()
    onsets = [event.depth for event in solution.events if event.kind is EventKind.SLIP_ONSET and event.direction
              and event.time < deepest]
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


#: The combined law's cases: three adhesions (the paper's, Δγ1 < Δγ0, Δγ0 = 0) on the paraboloid, a cone (growing
#: without adhesion from a = 0 it slides from first contact below an angle) and n = 3
COMBINED_CASES = [pytest.param(adhesion, profile, id=f"{name}-{label}")
                  for adhesion, name in zip(ADHESIONS + [(0.0, 0.1)], ("paper", "reversed", "grows-without"))
                  for profile, label in ((None, "paraboloid"), (PowerLaw.cone(0.05), "cone"),
                                         (PowerLaw(2e5, 3.0), "n3"))]


#: The quick round's cases of scenario A (seven continuum solves each, 0.6-2.4 s of CPU): each adhesion and each
#: indenter once; the other six run in make test-all and CI (tests/quick_round.py)
COMBINED_QUICK = {("paper", "paraboloid"), ("reversed", "cone"), ("grows-without", "n3")}


@pytest.mark.parametrize("adhesion, profile", grid(
    {"adhesion": dict(zip(("paper", "reversed", "grows-without"), ADHESIONS + [(0.0, 0.1)])),
     "profile": {"paraboloid": None, "cone": PowerLaw.cone(0.05), "n3": PowerLaw(2e5, 3.0)}}, COMBINED_QUICK))
def test_the_combined_laws_adhesive_onset_is_the_continuums(adhesion, profile):
    """Both parts of the cap on a curved indenter with adhesion: the onset of theory.combined_onset (the first depth
    where the jump-in ring's edge, x_c or the grown springs' turn reaches its cap) is the continuum's first slip onset
    at five angles, none where it finds none by d_max; the continuum slides by d_max just below the critical angle and
    not just above it; the phase diagram's adhesive curve is it (+inf where none) (:data:`COMBINED_CASES`)."""
    params = me.Parameters.paper().replace(dgamma0=adhesion[0], dgamma1=adhesion[1])
    friction = FrictionLaw("tau0+coulomb", mu=0.2)
    angles = np.array([5.0, 10.0, 20.0, 40.0, 70.0])
    depths = mindlin.d_crit_A(angles, friction, params, profile, adhesion=True)
    for alpha, depth in zip(angles, depths):
        found = _onset(params, alpha, friction, profile)
        if np.isnan(depth):
            assert found == math.inf, alpha
        else:
            assert found == pytest.approx(depth, rel=0, abs=ONSET_SHARE * params.d_max), alpha
    critical = mindlin.critical_angle_A(friction, params, profile, adhesion=True)
    assert _onset(params, critical - 0.01, friction, profile) <= params.d_max
    assert _onset(params, critical + 0.01, friction, profile) == math.inf
    diagram = me.phase_diagram(params, angles, friction=friction, profile=profile)
    np.testing.assert_array_equal(diagram["d_crit_jkr"].values, np.where(np.isnan(depths), np.inf, depths))
    assert float(diagram["critical_angle_jkr"]) == critical


def _onset_b(params, alpha, friction, profile, final_depth=None):
    """The depth of the continuum's first SLIP_ONSET at a cap after the vertical stroke of scenario B: going out at
    ``alpha`` (``final_depth`` None, -inf: none before the pull-off), or further in to ``final_depth`` (+inf: none)."""
    if final_depth is None:
        path = me.Path.scenario_B(alpha, params, profile=profile)
    else:
        path = me.Path.scenario_B_indentation(alpha, params, final_depth=final_depth, profile=profile)
    solution = solve_path(params, path, profile=profile, friction=friction)
    turn, end = path.corner_times[1:3] - path.first_contact_time()  # the vertical stroke's end, the angled one's
    onsets = [event.depth for event in solution.events if event.kind is EventKind.SLIP_ONSET and event.direction
              and turn <= event.time <= end]
    return onsets[0] if onsets else (-math.inf if final_depth is None else math.inf)


@pytest.mark.parametrize("adhesion, profile", COMBINED_CASES[:6] + [
    pytest.param((0.05, 0.05), PowerLaw(50.0, 1.5), id="equal-n1.5")])
def test_the_combined_laws_adhesive_onset_of_scenario_b_is_the_continuums(adhesion, profile):
    """Both parts of the cap on a curved indenter with adhesion, scenario B: going out, every spring holds the same
    shift and the edge, in tension, only K a: the onset is τ0's (21), free of μ (its derived excess vanishes there),
    the continuum's first slip at three angles, none before the pull-off above the critical angle and some just
    below it; further in, the first depth a spring reaches its cap about the contact of d_max
    (theory.combined_onset.d_crit_B_indentation) is the continuum's at two angles (+inf, never, for the cone: its
    springs do not slide by 20 d_max); the phase diagram's adhesive curves and angle are these (nan before)."""
    params = me.Parameters.paper().replace(dgamma0=adhesion[0], dgamma1=adhesion[1])
    friction = FrictionLaw("tau0+coulomb", mu=0.2)
    indenter = profile or PowerLaw.paraboloid(params.R)
    angles = np.array([20.0, 45.0, 70.0])
    out = mindlin.d_crit_B(angles, friction, params, profile, adhesion=True)
    np.testing.assert_array_equal(out, me.power_law.d_crit_B(angles, indenter, params, adhesion=True))
    excess = symbolic.relation("adhesive_onset_excess_B")
    for alpha, depth in zip(angles, out):
        assert _onset_b(params, alpha, friction, profile) == pytest.approx(depth, rel=0,
                                                                            abs=ONSET_SHARE * params.d_max), alpha
        if np.isfinite(depth):  # the radius pinned at d_max's until the Δγ1 branch is reached, then on it
            radius = min(float(me.power_law.contact_radius(params.d_max, indenter, params, params.dgamma0)),
                         float(me.power_law.contact_radius(depth, indenter, params, params.dgamma1)))
            left = excess.numeric(depth, params.d_max, radius, 1 / math.tan(math.radians(alpha)), params.tau0,
                                  params.G_star)
            assert abs(float(left)) <= ONSET_SHARE * params.d_max, alpha
    critical = mindlin.critical_angle_B(friction, params, profile, adhesion=True)
    assert _onset_b(params, critical - 0.01, friction, profile) > -math.inf
    assert _onset_b(params, critical + 0.01, friction, profile) == -math.inf
    inward = mindlin.d_crit_B_indentation(angles[:2], friction, params, profile, adhesion=True)
    for alpha, depth in zip(angles[:2], inward):
        final = 1.2 * depth if np.isfinite(depth) else 20 * params.d_max
        assert _onset_b(params, alpha, friction, profile, final) == pytest.approx(
            depth, rel=0, abs=ONSET_SHARE * params.d_max), alpha
    diagram = me.phase_diagram(params, angles, scenario="B", friction=friction, profile=profile)
    np.testing.assert_array_equal(diagram["d_crit_jkr"].sel(branch="pull-off").values, out)
    np.testing.assert_array_equal(diagram["d_crit_jkr"].sel(branch="indentation").values[:2], inward)
    assert float(diagram["critical_angle_jkr"]) == critical
    assert not np.any(np.isnan(diagram["d_crit_jkr"].values))

