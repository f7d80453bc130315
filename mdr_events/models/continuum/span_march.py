"""``solve_ivp``'s loop for a span's force (DOP853, dense output, terminal events), restarted at the knots of its
right-hand side, without ``solve_ivp``'s bookkeeping per call and per step.

:func:`~.integrate.solve_between_knots` integrates a span of a tabulated indenter piece by piece between the table's
knots, some two hundred pieces of one or two steps per run: ``solve_ivp``'s own work per call (its options checked,
the events prepared and evaluated at the start, an ``OdeSolution`` per piece) and per step (the events' signs compared
in NumPy arrays of a few values) cost about as much as the steps. :func:`march` takes the same steps with the same
``DOP853`` solver and options, compares the events' signs as Python floats by ``solve_ivp``'s rule, solves a crossing
as ``solve_ivp`` does (Brent's method on the step's dense output, ``xtol = rtol = 4 eps``), keeps the first terminal
root in time, and joins the pieces' dense outputs into one ``OdeSolution``: the same steps, roots and dense output, bit
for bit (``tests/models/continuum/test_span_march.py`` compares both routes on every kind of span).
"""

from __future__ import annotations

from typing import Callable, NamedTuple

from scipy.integrate import DOP853, OdeSolution
from scipy.optimize import brentq

from .rate_march import EVENT_TOL, _crossed  # (solve_ivp's rule of a crossing, as the edge's march reads it)

__all__ = ["Marched", "march"]


class Marched(NamedTuple):
    """The end of a span's integration, with what ``solve_ivp``'s result gives of it.

    Parameters
    ----------
    status : int
        ``solve_ivp``'s: 0 the end of the interval, 1 a terminal event, -1 the solver failed.
    message : str
        The solver's message where it failed (else ``""``).
    sol : OdeSolution or None
        The dense output from the start over every step taken (``None`` where the solver failed).
    t_events : list of list of float
        Each event's root (at most one: the first terminal event in time; none for the others).
    y : float
        The state where the integration ended (the end of the interval, or the event's root).
    """

    status: int
    message: str
    sol: OdeSolution | None
    t_events: list[list[float]]
    y: float


def _first_root(events: list, active: list[int], sol, t_old: float, t: float) -> tuple[int, float]:
    """The event among ``active`` that crosses first from ``t_old`` towards ``t``, and its root: each root by Brent's
    method on the step's dense output (``solve_event_equation``), ordered as ``handle_events`` orders them (every
    event terminal: the first one ends the integration)."""
    roots = [brentq(lambda var, event=events[index]: event(var, sol(var)), t_old, t, xtol=EVENT_TOL, rtol=EVENT_TOL)
             for index in active]
    ascending = t > t_old
    first = min(range(len(roots)), key=lambda k: roots[k] if ascending else -roots[k])  # (a stable order, as argsort)
    return active[first], roots[first]


def march(rhs: Callable, pieces: list[tuple[float, float]], force: float, events: list, rtol: float, atol: float,
          max_step: float, first_steps: bool) -> Marched:
    """Integrate ``dF/dvar = rhs(var, F)`` over consecutive ``pieces`` from ``force``, a fresh ``DOP853`` per piece
    (started at the end of the one before), to the end of the last or the first terminal event.

    Parameters
    ----------
    rhs : callable
        ``rhs(var, y)`` with ``y`` an array of one value, returning a sequence of one value.
    pieces : list of (float, float)
        The pieces ``(low, high)`` of the integration variable, each starting where the one before ends.
    force : float
        The initial value at the first piece's start.
    events : list
        The terminal event functions ``event(var, y)``, each with its ``direction``.
    rtol, atol : float
        The solver's tolerances.
    max_step : float
        The solver's largest step.
    first_steps : bool
        Whether each piece is first tried in one step (``first_step`` the piece's length, at most ``max_step``), as
        :func:`~.integrate.solve_between_knots` restarts at knots; else the solver picks its first step.

    Returns
    -------
    Marched
        What ``solve_ivp`` of the pieces, joined, gives.
    """
    ts, interpolants = [pieces[0][0]], []
    t_events: list[list[float]] = [[] for _ in events]
    directions = [float(getattr(event, "direction", 0.0)) for event in events]
    for low, high in pieces:
        options = dict(first_step=min(abs(high - low), max_step)) if first_steps else {}
        solver = DOP853(rhs, low, [force], high, rtol=rtol, atol=atol, max_step=max_step, **options)
        g = [event(low, [force]) for event in events]  # (as solve_ivp, after its solver, at each piece's start)
        appended, status = 0, None
        while status is None:
            message = solver.step()
            if solver.status == "failed":
                return Marched(-1, message or "", None, t_events, force)
            status = 0 if solver.status == "finished" else None
            t, y = solver.t, solver.y
            sol = solver.dense_output()
            interpolants.append(sol)
            g_new = [event(t, y) for event in events]
            active = [index for index in range(len(events)) if _crossed(g[index], g_new[index], directions[index])]
            if active:
                index, t = _first_root(events, active, sol, solver.t_old, t)
                t_events[index].append(t)
                y, status = sol(t), 1
            g = g_new
            if appended and ts[-1] == t:  # (solve_ivp keeps no step of zero length after the first of its own)
                interpolants.pop()
            else:
                ts.append(t)
                appended += 1
        force = float(y[0])
        if status == 1:
            break
    return Marched(status, "", OdeSolution(ts, interpolants), t_events, force)
