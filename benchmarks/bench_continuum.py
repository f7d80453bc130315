"""Benchmark: one continuum run per scenario, and continuum vs discrete at equal accuracy.

Prints, measured side by side in one run:
- the median time of ``continuum.solve_path`` for one angle of scenario A
  and of scenario B (target: under 20 ms);
- the discrete model's relative error in ``F_x,max`` (scenario A, 30°)
  against the exact value at several Δx, the Δx needed for the continuum's
  error (or 1e-4 if that is out of reach), extrapolated at first order from
  the finest run, and the time ratio discrete / continuum at that accuracy.

Run: ``python benchmarks/bench_continuum.py``.
"""

from __future__ import annotations

import time

import numpy as np

import mdr_events as me
from _timing import median_time
from mdr_events.continuum import evaluate, solve_path
from mdr_events.convergence import exact_references_A
from mdr_events.discrete import run_discrete
from mdr_events.paths import Path


def main() -> None:
    p = me.Parameters.paper()
    alpha = 30.0
    paths = {"A": Path.scenario_A(alpha, p), "B": Path.scenario_B(alpha, p)}
    solve_path(p, paths["A"])  # build the lambdified relations once
    print(f"mdr_events {me.__version__}: continuum, one angle ({alpha:g}°), median of 7")
    runs = {}
    for name, path in paths.items():
        runs[name] = median_time(lambda: solve_path(p, path))
        print(f"  scenario {name}: solve_path {runs[name] * 1e3:.1f} ms (target < 20 ms)")

    exact = exact_references_A(p, alpha)["tangential_force_max"]
    solution = solve_path(p, paths["A"])
    corner = [e[0] for e in solution.events if e[1] == "corner"][0]
    continuum_error = abs(evaluate(solution, np.array([corner]))["tangential_force"][0] - exact) / exact
    target = max(continuum_error, 1e-4)
    print(f"  continuum F_x,max relative error {continuum_error:.1e}; accuracy target {target:.0e}")
    last = None
    for dx in (8e-6, 4e-6, 2e-6, 1e-6):
        start = time.perf_counter()
        raw = run_discrete(p, [paths["A"]], dx, 0.5 * dx / p.v)
        elapsed = time.perf_counter() - start
        error = abs(np.nanmax(raw["tangential_force"]) - exact) / exact
        print(f"  discrete dx = {dx * 1e6:g} µm: error {error:.2e}, {elapsed * 1e3:.0f} ms")
        last = (dx, error, elapsed)
    dx, error, elapsed = last
    factor = error / target  # first order in Δx; steps and springs both scale with 1/Δx
    cost = elapsed * factor**2
    print(f"  discrete at the target: dx ≈ {dx / factor * 1e9:.1f} nm, ≈ {cost:.0f} s (first-order extrapolation)")
    print(f"  ratio discrete / continuum at equal accuracy ≈ {cost / runs['A']:.0f}x (target >= 100x)")


if __name__ == "__main__":
    main()
