"""How a fit's results are determined, for comparing a fit computed elsewhere (:mod:`mdr_events.io.agreement`).

``least_squares`` stops on the first of three criteria, each with the tolerance ``tol`` (the dataset's attribute
``optimizer_tolerance``), and which one fires is itself a matter of rounding (this machine stops the fit of
results/ on ``xtol``, the one that wrote it on ``ftol``). So the estimate is known to the largest of their bounds. With
the cost ``F = χ²/2`` and the weighted Jacobian ``J`` (scaled parameters ``θ``): ``ftol`` leaves ``F`` within ``tol F``
of its minimum, so ``δθᵀ JᵀJ δθ <= 2 tol F``: ``sqrt(tol χ²/s)`` standard errors (``s`` the variance scale: 1 with the
noise given, the reduced χ² where it is estimated); ``xtol`` a step below ``tol (tol + |θ|)``, about 1e-11 in ``θ``,
and ``gtol`` a gradient below ``tol``, ``tol σ²/s`` in ``θ``: both far below the first, which is the bound. A fit that
did not converge (``optimizer_converged = 0``) has no such bound: it cannot be compared. The Jacobian is a forward difference of curves known to the
continuum's ``rtol`` with the step ``h`` (``jacobian_step``): each column to ``2 rtol/h`` of its size, which moves the
stationary point of Gauss–Newton by that share of a standard error (its error is not correlated with the noise) and
the singular values by that share of the largest (Weyl), so that the standard errors, the correlations and the
condition number ``κ`` are known to ``2 rtol/h (1 + κ)``. So, with ``c = sqrt(ftol χ²/s) + 2 rtol/h``:

=========================  =========================================================================
quantity                   tolerance
=========================  =========================================================================
estimates, E*, G*          ``c`` standard errors (:class:`FitEstimate`)
interval ends              ``c σ`` plus the half-width's share ``2 rtol/h (1 + κ)`` (:class:`FitInterval`)
standard errors, κ         their share ``2 rtol/h (1 + κ)`` (:class:`FitSpread`)
correlations               twice that share, absolute (:class:`FitSpread`)
fitted curves, residuals   the continuum's ``rtol`` of the largest magnitude, plus ``c √k`` noise
                           standard deviations (``k`` free parameters; :class:`FitCurve`)
reduced χ², RMS residual   second order in ``δθ`` at the minimum (``c² k``), first order in the curves'
                           accuracy ``m`` (in noise units) (:class:`FitCost`)
noise (estimated)          the measured samples' tolerance times the estimator's sensitivity (:class:`FitNoise`)
=========================  =========================================================================

The fitted parameters in the attributes (``param_<name>``, ``friction_mu``) are compared as their estimates
(:class:`FittedParameter`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import xarray as xr

from mdr_events.io.agreement import (Accuracy, Integrated, RoundOff, accuracy_of, attribute_of, register_accuracy,
                                     values_of)

__all__ = ["FitEstimate", "FitInterval", "FitSpread", "FitCurve", "FitCost", "FitNoise", "FittedParameter",
           "estimate_share", "jacobian_share",
           "spread_share", "register_fit_accuracy"]


def _attribute(dataset: xr.Dataset, name: str) -> float:
    return attribute_of(dataset, name, "the fit's accuracy")


def jacobian_share(dataset: xr.Dataset) -> float:
    """``2 rtol / h``: the share of its size to which each column of the forward-difference Jacobian is known."""
    return 2.0 * _attribute(dataset, "continuum_rtol") / _attribute(dataset, "jacobian_step")


def _quantities(dataset: xr.Dataset) -> list[str]:
    return [str(q) for q in dataset["quantity"].values]


def estimate_share(dataset: xr.Dataset) -> float:
    """``c = sqrt(ftol χ²/s) + 2 rtol/h``: the share of a standard error to which the estimates are determined
    (``inf`` if the optimizer did not converge)."""
    if not int(dataset.attrs.get("optimizer_converged", 0)):
        return math.inf
    free = dataset.sizes["parameter"]
    compared = sum(int(np.count_nonzero(np.isfinite(dataset[f"residual_{q}"].values))) for q in _quantities(dataset))
    dof = max(compared - free, 1)
    reduced = float(dataset["reduced_chi_square"])
    given = bool(np.all(dataset["noise_given"].values == 1))
    # χ²/s: χ² itself with the noise given; the degrees of freedom where the variance scale is the reduced χ²
    return math.sqrt(_attribute(dataset, "optimizer_tolerance") * (reduced * dof if given else dof)) + \
        jacobian_share(dataset)


def spread_share(dataset: xr.Dataset) -> float:
    """``2 rtol/h (1 + κ)``: the relative accuracy of the standard errors and of the condition number ``κ``."""
    return jacobian_share(dataset) * (1.0 + float(dataset["condition_number"]))


@dataclass(frozen=True)
class FitEstimate(Accuracy):
    """An estimate (or a function of the estimates, e.g. E*): ``c`` of its ``standard_error`` variable."""

    standard_error: str = "standard_error"

    def tolerance(self, dataset, name):
        return estimate_share(dataset) * np.abs(values_of(dataset, self.standard_error)) + \
            RoundOff().tolerance(dataset, name)

    def describe(self):
        return f"an optimizer's estimate: c = sqrt(ftol χ²/s) + 2 rtol/h times {self.standard_error}"


@dataclass(frozen=True)
class FitInterval(Accuracy):
    """An end of an interval, ``estimate ± half``: the estimate's tolerance plus the half-width's share."""

    def tolerance(self, dataset, name):
        half = np.abs(values_of(dataset, name) - values_of(dataset, "estimate"))
        with np.errstate(invalid="ignore"):
            return FitEstimate().tolerance(dataset, "estimate") + spread_share(dataset) * np.nan_to_num(half)

    def describe(self):
        return "an interval's end: the estimate's tolerance and 2 rtol/h (1 + κ) of its half-width"


@dataclass(frozen=True)
class FitSpread(Accuracy):
    """What the Jacobian alone gives (standard errors, the condition number): their share ``2 rtol/h (1 + κ)``;
    with ``relative=False`` (correlations, at most 1) twice that share, absolute."""

    relative: bool = True

    def tolerance(self, dataset, name):
        share = spread_share(dataset)
        return share * np.abs(values_of(dataset, name)) if self.relative else np.asarray(2.0 * share)

    def describe(self):
        return "from the forward-difference Jacobian: 2 rtol/h (1 + κ)" + ("" if self.relative else ", absolute")


def _curve_share(dataset: xr.Dataset, quantity: str) -> float:
    """The continuum's accuracy of a fitted curve in noise standard deviations, ``m = rtol max|F| / σ``."""
    noise = float(dataset["noise"].sel(quantity=quantity))
    largest = float(np.nanmax(np.abs(values_of(dataset, f"fitted_{quantity}")), initial=0.0))
    return _attribute(dataset, "continuum_rtol") * largest / noise if noise > 0 else math.inf


@dataclass(frozen=True)
class FitCurve(Accuracy):
    """A fitted curve (or the residual measured − fitted) of ``quantity``: the continuum's ``rtol`` of its largest
    magnitude, plus ``c √k`` of the noise's standard deviation (how far the estimates' tolerance moves it)."""

    quantity: str

    def tolerance(self, dataset, name):
        noise = float(dataset["noise"].sel(quantity=self.quantity))
        moved = estimate_share(dataset) * math.sqrt(dataset.sizes["parameter"]) * noise
        return np.asarray(_curve_share(dataset, self.quantity) * noise + moved)

    def describe(self):
        return f"the fitted {self.quantity}: the continuum's rtol and c √k noise standard deviations"


@dataclass(frozen=True)
class FitCost(Accuracy):
    """The reduced χ² (``per_quantity=False``) or each quantity's RMS residual over the noise: flat at the minimum,
    so second order in the estimates' tolerance, ``c² k``, first order in the curves' accuracy ``m``, and the
    optimizer's ``ftol`` of the cost."""

    per_quantity: bool = False

    def tolerance(self, dataset, name):
        c, free = estimate_share(dataset), dataset.sizes["parameter"]
        ftol = _attribute(dataset, "optimizer_tolerance")
        shares = np.array([_curve_share(dataset, q) for q in _quantities(dataset)])
        if not self.per_quantity:
            reduced = float(dataset["reduced_chi_square"])
            return np.asarray(reduced * ftol + 2.0 * float(np.max(shares)) * math.sqrt(reduced) + c * c * free)
        rms = np.abs(values_of(dataset, name))
        with np.errstate(divide="ignore"):
            return shares + c * c * free / (2.0 * rms) + rms * ftol / 2.0

    def describe(self):
        return "a cost at the minimum: c² k, the curves' accuracy and ftol"


#: How much the noise estimate (1.4826 MAD of the second differences / √6) moves per unit of the samples' error:
#: a second difference moves by up to 4 of them, its median and MAD by up to twice that.
NOISE_SENSITIVITY = 1.4826 * 2.0 * 4.0 / math.sqrt(6.0)


@dataclass(frozen=True)
class FitNoise(Accuracy):
    """The noise's standard deviation of each quantity: given (round-off), or estimated from the measured samples'
    second differences, which moves by :data:`NOISE_SENSITIVITY` times the samples' tolerance."""

    def tolerance(self, dataset, name):
        out = []
        for q, given in zip(_quantities(dataset), dataset["noise_given"].values):
            measured = f"measured_{q}"
            samples = np.max(np.broadcast_to(accuracy_of(dataset, measured).tolerance(dataset, measured),
                                             dataset[measured].shape), initial=0.0)
            out.append(0.0 if given else NOISE_SENSITIVITY * float(samples))
        return np.asarray(out) + RoundOff().tolerance(dataset, name)

    def describe(self):
        return "the noise estimated from the samples' second differences"


@dataclass(frozen=True)
class FittedParameter(Accuracy):
    """An attribute holding a parameter of the fitted model (``param_<name>``, ``friction_mu``): the tolerance of
    its estimate where ``parameter`` is free (``E_star``, ``G_star``: of their variables where they were fitted);
    otherwise given, so round-off."""

    parameter: str

    def tolerance(self, dataset, name):
        free = [str(p) for p in dataset["parameter"].values]
        if self.parameter in free:
            row = free.index(self.parameter)
            return np.asarray(FitEstimate().tolerance(dataset, "estimate")[row])
        if self.parameter in dataset.variables and {"E", "nu"} & set(free):
            return FitEstimate(f"{self.parameter}_standard_error").tolerance(dataset, self.parameter)
        return RoundOff().tolerance(dataset, name)

    def describe(self):
        return f"the fitted {self.parameter}"


def register_fit_accuracy(content: str, quantities: tuple[str, ...], parameters: tuple[str, ...]) -> None:
    """Declare how each variable and fitted attribute of a fit is computed (:func:`mdr_events.io.agreement.register_accuracy`).

    Parameters
    ----------
    content : str
        A fit's ``content`` attribute.
    quantities : tuple of str
        The curves a fit may hold (``measured_<q>``, ``fitted_<q>``, ``residual_<q>``).
    parameters : tuple of str
        The model's parameters (the ``param_<name>`` attributes).
    """
    curves = {f"{kind}_{q}": FitCurve(q) for q in quantities for kind in ("fitted", "residual")}
    # measured curves as the continuum's (the synthetic measurements of results/ are its curves plus seeded noise;
    # a measurement read from a file is the same everywhere, and changes of it beyond that are still seen)
    variables = {**curves, **{f"measured_{q}": Integrated("continuum_rtol") for q in quantities},
                 "estimate": FitEstimate(), "lower_95": FitInterval(), "upper_95": FitInterval(),
                 "start": RoundOff(), "time": RoundOff(), "noise": FitNoise(),
                 "standard_error": FitSpread(), "condition_number": FitSpread(), "correlation": FitSpread(relative=False),
                 "reduced_chi_square": FitCost(), "rms_normalised_residual": FitCost(per_quantity=True),
                 **{key: FitEstimate(f"{key}_standard_error") for key in ("E_star", "G_star")},
                 **{f"{key}_standard_error": FitSpread() for key in ("E_star", "G_star")}}
    attributes = {**{f"param_{name}": FittedParameter(name) for name in (*parameters, "E_star", "G_star")},
                  "friction_mu": FittedParameter("mu")}
    register_accuracy(content, variables, attributes=attributes)
