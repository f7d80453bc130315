"""Side-by-side timing of checkouts: each checkout's package runs in a worker process of its own (its root first on
``PYTHONPATH``) and the repetitions alternate between the workers, so that all see the same load of a shared machine.

A benchmark script that uses it answers ``--worker`` by calling :func:`serve` with its tasks (name -> function), and
``--worker --cpu`` by timing them in the process's CPU time instead of the wall clock: on a machine other work shares,
the CPU time a task takes is what compares (the wall clock counts the time the process waited for a core).
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time
from typing import Callable


class Staged:
    """A task timed after an untimed preparation: ``run(*prepare())``, only ``run`` timed by :func:`serve` (e.g. a
    part of a pipeline timed on what the step before it has just made, with the caches as that step leaves them).
    Called, it does both."""

    def __init__(self, prepare: Callable[[], tuple], run: Callable[..., object]) -> None:
        self.prepare, self.run = prepare, run

    def __call__(self) -> object:
        return self.run(*self.prepare())


def serve(tasks: dict[str, callable], cpu: bool = False) -> None:
    """Time the tasks named on standard input, one per line, printing each time (s): wall clock, or the process's CPU
    time with ``cpu``; of a :class:`Staged` task its ``run`` alone, after its ``prepare``."""
    clock = time.process_time if cpu else time.perf_counter
    print("ready", flush=True)
    for line in sys.stdin:
        task = tasks[line.strip()]
        arguments, task = (task.prepare(), task.run) if isinstance(task, Staged) else ((), task)
        start = clock()
        task(*arguments)
        print(clock() - start, flush=True)


def clock_name(cpu: bool) -> str:
    """What the figures are, for a benchmark's heading."""
    return "CPU time" if cpu else "wall time"


def verdict(figure: float, target: float) -> str:
    """``"met"`` where ``figure <= target``, else ``"NOT met"``."""
    return "met" if figure <= target else "NOT met"


class Checkout:
    """A worker process (``script --worker``, with ``--cpu`` for CPU time) timing the package of the checkout
    ``root``."""

    def __init__(self, root: str, script: str, cpu: bool = False):
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join([root, *filter(None, [env.get("PYTHONPATH")])])
        self.process = subprocess.Popen([sys.executable, script, "--worker", *(["--cpu"] if cpu else [])], env=env,
                                        cwd=root, text=True, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        assert self.process.stdout.readline().strip() == "ready"

    def time(self, task: str) -> float:
        self.process.stdin.write(task + "\n")
        self.process.stdin.flush()
        return float(self.process.stdout.readline())

    def close(self) -> None:
        self.process.stdin.close()
        self.process.wait()


def measure(roots: list[str], script: str, tasks: list[str], repeat: int, cpu: bool = False) -> list[dict[str, float]]:
    """The median time of every task in each checkout of ``roots``, the repetitions alternating between them, in an
    order that alternates too (CPU time with ``cpu``)."""
    checkouts = [Checkout(root, script, cpu) for root in roots]
    try:
        times = [{task: [] for task in tasks} for _ in checkouts]
        pairs = list(zip(checkouts, times))
        for repetition in range(repeat):
            for task in tasks:
                # the order alternates: the checkout timed first was 10 % slower on tasks of a millisecond (the same
                # checkout against itself gave extrema 0.9x)
                for checkout, found in (pairs if repetition % 2 == 0 else pairs[::-1]):
                    found[task].append(checkout.time(task))
    finally:
        for checkout in checkouts:
            checkout.close()
    return [{task: statistics.median(values) for task, values in found.items()} for found in times]


def print_ratios(medians: list[dict[str, float]], names, label: str = "{}") -> None:
    """With two checkouts measured (this one, then ``--against``'s), print each task's ratio before / now (two
    decimals), the tasks ``names`` in order, each shown as ``label.format(name)``; with one, nothing."""
    if len(medians) == 2:
        now, before = medians
        print("  ratio before / now: " + ", ".join(f"{label.format(name)} {before[name] / now[name]:.2f}x"
                                                   for name in names))


def command_line(description: str, script: str, tasks: callable, repeat: int):
    """A benchmark's options (``--repeat``, ``--against DIR``, ``--cpu``) and the checkouts they name (label -> root,
    this one first); ``None`` where the process is a worker (``--worker``), which has then served ``tasks()``."""
    import argparse
    from pathlib import Path

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--repeat", type=int, default=repeat, help=f"runs per figure (median; default {repeat})")
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side")
    parser.add_argument("--cpu", action="store_true", help="CPU time instead of the wall clock")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.worker:
        serve(tasks(), options.cpu)
        return None
    roots = {"this checkout": str(Path(script).resolve().parent.parent)}
    if options.against:
        roots[f"--against {options.against}"] = str(Path(options.against).resolve())
    return options, roots
