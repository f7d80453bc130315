r"""Each spring's time to reach its cap in closed form, all springs at once, where every window is fixed but for ``x``.

Along a segment of the path at a constant depth (``d`` constant, the radius at rest: no piece of the radius's history
:mod:`.play_history` moves in it) every spring's cap ``c = ū(a) + μ ρ(ξ) max(d − g(ξ), 0)`` is constant in time, and
its window ``[x − c, x + c]`` moves with ``x``, which is linear in time. No clamp of a spring's chain lies inside such a
part (no corner, jump or extreme of its own), so a spring's anchor before the clamp at ``t`` is one value ``Y`` over
the whole part, and its distance outside its window

``D(t) = max(x(t) − c − Y, Y − x(t) − c)``

is the larger of two lines in ``t``: where ``x`` grows it reaches its cap where ``x(t) = Y + c``, where ``x`` falls
where ``x(t) = Y − c``, one division per spring (:func:`reach_times`). The events' search of :mod:`.play_run` reads
the first spring's time (the slip onset: the least of them) or the last one's (full slip: the greatest) in place of
Brent's root of the springs' largest or least distance (:func:`~.play_search.brent`, 10–50 sequential readings where
the distance is flat to round-off before the front starts), and checks the bracket it gives on the share at a cap as
before. Anywhere else (the depth or the radius moving, with ``τ0``'s part its cap ``ū(a(t))`` moving) the closed form
does not apply and :func:`constant_part` says so.
"""

from __future__ import annotations

import numpy as np

__all__ = ["constant_part", "reach_times", "reach_ulps", "pressed_time", "REACH_ULPS", "REACH_ULPS_CAP",
           "PRESSED_STEPS"]

#: The units in the last place of a time a closed-form reach and the route's own reading of a spring's cap can differ
#: by besides the anchors' round-off over the speed (:func:`reach_ulps`): each rounds a time once or twice.
REACH_ULPS = 4
#: The widest window :func:`reach_ulps` gives (ulps): ``2**53`` units in the last place of a time span about twice the
#: time itself, so a wider one tells no more (at ``time = 0``, whose ulp is the least subnormal, the count would not be
#: finite).
REACH_ULPS_CAP = 2**53


#: The fixed-point steps of :func:`pressed_time` at most (each moves the time by the profile's value at the centre
#: probe, ``EDGE_SHARE²`` of the depth on a paraboloid, ``EDGE_SHARE`` on a cone: two or three steps reach the fixed
#: point).
PRESSED_STEPS = 8


def constant_part(play, low: float, high: float) -> float | None:
    """The start of the part of ``(low, high]`` along which every spring's window is fixed but for ``x`` (module
    docstring): the last clamp time of the springs' chain inside it (or ``low``), ``None`` where that part is not one.

    Parameters
    ----------
    play : PlaySprings
        The springs.
    low, high : float
        The interval (s, path clock), ``low < high``.

    Returns
    -------
    float or None
        The part's start ``s`` (the windows are fixed on ``(s, high]``).
    """
    chain = play.chain
    inside = chain.times[(chain.times > low) & (chain.times < high)]
    start = float(inside[-1]) if inside.size else float(low)
    if np.any((chain.convex[:, 0] < high) & (chain.convex[:, 1] > start)):  # (springs' own extremes: never at rest,
        return None  # but the chain's own bookkeeping says so)
    corner_t, corner_d = play.path_corners()[::2]
    k = int(np.searchsorted(corner_t, start, side="right")) - 1
    if not 0 <= k < corner_t.size - 1 or corner_d[k] != corner_d[k + 1] or corner_t[k + 1] < high:
        return None
    if any(begin < high and end > start for begin, end in play.history.pieces()):
        return None
    radii = play.history.radii(np.array([0.5 * (start + high), high]))
    return start if radii[0] == radii[1] and radii[1] > 0.0 else None


def reach_times(play, xi: np.ndarray, start: float, high: float) -> tuple[np.ndarray, np.ndarray]:
    """Where each spring's distance outside its window (:meth:`~.play_springs.PlaySprings.outside`) first and last
    turns non-negative on ``(start, high]``, a part of :func:`constant_part`: ``start`` where it is at its cap from the
    part's start, ``inf`` where it stays inside up to ``high``.

    Parameters
    ----------
    play : PlaySprings
        The springs.
    xi : numpy.ndarray
        The springs' coordinates (m), within the contact on the part.
    start, high : float
        The part (s, path clock).

    Returns
    -------
    tuple of numpy.ndarray
        The first and the last time of each spring (s, path clock).
    """
    before, lower, upper = play.windows_before(xi, high)
    corner_t, corner_x, _ = play.path_corners()
    k = int(np.searchsorted(corner_t, start, side="right")) - 1
    speed = (corner_x[k + 1] - corner_x[k]) / (corner_t[k + 1] - corner_t[k])
    below, above = lower - before, before - upper  # (at ``high``; ``D = max(below, above)``)
    if speed == 0.0:
        outside = np.maximum(below, above) >= 0.0
        first = np.where(outside, start, np.inf)
        return first, first
    # (the side the motion pushes towards: its distance grows by ``|speed|`` a second; the other side's falls)
    rising, falling = (below, above) if speed > 0.0 else (above, below)
    rate = abs(speed)
    crossing = high - rising / rate  # (the rising side's zero)
    at_start = (rising - rate * (high - start) >= 0.0) | (falling + rate * (high - start) >= 0.0)
    reached = rising >= 0.0
    first = np.where(at_start, start, np.where(reached, np.maximum(crossing, start), np.inf))
    last = np.where(reached, np.maximum(crossing, start), np.where(falling >= 0.0, start, np.inf))
    return first, last


def reach_ulps(play, start: float, time: float) -> int:
    """How many units in the last place of ``time`` a closed-form reach on the part from ``start``
    (:func:`reach_times`) and the route's own reading of the distances (:meth:`~.play_springs.PlaySprings.outside`)
    can put a spring's reach apart: each distance is a difference of anchors and edges of the path's size ``|x|``,
    rounded to ``eps |x|`` (a few roundings each way), which ``x``'s speed turns into ``eps |x| / |ẋ|`` of time, and
    each time is rounded: :data:`REACH_ULPS` plus four times the former in ulps of ``time``, at most
    :data:`REACH_ULPS_CAP` of them (a ``time`` near 0).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    start : float
        The part's start (s, path clock).
    time : float
        The reach (s, path clock).

    Returns
    -------
    int
        The window (ulps).
    """
    corner_t, corner_x, _ = play.path_corners()
    k = int(np.searchsorted(corner_t, start, side="right")) - 1
    speed = abs(corner_x[k + 1] - corner_x[k]) / (corner_t[k + 1] - corner_t[k])
    if not speed > 0.0:
        return REACH_ULPS
    scale = float(np.max(np.abs(corner_x)))
    with np.errstate(over="ignore"):  # (an ulp of a time near 0 is subnormal: the count overflows, capped)
        ulps = np.float64(4.0 * np.finfo(float).eps * scale / speed) / np.spacing(np.float64(abs(time)))
    return REACH_ULPS + int(min(np.ceil(ulps), REACH_ULPS_CAP))


def pressed_time(play, low: float, high: float) -> float | None:
    """Where, in ``[low, high]``, the centre probe of the kink search first counts as compressed
    (:meth:`~.play_springs.PlaySprings.centre_pressed`: ``d(t) − g(EDGE_SHARE a(t))`` above the pressed round-off), in
    closed form on the depth alone: ``d`` is linear between the path's corners, so the time it reaches a depth is one
    division; the depth to reach, the round-off plus the profile at the probe at the time found last, taken to its
    fixed point (:data:`PRESSED_STEPS`; the probe's ``g`` is ``EDGE_SHARE²`` of the depth on a paraboloid). Along
    scenario A under Coulomb's law alone every compressed spring slides from its attachment, so from that time on
    the share at a cap is 1 (:func:`~.play_run._bisect` checks it).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    low, high : float
        The interval (s, path clock).

    Returns
    -------
    float or None
        The time (s, path clock) to the depth's rounding; ``None`` where the depth does not reach it by ``high``.
    """
    from .play_springs import EDGE_SHARE

    # (no convergence test but equality, at most PRESSED_STEPS: the time is a seed, not the answer. What makes the
    # answer right is not this iteration but the checks of it: play_run._pressed_root's two readings of the compressed
    # test either side of the time (a time off the fixed point fails them and the compressed test is bisected
    # instead), and play_run._bisect's check of the bracket found on the share itself (a wrong one fails it and the
    # guess is bisected as before))
    time = None
    for _ in range(PRESSED_STEPS):
        radius = play.radius(low if time is None else time)
        found = _depth_time(play, low, high, play.pressed_round_off
                            + float(play.line.profile(np.array([EDGE_SHARE * radius]))[0]))
        if found is None or found == time:
            return found
        time = found
    return time


def _depth_time(play, low: float, high: float, depth: float) -> float | None:
    """The first time in ``[low, high]`` the path's depth (linear between its corners) reaches ``depth``; ``None``
    where it does not."""
    corner_t, _, corner_d = play.path_corners()
    times = np.concatenate([[low], corner_t[(corner_t > low) & (corner_t < high)], [high]])
    depths = np.interp(times, corner_t, corner_d)
    reached = np.flatnonzero(depths >= depth)
    if not reached.size:
        return None
    k = int(reached[0])
    if k == 0:
        return float(low)
    t0, t1, d0, d1 = (float(value) for value in (times[k - 1], times[k], depths[k - 1], depths[k]))
    return min(max(t0 + (depth - d0) / (d1 - d0) * (t1 - t0), t0), t1)
