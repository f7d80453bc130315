"""Benchmark: start-up, ``import mdr_events`` and ``mdr-events --help`` (issue 28, item 3).

Prints the medians of fresh interpreters (each run is a subprocess, so nothing is cached in memory but the OS's file
cache; one unmeasured run first warms it):

- ``python -c "import mdr_events"``, wall time (target: under 0.3 s), and the interpreter alone (``python -c pass``)
  for comparison;
- ``python -X importtime -c "import mdr_events"``: the cumulative import time of ``mdr_events`` it reports;
- ``mdr-events --help``, wall time (target: under 0.5 s);
- the heavy libraries ``import mdr_events`` loads (none expected; ``tests/test_imports.py`` checks it);
- a verb's run, ``mdr-events phase-diagram --scenario A`` (its netCDF file and figure written), wall time, and whether
  it loads ``dask.distributed`` (target: not; xarray's ``to_netcdf`` would, some 0.4 s:
  ``tests/app/test_verb_imports.py``).

``--against DIR`` measures a checkout of another commit side by side (its package first on ``PYTHONPATH``), e.g.
``git worktree add /tmp/before <commit>`` then ``--against /tmp/before``.

Run: ``python benchmarks/bench_import.py [--repeat N] [--against DIR]``.
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: Targets of issue 28 (s): ``import mdr_events`` and ``mdr-events --help``, wall time, median.
IMPORT_TARGET, HELP_TARGET = 0.3, 0.5
#: What start-up must not load.
HEAVY = ("matplotlib", "sympy", "dask", "distributed", "scipy", "scipy.stats", "scipy.interpolate", "xarray",
         "pandas", "numpy")
HELP_CODE = "import sys; sys.argv = ['mdr-events', '--help']; from mdr_events.app.cli import console_main; console_main()"
#: A verb's run (its files written into the directory given after the code), then whether dask.distributed was loaded.
VERB_CODE = ("import contextlib, io, sys\n"
             "from mdr_events.app.cli import main\n"
             "with contextlib.redirect_stdout(io.StringIO()):\n"
             "    status = main(['phase-diagram', '--scenario', 'A', '--out', sys.argv[1]])\n"
             "print(status, 'distributed' in sys.modules)")


def _environment(root: str) -> dict[str, str]:
    """The environment of a run: the checkout ``root`` first on ``PYTHONPATH`` (runs start in ``root`` too, since
    ``python -c`` puts the working directory first)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([root, *filter(None, [env.get("PYTHONPATH")])])
    return env


def wall(arguments: list[str], env: dict[str, str], repeat: int) -> float:
    """Median wall time (s) of ``repeat`` runs of ``arguments`` (after one unmeasured run)."""
    times = []
    for index in range(repeat + 1):
        start = time.perf_counter()
        subprocess.run(arguments, env=env, cwd=env["PYTHONPATH"].split(os.pathsep)[0], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if index:
            times.append(time.perf_counter() - start)
    return statistics.median(times)


def importtime(env: dict[str, str], repeat: int) -> float:
    """Median (s) of the cumulative import time of ``mdr_events`` that ``-X importtime`` reports."""
    times = []
    for _ in range(repeat):
        done = subprocess.run([sys.executable, "-X", "importtime", "-c", "import mdr_events"], env=env, check=True,
                              cwd=env["PYTHONPATH"].split(os.pathsep)[0], capture_output=True, text=True)
        found = re.search(r"^import time:\s+\d+ \|\s+(\d+) \| mdr_events$", done.stderr, flags=re.M)
        times.append(int(found.group(1)) * 1e-6)
    return statistics.median(times)


def heavy_loaded(env: dict[str, str]) -> list[str]:
    """The libraries of :data:`HEAVY` that ``import mdr_events`` loads."""
    code = f"import sys, mdr_events; print(' '.join(m for m in {HEAVY!r} if m in sys.modules))"
    return subprocess.run([sys.executable, "-c", code], env=env, cwd=env["PYTHONPATH"].split(os.pathsep)[0],
                          check=True, capture_output=True, text=True).stdout.split()


def verb_loads_distributed(env: dict[str, str], out: str) -> bool:
    """Whether a verb's run (:data:`VERB_CODE`, its files written into ``out``) loads dask.distributed."""
    done = subprocess.run([sys.executable, "-c", VERB_CODE, out], env=env, cwd=env["PYTHONPATH"].split(os.pathsep)[0],
                          check=True, capture_output=True, text=True)
    status, loaded = done.stdout.split()[-2:]
    if status != "0":
        raise RuntimeError(f"phase-diagram ended with status {status}: {done.stderr}")
    return loaded == "True"


def measure(root: str, repeat: int) -> dict[str, object]:
    """Every figure of this benchmark for the package in the checkout ``root``."""
    env = _environment(root)
    with tempfile.TemporaryDirectory() as out:
        return {"python": wall([sys.executable, "-c", "pass"], env, repeat),
                "import": wall([sys.executable, "-c", "import mdr_events"], env, repeat),
                "importtime": importtime(env, repeat),
                "help": wall([sys.executable, "-c", HELP_CODE], env, repeat),
                "heavy": heavy_loaded(env),
                "verb": wall([sys.executable, "-c", VERB_CODE, out], env, repeat),
                "distributed": verb_loads_distributed(env, out)}


def main() -> None:
    """Measure and print the medians with their targets."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=9, help="runs per figure (median; default 9)")
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side")
    options = parser.parse_args()
    here = str(Path(__file__).resolve().parent.parent)
    rows = {"this checkout": measure(here, options.repeat)}
    if options.against:
        rows[f"--against {options.against}"] = measure(str(Path(options.against).resolve()), options.repeat)
    print(f"start-up, medians of {options.repeat} fresh interpreters (wall time, s)")
    for name, row in rows.items():
        print(f"  {name}:")
        print(f"    python -c pass                       {row['python']:.3f}")
        print(f"    python -c 'import mdr_events'        {row['import']:.3f}  (target < {IMPORT_TARGET})"
              f"{'' if row['import'] < IMPORT_TARGET else '  OVER'}")
        print(f"    -X importtime: mdr_events cumulative {row['importtime']:.3f}")
        print(f"    mdr-events --help                    {row['help']:.3f}  (target < {HELP_TARGET})"
              f"{'' if row['help'] < HELP_TARGET else '  OVER'}")
        print(f"    heavy libraries at import: {', '.join(row['heavy']) or 'none'}")
        print(f"    mdr-events phase-diagram --scenario A {row['verb']:.3f}; dask.distributed loaded: "
              f"{'yes' if row['distributed'] else 'no'} (target: no){'  OVER' if row['distributed'] else ''}")
    if len(rows) == 2:
        now, before = rows.values()
        print(f"  ratio (before / now): import {before['import'] / now['import']:.1f}x, "
              f"--help {before['help'] / now['help']:.1f}x, phase-diagram {before['verb'] / now['verb']:.2f}x")


if __name__ == "__main__":
    main()
