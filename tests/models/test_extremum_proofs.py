"""The proofs by which :func:`~mdr_events.models.continuum.span_extrema.extremum` skips work against the routes they
skip, which must give the same answer bit for bit: a closed-form force whose rate is linear in the radius
(:attr:`~mdr_events.models.continuum.closed_form.Primitive.linear`) and of one sign at both ends of a bracket has no
stationary point there (:meth:`~mdr_events.models.continuum.closed_form.ClosedForce.stationary` against its readings,
:meth:`~mdr_events.models.continuum.closed_form.ClosedForce.read_stationary`), and a still primitive
(:attr:`~mdr_events.models.continuum.closed_form.Primitive.still`) is ``+0`` without its branch's values, on every
closed-form span of runs of
both scenarios, a zigzag, a reciprocating path, a table, power laws, Coulomb's law, without and with adhesion and on
a layer, and on brackets built to defeat the proof."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum.closed_form import ClosedForce, Primitive

from bench_paths import HERTZ, PAPER, ZIGZAG, paper_table as _table, reciprocating as _reciprocating

#: Brackets read on each closed-form span: the scan's intervals (``EXTREMUM_GRID - 1`` of them, where the refinement
#: reads) and this many random ones.
RANDOM_BRACKETS = 40


#: label -> (params, path, solve_path's keywords)
CASES = {
    "A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {}),
    "B 20°": lambda: (PAPER, me.Path.scenario_B(20.0, PAPER), {}),
    "B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {}),
    "zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {}),
    "reciprocating": lambda: (PAPER, _reciprocating(), {}),
    "table, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=_table()), {"profile": _table()}),
    "cone, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER, profile=PowerLaw.cone(0.05)),
                            {"profile": PowerLaw.cone(0.05)}),
    "Hertz, Coulomb, A 20°": lambda: (HERTZ, me.Path.scenario_A(20.0, HERTZ),
                                      {"friction": FrictionLaw("coulomb", mu=0.3)}),
    "Hertz, B 30°": lambda: (HERTZ, me.Path.scenario_B(30.0, HERTZ), {}),
    "τ0 + Coulomb, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER),
                                    {"friction": FrictionLaw("tau0+coulomb", mu=0.3)}),
    "layer, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {"layer": me.Layer(5e-3)}),
    "layer, B 90°": lambda: (PAPER, me.Path.scenario_B(90.0, PAPER), {"layer": me.Layer(5e-3)}),
}


def _brackets(low: float, high: float, rng: np.random.Generator) -> list[tuple[float, float]]:
    """The scan's intervals of ``[low, high]``, the whole of it and random sub-intervals (some of no length)."""
    from mdr_events.models.continuum.span_extrema import EXTREMUM_GRID

    grid = np.linspace(low, high, EXTREMUM_GRID).tolist()
    random = np.sort(rng.uniform(low, high, (RANDOM_BRACKETS, 2)), axis=1).tolist()
    return [*zip(grid[:-1], grid[1:]), (low, high), (low, low), (high, high), *map(tuple, random)]


@pytest.mark.parametrize("case", list(CASES))
def test_a_linear_rates_proof_gives_the_readings_answer(case):
    """On every closed-form span of the run, ``stationary`` (the proof first) and ``read_stationary`` (the readings)
    give the same roots, bit for bit, on the scan's intervals and random brackets; a run of scenario B holds a linear
    rate, so that the proof is exercised (the last span's full slip ``A₁ a``)."""
    params, path, options = CASES[case]()
    solution = solve_path(params, path, **options)
    closed = [span.interpolant for span in solution.spans if type(span.interpolant) is ClosedForce]
    rng = np.random.default_rng(0)
    for force in closed:
        low, high = sorted((force.ts[0], force.ts[-1]))
        for bracket in _brackets(low, high, rng):
            assert force.stationary(*bracket) == force.read_stationary(*bracket), (case, bracket)
            if force.primitive.still:  # (never_stationary's claim: extremum does not ask)
                assert force.read_stationary(*bracket) == [], (case, bracket)
    if case.startswith("B") and "layer" not in case:
        assert any(force.primitive.linear for force in closed)


class _Convex:
    """A branch ``d(a) = (a − 1)²`` (its slope ``2 (a − 1)``): convex, least at ``a = 1``."""

    knots = ()

    def depth(self, a):
        return (a - 1.0) ** 2

    def slope(self, a):
        return 2.0 * (a - 1.0)

    def integral(self, a):
        return ((a - 1.0) ** 3 + 1.0) / 3.0


def _closed(A0: float, A1: float, C: float = 0.0) -> ClosedForce:
    """A closed form of rate ``A₀ + A₁ a + C d(a)`` on :class:`_Convex`, over the radii 0 to 2."""
    return ClosedForce(Primitive(_Convex(), _Convex(), A0, A1, 0.0, 0.0, C, 0.0), 0.0, 0.0, 1.0, 1.0, [0.0, 2.0])


@pytest.mark.parametrize("hair", [-1, 0, 1])
def test_a_linear_rates_root_a_hair_from_the_brackets_end_is_found_as_the_readings_find_it(hair):
    """Adversarial: the rate ``a − r`` with its root ``r`` one ulp inside the bracket's end, at it, or one ulp
    beyond. Inside, the ends' rates are of opposite signs (the proof does not hold: the readings find the root); at or
    beyond, one end's rate is 0 or both of one sign (no root, by either route)."""
    end = 1.5
    root = end + hair * math.ulp(end)
    force = _closed(-root, 1.0)
    found, read = force.stationary(0.5, end), force.read_stationary(0.5, end)
    assert found == read
    assert (len(found) == 1) is (hair < 0)


def test_a_rate_of_one_sign_at_both_ends_that_dips_between_is_not_skipped():
    """Adversarial: ``C d(a) − A`` on the convex branch, positive at both ends of ``[0, 2]`` and negative about its
    least at ``a = 1`` (the force has a maximum and a minimum inside, each beyond the ends' values): not linear, so the
    readings find both roots ``1 ± 10⁻³``."""
    dip = 1e-6
    force = _closed(-dip, 0.0, 1.0)
    assert not force.primitive.linear
    roots = force.stationary(0.0, 2.0)
    assert roots == force.read_stationary(0.0, 2.0)
    np.testing.assert_allclose(roots, [1.0 - math.sqrt(dip), 1.0 + math.sqrt(dip)], rtol=1e-12)


@pytest.mark.parametrize("coefficient", ["B0", "B1", "C", "C0"])
def test_a_rate_with_a_branch_term_is_not_linear(coefficient):
    """Any coefficient of ``d'``, ``a d'``, ``d`` or ``d₀`` other than 0 makes the rate not linear in the radius."""
    primitive = Primitive(_Convex(), _Convex(), 1.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    assert primitive.linear
    assert not primitive._replace(**{coefficient: 1e-300}).linear


def _skipped_call(force: ClosedForce, var: np.ndarray) -> np.ndarray:
    """``ClosedForce.__call__``'s route that reads the branch (the one a still primitive skips)."""
    return force.force + force.G2 * (force.primitive(np.reshape(var, -1) * force.scale) - force.origin)


def _same_bits(found: np.ndarray, expected: np.ndarray) -> bool:
    return np.reshape(found, -1).tobytes() == np.reshape(expected, -1).tobytes()


@pytest.mark.parametrize("case", list(CASES))
def test_a_still_primitives_force_is_the_branchs_route_bit_for_bit(case):
    """On every closed-form span of the run, the force read at the scan's points and at random ones is the route that
    reads the branch, bit for bit (the sign of a zero too); scenario B's first span (vertical) is still, so that the
    route is exercised."""
    from mdr_events.models.continuum.span_extrema import EXTREMUM_GRID

    params, path, options = CASES[case]()
    closed = [span.interpolant for span in solve_path(params, path, **options).spans
              if type(span.interpolant) is ClosedForce]
    rng = np.random.default_rng(1)
    for force in closed:
        low, high = sorted((force.ts[0], force.ts[-1]))
        for var in (np.linspace(low, high, EXTREMUM_GRID), rng.uniform(low, high, RANDOM_BRACKETS)):
            assert _same_bits(force(var)[0], _skipped_call(force, var)), case
    if case.startswith("B") and "layer" not in case:
        assert any(force.primitive.still for force in closed)


class _Crossing(_Convex):
    """A branch whose depth ``a − 1`` changes sign at ``a = 1`` (a zero coefficient times it is ``+0`` on one side,
    ``−0`` on the other) and whose integral is ``a²``."""

    def depth(self, a):
        return a - 1.0

    def integral(self, a):
        return a * a

    def depths(self, a):
        return np.asarray(a, dtype=float) - 1.0

    def integrals(self, a):
        a = np.asarray(a, dtype=float)
        return a * a


@pytest.mark.parametrize("start_force", [0.0, -0.0, 1.5])
@pytest.mark.parametrize("signs", [(0.0, 0.0), (-0.0, 0.0), (0.0, -0.0), (-0.0, -0.0)])
def test_a_still_primitives_zeros_keep_their_signs(start_force, signs):
    """Adversarial: all coefficients zero, ``A₀`` and ``A₁`` of either sign, on a branch whose depth changes sign
    (``P`` is ``−0`` below ``a = 1`` where ``A₀ = A₁ = −0``, ``+0`` at the start 1.5), a force of ``±0`` or not at the
    start, and radii ``+0``, ``−0``, ``nan``, ``inf`` and negative among positive ones: the force is the branch's route
    bit for bit; ``still`` only where ``A₀`` and ``A₁`` are ``+0``."""
    A0, A1 = signs
    primitive = Primitive(_Crossing(), _Crossing(), A0, A1, 0.0, 0.0, -0.0, 0.0)
    assert primitive.still is (math.copysign(1.0, A0) > 0 and math.copysign(1.0, A1) > 0)
    force = ClosedForce(primitive, 1.5, start_force, 2.0, 1.0, [1.5, 2.0])
    with np.errstate(invalid="ignore"):
        for var in ([0.5, 1.0, 2.0], [0.0, 0.5], [-0.0, 0.5], [0.5, math.nan], [0.5, math.inf], [-1.0, 0.5]):
            var = np.array(var)
            assert _same_bits(force(var)[0], _skipped_call(force, var)), (var, signs, start_force)


def test_a_still_primitive_past_a_tables_end_is_zero_where_its_branch_is_nan():
    """The behaviour chosen past a table's end (``END_SHARE`` beyond its last radius), where the branch's depth and
    integral are ``nan``: the route that reads the branch sums ``0 · nan = nan``, a still primitive's force is the
    start's force (``P = +0``: every coefficient is zero) without reading it; within the table both are the same bit
    for bit. (No run reads there: a depth beyond the table is refused.)"""
    from mdr_events.models.continuum.branch import TabulatedBranch
    from mdr_events.theory.tabulated import END_SHARE

    branch = TabulatedBranch(PAPER, PAPER.dgamma0, _table())
    end = branch.line.shape.x_max  # (the table's last radius)
    start_force = 1.5
    force = ClosedForce(Primitive(branch, branch, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), 1e-3, start_force, 2.0, 1.0,
                        [1e-3, end])
    assert force.primitive.still
    inside = np.array([0.0, 1e-3, end, end * (1.0 + END_SHARE)])
    assert _same_bits(force(inside)[0], _skipped_call(force, inside))
    past = np.array([end * (1.0 + 4.0 * END_SHARE), 5e-3, 1.0])
    with np.errstate(invalid="ignore"):
        assert np.all(np.isnan(_skipped_call(force, past)))
    assert _same_bits(force(past)[0], np.full(past.shape, start_force))


def test_a_still_span_is_never_stationary_and_others_are_asked():
    """``never_stationary`` of ``F_x``: true on scenario B's still first span (its readings find nothing, above),
    false on its shrinking spans (closed forms that are not still) and on scenario A's growing one."""
    from mdr_events.models.continuum.stationary import never_stationary

    for params, path, still in ((PAPER, me.Path.scenario_B(20.0, PAPER), {0}), (PAPER, me.Path.scenario_A(20.0, PAPER),
                                                                            set())):
        solution = solve_path(params, path)
        for index, span in enumerate(solution.spans):
            if type(span.interpolant) is ClosedForce:
                assert never_stationary(solution, index, "tangential_force") is (index in still), index
