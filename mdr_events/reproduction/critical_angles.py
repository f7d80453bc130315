"""The critical angles: scenario A's (slip begins exactly at ``d_max``, eqs. (17) and (18)) beside the paper's, and
the angle of scenario B above which the contact comes apart before any spring slides (eq. (21)). Closed forms:
no step to announce."""

from __future__ import annotations

from typing import NamedTuple

from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import RADII
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section
from mdr_events.theory import analytic

__all__ = ["CRITICAL_ANGLES", "PAPER_CRITICAL_ANGLES", "CriticalAngleRow", "ScenarioBAngleRow", "CriticalAngles",
           "critical_angles_A", "critical_angles_B"]

#: Critical angles stated in section 4 (R = 30 mm), degrees.
PAPER_CRITICAL_ANGLES = {"hertz": 23.59, "jkr": 22.87}


class CriticalAngleRow(NamedTuple):
    """A critical angle of scenario A (slip begins exactly at ``d_max``), ours and the paper's."""

    radius: float
    model: str  #: "hertz" (eq. (17)) or "jkr" (eq. (18))
    equation: str
    computed: float  #: degrees
    paper: float | None  #: degrees; None where the paper states none


class ScenarioBAngleRow(NamedTuple):
    """The angle above which, in scenario B, the contact comes apart before any spring slides."""

    radius: float
    angle: float  #: degrees, adhesive (eq. (21) at the jump-off)


class CriticalAngles(NamedTuple):
    """The rows of the section's two tables."""

    scenario_A: list[CriticalAngleRow]
    scenario_B: list[ScenarioBAngleRow]


def critical_angles_A() -> list[CriticalAngleRow]:
    """The critical angles of scenario A for each radius, non-adhesive and adhesive."""
    rows = []
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        for model, adhesive, equation in (("hertz", False, "(17)"), ("jkr", True, "(18)")):
            paper = PAPER_CRITICAL_ANGLES[model] if label == "R30" else None
            rows.append(CriticalAngleRow(radius, model, equation,
                                         analytic.critical_angle(params, "A", adhesion=adhesive), paper))
    return rows


def critical_angles_B() -> list[ScenarioBAngleRow]:
    """The adhesive critical angle of scenario B for each radius."""
    return [ScenarioBAngleRow(radius, analytic.critical_angle(Parameters.paper(R=radius), "B", adhesion=True))
            for radius in RADII.values()]


def _critical_angle_cells(row: CriticalAngleRow) -> list[str]:
    paper_text = f"{row.paper:.2f}°" if row.paper is not None else "not stated"
    difference = f"{row.computed - row.paper:+.3f}°" if row.paper is not None else "—"
    model = row.model.upper() if row.model == "jkr" else "Hertz"
    return [f"{row.radius * 1e3:g} mm", f"α_c {model} {row.equation}", paper_text, f"{row.computed:.3f}°", difference]


def critical_angle_lines(angles: CriticalAngles) -> list[str]:
    """The section's text: scenario A's angles beside the paper's, then scenario B's."""
    lines = ["## Critical angles of scenario A (slip begins exactly at d_max)", ""]
    lines += markdown_table(["R", "quantity", "paper", "mdr_events", "difference"],
                            [_critical_angle_cells(row) for row in angles.scenario_A])
    lines += [
        "",
        "## Scenario B: angle above which the contact comes apart before any spring slides",
        "",
        "From eq. (21) (pull-off branch, Δγ1) at the jump-off point; without adhesion slip",
        "always comes first (90°). Not stated in the paper.",
        "",
    ]
    return lines + markdown_table(["R", "α (adhesive)"],
                                  [[f"{row.radius * 1e3:g} mm", f"{row.angle:.3f}°"] for row in angles.scenario_B])


CRITICAL_ANGLES = Section(
    name="critical_angles",
    steps=(),
    collect=lambda results: CriticalAngles(critical_angles_A(), critical_angles_B()),
    render=critical_angle_lines,
)
