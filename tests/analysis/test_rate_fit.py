"""Fitting the rate-dependent law jointly to curves at several speeds (analysis.rate_fit): from synthetic curves of a
known law with noise, three speeds in one call recover v_ref and n within their intervals, with per-curve offsets;
bad input is named."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.rate_fit import RateMeasurement, fit_rate_adhesion
from mdr_events.models.continuum import solve_edge

PAPER = me.Parameters.paper()
TRUE = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
START = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 3e-6, 0.8)
#: The noise of the synthetic curves: 1 % of JKR's pull-off force.
NOISE = 0.01 * 1.5 * np.pi * PAPER.dgamma1 * PAPER.R
#: The load cells' zeros of the three curves (N).
ZEROS = (2e-4, -1e-4, 0.0)


@functools.cache
def _exact_curves():
    """The true law's pull-off curves at the three speeds, (path, times, force) each: solved once in this module
    (about 1 s of CPU), their arrays read-only, so that no test changes what the next one reads."""
    out = []
    for speed in (1e-7, 1e-6, 1e-5):
        path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -200e-6)]), speed=speed)
        times = np.linspace(path.first_contact_time(), path.duration, 400)
        force = solve_edge(PAPER, path, TRUE).normal_force(times, path)
        times.flags.writeable = force.flags.writeable = False
        out.append((path, times, force))
    return tuple(out)


@functools.cache
def _measurements(seed=7):
    """The three synthetic curves: the exact ones with the load cells' zeros and noise (made once per seed in this
    module, their arrays read-only, so that a fit cannot change what the next test reads)."""
    rng = np.random.default_rng(seed)
    out = []
    for (path, times, exact), zero in zip(_exact_curves(), ZEROS):
        force = exact + zero
        noisy = force + rng.normal(0.0, NOISE, times.size)
        noisy.flags.writeable = False
        out.append(RateMeasurement(path, times, noisy, NOISE))
    return tuple(out)


def test_three_speeds_give_v_ref_and_n_within_their_intervals():
    result = fit_rate_adhesion(_measurements(), PAPER, START, free=("v_ref", "n"), offsets=True)
    estimate = result["estimate"]
    for name, truth in (("v_ref", TRUE.v_ref), ("n", TRUE.n)):
        assert float(result["interval_lower"].sel(parameter=name)) <= truth <= float(
            result["interval_upper"].sel(parameter=name)), (name, float(estimate.sel(parameter=name)))
    assert float(estimate.sel(parameter="v_ref")) == pytest.approx(TRUE.v_ref, rel=0.1)
    assert float(estimate.sel(parameter="n")) == pytest.approx(TRUE.n, rel=0.05)
    for index, zero in enumerate(ZEROS):
        assert abs(float(estimate.sel(parameter=f"offset_{index}")) - zero) < 4 * NOISE / np.sqrt(400)
    assert np.all(np.abs(result["residual_rms"].values - 1.0) < 0.2)  # the curves fitted to their noise
    assert result.attrs["status"] > 0


def test_three_speeds_give_all_four_values_of_the_law_within_their_intervals():
    """v_ref, n, dgamma0 and dgamma1 free from a start 20-200 % off, the curves without offsets: each within its 95 %
    interval (issue 29's time for this fit, 5 s, is measured by benchmarks/bench_rate_adhesion.py)."""
    rng_free = np.random.default_rng(11)
    measured = [RateMeasurement(path, times, force + rng_free.normal(0.0, NOISE, times.size), NOISE)
                for path, times, force in _exact_curves()]
    start = me.RateDependentAdhesion(1.2 * PAPER.dgamma0, 0.8 * PAPER.dgamma1, 3e-6, 0.8)
    result = fit_rate_adhesion(measured, PAPER, start, free=("v_ref", "n", "dgamma0", "dgamma1"))
    for name in ("v_ref", "n", "dgamma0", "dgamma1"):
        truth = getattr(TRUE, name)
        assert float(result["interval_lower"].sel(parameter=name)) <= truth <= float(
            result["interval_upper"].sel(parameter=name)), (name, float(result["estimate"].sel(parameter=name)))


@pytest.mark.parametrize("call, words", [
    (lambda: fit_rate_adhesion([], PAPER, START), "measurements=.*RateMeasurement"),
    (lambda: fit_rate_adhesion(_measurements()[:1], PAPER, START, free=("E",)), "free=.*v_ref, n"),
    (lambda: fit_rate_adhesion([RateMeasurement(me.Path.scenario_A(90.0, PAPER), np.zeros(3), np.zeros(2))], PAPER,
                               START), r"measurements\[0\]"),
])
def test_bad_input_is_named(call, words):
    with pytest.raises((TypeError, ValueError), match=words):
        call()


#: A start two decades above the true v_ref at the true n: the first steps of the trust region reach v_ref where the
#: edge's ODE is too stiff for solve_edge's budget (MAX_EVALUATIONS; measured: one trial refused, at v_ref = 1e-11 and
#: n = 0.26, from this start as from four decades above), which the fit takes as a rejected step.
NEAR_STIFF_START = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-4, 0.6)


@pytest.mark.slow  # (three curves fitted from two decades off: 150 solves of the edge and one refused by its budget,
#                    6 s of CPU measured; four decades off, as before, 174 solves and 9 s. The quick suite keeps the
#                    refusal's parts: the Jacobian stepping back, a refused start named)
def test_a_fit_from_near_the_stiff_edge_rejects_the_refused_trials_and_recovers_the_law():
    """Before, the first trial the edge solver refused ended the whole fit with its ValueError."""
    result = fit_rate_adhesion(_measurements(), PAPER, NEAR_STIFF_START, free=("v_ref", "n"))
    assert result.attrs["rejected_trials"] >= 1 and result.attrs["status"] > 0
    for name, truth in (("v_ref", TRUE.v_ref), ("n", TRUE.n)):
        assert float(result["interval_lower"].sel(parameter=name)) <= truth <= float(
            result["interval_upper"].sel(parameter=name)), (name, float(result["estimate"].sel(parameter=name)))


def test_the_jacobian_steps_back_where_the_forward_trial_is_refused_or_beyond_a_bound():
    """The residuals r = (θ0², θ0 θ1) with nan beyond θ0 = 1 (a refused law): the columns at θ = (1, 2) are the
    backward differences (2θ0, θ1) and (0, θ0) to the step's first order, and n's bound makes its column backward."""
    from mdr_events.analysis.rate_fit import FD_STEP, _jacobian

    def residuals(theta):
        return np.full(2, np.nan) if theta[0] > 1.0 else np.array([theta[0] ** 2, theta[0] * theta[1]])

    theta = np.array([1.0, 2.0])
    bounds = (np.array([-np.inf, -np.inf]), np.array([np.inf, 2.0]))
    jacobian = _jacobian(residuals, theta, 2, bounds, None)
    assert np.allclose(jacobian, [[2.0, 0.0], [2.0, 1.0]], atol=4 * FD_STEP * 2.0)  # (the step's first-order error)
    with pytest.raises(ValueError, match="neither neighbour's edge is followed"):
        _jacobian(lambda t: np.full(2, np.nan) if abs(t[0] - 1.0) > 0 else residuals(t), theta, 2, bounds, None)


def test_a_start_whose_edge_is_not_followed_is_named():
    start = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-12, 0.6)
    with pytest.raises(ValueError, match=r"start=RateDependentAdhesion\(.*v_ref=1e-12.*its edge cannot be followed"):
        fit_rate_adhesion(_measurements()[2:], PAPER, start)
