"""The log–log figure of a convergence study (:func:`mdr_events.convergence_study`), drawn from the dataset only.

Nothing is recomputed here: the errors and the fitted lines (``<norm>_fitted``) are the dataset's; only
the reference slope is drawn from the study's ``expected_order``. This module leaves the matplotlib
backend alone (the CLI selects Agg itself).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.ticker import NullFormatter

from mdr_events.analysis.convergence_study import NORMS
from mdr_events.plotting.figures import add_inferred_footnote

__all__ = ["plot_convergence_study", "NORM_STYLES", "QUANTITY_TITLES", "REFERENCE_LABEL"]

#: Norm -> label and colour/marker of its points and fitted line.
NORM_STYLES = {"max_error": dict(label="max", color="tab:blue", marker="o"),
               "rms_error": dict(label="RMS", color="tab:orange", marker="s"),
               "l1_error": dict(label="L1", color="tab:green", marker="^")}
#: Quantity -> panel title.
QUANTITY_TITLES = {"normal_force": "normal force $F_N$", "tangential_force": "tangential force $F_x$",
                   "contact_area": "contact area $A$", "contact_radius": "contact radius $a$"}
#: Label of the reference slope (formatted with the expected order).
REFERENCE_LABEL = "slope {order:g} (expected)"
#: The reference line lies this factor above the largest error at the coarsest spacing.
REFERENCE_OFFSET = 2.0
_UM = 1e6


def _positive(values: np.ndarray) -> np.ndarray:
    """Values a log axis can show (others ``nan``)."""
    values = np.asarray(values, dtype=float)
    return np.where(np.isfinite(values) & (values > 0), values, np.nan)


def plot_convergence_study(study: xr.Dataset):
    """The max, RMS and L1 errors of each quantity against ``Δx``, log–log, with their fitted lines.

    One panel per quantity. In each: per norm the errors (markers) and one line, the fitted
    ``C Δx^order`` stored in the study (labelled with the observed order ± its spread), or, where the
    study has no fit (fewer than 2 usable spacings), the errors joined by a dotted line; and a grey
    dashed reference line of the expected order, above the errors.

    Parameters
    ----------
    study : xarray.Dataset
        Output of :func:`mdr_events.convergence_study`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    quantities = [str(name) for name in study["quantity"].values]
    dx = study["dx"].values
    expected = float(study["expected_order"])
    figure, axes = plt.subplots(1, max(len(quantities), 1), figsize=(3.4 * max(len(quantities), 1) + 0.6, 3.8),
                                sharex=True, squeeze=False, constrained_layout=True)
    for ax, quantity in zip(axes[0], quantities):
        largest_coarse = np.nan
        shown_errors = 0
        for norm in NORMS:
            style = NORM_STYLES[norm]
            errors = _positive(study[norm].sel(quantity=quantity).values)
            shown_errors += int(np.count_nonzero(np.isfinite(errors)))
            fitted = _positive(study[f"{norm}_fitted"].sel(quantity=quantity).values)
            order = float(study[f"{norm}_order"].sel(quantity=quantity))
            spread = float(study[f"{norm}_order_spread"].sel(quantity=quantity))
            ax.scatter(dx * _UM, errors, color=style["color"], marker=style["marker"], s=22, zorder=3)
            if np.isfinite(order):
                text = f"{style['label']}: order {order:.2f}" + (f" ± {spread:.2f}" if np.isfinite(spread) else "")
                ax.plot(dx * _UM, fitted, color=style["color"], lw=1.2, label=text, gid=f"fit:{norm}")
            else:
                ax.plot(dx * _UM, errors, color=style["color"], lw=1.0, ls=":", label=f"{style['label']}: no fit",
                        gid=f"fit:{norm}")
            coarsest = errors[int(np.argmax(dx))]
            largest_coarse = np.nanmax([largest_coarse, coarsest]) if np.isfinite(coarsest) else largest_coarse
        if np.isfinite(largest_coarse):
            reference = REFERENCE_OFFSET * largest_coarse * (dx / np.max(dx)) ** expected
            ax.plot(dx * _UM, reference, color="0.5", lw=1.0, ls="--", label=REFERENCE_LABEL.format(order=expected),
                    gid="reference")
        ax.set_xscale("log")
        ax.set_xlim(0.8 * np.min(dx) * _UM, 1.25 * np.max(dx) * _UM)  # (also where no error is drawn)
        if shown_errors:
            ax.set_yscale("log")
        else:  # (every error 0: candidates equal to the exact run; a log axis has nothing to show)
            ax.text(0.5, 0.5, "every error is 0", transform=ax.transAxes, ha="center", va="center", fontsize=9)
        ax.set_xticks(dx * _UM, [f"{value:g}" for value in dx * _UM])
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_title(QUANTITY_TITLES.get(quantity, quantity), fontsize=10)
        ax.set_xlabel("spacing Δx (µm)")
        ax.grid(True, which="both", color="0.9", lw=0.6)
        ax.legend(fontsize=7, loc="lower right")
    axes[0][0].set_ylabel("error relative to the range")
    figure.suptitle(f"Convergence to the exact continuum ({study.attrs.get('verdict', 'no verdict')}, "
                    f"expected order {expected:g})", fontsize=11)
    add_inferred_footnote(figure, study)
    return figure
