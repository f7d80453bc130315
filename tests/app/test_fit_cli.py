"""``mdr-events fit`` and the ``[fit]`` table of study files: parameters from a measurement in a CSV file.

The measurement is synthetic: the continuum of scenario A at 20° with 1 % noise, written in ms, mN and mm²
under a tribometer's column names, as an instrument would.
"""

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.fit import synthetic_measurement
from mdr_events.analysis.validate import resolve_path
from mdr_events.app.cli import main
from mdr_events.app.fit_files import fit_markdown
from mdr_events.app.study import StudyError, load_study, run_study

from test_validate_cli import assert_one_error_line, write_csv

ALPHA = 20.0
NAMES = "time=t_ms,normal_force=Fn_mN,tangential_force=Fx_mN,contact_area=A_mm2"
UNITS = "time=ms,normal_force=mN,tangential_force=mN,contact_area=mm2"


@pytest.fixture(scope="module")
def measured(paper, tmp_path_factory):
    """``measured.csv`` (F_N, F_x, A) and ``normal_only.csv`` (F_N alone) in a directory of their own."""
    folder = tmp_path_factory.mktemp("measured")
    times = np.linspace(0.0, 1.02 * resolve_path(paper, "A", ALPHA).duration, 801)
    data = synthetic_measurement(paper, "A", ALPHA, times=times, relative_noise=0.01, seed=4)
    write_csv(folder / "measured.csv", {"t_ms": times * 1e3, "Fn_mN": data["normal_force"].values * 1e3,
                                        "Fx_mN": data["tangential_force"].values * 1e3,
                                        "A_mm2": data["contact_area"].values * 1e6})
    write_csv(folder / "normal_only.csv", {"time": times, "normal_force": data["normal_force"].values})
    return folder


def fit_cli(capsys, *argv):
    status = main(["fit", *map(str, argv)])
    out, err = capsys.readouterr()
    return status, out, err


def test_the_command_fits_and_writes_its_files(paper, measured, tmp_path, command):
    """The fit on the command line, in-process (:func:`mdr_events.app.cli.main`, the code the console script runs:
    the console script itself is run by tests/app/test_validate_cli.py and tests/app/test_console_start_up.py)."""
    out = tmp_path / "out"
    result = command("fit", str(measured / "measured.csv"), "--scenario", "A", "--alpha", "20", "--free", "tau0",
                     "dgamma1", "--tau0", "30e3", "--dgamma1", "0.2", "--names", NAMES, "--units", UNITS,
                     "--time-origin", "path_start", "--out", str(out))
    assert result.returncode == 0, result.stderr
    assert "every free parameter is determined" in result.stdout
    assert sorted(p.name for p in out.iterdir()) == ["measured_fit.md", "measured_fit.nc", "measured_fit.png"]
    fit = me.open_result(out / "measured_fit.nc")
    for name in ("tau0", "dgamma1"):
        row = fit.sel(parameter=name)
        assert float(row["lower_95"]) <= getattr(paper, name) <= float(row["upper_95"]), name
    assert float(fit.sel(parameter="tau0")["start"]) == 30e3
    assert fit.attrs["path_description"] == "scenario A, α = 20°"
    summary = (out / "measured_fit.md").read_text()
    assert "| tau0 | 30000 Pa |" in summary and "## Correlations" in summary and "measured_fit.png" in summary
    assert (out / "measured_fit.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_tau0_from_the_normal_force_alone_exits_1(capsys, measured, tmp_path, without_drawing):
    status, out, err = fit_cli(capsys, measured / "normal_only.csv", "--scenario", "A", "--alpha", ALPHA,
                               "--free", "tau0", "dgamma1", "--time-origin", "path_start", "--out", tmp_path / "out")
    assert status == 1, err
    assert "tau0 = " in out and "(not identifiable)" in out
    summary = (tmp_path / "out" / "normal_only_fit.md").read_text()
    assert "**not identifiable**" in summary and "tau0 acts only on F_x" in summary


@pytest.mark.parametrize("argv, fragment", [
    (["--free", "mu"], "free: 'mu' is not allowed"),
    (["--free", "tau0", "--bounds", "tau0=1e3"], "--bounds 'tau0=1e3' is not allowed"),
    (["--free", "tau0", "--bounds", "tau0=5e4:6e4"], "excludes the start"),
    (["--free", "tau0", "--noise", "normal_force=abc"], "--noise normal_force='abc' is not allowed"),
    (["--free", "tau0", "--noise", "pressure=1"], "'pressure' is not allowed"),
    (["--free", "tau0", "--alpha", "20", "--path", "missing.toml"], "not allowed with --path"),
])
def test_bad_input_is_one_line_exit_2_and_writes_nothing(capsys, measured, tmp_path, argv, fragment):
    arguments = [measured / "normal_only.csv", "--out", tmp_path / "out", *argv]
    if "--path" not in argv:
        arguments += ["--scenario", "A", "--alpha", ALPHA]
    status, out, err = fit_cli(capsys, *arguments)
    assert status == 2
    assert_one_error_line(err, fragment)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_a_study_fits_its_measurement(capsys, paper, measured, tmp_path, without_drawing):
    study = tmp_path / "study.toml"
    study.write_text(f"""
[parameters]
preset = "paper-R30"
tau0 = 30e3
[fit]
data = "{measured / 'measured.csv'}"
free = ["tau0"]
names = {{ time = "t_ms", normal_force = "Fn_mN", tangential_force = "Fx_mN", contact_area = "A_mm2" }}
units = {{ time = "ms", normal_force = "mN", tangential_force = "mN", contact_area = "mm2" }}
time_origin = "path_start"
bounds = {{ tau0 = [1e3, 1e6] }}
noise = {{ normal_force = 5e-3 }}
scenario = "A"
alpha = 20
[output]
directory = "out"
""")
    outcomes = run_study(load_study(study), progress=lambda message: None)
    assert sorted(outcome.path.name for outcome in outcomes) == ["study_fit_measured.md", "study_fit_measured.nc",
                                                                 "study_fit_measured.png"]
    assert list(outcomes.verdicts.values()) == ["pass"]
    fit = me.open_result(tmp_path / "out" / "study_fit_measured.nc")
    assert float(fit.sel(quantity="normal_force")["noise"]) == 5e-3 and int(fit["noise_given"].sum()) == 1
    tau0 = fit.sel(parameter="tau0")
    assert float(tau0["lower_95"]) <= paper.tau0 <= float(tau0["upper_95"])
    assert fit_markdown(fit).startswith("# Fit of the model to `measured.csv`")


def test_a_missing_measurement_in_a_study_writes_nothing(tmp_path):
    study = tmp_path / "study.toml"
    study.write_text('[fit]\ndata = "missing.csv"\nfree = ["tau0"]\nscenario = "A"\nalpha = 20\n'
                     '[output]\ndirectory = "out"\n')
    with pytest.raises(StudyError, match="no such file"):
        run_study(load_study(study), progress=lambda message: None)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())
