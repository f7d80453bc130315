"""Benchmark: the flat punch on a layer in the continuum against the half-space's flat punch, side by side (issue 34).

Prints the median CPU and wall times of ``simulate(..., method="continuum")`` of a flat punch of radius 2 mm pressed
10 µm, on the half-space, on the paper's 5 mm layer (the face comes off at once) and on a layer of ``h/a₀ = 0.1`` (the
contact recedes under the face), and each layer's ratio to the half-space (target of issue 34: a layer run at most 2×
the half-space run): vertically in and out (scenario A at 90°) and scenario B at 20° (sliding on the recession).

The first run of each contact (the relations lambdified, the tables read) is made before the timing. The verdict reads
the CPU times' ratio (the wall time carries the shared machine's load).

``--against DIR`` measures a checkout of another commit side by side (``_side_by_side.py``: each checkout in a worker
process of its own, its package first on ``PYTHONPATH``, the repetitions alternating between them, in CPU time): it
prints both checkouts' rows, CPU only, and each row's ratio before / now. E.g. ``git worktree add /tmp/before
<commit>`` then ``--against /tmp/before``.

Run: ``python benchmarks/bench_layer_punch.py [--repeat N] [--against DIR]``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from _side_by_side import measure, serve, verdict
from _timing import median_times

#: The target of issue 34: a layer run at most this many times the half-space run.
RATIO_TARGET = 2.0
#: The face's radius and the depth pressed (m).
FACE, D_MAX = 2e-3, 1e-5
#: label, the thickness (m)
BODIES = [("half-space", float("inf")), ("5 mm layer", 5e-3), ("h/a0 = 0.1", 0.1 * FACE)]
#: label, the scenario's name and its angle (°)
ROWS = [("A 90°", "A", 90.0), ("B 20°", "B", 20.0)]


def _tasks() -> dict[str, callable]:
    """Every ``"<motion>|<body>"`` of this checkout as a function to time, each run once first (the relations
    lambdified, the tables read)."""
    import dataclasses

    import mdr_events as me

    punch = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(FACE))
    tasks = {}
    for label, name, angle in ROWS:
        motion = me.Scenario(name, alpha=[angle], d_max=D_MAX)
        for body, h in BODIES:
            contact = punch.replace(h=h)

            def run(contact=contact, motion=motion):
                me.simulate(contact, motion, "continuum")

            run()  # (the first run: relations and tables)
            tasks[f"{label}|{body}"] = run
    return tasks


def _row(label: str, body: str, cpu: float, base: float, wall: float | None = None) -> str:
    """One printed row: the CPU time, the wall time where given, the ratio to the half-space and its verdict."""
    ratio = cpu / base
    shown = "" if body == "half-space" else " " + verdict(ratio, RATIO_TARGET)
    walls = "" if wall is None else f" {wall * 1e3:10.1f}"
    return f"{label:8s} {body:12s} {cpu * 1e3:9.2f}{walls} {ratio:10.2f}{shown}"


def _alone(repeat: int) -> None:
    """This checkout alone: CPU and wall medians."""
    print(f"{'motion':8s} {'body':12s} {'CPU (ms)':>9s} {'wall (ms)':>10s} {'CPU ratio':>10s}")
    tasks = _tasks()
    for label, _, _ in ROWS:
        base = None
        for body, _ in BODIES:
            wall, cpu = median_times(tasks[f"{label}|{body}"], repeat)
            base = cpu if base is None else base
            print(_row(label, body, cpu, base, wall))


def _side_by_side(repeat: int, against: str) -> None:
    """This checkout and ``against``, alternately in one run: CPU medians, each row's ratio before / now."""
    roots = {"this checkout": str(Path(__file__).resolve().parent.parent),
             f"--against {against}": str(Path(against).resolve())}
    names = [f"{label}|{body}" for label, _, _ in ROWS for body, _ in BODIES]
    medians = measure(list(roots.values()), __file__, names, repeat, cpu=True)
    print(f"flat punch, continuum: CPU medians of {repeat}, both checkouts alternately in one run")
    print(f"{'motion':8s} {'body':12s} {'CPU (ms)':>9s} {'CPU ratio':>10s}")
    for name, found in zip(roots, medians):
        print(f"  {name}:")
        for label, _, _ in ROWS:
            base = found[f"{label}|half-space"]
            for body, _ in BODIES:
                print(_row(label, body, found[f"{label}|{body}"], base))
    now, before = medians
    print("  before / now: " + ", ".join(f"{name.replace('|', ' ')} {before[name] / now[name]:.2f}x" for name in names))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--cpu", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.worker:
        serve(_tasks(), options.cpu)
    elif options.against:
        _side_by_side(options.repeat, options.against)
    else:
        _alone(options.repeat)


if __name__ == "__main__":
    main()
