"""A verb loads what it uses only (issue 28): each ``mdr-events <verb>`` is a fresh interpreter, whose imports are
most of a small run's time.

Each check runs the verb in a fresh interpreter (this one has imported everything) and reads ``sys.modules`` after
it (the helps one after the other in one interpreter, and the two runs in another, each checked for what it and those
before it loaded). What may not be loaded, and why it is not needed:

- ``scipy.stats``: the fit's Student t quantile alone uses it, not the fit's schema every result file is checked
  against (:mod:`mdr_events.analysis.fit_diagnostics`);
- a verb's ``--help`` lists its options: no SymPy, xarray, dask or SciPy (:mod:`mdr_events.app.inputs` imports the
  models where a value is read).

- ``distributed``: xarray's ``to_netcdf`` asks dask for its scheduler on every write, importing dask.distributed
  (some 0.4 s) for a dataset in memory; the files are written without that question
  (:func:`mdr_events.io.netcdf3.write_netcdf3`).

``dask`` itself is loaded by xarray on the first array it wraps (its check whether the array is a dask array), so
a verb that writes a dataset loads it whatever this package imports: it is not among the modules a run is checked
for (a ``--help`` loads it not).
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import pytest

#: What a run of ``phase-diagram`` or ``simulate`` does not use.
NOT_USED_BY_A_RUN = ("scipy.stats", "distributed")
#: What a verb's ``--help`` does not use (listing the options of phase-diagram, sweep, run, reproduce, derive).
NOT_USED_BY_HELP = ("distributed", "dask", "scipy", "scipy.stats", "sympy", "xarray", "matplotlib")


def loaded_after(argvs: list[list[str]], cwd) -> list[set[str]]:
    """The modules in ``sys.modules`` after each ``mdr-events argv`` of ``argvs`` ran, one after the other in one
    fresh interpreter (each status asserted 0): the n-th set holds what the first n commands loaded."""
    code = textwrap.dedent(f"""
        import contextlib, io, json, sys
        from mdr_events.app.cli import main
        for argv in {argvs!r}:
            with contextlib.redirect_stdout(io.StringIO()):
                try:
                    status = main(argv)
                except SystemExit as done:  # (--help)
                    status = done.code
            assert status == 0, (argv, status)
            print(json.dumps(sorted(name for name, module in sys.modules.items() if module is not None)))
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600, cwd=cwd)
    assert done.returncode == 0, done.stderr
    return [set(json.loads(line)) for line in done.stdout.splitlines()[-len(argvs):]]


#: The runs checked, each with the file it writes.
RUNS = {"phase-diagram": (["phase-diagram", "--scenario", "A"], "phase_diagram_A.nc"),
        "simulate": (["simulate", "--scenario", "A", "--alpha", "20", "--method", "continuum"],
                     "simulation_A_continuum.nc")}


@pytest.fixture(scope="module")
def runs_loaded(tmp_path_factory):
    """The folder the runs wrote to, and what each run had loaded, itself and the runs before it (one interpreter for
    both: its start-up and the imports they share, ~2 s of CPU, are paid once; what the first loaded the second is
    checked against too, a stricter check than its own)."""
    folder = tmp_path_factory.mktemp("runs")
    loaded = loaded_after([[*argv, "--out", str(folder)] for argv, _ in RUNS.values()], folder)
    return folder, dict(zip(RUNS, loaded))


@pytest.mark.parametrize("verb", list(RUNS))
def test_a_run_loads_neither_scipy_stats_nor_dask_distributed(runs_loaded, verb):
    folder, loaded = runs_loaded[0], runs_loaded[1][verb]
    assert (folder / RUNS[verb][1]).is_file()
    assert "xarray" in loaded  # (the runs did write their datasets through xarray)
    assert not loaded & set(NOT_USED_BY_A_RUN), sorted(loaded & set(NOT_USED_BY_A_RUN))


#: The verbs whose ``--help`` is checked.
HELPED = ("phase-diagram", "sweep", "run", "reproduce", "derive")


@pytest.fixture(scope="module")
def helps_loaded(tmp_path_factory):
    """What each verb's ``--help`` had loaded, itself and the helps before it, in one fresh interpreter (a start-up
    each paid once; each help checked for what it and those before it loaded: stricter than its own)."""
    folder = tmp_path_factory.mktemp("helps")
    return dict(zip(HELPED, loaded_after([[verb, "--help"] for verb in HELPED], folder)))


@pytest.mark.parametrize("verb", HELPED)
def test_a_verbs_help_loads_no_heavy_library(helps_loaded, verb):
    loaded = helps_loaded[verb]
    assert not loaded & set(NOT_USED_BY_HELP), sorted(loaded & set(NOT_USED_BY_HELP))
