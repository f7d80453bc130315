"""The figure of the universal map (:func:`mdr_events.analysis.universal_map.universal_map`): the critical
angles over the dimensionless groups, with the paper's parameter sets marked. Drawn from the dataset only."""

from __future__ import annotations

import matplotlib.pyplot as plt
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.analysis.universal_map import GROUP_NAMES, LAYER_GROUP, UNIVERSAL_MAP_CONTENT
from mdr_events.io.datasets import register_figure
from mdr_events.plotting.figures import LEGEND_BORDER_PAD, LEGEND_FONTSIZE, add_inferred_footnote

__all__ = ["plot_universal_map"]

#: Angles at which contour lines are drawn and labelled, degrees.
CONTOUR_ANGLES = (5, 10, 15, 20, 30, 40, 50, 60, 70, 80, 85, 89)
MARK_STYLES = {"R30": dict(marker="o", color="white", mec="k", ms=8), "R100": dict(marker="s", color="white",
                                                                                  mec="k", ms=8)}
PANELS = (("critical_angle_A", "adhesion_in", "Scenario A: α_c (slides while indenting below it)"),
          ("critical_angle_B", "adhesion_out", "Scenario B: comes apart before sliding above this angle"))


def _marks(dataset: xr.Dataset) -> list[str]:
    return sorted({key.split("_")[1] for key in dataset.attrs if key.startswith("mark_")})


def _at_thinness(dataset: xr.Dataset, thinness: float | None) -> tuple[xr.Dataset, str]:
    """The map at one value of the layer's group (a map without that axis as it is) and its heading; the marks
    (half-spaces) dropped away from ``λ = 0``."""
    (name, (symbol, _)), = LAYER_GROUP.items()
    if name not in dataset.dims:
        if thinness is not None:
            raise ValueError(f"thinness={thinness!r} is not allowed: the map has no {name} axis; allowed: None")
        return dataset, "Universal map: the critical angles depend on S and Γ alone"
    values = dataset[name].values
    at = float(values[0]) if thinness is None else thinness
    if at not in values:
        raise ValueError(f"thinness={thinness!r} is not allowed; allowed: one of the map's {name} values "
                         f"{', '.join(f'{value:g}' for value in values)}")
    selected = dataset.sel({name: at})
    if at != 0.0:
        selected.attrs = {key: value for key, value in selected.attrs.items() if not key.startswith("mark_")}
    return selected, (f"Universal map at {symbol} = √(R d_max)/h = {at:g} (bonded layer, ν = "
                      f"{dataset.attrs['param_nu']:g})")


def plot_universal_map(dataset: xr.Dataset, title: str | None = None, thinness: float | None = None) -> Figure:
    """Two panels: α_c of scenario A over (S, Γ0) and the angle of scenario B over (S, Γ1) (at the base's Γ0),
    filled with labelled contour lines; the marked parameter sets (the paper's) as symbols.

    Parameters
    ----------
    dataset : xarray.Dataset
        A map of :func:`~mdr_events.analysis.universal_map.universal_map`.
    title : str, optional
        The figure's title (default: the map's claim).
    thinness : float, optional
        A map over the layer's group ``λ``: the value whose panels are drawn (default its first); the marked sets,
        half-spaces, are drawn at ``λ = 0`` only.

    Returns
    -------
    matplotlib.figure.Figure
        The two panels with their colour bars.

    Raises
    ------
    ValueError
        ``thinness`` beside a map without that axis, or not among the map's values.
    """
    dataset, claim = _at_thinness(dataset, thinness)
    figure, axes = plt.subplots(1, 2, figsize=(11.5, 5.0), layout="constrained")
    for ax, (name, adhesion, heading) in zip(axes, PANELS):
        values = dataset[name]
        slip, gamma = dataset["slip"].values, dataset[adhesion].values
        mesh = ax.pcolormesh(gamma, slip, values.values, shading="auto", cmap="viridis", vmin=0, vmax=90)
        lines = ax.contour(gamma, slip, values.values, levels=CONTOUR_ANGLES, colors="w", linewidths=0.7)
        ax.clabel(lines, fmt="%g°", fontsize=7)
        for label in _marks(dataset):
            ax.plot(dataset.attrs[f"mark_{label}_{adhesion}"], dataset.attrs[f"mark_{label}_slip"], ls="none",
                    label=f"paper, {label}", **MARK_STYLES.get(label, dict(marker="^", color="w", mec="k")))
        ax.set_yscale("log")
        ax.set_xlabel(f"{GROUP_NAMES[adhesion][0]} = 2π Δγ √R / (E* d_max^3/2)")
        ax.set_ylabel(f"{GROUP_NAMES['slip'][0]} = π τ0 √R / (2 G* √d_max)")
        ax.set_title(heading, fontsize=10)
        figure.colorbar(mesh, ax=ax, label="angle (degree)")
        if _marks(dataset):
            ax.legend(fontsize=LEGEND_FONTSIZE, borderpad=LEGEND_BORDER_PAD, loc="upper right")
    axes[1].text(0.02, 0.02, f"Γ0 = {dataset.attrs['adhesion_in_of_B']:.3g}", transform=axes[1].transAxes,
                 color="w", fontsize=8)
    figure.suptitle(title if title is not None else claim)
    add_inferred_footnote(figure, dataset)
    return figure


register_figure(UNIVERSAL_MAP_CONTENT, plot_universal_map)
