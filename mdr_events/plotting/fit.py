"""The figure of a fit (:func:`mdr_events.fit`): the measured curves with the fitted ones, and the residuals.

Drawn from the fit's dataset only (never recomputed); registered for ``FitResult.plot()``
(:func:`mdr_events.io.datasets.register_figure`).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.analysis.fit import FIT_CONTENT
from mdr_events.io.datasets import register_figure
from mdr_events.plotting.figures import LEGEND_BORDER_PAD, LEGEND_FONTSIZE, add_inferred_footnote
from mdr_events.plotting.validation import VALIDATION_PANELS

__all__ = ["plot_fit"]

MEASURED_STYLE = dict(color="0.55", marker=".", ls="none", ms=2.5, zorder=2)
FITTED_STYLE = dict(color="crimson", lw=1.4, zorder=3)
RESIDUAL_STYLE = dict(color="0.35", marker=".", ls="none", ms=2.0, zorder=2)
NOISE_BAND_STYLE = dict(color="tab:green", alpha=0.15, lw=0, zorder=0)


def _estimate_line(fit: xr.Dataset, name: str) -> str:
    row = fit.sel(parameter=name)
    unit = str(row["parameter_units"].values)
    value, low, high = float(row["estimate"]), float(row["lower_95"]), float(row["upper_95"])
    verdict = str(row["identifiability"].values)
    return f"{name} = {value:.5g} {unit} [{low:.4g}, {high:.4g}] ({verdict})"


def plot_fit(fit: xr.Dataset, title: str | None = None) -> Figure:
    """Measured and fitted curves against time (top) and the residuals with the ±2σ noise band (below).

    Parameters
    ----------
    fit : xarray.Dataset
        The dataset of a :class:`mdr_events.analysis.fit.FitResult`.
    title : str, optional
        Default: the verdict; the estimates with their 95 % intervals are listed below the title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    quantities = [str(q) for q in fit["quantity"].values]
    figure, axes = plt.subplots(2, len(quantities), figsize=(4.2 * len(quantities), 6.2), squeeze=False,
                                sharex="col", gridspec_kw={"height_ratios": (2.2, 1.0)}, layout="constrained")
    time = fit["time"].values
    for column, name in enumerate(quantities):
        scale, symbol, unit = VALIDATION_PANELS[name]
        top, bottom = axes[0, column], axes[1, column]
        top.plot(time, fit[f"measured_{name}"].values * scale, label="measured", **MEASURED_STYLE)
        top.plot(time, fit[f"fitted_{name}"].values * scale, label="fitted (continuum)", **FITTED_STYLE)
        top.set_ylabel(f"{symbol} ({unit})")
        top.legend(fontsize=LEGEND_FONTSIZE, borderpad=LEGEND_BORDER_PAD)
        noise = 2.0 * float(fit["noise"].sel(quantity=name)) * scale
        bottom.axhspan(-noise, noise, label="±2σ noise", **NOISE_BAND_STYLE)
        bottom.plot(time, fit[f"residual_{name}"].values * scale, **RESIDUAL_STYLE)
        bottom.axhline(0.0, color="k", lw=0.6)
        bottom.set_ylabel(f"residual ({unit})")
        bottom.set_xlabel("measured time (s)")
        bottom.legend(fontsize=LEGEND_FONTSIZE, borderpad=LEGEND_BORDER_PAD, loc="upper left")
    lines = [_estimate_line(fit, str(name)) for name in fit["parameter"].values]
    heading = title if title is not None else f"Fit: {fit.attrs['verdict']}"
    figure.suptitle("\n".join([heading] + lines), fontsize=9)
    add_inferred_footnote(figure, fit)
    return figure

register_figure(FIT_CONTENT, plot_fit)
