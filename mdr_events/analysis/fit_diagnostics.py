"""What a fit's optimum says (:func:`mdr_events.analysis.fit.fit`): intervals, identifiability, notes, warnings.

**Uncertainty.** The covariance of the scaled parameters is ``s² (JᵀJ)⁻¹`` with ``J`` the Jacobian of the
weighted residuals at the optimum (pseudo-inverse over its singular values above :data:`RCOND` of the
largest), ``s² = Σr²/(n − p)`` where the noise was estimated and ``s² = 1`` where it was given (as
``scipy.optimize.curve_fit`` with ``absolute_sigma``). Standard errors and 95 % intervals (Student t,
``n − p`` degrees of freedom) follow in the scaled form and are mapped back (asymmetric for the log-scaled
parameters).

**Identifiability** (:class:`Identifiability`) per parameter: ``NOT_IDENTIFIABLE`` where it lies in a
direction the data do not see (a singular value below :data:`RCOND` of the largest: e.g. ``τ0`` from
``F_N`` alone, which does not depend on friction in the MDR's uncoupled springs); ``POORLY_DETERMINED``
where its scaled standard error exceeds :data:`POOR_STANDARD_ERROR`; ``AT_BOUND`` where the estimate sits
on a bound (its interval is not a linearisation's); else ``DETERMINED``. Pairs correlated beyond
:data:`STRONG_CORRELATION` are named: the data fix only a combination of them.

Beside them: the notes of the identifiability analysis (:func:`identifiability_notes`), the warnings that say the
fit does not describe the data whatever the intervals say (:func:`fit_warnings`), the effective moduli ``E*``
and ``G*`` with their standard errors (:func:`effective_moduli`).
"""

from __future__ import annotations

import enum
import math
import sys
from typing import Mapping, NamedTuple, Sequence

import numpy as np

from mdr_events.analysis.fit_data import QUANTITY_UNITS, Measurement, ModelCurves, estimate_noise
from mdr_events.analysis.fit_parameters import LOG_SCALED, FreeParameters
from mdr_events.analysis.fit_problem import FD_STEP
from mdr_events.parameters import Parameters

__all__ = ["exp_or_inf", "scaled_or_inf", "Identifiability", "ParameterEstimate", "identifiability_of", "identifiability_notes", "fit_warnings",
           "natural_intervals", "effective_moduli"]

#: Singular values below this share of the largest are directions the data do not see: the Jacobian's
#: rounding (FD_STEP against the curves' 1e-10) is ~1e-4 of a column, a parameter without effect sits
#: at ~1e-10 of the others; 1e-6 lies between.
RCOND = 1e-6
#: A scaled standard error above this is "poorly determined": a factor e^(1.96·0.5) ≈ 2.7 at 95 % for the
#: log-scaled parameters, half the path's duration or depth for the offsets, ±1 in ν.
POOR_STANDARD_ERROR = 0.5
#: Pairs correlated beyond this (in absolute value) are named: only a combination is determined.
STRONG_CORRELATION = 0.99
#: An estimate within this (scaled) of a bound sits on it.
BOUND_SHARE = 1e-8
#: The confidence level of the intervals.
CONFIDENCE = 0.95
#: A fit whose residuals exceed this many times the noise (RMS, any quantity) does not describe the data.
MISFIT_RMS = 2.0
#: A measured sample is in contact where a quantity exceeds this many times its noise.
CONTACT_NOISE_MULTIPLE = 5.0
#: The fit's curves fade out (rather than jump) at the loss of contact over the time they spend between this
#: many contact thresholds and one over this many: the data's crossing may lie anywhere in it.
FADE_MULTIPLE = 3.0
#: Contact lost this far apart in the data and the fit, or a record starting this far after the first contact
#: (a share of the path's duration; at least two sample spacings), points to a wrong time origin.
CONTACT_TIME_SHARE = 1e-3
#: Measured and fitted magnitudes (largest |value|) further apart than this factor point to a wrong unit.
MAGNITUDE_FACTOR = 10.0


class Identifiability(enum.Enum):
    """What the data say of one free parameter (see the module's notes)."""

    DETERMINED = "determined"
    POORLY_DETERMINED = "poorly determined"
    NOT_IDENTIFIABLE = "not identifiable"
    AT_BOUND = "at a bound"


class ParameterEstimate(NamedTuple):
    """One fitted parameter: the estimate, its standard error and 95 % interval (natural units), the verdict."""

    value: float
    standard_error: float
    lower: float
    upper: float
    identifiability: Identifiability


def identifiability_of(jacobian: np.ndarray, theta: np.ndarray, lower: np.ndarray, upper: np.ndarray,
                       variance_scale: float
                       ) -> tuple[np.ndarray, np.ndarray, float, list[Identifiability], np.ndarray]:
    """Covariance (scaled), the condition number and the verdict per parameter (see the module's notes).

    Parameters
    ----------
    jacobian : numpy.ndarray
        The Jacobian of the weighted residuals at the optimum (samples × scaled parameters).
    theta, lower, upper : numpy.ndarray
        The scaled optimum and bounds.
    variance_scale : float
        ``s²``: 1 where every noise was given, else the reduced chi-square.

    Returns
    -------
    covariance : numpy.ndarray
        Of the scaled parameters (pseudo-inverse over the singular values above :data:`RCOND` of the largest).
    standard_error : numpy.ndarray
        Scaled; ``inf`` for a parameter the data do not see.
    condition : float
        The condition number of the Jacobian.
    verdicts : list of Identifiability
        One per parameter.
    correlation : numpy.ndarray
        Of the scaled estimates (``nan`` in the rows and columns of a parameter the data do not see).
    """
    _, singular, vt = np.linalg.svd(jacobian, full_matrices=False)
    largest = singular[0] if singular.size and singular[0] > 0 else 1.0
    seen = singular > RCOND * largest
    condition = float(singular[0] / singular[-1]) if singular[-1] > 0 else math.inf
    inverse = np.where(seen, 1.0 / np.where(seen, singular, 1.0) ** 2, 0.0)
    unscaled = (vt.T * inverse) @ vt
    with np.errstate(over="ignore"):  # (s² (JᵀJ)⁻¹ beyond the doubles: the noise's square over a small Jacobian)
        covariance = unscaled * variance_scale
    unseen = np.any(np.abs(vt[~seen]) > math.sqrt(RCOND), axis=0) if np.any(~seen) else np.zeros(theta.size, bool)
    # fewer residuals than parameters: the directions beyond vt's rows are not seen either (each parameter's share of
    # them, 1 - its squared norm over vt's rows; rounding, ~1e-16, where vt is square); round eighteen: two samples
    # and four free values gave the fourth a standard error of 0
    unseen |= 1.0 - np.sum(vt**2, axis=0) > RCOND
    standard_error = np.sqrt(np.maximum(np.diag(covariance), 0.0))
    overflowed = not np.all(np.isfinite(covariance))
    if overflowed:  # each a square root, s (JᵀJ)⁻¹ᐟ², finite where s² (JᵀJ)⁻¹ is not (round twenty: a rate fit's
        # noise of 1e154 N, inside its range, ran the covariance out of the doubles with a RuntimeWarning)
        root = np.sqrt(np.maximum(np.diag(unscaled), 0.0))
        standard_error = math.sqrt(variance_scale) * root
    standard_error[unseen] = math.inf
    verdicts = []
    for j in range(theta.size):
        if unseen[j]:
            verdicts.append(Identifiability.NOT_IDENTIFIABLE)
        elif theta[j] - lower[j] <= BOUND_SHARE * max(1.0, abs(theta[j])) or \
                upper[j] - theta[j] <= BOUND_SHARE * max(1.0, abs(theta[j])):
            verdicts.append(Identifiability.AT_BOUND)
        elif standard_error[j] > POOR_STANDARD_ERROR:
            verdicts.append(Identifiability.POORLY_DETERMINED)
        else:
            verdicts.append(Identifiability.DETERMINED)
    with np.errstate(invalid="ignore", divide="ignore"):
        correlation = unscaled / np.outer(root, root) if overflowed else \
            covariance / np.outer(standard_error, standard_error)
    correlation[unseen, :] = math.nan
    correlation[:, unseen] = math.nan
    np.fill_diagonal(correlation, 1.0)
    return covariance, standard_error, condition, verdicts, correlation


#: Parameters the normal problem does not depend on: uncoupled springs (MDR) make F_N, A and a independent of
#: friction and of the tangential stiffness.
TANGENTIAL_ONLY = ("tau0",)


def identifiability_notes(names: Sequence[str], quantities: Sequence[str], verdicts: Sequence[Identifiability],
                          correlation: np.ndarray) -> list[str]:
    """What the identifiability analysis says beside the verdicts.

    Parameters
    ----------
    names : sequence of str
        The free parameters.
    quantities : sequence of str
        The quantities fitted.
    verdicts : sequence of Identifiability
        One per free parameter.
    correlation : numpy.ndarray
        Of the scaled estimates.

    Returns
    -------
    list of str
        A parameter only ``F_x`` sees without ``F_x`` data, how ``E`` and ``ν`` enter, pairs correlated beyond
        :data:`STRONG_CORRELATION`, parameters on a bound.
    """
    notes = []
    if "tangential_force" not in quantities:
        for name in names:
            if name in TANGENTIAL_ONLY:
                notes.append(f"{name} acts only on F_x (the MDR's springs are uncoupled: F_N, A and a do not depend on "
                             "friction); without F_x data it cannot be determined")
    if "E" in names or "nu" in names:
        notes.append("E and ν enter the model only through E* = E/(1−ν²) (normal) and G* = 2E/((1+ν)(2−ν)) "
                     "(tangential); E* and G* are reported beside them")
        if "nu" in names and "tangential_force" not in quantities:
            notes.append("ν changes G*/E* only, and G* acts only on F_x: without F_x data ν cannot be determined")
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            if abs(correlation[i, j]) > STRONG_CORRELATION:
                # (the value is the variable correlation: words with its digits would differ between CPUs)
                notes.append(f"{names[i]} and {names[j]} are correlated beyond ±{STRONG_CORRELATION:g}: the data fix "
                             "a combination of them rather than each")
    for name, verdict in zip(names, verdicts):
        if verdict is Identifiability.AT_BOUND:
            notes.append(f"{name} sits on a bound: its interval is not a linearisation's, widen the bound or fix it")
    return notes


def fit_warnings(measurement: Measurement, model: ModelCurves, rms: Mapping[str, float], first_contact: float,
                 time_offset: float, duration: float, offset_free: bool) -> list[str]:
    """What says the fit does not describe the data, whatever the intervals say: residuals far above the noise,
    magnitudes or a time span that point to a wrong unit, a record that starts after the first contact (in
    contact: the offset a fit of Δγ1 would hide), contact lost at another time than in the fit."""
    warnings = []
    for name, value in rms.items():
        if value > MISFIT_RMS:
            warnings.append(f"the residuals of {name} are {value:.3g} times its noise: the model does not describe "
                            "the data (check the units, time_origin, the path and the free parameters)")
    for name, values in measurement.values.items():
        measured, fitted = np.nanmax(np.abs(values)), np.nanmax(np.abs(model.values[name]), initial=0.0)
        if fitted > 0 and not 1.0 / MAGNITUDE_FACTOR <= measured / fitted <= MAGNITUDE_FACTOR:
            warnings.append(f"the measured {name} reaches {measured:.3g} {QUANTITY_UNITS[name]}, the fit "
                            f"{fitted:.3g}: check its unit (units=)")
    times = measurement.path_time - time_offset
    span = float(times[-1] - times[0])
    if not duration / MAGNITUDE_FACTOR <= span <= MAGNITUDE_FACTOR * duration:
        warnings.append(f"the measured time spans {span:.3g} s and the path lasts {duration:.3g} s: check the unit of "
                        "time (units=)")
    tolerance = max(CONTACT_TIME_SHARE * duration, 2.0 * float(np.median(np.diff(times))))
    if offset_free:
        return warnings
    if model.in_contact[0] and times[0] - first_contact > tolerance:
        warnings.append(f"the record starts {times[0] - first_contact:.4g} s after the path's first contact, in "
                        f"contact: if it starts at the first contact, give time_origin="
                        f"{measurement.candidate.time[0]:.6g}, or free time_offset")
    # contact lost (a jump): where the data and the fit last exceed the same multiple of the noise (the data's own
    # scatter where a given σ is smaller: a σ that understates it would take noise after the pull-off for contact);
    # where the fit fades out instead (a cone's small jump-off radius; curves that end slowly against a large noise),
    # the noise moves that crossing anywhere the fit spends between FADE_MULTIPLE thresholds and 1/FADE_MULTIPLE of one
    measured, fitted = np.zeros(times.size, bool), np.zeros(times.size, bool)
    strong, weak = np.zeros(times.size, bool), np.zeros(times.size, bool)
    for name, values in measurement.values.items():
        threshold = CONTACT_NOISE_MULTIPLE * max(measurement.noise[name], estimate_noise(values))
        magnitude = np.nan_to_num(np.abs(model.values[name]))
        measured |= np.nan_to_num(np.abs(values)) > threshold
        fitted |= magnitude > threshold
        strong |= magnitude > FADE_MULTIPLE * threshold
        weak |= magnitude > threshold / FADE_MULTIPLE
    if measured.any() and fitted.any() and not measured[-1] and not fitted[-1]:
        lost, fitted_lost = times[np.flatnonzero(measured)[-1]], times[np.flatnonzero(fitted)[-1]]
        # (a fit that never reaches FADE_MULTIPLE thresholds fades over all its contact: round thirty, 10 % noise of
        # the right model at the right clock warned in 8 of 32 seeds with a fade of 0)
        faded_from = times[np.flatnonzero(strong)[-1]] if strong.any() else times[np.flatnonzero(fitted)[0]]
        fade = max(fitted_lost - faded_from, times[np.flatnonzero(weak)[-1]] - fitted_lost)
        if abs(lost - fitted_lost) > tolerance + fade:
            warnings.append(f"the data lose contact at {lost:.6g} s, the fit at {fitted_lost:.6g} s (the path's "
                            "clock): free time_offset or give time_origin")
    return warnings


#: The largest argument of exp that a double holds (log of the largest double).
LOG_LARGEST = math.log(sys.float_info.max)


def exp_or_inf(exponent: float) -> float:
    """``exp(exponent)``, ``inf`` where it overflows (the upper end of a log-scaled parameter's interval that the
    data do not see: ``math.exp`` raised ``OverflowError``)."""
    return math.exp(exponent) if exponent < LOG_LARGEST else math.inf


def scaled_or_inf(value: float, factor: float) -> float:
    """``value * factor`` of two non-negative numbers, ``inf`` where it overflows."""
    with np.errstate(over="ignore"):
        product = float(np.float64(value) * np.float64(factor))
    return product if math.isfinite(product) else math.inf


def natural_intervals(free: FreeParameters, theta: np.ndarray, standard_error: np.ndarray,
                      dof: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Estimates, standard errors and 95 % intervals in natural units (delta method for the log-scaled).

    Parameters
    ----------
    free : FreeParameters
        The free parameters and their scaling.
    theta, standard_error : numpy.ndarray
        The scaled optimum and its standard errors.
    dof : int
        The degrees of freedom of the Student t quantile (at least 1 is used).

    Returns
    -------
    value, standard_error, lower, upper : numpy.ndarray
        In natural units; a log-scaled parameter's interval is asymmetric, ``(0, inf)`` where the data do not see it;
        every interval within the parameter's bounds (``ν`` at most 0.5, ``bounds=``).
    """
    from scipy import stats  # (only here: scipy.stats costs the verbs that load the fit's schema ~0.2 s)

    quantile = float(stats.t.ppf(0.5 + CONFIDENCE / 2.0, max(dof, 1)))
    value = free.to_natural(theta)
    natural_error, lower, upper = [], [], []
    for j, name in enumerate(free.names):
        half = quantile * standard_error[j]
        if name in LOG_SCALED:
            # (a parameter the data do not see has a half-width beyond what exp takes: its interval is (0, inf))
            natural_error.append(scaled_or_inf(value[j], standard_error[j]))
            lower.append(value[j] * math.exp(-half) if half < LOG_LARGEST else 0.0)
            upper.append(scaled_or_inf(value[j], math.exp(half)) if half < LOG_LARGEST else math.inf)
        else:
            scale = free.scale(name)
            natural_error.append(scale * standard_error[j])
            lower.append(value[j] - scale * half)
            upper.append(value[j] + scale * half)
    # (within the bounds: the fit holds the parameter there, so no value beyond them is a plausible one; round thirty:
    # ν fitted at its bound 0.5 was reported within [0.4958, 0.5042])
    lower, upper = np.maximum(np.array(lower), free.lower), np.minimum(np.array(upper), free.upper)
    return value, np.array(natural_error), lower, upper


def effective_moduli(free: FreeParameters, theta: np.ndarray, covariance: np.ndarray,
                     params: Parameters) -> dict[str, tuple[float, float]]:
    """E* and G* with their standard errors (delta method over the scaled parameters; the step backward at an
    upper bound, as in the Jacobian: ν = 0.5 is the paper's)."""
    _, upper = free.scaled_bounds()
    out = {}
    for key, read in (("E_star", lambda p: p.E_star), ("G_star", lambda p: p.G_star)):
        gradient = np.zeros(theta.size)
        for j, name in enumerate(free.names):
            if name in ("E", "nu"):
                step = FD_STEP if theta[j] + FD_STEP <= upper[j] else -FD_STEP
                moved = theta.copy()
                moved[j] += step
                gradient[j] = (read(free.model(moved)[0]) - read(params)) / step
        variance = float(gradient @ covariance @ gradient)
        out[key] = (read(params), math.sqrt(max(variance, 0.0)))
    return out
