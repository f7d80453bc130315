"""Files: every result reads back identical, writes are atomic, foreign or damaged files are named."""

import os
import subprocess
import sys

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io import datasets
from mdr_events.io.files import atomic_write, write_netcdf


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
    }


@pytest.fixture(scope="module")
def paper_module():
    return me.Parameters.paper()


@pytest.mark.parametrize("name", ["phase_A", "phase_B", "discrete", "continuum", "custom", "custom_cases",
                                  "cross_check"])
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
    assert {dataset.attrs["content"] for dataset in results.values()} == set(datasets.registered_contents())
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

    def interrupted(self, path, *args, **kwargs):
        with open(path, "wb") as handle:
            handle.write(b"CDF\x02 truncated")
        raise OSError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", interrupted)
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
