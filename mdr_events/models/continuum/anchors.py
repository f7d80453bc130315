"""The stored anchor map ``Y(ξ)`` of the springs in contact, and what is read off it.

A spring attached at time ``t_ξ`` gets the anchor ``Y = x(t_ξ)``. The cap (13) acts on both sides:
the anchors are kept inside the window ``[x − ū(a), x + ū(a)]`` (a play operator per spring, all
sharing ``x`` and ``ū = K a``). The map stores the anchors as last *materialised*; the effective
anchors are ``clip(Y, x − ū, x + ū)`` as long as each level has only pushed since (the window's
bounds move outward-pushing only while springs sit at them: a level that turns back re-sticks its
springs, and the solver then materialises the clip, :meth:`AnchorMap.clip`).

The map is a list of contiguous pieces on ``[0, a]``, each constant or one growth on a path
segment, ``Y(ξ) = x_s + (v_x/v_d)(d_0(ξ) − d_s)`` with ``d_0`` the ``Δγ0`` branch: monotone in ``ξ``
(increasing for ``v_x > 0``). With reversals the map is not monotone; each cap's slip zone is then
a union of intervals, found piece by piece.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .branch import Branch
from .state import Cap

if TYPE_CHECKING:
    from .caps import Caps
    from .media import HalfSpaceMedium


@dataclass(frozen=True)
class Piece:
    """``Y(ξ) = x0 + ratio (d0(ξ) − d_ref)`` on ``[start, end]`` (``ratio = 0``: constant ``x0``).

    Parameters
    ----------
    start : float
        The first spring's coordinate ``ξ`` (m).
    end : float
        The last spring's coordinate (m).
    x0 : float
        The anchor (m) at the depth ``d_ref``; a constant piece's value.
    ratio : float, default 0.0
        ``v_x / v_d`` of the path segment the springs attached on (0: a constant piece).
    d_ref : float, default 0.0
        The depth (m) at which the indenter was at ``x0``.
    """

    start: float
    end: float
    x0: float
    ratio: float = 0.0
    d_ref: float = 0.0

    @property
    def constant(self) -> bool:
        """Whether the piece is constant (``ratio == 0``)."""
        return self.ratio == 0.0

    def at_depth(self, depth):
        """``Y`` where the attachment branch's depth is ``depth``: ``x0 + ratio (depth − d_ref)`` (the one place the
        piece's expression is written; a growth piece's value, for a float or an array of depths).

        Parameters
        ----------
        depth : float or numpy.ndarray
            The attachment branch's depth ``d0(ξ)`` (m) at the springs read.

        Returns
        -------
        float or numpy.ndarray
            The anchor (m).
        """
        return self.x0 + self.ratio * (depth - self.d_ref)

    def same_growth(self, other: "Piece") -> bool:
        """Whether ``other`` continues the growth of this piece (the same ``Y``).

        Parameters
        ----------
        other : Piece
            The piece that follows.

        Returns
        -------
        bool
            ``True`` if ``x0``, ``ratio`` and ``d_ref`` are equal.
        """
        return (self.x0, self.ratio, self.d_ref) == (other.x0, other.ratio, other.d_ref)

    def rises_towards(self, cap: Cap) -> bool:
        """Whether ``cap · Y`` increases with ``ξ`` on this (growth) piece.

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        bool
            ``True`` if ``cap · ratio > 0``.
        """
        return self.ratio > 0 if cap > 0 else self.ratio < 0


class _Prefix(Sequence):
    """The first ``length`` entries of a list, read-only: an :class:`AnchorMap` snapshot's pieces."""

    def __init__(self, items: list[Piece], length: int):
        self._items, self._length = items, length

    def __len__(self) -> int:
        return self._length

    def __getitem__(self, index):
        if isinstance(index, slice):
            return self._items[: self._length][index]
        if index < 0:
            index += self._length
        if not 0 <= index < self._length:
            raise IndexError("piece index out of range")
        return self._items[index]

    def __iter__(self):
        return iter(self._items[: self._length])


class AnchorMap:
    """The stored anchors ``Y(ξ)`` on ``[0, a]`` as a list of contiguous pieces.

    Parameters
    ----------
    attach : Branch
        The ``Δγ0`` branch, along which springs attach (``d0``).
    rtol : float
        Relative accuracy of the radius roots (slip fronts).
    pieces : list of Piece, optional
        The pieces, ordered by ``start``.
    """

    def __init__(self, attach: Branch, rtol: float, pieces: Sequence[Piece] | None = None):
        self.attach = attach
        self.rtol = rtol
        #: the depth of the branch's largest radius (its :attr:`~.branch.Branch.ceiling`): a level reached deeper lies
        #: past every spring of a piece (:meth:`inverse`)
        self.deepest = attach.depth(attach.ceiling) if math.isfinite(attach.ceiling) else math.inf
        self.pieces: Sequence[Piece] = list(pieces or [])
        #: the first this many entries of ``pieces`` are seen by a snapshot (:meth:`copy`): not changed in place
        self._shared = 0
        #: the values at both ends of the pieces seen (pieces are immutable; shared with the snapshots)
        self._end_values: dict[Piece, tuple[float, float]] = {}

    def copy(self) -> "AnchorMap":
        """A snapshot that does not change when this map does (pieces are immutable).

        It shares this map's list, seeing its first ``len`` entries; this map appends in place but
        replaces the list before it changes a shared entry. A path of N growth segments then keeps N
        snapshots in O(N) memory, not O(N²).

        Returns
        -------
        AnchorMap
            The snapshot.
        """
        snapshot = AnchorMap(self.attach, self.rtol)
        snapshot.pieces = _Prefix(self.pieces, len(self.pieces))
        snapshot._end_values = self._end_values
        self._shared = len(self.pieces)
        return snapshot

    def _own(self, changed: int) -> list[Piece]:
        """The pieces as a list this map may change from index ``changed`` on (copied if a snapshot sees it)."""
        if not isinstance(self.pieces, list) or changed < self._shared:
            self.pieces, self._shared = list(self.pieces), 0
        return self.pieces

    def _set_last(self, piece: Piece) -> None:
        """Replace the last piece (in place unless a snapshot sees it)."""
        self._own(len(self.pieces) - 1)[-1] = piece

    # --- building -------------------------------------------------------------------------------
    def reset(self) -> None:
        """Forget every piece (the contact has come apart)."""
        self.pieces, self._shared = [], 0

    def extend(self, start: float, piece: Piece) -> None:
        """Forget everything beyond ``start`` and append ``piece`` (springs attaching from ``start``).

        Parameters
        ----------
        start : float
            The coordinate (m) from which springs attach.
        piece : Piece
            Their anchors (merged with the last piece where it continues its growth).
        """
        pieces = self.pieces
        if not pieces or pieces[-1].start < start and pieces[-1].end <= start:  # nothing to forget: the tail only
            if pieces and pieces[-1].same_growth(piece):
                self._set_last(dataclasses.replace(pieces[-1], end=piece.end))  # the same growth resumed
            else:
                self._own(len(pieces)).append(piece)
            return
        kept = [p if p.end <= start else dataclasses.replace(p, end=start) for p in pieces if p.start < start]
        if kept and kept[-1].same_growth(piece):
            kept[-1] = dataclasses.replace(kept[-1], end=piece.end)  # the same growth resumed: one piece
        else:
            kept.append(piece)
        self.pieces, self._shared = kept, 0

    def close(self, end: float) -> None:
        """Fix the end of the last piece (the radius the growth stopped at).

        Parameters
        ----------
        end : float
            The radius (m).
        """
        if self.pieces and self.pieces[-1].end != end:
            self._set_last(dataclasses.replace(self.pieces[-1], end=end))

    def truncate(self, radius: float) -> None:
        """Forget the springs beyond ``radius`` (they have detached), and a piece that starts at ``radius``: it holds
        none (as ``SplitAnchorMap.truncate`` does). Such a piece is left by a
        growth that stopped where it started (a growing span of an ulp, up to a corner's time, before a pinned one);
        kept, its value at the edge was the layout's target on a pinned span, whose edge never reaches into it: the
        level met that target, the layout saw no spring there, and the event fired again at every restart ("made no
        progress", round twenty-two V5).

        Parameters
        ----------
        radius : float
            The contact radius (m).
        """
        pieces = self.pieces
        if pieces and (pieces[-1].end > radius or (len(pieces) > 1 and pieces[-1].start >= radius)):
            self.pieces = [p if p.end <= radius else dataclasses.replace(p, end=radius)
                           for p in pieces if p.start < radius]
            self._shared = 0

    def drop_edge_piece(self, radius: float) -> None:
        """The shrinking edge has passed the start of the last piece (to the root's rounding): forget that
        piece, and any before it that starts beyond ``radius`` (a sliver left by the rounding of an earlier
        transition: ended at ``radius``, it had a negative length, and its zone's target was met again at every
        restart, "made no progress"), and end the last one kept at ``radius``.

        Parameters
        ----------
        radius : float
            The contact radius (m).
        """
        if len(self.pieces) > 1:
            kept = [piece for piece in self.pieces[:-1] if piece.start < radius] or [self.pieces[0]]
            self.pieces, self._shared = kept[:-1] + [dataclasses.replace(kept[-1], end=radius)], 0

    def clip(self, lower: float, upper: float, radius: float) -> None:
        """Materialise the play operator: ``Y ← clip(Y, lower, upper)`` on ``[0, radius]``.

        A growth piece is split where it crosses a bound; neighbouring constant pieces of equal value
        are merged (after a few reciprocating cycles the whole map is one or two constants).

        Parameters
        ----------
        lower : float
            The window's lower bound ``x − ū`` (m; ``-inf``: none).
        upper : float
            The window's upper bound ``x + ū`` (m; ``+inf``: none).
        radius : float
            The contact radius (m): the springs beyond it are dropped.
        """
        clipped: list[Piece] = []
        for p in self.in_contact(radius):
            end = min(p.end, radius)
            if p.constant:
                parts = [Piece(p.start, end, min(max(p.x0, lower), upper))]
            else:
                # an infinite bound (a one-sided clip) cuts nothing: its cut at the start makes an empty part
                cuts = sorted(min(max(self.inverse(p, bound), p.start), end) if math.isfinite(bound) else p.start
                              for bound in (lower, upper))
                edges = [p.start, cuts[0], cuts[1], end]
                parts = []
                for lo, hi in zip(edges[:-1], edges[1:]):
                    if hi > lo:
                        middle = self.piece_value(p, 0.5 * (lo + hi))
                        if lower <= middle <= upper:
                            parts.append(dataclasses.replace(p, start=lo, end=hi))
                        else:
                            parts.append(Piece(lo, hi, lower if middle < lower else upper))
            for part in parts:
                if clipped and clipped[-1].constant and part.constant and clipped[-1].x0 == part.x0:
                    clipped[-1] = dataclasses.replace(clipped[-1], end=part.end)
                else:
                    clipped.append(part)
        self.pieces, self._shared = clipped, 0

    def clip_caps(self, x: float, caps: "Caps", depth: float, radius: float) -> None:
        """Materialise the play operator of every spring: ``Y ← clip(Y, x − ū(ξ), x + ū(ξ))`` on ``[0, radius]``
        with the friction law's caps ``ū(ξ) = K a + κ (d − g(ξ))`` (:class:`~.caps.Caps`): :meth:`clip` for
        ``κ = 0``, else a one-sided clip per cap in the coordinates the cap sees (:meth:`seen_by`).

        Parameters
        ----------
        x : float
            The indenter's tangential position (m).
        caps : Caps
            The friction law's caps.
        depth : float
            The depth ``d`` (m).
        radius : float
            The contact radius (m).
        """
        shift = caps.centre_shift(radius, depth)
        if caps.kappa == 0.0:
            self.clip(x - shift, x + shift, radius)
            return
        for cap, lower, upper in ((Cap.POSITIVE, x - shift, math.inf), (Cap.NEGATIVE, -math.inf, x + shift)):
            seen = self.seen_by(cap, caps.kappa)
            seen.clip(lower, upper, radius)
            self.pieces, self._shared = seen.seen_by(cap, -caps.kappa).pieces, 0

    def seen_by(self, cap: Cap, kappa: float) -> "AnchorMap":
        """The anchors as ``cap`` compares them with its level under Coulomb's caps: ``Z = Y − cap κ g(ξ)``
        (this map itself for ``κ = 0``).

        A spring is at the cap where ``cap (x − Y) >= K a + κ (d − g)``, i.e. ``cap Z <= cap (x − cap (K a + κ d))``:
        a level the same for every spring, as with ``τ0`` alone. Without adhesion springs attach along
        ``d0 = g``, so a piece ``x0 + r (g − d_ref)`` is seen as ``x0 − cap κ d_ref + (r − cap κ)(g − d_ref)``: a
        piece of the same kind, monotone in ``ξ``. Under the flat punch's face ``g = 0``: the map itself.

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.
        kappa : float
            ``κ = μ E*/G*``.

        Returns
        -------
        AnchorMap
            The map of ``Z`` (a new one; this map for ``κ = 0`` or the flat punch).
        """
        if kappa == 0.0 or getattr(self.attach, "flat", False):
            return self
        shift = float(cap) * kappa
        seen = [Piece(p.start, p.end, p.x0 - shift * p.d_ref, p.ratio - shift, p.d_ref) for p in self.pieces]
        return AnchorMap(self.attach, self.rtol, seen)

    def sliding_length(self, caps: "Caps", x: np.ndarray, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
        """The length (m) of the springs at either cap at several instants: each cap's :meth:`zone_sizes` with its
        level ``x ∓ (K a + κ d)``, as the cap sees the anchors (:meth:`seen_by`).

        Parameters
        ----------
        caps : Caps
            The friction law's caps.
        x, depth, radius : numpy.ndarray
            The indenter's position, the depth and the contact radius at each instant (m).

        Returns
        -------
        numpy.ndarray
            The lengths (m).
        """
        shift = caps.centre_shift(radius, depth)
        radius = np.asarray(radius, dtype=float)
        extents = self._extents(radius)  # (the pieces' starts and ends, hence each cap's, are the same)
        # (each cap's sign as an int: NumPy asks an IntEnum operand for its array attributes, the enum's slow lookup)
        return sum(self.seen_by(cap, caps.kappa)._zone_sizes(cap, x - int(cap) * shift, radius, extents)
                   for cap in Cap)

    # --- values ---------------------------------------------------------------------------------
    def in_contact(self, radius: float) -> list[Piece]:
        """The pieces that hold springs of a contact of radius ``radius``.

        Parameters
        ----------
        radius : float
            The contact radius (m).

        Returns
        -------
        list of Piece
            Those that start below it (at least the first).
        """
        return [p for p in self.pieces if p.start < radius] or list(self.pieces[:1])

    def piece_value(self, p: Piece, xi: float) -> float:
        """``Y(ξ)`` on piece ``p``.

        Parameters
        ----------
        p : Piece
            A piece of this map.
        xi : float
            The spring's coordinate (m).

        Returns
        -------
        float
            The anchor (m).
        """
        return p.x0 if p.constant else p.at_depth(self.attach.depth(xi))

    def end_values(self, p: Piece, end: float) -> tuple[float, float]:
        """``Y`` at the start of piece ``p`` and at ``end``; remembered where ``end`` is the piece's own (a
        span's zone layout reads every piece: a path of N growth segments would evaluate them N² times).

        Parameters
        ----------
        p : Piece
            A piece of this map.
        end : float
            The coordinate (m) of the second value.

        Returns
        -------
        tuple of float
            ``(Y(p.start), Y(end))`` (m).
        """
        if end != p.end:
            return self.piece_value(p, p.start), self.piece_value(p, end)
        values = self._end_values.get(p)
        if values is None:
            values = self._end_values[p] = (self.piece_value(p, p.start), self.piece_value(p, end))
        return values

    def piece_values(self, p: Piece, xi: np.ndarray) -> np.ndarray:
        """:meth:`piece_value` for an array of ``ξ``.

        Parameters
        ----------
        p : Piece
            A piece of this map.
        xi : numpy.ndarray
            The springs' coordinates (m).

        Returns
        -------
        numpy.ndarray
            The anchors (m), the shape of ``xi``.
        """
        return np.full(np.shape(xi), p.x0) if p.constant else p.at_depth(self.attach.depths(xi))

    def value(self, xi: float) -> float:
        """``Y(ξ)``; where ``Y`` jumps at a piece boundary, the value of the piece that starts there.

        Parameters
        ----------
        xi : float
            The spring's coordinate (m).

        Returns
        -------
        float
            The anchor (m).
        """
        chosen = self.pieces[0]
        for p in self.pieces:
            if p.start <= xi:
                chosen = p
        return self.piece_value(chosen, min(max(xi, chosen.start), chosen.end))

    def inverse(self, p: Piece, level: float) -> float:
        """The ``ξ`` at which growth piece ``p`` takes the value ``level``, continued beyond the piece;
        where the depth it needs lies below the branch's fold (far on the piece's start side), the
        piece's start; where it lies beyond the deepest a table's branch reaches (far on its end side), the
        table's last radius.

        Parameters
        ----------
        p : Piece
            A growth piece of this map.
        level : float
            The anchor value (m).

        Returns
        -------
        float
            The coordinate ``ξ`` (m).
        """
        depth = p.d_ref + (level - p.x0) / p.ratio
        if depth > self.deepest:  # (beyond the branch's tables, a layer's a/h = 64: past the piece's springs)
            return self.attach.ceiling
        xi = self.attach.radius(depth, self.rtol)
        return xi if xi == xi else self._unreached(p, depth)

    def _unreached(self, p: Piece, depth):
        """:meth:`inverse` where the branch has no radius of ``depth`` (a float or an array): the piece's start below
        the fold, the last knot (a table's last radius) above it."""
        beyond = self.attach.knots[-1] if self.attach.knots else p.start
        return np.where(depth <= self.attach.jump_off_depth, p.start, beyond) if np.ndim(depth) else \
            (p.start if depth <= self.attach.jump_off_depth else beyond)

    def inverses(self, p: Piece, levels: np.ndarray) -> np.ndarray:
        """:meth:`inverse` for an array of levels (a run's samples: the sliding length :func:`~.solution.evaluate`
        gives), by the branch's :meth:`~.branch.Branch.sample_radii`: on the paraboloid with adhesion the quartic's
        root in closed form, a few ulp from :meth:`inverse`'s iteration (which the events read), without its steps
        over the whole array; any other branch, its ``radii``.

        Parameters
        ----------
        p : Piece
            A growth piece of this map.
        levels : numpy.ndarray
            The anchor values (m).

        Returns
        -------
        numpy.ndarray
            The coordinates ``ξ`` (m), the shape of ``levels``.
        """
        depth = p.d_ref + (np.asarray(levels, dtype=float) - p.x0) / p.ratio
        xi = self.attach.sample_radii(depth)
        return np.where(np.isnan(xi), self._unreached(p, depth), xi)

    def integral(self, p: Piece, lower: float, upper: float) -> float:
        """``∫ Y(ξ) dξ`` over ``[lower, upper]`` on piece ``p``.

        Parameters
        ----------
        p : Piece
            A piece of this map.
        lower : float
            The lower bound of ``ξ`` (m).
        upper : float
            The upper bound of ``ξ`` (m).

        Returns
        -------
        float
            The integral (m²).
        """
        total = p.x0 * (upper - lower)
        if not p.constant:
            total += p.ratio * (self.attach.integral(upper) - self.attach.integral(lower) - p.d_ref * (upper - lower))
        return total

    # --- slip zones and force, exactly ----------------------------------------------------------
    def zone_size(self, cap: Cap, level: float, radius: float) -> float:
        """The size of ``cap``'s slip zone ``{ξ <= a: cap · Y(ξ) <= cap · level}`` (the springs whose
        effective anchor is the level); one point of :meth:`zone_sizes`.

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.
        level : float
            The level (m): the anchor of a spring at the cap.
        radius : float
            The contact radius (m).

        Returns
        -------
        float
            The zone's size (m), a union of intervals.
        """
        return float(self.zone_sizes(cap, np.array([level]), np.array([radius]))[0])

    def zone_sizes(self, cap: Cap, levels: np.ndarray, radii: np.ndarray) -> np.ndarray:
        """:meth:`zone_size` for arrays of levels and radii (vectorised over points, looped over pieces).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.
        levels : numpy.ndarray
            The levels (m).
        radii : numpy.ndarray
            The contact radii (m), broadcast with ``levels``.

        Returns
        -------
        numpy.ndarray
            The zones' sizes (m), the broadcast shape.
        """
        radii = np.asarray(radii, dtype=float)
        return self._zone_sizes(cap, levels, radii, self._extents(radii))

    def _extents(self, radii: np.ndarray) -> list[tuple[np.ndarray, np.ndarray, float]]:
        """Per piece, what :meth:`_zone_sizes` reads of the radii alone (both caps alike): the end of its springs in
        contact ``min(end, a)``, their length ``max(min(end, a) − start, 0)`` and the largest of those ends."""
        extents = []
        for p in self.pieces:
            ends = np.minimum(p.end, radii)
            extents.append((ends, np.maximum(ends - p.start, 0.0), float(np.max(ends))))
        return extents

    def _zone_sizes(self, cap: Cap, levels: np.ndarray, radii: np.ndarray,
                    extents: list[tuple[np.ndarray, np.ndarray, float]]) -> np.ndarray:
        """:meth:`zone_sizes` with the pieces' :meth:`_extents` of ``radii`` given (shared by both caps): each piece's
        springs at the cap added in place (``np.add(..., where=)``: the sum of ``np.where(..., length, 0)``, whose
        zeros add nothing to a total of lengths >= 0), the front's radius root only where the level lies within the
        piece's values (the same root, of the same levels, as before)."""
        levels = np.asarray(levels, dtype=float)
        shape = np.broadcast_shapes(levels.shape, radii.shape)
        total = np.zeros(shape)
        sign = int(cap)  # (an int: see sliding_length)
        reached = sign * levels
        for p, (ends, length, largest) in zip(self.pieces, extents):
            if p.constant:
                np.add(total, length, out=total, where=sign * p.x0 <= reached)
                continue
            first, last = sign * self.piece_value(p, p.start), sign * self.piece_value(p, largest)
            # (as NumPy's min and max of the two: nan if either is; Python's would drop a nan second)
            low, high = (min(first, last), max(first, last)) if first == first and last == last else \
                (math.nan, math.nan)
            np.add(total, length, out=total, where=reached >= high)
            inside = (reached >= low) & (reached < high)
            if inside.any():
                xi = self.inverses(p, levels[inside] if levels.shape == shape else
                                   np.broadcast_to(levels, shape)[inside])
                part = xi - p.start if p.rises_towards(cap) else np.broadcast_to(ends, shape)[inside] - xi
                total[inside] += np.clip(part, 0.0, np.broadcast_to(length, shape)[inside])
        return total

    def clipped_shift_integral(self, x: float, cap_shift: float, radius: float,
                               medium: "HalfSpaceMedium | None" = None) -> float:
        """``∫_0^a w(ξ) clip(x − Y(ξ), −ū, ū) dξ`` with ``ū = cap_shift``: the springs' shifts, integrated, each weighed
        by its tangential stiffness ``w`` in units of ``G*`` (``medium``; 1 on the half-space).

        The springs at a bound give ``±ū`` times their length exactly; only those inside the window are
        differences ``x − Y``. (The same integral as ``x a − ∫ clip(Y, x − ū, x + ū)``, which loses the
        digits of ``|x| / ū``: a path at 1e-3° has ``x`` 1e9 times ``ū``, and a full slip lost 1e-7 of its
        force.)

        Parameters
        ----------
        x : float
            The indenter's tangential position (m).
        cap_shift : float
            The cap ``ū = K a`` (m).
        radius : float
            The contact radius ``a`` (m).
        medium : HalfSpaceMedium, optional
            What the springs are made of (:mod:`.media`; default the half-space, every ``w = 1``).

        Returns
        -------
        float
            The integral (m²).
        """
        from .media import HALF_SPACE_MEDIUM

        medium = HALF_SPACE_MEDIUM if medium is None else medium
        measure = medium.measure
        lower, upper = x - cap_shift, x + cap_shift
        total = 0.0
        for p in self.in_contact(radius):
            end = min(p.end, radius)
            if end <= p.start:
                continue
            if p.constant:
                total += measure(p.start, end) * min(max(x - p.x0, -cap_shift), cap_shift)
                continue
            # the piece is monotone: its springs are at one bound up to the first cut, at the other beyond
            # the second; a rising piece has its low anchors (shift +ū) first
            start_bound, end_bound, start_shift = (lower, upper, cap_shift) if p.ratio > 0 else (upper, lower, -cap_shift)
            first = min(max(self.inverse(p, start_bound), p.start), end)
            second = min(max(self.inverse(p, end_bound), p.start), end)
            inside = 0.0
            if second > first:
                inside = x * measure(first, second) - medium.piece_integral(self, p, first, second)
            total += start_shift * measure(p.start, first) + inside - start_shift * measure(second, end)
        return total

    def coulomb_shift_integral(self, x: float, caps: "Caps", depth: float, radius: float) -> float:
        """``∫_0^a clip(x − Y(ξ), −ū(ξ), ū(ξ)) dξ`` with the caps ``ū(ξ) = K a + κ (d − g(ξ))``, ``κ > 0``.

        On each (monotone) piece the springs at the positive cap (``Z₊ <= L₊`` as :meth:`seen_by` it) lie at one
        end, those at the negative cap at the other, and they give their caps exactly, ``∫ (K a + κ (d − g))``;
        the springs between give ``x − Y``.

        Parameters
        ----------
        x : float
            The indenter's tangential position (m).
        caps : Caps
            The friction law's caps (``κ > 0``).
        depth : float
            The depth ``d`` (m).
        radius : float
            The contact radius ``a`` (m).

        Returns
        -------
        float
            The integral (m²).
        """
        shift = caps.centre_shift(radius, depth)
        sides = [(float(cap), self.seen_by(cap, caps.kappa), x - float(cap) * shift) for cap in Cap]

        def cap_integral(lower: float, upper: float) -> float:  # ∫ (K a + κ (d − g)) dξ, g = d0 without adhesion
            if upper <= lower:
                return 0.0
            return shift * (upper - lower) - caps.kappa * (self.attach.integral(upper) - self.attach.integral(lower))

        total = 0.0
        for index, p in enumerate(self.in_contact(radius)):
            end = min(p.end, radius)
            if end <= p.start:
                continue
            inner, outer = p.start, end  # the springs between the caps lie in [inner, outer]
            for sign, seen, level in sides:
                q = seen.pieces[index]
                values = sign * seen.piece_value(q, p.start), sign * seen.piece_value(q, end)
                if not min(values) <= sign * level:  # no spring at the cap
                    at_cap = (p.start, p.start)
                elif max(values) <= sign * level:  # every spring (a constant piece: one value)
                    at_cap = (p.start, end)
                else:  # a front: the springs at the cap are on the side where sign Z is lower
                    cut = min(max(seen.inverse(q, level), p.start), end)
                    at_cap = (p.start, cut) if values[0] <= values[1] else (cut, end)
                total += sign * cap_integral(*at_cap)
                if at_cap[1] > at_cap[0]:
                    if at_cap[0] <= p.start:
                        inner = max(inner, at_cap[1])
                    else:
                        outer = min(outer, at_cap[0])
            if outer > inner:
                total += x * (outer - inner) - self.integral(p, inner, outer)
        return total

    def tangential_force(self, caps: "Caps", G_star: float, x: float, a: float, depth: float = 0.0) -> float:
        r"""``F_x = 2G* ∫_0^a clip(x − Y, −ū, ū) dξ`` with the caps of ``caps`` (``ū = K a`` for ``τ0`` alone, then
        ``depth`` is not used): the force of this map with the window at ``x``, without integration (0 out of
        contact).

        .. math:: F_x = \sum \Delta k_x u_x(x_i) \to 2 G^* \int_0^a \operatorname{clip}(x - Y(\xi), -\bar u, \bar u)\,
                  \mathrm{d}\xi \qquad (6), (15)

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
            The depth ``d`` (m), read by Coulomb's caps only.

        Returns
        -------
        float
            ``F_x`` (N).
        """
        if not a > 0 or not self.pieces:
            return 0.0
        if caps.kappa == 0.0:  # (on a layer ū = K a/Φ_t and each spring weighs w = k_t/G*: caps.medium)
            return 2.0 * G_star * self.clipped_shift_integral(x, caps.centre_shift(a, depth), a, caps.medium)
        return 2.0 * G_star * self.coulomb_shift_integral(x, caps, depth, a)

