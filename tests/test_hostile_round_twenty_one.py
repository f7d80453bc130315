"""The twenty-first hostile round (issue 32): each class of what failed, with the cases that showed it.

The round's cases (the continuum's closed-form and quadrature spans at extreme ``R``, ``E``, angles, ``d_max``,
speeds, ``τ0`` and adhesion; Ferrari's radii at extreme scales and paths to the pull-off fold; the flat punch on a
layer in both methods; Coulomb's law spring by spring on a layer; the rate law's extrema and its LSODA runner's
fallback; the heartbeat; readers with non-finite, Unicode and BOM/CRLF cells; study files; resource guards;
interrupts at start-up and later, with Ctrl-C ignored too) are listed with their outcomes in the issue's closing note;
what failed is below. The console script's start-up (a Ctrl-C while the command line is imported) is tested in
``tests/app/test_console_start_up.py``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import cli_one_line, one_line_naming
from mdr_events.validation import MAX_COUNT

PAPER = me.Parameters.paper()
#: No resource limit: the time step's own bound is what refuses it.
UNLIMITED = me.Limits(steps=np.inf, samples=np.inf, memory=np.inf)


# --- U1: a time step whose count of steps is beyond the doubles' integers: `simulate --method discrete --dt 5e-324`
# exited 3, "internal error (OverflowError: cannot convert float infinity to integer)" (int(inf) in the time grid's
# size, before the limits were checked); with the limits off, `--dt 1e-18` reached NumPy's arange of 1e21 samples ---


@pytest.mark.parametrize("dt, limits", [("5e-324", []), ("1e-18", ["--limit", "steps=inf", "--limit", "samples=inf",
                                                                     "--limit", "memory=inf"])])
def test_a_time_step_too_small_to_count_is_refused_naming_it(capsys, tmp_path, dt, limits):
    err = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", "--method", "discrete", "--dx", "2e-6",
                                "--dt", dt, *limits, "--out", str(tmp_path / "o")])
    assert f"dt={float(dt)!r} is not allowed" in err and "allowed: a time step in s >=" in err, err


@pytest.mark.parametrize("dt", [1e-300, 1e-18])
def test_without_limits_the_steps_count_bounds_the_time_step(dt):
    contact = me.Contact.from_parameters(PAPER)
    method = me.Discrete(dx=2e-6, dt=dt)
    message = one_line_naming(lambda: me.simulate(contact, me.Scenario("A", (20.0,)), method=method, limits=UNLIMITED),
                              f"dt={dt!r}")
    longest = float(message.split("case's ")[1].split(" s")[0])
    least = float(message.split("allowed: a time step in s >= ")[1].split(" ")[0])
    assert least == pytest.approx(longest / MAX_COUNT, rel=1e-2), message  # (the least dt, printed to 3 digits)


# --- U2: an option after `--`: `fit --free tau0 -- run.csv --out o` (the usual way to end a multi-value option) said
# "the following arguments are required: --out" although --out was given: every word after `--` is a file to
# argparse. The message says so, and how to write it --------------------------------------------------------------


@pytest.mark.parametrize("argv, option", [
    (["fit", "--scenario", "A", "--alpha", "20", "--free", "tau0", "--", "{run}", "--out", "{out}"], "--out"),
    (["validate", "--scenario", "A", "--alpha", "20", "--dx", "1e-6", "2e-6", "--", "{run}", "--out={out}"], "--out"),
    (["fit", "{run}", "--scenario", "A", "--alpha", "20", "--out", "{out}", "--free", "tau0", "--", "--E", "1e6"],
     "--E"),
])
def test_an_option_after_the_separator_is_named(capsys, tmp_path, argv, option):
    run = tmp_path / "run.csv"
    run.write_text("time,normal_force\n0,0\n1,1e-3\n2,0\n")
    err = cli_one_line(capsys, [word.format(run=run, out=tmp_path / "o") for word in argv])
    assert f"({option} comes after `--`, which ends the options" in err and "before `--`" in err, err


def test_a_file_taken_by_a_multi_value_option_is_still_named(capsys, tmp_path):
    """The hint of round twenty (a file among ``--free``'s values) stays, with or without a separator after it."""
    run = tmp_path / "run.csv"
    run.write_text("time,normal_force\n0,0\n1,1e-3\n2,0\n")
    for tail in ([], ["--"]):
        err = cli_one_line(capsys, ["fit", "--free", "tau0", str(run), "--scenario", "A", "--alpha", "20", "--out",
                                    str(tmp_path / "o"), *tail])
        assert f"--free took {str(run)!r}, a file" in err, err


# --- U3: a grid counted against the limits after it was read: `phase_diagram(params, 1e8 angles)` copied and sorted
# the angles (validate_alpha, check_distinct) before its limits refused them: 4.9 GB peak and a minute against the
# 2 GiB limit; the layer's curves and the critical angles against thickness read their depths or thicknesses first
# too, and cross_check its angles (1e7: 1.4 GB). Now each counts its grid (limits.values_in) before reading it -----

#: Values in the grid: far beyond the limits below, and a copy of them (8 bytes each, 8 MB) well above what the
#: refusal itself allocates (a message and the limits: kilobytes).
GRID = 10**6
#: The least a reading of the grid allocates: one float per value (the conversion's copy; the sort needs more).
ONE_COPY = 8 * GRID
LOW = me.Limits(samples=10, steps=10, memory=2**20)


def _layered():
    return me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.Paraboloid(PAPER.R),
                      me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                      me.FrictionLaw("tau0", tau0=PAPER.tau0), me.Layer(5e-3))


#: Each entry point, given the contact on a layer and its grid (angles in degrees, depths or thicknesses in m).
CALLS = {
    "phase_diagram": lambda contact, grid: me.phase_diagram(PAPER, grid, limits=LOW),
    "phase_diagram on a layer": lambda contact, grid: me.phase_diagram(contact, grid, limits=LOW),
    "layer_normal_curve": lambda contact, grid: me.layer_normal_curve(contact, grid, limits=LOW),
    "layer_pull_off_curve": lambda contact, grid: me.layer_pull_off_curve(contact, grid, limits=LOW),
    "critical_angles_against_thickness": lambda contact, grid: me.critical_angles_against_thickness(contact, grid,
                                                                                                    limits=LOW),
    # (no limits of its own: its runs' defaults, 2001 samples a case, refuse 5000 angles)
    "cross_check": lambda contact, grid: me.cross_check(me.Contact.from_parameters(PAPER), "A", alpha=grid),
}
#: The least grid each refuses (a first call imports what the entry point needs before the measurement).
BEYOND = {"cross_check": 10**4}
#: Each entry point's grid of ``n`` distinct values within its range.
GRIDS = {"phase_diagram": lambda n: np.linspace(1.0, 80.0, n), "cross_check": lambda n: np.linspace(1.0, 80.0, n),
         "phase_diagram on a layer": lambda n: np.linspace(1.0, 80.0, n),
         "layer_normal_curve": lambda n: np.linspace(0.0, 1e-4, n)}
THICKNESSES = lambda n: np.linspace(1e-3, 1e-2, n)  # noqa: E731


@pytest.mark.parametrize("entry", list(CALLS))
def test_a_grid_is_counted_before_it_is_read(entry):
    """Each refuses a grid of distinct values beyond its limits before it allocates a copy of it (before: the copy
    and the sort of check_distinct, 8 bytes and more per value)."""
    import tracemalloc

    contact, grid = _layered(), GRIDS.get(entry, THICKNESSES)  # (made before the measurement)
    with pytest.raises(me.ResourceLimitError):  # (a grid just beyond the limits first: the modules it imports)
        CALLS[entry](contact, grid(BEYOND.get(entry, 11)))
    values = grid(GRID)
    tracemalloc.start()
    try:
        with pytest.raises(me.ResourceLimitError) as caught:
            CALLS[entry](contact, values)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert f"{GRID}" in str(caught.value), str(caught.value)
    assert peak < ONE_COPY, f"{entry}: {peak / 2**20:.1f} MiB allocated before the refusal"


# --- U4: a command started with stderr closed (`mdr-events ... 2>&-`): Python's sys.stderr is None, and print(...,
# file=None) writes to stdout, which holds the files written: the error line, the heartbeat's and the interrupt's went
# there, and after SIGTERM console_main's sys.stderr.flush() raised AttributeError: exit 1, not 143 --------------

TERMINATED_IN_RUN = textwrap.dedent("""
    import os, signal, sys
    import mdr_events.app.cli.phase_diagram as verb

    def run(args):  # SIGTERM while the command runs, before it writes anything
        os.kill(os.getpid(), signal.SIGTERM)
        for _ in range(10**6):
            pass

    verb.run = run
    from mdr_events.app.console import console_main
    sys.exit(console_main())
""")


@pytest.mark.parametrize("case", ["bad input", "terminated"])
def test_without_stderr_nothing_of_its_goes_to_stdout(tmp_path, case):
    # (phase-diagram: a verb that checks its parameters before it loads its solvers, ~0.3 s of CPU a run; simulate's
    # ~1.7 s; what is checked is console_main's, the same for every verb)
    argv = {"bad input": ["-c", "import sys; from mdr_events.app.console import console_main; sys.exit(console_main())",
                          "phase-diagram", "--scenario", "A", "--E", "-1", "--out", "out"],
            "terminated": ["-c", TERMINATED_IN_RUN, "phase-diagram", "--scenario", "A", "--out", "out"]}
    done = subprocess.run([sys.executable, *argv[case]], stdout=subprocess.PIPE, cwd=tmp_path, timeout=300,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)),
                          preexec_fn=lambda: os.close(2))  # (as `2>&-`)
    assert (done.returncode, done.stdout) == ({"bad input": 2, "terminated": 143}[case], b""), done.stdout
