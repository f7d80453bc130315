"""The springs' force summed over the windows held (:class:`~mdr_events.models.continuum.rate_play.RatePlay`).

Every anchor ``clamp(X, l, u)``: the springs of the jump-in's first instant, the intervals ``X`` does not cross inside
summed as products of masks, and those it crosses cut where the linear ``X`` meets its held window (each part a
constant anchor or ``X``), by the same record force as :class:`~mdr_events.models.continuum.rate_shifts.RateShifts`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .rate_play_windows import _Rows
from .rate_shifts import _relation, gauss_radius

if TYPE_CHECKING:
    from .rate_play import RatePlay


def _block(play: RatePlay, view, rows: _Rows, held: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """The springs of the jump-in's first instant (one anchor, clamped by the window held on the first interval)."""
    block = view.block
    kept = np.minimum(block.radius, rows.radius)
    anchor = np.minimum(np.maximum(block.anchor, held[0]), held[1])
    force = _relation().numeric(rows.x, anchor, 0.0, kept, kept, 0.0, 0.0, 0.0, play.G_star)
    at_lower = anchor == rows.lower
    return np.stack([force + np.zeros(kept.shape), np.where(at_lower, kept, 0.0),
                     np.where((anchor == rows.upper) & ~at_lower, kept, 0.0)])


def _intervals(play: RatePlay, rows: _Rows, columns: np.ndarray, owner: np.ndarray, his: np.ndarray,
               held_l: np.ndarray, held_u: np.ndarray) -> np.ndarray:
    """The springs attached on each interval between candidates, at each row: summed whole where the interval ends at
    the next candidate and ``X`` does not cross its window inside, else cut (:func:`_cut_parts`)."""
    grid = play._grid
    following = np.minimum(columns + 1, grid.times.size - 1)
    inside = (columns <= rows.last[:, None]) & (columns >= rows.first[:, None]) & (owner >= 0)
    start = grid.times[columns][None, :]
    end = np.where(columns < rows.last[:, None], grid.times[following], rows.times[:, None])
    end = np.minimum(end, his[np.maximum(owner, 0), :].T if his.size else end)
    kept = inside & (end > start)
    whole = kept & (columns < rows.last[:, None]) & (end == grid.times[following])
    x0, x1 = grid.x[columns], grid.x[following]
    rise = x1 - x0
    span = (grid.times[following] - grid.times[columns])
    with np.errstate(divide="ignore", invalid="ignore"):
        crosses = [_interior(np.where(rise != 0.0, start + (level - x0) / rise * span, start), start, end)
                   for level in (held_l, held_u)]
    whole &= ~(crosses[0] | crosses[1])
    total = _whole_intervals(play, rows, columns, following, whole, held_l, held_u)
    cut = np.nonzero(kept & ~whole)
    if cut[0].size:
        total += _cut_parts(play, rows, cut, columns[cut[1]], end[cut], held_l[cut], held_u[cut])
    return total


def _interior(cross: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Where a crossing lies strictly inside its interval once clipped to it."""
    clipped = np.minimum(np.maximum(cross, start), end)
    return (clipped > start) & (clipped < end)


def _whole_intervals(play: RatePlay, rows: _Rows, columns: np.ndarray, following: np.ndarray, whole: np.ndarray,
                     held_l: np.ndarray, held_u: np.ndarray) -> np.ndarray:
    """The record force (``rate_springs_record_force``) of the whole intervals, summed per row as products of their
    masks with each interval's measure and ``X a|τ_k^τ_k+1 − ∫ Ẋ a dτ`` (its sticking springs' share)."""
    grid = play._grid
    measure = grid.radius[following] - grid.radius[columns]
    held = (grid.x[following] * grid.radius[following] - grid.x[columns] * grid.radius[columns]
            - (grid.primitive[following] - grid.primitive[columns]))
    middle = play._x(0.5 * (grid.times[columns] + grid.times[following]))
    constant = whole & ((middle < held_l) | (middle > held_u) | (held_l == held_u))
    anchor = np.where(middle < held_l, held_l, held_u)
    sticking = whole & ~constant
    level = np.where(constant, anchor, 0.0) @ measure
    swept = whole.astype(float) @ measure
    force = 2.0 * play.G_star * (rows.x * swept - level - sticking.astype(float) @ held)
    at_lower = constant & (anchor == rows.lower[:, None])
    at_upper = constant & (anchor == rows.upper[:, None]) & ~at_lower
    return np.stack([force, at_lower.astype(float) @ measure, at_upper.astype(float) @ measure])


def _cut_parts(play: RatePlay, rows: _Rows, cut: tuple, columns: np.ndarray, end: np.ndarray, c_l: np.ndarray,
               c_u: np.ndarray) -> np.ndarray:
    """The springs attached on intervals ``[τ_k, end]`` that ``X`` crosses the window inside, or that end before the
    next candidate: each cut where the linear ``X`` meets its held window, each part a constant anchor or ``X``."""
    grid = play._grid
    owner, start = cut[0], grid.times[columns]
    x0, x1 = play._x(start), play._x(end)
    rise = x1 - x0
    with np.errstate(divide="ignore", invalid="ignore"):
        cross_l = np.where(rise != 0.0, start + (c_l - x0) / rise * (end - start), start)
        cross_u = np.where(rise != 0.0, start + (c_u - x0) / rise * (end - start), start)
    inner = np.sort(np.stack([np.clip(cross_l, start, end), np.clip(cross_u, start, end)]), axis=0)
    cuts = np.stack([start, inner[0], inner[1], end])  # (4, n): three parts each
    lows, highs = cuts[:-1].ravel(), cuts[1:].ravel()
    keep = highs > lows  # (a part of no length carries no force)
    lows, highs, owner = lows[keep], highs[keep], np.tile(owner, 3)[keep]
    c_l3, c_u3 = np.tile(c_l, 3)[keep], np.tile(c_u, 3)[keep]
    middle = play._x(0.5 * (lows + highs))
    constant = (middle < c_l3) | (middle > c_u3) | (c_l3 == c_u3)
    anchor = np.where(middle < c_l3, c_l3, c_u3)
    a_low, a_high = _radius_at(play, lows), _radius_at(play, highs)
    swept = _primitive_at(play, highs) - _primitive_at(play, lows)
    force = _relation().numeric(rows.x[owner], np.where(constant, anchor, 0.0), a_low,
                                np.where(constant, a_high, a_low), a_high, np.where(constant, 0.0, play._x(lows)),
                                np.where(constant, 0.0, play._x(highs)), np.where(constant, 0.0, swept), play.G_star)
    measure = a_high - a_low
    at_lower = constant & (anchor == rows.lower[owner])
    at_upper = constant & (anchor == rows.upper[owner]) & ~at_lower
    count = rows.times.size
    return np.stack([np.bincount(owner, weights=force, minlength=count),
                     np.bincount(owner, weights=np.where(at_lower, measure, 0.0), minlength=count),
                     np.bincount(owner, weights=np.where(at_upper, measure, 0.0), minlength=count)])


def _radius_at(play: RatePlay, times: np.ndarray) -> np.ndarray:
    """The radius (m) at ``times``: the candidates' own where a time is one, else the edge's polynomials."""
    grid = play._grid
    index = np.clip(np.searchsorted(grid.times, times), 0, len(grid.times) - 1)
    out = grid.radius[index].copy()
    other = grid.times[index] != times
    if np.any(other):
        out[other] = play._radius(times[other])
    return out


def _primitive_at(play: RatePlay, times: np.ndarray) -> np.ndarray:
    """``∫ ẋ a dτ`` (m²) from the first candidate to each of ``times``: the candidates' primitive, and Gauss–Legendre
    on the remainder of a time that is not one."""
    grid = play._grid
    index = np.clip(np.searchsorted(grid.times, times, side="right") - 1, 0, len(grid.times) - 1)
    out = grid.primitive[index].copy()
    rows = np.flatnonzero(grid.times[index] != times)
    if rows.size:
        index, times = index[rows], times[rows]
        start = grid.times[index]
        following = np.minimum(index + 1, len(grid.times) - 1)
        width = grid.times[following] - start
        slope = np.where(width > 0.0, (grid.x[following] - grid.x[index]) / np.where(width > 0.0, width, 1.0), 0.0)
        half, weighted = gauss_radius(play._radius, start, times)
        out[rows] += slope * half * weighted
    return out
