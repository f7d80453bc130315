r"""Coulomb's part of the friction law spring by spring: every anchor the play operator of its own window.

Each spring at ``ξ`` holds its tangential shift within ``±c(ξ, t)``, ``c = ū(a) + μ ρ(ξ) (d − g(ξ))`` (:mod:`.caps`;
``ρ = k/k_t``, ``E*/G*`` on the half-space, ``K'/K_t'`` on a layer, as the discrete model's
:meth:`~mdr_events.models.spring_media.LayerSprings.coulomb_ratios`, derived in
:func:`~mdr_events.theory.layer_continuum_symbolic.derive_continuum_model`). On the half-space ``ρ`` is one number and
the springs share a level (:meth:`~.anchors.AnchorMap.seen_by`); on a layer ``μ ρ(ξ) d`` is not separable and no level
is shared. This module composes each spring's play operator on its own, exactly in time, and integrates the force in
``ξ`` with the kinks located (route (b) of issue 34's Coulomb part; it takes any per-spring cap, so on the half-space
it is a third route beside the spans, checked against them).

The anchor of a spring in contact at ``t`` that attached at ``τ`` (the last time the radius grew through ``ξ``,
:mod:`.play_history`: without adhesion where ``d`` rose through ``g(ξ)``, with adhesion on the ``Δγ0`` branch or at a
jump-in) is the output of the play operator of the window ``[L, U] = [x − c, x + c]`` over ``[τ, t]`` started at
``x(τ)`` (it attaches with no shift); with adhesion ``c = ū(a) + μρ max(d − g, 0)``, Coulomb's part off in tension,
and each spring's chain holds the times its compression changes sign (the kink of its ``c`` in time), and the
radius's jumps with both of their sides. Where ``L`` and ``U`` are monotone between two times the operator over
that interval is the clamp at its start followed by the clamp at its end; where ``L`` is convex and ``U`` concave,
too (their running extremes lie at the interval's ends). Along a path segment ``x`` and ``d`` are linear in time, and
``L = x − ū(a(t)) − μρ(d − g)`` is convex wherever ``ū(a(t))`` is concave in ``t`` (the paraboloid's and the power
laws' along a segment without adhesion, section 6 of the symbolic module; checked on every run), so the anchor is a
finite chain of clamps at the path's corners. Where the sampled ``ū(a(t))`` of a piece of the radius's history is not
concave the chain gains, for every spring, the times of its own ``L``'s maximum and ``U``'s minimum there (golden
sections, :data:`GOLDEN_STEPS`).

The force ``F_x = 2G* ∫₀ᵃ w(ξ)(x − Y_ξ) dξ`` (``w = k_t/G*``) is summed by Gauss–Legendre on panels of ``[0, a]``
split where the anchor's provenance (which clamp of its chain last moved it, and to which edge) changes: there the
anchor has a kink (a slip front, an old front kept in memory; the provenance also tells whether the spring was
compressed at that clamp: with adhesion its cap has a kink at ``x_c`` of that time); in between it is smooth. A kink
is located by bisection on the provenance (:data:`KINK_HALVINGS`), looked for between neighbouring nodes and between
the centre or the edge (:data:`EDGE_SHARE` inside) and the nearest node; not between two springs that lie on the
same smooth edge of their windows at ``t`` to round-off (:data:`EDGE_ROUND_OFF`: their anchors are that edge whatever
their provenance). The springs at a cap at ``t`` are those whose last clamp is ``t``'s own.

Many times are read at once (:meth:`PlaySprings.probed_states`, :meth:`PlaySprings.outsides`): every spring carries
its own time, the panels' ends of all the times lie in one flat array (:class:`_Breaks`, sorted by time, then radius),
every round of the kink search and every cut of its bisection is one evaluation of the anchors for the springs of all
the times still searched, and the edges' round-off reads each time's own largest cap; each time's values are those of
a call at that time alone, bit for bit (a single time is the batch of one). The clamp times are the same columns at
every time (those at or after it dropped), so a clamp's provenance code does not depend on the times read together;
where no spring has extremes of its own they are clamped a shared time at a time (:meth:`PlaySprings._shared_clamps`,
each spring's crossings of ``d = g`` between them), without sorting the columns spring by spring.

The springs' values (:mod:`.play_line`), the clamp times every spring shares (:mod:`.play_chain`), the quadrature's
panels and rule (:mod:`.play_quadrature`) and the golden sections of the springs' own extremes (:mod:`.play_golden`)
are modules of their own.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .play_chain import CONCAVITY_SAMPLES, shared_chain
from .play_golden import GOLDEN_STEPS, GOLDEN_TABLE_POINTS, GOLDEN_TABLE_RTOL, _golden, convex_tables
from .play_history import DepthHistory, SpanHistory
from .play_line import SpringLine, spring_line
from .play_quadrature import EDGE_SHARE, NODES, _Breaks, _Quadrature

__all__ = ["SpringLine", "spring_line", "PlaySprings", "SpringState", "DepthHistory", "SpanHistory", "LOWER_CAP",
           "UPPER_CAP", "PANELS", "NODES", "EDGE_SHARE", "KINK_HALVINGS", "KINK_CUTS", "SETTLED_BRACKETS", "GOLDEN_STEPS",
           "GOLDEN_TABLE_RTOL", "GOLDEN_TABLE_POINTS",
           "CONCAVITY_SAMPLES", "EDGE_ROUND_OFF", "REMEMBER_SHIFTS"]

#: Panels of ``[0, a]`` before the kinks are added.
PANELS = 8
#: Halvings of the bracket of a kink in ``ξ``: below the doubles' resolution of the radius.
KINK_HALVINGS = 60
#: Points a kink's bracket is cut into at once (a power of two): 6 halvings a round, about 8 rounds from a node's
#: spacing to two neighbouring doubles (16 cuts took 12), each evaluation's fixed cost (0.05-0.2 ms on a layer: the
#: chain's clamps, the attachments, the springs' values) above its 63 points a bracket (0.3-1.5 us each).
KINK_CUTS = 64
#: Whether the kinks' bisection stops cutting a bracket once no double lies between its ends (the others' cuts read
#: alone: a cut's evaluation holds only the brackets still open; ``False``: every bracket cut until all are settled,
#: the route of before, which the tests compare it with: the same kinks bit for bit, a settled bracket's cuts being
#: its ends).
SETTLED_BRACKETS = True
#: Rounds of kink finding in one evaluation (a kink found can reveal another between the same two nodes).
KINK_ROUNDS = 6
_sum = np.add.reduce
#: ``d − g`` within this share of the path's largest depth counts as not compressed (:meth:`PlaySprings.anchors`).
PRESSED_ROUND_OFF = 1e-12
#: A spring's anchor within this share of the path's largest ``|x|`` and its cap of its window's edge at ``t`` lies on
#: it to round-off: where neighbouring springs do, their provenances (set at ``t`` or before, resting on the edge)
#: can differ by round-off with no kink between (a thick layer whose compressed zone reaches its cap at once, its
#: ``ρ(ξ)`` constant to 7e-13: thousands of such pairs, 1e-16 m off the edge, along the re-contact path of
#: tests/models/test_layer_coulomb.py).
EDGE_ROUND_OFF = 1e-12
#: Whether :meth:`PlaySprings.remember_radii` reads ``ū(a)`` of its times in one call (``False``: one call a time, as
#: before; the same values bit for bit, elementwise operations of the cap's table).
REMEMBER_SHIFTS = True
#: Provenance codes: attached and never moved (plus the segment), a clamp's lower edge, its upper edge
_ATTACHED, _LOWER, _UPPER = 0, 1, 2
#: The provenance of a spring at the lower cap at the time asked (in tension, compressed), and at the upper one
LOWER_CAP, UPPER_CAP = (-1, -4), (-2, -5)
#: The provenance codes of the clamps start here, above every attachment's
_COLUMN_CODES = 1 << 40


class SpringState(NamedTuple):
    """The springs at one time (:meth:`PlaySprings.state`)."""

    #: ``F_x`` (N)
    force: float
    #: the measure of the springs at a cap (``k_t/G*`` times m)
    measure: float
    #: the length they cover (m)
    length: float
    #: the length of the compressed springs at a cap (m)
    compressed_at_cap: float
    #: the length of the compressed springs (m; ``x_c`` where some are in tension)
    compressed: float


@dataclass
class PlaySprings:
    """``F_x`` and the springs at a cap along ``path`` (path clock), every anchor its own play operator (module
    docstring).

    Parameters
    ----------
    line : SpringLine
        The springs.
    path : Path
        The path.
    history : DepthHistory, SpanHistory or RateHistory, optional
        The radius along the path (default: without adhesion, ``g⁻¹(d)``).
    """

    line: SpringLine
    path: object
    history: object = None

    def __post_init__(self) -> None:
        if self.history is None:
            self.history = DepthHistory(self.line, self.path)
        self._corner_t = np.asarray(self.path.corner_times, dtype=float)
        self._corner_x, self._corner_d = (np.asarray(self.path.waypoints[:, i], dtype=float) for i in (0, 1))
        self._shifts: dict[tuple, float] = {}
        #: ``a(t)`` and ``x_c`` of the times and depths asked before (every evaluation asks them again)
        self._radii: dict[float, float] = {}
        self._compressed: dict[float, float] = {}
        #: a spring counts as compressed (its cap's Coulomb part on) beyond this ``d − g`` (m): at a crossing of
        #: ``d = g(ξ)`` the rounding of ``d − g`` would flip it from spring to spring
        self._pressed_round_off = PRESSED_ROUND_OFF * float(np.max(np.abs(self._corner_d)))
        self.chain = shared_chain(self.history, self.line, self._corner_t)
        #: whether springs have extremes of their own among their clamp times (:meth:`_columns`; else
        #: :meth:`_shared_clamps`)
        self._own_columns = bool(self.chain.convex.size)
        #: :meth:`_convex_tables`, made at the first golden section
        self._tables: list | None = None
        #: the derivatives of the tables' splines (``None`` where read exactly), made at the first golden section
        self._slopes: list | None = None
        self._shared_columns: list | None = None
        #: the path's largest ``|x|`` (m): the scale of the anchors' round-off
        self._x_scale = float(np.max(np.abs(self._corner_x)))

    # -- kinematics ---------------------------------------------------------------------------------------------
    def _x(self, t):
        return np.interp(t, self._corner_t, self._corner_x)

    def _d(self, t):
        return np.interp(t, self._corner_t, self._corner_d)

    def _window(self, xi: np.ndarray, g: np.ndarray, ratio: np.ndarray, times, shift=None):
        """``(L, U)`` of each spring at ``times`` (one per spring; ``ū(a(t))`` by ``shift`` if given)."""
        x, d = self._x(times), self._d(times)
        shifts = self.line.shift(self.history.radii(times)) if shift is None else shift(times)
        cap = shifts + ratio * np.maximum(d - g, 0.0)
        return x - cap, x + cap

    def _exact_shift(self, times):
        return self.line.shift(self.history.radii(times))

    def _convex_tables(self) -> list:
        """:func:`~.play_golden.convex_tables` of ``chain.convex``, made at the first golden section."""
        if self._tables is None:
            self._tables = convex_tables(self._exact_shift, self.chain.convex)
        return self._tables

    def _shift_at(self, time: float, radius: float | None = None) -> float:
        """``ū(a)`` at one time (``a(t)``, or the ``radius`` given: a jump's side), remembered (the chain's times recur
        in every evaluation)."""
        key = (time, radius)
        cached = self._shifts.get(key)
        if cached is None:
            a = np.array([self.radius(time) if radius is None else radius])
            cached = self._shifts[key] = float(self.line.shift(a)[0])
        return cached

    def _shifts_at(self, t):
        """:meth:`_shift_at` at one time, or at each of an array of times."""
        if np.ndim(t) == 0:
            return self._shift_at(float(t))
        t = np.asarray(t, dtype=float)
        flat = t.ravel()
        if flat.size and np.all(flat[1:] >= flat[:-1]):  # (the times of springs grouped by time, in order: their runs
            starts = np.concatenate([[True], flat[1:] != flat[:-1]])  # are the unique times, no sort)
            unique, inverse = flat[starts], np.cumsum(starts) - 1
        else:
            unique, inverse = np.unique(flat, return_inverse=True)
        return np.array([self._shift_at(time) for time in unique.tolist()])[inverse.reshape(t.shape)]

    def _own_times(self, xi, g, ratio, start, t):
        """Each spring's times of its ``L``'s maximum and ``U``'s minimum on every interval of ``chain.convex``
        within ``[start, t]`` (``nan`` where none), by golden sections."""
        if not self.chain.convex.size:
            return []
        # (every interval's and both edges' sections in one: each step one inversion of the radius for them all)
        lows, highs = [], []
        for lo, hi in self.chain.convex:
            a, b = np.maximum(lo, start), np.minimum(hi, np.broadcast_to(t, xi.shape))
            lows += [a, a]
            highs += [b, b]
        count = len(lows)
        low, high = np.concatenate(lows), np.concatenate(highs)
        sign = np.repeat(np.tile([1.0, -1.0], count // 2), xi.size)
        g_all, ratio_all = (np.tile(v, count) for v in (g, ratio))
        table_of = np.repeat(np.arange(count // 2), 2 * xi.size)  # (a table per interval, both edges' rows)
        found = np.full(low.shape, np.nan)
        at_low = self._extreme_at_low(low, high, sign, g_all, ratio_all, table_of)
        found[at_low] = low[at_low]
        rows = np.flatnonzero((high > low) & ~at_low)  # (the others' sections: empty, or ended at ``low``)
        if rows.size:
            tables, table_of = self._convex_tables()[::2], table_of[rows]
            cuts = np.searchsorted(table_of, np.arange(1, len(tables)))
            sign, g_all, ratio_all = sign[rows], g_all[rows], ratio_all[rows]

            def edge(s):  # (``L``, or ``−U = −x − c``: the cap once, not both edges then one dropped)
                shift = np.concatenate([table(part) for table, part in zip(tables, np.split(s, cuts)) if part.size])
                cap = shift + ratio_all * np.maximum(self._d(s) - g_all, 0.0)
                return sign * self._x(s) - cap

            found[rows] = _golden(edge, low[rows], high[rows])
        return np.split(found, count)

    def _extreme_at_low(self, low, high, sign, g, ratio, table_of) -> np.ndarray:
        """Which rows of :meth:`_own_times` have their edge's extreme at ``low`` (no golden section needed): the edge
        (``L``, or ``−U``) concave on the stretch (``ū(a(t))`` convex, ``x`` and ``d`` linear: no corner inside
        ``(low, high)``) and not rising at ``low`` (its right derivative ``±x' − ū' − ratio d' [d > g]`` at most 0;
        ``ū'`` the spline's, rows read exactly never)."""
        if self._slopes is None:
            self._slopes = [getattr(table, "derivative", lambda: None)() for table in self._convex_tables()[::2]]
        slope = np.full(low.shape, np.nan)
        for k, derivative in enumerate(self._slopes):
            if derivative is not None:
                mine = table_of == k
                slope[mine] = derivative(low[mine])
        last = self._corner_t.size - 2
        segment = np.clip(np.searchsorted(self._corner_t, low, side="right") - 1, 0, last)
        straight = np.clip(np.searchsorted(self._corner_t, high, side="left") - 1, 0, last) == segment
        span = self._corner_t[segment + 1] - self._corner_t[segment]
        with np.errstate(divide="ignore", invalid="ignore"):  # (a segment of no duration: nan, its rows' sections)
            vx, vd = ((c[segment + 1] - c[segment]) / span for c in (self._corner_x, self._corner_d))
        pressed = self._d(low) - g
        slope = sign * vx - slope - ratio * vd * ((pressed > 0.0) | ((pressed == 0.0) & (vd > 0.0)))
        return (high > low) & straight & (slope <= 0.0)

    def _columns(self, xi, g, ratio, start, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The clamp times of each spring before ``t`` (one time, or one per spring; a column each, ``nan`` where
        none), ``ū`` there and which columns are crossings: the shared times (at a jump both sides, the earlier first),
        each spring's own extremes, and with adhesion the times its compression changes sign (``d = g(ξ)``: its cap's
        kink, where its Coulomb part is 0 exactly). The columns are the same whatever ``t`` (those at or after it
        ``nan``): a clamp's provenance code, its column's index, is the same at every time."""
        n = xi.size
        times, shifts = [], []
        jumps = {time: (before, after) for time, before, after in self.history.jumps}
        for time in self.chain.times:
            sides = jumps.get(time, (None,))
            for radius in sides:
                times.append(np.where(time < t, time, np.nan) * np.ones(n))
                shifts.append(np.full(n, self._shift_at(float(time), radius)))
        own = self._own_times(xi, g, ratio, start, t)
        crossing = [False] * len(times) + [False] * len(own)
        if self.history.adhesive:
            crossings = self._crossings(g, start)
            own += crossings
            crossing += [True] * len(crossings)
        own = [np.where(column < t, column, np.nan) for column in own]
        times += own
        shifts += self._own_shifts(own, n, start)
        if not times:
            return np.empty((n, 0)), np.empty((n, 0)), np.empty(0, bool)
        return np.stack(times, axis=1), np.stack(shifts, axis=1), np.array(crossing)

    def _shared_clamps(self, anchor, label, g, ratio, start, t):
        """The clamps of :meth:`_columns` where no spring has extremes of its own (``ū(a(t))`` concave on every piece):
        the shared times a column at a time, in order for every spring, and with adhesion each spring's crossings of
        ``d = g(ξ)`` (one per segment, inside it) before the first shared time after them (ties: the shared first);
        the order, codes and arithmetic of the columns' sorted clamps."""
        crossings = [np.where(column < t, column, np.nan) for column in self._crossings(g, start)] \
            if self.history.adhesive else []
        shifts = self._own_shifts(crossings, g.size)
        shared = self._shared()
        first = len(shared)
        pending = [np.isfinite(column) & (column > start) for column in crossings]

        def cross(anchor, label, before: float):
            for j, column in enumerate(crossings):
                due = pending[j] & (column < before)
                if np.any(due):
                    x, cap = self._x(column), shifts[j] + ratio * np.maximum(0.0, 0.0)
                    anchor, label = _clamp(anchor, label, x - cap, x + cap, due, np.full(g.shape, _COLUMN_CODES
                                                                                       + 6 * (first + j)))
                    pending[j] = pending[j] & ~due
            return anchor, label

        latest, earliest = float(np.max(t)), float(np.min(start, initial=np.inf))
        for column, (time, x, d, shift) in enumerate(shared):
            if time >= latest:  # (this column and the later ones after every spring's time)
                break
            if time <= earliest:  # (before every spring's attachment, and so before its crossings)
                continue
            anchor, label = cross(anchor, label, time)
            live = (time < t) & (time > start)
            if np.any(live):
                pressed = d - g
                cap = shift + ratio * np.maximum(pressed, 0.0)
                codes = _COLUMN_CODES + 6 * column + 3 * (pressed > self._pressed_round_off)
                anchor, label = _clamp(anchor, label, x - cap, x + cap, live, codes)
        return cross(anchor, label, np.inf)

    def _shared(self) -> list[tuple[float, float, float, float]]:
        """The shared clamp columns of :meth:`_columns` in order (a jump's both sides, the earlier first): ``(time, x,
        d, ū)`` each, read once."""
        if self._shared_columns is None:
            jumps = {time: (before, after) for time, before, after in self.history.jumps}
            self._shared_columns = [(time, self._x(time), self._d(time), self._shift_at(time, radius))
                                    for time in self.chain.times.tolist() for radius in jumps.get(time, (None,))]
        return self._shared_columns

    def _own_shifts(self, columns: list[np.ndarray], n: int, start=None) -> list[np.ndarray]:
        """``ū`` at each spring's own clamp times (0 where ``nan``, or at or before its attachment ``start`` if given:
        no clamp there), the radii of the distinct times read in one call of the history (the sections' times ended at
        a stretch's start recur across springs)."""
        out = [np.zeros(n) for _ in columns]
        if not columns or not self.line.shifts:
            return out
        stacked = np.stack(columns)
        live = np.isfinite(stacked) if start is None else np.isfinite(stacked) & (stacked > start)
        if np.any(live):
            shift = np.zeros(stacked.shape)
            unique, inverse = np.unique(stacked[live], return_inverse=True)
            shift[live] = self.line.shift(self.history.radii(unique))[inverse]
            out = list(shift)
        return out

    def _crossings(self, g: np.ndarray, start: np.ndarray) -> list[np.ndarray]:
        """The times each spring's depth ``d − g(ξ)`` changes sign on each segment (``nan``: none), but its attachment:
        a spring that attached uncompressed (``|d − g| <=`` the pressed round-off at ``start``, its attachment: on a
        ``Δγ0 = 0`` branch, ``d₀(ξ) = g(ξ)``) crosses on that segment at its attachment itself, a rounding before or
        after it. A crossing an ulp after would clamp it to a window of no width (``ū = 0``) and relabel it, spring
        by spring as the roundings fall, so that the kinks' search found ever more provenances changing between
        neighbours (13867 after 6 rounds: a power law of n = 12 under ``Adhesion(0, 0.15)`` and Coulomb's law on a
        5 mm layer)."""
        out = []
        uncompressed = np.abs(self._d(start) - g) <= self._pressed_round_off
        attached_on = np.searchsorted(self._corner_t, start, side="right") - 1
        for k in range(len(self._corner_t) - 1):
            (t0, t1), (d0, d1) = self._corner_t[k:k + 2], self._corner_d[k:k + 2]
            if d0 == d1:  # (one column per segment whatever ``t``: those from ``t`` on are dropped by the caller)
                continue
            share = (g - d0) / (d1 - d0)
            inside = (share > 0.0) & (share < 1.0) & ~(uncompressed & (attached_on == k))
            out.append(np.where(inside, t0 + (t1 - t0) * share, np.nan))
        return out

    def anchors(self, xi, t: float) -> tuple[np.ndarray, np.ndarray]:
        """The anchors ``Y_ξ(t)`` of the springs at ``xi`` in contact at ``t`` and their provenance (an integer per
        spring: which clamp of the chain, or the attachment, last set it, to which edge and whether the spring was
        compressed then; negative at ``t`` itself, at a cap: :data:`LOWER_CAP`, :data:`UPPER_CAP`).

        Parameters
        ----------
        xi : numpy.ndarray
            The springs' coordinates (m), within the contact at ``t`` (``0 <= ξ < a(t)``).
        t : float
            The time (s, path clock).

        Returns
        -------
        tuple of numpy.ndarray
            The anchors (m) and the provenance codes.

        Raises
        ------
        RuntimeError
            A spring that matches no attachment of the radius's history up to ``t`` (a spring out of contact, or a
            bug: its anchor would be clamped from the path's start).
        """
        return self._anchors(xi, t)[:2]

    def _anchors(self, xi, t, group=None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`anchors`, which edge of its window at ``t`` each spring lay on before it (:func:`_on_edge`) and how
        far outside the window it lay (m; :meth:`outside`). ``t`` is one time or one per spring; with ``group`` (an
        index per spring, its time's) the edges' round-off reads the largest cap of each group's springs, as a call
        with that group's springs alone does."""
        before, label, lower, upper, cap, pressed = self._before_clamp(xi, t)
        anchor, label = _clamp(before, label, lower, upper, np.ones(before.shape, bool), np.where(pressed, -6, -3))
        if group is None:
            largest = np.max(cap, initial=0.0)
        else:
            largest = np.zeros(int(np.max(group, initial=-1)) + 1)
            np.maximum.at(largest, group, cap)
            largest = largest[group]
        edges = _on_edge(before, lower, upper, EDGE_ROUND_OFF * (self._x_scale + largest), pressed)
        return anchor, label, edges, np.maximum(lower - before, before - upper)

    def caps_over(self, xi, times) -> np.ndarray:
        """Whether each spring is at a cap at each of ``times``, where the same clamps precede them all (no clamp time
        of the chain in ``[times[0], times[-1])``, every window fixed but for ``x``: a part of
        :func:`~.play_reach.constant_part`): the anchors before the clamp read once, at the first time, each time's
        window its own, the labels :meth:`anchors` gives at each time (negative: at a cap), bit for bit.

        Parameters
        ----------
        xi : numpy.ndarray
            The springs' coordinates (m), within the contact at every time.
        times : numpy.ndarray
            The times (s, path clock), increasing, on one such part.

        Returns
        -------
        numpy.ndarray
            ``(times.size, xi.size)``: whether each spring is at a cap at each time.
        """
        xi, times = np.asarray(xi, dtype=float), np.asarray(times, dtype=float)
        before = self._before_clamp(xi, float(times[0]))[0]
        g, ratio = self.line.profile(xi), self.line.ratio(xi)
        x_t = self._x(times)[:, None]
        cap = self._shifts_at(times)[:, None] + ratio * np.maximum(self._d(times)[:, None] - g, 0.0)
        lower, upper = x_t - cap, x_t + cap  # (the clamp at t of _anchors: raised below L or on a window of no
        return (before < lower) | (lower == upper) | (before > upper)  # width, lowered above U)

    def windows_before(self, xi, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Each spring's anchor before the clamp at ``t`` (every clamp of its chain before ``t`` applied) and its window
        ``[L, U] = [x − c, x + c]`` at ``t`` (:mod:`.play_reach` reads a spring's time to reach its cap off them).

        Parameters
        ----------
        xi : numpy.ndarray
            The springs' coordinates (m), within the contact at ``t``.
        t : float
            The time (s, path clock).

        Returns
        -------
        tuple of numpy.ndarray
            The anchors before the clamp (m), ``L`` and ``U`` (m).
        """
        before, _, lower, upper, _, _ = self._before_clamp(np.asarray(xi, dtype=float), t)
        return before, lower, upper

    def _before_clamp(self, xi, t) -> tuple[np.ndarray, ...]:
        """The anchors before the clamp at ``t`` (one time or one per spring) and their provenance, the window
        ``(L, U)`` at ``t``, the cap and whether each spring is compressed (:meth:`_anchors`)."""
        xi = np.asarray(xi, dtype=float)
        g, ratio = self.line.profile(xi), self.line.ratio(xi)
        start, code = self.history.attach(xi, t)
        if np.any(start == -np.inf):  # (review S6: its anchor would be clamped from the path's start on)
            t = float(np.broadcast_to(t, xi.shape)[start == -np.inf][0])
            raise RuntimeError(f"springs at xi = {xi[start == -np.inf][:3].tolist()} m match no attachment of the "
                               f"radius's history up to t={t!r} s (in contact at t: within [0, {self.radius(t)!r}) "
                               "m?): a bug to report")
        anchor, label = self._x(start), _ATTACHED + 3 * (code + 2)
        times, shifts, crossing = self._columns(xi, g, ratio, start, t) if self._own_columns else (np.empty((0, 0)),) * 3
        if not self._own_columns:
            anchor, label = self._shared_clamps(anchor, label, g, ratio, start, t)
        elif times.shape[1]:
            order = np.argsort(times, axis=1, kind="stable")
            rows = np.arange(xi.size)[:, None]
            when, shift = times[rows, order], shifts[rows, order]
            pressed = np.where(crossing[order], 0.0, self._d(when) - g[:, None])
            cap = shift + ratio[:, None] * np.maximum(pressed, 0.0)
            x = self._x(when)
            live = np.isfinite(when) & (when > start[:, None])
            # (a clamp's code tells whether the spring was compressed then: its cap's formula has a kink in ξ there)
            codes = _COLUMN_CODES + 6 * order + 3 * (pressed > self._pressed_round_off)
            for k in range(when.shape[1]):
                anchor, label = _clamp(anchor, label, x[:, k] - cap[:, k], x[:, k] + cap[:, k], live[:, k],
                                       codes[:, k])
        x_t, cap = self._x(t), self._shifts_at(t) + ratio * np.maximum(self._d(t) - g, 0.0)
        pressed = self._d(t) - g > self._pressed_round_off
        return anchor, label, x_t - cap, x_t + cap, cap, pressed

    def radius(self, t: float) -> float:
        """The contact radius at ``t`` (m).

        Parameters
        ----------
        t : float
            The time (s, path clock).

        Returns
        -------
        float
            ``a(t)`` (0 out of contact).
        """
        cached = self._radii.get(t)
        if cached is None:
            cached = self._radii[t] = float(self.history.radii(np.array([t]))[0])
        return cached

    def remember_radii(self, times) -> None:
        """Read ``a(t)`` at many times in one call of the history (the layer's branch inverted for all of them at
        once, to its ``RADII_RTOL``) and remember them for :meth:`radius`, and ``ū(a(t))`` in one call of the cap's
        table for :meth:`shift` (:data:`REMEMBER_SHIFTS`; each element's value as a call on it alone gives it).

        Parameters
        ----------
        times : array_like
            The times (s, path clock): the run's output times.
        """
        asked = [float(time) for time in np.ravel(times)]
        fresh = np.asarray([time for time in asked if time not in self._radii], dtype=float)
        if fresh.size:
            self._radii.update(zip(fresh.tolist(), self.history.radii(fresh).tolist()))
        if REMEMBER_SHIFTS:  # (``ū(a)`` of the times in one call of the cap's table, each as :meth:`_shift_at` reads it)
            unread = list(dict.fromkeys(time for time in asked if (time, None) not in self._shifts))
            if unread:
                radii = np.array([self._radii[time] for time in unread])
                self._shifts.update(zip(((time, None) for time in unread), self.line.shift(radii).tolist()))

    def path_corners(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The path's corners: their times (s, path clock), ``x`` and ``d`` (m).

        Returns
        -------
        tuple of numpy.ndarray
            The times, ``x`` and ``d``.
        """
        return self._corner_t, self._corner_x, self._corner_d

    def shift(self, t: float) -> float:
        """``ū(a(t))``: the cap of ``τ0``'s part at ``t`` (m; 0 without it or out of contact).

        Parameters
        ----------
        t : float
            The time (s, path clock).

        Returns
        -------
        float
            The cap's part shared by every spring.
        """
        return self._shift_at(float(t))

    def compressed_radius(self, t: float) -> float:
        """``x_c`` at ``t``: the radius of the compressed springs, ``g(x_c) = d`` (m; 0 at ``d <= 0``).

        Parameters
        ----------
        t : float
            The time (s, path clock).

        Returns
        -------
        float
            ``x_c``.
        """
        if not self.history.adhesive:  # (every spring in contact compressed: x_c = a = g⁻¹(d), the same call)
            return self.radius(t)
        depth = float(self._d(t))
        cached = self._compressed.get(depth)
        if cached is None:
            cached = self._compressed[depth] = float(self.line.radius(np.array([depth]))[0])
        return cached

    def state(self, t: float, kinks: bool = True) -> "SpringState":
        """``F_x`` and the springs at a cap at ``t`` (:class:`SpringState`).

        Parameters
        ----------
        t : float
            The time (s, path clock).
        kinks : bool, default True
            Whether the quadrature's panels are split at the anchors' kinks (without: the panels of the history's
            breaks alone, a cheap guess of which springs are at a cap, which the events' bisection verifies).

        Returns
        -------
        SpringState
            The force, the sliding springs' measure and length, the compressed springs' length at a cap and in all.
        """
        return self.probed_state(t, np.empty(0), kinks)[0]

    def probed_state(self, t: float, probes: np.ndarray, kinks: bool = True) -> tuple["SpringState", np.ndarray]:
        """:meth:`state` and the provenance of the springs at ``probes`` (:meth:`anchors`), read with the quadrature's
        first nodes (one evaluation of the anchors).

        Parameters
        ----------
        t : float
            The time (s, path clock).
        probes : numpy.ndarray
            The probed springs' coordinates (m), within the contact at ``t``.
        kinks : bool, default True
            As :meth:`state`.

        Returns
        -------
        tuple
            The :class:`SpringState` and the probes' provenance codes (negative at a cap).
        """
        probes = np.asarray(probes, dtype=float)
        states, probed = self.probed_states(np.array([float(t)]), probes, np.zeros(probes.size, dtype=np.intp), kinks)
        return states[0], probed

    def probed_states(self, times, probes: np.ndarray, probe_time: np.ndarray,
                      kinks: bool | np.ndarray = True) -> tuple[list["SpringState"], np.ndarray]:
        """:meth:`probed_state` at many times at once: every round of the kink search and every cut of its bisection
        one evaluation of the anchors for the springs of all the times, each time's springs as a call at that time
        alone gives them (bit for bit: the anchors are spring by spring, the edges' round-off read per time).

        Parameters
        ----------
        times : array_like
            The times (s, path clock).
        probes : numpy.ndarray
            The probed springs' coordinates (m), each within the contact at its time.
        probe_time : numpy.ndarray
            The index in ``times`` of each probe's time.
        kinks : bool or numpy.ndarray of bool, default True
            As :meth:`state`, for every time or one per time (the times without the kink search read in its first
            round, their springs as a call without it gives them: :meth:`_kinks`).

        Returns
        -------
        tuple
            The :class:`SpringState` at each time and the probes' provenance codes (negative at a cap).
        """
        times = np.asarray(times, dtype=float)
        kinks = np.broadcast_to(np.asarray(kinks, dtype=bool), times.shape)
        probes, probe_time = np.asarray(probes, dtype=float), np.asarray(probe_time, dtype=np.intp)
        radii = np.array([self.radius(float(t)) for t in times])
        states = [SpringState(0.0, 0.0, 0.0, 0.0, 0.0)] * times.size  # (out of contact: none at a cap)
        probed = np.zeros(probes.shape, dtype=np.int64)
        inside = np.flatnonzero(radii > 0.0)
        if not inside.size:
            return states, probed
        index = np.full(times.size, -1)
        index[inside] = np.arange(inside.size)
        kept = index[probe_time] >= 0
        nodes, weights, anchor, label, group, probed[kept], profile, weight = self._quadratures(
            times[inside], radii[inside], probes[kept], index[probe_time[kept]], kinks[inside])
        w = weight * weights
        at_cap, at = label < 0, times[inside][group]
        pressed = self._d(at) - profile > self._pressed_round_off
        moved = w * (self._x(at) - anchor)
        bounds = np.searchsorted(group, np.arange(inside.size + 1))
        for k, (low, high) in enumerate(zip(bounds[:-1].tolist(), bounds[1:].tolist())):
            cap, press, each = at_cap[low:high], pressed[low:high], weights[low:high]
            # (``np.add.reduce``: ``np.sum``'s own reduction, without its wrapper's cost at each of some hundred times)
            states[inside[k]] = SpringState(2.0 * self.line.G_star * float(_sum(moved[low:high])),
                                            float(_sum(w[low:high][cap])), float(_sum(each[cap])),
                                            float(_sum(each[cap & press])), float(_sum(each[press])))
        return states, probed

    def outside(self, t: float, probes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """How far each spring's anchor lies outside its window at ``t`` before the clamp at ``t`` (m: positive where it
        is at a cap, :meth:`anchors`), on the quadrature's nodes without the kink search and at ``probes``: continuous
        in time, where the springs reach their caps it crosses 0 (the events' bisection looks for that root first).

        Parameters
        ----------
        t : float
            The time (s, path clock), in contact.
        probes : numpy.ndarray
            More springs' coordinates (m), within the contact at ``t``.

        Returns
        -------
        tuple of numpy.ndarray
            The distances at the nodes, whether the nodes' springs are compressed, the distances at the probes.
        """
        probes = np.asarray(probes, dtype=float)
        distance, pressed, _, at_probes = self.outsides(np.array([float(t)]), probes,
                                                        np.zeros(probes.size, dtype=np.intp))
        return distance, pressed, at_probes

    def outsides(self, times, probes: np.ndarray, probe_time: np.ndarray) -> tuple[np.ndarray, ...]:
        """:meth:`outside` at many times at once (one evaluation of the anchors for the springs of all of them, each
        time's as a call at that time alone gives them).

        Parameters
        ----------
        times : array_like
            The times (s, path clock), each in contact.
        probes : numpy.ndarray
            More springs' coordinates (m), each within the contact at its time.
        probe_time : numpy.ndarray
            The index in ``times`` of each probe's time.

        Returns
        -------
        tuple of numpy.ndarray
            The distances at the nodes, whether the nodes' springs are compressed, the index of each node's time (the
            nodes in the order of their times), the distances at the probes.
        """
        times = np.asarray(times, dtype=float)
        probes, probe_time = np.asarray(probes, dtype=float), np.asarray(probe_time, dtype=np.intp)
        nodes, pressed, group = self.nodes_at(times)
        at = times[np.concatenate([group, probe_time])]
        distance = self._anchors(np.concatenate([nodes, probes]), at)[3]
        return distance[:nodes.size], pressed, group, distance[nodes.size:]

    def nodes_at(self, times) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The quadrature's nodes before the kink search at each of ``times`` (:meth:`outsides` reads the springs
        there), whether each node's spring is compressed, and the index of each node's time.

        Parameters
        ----------
        times : array_like
            The times (s, path clock), each in contact.

        Returns
        -------
        tuple of numpy.ndarray
            The nodes (m, in the order of their times), whether compressed, their times' indices.
        """
        times = np.asarray(times, dtype=float)
        nodes, _, group, _ = self._grid(times, np.array([self.radius(float(t)) for t in times])).gauss()
        return nodes, self._d(times[group]) - self.line.profile(nodes) > self._pressed_round_off, group

    def centre_pressed(self, times) -> np.ndarray:
        """Whether the centre probe of the kink search (:data:`EDGE_SHARE` of the radius inside the centre, the
        innermost spring the share reads) counts as compressed at each of ``times``: ``d − g`` above
        :attr:`pressed_round_off`.

        Parameters
        ----------
        times : array_like
            The times (s, path clock).

        Returns
        -------
        numpy.ndarray
            A boolean per time (``False`` out of contact).
        """
        times = np.atleast_1d(np.asarray(times, dtype=float))
        radii = np.array([self.radius(float(t)) for t in times])
        return (radii > 0.0) & (self._d(times) - self.line.profile(EDGE_SHARE * radii) > self._pressed_round_off)

    @property
    def pressed_round_off(self) -> float:
        """A spring counts as compressed (its cap's Coulomb part on) beyond this ``d − g`` (m)."""
        return self._pressed_round_off

    def _grid(self, times: np.ndarray, radii: np.ndarray) -> "_Breaks":
        """The panels' ends at each of ``times`` before the kinks: :data:`PANELS` equal ones on ``[0, a]`` and the
        history's breaks."""
        grid = np.linspace(0.0, radii, PANELS + 1, axis=1)
        extra = [self.history.breaks(float(t)) for t in times]
        rows = [np.union1d(row, more) if more.size else row for row, more in zip(grid, extra)]
        group = np.repeat(np.arange(times.size), [row.size for row in rows])
        return _Breaks(np.concatenate(rows), group, np.zeros(group.size, bool))

    def _quadratures(self, times: np.ndarray, radii: np.ndarray, probes: np.ndarray, probe_time: np.ndarray,
                     kinks: bool | np.ndarray = True) -> "_Quadrature":
        """The quadrature's nodes and weights on ``[0, a]`` at each of ``times`` (Gauss–Legendre on the panels split
        at the history's breaks and, with ``kinks`` (for every time or one per time), the kinks: :meth:`_kinks`), the
        anchors and their provenance there, the index of each node's time (the nodes in the order of their times), the
        provenance at ``probes``, and the springs' ``g`` and ``k_t/G*`` at the nodes (:class:`_Quadrature`)."""
        breaks = self._grid(times, radii)
        kinks = np.broadcast_to(np.asarray(kinks, dtype=bool), times.shape)
        if np.any(kinks):
            return self._kinks(times, breaks, probes, probe_time, kinks)
        nodes, weights, group, _ = breaks.gauss()
        points = np.concatenate([nodes, probes])
        anchor, label = self.anchors(points, times[np.concatenate([group, probe_time])])
        return _Quadrature(nodes, weights, anchor[:nodes.size], label[:nodes.size], group, label[nodes.size:],
                           *(read(points)[:nodes.size] for read in (self.line.profile, self.line.weight)))

    def cap_sides(self, t: float, edge: float) -> tuple[float, float]:
        """The lengths (m) of the springs within ``edge`` at the lower and the upper cap at ``t``, on the quadrature's
        nodes (a zone narrower than any probe's spacing, which the nodes graded at the kinks and breaks hold).

        Parameters
        ----------
        t : float
            The time (s, path clock).
        edge : float
            The springs counted: those at ``ξ < edge`` (m).

        Returns
        -------
        tuple of float
            The lengths at the lower cap (``x − c``) and the upper one.
        """
        a = self.radius(t)
        if not a > 0.0:
            return 0.0, 0.0
        nodes, weights, _, labels, *_ = self._quadratures(np.array([float(t)]), np.array([a]), np.empty(0),
                                                            np.empty(0, dtype=np.intp))
        inside = nodes < edge
        return (float(np.sum(weights[inside & np.isin(labels, LOWER_CAP)])),
                float(np.sum(weights[inside & np.isin(labels, UPPER_CAP)])))

    def _kinks(self, times: np.ndarray, breaks: "_Breaks", probes: np.ndarray, probe_time: np.ndarray,
               searched_times: np.ndarray | None = None) -> "_Quadrature":
        """Each time's ``breaks`` with the kinks between them added: wherever two neighbouring nodes' provenances
        differ (within a panel, across a panel's end, or in the first round between the centre or the edge,
        :data:`EDGE_SHARE` inside it, and the nearest node) and no kink found before lies between them, the change
        located by bisection; repeated until every such pair holds a kink, every round one evaluation of the anchors
        for the times still searched. Returns :meth:`_quadratures`' nodes, weights, anchors, provenance and times of
        the last breaks (:func:`~.play_quadrature._gauss`), the provenance at ``probes`` (read in the first round) and the springs'
        values at the nodes (read with their anchors). The times not ``searched_times`` (default: every time searched)
        end with the first round: their breaks' nodes and the anchors there, spring by spring as
        :meth:`_quadratures` reads them without the kinks (the edges' round-off, which the first round reads with the
        centre's and the edge's springs, decides only where kinks are looked for)."""
        done, probed, active = [], None, np.ones(times.size, bool)
        for round_ in range(KINK_ROUNDS + 1):
            current = breaks.of(active)
            nodes, weights, group, panel = current.gauss()
            inner, inner_group, inner_panel, is_node = nodes, group, panel, slice(None)
            if round_ == 0:  # (a zone between the centre or the edge and the nearest node: the stick zone left at the
                inner, inner_group, inner_panel, is_node = current.with_ends(nodes, group, panel)  # edge before full
                points, at = np.concatenate([inner, probes]), np.concatenate([inner_group, probe_time])  # slip; once:
                anchor, label, edges, _ = self._anchors(points, times[at], at)  # its kink is a break)
                probed, anchor, label, edges = label[inner.size:], anchor[:inner.size], label[:inner.size], \
                    edges[:inner.size]
            else:
                points = inner
                anchor, label, edges, _ = self._anchors(inner, times[inner_group], inner_group)
            values = [read(points)[:inner.size][is_node] for read in (self.line.profile, self.line.weight)]
            # (two springs on the same smooth edge of their windows at t to round-off hold the same anchor whatever
            # their provenance: no kink between them)
            change = np.flatnonzero((inner_group[1:] == inner_group[:-1]) & (label[1:] != label[:-1])
                                    & ((edges[1:] == 0) | (edges[1:] != edges[:-1])))
            found_before = np.cumsum(current.kink)  # (the kinks among the breaks up to each: none between two nodes
            fresh = change[found_before[inner_panel[change + 1]] == found_before[inner_panel[change]]]  # if equal)
            if round_ == 0 and searched_times is not None:
                fresh = fresh[searched_times[inner_group[fresh]]]
            searched = np.zeros(times.size, bool)
            searched[inner_group[fresh]] = True
            finished = (active & ~searched)[group]
            done.append((nodes[finished], weights[finished], group[finished], anchor[is_node][finished],
                         label[is_node][finished], values[0][finished], values[1][finished]))
            if not fresh.size:
                break
            at = inner_group[fresh]
            breaks = breaks.with_kinks(self._bisect(times[at], inner[fresh], inner[fresh + 1], label[fresh]), at)
            active = searched
        else:
            raise RuntimeError(f"the springs' kinks at t={float(times[np.flatnonzero(active)[0]])!r} s were still "
                               f"being found after {KINK_ROUNDS} rounds ({fresh.size} more): a bug to report (the "
                               "force would be summed across a kink)")
        nodes, weights, group, anchor, label, profile, weight = (np.concatenate(column) for column in zip(*done))
        order = np.argsort(group, kind="stable")
        return _Quadrature(nodes[order], weights[order], anchor[order], label[order], group[order], probed,
                           profile[order], weight[order])

    def _bisect(self, t, low: np.ndarray, high: np.ndarray, low_label: np.ndarray) -> np.ndarray:
        """Each bracket (at ``t``, or at its own time of an array of them) cut into :data:`KINK_CUTS` at once, kept where the provenance first differs from ``low``'s,
        until :data:`KINK_HALVINGS` halvings' worth."""
        share = np.arange(1, KINK_CUTS) / KINK_CUTS
        low, high = np.array(low, dtype=float), np.array(high, dtype=float)
        for _ in range(-(-KINK_HALVINGS // int(np.log2(KINK_CUTS)))):
            # (no double between a bracket's ends: every cut is one of them, and the bracket, its provenances read
            # again, stays; such brackets are not cut again, the others' cuts read alone: :data:`SETTLED_BRACKETS`)
            live = np.nextafter(low, high) < high
            if not np.any(live):
                break
            rows = np.flatnonzero(live) if SETTLED_BRACKETS else np.arange(low.size)
            below, above = low[rows], high[rows]
            points = below[:, None] + (above - below)[:, None] * share[None, :]
            at = np.repeat(np.asarray(t)[rows], KINK_CUTS - 1) if np.ndim(t) else t
            same = (self.anchors(points.ravel(), at)[1].reshape(points.shape) == low_label[rows, None])
            first = np.argmin(np.concatenate([same, np.zeros((rows.size, 1), bool)], axis=1), axis=1)
            edges = np.concatenate([below[:, None], points, above[:, None]], axis=1)
            each = np.arange(rows.size)
            low[rows], high[rows] = edges[each, first], edges[each, first + 1]
        return 0.5 * (low + high)

    def tangential_force(self, times) -> np.ndarray:
        """``F_x`` (N) at ``times`` (s, path clock), all of them at once (:meth:`probed_states`).

        Parameters
        ----------
        times : array_like
            The times.

        Returns
        -------
        numpy.ndarray
            The forces.
        """
        times = np.atleast_1d(np.asarray(times, dtype=float))
        self.remember_radii(times)
        states = self.probed_states(times, np.empty(0), np.empty(0, dtype=np.intp))[0]
        return np.array([state.force for state in states])


def _on_edge(anchor, lower, upper, round_off: float, pressed) -> np.ndarray:
    """Which edge of its window at ``t`` each spring's anchor before the clamp at ``t`` lies on to ``round_off``: 0
    none, 1 or 2 the lower or upper with the spring in tension, 3 or 4 compressed (the cap's formula has a kink in
    ``ξ`` at ``x_c``; along either edge on either side of it the anchor is smooth)."""
    side = np.where(np.abs(anchor - lower) <= round_off, 1, np.where(np.abs(upper - anchor) <= round_off, 2, 0))
    return np.where(side > 0, side + 2 * pressed, 0)


def _clamp(anchor, label, lower, upper, live, code):
    """Clamp ``anchor`` to ``[lower, upper]`` where ``live``; where it moved, ``label`` takes ``code`` (+1 lower,
    +2 upper; a negative code −3 or −6: −1 or −4 lower, −2 or −5 upper)."""
    raised = live & ((anchor < lower) | (lower == upper))  # (a window of no width: at its cap, called the lower)
    lowered = live & (anchor > upper) & ~raised
    anchor = np.where(raised, lower, np.where(lowered, upper, anchor))
    if np.all(code < 0):  # (−3: the lower −1, the upper −2; −6: −4 and −5, the spring compressed)
        label = np.where(raised, code + 2, np.where(lowered, code + 1, label))
    else:
        label = np.where(raised, code + _LOWER, np.where(lowered, code + _UPPER, label))
    return anchor, label
