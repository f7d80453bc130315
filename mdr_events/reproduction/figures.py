"""Fig. 8 (scenario A) and Fig. 10 (scenario B): the continuum at the figures' angles with the discrete model overlaid
at one (``fig<8|10>_<R30|R100>``), and what section 4.2 reads off them, the four differences between simulation and
experiment (:mod:`mdr_events.reproduction.differences`)."""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, dataset_plan, simulation_plans
from mdr_events.models.continuum import extremum, solve_path
from mdr_events.models.motion import scenario_paths
from mdr_events.models.simulate import simulate
from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import (FIGURE_ANGLES, FIGURE_DX, FIGURE_NUMBERS, FIGURE_STEPS, OVERLAY_ANGLE,
                                            jobs)
from mdr_events.reproduction.differences import differences_lines
from mdr_events.reproduction.section import Section, Step

__all__ = ["FIGURES", "FigureRuns", "EXTREMES", "figure_stem"]

#: Extremes of the continuum runs the report quotes (exact, from the solution: :func:`mdr_events.models.continuum.extremum`):
#: name -> (quantity, largest).
EXTREMES = {"normal_force_max": ("normal_force", True), "normal_force_min": ("normal_force", False),
            "tangential_force_max": ("tangential_force", True), "contact_area_max": ("contact_area", True),
            "mean_pressure_max": ("mean_pressure", True), "mean_shear_stress_max": ("mean_shear_stress", True)}


class FigureRun(NamedTuple):
    """One radius and scenario of the figures: the continuum, the discrete overlay, the exact extremes per angle."""

    continuum: xr.Dataset
    discrete: xr.Dataset
    extremes: dict[str, np.ndarray]  #: name of :data:`EXTREMES` -> one value per angle


class FigureRuns(NamedTuple):
    """Every run of the figures, keyed by (radius label, scenario)."""

    continuum: dict[tuple[str, str], xr.Dataset]
    discrete: dict[tuple[str, str], xr.Dataset]  #: at :data:`OVERLAY_ANGLE`
    extremes: dict[tuple[str, str], dict[str, np.ndarray]]


def figure_stem(label: str, scenario: str) -> str:
    """The stem of a figure's files: ``fig8_R30``."""
    return f"fig{FIGURE_NUMBERS[scenario]}_{label}"


def figure_run(radius: float, scenario: str) -> FigureRun:
    """The continuum at :data:`FIGURE_ANGLES`, the discrete model at :data:`OVERLAY_ANGLE` and the exact
    :data:`EXTREMES` of each continuum run."""
    params = Parameters.paper(R=radius)
    continuum = simulate(params, scenario, alpha=FIGURE_ANGLES, method="continuum")
    discrete = simulate(params, scenario, alpha=[OVERLAY_ANGLE], dx=FIGURE_DX, n_steps=FIGURE_STEPS)
    solutions = [solve_path(params, path) for path in scenario_paths(params, scenario, FIGURE_ANGLES)[0]]
    extremes = {name: np.array([extremum(solution, quantity, largest)[1] for solution in solutions])
                for name, (quantity, largest) in EXTREMES.items()}
    return FigureRun(continuum, discrete, extremes)


def _collect(runs: list[FigureRun]) -> FigureRuns:
    keys = [(label, scenario) for label, _, scenario in jobs()]
    return FigureRuns({key: run.continuum for key, run in zip(keys, runs)},
                      {key: run.discrete for key, run in zip(keys, runs)},
                      {key: run.extremes for key, run in zip(keys, runs)})


def _plans(runs: FigureRuns, out: Path, keep_agreeing: bool) -> list[list[PlannedFile]]:
    groups = []
    for (label, scenario), dataset in runs.continuum.items():
        stem = figure_stem(label, scenario)
        overlay, plan = dataset_plan(runs.discrete[(label, scenario)], out / f"{stem}_discrete.nc", keep_agreeing)
        groups.append([plan] + simulation_plans(dataset, out, stem, overlay=overlay, keep_agreeing=keep_agreeing))
    return groups


FIGURES = Section(
    name="figures",
    steps=tuple(Step(f"Fig. {FIGURE_NUMBERS[scenario]}, R = {radius * 1e3:g} mm: continuum, {len(FIGURE_ANGLES)} "
                     f"angles; discrete overlay at {OVERLAY_ANGLE:g}° (Δx = {FIGURE_DX * 1e6:g} µm)",
                     partial(figure_run, radius, scenario)) for _, radius, scenario in jobs()),
    collect=_collect,
    render=lambda runs: differences_lines(runs.continuum, runs.discrete, runs.extremes),
    plan=_plans,
    writing="writing Fig. 8 and 10 (.nc, .png, events .csv)",
    files=("- `fig8_R30.{nc,png}`, `fig8_R100.{nc,png}`: Fig. 8 (scenario A), continuum method, with its event",
           "  log in `fig8_R*_events.csv` and the discrete overlay in `fig8_R*_discrete.nc`.",
           "- `fig10_R30.{nc,png}`, `fig10_R100.{nc,png}`: Fig. 10 (scenario B), likewise."),
)
