"""Integrate one span: an event met at its start, a force constant or linear in time, a moving span without a front
in closed form (:mod:`.closed_form`), or else a quadrature by panels (:mod:`.span_panels`: the right-hand side and the
events read the span's variable alone), with the span's events, a piece started at each knot of its right-hand side,
in the variable graded towards a singular end where the integrator gives one (:mod:`.graded`); which events fired,
and where. With the integrator's ``quadrature`` off, ``solve_ivp``'s loop (DOP853, dense output; :mod:`.span_march`).

The span's right-hand side and events are its integrator's (:class:`~.span.SpanIntegrator`, or
:class:`~.split_span.SplitSpanIntegrator` for both parts of the cap with adhesion on a curved indenter).
"""

from __future__ import annotations

import math
from typing import Callable


from .anchors import AnchorMap
from .closed_form import closed_span
from .graded import SpanProblem, graded_problem
from .model import ContinuumModel
from .span import EventFunction, SpanIntegrator, SpanOutcome
from .span_march import Marched, march
from .span_panels import NODES, PIECE_NODES, panels, radau_rule, rule
from .span_record import Span, Variable
from .state import Cap, Regime
from .tolerances import MIN_STEPS_PER_SPAN, SIMULTANEOUS_SHARE, Tolerances

__all__ = ["integrate_span", "solve_between_knots", "fired_events", "radius_at"]


def fired_events(events: list[EventFunction], roots: list, start: float, offset: float,
                 natural: Callable[[float], float] | None = None) -> tuple[float, frozenset]:
    """The first root among the events' ``roots`` (``solve_ivp``'s ``t_events``) and every event that fires
    with it: those whose roots coincide (to SIMULTANEOUS_SHARE of the natural variable, the time or the radius),
    and the rising ones whose function is already zero to rounding there (the roots of identical functions, e.g.
    onset and full slip of a uniform field, differ by an ulp).

    Parameters
    ----------
    events : list of EventFunction
        The span's event functions.
    roots : list
        ``solve_ivp``'s ``t_events``.
    start : float
        The span's start (its variable).
    offset : float
        The rising events' offset (m).
    natural : callable, optional
        The natural variable of the span's variable (a graded span's :meth:`~.graded.Grading.natural`: roots are
        compared there, not in ``u``, whose share of a root near ``u = 0`` is far wider than the time's); default
        the variable itself.

    Returns
    -------
    tuple
        The first root (in the span's variable) and the keys that fire there.
    """
    natural = natural or (lambda var: var)
    hits = sorted((abs(found[0] - start), found[0], index) for index, found in enumerate(roots) if len(found))
    first = hits[0][1]
    at = float(natural(first))
    fired = {events[index].key for _, var, index in hits
             if abs(float(natural(var)) - at) <= SIMULTANEOUS_SHARE * max(abs(at), 1e-300)}
    for event in events:
        if event.key not in fired and event.direction > 0 and event(first) >= -2 * offset:
            fired.add(event.key)
    return first, frozenset(fired)


def integrate_span(model: ContinuumModel, anchors: AnchorMap, span: Span, sliding: dict[Cap, bool],
                   force: float, integrator_class: type[SpanIntegrator] = SpanIntegrator) -> SpanOutcome:
    """Integrate ``F_x`` over ``span`` from ``force``, up to its end or the first event.

    Sets the span's interpolant (or constant force) and integration variable; the caller sets its
    end to the returned ``t_stop``.

    Parameters
    ----------
    model : ContinuumModel
        The contact's branches, caps and tolerances.
    anchors : AnchorMap
        The stored anchors of the springs in contact (read, not changed).
    span : Span
        The span, its regime and (pinned) radius; its interpolant, force and variable are set.
    sliding : dict of Cap to bool
        Whether springs slide at each cap at the start.
    force : float
        ``F_x`` (N) at the start.
    integrator_class : type, default SpanIntegrator
        The span's right-hand side and events (:class:`~.split_span.SplitSpanIntegrator` for both parts of the cap
        with adhesion on a curved indenter).

    Returns
    -------
    SpanOutcome
        The events that stopped it (none: its planned end), the time, force and radius there.

    Raises
    ------
    RuntimeError
        A state that is not finite, or ``solve_ivp`` failing (a bug to report).
    """
    t0, t1 = span.t_start, span.t_end
    span.force = force
    if t1 <= t0:
        return SpanOutcome(frozenset(), t0, force, radius_at(model, span, t0))
    if model.caps.frictionless:  # τ0 = 0 (μ = 0): ū ≡ 0, every spring slides with zero shift, F_x ≡ 0
        span.force = 0.0
        return SpanOutcome(frozenset(), t1, 0.0, radius_at(model, span, t1))
    integrator = integrator_class(model, anchors, span, sliding)
    return integrator.finish(_integrate(model, span, integrator, force))


def _integrate(model: ContinuumModel, span: Span, integrator: SpanIntegrator, force: float) -> SpanOutcome:
    """:func:`integrate_span` once the span's integrator is laid out: an event met at the start, a constant or
    linear force, or ``solve_ivp`` with the events."""
    t0, t1 = span.t_start, span.t_end
    span.variable = Variable.RADIUS if integrator.moving else Variable.TIME
    span.scale = integrator.scale
    met = integrator.met_at_start()
    if met:
        return SpanOutcome(met, t0, force, integrator.a0)
    if integrator.force_is_constant():
        return SpanOutcome(frozenset(), t1, force, integrator.radius_of(integrator.stop))
    if integrator.force_is_linear():
        return integrator.linear_span(force)
    start, stop = integrator.start, integrator.stop
    if not (math.isfinite(start) and math.isfinite(stop) and math.isfinite(force)):
        raise RuntimeError(f"the continuum method lost its state on [{t0!r}, {t1!r}] s ({span.regime.value}: from "
                           f"{start!r} to {stop!r}, F_x = {force!r}); please report the parameters and path")
    span.grading = grading = integrator.grading()
    events = integrator.event_functions()
    if grading is None:
        problem = SpanProblem(integrator.rhs, events, start, stop, integrator.knots(), integrator.max_step())
    else:  # (the variable u of :mod:`.graded`, from 1 to 0)
        problem = graded_problem(integrator, grading, events, MIN_STEPS_PER_SPAN)
    tolerances = model.solver_tolerances
    primitive = integrator.primitive() if grading is None else None
    # (no front through the anchors: the force in closed form, :mod:`.closed_form`; None: an event it left unsettled)
    solution = None if primitive is None else closed_span(primitive, problem.start, problem.stop, force, integrator.G2,
                                                          integrator.scale, problem.knots, problem.events)
    if solution is None and integrator.quadrature:  # (a right-hand side and events of the variable alone: panels)
        pieces = list(zip([problem.start, *problem.knots], [*problem.knots, problem.stop]))
        # (between knots, pieces of ~1/120 of a span on a 41-point table: a rule of fewer points is exact enough)
        solution = panels(problem.rhs, pieces, force, problem.events, tolerances.rtol, tolerances.atol,
                          problem.max_step, radau_rule(PIECE_NODES) if problem.knots else rule(NODES))
    elif solution is None:
        solution = solve_between_knots(problem.rhs, problem.start, problem.stop, force, problem.knots, problem.events,
                                       tolerances, problem.max_step)
    if solution.status < 0:
        raise RuntimeError(f"solve_ivp failed on [{start}, {stop}] ({span.regime.value}): {solution.message}")
    span.interpolant = solution.sol
    roots = solution.t_events
    if solution.status == 0 and grading is not None and grading.event is not None:  # (its origin's event, at u = 0)
        roots = [[problem.stop] if event.key == grading.event else [] for event in problem.events]
        if not any(roots):  # (an event no function watches: it fires alone)
            return SpanOutcome(frozenset({grading.event}), float(integrator.time_of(grading.origin)),
                               solution.y, float(integrator.radius_of(grading.origin)))
    if any(len(found) for found in roots):
        first, fired = fired_events(problem.events, roots, problem.start, integrator.offset,
                                    None if grading is None else grading.natural)
        natural = first if grading is None else float(grading.natural(first))
        return SpanOutcome(fired, float(integrator.time_of(natural)), float(solution.sol(first)[0]),
                           float(integrator.radius_of(natural)))
    return SpanOutcome(frozenset(), t1, solution.y, float(integrator.radius_of(stop)))


def solve_between_knots(rhs: Callable, start: float, stop: float, force: float, knots: list[float], events: list,
                        tolerances: Tolerances, max_step: float) -> Marched:
    """``solve_ivp(rhs, (start, stop), [force], method="DOP853", dense_output=True, events=events, ...)``, restarted
    at each knot of the right-hand side, by :func:`~.span_march.march` (``solve_ivp``'s loop without its bookkeeping:
    the same steps, roots and dense output).

    At a knot a derivative of ``rhs`` jumps (the PCHIP of a tabulated ``g``): a solver stepping across it shrinks
    its steps hundreds of times and still loses accuracy there (2.6e-6 of ``F_x`` on a 41-point table of the
    paraboloid against the closed form of an all-stick span, 1e-15 piece by piece). Each piece, smooth, is first
    tried in one step; the pieces' dense outputs are joined into one ``OdeSolution``. The state at a restart is the
    end of the piece before, so a terminal event is seen in exactly one piece, where the integration stops.

    Parameters
    ----------
    rhs : callable
        The right-hand side ``rhs(var, y)``.
    start, stop : float
        The span of the integration variable.
    force : float
        The initial value.
    knots : list of float
        The knots strictly between ``start`` and ``stop``, ordered from ``start`` (none: one piece, whose first step
        the solver picks).
    events : list
        The terminal event functions.
    tolerances : Tolerances
        The solver's (its ``rtol`` and ``atol``; a run's ``atol`` is :func:`~.tolerances.force_atol`).
    max_step : float
        The solver's largest step.

    Returns
    -------
    Marched
        The status, the joined dense output from ``start``, the first event's root and the state at the end.
    """
    pieces = list(zip([start, *knots], [*knots, stop]))
    return march(rhs, pieces, force, events, tolerances.rtol, tolerances.atol, max_step, first_steps=bool(knots))


def radius_at(model: ContinuumModel, span: Span, t: float) -> float:
    """The contact radius of ``span`` at path time ``t``.

    Parameters
    ----------
    model : ContinuumModel
        The contact.
    span : Span
        The span.
    t : float
        The path time (s).

    Returns
    -------
    float
        The radius (m).
    """
    if span.regime in (Regime.GROWING, Regime.SHRINKING):
        return model.branch(span.regime).radius(span.segment.d(t), model.tolerances.radius_rtol)
    return span.pinned_radius
