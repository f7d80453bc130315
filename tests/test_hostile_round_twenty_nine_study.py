"""Hostile round twenty-nine (issue 32, class 6: all files of one run are replaced together or not at all): a study
file is one run. ``run_study`` had written each job's files together but one job at a time, so that SIGTERM between
the ``[simulation]`` job and the ``[phase_diagram]`` job left the new simulation's three files beside the previous
run's phase diagrams. Every job is now computed and planned first and the study's files committed in one
``atomic_write_all`` at the end."""

from __future__ import annotations

from pathlib import Path

import pytest

from mdr_events.app import result_files
from mdr_events.app.result_files import FileStatus
from mdr_events.app.study import load_study, run_study

#: The study of both runs: a simulation (the first job) and two phase diagrams (the second and third); ``TAU0``
#: differs between the previous run and the new one, so that every file of the new run differs from the old.
STUDY = """
[parameters]
preset = "paper-R100"
tau0 = {tau0}

[simulation]
scenario = "B"
alpha = [20, 60]
method = "continuum"
samples = 301

[phase_diagram]
scenarios = ["A", "B"]

[output]
directory = "out"
name = "demo"
"""
#: The files the study writes: the simulation's three, each phase diagram's two.
STUDY_FILES = {"demo_simulation.nc", "demo_simulation.png", "demo_simulation_events.csv", "demo_phase_diagram_A.nc",
               "demo_phase_diagram_A.png", "demo_phase_diagram_B.nc", "demo_phase_diagram_B.png"}
PREVIOUS_TAU0, NEW_TAU0 = 30e3, 42e3


def _contents(directory: Path) -> dict[str, bytes]:
    """Every file in ``directory`` (hidden temporaries too) -> its bytes."""
    return {path.name: path.read_bytes() for path in sorted(directory.iterdir())}


def _run(tmp_path: Path, tau0: float):
    study_file = tmp_path / "study.toml"
    study_file.write_text(STUDY.format(tau0=tau0))
    return run_study(load_study(study_file), progress=lambda message: None)


@pytest.fixture
def previous_run(tmp_path: Path) -> dict[str, bytes]:
    """The output directory as the previous run left it."""
    _run(tmp_path, PREVIOUS_TAU0)
    before = _contents(tmp_path / "out")
    assert set(before) == STUDY_FILES
    return before


@pytest.mark.parametrize("failing_scenario", ["A", "B"])  # the second job, the last one
@pytest.mark.parametrize("failure", [KeyboardInterrupt, RuntimeError])  # Ctrl-C / SIGTERM's handler, a bug
def test_a_study_interrupted_in_a_later_job_leaves_every_previous_file(tmp_path, monkeypatch, previous_run,
                                                                      failing_scenario, failure):
    computed = result_files.phase_diagram

    def interrupted(*args, scenario, **options):
        if scenario == failing_scenario:
            raise failure(f"interrupted while computing the phase diagram of scenario {scenario}")
        return computed(*args, scenario=scenario, **options)

    monkeypatch.setattr(result_files, "phase_diagram", interrupted)  # (what the [phase_diagram] job computes with)
    with pytest.raises(failure):
        _run(tmp_path, NEW_TAU0)
    assert _contents(tmp_path / "out") == previous_run  # every old file as it was, no new one, no temporary


def test_a_study_that_runs_through_replaces_every_file(tmp_path, previous_run):
    outcomes = _run(tmp_path, NEW_TAU0)
    after = _contents(tmp_path / "out")
    assert set(after) == STUDY_FILES
    assert {outcome.path.name for outcome in outcomes} == STUDY_FILES
    assert all(outcome.status is FileStatus.WRITTEN for outcome in outcomes)
    assert all(after[name] != previous_run[name] for name in STUDY_FILES)  # each replaced by the new run's
