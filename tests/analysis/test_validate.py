"""``validate``: a simulator's output against the exact continuum, and reading it from any program."""

import math

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.convergence import history_differences, slip_onset_delay_bound
from mdr_events.analysis.samples import VALIDATED_EVENTS
from mdr_events.models.continuum import solve_path
from mdr_events.io.candidates import read_candidate

ALPHA = 20.0
DX = 2e-6


@pytest.fixture(scope="module")
def discrete(paper):
    """The package's own spring model, scenario A at 20°: a simulator to validate (one case)."""
    return me.simulate(paper, "A", alpha=[ALPHA], dx=DX, dt=0.5 * DX / paper.v)


@pytest.fixture(scope="module")
def solution(paper):
    return solve_path(paper, me.Path.scenario_A(ALPHA, paper))


@pytest.fixture(scope="module")
def tolerance(paper, solution):
    """The spring model's tolerance at Δx = 2 µm: its norms are within 1e-3 of each range, but its slip onset lags
    by up to ``slip_onset_delay_bound`` beyond a step (a step's travel short, the cap of a radius rounded to Δx/2):
    1.9e-3 of the path's duration (measured 1.4e-3)."""
    dt = 0.5 * DX / paper.v
    return max(1e-3, slip_onset_delay_bound(solution, paper, DX, dt) / solution.path.duration)


@pytest.fixture(scope="module")
def report(paper, discrete, tolerance):
    return me.validate(discrete.isel(alpha=0), paper, "A", ALPHA, tolerance=tolerance)


def test_the_errors_are_those_of_an_independent_route(paper, discrete, report):
    """max |candidate − exact| equals convergence.history_differences' (another route over the same samples:
    the continuum run by simulate at the discrete times) to the solver's tolerance; the norms are ordered
    L1 <= RMS <= max."""
    continuum = me.simulate(paper, "A", alpha=[ALPHA], method="continuum", t=discrete["time"].values)
    reference = history_differences(discrete, continuum)
    for name in ("normal_force", "tangential_force", "contact_area"):
        exact = report[f"exact_{name}"].values
        compared = np.isfinite(report[f"difference_{name}"].values)
        spread = np.ptp(exact[compared])
        absolute = float(report["max_error"].sel(quantity=name)) * spread
        assert absolute == pytest.approx(reference[name][0] * np.max(np.abs(continuum[name].values[0][compared])),
                                         rel=1e-6), name
        row = report.sel(quantity=name)
        assert float(row["l1_error"]) <= float(row["rms_error"]) <= float(row["max_error"])


def test_a_right_simulator_passes_and_a_wrong_one_fails(paper, discrete, report, tolerance):
    """At Δx = 2 µm the spring model is within 1e-3 of every quantity's range and its events within its tolerance
    (the slip onset's bound); with its tangential stiffness 5 % too high (F_x × 1.05) F_x fails and the rest still
    pass."""
    assert report.attrs["verdict"] == "pass" and np.all(report["within_tolerance"].values == 1)
    assert np.all(report["max_error"].values <= 1e-3)
    wrong = discrete.isel(alpha=0).copy()
    wrong["tangential_force"] = 1.05 * wrong["tangential_force"]
    failed = me.validate(wrong, paper, "A", ALPHA, tolerance=tolerance)
    assert failed.attrs["verdict"] == "fail"
    assert int(failed["within_tolerance"].sel(quantity="tangential_force")) == 0
    assert int(failed["within_tolerance"].sel(quantity="normal_force")) == 1


def test_events_are_found_within_a_step(paper, discrete, report, solution):
    """First contact, full slip, start of detachment and pull-off of the spring model lie within two time steps of
    the continuum's; its slip onset within one step and ``slip_onset_delay_bound`` (first order: a step's travel
    and the cap of a radius known to Δx/2, amplified by |ẋ|/(|ẋ| − K ȧ)); no re-contact in either run."""
    step = float(discrete["time"].values[1] - discrete["time"].values[0])
    errors = dict(zip(report["event"].values, report["event_time_error"].values))
    assert list(errors) == list(VALIDATED_EVENTS)
    assert np.isnan(errors.pop("re_contact"))
    for kind, error in errors.items():
        assert np.isfinite(error), kind
    for kind in ("first_contact", "full_slip", "detachment_starts", "pull_off"):
        assert abs(errors[kind]) <= 2 * step, kind
    assert 0 < errors["slip_onset"] <= step + slip_onset_delay_bound(solution, paper, DX, step)
    assert float(report["pull_off_force_exact"]) == pytest.approx(
        float(me.analytic.normal_force(report["event_depth_exact"].sel(event="pull_off"),
                                       me.jump_off(paper, paper.dgamma1)["contact_radius"], paper)), rel=1e-9)


def test_a_csv_in_your_units_with_your_names_gives_the_same_report(paper, discrete, report, tmp_path):
    """The same run as a CSV in ms, mN and mm² with other column names and a header comment: the same
    errors (to the CSV's 17 digits)."""
    run = discrete.isel(alpha=0)
    path = tmp_path / "run.csv"
    columns = {"t_ms": run["time"].values * 1e3, "Fn_mN": run["normal_force"].values * 1e3,
               "Ft_mN": run["tangential_force"].values * 1e3, "A_mm2": run["contact_area"].values * 1e6}
    with open(path, "w") as handle:
        handle.write("# my simulator\n" + ",".join(columns) + "\n")
        for row in zip(*columns.values()):
            handle.write(",".join(f"{value:.17g}" for value in row) + "\n")
    names = {"time": "t_ms", "normal_force": "Fn_mN", "tangential_force": "Ft_mN", "contact_area": "A_mm2"}
    units = {"time": "ms", "normal_force": "mN", "tangential_force": "mN", "contact_area": "mm2"}
    from_csv = me.validate(path, paper, "A", ALPHA, names=names, units=units)
    for name in ("normal_force", "tangential_force", "contact_area"):
        assert float(from_csv["max_error"].sel(quantity=name)) == pytest.approx(
            float(report["max_error"].sel(quantity=name)), rel=1e-9)


def test_time_origins_agree(paper, discrete, report):
    """Times counted from the path's start, or from 3 s before first contact, give the same report."""
    run = discrete.isel(alpha=0)
    shifted = {"time": run["time"].values + 3.0, "normal_force": run["normal_force"].values,
               "tangential_force": run["tangential_force"].values, "contact_area": run["contact_area"].values}
    offset = me.validate(shifted, paper, "A", ALPHA, time_origin=3.0)
    same = report["max_error"].sel(quantity=offset["quantity"].values).values
    np.testing.assert_allclose(offset["max_error"].values, same, rtol=1e-9)
    path = me.Path.scenario_A(ALPHA, paper)
    start = dict(shifted, time=run["time"].values + path.first_contact_time())
    from_start = me.validate(start, paper, path, time_origin="path_start")
    np.testing.assert_allclose(from_start["max_error"].values, same, rtol=1e-9)


def test_the_report_is_a_labelled_result_that_round_trips(report, tmp_path):
    for name, variable in report.variables.items():
        assert "units" in variable.attrs and "long_name" in variable.attrs, name
    written = me.write_netcdf(report, tmp_path / "report.nc")
    xr.testing.assert_identical(me.open_result(written), report)


@pytest.mark.parametrize("candidate, match", [
    ({"t": [0.0, 1.0], "normal_force": [0.0, 1.0]}, "no time column; columns found: t, normal_force"),
    ({"time": [0.0, 1.0], "force": [0.0, 1.0]}, "none of .* found; columns found: time, force"),
    ({"time": [0.0, 1.0, 0.5], "normal_force": [0.0, 1.0, 2.0]}, "strictly increasing"),
    ({"time": [0.0, 1.0], "normal_force": [0.0, 1.0, 2.0]}, "has 3 values and the time 2"),
])
def test_bad_candidates_are_named(candidate, match):
    with pytest.raises(ValueError, match=match):
        read_candidate(candidate)


def test_bad_names_units_and_arguments(paper, discrete):
    run = discrete.isel(alpha=0)
    with pytest.raises(ValueError, match=r"units\['normal_force'\]='lbf' is not allowed; allowed: 'N'"):
        read_candidate(run, units={"normal_force": "lbf"})
    with pytest.raises(ValueError, match=r"names\['normal_force'\]='Fn' is not a column; allowed: one of the columns found"):
        read_candidate(run, names={"normal_force": "Fn"})
    with pytest.raises(ValueError, match="alpha=None is not allowed with scenario 'A'"):
        me.validate(run, paper, "A")
    with pytest.raises(ValueError, match="time_origin='contact' is not allowed"):
        me.validate(run, paper, "A", ALPHA, time_origin="contact")
    with pytest.raises(ValueError, match="never touches"):
        me.validate({"time": [0.0, 1.0], "normal_force": [0.0, 0.0]}, paper, "A", ALPHA)
    with pytest.raises(TypeError, match="candidate of type int is not allowed"):
        me.validate(3, paper, "A", ALPHA)


def test_the_pull_off_force_is_also_compared_at_the_candidates_own_sample(paper, report):
    """F_N(t) is steep before the jump: the candidate's last force in contact is compared with the exact F_N at
    that same sample (close: a first-order model), not only with the jump's (off by sqrt(dt))."""
    candidate = float(report["pull_off_force_candidate"])
    at_sample = float(report["pull_off_force_exact_at_last_sample"])
    assert abs(candidate - at_sample) < 0.05 * abs(at_sample)
    assert abs(candidate - float(report["pull_off_force_exact"])) > abs(candidate - at_sample)


def test_a_time_axis_shorter_than_the_contact_is_refused(paper, discrete):
    run = discrete.isel(alpha=0)
    half = {name: run[name].values[: run.sizes["time"] // 2] for name in ("time", "normal_force", "contact_area")}
    with pytest.raises(ValueError, match="column 'time' ends at .* in contact, while the exact contact lasts beyond its "
                                         "next sample; allowed: values that cover the contact"):
        me.validate(half, paper, "A", ALPHA)


def test_what_was_not_checked_is_said(paper, discrete):
    """Columns not named as a quantity are listed, and so are the quantities not compared: a pass on F_N alone
    does not hide an unchecked F_x."""
    run = discrete.isel(alpha=0)
    table = {"t": run["time"].values, "Fn": run["normal_force"].values, "Ft": run["tangential_force"].values}
    report = me.validate(table, paper, "A", ALPHA, names={"time": "t", "normal_force": "Fn"})
    assert report["quantity"].values.tolist() == ["normal_force"]
    assert report.attrs["unused_columns"] == "Ft"
    assert report.attrs["quantities_not_compared"] == "tangential_force, contact_area, contact_radius"


def test_a_candidate_out_of_step_with_the_exact_run_is_refused(paper, discrete):
    """Times in the wrong unit or from the wrong origin put no sample in contact beside the exact contact:
    an error naming the time, not a failed verdict with nonsense numbers."""
    run = discrete.isel(alpha=0)
    shifted = {"time": run["time"].values + 5000.0, "normal_force": run["normal_force"].values,
               "contact_area": run["contact_area"].values}
    with pytest.raises(ValueError, match="0 samples of the candidate are in contact while the exact run is"):
        me.validate(shifted, paper, "A", ALPHA)


def test_a_power_law_candidate_is_validated_against_its_own_indenter(paper):
    """A discrete run of a power-law indenter (n = 3, Δx = 2 µm) passes against the power-law continuum (its
    first-order gap, below 1e-3 of each range) and fails against the paraboloid's: the door tells the indenters
    apart. The report names the profile."""
    from mdr_events.contact.indenters import PowerLaw

    profile = PowerLaw(2e3, 3.0)
    candidate = me.simulate(paper, "A", alpha=20.0, dx=2e-6, profile=profile).isel(alpha=0)
    report = me.validate(candidate, paper, "A", 20.0, profile=profile)
    assert report.attrs["verdict"] == "pass" and report.attrs["profile"].startswith("power law")
    assert np.all(report["max_error"].values < 1e-3)
    wrong = me.validate(candidate, paper, "A", 20.0)
    assert wrong.attrs["verdict"] == "fail" and np.all(wrong["max_error"].values > 0.1)
    assert "profile" not in wrong.attrs


def test_a_solution_of_another_indenter_is_refused(paper):
    from mdr_events.models.continuum import solve_path
    from mdr_events.contact.indenters import PowerLaw

    candidate = me.simulate(paper, "A", alpha=20.0, dx=4e-6, n_steps=2000).isel(alpha=0)
    solution = solve_path(paper, me.Path.scenario_A(20.0, paper))
    with pytest.raises(ValueError, match=r"solution= was solved for profile=None, not for profile=PowerLaw"):
        me.validate(candidate, paper, "A", 20.0, solution=solution, profile=PowerLaw(2e3, 3.0))
