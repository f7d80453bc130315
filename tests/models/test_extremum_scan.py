"""The extrema's scan and the fill of a run's samples built for all spans at once (issue 28: one pass over the spans)
against the routes span by span they replace, kept here as references: the same values bit for bit, since every
value is computed by the same operations element by element (a call over several spans' points gives each point the
value a call over its span's alone gives). The moving spans read as polynomials in ``√a`` (``span_polynomials``) are
another route, equal to these to rounding alone: ``test_span_polynomials.py`` compares them; here the route of
before is taken throughout (``POLYNOMIAL_ROUTE`` off)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum import solution as S
from mdr_events.models.continuum import span_extrema as X
from mdr_events.models.continuum import closed_form, extrema, span_polynomials, stationary
from mdr_events.models.continuum.dense import force_values
from mdr_events.models.continuum.state import Regime
from mdr_events.models.paths import exit_depth
from mdr_events.theory import analytic

PAPER = me.Parameters.paper()


@pytest.fixture(autouse=True)
def _route_of_before(monkeypatch):
    """Every span read by the route of before (the routes compared here bit for bit are those of the other spans)."""
    monkeypatch.setattr(span_polynomials, "POLYNOMIAL_ROUTE", False)

HERTZ = PAPER.replace(dgamma0=0.0, dgamma1=0.0)
#: A flat punch pressed 10 µm into a layer a tenth of its radius thick (``bench_layer_punch.py``'s): its contact
#: recedes under the face along two moving spans, each a layer's closed form (their series read in one call).
FACE, PUNCH = me.FlatPunch(2e-3), PAPER.replace(d_max=1e-5)
ZIGZAG = [(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)]


def _table():
    radii = np.linspace(0.0, 4e-3, 41)
    return me.TabulatedProfile(radii, radii**2 / (2 * PAPER.R))


#: label -> (params, path, solve_path's keywords): the spans of every kind the scan meets (closed forms, DOP853's
#: steps, a table's panels, linear forces, constants), both branches with several spans each, Coulomb's compressed
#: zone, a layer, many pinned spans (the reciprocating path).
CASES = {
    "A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {}),
    "B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {}),
    "zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {}),
    "table, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=_table()), {"profile": _table()}),
    "cone, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER, profile=PowerLaw.cone(0.05)),
                            {"profile": PowerLaw.cone(0.05)}),
    "Hertz, Coulomb, A 20°": lambda: (HERTZ, me.Path.scenario_A(20.0, HERTZ),
                                      {"friction": FrictionLaw("coulomb", mu=0.3)}),
    "Coulomb with adhesion, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER),
                                             {"friction": FrictionLaw("coulomb", mu=0.3)}),
    "thin layer, zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {"layer": me.Layer(1e-3)}),
    "reciprocating": lambda: (PAPER, _reciprocating(), {}),
    "flat punch, B 20°": lambda: (PAPER, me.Path.scenario_B(20.0, PAPER, profile=me.FlatPunch(2e-3)),
                                  {"profile": me.FlatPunch(2e-3)}),
    "n = 1.05, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=PowerLaw(0.5, 1.05)),
                                {"profile": PowerLaw(0.5, 1.05)}),
    "tau0+coulomb with adhesion, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER),
                                                  {"friction": FrictionLaw("tau0+coulomb", mu=0.3)}),
    "5 mm layer, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {"layer": me.Layer(5e-3)}),
    "flat punch receding on a thin layer, B 20°": lambda: (PUNCH, me.Path.scenario_B(20.0, PUNCH, profile=FACE),
                                                          {"profile": FACE, "layer": me.Layer(0.1 * FACE.radius)}),
}
#: (The rate-dependent law's extrema are its own, ``rate_run``'s, not this scan's: it has no case here.)


def _reciprocating():
    """In at 20° to ``(x_c, d_max)``, ten cycles ``x_c ± 3 ū(a_max)``, out vertically (``bench_simulate.py``'s): some
    sixty pinned spans, their forces constant or linear in time."""
    amplitude = 3.0 * float(analytic.critical_shift(float(analytic.jkr_contact_radius(PAPER.d_max, PAPER,
                                                                                     PAPER.dgamma0)), PAPER))
    x_c = PAPER.d_max / math.tan(math.radians(20.0))
    turns = [(x_c + amplitude * (1 if i % 2 == 0 else -1), PAPER.d_max) for i in range(20)]
    return me.Path([(0.0, 0.0), (x_c, PAPER.d_max), *turns, (x_c, PAPER.d_max), (x_c, exit_depth(PAPER))], PAPER.v)


def _reference_scan(solution):
    """``scan_spans`` as it was, span by span: each moving span's grid by ``_radius_grid``, a pinned one's by
    ``np.linspace``, each span evaluated alone, then ``F_N`` of all of them."""
    times, values = [], []
    for index, span in enumerate(solution.spans):
        lower, upper = span.t_start - solution.t_contact, span.t_end - solution.t_contact
        count = X.EXTREMUM_GRID if upper > lower else 1
        if span.regime in (Regime.GROWING, Regime.SHRINKING):
            grid, radii = X._radius_grid(solution, span, lower, upper, count)
        else:
            grid, radii = np.linspace(lower, upper, count), None
        times.append(grid)
        values.append(S.evaluate_span(solution, index, grid, sliding=False, radii=radii, normal=False))
    S._fill_normal_force(solution.model, values)
    return times, values


def _runs(case):
    params, path, options = CASES[case]()
    solution = solve_path(params, path, **options)
    return [solution] + ([solution.compressed] if solution.compressed is not None else [])


@pytest.mark.parametrize("case", list(CASES))
def test_the_scan_of_all_spans_at_once_is_the_scan_span_by_span(case):
    for run in _runs(case):
        times, values = _reference_scan(run)
        scan = X.scan_spans(run)
        assert len(scan.times) == len(times) == len(run.spans)
        for found, reference in zip(scan.times, times):
            np.testing.assert_array_equal(found, reference)
        for found, reference in zip(scan.values, values):
            assert found.keys() == reference.keys()
            for name in reference:
                np.testing.assert_array_equal(found[name], reference[name], err_msg=name)


def test_the_rows_of_linspace_are_linspace_row_by_row():
    """``_linspace_rows``: each row ``np.linspace``'s own, a row of no step (equal ends) and one whose step underflows
    to 0 (a denormal difference) among others; ``np.linspace`` of the arrays would take the zero step's route for every
    row."""
    start = np.array([0.0, 1.0, 2.5e-4, 5e-324, -3.0, 7.0])
    stop = np.array([1.0, 1.0, 1.7e-3, 1e-323, 2.0, -7.0])
    rows = X._linspace_rows(start, stop, X.EXTREMUM_GRID)
    for row, lower, upper in zip(rows, start, stop):
        np.testing.assert_array_equal(row, np.linspace(lower, upper, X.EXTREMUM_GRID))


def _span_by_span(interpolants, points):
    """``span_forces`` as it was: each span's interpolant called on its own points (``force_values``)."""
    return [force_values(interpolant, where) for interpolant, where in zip(interpolants, points)]


@pytest.mark.parametrize("case", list(CASES))
def test_the_fill_of_all_spans_at_once_is_the_fill_span_by_span(case, monkeypatch):
    """``evaluate`` at a run's 2001 samples and at times out of order (each span's rows gathered by index), with
    ``F_x`` of all spans by the kinds of their interpolants and with each span's own call: the same, bit for bit; so
    is the scan."""
    for run in _runs(case):
        samples = np.linspace(0.0, run.end_time * (1.0 + 1.0 / 2001), 2001)
        shuffled = np.random.default_rng(7).permutation(samples[::3])
        found = [S.evaluate(run, times) for times in (samples, shuffled)] + [X.scan_spans(run).values]
        with monkeypatch.context() as patch:
            patch.setattr(S, "span_forces", _span_by_span)
            reference = [S.evaluate(run, times) for times in (samples, shuffled)] + [X.scan_spans(run).values]
        for got, expected in zip(found[:2], reference[:2]):
            for name in S.EVALUATED_QUANTITIES:
                np.testing.assert_array_equal(got[name], expected[name], err_msg=name)
        for got, expected in zip(found[2], reference[2]):
            np.testing.assert_array_equal(got["tangential_force"], expected["tangential_force"])


@pytest.mark.parametrize("share, refined", [(0.5, False), (4.0, True)])
def test_a_refined_point_replaces_the_scans_beyond_the_tie_alone(share, refined, monkeypatch):
    """``extremum``'s refinement and its ties are one rule (``within_tie``, the rate run's too): a stationary point
    better than the scan's best point by ``share`` times ``EXTREMUM_TIE`` of the quantity's size along the run replaces
    it only beyond the tie (``share > 1``). ``F_N``'s minimum of scenario A (the pull-off, -0.02 N against 0.52 N at
    the top: the old rule, a tie of ``2 EXTREMUM_TIE`` of the value itself, took a point better by half the run's tie)."""
    run = solve_path(PAPER, me.Path.scenario_A(20.0, PAPER))
    scan = X.scan_spans(run)
    kept = scan.matrix("normal_force")  # (side 1: the minimum's, of -F_N)
    best, first, size = np.array(kept.best[1]), np.array(kept.first[1]), kept.size
    holder = int(np.nanargmax(best))
    scanned_time = float(scan.times[holder][first[holder]])
    scanned = float(scan.values[holder]["normal_force"][first[holder]])
    found_time, found = scanned_time + 1.0, scanned - share * X.EXTREMUM_TIE * size  # (lower: better for a minimum)

    def stationary(solution, index, quantity, times, radii):
        return [(found_time, found)] if index == holder and quantity == "normal_force" else []

    monkeypatch.setattr(X, "stationary_points", stationary)
    assert X.extremum(run, "normal_force", largest=False, scan=scan) == \
        ((found_time, found) if refined else (scanned_time, scanned))


def _stationary_before(solution, index, quantity):
    """``stationary_points``' early answers as they were (no point out of contact, of the radius and the area, nor of
    ``F_N`` on a pinned radius; every other span searched): the reference of ``never_stationary``."""
    span = solution.spans[index]
    if span.regime is Regime.NONE or quantity in ("contact_radius", "contact_area"):
        return True
    return quantity == "normal_force" and span.regime is Regime.PINNED


@pytest.mark.parametrize("case", ["A 20°", "B 30°", "zigzag", "reciprocating", "table, A 20°"])
def test_the_spans_passed_over_change_no_extremum(case, monkeypatch):
    """``extremum`` does not refine the spans ``never_stationary`` names (also a constant force or one linear in time):
    every extremum of every quantity is the one found with every span refined as before, bit for bit."""
    for run in _runs(case):
        found = [X.extremum(run, quantity, largest) for quantity in X.EXTREMUM_QUANTITIES for largest in (True, False)]
        with monkeypatch.context() as patch:
            patch.setattr(X, "never_stationary", lambda solution, index, quantity: False)
            patch.setattr(stationary, "never_stationary", _stationary_before)
            reference = [X.extremum(run, quantity, largest) for quantity in X.EXTREMUM_QUANTITIES
                         for largest in (True, False)]
        assert found == reference


def _extremum_before(solution, quantity, largest, scan):
    """``extremum`` as it was (issue 28, before the six extrema's scan was reduced at once): each quantity's matrix
    and each sign's reduction on its own, the loop over the spans on NumPy's arrays."""
    if quantity == "tangential_force" and solution.compressed is not None:
        return _extremum_before(solution.compressed, quantity, largest, X.scan_spans(solution.compressed))
    sign = 1.0 if largest else -1.0
    width = max(len(times) for times in scan.times)
    matrix = np.full((len(scan.times), width), np.nan)
    for row, filled in enumerate(scan.values):
        values = X._quantity(filled, quantity)
        matrix[row, :len(values)] = values
    with np.errstate(invalid="ignore"):
        largest_row = np.fmax.reduce(np.abs(matrix), axis=1)
        reach = np.fmax(np.fmax.reduce(np.abs(np.diff(matrix, axis=1)), axis=1), 0.0) if width > 1 \
            else np.zeros(len(largest_row))
        size = float(np.fmax.reduce(largest_row[np.isfinite(largest_row)], initial=0.0))
        signed = matrix * sign
        best = np.fmax.reduce(signed, axis=1)
        first = np.argmax(signed >= (best - X.EXTREMUM_TIE * largest_row)[:, None], axis=1)
    spans = np.flatnonzero(np.isfinite(best))
    if not spans.size:
        return math.nan, math.nan
    best_scanned = float(np.max(best[spans]))
    results = []
    for index in spans.tolist():
        times, i, value = scan.times[index], int(first[index]), float(best[index])
        time = float(times[i])
        if len(times) > 1 and value + reach[index] >= best_scanned \
                and quantity not in ("contact_radius", "contact_area") \
                and not stationary.never_stationary(solution, index, quantity):
            time, value = X._refined(solution, scan, index, quantity, sign, (i, value), size)
        results.append((time, value))
    best_value = max(value for _, value in results)
    best_time, best_value = min((time, value) for time, value in results if X.within_tie(value, best_value, size))
    return best_time, sign * best_value


@pytest.mark.parametrize("case", list(CASES))
def test_the_extrema_reduced_at_once_are_the_extrema_one_by_one(case, monkeypatch):
    """Every quantity's maximum and minimum, each alone and the six of ``solution_extrema`` reduced in one array
    (``ExtremumScan.prepare``), are what the route of one matrix and one sign at a time gives
    (``_extremum_before``), bit for bit."""
    for run in _runs(case):
        reference = {(quantity, largest): _extremum_before(run, quantity, largest, X.scan_spans(run))
                     for quantity in X.EXTREMUM_QUANTITIES for largest in (True, False)}
        assert {key: X.extremum(run, *key) for key in reference} == reference
        found = extrema.solution_extrema(run)
        with monkeypatch.context() as patch:
            patch.setattr(extrema, "extremum", lambda solution, quantity, largest, scan=None: _extremum_before(
                solution, quantity, largest, X.scan_spans(solution) if scan is None else scan))
            assert extrema.solution_extrema(run) == found


def test_equal_parts_are_numpys_linspace():
    """``closed_form.equal_parts`` (``ClosedForce.stationary``'s readings in Python floats) gives ``np.linspace``'s
    numbers bit for bit: intervals of every scale, reversed, of no length, of one ulp and of denormal steps (NumPy's
    other route)."""
    rng = np.random.default_rng(28)
    ends = [(0.0, 0.0), (1.0, 1.0), (0.0, 5e-324), (5e-324, 1e-323), (-1.0, 1.0), (0.7, 0.3), (-0.0, 0.0),
            (1e300, 1.5e300)]
    ends += [tuple(rng.normal(size=2) * 10.0 ** float(rng.integers(-300, 300))) for _ in range(500)]
    ends += [(float(a), float(np.nextafter(a, np.inf))) for a in rng.normal(size=100)]
    for low, high in ends:
        for parts in (1, 2, closed_form.STATIONARY_READINGS, X.EXTREMUM_GRID - 1):
            found = closed_form.equal_parts(low, high, parts)
            expected = np.linspace(low, high, parts + 1).tolist()
            assert [value.hex() for value in found] == [value.hex() for value in expected]
