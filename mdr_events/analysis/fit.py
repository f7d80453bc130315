"""Fit the model to measured curves: :func:`fit` (the continuum method, any path it accepts).

Given measured ``F_N(t)``, ``F_x(t)`` and ``A(t)`` (or ``a(t)``; any subset), which moduli, critical shear
stress and works of adhesion (and which time and depth offset of the experiment's zero) explain them, how
well are they determined, and can the data determine them at all?

The measurement is read as in :func:`mdr_events.validate` (:func:`mdr_events.io.candidates.read_candidate`:
a Dataset, arrays, a CSV or netCDF file, your names and units). The residuals are

``r = (model − measured) / σ_q``

per quantity ``q`` and sample, with ``σ_q`` the noise of the quantity: given (``noise=``) or estimated from
the data (:func:`estimate_noise`). ``scipy.optimize.least_squares`` minimises ``Σ r²`` over the free
parameters in scaled form (:data:`LOG_SCALED` on a log scale, the offsets relative to the path's duration
and depth; :class:`FreeParameters`).

The fit's parts, one idea each, every name re-exported here as before:

- :mod:`~mdr_events.analysis.fit_parameters`: the free parameters, their units, scaling, bounds and starts;
- :mod:`~mdr_events.analysis.fit_data`: the measurement, its noise, the model's curves at its samples (with the
  rule for samples out of contact) and synthetic measurements;
- :mod:`~mdr_events.analysis.fit_problem`: the weighted residuals, their Jacobian and the least-squares solve;
- :mod:`~mdr_events.analysis.fit_diagnostics`: the uncertainty (covariance, intervals), identifiability, notes
  and warnings at the optimum;
- :mod:`~mdr_events.analysis.fit_accuracy`: how a fit's results are determined (when two fits agree);
- this module: the job of :func:`fit`, the fit itself, its dataset and :class:`FitResult`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping, NamedTuple, Sequence

import numpy as np
import xarray as xr
from scipy import optimize

from mdr_events.analysis.reports import check_content
from mdr_events.analysis.fit_accuracy import register_fit_accuracy
# (the fit's parts: every name of before is importable from here too)
from mdr_events.analysis.fit_data import (FITTED_QUANTITIES, NOISE_FLOOR_SHARE, QUANTITY_SYMBOLS, QUANTITY_UNITS,
                                          SYNTHETIC_CONTENT, Measurement, ModelCurves, curves_of, estimate_noise,
                                          measurement_of, model_curves, shifted_path, synthetic_measurement)
from mdr_events.analysis.fit_diagnostics import (BOUND_SHARE, CONFIDENCE, CONTACT_NOISE_MULTIPLE, CONTACT_TIME_SHARE,
                                                 FADE_MULTIPLE, LOG_LARGEST, MAGNITUDE_FACTOR, MISFIT_RMS,
                                                 POOR_STANDARD_ERROR, RCOND, STRONG_CORRELATION, TANGENTIAL_ONLY,
                                                 Identifiability, ParameterEstimate, scaled_or_inf, effective_moduli,
                                                 fit_warnings, identifiability_notes, identifiability_of,
                                                 natural_intervals)
from mdr_events.analysis.fit_parameters import (FREE_NAMES, FRICTION_NAME, LOG_SCALED, NU_MARGIN, OFFSET_BOUND_REACH,
                                                OFFSET_LONG_NAMES, OFFSET_UNITS, OFFSETS, FreeParameters,
                                                free_parameters, unit_of)
from mdr_events.analysis.fit_problem import FD_STEP, FIT_TOLERANCE, MAX_EVALUATIONS_PER_PARAMETER, Problem, solve
from mdr_events.theory.job import rate_independent
from mdr_events.analysis.validate import one_path, one_path_job, reference_of
from mdr_events.contact import Contact
from mdr_events.contact.friction import friction_attrs
from mdr_events.io.candidates import Candidate, read_candidate
from mdr_events.io.datasets import figure_of, read_text_list, register_schema, stamp, text_list_attrs
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.models.continuum import Tolerances
from mdr_events.models.indenters import profile_attrs
from mdr_events.models.methods import Continuum
from mdr_events.models.motion import Scenario
from mdr_events.models.paths import Path
from mdr_events.models.job import ModelJob
from mdr_events.parameters import PARAMETER_UNITS, Parameters
from mdr_events.theory.scales import check_representable
from mdr_events.validation import check_callback, shown

__all__ = ["fit", "FitResult", "OptimizerRun", "synthetic_measurement", "model_curves", "curves_of", "FreeParameters", "Identifiability", "ParameterEstimate", "estimate_noise",
           "FIT_CONTENT", "SYNTHETIC_CONTENT", "FREE_NAMES", "FITTED_QUANTITIES", "LOG_SCALED", "OFFSETS"]

#: Bytes a fit holds per measured sample at its peak beyond a part per quantity fitted and free parameter: the model's
#: curves at the samples, the residuals and the Jacobian's columns (one per free parameter, each of every quantity),
#: the optimizer's copies (:func:`fit_bytes`). Measured with tracemalloc after a warm-up, 3e4 and 1e5 samples of the
#: paper's A 20 deg: 397 B a sample with one quantity and tau0 free (430 B on a 5 mm layer), 788 B with four, 721 B
#: with one and six free, 1786 B with four and six free; 384 + 72 q (f + 1) bounds each (0.74-0.82 of it). Issue 32,
#: round 30: 1e7 samples, accepted by ``samples``, held 4-18 GB under a 2 GiB limit.
FIT_BYTES_PER_SAMPLE, FIT_BYTES_PER_SAMPLE_VALUE = 384, 72


def fit_bytes(samples: int, quantities: int, free: int) -> int:
    """The memory a fit of ``samples`` measured samples of ``quantities`` quantities with ``free`` free parameters
    holds at its peak (:data:`FIT_BYTES_PER_SAMPLE`), to count against ``Limits.memory`` before its first solve."""
    return samples * (FIT_BYTES_PER_SAMPLE + FIT_BYTES_PER_SAMPLE_VALUE * quantities * (free + 1))


#: The ``content`` attribute of a fit's dataset.
FIT_CONTENT = "fit of the model to measured curves"


class OptimizerRun(NamedTuple):
    """How the optimizer got there: a log, not a result (the counts depend on its path, which rounding changes
    from one CPU to another, so no compared dataset holds them)."""

    continuum_solves: int  #: continuum solves of the fit, the Jacobian's included
    evaluations: int  #: residual evaluations of ``least_squares``
    status: int  #: ``least_squares``' status (> 0: converged)
    message: str  #: ``least_squares``' message

    def describe(self) -> str:
        return f"{self.continuum_solves} continuum solves, {self.evaluations} optimizer evaluations: {self.message}"


@dataclass(frozen=True)
class FitResult:
    """What :func:`fit` found: the labelled dataset (:attr:`dataset`, everything) and its main readings.

    Parameters
    ----------
    dataset : xarray.Dataset
        Along ``parameter``: ``estimate``, ``start``, ``standard_error``, ``lower_95``, ``upper_95``,
        ``identifiability``; ``correlation`` (``parameter`` × ``parameter_2``); along ``time`` (the measured
        samples, s on the measurement's clock): ``measured_<q>``, ``fitted_<q>``, ``residual_<q>``
        (measured − fitted, ``nan`` where left out), ``left_out``; along ``quantity``: ``noise``,
        ``noise_given``, ``rms_normalised_residual``; scalars ``condition_number``, ``reduced_chi_square``,
        ``E_star``/``G_star`` (with ``*_standard_error``); attributes ``verdict``, ``identifiable``, ``notes``,
        ``warnings`` (:attr:`warnings`), ``optimizer_converged`` and what the accuracy of the results follows from
        (``optimizer_tolerance``, ``jacobian_step``, ``continuum_rtol``: :mod:`mdr_events.analysis.fit_accuracy`).
    parameters : Parameters
        The start with the fitted values in place.
    time_offset : float
        The fitted offset of the measurement's clock (s; 0 where not free).
    depth_offset : float
        The fitted offset of the measured depth (m; 0 where not free).
    optimizer : OptimizerRun or None
        The optimizer's log: solves, evaluations, status and message (``None`` for a result read from a file).
    """

    dataset: xr.Dataset
    parameters: Parameters
    time_offset: float
    depth_offset: float
    optimizer: OptimizerRun | None

    @property
    def estimates(self) -> dict[str, ParameterEstimate]:
        """Each free parameter's :class:`ParameterEstimate`."""
        d = self.dataset
        return {str(name): ParameterEstimate(float(d["estimate"].sel(parameter=name)),
                                             float(d["standard_error"].sel(parameter=name)),
                                             float(d["lower_95"].sel(parameter=name)),
                                             float(d["upper_95"].sel(parameter=name)),
                                             Identifiability(str(d["identifiability"].sel(parameter=name).values)))
                for name in d["parameter"].values}

    @property
    def correlation(self) -> np.ndarray:
        """The correlation matrix of the free parameters' estimates (scaled parameters), ``parameter`` ×
        ``parameter_2``."""
        return self.dataset["correlation"].values

    @property
    def condition_number(self) -> float:
        """The condition number of the weighted Jacobian at the optimum (scaled parameters)."""
        return float(self.dataset["condition_number"])

    @property
    def identifiable(self) -> bool:
        """Whether every free parameter is :attr:`Identifiability.DETERMINED`."""
        return bool(self.dataset.attrs["identifiable"])

    @property
    def verdict(self) -> str:
        """The verdict in words: whether every free parameter is determined (naming the others) and whether the fit
        describes the data (the dataset's attribute ``verdict``)."""
        return str(self.dataset.attrs["verdict"])

    @property
    def warnings(self) -> list[str]:
        """What says the fit does not describe the data (residuals far above the noise, a unit or a time origin
        that looks wrong); empty for a good fit. The intervals assume the model describes the data."""
        return read_text_list(self.dataset.attrs, "warnings")

    @property
    def notes(self) -> list[str]:
        """What the identifiability analysis says beside the verdicts (strong correlations, a bound reached)."""
        return read_text_list(self.dataset.attrs, "notes")

    @classmethod
    def from_dataset(cls, dataset: xr.Dataset) -> "FitResult":
        """The result of a fit's dataset (e.g. a file read by :func:`~mdr_events.open_result`; those written before
        the lists of notes and warnings too): its parameters from the attributes, the fitted offsets from the
        estimates (0 where not free); :attr:`optimizer` is ``None`` (its log is in no dataset).

        Parameters
        ----------
        dataset : xarray.Dataset
            A fit's dataset (attribute ``content`` a fit's).

        Returns
        -------
        FitResult
            The result, its :attr:`optimizer` ``None``.

        Raises
        ------
        ValueError
            A dataset of another kind of result.
        """
        check_content(dataset, FIT_CONTENT, "fit")
        names = [str(name) for name in dataset["parameter"].values]
        offset = {name: float(dataset["estimate"].sel(parameter=name)) if name in names else 0.0
                  for name in ("time_offset", "depth_offset")}
        return cls(dataset, Parameters.from_attrs(dataset.attrs), offset["time_offset"], offset["depth_offset"], None)

    def to_dataset(self) -> xr.Dataset:
        """The labelled dataset (:attr:`dataset`), what :func:`~mdr_events.write_netcdf` writes.

        Returns
        -------
        xarray.Dataset
            The dataset itself, not a copy.
        """
        return self.dataset

    def __repr__(self) -> str:
        lines = [f"FitResult: {self.verdict}"]
        for name, estimate in self.estimates.items():
            lines.append(f"  {name} = {estimate.value:.6g} ± {estimate.standard_error:.3g}, 95 % [{estimate.lower:.6g}, "
                         f"{estimate.upper:.6g}] ({estimate.identifiability.value})")
        lines += [f"  warning: {text}" for text in self.warnings]
        return "\n".join(lines)

    @property
    def residuals(self) -> xr.Dataset:
        """The residuals (measured − fitted) per quantity along the measured time, and ``left_out``."""
        return self.dataset[[name for name in self.dataset.data_vars if name.startswith("residual_")] + ["left_out"]]

    @property
    def curves(self) -> xr.Dataset:
        """The measured and fitted curves along the measured time."""
        return self.dataset[[name for name in self.dataset.data_vars
                             if name.startswith(("measured_", "fitted_"))]]

    def plot(self, title: str | None = None):
        """Data, fit and residuals (:func:`mdr_events.plotting.fit.plot_fit`).

        Parameters
        ----------
        title : str, optional
            The figure's title; default: the verdict. The estimates with their 95 % intervals are listed below it.

        Returns
        -------
        matplotlib.figure.Figure
            Measured and fitted curves against time (top), the residuals with the ±2σ noise band (below).
        """
        return figure_of(self.dataset)(self.dataset, title=title)


class FitJob(NamedTuple):
    """What :func:`fit` fits: the start's contact along the one path (:class:`ModelJob`; ``path_of`` rebuilds the
    path for a trial's parameters), the bounds and noise, how to read the data, the continuum's tolerances."""

    model: ModelJob
    path_of: Callable[[Parameters], Path]
    bounds: Mapping[str, tuple[float, float]] | None
    noise: Mapping[str, float] | None
    names: Mapping[str, str] | None
    units: Mapping[str, str] | None
    time_origin: Any
    tolerances: Tolerances
    select: Mapping[str, object] | None = None


def _fit_job(contact, motion, alpha, reference, options: Mapping[str, Any]) -> FitJob:
    """The job of :func:`fit`; the keywords of before, ``fit(measured, path, alpha, start=params, ...)``, read in this
    one place (their path and angle come where the contact and the motion now do)."""
    options = dict(options)
    if "start" in options:
        if motion is not None and alpha is not None:
            raise ValueError(f"alpha={shown(alpha)} is not allowed twice (the third argument is the angle with start=)")
        contact, motion, alpha = options.pop("start"), contact, (motion if motion is not None else alpha)
        if not isinstance(contact, (Parameters, Contact)):
            raise TypeError(f"start={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a "
                            "mdr_events.Parameters (the fit's start, with the fixed parameters' values)")
    values = {name: options.pop(name, None) for name in ("bounds", "noise", "names", "units", "select")}
    time_origin = options.pop("time_origin", "first_contact")
    _, tolerances = reference_of(reference, options.pop("tolerances", None), None)
    model = one_path_job(contact, motion, alpha, options, caller="fit")
    rate_independent(model.contact, "fit (its forward model, solve_path, is rate-independent)")
    if options:
        raise TypeError(f"fit() got an unexpected keyword argument {next(iter(options))!r}; allowed: bounds, noise, "
                        "names, units, time_origin, select (and start, profile, friction, tolerances as before)")
    _, angle = one_path(model)  # (one path: checked once, before any trial)
    # the scenario's angle selects its run in a result of several, as validate's does (a simulation of 20° and 30°
    # was refused "holds several runs along 'alpha'; allowed: ... --alpha" with --alpha given)
    select = values["select"] if values["select"] is not None or angle is None else {"alpha": angle}
    return FitJob(model, lambda params: one_path(model._replace(params=params))[0], values["bounds"],
                  values["noise"], values["names"], values["units"], time_origin, tolerances, select)


def fit(measured, contact: Contact | Parameters | None = None, motion=None, alpha: float | None = None, *,
        free: Sequence[str], reference: Continuum | None = None, limits: Limits = DEFAULT_LIMITS,
        progress: Callable[[str], None] | None = None, **options) -> FitResult:
    """Fit the continuum model to measured curves by weighted least squares.

    Parameters
    ----------
    measured : xarray.Dataset, mapping of arrays, or the path of a CSV / netCDF file
        Time and any of ``normal_force``, ``tangential_force``, ``contact_area``, ``contact_radius``
        (:func:`mdr_events.io.candidates.read_candidate`; ``nan`` marks a missing sample).
    contact : Contact or Parameters
        The start of the fit: the contact (:class:`~mdr_events.Contact`, or a :class:`~mdr_events.Parameters` with
        ``profile=`` and ``friction=`` among the options); the values not free keep theirs.
    motion : Scenario, Paths, Path or {"A", "B", "B+"}
        The one path of the experiment, as :func:`mdr_events.validate` takes it (a :class:`~mdr_events.Scenario` of
        one angle or a scenario's name with ``alpha``, rebuilt for each trial: its way out depends on the
        parameters; :class:`~mdr_events.Paths` of one path or a :class:`Path`). The keywords of before,
        ``fit(measured, path, alpha, start=params, ...)``, are read too.
    alpha : float, optional
        With a scenario's name: the path's angle (degrees).
    free : sequence of str
        The parameters to fit, from :data:`FREE_NAMES`: ``E``, ``nu``, ``R``, ``tau0``, ``dgamma0``,
        ``dgamma1``, ``mu`` (with a friction law that has Coulomb's part), ``h`` (on a layer of finite thickness: its
        thickness, the base kept) and the offsets ``time_offset`` (s),
        ``depth_offset`` (m).
    reference : Continuum, optional
        The continuum with its tolerances (default ``Continuum()``; ``tolerances=`` among the options says the same).
    limits : Limits
        What each continuum run may use. Another indenter than the paraboloid has no ``R`` to free; with Coulomb's
        part in the friction law, ``"mu"`` may be free (its ``μ`` the start).
    progress : callable, optional
        Hears how far reading a long CSV file is (:func:`~mdr_events.io.candidates.read_candidate`), the fit's bound
        on its continuum solves before it starts, and every
        :data:`~mdr_events.analysis.fit_problem.PROGRESS_SOLVES` solves how many it took
        (:meth:`~mdr_events.analysis.fit_problem.Problem.report_to`).
    **options
        Beside a Parameters also ``profile`` and ``friction``; and:

        ``bounds`` : mapping, optional
            Free name → ``(lower, upper)`` in its unit; default: the physical ranges (moduli, τ0 and works of
            adhesion > 0 on their log scale, ``ν`` in (−1, 0.5], the offsets unbounded).
        ``noise`` : mapping, optional
            Quantity → the standard deviation of its measurement noise (SI units); the others are estimated
            (:func:`~mdr_events.analysis.fit_data.estimate_noise`). Residuals are weighted by ``1/σ``.
        ``names``, ``units``, ``time_origin``
            As in :func:`mdr_events.validate`: your column names and units; what the measured time counts from
            (``"first_contact"`` of the path as given, ``"path_start"``, or the measured time at first contact).
        ``select`` : mapping, optional
            As in :func:`mdr_events.validate`: the run of a result of several (default: a scenario's angle selects
            its run along ``alpha``).

    Returns
    -------
    FitResult
        The estimates with their standard errors, 95 % intervals and identifiability, the correlations, the
        verdict and warnings, the fitted parameters and the labelled dataset (:class:`FitResult`).

    Raises
    ------
    ValueError
        Naming the argument: an empty or all-``nan`` measurement, a name not in :data:`FREE_NAMES`, bounds that
        exclude the start, a start of 0 for a log-scaled parameter, fewer samples than free parameters.
    """
    job = _fit_job(contact, motion, alpha, reference, options)
    _check_fit(job, free, progress)
    limits = check_limits(limits)
    read = read_candidate(measured, job.names, job.units, limits, select=job.select, progress=progress)
    nominal = job.path_of(job.model.params)
    problem = _problem(job, read, nominal, free, limits)
    problem.report_to(progress)
    solution = solve(problem)
    optimum = _optimum(problem, solution)
    params, time_offset, depth_offset = problem.free.model(optimum.theta)
    dataset = _dataset(problem, optimum, params)
    warnings = _warnings(problem, optimum, dataset, params, time_offset, depth_offset)
    attrs = _attrs(job, nominal, problem, solution, optimum, warnings)
    run = OptimizerRun(problem.solves, int(solution.nfev), int(solution.status), str(solution.message))
    return FitResult(stamp(dataset, params, **attrs), params, time_offset, depth_offset, run)


def _check_fit(job: FitJob, free: Sequence[str], progress: Callable[[str], None] | None) -> None:
    """The checks of :func:`fit` before the data are read: ``progress``, the start's scales, ``R`` free only with
    the paraboloid, Coulomb's part (its ``μ`` or ``μ`` free) and ``ν`` free only on the half-space."""
    start, profile, friction = job.model.params, job.model.profile, job.model.friction
    check_callback("progress", progress, "a line of text")
    check_representable(start, profile, friction)
    if profile is not None and "R" in free:
        raise ValueError(f"free={list(free)!r} frees R with profile={profile!r}; allowed: the names of "
                         f"{list(FREE_NAMES)} but R (the power law's shape is c and n, R belongs to the paraboloid)")
    layer = job.model.contact.layer
    if not layer.is_half_space and friction.uses_mu and (friction.coulomb_mu > 0.0 or "mu" in free):
        # (the fit's model reads the continuum's spans; round twenty-five: the first trial's refusal blamed its values,
        # "the fit tried mu=0.5, and the model refused: ...; narrow the fit with bounds= or a better start")
        raise ValueError(f"friction={friction.law!r} with mu={friction.mu!r}{' free' if 'mu' in free else ''} is not "
                         f"allowed in fit on {layer.describe()}; allowed: 'tau0' there (the fit's model reads the "
                         "continuum's spans, which take Coulomb's part on the half-space only; on a layer it runs in "
                         "simulate(..., method='continuum'), a continuum sweep and method='discrete')")
    if not layer.is_half_space and "nu" in free:
        raise ValueError(f"free={list(free)!r} frees nu on {layer.describe()}; allowed: the names of "
                         f"{list(FREE_NAMES)} but nu (each ν needs the layer's tables of its own, about 4 s to build "
                         "each: fit nu on the half-space, or give it)")


def _problem(job: FitJob, read: Candidate, nominal: Path, free: Sequence[str], limits: Limits) -> Problem:
    """The weighted residuals of the fit: the measurement on the nominal path's clock, the free parameters checked,
    more samples than free parameters and not all of them 0."""
    start, profile, friction = job.model.params, job.model.profile, job.model.friction
    measurement = measurement_of(read, nominal, job.time_origin, job.noise)
    free_set = free_parameters(free, start, job.bounds, nominal.duration, max(nominal.max_depth, start.d_max), friction,
                               job.model.contact.layer)
    limits.check(f"the fit of {read.time.size} samples of {len(measurement.values)} quantities with "
                 f"{len(free_set.names)} free parameters",
                 memory=fit_bytes(read.time.size, len(measurement.values), len(free_set.names)))
    # a scenario is rebuilt per trial (its way out ends below the jump-off, which depends on the parameters)
    problem = Problem(free_set, measurement, job.path_of, job.tolerances, limits, profile, friction,
                      job.model.contact.layer)
    samples = sum(int(np.count_nonzero(np.isfinite(v))) for v in measurement.values.values())
    if samples <= len(free_set.names):
        raise ValueError(f"{read.where}: {samples} finite samples for {len(free_set.names)} free parameters; "
                         "allowed: more samples than free parameters")
    if all(not np.any(np.nan_to_num(values)) for values in measurement.values.values()):
        raise ValueError(f"{read.where}: every measured {', '.join(measurement.values)} is 0: nothing to fit (the "
                         "parameters would run off to where the model vanishes); allowed: curves of a contact")
    return problem


class _Optimum(NamedTuple):
    """What the optimum says in the scaled parameters: the curves there, the samples compared, the goodness of fit
    and the identifiability analysis (:func:`~mdr_events.analysis.fit_diagnostics.identifiability_of`)."""

    theta: np.ndarray
    model: ModelCurves
    compared: dict[str, np.ndarray]  #: per quantity: the samples where both the data and the model have a value
    dof: int
    chi_square: float
    all_given: bool  #: every quantity's noise given (none estimated)
    covariance: np.ndarray
    scaled_error: np.ndarray
    condition: float
    verdicts: list[Identifiability]
    correlation: np.ndarray

    @property
    def reduced_chi_square(self) -> float:
        return self.chi_square / max(self.dof, 1)


def _optimum(problem: Problem, solution: optimize.OptimizeResult) -> _Optimum:
    """The analysis at the optimum ``solution.x``, with the Jacobian ``least_squares`` asked for there last."""
    theta = solution.x
    model, residual = problem.evaluated(theta)
    measurement = problem.measurement
    compared = {name: np.isfinite(model.values[name]) & np.isfinite(measurement.values[name])
                for name in problem.quantities}
    dof = sum(int(np.count_nonzero(mask)) for mask in compared.values()) - theta.size
    chi_square = float(residual @ residual)
    all_given = all(measurement.noise_given.values())
    variance_scale = 1.0 if all_given else chi_square / max(dof, 1)
    lower, upper = problem.free.scaled_bounds()
    analysis = identifiability_of(solution.jac, theta, lower, upper, variance_scale)
    return _Optimum(theta, model, compared, dof, chi_square, all_given, *analysis)


def _warnings(problem: Problem, optimum: _Optimum, dataset: xr.Dataset, params: Parameters, time_offset: float,
              depth_offset: float) -> list[str]:
    """:func:`~mdr_events.analysis.fit_diagnostics.fit_warnings` of the fit, along the fitted path."""
    rms = dict(zip(problem.quantities, dataset["rms_normalised_residual"].values.tolist()))
    fitted_path = shifted_path(problem.path_of(params), depth_offset)
    return fit_warnings(problem.measurement, optimum.model, rms, fitted_path.first_contact_time(), time_offset,
                        fitted_path.duration, "time_offset" in problem.free.names)


def _verdict(names: Sequence[str], verdicts: Sequence[Identifiability], warnings: Sequence[str]) -> tuple[bool, str]:
    """Whether every free parameter is determined, and the verdict in words (naming the others and the warnings)."""
    identifiable = all(v is Identifiability.DETERMINED for v in verdicts)
    undetermined = [f"{n} ({v.value})" for n, v in zip(names, verdicts) if v is not Identifiability.DETERMINED]
    verdict = "every free parameter is determined" if identifiable else \
        "not every free parameter is determined: " + ", ".join(undetermined)
    if warnings:
        verdict += f"; but the fit does not describe the data ({len(warnings)} warning{'s' * (len(warnings) > 1)})"
    return identifiable, verdict


def _attrs(job: FitJob, nominal: Path, problem: Problem, solution: optimize.OptimizeResult, optimum: _Optimum,
           warnings: list[str]) -> dict[str, Any]:
    """The attributes of a fit's dataset: the verdict, notes and warnings, what was fitted to what, the rules and
    what the accuracy of the results follows from, the path, indenter and friction law (with the fitted ``μ``)."""
    free = problem.free
    identifiable, verdict = _verdict(free.names, optimum.verdicts, warnings)
    notes = identifiability_notes(free.names, problem.quantities, optimum.verdicts, optimum.correlation)
    attrs = dict(content=FIT_CONTENT, verdict=verdict, identifiable=int(identifiable),
                 **text_list_attrs("notes", notes), **text_list_attrs("warnings", warnings),
                 free=", ".join(free.names), measured_source=problem.measurement.candidate.source,
                 time_origin=str(job.time_origin), path_waypoints=nominal.describe(), path_speed=nominal.speed,
                 optimizer_converged=int(solution.status > 0), optimizer_tolerance=FIT_TOLERANCE,
                 jacobian_step=FD_STEP, continuum_rtol=job.tolerances.rtol, confidence=CONFIDENCE,
                 noise_rule="given" if optimum.all_given else
                 "estimated from the data's second differences where not given",
                 out_of_contact_rule="the model's forces and area are 0 out of the elastomer; samples before a path "
                                     "that starts inside it or after one that ends in contact are left out")
    if isinstance(job.model.motion, Scenario):
        attrs.update(scenario=job.model.motion.name, alpha=float(job.model.motion.alpha[0]))
    attrs.update(profile_attrs(job.model.profile))
    attrs.update(friction_attrs(free.friction_at(optimum.theta)))  # (with the fitted μ where it is free)
    if not job.model.contact.layer.is_half_space:  # (the fitted thickness where h is free; none on the half-space)
        attrs.update(free.layer_at(optimum.theta).to_attrs())
    return attrs


def _dataset(problem: Problem, optimum: _Optimum, params: Parameters) -> xr.Dataset:
    """The fit's dataset without its attributes: the estimates (:func:`_parameter_variables`), the curves
    (:func:`_curve_variables`), their coordinates."""
    names = list(problem.free.names)
    quantities = list(problem.quantities)
    coords = {
        "time": ("time", problem.measurement.candidate.time, {"units": "s", "long_name": "measured time"}),
        "quantity": ("quantity", np.array(quantities), {"units": "1", "long_name": "quantity fitted"}),
        "parameter": ("parameter", np.array(names), {"units": "1", "long_name": "free parameter"}),
        "parameter_2": ("parameter_2", np.array(names), {"units": "1", "long_name": "free parameter"}),
        "parameter_units": ("parameter", np.array([unit_of(n) for n in names]), {"units": "1",
                                                                                  "long_name": "unit of the parameter"}),
    }
    data = {**_parameter_variables(problem.free, optimum, params), **_curve_variables(problem, optimum)}
    return xr.Dataset(data, coords=coords)


def _parameter_variables(free: FreeParameters, optimum: _Optimum, params: Parameters) -> dict[str, tuple]:
    """The variables along ``parameter`` (estimates, intervals, verdicts, correlation), the scalars (condition
    number, reduced chi-square) and the effective moduli with their standard errors."""
    value, error, low, high = natural_intervals(free, optimum.theta, optimum.scaled_error, optimum.dof)
    data = {
        "estimate": (("parameter",), value, {"units": "see parameter_units", "long_name": "fitted value"}),
        "start": (("parameter",), free.start_values(), {"units": "see parameter_units", "long_name": "start value"}),
        "standard_error": (("parameter",), error, {"units": "see parameter_units",
                                                   "long_name": "standard error (linearised at the optimum)"}),
        "lower_95": (("parameter",), low, {"units": "see parameter_units", "long_name": "lower end of the 95 % interval"}),
        "upper_95": (("parameter",), high, {"units": "see parameter_units", "long_name": "upper end of the 95 % interval"}),
        "identifiability": (("parameter",), np.array([v.value for v in optimum.verdicts]),
                            {"units": "1", "long_name": "what the data say of the parameter"}),
        "correlation": (("parameter", "parameter_2"), optimum.correlation, {"units": "1", "long_name": "correlation of "
                                                                            "the scaled parameters' estimates"}),
        "condition_number": ((), optimum.condition, {"units": "1", "long_name": "condition number of the weighted "
                                                     "Jacobian (scaled parameters)"}),
        "reduced_chi_square": ((), optimum.reduced_chi_square, {"units": "1", "long_name": "sum of squared weighted "
                                                                "residuals per degree of freedom"}),
    }
    for key, (number, standard_error) in effective_moduli(free, optimum.theta, optimum.covariance, params).items():
        symbol = "E*" if key == "E_star" else "G*"
        data[key] = ((), number, {"units": "Pa", "long_name": f"effective modulus {symbol} at the fit"})
        data[f"{key}_standard_error"] = ((), standard_error, {"units": "Pa", "long_name": f"standard error of {symbol}"})
    return data


def _curve_variables(problem: Problem, optimum: _Optimum) -> dict[str, tuple]:
    """The variables along ``time`` (measured, fitted, residual, left out) and along ``quantity`` (the noise, whether
    it was given, the RMS normalised residual)."""
    measurement, curves, compared = problem.measurement, optimum.model.values, optimum.compared
    quantities = list(problem.quantities)
    data = {}
    left_out = np.zeros(measurement.path_time.size, dtype=np.int8)
    for name in quantities:
        unit = QUANTITY_UNITS[name]
        symbol = QUANTITY_SYMBOLS[name]
        data[f"measured_{name}"] = (("time",), measurement.values[name], {"units": unit, "long_name": f"measured {symbol}"})
        data[f"fitted_{name}"] = (("time",), curves[name], {"units": unit, "long_name": f"fitted {symbol}"})
        data[f"residual_{name}"] = (("time",), np.where(compared[name], measurement.values[name] - curves[name], np.nan),
                                    {"units": unit, "long_name": f"measured − fitted {symbol}, compared samples"})
        left_out |= (~compared[name]).astype(np.int8)
    data["left_out"] = (("time",), left_out, {"units": "1", "long_name": "1: a sample left out of some quantity "
                                              "(missing, or where the model says nothing)"})
    rms = [float(np.sqrt(np.mean(((curves[q] - measurement.values[q])[compared[q]] / measurement.noise[q]) ** 2)))
           if np.any(compared[q]) else math.nan for q in quantities]
    data["noise"] = (("quantity",), np.array([measurement.noise[q] for q in quantities]),
                     {"units": "SI unit of the quantity", "long_name": "standard deviation of the measurement noise"})
    data["noise_given"] = (("quantity",), np.array([int(measurement.noise_given[q]) for q in quantities], np.int8),
                           {"units": "1", "long_name": "1: noise given, 0: estimated from the data"})
    data["rms_normalised_residual"] = (("quantity",), np.array(rms), {"units": "1", "long_name": "RMS of the residual "
                                                                      "over the noise (about 1 for a good fit)"})
    return data


#: A fit is determined as in fit_accuracy (a synthetic measurement's accuracy: fit_data).
register_fit_accuracy(FIT_CONTENT, FITTED_QUANTITIES, tuple(PARAMETER_UNITS))
register_schema(FIT_CONTENT, {"estimate": ("parameter",), "standard_error": ("parameter",),
                              "correlation": ("parameter", "parameter_2"), "left_out": ("time",)})
