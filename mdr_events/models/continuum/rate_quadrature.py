"""``∫ σẋ a dτ`` over an advancing piece of the rate-dependent edge, by Gauss–Legendre on the solver's steps.

The records' integral by parts (:mod:`~mdr_events.models.continuum.rate_shifts`): :data:`GAUSS_NODES` nodes per knot
interval, exact for the steps' dense polynomials; the knots' cumulative sums computed once per record.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .rate_levels import _knots
from .rate_records import _View

if TYPE_CHECKING:
    from .rate_shifts import RateShifts

__all__ = ["GAUSS_NODES", "gauss_radius"]


#: Gauss–Legendre nodes per solver step for ``∫ Ẋ a dτ``: exact to degree 15, beyond the dense output's polynomials
#: (Radau's 3, BDF's 5, LSODA's up to 12).
GAUSS_NODES = 8

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(GAUSS_NODES)


def _swept(shifts: RateShifts, solution, start: float, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """``∫_lo^hi σẋ a dτ`` (m²) within the advancing piece of ``solution`` from ``start`` (elementwise;
    ``lo <= hi``), Gauss–Legendre on each knot interval; the knots' cumulative sums computed once per record."""
    key = (id(solution), start)
    if key not in shifts._sweeps:
        end = float(np.asarray(solution.ts)[-1])
        knots = _knots(_View(start, end, solution, 1, (), None), shifts._corners[0])
        slope = np.diff(shifts._x(knots)) / np.where(np.diff(knots) > 0.0, np.diff(knots), 1.0)
        whole = _partial(solution, knots, slope, knots[1:], np.arange(len(knots) - 1))
        shifts._sweeps[key] = (knots, slope, np.concatenate([[0.0], np.cumsum(whole)]))
    knots, slope, cumulative = shifts._sweeps[key]

    def primitive(ends: np.ndarray) -> np.ndarray:
        index = np.minimum(np.maximum(np.searchsorted(knots, ends, side="right") - 1, 0), len(knots) - 2)
        return cumulative[index] + _partial(solution, knots, slope, ends, index)
    return primitive(hi) - primitive(lo)


def _partial(solution, knots: np.ndarray, slope: np.ndarray, ends: np.ndarray, index: np.ndarray) -> np.ndarray:
    """``∫ σẋ a dτ`` from ``knots[index]`` to ``ends`` (each within its knot interval), Gauss–Legendre; 0 where an end
    is its knot (the rule's half-width 0: no nodes evaluated there)."""
    start = knots[index]
    out = np.zeros(ends.shape)
    moved = np.flatnonzero(ends != start)
    if moved.size:
        half, weighted = gauss_radius(lambda t: solution(t)[0], start[moved], ends[moved])
        out[moved] = slope[index[moved]] * half * weighted
    return out


def gauss_radius(radius, start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The half-widths and the weighted sums of :data:`GAUSS_NODES` Gauss–Legendre nodes of ``radius`` on each
    ``[start, end]`` (their product is ``∫ a dτ``, exact for a step's polynomial).

    Parameters
    ----------
    radius : callable
        The radius (m) at an array of times.
    start, end : numpy.ndarray
        The intervals (s).

    Returns
    -------
    tuple of numpy.ndarray
        The half-widths (s) and the weighted sums (m).
    """
    half = 0.5 * (end - start)
    nodes = start[:, None] + half[:, None] * (1.0 + _NODES[None, :])
    return half, radius(nodes.ravel()).reshape(nodes.shape) @ _WEIGHTS
