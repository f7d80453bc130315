"""Layers of finite thickness: the critical angles against the thickness (issue 34, item 5).

The paper's paraboloids (R = 30 mm and 100 mm) on its elastomer with its works of adhesion and ``τ0``, on a layer
bonded to a rigid base from 0.3 mm to 50 mm thick and the half-space
(:func:`~mdr_events.analysis.layer_angles.critical_angles_against_thickness`): scenario A at ``d_max``, B at the
jump-off, B+ at ``2 d_max``, with and without adhesion, and scenario A's thin-layer limit ``atan(G d_max/(τ0 h))``.
"""

from __future__ import annotations

from pathlib import Path as FilePath

import numpy as np
import xarray as xr

from mdr_events.analysis.layer_angles import critical_angles_against_thickness
from mdr_events.app.result_files import PlannedFile, figure_plan
from mdr_events.contact.model import Contact
from mdr_events.parameters import PAPER_D_MAX, Parameters
from mdr_events.plotting.layer import plot_critical_angles_against_thickness
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step

__all__ = ["LAYER_ANGLES", "LAYER_ANGLES_STEM", "ANGLE_THICKNESSES", "layer_angle_curves", "layer_angle_lines"]

#: The figure's stem in ``results/``.
LAYER_ANGLES_STEM = "finite_layer_critical_angles"
#: The thicknesses (m): 0.3 mm (a/h ≈ 14 at d_max for R = 30 mm) to 50 mm, the paper's 5 mm and the table's among
#: them, and the half-space last.
ANGLE_THICKNESSES = np.array([3e-4, 4e-4, 5e-4, 7e-4, 1e-3, 1.5e-3, 2e-3, 3e-3, 5e-3, 7e-3, 1e-2, 1.5e-2, 2e-2, 3e-2,
                              5e-2, np.inf])
#: The rows of the report's table (m).
_TABLE_THICKNESSES = (np.inf, 2e-2, 5e-3, 1e-3)
#: The paper's two paraboloids (m).
_RADII = (0.03, 0.1)


def layer_angle_curves() -> dict[str, xr.Dataset]:
    """The critical angles against the thickness for each paraboloid (label -> dataset, :data:`ANGLE_THICKNESSES`)."""
    return {f"R = {R * 1e3:g} mm": critical_angles_against_thickness(Contact.from_parameters(Parameters.paper(R)),
                                                                       ANGLE_THICKNESSES)
            for R in _RADII}


def _rows(curves: dict[str, xr.Dataset]) -> list[list[str]]:
    """Each paraboloid's angles at the table's thicknesses (2 decimals: the angles are known to ~1e-7 relative)."""
    rows = []
    for label, curve in curves.items():
        for h in _TABLE_THICKNESSES:
            at = curve.sel(thickness=h)
            rows.append([label, "half-space" if h == np.inf else f"{h * 1e3:g} mm",
                         *(f"{float(at.critical_angle_jkr.sel(scenario=s)):.2f}°" for s in ("A", "B", "B+")),
                         f"{float(at.critical_angle_hertz.sel(scenario='A')):.2f}°"])
    return rows


def layer_angle_lines(curves: dict[str, xr.Dataset]) -> list[str]:
    """The section of ``results/README.md``."""
    table = markdown_table(["paraboloid", "layer", "A (adhesive)", "B (adhesive)", "B+ (adhesive)", "A (no adhesion)"],
                           _rows(curves), ["default", "default", "right", "right", "right", "right"])
    return ["", "## Layers of finite thickness: the critical angles", "",
            "The critical angles of the paper's scenarios (`me.critical_angle`, `me.critical_angles_against_thickness`) "
            "on a layer bonded to a rigid base: the springs' cap (13) becomes π a² τ0 / K_t(a) with the layer's "
            "tangential punch stiffness K_t, and the radius follows the layer's branches (Heß's rule with K'(a)). "
            f"Scenario A at d_max = {PAPER_D_MAX * 1e3:g} mm, B at the jump-off on the Δγ1 branch, B+ at 2 d_max. A "
            "thinner layer shears more easily, so its springs take a larger shift before they slide: every angle "
            "rises, and scenario A's tends to the thin layer's atan(G d_max / (τ0 h)) (dashed; independent of the "
            f"adhesion and the indenter). Figure: `{LAYER_ANGLES_STEM}.png`.", ""] + table + [""]


def _plans(curves: dict[str, xr.Dataset], out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    figure = plot_critical_angles_against_thickness(curves)
    return [[figure_plan(figure, out / f"{LAYER_ANGLES_STEM}.png", keep_agreeing)]]


LAYER_ANGLES = Section(
    name="layer_angles",
    steps=(Step("layers of finite thickness: the critical angles against h (R = 30, 100 mm)", layer_angle_curves),),
    collect=lambda results: results[0],
    render=layer_angle_lines,
    plan=_plans,
    writing="writing the critical angles against the layer's thickness",
    files=(f"- `{LAYER_ANGLES_STEM}.png`: the critical angles of scenarios A, B and B+ against the layer's",
           "  thickness, with and without adhesion, and scenario A's thin-layer limit."),
)
