"""What is read off the anchors of an adhesive contact under ``"tau0+coulomb"`` without integrating: the springs at
each cap in each region (:class:`~.regions.Region`), the play operator materialised, the algebraic force and the
springs that slide.

A cap ``σ`` of a region holds the springs whose anchors, as it sees them (``Y − σ κ g`` compressed, ``Y`` in
tension), lie at or beyond its level (``σ Z <= σ L``): on each monotone part an interval at one of its ends
(:func:`at_cap_intervals`). Those springs carry the cap, ``K a + κ (d − g)`` compressed and ``K a`` in tension, the
others ``x − Y`` (``F_x = 2G* ∫_0^a clip(x − Y, −ū(ξ), ū(ξ)) dξ``, (15)).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .formulas import Formula, FormulaPiece
from .regions import Region
from .state import Cap

if TYPE_CHECKING:
    from .caps import Caps
    from .split_map import SplitAnchorMap

__all__ = ["at_cap_intervals", "clipped_pieces", "region_shift_integral", "zone_lengths"]


def at_cap_intervals(formula: Formula, cap: Cap, level: float, lower: float, upper: float) -> list[tuple[float, float]]:
    """Where ``σ formula <= σ level`` on ``[lower, upper]`` (the formula as the cap sees the anchors), cut at its
    turns: one interval at an end of each monotone part, or the part, or none.

    Parameters
    ----------
    formula : Formula
        The anchors as the cap sees them.
    cap : Cap
        The side, +1 or −1.
    level : float
        The cap's level (m).
    lower : float
        The interval's start (m).
    upper : float
        Its end (m).

    Returns
    -------
    list of tuple of float
        The intervals, in order.
    """
    sign, out = float(cap), []
    if upper <= lower:
        return out
    if formula.constant:
        return [(lower, upper)] if sign * formula.x0 <= sign * level else out
    cuts = [lower] + [t for t in formula.turns() if lower < t < upper] + [upper]
    for start, end in zip(cuts[:-1], cuts[1:]):
        first, last = sign * formula.value(start), sign * formula.value(end)
        reached = sign * level
        if first <= reached and last <= reached:
            out.append((start, end))
        elif first <= reached or last <= reached:
            cut = min(max(formula.inverse(level, start, end), start), end)
            out.append((start, cut) if first <= reached else (cut, end))
    return [(start, end) for start, end in out if end > start]


def clipped_pieces(anchors: "SplitAnchorMap", region: Region, cap: Cap, level: float, kappa: float, lower: float,
                   upper: float) -> list[FormulaPiece]:
    """The pieces of ``anchors`` with the springs of ``region`` (on ``[lower, upper]``) at ``cap`` materialised at its
    level (:meth:`~.regions.Region.bound`): the play operator's one-sided clip ``Y ← clip(Y, …)`` of that cap.

    Parameters
    ----------
    anchors : SplitAnchorMap
        The stored anchors.
    region : Region
        The region.
    cap : Cap
        The side, +1 or −1.
    level : float
        The cap's level (m).
    kappa : float
        ``κ = μ E*/G*``.
    lower : float
        The interval's start (m).
    upper : float
        Its end (m).

    Returns
    -------
    list of FormulaPiece
        The pieces of the whole map.
    """
    shift = region.view_shift(cap, kappa)
    bound = region.bound(anchors.shape, cap, level, kappa)
    out = []
    for p in anchors.pieces:
        start, end = max(p.start, lower), min(p.end, upper)
        caught = at_cap_intervals(p.formula.seen(shift), cap, level, start, end) if end > start else []
        position = p.start
        for low, high in caught:
            if low > position:
                out.append(FormulaPiece(position, low, p.formula))
            out.append(FormulaPiece(low, high, bound))
            position = high
        if p.end > position:
            out.append(FormulaPiece(position, p.end, p.formula))
    return out


def _cap_integral(anchors: "SplitAnchorMap", region: Region, K: float, kappa: float, radius: float, depth: float,
                  lower: float, upper: float) -> float:
    """``∫ (K a + weight κ (d − g)) dξ`` over ``[lower, upper]``: the caps of the springs there, integrated."""
    if upper <= lower:
        return 0.0
    total = (K * radius + region.weight * kappa * depth) * (upper - lower)
    if region.weight:
        hertz = anchors.shape.hertz
        total -= kappa * (hertz.integral(upper) - hertz.integral(lower))
    return total


def region_shift_integral(anchors: "SplitAnchorMap", region: Region, caps: "Caps", x: float, radius: float,
                          depth: float, lower: float, upper: float) -> float:
    """``∫ clip(x − Y, −ū, ū) dξ`` over the springs of ``region`` on ``[lower, upper]``: the caps of those at one
    exactly, ``x − Y`` of the others (integrated between the caps' intervals, not as a difference of totals).

    Parameters
    ----------
    anchors : SplitAnchorMap
        The map the region is read from.
    region : Region
        The region.
    caps : Caps
        The friction law's caps.
    x : float
        The indenter's tangential position (m).
    radius : float
        The contact radius (m).
    depth : float
        The depth (m).
    lower : float
        The interval's start (m).
    upper : float
        Its end (m).

    Returns
    -------
    float
        The integral (m²).
    """
    K, kappa = caps.K, caps.kappa
    total = 0.0
    for p in anchors.pieces:
        start, end = max(p.start, lower), min(p.end, upper)
        if end <= start:
            continue
        held = []
        for cap in Cap:
            level = region.level(cap, x, K, kappa, radius, depth)
            for low, high in at_cap_intervals(p.formula.seen(region.view_shift(cap, kappa)), cap, level, start, end):
                total += float(cap) * _cap_integral(anchors, region, K, kappa, radius, depth, low, high)
                held.append((low, high))
        position = start
        for low, high in sorted(held) + [(end, end)]:
            if low > position:
                total += x * (low - position) - p.formula.integral(position, low)
            position = max(position, high)
    return total


def zone_lengths(anchors: "SplitAnchorMap", region: Region, cap: Cap, levels: np.ndarray, lower: np.ndarray,
                 upper: np.ndarray, kappa: float) -> np.ndarray:
    """The length of ``cap``'s zone in ``region`` at each of several instants (vectorised over them): the region
    ``[lower, upper]`` and the level at each.

    Parameters
    ----------
    anchors : SplitAnchorMap
        The map the region is read from.
    region : Region
        The region.
    cap : Cap
        The side, +1 or −1.
    levels : numpy.ndarray
        The cap's level at each instant (m).
    lower : numpy.ndarray
        The region's start at each (m).
    upper : numpy.ndarray
        Its end at each (m).
    kappa : float
        ``κ = μ E*/G*``.

    Returns
    -------
    numpy.ndarray
        The lengths (m).
    """
    sign = float(cap)
    levels, lower, upper = (np.asarray(v, dtype=float) for v in (levels, lower, upper))
    total = np.zeros(np.broadcast(levels, lower, upper).shape)
    if not total.size or not np.any(upper > lower):
        return total
    for part in anchors.parts(region.view_shift(cap, kappa), float(np.min(lower)), float(np.max(upper))):
        start, end = np.maximum(part.start, lower), np.minimum(part.end, upper)
        if part.formula.constant:
            total += np.where((end > start) & (sign * part.formula.x0 <= sign * levels), end - start, 0.0)
            continue
        first, last = sign * part.value(part.start), sign * part.value(part.end)
        reached = sign * levels
        if float(np.max(reached)) < min(first, last):  # (no level reaches the part: no spring of it at the cap)
            continue
        if float(np.min(reached)) >= max(first, last):  # (every level beyond it: all its springs at the cap)
            total += np.maximum(end - start, 0.0)
            continue
        cut = np.where(reached >= max(first, last), np.inf, -np.inf) * (1.0 if first <= last else -1.0)
        inside = (reached > min(first, last)) & (reached < max(first, last))
        if np.any(inside):
            cut = cut.copy()
            cut[inside] = part.formula.inverses(levels[inside], part.start, part.end)
        low, high = (start, np.minimum(end, cut)) if first <= last else (np.maximum(start, cut), end)
        total += np.maximum(high - low, 0.0)
    return total
