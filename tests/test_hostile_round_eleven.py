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
