"""A continuum sweep's run under the rate-dependent adhesion law (issue 29): the quantities of
:data:`~mdr_events.analysis.sweep_runs.QUANTITIES` from the run ``simulate``'s continuum method makes of the law.

The run is :func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts` by the solver of ``simulate``
(:data:`~mdr_events.models.continuum.rate_run.RUN_METHOD` at the method's ``rtol``), its event log and extrema those of
:func:`~mdr_events.models.continuum.rate_run.rate_events` and :func:`~mdr_events.models.continuum.rate_run.rate_extrema`:
a sweep's run is the single run's, bit for bit. The quantities read off them as the paper's law's are read off its
solution (``sweep_runs.continuum_quantities``): the extrema, the first slip onset on the way in
and out, the first full slip, the contact's end (the law's pull-off: its depth and ``F_N`` there) and the events
logged, times from the path's start. The tangential work ``∫ F_x dx`` is Gauss–Legendre's rule of
:data:`~mdr_events.models.continuum.work.WORK_NODES` nodes on every step of the edge's solver, cut at the path's
corners and at the run's events (``F_x`` is smooth between them and ``x`` linear in time within a segment).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from mdr_events.analysis.sweep_events import event_quantities, first_events
from mdr_events.limits import Limits
from mdr_events.models.continuum.rate_coulomb import takes_rate_coulomb
from mdr_events.models.continuum.rate_run import (RUN_METHOD, evaluate_run, rate_events, rate_extrema, rate_quantities,
                                                  scan_run)
from mdr_events.models.continuum.rate_shifts import RateShifts, solve_rate_shifts
from mdr_events.models.continuum.work import WORK_NODES
from mdr_events.models.job import ModelJob
from mdr_events.models.paths import Path

if TYPE_CHECKING:
    from mdr_events.models.methods import Continuum

__all__ = ["rate_continuum_quantities", "rate_tangential_work", "check_rate_sweep_run", "HISTORY_NAMES"]

#: The history's quantities (rows), as :data:`~mdr_events.analysis.sweep_runs.HISTORY_QUANTITIES` names them.
HISTORY_NAMES = ("normal_force", "tangential_force", "contact_area")


def check_rate_sweep_run(model: ModelJob) -> None:
    """Refuse, before a sweep runs, what its continuum runs of the rate law do not take: Coulomb's part.

    :func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts` holds one cap for every spring (``τ0``'s);
    ``simulate``'s continuum method runs Coulomb's part spring by spring (``continuum.rate_coulomb``), whose cost
    (about 10 ms of CPU an output time) a sweep's quantities (its work read at Gauss nodes on every step) would
    multiply. Each cell refused so at run time before.

    Parameters
    ----------
    model : ModelJob
        A run's contact along its motion (its adhesion the rate-dependent law).

    Raises
    ------
    ValueError
        A friction law with Coulomb's part: one line naming it, the law and what runs it.
    """
    if takes_rate_coulomb(model.friction):
        raise ValueError(f"friction={model.friction!r} is not allowed in a continuum sweep with "
                         f"adhesion={model.adhesion!r} (Coulomb's part: each spring its own cap); allowed: "
                         "FrictionLaw('tau0') (Coulomb's part under this law: method='discrete' sweeps it, "
                         "simulate(..., method='continuum') runs it one run at a time)")


def rate_tangential_work(shifts: RateShifts, breaks: np.ndarray) -> float:
    """``W = ∫ F_x dx`` (J) of a rate run from its first contact to its end, by Gauss–Legendre's rule on the intervals
    between ``breaks`` (path clock; the module docstring says which), where ``x`` is linear in time.

    Parameters
    ----------
    shifts : RateShifts
        The run.
    breaks : numpy.ndarray
        The times (s, path clock) at which the rule is cut, beside the path's corners and the first contact: the scan's
        (:func:`~mdr_events.models.continuum.rate_run.scan_run`, whose last is the run's end) and the events'.

    Returns
    -------
    float
        The work (J).
    """
    path, start = shifts.path, shifts.path.first_contact_time()
    breaks = np.asarray(breaks, dtype=float)
    end = float(np.max(breaks))
    knots = np.concatenate([[start], breaks, path.corner_times])
    knots = np.unique(knots[(knots >= start) & (knots <= end)])
    if knots.size < 2:
        return 0.0
    nodes, weights = np.polynomial.legendre.leggauss(WORK_NODES)
    middle, half = (knots[1:] + knots[:-1]) / 2.0, np.diff(knots) / 2.0
    clock = (middle[:, None] + half[:, None] * nodes[None, :]).ravel()
    force = rate_quantities(shifts, clock - start)["tangential_force"].reshape(middle.size, WORK_NODES)
    travel = np.diff(path.position(knots)[0])
    return float(np.sum(travel / 2.0 * (force @ weights)))


def rate_continuum_quantities(model: ModelJob, path: Path, method: Continuum, limits: Limits,
                              times: np.ndarray | None) -> tuple[dict[str, float], np.ndarray | None]:
    """A run's quantities under the rate law (module docstring), and its history at ``times`` (path clock).

    Parameters
    ----------
    model : ModelJob
        The run's contact (its adhesion a :class:`~mdr_events.RateDependentAdhesion`) along its motion.
    path : Path
        The run's one path.
    method : Continuum
        The method, whose ``rtol`` the edge's ODE takes.
    limits : Limits
        What the run may use (its history's samples checked against it).
    times : numpy.ndarray or None
        The history's times (s from the path's start), or ``None`` for none.

    Returns
    -------
    tuple of dict and numpy.ndarray or None
        The quantities by name, and the history (rows ``normal_force``, ``tangential_force``, ``contact_area``).
    """
    if times is not None:
        limits.check(f"the run's history of {np.size(times)} samples", samples=np.size(times))
    shifts = solve_rate_shifts(model.params, path, model.adhesion, profile=model.profile, friction=model.friction,
                               rtol=method.tolerances.rtol, method=RUN_METHOD)
    start = path.first_contact_time()
    curves = None
    if times is None:
        scan = scan_run(shifts)
    else:  # (the history's F_x and the scan's in one pass over the run's pieces)
        curves, scan = evaluate_run(shifts, np.asarray(times, dtype=float) - start)
    events, extrema = rate_events(shifts, scan), rate_extrema(shifts, scan)
    out = {"normal_force_min": extrema["normal_force_min"],
           "tangential_force_max": max(abs(extrema["tangential_force_max"]), abs(extrema["tangential_force_min"])),
           "contact_area_max": extrema["contact_area_max"],
           "tangential_work": rate_tangential_work(shifts, np.concatenate([scan.times, [e.time + start for e in events]])),
           "event_count": float(len(events))}
    first = first_events(events, path, start)
    out.update(event_quantities(first, start))
    pull = first.get("pull_off")
    out["pull_off_force"] = float(shifts.normal_force(np.array([pull.time + start]))[0]) if pull else math.nan
    if curves is None:
        return out, None
    curves["contact_area"] = math.pi * curves["contact_radius"] ** 2
    before = np.asarray(times, dtype=float) < start  # (before the first contact: nothing touches)
    history = np.array([np.where(before, 0.0, curves[name]) for name in HISTORY_NAMES])
    return out, history
