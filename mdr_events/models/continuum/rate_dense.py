"""The edge's dense output at many times at once: each step's polynomial as one row of an array.

``OdeSolution`` evaluates a step at a time (a Python call per step among the times asked). The springs' shifts on top
of the rate-dependent edge (:mod:`~mdr_events.models.continuum.rate_shifts`) ask for the radius at thousands of times
spread over hundreds of steps, many times over (bisections, quadrature). :func:`step_polynomials` lays the steps of
Radau's and LSODA's dense outputs out as rows of coefficients in the power basis of their own variable (LSODA's
``x = (t − t_new)/h``, Nordsieck's array; Radau's ``x = (t − t_old)/h``, ``y_old`` and its collocation polynomial's
``Q``) and evaluates all the times in one pass (Horner's rule): the same polynomials, summed in another order (a few
ulp apart). Other dense outputs are kept as they are.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate._ivp.common import OdeSolution
from scipy.integrate._ivp.lsoda import LsodaDenseOutput
from scipy.integrate._ivp.radau import RadauDenseOutput

from .rate_lsoda import LsodaSteps

__all__ = ["StepPolynomials", "step_polynomials", "REACH_STEPS", "REACH_NUDGES", "PROBE_ULPS"]

#: The most safeguarded Newton steps :meth:`StepPolynomials.reach` takes in a step (each one a bisection where Newton's
#: would leave the bracket: 64 halvings reach a double's spacing from any step's width).
REACH_STEPS = 64
#: The doubles below an iterate that converged from above at which :meth:`StepPolynomials.reach` probes for the value:
#: a Newton step below the clock's spacing leaves the first time within a double or two of the iterate.
PROBE_ULPS = 4
#: The doubles :meth:`StepPolynomials.reach` steps up from a Newton iterate that converged just below the value (its
#: last step below the clock's spacing leaves it within a few ulp of the first time the value is reached).
REACH_NUDGES = 8


class StepPolynomials:
    """The steps of a scalar ODE's dense output as polynomials, called like ``OdeSolution``.

    Parameters
    ----------
    ts : numpy.ndarray
        The steps' ends (increasing).
    origins, scales : numpy.ndarray
        Each step's variable ``x = (t − origin) / scale``.
    coefficients : numpy.ndarray
        Each step's coefficients of ``x^0, x^1, …`` (rows padded with zeros).
    side : str
        Which step a time on a step's end belongs to (``OdeSolution``'s rule).
    """

    def __init__(self, ts: np.ndarray, origins: np.ndarray, scales: np.ndarray, coefficients: np.ndarray, side: str):
        self.ts, self.origins, self.scales, self.coefficients, self.side = ts, origins, scales, coefficients, side
        self._columns = np.ascontiguousarray(coefficients.T)  # (one row per power: each gathered at once by take)
        self._at_ends = None  # (the state at the steps' ends, the first time reach asks)

    def __call__(self, t) -> np.ndarray:
        """The state at ``t`` (shape ``(1,)`` for a scalar, ``(1, n)`` for ``n`` times).

        Parameters
        ----------
        t : float or array_like
            The times.

        Returns
        -------
        numpy.ndarray
            The state, as ``OdeSolution`` returns it.
        """
        times = np.asarray(t, dtype=float)
        flat = np.atleast_1d(times).ravel()
        step = np.searchsorted(self.ts, flat, side=self.side) - 1
        np.minimum(np.maximum(step, 0, out=step), len(self.origins) - 1, out=step)
        x = (flat - self.origins.take(step)) / self.scales.take(step)
        columns = self._columns
        value = columns[-1].take(step)
        for column in columns[-2::-1]:  # (Horner's rule in place: the same products and sums)
            value *= x
            value += column.take(step)
        return value.reshape((1,) + times.shape) if times.ndim else value[:1].reshape(1)


    def _value_and_slope(self, t: np.ndarray, step: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The polynomial of ``step`` and its slope in ``t`` at ``t`` (Horner's rule)."""
        scale = self.scales.take(step)
        x = (t - self.origins.take(step)) / scale
        columns = self._columns
        value, slope = columns[-1].take(step), np.zeros(t.shape)
        for column in columns[-2::-1]:
            slope *= x
            slope += value
            value *= x
            value += column.take(step)
        return value, slope / scale

    def reach(self, target: np.ndarray, lo: float, hi: np.ndarray) -> np.ndarray:
        """The first time in ``[lo, hi]`` (elementwise) at which the state, non-decreasing there, reaches ``target``:
        the step found among the steps' ends, then safeguarded Newton steps on its polynomial (bisection where
        Newton's would leave the bracket) until a step is below the clock's spacing; ``hi`` where it is not reached.

        Parameters
        ----------
        target : numpy.ndarray
            The values to reach.
        lo : float
            The earliest time (s).
        hi : numpy.ndarray
            The latest times (s), one per target.

        Returns
        -------
        numpy.ndarray
            The times (s).
        """
        target, hi = np.asarray(target, dtype=float), np.asarray(hi, dtype=float)
        if self._at_ends is None:
            self._at_ends = self(self.ts)[0]
        later = self.ts > lo
        ends = np.concatenate([[lo], self.ts[later]])
        climbed = np.maximum.accumulate(np.concatenate([self(lo), self._at_ends[later]]))
        after = np.minimum(np.searchsorted(climbed, target, side="left"), len(ends) - 1)
        low, high = ends[np.maximum(after - 1, 0)], np.minimum(ends[after], hi)
        reached = (self(high)[0] >= target) & (high > low)
        out = high.copy()
        if not reached.any():
            return out
        low, high, goal = low[reached], high[reached], target[reached]
        step = np.minimum(np.maximum(np.searchsorted(self.ts, 0.5 * (low + high), side=self.side) - 1, 0),
                          len(self.origins) - 1)
        t = self._start(low, high, goal, step)
        bracket, probed = np.stack([low, high]), np.zeros(t.shape, dtype=bool)
        active = np.arange(t.size)  # (each target stops at its own convergence, the others iterate on: the same
        for _ in range(REACH_STEPS):  # time asked alone or among others)
            active = self._newton(t, bracket, probed, goal, step, active)
            if not active.size:
                break
        out[reached] = self._first_double(t, bracket[0], bracket[1], goal, step)
        return out

    def _newton(self, t: np.ndarray, bracket: np.ndarray, probed: np.ndarray, goal: np.ndarray, step: np.ndarray,
                active: np.ndarray) -> np.ndarray:
        """One safeguarded Newton step of :meth:`reach` on the targets ``active`` (``t``, the ``bracket``'s rows
        ``low`` and ``high`` and ``probed`` updated in place); the targets still to converge."""
        at, goal, step = t[active], goal[active], step[active]
        value, slope = self._value_and_slope(at, step)
        above = value >= goal
        low, high = np.where(above, bracket[0, active], at), np.where(above, at, bracket[1, active])
        bracket[0, active], bracket[1, active] = low, high
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = at - (value - goal) / slope
        spacing = np.spacing(np.abs(at))
        tiny = np.abs(newton - at) <= spacing
        # (converged from below: the next doubles up reach the value; or the bracket is a double wide)
        done = (tiny & ~above) | (high - low <= spacing)
        middle = 0.5 * (low + high)
        # (converged from above: a probe a few doubles below brackets the first time; where the probe is above too,
        # the value is flat there to its last digit, and the bracket is halved)
        probe = tiny & above & ~probed[active]
        inside = (newton > low) & (newton < high) & ~tiny
        moved = np.where(probe, np.maximum(at - PROBE_ULPS * spacing, middle), np.where(inside, newton, middle))
        probed[active] = probe
        t[active] = np.where(done, at, moved)
        return active[~done]

    def _start(self, low: np.ndarray, high: np.ndarray, goal: np.ndarray, step: np.ndarray) -> np.ndarray:
        """The secant's time between the bracket's ends on the step's polynomial (its middle where that is not
        strictly inside): Newton's start, a few ulp of the clock from the time sought on a smooth step."""
        ends = np.concatenate([low, high])
        values = self._value_and_slope(ends, np.concatenate([step, step]))[0]
        v_low, v_high = values[:low.size], values[low.size:]
        with np.errstate(divide="ignore", invalid="ignore"):
            secant = low + (goal - v_low) / (v_high - v_low) * (high - low)
        return np.where((secant > low) & (secant < high), secant, 0.5 * (low + high))

    def _first_double(self, t: np.ndarray, low: np.ndarray, high: np.ndarray, goal: np.ndarray,
                      step: np.ndarray) -> np.ndarray:
        """The least double about ``t`` at which the step's polynomial reaches ``goal``: up from an iterate that
        converged just below it (not beyond the bracket's ``high``), down from one just above (not to its ``low``,
        below the value), at most :data:`REACH_NUDGES` doubles either way."""
        for _ in range(REACH_NUDGES):
            short = self._value_and_slope(t, step)[0] < goal
            if not short.any():
                break
            t = np.where(short, np.minimum(np.nextafter(t, np.inf), high), t)
        for _ in range(REACH_NUDGES):
            before = np.nextafter(t, -np.inf)
            down = (before > low) & (self._value_and_slope(before, step)[0] >= goal)
            if not down.any():
                break
            t = np.where(down, before, t)
        return t


def _row(interpolant) -> tuple[float, float, np.ndarray] | None:
    """A step's origin, scale and coefficients in the power basis, or ``None`` for another kind of dense output."""
    if type(interpolant) is LsodaDenseOutput:
        return interpolant.t, interpolant.h, interpolant.yh[0]
    if type(interpolant) is RadauDenseOutput:
        return interpolant.t_old, interpolant.h, np.concatenate([interpolant.y_old[:1], interpolant.Q[0]])
    return None


def step_polynomials(solution):
    """``solution`` as :class:`StepPolynomials` where it is an ``OdeSolution`` of Radau's or LSODA's steps of one
    state; else ``solution`` itself.

    Parameters
    ----------
    solution : callable
        A piece's dense output (LSODA's steps as :class:`~.rate_lsoda.LsodaSteps`: their rows as they are).

    Returns
    -------
    StepPolynomials or callable
        The same values, evaluated in one pass.
    """
    if isinstance(solution, LsodaSteps):
        laid_out = solution.polynomial_rows()
        if laid_out is None:
            return solution.solution
        origins, scales, rows = laid_out
        return StepPolynomials(solution.ts, origins, scales, _padded(rows), solution.side)
    if not isinstance(solution, OdeSolution) or not solution.ascending or not solution.interpolants:
        return solution
    rows = [_row(interpolant) for interpolant in solution.interpolants]
    if any(row is None for row in rows) or rows[0][2].ndim != 1:
        return solution
    origins = np.array([row[0] for row in rows], dtype=float)
    scales = np.array([row[1] for row in rows], dtype=float)
    return StepPolynomials(np.asarray(solution.ts, dtype=float), origins, scales, _padded([row[2] for row in rows]),
                           solution.side)


def _padded(rows: list) -> np.ndarray:
    """The rows of coefficients as one array, each padded with zeros to the longest."""
    coefficients = np.zeros((len(rows), max(len(row) for row in rows)))
    for index, row in enumerate(rows):
        coefficients[index, :len(row)] = row
    return coefficients
