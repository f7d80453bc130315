"""The anchor map ``Y(ξ)``: where each spring in contact would carry no tangential shift.

A spring attached at time ``t_ξ`` has ``Y = x(t_ξ)``; its shift is ``u = min(x − Y(ξ), ū(a))``
with ``ū(a) = π a τ0/(2G*)`` (13). For growth on a path segment
``Y(ξ) = x_s + (v_x/v_d)(d_0(ξ) − d_s)`` with ``d_0`` the ``Δγ0`` branch. For paths whose
tangential motion does not reverse, ``Y`` is non-decreasing in ``ξ``, so the sliding springs form
one zone ``[0, c]`` bounded by the slip front ``Y(c) = x − ū(a)``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .branch import Branch


@dataclass(frozen=True)
class Piece:
    """``Y(ξ) = x0 + ratio (d0(ξ) − d_ref)`` on ``[start, end]`` (``ratio = 0``: constant ``x0``)."""

    start: float
    end: float
    x0: float
    ratio: float = 0.0
    d_ref: float = 0.0

    def same_growth(self, other: "Piece") -> bool:
        """Whether ``other`` continues the growth of this piece (the same ``Y``)."""
        return (self.x0, self.ratio, self.d_ref) == (other.x0, other.ratio, other.d_ref)


class AnchorMap:
    """The non-decreasing anchor map ``Y(ξ)`` on ``[0, a]`` as a list of pieces.

    Parameters
    ----------
    attach : Branch
        The ``Δγ0`` branch, along which springs attach (``d0``).
    rtol : float
        Relative accuracy of the slip front's root.
    pieces : list of Piece, optional
        The pieces, ordered by ``start``.
    """

    def __init__(self, attach: Branch, rtol: float, pieces: list[Piece] | None = None):
        self.attach = attach
        self.rtol = rtol
        self.pieces: list[Piece] = list(pieces or [])

    def copy(self) -> "AnchorMap":
        """An independent copy (pieces are immutable)."""
        return AnchorMap(self.attach, self.rtol, self.pieces)

    def reset(self) -> None:
        self.pieces = []

    def extend(self, start: float, piece: Piece) -> None:
        """Forget everything beyond ``start`` and append ``piece`` (springs attaching from ``start``)."""
        kept = [dataclasses.replace(p, end=min(p.end, start)) for p in self.pieces if p.start < start]
        if kept and kept[-1].same_growth(piece):
            kept[-1] = dataclasses.replace(kept[-1], end=piece.end)  # the same growth resumed: one piece
        else:
            kept.append(piece)
        self.pieces = kept

    def close(self, end: float) -> None:
        """Fix the end of the last piece (the radius the growth stopped at)."""
        if self.pieces:
            self.pieces[-1] = dataclasses.replace(self.pieces[-1], end=end)

    def _value(self, p: Piece, xi: float) -> float:
        return p.x0 if p.ratio == 0.0 else p.x0 + p.ratio * (self.attach.depth(xi) - p.d_ref)

    def value(self, xi: float) -> float:
        """``Y(ξ)``; where ``Y`` jumps at a piece boundary, the value of the piece that starts there."""
        chosen = self.pieces[0]
        for p in self.pieces:
            if p.start <= xi:
                chosen = p
        return self._value(chosen, min(max(xi, chosen.start), chosen.end))

    def end_value(self, index: int, radius: float) -> float:
        """``Y`` at the end of piece ``index`` (the last piece ends at ``radius``), from that piece."""
        p = self.pieces[index]
        return self._value(p, radius if index == len(self.pieces) - 1 else min(p.end, radius))

    def integral(self, lower: float, upper: float) -> float:
        """``∫_lower^upper Y(ξ) dξ``."""
        total = 0.0
        for i, p in enumerate(self.pieces):
            end = p.end if i < len(self.pieces) - 1 else max(p.end, upper)
            lo, hi = max(lower, p.start), min(upper, end)
            if hi <= lo:
                continue
            total += p.x0 * (hi - lo)
            if p.ratio != 0.0:
                total += p.ratio * (self.attach.integral(hi) - self.attach.integral(lo) - p.d_ref * (hi - lo))
        return total

    def front(self, level: float, radius: float) -> float:
        """Slip front ``c = sup{ξ ≤ a: Y(ξ) <= level}`` (0 if none, ``a`` if all); one point of :meth:`fronts`."""
        return float(self.fronts(np.array([level]), np.array([radius]))[0])

    def fronts(self, levels: np.ndarray, radii: np.ndarray) -> np.ndarray:
        """Slip fronts ``c = sup{ξ ≤ a: Y(ξ) <= level}`` for arrays of levels and radii (vectorised over
        points, looped over pieces)."""
        levels = np.asarray(levels, dtype=float)
        radii = np.asarray(radii, dtype=float)
        fronts = radii.copy()  # a point no piece stops slides everywhere
        done = ~(radii > 0)
        fronts[done] = 0.0
        last = len(self.pieces) - 1
        for i, p in enumerate(self.pieces):
            end = radii if i == last else np.minimum(p.end, radii)
            stops_before = ~done & (self._value(p, p.start) > levels)
            fronts[stops_before] = p.start
            done |= stops_before
            end_values = p.x0 + p.ratio * (self.attach.depths(end) - p.d_ref) if p.ratio else np.full_like(end, p.x0)
            within = ~done & (end_values > levels)
            if p.ratio and within.any():
                xi = self.attach.radii(p.d_ref + (levels[within] - p.x0) / p.ratio)
                fronts[within] = np.minimum(np.maximum(np.nan_to_num(xi, nan=p.start), p.start), end[within])
            elif within.any():
                fronts[within] = end[within]
            done |= within | (end >= radii)
        return fronts

    def piece_of_front(self, level: float, radius: float, tolerance: float = 0.0) -> int:
        """Index of the piece that holds the slip front at ``level``: among the pieces that start
        within the contact (``start <= radius``: a growth piece about to start counts), the first
        whose value at its end (or at the radius) exceeds the level by more than ``tolerance`` (a
        front at a piece's end to rounding is in the next); the last of them if none does."""
        chosen = 0
        for i, p in enumerate(self.pieces):
            if p.start > radius:
                break
            chosen = i
            if self._value(p, min(p.end, radius)) > level + tolerance:
                return i
        return chosen

    def front_in_piece(self, index: int, level: float) -> float:
        """The slip front continued smoothly within the growth piece ``index`` (the inverse of its
        ``Y``, unclipped); below the branch's fold there is no continuation and it holds the
        piece's start."""
        p = self.pieces[index]
        xi = self.attach.radius(p.d_ref + (level - p.x0) / p.ratio, self.rtol)
        return xi if xi == xi else p.start

    def restick(self, front: float, anchor: float) -> None:
        """Sliding springs in ``[0, front]`` stick again with the common anchor ``x − ū``."""
        rest = [dataclasses.replace(p, start=max(p.start, front)) for p in self.pieces if p.end > front]
        self.pieces = [Piece(0.0, front, anchor)] + rest

    def restick_slip_zone(self, level: float, radius: float) -> None:
        """The springs sliding at ``level = x − ū`` (``Y <= level``, the slip zone ``[0, c]``) stick again
        with the anchor ``level``, where their shift is the cap."""
        self.restick(self.front(level, radius) if radius > 0 else 0.0, level)

    def tangential_force(self, K: float, G_star: float, x: float, a: float) -> float:
        """``F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]`` with ``ū = K a`` and the slip front ``c``: the
        force of this map, without integration (0 out of contact)."""
        if not a > 0:
            return 0.0
        c = self.front(x - K * a, a)
        return 2.0 * G_star * (c * K * a + x * (a - c) - self.integral(c, a))
