"""A span's force as a quadrature, not an ODE: where the right-hand side and the events depend on the span's variable
alone (never on ``F_x``: :class:`~.split_span.SplitSpanIntegrator`), ``F_x(v) = F_x(v_0) + ∫ rhs`` is integrated by
panels of Gauss–Legendre's rule, each with its dense output, instead of DOP853's steps.

A panel ``[v_0, v_0 + h]`` reads the right-hand side at the :data:`NODES` Gauss–Legendre points; the force over it is
the integral of their interpolant, a polynomial of degree :data:`NODES` in ``x = (v − v_0)/h`` (DOP853's degree,
:data:`~.stationary.DENSE_DEGREE`), stored as ``scipy``'s ``Dop853DenseOutput`` (the nested products of its
``_call_impl``: :mod:`.dense` and :mod:`.stationary` read it as any DOP853 step) and ending on the rule's value,
exact for polynomials of degree ``2 NODES − 1``. One more reading, at the panel's end (where the nodes' polynomial is
largest: a pessimistic check), against the interpolant gives the panel's error, ``h |rhs − P|``, held to the
solver's tolerances as DOP853 holds its own (``atol + rtol max(|F_0|, |F_1|)``); a panel is accepted or cut by
``(1/error)^(1/(NODES + 1))`` as an ODE solver picks its steps. Each piece starts as one panel (at most
``max_step``): a smooth span takes a few panels of :data:`NODES` ``+ 1`` readings where DOP853 took steps of 12 and
three more for its dense output.

The events are read at each panel's end and solved as :func:`~.span_march.march` solves them (``solve_ivp``'s rule of
a crossing, Brent's method on the panel, the first terminal root): :func:`panels` returns its
:class:`~.span_march.Marched`. ``tests/models/test_span_panels.py`` compares both routes.
"""

from __future__ import annotations

import functools
import math
from typing import Callable, NamedTuple

import mpmath
import numpy as np
from scipy.integrate import OdeSolution
from scipy.integrate._ivp.rk import Dop853DenseOutput

from .rate_march import _crossed
from .span_march import Marched, _first_root
from .tolerances import EPS

__all__ = ["panels", "NODES", "PIECE_NODES", "Rule", "rule", "panel_rows"]

#: Gauss–Legendre points of a panel: the right-hand side's interpolant has degree ``NODES − 1``, the force's
#: ``NODES`` (the degree of DOP853's dense output, which the readers of a span's interpolant expect)
NODES = 7
#: Gauss–Legendre points of a panel between a table's knots, where every piece is a panel or more (some hundred a
#: span: a 41-point table's ``g`` is a PCHIP on a grid four times finer, a piece ~1/120 of a span): the rule's error
#: ``∝ h⁹`` is far below the tolerances on so short a piece, and 5 readings a panel (4 and the check) take the place of
#: 8. Measured on that table (readings and CPU time of ``solve_path``; ``F_x`` against the run at ``rtol = 1e-13``, a
#: share of its largest value): A at 20° 3208 readings, 45.9 ms, 1.7e-10 with 7 points; 2455, 37.3 ms, 3.5e-10 with 4;
#: with 3 the panels are cut four times as often (1629 panels, 67 ms); the zigzag 24.7 -> 17.1 ms
PIECE_NODES = 4
#: A panel's next length is at most this many times the last (and at least :data:`LEAST_FACTOR` of it), times
#: :data:`SAFETY` of what the error asks (an ODE solver's usual bounds)
MOST_FACTOR, LEAST_FACTOR, SAFETY = 10.0, 0.2, 0.9
#: A panel shorter than this many ulp of its variable fails, as DOP853 fails on a step too small
LEAST_PANEL_ULPS = 10.0


class Rule(NamedTuple):
    """A panel's Gauss–Legendre rule and the matrices that turn its readings into a dense output of :data:`NODES` rows.

    Parameters
    ----------
    count : int
        The rule's points (the right-hand side's interpolant has degree ``count − 1``, the force's ``count``).
    nodes, weights : numpy.ndarray
        The points and weights on ``[0, 1]``.
    rows : numpy.ndarray
        The matrix, ``(NODES, count)``, from the readings to the rows ``F`` of ``Dop853DenseOutput`` (per unit ``h``).
    at_end : numpy.ndarray
        The interpolant's weights at ``x = 1``.
    """

    count: int
    nodes: np.ndarray
    weights: np.ndarray
    rows: np.ndarray
    at_end: np.ndarray


@functools.lru_cache(maxsize=None)
def rule(count: int = NODES) -> Rule:
    """The :class:`Rule` of ``count`` Gauss–Legendre points (``1 <= count <= NODES``): the matrices worked out in 40
    digits (``mpmath``) from the nodes as they are in double precision, then rounded. A rule of fewer points than
    :data:`NODES` gives a force of lower degree, stored in the same rows (the nested basis of ``Dop853DenseOutput``
    spans every polynomial of degree up to :data:`NODES` that vanishes at ``x = 0``).

    Parameters
    ----------
    count : int, default NODES
        The rule's points.

    Returns
    -------
    Rule
        Its nodes, weights and matrices.
    """
    if not 1 <= count <= NODES:
        raise ValueError(f"count={count!r} is not allowed; allowed: a whole number of points in [1, {NODES}]")
    points, weights = np.polynomial.legendre.leggauss(count)
    nodes, weights = 0.5 * (points + 1.0), 0.5 * weights
    with mpmath.workdps(40):
        x = [mpmath.mpf(float(v)) for v in nodes]
        # the Lagrange basis of the nodes in powers of x (a column each), integrated from 0 and read at NODES points
        # of (0, 1]; the nested basis of Dop853DenseOutput, x (1 − x) x (1 − x) …, read there too
        lagrange = mpmath.inverse(mpmath.matrix([[v**k for k in range(count)] for v in x]))
        probe = [mpmath.mpf(k) / NODES for k in range(1, NODES + 1)]
        integrals = mpmath.matrix([[sum(lagrange[k, i] * p ** (k + 1) / (k + 1) for k in range(count))
                                    for i in range(count)] for p in probe])
        nested = mpmath.matrix([[_nested(p, j) for j in range(NODES)] for p in probe])
        rows = mpmath.inverse(nested) * integrals
        at_end = [sum(lagrange[k, i] for k in range(count)) for i in range(count)]
        return Rule(count, nodes, weights, np.array(rows.tolist(), dtype=float),
                    np.array([float(v) for v in at_end]))


def _nested(x, j: int):
    """The ``j``-th function of ``Dop853DenseOutput``'s nested products at ``x``: ``x``, ``x (1 − x)``,
    ``x² (1 − x)``, … (the row ``F[j]`` is its coefficient)."""
    value = 1
    for i in range(j + 1):
        value *= x if i % 2 == 0 else 1 - x
    return value


def panel_rows(readings: np.ndarray, h: float, panel_rule: Rule | None = None) -> np.ndarray:
    """The rows ``F`` of ``Dop853DenseOutput`` of a panel of length ``h`` from the right-hand side's readings at its
    nodes, the first one set to the rule's value (the force's change over the panel, exactly as the rule sums it).

    Parameters
    ----------
    readings : numpy.ndarray
        The right-hand side at the panel's points (``v_0 + h x_i``).
    h : float
        The panel's length (signed: the variable may fall).
    panel_rule : Rule, optional
        The panel's rule (default the :data:`NODES`-point one).

    Returns
    -------
    numpy.ndarray
        ``F``, of shape ``(NODES, 1)``.
    """
    panel_rule = panel_rule or rule()
    rows = h * (panel_rule.rows @ readings)
    rows[0] = h * float(panel_rule.weights @ readings)
    return rows.reshape(NODES, 1)


def _panel(rhs: Callable, low: float, h: float, panel_rule: Rule) -> tuple[np.ndarray, float]:
    """The readings at a panel's nodes and the error of the force's interpolant checked at its end."""
    readings = np.array([rhs(low + h * x, None)[0] for x in panel_rule.nodes])
    end = rhs(low + h, None)[0]
    return readings, abs(h) * abs(end - float(panel_rule.at_end @ readings))


class _Panel(NamedTuple):
    """An accepted panel: its end, its dense output, the force there and the next panel's length (unsigned)."""

    end: float
    dense: Dop853DenseOutput
    force: float
    next_length: float


class _Quadrature(NamedTuple):
    """What every panel of one :func:`panels` call is read and held to: the right-hand side, the tolerances, the
    longest panel and the rule."""

    rhs: Callable
    rtol: float
    atol: float
    max_step: float
    rule: Rule


def _accepted(quadrature: _Quadrature, low: float, high: float, length: float, force: float) -> _Panel | None:
    """The next panel from ``low`` towards ``high`` (first tried ``length`` long, cut until its error is within the
    tolerances; the last one ends on ``high`` exactly), or ``None`` where it would be shorter than
    :data:`LEAST_PANEL_ULPS` ulp."""
    rhs, rtol, atol, _, panel_rule = quadrature
    while True:
        h = math.copysign(length, high - low)
        last = abs(high - low) - length <= LEAST_PANEL_ULPS * EPS * max(abs(low), abs(high))
        if last:  # (the piece's end exactly, no sliver left before it)
            h = high - low
        readings, error = _panel(rhs, low, h, panel_rule)
        rows = panel_rows(readings, h, panel_rule)
        end_force = force + float(rows[0, 0])
        ratio = error / (atol + rtol * max(abs(force), abs(end_force)))
        factor = min(MOST_FACTOR, SAFETY * ratio ** (-1.0 / (panel_rule.count + 1))) if ratio > 0.0 else MOST_FACTOR
        if not math.isfinite(ratio):  # (a reading that is not finite: shrink until the panel is too short)
            factor = LEAST_FACTOR
        if ratio <= 1.0:
            end = high if last else low + h
            return _Panel(end, Dop853DenseOutput(low, end, np.array([force]), rows), end_force, abs(h) * factor)
        length = abs(h) * max(LEAST_FACTOR, factor)
        if length < LEAST_PANEL_ULPS * EPS * max(abs(low), abs(high)):
            return None


def _fill(quadrature: _Quadrature, low: float, high: float, force: float, length: float, ts: list,
          interpolants: list) -> float | None:
    """Panels from ``low`` to ``high`` appended to ``ts`` and ``interpolants`` (no event watched); the force at
    ``high``, or ``None`` where a panel failed."""
    while low != high:
        panel = _accepted(quadrature, low, high, min(length, abs(high - low), quadrature.max_step), force)
        if panel is None:
            return None
        ts.append(panel.end)
        interpolants.append(panel.dense)
        low, force, length = panel.end, panel.force, panel.next_length
    return force


def panels(rhs: Callable, pieces: list[tuple[float, float]], force: float, events: list, rtol: float, atol: float,
           max_step: float, panel_rule: Rule | None = None) -> Marched:
    """Integrate ``dF/dvar = rhs(var)`` (``rhs(var, y)``, ``y`` unused) over consecutive ``pieces`` from ``force`` by
    panels, to the end of the last or the first terminal event (module docstring).

    A panel in which an event fires is integrated again up to the event's root (a panel's readings beyond it would
    read the right-hand side past a change of the zones, where it need not be smooth).

    Parameters
    ----------
    rhs : callable
        ``rhs(var, y)`` returning a sequence of one value; it must not read ``y`` (passed as ``None``).
    pieces : list of (float, float)
        The pieces ``(low, high)`` of the variable, each starting where the one before ends (a panel never crosses
        the end of a piece: a knot of the right-hand side).
    force : float
        The initial value at the first piece's start.
    events : list
        The terminal event functions ``event(var, y)``, each with its ``direction``.
    rtol, atol : float
        The tolerances each panel's error is held to.
    max_step : float
        The longest panel.
    panel_rule : Rule, optional
        The panels' rule (default the :data:`NODES`-point one; fewer points where the pieces are short, between a
        table's knots: :data:`PIECE_NODES`).

    Returns
    -------
    Marched
        As :func:`~.span_march.march` returns it: the status (0 the end, 1 an event, -1 a panel too short), the
        joined dense output, each event's root (the first terminal one) and the force where it ended.
    """
    quadrature = _Quadrature(rhs, rtol, atol, max_step, panel_rule or rule())
    ts, interpolants = [pieces[0][0]], []
    t_events: list[list[float]] = [[] for _ in events]
    directions = [float(getattr(event, "direction", 0.0)) for event in events]
    g = [event(pieces[0][0], None) for event in events]
    for low, high in pieces:
        length = min(abs(high - low), max_step)
        while low != high:
            panel = _accepted(quadrature, low, high, length, force)
            if panel is None:
                return Marched(-1, f"a panel too short at {low!r}", None, t_events, force)
            g_new = [event(panel.end, None) for event in events]
            active = [index for index in range(len(events)) if _crossed(g[index], g_new[index], directions[index])]
            if active:
                index, root = _first_root(events, active, panel.dense, low, panel.end)
                t_events[index].append(root)
                if root == low and len(ts) == 1:  # (solve_ivp keeps a first step of zero length)
                    return Marched(1, "", OdeSolution([low, low], [panel.dense]), t_events, force)
                force = _fill(quadrature, low, root, force, abs(root - low), ts, interpolants)
                if force is None:
                    return Marched(-1, f"a panel too short before {root!r}", None, t_events, force)
                return Marched(1, "", OdeSolution(ts, interpolants), t_events, force)
            ts.append(panel.end)
            interpolants.append(panel.dense)
            g, force, low = g_new, panel.force, panel.end
            length = min(panel.next_length, abs(high - low), max_step)
    return Marched(0, "", OdeSolution(ts, interpolants), t_events, force)
