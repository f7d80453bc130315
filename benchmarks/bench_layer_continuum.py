"""Benchmark: the continuum on a layer of finite thickness against the half-space, side by side (issue 34).

Prints the median wall time of ``simulate(..., method="continuum")`` with the paper's parameters on the half-space and
on the paper's 5 mm layer (bonded base), and their ratio (target of issue 34: a layer run at most 2× the half-space
run, its tables precomputed and cached):

- scenario A at 20° (2001 samples);
- Fig. 8: scenario A at the eight angles 10°…80°;
- Fig. 10: scenario B at the eight angles;
- a fretting loop at the paper's ``d_max`` (three cycles of ±20 µm: full slip and re-stick on every reversal);
- the frictionless base, vertically in and out (scenario A at 90°);
- Coulomb's part without adhesion (``"coulomb"``, ``"tau0+coulomb"``, μ = 0.3, ``Δγ0 = Δγ1 = 0``) along scenario A at
  20° and a fretting path of ±1 mm: on the layer every spring's play operator on its own
  (:mod:`mdr_events.models.continuum.play_run`), on the half-space the spans; :data:`COULOMB_SAMPLES` samples (the
  route reads them in batches: 0.03-0.11 s of CPU a run, the output times' evaluations and the events' sequential
  searches);
- the same with the paper's adhesion along scenario A at 20°, :data:`ADHESIVE_SAMPLES` samples (the route's radius
  the spans' frictionless run: 0.03-0.1 s of CPU a run; with ``τ0`` a third of it the radius at each spring's own
  crossings of ``d = g``).

The layer's first run of a process (the relations of ``theory/layer_continuum_symbolic.py`` lambdified, the tables
read) is made before the timing, as the half-space's own derivations are. Beside the wall times the process's CPU
times (``time.process_time``, medians too): on a machine shared with other work the wall time carries their load, so
the verdict reads the CPU times' ratio.

``--against DIR`` measures a checkout of another commit side by side (``_side_by_side.py``: each checkout in a worker
process of its own, the repetitions alternating, CPU time) and prints each row's CPU times and ratio to the half-space
in both, and the layer's time before / now.

Run: ``python benchmarks/bench_layer_continuum.py [--repeat N] [--only TEXT] [--against DIR]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import statistics
import time
from pathlib import Path

import numpy as np

import mdr_events as me

from _side_by_side import measure, serve
from _timing import median_time

#: The target of issue 34: a layer run at most this many times the half-space run.
RATIO_TARGET = 2.0
#: The paper's elastomer layer (m).
PAPER_LAYER = 5e-3


def fretting() -> me.Paths:
    """In to the paper's ``d_max``, three tangential cycles of ±20 µm there, and out."""
    d_max = me.Parameters.paper().d_max
    x = np.concatenate([[0.0, 0.0], np.tile([20e-6, -20e-6], 3), [0.0, 0.0]])
    d = np.concatenate([[-1e-6, d_max], np.full(6, d_max), [d_max, -1e-4]])
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


#: The output samples of the Coulomb rows.
COULOMB_SAMPLES = 201


def coulomb_fretting() -> me.Paths:
    """In to the paper's ``d_max``, two tangential cycles of ±1 mm there (full slip under Coulomb's law), and out."""
    d_max = me.Parameters.paper().d_max
    x = [0.0, 0.0, 1e-3, -1e-3, 1e-3, 0.0, 0.0]
    d = [0.0, d_max, d_max, d_max, d_max, d_max, -1e-5]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), me.Parameters.paper().v)})


#: The output samples of the Coulomb rows with adhesion.
ADHESIVE_SAMPLES = 21
#: label, the motion, the friction law, whether adhesive (the Coulomb rows)
COULOMB_ROWS = [(f"{law} {label}", motion, law, False) for law in ("coulomb", "tau0+coulomb")
                for label, motion in (("A 20°", me.Scenario("A", alpha=[20.0])), ("fretting ±1 mm", coulomb_fretting()))]
COULOMB_ROWS += [(f"{law} A 20°, adhesive", me.Scenario("A", alpha=[20.0]), law, True)
                 for law in ("coulomb", "tau0+coulomb")]
#: label, the motion, the base
ROWS = [
    ("A 20°", me.Scenario("A", alpha=[20.0]), "bonded"),
    ("Fig. 8 (8 angles)", me.Scenario("A"), "bonded"),
    ("Fig. 10 (8 angles)", me.Scenario("B"), "bonded"),
    ("fretting ±20 µm, 3 cycles", fretting(), "bonded"),
    ("A 90°, frictionless base", me.Scenario("A", alpha=[90.0]), "frictionless"),
]


def median_cpu_time(function, repeat: int) -> float:
    """Median CPU time of this process in s over ``repeat`` calls of ``function``."""
    times = []
    for _ in range(repeat):
        start = time.process_time()
        function()
        times.append(time.process_time() - start)
    return statistics.median(times)


def _cases(only: str) -> list[tuple]:
    """The rows whose label holds ``only``: label, motion, the half-space's contact, the layer's base, options."""
    cases = [(label, motion, me.Contact.paper(), base, {}) for label, motion, base in ROWS]
    for label, motion, law, adhesive in COULOMB_ROWS:
        friction = me.FrictionLaw(law, mu=0.3, tau0=None if law == "coulomb" else me.Parameters.paper().tau0)
        paper = me.Contact.paper() if adhesive else me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)
        samples = ADHESIVE_SAMPLES if adhesive else COULOMB_SAMPLES
        cases.append((label, motion, dataclasses.replace(paper, friction=friction), "bonded", {"samples": samples}))
    return [case for case in cases if only in case[0]]


def _runs(case) -> dict:
    """The half-space's and the layer's run of a row, each run once (derivations, tables, lambdified relations)."""
    _, motion, half, base, options = case
    layer = half.replace(h=PAPER_LAYER, **{"layer.base": base})
    runs = {name: (lambda contact=contact: me.simulate(contact, motion, "continuum", **options))
            for name, contact in (("half", half), ("layer", layer))}
    for run in runs.values():
        run()
    return runs


#: The environment variable that passes ``--only`` to the workers of ``--against``.
_ONLY = "BENCH_LAYER_CONTINUUM_ONLY"


def _side_by_side(arguments) -> None:
    """``--against``: both checkouts' CPU times of the rows, the repetitions alternating (``_side_by_side.py``)."""
    roots = {"now": str(Path(__file__).resolve().parent.parent), "before": str(Path(arguments.against).resolve())}
    os.environ[_ONLY] = arguments.only
    tasks = [f"{case[0]}|{name}" for case in _cases(arguments.only) for name in ("half", "layer")]
    now, before = measure(list(roots.values()), __file__, tasks, arguments.repeat, cpu=True)
    print(f"CPU time, medians of {arguments.repeat}, interleaved with --against {arguments.against}")
    print(f"{'case':28s} {'before: half':>12s} {'layer':>8s} {'ratio':>6s} {'now: half':>10s} {'layer':>8s} {'ratio':>6s} "
          f"{'layer before/now':>16s}")
    for case in _cases(arguments.only):
        half, layer = (f"{case[0]}|{name}" for name in ("half", "layer"))
        print(f"{case[0]:28s} {before[half]:10.3f} s {before[layer]:6.3f} s {before[layer] / before[half]:5.2f}x "
              f"{now[half]:8.3f} s {now[layer]:6.3f} s {now[layer] / now[half]:5.2f}x {before[layer] / now[layer]:15.2f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--only", default="", help="the rows whose label holds this text (default: every row)")
    parser.add_argument("--against", default=None, metavar="DIR", help="a checkout to measure side by side (CPU)")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--cpu", action="store_true", help=argparse.SUPPRESS)
    arguments = parser.parse_args()
    if arguments.worker:
        serve({f"{case[0]}|{name}": run for case in _cases(os.environ.get(_ONLY, ""))
               for name, run in _runs(case).items()}, arguments.cpu)
        return
    if arguments.against:
        _side_by_side(arguments)
        return
    repeat = arguments.repeat
    print(f"mdr_events {me.__version__}: continuum, paper parameters, half-space vs a {PAPER_LAYER * 1e3:g} mm layer; "
          f"medians of {repeat} calls")
    print(f"{'case':28s} {'half-space':>11s} {'layer':>9s} {'ratio':>6s} {'CPU: half':>10s} {'layer':>8s} {'ratio':>6s} "
          f"target <= {RATIO_TARGET:g}")
    for case in _cases(arguments.only):
        label = case[0]
        runs = _runs(case)
        times = {name: median_time(run, repeat) for name, run in runs.items()}
        cpu = {name: median_cpu_time(run, repeat) for name, run in runs.items()}
        ratio, cpu_ratio = times["layer"] / times["half"], cpu["layer"] / cpu["half"]
        verdict = "ok" if cpu_ratio <= RATIO_TARGET else "over"
        print(f"{label:28s} {times['half']:9.3f} s {times['layer']:7.3f} s {ratio:5.2f}x {cpu['half']:8.3f} s "
              f"{cpu['layer']:6.3f} s {cpu_ratio:5.2f}x {verdict}")


if __name__ == "__main__":
    main()
