"""The least-squares problem of a fit (:func:`mdr_events.analysis.fit.fit`): its residuals, Jacobian and solve.

The residuals are

``r = (model − measured) / σ_q``

per quantity ``q`` and sample, with ``σ_q`` the noise of the quantity
(:class:`~mdr_events.analysis.fit_data.Measurement`); samples left out (:mod:`mdr_events.analysis.fit_data`)
contribute 0. :class:`Problem` evaluates them at the scaled parameters ``θ``
(:class:`~mdr_events.analysis.fit_parameters.FreeParameters`), one continuum solve per trial, and their Jacobian
by forward differences of :data:`FD_STEP`; :func:`solve` minimises ``Σ r²`` with
``scipy.optimize.least_squares`` to :data:`FIT_TOLERANCE`.
"""

from __future__ import annotations

import math
import sys
from typing import Callable

import numpy as np
from scipy import optimize

from mdr_events.analysis.fit_data import Measurement, ModelCurves, model_curves, shifted_path
from mdr_events.analysis.fit_parameters import FreeParameters
from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.limits import Limits
from mdr_events.models.continuum import Tolerances
from mdr_events.models.kernel_model import KernelModel
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters

__all__ = ["Problem", "solve", "largest_residual", "FD_STEP", "FIT_TOLERANCE", "MAX_EVALUATIONS_PER_PARAMETER",
           "PROGRESS_SOLVES"]

#: Forward-difference step of the Jacobian in the scaled parameters. The continuum's curves are exact to
#: about 1e-10 relative (``Tolerances.rtol``): the rounding part of a column's error is then ~1e-4, the
#: truncation part ~1e-6 (the step times the curvature): enough for Gauss–Newton and the covariance.
FD_STEP = 1e-6
#: Convergence of ``least_squares`` (``xtol``, ``ftol``, ``gtol``): far below the noise, near the curves'
#: accuracy, so that noise-free data are recovered to 1e-6.
FIT_TOLERANCE = 1e-12
def largest_residual(samples: int) -> float:
    """The largest weighted residual a fit of ``samples`` residuals takes: the Jacobian's forward differences reach
    ``2|r|/FD_STEP`` (a residual's change over the step up to twice its size), and ``least_squares`` sums ``samples``
    squares of them (``JᵀJ``, the cost), which must stay below the largest double with a factor 2 to spare."""
    return FD_STEP * math.sqrt(sys.float_info.max / max(samples, 1)) / 4.0


#: Function evaluations (continuum solves besides the Jacobian's) per free parameter at most.
MAX_EVALUATIONS_PER_PARAMETER = 50
#: A progress line every this many continuum solves (:meth:`Problem.report_to`): about every 10 s on the paper's path.
PROGRESS_SOLVES = 100


class Problem:
    """The weighted residuals of one fit, and a count of the continuum solves."""

    def __init__(self, free: FreeParameters, measurement: Measurement, path_of: Callable[[Parameters], Path],
                 tolerances: Tolerances, limits: Limits, profile: SimulatedProfile = None,
                 friction: FrictionLaw = TAU0, layer: Layer = HALF_SPACE):
        self.free, self.measurement, self.path_of = free, measurement, path_of
        self.tolerances, self.limits, self.profile, self.friction = tolerances, limits, profile, friction
        #: the body (its thickness the free parameter's ``h`` where it is free:
        #: :meth:`~mdr_events.analysis.fit_parameters.FreeParameters.layer_at`)
        self.layer = layer
        self.solves = 0
        #: hears a line every :data:`PROGRESS_SOLVES` solves (:meth:`report_to`; ``None``: silent)
        self.progress: Callable[[str], None] | None = None
        self.quantities = tuple(measurement.values)
        #: least_squares asks for the Jacobian where it just evaluated the residuals: the last (θ, curves, r)
        self._last: tuple[np.ndarray, ModelCurves, np.ndarray] | None = None

    def most_solves(self) -> int:
        """The continuum solves :func:`solve` may take at most: ``least_squares``' evaluations
        (:data:`MAX_EVALUATIONS_PER_PARAMETER` per free parameter), each with at most one Jacobian of a solve per free
        parameter, and the optimum's curves once more."""
        count = len(self.free.names)
        return MAX_EVALUATIONS_PER_PARAMETER * count * (1 + count) + 1

    def report_to(self, progress: Callable[[str], None] | None) -> None:
        """Say how far the fit is to ``progress``: its bound on the solves now (:meth:`most_solves`), then the solves
        so far every :data:`PROGRESS_SOLVES` (round nineteen: a fit of many free values on hostile data ran minutes
        without a line; its bound, ``max_nfev``, was named nowhere)."""
        self.progress = progress
        if progress is not None:
            progress(f"fit: {len(self.free.names)} free value(s), at most {self.most_solves()} continuum solves "
                     f"({MAX_EVALUATIONS_PER_PARAMETER} evaluations per free value, each with a Jacobian of one solve "
                     "per free value)")

    def curves(self, theta: np.ndarray) -> ModelCurves:
        """The model's curves at ``θ`` (one continuum solve); a trial the model refuses is named in the error."""
        self.solves += 1
        if self.progress is not None and self.solves % PROGRESS_SOLVES == 0:
            self.progress(f"fit: {self.solves} continuum solves of at most {self.most_solves()}")
        try:  # (a trial far out is refused in Parameters, or by the model: named below with its values)
            params, time_offset, depth_offset = self.free.model(theta)
            friction = self.free.friction_at(theta)
            path = shifted_path(self.path_of(params), depth_offset)
            model = KernelModel(params, self.profile, friction, layer=self.free.layer_at(theta))
            return model_curves(model, path, self.measurement.path_time - time_offset, self.tolerances, self.limits,
                                self.quantities)
        except (ValueError, RuntimeError) as error:
            trial = ", ".join(f"{name}={value:.6g}" for name, value in zip(self.free.names,
                                                                             self.free.to_natural(theta)))
            raise type(error)(f"the fit tried {trial}, and the model refused: {error}; narrow the fit with "
                              "bounds= or a better start") from error

    def evaluated(self, theta: np.ndarray) -> tuple[ModelCurves, np.ndarray]:
        """The curves and the weighted residuals at ``θ`` (the last ones again without a solve)."""
        if self._last is None or not np.array_equal(self._last[0], theta):
            curves = self.curves(theta)
            self._last = (np.array(theta, copy=True), curves, self.weighted(curves))
        return self._last[1], self._last[2]

    def residuals(self, theta: np.ndarray) -> np.ndarray:
        """The weighted residuals at ``θ`` (``least_squares``' function)."""
        return self.evaluated(theta)[1]

    def weighted(self, curves: ModelCurves) -> np.ndarray:
        """``(model − measured) / σ`` of every quantity, one after the other; 0 where a sample is left out.

        Raises ``ValueError`` where a residual exceeds :func:`largest_residual` (its square and the Jacobian's would
        overflow: the optimizer took nan steps), naming the quantity, the noise and both curves' magnitudes."""
        parts = []
        bound = largest_residual(sum(values.size for values in self.measurement.values.values()))
        for name in self.quantities:
            measured, noise = self.measurement.values[name], self.measurement.noise[name]
            with np.errstate(over="ignore"):
                difference = (curves.values[name] - measured) / noise
            difference = np.where(np.isnan(difference), 0.0, difference)
            if not np.all(np.abs(difference) <= bound):
                model = float(np.nanmax(np.abs(curves.values[name]), initial=0.0))
                data = float(np.nanmax(np.abs(measured), initial=0.0))
                raise ValueError(f"{self.measurement.candidate.source}: {name}'s residual (model − measured)/σ "
                                 f"reaches {float(np.max(np.abs(difference))):.3g} with the noise σ = {noise:.3g} "
                                 f"({'given' if self.measurement.noise_given[name] else 'estimated from the data'}), "
                                 f"the model's largest |{name}| {model:.3g} and the measured {data:.3g} (SI); allowed: "
                                 f"residuals up to {bound:.3g}, whose squares stay finite (check the data's unit, "
                                 "units=, or give noise=)")
            parts.append(difference)
        return np.concatenate(parts)

    def jacobian(self, theta: np.ndarray) -> np.ndarray:
        """Forward differences of :data:`FD_STEP` in each scaled parameter (backward at an upper bound).

        A sample whose contact state the step changes (the jump at a pull-off or a contact made moved across
        it) has no derivative there: its entry is 0 (the residual is flat on either side of the jump), not
        the jump over the step, which would claim a precision the data do not have.
        """
        curves, base = self.evaluated(theta)
        same_state = np.tile(curves.in_contact, len(self.quantities))
        _, upper = self.free.scaled_bounds()
        columns = []
        for j in range(theta.size):
            step = FD_STEP if theta[j] + FD_STEP <= upper[j] else -FD_STEP
            moved = theta.copy()
            moved[j] += step
            trial = self.curves(moved)
            column = (self.weighted(trial) - base) / step
            columns.append(np.where(same_state == np.tile(trial.in_contact, len(self.quantities)), column, 0.0))
        return np.column_stack(columns)


def solve(problem: Problem) -> optimize.OptimizeResult:
    """Minimise the problem's ``Σ r²`` from the start values, within the bounds (scaled parameters).

    Parameters
    ----------
    problem : Problem
        The weighted residuals of the fit.

    Returns
    -------
    scipy.optimize.OptimizeResult
        ``least_squares``' result: ``x`` the scaled optimum, ``jac`` the Jacobian there (the problem's own,
        asked for at the optimum last), ``nfev``, ``status`` and ``message``.
    """
    free = problem.free
    theta0 = free.to_scaled(free.start_values())
    lower, upper = free.scaled_bounds()
    return optimize.least_squares(problem.residuals, theta0, jac=lambda theta: problem.jacobian(theta),
                                  bounds=(lower, upper), method="trf", x_scale=1.0, xtol=FIT_TOLERANCE,
                                  ftol=FIT_TOLERANCE, gtol=FIT_TOLERANCE,
                                  max_nfev=MAX_EVALUATIONS_PER_PARAMETER * len(free.names))
