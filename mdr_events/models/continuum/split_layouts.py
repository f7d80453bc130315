"""The layouts of the two regions of ``"tau0+coulomb"`` with adhesion (:mod:`.split_span`), and the anchors springs
get crossing ``x_c`` at a cap.

Each cap of each region is laid out with :class:`~.regions.RegionLayout` on the parts of the map the region is read
from (:func:`region_parts`), at an :class:`Instant`, its ends moving as :class:`Ends` says (:func:`lay_out_regions`).
A spring crossing ``x_c`` at a cap of the region it leaves keeps the window of that instant (:func:`crossing_formula`,
``adhesive_crossing_anchor``).
"""

from __future__ import annotations

from typing import NamedTuple

from .formulas import Formula
from .model import Segment
from .regions import Region, RegionLayout
from .split_map import SpanMaps, SplitAnchorMap
from .state import Cap, Regime

__all__ = ["KEYS", "Ends", "STILL", "Instant", "split_lengths", "region_parts", "lay_out_regions",
           "crossing_formula"]

#: A region and a cap: the key of a layout, of its slip and of its events.
Key = tuple[Region, Cap]
KEYS: tuple[Key, ...] = tuple((region, cap) for region in Region for cap in Cap)


class Ends(NamedTuple):
    """How a region's start and end behave during a span (each a pair: start, end)."""

    #: whether each end moves
    moving: tuple[bool, bool] = (False, False)
    #: whether each end moves outwards, into springs the region did not hold (a part of zero length is laid there)
    growing: tuple[bool, bool] = (False, False)
    #: whether the anchors' value at a moving end is a target of the level
    targets: tuple[bool, bool] = (True, True)
    #: whether the end is the growing edge (springs attach with no shift: :class:`~.regions.RegionLayout`)
    fresh: bool = False


#: Neither end moves (a layout at one instant).
STILL = Ends()


def split_lengths(anchors: SplitAnchorMap, cap_shift: float, x: float, travel: float) -> float:
    """The lengths the slip criterion compares (:func:`~.zones.length_scale`): the centre's cap, the indenter's and
    the anchors' positions and the travel.

    Parameters
    ----------
    anchors : SplitAnchorMap
        The stored anchors.
    cap_shift : float
        The centre's cap ``K a + κ d`` (m).
    x : float
        The indenter's tangential position (m).
    travel : float
        The travel over the rounding of the levels' variables (m).

    Returns
    -------
    float
        The length (m).
    """
    return max(cap_shift, abs(x), anchors.largest_value(), travel)


def region_parts(anchors: SplitAnchorMap, shift: float, lower: float, upper: float, ends: Ends) -> list:
    """The parts of ``anchors`` seen with ``shift`` on ``[lower, upper]``, with a part of zero length laid at a growing
    end where the springs beyond belong to another part.

    Parameters
    ----------
    anchors : SplitAnchorMap
        The map the region is read from.
    shift : float
        ``σ κ`` of a compressed cap, 0 in tension.
    lower : float
        The region's start (m).
    upper : float
        Its end (m).
    ends : Ends
        How the region's ends move.

    Returns
    -------
    list of Part
        The parts, in order.
    """
    parts = anchors.parts(shift, lower, upper) if upper > lower else []
    if ends.growing[1]:
        tail = anchors.part_at(shift, upper, 1.0)
        if not (parts and parts[-1].formula == tail.formula and parts[-1].low == tail.low and parts[-1].end == upper):
            parts.append(tail)
    if ends.growing[0]:
        head = anchors.part_at(shift, lower, -1.0)
        if not (parts and parts[0].formula == head.formula and parts[0].high == head.high and parts[0].start == lower):
            parts.insert(0, head)
    return parts


class Instant(NamedTuple):
    """Where the indenter and the contact are at one instant: what the regions' layouts are laid out at."""

    x: float         #: the tangential position (m)
    depth: float     #: the depth (m)
    radius: float    #: the contact radius (m)
    boundary: float  #: the compression boundary ``x_c`` (m)


def lay_out_regions(maps: SpanMaps, caps, at: Instant, sliding: dict[Key, bool], tolerance: float,
                    ends: dict[Region, Ends] | None = None, only: Region | None = None) -> dict[Key, RegionLayout]:
    """Every cap's zone in every region that holds springs (the compressed zone ``[0, x_c]``, the annulus
    ``[x_c, a]``) at the instant ``at``; ``ends``: how each region's ends move during the span (default
    :data:`STILL`); ``only``: that region's alone.

    Parameters
    ----------
    maps : SpanMaps
        The maps the regions are read from.
    caps : Caps
        The friction law's caps.
    at : Instant
        The instant.
    sliding : dict
        Whether springs slide at each cap in each region (keys ``(Region, Cap)``).
    tolerance : float
        A value this close beyond a level counts as reached (m).
    ends : dict of Region to Ends, optional
        How each region's ends move.
    only : Region, optional
        The one region to lay out (default both).

    Returns
    -------
    dict
        The layouts, keyed ``(Region, Cap)``.
    """
    x, depth, radius, boundary = at
    extents = {Region.COMPRESSED: (0.0, boundary), Region.TENSILE: (boundary, radius)}
    out = {}
    for region, cap in KEYS:
        if only is not None and region is not only:
            continue
        region_ends = (ends or {}).get(region, STILL)
        lower, upper = extents[region]
        if not (upper > lower or any(region_ends.growing)):
            continue
        parts = region_parts(maps.of(region), region.view_shift(cap, caps.kappa), lower, upper, region_ends)
        if parts:
            level = region.level(cap, x, caps.K, caps.kappa, radius, depth)
            out[(region, cap)] = RegionLayout(parts, cap, level, sliding.get((region, cap), False), tolerance,
                                              region_ends.moving, region_ends.targets, region_ends.fresh)
    return out


def crossing_formula(anchors: SplitAnchorMap, segment: Segment, regime: Regime, radius: float, cap: Cap,
                     K: float) -> Formula:
    """The anchors springs get crossing ``x_c`` at ``cap`` on ``segment``: ``x(τ) − σ K a(τ)`` with ``d(τ) = g(ξ)``,
    ``x0 + (v_x/v_d)(g(ξ) − d_s) − σ K A(g(ξ))`` (``adhesive_crossing_anchor``); ``A`` the radius of the depth on
    the branch the radius follows, or the pinned ``radius``.

    Parameters
    ----------
    anchors : SplitAnchorMap
        The stored anchors (their shape).
    segment : Segment
        The path segment.
    regime : Regime
        How the radius moves.
    radius : float
        The pinned radius (m; a pinned span's).
    cap : Cap
        The side, +1 or −1.
    K : float
        ``τ0``'s cap per radius (1).

    Returns
    -------
    Formula
        The anchors.
    """
    ratio = segment.vx / segment.vd
    if regime is Regime.PINNED:
        return Formula(anchors.shape, segment.xs - float(cap) * K * radius, alpha=ratio, d_ref=segment.ds)
    branch = "grow" if regime is Regime.GROWING else "shrink"
    return Formula(anchors.shape, segment.xs, alpha=ratio, d_ref=segment.ds, gamma=-float(cap) * K, radius_of=branch)
