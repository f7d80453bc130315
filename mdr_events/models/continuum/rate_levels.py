"""The level ``L = σx − K a`` of the rate-dependent edge's springs: where its running maximum can change.

The times at which the running maximum ``M`` of ``L`` can change (every knot of the edge's pieces, the solver's steps
and the path's corners, and each step's interior maximum, probed then refined) and the first time ``σx`` reaches a
level, in closed form; read by :class:`~mdr_events.models.continuum.rate_shifts.RateShifts`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from scipy.optimize import minimize_scalar

from .rate_records import _View

if TYPE_CHECKING:
    from .rate_shifts import RateShifts

__all__ = ["STEP_PROBES"]


#: Points inside each solver step at which ``L = σx − K a`` is probed for an interior maximum (then refined).
STEP_PROBES = 5


def _reach(shifts: RateShifts, top: np.ndarray, level: np.ndarray) -> np.ndarray:
    """The first time ``σx`` reaches ``level`` (elementwise), at most ``top``: ``σx`` is linear between the path's
    corners and never falls, so the time is read off the corner where it first reaches the level, on the segment
    before it (the inverse of :meth:`RateShifts._x` in closed form)."""
    corners, along = shifts._corners
    after = np.minimum(np.searchsorted(along, level, side="left"), len(along) - 1)
    before = np.maximum(after - 1, 0)
    rise = along[after] - along[before]
    share = np.where(rise > 0.0, (level - along[before]) / np.where(rise > 0.0, rise, 1.0), 1.0)
    when = corners[before] + np.minimum(np.maximum(share, 0.0), 1.0) * (corners[after] - corners[before])
    return np.minimum(when, top)


def _knots(view: _View, corners: np.ndarray) -> np.ndarray:
    """The solver's steps of a piece and the path's corners within it."""
    steps = getattr(view.solution, "ts", np.array([view.t0, view.t1]))
    inner = corners[(corners > view.t0) & (corners < view.t1)]
    return np.unique(np.concatenate([[view.t0, view.t1], np.clip(steps, view.t0, view.t1), inner]))


def _level_candidates(shifts: RateShifts) -> tuple[np.ndarray, np.ndarray]:
    """Times and values of ``L`` at which its running maximum can change: every knot of every piece and each step's
    interior maximum (:func:`_peaks`)."""
    corners = shifts._corners[0]
    stamps = []
    for view in shifts.views:
        knots = _knots(view, corners)
        stamps += [knots, _peaks(shifts._level, knots)]
    every = np.sort(np.concatenate(stamps))
    return every, shifts._level(every)


def _peaks(function, knots: np.ndarray) -> np.ndarray:
    """The interior maxima of ``function`` (vectorised) in each interval of ``knots``: probed at :data:`STEP_PROBES`
    points, refined by bounded minimisation; each found by its refined time and its best probe."""
    width = np.diff(knots)
    share = np.arange(1, STEP_PROBES + 1) / (STEP_PROBES + 1)
    probes = knots[:-1, None] + width[:, None] * share[None, :]
    inner, ends = function(probes.ravel()).reshape(probes.shape), function(knots)
    found = []
    for step in np.flatnonzero(inner.max(axis=1) > np.maximum(ends[:-1], ends[1:])):
        best = minimize_scalar(lambda t: -float(function(np.array([t]))[0]), method="bounded",
                               bounds=(knots[step], knots[step + 1]),
                               options={"xatol": 4.0 * np.finfo(float).eps * abs(knots[step + 1])})
        found += [best.x, probes[step, int(np.argmax(inner[step]))]]
    return np.array(found)
