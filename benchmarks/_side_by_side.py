"""Side-by-side timing of checkouts: each checkout's package runs in a worker process of its own (its root first on
``PYTHONPATH``) and the repetitions alternate between the workers, so that all see the same load of a shared machine.

A benchmark script that uses it answers ``--worker`` by calling :func:`serve` with its tasks (name -> function).
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time


def serve(tasks: dict[str, callable]) -> None:
    """Time the tasks named on standard input, one per line, printing each time (s)."""
    print("ready", flush=True)
    for line in sys.stdin:
        start = time.perf_counter()
        tasks[line.strip()]()
        print(time.perf_counter() - start, flush=True)


class Checkout:
    """A worker process (``script --worker``) timing the package of the checkout ``root``."""

    def __init__(self, root: str, script: str):
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join([root, *filter(None, [env.get("PYTHONPATH")])])
        self.process = subprocess.Popen([sys.executable, script, "--worker"], env=env, cwd=root, text=True,
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        assert self.process.stdout.readline().strip() == "ready"

    def time(self, task: str) -> float:
        self.process.stdin.write(task + "\n")
        self.process.stdin.flush()
        return float(self.process.stdout.readline())

    def close(self) -> None:
        self.process.stdin.close()
        self.process.wait()


def measure(roots: list[str], script: str, tasks: list[str], repeat: int) -> list[dict[str, float]]:
    """The median time of every task in each checkout of ``roots``, the repetitions alternating between them."""
    checkouts = [Checkout(root, script) for root in roots]
    try:
        times = [{task: [] for task in tasks} for _ in checkouts]
        for _ in range(repeat):
            for task in tasks:
                for checkout, found in zip(checkouts, times):
                    found[task].append(checkout.time(task))
    finally:
        for checkout in checkouts:
            checkout.close()
    return [{task: statistics.median(values) for task, values in found.items()} for found in times]
