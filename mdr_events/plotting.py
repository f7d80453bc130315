"""Figures drawn from the datasets (never recomputed here): Fig. 9a, 9b."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from .datasets import atomic_write  # noqa: E402

__all__ = ["plot_phase_diagram", "save_figure"]

_MM = 1e3


def _label(ax, alpha, depth_mm, text):
    ax.text(alpha, depth_mm, text, ha="center", va="center", fontsize=10,
            bbox={"boxstyle": "round", "facecolor": "white", "edgecolor": "0.7", "alpha": 0.85})


def plot_phase_diagram(dataset: xr.Dataset, ax=None):
    """Draw Fig. 9a (scenario A) or 9b (scenario B) from :func:`phase_diagram` output.

    Solid: non-adhesive curves (17)/(20); dashed: adhesive curves (18)/(21);
    the ``d_max`` line, the critical angles and the regions
    ("sliding-ind", "no-sliding-ind", "sliding-det", "no-sliding-det").
    Axes in degrees and millimetres.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 4.8), constrained_layout=True)
    scenario = dataset.attrs["scenario"]
    alpha = dataset["alpha"].values
    d_max = float(dataset["d_max"]) * _MM
    R_mm = dataset.attrs["param_R"] * _MM
    style = {"hertz": dict(color="k", ls="-", label="non-adhesive"),
             "jkr": dict(color="tab:red", ls="--", label="adhesive")}
    if scenario == "A":
        for key, eq in (("hertz", "(17)"), ("jkr", "(18)")):
            ax.plot(alpha, dataset[f"d_crit_{key}"].values * _MM, **{**style[key], "label": f"{style[key]['label']} {eq}"})
        top = 2.0 * d_max
        for key in ("hertz", "jkr"):
            angle = float(dataset[f"critical_angle_{key}"])
            ax.plot([angle, angle], [0, d_max], color=style[key]["color"], ls=":", lw=1)
            ax.plot(angle, d_max, "o", color=style[key]["color"], ms=4)
        ax.annotate(
            f"$\\alpha_c^{{Hertz}}$ = {float(dataset['critical_angle_hertz']):.2f}°\n"
            f"$\\alpha_c^{{JKR}}$ = {float(dataset['critical_angle_jkr']):.2f}°",
            xy=(float(dataset["critical_angle_hertz"]), d_max), xytext=(40, 0.55 * top),
            arrowprops={"arrowstyle": "->", "color": "0.4"}, fontsize=9)
        _label(ax, 9.0, 0.85 * top, "sliding-ind")
        _label(ax, 65.0, 0.25 * top, "no-sliding-ind")
        ax.set_ylim(0, top)
        title = f"Fig. 9a: scenario A, R = {R_mm:g} mm"
    else:
        branches = list(dataset["branch"].values)
        for key, eq in (("hertz", "(20)"), ("jkr", "(21)")):
            for i, branch in enumerate(branches):
                values = dataset[f"d_crit_{key}"].sel(branch=branch).values * _MM
                ax.plot(alpha, values, **{**style[key], "label": f"{style[key]['label']} {eq}" if i == 0 else None})
        jump_off = float(dataset["jump_off_depth"]) * _MM
        ax.axhline(0.0, color="0.5", lw=0.8)
        ax.axhline(jump_off, color="tab:red", lw=0.8, ls="-.", label="jump-off depth (Δγ1)")
        top = 3.0 * d_max
        _label(ax, 60.0, 0.85 * top, "no-sliding-ind")
        _label(ax, 10.0, 0.9 * top, "sliding-ind")
        _label(ax, 62.0, 0.55 * d_max, "no-sliding-det")
        _label(ax, 8.0, 0.35 * d_max, "sliding-det")
        ax.set_ylim(min(2.0 * jump_off, -0.1 * d_max), top)
        title = f"Fig. 9b: scenario B, R = {R_mm:g} mm"
    ax.axhline(d_max, color="tab:blue", lw=1.0, ls="--", label="$d_{max}$")
    ax.set_xlim(0, 90)
    ax.set_xticks(np.arange(0, 91, 10))
    ax.set_xlabel("path angle α (°)")
    ax.set_ylabel("indentation depth d (mm)")
    ax.set_title(title)
    ax.legend(loc="upper right" if scenario == "A" else "center right", fontsize=8)
    return ax


def save_figure(figure, path: str | os.PathLike) -> Path:
    """Save a figure as PNG atomically and reproducibly (no time stamp), then close it."""
    try:
        return atomic_write(path, lambda temporary: figure.savefig(
            temporary, format="png", dpi=120, metadata={"Software": None}), suffix=".png")
    finally:
        plt.close(figure)
