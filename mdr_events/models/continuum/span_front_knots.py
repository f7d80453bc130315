"""Where a slip front crosses a knot of a table's branch inside a span, found for all the knots at once.

A front's ``ξ(level)`` inverts its growth piece, ``Y = x0 + r (d0(ξ) − d_ref)``, whose ``d0`` is a table's PCHIP: the
zone's size, and the right-hand side with it, has a kink of its second derivative where ``ξ`` passes a knot of ``g``
(:attr:`~.branch.TabulatedBranch.knots`), and the quadrature (:mod:`.span_panels`) starts a piece there
(:meth:`~.span.SpanIntegrator.front_knots`). ``ξ`` passes the knot ``k`` where the level reaches the piece's value
there, ``Y(k)``: on the branch above its jump-off (where the inverse lives) ``Y`` is monotone in ``ξ``, so the knots a
level sweeps between two readings are those whose values lie strictly between the level's there (a sorted search),
and each is the root of ``level(var) − Y(k)`` in that bracket.

The levels are read as arrays (:func:`levels`) and every root of a front is refined at once by the Illinois variant of
regula falsi (:func:`bracketed_roots`), a handful of array readings where Brent's method took some five scalar
readings per knot (A at 20° on a 41-point table: 95 knots a run, 2.5 ms of the table's 26; measured in
``benchmarks/bench_simulate.py``). A root is the level's to :data:`ROOT_ULPS` ulp of the variable, as
``scipy.optimize.brentq`` was asked for (``rtol = 4 EPS``): where the knot lands decides where a
piece starts, so its last ulp moves the force by rounding alone (``tests/models/test_tabulated_models.py`` holds the
table's force to the run at ``rtol = 1e-13`` and each knot's ``ξ`` to the knot).
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from .tolerances import EPS

__all__ = ["front_knots", "levels", "bracketed_roots", "ROOT_ULPS", "MAX_ROOT_STEPS"]

#: A root's bracket is narrowed to this many ulp of the variable (``brentq``'s ``rtol = 4 EPS`` before)
ROOT_ULPS = 4.0
#: The Illinois steps a root may take (the levels, smooth between two of the branch's knots, take 5-8 from a bracket
#: there; Illinois' steps converge superlinearly on any continuous function with a simple root)
MAX_ROOT_STEPS = 100


def levels(integrator, cap: float, var: np.ndarray) -> np.ndarray:
    """:meth:`~.span.SpanIntegrator.level` for an array of the span's variable: ``x − cap · (K a + κ d)``, the time of
    a moving span's radius the time its depth is reached (:meth:`~.span.SpanIntegrator.time_of`, by the branch's
    ``depths``).

    Parameters
    ----------
    integrator : SpanIntegrator
        The span.
    cap : float
        The side, +1 or −1.
    var : numpy.ndarray
        The integration variable: the time (s) of a pinned span, the radius over its scale of a moving one.

    Returns
    -------
    numpy.ndarray
        The levels (m), the shape of ``var``.
    """
    var = np.asarray(var, dtype=float)
    segment = integrator.segment
    if integrator.moving:
        radius = var * integrator.scale
        t = segment.time_at_depth(integrator.branch.depths(radius))
    else:
        radius, t = np.full(var.shape, integrator.span.pinned_radius), var
    return segment.x(t) - cap * integrator.caps.centre_shift(radius, segment.d(t))


def bracketed_roots(function: Callable[[np.ndarray, np.ndarray], np.ndarray], low: np.ndarray, high: np.ndarray,
                    at_low: np.ndarray, at_high: np.ndarray) -> np.ndarray:
    """The root of ``function`` in each bracket ``[low, high]`` (its values there of opposite signs), all at once:
    the Illinois variant of regula falsi (the end kept twice in a row has its value halved, so that both ends
    close in), each element until a step moves it by at most :data:`ROOT_ULPS` ulp of itself, or the
    function is 0 there (a point the rounding puts outside its bracket, or not a number, is the middle instead).

    Parameters
    ----------
    function : callable
        ``function(x, which)``: the values at ``x`` of the functions ``which`` (indices into the brackets).
    low, high : numpy.ndarray
        The brackets' ends.
    at_low, at_high : numpy.ndarray
        The values there, of opposite signs.

    Returns
    -------
    numpy.ndarray
        The roots, one a bracket (the last point read, inside its bracket; after :data:`MAX_ROOT_STEPS` steps, the
        last point read).
    """
    a, b = np.array(low, dtype=float), np.array(high, dtype=float)
    fa, fb = np.array(at_low, dtype=float), np.array(at_high, dtype=float)
    roots = np.empty(a.shape)
    which = np.arange(a.size)
    for _ in range(MAX_ROOT_STEPS):
        c = b - fb * (b - a) / (fb - fa)
        c = np.where((np.minimum(a, b) <= c) & (c <= np.maximum(a, b)), c, 0.5 * (a + b))
        fc = function(c, which)
        roots[which] = c
        going = (np.abs(c - b) > ROOT_ULPS * EPS * np.abs(c)) & (fc != 0.0)
        kept = fc * fb > 0.0  # (c on b's side: a stays, its value halved; else b becomes a)
        a, fa = np.where(kept, a, b), np.where(kept, 0.5 * fa, fb)
        b, fb = c, fc
        if not going.all():
            a, b, fa, fb, which = (v[going] for v in (a, b, fa, fb, which))
            if not which.size:
                break
    return roots


def front_knots(integrator, knots: tuple[float, ...], fronts: list, readings: np.ndarray) -> list[float]:
    """The variables, increasing, where a front of ``fronts`` crosses one of ``knots`` between the ``readings``
    (increasing; module docstring): a knot the level sweeps between two readings is where it reaches the piece's value
    there (a knot it crosses twice between two readings is missed, which costs panels, not accuracy).

    Parameters
    ----------
    integrator : SpanIntegrator
        The span.
    knots : tuple of float
        The branch's knots (m), increasing.
    fronts : list of (Cap, Piece)
        The fronts: each cap with its front's growth piece.
    readings : numpy.ndarray
        Where the levels are read: the span's ends and the branch's knots inside it, increasing.

    Returns
    -------
    list of float
        The variables (none: no front crosses a knot).
    """
    found = []
    for cap, p in fronts:
        seen = integrator.zones[cap].anchors
        # (the inverse lives above the branch's jump-off, where Y is monotone in ξ: the knots' values sorted)
        above = np.asarray(knots)[np.asarray(knots) > seen.attach.jump_off_radius]
        values = seen.piece_values(p, above)
        order = np.argsort(values, kind="stable")
        values = values[order]
        sign = float(cap)
        at = levels(integrator, sign, readings)
        lows, highs = np.minimum(at[:-1], at[1:]), np.maximum(at[:-1], at[1:])
        first = np.searchsorted(values, lows, side="right")
        last = np.searchsorted(values, highs, side="left")
        counts = np.maximum(last - first, 0)
        if not counts.any():
            continue
        interval = np.repeat(np.arange(len(readings) - 1), counts)
        target = values[np.concatenate([np.arange(f, f + n) for f, n in zip(first, counts) if n])]
        roots = bracketed_roots(lambda x, which: levels(integrator, sign, x) - target[which],
                                readings[interval], readings[interval + 1],
                                at[interval] - target, at[interval + 1] - target)
        found += roots.tolist()
    return sorted(found)
