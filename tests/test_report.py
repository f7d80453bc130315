"""The committed results/ is what a fresh `mdr-events reproduce` computes (so it cannot go stale)."""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events import report

RESULTS = Path(__file__).parent.parent / "results"


@pytest.fixture(scope="module")
def fresh():
    """One fresh computation of everything behind results/ (about 25 s)."""
    return report.compute()


def test_committed_report_matches_a_fresh_computation(fresh):
    assert (RESULTS / "README.md").read_text() == report.report_text(fresh)


def test_committed_datasets_match_a_fresh_computation(fresh):
    for (label, scenario), dataset in fresh.continuum.items():
        stem = f"fig{report.FIGURE_NUMBERS[scenario]}_{label}"
        xr.testing.assert_identical(me.open_result(RESULTS / f"{stem}.nc"), dataset)
        xr.testing.assert_identical(me.open_result(RESULTS / f"{stem}_discrete.nc"), fresh.discrete[(label, scenario)])
        assert (RESULTS / f"{stem}.png").stat().st_size > 0
        assert (RESULTS / f"{stem}_events.csv").read_text().startswith("alpha_degree,event,time_s,kind")


def test_report_states_the_papers_numbers_beside_ours(fresh):
    text = report.report_text(fresh)
    assert "| 23.59° |" in text and "| 22.87° |" in text
    assert "**inferred**" in text
    for heading in ("### (1)", "### (2)", "### (3)", "### (4)", "## Slip onset: closed form, continuum and discrete"):
        assert heading in text
    # every cross-check row is explained, none disagrees
    assert "**disagree**" not in text


def test_adhesive_strength_is_the_jkr_value_for_every_angle(fresh):
    """Section 4.2 (1): |F_N,min| = (3/2) π Δγ1 R for all angles (continuum, 200 001 samples)."""
    for (label, scenario), values in fresh.adhesive_strength.items():
        params = me.Parameters.paper(R=report.RADII[label])
        np.testing.assert_allclose(values, -me.pull_off_force(params, params.dgamma1), rtol=1e-7)
