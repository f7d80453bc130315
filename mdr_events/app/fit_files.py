"""Fit files: a :class:`~mdr_events.analysis.fit.FitResult` written as ``<stem>.nc``, ``<stem>.md``, ``<stem>.png``.

- ``<stem>.nc``: the fit's dataset (:func:`mdr_events.io.files.write_netcdf`; ``open_result`` reads it back);
- ``<stem>.md``: a Markdown summary: the verdict, the estimates with their standard errors, 95 % intervals
  and identifiability, the notes, the noise and residuals per quantity, the correlations;
- ``<stem>.png``: :func:`mdr_events.plotting.fit.plot_fit`.

Rendered first, written after (:func:`~mdr_events.app.validation_files.write_rendered`, each file atomic), as
the validation files: a fit that fails writes nothing. Used by ``mdr-events fit`` and the ``[fit]`` table of
study files.
"""

from __future__ import annotations

import math
import os

import numpy as np
import xarray as xr

from mdr_events.io.datasets import read_text_list
from mdr_events.analysis.fit import OptimizerRun
from mdr_events.app.validation_files import VALIDATION_SUFFIXES, RenderedReport
from mdr_events.parameters import PARAMETER_UNITS
from mdr_events.plotting.figures import figure_png
from mdr_events.plotting.fit import plot_fit

__all__ = ["FIT_SUFFIXES", "fit_markdown", "fit_console_summary", "render_fit"]

#: The files of one fit, by suffix: those of a validated run.
FIT_SUFFIXES = VALIDATION_SUFFIXES


def _value(number: float, unit: str) -> str:
    if not math.isfinite(number):
        return "∞" if number > 0 else "−∞" if number < 0 else "—"
    return f"{number:.6g}" + (f" {unit}" if unit != "1" else "")


def _estimate_rows(fit: xr.Dataset) -> list[str]:
    rows = ["| parameter | start | estimate | standard error | 95 % interval | verdict |",
            "|---|---:|---:|---:|---|---|"]
    for name in fit["parameter"].values:
        row = fit.sel(parameter=name)
        unit = str(row["parameter_units"].values)
        verdict = str(row["identifiability"].values)
        rows.append(f"| {name} | {_value(float(row['start']), unit)} | {_value(float(row['estimate']), unit)} | "
                    f"{_value(float(row['standard_error']), unit)} | [{_value(float(row['lower_95']), unit)}, "
                    f"{_value(float(row['upper_95']), unit)}] | {verdict if verdict == 'determined' else f'**{verdict}**'} |")
    return rows


def fit_markdown(fit: xr.Dataset, stem: str | None = None) -> str:
    """The Markdown summary of a fit (``<stem>.md``; ``stem`` names the figure beside it)."""
    source = str(fit.attrs.get("measured_source", "measurement"))
    lines = [f"# Fit of the model to `{os.path.basename(source)}`", "",
             f"**{fit.attrs['verdict'][0].upper()}{fit.attrs['verdict'][1:]}.**", "",
             f"- Measured: `{source}`; time origin {fit.attrs.get('time_origin', '?')}",
             f"- Path: {fit.attrs.get('path_description', fit.attrs.get('path_waypoints', '?'))}",
             f"- Free: {fit.attrs['free']}; the other parameters as given: " + ", ".join(
                 f"{name} = {fit.attrs[f'param_{name}']:g}" + (f" {unit}" if unit != "1" else "")
                 for name, unit in PARAMETER_UNITS.items()
                 if name not in str(fit.attrs["free"]).split(", ") and f"param_{name}" in fit.attrs),
             f"- Condition number of the weighted Jacobian: {float(fit['condition_number']):.4g}; reduced χ²: "
             f"{float(fit['reduced_chi_square']):.4g}",
             f"- Optimizer: {'converged' if int(fit.attrs.get('optimizer_converged', 0)) else '**did not converge**'}",
             "",
             "## Estimates", "", f"Intervals at {100 * float(fit.attrs.get('confidence', 0.95)):g} % from the "
             "Jacobian at the optimum (asymmetric for the log-scaled parameters).", ""]
    lines += _estimate_rows(fit)
    free = str(fit.attrs["free"]).split(", ")
    if "E" in free or "nu" in free:
        lines += ["", f"Effective moduli at the fit: E* = {float(fit['E_star']):.6g} ± "
                      f"{float(fit['E_star_standard_error']):.3g} Pa, G* = {float(fit['G_star']):.6g} ± "
                      f"{float(fit['G_star_standard_error']):.3g} Pa."]
    warnings = read_text_list(fit.attrs, "warnings")
    if warnings:
        lines += ["", "## Warnings: the fit does not describe the data", "",
                  "The intervals above assume it does; fix these first.", ""] + \
            [f"- **{warning}**" for warning in warnings]
    notes = read_text_list(fit.attrs, "notes")
    if notes:
        lines += ["", "## Notes", ""] + [f"- {note}" for note in notes]
    lines += ["", "## Residuals", "", "| quantity | noise σ | source | RMS residual / σ |", "|---|---:|---|---:|"]
    for name in fit["quantity"].values:
        row = fit.sel(quantity=name)
        unit = str(fit[f"measured_{name}"].attrs.get("units", ""))
        lines.append(f"| {name} | {float(row['noise']):.4g} {unit} | "
                     f"{'given' if int(row['noise_given']) else 'estimated'} | {float(row['rms_normalised_residual']):.4g} |")
    left_out = int(np.count_nonzero(fit["left_out"].values))
    lines += ["", f"Samples left out of some quantity: {left_out} of {fit.sizes['time']} "
                  f"({fit.attrs.get('out_of_contact_rule', '')})."]
    names = [str(name) for name in fit["parameter"].values]
    if len(names) > 1:
        lines += ["", "## Correlations", "", "| | " + " | ".join(names) + " |", "|---|" + "---:|" * len(names)]
        for i, name in enumerate(names):
            cells = [f"{value:+.3f}" if math.isfinite(value) else "—" for value in fit["correlation"].values[i]]
            lines.append(f"| {name} | " + " | ".join(cells) + " |")
    if stem is not None:
        lines += ["", f"![measured and fitted curves, residuals below]({stem}.png)", "",
                  f"The whole fit: `{stem}.nc` (`mdr_events.open_result`)."]
    return "\n".join(lines) + "\n"


def fit_console_summary(fit: xr.Dataset, name: str, optimizer: OptimizerRun | None = None) -> list[str]:
    """A few lines for the terminal: the verdict (with the optimizer's log, if given) and each estimate with its
    interval."""
    lines = [f"{name}: {fit.attrs['verdict']}" + ("" if optimizer is None else f" ({optimizer.describe()})")]
    lines += [f"  warning: {warning}" for warning in read_text_list(fit.attrs, "warnings")]
    for parameter in fit["parameter"].values:
        row = fit.sel(parameter=parameter)
        unit = str(row["parameter_units"].values)
        lines.append(f"  {parameter} = {_value(float(row['estimate']), unit)}, 95 % [{_value(float(row['lower_95']), unit)}"
                     f", {_value(float(row['upper_95']), unit)}] ({row['identifiability'].values})")
    return lines


def render_fit(fit: xr.Dataset, stem: str) -> RenderedReport:
    """The files of a fit, computed but not written: the Markdown text and the figure's PNG bytes."""
    return RenderedReport(stem, fit, fit_markdown(fit, stem), figure_png(plot_fit(fit)))
