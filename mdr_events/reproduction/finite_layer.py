"""Layers of finite thickness (issue 34, the normal problem): the pull-off force from the half-space to the thin
limits, and an indentation to ``d_max`` and back on the paper's 5 mm layer beside the half-space.

The paper's paraboloids (R = 30 mm and 100 mm) on its elastomer (``E``, ``ν = 0.5``, inferred) with its works of
adhesion, on a layer bonded to or sliding on a rigid base (:mod:`mdr_events.theory.layer`). The thin limits of the
pull-off over the half-space's ``(3/2)πΔγ1 R`` follow from the thin layers' stiffness and Heß's rule minimised by
hand: the incompressible bonded layer (thin film, ``K = 3πGa⁴/(8h³)``) ``3πΔγ1 R``, a ratio 2; the frictionless
base (Winkler, ``κ = E*/h``) ``2πΔγ1 R``, a ratio 4/3; both independent of ``h`` (``tests/theory/test_layer_curves``
checks the approach).

The outside check (issue 34, item 6): ContactMechanics' boundary-element forces of a non-adhesive paraboloid on a
bonded 5 mm layer (ν = 0.49, a/h from 0.4 to 1.5), recorded by ``tools/contactmechanics_layer_check.py`` in
``data/layer_contactmechanics_check.csv`` with its own grid and box errors, against the MDR's forces computed afresh.
"""

from __future__ import annotations

import csv
import math
from importlib import resources
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, figure_plan
from mdr_events.contact.indenters import Paraboloid
from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.contact.model import Contact
from mdr_events.parameters import PAPER_D_MAX, Parameters
from mdr_events.plotting.layer import plot_layer_cycles, plot_pull_off_against_thickness
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory.layer import branch_depth, normal_force
from mdr_events.theory.layer.curves import layer_indentation_cycle, layer_pull_off_curve

__all__ = ["FINITE_LAYER", "LAYER_STEM", "LAYER_THICKNESS", "LayerResults", "LayerRow", "OutsideRow", "layer_results",
           "layer_rows", "layer_lines", "outside_check", "THIN_LIMITS", "OUTSIDE_CHECK"]

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
#: ContactMechanics' recorded forces (``tools/contactmechanics_layer_check.py``).
OUTSIDE_CHECK = "data/layer_contactmechanics_check.csv"
#: The radii the MDR's depth is inverted on, relative to the half-space's ``sqrt(R d)``: a/h up to 3 at 5 mm.
_RADIUS_GRID = np.geomspace(1e-5, 2.0, 40001)


class LayerRow(NamedTuple):
    """One paraboloid's maxima on the half-space and on the layer."""

    R: float
    force_max: tuple[float, float]
    area_max: tuple[float, float]
    pull_off: tuple[float, float]


class LayerResults(NamedTuple):
    """The pull-off curves (label -> dataset) and the cycles (label -> dataset) with the table's rows, and the
    outside check's rows."""

    pull_off: dict[str, xr.Dataset]
    cycles: dict[str, xr.Dataset]
    rows: list[LayerRow]
    outside: list["OutsideRow"] = []


class OutsideRow(NamedTuple):
    """One case of the outside check: ContactMechanics' recorded force and the MDR's computed now."""

    R: float  #: m
    depth: float  #: m
    nu: float
    thickness: float  #: m
    relative_radius: float  #: the MDR's a/h
    force_mdr: float  #: N
    force_cm: float  #: N, ContactMechanics' finest grid in its larger box
    cm_change: float  #: ContactMechanics' own uncertainty: its grid and box changes, relative, summed


def outside_check() -> list[OutsideRow]:
    """ContactMechanics' recorded forces (:data:`OUTSIDE_CHECK`) beside the MDR's, computed afresh: the non-adhesive
    paraboloid's radius at the depth on the bonded layer (its branch (9) at ``Δγ = 0`` inverted on a fine grid of
    radii) and its force (10)."""
    rows = []
    with resources.files("mdr_events.reproduction").joinpath(OUTSIDE_CHECK).open(encoding="utf-8") as handle:
        for record in csv.DictReader(handle):
            R, depth, nu, h = (float(record[key]) for key in ("R_m", "depth_m", "nu", "thickness_m"))
            E_star = Parameters.paper(R).E / (1.0 - nu**2)
            layer, indenter = Layer(h, LayerBase.BONDED), Paraboloid(R)
            radii = _RADIUS_GRID * math.sqrt(R * depth)
            radius = float(np.interp(depth, branch_depth(radii, indenter, E_star, nu, 0.0, layer), radii))
            rows.append(OutsideRow(R, depth, nu, h, radius / h,
                                   float(normal_force(depth, radius, indenter, E_star, nu, layer)),
                                   float(record["normal_force_cm_N"]),
                                   float(record["cm_grid_change"]) + float(record["cm_box_change"])))
    return rows


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
    """The table: each paraboloid's ``F_N,max``, ``A_max`` and ``|F_N,min|`` on the half-space and the layer, and the
    rise."""
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


def _outside_lines(rows: list[OutsideRow]) -> list[str]:
    """The outside check's paragraph and table."""
    table = markdown_table(["R", "d", "a/h", "F_N, MDR", "F_N, ContactMechanics", "MDR / CM − 1", "CM's own change"],
                           [[f"{row.R * 1e3:g} mm", f"{row.depth * 1e3:g} mm", f"{row.relative_radius:.3f}",
                             f"{row.force_mdr:.6g} N", f"{row.force_cm:.6g} N",
                             f"{row.force_mdr / row.force_cm - 1.0:.1e}", f"{row.cm_change:.1e}"] for row in rows],
                           ["default"] * 2 + ["right"] * 5)
    worst = max(abs(row.force_mdr / row.force_cm - 1.0) for row in rows)
    return ["An outside check: ContactMechanics (`PeriodicFFTElasticHalfSpace(..., thickness=h, poisson=ν)`, a "
            "boundary-element method on a periodic FFT grid, the Green's function of a layer bonded to a rigid base "
            "with a frictionless top) against the MDR on the same layer (5 mm, ν = 0.49 < 0.5, where its Green's "
            "function is regular), a non-adhesive paraboloid. ContactMechanics' forces were recorded by "
            "`tools/contactmechanics_layer_check.py` (its grid a/Δx ≈ 16 and 32, its box 16 and 32 contact radii: "
            "the last column sums the two changes); the MDR's are computed afresh. They agree to "
            f"{worst:.1e} of the force, within ContactMechanics' own change, for a/h from "
            f"{rows[0].relative_radius:.2f} to {max(row.relative_radius for row in rows):.2f}.", ""] + table + [""]


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
            "half-space simulation (with sliding: the next section, the discrete model on the layer). Figure: "
            f"`{LAYER_STEM}_cycles.png`.", ""] + table + [""] + _outside_lines(results.outside)


def _plans(results: LayerResults, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    labels = {f"thin limit, {base} base": value for base, value in THIN_LIMITS.items()}
    pull = plot_pull_off_against_thickness(results.pull_off, labels)
    cycles = plot_layer_cycles(results.cycles)
    return [[figure_plan(pull, out / f"{LAYER_STEM}_pull_off.png", keep_agreeing),
             figure_plan(cycles, out / f"{LAYER_STEM}_cycles.png", keep_agreeing)]]


FINITE_LAYER = Section(
    name="finite_layer",
    steps=(Step("layers of finite thickness: pull-off against h (R = 30, 100 mm; bonded, frictionless) and the 5 mm "
                "layer's indentation cycle (the layer's tables: built once in a few seconds each, then cached)",
                layer_results),
           Step("layers of finite thickness: ContactMechanics' recorded forces against the MDR's (the outside check)",
                outside_check)),
    collect=lambda results: results[0]._replace(outside=results[1]),
    render=layer_lines,
    plan=_plans,
    writing="writing the finite-layer figures",
    files=(f"- `{LAYER_STEM}_pull_off.png`, `{LAYER_STEM}_cycles.png`: the pull-off force against a/h from the "
           "half-space", "  to the thin limits, and F_N(d) on the paper's 5 mm layer beside the half-space."),
)
