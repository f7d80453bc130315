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
#: How closely a scaled run's largest F_x over λ matches the unscaled run's: the solver's rtol accumulated over the
#: run's integration steps (of the order of a thousand).
SCALED_FORCE_RTOL = 1000 * me.Tolerances().rtol


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
                                   rtol=SCALED_FORCE_RTOL)


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


#: Round-off of a closed form evaluated at scaled stresses (64 ulps of 1), and of a root of a slope on a layer's
#: tables: the slope's terms (``a g'``, ``Δl``, ``K d'``, ``a K' Δl``) round to some ulps each and where the least is
#: shallow they nearly cancel, the root's condition (measured: 1.8e-14 of the radius, 7.9e-13 of the pull-off's depth,
#: ``g − Δl`` cancelling): 64 eps times 1e4, round 29's ``ROOT_RTOL``.
ROOT_RTOL = 64 * float(np.finfo(float).eps) * 1e4
LAYER_CASES = [(me.Paraboloid(PAPER.R), me.Layer(5e-3, "bonded")), (me.Paraboloid(PAPER.R), me.Layer(1e-3, "frictionless")),
               (me.PowerLaw(c=50.0, n=3.0), me.Layer(5e-4, "bonded")), (me.PowerLaw(c=1.0, n=1.0), me.Layer(5e-2, "bonded"))]


def _layer_contact(profile, layer, stress: float) -> me.Contact:
    return me.Contact(me.Elastomer(PAPER.E * stress, PAPER.nu), profile,
                      me.Adhesion(PAPER.dgamma0 * stress, PAPER.dgamma1 * stress),
                      FrictionLaw("tau0", tau0=PAPER.tau0 * stress), layer)


def _flat_leasts(profile, layer, stress: float) -> np.ndarray:
    """The jump-off (radius, depth, force / λ), the pull-off under force control (radius, depth, force / λ) and, on a
    bonded base, scenario B's critical angle (its scan ends at the jump-off) of the paper's set on ``layer``."""
    from mdr_events.theory.layer import pull_off

    contact = _layer_contact(profile, layer, stress)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        jump = me.jump_off(contact, contact.adhesion.dgamma1)
        pulled = pull_off(profile, contact.elastomer.E_star, PAPER.nu, contact.adhesion.dgamma1, layer)
        angle = me.critical_angle(contact, "B", d_max=PAPER.d_max) if layer.base == me.LayerBase.BONDED else 0.0
    return np.array([jump["contact_radius"], jump["depth"], jump["normal_force"] / stress, pulled.radius, pulled.depth,
                     pulled.force / stress, angle])


@pytest.mark.parametrize("stress", [1e-140, 3.7e5, 1e148])
@pytest.mark.parametrize("case", range(len(LAYER_CASES)))
def test_layer_jump_off_and_pull_off_are_free_of_the_stress_scale(case, stress):
    """A least (the jump-off's depth, the pull-off's force) is flat: Brent's minimiser placed its radius anywhere
    within ~√ε of it, so that the stress scaling, which leaves every length unchanged, moved the jump-off radius and
    force by up to 5.7e-8, the pull-off's radius by 2.5e-8 and depth by 3.7e-6, scenario B's critical angle by 1.3e-8.
    At the root of the slope they are unchanged to the root's round-off."""
    profile, layer = LAYER_CASES[case]
    np.testing.assert_allclose(_flat_leasts(profile, layer, stress), _flat_leasts(profile, layer, 1.0),
                               rtol=ROOT_RTOL, atol=0.0)


@pytest.mark.parametrize("radius", [0.01, 0.03, 0.1])
@pytest.mark.parametrize("work", [0.01, 0.15, 1.0])
def test_half_space_pull_off_radius_is_the_closed_form(radius, work):
    """On the half-space the pull-off radius under force control of the paraboloid is ``(9π Δγ R²/(8E*))^(1/3)``
    (JKR): the minimiser gave it to 7e-10 .. 1.5e-8, the slope's root to round-off."""
    from mdr_events.theory.layer import pull_off

    E_star = PAPER.E / (1.0 - PAPER.nu ** 2)
    found = pull_off(me.Paraboloid(radius), E_star, PAPER.nu, work, me.Layer())
    exact = (9.0 * np.pi * work * radius ** 2 / (8.0 * E_star)) ** (1.0 / 3.0)
    assert found.radius == pytest.approx(exact, rel=64 * float(np.finfo(float).eps), abs=0.0)


#: The speed factor of h122's open case: the paper's 1 µm/s times 2^20 (about 1 m/s), whose first depth after the
#: touch rounds to a subnormal (1.14e-322 m).
FAST = 2.0 ** 20
#: How closely the layer's radius meets the half-space's closed form where the branch hands over to it: the layer's
#: correction there is of the order of ``a/h = HALF_SPACE_SHARE`` (an ulp), Newton's iteration converged to 1e-14.
HAND_OVER_RTOL = 1e-14


def test_a_layer_run_whose_first_depth_is_subnormal_runs():
    """h122's open case: Coulomb's part on the 5 mm bonded layer along A 20° at ~1 m/s raised "the radius of
    depth=1.14e-322 m ... did not converge" (Newton's iteration halving its way down from the scan's first radius). A
    depth where the branch is the half-space's to rounding has the half-space's radius in closed form; the run is
    finite in contact, its sliding fraction a share."""
    contact = me.Contact(me.Elastomer(324e3, 0.5), me.Paraboloid(0.03), me.Adhesion(0.01, 0.15),
                         me.FrictionLaw("coulomb", mu=0.3), me.Layer(5e-3))
    run = me.simulate(contact, me.Scenario("A", alpha=[20.0], d_max=3e-4, v=1e-6 * FAST), method="continuum")
    in_contact = run["contact_area"].values > 0
    for name in ("normal_force", "tangential_force", "contact_radius", "contact_area"):
        assert np.all(np.isfinite(run[name].values[in_contact])), name
    sliding = run["sliding_fraction"].values[in_contact]
    assert np.all((sliding >= 0) & (sliding <= 1)) and float(run["tangential_force"].max()) > 0


def test_the_layers_radius_hands_over_to_the_half_space_continuously():
    """Below ``kc (HALF_SPACE_SHARE h)ⁿ`` the radius without adhesion is ``d^(1/n)/(κc)^(1/n)``; above it Newton's
    iteration on the layer's branch: the two meet to rounding, the array route gives the scalar's, and a subnormal
    depth has a finite radius."""
    from mdr_events.models.continuum.layer_branch import LayerBranch
    from mdr_events.theory.layer.scalar_factors import NormalFactors

    params, layer = me.Parameters.paper(), me.Layer(5e-3)
    branch = LayerBranch(params, 0.0, me.Paraboloid(0.03), layer, NormalFactors(params.nu, layer, 2.0))
    hand_over = branch._half_space_depth
    for depth in (hand_over * (1 + 1e-12), hand_over * (1 - 1e-12)):  # (Newton's side, the closed form's side)
        np.testing.assert_allclose(branch.radius(depth, HAND_OVER_RTOL), np.sqrt(depth / branch.kc),
                                   rtol=HAND_OVER_RTOL)
    depths = np.array([1e-322, 1e-300, hand_over / 2, hand_over * 2, 1e-20])
    scalar = np.array([branch.radius(depth, HAND_OVER_RTOL) for depth in depths])
    assert np.all(np.isfinite(scalar) & (scalar > 0))
    np.testing.assert_allclose(branch.radii(depths), scalar, rtol=HAND_OVER_RTOL)
    np.testing.assert_allclose(scalar[:3], np.sqrt(depths[:3]) / np.sqrt(branch.kc), rtol=HAND_OVER_RTOL)
