"""The thirtieth hostile round (issue 32), resource guards and interrupts: each class of what failed, with the cases
that showed it (sizes measured against ``Limits``, interrupts of the writing verbs, a sweep's store of another
version)."""

from __future__ import annotations

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
