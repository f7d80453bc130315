"""A tabulated indenter in both simulators: a table of the paraboloid against the paraboloid's runs (to the table's
interpolation error, falling as the table refines), the continuum against the table's own relations (to 1e-9), the
discrete model converging to it; depths past the table refused."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences, observed_orders
from mdr_events.models.continuum import EventKind, extremum, solve_path
from mdr_events.models.continuum.tolerances import EPS
from mdr_events.contact.indenters import TabulatedProfile
from mdr_events.models.paths import exit_depth
from mdr_events.theory import tabulated as tb

REACH = 4e-3


@pytest.fixture(scope="module")
def paper():
    return me.Parameters.paper()


def _paraboloid_table(params, points: int) -> TabulatedProfile:
    r = np.linspace(0.0, REACH, points)
    return TabulatedProfile(r, r**2 / (2 * params.R))


def test_a_table_of_the_paraboloid_runs_as_the_paraboloid(paper):
    """Scenario A at 20°, continuum: F_N, F_x and A of tables with 41 and 81 points against the paraboloid's (max over
    the run, relative to the largest value): within 1e-3, and at least 3 times closer with the finer table (second
    order would be 4)."""
    reference = me.simulate(paper, "A", alpha=[20.0], method="continuum", samples=801)
    times = reference["time"].values
    gaps = []
    for points in (41, 81):
        run = me.simulate(paper, "A", alpha=[20.0], method="continuum", t=times,
                          profile=_paraboloid_table(paper, points))
        gaps.append(history_differences(run, reference))
    for name in ("normal_force", "tangential_force", "contact_area"):
        coarse, fine = gaps[0][name][0], gaps[1][name][0]
        assert fine < 1e-3 and coarse / fine > 3.0, (name, coarse, fine)


def test_a_level_beyond_what_the_table_reaches_clips_its_springs_at_its_end(paper):
    """Δγ1 < Δγ0, re-contact and growth to d_max: a cap's level x + K a then lies beyond the anchor of the table's last
    radius (the depth it needs is deeper than the table reaches): every spring is inside the window, none at the cap.
    The algebraic force on the stored anchors is the integrated one, and both the paraboloid's to the table's
    interpolation error (before, the level's inverse was the piece's start: every spring clipped at the cap, the
    algebraic force of the wrong sign, and the edge's shift wrong on the way out, F_x −0.61 N against 0.36 N)."""
    params = paper.replace(dgamma0=0.15, dgamma1=0.01)
    d_max = params.d_max
    points = [(0.0, 0.0), (0.0, 0.8 * d_max), (0.0, 0.6 * d_max), (-0.3 * d_max, 0.6 * d_max),
              (-0.3 * d_max, -0.02 * d_max), (0.7 * d_max, d_max), (0.7 * d_max, exit_depth(params))]
    path = me.Path(np.array(points), params.v)
    r = np.linspace(0.0, 5e-3, 41)
    table = TabulatedProfile(r, r**2 / (2 * params.R))
    solution = solve_path(params, path, profile=table)
    reference = solve_path(params, path)
    times = np.linspace(0.0, 0.99 * min(solution.end_time, reference.end_time), 801)  # (not the pull-off itself)
    integrated = me.continuum.evaluate(solution, times)["tangential_force"]
    scale = float(np.nanmax(np.abs(integrated)))
    np.testing.assert_allclose(me.continuum.algebraic_tangential_force(solution, times), integrated, rtol=0,
                               atol=1e-9 * scale)
    np.testing.assert_allclose(integrated, me.continuum.evaluate(reference, times)["tangential_force"], rtol=0,
                               atol=1e-3 * scale)


def test_the_continuum_meets_the_tables_relations(paper):
    """The continuum of a table: its least F_N along the way out is the table's pull-off force under force control
    (the least F_N along the branch), and its slip onset while indenting the table's d_crit_A, to 1e-9."""
    table = _paraboloid_table(paper, 41)
    path = me.Path.scenario_A(20.0, paper, profile=table)
    solution = solve_path(paper, path, profile=table)
    pull_off = tb.pull_off_force(table, paper, paper.dgamma1)
    assert extremum(solution, "normal_force", False)[1] == pytest.approx(pull_off, rel=1e-9)
    onset = next(event for event in solution.events if event.kind is EventKind.SLIP_ONSET)
    assert onset.depth == pytest.approx(tb.d_crit_A(20.0, table, paper, adhesion=True), abs=1e-9 * paper.d_max)


def test_the_discrete_model_converges_to_the_continuum(paper):
    """The same table in both: max_t |discrete − continuum| of F_N, F_x and A at Δx = 8, 4, 2 µm (dt = Δx/(2v)) falls
    at first order (observed orders above 0.7), as for the paraboloid."""
    table = _paraboloid_table(paper, 41)
    spacings = (8e-6, 4e-6, 2e-6)
    differences = {}
    for dx in spacings:
        discrete = me.simulate(paper, "A", alpha=[30.0], dx=dx, dt=0.5 * dx / paper.v, profile=table)
        exact = me.simulate(paper, "A", alpha=[30.0], method="continuum", t=discrete["time"].values, profile=table)
        for name, values in history_differences(discrete, exact).items():
            differences.setdefault(name, []).append(values[0])
    for name in ("normal_force", "tangential_force", "contact_area"):
        assert np.all(observed_orders(spacings, differences[name]) > 0.7), (name, differences[name])


def test_results_carry_the_table(paper):
    """The attributes hold the table exactly (each value as Python writes it back)."""
    table = TabulatedProfile([0.0, 1.1e-3, 2.3e-3, 4.0e-3], [0.0, 2.0e-5, 8.9e-5, 2.7e-4])
    ds = me.simulate(paper, "A", alpha=[20.0], method="continuum", samples=51, profile=table)
    back = TabulatedProfile([float(v) for v in ds.attrs["profile_table_r"].split(", ")],
                            [float(v) for v in ds.attrs["profile_table_f"].split(", ")])
    assert back == table and "param_R" in ds.attrs["profile_note"]


def test_a_path_deeper_than_the_table_reaches_is_refused(paper):
    table = _paraboloid_table(paper, 41)
    deepest = tb.branch(table, paper, paper.dgamma0).deepest
    path = me.Path([(0.0, -1e-5), (0.0, 1.01 * deepest), (0.0, -1e-4)], speed=1e-6)
    for call in (lambda: me.simulate(paper, path, method="continuum", profile=table),
                 lambda: me.simulate(paper, path, dx=4e-6, profile=table),
                 lambda: solve_path(paper, path, profile=table)):
        with pytest.raises(ValueError, match=r"reaches the depth .* allowed for 'tabulated profile f\(r\), 41 points"):
            call()


@pytest.mark.parametrize("points", [3, 11, 81])
def test_a_table_of_a_cone_is_the_cone_in_the_continuum(points):
    """A linear table has a cone's tip (g' > 0 at 0): its adhesive branch's minimum lies far below the first grid
    point (1.5 µm here, the table's step up to 10 mm). It was missed (jump-off at a = 0) and the continuum failed
    with an infinite slope; now the jump-off and the run are the cone's, to round-off (g of a linear table is exact)."""
    from mdr_events.theory import power_law, tabulated

    params = me.Parameters.paper()
    radii = np.linspace(0.0, 2e-2, points)
    table, cone = me.TabulatedProfile(tuple(radii), tuple(0.1 * radii)), me.PowerLaw.cone(0.1)
    expected = power_law.jump_off(cone, params, params.dgamma0)
    line = tabulated.branch(table, params, params.dgamma0)
    assert line.jump_off_radius == pytest.approx(expected["contact_radius"], rel=1e-7)  # a flat minimum: xatol
    assert line.jump_off_depth == pytest.approx(expected["depth"], rel=1e-12)
    runs = [me.simulate(params, "A", [20.0], method="continuum", profile=shape).isel(alpha=0) for shape in (table, cone)]
    for name in ("normal_force", "tangential_force"):
        scale = float(np.abs(runs[1][name]).max())
        assert float(np.abs(runs[0][name] - runs[1][name]).max()) < 1e-9 * scale


def test_the_dense_output_of_many_points_is_the_interpolants_bit_for_bit(paper):
    """continuum.dense.force_values evaluates a span's DOP853 steps for all points at once (issue 28): at points
    inside, at every step's ends (where OdeSolution picks one of two steps) and beyond, on spans integrated forwards
    and backwards (a shrinking radius), of a table (a step per knot) and of the paraboloid, the values are the
    OdeSolution's bit for bit."""
    from mdr_events.models.continuum import solve_path
    from mdr_events.models.continuum.dense import _gathered, force_values

    r = np.linspace(0.0, 4e-3, 41)
    table = me.TabulatedProfile(r, r**2 / (2 * paper.R))
    zigzag = me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], paper.v)
    solutions = [solve_path(paper, me.Path.scenario_A(20.0, paper, profile=table), profile=table),
                 solve_path(paper, me.Path.scenario_B(30.0, paper)), solve_path(paper, zigzag)]
    rng = np.random.default_rng(28)
    checked = {True: 0, False: 0}
    for solution in solutions:
        for span in solution.spans:
            if _gathered(span.interpolant) is None:
                continue
            ts = np.asarray(span.interpolant.ts)
            low, high = min(ts[0], ts[-1]), max(ts[0], ts[-1])
            points = np.concatenate([ts, rng.uniform(low, high, 500), np.linspace(low, high, 777),
                                     [low - 0.1 * (high - low), high + 0.1 * (high - low)]])
            np.testing.assert_array_equal(force_values(span.interpolant, points), span.interpolant(points)[0])
            checked[bool(ts[-1] > ts[0])] += 1
    assert checked[True] and checked[False]  # steps taken forwards and backwards


def test_the_stationary_points_of_a_dense_output_are_those_of_each_step_s_own_polynomial(paper, monkeypatch):
    """stationary._dense_output_roots picks the steps that meet a bracket at once and reads several steps' polynomials
    off in one evaluation (issue 28): the roots are bit for bit those of each step's own interpolant read off at its
    Chebyshev nodes, step by step, on brackets over one step, several and a whole span, of a table's spans (a step per
    knot), forwards and backwards."""
    from numpy.polynomial import chebyshev

    from mdr_events.models.continuum import solve_path
    from mdr_events.models.continuum.stationary import _DERIVATIVE, _NODES, IMAGINARY_SHARE, _dense_output_roots

    def step_by_step(interpolant, low, high):
        ts, roots = np.asarray(interpolant.ts, dtype=float), []
        for k, step in enumerate(interpolant.interpolants):
            start, end = min(ts[k], ts[k + 1]), max(ts[k], ts[k + 1])
            lower, upper = max(start, low), min(end, high)
            if upper > lower:
                centre, half = 0.5 * (start + end), 0.5 * (end - start)
                for root in chebyshev.chebroots(_DERIVATIVE @ step(centre + half * _NODES)[0]):
                    var = centre + half * float(root.real)
                    if abs(root.imag) <= IMAGINARY_SHARE and lower <= var <= upper:
                        roots.append(var)
        return roots

    from mdr_events.models.continuum.span import SpanIntegrator

    monkeypatch.setattr(SpanIntegrator, "closed_form", False)  # (every moving span a dense output of panels)
    r = np.linspace(0.0, 4e-3, 41)
    table = me.TabulatedProfile(r, r**2 / (2 * paper.R))
    solutions = [solve_path(paper, me.Path.scenario_A(20.0, paper, profile=table), profile=table),
                 solve_path(paper, me.Path.scenario_B(30.0, paper))]
    rng = np.random.default_rng(26)
    found = 0
    for solution in solutions:
        for span in solution.spans:
            if not hasattr(span.interpolant, "interpolants"):
                continue
            ts = np.asarray(span.interpolant.ts)
            low, high = min(ts[0], ts[-1]), max(ts[0], ts[-1])
            brackets = [(low, high), *np.sort(rng.uniform(low, high, (20, 2)), axis=1).tolist()]
            for lower, upper in brackets:
                roots = _dense_output_roots(span.interpolant, lower, upper)
                assert roots == step_by_step(span.interpolant, lower, upper)
                found += len(roots)
    assert found  # (stationary points were met)


#: The table's force against the tight run, over its largest value: each panel is held to ``rtol`` = 1e-10 of the
#: force, a check that a piece where the right-hand side is smooth passes far below it; what is left is the rounding
#: of some 300 pieces (the table's knots, and where a front crosses one: ``SpanIntegrator.front_knots``). Measured
#: 3.7e-12; without the fronts' knots 3.5e-10 (their kinks inside the panels, cut until each passed its check), and
#: with DOP853 restarted at each knot 1.1e-8.
TABLE_PIECES_FORCE = 1e-10


def test_a_tables_moving_spans_are_a_quadrature_between_its_knots(paper):
    """A table's knots start a piece of the quadrature each (a restart of DOP853 at each knot cost 15 readings where a
    panel takes 5), and so do the radii where a front crosses one. Scenario A at 20° on a 41-point table of the
    paraboloid: F_x within TABLE_PIECES_FORCE of the run at rtol = 1e-13."""
    from mdr_events.models.continuum.solution import evaluate
    from mdr_events.models.continuum.tolerances import Tolerances
    from mdr_events.models.paths import Path

    table = _paraboloid_table(paper, 41)
    path = Path.scenario_A(20.0, paper, profile=table)
    solution = solve_path(paper, path, profile=table)
    tight = solve_path(paper, path, Tolerances(rtol=1e-13, atol=1e-18), profile=table)
    times = np.linspace(0.0, min(solution.end_time, tight.end_time), 801)
    force, reference = (evaluate(run, times)["tangential_force"] for run in (solution, tight))
    assert np.max(np.abs(force - reference)) <= TABLE_PIECES_FORCE * np.max(np.abs(reference))


def test_a_front_crossing_a_knot_of_the_table_starts_a_piece_there(paper, monkeypatch):
    """``SpanIntegrator.front_knots``: scenario A at 20° on a 41-point table of the paraboloid, the spans with a front
    (growing, shrinking): at each knot found the front's ``ξ`` (the inverse of its piece at the level) is a knot of
    ``g`` to the root's rounding, and every knot of ``g`` the front sweeps over the span is found (a single front,
    monotone there)."""
    from mdr_events.models.continuum import integrate
    from mdr_events.models.paths import Path

    spans = []
    original = integrate._integrate

    def spy(model, span, integrator, force):
        spans.append(integrator)
        return original(model, span, integrator, force)

    monkeypatch.setattr(integrate, "_integrate", spy)
    table = _paraboloid_table(paper, 41)
    solve_path(paper, Path.scenario_A(20.0, paper, profile=table), profile=table)
    fronted = [integrator for integrator in spans if integrator.has_fronts()]
    swept = []
    for integrator in fronted:
        ((cap, piece),) = [(cap, p) for cap in integrator.zones for p, _, _ in integrator.zones[cap].fronts]
        seen, knots = integrator.zones[cap].anchors, np.array(integrator.anchors.attach.knots)
        found = integrator.front_knots()
        xi = [seen.inverse(piece, integrator.level(cap, var)) for var in found]
        assert np.all(np.min(np.abs(np.subtract.outer(xi, knots)), axis=1) <= 1e-9 * knots[-1])
        ends = sorted(seen.inverse(piece, integrator.level(cap, var)) for var in (integrator.start, integrator.stop))
        swept.append(np.count_nonzero((knots > ends[0]) & (knots < ends[1])))
        assert len(found) == swept[-1]
        assert set(found) <= set(integrator.knots())
    assert sum(count > 0 for count in swept) >= 2  # (the growing span with a front and the shrinking one)


#: The radius of the table's route against the route before, over its largest value: both invert the same branch at
#: the same depths, the route before until a step is below ``tabulated.RADIUS_RTOL`` (4 EPS) of the radius (that
#: step's own error far below it), the route now until a step's own error by Newton's rule is below ``NEWTON_SHARE``
#: of RADIUS_RTOL: each is the root to well within RADIUS_RTOL, plus its last step's rounding, an ulp each (2 EPS);
#: measured 0.63 EPS, and a radius off by 1e-13 of itself is 450 EPS
ROUTE_RADIUS = tb.RADIUS_RTOL + 2 * EPS
#: F_N of the two routes over its largest value: at a given depth F_N = 2 E* ∫(d − g) moves with the radius by
#: 2 E* (d − g(a)) da, the adhesive stretch's share, over the largest F_N less than the radius's relative change
#: (measured 0.43 of it on this run), so ROUTE_RADIUS holds it (measured 1.93 EPS; radii off by 1e-13 of themselves
#: move it 192 EPS)
ROUTE_NORMAL = ROUTE_RADIUS
#: F_x of the two routes over its largest value. A knot moved by δ leaves a kink of the right-hand side's second
#: derivative δ inside a panel, an error of the order of its jump times δ³, nothing at ROOT_ULPS (δ ~ 1e-15); what
#: moves F_x is the panels themselves: a piece's ends changed by any ulp draw other panels, each held to its check,
#: whose errors differ by far less than the check (rtol 1e-10). That floor, measured: knots moved by 1e-14 (a few
#: dozen ulp) 2.1e-13, by 1e-12 and 1e-10 4.2e-13, radii by at most 2 ulp 2.6e-13, the route before 2.3e-13. The
#: bound is 4 times the floor's 2.6e-13. A knot moved by 1e-12 or 1e-10 of itself is within the floor, so F_x cannot
#: see it (each knot is held to KNOT_ULPS ulp of the scalar route's by tests/models/test_span_front_knots.py); knots
#: moved by 1e-8 (1.1e-12), radii off by 1e-12 (2.5e-12) and the brackets' middles as knots (1.6e-10) fail here
ROUTE_FORCE = 1e-12


def test_the_tables_route_is_its_route_of_before_to_its_rounding(paper, monkeypatch):
    """The table's route (every front knot at once by regula falsi, ``span_front_knots``; an inversion ended by
    Newton's rule on its step, ``tabulated.NEWTON_SHARE``) against the route before it (Brent's method per knot, the
    inversion's confirming step) on scenario A at 20° with a 41-point table (95 front knots): F_x within ROUTE_FORCE,
    F_N within ROUTE_NORMAL and a within ROUTE_RADIUS of each run's largest value (they differ in the last ulps of the
    knots and radii), and not bit for bit (the route before was run)."""
    from scipy.optimize import brentq

    from mdr_events.models.continuum import span_front_knots

    def brent(function, low, high, at_low, at_high):
        return np.array([brentq(lambda x, i=i: float(function(np.array([x]), np.array([i]))[0]), lo, hi,
                                xtol=EPS * max(abs(lo), abs(hi)), rtol=4 * EPS)
                         for i, (lo, hi) in enumerate(zip(low, high))])

    table = _paraboloid_table(paper, 41)
    now = me.simulate(paper, "A", alpha=[20.0], method="continuum", profile=table)
    monkeypatch.setattr(span_front_knots, "bracketed_roots", brent)
    monkeypatch.setattr(tb, "NEWTON_SHARE", 0.0)
    before = me.simulate(paper, "A", alpha=[20.0], method="continuum", profile=table)
    for name, bound in (("tangential_force", ROUTE_FORCE), ("normal_force", ROUTE_NORMAL),
                        ("contact_radius", ROUTE_RADIUS)):
        reference = before[name].values
        assert np.nanmax(np.abs(now[name].values - reference)) <= bound * np.nanmax(np.abs(reference)), name
    assert not np.array_equal(now["tangential_force"].values, before["tangential_force"].values)
