"""A contact's pieces between tangential reversals, read off a run's event log: where the per-spring route
(:mod:`.play_run`) searches the springs' events (a re-stick at a piece's start where it begins at a reversal, then the
first slip onset and full slip in it).
"""

from __future__ import annotations

from .state import EventKind

__all__ = ["log_pieces", "reversal_end"]


def reversal_end(events, time: float) -> bool:
    """Whether ``time`` is a tangential reversal of the log (else a contact's end).

    Parameters
    ----------
    events : list of Event
        The run's log.
    time : float
        A piece's end (s from first contact).

    Returns
    -------
    bool
        Whether a tangential reversal is logged at ``time``.
    """
    return any(event.kind is EventKind.TANGENTIAL_REVERSAL and event.time == time for event in events)


def log_pieces(events) -> list[tuple[float, float, bool]]:
    """Each contact of the log cut at its tangential reversals.

    Parameters
    ----------
    events : list of Event
        The run's log.

    Returns
    -------
    list of tuple
        ``(begin, end, whether it begins at a reversal)`` per piece (s from first contact), in the log's order.
    """
    contacts = [event.time for event in events if event.kind in (EventKind.FIRST_CONTACT, EventKind.RE_CONTACT)]
    ends = [event.time for event in events if event.kind in (EventKind.PULL_OFF, EventKind.CONTACT_ENDS)]
    reversals = [event.time for event in events if event.kind is EventKind.TANGENTIAL_REVERSAL]
    last = max([event.time for event in events], default=0.0)
    out = []
    for begin in contacts:
        end = min([time for time in ends if time > begin], default=last)
        cuts = [begin] + [time for time in reversals if begin < time < end] + [end]
        out += [(low, high, low != begin) for low, high in zip(cuts[:-1], cuts[1:]) if high > low]
    return out
