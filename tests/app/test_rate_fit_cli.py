"""The joint fit of the rate-dependent law (issue 29, item 4) on the command line (``mdr-events fit A.csv B.csv
--adhesion-law rate ... --speeds VA VB``) and in a study file (``[fit] data = [...]``, ``speeds``, ``offsets``): one
result equal to :func:`~mdr_events.fit_rate_adhesion`'s of the same curves bit for bit, stamped with the law; bad
input one line, exit 2, nothing written."""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.rate_fit import RateMeasurement, fit_rate_adhesion
from mdr_events.app.cli import build_parser, main
from mdr_events.app.cli import fit as fit_verb
from mdr_events.app.study import StudyError, load_study, run_study
from mdr_events.models.continuum import solve_edge
from tests.hostile_checks import cli_one_line, one_line_naming

PAPER = me.Parameters.paper()
TRUE = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
START = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 3e-6, 0.8)
#: Two speeds a decade either side of v_ref, 80 samples each (the API's own test recovers the law from three).
SPEEDS = (1e-7, 1e-5)
SAMPLES = 80
#: The curves' noise: 1 % of JKR's pull-off force (N).
NOISE = 0.01 * 1.5 * np.pi * PAPER.dgamma1 * PAPER.R
WAYPOINTS = [(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -200e-6)]
START_OPTIONS = ["--adhesion-law", "rate", "--v-ref", "3e-6", "--rate-exponent", "0.8"]


def curves(tmp_path: Path) -> list[RateMeasurement]:
    """The synthetic curves (the path starts at the surface: its clock is the time from first contact), written as
    CSV files ``curve_<i>.csv`` (``repr``: read back bit for bit)."""
    rng, out = np.random.default_rng(11), []
    for index, speed in enumerate(SPEEDS):
        path, times, clean = _solved_curve(speed)
        force = clean + rng.normal(0.0, NOISE, SAMPLES)
        (tmp_path / f"curve_{index}.csv").write_text("time,normal_force\n" + "".join(
            f"{float(t)!r},{float(f)!r}\n" for t, f in zip(times, force)))
        out.append(RateMeasurement(path, times, force, NOISE))
    (tmp_path / "path.toml").write_text(f"[path]\nwaypoints = {[list(p) for p in WAYPOINTS]!r}\n")
    return out


@functools.cache
def _solved_curve(speed: float) -> tuple[me.Path, np.ndarray, np.ndarray]:
    """The path, times and noise-free normal force of :func:`curves` at ``speed``, solved once per module (two tests
    read them, ~0.4 s of CPU a solve); the arrays read-only, so that no test changes another's."""
    path = me.Path(np.array(WAYPOINTS), speed=speed)
    times = np.linspace(path.first_contact_time(), path.duration, SAMPLES)
    force = solve_edge(PAPER, path, TRUE).normal_force(times, path)
    times.flags.writeable = force.flags.writeable = False
    return path, times, force


def test_the_cli_joint_fit_is_the_apis_bit_for_bit(capsys, tmp_path):
    measured = curves(tmp_path)
    status = main(["fit", str(tmp_path / "curve_0.csv"), str(tmp_path / "curve_1.csv"), "--path",
                   str(tmp_path / "path.toml"), "--speeds", *map(repr, SPEEDS), *START_OPTIONS, "--free", "v_ref", "n",
                   "--noise", f"normal_force={NOISE!r}", "--out", str(tmp_path / "out")])
    out = capsys.readouterr().out
    assert status == 0, out
    written = me.open_result(tmp_path / "out" / "curve_0_rate_fit.nc")
    direct = fit_rate_adhesion(measured, PAPER, START, free=("v_ref", "n"))
    for name in ("estimate", "standard_error", "interval_lower", "interval_upper"):
        np.testing.assert_array_equal(written[name].values, direct[name].values)
    for name, truth in (("v_ref", TRUE.v_ref), ("n", TRUE.n)):  # (and the law is found: within its interval)
        row = written.sel(parameter=name)
        assert float(row["interval_lower"]) <= truth <= float(row["interval_upper"]), name
    assert me.Contact.from_attrs(written.attrs).adhesion == START and "v_ref = " in out


def test_a_study_of_the_joint_fit_builds_the_clis_job_and_writes_its_result(tmp_path):
    curves(tmp_path)
    study = tmp_path / "study.toml"
    study.write_text('[path]\nwaypoints = [[0.0, 0.0], [0.0, 3e-4], [0.0, -2e-4]]\n'
                     '[adhesion]\nlaw = "rate"\nv_ref = 3e-6\nn = 0.8\n'
                     f'[fit]\ndata = ["curve_0.csv", "curve_1.csv"]\nspeeds = [{SPEEDS[0]!r}, {SPEEDS[1]!r}]\n'
                     'free = ["v_ref", "n"]\noffsets = true\n[output]\ndirectory = "out"\n')
    loaded = load_study(study)
    cli = fit_verb.job(build_parser().parse_args([
        "fit", str(tmp_path / "curve_0.csv"), str(tmp_path / "curve_1.csv"), "--path", str(study), "--speeds",
        *map(repr, SPEEDS), *START_OPTIONS, "--free", "v_ref", "n", "--offsets", "--out", "o"]))
    for name in ("files", "contact", "free", "offsets", "noise", "time_origin", "d_max", "limits"):
        assert getattr(cli, name) == getattr(loaded.fit, name), name
    for mine, theirs in zip(cli.paths, loaded.fit.paths, strict=True):
        assert mine.speed == theirs.speed and np.array_equal(mine.waypoints, theirs.waypoints)
    assert [path.speed for path in loaded.fit.paths] == list(SPEEDS)
    outcomes = run_study(loaded, progress=lambda line: None)
    written = me.open_result(tmp_path / "out" / "study_rate_fit_curve_0.nc")
    assert list(written["parameter"].values) == ["v_ref", "n", "offset_0", "offset_1"]
    assert outcomes.verdicts["fit curve_0.csv"] is me.Verdict.PASS


@pytest.mark.parametrize("options, fragment", [
    (["--free", "tau0"], "--free tau0 is not allowed with --adhesion-law rate; allowed: distinct names among v_ref, n, "
                         "dgamma0, dgamma1"),
    (["--free", "n", "--speeds", "1e-7"], "--speeds 1e-07 is not allowed with 2 measurement(s); allowed: one speed per "
                                          "DATA"),
    (["--free", "n", "--speeds", "1e-7", "-1"], "--speeds: speed=-1.0 is not allowed; allowed: a finite number > 0"),
    (["--free", "n", "--bounds", "n=0.1:1"], "--bounds n=0.1:1 is not allowed with --adhesion-law rate"),
    (["--free", "n", "--h", "5e-3"], "--h 0.005 with --adhesion-law rate: Contact.layer=Layer(thickness=0.005"),
    (["--free", "n", "--noise", "tangential_force=1"], "--noise tangential_force=1 is not allowed with --adhesion-law "
                                                       "rate; allowed: normal_force=SIGMA alone"),
])
def test_a_bad_rate_fit_is_one_line_exit_2_and_nothing_written(capsys, tmp_path, options, fragment):
    (tmp_path / "path.toml").write_text("[path]\nwaypoints = [[0.0, 0.0], [0.0, 3e-4]]\n")
    err = cli_one_line(capsys, ["fit", "a.csv", "b.csv", "--path", str(tmp_path / "path.toml"), *START_OPTIONS,
                                *options, "--out", str(tmp_path / "new")])
    assert fragment in err, err
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize("options, fragment", [
    (["a.csv", "b.csv", "--free", "tau0"], "2 measurements (a.csv b.csv) are not allowed with the adhesion law "
                                           "'paper'; allowed: one DATA"),
    (["a.csv", "--free", "tau0", "--speeds", "1e-6"], "--speeds is not allowed with the adhesion law 'paper'"),
    (["a.csv", "--free", "tau0", "--offsets"], "--offsets is not allowed with the adhesion law 'paper'"),
])
def test_the_rate_fits_options_without_the_rate_law_are_refused(capsys, tmp_path, options, fragment):
    err = cli_one_line(capsys, ["fit", *options, "--scenario", "A", "--alpha", "20", "--out", str(tmp_path / "new")])
    assert fragment in err, err
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize("fit, fragment", [
    ('data = ["a.csv", "b.csv"]\nfree = ["n"]\nspeeds = [1e-6]\n', "[fit] speeds = [1e-06] is not allowed with 2 "
                                                                   "measurement(s)"),
    ('data = "a.csv"\nfree = ["tau0"]\noffsets = true\n', "[fit] offsets is not allowed with the adhesion law 'paper'"),
    ('data = ["a.csv", "b.csv"]\nfree = ["tau0"]\n', "[fit] 2 measurements are not allowed with the adhesion law "
                                                     "'paper'"),
    ('data = ["a.csv"]\nfree = ["n"]\nbounds = { n = [0.1, 1] }\n', "[fit] bounds = {'n': [0.1, 1]} is not allowed "
                                                                    "with the rate law"),
])
def test_a_bad_fit_table_of_the_rate_law_is_named_when_the_study_is_read(tmp_path, fit, fragment):
    rate = '[adhesion]\nlaw = "rate"\nv_ref = 3e-6\nn = 0.8\n' if "tau0" not in fit else ""
    study = tmp_path / "study.toml"
    study.write_text('[path]\nwaypoints = [[0.0, 0.0], [0.0, 3e-4]]\n' + rate + "[fit]\n" + fit
                     + '[output]\ndirectory = "out"\n')
    assert fragment in one_line_naming(lambda: load_study(study), "[fit]", StudyError)


def _fit_result(n: float, status: int):
    """A joint fit's result as :func:`fit_rate_adhesion` lays it out (v_ref and n free), finite errors and intervals."""
    import xarray as xr

    names = ["v_ref", "n"]
    return xr.Dataset({"estimate": ("parameter", [1e-6, n]), "standard_error": ("parameter", [1e-8, 0.01]),
                       "interval_lower": ("parameter", [0.9e-6, n - 0.02]),
                       "interval_upper": ("parameter", [1.1e-6, n + 0.02])},
                      coords={"parameter": names}, attrs={"status": status})


@pytest.mark.parametrize("n, status, determined", [
    (0.6, 1, True),   # converged, inside the bounds
    (0.6, 0, False),  # least_squares stopped at its evaluation limit: exit 0 before
    (1.0, 1, False),  # n on its upper bound: the linearised interval ignores the bound (exit 0 before)
    (1e-3, 2, False),  # n on its lower bound
])
def test_the_joint_fit_is_determined_only_when_it_converged_inside_the_bounds(n, status, determined):
    from mdr_events.app.jobs import RateFitJob

    assert RateFitJob.determined(_fit_result(n, status)) is determined
