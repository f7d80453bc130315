"""The springs in contact of one discrete case as groups that share one shift, with exact sums.

The discrete model (:mod:`mdr_events.models.discrete`) steps its springs through :class:`SpringGroups`: a spring's
shift is ``u = x − Y`` with its anchor ``Y``, and the anchors are exact integers in units of ``2**-bits`` m
(:func:`scale_bits`, :func:`scaled`, :func:`unscaled`), so that ``Σ u`` comes from a running sum without drift.
Kept apart from the model's rules because it is one idea of its own: a play operator per spring, kept per group
of springs (union-find, two heaps), with integer arithmetic.
"""

from __future__ import annotations

import heapq
import math
import sys
from collections.abc import Sequence

import numpy as np

__all__ = ["SpringGroups", "scale_bits", "scaled", "unscaled"]


def scale_bits(*arrays: np.ndarray) -> int:
    """The smallest ``bits`` that makes every value of ``arrays`` an integer multiple of ``2**-bits``."""
    values = np.concatenate([np.ravel(part) for part in arrays])
    values = values[values != 0.0]
    if not values.size:
        return 0
    # v = f 2**e with 0.5 <= |f| < 1 and 53 significant bits: a multiple of 2**(e - 53)
    return max(0, 53 - int(np.frexp(values)[1].min()))


def scaled(values: np.ndarray, bits: int) -> list[int]:
    """``values * 2**bits`` as exact Python integers (each value a multiple of ``2**-bits``)."""
    values = np.asarray(values, dtype=float)
    largest = float(np.max(np.abs(values))) if values.size else 0.0
    if largest == 0.0 or math.frexp(largest)[1] + bits < 1000:  # ldexp exact, no overflow
        return [int(value) for value in np.ldexp(values, bits).tolist()]
    scaled = []
    for value in values.tolist():
        numerator, denominator = value.as_integer_ratio()
        scaled.append(numerator << (bits - denominator.bit_length() + 1))
    return scaled


def unscaled(value: int, bits: int) -> float:
    """The float nearest to ``value * 2**-bits`` (correctly rounded, subnormal results aside)."""
    if bits <= 900:  # float(value) is finite here: round once, then scale by an exact power of two
        return float(value) * 2.0 ** -bits
    return value / (1 << bits)


class SpringGroups:
    """The springs in contact of one case, in groups that share one shift; every sum exact.

    A spring in contact has an anchor ``Y``, the position of the indenter at
    which it would be unstretched, and the shift ``u = x − Y``: it attaches
    with ``Y = x``, keeps ``Y`` while it sticks, and where the cap clips it,
    ``Y`` moves with the window ``[x − ū, x + ū]`` (a play operator per
    spring): the spring sits at ``u = +ū`` with ``Y = x − ū`` (the *low* cap)
    or at ``u = −ū`` with ``Y = x + ū`` (the *high* cap). Springs that once
    share a shift share it until they detach, so they are kept as *groups*
    (union-find, each spring reached through its index range, a stack from the
    centre out: springs attach and detach at the edge).

    Anchors are integers in units of ``2**-bits`` m: every sample of ``x`` and
    every cap ``ū(a)`` is such an integer, so the shifts ``x − Y`` and the sum
    of the anchors of the springs in contact (:attr:`anchor_sum`, updated
    only where springs attach, detach or are clipped) are exact, with no
    drift over any number of steps; ``Σ u = m x − Σ Y`` is rounded once.

    Springs of unequal stiffness (a layer of finite thickness,
    :mod:`~mdr_events.models.spring_media`) carry integer weights ``w_j``
    (``prefix[j]`` the sum of those below ``j``); each group keeps the sum of
    its springs' weights beside their count, :attr:`anchor_sum` is then
    ``Σ w_j Y_j`` and ``Σ w_j u_j = prefix[m] x − Σ w_j Y_j``, exact as well.
    By default every spring weighs 1 (``prefix[j] = j``) and the sums are the
    plain ones.

    Per step the work is the springs' groups that change: the two caps (their
    anchors follow the window), the free groups that the window reaches (from
    two heaps of the free groups' anchors: lowest and highest first) and the
    index ranges that detach. A step that clips nothing costs O(1).
    """

    __slots__ = ("parent", "count", "weight", "anchor", "free", "lows", "highs", "starts", "groups", "low_cap",
                 "high_cap", "anchor_sum", "prefix")

    #: Groups and heap entries allowed beyond the live bound before they are compacted (:meth:`_bound`).
    SLACK = 256

    def __init__(self, prefix: Sequence[int] = range(sys.maxsize)) -> None:
        #: Σ of the springs' integer weights below each index (default: every spring weighs 1)
        self.prefix = prefix
        self.reset()

    def reset(self) -> None:
        """No springs in contact (the contact came apart)."""
        self.parent: list[int] = []  # union-find: a group merged into a cap points towards it
        self.count: list[int] = []  # springs of a root group
        self.weight: list[int] = []  # the sum of their weights
        self.anchor: list[int] = []  # anchor of a root group (2**-bits m)
        self.free: list[bool] = []  # a root group that sticks (in the heaps), not a cap
        self.lows: list[tuple[int, int]] = []  # (anchor, group): a min-heap of the free groups
        self.highs: list[tuple[int, int]] = []  # (-anchor, group): a max-heap of the free groups
        self.starts: list[int] = []  # index ranges from the centre out: first spring of each ...
        self.groups: list[int] = []  # ... and its group
        self.low_cap = -1  # the group at u = +ū (anchor x − ū), or -1
        self.high_cap = -1  # the group at u = −ū (anchor x + ū), or -1
        self.anchor_sum = 0  # Σ Y over the springs in contact (2**-bits m), exact

    def _root(self, group: int) -> int:
        parent = self.parent
        root = group
        while parent[root] != root:
            root = parent[root]
        while parent[group] != root:  # path compression
            parent[group], group = root, parent[group]
        return root

    def attach(self, start: int, stop: int, anchor: int) -> None:
        """Springs ``start ≤ j < stop`` attach with zero shift at the position ``anchor``."""
        weight = self.prefix[stop] - self.prefix[start]
        self.anchor_sum += weight * anchor
        if self.groups:
            group = self.groups[-1]  # the outermost springs stick at the same anchor (x did not move): join them
            if self.parent[group] == group and self.free[group] and self.anchor[group] == anchor:
                self.count[group] += stop - start
                self.weight[group] += weight
                return
        group = len(self.parent)
        self.parent.append(group)
        self.count.append(stop - start)
        self.weight.append(weight)
        self.anchor.append(anchor)
        self.free.append(True)
        heapq.heappush(self.lows, (anchor, group))
        heapq.heappush(self.highs, (-anchor, group))
        self.starts.append(start)
        self.groups.append(group)
        self._bound()

    def detach(self, top: int, stop: int) -> None:
        """Springs ``stop ≤ j < top`` (the outermost ``top − stop``) detach and forget their shift."""
        starts, groups, count, prefix = self.starts, self.groups, self.count, self.prefix
        while top > stop:
            start = starts[-1]
            root = self._root(groups[-1])
            low = start if start > stop else stop
            leaving = prefix[top] - prefix[low]
            count[root] -= top - low
            self.weight[root] -= leaving
            self.anchor_sum -= leaving * self.anchor[root]
            if low == start:
                starts.pop()
                groups.pop()
            top = low

    def _live(self, group: int, anchor: int) -> bool:
        """A heap entry that is still a free group at that anchor (entries are removed lazily)."""
        return self.parent[group] == group and self.free[group] and self.count[group] > 0 \
            and self.anchor[group] == anchor

    def _take(self, cap: int, group: int, level: int) -> int:
        """The free ``group`` reaches the cap at anchor ``level``: it joins ``cap`` (or becomes it)."""
        self.free[group] = False
        self.anchor_sum += self.weight[group] * (level - self.anchor[group])
        if cap < 0:
            self.anchor[group] = level
            return group
        self.parent[group] = cap
        self.count[cap] += self.count[group]
        self.weight[cap] += self.weight[group]
        return cap

    def _settle(self, cap: int, level: int, low: bool) -> int:
        """The cap group ``cap`` moves with its level if it still sits at or beyond it; if the
        level moved back past it, its springs stick again where they are (a free group). The cap after."""
        if self.count[cap] == 0:
            return -1
        anchor = self.anchor[cap]
        if (anchor > level) if low else (anchor < level):
            self.free[cap] = True
            heapq.heappush(self.lows, (anchor, cap))
            heapq.heappush(self.highs, (-anchor, cap))
            return -1
        self.anchor_sum += self.weight[cap] * (level - anchor)
        self.anchor[cap] = level
        return cap

    def clip(self, low: int, high: int) -> int:
        """Clip every shift to the window ``[low, high] = [x − ū, x + ū]`` of anchors; the number of
        springs at a cap (``|u| = ū``) after it."""
        count, lows, highs = self.count, self.lows, self.highs
        # both caps first: a cap left behind by a long step may be reached by the other level
        low_cap, high_cap = self.low_cap, self.high_cap
        if low_cap >= 0:
            low_cap = self._settle(low_cap, low, True)
        if high_cap >= 0:
            high_cap = self._settle(high_cap, high, False)
        while lows and lows[0][0] <= low:
            anchor, group = heapq.heappop(lows)
            if self._live(group, anchor):
                low_cap = self._take(low_cap, group, low)
        while highs and -highs[0][0] >= high:
            anchor, group = heapq.heappop(highs)
            if self._live(group, -anchor):
                high_cap = self._take(high_cap, group, high)
        released = (self.low_cap >= 0 > low_cap) or (self.high_cap >= 0 > high_cap)
        self.low_cap, self.high_cap = low_cap, high_cap
        at_caps = (count[low_cap] if low_cap >= 0 else 0) + (count[high_cap] if high_cap >= 0 else 0)
        if released:
            self._bound()  # a released cap added heap entries
        return at_caps

    def _bound(self) -> None:
        """Compact when the groups and heap entries (live or stale) outgrow the index ranges. Each
        range holds at most one live root with a few live heap entries, so memory stays linear in
        the springs in contact; a compaction is linear in the ranges and follows as many new
        entries or detached ranges (amortised O(1) per attach, detach or release)."""
        if len(self.parent) + len(self.lows) + len(self.highs) > 8 * len(self.starts) + self.SLACK:
            self._compact()

    def _compact(self) -> None:
        """Renumber the live groups (roots), join neighbouring index ranges of one group, rebuild the
        heaps: memory stays linear in the springs in contact, whatever the number of steps."""
        renumbered: dict[int, int] = {}
        starts: list[int] = []
        groups: list[int] = []
        for start, group in zip(self.starts, self.groups):
            new = renumbered.setdefault(self._root(group), len(renumbered))
            if not groups or groups[-1] != new:
                starts.append(start)
                groups.append(new)
        roots = list(renumbered)
        self.parent = list(range(len(roots)))
        self.count = [self.count[root] for root in roots]
        self.weight = [self.weight[root] for root in roots]
        self.anchor = [self.anchor[root] for root in roots]
        self.free = [self.free[root] for root in roots]
        self.low_cap = renumbered.get(self.low_cap, -1)
        self.high_cap = renumbered.get(self.high_cap, -1)
        self.starts, self.groups = starts, groups
        self.lows = [(anchor, group) for group, (anchor, free) in enumerate(zip(self.anchor, self.free)) if free]
        self.highs = [(-anchor, group) for anchor, group in self.lows]
        heapq.heapify(self.lows)
        heapq.heapify(self.highs)

    def shifts(self, x: int, springs: int) -> list[int]:
        """Every spring's shift ``x − Y`` (2**-bits m), from the centre out; ``springs`` in contact."""
        shifts: list[int] = []
        for start, stop, group in zip(self.starts, self.starts[1:] + [springs], self.groups):
            shifts.extend([x - self.anchor[self._root(group)]] * (stop - start))
        return shifts
