"""Coulomb's law with adhesion at a constant depth (``mindlin_coulomb_adhesive``): the loop of the Cattaneo–Mindlin
check (:mod:`.mindlin`) with the paper's adhesion (Heß's rule, Δγ0 < Δγ1), continuum and discrete, each beside the
closed form, which is the one without adhesion: Coulomb's part is the compressed zone's, free of Δγ
(:func:`mdr_events.theory.symbolic.derive_adhesive_friction_model`; the continuum's ``PathSolution.compressed``).

The datasets carry the closed form as the check without adhesion does (``study="cattaneo_mindlin"``, whose schema
and accuracy :mod:`.mindlin` registers).
"""

from __future__ import annotations

from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, dataset_plan, figure_plan
from mdr_events.models.simulate import simulate
from mdr_events.parameters import Parameters
from mdr_events.plotting.mindlin import plot_mindlin_check
from mdr_events.reproduction.common import FIGURE_DX
from mdr_events.reproduction.markdown import markdown_table, relative_difference_text
from mdr_events.reproduction.mindlin import (MINDLIN_CASE, MINDLIN_FRICTION, MINDLIN_REPORTED_BOUND, MINDLIN_SAMPLES,
                                             MINDLIN_STEM, MindlinCheck, _with_closed_form, mindlin_check,
                                             mindlin_path)
from mdr_events.reproduction.section import Section, Step

__all__ = ["MINDLIN_ADHESIVE", "MINDLIN_ADHESIVE_STEM", "AdhesiveMindlin", "AdhesiveRow", "adhesive_mindlin",
           "adhesive_rows", "adhesive_lines"]

#: The stem of the section's files in ``results/``.
MINDLIN_ADHESIVE_STEM = "mindlin_coulomb_adhesive"


class AdhesiveMindlin(NamedTuple):
    """The loop with the paper's adhesion (continuum and discrete) and the same loop without it."""

    adhesive: MindlinCheck
    without: MindlinCheck


def adhesive_mindlin(params: Parameters) -> AdhesiveMindlin:
    """:func:`~.mindlin.mindlin_check`'s path and law with the adhesion of ``params``: the continuum at
    ``MINDLIN_SAMPLES`` times and the path's corners, the discrete model at Δx = FIGURE_DX (dt = Δx/(2v)), each with
    the closed form on its samples; beside it the check without adhesion."""
    path, depth = mindlin_path(params)
    start = path.first_contact_time()
    times = np.union1d(np.linspace(0.0, path.duration - start, MINDLIN_SAMPLES), path.corner_times[1:] - start)
    continuum = simulate(params, {MINDLIN_CASE: path}, method="continuum", t=times, friction=MINDLIN_FRICTION)
    discrete = simulate(params, {MINDLIN_CASE: path}, dx=FIGURE_DX, dt=0.5 * FIGURE_DX / params.v,
                        friction=MINDLIN_FRICTION)
    adhesive = MindlinCheck(_with_closed_form(continuum, path, depth, params),
                            _with_closed_form(discrete, path, depth, params))
    return AdhesiveMindlin(adhesive, mindlin_check(params))


class AdhesiveRow(NamedTuple):
    """One method's largest difference from the closed form with adhesion, and from its own run without, over the
    full slip μ F_N^H (the largest closed form)."""

    method: str
    max_difference: float
    from_without: float


def _largest_difference(first: xr.Dataset, second: xr.Dataset, name: str, scale: float) -> float:
    """``max |first − second|`` of ``name`` over the samples both hold, over ``scale``."""
    difference = first[name].values - second[name].values
    return float(np.nanmax(np.abs(difference))) / scale


def adhesive_rows(check: AdhesiveMindlin) -> list[AdhesiveRow]:
    """The rows of the section's table: the continuum's and the discrete model's differences."""
    full = float(np.nanmax(check.adhesive.continuum["cattaneo_mindlin_force"].values))
    rows = []
    for method, adhesive, without in (("continuum", check.adhesive.continuum, check.without.continuum),
                                      (f"discrete, Δx = {FIGURE_DX * 1e6:g} µm", check.adhesive.discrete,
                                       check.without.discrete)):
        closed = adhesive["tangential_force"].values - adhesive["cattaneo_mindlin_force"].values
        rows.append(AdhesiveRow(method, float(np.nanmax(np.abs(closed))) / full,
                                _largest_difference(adhesive, without, "tangential_force", full)))
    return rows


def _text(value: float) -> str:
    """Below ``MINDLIN_REPORTED_BOUND`` as that bound (the continuum's solver's digits differ between machines)."""
    return f"< {MINDLIN_REPORTED_BOUND:g}" if value < MINDLIN_REPORTED_BOUND else relative_difference_text(value)


def adhesive_lines(check: AdhesiveMindlin) -> list[str]:
    """The section: the loop with adhesion against the closed form and against the loop without adhesion."""
    params = check.adhesive.continuum.attrs
    lines = [
        f"## Coulomb's law with adhesion: Cattaneo–Mindlin of the compressed zone (`{MINDLIN_ADHESIVE_STEM}.png`)",
        "",
        f"The loop of `{MINDLIN_STEM}` with the paper's adhesion (Δγ0 = {params['param_dgamma0']:g}, Δγ1 = "
        f"{params['param_dgamma1']:g} J/m²): the springs beyond x_c, where g(x_c) = d, are in tension and hold no "
        "Coulomb shift, and the compressed springs are the contact without adhesion of the same path, so the closed "
        "form is the same Cattaneo–Mindlin loop, free of Δγ (full slip μ F_N^H(d), above μ F_N). "
        f"`{MINDLIN_ADHESIVE_STEM}.nc` (continuum) and `{MINDLIN_ADHESIVE_STEM}_discrete.nc` carry it as "
        "`cattaneo_mindlin_force`; the last column is each method's difference from its own run without adhesion "
        f"(`{MINDLIN_STEM}*.nc`).",
        "",
    ]
    lines += markdown_table(["method", "max \\|F_x − closed form\\| / (μ F_N^H)", "max \\|F_x − F_x without "
                             "adhesion\\| / (μ F_N^H)"],
                            [[row.method, _text(row.max_difference), _text(row.from_without)]
                             for row in adhesive_rows(check)])
    return lines + [""]


def _plans(check: AdhesiveMindlin, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    exact, plan = dataset_plan(check.adhesive.continuum, out / f"{MINDLIN_ADHESIVE_STEM}.nc", keep_agreeing)
    springs, discrete_plan = dataset_plan(check.adhesive.discrete, out / f"{MINDLIN_ADHESIVE_STEM}_discrete.nc",
                                          keep_agreeing)
    figure = plot_mindlin_check(exact, springs)
    return [[plan, discrete_plan, figure_plan(figure, out / f"{MINDLIN_ADHESIVE_STEM}.png", keep_agreeing)]]


MINDLIN_ADHESIVE = Section(
    name="mindlin_adhesive",
    steps=(Step(f"Cattaneo–Mindlin with adhesion: Coulomb's law (μ = {MINDLIN_FRICTION.mu:g}) at a constant depth "
                f"with and without the paper's adhesion, continuum and discrete (Δx = {FIGURE_DX * 1e6:g} µm)",
                lambda: adhesive_mindlin(Parameters.paper())),),
    collect=lambda results: results[0],
    render=adhesive_lines,
    plan=_plans,
    writing="writing the Cattaneo–Mindlin check with adhesion (.nc, .png)",
    files=(f"- `{MINDLIN_ADHESIVE_STEM}.{{nc,png}}` (continuum) and `{MINDLIN_ADHESIVE_STEM}_discrete.nc`: "
           "Coulomb's law with", "  adhesion at a constant depth against Cattaneo–Mindlin of the compressed zone."),
)
