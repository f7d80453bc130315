"""The continuum method under the rate-dependent law (continuum.rate_run, through simulate): the event log of the edge
and the springs at the right places, the extrema bounding the samples, a contact that ends shown gone."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me

PAPER = me.Parameters.paper()
BASE = me.Contact.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
RATE = me.Contact(BASE.elastomer, BASE.indenter, LAW, BASE.friction)
#: Full slip is (13) on the records' closed forms where the slip radius reaches the contact's: to rounding, with the
#: time found by bisection to the clock's spacing (the force moves by F' δt there, ~1e-16 of it).
FULL_SLIP_RTOL = 1e-9
#: An extremum refined between the samples beside the best of the edge's steps lies beyond every output sample, to
#: rounding (a few ulp of the force).
BEYOND_SAMPLES = 1e-12


@pytest.fixture(scope="module")
def scenario_a():
    return me.simulate(RATE, me.Scenario("A", alpha=[20.0]), "continuum").isel(alpha=0)


def test_the_log_holds_the_edge_s_and_the_springs_events_in_order(scenario_a):
    kinds = [str(kind) for kind in scenario_a["event_kind"].values if str(kind)]
    assert kinds == ["first_contact", "slip_onset", "corner", "re_stick", "detachment_starts", "slip_onset",
                     "full_slip"]
    times = scenario_a["event_time"].values[:len(kinds)]
    assert np.all(np.diff(times) >= 0.0)
    full = kinds.index("full_slip")
    radius = float(scenario_a["event_radius"].values[full])
    at = np.array([times[full]])
    from mdr_events.models.continuum import solve_rate_shifts

    from mdr_events.models.continuum.rate_run import RUN_METHOD

    path = me.Path.scenario_A(20.0, PAPER)
    force = solve_rate_shifts(PAPER, path, LAW, method=RUN_METHOD).tangential_force(at + path.first_contact_time())[0]
    assert force == pytest.approx(PAPER.tau0 * np.pi * radius ** 2, rel=FULL_SLIP_RTOL)
    directions = scenario_a["event_direction"].values[:len(kinds)]
    assert [int(d) for k, d in zip(kinds, directions) if k in ("slip_onset", "re_stick", "full_slip")] == [1] * 4


@pytest.mark.parametrize("name", ["normal_force", "tangential_force", "contact_area"])
def test_the_extrema_bound_the_samples(scenario_a, name):
    values = scenario_a[name].values
    largest, least = float(scenario_a[f"{name}_max"]), float(scenario_a[f"{name}_min"])
    scale = np.nanmax(np.abs(values))
    assert largest >= np.nanmax(values) - BEYOND_SAMPLES * scale and least <= np.nanmin(values) + BEYOND_SAMPLES * scale
    step = np.nanmax(np.abs(np.diff(values)))  # (a continuous quantity: its extremum within one sample's change of
    # the best sample; the largest F_N is at the corner, a kink between two samples)
    assert largest - np.nanmax(values) <= step and np.nanmin(values) - least <= step


def test_a_contact_that_ends_is_shown_gone_and_logged():
    """Vertically in and out far enough at 0.1 µm/s: the contact ends on the path (its radius collapses), the log ends
    with contact_ends, the first sample after it shows the contact gone and the later ones are nan."""
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -300e-6)]), speed=1e-7)
    run = me.simulate(RATE, me.Paths([path]), "continuum", samples=401).isel(case=0)
    kinds = [str(kind) for kind in run["event_kind"].values if str(kind)]
    assert kinds[0] == "first_contact" and kinds[-1] == "contact_ends"
    end = float(run["event_time"].values[len(kinds) - 1])
    after = np.flatnonzero(run["time"].values > end)
    assert after.size >= 1 and run["normal_force"].values[after[0]] == 0.0
    assert np.all(np.isnan(run["normal_force"].values[after[1:]]))
    assert float(run["normal_force_min"]) < 0.0 and float(run["contact_area_min"]) == 0.0


def test_a_continuum_sweep_of_the_law_runs_simulate_s_run():
    """The sweep's continuum quantities under the law are those of simulate's continuum run (refused before: they read
    the paper's spans); every run against its single run bit for bit in tests/analysis/test_rate_sweep.py."""
    swept = me.sweep({"v": [1e-6, 1e-5]}, RATE, me.Scenario("A", alpha=[20.0]), method="continuum",
                     scheduler="serial", quantities=("normal_force_min",))
    for speed in (1e-6, 1e-5):
        alone = me.simulate(RATE, me.Scenario("A", alpha=[20.0], v=speed), "continuum")
        assert float(swept["normal_force_min"].sel(v=speed)) == float(alone["normal_force_min"].isel(alpha=0))


@pytest.mark.parametrize("friction", [me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.3),
                                      pytest.param(me.FrictionLaw("coulomb", mu=0.3), marks=pytest.mark.slow)],
                         ids=["tau0+coulomb", "coulomb"])  # (some 4 s of CPU each: the events bisected on the route)
def test_coulomb_s_part_runs_spring_by_spring_on_the_edge(friction):
    """Item 2 of issue 29 was left as a refusal for Coulomb's part (each spring its own cap); issue 26 asked that nothing
    the discrete model runs be refused by the continuum: both laws with Coulomb's part run, F_x at the samples is the
    per-spring route's on the edge's history (continuum.rate_coulomb; its accuracy: tests/models/test_rate_coulomb.py),
    the normal problem is the edge's whatever the friction law, and the log holds the edge's and the springs' events."""
    from mdr_events.models.continuum.play_springs import PlaySprings, spring_line
    from mdr_events.models.continuum.rate_edge import solve_edge
    from mdr_events.models.continuum.rate_history import RateHistory
    from mdr_events.models.continuum.rate_run import RUN_METHOD

    path = me.Path.scenario_A(20.0, PAPER)
    paper_law = me.simulate(RATE, me.Scenario("A", alpha=[20.0]), "continuum", samples=11).isel(alpha=0)
    coulomb = dataclasses.replace(RATE, friction=friction)
    run = me.simulate(coulomb, me.Scenario("A", alpha=[20.0]), "continuum", samples=11).isel(alpha=0)
    for name in ("normal_force", "contact_radius", "indentation_depth"):
        np.testing.assert_array_equal(run[name].values, paper_law[name].values, err_msg=name)
    route = PlaySprings(spring_line(PAPER, None, friction), path,
                        RateHistory(solve_edge(PAPER, path, LAW, method=RUN_METHOD)))
    times = run["time"].values + path.first_contact_time()
    held = np.isfinite(run["tangential_force"].values)
    np.testing.assert_array_equal(run["tangential_force"].values[held], route.tangential_force(times[held]))
    kinds = [str(kind) for kind in run["event_kind"].values if str(kind)]
    assert kinds[0] == "first_contact" and "slip_onset" in kinds and "detachment_starts" in kinds, kinds
    # (the run ends in contact, the edge lagging: its full slip on the way out is searched to the path's end, not to
    # the log's last event; before, under "tau0+coulomb" it was missed)
    assert "full_slip" in kinds and [int(way) for kind, way in zip(kinds, run["event_direction"].values)
                                     if kind in ("slip_onset", "full_slip")] == [1, 1], kinds
    assert float(run["tangential_force_max"]) >= np.max(run["tangential_force"].values[held])


#: The least F_N against the edge's own pull-off (solve_edge's extremum of the same normal problem by the run's method,
#: by its own scan): both refine the minimum between the edge's steps, to the bounded minimisation's tolerance
#: (measured 2.5e-15).
PULL_OFF_RTOL = 1e-12


def test_simulate_at_several_speeds_gives_each_path_as_alone_and_a_faster_one_pulls_harder():
    """Issue 29's "simulate at several speeds": scenario A at 20° at 0.1, 1 and 10 µm/s, one case per path in one call
    (the time axis is the slowest path's, so each path alone is asked at the same times): every case is its path alone,
    bit for bit; the least F_N is each path's pull-off by solve_edge and grows in magnitude with the speed, and the
    smaller contact the faster edge reaches on the way in holds less tangential force."""
    from mdr_events.models.continuum import solve_edge
    from mdr_events.models.continuum.rate_run import RUN_METHOD

    paths = {f"v = {speed:g} m/s": me.Path.scenario_A(20.0, PAPER.replace(v=speed)) for speed in (1e-7, 1e-6, 1e-5)}
    together = me.simulate(RATE, me.Paths(paths), "continuum", samples=401)
    times = together["time"].values
    least = []
    for index, (label, path) in enumerate(paths.items()):
        alone = me.simulate(RATE, me.Paths({label: path}), "continuum", t=times).isel(case=0)
        case = together.isel(case=index)
        for name in ("normal_force", "tangential_force", "contact_radius", "normal_force_min", "tangential_force_max"):
            np.testing.assert_array_equal(case[name].values, alone[name].values, err_msg=f"{label}: {name}")
        least.append(float(case["normal_force_min"]))
        pull_off = solve_edge(PAPER, path, LAW, method=RUN_METHOD).pull_off_force(path)
        assert least[-1] == pytest.approx(pull_off, rel=PULL_OFF_RTOL)
    assert least[0] > least[1] > least[2], least
    largest = together["tangential_force_max"].values
    assert largest[0] > largest[1] > largest[2], largest
