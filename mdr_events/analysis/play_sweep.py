"""A continuum sweep's run of Coulomb's part on a layer of finite thickness (issue 34): the quantities of
:data:`~mdr_events.analysis.sweep_runs.QUANTITIES` from the run ``simulate``'s continuum method makes of it, spring by
spring (:func:`~mdr_events.models.continuum.play_run.run_play_springs`).

The spans' solution that the paper's law's quantities read (``sweep_runs.continuum_quantities``) does not run Coulomb's
part on a layer (each spring's cap ``μ k/k_t (d − g)`` has a ratio of its own, no level is shared); the per-spring
route gives the same quantities. Its run at the method's output times is ``simulate``'s, bit for bit: ``F_N``'s and
``A``'s exact extrema (the frictionless spans' normal run), ``F_x``'s among the samples and the path's corners refined
between them, the event log (the normal run's and the springs' slip onsets and full slips, bisected), so a sweep's
``normal_force_min``, ``tangential_force_max``, ``contact_area_max``, the first slip onsets in and out, the first full
slip, the pull-off and the events logged are those of ``simulate``'s dataset. The tangential work ``∫ F_x dx`` is
Gauss–Legendre's rule of :data:`~mdr_events.models.continuum.work.WORK_NODES` nodes between the path's corners,
the run's events and the path's crossings of the surface (``F_x`` is smooth between them: its kinks are the springs'
slip fronts reaching a cap, the reversals, the radius's jumps, each an event, and Coulomb's part turning off in
tension; ``x`` is linear in time within a segment), on :data:`WORK_PIECES` even pieces at least, each mapped by
``t = t₀ + L(3u² − 2u³)`` so that a square-root end (the radius at the pull-off's fold) is smooth in ``u``; the
route's ``F_x`` read at all the nodes at once. The history's ``F_x`` is the route's at the history's times.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from mdr_events.analysis.sweep_events import event_quantities, first_events
from mdr_events.contact.layer import LayerBase
from mdr_events.limits import Limits
from mdr_events.models.continuum.play_run import run_play_springs
from mdr_events.models.continuum.play_springs import PlaySprings, SpanHistory, spring_line
from mdr_events.models.continuum.work import WORK_NODES
from mdr_events.models.job import ModelJob
from mdr_events.models.paths import Path

if TYPE_CHECKING:
    from mdr_events.models.methods import Continuum

__all__ = ["play_continuum_quantities", "play_tangential_work", "HISTORY_NAMES", "WORK_PIECES"]

#: Even pieces of the run the work's rule is cut into besides the corners, events and surface crossings: ``F_x`` is
#: smooth between those but varies on the run's whole scale (the radius shrinking to the pull-off); with 16 the rule is
#: within 3e-11 of the half-space spans' exact work along scenario B at 20° on ``h = 1e9 m`` (8e-9 with the breaks
#: alone, 5e-11 with 8 pieces).
WORK_PIECES = 16
#: The history's quantities (rows), as :data:`~mdr_events.analysis.sweep_runs.HISTORY_QUANTITIES` names them.
HISTORY_NAMES = ("normal_force", "tangential_force", "contact_area")


def _springs(model: ModelJob, path: Path, solution) -> PlaySprings | None:
    """The route's springs along ``path`` as :func:`~mdr_events.models.continuum.play_run.run_play_springs` makes them
    (``None`` on a frictionless base: no tangential springs, ``F_x = 0``)."""
    if model.contact.layer.base is not LayerBase.BONDED:
        return None
    params = model.params
    adhesive = params.dgamma0 != 0.0 or params.dgamma1 != 0.0
    return PlaySprings(spring_line(params, model.profile, model.friction, model.contact.layer), path,
                       SpanHistory(solution) if adhesive else None)


def _forces(play: PlaySprings | None, clock: np.ndarray) -> np.ndarray:
    """``F_x`` (N) at the path-clock times ``clock`` (all in contact), all at once."""
    if play is None or clock.size == 0:
        return np.zeros(clock.shape)
    states = play.probed_states(clock, np.empty(0), np.empty(0, dtype=np.intp))[0]
    return np.array([state.force for state in states])


def play_tangential_work(play: PlaySprings | None, path: Path, end: float, breaks: np.ndarray) -> float:
    """``W = ∫ F_x dx`` (J) of a run from its first contact to ``end`` (s from first contact) by Gauss–Legendre's rule
    on the intervals between the path's corners and ``breaks`` (s from first contact: the run's events).

    Parameters
    ----------
    play : PlaySprings or None
        The route's springs (``None``: no tangential springs, 0 J).
    path : Path
        The run's path.
    end : float
        The run's end (s from first contact).
    breaks : numpy.ndarray
        Times (s from first contact) where ``F_x`` may have kinks.

    Returns
    -------
    float
        The work (J).
    """
    start = path.first_contact_time()
    knots = np.concatenate([np.linspace(0.0, end, WORK_PIECES + 1), np.asarray(breaks, dtype=float),
                            path.corner_times - start, _surface_times(path) - start])
    knots = np.unique(knots[(knots >= 0.0) & (knots <= end)])
    if play is None or knots.size < 2:
        return 0.0
    nodes, weights = np.polynomial.legendre.leggauss(WORK_NODES)
    u = (nodes + 1.0) / 2.0  # (on [0, 1]: t = t₀ + L s(u), s = 3u² − 2u³, ds/du = 6u(1 − u))
    share, slope = 3.0 * u**2 - 2.0 * u**3, 3.0 * u * (1.0 - u) * weights
    clock = (knots[:-1, None] + np.diff(knots)[:, None] * share[None, :]).ravel() + start
    force = _forces(play, clock).reshape(knots.size - 1, WORK_NODES)
    travel = np.diff(path.position(knots + start)[0])
    return float(np.sum(travel * (force @ slope)))


def _surface_times(path: Path) -> np.ndarray:
    """The times (s, path clock) at which the path crosses the surface, ``d = 0``, inside a segment: where the
    compressed zone vanishes or the whole flat face turns from compression to tension, Coulomb's part (off in tension)
    gives ``F_x`` a kink or a singular curvature (``(d − g)₊`` integrated over the springs)."""
    t, d = np.asarray(path.corner_times, dtype=float), np.asarray(path.waypoints[:, 1], dtype=float)
    crossing = np.flatnonzero(d[:-1] * d[1:] < 0.0)
    return t[crossing] + (t[crossing + 1] - t[crossing]) * d[crossing] / (d[crossing] - d[crossing + 1])


def play_continuum_quantities(model: ModelJob, path: Path, method: Continuum, limits: Limits,
                              times: np.ndarray | None) -> tuple[dict[str, float], np.ndarray | None]:
    """A run's quantities under Coulomb's part on a layer (module docstring), and its history at ``times``.

    Parameters
    ----------
    model, path, method, limits
        The run's contact (Coulomb's part of the friction law on a layer of finite thickness) along its motion, its one
        path, the :class:`~mdr_events.Continuum` method (its tolerances and output times: ``simulate``'s run) and what
        the run may use (its history's samples checked against it).
    times : numpy.ndarray or None
        The history's times (s from the path's start), or ``None`` for none.

    Returns
    -------
    tuple of dict and numpy.ndarray or None
        The quantities by name and the history (rows :data:`HISTORY_NAMES`).
    """
    if times is not None:
        limits.check(f"the run's history of {np.size(times)} samples", samples=np.size(times))
    raw = run_play_springs(model.kernel, [path], method.output_times(1, limits), method.tolerances, limits)
    solution, events, extrema = raw["solutions"][0], raw["events"][0], raw["extrema"][0]
    play = _springs(model, path, solution)
    start = path.first_contact_time()
    out = {"normal_force_min": extrema["normal_force_min"],
           "tangential_force_max": max(abs(extrema["tangential_force_max"]), abs(extrema["tangential_force_min"])),
           "contact_area_max": extrema["contact_area_max"],
           "tangential_work": play_tangential_work(play, path, solution.end_time,
                                                   np.array([event.time for event in events])),
           "event_count": float(len(events))}
    first = first_events(events, path, start)
    out.update(event_quantities(first, start))
    pull = first.get("pull_off")
    out["pull_off_force"] = float(solution.model.normal_force(pull.depth, pull.radius)) if pull else math.nan
    if times is None:
        return out, None
    return out, _history(play, solution, path, np.asarray(times, dtype=float))


def _history(play: PlaySprings | None, solution, path: Path, times: np.ndarray) -> np.ndarray:
    """``F_N``, ``F_x`` and ``A`` at ``times`` (s, path clock): the normal run's curves
    (:func:`~mdr_events.analysis.fit_data.curves_of`, as ``sweep_runs.continuum_quantities``' history), ``F_x`` the
    route's in contact."""
    from mdr_events.analysis.fit_data import curves_of

    curves = curves_of(solution, path, times, HISTORY_NAMES)
    force = curves.values["tangential_force"]
    force[curves.in_contact] = _forces(play, times[curves.in_contact])
    return np.array([curves.values[name] for name in HISTORY_NAMES])
