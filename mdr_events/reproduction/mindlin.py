"""Coulomb's law at a constant depth against Cattaneo–Mindlin: the virgin curve, a Mindlin loop and full slip,
continuum and discrete, each beside the closed form (``mindlin_coulomb``).

The check's datasets carry the closed form (:data:`MINDLIN_VARIABLES`), whose schema and accuracy this module
registers with :mod:`mdr_events.io` when imported (``study="cattaneo_mindlin"``).
"""

from __future__ import annotations

from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, dataset_plan, figure_plan
from mdr_events.contact.friction import FrictionLaw
from mdr_events.io.agreement import RoundOff, register_accuracy
from mdr_events.io.datasets import register_schema
from mdr_events.models.motion import CUSTOM_DIMENSION
from mdr_events.models.paths import Path
from mdr_events.models.simulate import simulate
from mdr_events.models.simulation_schema import SIMULATION_CONTENT
from mdr_events.parameters import Parameters
from mdr_events.plotting.mindlin import plot_mindlin_check
from mdr_events.reproduction.common import FIGURE_DX
from mdr_events.reproduction.markdown import markdown_table, relative_difference_text
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory import mindlin

__all__ = ["MINDLIN", "MINDLIN_STEM", "MindlinCheck", "MindlinRow", "mindlin_check", "mindlin_path", "mindlin_rows",
           "mindlin_lines", "MINDLIN_FRICTION"]

#: The check: the paper's material without adhesion, Coulomb's law with this μ, ...
MINDLIN_FRICTION = FrictionLaw("coulomb", mu=0.3)
#: ... vertically in to this share of d_max, then along x through these shares of the full-slip shift κ d: the
#: virgin curve, a Mindlin loop (unloading and reloading), and on to full slip.
MINDLIN_DEPTH_SHARE = 1.0 / 3.0
MINDLIN_TURNS = (0.0, 0.6, -0.6, 0.6, 1.3)
MINDLIN_SAMPLES = 2001
#: The case label and the ``study`` attribute of its datasets (which selects :data:`MINDLIN_VARIABLES`).
MINDLIN_CASE = "cattaneo-mindlin"
MINDLIN_STUDY = "cattaneo_mindlin"
MINDLIN_VARIABLES: dict[str, tuple[tuple[str, ...], str, str]] = {
    "cattaneo_mindlin_force": ((CUSTOM_DIMENSION, "time"), "N",
                               "tangential force of the closed form at the constant depth: Cattaneo-Mindlin's virgin "
                               "curve and Masing's rules (mdr_events.mindlin.tangential_force); nan off that depth"),
}
register_schema(SIMULATION_CONTENT, {name: dims for name, (dims, _, _) in MINDLIN_VARIABLES.items()},
                when=("study", MINDLIN_STUDY))
#: The closed form on the samples (round-off).
register_accuracy(SIMULATION_CONTENT, {name: RoundOff() for name in MINDLIN_VARIABLES}, when=("study", MINDLIN_STUDY))


class MindlinCheck(NamedTuple):
    """The continuum and the discrete run of :func:`mindlin_path`, each with the closed form on its samples."""

    continuum: xr.Dataset
    discrete: xr.Dataset


def mindlin_path(params: Parameters) -> tuple[Path, float]:
    """The path of the check and its constant depth (m)."""
    depth = MINDLIN_DEPTH_SHARE * params.d_max
    full = mindlin.full_slip_shift(depth, MINDLIN_FRICTION, params)
    waypoints = [(0.0, 0.0)] + [(share * full, depth) for share in MINDLIN_TURNS]
    return Path(np.array(waypoints), speed=params.v), depth


def _with_closed_form(dataset: xr.Dataset, path: Path, depth: float, params: Parameters) -> xr.Dataset:
    """``dataset`` with :data:`MINDLIN_VARIABLES` on its samples at ``depth``: from the corner where ``path`` reached
    it on (the springs were at rest there, ``x = 0``), by time, half a sample before it, not by the sampled depth's
    equality with ``depth`` (which the rounding of another CPU may break at the corner)."""
    times = dataset["time"].values
    reached = path.corner_times[1] - path.first_contact_time()
    running = np.isfinite(dataset["indentation_depth"].values[0])
    held = (times > reached - 0.5 * float(np.min(np.diff(times)))) & running
    x = dataset["tangential_displacement"].values[0][held]
    closed = np.full(dataset.sizes["time"], np.nan)
    closed[held] = mindlin.tangential_force(np.concatenate([[0.0], x]), depth, MINDLIN_FRICTION, params)[1:]
    (dims, units, long_name), = MINDLIN_VARIABLES.values()
    dataset = dataset.assign(cattaneo_mindlin_force=(dims, closed[None, :], {"units": units, "long_name": long_name}))
    dataset.attrs.update(study=MINDLIN_STUDY, mindlin_depth=depth)
    return dataset


def mindlin_check(params: Parameters) -> MindlinCheck:
    """Coulomb's law (:data:`MINDLIN_FRICTION`) along :func:`mindlin_path` without adhesion: the continuum at
    :data:`MINDLIN_SAMPLES` times and the path's corners, the discrete model at Δx = FIGURE_DX (dt = Δx/(2v))."""
    hertz = params.replace(dgamma0=0.0, dgamma1=0.0)
    path, depth = mindlin_path(hertz)
    start = path.first_contact_time()
    times = np.union1d(np.linspace(0.0, path.duration - start, MINDLIN_SAMPLES), path.corner_times[1:] - start)
    continuum = simulate(hertz, {MINDLIN_CASE: path}, method="continuum", t=times, friction=MINDLIN_FRICTION)
    discrete = simulate(hertz, {MINDLIN_CASE: path}, dx=FIGURE_DX, dt=0.5 * FIGURE_DX / hertz.v,
                        friction=MINDLIN_FRICTION)
    return MindlinCheck(_with_closed_form(continuum, path, depth, hertz),
                        _with_closed_form(discrete, path, depth, hertz))


class MindlinRow(NamedTuple):
    """One method's largest difference from the closed form, over μ F_N."""

    method: str
    max_difference: float


def mindlin_rows(check: MindlinCheck) -> list[MindlinRow]:
    """The rows of the report's table of :func:`mindlin_check`."""
    rows = []
    for method, dataset in (("continuum", check.continuum), (f"discrete, Δx = {FIGURE_DX * 1e6:g} µm", check.discrete)):
        full = MINDLIN_FRICTION.mu * float(np.nanmax(dataset["normal_force"].values))
        difference = dataset["tangential_force"].values - dataset["cattaneo_mindlin_force"].values
        rows.append(MindlinRow(method, float(np.nanmax(np.abs(difference))) / full))
    return rows


#: The stem of the check's files in ``results/``.
MINDLIN_STEM = "mindlin_coulomb"
#: Differences from the closed form below this (the tests' bound on the continuum) are reported as below it.
MINDLIN_REPORTED_BOUND = 1e-9


def _difference_text(row: MindlinRow) -> str:
    """Below :data:`MINDLIN_REPORTED_BOUND` as that bound: the continuum's differences are its solver's (rtol 1e-10),
    whose digits differ between machines."""
    if row.max_difference < MINDLIN_REPORTED_BOUND:
        return f"< {MINDLIN_REPORTED_BOUND:g}"
    return relative_difference_text(row.max_difference)


def mindlin_lines(check: MindlinCheck) -> list[str]:
    """The Cattaneo–Mindlin check: each method's largest difference from the closed form (:func:`mindlin_rows`)."""
    turns = " → ".join(f"{share:g}" for share in MINDLIN_TURNS)
    lines = [
        f"## Coulomb's law: Cattaneo–Mindlin (`{MINDLIN_STEM}.png`)",
        "",
        f"The friction law `FrictionLaw('coulomb', mu={MINDLIN_FRICTION.mu:g})` (each spring holds μ times its normal "
        f"force) with the paper's material without adhesion: vertically in to d = {MINDLIN_DEPTH_SHARE:.4g} d_max, then "
        f"along x through {turns} times the full-slip shift μ E* d / G* (the virgin curve, a Mindlin loop, full slip). "
        "The closed form is Cattaneo–Mindlin's virgin curve `μ (F_N(d) − F_N(d − x G*/(μ E*)))` and Masing's rules "
        f"(`mdr_events.mindlin.tangential_force`); `{MINDLIN_STEM}.nc` (continuum) and `{MINDLIN_STEM}_discrete.nc` "
        "carry it as `cattaneo_mindlin_force`.",
        "",
    ]
    lines += markdown_table(["method", "max \\|F_x − closed form\\| / (μ F_N)"],
                            [[row.method, _difference_text(row)] for row in mindlin_rows(check)])
    return lines + [""]


def _plans(check: MindlinCheck, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    exact, plan = dataset_plan(check.continuum, out / f"{MINDLIN_STEM}.nc", keep_agreeing)
    springs, discrete_plan = dataset_plan(check.discrete, out / f"{MINDLIN_STEM}_discrete.nc", keep_agreeing)
    figure = plot_mindlin_check(exact, springs)
    return [[plan, discrete_plan, figure_plan(figure, out / f"{MINDLIN_STEM}.png", keep_agreeing)]]


MINDLIN = Section(
    name="mindlin",
    steps=(Step(f"Cattaneo–Mindlin: Coulomb's law (μ = {MINDLIN_FRICTION.mu:g}) at a constant depth, continuum and "
                f"discrete (Δx = {FIGURE_DX * 1e6:g} µm) against the closed form",
                lambda: mindlin_check(Parameters.paper())),),
    collect=lambda results: results[0],
    render=mindlin_lines,
    plan=_plans,
    writing="writing the Cattaneo–Mindlin check (.nc, .png)",
    files=(f"- `{MINDLIN_STEM}.png`, `{MINDLIN_STEM}.nc` (continuum) and `{MINDLIN_STEM}_discrete.nc`: Coulomb's law "
           "at a", "  constant depth against Cattaneo–Mindlin."),
)
