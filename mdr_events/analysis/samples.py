"""The samples of a validation: where each run is in contact, which samples are compared and why the others are
left out, the norms of the differences, and the events read off a candidate's samples (:func:`candidate_events`).

Samples left out (``left_out``, coded, and counted):

- ``1`` outside the runs: after the end of either run (``nan``), not counted as left out;
- ``2`` contact differs: one method in contact and the other not. The jump-in and the jump-off are
  discontinuities in time that a discrete model meets up to one step (and one spring) apart, so a
  pointwise difference there is the whole jump however fine the model;
- ``3`` straddles an event: the first sample after a path corner (a time-stepping model moves
  straight from one sample to the next and cuts the corner) or a contact made or lost.

Norms over the samples compared in contact, each relative to the range (max − min) of the exact
quantity there: ``max_error`` (max ``|Δ|``), ``rms_error`` (root mean square) and ``l1_error``
(time-weighted mean of ``|Δ|``, trapezoid rule over the compared samples).

Events found in the candidate by these rules (``nan`` where the candidate lacks what a rule needs):

- **slip onset**: the first sample with ``sliding_fraction > SLIDING_SHARE`` (:func:`sliding`);
- **full slip**: the first sample with ``sliding_fraction >= 1 − SLIDING_SHARE`` (:func:`sliding`) but one that makes
  a contact and is followed in contact by partial slip (an adhesive contact made under Coulomb's law slides fully
  for that instant only: every spring is in tension), or without a sliding fraction, with
  ``|F_x| >= (1 − FULL_SLIP_SHARE) τ0 A``;
- **start of detachment**: the first sample after the largest contact area (or radius) at which it is
  smaller than that largest value by more than :data:`DETACHMENT_SHARE` of it (a pinned radius's round-off is no
  detachment);
- **pull-off**: the first sample without contact after a contact (contact: ``A > 0``, or ``a > 0``, or
  ``F_N ≠ 0`` without either); its force is ``F_N`` of the last sample in contact, reported beside
  the exact force at the jump and the exact ``F_N`` at that same sample (``F_N(t)`` has an infinite
  slope at the jump, so a sampled force converges to the jump's only as ``sqrt(Δt)``).
"""

from __future__ import annotations

import math
from typing import Mapping, NamedTuple

import numpy as np

from mdr_events.io.candidates import Candidate
from mdr_events.models.continuum import PathSolution
from mdr_events.models.continuum.rate_reference import RateSolution

#: An exact solution as a referee reads it (``evaluate_at``, ``events``, ``end_time``, ``ended_by_contact``).
ExactSolution = PathSolution | RateSolution

__all__ = ["in_contact", "exact_at", "compared_samples", "check_run_covers_the_contact", "contact_differs_share",
           "uncovered_share", "left_out_error", "corner_excess", "CONTINUOUS_EVENTS", "exact_range", "relative_norms",
           "candidate_events", "LEFT_OUT_CODES", "VALIDATED_EVENTS", "CONTACT_MAKING_EVENTS", "events_not_shown",
           "event_time_errors", "FULL_SLIP_SHARE", "SLIDING_SHARE", "Sliding", "sliding", "COMPARED", "UNITS",
           "CONTACT_INDICATORS", "MIN_SAMPLES_IN_CONTACT", "contact_of_tangential_force", "DETACHMENT_SHARE",
           "GAP_FACTOR", "TIME_AXIS_SHARE", "ExactSolution"]


#: ``left_out`` codes -> meaning.
LEFT_OUT_CODES = {0: "compared", 1: "outside the runs", 2: "contact differs", 3: "straddles an event"}
#: Events compared, in the order of the report's ``event`` dimension.
VALIDATED_EVENTS = ("first_contact", "slip_onset", "full_slip", "detachment_starts", "pull_off", "re_contact")
#: Of those, the events that make a contact (the others happen in contact).
CONTACT_MAKING_EVENTS = ("first_contact", "re_contact")
#: A candidate without a sliding fraction is in full slip where ``|F_x|`` reaches this share below τ0 A.
FULL_SLIP_SHARE = 1e-3
#: A sample slides where its sliding fraction exceeds this share, and slides fully within it of 1. One spring of a
#: discrete model is 1/N of the contact (N <= 1e7 springs by the default limits), so a slip zone it resolves shows;
#: a zone the exact solution holds at round-off does not (under Coulomb's law the spring at the edge of a growing
#: contact has a zero compression and cap, and a vertical indentation's zone is that one spring: 4e-16 of the
#: contact, not a slip onset).
SLIDING_SHARE = 1e-9
#: The start of detachment is read where the contact's size falls below its largest by more than this share of it: a
#: radius or area held on a pinned branch wobbles at its simulator's round-off (an area summed in another order, a
#: radius solved again each step: 1e-16 to 1e-10 of it), and a wobble of one ulp after the largest sample started the
#: detachment there, 5 % of the path early (a right run failed by 47 tolerances); a spring model's least fall is one
#: spring's ring, 2 dx / a (1e-3 and more).
DETACHMENT_SHARE = 1e-9
#: Continuum events after which the first sample is left out (a corner cut, a contact made or lost).
STRADDLED_EVENTS = ("corner", "tangential_reversal", "first_contact", "re_contact", "pull_off", "contact_ends")
#: Of those, the events that end a contact.
CONTACT_ENDING_EVENTS = ("pull_off", "contact_ends")
#: The quantities that show where a run is in contact (``A > 0``, ``a > 0``, ``F_N ≠ 0``; :func:`in_contact`).
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


def in_contact(quantities: Mapping[str, np.ndarray]) -> np.ndarray:
    """Where a run is in contact: ``A > 0``, else ``a > 0``, else ``F_N ≠ 0`` (``nan``: unknown, False)."""
    for name in ("contact_area", "contact_radius"):
        if name in quantities:
            return np.nan_to_num(quantities[name]) > 0
    return np.nan_to_num(quantities["normal_force"]) != 0 if "normal_force" in quantities else \
        np.nan_to_num(quantities["tangential_force"]) != 0


def contact_of_tangential_force(contact: np.ndarray, tangential_force: np.ndarray, exact: dict,
                                tolerance: float) -> np.ndarray:
    """Where a candidate that shows only its tangential force is in contact: where ``F_x ≠ 0``
    (:func:`in_contact`), and also where it reads 0 while the exact run is in contact and either the exact ``F_x`` is
    within ``tolerance`` of its range of 0 (no tangential load: scenario B's vertical stroke, a reversal) or the
    candidate's ``F_x`` is not 0 on both sides (a sample dropped out of its contact, not a contact made or lost at
    another time: its pull-off would show it, and a tangential force alone shows none). A 0 at the ends of its
    contact where the exact ``F_x`` is beyond the tolerance is a contact lost, as for any other quantity: it counts in
    :func:`contact_differs_share`. Before, every 0 was read as out of contact and left out (``left_out`` code 2)
    with no share counted: a run whose ``F_x`` was 0 over a third of the path passed."""
    exact_contact = exact["contact_radius"] > 0
    force = exact["tangential_force"]
    unloaded = np.abs(np.nan_to_num(force)) <= tolerance * exact_range(force, exact_contact)
    loaded = np.flatnonzero(contact)
    within = np.zeros(contact.shape, dtype=bool)
    if loaded.size:
        within[loaded[0]:loaded[-1] + 1] = True
    return contact | (exact_contact & (unloaded | within) & (np.nan_to_num(tangential_force) == 0))


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


def exact_at(solution: ExactSolution, times: np.ndarray) -> dict[str, np.ndarray]:
    """The exact quantities at the candidate's times (s from first contact): 0 before the contact, and after a run
    that ended by coming apart (the indenter stays out, as a candidate that keeps writing shows)."""
    exact = solution.evaluate_at(np.maximum(times, 0.0))
    after = (times > solution.end_time) if solution.ended_by_contact else np.zeros(times.shape, bool)
    for name in ("normal_force", "tangential_force", "contact_radius"):
        exact[name][(times < 0) | after] = 0.0
    exact["contact_area"] = math.pi * exact["contact_radius"] ** 2
    return exact


def compared_samples(source: str, times: np.ndarray, exact: dict, quantities: dict, contact: np.ndarray,
                      solution: ExactSolution) -> tuple[np.ndarray, np.ndarray]:
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


def check_run_covers_the_contact(read: Candidate, times: np.ndarray, contact: np.ndarray, solution: ExactSolution,
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
            raise ValueError(f"{read.where}: column {column!r} {where}, in contact, while the exact contact lasts "
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


def uncovered_share(times: np.ndarray, solution: ExactSolution) -> float:
    """The exact contact's time the candidate does not sample, as a share of it: before its first sample (a run whose
    start is cut off), inside gaps longer than :data:`GAP_FACTOR` times its median spacing within the exact contact
    (a run with its middle cut out; rows spaced widely out of contact do not widen what counts as a gap), and after
    its last sample (a tail cut off); the exact contact taken as ``[0, end_time]`` from first contact."""
    end = solution.end_time
    if not end > 0.0 or times.size < 2:
        return 0.0
    gaps = np.diff(times)
    inside = (times[:-1] >= 0.0) & (times[1:] <= end)
    typical = float(np.median(gaps[inside])) if np.count_nonzero(inside) >= 2 else 0.0
    wide = gaps > GAP_FACTOR * typical
    starts = np.concatenate([[-np.inf], times[:-1][wide], [times[-1]]])
    stops = np.concatenate([[times[0]], times[1:][wide], [np.inf]])
    # (the tail: up to the candidate's next sample it is covered, as for a run that stops writing at its pull-off)
    starts[-1] = times[-1] + (gaps[-1] if gaps[-1] <= GAP_FACTOR * typical else 0.0)
    overlap = np.clip(np.minimum(stops, end) - np.maximum(starts, 0.0), 0.0, None)
    return float(np.sum(overlap)) / end


#: Continuum events at which the curves keep their value (a corner of the path, a reversal of its tangential motion):
#: a sample straddling one differs from the exact by what a step cuts off, not by a jump.
CONTINUOUS_EVENTS = ("corner", "tangential_reversal")


def corner_excess(times: np.ndarray, candidate: np.ndarray, exact: np.ndarray, codes: np.ndarray,
                  compared: np.ndarray, events) -> float:
    """The largest difference of a sample straddling a corner or a reversal (``left_out`` code 3) beyond the exact
    quantity's change over the intervals beside it (what cutting the corner can change), relative to the exact
    quantity's range over the compared samples (0 if none): a spike there was bounded only by one range."""
    if not np.any(compared):
        return 0.0
    worst = 0.0
    for event in events:
        if event.kind.value not in CONTINUOUS_EVENTS:
            continue
        k = int(np.searchsorted(times, event.time, side="left"))
        if not (0 < k < len(times) and codes[k] == 3 and np.isfinite(candidate[k])):
            continue
        neighbours = exact[max(k - 1, 0):min(k + 2, len(times))]
        change = float(np.max(neighbours) - np.min(neighbours))
        worst = max(worst, abs(float(candidate[k] - exact[k])) - change)
    return worst / exact_range(exact, compared)


def contact_change_excess(times: np.ndarray, candidate: np.ndarray, exact: np.ndarray, codes: np.ndarray,
                          compared: np.ndarray, events) -> float:
    """The largest difference of a sample where one run is in contact and the other is not (``left_out`` code 2), or
    of one straddling a contact made or lost (code 3: the first contact, a re-contact, a pull-off, a contact's end),
    beyond the exact values around it, relative to the exact quantity's range over the compared samples (0 if none).

    A contact made or lost a little earlier or later than the exact one moves the jump between the values on either
    side of it: each stretch of such samples, ``i…j``, lies within the exact values over ``i-1…j+1`` and 0 (the
    value of every compared quantity out of contact). A spike there was bounded by one range only
    (:data:`~mdr_events.analysis.reports.LEFT_OUT_BOUND`): a first sample of 0.9 times the peak force passed.
    """
    judged = codes == 2
    for event in events:
        if event.kind.value in STRADDLED_EVENTS and event.kind.value not in CONTINUOUS_EVENTS:
            k = int(np.searchsorted(times, event.time, side="left"))
            if 0 < k < len(times) and codes[k] == 3:
                judged[k] = True
    stretch = np.flatnonzero(judged & np.isfinite(candidate))
    if not stretch.size or not np.any(compared):
        return 0.0
    worst = 0.0
    for part in np.split(stretch, np.flatnonzero(np.diff(stretch) > 1) + 1):
        around = exact[max(int(part[0]) - 1, 0):int(part[-1]) + 2]
        around = np.append(around[np.isfinite(around)], 0.0)
        values = candidate[part]
        worst = max(worst, float(np.max(np.maximum(values - np.max(around), np.min(around) - values))))
    return worst / exact_range(exact, compared)


def left_out_error(candidate: np.ndarray, exact: np.ndarray, codes: np.ndarray, compared: np.ndarray) -> float:
    """The largest difference of the samples left out for a contact that differs or an event they straddle, relative
    to the exact quantity's range over the compared samples (0 if none)."""
    left = (codes >= 2) & np.isfinite(candidate)
    if not np.any(left) or not np.any(compared):
        return 0.0
    return float(np.max(np.abs(candidate[left] - exact[left]))) / exact_range(exact, compared)


def _contact_ends_within_a_step(solution: ExactSolution, times: np.ndarray) -> bool:
    """Whether the exact contact has ended by the candidate's next sample (its last time plus its last spacing): a
    simulator that stops writing at its last sample in contact (the pull-off) covers the contact."""
    following = float(times[-1] + (times[-1] - times[-2])) if len(times) > 1 else float(times[-1])
    if following >= solution.end_time:
        return True
    return not float(solution.evaluate_at(np.array([max(following, 0.0)]))["contact_radius"][0]) > 0.0


def exact_range(exact: np.ndarray, compared: np.ndarray) -> float:
    """The exact quantity's range over the compared samples (its largest magnitude if flat, else 1): what every
    error of it is relative to."""
    e = exact[compared]
    return float(np.max(e) - np.min(e)) or float(np.max(np.abs(e))) or 1.0


def candidate_scale(candidate: np.ndarray, exact: np.ndarray, compared: np.ndarray) -> tuple[float, float]:
    """The factor ``k`` of the least-squares fit ``candidate ≈ k exact`` over the compared samples, and the fit's
    largest residual relative to ``|k|`` times the exact range (``nan``, ``nan`` where the exact values are all 0 or
    none is compared): a candidate a unit's factor or a sign away from the exact (:func:`scale_hint`)."""
    c, e = candidate[compared], exact[compared]
    norm = float(np.dot(e, e)) if e.size else 0.0
    if not norm > 0.0 or not np.all(np.isfinite(c)):
        return math.nan, math.nan
    factor = float(np.dot(c, e)) / norm
    spread = abs(factor) * exact_range(exact, compared)
    return factor, (float(np.max(np.abs(c - factor * e))) / spread if spread > 0.0 else math.nan)


def relative_norms(times, difference, exact, compared) -> tuple[float, float, float]:
    """max, RMS and time-weighted L1 of the difference over the compared samples, each relative to the
    exact quantity's range there."""
    if not np.any(compared):
        return math.nan, math.nan, math.nan
    d, t = difference[compared], times[compared]
    spread = exact_range(exact, compared)
    l1 = float(np.trapezoid(np.abs(d), t) / (t[-1] - t[0])) if t.size > 1 else float(abs(d[0]))
    return float(np.max(np.abs(d))) / spread, float(np.sqrt(np.mean(d**2))) / spread, l1 / spread


class Sliding(NamedTuple):
    """Where a run's samples slide (:func:`sliding`)."""

    #: the sliding fraction beyond :data:`SLIDING_SHARE` (``nan``, out of contact: no)
    partly: np.ndarray
    #: the sliding fraction within :data:`SLIDING_SHARE` of 1
    fully: np.ndarray


def sliding(sliding_fraction: np.ndarray) -> Sliding:
    """Where a run slides, and where it slides fully, by :data:`SLIDING_SHARE`.

    Parameters
    ----------
    sliding_fraction : numpy.ndarray
        The share of the springs in contact that slide, per sample (``nan`` out of contact).

    Returns
    -------
    Sliding
        Boolean arrays: the samples that slide, and those in full slip.
    """
    share = np.nan_to_num(sliding_fraction)
    return Sliding(share > SLIDING_SHARE, share >= 1.0 - SLIDING_SHARE)


def _jump_in_instant(fully: np.ndarray, contact: np.ndarray) -> np.ndarray:
    """The samples that make a contact in full slip and are followed in contact by partial slip: an adhesive
    contact made under Coulomb's law has every spring in tension (no cap, all sliding) for that instant only, and
    the exact event log has no full slip there (it slides fully from the next instant on, or not)."""
    made = contact & ~np.concatenate(([False], contact[:-1]))
    partial_next = np.concatenate((contact[1:] & ~fully[1:], [False]))
    return fully & made & partial_next


def candidate_events(times, quantities, contact, params, full_slip_by_force: bool = True) -> dict[str, float]:
    """Times of the events by the module's rules (times as given; also ``pull_off_force`` and
    ``last_in_contact``, the index of the last sample in contact, -1 if none) (``nan`` where not found or not
    determinable); without a sliding fraction, full slip is read off ``|F_x|`` against ``τ0 A`` only with
    ``full_slip_by_force`` (the paper's law: under Coulomb's the cap is not ``τ0 A``)."""
    out = {name: math.nan for name in VALIDATED_EVENTS}
    out["pull_off_force"] = math.nan
    out["last_in_contact"] = -1
    touching = np.flatnonzero(contact)
    if touching.size:
        out["first_contact"] = float(times[touching[0]])
    fraction = quantities.get("sliding_fraction")
    if fraction is not None:
        partly, fully = sliding(fraction)
        onset, full = np.flatnonzero(partly), np.flatnonzero(fully & ~_jump_in_instant(fully, np.asarray(contact)))
        out["slip_onset"] = float(times[onset[0]]) if onset.size else math.nan
        out["full_slip"] = float(times[full[0]]) if full.size else math.nan
    elif full_slip_by_force and "tangential_force" in quantities and ("contact_area" in quantities
                                                                   or "contact_radius" in quantities):
        area = quantities.get("contact_area", math.pi * quantities.get("contact_radius", np.nan) ** 2)
        full = np.flatnonzero((area > 0) & (np.abs(quantities["tangential_force"])
                                            >= (1 - FULL_SLIP_SHARE) * params.tau0 * area))
        out["full_slip"] = float(times[full[0]]) if full.size else math.nan
    size = quantities.get("contact_area", quantities.get("contact_radius"))
    if size is not None and np.any(np.isfinite(size)):
        largest = int(np.nanargmax(size))
        smaller = np.flatnonzero(np.nan_to_num(size[largest:], nan=np.inf) < size[largest] * (1.0 - DETACHMENT_SHARE))
        out["detachment_starts"] = float(times[largest + smaller[0]]) if smaller.size else math.nan
    lost = np.flatnonzero(contact[:-1] & ~contact[1:])
    if lost.size:
        out["pull_off"] = float(times[lost[0] + 1])
        out["last_in_contact"] = int(lost[0])
        if "normal_force" in quantities:
            out["pull_off_force"] = float(quantities["normal_force"][lost[0]])
        again = np.flatnonzero(contact[lost[0] + 1:])
        out["re_contact"] = float(times[lost[0] + 1 + again[0]]) if again.size else math.nan
    return out


def events_not_shown(quantities: Mapping[str, np.ndarray]) -> dict[str, str]:
    """The events a candidate's quantities cannot show, each with the reason (the others are compared)."""
    size = "contact_area" in quantities or "contact_radius" in quantities
    contact = "" if any(name in quantities for name in CONTACT_INDICATORS) else \
        "a tangential force alone does not show where the run is in contact"
    sliding = "sliding_fraction" in quantities
    reasons = {"first_contact": contact, "pull_off": contact, "re_contact": contact,
               "detachment_starts": "" if size else "no contact area or radius",
               "slip_onset": "" if sliding else "no sliding_fraction",
               "full_slip": "" if sliding else "no sliding_fraction (F_x approaches τ0 A gradually: the exact solution "
                                               "itself reaches it within FULL_SLIP_SHARE 0.4 % of the path early)"}
    return {name: reason for name, reason in reasons.items() if reason}


def event_time_errors(exact: np.ndarray, candidate: np.ndarray, exact_ends: tuple[float, float],
                      candidate_ends: tuple[float, float], duration: float, times: np.ndarray) -> np.ndarray:
    """Per event of :data:`VALIDATED_EVENTS`: ``|Δt|`` beyond the candidate's sample spacing there (an event is found
    at the first sample past it: up to one spacing late, the exact solution sampled too), relative to the path's
    ``duration``; for an event in one run
    only, how long before the other run could no longer show it (an event in contact: the end of its contact; one
    that makes a contact: its last sample) it lies, relative to the duration (0 beyond that: it may not have reached
    it); ``nan`` for an event in neither. ``*_ends``: (end of the contact, last time) of each run."""
    errors = np.full(len(VALIDATED_EVENTS), np.nan)
    for i, name in enumerate(VALIDATED_EVENTS):
        which = 1 if name in CONTACT_MAKING_EVENTS else 0
        if np.isfinite(exact[i]) and np.isfinite(candidate[i]):
            found = min(max(int(np.searchsorted(times, candidate[i])), 1), len(times) - 1)
            errors[i] = max(abs(candidate[i] - exact[i]) - (times[found] - times[found - 1]), 0.0) / duration
        elif np.isfinite(exact[i]):
            errors[i] = max(candidate_ends[which] - exact[i], 0.0) / duration
        elif np.isfinite(candidate[i]):
            errors[i] = max(exact_ends[which] - candidate[i], 0.0) / duration
    return errors
