"""The four differences between simulation and experiment of section 4.2, read off the runs of Fig. 8 and 10
(:mod:`mdr_events.reproduction.figures`): the rows of their tables (named tuples of plain numbers in SI units) and
their text."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import FIGURE_DX, OVERLAY_ANGLE, event_times, first_or_nan
from mdr_events.reproduction.markdown import markdown_table, relative_difference_text
from mdr_events.theory import analytic

__all__ = ["Differences", "differences", "differences_lines", "PAPER_TAU0", "DETAIL_CASE"]

#: The stated plateau of the mean shear stress in pull-off, Pa.
PAPER_TAU0 = 42e3
#: The case whose event log and extremes the differences (1)–(4) show in detail: (radius label, scenario).
DETAIL_CASE = ("R30", "A")

#: The runs of the figures by (radius label, scenario), and each run's exact extremes (name -> one per angle).
Runs = dict[tuple[str, str], xr.Dataset]
Extremes = dict[tuple[str, str], dict[str, np.ndarray]]


class AdhesiveStrengthRow(NamedTuple):
    """|F_N,min| (N) of one (radius, scenario): JKR, the continuum over the angles, the discrete model."""

    radius: float
    scenario: str
    jkr: float  #: (3/2) π Δγ1 R
    continuum_min: float
    continuum_max: float
    largest_relative_difference: float  #: of the continuum from JKR
    discrete: float  #: at :data:`OVERLAY_ANGLE`


class PinnedIntervalRow(NamedTuple):
    """The interval (s) after ``d_max`` during which the radius stays pinned, and ``F_x``'s change (N) over it."""

    alpha: float
    d_max_time: float
    detachment_time: float
    tangential_force_change: float

    @property
    def duration(self) -> float:
        return self.detachment_time - self.d_max_time


class MaximaRow(NamedTuple):
    """Exact maxima of one continuum run (SI units)."""

    alpha: float
    normal_force: float
    tangential_force: float
    contact_area: float
    mean_pressure: float


class ShearPlateauRow(NamedTuple):
    """Whether the mean shear stress of a scenario-A run reaches ``τ0`` before the jump-off."""

    radius: float
    alpha: float
    travel: float  #: x1 = d_max / tan α (m)
    shift_at_jump_off: float  #: ū(a_jump-off) (m)
    largest_shear_stress: float  #: Pa
    reaches_tau0: bool
    full_slip_time: float | None  #: s, the last full slip; None if none


class AreaGrowthRow(NamedTuple):
    """How smoothly the contact area grows during indentation in one run."""

    alpha: float
    jump_in_area: float  #: π a0² (m²)
    largest_step_share: float  #: largest change between samples, as a share of A_max
    sample_spacing: float  #: s


@dataclass
class Differences:
    """The tables of the four differences between simulation and experiment of section 4.2."""

    samples_per_run: int
    adhesive_strength: list[AdhesiveStrengthRow]
    pinned_intervals: list[PinnedIntervalRow]
    maxima: list[MaximaRow]
    shear_plateau: list[ShearPlateauRow]
    area_growth: list[AreaGrowthRow]


def adhesive_strength_rows(continuum: Runs, discrete: Runs, extremes: Extremes) -> list[AdhesiveStrengthRow]:
    """|F_N,min| against JKR's (3/2) π Δγ1 R for every (radius, scenario)."""
    rows = []
    for key, ds in continuum.items():
        params = Parameters.from_attrs(ds.attrs)
        jkr = -analytic.pull_off_force(params, params.dgamma1)
        values = -extremes[key]["normal_force_min"]
        worst = np.max(np.abs(values - jkr)) / jkr
        springs = -float(discrete[key]["normal_force"].min())
        rows.append(AdhesiveStrengthRow(params.R, key[1], jkr, values.min(), values.max(), worst, springs))
    return rows


def pinned_interval_rows(ds: xr.Dataset) -> list[PinnedIntervalRow]:
    """From ``d_max`` (the corner) to the start of detachment, per angle of a continuum run."""
    rows = []
    for alpha in ds["alpha"].values:
        corner = first_or_nan(event_times(ds, alpha, "corner"))
        release = first_or_nan(event_times(ds, alpha, "detachment_starts"))
        case = ds.sel(alpha=alpha)
        inside = (case["time"] >= corner) & (case["time"] <= release)
        force = case["tangential_force"].values[inside.values]
        change = float(np.max(force) - np.min(force)) if force.size else math.nan
        rows.append(PinnedIntervalRow(alpha, corner, release, change))
    return rows


def maxima_rows(ds: xr.Dataset, extremes: dict[str, np.ndarray]) -> list[MaximaRow]:
    """The exact maxima of each angle's run (``extremes``: those of its case)."""
    return [MaximaRow(alpha, extremes["normal_force_max"][i], extremes["tangential_force_max"][i],
                      extremes["contact_area_max"][i], extremes["mean_pressure_max"][i])
            for i, alpha in enumerate(ds["alpha"].values)]


def shear_plateau_rows(continuum: Runs, extremes: Extremes) -> list[ShearPlateauRow]:
    """Every scenario-A angle of every radius: does τ reach τ0 in pull-off?"""
    rows = []
    for (label, scenario), ds in continuum.items():
        if scenario != "A":
            continue
        params = Parameters.from_attrs(ds.attrs)
        cap = float(analytic.critical_shift(analytic.jump_off(params, params.dgamma1)["contact_radius"], params))
        for i, alpha in enumerate(ds["alpha"].values):
            x1 = params.d_max / math.tan(math.radians(alpha))
            tau = float(extremes[(label, scenario)]["mean_shear_stress_max"][i])
            full = event_times(ds, alpha, "full_slip")
            rows.append(ShearPlateauRow(params.R, alpha, x1, cap, tau, math.isclose(tau, params.tau0, rel_tol=1e-9),
                                        float(full[-1]) if len(full) else None))
    return rows


def area_growth_rows(ds: xr.Dataset) -> list[AreaGrowthRow]:
    """The jump-in area and the largest change of A between samples before ``d_max``, per angle."""
    rows = []
    for alpha in ds["alpha"].values:
        case = ds.sel(alpha=alpha)
        corner = first_or_nan(event_times(ds, alpha, "corner"))
        area = case["contact_area"].values
        indentation = case["time"].values <= corner
        steps = np.abs(np.diff(area[indentation]))
        spacing = float(case["time"].values[1] - case["time"].values[0])
        rows.append(AreaGrowthRow(alpha, area[0], steps.max() / np.nanmax(area), spacing))
    return rows


def differences(continuum: Runs, discrete: Runs, extremes: Extremes) -> Differences:
    """The tables of the four differences (the detailed ones of :data:`DETAIL_CASE`)."""
    detail = continuum[DETAIL_CASE]
    return Differences(
        samples_per_run=detail.sizes["time"],
        adhesive_strength=adhesive_strength_rows(continuum, discrete, extremes),
        pinned_intervals=pinned_interval_rows(detail),
        maxima=maxima_rows(detail, extremes[DETAIL_CASE]),
        shear_plateau=shear_plateau_rows(continuum, extremes),
        area_growth=area_growth_rows(detail),
    )


# ----------------------------------------------------------------------------
# the text
def _adhesive_strength_lines(samples_per_run: int, rows: list[AdhesiveStrengthRow]) -> list[str]:
    lines = [
        "",
        "## The four differences between simulation and experiment of section 4.2",
        "",
        "Panels refer to `fig8_R30.png` (scenario A) and `fig10_R30.png` (scenario B): (a) F_N, (b) F_x,",
        f"(c) A, (d) <p>, (e) τ. Continuum method, {samples_per_run} samples per run.",
        "",
        "### (1) The adhesive strength |F_N,min| is the same for every angle (panel a)",
        "",
        "The paper: normal and tangential contact are independent, so |F_N,min| does not depend on α;",
        "JKR gives |F_N,min| = (3/2) π Δγ1 R. Ours (continuum, the exact minimum of each run's solution,",
        f"`mdr_events.models.continuum.extremum`; the discrete model at {OVERLAY_ANGLE:g}°, "
        f"Δx = {FIGURE_DX * 1e6:g} µm, for comparison):",
        "",
    ]
    return lines + markdown_table(
        ["R", "scenario", "(3/2)πΔγ1R", "continuum, min over angles", "max over angles",
         "largest relative difference", f"discrete at {OVERLAY_ANGLE:g}°"],
        [[f"{row.radius * 1e3:g} mm", row.scenario, f"{row.jkr * 1e3:.4f} mN", f"{row.continuum_min * 1e3:.4f} mN",
          f"{row.continuum_max * 1e3:.4f} mN", relative_difference_text(row.largest_relative_difference),
          f"{row.discrete * 1e3:.4f} mN"] for row in rows])


def _pinned_interval_lines(rows: list[PinnedIntervalRow]) -> list[str]:
    lines = [
        "",
        "The same independence makes A and F_x constant at the start of pull-off (panels c and b): the",
        "radius stays pinned from d_max until d falls to the Δγ1 branch, and in scenario A the indenter",
        "moves only normally then. Scenario A, R = 30 mm (continuum event log):",
        "",
    ]
    return lines + markdown_table(
        ["α", "d_max reached", "detachment starts", "interval of constant A", "F_x change over it"],
        [[f"{row.alpha:g}°", f"{row.d_max_time:.1f} s", f"{row.detachment_time:.1f} s", f"{row.duration:.1f} s",
          f"{row.tangential_force_change:.1e} N"] for row in rows])


def _maxima_lines(rows: list[MaximaRow]) -> list[str]:
    lines = [
        "",
        "### (2) Maximum forces, area and pressure are below the experiment's (panels a–d)",
        "",
        "The paper: the experiment used a layer of h = 5 mm, the model is a half-space (h → ∞), whose",
        "contact is softer. The experimental values are in the paper's Fig. 5, not in the section text, so",
        "only ours are listed (scenario A, R = 30 mm, continuum, exact maxima of each run's solution):",
        "",
    ]
    return lines + markdown_table(
        ["α", "F_N,max", "F_x,max", "A_max", "<p>_max"],
        [[f"{row.alpha:g}°", f"{row.normal_force * 1e3:.3f} mN", f"{row.tangential_force * 1e3:.3f} mN",
          f"{row.contact_area * 1e6:.3f} mm²", f"{row.mean_pressure / 1e3:.3f} kPa"] for row in rows])


def _shear_plateau_cells(row: ShearPlateauRow) -> list[str]:
    full_slip = f"{row.full_slip_time:.1f} s" if row.full_slip_time is not None else "—"
    return [f"{row.radius * 1e3:g} mm", f"{row.alpha:g}°", f"{row.travel * 1e6:.1f} µm",
            f"{row.shift_at_jump_off * 1e6:.1f} µm", f"{row.largest_shear_stress / 1e3:.2f} kPa",
            "yes" if row.reaches_tau0 else "no", full_slip]


def _shear_plateau_lines(rows: list[ShearPlateauRow]) -> list[str]:
    lines = [
        "",
        f"### (3) The τ0 = {PAPER_TAU0 / 1e3:g} kPa plateau in pull-off (panel e)",
        "",
        "The paper: \"in the pull-off phase ... the tangential stresses in all cases increase to the",
        "maximum stationary value τ0\". In the model every spring slides once ū(a) of the shrinking",
        "contact falls below the indenter's travel x1 = d_max/tan α, and that happens before the jump-off",
        "only if ū(a_jump-off) < x1. **Where it does not, τ stays below τ0**: with the inferred E, ν and v",
        "this is the case at 70° and 80° for R = 30 mm and from 50° on for R = 100 mm. Scenario A,",
        "largest τ per angle (continuum, exact maximum of each run's solution; full slip from the event log):",
        "",
    ]
    return lines + markdown_table(["R", "α", "x1", "ū(a_jump-off)", "τ_max", "reaches τ0", "full slip at"],
                                  [_shear_plateau_cells(row) for row in rows])


def _area_growth_lines(rows: list[AreaGrowthRow]) -> list[str]:
    lines = [
        "",
        "### (4) The contact area grows smoothly (panel c)",
        "",
        "The paper: in the experiment new regions of rubber attach abruptly; in the model the area grows",
        "only through the normal JKR contact, hence smoothly. Ours: after the JKR jump-in at first contact,",
        "A changes between consecutive samples by at most the share of A_max below (it is continuous,",
        "so this share falls with the sample spacing); scenario A, R = 30 mm:",
        "",
    ]
    return lines + markdown_table(
        ["α", "jump-in area πa0²", "largest change between samples during indentation", "sample spacing"],
        [[f"{row.alpha:g}°", f"{row.jump_in_area * 1e6:.4f} mm²", f"{row.largest_step_share:.2e} of A_max",
          f"{row.sample_spacing:.2f} s"] for row in rows])


def differences_lines(continuum: Runs, discrete: Runs, extremes: Extremes) -> list[str]:
    """The text of the four differences (section 4.2) from the figures' runs."""
    tables = differences(continuum, discrete, extremes)
    return (_adhesive_strength_lines(tables.samples_per_run, tables.adhesive_strength)
            + _pinned_interval_lines(tables.pinned_intervals)
            + _maxima_lines(tables.maxima)
            + _shear_plateau_lines(tables.shear_plateau)
            + _area_growth_lines(tables.area_growth))
