r"""The springs' shifts on top of a rate-dependent edge along a path whose ``x`` turns back (fretting, a zigzag, a
reversal): every anchor a play operator of the window ``[L, U] = [x − K a, x + K a]`` (13), the same for every spring.

:class:`~mdr_events.models.continuum.rate_shifts.RateShifts` holds the closed form of a path whose ``x`` does not turn
back (only ``L`` pushes, every anchor ``max(X, M)``). Where ``x`` turns back ``U`` pushes too. The windows a spring
sees from its attachment at ``τ`` to ``t`` compose to one clamp (a clamp of a clamp is a clamp), so its anchor is
``clamp(X(τ), l(τ), u(τ))`` with ``X(τ) = x(τ)`` and, going back in ``τ`` from ``(l, u)(t) = (L(t), U(t))``,

.. math:: l(\tau) = \mathrm{clamp}(L(\tau), l(\tau^+), u(\tau^+)), \qquad
          u(\tau) = \mathrm{clamp}(U(\tau), l(\tau^+), u(\tau^+)),

the running maximum of ``L`` and minimum of ``U`` over ``[τ, t]`` until they meet, after which the window is one value
``c`` for every earlier spring (those springs slid together and merged). Between two of the candidates where a running
extremum can change (every knot of the edge's steps and the path's corners, each step's interior maxima of ``L`` and
minima of ``U``) ``x`` is linear and the radius one polynomial; there ``L(τ) <= X(τ) <= U(τ)``, so the anchor is
``clamp(X(τ), c_l, c_u)`` with the extremes held from the next candidate on, and each interval splits where the
linear ``X`` meets them. Each part is a constant anchor or ``X`` itself, summed by the record's force
(:func:`~mdr_events.theory.symbolic.derive_rate_dependent_adhesion`'s ``rate_springs_record_force``: a constant
anchor ``c`` is its ``level`` over the whole part, ``X`` its sticking springs, ``∫ Ẋ a dτ`` by Gauss–Legendre on the
step's polynomial, exact). The springs of the jump-in's first instant carry the anchor of the contact's start.

The force is evaluated time by time (the windows depend on ``t``); the candidates' values and the integrals between
them are computed once. A spring is at a cap where its anchor is the current ``L(t)`` or ``U(t)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

from .rate_edge import EdgeEventKind
from .rate_shifts import RateShifts, _first_radius, _knots, _peaks, _relation, gauss_radius

__all__ = ["RatePlay"]

#: Halvings of the bracket of the first slip (a spring's anchor first at a cap): 2^-64 of a candidate interval, below
#: the clock's spacing.
ONSET_HALVINGS = 64


@dataclass
class RatePlay(RateShifts):
    """``F_x`` along a path whose ``x`` turns back, on top of the rate-dependent edge (module docstring); ``sign`` is
    +1 (``x`` as it is).

    Parameters
    ----------
    edge : EdgeRun
        The radius along the path.
    path : Path
        The path.
    cap : float
        ``K`` of ``ū = K a`` (13) (m per m).
    G_star : float
        The effective shear modulus ``G*`` (Pa).
    sign : float
        +1.
    """

    def __post_init__(self) -> None:
        super().__post_init__()
        corners = self._corners[0]
        stamps = [self._candidates[0]]
        for view in self.views:  # (U's interior minima: the maxima of -U)
            stamps.append(_peaks(lambda t: -self._upper(t), _knots(view, corners)))
        times = np.unique(np.concatenate(stamps))
        radius = self._radius(times)
        x = self._x(times)
        self._touches = np.array([event.time for event in self.edge.events
                                  if event.kind in (EdgeEventKind.FIRST_CONTACT, EdgeEventKind.RE_CONTACT)])
        self._grid = _Grid(times, radius, x, x - self.cap * radius, x + self.cap * radius, self._primitive(times))
        self._candidates = (times, self._grid.lower)  # (the times a run's scan looks at: rate_run.scan_run)

    def _upper(self, times) -> np.ndarray:
        """``U = x + K a`` (m) at ``times``."""
        return self._x(times) + self.cap * self._radius(times)

    def _primitive(self, times: np.ndarray) -> np.ndarray:
        """``∫ ẋ a dτ`` (m²) from the first time to each of ``times`` (increasing, holding every knot): Gauss–Legendre
        on each interval between them, where ``x`` is linear and the radius one polynomial."""
        width = np.diff(times)
        slope = np.diff(self._x(times)) / np.where(width > 0.0, width, 1.0)
        half, weighted = gauss_radius(self._radius, times[:-1], times[1:])
        return np.concatenate([[0.0], np.cumsum(slope * half * weighted)])

    def running_level(self, times) -> np.ndarray:
        """Not defined where ``x`` turns back (both levels push); refused.

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        numpy.ndarray
            Never.

        Raises
        ------
        ValueError
            Always: the anchors' windows are :meth:`tangential_force`'s.
        """
        raise ValueError("running_level is not allowed along a path whose x turns back; allowed: tangential_force and "
                         "slip_radius (the anchors' windows depend on the time asked)")

    def slip_onset_time(self) -> float:
        """The first time (s, path clock) at which a spring's anchor is at a cap, found between the candidates by
        bisection.

        Returns
        -------
        float
            The time, or ``nan`` where no spring slides during the first contact.
        """
        ended = [event.time for event in self.edge.events if event.kind is EdgeEventKind.CONTACT_ENDS]
        times = self._grid.times
        first = times[(times >= self.views[0].t0) & (times <= (ended[0] if ended else self.path.duration))]
        sliding = self._evaluate(first)[1] > 0.0
        if not np.any(sliding):
            return float("nan")
        after = int(np.argmax(sliding))
        if after == 0:
            return float(first[0])
        low, high = float(first[after - 1]), float(first[after])
        for _ in range(ONSET_HALVINGS):
            middle = 0.5 * (low + high)
            if middle in (low, high):
                break
            if self._evaluate(np.array([middle]))[1][0] > 0.0:
                high = middle
            else:
                low = middle
        return high

    def sliding_sides(self, times) -> tuple[np.ndarray, np.ndarray]:
        """The measures (m) of the springs at the lower cap ``x − K a`` (pushed towards ``+x``) and at the upper one
        ``x + K a`` (towards ``−x``) at ``times`` (s, path clock).

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        tuple of numpy.ndarray
            The lower cap's and the upper cap's, each the shape of ``times``.
        """
        _, lower, upper = self._sides(times)
        return lower, upper

    def _sides(self, times) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        times = np.atleast_1d(np.asarray(times, dtype=float))
        out = np.zeros((3,) + times.shape)
        starts = np.array([view.t0 for view in self.views])
        owner = np.searchsorted(starts, times, side="right") - 1
        for row, (time, index) in enumerate(zip(times, owner)):
            if index >= 0 and time <= self.views[index].t1:
                out[:, row] = _force_at(self, self.views[index], float(time))
        return out[0], out[1], out[2]

    def _evaluate(self, times) -> tuple[np.ndarray, np.ndarray]:
        force, lower, upper = self._sides(times)
        return force, lower + upper


class _Grid(NamedTuple):
    """The candidates (times, increasing) and the radius, ``x``, ``L``, ``U`` and ``∫ ẋ a dτ`` there."""

    times: np.ndarray
    radius: np.ndarray
    x: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    primitive: np.ndarray


def _windows(play: RatePlay, time: float):
    """The candidates of the contact up to ``time`` with ``time`` last, and on each interval between them the held
    window ``(c_l, c_u)``: the running extremes from its end on, one value ``c`` before they met."""
    grid = play._grid
    touched = play._touches[play._touches <= time]
    inside = np.flatnonzero((grid.times < time) & (grid.times >= (touched[-1] if touched.size else -np.inf)))
    at = np.concatenate([grid.times[inside], [time]])
    radius, x = play._radius(np.array([time]))[0], play._x(np.array([time]))[0]
    lower = np.concatenate([grid.lower[inside], [x - play.cap * radius]])
    upper = np.concatenate([grid.upper[inside], [x + play.cap * radius]])
    high = np.maximum.accumulate(lower[::-1])[::-1]  # max of L over [τ_k, t]
    low = np.minimum.accumulate(upper[::-1])[::-1]   # min of U over [τ_k, t]
    held_l, held_u = high[1:], low[1:]               # (on the interval (τ_k, τ_k+1): from its end on)
    met = np.flatnonzero(high >= low)
    if met.size:  # the latest candidate where the window has closed: every interval before it holds one value
        k = int(met[-1])
        if k < held_l.size:
            value = _closed_value(play, at[k], at[k + 1], held_l[k], held_u[k], lower[k], upper[k])
            held_l[:k], held_u[:k] = value, value
        else:
            held_l[:], held_u[:] = high[-1], high[-1]
    return at, held_l, held_u, (lower[-1], upper[-1])


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


def _force_at(play: RatePlay, view, time: float) -> tuple[float, float, float]:
    """``F_x`` (N) and the measures (m) of the springs at the lower and the upper cap at ``time`` within ``view``
    (module docstring)."""
    at, held_l, held_u, now = _windows(play, time)
    x_now, radius_now = play._x(np.array([time]))[0], play._radius(np.array([time]))[0]
    ranges = [(record.lo, record.hi, record.solution) for record in view.records]
    if view.way > 0:
        ranges.append((view.t0, time, view.solution))
    totals = np.zeros(3)
    for lo, hi, solution in ranges:
        if view.way < 0 and float(solution(hi)[0]) > radius_now:  # (the receding edge took the springs beyond)
            hi = float(_first_radius(solution, lo, np.array([hi]), np.array([radius_now]))[0])
        totals += _range_force(play, at, held_l, held_u, lo, hi, x_now, now)
    block = view.block
    kept = min(block.radius, radius_now)
    anchor = min(max(block.anchor, held_l[0] if held_l.size else now[0]), held_u[0] if held_u.size else now[1])
    totals[0] += float(_relation().numeric(x_now, anchor, 0.0, kept, kept, 0.0, 0.0, 0.0, play.G_star))
    totals[1:] += [kept if anchor == now[0] else 0.0, kept if anchor == now[1] and anchor != now[0] else 0.0]
    return totals[0], totals[1], totals[2]


def _range_force(play: RatePlay, at, held_l, held_u, lo: float, hi: float, x_now: float, now) -> np.ndarray:
    """The force and the measures at the lower and the upper cap of the springs attached on ``[lo, hi]``: each
    interval between candidates cut where the linear ``X`` meets its held window, each part a constant anchor or
    ``X``."""
    first = np.searchsorted(at, lo, side="right") - 1
    last = np.searchsorted(at, hi, side="left")
    edges = np.clip(at[max(first, 0):last + 1], lo, hi)
    c_l, c_u = held_l[max(first, 0):last], held_u[max(first, 0):last]
    start, end = edges[:-1], edges[1:]
    keep = end > start
    start, end, c_l, c_u = start[keep], end[keep], c_l[keep], c_u[keep]
    if not start.size:
        return np.zeros(3)
    x0, x1 = play._x(start), play._x(end)
    rise = x1 - x0
    with np.errstate(divide="ignore", invalid="ignore"):
        cross_l = np.where(rise != 0.0, start + (c_l - x0) / rise * (end - start), start)
        cross_u = np.where(rise != 0.0, start + (c_u - x0) / rise * (end - start), start)
    inner = np.sort(np.stack([np.clip(cross_l, start, end), np.clip(cross_u, start, end)]), axis=0)
    cuts = np.stack([start, inner[0], inner[1], end])  # (4, n): three parts each
    lows, highs = cuts[:-1].ravel(), cuts[1:].ravel()
    c_l3, c_u3 = np.tile(c_l, 3), np.tile(c_u, 3)
    middle = play._x(0.5 * (lows + highs))
    constant = (middle < c_l3) | (middle > c_u3) | (c_l3 == c_u3)
    anchor = np.where(middle < c_l3, c_l3, c_u3)
    a_low, a_high = _radius_at(play, lows), _radius_at(play, highs)
    x_low, x_high = play._x(lows), play._x(highs)
    swept = _swept_between(play, lows, highs)
    force = _relation_sum(play, x_now, np.where(constant, anchor, 0.0), a_low, np.where(constant, a_high, a_low),
                         a_high, np.where(constant, 0.0, x_low), np.where(constant, 0.0, x_high),
                         np.where(constant, 0.0, swept))
    measure = a_high - a_low
    at_lower = constant & (anchor == now[0])
    at_upper = constant & (anchor == now[1]) & ~at_lower
    return np.array([force, np.sum(np.where(at_lower, measure, 0.0)), np.sum(np.where(at_upper, measure, 0.0))])


def _relation_sum(play: RatePlay, x_now, level, lo, star, hi, x_star, x_hi, swept) -> float:
    """The record force (``rate_springs_record_force``) of each part, summed (N)."""
    return float(np.sum(_relation().numeric(x_now, level, lo, star, hi, x_star, x_hi, swept, play.G_star)))


def _swept_between(play: RatePlay, lows: np.ndarray, highs: np.ndarray) -> np.ndarray:
    """``∫ ẋ a dτ`` (m²) over each ``[low, high]`` (each within one interval between candidates): the candidates'
    primitive and Gauss–Legendre on the ends' remainders."""
    return _primitive_at(play, highs) - _primitive_at(play, lows)


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
