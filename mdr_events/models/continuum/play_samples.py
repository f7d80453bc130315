"""The springs of the per-spring route (:mod:`.play_run`) read at many times at once: the shared samples of a spring
run.

:func:`_probed_all` reads the springs' state at a set of times in contact and their share at a cap, the centre and the
edge probed beside the quadrature's nodes and :data:`PROBE_POINTS` probes where none is at a cap (in a few evaluations
of the anchors, :data:`PROBE_CHUNK`; skipped where :func:`~.play_bound.sticking` proves none is, :data:`PROBE_BOUND`).
On it: the share at any times (:func:`_shares`), the output samples' ``F_x``, sliding fraction and share, several
groups of times read in one call (:func:`_samples`, :func:`_samples_together`: the samples, the pieces' ends the
events' searches start from, :func:`_piece_ends`, and the extrema's scan of :func:`~.play_run.spring_run`), the
springs' distance outside their windows and whether any counts as compressed (:func:`_distances`,
:func:`_compressed`: what the events' bisection of :mod:`.play_run` reads), and the events' directions, the probes of
all the events read in one evaluation of the anchors (:func:`_events`). Moved here from :mod:`.play_run` unchanged
(the names their docstrings give without a module, ``_root`` and ``_spring_events``, are :mod:`.play_run`'s).
"""

from __future__ import annotations

import numpy as np

from .play_bound import sticking
from .play_pieces import log_pieces, reversal_end
from .play_probes import probes_at_cap
from .play_springs import LOWER_CAP, UPPER_CAP, PlaySprings, SpringState
from .state import Event, EventKind

__all__ = ["FULL_SHARE", "PROBE_POINTS", "PROBE_CHUNK", "PROBE_BOUND"]

#: The springs at a cap cover the contact (full slip) within this share of its radius (the quadrature's rounding).
FULL_SHARE = 1e-12
#: Where the edge is probed: this share of the radius inside it.
PROBE_SHARE = 1e-12
#: A contact's end is probed this share of its last piece before it (the radius 0 at the end itself).
END_PROBE = 1e-9
#: Springs probed where the quadrature's nodes hold none at a cap (a zone opening between them is found once it
#: reaches one of these: its onset within its growth to ``a/(PROBE_POINTS − 1)``).
PROBE_POINTS = 1025
#: The times whose probes (:data:`PROBE_POINTS` each) :func:`_probed_all` reads in one evaluation of the anchors.
PROBE_CHUNK = 32
#: The share of a contact whose centre alone is at a cap (:func:`_shares`).
SMALLEST = 5e-324
#: Whether the probes of a time are skipped where :func:`~.play_bound.sticking` proves none of them is at a cap
#: (``False``: read at every time where no node is, the route of before, which the tests compare it with).
PROBE_BOUND = True


def _probed_all(play: PlaySprings, times: np.ndarray,
                kinks: bool | np.ndarray = True) -> tuple[list[SpringState], np.ndarray]:
    """The springs' state at each of ``times`` (all in contact) and their share at a cap with the centre and the edge
    probed (:func:`_shares`): the centre and the edge read with the quadrature's nodes, the other probes where none is
    at a cap; the states of all the times in one call (:meth:`~.play_springs.PlaySprings.probed_states`), the other
    probes of all the times where they are read in a few (:data:`PROBE_CHUNK`)."""
    times = [float(time) for time in times]
    alone = np.array([not play.shift(time) > 0.0 for time in times], dtype=bool)
    a = np.array([play.radius(time) for time in times])
    edge = np.array([min(radius, float(play.compressed_radius(time))) if coulomb_alone else radius
                     for time, radius, coulomb_alone in zip(times, a, alone)])
    ends = np.array([0.0, 1.0 - PROBE_SHARE])
    ended = np.flatnonzero(edge > 0.0)
    states, at_ends = play.probed_states(np.array(times), (edge[ended][:, None] * ends).ravel(),
                                         np.repeat(ended, ends.size), kinks)
    at_cap = np.zeros((len(times), ends.size), bool)
    at_cap[ended] = at_ends.reshape(-1, ends.size) < 0
    share = np.array([(state.compressed_at_cap / state.compressed if state.compressed > 0.0 else 0.0)
                      if coulomb_alone else state.length / radius for state, coulomb_alone, radius in zip(states, alone, a)])
    share[alone & ~(edge > 0.0)] = 0.0  # (no compressed springs: none at a cap)
    probed = np.flatnonzero((share == 0.0) & (edge > 0.0))
    grid = np.linspace(0.0, 1.0 - PROBE_SHARE, PROBE_POINTS)
    if PROBE_BOUND and probed.size:  # (where no probe can be at a cap the probes would find none: play_bound)
        stuck = sticking(play, np.array(times)[probed], grid)
        probed = probed[~stuck]
    at = probes_at_cap(play, np.array(times), edge, probed, grid, PROBE_CHUNK)
    spread = np.any(at, axis=1)  # (a probe at a cap where the share is 0)
    at_cap[probed] = at[:, [0, -1]]
    share[probed[spread]] = SMALLEST
    whole = np.all(at_cap, axis=1) | ~(edge > 0.0) | (share == SMALLEST)
    return states, np.where(whole, share, np.minimum(share, 1.0 - 2.0 * FULL_SHARE))


def _shares(play: PlaySprings, times: np.ndarray, kinks: bool | np.ndarray = True) -> np.ndarray:
    """The share of the contact's length at a cap at each of ``times``, or the least positive float where only the
    centre spring or the edge is (a zone opening at ``ξ = 0`` between the quadrature's nodes: the slip onset of
    scenario A); 0 out of contact. Under Coulomb's law alone the compressed zone's (its springs in tension hold no
    shift: they slide from the start, and the slip events are the compressed zone's, as the spans log them). Without
    ``kinks`` the quadrature's panels are not split at the anchors' kinks (:meth:`~.play_springs.PlaySprings.state`;
    for every time or one per time). All the times at once (:func:`_probed_all`)."""
    out = np.zeros(times.shape)
    inside = np.array([play.radius(float(time)) > 0 for time in times], dtype=bool)
    if np.any(inside):
        out[inside] = _probed_all(play, times[inside], np.broadcast_to(kinks, times.shape)[inside])[1]
    return out


def _distances(play: PlaySprings, times: np.ndarray, onset: bool) -> np.ndarray:
    """:func:`_root`'s distance at each of ``times``: the largest (``onset``) or least distance outside the windows
    (:meth:`~.play_springs.PlaySprings.outsides`) of the compressed springs at the nodes under Coulomb's law alone,
    else of all, and of the probes; ``nan`` where no spring is probed."""
    out = np.full(times.shape, np.nan)
    alone = [not play.shift(float(time)) > 0.0 for time in times]
    edge = np.array([min(play.radius(float(time)), float(play.compressed_radius(float(time)))) if coulomb_alone
                     else play.radius(float(time)) for time, coulomb_alone in zip(times, alone)])
    rows = np.flatnonzero(edge > 0.0)
    if not rows.size:
        return out
    share = np.linspace(0.0, 1.0 - PROBE_SHARE, PROBE_POINTS) if onset else np.array([0.0, 1.0 - PROBE_SHARE])
    nodes, pressed, group, at_probes = play.outsides(times[rows], (edge[rows][:, None] * share).ravel(),
                                                     np.repeat(np.arange(rows.size), share.size))
    at_probes = at_probes.reshape(rows.size, share.size)
    bounds = np.searchsorted(group, np.arange(rows.size + 1))
    for k, row in enumerate(rows.tolist()):
        at_nodes, press = nodes[bounds[k]:bounds[k + 1]], pressed[bounds[k]:bounds[k + 1]]
        values = np.concatenate([at_nodes[press] if alone[row] else at_nodes, at_probes[k]])
        out[row] = float(np.max(values) if onset else np.min(values))
    return out


def _samples(play: PlaySprings, times: np.ndarray, radius: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``F_x``, the sliding fraction (length at a cap over ``a``) and the share of :func:`_shares` at each time in
    contact (0, nan and 0 elsewhere), all the times at once (:func:`_probed_all`)."""
    return _samples_together(play, [(times, radius)])[0]


def _samples_together(play: PlaySprings, groups: list) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """:func:`_samples` of each ``(times, radius)`` of ``groups`` (``radius`` ``None``: the springs' own, each time's
    read alone, as :func:`_shares` reads them), every group's distinct times in contact read in one call of
    :func:`_probed_all` (each time's values those of a call at that time alone:
    :meth:`~.play_springs.PlaySprings.probed_states`). The radii are read group by group in their order, each group's
    in one call of :meth:`~.play_springs.PlaySprings.remember_radii` as :func:`_samples` reads them (the layer's branch
    inverted for many depths at once holds each to its tolerance, not to the bit of a call on it alone: the groups'
    radii, and so their values, those of the calls one at a time; the scan's are read before the events' searches,
    not after them, which differs only at a time both read, an exact tie of a scan's time with a search's)."""
    rows = []
    for times, radius in groups:
        if radius is not None:
            play.remember_radii(times[radius > 0])
        rows.append(np.array([k for k in range(times.size) if (radius is None or radius[k] > 0)
                              and play.radius(float(times[k])) > 0], dtype=np.intp))
    distinct, inverse = np.unique(np.concatenate([times[row] for (times, _), row in zip(groups, rows)]),
                                  return_inverse=True)
    states, at = _probed_all(play, distinct)
    out, first = [], 0
    for (times, _), row in zip(groups, rows):
        force, sliding, shares = np.zeros(times.shape), np.full(times.shape, np.nan), np.zeros(times.shape)
        mine = inverse[first:first + row.size]
        first += row.size
        shares[row] = at[mine]
        for k, index in zip(row.tolist(), mine.tolist()):
            force[k], sliding[k] = states[index].force, min(states[index].length / play.radius(float(times[k])), 1.0)
        out.append((force, sliding, shares))
    return out


def _piece_ends(events, start: float) -> np.ndarray:
    """The times (path clock) whose share at a cap :func:`_spring_events` reads before its searches: each piece's
    start after a reversal (a re-stick there) and its last time (its end, or :data:`END_PROBE` before it where the
    contact ends: the radius 0 at the end itself)."""
    pieces = log_pieces(events)
    lasts = _lasts(events, pieces)
    return np.array([begin + start for begin, _, reversal in pieces if reversal] + [last + start for last in lasts],
                    dtype=float)


def _lasts(events, pieces: list) -> list[float]:
    """Each piece's last time read (s from first contact): its end where a reversal ends it, else :data:`END_PROBE`
    of it before its end (the radius 0 at the contact's end itself)."""
    return [end if reversal_end(events, end) else end - END_PROBE * (end - begin) for begin, end, _ in pieces]


def _compressed(play: PlaySprings, times: np.ndarray) -> np.ndarray:
    """1 where the centre probe of the kink search (:meth:`~.play_springs.PlaySprings.centre_pressed`) or a node of
    the quadrature (:meth:`~.play_springs.PlaySprings.nodes_at`) at each of ``times`` counts as compressed, else 0,
    all the times at once (the share at a cap under Coulomb's law alone is 0 without one; with adhesion the nodes
    span the jump-in's radius, whose compressed zone the centre probe's panel holds first)."""
    out = np.zeros(times.shape)
    inside = np.flatnonzero([play.radius(float(time)) > 0.0 for time in times])
    if inside.size:
        _, pressed, group = play.nodes_at(times[inside])
        out[inside[np.unique(group[pressed])]] = 1.0
        out[inside[play.centre_pressed(times[inside])]] = 1.0
    return out


def _edge(play: PlaySprings, time: float, coulomb_alone: bool) -> float:
    """The extent of the springs whose share at a cap is read at ``time``: under Coulomb's law alone the compressed
    ones' (:func:`_shares`), else the contact's."""
    radius = play.radius(time)
    return min(radius, float(play.compressed_radius(time))) if coulomb_alone else radius


def _event(play: PlaySprings, time: float, start: float, kind: EventKind) -> Event:
    """The event at ``time`` (path clock); direction: the cap its springs are at (+1 the lower, ``x − c``: pushed
    towards ``+x``; −1 the upper), the more covered of the two at the probes of :func:`_shares` (the compressed
    springs under Coulomb's law alone), or where no probe is at a cap on the quadrature's nodes
    (:meth:`~.play_springs.PlaySprings.cap_sides`: a zone narrower than the probes' spacing)."""
    edge = _edge(play, time, not play.shift(time) > 0.0)
    labels = play.anchors(edge * np.linspace(0.0, 1.0 - PROBE_SHARE, PROBE_POINTS), time)[1]
    return _directed(play, time, start, kind, edge, labels)


def _events(play: PlaySprings, found: list, start: float) -> list[Event]:
    """:func:`_event` at each ``(time, kind)`` of ``found``, the probes of all of them read in one evaluation of the
    anchors (each spring at its own time: its provenance as a call at that time alone gives it)."""
    if not found:
        return []
    edges = np.array([_edge(play, time, not play.shift(time) > 0.0) for time, _ in found])
    points = (edges[:, None] * np.linspace(0.0, 1.0 - PROBE_SHARE, PROBE_POINTS)).ravel()
    labels = play.anchors(points, np.repeat([time for time, _ in found], PROBE_POINTS))[1].reshape(len(found), -1)
    return [_directed(play, time, start, kind, edge, row) for (time, kind), edge, row in zip(found, edges, labels)]


def _directed(play: PlaySprings, time: float, start: float, kind: EventKind, edge: float, labels) -> Event:
    """The event of :func:`_event` from the provenance ``labels`` of its probes within ``edge``."""
    lower, upper = np.count_nonzero(np.isin(labels, LOWER_CAP)), np.count_nonzero(np.isin(labels, UPPER_CAP))
    if lower == upper == 0:  # (a zone narrower than the probes' spacing, found on the quadrature's nodes)
        lower, upper = play.cap_sides(time, float(edge))
    direction = 0 if lower == upper == 0 else (1 if lower >= upper else -1)
    return Event(time - start, kind, float(play._d(time)), play.radius(time), float(play._x(time)), direction)
