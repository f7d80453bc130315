"""Fitting to measurements, a demonstration: synthetic measured curves from the paper's parameters with noise, and
the fit that recovers them from a start 30 % off (``fit_A20_R30``)."""

from __future__ import annotations

from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.fit import FitResult, fit, synthetic_measurement
from mdr_events.analysis.validate import resolve_path
from mdr_events.app.result_files import PlannedFile, dataset_plan, figure_plan
from mdr_events.parameters import Parameters
from mdr_events.plotting.fit import plot_fit
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step

__all__ = ["FIT", "FIT_STEM", "FitDemonstration", "fit_demonstration", "fit_lines", "FIT_DEMO_ANGLE", "FIT_DEMO_FREE",
           "FIT_DEMO_NOISE", "FIT_DEMO_SAMPLES", "FIT_DEMO_SEED"]

#: The fit demonstration: scenario A at this angle, R = 30 mm ...
FIT_DEMO_ANGLE = 20.0
#: ... these parameters free, started 30 % off (alternately above and below) ...
FIT_DEMO_FREE = ("E", "tau0", "dgamma0", "dgamma1")
FIT_DEMO_START_FACTORS = (1.3, 0.7, 1.3, 0.7)
#: ... on F_N, F_x and A at this many samples to 1.02 times the path's duration, with white noise of this share of
#: each quantity's largest magnitude, drawn with this seed.
FIT_DEMO_SAMPLES = 2001
FIT_DEMO_NOISE = 0.01
FIT_DEMO_SEED = 2023


class FitDemonstration(NamedTuple):
    """Synthetic measured curves from known parameters, and the fit that recovers them."""

    truth: Parameters
    start: Parameters
    measured: xr.Dataset
    result: FitResult


def fit_demonstration(truth: Parameters) -> FitDemonstration:
    """Fit :data:`FIT_DEMO_FREE` to synthetic measurements of scenario A at :data:`FIT_DEMO_ANGLE` (noise
    :data:`FIT_DEMO_NOISE`, seed :data:`FIT_DEMO_SEED`) from a start 30 % off."""
    duration = resolve_path(truth, "A", FIT_DEMO_ANGLE).duration
    times = np.linspace(0.0, 1.02 * duration, FIT_DEMO_SAMPLES)
    measured = synthetic_measurement(truth, "A", FIT_DEMO_ANGLE, times=times, relative_noise=FIT_DEMO_NOISE,
                                     seed=FIT_DEMO_SEED)
    start = truth.replace(**{name: getattr(truth, name) * factor
                             for name, factor in zip(FIT_DEMO_FREE, FIT_DEMO_START_FACTORS)})
    result = fit(measured, "A", FIT_DEMO_ANGLE, free=FIT_DEMO_FREE, start=start, time_origin="path_start")
    return FitDemonstration(truth, start, measured, result)

#: The stem of the fit demonstration's files in ``results/``.
FIT_STEM = f"fit_A{FIT_DEMO_ANGLE:g}_R30"
#: Significant digits of a fitted value in the report: its accuracy (c standard errors, 1e-7 of it here:
#: :mod:`mdr_events.analysis.fit_accuracy`) lies far below the last.
FIT_DIGITS = 5


def _estimated(value: float) -> str:
    """A fitted value to :data:`FIT_DIGITS` significant digits, trailing zeros kept, written with a fraction or an
    exponent, so that it reads as a rounded value (compared within one unit of its last digit), not as a count."""
    text = f"{value:#.{FIT_DIGITS}g}"
    return f"{value:.{FIT_DIGITS - 1}e}" if text.endswith(".") else text


def _estimate_rows(demo: FitDemonstration) -> list[list[str]]:
    rows = []
    for name, estimate in demo.result.estimates.items():
        truth = getattr(demo.truth, name)
        inside = "yes" if estimate.lower <= truth <= estimate.upper else "**no**"
        rows.append([name, f"{truth:.5g}", f"{getattr(demo.start, name):.5g}", _estimated(estimate.value),
                     f"[{_estimated(estimate.lower)}, {_estimated(estimate.upper)}]", inside,
                     estimate.identifiability.value])
    return rows


def fit_lines(demo: FitDemonstration) -> list[str]:
    """The report's section on the fit demonstration: true, start and recovered parameters with intervals."""
    fitted = demo.result
    lines = ["", "## Fitting to measurements: a demonstration", "",
             f"Synthetic \"measured\" curves: the continuum of scenario A at {FIT_DEMO_ANGLE:g}° (R = 30 mm), "
             f"F_N, F_x and A at {FIT_DEMO_SAMPLES} samples, with white noise of {FIT_DEMO_NOISE:.0%} of each "
             f"quantity's largest magnitude (seed {FIT_DEMO_SEED}; `{FIT_STEM}_measured.nc`). `mdr_events.fit` "
             f"started 30 % off and estimated the noise itself (`{FIT_STEM}.{{nc,png}}`):",
             ""]
    lines += markdown_table(["parameter", "true", "start", "fitted", "95 % interval", "truth inside", "verdict"],
                            _estimate_rows(demo),
                            ["default", "right", "right", "right", "default", "centre", "default"])
    dataset = fitted.dataset
    lines += ["", f"Verdict: {fitted.verdict}; condition number {fitted.condition_number:.1f}; reduced χ² "
                  f"{float(dataset['reduced_chi_square']):.3f}.", ""]
    return lines


def _plans(demo: FitDemonstration, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    measured = dataset_plan(demo.measured, out / f"{FIT_STEM}_measured.nc", keep_agreeing)[1]
    fitted, plan = dataset_plan(demo.result.dataset, out / f"{FIT_STEM}.nc", keep_agreeing)
    return [[measured, plan, figure_plan(plot_fit(fitted), out / f"{FIT_STEM}.png", keep_agreeing)]]


FIT = Section(
    name="fit",
    steps=(Step(f"fit of {len(FIT_DEMO_FREE)} parameters to synthetic measurements (scenario A at "
                f"{FIT_DEMO_ANGLE:g}°, {FIT_DEMO_NOISE:.0%} noise)", lambda: fit_demonstration(Parameters.paper())),),
    collect=lambda results: results[0],
    render=fit_lines,
    plan=_plans,
    writing="writing the fit (.nc, .png)",
    files=(f"- `{FIT_STEM}.{{nc,png}}`: the fit demonstration (estimates, intervals, correlations, residuals), its",
           f"  synthetic measurement in `{FIT_STEM}_measured.nc`."),
)
