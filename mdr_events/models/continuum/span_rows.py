"""Which span of a run holds each of a time grid's samples (:func:`~.solution.evaluate`'s fill): each span's rows,
a slice where they are one block (a run's samples, in order), else their indices."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .state import Regime

if TYPE_CHECKING:
    from .solution import PathSolution


def _sorted_span_rows(solution: PathSolution, times: np.ndarray) -> list[tuple[int, slice]] | None:
    """:func:`_span_rows` of :meth:`~.solution.PathSolution.span_index` and the times inside the run, for times that
    do not decrease (a run's samples): each span's block located by one ``searchsorted`` of the spans' ends among the
    times (a time at an approach's end, a contact made, the next span's: ``span_index``'s rule); ``None`` for times
    out of order (their rows by :func:`_span_rows`)."""
    if times.size > 1 and not np.all(times[1:] >= times[:-1]):
        return None
    spans = solution.spans
    ends = np.array([span.t_end for span in spans]) - solution.t_contact
    approach = np.array([span.regime is Regime.NONE for span in spans[:-1]], dtype=bool)
    uppers = np.where(approach, np.searchsorted(times, ends[:-1], side="left"),
                      np.searchsorted(times, ends[:-1], side="right")).tolist() + [times.size]
    low = int(np.searchsorted(times, 0.0, side="left"))
    high = int(np.searchsorted(times, solution.end_time, side="right"))
    rows, lower = [], 0
    for index, upper in enumerate(uppers):
        start, stop = max(lower, low), min(upper, high)
        if stop > start:
            rows.append((index, slice(start, stop)))
        lower = upper
    return rows


def _span_rows(owner: np.ndarray, inside: np.ndarray, count: int) -> list[tuple[int, slice | np.ndarray]]:
    """The rows of each of ``count`` spans that holds a time ``inside`` the run (``owner``: the span of each time), in
    the spans' order: slices where the times inside are one block with their spans in order (increasing times, as
    a run's samples are: views, not copies gathered and scattered back), else the indices of each span's rows."""
    rows = np.flatnonzero(inside)
    if not rows.size:
        return []
    owners = owner[rows]
    if rows[-1] - rows[0] == rows.size - 1 and np.all(owners[1:] >= owners[:-1]):
        edges = rows[0] + np.searchsorted(owners, np.arange(count + 1))
        return [(index, slice(int(lower), int(upper))) for index, (lower, upper) in enumerate(zip(edges[:-1],
                                                                                                  edges[1:]))
                if upper > lower]
    return [(index, rows[owners == index]) for index in range(count) if np.any(owners == index)]
