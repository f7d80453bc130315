"""Ctrl-C and SIGTERM while the console script imports the command line (issue 32's leftover of round twenty).

The command line's module took ~0.2 s to import on a loaded machine before :func:`mdr_events.app.cli.main` installed
its handlers: a Ctrl-C then printed Python's traceback and exited with 1. The script's entry point (pyproject's
``[project.scripts]``) installs them first. Each test runs the entry point as pip's script does (``from <module>
import <function>; sys.exit(<function>())``) in a fresh interpreter whose import of ``mdr_events.app.cli`` is held
(a finder on ``sys.meta_path`` that says so on stdout, then sleeps), signals it there and reads what it printed.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: Seconds the held import sleeps: the signal arrives well within it (it is sent once the finder has said so), and
#: ends the process at once; where it is ignored the process waits this long.
HELD = 20.0
#: The hold where the signal is ignored: the signal is sent as soon as the finder has said so, and its (ignored)
#: delivery is immediate; the command then runs.
HELD_IGNORED = 2.0

SCRIPT = textwrap.dedent("""
    import os, signal, sys, time
    if sys.argv.pop(1) == "foreground":
        signal.signal(signal.SIGINT, signal.default_int_handler)  # (a test run in the background inherits SIG_IGN)
    module, function, held = sys.argv.pop(1), sys.argv.pop(1), float(sys.argv.pop(1))

    class Held:  # the command line's import, held: the window a Ctrl-C at start-up lands in
        def find_spec(self, name, path=None, target=None):
            if name == "mdr_events.app.cli":
                sys.meta_path.remove(self)
                os.write(1, b"importing\\n")
                time.sleep(held)
            return None

    sys.meta_path.insert(0, Held())
    entry = getattr(__import__(module, fromlist=[function]), function)
    sys.exit(entry())
""")


def _entry_point() -> tuple[str, str]:
    """The console script's module and function, as pyproject.toml names them."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    module, function = project["scripts"]["mdr-events"].split(":")
    return module, function


def _signalled_at_start_up(signum: int, tmp_path: Path, *, sigint: str = "foreground",
                           held: float = HELD) -> subprocess.CompletedProcess:
    """Start the entry point on ``--version``, wait for the held import, send ``signum``; the process's outcome."""
    module, function = _entry_point()
    process = subprocess.Popen([sys.executable, "-c", SCRIPT, sigint, module, function, str(held), "--version"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp_path,
                               env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)),
                               preexec_fn=(lambda: signal.signal(signal.SIGINT, signal.SIG_IGN))
                               if sigint == "background" else None)
    try:
        assert process.stdout.readline() == "importing\n"
        process.send_signal(signum)
        out, err = process.communicate(timeout=HELD + 60)
    finally:
        process.kill()
    return subprocess.CompletedProcess(process.args, process.returncode, out, err)


@pytest.mark.parametrize("signum, line", [
    (signal.SIGINT, "mdr-events: interrupted (Ctrl-C); no file was left half-written\n"),
    (signal.SIGTERM, "mdr-events: terminated (SIGTERM); no file was left half-written\n"),
])
def test_a_signal_while_the_command_line_is_imported_ends_it_in_one_line(tmp_path, signum, line):
    """The command line's one line and status (``128 + signal``: 130, 143), not a traceback (before: Ctrl-C printed
    ``KeyboardInterrupt``'s traceback and exited with 1; SIGTERM killed it silently, -15)."""
    done = _signalled_at_start_up(signum, tmp_path)
    assert (done.returncode, done.stderr, done.stdout) == (128 + signum, line, ""), done.stderr[-2000:]


def test_a_background_job_ignores_ctrl_c_at_start_up(tmp_path):
    """SIGINT ignored (a background job) stays ignored: the command runs (here ``--version``) once the import ends."""
    done = _signalled_at_start_up(signal.SIGINT, tmp_path, sigint="background", held=HELD_IGNORED)
    assert (done.returncode, done.stderr) == (0, ""), done.stderr[-2000:]
    assert done.stdout.startswith("mdr_events "), done.stdout


def test_the_entry_point_of_before_still_runs(tmp_path):
    """``mdr_events.app.cli:console_main``, which installed environments' scripts name, runs a command as before (here
    to its one line of bad input; ``phase-diagram`` checks its parameters before it loads its solvers: ~0.3 s of CPU,
    ``simulate``'s ~1.9 s)."""
    done = subprocess.run([sys.executable, "-c", "import sys; from mdr_events.app.cli import console_main; "
                           "sys.exit(console_main())", "phase-diagram", "--scenario", "A", "--E", "-1",
                           "--out", "o"], capture_output=True, text=True, cwd=tmp_path,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)), timeout=300)
    assert (done.returncode, done.stdout) == (2, ""), done.stderr[-2000:]
    assert done.stderr == "mdr-events: error: Parameters.E=-1.0 is not allowed; allowed: a finite number > 0 (Pa)\n"


#: What may be imported before the handlers are installed, besides the package's ``__init__`` and the entry point's
#: module: the standard library's small modules they need. ``typing`` and ``re`` (two thirds of the package's import,
#: ~10 ms unloaded, ~0.1 s on a loaded machine) and the command line itself are not among them.
NOT_BEFORE_THE_HANDLERS = ("typing", "re", "mdr_events.app.cli", "numpy")


def test_the_handlers_come_before_anything_heavy():
    """Round twenty-one: a Ctrl-C 0.12 s after the start of a loaded machine's ``mdr-events validate`` landed in
    ``typing``'s import of ``re`` by the package's ``__init__``, before the entry point's module had run: a traceback.
    Importing the entry point's module (the package's ``__init__`` first) loads none of them."""
    module, _ = _entry_point()
    done = subprocess.run([sys.executable, "-c", "import sys; before = set(sys.modules); import " + module +
                           "; print(' '.join(sorted(set(sys.modules) - before)))"], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)), timeout=300)
    loaded = done.stdout.split()
    assert done.returncode == 0 and module in loaded, done.stderr[-2000:]
    assert not [name for name in NOT_BEFORE_THE_HANDLERS if name in loaded], loaded
