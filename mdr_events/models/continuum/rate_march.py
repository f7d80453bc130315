"""``solve_ivp``'s loop for the edge's scalar ODE with terminal events, without its per-step bookkeeping.

:func:`~mdr_events.models.continuum.rate_edge.solve_edge` integrates one radius through thousands of steps per piece;
``solve_ivp`` spends about as much time per step on its general event handling (NumPy on arrays of one or two
values) as on the step. :func:`march` takes the same steps with the same ``OdeSolver`` and the same options, compares
the events' signs as Python floats, and solves a crossing as ``solve_ivp`` does (Brent's method on the step's dense
output, ``xtol = rtol = 4 eps``): the same steps, roots and dense output, bit for bit.
"""

from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np
from scipy.integrate import BDF, LSODA, Radau
from scipy.integrate._ivp.common import OdeSolution
from scipy.optimize import brentq

__all__ = ["Marched", "march", "SOLVERS"]

#: The ``OdeSolver`` of each method name (those ``solve_edge`` takes: stiff-capable).
SOLVERS = {"Radau": Radau, "BDF": BDF, "LSODA": LSODA}
#: The events' root tolerance, ``solve_ivp``'s.
EVENT_TOL = 4.0 * float(np.finfo(float).eps)


class Marched(NamedTuple):
    """The end of one integration.

    Parameters
    ----------
    t : float
        Where it ended (s).
    y : float
        The state there.
    status : int
        ``solve_ivp``'s: 0 the end of the interval, 1 a terminal event, -1 the solver failed.
    message : str
        The solver's message where it failed.
    sol : OdeSolution
        The dense output over the steps taken.
    event : int or None
        The index of the event that ended it.
    """

    t: float
    y: float
    status: int
    message: str
    sol: OdeSolution
    event: int | None


def _crossed(before: float, after: float, direction: float) -> bool:
    """``solve_ivp``'s rule: a zero crossed upwards (``<= 0`` to ``>= 0``) or downwards, in the event's direction."""
    up, down = before <= 0.0 <= after, before >= 0.0 >= after
    return (up and direction > 0) or (down and direction < 0) or ((up or down) and direction == 0)


def _root(event: Callable, sol, t_old: float, t: float, after: float) -> float:
    """Where ``event`` crosses zero on the step's dense output ``sol`` (Brent's method, as ``solve_ivp``). Where the
    dense output does not change sign over the step although the steps' own values did (they differ from it by
    rounding at the step's ends: ``solve_ivp`` then fails with Brent's "f(a) and f(b) must have different signs"),
    the crossing is at the end already on the far side: the step's start if it is, else its end."""
    start, end = event(t_old, sol(t_old)), event(t, sol(t))
    if (start > 0.0) == (end > 0.0) and start != 0.0 and end != 0.0:
        return t_old if (start > 0.0) == (after > 0.0) else t
    return brentq(lambda time: event(time, sol(time)), t_old, t, xtol=EVENT_TOL, rtol=EVENT_TOL)


def march(fun: Callable, t0: float, t1: float, y0: float, method: str, rtol: float, atol: float,
          events: list) -> Marched:
    """Integrate ``ẏ = fun(t, y)`` from ``(t0, y0)`` to ``t1`` or the first terminal event (every event is terminal).

    Parameters
    ----------
    fun : callable
        ``fun(t, y)`` with ``y`` an array of one value, returning a sequence of one value.
    t0, t1 : float
        The interval (s).
    y0 : float
        The start.
    method : str
        A key of :data:`SOLVERS`.
    rtol, atol : float
        The solver's tolerances.
    events : list of callable
        ``event(t, y)``, each with its ``direction`` attribute.

    Returns
    -------
    Marched
        Where and why it ended, and the dense output.
    """
    solver = SOLVERS[method](fun, t0, np.array([y0], dtype=float), t1, rtol=rtol, atol=atol)
    directions = [float(getattr(event, "direction", 0.0)) for event in events]
    signs = [float(event(t0, solver.y)) for event in events]
    ts, interpolants = [t0], []
    status, message, ended = None, "", None
    while status is None:
        message = solver.step()
        if solver.status == "failed":
            status = -1
            break
        status = 0 if solver.status == "finished" else None
        t, y = solver.t, solver.y
        sol = solver.dense_output()
        interpolants.append(sol)
        now = [float(event(t, y)) for event in events]
        roots = [(_root(event, sol, solver.t_old, t, now[index]), index)
                 for index, event in enumerate(events) if _crossed(signs[index], now[index], directions[index])]
        if roots:
            t, ended = min(roots)
            status = 1
        if len(ts) > 1 and ts[-1] == t:  # (solve_ivp's: a step that did not move replaces the last)
            interpolants.pop()
        else:
            ts.append(t)
        signs = now
    end = ts[-1]
    y_end = float(interpolants[-1](end)[0]) if status == 1 else float(solver.y[0])
    dense = OdeSolution(np.array(ts), interpolants, alt_segment=method in ("BDF", "LSODA")) if interpolants else None
    return Marched(float(end), y_end, status, str(message or ""), dense, ended)
