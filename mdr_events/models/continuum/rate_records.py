"""The springs attached along a rate-dependent edge: each piece of the edge with the records of those still attached.

A record is an advancing piece of the edge (:func:`~mdr_events.models.continuum.rate_edge.solve_edge`) whose springs
attached between two times; a receding piece cuts the records at its radius (the first time an advancing piece's
radius reached it, on its steps' polynomials or by bisection), and the contact's end clears them. What
:class:`~mdr_events.models.continuum.rate_shifts.RateShifts` sums over (its module docstring).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .rate_dense import StepPolynomials, step_polynomials
from .rate_edge import EdgeEventKind, EdgeRun

__all__ = ["BISECTIONS"]


#: Halvings of a bracket where the radius reaches a value on a dense output that is not the steps' polynomials (on them
#: :meth:`~mdr_events.models.continuum.rate_dense.StepPolynomials.reach`; where ``x`` reaches a level, the sliding
#: springs' end, the closed form :func:`_reach`): 2^-64 of a step, below a double's spacing.
BISECTIONS = 64


class _Record(NamedTuple):
    """Springs attached on an advancing piece between the times ``lo`` and ``hi``, the radius ``solution(τ)[0]``."""

    lo: float
    hi: float
    solution: object


class _Block(NamedTuple):
    """The springs of the jump-in's first instant: ``[0, radius]`` with one anchor (``σx`` at the contact's start)."""

    radius: float
    anchor: float


class _View(NamedTuple):
    """One piece of the edge and the springs attached at its start."""

    t0: float
    t1: float
    solution: object
    way: int  #: +1 advancing, -1 receding, 0 resting
    records: tuple
    block: _Block


def _in_contact(views: list, times: np.ndarray) -> np.ndarray:
    inside = np.zeros(times.shape, dtype=bool)
    for view in views:
        inside |= (times >= view.t0) & (times <= view.t1)
    return inside


def _timeline(edge: EdgeRun, position) -> list[_View]:
    """Each piece of the edge with the records of springs attached at its start (cut by receding pieces, cleared where
    the contact ended)."""
    ends = {event.time for event in edge.events if event.kind is EdgeEventKind.CONTACT_ENDS}
    views, records, block, ended = [], [], None, True
    for t0, t1, _, dense in edge.pieces:
        solution = step_polynomials(dense)
        a0, a1 = float(solution(t0)[0]), float(solution(t1)[0])
        if ended:
            records, block = [], _Block(a0, float(position(np.array([t0]))[0]))
        way = 1 if a1 > a0 else -1 if a1 < a0 else 0
        views.append(_View(t0, t1, solution, way, tuple(records), block))
        if way > 0:
            records.append(_Record(t0, t1, solution))
        elif way < 0:
            records = _cut(records, a1)
            block = _Block(min(block.radius, a1), block.anchor)
        ended = t1 in ends
    return views


def _cut(records: list, radius: float) -> list:
    """The records of springs within ``radius`` (a receding edge took the rest)."""
    kept = []
    for record in records:
        a_lo, a_hi = (float(record.solution(t)[0]) for t in (record.lo, record.hi))
        if a_lo >= radius:
            break
        if a_hi > radius:
            record = record._replace(hi=float(_first_radius(record.solution, record.lo, np.array([record.hi]),
                                                            np.array([radius]))[0]))
        kept.append(record)
    return kept


def _first_radius(solution, lo: float, hi: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """The first time in ``[lo, hi]`` at which an advancing piece's radius reaches ``radius`` (elementwise): on its
    steps' polynomials (:meth:`~mdr_events.models.continuum.rate_dense.StepPolynomials.reach`), else by
    :func:`_bisect`."""
    if isinstance(solution, StepPolynomials):
        return solution.reach(radius, lo, hi)
    return _bisect(lambda t: solution(t)[0], np.full(hi.shape, lo), hi, radius)


def _bisect(increasing, lo: np.ndarray, hi: np.ndarray, target: np.ndarray) -> np.ndarray:
    """The least ``τ`` in ``[lo, hi]`` (elementwise) with ``increasing(τ) >= target``, to :data:`BISECTIONS` halvings
    (``increasing`` non-decreasing in ``τ``, vectorised)."""
    lo, hi = lo.astype(float).copy(), hi.astype(float).copy()
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        above = np.asarray(increasing(mid), dtype=float) >= target
        hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
    return hi
