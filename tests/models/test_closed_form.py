"""The closed form of a moving span without a front (:mod:`mdr_events.models.continuum.closed_form`) against the
quadrature of the same span's right-hand side (:mod:`~mdr_events.models.continuum.span_panels`): the primitive's
derivative is the right-hand side, and whole runs by both routes log the same events and the same force."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import evaluate, integrate, solve_path, tangential_work
from mdr_events.models.continuum.closed_form import ClosedForce
from mdr_events.models.continuum.extrema import solution_extrema
from mdr_events.models.continuum.span import SpanIntegrator

PAPER = me.Parameters.paper()
#: The paper's layer (m), bonded to its base.
LAYER = me.Layer(5e-3)
HERTZ = PAPER.replace(dgamma0=0.0, dgamma1=0.0)
#: Both routes' F_x over its largest value: the quadrature holds each panel to rtol = 1e-10 of the force (measured
#: 1e-16 to 6e-13 between the routes on these cases, the closed form exact to rounding): the solver's rtol.
ROUTE_SHARE = 1e-10
#: The events' times, relative: each root found to 4 eps of its variable (the radius), mapped onto the time through
#: the branch (a slope up to ~1e3 near a contact's end), on functions that differ between the routes by rounding.
EVENT_RTOL = 1e-10
#: ``dP/da`` in closed form against the right-hand side, over the largest rate: the same terms summed in another
#: order (``S₀ + S₁ a`` for ``a − n₊ − n₋``), a few ulp of the largest.
RATE_SHARE = 1e-13
#: The primitive's derivative (a central difference of step h = 1e-4 of the radius) against the right-hand side, over
#: the largest rate: the difference's truncation, ``h² P'''/6``, some 1e-8 of it, and its rounding ``eps P/h``.
DERIVATIVE_SHARE = 1e-6
#: ``tangential_work`` of a closed-form run against the quadrature's run at rtol = 1e-13, relative: the reference is
#: held to 1e-13 of the force, the closed form is exact to rounding, and the work's 8-point Gauss rule between the
#: span's readings (at least EVENT_READINGS of them) integrates a smooth force to rounding; ten times the reference's
#: rtol. (One rule over a whole span, the readings not breakpoints, was 1.6e-11 off on A 20°.)
WORK_RTOL = 1e-12


def _table():
    radii = np.linspace(0.0, 4e-3, 41)
    return me.TabulatedProfile(radii, radii**2 / (2 * PAPER.R))


#: label -> (params, path, solve_path's keywords): growing spans that stick and shrinking ones in full slip (A, B),
#: a table (its knots), power laws, a contact without adhesion under Coulomb's law (κ > 0), fretting
CASES = {
    "A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {}),
    "B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {}),
    "table, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=_table()), {"profile": _table()}),
    "cone, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER, profile=PowerLaw.cone(0.05)),
                            {"profile": PowerLaw.cone(0.05)}),
    "n = 3, A 30°": lambda: (PAPER, me.Path.scenario_A(30.0, PAPER, profile=PowerLaw(2e5, 3.0)),
                             {"profile": PowerLaw(2e5, 3.0)}),
    "Hertz, Coulomb, A 20°": lambda: (HERTZ, me.Path.scenario_A(20.0, HERTZ),
                                      {"friction": FrictionLaw("coulomb", mu=0.3)}),
    "zigzag": lambda: (PAPER, me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4),
                                       (2e-4, -1e-4)], PAPER.v), {}),
    # on the paper's 5 mm layer bonded to its base (:mod:`~mdr_events.models.continuum.layer_closed_form`)
    "layer, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {"layer": LAYER}),
    "layer, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {"layer": LAYER}),
    "layer, B 70°": lambda: (PAPER, me.Path.scenario_B(70.0, PAPER), {"layer": LAYER}),
    "thin layer, zigzag": lambda: (PAPER, me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4),
                                                   (-1e-4, 3e-4), (2e-4, -1e-4)], PAPER.v), {"layer": me.Layer(1e-3)}),
}


def _run(case, monkeypatch, closed_form, readings=None):
    """The case's run with or without closed forms; ``readings`` (a list) gets, for each closed-form span as it ends
    (before the transition changes the anchors it read), ``(rhs, rate, difference, force, one by one)`` at seven
    points inside it: the right-hand side, ``2G* dP/da`` scaled to the variable, the central difference of the force
    and the force read at once and point by point."""
    params, path, options = CASES[case]()
    with monkeypatch.context() as patch:
        patch.setattr(SpanIntegrator, "closed_form", closed_form)
        if readings is not None:
            original = integrate._integrate

            def spy(model, span, integrator, force):
                outcome = original(model, span, integrator, force)
                if isinstance(span.interpolant, ClosedForce):
                    readings.append(_read(integrator, span.interpolant))
                return outcome

            patch.setattr(integrate, "_integrate", spy)
        return solve_path(params, path, **options)


def _read(integrator, interpolant):
    """What :func:`_run` records of a closed-form span."""
    primitive = integrator.primitive()
    low, high = sorted((interpolant.ts[0], interpolant.ts[-1]))
    var = np.linspace(low, high, 9)[1:-1]
    rhs = np.array([integrator.rhs(v, None)[0] for v in var])
    rate = np.array([integrator.G2 * integrator.scale * primitive.rate(v * integrator.scale) for v in var])
    h = 1e-4 * (high - low)
    difference = (interpolant(var + h)[0] - interpolant(var - h)[0]) / (2 * h)
    fine = np.linspace(low, high, 2001)
    rates = np.array([primitive.rate(v * integrator.scale) for v in fine])
    changes = int(np.count_nonzero(np.sign(rates[1:]) * np.sign(rates[:-1]) < 0))
    stationary = interpolant.stationary(low, high)
    residual = [abs(primitive.rate(v * integrator.scale)) for v in stationary]
    return (rhs, rate, difference, interpolant(var)[0], np.array([interpolant(v)[0] for v in var]),
            (changes, len(stationary), residual, float(np.max(np.abs(rates[np.isfinite(rates)])))))


@pytest.mark.parametrize("case", list(CASES))
def test_the_closed_form_and_the_quadrature_give_the_same_run(case, monkeypatch):
    closed, quadrature = _run(case, monkeypatch, True), _run(case, monkeypatch, False)
    assert [event.kind for event in closed.events] == [event.kind for event in quadrature.events]
    np.testing.assert_allclose([event.time for event in closed.events], [event.time for event in quadrature.events],
                               rtol=EVENT_RTOL, atol=0)
    times = np.linspace(0.0, min(closed.end_time, quadrature.end_time), 2001)
    force, reference = (evaluate(run, times)["tangential_force"] for run in (closed, quadrature))
    np.testing.assert_allclose(force, reference, rtol=0, atol=ROUTE_SHARE * np.max(np.abs(reference)))
    extremes = [solution_extrema(run) for run in (closed, quadrature)]  # (read off the closed form's stationary points)
    for name in ("tangential_force_max", "tangential_force_min"):
        assert extremes[0][name] == pytest.approx(extremes[1][name], abs=ROUTE_SHARE * np.max(np.abs(reference)))


@pytest.mark.parametrize("case", list(CASES))
def test_the_primitives_derivative_is_the_right_hand_side(case, monkeypatch):
    """Every closed-form span of the run (at least one a case): ``2G* dP/da`` and the central difference of the force
    are the integrator's right-hand side inside the span, the force read at once is the force read point by point,
    bit for bit, and ``ClosedForce.stationary`` finds every change of sign of its rate (on a scan of 2001 points) at a
    root of it."""
    readings = []
    _run(case, monkeypatch, True, readings)
    assert readings
    for rhs, rate, difference, together, alone, (changes, found, residual, largest) in readings:
        assert found == changes  # (each change of sign of the rate on a fine scan is a stationary point found)
        assert all(value <= RATE_SHARE * largest for value in residual)
        scale = max(np.max(np.abs(rhs)), 1e-300)
        np.testing.assert_allclose(rate, rhs, rtol=0, atol=RATE_SHARE * scale)
        np.testing.assert_allclose(difference, rhs, rtol=0, atol=DERIVATIVE_SHARE * scale)
        np.testing.assert_array_equal(together, alone)


@pytest.mark.parametrize("case", ["A 20°", "B 30°"])
def test_the_work_over_closed_spans_is_the_tight_quadrature_s(case, monkeypatch):
    """``∫ F_x dx`` over a run whose spans are closed forms: their event readings are the breakpoints the work's
    quadrature rules between (a span's ends alone left one rule over a non-polynomial force)."""
    params, path, options = CASES[case]()
    closed = tangential_work(_run(case, monkeypatch, True))
    with monkeypatch.context() as patch:
        patch.setattr(SpanIntegrator, "closed_form", False)
        tight = tangential_work(solve_path(params, path, tolerances=me.Tolerances(rtol=1e-13, atol=1e-22), **options))
    assert abs(closed - tight) <= WORK_RTOL * abs(tight), (closed, tight)


@pytest.mark.parametrize("coefficient", ["A0", "C"])
def test_a_force_in_closed_form_that_is_not_finite_fails_as_the_quadrature_does(coefficient, monkeypatch):
    """A primitive whose value is not finite (a coefficient NaN: what a branch's closed form that overflows gives)
    ends the run with the quadrature's error (a ``RuntimeError`` naming the span), not with a NaN force passed on."""
    params, path, options = CASES["A 20°"]()
    original = SpanIntegrator.primitive

    def broken(integrator):
        primitive = original(integrator)
        return None if primitive is None else primitive._replace(**{coefficient: float("nan")})

    monkeypatch.setattr(SpanIntegrator, "primitive", broken)
    with pytest.raises(RuntimeError, match="not finite"):
        solve_path(params, path, **options)


def test_each_interpolant_type_gives_its_stationary_points():
    """``interpolant_roots`` by the interpolant's type: a force linear in time has none, a closed form's are its
    ``stationary`` ones (a quadratic force ``P = a²/2 − a/2``: its rate ``a − 1/2`` vanishes at the radius 1/2),
    a DOP853 step's the roots of its polynomial's derivative; anything else is refused by name."""
    from scipy.integrate import solve_ivp

    from mdr_events.models.continuum.closed_form import Primitive
    from mdr_events.models.continuum.span import LinearForce
    from mdr_events.models.continuum.stationary import interpolant_roots

    assert interpolant_roots(LinearForce(0.0, 1.0, 2.0, 3.0), 0.0, 1.0) == []

    class Flat:  # (a branch whose depth and integral vanish: P is the primitive's polynomial part alone)
        knots = ()

        def depth(self, a):
            return 0.0

        integral = slope = depth

    closed = ClosedForce(Primitive(Flat(), Flat(), -0.5, 1.0, 0.0, 0.0, 0.0, 0.0), 0.0, 0.0, 1.0, 1.0, [0.0, 1.0])
    assert interpolant_roots(closed, 0.0, 1.0) == [0.5]
    dense = solve_ivp(lambda t, y: [t - 0.5], (0.0, 1.0), [0.0], method="DOP853", dense_output=True).sol
    np.testing.assert_allclose(interpolant_roots(dense, 0.0, 1.0), [0.5], rtol=0, atol=RATE_SHARE)
    with pytest.raises(TypeError, match="interpolant="):
        interpolant_roots(object(), 0.0, 1.0)


@pytest.mark.parametrize("part", [0, 1, 7, 15])
def test_an_event_that_turns_back_between_two_readings_is_found(part):
    """The edge's target on a shrinking span of the paper's adhesion (Δγ1 > Δγ0), unloaded back along the loading
    line: ``cap·level − cap·Y(a) = c − K a + |β| √a`` (``β = cap r0 (k1 − k0)``, ``d0 = d + (k1 − k0) √a``; the
    ``d`` terms cancel) is concave in the radius. Placed so that it rises through 0 and falls back inside one of the
    16 parts, between two readings (both negative), the closed form must still find its first root: in the first part
    (read with the third reading), the second, the middle and the last."""
    from mdr_events.models.continuum.branch import Branch
    from mdr_events.models.continuum.closed_form import EVENT_READINGS, Primitive, closed_span

    k0, k1 = (np.sqrt(2 * np.pi * work / PAPER.E_star) for work in (PAPER.dgamma0, PAPER.dgamma1))
    beta = np.tan(np.radians(20.0)) * (k1 - k0)
    scale, start, stop = 1e-3, 1.0, 0.5
    step = (start - stop) / EVENT_READINGS
    peak = start - (part + 0.5) * step  # (the middle of the part)
    K = beta / (2 * np.sqrt(peak * scale))  # (the turn √a* = |β|/(2K) there)
    curvature = beta / (4 * (peak * scale) ** 1.5)  # (|d²/da²| at the turn)
    height = 0.25 * curvature / 2 * (0.5 * step * scale) ** 2  # (positive over a quarter of the part)
    c = K * peak * scale - beta * np.sqrt(peak * scale) + height

    def event(var, y=None):
        a = var * scale
        return c - K * a + beta * np.sqrt(a)
    event.direction = 1.0
    readings = np.linspace(start, stop, EVENT_READINGS + 1)
    assert max(event(var) for var in readings) < 0.0 < event(peak)  # (hidden between two readings)
    s = (beta + np.sqrt(beta**2 + 4 * K * c)) / (2 * K)  # (the larger root of K s² − |β| s − c: the first met)
    branch = Branch(PAPER, PAPER.dgamma1)
    marched = closed_span(Primitive(branch, branch, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), start, stop, 0.0, 1.0, scale, [],
                          [event])
    assert marched.status == 1
    assert marched.t_events[0] == [pytest.approx(s * s / scale, rel=EVENT_RTOL)]


#: Equal parts of a run in time over which the reference's work is summed (:func:`tangential_work` rules between a
#: span's breakpoints alone: a span the quadrature took in one panel, full slip as the layer's contact shrinks, has one
#: 8-point rule over a non-polynomial integrand, 4.4e-11 off on "layer, B 30°"; in parts of 1/256 of the run the rule's
#: error, ~(1/256)^16 of the span's, is gone).
WORK_PARTS = 256


@pytest.mark.parametrize("case", ["layer, A 20°", "layer, B 30°"])
def test_the_work_over_closed_spans_on_a_layer_is_the_tight_quadrature_s(case, monkeypatch):
    """As on the half-space (above), the tight quadrature's work summed over :data:`WORK_PARTS` parts of the run."""
    params, path, options = CASES[case]()
    closed = tangential_work(_run(case, monkeypatch, True))
    with monkeypatch.context() as patch:
        patch.setattr(SpanIntegrator, "closed_form", False)
        run = solve_path(params, path, tolerances=me.Tolerances(rtol=1e-13, atol=1e-22), **options)
    edges = np.linspace(0.0, run.end_time, WORK_PARTS + 1)
    tight = sum(tangential_work(run, float(low), float(high)) for low, high in zip(edges[:-1], edges[1:]))
    assert abs(closed - tight) <= WORK_RTOL * abs(tight), (closed, tight)


def _ragged(var, y=None):
    """An event below zero everywhere whose every halving looks curved: ``−1`` at the odd dyadic depths of ``var``
    in ``[0, 1]`` (``1/2``, ``1/8``, ``3/8``, ...), ``−1e-9`` at the even ones (``0``, ``1``, ``1/4``, ...), so that
    the middle of two readings differs from them by their own size and no half is ever cleared nor crosses."""
    numerator = round(var * 2**60)
    depth = 60 - ((numerator & -numerator).bit_length() - 1 if numerator else 60)
    return -1.0 if depth % 2 else -1e-9


_ragged.direction = 1.0


def test_an_event_the_search_cannot_settle_leaves_the_span_to_the_quadrature(monkeypatch):
    """:func:`_turn_between` spends :data:`TURN_READS` on an event it can neither clear nor see cross: it raises
    (it returned ``None``, no crossing, silently), :func:`closed_span` gives ``None`` (no closed form for the span),
    and ``integrate_span`` integrates such a span by the quadrature: a run whose every closed-form span is unsettled
    is the quadrature's run bit for bit."""
    from mdr_events.models.continuum import closed_form
    from mdr_events.models.continuum.branch import Branch
    from mdr_events.models.continuum.closed_form import TURN_READS, Primitive, _turn_between, _Unsettled, closed_span

    reads = []

    def counted(var, y=None):
        reads.append(var)
        return _ragged(var)

    counted.direction = 1.0
    low, high = 0.0, 1.0
    with pytest.raises(_Unsettled):
        _turn_between(counted, 1.0, low, high, _ragged(low), _ragged(high))
    assert len(reads) == TURN_READS
    branch = Branch(PAPER, PAPER.dgamma1)
    primitive = Primitive(branch, branch, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    assert closed_span(primitive, 1.0, 0.5, 0.0, 1.0, 1e-3, [], [_ragged]) is None  # (its readings k/32: no clearing)

    def unsettled(*args):
        raise _Unsettled("every part")

    monkeypatch.setattr(closed_form, "_hidden", unsettled)
    fallen, quadrature = _run("A 20°", monkeypatch, True), _run("A 20°", monkeypatch, False)
    assert [(event.kind, event.time) for event in fallen.events] == [(event.kind, event.time)
                                                                     for event in quadrature.events]
    times = np.linspace(0.0, quadrature.end_time, 201)
    np.testing.assert_array_equal(evaluate(fallen, times)["tangential_force"],
                                  evaluate(quadrature, times)["tangential_force"])


@pytest.mark.parametrize("case", list(CASES))
def test_no_closed_form_span_watches_the_zone_leaving_the_edge(case, monkeypatch):
    """``ZONE_LEAVES_EDGE`` (direction +1, with a concave ``K a(t)`` term: not covered by convexity) is watched only
    where the edge's piece holds a front, and such a span has no closed form: none of the cases' closed-form spans
    watches it, and ``span_primitive`` refuses a span whose edge's piece holds a front."""
    from types import SimpleNamespace

    from mdr_events.models.continuum.closed_form import span_primitive
    from mdr_events.models.continuum.span import Trigger
    from mdr_events.models.continuum.state import Cap

    watched = []
    original = integrate._integrate

    def spy(model, span, integrator, force):
        closed = integrator.primitive() is not None and integrator.grading() is None
        outcome = original(model, span, integrator, force)
        if closed:
            watched.append({event.trigger for event in integrator.event_functions()})
        return outcome

    params, path, options = CASES[case]()
    monkeypatch.setattr(integrate, "_integrate", spy)
    solve_path(params, path, **options)
    assert watched and not any(Trigger.ZONE_LEAVES_EDGE in triggers for triggers in watched)
    zone = SimpleNamespace(edge_front_outward=True)
    with pytest.raises(RuntimeError, match="holds a front"):
        span_primitive(SimpleNamespace(K=1.0, kappa=0.0, segment=None, zones={Cap.POSITIVE: zone, Cap.NEGATIVE: zone}))


#: The shape of an event its readings settle, sampled at SHAPE_SAMPLES points of its span: each sample within this
#: share of the function's range (plus its largest magnitude) of what the proof gives (a chord's side, a monotone
#: step). The functions' rounding is some ulp of the lengths they subtract (x, K a, the offset: mm), far below; a turn
#: the proof missed would show as the curvature times the samples' spacing squared, ~1/SHAPE_SAMPLES² of the range.
SHAPE_SHARE = 1e-9
SHAPE_SAMPLES = 65
#: The paper's adhesion (Δγ1 > Δγ0), in at 20° to d_max and back out along the same line: the shrinking span's edge is
#: its own target there (``c − K a + |β|√a``, which can be concave: the kind of event the guard was added for,
#: ``test_an_event_that_turns_back_between_two_readings_is_found``)
BACK_ALONG_THE_LINE = (PAPER, me.Path([(0.0, 0.0), (PAPER.d_max / np.tan(np.radians(20.0)), PAPER.d_max), (0.0, 0.0)],
                                      PAPER.v), {})
#: The cases on a convex branch of the half-space (the paraboloid, power laws ``n >= 1``, with Coulomb's part): the
#: proof holds on their moving spans, so each settles some ``ZONE_REACHES`` and some ``LEVEL_TURNS`` (the fast path)
PROVEN_CASES = ("A 20°", "B 30°", "cone, B 30°", "n = 3, A 30°", "Hertz, Coulomb, A 20°", "zigzag")


def _settled_shapes(params, path, options, monkeypatch):
    """Each closed-form span's events as ``(trigger, direction, settled, edge is the target, times, values)`` at
    :data:`SHAPE_SAMPLES` points of the span's variable, read before the transition changes the anchors."""
    found = []
    original = integrate._integrate

    def spy(model, span, integrator, force):
        if integrator.primitive() is not None and integrator.grading() is None and not integrator.met_at_start():
            var = np.linspace(integrator.start, integrator.stop, SHAPE_SAMPLES)
            times = np.array([integrator.time_of(v) for v in var])
            for event in integrator.event_functions():
                edge = event.cap is not None and integrator.zones[event.cap].edge_is_target
                found.append((event.trigger, event.direction, event.settled, edge, times,
                              np.array([event(v) for v in var])))
        return original(model, span, integrator, force)

    monkeypatch.setattr(integrate, "_integrate", spy)
    solve_path(params, path, **options)
    return found


def _shape_holds(direction, times, values, monotone):
    """Whether ``values`` at ``times`` are monotone (``monotone``), else convex in time (direction +1) or concave
    (−1), within :data:`SHAPE_SHARE`."""
    tolerance = SHAPE_SHARE * (np.ptp(values) + np.max(np.abs(values)))
    if monotone:
        steps = np.diff(values)
        return bool(np.all(steps >= -tolerance) or np.all(steps <= tolerance))
    left, middle, right = times[:-2], times[1:-1], times[2:]
    chord = values[:-2] + (values[2:] - values[:-2]) * (middle - left) / (right - left)
    return bool(np.all(direction * (chord - values[1:-1]) >= -tolerance))


@pytest.mark.parametrize("case", [*CASES, "back along the line"])
def test_each_settled_event_has_the_shape_its_proof_gives(case, monkeypatch):
    """The events a closed-form span does not read between its readings (``settled``,
    :meth:`~mdr_events.models.continuum.span.SpanIntegrator.levels_convex`) have the shape that rules out a hidden
    crossing, sampled along each span: the level's turn and the edge passing a piece monotone, a level against a fixed
    target convex in time (direction +1). The edge's own target is never settled (the back-and-forth path holds one,
    concave: the guard's case), nor any event on a table's branch or a layer (no proof there); on a convex branch of the
    half-space (:data:`PROVEN_CASES`) some of each kind the proof covers are settled."""
    from mdr_events.models.continuum.span import Trigger

    params, path, options = BACK_ALONG_THE_LINE if case == "back along the line" else CASES[case]()
    found = _settled_shapes(params, path, options, monkeypatch)
    assert found
    monotone = {Trigger.LEVEL_TURNS, Trigger.EDGE_PASSES_PIECE}
    for trigger, direction, settled, edge, times, values in found:
        if settled:
            assert _shape_holds(direction, times, values, trigger in monotone), (trigger, values)
        assert not (settled and edge), trigger
        if "table" in case or "layer" in case:
            assert settled == (trigger is Trigger.EDGE_PASSES_PIECE), trigger
    if case == "back along the line":  # (the guard's kind of event met in a run: the edge's own target, guarded)
        assert any(edge and not settled for _, _, settled, edge, _, _ in found)
    if case in PROVEN_CASES:  # (the fast path kept: a proof that settled nothing would pass the loop above)
        for kind in (Trigger.ZONE_REACHES, Trigger.LEVEL_TURNS):
            assert any(settled for trigger, _, settled, _, _, _ in found if trigger is kind), kind


@pytest.mark.parametrize("declared", [False, True])
def test_a_new_medium_keeps_the_guard_unless_it_declares_a_linear_cap(declared, monkeypatch):
    """:attr:`~mdr_events.models.continuum.media.HalfSpaceMedium.linear_cap` fails closed: a subclass of the
    half-space's medium that does not declare it (a new medium, here the half-space under another name) settles none
    of the events the proof would settle, so all of them stay under the guard; one that declares it settles them as
    the half-space does (A 20°: some ``ZONE_REACHES`` and ``LEVEL_TURNS``). The layers' media are not linear."""
    from mdr_events.models.continuum import model
    from mdr_events.models.continuum.layer_media import FrictionlessLayerMedium, LayerMedium
    from mdr_events.models.continuum.media import HALF_SPACE_MEDIUM, HalfSpaceMedium
    from mdr_events.models.continuum.span import Trigger

    class Undeclared(HalfSpaceMedium):
        pass

    class Declared(HalfSpaceMedium):
        linear_cap = True

    medium = (Declared if declared else Undeclared)()
    assert medium.linear_cap is declared and HALF_SPACE_MEDIUM.linear_cap
    assert not (LayerMedium.linear_cap or FrictionlessLayerMedium.linear_cap)
    monkeypatch.setattr(model, "medium_of", lambda *args: medium)
    found = _settled_shapes(*CASES["A 20°"](), monkeypatch)
    for kind in (Trigger.ZONE_REACHES, Trigger.LEVEL_TURNS):
        assert any(settled for trigger, _, settled, _, _, _ in found if trigger is kind) is declared, kind


@pytest.mark.parametrize("settled", [False, True])
def test_the_guard_reads_between_the_readings_only_the_events_not_settled(settled):
    """The edge's target turning back inside the middle part (as in
    ``test_an_event_that_turns_back_between_two_readings_is_found``), as the span's ``EventFunction``: not settled
    (what :meth:`~mdr_events.models.continuum.span.SpanIntegrator.event_functions` makes of the edge's own target)
    the guard finds its root; marked settled, the closed form reads it at its readings alone and runs to the span's
    end (which is why only a proof may settle an event)."""
    from mdr_events.models.continuum.branch import Branch
    from mdr_events.models.continuum.closed_form import EVENT_READINGS, Primitive, closed_span
    from mdr_events.models.continuum.span import EventFunction, Trigger
    from mdr_events.models.continuum.state import Cap

    k0, k1 = (np.sqrt(2 * np.pi * work / PAPER.E_star) for work in (PAPER.dgamma0, PAPER.dgamma1))
    beta, scale, start, stop = np.tan(np.radians(20.0)) * (k1 - k0), 1e-3, 1.0, 0.5
    peak = start - 7.5 * (start - stop) / EVENT_READINGS  # (the middle of the eighth part)
    K = beta / (2 * np.sqrt(peak * scale))  # (the turn there, positive over a quarter of the part)
    height = 0.25 * beta / (8 * (peak * scale) ** 1.5) * (0.5 * (start - stop) / EVENT_READINGS * scale) ** 2
    c = K * peak * scale - beta * np.sqrt(peak * scale) + height
    event = EventFunction(Trigger.ZONE_REACHES, Cap.POSITIVE, lambda var: c - K * var * scale + beta * np.sqrt(
        var * scale), 1.0, settled)
    s = (beta + np.sqrt(beta**2 + 4 * K * c)) / (2 * K)
    branch = Branch(PAPER, PAPER.dgamma1)
    marched = closed_span(Primitive(branch, branch, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), start, stop, 0.0, 1.0, scale, [],
                          [event])
    if settled:
        assert marched.status == 0 and marched.t_events == [[]]
    else:
        assert marched.status == 1 and marched.t_events[0] == [pytest.approx(s * s / scale, rel=EVENT_RTOL)]
