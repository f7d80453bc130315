"""What the referees conclude, typed: the verdicts as enums, and the reports of :func:`~mdr_events.validate` and
:func:`~mdr_events.convergence_study` as objects over their datasets.

A report's dataset is what is written and read (netCDF); ``ValidationReport.from_dataset`` and
``to_dataset`` round-trip it, files written before included. The rule of a validation's verdict
is here, once (:func:`validation_failures`): :func:`~mdr_events.validate` sets the verdict by it, and a report lists
what failed by it.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass
from typing import ClassVar, NamedTuple, Sequence

import numpy as np
import xarray as xr

__all__ = ["Verdict", "ConvergenceVerdict", "ValidationReport", "ConvergenceReport", "validation_failures",
           "ValidationMeasures", "EventTimes",
           "LEFT_OUT_BOUND", "VALIDATION_CONTENT", "check_content", "CONVERGENCE_STUDY_CONTENT"]

#: The ``content`` attribute of a validation's and of a convergence study's dataset.
VALIDATION_CONTENT = "validation of a simulator against the exact continuum"
CONVERGENCE_STUDY_CONTENT = "observed order of convergence of a simulator to the exact continuum"
#: A sample left out (its contact differs, or it straddles an event) still lies within this many ranges of the exact
#: value: what an event's timing can change (a jump to 0 at the pull-off); a spike of 100 ranges there passed.
LEFT_OUT_BOUND = 1.0


class Verdict(str, enum.Enum):
    """A validation's verdict (its value is the attribute ``verdict`` of the dataset)."""

    PASS = "pass"
    FAIL = "fail"

    def __str__(self) -> str:
        return self.value


class ConvergenceVerdict(str, enum.Enum):
    """A convergence study's verdict (its value is the attribute ``verdict`` of the dataset)."""

    CONVERGES = "converges"
    DOES_NOT_CONVERGE = "does not converge"
    UNDETERMINED = "undetermined"

    def __str__(self) -> str:
        return self.value


class EventTimes(NamedTuple):
    """The events compared, their times (s from first contact, ``nan``: not in that run) and their errors relative
    to the path's duration (``nan``: not compared)."""

    names: Sequence[str]
    exact: Sequence[float]
    candidate: Sequence[float]
    errors: Sequence[float]


def _event_failures(events: EventTimes, tolerance: float) -> list[str]:
    failures = []
    for name, exact, candidate, error in zip(*events):
        if not error > tolerance:  # (nan: not compared)
            continue
        if math.isfinite(exact) and math.isfinite(candidate):
            failures.append(f"{name}: at {candidate:.6g} s in the candidate, {exact:.6g} s exact: {error:.3g} of the "
                            f"path's duration > tolerance {tolerance:g}")
        elif math.isfinite(exact):
            failures.append(f"{name}: not in the candidate (exact at {exact:.6g} s, {error:.3g} of the path's duration "
                            f"before the candidate stops showing it) > tolerance {tolerance:g}")
        else:
            failures.append(f"{name}: at {candidate:.6g} s in the candidate, not in the exact run ({error:.3g} of "
                            f"the path's duration before it ends) > tolerance {tolerance:g}")
    return failures


#: How close the candidate's least-squares scale on the exact quantity is to a power of ten or to -1, and how small
#: the fit's largest residual (relative to the scaled range), for a failing max error to name the scale: 5 % tells a
#: unit's factor (10^3 between mN and N), a sign or a diameter's 2 from a model's error of that size.
SCALE_HINT_RTOL = 0.05


#: The quantity whose candidate twice the exact is a diameter written for it.
RADIUS = "contact_radius"


def scale_hint(factor: float, residual: float, quantity: str = "") -> str:
    """What a failing quantity's scale on the exact says (empty: nothing): that the candidate is a power of ten times
    it (a unit), minus it (a sign convention) or, for the contact radius, twice it (a diameter), where the fit
    ``candidate ≈ factor exact`` holds to :data:`SCALE_HINT_RTOL` of the range
    (:func:`mdr_events.analysis.samples.candidate_scale`). Round 30: a tangential force in mN read as N failed with
    "max error 997 of its range", a flipped one with "2 of its range", neither saying why."""
    if not (math.isfinite(factor) and factor != 0.0 and residual <= SCALE_HINT_RTOL):
        return ""
    if quantity == RADIUS and abs(factor / 2.0 - 1.0) <= SCALE_HINT_RTOL:
        return " (the candidate is 2 times the exact throughout: a diameter?)"
    nearest = math.copysign(10.0 ** round(math.log10(abs(factor))), factor)
    if nearest == 1.0 or abs(factor / nearest - 1.0) > SCALE_HINT_RTOL:
        return ""
    if nearest < 0.0 and abs(nearest) == 1.0:
        return " (the candidate is minus the exact throughout: the other sign convention?)"
    why = "its unit and sign?" if nearest < 0.0 else "its unit?"
    return f" (the candidate is {nearest:g} times the exact throughout: {why})"


class ValidationMeasures(NamedTuple):
    """What a validation measured, which :func:`validation_failures` judges: each sequence has one value per quantity
    compared, in the order of ``quantities`` (shares of that quantity's range); the others are the run's."""

    #: the quantities compared (names of :data:`~mdr_events.analysis.samples.COMPARED`)
    quantities: Sequence[str]
    #: each quantity's largest error over the samples compared
    max_errors: Sequence[float]
    #: the share of the exact contact's time in contact in one run only or not sampled (``nan``: not shown)
    contact_differs: float
    #: each quantity's largest distance of a sample left out from the exact value (ranges)
    left_out_errors: Sequence[float]
    #: each quantity's largest excess of a sample at a corner or a reversal beyond the exact change there
    corner_excess: Sequence[float] = ()
    #: each quantity's largest excess of a sample where the contact differs or is made beyond the exact values
    contact_change_excess: Sequence[float] = ()
    #: the events compared (``None``: a report written before events were compared)
    events: EventTimes | None = None
    #: per quantity the candidate's least-squares scale on the exact and its residual (:func:`scale_hint`; empty:
    #: none named)
    scales: Sequence[Sequence[float]] = ()


def validation_failures(measures: ValidationMeasures, tolerance: float) -> list[str]:
    """What fails a validation of ``measures`` at ``tolerance``, in words (none: it passes): no quantity compared; a
    quantity's max error above ``tolerance`` (or not a number); the share of the exact contact's time in contact in
    one run only above ``tolerance``; a sample left out farther than :data:`LEFT_OUT_BOUND` ranges from the exact
    value; a sample at a corner or a reversal farther than ``tolerance`` beyond the exact change beside it, or one
    where the contact differs or is made farther than ``tolerance`` beyond the exact values around it and 0; an
    event's time off by more than ``tolerance`` of the path's duration, or in one run only (:class:`EventTimes`); a
    failing max error names the candidate's scale where it is a unit's factor or a sign away (:func:`scale_hint`)."""
    (quantities, max_errors, contact_differs, left_out_errors, corner_excess, contact_change_excess, events,
     scales) = measures
    if not len(quantities):
        return ["no quantity compared"]
    hints = [scale_hint(*scale, name) for scale, name in zip(scales, quantities)] or [""] * len(quantities)
    failures = [f"{name}: max error {error:.3g} of its range > tolerance {tolerance:g}{hint}"
                for name, error, hint in zip(quantities, max_errors, hints) if not error <= tolerance]
    if contact_differs > tolerance:  # (nan: a report written before, of a tangential force alone)
        failures.append(f"contact: {contact_differs:.3g} of the exact contact's time in contact in one run only or "
                        f"not sampled > tolerance {tolerance:g}")
    failures += [f"{name}: a sample left out lies {error:.3g} ranges from the exact value > {LEFT_OUT_BOUND:g}"
                 for name, error in zip(quantities, left_out_errors) if error > LEFT_OUT_BOUND]
    failures += [f"{name}: a sample at a corner lies {excess:.3g} of its range beyond the exact change there > "
                 f"tolerance {tolerance:g}" for name, excess in zip(quantities, corner_excess) if excess > tolerance]
    failures += [f"{name}: a sample where the contact differs or is made lies {excess:.3g} of its range beyond the "
                 f"exact values around it and 0 > tolerance {tolerance:g}"
                 for name, excess in zip(quantities, contact_change_excess) if excess > tolerance]
    return failures + ([] if events is None else _event_failures(events, tolerance))


def check_content(dataset, content: str, kind: str) -> xr.Dataset:
    """``dataset`` if it is a Dataset of ``content`` (its attribute); else ``ValueError`` naming what it is and the
    ``kind`` of result allowed."""
    if not isinstance(dataset, xr.Dataset) or dataset.attrs.get("content") != content:
        found = dataset.attrs.get("content") if isinstance(dataset, xr.Dataset) else type(dataset).__name__
        raise ValueError(f"dataset of {found!r} is not allowed; allowed: a {kind} ({content!r})")
    return dataset


@dataclass(frozen=True)
class _Report:
    """A result held as its dataset (what is written and read), checked to be of its kind when made."""

    CONTENT: ClassVar[str]
    KIND: ClassVar[str]
    dataset: xr.Dataset

    def __post_init__(self) -> None:
        check_content(self.dataset, self.CONTENT, self.KIND)

    @classmethod
    def from_dataset(cls, dataset: xr.Dataset):
        """The report of a dataset of its kind (e.g. read by :func:`~mdr_events.open_result`)."""
        return cls(dataset)

    def to_dataset(self) -> xr.Dataset:
        return self.dataset


@dataclass(frozen=True)
class ValidationReport(_Report):
    """A validation (:func:`~mdr_events.validate`): its dataset and what it concludes.

    Parameters
    ----------
    dataset : xarray.Dataset
        Everything: the samples side by side, the norms, the events, the attributes (``content`` must be a
        validation's).

    Raises
    ------
    ValueError
        A dataset of another kind of result.
    """

    CONTENT: ClassVar[str] = VALIDATION_CONTENT
    KIND: ClassVar[str] = "validation"

    @property
    def verdict(self) -> Verdict:
        """The verdict, :attr:`Verdict.PASS` or :attr:`Verdict.FAIL` (the dataset's attribute ``verdict``)."""
        return Verdict(str(self.dataset.attrs["verdict"]))

    @property
    def passed(self) -> bool:
        """Whether the verdict is :attr:`Verdict.PASS`."""
        return self.verdict is Verdict.PASS

    @property
    def tolerance(self) -> float:
        """The tolerance the errors were held to (a share of each quantity's range; attribute ``tolerance``)."""
        return float(self.dataset.attrs["tolerance"])

    @property
    def failures(self) -> list[str]:
        """What fails, in words (:func:`validation_failures`); empty for a pass."""
        data = self.dataset
        quantities = [str(name) for name in data["quantity"].values]
        share = float(data["contact_differs_share"]) if "contact_differs_share" in data else math.nan
        left_out = data["left_out_max_error"].values if "left_out_max_error" in data else np.zeros(len(quantities))
        corner, change = (data[key].values if key in data else () for key in ("corner_max_excess",
                                                                              "contact_change_max_excess"))
        # (() of files written before)
        events = EventTimes([str(name) for name in data["event"].values], data["event_time_exact"].values,
                            data["event_time_candidate"].values, data["event_time_relative_error"].values) \
            if "event_time_relative_error" in data else None  # (files written before compared no events)
        from mdr_events.analysis.samples import candidate_scale  # (the samples' module loads the models)

        scales = [candidate_scale(data[f"candidate_{name}"].values, data[f"exact_{name}"].values,
                                  np.isfinite(data[f"difference_{name}"].values)) for name in quantities] \
            if all(f"difference_{name}" in data for name in quantities) else ()  # (as validate found them)
        return validation_failures(ValidationMeasures(quantities, data["max_error"].values, share, left_out, corner,
                                                      change, events, scales), self.tolerance)


@dataclass(frozen=True)
class ConvergenceReport(_Report):
    """A convergence study (:func:`~mdr_events.convergence_study`): its dataset and its verdict.

    Parameters
    ----------
    dataset : xarray.Dataset
        Everything: per spacing the norms, the observed orders, the event errors (``content`` must be a
        convergence study's).

    Raises
    ------
    ValueError
        A dataset of another kind of result.
    """

    CONTENT: ClassVar[str] = CONVERGENCE_STUDY_CONTENT
    KIND: ClassVar[str] = "convergence study"

    @property
    def verdict(self) -> ConvergenceVerdict:
        """The verdict: converges, does not converge, or undetermined (the dataset's attribute ``verdict``)."""
        return ConvergenceVerdict(str(self.dataset.attrs["verdict"]))

    @property
    def expected_order(self) -> float:
        """The order of convergence the simulator's method should show (attribute ``expected_order``)."""
        return float(self.dataset.attrs["expected_order"])
