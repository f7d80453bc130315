"""The springs under the rate-dependent adhesion law (models.rate_springs): their edge converges at first order in Δx
to the continuum's normal problem (continuum.solve_edge), their tangential force runs on top, and as v_ref → ∞ they
are the paper's springs, spring for spring."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.models.continuum import solve_edge

PAPER = me.Parameters.paper()
BASE = me.Contact.paper()
#: A reference speed 10 times the path's and Maugis–Barquins' exponent: the edge lags the indenter visibly.
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-5, 0.6)
#: Beyond the path's speed by 15 orders: every crossing of a spring takes less than the time step's rounding, so the
#: springs follow the paper's thresholds exactly.
FAST = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e9, 0.6)


def _contact(law):
    return me.Contact(BASE.elastomer, BASE.indenter, law, BASE.friction)


def test_the_springs_converge_to_the_continuum_s_normal_problem_at_first_order():
    """Vertically in and out: F_N of the springs at Δx = 4, 2, 1, 0.5 µm (dt = Δx / 4v) against solve_edge's, relative
    to its range over the samples both hold in contact (up to 95 % of the path: the collapse at pull-off is a jump)."""
    path = me.Path.scenario_A(90.0, PAPER)
    reference = solve_edge(PAPER, path, LAW)
    spacings = (4e-6, 2e-6, 1e-6, 5e-7)
    errors = []
    for dx in spacings:
        run = me.simulate(_contact(LAW), me.Paths([path]), "discrete", dx=dx, dt=0.25 * dx / PAPER.v).isel(case=0)
        times = run["time"].values + path.first_contact_time()
        force, exact = run["normal_force"].values, reference.normal_force(times, path)
        held = np.isfinite(force) & (reference.radius(times) > 0) & (times < 0.95 * path.duration)
        errors.append(np.max(np.abs(force - exact)[held]) / np.ptp(exact[held]))
    assert errors[-1] < 2e-4, errors
    assert np.all(observed_orders(spacings, np.array(errors)) > 0.8), errors


def test_the_tangential_force_runs_on_the_moving_edge():
    """Scenario A at 20°: F_x finite wherever the springs touch, and it differs from the paper's springs (the edge
    lags), while at v_ref = 1e9 m/s the springs are the paper's, sample for sample."""
    slow = me.simulate(_contact(LAW), me.Scenario("A", alpha=[20.0]), "discrete", dx=2e-6)
    paper = me.simulate(BASE, me.Scenario("A", alpha=[20.0]), "discrete", dx=2e-6)
    assert (slow.attrs["adhesion_law"], slow.attrs["adhesion_v_ref"], slow.attrs["adhesion_n"]) == \
        ("rate_dependent", 1e-5, 0.6) and "adhesion_law" not in paper.attrs
    touching = slow["contact_radius"].values > 0
    assert np.all(np.isfinite(slow["tangential_force"].values[touching]))
    assert np.nanmax(np.abs(slow["tangential_force"].values - paper["tangential_force"].values)) > 1e-4
    fast = me.simulate(_contact(FAST), me.Scenario("A", alpha=[20.0]), "discrete", dx=2e-6)
    for name in ("contact_radius", "normal_force", "tangential_force", "sliding_fraction"):
        np.testing.assert_array_equal(fast[name].values, paper[name].values, err_msg=name)


def test_the_continuum_method_runs_the_law_and_the_springs_converge_to_it():
    """simulate(..., "continuum") under the law (issue 29: the continuum integrates it, the speed a dimension of the
    motion): stamped with the law, its F_x the continuum's springs' (solve_rate_shifts by its method) sample for
    sample, and the
    discrete method's F_x within the first-order error of Δx = 1 µm of it (1e-3 of its range, measured 2e-4)."""
    from mdr_events.models.continuum import solve_rate_shifts
    from mdr_events.models.continuum.rate_run import RUN_METHOD

    exact = me.simulate(_contact(LAW), me.Scenario("A", alpha=[20.0], v=1e-5), "continuum", samples=501)
    assert (exact.attrs["method"], exact.attrs["adhesion_law"], exact.attrs["adhesion_v_ref"]) == \
        ("continuum", "rate_dependent", LAW.v_ref)
    path = me.Path.scenario_A(20.0, PAPER.replace(v=1e-5))
    run = exact.isel(alpha=0)
    held = np.isfinite(run["tangential_force"].values)
    shifts = solve_rate_shifts(PAPER, path, LAW, method=RUN_METHOD)
    np.testing.assert_array_equal(run["tangential_force"].values[held],
                                  shifts.tangential_force(run["time"].values[held] + path.first_contact_time()))
    springs = me.simulate(_contact(LAW), me.Scenario("A", alpha=[20.0], v=1e-5), "discrete", dx=1e-6).isel(alpha=0)
    times = springs["time"].values
    force = springs["tangential_force"].values
    inside = np.isfinite(force)
    gap = np.abs(force[inside] - shifts.tangential_force(times[inside] + path.first_contact_time()))
    assert np.mean(gap) < 1e-3 * float(run["tangential_force_max"])


def test_a_sweep_over_the_speed_and_v_ref_sees_their_ratio_alone():
    """The springs' edge moves by the ratio v/v_ref alone (the law's speeds scale with v_ref, the path's with v): a
    sweep over both gives the same least F_N and largest F_x wherever the ratio is the same (the time grid scales with
    v, so the depths of the samples are the same; rounding of the times, 1e-12), and a faster path pulls harder."""
    result = me.sweep({"v": [1e-7, 1e-6], "adhesion.v_ref": [1e-6, 1e-5]}, _contact(LAW),
                      me.Scenario("A", alpha=[20.0]), method="discrete", scheduler="serial")  # (the engines are
    # tests/analysis/test_sweep.py's: a local cluster's worker processes cost more than these four runs)
    for name in ("normal_force_min", "tangential_force_max"):
        values = result[name].values
        assert values[0, 0] == pytest.approx(values[1, 1], rel=1e-12), name
    assert result["normal_force_min"].values[1, 0] < result["normal_force_min"].values[0, 0]
