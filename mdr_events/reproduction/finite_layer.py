"""Layers of finite thickness (issue 34, the normal problem): the pull-off force from the half-space to the thin
limits, and an indentation to ``d_max`` and back on the paper's 5 mm layer beside the half-space.

The paper's paraboloids (R = 30 mm and 100 mm) on its elastomer (``E``, ``ν = 0.5``, inferred) with its works of
adhesion, on a layer bonded to or sliding on a rigid base (:mod:`mdr_events.theory.layer`). The thin limits of the
pull-off over the half-space's ``(3/2)πΔγ1 R`` follow from the thin layers' stiffness and Heß's rule minimised by
hand: the incompressible bonded layer (thin film, ``K = 3πGa⁴/(8h³)``) ``3πΔγ1 R``, a ratio 2; the frictionless
base (Winkler, ``κ = E*/h``) ``2πΔγ1 R``, a ratio 4/3; both independent of ``h`` (``tests/theory/test_layer_curves``
checks the approach).
"""

from __future__ import annotations

import math
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import FileOutcome, write_figure
from mdr_events.contact.model import Contact
from mdr_events.parameters import PAPER_D_MAX, Parameters
from mdr_events.plotting.layer import plot_layer_cycles, plot_pull_off_against_thickness
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory.layer.curves import layer_indentation_cycle, layer_pull_off_curve

__all__ = ["FINITE_LAYER", "LAYER_STEM", "LAYER_THICKNESS", "LayerResults", "LayerRow", "layer_results",
           "layer_rows", "layer_lines", "THIN_LIMITS"]

#: The stem of the section's figures in ``results/``.
LAYER_STEM = "finite_layer"
#: The layer of the paper's experiment (m).
LAYER_THICKNESS = 5e-3
#: The paper's two paraboloids (m).
RADII = (0.03, 0.1)
#: The thicknesses of the pull-off curves: the half-space's pull-off radius at ``Δγ1`` times these (from the
#: half-space side, a/h ≈ 1e-3, to a/h ≈ 20 (thin film) and 37 (Winkler) on the thin side).
THICKNESS_FACTORS = np.geomspace(1e3, 1.5e-2, 25)
#: The thin limits of ``|F_po| / ((3/2)πΔγ1 R)`` by base (module docstring).
THIN_LIMITS = {"bonded": 2.0, "frictionless": 4.0 / 3.0}
#: Samples of each stage of an indentation cycle.
CYCLE_SAMPLES = 201


class LayerRow(NamedTuple):
    """One paraboloid's maxima on the half-space and on the layer."""

    R: float
    force_max: tuple[float, float]
    area_max: tuple[float, float]
    pull_off: tuple[float, float]


class LayerResults(NamedTuple):
    """The pull-off curves (label -> dataset) and the cycles (label -> dataset) with the table's rows."""

    pull_off: dict[str, xr.Dataset]
    cycles: dict[str, xr.Dataset]
    rows: list[LayerRow]


def _pull_off_radius(contact: Contact) -> float:
    """The half-space's pull-off radius at ``Δγ1``: ``(9πΔγ1 R²/(8E*))^(1/3)`` (JKR)."""
    return (9.0 * math.pi * contact.adhesion.dgamma1 * contact.indenter.R**2
            / (8.0 * contact.elastomer.E_star)) ** (1.0 / 3.0)


def layer_results() -> LayerResults:
    """Every curve of the section: the pull-off against ``h`` (both radii, both bases) and the cycles at 5 mm."""
    curves, cycles, rows = {}, {}, []
    for R in RADII:
        contact = Contact.from_parameters(Parameters.paper(R))
        for base in THIN_LIMITS:
            based = contact.replace(**{"layer.base": base})
            curves[f"R = {R * 1e3:g} mm, {base} base"] = layer_pull_off_curve(
                based, _pull_off_radius(contact) * THICKNESS_FACTORS)
        layered = contact.replace(h=LAYER_THICKNESS)
        pair = [layer_indentation_cycle(c, PAPER_D_MAX, CYCLE_SAMPLES) for c in (contact, layered)]
        pulls = [float(layer_pull_off_curve(c, [c.layer.thickness]).pull_off_force[0]) for c in (contact, layered)]
        cycles[f"R = {R * 1e3:g} mm, half-space"], cycles[f"R = {R * 1e3:g} mm, h = 5 mm bonded"] = pair
        rows.append(LayerRow(R, tuple(float(c.normal_force.max()) for c in pair),
                             tuple(float(c.contact_area.max()) for c in pair), tuple(pulls)))
    return LayerResults(curves, cycles, rows)


def layer_rows(results: LayerResults) -> list[list[str]]:
    """The table: each paraboloid's F_N,max, A_max and |F_N,min| on the half-space and the layer, and the rise."""
    table = []
    for row in results.rows:
        for name, (half, layer), unit, scale in (("F_N,max", row.force_max, "N", 1.0),
                                                 ("A_max", row.area_max, "mm²", 1e6),
                                                 ("\\|F_N,min\\|", row.pull_off, "N", -1.0)):
            table.append([f"{row.R * 1e3:g} mm", name, f"{half * scale:.4g} {unit}", f"{layer * scale:.4g} {unit}",
                          f"{layer / half:.3f}"])
    return table


def _asymptote_lines(results: LayerResults) -> list[str]:
    """The pull-off at the thinnest layer of each curve against its limit."""
    lines = []
    for label, curve in results.pull_off.items():
        base = curve.attrs["param_layer_base"]
        ratio = -float(curve.pull_off_force[-1]) / (1.5 * math.pi * curve.attrs["param_dgamma1"]
                                                     * curve.attrs["param_R"])
        lines.append(f"{label}: {ratio:.4g} at a/h = {float(curve.relative_radius[-1]):.3g} (limit "
                     f"{THIN_LIMITS[base]:.4g})")
    return lines


def layer_lines(results: LayerResults) -> list[str]:
    """The section of ``results/README.md``."""
    table = markdown_table(["R", "quantity", "half-space", "h = 5 mm, bonded", "layer / half-space"],
                           layer_rows(results), ["default", "default", "right", "right", "right"])
    return ["", "## Layers of finite thickness: pull-off and the 5 mm layer (normal problem)", "",
            "The generalized MDR of an elastic layer on a rigid base (`mdr_events.theory.layer`; `Contact.layer`) "
            "with the paper's paraboloids, elastomer (ν = 0.5) and works of adhesion. The pull-off force under "
            "force control (`me.layer_pull_off_curve`, Δγ1) over the half-space's (3/2)πΔγ1R rises from 1 (the "
            "half-space) to the thin limits derived from the thin layers' stiffness: 2 on a bonded incompressible "
            "layer (thin film), 4/3 on a frictionless base (Winkler); R = 30 mm and 100 mm fall on one curve "
            "against a/h at pull-off (the MDR's scaling). At the thinnest layer computed: "
            + "; ".join(_asymptote_lines(results)) + f". Figure: `{LAYER_STEM}_pull_off.png`.", "",
            "The paper's experiment indents a layer 5 mm thick (bonded): vertically to d_max = "
            f"{PAPER_D_MAX * 1e3:g} mm on the Δγ0 branch and back, the radius pinned until the Δγ1 branch, then "
            "along it to the jump-off (`me.layer_indentation_cycle`; F_N,min is the pull-off under force control, "
            "which the cycle passes). The layer raises every maximum, as the paper's measurements exceed its "
            "half-space simulation (the tangential part is a later phase of issue 34). Figure: "
            f"`{LAYER_STEM}_cycles.png`.", ""] + table + [""]


def _write(results: LayerResults, out: FilePath, keep_agreeing: bool) -> list[list[FileOutcome]]:
    labels = {f"thin limit, {base} base": value for base, value in THIN_LIMITS.items()}
    pull = plot_pull_off_against_thickness(results.pull_off, labels)
    cycles = plot_layer_cycles(results.cycles)
    return [[write_figure(pull, out / f"{LAYER_STEM}_pull_off.png", keep_agreeing),
             write_figure(cycles, out / f"{LAYER_STEM}_cycles.png", keep_agreeing)]]


FINITE_LAYER = Section(
    name="finite_layer",
    steps=(Step("layers of finite thickness: pull-off against h (R = 30, 100 mm; bonded, frictionless) and the 5 mm "
                "layer's indentation cycle (the layer's tables: built once in a few seconds each, then cached)",
                layer_results),),
    collect=lambda results: results[0],
    render=layer_lines,
    write=_write,
    writing="writing the finite-layer figures",
    files=(f"- `{LAYER_STEM}_pull_off.png`, `{LAYER_STEM}_cycles.png`: the pull-off force against a/h from the "
           "half-space", "  to the thin limits, and F_N(d) on the paper's 5 mm layer beside the half-space."),
)
