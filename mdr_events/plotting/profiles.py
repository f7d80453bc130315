"""The figure comparing indenters (:func:`mdr_events.reproduction.profiles.profile_comparison`): the normal force, the
tangential force and the contact radius against time, one colour per profile, the continuum as lines and the
discrete model as open markers. Drawn from the datasets only."""

from __future__ import annotations

from collections.abc import Mapping

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.models.motion import case_dimension
from mdr_events.plotting.figures import LEGEND_BORDER_PAD, LEGEND_FONTSIZE, add_inferred_footnote

__all__ = ["plot_profile_comparison"]

#: Panels: variable, scale to the plotted unit, axis label.
PROFILE_PANELS = (("normal_force", 1.0, "normal force F_N (N)"),
                  ("tangential_force", 1.0, "tangential force F_x (N)"),
                  ("contact_radius", 1e3, "contact radius a (mm)"))
#: Open markers of the discrete model, about this many per curve.
MARKERS_PER_CURVE = 40


def _exponent(dataset: xr.Dataset) -> str:
    """`` (n = 3)`` from the dataset's ``profile_n`` attribute (the paraboloid of R without it: 2); a flat punch's
    `` (a = 3 mm)`` from ``profile_radius``."""
    if "profile_radius" in dataset.attrs:
        return f" (a = {float(dataset.attrs['profile_radius']) * 1e3:g} mm)"
    return f" (n = {float(dataset.attrs.get('profile_n', 2.0)):g})"


def plot_profile_comparison(continuum: Mapping[str, xr.Dataset], discrete: Mapping[str, xr.Dataset] | None = None,
                            title: str | None = None) -> Figure:
    """Three panels against time for each named simulation of ``continuum`` (lines) and ``discrete`` (markers,
    same colour), labelled by the name and the dataset's ``profile`` attribute."""
    figure, axes = plt.subplots(3, 1, figsize=(7.0, 8.5), sharex=True, constrained_layout=True)
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, len(continuum)))
    for colour, (name, dataset) in zip(colours, continuum.items()):
        for ax, (variable, scale, _) in zip(axes, PROFILE_PANELS):
            ax.plot(dataset["time"].values, dataset[variable].values[0] * scale, color=colour, lw=1.4,
                    label=f"{name.replace('_', ' ')}{_exponent(dataset)}, continuum")
            if discrete is not None and name in discrete:
                springs = discrete[name]
                values = springs[variable].values[0] * scale
                step = max(1, np.count_nonzero(np.isfinite(values)) // MARKERS_PER_CURVE)
                ax.plot(springs["time"].values[::step], values[::step], ls="none", marker="o", ms=3.5, mfc="none",
                        mec=colour, mew=0.8, label=f"{name.replace('_', ' ')}, discrete (Δx = {springs.attrs['dx'] * 1e6:g} µm)")
    for letter, ax, (_, _, label) in zip("abc", axes, PROFILE_PANELS):
        ax.set_ylabel(label)
        ax.text(0.01, 0.92, f"({letter})", transform=ax.transAxes, fontsize=10, va="top")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("time t (s)")
    first = next(iter(continuum.values()))
    footnote_strip = add_inferred_footnote(figure, first)
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncol=min(len(continuum), 2), fontsize=LEGEND_FONTSIZE,
                  borderaxespad=LEGEND_BORDER_PAD + footnote_strip / LEGEND_FONTSIZE)  # above the footnote
    if title is None:
        alpha = float(first[case_dimension(first)].values[0])
        title = (f"Other indenters f = c rⁿ and a flat punch, scenario A at {alpha:g}°, the paper's material and "
                 f"adhesion\n(each with the non-adhesive contact radius of R = {first.attrs['param_R'] * 1e3:g} mm at "
                 "d_max)")
    figure.suptitle(title, fontsize=10)
    return figure
