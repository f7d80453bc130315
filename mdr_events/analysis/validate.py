"""Validate a discrete simulator — yours or ours — against the exact continuum: :func:`validate`.

The candidate (any program's output: :func:`mdr_events.io.candidates.read_candidate`) is compared
sample by sample with the continuum solution of the contact's adhesion law
(:func:`mdr_events.models.methods.exact_solution`: :func:`mdr_events.models.continuum.solve_path` under the paper's
law, the run of ``simulate(method="continuum")`` under the rate-dependent law, its radius an ODE state) evaluated
at the candidate's own times, and event by event with the continuum's event log. The report is an
``xarray.Dataset`` (:class:`~mdr_events.analysis.reports.ValidationReport` reads it typed). Which samples are
compared, the norms and the rules that find a candidate's events are :mod:`mdr_events.analysis.samples`'s; each
event is compared with the first event of that kind in the continuum's log (time and depth; the depth of a
candidate event is the path's depth at its time).
"""

from __future__ import annotations

import math
from typing import Any, Callable, Mapping, NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.reports import (LEFT_OUT_BOUND, VALIDATION_CONTENT, EventTimes, ValidationMeasures, Verdict,
                                        validation_failures)
from mdr_events.analysis.samples import (COMPARED, CONTACT_INDICATORS, FULL_SLIP_SHARE, LEFT_OUT_CODES, UNITS,
                                        VALIDATED_EVENTS, candidate_events, check_run_covers_the_contact,
                                        compared_samples, contact_change_excess, contact_differs_share,
                                        contact_of_tangential_force, corner_excess,
                                        event_time_errors,
                                        events_not_shown, exact_at, in_contact, left_out_error, relative_norms,
                                        candidate_scale,
                                        uncovered_share)
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.io.candidates import Candidate, check_run_is_finite, read_candidate
from mdr_events.theory.scales import check_representable
from mdr_events.io.datasets import register_schema, stamp, text_list_attrs
from mdr_events.models.continuum import PathSolution, Tolerances
from mdr_events.models.continuum.rate_reference import RateSolution
from mdr_events.contact import Contact
from mdr_events.models.indenters import SimulatedProfile, profile_attrs
from mdr_events.models.methods import Continuum, check_exact_solution, exact_solution
from mdr_events.models.motion import Paths
from mdr_events.models.job import ModelJob
from mdr_events.models.simulate import check_layer_taken, model_job
from mdr_events.models.paths import Path
from mdr_events.models.motion import check_path_representable
from mdr_events.parameters import Parameters
from mdr_events.validation import as_float, check_callback, check_real, shown
from mdr_events.contact.adhesion import adhesion_attrs
from mdr_events.contact.friction import friction_attrs

__all__ = ["validate", "DEFAULT_TOLERANCE", "contact_differs_share", "resolve_path", "times_from_contact", "candidate_events", "VALIDATION_CONTENT", "LEFT_OUT_CODES", "VALIDATED_EVENTS", "FULL_SLIP_SHARE"]
#: The verdict's bound on each quantity's max error, relative to its range, unless given.
DEFAULT_TOLERANCE = 1e-3
#: The exact solutions a referee reads (:func:`~mdr_events.models.methods.exact_solution`), one per kind of adhesion
#: law's continuum.
EXACT_SOLUTIONS = (PathSolution, RateSolution)
#: Bytes per candidate sample a validation holds at its peak (the columns read, the exact values at the samples, the
#: errors and masks of every quantity, the report's variables), counted against ``Limits.memory`` once the candidate is
#: read and before the exact run (measured with tracemalloc after a warm-up, 3e4 and 1e5 samples: 364 B with one
#: quantity, 379-396 B with three to five on the paper's A and B, 396 B under tau0+coulomb, 429 B on a 5 mm layer,
#: 512 B under the rate law; issue 32, round 30: 1e7 samples, accepted by ``samples``, held ~4-5 GB under 2 GiB).
BYTES_PER_VALIDATED_SAMPLE = 640
#: The time origins :func:`validate` accepts besides a number.
TIME_ORIGINS = ("first_contact", "path_start")


def resolve_path(params: Parameters, path, alpha, profile: SimulatedProfile = None) -> Path:
    """The :class:`Path` validated: ``path`` itself, or the scenario's path at the one angle ``alpha`` (ending below
    the jump-off of ``profile``, ``None``: the paraboloid); :func:`one_path` of the keywords of before."""
    return one_path(one_path_job(params, path, alpha, {"profile": profile}))[0]


def times_from_contact(candidate: Candidate, path: Path, time_origin) -> np.ndarray:
    """The candidate's times as seconds from the path's first contact, by ``time_origin`` (:func:`validate`)."""
    if isinstance(time_origin, str):
        if time_origin not in TIME_ORIGINS:
            raise ValueError(f"time_origin={shown(time_origin)} is not allowed; allowed: {', '.join(map(repr, TIME_ORIGINS))} "
                             "or the candidate's time of first contact (s)")
        return candidate.time - (path.first_contact_time() if time_origin == "path_start" else 0.0)
    if isinstance(time_origin, bool) or not isinstance(time_origin, (int, float)) or not math.isfinite(as_float(time_origin)):
        raise ValueError(f"time_origin={shown(time_origin)} is not allowed; allowed: {', '.join(map(repr, TIME_ORIGINS))} "
                         "or the candidate's time of first contact (s), a finite number")
    times = candidate.time - float(time_origin)
    if np.any(np.diff(times) <= 0):  # (1e300 s: every time rounds to the same number)
        raise ValueError(f"time_origin={shown(time_origin)} is not allowed: the times minus it are no longer distinct in "
                         "double precision; allowed: the candidate's time of first contact (s), of the size of its "
                         "times")
    return times


def reference_of(reference, tolerances, solution) -> tuple[PathSolution | RateSolution | None, Tolerances]:
    """The solution at hand (or ``None``) and the tolerances of the exact reference: ``reference`` (a
    :class:`~mdr_events.Continuum` or a solution), or the keywords of before (``tolerances=``, ``solution=``)."""
    given = [name for name, value in (("reference", reference), ("tolerances", tolerances), ("solution", solution))
             if value is not None]
    if len(given) > 1:
        raise ValueError(f"{' and '.join(given)} are not allowed together; allowed: one of them")
    if isinstance(reference, EXACT_SOLUTIONS) or solution is not None:
        found = reference if solution is None else solution
        if not isinstance(found, EXACT_SOLUTIONS):
            raise TypeError(f"solution={shown(found)} ({type(found).__name__}) is not allowed; allowed: a PathSolution "
                            "(or a RateSolution under the rate-dependent law)")
        return found, Tolerances()  # (the tolerances serve a solve, and there is none)
    if reference is not None and not isinstance(reference, Continuum):
        raise TypeError(f"reference={shown(reference)} ({type(reference).__name__}) is not allowed; allowed: a "
                        "Continuum (its tolerances), a PathSolution or a RateSolution")
    if tolerances is not None and not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances={shown(tolerances)} ({type(tolerances).__name__}) is not allowed; allowed: a "
                        "Tolerances")
    return None, (reference.tolerances if reference is not None else tolerances or Tolerances())


def one_path(job: ModelJob) -> tuple[Path, float | None]:
    """The one path a candidate ran (its motion must have one case) and its angle (``None``: a custom path), its
    scales within the double range (:func:`~mdr_events.theory.scales.check_representable`; every referee's, the
    LAMMPS check's too, before it runs)."""
    if isinstance(job.motion, Paths):
        label, path = next(iter(job.motion.paths.items()))
        if len(job.motion.paths) != 1:
            raise ValueError(f"motion holds {len(job.motion.paths)} paths; allowed: the one the candidate ran")
        check_path_representable(job.params, path, "path", job.profile, job.friction)
        return path, None
    if len(job.motion.alpha) != 1:
        raise ValueError(f"motion={job.motion!r} holds {len(job.motion.alpha)} angles; allowed: the one the candidate "
                         "ran")
    check_representable(job.params, job.profile, job.friction)
    return job.motion.cases(job.params, job.profile, job.friction).paths[0], job.motion.alpha[0]


class ValidationJob(NamedTuple):
    """What :func:`validate` compares: the contact along the one path the candidate ran (:class:`ModelJob`), how to
    read the candidate, and the exact reference (a solution at hand, or the tolerances to solve with)."""

    model: ModelJob
    path: Path
    names: Mapping[str, str] | None
    units: Mapping[str, str] | None
    time_origin: Any
    select: Mapping[str, object] | None
    solution: PathSolution | RateSolution | None
    tolerances: Tolerances

    def exact(self, limits: Limits) -> PathSolution | RateSolution:
        """The exact solution of :attr:`path`: the one at hand, else the continuum's of the contact's adhesion law
        (:func:`~mdr_events.models.methods.exact_solution`).

        Parameters
        ----------
        limits : Limits
            What the continuum run may use.

        Returns
        -------
        PathSolution or RateSolution
            The solution.
        """
        if self.solution is not None:
            return self.solution
        return exact_solution(self.model, self.path, self.tolerances, limits)


def one_path_job(contact, motion, alpha, options: dict[str, Any], caller: str = "validate") -> ModelJob:
    """:func:`~mdr_events.models.simulate.model_job` of a motion of one path (a scenario's name needs one angle;
    :func:`one_path` checks a Scenario's or Paths'), of a contact the continuum runs (``Continuum.check_model``: under
    the rate-dependent law the friction law ``"tau0"``, its springs' caps one play operator), on a body it runs (a
    layer of finite thickness with what the continuum takes there, the paper's law:
    :func:`~mdr_events.models.simulate.check_layer_taken`)."""
    if isinstance(motion, str) and (alpha is None or np.ndim(alpha) != 0):  # (a scenario of several angles)
        raise ValueError(f"alpha={shown(alpha)} is not allowed with scenario {motion!r}; allowed: one angle in degrees")
    job = model_job(contact, motion, alpha, options)
    Continuum().check_model(job)
    check_exact_solution(job, caller)
    check_layer_taken(job.contact, job.motion, Continuum(), where=caller)
    return job


def _validation_job(contact, motion, alpha, tolerance, reference, options: Mapping[str, Any],
                    caller: str = "validate") -> ValidationJob:
    """The job of ``validate(candidate, contact, motion, alpha, tolerance=, reference=, **options)``, every argument
    checked (the keywords of before converted by :func:`~mdr_events.models.simulate.model_job`)."""
    options = dict(options)
    names, units, select = (options.pop(name, None) for name in ("names", "units", "select"))
    time_origin = options.pop("time_origin", "first_contact")
    solution, tolerances = reference_of(reference, options.pop("tolerances", None), options.pop("solution", None))
    model = one_path_job(contact, motion, alpha, options, caller)
    if options:
        raise TypeError(f"{caller}() got an unexpected keyword argument {next(iter(options))!r}; allowed: names, "
                        "units, time_origin, select (and profile, friction beside a Parameters)")
    check_real("tolerance", tolerance, "a number in (0, 1] (the largest error relative to the quantity's range: "
               "above 1 every run would pass)", lambda value: 0 < value <= 1)
    check_representable(model.params, model.profile, model.friction)
    for name, what in (("profile", "indenter"), ("friction", "friction law"), ("adhesion", "adhesion law")):
        if solution is not None and getattr(solution, name) != getattr(model, name):
            raise ValueError(f"solution= was solved for {name}={getattr(solution, name)!r}, not for "
                             f"{name}={getattr(model, name)!r}; allowed: a solution of this {what}")
    path, angle = one_path(model)
    if solution is not None:
        _check_solution_is_of(solution, model, path)
    if select is None and angle is not None:
        select = {"alpha": angle}
    return ValidationJob(model, path, names, units, time_origin, select, solution, tolerances)


def _check_solution_is_of(solution: PathSolution | RateSolution, model: ModelJob, path: Path) -> None:
    """Refuse a solution at hand of other parameters or another path than the run judged (a run of τ0 = 20 kPa
    passed as the paper's contact beside a solution of 20 kPa)."""
    if solution.params != model.params:
        differ = [f"{name}={getattr(solution.params, name)!r} (judged: {getattr(model.params, name)!r})"
                  for name in model.params.as_dict() if getattr(solution.params, name) != getattr(model.params, name)]
        raise ValueError(f"solution= was solved for {', '.join(differ)}; allowed: a solution of the contact and "
                         "motion judged")
    solved = solution.path
    if solved is not None and not (np.array_equal(solved.waypoints, path.waypoints) and solved.speed == path.speed):
        raise ValueError(f"solution= was solved along {solved.describe()} at {solved.speed!r} m/s, not along the path "
                         f"judged ({path.describe()} at {path.speed!r} m/s); allowed: a solution of that path")


def validate(candidate, contact: Contact | Parameters, motion, alpha: float | None = None, *,
             tolerance: float = DEFAULT_TOLERANCE, reference: Continuum | PathSolution | RateSolution | None = None,
             limits: Limits = DEFAULT_LIMITS, progress: Callable[[str], None] | None = None,
             **options) -> xr.Dataset:
    """Compare a simulator's output with the exact continuum on the same path, sample and event by event.

    Parameters
    ----------
    candidate : xarray.Dataset, mapping of arrays, or the path of a CSV / netCDF file
        Time and at least one of ``normal_force``, ``tangential_force``, ``contact_area``,
        ``contact_radius`` (and optionally ``sliding_fraction``, for the slip events);
        :func:`mdr_events.io.candidates.read_candidate`.
    contact : Contact or Parameters
        The contact the candidate simulated (:class:`~mdr_events.Contact`); a :class:`~mdr_events.Parameters` is read
        as by :func:`mdr_events.simulate` (with ``profile=`` and ``friction=`` among the options).
    motion : Scenario, Paths, Path or {"A", "B", "B+"}
        The one path the candidate ran: a :class:`~mdr_events.Scenario` of one angle, :class:`~mdr_events.Paths` of
        one path or a :class:`Path`; or a scenario's name with ``alpha``.
    alpha : float, optional
        With a scenario's name: the path's angle (one angle, degrees).
    tolerance : float
        The verdict's bound on each quantity's ``max_error`` (relative to its range), in (0, 1].
    reference : Continuum, PathSolution or RateSolution, optional
        The exact reference: the continuum of the contact's adhesion law with its tolerances (default
        ``Continuum()``; under the rate-dependent law the run of ``simulate(method="continuum")``, its log's events
        those of the moving edge and of the springs on top), or its solution of this path, contact and tolerances if
        already at hand (:func:`~mdr_events.analysis.convergence_study.convergence_study`
        solves once for all spacings). ``tolerances=`` and ``solution=`` among the options say the same.
    limits : Limits
        What the continuum run may use (a measured path of more than ``limits.waypoints`` waypoints is
        refused unless raised).
    progress : callable, optional
        Hears how far reading a long CSV file is (:func:`~mdr_events.io.candidates.read_candidate`).
    **options
        How to read the candidate; beside a :class:`~mdr_events.Parameters` also ``profile`` and ``friction``:

        ``names``, ``units`` : mapping, optional
            Quantity -> your column name; quantity -> your unit (``"mN"``, ``"ms"``, ``"um"``, ...).
        ``time_origin`` : "first_contact", "path_start" or float
            What the candidate's time counts from: the first contact (default), the path's start, or a
            number: the candidate's time at first contact (s).
        ``select`` : mapping, optional
            A candidate holding several runs (a simulation along ``alpha``): the one at these coordinates;
            default ``{"alpha": alpha}`` with a scenario's angle.

    Returns
    -------
    xarray.Dataset
        Along ``time`` (the candidate's samples, s from first contact): ``candidate_<q>``, ``exact_<q>``,
        ``difference_<q>`` (``nan`` where left out), ``left_out`` (:data:`LEFT_OUT_CODES`); along
        ``quantity``: ``max_error``, ``rms_error``, ``l1_error``, ``within_tolerance``; along ``event``
        (:data:`VALIDATED_EVENTS`): the times and depths, exact and candidate, and their errors;
        ``pull_off_force_*``; the counts of samples compared and left out; the attribute ``verdict``
        (``"pass"``: every quantity *compared* within ``tolerance``), and ``quantities_not_compared`` and
        ``unused_columns`` (columns not named as a quantity: name them with ``names=`` to check them).
    """
    job = _validation_job(contact, motion, alpha, tolerance, reference, options)
    limits = check_limits(limits)
    check_callback("progress", progress, "a line of text")
    samples = _samples(job, candidate, limits, progress, tolerance)
    data = {"left_out": (("time",), samples.codes, {
        "units": "1", "long_name": "why a sample is left out", "flag_values": np.array(list(LEFT_OUT_CODES), dtype=np.int8),
        "flag_meanings": " ".join(m.replace(" ", "_") for m in LEFT_OUT_CODES.values())})}
    present = [name for name in COMPARED if name in samples.quantities]
    max_errors, left_out_errors, corner, change, scales = _norm_variables(data, samples, present, tolerance)
    differs = _contact_variable(data, samples)
    events, not_shown = _event_variables(data, samples, job)
    data["samples_compared"] = ((), int(np.count_nonzero(samples.compared)), {"units": "1",
                                                                              "long_name": "samples compared"})
    data["samples_left_out"] = ((), int(np.count_nonzero(samples.codes > 1)), {
        "units": "1", "long_name": "samples of the runs left out (contact differs, straddles an event)"})
    coords = {"time": ("time", samples.times, {"units": "s", "long_name": "time from first contact"}),
              "quantity": ("quantity", np.array(present), {"units": "1", "long_name": "quantity compared"}),
              "event": ("event", np.array(VALIDATED_EVENTS), {"units": "1", "long_name": "event compared"})}
    failures = validation_failures(ValidationMeasures(present, max_errors, differs, left_out_errors, corner, change,
                                                      events, scales), tolerance)
    verdict = Verdict.FAIL if failures else Verdict.PASS
    read, model = samples.read, job.model
    attrs = dict(content=VALIDATION_CONTENT, candidate_source=read.source, tolerance=float(tolerance),
                 unused_columns=", ".join(read.unused) or "none",
                 quantities_not_compared=", ".join(name for name in COMPARED if name not in present) or "none",
                 events_not_compared="; ".join(f"{name} ({why})" for name, why in not_shown.items()) or "none",
                 **text_list_attrs("failures", failures),
                 time_origin=str(job.time_origin), verdict=verdict.value, path_waypoints=job.path.describe(),
                 path_speed=job.path.speed, **profile_attrs(model.profile), **friction_attrs(model.friction),
                 **adhesion_attrs(model.adhesion))
    if not model.contact.layer.is_half_space:  # (the half-space stamps no layer: its reports are those of before)
        attrs.update(model.contact.layer.to_attrs())
    return stamp(xr.Dataset(data, coords=coords), model.params, **attrs)


class _Samples(NamedTuple):
    """A candidate read and set beside the exact solution at its times: its quantities, where it is in contact,
    each sample's ``left_out`` code and whether it is compared."""

    read: Candidate
    times: np.ndarray
    solution: PathSolution | RateSolution
    exact: dict[str, np.ndarray]
    quantities: dict[str, np.ndarray]
    contact: np.ndarray
    codes: np.ndarray
    compared: np.ndarray


def _samples(job: ValidationJob, candidate, limits: Limits, progress, tolerance: float) -> _Samples:
    """Read the candidate, refuse a run that cannot be judged (nothing to compare, not finite, never in contact, cut
    short in contact), solve the exact run (unless at hand) and sort the samples (a tangential force alone shows its
    contact where it is not 0 and where the exact one is within ``tolerance`` of 0:
    :func:`~mdr_events.analysis.samples.contact_of_tangential_force`)."""
    read = read_candidate(candidate, job.names, job.units, limits, select=job.select, progress=progress)
    limits.check(f"validating {read.time.size} samples of {read.where}",
                 memory=BYTES_PER_VALIDATED_SAMPLE * read.time.size)
    if not any(name in COMPARED for name in read.quantities):
        raise ValueError(f"{read.where}: none of {', '.join(COMPARED)} found (columns read: "
                         f"{', '.join(read.quantities)}); allowed: at least one of them (the sliding fraction alone "
                         "serves only the events)")
    check_run_is_finite(read, in_contact(read.quantities), job.names)
    times = times_from_contact(read, job.path, job.time_origin)
    solution = job.exact(limits)
    exact = exact_at(solution, times)
    quantities = dict(read.quantities)
    contact = in_contact(quantities)
    if not np.any(contact):
        raise ValueError(f"{read.where}: the candidate never touches (no sample in contact); allowed: a run "
                         "that makes contact")
    check_run_covers_the_contact(read, times, contact, solution, job.names)
    if not any(name in quantities for name in CONTACT_INDICATORS):
        contact = contact_of_tangential_force(contact, quantities["tangential_force"], exact, tolerance)
    codes, compared = compared_samples(read.where, times, exact, quantities, contact, solution)
    return _Samples(read, times, solution, exact, quantities, contact, codes, compared)


def _norm_variables(data: dict, samples: _Samples, present: list[str], tolerance: float
                    ) -> tuple[list[float], list[float], list[float], list[float], list[tuple[float, float]]]:
    """Per quantity: the candidate, the exact values and their difference along time, the norms, whether within
    ``tolerance``, the largest error of the samples left out, of those at a corner beyond the exact change there and
    of those where the contact differs beyond the exact values around them, and the candidate's scale on the exact
    (not stored: the report's candidate and exact values give it); returns the max errors, the left-out errors, the
    corners' excess, the contact changes' and the scales (factor, residual)."""
    norms = {"max_error": [], "rms_error": [], "l1_error": []}
    left_out_errors, excess, change, scales = [], [], [], []
    for name in present:
        candidate, exact = samples.quantities[name], samples.exact[name]
        scales.append(candidate_scale(candidate, exact, samples.compared))
        left_out_errors.append(left_out_error(candidate, exact, samples.codes, samples.compared))
        change.append(contact_change_excess(samples.times, candidate, exact, samples.codes, samples.compared,
                                            samples.solution.events))
        excess.append(corner_excess(samples.times, candidate, exact, samples.codes, samples.compared,
                                    samples.solution.events))
        difference = np.where(samples.compared, candidate - exact, np.nan)
        data[f"candidate_{name}"] = (("time",), candidate, {"units": UNITS[name], "long_name": f"candidate {name}"})
        data[f"exact_{name}"] = (("time",), exact, {"units": UNITS[name], "long_name": f"exact {name} (continuum)"})
        data[f"difference_{name}"] = (("time",), difference,
                                      {"units": UNITS[name], "long_name": f"candidate − exact {name}, compared samples"})
        for key, value in zip(norms, relative_norms(samples.times, np.nan_to_num(difference), exact, samples.compared)):
            norms[key].append(value)
    for key, values in norms.items():
        data[key] = (("quantity",), np.array(values), {"units": "1", "long_name": f"{key.replace('_', ' ')} relative "
                                                       "to the exact quantity's range over the compared samples"})
    within = np.array([value <= tolerance for value in norms["max_error"]], dtype=np.int8)
    data["within_tolerance"] = (("quantity",), within, {"units": "1", "long_name": "max_error <= tolerance (1: yes)"})
    data["left_out_max_error"] = (("quantity",), np.array(left_out_errors), {
        "units": "1", "long_name": f"max error of the samples left out (contact differs, straddles an event) relative to "
                                   f"the range; the verdict's bound: {LEFT_OUT_BOUND:g} (what an event's timing changes)"})
    data["corner_max_excess"] = (("quantity",), np.array(excess), {
        "units": "1", "long_name": "max error of a sample straddling a corner or a reversal beyond the exact change "
                                   "over the intervals beside it, relative to the range (the verdict's bound: "
                                   "tolerance)"})
    data["contact_change_max_excess"] = (("quantity",), np.array(change), {
        "units": "1", "long_name": "max error of a sample where one run is in contact and the other is not, or of one "
                                   "straddling a contact made, beyond the exact values around it and 0, relative to "
                                   "the range (the verdict's bound: tolerance)"})
    return norms["max_error"], left_out_errors, excess, change, scales


def _contact_variable(data: dict, samples: _Samples) -> float:
    """The share of the exact contact's time in contact in one run only or not sampled (a run with its start, middle
    or tail cut out, or blanked out with zeros). A tangential force alone shows the contact where it is not 0 and
    where the exact one is beyond the tolerance of 0 (:func:`~mdr_events.analysis.samples.contact_of_tangential_force`):
    its share counts those samples too."""
    uncovered = uncovered_share(samples.times, samples.solution)
    differs = uncovered + contact_differs_share(samples.times, samples.codes, samples.exact["contact_radius"] > 0)
    data["contact_differs_share"] = ((), differs, {"units": "1", "long_name": "time of the exact contact in contact in "
                                                   "one run only or not sampled, as a share of the exact contact's time "
                                                   "(the verdict's bound: tolerance; a tangential force alone shows "
                                                   "the contact where it is not 0 or the exact one is within the "
                                                   "tolerance of 0)"})
    return differs


def _event_variables(data: dict, samples: _Samples, job: ValidationJob) -> tuple[EventTimes, dict[str, str]]:
    """Each validated event's time and depth, exact and the candidate's, their errors (the time's also relative to
    the path's duration, where the candidate's quantities show the event), and the pull-off force; returns the
    events compared and those the candidate cannot show, with why."""
    paper_law = job.model.friction.is_default
    found = candidate_events(samples.times, samples.quantities, samples.contact, job.model.params, paper_law)
    not_shown = {**events_not_shown(samples.quantities), **samples.solution.events_not_timed}
    first = {}
    for event in samples.solution.events:
        first.setdefault("pull_off" if event.kind.value == "contact_ends" else event.kind.value, event)
    exact_times = np.array([first[kind].time if kind in first else math.nan for kind in VALIDATED_EVENTS])
    exact_depths = np.array([first[kind].depth if kind in first else math.nan for kind in VALIDATED_EVENTS])
    candidate_times = np.array([math.nan if kind in not_shown else found[kind] for kind in VALIDATED_EVENTS])
    start = job.path.first_contact_time()
    touching = np.flatnonzero(samples.contact)
    errors = event_time_errors(exact_times, candidate_times,
                               (samples.solution.end_time, job.path.duration - start),
                               (float(samples.times[touching[-1]]), float(samples.times[-1])), job.path.duration,
                               samples.times)
    errors[[kind in not_shown for kind in VALIDATED_EVENTS]] = math.nan
    candidate_depths = np.where(np.isfinite(candidate_times),
                                job.path.position(start + np.nan_to_num(candidate_times))[1], np.nan)
    for key, values, unit, text in (
            ("event_time_exact", exact_times, "s", "time of the event, continuum"),
            ("event_time_candidate", candidate_times, "s", "time of the event in the candidate (module rules)"),
            ("event_time_error", candidate_times - exact_times, "s", "candidate − exact event time"),
            ("event_depth_exact", exact_depths, "m", "depth at the event, continuum"),
            ("event_depth_candidate", candidate_depths, "m", "depth at the candidate's event"),
            ("event_depth_error", candidate_depths - exact_depths, "m", "candidate − exact event depth"),
            ("event_time_relative_error", errors, "1", "|candidate − exact| event time beyond the candidate's sample "
             "spacing there, relative to the path's duration; for an event in one run only, how long before the other "
             "stops showing it (the verdict's bound: tolerance; nan: not compared)")):
        data[key] = (("event",), values, {"units": unit, "long_name": text})
    pull = first.get("pull_off")
    exact_force = samples.solution.normal_force_at(pull) if pull else math.nan
    data["pull_off_force_exact"] = ((), exact_force, {"units": "N", "long_name": "F_N at the pull-off, continuum"})
    data["pull_off_force_candidate"] = ((), found["pull_off_force"],
                                        {"units": "N", "long_name": "F_N at the candidate's last sample in contact"})
    last = found["last_in_contact"]
    data["pull_off_force_exact_at_last_sample"] = (
        (), float(samples.exact["normal_force"][last]) if last >= 0 else math.nan,
        {"units": "N", "long_name": "exact F_N at the candidate's last sample in contact (F_N(t) is steep before the "
                                    "jump: compare with the candidate's there, not with the jump's)"})
    return EventTimes(VALIDATED_EVENTS, exact_times, candidate_times, errors), not_shown

register_schema(VALIDATION_CONTENT, {"left_out": ("time",), "max_error": ("quantity",), "rms_error": ("quantity",),
                                     "l1_error": ("quantity",), "within_tolerance": ("quantity",),
                                     "event_time_exact": ("event",), "event_time_candidate": ("event",)})
