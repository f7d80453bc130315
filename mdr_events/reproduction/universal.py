"""The universal map: the critical angles over the model's three dimensionless groups, the paper's two parameter
sets marked on it (``universal_map``), swept with :func:`mdr_events.sweep` on a local dask cluster."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from mdr_events.analysis.universal_map import universal_map
from mdr_events.app.result_files import PlannedFile, dataset_plan, figure_plan
from mdr_events.parameters import Parameters
from mdr_events.plotting.universal import plot_universal_map
from mdr_events.reproduction.common import RADII
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory.analytic import critical_angle, dimensionless_groups

__all__ = ["UNIVERSAL", "UNIVERSAL_STEM", "MAP_SLIP", "MAP_ADHESION", "universal_lines"]

#: The universal map's grid: the slip parameter S (log-spaced) and the adhesion parameters Γ.
MAP_SLIP = np.geomspace(0.3, 15.0, 121)
MAP_ADHESION = np.linspace(0.0, 0.3, 121)
#: The stem of the universal map's files in ``results/``.
UNIVERSAL_STEM = "universal_map"


def _paper_set_cells(label: str, radius: float) -> list[str]:
    params = Parameters.paper(R=radius)
    groups = dimensionless_groups(params)
    return [f"paper, {label}", f"{groups.slip:#.4g}", f"{groups.adhesion_in:#.4g}", f"{groups.adhesion_out:#.4g}",
            f"{critical_angle(params, 'A'):.2f}°", f"{critical_angle(params, 'B'):.2f}°"]


def universal_lines(dataset: xr.Dataset) -> list[str]:
    """The report's section on the universal map: the groups, and the paper's sets on it."""
    lines = ["", "## The universal map", "",
             "Measured in `d_max` (depths, tangential travel) and `√(R d_max)` (radii), the model has three "
             "parameters: the slip parameter `S = π τ0 √R / (2 G* √d_max)` and the adhesion parameters "
             "`Γ = 2π Δγ √R / (E* d_max^(3/2))` of the two works of adhesion (`mdr_events.analytic."
             "dimensionless_groups`). Every angle, every depth over `d_max` and `F_x/(π a² τ0)` depend on "
             "them (and the path's angle) alone; a test checks it with two parameter sets of equal groups. "
             "`universal_map.{nc,png}`: the critical angle of scenario A over (S, Γ0) and the angle of scenario B "
             f"above which the contact comes apart before sliding over (S, Γ1) at Γ0 = "
             f"{dataset.attrs['adhesion_in_of_B']:#.4g}, {dataset.sizes['slip']} × {dataset.sizes['adhesion_in']} "
             "values each, swept with `mdr_events.sweep`.", ""]
    lines += markdown_table(["set", "S", "Γ0", "Γ1", "α_c, scenario A", "angle, scenario B"],
                            [_paper_set_cells(label, radius) for label, radius in RADII.items()],
                            ["default"] + ["right"] * 5)
    return lines + [""]


def _compute() -> xr.Dataset:
    return universal_map(MAP_SLIP, MAP_ADHESION, Parameters.paper(),
                         marked={label: Parameters.paper(R=radius) for label, radius in RADII.items()})


def _plans(dataset: xr.Dataset, out: Path, keep_agreeing: bool) -> list[list[PlannedFile]]:
    mapped, plan = dataset_plan(dataset, out / f"{UNIVERSAL_STEM}.nc", keep_agreeing)
    return [[plan, figure_plan(plot_universal_map(mapped), out / f"{UNIVERSAL_STEM}.png", keep_agreeing)]]


UNIVERSAL = Section(
    name="universal",
    steps=(Step(f"universal map: critical angles over {MAP_SLIP.size} × {MAP_ADHESION.size} values of the "
                "dimensionless groups (the sweep on a local dask cluster)", _compute),),
    collect=lambda results: results[0],
    render=universal_lines,
    plan=_plans,
    writing="writing the universal map (.nc, .png)",
    files=(f"- `{UNIVERSAL_STEM}.{{nc,png}}`: the critical angles over the dimensionless groups, the paper's sets "
           "marked.",),
)
