"""The critical angle of scenario A against the path's speed under rate-dependent adhesion
(analysis.rate_angles): the paper's (18) as v_ref → ∞ at the first order n = 1 gives, between (18) and the
non-adhesive (17) and rising with the speed, and the discrete springs (an independent route) sliding before d_max
just below it and not just above; bad input is named."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.rate_angles import (critical_angle_at_speed, critical_angles_at_speeds,
                                             phase_diagram_at_speeds, slip_onset_depth_at_speed)
from mdr_events.theory.analytic import critical_angle

PAPER = me.Parameters.paper()
ADHESIVE = critical_angle(PAPER, "A", adhesion=True)
HERTZ = critical_angle(PAPER, "A", adhesion=False)
#: The observed order of the approach to (18) in 1/v_ref with n = 1: the angle's error at v_ref = 1 m/s is ~7e-7°,
#: the ODE's (rtol 1e-10) ~1e-8°: the order is known to ~2 %.
ORDER_SPREAD = 0.05
#: Either side of the angle the discrete springs at Δx = 1 µm are checked at (°): their first-order error moves the
#: slip onset by less (a sliding share of 7 % at 0.01° below the angle at this Δx).
DISCRETE_MARGIN = 0.01
#: The discrete springs' slip onset depth against the continuum's: the output samples' spacing in depth (3.2e-4 of the
#: onset depth at 15°) on either side, and the springs' first-order delay at Δx ≤ 1 µm (measured 1.5e-5 at 1 µm).
DISCRETE_ONSET_RTOL = 1e-3
#: Two routes to one number: the slip-onset depth at the critical angle is d_max, to the angle's and the onset's
#: Brent tolerances and the edge's ODE (rtol 1e-10).
ROUTES_RTOL = 1e-8


def _law(v_ref, n=0.6):
    return me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, v_ref, n)


@pytest.mark.slow  # 7.4 s of CPU (measured on the shared 2-core machine, loaded): two critical angles by Brent's method
# on a stiff edge (v_ref = 1 m/s); the quick round keeps the same limit on the slip depth
# (test_a_fast_reference_speed_gives_the_paper_s_slip_depth...)
def test_a_fast_reference_speed_gives_the_paper_s_angle_at_first_order():
    errors = [critical_angle_at_speed(PAPER, _law(v_ref, n=1.0), PAPER.v) - ADHESIVE for v_ref in (1e-2, 1.0)]
    assert all(error > 0 for error in errors)  # the edge lags: a smaller radius, a larger angle
    assert math.log10(errors[0] / errors[1]) / 2.0 == pytest.approx(1.0, abs=ORDER_SPREAD)


def test_the_angle_rises_with_the_speed_between_the_adhesive_and_the_non_adhesive_one():
    angles = critical_angles_at_speeds(PAPER, _law(1e-6), [1e-8, 1e-6, 1e-4], method="LSODA")
    values = angles["critical_angle"].values
    assert ADHESIVE < values[0] < values[1] < values[2] < HERTZ
    assert angles.attrs["critical_angle_adhesive"] == ADHESIVE and angles.attrs["critical_angle_hertz"] == HERTZ
    assert angles["critical_angle"].attrs["units"] == "degree" and angles["speed"].attrs["units"] == "m s-1"
    # the radius it reports is the one that makes the angle: tan α K a = d_max
    cap = math.pi * PAPER.tau0 / (2.0 * PAPER.G_star)
    tangent = np.tan(np.radians(values))
    assert np.allclose(tangent * cap * angles["contact_radius"].values, PAPER.d_max, rtol=1e-9)


def test_the_discrete_springs_slide_before_d_max_just_below_the_angle_and_not_just_above():
    law = _law(1e-6)
    angle = critical_angle_at_speed(PAPER, law, PAPER.v, method="LSODA")  # (within 1e-7° of Radau's: the margin 0.01°)
    paper = me.Contact.paper()
    contact = me.Contact(paper.elastomer, paper.indenter, law, paper.friction)
    run = me.simulate(contact, me.Scenario("A", alpha=[angle - DISCRETE_MARGIN, angle + DISCRETE_MARGIN]),
                      "discrete", dx=1e-6)
    slid = []
    for alpha in run["alpha"].values:
        case = run.sel(alpha=alpha)
        deepest = int(np.nanargmax(case["indentation_depth"].values))
        slid.append(float(np.nanmax(case["sliding_fraction"].values[:deepest + 1])))
    assert slid[0] > 0.01 and slid[1] == 0.0


def test_the_slip_onset_at_the_critical_angle_is_d_max():
    law = _law(1e-6)
    for speed in (1e-7, 1e-5):  # (both routes on the same integrator: its error cancels)
        angle = critical_angle_at_speed(PAPER, law, speed, method="LSODA")
        assert slip_onset_depth_at_speed(PAPER, law, speed, angle, method="LSODA") == pytest.approx(PAPER.d_max,
                                                                                                    rel=ROUTES_RTOL)


def test_the_phase_diagram_lies_between_the_paper_s_curves_and_falls_with_the_speed():
    diagram = phase_diagram_at_speeds(PAPER, _law(1e-6), [1e-8, 1e-6, 1e-4], [10.0, 20.0, 30.0], method="LSODA")
    depths = diagram["d_crit"].values
    assert np.all(diagram["d_crit_hertz"].values < depths) and np.all(depths < diagram["d_crit_jkr"].values)
    assert np.all(np.diff(depths, axis=0) < 0)  # faster: a smaller radius, an earlier slip
    assert diagram["d_crit"].dims == ("speed", "alpha") and diagram["d_crit"].attrs["units"] == "m"


def test_a_fast_reference_speed_gives_the_paper_s_slip_depth_at_first_order():
    closed = phase_diagram_at_speeds(PAPER, _law(1.0, n=1.0), [PAPER.v], [20.0])["d_crit_jkr"].item()
    # (at v_ref = 1 m/s the error, 3e-11 m, nears the closed form's and the ODE's floor, ~1e-11 m: two decades above)
    errors = [closed - slip_onset_depth_at_speed(PAPER, _law(v_ref, n=1.0), PAPER.v, 20.0) for v_ref in (1e-3, 1e-1)]
    assert all(error > 0 for error in errors)
    assert math.log10(errors[0] / errors[1]) / 2.0 == pytest.approx(1.0, abs=ORDER_SPREAD)


@pytest.mark.parametrize("dx", [1e-6, 0.5e-6])
def test_the_discrete_springs_begin_to_slide_at_the_slip_onset_depth(dx):
    law = _law(1e-6)
    paper = me.Contact.paper()
    run = me.simulate(me.Contact(paper.elastomer, paper.indenter, law, paper.friction),
                      me.Scenario("A", alpha=[15.0]), "discrete", dx=dx).sel(alpha=15.0)
    first = int(np.flatnonzero(run["sliding_fraction"].values > 0.0)[0])
    exact = slip_onset_depth_at_speed(PAPER, law, PAPER.v, 15.0)
    assert run["indentation_depth"].values[first] == pytest.approx(exact, rel=DISCRETE_ONSET_RTOL)


def test_without_tau0_the_springs_slide_from_the_start():
    assert critical_angle_at_speed(PAPER.replace(tau0=0.0), _law(1e-6), PAPER.v) == 90.0


@pytest.mark.parametrize("call, words", [
    (lambda: critical_angle_at_speed(PAPER, _law(1e-6), 0.0), r"speed=0.0 is not allowed; allowed: a finite number > 0"),
    (lambda: critical_angle_at_speed(PAPER, _law(1e-6), math.nan), r"speed=nan is not allowed"),
    (lambda: critical_angles_at_speeds(PAPER, _law(1e-6), [1e-6, -1.0]), r"speeds\[1\]=-1.0 is not allowed"),
    (lambda: critical_angle_at_speed(PAPER, me.Adhesion(0.01, 0.15), 1e-6), r"law="),
    (lambda: critical_angle_at_speed("paper", _law(1e-6), 1e-6), r"params='paper' .* allowed: a Parameters"),
    (lambda: slip_onset_depth_at_speed(PAPER, _law(1e-6), 1e-6, 90.0), r"alpha=90.0 is not allowed; allowed: .*\(0, 90\)"),
    (lambda: phase_diagram_at_speeds(PAPER, _law(1e-6), [1e-6], [20.0, -5.0]), r"alpha\[1\]=-5.0 is not allowed"),
    (lambda: phase_diagram_at_speeds(PAPER, _law(1e-6), [1e-6], [20.0], method="RK45"), r"method='RK45'"),
])
def test_bad_input_is_named(call, words):
    with pytest.raises((TypeError, ValueError), match=words):
        call()
