"""The tabulated profile: its numerical Abel transform against the power laws' closed forms (second order in the
table's spacing), Heß's relations on it against the paraboloid's, and bad tables named."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.indenters import PowerLaw, TabulatedProfile
from mdr_events.theory import analytic
from mdr_events.theory import power_law as pl
from mdr_events.theory import symbolic as S
from mdr_events.theory import tabulated as tb

REACH = 4e-3  #: the tables' last radius (m)


@pytest.fixture(scope="module")
def paper():
    return me.Parameters.paper()


def _sampled(profile: PowerLaw, points: int) -> TabulatedProfile:
    r = np.linspace(0.0, REACH, points)
    return TabulatedProfile(r, profile.c * r**profile.n)


def test_the_abel_transform_of_a_sampled_cone_is_exact():
    """A linear table is its own PCHIP: the quadrature gives the cone's g = (π/2) c x to round-off."""
    profile = PowerLaw.cone(0.1)
    x = np.linspace(0.0, REACH, 997)
    np.testing.assert_allclose(tb.equivalent_profile(x, _sampled(profile, 41)), pl.equivalent_profile(x, profile),
                               rtol=0, atol=1e-14 * float(pl.equivalent_profile(REACH, profile)))


@pytest.mark.parametrize("n", [1.5, 2.0, 3.0])
def test_the_abel_transform_of_a_sampled_power_law_converges_at_second_order(n):
    """g of tables of c rⁿ with 41, 81, 161 points against κₙ c xⁿ (3): the largest error over [0, r_max] (relative
    to g(r_max)) falls at the order of the PCHIP of f, second order where f is smooth; ``n = 1.5`` has ``f''``
    singular at the tip, where the interpolation error goes as ``h^1.5``: order min(n, 2), less 0.1."""
    profile = pl.with_radius_at(n, 3e-3, 3e-4)
    x = np.linspace(0.0, REACH, 997)
    exact = pl.equivalent_profile(x, profile)
    errors = [np.max(np.abs(tb.equivalent_profile(x, _sampled(profile, points)) - exact)) / exact[-1]
              for points in (41, 81, 161)]
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > min(n, 2.0) - 0.1), errors
    assert errors[-1] < 1e-4, errors


def test_the_angular_form_is_the_abel_transform():
    """The relation the quadrature uses, x ∫ f'(x sin θ) dθ, is (3) with r = x sin θ: for f = r² it gives x² (the
    paraboloid's 2 × x²/2), evaluated by SymPy."""
    import sympy as sp
    rel = S.relation("abel_transform_angular")
    assert rel.equation == "(3)"
    value = rel.rhs.replace(S.f, sp.Lambda(S.r, S.r**2 / 2)).doit()
    assert sp.simplify(value - S.x**2) == 0


def test_hess_relations_on_a_sampled_paraboloid(paper):
    """A table of the paraboloid (321 points): its jump-off, pull-off force, contact radius and scenario-A onset
    against the paper's closed forms to the table's interpolation error (1e-5)."""
    table = _sampled(PowerLaw.paraboloid(paper.R), 321)
    point, reference = tb.jump_off(table, paper, paper.dgamma1), analytic.jump_off(paper, paper.dgamma1)
    assert point["depth"] == pytest.approx(reference["depth"], rel=1e-5)
    # the radius of a minimum is known to the square root of the depths' error (the branch is flat there), and so is
    # the normal force there (it is not stationary at the displacement-controlled jump-off)
    for key in ("contact_radius", "normal_force"):
        assert point[key] == pytest.approx(reference[key], rel=math.sqrt(1e-5)), key
    assert tb.pull_off_force(table, paper, paper.dgamma1) == pytest.approx(
        pl.pull_off_force(PowerLaw.paraboloid(paper.R), paper, paper.dgamma1), rel=1e-5)
    depths = np.linspace(0.0, paper.d_max, 7)
    np.testing.assert_allclose(tb.contact_radius(depths, table, paper, paper.dgamma0),
                               analytic.jkr_contact_radius(depths, paper, paper.dgamma0), rtol=1e-5)
    onset = pl.d_crit_A(20.0, PowerLaw.paraboloid(paper.R), paper, adhesion=True)
    assert tb.d_crit_A(20.0, table, paper, adhesion=True) == pytest.approx(onset, rel=1e-5)
    assert math.isnan(tb.d_crit_A(60.0, table, paper, adhesion=True))  # beyond what the table reaches
    assert math.isinf(tb.d_crit_A(90.0, table, paper))
    assert tb.critical_angle_A(table, paper) == pytest.approx(analytic.critical_angle(paper, "A"), rel=1e-5)


def test_the_branch_is_consistent_with_itself(paper):
    """depth(radius(d)) = d to a few ulp; the slope is the depth's derivative and the integral its antiderivative
    (central differences and quadrature)."""
    from scipy import integrate
    line = tb.branch(_sampled(PowerLaw.cone(0.1), 61), paper, paper.dgamma0)
    for depth in np.linspace(line.jump_off_depth, line.deepest, 9)[1:]:
        assert line.depth(line.radius(depth)) == pytest.approx(depth, abs=1e-14 * abs(line.deepest))
    a, h = 1.234e-3, 1e-8
    assert line.slope(a) == pytest.approx((line.depth(a + h) - line.depth(a - h)) / (2 * h), rel=1e-6)
    assert line.integral(a) == pytest.approx(integrate.quad(line.depth, 0.0, a, limit=200)[0], rel=1e-9)


@pytest.mark.parametrize("make, exception, words", [
    (lambda: TabulatedProfile([0.0, 1e-3], [0.0, 1e-5]), ValueError, ["lengths 2 and 2", "3 to 10000"]),
    # (the quadrature costs the square of the points: 10^6 would take some ten hours)
    (lambda: TabulatedProfile(np.linspace(0.0, 1e-3, 10_001), np.linspace(0.0, 1e-3, 10_001) ** 2), ValueError,
     ["lengths 10001 and 10001", "3 to 10000", "resample"]),
    (lambda: TabulatedProfile([0.0, 1e-3, 2e-3], [0.0, 1e-5]), ValueError, ["lengths 3 and 2"]),
    (lambda: TabulatedProfile([1e-4, 1e-3, 2e-3], [0.0, 1e-5, 2e-5]), ValueError, ["TabulatedProfile.r=", "from 0"]),
    (lambda: TabulatedProfile([0.0, 2e-3, 1e-3], [0.0, 1e-5, 2e-5]), ValueError, ["strictly increasing radii"]),
    (lambda: TabulatedProfile([0.0, 1e-3, 2e-3], [0.0, 2e-5, 1e-5]), ValueError, ["TabulatedProfile.f=",
                                                                                 "strictly increasing"]),
    (lambda: TabulatedProfile([0.0, 1e-3, math.nan], [0.0, 1e-5, 2e-5]), ValueError, ["finite"]),
    (lambda: TabulatedProfile([0.0, 1e-3, 2e-3], ["0", "1", "2"]), TypeError, ["TabulatedProfile.f="]),
])
def test_bad_tables_are_named(make, exception, words):
    with pytest.raises(exception) as caught:
        make()
    for word in words:
        assert word in str(caught.value)


def test_a_table_whose_abel_transform_falls_is_refused():
    """A steep rise that then flattens (a rounded punch's edge seen from inside): g(x) falls past the rise."""
    r = np.linspace(0.0, 2e-3, 81)
    table = TabulatedProfile(r, 1e-4 * (1.0 - np.exp(-r / 2e-4)))
    with pytest.raises(ValueError, match=r"its Abel transform g\(x\) does not increase at x = "):
        tb.equivalent(table)
    with pytest.raises(ValueError, match=r"does not increase"):
        me.simulate(me.Parameters.paper(), "A", alpha=20.0, profile=table)


@pytest.mark.parametrize("work", [0.0, 0.01, 0.15])
@pytest.mark.parametrize("make", [lambda r: r**2 / (2 * 0.03), lambda r: 0.2 * r, lambda r: r**3 / 1e-3],
                         ids=["paraboloid", "cone", "cubic"])
def test_the_radii_of_an_array_are_the_scalar_radius_bit_for_bit(paper, make, work):
    """TabulatedBranch.radii takes the scalar iteration's steps for a whole array (issue 28: the continuum's fill of a
    table called radius() per sample): each radius, in and out of the branch, on the grid, at the fold and next to
    it, is radius()'s bit for bit."""
    r = np.linspace(0.0, 3e-3, 31)
    line = tb.branch(TabulatedProfile(r, make(r)), paper, work)
    reach = line.deepest - line.jump_off_depth
    depths = np.concatenate([np.linspace(line.jump_off_depth, line.deepest, 2001), line._depths,
                             line.jump_off_depth + reach * np.logspace(-16, -1, 100),
                             [line.jump_off_depth - reach, 2 * line.deepest + 1e-3, np.nan, line.deepest]])
    radii = line.radii(depths)
    expected = np.array([line.radius(float(depth)) for depth in depths])
    np.testing.assert_array_equal(radii, expected)
    assert np.isnan(radii[-4:-1]).all() and np.isfinite(radii[:-4]).all()
    assert line.radii(np.float64(depths[7])).shape == () and line.radii(depths[:6].reshape(2, 3)).shape == (2, 3)


#: Newton's steps per inversion at the continuum's ``radius_rtol`` (1e-14) from the Hermite start, averaged over the
#: branch's depths: its error falls as the fourth power of the bracket (~1e-9 of the radius on a 41-point table), so a
#: step brings it to ~1e-18, which Newton's rule on the step (``tabulated.NEWTON_SHARE``) accepts without the step
#: after it that only confirmed it (measured 1.29; where the inverse bends most, two; from the chord's root, error
#: ~1e-4, they took three; with the confirming step, 2.08)
MEAN_INVERSION_STEPS = 1.4


@pytest.mark.parametrize("work", [0.0, 0.01])
def test_a_radius_is_about_one_newton_step_from_its_hermite_start(paper, work, monkeypatch):
    """TabulatedBranch._invert starts from the cubic Hermite interpolant of the inverse a(d) through its bracket's
    ends: at the continuum's rtol its Newton steps (one square root each) average MEAN_INVERSION_STEPS, and each radius
    is a root of d(a) = depth to that rtol."""
    r = np.linspace(0.0, REACH, 41)
    line = tb.branch(TabulatedProfile(r, r**2 / (2 * paper.R)), paper, work)
    depths = np.linspace(line.jump_off_depth, line.deepest, 2003)[1:-1]
    roots = []

    class Counting:  # (the module's math, its square roots counted)
        def __getattr__(self, name):
            return getattr(math, name)

        def sqrt(self, value):
            roots.append(value)
            return math.sqrt(value)

    monkeypatch.setattr(tb, "math", Counting())
    radii = [line.radius(float(depth), 1e-14) for depth in depths]
    monkeypatch.undo()
    first = np.count_nonzero(depths < line._depths[1]) if work else 0  # (the chord's square's root: no step)
    assert (len(roots) - first) / len(depths) <= MEAN_INVERSION_STEPS
    slopes = np.array([line.slope(a) for a in radii])
    residual = np.array([line.depth(a) for a in radii]) - depths
    assert np.all(np.abs(residual) <= 4e-14 * np.array(radii) * slopes + 4 * np.spacing(depths))


#: A radius against the root of its depth by ``brentq`` (``rtol`` = 4 EPS, its least): the inversion's RADIUS_RTOL
#: (4 EPS) and Brent's own, 8 ulp (measured 0.9 ulp; Newton's rule on ``d''`` alone ended them 96 ulp to 2e7 ulp off)
INFLECTION_ULPS = 8


def test_newtons_rule_does_not_end_an_inversion_at_an_inflection(paper):
    """A coarse table (6 points) of ``r² − r³/2 + 0.12 r⁴`` without adhesion: on each bracket whose piece of ``g`` (a
    cubic) has its inflection inside, the depth whose Hermite start lands on the inflection (its error 7e-7 to 2e-3 of
    the radius). There ``d''`` vanishes, so ``|d''| Δ²`` alone passed ``NEWTON_SHARE``'s test after one step that left
    an error of ``|d'''| Δ³ / (3 d')``; ``radius`` and ``radii`` are the root within INFLECTION_ULPS ulp."""
    from scipy import optimize

    r = np.linspace(0.0, 1.0, 6)
    line = tb.TabulatedBranch(TabulatedProfile(r, r**2 - 0.5 * r**3 + 0.12 * r**4), paper, 0.0)

    def hermite(cell, depth):  # (_invert's start, its formula)
        low, high, d_low, d_high, _, _, _, m0, m1 = cell
        share = (depth - d_low) / (d_high - d_low)
        rest = 1.0 - share
        return (((1.0 + 2.0 * share) * rest * rest) * low + (share * rest * rest) * m0
                + (share * share * (3.0 - 2.0 * share)) * high + (share * share * (share - 1.0)) * m1)

    depths, roots = [], []
    for cell in line._cells[1:]:
        low, high, d_low, d_high, start, _, (s0, s1, _), m0, _ = cell
        inflection = start - s1 / (2.0 * s0) if s0 else math.nan
        if m0 == m0 and low < inflection < high:
            depths.append(optimize.brentq(lambda d, cell=cell: hermite(cell, d) - inflection, d_low, d_high,
                                          xtol=1e-300, rtol=4 * np.finfo(float).eps))
            roots.append(optimize.brentq(lambda a: line.depth(a) - depths[-1], low, high, xtol=1e-300,
                                         rtol=4 * np.finfo(float).eps))
    assert len(roots) >= 10  # (the inflections inside their brackets)
    bound = INFLECTION_ULPS * np.finfo(float).eps * np.array(roots)
    assert np.all(np.abs(np.array([line.radius(depth) for depth in depths]) - roots) <= bound)
    assert np.all(np.abs(line.radii(np.array(depths)) - roots) <= bound)




#: The scalar forms (Horner in Python on the piece) against the array forms (SciPy's PPoly) at one radius: the same
#: polynomial summed in another order, a few ulp of the value.
SCALAR_ULPS = 8


@pytest.mark.parametrize("work", [0.0, 0.15])
def test_past_the_table_s_end_scalar_and_array_read_its_end_to_rounding_and_nan_beyond(paper, work):
    """A radius at the table's end or within ``END_SHARE`` past it (the rounding of the continuum's ``var · scale``):
    the scalar ``depth``, ``integral`` and ``slope`` are those at the end, as the array forms (``depths``,
    ``TabulatedBranch.integrals``, ``slopes``) read them; further past (an ulp beyond the share, 1e-9, 1 %, twice
    the end) all of them are ``nan`` (the scalar ones extrapolated the last piece's cubic, then clipped silently)."""
    from mdr_events.models.continuum.branch import make_branch
    r = np.linspace(0.0, 3e-3, 31)
    table = TabulatedProfile(r, r**2 / (2 * paper.R))
    line, branch = tb.branch(table, paper, work), make_branch(paper, work, table)
    end = line.shape.x_max
    last = end * (1 + tb.END_SHARE)  # (the last radius read as the end)
    near = np.array([end, np.nextafter(end, np.inf), last])
    far = np.array([np.nextafter(last, np.inf), end * (1 + 1e-9), 1.01 * end, 2 * end])
    depths, integrals, slopes = line.depths(near), branch.integrals(near), branch.slopes(near)
    for a, depth, integral, slope in zip(near.tolist(), depths, integrals, slopes):
        assert (line.depth(a), line.integral(a), line.slope(a)) == (line.depth(end), line.integral(end),
                                                                     line.slope(end))
        assert line.depth(a) == pytest.approx(depth, rel=SCALAR_ULPS * np.finfo(float).eps, abs=0)
        assert line.integral(a) == pytest.approx(integral, rel=SCALAR_ULPS * np.finfo(float).eps, abs=0)
        assert line.slope(a) == slope
    assert np.isnan(line.depths(far)).all() and np.isnan(branch.integrals(far)).all()
    assert np.isnan(branch.slopes(far)).all()
    assert all(np.isnan([line.depth(a), line.integral(a), line.slope(a)]).all() for a in far.tolist())
