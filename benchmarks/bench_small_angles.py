"""Benchmark: the continuum on random parameter sets at small angles (the reliability issue's sweep).

Draws N sets (default 1000, seed 0 onwards: E 1e5-1e10 Pa, ν 0-0.5, R 1-100 mm, τ0 1e2-1e6 Pa, Δγ0 = 0 in a
quarter of the draws else 1e-4-0.1 J/m², Δγ1 = Δγ0 + 1e-3-1 J/m², d_max 10 µm-1 mm; α log-uniform in
[1e-3°, 3°]; scenario A or B+) and runs the continuum on each, one after the other. Prints:

- how many ran, how many the resolution rule refused (travel beyond ``MAX_TRAVEL_PER_CAP`` ū) and whether
  any was refused below the limit or ran above it (both must be 0), and any other error;
- the largest ``|F_x| − τ0 A`` over the largest ``τ0 A`` of the runs, alone and in units of
  ``eps · travel / ū`` (the positions' rounding against the cap);
- the largest error of the first slip onset against (18) in scenario A where it lies before ``d_max``;
- the median and the largest time of one run.

Run: ``python benchmarks/bench_small_angles.py [N]``.
"""

from __future__ import annotations

import math
import sys
import time
from collections import Counter

import numpy as np

import mdr_events as me
from mdr_events.models.continuum import MAX_TRAVEL_PER_CAP, ContinuumModel, kinematics, resolution
from mdr_events.models.motion import scenario_paths

EPS = float(np.finfo(float).eps)


def draw(seed: int) -> tuple[me.Parameters, float, str]:
    rng = np.random.default_rng(seed)
    dgamma0 = 0.0 if rng.random() < 0.25 else 10 ** rng.uniform(-4, -1)
    params = me.Parameters(E=10 ** rng.uniform(5, 10), nu=rng.uniform(0.0, 0.5), R=10 ** rng.uniform(-3, -1),
                           tau0=10 ** rng.uniform(2, 6), dgamma0=dgamma0, dgamma1=dgamma0 + 10 ** rng.uniform(-3, 0),
                           d_max=10 ** rng.uniform(-5, -3), v=1e-6)
    return params, float(10 ** rng.uniform(-3, math.log10(3.0))), str(rng.choice(["A", "B+"]))


def one(seed: int) -> dict:
    params, alpha, scenario = draw(seed)
    path = scenario_paths(params, scenario, [alpha])[0][0]
    per_cap = resolution(ContinuumModel(params, me.Tolerances()), path, kinematics(path)).travel_per_cap
    start = time.perf_counter()
    try:
        ds = me.simulate(params, scenario, alpha=alpha, method="continuum")
    except ValueError as error:
        kind = "refused" if "allowed for the continuum method: a travel" in str(error) else f"error: {error}"
        return dict(seed=seed, kind=kind, per_cap=per_cap, seconds=time.perf_counter() - start)
    seconds = time.perf_counter() - start
    cap = params.tau0 * ds["contact_area"].values
    excess = float(np.nanmax(np.abs(ds["tangential_force"].values) - cap) / np.nanmax(cap))
    onset_error = math.nan
    depth = float(me.d_crit(alpha, params, "A", adhesion=True))
    if scenario == "A" and depth < params.d_max:
        kinds = list(ds["event_kind"].values[0])
        onset_error = abs(float(ds["event_depth"].values[0, kinds.index("slip_onset")]) - depth) / params.d_max
    return dict(seed=seed, kind="ran", per_cap=per_cap, seconds=seconds, excess=excess, onset_error=onset_error)


def main(count: int) -> None:
    results = [one(seed) for seed in range(count)]
    kinds = Counter(result["kind"] if result["kind"] in ("ran", "refused") else "error" for result in results)
    ran = [result for result in results if result["kind"] == "ran"]
    print(f"continuum on {count} random sets at 1e-3° to 3° (seeds 0-{count - 1}): {kinds['ran']} ran, "
          f"{kinds['refused']} refused by the resolution rule (travel > {MAX_TRAVEL_PER_CAP:.0e} ū), "
          f"{kinds['error']} other errors")
    wrong = [r["seed"] for r in results if (r["kind"] == "refused") != (r["per_cap"] > MAX_TRAVEL_PER_CAP)]
    print(f"  refused below the limit or run above it: {len(wrong)} {wrong[:10]}")
    for result in results:
        if result["kind"] not in ("ran", "refused"):
            print(f"  seed {result['seed']}: {result['kind'][:200]}")
    worst = max(ran, key=lambda r: r["excess"])
    ratio = max(r["excess"] / (EPS * r["per_cap"]) for r in ran if r["per_cap"] > 0)
    print(f"  largest |F_x| − τ0 A: {worst['excess']:.2e} of the largest τ0 A (seed {worst['seed']}); in units of "
          f"eps · travel/ū at most {ratio:.1f}")
    onsets = [r["onset_error"] for r in ran if not math.isnan(r["onset_error"])]
    print(f"  slip onset against (18), scenario A before d_max ({len(onsets)} runs): largest error "
          f"{max(onsets):.1e} d_max")
    seconds = np.array([r["seconds"] for r in ran])
    print(f"  time of one run: median {np.median(seconds) * 1e3:.0f} ms, largest {seconds.max():.2f} s")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1000)
