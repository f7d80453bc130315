"""Benchmark: the discrete spring model, one path, Fig. 8 and a fine spacing side by side.

Prints, for ``mdr_events.simulate(..., method="discrete")`` with the paper's
parameters, the median wall time against its target (issue 17):

- one path at Δx = 1 µm: scenario A at 20° (target < 0.1 s) and B at 20°,
  10 000 steps; the zigzag custom path, 20 000 steps;
- Fig. 8: scenario A, the eight angles 10°…80°, Δx = 1 µm, 10 000 steps
  (target < 0.3 s);
- one path (scenario A at 20°) at Δx = 0.25 µm, 100 000 steps (target < 5 s),

and next to it the same call stepped spring by spring (the plain per-step
numpy loop over the springs, ``discrete._run_case_per_spring``: one call, for
the 1 µm rows), the spring updates per second (springs in contact × samples:
the work of stepping every spring, over the median time), the peak memory of
one call (tracemalloc, outputs and dataset included) and the peak of the
stepping alone beyond its outputs (the springs' state and one block of
samples; it grows with the springs, not with the steps).

Run: ``python benchmarks/bench_discrete.py``.
"""

from __future__ import annotations

import contextlib
import statistics
import time
import tracemalloc

import numpy as np

import mdr_events as me
from mdr_events.models import discrete
from mdr_events.models.methods import Discrete
from mdr_events.contact.adhesion import law_of
from mdr_events.contact.friction import as_friction_law
from mdr_events.models.motion import simulation_cases
from mdr_events.models.simulate import simulate

ZIGZAG = me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], 1e-6)

#: label, simulate arguments, target median (s) or None, whether to time the spring-by-spring stepping, repeats
ROWS = [
    ("A 20°, 1 µm", dict(motion="A", alpha=[20.0], dx=1e-6, n_steps=10_000), 0.1, True, 7),
    ("B 20°, 1 µm", dict(motion="B", alpha=[20.0], dx=1e-6, n_steps=10_000), None, True, 7),
    ("zigzag, 1 µm", dict(motion=ZIGZAG, dx=1e-6, n_steps=20_000), None, True, 7),
    ("Fig. 8 (8 angles), 1 µm", dict(motion="A", dx=1e-6, n_steps=10_000), 0.3, True, 7),
    ("A 20°, 0.25 µm", dict(motion="A", alpha=[20.0], dx=0.25e-6, n_steps=100_000), 5.0, False, 3),
]


@contextlib.contextmanager
def spring_by_spring():
    """``run_discrete`` with the per-spring reference stepping in place of the kernel."""
    kernel = discrete._run_case
    discrete._run_case = discrete._run_case_per_spring
    try:
        yield
    finally:
        discrete._run_case = kernel


def timed(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def peak_memory(function) -> float:
    """Peak traced memory of one call, MB."""
    tracemalloc.start()
    try:
        function()
        return tracemalloc.get_traced_memory()[1] / 1e6
    finally:
        tracemalloc.stop()


def stepping_peak(p, kwargs) -> float:
    """Peak traced memory of the stepping of each case beyond its preallocated outputs (largest case), kB."""
    paths = simulation_cases(p, kwargs["motion"], kwargs.get("alpha")).paths
    run = discrete._prepare(p, paths, kwargs["dx"], Discrete(n_steps=kwargs["n_steps"])._time_step(paths),
                            discrete.paraboloid_profile(p), as_friction_law(None), law_of(p))
    n = run.time.size
    peaks = []
    for case in range(len(paths)):
        outputs = np.zeros(n, np.int64), np.zeros(n), np.zeros(n, np.int64)
        peaks.append(1e3 * peak_memory(lambda: discrete._run_case(
            run.grid, run.x[:, case], run.d[:, case], run.time, int(run.last_sample[case]),
            float(run.last_entries[case]), *outputs)))
    return max(peaks)


def main() -> None:
    p = me.Parameters.paper()
    simulate(p, "A", alpha=[30.0], dx=1e-5, n_steps=100)  # build the lambdified relations once
    print(f"mdr_events {me.__version__}: discrete model, paper parameters, simulate(..., method='discrete'); "
          "medians of 7 calls (0.25 µm: 3)")
    header = (f"{'case':24s} {'springs':>7s} {'steps':>7s} {'median':>9s} {'target':>8s} {'':4s} "
              f"{'spring by spring':>16s} {'ratio':>6s} {'updates/s':>10s} {'peak MB':>8s} {'stepping kB':>11s}")
    print(header)
    print("-" * len(header))
    for label, kwargs, target, reference, repeat in ROWS:
        run = lambda: simulate(p, method="discrete", **kwargs)  # noqa: E731
        ds = run()
        median = statistics.median(timed(run) for _ in range(repeat))
        springs = ds.attrs["spring_count_per_side"]
        updates = float(np.nansum(ds["contact_radius"].values) / ds.attrs["dx"])  # Σ springs in contact
        verdict = "" if target is None else ("ok" if median < target else "MISS")
        if reference:
            with spring_by_spring():
                slow = timed(run)
            versus = f"{slow:14.2f} s {slow / median:5.0f}x"
        else:
            versus = f"{'(not run)':>16s} {'':>6s}"
        print(f"{label:24s} {springs:7d} {ds.sizes['time'] - 1:7d} {median:7.3f} s "
              f"{'< %g s' % target if target else '':>8s} {verdict:4s} {versus} {updates / median:10.3g} "
              f"{peak_memory(run):8.1f} {stepping_peak(p, kwargs):11.0f}")


if __name__ == "__main__":
    main()
