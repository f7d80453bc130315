"""The eleventh hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import mdr_events as me


# --- L1: Ctrl-C that left code run by exec() of a string (dataclasses builds its methods so, while pandas is imported)
# made CPython note an unhandled KeyboardInterrupt: `python -m mdr_events.app.cli validate ...` printed its one line
# and then died by SIGINT (a parent saw -2, not 130) in about 3 of 20 tries --------------------------------------------
EXECUTED = textwrap.dedent("""
    import signal, sys
    signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a foreground process (a background job ignores it)
    import mdr_events.app.cli.simulate as verb

    def run(args):  # Ctrl-C lands in code that exec() runs from a string, as in a dataclass's generated methods
        exec("import os, signal\\nos.kill(os.getpid(), signal.SIGINT)\\nfor _ in range(10**7):\\n    pass\\n", {})

    verb.run = run
    from mdr_events.app.cli import console_main
    sys.exit(console_main())
""")


def test_an_interrupt_that_left_exec_ends_the_module_run_with_130(tmp_path):
    (tmp_path / "interrupted_in_exec.py").write_text(EXECUTED, encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "interrupted_in_exec", "simulate", "--scenario", "A", "--alpha", "20",
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
def test_a_sweeps_bad_option_is_named_before_the_files(tmp_path, options, named, store):
    study = tmp_path / "s.toml"
    if store:
        study.write_text(SWEEP_STUDY, encoding="utf-8")
        (tmp_path / "out" / "s_sweep.zarr").mkdir(parents=True)  # an earlier sweep's store
    done = _cli("sweep", str(study), *options)
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


def test_a_value_not_among_the_choices_lists_them_in_the_packages_words(tmp_path):
    done = _cli("simulate", "--scenario", "C", "--out", str(tmp_path / "o"))
    assert (done.returncode, done.stderr) == (
        2, "mdr-events: error: argument --scenario: invalid choice: 'C'; allowed: A, B, B+\n")
