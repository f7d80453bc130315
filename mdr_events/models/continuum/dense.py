"""A span's dense output evaluated at many points at once: the values ``solve_ivp``'s ``OdeSolution`` gives, bit for
bit, without its Python loop over the solver's steps.

``OdeSolution`` hands each step's points to that step's interpolant, one call per step: a span of a tabulated indenter
starts a piece at each of the table's knots (a panel of :mod:`.span_panels` each, stored as a DOP853 step), some ninety
steps, and filling 2001 samples cost a hundred such calls. DOP853's interpolant of a step is a polynomial in ``x = (t − t_old)/h``
evaluated by a fixed sequence of products and sums (``Dop853DenseOutput``); :func:`force_values` takes that sequence for
every point at once, each point with the coefficients of the step ``OdeSolution`` would pick for it, so that every value
is the interpolant's own. Any other dense output (another method, :class:`~.span.LinearForce`) is called as it is.
"""

from __future__ import annotations

import weakref
from typing import Callable, NamedTuple

import numpy as np
from scipy.integrate import OdeSolution

try:  # (SciPy's class of DOP853's step interpolant; without it every dense output is called as it is)
    from scipy.integrate._ivp.rk import Dop853DenseOutput
except ImportError:  # pragma: no cover
    Dop853DenseOutput = None

__all__ = ["cut", "force_values"]


class _Steps(NamedTuple):
    """The steps of a DOP853 ``OdeSolution`` as arrays: how it picks a step (``ts_sorted``, ``side``, ``ascending``)
    and each step's ``t_old``, ``h``, ``y_old`` and the rows of ``F``, last first (the order they are summed in)."""

    ts_sorted: np.ndarray
    side: str
    ascending: bool
    t_old: np.ndarray
    h: np.ndarray
    y_old: np.ndarray
    reversed_F: np.ndarray


#: Each solution's steps as arrays, gathered once (a fill and the extrema's scan read the same spans).
_GATHERED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _gathered(interpolant) -> _Steps | None:
    """:class:`_Steps` of a one-component ``OdeSolution`` whose every step is DOP853's, else ``None``."""
    if type(interpolant) is not OdeSolution or Dop853DenseOutput is None:
        return None
    if interpolant in _GATHERED:
        return _GATHERED[interpolant]
    steps = interpolant.interpolants
    if not steps or any(type(step) is not Dop853DenseOutput or step.y_old.shape != (1,) for step in steps):
        return None
    found = _Steps(np.asarray(interpolant.ts_sorted, dtype=float), interpolant.side, bool(interpolant.ascending),
                   np.array([step.t_old for step in steps], dtype=float), np.array([step.h for step in steps],
                                                                                  dtype=float),
                   np.array([step.y_old[0] for step in steps]), np.array([step.F[::-1, 0] for step in steps]).T)
    _GATHERED[interpolant] = found
    return found


def force_values(interpolant: Callable, points: np.ndarray) -> np.ndarray:
    """``interpolant(points)[0]`` of a span's dense output (``OdeSolution``) at a 1-D array of points.

    Parameters
    ----------
    interpolant : callable
        The span's interpolant of ``F_x`` (``solve_ivp``'s ``OdeSolution``, or any callable of that shape).
    points : numpy.ndarray
        The points (the span's variable: time or scaled radius), 1-D.

    Returns
    -------
    numpy.ndarray
        ``F_x`` at the points (N), the interpolant's values bit for bit.
    """
    steps = _gathered(interpolant)
    if steps is None or np.ndim(points) != 1:
        return interpolant(points)[0]
    t = np.asarray(points, dtype=float)
    return _polynomials(t, _picked(steps, t), steps)


def _step_values(steps: list[_Steps], points: list[np.ndarray]) -> list[np.ndarray]:
    """:func:`force_values` of several spans' DOP853 steps (:func:`_gathered`) at their points (1-D) in one
    evaluation: each point with the step its own span's ``OdeSolution`` picks, the steps of all spans in one table.

    Parameters
    ----------
    steps : list of _Steps
        Each span's steps.
    points : list of numpy.ndarray
        Each span's points (its variable), 1-D.

    Returns
    -------
    list of numpy.ndarray
        ``F_x`` at each span's points (N), each value its interpolant's bit for bit.
    """
    if len(steps) == 1:
        t = np.asarray(points[0], dtype=float)
        return [_polynomials(t, _picked(steps[0], t), steps[0])]
    times = [np.asarray(where, dtype=float) for where in points]
    offsets = np.cumsum([0] + [len(found.t_old) for found in steps[:-1]])
    picked = np.concatenate([_picked(found, t) + offset for found, t, offset in zip(steps, times, offsets.tolist())])
    table = _Steps(None, "", True, *(np.concatenate([getattr(found, name) for found in steps], axis=-1)
                                     for name in ("t_old", "h", "y_old", "reversed_F")))
    values = _polynomials(np.concatenate(times), picked, table)
    return cut(values, [len(t) for t in times])


def cut(values: np.ndarray, lengths: list[int]) -> list[np.ndarray]:
    """``values`` cut into consecutive parts of ``lengths`` (views): ``np.split``'s parts, without its cost per part
    (a transposition and a slice each, some 5 µs; a run's spans are tens).

    Parameters
    ----------
    values : numpy.ndarray
        A 1-D array.
    lengths : list of int
        The parts' lengths, summing to ``len(values)``.

    Returns
    -------
    list of numpy.ndarray
        The parts, in order.
    """
    parts, start = [], 0
    for length in lengths:
        parts.append(values[start:start + length])
        start += length
    return parts


def _picked(steps: _Steps, t: np.ndarray) -> np.ndarray:
    """The index of the step ``OdeSolution`` picks for each of the points ``t``."""
    count = len(steps.t_old)
    segment = np.searchsorted(steps.ts_sorted, t, side=steps.side) - 1  # (as OdeSolution picks a step)
    np.clip(segment, 0, count - 1, out=segment)
    if not steps.ascending:
        segment = count - 1 - segment
    return segment


def _polynomials(t: np.ndarray, segment: np.ndarray, steps: _Steps) -> np.ndarray:
    """Each point's step interpolant (step ``segment`` of ``steps``) at ``t``: ``Dop853DenseOutput``'s products and
    sums, every point at once."""
    x = (t - steps.t_old[segment]) / steps.h[segment]
    rest = 1 - x
    y = np.zeros(t.shape)
    # (Dop853DenseOutput._call_impl's products and sums; every row's coefficients gathered at once)
    for i, row in enumerate(np.take(steps.reversed_F, segment, axis=1)):
        y += row
        y *= x if i % 2 == 0 else rest
    y += steps.y_old[segment]
    return y
