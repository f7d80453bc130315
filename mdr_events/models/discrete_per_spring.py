"""The discrete model's rules stepped spring by spring, as stated: the reference of the grouped stepping.

Every spring's shift a float moved by each step and clipped, ``Σ u`` a plain sum (or the layer's weighted one): the
reference of :mod:`mdr_events.models.discrete`'s stepping in groups, and the run of the friction laws with Coulomb's
part, whose caps differ from spring to spring.
"""

from __future__ import annotations

import numpy as np

from mdr_events.models.discrete_grid import _Grid, _first_count


def _run_case_per_spring(grid: _Grid, x: np.ndarray, d: np.ndarray, time: np.ndarray, last: int,
                         last_entry: float, counts: np.ndarray, sums: np.ndarray, sliding: np.ndarray,
                         edge: np.ndarray | None = None) -> int:
    """The rules stepped spring by spring, as stated (:mod:`mdr_events.models.discrete`): the reference of
    :func:`~mdr_events.models.discrete._run_case`.

    Same arguments and outputs; every spring's shift is a float moved by each step and clipped, and ``Σ u`` a plain
    sum: O(springs) numpy work per step, where :func:`~mdr_events.models.discrete._run_case` is O(1). It also runs
    the friction laws with Coulomb's part (``grid.has_coulomb``), whose caps differ from spring to spring: ``ū_j =
    ū(m Δx) + κ_j max(d − g(x_j), 0)``; a spring whose cap is 0 slides. On a layer of finite thickness
    (:class:`~mdr_events.models.spring_media.LayerSprings`) the springs differ and ``sums`` is their weighted sum
    ``Σ (k_t(x_j)/G*) u_j`` (``grid.sum_shifts``).
    """
    shift = np.zeros(grid.n_springs)
    m = _first_count(grid, d, edge)
    counts[0], sums[0], sliding[0] = m, 0.0, 0
    k = 1
    while k <= last:
        depth = d[k:k + 1]
        if edge is not None:  # a rate-dependent edge: counted before
            m_new = int(edge[k])
        elif d[k] > d[k - 1]:
            if m:
                m_new = int(grid.attach.grow(np.array([m]), depth)[0])
            else:
                m_new = int(grid.attach.count(depth)[0]) if d[k] >= grid.first_touch else 0
        elif d[k] < d[k - 1]:
            m_new = int(grid.detach.shrink(np.array([m]), depth)[0])
        else:
            m_new = m
        kept = min(m, m_new)
        shift[:kept] += x[k] - x[k - 1]
        shift[kept:] = 0.0  # detached springs forget their shift, new ones attach with none
        cap = grid.caps[m_new]
        if grid.has_coulomb:
            cap = cap + grid.coulomb[:m_new] * np.maximum(d[k] - grid.g[:m_new], 0.0)
        in_contact = shift[:m_new]
        np.minimum(in_contact, cap, out=in_contact)
        np.maximum(in_contact, -cap, out=in_contact)
        counts[k], sums[k] = m_new, grid.sum_shifts(in_contact)
        if grid.has_coulomb:
            sliding[k] = np.count_nonzero((np.abs(in_contact) >= cap) | ~(cap > 0.0))
        else:
            sliding[k] = np.count_nonzero(np.abs(in_contact) >= cap) if cap > 0.0 else m_new
        if m and not m_new and last_entry <= time[k - 1]:
            last = k
        m = m_new
        k += 1
    return last
