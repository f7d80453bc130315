"""Hostile use of ``mdr-events`` and of the file-writing API: every bad argument gives one line on stderr and
exit status 2 (a failed computation 3), before anything is computed where it can be, and nothing is written half.

The cases call :func:`mdr_events.app.cli.main` in-process (the code the console script runs, without paying the
package's imports again: some 1–1.5 s of CPU a fresh interpreter). What only a real process shows runs the installed
console script in a subprocess: its one-line usage error (``--bogus``) and an uncaught exception's traceback and
status under ``--debug`` (:data:`CASES`, started at once in the module's fixture ``console``), and the signals while
writing. A failure inside the program (a solver that gives up, a slow disk) is injected by a ``sitecustomize.py`` on
``PYTHONPATH`` that patches the package before the console script runs (in-process: ``monkeypatch``).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import main
from mdr_events.app.result_files import write_simulation
from mdr_events.app.study import StudyError, load_study, run_study
from mdr_events.io.files import TEMPORARY_MARKER, is_temporary_name

EXE = Path(sys.executable).parent / "mdr-events"
#: Root ignores permissions: a read-only directory is writable for it.
AS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0

#: Injected failures: Python run by ``sitecustomize.py`` before the console script.
SOLVER_GIVES_UP = """
import mdr_events.models.methods as methods
def run_continuum(*args, **kwargs):
    raise RuntimeError("the continuum method made no progress at t = 1.5 s after 8 restarts\\n"
                       "radius 1e-4 m; caps: stick, stick; last event: slip_onset")
methods.run_continuum = run_continuum
"""
#: A slow disk: the first netCDF file is written half, then the writer waits (to be killed).
SLOW_DISK = """
import time
import mdr_events.io.netcdf3
def write_netcdf3(dataset, path):
    with open(path, "wb") as handle:
        handle.write(b"CDF\\x02 half a file")
    time.sleep(60)
mdr_events.io.netcdf3.write_netcdf3 = write_netcdf3
"""

STUDY = """
[phase_diagram]
scenarios = ["A"]

[output]
directory = {directory!r}
"""
STUDY_NAMED = STUDY + "name = {name!r}\n"


class Case(NamedTuple):
    argv: tuple[str, ...]
    inject: str | None = None


class Result(NamedTuple):
    returncode: int
    stdout: str
    stderr: str


def _environment(tmp: Path, name: str, inject: str | None) -> dict[str, str]:
    env = dict(os.environ)
    if inject is not None:
        folder = tmp / "inject" / name
        folder.mkdir(parents=True)
        (folder / "sitecustomize.py").write_text(textwrap.dedent(inject))
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(folder), env.get("PYTHONPATH")]))
    return env


def start(tmp: Path, name: str, argv, inject: str | None = None) -> subprocess.Popen:
    """``mdr-events *argv`` started in ``tmp``, with ``inject`` run first."""
    if not EXE.exists():
        pytest.skip("console script not installed (package not pip-installed)")
    return subprocess.Popen([str(EXE), *argv], cwd=tmp, env=_environment(tmp, name, inject), text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def temporaries(directory: Path) -> list[str]:
    return sorted(name for name in os.listdir(directory) if TEMPORARY_MARKER in name) if directory.exists() else []


def files(directory: Path) -> list[str]:
    return sorted(os.listdir(directory)) if directory.exists() else []


#: name -> the command through the console script (what only a real process shows); the files the cases need are
#: made by the fixture ``console``.
CASES = {
    # row 3: the solver gives up: with --debug, the interpreter's traceback and status
    "solver_gives_up_debug": Case(("--debug", "simulate", "--scenario", "A", "--method", "continuum", "--alpha",
                                   "20", "--out", "solver_out_debug"), SOLVER_GIVES_UP),
    # row 4: an unknown option: the console script's one-line usage error
    "bogus_option": Case(("--bogus",)),
}


@pytest.fixture(scope="module")
def console(tmp_path_factory) -> tuple[Path, dict[str, Result]]:
    """Every case of :data:`CASES` run at once in one directory: (the directory, name -> result)."""
    tmp = tmp_path_factory.mktemp("hostile")
    (tmp / "a_file").write_text("precious")
    (tmp / "a_directory").mkdir()
    (tmp / "study_into_file.toml").write_text(
        STUDY.format(directory="a_file") + "\n[simulation]\nscenario = 'A'\nalpha = [20]\n")
    (tmp / "study_escape.toml").write_text(STUDY_NAMED.format(directory="out", name="../escape/x"))
    (tmp / "binary.toml").write_bytes(b"\x89PNG\r\n\x1a\n\x00\xff\xfe binary")
    processes = {name: start(tmp, name, case.argv, case.inject) for name, case in CASES.items()}
    results = {}
    try:
        for name, process in processes.items():
            stdout, stderr = process.communicate(timeout=300)
            results[name] = Result(process.returncode, stdout, stderr)
    finally:
        for process in processes.values():
            if process.poll() is None:
                process.kill()
    return tmp, results


def run(capsys, *argv) -> Result:
    """``mdr-events *argv`` in-process."""
    status = main(list(argv))
    out, err = capsys.readouterr()
    return Result(status, out, err)


def assert_one_line(result: Result, status: int, *fragments: str) -> str:
    """One line on stderr, ``mdr-events: error: ...`` (no traceback, no usage block), and the exit status."""
    assert result.returncode == status, result.stderr
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("mdr-events: error: "), result.stderr
    for fragment in fragments:
        assert fragment in result.stderr
    return result.stderr


# --- row 1: output directories ---------------------------------------------------------------------------

def test_an_output_that_is_a_file_or_below_one_is_one_line_exit_2(console, monkeypatch, capsys):
    tmp, _ = console
    monkeypatch.chdir(tmp)
    assert_one_line(run(capsys, "phase-diagram", "--scenario", "A", "--out", "a_file"), 2, "--out='a_file'",
                    "it is a file", "allowed: a directory")
    assert_one_line(run(capsys, "simulate", "--scenario", "A", "--alpha", "20", "--out", "a_file/sub"), 2,
                    "--out='a_file/sub'", "it lies below", "a_file, a file")
    assert (tmp / "a_file").read_text() == "precious"


@pytest.mark.parametrize("argv, fragments", [
    (("simulate", "--scenario", "A", "--alpha", "20", "--dx", "4e-6", "--n-steps", "400", "--out", "a_file/sub"),
     ["--out='a_file/sub'", "a_file, a file", "allowed: a directory"]),
    (("phase-diagram", "--scenario", "B", "--out", "a_file/../x"), ["a_file, a file"]),
    (("reproduce", "--out", "a_file"), ["--out='a_file'", "it is a file"]),
    (("validate", "run.csv", "--scenario", "A", "--alpha", "20", "--out", "a_file"), ["--out='a_file'", "a file"]),
    (("phase-diagram", "--scenario", "A", "--out", "dangling"), ["--out='dangling'", "it is a broken symbolic link"]),
])
def test_every_command_checks_its_output_directory_first(tmp_path, monkeypatch, capsys, argv, fragments):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_file").write_text("precious")
    (tmp_path / "dangling").symlink_to(tmp_path / "nowhere")
    # one line on stderr also says that nothing was computed: reproduce prints its progress there
    assert_one_line(run(capsys, *argv), 2, *fragments)
    assert files(tmp_path) == ["a_file", "dangling"] and (tmp_path / "a_file").read_text() == "precious"


@pytest.mark.skipif(AS_ROOT, reason="root writes into read-only directories")
def test_a_read_only_output_directory_is_one_line_exit_2(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "read_only").mkdir(mode=0o555)
    (tmp_path / "locked").mkdir(mode=0o555)
    try:
        assert_one_line(run(capsys, "phase-diagram", "--scenario", "A", "--out", "read_only"), 2,
                        "--out='read_only'", "it is not writable", "allowed: a directory")
        assert files(tmp_path / "read_only") == []
        assert_one_line(run(capsys, "phase-diagram", "--scenario", "A", "--out", str(tmp_path / "locked" / "sub")),
                        2, "cannot be created", "locked is not writable")
    finally:
        (tmp_path / "locked").chmod(0o755)
        (tmp_path / "read_only").chmod(0o755)


def test_a_study_checks_its_output_directory_before_computing(console, monkeypatch, capsys):
    tmp, _ = console
    monkeypatch.chdir(tmp)
    # the one line is the error: no progress line ("simulation: ...") came before it
    assert_one_line(run(capsys, "run", "study_into_file.toml"), 2, "study_into_file.toml", "[output] directory=",
                    "a_file", "it is a file")


def test_a_directory_given_as_the_study_file_is_named(console, monkeypatch, capsys):
    tmp, _ = console
    monkeypatch.chdir(tmp)
    assert_one_line(run(capsys, "run", "a_directory"), 2, "a_directory is a directory", "allowed: a study file")


def test_run_study_checks_the_output_directory_before_computing(tmp_path, monkeypatch):
    (tmp_path / "taken").write_text("a file")
    study = tmp_path / "study.toml"
    study.write_text(STUDY.format(directory="taken/out"))
    monkeypatch.setattr("mdr_events.app.result_files.phase_diagram",
                        lambda *args, **kwargs: pytest.fail("computed before the output directory was checked"))
    with pytest.raises(StudyError, match=r"\[output\] directory=.*taken.* a file, not a directory"):
        run_study(load_study(study))


# --- row 2: output names ---------------------------------------------------------------------------------

def test_a_study_name_that_leaves_the_output_directory_is_refused(console, monkeypatch, capsys):
    tmp, _ = console
    monkeypatch.chdir(tmp)
    assert_one_line(run(capsys, "run", "study_escape.toml"), 2, "study_escape.toml", "[output] name='../escape/x'",
                    "allowed: a plain file-name stem")
    assert not (tmp / "escape").exists() and not (tmp / "out").exists()


@pytest.mark.parametrize("name", ["../escape/x", "/tmp/absolute", "sub/x", "a\\b", "..", ".", "", "x\ny",
                                  f"x{TEMPORARY_MARKER}1", "n" * 201])
def test_study_names_are_plain_file_name_stems(tmp_path, name):
    study = tmp_path / "study.toml"
    study.write_text(STUDY_NAMED.format(directory="out", name=name))
    with pytest.raises(StudyError, match=r"\[output\] name=.* is not allowed; allowed: a plain file-name stem"):
        load_study(study)


def test_a_plain_study_name_is_used(tmp_path):
    study = tmp_path / "study.toml"
    study.write_text(STUDY_NAMED.format(directory="out", name="my study-1.2"))
    written = run_study(load_study(study), progress=lambda message: None)
    assert sorted(outcome.path.name for outcome in written) == ["my study-1.2_phase_diagram_A.nc",
                                                                 "my study-1.2_phase_diagram_A.png"]


@pytest.mark.parametrize("stem", ["../x", "/tmp/x", ""])
def test_result_writers_refuse_stems_that_leave_the_directory(tmp_path, paper, stem):
    dataset = me.simulate(paper, "A", alpha=[20.0], dx=4e-6, n_steps=400)
    with pytest.raises(ValueError, match="stem=.* is not allowed; allowed: a plain file-name stem"):
        write_simulation(dataset, tmp_path / "out", stem)
    assert files(tmp_path) == []


# --- row 3: failures of the computation and of files -----------------------------------------------------

def test_a_solver_that_gives_up_is_one_line_exit_3(console, monkeypatch, capsys):
    tmp, _ = console
    monkeypatch.chdir(tmp)
    injected = {}
    exec(SOLVER_GIVES_UP.replace("methods.run_continuum = run_continuum", ""), injected)  # (sitecustomize.py's)
    monkeypatch.setattr("mdr_events.models.methods.run_continuum", injected["run_continuum"])
    line = assert_one_line(run(capsys, "simulate", "--scenario", "A", "--method", "continuum", "--alpha", "20", "--out",
                               "solver_out"), 3, "the computation failed", "RuntimeError",
                           "made no progress at t = 1.5 s", "last event: slip_onset", "--debug")
    assert "Traceback" not in line
    assert files(tmp / "solver_out") == []


def test_debug_shows_the_traceback(console):
    _, results = console
    result = results["solver_gives_up_debug"]
    assert result.returncode == 1  # Python's own status for an uncaught exception
    assert "Traceback (most recent call last)" in result.stderr
    assert "RuntimeError: the continuum method made no progress" in result.stderr


@pytest.mark.parametrize("error, status, fragments", [
    (MemoryError(), 3, ["the computation failed (MemoryError: no message)"]),
    (AttributeError("'NoneType' object has no attribute 'values'"), 3,
     ["internal error (AttributeError: 'NoneType' object has no attribute 'values')", "please report it", "--debug"]),
    (OSError(28, "No space left on device", "out/phase_diagram_A.nc"), 2,
     ["error: out/phase_diagram_A.nc: No space left on device"]),
    (PermissionError(13, "Permission denied", "run.csv"), 2, ["error: run.csv: Permission denied"]),
    (RuntimeError("solve_ivp failed on [0, 1]\nstep size too small"), 3,
     ["the computation failed (RuntimeError: solve_ivp failed on [0, 1] step size too small)"]),
])
def test_every_failure_is_one_line_with_its_status(tmp_path, monkeypatch, capsys, error, status, fragments):
    def fail(*args, **kwargs):
        raise error

    monkeypatch.setattr("mdr_events.app.result_files.phase_diagram", fail)
    assert_one_line(run(capsys, "phase-diagram", "--scenario", "A", "--out", str(tmp_path / "out")), status,
                    *fragments)
    assert files(tmp_path) == []
    with pytest.raises(type(error)):
        main(["--debug", "phase-diagram", "--scenario", "A", "--out", str(tmp_path / "out")])


def test_a_file_that_cannot_be_written_leaves_nothing(tmp_path, monkeypatch, capsys):
    def disk_full(dataset, path):
        with open(path, "wb") as handle:
            handle.write(b"CDF\x02 half")
        raise OSError(28, "No space left on device", path)

    monkeypatch.setattr("mdr_events.io.netcdf3.write_netcdf3", disk_full)  # (the netCDF writer of a result)
    line = assert_one_line(run(capsys, "phase-diagram", "--scenario", "A", "--out", str(tmp_path)), 2,
                           f"error: {tmp_path / 'phase_diagram_A.nc'}: No space left on device")
    assert TEMPORARY_MARKER not in line
    assert files(tmp_path) == []  # the temporary file is gone, and no .png without its .nc


# --- row 4: unknown options --------------------------------------------------------------------------------

def test_an_unknown_option_is_a_one_line_usage_error(console):
    _, results = console
    line = assert_one_line(results["bogus_option"], 2, "unrecognized argument(s) --bogus",
                           "allowed: the options listed by mdr-events --help")
    assert "usage:" not in line and "Traceback" not in line


@pytest.mark.parametrize("argv, fragment", [
    (("phase-diagram", "--bogus", "--scenario", "A", "--out", "never"),
     "unrecognized argument(s) --bogus; allowed: the options listed by mdr-events phase-diagram --help"),
    (("--bogus", "derive"), "unrecognized argument(s) --bogus; allowed: the options listed by mdr-events derive"),
    ((), "a command is required; allowed: derive, phase-diagram, simulate, validate, fit, sweep, run, reproduce"),
])
def test_unknown_options_and_a_missing_command_name_what_is_allowed(tmp_path, monkeypatch, capsys, argv, fragment):
    monkeypatch.chdir(tmp_path)
    assert_one_line(run(capsys, *argv), 2, fragment)
    assert files(tmp_path) == []


# --- row 5: study files that are not TOML text --------------------------------------------------------------

def test_a_binary_study_file_is_named(console, monkeypatch, capsys):
    tmp, _ = console
    monkeypatch.chdir(tmp)
    assert_one_line(run(capsys, "run", "binary.toml"), 2, "binary.toml: not UTF-8 text", "allowed: a study file")


@pytest.mark.parametrize("path", [None, 3, b"study.toml", ["study.toml"]])
def test_load_study_names_a_path_of_the_wrong_type(path):
    with pytest.raises(TypeError) as error:
        load_study(path)
    assert str(error.value) == (f"path={path!r} ({type(path).__name__}) is not allowed; allowed: a str or "
                                "os.PathLike naming a study file (.toml)")


@pytest.mark.parametrize("content, fragment", [(b"\xff\xfe[output]", "not UTF-8 text"),
                                               (b"[output\ndirectory = 1", "not valid TOML")])
def test_load_study_names_a_file_that_is_not_toml_text(tmp_path, content, fragment):
    path = tmp_path / "study.toml"
    path.write_bytes(content)
    with pytest.raises(StudyError, match=fragment) as error:
        load_study(path)
    assert str(path) in str(error.value) and "\n" not in str(error.value)


def test_a_candidate_that_is_no_text_or_a_directory_is_named(tmp_path, paper):
    (tmp_path / "binary.csv").write_bytes(b"time,normal_force\n\xff\xfe\x00")
    with pytest.raises(ValueError, match="binary.csv: not UTF-8 text"):
        me.validate(tmp_path / "binary.csv", paper, "A", 20.0)
    with pytest.raises(ValueError, match="is a directory"):
        me.validate(tmp_path, paper, "A", 20.0)


# --- row 6: write_netcdf and open_result -----------------------------------------------------------------

def test_write_netcdf_names_what_is_not_a_dataset(tmp_path):
    with pytest.raises(TypeError, match=r"^dataset='hello' \(str\) is not allowed; allowed: an xarray.Dataset$"):
        me.write_netcdf("hello", tmp_path / "x.nc")
    with pytest.raises(TypeError) as error:
        me.write_netcdf(list(range(1000)), tmp_path / "x.nc")
    assert len(str(error.value)) < 200 and "..." in str(error.value)  # the value is shown cut
    with pytest.raises(TypeError, match="path=None"):
        me.write_netcdf(me.phase_diagram(me.Parameters.paper(), scenario="A", alpha=[10.0]), None)
    assert files(tmp_path) == []


def test_open_result_names_the_file(tmp_path):
    (tmp_path / "notes.nc").write_text("not netCDF\nat all")
    for path, fragment in [(tmp_path / "absent.nc", "absent.nc': no such file"),
                           (tmp_path / "notes.nc", "notes.nc' is not a readable netCDF file"),
                           (tmp_path, "is a directory")]:
        with pytest.raises(ValueError, match=fragment) as error:
            me.open_result(path)
        assert "\n" not in str(error.value)
    with pytest.raises(TypeError, match="path=None"):
        me.open_result(None)


# --- row 7: nothing written half -------------------------------------------------------------------------

def test_duplicate_angles_are_refused_by_simulate(paper):
    with pytest.raises(ValueError, match=r"alpha=\[20, 20\] repeats 20.0"):
        me.simulate(paper, "A", alpha=[20, 20])


@pytest.fixture(scope="module")
def continuum_run():
    return me.simulate(me.Parameters.paper(), "A", alpha=[20.0], method="continuum", samples=51)


def test_a_simulation_with_repeated_cases_writes_nothing(tmp_path, continuum_run):
    twice = continuum_run.isel(alpha=[0, 0])
    with pytest.raises(ValueError, match=r"dataset alpha=\[20.0, 20.0\] repeats 20.0; allowed: .*distinct"):
        write_simulation(twice, tmp_path / "out", "twice")
    assert files(tmp_path) == []


def test_a_figure_that_fails_leaves_no_netcdf(tmp_path, continuum_run):
    def broken(dataset, overlay=None):
        raise ValueError("x and y must have same first dimension")

    with pytest.raises(ValueError, match="same first dimension"):
        write_simulation(continuum_run, tmp_path, "sim", plot=broken)
    assert files(tmp_path) == []
    # and where the files exist, a failing figure leaves them as they were
    written = write_simulation(continuum_run, tmp_path, "sim")
    before = {outcome.path.name: outcome.path.read_bytes() for outcome in written}
    with pytest.raises(ValueError):
        write_simulation(continuum_run.assign_attrs(note="changed"), tmp_path, "sim", plot=broken)
    assert {name: (tmp_path / name).read_bytes() for name in before} == before
    assert files(tmp_path) == sorted(before)


# --- row 8: temporary files --------------------------------------------------------------------------------

def _wait_for_temporary(process: subprocess.Popen, directory: Path, timeout: float = 60.0) -> list[str]:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        found = temporaries(directory)
        if found:
            return found
        if process.poll() is not None:
            pytest.fail(f"mdr-events ended ({process.returncode}) before writing: {process.stderr.read()}")
        time.sleep(0.05)
    process.kill()
    pytest.fail("no temporary file appeared")


def test_sigterm_while_writing_removes_the_temporary_file(tmp_path):
    out = tmp_path / "out"
    process = start(tmp_path, "slow", ("phase-diagram", "--scenario", "A", "--out", str(out)), SLOW_DISK)
    found = _wait_for_temporary(process, out)
    assert all(is_temporary_name(name) for name in found)
    process.send_signal(signal.SIGTERM)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 128 + signal.SIGTERM
    assert stderr == "mdr-events: terminated (SIGTERM); no file was left half-written\n"
    assert files(out) == []


def test_ctrl_c_while_writing_removes_the_temporary_file(tmp_path, monkeypatch, capsys):
    def interrupted(dataset, path):
        with open(path, "wb") as handle:
            handle.write(b"CDF\x02 half")
        raise KeyboardInterrupt

    monkeypatch.setattr("mdr_events.io.netcdf3.write_netcdf3", interrupted)  # (the netCDF writer of a result)
    result = run(capsys, "phase-diagram", "--scenario", "A", "--out", str(tmp_path))
    assert result.returncode == 128 + signal.SIGINT
    assert result.stderr == "mdr-events: interrupted (Ctrl-C); no file was left half-written\n"
    assert files(tmp_path) == []


@pytest.mark.slow
def test_a_temporary_file_left_by_sigkill_is_removed_by_the_next_run(tmp_path):
    out = tmp_path / "out"
    process = start(tmp_path, "slow", ("phase-diagram", "--scenario", "A", "--out", str(out)), SLOW_DISK)
    left = _wait_for_temporary(process, out)
    process.kill()  # SIGKILL: no clean-up can run
    process.communicate(timeout=60)
    assert temporaries(out) == left
    again = start(tmp_path, "again", ("phase-diagram", "--scenario", "A", "--out", str(out)))
    _, stderr = again.communicate(timeout=300)
    assert again.returncode == 0, stderr
    assert files(out) == ["phase_diagram_A.nc", "phase_diagram_A.png"]


def test_an_unrelated_hidden_file_is_left_alone(tmp_path, paper):
    keep = [".notes", ".x.mdr-tmp", f".{TEMPORARY_MARKER}"]
    for name in keep:
        (tmp_path / name).write_text("mine")
        os.utime(tmp_path / name, (0, 0))
    me.write_netcdf(me.phase_diagram(paper, scenario="A", alpha=np.array([10.0])), tmp_path / "x.nc")
    assert files(tmp_path) == sorted(keep + ["x.nc"])
