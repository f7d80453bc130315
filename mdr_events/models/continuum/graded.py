"""A span's variable graded towards a singular end: ``x_c = g⁻¹(d) ∝ d^(1/n)`` where a span with ``x_c`` moving ends at
the surface (``d → 0``), so the force's rate has a term ``∝ (v_stop − v)^(1/n)`` there, against which DOP853 shrinks
its steps tenfold, rejecting many (300 evaluations of the right-hand side on scenario A at 20°, of the run's 1400).
With ``v = origin + reach u^p`` (``u`` from 1 at the start to 0 at the stop: :class:`Grading`; ``p`` a whole
multiple of ``n``, :func:`grading_power`) ``x_c ∝ u^(p/n)`` is smooth at ``u = 0``: the span takes a few steps
(:func:`graded_problem`; 300 → 47 evaluations on that span). A front reaching the centre of a part in
``ξⁿ`` moves as ``(t_e − t)^(1/n)``: on a pinned span whose level is linear in time, ``t_e`` is a closed form and the
span is graded towards it, ending there with its event (:attr:`Grading.event`). The span keeps its grading (:attr:`~.span_record.Span.grading`): its dense output is in ``u``, and
whatever reads it at a time or a radius goes through :meth:`Grading.graded` (:func:`span_variable`).
"""

from __future__ import annotations

import math
from typing import Callable, NamedTuple

import numpy as np

__all__ = ["Grading", "GradedEvent", "SpanProblem", "graded_problem", "grading_power", "span_variable", "natural_variable", "MAX_POWER"]


class Grading(NamedTuple):
    """The natural variable ``v`` (the time, or the radius over the span's scale) of a graded span,
    ``v = origin + reach u^p`` (:func:`grading_power`)."""

    origin: float  #: ``v`` at the span's stop (``u = 0``), its singular end
    reach: float   #: ``v`` at the start less ``origin`` (``u = 1``)
    power: int = 2  #: ``p``
    #: the key of the event at ``origin`` (a front reaching the centre at a time known in closed form; ``None``: the
    #: origin is the span's planned stop)
    event: tuple | None = None

    def natural(self, u):
        """``v`` at ``u``.

        Parameters
        ----------
        u : float or numpy.ndarray
            The graded variable.

        Returns
        -------
        float or numpy.ndarray
            ``origin + reach u^p``.
        """
        return self.origin + self.reach * u**self.power

    def graded(self, v):
        """``u`` at ``v`` (0 at or beyond the stop).

        Parameters
        ----------
        v : float or numpy.ndarray
            The natural variable.

        Returns
        -------
        float or numpy.ndarray
            ``((v − origin)/reach)^(1/p)``.
        """
        if np.ndim(v) == 0:
            return max((float(v) - self.origin) / self.reach, 0.0) ** (1.0 / self.power)
        return np.maximum((np.asarray(v, dtype=float) - self.origin) / self.reach, 0.0) ** (1.0 / self.power)

    def rate(self, u):
        """``dv/du`` at ``u``.

        Parameters
        ----------
        u : float or numpy.ndarray
            The graded variable.

        Returns
        -------
        float or numpy.ndarray
            ``p reach u^(p−1)``.
        """
        return self.power * self.reach * u ** (self.power - 1)


def grading_power(tip: float | None) -> int | None:
    """The least whole power ``p`` that makes ``d^(1/n) ∝ u^(p/n)`` and ``v`` smooth in ``u``: ``n`` where it is whole,
    ``2n`` where that is (``n = 1.5``: 3); ``None`` for ``n <= 1`` (no steep end: the cone's ``x_c ∝ d``), another
    ``n``, or a profile that is not a power at its tip.

    Parameters
    ----------
    tip : float or None
        The power ``n`` of the profile at its tip (:attr:`~.branch.Branch.tip_power`).

    Returns
    -------
    int or None
        ``p``.
    """
    if tip is None or not tip > 1.0:
        return None
    for power in (tip, 2.0 * tip):
        if power == round(power) and power <= MAX_POWER:
            return int(power)
    return None


#: The highest power :func:`grading_power` gives (``u^p`` of a higher one spans too many decades of ``v`` near the stop)
MAX_POWER = 6


class GradedEvent:
    """An event function of the natural variable read in the graded one (its key, trigger, cap and direction kept:
    the direction is along the integration, which ``u`` runs as ``v`` does)."""

    terminal = True

    def __init__(self, event, grading: Grading):
        self.event, self.grading = event, grading
        self.direction = event.direction
        self.trigger, self.cap = event.trigger, event.cap

    @property
    def key(self):
        """The wrapped event's key.

        Returns
        -------
        tuple
            As the event's.
        """
        return self.event.key

    def __call__(self, u: float, y=None) -> float:
        return self.event(self.grading.natural(u))


class SpanProblem(NamedTuple):
    """What the solver integrates on a span: its right-hand side, events, ends, knots and longest step, in the
    span's variable (``u`` on a graded span, :func:`graded_problem`; else the natural one).

    Attributes
    ----------
    rhs : callable
        ``dF/dvar`` of the variable and the force.
    events : list
        The event functions of the variable.
    start, stop : float
        The variable's ends.
    knots : list
        The knots of the right-hand side strictly between them.
    max_step : float
        The solver's longest step (``inf``: none).
    """

    rhs: Callable
    events: list
    start: float
    stop: float
    knots: list
    max_step: float


def graded_problem(integrator, grading: Grading, events: list, steps: int) -> SpanProblem:
    """The span of ``integrator`` in the graded variable: ``dF/du = (dF/dv)(v(u)) dv/du``, the events of ``v(u)``,
    ``u`` from 1 to 0, the knots mapped, at most ``1/steps`` of the span a step where the integrator limits its steps.

    Parameters
    ----------
    integrator : SpanIntegrator
        The span's right-hand side and events in the natural variable.
    grading : Grading
        The grading.
    events : list of EventFunction
        The span's events.
    steps : int
        The least steps of a limited span.

    Returns
    -------
    SpanProblem
        The problem in ``u``.
    """
    natural, rate, rhs = grading.natural, grading.rate, integrator.rhs

    def graded_rhs(u: float, y) -> list[float]:
        return [rhs(natural(u), y)[0] * rate(u)]

    limited = math.isfinite(integrator.max_step())
    return SpanProblem(graded_rhs, [GradedEvent(event, grading) for event in events], 1.0, 0.0,
                         [grading.graded(knot) for knot in integrator.knots()], 1.0 / steps if limited else math.inf)


def span_variable(span, natural):
    """The variable a span's dense output is read at, from its natural variable (the time, or the radius over its
    scale): ``u`` on a graded span, else the same.

    Parameters
    ----------
    span : Span
        The span.
    natural : float or numpy.ndarray
        The natural variable.

    Returns
    -------
    float or numpy.ndarray
        The span's variable.
    """
    return natural if span.grading is None else span.grading.graded(natural)


def natural_variable(span, var):
    """The natural variable of a span at its own variable (the inverse of :func:`span_variable`).

    Parameters
    ----------
    span : Span
        The span.
    var : float or numpy.ndarray
        The span's variable.

    Returns
    -------
    float or numpy.ndarray
        The natural variable.
    """
    return var if span.grading is None else span.grading.natural(var)
