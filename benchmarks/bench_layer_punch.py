"""Benchmark: the flat punch on a layer in the continuum against the half-space's flat punch, side by side (issue 34).

Prints the median CPU and wall times of ``simulate(..., method="continuum")`` of a flat punch of radius 2 mm pressed
10 µm, on the half-space, on the paper's 5 mm layer (the face comes off at once) and on a layer of ``h/a₀ = 0.1`` (the
contact recedes under the face), and each layer's ratio to the half-space (target of issue 34: a layer run at most 2×
the half-space run): vertically in and out (scenario A at 90°) and scenario B at 20° (sliding on the recession).

The first run of each contact (the relations lambdified, the tables read) is made before the timing. The verdict reads
the CPU times' ratio (the wall time carries the shared machine's load).

Run: ``python benchmarks/bench_layer_punch.py [--repeat N]``.
"""

from __future__ import annotations

import argparse
import dataclasses

import mdr_events as me

from _timing import median_times

#: The target of issue 34: a layer run at most this many times the half-space run.
RATIO_TARGET = 2.0
#: The face's radius and the depth pressed (m).
FACE, D_MAX = 2e-3, 1e-5
PUNCH = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(FACE))
#: label, the thickness (m)
BODIES = [("half-space", float("inf")), ("5 mm layer", 5e-3), ("h/a0 = 0.1", 0.1 * FACE)]
#: label, the motion
ROWS = [("A 90°", me.Scenario("A", alpha=[90.0], d_max=D_MAX)), ("B 20°", me.Scenario("B", alpha=[20.0], d_max=D_MAX))]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    print(f"{'motion':8s} {'body':12s} {'CPU (ms)':>9s} {'wall (ms)':>10s} {'CPU ratio':>10s}")
    for label, motion in ROWS:
        base = None
        for body, h in BODIES:
            contact = PUNCH.replace(h=h)

            def run(contact=contact):
                me.simulate(contact, motion, "continuum")

            run()  # (the first run: relations and tables)
            wall, cpu = median_times(run, args.repeat)
            base = cpu if base is None else base
            ratio = cpu / base
            verdict = "" if body == "half-space" else (" met" if ratio <= RATIO_TARGET else " NOT met")
            print(f"{label:8s} {body:12s} {cpu * 1e3:9.1f} {wall * 1e3:10.1f} {ratio:10.2f}{verdict}")


if __name__ == "__main__":
    main()
