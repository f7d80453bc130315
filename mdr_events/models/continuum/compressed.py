"""Coulomb's law alone with adhesion: the compressed zone's run beside the contact, and the contact's slip events.

Under Coulomb's caps ``ū(ξ) = κ max(d − g(ξ), 0)`` the springs in tension (the adhesive annulus ``x_c < ξ <= a``,
``g(x_c) = d``) have a zero cap: they slide with no shift, and the tangential force is that of the compressed zone
``ξ <= x_c``, the contact without adhesion of the same path (:func:`~.caps.compressed_zone_alone`). ``solve_path``
runs that zone beside the adhesive contact and :func:`attach_compressed_zone` joins them.

What slides is the zone's slip zone *and* the annulus, as the sliding fraction counts it (and as the discrete model's
springs show it), so the contact's slip events are the zone's plus those of the annulus (direction 0: a zero cap has
no side):

- **slip onset** where the annulus opens while the contact sticks: at the first contact when ``Δγ0 > 0`` (the
  jump-in radius at ``d = 0`` is all annulus), else where the depth first falls below ``g(a)`` (``Δγ0 = 0``: the
  contact grows without an annulus);
- **full slip** where the zone's contact ends while the adhesive contact goes on (``d <= 0``: every spring in
  tension), unless the zone already slid fully.

The instant of an adhesive first contact (``d = 0``, every spring in tension for that instant only) is no full slip:
the zone is in contact from the same instant on, and no sampled run can show it.
"""

from __future__ import annotations

import numpy as np

from .solution import PathSolution, contact_radii, evaluate
from .state import CONTACT_ENDING, Event, EventKind, Regime

__all__ = ["SLIP_KINDS", "ANNULUS_SHARE", "attach_compressed_zone", "annulus_slip_events"]

#: What the compressed zone's run logs of its slip (the adhesive contact's own run logs its radius and contact).
SLIP_KINDS = frozenset({EventKind.SLIP_ONSET, EventKind.FULL_SLIP, EventKind.FRONT_AT_CENTRE, EventKind.FRONT_AT_EDGE,
                        EventKind.RE_STICK})
#: The annulus is open where the contact radius exceeds the zone's by more than this share of it: the two radii are
#: roots of branches of (9) found to the radius tolerance (``radius_rtol``, 1e-13 at most), so that a contact growing
#: along ``d0 = g`` (``Δγ0 = 0``) has none.
ANNULUS_SHARE = 1e-9
#: The zone's slip events after which it still slides (a later onset of the annulus is then no onset of the contact).
_SLIDING_AFTER = frozenset({EventKind.SLIP_ONSET, EventKind.FULL_SLIP, EventKind.FRONT_AT_CENTRE})


def attach_compressed_zone(solution: PathSolution, zone: PathSolution) -> None:
    """Give the adhesive contact's ``solution`` (its springs without shift) the tangential force of ``zone``, the run of
    its compressed zone (the same path without adhesion), and the contact's slip events: the zone's, with the contact's
    radius, and the annulus's (:func:`annulus_slip_events`); the contact's own slip events (its springs all slide at a
    zero cap) are dropped. At equal times the contact's events come first, an ending last."""
    solution.compressed = zone
    slips = [event for event in zone.events if event.kind in SLIP_KINDS]
    if slips:
        radii = contact_radii(solution, np.array([event.time for event in slips]))
        slips = [event._replace(radius=float(radius)) for event, radius in zip(slips, radii)]
    kept = [event for event in solution.events if event.kind not in SLIP_KINDS]
    ending = CONTACT_ENDING | {EventKind.PATH_END}
    events = kept + slips + annulus_slip_events(solution, zone, slips)
    solution.events = sorted(events, key=lambda event: (event.time, event.kind in ending))


def annulus_slip_events(solution: PathSolution, zone: PathSolution, zone_slips: list[Event]) -> list[Event]:
    """The slip events the annulus of tensile springs adds to the contact of ``solution`` (module docstring): per
    contact, a slip onset where the annulus first opens while the zone sticks, and a full slip where the zone's contact
    ends inside the contact's, each with direction 0 (``zone_slips``: the zone's slip events, times from first
    contact)."""
    events = []
    for start, end in _contacts(solution):
        opens = _annulus_opens(solution, zone, start, end)
        if opens is not None and _last_slip(zone_slips, start, opens) not in _SLIDING_AFTER:
            events.append(_event_at(solution, opens, EventKind.SLIP_ONSET))
        for ended in (event.time + zone.t_contact - solution.t_contact for event in zone.events
                      if event.kind in CONTACT_ENDING):
            if start < ended < end and _last_slip(zone_slips, start, ended) is not EventKind.FULL_SLIP:
                events.append(_event_at(solution, ended, EventKind.FULL_SLIP))
    return events


def _contacts(solution: PathSolution) -> list[tuple[float, float]]:
    """Each contact of ``solution`` as (start, end), s from first contact (the end of the run if it goes on)."""
    starts = [event.time for event in solution.events if event.kind in (EventKind.FIRST_CONTACT, EventKind.RE_CONTACT)]
    ends = [event.time for event in solution.events if event.kind in CONTACT_ENDING]
    return [(start, ends[index] if index < len(ends) else solution.end_time) for index, start in enumerate(starts)]


def _annulus_opens(solution: PathSolution, zone: PathSolution, start: float, end: float) -> float | None:
    """The start of the first span of the contact ``[start, end]`` whose middle has an annulus (the contact's radius
    beyond the zone's by :data:`ANNULUS_SHARE`), or ``None``. Within a span the annulus is there from its start or not
    at all: growing along ``d0 < g`` (``Δγ0 > 0``) or shrinking along ``d1 < g`` it is there throughout; a pinned
    radius has it wherever ``d < g(a)``, and the depth, linear in time, starts below ``g(a)`` or falls from it."""
    spans = [span for span in solution.spans if span.regime is not Regime.NONE and span.t_end > span.t_start
             and start <= span.t_start - solution.t_contact < end]
    if not spans:
        return None
    middles = np.array([0.5 * (span.t_start + span.t_end) for span in spans]) - solution.t_contact
    radii = contact_radii(solution, middles)
    zone_radii = np.nan_to_num(evaluate(zone, middles + solution.t_contact - zone.t_contact)["contact_radius"])
    open_ = np.flatnonzero(radii - zone_radii > ANNULUS_SHARE * radii)
    return float(spans[open_[0]].t_start - solution.t_contact) if open_.size else None


def _last_slip(zone_slips: list[Event], start: float, time: float) -> EventKind | None:
    """The zone's last slip event up to ``time`` of the contact that began at ``start`` (``None``: none yet); it
    slides after one of :data:`_SLIDING_AFTER`."""
    last = [event.kind for event in zone_slips if start <= event.time <= time]
    return last[-1] if last else None


def _event_at(solution: PathSolution, time: float, kind: EventKind) -> Event:
    """An event of the annulus at ``time`` (s from first contact), direction 0, with the path's position there."""
    t = time + solution.t_contact
    x, depth = (float(value) for value in solution.path.position(t))
    radius = float(contact_radii(solution, np.array([time]))[0])
    return Event(time, kind, depth, radius, x, 0)
