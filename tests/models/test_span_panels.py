"""The quadrature by panels (:mod:`mdr_events.models.continuum.span_panels`, the split spans' route) against closed
forms, and against DOP853's route (:func:`~mdr_events.models.continuum.span_march.march`) on the runs of both parts
of the cap with adhesion: both within the tolerance of the run at ``rtol = 1e-13``, with the same events."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import Tolerances, evaluate, integrate, solve_path
from mdr_events.models.continuum.dense import force_values
from mdr_events.models.continuum.span import EventFunction, SpanIntegrator, Trigger
from mdr_events.models.continuum.span_panels import NODES, PIECE_NODES, panels, radau_rule, rule
from mdr_events.models.continuum.split_span import SplitSpanIntegrator

RTOL, ATOL = 1e-10, 1e-14
EPS = np.finfo(float).eps
#: The dense output against a closed form, as a share of the force's largest value: each panel holds its error (the
#: interpolant checked at the panel's end, where the nodes' polynomial is largest) to ATOL + RTOL |F|; a few panels'
#: errors add up, and a point inside a panel is no worse than its end: ten times RTOL.
DENSE_SHARE = 10 * RTOL


def _rate(function):
    """A right-hand side of the variable alone, counting its readings, that refuses to read the force."""
    def rhs(var, y):
        assert y is None, "the quadrature passed a force to the right-hand side"
        rhs.readings += 1
        return [function(var)]

    rhs.readings = 0
    return rhs


def _event(function, direction=1.0):
    return EventFunction(Trigger.ZONE_REACHES, None, function, direction)


@pytest.mark.parametrize("count", [NODES, PIECE_NODES, 1], ids=lambda count: f"{count} points")
def test_a_polynomial_rate_of_the_panels_degree_is_integrated_exactly_in_one_panel(count):
    """A rate of degree count − 1 is its own interpolant: one panel of the count-point rule (the error check is
    rounding), the dense output the integral at every point, read the same by ``force_values`` (DOP853's nested
    products, which hold a force of lower degree in the same rows)."""
    coefficients = np.array([0.3, -1.2, 0.7, 2.0, -0.5, 0.25, 1.5])[:count]
    rate = np.polynomial.Polynomial(coefficients)
    force = rate.integ()
    solved = panels(_rate(rate), [(0.0, 1.0)], 0.0, [], RTOL, ATOL, math.inf, rule(count))
    assert solved.status == 0 and list(solved.sol.ts) == [0.0, 1.0]
    points = np.linspace(0.0, 1.0, 101)
    np.testing.assert_allclose(solved.sol(points)[0], force(points), rtol=0, atol=16 * EPS)
    np.testing.assert_array_equal(force_values(solved.sol, points), solved.sol(points)[0])
    assert solved.y == pytest.approx(force(1.0), rel=4 * EPS)


def test_a_rule_of_more_points_than_the_dense_rows_is_refused_by_name():
    with pytest.raises(ValueError, match=rf"count={NODES + 1}.*\[1, {NODES}\]"):
        rule(NODES + 1)


@pytest.mark.parametrize("count", [NODES, PIECE_NODES])
def test_a_smooth_rate_is_integrated_to_the_tolerance_by_either_rule(count):
    """``F = sin`` from ``cos`` over a few periods by the count-point rule: the dense output within DENSE_SHARE of
    the closed form (the error check holds the rule's own interpolant, whatever its degree)."""
    solved = panels(_rate(math.cos), [(0.0, 10.0)], 0.0, [], RTOL, ATOL, math.inf, rule(count))
    points = np.linspace(0.0, 10.0, 1001)
    np.testing.assert_allclose(force_values(solved.sol, points), np.sin(points), rtol=0, atol=DENSE_SHARE)


@pytest.mark.parametrize("count", range(2, NODES + 1))
def test_a_radau_rule_starts_at_the_panel_s_start_and_is_exact_to_degree_2n_minus_2(count):
    """Gauss–Radau's rule of ``count`` points (the panels between a table's knots): its first point is the panel's
    start, its weights integrate every power up to ``2 count − 2`` over ``[0, 1]`` to rounding and not the next (one
    degree below Gauss–Legendre's: the point it fixes), and a rate of degree ``count − 1`` is integrated in one panel
    as by Gauss–Legendre's rule."""
    radau = radau_rule(count)
    assert radau.shared and radau.nodes[0] == 0.0 and np.all(np.diff(radau.nodes) > 0) and radau.nodes[-1] < 1.0
    moments = np.array([radau.weights @ radau.nodes**k for k in range(2 * count)])
    exact = 1.0 / np.arange(1, 2 * count + 1)
    np.testing.assert_allclose(moments[:-1], exact[:-1], rtol=8 * EPS, atol=0)
    assert abs(moments[-1] - exact[-1]) > 1e-9  # (2.4e-8 at 7 points: a million times the rounding)
    rate = np.polynomial.Polynomial(np.array([0.3, -1.2, 0.7, 2.0, -0.5, 0.25, 1.5])[:count])
    solved = panels(_rate(rate), [(0.0, 1.0)], 0.0, [], RTOL, ATOL, math.inf, radau)
    points = np.linspace(0.0, 1.0, 101)
    assert list(solved.sol.ts) == [0.0, 1.0]
    np.testing.assert_allclose(solved.sol(points)[0], rate.integ()(points), rtol=0, atol=16 * EPS)


def test_a_radau_panel_s_start_is_the_panel_before_s_check_read_once():
    """Four pieces of a rate of the rule's degree, one panel each: the right-hand side read once at the start and
    then ``PIECE_NODES`` times a panel (its inner points and the check at its end, which the next panel starts
    from): 1 + 4 PIECE_NODES readings, where reading each start again took 4 more."""
    rate = _rate(np.polynomial.Polynomial([0.3, -1.2, 0.7, 2.0, -0.5][:PIECE_NODES]))
    solved = panels(rate, [(0.0, 0.5), (0.5, 1.0), (1.0, 1.5), (1.5, 2.0)], 0.0, [], RTOL, ATOL, math.inf,
                    radau_rule(PIECE_NODES))
    assert list(solved.sol.ts) == [0.0, 0.5, 1.0, 1.5, 2.0] and rate.readings == 1 + 4 * PIECE_NODES


def test_a_piece_is_first_tried_at_the_length_the_last_panel_allows():
    """``cos`` on a short piece, then a long one: the long piece is first tried at the length the short piece's panel
    allows (its error scaled as a step size is), not whole (rejected, then cut), so no panel is rejected:
    ``PIECE_NODES`` readings a panel and one at the start (the whole piece tried first took 15 more). The force
    within DENSE_SHARE of ``sin``."""
    rate = _rate(math.cos)
    solved = panels(rate, [(0.0, 0.05), (0.05, 3.0)], 0.0, [], RTOL, ATOL, math.inf, radau_rule(PIECE_NODES))
    panels_taken = len(solved.sol.ts) - 1
    assert panels_taken > 2 and rate.readings == 1 + PIECE_NODES * panels_taken
    points = np.linspace(0.0, 3.0, 1001)
    np.testing.assert_allclose(force_values(solved.sol, points), np.sin(points), rtol=0, atol=DENSE_SHARE)


@pytest.mark.parametrize("start, stop", [(0.0, 10.0), (10.0, 0.0)], ids=["rising", "falling"])
def test_a_smooth_rate_is_integrated_to_the_tolerance(start, stop):
    """``F = sin`` from ``cos`` over a few periods, either way: the dense output within DENSE_SHARE of the closed
    form, the end to the rule's accuracy, in a few panels of NODES + 1 readings each."""
    rhs = _rate(math.cos)
    solved = panels(rhs, [(start, stop)], math.sin(start), [], RTOL, ATOL, math.inf)
    assert solved.status == 0 and solved.sol.ts[-1] == stop
    points = np.linspace(start, stop, 1001)
    np.testing.assert_allclose(force_values(solved.sol, points), np.sin(points), rtol=0, atol=DENSE_SHARE)
    assert solved.y == pytest.approx(math.sin(stop), abs=DENSE_SHARE)
    assert rhs.readings <= 40 * (NODES + 1)  # (measured: 14 panels and 3 cut)


def test_a_steep_rate_is_cut_into_panels_and_each_piece_ends_on_its_knot():
    """``1/(1 + (v/ε)²)``, whose force is ``ε atan(v/ε)``: the panels shrink around the steep middle (one panel
    would be off by 1e-4 of it) and the knot at 0.3 is a panel's end exactly."""
    width = 1e-3
    rhs = _rate(lambda v: 1.0 / (1.0 + (v / width) ** 2))
    exact = lambda v: width * np.arctan(np.asarray(v) / width)  # noqa: E731
    solved = panels(rhs, [(-1.0, 0.3), (0.3, 1.0)], float(exact(-1.0)), [], RTOL, ATOL, math.inf)
    assert solved.status == 0 and 0.3 in list(solved.sol.ts) and len(solved.sol.ts) > 10
    points = np.linspace(-1.0, 1.0, 4001)
    scale = float(np.max(np.abs(exact(points))))
    np.testing.assert_allclose(force_values(solved.sol, points), exact(points), rtol=0, atol=DENSE_SHARE * scale)


def test_an_event_ends_the_panels_at_its_root_read_before_it_alone():
    """A level crossing at v = 2.5 ends the integration there (the first of two events; the other falls and is not
    watched rising), the force at the root as the closed form. The rate jumps to 1e3 beyond the root (the zones
    change there, the rate need not continue smoothly): the panel in which the event fired is integrated again up to
    the root, so no reading beyond it enters the force (with the panel kept, the force at the root was 0.12 off)."""
    root = 2.5
    rhs = _rate(lambda v: math.cos(v) if v <= root else 1e3)
    events = [_event(lambda v: 1.0 - v, 1.0), _event(lambda v: v - root, 1.0)]
    solved = panels(rhs, [(0.0, 10.0)], 0.0, events, RTOL, ATOL, math.inf)
    assert solved.status == 1 and solved.t_events[0] == [] and len(solved.t_events[1]) == 1
    assert solved.t_events[1][0] == pytest.approx(root, rel=4 * EPS) and solved.sol.ts[-1] == solved.t_events[1][0]
    assert solved.y == pytest.approx(math.sin(root), abs=DENSE_SHARE)
    points = np.linspace(0.0, solved.sol.ts[-1], 501)
    np.testing.assert_allclose(force_values(solved.sol, points), np.sin(points), rtol=0, atol=DENSE_SHARE)


def test_an_event_at_the_start_ends_the_integration_at_once():
    """An event already met at the start (a function at zero rising) fires at the start, with a panel of zero length
    as ``solve_ivp`` keeps one."""
    solved = panels(_rate(math.cos), [(0.0, 1.0)], 0.7, [_event(lambda v: v, 1.0)], RTOL, ATOL, math.inf)
    assert solved.status == 1 and solved.t_events[0] == [0.0] and list(solved.sol.ts) == [0.0, 0.0]
    assert solved.y == 0.7


def test_a_rate_that_is_not_finite_fails_instead_of_looping():
    """A reading of ``nan`` past v = 0.5 (a state lost) shrinks the panels there until they are too short: status
    -1, as DOP853 fails, not a panel grown for ever (the error of ``nan`` is no number to scale a length by)."""
    solved = panels(_rate(lambda v: math.cos(v) if v < 0.5 else math.nan), [(0.0, 1.0)], 0.0, [], RTOL, ATOL,
                    math.inf)
    assert solved.status == -1 and solved.sol is None and "too short" in solved.message


def test_a_panel_never_exceeds_the_longest_step():
    solved = panels(_rate(math.cos), [(0.0, 1.0)], 0.0, [], RTOL, ATOL, 1.0 / 8)
    assert np.max(np.abs(np.diff(solved.sol.ts))) <= 1.0 / 8 and len(solved.sol.ts) == 9


COMBINED = FrictionLaw("tau0+coulomb", mu=0.3)
#: Each route's F_x against DOP853's run at rtol 1e-13, as a share of its largest value: test_split_steps'
#: TOLERANCE_SHARE (the solver's rtol accumulated over a run's spans, with a margin). Measured (DOP853 / panels):
#: A 20° 1.7e-10 / 3.2e-12, the cone 6.3e-11 / 1.2e-13, n = 3 B 30° 2.5e-11 / 1.1e-12, the drop onto the Δγ1
#: branch 2.6e-11 / 5.5e-13 (against its algebraic force), a table's B 30° 1.5e-8 / 2.1e-10 (not a case here).
ROUTE_SHARE = 1e-9
#: The routes' events at the same times but for the roots' rounding: each root to 4 eps of its variable, which on a
#: radius or a graded variable maps onto the time through the branch (a slope up to ~1e3 at a contact's end).
EVENT_RTOL = 1e-10


def _drop():
    """In at 10° to 0.9 d_max, straight in to d_max, out backwards to 0.6 d_max (the radius drops onto the Δγ1
    branch, Δγ1 < Δγ0) and out to the surface (tests/models/test_continuum_drops_and_edges.py's path)."""
    params = me.Parameters.paper().replace(dgamma0=0.15, dgamma1=0.01)
    d_max = params.d_max
    x1 = 0.9 * d_max / np.tan(np.radians(10.0))
    points = [(0.0, 0.0), (x1, 0.9 * d_max), (x1, d_max), (x1 - 1.5 * d_max, 0.6 * d_max), (x1 - 1.5 * d_max, 0.0)]
    return params, me.Path(np.array(points), params.v), None


TAU0 = FrictionLaw("tau0")


def _zigzag(params):
    """In with tangential reversals, a pinned zigzag, out (benchmarks/bench_simulate.py's)."""
    return me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], params.v)


#: label -> (params, path, profile, friction): both parts with adhesion (the split spans), and ``τ0`` alone (the
#: spans of :class:`~mdr_events.models.continuum.span.SpanIntegrator`: growing with a front, all stick, shrinking, a
#: pinned span with a front)
CASES = {"A 20°": lambda: (me.Parameters.paper(), me.Path.scenario_A(20.0, me.Parameters.paper()), None, COMBINED),
         "cone, A 20°": lambda: (me.Parameters.paper(), me.Path.scenario_A(20.0, me.Parameters.paper()),
                                 PowerLaw.cone(0.05), COMBINED),
         "n = 3, B 30°": lambda: (me.Parameters.paper(), me.Path.scenario_B(30.0, me.Parameters.paper()),
                                  PowerLaw(2e5, 3.0), COMBINED),
         "drop onto the Δγ1 branch": lambda: (*_drop(), COMBINED),
         "τ0, A 20°": lambda: (me.Parameters.paper(), me.Path.scenario_A(20.0, me.Parameters.paper()), None, TAU0),
         "τ0, B 60°": lambda: (me.Parameters.paper(), me.Path.scenario_B(60.0, me.Parameters.paper()), None, TAU0),
         "τ0, zigzag": lambda: (me.Parameters.paper(), _zigzag(me.Parameters.paper()), None, TAU0),
         "τ0, cone, A 30°": lambda: (me.Parameters.paper(), me.Path.scenario_A(30.0, me.Parameters.paper()),
                                     PowerLaw.cone(0.05), TAU0)}


def _run(case, monkeypatch, quadrature, tolerances=Tolerances(), calls=None):
    """The case's run by the route asked; ``calls`` (a list) gets one entry per quadrature by panels."""
    params, path, profile, friction = CASES[case]()
    with monkeypatch.context() as patch:
        patch.setattr(SplitSpanIntegrator, "quadrature", quadrature)
        patch.setattr(SpanIntegrator, "quadrature", quadrature)
        patch.setattr(SpanIntegrator, "closed_form", False)  # (test_closed_form compares the closed forms)
        if calls is not None:
            def counted(*args, **kwargs):
                calls.append(args[1])
                return panels(*args, **kwargs)

            patch.setattr(integrate, "panels", counted)
        solution = solve_path(params, path, tolerances, profile=profile, friction=friction)
    return solution, evaluate(solution, np.linspace(0.0, solution.end_time, 2001))["tangential_force"]


@pytest.mark.parametrize("case", list(CASES))
def test_both_routes_agree_with_the_tight_run_and_log_the_same_events(case, monkeypatch):
    tight, reference = _run(case, monkeypatch, False, Tolerances(rtol=1e-13))
    scale = float(np.max(np.abs(reference)))
    calls = {True: [], False: []}
    runs = {quadrature: _run(case, monkeypatch, quadrature, calls=calls[quadrature]) for quadrature in (True, False)}
    for quadrature, (solution, force) in runs.items():
        np.testing.assert_allclose(force, reference, rtol=0, atol=ROUTE_SHARE * scale, err_msg=f"{quadrature=}")
        assert [event.kind for event in solution.events] == [event.kind for event in tight.events]
        np.testing.assert_allclose([event.time for event in solution.events], [event.time for event in tight.events],
                                   rtol=EVENT_RTOL, atol=0)
    assert calls[True] and not calls[False]  # (each route the one it names: the panels ran, or DOP853 alone)
