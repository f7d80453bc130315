"""Fig. 8 (scenario A) and Fig. 10 (scenario B) on the paper's 5 mm layer (issue 34): the discrete model at the
figures' angles on the half-space and on the layer bonded to its base, same parameters, and how much the layer raises
the maxima the paper's experiment shows above its simulation (section 4.2, item 2: ``F_N,max``, ``F_x,max``,
``A_max``, ``⟨p⟩_max`` and ``|F_N,min|``).

Both runs are the spring model at the figures' spacing and steps (:data:`~mdr_events.reproduction.common.FIGURE_DX`,
:data:`~mdr_events.reproduction.common.FIGURE_STEPS`) along the same paths; on the layer the springs are those of the
generalized MDR (:mod:`mdr_events.models.spring_media`). The maxima are the runs' own (first order in Δx: the
radius within Δx/2 of the layer's theory, ``tests/models/test_layer_discrete.py``).
"""

from __future__ import annotations

from functools import partial
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, figure_plan
from mdr_events.contact.model import Contact
from mdr_events.models.motion import Scenario
from mdr_events.models.simulate import simulate
from mdr_events.parameters import Parameters
from mdr_events.plotting.layer import plot_layer_simulations
from mdr_events.reproduction.common import FIGURE_ANGLES, FIGURE_DX, FIGURE_NUMBERS, FIGURE_STEPS, jobs
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step

__all__ = ["LAYER_FIGURES", "LayerFigureRun", "LAYER_THICKNESS", "MAXIMA", "layer_figure_run", "maxima_rows",
           "layer_figure_stem"]

#: The layer of the paper's experiment (m), bonded to its base.
LAYER_THICKNESS = 5e-3
#: The angles the figures draw (degrees).
DRAWN_ANGLES = (20.0, 60.0)
#: The maxima the report compares: label -> (variable, sign: +1 the largest value, -1 the largest magnitude of the
#: most negative), unit, scale to the unit.
MAXIMA = {"F_N,max": ("normal_force", 1.0, "N", 1.0), "F_x,max": ("tangential_force", 1.0, "N", 1.0),
          "A_max": ("contact_area", 1.0, "mm²", 1e6), "⟨p⟩_max": ("mean_pressure", 1.0, "kPa", 1e-3),
          "\\|F_N,min\\|": ("normal_force", -1.0, "N", 1.0)}


class LayerFigureRun(NamedTuple):
    """One radius and scenario at the figures' angles: the discrete model on the half-space and on the layer."""

    half_space: xr.Dataset
    layer: xr.Dataset


def layer_figure_stem(label: str, scenario: str) -> str:
    """The stem of a figure's file: ``fig8_R30_layer``."""
    return f"fig{FIGURE_NUMBERS[scenario]}_{label}_layer"


def layer_figure_run(radius: float, scenario: str) -> LayerFigureRun:
    """The discrete model at :data:`FIGURE_ANGLES` on the half-space and on the :data:`LAYER_THICKNESS` layer."""
    contact = Contact.from_parameters(Parameters.paper(R=radius))
    motion = Scenario(scenario, FIGURE_ANGLES)
    half, layer = (simulate(body, motion, "discrete", dx=FIGURE_DX, n_steps=FIGURE_STEPS)
                   for body in (contact, contact.replace(h=LAYER_THICKNESS)))
    return LayerFigureRun(half, layer)


def _largest(run: xr.Dataset, variable: str, sign: float) -> np.ndarray:
    """Each angle's largest ``sign × variable`` over time (``nan`` after a case has ended is skipped)."""
    return np.nanmax(sign * run[variable].values, axis=1)


def maxima_rows(runs: dict[tuple[str, str], LayerFigureRun]) -> list[list[str]]:
    """The table: per radius, figure and quantity the largest over the angles on the half-space and on the layer,
    their ratio and the range of the ratio angle by angle."""
    rows = []
    for (label, scenario), run in runs.items():
        for name, (variable, sign, unit, scale) in MAXIMA.items():
            half, layer = (_largest(dataset, variable, sign) for dataset in (run.half_space, run.layer))
            ratios = layer / half
            rows.append([label.replace("R", "R = ") + " mm", f"Fig. {FIGURE_NUMBERS[scenario]}", name,
                         f"{half.max() * scale:.4g} {unit}", f"{layer.max() * scale:.4g} {unit}",
                         f"{layer.max() / half.max():.3f}", f"{ratios.min():.3f}–{ratios.max():.3f}"])
    return rows


def _lines(runs: dict[tuple[str, str], LayerFigureRun]) -> list[str]:
    """The section of ``results/README.md``."""
    table = markdown_table(["R", "figure", "quantity", "half-space", "h = 5 mm, bonded", "layer / half-space",
                            "ratio by angle"], maxima_rows(runs), ["default"] * 3 + ["right"] * 4)
    return ["", "## Fig. 8 and 10 on the paper's 5 mm layer (discrete model)", "",
            "The paper's simulations are of a half-space; its experiment indents a layer 5 mm thick on a rigid base, "
            "and every measured maximum exceeds the simulated one (section 4.2, item 2). The spring model runs both "
            f"(`simulate(contact.replace(h=5e-3), Scenario(...), 'discrete')`, Δx = {FIGURE_DX * 1e6:g} µm, "
            f"{FIGURE_STEPS} steps, the angles {', '.join(f'{angle:g}' for angle in FIGURE_ANGLES)}°) with the same "
            "parameters: on the layer its springs have the generalized MDR's stiffness k(x) = K'(x)/2 and "
            "k_t(x) = K_t'(x)/2, the layer's profile g(x), Heß's Δl = sqrt(4π a Δγ/K'(a)) and the cap "
            "π a² τ0/K_t(a). The largest value over the angles, and the ratio angle by angle:", ""] + table + [
            "", "The layer raises the normal force and area most (it is stiffer and its profile flatter: the contact "
            "grows wider at the same depth), the tangential force with the area (full sliding carries π a² τ0 on any "
            "layer), the mean pressure with the stiffness, and the pull-off a little (its radius is small against "
            "h). Figures: " + ", ".join(f"`{layer_figure_stem(label, scenario)}.png`" for label, _, scenario
                                        in jobs()) + f" (α = {', '.join(f'{a:g}' for a in DRAWN_ANGLES)}°: "
            "solid the half-space, dashed the layer).", ""]


def _collect(results: list[LayerFigureRun]) -> dict[tuple[str, str], LayerFigureRun]:
    return {(label, scenario): run for (label, _, scenario), run in zip(jobs(), results)}


def _plans(runs: dict[tuple[str, str], LayerFigureRun], out: FilePath,
           keep_agreeing: bool) -> list[list[PlannedFile]]:
    plans = []
    for (label, scenario), run in runs.items():
        figure = plot_layer_simulations({"half-space": run.half_space, "h = 5 mm, bonded": run.layer}, DRAWN_ANGLES)
        plans.append(figure_plan(figure, out / f"{layer_figure_stem(label, scenario)}.png", keep_agreeing))
    return [plans]


LAYER_FIGURES = Section(
    name="layer_figures",
    steps=tuple(Step(f"Fig. {FIGURE_NUMBERS[scenario]}, R = {radius * 1e3:g} mm on the 5 mm layer: discrete, "
                     f"{len(FIGURE_ANGLES)} angles, beside the half-space (Δx = {FIGURE_DX * 1e6:g} µm)",
                     partial(layer_figure_run, radius, scenario)) for _, radius, scenario in jobs()),
    collect=_collect,
    render=_lines,
    plan=_plans,
    writing="writing Fig. 8 and 10 on the 5 mm layer (.png)",
    files=("- `fig8_R30_layer.png`, `fig8_R100_layer.png`, `fig10_R30_layer.png`, `fig10_R100_layer.png`: the",
           "  discrete model along Fig. 8's and 10's paths on the paper's 5 mm layer beside the half-space."),
)
