"""The extrema's moving spans read as polynomials in ``s = √a`` (``span_polynomials``, issue 28) against the route of
before (``POLYNOMIAL_ROUTE`` off: ``evaluate_span``, the branch's NumPy forms, ``stationary_points``), within the
rounding the two computations differ by, derived below; and bit for bit where no span is such a polynomial (another
indenter, a layer, the rate law's own run, Coulomb's compressed zone)."""

from __future__ import annotations

import dataclasses
import functools
import math
import sys
import threading
from fractions import Fraction

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum import span_extrema as X
from mdr_events.models.continuum import span_polynomials as SP
from mdr_events.models.continuum.branch import Branch
from mdr_events.models.continuum.extrema import solution_extrema
from mdr_events.models.continuum.tolerances import EPS

PAPER = me.Parameters.paper()
ZIGZAG = [(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)]
#: The ulp of a value's terms (``Σ |c_k| s^k``, and the parts the route of before sums apart) by which the two routes
#: may differ: Horner's rule over degree ``n = 6`` errs by ``γ_2n ≈ 12 ε`` of the terms; the route of before sums at
#: most 8 rounded terms of the same size (``a (A₀ + A₁ a/2) + B₀ d + B₁ (a d − ∫d) + C ∫d + C₀ ∫d₀``, then
#: ``F₀ + 2G* (P − P₀)``; each of ``d``, ``∫d`` two terms); ``s = √a`` is rounded by half an ulp, which moves the
#: value by ``s p'(s) ε/2 ≤ (n/2) ε`` of the terms (3); the depth the route of before reads at a scan time, from the
#: time of the radius's depth, by a few ulp of the segment's terms (4): ``12 + 8 + 3 + 4 = 27 ≤ 32``.
SCAN_ULPS = 32
#: The ulp of ``s`` by which the routes' stationary points may differ besides the value's flatness: each root is
#: held to 4 ulp (``brentq``'s ``4 ε``, ``span_polynomials.ROOT_ULPS``), and the time of its radius is a few more
#: operations (``Segment.time_at_depth`` of the branch's depth): ``4 + 4 + 4``.
ROOT_TIME_ULPS = 12


def _reciprocating():
    x_c = PAPER.d_max / math.tan(math.radians(20.0))
    turns = [(x_c + 2e-5 * (1 if i % 2 == 0 else -1), PAPER.d_max) for i in range(20)]
    return me.Path([(0.0, 0.0), (x_c, PAPER.d_max), *turns, (x_c, PAPER.d_max), (x_c, -1e-4)], PAPER.v)


def _table():
    radii = np.linspace(0.0, 4e-3, 41)
    return me.TabulatedProfile(radii, radii**2 / (2 * PAPER.R))


#: label -> (params, path, solve_path's keywords, whether some span is a polynomial in √a).
CASES = {
    "A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {}, True),
    "B 20°": lambda: (PAPER, me.Path.scenario_B(20.0, PAPER), {}, True),
    "B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {}, True),
    "B 60°": lambda: (PAPER, me.Path.scenario_B(60.0, PAPER), {}, True),
    "zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {}, True),
    "reciprocating": lambda: (PAPER, _reciprocating(), {}, True),
    "Hertz (no adhesion), B 30°": lambda: (PAPER.replace(dgamma0=0.0, dgamma1=0.0),
                                           me.Path.scenario_B(30.0, PAPER.replace(dgamma0=0.0, dgamma1=0.0)), {}, True),
    "adhesion Δγ1 = Δγ0, B 30°": lambda: (PAPER.replace(dgamma1=PAPER.dgamma0),
                                          me.Path.scenario_B(30.0, PAPER.replace(dgamma1=PAPER.dgamma0)), {}, True),
    "tau0+coulomb, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER),
                                    {"friction": me.FrictionLaw("tau0+coulomb", mu=0.3)}, None),
    "table, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=_table()), {"profile": _table()}, False),
    "power law, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER, profile=me.PowerLaw(2.0e3, 3.0)),
                                 {"profile": me.PowerLaw(2.0e3, 3.0)}, False),
    "layer, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {"layer": me.Layer(5e-3)}, False),
    "Coulomb with adhesion, B 20°": lambda: (PAPER, me.Path.scenario_B(20.0, PAPER),
                                             {"friction": me.FrictionLaw("coulomb", mu=0.3)}, False),
}


def _row_terms(solution, polynomials, row: int, radii: np.ndarray, times: np.ndarray) -> tuple[np.ndarray, ...]:
    """The terms of ``F_x`` and ``F_N`` of a polynomial span at its scan's radii and times (s from first contact):
    ``Σ_k |c_k| v^k`` (``v`` its variable), with the parts the route of before sums apart: ``|F₀|`` and ``|2G* P₀|``
    of a closed form, the depth's segment terms ``2E* a (|d_s| + |v_d| (|t| + |t₀|))`` read at a scan time, a linear
    force's ``|r| (|t_c| + |t₀|)``: the size the rounding of either route is a share of."""
    span = solution.spans[polynomials.indices[row]]
    segment, E2 = span.segment, 2.0 * PAPER.E_star
    t = solution.t_contact + times
    variable = np.sqrt(radii) if polynomials.moving[row] else times
    powers = np.abs(variable)[:, None] ** np.arange(SP.DEGREE + 1)
    force = np.abs(polynomials.force[row]) @ powers.T
    normal = np.abs(polynomials.normal[row]) @ powers.T + E2 * radii * (abs(segment.ds) + abs(segment.vd) * (
        np.abs(t) + abs(segment.t0))) + E2 * radii**3 / (3.0 * PAPER.R)
    if polynomials.moving[row]:
        force = force + abs(span.interpolant.force) + abs(span.interpolant.G2 * span.interpolant.origin)
    elif span.interpolant is not None:
        force = force + abs(span.interpolant.force) + abs(span.interpolant.rate) * (
            abs(solution.t_contact) + abs(span.interpolant.t0))
    return force, normal


def _terms(solution, polynomials, quantity: str) -> float:
    """The largest terms of ``quantity`` (:func:`_row_terms`) over every scan point of the polynomial spans."""
    scan = X.scan_spans(solution)
    largest = 0.0
    for row, index in enumerate(polynomials.indices):
        terms = _row_terms(solution, polynomials, row, scan.values[index]["contact_radius"], scan.times[index])
        largest = max(largest, float(np.max(terms[0 if quantity == "tangential_force" else 1])))
    return largest


@functools.lru_cache(maxsize=None)
def _run(case):
    """A case's run (shared by the tests: neither route changes a solution) and whether it has polynomial spans."""
    params, path, options, taken = CASES[case]()
    return solve_path(params, path, **options), taken


def _old(function, monkeypatch):
    with monkeypatch.context() as patch:
        patch.setattr(SP, "POLYNOMIAL_ROUTE", False)
        return function()


@pytest.mark.parametrize("case", list(CASES))
def test_the_polynomial_scan_is_the_scan_of_before_to_rounding(case, monkeypatch):
    """Every scan point's ``F_x`` and ``F_N`` (and the radius, bit for bit) within :data:`SCAN_ULPS` ε of the terms of
    its own value; every span that is no polynomial in ``√a``, and a run without one, bit for bit."""
    solution, taken = _run(case)
    polynomials = SP.span_polynomials(solution)
    if taken is not None:
        assert bool(polynomials.indices) is taken
    new = X.scan_spans(solution)
    old = _old(lambda: X.scan_spans(solution), monkeypatch)
    for index, (got, expected) in enumerate(zip(new.values, old.values)):
        np.testing.assert_array_equal(new.times[index], old.times[index])
        np.testing.assert_array_equal(got["contact_radius"], expected["contact_radius"])
        if index not in polynomials.indices:
            assert got.keys() == expected.keys()
            for name in got:
                np.testing.assert_array_equal(got[name], expected[name], err_msg=name)
            continue
        force_terms, normal_terms = _row_terms(solution, polynomials, polynomials.indices.index(index),
                                               got["contact_radius"], new.times[index])
        assert np.all(np.abs(got["tangential_force"] - expected["tangential_force"]) <= SCAN_ULPS * EPS * force_terms)
        assert np.all(np.abs(got["normal_force"] - expected["normal_force"]) <= SCAN_ULPS * EPS * normal_terms)


@pytest.mark.parametrize("case", list(CASES))
def test_the_polynomial_extrema_are_those_of_before_to_rounding(case, monkeypatch):
    """``solution_extrema``: each value within :data:`SCAN_ULPS` ε of the run's largest terms of its quantity; each
    time the same, or (a stationary point) within what a flat extremum's value tolerance allows,
    ``δt = sqrt(2 (δF_new + δF_old) / |F_tt|)`` (``F_tt = F_ss / (dt/ds)²`` at ``F_s = 0``, read off the span's
    polynomial), plus :data:`ROOT_TIME_ULPS` ulp of ``s`` carried to the time; bit for bit without polynomials."""
    solution, _ = _run(case)
    polynomials = SP.span_polynomials(solution)
    new = solution_extrema(solution)
    old = _old(lambda: solution_extrema(solution), monkeypatch)
    if not polynomials.indices:
        assert new == old
        return
    assert new.keys() == old.keys()
    for quantity in ("normal_force", "tangential_force", "contact_area"):
        tolerance = SCAN_ULPS * EPS * (_terms(solution, polynomials, quantity) if quantity != "contact_area" else 0.0)
        for kind in ("max", "min"):
            value, time = f"{quantity}_{kind}", f"{quantity}_{kind}_time"
            assert abs(new[value] - old[value]) <= tolerance, (value, new[value], old[value])
            if new[time] != old[time]:
                assert abs(new[time] - old[time]) <= _time_tolerance(solution, polynomials, quantity, old[time],
                                                                      tolerance), (time, new[time], old[time])


def _time_tolerance(solution, polynomials, quantity: str, time: float, tolerance: float) -> float:
    """What a stationary point's time may move by, at ``time`` (s from first contact) of a polynomial span."""
    t = solution.t_contact + time
    index = next(index for index, moving in zip(polynomials.indices, polynomials.moving)
                 if moving and solution.spans[index].t_start <= t <= solution.spans[index].t_end)
    span, row = solution.spans[index], polynomials.indices.index(index)
    branch = solution.model.branch(span.regime)
    a = branch.radius(max(float(span.segment.d(t)), branch.jump_off_depth), 1e-14)
    s = math.sqrt(a)
    coefficients = (polynomials.force if quantity == "tangential_force" else polynomials.normal)[row]
    second = sum(k * (k - 1) * c * s ** (k - 2) for k, c in enumerate(coefficients) if k >= 2)
    dt_ds = 2.0 * s * branch.slope(a) / span.segment.vd
    curvature = abs(second) / dt_ds**2
    return math.sqrt(2.0 * 2.0 * tolerance / curvature) + abs(dt_ds) * ROOT_TIME_ULPS * EPS * s + 8 * EPS * abs(t)


#: Runs through ``simulate`` whose extrema are no span's (the rate law's own run, Coulomb's part on a layer) or no
#: polynomial's: the dataset bit for bit with the route on and off.
SIMULATED = {
    "rate law, B 30°": lambda: (dataclasses.replace(me.Contact.paper(), adhesion=me.RateDependentAdhesion(
        PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)), "B", 30.0),
    "power law, A 30°": lambda: (dataclasses.replace(me.Contact.paper(), indenter=me.PowerLaw(2.0e3, 3.0)), "A", 30.0),
}


@pytest.mark.parametrize("case", list(SIMULATED))
def test_runs_without_polynomial_spans_are_bit_for_bit(case, monkeypatch):
    contact, scenario, angle = SIMULATED[case]()

    def run():
        return me.simulate(contact, scenario, alpha=[angle], method="continuum")

    new, old = run(), _old(run, monkeypatch)
    for name in new.variables:
        mine, theirs = np.asarray(new[name].values), np.asarray(old[name].values)
        assert mine.tobytes() == theirs.tobytes() if mine.dtype.kind == "f" else np.array_equal(mine, theirs), name


def test_simulate_differs_in_the_extrema_alone(monkeypatch):
    """Scenario B through ``simulate``: every variable but the extrema bit for bit with the route on and off (the
    samples, the event log), the extrema within their derived tolerance (above)."""
    def run():
        return me.simulate(PAPER, "B", alpha=[30.0], method="continuum")

    new, old = run(), _old(run, monkeypatch)
    for name in new.variables:
        if name.endswith(("_max", "_min", "_max_time", "_min_time")):
            continue
        mine, theirs = np.asarray(new[name].values), np.asarray(old[name].values)
        assert mine.tobytes() == theirs.tobytes() if mine.dtype.kind == "f" else np.array_equal(mine, theirs), name


#: A hair: an interior maximum above its bracket's ends by this share of the value.
HAIR = 1e-13


@pytest.mark.parametrize("curvature", [1.0, 1e-3, 1e-6])
def test_an_interior_extremum_above_its_ends_by_a_hair_is_found(curvature):
    """``polynomial_stationary`` on ``p(s) = c − h x² + e x³`` (``x = s − m``, expanded in ``s``; ``e`` small: an
    asymmetric bump), a maximum at ``s = m`` inside ``[m − δ, m + δ]`` above both ends by :data:`HAIR` of ``c``: found
    (the one root, the other ``2h/(3e)`` away), and within the root's conditioning of ``m``: Horner's ``γ_2n`` (``2n =
    12``) of the derivative's terms ``Σ |k c_k| m^(k−1)`` over its slope ``|p''(m)|``, plus
    :data:`~.span_polynomials.ROOT_ULPS` ulp of ``m``; its value above the ends' values."""
    m, c = 1.0, 1.0
    delta = math.sqrt(HAIR * c / curvature)
    e = 1e-3 * curvature / delta
    coefficients = [c - curvature * m**2 - e * m**3, 2 * curvature * m + 3 * e * m**2, -curvature - 3 * e * m,
                    e, 0.0, 0.0, 0.0]
    found = SP.polynomial_stationary(coefficients, m - delta, m + delta)
    assert len(found) == 1
    slope_terms = sum(abs(k * ck) * m ** (k - 1) for k, ck in enumerate(coefficients) if k >= 1)
    second = abs(sum(k * (k - 1) * ck * m ** (k - 2) for k, ck in enumerate(coefficients) if k >= 2))
    assert abs(found[0] - m) <= 12 * EPS * slope_terms / second + SP.ROOT_ULPS * EPS * m
    value = SP.polynomial_value(coefficients, found[0])
    assert value > max(SP.polynomial_value(coefficients, end) for end in (m - delta, m + delta))


def test_horner_of_rows_is_each_rows_own():
    """``horner`` over a matrix of rows: each row's values those of the row alone, and ``numpy.polynomial``'s to
    ``γ_2n`` of the terms."""
    rng = np.random.default_rng(28)
    coefficients = rng.normal(size=(5, SP.DEGREE + 1))
    s = rng.uniform(0.0, 2.0, size=(5, 9))
    together = SP.horner(coefficients, s)
    for row in range(5):
        np.testing.assert_array_equal(together[row], SP.horner(coefficients[row:row + 1], s[row:row + 1])[0])
        reference = np.polynomial.polynomial.polyval(s[row], coefficients[row])
        terms = np.abs(coefficients[row]) @ (s[row][None, :] ** np.arange(SP.DEGREE + 1)[:, None])
        assert np.all(np.abs(together[row] - reference) <= 2 * 2 * SP.DEGREE * EPS * terms)


@pytest.mark.parametrize("case", ["A 20°", "B 20°", "B 30°", "B 60°", "zigzag", "reciprocating"])
def test_the_proof_of_no_stationary_point_changes_no_extremum(case, monkeypatch):
    """``polynomial_stationary`` skips its readings where the Taylor shift proves the derivative keeps its sign
    (``_root_free``): every extremum is the one of the readings everywhere, bit for bit."""
    solution, _ = _run(case)
    found = solution_extrema(solution)
    monkeypatch.setattr(SP, "_root_free", lambda slope, low, high: False)
    assert solution_extrema(solution) == found


def test_the_proof_of_no_root_holds_where_it_is_given():
    """``_root_free`` on random polynomials of degree 5 and brackets about their roots and away from them: where it
    answers ``True`` the derivative keeps its sign at 2001 points of the bracket, and it answers ``True`` on brackets
    away from every root (it is not vacuous)."""
    rng = np.random.default_rng(5)
    proven = 0
    for _ in range(400):
        roots = rng.uniform(-1.0, 1.0, size=5)
        slope = np.polynomial.polynomial.polyfromroots(roots) * rng.uniform(0.5, 2.0)
        low = rng.uniform(-1.2, 1.0)
        high = low + 10.0 ** rng.uniform(-6.0, -0.5)
        if SP._root_free(slope.tolist(), low, high):
            proven += 1
            values = np.polynomial.polynomial.polyval(np.linspace(low, high, 2001), slope)
            assert np.all(values > 0) or np.all(values < 0)
            assert not np.any((roots >= low) & (roots <= high))
    assert proven > 100


def test_the_proof_s_interval_covers_its_bracket_exactly():
    """``_root_free`` proves a sign on ``[m − h, m + h]`` about the rounded middle ``m``: that interval covers the
    bracket ``[low, high]`` in exact arithmetic (``fractions``), on brackets from one ulp wide to wide, from 0 and away
    from it, where ``m ± (high − low)/2`` misses an end by an ulp about half the time."""
    rng = np.random.default_rng(274)
    for _ in range(2000):
        low = 0.0 if rng.uniform() < 0.2 else float(np.ldexp(rng.uniform(0.5, 1.0), int(rng.integers(-40, 10))))
        width = rng.choice([0.0, 1.0, 2.0 ** -52, 10.0 ** rng.uniform(-12.0, 2.0)])
        high = math.nextafter(low, math.inf) if width == 0.0 else low + width * max(low, 1.0)
        middle, half = SP._centred(low, high)
        assert Fraction(middle) - Fraction(half) <= Fraction(low) <= Fraction(high) <= Fraction(middle) + Fraction(half)
        needed = max(Fraction(high) - Fraction(middle), Fraction(middle) - Fraction(low))
        assert Fraction(half) - needed <= 2 * Fraction(math.ulp(half))  # (rounded, then raised by an ulp: no wider)


#: Threads and runs each that :func:`fold_radius` is called from at once, each run with a parameters object of its own
#: (so that each call drops the least recently kept radius): the dict of before dropped one key from two threads
#: (a ``KeyError``) in each of 6 runs of this size we tried (in 1 of 6 with 100 calls).
FOLD_THREADS, FOLD_CALLS = 8, 1000
#: Every this many calls a thread checks its radius against the branch's own iteration (each check as dear as a call).
FOLD_CHECKED = 8


def test_the_fold_radius_is_kept_safely_from_threads():
    """``fold_radius`` called from :data:`FOLD_THREADS` threads at once (dask's threaded scheduler), every call a new
    parameters object: no error, and the radii checked (:data:`FOLD_CHECKED`) the branch's own bit for bit; the same object's radius is kept
    (read back without a new iteration)."""
    switch = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # (threads switch as often as they can: the race of before in most runs)
    failures = []

    def calls(thread):
        try:
            for call in range(FOLD_CALLS):
                params = PAPER.replace(R=PAPER.R * (1.0 + 1e-3 * (thread * FOLD_CALLS + call)))
                branch = Branch(params, params.dgamma0)
                radius = SP.fold_radius(branch, 1e-12)
                if call % FOLD_CHECKED == 0 and radius != branch.radius(branch.jump_off_depth, 1e-12):
                    failures.append((params.R, radius))
        except Exception as error:  # (collected: an error in a thread would not fail the test)
            failures.append(repr(error))

    try:
        threads = [threading.Thread(target=calls, args=(thread,)) for thread in range(FOLD_THREADS)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
    finally:
        sys.setswitchinterval(switch)
    assert failures == []
    branch = Branch(PAPER, PAPER.dgamma0)
    first = SP.fold_radius(branch, 1e-12)
    branch.radius = None  # (a second call that iterated again would fail here)
    assert SP.fold_radius(branch, 1e-12) == first
