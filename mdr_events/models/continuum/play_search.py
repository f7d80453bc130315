"""Searches run side by side, each a generator that yields the readings it needs and is sent their values
(:func:`searched`): the events of the per-spring route (:mod:`.play_run`) read every step's times of all their searches
in one batch. Brent's root (:func:`brent`, scipy's ``brentq`` step for step) and the halvings of a bracket
(:func:`halve`, :data:`TREE_LEVELS` a step) as such searches.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["searched", "brent", "halve", "EVENT_HALVINGS", "TREE_LEVELS", "BRENT_ITERATIONS"]

#: Halvings of an event's bracket between two samples (2^-48 of it: 1e-14 of the spacing).
EVENT_HALVINGS = 48
#: The halvings of an event's bracket taken a step (:func:`halve`): the ``2^TREE_LEVELS − 1`` midpoints they can
#: visit read at once (a reading's fixed cost, about 0.6 ms on a layer, over three times' 0.1-0.3 ms each; of one to
#: four levels two measured fastest on the benchmark's Coulomb rows).
TREE_LEVELS = 2
#: Brent's iterations before the halvings go on alone (scipy's ``brentq``'s default).
BRENT_ITERATIONS = 100


def searched(read, searches: list) -> list:
    """Run ``searches`` (generators yielding a tuple of ``(reading, time)`` asks and sent their values) side by side:
    each step's asks of all of them read at once by ``read`` (a list of asks to a list of values); their results in
    their order. Each search reads what it would read alone where ``read`` gives each ask its own value.

    Parameters
    ----------
    read : callable
        The values of a list of ``(reading, time)`` asks.
    searches : list of generator
        The searches.

    Returns
    -------
    list
        Each search's result (its return value).
    """
    results, asks = [None] * len(searches), {}

    def advance(index: int, values) -> None:
        try:
            asks[index] = searches[index].send(values)
        except StopIteration as stop:
            results[index] = stop.value
            asks.pop(index, None)

    for index in range(len(searches)):
        advance(index, None)
    while asks:
        flat = [(index, reading, time) for index, pending in asks.items() for reading, time in pending]
        values = read([(reading, time) for _, reading, time in flat])
        given: dict[int, list] = {}
        for (index, _, _), value in zip(flat, values):
            given.setdefault(index, []).append(value)
        for index, value in given.items():
            advance(index, tuple(value))
    return results


def brent(reading, xa: float, xb: float, fa: float, fb: float):
    """The root of the ``reading`` between ``xa`` and ``xb`` by Brent's method (Brent 1973, as scipy's ``brentq``
    steps it, at ``xtol`` an ulp of ``xb`` and ``rtol`` four epsilons: its root and readings, bit for bit), as a search
    of :func:`searched`.

    Parameters
    ----------
    reading : object
        What each ask reads (the first item of its ``(reading, time)``).
    xa, xb : float
        The bracket's ends.
    fa, fb : float
        The reading's values there.

    Yields
    ------
    tuple
        One ask ``(reading, time)`` a step, sent back its value (a tuple of one float).

    Returns
    -------
    float or None
        The root; ``None`` where a value is ``nan``, the signs at the ends do not differ, or it does not converge in
        :data:`BRENT_ITERATIONS` steps (where ``brentq`` raises).
    """
    xtol, rtol = float(np.spacing(xb)), 4.0 * float(np.finfo(float).eps)
    xpre, xcur, fpre, fcur = xa, xb, fa, fb
    xblk = fblk = spre = scur = 0.0
    if np.isnan(fpre) or np.isnan(fcur):
        return None
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        return None
    for _ in range(BRENT_ITERATIONS):
        if fpre != 0.0 and fcur != 0.0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2.0
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        spre, scur = _step(xpre, xcur, xblk, fpre, fcur, fblk, spre, scur, sbis, delta)
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0.0 else -delta)
        fcur = (yield ((reading, xcur),))[0]
        if np.isnan(fcur):
            return None
    return None


def _step(xpre, xcur, xblk, fpre, fcur, fblk, spre, scur, sbis, delta) -> tuple[float, float]:
    """Brent's next step: the interpolation's or extrapolation's where it is short and good, else the bisection's
    (scipy's ``brentq``)."""
    if abs(spre) > delta and abs(fcur) < abs(fpre):
        if xpre == xblk:  # (interpolate)
            stry = -fcur * (xcur - xpre) / (fcur - fpre)
        else:  # (extrapolate)
            dpre, dblk = (fpre - fcur) / (xpre - xcur), (fblk - fcur) / (xblk - xcur)
            stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
        if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
            return scur, stry
    return sbis, sbis


def halve(low: float, high: float, reached):
    """The bracket of :data:`EVENT_HALVINGS` halvings of ``[low, high]``, :data:`TREE_LEVELS` halvings a step: every
    midpoint the next ones can visit asked at once (:func:`_answers`), then the halvings walked through their answers
    (the bracket of halving one at a time, bit for bit, whatever ``reached`` does between them).

    Parameters
    ----------
    low, high : float
        The bracket (``reached`` false at ``low``, true at ``high``).
    reached : callable
        A time to a search of :func:`searched` whose result tells whether the time is past the event.

    Yields
    ------
    tuple
        The asks of every midpoint's search at a step, sent back their values.

    Returns
    -------
    tuple of float
        The last bracket.
    """
    done = 0
    while done < EVENT_HALVINGS:
        levels = min(TREE_LEVELS, EVENT_HALVINGS - done)
        answers = yield from _answers(reached, _tree(low, high, levels))
        for _ in range(levels):
            middle = 0.5 * (low + high)
            if middle in (low, high):
                return low, high
            if answers[middle]:
                high = middle
            else:
                low = middle
        done += levels
    return low, high


def _tree(low: float, high: float, levels: int) -> list[float]:
    """The midpoints ``levels`` halvings of ``[low, high]`` can visit (none of a bracket with no double inside)."""
    out, brackets = [], [(low, high)]
    for _ in range(levels):
        following = []
        for below, above in brackets:
            middle = 0.5 * (below + above)
            if middle not in (below, above):
                out.append(middle)
                following += [(below, middle), (middle, above)]
        brackets = following
    return out


def _answers(reached, times: list[float]):
    """``reached`` at each of ``times`` (a search of :func:`searched`): every time's asks of a step asked together."""
    answers, pending = {}, []

    def advance(time: float, search, values) -> None:
        try:
            pending.append((time, search, search.send(values)))
        except StopIteration as stop:
            answers[time] = stop.value

    for time in times:
        advance(time, reached(time), None)
    while pending:
        asked, pending = pending, []
        values = yield tuple(ask for _, _, asks in asked for ask in asks)
        first = 0
        for time, search, asks in asked:
            advance(time, search, tuple(values[first:first + len(asks)]))
            first += len(asks)
    return answers
