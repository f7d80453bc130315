"""Result files: a dataset as netCDF with its figure as PNG, and the event log as CSV.

Shared by the CLI and ``mdr-events reproduce``; every file is written to a
temporary name and renamed into place (:func:`mdr_events.datasets.atomic_write`).
"""

from __future__ import annotations

from pathlib import Path

import xarray as xr

from .datasets import atomic_write, write_netcdf
from .parameters import Parameters

__all__ = ["write_phase_diagram", "write_simulation", "write_event_log"]


def write_phase_diagram(params: Parameters, scenario: str, out: Path, stem: str) -> list[Path]:
    """Compute the phase diagram (Fig. 9a/9b) and write ``stem.nc`` and ``stem.png``."""
    from .phase import phase_diagram
    from .plotting import plot_phase_diagram, save_figure

    dataset = phase_diagram(params, scenario=scenario)
    written = [write_netcdf(dataset, Path(out) / f"{stem}.nc")]
    axes = plot_phase_diagram(dataset)
    written.append(save_figure(axes.figure, Path(out) / f"{stem}.png"))
    return written


def write_simulation(dataset: xr.Dataset, out: Path, stem: str, overlay: xr.Dataset | None = None) -> list[Path]:
    """Write a simulation dataset as ``stem.nc`` and its figure (with ``overlay``) as ``stem.png``."""
    from .plotting import plot_simulation, save_figure

    written = [write_netcdf(dataset, Path(out) / f"{stem}.nc")]
    written.append(save_figure(plot_simulation(dataset, overlay=overlay), Path(out) / f"{stem}.png"))
    return written


def write_event_log(dataset: xr.Dataset, path: Path) -> Path:
    """The continuum event log as CSV (one row per event per angle), written atomically."""
    lines = ["alpha_degree,event,time_s,kind,depth_m,radius_m,x_m"]
    for alpha in dataset["alpha"].values:
        case = dataset.sel(alpha=alpha)
        for number in dataset["event"].values:
            kind = str(case["event_kind"].values[number])
            if not kind:
                continue
            values = [float(case[name].values[number]) for name in ("event_time", "event_depth", "event_radius", "event_x")]
            lines.append(f"{alpha:.17g},{number},{values[0]:.17g},{kind},{values[1]:.17g},{values[2]:.17g},{values[3]:.17g}")
    text = "\n".join(lines) + "\n"
    return atomic_write(path, lambda temporary: Path(temporary).write_text(text), suffix=".csv")
