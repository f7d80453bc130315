"""``mdr-events sweep study.toml`` and the ``[sweep]`` table: files, resume, engine options, bad tables."""

import importlib.util
import os
import subprocess

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.app.cli import main
from mdr_events.app.study import load_study, run_study

from test_validate_cli import assert_one_error_line, console_script

# looked up, not imported (dask.distributed costs a worker about a second at collection; a run imports it where it
# starts a cluster)
if importlib.util.find_spec("distributed") is None:
    pytest.skip("the extra 'scale' is not installed (make installs it)", allow_module_level=True)

STUDY = """
[parameters]
preset = "paper-R30"
[sweep]
grid = { tau0 = [30e3, 42e3], alpha = [10, 20, 30] }
scenario = "A"
chunk_size = 2
{extra}
[output]
directory = "out"
"""


def write_study(folder, extra=""):
    path = folder / "study.toml"
    path.write_text(STUDY.replace("{extra}", extra))
    return path


@pytest.mark.slow  # a local dask cluster started by the console script (~15 s); a cluster's numbers are the serial
# ones in tests/analysis/test_sweep.py, the CLI's sweep serially below
def test_console_script_sweeps_on_a_local_cluster_and_writes_store_and_netcdf(paper, tmp_path):
    study = write_study(tmp_path)
    result = subprocess.run([*console_script(), "sweep", str(study), "--workers", str(min(2, os.cpu_count() or 1))], capture_output=True, text=True,
                            cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "sweep: 6/6 runs" in result.stderr and "sweep: 6 runs, 0 failed" in result.stderr
    swept = me.open_result(tmp_path / "out" / "study_sweep.nc")
    assert dict(swept.sizes) == {"tau0": 2, "alpha": 3} and swept.attrs["parameters_preset"] == "paper-R30"
    serial = me.sweep({"tau0": [30e3, 42e3], "alpha": [10.0, 20.0, 30.0]}, "A", base=paper, scheduler="serial")
    for name in ("tangential_force_max", "slip_onset_in_depth", "pull_off_force"):
        np.testing.assert_array_equal(swept[name].values, serial[name].values)
    store = xr.open_zarr(tmp_path / "out" / "study_sweep.zarr", zarr_format=2)
    assert int(store["done"].sum()) == 6


def test_resume_runs_nothing_again_for_a_finished_store(capsys, tmp_path):
    study = write_study(tmp_path)
    assert main(["sweep", str(study), "--scheduler", "serial"]) == 0
    first = me.open_result(tmp_path / "out" / "study_sweep.nc")
    capsys.readouterr()
    assert main(["sweep", str(study), "--scheduler", "serial"]) == 2  # an existing store is not replaced silently
    assert_one_error_line(capsys.readouterr().err, "holds an earlier sweep; allowed: --resume to continue it")
    assert main(["sweep", str(study), "--scheduler", "serial", "--resume"]) == 0
    out, err = capsys.readouterr()
    assert "/6 runs" not in err and "sweep: 6 runs, 0 failed" in err
    xr.testing.assert_identical(me.open_result(tmp_path / "out" / "study_sweep.nc"), first)
    assert main(["sweep", str(study), "--scheduler", "serial", "--restart"]) == 0
    assert "sweep: 6/6 runs" in capsys.readouterr().err  # every run again


def test_a_study_run_also_sweeps(tmp_path):
    study = write_study(tmp_path, 'scheduler = "serial"\nquantities = ["critical_angle_A"]')
    outcomes = run_study(load_study(study), progress=lambda message: None)
    assert sorted(o.path.name for o in outcomes) == ["study_sweep.nc", "study_sweep.zarr"]
    swept = me.open_result(tmp_path / "out" / "study_sweep.nc")
    assert set(swept.data_vars) == {"critical_angle_A", "failed", "error"}


@pytest.mark.parametrize("argv, fragment", [
    (["--workers", "0"], "--workers 0 is not allowed"),
    (["--scheduler", "bogus"], "scheduler='bogus' is not allowed"),
])
def test_bad_engine_options_are_one_line_exit_2(capsys, tmp_path, argv, fragment):
    study = write_study(tmp_path)
    assert main(["sweep", str(study), *argv]) == 2
    assert_one_error_line(capsys.readouterr().err, fragment)
    assert not (tmp_path / "out" / "study_sweep.nc").exists()


def test_a_bad_grid_value_is_named_before_anything_runs(capsys, tmp_path):
    study = tmp_path / "study.toml"
    study.write_text('[sweep]\ngrid = { nu = [0.3, 0.7] }\nalpha = 20\nscheduler = "serial"\n'
                     '[output]\ndirectory = "out"\n')
    assert main(["sweep", str(study)]) == 2
    assert_one_error_line(capsys.readouterr().err, "[sweep] grid: Elastomer.nu=0.7 is not allowed")
    assert not (tmp_path / "out" / "study_sweep.zarr").exists()


def test_a_limits_table_reaches_every_run_of_a_study(capsys, tmp_path):
    """[limits] as --limit: a discrete sweep past its steps is recorded as failed with the estimate; a simulation
    past it is refused before it starts (exit 2). (A bad value: tests/app/test_study.py.)"""
    study = write_study(tmp_path, 'scheduler = "serial"\nmethod = "discrete"\ndx = 4e-6\nn_steps = 5000\n'
                                  'quantities = ["tangential_force_max"]\n[limits]\nsteps = 1000\nmemory = "1GiB"')
    assert load_study(study).limits == me.Limits(steps=1000, memory=2**30)
    assert main(["sweep", str(study)]) == 0
    swept = me.open_result(tmp_path / "out" / "study_sweep.nc")
    assert swept["failed"].values.all() and "steps" in str(swept["error"].values.ravel()[0])
    simulation = tmp_path / "simulation.toml"
    simulation.write_text('[simulation]\nscenario = "A"\nalpha = [20]\nn_steps = 5000\n[limits]\nsteps = 1000\n'
                          '[output]\ndirectory = "out2"\n')
    capsys.readouterr()
    assert main(["run", str(simulation)]) == 2
    error = capsys.readouterr().err.splitlines()[-1]  # after the progress line, the one error line
    assert error.startswith("mdr-events: error:") and "needs 5e+03 discrete time steps" in error
    assert not (tmp_path / "out2").exists() or not any((tmp_path / "out2").iterdir())


@pytest.mark.slow
def test_ctrl_c_on_a_local_cluster_sweep_prints_one_line(tmp_path):
    """A Ctrl-C at the terminal reaches every process of the group: the workers (which ignore it) printed a
    traceback each; now the one line of the command alone, and the cluster closed."""
    import signal
    import time

    study = tmp_path / "study.toml"
    study.write_text(STUDY.replace("grid = { tau0 = [30e3, 42e3], alpha = [10, 20, 30] }",
                                   "grid = { tau0 = [20e3, 30e3, 42e3, 55e3, 70e3, 85e3, 100e3, 120e3], "
                                   "alpha = [5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70] }")
                     .replace("chunk_size = 2", "chunk_size = 1").replace("{extra}", ""))
    process = subprocess.Popen([*console_script(), "sweep", str(study), "--workers", "2"], cwd=tmp_path,
                               stderr=subprocess.PIPE, text=True, start_new_session=True)
    first = process.stderr.readline()  # the first chunk's progress: the workers are up and running (of 112 runs)
    assert first.startswith("sweep: "), first
    time.sleep(0.2)
    os.killpg(process.pid, signal.SIGINT)  # as the terminal sends it: to the whole group
    _, rest = process.communicate(timeout=120)
    assert process.returncode == 128 + signal.SIGINT, rest
    assert "Traceback" not in rest and "KeyboardInterrupt" not in rest, rest
    assert rest.strip().splitlines()[-1].startswith("mdr-events: interrupted (Ctrl-C)"), rest
