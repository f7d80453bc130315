"""The per-spring route's own machinery (``mdr_events.models.continuum.play_springs``, review notes S4 and S6 of issue
34): the golden sections where ``ū(a(t))`` is not concave, against a brute-force play operator on a fine time grid;
every spring in contact matching an attachment of the radius's history (the centre spring at a jump-in included), and
one that matches none an internal error, not an anchor clamped from the path's start.

Tolerances: the brute-force play clamps each spring at ``n`` equally spaced times, missing a window's extremum between
two of them by ``O((Δt)²)`` (second order: its error at ``2n`` is about a third of the change from ``n`` to ``2n``); the
route, exact up to its golden sections' ``0.618^80`` of an interval, must lie within that change of the finer run.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

import mdr_events as me
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum.play_springs import (GOLDEN_TABLE_POINTS, GOLDEN_TABLE_RTOL, PlaySprings,
                                                       SpanHistory, spring_line)
from play_recorders import made_plays

#: A power law with ``n < 1`` (``g = c x^0.5``): ``a ∝ d²``, so the cap ``ū = K a`` is convex along a straight segment
#: and the lower window ``x − c`` of a spring can have its maximum inside a segment (the route's golden sections).
CONVEX = me.PowerLaw(2e-2, 0.5)
LAW = me.FrictionLaw("tau0+coulomb", mu=0.05, tau0=42000.0)
D_MAX = me.Parameters.paper().d_max
#: The slope ``dx/dd`` of the loading segment: between the cap's slopes ``dc/dd`` at its start and end (0.10 and 0.26
#: at the centre), so that ``x − c`` rises, then falls inside it.
SLOPE = 0.18
#: The brute-force play's time steps (the finer doubles them).
STEPS = 4000
#: Without the golden sections the anchors are off by far more than the brute force's own error (3e-5 of the largest
#: shift measured, against 6e-9): the test tells the two apart by this factor at least.
MISSED = 100.0


def convex_play() -> tuple[PlaySprings, me.Path]:
    contact = dataclasses.replace(me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0), friction=LAW, indenter=CONVEX)
    params = contact.parameters(D_MAX, me.Parameters.paper().v)
    path = me.Path(np.array([[0.0, -1e-6], [SLOPE * D_MAX, D_MAX], [0.1 * D_MAX, 0.6 * D_MAX]]),
                   me.Parameters.paper().v)
    return PlaySprings(spring_line(params, CONVEX, LAW), path), path


def brute_force(play: PlaySprings, xi: np.ndarray, t: float, steps: int) -> np.ndarray:
    """Each spring's anchor clamped to its window at ``steps`` equally spaced times from its attachment to ``t``."""
    start, _ = play.history.attach(xi, t)
    g, ratio = play.line.profile(xi), play.line.ratio(xi)
    times = np.linspace(0.0, 1.0, steps)[:, None] * (t - start)[None, :] + start[None, :]
    x, d = play._x(times), play._d(times)
    cap = play.line.shift(play.history.radii(times.ravel())).reshape(times.shape) + ratio * np.maximum(d - g, 0.0)
    anchor = x[0].copy()
    for k in range(1, steps):
        anchor = np.clip(anchor, x[k] - cap[k], x[k] + cap[k])
    return anchor


@pytest.mark.parametrize("share", [0.999, 1.5], ids=["end of loading", "coming back"])
def test_where_the_cap_is_convex_in_time_the_golden_sections_give_the_brute_force_play(share):
    """S4: along a segment where ``ū(a(t))`` is convex (the chain flags it), each spring's extremum of its window
    inside the segment is found by golden sections: the anchors are the brute-force play's on a fine grid, and
    without the golden sections they are not."""
    play, path = convex_play()
    assert play.chain.convex.size, "no interval flagged: the test does not reach the golden sections"
    t = float(path.corner_times[1] * share if share < 1.0 else path.corner_times[1] + (share - 1.0) * (
        path.corner_times[2] - path.corner_times[1]))
    xi = play.radius(t) * np.linspace(0.01, 0.99, 50)
    route = play.anchors(xi, t)[0]
    coarse, fine = brute_force(play, xi, t, STEPS), brute_force(play, xi, t, 2 * STEPS)
    own = np.max(np.abs(coarse - fine))
    assert np.max(np.abs(route - fine)) <= own
    flagged = play.chain
    play.chain = flagged._replace(convex=np.empty((0, 2)))
    try:
        without = play.anchors(xi, t)[0]
    finally:
        play.chain = flagged
    assert np.max(np.abs(without - fine)) > MISSED * own


def adhesive_play(works=(0.05, 0.05)):
    contact = dataclasses.replace(me.Contact.paper().replace(dgamma0=works[0], dgamma1=works[1]), friction=LAW)
    params = contact.parameters(D_MAX, me.Parameters.paper().v)
    x, d = [0.0, 0.0, 0.0, 0.0, 1e-4], [-1e-6, D_MAX, -4e-5, D_MAX, D_MAX]  # (in, out beyond the jump-off, in again)
    path = me.Path(np.column_stack([x, d]), me.Parameters.paper().v)
    solution = solve_path(params, path, me.Tolerances(), me.Limits(), None, me.FrictionLaw("coulomb", mu=0.0),
                          contact.adhesion)
    return PlaySprings(spring_line(params, None, LAW), path, SpanHistory(solution)), path


def test_the_centre_spring_attaches_at_a_jump_in_and_at_a_re_contact():
    """S6: the centre spring ``ξ = 0`` is reached by the radius's jump from 0 at the first contact and at the
    re-contact (before: no attachment matched it, its start ``−inf`` and its anchor clamped from the path's start)."""
    play, path = adhesive_play()
    jumps_in = [time for time, before, _ in play.history.jumps if before == 0.0]
    assert len(jumps_in) == 2, play.history.jumps
    for time in jumps_in:
        later = time + 1e-3 * (path.corner_times[-1] - time)
        start, _ = play.history.attach(np.array([0.0, 0.5 * play.radius(later)]), later)
        assert start.tolist() == [time, time]
    t = float(path.corner_times[-1])
    anchor = play.anchors(np.array([0.0]), t)[0]
    assert np.isfinite(anchor).all()


def test_a_spring_matching_no_attachment_is_an_internal_error():
    """S6: a spring out of contact at ``t`` matches no attachment: ``anchors`` raises, naming it, rather than clamping
    its anchor from the path's start."""
    play, path = adhesive_play()
    t = float(path.corner_times[1])
    outside = 2.0 * play.radius(t)
    with pytest.raises(RuntimeError) as caught:
        play.anchors(np.array([0.1 * outside, outside]), t)
    assert "match no attachment" in str(caught.value) and repr(outside) in str(caught.value)


@pytest.fixture(scope="module")
def cone_on_a_layer_play() -> tuple[PlaySprings, me.Path]:
    """The springs of issue 32's W8 run, as the run makes them: a cone on a 2 mm layer under ``τ0`` + Coulomb with
    the paper's adhesion, scenario A at 45° (its ``ū(a(t))`` is convex on a stretch: the golden sections read it from
    a spline)."""
    law = me.FrictionLaw("tau0+coulomb", tau0=me.Parameters.paper().tau0, mu=0.5)
    contact = dataclasses.replace(me.Contact.paper(), friction=law, layer=me.Layer(2e-3), indenter=me.PowerLaw(0.2, 1.0))
    with pytest.MonkeyPatch.context() as patch:
        made = made_plays(patch)
        me.simulate(contact, "A", [45.0], "continuum", samples=5)
    (play,) = made
    return play, play.path


def test_the_golden_sections_spline_is_the_cap_within_its_tolerance_between_its_nodes(cone_on_a_layer_play):
    """W8: the spline each convex stretch's golden sections read ``ū(a(t))`` from is checked at its grid's midpoints
    only; at points anywhere on the stretch it lies within ``GOLDEN_TABLE_RTOL`` of the largest ``ū`` too (the
    midpoints are where a cubic spline's error peaks; a coarser grid, which fails the check, is off by more)."""
    play, _ = cone_on_a_layer_play
    assert play.chain.convex.size, "no convex stretch: the test does not reach the splines"
    tables = play._convex_tables()
    assert all(table is not play._exact_shift for table in tables), "no grid reached the tolerance"
    for (lo, hi), table in zip(play.chain.convex, tables[::2]):
        times = np.random.default_rng(7).uniform(lo, hi, 2000)
        exact = play._exact_shift(times)
        scale = np.max(np.abs(play._exact_shift(np.linspace(lo, hi, 65))))
        assert np.max(np.abs(table(times) - exact)) <= GOLDEN_TABLE_RTOL * scale
        coarse = CubicSpline(np.linspace(lo, hi, GOLDEN_TABLE_POINTS[0]),
                             play._exact_shift(np.linspace(lo, hi, GOLDEN_TABLE_POINTS[0])))
        assert np.max(np.abs(coarse(times) - exact)) > GOLDEN_TABLE_RTOL * scale


@pytest.mark.parametrize("share", [0.999, 1.5], ids=["end of loading", "coming back"])
def test_the_golden_sections_on_the_spline_give_the_anchors_of_the_exact_cap(share):
    """W8: with each golden step reading the stretch's spline (within ``ε = GOLDEN_TABLE_RTOL`` of the largest ``ū``)
    the anchors are those of the sections reading ``ū(a(t))`` exactly, within ``2ε`` of it: a section's maximum of an
    edge read within ``ε`` lies within ``2ε`` of the true one, and the clamp's value is read exactly at the time
    found (on :func:`convex_play`, whose anchors the sections' extremes set: see the test above)."""
    play, path = convex_play()
    t = float(path.corner_times[1] * share if share < 1.0 else path.corner_times[1] + (share - 1.0) * (
        path.corner_times[2] - path.corner_times[1]))
    xi = play.radius(t) * np.linspace(0.01, 0.99, 50)
    splined = play.anchors(xi, t)[0]
    assert all(table is not play._exact_shift for table in play._tables), "no grid reached the tolerance"
    scale = max(np.max(np.abs(play._exact_shift(np.linspace(lo, hi, 65)))) for lo, hi in play.chain.convex)
    play._tables = [play._exact_shift] * len(play._tables)
    exact = play.anchors(xi, t)[0]
    assert np.max(np.abs(splined - exact)) <= 2.0 * GOLDEN_TABLE_RTOL * scale
