"""Benchmark: Coulomb's part with adhesion in the continuum against the τ0 run (issue 26, performance).

Medians, measured interleaved in one run, of ``solve_path`` + ``evaluate`` at 2001 samples (what a user's curve
costs) with the paper's adhesion (Δγ0 = 0.01, Δγ1 = 0.15 J/m²):

- scenario A at 20° for ``"tau0"``, ``"tau0+coulomb"`` (μ = 0.3: the contact split at ``x_c``, the split integrator)
  and ``"coulomb"`` (μ = 0.3: the compressed zone as the run without adhesion), and each one's ratio to the τ0 run
  (target: at most 2x);
- a 10-cycle fretting path at d_max/3 (±0.6 of Coulomb's full-slip shift) for the same three laws (target: under
  100 ms with adhesion).

``--against DIR`` measures a checkout of another commit side by side (``_side_by_side.py``: each checkout in a worker
process of its own, the repetitions alternating) and prints each figure's ratio before / now; ``--cpu`` times the
process's CPU time instead of the wall clock (the figure that compares on a shared machine).

Run: ``python benchmarks/bench_coulomb_adhesion.py [--repeat N] [--against DIR] [--cpu]``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from _side_by_side import clock_name, measure, print_ratios, serve, verdict

#: Issue 26's targets: a Coulomb-with-adhesion run of scenario A at 20° over the τ0 run; a 10-cycle fretting path (s).
RATIO_TARGET, FRETTING_TARGET = 2.0, 0.1
#: The paths and laws timed.
PATHS = ("A 20°", "fretting")
LAWS = ("tau0", "tau0+coulomb", "coulomb")


def _tasks() -> dict[str, callable]:
    """Every ``"<path>|<law>"`` of this checkout, as a function to time (imports the checkout's package)."""
    import numpy as np

    import mdr_events as me
    from mdr_events.contact.friction import FrictionLaw
    from mdr_events.models.continuum import evaluate, solve_path
    from mdr_events.theory import mindlin

    p = me.Parameters.paper()
    depth = p.d_max / 3.0
    shift = 0.6 * mindlin.full_slip_shift(depth, FrictionLaw("coulomb", mu=0.3), p)
    fretting = me.Path(np.array([(0.0, 0.0), (0.0, depth)] + [(sign * shift, depth) for sign in (1, -1) * 10]
                                + [(0.0, depth), (0.0, 0.0)]), speed=p.v)
    paths = {"A 20°": me.Path.scenario_A(20.0, p), "fretting": fretting}
    laws = {"tau0": FrictionLaw(), "tau0+coulomb": FrictionLaw("tau0+coulomb", mu=0.3),
            "coulomb": FrictionLaw("coulomb", mu=0.3)}
    tasks = {}
    for label, path in paths.items():
        for name, law in laws.items():
            def run(path=path, law=law):
                solution = solve_path(p, path, friction=law)
                return evaluate(solution, np.linspace(0.0, solution.end_time, 2001))

            run()  # once unmeasured: caches, lambdified relations
            tasks[f"{label}|{name}"] = run
    return tasks


def report(name: str, medians: dict[str, float]) -> None:
    """Print one checkout's figures with their targets, and whether each is met."""
    print(f"  {name}:")
    tau0 = medians["A 20°|tau0"]
    for law in LAWS:
        ratio = medians[f"A 20°|{law}"] / tau0
        target = f" (target <= {RATIO_TARGET}x: {verdict(ratio, RATIO_TARGET)})" if law != "tau0" else ""
        print(f"    scenario A at 20°, {law:12s} {medians[f'A 20°|{law}'] * 1e3:7.1f} ms = {ratio:5.2f}x tau0{target}")
    for law in LAWS:
        run = medians[f"fretting|{law}"]
        target = f" (target < {FRETTING_TARGET * 1e3:.0f} ms: {verdict(run, FRETTING_TARGET)})" if law != "tau0" else ""
        print(f"    10-cycle fretting, {law:12s} {run * 1e3:7.1f} ms{target}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=9, help="runs per figure (median; default 9)")
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side")
    parser.add_argument("--cpu", action="store_true", help="CPU time instead of the wall clock")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.worker:
        serve(_tasks(), options.cpu)
        return
    roots = {"this checkout": str(Path(__file__).resolve().parent.parent)}
    if options.against:
        roots[f"--against {options.against}"] = str(Path(options.against).resolve())
    tasks = [f"{label}|{law}" for label in PATHS for law in LAWS]
    medians = measure(list(roots.values()), __file__, tasks, options.repeat, options.cpu)
    print(f"Coulomb's part with the paper's adhesion: solve_path + evaluate (2001 samples), medians of "
          f"{options.repeat} ({clock_name(options.cpu)}), interleaved")
    for name, found in zip(roots, medians):
        report(name, found)
    print_ratios(medians, tasks)


if __name__ == "__main__":
    main()
