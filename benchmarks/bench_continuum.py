"""Benchmark: one continuum run per scenario, and continuum vs discrete at equal accuracy.

Prints, measured side by side in one run:
- the median time of one continuum run at 30° for scenario A and B, as
  ``solve_path`` alone and with the 2001-sample grid filled as
  ``simulate`` does (target: under 20 ms), and the slowest angle of 10°…80°;
- the relative error in ``F_x,max`` and ``F_N,min`` (scenario A, 30°) of the
  continuum and of the discrete model at several Δx against the exact
  values; the Δx at which the discrete model should reach the continuum's
  error (or 1e-4 if that is out of reach), estimated at first order and then
  *measured*; and the time ratio discrete / continuum at that accuracy
  (target: at least 100x).

Run: ``python benchmarks/bench_continuum.py``.
"""

from __future__ import annotations

import time

import numpy as np

import mdr_events as me
from _timing import median_time
from mdr_events.models.continuum import evaluate, solve_path
from mdr_events.analysis.convergence import exact_references_A
from mdr_events.models.discrete import run_discrete
from mdr_events.models.paths import Path


def main() -> None:
    p = me.Parameters.paper()
    alpha = 30.0
    paths = {"A": Path.scenario_A(alpha, p), "B": Path.scenario_B(alpha, p)}
    solve_path(p, paths["A"])  # build the lambdified relations once

    def full_run(path):  # solve, then fill the default 2001-sample grid as simulate() does
        solution = solve_path(p, path)
        return evaluate(solution, np.linspace(0.0, solution.end_time * 1.0005, 2001))

    print(f"mdr_events {me.__version__}: continuum, one angle per run, median of 7")
    runs, runs_full = {}, {}
    for name, path in paths.items():
        runs[name] = median_time(lambda: solve_path(p, path))
        runs_full[name] = median_time(lambda: full_run(path))
        print(f"  scenario {name} at {alpha:g}°: solve_path {runs[name] * 1e3:.1f} ms, "
              f"solve + fill 2001 samples {runs_full[name] * 1e3:.1f} ms (target < 20 ms)")
    for name in ("A", "B"):
        angles = (10.0, 20.0, 40.0, 50.0, 60.0, 70.0, 80.0)
        times = [median_time(lambda: full_run(getattr(Path, f"scenario_{name}")(angle, p)), repeat=3)
                 for angle in angles]
        print(f"  scenario {name}, 10°…80°: solve + fill, slowest angle {max(times) * 1e3:.1f} ms, "
              f"median {np.median(times) * 1e3:.1f} ms")

    exact = exact_references_A(p, alpha)
    keys = ("tangential_force_max", "normal_force_min")
    solution = solve_path(p, paths["A"])
    times = np.linspace(0.0, solution.end_time * 1.0005, 20001)
    filled = evaluate(solution, times)
    corner = [e[0] for e in solution.events if e[1] == "corner"][0]
    continuum = {"tangential_force_max": evaluate(solution, np.array([corner]))["tangential_force"][0],
                 "normal_force_min": np.nanmin(filled["normal_force"])}
    continuum_error = max(abs(continuum[k] - exact[k]) / abs(exact[k]) for k in keys)
    target = max(continuum_error, 1e-4)
    print(f"  continuum: relative error of F_x,max and F_N,min at most {continuum_error:.1e} "
          f"(F_N,min on a 20001-sample grid); accuracy target {target:.0e}")

    def discrete(dx):
        start = time.perf_counter()
        raw = run_discrete(p, [paths["A"]], dx, 0.5 * dx / p.v)
        elapsed = time.perf_counter() - start
        errors = {"tangential_force_max": abs(np.nanmax(raw["tangential_force"]) - exact["tangential_force_max"]),
                  "normal_force_min": abs(np.nanmin(raw["normal_force"]) - exact["normal_force_min"])}
        error = max(errors[k] / abs(exact[k]) for k in keys)
        print(f"  discrete dx = {dx * 1e9:7.1f} nm: error F_x,max {errors[keys[0]] / abs(exact[keys[0]]):.2e}, "
              f"F_N,min {errors[keys[1]] / abs(exact[keys[1]]):.2e}; {elapsed:.2f} s")
        return error, elapsed

    for dx in (8e-6, 4e-6, 2e-6):
        error, elapsed = discrete(dx)
    # first order in Δx: the spacing that should reach the target, then measured there
    dx_target = 2e-6 * target / error
    print(f"  first-order estimate of the spacing for {target:.0e}: {dx_target * 1e9:.0f} nm; measuring there")
    error, elapsed = discrete(dx_target)
    reached = "reached" if error <= target else f"not reached ({error:.1e})"
    print(f"  accuracy {target:.0e} {reached} by the discrete model at {dx_target * 1e9:.0f} nm in {elapsed:.1f} s; "
          f"continuum run (solve + fill) {runs_full['A'] * 1e3:.1f} ms")
    print(f"  ratio discrete / continuum at equal accuracy: {elapsed / runs_full['A']:.0f}x (target >= 100x)")

if __name__ == "__main__":
    main()
