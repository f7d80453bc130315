"""The side-by-side benchmarks' tasks build against this checkout: a worker (``--worker``) builds every task of its
script with :func:`_tasks` before it measures any, reaching into the package's internals (``simulate``'s front end,
its job, the dataset), so a changed signature there broke ``bench_simulate.py`` unseen (round twenty-two's
``simulation_job(..., limits)``); here it fails a test instead. Each task is built, not timed or run again."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"


@pytest.mark.parametrize("script", ["bench_simulate", "bench_evaluate", "bench_phase_diagram",
                                    "bench_coulomb_adhesion"])
def test_a_side_by_side_benchmark_builds_every_task(script, monkeypatch):
    monkeypatch.syspath_prepend(str(BENCHMARKS))
    module = importlib.import_module(script)
    try:
        tasks = module._tasks()
    finally:
        sys.modules.pop(script, None)
    assert tasks and all(callable(task) for task in tasks.values()), sorted(tasks)
