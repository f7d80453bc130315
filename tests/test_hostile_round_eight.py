"""The eighth hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import main
from mdr_events.app.study import StudyError, load_study

CONTACT = me.Contact.paper()
PLAIN = "a plain decimal number (ASCII digits 0-9"


def one_line(capsys, status: int, expected: int = 2) -> str:
    err = capsys.readouterr().err
    assert status == expected and err.count("\n") == 1 and err.startswith("mdr-events: error:"), err
    return err


# --- N1: a number written as text was read by Python's float()/int(): digit separators and every script's digits ---
NOT_PLAIN = ["1_0", "２０", "٢٠", "2\u0660"]  # (underscore, full-width, Arabic-Indic, a mixed ASCII and Arabic zero)


@pytest.mark.parametrize("text", NOT_PLAIN)
@pytest.mark.parametrize("argv, option", [
    (["simulate", "--scenario", "A", "--alpha", "{}"], "argument --alpha: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "{}"], "argument --alpha: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--E", "{}"], "argument --E: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--n-steps", "{}"], "argument --n-steps: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--dx", "{}"], "argument --dx: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--power-law", "2000", "{}"], "argument --power-law: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--flat-punch", "{}"], "argument --flat-punch: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--friction", "coulomb", "--mu", "{}"], "argument --mu: "),
    (["simulate", "--scenario", "A", "--alpha", "20", "--limit", "steps={}"], "--limit 'steps="),
    (["validate", "run.csv", "--scenario", "A", "--alpha", "20", "--tolerance", "{}"], "argument --tolerance: "),
    (["validate", "run.csv", "--scenario", "A", "--alpha", "20", "--time-origin", "{}"], "--time-origin '"),
    (["fit", "run.csv", "--free", "tau0", "--scenario", "A", "--alpha", "20", "--noise", "normal_force={}"],
     "--noise normal_force='"),
    (["fit", "run.csv", "--scenario", "A", "--alpha", "20", "--free", "tau0", "--bounds", "tau0={}:1e6"],
     "--bounds 'tau0="),
    (["phase-diagram", "--scenario", "A", "--tau0", "{}"], "argument --tau0: "),
    (["lammps-check", "--normal", "jkr", "--scenario", "A", "--alpha", "20", "--steps", "{}"], "argument --steps: "),
    (["lammps-check", "--normal", "jkr", "--scenario", "A", "--alpha", "20", "--dt", "{}"], "argument --dt: "),
    (["sweep", "study.toml", "--workers", "{}"], "argument --workers: "),
])
def test_every_number_option_reads_plain_decimal_notation_only(tmp_path, capsys, argv, option, text):
    """``--alpha 1_0`` simulated 10°, ``--alpha ２０`` 20°: Python's float() and int() read digit separators and the
    digits of every script. Every option of a number reads one notation (validation.plain_number)."""
    argv = [word.format(text) for word in argv] + ["--out", str(tmp_path / "out")]
    err = one_line(capsys, main(argv))
    assert option in err and text in err and "plain decimal" in err, err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("text, value", [("20", 20.0), ("+20", 20.0), ("2e1", 20.0), ("20.", 20.0), (".5e2", 50.0),
                                         (" 20 ", 20.0), ("-0", -0.0), ("inf", float("inf")), ("1E-3", 1e-3)])
def test_plain_decimal_notation_is_read_as_before(text, value):
    from mdr_events.app.cli import build_parser
    from mdr_events.validation import plain_number

    args = build_parser().parse_args(["simulate", "--scenario", "A", "--alpha", text, "--out", "o"])
    assert args.alpha == [value]
    assert plain_number(text) == value


@pytest.mark.parametrize("text", ["1e3", "1.0", "0x10", "1_000", "٣", ""])
def test_an_integer_option_reads_plain_decimal_integers_only(capsys, tmp_path, text):
    err = one_line(capsys, main(["simulate", "--scenario", "A", "--alpha", "20", "--n-steps", text,
                                 "--out", str(tmp_path / "out")]))
    assert f"argument --n-steps: {text!r} is not allowed; allowed: a plain decimal integer" in err


@pytest.mark.parametrize("text", NOT_PLAIN)
def test_a_csv_cell_reads_plain_decimal_notation_only(tmp_path, text):
    """A CSV cell "２０" was read as 20 (the round-two fix refused "_" alone)."""
    path = tmp_path / "run.csv"
    path.write_text(f"time,normal_force\n0,1\n1,{text}\n2,3\n", encoding="utf-8")
    with pytest.raises(ValueError) as raised:
        me.validate(path, CONTACT, "A", 20.0)
    assert f"line 3, column 'normal_force': {text!r} is not a number; allowed: {PLAIN}" in str(raised.value)


@pytest.mark.parametrize("text", NOT_PLAIN)
def test_a_study_s_limit_reads_plain_decimal_notation_only(tmp_path, text):
    study = tmp_path / "study.toml"
    study.write_text(f'[parameters]\npreset = "paper-R30"\n[phase_diagram]\nscenarios = ["A"]\n'
                     f'[limits]\nsteps = "{text}"\n[output]\ndirectory = "out"\n', encoding="utf-8")
    with pytest.raises(StudyError) as raised:
        load_study(study)
    assert f"[limits] 'steps={text}' is not allowed" in str(raised.value) and PLAIN in str(raised.value)


@pytest.mark.parametrize("text", [*NOT_PLAIN, True])
@pytest.mark.parametrize("read", [me.Contact.from_attrs, me.Parameters.from_attrs])
def test_a_file_s_number_attribute_reads_plain_decimal_notation_only(read, text):
    attrs = {**me.Parameters.paper().to_attrs(), **CONTACT.to_attrs(), "param_E": text}
    with pytest.raises(ValueError, match="the attribute param_E=.* is not allowed; allowed: a number"):
        read(attrs)


def test_a_tabulated_profile_s_attribute_reads_plain_decimal_notation_only():
    profile = me.TabulatedProfile([0.0, 1e-3, 2e-3], [0.0, 1e-6, 4e-6])
    attrs = dict(me.Contact(CONTACT.elastomer, profile, CONTACT.adhesion, CONTACT.friction).to_attrs())
    attrs["profile_table_r"] = "0,1e-3,２e-3"
    with pytest.raises(ValueError, match="profile_table_r=.* is not allowed; allowed: numbers separated by commas"):
        me.Contact.from_attrs(attrs)


# --- N2: symbolic.relation('nope'): a bare KeyError, its message quoted as a key, unlike every other unknown name --
def test_an_unknown_relation_is_named_with_the_allowed_keys():
    from mdr_events.theory import symbolic

    with pytest.raises(ValueError) as raised:
        symbolic.relation("nope")
    assert isinstance(raised.value, KeyError)  # (a look-up by key, as before)
    message = str(raised.value)
    assert message.startswith("key='nope' is not allowed (unknown relation 'nope'); allowed: ")
    assert "jkr_depth" in message and "profile_power_law" in message and "\n" not in message


@pytest.mark.parametrize("key", [None, 3, ["jkr_depth"]])
def test_a_relation_s_key_of_another_type_is_named(key):
    from mdr_events.theory import symbolic

    with pytest.raises(TypeError, match=r"key=.* is not allowed; allowed: a relation's key \(str\)"):
        symbolic.relation(key)


# --- N3: a study with a bad value and nothing to compute said "nothing to compute" -----------------------------------
@pytest.mark.parametrize("tables, words", [
    ('[parameters]\npreset = "paper-R30"\nE = inf\n', "[parameters] Parameters.E=inf is not allowed"),
    ('[parameters]\npreset = "paper-R30"\nnu = 0.7\n', "[parameters] Parameters.nu=0.7 is not allowed"),
    ('[parameters]\npreset = "paper-R30"\n[profile]\nc = -1.0\nn = 2.0\n', "[profile] PowerLaw.c=-1.0 is not allowed"),
    ('[parameters]\npreset = "paper-R30"\n[friction]\nlaw = "coulomb"\nmu = -1.0\n', "[friction] mu=-1.0 is not allowed"),
    ('[parameters]\npreset = "paper-R30"\n[limits]\nsteps = "many"\n', "[limits] 'steps=many' is not allowed"),
    ('[parameters]\npreset = "paper-R30"\n[path]\nwaypoints = [[0, 0]]\n', "[path] waypoints = [[0, 0]] is not allowed"),
])
def test_a_bad_value_is_named_before_what_the_study_lacks(tmp_path, tables, words):
    study = tmp_path / "study.toml"
    study.write_text(tables + '[output]\ndirectory = "out"\n')
    with pytest.raises(ValueError) as raised:
        load_study(study)
    assert words in str(raised.value) and "nothing to compute" not in str(raised.value)
    assert not (tmp_path / "out").exists()


def test_a_study_of_good_values_and_nothing_to_compute_still_says_so(tmp_path):
    study = tmp_path / "study.toml"
    study.write_text('[parameters]\npreset = "paper-R30"\n[output]\ndirectory = "out"\n')
    with pytest.raises(ValueError, match="nothing to compute"):
        load_study(study)


# --- N4: the LAMMPS run's size was not checked: --limit steps=10 ran 10⁴ steps, --dt 5e-324 an internal error --------
@pytest.fixture()
def no_lammps_run(monkeypatch):
    """LAMMPS must not start: the size is refused before."""
    from mdr_events.dem import runner

    def refuse(*args, **kwargs):
        raise AssertionError("LAMMPS was started")

    monkeypatch.setattr(runner, "run_deck", refuse)


FRICTIONLESS = me.Contact(CONTACT.elastomer, CONTACT.indenter, me.Adhesion(0.0, 0.0), me.FrictionLaw("tau0", tau0=0.0))


@pytest.mark.parametrize("kwargs, words", [
    (dict(limits=me.Limits(steps=10)), "the LAMMPS run (10000 steps of dt = 0.119 s) needs 1e+04 discrete time steps"),
    (dict(steps=10**8), "the LAMMPS run (100000000 steps"),
    (dict(dt=1e-9), "needs 1.19e+12 discrete time steps"),
    (dict(steps=2000, limits=me.Limits(memory=1e5)), "the LAMMPS run (2000 steps of dt = 0.596 s) needs"),
])
def test_the_lammps_run_is_checked_against_the_limits_before_it_starts(no_lammps_run, kwargs, words):
    with pytest.raises(me.ResourceLimitError) as raised:
        me.lammps_check(FRICTIONLESS, "A", 20.0, **kwargs)
    assert words in str(raised.value)


@pytest.mark.parametrize("kwargs, words", [
    (dict(dt=5e-324), "dt=5e-324 is not allowed: the path's 1192.14 s would take inf steps; allowed: a time step"),
    (dict(dt=1e-300), "dt=1e-300 is not allowed: the path's 1192.14 s would take 1.19e+303 steps"),
    (dict(steps=10**400), "... is not allowed; allowed: a number of time steps, an integer >= 1 (at most 9e+15)"),
    (dict(limits="big"), "limits='big' (str) is not allowed; allowed: a mdr_events.Limits"),
])
def test_a_lammps_step_beyond_any_count_is_named(no_lammps_run, kwargs, words):
    """dt=5e-324: OverflowError (cannot convert float infinity to integer), exit 3 in the CLI."""
    with pytest.raises((ValueError, TypeError)) as raised:
        me.lammps_check(FRICTIONLESS, "A", 20.0, **kwargs)
    assert words in str(raised.value)


@pytest.mark.parametrize("extra", [["--limit", "steps=10"], ["--dt", "5e-324"], ["--steps", "99999999999"]])
def test_the_cli_refuses_a_lammps_run_too_large_in_one_line(no_lammps_run, tmp_path, capsys, extra):
    status = main(["lammps-check", "--normal", "hertz/material", "--dgamma0", "0", "--dgamma1", "0", "--scenario", "A",
                   "--alpha", "20", *extra, "--out", str(tmp_path / "out")])
    one_line(capsys, status)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


# --- N5: a sweep's grid of range(10**9) was read into an array (8 GB, the process killed) before its size was checked -
@pytest.mark.parametrize("grid", [{"tau0": range(10**9)}, {"tau0": range(1, 10**5), "dgamma1": range(1, 10**5)},
                                  {"tau0": np.zeros(10**9, dtype=np.int8)}])
def test_a_grid_s_size_is_checked_before_its_values_are_read(grid):
    import resource

    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    with pytest.raises(me.ResourceLimitError, match=r"the grid of \d+ runs needs .* GiB of memory"):
        me.sweep(grid, CONTACT, "A", 20.0, output=me.SweepOutput(quantities=("critical_angle_A",)),
                 engine=me.Engine(scheduler="serial"))
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 2**20  # kB: less than 1 GiB more
