"""Scenario B's critical angle at a speed under rate-dependent adhesion (analysis.rate_let_go) and the let-go it rests on
(continuum.let_go): the paper's (21) as v_ref -> inf, the continuum's and the springs' slip on either side of it, the
flat punch letting go where it starts to recede."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.rate_let_go import _let_go, critical_angle_B_at_speed, critical_angles_B_at_speeds, \
    let_go_B_at_speed
from mdr_events.models.continuum import EdgeEventKind, solve_edge
from mdr_events.models.continuum.edge_let_go import let_go
from mdr_events.models.continuum.rate_shifts import solve_rate_shifts
from mdr_events.theory.analytic import critical_angle

PAPER = me.Parameters.paper()
BASE = me.Contact.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
#: The edge's method of these tests: LSODA, within 1e-8 degree of Radau's angle (measured 7e-9) at a seventh of its time.
METHOD = "LSODA"
#: Near the let-go the edge passes the fold of the branch (9) (the turning point, a saddle-node) at the speed the path
#: drives it; its lag behind the quasi-static fold grows as (v / v_ref)^(2/3) (slow passage through a saddle-node,
#: n = 1), so the angle's gap to (21) falls by 10^(2/3) = 4.6 per decade of v_ref: measured orders 0.60 and 0.65 per
#: decade, approaching 2/3 from below.
FOLD_ORDER = (0.5, 0.75)
#: How far off the critical angle the springs are looked at (degree): the discrete springs' slip onset is late by
#: about one spring's crossing, 0.01-0.08 s here, while 0.25° moves it by about 0.5 s.
ANGLE_OFFSET = 0.25


@pytest.mark.slow  # 8.0 s of CPU (measured on the shared 2-core machine, loaded): three critical angles and let-go
# points up to v_ref = 1e-2 m/s (a stiff edge); the quick round keeps the let-go against the springs on both sides of
# the angle
def test_v_ref_to_infinity_is_the_paper_s_21_at_the_fold_s_order():
    """n = 1, v_ref 100 to 10 000 times the path's speed: the gap to (21) and the let-go radius's gap to the paper's
    jump-off radius fall at the order of a slow passage through the fold."""
    paper = critical_angle(PAPER, "B", adhesion=True)
    jump_off = me.analytic.jump_off(PAPER, PAPER.dgamma1)["contact_radius"]
    gaps, radii = [], []
    for v_ref in (1e-4, 1e-3, 1e-2):
        law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, v_ref, 1.0)
        angle = critical_angle_B_at_speed(PAPER, law, PAPER.v, method=METHOD)
        gaps.append(paper - angle)
        radii.append(let_go_B_at_speed(PAPER, law, PAPER.v, angle, method=METHOD).radius - jump_off)
    for values in (gaps, radii):
        orders = np.log10(np.array(values[:-1]) / np.array(values[1:]))
        assert np.all(np.array(values) > 0.0) and np.all((FOLD_ORDER[0] < orders) & (orders < FOLD_ORDER[1])), values


@functools.cache
def _critical_angle() -> float:
    """The law's critical angle at the paper's speed (degree): found once in this module (0.6 s of CPU), for both
    sides."""
    return critical_angle_B_at_speed(PAPER, LAW, PAPER.v, method=METHOD)


@pytest.mark.parametrize("side", [-1.0, 1.0])
def test_the_continuum_and_the_springs_slide_before_the_let_go_below_the_angle_only(side):
    """At α_c ∓ 0.25°: the continuum's springs (rate_shifts) and the discrete springs (Δx = 2 µm) first slide before
    the let-go below the angle, after it above."""
    angle = _critical_angle() + side * ANGLE_OFFSET
    point, path = _let_go(PAPER, LAW, PAPER.v, math.radians(angle), None, 1e-10, "Radau")
    onset = solve_rate_shifts(PAPER, path, LAW).slip_onset_time()
    contact = me.Contact(BASE.elastomer, BASE.indenter, LAW, BASE.friction)
    run = me.simulate(contact, me.Paths([path]), "discrete", dx=2e-6).isel(case=0)
    times = run["time"].values + path.first_contact_time()
    sliding = run["sliding_fraction"].values
    first = times[np.flatnonzero(np.nan_to_num(sliding) > 0.0)[0]]
    if side < 0:
        assert onset < point.time and first < point.time, (onset, first, point)
    else:
        assert onset > point.time and first > point.time, (onset, first, point)


def test_the_flat_punch_lets_go_where_it_starts_to_recede():
    """g = g' = 0 under the face: every receding edge is past the let-go (Kendall's detachment, all at once)."""
    punch = me.FlatPunch(5e-4)
    path = me.Path(np.array([(0.0, 0.0), (0.0, 2e-5), (0.0, -2e-4)]), speed=1e-6)
    run = solve_edge(PAPER, path, LAW, profile=punch)
    starts = [event.time for event in run.events if event.kind is EdgeEventKind.RECEDING_STARTS]
    found = let_go(run, path, PAPER, punch)
    assert found is not None and found.time == pytest.approx(starts[0], rel=1e-12, abs=0.0)


def test_the_angles_against_speed_are_labelled_and_fall_from_the_paper_s():
    """Two speeds: the angle below (21), falling with the speed (the edge lags more), the paper's (21) stamped."""
    result = critical_angles_B_at_speeds(PAPER, LAW, [1e-7, 1e-5], method=METHOD)
    angles = result["critical_angle"].values
    assert result.attrs["critical_angle_paper"] == critical_angle(PAPER, "B", adhesion=True)
    assert angles[1] < angles[0] < result.attrs["critical_angle_paper"]
    assert np.all(result["let_go_radius"].values > me.analytic.jump_off(PAPER, PAPER.dgamma1)["contact_radius"])


def test_bad_angles_are_named():
    with pytest.raises(ValueError, match="alpha=0.0 is not allowed; allowed: a number of degrees in \\(0, 90\\]"):
        let_go_B_at_speed(PAPER, LAW, PAPER.v, 0.0)


#: Brent's tolerance on the angle (ANGLE_XTOL, 1e-12 rad) in degrees, with room for the closed form's rounding.
ANGLE_ATOL_DEGREES = 1e-9


@pytest.mark.parametrize("speed", [1e-8, 1e-4])
def test_the_flat_punch_s_angle_is_its_21_at_any_speed(speed):
    """The punch's edge rests at its face until the release rate reaches Δγ1 (Kendall's depth, the rate-independent
    jump-off) and lets go there at once: the angle is the closed form (21) of the punch, whatever the speed."""
    from mdr_events.theory import power_law

    punch = me.FlatPunch(5e-4)
    angle = critical_angle_B_at_speed(PAPER, LAW, speed, profile=punch, method=METHOD)
    assert angle == pytest.approx(power_law.critical_angle_B(punch, PAPER), abs=ANGLE_ATOL_DEGREES)
