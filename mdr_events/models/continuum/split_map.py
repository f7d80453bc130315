"""The stored anchors of ``"tau0+coulomb"`` with adhesion on a curved indenter: pieces of :class:`~.formulas.Formula`,
the two regions they are read in, and the maps a span reads them from.

The contact ``[0, a]`` is split at the compression boundary ``x_c`` (``g(x_c) = d``): the compressed zone
``[0, x_c]``, whose caps ``σ`` see ``Y − σ κ g(ξ)`` against the level ``x − σ (K a + κ d)``, and the tensile annulus
``[x_c, a]``, whose caps see ``Y`` against ``x − σ K a`` (:class:`Region`; ``derive_adhesive_friction_model``). The
effective anchors are ``clip(Y, bounds)`` in the region a spring is in, as for one region
(:mod:`.anchors`), as long as each level has only pushed since the anchors were last materialised.

A spring that crosses ``x_c`` during a span keeps the anchor it had at that instant, where both regions' caps are
``K a``: the anchor the source region gave it, clipped by the window ``x(τ) ∓ K a(τ)`` of the crossing
(``adhesive_crossing_anchor``). A span therefore reads each region from its own map (:class:`SpanMaps`): the region
the springs cross into holds, over the swept interval, the anchors they will have there; at the span's end the two
maps are joined at ``x_c`` into the stored map again.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING

import numpy as np

from .anchors import Piece
from .formulas import Formula, FormulaPiece, Shape, growth_formula
from .regions import Part, Region
from .split_span_maps import SpanMaps  # (the maps a span reads, a module of their own; the name kept here too)
from .split_sums import clipped_pieces
from .state import Cap

if TYPE_CHECKING:
    from .caps import Caps

__all__ = ["EDGE_SHARE", "SplitAnchorMap", "SpanMaps"]


#: A piece starting this share of the radius inside the shrinking edge has been passed by it (an event's root and the
#: radius carry the rounding of the radius roots, at most MAX_RADIUS_RTOL = 1e-13, and of the event's variable)
EDGE_SHARE = 1e-12


def _part(formula: Formula, start: float, end: float) -> Part:
    """The part of ``formula`` on ``[start, end]`` (no turn inside), with its monotone interval."""
    low, high = formula.monotone_interval(start, end) if not formula.constant else (start, end)
    return Part(formula, start, end, min(low, start), max(high, end))


def _merged(pieces: list[FormulaPiece]) -> list[FormulaPiece]:
    """Neighbouring pieces of one formula as one (after reciprocating cycles a map is a few constants)."""
    out: list[FormulaPiece] = []
    for piece in pieces:
        if piece.end <= piece.start:
            continue
        if out and out[-1].formula == piece.formula and out[-1].end == piece.start:
            out[-1] = dataclasses.replace(out[-1], end=piece.end)
        else:
            out.append(piece)
    return out


class SplitAnchorMap:
    """The stored anchors ``Y(ξ)`` on ``[0, a]`` as contiguous pieces of formulas, the building operations of
    :class:`~.anchors.AnchorMap` (the planner's pieces converted), and the parts a cap of a region sees.

    Parameters
    ----------
    shape : Shape
        The functions the formulas are made of.
    pieces : list of FormulaPiece, optional
        The pieces, ordered.
    """

    def __init__(self, shape: Shape, pieces: list[FormulaPiece] | None = None):
        self.shape = shape
        self.pieces: list[FormulaPiece] = list(pieces or [])
        #: the parts already cut (:meth:`parts`), by shift and extent, with the list of pieces they were cut from:
        #: every operation that changes the map gives it a new list, which makes them stale
        self._parts_cut: tuple[list[FormulaPiece], dict] = (self.pieces, {})
        #: ``(t, x_c)``: the path time and the compression boundary the map was last joined at
        #: (:meth:`SpanMaps.joined`): a span starting then splits its regions exactly there, not at ``x_c`` recomputed
        #: to another rounding
        self.joined_at: tuple[float, float] | None = None

    def copy(self) -> "SplitAnchorMap":
        """A copy that does not change when this map does (pieces are immutable).

        Returns
        -------
        SplitAnchorMap
            The copy.
        """
        return SplitAnchorMap(self.shape, self.pieces)

    # --- building (as AnchorMap) ----------------------------------------------------------------
    def reset(self) -> None:
        """Forget every piece (the contact has come apart)."""
        self.pieces = []

    def extend(self, start: float, piece: Piece) -> None:
        """Forget everything beyond ``start`` and append the planner's ``piece`` (springs attaching).

        Parameters
        ----------
        start : float
            The coordinate (m) from which springs attach.
        piece : Piece
            Their anchors, as the planner gives them.
        """
        formula = growth_formula(self.shape, piece.x0, piece.ratio, piece.d_ref)
        kept = [p if p.end <= start else dataclasses.replace(p, end=start) for p in self.pieces if p.start < start]
        self.pieces = _merged(kept + [FormulaPiece(piece.start, piece.end, formula)])

    def close(self, end: float) -> None:
        """Fix the end of the last piece (the radius a growth stopped at).

        Parameters
        ----------
        end : float
            The radius (m).
        """
        if self.pieces and self.pieces[-1].end != end:
            self.pieces = self.pieces[:-1] + [dataclasses.replace(self.pieces[-1], end=end)]

    def truncate(self, radius: float) -> None:
        """Forget the springs beyond ``radius`` (they have detached).

        Parameters
        ----------
        radius : float
            The contact radius (m).
        """
        self.pieces = [p if p.end <= radius else dataclasses.replace(p, end=radius)
                       for p in self.pieces if p.start < radius] or self.pieces[:1]

    def drop_edge_piece(self, radius: float) -> None:
        """The shrinking edge has passed the start of the last piece, to the root's rounding (:data:`EDGE_SHARE` of
        the radius): forget that piece and end the one before at ``radius`` (a part's boundary inside a piece, a
        turn, is passed by :meth:`truncate` alone).

        Parameters
        ----------
        radius : float
            The contact radius (m).
        """
        if len(self.pieces) > 1 and self.pieces[-1].start >= radius * (1.0 - EDGE_SHARE):
            self.pieces = self.pieces[:-2] + [dataclasses.replace(self.pieces[-2], end=radius)]

    def replaced(self, lower: float, upper: float, formula: Formula) -> "SplitAnchorMap":
        """A new map with the springs on ``[lower, upper]`` given ``formula`` (a crossing's anchors).

        Parameters
        ----------
        lower : float
            The first spring (m).
        upper : float
            The last (m).
        formula : Formula
            Their anchors.

        Returns
        -------
        SplitAnchorMap
            The new map.
        """
        below = [p if p.end <= lower else dataclasses.replace(p, end=lower) for p in self.pieces if p.start < lower]
        above = [p if p.start >= upper else dataclasses.replace(p, start=upper) for p in self.pieces if p.end > upper]
        return SplitAnchorMap(self.shape, _merged(below + [FormulaPiece(lower, upper, formula)] + above))

    def joined(self, other: "SplitAnchorMap", at: float) -> "SplitAnchorMap":
        """This map below ``at`` and ``other`` above it.

        Parameters
        ----------
        other : SplitAnchorMap
            The map above ``at``.
        at : float
            Where they join (m).

        Returns
        -------
        SplitAnchorMap
            The joined map.
        """
        below = [p if p.end <= at else dataclasses.replace(p, end=at) for p in self.pieces if p.start < at]
        above = [p if p.start >= at else dataclasses.replace(p, start=at) for p in other.pieces if p.end > at]
        return SplitAnchorMap(self.shape, _merged(below + above))

    # --- reading -------------------------------------------------------------------------------
    def value(self, xi: float) -> float:
        """``Y(ξ)``; at a boundary, the piece that starts there.

        Parameters
        ----------
        xi : float
            The spring's coordinate (m).

        Returns
        -------
        float
            The stored anchor (m).
        """
        chosen = self.pieces[0]
        for p in self.pieces:
            if p.start <= xi:
                chosen = p
        return chosen.formula.value(xi)

    def parts(self, shift: float, lower: float, upper: float) -> list[Part]:
        """The monotone parts of the anchors seen with ``shift`` (``Y − shift g``) on ``[lower, upper]``, cut at
        the formulas' turns (parts of positive length only).

        Parameters
        ----------
        shift : float
            ``σ κ`` of a compressed cap, 0 in tension.
        lower : float
            The first spring (m).
        upper : float
            The last (m).

        Returns
        -------
        list of Part
            The parts, in order (a new list; the parts themselves are those cut the first time the same shift and
            extent were asked of these pieces: the layouts of a transition and of the span after it share them, and
            what each part reads once, its values at its ends and its scan, is read once for both).
        """
        pieces, cut = self._parts_cut
        if pieces is not self.pieces:
            cut = {}
            self._parts_cut = (self.pieces, cut)
        key = (shift, lower, upper)
        if key not in cut:
            cut[key] = self._cut(shift, lower, upper)
        return list(cut[key])

    def _cut(self, shift: float, lower: float, upper: float) -> list[Part]:
        """:meth:`parts`, cut anew."""
        out = []
        for p in self.pieces:
            start, end = max(p.start, lower), min(p.end, upper)
            if end > start:
                formula = p.formula.seen(shift)
                cuts = [start] + [t for t in formula.turns() if start < t < end] + [end]
                out.extend(_part(formula, low, high) for low, high in zip(cuts[:-1], cuts[1:]))
        return out

    def part_at(self, shift: float, xi: float, direction: float) -> Part:
        """The part of zero length at ``ξ`` that an end moving in ``direction`` (+1: outwards) grows into.

        Parameters
        ----------
        shift : float
            ``σ κ`` of a compressed cap, 0 in tension.
        xi : float
            The end's position (m).
        direction : float
            +1 where the end moves outwards, −1 inwards.

        Returns
        -------
        Part
            The part of zero length.
        """
        if direction > 0:
            chosen = next((p for p in self.pieces if p.start <= xi < p.end), self.pieces[-1])
        else:
            chosen = next((p for p in reversed(self.pieces) if p.start < xi <= p.end), self.pieces[0])
        formula = chosen.formula.seen(shift)
        probe = xi * (1.0 + direction * 1e-12) if xi > 0.0 else max(direction, 0.0) * 1e-300
        low, high = formula.monotone_interval(probe, probe) if not formula.constant else (xi, xi)
        return Part(formula, xi, xi, min(low, xi), max(high, xi))

    def maps(self) -> "SpanMaps":
        """This map read in both regions (between spans every spring's anchors are this map's).

        Returns
        -------
        SpanMaps
            Both regions read from this map.
        """
        return SpanMaps(self, self)

    def clip_caps(self, x: float, caps: "Caps", depth: float, radius: float) -> None:
        """Materialise every spring's play operator, ``Y ← clip(Y, x − ū(ξ), x + ū(ξ))`` with the caps of its region
        (:func:`~.split_sums.clipped_pieces` for each cap and region).

        Parameters
        ----------
        caps : Caps
            The friction law's caps.
        x : float
            The indenter's tangential position (m).
        depth : float
            The depth (m).
        radius : float
            The contact radius (m).
        """
        boundary = min(self.shape.boundary(depth), radius)
        for cap in Cap:
            for region, lower, upper in ((Region.COMPRESSED, 0.0, boundary), (Region.TENSILE, boundary, radius)):
                if upper > lower:
                    level = region.level(cap, x, caps.K, caps.kappa, radius, depth)
                    self.pieces = _merged(clipped_pieces(self, region, cap, level, caps.kappa, lower, upper))

    def tangential_force(self, caps: "Caps", G_star: float, x: float, a: float, depth: float = 0.0) -> float:
        """``F_x`` (N) of these anchors with the window at ``x`` (:meth:`SpanMaps.tangential_force`).

        Parameters
        ----------
        caps : Caps
            The friction law's caps.
        G_star : float
            ``G*`` (Pa).
        x : float
            The indenter's tangential position (m).
        a : float
            The contact radius (m).
        depth : float, default 0.0
            The depth (m).

        Returns
        -------
        float
            ``F_x`` (N).
        """
        return self.maps().tangential_force(caps, G_star, x, a, depth)

    def breaks(self, shift: float, lower: float, upper: float) -> list[float]:
        """The pieces' boundaries and the turns of the anchors seen with ``shift`` between ``lower`` and ``upper``
        (either order): where parts begin and end.

        Parameters
        ----------
        shift : float
            ``σ κ`` of a compressed cap, 0 in tension.
        lower : float
            One end (m).
        upper : float
            The other (m).

        Returns
        -------
        list of float
            The boundaries (m).
        """
        low, high = min(lower, upper), max(lower, upper)
        out = []
        for p in self.pieces:
            if p.end < low or p.start > high:
                continue
            out += [b for b in (p.start, p.end) if low <= b <= high]
            out += [t for t in p.formula.seen(shift).turns() if max(p.start, low) < t < min(p.end, high)]
        return out

    def sliding_length(self, caps: "Caps", x: np.ndarray, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
        """The length (m) of the springs at either cap at several instants (:meth:`SpanMaps.sliding_length`).

        Parameters
        ----------
        caps : Caps
            The friction law's caps.
        x : numpy.ndarray
            The indenter's positions (m).
        depth : numpy.ndarray
            The depths (m).
        radius : numpy.ndarray
            The contact radii (m).

        Returns
        -------
        numpy.ndarray
            The lengths (m).
        """
        return self.maps().sliding_length(caps, x, depth, radius)

    def largest_value(self) -> float:
        """The largest ``|Y|`` at the pieces' starts (m): a length the tolerances are shares of.

        Returns
        -------
        float
            The length (m).
        """
        return max((abs(p.formula.value(p.start)) for p in self.pieces), default=0.0)
