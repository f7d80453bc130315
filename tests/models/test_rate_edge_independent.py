"""Issue 29, item 3: the force–time curve of :func:`~mdr_events.models.continuum.rate_edge.solve_edge` against an
independent integration of the normal problem, written here from Heß's rule alone: on the paraboloid the release rate
of an edge at radius ``a`` and depth ``d`` is ``Γ = E* (a²/R − d)² / (2π a)``; the law gives the edge's speed
``ȧ = v_ref (Δγ0/Γ − 1)^(1/n)`` where ``Γ < Δγ0`` (advancing), ``ȧ = −v_ref (Γ/Δγ1 − 1)^(1/n)`` where ``Γ > Δγ1``
(receding), 0 between (resting); ``F_N = E* (2 d a − 2a³/(3R))``. SciPy's DOP853 (an explicit Runge–Kutta method,
neither of the edge's Radau/LSODA) integrates it from a radius of the reference shortly after the jump-in (where the
edge's speed is unbounded) through the way in, the turn and the way out to near the contact's end."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import mdr_events as me
from mdr_events.models.continuum.rate_edge import EdgeEventKind, solve_edge

PAPER = me.Parameters.paper()
#: The curves' largest difference relative to the force's range: the edge's ODE runs at rtol 1e-10 (EDGE_RTOL), the
#: independent one at 1e-12; a radius error of 1e-10 moves F_N by about as much of its range, and up to a hundred
#: times more where the edge recedes fast near the end (measured: 1.5e-11 for n = 0.5).
CURVE_RTOL = 1e-8
#: The share of the way in after which the independent integration starts (the jump-in's unbounded speed before),
#: and the share of the way out to the contact's end it runs to (the collapse at the end is a jump).
START_SHARE, END_SHARE = 0.05, 0.9


def independent_normal_force(law: me.RateDependentAdhesion, path: me.Path, start: float, radius: float,
                             times: np.ndarray) -> np.ndarray:
    """``F_N`` at ``times`` (path clock, increasing, after ``start``) from the radius ``radius`` at ``start``, by
    DOP853 on each of the path's straight segments (the depth's kink at a corner a restart)."""
    e_star = PAPER.E / (1.0 - PAPER.nu ** 2)

    def speed_on(low: float, high: float):
        """The edge's speed on the segment ``[low, high]``, where the depth is linear in time."""
        d_low, d_high = (float(d) for d in path.position(np.array([low, high]))[1])
        slope = (d_high - d_low) / (high - low)

        def speed(t, state):
            a, d = state[0], d_low + slope * (t - low)
            release = e_star * (a * a / PAPER.R - d) ** 2 / (2.0 * math.pi * a)
            if release < law.dgamma0:
                return [law.v_ref * (law.dgamma0 / release - 1.0) ** (1.0 / law.n)]
            if release > law.dgamma1:
                return [-law.v_ref * (release / law.dgamma1 - 1.0) ** (1.0 / law.n)]
            return [0.0]
        return speed

    knots = [start, *[t for t in path.corner_times if start < t < times[-1]], times[-1]]
    radii, state = [], [radius]
    for low, high in zip(knots[:-1], knots[1:]):
        inside = times[(times > low) & (times <= high)] if radii else times[(times >= low) & (times <= high)]
        run = solve_ivp(speed_on(low, high), (low, high), state, method="DOP853", rtol=1e-12, atol=1e-15,
                        dense_output=True)
        assert run.success, run.message
        radii.append(run.sol(inside)[0])
        state = [float(run.sol(high)[0])]
    a = np.concatenate(radii)
    depth = path.position(times)[1]
    return e_star * (2.0 * depth * a - 2.0 * a ** 3 / (3.0 * PAPER.R))


@pytest.mark.parametrize("v_ref, n, speed", [
    pytest.param(1e-6, 0.5, 1e-6, marks=pytest.mark.slow),  # (~4 s of CPU: the slow path's long resting edge; the
    (1e-7, 1.0, 1e-6), (1e-6, 0.6, 1e-5)])                  # other two cover every regime in ~2 s each)
def test_the_edge_s_force_is_that_of_an_independent_integration(v_ref, n, speed):
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, v_ref, n)
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -2e-4)]), speed=speed)
    reference = solve_edge(PAPER, path, law)
    ends = [event.time for event in reference.events if event.kind is EdgeEventKind.CONTACT_ENDS]
    turn = float(path.corner_times[1])
    end = ends[0] if ends else path.duration
    start = START_SHARE * turn
    times = np.linspace(start, turn + END_SHARE * (end - turn), 600)
    exact = reference.normal_force(times, path)
    found = independent_normal_force(law, path, start, float(reference.radius(np.array([start]))[0]), times)
    assert np.max(np.abs(found - exact)) <= CURVE_RTOL * np.ptp(exact), np.max(np.abs(found - exact)) / np.ptp(exact)
    kinds = {event.kind for event in reference.events}
    assert {EdgeEventKind.EDGE_STOPS, EdgeEventKind.RECEDING_STARTS} <= kinds  # (every regime compared)
