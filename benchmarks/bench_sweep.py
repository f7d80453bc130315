"""Benchmark: parameter sweeps on dask (``sweep``).

Prints, measured side by side in one run (the machine is shared and noisy; single timings of long runs):

- the issue's target: 2 000 continuum runs of scenario A (τ0: 40 values from 20 to 80 kPa × α: 50 values from
  5° to 80°), serially and on a 2-worker ``LocalCluster`` (loopback, one thread per worker process, the
  cluster started before the timing): the times, the speed-up (target at least 1.7×), the runs per second per
  core, and the extrapolation to 10⁶ runs on a 64-core cluster;
- the engine's overhead per run: 20 000 closed-form runs (``quantities=("critical_angle_A",)``, no model),
  serially and on the same cluster (median of 3): (cluster time − serial time / 2) / runs, the time the engine
  adds to each run beyond its share of the work (target under 1 ms);
- the time to start and stop the local cluster (what ``scheduler="local"`` adds to one sweep).

Run: ``python benchmarks/bench_sweep.py`` (about three minutes).
"""

from __future__ import annotations

import time

import numpy as np
from distributed import LocalCluster

import mdr_events as me
from mdr_events.analysis.executors import LOOPBACK_DASHBOARD
from _timing import median_time

WORKERS = 2
GRID = {"tau0": np.linspace(20e3, 80e3, 40), "alpha": np.linspace(5.0, 80.0, 50)}
CLOSED_FORM_GRID = {"tau0": np.linspace(20e3, 80e3, 200), "dgamma0": np.linspace(0.0, 0.05, 100)}
#: Runs per chunk: the default of ``sweep``.
CHUNK = 50


def timed(function) -> tuple[float, object]:
    start = time.perf_counter()
    result = function()
    return time.perf_counter() - start, result


def main() -> None:
    params = me.Parameters.paper()
    runs = GRID["tau0"].size * GRID["alpha"].size
    print(f"mdr_events {me.__version__}: sweep of {runs} continuum runs (scenario A, τ0 × α), chunks of {CHUNK}")
    started, cluster = timed(lambda: LocalCluster(n_workers=WORKERS, threads_per_worker=1, processes=True,
                                                  host="127.0.0.1", dashboard_address=LOOPBACK_DASHBOARD))
    with cluster:
        address = cluster.scheduler_address
        serial_time, serial = timed(lambda: me.sweep(GRID, "A", base=params, scheduler="serial", chunk_size=CHUNK))
        cluster_time, parallel = timed(lambda: me.sweep(GRID, "A", base=params, scheduler=address, chunk_size=CHUNK))
        same = all(np.array_equal(serial[name].values, parallel[name].values, equal_nan=True)
                   for name in serial.data_vars if name != "error")
        speedup = serial_time / cluster_time
        per_core = runs / cluster_time / WORKERS
        print(f"  serial {serial_time:6.1f} s ({serial_time / runs * 1e3:.1f} ms per run); {WORKERS}-worker local "
              f"cluster {cluster_time:6.1f} s: speed-up {speedup:.2f}x (target >= 1.7x); identical numbers: {same}")
        print(f"  {per_core:.1f} runs per second per core: 10^6 runs on a 64-core cluster ≈ "
              f"{1e6 / (per_core * 64) / 60:.1f} min (at this machine's speed per core)")
        closed = CLOSED_FORM_GRID["tau0"].size * CLOSED_FORM_GRID["dgamma0"].size
        options = dict(base=params, quantities=("critical_angle_A",), chunk_size=CHUNK * 10)
        serial_closed = median_time(lambda: me.sweep(CLOSED_FORM_GRID, "A", 20.0, scheduler="serial", **options), 3)
        cluster_closed = median_time(lambda: me.sweep(CLOSED_FORM_GRID, "A", 20.0, scheduler=address, **options), 3)
        overhead = (cluster_closed - serial_closed / WORKERS) / closed
        print(f"  engine overhead: {closed} closed-form runs, serial {serial_closed:.2f} s, cluster {cluster_closed:.2f} s "
              f"(medians of 3): {overhead * 1e3:.3f} ms per run (target < 1 ms)")
    lifetime, _ = timed(lambda: LocalCluster(n_workers=WORKERS, threads_per_worker=1, processes=True,
                                             host="127.0.0.1", dashboard_address=LOOPBACK_DASHBOARD).close())
    print(f"  local cluster: started in {started:.1f} s; a fresh one started and closed in {lifetime:.1f} s")


if __name__ == "__main__":
    main()
