"""The observed order of convergence of a simulator to the exact continuum: :func:`convergence_study`.

The same simulator run at three or more spacings ``Δx`` is validated at each (:func:`mdr_events.validate`,
once per spacing, nothing else recomputed), and every error is fitted in log–log against ``Δx``:

    log e = log C + p log Δx        (least squares over the usable spacings)

whose slope ``p`` is the **observed order** and whose standard error is its **spread**

    spread = sqrt( Σ r_i² / (n − 2) / Σ (log Δx_i − mean log Δx)² )     (r_i: the residuals, n points).

Rules:

- only errors that are finite and not 0 enter a fit (``log 0`` is ``−∞``: an error exactly 0, e.g. an
  event found on the exact sample, says nothing about a rate; ``nan``: not determined at that spacing);
  the fit is of the magnitudes ``|e|``;
- with fewer than 2 usable spacings there is no fit (order, spread and fitted values ``nan``); with
  exactly 2 the order is the slope through them and the spread is ``nan`` (no degree of freedom left);
- a row **converges** when ``order − 2·spread ≥ CONVERGES_SHARE · expected_order`` (a ``nan`` spread
  counts as 0): the error shrinks at least at half the expected rate, with two standard errors to spare;
  **and** when its **finest order** (the slope through the two finest usable spacings alone) is at least
  ``CONVERGES_SHARE · expected_order`` too: an error that stops falling at the finest spacing (a floor, a run
  that no longer refines) is not converging, however well the coarser spacings fell (five spacings whose last
  error equals the one before fitted an order of 0.8 ± 0.12 and passed the first rule alone).
  A row without a fit does not converge;
- the **verdict** (attribute) reads the norms only (max, RMS and L1 of every quantity): ``"converges"``
  when each of them with a fit converges, ``"does not converge"`` when one with a fit does not,
  ``"undetermined"`` when none has a fit. The event rows are reported beside them but left out of the
  verdict: a time-stepping model finds an event on its sample grid, so its event errors are not a smooth
  function of ``Δx`` (their observed orders come out erratic even for a right simulator).

Beside the orders, each spacing keeps its validation's verdict (``validation_verdict``, 1: pass, by
:func:`~mdr_events.analysis.reports.validation_failures` at ``tolerance``: the norms, the contact and the events, as
:func:`~mdr_events.validate`, the command line and study files judge a run) and its event errors relative to the
path's duration (``event_time_relative_error``, the verdict's measure).
"""

from __future__ import annotations

import math
from numbers import Real
from typing import Mapping, NamedTuple

import numpy as np
import xarray as xr

from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.analysis.reports import CONVERGENCE_STUDY_CONTENT, ConvergenceVerdict, ValidationReport
from mdr_events.analysis.validate import COMPARED, DEFAULT_TOLERANCE, VALIDATED_EVENTS, _validation_job, validate
from mdr_events.contact import Contact
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.models.continuum import PathSolution
from mdr_events.models.continuum.rate_reference import RateSolution
from mdr_events.models.methods import Continuum
from mdr_events.parameters import Parameters
from mdr_events.validation import SCALE_MAX, SCALE_MIN, as_float

__all__ = ["convergence_study", "fit_observed_order", "OrderFit", "CONVERGENCE_STUDY_CONTENT", "NORMS",
           "CONVERGES_SHARE", "SPREAD_FACTOR", "MIN_SPACINGS"]

#: The ``content`` attribute of a convergence study.
#: The norms of :func:`mdr_events.validate` fitted, per quantity.
NORMS = ("max_error", "rms_error", "l1_error")
#: A row converges when ``order − SPREAD_FACTOR · spread >= CONVERGES_SHARE · expected_order``.
CONVERGES_SHARE = 0.5
SPREAD_FACTOR = 2.0
#: The fewest spacings a study accepts.
MIN_SPACINGS = 3
CONVERGES_RULE = (f"order - {SPREAD_FACTOR:g} * spread >= {CONVERGES_SHARE:g} * expected_order "
                  f"(spread nan counts as 0) and finest order >= {CONVERGES_SHARE:g} * expected_order (the slope "
                  "through the two finest usable spacings: the error still falls there); no fit: does not converge")


class OrderFit(NamedTuple):
    """A least-squares fit ``log|e| = log C + order · log Δx`` (:func:`fit_observed_order`)."""

    order: float
    """The slope (``nan``: fewer than 2 usable points)."""
    spread: float
    """The slope's standard error (``nan`` with fewer than 3 usable points)."""
    fitted: np.ndarray
    """``C Δx^order`` at each of the spacings given (``nan`` without a fit)."""
    points: int
    """How many spacings entered the fit."""
    finest_order: float = math.nan
    """The slope through the two finest usable spacings alone (``nan``: fewer than 2 usable points)."""


def fit_observed_order(spacings, errors) -> OrderFit:
    """Fit ``log|e| = log C + p log Δx`` by least squares over the spacings whose error is finite and not 0.

    Parameters
    ----------
    spacings : array_like
        The spacings ``Δx`` (> 0; any unit: the order does not depend on it).
    errors : array_like
        One error per spacing; ``0``, ``nan`` and ``inf`` are left out of the fit.

    Returns
    -------
    OrderFit
        The order ``p``, its standard error, ``C Δx^p`` at every spacing given, the number of points used and the
        finest order (the slope through the two finest usable spacings).
    """
    dx = np.asarray(spacings, dtype=float)
    magnitude = np.abs(np.asarray(errors, dtype=float))
    if dx.shape != magnitude.shape or dx.ndim != 1:
        raise ValueError(f"spacings {dx.shape} and errors {magnitude.shape} are not allowed; allowed: two 1-d "
                         "arrays of the same length")
    use = np.isfinite(magnitude) & (magnitude > 0) & np.isfinite(dx) & (dx > 0)
    points = int(np.count_nonzero(use))
    nothing = OrderFit(math.nan, math.nan, np.full(dx.shape, math.nan), points)
    if points < 2:
        return nothing
    x, y = np.log(dx[use]), np.log(magnitude[use])
    centred = x - x.mean()
    sxx = float(np.sum(centred**2))
    if sxx == 0.0:  # every usable error at the same spacing: no slope
        return nothing
    order = float(np.sum(centred * (y - y.mean())) / sxx)
    intercept = float(y.mean() - order * x.mean())
    residuals = y - (intercept + order * x)
    spread = float(math.sqrt(np.sum(residuals**2) / (points - 2) / sxx)) if points > 2 else math.nan
    with np.errstate(divide="ignore", invalid="ignore"):
        fitted = np.where(dx > 0, np.exp(intercept + order * np.log(np.where(dx > 0, dx, 1.0))), np.nan)
    # (the two finest distinct usable spacings, sxx > 0 above: at least two; a repeated one's errors averaged)
    finest = np.unique(x)[:2]
    finest_error = [float(np.mean(y[x == spacing])) for spacing in finest]
    finest_order = (finest_error[1] - finest_error[0]) / float(finest[1] - finest[0])
    return OrderFit(order, spread, fitted, points, finest_order)


def _converges(fit: OrderFit, expected_order: float) -> bool:
    """The module's rule: the fitted order, less :data:`SPREAD_FACTOR` spreads, and the finest order each at least
    :data:`CONVERGES_SHARE` of the expected order."""
    if not (math.isfinite(fit.order) and math.isfinite(fit.finest_order)):
        return False
    margin = SPREAD_FACTOR * fit.spread if math.isfinite(fit.spread) else 0.0
    return min(fit.order - margin, fit.finest_order) >= CONVERGES_SHARE * expected_order


def _spacings(candidates_by_dx) -> list[float]:
    allowed = (f"allowed: a mapping of at least {MIN_SPACINGS} spacings Δx (m; distinct numbers from "
               f"{SCALE_MIN:.2g} to {SCALE_MAX:.2g}, whose logarithms are fitted and drawn) to candidates (anything "
               "mdr_events.validate takes)")
    if not isinstance(candidates_by_dx, Mapping):
        raise ValueError(f"candidates_by_dx of type {type(candidates_by_dx).__name__} is not allowed; {allowed}")
    keys = list(candidates_by_dx)
    bad = [key for key in keys if isinstance(key, bool) or not isinstance(key, Real)
           or not SCALE_MIN <= as_float(key) <= SCALE_MAX]
    if bad:
        raise ValueError(f"candidates_by_dx has the spacing(s) {', '.join(map(repr, bad))}; {allowed}")
    spacings = [float(key) for key in keys]
    if len(set(spacings)) != len(spacings):
        raise ValueError(f"candidates_by_dx has repeated spacings {sorted(spacings)}; {allowed}")
    if len(spacings) < MIN_SPACINGS:
        raise ValueError(f"candidates_by_dx has {len(spacings)} spacing(s) {sorted(spacings, reverse=True)}; "
                         f"{allowed}")
    return spacings


def convergence_study(candidates_by_dx: Mapping[float, object], contact: Contact | Parameters, motion,
                      alpha: float | None = None, *, expected_order: float = 1.0,
                      tolerance: float = DEFAULT_TOLERANCE,
                      reference: Continuum | PathSolution | RateSolution | None = None, limits: Limits = DEFAULT_LIMITS,
                      **options) -> xr.Dataset:
    """The observed order of convergence of a simulator to the exact continuum, from three or more spacings.

    The continuum is solved once for the path, and each candidate validated once against that solution
    (:func:`mdr_events.validate`, with the same ``params``, ``path``,
    ``alpha``, ``names``, ``units`` and ``time_origin``); its norms and event errors are fitted in
    log–log against ``Δx`` (the module's rules: left-out errors, spread, ``converges``, verdict).

    Parameters
    ----------
    candidates_by_dx : mapping of float to candidate
        Spacing ``Δx`` (m) -> the simulator's output at that spacing: an xarray Dataset, a mapping of
        arrays, or a CSV / netCDF file (:func:`mdr_events.validate`). At least three distinct spacings.
    contact : Contact or Parameters
        The contact the candidates simulated, as for :func:`mdr_events.validate`.
    motion : Scenario, Paths, Path or {"A", "B", "B+"}
        The one path, as for :func:`mdr_events.validate`.
    alpha : float, optional
        With a scenario's name: the path's angle (degrees).
    expected_order : float
        The order the simulator should have (> 0; 1 for the paper's spring model), reported beside the
        observed ones and used by ``converges``.
    tolerance : float
        The bound of each spacing's validation verdict (:func:`mdr_events.validate`'s, in (0, 1]); not used by the
        study's own verdict (the observed order).
    reference : Continuum, PathSolution or RateSolution, optional
        The exact reference, as for :func:`mdr_events.validate`.
    limits : Limits
        What the continuum run may use (:func:`mdr_events.validate`).
    **options
        How to read the candidates, as for :func:`mdr_events.validate`: ``names``, ``units``, ``time_origin``,
        ``select``; beside a Parameters ``profile`` and ``friction``.

    Returns
    -------
    xarray.Dataset
        Coordinates ``dx`` (m, coarsest first), ``quantity``, ``event`` (:data:`VALIDATED_EVENTS`).
        Errors: ``max_error``, ``rms_error``, ``l1_error`` (``dx`` × ``quantity``, relative to each
        quantity's range); ``event_time_error`` (s) and ``event_depth_error`` (m) (``dx`` × ``event``,
        absolute values); ``pull_off_force_error`` (N, ``dx``, absolute value). For each of these
        errors ``E``: ``E_order`` (the observed order, along ``quantity`` / ``event`` / scalar),
        ``E_order_spread`` (its standard error), ``E_finest_order`` (the slope through the two finest usable
        spacings), ``E_converges`` (1: yes) and ``E_fitted`` (the fitted
        line ``C Δx^order`` at each spacing, same dims and unit as ``E``). Also ``expected_order``,
        ``samples_compared``, ``samples_left_out`` and ``validation_verdict`` (1: pass; per ``dx``) and
        ``event_time_relative_error`` (``dx`` × ``event``: validate's, ``nan`` not compared). Attributes ``verdict``
        (``"converges"``, ``"does not converge"``, ``"undetermined"``), ``expected_order``, ``tolerance``,
        ``converges_rule``, ``candidate_sources``.
    """
    if isinstance(expected_order, bool) or not isinstance(expected_order, Real) \
            or not math.isfinite(as_float(expected_order)) or expected_order <= 0:
        raise ValueError(f"expected_order={expected_order!r} is not allowed; allowed: a finite number > 0")
    expected_order = float(expected_order)
    limits = check_limits(limits)
    spacings = _spacings(candidates_by_dx)
    order = sorted(range(len(spacings)), key=lambda i: -spacings[i])
    keys = list(candidates_by_dx)
    # one continuum solution serves every spacing: the study costs one solve and the comparisons
    job = _validation_job(contact, motion, alpha, tolerance, reference, options, "convergence_study")
    solution = job.exact(limits)
    reading = {name: value for name, value in options.items() if name not in ("tolerances", "solution")}
    reports = [validate(candidates_by_dx[keys[i]], contact, motion, alpha, tolerance=tolerance, reference=solution,
                        limits=limits, **reading) for i in order]
    dx = np.array([spacings[i] for i in order])
    found = {str(name) for report in reports for name in report["quantity"].values}
    quantities = [name for name in COMPARED if name in found]
    data = _order_variables(reports, dx, quantities, expected_order)
    for key, text in (("samples_compared", "samples compared"),
                      ("samples_left_out", "samples of the runs left out (contact differs, straddles an event)")):
        data[key] = (("dx",), np.array([int(report[key]) for report in reports]), {"units": "1", "long_name": text})
    _validation_variables(data, reports)
    coords = {"dx": ("dx", dx, {"units": "m", "long_name": "spacing of the springs"}),
              "quantity": ("quantity", np.array(quantities), {"units": "1", "long_name": "quantity compared"}),
              "event": ("event", np.array(VALIDATED_EVENTS), {"units": "1", "long_name": "event compared"})}
    first = reports[0].attrs
    attrs = dict(content=CONVERGENCE_STUDY_CONTENT, verdict=_verdict(data).value, expected_order=expected_order,
                 tolerance=float(tolerance),
                 converges_rule=CONVERGES_RULE, time_origin=str(job.time_origin),
                 candidate_sources="; ".join(str(report.attrs["candidate_source"]) for report in reports),
                 path_waypoints=first["path_waypoints"], path_speed=first["path_speed"])
    # the indenter, the friction law and the adhesion law, as the reports name them
    attrs.update({key: value for key, value in first.items() if key.startswith(("profile", "friction_", "adhesion_"))})
    return stamp(xr.Dataset(data, coords=coords), job.model.params, **attrs)


def _validation_variables(data: dict, reports: list[xr.Dataset]) -> None:
    """Per spacing, its validation's verdict (the one rule: :func:`~mdr_events.analysis.reports.validation_failures`)
    and its event errors relative to the path's duration."""
    passed = [ValidationReport.from_dataset(report).passed for report in reports]
    data["validation_verdict"] = (("dx",), np.array(passed, dtype=np.int8), {
        "units": "1", "long_name": "the validation's verdict at this spacing (1: pass: the norms, the contact and the "
                                   "events within the tolerance; validate's rule)"})
    data["event_time_relative_error"] = (("dx", "event"), np.stack(
        [report["event_time_relative_error"].sel(event=list(VALIDATED_EVENTS)).values for report in reports]), {
        "units": "1", "long_name": "|candidate − exact| event time beyond the candidate's sample spacing, relative to "
                                   "the path's duration (validate's; nan: not compared)"})


def _fitted_variables(data: dict, key: str, values: np.ndarray, dx: np.ndarray, dims: tuple[str, ...], unit: str,
                      text: str, row_text: str, expected_order: float) -> None:
    """``key`` (``dx`` × ``dims``) and its fits, one per row along ``dims`` (none: one row): the observed order, its
    standard error, whether it converges and the fitted line."""
    data[key] = (("dx", *dims), values, {"units": unit, "long_name": text})
    columns = values.reshape(len(dx), -1)
    fits = [fit_observed_order(dx, columns[:, j]) for j in range(columns.shape[1])]
    shape = values.shape[1:]
    orders = np.array([fit.order for fit in fits]).reshape(shape)
    spreads = np.array([fit.spread for fit in fits]).reshape(shape)
    finest = np.array([fit.finest_order for fit in fits]).reshape(shape)
    flags = np.array([_converges(fit, expected_order) for fit in fits], dtype=np.int8).reshape(shape)
    fitted = np.stack([fit.fitted for fit in fits], axis=1).reshape(values.shape)
    data[f"{key}_order"] = (dims, orders, {"units": "1", "long_name": f"observed order of the {row_text}: "
                                           "least-squares slope of log(error) against log(dx)"})
    data[f"{key}_order_spread"] = (dims, spreads, {"units": "1", "long_name": f"standard error of the observed "
                                                   f"order of the {row_text}"})
    data[f"{key}_finest_order"] = (dims, finest, {"units": "1", "long_name": f"observed order of the {row_text} "
                                                  "between the two finest usable spacings alone"})
    data[f"{key}_converges"] = (dims, flags, {"units": "1", "long_name": f"the {row_text} converges (1: yes): "
                                              f"{CONVERGES_RULE}"})
    data[f"{key}_fitted"] = (("dx", *dims), fitted, {"units": unit, "long_name": f"fitted {row_text}, C dx**order"})


def _order_variables(reports: list[xr.Dataset], dx: np.ndarray, quantities: list[str], expected_order: float
                     ) -> dict[str, tuple]:
    """The norms, event errors and pull-off force error of the reports along ``dx``, each with its observed order."""
    data: dict[str, tuple] = {}
    for key in NORMS:
        values = np.stack([report[key].reindex(quantity=quantities).values for report in reports])
        _fitted_variables(data, key, values, dx, ("quantity",), "1",
                          f"{key.replace('_', ' ')} relative to the exact quantity's range", key.replace("_", " "),
                          expected_order)
    for key, unit, what in (("event_time_error", "s", "time"), ("event_depth_error", "m", "depth")):
        values = np.abs(np.stack([report[key].sel(event=list(VALIDATED_EVENTS)).values for report in reports]))
        _fitted_variables(data, key, values, dx, ("event",), unit, f"|candidate − exact| event {what}",
                          f"event {what} error", expected_order)
    pull_off = np.abs(np.array([float(report["pull_off_force_candidate"]) - float(report["pull_off_force_exact"])
                                for report in reports]))
    _fitted_variables(data, "pull_off_force_error", pull_off, dx, (), "N", "|candidate − exact| F_N at the pull-off",
                      "pull-off force error", expected_order)
    data["expected_order"] = ((), expected_order, {"units": "1", "long_name": "expected order of convergence"})
    return data


def _verdict(data: dict[str, tuple]) -> ConvergenceVerdict:
    """The norms' verdict: undetermined without any fitted order; converges if every fitted order does."""
    with_fit = [(data[f"{key}_converges"][1], np.isfinite(data[f"{key}_order"][1])) for key in NORMS]
    if not any(np.any(finite) for _, finite in with_fit):
        return ConvergenceVerdict.UNDETERMINED
    if all(np.all(flags[finite] == 1) for flags, finite in with_fit):
        return ConvergenceVerdict.CONVERGES
    return ConvergenceVerdict.DOES_NOT_CONVERGE

register_schema(CONVERGENCE_STUDY_CONTENT, {
    **{key: ("dx", "quantity") for key in NORMS},
    # (not *_finest_order: a study written before it is read as before)
    **{f"{key}_{part}": ("quantity",) for key in NORMS for part in ("order", "order_spread", "converges")},
    **{f"{key}_fitted": ("dx", "quantity") for key in NORMS},
    "event_time_error": ("dx", "event"), "event_depth_error": ("dx", "event"),
    "event_time_error_order": ("event",), "event_depth_error_order": ("event",),
    "pull_off_force_error": ("dx",), "pull_off_force_error_order": (), "expected_order": ()})
