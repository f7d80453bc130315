"""The figure of a validation report (:func:`mdr_events.validate`): candidate against exact, and the difference.

Drawn from the report only (never recomputed); the matplotlib backend is left alone (the CLI selects
Agg itself).
"""

from __future__ import annotations

import os

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.analysis.validate import LEFT_OUT_CODES
from mdr_events.plotting.figures import LEGEND_BORDER_PAD, LEGEND_FONTSIZE, add_inferred_footnote

__all__ = ["plot_validation", "VALIDATION_PANELS"]

#: Quantity -> (scale to display units, symbol, display unit); another quantity is drawn in its SI unit.
VALIDATION_PANELS: dict[str, tuple[float, str, str]] = {
    "normal_force": (1e3, "$F_N$", "mN"),
    "tangential_force": (1e3, "$F_x$", "mN"),
    "contact_area": (1e6, "$A$", "mm²"),
    "contact_radius": (1e3, "$a$", "mm"),
}
#: Styles: the exact continuum as a line, the candidate as open markers on a thin line, the left-out samples
#: by their code (:data:`mdr_events.analysis.validate.LEFT_OUT_CODES`), the continuum's events as dotted lines.
EXACT_STYLE = dict(color="k", lw=1.3, zorder=2)
CANDIDATE_STYLE = dict(color="crimson", lw=0.7, ls=(0, (4, 3)), marker="o", ms=3.5, mfc="none", mew=0.8, zorder=3)
DIFFERENCE_STYLE = dict(color="crimson", lw=0.9, zorder=3)
LEFT_OUT_STYLES = {2: dict(color="tab:orange", marker="x", ls="none", ms=6, mew=1.3, zorder=4),
                   3: dict(color="tab:blue", marker="+", ls="none", ms=8, mew=1.3, zorder=4)}
EVENT_STYLE = dict(color="0.55", lw=0.8, ls=":", zorder=1)
TOLERANCE_STYLE = dict(color="tab:green", alpha=0.15, lw=0, zorder=0)
#: Open markers on the candidate's line: about this many per curve.
CANDIDATE_MARKERS_PER_CURVE = 40


def _display(report: xr.Dataset, name: str) -> tuple[float, str, str]:
    if name in VALIDATION_PANELS:
        return VALIDATION_PANELS[name]
    return 1.0, name.replace("_", " "), str(report[f"exact_{name}"].attrs.get("units", ""))


def plot_validation(report: xr.Dataset, title: str | None = None) -> Figure:
    """Candidate and exact against time (top) and their difference (below), one column per quantity compared.

    Parameters
    ----------
    report : xarray.Dataset
        Output of :func:`mdr_events.validate`.
    title : str, optional
        Default: the candidate's file name, the verdict and the tolerance.

    Returns
    -------
    matplotlib.figure.Figure
        Time from first contact in s. Top: the exact continuum (black), the candidate (crimson, open
        markers), the samples left out marked by why (contact differs ×, straddles an event +), the
        continuum's events (slip onset, full slip, start of detachment, pull-off) as dotted lines. Below: the
        difference candidate − exact over the compared samples, the band ± tolerance × the exact quantity's
        range (what the verdict allows of the max error), and the left-out samples at 0. For a paper preset,
        with a footnote naming the inferred parameters.
    """
    quantities = [str(name) for name in report["quantity"].values]
    if not quantities:
        raise ValueError("a validation report without quantities is not allowed; allowed: a report of "
                         "mdr_events.validate")
    columns = len(quantities)
    figure, axes = plt.subplots(2, columns, figsize=(4.6 * columns, 6.6), sharex="col", squeeze=False,
                                gridspec_kw={"height_ratios": [2.0, 1.0]}, constrained_layout=True)
    time = report["time"].values
    codes = report["left_out"].values
    tolerance = float(report.attrs.get("tolerance", np.nan))
    event_times = report["event_time_exact"].values if "event_time_exact" in report else np.array([])
    event_times = event_times[np.isfinite(event_times)]
    for column, name in enumerate(quantities):
        top, bottom = axes[0, column], axes[1, column]
        scale, symbol, unit = _display(report, name)
        candidate = report[f"candidate_{name}"].values * scale
        exact = report[f"exact_{name}"].values * scale
        difference = report[f"difference_{name}"].values * scale
        compared = np.isfinite(difference)
        step = max(1, int(np.count_nonzero(np.isfinite(candidate))) // CANDIDATE_MARKERS_PER_CURVE)
        top.plot(time, exact, label="exact (continuum)", **EXACT_STYLE)
        top.plot(time, candidate, markevery=step, label="candidate", **CANDIDATE_STYLE)
        bottom.plot(time, difference, label="candidate − exact", **DIFFERENCE_STYLE)
        if np.any(compared) and np.isfinite(tolerance):
            spread = float(np.ptp(exact[compared])) or float(np.max(np.abs(exact[compared]))) or 1.0
            bottom.axhspan(-tolerance * spread, tolerance * spread, label=f"± tolerance × range ({tolerance:g})",
                           **TOLERANCE_STYLE)
        for code, style in LEFT_OUT_STYLES.items():
            marked = codes == code
            label = f"left out: {LEFT_OUT_CODES[code]} ({np.count_nonzero(marked)})"
            top.plot(time[marked], candidate[marked], label=label, **style)
            bottom.plot(time[marked], np.zeros(np.count_nonzero(marked)), label=label, **style)
        for ax in (top, bottom):
            for number, moment in enumerate(event_times):
                ax.axvline(moment, label="continuum events" if number == 0 else None, **EVENT_STYLE)
            ax.grid(alpha=0.3)
        top.set_ylabel(f"{symbol} ({unit})")
        bottom.set_ylabel(f"Δ{symbol} ({unit})")
        bottom.set_xlabel("time from first contact t (s)")
        bottom.axhline(0.0, color="0.6", lw=0.6, zorder=1)
        row = report.sel(quantity=name)
        within = int(row["within_tolerance"]) == 1
        top.set_title(f"{symbol}: max error {float(row['max_error']):.3g} of the range "
                      f"({'within' if within else 'outside'} tolerance)", fontsize=10)
    footnote_strip = add_inferred_footnote(figure, report)
    handles, labels = [], []
    for ax in (axes[0, 0], axes[1, 0]):
        for handle, label in zip(*ax.get_legend_handles_labels()):
            if label not in labels:
                handles.append(handle)
                labels.append(label)
    figure.legend(handles, labels, loc="outside lower center", ncol=4, fontsize=LEGEND_FONTSIZE,
                  borderaxespad=LEGEND_BORDER_PAD + footnote_strip / LEGEND_FONTSIZE)
    if title is None:
        source = os.path.basename(str(report.attrs.get("candidate_source", "candidate"))) or "candidate"
        verdict = str(report.attrs.get("verdict", "?"))
        title = (f"Validation of {source} against the exact continuum: {verdict} "
                 f"(max error ≤ {tolerance:g} of each quantity's range)")
    figure.suptitle(title)
    return figure
