"""Benchmark: the quick round of the tests, ``make test`` (issue 28, item 4), in CPU time.

On a shared machine the wall clock of a test run says more about the others' load than about the tests; the CPU each
test takes does not. This runs the quick round as ``make test`` does (``-n 2 --dist loadscope -m "not slow"``, one
OpenBLAS thread per worker) with a plugin that records each test's CPU time, its process's and its waited-for
subprocesses' (``_test_cpu_clock.py``), and prints:

- the CPU of the whole round, pytest-xdist's controller's included (target: at most 200 s, so that two workers
  finish in under 2 min of a quiet machine's wall clock) and each worker's share, its start-up and collection
  included (target: none over 120 s; pytest-xdist's ``loadscope`` keeps a module on one worker, so one long module
  caps the wall time);
- the CPU of ``pytest --collect-only -q`` alone, which every worker pays before its first test;
- the slowest modules and tests (the candidates for a cheaper test or the ``slow`` mark);
- what the round computed afresh: the bytecode the collection wrote and the files it added to the package's caches on
  disk (derived relations, layer tables). A new checkout, a new machine or an edit to the sources the caches are keyed
  by pays them once, in whichever tests come first (measured on a fresh, loaded 2-core machine: the round 529 s of
  CPU cold against 497 s warm, ``mdr-events derive | head -1``'s test 19.8 s against 1.4 s, the collection alone
  47 s against 6 s): such a round's figures are not a warm ``make test``'s, run it again for those.

Run: ``python benchmarks/bench_tests.py [--workers N] [--dist MODE] [--top N] [--keep FILE] [-- PYTEST_ARGS...]`` from the clone's root (the
arguments after ``--`` replace the test selection, e.g. ``-- tests/theory``).
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: Targets of issue 28, item 4 (s of CPU): the quick round's total, one worker's share.
TOTAL_TARGET, WORKER_TARGET = 200.0, 120.0
ROOT = Path(__file__).resolve().parent.parent


def _environment(prefix: str) -> dict[str, str]:
    """``make test``'s environment (one OpenBLAS thread, bytecode written) with this folder on ``PYTHONPATH`` (the
    plugin) and the records' prefix."""
    path = os.pathsep.join(filter(None, [str(ROOT), str(Path(__file__).parent), os.environ.get("PYTHONPATH")]))
    return {**os.environ, "PYTHONPATH": path, "OPENBLAS_NUM_THREADS": "1", "PYTHONDONTWRITEBYTECODE": "",
            "MDR_TEST_CLOCK_OUT": prefix}


def _collection_cpu(selection: list[str]) -> float:
    """CPU time (s) of ``pytest --collect-only -q`` over ``selection``, children included."""
    before = os.times()
    subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider", *selection],
                   cwd=ROOT, env=_environment(os.devnull), capture_output=True, check=False)
    after = os.times()
    return (after.children_user + after.children_system) - (before.children_user + before.children_system)


def _files(root: Path | None, pattern: str) -> set[Path]:
    """The files under ``root`` (none if it is ``None`` or missing) whose names match ``pattern``."""
    return set(root.rglob(pattern)) if root is not None and root.is_dir() else set()


def _bytecode() -> set[Path]:
    """The package's and the tests' bytecode files (``make test`` writes them: PYTHONDONTWRITEBYTECODE emptied)."""
    return _files(ROOT / "mdr_events", "*.pyc") | _files(ROOT / "tests", "*.pyc")


def _cache_root() -> Path | None:
    """The package's cache directory (the derived relations, the layer tables) as the tests see it: this clone's
    ``cache_directory`` in the tests' environment."""
    code = "from mdr_events.theory.cache_files import cache_directory; print(cache_directory() or '')"
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=_environment(os.devnull), capture_output=True,
                          text=True, check=True)
    return Path(done.stdout.strip()) if done.stdout.strip() else None


def _records(prefix: str) -> list[dict]:
    """Every record the workers wrote, each with its worker's name."""
    out = []
    for path in sorted(Path(prefix).parent.glob(Path(prefix).name + "_*.jsonl")):
        worker = path.stem.rsplit("_", 1)[1]
        out += [{**json.loads(line), "worker": worker} for line in path.read_text(encoding="utf-8").splitlines()]
    return out


def report(records: list[dict], wall: float, collection: float, top: int) -> None:
    """Print the totals against their targets, and the slowest modules and tests."""
    tests = [record for record in records if record["id"] not in ("<start>", "<controller>")]
    controller = sum(record["cpu"] for record in records if record["id"] == "<controller>")
    shares = collections.Counter()
    for record in records:
        if record["id"] != "<controller>":
            shares[record["worker"]] += record["cpu"]
    modules = collections.Counter()
    for record in tests:
        modules[record["id"].split("::")[0]] += record["cpu"]
    total = sum(shares.values()) + controller
    print(f"quick round: {len(tests)} tests, {wall:.0f} s wall (this machine's load included)")
    print(f"  CPU {total:.1f} s (pytest-xdist's controller's {controller:.1f} s included), target <= "
          f"{TOTAL_TARGET:.0f} s: {'met' if total <= TOTAL_TARGET else 'NOT met'}")
    for worker, share in sorted(shares.items()):
        print(f"  worker {worker}: CPU {share:.1f} s (start-up and collection included), target <= "
              f"{WORKER_TARGET:.0f} s: {'met' if share <= WORKER_TARGET else 'NOT met'}")
    print(f"  pytest --collect-only -q alone: CPU {collection:.1f} s (paid by every worker)")
    children = sum(record.get("children", 0.0) for record in tests)
    print(f"  the tests' subprocesses: CPU {children:.1f} s of the total")
    ends = collections.defaultdict(float)
    for record in tests:
        ends[record["worker"]] = max(ends[record["worker"]], record.get("end", 0.0))
    if len(ends) > 1:
        print(f"  tail: the last worker ended {max(ends.values()) - min(ends.values()):.1f} s of wall after the first "
              "(the wall time one worker idled)")
    print("  slowest modules (CPU s):")
    for module, cpu in modules.most_common(top):
        print(f"    {cpu:7.1f}  {module}")
    print("  slowest tests (CPU s):")
    for record in sorted(tests, key=lambda record: -record["cpu"])[:top]:
        print(f"    {record['cpu']:7.2f}  {record['id']}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2, help="pytest-xdist workers (default 2, the machine's cores)")
    parser.add_argument("--top", type=int, default=20, help="modules and tests listed (default 20)")
    parser.add_argument("--dist", default="loadscope", help="pytest-xdist's distribution (default loadscope, make test's)")
    parser.add_argument("--keep", type=Path, help="a file to write every test's record to (JSON lines)")
    parser.add_argument("selection", nargs="*", help="pytest's arguments instead of the quick round's (after --)")
    options = parser.parse_args()
    selection = options.selection or ["-m", "not slow"]
    caches = _cache_root()
    bytecode, cached = _bytecode(), _files(caches, "*")
    collection = _collection_cpu(selection)
    bytecode = len(_bytecode() - bytecode)
    with tempfile.TemporaryDirectory() as scratch:
        prefix = str(Path(scratch) / "clock")
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-p", "_test_cpu_clock",
                        "-n", str(options.workers), "--dist", options.dist, *selection], cwd=ROOT,
                       env=_environment(prefix), check=False)
        records = _records(prefix)
        report(records, time.perf_counter() - start, collection, options.top)
        cached = sorted(path.name for path in _files(caches, "*") - cached)
        if bytecode or cached:
            print(f"  cold: the collection wrote {bytecode} bytecode files, the round added {len(cached)} files to "
                  f"the caches ({', '.join(cached) or 'none'}): their first computation is in the figures above; run "
                  "again for a warm round's")
        if options.keep:
            options.keep.write_text("".join(json.dumps(record) + "\n" for record in records), encoding="utf-8")


if __name__ == "__main__":
    main()
