"""Benchmark: fitting the model to measured curves (``fit``).

Prints, measured side by side in one run (medians; the machine is shared and noisy):

- the issue's target: ``fit`` of 4 parameters (``E``, ``tau0``, ``dgamma0``, ``dgamma1``) to 2001 samples
  of ``F_N``, ``F_x`` and ``A`` (``synthetic_measurement``, 1 % noise, seed 7; scenario A at 20°, times
  0 … 1.02 × the path's duration, ``time_origin="path_start"``) from a start 30 % off (the parameters
  multiplied alternately by 1.3 and 0.7): the median wall time of 5 (target: under 2 s), and the fit's
  number of continuum solves and of optimizer evaluations;
- the median cost of one continuum solve + evaluation at the 2001 samples (``model_curves``, median of 7)
  and the ratio fit time / (solves × one solve): the fit's overhead beyond its solves;
- the same fit without noise: its median time of 5 and the largest relative error of the 4 estimates.

Run: ``python benchmarks/bench_fit.py``.
"""

from __future__ import annotations

import numpy as np

import mdr_events as me
from _timing import median_time
from mdr_events.analysis.fit import model_curves, synthetic_measurement
from mdr_events.analysis.validate import resolve_path
from mdr_events.limits import DEFAULT_LIMITS

#: The free parameters of the issue's target.
FREE = ("E", "tau0", "dgamma0", "dgamma1")
#: Factors applied alternately to the free parameters for the start (30 % off).
START_FACTORS = (1.3, 0.7)
#: Repeats of the fit (about 1 s each).
FIT_REPEAT = 5
SAMPLES = 2001
QUANTITIES = ("normal_force", "tangential_force", "contact_area")


def main() -> None:
    p = me.Parameters.paper()
    scenario, alpha = "A", 20.0
    path = resolve_path(p, scenario, alpha)
    times = np.linspace(0.0, 1.02 * path.duration, SAMPLES)
    start = p.replace(**{name: getattr(p, name) * START_FACTORS[i % 2] for i, name in enumerate(FREE)})

    def measurement(relative_noise: float):
        return synthetic_measurement(p, scenario, alpha, times=times, relative_noise=relative_noise, seed=7)

    def run_fit(data):
        return me.fit(data, scenario, alpha, free=FREE, start=start, time_origin="path_start")

    noisy = measurement(0.01)
    result = run_fit(noisy)  # builds the lambdified relations once; the counts are the same every run
    solves = result.optimizer.continuum_solves
    evaluations = result.optimizer.evaluations
    fit_time = median_time(lambda: run_fit(noisy), repeat=FIT_REPEAT)
    one_solve = median_time(lambda: model_curves(p, path, times, me.Tolerances(), DEFAULT_LIMITS, QUANTITIES))
    print(f"mdr_events {me.__version__}: fit of {len(FREE)} parameters ({', '.join(FREE)}), scenario {scenario} at "
          f"{alpha:g}°, {SAMPLES} samples of F_N, F_x, A, start 30 % off")
    print(f"  1 % noise:  fit {fit_time:6.2f} s (median of {FIT_REPEAT}; target < 2 s); {solves} continuum solves, "
          f"{evaluations} optimizer evaluations")
    print(f"  one continuum solve + evaluation at {SAMPLES} samples {one_solve * 1e3:.1f} ms (median of 7); "
          f"fit / (solves x one solve) = {fit_time / (solves * one_solve):.2f} (1 = no overhead beyond the solves)")

    clean = measurement(0.0)
    result = run_fit(clean)
    clean_time = median_time(lambda: run_fit(clean), repeat=FIT_REPEAT)
    estimates = result.estimates
    errors = {name: abs(estimates[name].value - getattr(p, name)) / abs(getattr(p, name)) for name in FREE}
    worst = max(errors, key=errors.get)
    print(f"  no noise:   fit {clean_time:6.2f} s (median of {FIT_REPEAT}); {result.optimizer.continuum_solves} "
          f"continuum solves, {result.optimizer.evaluations} optimizer evaluations; largest "
          f"relative error of the estimates {errors[worst]:.1e} ({worst})")


if __name__ == "__main__":
    main()
