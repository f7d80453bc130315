"""Each spring's own clamp times where ``ū(a(t))`` is not concave (:mod:`.play_springs`): golden sections of its
window's edges, ``ū(a(t))`` of each such stretch read from a cubic spline of it (:func:`convex_tables`) instead of an
inversion of the radius every step.
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import CubicSpline

__all__ = ["GOLDEN_STEPS", "GOLDEN_TABLE_RTOL", "GOLDEN_TABLE_POINTS", "convex_tables"]

#: Steps of a golden section (0.618^45 ≈ 4e-10 of the interval): below where a smooth maximum is located at all (its
#: values within round-off ``ε`` over ``√ε ≈ 1.5e-8`` of the interval, where the steps' comparisons are round-off's),
#: the clamp's value off by ``L''δt²/2``, about ``ε`` of it (80 steps, to 2e-17, took twice the evaluations for no
#: change; each an inversion of the radius on a layer).
GOLDEN_STEPS = 45
#: ``ū(a(t))`` on a convex stretch is read in the golden sections from a cubic spline of it (one inversion of the
#: radius on a grid, not one each step): its error, measured at the grid's midpoints, is kept below this share of
#: the stretch's largest ``ū``. A section's maximum of an edge read within ``ε`` of it lies within ``2ε`` of the true
#: one, and the clamp's value is read exactly at the time found (:meth:`PlaySprings._own_shifts`): the clamp is off by
#: at most ``2ε`` (2e-13 of ``ū``, beside the golden section's own ``ε`` of round-off).
GOLDEN_TABLE_RTOL = 1e-13
#: Grid sizes tried for a stretch's spline, doubling (the error falls as the spacing's fourth power, 16× a doubling:
#: a cone on a layer's stretch needed 513 points, 2e-14); beyond the last the stretch is read exactly each step.
GOLDEN_TABLE_POINTS = (65, 129, 257, 513, 1025, 2049, 4097)


def convex_tables(exact_shift, convex: np.ndarray) -> list:
    """``ū(a(t))`` on each interval of ``convex`` (twice: both edges' sections), a cubic spline of it within
    :data:`GOLDEN_TABLE_RTOL`, or the exact reading where no grid of :data:`GOLDEN_TABLE_POINTS` reaches it.

    Parameters
    ----------
    exact_shift : callable
        ``ū(a(t))`` at an array of times (the radius inverted).
    convex : numpy.ndarray
        The intervals ``(start, end)`` (s, path clock) where ``ū(a(t))`` is not concave.

    Returns
    -------
    list
        A callable of the times per interval and edge (a spline, or ``exact_shift``).
    """
    tables = []
    for lo, hi in convex:
        table = exact_shift
        for points in GOLDEN_TABLE_POINTS:
            grid = np.linspace(lo, hi, points)
            values = exact_shift(grid)
            spline = CubicSpline(grid, values)
            middle = 0.5 * (grid[1:] + grid[:-1])
            error = np.max(np.abs(spline(middle) - exact_shift(middle)))
            if error <= GOLDEN_TABLE_RTOL * max(float(np.max(np.abs(values))), 1e-300):
                table = spline
                break
        tables += [table, table]
    return tables


def _golden(function, low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """The argmax of ``function`` (vectorised, one variable per row) on each ``[low, high]`` by golden sections
    (``nan`` where the interval is empty): :data:`GOLDEN_STEPS` steps, each one evaluation of ``function`` for every
    row (the inner point kept is the one evaluated before, its value reused: the interval's golden ratio makes it the
    next step's other inner point; the route before it evaluated both anew each step, twice the evaluations: kept
    in tests/models/test_play_golden.py)."""
    ratio = 0.5 * (np.sqrt(5.0) - 1.0)
    empty = ~(high > low)
    a, b = np.where(empty, 0.0, low), np.where(empty, 1.0, high)
    c, e = b - ratio * (b - a), a + ratio * (b - a)
    fc, fe = function(c), function(e)
    for _ in range(GOLDEN_STEPS):
        left = fc > fe  # (the maximum in [a, e]: e becomes b, c becomes e; else in [c, b]: c becomes a, e becomes c)
        a, b = np.where(left, a, c), np.where(left, e, b)
        kept, kept_value = np.where(left, c, e), np.where(left, fc, fe)
        new = np.where(left, b - ratio * (b - a), a + ratio * (b - a))
        value = function(new)
        c, fc = np.where(left, new, kept), np.where(left, value, kept_value)
        e, fe = np.where(left, kept, new), np.where(left, kept_value, value)
    return np.where(empty, np.nan, 0.5 * (a + b))
