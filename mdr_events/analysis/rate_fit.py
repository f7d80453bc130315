"""Fitting the rate-dependent adhesion law to normal-force curves measured at several speeds, jointly.

Researchers measure the same indentation at several speeds; the law's ``v_ref`` and ``n`` (and, if asked, its works
at rest) are shared by all the curves, while each curve may carry its own force offset (a load cell's zero). The
forward model is the normal problem of :func:`~mdr_events.models.continuum.solve_edge`; ``least_squares`` minimises
the weighted residuals of every curve together, with ``v_ref`` and the works on a log scale and ``n`` in ``(0, 1]``.
The intervals are those of the linearised model at the optimum, ``cov = s² (JᵀJ)⁻¹`` in the scaled parameters, with
``s²`` the residuals' variance where no noise is given, mapped back to each parameter's unit (log-scaled ones
asymmetric).

A trial law whose edge the paths' clocks cannot follow (:class:`~mdr_events.models.continuum.rate_edge.EdgeUnresolved`:
a ``v_ref`` many orders above a path's speed makes the ODE too stiff, one far below it lets the indenter outrun the
advancing edge) is a rejected step: its residuals are ``nan``, on which ``least_squares``' trust region (``trf``)
shrinks to a quarter of the step and tries again. The Jacobian (:func:`_jacobian`) is the forward difference of
``scipy``'s ``2-point`` scheme, taken backwards in a law's column whose forward step is refused or beyond a bound;
the offsets' columns are exact (the residuals are linear in them). Only the start must be followed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
import xarray as xr
from scipy import optimize

from mdr_events.analysis.fit_data import estimate_noise
from mdr_events.analysis.fit_diagnostics import (MISFIT_RMS, Identifiability, exp_or_inf, identifiability_of,
                                                 scaled_or_inf)
from mdr_events.analysis.rate_angles import EDGE_SOLVE_STEPS, check_rate_factor
from mdr_events.contact.adhesion import RateDependentAdhesion, check_rate_law
from mdr_events.io.datasets import register_schema
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits, values_in
from mdr_events.models.continuum.rate_edge import EdgeUnresolved, solve_edge
from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters, check_parameters
from mdr_events.theory.scales import check_representable
from mdr_events.validation import SCALE_MAX, SCALE_MIN, check_flag, check_real, real_array, shown

__all__ = ["RateMeasurement", "fit_rate_adhesion", "RATE_FREE_NAMES", "RATE_FIT_RTOL", "RATE_FIT_METHOD",
           "RATE_FIT_CONTENT"]

#: The ``content`` attribute of a joint fit of the rate law (its schema registered below, read by ``open_result``).
RATE_FIT_CONTENT = "joint fit of the rate-dependent adhesion law to normal-force curves at several speeds"

#: The law's values that may be free, with their units; those on a log scale.
RATE_FREE_NAMES = {"v_ref": "m s-1", "n": "1", "dgamma0": "J m-2", "dgamma1": "J m-2"}
_LOG_SCALED = ("v_ref", "dgamma0", "dgamma1")
#: The edge's ODE in a fit: LSODA at this tolerance, whose curves lie within ~2e-9 of the reference (Radau at 1e-12)
#: on the paper's paths, in about a seventh of Radau's time at the same accuracy: far below a measurement's noise, and
#: far below what a Jacobian's step ``FD_STEP`` moves a curve by (500 times), so the finite differences are the
#: model's, not the integrator's.
RATE_FIT_RTOL = 1e-10
RATE_FIT_METHOD = "LSODA"
#: The laws whose curves a fit keeps: the Jacobian's centre and the latest step (an offset's column moves no law).
KEPT_LAWS = 2
#: least_squares' tolerances (xtol, ftol, gtol) on the scaled parameters.
FIT_TOLERANCE = 1e-10
#: The bounds of ``n`` and the relative step of the finite differences of the Jacobian.
N_BOUNDS = (1e-3, 1.0)
FD_STEP = 1e-6
#: The confidence of the intervals.
CONFIDENCE = 0.95
#: The bytes one measured sample takes in a fit (its time and force, the model's radius, depth and force, the
#: residual and a row of the Jacobian per free value; counted against ``Limits.memory``).
BYTES_PER_SAMPLE = 128


class RateMeasurement(NamedTuple):
    """One measured normal-force curve.

    Parameters
    ----------
    path : Path
        The path the indenter followed (its speed is the curve's).
    times : numpy.ndarray
        The sample times (s, on the path's clock).
    normal_force : numpy.ndarray
        ``F_N`` (N) at them.
    noise : float, optional
        The standard deviation of its noise (N); ``None``: estimated from the fit's residuals.
    """

    path: Path
    times: np.ndarray
    normal_force: np.ndarray
    noise: float | None = None


def _check(measurements, params, start, free, offsets, profile, limits) -> Limits:
    """Refuse what the fit cannot take, before anything is solved: each argument's type and range, each curve's
    samples (real, finite, 1-D, within the path's clock and the double range), their count and the solves of the
    edge the first step takes (the start and a Jacobian's column per free value of the law, each curve once:
    :data:`~mdr_events.analysis.rate_angles.EDGE_SOLVE_STEPS` steps a solve) against ``limits``, which it returns."""
    check_parameters(params)
    check_rate_law(start, "start")
    check_flag("offsets", offsets)
    limits = check_limits(limits)
    if isinstance(free, str) or not isinstance(free, Sequence) or not all(isinstance(name, str) for name in free):
        raise TypeError(f"free={shown(free)} ({type(free).__name__}) is not allowed; allowed: a list or tuple of names "
                        f"among {', '.join(RATE_FREE_NAMES)}")
    unknown = [name for name in free if name not in RATE_FREE_NAMES]
    if unknown or not free or len(set(free)) != len(free):
        raise ValueError(f"free={shown(free)} is not allowed; allowed: distinct names among "
                         f"{', '.join(RATE_FREE_NAMES)}")
    if "n" in free and start.n < N_BOUNDS[0]:
        raise ValueError(f"start.n={start.n!r} is not allowed with n free; allowed: {N_BOUNDS[0]:g} <= n <= "
                         f"{N_BOUNDS[1]:g} (the fit's bounds on n)")
    if isinstance(measurements, (str, bytes)) or not isinstance(measurements, Sequence) or not measurements or not all(
            isinstance(m, RateMeasurement) for m in measurements):
        raise TypeError(f"measurements={shown(measurements)} is not allowed; allowed: a non-empty list or tuple of "
                        "RateMeasurement(path, times, normal_force[, noise])")
    profile = check_simulated_profile(profile)
    # (the samples counted before they are read: round twenty-four, a million were converted three times, 24 MB, to
    # be refused for their count)
    total = sum(values_in(m.times) for m in measurements)
    first_step = len(measurements) * (1 + len(free))
    limits.check(f"the fit's {len(measurements)} curve(s) of {total} samples ({first_step} solves of the edge in its "
                 "first step)", samples=total, memory=BYTES_PER_SAMPLE * total, steps=first_step * EDGE_SOLVE_STEPS)
    for index, m in enumerate(measurements):
        _check_curve(f"measurements[{index}]", m, params, profile)
        check_rate_factor(start, m.path.speed, "start")  # (the start at its limit ended in the edge solver's words)
    return limits


def _check_curve(name: str, m: RateMeasurement, params: Parameters, profile: SimulatedProfile) -> None:
    """One curve's path (its speed's scales with ``params`` and ``profile`` within the double range), samples and
    noise (:func:`_check`)."""
    if not isinstance(m.path, Path):
        raise TypeError(f"{name}.path={shown(m.path)} ({type(m.path).__name__}) is not allowed; allowed: a Path")
    try:  # (as the angles at speeds check theirs; round nineteen: a speed of 1e308 m/s was named by the times, on a
        # path of 1.2e-311 s)
        check_representable(params.replace(v=m.path.speed), profile)
    except ValueError as error:
        raise ValueError(f"{name}.path.speed={m.path.speed!r} m/s: {error}") from None
    allowed = "a 1-D array of finite real numbers"
    times = real_array(f"{name}.times", m.times, allowed + " (s on the path's clock)")
    force = real_array(f"{name}.normal_force", m.normal_force, allowed + " (N)")
    if times.ndim != 1 or times.size < 2:
        raise ValueError(f"{name}.times of shape {times.shape} is not allowed; allowed: {allowed} of length >= 2")
    if force.shape != times.shape:
        raise ValueError(f"{name}.normal_force of shape {force.shape} is not allowed; allowed: {allowed} of the "
                         f"times' length, shape {times.shape}")
    for part, values in (("times", times), ("normal_force", force)):
        if not np.all(np.isfinite(values)):
            index = int(np.flatnonzero(~np.isfinite(values))[0])
            raise ValueError(f"{name}.{part}[{index}]={float(values[index])!r} is not allowed; allowed: {allowed}")
    outside = (times < 0.0) | (times > m.path.duration)
    if np.any(outside):
        raise ValueError(f"{name}.times={float(times[outside][0])!r} s is not allowed; allowed: times on the path's "
                         f"clock, in [0, {m.path.duration!r}] s")
    if np.max(np.abs(force)) > SCALE_MAX:
        raise ValueError(f"{name}.normal_force={float(force[np.argmax(np.abs(force))])!r} N is not allowed; allowed: "
                         f"magnitudes at most {SCALE_MAX:.2g} N (the double range's square root)")
    if m.noise is not None:  # (from SCALE_MIN: its weight 1/noise finite; round nineteen: 1e-320 gave inf weights,
        # whose nan residuals blamed the start's edge)
        check_real(f"{name}.noise", m.noise, f"None or a finite number from {SCALE_MIN:.2g} to {SCALE_MAX:.2g} (N)",
                   lambda value: SCALE_MIN <= value <= SCALE_MAX)


def _law(values: dict[str, float]) -> RateDependentAdhesion:
    return RateDependentAdhesion(values["dgamma0"], values["dgamma1"], values["v_ref"], values["n"])


class TrialBeyondLaw(Exception):
    """A trial step of the fit to values no law has (rejected as a law whose edge is not followed)."""


def _trial(params: Parameters, values: dict[str, float]) -> tuple[RateDependentAdhesion, Parameters]:
    """The law of a trial's ``values`` and the parameters with its works, or :class:`TrialBeyondLaw` where no law has
    them (``dgamma1 < dgamma0`` with both free, or a log-scaled value beyond the double range): they raised
    ``OverflowError`` or named, as the user's, a value the user never gave (round eighteen)."""
    try:
        return _law(values), params.replace(dgamma0=values["dgamma0"], dgamma1=values["dgamma1"])
    except ValueError:
        raise TrialBeyondLaw from None


def fit_rate_adhesion(measurements: Sequence[RateMeasurement], params: Parameters, start: RateDependentAdhesion,
                      free: Sequence[str] = ("v_ref", "n"), offsets: bool = False,
                      profile: SimulatedProfile = None, *, limits: Limits = DEFAULT_LIMITS) -> xr.Dataset:
    """Fit the rate-dependent law jointly to normal-force curves measured at several speeds (module docstring).

    Parameters
    ----------
    measurements : sequence of RateMeasurement
        The curves, each with its own path (and speed).
    params : Parameters
        The material and ``R`` (the paraboloid's); its works of adhesion are the start's.
    start : RateDependentAdhesion
        The law to start from; the values not free keep theirs.
    free : sequence of str, optional
        The law's values to fit, among :data:`RATE_FREE_NAMES` (default ``v_ref`` and ``n``).
    offsets : bool, optional
        Give each curve a free force offset (N), added to the model's.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    limits : Limits, optional
        The resource limits the curves' samples (summed) and the first step's solves of the edge are checked against
        before the fit runs; each later solve is counted as it comes
        (:data:`~mdr_events.analysis.rate_angles.EDGE_SOLVE_STEPS` steps each).

    Returns
    -------
    xarray.Dataset
        ``estimate``, ``standard_error``, ``interval_lower`` and ``interval_upper`` per parameter (the law's free
        values, then the offsets) with its ``identifiability`` (as :func:`~mdr_events.fit`'s verdicts, the law's values
        on its scale: :func:`_verdict`), ``correlation`` between them, and per curve the RMS of its weighted residuals
        and ``misfit``, the RMS of its residuals over its noise (given, or estimated from the curve as fit estimates
        it: above :data:`~mdr_events.analysis.fit_diagnostics.MISFIT_RMS` the law does not describe it);
        attributes: the residuals' variance ``s2``, the solves, the rejected trials (``rejected_trials``: laws
        whose edge a path did not follow, module docstring), ``least_squares``' status and message.

    Raises
    ------
    TypeError
        Measurements, parameters, a start, free names or offsets of another kind.
    ValueError
        A free name not allowed, a curve that is not finite 1-D, outside its path's clock or beyond the double
        range, a noise that is not positive, a start's ``n`` below the fit's bound, a start whose edge a path does
        not follow, a Jacobian at a law neither of whose neighbours' edges are followed, samples or solves beyond
        ``limits`` (``ResourceLimitError``).
    """
    limits = _check(measurements, params, start, free, offsets, profile, limits)
    base = {"v_ref": start.v_ref, "n": start.n, "dgamma0": start.dgamma0, "dgamma1": start.dgamma1}
    count = len(measurements)
    names = list(free) + ([f"offset_{index}" for index in range(count)] if offsets else [])
    forces = [np.asarray(m.normal_force, dtype=float) for m in measurements]
    weights, scale = _weights(measurements)
    curves: dict[tuple[float, ...], list[np.ndarray] | None] = {}  # the model's curves by the law's values, the
    # latest few (None: the law's edge is not followed on a path, a rejected trial)
    solves, rejected = [0], [0]

    def values_of(theta: np.ndarray) -> dict[str, float]:
        values = dict(base)
        for name, value in zip(free, theta):
            values[name] = exp_or_inf(value) if name in _LOG_SCALED else float(value)
        return values

    def model_curves(values: dict[str, float]) -> list[np.ndarray] | None:
        """Each curve of the law of ``values``, solved once: a Jacobian's columns of the offsets, which move no law,
        and a step that moves an offset alone cost no solve. ``None`` where a path's edge is not followed (the
        curves after it are not solved)."""
        key = tuple(values[name] for name in RATE_FREE_NAMES)
        if key not in curves:
            if len(curves) >= KEPT_LAWS:
                del curves[next(iter(curves))]
            solves[0] += len(measurements)  # (each trial's solves counted as they come: 1000 curves ran for hours)
            limits.check(f"the fit's {count} curve(s) ({solves[0]} solves of the edge so far)",
                         steps=solves[0] * EDGE_SOLVE_STEPS)
            try:
                law, trial = _trial(params, values)
                curves[key] = [solve_edge(trial, m.path, law, profile=profile, rtol=RATE_FIT_RTOL,
                                          method=RATE_FIT_METHOD).normal_force(np.asarray(m.times, dtype=float), m.path)
                               for m in measurements]
            except (EdgeUnresolved, TrialBeyondLaw):
                rejected[0] += 1
                curves[key] = None
        return curves[key]

    def residuals(theta: np.ndarray) -> np.ndarray:
        models = model_curves(values_of(theta))
        if models is None:  # (a rejected trial: least_squares shrinks its step)
            return np.full(sum(force.size for force in forces), np.nan)
        parts = []
        for index, (model, weight) in enumerate(zip(models, weights)):
            if offsets:
                model = model + theta[len(free) + index]
            parts.append(_weighted(index, model, weight, measurements[index], bound))
        return np.concatenate(parts)

    bound = _residual_bound(sum(force.size for force in forces))
    theta0 = np.array([math.log(base[name]) if name in _LOG_SCALED else base[name] for name in free]
                      + [0.0] * (count if offsets else 0))
    lower, upper = _scaled_bounds(names)
    _check_start(residuals(theta0), start)
    blocks = _offset_blocks(forces, weights) if offsets else None
    solution = optimize.least_squares(residuals, theta0, jac=lambda theta: _jacobian(residuals, theta, len(free),
                                                                                     (lower, upper), blocks),
                                      bounds=(lower, upper), x_scale="jac", xtol=FIT_TOLERANCE, ftol=FIT_TOLERANCE,
                                      gtol=FIT_TOLERANCE)
    return _result(solution, names, free, values_of, measurements, forces, scale, (solves[0], rejected[0]))


def _weights(measurements: Sequence[RateMeasurement]) -> tuple[list[float], float]:
    """Each curve's weight ``1/σ`` (1 where no noise is given) over the largest, and that largest weight ``c``.

    ``least_squares`` minimises the residuals weighted by the ratios alone, each curve's ``(model − measured) σ_min/σ``
    in newtons, whatever the noises' scale: the optimum of ``Σ r²`` does not change with a common factor of the
    weights, while their own scale ran the trust region's products out of the double range (round nineteen: a
    noise of 1e-100 N gave SciPy's overflow warnings and a fit stopped where it started, exit 0; 1e-300 N "array
    must not contain infs or NaNs"). The covariance and the RMS are scaled back by ``c`` (:func:`_result`)."""
    weights = [1.0 / m.noise if m.noise is not None else 1.0 for m in measurements]
    scale = max(weights)
    return [weight / scale for weight in weights], scale


def _residual_bound(samples: int) -> float:
    """:func:`~mdr_events.analysis.fit_problem.largest_residual` of ``samples`` residuals (imported here: this module
    registers a schema on every result's write)."""
    from mdr_events.analysis.fit_problem import largest_residual

    return largest_residual(samples)


def _weighted(index: int, model: np.ndarray, weight: float, m: RateMeasurement, bound: float) -> np.ndarray:
    """Curve ``index``'s residuals ``weight (model − measured)`` (``weight`` as :func:`_weights` weighs it); refused
    beyond ``bound`` (:func:`_residual_bound`, the paper law's fit's: their squares and the Jacobian's would overflow),
    naming both curves' magnitudes."""
    with np.errstate(over="ignore"):
        residual = weight * (model - np.asarray(m.normal_force, dtype=float))
    if np.all(np.abs(residual) <= bound):
        return residual
    largest = float(np.max(np.abs(residual)))  # (inf where it overflowed)
    raise ValueError(f"measurements[{index}]: the residual model − measured reaches {largest:.3g} N with the model's "
                     f"largest |F_N| {float(np.max(np.abs(model))):.3g} N and the measured "
                     f"{float(np.max(np.abs(m.normal_force))):.3g} N; allowed: residuals up to {bound:.3g} N, whose "
                     "squares stay finite (check the data's unit, or the start)")


#: The dataset's variables in each parameter's unit (the others are numbers).
_PARAMETER_UNITS = ("estimate", "standard_error", "interval_lower", "interval_upper")


def _scaled_bounds(names: Sequence[str]) -> tuple[np.ndarray, np.ndarray]:
    """The bounds of the scaled parameters ``names`` as the fit takes them: :data:`N_BOUNDS` for ``n``, none else."""
    lower = np.array([N_BOUNDS[0] if name == "n" else -np.inf for name in names])
    upper = np.array([N_BOUNDS[1] if name == "n" else np.inf for name in names])
    return lower, upper


def _verdict(name: str, verdict: Identifiability) -> Identifiability:
    """What the data say of ``name``: :func:`~mdr_events.analysis.fit_diagnostics.identifiability_of`'s verdict, the
    law's values on fit's scale (``v_ref`` and the works log-scaled, ``n`` as it is: poorly determined beyond a scaled
    standard error of :data:`~mdr_events.analysis.fit_diagnostics.POOR_STANDARD_ERROR`); a force offset (N) has no
    such scale, and is poorly determined never (round nineteen: the law's values of a fit to curves in the wrong unit,
    v_ref's interval eleven decades wide, were exit 0)."""
    if name not in RATE_FREE_NAMES and verdict is Identifiability.POORLY_DETERMINED:
        return Identifiability.DETERMINED
    return verdict


def _check_start(residual: np.ndarray, start: RateDependentAdhesion) -> None:
    """Refuse a start whose edge a path's clock cannot follow (its residuals ``nan``): the fit has no step to shrink
    back to."""
    if not np.all(np.isfinite(residual)):
        raise ValueError(f"start={start!r} is not allowed: its edge cannot be followed on a measurement's path (see "
                         "solve_edge); allowed: a start whose edge every path follows (v_ref nearer the paths' speeds)")


def _offset_blocks(forces: list[np.ndarray], weights: list[float]) -> np.ndarray:
    """The offsets' columns of the Jacobian, exact: curve ``i``'s rows are ``weight_i`` in column ``i``."""
    blocks = np.zeros((sum(force.size for force in forces), len(forces)))
    row = 0
    for index, (force, weight) in enumerate(zip(forces, weights)):
        blocks[row:row + force.size, index] = weight
        row += force.size
    return blocks


def _jacobian(residuals, theta: np.ndarray, laws: int, bounds: tuple[np.ndarray, np.ndarray],
              blocks: np.ndarray | None) -> np.ndarray:
    """The Jacobian of ``residuals`` at ``theta`` (module docstring): in each of the first ``laws`` columns the forward
    difference of step ``FD_STEP max(1, |θ|)`` (``scipy``'s ``2-point`` step), backwards where the forward point lies
    beyond ``bounds`` or its law's edge is not followed (``nan`` residuals); the offsets' columns ``blocks``.

    Parameters
    ----------
    residuals : callable
        The weighted residuals of the scaled parameters.
    theta : numpy.ndarray
        Where the Jacobian is taken.
    laws : int
        The columns of the law's values (the first ones).
    bounds : tuple of numpy.ndarray
        The lower and upper bounds of ``theta``.
    blocks : numpy.ndarray or None
        The offsets' exact columns, or ``None`` without offsets.

    Returns
    -------
    numpy.ndarray
        The Jacobian, one row per residual and one column per parameter.
    """
    centre = residuals(theta)
    columns = []
    for index in range(laws):
        for way in (1.0, -1.0):
            step = np.zeros_like(theta)
            step[index] = way * FD_STEP * max(1.0, abs(theta[index]))
            moved = theta + step
            if not bounds[0][index] <= moved[index] <= bounds[1][index]:
                continue
            shifted = residuals(moved)
            if np.all(np.isfinite(shifted)):
                columns.append((shifted - centre) / (moved[index] - theta[index]))
                break
        else:
            raise ValueError(f"the fit's Jacobian at the law's value {index} (scaled {float(theta[index])!r}) is not "
                             "allowed: neither neighbour's edge is followed; allowed: a law away from the edge of what "
                             "solve_edge follows")
    return np.column_stack(columns + ([blocks] if blocks is not None else []))


def _result(solution, names, free, values_of, measurements, forces, scale, solves) -> xr.Dataset:
    """The dataset of the fit at ``solution.x``: estimates, intervals, correlations, each curve's RMS (the residuals
    and Jacobian weighted over the largest weight ``scale``, :func:`_weights`)."""
    residual, jacobian = solution.fun, solution.jac
    dof = max(residual.size - len(names), 1)
    known = all(m.noise is not None for m in measurements)
    # cov = s² (JᵀJ)⁻¹ with J = scale J': s² / scale² (JᵀJ')⁻¹; s² = 1 with every noise given, else Σr²/dof
    variance = (1.0 / scale) ** 2 if known else float(residual @ residual) / dof
    with np.errstate(over="ignore"):
        s2 = 1.0 if known else float(np.float64(variance) * scale * scale)
    covariance, error, _, verdicts, correlation = identifiability_of(jacobian, solution.x, *_scaled_bounds(names),
                                                                      variance)
    from scipy import stats  # (here: the module registers its schema on every result's write, stats costs ~0.1 s)

    quantile = float(stats.norm.ppf(0.5 + CONFIDENCE / 2.0))
    theta = solution.x
    natural = values_of(theta)
    estimate, low, high, units = [], [], [], []
    for index, name in enumerate(names):
        centre, spread = theta[index], quantile * error[index]
        if name in _LOG_SCALED:  # (an offset or n: linear)
            estimate.append(natural[name])
            low.append(math.exp(centre - spread))
            high.append(exp_or_inf(centre + spread))  # (inf where the data do not see it: a raw OverflowError)
            error[index] = scaled_or_inf(natural[name], error[index])  # to first order, in the unit
        else:
            estimate.append(centre)
            low.append(centre - spread)
            high.append(centre + spread)
        units.append(RATE_FREE_NAMES.get(name, "N"))
    rms, start = [], 0
    for force in forces:
        rms.append(scaled_or_inf(float(np.sqrt(np.mean(residual[start:start + force.size] ** 2))), scale))
        start += force.size
    misfit = [value if m.noise is not None else value / estimate_noise(force)
              for value, m, force in zip(rms, measurements, forces)]
    dataset = xr.Dataset(
        {"estimate": ("parameter", np.array(estimate)), "standard_error": ("parameter", error),
         "interval_lower": ("parameter", np.array(low)), "interval_upper": ("parameter", np.array(high)),
         "correlation": (("parameter", "parameter_2"), correlation),
         "residual_rms": ("measurement", np.array(rms)), "misfit": ("measurement", np.array(misfit)),
         "identifiability": ("parameter", np.array([_verdict(name, verdict).value
                                                    for name, verdict in zip(names, verdicts)]))},
        coords={"parameter": names, "parameter_2": names, "measurement": np.arange(len(forces))})
    long_names = {"estimate": "the fitted value", "standard_error": "its standard error (linearised)",
                  "interval_lower": f"lower end of its {CONFIDENCE:.0%} interval",
                  "interval_upper": f"upper end of its {CONFIDENCE:.0%} interval",
                  "correlation": "correlation of the estimates (linearised)",
                  "residual_rms": "RMS of the curve's weighted residuals (1: as noisy as its noise)",
                  "misfit": "RMS of the curve's residuals over its noise, given or estimated from its second "
                            f"differences (as fit's: above {MISFIT_RMS:g} the law does not describe the curve)",
                  "identifiability": "what the data say of the value (as fit's: determined, poorly determined, not "
                                     "identifiable, at a bound)"}
    for name, text in long_names.items():
        dataset[name].attrs.update(long_name=text, units="varies" if name in _PARAMETER_UNITS else "1")
    dataset["parameter"].attrs.update(units="1", long_name="the fitted value's name",
                                      units_of_each=", ".join(f"{n}: {u}" for n, u in zip(names, units)))
    dataset["parameter_2"].attrs.update(units="1", long_name="the fitted value's name (the correlation's columns)")
    dataset["measurement"].attrs.update(units="1", long_name="the measurement's index, in the order given")
    dataset.attrs.update(s2=s2, noise_known=int(known), solves=solves[0], rejected_trials=solves[1],
                         status=int(solution.status),
                         message=str(solution.message), confidence=CONFIDENCE, content=RATE_FIT_CONTENT)
    return dataset


register_schema(RATE_FIT_CONTENT, {"estimate": ("parameter",), "standard_error": ("parameter",),
                                   "interval_lower": ("parameter",), "interval_upper": ("parameter",),
                                   "correlation": ("parameter", "parameter_2"), "residual_rms": ("measurement",)})
