"""The span's integration by :func:`~mdr_events.models.continuum.span_march.march` (``solve_ivp``'s loop without its
bookkeeping, issue 28) against ``solve_ivp`` itself, the route it replaces: on every kind of span (moving and pinned,
with and without knots, with events fired in either direction of the variable, both regions of Coulomb's cap with
adhesion, a layer) the solutions are the same bit for bit: the event logs, the spans' step times and the filled
quantities."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import OdeSolution, solve_ivp

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.continuum import evaluate, integrate, solve_path
from mdr_events.models.continuum.span import SpanIntegrator
from mdr_events.models.continuum.split_span import SplitSpanIntegrator
from mdr_events.models.paths import Path

PAPER = me.Parameters.paper()


def solve_ivp_between_knots(rhs, start, stop, force, knots, events, tolerances, max_step):
    """The route before :mod:`~mdr_events.models.continuum.span_march`: ``solve_ivp`` per piece between the knots,
    the pieces' dense outputs joined."""
    options = dict(method="DOP853", rtol=tolerances.rtol, atol=tolerances.atol, dense_output=True,
                   events=events or None, max_step=max_step)
    if not knots:
        solution = solve_ivp(rhs, (start, stop), [force], **options)
    else:
        ts, interpolants = [start], []
        for low, high in zip([start, *knots], [*knots, stop]):
            solution = solve_ivp(rhs, (low, high), [force], first_step=min(abs(high - low), max_step), **options)
            if solution.status < 0:
                break
            ts.extend(solution.sol.ts[1:])
            interpolants.extend(solution.sol.interpolants)
            force = solution.y[0, -1]
            if solution.status == 1:
                break
        solution.sol = OdeSolution(ts, interpolants)
    return integrate.Marched(solution.status, solution.message, solution.sol,
                             [] if solution.t_events is None else [list(found) for found in solution.t_events],
                             float(solution.y[0, -1]))


def _table(params):
    radii = np.linspace(0.0, 4e-3, 41)
    return me.TabulatedProfile(radii, radii**2 / (2 * params.R))


def _zigzag():
    return me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], PAPER.v)


def _fretting():
    turns = np.array([0.0, 0.8, -0.8, 0.8, -0.3, 1.5]) * 50e-6
    points = [(0.0, -1e-6), (0.0, 1.5e-4)] + [(x, 1e-4) for x in turns] + [(75e-6, -2e-6), (0.0, 98e-6)]
    return me.Path(points, 1e-6)


#: label -> (params, path, solve_path's keywords)
CASES = {
    "A 20°": lambda: (PAPER, Path.scenario_A(20.0, PAPER), {}),
    "B 30°": lambda: (PAPER, Path.scenario_B(30.0, PAPER), {}),
    "zigzag": lambda: (PAPER, _zigzag(), {}),
    "table, A 20°": lambda: (PAPER, Path.scenario_A(20.0, PAPER, profile=_table(PAPER)), {"profile": _table(PAPER)}),
    "table, zigzag": lambda: (PAPER, _zigzag(), {"profile": _table(PAPER)}),
    "power law, B 30°": lambda: (PAPER, Path.scenario_B(30.0, PAPER, profile=me.PowerLaw(2e3, 3.0)),
                                 {"profile": me.PowerLaw(2e3, 3.0)}),
    "both parts with adhesion, fretting": lambda: (PAPER.replace(dgamma0=0.01, dgamma1=0.15, tau0=1e3), _fretting(),
                                                   {"friction": FrictionLaw("tau0+coulomb", mu=0.3)}),
    "layer, zigzag": lambda: (PAPER, _zigzag(), {"layer": me.Layer(5e-3)}),
}


def _solved(case, monkeypatch, route):
    params, path, options = CASES[case]()
    with monkeypatch.context() as patch:
        # (every span marches DOP853's steps where it is not a quadrature: test_span_panels compares both routes)
        patch.setattr(SplitSpanIntegrator, "quadrature", False)
        patch.setattr(SpanIntegrator, "quadrature", False)
        patch.setattr(SpanIntegrator, "closed_form", False)  # (test_closed_form compares the closed forms)
        if route is not None:
            patch.setattr(integrate, "solve_between_knots", route)
        return solve_path(params, path, **options)


@pytest.mark.parametrize("case", list(CASES))
def test_the_march_takes_solve_ivps_steps_and_roots_bit_for_bit(case, monkeypatch):
    marched = _solved(case, monkeypatch, None)
    reference = _solved(case, monkeypatch, solve_ivp_between_knots)
    assert [tuple(event) for event in marched.events] == [tuple(event) for event in reference.events]
    integrated = [span.interpolant for span in marched.spans if hasattr(span.interpolant, "ts")]
    assert integrated, "no span was integrated"
    assert [list(span.interpolant.ts) for span in marched.spans if hasattr(span.interpolant, "ts")] == \
        [list(span.interpolant.ts) for span in reference.spans if hasattr(span.interpolant, "ts")]
    times = np.linspace(0.0, marched.end_time, 1001)
    for name, values in evaluate(marched, times).items():
        np.testing.assert_array_equal(values, evaluate(reference, times)[name], err_msg=name)
    assert math.isfinite(marched.end_time) and marched.end_time == reference.end_time


@pytest.mark.parametrize("case", list(CASES))
def test_the_same_run_solved_or_evaluated_again_is_bit_identical(case, monkeypatch):
    """Same input, same output, whatever was computed before: a solution evaluated a second time, and the same path
    solved a second time, give the first values bit for bit (a layer's radius once started Newton from the last roots
    found, and evaluating a solution twice moved F_N by an ulp on an Intel CPU)."""
    first = _solved(case, monkeypatch, None)
    times = np.linspace(0.0, first.end_time, 1001)
    values = evaluate(first, times)
    again, resolved = evaluate(first, times), evaluate(_solved(case, monkeypatch, None), times)
    for name in values:
        np.testing.assert_array_equal(again[name], values[name], err_msg=name)
        np.testing.assert_array_equal(resolved[name], values[name], err_msg=name)
