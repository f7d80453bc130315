"""Fig. 9: the phase diagrams of scenarios A (9a) and B (9b) for both radii (``phase_diagram_<A|B>_<R30|R100>``)."""

from __future__ import annotations

from functools import partial
from pathlib import Path

import xarray as xr

from mdr_events.app.result_files import PlannedFile, phase_diagram_plans
from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import jobs
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory.phase import phase_diagram

__all__ = ["PHASE_DIAGRAMS", "phase_diagram_stem"]

#: The paper's figure of each scenario's phase diagram.
PHASE_FIGURES = {"A": "9a", "B": "9b"}


def phase_diagram_stem(label: str, scenario: str) -> str:
    """The stem of a phase diagram's files: ``phase_diagram_A_R30``."""
    return f"phase_diagram_{scenario}_{label}"


def _compute(radius: float, scenario: str) -> xr.Dataset:
    return phase_diagram(Parameters.paper(R=radius), scenario=scenario)


def _collect(diagrams: list[xr.Dataset]) -> dict[tuple[str, str], xr.Dataset]:
    return {(label, scenario): diagram for (label, _, scenario), diagram in zip(jobs(), diagrams)}


def _plans(diagrams: dict[tuple[str, str], xr.Dataset], out: Path, keep_agreeing: bool) -> list[list[PlannedFile]]:
    return [phase_diagram_plans(diagram, out, phase_diagram_stem(label, scenario), keep_agreeing)
            for (label, scenario), diagram in diagrams.items()]


PHASE_DIAGRAMS = Section(
    name="phase_diagrams",
    steps=tuple(Step(f"Fig. {PHASE_FIGURES[scenario]}, R = {radius * 1e3:g} mm (phase diagram)",
                     partial(_compute, radius, scenario)) for _, radius, scenario in jobs()),
    collect=_collect,
    render=lambda diagrams: [],
    plan=_plans,
    writing="writing Fig. 9a and 9b (.nc, .png)",
    files=("- `phase_diagram_A_R30.{nc,png}`, `phase_diagram_A_R100.{nc,png}`: Fig. 9a.",
           "- `phase_diagram_B_R30.{nc,png}`, `phase_diagram_B_R100.{nc,png}`: Fig. 9b."),
)
