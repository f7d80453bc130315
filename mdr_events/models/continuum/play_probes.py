"""The probes of the per-spring route (:mod:`.play_run`), where a zone opening between the quadrature's nodes is looked
for: each probe's label at each time asked, read in as few evaluations of the anchors as the times allow.

At a time where no node is at a cap :func:`~.play_samples._probed_all` reads :data:`~.play_samples.PROBE_POINTS` probes. The
times on one part of :func:`~.play_reach.constant_part` (every window fixed but for ``x``: a fretting stroke before its
slip onset) whose clamps before them are the same (no clamp time of the chain between the first and the last) and
whose probes are the same springs share each spring's anchor before the clamp, so they are read in one evaluation
(:meth:`~.play_springs.PlaySprings.caps_over`: the anchors once, each time's window its own, the labels each time's
own evaluation gives, bit for bit); the others in chunks of times, one evaluation each, as before.
``SHARED_PROBES = False`` reads every time in the chunks, the route of before (``tests/models/test_play_bound.py``).
"""

from __future__ import annotations

import numpy as np

from .play_reach import constant_part

__all__ = ["probes_at_cap", "shared_parts", "SHARED_PROBES"]

#: Whether the probes of the times on one part where every window is fixed but for ``x`` are read in one evaluation
#: of the anchors (:func:`shared_parts`; ``False``: each time in the chunks, the route of before, which the tests
#: compare it with).
SHARED_PROBES = True


def probes_at_cap(play, times: np.ndarray, edge: np.ndarray, rows: np.ndarray, grid: np.ndarray,
                  chunk: int) -> np.ndarray:
    """Whether each probe (``edge`` of each time times ``grid``) is at a cap at each time of ``rows`` (module
    docstring).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    times : numpy.ndarray
        The times (s, path clock).
    edge : numpy.ndarray
        The extent of the springs probed at each time (m).
    rows : numpy.ndarray
        The indices of the times probed.
    grid : numpy.ndarray
        The probes as shares of ``edge``.
    chunk : int
        The times read in one evaluation of the anchors where they are read on their own.

    Returns
    -------
    numpy.ndarray
        ``(rows.size, grid.size)``: whether each probe is at a cap.
    """
    out = np.zeros((rows.size, grid.size), bool)
    alone = []
    for group in shared_parts(play, times, edge, rows):
        if len(group) == 1:
            alone += group
        else:
            out[group] = play.caps_over(edge[rows[group[0]]] * grid, times[rows[group]])
    for first in range(0, len(alone), chunk):
        some = alone[first:first + chunk]
        chosen = rows[some]
        labels = play.anchors((edge[chosen][:, None] * grid).ravel(), np.repeat(times[chosen], grid.size))[1]
        out[some] = labels.reshape(len(some), grid.size) < 0
    return out


def shared_parts(play, times: np.ndarray, edge: np.ndarray, rows: np.ndarray) -> list[list[int]]:
    """The indices into ``rows`` grouped by time (increasing) where :meth:`~.play_springs.PlaySprings.caps_over` may
    read them together (module docstring): the same clamp times of the chain before each (none in ``[first, last)``),
    the same ``edge``, and a part of :func:`~.play_reach.constant_part` from the first to the last; every other index
    a group of its own (each alone where :data:`SHARED_PROBES` is ``False``).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    times, edge, rows : numpy.ndarray
        As :func:`probes_at_cap`.

    Returns
    -------
    list of list of int
        The groups, in the order of their times.
    """
    order = sorted(range(rows.size), key=lambda k: float(times[rows[k]]))
    if not SHARED_PROBES or rows.size < 2:
        return [[k] for k in order]
    keys = np.searchsorted(play.chain.times, times[rows], side="left")
    groups: list[list[int]] = []
    for k in order:
        last = groups[-1][-1] if groups else None
        if last is not None and keys[k] == keys[last] and edge[rows[k]] == edge[rows[last]] \
                and times[rows[k]] > times[rows[last]]:
            groups[-1].append(k)
        else:
            groups.append([k])
    out = []
    for group in groups:
        low, high = float(times[rows[group[0]]]), float(times[rows[group[-1]]])
        shared = len(group) > 1 and constant_part(play, low, high) == low
        out += [group] if shared else [[k] for k in group]
    return out
