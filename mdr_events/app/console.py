"""The console script ``mdr-events``: Ctrl-C and SIGTERM answered from the start, the command line's import included.

pip's script for ``mdr-events`` imports the module of its entry point, then calls it. The command line's module
(:mod:`mdr_events.app.cli` and its verbs' parsers) takes about 50 ms to import, several times that on a loaded
machine, and its :func:`~mdr_events.app.cli.main` installs its handlers of Ctrl-C and SIGTERM only when it runs: a
Ctrl-C during that import printed Python's traceback (a ``KeyboardInterrupt`` in some module of the CLI) and exited
with 1. This module imports the standard library alone; :func:`console_main` installs, before it imports the CLI,
handlers that end the process as :func:`~mdr_events.app.cli.main` ends an interrupted command (its one line,
:data:`INTERRUPTED_LINES`, and the status ``128 + signal``: 130 or 143) — nothing is written yet, so there is nothing
to clean up. A Ctrl-C ignored (a background job) stays ignored. ``mdr_events.app.cli:console_main``, which installed
environments' scripts still name, works as before.

What runs before the handlers is the interpreter's own start-up, the package's ``__init__`` (kept to the standard
library's small modules: no ``typing``, no ``re``) and this module: about 9 ms of imports unloaded, where the CLI's
import took 50 ms more (``tests/app/test_console_start_up.py``).
"""

from __future__ import annotations

import os
import signal
import sys

__all__ = ["console_main", "INTERRUPTED_LINES"]

#: The line an interrupted command ends with (after ``mdr-events:`` and a space), by signal: the command line's, from
#: start-up on.
INTERRUPTED_LINES = {
    signal.SIGINT: "interrupted (Ctrl-C); no file was left half-written",
    signal.SIGTERM: "terminated (SIGTERM); no file was left half-written",
}


def _end_during_start_up(signum: int, frame) -> None:
    """A signal before the command runs: its line on stderr (written directly, unbuffered) and the status
    ``128 + signum``, at once (no ``KeyboardInterrupt`` that an importing module could catch or print)."""
    if sys.stderr is not None:  # (started with stderr closed, 2>&-: descriptor 2 may be another file's by now)
        try:
            os.write(2, f"mdr-events: {INTERRUPTED_LINES[signum]}\n".encode())
        except OSError:  # (the status says it)
            pass
    os._exit(128 + signum)  # noqa: SLF001 - nothing to flush or clean up before the command has run


def console_main() -> int:
    """The console script ``mdr-events``: :func:`mdr_events.app.cli.console_main`, with Ctrl-C and SIGTERM handled
    while the command line is imported.

    Returns
    -------
    int
        The exit status (:data:`mdr_events.app.cli.EXIT_STATUSES`).
    """
    answered = [signum for signum, default in ((signal.SIGINT, signal.default_int_handler),
                                               (signal.SIGTERM, signal.SIG_DFL)) if signal.getsignal(signum) is default]
    previous = {signum: signal.signal(signum, _end_during_start_up) for signum in answered}
    from mdr_events.app.cli import console_main as run_command

    try:
        for signum, handler in previous.items():  # main() installs its own from these, as when called directly
            signal.signal(signum, handler)
        return run_command()
    except KeyboardInterrupt:  # between the two handlers (main() catches every one once it runs)
        _end_during_start_up(signal.SIGINT, None)
        raise  # (not reached: the line above ends the process)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(console_main())
