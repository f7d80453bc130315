"""``mdr-events reproduce``: regenerate ``results/`` and its README.

Everything in ``results/`` is written by :func:`reproduce`, deterministically
(same input, same bytes), so that a test can compare the committed report
with a fresh computation. The figures of the simulations come from the
continuum method, with the paper's discrete spring model overlaid for one
angle; the report puts the section's stated numbers beside ours. A fretting
study (reciprocating sliding at ``d_max``, R = 30 mm) adds ``fretting_R30.*``
and the energy dissipated per cycle beside its closed form; a fit to synthetic
measurements adds ``fit_A20_R30*`` and the recovered parameters beside the true ones.

What the report says is computed in :mod:`mdr_events.app.report_data`; this
module only writes it as markdown.
"""

from __future__ import annotations

import importlib.metadata
import math
import platform
import re
from pathlib import Path
from typing import Callable

from mdr_events._version import __version__
from mdr_events.app.report_data import (FIT_DEMO_ANGLE, FIT_DEMO_NOISE, FIT_DEMO_SAMPLES, FIT_DEMO_SEED, FitDemonstration,
                                        COMPUTE_STEPS, CONVERGENCE_SPACINGS, FIGURE_DX, FIGURE_NUMBERS,
                                        FIGURE_STEPS, FRETTING_ANGLE, FRETTING_CYCLES, FRETTING_OBLIQUE,
                                        FRETTING_RADIUS, HISTORY_ANGLE, HISTORY_SPACINGS, OVERLAY_ANGLE,
                                        PAPER_CRITICAL_ANGLES, PAPER_TAU0, PROFILE_ANGLE, RADII, AdhesiveStrengthRow,
                                        AreaGrowthRow, ProfileRow, profile_rows,
                                        ConvergenceRow, CriticalAngleRow, CrossCheckRow, Differences, FrettingStudy,
                                        HistoryConvergence, MaximaRow, PinnedIntervalRow, Reproduction,
                                        ScenarioBAngleRow, ShearPlateauRow, SlipOnsetVerdict, compute,
                                        critical_angles_A, critical_angles_B, cross_check_rows, differences,
                                        extremum_convergence, fretting_rows, history_convergence, jobs,
                                        MINDLIN_DEPTH_SHARE, MINDLIN_FRICTION, MINDLIN_TURNS, MindlinRow,
                                        mindlin_rows)
from mdr_events.app.result_files import (FileOutcome, FileStatus, describe_outcomes, write_dataset, write_figure,
                                         write_phase_diagram, write_simulation, write_text)
from mdr_events.io.agreement import rounded_text_differences
from mdr_events.models.continuum import Tolerances
from mdr_events.io.datasets import DOI
from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, Parameters
from mdr_events.contact.indenters import FlatPunch
from mdr_events.plotting.figures import plot_fretting
from mdr_events.plotting.fit import plot_fit
from mdr_events.plotting.universal import plot_universal_map
from mdr_events.plotting.profiles import plot_profile_comparison
from mdr_events.plotting.mindlin import plot_mindlin_check
from mdr_events.theory.analytic import critical_angle, dimensionless_groups

__all__ = ["reproduce", "report_text", "compute", "Reproduction", "PAPER_CRITICAL_ANGLES", "RADII", "FIGURE_NUMBERS",
           "software_versions", "recorded_versions", "RECORDED_PACKAGES", "fretting_section", "relative_difference_text",
           "FRETTING_STEM", "WRITE_STEPS", "PROFILE_STEM", "profile_rows", "profiles_section", "MINDLIN_STEM",
           "mindlin_section"]

#: Relative differences below this are round-off, whose digits differ between machines: the report prints
#: "< 1e-12" for them, so that it stays the same text everywhere.
REPORT_ROUNDOFF = 1e-12
#: The relative accuracy of what the continuum integrates (its ``rtol``, :class:`mdr_events.io.agreement.Integrated`):
#: a difference from it below this is printed as "< 1e-10" (the energy of a fretting loop, the flat punch's F_x).
INTEGRATED_ACCURACY = Tolerances().rtol
#: Packages whose versions ``results/README.md`` records (the lock file pins them, with the rest).
RECORDED_PACKAGES = ("numpy", "scipy", "sympy", "matplotlib", "xarray", "pandas")
#: The stem of the fretting study's files in ``results/``.
FRETTING_STEM = f"fretting_{FRETTING_RADIUS}"
#: The stem of the fit demonstration's files in ``results/``.
FIT_STEM = f"fit_A{FIT_DEMO_ANGLE:g}_R30"
#: The stem of the universal map's files in ``results/``.
UNIVERSAL_STEM = "universal_map"
#: The comparison of indenters (:func:`~mdr_events.app.report_data.profile_comparison`).
PROFILE_STEM = f"profiles_A{PROFILE_ANGLE:g}"
#: The Cattaneo–Mindlin check of Coulomb's law (:func:`~mdr_events.app.report_data.mindlin_check`).
MINDLIN_STEM = "mindlin_coulomb"
#: Differences from the closed form below this (the tests' bound on the continuum) are reported as below it.
MINDLIN_REPORTED_BOUND = 1e-9
#: Progress steps of :func:`reproduce` after :func:`compute`: Fig. 8 and 10; the fretting study, the fit and README.md.
WRITE_STEPS = 2



def _mm(value: float, digits: int = 4) -> str:
    return "—" if not math.isfinite(value) else f"{value * 1e3:.{digits}f}"


def relative_difference_text(value: float, accuracy: float = REPORT_ROUNDOFF) -> str:
    """A relative difference as the report prints it: ``< accuracy`` below the accuracy of what it compares (default
    :data:`REPORT_ROUNDOFF`, round-off; :data:`INTEGRATED_ACCURACY` for a value integrated by the continuum), whose
    digits differ between machines, else two digits (``2.5e-09``)."""
    return f"< {accuracy:g}" if abs(value) < accuracy else f"{value:.1e}"


# ----------------------------------------------------------------------------
# critical angles
def _critical_angle_line(row: CriticalAngleRow) -> str:
    paper_text = f"{row.paper:.2f}°" if row.paper is not None else "not stated"
    diff = f"{row.computed - row.paper:+.3f}°" if row.paper is not None else "—"
    model = row.model.upper() if row.model == "jkr" else "Hertz"
    return (f"| {row.radius * 1e3:g} mm | α_c {model} {row.equation} "
            f"| {paper_text} | {row.computed:.3f}° | {diff} |")


def _critical_angle_section(scenario_a: list[CriticalAngleRow], scenario_b: list[ScenarioBAngleRow]) -> list[str]:
    lines = [
        "## Critical angles of scenario A (slip begins exactly at d_max)",
        "",
        "| R | quantity | paper | mdr_events | difference |",
        "|---|---|---|---|---|",
    ]
    lines += [_critical_angle_line(row) for row in scenario_a]
    lines += [
        "",
        "## Scenario B: angle above which the contact comes apart before any spring slides",
        "",
        "From eq. (21) (pull-off branch, Δγ1) at the jump-off point; without adhesion slip",
        "always comes first (90°). Not stated in the paper.",
        "",
        "| R | α (adhesive) |",
        "|---|---|",
    ]
    lines += [f"| {row.radius * 1e3:g} mm | {row.angle:.3f}° |" for row in scenario_b]
    return lines


# ----------------------------------------------------------------------------
# slip onset, three ways
def _verdict_text(verdict: SlipOnsetVerdict, scenario: str) -> str:
    phase_end = "jump-off" if scenario == "B" else "d_max"
    return {
        SlipOnsetVerdict.NO_SLIP_IN_INDENTATION: "no slip in indentation (closed form beyond d_max)",
        SlipOnsetVerdict.JUMP_OFF_FIRST: "jump-off before any slip",
        SlipOnsetVerdict.FOUND_ONCE_AT_PHASE_END: f"agree: only one method slips, within tolerance of the {phase_end}",
        SlipOnsetVerdict.PINNED: "pinned",
        SlipOnsetVerdict.DISAGREE: "**disagree**",
        SlipOnsetVerdict.AGREE: "agree",
    }[verdict]


def _cross_check_line(row: CrossCheckRow) -> str:
    line = (f"| {row.radius * 1e3:g} mm | {row.scenario} | {row.alpha:g}° | {_mm(row.closed_form, 5)} "
            f"| {_mm(row.continuum, 5)} | {_mm(row.discrete, 5)} | {row.discrete_minus_continuum * 1e6:+.3f} µm "
            f"| {row.tolerance * 1e6:.3f} µm | {_verdict_text(row.verdict, row.scenario)} |")
    return line.replace("+nan µm", "—")


def _cross_check_section(rows: list[CrossCheckRow]) -> list[str]:
    lines = [
        "",
        "## Slip onset: closed form, continuum and discrete model side by side",
        "",
        "Depth d at which the first spring slides (mm): scenario A during indentation, eq. (18);",
        "scenario B during pull-off, eq. (21). Continuum: the event log of the continuum method.",
        f"Discrete: the paper's spring model, Δx = {FIGURE_DX * 1e6:g} µm, {FIGURE_STEPS} time steps; its",
        "tolerance is 3KΔx plus one time step of depth (K = π τ0 tan α / (2G*)). \"pinned\": in scenario B the",
        "radius is still pinned at a(d_max; Δγ0) when the springs slide, which (21) does not model, so the",
        "closed form is not expected to agree (see `mdr_events.cross_check`).",
        "",
        "| R | scenario | α | closed form | continuum | discrete | discrete − continuum | tolerance | note |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    return lines + [_cross_check_line(row) for row in rows]


# ----------------------------------------------------------------------------
# the four differences between simulation and experiment (section 4.2)
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
        f"`mdr_events.models.continuum.extremum`; the discrete model at {OVERLAY_ANGLE:g}°, Δx = {FIGURE_DX * 1e6:g} µm, "
        "for comparison):",
        "",
        "| R | scenario | (3/2)πΔγ1R | continuum, min over angles | max over angles | largest relative difference "
        f"| discrete at {OVERLAY_ANGLE:g}° |",
        "|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        worst_text = relative_difference_text(row.largest_relative_difference)
        lines.append(f"| {row.radius * 1e3:g} mm | {row.scenario} | {row.jkr * 1e3:.4f} mN "
                     f"| {row.continuum_min * 1e3:.4f} mN | {row.continuum_max * 1e3:.4f} mN | {worst_text} "
                     f"| {row.discrete * 1e3:.4f} mN |")
    return lines


def _pinned_interval_lines(rows: list[PinnedIntervalRow]) -> list[str]:
    lines = [
        "",
        "The same independence makes A and F_x constant at the start of pull-off (panels c and b): the",
        "radius stays pinned from d_max until d falls to the Δγ1 branch, and in scenario A the indenter",
        "moves only normally then. Scenario A, R = 30 mm (continuum event log):",
        "",
        "| α | d_max reached | detachment starts | interval of constant A | F_x change over it |",
        "|---|---|---|---|---|",
    ]
    return lines + [f"| {row.alpha:g}° | {row.d_max_time:.1f} s | {row.detachment_time:.1f} s "
                    f"| {row.duration:.1f} s | {row.tangential_force_change:.1e} N |" for row in rows]


def _maxima_lines(rows: list[MaximaRow]) -> list[str]:
    lines = [
        "",
        "### (2) Maximum forces, area and pressure are below the experiment's (panels a–d)",
        "",
        "The paper: the experiment used a layer of h = 5 mm, the model is a half-space (h → ∞), whose",
        "contact is softer. The experimental values are in the paper's Fig. 5, not in the section text, so",
        "only ours are listed (scenario A, R = 30 mm, continuum, exact maxima of each run's solution):",
        "",
        "| α | F_N,max | F_x,max | A_max | <p>_max |",
        "|---|---|---|---|---|",
    ]
    return lines + [f"| {row.alpha:g}° | {row.normal_force * 1e3:.3f} mN | {row.tangential_force * 1e3:.3f} mN "
                    f"| {row.contact_area * 1e6:.3f} mm² | {row.mean_pressure / 1e3:.3f} kPa |" for row in rows]


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
        "| R | α | x1 | ū(a_jump-off) | τ_max | reaches τ0 | full slip at |",
        "|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        full_slip = f"{row.full_slip_time:.1f} s" if row.full_slip_time is not None else "—"
        lines.append(f"| {row.radius * 1e3:g} mm | {row.alpha:g}° | {row.travel * 1e6:.1f} µm "
                     f"| {row.shift_at_jump_off * 1e6:.1f} µm | {row.largest_shear_stress / 1e3:.2f} kPa "
                     f"| {'yes' if row.reaches_tau0 else 'no'} | {full_slip} |")
    return lines


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
        "| α | jump-in area πa0² | largest change between samples during indentation | sample spacing |",
        "|---|---|---|---|",
    ]
    return lines + [f"| {row.alpha:g}° | {row.jump_in_area * 1e6:.4f} mm² | {row.largest_step_share:.2e} of A_max "
                    f"| {row.sample_spacing:.2f} s |" for row in rows]


def _differences_section(tables: Differences) -> list[str]:
    return (_adhesive_strength_lines(tables.samples_per_run, tables.adhesive_strength)
            + _pinned_interval_lines(tables.pinned_intervals)
            + _maxima_lines(tables.maxima)
            + _shear_plateau_lines(tables.shear_plateau)
            + _area_growth_lines(tables.area_growth))


# ----------------------------------------------------------------------------
# convergence of the discrete model
def _convergence_cells(row: ConvergenceRow) -> str:
    cells = [f"{row.errors[0]:.2e}"] + [f"{e:.2e} ({o:.2f})" for e, o in zip(row.errors[1:], row.orders)]
    return " | ".join(cells)


#: Labels of the quantities in the convergence tables.
CONVERGENCE_LABELS = {"normal_force_min": "F_N,min", "contact_area_max": "A_max", "tangential_force_max": "F_x,max",
                      "normal_force": "F_N", "tangential_force": "F_x", "contact_area": "A"}


def _convergence_section(extrema: list[ConvergenceRow], histories: dict[str, HistoryConvergence]) -> list[str]:
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
        "| α | quantity | " + " | ".join(f"Δx = {dx * 1e6:g} µm" for dx in CONVERGENCE_SPACINGS) + " |",
        "|---|---|" + "---|" * len(CONVERGENCE_SPACINGS),
    ]
    lines += [f"| {row.case:g}° | {CONVERGENCE_LABELS[row.quantity]} | " + _convergence_cells(row) + " |"
              for row in extrema]
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
        "| scenario | quantity | " + " | ".join(f"Δx = {dx * 1e6:g} µm" for dx in HISTORY_SPACINGS) + " |",
        "|---|---|" + "---|" * len(HISTORY_SPACINGS),
    ]
    for scenario, history in histories.items():
        lines += [f"| {scenario} | {CONVERGENCE_LABELS[row.quantity]} | " + _convergence_cells(row) + " |"
                  for row in history.rows]
        lines.append(f"| {scenario} | samples left out | "
                     + " | ".join(str(n) for n in history.samples_left_out) + " |")
    return lines


# ----------------------------------------------------------------------------
# fretting at d_max
def fretting_section(study: FrettingStudy) -> list[str]:
    """The report's section on the fretting study: the energy dissipated per cycle, closed form, continuum and
    discrete model, for the last closed loop of each case."""
    rows = fretting_rows(study)
    first = rows[0]
    discrete = study.discrete.attrs
    radius = study.continuum.attrs["param_R"]
    speed = float(study.continuum["path_speed"].values[0])
    oblique = next(row for row in rows if row.case == FRETTING_OBLIQUE)
    lines = [
        "",
        f"## Fretting at d_max (R = {radius * 1e3:g} mm)",
        "",
        f"Reciprocating sliding at d = d_max with the amplitude X = {first.amplitude / first.cap:g}ū(a_max) = "
        f"{first.amplitude * 1e3:.4f} mm (a_max = {first.contact_radius * 1e3:.4f} mm, the Δγ0",
        f"contact radius at d_max; ū = π a τ0/(2G*) = {first.cap * 1e3:.4f} mm): {FRETTING_CYCLES} full cycles "
        "x_c → x_c + X → x_c − X → … → x_c + X,",
        f"then out vertically; after vertical indentation (x_c = 0) and after scenario A's in-path at "
        f"{FRETTING_ANGLE:g}° (x_c = d_max/tan {FRETTING_ANGLE:g}° =",
        f"{oblique.centre * 1e3:.4f} mm). The depth, hence the contact, stays fixed while it slides, so that each "
        "loop of F_x against x",
        f"is the parallelogram of the fixed contact: plateaus ±π a² τ0, slopes 2G* a (`{FRETTING_STEM}.png`, dashed).",
        "Energy dissipated per cycle, over the last closed loop of each case (between its last two tangential",
        f"reversals of the same direction, from the event log `{FRETTING_STEM}_events.csv`). Continuum: ∫F_x dx of the",
        "solution, `mdr_events.models.continuum.solution.tangential_work`. Discrete: the paper's spring model,",
        f"Δx = {discrete['dx'] * 1e6:g} µm, {study.discrete.sizes['time'] - 1} time steps (the indenter moves v dt = "
        f"{discrete['dt'] * speed * 1e6:.2f} µm per step), the trapezoid",
        "rule on its samples between the same two times (its ends up to one step inside the loop).",
        "",
        "| case | x_c | loop | closed form 4πa²τ0(X − ū) | continuum | relative difference | discrete "
        "| relative difference |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        lines.append(f"| {row.case} | {row.centre * 1e3:.4f} mm | {row.loop_start:.1f} s – {row.loop_end:.1f} s "
                     f"| {row.closed_form * 1e3:.6f} mJ | {row.continuum * 1e3:.6f} mJ "
                     f"| {relative_difference_text(row.continuum_difference, INTEGRATED_ACCURACY)} | "
                     f"{row.discrete * 1e3:.6f} mJ "
                     f"| {row.discrete_difference:+.1e} |")
    return lines


#: Significant digits of a fitted value in the report: its accuracy (c standard errors, 1e-7 of it here:
#: :mod:`mdr_events.analysis.fit_accuracy`) lies far below the last.
FIT_DIGITS = 5


def _estimated(value: float) -> str:
    """A fitted value to :data:`FIT_DIGITS` significant digits, trailing zeros kept, written with a fraction or an
    exponent, so that it reads as a rounded value (compared within one unit of its last digit), not as a count."""
    text = f"{value:#.{FIT_DIGITS}g}"
    return f"{value:.{FIT_DIGITS - 1}e}" if text.endswith(".") else text


def fit_section(demo: FitDemonstration) -> list[str]:
    """The report's section on the fit demonstration: true, start and recovered parameters with intervals."""
    fitted = demo.result
    lines = ["", "## Fitting to measurements: a demonstration", "",
             f"Synthetic \"measured\" curves: the continuum of scenario A at {FIT_DEMO_ANGLE:g}° (R = 30 mm), "
             f"F_N, F_x and A at {FIT_DEMO_SAMPLES} samples, with white noise of {FIT_DEMO_NOISE:.0%} of each "
             f"quantity's largest magnitude (seed {FIT_DEMO_SEED}; `{FIT_STEM}_measured.nc`). `mdr_events.fit` "
             f"started 30 % off and estimated the noise itself (`{FIT_STEM}.{{nc,png}}`):",
             "",
             "| parameter | true | start | fitted | 95 % interval | truth inside | verdict |",
             "|---|---:|---:|---:|---|:---:|---|"]
    for name, estimate in fitted.estimates.items():
        truth = getattr(demo.truth, name)
        inside = "yes" if estimate.lower <= truth <= estimate.upper else "**no**"
        lines.append(f"| {name} | {truth:.5g} | {getattr(demo.start, name):.5g} | {_estimated(estimate.value)} | "
                     f"[{_estimated(estimate.lower)}, {_estimated(estimate.upper)}] | {inside} | "
                     f"{estimate.identifiability.value} |")
    dataset = fitted.dataset
    lines += ["", f"Verdict: {fitted.verdict}; condition number {fitted.condition_number:.1f}; reduced χ² "
                  f"{float(dataset['reduced_chi_square']):.3f}.", ""]
    return lines


def universal_section(dataset) -> list[str]:
    """The report's section on the universal map: the groups, and the paper's sets on it."""
    lines = ["", "## The universal map", "",
             "Measured in `d_max` (depths, tangential travel) and `√(R d_max)` (radii), the model has three "
             "parameters: the slip parameter `S = π τ0 √R / (2 G* √d_max)` and the adhesion parameters "
             "`Γ = 2π Δγ √R / (E* d_max^(3/2))` of the two works of adhesion (`mdr_events.analytic."
             "dimensionless_groups`). Every angle, every depth over `d_max` and `F_x/(π a² τ0)` depend on "
             "them (and the path's angle) alone; a test checks it with two parameter sets of equal groups. "
             "`universal_map.{nc,png}`: the critical angle of scenario A over (S, Γ0) and the angle of scenario B "
             f"above which the contact comes apart before sliding over (S, Γ1) at Γ0 = "
             f"{dataset.attrs['adhesion_in_of_B']:#.4g}, {dataset.sizes['slip']} × {dataset.sizes['adhesion_in']} "
             "values each, swept with `mdr_events.sweep`.", "",
             "| set | S | Γ0 | Γ1 | α_c, scenario A | angle, scenario B |", "|---|---:|---:|---:|---:|---:|"]
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        groups = dimensionless_groups(params)
        lines.append(f"| paper, {label} | {groups.slip:#.4g} | {groups.adhesion_in:#.4g} | {groups.adhesion_out:#.4g} | "
                     f"{critical_angle(params, 'A'):.2f}° | {critical_angle(params, 'B'):.2f}° |")
    return lines + [""]


def profiles_section(rows: list[ProfileRow]) -> list[str]:
    """The comparison of indenters: the closed forms of each power law against the continuum, and the discrete
    model's gap (:func:`~mdr_events.app.report_data.profile_rows`)."""
    lines = [
        "## Other indenters: cone, paraboloid, quartic, flat punch",
        "",
        f"Scenario A at {PROFILE_ANGLE:g}° with the paper's material and adhesion for power laws `f = c rⁿ` that reach "
        "the paraboloid's (R = 30 mm) non-adhesive contact radius at d_max (`simulate(..., profile=PowerLaw(c, n))`), "
        "and the flat punch of that radius (`profile=FlatPunch(radius)`; "
        f"`{PROFILE_STEM}_<name>.nc`, `{PROFILE_STEM}_<name>_discrete.nc`, `{PROFILE_STEM}.png`). The closed forms are "
        "Heß's rule for the power law (`mdr_events.power_law`): the pull-off force under force control, which the "
        "least normal force of the displacement-controlled run equals, and the slip onset (18) while indenting; for "
        "the punch Kendall's pull-off force `−sqrt(8π a³ E* Δγ1)` and the onset `d = tan α K a` (full slip at once). "
        f"Discrete: Δx = {FIGURE_DX * 1e6:g} µm, {FIGURE_STEPS} steps; its largest gap to the continuum in F_x over the "
        "largest F_x.",
        "",
        "| indenter | c | n | pull-off force, closed form | continuum F_N,min | slip onset (18) | continuum onset | "
        "F_x,max | discrete gap |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        onset = "none before d_max" if math.isnan(row.onset_closed_form) else f"{row.onset_closed_form * 1e3:.6f} mm"
        found = "none" if math.isnan(row.onset_continuum) else f"{row.onset_continuum * 1e3:.6f} mm"
        if isinstance(row.profile, FlatPunch):
            shape = f"radius {row.profile.radius * 1e3:g} mm | —"
        else:
            shape = f"{row.profile.c:#.6g} | {row.profile.n:g}"
        lines.append(f"| {row.name.replace('_', ' ')} | {shape} | {row.pull_off_closed_form:#.9g} N | "
                     f"{row.pull_off_continuum:#.9g} N | {onset} | {found} | {row.tangential_force_max:#.6g} N | "
                     f"{_gap_text(row.discrete_difference)} |")
    return lines + [""]


def _gap_text(value: float) -> str:
    """A discrete model's gap to the continuum's F_x as the tables print it: three digits, or ``< 1e-10`` below the
    accuracy of the continuum's F_x (the punch's springs are the continuum: their digits there differ between
    machines)."""
    return f"< {INTEGRATED_ACCURACY:g}" if abs(value) < INTEGRATED_ACCURACY else f"{value:.2e}"


def mindlin_section(rows: list[MindlinRow]) -> list[str]:
    """The Cattaneo–Mindlin check: each method's largest difference from the closed form
    (:func:`~mdr_events.app.report_data.mindlin_rows`)."""
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
        "| method | max \\|F_x − closed form\\| / (μ F_N) |",
        "|---|---|",
    ]
    for row in rows:
        # the continuum's differences are its solver's (rtol 1e-10): their digits differ between machines
        shown = f"< {MINDLIN_REPORTED_BOUND:g}" if row.max_difference < MINDLIN_REPORTED_BOUND else \
            relative_difference_text(row.max_difference)
        lines.append(f"| {row.method} | {shown} |")
    return lines + [""]


def _parameter_section() -> list[str]:
    params = Parameters.paper()
    lines = [
        "",
        "## Parameters (R = 30 mm; the R = 100 mm set differs only in R)",
        "",
        "| parameter | value | unit | source |",
        "|---|---|---|---|",
    ]
    for name, value in params.as_dict().items():
        source = "**inferred** (not stated in section 4)" if name in Parameters.INFERRED_FIELDS else "section 4"
        lines.append(f"| {name} ({PARAMETER_LONG_NAMES[name]}) | {value:.6g} | {PARAMETER_UNITS[name]} | {source} |")
    lines += [
        f"| E* | {params.E_star:.6g} | Pa | derived |",
        f"| G* | {params.G_star:.6g} | Pa | derived |",
        "",
        "## Files",
        "",
        "- `phase_diagram_A_R30.{nc,png}`, `phase_diagram_A_R100.{nc,png}`: Fig. 9a.",
        "- `phase_diagram_B_R30.{nc,png}`, `phase_diagram_B_R100.{nc,png}`: Fig. 9b.",
        "- `fig8_R30.{nc,png}`, `fig8_R100.{nc,png}`: Fig. 8 (scenario A), continuum method, with its event",
        "  log in `fig8_R*_events.csv` and the discrete overlay in `fig8_R*_discrete.nc`.",
        "- `fig10_R30.{nc,png}`, `fig10_R100.{nc,png}`: Fig. 10 (scenario B), likewise.",
        f"- `{FRETTING_STEM}.{{nc,png}}`: the fretting study (F_x against x), continuum method, with its event log",
        f"  in `{FRETTING_STEM}_events.csv` and the discrete model in `{FRETTING_STEM}_discrete.nc`.",
        f"- `{FIT_STEM}.{{nc,png}}`: the fit demonstration (estimates, intervals, correlations, residuals), its",
        f"  synthetic measurement in `{FIT_STEM}_measured.nc`.",
        f"- `{UNIVERSAL_STEM}.{{nc,png}}`: the critical angles over the dimensionless groups, the paper's sets marked.",
        f"- `{PROFILE_STEM}.png`, `{PROFILE_STEM}_<cone|paraboloid|quartic|flat_punch>.nc` (continuum) and "
        "`..._discrete.nc`:",
        "  other indenters in scenario A.",
        f"- `{MINDLIN_STEM}.png`, `{MINDLIN_STEM}.nc` (continuum) and `{MINDLIN_STEM}_discrete.nc`: Coulomb's law at a",
        "  constant depth against Cattaneo–Mindlin.",
        "",
    ]
    return lines


def software_versions() -> dict[str, str]:
    """Python's version and those of :data:`RECORDED_PACKAGES`, as installed now."""
    versions = {"Python": platform.python_version()}
    versions.update({name: importlib.metadata.version(name) for name in RECORDED_PACKAGES})
    return versions


_COMPUTED_WITH = "Computed with "


def _software_section(versions: dict[str, str]) -> list[str]:
    return [
        "## Software",
        "",
        _COMPUTED_WITH + ", ".join(f"{name} {version}" for name, version in versions.items()) + ".",
        "",
        "`make` installs these versions from the lock file `constraints.txt`. With other versions (or",
        "another CPU) each quantity of the datasets agrees within the accuracy of how it is computed",
        "(`mdr_events.io.agreement`: round-off for closed forms and sums, the integrator's rtol for F_x,",
        "the curvature at an extremum for its time, the optimizer's stopping tolerance for the fit), and",
        "each number of this report within one unit of its last digit, which is coarser than that accuracy;",
        "`mdr-events reproduce` then keeps the files as they are.",
        "",
    ]


def recorded_versions(text: str) -> dict[str, str]:
    """The versions a report's software section records (``{}`` if it has none)."""
    match = re.search(f"^{_COMPUTED_WITH}(.*)\\.$", text, flags=re.MULTILINE)
    if match is None:
        return {}
    return dict(item.rsplit(" ", 1) for item in match.group(1).split(", "))


def report_text(data: Reproduction | None = None, versions: dict[str, str] | None = None) -> str:
    """The text of ``results/README.md`` (everything computed afresh unless ``data`` is given).

    ``versions``: the software versions to record (default :func:`software_versions`).
    """
    data = compute() if data is None else data
    lines = [
        "# Reproduction of section 4 of Lyashenko, Popov & Borysiuk (2023)",
        "",
        f"Written by `mdr-events reproduce` (mdr_events {__version__}); do not edit by hand.",
        f"Paper: doi:{DOI}.",
        "",
    ]
    lines += _critical_angle_section(critical_angles_A(), critical_angles_B())
    lines += _cross_check_section(cross_check_rows(data))
    lines += _differences_section(differences(data))
    lines += _convergence_section(extremum_convergence(data), history_convergence(data))
    if data.fretting is not None:
        lines += fretting_section(data.fretting)
    if data.fitting is not None:
        lines += fit_section(data.fitting)
    if data.universal is not None:
        lines += universal_section(data.universal)
    if data.profiles is not None:
        lines += profiles_section(profile_rows(data.profiles, Parameters.paper()))
    if data.mindlin is not None:
        lines += mindlin_section(mindlin_rows(data.mindlin))
    lines += _parameter_section()
    lines += _software_section(software_versions() if versions is None else versions)
    return "\n".join(lines)


def reproduce(out: Path, progress: Callable[[str], None] = print, keep_agreeing: bool = True) -> list[FileOutcome]:
    """Write every figure, dataset and the report into ``out``; ``progress`` hears each step.

    With ``keep_agreeing`` (the default) a file that agrees with the fresh computation is not
    rewritten (:mod:`mdr_events.app.result_files`), and the report keeps the software versions it records when
    every other file was kept and its numbers are unchanged, so that ``git status`` stays clean on a
    machine whose rounding differs.
    """
    out = Path(out)
    outcomes: list[FileOutcome] = []
    total = len(jobs()) + COMPUTE_STEPS + WRITE_STEPS
    count = iter(range(1, total + 1))

    def step(message: str) -> None:
        progress(f"[{next(count)}/{total}] {message}")

    def done(new: list[FileOutcome]) -> None:
        outcomes.extend(new)
        progress(f"    {describe_outcomes(new)}")

    for label, radius, scenario in jobs():
        figure = "9a" if scenario == "A" else "9b"
        step(f"Fig. {figure}, R = {radius * 1e3:g} mm (phase diagram)")
        done(write_phase_diagram(Parameters.paper(R=radius), scenario, out, f"phase_diagram_{scenario}_{label}",
                                 keep_agreeing=keep_agreeing))
    data = compute(step)
    step("writing Fig. 8 and 10 (.nc, .png, events .csv)")
    for (label, scenario), dataset in data.continuum.items():
        stem = f"fig{FIGURE_NUMBERS[scenario]}_{label}"
        overlay, outcome = write_dataset(data.discrete[(label, scenario)], out / f"{stem}_discrete.nc", keep_agreeing)
        done([outcome] + write_simulation(dataset, out, stem, overlay=overlay, keep_agreeing=keep_agreeing))
    step("writing the fretting study (.nc, .png, events .csv), the fit, the universal map, the other indenters "
         "and README.md")
    overlay, outcome = write_dataset(data.fretting.discrete, out / f"{FRETTING_STEM}_discrete.nc", keep_agreeing)
    done([outcome] + write_simulation(data.fretting.continuum, out, FRETTING_STEM, overlay=overlay,
                                      keep_agreeing=keep_agreeing, plot=plot_fretting))
    measured = write_dataset(data.fitting.measured, out / f"{FIT_STEM}_measured.nc", keep_agreeing)[1]
    fitted, outcome = write_dataset(data.fitting.result.dataset, out / f"{FIT_STEM}.nc", keep_agreeing)
    done([measured, outcome, write_figure(plot_fit(fitted), out / f"{FIT_STEM}.png", keep_agreeing)])
    mapped, outcome = write_dataset(data.universal, out / f"{UNIVERSAL_STEM}.nc", keep_agreeing)
    done([outcome, write_figure(plot_universal_map(mapped), out / f"{UNIVERSAL_STEM}.png", keep_agreeing)])
    written, kept = {}, {}
    profile_outcomes = []
    for name in data.profiles.profiles:
        written[name], outcome = write_dataset(data.profiles.continuum[name], out / f"{PROFILE_STEM}_{name}.nc",
                                               keep_agreeing)
        kept[name], discrete_outcome = write_dataset(data.profiles.discrete[name],
                                                     out / f"{PROFILE_STEM}_{name}_discrete.nc", keep_agreeing)
        profile_outcomes += [outcome, discrete_outcome]
    figure = plot_profile_comparison(written, kept)
    done(profile_outcomes + [write_figure(figure, out / f"{PROFILE_STEM}.png", keep_agreeing)])
    exact, outcome = write_dataset(data.mindlin.continuum, out / f"{MINDLIN_STEM}.nc", keep_agreeing)
    springs, discrete_outcome = write_dataset(data.mindlin.discrete, out / f"{MINDLIN_STEM}_discrete.nc", keep_agreeing)
    done([outcome, discrete_outcome, write_figure(plot_mindlin_check(exact, springs), out / f"{MINDLIN_STEM}.png",
                                                  keep_agreeing)])
    text = report_text(data)
    readme = out / "README.md"
    if keep_agreeing and readme.exists() and all(o.status is FileStatus.KEPT for o in outcomes):
        existing = readme.read_text()
        recorded = recorded_versions(existing)
        if recorded and not rounded_text_differences(report_text(data, versions=recorded), existing):
            text = existing  # the files on disk were written with the versions it records
    done([write_text(text, readme, keep_agreeing, rounded=True)])
    return outcomes
