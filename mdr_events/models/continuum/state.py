"""The hybrid automaton's discrete state: radius regime, slip state, events and the transition table.

The continuum method is a hybrid automaton: between events the tangential force ``F_x`` flows
(an ODE), and at events the discrete state jumps. The discrete state is two enums:

- :class:`Regime`, the contact radius: out of contact, growing on the ``Δγ0`` branch of (9),
  pinned, or shrinking on the ``Δγ1`` branch. It is fixed in closed form for each span by
  :func:`mdr_events.models.continuum.plan.plan_span` (the depth is linear on a path segment).
- :class:`Slip`, the tangential field: every spring sticks, a slip zone ``[0, c]`` sits at the cap
  ``ū(a)``, or every spring slides.

:data:`SLIP_TRANSITIONS` is the table ``(slip state, events fired together) → next slip state``;
:func:`next_slip` reads it and nothing else decides a slip transition.

=================  ===========================  ===============  ===================================
slip state         event(s)                     next slip state  also
=================  ===========================  ===============  ===================================
STICK              SLIP_ONSET                   PARTIAL
STICK              SLIP_ONSET + FULL_SLIP       FULL             ``F_x = τ0 π a²`` exactly
PARTIAL            FULL_SLIP                    FULL             ``F_x = τ0 π a²`` exactly
PARTIAL            RE_STICK                     STICK            slid springs get anchor ``x − ū``
STICK              FULL_SLIP (alone)            FULL             as onset + full slip
PARTIAL            FULL_SLIP + RE_STICK         STICK            ``F_x = τ0 π a²``, then re-stick
FULL               GROWTH (span planned)        PARTIAL          the new springs stick
any                FRONT_CROSSES_PIECE          unchanged        internal: restart, not logged
=================  ===========================  ===============  ===================================

Radius regime transitions are fixed by the path and the branches (closed form, see ``plan``):
``NONE → GROWING`` at first contact, ``PINNED → GROWING`` at growth_resumes, ``PINNED → SHRINKING``
at detachment_starts, ``SHRINKING → NONE`` at pull_off or contact_ends (the run ends), and a
new regime at every path corner.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from .anchors import AnchorMap


class Regime(enum.Enum):
    """What the contact radius does during a span."""

    NONE = "none"            #: out of contact (before first contact)
    GROWING = "growing"      #: on the Δγ0 branch of (9), springs attach
    PINNED = "pinned"        #: held: the depth is between the branches
    SHRINKING = "shrinking"  #: on the Δγ1 branch of (9), springs detach


class Slip(enum.Enum):
    """The slip state of the tangential springs in contact."""

    STICK = "stick"      #: no spring at the cap ū(a)
    PARTIAL = "partial"  #: a slip zone [0, c] at the cap, the rest sticks
    FULL = "full"        #: every spring at the cap


class EventKind(str, enum.Enum):
    """Kinds of events in the log (values are the names written to files)."""

    FIRST_CONTACT = "first_contact"
    CORNER = "corner"
    GROWTH_RESUMES = "growth_resumes"
    DETACHMENT_STARTS = "detachment_starts"
    SLIP_ONSET = "slip_onset"
    FULL_SLIP = "full_slip"
    RE_STICK = "re_stick"
    PULL_OFF = "pull_off"
    CONTACT_ENDS = "contact_ends"
    PATH_END = "path_end"
    #: internal, never logged: the slip front passes from one piece of the anchor map to the next
    FRONT_CROSSES_PIECE = "front_crosses_piece"

    def __str__(self) -> str:
        return self.value


#: Event names of the log, in the order they can occur (the internal event excluded).
EVENT_KINDS = tuple(kind.value for kind in EventKind if kind is not EventKind.FRONT_CROSSES_PIECE)
#: Events that end the contact and the run.
CONTACT_ENDING = frozenset({EventKind.PULL_OFF, EventKind.CONTACT_ENDS})
#: Slip events, found by event functions while the force is integrated.
SLIP_EVENTS = frozenset({EventKind.SLIP_ONSET, EventKind.FULL_SLIP, EventKind.RE_STICK})


class Event(NamedTuple):
    """One logged event."""

    time: float    #: s from first contact
    kind: EventKind
    depth: float   #: indentation depth d (m)
    radius: float  #: contact radius a (m)
    x: float       #: tangential position of the indenter (m)
    #: +1 / -1: the cap of a slip event (+1: shift u = +ū, the springs dragged towards +x; -1: u = -ū), or
    #: the new direction of motion of a tangential reversal; 0 for events without a direction
    direction: int = 0


#: (slip state, events fired together) -> next slip state.
SLIP_TRANSITIONS: dict[tuple[Slip, frozenset[EventKind]], Slip] = {
    (Slip.STICK, frozenset({EventKind.SLIP_ONSET})): Slip.PARTIAL,
    (Slip.STICK, frozenset({EventKind.SLIP_ONSET, EventKind.FULL_SLIP})): Slip.FULL,
    (Slip.PARTIAL, frozenset({EventKind.FULL_SLIP})): Slip.FULL,
    (Slip.PARTIAL, frozenset({EventKind.RE_STICK})): Slip.STICK,
    # coincidences: full slip found alone from stick (its onset a rounding error earlier), and full slip
    # together with re-stick (every spring at the cap just as the cap starts outgrowing the indenter)
    (Slip.STICK, frozenset({EventKind.FULL_SLIP})): Slip.FULL,
    (Slip.PARTIAL, frozenset({EventKind.FULL_SLIP, EventKind.RE_STICK})): Slip.STICK,
}


def next_slip(slip: Slip, fired: frozenset[EventKind]) -> Slip:
    """The slip state after the slip events ``fired`` (together) in state ``slip``; see the table above.

    The internal FRONT_CROSSES_PIECE changes nothing; an empty set changes nothing.
    """
    events = frozenset(fired) & SLIP_EVENTS
    if not events:
        return slip
    try:
        return SLIP_TRANSITIONS[(slip, events)]
    except KeyError:
        raise RuntimeError(f"the continuum method met the events {sorted(e.value for e in events)} in the slip "
                           f"state {slip.value!r}, which the transition table does not allow; please report the "
                           "parameters and path") from None


@dataclass
class ContactState:
    """The automaton's state between spans (it changes only in the transitions of ``solve``).

    Attributes
    ----------
    t : float
        Time (s, from the path's start).
    anchors : AnchorMap
        The tangential field of the springs in contact.
    in_contact, running : bool
        Whether the indenter touches the elastomer; whether the run goes on (a pull-off ends it).
    radius, force : float
        Contact radius ``a`` (m) and tangential force ``F_x`` (N, mirrored frame).
    slip : Slip
    detaching : bool
        Detachment has been announced (DETACHMENT_STARTS logged or a shrinking span run) and not
        undone by a pinned or growing span since.
    """

    t: float
    anchors: "AnchorMap"
    in_contact: bool = False
    running: bool = True
    radius: float = 0.0
    force: float = 0.0
    slip: Slip = Slip.STICK
    detaching: bool = False
