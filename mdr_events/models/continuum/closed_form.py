"""A moving span's force in closed form where no front moves through its anchors (issue 28): the springs at each cap
are whole pieces, so every size in the right-hand side of :mod:`.span` is linear in the radius and the force is an
integral of the branch itself.

On the half-space (``M(a) = a``, ``w = 1``, ``ū = K a``) and without a front, each cap's slip zone is the pieces
wholly at it and, where the edge piece is at it, ``[ξ_e, a]``: ``n₊ − n₋ = D₀ + D₁ a`` and the sticking length
``a − n₊ − n₋ = S₀ + S₁ a``. The rate (:meth:`~.span.SpanIntegrator.rhs`)

    dF_x/da = 2G* [(n₊ − n₋)(K + κ d') + (a − n₊ − n₋)(v_x/v_d) d' + (shrinking) u(a)],

with the edge's shift ``u(a) = ±K a`` at a cap, else ``x − Y(a)`` (``x = X₀ + (v_x/v_d) d`` on the segment,
``Y = x₀ + r (d₀(a) − d_ref)`` on the edge's piece, ``d₀`` the branch it attached on), is a sum of ``1``, ``a``,
``d'``, ``a d'``, ``d`` and ``d₀``, whose integrals are ``a``, ``a²/2``, ``d``, ``a d − ∫d`` (by parts), ``∫d`` and
``∫d₀``: the branch's depth and its integral (:meth:`~.branch.Branch.integrals`, closed forms of (9), of a power law
and of a table's PCHIP). So ``F_x(a) = F_x(a₀) + 2G* (P(a) − P(a₀))`` (:class:`Primitive`) with no step at all: a
growing span that sticks (scenario A's first), a shrinking one in full slip (``F_x = ±τ0 π a²``, the last), a growing
one whose inner pieces slide.

The span's events are read at :data:`EVENT_READINGS` equal parts of the span and at its knots (where a table's
``d`` has a kink; a panel's end is where :mod:`.span_panels` reads them) and solved as :func:`~.span_march.march`
solves them. Between two readings an event's function may cross zero and cross back unseen. Readings rule that out
for a function that is monotone between them, or convex in time with direction +1 (it starts below zero: else it
fired at once, :meth:`~.span.SpanIntegrator.met_at_start`; below zero at two readings, it is below its chord, below
zero, between them), or concave with direction −1 (it starts above zero); convexity says nothing of the other
pairings. On a convex branch (``d = g − k√a`` with ``g`` convex: the paraboloid, a power law ``n ≥ 1``) the radius is
concave in the depth, hence in time on a segment (``d`` linear in ``t``), and the events of a closed-form span are:

- ``ZONE_REACHES`` (+1) against a target fixed or linear in ``d`` (a piece's anchors, Coulomb's ``κ d``):
  ``L(t) − K a(t)`` with ``L`` linear, convex: proven;
- ``LEVEL_TURNS`` (−1), the level's rate ``L' − K ȧ``, ``ȧ`` monotone where ``a`` is concave (the function read,
  :meth:`~.span.SpanIntegrator.rate`, is that rate times ``∂d/∂a``: ``cap v_x ∂d/∂a − K v_d``, monotone in the
  radius as ``∂d/∂a`` is on a convex branch): proven;
- ``EDGE_PASSES_PIECE`` (−1), the radius against a fixed one, monotone on a moving span: proven;
- ``ZONE_LEAVES_EDGE`` (+1) never: it is watched only where the edge's piece holds a front
  (``edge_front_outward``), and a span with a front has no closed form (:meth:`~.span.SpanIntegrator.primitive`;
  :func:`span_primitive` raises if it meets one);
- ``ZONE_REACHES`` against the edge's own target: unproven. Its springs attached on ``d₀ = d + (k₁ − k₀)√a``, and
  ``cap·level − cap·Y = L(t) − K a − β √a`` (``β = cap r₀ (k₁ − k₀)``, negative where the edge is a target and
  ``Δγ1 > Δγ0``, the paper's) can be concave with direction +1 (unloading back along the loading line:
  ``c − K a + |β| √a``);
- every event on a branch that is not convex (a table's ``g``, a power law ``n < 1``) or on a layer (``ū = K a/Φ_t``
  need not be linear, nor ``ū'`` constant): unproven, but for the edge passing a piece, linear in the span's variable
  on any branch.

With Coulomb's part the level holds ``κ max(d, 0)`` too, linear in time where the depth keeps its sign on the span
(else a kink, concave in the level: unproven). The span's integrator marks the proven events ``settled``
(:meth:`~.span.SpanIntegrator.levels_convex`, :class:`~.span.EventFunction`) and they are read at the readings alone
(the guard's work on every reading gone: ``solve_path``'s CPU time, best of 200, A 20° 3.42 -> 3.19 ms, B 20°
0.76 -> 0.69 ms, the zigzag 3.16 -> 2.92 ms).
For the unproven ones the guard is a curvature heuristic, not a bound: a part whose readings show no crossing is read
again in between where the curvature read off three readings (times :data:`CURVATURE_SAFETY`) could turn the
function back (:func:`_turn_between`, at most :data:`TURN_READS` readings; spent, the span is the quadrature's). A
function whose curvature inside a part exceeds four times the one read there can still hide a turn. ``tests/models/test_closed_form.py`` compares the
closed form with the quadrature, finds such a turn of the edge's target (and misses it where the event is marked
settled: only a proof may mark one), and samples each settled event of its runs for the shape its proof gives.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

from .rate_march import _crossed
from .span_march import Marched, _first_root
from .state import Cap
from .tolerances import EPS

__all__ = ["Primitive", "ClosedForce", "EVENT_READINGS", "STATIONARY_READINGS", "equal_parts", "span_primitive",
           "closed_span"]

#: Equal parts of a bracket at whose ends :meth:`ClosedForce.stationary` reads the force's rate for a change of sign
#: (a stationary point inside a part is bracketed by it; a double root, touching zero, is not a sign change)
STATIONARY_READINGS = 16
#: Equal parts of a span at whose ends a closed-form span reads its events (besides its knots): as many as the
#: quadrature's panels on the fronts' spans (``MIN_STEPS_PER_SPAN`` of them at least) twice over
EVENT_READINGS = 16
#: The safety factor on the curvature :func:`_hidden` and :func:`_turn_between` read off three points of an event's
#: function. A heuristic, not a bound: a second difference is the curvature at some point between the three (the mean
#: value theorem), not its largest, and 4 admits a curvature four times that one anywhere in the part; e.g. the edge's
#: concave ``|β| √a``, whose curvature ``∝ a^(-3/2)`` grows fourfold where the radius shrinks by ``4^(2/3) ≈ 2.5``
#: between the readings' middle and the part's far end (the sixteen parts of a span are far narrower). A function whose
#: curvature grows faster (a kink between knots, a table's ``g`` not convex) can still hide a turn
CURVATURE_SAFETY = 4.0
#: The budget of :func:`_turn_between`: its readings in all between two of a span's readings, not a depth (a
#: depth-first search of halves, the earlier first: one path may go down to rounding while later halves stay unread;
#: all halves to 64 levels would be ``2⁶⁴`` readings). Spent with halves still uncleared, the span has no closed form
#: (:class:`_Unsettled`: :func:`closed_span` gives ``None``, and the quadrature reads it)
TURN_READS = 64


class _Unsettled(Exception):
    """:func:`_turn_between` spent :data:`TURN_READS` without clearing or finding a crossing."""


class Primitive(NamedTuple):
    """``P(a) = A₀ a + A₁ a²/2 + B₀ d(a) + B₁ (a d(a) − ∫d) + C ∫d + C₀ ∫d₀`` (module docstring), whose derivative is
    ``A₀ + A₁ a + (B₀ + B₁ a) d'(a) + C d(a) + C₀ d₀(a)``.

    Parameters
    ----------
    branch : Branch
        The span's branch ``d(a)``.
    attach : Branch
        The branch ``d₀`` the edge's springs attached on.
    A0, A1, B0, B1, C, C0 : float
        The coefficients.
    """

    branch: object
    attach: object
    A0: float
    A1: float
    B0: float
    B1: float
    C: float
    C0: float

    def __call__(self, a: np.ndarray) -> np.ndarray:
        """``P`` at the radii ``a`` (m), vectorised."""
        a = np.asarray(a, dtype=float)
        return self.combine(a, self.branch.depths(a), self.branch.integrals(a),
                            self.attach.integrals(a) if self.C0 else None)

    def combine(self, a: np.ndarray, depth: np.ndarray, integral: np.ndarray,
                attached: np.ndarray | None) -> np.ndarray:
        """``P`` at the radii ``a`` (m) from the branch's depths ``d(a)`` and integrals ``∫d`` read there, and the
        integrals ``∫d₀`` on the branch of attachment (read only where ``C0`` is not 0, else ``None``): the terms
        summed in one order, whoever read the branches (:meth:`__call__`, or all spans at once in
        :mod:`~mdr_events.models.continuum.span_forces`)."""
        value = a * (self.A0 + 0.5 * self.A1 * a) + self.B0 * depth + self.B1 * (a * depth - integral)
        value = value + self.C * integral
        if self.C0:
            value = value + self.C0 * attached
        return value

    def at(self, a: float) -> float:
        """``P`` at one radius ``a`` (m), in Python floats (the branch's scalar forms: the events' roots read it)."""
        depth, integral = self.branch.depth(a), self.branch.integral(a)
        value = a * (self.A0 + 0.5 * self.A1 * a) + self.B0 * depth + self.B1 * (a * depth - integral)
        value += self.C * integral
        return value + self.C0 * self.attach.integral(a) if self.C0 else value

    @property
    def still(self) -> bool:
        """Whether ``P`` is ``+0`` at every finite radius ``a >= +0`` where the branches' depth and integral are
        finite: every coefficient zero, ``A₀`` and ``A₁`` of positive sign. :meth:`combine` then sums
        ``a (A₀ + A₁ a/2) = +0`` and terms ``0 · (finite)`` of either sign, and ``+0`` plus a zero of either sign is
        ``+0`` (round to nearest): a span that does not move sideways (a vertical path's). ``ClosedForce.__call__``
        reads no branch there, and gives ``+0`` also where a branch is not finite (past a table's end, where
        :meth:`combine` sums ``0 · nan``): every coefficient is zero; no run reads there (a depth beyond the table
        is refused)."""
        return (not (self.A0 or self.A1 or self.B0 or self.B1 or self.C or self.C0)
                and math.copysign(1.0, self.A0) > 0 and math.copysign(1.0, self.A1) > 0)

    @property
    def linear(self) -> bool:
        """Whether the rate is ``A₀ + A₁ a`` alone (``B₀ = B₁ = C = C₀ = 0``: a shrinking span in full slip without
        Coulomb's part, a span that does not move sideways). :meth:`rate` then reads ``A₀ + A₁ a`` plus terms that are
        exactly zero (``0 · d'``, ``0 · d``, finite at a positive radius), each operation rounded monotonically, so its
        readings at increasing radii are monotone in floats as well: of the same sign (or zero) at both ends of an
        interval, none inside is of the other sign (:meth:`ClosedForce.stationary` asks no more of them)."""
        return not (self.B0 or self.B1 or self.C or self.C0)

    def rate(self, a: float) -> float:
        """``dP/da`` at the radius ``a`` (m): what the span's right-hand side reads, over ``2G*``."""
        slope = self.branch.slope(a)
        value = self.A0 + self.A1 * a + (self.B0 + self.B1 * a) * slope + self.C * self.branch.depth(a)
        return value + self.C0 * self.attach.depth(a) if self.C0 else value


def equal_parts(low: float, high: float, parts: int) -> list[float]:
    """``np.linspace(low, high, parts + 1).tolist()`` in Python floats, the same numbers (each ``k · step + low``, or
    ``k / parts · (high − low) + low`` where the step is 0, and ``high`` last), without NumPy's cost for one interval.

    Parameters
    ----------
    low, high : float
        The interval's ends.
    parts : int
        The number of equal parts, at least 1.

    Returns
    -------
    list of float
        The ``parts + 1`` readings from ``low`` to ``high``.
    """
    delta = high - low
    step = delta / parts
    inner = [k * step + low for k in range(parts)] if step != 0 else [k / parts * delta + low for k in range(parts)]
    return inner + [high]


class ClosedForce:
    """A span's force in closed form, called like ``solve_ivp``'s dense output in the span's variable
    (``interpolant(var)[0]``; ``var`` the radius over ``scale``), with its breakpoints ``ts`` (the span's ends, its
    events' readings and its knots: the readers integrate between them, where the force is smooth).

    Parameters
    ----------
    primitive : Primitive
        ``P``.
    start : float
        The span's start (its variable).
    force : float
        ``F_x`` there (N).
    G2 : float
        ``2G*`` (Pa).
    scale : float
        The span's radius per unit of its variable (m).
    ts : list of float
        The breakpoints, from the start to the end.
    """

    def __init__(self, primitive: Primitive, start: float, force: float, G2: float, scale: float, ts: list[float]):
        self.primitive, self.force, self.G2, self.scale = primitive, force, G2, scale
        self.origin = primitive.at(start * scale)
        self.ts = list(ts)

    def stationary(self, low: float, high: float) -> list[float]:
        """The roots of ``dF_x/dvar`` (the primitive's rate) in ``[low, high]``: where it changes sign between
        :data:`STATIONARY_READINGS` equal parts of the interval and the breakpoints, by Brent's method (what
        :mod:`.stationary` reads off a dense output's polynomials, here of the closed form; :meth:`read_stationary`).
        A rate linear in the radius (:attr:`Primitive.linear`) of one sign at both ends has none, and its readings
        would find none: it is read at the ends alone (``tests/models/test_extremum_proofs.py`` compares the two routes).

        Parameters
        ----------
        low, high : float
            The interval (the span's variable), ``low <= high``.

        Returns
        -------
        list of float
            The roots, increasing (none: the force is monotone there).
        """
        rate = lambda var: self.primitive.rate(var * self.scale)  # noqa: E731
        if self.primitive.linear and rate(float(low)) * rate(float(high)) >= 0.0:
            return []  # (the readings' rates are monotone, none of opposite signs: :attr:`Primitive.linear`)
        return self.read_stationary(low, high)

    def read_stationary(self, low: float, high: float) -> list[float]:
        """:meth:`stationary` by the readings alone (no proof asked first: the route the proof of a linear rate
        skips, whose answer it gives); its parameters and returns are :meth:`stationary`'s."""
        grid = sorted({*equal_parts(float(low), float(high), STATIONARY_READINGS),
                       *(t for t in self.ts if low < t < high)})
        rate = lambda var: self.primitive.rate(var * self.scale)  # noqa: E731
        rates = [rate(var) for var in grid]
        # (a rate zero at a reading counts where it changes sign there; one zero throughout, a constant force, has none)
        roots = [grid[k] for k in range(1, len(grid) - 1) if rates[k] == 0.0 and rates[k - 1] * rates[k + 1] < 0.0]
        for k in range(len(grid) - 1):
            if rates[k] * rates[k + 1] < 0.0:
                roots.append(brentq(rate, grid[k], grid[k + 1], xtol=4 * EPS * max(abs(grid[k]), abs(grid[k + 1])),
                                    rtol=4 * EPS))
        return sorted(roots)

    def at(self, var: float) -> float:
        """``F_x`` at one value of the span's variable (N), in Python floats."""
        return self.force + self.G2 * (self.primitive.at(var * self.scale) - self.origin)

    def __call__(self, var) -> np.ndarray:
        """Shape ``(1,)`` for a scalar ``var``, ``(1, n)`` for ``n`` of them, as ``OdeSolution``: NumPy's forms of the
        branch for both, so that a value is the same whether it was asked alone or among others (:meth:`at`, in
        Python floats, can differ from it by rounding). A still primitive (:attr:`Primitive.still`) at finite radii of
        positive sign is ``+0`` without reading its branch (past a table's end too, where the branch is ``nan``)."""
        var = np.asarray(var, dtype=float)
        radii = np.reshape(var, -1) * self.scale
        if self.primitive.still and np.all(np.isfinite(radii)) and not np.any(np.signbit(radii)):
            primitive = np.zeros(radii.shape)  # (P's values, bit for bit: Primitive.still)
        else:
            primitive = self.primitive(radii)
        values = self.force + self.G2 * (primitive - self.origin)
        return np.reshape(values, (1, *var.shape))


def span_primitive(integrator) -> Primitive:
    """``P`` of a moving span without a front on the half-space (:meth:`~.span.SpanIntegrator.primitive` checks it
    is one): its right-hand side's terms, each cap's zone ``inner + (a − ξ_e)`` where the edge piece is at the cap.

    Parameters
    ----------
    integrator : SpanIntegrator
        The span's zones, anchors, segment, branch and caps.

    Returns
    -------
    Primitive
        ``P``, with ``dF_x/da = 2G* dP/da``.
    """
    K, kappa, segment, zones = integrator.K, integrator.kappa, integrator.segment, integrator.zones
    if any(zones[cap].edge_front_outward for cap in Cap):  # (a front at the edge: ZONE_LEAVES_EDGE, module docstring)
        raise RuntimeError("span_primitive: a span whose edge piece holds a front has no closed form (primitive() "
                           "refuses a span with fronts); please report the parameters and path")
    constant, linear = {}, {}
    for cap in Cap:
        zone = zones[cap]
        linear[cap] = 1.0 if zone.edge_in else 0.0
        constant[cap] = zone.inner_length - linear[cap] * zone.pieces[zone.edge].start
    D0, D1 = constant[Cap.POSITIVE] - constant[Cap.NEGATIVE], linear[Cap.POSITIVE] - linear[Cap.NEGATIVE]
    S0 = -constant[Cap.POSITIVE] - constant[Cap.NEGATIVE]
    S1 = 1.0 - linear[Cap.POSITIVE] - linear[Cap.NEGATIVE]
    ratio = segment.vx / segment.vd
    # (n₊ − n₋)(K + κ d') + (a − n₊ − n₋)(v_x/v_d) d'
    A0, A1, B0, B1, C, C0 = D0 * K, D1 * K, D0 * kappa + S0 * ratio, D1 * kappa + S1 * ratio, 0.0, 0.0
    if integrator.shrinking:  # + the edge's shift u(a): ±K a at a cap, else x − Y(a)
        at_cap = [cap for cap in Cap if zones[cap].edge_in_zone]
        edge = integrator.anchors.pieces[-1]
        if at_cap:
            A1 += float(at_cap[0]) * K
        else:  # x = X₀ + (v_x/v_d) d on the segment; Y = x₀ + r (d₀(a) − d_ref) on the edge's piece
            A0 += segment.xs - ratio * segment.ds - edge.x0 + edge.ratio * edge.d_ref
            C, C0 = ratio, -edge.ratio
    return Primitive(integrator.branch, integrator.anchors.attach, A0, A1, B0, B1, C, C0)


def closed_span(primitive: Primitive, start: float, stop: float, force: float, G2: float, scale: float,
                knots: list[float], events: list) -> Marched | None:
    """The span's force in closed form from ``start`` to ``stop`` (its variable) or to the first terminal event, as
    the quadrature's :class:`~.span_march.Marched`.

    Parameters
    ----------
    primitive : Primitive
        ``P`` of the span.
    start, stop : float
        The span's ends (its variable, the radius over ``scale``).
    force : float
        ``F_x`` (N) at the start.
    G2 : float
        ``2G*`` (Pa).
    scale : float
        The span's radius per unit of its variable (m).
    knots : list of float
        The knots inside the span, ordered from its start (readings of the events, breakpoints of the force).
    events : list
        The terminal event functions ``event(var, y)``, each with its ``direction``.

    Returns
    -------
    Marched or None
        The status (0 the end, 1 an event), the force as a :class:`ClosedForce`, each event's root (the first
        terminal one) and the force where it ended; ``None`` where an event's function could cross between two
        readings unread (:data:`TURN_READS` spent): the span has no closed form then.
    """
    parts = equal_parts(float(start), float(stop), EVENT_READINGS)[1:-1]  # (np.linspace's numbers, in Python floats)
    ascending = stop > start
    readings = sorted({*parts, *knots, stop}, reverse=not ascending)
    # (the readings are the force's breakpoints too: a quadrature over the span, tangential_work's, rules between them)
    whole = ClosedForce(primitive, start, force, G2, scale, [start, *readings])
    t_events: list[list[float]] = [[] for _ in events]
    directions = [float(getattr(event, "direction", 0.0)) for event in events]
    # (the readings as Python floats, the same numbers: the layer's levels are NumPy scalars, on which the crossings'
    # tests and the guard's arithmetic cost several times more)
    g, low = [float(event(start, None)) for event in events], start
    g_old, older = g, None  # (the reading before low: the curvature of the three)
    # (the events their readings settle, monotone or convex in their direction, are not read in between: module
    # docstring, :meth:`~.span.SpanIntegrator.levels_convex`)
    settled = [index for index, event in enumerate(events) if getattr(event, "settled", False)]
    try:
        for var in readings:
            g_new = [float(event(var, None)) for event in events]
            active = [index for index in range(len(events)) if _crossed(g[index], g_new[index], directions[index])]
            # (an event whose readings show no crossing may turn back between them: read between where the curvature of
            # three readings could turn it; the first part's is known at the third reading, or read where one fires)
            triple = None if older is None else ((older, low, var), (g_old, g, g_new))
            early = older == start and _hidden(events, directions, (older, low, g_old, g), triple, settled)
            if early:  # (before anything in this part)
                active, hidden = [], early
            elif triple or active:
                hidden = _hidden(events, directions, (low, var, g, g_new), triple, active + settled)
            else:
                hidden = []
            if active or hidden:
                # (the events read the variable alone; the first root in the span's direction, as _first_root
                # orders them)
                found = [_first_root(events, active, _UNREAD, low, var)] if active else []
                found += [_first_root(events, [index], _UNREAD, *bracket) for index, bracket in hidden]
                index, root = min(found, key=lambda pair: pair[1] if ascending else -pair[1])
                t_events[index].append(root)
                inside = [read for read in readings if (start < read < root if ascending else root < read < start)]
                ended = ClosedForce(primitive, start, force, G2, scale, [start, *inside, root])
                return _checked(Marched(1, "", ended, t_events, ended.at(root)))
            g_old, older, g, low = g, low, g_new, var
    except _Unsettled:  # (an event's turn its readings could not rule out: the quadrature's, integrate_span)
        return None
    return _checked(Marched(0, "", whole, t_events, whole.at(stop)))


def _hidden(events: list, directions: list[float], part: tuple, triple: tuple | None,
            skip: list[int]) -> list[tuple[int, tuple[float, float]]]:
    """The events but ``skip`` that cross in their direction inside ``part`` (its ends and the events' values there,
    which show no crossing), each with a bracket of it (:func:`_turn_between`): those that :func:`_clear` does not
    clear by the curvature of ``triple`` (three readings and the events' values there: :data:`CURVATURE_SAFETY` times
    twice their second divided difference; ``None``: each read at the middle)."""
    low, high, g_low, g_high = part
    found = []
    if all(index in skip for index in range(len(events))):  # (every event fired or settled: nothing to read between)
        return found
    if triple is not None:
        (x0, x1, x2), (g0s, g1s, g2s) = triple
        inverse0, inverse1 = 1.0 / (x1 - x0), 1.0 / (x2 - x1)
        # (the curvature per unit of the slopes' difference: twice the second divided difference, times the safety)
        reach = 2.0 * CURVATURE_SAFETY / abs(x2 - x0)
    for index in range(len(events)):
        if index in skip:
            continue
        before, after = g_low[index], g_high[index]
        if triple is not None:
            bound = reach * abs((g2s[index] - g1s[index]) * inverse1 - (g1s[index] - g0s[index]) * inverse0)
            if _clear(before, after, high - low, bound):
                continue  # (monotone there, or kept to its readings' side)
        bracket = _turn_between(events[index], directions[index], low, high, before, after)
        if bracket:
            found.append((index, bracket))
    return found


def _clear(g_left: float, g_right: float, width: float, bound: float) -> bool:
    """Whether a function with these values at the ends of an interval ``width`` long, its curvature within ``bound``,
    neither turns inside (its chord's slope beyond what the curvature can turn, ``bound · width``) nor leaves its
    ends' sign (their values beyond the curvature's bulge over the chord, ``bound · width²/8``)."""
    monotone = abs(g_right - g_left) > bound * width * width
    aside = (g_left > 0.0) == (g_right > 0.0) and min(abs(g_left), abs(g_right)) > bound * width * width / 8.0
    return monotone or aside


def _turn_between(event, direction: float, low: float, high: float, before: float, after: float) -> tuple[float, float] | None:
    """A bracket inside ``[low, high]`` (two readings whose values ``before`` and ``after`` show no crossing) across
    which ``event`` crosses zero in its ``direction`` (none: it cannot, by its curvature).

    The event is read at the middle of the interval; each half is passed over where :func:`_clear` clears it by
    :data:`CURVATURE_SAFETY` times the curvature read off the three points, else read at its own middle, the earlier
    half first, at most :data:`TURN_READS` readings in all.

    Raises
    ------
    _Unsettled
        The readings spent with a half still neither cleared nor crossed (a possible crossing left unread).
    """
    pending = [(low, high, before, after)]
    for _ in range(TURN_READS):
        if not pending:
            return None
        low, high, before, after = pending.pop()
        middle = 0.5 * (low + high)
        value = event(middle, None)
        if _crossed(before, value, direction):
            return low, middle
        if _crossed(value, after, direction):
            return middle, high
        half = abs(middle - low)
        if not half * half > 0.0:  # (a half of no length, to rounding: nothing between its readings)
            continue
        bound = CURVATURE_SAFETY * abs(before - 2.0 * value + after) / (half * half)
        if not bound < math.inf:  # (an overflow: the curvature read off rounding)
            continue
        halves = [(low, middle, before, value), (middle, high, value, after)]
        pending += [piece for piece in reversed(halves) if not _clear(piece[2], piece[3], half, bound)]
    if not pending:
        return None
    raise _Unsettled(f"{len(pending)} half(s) uncleared after {TURN_READS} readings")


def _checked(marched: Marched) -> Marched:
    """``marched``, or the quadrature's failure (status -1, no dense output: :func:`~.integrate.integrate_span` raises
    it) where the force where it ended is not finite (the primitive's value there or at the start: a NaN or an
    infinity of the branch's closed forms would be passed on as the span's force, where the quadrature's panels
    shrink and fail)."""
    if math.isfinite(marched.y):
        return marched
    return Marched(-1, f"the force in closed form is not finite at {marched.sol.ts[-1]!r} (F_x = {marched.y!r})", None,
                   marched.t_events, marched.y)


def _UNREAD(var: float) -> None:
    """The state an event is handed while its root is sought: none (it reads the span's variable alone)."""
    return None
