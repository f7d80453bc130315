"""Benchmark: the rate-dependent adhesion law against the paper's, side by side in one run (issue 29).

Prints the median wall time of

- the discrete method, scenario A at 20°, Δx = 1 µm (10 000 steps): the paper's law and ``RateDependentAdhesion``
  (v_ref = 1 µm/s, n = 0.6), and their ratio (target: the rate-dependent run at most 3× the rate-independent one);
- the normal problem of the same path: ``continuum.solve_path`` without friction (the paper's law, the radius on its
  branches) and ``continuum.solve_edge`` (the radius an ODE), and their ratio.

Run: ``python benchmarks/bench_rate_adhesion.py [--repeat N]``.
"""

from __future__ import annotations

import argparse

import mdr_events as me
from mdr_events.models.continuum import solve_edge, solve_path

from _timing import median_time

#: The target of issue 29: a rate-dependent scenario A run at most this many times the rate-independent one.
RATIO_TARGET = 3.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    repeat = parser.parse_args().repeat
    params, paper = me.Parameters.paper(), me.Contact.paper()
    law = me.RateDependentAdhesion(params.dgamma0, params.dgamma1, 1e-6, 0.6)
    rate = me.Contact(paper.elastomer, paper.indenter, law, paper.friction)
    scenario = me.Scenario("A", alpha=[20.0])
    discrete = {label: median_time(lambda contact=contact: me.simulate(contact, scenario, "discrete", dx=1e-6),
                                   repeat) for label, contact in (("paper", paper), ("rate", rate))}
    path = me.Path.scenario_A(20.0, params)
    frictionless = me.FrictionLaw("tau0", tau0=0.0)
    normal = {"paper": median_time(lambda: solve_path(params, path, friction=frictionless), repeat),
              "rate": median_time(lambda: solve_edge(params, path, law), repeat)}
    print(f"discrete, A 20°, dx = 1 µm: paper's law {discrete['paper'] * 1e3:.1f} ms, rate-dependent "
          f"{discrete['rate'] * 1e3:.1f} ms, ratio {discrete['rate'] / discrete['paper']:.2f} (target <= "
          f"{RATIO_TARGET:g})")
    print(f"normal problem, A 20°: solve_path {normal['paper'] * 1e3:.1f} ms, solve_edge {normal['rate'] * 1e3:.1f} ms, "
          f"ratio {normal['rate'] / normal['paper']:.2f}")


if __name__ == "__main__":
    main()
