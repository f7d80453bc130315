"""Convergence of the discrete model (R = 30 mm): to the exact extrema of the continuum over the spacings, and to
the continuum over a whole run (:mod:`mdr_events.analysis.convergence`)."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from mdr_events.analysis.convergence import (HISTORY_QUANTITIES, discrete_errors, discrete_minus_continuum,
                                             observed_orders)
from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import SCENARIOS
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step

__all__ = ["CONVERGENCE", "ConvergenceRuns", "ConvergenceRow", "HistoryConvergence", "extremum_convergence",
           "history_convergence", "CONVERGENCE_SPACINGS", "HISTORY_SPACINGS", "HISTORY_ANGLE"]

#: Convergence to the exact extrema: spacings (m) and angles (degrees); the time step moves the indenter Δx/2.
CONVERGENCE_SPACINGS = (16e-6, 8e-6, 4e-6, 2e-6, 1e-6)
CONVERGENCE_ANGLES = (10.0, 30.0, 60.0)
#: Convergence to the continuum over a whole run: spacings (m) and the angle (degrees).
HISTORY_SPACINGS = (8e-6, 4e-6, 2e-6, 1e-6)
HISTORY_ANGLE = 30.0
#: Extrema of the discrete model whose convergence the report shows, in its order.
CONVERGENCE_EXTREMA = ("normal_force_min", "contact_area_max", "tangential_force_max")
#: Labels of the quantities in the convergence tables.
CONVERGENCE_LABELS = {"normal_force_min": "F_N,min", "contact_area_max": "A_max", "tangential_force_max": "F_x,max",
                      "normal_force": "F_N", "tangential_force": "F_x", "contact_area": "A"}


class ConvergenceRuns(NamedTuple):
    """The discrete model's relative errors: per angle against the exact extrema, per scenario against the
    continuum over the whole run."""

    discrete_errors: dict[float, dict[str, np.ndarray]]
    history: dict[str, dict[str, np.ndarray]]


class ConvergenceRow(NamedTuple):
    """Relative errors of one quantity, one per spacing, and the observed orders between neighbours."""

    case: float | str  #: the angle (degrees) or the scenario
    quantity: str
    errors: np.ndarray
    orders: np.ndarray


class HistoryConvergence(NamedTuple):
    """The discrete model against the continuum over a whole run of one scenario."""

    rows: list[ConvergenceRow]  #: one per quantity of :data:`HISTORY_QUANTITIES`
    samples_left_out: list[int]  #: one per spacing


def extremum_convergence(runs: ConvergenceRuns) -> list[ConvergenceRow]:
    """Errors of the :data:`CONVERGENCE_EXTREMA` against their exact values, per angle and spacing."""
    return [ConvergenceRow(alpha, key, errors[key], observed_orders(CONVERGENCE_SPACINGS, errors[key]))
            for alpha, errors in runs.discrete_errors.items() for key in CONVERGENCE_EXTREMA]


def history_convergence(runs: ConvergenceRuns) -> dict[str, HistoryConvergence]:
    """Per scenario: ``max |discrete − continuum| / max |continuum|`` over :data:`HISTORY_SPACINGS`."""
    result = {}
    for scenario, history in runs.history.items():
        rows = [ConvergenceRow(scenario, name, history[name], observed_orders(HISTORY_SPACINGS, history[name]))
                for name in HISTORY_QUANTITIES]
        result[scenario] = HistoryConvergence(rows, [int(n) for n in history["samples_left_out"]])
    return result


def _cells(case: str, row: ConvergenceRow) -> list[str]:
    """The row's case and quantity, then the first error and each further one with its observed order."""
    return ([case, CONVERGENCE_LABELS[row.quantity], f"{row.errors[0]:.2e}"]
            + [f"{e:.2e} ({o:.2f})" for e, o in zip(row.errors[1:], row.orders)])


def _spacing_titles(spacings: tuple[float, ...]) -> list[str]:
    return [f"Δx = {dx * 1e6:g} µm" for dx in spacings]


def _history_rows(histories: dict[str, HistoryConvergence]) -> list[list[str]]:
    rows = []
    for scenario, history in histories.items():
        rows += [_cells(scenario, row) for row in history.rows]
        rows.append([scenario, "samples left out", *(str(n) for n in history.samples_left_out)])
    return rows


def convergence_lines(runs: ConvergenceRuns) -> list[str]:
    """The section's text: the errors and observed orders, to the exact extrema and over the whole run."""
    lines = [
        "",
        "## Convergence of the discrete model (R = 30 mm)",
        "",
        "### To the exact extrema (scenario A)",
        "",
        "Relative error against the exact extrema of the continuum solution (`solution_extrema`; for scenario A",
        "they equal F_N,min = −(3/2)πΔγ1R, A_max = π a(d_max)² on the Δγ0 branch and F_x,max from the stick/slip",
        "integral at d_max to 1e-8, `mdr_events.analysis.convergence`), with the time",
        "step refined with Δx (the indenter moves Δx/2 per step). Observed order in brackets. The paper",
        "says the solution does not depend on Δx: it does, at first order, by about 0.1 % at Δx = 1 µm.",
        "A_max is quantised to a = mΔx, so its error is bounded by Δx/a but does not fall smoothly;",
        "likewise F_N,min, whose sampled radius is off by up to Δx/2, so that its error is bounded by",
        "E* Δl_max(a_F) Δx / |F_N,min| (about 1e-3 per µm here) without falling smoothly.",
        "",
    ]
    lines += markdown_table(["α", "quantity", *_spacing_titles(CONVERGENCE_SPACINGS)],
                            [_cells(f"{row.case:g}°", row) for row in extremum_convergence(runs)])
    lines += [
        "",
        f"### To the continuum over the whole run (α = {HISTORY_ANGLE:g}°)",
        "",
        "max over time of |discrete − continuum| divided by max over time of |continuum|, the continuum",
        "evaluated at the discrete model's sample times (`mdr_events.analysis.convergence.discrete_minus_continuum`);",
        "observed order in brackets. Left out (their number is in the last row): the samples at which one",
        "method is in contact and the other not (the jump-in, met up to one step apart), and the sample",
        "ending the time step that straddles a path corner (the discrete model cuts the corner there).",
        "",
    ]
    return lines + markdown_table(["scenario", "quantity", *_spacing_titles(HISTORY_SPACINGS)],
                                  _history_rows(history_convergence(runs)))


def _errors_at_extrema() -> dict[float, dict[str, np.ndarray]]:
    params = Parameters.paper()
    return {alpha: discrete_errors(params, alpha, CONVERGENCE_SPACINGS, steps_per_spacing=0.5)
            for alpha in CONVERGENCE_ANGLES}


def _errors_over_runs() -> dict[str, dict[str, np.ndarray]]:
    params = Parameters.paper()
    return {scenario: discrete_minus_continuum(params, scenario, HISTORY_ANGLE, HISTORY_SPACINGS)
            for scenario in SCENARIOS}


CONVERGENCE = Section(
    name="convergence",
    steps=(Step(f"convergence of the discrete model to the exact extrema ({len(CONVERGENCE_SPACINGS)} spacings, "
                f"{len(CONVERGENCE_ANGLES)} angles)", _errors_at_extrema),
           Step("convergence of the discrete model to the continuum over the whole run", _errors_over_runs)),
    collect=lambda errors: ConvergenceRuns(*errors),
    render=convergence_lines,
)
