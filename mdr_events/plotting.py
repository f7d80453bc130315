"""Figures drawn from the datasets (never recomputed here): Fig. 8, 9a, 9b, 10."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from .datasets import atomic_write  # noqa: E402

__all__ = ["plot_phase_diagram", "plot_simulation", "save_figure"]

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


#: Panels of Fig. 8 / Fig. 10: variable, scale to display units, axis label.
SIMULATION_PANELS = (
    ("normal_force", 1e3, "$F_N$ (mN)"),
    ("tangential_force", 1e3, "$F_x$ (mN)"),
    ("contact_area", 1e6, "$A$ (mm²)"),
    ("mean_pressure", 1e-3, "$\\langle p \\rangle$ (kPa)"),
    ("mean_shear_stress", 1e-3, "$\\tau$ (kPa)"),
)


def plot_simulation(dataset: xr.Dataset, overlay: xr.Dataset | None = None, title: str | None = None):
    """Fig. 8 (scenario A) or Fig. 10 (scenario B): panels a–e against time, one line per angle.

    ``overlay`` (e.g. the discrete model for one angle) is drawn as thin dashed red lines.
    Returns the figure.
    """
    figure, axes = plt.subplots(5, 1, figsize=(7.0, 12.0), sharex=True, constrained_layout=True)
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, dataset.sizes["alpha"]))
    time = dataset["time"].values
    for letter, ax, (name, scale, label) in zip("abcde", axes, SIMULATION_PANELS):
        for colour, alpha in zip(colours, dataset["alpha"].values):
            values = dataset[name].sel(alpha=alpha).values * scale
            text = "custom path" if np.isnan(alpha) else f"α = {alpha:g}°"
            ax.plot(time, values, color=colour, lw=1.4, label=text)
        if overlay is not None:
            for alpha in overlay["alpha"].values:
                text = f"{overlay.attrs.get('method', 'overlay')}, α = {alpha:g}°"
                if "dx" in overlay.attrs:
                    text += f", Δx = {overlay.attrs['dx'] * 1e6:g} µm"
                ax.plot(overlay["time"].values, overlay[name].sel(alpha=alpha).values * scale,
                        color="tab:red", lw=0.8, ls=(0, (4, 3)), label=text)
        ax.set_ylabel(label)
        ax.text(0.01, 0.92, f"({letter})", transform=ax.transAxes, fontsize=10, va="top")
        ax.grid(alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncol=5, fontsize=8)
    axes[-1].set_xlabel("time t (s)")
    if title is None:
        scenario = dataset.attrs.get("scenario", "")
        figure_number = {"A": "Fig. 8", "B": "Fig. 10"}.get(scenario, "Simulation")
        title = (f"{figure_number}: scenario {scenario}, R = {dataset.attrs['param_R'] * 1e3:g} mm, "
                 f"{dataset.attrs.get('method', '')}")
    figure.suptitle(title)
    return figure
