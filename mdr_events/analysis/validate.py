"""Validate a discrete simulator — yours or ours — against the exact continuum: :func:`validate`.

The candidate (any program's output: :func:`mdr_events.io.candidates.read_candidate`) is compared
sample by sample with the continuum solution (:func:`mdr_events.models.continuum.solve_path`) evaluated
at the candidate's own times, and event by event with the continuum's event log. The report is an
``xarray.Dataset``.

Samples left out (``left_out``, coded, and counted):

- ``1`` outside the runs: after the end of either run (``nan``), not counted as left out;
- ``2`` contact differs: one method in contact and the other not. The jump-in and the jump-off are
  discontinuities in time that a discrete model meets up to one step (and one spring) apart, so a
  pointwise difference there is the whole jump however fine the model;
- ``3`` straddles an event: the first sample after a path corner (a time-stepping model moves
  straight from one sample to the next and cuts the corner) or a contact made or lost.

Norms over the samples compared in contact, each relative to the range (max − min) of the exact
quantity there: ``max_error`` (max |Δ|), ``rms_error`` (root mean square) and ``l1_error``
(time-weighted mean of |Δ|, trapezoid rule over the compared samples).

Events found in the candidate by these rules (``nan`` where the candidate lacks what a rule needs):

- **slip onset**: the first sample with ``sliding_fraction > 0``;
- **full slip**: the first sample with ``sliding_fraction >= 1``, or without a sliding fraction, with
  ``|F_x| >= (1 − FULL_SLIP_SHARE) τ0 A``;
- **start of detachment**: the first sample after the largest contact area (or radius) at which it is
  smaller than that largest value;
- **pull-off**: the first sample without contact after a contact (contact: ``A > 0``, or ``a > 0``, or
  ``F_N ≠ 0`` without either); its force is ``F_N`` of the last sample in contact, reported beside
  the exact force at the jump and the exact ``F_N`` at that same sample (``F_N(t)`` has an infinite
  slope at the jump, so a sampled force converges to the jump's only as ``sqrt(Δt)``).

Each is compared with the first event of that kind in the continuum's log (time and depth; the depth
of a candidate event is the path's depth at its time).
"""

from __future__ import annotations

import math
from typing import Any, Callable, Mapping, NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.reports import LEFT_OUT_BOUND, VALIDATION_CONTENT, Verdict, validation_failures
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.io.candidates import Candidate, check_run_is_finite, read_candidate
from mdr_events.theory.scales import check_representable
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.models.continuum import PathSolution, Tolerances, evaluate, solve_path
from mdr_events.contact import Contact
from mdr_events.models.indenters import SimulatedProfile, profile_attrs
from mdr_events.models.methods import Continuum
from mdr_events.models.motion import Paths
from mdr_events.models.simulate import ModelJob, model_job
from mdr_events.models.paths import Path
from mdr_events.models.motion import check_path_representable
from mdr_events.parameters import Parameters
from mdr_events.validation import check_real, shown
from mdr_events.contact.friction import friction_attrs

__all__ = ["validate", "DEFAULT_TOLERANCE", "contact_differs_share", "resolve_path", "times_from_contact", "candidate_events", "VALIDATION_CONTENT", "LEFT_OUT_CODES", "VALIDATED_EVENTS", "FULL_SLIP_SHARE"]

#: The ``content`` attribute of a validation report.
#: ``left_out`` codes -> meaning.
LEFT_OUT_CODES = {0: "compared", 1: "outside the runs", 2: "contact differs", 3: "straddles an event"}
#: Events compared, in the order of the report's ``event`` dimension.
VALIDATED_EVENTS = ("slip_onset", "full_slip", "detachment_starts", "pull_off")
#: A candidate without a sliding fraction is in full slip where |F_x| reaches this share below τ0 A.
FULL_SLIP_SHARE = 1e-3
#: Continuum events after which the first sample is left out (a corner cut, a contact made or lost).
STRADDLED_EVENTS = ("corner", "tangential_reversal", "first_contact", "re_contact", "pull_off", "contact_ends")
#: Of those, the events that end a contact.
CONTACT_ENDING_EVENTS = ("pull_off", "contact_ends")
#: The quantities that show where a run is in contact (``A > 0``, ``a > 0``, ``F_N ≠ 0``; :func:`_in_contact`).
CONTACT_INDICATORS = ("contact_area", "contact_radius", "normal_force")
#: Quantities compared sample by sample (the sliding fraction only serves the events).
COMPARED = ("normal_force", "tangential_force", "contact_area", "contact_radius")
UNITS = {"normal_force": "N", "tangential_force": "N", "contact_area": "m2", "contact_radius": "m"}
#: A candidate still in contact at its last sample must reach the exact run's end to this share.
TIME_AXIS_SHARE = 1e-3
#: A gap between a candidate's samples this many times their median spacing leaves the exact contact in it unsampled.
GAP_FACTOR = 10.0
#: The fewest samples of a candidate that must lie within the exact contact: fewer cannot show its curves (two
#: samples, or a time column in µs read as s, left one or two samples to compare, and a pass).
MIN_SAMPLES_IN_CONTACT = 10
#: The verdict's bound on each quantity's max error, relative to its range, unless given.
DEFAULT_TOLERANCE = 1e-3
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
            raise ValueError(f"time_origin={time_origin!r} is not allowed; allowed: {', '.join(map(repr, TIME_ORIGINS))} "
                             "or the candidate's time of first contact (s)")
        return candidate.time - (path.first_contact_time() if time_origin == "path_start" else 0.0)
    if isinstance(time_origin, bool) or not isinstance(time_origin, (int, float)) or not math.isfinite(time_origin):
        raise ValueError(f"time_origin={time_origin!r} is not allowed; allowed: {', '.join(map(repr, TIME_ORIGINS))} "
                         "or the candidate's time of first contact (s), a finite number")
    times = candidate.time - float(time_origin)
    if np.any(np.diff(times) <= 0):  # (1e300 s: every time rounds to the same number)
        raise ValueError(f"time_origin={time_origin!r} is not allowed: the times minus it are no longer distinct in "
                         "double precision; allowed: the candidate's time of first contact (s), of the size of its "
                         "times")
    return times


def _in_contact(quantities: Mapping[str, np.ndarray]) -> np.ndarray:
    """Where a run is in contact: ``A > 0``, else ``a > 0``, else ``F_N ≠ 0`` (``nan``: unknown, False)."""
    for name in ("contact_area", "contact_radius"):
        if name in quantities:
            return np.nan_to_num(quantities[name]) > 0
    return np.nan_to_num(quantities["normal_force"]) != 0 if "normal_force" in quantities else \
        np.nan_to_num(quantities["tangential_force"]) != 0


def _left_out(times: np.ndarray, exact: dict, candidate: dict, contact: np.ndarray, events) -> np.ndarray:
    codes = np.zeros(times.shape, dtype=np.int8)
    finite = np.all([np.isfinite(values) for name, values in candidate.items() if name in COMPARED], axis=0) & \
        np.isfinite(exact["contact_radius"])  # (the sliding fraction, nan out of contact, only serves the events)
    codes[~finite] = 1
    differs = finite & (contact != (exact["contact_radius"] > 0))
    codes[differs] = 2
    out_of_contact = ~contact & ~(exact["contact_radius"] > 0)
    for event in events:
        if event.kind.value in STRADDLED_EVENTS:
            after = int(np.searchsorted(times, event.time, side="left"))
            if after < len(times) and times[after] > event.time and codes[after] == 0 and after > 0 and \
                    not (event.kind.value in CONTACT_ENDING_EVENTS and out_of_contact[after]):
                codes[after] = 3  # (after a pull-off both runs out of contact are compared: every force 0)
    return codes


def _exact_at(solution: PathSolution, times: np.ndarray) -> dict[str, np.ndarray]:
    """The exact quantities at the candidate's times (s from first contact): 0 before the contact, and after a run
    that ended by coming apart (the indenter stays out, as a candidate that keeps writing shows)."""
    exact = evaluate(solution, np.maximum(times, 0.0))
    after = (times > solution.end_time) if solution.ended_by_contact else np.zeros(times.shape, bool)
    for name in ("normal_force", "tangential_force", "contact_radius"):
        exact[name][(times < 0) | after] = 0.0
    exact["contact_area"] = math.pi * exact["contact_radius"] ** 2
    return exact


def _compared_samples(source: str, times: np.ndarray, exact: dict, quantities: dict, contact: np.ndarray,
                      solution: PathSolution) -> tuple[np.ndarray, np.ndarray]:
    """Each sample's ``left_out`` code and whether it is compared: both runs in contact, or both out of it (every
    force, the radius and the area 0 there); at least :data:`MIN_SAMPLES_IN_CONTACT` inside the exact contact."""
    codes = _left_out(times, exact, quantities, contact, solution.events)
    exact_contact = exact["contact_radius"] > 0
    inside = int(np.count_nonzero((codes == 0) & exact_contact & contact))
    if inside < MIN_SAMPLES_IN_CONTACT:
        raise ValueError(f"{source}: {inside} samples of the candidate are in contact while the exact run is (its "
                         f"time runs {times[0]:.6g}…{times[-1]:.6g} s from first contact, the exact contact "
                         f"0…{solution.end_time:.6g} s); allowed: at least {MIN_SAMPLES_IN_CONTACT}: check the time "
                         "column's unit and time_origin")
    return codes, (codes == 0) & ((exact_contact & contact) | (~exact_contact & ~contact))


def _check_run_covers_the_contact(read: Candidate, times: np.ndarray, contact: np.ndarray, solution: PathSolution,
                                  names: Mapping[str, str] | None) -> None:
    """Refuse a run that stops while it is in contact and the exact contact goes on past its next sample: its time
    axis ends there, or a column's values do (``nan`` from there on: a run cut short, not one to pass)."""
    names = dict(names or {})
    ends = {names.get("time", "time"): len(times) - 1}
    for quantity, values in read.quantities.items():
        finite = np.flatnonzero(np.isfinite(values))
        if quantity in COMPARED and finite.size and finite[-1] < len(times) - 1:
            ends[names.get(quantity, quantity)] = int(finite[-1])
    for column, last in ends.items():
        if contact[last] and times[last] < solution.end_time * (1.0 - TIME_AXIS_SHARE) and \
                not _contact_ends_within_a_step(solution, times[:last + 1]):
            where = (f"ends at {times[last]:.6g} s from first contact" if last == len(times) - 1 else
                     f"is nan from row {last + 2} on (after {times[last]:.6g} s from first contact)")
            raise ValueError(f"{read.source}: column {column!r} {where}, in contact, while the exact contact lasts "
                             "beyond its next sample; allowed: values that cover the contact up to the run's last "
                             f"sample in contact (the exact run lasts {solution.end_time:.6g} s)")


def contact_differs_share(times: np.ndarray, codes: np.ndarray, exact_contact: np.ndarray) -> float:
    """The time during which one run is in contact and the other is not (``left_out`` code 2), as a share of the
    time the exact run is in contact, both measured on the candidate's samples (each sample stands for half the
    intervals on either side). A run cut short, or blanked out with zeros, is in contact for less: its samples
    there were left out of the norms, and it passed."""
    if times.size < 2:
        return 0.0
    gaps = np.diff(times)
    weights = 0.5 * (np.append(gaps, 0.0) + np.insert(gaps, 0, 0.0))
    inside = float(np.sum(weights[exact_contact]))
    return float(np.sum(weights[codes == 2]) / inside) if inside > 0 else 0.0


def uncovered_share(times: np.ndarray, solution: PathSolution) -> float:
    """The exact contact's time the candidate does not sample, as a share of it: before its first sample (a run whose
    start is cut off), and inside gaps longer than :data:`GAP_FACTOR` times its median spacing (a run with its middle
    cut out); the exact contact taken as ``[0, end_time]`` from first contact."""
    end = solution.end_time
    if not end > 0.0 or times.size < 2:
        return 0.0
    gaps = np.diff(times)
    wide = gaps > GAP_FACTOR * float(np.median(gaps))
    starts, stops = np.append(-np.inf, times[:-1][wide]), np.append(times[0], times[1:][wide])
    overlap = np.clip(np.minimum(stops, end) - np.maximum(starts, 0.0), 0.0, None)
    return float(np.sum(overlap)) / end


def _left_out_error(candidate: np.ndarray, exact: np.ndarray, codes: np.ndarray, compared: np.ndarray) -> float:
    """The largest difference of the samples left out for a contact that differs or an event they straddle, relative
    to the exact quantity's range over the compared samples (0 if none)."""
    left = (codes >= 2) & np.isfinite(candidate)
    if not np.any(left) or not np.any(compared):
        return 0.0
    return float(np.max(np.abs(candidate[left] - exact[left]))) / _spread(exact, compared)


def _contact_ends_within_a_step(solution: PathSolution, times: np.ndarray) -> bool:
    """Whether the exact contact has ended by the candidate's next sample (its last time plus its last spacing): a
    simulator that stops writing at its last sample in contact (the pull-off) covers the contact."""
    following = float(times[-1] + (times[-1] - times[-2])) if len(times) > 1 else float(times[-1])
    if following >= solution.end_time:
        return True
    return not float(evaluate(solution, np.array([max(following, 0.0)]))["contact_radius"][0]) > 0.0


def _spread(exact: np.ndarray, compared: np.ndarray) -> float:
    """The exact quantity's range over the compared samples (its largest magnitude if flat, else 1): what every
    error of it is relative to."""
    e = exact[compared]
    return float(np.max(e) - np.min(e)) or float(np.max(np.abs(e))) or 1.0


def _norms(times, difference, exact, compared) -> tuple[float, float, float]:
    """max, RMS and time-weighted L1 of the difference over the compared samples, each relative to the
    exact quantity's range there."""
    if not np.any(compared):
        return math.nan, math.nan, math.nan
    d, t = difference[compared], times[compared]
    spread = _spread(exact, compared)
    l1 = float(np.trapezoid(np.abs(d), t) / (t[-1] - t[0])) if t.size > 1 else float(abs(d[0]))
    return float(np.max(np.abs(d))) / spread, float(np.sqrt(np.mean(d**2))) / spread, l1 / spread


def candidate_events(times, quantities, contact, params) -> dict[str, float]:
    """Times of the events by the module's rules (times as given; also ``pull_off_force`` and
    ``last_in_contact``, the index of the last sample in contact, -1 if none) (``nan`` where not found or not determinable)."""
    out = {name: math.nan for name in VALIDATED_EVENTS}
    out["pull_off_force"] = math.nan
    out["last_in_contact"] = -1
    sliding = quantities.get("sliding_fraction")
    if sliding is not None:
        onset = np.flatnonzero(np.nan_to_num(sliding) > 0)
        full = np.flatnonzero(np.nan_to_num(sliding) >= 1)
        out["slip_onset"] = float(times[onset[0]]) if onset.size else math.nan
        out["full_slip"] = float(times[full[0]]) if full.size else math.nan
    elif "tangential_force" in quantities and ("contact_area" in quantities or "contact_radius" in quantities):
        area = quantities.get("contact_area", math.pi * quantities.get("contact_radius", np.nan) ** 2)
        full = np.flatnonzero((area > 0) & (np.abs(quantities["tangential_force"])
                                            >= (1 - FULL_SLIP_SHARE) * params.tau0 * area))
        out["full_slip"] = float(times[full[0]]) if full.size else math.nan
    size = quantities.get("contact_area", quantities.get("contact_radius"))
    if size is not None and np.any(np.isfinite(size)):
        largest = int(np.nanargmax(size))
        smaller = np.flatnonzero(np.nan_to_num(size[largest:], nan=np.inf) < size[largest])
        out["detachment_starts"] = float(times[largest + smaller[0]]) if smaller.size else math.nan
    lost = np.flatnonzero(contact[:-1] & ~contact[1:])
    if lost.size:
        out["pull_off"] = float(times[lost[0] + 1])
        out["last_in_contact"] = int(lost[0])
        if "normal_force" in quantities:
            out["pull_off_force"] = float(quantities["normal_force"][lost[0]])
    return out


def reference_of(reference, tolerances, solution) -> tuple[PathSolution | None, Tolerances]:
    """The solution at hand (or ``None``) and the tolerances of the exact reference: ``reference`` (a
    :class:`~mdr_events.Continuum` or a solution), or the keywords of before (``tolerances=``, ``solution=``)."""
    given = [name for name, value in (("reference", reference), ("tolerances", tolerances), ("solution", solution))
             if value is not None]
    if len(given) > 1:
        raise ValueError(f"{' and '.join(given)} are not allowed together; allowed: one of them")
    if isinstance(reference, PathSolution) or solution is not None:
        found = reference if solution is None else solution
        if not isinstance(found, PathSolution):
            raise TypeError(f"solution={shown(found)} ({type(found).__name__}) is not allowed; allowed: a PathSolution")
        return found, Tolerances()  # (the tolerances serve a solve, and there is none)
    if reference is not None and not isinstance(reference, Continuum):
        raise TypeError(f"reference={shown(reference)} ({type(reference).__name__}) is not allowed; allowed: a "
                        "Continuum (its tolerances) or a PathSolution")
    if tolerances is not None and not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances={shown(tolerances)} ({type(tolerances).__name__}) is not allowed; allowed: a "
                        "Tolerances")
    return None, (reference.tolerances if reference is not None else tolerances or Tolerances())


def one_path(job: ModelJob) -> tuple[Path, float | None]:
    """The one path a candidate ran (its motion must have one case) and its angle (``None``: a custom path)."""
    if isinstance(job.motion, Paths):
        label, path = next(iter(job.motion.paths.items()))
        if len(job.motion.paths) != 1:
            raise ValueError(f"motion holds {len(job.motion.paths)} paths; allowed: the one the candidate ran")
        check_path_representable(job.params, path, "path", job.profile, job.friction)
        return path, None
    if len(job.motion.alpha) != 1:
        raise ValueError(f"motion={job.motion!r} holds {len(job.motion.alpha)} angles; allowed: the one the candidate "
                         "ran")
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
    solution: PathSolution | None
    tolerances: Tolerances


def one_path_job(contact, motion, alpha, options: dict[str, Any]) -> ModelJob:
    """:func:`~mdr_events.models.simulate.model_job` of a motion of one path (a scenario's name needs one angle;
    :func:`one_path` checks a Scenario's or Paths')."""
    if isinstance(motion, str) and (alpha is None or np.ndim(alpha) != 0):  # (a scenario of several angles)
        raise ValueError(f"alpha={alpha!r} is not allowed with scenario {motion!r}; allowed: one angle in degrees")
    return model_job(contact, motion, alpha, options)


def _validation_job(contact, motion, alpha, tolerance, reference, options: Mapping[str, Any],
                    caller: str = "validate") -> ValidationJob:
    """The job of ``validate(candidate, contact, motion, alpha, tolerance=, reference=, **options)``, every argument
    checked (the keywords of before converted by :func:`~mdr_events.models.simulate.model_job`)."""
    options = dict(options)
    names, units, select = (options.pop(name, None) for name in ("names", "units", "select"))
    time_origin = options.pop("time_origin", "first_contact")
    solution, tolerances = reference_of(reference, options.pop("tolerances", None), options.pop("solution", None))
    model = one_path_job(contact, motion, alpha, options)
    if options:
        raise TypeError(f"{caller}() got an unexpected keyword argument {next(iter(options))!r}; allowed: names, "
                        "units, time_origin, select (and profile, friction beside a Parameters)")
    check_real("tolerance", tolerance, "a number in (0, 1] (the largest error relative to the quantity's range: "
               "above 1 every run would pass)", lambda value: 0 < value <= 1)
    check_representable(model.params, model.profile, model.friction)
    for name in ("profile", "friction"):
        if solution is not None and getattr(solution.model, name) != getattr(model, name):
            raise ValueError(f"solution= was solved for {name}={getattr(solution.model, name)!r}, not for "
                             f"{name}={getattr(model, name)!r}; allowed: a solution of this "
                             f"{'indenter' if name == 'profile' else 'friction law'}")
    path, angle = one_path(model)
    if select is None and angle is not None:
        select = {"alpha": angle}
    return ValidationJob(model, path, names, units, time_origin, select, solution, tolerances)


def validate(candidate, contact: Contact | Parameters, motion, alpha: float | None = None, *,
             tolerance: float = DEFAULT_TOLERANCE, reference: Continuum | PathSolution | None = None,
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
        one path or a :class:`Path`; or a scenario's name with ``alpha`` (one angle, degrees).
    tolerance : float
        The verdict's bound on each quantity's ``max_error`` (relative to its range), in (0, 1].
    reference : Continuum or PathSolution, optional
        The exact reference: the continuum with its tolerances (default ``Continuum()``), or its solution of this
        path, contact and tolerances if already at hand (:func:`~mdr_events.analysis.convergence_study.convergence_study`
        solves once for all spacings). ``tolerances=`` and ``solution=`` among the options say the same.
    limits : Limits
        What the continuum run may use (a measured path of more than ``limits.waypoints`` waypoints is
        refused unless raised).
    progress : callable, optional
        Hears how far reading a long CSV file is (:func:`~mdr_events.io.candidates.read_candidate`).
    **options
        How to read the candidate: ``names``, ``units``, ``time_origin``, ``select`` (below); beside a
        :class:`~mdr_events.Parameters` also ``profile`` and ``friction``.
    names, units : mapping, optional
        Quantity -> your column name; quantity -> your unit (``"mN"``, ``"ms"``, ``"um"``, ...).
    time_origin : "first_contact", "path_start" or float
        What the candidate's time counts from: the first contact (default), the path's start, or a
        number: the candidate's time at first contact (s).
    select : mapping, optional
        A candidate holding several runs (a simulation along ``alpha``): the one at these coordinates; default
        ``{"alpha": alpha}`` with a scenario's angle.

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
    params, profile, friction, the_path = job.model.params, job.model.profile, job.model.friction, job.path
    names, units, time_origin, select, solution = job.names, job.units, job.time_origin, job.select, job.solution
    read = read_candidate(candidate, names, units, limits, select=select, progress=progress)
    if not any(name in COMPARED for name in read.quantities):
        raise ValueError(f"{read.source}: none of {', '.join(COMPARED)} found (columns read: "
                         f"{', '.join(read.quantities)}); allowed: at least one of them (the sliding fraction alone "
                         "serves only the events)")
    check_run_is_finite(read, _in_contact(read.quantities), names)
    times = times_from_contact(read, the_path, time_origin)
    solution = solve_path(params, the_path, job.tolerances, limits, profile, friction) if solution is None else solution
    exact = _exact_at(solution, times)
    quantities = {name: values for name, values in read.quantities.items()}
    contact = _in_contact(quantities)
    if not np.any(contact):
        raise ValueError(f"{read.source}: the candidate never touches (no sample in contact); allowed: a run "
                         "that makes contact")
    _check_run_covers_the_contact(read, times, contact, solution, names)
    codes, compared = _compared_samples(read.source, times, exact, quantities, contact, solution)

    data = {"left_out": (("time",), codes, {"units": "1", "long_name": "why a sample is left out",
                                            "flag_values": np.array(list(LEFT_OUT_CODES), dtype=np.int8),
                                            "flag_meanings": " ".join(m.replace(" ", "_")
                                                                      for m in LEFT_OUT_CODES.values())})}
    present = [name for name in COMPARED if name in quantities]
    norms = {"max_error": [], "rms_error": [], "l1_error": []}
    left_out_errors = []
    for name in present:
        left_out_errors.append(_left_out_error(quantities[name], exact[name], codes, compared))
        difference = np.where(compared, quantities[name] - exact[name], np.nan)
        data[f"candidate_{name}"] = (("time",), quantities[name], {"units": UNITS[name], "long_name": f"candidate {name}"})
        data[f"exact_{name}"] = (("time",), exact[name], {"units": UNITS[name], "long_name": f"exact {name} (continuum)"})
        data[f"difference_{name}"] = (("time",), difference,
                                      {"units": UNITS[name], "long_name": f"candidate − exact {name}, compared samples"})
        for key, value in zip(norms, _norms(times, np.nan_to_num(difference), exact[name], compared)):
            norms[key].append(value)
    for key, values in norms.items():
        data[key] = (("quantity",), np.array(values), {"units": "1", "long_name": f"{key.replace('_', ' ')} relative "
                                                       "to the exact quantity's range over the compared samples"})
    within = np.array([value <= tolerance for value in norms["max_error"]], dtype=np.int8)
    data["within_tolerance"] = (("quantity",), within, {"units": "1", "long_name": "max_error <= tolerance (1: yes)"})
    data["left_out_max_error"] = (("quantity",), np.array(left_out_errors), {
        "units": "1", "long_name": f"max error of the samples left out (contact differs, straddles an event) relative to "
                                   f"the range; the verdict's bound: {LEFT_OUT_BOUND:g} (what an event's timing changes)"})
    # (a tangential force alone does not say where a run is in contact: it may be 0 in contact, so no share then)
    differs = contact_differs_share(times, codes, exact["contact_radius"] > 0) + uncovered_share(times, solution) \
        if any(name in quantities for name in CONTACT_INDICATORS) else math.nan
    data["contact_differs_share"] = ((), differs, {"units": "1", "long_name": "time of the exact contact in contact in "
                                                   "one run only or not sampled, as a share of the exact contact's time "
                                                   "(the verdict's bound: tolerance; nan: a tangential force alone does "
                                                   "not show the contact)"})

    found = candidate_events(times, quantities, contact, params)
    first = {}
    for event in solution.events:
        kind = "pull_off" if event.kind.value == "contact_ends" else event.kind.value
        first.setdefault(kind, event)
    exact_times = np.array([first[kind].time if kind in first else math.nan for kind in VALIDATED_EVENTS])
    exact_depths = np.array([first[kind].depth if kind in first else math.nan for kind in VALIDATED_EVENTS])
    candidate_times = np.array([found[kind] for kind in VALIDATED_EVENTS])
    start = the_path.first_contact_time()
    candidate_depths = np.where(np.isfinite(candidate_times),
                                the_path.position(start + np.nan_to_num(candidate_times))[1], np.nan)
    for key, values, unit, text in (
            ("event_time_exact", exact_times, "s", "time of the event, continuum"),
            ("event_time_candidate", candidate_times, "s", "time of the event in the candidate (module rules)"),
            ("event_time_error", candidate_times - exact_times, "s", "candidate − exact event time"),
            ("event_depth_exact", exact_depths, "m", "depth at the event, continuum"),
            ("event_depth_candidate", candidate_depths, "m", "depth at the candidate's event"),
            ("event_depth_error", candidate_depths - exact_depths, "m", "candidate − exact event depth")):
        data[key] = (("event",), values, {"units": unit, "long_name": text})
    pull = first.get("pull_off")
    exact_force = float(solution.model.normal_force(pull.depth, pull.radius)) if pull else math.nan
    data["pull_off_force_exact"] = ((), exact_force, {"units": "N", "long_name": "F_N at the pull-off, continuum"})
    data["pull_off_force_candidate"] = ((), found["pull_off_force"],
                                        {"units": "N", "long_name": "F_N at the candidate's last sample in contact"})
    last = found["last_in_contact"]
    data["pull_off_force_exact_at_last_sample"] = (
        (), float(exact["normal_force"][last]) if last >= 0 else math.nan,
        {"units": "N", "long_name": "exact F_N at the candidate's last sample in contact (F_N(t) is steep before the "
                                    "jump: compare with the candidate's there, not with the jump's)"})
    data["samples_compared"] = ((), int(np.count_nonzero(compared)), {"units": "1", "long_name": "samples compared"})
    data["samples_left_out"] = ((), int(np.count_nonzero(codes > 1)),
                                {"units": "1", "long_name": "samples of the runs left out (contact differs, straddles an event)"})
    coords = {"time": ("time", times, {"units": "s", "long_name": "time from first contact"}),
              "quantity": ("quantity", np.array(present), {"units": "1", "long_name": "quantity compared"}),
              "event": ("event", np.array(VALIDATED_EVENTS), {"units": "1", "long_name": "event compared"})}
    verdict = Verdict.FAIL if validation_failures(present, norms["max_error"], differs, left_out_errors, tolerance) \
        else Verdict.PASS
    not_compared = [name for name in COMPARED if name not in quantities]
    attrs = dict(content=VALIDATION_CONTENT, candidate_source=read.source, tolerance=float(tolerance),
                 unused_columns=", ".join(read.unused) or "none",
                 quantities_not_compared=", ".join(not_compared) or "none",
                 time_origin=str(time_origin), verdict=verdict.value, path_waypoints=the_path.describe(),
                 path_speed=the_path.speed)
    attrs.update(profile_attrs(profile))
    attrs.update(friction_attrs(friction))
    return stamp(xr.Dataset(data, coords=coords), params, **attrs)


register_schema(VALIDATION_CONTENT, {"left_out": ("time",), "max_error": ("quantity",), "rms_error": ("quantity",),
                                     "l1_error": ("quantity",), "within_tolerance": ("quantity",),
                                     "event_time_exact": ("event",), "event_time_candidate": ("event",)})
