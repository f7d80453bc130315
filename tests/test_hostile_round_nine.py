"""The ninth hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap

import pytest

# --- R1: Ctrl-C (or SIGTERM) that lands while the garbage collector runs Python code ------------------------------
SWALLOWED = textwrap.dedent("""
    import os, signal, sys
    import mdr_events.app.cli.simulate as verb
    real, when, signum = verb.run, sys.argv.pop(1), getattr(signal, sys.argv.pop(1))

    class Collected:  # the signal handler runs inside __del__ (as in a WeakSet's callback): the interpreter swallows it
        def __del__(self):
            os.kill(os.getpid(), signum)
            for _ in range(1000):
                pass

    def run(args):
        if when == "before":
            Collected()
        real(args)
        if when == "after":
            Collected()

    verb.run = run
    from mdr_events.app.cli import console_main
    sys.exit(console_main())
""")


@pytest.mark.parametrize("name, status, line", [
    ("SIGINT", 130, "mdr-events: interrupted (Ctrl-C); no file was left half-written\n"),
    ("SIGTERM", 143, "mdr-events: terminated (SIGTERM); no file was left half-written\n")])
@pytest.mark.parametrize("when", ["before", "after"])
def test_an_interrupt_swallowed_by_garbage_collection_ends_the_command(tmp_path, when, name, status, line):
    """Round eight: Ctrl-C at the end of a run landed in a WeakSet's callback; Python printed four lines "Exception
    ignored in ... KeyboardInterrupt" and the command exited 0. Now: one line and the interrupt's status, before the
    run (nothing written) as after it (every file whole)."""
    done = subprocess.run([sys.executable, "-c", SWALLOWED, when, name, "simulate", "--scenario", "A", "--alpha", "20",
                           "--out", "out"], capture_output=True, text=True, timeout=300, cwd=tmp_path,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert (done.returncode, done.stderr) == (status, line)
    written = sorted(os.listdir(tmp_path / "out")) if (tmp_path / "out").exists() else []
    assert written == ([] if when == "before" else ["simulation_A_discrete.nc", "simulation_A_discrete.png"])
