"""What every hostile round asserts of a refusal, written once (imported by the rounds' modules in tests/): the API's
one line naming the argument and what is allowed, with no warning before it, and the CLI's one line on stderr with
exit status 2; and the cases more than one round builds (a depth that reaches a contact radius on a layer)."""

from __future__ import annotations

import math
import signal
import time
import tracemalloc
import warnings

import pytest

import mdr_events as me
from mdr_events.app.cli import main

#: Halvings of the depth's bracket: 24 take a bracket of 1e-4 m to 6e-12 m, where the radius (some 20 m per m of
#: depth near the tables' end of a 0.1 mm layer) moves by ~1e-10 m, 2e-8 of it: the callers' radius 0.1 % inside
#: the tables' last and their spacing of 1 % of it are untouched (measured: 2e-9 of the target below it). Each
#: halving is one curve of the layer (~30 ms); 40, to a float's spacing, cost 0.5 s more a caller for nothing.
DEPTH_HALVINGS = 24
#: How far below its target the radius found may lie, relative: far inside the callers' 0.1 % margin and 1 % spacing,
#: far above the 2e-8 the halvings reach (checked on each depth found: one curve more).
RADIUS_SHARE = 1e-6


def one_line_naming(call, named: str, errors=(ValueError, TypeError)) -> str:
    """The message of what ``call`` raises with every warning an error: one line, naming ``named`` and what is
    allowed, and no warning before it."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(errors) as caught:
            call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message, message
    return message


def cli_one_line(capsys, argv: list[str]) -> str:
    """The one line ``mdr-events argv`` prints on stderr, exiting 2."""
    status = main(argv)
    err = capsys.readouterr().err
    assert status == 2 and err.count("\n") == 1 and err.startswith("mdr-events: error:"), (status, err)
    return err


def depth_reaching(contact, target: float, low: float, high: float) -> float:
    """The depth (m, the bracket's low end) whose contact radius on the layer's Δγ0 branch reaches ``target`` from
    below, by bisection of ``[low, high]`` (a depth beyond the layer's tables counts as an infinite radius)."""
    for _ in range(DEPTH_HALVINGS):
        middle = 0.5 * (low + high)
        try:
            radius = float(me.layer_normal_curve(contact, [middle])["contact_radius"].sel(branch="dgamma0")[0])
        except ValueError:  # (beyond the tables)
            radius = math.inf
        low, high = (middle, high) if radius < target else (low, middle)
    found = float(me.layer_normal_curve(contact, [low])["contact_radius"].sel(branch="dgamma0")[0])
    assert (1.0 - RADIUS_SHARE) * target <= found < target, (low, found, target)
    return low


def peak_of(call) -> int:
    """The peak of what ``call`` allocates (bytes, tracemalloc), whatever it raises (checked by the caller)."""
    tracemalloc.start()
    try:
        call()
    finally:
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
    return peak


def refused_for_resources(call) -> int:
    """The peak of ``call`` refused for its resources (``ResourceLimitError``), traced the second time (the first
    imports what it uses)."""
    def refused():
        with pytest.raises(me.ResourceLimitError):
            call()
    refused()
    return peak_of(refused)


class OverBudget(Exception):
    """A call took more CPU time than its budget (:func:`cpu_limited`)."""


def cpu_limited(call, budget: float | None):
    """``call()``'s result and the CPU time it took (s), stopped with :class:`OverBudget` past ``budget`` s of CPU
    (``None``: no budget): a run that takes minutes fails in its budget's time, not the suite's. The time taken is
    checked against the budget as well, so that a call which swallows the signal's exception (an ``except Exception``
    where the timer fires, such as the package's cache readers) fails all the same once it returns. So does a call that
    ends just past its budget, before the profiling timer's signal arrives (its resolution is a few ms): it passed
    before this check and fails now; give a budget a margin over the time the call needs."""
    def over(signum, frame):
        raise OverBudget(f"over {budget} s of CPU")

    previous = signal.signal(signal.SIGPROF, over)
    signal.setitimer(signal.ITIMER_PROF, budget or 0.0)
    start = time.process_time()
    try:
        result = call()
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0.0)
        signal.signal(signal.SIGPROF, previous)
    taken = time.process_time() - start
    if budget is not None and taken > budget:
        raise OverBudget(f"{taken:.3g} s of CPU, over {budget} s (the call swallowed the timer's signal or ended "
                         "before it arrived)")
    return result, taken
