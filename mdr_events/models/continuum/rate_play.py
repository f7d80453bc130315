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

from .rate_edge import EdgeEventKind
from .rate_play_sums import _block, _intervals
from .rate_play_windows import _closed, _Extremes, _first_window, _held, _latest, _Rows, _rows
from .rate_shifts import RateShifts, _first_radius, _knots, _peaks, gauss_radius

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
