"""The events a sweep's continuum run reports, read off its event log alike for every adhesion law: the first slip
onset on the way in and on the way out, the first full slip and the contact's end (the paper's law logs a pull-off,
the rate-dependent law the contact's end), their times and depths."""

from __future__ import annotations

import math
from typing import Iterable

import numpy as np

from mdr_events.models.continuum import Event, EventKind
from mdr_events.models.paths import Path

__all__ = ["FIRST_EVENTS", "deepest_time", "first_events", "event_quantities"]

#: The events a sweep reports, by the name of their quantities (``<name>_time``, and ``<name>_depth`` but for the
#: full slip).
FIRST_EVENTS = ("slip_onset_in", "slip_onset_out", "full_slip", "pull_off")
#: The events that end a run's contact.
_ENDS = (EventKind.PULL_OFF, EventKind.CONTACT_ENDS)


def deepest_time(path: Path) -> float:
    """The time (s, path clock) of the path's deepest waypoint, which parts the way in from the way out."""
    return float(path.corner_times[int(np.argmax(path.waypoints[:, 1]))])


def _clock(event: Event, start: float) -> float:
    """The event's time on the path's clock (its log's times counted from ``start``; 0: the path's clock)."""
    return event.time + start if start else event.time


def first_events(events: Iterable[Event], path: Path, start: float = 0.0) -> dict[str, Event]:
    """The first event of each of :data:`FIRST_EVENTS` in ``events`` (those not logged left out).

    Parameters
    ----------
    events : iterable of Event
        The run's event log, its times counted from ``start`` (s, path clock).
    path : Path
        The run's path.
    start : float, optional
        Where the log's clock starts on the path's (0: the log is on the path's clock).

    Returns
    -------
    dict of str to Event
        The events by name.
    """
    deepest = deepest_time(path)
    first: dict[str, Event] = {}
    for event in events:
        if event.kind is EventKind.SLIP_ONSET:
            first.setdefault("slip_onset_in" if _clock(event, start) <= deepest else "slip_onset_out", event)
        elif event.kind is EventKind.FULL_SLIP:
            first.setdefault("full_slip", event)
        elif event.kind in _ENDS:
            first.setdefault("pull_off", event)
    return first


def event_quantities(first: dict[str, Event], start: float = 0.0) -> dict[str, float]:
    """The times (s, path clock) and depths (m) of :func:`first_events`' events, ``nan`` for those not logged.

    Parameters
    ----------
    first : dict of str to Event
        :func:`first_events`' result.
    start : float, optional
        Where the log's clock starts on the path's.

    Returns
    -------
    dict of str to float
        ``<name>_time`` of each of :data:`FIRST_EVENTS`, ``<name>_depth`` but for the full slip.
    """
    out = {}
    for key in FIRST_EVENTS:
        event = first.get(key)
        out[f"{key}_time"] = float(_clock(event, start)) if event else math.nan
        if key != "full_slip":
            out[f"{key}_depth"] = float(event.depth) if event else math.nan
    return out
