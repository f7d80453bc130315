"""``span_front_knots``: every front's knot crossing of a span found at once (the levels as arrays, the roots by
Illinois' regula falsi), against the scalar level and closed-form roots."""

from __future__ import annotations

import bisect
import math

import numpy as np
import pytest
from scipy.optimize import brentq

import mdr_events as me
from mdr_events.contact.indenters import TabulatedProfile
from mdr_events.models.continuum import integrate, solve_path, span_front_knots
from mdr_events.models.continuum.span import Cap
from mdr_events.models.continuum.tolerances import EPS
from mdr_events.models.paths import Path

#: A root against its closed form, in ulp of the root: the iteration stops where a step moves it by at most
#: ROOT_ULPS ulp; regula falsi's last step on a smooth function leaves an error of the order of the step times the
#: (superlinear) contraction, below the step itself, and the closed form rounds to within an ulp of its own
ROOT_ERROR_ULPS = span_front_knots.ROOT_ULPS + 1.0


def test_bracketed_roots_are_the_closed_forms_to_their_ulps():
    """Cube roots ``x³ = c`` (bracket [0.1, 3]: a curved function, the chord far from the root), a root at a bracket's
    end (its value 0 there: returned as it is) and a line (the chord's root, at once): each within ROOT_ERROR_ULPS ulp
    of its closed form, every element of the array iterated on its own (the others' convergence does not stop it)."""
    targets = np.geomspace(0.002, 26.0, 40)
    low, high = np.full(targets.size, 0.1), np.full(targets.size, 3.0)
    roots = span_front_knots.bracketed_roots(lambda x, which: x**3 - targets[which], low, high,
                                             low**3 - targets, high**3 - targets)
    assert np.all(np.abs(roots - np.cbrt(targets)) <= ROOT_ERROR_ULPS * EPS * np.cbrt(targets))
    line = span_front_knots.bracketed_roots(lambda x, which: 2.0 * x - 1.0, np.array([0.0]), np.array([4.0]),
                                            np.array([-1.0]), np.array([7.0]))
    assert line[0] == 0.5
    at_end = span_front_knots.bracketed_roots(lambda x, which: x - 1.0, np.array([0.0]), np.array([1.0]),
                                              np.array([-1.0]), np.array([0.0]))
    assert at_end[0] == 1.0


@pytest.fixture(scope="module")
def fronted_spans():
    """The spans with a front of scenario A at 20° on a 41-point table of the paraboloid."""
    params = me.Parameters.paper()
    r = np.linspace(0.0, 4e-3, 41)
    table = TabulatedProfile(r, r**2 / (2 * params.R))
    spans = []
    original = integrate._integrate

    def spy(model, span, integrator, force):
        spans.append(integrator)
        return original(model, span, integrator, force)

    integrate._integrate = spy
    try:
        solve_path(params, Path.scenario_A(20.0, params, profile=table), profile=table)
    finally:
        integrate._integrate = original
    return [integrator for integrator in spans if integrator.has_fronts()]


def test_the_levels_as_arrays_are_the_scalar_levels(fronted_spans):
    """``levels`` at 50 variables across each span, both caps: the scalar ``SpanIntegrator.level``'s to 8 ulp of the
    largest level's parts (x and the centre shift; the branch's depth read by the table's PPoly, not the scalar
    Horner steps: a few ulp of the depth, times the speed ratio of the segment)."""
    for integrator in fronted_spans:
        var = np.linspace(integrator.start, integrator.stop, 50)
        for cap in (1.0, -1.0):
            scalar = np.array([integrator.level(cap, float(v)) for v in var])
            scale = np.max(np.abs(integrator.segment.x(np.array([integrator.time_of(float(v)) for v in var]))))
            assert np.max(np.abs(span_front_knots.levels(integrator, cap, var) - scalar)) <= 8 * EPS * scale


def test_each_knot_found_is_where_the_level_reaches_the_knots_value(fronted_spans):
    """At each knot found the scalar level minus the front piece's value at the knot changes sign within ROOT_ULPS + 1
    ulp of the variable (the root is the level's to its ulps, not only the front's ``ξ`` to 1e-9 of the knot)."""
    checked = 0
    for integrator in fronted_spans:
        ((cap, piece),) = [(cap, p) for cap in integrator.zones for p, _, _ in integrator.zones[cap].fronts]
        seen = integrator.zones[cap].anchors
        knots = np.array(integrator.anchors.attach.knots)
        for var in integrator.front_knots():
            xi = seen.inverse(piece, integrator.level(cap, var))
            value = seen.piece_value(piece, float(knots[np.argmin(np.abs(knots - xi))]))
            step = (span_front_knots.ROOT_ULPS + 1.0) * EPS * abs(var)
            below, above = (integrator.level(cap, var + sign * step) - value for sign in (-1.0, 1.0))
            assert below * above <= 0.0 or math.isclose(below, 0.0, abs_tol=0.0)
            checked += 1
    assert checked == 95  # (A at 20°: every knot crossed)


#: The new route's knot against the scalar route's, in ulp of the knot: each is the level's root to its own stopping
#: rule, regula falsi's within ROOT_ERROR_ULPS (above), Brent's (``xtol = EPS`` of the bracket's larger end, ``rtol``
#: = 4 EPS, the ``brentq`` call the route made before) within 4 + 1 ulp of a variable of the order of the bracket's
#: ends (the radius over its scale, or a time inside a span not starting at 0)
KNOT_ULPS = ROOT_ERROR_ULPS + 5.0


def _scalar_front_knots(integrator) -> list[float]:
    """``SpanIntegrator.front_knots`` as it was before ``span_front_knots``: the front's ``ξ`` by the scalar inverse at
    each reading, the knots between two ``ξ`` by bisection, each kept where the level minus the piece's value there
    changes sign, and its root by Brent's method."""
    knots = integrator.anchors.attach.knots
    readings = sorted({integrator.start, integrator.stop, *integrator._radius_knots()})
    found = []
    for cap, p in [(cap, p) for cap in Cap for p, _, _ in integrator.zones[cap].fronts if not p.constant]:
        seen = integrator.zones[cap].anchors
        level = [integrator.level(cap, var) for var in readings]
        xis = [seen.inverse(p, value) for value in level]
        for k in range(len(readings) - 1):
            low, high = sorted(xis[k:k + 2])
            for knot in knots[bisect.bisect_right(knots, low):bisect.bisect_left(knots, high)]:
                value = seen.piece_value(p, knot)
                if (level[k] - value) * (level[k + 1] - value) < 0.0:
                    found.append(brentq(lambda var, cap=cap, value=value: integrator.level(cap, var) - value,
                                        readings[k], readings[k + 1], rtol=4 * EPS,
                                        xtol=EPS * max(abs(readings[k]), abs(readings[k + 1]))))
    return sorted(found)


def test_the_knots_found_at_once_are_the_scalar_routes(fronted_spans):
    """Every span's knots (A at 20° on a 41-point table: 95) are the scalar route's (``_scalar_front_knots``: the
    inverse at each reading and bisection select the knots, Brent's method refines them): the same count, each within
    KNOT_ULPS ulp of its own (a knot the sorted search misses, or a root off by a few ulp more, fails)."""
    total = 0
    for integrator in fronted_spans:
        found, scalar = np.array(integrator.front_knots()), np.array(_scalar_front_knots(integrator))
        assert found.shape == scalar.shape
        assert np.all(np.abs(found - scalar) <= KNOT_ULPS * EPS * np.abs(scalar))
        total += found.size
    assert total == 95  # (every knot compared: the selection's count is the route's, not a lower bound)
