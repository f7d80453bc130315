"""Writing netCDF-3 without asking dask for its scheduler (:mod:`mdr_events.io.netcdf3`, issue 28): the file is
``to_netcdf``'s byte for byte, what netCDF cannot hold is refused in its words, and a write loads no
``dask.distributed`` (checked in a fresh interpreter: this one may have loaded it already)."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io.netcdf3 import NETCDF3_FORMAT, write_netcdf3


def to_netcdf_bytes(dataset: xr.Dataset, path) -> bytes:
    dataset.to_netcdf(path, engine="scipy", format=NETCDF3_FORMAT)
    return path.read_bytes()


@pytest.fixture(scope="module")
def results(paper):
    return {"continuum": me.simulate(paper, "A", [20.0, 30.0], method="continuum"),
            "custom": me.simulate(paper, me.Path([(0.0, 0.0), (1e-4, 2e-4), (1e-4, -1e-4)], 1e-6),
                                  method="continuum"),
            "phase": me.phase_diagram(paper, [10.0, 20.0])}


@pytest.mark.parametrize("kind", ["continuum", "custom", "phase"])
def test_the_file_is_to_netcdfs_byte_for_byte(tmp_path, results, kind):
    dataset = results[kind]
    write_netcdf3(dataset, tmp_path / "direct.nc")
    assert (tmp_path / "direct.nc").read_bytes() == to_netcdf_bytes(dataset, tmp_path / "xarray.nc")
    with xr.open_dataset(tmp_path / "direct.nc", engine="scipy") as back:  # read back and written again
        back = back.load()
    write_netcdf3(back, tmp_path / "again.nc")
    assert (tmp_path / "again.nc").read_bytes() == to_netcdf_bytes(back, tmp_path / "xarray_again.nc")


def test_an_unlimited_dimension_of_the_encoding_is_kept(tmp_path):
    dataset = xr.Dataset({"v": ("t", np.arange(3.0))})
    dataset.encoding["unlimited_dims"] = {"t"}
    write_netcdf3(dataset, tmp_path / "direct.nc")
    assert (tmp_path / "direct.nc").read_bytes() == to_netcdf_bytes(dataset, tmp_path / "xarray.nc")


@pytest.mark.parametrize("change, error, words", [
    (lambda ds: ds.assign_attrs(weird={"a": 1}), TypeError, "Invalid value for attr 'weird': {'a': 1}"),
    (lambda ds: ds.assign_attrs({"": 1}), ValueError, "Invalid name '' for attr"),
    (lambda ds: ds.assign({"": ("t", np.zeros(2))}), ValueError, "Invalid name '' for a variable"),
])
def test_what_netcdf_cannot_hold_is_refused_as_to_netcdf_refuses_it(tmp_path, change, error, words):
    dataset = change(xr.Dataset({"v": ("t", np.zeros(2))}))
    with pytest.raises(error, match="Invalid"):  # (xarray's own refusal, in its words)
        dataset.to_netcdf(tmp_path / "xarray.nc", engine="scipy", format=NETCDF3_FORMAT)
    with pytest.raises(error) as refused:
        write_netcdf3(dataset, tmp_path / "direct.nc")
    assert words in str(refused.value)


def test_chunked_arrays_are_computed_by_to_netcdf(tmp_path):
    pytest.importorskip("dask")
    dataset = xr.Dataset({"v": ("t", np.arange(6.0))}).chunk({"t": 2})
    write_netcdf3(dataset, tmp_path / "direct.nc")
    assert (tmp_path / "direct.nc").read_bytes() == to_netcdf_bytes(dataset.load(), tmp_path / "xarray.nc")


def test_a_write_loads_no_dask_distributed(tmp_path):
    code = textwrap.dedent(f"""
        import sys
        import numpy as np, xarray as xr
        from mdr_events.io.files import write_netcdf
        write_netcdf(xr.Dataset({{"v": ("t", np.arange(3.0), {{"units": "1", "long_name": "v"}})}}),
                     {str(tmp_path / "out.nc")!r})
        print("distributed" in sys.modules)
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split()[-1] == "False"
