"""The continuum's extrema under the rate-dependent law (continuum.rate_run.rate_extrema): the stationary points of
each scan interval's Chebyshev interpolant (continuum.stationary.derivative_roots) against a brute-force dense scan of
the run; the springs' extent alone (RateShifts.slip_radius) against the full evaluation's; the samples and the scan
evaluated together (rate_run.evaluate_run) as each alone."""

from __future__ import annotations

import numpy as np
import pytest
from numpy.polynomial import polynomial

import mdr_events as me
from mdr_events.models.continuum import solve_rate_shifts
from mdr_events.models.continuum import rate_run
from mdr_events.models.continuum.extrema import EXTREMA_KINDS, EXTREMA_QUANTITIES, extremum_names
from mdr_events.models.continuum.rate_run import (RUN_METHOD, _quantity, evaluate_run, rate_extrema, rate_quantities,
                                                  run_end, scan_run)
from mdr_events.models.continuum.span_extrema import EXTREMUM_TIE
from mdr_events.models.continuum.stationary import chebyshev_nodes, derivative_roots

PAPER = me.Parameters.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
#: Paths whose extrema lie inside the scan's intervals (not on its times): scenario B at 30° (F_x's largest while the
#: springs stick and slide at the resting edge, the area's at the edge's stop), a vertical way in and out beyond the
#: pull-off (F_N's least on the receding edge), a slanted one (both), and scenario A (at its corner and on a plateau).
PATHS = {"B 30°": me.Path.scenario_B(30.0, PAPER), "A 20°": me.Path.scenario_A(20.0, PAPER),
         "vertical": me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -200e-6)]), speed=1e-6),
         "slanted": me.Path(np.array([(0.0, 0.0), (1e-4, PAPER.d_max), (3e-4, -200e-6)]), speed=3e-6)}
#: The dense scan's points on the two scan intervals beside the scan's best (and their common time, where a kink of
#: the quantity may lie: the path's corners and the edge's events are the scan's times).
DENSE_POINTS = 4001
#: Rounding of a value of the run: the share of its largest magnitude below which a better refined value is not taken
#: (rate_extrema keeps the scan's point on such a tie).
ROUNDING = EXTREMUM_TIE
#: The roots of a polynomial's derivative read at its Chebyshev points: the values carry rounding of about eps times
#: the largest value, which the interpolation amplifies by its Lebesgue constant (below 3 for 16 Chebyshev points) and
#: the derivative by Markov's n² at most; a simple root of ``p'`` then moves by that over ``|p''|`` there. This factor
#: above that first-order estimate.
ROOT_SAFETY = 10.0
#: The springs' extent alone and the full evaluation's, capped at the radius: a few ulp of the radius (the full
#: evaluation's extent at a receding edge is the record's radius at the time it was reached, within an ulp or two of
#: the radius the extent alone caps it at).
EXTENT_ULPS = 4


@pytest.fixture(scope="module")
def runs():
    out = {}
    for name, path in PATHS.items():
        shifts = solve_rate_shifts(PAPER, path, LAW, method=RUN_METHOD)
        scan = scan_run(shifts)
        out[name] = (shifts, scan, rate_extrema(shifts, scan))
    return out


def _scanned(scan, name: str) -> np.ndarray:
    return {"normal_force": scan.normal, "tangential_force": scan.force,
            "contact_area": np.pi * scan.radius ** 2}[name]


@pytest.mark.parametrize("name", list(PATHS))
def test_the_extrema_are_those_of_a_dense_scan_beside_the_scan_s_best(runs, name):
    """Each extremum against a dense scan of the two intervals beside the scan's best (the extremum is there, the
    quantity smooth inside them): its value at least the dense scan's best, to rounding, and beyond it by at most
    what the scan's spacing h can miss, ``max|q''| h²/8`` (the extremum within h/2 of a dense point), with
    ``max|q''| h²`` the dense scan's largest second difference."""
    shifts, scan, found = runs[name]
    start = shifts.path.first_contact_time()
    refined_inside = 0
    for quantity in EXTREMA_QUANTITIES:
        values = _scanned(scan, quantity)
        scale = float(np.nanmax(np.abs(values)))
        for kind, largest in EXTREMA_KINDS.items():
            sign = 1.0 if largest else -1.0
            value_name, time_name = extremum_names(quantity, kind)
            value, time = found[value_name], found[time_name]
            at = int(np.argmax(sign * values))
            if not 0 < at < len(scan.times) - 1 or value == 0.0:  # (at the run's ends, or the 0 after the contact)
                continue
            dense = np.unique(np.concatenate([np.linspace(scan.times[at - 1], scan.times[at + 1], DENSE_POINTS),
                                              scan.times[at:at + 1]]))
            q = sign * _quantity(shifts, quantity, dense)
            best = float(np.max(q))
            miss = float(np.max(np.abs(np.diff(q, 2)))) / 8.0
            assert best - ROUNDING * scale <= sign * value <= best + miss + ROUNDING * scale, (quantity, kind)
            assert scan.times[at - 1] <= time + start <= scan.times[at + 1]
            assert sign * value == pytest.approx(
                sign * float(_quantity(shifts, quantity, np.array([time + start]))[0]), rel=ROUNDING)
            refined_inside += sign * value > sign * float(values[at]) + ROUNDING * scale
    if name != "A 20°":  # (scenario A's are at its corner, at the edge's stop and on F_x's plateau: the scan's)
        assert refined_inside >= 1


def _earliest_tie(values) -> int:
    """The first scanned value within ``EXTREMUM_TIE`` of the largest (of the run's largest magnitude)."""
    best, size = float(np.max(values)), float(np.max(np.abs(values)))
    return int(np.flatnonzero(values >= best - EXTREMUM_TIE * max(size, abs(best)))[0])


def test_a_plateau_keeps_the_scan_s_point(runs):
    """F_x of scenario A at 20° is constant after the corner (the springs stick, x stands still, new springs attach
    without a shift): its largest is the scan's earliest point of the plateau (the earliest tie, as the paper's law
    reports it), not one that rounding would pick along the plateau."""
    shifts, scan, found = runs["A 20°"]
    at = _earliest_tie(scan.force)
    assert at < int(np.argmax(scan.force))  # (rounding raises a later sample: the plateau is read at its start)
    assert found["tangential_force_max"] == float(scan.force[at])
    assert found["tangential_force_max_time"] == float(scan.times[at]) - shifts.path.first_contact_time()


@pytest.mark.parametrize("beyond, taken", [(0.5, False), (2.0, True)])
def test_a_stationary_point_is_taken_where_it_is_better_beyond_rounding(runs, monkeypatch, beyond, taken):
    """A stationary point better than the scan's best by less than the rounding share (EXTREMUM_TIE of the value) is
    a tie: the scan's point stays; better by more, it is the extremum."""
    shifts, scan, _ = runs["A 20°"]
    at = _earliest_tie(scan.force)
    best, elsewhere = float(scan.force[at]), float(scan.times[at + 1])
    better = best * (1.0 + beyond * EXTREMUM_TIE)

    def stationary(shifts, name, sign, ends):
        return (elsewhere, better) if name == "tangential_force" and sign < 0 else (np.nan, np.nan)
    monkeypatch.setattr(rate_run, "_stationary", stationary)
    found = rate_extrema(shifts, scan)
    start = shifts.path.first_contact_time()
    expected = (better, elsewhere) if taken else (best, float(scan.times[at]))
    assert (found["tangential_force_max"], found["tangential_force_max_time"] + start) == pytest.approx(expected,
                                                                                                       rel=1e-15)


@pytest.mark.parametrize("degree", [3, 7, 12, 15])
def test_derivative_roots_are_a_polynomial_s_stationary_points(degree):
    """A polynomial of ``degree`` with known stationary points (separated: 0.9 times Chebyshev points, jittered),
    read at its Chebyshev points: each root to the rounding its curvature there allows (:data:`ROOT_SAFETY`)."""
    rng = np.random.default_rng(degree)
    count = degree - 1
    stationary = np.sort(0.9 * np.cos(np.pi * (np.arange(count) + 0.5 + rng.uniform(-0.2, 0.2, count)) / count))
    derivative = polynomial.polyfromroots(stationary)
    coefficients = polynomial.polyint(derivative)
    values = polynomial.polyval(chebyshev_nodes(degree), coefficients)
    found = np.sort(derivative_roots(values, degree))
    assert found.size == stationary.size
    largest = float(np.max(np.abs(polynomial.polyval(np.linspace(-1.0, 1.0, 1001), coefficients))))
    curvature = np.abs(polynomial.polyval(stationary, polynomial.polyder(derivative)))
    allowed = ROOT_SAFETY * 3.0 * degree ** 2 * np.finfo(float).eps * largest / curvature
    assert np.all(np.abs(found - stationary) <= allowed), (found - stationary, allowed)
    assert not chebyshev_nodes(degree).flags.writeable


@pytest.mark.parametrize("name, partial", [("B 30°", False), ("A 20°", True), ("slanted", True)])
def test_the_slip_radius_is_the_full_evaluation_s_extent(runs, name, partial):
    """The springs' extent alone (no quadrature, no time the receding radius was reached) is the full evaluation's,
    capped at the radius, to a few ulp; full slip at the same times; never beyond the radius. (Scenario B's springs
    all start to slide at once at the resting edge: no partial slip there.)"""
    shifts = runs[name][0]
    times = np.linspace(0.0, shifts.path.duration, 4001)
    radius, alone, full = shifts._radius(times), shifts.slip_radius(times), shifts._evaluate(times)[1]
    np.testing.assert_allclose(alone, np.minimum(full, radius), rtol=0.0,
                               atol=EXTENT_ULPS * np.spacing(float(np.max(radius))))
    assert np.all(alone <= radius)
    inside = radius > 0.0
    assert np.array_equal((alone >= radius) & inside, (full >= radius) & inside)
    assert np.any((alone >= radius) & inside)
    assert np.any((alone > 0.0) & (alone < radius)) == partial


@pytest.mark.parametrize("name", ["A 20°", "fretting"])
def test_the_samples_and_the_scan_evaluated_together_are_each_alone(runs, name):
    """evaluate_run (one pass over the pieces for the closed form; each in turn for the play of both levels, whose
    events read the scan's sides kept last) gives rate_quantities' and scan_run's values bit for bit."""
    if name == "fretting":
        path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (3e-5, PAPER.d_max), (-3e-5, PAPER.d_max),
                                 (0.0, -2e-4)]), speed=PAPER.v)
        shifts = solve_rate_shifts(PAPER, path, LAW, method=RUN_METHOD)
    else:
        shifts = runs[name][0]
    start = shifts.path.first_contact_time()
    times = np.linspace(0.0, run_end(shifts)[0] - start, 401)
    together, scan = evaluate_run(shifts, times)
    alone = rate_quantities(shifts, times)
    assert together.keys() == alone.keys()
    for quantity in alone:
        np.testing.assert_array_equal(together[quantity], alone[quantity])
    for part, value in zip(scan, scan_run(shifts)):
        np.testing.assert_array_equal(part, value)


@pytest.mark.parametrize("beyond, taken", [(0.5, False), (2.0, True)])
def test_a_tie_near_zero_is_held_to_the_run_s_rounding_as_the_paper_s(runs, monkeypatch, beyond, taken):
    """The scan's best near 0 (F_x of scenario A at 20° shifted so that its largest is 1e-30 N): a stationary point
    better by less than EXTREMUM_TIE of the quantity's largest magnitude along the run is a tie, as
    ``solution.extremum`` ties its spans' values (``within_tie``); held to ``EXTREMUM_TIE · |value|`` (1e-42 N), as
    the rate run held it, rounding alone would have moved the extremum."""
    shifts, scan, _ = runs["A 20°"]
    force = scan.force - float(np.max(scan.force)) + 1e-30
    at = _earliest_tie(force)
    best, elsewhere = float(force[at]), float(scan.times[at + 1])
    better = best + beyond * EXTREMUM_TIE * float(np.max(np.abs(force)))

    def stationary(shifts, name, sign, ends):
        return (elsewhere, better) if name == "tangential_force" and sign < 0 else (np.nan, np.nan)
    monkeypatch.setattr(rate_run, "_stationary", stationary)
    found = rate_extrema(shifts, scan._replace(force=force))
    start = shifts.path.first_contact_time()
    expected = (better, elsewhere) if taken else (best, float(scan.times[at]))
    assert (found["tangential_force_max"], found["tangential_force_max_time"] + start) == pytest.approx(expected,
                                                                                                       rel=1e-15)


def test_a_step_whose_constant_term_outweighs_the_rest_has_no_stationary_point():
    """``stationary.ROOT_FREE_MARGIN``: a step of a dense output whose derivative's Chebyshev coefficients have
    ``|c₀|`` just above the margin times the others' sum is left unsought; its derivative then has no root that the
    search keeps (real to ``IMAGINARY_SHARE``, within ``[-1, 1]``), on derivatives built to sit at the boundary with
    every sign and weight of the others (one coefficient alone puts a root at ``∓c₀/c₁``, inside [-1, 1] for a margin
    below 1)."""
    from numpy.polynomial import chebyshev

    from mdr_events.models.continuum.stationary import DENSE_DEGREE, IMAGINARY_SHARE, ROOT_FREE_MARGIN

    rng = np.random.default_rng(28)
    for trial in range(400):
        others = rng.standard_normal(DENSE_DEGREE - 1) * (rng.uniform(size=DENSE_DEGREE - 1) < 0.5 + trial / 800)
        others[trial % (DENSE_DEGREE - 1)] = rng.choice([-1.0, 1.0])  # (at least one)
        derivative = np.concatenate([[rng.choice([-1.0, 1.0]) * ROOT_FREE_MARGIN * (1 + 1e-9)
                                      * np.sum(np.abs(others))], others])
        values = chebyshev.chebval(chebyshev_nodes(), chebyshev.chebint(derivative))
        kept = [root for root in chebyshev.chebroots(derivative)
                if abs(root.imag) <= IMAGINARY_SHARE and abs(root.real) <= 1.0]
        assert not kept, (derivative, kept)
        assert not [root for root in derivative_roots(values) if abs(root) <= 1.0], derivative
