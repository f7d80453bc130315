"""The clamp times every spring of :mod:`.play_springs` shares: the path's corners, the radius's jumps, the ends of
each piece where the radius moves smoothly, and the stretches where ``ū(a(t))`` is not concave (where each spring
gains times of its own, :mod:`.play_golden`).

Along a path segment the window's edges ``L = x − c`` and ``U = x + c`` are convex and concave wherever ``ū(a(t))`` is
concave in ``t``, so the play operator over such an interval is the clamp at its start followed by the clamp at its
end; where the sampled ``ū(a(t))`` of a piece is not concave (a second difference above :data:`CONCAVITY_ROUND_OFF`
of its largest value, on :data:`CONCAVITY_SAMPLES` times) the stretch is kept with its ends among the shared times.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["Chain", "shared_chain", "CONCAVITY_SAMPLES", "CONCAVITY_ROUND_OFF"]

#: Depths at which a segment's ``ū(a(d))`` is sampled for its concavity.
CONCAVITY_SAMPLES = 65
#: A second difference of ``ū(a(d))`` counts as convex above this share of its largest value (round-off).
CONCAVITY_ROUND_OFF = 1e-12


class Chain(NamedTuple):
    """The clamp times shared by every spring (increasing) and the intervals where each spring gains its own."""

    #: the shared clamp times (s, path clock), increasing
    times: np.ndarray
    #: ``(start, end)`` of the intervals where ``ū(a(d))`` is not concave (each between two of ``times``)
    convex: np.ndarray


def shared_chain(history, line, corner_t: np.ndarray) -> Chain:
    """The corners, the radius's jumps, the ends of each piece where the radius moves smoothly (where it starts or
    stops moving ``ū(a(t))`` has a kink, at which a window's extremum can lie) and, on each piece, the subintervals
    where ``ū(a(t))`` is not concave (their ends join the shared times).

    Parameters
    ----------
    history : DepthHistory, SpanHistory or RateHistory
        The radius along the path (its ``pieces``, ``jumps`` and ``radii``).
    line : SpringLine
        The springs (their ``shift``, ``ū(a)``).
    corner_t : numpy.ndarray
        The path's corner times (s, path clock).

    Returns
    -------
    Chain
        The shared clamp times and the stretches where ``ū(a(t))`` is not concave.
    """
    pieces = history.pieces()
    times, convex = [corner_t, np.array([jump[0] for jump in history.jumps]),
                     np.array(pieces, dtype=float).ravel()], []
    for start, end in pieces:
        grid = np.linspace(start, end, CONCAVITY_SAMPLES)
        inner = grid.copy()
        inner[[0, -1]] = grid[[0, -1]] + np.array([1.0, -1.0]) * 1e-12 * (end - start)  # (inside the piece)
        shift = line.shift(history.radii(inner))
        second = shift[:-2] - 2.0 * shift[1:-1] + shift[2:]
        flagged = np.flatnonzero(second > CONCAVITY_ROUND_OFF * max(np.max(np.abs(shift)), 1e-300))
        # (neighbouring flags' intervals [j, j + 2] overlap: one stretch each run of them, on which L is concave
        # and U convex, one golden section each; a stretch per flag took 13 of them on a cone on a layer)
        runs = np.split(flagged, np.flatnonzero(np.diff(flagged) > 1) + 1) if flagged.size else []
        for run in runs:
            convex.append((grid[run[0]], grid[run[-1] + 2]))
            times.append(grid[[run[0], run[-1] + 2]])
    shared = np.unique(np.concatenate(times))
    return Chain(shared, np.array(convex, dtype=float).reshape(-1, 2))
