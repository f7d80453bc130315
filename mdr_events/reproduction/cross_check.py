"""Slip onset three ways: the closed form, the continuum and the discrete model side by side
(:func:`mdr_events.analysis.crosscheck.cross_check`), for every radius and scenario at the figures' angles."""

from __future__ import annotations

import enum
import math
from functools import partial
from typing import NamedTuple

import xarray as xr

from mdr_events.analysis.crosscheck import CROSS_CHECK_CONTENT, cross_check
from mdr_events.contact import Contact
from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import FIGURE_ANGLES, FIGURE_DX, FIGURE_STEPS, jobs
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step

__all__ = ["CROSS_CHECK", "SlipOnsetVerdict", "CrossCheckRow", "cross_check_rows"]


class SlipOnsetVerdict(enum.Enum):
    """How the slip onsets of a cross-check row compare (the first that applies)."""

    NO_SLIP_IN_INDENTATION = "the closed form lies beyond d_max (scenario A)"
    JUMP_OFF_FIRST = "the contact jumps off before any slip (scenario B)"
    FOUND_ONCE_AT_PHASE_END = "only one method slips, within tolerance of the end of the phase"
    PINNED = "the radius is pinned when the springs slide: (21) does not apply"
    DISAGREE = "a difference exceeds its tolerance"
    AGREE = "agree"


class CrossCheckRow(NamedTuple):
    """Slip-onset depths (m) of one angle of a cross-check (:func:`mdr_events.cross_check`)."""

    radius: float
    scenario: str
    alpha: float
    closed_form: float
    continuum: float
    discrete: float
    discrete_minus_continuum: float
    tolerance: float
    verdict: SlipOnsetVerdict


def _slip_onset_verdict(row: xr.Dataset, scenario: str, params: Parameters) -> SlipOnsetVerdict:
    closed = float(row["d_crit_closed_form"])
    if scenario == "A" and closed > params.d_max:
        return SlipOnsetVerdict.NO_SLIP_IN_INDENTATION
    if scenario == "B" and closed == -math.inf:
        return SlipOnsetVerdict.JUMP_OFF_FIRST
    if int(row["found_once_at_phase_end"]):
        return SlipOnsetVerdict.FOUND_ONCE_AT_PHASE_END
    if int(row["pinned_radius"]):
        return SlipOnsetVerdict.PINNED
    if int(row["disagree"]):
        return SlipOnsetVerdict.DISAGREE
    return SlipOnsetVerdict.AGREE


def cross_check_rows(cross_checks: dict[tuple[str, str], xr.Dataset]) -> list[CrossCheckRow]:
    """One row per angle of every cross-check (by (radius label, scenario)), in the order computed."""
    rows = []
    for (label, scenario), ds in cross_checks.items():
        params = Parameters.from_attrs(ds.attrs)
        for alpha in ds["alpha"].values:
            row = ds.sel(alpha=alpha)
            rows.append(CrossCheckRow(
                params.R, scenario, alpha, float(row["d_crit_closed_form"]), float(row["d_crit_continuum"]),
                float(row["d_crit_discrete"]), float(row["discrete_minus_continuum"]),
                float(row["discrete_tolerance"]), _slip_onset_verdict(row, scenario, params)))
    return rows


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


def _millimetres(value: float) -> str:
    return "—" if not math.isfinite(value) else f"{value * 1e3:.5f}"


def _cross_check_cells(row: CrossCheckRow) -> list[str]:
    return [f"{row.radius * 1e3:g} mm", row.scenario, f"{row.alpha:g}°", _millimetres(row.closed_form),
            _millimetres(row.continuum), _millimetres(row.discrete),
            f"{row.discrete_minus_continuum * 1e6:+.3f} µm".replace("+nan µm", "—"), f"{row.tolerance * 1e6:.3f} µm",
            _verdict_text(row.verdict, row.scenario)]


def cross_check_lines(cross_checks: dict[tuple[str, str], xr.Dataset]) -> list[str]:
    """The section's text: the slip-onset depths of every angle, with the discrete model's tolerance."""
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
    ]
    return lines + markdown_table(
        ["R", "scenario", "α", "closed form", "continuum", "discrete", "discrete − continuum", "tolerance", "note"],
        [_cross_check_cells(row) for row in cross_check_rows(cross_checks)])


def _compute(radius: float, scenario: str) -> xr.Dataset:
    return cross_check(Contact.paper(R=radius), scenario, FIGURE_ANGLES, dx=FIGURE_DX, n_steps=FIGURE_STEPS)


CROSS_CHECK = Section(
    name="cross_check",
    steps=tuple(Step(f"{CROSS_CHECK_CONTENT}, scenario {scenario}, R = {radius * 1e3:g} mm "
                     f"(closed form, continuum, discrete at {len(FIGURE_ANGLES)} angles)",
                     partial(_compute, radius, scenario)) for _, radius, scenario in jobs()),
    collect=lambda datasets: {(label, scenario): ds for (label, _, scenario), ds in zip(jobs(), datasets)},
    render=cross_check_lines,
)
