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

The windows depend on ``t``, and every time asked is evaluated at once, a row per time over the candidates' columns
(in chunks of :data:`CHUNK_PAIRS`): the candidates' values, the integrals between them and sparse tables of the extremes
of ``L`` and ``U`` over any run of candidates are computed once; where each time's window closed is found by bisection
on them, the held windows are accumulations along each row over the candidates that carry springs, the intervals that
``X`` does not cross inside their window are summed as products of masks with each interval's measure and integrals,
and the few others are cut as above. A spring is at a cap where its anchor is the current ``L(t)`` or ``U(t)``.
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
#: The most pairs of a time and a candidate laid out at once where the force is asked at many times (rows of times by
#: the columns of candidates they see; 2^19 doubles, 4 MB an array).
CHUNK_PAIRS = 1 << 16


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
        self._touches = np.sort(np.array([event.time for event in self.edge.events
                                          if event.kind in (EdgeEventKind.FIRST_CONTACT, EdgeEventKind.RE_CONTACT)],
                                         dtype=float))
        self._grid = _Grid(times, radius, x, x - self.cap * radius, x + self.cap * radius, self._primitive(times))
        self._extremes = _Extremes(self._grid.lower, self._grid.upper)
        self._last = (None, None)  # (the times last asked, as bytes, and the sides there)
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
        key = times.tobytes()
        if self._last[0] != key:  # (a run asks for the force and then the caps' sides at its scan's times)
            self._last = (key, self._sides_at(times))
        return tuple(part.copy() for part in self._last[1])

    def _sides_at(self, times: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        flat = times.ravel()
        out = np.zeros((3, flat.size))
        starts = np.array([view.t0 for view in self.views])
        owner = np.searchsorted(starts, flat, side="right") - 1
        for index in np.unique(owner[owner >= 0]):
            view = self.views[index]
            rows = np.flatnonzero((owner == index) & (flat <= view.t1))
            rows = rows[np.argsort(flat[rows], kind="stable")]
            for chunk in _chunks(self, flat[rows]):
                out[:, rows[chunk]] = _view_sides(self, view, flat[rows[chunk]])
        return tuple(part.reshape(times.shape) for part in out)

    def _evaluate_each(self, *times: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
        """:meth:`_evaluate` of each array of ``times`` alone, in turn (the sides of the last kept: a run asks its
        scan's last, whose sides its events read)."""
        return [self._evaluate(part) for part in times]

    def _evaluate(self, times, forces: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """``F_x`` (N) and the springs at either cap (m); ``forces`` as :class:`RateShifts` takes it (the sides and the
        force come together here, kept for the times last asked)."""
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


def _chunks(play: RatePlay, times: np.ndarray) -> list[slice]:
    """Slices of ``times`` (increasing) whose rows by the candidate columns they see hold at most
    :data:`CHUNK_PAIRS` pairs (at least one row each)."""
    grid = play._grid
    last = np.searchsorted(grid.times, times, side="left")
    out, begin = [], 0
    while begin < times.size:
        width = np.maximum(last[begin:] + 2, 2)  # (the columns up to each row's last, and its own)
        rows = np.arange(1, times.size - begin + 1)
        fits = np.flatnonzero(rows * width <= CHUNK_PAIRS)
        end = begin + (int(fits[-1]) + 1 if fits.size else 1)
        out.append(slice(begin, end))
        begin = end
    return out


def _view_sides(play: RatePlay, view, times: np.ndarray) -> np.ndarray:
    """``F_x`` (N) and the measures (m) of the springs at the lower and the upper cap at ``times`` (increasing, within
    ``view``), as rows of a ``(3, n)`` array: where each time's window closed (:func:`_latest`), the windows held on the
    intervals of the springs present (:func:`_held`), those intervals summed whole where ``X`` does not cross the
    window inside (:func:`_whole_intervals`), the others cut into parts (:func:`_cut_parts`), and the springs of the
    jump-in's instant."""
    rows = _rows(play, times)
    columns = np.arange(int(rows.first.min()), int(rows.last.max()) + 1)
    los, his, base = _ranges(play, view, rows)
    owner = np.searchsorted(los, play._grid.times[columns], side="right") - 1
    present = (owner >= 0) & (play._grid.times[columns] < base[np.maximum(owner, 0)])
    columns, owner = columns[present], owner[present]
    latest = _latest(play._extremes, rows)
    closed = _closed(play, rows, latest)
    total = _block(play, view, rows, _first_window(play, rows, latest, closed))
    if columns.size:
        held = _held(play._extremes, rows, columns, latest, closed)
        total += _intervals(play, rows, columns, owner, his, *held)
    return total


def _ranges(play: RatePlay, view, rows: _Rows) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The attachment times' ranges of the springs present: each record's start, its end at each row (where the
    receding edge took the springs beyond the radius then, the time the record's radius reached it) and its own end;
    the advancing piece itself up to each row's time."""
    los, his, base = [], [], []
    for record in view.records:
        hi = np.full(rows.times.shape, record.hi)
        if view.way < 0:  # (the receding edge took the springs beyond the radius now)
            beyond = record.solution(hi)[0] > rows.radius
            if np.any(beyond):
                hi[beyond] = _first_radius(record.solution, record.lo, hi[beyond], rows.radius[beyond])
        los.append(record.lo)
        his.append(hi)
        base.append(record.hi)
    if view.way > 0:
        los.append(view.t0)
        his.append(rows.times)
        base.append(view.t1)
    if not los:
        return np.full(1, np.inf), np.zeros((0, rows.times.size)), np.full(1, -np.inf)  # (no spring attached)
    return np.array(los), np.array(his), np.array(base)


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
