"""The two regions of an adhesive contact under ``"tau0+coulomb"``, and one cap's slip zone in one region.

A spring at ``ξ`` has the cap ``K a + κ max(d − g(ξ), 0)`` (``adhesive_friction_cap``): both parts in the compressed
zone ``ξ < x_c`` (``g(x_c) = d``), ``τ0``'s part alone in the tensile annulus beyond (:class:`Region`). In each region
a cap ``σ`` compares the anchors as it sees them with one level, the same for all its springs, as :mod:`.zones` does
for a whole contact; here a region's ends may move during a span (``x_c`` with the depth, ``a`` with the radius), and
:class:`RegionLayout` continues the zone with them: the part at a moving end grows or shrinks with it, and the value
of the anchors at a moving end may be what the level reaches next. What each region's layouts log together is one
:class:`~.state.ZoneSummary` per cap (:func:`combined_summary`).
"""

from __future__ import annotations

import bisect
import enum
import math
from dataclasses import dataclass, field

import numpy as np

from .formulas import Formula, Shape
from .state import Cap, Slip, ZoneSummary, NO_ZONE

__all__ = ["Region", "Part", "RegionLayout", "combined_summary", "START_SCAN"]

#: Points of a part's scan (evenly over its springs) whose inverse parabola about a level starts Newton's iteration
#: for its root (:meth:`Part.start_of`): read once per part, one value each (no root), and a start that depends on the
#: level alone (two steps mostly, three at most but a few: as the last roots' secant took)
START_SCAN = 33


class Region(enum.Enum):
    """Where a spring of an adhesive contact is: its cap is ``K a + weight · κ (d − g(ξ))``."""

    COMPRESSED = 1  #: ``ξ < x_c``: both parts of the cap
    TENSILE = 0     #: ``x_c < ξ <= a``: ``τ0``'s part ``K a`` alone

    @property
    def weight(self) -> float:
        """1 where Coulomb's part acts, 0 where it does not.

        Returns
        -------
        float
            The weight (1 or 0).
        """
        return float(self.value)

    def view_shift(self, cap: Cap, kappa: float) -> float:
        """The share of ``g(ξ)`` a cap subtracts from the anchors it compares (``σ κ`` compressed, 0 in tension).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.
        kappa : float
            ``κ = μ E*/G*``.

        Returns
        -------
        float
            The shift (1).
        """
        return float(cap) * kappa * self.weight

    def level(self, cap: Cap, x: float, K: float, kappa: float, radius: float, depth: float) -> float:
        """``x − σ (K a + weight κ d)``: the level the springs at ``cap`` sit at, as the cap sees them.

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.
        x : float
            The indenter's tangential position (m).
        K : float
            ``τ0``'s cap per radius (1).
        kappa : float
            ``κ = μ E*/G*``.
        radius : float
            The contact radius (m).
        depth : float
            The depth (m).

        Returns
        -------
        float
            The level (m).
        """
        return x - float(cap) * (K * radius + self.weight * kappa * depth)

    def bound(self, shape: Shape, cap: Cap, level: float, kappa: float) -> Formula:
        """The stored anchors of springs materialised at ``cap``: ``level + σ κ g(ξ)`` compressed, ``level`` in
        tension.

        Parameters
        ----------
        shape : Shape
            The functions of the contact.
        cap : Cap
            The side, +1 or −1.
        level : float
            The cap's level (m).
        kappa : float
            ``κ = μ E*/G*``.

        Returns
        -------
        Formula
            The anchors ``Y`` of those springs.
        """
        return Formula(shape, level, alpha=self.view_shift(cap, kappa))


@dataclass(frozen=True)
class Part:
    """A piece of the anchors as one cap of one region sees them, on an interval where they are monotone.

    Parameters
    ----------
    formula : Formula
        The anchors as the cap sees them (``Y − σ κ g`` compressed).
    start, end : float
        The springs it holds (m).
    low, high : float
        The formula's monotone interval around them: how far a front in it is continued (m).
    """

    formula: Formula
    start: float
    end: float
    low: float
    high: float
    #: what is read once and kept: the formula's values at ``low``, ``high`` and the part's ends, the scan of
    #: :meth:`start_of`
    memo: dict = field(default_factory=dict, compare=False, hash=False, repr=False)

    def value(self, xi: float) -> float:
        """The seen anchor at ``ξ`` (m).

        Parameters
        ----------
        xi : float
            The spring's coordinate (m).

        Returns
        -------
        float
            The anchor as the cap sees it (m; at the part's own ends remembered: the layouts and sums read them more
            than once, and a value of ``A(g)`` is a root; elsewhere, as the events' moving extents ask, computed).
        """
        if xi != self.start and xi != self.end:
            return self.formula.value(xi)
        values = self.memo.setdefault("values", {})
        if xi not in values:
            values[xi] = self.formula.value(xi)
        return values[xi]

    def rises_towards(self, cap: Cap) -> bool:
        """Whether ``σ Y`` increases with ``ξ`` over the part (its slip zone is then at its start).

        Parameters
        ----------
        cap : Cap
            The side, +1 or −1.

        Returns
        -------
        bool
            ``True`` for a constant, or where ``σ Y`` rises over the monotone interval.
        """
        if self.formula.constant:
            return True
        low, high = self._ends()
        return float(cap) * (high - low) > 0.0

    def _ends(self) -> tuple[float, float]:
        """The formula's values at ``low`` and ``high``, remembered."""
        memo = self.memo
        if "ends" not in memo:
            memo["ends"] = (self.formula.value(self.low), self.formula.value(self.high))
        return memo["ends"]

    def inverse(self, level: float) -> float:
        """Where the seen anchors equal ``level``, continued over the monotone interval (clamped at its ends).

        Parameters
        ----------
        level : float
            The level (m).

        Returns
        -------
        float
            ``ξ`` (m): Newton's iteration started from the chord of the part's scan about ``level``
            (:meth:`start_of`), so that a root depends on the level alone, not on the roots asked before.
        """
        return self.formula.inverse(level, self.low, self.high, self.start_of(level), self._ends())

    def start_of(self, level: float) -> float | None:
        """Newton's start for ``level``: the inverse parabola through the two points of the part's scan about it and
        the nearer neighbour, where it stays between those two, else their chord (:data:`START_SCAN` points evenly
        over the part's springs, or its monotone interval where it has none, read once, the first time asked; ``None``
        where the formula's inverse does not start from one: a closed form, or a radius ``A(g)`` that ``brentq``
        brackets).

        Parameters
        ----------
        level : float
            The level (m).

        Returns
        -------
        float or None
            The start (m), strictly inside the monotone interval, or ``None``.
        """
        formula = self.formula
        if formula.gamma or not (formula.alpha and formula.beta):
            return None
        memo = self.memo
        if "scan" not in memo:  # (over the part's springs, where its fronts are; a part of zero length: its interval)
            first, last = (self.start, self.end) if self.end > self.start else (self.low, self.high)
            width = last - first
            points = [first + width * k / (START_SCAN - 1) for k in range(START_SCAN)]
            values = [formula.value(xi) for xi in points]
            rising = values[-1] >= values[0]
            memo["scan"] = (points, values if rising else [-v for v in values], 1.0 if rising else -1.0)
        points, values, sign = memo["scan"]
        target = sign * level
        cell = min(max(bisect.bisect_right(values, target), 1), START_SCAN - 1)
        low, high = values[cell - 1], values[cell]
        share = (target - low) / (high - low) if high > low else 0.5
        start = points[cell - 1] + min(max(share, 0.0), 1.0) * (points[cell] - points[cell - 1])
        # the inverse parabola through the cell's points and the nearer neighbour (a start a power of the cell's width
        # closer: Newton's second step then mostly settles), where it stays in the cell
        third = cell + 1 if cell + 1 < START_SCAN and (cell < 2 or share > 0.5) else cell - 2
        if 0 <= third < START_SCAN and low < high and values[third] not in (low, high):
            other = values[third]
            below, above, beyond = target - low, target - high, target - other
            curved = (points[cell - 1] * above * beyond / ((low - high) * (low - other))
                      + points[cell] * below * beyond / ((high - low) * (high - other))
                      + points[third] * below * above / ((other - low) * (other - high)))
            if points[cell - 1] < curved < points[cell]:
                start = curved
        return start if self.low < start < self.high else 0.5 * (points[cell - 1] + points[cell])


class Role(enum.Enum):
    """How a part takes part in one cap's slip zone (as :class:`~.zones.Role`)."""

    OUT = "out"
    FRONT = "front"
    IN = "in"


class RegionLayout:
    """One cap's slip zone in one region at a span's start, continued through the span with the region's ends.

    Parameters
    ----------
    parts : list of Part
        The region's parts at the start, from its first end to its second (a moving end's part may have zero length).
    cap : Cap
    level : float
        The cap's level at the start, as the cap sees the anchors (:meth:`Region.level`).
    sliding : bool
        Whether springs slide at this cap in this region (a cap that does not has every part out).
    tolerance : float
        A value this close beyond the level counts as reached (:func:`~.zones.lay_out_zones`).
    moving : tuple of bool
        Whether the region's start and its end move during the span.
    targets : tuple of bool
        Whether the anchors' value at a moving start, a moving end, is a target of the level (not where springs
        arrive across ``x_c`` with the anchors the other region gave them).
    fresh : bool, default False
        The region's end is the growing edge, where springs attach with no shift, short of every cap by ``K a``: its
        value is never reached (at ``a → 0`` of a contact without adhesion every value lies within the tolerance).
    """

    def __init__(self, parts: list[Part], cap: Cap, level: float, sliding: bool, tolerance: float,
                 moving: tuple[bool, bool] = (False, False), targets: tuple[bool, bool] = (True, True),
                 fresh: bool = False):
        self.parts, self.cap, self.sign = parts, cap, float(cap)
        self.moving = moving
        reached = self.sign * level + tolerance
        last = len(parts) - 1
        self.roles: list[Role] = [self._role(p, reached, sliding, fresh and index == last)
                                  for index, p in enumerate(parts)]
        fixed, self.moving_targets = [], []
        for index, (p, role) in enumerate(zip(parts, self.roles)):
            if role is Role.IN:
                continue
            at_end = (role is Role.FRONT) == p.rises_towards(cap)
            end = 1 if at_end else 0
            if (index == last if at_end else index == 0) and moving[end]:
                if targets[end]:
                    self.moving_targets.append(end)
            else:
                fixed.append(self.sign * p.value(p.end if at_end else p.start))
        self.fixed_target = min(fixed, default=float("inf"))
        self.inner = sum(p.end - p.start for index, (p, role) in enumerate(zip(parts, self.roles))
                         if role is Role.IN and not self._moves(index))
        self.moving_in = [index for index, role in enumerate(self.roles) if role is Role.IN and self._moves(index)]
        self.fronts = [(index, p.rises_towards(cap)) for index, (p, role) in enumerate(zip(parts, self.roles))
                       if role is Role.FRONT]
        #: the moving ends where a front's zone lies at the end: the end leaving the zone is an event
        self.leaving = [end for end, index in ((0, 0), (1, last)) if parts and moving[end]
                        and self.roles[index] is Role.FRONT and self.parts[index].rises_towards(cap) == (end == 0)]

    def _role(self, p: Part, reached: float, sliding: bool, fresh: bool) -> Role:
        if not sliding:
            return Role.OUT
        start, end = self.sign * p.value(p.start), (math.inf if fresh else self.sign * p.value(p.end))
        if start <= reached and end <= reached:
            return Role.IN
        if start <= reached or end <= reached:
            return Role.IN if p.formula.constant else Role.FRONT
        return Role.OUT

    def _moves(self, index: int) -> bool:
        """Whether the part ``index`` has a moving end."""
        return (index == 0 and self.moving[0]) or (index == len(self.parts) - 1 and self.moving[1])

    def _ends(self, index: int, lower: float, upper: float) -> tuple[float, float]:
        p = self.parts[index]
        return (lower if index == 0 and self.moving[0] else p.start,
                upper if index == len(self.parts) - 1 and self.moving[1] else p.end)

    # --- through the span -----------------------------------------------------------------------
    def size(self, level: float, lower: float, upper: float) -> float:
        """The zone's size (m) with the level ``level`` and the region ``[lower, upper]``, continued smoothly.

        Parameters
        ----------
        level : float
            The cap's level (m), as the cap sees the anchors.
        lower : float
            The region's start (m).
        upper : float
            Its end (m).

        Returns
        -------
        float
            The size (m).
        """
        total = self.inner
        for index in self.moving_in:
            start, end = self._ends(index, lower, upper)
            total += end - start
        for index, at_start in self.fronts:
            xi = self.parts[index].inverse(level)
            start, end = self._ends(index, lower, upper)
            total += max(xi - start if at_start else end - xi, 0.0)
        return total

    def sizes(self, levels: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
        """:meth:`size` at several instants at once (vectorised: each front's roots by
        :meth:`~.formulas.Formula.inverses` on its monotone interval).

        Parameters
        ----------
        levels : numpy.ndarray
            The cap's level at each instant (m), as the cap sees the anchors.
        lower : numpy.ndarray
            The region's start at each (m).
        upper : numpy.ndarray
            Its end at each (m).

        Returns
        -------
        numpy.ndarray
            The sizes (m).
        """
        total = np.full(np.shape(levels), self.inner)
        for index in self.moving_in:
            start, end = self._ends(index, lower, upper)
            total = total + (end - start)
        for index, at_start in self.fronts:
            p = self.parts[index]
            xi = p.formula.inverses(levels, p.low, p.high)
            start, end = self._ends(index, lower, upper)
            total = total + np.maximum(xi - start if at_start else end - xi, 0.0)
        return total

    def end_value(self, end: int, lower: float, upper: float) -> float:
        """``σ Y`` as the cap sees it at the region's start (``end = 0``) or end (1).

        Parameters
        ----------
        end : int
            0 for the start, 1 for the end.
        lower : float
            The region's start (m).
        upper : float
            Its end (m).

        Returns
        -------
        float
            ``σ Y`` there (m).
        """
        p = self.parts[0 if end == 0 else -1]
        return self.sign * p.value(lower if end == 0 else upper)

    def target(self, lower: float, upper: float) -> float:
        """The value of ``σ · level`` at which the layout stops being right as the level pushes on (``inf``: none).

        Parameters
        ----------
        lower : float
            The region's start (m).
        upper : float
            Its end (m).

        Returns
        -------
        float
            The target (m; ``inf``: none).
        """
        values = [self.end_value(end, lower, upper) for end in self.moving_targets]
        return min([self.fixed_target] + values)

    # --- what is read and logged ------------------------------------------------------------------
    def at_cap(self, end: int) -> bool:
        """Whether the spring at the region's start (``end = 0``) or end (1) is at the cap.

        Parameters
        ----------
        end : int
            0 for the start, 1 for the end.

        Returns
        -------
        bool
            ``True`` if that spring is at the cap.
        """
        if not self.parts:
            return False
        index = 0 if end == 0 else len(self.parts) - 1
        role = self.roles[index]
        return role is Role.IN or (role is Role.FRONT and self.parts[index].rises_towards(self.cap) == (end == 0))

    def summary(self) -> ZoneSummary | None:
        """The zone's extent, and whether it holds the region's first and last spring (``None``: an empty region).

        Returns
        -------
        ZoneSummary or None
            The zone's summary, ``None`` for a region without springs.
        """
        present = [(p, role) for p, role in zip(self.parts, self.roles) if p.end > p.start]
        if not present:
            return None
        if all(role is Role.OUT for _, role in present):
            return NO_ZONE
        slip = Slip.FULL if all(role is Role.IN for _, role in present) else Slip.PARTIAL
        (first, first_role), (last, last_role) = present[0], present[-1]
        centre = first_role is Role.IN or (first_role is Role.FRONT and first.rises_towards(self.cap))
        edge = last_role is Role.IN or (last_role is Role.FRONT and not last.rises_towards(self.cap))
        return ZoneSummary(slip, centre, edge)


def combined_summary(compressed: ZoneSummary | None, tensile: ZoneSummary | None) -> ZoneSummary:
    """One cap's zone over the whole contact from its zones in the compressed zone and the tensile annulus (``None``:
    a region without springs): the centre is the compressed zone's, the edge the annulus's.

    Parameters
    ----------
    compressed : ZoneSummary or None
        The cap's zone in the compressed zone.
    tensile : ZoneSummary or None
        Its zone in the tensile annulus.

    Returns
    -------
    ZoneSummary
        The cap's zone over the contact.
    """
    present = [summary for summary in (compressed, tensile) if summary is not None]
    if not present or all(summary.slip is Slip.STICK for summary in present):
        return NO_ZONE
    slip = Slip.FULL if all(summary.slip is Slip.FULL for summary in present) else Slip.PARTIAL
    return ZoneSummary(slip, present[0].centre, present[-1].edge)
