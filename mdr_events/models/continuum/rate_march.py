"""``solve_ivp``'s loop for the edge's scalar ODE with terminal events, without its per-step bookkeeping.

:func:`~mdr_events.models.continuum.rate_edge.solve_edge` integrates one radius through thousands of steps per piece;
``solve_ivp`` spends about as much time per step on its general event handling (NumPy on arrays of one or two
values) as on the step. :func:`march` takes the same steps with the same ``OdeSolver`` and the same options, compares
the events' signs as Python floats, and solves a crossing as ``solve_ivp`` does (Brent's method on the step's dense
output, ``xtol = rtol = 4 eps``): the same steps, roots and dense output, bit for bit. LSODA's steps are taken by its
integrator's runner and its dense output kept as rows (:mod:`.rate_lsoda`), the same numbers.
"""

from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np
from scipy.integrate import BDF, LSODA, Radau
from scipy.integrate._ivp.common import OdeSolution
from scipy.optimize import brentq

from .rate_lsoda import FAILED, LsodaStepper, LsodaSteps, interpolant, runner_steps_as_scipy

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


class _Solver:
    """An ``OdeSolver`` stepped as ``solve_ivp`` steps it, its steps' dense outputs made as it goes."""

    def __init__(self, solver, method: str):
        self.solver, self.method = solver, method

    def advance(self) -> tuple[int | None, str]:
        """One step: the status (``None`` running, 0 at the bound, -1 failed) and the solver's message."""
        message = self.solver.step()
        status = self.solver.status
        return (-1 if status == "failed" else 0 if status == "finished" else None), message

    def last(self):
        """The last step's dense output."""
        return self.solver.dense_output()

    @staticmethod
    def interpolant(step):
        """A step's dense output, callable."""
        return step

    def dense(self, ts: list, steps: list) -> OdeSolution:
        """The dense output over the steps."""
        return OdeSolution(np.array(ts), steps, alt_segment=self.method in ("BDF", "LSODA"))


class _Lsoda:
    """LSODA stepped by its integrator's runner (:mod:`.rate_lsoda`), its steps' dense outputs kept as rows."""

    interpolant = staticmethod(interpolant)

    def __init__(self, stepper: LsodaStepper):
        self.solver = stepper

    def advance(self) -> tuple[int | None, str]:
        """One step, as :meth:`_Solver.advance`."""
        if not self.solver.step():
            return -1, FAILED
        return (0 if self.solver.t - self.solver.t_bound >= 0 else None), None

    def last(self) -> tuple:
        """The last step's numbers (:meth:`~.rate_lsoda.LsodaStepper.row`)."""
        return self.solver.row()

    @staticmethod
    def dense(ts: list, steps: list) -> LsodaSteps:
        """The dense output over the steps, as rows."""
        return LsodaSteps(ts, steps)


def _solver(fun: Callable, t0: float, t1: float, y0: float, method: str, rtol: float, atol: float):
    """The stepper of ``method``: LSODA by its runner where the interval is not empty and this SciPy steps it as
    :mod:`.rate_lsoda` assumes (:func:`~.rate_lsoda.runner_steps_as_scipy`), else the ``OdeSolver``
    (``tests/models/test_rate_lsoda.py`` compares the two on LSODA)."""
    if method == "LSODA" and t1 > t0 and runner_steps_as_scipy():
        return _Lsoda(LsodaStepper(fun, t0, t1, y0, rtol, atol))
    return _Solver(SOLVERS[method](fun, t0, np.array([y0], dtype=float), t1, rtol=rtol, atol=atol), method)


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
        Where and why it ended, and the dense output (LSODA's by its runner as :class:`~.rate_lsoda.LsodaSteps`).
    """
    stepper = _solver(fun, t0, t1, y0, method, rtol, atol)
    solver = stepper.solver
    directions = [float(getattr(event, "direction", 0.0)) for event in events]
    signs = [float(event(t0, solver.y)) for event in events]
    ts, steps = [t0], []
    status, message, ended = None, "", None
    while status is None:
        status, message = stepper.advance()
        if status == -1:
            break
        t, y = solver.t, solver.y
        steps.append(stepper.last())
        now = [float(event(t, y)) for event in events]
        crossed = [index for index in range(len(events)) if _crossed(signs[index], now[index], directions[index])]
        if crossed:
            sol = stepper.interpolant(steps[-1])
            t, ended = min((_root(events[index], sol, solver.t_old, t, now[index]), index) for index in crossed)
            status = 1
        if len(ts) > 1 and ts[-1] == t:  # (solve_ivp's: a step that did not move replaces the last)
            steps.pop()
        else:
            ts.append(t)
        signs = now
    end = ts[-1]
    y_end = float(stepper.interpolant(steps[-1])(end)[0]) if status == 1 else float(solver.y[0])
    dense = stepper.dense(ts, steps) if steps else None
    return Marched(float(end), y_end, status, str(message or ""), dense, ended)
