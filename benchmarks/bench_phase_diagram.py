"""Benchmark: phase diagrams for 100 000 angles vs a per-angle brentq loop.

Prints, measured side by side in one run on this machine:
- the median time of ``phase_diagram`` (all curves) for scenarios A and B
  with 100 000 angles (targets: each under 10 ms, issue 28; both together under 100 ms), and with
  ``--against DIR`` the same medians of another checkout, the repetitions interleaved in worker
  processes (``_side_by_side.py``), and their ratios before / now;
- the median per-angle time of a brentq loop on the same curves (the
  unreduced systems), measured on a subsample and scaled to 100 000 angles
  (``--full`` runs all of them);
- their ratio (target: at least 100x).

``--cpu`` times the side-by-side medians in each process's CPU time (on a shared machine the figure that compares).

Run: ``make benchmark`` or ``python benchmarks/bench_phase_diagram.py [--repeat N] [--against DIR] [--cpu]``.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
from scipy import optimize

import mdr_events as me
from _side_by_side import clock_name, measure, print_ratios, serve, verdict
from _timing import median_time

N_ANGLES = 100_000
#: Targets (s): each scenario's phase diagram (issue 28), and both together.
SCENARIO_TARGET, TOTAL_TARGET = 10e-3, 100e-3


def _tasks() -> dict[str, callable]:
    """Each scenario's phase diagram of :data:`N_ANGLES` angles, by scenario."""
    p = me.Parameters.paper()
    alphas = np.linspace(0.0, 90.0, N_ANGLES)
    tasks = {scenario: (lambda scenario=scenario: me.phase_diagram(p, alphas, scenario=scenario))
             for scenario in ("A", "B")}
    for task in tasks.values():
        task()  # build the lambdified relations once
    return tasks


def brentq_curves(alphas: np.ndarray, p: me.Parameters, scenario: str) -> None:
    """All curves of one phase diagram, one brentq per angle and curve, on the unreduced systems."""
    u_bar = lambda a: math.pi * a * p.tau0 / (2 * p.G_star)  # noqa: E731

    def depth(a, dgamma):
        return a**2 / p.R - math.sqrt(2 * math.pi * a * dgamma / p.E_star)

    tol = dict(xtol=1e-30, rtol=4 * np.finfo(float).eps, maxiter=1000)  # the vectorised solver's accuracy
    for alpha in alphas:
        tan = math.tan(math.radians(alpha))
        if scenario == "A":
            optimize.brentq(lambda d: d / tan - u_bar(math.sqrt(p.R * d)), 1e-30, 1e30, **tol)
            optimize.brentq(lambda a: depth(a, p.dgamma0) - tan * u_bar(a), 1e-9, 1e15, **tol)
        else:
            for sign, dgamma in ((-1, p.dgamma1), (1, p.dgamma0)):
                bracket = (1e-30, p.d_max) if sign < 0 else (p.d_max, 1e30)
                optimize.brentq(lambda d: -sign * (p.d_max - d) / tan - u_bar(math.sqrt(p.R * d)), *bracket, **tol)
                a_jo = (math.pi * dgamma * p.R**2 / (8 * p.E_star)) ** (1 / 3)
                f = lambda a: depth(a, dgamma) - (p.d_max + sign * tan * u_bar(a))  # noqa: E731
                if f(a_jo) < 0:
                    optimize.brentq(f, a_jo, 1e15, **tol)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true", help="run the brentq loop on all 100 000 angles")
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side")
    parser.add_argument("--cpu", action="store_true", help="CPU time instead of the wall clock (side by side)")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        serve(_tasks(), args.cpu)
        return
    roots = {"this checkout": str(Path(__file__).resolve().parent.parent)}
    if args.against:
        roots[f"--against {args.against}"] = str(Path(args.against).resolve())
    medians = measure(list(roots.values()), __file__, ["A", "B"], args.repeat, args.cpu)
    print(f"phase_diagram with {N_ANGLES} angles, all curves, medians of {args.repeat} ({clock_name(args.cpu)}), "
          "interleaved")
    for name, found in zip(roots, medians):
        print(f"  {name}: " + ", ".join(f"scenario {scenario} {found[scenario] * 1e3:.1f} ms (target < "
                                        f"{SCENARIO_TARGET * 1e3:.0f} ms: {verdict(found[scenario], SCENARIO_TARGET)})"
                                        for scenario in found))
    print_ratios(medians, medians[0], "scenario {}")

    p = me.Parameters.paper()
    alphas = np.linspace(0.0, 90.0, N_ANGLES)
    inner = alphas[(alphas > 0.0) & (alphas < 90.0)]
    sample = inner if args.full else inner[:: max(1, len(inner) // 2000)]
    for scenario in ("A", "B"):
        me.phase_diagram(p, alphas[:10], scenario=scenario)  # build the lambdified relations once
    print(f"mdr_events {me.__version__}: phase_diagram with {N_ANGLES} angles against a brentq loop, "
          f"median of {args.repeat}")
    total_fast = 0.0
    total_slow = 0.0
    for scenario in ("A", "B"):
        fast = median_time(lambda: me.phase_diagram(p, alphas, scenario=scenario), args.repeat)
        per_angle = median_time(lambda: brentq_curves(sample, p, scenario), 3) / len(sample)
        slow = per_angle * N_ANGLES
        total_fast += fast
        total_slow += slow
        print(f"  scenario {scenario}: phase_diagram {fast * 1e3:8.1f} ms | brentq loop "
              f"{slow * 1e3:9.0f} ms ({per_angle * 1e6:.1f} µs/angle, {len(sample)} angles timed) "
              f"| ratio {slow / fast:7.0f}x")
    ratio = total_slow / total_fast
    print(f"  both scenarios: {total_fast * 1e3:.1f} ms (target < {TOTAL_TARGET * 1e3:.0f} ms: "
          f"{verdict(total_fast, TOTAL_TARGET)}) | ratio {ratio:.0f}x (target >= 100x: {verdict(100.0, ratio)})")


if __name__ == "__main__":
    main()
