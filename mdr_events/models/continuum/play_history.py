"""The contact radius along a path as the per-spring route reads it (:mod:`.play_springs`): without adhesion
``a = g⁻¹(d)`` (:class:`DepthHistory`), with adhesion the spans' run with frictionless springs
(:class:`SpanHistory`). Each gives the radius at any time, where it jumps (both sides), the intervals where it moves
smoothly, and each spring's last attachment before a time.
"""

from __future__ import annotations

import numpy as np

__all__ = ["DepthHistory", "SpanHistory", "JUMP_ROUND_OFF"]

#: Radii of two spans' common end within this share of each other are one radius, not a jump.
JUMP_ROUND_OFF = 1e-12


class DepthHistory:
    """The radius of a contact without adhesion: ``a = g⁻¹(d)``, springs attaching where ``d`` rises through
    ``g(ξ)``; no jumps.

    Parameters
    ----------
    line : SpringLine
        The springs.
    path : Path
        The path.
    """

    def __init__(self, line: SpringLine, path) -> None:
        self.line, self.path = line, path
        self.corner_t = np.asarray(path.corner_times, dtype=float)
        self.corner_d = np.asarray(path.waypoints[:, 1], dtype=float)
        #: ``(time, radius before, radius after)`` where the radius jumps (none)
        self.jumps: list[tuple[float, float, float]] = []
        #: whether springs in contact can be in tension (no: every spring in contact is compressed)
        self.adhesive = False

    def radii(self, times) -> np.ndarray:
        """``a(t)`` (m) at ``times`` (s, path clock)."""
        return self.line.radius(np.interp(times, self.corner_t, self.corner_d))

    def pieces(self) -> list[tuple[float, float]]:
        """The intervals in contact on which the radius is smooth: each segment's part at ``d > 0``."""
        out = []
        for k in range(len(self.corner_t) - 1):
            (t0, t1), (d0, d1) = self.corner_t[k:k + 2], self.corner_d[k:k + 2]
            if max(d0, d1) <= 0.0 or d0 == d1:
                continue
            surface = t0 + (t1 - t0) * (0.0 - d0) / (d1 - d0)
            out.append((max(t0, surface), t1) if d1 > d0 else (t0, min(t1, surface)))
        return out

    def attach(self, xi: np.ndarray, t) -> tuple[np.ndarray, np.ndarray]:
        """The last time up to ``t`` (one time, or one per spring) at which each spring attached (``d`` rising through
        ``g(ξ)``) and the segment it attached on (−1: the path started with it in contact)."""
        g = self.line.profile(xi)
        when, segment = np.full(xi.shape, -np.inf), np.full(xi.shape, -2)
        if self.corner_d[0] > 0.0:
            inside = g < self.corner_d[0]
            when[inside], segment[inside] = self.corner_t[0], -1
        for k in range(len(self.corner_t) - 1):
            (t0, t1), (d0, d1) = self.corner_t[k:k + 2], self.corner_d[k:k + 2]
            if not d1 > d0 or t0 > np.max(t):
                continue
            at = t0 + (t1 - t0) * (g - d0) / (d1 - d0)
            take = (g >= d0) & (g < d1) & (at <= t)
            when[take], segment[take] = at[take], k
        return when, segment

    def breaks(self, t: float) -> np.ndarray:
        """The radii (m) inside the contact at ``t`` where the force's quadrature splits its panels besides the kinks
        it finds: none (the attachment is smooth in ``ξ`` between the jumps and pieces, which the kinks mark)."""
        return np.empty(0)


class SpanHistory:
    """The radius of an adhesive contact as the spans' run gives it (:class:`~.solution.PathSolution` with
    frictionless springs): springs attach where the radius grows through them along a ``Δγ0`` branch (at
    ``d = d₀(ξ)``, the branch's depth of the radius ``ξ``) or jumps past them (the jump-in), and the radius jumps at
    the spans' boundaries where it does (a drop onto the ``Δγ1`` branch).

    Parameters
    ----------
    solution : PathSolution
        The run of the contact with frictionless springs.
    """

    def __init__(self, solution) -> None:
        from .solution import _span_radius
        from .state import Regime

        self.solution, self._regime = solution, Regime
        self._span_radius = _span_radius
        self.adhesive = True
        self._spans = [(span.t_start, span.t_end, span) for span in solution.spans]  # (on the path's clock)
        self.jumps = []
        #: each span's radius at its ends (read once: ``attach`` asks at every evaluation)
        self._span_ends = [self._ends(span, low, high) for low, high, span in self._spans]
        previous = 0.0
        for (low, _, _), (first, last) in zip(self._spans, self._span_ends):
            if abs(first - previous) > JUMP_ROUND_OFF * max(abs(first), abs(previous)):
                self.jumps.append((low, previous, first))
            previous = last

    def _ends(self, span, low: float, high: float) -> tuple[float, float]:
        if span.regime is self._regime.NONE:
            return 0.0, 0.0
        radius = self._span_radius(self.solution.model, span, span.segment.d(np.array([low, high])))
        return float(radius[0]), float(radius[1])

    def radii(self, times) -> np.ndarray:
        """``a(t)`` (m) at ``times`` (s, path clock; the later span's at a boundary), 0 out of contact."""
        from .solution import contact_radii

        times = np.asarray(times, dtype=float)
        inside = (times >= self._spans[0][0]) & (times <= self._spans[-1][1])
        out = np.zeros(times.shape)
        if np.any(inside):
            out[inside] = contact_radii(self.solution, times[inside] - self.solution.t_contact)
        return out

    def pieces(self) -> list[tuple[float, float]]:
        """The spans in contact whose radius moves (growing or shrinking)."""
        moving = (self._regime.GROWING, self._regime.SHRINKING)
        return [(low, high) for low, high, span in self._spans if span.regime in moving and high > low]

    def attach(self, xi: np.ndarray, t) -> tuple[np.ndarray, np.ndarray]:
        """The last time up to ``t`` (one time, or one per spring) at which each spring attached, and the span it
        attached in (as a code)."""
        t = np.broadcast_to(np.asarray(t, dtype=float), np.shape(xi))
        latest = float(np.max(t, initial=-np.inf))
        when, code = np.full(xi.shape, -np.inf), np.full(xi.shape, -2)
        for index, (time, before, after) in enumerate(self.jumps):
            take = _beyond(xi, before) & (xi <= after) & (time <= t)
            when[take], code[take] = time, 2 * index
        grow = self.solution.model.grow
        for index, (low, high, span) in enumerate(self._spans):
            if span.regime is not self._regime.GROWING or low > latest:
                continue
            first, last = self._span_ends[index]
            if index and self._grows_on(index, first):  # (no ulp between two growing spans, each end its own span's
                first = min(first, self._span_ends[index - 1][1])  # root, nor across a pinned one between them)
            take = _beyond(xi, first) & (xi <= last)
            if not np.any(take):
                continue
            depth = np.asarray(grow.depths(xi[take]), dtype=float)
            d0, d1 = span.segment.d(np.array([low, high]))
            at = low + (high - low) * (depth - d0) / (d1 - d0)
            late = at <= t[take]
            rows = np.flatnonzero(take)[late]
            later = at[late] >= when[rows]
            when[rows[later]], code[rows[later]] = at[late][later], 2 * index + 1
        return when, code

    def breaks(self, t: float) -> np.ndarray:
        """The radii (m) inside the contact at ``t`` where the force's quadrature splits its panels besides the kinks
        it finds: none (the attachment is smooth in ``ξ`` between the jumps and pieces, which the kinks mark)."""
        return np.empty(0)

    def _grows_on(self, index: int, first: float) -> bool:
        """Whether the growing span ``index`` (its radius at its start ``first``) goes on from the span before it: a
        growing one, or a pinned one whose radius is ``first`` within :data:`JUMP_ROUND_OFF` (issue 32 round 27 Z5:
        the pinned radius the last growth's end, the new growth's start its own root a few ulps above, the springs
        between them attached in neither, a RuntimeError)."""
        regime = self._spans[index - 1][2].regime
        return regime is self._regime.GROWING or (
            regime is self._regime.PINNED and abs(first - self._span_ends[index - 1][1]) <= JUMP_ROUND_OFF * first)


def _beyond(xi: np.ndarray, radius: float) -> np.ndarray:
    """The springs a radius growing from ``radius`` reaches: beyond it, and from 0 the centre spring too (a first
    contact or a re-contact takes ``ξ = 0``)."""
    return (xi > radius) | ((radius == 0.0) & (xi == 0.0))
