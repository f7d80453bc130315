"""What every case of a discrete run shares: the springs' thresholds, caps, weights and integer scale.

The grid of :mod:`mdr_events.models.discrete`'s stepping, and the springs the first sample of a case touches.
"""

from __future__ import annotations

import sys
from typing import Callable, Sequence

import numpy as np

from mdr_events.models.spring_groups import scaled, unscaled
from mdr_events.models.spring_thresholds import _Threshold


class _Grid:
    """What every case of a run shares: the springs' thresholds, the caps ``ū(m Δx)`` and the integer
    scale of the positions (:class:`~mdr_events.models.spring_groups.SpringGroups`: units of ``2**-bits`` m; ``None``
    where the springs are stepped one by one, :func:`_run_case_per_spring`), Coulomb's ratio per spring and how the
    shifts add up (:mod:`~mdr_events.models.spring_media`: a plain sum on the half-space, weighted on a layer)."""

    def __init__(self, attach: _Threshold, detach: _Threshold, first_touch: float, caps: np.ndarray, bits: int | None,
                 g: np.ndarray | None = None, coulomb: float | np.ndarray = 0.0,
                 sum_shifts: Callable[[np.ndarray], float] = np.sum, weight_prefix: Sequence[int] = range(sys.maxsize),
                 weight_bits: int = 0):
        self.attach, self.detach = attach, detach
        #: Coulomb's part of the caps, ``κ_j max(d − g(x_j), 0)`` with ``κ_j = μ k(x_j)/k_t(x_j)`` (``μ E*/G*`` on the
        #: half-space; 0: the caps are ``caps``), one per spring
        self.g = g
        self.coulomb = np.broadcast_to(np.asarray(coulomb, dtype=float), np.shape(caps[1:]))
        self.has_coulomb = bool(np.any(self.coulomb > 0.0))
        self.sum_shifts = sum_shifts
        #: the groups' integer weights (:class:`~mdr_events.models.spring_groups.SpringGroups`: every spring weighs 1
        #: on the half-space; ``k_t(x_j)/G*`` in units of ``2**-weight_bits`` on a layer), summed below each index
        self.weight_prefix, self.weight_bits = weight_prefix, weight_bits
        self.first_touch = float(first_touch)
        self.attach_threshold = attach.threshold.tolist()
        self.detach_threshold = detach.threshold.tolist()
        self.detach_lowest = detach.lowest
        self.caps = caps.tolist()
        self.n_springs = len(self.caps) - 1
        self.bits = bits
        self.caps_scaled = None if bits is None else scaled(caps, bits)

    def to_float(self, value: int) -> float:
        """An integer in units of ``2**-bits`` m as the nearest float (m)."""
        return unscaled(value, self.bits)

    def sum_to_float(self, value: int) -> float:
        """A weighted sum of shifts in units of ``2**-(bits + weight_bits)`` m as the nearest float (m)."""
        return unscaled(value, self.bits + self.weight_bits)


def _first_count(grid: _Grid, d: np.ndarray, edge: np.ndarray | None) -> int:
    """The springs the first sample touches: counted before (``edge``), or by the attach threshold."""
    if edge is not None:
        return int(edge[0])
    return int(grid.attach.count(d[:1])[0]) if float(d[0]) >= grid.first_touch else 0
