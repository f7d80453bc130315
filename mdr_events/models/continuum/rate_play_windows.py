"""The windows of both levels composed back from a time asked
(:class:`~mdr_events.models.continuum.rate_play.RatePlay`).

A row per time asked over the candidates that carry springs: where its window closed (the running maximum of
``x − K a`` and minimum of ``x + K a`` going back until they meet) by bisection on sparse tables of the levels'
extremes, and the windows held since each candidate, accumulated along the row.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from scipy.optimize import brentq

if TYPE_CHECKING:
    from .rate_play import RatePlay


class _Rows(NamedTuple):
    """Times within one piece of the edge (increasing) and, at each, the first and the last candidate column it sees
    (from the latest touch down to before it), the radius, ``x`` and the levels ``L``, ``U``."""

    times: np.ndarray
    first: np.ndarray
    last: np.ndarray
    radius: np.ndarray
    x: np.ndarray
    lower: np.ndarray
    upper: np.ndarray


def _rows(play: RatePlay, times: np.ndarray) -> _Rows:
    grid = play._grid
    touched = np.searchsorted(play._touches, times, side="right") - 1
    touch = np.where(touched >= 0, play._touches[np.maximum(touched, 0)] if play._touches.size else 0.0, -np.inf)
    radius, x = play._radius(times), play._x(times)
    return _Rows(times, np.searchsorted(grid.times, touch, side="left"),
                 np.searchsorted(grid.times, times, side="left") - 1, radius, x, x - play.cap * radius,
                 x + play.cap * radius)


class _Extremes:
    """The largest ``L`` and the least ``U`` over any run of candidates (sparse tables of both: exact, one look-up
    each); ``levels[n]`` is ``floor(log2(n))``."""

    def __init__(self, lower: np.ndarray, upper: np.ndarray):
        high, low = [lower], [upper]
        while 2 ** len(high) <= lower.size:
            width = 2 ** (len(high) - 1)
            high.append(np.maximum(high[-1][:-width], high[-1][width:]))
            low.append(np.minimum(low[-1][:-width], low[-1][width:]))
        self.high = np.full((len(high), lower.size), -np.inf)
        self.low = np.full((len(low), lower.size), np.inf)
        for level, (top, bottom) in enumerate(zip(high, low)):
            self.high[level, :top.size], self.low[level, :bottom.size] = top, bottom
        self.levels = np.frexp(np.arange(lower.size + 1, dtype=float))[1] - 1

    def window(self, start, stop, lower, upper) -> tuple[np.ndarray, np.ndarray]:
        """The largest ``L`` and the least ``U`` over the candidates ``start..stop`` (elementwise, inclusive; none
        where ``start > stop``) and ``lower``, ``upper`` (the time's own ``L``, ``U``)."""
        length = stop - start + 1
        empty = length <= 0
        level = self.levels[np.where(empty, 1, length)]
        left = np.where(empty, 0, start)
        right = np.where(empty, 0, stop - 2 ** level + 1)
        high = np.maximum(np.maximum(self.high[level, left], self.high[level, right]), lower)
        low = np.minimum(np.minimum(self.low[level, left], self.low[level, right]), upper)
        return np.where(empty, lower, high), np.where(empty, upper, low)


def _latest(extremes: _Extremes, rows: _Rows) -> np.ndarray:
    """The latest candidate column at each row from which the window, going back from the row's time, has closed
    (running maximum of ``L`` at or above the running minimum of ``U`` since): ``last + 1`` where it is closed at the
    time itself, ``first − 1`` where it never closes (the closed columns are the first ones: found by bisection)."""
    below, above = rows.first - 1, rows.last + 2  # (closed at below, open at above)
    while np.any(above - below > 1):
        middle = (below + above) // 2
        high, low = extremes.window(np.clip(middle, rows.first, rows.last + 1), rows.last, rows.lower, rows.upper)
        met = (high >= low) & (above - below > 1)
        below, above = np.where(met, middle, below), np.where(met | (above - below <= 1), above, middle)
    return below


def _closed(play: RatePlay, rows: _Rows, latest: np.ndarray) -> np.ndarray:
    """The one value the window holds on every interval before the candidate ``latest`` where it closed
    (:func:`_closed_value`; 0 where it closes at the time itself or never)."""
    grid, value = play._grid, np.zeros(rows.times.shape)
    closing = np.flatnonzero((latest >= rows.first) & (latest <= rows.last))
    k, last = latest[closing], rows.last[closing]
    c_l, c_u = play._extremes.window(k + 1, last, rows.lower[closing], rows.upper[closing])
    rises, falls = grid.lower[k] >= c_u, grid.upper[k] <= c_l
    value[closing] = np.where(rises, c_u, c_l)
    for index in np.flatnonzero(rises & falls):  # (both inside one interval: which came first going back)
        end = grid.times[k[index] + 1] if k[index] < last[index] else rows.times[closing[index]]
        value[closing[index]] = _closed_value(play, grid.times[k[index]], end, c_l[index], c_u[index],
                                              grid.lower[k[index]], grid.upper[k[index]])
    return value


def _held(extremes: _Extremes, rows: _Rows, columns: np.ndarray, latest: np.ndarray,
          closed: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The window ``(c_l, c_u)`` held on the interval from each candidate of ``columns`` (increasing) at each time: the
    largest ``L`` and least ``U`` from the interval's end to the time, the closed value on the intervals before the
    window closed, the time's ``L`` on every interval where it closed at the time. The candidates from one of
    ``columns`` to the next are a run whose extremes are looked up once, the run holding a time's last candidate cut
    there; the running extremes over the runs, from the time back, are an accumulation along each row."""
    per_row = (slice(None), None)
    runs_end = np.append(columns[1:], extremes.high.shape[1] - 1)
    run_l, run_u = extremes.window(columns + 1, runs_end, -np.inf, np.inf)
    owner = np.searchsorted(columns, rows.last, side="left") - 1  # (the run holding the time's last candidate)
    cut_l, cut_u = extremes.window(columns[np.maximum(owner, 0)] + 1, rows.last, -np.inf, np.inf)
    order = np.arange(columns.size)[None, :]
    c_l = np.where(order < owner[per_row], run_l, np.where(order == owner[per_row], cut_l[per_row], -np.inf))
    c_u = np.where(order < owner[per_row], run_u, np.where(order == owner[per_row], cut_u[per_row], np.inf))
    c_l = np.maximum(np.maximum.accumulate(c_l[:, ::-1], axis=1)[:, ::-1], rows.lower[per_row])
    c_u = np.minimum(np.minimum.accumulate(c_u[:, ::-1], axis=1)[:, ::-1], rows.upper[per_row])
    return _closing(rows, columns, latest, closed, c_l, c_u)


def _closing(rows: _Rows, columns: np.ndarray, latest: np.ndarray, closed: np.ndarray, c_l: np.ndarray,
             c_u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The windows ``c_l``, ``c_u`` (a row per time, a column per candidate of ``columns``) where the window closed:
    the closed value before it closed, the time's ``L`` where it closed at the time."""
    per_row = (slice(None), None)
    before = columns < np.where(latest <= rows.last, latest, -1)[per_row]
    at_time = (latest == rows.last + 1)[per_row]
    return (np.where(at_time, rows.lower[per_row], np.where(before, closed[per_row], c_l)),
            np.where(at_time, rows.lower[per_row], np.where(before, closed[per_row], c_u)))


def _first_window(play: RatePlay, rows: _Rows, latest: np.ndarray, closed: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The window held on each time's first interval (from its candidate ``first``), the time's own where it sees no
    candidate."""
    c_l, c_u = play._extremes.window(rows.first + 1, rows.last, rows.lower, rows.upper)
    c_l, c_u = _closing(rows, rows.first[:, None], latest, closed, c_l[:, None], c_u[:, None])
    seen = rows.first <= rows.last
    return np.where(seen, c_l[:, 0], rows.lower), np.where(seen, c_u[:, 0], rows.upper)


def _closed_value(play: RatePlay, start: float, end: float, c_l: float, c_u: float, l_start: float,
                  u_start: float) -> float:
    """The one value of a window that closes inside ``[start, end]`` going back from ``end``: ``c_u`` where ``L``
    rose to it, ``c_l`` where ``U`` fell to it, the later of the two where both did."""
    rises, falls = l_start >= c_u, u_start <= c_l
    if rises and falls:  # (both inside one interval: the one nearer the end came first going back)
        when_l = brentq(lambda t: float(play._level(np.array([t]))[0]) - c_u, start, end)
        when_u = brentq(lambda t: float(play._upper(np.array([t]))[0]) - c_l, start, end)
        return c_u if when_l > when_u else c_l
    return c_u if rises else c_l
