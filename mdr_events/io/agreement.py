"""When a result computed elsewhere agrees with a committed one: each quantity within the accuracy of how it is
computed.

Another CPU (another SIMD path of NumPy's functions, another OpenBLAS kernel) or other library versions round
differently, and what that moves depends on how a value is computed: a closed form by a few ulp, ``F_x`` by the
integrator's local error control, the time of a flat maximum by the square root of its value's accuracy, an
optimizer's estimate by its stopping tolerance. So each kind of result declares, beside the definition of its
variables, how each one is determined (:func:`register_accuracy`), and :func:`result_differences` compares each
within that. The kinds of this module:

=====================  ===============================================  ==================================================
kind                   computed as                                      tolerance (absolute, per element)
=====================  ===============================================  ==================================================
:class:`RoundOff`      closed forms, sums over springs                  :data:`ROUND_OFF_ULPS` ε of the largest magnitude
:class:`RootFound`     closed forms of a root found to a relative       that accuracy (the dataset's attribute), plus
                       accuracy (the contact radius)                    round-off, of the largest magnitude
:class:`Integrated`    ``solve_ivp`` between events (``F_x``), and      the integrator's ``rtol`` (the dataset's
                       what is read off it (event times, the work)      attribute) of the largest magnitude
:class:`Quotient`      ``q = n / m`` (mean pressure and shear stress)   ``tol(n)/|m| + |q| tol(m)/|m|``
:class:`ExtremumTime`  the time of an extremum of a sampled quantity    ``sqrt(2 tol(F) / |F''|)`` from the curvature of
                                                                        the samples there, plus the search's tolerance
=====================  ===============================================  ==================================================

A quantity sampled along ``time`` is a function of the position on the path, which carries the round-off of the
path's length: the first three kinds add ``ROUND_OFF max|t| |dQ/dt|`` to it (the radius is steep near the jump-off).
The fit registers its own kinds (:mod:`mdr_events.analysis.fit_accuracy`: an optimizer's estimate within its
stopping tolerance and the Jacobian's accuracy). Integers, strings, dimensions and the names of variables are
compared exactly, float attributes within :class:`RoundOff` of their value unless their kind registers another
accuracy for them. A float variable of a registered kind of result without a declared accuracy is an error, not
a blanket tolerance. Counts that depend on an optimizer's or integrator's path (solves, evaluations, steps) are
not results: no dataset that is compared holds them.

Rounded text (``results/README.md``) is compared by :func:`~mdr_events.io.rounded_text.rounded_text_differences`.
"""

from __future__ import annotations

import abc
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np
import xarray as xr

from mdr_events.io.registrars import load_registrars
from mdr_events.io.rounded_text import Unit, rounded_text_differences  # noqa: F401 - the agreement of rounded text

__all__ = ["Accuracy", "RoundOff", "RootFound", "Integrated", "Quotient", "ExtremumTime", "ROUND_OFF_ULPS",
           "ROUND_OFF", "register_accuracy", "accuracy_of", "attribute_accuracy", "tolerance_of",
           "result_differences", "assert_results_agree", "rounded_text_differences", "Unit", "values_of",
           "attribute_of", "force_sensitivity"]

#: Units of round-off of a closed form or a sum, of the largest magnitude of its array. NumPy's SIMD paths of
#: the transcendental functions are accurate to 4 ulp on every CPU (its documented bound); a closed form chains up
#: to about ten of them (4 ulp each, 40) and the pairwise sums over at most 1e5 springs add log2(1e5) ≈ 17: 64.
ROUND_OFF_ULPS = 64
#: :data:`ROUND_OFF_ULPS` as a relative tolerance.
ROUND_OFF = ROUND_OFF_ULPS * float(np.finfo(float).eps)


def values_of(dataset: xr.Dataset, name: str) -> np.ndarray:
    """A variable's values as floats, or a float attribute as a 0-d array."""
    if name in dataset.variables:
        return np.asarray(dataset[name].values, dtype=float)
    return np.asarray(float(dataset.attrs[name]))


def _largest(values: np.ndarray) -> float:
    finite = values[np.isfinite(values)]
    return float(np.max(np.abs(finite))) if finite.size else 0.0


def _time_conditioning(dataset: xr.Dataset, name: str) -> np.ndarray | float:
    """``ROUND_OFF max|t| |dQ/dt|`` for a quantity ``Q`` sampled along ``time`` (its last dimension), else 0.

    Along a path every quantity is a function of the position on it, which carries the round-off of the path's
    length (``ε v t``): ``Q`` then carries ``|dQ/dt| ε t``, large where ``Q`` is steep (the radius near the
    jump-off, where ``da/dd`` diverges; the depth of a long path that returns to a small one). ``|dQ/dt|`` is the
    larger of the secants to the neighbouring samples."""
    if name not in dataset.variables or dataset[name].dims[-1:] != ("time",) or dataset.sizes["time"] < 2:
        return 0.0
    times = np.asarray(dataset["time"].values, dtype=float)
    values = np.asarray(dataset[name].values, dtype=float)
    slopes = np.nan_to_num(np.abs(np.diff(values, axis=-1) / np.diff(times)), nan=0.0, posinf=0.0)
    pad = np.zeros(values.shape[:-1] + (1,))
    steepest = np.maximum(np.concatenate([pad, slopes], axis=-1), np.concatenate([slopes, pad], axis=-1))
    return ROUND_OFF * float(np.max(np.abs(times))) * steepest


def _scale(dataset: xr.Dataset, name: str, scale_of: str | None) -> float:
    """The largest finite magnitude of ``scale_of`` (default: of ``name`` itself): what a relative accuracy is of.
    An extremum is as accurate as the quantity it is the extremum of, so its scale is that quantity's."""
    return _largest(values_of(dataset, scale_of or name))


class Accuracy(abc.ABC):
    """How a quantity is determined: its absolute tolerance against another environment's rounding."""

    @abc.abstractmethod
    def tolerance(self, dataset: xr.Dataset, name: str) -> np.ndarray:
        """The absolute tolerance of ``dataset``'s variable (or float attribute) ``name``, broadcastable to
        its values; computed from ``dataset`` (the committed result when two are compared)."""

    @abc.abstractmethod
    def describe(self) -> str:
        """A few words for a message: how the quantity is computed."""


@dataclass(frozen=True)
class RoundOff(Accuracy):
    """A closed form or a sum: :data:`ROUND_OFF` of the array's largest finite magnitude (or of ``scale_of``'s)."""

    scale_of: str | None = None

    def tolerance(self, dataset, name):
        return ROUND_OFF * _scale(dataset, name, self.scale_of) + _time_conditioning(dataset, name)

    def describe(self):
        return f"round-off, {ROUND_OFF_ULPS} ulp of the largest magnitude"


def attribute_of(dataset: xr.Dataset, attribute: str, name: str) -> float:
    """The float attribute ``attribute`` a tolerance of ``name`` is computed from; ``ValueError`` naming both if the
    dataset lacks it."""
    if attribute not in dataset.attrs:
        raise ValueError(f"{name}: its accuracy is the dataset's attribute {attribute!r}, which it lacks")
    return float(dataset.attrs[attribute])


def force_sensitivity(dataset: xr.Dataset) -> float:
    """``d ln F_N / d ln a`` bounds of the indenter a dataset names: ``n + 1`` for a power law ``c rⁿ`` (its attribute
    ``profile_n``; 3 for the paraboloid, which has none), 1 for the flat punch (``F_N = 2 E* a d``, its attribute
    ``profile_radius``), and for a table (``profile_table_r``, ``profile_table_f``) one more than its largest local
    exponent ``r f' / f`` between its points."""
    if "profile_n" in dataset.attrs:
        return float(dataset.attrs["profile_n"]) + 1.0
    if "profile_radius" in dataset.attrs:
        return 1.0
    if "profile_table_r" in dataset.attrs:
        r, f = (np.array([float(v) for v in str(dataset.attrs[key]).split(",")])
                for key in ("profile_table_r", "profile_table_f"))
        middle, mean = 0.5 * (r[1:] + r[:-1]), 0.5 * (f[1:] + f[:-1])
        with np.errstate(divide="ignore", invalid="ignore"):
            exponents = np.where(mean > 0, middle * np.diff(f) / np.diff(r) / mean, 0.0)
        return float(np.max(exponents[np.isfinite(exponents)], initial=1.0)) + 1.0
    return 3.0


@dataclass(frozen=True)
class _RelativeAccuracy(Accuracy):
    """A relative accuracy held in the dataset's ``attribute``, plus round-off, of the array's largest magnitude (or
    of ``scale_of``'s), and the path's round-off along ``time``."""

    attribute: str
    scale_of: str | None = None

    def share(self, dataset: xr.Dataset, name: str) -> float:
        """The relative accuracy: the attribute's, plus round-off."""
        return attribute_of(dataset, self.attribute, name) + ROUND_OFF

    def tolerance(self, dataset, name):
        return self.share(dataset, name) * _scale(dataset, name, self.scale_of) + _time_conditioning(dataset, name)


@dataclass(frozen=True)
class RootFound(_RelativeAccuracy):
    """A closed form of a root found to the relative accuracy in the dataset's ``attribute`` (e.g. the contact
    radius to ``radius_rtol``): that accuracy times the quantity's ``sensitivity`` to the root (``d ln Q / d ln a``:
    1 for the radius, 2 for the area; :func:`force_sensitivity` for the normal force), plus round-off, of the
    array's largest magnitude (or of ``scale_of``'s)."""

    attribute: str = "radius_rtol"
    sensitivity: float | Callable[[xr.Dataset], float] = 1.0

    def share(self, dataset, name):
        sensitivity = self.sensitivity(dataset) if callable(self.sensitivity) else self.sensitivity
        return sensitivity * attribute_of(dataset, self.attribute, name) + ROUND_OFF

    def describe(self):
        return f"a root found to the relative accuracy {self.attribute}, of the largest magnitude"


@dataclass(frozen=True)
class Integrated(_RelativeAccuracy):
    """Integrated by ``solve_ivp`` with the relative tolerance in the dataset's ``attribute``, or read off such an
    integral (an event's time: a crossing of a quantity known to ``rtol`` of its size, which changes by its size
    over the run): a rounding that tips one step from accepted to rejected moves it by up to that local error
    control, ``rtol`` of the array's largest magnitude (or of ``scale_of``'s), plus round-off."""

    attribute: str = "rtol"

    def describe(self):
        return f"integrated to the relative tolerance {self.attribute}, of the largest magnitude"


@dataclass(frozen=True)
class Quotient(Accuracy):
    """``q = numerator / denominator``, element by element: ``tol(n)/|m| + |q| tol(m)/|m|``."""

    numerator: str
    denominator: str

    def tolerance(self, dataset, name):
        quotient, denominator = values_of(dataset, name), np.abs(values_of(dataset, self.denominator))
        # (the numerator's and denominator's tolerances carry the conditioning along the path)
        with np.errstate(divide="ignore", invalid="ignore"):
            return (tolerance_of(dataset, self.numerator) + np.abs(quotient)
                    * tolerance_of(dataset, self.denominator)) / denominator

    def describe(self):
        return f"the quotient {self.numerator} / {self.denominator}"


def _time_of_extremum_tolerance(t: np.ndarray, f: np.ndarray, at: int, value_tolerance: float) -> float:
    """How far the time of an extremum moves when its value moves by ``value_tolerance``, from the samples ``f`` at
    times ``t`` around the sample ``at`` nearest to it (``nan`` where the run has ended); 0 where they cannot tell.

    At the first or last sample of the run (an extremum at its start or end) or beside a plateau the time moves at
    first order, ``tol / |F'|`` with the slope on the side that has one; inside the run the extremum is flat and its
    time moves by ``sqrt(2 tol / |F''|)``, with ``F''`` the curvature of the parabola through three samples (large at
    a kink, where the time is sharp)."""
    finite = np.isfinite(f)
    lo = at - 1 if at > 0 and finite[at - 1] else at  # the neighbours in the run, on either side
    hi = at + 1 if at < f.size - 1 and finite[at + 1] else at
    slopes = [abs((f[k + 1] - f[k]) / (t[k + 1] - t[k])) for k in range(lo, hi)]
    if hi - lo == 2:  # inside the run: three samples
        c = t[lo:hi + 1], f[lo:hi + 1]
        curvature = 2.0 * (c[1][0] / ((c[0][0] - c[0][1]) * (c[0][0] - c[0][2]))
                           + c[1][1] / ((c[0][1] - c[0][0]) * (c[0][1] - c[0][2]))
                           + c[1][2] / ((c[0][2] - c[0][0]) * (c[0][2] - c[0][1])))
        if curvature != 0.0 and all(slope > 0.0 for slope in slopes):
            return math.sqrt(2.0 * value_tolerance / abs(curvature))
    moving = [slope for slope in slopes if slope > 0.0]
    return value_tolerance / max(moving) if moving else 0.0


@dataclass(frozen=True)
class ExtremumTime(Accuracy):
    """The time of an extremum ``value`` of the quantity sampled in ``samples`` (along the last dimension, the
    coordinate ``time``): how far it moves when its value moves by its tolerance (:func:`_time_of_extremum_tolerance`:
    ``sqrt(2 tol(F) / |F''|)`` at a flat extremum inside the run, ``tol(F) / |F'|`` at the run's start or end and
    beside a plateau), plus the search's own tolerance, ``search_share`` of the run's duration."""

    value: str
    samples: str
    search_share: float

    def tolerance(self, dataset, name):
        times = np.asarray(dataset["time"].values, dtype=float)
        found = values_of(dataset, name)
        samples = np.asarray(dataset[self.samples].values, dtype=float).reshape(found.size, times.size)
        value_tolerance = np.broadcast_to(tolerance_of(dataset, self.value), found.shape).ravel()
        search = self.search_share * float(times[-1] - times[0])
        out = np.full(found.size, search)
        for case, time in enumerate(found.ravel()):
            if math.isfinite(time) and times.size >= 2:
                at = int(np.argmin(np.abs(times - time)))
                out[case] += _time_of_extremum_tolerance(times, samples[case], at, float(value_tolerance[case]))
        return out.reshape(found.shape)

    def describe(self):
        return f"the time of {self.value}: sqrt(2 tol / |F''|) or tol / |F'| from the samples of {self.samples} there"


#: What each kind of result declares: ``content`` -> condition -> ({variable: Accuracy}, {attribute: Accuracy}).
#: The condition ``None`` holds always, ``(attribute, value)`` when the result's attribute has that value.
_ACCURACIES: dict[str, dict[tuple[str, Any] | None, tuple[dict[str, Accuracy], dict[str, Accuracy]]]] = {}


def register_accuracy(content: str, variables: Mapping[str, Accuracy], when: tuple[str, Any] | None = None,
                      attributes: Mapping[str, Accuracy] | None = None) -> None:
    """Declare how each variable (and float attribute) of results of kind ``content`` is computed.

    Called beside the definition of the variables, when their module is imported. Registering the same ``content``
    and ``when`` again replaces them.

    Parameters
    ----------
    content : str
        The results' ``content`` attribute.
    variables : mapping of str to Accuracy
        Each float variable (coordinates included) and how it is computed.
    when : (str, object), optional
        As for :func:`mdr_events.io.datasets.register_schema`: only for results whose attribute has that value
        (its entries replace the unconditional ones).
    attributes : mapping of str to Accuracy, optional
        Float attributes computed otherwise than to round-off (e.g. a fit's ``param_<name>``).
    """
    _ACCURACIES.setdefault(content, {})[when] = (dict(variables), dict(attributes or {}))


def _declared(dataset: xr.Dataset, part: int) -> dict[str, Accuracy]:
    load_registrars("schemas")
    entries = _ACCURACIES.get(dataset.attrs.get("content"), {})
    declared = dict(entries.get(None, ({}, {}))[part])
    for condition, pair in entries.items():
        if condition is not None and dataset.attrs.get(condition[0]) == condition[1]:
            declared.update(pair[part])
    return declared


def accuracy_of(dataset: xr.Dataset, name: str) -> Accuracy:
    """The declared :class:`Accuracy` of ``dataset``'s float variable ``name``.

    Raises ``ValueError`` if its kind of result declares none for it: every compared quantity needs a tolerance
    derived from how it is computed.
    """
    declared = _declared(dataset, 0)
    if name not in declared:
        study = f" (study={dataset.attrs['study']!r}: its module declares them, e.g. mdr_events.reproduction for " \
            "the studies of results/; import it first)" if "study" in dataset.attrs else ""
        raise ValueError(f"variable {name!r} of content={dataset.attrs.get('content')!r} has no declared accuracy"
                         f"{study}; allowed: variables declared with mdr_events.io.agreement.register_accuracy")
    return declared[name]


def attribute_accuracy(dataset: xr.Dataset, name: str) -> Accuracy:
    """The :class:`Accuracy` of a float attribute: declared, or :class:`RoundOff` of its value."""
    return _declared(dataset, 1).get(name, RoundOff())


def tolerance_of(dataset: xr.Dataset, name: str) -> np.ndarray:
    """The absolute tolerance of ``dataset``'s float variable ``name`` (:func:`accuracy_of`)."""
    return accuracy_of(dataset, name).tolerance(dataset, name)


#: NumPy dtype kinds that hold strings (unicode, bytes, or Python objects as netCDF returns them).
_STRING_KINDS = {"U", "S", "O"}


def _float_differences(name: str, actual: np.ndarray, expected: np.ndarray, tolerance: np.ndarray,
                       accuracy: Accuracy) -> list[str]:
    """Non-finite entries exactly, finite ones within the (element-wise) tolerance."""
    same_pattern = (np.isnan(actual) == np.isnan(expected)) & (np.isinf(actual) == np.isinf(expected))
    if not np.all(same_pattern):
        return [f"{name}: nan/inf at {int(np.count_nonzero(~same_pattern))} other place(s)"]
    infinite = np.isinf(expected)
    if np.any(actual[infinite] != expected[infinite]):
        return [f"{name}: infinities of other sign"]
    finite = np.isfinite(expected)
    tolerance = np.broadcast_to(tolerance, expected.shape)
    unknown = finite & ~np.isfinite(tolerance)
    if np.any(unknown):  # an unseen parameter's infinite standard error: nothing to compare within, never "accept"
        at = tuple(int(i) for i in np.argwhere(unknown)[0])
        return [f"{name}: no finite tolerance at {at} ({accuracy.describe()}), so it cannot be compared"]
    with np.errstate(invalid="ignore"):  # inf - inf where both are infinite (compared above)
        excess = np.where(finite, np.abs(actual - expected) - tolerance, -np.inf)
    if excess.size and np.max(excess) > 0:
        at = np.unravel_index(int(np.argmax(excess)), expected.shape)
        allowed = float(tolerance[at])
        return [f"{name}: differs by {abs(float(actual[at] - expected[at])):.3g} at {tuple(int(i) for i in at)} "
                f"(allowed: {allowed:.3g}, {accuracy.describe()})"]
    return []


def _attribute_differences(actual: xr.Dataset, expected: xr.Dataset) -> list[str]:
    differing = []
    for key in sorted(set(actual.attrs) | set(expected.attrs)):
        mine, theirs = actual.attrs.get(key), expected.attrs.get(key)
        floats = all(isinstance(v, (float, np.floating)) for v in (mine, theirs))
        if floats and math.isfinite(float(theirs)):
            try:
                allowed = float(attribute_accuracy(expected, key).tolerance(expected, key))
            except (ValueError, KeyError) as error:  # what its tolerance needs is missing
                differing.append(f"{key} (no tolerance can be derived: {error})")
                continue
            if not abs(float(mine) - float(theirs)) <= allowed:
                differing.append(key)
        elif not (np.array_equal(np.asarray(mine), np.asarray(theirs), equal_nan=True) if floats else mine == theirs):
            differing.append(key)
    return [f"attributes {differing} differ"] if differing else []


def result_differences(actual: xr.Dataset, expected: xr.Dataset) -> list[str]:
    """How ``actual`` differs from ``expected`` beyond what another environment's rounding explains ([] if not).

    Exact: dimensions and their sizes, the names of variables and coordinates, the attributes of each variable,
    string and integer attributes, and arrays of integers and strings (e.g. event kinds). Floating-point arrays
    agree where their ``nan`` and ``inf`` match exactly and their finite values lie within the tolerance of their
    declared :class:`Accuracy`, computed from ``expected``; float attributes within theirs
    (:func:`attribute_accuracy`). A finite value whose tolerance is not finite (an unseen parameter's estimate)
    cannot be compared and is a difference.

    Parameters
    ----------
    actual : xarray.Dataset
        A result computed here.
    expected : xarray.Dataset
        The committed result of the same kind (its ``content`` selects the declared accuracies).

    Returns
    -------
    list of str
        One line per difference, naming the variable, where, by how much and what was allowed.

    Raises
    ------
    ValueError
        If a float variable of ``expected`` has no declared accuracy (:func:`accuracy_of`).
    """
    found: list[str] = []
    if dict(actual.sizes) != dict(expected.sizes):
        return [f"dimensions {dict(actual.sizes)} instead of {dict(expected.sizes)}"]
    if set(actual.variables) != set(expected.variables):
        return [f"variables {sorted(actual.variables)} instead of {sorted(expected.variables)}"]
    found += _attribute_differences(actual, expected)
    for name in sorted(expected.variables):
        mine, theirs = actual[name].variable, expected[name].variable
        if mine.dims != theirs.dims or mine.attrs != theirs.attrs:
            found.append(f"{name}: dimensions or attributes differ")
            continue
        values, reference = np.asarray(mine.values), np.asarray(theirs.values)
        kinds = {values.dtype.kind, reference.dtype.kind}
        if kinds == {"f"}:
            accuracy = accuracy_of(expected, name)
            try:
                tolerance = accuracy.tolerance(expected, name)
            except (ValueError, KeyError) as error:  # e.g. a file of an older schema, without what it needs
                found.append(f"{name}: no tolerance can be derived ({error})")
                continue
            found += _float_differences(name, values, reference, tolerance, accuracy)
        elif kinds <= _STRING_KINDS:  # netCDF gives strings back as objects
            if values.shape != reference.shape or not np.array_equal(values.astype(str), reference.astype(str)):
                found.append(f"{name}: strings differ")
        elif len(kinds) > 1 or not np.array_equal(values, reference):
            found.append(f"{name}: values differ ({values.dtype} and {reference.dtype} compared exactly)")
    return found


def assert_results_agree(actual: xr.Dataset, expected: xr.Dataset) -> None:
    """Raise ``AssertionError`` listing :func:`result_differences` if there are any."""
    found = result_differences(actual, expected)
    if found:
        raise AssertionError("results disagree: " + "; ".join(found))
