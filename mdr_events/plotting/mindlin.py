"""The Cattaneo–Mindlin check (:func:`mdr_events.reproduction.mindlin.mindlin_check`): the tangential force against the
tangential displacement at the constant depth (continuum as a line, discrete model as open markers, the closed
form dashed), and each method's difference from the closed form against time. Drawn from the datasets only."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.plotting.figures import LEGEND_FONTSIZE, add_inferred_footnote

__all__ = ["plot_mindlin_check"]

#: Open markers of the discrete model, about this many on the loop.
MARKERS = 60
#: Differences below this share of μ F_N are drawn at it (a log axis has no zero).
DIFFERENCE_FLOOR = 1e-17


def _held(dataset: xr.Dataset) -> np.ndarray:
    return np.isfinite(dataset["cattaneo_mindlin_force"].values[0])


def plot_mindlin_check(continuum: xr.Dataset, discrete: xr.Dataset) -> Figure:
    """Two panels: (a) ``F_x`` against ``x`` at the constant depth, (b) ``|F_x − closed form| / (μ F_N)`` against
    time, for the continuum and the discrete run (each with the variable ``cattaneo_mindlin_force``)."""
    figure, (loop, error) = plt.subplots(2, 1, figsize=(7.0, 8.0), constrained_layout=True)
    held = _held(continuum)
    scale = continuum.attrs["friction_mu"] * float(np.nanmax(continuum["normal_force"].values))
    x = continuum["tangential_displacement"].values[0][held] * 1e6
    loop.plot(x, continuum["tangential_force"].values[0][held] * 1e3, color="C0", lw=1.6, label="continuum")
    loop.plot(x, continuum["cattaneo_mindlin_force"].values[0][held] * 1e3, color="k", lw=0.9, ls="--",
              label="closed form (Cattaneo–Mindlin, Masing)")
    springs = _held(discrete)
    step = max(1, np.count_nonzero(springs) // MARKERS)
    loop.plot(discrete["tangential_displacement"].values[0][springs][::step] * 1e6,
              discrete["tangential_force"].values[0][springs][::step] * 1e3, ls="none", marker="o", ms=3.5, mfc="none",
              mec="C3", mew=0.8, label=f"discrete (Δx = {discrete.attrs['dx'] * 1e6:g} µm)")
    loop.axhline(scale * 1e3, color="0.6", lw=0.8, ls=":")
    loop.axhline(-scale * 1e3, color="0.6", lw=0.8, ls=":")
    loop.set_xlabel("tangential displacement x (µm)")
    loop.set_ylabel("tangential force F_x (mN)")
    loop.legend(fontsize=LEGEND_FONTSIZE, loc="lower right")
    for dataset, colour, label in ((continuum, "C0", "continuum"), (discrete, "C3", "discrete")):
        rows = _held(dataset)
        difference = np.abs(dataset["tangential_force"].values[0] - dataset["cattaneo_mindlin_force"].values[0])[rows]
        error.semilogy(dataset["time"].values[rows], np.maximum(difference / scale, DIFFERENCE_FLOOR), color=colour,
                       lw=1.0, label=label)
    error.set_xlabel("time t from first contact (s)")
    error.set_ylabel("|F_x − closed form| / (μ F_N)")
    error.legend(fontsize=LEGEND_FONTSIZE)
    for letter, ax in zip("ab", (loop, error)):
        ax.text(0.01, 0.97, f"({letter})", transform=ax.transAxes, fontsize=10, va="top")
        ax.grid(alpha=0.3)
    add_inferred_footnote(figure, continuum)
    figure.suptitle(f"Coulomb's law (μ = {continuum.attrs['friction_mu']:g}) at a constant depth d = "
                    f"{continuum.attrs['mindlin_depth'] * 1e3:g} mm, the paper's material without adhesion:\n"
                    "loading from rest, a Mindlin loop, full slip (dotted: ±μ F_N)", fontsize=10)
    return figure
