"""The continuum method against the closed forms, the exact references and the discrete model."""

import math

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.models import continuum
from mdr_events.models.continuum import solve_path
from mdr_events.analysis.convergence import HISTORY_QUANTITIES, discrete_minus_continuum, exact_references_A, observed_orders
from mdr_events.models.simulation_schema import SIMULATION_VARIABLES
from mdr_events.models.paths import Path


def events_of(solution, kind):
    return [event for event in solution.events if event.kind == kind]


@pytest.mark.parametrize("alpha", [5.0, 10.0, 15.0, 20.0, 22.0])
def test_scenario_A_slip_onset_is_eq_18(paper, alpha):
    solution = solve_path(paper, Path.scenario_A(alpha, paper))
    (onset,) = events_of(solution, "slip_onset")
    assert onset[2] == pytest.approx(me.d_crit(alpha, paper, "A", adhesion=True), rel=1e-9)


def test_scenario_A_above_the_critical_angle_no_slip_during_indentation(paper):
    alpha = me.critical_angle(paper, "A", adhesion=True) + 0.5
    solution = solve_path(paper, Path.scenario_A(alpha, paper))
    corner = events_of(solution, "corner")[0][0]
    assert all(event[0] > corner for event in events_of(solution, "slip_onset"))


@pytest.mark.parametrize("alpha", [10.0, 30.0, 60.0])
def test_scenario_A_tangential_force_at_d_max_is_exact(paper, alpha):
    solution = solve_path(paper, Path.scenario_A(alpha, paper))
    corner = events_of(solution, "corner")[0][0]
    out = continuum.evaluate(solution, np.array([corner]))
    assert out["tangential_force"][0] == pytest.approx(exact_references_A(paper, alpha)["tangential_force_max"], rel=1e-8)
    # and the integrated F_x equals the algebraic form F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]
    # (no re-sticking in scenario A, so the final anchor map is the one at d_max)
    a = out["contact_radius"][0]
    assert a == pytest.approx(float(me.jkr_contact_radius(paper.d_max, paper, paper.dgamma0)), rel=1e-12)
    algebraic = continuum.algebraic_tangential_force(solution, np.array([corner]))[0]
    assert out["tangential_force"][0] == pytest.approx(algebraic, rel=1e-9)


@pytest.mark.parametrize("waypoints", [
    # indent at two angles (two growth pieces), retract part way, push on at a third angle
    # (growth resumes after a pinned span), then pull off to the side
    [(0.0, 0.0), (60e-6, 100e-6), (400e-6, 200e-6), (420e-6, 120e-6), (430e-6, 300e-6), (900e-6, -5e-5)],
    # steep then shallow indentation: the slip front crosses from one growth piece into the next
    [(0.0, 0.0), (20e-6, 150e-6), (900e-6, 300e-6), (900e-6, -5e-5)],
    # fast tangential growth then vertical: re-sticking of the slip zone while the cap grows
    [(0.0, 0.0), (500e-6, 60e-6), (500e-6, 300e-6), (1200e-6, -5e-5)],
    # a pinned slide, then vertical growth: the anchor map jumps up at the new piece and the front
    # waits at its start (found by review: F_x stayed flat there)
    [(0.0, 0.0), (150e-6, 150e-6), (350e-6, 150e-6), (350e-6, 300e-6), (1350e-6, 300e-6), (1350e-6, -90e-6)],
    # slide to full slip, then press in at an angle: growth resumes from full slip (found by review:
    # it stalled at the corner)
    [(0.0, 0.0), (0.0, 300e-6), (1000e-6, 300e-6), (1500e-6, 330e-6), (1500e-6, -90e-6)],
])
def test_integrated_tangential_force_equals_the_algebraic_form_along_a_general_path(paper, waypoints):
    """dF_x/dt integrated across every regime and slip state equals F_x = 2G*[cū + ∫_c^a (x − Y)dξ]
    evaluated from the anchor map in force, at 400 times (1e-8 of the largest |F_x|)."""
    solution = solve_path(paper, Path(waypoints, paper.v))
    times = np.linspace(0.0, solution.end_time, 401)[:-1]
    integrated = continuum.evaluate(solution, times)["tangential_force"]
    algebraic = continuum.algebraic_tangential_force(solution, times)
    scale = np.max(np.abs(algebraic))
    assert scale > 0
    np.testing.assert_allclose(integrated, algebraic, rtol=0, atol=1e-8 * scale)
    assert np.all(np.abs(integrated) <= paper.tau0 * math.pi * integrated_radius(solution, times) ** 2 * (1 + 1e-9))


def integrated_radius(solution, times):
    return continuum.evaluate(solution, times)["contact_radius"]


def test_pull_off_happens_at_the_jump_off_depth(paper):
    solution = solve_path(paper, Path.scenario_A(40.0, paper))
    (pull,) = events_of(solution, "pull_off")
    jump = me.jump_off(paper, paper.dgamma1)
    assert pull[2] == pytest.approx(jump["depth"], rel=1e-12)
    assert pull[3] == pytest.approx(jump["contact_radius"], rel=1e-12)


def test_scenario_B_slip_onset_eq_21_or_the_pinned_radius(paper):
    """(21) assumes the radius follows the Δγ1 branch from d_max; in the model it is pinned at
    a0 until d falls to d_1(a0). Where slip comes first, it happens at d_max − tan α ū(a0)."""
    a0 = float(me.jkr_contact_radius(paper.d_max, paper, paper.dgamma0))
    release = float(me.jkr_depth(a0, paper, paper.dgamma1))
    for alpha in (1.0, 3.0, 10.0, 30.0, 60.0):
        solution = solve_path(paper, Path.scenario_B(alpha, paper))
        (onset,) = events_of(solution, "slip_onset")
        assert events_of(solution, "full_slip")[0][0] == onset[0]  # uniform field: all at once
        pinned = paper.d_max - math.tan(math.radians(alpha)) * me.critical_shift(a0, paper)
        expected = pinned if pinned >= release else me.d_crit(alpha, paper, "B", adhesion=True)
        assert onset[2] == pytest.approx(expected, rel=1e-9)
        if alpha == 1.0:
            assert pinned > release and abs(pinned - me.d_crit(alpha, paper, "B", adhesion=True)) > 1e-7


def test_schema_event_log_and_round_trip(paper, tmp_path):
    ds = me.simulate(paper, "B", alpha=[20.0, 70.0], method="continuum", t=np.linspace(0, 1500, 301))
    for name, (units, _) in SIMULATION_VARIABLES.items():
        assert ds[name].dims == ("alpha", "time") and ds[name].attrs["units"] == units
    assert ds["event_kind"].dims == ("alpha", "event")
    assert list(ds["event_kind"].sel(alpha=20.0).values[:3]) == ["first_contact", "corner", "detachment_starts"]
    logged = {str(kind) for kind in ds["event_kind"].values.ravel() if kind}
    assert logged <= set(continuum.EVENT_KINDS)
    path = me.write_netcdf(ds, tmp_path / "c.nc")
    xr.testing.assert_identical(me.open_result(path), ds)
    with pytest.raises(ValueError, match="strictly"):
        me.simulate(paper, "A", alpha=[30.0], method="continuum", t=[0.0, 2.0, 1.0])


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_discrete_converges_to_the_continuum(paper, scenario):
    """max_t |discrete − continuum| of F_N, F_x and A falls at first order in Δx (observed > 0.7 between
    8, 4 and 2 µm); at most one sample each at the jump-in, the corner and the jump-off is left out."""
    spacings = (8e-6, 4e-6, 2e-6)
    differences = discrete_minus_continuum(paper, scenario, 30.0, spacings)
    for name in HISTORY_QUANTITIES:
        orders = observed_orders(spacings, differences[name])
        assert np.all(orders > 0.7), (name, differences[name], orders)
        assert differences[name][-1] < 2e-3, name  # about 1e-3 per µm of Δx
    assert np.all(differences["samples_left_out"] <= 3)  # jump-in, corner, jump-off at most


def test_cross_check(paper):
    a = me.cross_check(paper, "A", (8.0, 20.0), dx=2e-6, n_steps=8000)
    np.testing.assert_allclose(a["d_crit_continuum"], a["d_crit_closed_form"], rtol=1e-9)
    assert np.all(np.abs(a["discrete_minus_continuum"]) <= a["discrete_tolerance"])
    assert np.all(a["disagree"] == 0)
    b = me.cross_check(paper, "B", (1.0, 30.0), dx=2e-6, n_steps=8000)
    assert list(b["pinned_radius"].values) == [1, 0]
    # (21) ignores the pinned radius at 1°: the continuum meets the pinned onset there, d_max − tan α ū(a0)
    assert list(b["disagree"].values) == [0, 0]
    assert float(b["d_crit_pinned"].values[0]) == pytest.approx(float(b["d_crit_continuum"].values[0]), rel=1e-9)
    assert abs(float(b["d_crit_closed_form"].values[0]) - float(b["d_crit_continuum"].values[0])) > 1e-7
    assert np.all(np.abs(b["discrete_minus_continuum"]) <= b["discrete_tolerance"])
    for unit_check in (a, b):
        for var in unit_check.data_vars.values():
            assert var.attrs["units"] and var.attrs["long_name"]


def test_held_radius_inside_the_fold_comes_off_at_once(paper):
    p = paper.replace(dgamma1=1.0, d_max=10e-6)
    a0 = float(me.jkr_contact_radius(p.d_max, p, p.dgamma0))
    assert a0 < me.jump_off(p, p.dgamma1)["contact_radius"]
    solution = solve_path(p, Path([(0.0, 0.0), (1e-6, p.d_max), (1e-6, -3e-4)], p.v))
    (pull,) = events_of(solution, "pull_off")
    assert pull[2] == pytest.approx(float(me.jkr_depth(a0, p, p.dgamma1)), rel=1e-12)
    assert pull[3] == pytest.approx(a0, rel=1e-12)


@pytest.mark.parametrize("scenario, alpha", [("A", 20.0), ("B", 30.0), ("B", 60.0)])
def test_extremum_is_the_largest_value_of_the_solution(paper, scenario, alpha):
    """The exact extremes of a run: never below the largest of 20 001 samples, above it by no more than the
    sampling can miss at a smooth maximum (second order in the sample spacing), and reached at the time it
    reports. Scenario B's F_x peaks inside a shrinking span, where no event marks it."""
    path = me.Path.scenario_B(alpha, paper) if scenario == "B" else me.Path.scenario_A(alpha, paper)
    solution = continuum.solve_path(paper, path)
    times = np.linspace(0.0, solution.end_time, 20_001)
    filled = continuum.evaluate(solution, times)
    area = np.pi * filled["contact_radius"] ** 2
    sampled = {"tangential_force": filled["tangential_force"], "normal_force": filled["normal_force"],
               "contact_area": area}
    for quantity, values in sampled.items():
        for largest in (True, False):
            time, value = continuum.extremum(solution, quantity, largest)
            best = np.nanmax(values) if largest else np.nanmin(values)
            scale = np.nanmax(np.abs(values))
            assert (value >= best) if largest else (value <= best), (quantity, largest)
            assert abs(value - best) <= 1e-4 * scale, (quantity, largest)
            at_time = continuum.evaluate(solution, np.array([time]))
            if quantity == "contact_area":
                assert np.pi * at_time["contact_radius"][0] ** 2 == pytest.approx(value, rel=1e-12)
            else:
                assert at_time[quantity][0] == pytest.approx(value, rel=1e-12, abs=1e-15 * scale)


def test_extremum_rejects_unknown_quantities(paper):
    solution = continuum.solve_path(paper, me.Path.scenario_A(20.0, paper))
    with pytest.raises(ValueError, match="quantity='force' is not allowed; allowed: normal_force"):
        continuum.extremum(solution, "force")
