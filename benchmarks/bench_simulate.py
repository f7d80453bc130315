"""Benchmark: ``simulate`` of the continuum against its own ``solve_path`` (issue 28, item 1).

For each path below it prints the medians, measured interleaved in one run, of

- ``solve_path`` alone;
- ``solution_extrema`` of that solution alone (the six exact extrema ``simulate`` adds; target: at most half the
  solve);
- ``simulate`` as users call it (2001 samples, the event log, the extrema, the dataset; target: at most 1.5x the
  solve on every path, under 2 ms for scenario A or B at one angle on a quiet machine);

and for the tabulated profile (a 41-point table of the paper's paraboloid) its ``simulate`` over the paraboloid's
(target: at most 3x).

Paths: scenarios A and B at 20° and 30°; the zigzag of ``bench_discrete.py`` (in with tangential reversals, a pinned
zigzag, out); the 10-cycle reciprocating path of ``bench_continuum.py``; scenario A at 20° with the table.

``--against DIR`` measures a checkout of another commit side by side: each checkout runs in a worker process of its
own (its package first on ``PYTHONPATH``) and the repetitions alternate between them, so that both see the same
load (``_side_by_side.py``); it prints each figure's ratio before / now. E.g. ``git worktree add /tmp/before <commit>`` then
``--against /tmp/before``.

``--cpu`` times each task in its process's CPU time instead of the wall clock (on a shared machine the figure that
compares). Each figure is printed with its target and whether it is met.

``--parts`` also times, per path, what ``simulate`` adds to its solve: ``evaluate`` of the solution at the run's 2001
samples, the extrema, the dataset's assembly (``continuum_dataset``) and the front end (the job, its checks and the
cases' paths), and prints each as a share of the solve with the rest (``simulate`` less all of them). Each part is
timed on what the step before it in ``simulate`` has just made (``_side_by_side.Staged``: ``evaluate`` on a fresh
solve, the extrema after it, the dataset of a fresh run), with the caches as that step leaves them: a part timed on
the same solution again and again kept its code and data in the caches (``evaluate`` 0.62 ms on B 20° against 1.0 ms
after a solve, the extrema 0.43 against 0.69 ms) and left that difference, some 0.4 ms on B, in the rest.

Run: ``python benchmarks/bench_simulate.py [--repeat N] [--against DIR] [--cpu] [--parts]``.
"""

from __future__ import annotations

import argparse
import inspect
from pathlib import Path

from _side_by_side import Staged, clock_name, measure, serve, verdict

#: Targets of issue 28: simulate / solve_path, extrema / solve_path, table / paraboloid, simulate of A or B (s).
SIMULATE_RATIO, EXTREMA_RATIO, TABLE_RATIO, SIMULATE_TARGET = 1.5, 0.5, 3.0, 2e-3
#: The benchmark's paths, by label.
PATHS = ("A 20°", "A 30°", "B 20°", "B 30°", "zigzag", "reciprocating", "A 20° table")
#: What is timed of each path.
TASKS = ("solve", "extrema", "simulate")
#: What ``--parts`` times besides (the parts of ``simulate`` beyond its solve, each after the step before it there).
PARTS = ("evaluate", "extrema in turn", "dataset", "front end")


def _build(label: str):
    """``(contact, path, options, simulate_call)`` of a path of :data:`PATHS` (imports the checkout's package)."""
    import math

    import numpy as np

    import mdr_events as me
    from mdr_events.models.paths import Path as P, exit_depth
    from mdr_events.theory import analytic

    p = me.Parameters.paper()
    options = {}
    if label.endswith("table"):
        r = np.linspace(0.0, 4e-3, 41)
        options["profile"] = me.TabulatedProfile(r, r**2 / (2 * p.R))
    if label.startswith(("A", "B")):
        name, angle = label[0], float(label.split()[1].rstrip("°"))
        path = getattr(P, f"scenario_{name}")(angle, p, **options)
        return p, path, options, lambda: me.simulate(p, name, alpha=[angle], method="continuum", **options)
    if label == "zigzag":
        path = me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], p.v)
    else:  # in at 20° to (x_c, d_max), 10 cycles x_c ± 3 ū(a_max), out vertically
        amplitude = 3.0 * float(analytic.critical_shift(float(analytic.jkr_contact_radius(p.d_max, p, p.dgamma0)), p))
        x_c = p.d_max / math.tan(math.radians(20.0))
        turns = [(x_c + amplitude * (1 if i % 2 == 0 else -1), p.d_max) for i in range(20)]
        path = me.Path([(0.0, 0.0), (x_c, p.d_max), *turns, (x_c, p.d_max), (x_c, exit_depth(p))], p.v)
    return p, path, options, lambda: me.simulate(p, path, method="continuum")


def _tasks() -> dict[str, callable]:
    """Every ``"<path>|<task>"`` of this checkout, as a function to time."""
    from mdr_events.models.continuum import solve_path
    from mdr_events.models.continuum.extrema import solution_extrema

    tasks = {}
    for label in PATHS:
        p, path, options, run = _build(label)
        solution = solve_path(p, path, **options)
        tasks[f"{label}|solve"] = lambda p=p, path=path, options=options: solve_path(p, path, **options)
        tasks[f"{label}|extrema"] = lambda solution=solution: solution_extrema(solution)
        tasks[f"{label}|simulate"] = run
        tasks.update(_part_tasks(label, p, path, options))
        run()  # once unmeasured: caches, lambdified relations
    return tasks


def _part_tasks(label: str, p, path, options: dict) -> dict[str, callable]:
    """``--parts``' tasks of a path, each timed after the step before it in ``simulate`` (:class:`Staged`): ``evaluate``
    at ``simulate``'s samples of a fresh solve, the extrema of a solution just evaluated, the dataset of a fresh run
    with its extrema, ``simulate``'s front end up to the cases (as :func:`mdr_events.models.simulate.simulate` runs
    it)."""
    from mdr_events.limits import check_limits
    from mdr_events.models.continuum import run_continuum, solve_path
    from mdr_events.models.continuum.extrema import solution_extrema
    from mdr_events.models.continuum.solution import evaluate
    from mdr_events.models.simulate import simulation_job
    from mdr_events.models.simulation_schema import continuum_dataset
    from mdr_events.theory.scales import check_representable

    motion, alpha = (label[0], [float(label.split()[1].rstrip("°"))]) if label[0] in "AB" else (path, None)

    # (a checkout before round twenty-two's counting first, measured with --against, takes no limits here; looked up
    # once, not timed: the front end's own work is)
    counted_first = "limits" in inspect.signature(simulation_job).parameters

    def front_end():
        limits = check_limits(None)
        model, method = simulation_job(p, motion, alpha, "continuum", dict(options),
                                       *([limits] if counted_first else []))
        check_representable(model.params, model.profile, model.friction)
        method.check_case_count(model.motion.case_count, limits)
        method.check_model(model)
        return model, model.motion.cases(model.params, model.profile, model.friction)

    model, cases = front_end()
    times = run_continuum(model.kernel, cases.paths, 2001)["time"]

    def solved() -> tuple:
        return (solve_path(p, path, **options),)

    def evaluated() -> tuple:
        solution = solve_path(p, path, **options)
        evaluate(solution, times)
        return (solution,)

    def ran() -> tuple:
        raw = run_continuum(model.kernel, cases.paths, 2001)
        return raw, [solution_extrema(solution) for solution in raw["solutions"]]

    return {f"{label}|evaluate": Staged(solved, lambda solution: evaluate(solution, times)),
            f"{label}|extrema in turn": Staged(evaluated, solution_extrema),
            f"{label}|dataset": Staged(ran, lambda raw, extrema: continuum_dataset(
                p, cases, raw["time"], raw, raw["events"], extrema, method="continuum")),
            f"{label}|front end": front_end}


def report(name: str, medians: dict[str, float]) -> None:
    """Print one checkout's figures with their targets, and whether each is met."""
    print(f"  {name}:")
    for label in PATHS:
        solve, extrema, run = (medians[f"{label}|{task}"] for task in TASKS)
        absolute = (f"; {run * 1e3:.1f} ms, target < {SIMULATE_TARGET * 1e3:.0f} ms: {verdict(run, SIMULATE_TARGET)}"
                    if label[0] in "AB" and "table" not in label else "")
        print(f"    {label:14s} solve_path {solve * 1e3:6.1f} ms | extrema {extrema * 1e3:6.1f} ms = "
              f"{extrema / solve:4.2f}x solve (target <= {EXTREMA_RATIO}: {verdict(extrema / solve, EXTREMA_RATIO)}) "
              f"| simulate {run * 1e3:6.1f} ms = {run / solve:4.2f}x solve (target <= {SIMULATE_RATIO}: "
              f"{verdict(run / solve, SIMULATE_RATIO)}{absolute})")
    if f"{PATHS[0]}|{PARTS[0]}" in medians:
        _report_parts(medians)
    table = medians["A 20° table|simulate"] / medians["A 20°|simulate"]
    print(f"    table profile / paraboloid, simulate A 20°: {table:.2f}x (target <= {TABLE_RATIO}: "
          f"{verdict(table, TABLE_RATIO)})")


def _report_parts(medians: dict[str, float]) -> None:
    """``--parts``: each path's ``simulate`` split into its solve and :data:`PARTS`, as shares of the solve."""
    for label in PATHS:
        solve = medians[f"{label}|solve"]
        parts = {name: medians[f"{label}|{name}"] for name in PARTS}
        rest = medians[f"{label}|simulate"] - solve - sum(parts.values())
        print(f"    {label:14s} simulate = solve {solve * 1e3:5.1f} ms + " + " + ".join(
            f"{name} {value * 1e3:4.2f} ms ({value / solve:4.2f}x)" for name, value in
            [*parts.items(), ("rest", rest)]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=9, help="runs per figure (median; default 9)")
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side")
    parser.add_argument("--cpu", action="store_true", help="CPU time instead of the wall clock")
    parser.add_argument("--parts", action="store_true", help="also time evaluate, the extrema, the dataset and the front end in turn")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.worker:
        serve(_tasks(), options.cpu)
        return
    roots = {"this checkout": str(Path(__file__).resolve().parent.parent)}
    if options.against:
        roots[f"--against {options.against}"] = str(Path(options.against).resolve())
    timed = TASKS + (PARTS if options.parts else ())
    medians = measure(list(roots.values()), __file__, [f"{label}|{task}" for label in PATHS for task in timed],
                      options.repeat, options.cpu)
    print(f"continuum: solve_path, solution_extrema and simulate (2001 samples), medians of {options.repeat} "
          f"({clock_name(options.cpu)}), interleaved")
    for name, found in zip(roots, medians):
        report(name, found)
    if len(medians) == 2:
        now, before = medians
        print("  ratio before / now: " + ", ".join(
            f"{label} simulate {before[f'{label}|simulate'] / now[f'{label}|simulate']:.1f}x "
            f"(extrema {before[f'{label}|extrema'] / now[f'{label}|extrema']:.1f}x)" for label in PATHS))


if __name__ == "__main__":
    main()
