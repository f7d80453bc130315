"""The verdict sees the contact and the events (issue 27, item 1): an event found later or earlier than the
tolerance of the path's duration fails, an event the candidate's quantities cannot show is named "not compared",
and the spring model's own lag at its slip onset is bounded (``slip_onset_delay_bound``)."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import slip_onset_delay_bound
from mdr_events.analysis.samples import VALIDATED_EVENTS
from mdr_events.app.cli import main
from mdr_events.app.validation_files import console_summary, validation_markdown
from mdr_events.models.continuum import solve_path

PAPER = me.Parameters.paper()
ALPHA = 20.0
#: A vertical in/out run (the issue's own case): in to 0.3 mm and out past the pull-off.
VERTICAL = me.Path([(0.0, -1e-5), (0.0, 3e-4), (0.0, -1e-4)], PAPER.v)
#: The quantities a displacement-controlled run writes (the exact run has the sliding fraction too).
WRITTEN = ("normal_force", "tangential_force", "contact_area", "sliding_fraction")


def exact_run(path: me.Path, samples: int = 4001) -> dict[str, np.ndarray]:
    """The exact continuum sampled as a simulator would write it: from first contact to the path's end."""
    end = path.duration - path.first_contact_time()
    ds = me.simulate(PAPER, {"run": path}, me.Continuum(t=np.linspace(0.0, end, samples))).isel(case=0)
    return {"time": ds["time"].values, **{name: ds[name].values for name in WRITTEN}}


def let_go_early(run: dict[str, np.ndarray], pull_off: float, share: float, duration: float) -> dict:
    """``run`` with its contact ending ``share`` of the path's duration before the exact pull-off (every force, the
    area 0 from there on, the sliding fraction undefined)."""
    gone = run["time"] >= pull_off - share * duration
    out = {name: np.where(gone, 0.0, values) for name, values in run.items() if name != "time"}
    out["sliding_fraction"] = np.where(gone, np.nan, run["sliding_fraction"])
    return {"time": run["time"], **out}


def event_error(report, event: str) -> float:
    return float(report["event_time_relative_error"].sel(event=event))


@pytest.fixture(scope="module")
def path_a():
    return me.Path.scenario_A(ALPHA, PAPER)


@pytest.fixture(scope="module")
def exact_a(path_a):
    return exact_run(path_a)


def test_the_exact_solution_passes_with_every_event_it_has(path_a, exact_a):
    """Sampled exactly, every event is found within one sample spacing (error 0 beyond it) and the run passes
    the default tolerance; re-contact is in neither run (not compared: nan)."""
    report = me.validate(exact_a, PAPER, path_a)
    assert report.attrs["verdict"] == "pass", me.ValidationReport.from_dataset(report).failures
    assert list(report["event"].values) == list(VALIDATED_EVENTS)
    for event in ("first_contact", "slip_onset", "full_slip", "detachment_starts", "pull_off"):
        assert event_error(report, event) == 0.0, event
    assert np.isnan(event_error(report, "re_contact"))
    assert report.attrs["events_not_compared"] == "none"
    vertical = me.validate(exact_run(VERTICAL), PAPER, VERTICAL)
    assert vertical.attrs["verdict"] == "pass", me.ValidationReport.from_dataset(vertical).failures


def test_the_issues_case_a_vertical_run_letting_go_2_percent_early_fails():
    """The issue's case: in and out vertically, the contact ending 2 % of the path's duration before the exact
    pull-off. Every sample it does show agrees with the exact run (max error ~1e-14), yet it fails: on the
    pull-off and on the contact in one run only."""
    run = exact_run(VERTICAL)
    solution = solve_path(PAPER, VERTICAL)
    early = let_go_early(run, solution.end_time, 0.02, VERTICAL.duration)
    report = me.validate(early, PAPER, VERTICAL)
    assert float(report["max_error"].max()) < 1e-9  # (the samples compared agree)
    assert report.attrs["verdict"] == "fail"
    failures = me.ValidationReport.from_dataset(report).failures
    assert any(text.startswith("pull_off:") for text in failures), failures
    assert any(text.startswith("contact:") for text in failures), failures
    # 2 % of the duration, less the one sample spacing the referee forgives
    step = float(np.diff(run["time"])[0])
    assert event_error(report, "pull_off") == pytest.approx(0.02 - step / VERTICAL.duration, rel=1e-2)


def test_a_pull_off_1_percent_early_fails_exit_1_and_is_named(path_a, exact_a, tmp_path, capsys, without_drawing):
    """The exact run of scenario A with its pull-off moved 1 % of the path earlier: exit 1, the pull-off named
    first in the console and in the Markdown."""
    solution = solve_path(PAPER, path_a)
    early = let_go_early(exact_a, solution.end_time, 0.01, path_a.duration)
    columns = {name: np.nan_to_num(values, nan=0.0) if name == "sliding_fraction" else values
               for name, values in early.items()}
    columns["sliding_fraction"] = np.where(columns["contact_area"] > 0, columns["sliding_fraction"], 0.0)
    csv = tmp_path / "early.csv"
    csv.write_text(",".join(columns) + "\n" + "".join(",".join(f"{value:.17g}" for value in row) + "\n"
                                                         for row in zip(*columns.values())))
    status = main(["validate", str(csv), "--scenario", "A", "--alpha", "20", "--out", str(tmp_path / "out")])
    out = capsys.readouterr().out
    assert status == 1
    failing = [line.strip() for line in out.splitlines() if line.strip().startswith("failing:")]
    assert any(line.startswith("failing: pull_off:") for line in failing), out
    report = me.open_result(tmp_path / "out" / "early.nc")
    assert event_error(report, "pull_off") > 1e-3
    summary = (tmp_path / "out" / "early.md").read_text()
    assert summary.index("## Failing") < summary.index("- Candidate:")
    assert "- **pull_off:" in summary


def test_the_spring_model_at_1_um_passes_with_its_events(paper):
    """The package's discrete model at Δx = 1 µm (dt = Δx/2v) passes the default tolerance, slip events included
    (it writes its sliding fraction); every event it shows is within the tolerance of the path's duration."""
    dx = 1e-6
    run = me.simulate(paper, "A", alpha=[ALPHA], dx=dx, dt=0.5 * dx / paper.v).isel(alpha=0)
    report = me.validate(run, paper, "A", ALPHA)
    assert report.attrs["verdict"] == "pass", me.ValidationReport.from_dataset(report).failures
    errors = report["event_time_relative_error"].values
    shown = np.isfinite(errors)
    assert set(report["event"].values[shown]) == {"first_contact", "slip_onset", "full_slip", "detachment_starts",
                                                  "pull_off"}
    assert np.all(errors[shown] <= report.attrs["tolerance"])


@pytest.mark.parametrize("dx", [2e-6, 1e-6])
def test_the_spring_models_slip_onset_lags_within_its_bound(paper, path_a, dx):
    """The spring model's slip onset comes late: the oldest springs attach at the end of the step that touches
    (a step's travel short) and their cap is that of a radius rounded to Δx/2. slip_onset_delay_bound
    (|ẋ| dt + K Δx/2)/(|ẋ| − K ȧ) bounds the lag beyond one step; measured 0.76 and 0.66 of it at 2 and 1 µm
    (dt = Δx/2v); a third of it is the floor (the bound is not loose)."""
    dt = 0.5 * dx / paper.v
    solution = solve_path(paper, path_a)
    run = me.simulate(paper, "A", alpha=[ALPHA], dx=dx, dt=dt).isel(alpha=0)
    report = me.validate(run, paper, "A", ALPHA, reference=solution, tolerance=1.0)
    lag = float(report["event_time_error"].sel(event="slip_onset")) - dt
    bound = slip_onset_delay_bound(solution, paper, dx, dt)
    assert bound / 3 <= lag <= bound, (lag, bound)
    assert event_error(report, "slip_onset") == pytest.approx(lag / path_a.duration, rel=1e-9)


def test_a_candidate_without_tangential_force_is_not_failed_on_slip_events(paper):
    """The spring model at 2 µm is late on its slip onset by 1.4e-3 of the duration (beyond 1e-3): with its
    sliding fraction it fails on that; the same run without F_x and the sliding fraction shows no slip event and
    passes, the slip events named "not compared" with the reason."""
    dx = 2e-6
    run = me.simulate(paper, "A", alpha=[ALPHA], dx=dx, dt=0.5 * dx / paper.v).isel(alpha=0)
    full = me.validate(run, paper, "A", ALPHA)
    assert full.attrs["verdict"] == "fail"
    assert [text.split(":")[0] for text in me.ValidationReport.from_dataset(full).failures] == ["slip_onset"]
    normal_only = {name: run[name].values for name in ("time", "normal_force", "contact_area")}
    report = me.validate(normal_only, paper, "A", ALPHA)
    assert report.attrs["verdict"] == "pass", me.ValidationReport.from_dataset(report).failures
    assert np.isnan(event_error(report, "slip_onset")) and np.isnan(event_error(report, "full_slip"))
    assert "slip_onset (no sliding_fraction)" in report.attrs["events_not_compared"]
    assert "full_slip (no sliding_fraction" in report.attrs["events_not_compared"]
    assert "Events not compared: slip_onset (no sliding_fraction)" in validation_markdown(report)


def test_the_events_round_trip_and_reports_written_before_still_open(path_a, exact_a, tmp_path):
    """The events and their errors are in the file; a report of before (four events, no relative errors, no
    failures attribute) still opens, is judged on what it holds and is drawn."""
    solution = solve_path(PAPER, path_a)
    failing = me.validate(let_go_early(exact_a, solution.end_time, 0.01, path_a.duration), PAPER, path_a)
    typed = me.ValidationReport.from_dataset(failing)
    read = me.ValidationReport.from_dataset(me.open_result(me.write_netcdf(failing, tmp_path / "now.nc")))
    assert read.failures == typed.failures and read.verdict is me.Verdict.FAIL
    np.testing.assert_array_equal(read.to_dataset()["event_time_relative_error"].values,
                                  failing["event_time_relative_error"].values)
    assert list(read.to_dataset()["event"].values) == list(VALIDATED_EVENTS)
    before = me.validate(exact_a, PAPER, path_a).drop_vars("event_time_relative_error").sel(
        event=["slip_onset", "full_slip", "detachment_starts", "pull_off"])
    for key in [key for key in before.attrs if key.startswith(("failures", "events_not_compared"))]:
        del before.attrs[key]
    old = me.ValidationReport.from_dataset(me.open_result(me.write_netcdf(before, tmp_path / "before.nc")))
    assert old.passed and old.failures == []
    assert "| pull-off |" in validation_markdown(old.to_dataset())
    assert any("PASS" in line for line in console_summary(old.to_dataset(), "before"))


def test_the_rule_names_an_event_out_of_tolerance_and_one_in_one_run_only():
    from mdr_events.analysis.reports import EventTimes, ValidationMeasures, validation_failures
    events = EventTimes(("pull_off", "re_contact", "slip_onset"), (100.0, np.nan, 50.0), (90.0, 200.0, np.nan),
                        (0.01, 0.05, np.nan))
    failures = validation_failures(ValidationMeasures(["normal_force"], [1e-4], 0.0, [0.0], events=events), 1e-3)
    assert [text.split(":")[0] for text in failures] == ["pull_off", "re_contact"]
    assert "not in the exact run" in failures[1]
    assert validation_failures(ValidationMeasures(["normal_force"], [1e-4], 0.0, [0.0], events=events), 0.1) == []
