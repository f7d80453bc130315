"""The layer's closed form of a span (:mod:`mdr_events.models.continuum.layer_closed_form`): the cells' series are the
functions the right-hand side reads and their integrals, and the radii Newton's first step gives are the iterated ones.
(Whole runs against the quadrature: ``tests/models/test_closed_form.py``.)"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.integrate import quad

import mdr_events as me
from mdr_events.models.continuum import layer_branch, layer_closed_form
from mdr_events.models.continuum.layer_branch import RADII_RTOL, LayerBranch
from mdr_events.models.continuum.layer_media import LayerMedium

PAPER = me.Parameters.paper()
EPS = np.finfo(float).eps
#: The series against the functions, over each function's largest value on the sample: the interpolant through
#: CELL_NODES = 8 Gauss points of a cell 0.1 wide in ln a, whose functions' nearest singularity (a = 0) lies 20
#: half-widths away, is within ρ^-8 ≈ 1.5e-13 of it (ρ ≈ 40, Bernstein's ellipse); measured 5e-14.
SERIES_SHARE = 1.5e-13
#: The integrals' differences against SciPy's quad at epsrel = QUAD_RTOL, over the largest: quad's own tolerance (its
#: estimate, not a bound: ten times it), the series' error integrated being far below (measured 2e-13 against quad at
#: 1e-13, which warns of its own rounding on the 1 mm layer).
QUAD_RTOL = 1e-12
INTEGRAL_SHARE = 10 * QUAD_RTOL
#: Layers (m): the paper's, a thin one (a/h up to ~3) and one so thick that the contact lies below the tables' least
#: λ (the series' range, cut into cells of its own).
LAYERS = (5e-3, 1e-3, 1e9)


def _branches(h: float):
    medium = LayerMedium(PAPER, me.Paraboloid(PAPER.R), me.Layer(h))
    return medium, [LayerBranch(PAPER, work, me.Paraboloid(PAPER.R), me.Layer(h), medium.normal)
                    for work in (PAPER.dgamma0, PAPER.dgamma1)]


@pytest.mark.parametrize("h", LAYERS)
def test_the_cells_series_are_the_functions_and_their_integrals(h):
    medium, branches = _branches(h)
    for branch in branches:
        series = layer_closed_form.branch_integrals(medium, branch)
        radii = np.sort(np.random.default_rng(7).uniform(series.floor, 12 * series.floor, 60))
        M, u, d, J_u, J_d = series.values(radii)
        exact = np.array([[medium.measure(0.0, a), medium.shift(1.0, a), branch.depth(a)] for a in radii]).T
        for values, functions in zip((M, u, d), exact):
            assert np.max(np.abs(values - functions)) <= SERIES_SHARE * np.max(np.abs(functions))
        ends = radii[::10]
        for integrals, integrand in ((J_u[::10], lambda a: medium.density(a) * medium.shift(1.0, a)),
                                     (J_d[::10], lambda a: medium.density(a) * branch.depth(a))):
            # (split at the splines' breaks, where the integrands' fifth derivative jumps)
            reference = np.array([quad(integrand, ends[0], end, epsabs=0.0, epsrel=QUAD_RTOL, limit=200,
                                       points=[b for b in series.ends if ends[0] < b < end] or None)[0]
                                  for end in ends])
            difference = integrals - integrals[0]
            assert np.max(np.abs(difference - reference)) <= INTEGRAL_SHARE * np.max(np.abs(reference))


def test_one_radius_and_many_read_the_series_alike():
    medium, (branch, _) = _branches(5e-3)
    series = layer_closed_form.branch_integrals(medium, branch)
    radii = np.linspace(series.floor, 20 * series.floor, 101)
    np.testing.assert_array_equal(np.array([series.value(float(a)) for a in radii]).T, series.values(radii))


def _clenshaw_allocating(coefficients: np.ndarray, t: np.ndarray) -> np.ndarray:
    """``layer_closed_form._clenshaw`` as ``BranchIntegrals.values`` read it before, a new array per operation."""
    b1 = b2 = 0.0
    for k in range(layer_closed_form.CELL_NODES, 0, -1):
        b1, b2 = coefficients[k] + layer_closed_form._ALPHA[k] * t * b1 - layer_closed_form._BETA[k] * b2, b1
    return coefficients[0] + t * b1 - 0.5 * b2


@pytest.mark.parametrize("h", LAYERS)
def test_a_few_radii_and_the_buffered_recurrence_read_the_series_alike(h):
    """``values`` of a few rows at up to ``SCALAR_RADII`` radii (read one by one as ``value``) and its recurrence into
    kept buffers (``_clenshaw``) give the numbers of the route before (``_clenshaw_allocating``, an array per
    operation) bit for bit, signs of zero included, on every row set a primitive asks."""
    medium, branches = _branches(h)
    for branch in branches:
        series = layer_closed_form.branch_integrals(medium, branch)
        radii = np.sort(np.random.default_rng(11).uniform(series.floor, min(series.ceiling, 40 * series.floor), 257))
        cell = np.clip(np.searchsorted(series._ends, radii, side="right") - 1, 0, len(series.ends) - 2)
        t = 2.0 * (radii - series._ends[cell]) / series.width[cell] - 1.0
        for rows in ((0, 2, 4), (0, 1, 3), (1,), (0, 1, 2, 3, 4)):
            before = _clenshaw_allocating(series._by_degree[:, list(rows)][:, :, cell], t)
            many = series.values(radii, rows)
            assert np.array_equal(many, before) and np.array_equal(np.signbit(many), np.signbit(before))
            for start in range(0, 40, layer_closed_form.SCALAR_RADII):
                few = series.values(radii[start:start + layer_closed_form.SCALAR_RADII], rows)
                assert np.array_equal(few, before[:, start:start + layer_closed_form.SCALAR_RADII])
                assert np.array_equal(np.signbit(few), np.signbit(before[:, start:start + 4]))


def test_a_few_radii_and_the_arrays_route_give_one_shape(monkeypatch):
    """``values`` of a few rows read one radius at a time (up to ``SCALAR_RADII``) and the arrays' route (the shortcut
    off) give the same shape and numbers, bit for bit: ``(rows,)`` for a 0-d radius, ``(rows, n)`` for n radii."""
    medium, (branch, _) = _branches(5e-3)
    series = layer_closed_form.branch_integrals(medium, branch)
    radii = np.linspace(2 * series.floor, 3 * series.floor, layer_closed_form.SCALAR_RADII + 1)
    for a in (np.array(radii[0]), np.float64(radii[1]), radii[:1], radii[:2], radii[:-1], radii):
        for rows in ((0, 2, 4), (1,)):
            few = series.values(a, rows)
            with monkeypatch.context() as patch:
                patch.setattr(layer_closed_form, "SCALAR_RADII", -1)
                arrays = series.values(a, rows)
            assert few.shape == arrays.shape == (len(rows),) + np.shape(a)
            assert np.array_equal(few, arrays)


@pytest.mark.parametrize("h", LAYERS[:2])
def test_the_radii_of_newtons_first_step_are_the_iterated_ones(h, monkeypatch):
    """Newton's step taken as the root where its own bound allows (``NEWTON_SHARE``), for many depths and for one,
    against the iteration to a step within ``RADII_RTOL``: within the tolerance, or the root's conditioning at the fold (``∂d/∂a → 0``: a depth
    rounded by a few ulp moves the root by that over the slope)."""
    _, branches = _branches(h)
    for branch in branches:
        radii = np.geomspace(branch.jump_off_radius * (1 + 1e-6), 0.3 * branch.ceiling, 2000)
        depths = branch.depths(radii)
        first = branch.radii(depths)
        alone = np.array([branch.radius(float(depth), RADII_RTOL) for depth in depths[::20]])
        with monkeypatch.context() as patch:
            patch.setattr(layer_branch, "NEWTON_SHARE", 0.0)
            iterated = branch.radii(depths)
            iterated_alone = np.array([branch.radius(float(depth), RADII_RTOL) for depth in depths[::20]])
        slopes = branch._arrays(iterated)[1]
        conditioning = 8 * EPS * np.abs(depths) / slopes
        assert np.all(np.abs(first - iterated) <= RADII_RTOL * iterated + conditioning)
        assert np.all(np.abs(alone - iterated_alone) <= RADII_RTOL * iterated_alone + conditioning[::20])
        few = branch.radii(depths[:3])  # (a few depths: the scalar iteration's, layer_branch.SCALAR_RADII)
        assert np.all(np.abs(few - iterated[:3]) <= RADII_RTOL * iterated[:3] + conditioning[:3])


@pytest.mark.parametrize("contact, motion", [
    (me.Contact.paper().replace(h=5e-3), me.Scenario("B", alpha=[30.0])),
    (me.Contact.paper().replace(h=5e-3), me.Scenario("A", alpha=[20.0])),
    (dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(2e-3)).replace(h=2e-4),
     me.Scenario("B", alpha=[20.0], d_max=1e-5))])
def test_a_primitive_read_off_its_needed_rows_is_every_rows_bit_for_bit(contact, motion):
    """``LayerPrimitive.__call__`` reads the series of the functions whose terms have a coefficient other than zero
    (``LayerPrimitive.rows``) and puts ``0`` for the others: on every closed span of a run (the paper's paraboloid
    on its 5 mm layer, a punch receding on a thin one) ``P`` is the value of every row (``all_rows``, the route before)
    bit for bit, signs of zero included, at 2001 radii across the span's cells (and ``at``, one radius in floats, at
    every fortieth); and some span reads fewer rows."""
    from mdr_events.limits import check_limits
    from mdr_events.models.continuum.solve import run_continuum
    from mdr_events.models.simulate import simulation_job

    model, _ = simulation_job(contact, motion, None, "continuum", {}, check_limits(None))
    cases = model.motion.cases(model.params, model.profile, model.friction)
    solution = run_continuum(model.kernel, cases.paths, 11)["solutions"][0]
    primitives = [span.interpolant.primitive for span in solution.spans if isinstance(
        getattr(span.interpolant, "primitive", None), layer_closed_form.LayerPrimitive) and not
        span.interpolant.primitive.still]
    assert primitives and any(len(primitive.rows) < len(layer_closed_form.BranchIntegrals.NAMES)
                              for primitive in primitives)
    for primitive in primitives:
        high = min(primitive.own.ceiling, getattr(primitive.branch, "face", primitive.own.ceiling))
        radii = np.linspace(primitive.own.floor, high, 2001)
        mine, theirs = primitive(radii), primitive.all_rows(radii)
        assert np.array_equal(mine, theirs) and np.array_equal(np.signbit(mine), np.signbit(theirs))
        for radius in radii[::40].tolist():  # (one radius in floats: every function's value before)
            every = primitive.combine(*primitive.own.value(radius),
                                       primitive.anchors.value(radius)[4] if primitive.C0 else 0.0)
            assert primitive.at(radius) == every and math.copysign(1.0, primitive.at(radius)) == math.copysign(1.0,
                                                                                                             every)


def _moving_integrators(monkeypatch) -> list:
    """The integrators of the moving spans of the thin punch's run (B at 20°, the recession), after the run."""
    from mdr_events.limits import check_limits
    from mdr_events.models.continuum import span as span_module
    from mdr_events.models.continuum.solve import run_continuum
    from mdr_events.models.simulate import simulation_job

    contact = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(2e-3)).replace(h=2e-4)
    model, _ = simulation_job(contact, me.Scenario("B", alpha=[20.0], d_max=1e-5), None, "continuum", {},
                              check_limits(None))
    cases = model.motion.cases(model.params, model.profile, model.friction)
    integrators = []
    met_at_start = span_module.SpanIntegrator.met_at_start
    monkeypatch.setattr(span_module.SpanIntegrator, "met_at_start",
                        lambda self: integrators.append(self) or met_at_start(self))
    run_continuum(model.kernel, cases.paths, 11)
    moving = [integrator for integrator in integrators if integrator.moving]
    assert moving
    return moving


def test_the_levels_and_rates_kept_per_variable_are_those_read_afresh(monkeypatch):
    """``SpanIntegrator.level`` keeps its last variable's ``x`` and centre shift, ``rate`` its variables' slopes
    (``_rate_parts``): on every moving span of the thin punch's run (B at 20°, the recession) both caps read in turn
    at 33 variables, then the ends again, give the numbers of a reading with nothing kept, bit for bit."""
    for integrator in _moving_integrators(monkeypatch):
        variables = np.linspace(integrator.start, integrator.stop, 33).tolist()
        for var in variables + [integrator.start, integrator.stop, integrator.start]:
            for cap in (1.0, -1.0, 1.0):
                kept = integrator.level(cap, var), integrator.rate(cap, var)
                integrator._last_level, integrator._rates = (None, math.nan, math.nan), None
                fresh = integrator.level(cap, var), integrator.rate(cap, var)
                assert kept == fresh and [math.copysign(1.0, v) for v in kept] == \
                    [math.copysign(1.0, v) for v in fresh]


def test_the_levels_and_rates_kept_tell_the_zeros_apart_and_are_bounded(monkeypatch):
    """The memos of ``SpanIntegrator.level`` and ``_rate_parts`` key a variable by its sign too (``-0.0`` then ``0.0``
    are two readings, as ``memo.exact_key`` keeps them apart), and the rates kept are the last ``RATES_KEPT``
    variables' alone: after 50 variables read, the last is read from the memo, the first afresh."""
    from mdr_events.models.continuum.span import RATES_KEPT, variable_key

    integrator = _moving_integrators(monkeypatch)[0]
    times, slopes = [], []
    time_of, branch = integrator.time_of, integrator.branch
    integrator.time_of = lambda var: times.append(math.copysign(1.0, var)) or time_of(var)
    integrator.branch = type("Counted", (), {"slope": lambda self, a: slopes.append(math.copysign(1.0, a)) or
                                             branch.slope(a), "__getattr__": lambda self, name: getattr(branch, name)})()
    for var in (-0.0, -0.0, 0.0, 0.0):
        for cap in (1.0, -1.0):
            integrator.level(cap, var), integrator._rate_parts(var)
    assert times == slopes == [-1.0, 1.0]
    variables = np.linspace(integrator.start, integrator.stop, 50).tolist()
    for var in variables:
        integrator._rate_parts(var)
    assert len(integrator._rates) == RATES_KEPT
    slopes.clear()
    integrator._rate_parts(variables[-1])
    assert slopes == []
    integrator._rate_parts(variables[0])
    assert slopes == [1.0]
    assert variable_key(-0.0) != variable_key(0.0) and variable_key(np.float64(0.5)) is None
