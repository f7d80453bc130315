"""The force's quadrature of the per-spring route (:mod:`.play_springs`) at many times at once: the panels' ends of
all the times in one flat array (:class:`_Breaks`, sorted by time, then radius), Gauss–Legendre's rule on each panel,
and what an evaluation returns at the nodes (:class:`_Quadrature`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["NODES", "EDGE_SHARE"]

#: Gauss–Legendre nodes per panel (between kinks the anchor is smooth: the rule's error falls as ``(width)^(2n)``).
NODES = 12
#: The centre's and the edge's provenance are read this share of the radius inside them, once per evaluation (a stick
#: zone left between the edge and the last node, 3e-4 of the radius before full slip along A 20°, was 5e-8 of the
#: force off): a zone narrower than this share is missed, by about the square of its width (5e-8 at 3.3e-4, below
#: 1e-12 at this share); nearer the edge the springs' provenance flips by round-off where a shrinking contact's edge
#: springs lie on their window's edge (one no kink search resolves), and the spring at ``a`` itself attaches at ``t``.
EDGE_SHARE = 1e-6
_GAUSS = np.polynomial.legendre.leggauss(NODES)


class _Quadrature(NamedTuple):
    """The quadrature at many times (:meth:`PlaySprings._quadratures`): the nodes in the order of their times, their
    weights, anchors, provenance and times' indices, the provenance at the probes asked, and the springs' ``g`` and
    ``k_t/G*`` at the nodes (read with the anchors: not read again)."""

    nodes: np.ndarray
    weights: np.ndarray
    anchor: np.ndarray
    label: np.ndarray
    group: np.ndarray
    probed: np.ndarray
    profile: np.ndarray
    weight: np.ndarray


class _Breaks(NamedTuple):
    """The panels' ends of the quadratures at many times, flat: sorted by their time's index, then by radius."""

    #: the radii (m)
    values: np.ndarray
    #: the index of each one's time
    group: np.ndarray
    #: whether each one is a kink found (:meth:`PlaySprings._kinks`)
    kink: np.ndarray

    def of(self, groups: np.ndarray) -> "_Breaks":
        """The breaks of the times where ``groups`` (a mask over the times) holds."""
        keep = groups[self.group]
        return _Breaks(self.values[keep], self.group[keep], self.kink[keep])

    def gauss(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """:func:`_gauss` on every time's panels: the nodes, the weights, each node's time's index and its panel (the
        index of the break at its lower end)."""
        panel = np.flatnonzero(self.group[:-1] == self.group[1:])
        nodes, weights = _gauss_panels(self.values[panel], self.values[panel + 1])
        return nodes, weights, np.repeat(self.group[panel], NODES), np.repeat(panel, NODES)

    def with_ends(self, nodes: np.ndarray, group: np.ndarray, panel: np.ndarray) -> tuple[np.ndarray, ...]:
        """The nodes of :meth:`gauss` with each time's centre and edge probes (:data:`EDGE_SHARE` inside them) first
        and last: the points, their times' indices, their panels and which of them are nodes."""
        first = np.flatnonzero(np.concatenate([[True], self.group[1:] != self.group[:-1]]))
        last = np.concatenate([first[1:], [self.values.size]]) - 1
        radius = self.values[last]
        ends = (radius * EDGE_SHARE, radius * (1.0 - EDGE_SHARE))
        points = np.concatenate([ends[0], nodes, ends[1]])
        groups = np.concatenate([self.group[first], group, self.group[first]])
        place = np.concatenate([np.full(first.size, -1), np.arange(nodes.size), np.full(first.size, nodes.size)])
        order = np.lexsort((place, groups))
        panels = np.concatenate([first, panel, last - 1])
        is_node = np.concatenate([np.zeros(first.size, bool), np.ones(nodes.size, bool), np.zeros(first.size, bool)])
        return points[order], groups[order], panels[order], is_node[order]

    def with_kinks(self, found: np.ndarray, group: np.ndarray) -> "_Breaks":
        """The breaks with the kinks ``found`` at the times of indices ``group`` added (once each)."""
        values, groups = np.concatenate([self.values, found]), np.concatenate([self.group, group])
        kink = np.concatenate([self.kink, np.ones(found.size, bool)])
        order = np.lexsort((values, groups))
        values, groups, kink = values[order], groups[order], kink[order]
        starts = np.flatnonzero(np.concatenate([[True], (groups[1:] != groups[:-1]) | (values[1:] != values[:-1])]))
        return _Breaks(values[starts], groups[starts], np.logical_or.reduceat(kink, starts))


def _gauss(breaks: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The nodes and weights of Gauss–Legendre's rule on each panel between ``breaks``."""
    return _gauss_panels(breaks[:-1], breaks[1:])


def _gauss_panels(lows: np.ndarray, highs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The nodes and weights of Gauss–Legendre's rule on each panel ``[lows, highs]``."""
    nodes = (0.5 * (highs - lows)[:, None] * (_GAUSS[0][None, :] + 1.0) + lows[:, None]).ravel()
    return nodes, (0.5 * (highs - lows)[:, None] * _GAUSS[1][None, :]).ravel()
