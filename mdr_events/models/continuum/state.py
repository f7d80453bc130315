"""The hybrid automaton's discrete state: radius regime, the two slip zones, events and the table of
what a change of a slip zone logs.

The continuum method is a hybrid automaton: between events the tangential force ``F_x`` flows
(an ODE), and at events the discrete state jumps. The discrete state is:

- :class:`Regime`, the contact radius: out of contact, growing on the ``Δγ0`` branch of (9),
  pinned, or shrinking on the ``Δγ1`` branch. It is fixed in closed form for each span by
  :func:`mdr_events.models.continuum.plan.plan_span` (the depth is linear on a path segment).
- per :class:`Cap` (the shift ``u = +ū`` or ``u = −ū`` of (13)), whether springs slide at it. The
  springs at the positive cap have their anchors at the lower level ``x − ū(a)``, those at the
  negative cap at the upper level ``x + ū(a)``: the play operator ``Y ← clip(Y, x − ū, x + ū)``.
  Each cap's slip zone can be several intervals; :class:`ZoneSummary` is what is logged of it.

:data:`ZONE_EVENTS` is the table ``(slip before, slip after) → events logged``;
:func:`zone_events` reads it (and adds a front reaching the centre or the edge) and nothing else
decides what a change of a slip zone logs. With both parts of the cap and adhesion on a curved indenter the table is
read on each cap's zone over the compressed zone and the tensile annulus together
(:func:`~.regions.combined_summary`), whose slip ``ContactState.regions`` keeps region by region.

==========  ==========  ==========================================================================
before      after       logged (with the cap as the event's direction)
==========  ==========  ==========================================================================
STICK       PARTIAL     SLIP_ONSET
STICK       FULL        SLIP_ONSET, FULL_SLIP (``F_x = ±τ0 π a²`` exactly)
PARTIAL     FULL        FULL_SLIP (as above)
PARTIAL     STICK       RE_STICK if the level turned back (the slid springs keep their anchors);
FULL        STICK       FRONT_AT_EDGE if the zone left through the shrinking edge
FULL        PARTIAL     nothing: springs attaching at the growing edge stick
PARTIAL     PARTIAL     FRONT_AT_CENTRE / FRONT_AT_EDGE when the zone first reaches ``ξ = 0`` / ``ξ = a``
==========  ==========  ==========================================================================

Radius regime transitions are fixed by the path and the branches (closed form, see ``plan``):
``NONE → GROWING`` at first contact and at every re-contact, ``PINNED → GROWING`` at growth_resumes,
``PINNED → SHRINKING`` at detachment_starts, ``SHRINKING → NONE`` at pull_off or contact_ends, and
a new regime at every path corner; with Coulomb's caps ``PINNED → PINNED`` where the depth crosses 0 (the adhesive
flat punch into tension or back: the caps' rate changes, nothing is logged).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from .anchors import AnchorMap


class Regime(enum.Enum):
    """What the contact radius does during a span."""

    NONE = "none"            #: out of contact
    GROWING = "growing"      #: on the Δγ0 branch of (9), springs attach
    PINNED = "pinned"        #: held: the depth is between the branches
    SHRINKING = "shrinking"  #: on the Δγ1 branch of (9), springs detach


class Cap(enum.IntEnum):
    """The two caps of the shift, ``u = ±ū(a)`` (13); the value is the sign."""

    POSITIVE = 1   #: ``u = +ū``: anchors at the lower level ``x − ū`` (springs dragged towards +x)
    NEGATIVE = -1  #: ``u = −ū``: anchors at the upper level ``x + ū``


class Slip(enum.Enum):
    """How much of the contact slides at one cap."""

    STICK = "stick"      #: no spring at this cap
    PARTIAL = "partial"  #: a slip zone (one or more intervals) at the cap
    FULL = "full"        #: every spring in contact at this cap


class ZoneSummary(NamedTuple):
    """What is logged of one cap's slip zone: its extent and whether it holds the centre and the edge.

    Parameters
    ----------
    slip : Slip
        Stick, a partial slip zone, or full slip at the cap.
    centre : bool
        Whether the spring at ``ξ = 0`` is in the zone.
    edge : bool
        Whether the spring at the contact's edge ``ξ = a`` is in the zone.
    """

    slip: Slip
    centre: bool  #: the spring at ξ = 0 is in the zone
    edge: bool    #: the spring at the contact's edge ξ = a is in the zone


#: The summary of a cap without a slip zone.
NO_ZONE = ZoneSummary(Slip.STICK, False, False)


class EventKind(str, enum.Enum):
    """Kinds of events in the log (values are the names written to files)."""

    FIRST_CONTACT = "first_contact"
    RE_CONTACT = "re_contact"
    CORNER = "corner"
    TANGENTIAL_REVERSAL = "tangential_reversal"
    GROWTH_RESUMES = "growth_resumes"
    DETACHMENT_STARTS = "detachment_starts"
    SLIP_ONSET = "slip_onset"
    FULL_SLIP = "full_slip"
    FRONT_AT_CENTRE = "front_at_centre"
    FRONT_AT_EDGE = "front_at_edge"
    RE_STICK = "re_stick"
    PULL_OFF = "pull_off"
    CONTACT_ENDS = "contact_ends"
    PATH_END = "path_end"

    def __str__(self) -> str:
        return self.value


#: Event names of the log.
EVENT_KINDS = tuple(kind.value for kind in EventKind)
#: Events that end a contact.
CONTACT_ENDING = frozenset({EventKind.PULL_OFF, EventKind.CONTACT_ENDS})


class Event(NamedTuple):
    """One logged event.

    Parameters
    ----------
    time : float
        s from first contact.
    kind : EventKind
        What happened.
    depth : float
        The indentation depth ``d`` (m).
    radius : float
        The contact radius ``a`` (m).
    x : float
        The tangential position of the indenter (m).
    direction : int, default 0
        +1 / −1: the cap of a slip event or the new direction of a tangential reversal; 0 otherwise, and for the
        slip events of the tensile annulus under Coulomb's law alone (a zero cap has no side).
    """

    time: float    #: s from first contact
    kind: EventKind
    depth: float   #: indentation depth d (m)
    radius: float  #: contact radius a (m)
    x: float       #: tangential position of the indenter (m)
    #: +1 / -1: the cap of a slip event (+1: shift u = +ū, the springs dragged towards +x; -1: u = -ū), or
    #: the new direction of motion of a tangential reversal; 0 for events without a direction and for the slip events
    #: of the tensile annulus under Coulomb's law alone (a zero cap has no side: :mod:`.compressed`)
    direction: int = 0


#: (slip before, slip after) -> events logged, for a change without a re-stick (see the module table).
ZONE_EVENTS: dict[tuple[Slip, Slip], tuple[EventKind, ...]] = {
    (Slip.STICK, Slip.PARTIAL): (EventKind.SLIP_ONSET,),
    (Slip.STICK, Slip.FULL): (EventKind.SLIP_ONSET, EventKind.FULL_SLIP),
    (Slip.PARTIAL, Slip.FULL): (EventKind.FULL_SLIP,),
    (Slip.PARTIAL, Slip.STICK): (EventKind.FRONT_AT_EDGE,),
    (Slip.FULL, Slip.STICK): (EventKind.FRONT_AT_EDGE,),
    (Slip.FULL, Slip.PARTIAL): (),
}


def zone_events(before: ZoneSummary, after: ZoneSummary, restuck: bool = False) -> tuple[EventKind, ...]:
    """The events one cap's slip zone logs when it changes from ``before`` to ``after``.

    Parameters
    ----------
    before : ZoneSummary
        The zone as last logged.
    after : ZoneSummary
        The zone now.
    restuck : bool, default False
        The zone ended because its level turned back (RE_STICK). Otherwise the table :data:`ZONE_EVENTS`; a zone
        that stays partial logs its front reaching the centre or the edge.

    Returns
    -------
    tuple of EventKind
        The events to log, in order (possibly none).
    """
    if restuck:
        return (EventKind.RE_STICK,) if before.slip is not Slip.STICK else ()
    if before.slip is not after.slip:
        return ZONE_EVENTS[(before.slip, after.slip)]
    if after.slip is not Slip.PARTIAL:
        return ()
    return tuple(kind for kind, reached, held in ((EventKind.FRONT_AT_CENTRE, after.centre, before.centre),
                                                  (EventKind.FRONT_AT_EDGE, after.edge, before.edge))
                 if reached and not held)


def _both_caps(value) -> dict:
    return {cap: value for cap in Cap}


@dataclass
class ContactState:
    """The automaton's state between spans (it changes only in the transitions of ``solve``).

    Parameters
    ----------
    t : float
        Time (s, from the path's start).
    anchors : AnchorMap
        The stored anchors of the springs in contact.
    in_contact : bool, default False
        Whether the indenter touches the elastomer.
    running : bool, default True
        Whether the run goes on (it ends at the end of the path, or at a pull-off after which the path never
        enters the elastomer again).
    radius : float, default 0.0
        Contact radius ``a`` (m).
    force : float, default 0.0
        Tangential force ``F_x`` (N).
    sliding : dict of Cap to bool, optional
        Whether springs slide at each cap (default: at neither).
    zones : dict of Cap to ZoneSummary, optional
        What was last logged of each cap's slip zone (default: none).
    detaching : bool, default False
        Detachment has been announced (DETACHMENT_STARTS logged or a shrinking span run) and not
        undone by a pinned or growing span since.
    contacts : int, default 0
        Contacts made so far (first contact and re-contacts).
    last_fired : frozenset, default frozenset()
        The span events (trigger, cap) that stopped the last span (reported if the solver gets stuck).
    regions : dict, optional
        With both parts of the cap and adhesion on a curved indenter (:mod:`.split_span`): whether springs slide at
        each cap in each region, keyed ``(Region, Cap)`` (missing: not); ``sliding`` is then whether they slide in
        either.
    """

    t: float
    anchors: "AnchorMap"
    in_contact: bool = False
    running: bool = True
    radius: float = 0.0
    force: float = 0.0
    sliding: dict = field(default_factory=lambda: _both_caps(False))
    zones: dict = field(default_factory=lambda: _both_caps(NO_ZONE))
    detaching: bool = False
    contacts: int = 0
    last_fired: frozenset = frozenset()
    regions: dict = field(default_factory=dict)

    def forget_slip(self) -> None:
        """No spring slides (a fresh contact, or the contact gone)."""
        self.sliding = _both_caps(False)
        self.zones = _both_caps(NO_ZONE)
        self.regions = {}
