"""The golden sections of :mod:`mdr_events.models.continuum.play_golden`: the one-evaluation-a-step route against
the route it replaced (both inner points evaluated anew each step) and against the closed-form maximum."""

from __future__ import annotations

import numpy as np
import pytest

from mdr_events.models.continuum.play_golden import GOLDEN_STEPS, _golden

#: The bracket left after the steps, as a share of the interval: 0.618^GOLDEN_STEPS (the final midpoint lies within
#: half of it from the maximum, whichever route); twice it allows for either route's bracket about the true one, and
#: 64 ulps of the interval's ends for the round-off of the bracket's ends (the points' recurrences differ).
BRACKET_SHARE = (0.5 * (np.sqrt(5.0) - 1.0)) ** GOLDEN_STEPS
ROUND_OFF_SHARE = 64 * np.finfo(float).eps


def _golden_both(function, low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """``play_golden._golden`` with both inner points evaluated anew each step: the route before it, kept here to
    compare the two."""
    ratio = 0.5 * (np.sqrt(5.0) - 1.0)
    empty = ~(high > low)
    a, b = np.where(empty, 0.0, low), np.where(empty, 1.0, high)
    c, e = b - ratio * (b - a), a + ratio * (b - a)
    fc, fe = function(c), function(e)
    for _ in range(GOLDEN_STEPS):
        left = fc > fe
        b = np.where(left, e, b)
        a = np.where(left, a, c)
        c, e = b - ratio * (b - a), a + ratio * (b - a)
        fc, fe = function(c), function(e)
    return np.where(empty, np.nan, 0.5 * (a + b))


def _quartic_rows(seed: int, rows: int):
    """Rows of a strictly concave quartic ``−(t − m)²(1 + k (t − m)²)`` with its maximum ``m`` inside ``[low, high]``
    (a smooth, unimodal function with known argmax), or outside it on some rows (then at an end)."""
    rng = np.random.default_rng(seed)
    low = rng.uniform(-1.0, 1.0, rows)
    high = low + rng.uniform(1e-6, 3.0, rows)
    peak = low + (high - low) * rng.uniform(-0.3, 1.3, rows)
    k = rng.uniform(0.0, 5.0, rows)

    def function(t):
        u = t - peak
        return -u * u * (1.0 + k * u * u)

    return function, low, high, np.clip(peak, low, high)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_one_evaluation_a_step_finds_the_maximum_the_two_evaluation_route_finds(seed):
    function, low, high, peak = _quartic_rows(seed, 500)
    calls = []

    def counted(t):
        calls.append(t.size)
        return function(t)

    new, old = _golden(counted, low, high), _golden_both(function, low, high)
    width = high - low
    tolerance = (BRACKET_SHARE + ROUND_OFF_SHARE) * width + ROUND_OFF_SHARE * np.maximum(np.abs(low), np.abs(high))
    assert np.all(np.abs(new - peak) <= tolerance), np.max(np.abs(new - peak) / width)
    assert np.all(np.abs(new - old) <= 2 * tolerance), np.max(np.abs(new - old) / width)
    assert len(calls) == GOLDEN_STEPS + 2  # (one evaluation a step, two to start: the old route's 2 + 2 per step)


def test_empty_intervals_give_nan_on_both_routes():
    low, high = np.array([0.0, 1.0, 2.0]), np.array([1.0, 1.0, 1.5])
    for route in (_golden, _golden_both):
        found = route(lambda t: -(t - 0.25) ** 2, low, high)
        assert abs(found[0] - 0.25) < 1e-8 and np.all(np.isnan(found[1:]))


@pytest.mark.parametrize("share", [0.5, 0.999, 1.5], ids=["loading", "end of loading", "coming back"])
def test_the_edges_extremes_taken_at_the_stretch_start_are_where_the_golden_sections_end(share, monkeypatch):
    """X5: the rows whose edge (concave on the stretch) does not rise at its start skip their golden sections and take
    the start itself; a section would end within its final bracket of it (``BRACKET_SHARE`` of the interval). Every
    row's time is the sections' within that bracket (nan where theirs is), on :func:`convex_play`, whose edges rise,
    then fall inside the loading segment: both kinds of row."""
    from test_play_springs import convex_play

    from mdr_events.models.continuum.play_springs import PlaySprings

    play, path = convex_play()
    t = float(path.corner_times[1] * share if share < 1.0 else path.corner_times[1] + (share - 1.0) * (
        path.corner_times[2] - path.corner_times[1]))
    xi = play.radius(t) * np.linspace(0.01, 0.99, 50)
    g, ratio = play.line.profile(xi), play.line.ratio(xi)
    start, _ = play.history.attach(xi, t)
    taken = []
    shortcut = PlaySprings._extreme_at_low

    def recorded(self, *args):
        taken.append(shortcut(self, *args))
        return taken[-1]

    monkeypatch.setattr(PlaySprings, "_extreme_at_low", recorded)
    skipped = np.concatenate(play._own_times(xi, g, ratio, start, t))
    monkeypatch.setattr(PlaySprings, "_extreme_at_low", lambda self, low, *args: np.zeros(low.shape, bool))
    sections = np.concatenate(play._own_times(xi, g, ratio, start, t))
    assert np.count_nonzero(taken[0]) > 0, "no row skipped its section: the test does not reach the shortcut"
    assert np.count_nonzero(~taken[0] & np.isfinite(sections)) > 0, "no row kept its section"
    np.testing.assert_array_equal(np.isnan(skipped), np.isnan(sections))
    width = float(np.max(np.diff(play.chain.convex, axis=1)))
    tolerance = (BRACKET_SHARE + ROUND_OFF_SHARE) * width + ROUND_OFF_SHARE * t
    live = np.isfinite(sections)
    assert np.max(np.abs(skipped[live] - sections[live])) <= tolerance
