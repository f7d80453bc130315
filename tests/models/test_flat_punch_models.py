"""The flat punch in both simulators: its radius fixed from the first touch on, Kendall's pull-off with every spring
at once, the slip onset that is full slip at once; the discrete model converging to the continuum."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.continuum import EventKind, extremum, solve_path
from mdr_events.contact.indenters import FlatPunch
from mdr_events.theory import power_law as pl

PUNCH = FlatPunch(1.5e-3)


@pytest.fixture(scope="module")
def paper():
    return me.Parameters.paper()


@pytest.mark.parametrize("alpha", [20.0, 60.0])
def test_the_continuum_meets_the_punchs_closed_forms(paper, alpha):
    """Scenario A: in contact the radius is the punch's and F_N = 2 E* a d (10); the least F_N is Kendall's
    −sqrt(8π a³ E* Δγ1) at the depth where the edge spring reaches Heß's limit, where all springs let go; the slip
    onset is full slip at once, at d = tan α K a, with F_x = τ0 π a² (all to 1e-12, the onset to 1e-9 d_max)."""
    path = me.Path.scenario_A(alpha, paper, profile=PUNCH)
    solution = solve_path(paper, path, profile=PUNCH)
    ds = me.simulate(paper, "A", alpha=[alpha], method="continuum", profile=PUNCH)
    radius, depth = ds["contact_radius"].values[0], ds["indentation_depth"].values[0]
    touching = radius > 0
    np.testing.assert_array_equal(radius[touching], PUNCH.radius)
    np.testing.assert_allclose(ds["normal_force"].values[0][touching], 2 * paper.E_star * PUNCH.radius * depth[touching],
                               rtol=1e-12, atol=1e-12 * paper.E_star * PUNCH.radius * paper.d_max)
    jump = pl.jump_off(PUNCH, paper, paper.dgamma1)
    assert extremum(solution, "normal_force", False)[1] == pytest.approx(jump["normal_force"], rel=1e-12)
    assert jump["normal_force"] == pytest.approx(-math.sqrt(8 * math.pi * PUNCH.radius**3 * paper.E_star * paper.dgamma1),
                                                 rel=1e-14)
    events = {event.kind: event for event in reversed(solution.events)}  # the first of each kind
    assert events[EventKind.FIRST_CONTACT].radius == PUNCH.radius and events[EventKind.FIRST_CONTACT].depth == 0.0
    assert events[EventKind.PULL_OFF].depth == pytest.approx(jump["depth"], rel=1e-12)
    onset = float(pl.d_crit_A(alpha, PUNCH, paper))
    if onset < paper.d_max:
        assert events[EventKind.SLIP_ONSET].depth == pytest.approx(onset, abs=1e-9 * paper.d_max)
        assert events[EventKind.FULL_SLIP].time == events[EventKind.SLIP_ONSET].time
        assert extremum(solution, "tangential_force", True)[1] == pytest.approx(paper.tau0 * math.pi * PUNCH.radius**2,
                                                                                 rel=1e-12)
    else:
        assert EventKind.SLIP_ONSET not in events


def test_the_punch_touches_again_after_its_pull_off(paper):
    """In, out past the pull-off, in again: a second contact at the surface with the whole face, and the same
    pull-off depth; without adhesion it comes off at the surface."""
    jump = pl.jump_off(PUNCH, paper, paper.dgamma1)["depth"]
    path = me.Path([(0.0, -1e-5), (0.0, 1e-4), (0.0, 2 * jump), (1e-5, 1e-4), (1e-5, 2 * jump)], speed=1e-6)
    solution = solve_path(paper, path, profile=PUNCH)
    kinds = [event.kind for event in solution.events]
    assert kinds.count(EventKind.PULL_OFF) == 2 and EventKind.RE_CONTACT in kinds
    pulls = [event for event in solution.events if event.kind is EventKind.PULL_OFF]
    assert all(event.depth == pytest.approx(jump, rel=1e-12) for event in pulls)
    contact = next(event for event in solution.events if event.kind is EventKind.RE_CONTACT)
    assert contact.depth == pytest.approx(0.0, abs=1e-12 * paper.d_max) and contact.radius == PUNCH.radius
    hertz = paper.replace(dgamma0=0.0, dgamma1=0.0)
    apart = solve_path(hertz, path, profile=PUNCH)
    ends = [event for event in apart.events if event.kind in (EventKind.PULL_OFF, EventKind.CONTACT_ENDS)]
    assert ends[0].depth == pytest.approx(0.0, abs=1e-12 * paper.d_max)


def test_the_discrete_model_is_the_continuum_when_the_face_holds_whole_springs(paper):
    """Every spring under a punch has one length and (attached at one instant) one anchor, so the springs are the
    continuum exactly once the face holds a whole number of them: at Δx = 4, 2, 1 µm (dt = Δx/(2v)) F_N, F_x and A
    agree to round-off at every sample. At Δx = 8 µm the face holds 187.5 spacings, the springs' radius is
    188 Δx = 1.504 mm, and F_N differs by exactly that radius's share."""
    for dx in (4e-6, 2e-6, 1e-6):
        discrete = me.simulate(paper, "A", alpha=[30.0], dx=dx, dt=0.5 * dx / paper.v, profile=PUNCH)
        exact = me.simulate(paper, "A", alpha=[30.0], method="continuum", t=discrete["time"].values, profile=PUNCH)
        assert np.nanmax(discrete["contact_radius"].values) == PUNCH.radius
        for name, values in history_differences(discrete, exact).items():
            if name != "samples_left_out":
                assert values[0] < 1e-14, (dx, name, values)
    dx = 8e-6
    discrete = me.simulate(paper, "A", alpha=[30.0], dx=dx, dt=0.5 * dx / paper.v, profile=PUNCH)
    exact = me.simulate(paper, "A", alpha=[30.0], method="continuum", t=discrete["time"].values, profile=PUNCH)
    springs = 188 * dx
    assert np.nanmax(discrete["contact_radius"].values) == pytest.approx(springs, rel=1e-15)
    assert history_differences(discrete, exact)["normal_force"][0] == pytest.approx(springs / PUNCH.radius - 1, rel=1e-9)


def test_coulombs_law_on_a_punch_slides_wholly_at_mu_F_N_in_both_methods(paper):
    """Every spring is compressed by d: all share the cap μ E* d / G*, so full slip is μ F_N at once (the continuum's
    play operator of the face: tests/models/test_flat_punch_coulomb.py). The springs clip each step to their caps:
    the ratio to 1e-12; the continuum's pinned span is the linear form ``F0 + rate (t − t0)``, whose rounding is a few
    ulp of the span's largest force, 1e-12 of it (near the surface, where F_x → 0, that is not 1e-12 of F_x)."""
    hertz = paper.replace(dgamma0=0.0, dgamma1=0.0)
    coulomb = FrictionLaw("coulomb", mu=0.3)
    discrete = me.simulate(hertz, "A", alpha=[20.0], dx=4e-6, profile=PUNCH, friction=coulomb)
    exact = me.simulate(hertz, "A", alpha=[20.0], method="continuum", profile=PUNCH, friction=coulomb)
    for run in (discrete, exact):
        normal = run["normal_force"].values[0]
        pressed = (run["sliding_fraction"].values[0] == 1.0) & (normal > 0)
        assert np.count_nonzero(pressed) > 100
        force = run["tangential_force"].values[0][pressed]
        if run is discrete:
            np.testing.assert_allclose(force / normal[pressed], 0.3, rtol=1e-12)
        else:
            np.testing.assert_allclose(force, 0.3 * normal[pressed], rtol=0, atol=1e-12 * np.max(force))


@pytest.mark.parametrize("friction", [FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.2)],
                         ids=lambda f: f.law)
@pytest.mark.parametrize("scenario", ["B", "B+"])
def test_scenario_b_onsets_of_a_punch_with_coulombs_law(paper, friction, scenario):
    """Every spring under the punch is compressed by d, so every cap is K a + κ d: out at α, d = (d_max cot α − K a) /
    (cot α + κ); further in, d = (K a + d_max cot α)/(cot α − κ) (mindlin.d_crit_B, d_crit_B_indentation). The
    discrete model (Δx = 1 µm; the face holds whole springs, so only its time step lags) slides first within one
    time step's depth of it (the path moves 0.5 µm per step)."""
    from mdr_events.theory import mindlin
    hertz = paper.replace(dgamma0=0.0, dgamma1=0.0, tau0=1e3)  # (τ0 = 42 kPa: the punch comes off before it slides)
    alpha, dx = 40.0, 1e-6
    path = (me.Path.scenario_B if scenario == "B" else me.Path.scenario_B_indentation)(alpha, hertz, profile=PUNCH)
    expected = (mindlin.d_crit_B if scenario == "B" else mindlin.d_crit_B_indentation)(alpha, friction, hertz, PUNCH)
    run = me.simulate(hertz, path, dx=dx, dt=0.5 * dx / path.speed, profile=PUNCH, friction=friction)
    time, depth = run["time"].values, run["indentation_depth"].values[0]
    corner, turn = path.corner_times[1:3] - path.first_contact_time()  # d_max, and the far end of the motion at α
    after = (time > corner) & (time <= turn) & (np.nan_to_num(run["sliding_fraction"].values[0]) > 0)
    assert np.any(after) and 0.0 < expected < np.inf
    found = depth[np.argmax(after)]
    assert found == pytest.approx(expected, abs=0.5 * dx)
