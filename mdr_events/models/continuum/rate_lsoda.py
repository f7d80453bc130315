"""LSODA's steps of the edge's ODE taken straight from its wrapper, and its dense output kept as rows of numbers.

:func:`~mdr_events.models.continuum.rate_march.march` takes about a thousand LSODA steps per moving piece of the edge
(:mod:`~mdr_events.models.continuum.rate_edge`); through ``OdeSolver.step`` each one also costs the layers of
``scipy.integrate.ode`` and ``OdeSolver`` around the Fortran call (the right-hand side wrapped twice, the state
copied) and a ``LsodaDenseOutput`` made for it. :class:`LsodaStepper` makes scipy's ``LSODA`` solver as ``solve_ivp``
does (the same options, work arrays and first step) and then calls its integrator's runner itself with the
arguments ``LSODA._step_impl`` gives it (one step, ``itask = 5``, not beyond the bound): the same Fortran on the same
arrays, the same steps bit for bit. Each step's dense output is read as ``LSODA._dense_output_impl`` reads it (the
Nordsieck array of the last successful order, its last column rescaled where the order is to fall) but kept as a row
(:class:`LsodaSteps`): :mod:`~mdr_events.models.continuum.rate_dense` lays the rows out as they are, and the
``OdeSolution`` of those steps, with the same interpolants, is made only when a piece is asked for its value
(:attr:`LsodaSteps.solution`). ``tests/models/test_rate_lsoda.py`` compares both routes.
"""

from __future__ import annotations

import functools
from typing import Callable

import numpy as np
from scipy.integrate import LSODA
from scipy.integrate._ivp.base import ConstantDenseOutput
from scipy.integrate._ivp.common import OdeSolution
from scipy.integrate._ivp.lsoda import LsodaDenseOutput

__all__ = ["LsodaStepper", "LsodaSteps", "interpolant", "runner_steps_as_scipy"]

#: ``LSODA._step_impl``'s ``itask``: one step, not beyond ``rwork[0]`` (the bound).
ONE_STEP = 5
#: ``LSODA._step_impl``'s message where the step failed.
FAILED = "Unexpected istate in LSODA."
#: The steps :func:`runner_steps_as_scipy` compares (enough for LSODA to change its order and switch methods).
CHECKED_STEPS = 60


class LsodaStepper:
    """scipy's ``LSODA`` solver of ``ẏ = fun(t, y)`` (one state) stepped by its integrator's runner.

    Parameters
    ----------
    fun : callable
        ``fun(t, y)`` with ``y`` an array of one value, returning a sequence of one value.
    t0, t_bound : float
        The start and the bound (s), ``t0 < t_bound``.
    y0 : float
        The start.
    rtol, atol : float
        The solver's tolerances.
    """

    def __init__(self, fun: Callable, t0: float, t_bound: float, y0: float, rtol: float, atol: float):
        solver = LSODA(fun, t0, np.array([y0], dtype=float), t_bound, rtol=rtol, atol=atol)
        ode = solver._lsoda_solver
        integrator = ode._integrator
        self.integrator, self.fun, self.t_bound = integrator, fun, t_bound
        self.jac, self.f_params, self.jac_params = ode.jac or (lambda: None), ode.f_params, ode.jac_params
        self.t, self.y, self.t_old = ode.t, ode._y, None
        self.iwork, self.rwork = integrator.iwork, integrator.rwork  # (the work arrays every call is given)

    def step(self) -> bool:
        """One step (``LSODA._step_impl``): ``False`` where it failed.

        Returns
        -------
        bool
            Whether the step succeeded (:attr:`t`, :attr:`y` and :attr:`t_old` moved on).
        """
        integrator = self.integrator
        rtol, atol, _, istate, rwork, iwork, jt = integrator.call_args
        y, t, istate = integrator.runner(self.fun, self.y, self.t, self.t_bound, rtol, atol, ONE_STEP, istate,
                                         rwork, iwork, self.jac, jt, self.f_params, 1, self.jac_params,
                                         integrator.state_doubles, integrator.state_ints)
        integrator.istate = istate
        if istate < 0:
            integrator.success = 0
            return False
        integrator.call_args[3], integrator.istate, integrator.success = 2, 2, 1
        self.t_old, self.t, self.y = self.t, t, y
        return True

    def row(self) -> tuple:
        """The last step's dense output as ``(t_old, t, h, order, yh)`` (``LSODA._dense_output_impl``'s numbers, ``yh``
        the Nordsieck row of one state), or ``(t_old, t, None, None, y)`` for a step that did not move.

        Returns
        -------
        tuple
            The step's numbers.
        """
        if self.t == self.t_old:
            return (self.t_old, self.t, None, None, self.y.copy())
        iwork, rwork = self.iwork, self.rwork
        order, h = iwork[13], rwork[11]
        yh = rwork[20:21 + order].copy()
        if iwork[14] < order:
            yh[-1] *= (h / rwork[10]) ** order
        return (self.t_old, self.t, h, order, yh)


def interpolant(row: tuple):
    """The dense output ``LSODA`` would have made of a step's :meth:`LsodaStepper.row`.

    Parameters
    ----------
    row : tuple
        ``(t_old, t, h, order, yh)``.

    Returns
    -------
    LsodaDenseOutput or ConstantDenseOutput
        The step's interpolant.
    """
    t_old, t, h, order, yh = row
    if h is None:
        return ConstantDenseOutput(t_old, t, yh)
    return LsodaDenseOutput(t_old, t, h, order, yh.reshape(1, -1))


class LsodaSteps:
    """LSODA's dense output over a piece's steps, as rows; called like the ``OdeSolution`` of them.

    Parameters
    ----------
    ts : list of float
        The steps' ends (increasing), one more than ``rows``.
    rows : list of tuple
        Each step's :meth:`LsodaStepper.row`.
    """

    #: ``OdeSolution``'s rule for LSODA's steps (``alt_segment``): a time on a step's end belongs to the later step
    side = "right"

    def __init__(self, ts: list, rows: list):
        self.ts, self.rows = np.asarray(ts, dtype=float), rows
        self._solution = None

    @property
    def solution(self) -> OdeSolution:
        """The ``OdeSolution`` ``solve_ivp`` would have made of these steps (made on first use)."""
        if self._solution is None:
            self._solution = OdeSolution(self.ts, [interpolant(row) for row in self.rows], alt_segment=True)
        return self._solution

    @property
    def interpolants(self) -> list:
        """The steps' interpolants (:attr:`solution`'s)."""
        return self.solution.interpolants

    def __call__(self, t) -> np.ndarray:
        """The state at ``t``, as the ``OdeSolution`` of the steps gives it.

        Parameters
        ----------
        t : float or array_like
            The times (s).

        Returns
        -------
        numpy.ndarray
            The state (shape ``(1,)`` or ``(1, n)``).
        """
        return self.solution(t)

    def polynomial_rows(self) -> tuple[np.ndarray, np.ndarray, list] | None:
        """Each step's origin, scale and Nordsieck row (the power basis of ``x = (t − origin)/scale``), or ``None``
        where a step did not move (its interpolant a constant).

        Returns
        -------
        tuple or None
            ``(origins, scales, rows)``.
        """
        if any(row[2] is None for row in self.rows):
            return None
        return (np.array([row[1] for row in self.rows], dtype=float),
                np.array([row[2] for row in self.rows], dtype=float), [row[4] for row in self.rows])


def _stiff_check(t: float, y: np.ndarray) -> list[float]:
    """``ẏ = −50 (y − cos t)``: stiff enough for LSODA to switch methods and change its order within a few steps."""
    return [-50.0 * (y[0] - np.cos(t))]


@functools.cache
def runner_steps_as_scipy() -> bool:
    """Whether this SciPy's ``LSODA`` is stepped by its runner as :class:`LsodaStepper` assumes (its private layout:
    the integrator's ``runner``, ``call_args``, the work arrays' places): an ODE stepped both ways, every step's end,
    state and dense output at its middle compared bit for bit, once per process. Where they differ, or a name has
    gone, the edge is stepped by ``OdeSolver.step`` (:mod:`.rate_march`): slower, the same numbers.

    Returns
    -------
    bool
        Whether :class:`LsodaStepper` may run.
    """
    try:
        stepper = LsodaStepper(_stiff_check, 0.0, 1.0, 0.0, 1e-8, 1e-12)
        solver = LSODA(_stiff_check, 0.0, np.array([0.0]), 1.0, rtol=1e-8, atol=1e-12)
        for _ in range(CHECKED_STEPS):
            if solver.status != "running":
                return True
            moved, _ = stepper.step(), solver.step()
            middle = 0.5 * (solver.t_old + solver.t)
            if not (moved and stepper.t == solver.t and stepper.y[0] == solver.y[0]
                    and interpolant(stepper.row())(middle)[0] == solver.dense_output()(middle)[0]):
                return False
        return True
    except Exception:  # (SciPy's private names moved: the public route)
        return False
