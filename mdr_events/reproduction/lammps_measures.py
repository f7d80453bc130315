"""What the section "LAMMPS granular models against the exact MDR" measures in each stored report: the norms, the
contact's end and pull-off, the events, and the quantities that explain each difference (LAMMPS's Coulomb cap, its
stiffness, the DMT offset, the energy of a fretting loop), read from the report alone."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.reproduction.lammps_cases import LAMMPS_DGAMMA, LAMMPS_MU, LAMMPS_RADIUS, LammpsCase, case_path

__all__ = ["CAP_RTOL", "CaseRow", "case_row", "lammps_pull_off", "critical_force", "at_cap", "stick_stiffness",
           "dmt_offsets", "loop_energy", "first_decrease_time", "rescale_difference"]

#: A sample is at LAMMPS's Coulomb cap where ``| |F_x| / (μ F_crit) - 1 | <= CAP_RTOL``: LAMMPS scales the force onto
#: the cap, which leaves it a few ε off; a sticking sample (below it) or a cap of another F_crit is that close only by
#: chance.
CAP_RTOL = 1e-9


def lammps_pull_off(normal: str) -> float:
    """LAMMPS's pull-off force ``F_pulloff`` (N) of the adhesive model (``3πγR`` for JKR, ``4πγR`` for DMT, with
    ``γ = Δγ/2``), 0 for Hertz."""
    gamma = LAMMPS_DGAMMA / 2.0
    return {"jkr": 3.0, "dmt": 4.0}.get(normal, 0.0) * math.pi * gamma * LAMMPS_RADIUS


def critical_force(normal: str, normal_force: np.ndarray, thornton: bool = True) -> np.ndarray:
    """LAMMPS's ``F_crit``: ``|F_N + 2 F_pulloff|`` (Thornton's heuristic; ``|F_N|`` for Hertz or ``thornton=False``)."""
    return np.abs(normal_force + (2.0 * lammps_pull_off(normal) if thornton else 0.0))


def _touching(report: xr.Dataset) -> np.ndarray:
    return report["lammps_contact"].values > 0


def at_cap(report: xr.Dataset, normal: str, thornton: bool = True) -> np.ndarray:
    """The samples in LAMMPS's contact whose tangential force is at the cap ``μ F_crit`` (:data:`CAP_RTOL`)."""
    cap = LAMMPS_MU * critical_force(normal, report["candidate_normal_force"].values, thornton)
    force = np.abs(report["candidate_tangential_force"].values)
    return _touching(report) & (cap > 0.0) & (np.abs(force - cap) <= CAP_RTOL * cap)


def stick_stiffness(report: xr.Dataset, normal: str) -> np.ndarray:
    """``ΔF_x / Δx`` (N/m) of LAMMPS between consecutive samples in contact below the cap where ``x`` moves (the
    sample spacing's ``Δx`` from the path)."""
    path, start = _path_and_start(report)
    x = path.position(start + report["time"].values)[0]
    force, capped = report["candidate_tangential_force"].values, at_cap(report, normal)
    below = _touching(report) & ~capped
    pairs = below[1:] & below[:-1] & (np.abs(np.diff(x)) > 0.0)
    return np.diff(force)[pairs] / np.diff(x)[pairs]


def dmt_offsets(report: xr.Dataset) -> np.ndarray:
    """``F_Hertz(δ) − F_N`` (N) of LAMMPS at each sample in contact with ``δ > 0``, ``F_Hertz = (4/3) E* R^½ δ^(3/2)``."""
    depth = report["lammps_depth"].values
    inside = _touching(report) & (depth > 0.0)
    hertz = 4.0 / 3.0 * float(report.attrs["param_E_star"]) * math.sqrt(LAMMPS_RADIUS) * depth[inside] ** 1.5
    return hertz - report["candidate_normal_force"].values[inside]


def _path_and_start(report: xr.Dataset):
    case = _case_of(report)
    path = case_path(case)
    return path, path.first_contact_time()


def _case_of(report: xr.Dataset) -> LammpsCase:
    return LammpsCase(str(report.attrs["lammps_normal_model"]), str(report.attrs["lammps_tangential_model"]),
                      str(report.attrs["lammps_path"]))


def loop_energy(report: xr.Dataset) -> tuple[float, float]:
    """``∫ F_x dx`` (J) of LAMMPS and of the exact continuum over the fretting path's closed loop (from its first
    turn at ``+X`` through ``−X`` back to ``+X``), the trapezoid rule on the same samples."""
    path, start = _path_and_start(report)
    corners = path.corner_times - start
    times = report["time"].values
    inside = (times >= corners[2]) & (times <= corners[4])
    x = path.position(start + times[inside])[0]
    return tuple(float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(x)))
                 for f in (report[f"{kind}_tangential_force"].values[inside] for kind in ("candidate", "exact")))


def rescale_difference(mindlin: xr.Dataset, rescale: xr.Dataset) -> tuple[float, float]:
    """The largest ``|F_x|`` difference (N) of ``mindlin_rescale`` from ``mindlin`` (same normal model and path)
    before the contact first shrinks (:func:`first_decrease_time`) and from then on."""
    times = mindlin["time"].values
    before = times < first_decrease_time(mindlin)
    difference = np.abs(rescale["candidate_tangential_force"].values - mindlin["candidate_tangential_force"].values)
    return float(np.max(difference[before], initial=0.0)), float(np.max(difference[~before], initial=0.0))


def first_decrease_time(report: xr.Dataset) -> float:
    """The report's time of the first sample whose LAMMPS depth is below the one before (the contact starts to
    shrink)."""
    depth = report["lammps_depth"].values
    falling = np.flatnonzero(np.diff(depth) < 0.0)
    return float(report["time"].values[falling[0] + 1]) if falling.size else math.nan


def _event(report: xr.Dataset, name: str, variable: str) -> float:
    return float(report[variable].sel(event=name))


class CaseRow(NamedTuple):
    """One case's row of the section's table, measured from its report."""

    case: LammpsCase
    normal_error: float  #: max ``|ΔF_N|`` / range
    tangential_error: float  #: max ``|ΔF_x|`` / range (nan without a tangential model)
    contact_differs: float  #: share of the exact contact's time in contact in one run only
    pull_off_lammps: float  #: least F_N of LAMMPS's samples (N)
    pull_off_exact: float  #: F_N at the exact pull-off (N)
    last_depth_lammps: float  #: depth of LAMMPS's last sample in contact (m)
    pull_off_depth_exact: float  #: depth of the exact pull-off (m)
    first_contact_error: float  #: event-time error, share of the path's duration
    pull_off_error: float
    verdict: str
    cap_share: float  #: share of LAMMPS's contact samples at its cap μ F_crit (nan without friction)
    first_at_cap: float  #: s from first contact
    slip_onset_exact: float
    full_slip_exact: float
    step: float  #: LAMMPS's time step (s)
    speed: float  #: the path's speed (m/s)


def case_row(report: xr.Dataset) -> CaseRow:
    """The measured row of one stored report (:func:`~mdr_events.reproduction.lammps_cases.run_case`)."""
    case = _case_of(report)
    errors = dict(zip((str(q) for q in report["quantity"].values), report["max_error"].values))
    touching = _touching(report)
    capped = at_cap(report, case.normal) if case.tangential != "none" else np.zeros_like(touching)
    times = report["time"].values
    return CaseRow(
        case, float(errors["normal_force"]),
        float(errors["tangential_force"]) if case.tangential != "none" else math.nan,
        float(report["contact_differs_share"]), float(np.min(report["candidate_normal_force"].values)),
        float(report["pull_off_force_exact"]), float(report["lammps_depth"].values[np.flatnonzero(touching)[-1]]),
        _event(report, "pull_off", "event_depth_exact"), _event(report, "first_contact", "event_time_relative_error"),
        _event(report, "pull_off", "event_time_relative_error"), str(report.attrs["verdict"]),
        float(np.count_nonzero(capped)) / float(np.count_nonzero(touching)) if case.tangential != "none" else math.nan,
        float(times[np.flatnonzero(capped)[0]]) if np.any(capped) else math.nan,
        _event(report, "slip_onset", "event_time_exact"), _event(report, "full_slip", "event_time_exact"),
        float(report.attrs["lammps_dt"]), float(report.attrs["path_speed"]))
