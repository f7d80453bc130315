"""The committed results/ is what a fresh `mdr-events reproduce` computes (so it cannot go stale).

Across machines and library versions each quantity of the datasets is compared within the accuracy of how it is
computed (:mod:`mdr_events.io.agreement`; exact for dimensions, strings and integers); the report, which rounds,
within one unit of each number's last digit (tests/reproduction/test_other_cpu.py plays another CPU). Bit-identical
output on repeat within one environment is tested where each result is made (tests/io/test_files.py,
tests/models/test_discrete.py, test_properties.py).
"""

import re
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.reproduction import runner
from mdr_events.reproduction.common import FIGURE_NUMBERS, RADII
from mdr_events.reproduction.fit_demo import FIT_STEM
from mdr_events.reproduction.fretting import FRETTING_STEM
from mdr_events.reproduction.markdown import INTEGRATED_ACCURACY
from mdr_events.reproduction.mindlin import MINDLIN_STEM, mindlin_rows
from mdr_events.reproduction.mindlin_adhesive import MINDLIN_ADHESIVE_STEM, adhesive_rows
from mdr_events.reproduction.profiles import PROFILE_STEM, profile_rows
from mdr_events.reproduction.readme import RECORDED_PACKAGES, recorded_versions
from mdr_events.reproduction.universal import UNIVERSAL_STEM
from mdr_events.io.agreement import assert_results_agree, result_differences, rounded_text_differences, tolerance_of
from mdr_events.io.files import write_netcdf
from mdr_events.app.result_files import FileStatus

ROOT = Path(__file__).resolve().parents[2]
RESULTS = ROOT / "results"


@pytest.fixture(scope="module")
def computed():
    """One fresh computation of everything behind results/ (about 20 s) and the progress messages it sent."""
    messages = []
    return runner.compute(messages.append), messages


@pytest.fixture(scope="module")
def fresh(computed):
    return computed[0]


def locked_versions() -> dict[str, str]:
    """``name==version`` pins of the lock file (names lower-cased)."""
    pins = re.findall(r"^([A-Za-z0-9_.\-]+)==(\S+)", (ROOT / "constraints.txt").read_text(), flags=re.MULTILINE)
    return {name.lower(): version for name, version in pins}


@pytest.mark.slow
def test_committed_report_matches_a_fresh_computation(fresh):
    """Every rounded number of results/README.md is what this machine computes; only the software section
    may differ (it records the versions results/ was written with, which need not be this machine's)."""
    committed = (RESULTS / "README.md").read_text()
    recorded = recorded_versions(committed)
    assert set(recorded) == {"Python", *RECORDED_PACKAGES}
    assert rounded_text_differences(runner.report_text(fresh, versions=recorded), committed) == []


def test_results_were_written_with_the_locked_versions():
    """The lock file pins exactly the versions that results/README.md says results/ was written with."""
    recorded = recorded_versions((RESULTS / "README.md").read_text())
    locked = locked_versions()
    for name in RECORDED_PACKAGES:
        assert recorded[name] == locked[name], name


@pytest.mark.slow
def test_committed_datasets_agree_with_a_fresh_computation(fresh):
    figures = fresh["figures"]
    for (label, scenario), dataset in figures.continuum.items():
        stem = f"fig{FIGURE_NUMBERS[scenario]}_{label}"
        assert_results_agree(dataset, me.open_result(RESULTS / f"{stem}.nc"))
        assert_results_agree(figures.discrete[(label, scenario)], me.open_result(RESULTS / f"{stem}_discrete.nc"))
        assert (RESULTS / f"{stem}.png").stat().st_size > 0
        assert (RESULTS / f"{stem}_events.csv").read_text().startswith("alpha_degree,event,time_s,kind")
    stem = FRETTING_STEM
    assert_results_agree(fresh["fretting"].continuum, me.open_result(RESULTS / f"{stem}.nc"))
    assert_results_agree(fresh["fretting"].discrete, me.open_result(RESULTS / f"{stem}_discrete.nc"))
    assert (RESULTS / f"{stem}.png").stat().st_size > 0
    events = (RESULTS / f"{stem}_events.csv").read_text()
    assert events.startswith("case,event,time_s,kind") and events.count("tangential_reversal") == 12
    assert_results_agree(fresh["fit"].measured, me.open_result(RESULTS / f"{FIT_STEM}_measured.nc"))
    assert_results_agree(fresh["fit"].result.dataset, me.open_result(RESULTS / f"{FIT_STEM}.nc"))
    assert_results_agree(fresh["universal"], me.open_result(RESULTS / f"{UNIVERSAL_STEM}.nc"))


def test_every_committed_quantity_declares_how_it_is_computed():
    """No blanket tolerance: each float variable of each committed dataset has a declared accuracy, whose tolerance
    is finite and non-negative everywhere the value is finite."""
    for path in sorted(RESULTS.glob("*.nc")):
        dataset = me.open_result(path)
        for name, variable in dataset.variables.items():
            if variable.dtype.kind != "f":
                continue
            tolerance = np.broadcast_to(tolerance_of(dataset, name), variable.shape)
            finite = np.isfinite(variable.values)
            assert np.all(tolerance[finite] >= 0) and np.all(np.isfinite(tolerance[finite])), (path.name, name)


@pytest.mark.slow
def test_the_other_indenters_meet_their_closed_forms(fresh):
    """results/profiles_A20_*: the committed files agree with a fresh run; for each indenter (the flat punch too) the
    continuum's least normal force is the pull-off force under force control and its slip onset while indenting is
    (18),
    both to 1e-9, and the discrete model (Δx = 1 µm) lies within 1e-3 of the largest F_x (first order: about
    1e-3 per µm, as for the paraboloid)."""
    for name in fresh["profiles"].profiles:
        stem = f"{PROFILE_STEM}_{name}"
        assert_results_agree(fresh["profiles"].continuum[name], me.open_result(RESULTS / f"{stem}.nc"))
        assert_results_agree(fresh["profiles"].discrete[name], me.open_result(RESULTS / f"{stem}_discrete.nc"))
    assert (RESULTS / f"{PROFILE_STEM}.png").stat().st_size > 0
    rows = profile_rows(fresh["profiles"], me.Parameters.paper())
    assert [getattr(row.profile, "n", "punch") for row in rows] == [1.0, 2.0, 4.0, "punch"]
    for row in rows:
        assert row.pull_off_continuum == pytest.approx(row.pull_off_closed_form, rel=1e-9), row.name
        assert row.onset_continuum == pytest.approx(row.onset_closed_form, rel=1e-9), row.name
        assert row.discrete_difference < 1e-3, row.name
    paraboloid = rows[1]
    assert paraboloid.pull_off_closed_form == pytest.approx(me.pull_off_force(me.Parameters.paper(),
                                                                              me.Parameters.paper().dgamma1), rel=1e-14)


@pytest.mark.slow
def test_the_cattaneo_mindlin_check_meets_its_closed_form(fresh):
    """results/mindlin_coulomb*: the committed files agree with a fresh run and carry the closed form; the continuum
    equals it to 1e-9 of μ F_N, the discrete model (Δx = 1 µm, first order) to 1e-5; the loop goes to full slip."""
    stem = MINDLIN_STEM
    continuum, discrete = fresh["mindlin"]
    assert_results_agree(continuum, me.open_result(RESULTS / f"{stem}.nc"))
    assert_results_agree(discrete, me.open_result(RESULTS / f"{stem}_discrete.nc"))
    assert (RESULTS / f"{stem}.png").stat().st_size > 0
    rows = mindlin_rows(fresh["mindlin"])
    assert rows[0].max_difference < 1e-9 and rows[1].max_difference < 1e-5
    full = 0.3 * np.nanmax(continuum["normal_force"].values)
    assert np.nanmax(continuum["cattaneo_mindlin_force"].values) == pytest.approx(full, rel=1e-12)
    assert continuum.attrs["friction_law"] == "coulomb" and continuum.attrs["param_dgamma0"] == 0.0


@pytest.mark.slow
def test_the_cattaneo_mindlin_check_with_adhesion_is_free_of_it(fresh):
    """results/mindlin_coulomb_adhesive*: the committed files agree with a fresh run; with the paper's adhesion the
    continuum equals the closed form without adhesion to 1e-9 of μ F_N^H and its own run without adhesion to rounding
    (Coulomb's part is the compressed zone's), the discrete model (Δx = 1 µm) to 1e-5 and 1e-12; full slip is
    μ F_N^H, above μ F_N (the tensile annulus pulls)."""
    check = fresh["mindlin_adhesive"]
    assert_results_agree(check.adhesive.continuum, me.open_result(RESULTS / f"{MINDLIN_ADHESIVE_STEM}.nc"))
    assert_results_agree(check.adhesive.discrete, me.open_result(RESULTS / f"{MINDLIN_ADHESIVE_STEM}_discrete.nc"))
    assert (RESULTS / f"{MINDLIN_ADHESIVE_STEM}.png").stat().st_size > 0
    continuum, discrete = adhesive_rows(check)
    assert continuum.max_difference < 1e-9 and continuum.from_without < 1e-12
    assert discrete.max_difference < 1e-5 and discrete.from_without < 1e-12
    exact = check.adhesive.continuum
    full = np.nanmax(exact["cattaneo_mindlin_force"].values)
    assert np.nanmax(exact["tangential_force"].values) == pytest.approx(full, rel=1e-12)
    assert full > (1 + 1e-3) * 0.3 * np.nanmax(exact["normal_force"].values)
    assert exact.attrs["param_dgamma0"] == 0.01 and exact.attrs["friction_law"] == "coulomb"


def test_the_comparison_catches_what_the_tolerance_does_not_allow():
    """F_x's tolerance is the integrator's rtol of its largest magnitude and nothing else is loose: a change of
    3 rtol at the largest value, a moved nan, an event kind or an attribute is a difference."""
    committed = me.open_result(RESULTS / "fig10_R30.nc")

    def changed(edit):
        copy = committed.copy(deep=True)
        edit(copy)
        return result_differences(copy, committed)

    rtol = committed.attrs["rtol"]
    largest = np.unravel_index(np.nanargmax(np.abs(committed["tangential_force"].values)),
                               committed["tangential_force"].shape)
    tolerance = np.broadcast_to(tolerance_of(committed, "tangential_force"), committed["tangential_force"].shape)
    assert tolerance[largest] == pytest.approx(rtol * abs(committed["tangential_force"].values[largest]), rel=1e-2)
    assert changed(lambda ds: ds["tangential_force"].values.__setitem__(
        largest, ds["tangential_force"].values[largest] * (1 + 0.3 * rtol))) == []
    assert changed(lambda ds: ds["tangential_force"].values.__setitem__(
        largest, ds["tangential_force"].values[largest] * (1 + 3 * rtol)))
    after_the_run = (-1, int(np.argmax(np.isnan(committed["normal_force"].values[-1]))))  # 80°: the shortest run
    assert np.isnan(committed["normal_force"].values[after_the_run])
    assert changed(lambda ds: ds["normal_force"].values.__setitem__(after_the_run, 0.0))
    assert changed(lambda ds: ds["event_kind"].values.__setitem__((0, 1), "full_slip"))
    assert changed(lambda ds: ds.attrs.__setitem__("rtol", 2e-10))
    assert changed(lambda ds: ds["contact_area"].attrs.__setitem__("units", "mm2"))


@pytest.mark.slow
def test_adhesive_strength_is_the_jkr_value_for_every_angle(fresh):
    """Section 4.2 (1): |F_N,min| = (3/2) π Δγ1 R for all angles, from the solution's exact minimum (the
    Brent refinement leaves a second-order value error; the radius root is exact to a few ulp)."""
    for (label, scenario), extremes in fresh["figures"].extremes.items():
        params = me.Parameters.paper(R=RADII[label])
        np.testing.assert_allclose(extremes["normal_force_min"], me.pull_off_force(params, params.dgamma1),
                                   rtol=1e-12)


@pytest.mark.slow
def test_maximum_normal_force_is_exact_and_the_same_for_every_angle(fresh):
    """Section 4.2 (2): F_N,max is the JKR force (10) at d_max on the Δγ0 branch whatever α (it was read off
    2001 samples and varied with α before)."""
    for (label, _), extremes in fresh["figures"].extremes.items():
        params = me.Parameters.paper(R=RADII[label])
        exact = me.jkr_normal_force(me.jkr_contact_radius(params.d_max, params, params.dgamma0), params,
                                    params.dgamma0)
        np.testing.assert_allclose(extremes["normal_force_max"], exact, rtol=1e-13)
    assert "| 10° | 517.447 mN |" in runner.report_text(fresh)


@pytest.mark.slow
def test_reproduce_keeps_files_that_agree_and_rewrites_those_that_do_not(fresh, tmp_path, monkeypatch):
    """`mdr-events reproduce` leaves a file alone when its content agrees with the fresh computation (so that
    git status stays clean on another machine) and says so; a real change is written."""
    def replay(progress=None, sections=None):
        """The fresh computation, with one message per step as compute sends them (counted below)."""
        for number in range(runner.COMPUTE_STEPS):
            progress(f"computing, step {number + 1}")
        return fresh

    monkeypatch.setattr(runner, "compute", replay)
    first = runner.reproduce(tmp_path, progress=lambda message: None)
    assert {outcome.status for outcome in first} == {FileStatus.WRITTEN}
    before = {path.name: path.read_bytes() for path in tmp_path.iterdir()}

    # another machine's rounding: one value moved by half its tolerance
    target = tmp_path / "fig8_R30.nc"
    nudged = me.open_result(target)
    allowed = np.broadcast_to(tolerance_of(nudged, "normal_force"), nudged["normal_force"].shape)[0, 10]
    nudged["normal_force"].values[0, 10] += 0.5 * allowed
    write_netcdf(nudged, target)
    nudged_bytes = target.read_bytes()
    assert nudged_bytes != before["fig8_R30.nc"]
    messages = []
    second = runner.reproduce(tmp_path, progress=messages.append)
    assert {outcome.status for outcome in second} == {FileStatus.KEPT}
    assert target.read_bytes() == nudged_bytes
    assert any("fig8_R30.nc" in message and "not rewritten" in message for message in messages)
    # every step numbered once, up to the total announced; the fretting files listed like the others
    steps = [re.match(r"\[(\d+)/(\d+)\] ", message) for message in messages]
    numbers = [(int(m.group(1)), int(m.group(2))) for m in steps if m]
    total = numbers[0][1]
    assert numbers == [(k, total) for k in range(1, total + 1)]
    fretting = [f"{FRETTING_STEM}{suffix}" for suffix in ("_discrete.nc", ".nc", ".png", "_events.csv")]
    assert any(all(name in message for name in fretting) and "not rewritten" in message for message in messages)

    # a real change (beyond the tolerance) is rewritten, the rest kept
    nudged["normal_force"].values[0, 10] *= 1 + 1e-6
    write_netcdf(nudged, target)
    third = {outcome.path.name: outcome.status for outcome in runner.reproduce(tmp_path, progress=lambda m: None)}
    assert third["fig8_R30.nc"] is FileStatus.WRITTEN and third["fig10_R30.nc"] is FileStatus.KEPT
    assert target.read_bytes() == before["fig8_R30.nc"]
    assert {path.name: path.read_bytes() for path in tmp_path.iterdir()} == before


@pytest.mark.slow
def test_compute_sends_one_progress_message_per_step(computed):
    """reproduce numbers its steps out of a total that counts compute's as COMPUTE_STEPS."""
    _, messages = computed
    assert len(messages) == runner.COMPUTE_STEPS
    # the steps after the figures' and convergence's, in the sections' order (each message's start)
    expected = ["fretting at d_max, R = 30 mm", "fit of 4 parameters to synthetic measurements",
                "universal map: critical angles", "other indenters: cone, paraboloid, quartic and flat punch",
                "Cattaneo–Mindlin: Coulomb's law", "Cattaneo–Mindlin with adhesion: Coulomb's law",
                "LAMMPS hertz/material", "LAMMPS jkr", "LAMMPS dmt", "rate-dependent adhesion: pull-off at 7 speeds",
                "rate-dependent adhesion: the critical angle of A", "rate-dependent adhesion: A's phase diagram",
                "rate-dependent adhesion: A at 20°", "rate-dependent adhesion: the critical angle of B",
                "layers of finite thickness: pull-off against h",
                "layers of finite thickness: ContactMechanics' recorded forces",
                "Fig. 8, R = 30 mm on the 5 mm layer", "Fig. 10, R = 30 mm on the 5 mm layer",
                "Fig. 8, R = 100 mm on the 5 mm layer", "Fig. 10, R = 100 mm on the 5 mm layer",
                "layers of finite thickness: the critical angles against h"]
    tail = messages[-len(expected):]
    assert all(message.startswith(start) for message, start in zip(tail, expected)), tail


@pytest.mark.slow
def test_report_states_the_papers_numbers_beside_ours(fresh):
    text = runner.report_text(fresh)
    assert "| 23.59° |" in text and "| 22.87° |" in text
    assert "**inferred**" in text
    for heading in ("### (1)", "### (2)", "### (3)", "### (4)", "## Slip onset: closed form, continuum and discrete",
                    "## Fretting at d_max (R = 30 mm)", "## Software"):
        assert heading in text
    # every cross-check row is explained, none disagrees
    assert "**disagree**" not in text
    # the fretting section lists both cases, the continuum equal to the closed form
    for case in ("vertical", "oblique 20°"):
        line, = (line for line in text.splitlines() if line.startswith(f"| {case} |"))
        assert f"| < {INTEGRATED_ACCURACY:g} |" in line
