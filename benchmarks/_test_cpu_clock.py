"""A pytest plugin for ``bench_tests.py``: each test's CPU time (its process's and its waited-for children's: the
console-script tests run subprocesses) and wall time, one JSON line per test, in a file per pytest-xdist worker.

Loaded with ``-p _test_cpu_clock`` (this folder on ``PYTHONPATH``); the files are ``$MDR_TEST_CLOCK_OUT_<worker>.jsonl``.
Each worker's first line, ``"<start>"``, holds the CPU its start-up and collection took; pytest-xdist's controller
(which runs no test: it hands them out and reports them) writes its own CPU in one line, ``"<controller>"``, to
``$MDR_TEST_CLOCK_OUT_controller.jsonl``.
"""

from __future__ import annotations

import json
import os
import time

import pytest

#: The files' prefix, set by bench_tests.py.
OUT_VARIABLE = "MDR_TEST_CLOCK_OUT"


def _cpu() -> float:
    """The process's CPU time and that of its children waited for (s)."""
    used = os.times()
    return used.user + used.system + used.children_user + used.children_system


def _children_cpu() -> float:
    """The CPU time of the process's children waited for (s): the subprocesses a test ran."""
    used = os.times()
    return used.children_user + used.children_system


def _write(record: dict) -> None:
    worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
    with open(f"{os.environ[OUT_VARIABLE]}_{worker}.jsonl", "a", encoding="utf-8") as stream:
        stream.write(json.dumps(record) + "\n")


def pytest_collection_finish(session) -> None:
    """The CPU spent before the first test: the interpreter, pytest's plugins and the collection."""
    _write({"id": "<start>", "cpu": _cpu(), "wall": 0.0})


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    """One test's setup, call and teardown."""
    cpu, children, wall = _cpu(), _children_cpu(), time.perf_counter()
    yield
    _write({"id": item.nodeid, "cpu": _cpu() - cpu, "children": _children_cpu() - children,
            "wall": time.perf_counter() - wall, "end": time.time()})


def pytest_unconfigure(config) -> None:
    """pytest-xdist's controller: its own CPU over the session (its start-up, the workers' reports taken in), without
    its children's (the workers, whose records are their own)."""
    if getattr(config.option, "numprocesses", None) and not hasattr(config, "workerinput"):
        used = os.times()
        with open(f"{os.environ[OUT_VARIABLE]}_controller.jsonl", "a", encoding="utf-8") as stream:
            stream.write(json.dumps({"id": "<controller>", "cpu": used.user + used.system, "wall": 0.0}) + "\n")
