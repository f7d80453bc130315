"""The eleventh hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from typing import NamedTuple

import numpy as np
import pytest

import mdr_events as me


# --- L1: Ctrl-C that left code run by exec() of a string (dataclasses builds its methods so, while pandas is imported)
# made CPython note an unhandled KeyboardInterrupt: `python -m mdr_events.app.cli validate ...` printed its one line
# and then died by SIGINT (a parent saw -2, not 130) in about 3 of 20 tries --------------------------------------------
EXECUTED = textwrap.dedent("""
    import signal, sys
    signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a foreground process (a background job ignores it)
    import mdr_events.app.cli.phase_diagram as verb

    def run(args):  # Ctrl-C lands in code that exec() runs from a string, as in a dataclass's generated methods
        exec("import os, signal\\nos.kill(os.getpid(), signal.SIGINT)\\nfor _ in range(10**7):\\n    pass\\n", {})

    verb.run = run
    from mdr_events.app.cli import console_main
    sys.exit(console_main())
""")


def test_an_interrupt_that_left_exec_ends_the_module_run_with_130(tmp_path):
    # (phase-diagram: it checks its parameters before it loads its solvers, ~0.3 s of CPU a start, simulate's ~1.7 s;
    # what is checked is console_main's, every verb's)
    (tmp_path / "interrupted_in_exec.py").write_text(EXECUTED, encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "interrupted_in_exec", "phase-diagram", "--scenario", "A",
                           "--out", "out"], capture_output=True, text=True, timeout=300, cwd=tmp_path,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), *sys.path])))
    assert (done.returncode, done.stderr) == (130, "mdr-events: interrupted (Ctrl-C); no file was left half-written\n")


def _cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "mdr_events.app.cli", *args], capture_output=True, text=True,
                          timeout=300, cwd=cwd)


# --- L2: `sweep --scheduler bogus` (or --workers beyond the cores) beside an existing store reported the store: an
# argument's error comes before the state of the files ------------------------------------------------------------------
SWEEP_STUDY = """[parameters]
preset = "paper-R30"
[sweep]
grid = { tau0 = [30e3, 42e3] }
scenario = "A"
alpha = 20
method = "continuum"
scheduler = "serial"
[output]
directory = "out"
"""


@pytest.mark.parametrize("options, named", [
    (["--scheduler", "bogus"], "scheduler='bogus' is not allowed"),
    (["--scheduler", "ucx://host:8786"], "scheduler='ucx://host:8786' is not allowed"),
    (["--workers", "100000"], "workers=100000 is not allowed"),
    (["--scheduler", "serial", "--workers", "1"], "workers=1 is not allowed with scheduler='serial'"),
])
@pytest.mark.parametrize("store", [True, False], ids=["store", "no-study-file"])
def test_a_sweeps_bad_option_is_named_before_the_files(tmp_path, options, named, store, command):
    study = tmp_path / "s.toml"
    if store:
        study.write_text(SWEEP_STUDY, encoding="utf-8")
        (tmp_path / "out" / "s_sweep.zarr").mkdir(parents=True)  # an earlier sweep's store
    # (in-process: the console script's one-line refusal and exit 2 are checked in a fresh interpreter by the unknown
    # verbs below and tests/app/test_hostile_cli.py; make test's time, issue 28 item 4)
    done = command("sweep", str(study), *options)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert named in done.stderr and "allowed: " in done.stderr


# --- L3: an unknown verb got argparse's words ("argument command: invalid choice: ..."), as did a value not among an
# option's choices ("(choose from 'A', 'B', 'B+')") ---------------------------------------------------------------------
@pytest.mark.parametrize("verb", ["bogus", "simulat", "Simulate", ""])
def test_an_unknown_verb_is_named_with_the_verbs(verb):
    done = _cli(verb, "--out", "o")
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert done.stderr.startswith(f"mdr-events: error: the verb {verb!r} is not allowed; allowed: derive, "
                                  "phase-diagram, simulate, validate, fit, sweep, run, reproduce, lammps-check")
    assert "invalid choice" not in done.stderr and "choose from" not in done.stderr


def test_a_value_not_among_the_choices_lists_them_in_the_packages_words(tmp_path, command):
    done = command("simulate", "--scenario", "C", "--out", str(tmp_path / "o"))
    assert (done.returncode, done.stderr) == (
        2, "mdr-events: error: argument --scenario: invalid choice: 'C'; allowed: A, B, B+\n")


# --- R1: fit_rate_adhesion took its arguments unchecked: params=None, start=None or an Adhesion (AttributeError), a
# start's n below the fit's bound (scipy's "Initial guess is outside of provided bounds"), free='n' (read letter by
# letter), offsets='yes', a masked, complex or bool curve, times outside the path's clock, forces of 1e300 (nan
# intervals), a noise of True, 2e7 samples (ran without a resource check) --------------------------------------------
from mdr_events.analysis.rate_fit import RateMeasurement, fit_rate_adhesion  # noqa: E402
from mdr_events.models.continuum import solve_edge  # noqa: E402

PAPER = me.Parameters.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
VERTICAL = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -200e-6)]), speed=1e-6)
TIMES = np.linspace(VERTICAL.first_contact_time(), VERTICAL.duration, 60)
START = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 3e-6, 0.8)


@pytest.fixture(scope="module")
def edge_run():
    """The law's edge on the vertical path, solved once for the module when its first test runs (not at collection,
    where every worker would pay it: ~0.5 s of CPU)."""
    return solve_edge(PAPER, VERTICAL, LAW)


class Measured(NamedTuple):
    """The curve measured on the vertical path: its forces at :data:`TIMES` and the measurement of them."""

    force: np.ndarray
    curve: RateMeasurement


@pytest.fixture(scope="module")
def measured(edge_run) -> Measured:
    force = edge_run.normal_force(TIMES, VERTICAL)
    return Measured(force, RateMeasurement(VERTICAL, TIMES, force))


@pytest.mark.parametrize("arguments, named", [  # arguments(measured) -> (positional, keywords)
    (lambda m: (([m.curve], None, START), {}), "params=None"),
    (lambda m: (([m.curve], PAPER, None), {}), "start=None"),
    (lambda m: (([m.curve], PAPER, me.Adhesion(0.01, 0.15)), {}), "start=Adhesion"),
    (lambda m: (([m.curve], PAPER, me.RateDependentAdhesion(0.01, 0.15, 1e-6, 1e-4)), {"free": ("n",)}),
     "start.n=0.0001"),
    (lambda m: (([m.curve], PAPER, START), {"free": "n"}), "free='n'"),
    (lambda m: (([m.curve], PAPER, START), {"free": None}), "free=None"),
    (lambda m: (([m.curve], PAPER, START), {"offsets": "yes"}), "offsets='yes'"),
    (lambda m: ((m.curve, PAPER, START), {}), "measurements="),
    (lambda m: (((c for c in [m.curve]), PAPER, START), {}), "measurements="),
    (lambda m: (([RateMeasurement(VERTICAL, ["a", "b"], [1.0, 2.0])], PAPER, START), {}), "measurements[0].times"),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES + 0j, m.force)], PAPER, START), {}), "measurements[0].times"),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES, m.force > 0)], PAPER, START), {}),
     "measurements[0].normal_force"),
    (lambda m: (([RateMeasurement(VERTICAL, np.ma.array(TIMES, mask=TIMES > TIMES[30]), m.force)], PAPER, START), {}),
     "measurements[0].times is a masked array"),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES - 1e6, m.force)], PAPER, START), {}), "measurements[0].times=-"),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES + 1e9, m.force)], PAPER, START), {}), "measurements[0].times="),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES, m.force * 1e300)], PAPER, START), {}),
     "measurements[0].normal_force="),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES, m.force, True)], PAPER, START), {}), "measurements[0].noise=True"),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES, m.force, "0.1")], PAPER, START), {}),
     "measurements[0].noise='0.1'"),
    (lambda m: (([RateMeasurement(VERTICAL, TIMES, m.force, np.ones(3))], PAPER, START), {}),
     "measurements[0].noise="),
    (lambda m: (([RateMeasurement("path", TIMES, m.force)], PAPER, START), {}), "measurements[0].path='path'"),
    (lambda m: (([m.curve], PAPER, START), {"limits": me.Limits(samples=59)}), "samples"),
], ids=lambda value: str(value)[:30] if isinstance(value, str) else "case")
def test_fit_rate_adhesion_names_what_it_cannot_take(measured, arguments, named):
    positional, keywords = arguments(measured)
    with pytest.raises((TypeError, ValueError)) as refused:
        fit_rate_adhesion(*positional, **keywords)
    message = str(refused.value)
    assert "\n" not in message and named in message and "allowed" in message, message


def test_fit_rate_adhesion_checks_the_samples_before_it_runs(monkeypatch):
    import mdr_events.analysis.rate_fit as rate_fit

    monkeypatch.setattr(rate_fit, "solve_edge", lambda *a, **k: pytest.fail("solved before the samples were checked"))
    many = np.linspace(TIMES[0], TIMES[-1], 20_000_001)
    with pytest.raises(me.ResourceLimitError, match="20000001 samples"):
        fit_rate_adhesion([RateMeasurement(VERTICAL, many, np.zeros(many.size))], PAPER, START, free=("n",))


# --- R2: EdgeRun's methods took anything: radius(nan) was 0, normal_force('abc') numpy's words, pull_off_force with
# samples=1 returned 0.0 and with samples=10**12 ran out of memory (MemoryError, 7.3 TiB) ----------------------------
@pytest.mark.parametrize("call, named", [
    (lambda run: run.radius(np.array([np.nan])), "times=nan"),
    (lambda run: run.radius([1.0, np.inf]), "times=inf"),
    (lambda run: run.normal_force("abc", VERTICAL), "times='abc'"),
    (lambda run: run.normal_force(TIMES, "path"), "path='path'"),
    (lambda run: run.pull_off_force(VERTICAL, samples=1), "samples=1"),
    (lambda run: run.pull_off_force(VERTICAL, samples=2.5), "samples=2.5"),
    (lambda run: run.pull_off_force(VERTICAL, samples=10**12), "10^12 samples"),
], ids=["radius-nan", "radius-inf", "force-str", "force-path", "pull-off-1", "pull-off-float", "pull-off-huge"])
def test_an_edge_runs_methods_name_what_they_cannot_take(edge_run, call, named):
    with pytest.raises((TypeError, ValueError)) as refused:
        call(edge_run)
    message = str(refused.value).replace("1000000000000", "10^12")
    assert "\n" not in message and named in message and "allowed" in message, message


# --- R3: the parts' readers of a result's attributes (Adhesion, RateDependentAdhesion, Elastomer, FrictionLaw,
# Parameters .from_attrs, indenter_from_attrs) raised KeyError, AttributeError ('NoneType' object has no attribute
# 'get'), OverflowError (10**400) or Python's words ("argument of type 'NoneType' is not iterable"); Contact.from_attrs
# alone named them ----------------------------------------------------------------------------------------------------
from mdr_events.contact.indenters import indenter_from_attrs  # noqa: E402

READERS = {"Adhesion": me.Adhesion.from_attrs, "RateDependentAdhesion": me.RateDependentAdhesion.from_attrs,
           "Elastomer": me.contact.Elastomer.from_attrs, "FrictionLaw": me.FrictionLaw.from_attrs,
           "indenter": indenter_from_attrs, "Parameters": me.Parameters.from_attrs}
GOOD_ATTRS = {**me.Contact.paper().to_attrs(), "adhesion_law": "rate_dependent", "adhesion_v_ref": 1e-6,
              "adhesion_n": 0.6, "param_d_max": 3e-4, "param_v": 1e-6}


@pytest.mark.parametrize("reader", READERS, ids=str)
@pytest.mark.parametrize("attrs, kind", [
    (None, TypeError), ([1], TypeError), ("param_E", TypeError), ({}, ValueError),
    ({key: 10**400 if isinstance(value, float) else value for key, value in GOOD_ATTRS.items()}, ValueError),
    ({key: None if isinstance(value, float) else value for key, value in GOOD_ATTRS.items()}, ValueError),
], ids=["None", "list", "str", "empty", "overflow", "None-values"])
def test_every_reader_of_attributes_names_what_it_cannot_read(reader, attrs, kind):
    assert READERS[reader](GOOD_ATTRS) is not None
    with pytest.raises(kind) as refused:
        READERS[reader](attrs)
    assert type(refused.value) is kind  # (not KeyError, a subclass of neither, nor a bare OverflowError)
    message = str(refused.value)
    assert "\n" not in message and "attr" in message and "allowed: " in message, message


# --- R4: phase_diagram's refusal of an empty or 2-D alpha said "alpha must be ..., got shape (0,)": not what is allowed
@pytest.mark.parametrize("alpha", [[], np.full((2, 2), 20.0)], ids=["empty", "2-D"])
def test_phase_diagram_names_the_angles_it_takes(alpha):
    with pytest.raises(ValueError) as refused:
        me.phase_diagram(me.Contact.paper(), alpha=alpha)
    message = str(refused.value)
    assert "\n" not in message and "alpha of shape" in message
    assert "allowed: a non-empty 1-D array of angles in degrees" in message


# --- R5: fit with six free values stepped far out: exp() of the log-scaled trial overflowed before the model was asked
# (exit 3, "internal error (OverflowError: math range error)"); a trial out of range is refused, named with its values
def test_a_fit_that_steps_out_of_the_double_range_is_refused_in_one_line(tmp_path, command):
    contact = me.Contact.paper().replace(tau0=30e3)
    run = me.simulate(contact, me.Scenario("A", 20), "continuum").isel(alpha=0)
    table = run[["normal_force", "tangential_force"]].to_dataframe().reset_index()
    table[["time", "normal_force", "tangential_force"]].to_csv(tmp_path / "measured.csv", index=False)
    done = command("fit", str(tmp_path / "measured.csv"), "--scenario", "A", "--alpha", "20", "--out",
                   str(tmp_path / "o"), "--free", "E", "nu", "R", "tau0", "dgamma0", "dgamma1")  # (in-process: the
    # console script's own one line is test_an_unknown_verb_is_named_with_the_verbs's)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "the fit tried E=inf" in done.stderr and "allowed: " in done.stderr and "np.float64" not in done.stderr


def test_an_overflowing_trial_is_inf_not_an_overflow_error():
    from mdr_events.analysis.fit_parameters import _exp

    assert _exp(1e6) == float("inf") and _exp(0.0) == 1.0
