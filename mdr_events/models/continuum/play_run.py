"""The continuum method with every spring's play operator on its own (:mod:`.play_springs`): Coulomb's part of the
friction law on a layer of finite thickness, with or without adhesion.

:func:`run_play_springs` fills what :func:`~mdr_events.models.continuum.solve.run_continuum` fills: the normal problem
(radius, ``F_N``, area, the edge's events and extrema) is the spans' run of the same contact with frictionless springs
(it does not depend on the friction law; with adhesion its radius is the springs' history,
:class:`~.play_springs.SpanHistory`), and ``F_x``, the sliding fraction, the springs' events and the extrema of
``F_x`` are the per-spring route's. The log holds the edge's events and the path's corners of the spans' run and, per
piece of a contact between tangential reversals, a re-stick at the reversal where springs were at a cap before it,
the slip onset (the first time a spring is at a cap: the share at a cap first positive at the output times in the
piece and its end, the centre and the edge probed beside the quadrature's nodes, then bisected to
:data:`EVENT_HALVINGS`) and full slip (every spring at a cap, found the same way). A re-stick where a level turns
back without a reversal of ``x``, and a zone that opens and closes between two output times, are not logged. The
extrema of ``F_x`` are the largest and least of the samples and the route's own scan of the run
(:func:`_scanned_force_extrema`, :func:`_extrema_scan`: :data:`SEGMENT_SCAN` times inside each path segment in
contact, so that they do not hang on the output times) refined by bounded minimisation between its neighbours
(a best sample at a corner, where ``F_x`` kinks but may go on growing, left to the brackets), and every interior extremum the
scan's differences and the one-sided slopes at each segment's ends bracket refined too (:func:`_slope_brackets`).

The output times are read at once (:func:`~.play_samples._probed_all`, :meth:`~.play_springs.PlaySprings.probed_states`), with
the pieces' ends the events' searches start from and the extrema's scan (:func:`spring_run`, :data:`SHARED_SAMPLES`), and the
events of all the pieces are searched side by side (:func:`~.play_search.searched`): each search a generator that yields the
readings it needs (the share, the share without the kink search, the springs' distance outside their windows) and is
sent their values, every step's readings of all the searches read in one batch (:mod:`.play_search`: Brent's method
scipy's ``brentq`` step for step, the halvings taken a few a step). Each event is the one the searches found one at
a time, reading one time at a time, bit for bit.

Where the windows are fixed but for ``x`` (a segment at a constant depth, :func:`~.play_reach.constant_part`) the root
that seeds an event's halvings is each spring's time to reach its cap in closed form (:mod:`.play_reach`) instead of
Brent's, and ``F_x`` there is monotone, its extrema not refined; a full slip from no spring compressed (the first
contact, or with adhesion the jump-in) under Coulomb's law alone is seeded by the time the centre probe counts as
compressed, in closed form on the depth (:func:`~.play_reach.pressed_time`). Every seed's bracket is checked on the
share as before (:data:`CLOSED_REACH` ``False``: the route of before).

The probes are not read where a bound proves none of them is at a cap (:func:`~.play_bound.sticking`: along the first
segment in contact, before the slip onset; :data:`~.play_samples.PROBE_BOUND`), and the probes of the times on one part of
:func:`~.play_reach.constant_part` (a fretting stroke before its slip onset) are read in one evaluation of the
anchors (:meth:`~.play_springs.PlaySprings.caps_over`, :data:`~.play_probes.SHARED_PROBES`); each ``False`` is the route of before,
the same answers bit for bit.
"""

from __future__ import annotations

from enum import Enum
from typing import NamedTuple

import numpy as np
from scipy.optimize import minimize_scalar

from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.layer import LayerBase
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.models.kernel_model import KernelModel

from .extrema import extremum_names, solution_extrema
from .first_touch import first_segment_middle, first_touch_fraction, first_touch_rows
from .play_pieces import log_pieces
from .play_reach import constant_part, pressed_time, reach_times, reach_ulps
from .play_samples import (FULL_SHARE, PROBE_POINTS, PROBE_SHARE, _compressed, _distances, _edge, _event, _events,
                           _lasts, _piece_ends, _samples, _samples_together, _shares)
from .play_search import EVENT_HALVINGS, brent, halve, searched
from .play_springs import PlaySprings, SpanHistory, spring_line
from .solution import contact_radii
from .solve import run_continuum
from .span_extrema import first_tie, within_tie
from .state import Event, EventKind
from .tolerances import Tolerances

__all__ = ["run_play_springs", "takes_play_springs", "EVENT_HALVINGS", "EXTREMUM_XTOL", "SEGMENT_SCAN", "SLOPE_SHARE", "ROOT_ULPS",
           "CLOSED_REACH", "SHARED_SAMPLES", "SHARED_READINGS", "SpringRun", "spring_run"]

#: The events' bisection evaluates its guess only within this many units in the last place of the root of the springs'
#: distance from their caps (:func:`_root`): Brent's method finds the root to about five of them.
ROOT_ULPS = 64
#: Whether the events' search takes the springs' times to reach their caps in closed form where the windows are fixed
#: but for ``x`` (:mod:`.play_reach`; ``False``: Brent's root everywhere, the route of before, which the tests compare
#: it with).
CLOSED_REACH = True
#: The bounded refinement of an extremum of ``F_x``, as a share of the path's duration.
EXTREMUM_XTOL = 1e-12
#: The route's own scan of a run for ``F_x``'s extrema (:func:`_extrema_scan`): this many times evenly inside each path
#: segment in contact (its quarters), beside the contact's ends, the output samples and the path's corners, whatever
#: the output times. Within a segment ``F_x`` may rise then fall (as ``μ F_N`` after the onset on a way out) or fall
#: then rise (issue 32 round 27 Z6: to 0 as the contact ends): the scan's differences and the one-sided slopes at each
#: segment's ends bracket each interior extremum (:func:`_slope_brackets`), three times keep a margin. Its size
#: (3 × the segments in contact) counts against ``Limits.samples``. (257 times evenly over the contact instead cost
#: 1.4-3.8 times a run of 21-201 samples and left segments empty on a path of more; 65 a segment, 7.4 times a run of 200
#: segments.)
SEGMENT_SCAN = 3
#: Whether :func:`spring_run` reads the output samples, the pieces' ends and the extrema's scan in one call
#: (``False``: one call each, the route of before, which the tests compare it with).
SHARED_SAMPLES = True
#: Whether a step's shares with and without the kink search (:class:`_Reading` ``SHARE`` and ``GUESS``) are read in
#: one call of :func:`_probed_all`, the times without it ending with the kink search's first round, and the events'
#: directions in one evaluation of the anchors (:func:`_events`) (``False``: a call each, the route of before, which
#: the tests compare it with).
SHARED_READINGS = True
#: The one-sided slopes of ``F_x`` at a scanned piece's ends (:func:`_slope_brackets`): read this share of the piece
#: inside each end (an extremum nearer an end than this differs from the end's ``F_x`` by at most the slope times the
#: step; the quadrature's round-off of ``F_x`` is some ulps of its size, far below the difference over the step).
SLOPE_SHARE = 1e-6
#: The springs' events the spans' frictionless run logs and this route replaces.
_SPRING_EVENTS = frozenset({EventKind.SLIP_ONSET, EventKind.FULL_SLIP, EventKind.RE_STICK, EventKind.FRONT_AT_CENTRE,
                            EventKind.FRONT_AT_EDGE})
#: The frictionless law of the normal run.
_FRICTIONLESS = FrictionLaw("coulomb", mu=0.0)


def takes_play_springs(model: KernelModel) -> bool:
    """Whether the continuum runs ``model`` spring by spring: Coulomb's part on a finite layer.

    Parameters
    ----------
    model : KernelModel
        The flat model.

    Returns
    -------
    bool
        Whether :func:`run_play_springs` runs it.
    """
    return not model.layer.is_half_space and model.friction.coulomb_mu > 0.0


def _adhesive(model: KernelModel) -> bool:
    return model.params.dgamma0 != 0.0 or model.params.dgamma1 != 0.0


def run_play_springs(model: KernelModel, paths, times, tolerances: Tolerances = Tolerances(),
                     limits: Limits = DEFAULT_LIMITS) -> dict:
    """Every path solved: the normal problem by the spans, the springs by their own play operators (module docstring).

    Parameters
    ----------
    model : KernelModel
        The flat model.
    paths : list of Path
        One path per case.
    times : numpy.ndarray or int
        The output times (s from first contact), or their number.
    tolerances : Tolerances, optional
        The spans' tolerances.
    limits : Limits, optional
        The resource limits.

    Returns
    -------
    dict
        As :func:`~mdr_events.models.continuum.solve.run_continuum`, with ``extrema``.
    """
    normal = model._replace(friction=_FRICTIONLESS)
    raw = run_continuum(normal, paths, times, tolerances, limits)
    if model.layer.base is not LayerBase.BONDED:  # (no tangential springs: F_x = 0 whatever the law)
        raw["extrema"] = [solution_extrema(solution) for solution in raw["solutions"]]
        return raw
    line = spring_line(model.params, model.profile, model.friction, model.layer)
    raw["extrema"] = []
    for case, (path, solution) in enumerate(zip(paths, raw["solutions"])):
        play = PlaySprings(line, path, SpanHistory(solution) if _adhesive(model) else None)
        radius = raw["contact_radius"][case]
        run = spring_run(play, raw["time"], radius, path, solution.events, solution.end_time,
                         lambda scan: contact_radii(solution, scan), limits)
        raw["tangential_force"][case] = np.where(np.isnan(raw["tangential_force"][case]), np.nan, run.force)
        raw["sliding_fraction"][case] = np.where(radius > 0, run.sliding, np.nan)
        _first_touch(model, play, solution, raw, case)
        kept = [event for event in solution.events if event.kind not in _SPRING_EVENTS]
        raw["events"][case] = sorted(kept + run.events, key=lambda event: event.time)
        extrema = solution_extrema(solution)
        extrema.update(run.extrema)
        raw["extrema"].append(extrema)
    return raw


def _first_touch(model: KernelModel, play: PlaySprings, solution, raw: dict, case: int) -> None:
    """The sliding fraction of case ``case`` at a flat face's first touch (:mod:`.first_touch`: 0/0 there, the
    springs' history out of contact at ``d = 0``), its limit as the contact starts: the springs' own value in the
    middle of the first segment with Coulomb's part alone."""
    rows = first_touch_rows(model.profile, raw["time"], raw["indentation_depth"][case], raw["contact_radius"][case])
    if np.any(rows):
        middle = np.array([first_segment_middle(solution)])
        raw["sliding_fraction"][case][rows] = first_touch_fraction(solution.model.K, lambda: _samples(
            play, middle + solution.t_contact, contact_radii(solution, middle))[1][0])


class SpringRun(NamedTuple):
    """What the per-spring route gives of a path's run (:func:`spring_run`)."""

    #: ``F_x`` at the output samples (N; 0 out of contact)
    force: np.ndarray
    #: the sliding fraction there (nan out of contact)
    sliding: np.ndarray
    #: the springs' events (:func:`_spring_events`), on the clock from first contact
    events: list
    #: ``F_x``'s extrema and their times (:func:`_scanned_force_extrema`)
    extrema: dict


def spring_run(play: PlaySprings, times: np.ndarray, radius: np.ndarray, path, events, end: float, radii,
               limits: Limits) -> SpringRun:
    """``F_x`` and the sliding fraction at the output samples, the springs' events and ``F_x``'s extrema of one path,
    for every route that runs the springs one by one (the spans' run here, the rate law's edge in
    :mod:`.rate_coulomb`). The three sets of times whose springs are read with the kink search (the output samples, the
    contact's pieces' ends the events' searches start from, :func:`_piece_ends`, and the extrema's scan,
    :func:`_extrema_scan`) are read in one call of :func:`_probed_all` (:func:`_samples_together`: its kink search's
    rounds and cuts waited on once, not three times; each time's values those of a call at that time alone, bit for
    bit; :data:`SHARED_SAMPLES` ``False``: one call each, the route of before).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    times : numpy.ndarray
        The output samples' times (s from first contact).
    radius : numpy.ndarray
        The contact radius there as the route computes it (m).
    path : Path
        The path.
    events : list of Event
        The edge's events and the path's corners the route logs (the contact's pieces: :func:`~.play_pieces.log_pieces`).
    end : float
        The contact's end (s from first contact).
    radii : callable
        The contact radius (m) at an array of times (s from first contact), as the route computes it.
    limits : Limits
        The resource limits the extrema's scan counts against.

    Returns
    -------
    SpringRun
        The samples, the springs' events and ``F_x``'s extrema.
    """
    start = path.first_contact_time()
    scan = _extrema_scan(end, path.corner_times - start, limits)
    if SHARED_SAMPLES:
        asked = _piece_ends(events, start)
        (force, sliding, shares), (_, _, at_ends), (scanned, _, _) = _samples_together(
            play, [(times + start, radius), (asked, None), (scan + start, radii(scan))])
        found = _spring_events(play, times, shares, start, events, dict(zip(asked.tolist(), at_ends.tolist())))
    else:
        force, sliding, shares = _samples(play, times + start, radius)
        found = _spring_events(play, times, shares, start, events)
        scanned = _samples(play, scan + start, radii(scan))[0]
    return SpringRun(force, sliding, found, _scanned_force_extrema(play, times, force, start, path, end, scan, scanned))


def _spring_events(play: PlaySprings, times: np.ndarray, sampled: np.ndarray, start: float, events,
                   shares: dict | None = None) -> list[Event]:
    """The springs' events (module docstring) on the clock from first contact: in each piece of a contact between
    tangential reversals, a re-stick at its start where springs were at a cap before the reversal, then the first
    slip onset and full slip (every piece's searched side by side: :func:`~.play_search.searched`). ``shares``: the
    share at a cap at :func:`_piece_ends`' times where read already (:func:`spring_run`)."""
    pieces = log_pieces(events)
    lasts = _lasts(events, pieces)
    if shares is None:
        asked = _piece_ends(events, start)
        shares = dict(zip(asked.tolist(), _shares(play, asked).tolist()))
    found, searches = [], []  # (the events in their order: a time, or the index of its search)
    for (begin, end, reversal), last in zip(pieces, lasts):
        if reversal and shares[begin + start] > 0.0:
            found.append((begin + start, EventKind.RE_STICK))
        inside = (times > begin) & (times < end)
        probes, values = np.append(times[inside], last), np.append(sampled[inside], shares[last + start])
        for kind, reached in ((EventKind.SLIP_ONSET, lambda share: share > 0.0),
                              (EventKind.FULL_SLIP, lambda share: share >= 1.0 - FULL_SHARE)):
            hit = np.flatnonzero(reached(values))
            if not hit.size:
                continue
            k = int(hit[0])
            low = probes[k - 1] if k > 0 else begin
            found.append((len(searches), kind))
            searches.append(_bisect(low + start, probes[k] + start, reached, kind is EventKind.SLIP_ONSET, play))
    results = searched(lambda asks: _readings(play, asks), searches)
    found = [(time if kind is EventKind.RE_STICK else results[time], kind) for time, kind in found]
    if not SHARED_READINGS:
        return [_event(play, time, start, kind) for time, kind in found]
    return _events(play, found, start)


class _Reading(Enum):
    """What an event's search asks at a time (:func:`_readings`)."""

    #: the share at a cap (:func:`_shares`)
    SHARE = "share"
    #: the share without the kink search (:func:`_shares` without ``kinks``)
    GUESS = "guess"
    #: the largest distance outside the windows, at the nodes and :data:`~.play_samples.PROBE_POINTS` probes (:func:`_root`)
    ONSET = "onset"
    #: the least one, at the nodes and the centre and edge probes
    LAST = "last"
    #: whether the centre probe or a node counts as compressed (:func:`_compressed`: 1 or 0)
    COMPRESSED = "compressed"


def _readings(play: PlaySprings, asks: list) -> list[float]:
    """The value of each ``(reading, time)`` ask, those of one reading read at once (the radii of all the times too)."""
    out = [0.0] * len(asks)
    play.remember_radii([time for _, time in asks])
    for reading in _Reading:
        kinds = (_Reading.SHARE, _Reading.GUESS) if SHARED_READINGS and reading is _Reading.SHARE else (reading,)
        if SHARED_READINGS and reading is _Reading.GUESS:  # (read with the shares)
            continue
        rows = [k for k, (kind, _) in enumerate(asks) if kind in kinds]
        if not rows:
            continue
        times = np.array([asks[k][1] for k in rows])
        if reading in (_Reading.SHARE, _Reading.GUESS):
            values = _shares(play, times, np.array([asks[k][0] is _Reading.SHARE for k in rows]))
        elif reading is _Reading.COMPRESSED:
            values = _compressed(play, times)
        else:
            values = _distances(play, times, reading is _Reading.ONSET)
        for k, value in zip(rows, values.tolist()):
            out[k] = value
    return out


def _bisect(low: float, high: float, reached, onset: bool, play: PlaySprings | None = None):
    """The first time in ``(low, high]`` the share at a cap (:func:`_shares`) is ``reached`` (``onset``: the slip onset's
    test, else full slip's), to :data:`EVENT_HALVINGS` halvings (a search of :func:`~.play_search.searched`). Bisected
    on the share without the kink search (:func:`_shares` without ``kinks``), which is evaluated only within
    :data:`ROOT_ULPS` of the root of the springs' distance from their caps (:func:`_root`; the other halvings decided
    by it), then the bracket found checked on the share itself; where it is not the share's own, bisected on the guess
    at every halving and checked again, else on the share (the halvings on the far side of a bracket's end it was not
    reached at, or was, decided by it). Where the share turns once in the bracket, the checked bracket is the one
    bisection on the share visits (every time either visits lies outside it)."""
    known = [-np.inf, np.inf]  # (the share not reached up to the first, reached from the second on)
    root, ulps = yield from _root(low, high, onset, play)

    def near_root(time: float):
        if time > root + ulps * np.spacing(root):
            return True
        return time >= root - ulps * np.spacing(root) and reached((yield ((_Reading.GUESS, time),))[0])

    def by_guess(time: float):
        return reached((yield ((_Reading.GUESS, time),))[0])

    def by_share(time: float):
        return time >= known[1] or (time > known[0] and reached((yield ((_Reading.SHARE, time),))[0]))

    def by_compressed(time: float):
        return bool((yield ((_Reading.COMPRESSED, time),))[0])

    first = [near_root] if root is not None else []
    if root is None and _from_contact(play, low, onset):
        pressed = yield from _pressed_root(play, low, high)
        first = [by_compressed] if pressed is None else [lambda time: _near_pressed(pressed, time)]
    for guess in first + [by_guess]:
        bracket = yield from halve(low, high, guess)
        below, above = (reached(value) for value in (yield tuple((_Reading.SHARE, end) for end in bracket)))
        if above and not below:
            return bracket[1]
        known[0] = known[0] if above else max(known[0], bracket[1])
        known[1] = min(known[1], bracket[0]) if below else known[1]
    return (yield from halve(low, high, by_share))[1]


def _from_contact(play: PlaySprings | None, low: float, onset: bool) -> bool:
    """Whether a full slip's search with no root of the distance (:func:`_root`: the distance not negative from the
    piece's start) starts with no spring compressed (``x_c = 0``: where the contact starts, or with adhesion at its
    jump-in), under Coulomb's law alone: the share at a cap is then 0 until the centre probe or a node of the
    quadrature counts as compressed (:func:`_compressed`) and, where every compressed spring slides from its
    attachment (scenario A with ``ẋ > μρ ḋ``: each spring's ``x − Y − c = (ẋ − μρ ḋ)(t − τ)`` from its attachment at
    ``τ``), 1 from then on: that time, found on the depth alone (:func:`_pressed_root`), seeds the bracket the share
    checks (a wrong seed fails the check and the guess is bisected as before)."""
    return (play is not None and CLOSED_REACH and not onset and play.compressed_radius(low) == 0.0
            and not play.shift(low) > 0.0)


def _pressed_root(play: PlaySprings, low: float, high: float):
    """The time the centre probe first counts as compressed in ``[low, high]`` in closed form
    (:func:`~.play_reach.pressed_time`), checked by two readings of :func:`_compressed` :data:`ROOT_ULPS` either side
    of it (a search of :func:`~.play_search.searched`). Returns the window's ends ``(below, above)`` (the reading 0 at
    the first, 1 at the second), ``None`` where there is no time or the check fails."""
    root = pressed_time(play, low, high)
    if root is None:
        return None
    window = ROOT_ULPS * np.spacing(root)
    ends = (max(root - window, low), min(root + window, high))
    below, above = (yield tuple((_Reading.COMPRESSED, end) for end in ends))
    return ends if below == 0.0 and above == 1.0 else None


def _near_pressed(ends: tuple[float, float], time: float):
    """Whether the centre probe or a node counts as compressed at ``time`` (a search of
    :func:`~.play_search.searched`): decided by :func:`_pressed_root`'s window ``ends`` outside it, read inside."""
    if time >= ends[1]:
        return True
    return time > ends[0] and bool((yield ((_Reading.COMPRESSED, time),))[0])


def _root(low: float, high: float, onset: bool, play: PlaySprings | None = None):
    """Where, between ``low`` and ``high``, the first spring the share without the kink search reads reaches its cap (``onset``) or the
    last one does, by Brent's method (:func:`~.play_search.brent`) on the largest or least distance outside the windows
    (:func:`_distances`): ``None`` where it is not positive at ``high``; where it is not negative at ``low``, from
    :data:`ROOT_ULPS` after it on, and where it is not negative there either, the slip onset at ``low``. On a part of
    :func:`~.play_reach.constant_part` the root in closed form (:func:`_reach_root`) with its own, narrower window.
    Returns the root (or ``None``) and the window about it (units in the last place)."""
    reading = _Reading.ONSET if onset else _Reading.LAST
    at_high = (yield ((reading, high),))[0]
    if not at_high > 0.0:
        return None, ROOT_ULPS
    at_low = (yield ((reading, low),))[0]
    if not at_low < 0.0:  # (out of contact at ``low``, or springs at their caps at a reversal's instant, before the
        start = low + ROOT_ULPS * np.spacing(low)  # re-stick: looked for from just after it)
        at_low = (yield ((reading, start),))[0]
        if not at_low < 0.0:  # (the slip onset as the piece starts, Coulomb's springs at the edge sliding at once;
            return (low if onset else None), ROOT_ULPS  # checked after)
        low = start
    part = constant_part(play, low, high) if play is not None and CLOSED_REACH else None
    if part is not None and part > low:  # (the windows fixed from the part's start: the root before it by Brent's)
        at_part = (yield ((reading, part),))[0]
        if at_part > 0.0:
            return (yield from brent(reading, low, part, at_low, at_part)), ROOT_ULPS
        if not at_part < 0.0:  # (0: the root itself; nan: Brent's on the whole)
            return (part if at_part == 0.0 else (yield from brent(reading, low, high, at_low, at_high))), ROOT_ULPS
    closed = None if part is None else _reach_root(play, part, high, onset)
    return closed if closed is not None else ((yield from brent(reading, low, high, at_low, at_high)), ROOT_ULPS)


def _reach_root(play: PlaySprings, part: float, high: float, onset: bool) -> tuple[float, int] | None:
    """:func:`_root` on a part of :func:`~.play_reach.constant_part` (the windows fixed but for ``x`` on ``(part,
    high]``): the first time a spring :func:`_distances` reads at ``high`` reaches its cap (``onset``) or the last
    one's, each in closed form (:func:`~.play_reach.reach_times`), and the window about it where the share is read
    (:func:`~.play_reach.reach_ulps`: the distances' round-off over the speed, both ways); ``None`` where none
    reaches its cap by ``high``."""
    alone = not play.shift(high) > 0.0
    share = np.linspace(0.0, 1.0 - PROBE_SHARE, PROBE_POINTS) if onset else np.array([0.0, 1.0 - PROBE_SHARE])
    nodes, pressed, _ = play.nodes_at(np.array([high]))
    points = np.concatenate([nodes[pressed] if alone else nodes, _edge(play, high, alone) * share])
    first, last = reach_times(play, points, part, high)
    root = float(np.min(first) if onset else np.max(last))
    if not np.isfinite(root):
        return None
    root = min(root, high)
    return root, min(ROOT_ULPS, reach_ulps(play, part, root))


def _monotone(play: PlaySprings, times: np.ndarray) -> bool:
    """Whether ``F_x`` is monotone between each two neighbours of ``times`` (path clock, increasing): each interval a
    part of :func:`~.play_reach.constant_part` (every window fixed but for ``x``, linear in time there). A spring's
    ``x − Y`` then follows ``x`` while it sticks and stays at ``±c`` once at its cap, which only the side ``x`` moves
    towards can reach: every spring's, and so ``F_x = 2G* ∫ w (x − Y) dξ``, moves with ``x`` or rests, so its extremes
    on the interval lie at its ends (where it rests, full slip, the refinement of :func:`_force_extrema` would only
    read the plateau's round-off). A jump of the radius in ``(low, high]`` rules an interval out on its own (not on
    :func:`~.play_reach.constant_part`'s word alone: a jump changes the windows, a wrong part would leave an extremum
    unrefined)."""
    jumps = np.array([jump[0] for jump in play.history.jumps])
    return CLOSED_REACH and all(high == low or (not np.any((jumps > low) & (jumps <= high))
                                                and constant_part(play, low, high) == low)
                                for low, high in zip(times[:-1].tolist(), times[1:].tolist()))


def _extrema_scan(end: float, corners: np.ndarray, limits: Limits) -> np.ndarray:
    """The route's own scan of a run for ``F_x``'s extrema (s from first contact, sorted): first contact, ``end`` and
    :data:`SEGMENT_SCAN` times evenly inside each path segment in contact (``corners``: the path's corner times from
    first contact), checked against ``limits.samples``."""
    low, high = _scan_pieces(end, corners)
    within = _scan_grid(low, high)[:, 1:-1].ravel()
    limits.check(f"the F_x extrema scan of the continuum run ({low.size} path segments in contact)",
                 samples=float(within.size))
    return np.unique(np.concatenate([[0.0, end], within]))


def _scan_pieces(end: float, corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The path segments' parts between first contact and ``end`` (s from first contact): their starts and ends."""
    low, high = np.clip(corners[:-1], 0.0, end), np.clip(corners[1:], 0.0, end)
    inside = high > low
    return low[inside], high[inside]


def _scan_grid(low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """Each piece's ends and its :data:`SEGMENT_SCAN` scanned times between them, a row per piece."""
    shares = np.arange(1, SEGMENT_SCAN + 1) / (SEGMENT_SCAN + 1)
    return np.column_stack([low, low[:, None] + shares * (high - low)[:, None], high])


def _slope_grid(play: PlaySprings, start: float, end: float, corners: np.ndarray) -> np.ndarray:
    """:func:`_scan_grid` of the pieces (:func:`_scan_pieces`) where ``F_x`` is not proven monotone
    (:func:`_monotone`), s from first contact."""
    low, high = _scan_pieces(end, corners)
    keep = [k for k in range(low.size) if not _monotone(play, np.array([low[k], high[k]]) + start)]
    return _scan_grid(low[keep], high[keep])


def _unpressed_ends(play: PlaySprings, start: float, grid: np.ndarray, known: dict, steps: np.ndarray) -> None:
    """A piece whose ``F_x`` is flat at its end because its depth fell to 0 inside it (with adhesion under Coulomb's
    law alone no spring is compressed, ``F_x = 0``, from there to the contact's end) ends, for
    :func:`_slope_brackets`, where the depth, linear along the segment, reaches 0, its slope read
    :data:`SLOPE_SHARE` of the piece before (``grid``, ``known`` and ``steps`` changed in place): an extremum
    before the plateau (issue 32 round 27 Z6) is then bracketed by the slope's sign as anywhere else, without
    refining the plateau."""
    rows = [k for k in range(grid.shape[0]) if steps[1, k] == known[float(grid[k, -1])] == 0.0
            and play._d(float(grid[k, -2]) + start) > 0.0 >= play._d(float(grid[k, -1]) + start)]
    for k in rows:
        low, high = float(grid[k, -2]), float(grid[k, -1])
        depth_low, depth_high = float(play._d(low + start)), float(play._d(high + start))
        plateau = low + depth_low / (depth_low - depth_high) * (high - low)
        if play.compressed_radius(plateau + SLOPE_SHARE * (high - low) + start) > 0.0:
            continue  # (not the plateau's start: the flat end left to _slope_brackets' own rule)
        grid[k, -1] = plateau
        known[plateau] = 0.0
        steps[1, k] = play.state(plateau - SLOPE_SHARE * (grid[k, -1] - grid[k, 0]) + start)[0]


def _slope_brackets(grid: np.ndarray, known: dict, steps: np.ndarray) -> list[tuple[float, float, float]]:
    """Where an interior extremum of ``F_x`` lies between the scan's times ``grid`` (:func:`_slope_grid`; issue 32
    round 27 Z6): ``(low, high, sign)``, ``sign`` +1 a maximum, −1 a minimum, in s from first contact; ``known``:
    ``F_x`` at the grid's times, ``steps``: at :data:`SLOPE_SHARE` of each piece inside its start and its end (two
    rows).

    Each piece of a path segment in contact (:func:`_scan_pieces`) is read at its ends, :data:`SLOPE_SHARE` of it
    inside each end (the one-sided slopes' signs there) and at the scan's times inside it; in the sequence of the
    left end's slope, the differences of neighbouring times and the right end's slope, a fall then a rise brackets a
    minimum between the first's start and the second's end (a rise then a fall a maximum): ``F_x`` is smooth between
    a piece's ends (its kinks are the path's corners, the contact's ends and the springs' transitions, where its
    slope changes but keeps its sign unless an extremum lies there, one of the times read), so a slope's sign change
    between two neighbours holds a stationary point between them. Why this is sound: each stationary point that is a
    local extremum changes the slope's sign, so every interior extremum is bracketed unless two of them lie between
    the same two neighbours (a quarter of a segment) or one within :data:`SLOPE_SHARE` of a piece's end, where it
    differs from the end's ``F_x`` by at most the slope times that step. A slope 0 at an end (``F_x`` flat there: with
    adhesion under Coulomb's law alone no spring compressed before the contact ends) says nothing: the piece's part
    next to it is bracketed whichever way ``F_x`` goes into it (a dip before the plateau, issue 32 round 27 Z6).
    Within a segment ``x`` and ``d`` are linear
    in time and ``F_x`` is not monotone between the springs' events (refuted: the Z6 case falls, the sticking
    springs following ``x``, then rises to 0 as the sliding springs' caps shrink with the depth, a minimum at no
    event), hence the slopes rather than the events. The brackets do not depend on the output times. Pieces on a
    part where ``F_x`` is monotone (:func:`_monotone`) are not read (:func:`_slope_grid`)."""
    row = np.array([[known[float(time)] for time in times] for times in grid]).reshape(grid.shape)
    rises = np.column_stack([steps[0] - row[:, 0], np.diff(row, axis=1), row[:, -1] - steps[1]])
    brackets = []
    for times, rise in zip(grid, np.sign(rises)):
        turns = (rise[:-1] * rise[1:] < 0.0).tolist()
        turns[0] = turns[0] or (rise[0] == 0.0 and rise[1] != 0.0)  # (F_x flat at an end: a plateau, as of no
        turns[-1] = turns[-1] or (rise[-1] == 0.0 and rise[-2] != 0.0)  # spring compressed, its extremum unknown)
        for j in np.flatnonzero(turns).tolist():
            side = rise[j] if rise[j] != 0.0 else -rise[j + 1]
            brackets.append((float(times[max(j - 1, 0)]), float(times[min(j + 1, times.size - 1)]), float(side)))
    return brackets


def _scanned_force_extrema(play: PlaySprings, times: np.ndarray, force: np.ndarray, start: float, path, end: float,
                           scan: np.ndarray, scanned: np.ndarray) -> dict:
    """:func:`_force_extrema` of the output samples and the route's own scan of the run (:func:`_extrema_scan`), so
    that the extrema do not hang on the output times (issue 32 Y2: one sample at the first contact gave a maximum of
    0), for every route that runs the springs one by one (:func:`spring_run`: the spans' run here, the rate law's
    edge in :mod:`.rate_coulomb`).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    times, force : numpy.ndarray
        The output samples' times (s from first contact) and ``F_x`` (N).
    start : float
        The first contact (s, path clock).
    path : Path
        The path.
    end : float
        The contact's end (s from first contact).
    scan, scanned : numpy.ndarray
        The scan's times (s from first contact) and ``F_x`` there (N).

    Returns
    -------
    dict
        As :func:`_force_extrema`.
    """
    order = np.argsort(np.concatenate([times, scan]), kind="stable")  # (the samples first among equal times)
    times, force = np.concatenate([times, scan])[order], np.concatenate([force, scanned])[order]
    corners = path.corner_times - start
    inner = corners[(corners > times[0]) & (corners < times[-1])]
    grid = _slope_grid(play, start, end, corners)
    step = SLOPE_SHARE * (grid[:, -1] - grid[:, 0])
    read = np.concatenate([inner, grid[:, 0] + step, grid[:, -1] - step])  # (the corners and the slopes: one batch)
    values = np.array([state.force for state in play.probed_states(read + start, np.empty(0),
                                                                      np.empty(0, dtype=np.intp))[0]])
    known = dict(zip(np.concatenate([scan, inner]).tolist(), np.concatenate([scanned, values[:inner.size]]).tolist()))
    steps = values[inner.size:].reshape(2, -1)
    _unpressed_ends(play, start, grid, known, steps)
    brackets = _slope_brackets(grid, known, steps)
    return _force_extrema(play, times, force, start, path, (inner, values[:inner.size]), brackets)


def _force_extrema(play: PlaySprings, times: np.ndarray, force: np.ndarray, start: float, path, at_corners,
                   brackets) -> dict:
    """The largest and least ``F_x`` (N) and their times (s from first contact): among the samples and the path's
    corners (``at_corners``: the corners inside ``times``' span and ``F_x`` there, where it has kinks), the best
    refined between its neighbours (a corner not: its sides are pieces the brackets cover), and each of ``brackets``
    (:func:`_slope_brackets`: ``(low, high, sign)``) of its kind that does not hold that refined time refined on its
    own; of all these points the earliest that ties the best (:func:`_earliest_tie`), as every extremum of the
    continuum is read (:func:`~.span_extrema.within_tie`)."""
    out, duration = {}, path.duration
    corners, at_corners = at_corners
    order = np.argsort(np.concatenate([times, corners]), kind="stable")
    times, force = np.concatenate([times, corners])[order], np.concatenate([force, at_corners])[order]
    for kind, sign in (("max", 1.0), ("min", -1.0)):
        k = int(np.argmax(sign * force))
        value, time = float(force[k]), float(times[k])
        low, high = times[max(k - 1, 0)], times[min(k + 1, times.size - 1)]
        # (where the best's refinement found a better F_x: a local extremum of its bracket)
        refined_at, found = None, []
        # (at a corner F_x kinks but may go on growing past it, as where the depth turns and x does not: issue 32
        # round 27 Z4; the corner is an end of the pieces on each side, whose interior extrema the one-sided slopes
        # there and the scan's differences bracket (_slope_brackets, refined below), so a corner is not refined
        # again on each side: two bounded minimisations of ~30 readings that found the corner itself where it is
        # the extremum, 3-7 times the run of a layer's Coulomb rows)
        if (time not in corners and high > low and value != 0.0
                and not _monotone(play, np.unique([low, time, high]) + start)):
            refined, at = _refined(play, sign, low, high, start, duration)
            if sign * refined > sign * value:
                found.append((at, refined))
                refined_at = at
        # (a bracket that holds the refined extremum holds no other, F_x unimodal there: _slope_brackets)
        for a, b in [(a, b) for a, b, side in brackets if side == sign
                     and not (refined_at is not None and a < refined_at < b)]:
            refined, at = _refined(play, sign, a, b, start, duration)
            found.append((at, refined))
        value_name, time_name = extremum_names("tangential_force", kind)
        out[time_name], out[value_name] = _earliest_tie(times, force, found, sign)
    return out


def _earliest_tie(times: np.ndarray, force: np.ndarray, found: list[tuple[float, float]],
                  sign: float) -> tuple[float, float]:
    """The earliest ``(time, F_x)`` of the samples (``times``, sorted, and ``force``) and the refined points
    (``found``) that ties the best of them (:func:`~.span_extrema.within_tie`: :data:`~.span_extrema.EXTREMUM_TIE` of
    ``F_x``'s largest magnitude along the run), ``sign`` +1 for the largest, −1 for the least. The model holds
    ``F_x`` constant where every spring sticks and ``x`` rests (a corner of A's path under the rate law: the springs
    attaching at a growing edge carry nothing), but the quadrature reads such a plateau to its rounding (measured
    1e-13 of ``F_x``), so its best sample was any of the plateau's and moved with every exact scaling of the run
    (issue 32 round 30: 9e-2 of the run under ``E, τ0, Δγ → 1e148 ·``); the earliest tie is the plateau's start, as
    the spans' extrema and the rate run's read theirs."""
    signed = sign * force
    best = max([float(np.max(signed))] + [sign * value for _, value in found])
    size = float(np.fmax.reduce(np.abs(force), initial=0.0))
    first = first_tie(signed, best, size)
    tied = [(float(times[first]), float(force[first]))] if first >= 0 else []
    return min(tied + [(at, value) for at, value in found if within_tie(sign * value, best, size)])


def _refined(play: PlaySprings, sign: float, low: float, high: float, start: float,
             duration: float) -> tuple[float, float]:
    """``F_x`` (N) at its largest (``sign`` +1) or least (−1) on ``[low, high]`` (s from first contact) and its time,
    by bounded minimisation to :data:`EXTREMUM_XTOL` of the path's ``duration``."""
    found = minimize_scalar(lambda t: -sign * play.state(float(t) + start)[0], bounds=(low, high), method="bounded",
                            options={"xatol": EXTREMUM_XTOL * duration})
    return -sign * float(found.fun), float(found.x)
