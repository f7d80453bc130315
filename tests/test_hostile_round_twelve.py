"""The twelfth hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io.files import open_result, write_netcdf

PAPER = me.Parameters.paper()


@pytest.fixture(scope="module")
def simulation():
    return me.simulate(PAPER, "A", [10.0, 20.0], method="continuum", samples=51)


# --- M1: write_netcdf wrote what open_result then refused (a case selected away, `ds.isel(alpha=0)`, read as "wrong
# dimensions"; a dropped or transposed variable; CF attributes the reader decodes: _FillValue, scale_factor, a time's
# units, coordinates; a one-element list or bytes attribute; a zero-length record dimension, read by SciPy as a
# SyntaxError). Every dataset the writer accepts now reads back identical, and the reader takes one case selected -----

@pytest.mark.parametrize("select", [{"alpha": 0}, {"time": 0}, {"alpha": [0]}, {"time": slice(0, 5)}])
def test_a_selection_written_reads_back_identical(simulation, select, tmp_path):
    dataset = simulation.isel(select)
    again = open_result(write_netcdf(dataset, tmp_path / "one.nc"))
    xr.testing.assert_identical(again, dataset)


def _labelled(values):
    return {"units": "1", "long_name": "extra"} | values


@pytest.mark.parametrize("change, words", [
    (lambda ds: ds.drop_vars("normal_force"), "lacks the variable(s) ['normal_force']"),
    (lambda ds: ds.transpose("time", "alpha", "event"), "has variable(s) with the wrong dimensions"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2))), "without units or long_name: ['extra']"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2), _labelled({"_FillValue": 1.0}))),
     "attribute '_FillValue'=1.0 reads back as absent"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2), _labelled({"scale_factor": 2.0}))), "'scale_factor'"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2), _labelled({"units": "days since 2000-01-01"}))),
     "'units'='days since 2000-01-01' reads back as absent"),
    (lambda ds: ds.assign_attrs(note=[1.5]), "attribute 'note'=[1.5] reads back as"),
    (lambda ds: ds.assign_attrs(note=b"ab"), "attribute 'note'=b'ab' reads back as 'ab'"),
    (lambda ds: ds.assign_attrs(coordinates="alpha"), "attribute 'coordinates'='alpha' reads back as absent"),
    (lambda ds: ds.isel(alpha=slice(0, 0), event=slice(0, 0), time=slice(0, 0)), "it is not read (TypeError"),
])
def test_what_would_not_read_back_is_refused_before_it_is_placed(simulation, change, words, tmp_path):
    with pytest.raises(ValueError, match=re.escape(words)) as caught:
        write_netcdf(change(simulation), tmp_path / "x.nc")
    assert "allowed" in str(caught.value) and "\n" not in str(caught.value)
    assert list(tmp_path.iterdir()) == []  # (the temporary removed, nothing placed)


def test_a_file_scipy_cannot_read_is_named_not_a_syntax_error(tmp_path):
    path = tmp_path / "empty_record.nc"
    diagram = me.phase_diagram(PAPER, scenario="B")
    diagram.isel({name: slice(0, 0) for name in diagram.dims}).to_netcdf(path, engine="scipy")
    with pytest.raises(ValueError, match="is not a readable netCDF file \\(SyntaxError"):
        open_result(path)
