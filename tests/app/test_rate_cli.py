"""The rate-dependent adhesion law (issue 29) on the command line (``--adhesion-law rate --v-ref V --rate-exponent N``)
and in a study file (``[adhesion]``): both front ends build the job the API runs, the runs equal the API's bit for bit
and stamp the law (``Contact.from_attrs`` reads it back), and bad input is one line, exit 2, nothing written."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import build_parser
from mdr_events.app.cli import simulate as simulate_verb
from mdr_events.app.study import StudyError, load_study, run_study
from tests.hostile_checks import cli_one_line, one_line_naming

#: The law of the tests: the paper's works at rest (0.01 and 0.15 J/m²), an edge's reference speed at the paper's
#: path speed (1 µm/s) and Maugis & Barquins' exponent of about one half.
LAW = me.RateDependentAdhesion(0.01, 0.15, 1e-6, 0.5)
RATE = ["--adhesion-law", "rate", "--v-ref", "1e-6", "--rate-exponent", "0.5"]
RATE_TABLE = '[adhesion]\nlaw = "rate"\nv_ref = 1e-6\nn = 0.5\n'
#: A short discrete run (20 µm springs, 1000 steps).
QUICK = ["--scenario", "A", "--alpha", "20", "--dx", "2e-5", "--n-steps", "1000"]


def rate_contact() -> me.Contact:
    return dataclasses.replace(me.Contact.paper(), adhesion=LAW)


def study_file(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "study.toml"
    path.write_text(text + '\n[output]\ndirectory = "out"\n')
    return path


def test_both_front_ends_build_the_api_job_of_the_rate_law(tmp_path):
    cli = simulate_verb.job(build_parser().parse_args(["simulate", *QUICK, *RATE, "--out", "o"]))
    study = load_study(study_file(tmp_path, '[simulation]\nscenario = "A"\nalpha = [20]\ndx = 2e-5\nn_steps = 1000\n'
                                            + RATE_TABLE)).simulation
    assert dataclasses.replace(cli, stem=study.stem) == study
    assert cli.contact == rate_contact()
    paper = simulate_verb.job(build_parser().parse_args(["simulate", *QUICK, "--adhesion-law", "paper", "--out", "o"]))
    assert paper.contact == me.Contact.paper()


@pytest.mark.parametrize("method, options", [("discrete", ["--dx", "2e-5", "--n-steps", "1000"]), ("continuum", [])])
def test_simulate_of_the_rate_law_is_the_apis_run_bit_for_bit(capsys, tmp_path, method, options):
    status = simulate_verb.run(build_parser().parse_args(
        ["simulate", "--scenario", "A", "--alpha", "20", "--method", method, *options, *RATE, "--out", str(tmp_path)]))
    capsys.readouterr()
    assert status is None
    written = me.open_result(tmp_path / f"simulation_A_{method}.nc")
    direct = me.simulate(rate_contact(), me.Scenario("A", alpha=[20.0]), method,
                         **({"dx": 2e-5, "n_steps": 1000} if method == "discrete" else {}))
    for name in ("normal_force", "tangential_force", "contact_radius"):
        np.testing.assert_array_equal(written[name].values, direct[name].values)
    assert written.attrs["adhesion_law"] == "rate_dependent"
    assert me.Contact.from_attrs(written.attrs) == rate_contact()


def test_a_study_of_the_rate_law_writes_the_apis_run(tmp_path, without_drawing):
    study = load_study(study_file(tmp_path, '[simulation]\nscenario = "A"\nalpha = [20]\nmethod = "continuum"\n'
                                  + RATE_TABLE))
    run_study(study, progress=lambda line: None)
    written = me.open_result(tmp_path / "out" / "study_simulation.nc")
    direct = me.simulate(rate_contact(), me.Scenario("A", alpha=[20.0]), "continuum")
    np.testing.assert_array_equal(written["normal_force"].values, direct["normal_force"].values)
    assert me.Contact.from_attrs(written.attrs).adhesion == LAW


@pytest.mark.parametrize("options, fragment", [
    (["--adhesion-law", "rate", "--v-ref", "0", "--rate-exponent", "0.5"],
     "--adhesion-law rate --v-ref 0 --rate-exponent 0.5: RateDependentAdhesion.v_ref=0.0 is not allowed; allowed: a "
     "finite number > 0"),
    (["--adhesion-law", "rate", "--v-ref", "-1e-6", "--rate-exponent", "0.5"], "RateDependentAdhesion.v_ref=-1e-06"),
    (["--adhesion-law", "rate", "--v-ref", "inf", "--rate-exponent", "0.5"], "RateDependentAdhesion.v_ref=inf"),
    (["--adhesion-law", "rate", "--v-ref", "1e-6", "--rate-exponent", "0"],
     "RateDependentAdhesion.n=0.0 is not allowed; allowed: a number with 0 < n <= 1"),
    (["--adhesion-law", "rate", "--v-ref", "1e-6", "--rate-exponent", "1.5"], "RateDependentAdhesion.n=1.5"),
    (["--adhesion-law", "rate", "--v-ref", "1e-6", "--rate-exponent", "nan"], "RateDependentAdhesion.n=nan"),
    (["--v-ref", "1e-6"], "--v-ref 1e-06 is not allowed with the adhesion law 'paper'; allowed: --v-ref and "
                          "--rate-exponent with --adhesion-law rate"),
    (["--adhesion-law", "paper", "--rate-exponent", "0.5"], "--rate-exponent 0.5 is not allowed with the adhesion "
                                                             "law 'paper'"),
    (["--adhesion-law", "rate", "--v-ref", "1e-6"], "--adhesion-law rate lacks --rate-exponent; allowed:"),
    (["--adhesion-law", "viscous"], "argument --adhesion-law: invalid choice: 'viscous'; allowed: paper, rate"),
    ([*RATE, "--dgamma0", "0"], "RateDependentAdhesion.dgamma0=0.0 is not allowed; allowed: a finite number > 0"),
    ([*RATE, "--dgamma1", "0.001"], "RateDependentAdhesion.dgamma1=0.001 is not allowed; allowed: a finite number >= "
                                    "dgamma0"),
    ([*RATE, "--h", "5e-3"], "--h 0.005: adhesion=RateDependentAdhesion(dgamma0=0.01, dgamma1=0.15, v_ref=1e-06, "
                             "n=0.5) (RateDependentAdhesion) is not allowed on layer h = 0.005 m"),
])
def test_a_bad_rate_law_is_one_line_exit_2_and_nothing_written(capsys, tmp_path, options, fragment):
    err = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", *options, "--out",
                                str(tmp_path / "new")])
    assert fragment in err and "allowed" in err, err
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize("table, fragment", [
    ('[adhesion]\nlaw = "rate"\nv_ref = 0\nn = 0.5\n', "[adhesion] RateDependentAdhesion.v_ref=0.0 is not allowed"),
    ('[adhesion]\nlaw = "rate"\nv_ref = 1e-6\nn = 2\n', "[adhesion] RateDependentAdhesion.n=2.0 is not allowed"),
    ('[adhesion]\nlaw = "rate"\nv_ref = nan\nn = 0.5\n', "RateDependentAdhesion.v_ref=nan is not allowed"),
    ('[adhesion]\nlaw = "rate"\nv_ref = 1e-6\n', "[adhesion] the adhesion law 'rate' lacks n; allowed:"),
    ('[adhesion]\nlaw = "paper"\nn = 0.5\n', "[adhesion] n=0.5 is not allowed with the adhesion law 'paper'"),
    ('[adhesion]\nlaw = "viscous"\n', "[adhesion] law='viscous' is not allowed; allowed: 'paper' or 'rate'"),
    ('[adhesion]\nv_ref = 1e-6\n', "[adhesion] lacks the required key(s) law"),
    ('[adhesion]\nlaw = "rate"\nv_ref = "fast"\nn = 0.5\n', "[adhesion] v_ref = 'fast' is not allowed; allowed: a "
                                                             "number"),
    (RATE_TABLE + '[layer]\nh = 5e-3\n', "[simulation] adhesion=RateDependentAdhesion(dgamma0=0.01, dgamma1=0.15, v_ref=1e-06, n=0.5) "
     "(RateDependentAdhesion) is not allowed on layer h = 0.005 m"),
])
def test_a_bad_adhesion_table_is_named_when_the_study_is_read(tmp_path, table, fragment):
    path = study_file(tmp_path, '[simulation]\nscenario = "A"\nalpha = [20]\nmethod = "continuum"\n' + table)
    message = one_line_naming(lambda: load_study(path), "[adhesion]" if "[simulation]" not in fragment
                              else "[simulation]", StudyError)
    assert fragment in message, message


def test_both_front_ends_ask_for_the_critical_angles_against_the_speed():
    from mdr_events.app.cli import phase_diagram as phase_verb

    cli = phase_verb.job(build_parser().parse_args(["phase-diagram", "--scenario", "B", *RATE, "--speeds", "1e-7",
                                                    "1e-5", "--out", "o"]))
    assert cli.speeds == (1e-7, 1e-5) and cli.contact == rate_contact() and cli.stem == "critical_angle_B_at_speeds"
    default = phase_verb.job(build_parser().parse_args(["phase-diagram", "--scenario", "A", *RATE, "--out", "o"]))
    assert default.speeds == (me.Parameters.paper().v,)
    paper = phase_verb.job(build_parser().parse_args(["phase-diagram", "--scenario", "A", "--out", "o"]))
    assert paper.speeds is None and paper.stem == "phase_diagram_A"


def test_a_study_asks_for_the_clis_critical_angles_against_the_speed(tmp_path):
    from mdr_events.app.cli import phase_diagram as phase_verb

    study = load_study(study_file(tmp_path, '[phase_diagram]\nscenarios = ["A", "B"]\nspeeds = [1e-7, 1e-5]\n'
                                  + RATE_TABLE))
    for job in study.phase_diagrams:
        cli = phase_verb.job(build_parser().parse_args(["phase-diagram", "--scenario", job.scenario, *RATE,
                                                        "--speeds", "1e-7", "1e-5", "--out", "o"]))
        assert dataclasses.replace(cli, stem=job.stem) == job and job.stem.endswith(f"critical_angle_{job.scenario}"
                                                                                    "_at_speeds")


@pytest.mark.slow  # (two edge solves of the critical angle, ~4 s of CPU each: the CLI's and the API's)
def test_the_critical_angle_against_the_speed_is_the_apis_bit_for_bit(capsys, tmp_path):
    from mdr_events.app.cli import main

    assert main(["phase-diagram", "--scenario", "A", *RATE, "--speeds", "1e-6", "--out", str(tmp_path)]) == 0
    capsys.readouterr()
    written = me.open_result(tmp_path / "critical_angle_A_at_speeds.nc")
    direct = me.critical_angles_at_speeds(rate_contact(), [1e-6])
    np.testing.assert_array_equal(written["critical_angle"].values, direct["critical_angle"].values)
    assert me.Contact.from_attrs(written.attrs) == rate_contact()


@pytest.mark.parametrize("argv, fragment", [
    (["phase-diagram", "--scenario", "A", "--speeds", "1e-6"], "--speeds 1e-06: speeds=[1e-06] are not allowed with "
                                                               "the adhesion law 'paper'; allowed:"),
    (["phase-diagram", "--scenario", "A", *RATE, "--speeds", "1e-6", "-1"], "--speeds 1e-06 -1: speed=-1.0 is not "
                                                                           "allowed; allowed: a finite number > 0"),
    (["phase-diagram", "--scenario", "B", *RATE, "--friction", "coulomb", "--mu", "0.3"],
     "--adhesion-law rate: contact.friction=FrictionLaw('coulomb', mu=0.3) is not allowed in the critical angles "
     "against the speed; allowed: FrictionLaw('tau0'"),
    (["validate", "run.csv", "--scenario", "A", "--alpha", "20", *RATE, "--friction", "coulomb", "--mu", "0.3"],
     "--adhesion-law rate: friction=FrictionLaw('coulomb', mu=0.3) is not allowed in validate with "
     "adhesion=RateDependentAdhesion(dgamma0=0.01, dgamma1=0.15, v_ref=1e-06, n=0.5): its reference, the rate law's "
     "continuum at the candidate's times, holds tau0's cap alone"),
])
def test_a_verb_that_does_not_take_the_rate_law_so_is_one_line(capsys, tmp_path, argv, fragment):
    err = cli_one_line(capsys, [*argv, "--out", str(tmp_path / "new")])
    assert fragment in err, err
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize("tables, fragment", [
    ('[validate]\nruns = ["run.csv"]\nscenario = "A"\nalpha = 20\n[friction]\nlaw = "coulomb"\nmu = 0.3\n',
     "[validate] friction=FrictionLaw('coulomb', mu=0.3) is not allowed in validate with "
     "adhesion=RateDependentAdhesion("),
    ('[phase_diagram]\nscenarios = ["A"]\nspeeds = [0]\n', "[phase_diagram] speed=0 is not allowed"),
])
def test_a_table_that_does_not_take_the_rate_law_so_is_named_when_read(tmp_path, tables, fragment):
    path = study_file(tmp_path, tables + RATE_TABLE)
    table = fragment.split("]")[0] + "]"
    assert fragment in one_line_naming(lambda: load_study(path), table, StudyError)


def test_a_study_sweep_of_the_rate_law_over_its_values_is_the_apis(tmp_path):
    """``[sweep]`` over ``v_ref`` and the law's exponent ``adhesion.n`` in the continuum: the sweep the API runs."""
    from mdr_events.app.study import run_sweep

    study = load_study(study_file(tmp_path, '[sweep]\ngrid = { v_ref = [1e-7, 1e-5], "adhesion.n" = [0.5] }\n'
                                            'scenario = "A"\nalpha = 20\nmethod = "continuum"\nscheduler = "serial"\n'
                                            'quantities = ["normal_force_min", "tangential_force_max"]\n'
                                  + RATE_TABLE))
    run_sweep(study, progress=lambda line: None)
    written = me.open_result(tmp_path / "out" / "study_sweep.nc")
    direct = me.sweep({"v_ref": [1e-7, 1e-5], "adhesion.n": [0.5]}, rate_contact(), me.Scenario("A", [20.0]),
                      method="continuum", scheduler="serial", quantities=("normal_force_min", "tangential_force_max"))
    assert written.attrs["failed_runs"] == 0
    for name in ("normal_force_min", "tangential_force_max"):
        np.testing.assert_array_equal(written[name].values, direct[name].values)


#: The springs' spacing of the run refereed (its first-order error, 8e-4 of the range, within validate's default
#: tolerance of 1e-3 is not needed: the equality with the API is the test).
VALIDATED_DX = 2e-6


def _rate_run_file(tmp_path: Path) -> Path:
    run = tmp_path / "run.nc"
    me.write_netcdf(me.simulate(rate_contact(), me.Scenario("A", alpha=[20.0]), "discrete",
                                dx=VALIDATED_DX).isel(alpha=0), run)
    return run


def _same_report(written, direct) -> None:
    for name in ("max_error", "rms_error", "exact_normal_force", "exact_tangential_force", "event_time_exact",
                 "event_time_candidate", "pull_off_force_exact"):
        np.testing.assert_array_equal(written[name].values, direct[name].values, err_msg=name)
    for key in ("verdict", "adhesion_law", "adhesion_v_ref", "adhesion_n", "events_not_compared"):
        assert written.attrs[key] == direct.attrs[key], key


def test_validate_of_the_rate_law_on_the_command_line_is_the_apis_bit_for_bit(capsys, tmp_path):
    """The referee's reference is the rate law's continuum on the command line as in the API (it refused the law)."""
    from mdr_events.app.cli import main

    run = _rate_run_file(tmp_path)
    status = main(["validate", str(run), "--scenario", "A", "--alpha", "20", *RATE, "--out", str(tmp_path / "out")])
    capsys.readouterr()
    direct = me.validate(run, rate_contact(), "A", 20.0)
    assert status == (0 if direct.attrs["verdict"] == "pass" else 1)
    _same_report(me.open_result(tmp_path / "out" / "run.nc"), direct)
    assert direct.attrs["adhesion_law"] == "rate_dependent"


def test_a_study_s_validate_of_the_rate_law_is_the_apis_bit_for_bit(tmp_path, without_run_figures):
    without_run_figures()  # (the report's figure of the rate law is drawn on the command line above)
    run = _rate_run_file(tmp_path)
    study = load_study(study_file(tmp_path, f'[validate]\nruns = ["{run}"]\nscenario = "A"\nalpha = 20\n'
                                  + RATE_TABLE))
    run_study(study, progress=lambda line: None)
    _same_report(me.open_result(tmp_path / "out" / "study_validation_run.nc"),
                 me.validate(run, rate_contact(), "A", 20.0))
