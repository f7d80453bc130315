"""Benchmark: a steep cone on a layer under ``tau0+coulomb`` against the paraboloid, side by side (issue 32, round
twenty-five's X5).

Prints the median CPU time (``time.process_time``) of ``simulate(contact, "A", [45.0], "continuum")`` at the default
samples on a 2 mm layer under ``FrictionLaw("tau0+coulomb", mu=0.5)`` for the paper's paraboloid and for
``PowerLaw(0.5, 1)`` (a cone: the golden sections of every spring's own extremes, :mod:`.play_golden`), the runs
alternating, and their ratio (target: at most 5×; 12.1× before the sections' shortcuts). The first run of each (the
layer's tables and relations made) is made before the timing.

Run: ``python benchmarks/bench_cone_layer.py [--repeat N] [--samples N]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import statistics
import time

import mdr_events as me


def _contacts() -> dict[str, me.Contact]:
    paraboloid = dataclasses.replace(me.Contact.paper(), layer=me.Layer(2e-3),
                                     friction=me.FrictionLaw("tau0+coulomb", tau0=me.Parameters.paper().tau0, mu=0.5))
    return {"paraboloid": paraboloid, "cone": dataclasses.replace(paraboloid, indenter=me.PowerLaw(0.5, 1.0))}


def _cpu(contact: me.Contact, samples: int | None) -> float:
    keywords = {} if samples is None else {"samples": samples}
    start = time.process_time()
    me.simulate(contact, "A", [45.0], "continuum", **keywords)
    return time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--samples", type=int, default=None, help="the continuum's samples (default: its own)")
    arguments = parser.parse_args()
    contacts = _contacts()
    times: dict[str, list[float]] = {name: [] for name in contacts}
    for name, contact in contacts.items():
        _cpu(contact, arguments.samples)  # (the first run: tables and relations made)
    for _ in range(arguments.repeat):
        for name, contact in contacts.items():
            times[name].append(_cpu(contact, arguments.samples))
    medians = {name: statistics.median(values) for name, values in times.items()}
    for name, value in medians.items():
        print(f"{name:>10}: {value:.2f} s CPU (median of {arguments.repeat})")
    print(f"ratio cone / paraboloid: {medians['cone'] / medians['paraboloid']:.1f} (target <= 5)")


if __name__ == "__main__":
    main()
