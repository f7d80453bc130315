"""Benchmark: ``evaluate`` of a continuum solution at ``simulate``'s 2001 samples, alone (issue 28, item 1: what
``simulate`` adds to its solve; target of round eight: at most 0.6 ms on scenario A at 20° and on the zigzag, 0.35 ms
on scenario B at 20°).

``bench_simulate.py --parts`` times ``evaluate`` once per repetition among the other parts, a millisecond each: on a
shared machine one call's figure moves by some 10 %. Here each timing is :data:`CALLS` calls of the same solution's
``evaluate`` (its steps gathered and its branch's radii kept by the first call, as in ``simulate``'s own), the medians
of the repetitions, per call.

Paths: scenarios A and B at 20°, the zigzag and the reciprocating path of ``bench_simulate.py``, scenario A at 20°
with the table.

``--against DIR`` measures a checkout of another commit side by side (``_side_by_side.py``: a worker process each,
the repetitions alternating) and prints the ratios before / now; ``--cpu`` times in the process's CPU time.

Run: ``python benchmarks/bench_evaluate.py [--repeat N] [--against DIR] [--cpu]``.
"""

from __future__ import annotations

from _side_by_side import Staged, clock_name, command_line, measure, print_ratios, verdict

#: The paths timed, by their labels in ``bench_simulate.py``.
PATHS = ("A 20°", "B 20°", "zigzag", "reciprocating", "A 20° table")
#: Round eight's targets (s per call) where there is one.
TARGETS = {"A 20°": 0.6e-3, "B 20°": 0.35e-3, "zigzag": 0.6e-3}
#: Calls of ``evaluate`` per timing.
CALLS = 20


def _tasks() -> dict[str, Staged]:
    """Each path's :data:`CALLS` evaluations at ``simulate``'s samples of one fresh solve, the solve untimed
    (``bench_simulate``'s ``--parts`` task is :class:`Staged`: its ``prepare`` solves, its ``run`` evaluates; imports the
    checkout's package)."""
    import bench_simulate

    tasks = {}
    for label in PATHS:
        p, path, options, _ = bench_simulate._build(label)
        evaluate = bench_simulate._part_tasks(label, p, path, options)[f"{label}|evaluate"]
        evaluate()  # (once unmeasured)
        tasks[label] = Staged(evaluate.prepare, lambda *solved, run=evaluate.run: [run(*solved) for _ in range(CALLS)])
    return tasks


def report(name: str, medians: dict[str, float]) -> None:
    """Print one checkout's figures per call, with their targets."""
    print(f"  {name}:")
    for label in PATHS:
        each = medians[label] / CALLS
        target = TARGETS.get(label)
        aim = f" (target <= {target * 1e3:.2f} ms: {verdict(each, target)})" if target else ""
        print(f"    {label:14s} evaluate {each * 1e3:6.3f} ms{aim}")


def main() -> None:
    parsed = command_line(__doc__.splitlines()[0], __file__, _tasks, repeat=9)
    if parsed is None:
        return
    options, roots = parsed
    medians = measure(list(roots.values()), __file__, list(PATHS), options.repeat, options.cpu)
    print(f"continuum: evaluate at 2001 samples, {CALLS} calls per timing, medians of {options.repeat} "
          f"({clock_name(options.cpu)}), interleaved, per call")
    for name, found in zip(roots, medians):
        report(name, found)
    print_ratios(medians, PATHS)


if __name__ == "__main__":
    main()
