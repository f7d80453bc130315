"""Benchmark: phase diagrams for 100 000 angles vs a per-angle brentq loop.

Prints, measured side by side in one run on this machine:
- the median time of ``phase_diagram`` (all curves) for scenarios A and B
  with 100 000 angles (target: both together under 100 ms);
- the median per-angle time of a brentq loop on the same curves (the
  unreduced systems), measured on a subsample and scaled to 100 000 angles
  (``--full`` runs all of them);
- their ratio (target: at least 100x).

Run: ``make benchmark`` or ``python benchmarks/bench_phase_diagram.py``.
"""

from __future__ import annotations

import argparse
import math

import numpy as np
from scipy import optimize

import mdr_events as me
from _timing import median_time

N_ANGLES = 100_000


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
    args = parser.parse_args()

    p = me.Parameters.paper()
    alphas = np.linspace(0.0, 90.0, N_ANGLES)
    inner = alphas[(alphas > 0.0) & (alphas < 90.0)]
    sample = inner if args.full else inner[:: max(1, len(inner) // 2000)]
    for scenario in ("A", "B"):
        me.phase_diagram(p, alphas[:10], scenario=scenario)  # build the lambdified relations once
    print(f"mdr_events {me.__version__}: phase_diagram with {N_ANGLES} angles, all curves, "
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
    print(f"  both scenarios: {total_fast * 1e3:.1f} ms (target < 100 ms) | ratio {total_slow / total_fast:.0f}x "
          f"(target >= 100x)")


if __name__ == "__main__":
    main()
