"""Benchmark: validating a simulator's output against the exact continuum.

Prints, measured side by side in one run (medians of 7):
- ``validate`` of a 10 001-sample candidate (the package's own spring model, scenario A at 20°,
  Δx = 1 µm), from a Dataset (target: under 100 ms beyond reading the file) and from a CSV file
  (reading included, for comparison);
- a 4-spacing ``convergence_study`` against the four ``validate`` calls it makes (target: no more).

Run: ``python benchmarks/bench_validate.py``.
"""

from __future__ import annotations

import tempfile
from pathlib import Path as FilePath

import numpy as np

import mdr_events as me
from _timing import median_time


def main() -> None:
    p = me.Parameters.paper()
    run = me.simulate(p, "A", alpha=[20.0], dx=1e-6, n_steps=10_000).isel(alpha=0)
    columns = ("time", "normal_force", "tangential_force", "contact_area")
    with tempfile.TemporaryDirectory() as folder:
        csv = FilePath(folder) / "run.csv"
        table = np.column_stack([run[name].values for name in columns])
        np.savetxt(csv, table, delimiter=",", header=",".join(columns), comments="", fmt="%.17g")
        me.validate(run, p, "A", 20.0)  # build the lambdified relations once
        dataset = median_time(lambda: me.validate(run, p, "A", 20.0))
        from_file = median_time(lambda: me.validate(csv, p, "A", 20.0))
    print(f"mdr_events {me.__version__}: validate, scenario A at 20°, {run.sizes['time']} samples, median of 7")
    print(f"  from a Dataset   {dataset * 1e3:6.1f} ms (target < 100 ms)")
    print(f"  from a CSV file  {from_file * 1e3:6.1f} ms (reading included)")

    spacings = (8e-6, 4e-6, 2e-6, 1e-6)
    runs = {dx: me.simulate(p, "A", alpha=[20.0], dx=dx, dt=0.5 * dx / p.v).isel(alpha=0) for dx in spacings}
    study = median_time(lambda: me.convergence_study(runs, p, "A", 20.0))
    calls = median_time(lambda: [me.validate(candidate, p, "A", 20.0) for candidate in runs.values()])
    print(f"  convergence_study, 4 spacings {study * 1e3:6.1f} ms; the 4 validate calls {calls * 1e3:6.1f} ms; "
          f"ratio {study / calls:.2f} (target <= 1, to noise)")


if __name__ == "__main__":
    main()
