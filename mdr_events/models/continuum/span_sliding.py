"""The sliding length of several spans at their samples at once (issue 28: one pass over the spans): the values each
span's own :meth:`~.anchors.AnchorMap.sliding_length` gives, bit for bit, with the pieces of every span taken together.

A span's sliding length sums, cap by cap, its anchor map's pieces in order: a constant piece adds the length of its
springs in contact where the level has passed its value; a growth piece adds it where the level has passed the
piece's values at both ends, and where the level lies between them the length up to the slip front, the radius where
the piece takes the level's value (:meth:`~.anchors.AnchorMap.inverses`). Here the ``k``-th piece of every span is
handled at once: each sample reads its own span's numbers (repeated over its samples), so that every sample sees the
same operations, in the same order, as in its span's own call; the fronts of all spans are the attachment branch's
roots in one call (:meth:`~.branch.Branch.grouped_sample_radii`: each span's iteration near the fold as its own call
runs it). ``tests/models/test_evaluate_batch.py`` compares both routes.

Only maps of :class:`~.anchors.AnchorMap` itself are taken together; a span whose sliding length is read off other
layouts (``Span.zones``, a split map) keeps its own call (:func:`span_sliding_lengths`' caller decides, by
:func:`takes_batch`).
"""

from __future__ import annotations

import math

import numpy as np

from .anchors import AnchorMap
from .dense import cut
from .state import Cap

__all__ = ["takes_batch", "span_sliding_lengths"]


def takes_batch(span) -> bool:
    """Whether a span's sliding length is read off an :class:`~.anchors.AnchorMap` (no zones of its own): the spans
    :func:`span_sliding_lengths` takes together.

    Parameters
    ----------
    span : Span
        A span in contact.

    Returns
    -------
    bool
        ``True`` if its anchors are an ``AnchorMap`` and it has no zones.
    """
    return span.zones is None and type(span.anchors) is AnchorMap


def span_sliding_lengths(caps, maps: list[AnchorMap], x: np.ndarray, depth: np.ndarray, radius: np.ndarray,
                         lengths: list[int]) -> np.ndarray:
    """:meth:`~.anchors.AnchorMap.sliding_length` of each span's map at its samples, the samples of all spans
    concatenated (each span's consecutive, in the order of ``maps``), bit for bit.

    Parameters
    ----------
    caps : Caps
        The friction law's caps.
    maps : list of AnchorMap
        Each span's anchor map (all of one attachment branch).
    x, depth, radius : numpy.ndarray
        The indenter's position, the depth and the contact radius at every sample (m), 1-D.
    lengths : list of int
        Each span's number of samples (each at least 1).

    Returns
    -------
    numpy.ndarray
        The sliding lengths (m) at every sample.
    """
    radius = np.asarray(radius, dtype=float)
    shift = caps.centre_shift(radius, depth)
    owner = np.repeat(np.arange(len(maps)), lengths)
    offsets = np.cumsum([0] + list(lengths[:-1]))
    extents = _extents(maps, radius, owner, offsets)
    depths: dict[float, float] = {}  # (the attachment branch's depth at each radius read, for both caps)
    totals = [_zone_sizes([m.seen_by(cap, caps.kappa) for m in maps], cap, x - int(cap) * shift, extents, owner,
                          offsets, depths) for cap in Cap]
    return sum(totals)  # (as the per-span sum over the caps: 0 + the first + the second)


def _extents(maps: list[AnchorMap], radius: np.ndarray, owner: np.ndarray, offsets: np.ndarray) -> list:
    """Per piece index ``k``: the springs' ends
    ``min(end, a)`` and lengths ``max(min(end, a) − start, 0)`` at every sample, and the largest end over each span's
    samples (``AnchorMap._extents``, every span's ``k``-th piece at once; ``nan`` where a span has none)."""
    found = []
    for k in range(max(len(m.pieces) for m in maps)):
        pieces = [m.pieces[k] if len(m.pieces) > k else None for m in maps]
        start, end = (np.array([getattr(p, name) if p is not None else math.nan for p in pieces])
                      for name in ("start", "end"))
        ends = np.minimum(end[owner], radius)
        length = np.maximum(ends - start[owner], 0.0)
        largest = np.maximum.reduceat(ends, offsets)
        found.append((ends, length, largest))
    return found


def _zone_sizes(seen: list[AnchorMap], cap: Cap, levels: np.ndarray, extents: list, owner: np.ndarray,
                offsets: np.ndarray, depths: dict[float, float]) -> np.ndarray:
    """``AnchorMap._zone_sizes`` of every span's map as ``cap`` sees it, at its samples' ``levels``: piece index by
    piece index, each sample with its own span's piece (its additions in the order of its span's call); ``depths``:
    the attachment branch's depths at the radii read so far (:func:`_piece_value`)."""
    total = np.zeros(levels.shape)
    sign = int(cap)
    reached = sign * levels
    top = np.maximum.reduceat(reached, offsets)  # (each span's highest level: nan where any is)
    lists = [list(m.pieces) for m in seen]  # (each map's pieces read once: a snapshot's indexing checks its bounds)
    for k, (ends, length, largest) in enumerate(extents):
        pieces = [found[k] if len(found) > k else None for found in lists]
        value = [sign * p.x0 if p is not None and p.constant else math.nan for p in pieces]
        if any(v == v for v in value):  # (a span without a constant piece k: nan, which no level passes)
            np.add(total, length, out=total, where=np.array(value)[owner] <= reached)
        growth = [s for s, p in enumerate(pieces) if p is not None and not p.constant]
        if growth:
            _add_growth(seen[growth[0]].attach, [pieces[s] for s in growth], growth, sign, levels, reached,
                        (ends, length, largest), owner, top, depths, total)
    return total


def _piece_value(attach, p, xi: float, depths: dict[float, float]) -> float:
    """:meth:`~.anchors.AnchorMap.piece_value` of the growth piece ``p`` at ``xi`` (both read
    :meth:`~.anchors.Piece.at_depth`: the same bits), the attachment branch's depth at ``xi`` kept in ``depths`` by
    the radius: a run's spans share their pieces' starts and ends, and both caps read them (a zigzag's 76 readings
    are some 20 radii)."""
    depth = depths.get(xi)
    if depth is None:
        depth = depths[xi] = attach.depth(xi)
    return p.at_depth(depth)


def _add_growth(attach, grown: list, growth: list[int], sign: int, levels: np.ndarray, reached: np.ndarray,
                extent: tuple, owner: np.ndarray, top: np.ndarray, depths: dict[float, float],
                total: np.ndarray) -> None:
    """The growth pieces ``grown`` (as the cap sees them, on the attachment branch ``attach``) of the spans
    ``growth`` added to ``total``: their whole length where the level has passed both ends' values, the length to the
    front where it lies between them; ``top``: each span's highest level (``nan`` where any is), below its piece's
    lower value nothing is added."""
    ends, length, largest = extent
    count = len(largest)
    low, high = np.full(count, math.nan), np.full(count, math.nan)
    numbers = np.full((5, count), math.nan)  # (x0, ratio, d_ref, start, rises) of each span's piece
    for s, p in zip(growth, grown):
        first = sign * _piece_value(attach, p, p.start, depths)
        last = sign * _piece_value(attach, p, float(largest[s]), depths)
        if first == first and last == last:  # (as NumPy's min and max of the two: nan if either is)
            low[s], high[s] = min(first, last), max(first, last)
        numbers[:, s] = (p.x0, p.ratio, p.d_ref, p.start, 1.0 if p.rises_towards(sign) else 0.0)
    if not np.any((top >= low) | np.isnan(top)):  # (no span's level reaches its piece's lower value: nothing to add)
        return
    # (a span without a growth piece k has nan values, which no level passes nor lies between)
    row_low, row_high = low[owner], high[owner]
    np.add(total, length, out=total, where=reached >= row_high)
    inside = np.flatnonzero((reached >= row_low) & (reached < row_high))  # (in order: the rows a mask picks)
    if not inside.size:
        return
    who = owner[inside]
    x0, ratio, d_ref, start, rises = (row[who] for row in numbers)
    depth = d_ref + (levels[inside] - x0) / ratio  # (AnchorMap.inverses, each sample with its span's piece)
    groups = np.bincount(who, minlength=count)
    xi = np.concatenate(attach.grouped_sample_radii(cut(depth, [int(n) for n in groups if n])))
    beyond = np.full(depth.shape, attach.knots[-1]) if attach.knots else start
    xi = np.where(np.isnan(xi), np.where(depth <= attach.jump_off_depth, start, beyond), xi)
    part = np.where(rises == 1.0, xi - start, ends[inside] - xi)
    total[inside] += np.clip(part, 0.0, length[inside])

