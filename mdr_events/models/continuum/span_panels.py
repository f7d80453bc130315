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
``max_step``, and at most the length the last panel's error allows): a smooth span takes a few panels of :data:`NODES`
``+ 1`` readings where DOP853 took steps of 12 and three more for its dense output. Between a table's knots, where the
pieces are short, the panels are Gauss–Radau's (:func:`radau_rule`, :data:`PIECE_NODES`): their first point is the
panel's start, read once as the panel before's check at its end.

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

from mdr_events.validation import shown

from .rate_march import _crossed
from .span_march import Marched, _first_root
from .tolerances import EPS

__all__ = ["panels", "NODES", "PIECE_NODES", "Rule", "rule", "radau_rule", "panel_rows"]

#: Gauss–Legendre points of a panel: the right-hand side's interpolant has degree ``NODES − 1``, the force's
#: ``NODES`` (the degree of DOP853's dense output, which the readers of a span's interpolant expect)
NODES = 7
#: Gauss–Radau points of a panel between a table's knots (:func:`radau_rule`), where every piece is a panel or more
#: (some hundred a span: a 41-point table's ``g`` is a PCHIP on a grid four times finer, a piece ~1/120 of a span): the
#: first point is the panel's start, whose reading is the panel before's check at its end, so a panel takes 5 new
#: readings with its check (exact to degree 8; 4 Gauss–Legendre points and their check took as many), and each piece is first tried at the length the last panel's error
#: allows where that is shorter than the piece (a whole piece tried and cut cost 14 % of the panels). Measured on that
#: table (readings of ``solve_path``; ``F_x`` against the run at ``rtol = 1e-13``, a share of its largest value): A at
#: 20° 855 readings, 3.7e-12 with 4 Gauss–Legendre points and their check; 723, 2.2e-12 with these (4 Gauss–Radau
#: points: 731, 3.4e-12); A at 40° 540 -> 382, the zigzag 115 -> 72. (Gauss–Legendre's 3 points cut the panels four
#: times as often as 4.)
PIECE_NODES = 5
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
    shared : bool
        Whether the first point is the panel's start (Gauss–Radau's rule, :func:`radau_rule`): the reading there is
        the panel before's check at its end, taken once for both (default ``False``: Gauss–Legendre's, inside).
    """

    count: int
    nodes: np.ndarray
    weights: np.ndarray
    rows: np.ndarray
    at_end: np.ndarray
    shared: bool = False


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
    _check_count(count, 1)
    points, weights = np.polynomial.legendre.leggauss(count)
    nodes, weights = 0.5 * (points + 1.0), 0.5 * weights
    rows, at_end, _ = _matrices(nodes)
    return Rule(count, nodes, weights, rows, at_end)


@functools.lru_cache(maxsize=None)
def radau_rule(count: int = PIECE_NODES) -> Rule:
    """The :class:`Rule` of ``count`` Gauss–Radau points (``2 <= count <= NODES``), the first at the panel's start
    (``x = 0``), the others the roots of ``(P_{count−1} + P_count)/(1 + t)`` mapped onto ``(0, 1)``: exact for
    polynomials of degree ``2 count − 2``, and its first reading is the panel before's check at its end
    (:attr:`Rule.shared`), so a panel takes ``count`` new readings with its check where Gauss–Legendre's takes
    ``count + 1``. The weights are the nodes' Lagrange basis integrated over ``[0, 1]`` in 40 digits (:func:`rule`'s
    matrices).

    Parameters
    ----------
    count : int, default PIECE_NODES
        The rule's points.

    Returns
    -------
    Rule
        Its nodes, weights and matrices.
    """
    _check_count(count, 2)
    roots = np.polynomial.legendre.legroots([0.0] * (count - 1) + [1.0, 1.0])
    inner = np.sort(roots[np.abs(roots + 1.0) > 0.5 / count])  # (the root t = −1 of P_{n−1} + P_n is the start's)
    nodes = np.concatenate([[0.0], 0.5 * (inner + 1.0)])
    rows, at_end, weights = _matrices(nodes)
    return Rule(count, nodes, weights, rows, at_end, True)


def _check_count(count: int, least: int) -> None:
    """Refuse a rule's ``count`` outside ``[least, NODES]`` by name."""
    if not least <= count <= NODES:
        raise ValueError(f"count={shown(count)} is not allowed; allowed: a whole number of points in [{least}, {NODES}]")


def _matrices(nodes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The rows' matrix, the interpolant's weights at ``x = 1`` and the integral's weights over ``[0, 1]`` of a
    rule's ``nodes`` (as they are in double precision), worked out in 40 digits (``mpmath``), then rounded."""
    count = len(nodes)
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
        return (np.array(rows.tolist(), dtype=float), np.array([float(v) for v in at_end]),
                np.array([float(integrals[NODES - 1, i]) for i in range(count)]))


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


def _panel(quadrature: _Quadrature, low: float, h: float, end: float) -> tuple[np.ndarray, float, float]:
    """The readings at a panel's nodes, the error of the force's interpolant checked at its end and the reading
    there. A rule whose first node is the start (:attr:`Rule.shared`) reads the end at ``end`` (the panel's end as
    the next panel starts from it) and takes the start's reading from :attr:`_Quadrature.shared` where it holds it;
    Gauss–Legendre's reads the end at ``low + h``."""
    rhs, panel_rule, shared = quadrature.rhs, quadrature.rule, quadrature.shared
    if not panel_rule.shared:
        readings = np.array([rhs(low + h * x, None)[0] for x in panel_rule.nodes])
        reading = rhs(low + h, None)[0]
        return readings, abs(h) * abs(reading - float(panel_rule.at_end @ readings)), reading
    if shared[0] != low:  # (the first panel, or one after an event's root: read the start, kept for a retry)
        shared[:] = [low, rhs(low, None)[0]]
    # (the nodes as Python floats: the right-hand side's arithmetic on NumPy scalars cost a third more, and its memos
    # key Python floats alone)
    readings = np.array([shared[1], *(rhs(low + h * x, None)[0] for x in panel_rule.nodes[1:].tolist())])
    reading = rhs(end, None)[0]
    return readings, abs(h) * abs(reading - float(panel_rule.at_end @ readings)), reading


class _Panel(NamedTuple):
    """An accepted panel: its end, its dense output, the force there, the next panel's length (unsigned) and the
    length its error allows (the next's without :data:`MOST_FACTOR`'s bound: what the next piece starts from,
    :func:`panels`)."""

    end: float
    dense: Dop853DenseOutput
    force: float
    next_length: float
    allowed: float


class _Quadrature(NamedTuple):
    """What every panel of one :func:`panels` call is read and held to: the right-hand side, the tolerances, the
    longest panel and the rule; ``shared``, ``[var, reading]``, the right-hand side's last reading at an accepted
    panel's end (or a start read for a retry), which a rule of :attr:`Rule.shared` takes as its next start's."""

    rhs: Callable
    rtol: float
    atol: float
    max_step: float
    rule: Rule
    shared: list


def _accepted(quadrature: _Quadrature, low: float, high: float, length: float, force: float) -> _Panel | None:
    """The next panel from ``low`` towards ``high`` (first tried ``length`` long, cut until its error is within the
    tolerances; the last one ends on ``high`` exactly), or ``None`` where it would be shorter than
    :data:`LEAST_PANEL_ULPS` ulp."""
    _, rtol, atol, _, panel_rule, shared = quadrature
    while True:
        h = math.copysign(length, high - low)
        last = abs(high - low) - length <= LEAST_PANEL_ULPS * EPS * max(abs(low), abs(high))
        if last:  # (the piece's end exactly, no sliver left before it)
            h = high - low
        end = high if last else low + h
        readings, error, reading = _panel(quadrature, low, h, end)
        rows = panel_rows(readings, h, panel_rule)
        end_force = force + float(rows[0, 0])
        ratio = error / (atol + rtol * max(abs(force), abs(end_force)))
        exponent = -1.0 / (panel_rule.count + 1)
        factor = min(MOST_FACTOR, SAFETY * ratio ** exponent) if ratio > 0.0 else MOST_FACTOR
        if not math.isfinite(ratio):  # (a reading that is not finite: shrink until the panel is too short)
            factor = LEAST_FACTOR
        if ratio <= 1.0:
            shared[:] = [end, reading]
            allowed = abs(h) * SAFETY * ratio ** exponent if ratio > 0.0 else math.inf
            return _Panel(end, Dop853DenseOutput(low, end, np.array([force]), rows), end_force, abs(h) * factor,
                          allowed)
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
    quadrature = _Quadrature(rhs, rtol, atol, max_step, panel_rule or rule(), [math.nan, math.nan])
    ts, interpolants = [pieces[0][0]], []
    t_events: list[list[float]] = [[] for _ in events]
    directions = [float(getattr(event, "direction", 0.0)) for event in events]
    g = [event(pieces[0][0], None) for event in events]
    allowed = math.inf
    for low, high in pieces:
        # (a piece is first tried whole, or at the length the last panel's error allows where that is shorter)
        length = min(abs(high - low), max_step, allowed)
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
            allowed = panel.allowed
    return Marched(0, "", OdeSolution(ts, interpolants), t_events, force)
