"""The edge's steps as polynomials (continuum.rate_dense): the values of solve_ivp's dense output to a few ulp. What
they are for, the continuum's scenario A under the rate-dependent law within issue 29's 3× of the paper's, is measured
side by side by benchmarks/bench_rate_adhesion.py (speed targets live there, not in timed tests)."""

from __future__ import annotations


import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import solve_edge, solve_rate_shifts
from mdr_events.models.continuum.rate_dense import StepPolynomials, step_polynomials

PAPER = me.Parameters.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
#: The same polynomials summed by Horner's rule instead of powers: a few ulp of the radius (measured below 4e-16 of
#: the largest), so 1e-14 of it.
SUMMATION_RTOL = 1e-14


@pytest.mark.parametrize("method", ["Radau", "LSODA"])
def test_the_polynomials_give_the_dense_output_s_values(method):
    path = me.Path.scenario_A(20.0, PAPER)
    run = solve_edge(PAPER, path, LAW, method=method)
    moving = [piece[3] for piece in run.pieces if hasattr(piece[3], "interpolants")]
    assert moving
    rng = np.random.default_rng(3)
    for dense in moving:
        fast = step_polynomials(dense)
        assert isinstance(fast, StepPolynomials)
        times = np.concatenate([dense.ts, rng.uniform(dense.ts[0], dense.ts[-1], 4000)])
        scale = np.max(np.abs(dense(times)[0]))
        np.testing.assert_allclose(fast(times)[0], dense(times)[0], rtol=0.0, atol=SUMMATION_RTOL * scale)
        assert fast(float(times[7])).shape == dense(float(times[7])).shape == (1,)


#: Where StepPolynomials.reach and the closed-form inverse of x meet the bisection they replace: a Newton step below
#: the clock's spacing against the least double reached by 64 halvings (a few ulp of the clock's time).
REACH_ULPS = 8


def test_reach_finds_the_first_time_the_radius_reaches_a_value_as_the_bisection_does():
    from mdr_events.models.continuum.rate_shifts import _bisect

    path = me.Path.scenario_A(20.0, PAPER)
    run = solve_edge(PAPER, path, LAW, method="LSODA")
    dense = next(piece[3] for piece in run.pieces if hasattr(piece[3], "interpolants"))
    fast = step_polynomials(dense)
    lo, end = float(dense.ts[0]), float(dense.ts[-1])
    rng = np.random.default_rng(5)
    hi = rng.uniform(lo, end, 300)
    # (half of them reached before hi, half not; values between those of two doubles of the clock)
    target = fast(rng.uniform(lo, end, 300))[0] * (1.0 + rng.uniform(-1e-12, 1e-12, 300))
    found = fast.reach(target, lo, hi)
    expected = _bisect(lambda t: fast(t)[0], np.full(hi.shape, lo), hi, target)
    np.testing.assert_allclose(found, expected, rtol=0.0, atol=REACH_ULPS * np.spacing(end))
    assert np.all(found <= hi) and np.all(found[fast(hi)[0] < target] == hi[fast(hi)[0] < target])
    # one by one too (a Newton iterate that converged from below once returned its bracket's stale end)
    alone = np.array([fast.reach(target[index:index + 1], lo, hi[index:index + 1])[0] for index in range(100)])
    np.testing.assert_allclose(alone, expected[:100], rtol=0.0, atol=REACH_ULPS * np.spacing(end))
    # and bit for bit the time found among the others (each target's iteration stops at its own convergence: the
    # play's force at many times at once is the force at each alone)
    np.testing.assert_array_equal(alone, found[:100])


#: Where StepPolynomials.reach's Newton steps (a secant's start, a probe below an iterate that converged from above)
#: meet the 64 halvings of the bisection: both are the least double at which the step's polynomial reaches the value;
#: they can differ only where that double is a step's end, at which the bisection reads the next step's polynomial
#: (equal to this one's to rounding), by a double (measured: 0 on 18 000 targets).
REACH_EXACT_ULPS = 1
#: The samples of an advancing piece on which the part where its radius does not fall is found.
MONOTONE_GRID = 400_001


@pytest.mark.parametrize("v_ref, n, alpha", [(1e-6, 0.6, 20.0), (1e-5, 0.9, 60.0), (3e-7, 0.4, 5.0)])
def test_reach_is_the_least_double_the_bisection_finds_also_where_the_radius_is_flat(v_ref, n, alpha):
    """Every advancing piece, 3000 targets between doubles of the radius: among them values where the edge has almost
    stopped, the radius flat to its last digit over thousands of doubles of the clock, where a Newton iterate that
    converged from above is not the first time (the probe below it finds the flat stretch, the bracket is halved)."""
    from mdr_events.models.continuum.rate_shifts import _bisect

    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, v_ref, n)
    run = solve_edge(PAPER, me.Path.scenario_A(alpha, PAPER), law, method="LSODA")
    rng = np.random.default_rng(11)
    checked = 0
    for piece in run.pieces:
        fast = step_polynomials(piece[3])
        if not isinstance(fast, StepPolynomials) or not fast(fast.ts[-1])[0] > fast(fast.ts[0])[0]:
            continue
        lo, end = float(fast.ts[0]), float(fast.ts[-1])
        # (where the edge comes to rest the dense output overshoots by a few ulp of the radius before the stop event:
        # the targets lie where it does not yet fall, reach's precondition)
        grid = np.linspace(lo, end, MONOTONE_GRID)
        falls = np.flatnonzero(np.diff(fast(grid)[0]) < 0.0)
        end = float(grid[falls[0]]) if falls.size else end
        target = fast(rng.uniform(lo, end, 3000))[0] * (1.0 + rng.uniform(-1e-12, 1e-12, 3000))
        hi = rng.uniform(lo, end, 3000)
        found = fast.reach(target, lo, hi)
        expected = _bisect(lambda t: fast(t)[0], np.full(hi.shape, lo), hi, target)
        np.testing.assert_allclose(found, expected, rtol=0.0, atol=REACH_EXACT_ULPS * np.spacing(end))
        checked += 1
    assert checked


def test_the_first_time_x_reaches_a_level_is_the_bisection_s():
    from mdr_events.models.continuum.rate_shifts import _bisect, _reach

    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (2e-4, PAPER.d_max), (5e-4, -1e-4)]), speed=PAPER.v)
    shifts = solve_rate_shifts(PAPER, path, LAW, method="LSODA")
    levels = np.linspace(-1e-5, 6e-4, 200)
    top = np.full(levels.shape, path.duration * 0.9)
    expected = _bisect(shifts._x, np.zeros(levels.shape), top, levels)
    np.testing.assert_allclose(_reach(shifts, top, levels), expected, rtol=0.0,
                               atol=REACH_ULPS * np.spacing(path.duration))
