"""``mdr-events validate`` and the ``[validate]`` table of study files: a simulator's runs against the continuum.

The simulator under test is the package's own spring model (scenario A at 20°, Δx = 2 µm: within 1e-3 of
every quantity's range), written as a CSV as any program would; a wrong one has F_x × 1.1.
"""

import functools
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from matplotlib.figure import Figure

import mdr_events as me
from mdr_events.analysis.convergence import slip_onset_delay_bound
from mdr_events.app.cli import main
from mdr_events.models.continuum import solve_path
from mdr_events.app import validation_files
from mdr_events.app.study import load_study
from mdr_events.app.validation_files import validation_markdown, write_validation
from mdr_events.plotting.validation import plot_validation

ALPHA = 20.0
DX = 2e-6
COLUMNS = ("time", "normal_force", "tangential_force", "contact_area")


def spring_tolerance(params, dx=DX):
    """The tolerance the spring model at ``dx`` (dt = Δx/2v) is judged at when it writes its sliding fraction: 1e-3
    of each range for its norms, and its slip onset's lag beyond a step, ``slip_onset_delay_bound`` (a step's travel
    short, the cap of a radius rounded to Δx/2), relative to the path's duration (1.9e-3 at 2 µm; measured 1.4e-3)."""
    solution = solve_path(params, me.Path.scenario_A(ALPHA, params))
    bound = slip_onset_delay_bound(solution, params, dx, 0.5 * dx / params.v)
    return max(1e-3, bound / solution.path.duration)


def discrete_run(params, dx=DX):
    """The spring model's run of scenario A at 20° (one case), sampled every half spring spacing of travel: run once
    per parameters and spacing in this module (six tests read the one at :data:`DX`), a deep copy for each caller so
    that none sees what another changed."""
    return _discrete_run(params, dx).copy(deep=True)


@functools.cache
def _discrete_run(params, dx):
    return me.simulate(params, "A", alpha=[ALPHA], dx=dx, dt=0.5 * dx / params.v).isel(alpha=0)


def write_csv(path, columns: dict):
    """A CSV with a header row, full precision (as a user's simulator would write it)."""
    path.write_text(",".join(columns) + "\n" + "".join(
        ",".join(f"{value:.17g}" for value in row) + "\n" for row in zip(*columns.values())))
    return path


@pytest.fixture(scope="module")
def runs(paper, tmp_path_factory):
    """``run.csv`` (right) and ``wrong.csv`` (F_x × 1.1) in a directory of their own."""
    folder = tmp_path_factory.mktemp("runs")
    run = discrete_run(paper)
    columns = {name: run[name].values for name in COLUMNS}
    write_csv(folder / "run.csv", columns)
    write_csv(folder / "wrong.csv", dict(columns, tangential_force=1.1 * columns["tangential_force"]))
    return folder


def validate_cli(capsys, *argv):
    status = main(["validate", *map(str, argv)])
    out, err = capsys.readouterr()
    return status, out, err


def assert_one_error_line(err, fragment):
    assert err.count("\n") == 1 and err.startswith("mdr-events: error:"), err
    assert fragment in err, err
    assert "Traceback" not in err


def console_script():
    """The installed ``mdr-events``, or the CLI module run by this interpreter if it is not installed."""
    exe = shutil.which("mdr-events") or str(Path(sys.executable).parent / "mdr-events")
    return [exe] if Path(exe).exists() else [sys.executable, "-m", "mdr_events.app.cli"]


def test_console_script_passes_a_right_run_and_writes_its_files(runs, tmp_path):
    out = tmp_path / "out"
    result = subprocess.run([*console_script(), "validate", str(runs / "run.csv"), "--preset", "paper-R30",
                             "--scenario", "A", "--alpha", "20", "--out", str(out)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert f"{runs / 'run.csv'}: PASS (tolerance 0.001" in result.stdout
    assert "max error / range: normal_force" in result.stdout and "1 run: 1 pass, 0 fail" in result.stdout
    assert len(result.stdout.splitlines()) <= 24  # one screen
    assert sorted(p.name for p in out.iterdir()) == ["run.md", "run.nc", "run.png"]
    report = me.open_result(out / "run.nc")
    assert report.attrs["verdict"] == "pass" and report.attrs["tolerance"] == 1e-3
    assert set(report["quantity"].values) == {"normal_force", "tangential_force", "contact_area"}
    assert np.all(report["max_error"].values <= 1e-3)
    assert report.attrs["path_description"] == "scenario A, α = 20°"
    assert report.attrs["parameters_preset"] == "paper-R30"
    summary = (out / "run.md").read_text()
    assert "**Verdict: pass**" in summary and "| tangential_force |" in summary and "| pull-off |" in summary
    compared, left_out = int(report["samples_compared"]), int(report["samples_left_out"])
    assert f"Samples compared: {compared}; left out: {left_out}" in summary
    assert "Tolerance: 0.001" in summary and f"Candidate: `{runs / 'run.csv'}`" in summary
    assert (out / "run.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_wrong_run_exits_1_and_says_which_quantity(capsys, runs, tmp_path, without_drawing):
    status, out, err = validate_cli(capsys, runs / "run.csv", runs / "wrong.csv", "--scenario", "A", "--alpha", "20",
                                    "--out", tmp_path)
    assert status == 1, err
    assert "run.csv: PASS" in out and "wrong.csv: FAIL" in out and "2 runs: 1 pass, 1 fail" in out
    assert "tangential_force 9.9" in out and "(!)" in out  # max error ~0.1 of the range, flagged
    wrong = me.open_result(tmp_path / "wrong.nc")
    assert wrong.attrs["verdict"] == "fail"
    assert int(wrong["within_tolerance"].sel(quantity="tangential_force")) == 0
    assert int(wrong["within_tolerance"].sel(quantity="normal_force")) == 1
    summary = (tmp_path / "wrong.md").read_text()
    assert "**Verdict: fail**" in summary and "| tangential_force |" in summary and "**no**" in summary
    assert me.open_result(tmp_path / "run.nc").attrs["verdict"] == "pass"


def test_a_tolerance_of_your_own_decides(capsys, runs, tmp_path, without_drawing):
    """F_x × 1.1 is about 0.1 of the range off: it passes a tolerance of 0.2."""
    status, out, _ = validate_cli(capsys, runs / "wrong.csv", "--scenario", "A", "--alpha", "20", "--out", tmp_path,
                                  "--tolerance", "0.2")
    assert status == 0 and "wrong.csv: PASS (tolerance 0.2" in out
    assert me.open_result(tmp_path / "wrong.nc").attrs["tolerance"] == 0.2


def test_your_names_units_and_time_origin(capsys, paper, runs, tmp_path, without_drawing):
    """The same run in ms, mN, mm² under other names, its time from the path's start: the same errors."""
    run = discrete_run(paper)
    start = me.Path.scenario_A(ALPHA, paper).first_contact_time()
    write_csv(tmp_path / "mine.csv", {"t": (run["time"].values + start) * 1e3, "Fn": run["normal_force"].values * 1e3,
                                      "Ft": run["tangential_force"].values * 1e3,
                                      "A": run["contact_area"].values * 1e6})
    status, _, err = validate_cli(capsys, tmp_path / "mine.csv", "--scenario", "A", "--alpha", "20", "--out",
                                  tmp_path / "out",
                                  "--names", "time=t,normal_force=Fn,tangential_force=Ft,contact_area=A",
                                  "--units", "time=ms,normal_force=mN,tangential_force=mN,contact_area=mm2",
                                  "--time-origin", "path_start")
    assert status == 0, err
    mine = me.open_result(tmp_path / "out" / "mine.nc")
    reference = me.validate(runs / "run.csv", paper, "A", ALPHA)
    np.testing.assert_allclose(mine["max_error"].values, reference["max_error"].values, rtol=1e-6)
    assert mine.attrs["time_origin"] == "path_start"


def test_a_path_file_and_a_parameters_file(capsys, paper, runs, tmp_path, without_drawing):
    """--path: a TOML [path] table (here scenario A's waypoints) gives the scenario's report; --params: a TOML
    [parameters] table (a study file's) gives its parameters, here another τ0 that the run does not follow."""
    path = me.Path.scenario_A(ALPHA, paper)
    points = ", ".join(f"[{float(x)!r}, {float(d)!r}]" for x, d in path.waypoints)
    (tmp_path / "path.toml").write_text(f"[path]\nwaypoints = [{points}]\nspeed = {path.speed!r}\n")
    status, _, err = validate_cli(capsys, runs / "run.csv", "--path", tmp_path / "path.toml", "--out", tmp_path / "p")
    assert status == 0, err
    from_file = me.open_result(tmp_path / "p" / "run.nc")
    scenario = me.validate(runs / "run.csv", paper, "A", ALPHA)
    np.testing.assert_allclose(from_file["max_error"].values, scenario["max_error"].values, rtol=1e-9)
    assert from_file.attrs["path_description"] == f"from the path file {tmp_path / 'path.toml'}"

    (tmp_path / "params.toml").write_text("[parameters]\npreset = 'paper-R30'\ntau0 = 60e3\n"
                                          "[output]\ndirectory = 'x'\n")
    status, out, err = validate_cli(capsys, runs / "run.csv", "--params", tmp_path / "params.toml", "--scenario", "A",
                                    "--alpha", "20", "--out", tmp_path / "q")
    assert status == 1, err  # the run slides at τ0 = 42 kPa, not 60 kPa
    other = me.open_result(tmp_path / "q" / "run.nc")
    assert other.attrs["param_tau0"] == 60e3 and other.attrs["parameters_from_preset"].count("tau0") == 0


def test_three_spacings_give_a_convergence_study(capsys, paper, tmp_path, without_run_figures):
    pytest.importorskip("mdr_events.analysis.convergence_study")
    without_run_figures()  # (the study's figure is drawn)
    names = []
    for dx in (8e-6, 4e-6, 2e-6):
        run = discrete_run(paper, dx)
        names.append(write_csv(tmp_path / f"run_dx{dx * 1e6:g}um.csv", {name: run[name].values for name in COLUMNS}))
    status, out, err = validate_cli(capsys, *names, "--scenario", "A", "--alpha", "20", "--out", tmp_path / "out")
    assert status == 1, err  # the coarser runs are outside 1e-3
    assert "convergence study (3 spacings): converges" in out
    study = me.open_result(tmp_path / "out" / "convergence_study.nc")
    np.testing.assert_allclose(study["dx"].values, [8e-6, 4e-6, 2e-6])
    assert np.all(np.abs(study["max_error_order"].values - 1.0) < 0.2)
    assert (tmp_path / "out" / "convergence_study.png").exists()
    # --dx names the spacings; fewer than three: no study, said so
    status, out, _ = validate_cli(capsys, names[2], "--scenario", "A", "--alpha", "20", "--out", tmp_path / "one",
                                  "--dx", "2e-6")
    assert status == 0 and "convergence study skipped" in out


def write_bad_csvs(folder: Path, runs: Path) -> None:
    text = (runs / "run.csv").read_text().splitlines()
    (folder / "no_time.csv").write_text("\n".join([text[0].replace("time", "t")] + text[1:]) + "\n")
    (folder / "nan_time.csv").write_text("\n".join(text[:3] + ["nan" + text[3][text[3].index(","):]] + text[4:]) + "\n")
    (folder / "no_contact.csv").write_text("time,normal_force\n0,0\n1,0\n2,0\n")


A20 = ["--scenario", "A", "--alpha", "20"]


@pytest.mark.parametrize("argv, fragment", [
    # a column missing, named by the user or required
    (["no_time.csv", *A20], "no_time.csv: no time column; columns found: t, normal_force"),
    (["run.csv", *A20, "--names", "normal_force=Fn"],
     "wrong.csv: names['normal_force']='Fn' is not a column; allowed: one of the columns found: time, normal_force"),
    # units
    (["run.csv", *A20, "--units", "time=fortnight"],
     "wrong.csv: units['time']='fortnight' is not allowed; allowed: 's', 'ms'"),
    (["run.csv", *A20, "--units", "speed=ms"],
     "--units 'speed=ms': 'speed' is not allowed; allowed: time, normal_force"),
    (["run.csv", *A20, "--names", "time"], "--names 'time': 'time' is not allowed; allowed: QUANTITY=VALUE pairs"),
    # files
    (["missing.csv", *A20], "candidate='missing.csv': no such file"),
    (["run.csv", "nan_time.csv", *A20], "nan_time.csv: column 'time' is not allowed as the time"),
    (["no_contact.csv", *A20], "no_contact.csv: the candidate never touches"),
    (["run.csv", "sub/run.csv", *A20], "the runs run.csv and sub/run.csv would both be written as run.*"),
    # the path and its angle
    (["run.csv", "--scenario", "A", "--alpha", "100"],
     "--alpha 100: alpha=100.0 (degrees) is not allowed; allowed: finite angles in [0, 90]"),
    (["run.csv", "--scenario", "A", "--alpha", "steep"], "argument --alpha: 'steep' is not allowed; allowed: a plain decimal number"),
    (["run.csv", "--scenario", "A", "--alpha", "0"], "--alpha 0: alpha=0.0 in scenario A"),
    (["run.csv", "--scenario", "A"], "--scenario A needs --alpha"),
    (["run.csv", "--alpha", "20"], "one of the arguments --scenario --path is required"),
    (["run.csv", *A20, "--path", "path.toml"], "not allowed with argument --scenario"),
    (["run.csv", "--path", "path.toml"], "--path path.toml: no such path file"),
    (["run.csv", *A20, "--params", "nope.toml"], "--params nope.toml: no such parameters file"),
    (["run.csv", *A20, "--E", "-1"], "Parameters.E=-1.0 is not allowed"),
    # options
    (["run.csv", *A20, "--tolerance", "0"], "--tolerance 0.0 is not allowed; allowed: a number in (0, 1]"),
    (["run.csv", *A20, "--time-origin", "soon"],
     "--time-origin 'soon' is not allowed; allowed: first_contact, path_start"),
    (["run.csv", *A20, "--dx", "1e-6", "2e-6"], "--dx has 2 values and there are 1 runs"),
])
def test_bad_input_is_one_line_exit_2_and_writes_nothing(capsys, runs, tmp_path, monkeypatch, argv, fragment):
    """Refused before anything is written, and before any run's figure is drawn (every run is judged first)."""
    monkeypatch.chdir(tmp_path)
    drawn = []
    monkeypatch.setattr(validation_files, "render_validation", lambda report, stem: drawn.append(stem))
    for name in ("run.csv", "wrong.csv"):
        shutil.copy(runs / name, tmp_path / name)
    (tmp_path / "sub").mkdir()
    shutil.copy(runs / "run.csv", tmp_path / "sub" / "run.csv")
    write_bad_csvs(tmp_path, runs)
    if "--dx" in argv:  # one spacing per run
        argv = [arg for arg in argv if arg != "wrong.csv"]
        status, out, err = validate_cli(capsys, *argv, "--out", "out")
    else:  # a valid run first: nothing is written for it either when a later one is bad
        status, out, err = validate_cli(capsys, "wrong.csv", *argv, "--out", "out")
    assert status == 2
    assert_one_error_line(err, fragment)
    assert out == ""
    assert not (tmp_path / "out").exists()
    assert drawn == []


def test_a_netcdf_run_is_read_and_never_overwritten(capsys, paper, tmp_path, without_drawing):
    """A netCDF run (the package's own, with its units and its sliding fraction: judged at its slip onset's tolerance,
    spring_tolerance) validates; --out beside it would overwrite it: refused."""
    me.write_netcdf(discrete_run(paper), tmp_path / "run.nc")
    before = (tmp_path / "run.nc").read_bytes()
    status, _, err = validate_cli(capsys, tmp_path / "run.nc", "--scenario", "A", "--alpha", "20", "--out", tmp_path)
    assert status == 2
    assert_one_error_line(err, f"--out {tmp_path}: writing {tmp_path / 'run.nc'} would overwrite a run")
    assert (tmp_path / "run.nc").read_bytes() == before and sorted(p.name for p in tmp_path.iterdir()) == ["run.nc"]
    status, out, err = validate_cli(capsys, tmp_path / "run.nc", "--scenario", "A", "--alpha", "20", "--out",
                                    tmp_path / "out", "--tolerance", spring_tolerance(paper))
    assert status == 0, err
    assert me.open_result(tmp_path / "out" / "run.nc").attrs["verdict"] == "pass"


STUDY = """
[parameters]
preset = "paper-R30"

[validate]
runs = ["runs/run.csv", "runs/wrong.csv"]
scenario = "A"
alpha = 20
tolerance = 1e-3

[output]
directory = "out"
name = "demo"
"""


def copy_runs(runs: Path, folder: Path) -> None:
    (folder / "runs").mkdir()
    for name in ("run.csv", "wrong.csv"):
        shutil.copy(runs / name, folder / "runs" / name)


def test_a_study_validates_its_runs(capsys, runs, tmp_path, without_drawing, without_run_figures):
    copy_runs(runs, tmp_path)
    (tmp_path / "study.toml").write_text(STUDY)
    assert main(["run", str(tmp_path / "study.toml")]) == 1  # wrong.csv fails
    out, err = capsys.readouterr()
    assert "validation failed: runs/wrong.csv" in out and "validate: runs/run.csv: pass" in err
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [
        f"demo_validation_{run}.{suffix}" for run in ("run", "wrong") for suffix in ("md", "nc", "png")]
    right = me.open_result(tmp_path / "out" / "demo_validation_run.nc")
    assert right.attrs["verdict"] == "pass" and right.attrs["path_description"] == "scenario A, α = 20°"
    without_run_figures()  # (the same study again, for its verdicts)
    outcomes = me.run_study(load_study(tmp_path / "study.toml"), progress=lambda message: None)
    assert outcomes.verdicts == {"runs/run.csv": "pass", "runs/wrong.csv": "fail"}


def test_a_study_takes_the_angle_and_options_from_its_tables(capsys, paper, runs, tmp_path, without_drawing):
    """Scenario and angle from [simulation] (simulated too), your names and units in [validate]."""
    run = discrete_run(paper)
    (tmp_path / "runs").mkdir()
    write_csv(tmp_path / "runs" / "mine.csv", {"t": run["time"].values * 1e3, "Fx": run["tangential_force"].values})
    (tmp_path / "study.toml").write_text("""
[simulation]
scenario = "A"
alpha = [20]
method = "continuum"
samples = 11
[validate]
runs = ["runs/mine.csv"]
names = { time = "t", tangential_force = "Fx" }
units = { time = "ms" }
time_origin = 0
[output]
directory = "out"
""")
    assert main(["run", str(tmp_path / "study.toml")]) == 0, capsys.readouterr().err
    names = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert names == ["study_simulation.nc", "study_simulation.png", "study_simulation_events.csv",
                     "study_validation_mine.md", "study_validation_mine.nc", "study_validation_mine.png"]
    report = me.open_result(tmp_path / "out" / "study_validation_mine.nc")
    assert list(report["quantity"].values) == ["tangential_force"] and report.attrs["verdict"] == "pass"


@pytest.mark.parametrize("change, fragment", [
    ("runs = ['runs/run.csv', 'runs/missing.csv']", "missing.csv': no such file"),
    ("units = { time = 'fortnight' }", "run.csv: units['time']='fortnight' is not allowed"),
    ("alpha = 95", "[validate] alpha=95.0 (degrees) is not allowed"),
])
def test_a_bad_run_in_a_study_writes_nothing(capsys, runs, tmp_path, monkeypatch, change, fragment):
    """The runs are validated before anything of the study is written, also its simulation, and before any run's
    figure is drawn."""
    drawn = []
    monkeypatch.setattr(validation_files, "render_validation", lambda report, stem: drawn.append(stem))
    copy_runs(runs, tmp_path)
    key = change.split(" = ")[0]
    lines = [line for line in STUDY.splitlines() if not line.startswith(f"{key} = ")]
    text = "\n".join(lines).replace("[validate]", f"[validate]\n{change}")
    text += "\n[simulation]\nscenario = 'A'\nalpha = [20]\nmethod = 'continuum'\nsamples = 11\n"
    (tmp_path / "study.toml").write_text(text)
    assert main(["run", str(tmp_path / "study.toml")]) == 2
    err = capsys.readouterr().err
    last = err.splitlines()[-1]
    assert fragment in last and f"{tmp_path / 'study.toml'}: [validate] " in last
    assert not (tmp_path / "out").exists() and drawn == []


def test_the_figure_and_summary_are_drawn_from_the_report_only(paper, runs, tmp_path):
    """A report read back from its file gives the same figure layout and the same Markdown."""
    report = me.validate(runs / "wrong.csv", paper, "A", ALPHA)
    written = write_validation(report, tmp_path, "wrong")
    assert [outcome.path.name for outcome in written] == ["wrong.nc", "wrong.md", "wrong.png"]
    again = me.open_result(tmp_path / "wrong.nc")
    assert validation_markdown(again, "wrong") == (tmp_path / "wrong.md").read_text()
    figure = plot_validation(again)
    assert isinstance(figure, Figure)
    assert len(figure.axes) == 2 * report.sizes["quantity"]
    assert "fail" in figure.get_suptitle()
    titles = [ax.get_title() for ax in figure.axes if ax.get_title()]
    assert sum("outside tolerance" in title for title in titles) == 1  # F_x
    labels = figure.legends[0].get_texts()
    assert any(text.get_text().startswith("left out: straddles an event") for text in labels)


@pytest.mark.parametrize("column, row, value, words", [
    ("normal_force", 700, np.inf, "holds inf at data row 701"),
    ("tangential_force", 5, -np.inf, "holds -inf at data row 6"),
    ("contact_area", 900, np.nan, "holds nan at data row 901"),       # inside the run: finite values follow
    ("tangential_force", 1, np.nan, "holds nan at data row 2"),
])
def test_a_run_with_a_non_finite_sample_is_refused_never_passed(capsys, runs, tmp_path, column, row, value, words):
    """A broken run is refused in one line naming the file, the column and the first row (it passed before: the
    sample was left out silently); nothing is written."""
    table = np.genfromtxt(runs / "run.csv", delimiter=",", names=True)
    columns = {name: table[name].copy() for name in COLUMNS}
    columns[column][row] = value
    broken = write_csv(tmp_path / "broken.csv", columns)
    status, _, err = validate_cli(capsys, broken, "--scenario", "A", "--alpha", "20", "--out", tmp_path / "o")
    assert status == 2
    assert_one_error_line(err, f"broken.csv: column {column!r} {words}")
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


def test_nan_after_the_run_and_an_undefined_share_out_of_contact_are_fine(paper, tmp_path):
    """What a simulator naturally writes: nan after its run ends, and a sliding share of nan where no spring is in
    contact (the package's own output has both) validates (at the spring model's tolerance: spring_tolerance)."""
    run = discrete_run(paper)
    sliding = run["sliding_fraction"].values
    assert np.isnan(sliding[0]) and np.isnan(run["normal_force"].values[-1])
    report = me.validate(run, paper, "A", ALPHA, tolerance=spring_tolerance(paper))
    assert report.attrs["verdict"] == "pass"
    inside = run.copy(deep=True)
    inside["sliding_fraction"].values[500] = np.nan  # in contact: refused
    with pytest.raises(ValueError, match="'sliding_fraction' holds nan at data row 501"):
        me.validate(inside, paper, "A", ALPHA)
