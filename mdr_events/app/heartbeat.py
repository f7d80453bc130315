"""A line now and then while a long computation runs that reports nothing of its own (round twenty).

``simulate`` and ``phase-diagram`` compute for seconds on most inputs but for a minute or more on some (Coulomb's law
spring by spring under the rate law or on a layer, the rate law's critical angles of scenario B at speeds), and said
nothing until their files were written: a user could not tell a long run from a hung one. :func:`heartbeat` reports,
through the job's ``progress`` (the command line's stderr, a study's progress), that the computation still runs,
first after :data:`FIRST_AFTER` seconds of computing and then every :data:`EVERY` seconds; a run shorter than that
prints nothing. The seconds are the process's CPU time (the line says the wall time): a quick run waiting for a core
on a shared machine is not a long run, and what a quick run prints does not depend on the machine's load.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

__all__ = ["heartbeat", "FIRST_AFTER", "EVERY"]

#: Seconds of silence before the first line: longer than the quick runs (about a second each), short enough that a
#: user waiting for a minute-long run is told it is running before wondering.
FIRST_AFTER = 10.0
#: Seconds between the lines after the first.
EVERY = 30.0
#: Seconds (wall) between the thread's looks at the process's CPU time.
POLL = 0.5


@contextmanager
def heartbeat(progress: Callable[[str], None], what: str) -> Iterator[None]:
    """Within the ``with`` block, ``progress("<what>: still running after N s ...")`` from a daemon thread, first after
    :data:`FIRST_AFTER` seconds of the process's CPU time and then every :data:`EVERY` seconds, until the block ends
    (normally or not).

    Parameters
    ----------
    progress : callable
        Takes one line.
    what : str
        What runs, e.g. ``"simulate (scenario A, 3 case(s), continuum method)"``.

    Yields
    ------
    None
    """
    stop = threading.Event()
    start, cpu_start = time.monotonic(), time.process_time()
    first, every = FIRST_AFTER, EVERY  # (read when called: a test shortens them)

    def beat() -> None:
        due = first
        while not stop.wait(min(POLL, max(due - (time.process_time() - cpu_start), 0.0))):
            if time.process_time() - cpu_start >= due:
                progress(f"{what}: still running after {time.monotonic() - start:.0f} s (Ctrl-C stops it; the files "
                         "are written when it ends)")
                due += every

    thread = threading.Thread(target=beat, name="mdr-events heartbeat", daemon=True)
    thread.start()
    try:
        yield
    finally:
        stop.set()
        thread.join()
