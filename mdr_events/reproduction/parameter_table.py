"""The parameters of the reproduction: the paper's set (R = 30 mm), which of them section 4 states and which are
inferred, and the effective moduli derived from them. Read, not computed: no step to announce."""

from __future__ import annotations

from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, Parameters
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section

__all__ = ["PARAMETERS", "parameter_lines"]


def _parameter_rows(params: Parameters) -> list[list[str]]:
    rows = []
    for name, value in params.as_dict().items():
        source = "**inferred** (not stated in section 4)" if name in Parameters.INFERRED_FIELDS else "section 4"
        rows.append([f"{name} ({PARAMETER_LONG_NAMES[name]})", f"{value:.6g}", PARAMETER_UNITS[name], source])
    return rows + [["E*", f"{params.E_star:.6g}", "Pa", "derived"], ["G*", f"{params.G_star:.6g}", "Pa", "derived"]]


def parameter_lines(params: Parameters) -> list[str]:
    """The table of the parameters, each with its unit and where it comes from."""
    lines = ["", "## Parameters (R = 30 mm; the R = 100 mm set differs only in R)", ""]
    return lines + markdown_table(["parameter", "value", "unit", "source"], _parameter_rows(params)) + [""]


PARAMETERS = Section(
    name="parameters",
    steps=(),
    collect=lambda results: Parameters.paper(),
    render=parameter_lines,
)
