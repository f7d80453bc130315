"""LSODA's steps of the edge taken by its integrator's runner (continuum.rate_lsoda) against scipy's ``OdeSolver.step``
(the reference route of rate_march): the same steps, events and dense output, bit for bit. What it is for, the
continuum's scenario A under the rate-dependent law within issue 29's 3× of the paper's, is measured side by side by
benchmarks/bench_rate_adhesion.py."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import LSODA

import mdr_events as me
from mdr_events.models.continuum import rate_march, solve_edge
from mdr_events.models.continuum.rate_dense import step_polynomials
from mdr_events.models.continuum.rate_lsoda import LsodaStepper, LsodaSteps

PAPER = me.Parameters.paper()


def _reference_solver(fun, t0, t1, y0, method, rtol, atol):
    """rate_march's stepper by ``OdeSolver.step`` for every method (LSODA's dense outputs made step by step)."""
    return rate_march._Solver(rate_march.SOLVERS[method](fun, t0, np.array([y0], dtype=float), t1, rtol=rtol,
                                                         atol=atol), method)


def _runs(monkeypatch, path: me.Path, law: me.RateDependentAdhesion):
    """``solve_edge`` by LSODA through the runner and through the reference route."""
    ours = solve_edge(PAPER, path, law, method="LSODA")
    with monkeypatch.context() as patched:
        patched.setattr(rate_march, "_solver", _reference_solver)
        theirs = solve_edge(PAPER, path, law, method="LSODA")
    return ours, theirs


@pytest.mark.parametrize("alpha, v_ref, n", [(20.0, 1e-6, 0.6), (60.0, 1e-5, 0.9), (5.0, 3e-7, 0.4)])
def test_the_runner_takes_the_solver_s_steps_and_events_bit_for_bit(monkeypatch, alpha, v_ref, n):
    """Every piece of scenario A (advancing, resting, receding to the contact's end): the same events, the same steps'
    ends, the same polynomials of each step and the same radius at 3000 times."""
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, v_ref, n)
    path = me.Path.scenario_A(alpha, PAPER)
    ours, theirs = _runs(monkeypatch, path, law)
    assert ours.events == theirs.events
    assert len(ours.pieces) == len(theirs.pieces)
    moving = 0
    for mine, reference in zip(ours.pieces, theirs.pieces):
        assert mine[:2] == reference[:2]
        if isinstance(mine[3], LsodaSteps):
            moving += 1
            np.testing.assert_array_equal(mine[3].ts, reference[3].ts)
            fast, slow = step_polynomials(mine[3]), step_polynomials(reference[3])
            for name in ("ts", "origins", "scales", "coefficients"):
                np.testing.assert_array_equal(getattr(fast, name), getattr(slow, name))
    assert moving >= 2
    times = np.linspace(path.first_contact_time(), path.duration, 3000)
    np.testing.assert_array_equal(ours.radius(times), theirs.radius(times))


def test_a_step_whose_order_falls_is_read_as_the_solver_reads_it():
    """``LsodaStepper.row`` against ``LSODA.dense_output`` on a stiff linear ODE run by both side by side, through
    steps where the order rises and falls (the Nordsieck array's last column rescaled: ``iwork[14] < iwork[13]``)."""
    def fun(t, y):
        return [-50.0 * (y[0] - np.cos(t))]

    ours = LsodaStepper(fun, 0.0, 20.0, 0.0, 1e-10, 1e-12)
    theirs = LSODA(fun, 0.0, np.array([0.0]), 20.0, rtol=1e-10, atol=1e-12)
    falls = 0
    while theirs.status == "running":
        theirs.step()
        assert ours.step()
        falls += int(ours.integrator.iwork[14] < ours.integrator.iwork[13])
        t_old, t, h, order, yh = ours.row()
        dense = theirs.dense_output()
        assert (t_old, t, h, order) == (dense.t_old, dense.t, dense.h, dense.p[-1])
        np.testing.assert_array_equal(yh, dense.yh[0])
        np.testing.assert_array_equal(ours.y, theirs.y)
    assert falls > 0


def test_the_runner_is_checked_against_scipy_s_own_steps_once(monkeypatch):
    """This SciPy steps LSODA as the runner assumes (else a newer SciPy's private layout has moved: the edge then runs
    on ``OdeSolver.step``, and this test says so); a runner whose dense output is off is refused, a name gone too."""
    from mdr_events.models.continuum import rate_lsoda

    rate_lsoda.runner_steps_as_scipy.cache_clear()
    assert rate_lsoda.runner_steps_as_scipy()
    true_row = rate_lsoda.LsodaStepper.row

    def off_row(self):
        t_old, t, h, order, yh = true_row(self)
        return (t_old, t, h, order, None if yh is None else yh * (1.0 + 1e-15))

    for broken in (off_row, property(lambda self: (_ for _ in ()).throw(AttributeError("gone")))):
        monkeypatch.setattr(rate_lsoda.LsodaStepper, "row", broken)
        rate_lsoda.runner_steps_as_scipy.cache_clear()
        assert not rate_lsoda.runner_steps_as_scipy()
    monkeypatch.undo()
    rate_lsoda.runner_steps_as_scipy.cache_clear()
