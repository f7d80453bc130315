"""The measurement a fit reads and the model's curves it is compared with (:func:`mdr_events.analysis.fit.fit`).

The measured curves on the path's clock with each quantity's noise (:class:`Measurement`; the noise given or
:func:`estimate_noise`); the model at the measured samples (:func:`model_curves`, :func:`curves_of`:
:class:`ModelCurves`); curves a measurement of the model would give (:func:`synthetic_measurement`).

**Samples out of contact** (the documented rule; never a ``nan`` set to 0). The model's forces and area are
exactly 0 while the indenter is out of the elastomer: before the first contact, after the pull-off, after a
path that ends outside it, before a path that starts outside it. Those samples are compared with 0 like any
other (a force measured after the pull-off is the instrument's noise around zero, and the time of the jump
is information on ``Δγ1``). The model says nothing before a path that starts inside the elastomer or after
one that ends in contact: samples there are *left out*, and so are samples whose measured value is ``nan``.
Left-out samples contribute a zero residual (the residual vector keeps its length) and are counted.
"""

from __future__ import annotations

import math
from typing import Any, Mapping, NamedTuple, Sequence

import numpy as np
import xarray as xr

from mdr_events.theory.job import rate_independent
from mdr_events.analysis.validate import one_path, one_path_job, reference_of, times_from_contact
from mdr_events.contact import Contact
from mdr_events.contact.friction import friction_attrs
from mdr_events.io.agreement import Integrated, RoundOff, register_accuracy
from mdr_events.io.candidates import Candidate
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.models.continuum import PathSolution, Tolerances, evaluate, solve_path
from mdr_events.models.indenters import profile_attrs
from mdr_events.models.kernel_model import KernelModel, as_kernel_model
from mdr_events.models.methods import Continuum
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory.scales import check_representable
from mdr_events.validation import SCALE_MAX, check_count, check_mapping, check_real, real_array, shown

__all__ = ["estimate_noise", "Measurement", "measurement_of", "ModelCurves", "model_curves", "curves_of",
           "shifted_path", "synthetic_measurement", "SYNTHETIC_CONTENT", "FITTED_QUANTITIES"]

#: The ``content`` attribute of :func:`synthetic_measurement`'s dataset.
SYNTHETIC_CONTENT = "synthetic measurement of the model"
#: Measured quantities a fit compares (any subset; the sliding fraction is not measured).
FITTED_QUANTITIES = ("normal_force", "tangential_force", "contact_area", "contact_radius")
QUANTITY_UNITS = {"normal_force": "N", "tangential_force": "N", "contact_area": "m2", "contact_radius": "m"}
QUANTITY_SYMBOLS = {"normal_force": "F_N", "tangential_force": "F_x", "contact_area": "A", "contact_radius": "a"}
#: The noise estimate never falls below this share of the quantity's largest magnitude (noise-free data).
NOISE_FLOOR_SHARE = 1e-12


def estimate_noise(values: np.ndarray) -> float:
    """The noise's standard deviation in a sampled curve, from its second differences (robust).

    For white noise of deviation σ on a curve smooth over a few samples, ``Δ²y`` has deviation ``σ√6``; the
    median absolute deviation (×1.4826) ignores the few jumps (contact made, pull-off) and corners. Never
    below :data:`NOISE_FLOOR_SHARE` of the largest magnitude (noise-free data). ``nan`` samples are skipped.
    """
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    floor = NOISE_FLOOR_SHARE * float(np.max(np.abs(finite), initial=0.0)) or NOISE_FLOOR_SHARE
    if finite.size < 4:
        return floor
    second = np.diff(finite, 2)
    mad = float(np.median(np.abs(second - np.median(second))))
    return max(1.4826 * mad / math.sqrt(6.0), floor)



class Measurement(NamedTuple):
    """The measured curves on the path's clock, and each quantity's noise."""

    path_time: np.ndarray  #: s from the nominal path's start, before the time offset
    values: dict[str, np.ndarray]
    noise: dict[str, float]
    noise_given: dict[str, bool]
    candidate: Candidate


def measurement_of(read: Candidate, path: Path, time_origin: Any,
                   noise: Mapping[str, float] | None) -> Measurement:
    """The measurement of a fit: the measured quantities a fit compares, on the path's clock, with their noise.

    Parameters
    ----------
    read : Candidate
        The measured data (:func:`~mdr_events.io.candidates.read_candidate`).
    path : Path
        The nominal path (the start's parameters): its first contact places the measured time on its clock.
    time_origin : str or float
        What the measured time counts from (:func:`~mdr_events.analysis.validate.times_from_contact`).
    noise : mapping or None
        Quantity → the standard deviation of its noise; the others are estimated (:func:`estimate_noise`).

    Returns
    -------
    Measurement

    Raises
    ------
    ValueError
        No quantity to fit, one without a finite sample, a noise of a quantity not measured or out of range.
    """
    values = {name: read.quantities[name] for name in FITTED_QUANTITIES if name in read.quantities}
    if not values:
        raise ValueError(f"{read.where}: none of {', '.join(FITTED_QUANTITIES)} to fit; found: "
                         f"{', '.join(read.quantities)}")
    for name, series in values.items():
        if not np.any(np.isfinite(series)):
            raise ValueError(f"{read.where}: {name} has no finite sample; allowed: measured values (nan marks a "
                             "missing sample)")
    noise = check_mapping("noise", noise, "{'normal_force': 2e-3}")
    sigma, given = {}, {}
    for name in noise:
        if name not in values:
            raise ValueError(f"noise: {name!r} is not allowed; allowed: the quantities measured "
                             f"({', '.join(values)})")
    for name, series in values.items():
        given[name] = name in noise
        largest = float(np.nanmax(np.abs(series), initial=0.0))
        # a residual over the noise, and its square, must stay finite, and so must the weight 1/noise² (1e200
        # underflowed it to 0: divisions by zero in the covariance)
        sigma[name] = check_real(f"noise[{name!r}]", noise[name], f"a number > 0 ({QUANTITY_UNITS[name]}) from "
                                 f"{largest / SCALE_MAX:.3g} to {max(largest, 1.0) * SCALE_MAX:.3g}: the data's largest "
                                 f"magnitude divided and multiplied by {SCALE_MAX:.2g}",
                                 lambda value: value > 0 and largest <= value * SCALE_MAX
                                 and value <= max(largest, 1.0) * SCALE_MAX) if given[name] else estimate_noise(series)
    return Measurement(times_from_contact(read, path, time_origin) + path.first_contact_time(), values, sigma, given, read)


class ModelCurves(NamedTuple):
    """The model at the measured samples: each quantity (``nan``: left out) and where it is in contact."""

    values: dict[str, np.ndarray]
    in_contact: np.ndarray


def shifted_path(path: Path, depth_offset: float) -> Path:
    """``path`` with its depth zero ``depth_offset`` above the real surface (``path`` itself for 0)."""
    if depth_offset == 0.0:
        return path
    return Path(path.waypoints - np.array([0.0, depth_offset]), path.speed, path.alpha)


def model_curves(model: KernelModel | Parameters, path: Path, times: np.ndarray, tolerances: Tolerances,
                 limits: Limits, quantities: Sequence[str]) -> ModelCurves:
    """The curves of ``model`` (:class:`~mdr_events.models.kernel_model.KernelModel`; a ``Parameters`` alone the
    paper's model) at ``times`` (s on the path's clock) by the module's rule out of contact: 0 where the indenter is
    out of the elastomer, ``nan`` (left out) before a path that starts inside it and after one that ends in
    contact."""
    params, profile, friction, adhesion, layer = as_kernel_model(model)
    return curves_of(solve_path(params, path, tolerances, limits, profile, friction, adhesion, layer), path, times,
                     quantities)


def curves_of(solution: PathSolution, path: Path, times: np.ndarray, quantities: Sequence[str]) -> ModelCurves:
    """:func:`model_curves` of a solution at hand (``path``: the one it solved)."""
    since_contact = times - solution.t_contact
    filled = evaluate(solution, np.maximum(since_contact, 0.0))
    radius = filled["contact_radius"]
    out = {"normal_force": filled["normal_force"], "tangential_force": filled["tangential_force"],
           "contact_radius": radius, "contact_area": math.pi * radius**2}
    before = since_contact < 0
    after = since_contact > solution.end_time
    in_contact = (np.nan_to_num(radius) > 0) & ~before & ~after  # evaluate's radius at t < 0 is that at contact
    outside_before = path.waypoints[0, 1] <= 0.0
    for name in quantities:
        values = out[name]
        values[before] = 0.0 if outside_before else math.nan
        values[after] = 0.0 if solution.ended_by_contact else math.nan
    return ModelCurves({name: out[name] for name in quantities}, in_contact)


#: The largest relative noise a synthetic measurement takes: noise of the curves' own size.
MAX_RELATIVE_NOISE = 1.0


def _synthetic_arguments(times, quantities, relative_noise, time_shift, seed, limits: Limits) -> tuple:
    """Each argument of :func:`synthetic_measurement` checked, named where refused: the times a finite, strictly
    increasing 1-D grid within ``limits.samples`` (and scales that stay numbers), the quantities distinct names of
    :data:`FITTED_QUANTITIES`, the noise in ``[0, MAX_RELATIVE_NOISE]``, the shift a finite time."""
    limits = check_limits(limits)
    grid = real_array("times", times, "a strictly increasing 1-D grid of finite times (s)")
    limits.check(f"a synthetic measurement of {grid.size} samples", samples=grid.size,
                 memory=8 * grid.size * (len(FITTED_QUANTITIES) + 2))
    if grid.ndim != 1 or grid.size < 2 or not np.all(np.isfinite(grid)) or np.any(np.diff(grid) <= 0) \
            or np.max(np.abs(grid)) > SCALE_MAX:
        raise ValueError(f"times={shown(times)} is not allowed; allowed: a strictly increasing 1-D grid of at least 2 "
                         f"finite times (s) within ±{SCALE_MAX:.2g}")
    if isinstance(quantities, str) or not all(isinstance(name, str) for name in quantities) or not quantities \
            or len(set(quantities)) != len(quantities) or not set(quantities) <= set(FITTED_QUANTITIES):
        raise ValueError(f"quantities={shown(quantities)} is not allowed; allowed: distinct names of "
                         f"{', '.join(FITTED_QUANTITIES)}, e.g. ('normal_force',)")
    noise = check_real("relative_noise", relative_noise, f"a share of each curve's largest value in [0, "
                       f"{MAX_RELATIVE_NOISE:g}]", lambda value: 0.0 <= value <= MAX_RELATIVE_NOISE)
    shift = check_real("time_shift", time_shift, f"a finite time (s) within ±{SCALE_MAX:.2g}",
                       lambda value: abs(value) <= SCALE_MAX and np.all(np.diff(grid + value) > 0))
    check_count("seed", seed, 0)
    return grid, tuple(quantities), noise, shift


def synthetic_measurement(contact: Contact | Parameters, motion, alpha: float | None = None, *, times: np.ndarray,
                          relative_noise: float = 0.0, reference: Continuum | None = None,
                          limits: Limits = DEFAULT_LIMITS, **options) -> xr.Dataset:
    """Curves a measurement of this model would give: the continuum at ``times`` (s on the path's clock,
    the clock then reading ``times + time_shift``) plus white noise of ``relative_noise`` times each
    quantity's largest magnitude (``numpy.random.default_rng(seed)``), as a Dataset :func:`fit` reads
    (``time_origin="path_start"``, with ``time_shift`` the offset a fit should find).

    ``contact``, ``motion`` and ``alpha`` are the one path's, as :func:`mdr_events.validate` takes them;
    ``reference`` the continuum with its tolerances. The options: ``seed`` (default 0), ``quantities`` (default
    ``F_N``, ``F_x``, ``A``), ``time_shift`` (s, default 0); beside a :class:`~mdr_events.Parameters` also
    ``profile``, ``friction`` and ``tolerances``."""
    options = dict(options)
    seed, time_shift = options.pop("seed", 0), options.pop("time_shift", 0.0)
    quantities = options.pop("quantities", ("normal_force", "tangential_force", "contact_area"))
    _, tolerances = reference_of(reference, options.pop("tolerances", None), None)
    job = one_path_job(contact, motion, alpha, options, caller="fit")
    rate_independent(job.contact, "fit (its forward model, solve_path, is rate-independent)")
    if options:
        raise TypeError(f"synthetic_measurement() got an unexpected keyword argument {next(iter(options))!r}; "
                        "allowed: seed, quantities, time_shift (and profile, friction, tolerances beside a Parameters)")
    params, profile, friction = job.params, job.profile, job.friction
    check_representable(params, profile, friction)
    the_path, _ = one_path(job)
    limits = check_limits(limits)
    times, quantities, relative_noise, time_shift = _synthetic_arguments(times, quantities, relative_noise, time_shift,
                                                                         seed, limits)
    curves = model_curves(KernelModel(params, profile, friction, layer=job.contact.layer), the_path, times, tolerances,
                          limits, tuple(quantities)).values
    rng = np.random.default_rng(seed)
    data = {}
    for name in quantities:
        noise = relative_noise * float(np.nanmax(np.abs(curves[name]))) * rng.standard_normal(times.size)
        data[name] = (("time",), curves[name] + noise, {"units": QUANTITY_UNITS[name],
                                                        "long_name": f"synthetic measured {QUANTITY_SYMBOLS[name]}"})
    coords = {"time": ("time", times + time_shift, {"units": "s", "long_name": "time of the synthetic measurement"})}
    return stamp(xr.Dataset(data, coords=coords), params, content=SYNTHETIC_CONTENT,
                 relative_noise=float(relative_noise), seed=int(seed), time_shift=float(time_shift),
                 continuum_rtol=tolerances.rtol, path_waypoints=the_path.describe(), path_speed=the_path.speed, **profile_attrs(profile),
                 **friction_attrs(friction))


register_schema(SYNTHETIC_CONTENT, {"time": ("time",)})
#: A synthetic measurement is the continuum's curves (to its rtol) plus seeded noise; a fit as in fit_accuracy.
register_accuracy(SYNTHETIC_CONTENT, {**{name: Integrated("continuum_rtol") for name in FITTED_QUANTITIES},
                                      "time": RoundOff()})
