"""Benchmark: the discrete model on a layer of finite thickness against the half-space, side by side (issue 34).

Prints the median wall time of ``simulate(..., method="discrete")`` with the paper's parameters on the half-space and
on the paper's 5 mm layer (bonded base) at the same spacing and steps, and their ratio (target of issue 34: a layer
run at most 2× the half-space run, its tables precomputed and cached):

- scenario A at 20°, Δx = 1 µm, 10 000 steps (the groups with integer weights, the kernel of both);
- Fig. 8: scenario A at the eight angles 10°…80°, Δx = 1 µm, 10 000 steps;
- Fig. 10: scenario B at the eight angles, Δx = 1 µm, 10 000 steps;
- Coulomb's law (``tau0+coulomb``, μ = 0.3) at 20°, Δx = 4 µm: every spring its own cap, stepped one by one on both;
- the frictionless base, vertically in and out (scenario A at 90°), Δx = 1 µm;

and once, in a fresh process with an empty cache directory, the first layer run (scenario A at 20°, Δx = 4 µm),
which builds the layer's normal and tangential tables for ``ν = 0.5``, beside the same run with the tables on disk.

Run: ``python benchmarks/bench_layer_discrete.py [--repeat N]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import subprocess
import sys
import tempfile

import mdr_events as me

from _timing import median_time

#: The target of issue 34: a layer run at most this many times the half-space run.
RATIO_TARGET = 2.0
#: The paper's elastomer layer (m).
PAPER_LAYER = 5e-3

#: label, the motion, the spacing (m), the friction law (None: the paper's), the base
ROWS = [
    ("A 20°, 1 µm", me.Scenario("A", alpha=[20.0]), 1e-6, None, "bonded"),
    ("Fig. 8 (8 angles), 1 µm", me.Scenario("A"), 1e-6, None, "bonded"),
    ("Fig. 10 (8 angles), 1 µm", me.Scenario("B"), 1e-6, None, "bonded"),
    ("A 20°, tau0+coulomb, 4 µm", me.Scenario("A", alpha=[20.0]), 4e-6, "tau0+coulomb", "bonded"),
    ("A 90°, frictionless base", me.Scenario("A", alpha=[90.0]), 1e-6, None, "frictionless"),
]

#: The first run on a layer in a fresh process: the tables built (cold) or read from disk (warm).
FIRST_RUN = """
import time
import mdr_events as me
me.simulate(me.Contact.paper(), me.Scenario("A", alpha=[20.0]), "discrete", dx=4e-6)  # imports, derivations
start = time.perf_counter()
me.simulate(me.Contact.paper().replace(h=5e-3), me.Scenario("A", alpha=[20.0]), "discrete", dx=4e-6)
print(time.perf_counter() - start)
"""


def contacts(law: str | None, base: str) -> tuple[me.Contact, me.Contact]:
    """The paper's contact on the half-space and on the 5 mm layer, with the friction law ``law``."""
    half = me.Contact.paper()
    if law is not None:
        half = dataclasses.replace(half, friction=me.FrictionLaw(law, tau0=half.friction.tau0, mu=0.3))
    return half, half.replace(h=PAPER_LAYER, **{"layer.base": base})


def first_run(cache: str) -> float:
    """The first layer run's time in a fresh process whose cache directory is ``cache`` (s)."""
    environment = dict(os.environ, MDR_EVENTS_CACHE_DIR=cache)
    found = subprocess.run([sys.executable, "-c", FIRST_RUN], capture_output=True, text=True, check=True,
                           env=environment)
    return float(found.stdout.split()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    repeat = parser.parse_args().repeat
    print(f"mdr_events {me.__version__}: discrete model, paper parameters, half-space vs a {PAPER_LAYER * 1e3:g} mm "
          f"layer; medians of {repeat} calls")
    print(f"{'case':28s} {'springs':>7s} {'half-space':>11s} {'layer':>9s} {'ratio':>6s} target <= {RATIO_TARGET:g}")
    for label, motion, dx, law, base in ROWS:
        half, layer = contacts(law, base)
        runs = {name: (lambda contact=contact: me.simulate(contact, motion, "discrete", dx=dx))
                for name, contact in (("half", half), ("layer", layer))}
        springs = int(runs["layer"]().attrs["spring_count_per_side"])  # (and the tables loaded)
        runs["half"]()
        times = {name: median_time(run, repeat) for name, run in runs.items()}
        ratio = times["layer"] / times["half"]
        verdict = "ok" if ratio <= RATIO_TARGET else "over"
        print(f"{label:28s} {springs:7d} {times['half']:9.3f} s {times['layer']:7.3f} s {ratio:5.2f}x {verdict}")
    with tempfile.TemporaryDirectory() as cache:
        cold, warm = first_run(cache), first_run(cache)
    print(f"first layer run in a fresh process (A 20°, 4 µm): {cold:.2f} s building the tables (ν = 0.5, bonded: "
          f"normal and tangential), {warm:.2f} s with them on disk")


if __name__ == "__main__":
    main()
