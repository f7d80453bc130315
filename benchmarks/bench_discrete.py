"""Benchmark: the discrete spring model on the eight angles of Fig. 8.

Prints the median wall time of ``mdr_events.simulate`` (scenario A, angles
10°…80°, Δx = 1 µm: about 3 100 springs per side at d_max, 10 000 time steps
for the longest case; target under 3 s on one core) and the spring updates
per second (springs per side × active cases × steps actually taken).

Run: ``python benchmarks/bench_discrete.py``.
"""

from __future__ import annotations

import statistics
import time

import numpy as np

import mdr_events as me
from mdr_events.models.simulate import simulate


def main(repeat: int = 5) -> None:
    p = me.Parameters.paper()
    simulate(p, "A", alpha=[30.0], dx=1e-5, n_steps=100)  # build the lambdified relations once
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        ds = simulate(p, "A", dx=1e-6, n_steps=10_000)
        times.append(time.perf_counter() - start)
    median = statistics.median(times)
    springs = ds.attrs["spring_count_per_side"]
    active_steps = int(np.isfinite(ds["normal_force"].values).sum())
    in_contact = float(np.nansum(ds["contact_radius"].values) / ds.attrs["dx"])
    print(f"mdr_events {me.__version__}: discrete, scenario A, 8 angles, dx = 1 µm "
          f"({springs} springs per side), {ds.sizes['time']} steps, median of {repeat}")
    print(f"  wall time            {median:.2f} s (target < 3 s); runs: {', '.join(f'{t:.2f}' for t in times)}")
    print(f"  spring updates/s     {springs * active_steps / median:.3g} (array width x active steps)")
    print(f"  springs in contact/s {in_contact / median:.3g}")
    print(f"  memory of the state  {8 * springs * ds.sizes['alpha'] / 1e6:.2f} MB (springs x angles)")


if __name__ == "__main__":
    main()
