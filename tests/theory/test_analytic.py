"""Closed forms against brentq on the unreduced system, limits and the paper's numbers."""

import math

import numpy as np
import pytest
from scipy import optimize

import mdr_events as me
from mdr_events.theory import analytic, roots

ANGLES = np.linspace(0.5, 85.0, 60)


# --- an independent, hand-typed statement of the model, used only as a check -----
def jkr_depth(a, p, dgamma):
    return a**2 / p.R - math.sqrt(2 * math.pi * a * dgamma / p.E_star)


def u_bar(a, p):
    return math.pi * a * p.tau0 / (2 * p.G_star)


def brentq_d_crit_A(alpha, p):
    tan = math.tan(math.radians(alpha))
    f = lambda a: jkr_depth(a, p, p.dgamma0) - tan * u_bar(a, p)  # noqa: E731
    lo = (2 * math.pi * p.dgamma0 * p.R**2 / p.E_star) ** (1 / 3) * 0.999  # below: f < 0
    hi = 1.0
    a = optimize.brentq(f, lo * 1e-3, hi, xtol=1e-16, rtol=1e-15)
    return tan * u_bar(a, p)


def brentq_d_crit_B(alpha, p, branch):
    tan = math.tan(math.radians(alpha))
    sign, dgamma = (-1, p.dgamma1) if branch == "pull-off" else (1, p.dgamma0)
    f = lambda a: jkr_depth(a, p, dgamma) - (p.d_max + sign * tan * u_bar(a, p))  # noqa: E731
    a_jo = (math.pi * dgamma * p.R**2 / (8 * p.E_star)) ** (1 / 3)
    if f(a_jo) > 0:  # the line meets only the unstable branch: jump-off first
        return -math.inf
    a = optimize.brentq(f, a_jo, 1.0, xtol=1e-16, rtol=1e-15)
    return p.d_max + sign * tan * u_bar(a, p)


# ------------------------------------------------------------------------------------
def test_scenario_A_hertz_is_eq_17(paper):
    tan = np.tan(np.radians(ANGLES))
    expected = math.pi**2 * paper.tau0**2 * paper.R * tan**2 / (4 * paper.G_star**2)
    np.testing.assert_allclose(me.d_crit(ANGLES, paper, "A"), expected, rtol=1e-13)


@pytest.mark.parametrize("params", ["paper", "paper_r100"])
def test_scenario_A_adhesive_against_brentq(params, request):
    p = request.getfixturevalue(params)
    ours = me.d_crit(ANGLES, p, "A", adhesion=True)
    expected = [brentq_d_crit_A(a, p) for a in ANGLES]
    np.testing.assert_allclose(ours, expected, rtol=1e-11)


@pytest.mark.parametrize("branch", ["pull-off", "indentation"])
@pytest.mark.parametrize("params", ["paper", "paper_r100"])
def test_scenario_B_adhesive_against_brentq(branch, params, request):
    p = request.getfixturevalue(params)
    ours = me.d_crit(ANGLES, p, "B", adhesion=True, branch=branch)
    expected = np.array([brentq_d_crit_B(a, p, branch) for a in ANGLES])
    assert np.array_equal(np.isinf(ours), np.isinf(expected))
    finite = np.isfinite(expected)
    np.testing.assert_allclose(ours[finite], expected[finite], rtol=1e-10, atol=1e-18)
    if branch == "pull-off":
        assert np.any(ours[finite] < 0), "the adhesive pull-off curve goes below d = 0 (paper, Fig. 9b)"


@pytest.mark.parametrize("branch, sign", [("pull-off", 1), ("indentation", -1)])
def test_scenario_B_hertz_against_brentq_on_the_unsquared_equation(paper, branch, sign):
    for alpha in ANGLES:
        tan = math.tan(math.radians(alpha))
        f = lambda d: sign * (paper.d_max - d) / tan - u_bar(math.sqrt(paper.R * d), paper)  # noqa: E731
        bracket = (1e-30, paper.d_max) if branch == "pull-off" else (paper.d_max, 1e3)
        expected = optimize.brentq(f, *bracket, xtol=1e-20, rtol=1e-14)
        assert me.d_crit(alpha, paper, "B", branch=branch) == pytest.approx(expected, rel=1e-9)


def test_product_of_the_roots_of_20_is_d_max_squared(paper):
    lower = me.d_crit(ANGLES, paper, "B", branch="pull-off")
    upper = me.d_crit(ANGLES, paper, "B", branch="indentation")
    np.testing.assert_allclose(lower * upper, paper.d_max**2, rtol=1e-11)


def test_zero_adhesion_gives_the_non_adhesive_curves(paper):
    p0 = paper.replace(dgamma0=0.0, dgamma1=0.0)
    np.testing.assert_allclose(me.d_crit(ANGLES, p0, "A", adhesion=True), me.d_crit(ANGLES, p0, "A"), rtol=1e-12)
    for branch in analytic.BRANCHES:
        np.testing.assert_allclose(me.d_crit(ANGLES, p0, "B", adhesion=True, branch=branch),
                                   me.d_crit(ANGLES, p0, "B", branch=branch), rtol=1e-11)
    # and small adhesion converges to them
    gaps = [np.max(np.abs(me.d_crit(ANGLES, paper.replace(dgamma0=g), "A", adhesion=True)
                          - me.d_crit(ANGLES, paper, "A"))) for g in (1e-4, 1e-6, 1e-8)]
    assert gaps[0] > gaps[1] > gaps[2]


def test_limits_at_90_and_0_degrees(paper):
    for adhesion in (False, True):
        assert me.d_crit(90.0, paper, "A", adhesion=adhesion) == math.inf
        assert me.d_crit(90.0, paper, "B", adhesion=adhesion, branch="indentation") == math.inf
        assert me.d_crit(90.0, paper, "B", adhesion=adhesion, branch="pull-off") == -math.inf
        assert me.d_crit(0.0, paper, "A", adhesion=adhesion) == 0.0
        small = me.d_crit(1e-7, paper, "A", adhesion=adhesion)
        assert 0.0 < small < 1e-12
        for branch in analytic.BRANCHES:
            assert me.d_crit(0.0, paper, "B", adhesion=adhesion, branch=branch) == pytest.approx(paper.d_max, rel=1e-12)
            assert me.d_crit(1e-6, paper, "B", adhesion=adhesion, branch=branch) == pytest.approx(paper.d_max, rel=1e-6)
    # Hertz pull-off tends to 0 as α → 90° like d_max²/k²: slip just before the contact vanishes
    for alpha in (89.0, 89.99, 89.9999):
        k = math.pi * paper.tau0 * math.sqrt(paper.R) * math.tan(math.radians(alpha)) / (2 * paper.G_star)
        expected = paper.d_max**2 / (math.sqrt(paper.d_max + k**2 / 4) + k / 2) ** 2
        assert me.d_crit(alpha, paper, "B", branch="pull-off") == pytest.approx(expected, rel=1e-13)


def test_monotone_in_angle(paper):
    for adhesion in (False, True):
        assert np.all(np.diff(me.d_crit(ANGLES, paper, "A", adhesion=adhesion)) > 0)
        assert np.all(np.diff(me.d_crit(ANGLES, paper, "B", adhesion=adhesion, branch="indentation")) > 0)
        pull = me.d_crit(ANGLES, paper, "B", adhesion=adhesion, branch="pull-off")
        assert np.all(np.diff(pull[np.isfinite(pull)]) < 0)


def test_critical_angles_of_the_paper(paper, paper_r100):
    assert me.critical_angle(paper, "A", adhesion=False) == pytest.approx(23.59, abs=0.02)
    assert me.critical_angle(paper, "A", adhesion=True) == pytest.approx(22.87, abs=0.02)
    for adhesion in (False, True):
        alpha_c = me.critical_angle(paper, "A", adhesion=adhesion)
        assert me.d_crit(alpha_c, paper, "A", adhesion=adhesion) == pytest.approx(paper.d_max, rel=1e-11)
        larger = me.critical_angle(paper_r100, "A", adhesion=adhesion)
        assert math.isfinite(larger) and 0 < larger < alpha_c


def test_critical_angle_of_scenario_B(paper):
    assert me.critical_angle(paper, "B", adhesion=False) == 90.0
    alpha_b = me.critical_angle(paper, "B", adhesion=True)
    jump = me.jump_off(paper, paper.dgamma1)
    assert me.d_crit(alpha_b - 1e-6, paper, "B", adhesion=True) == pytest.approx(jump["depth"], rel=1e-5)
    assert me.d_crit(alpha_b + 1e-6, paper, "B", adhesion=True) == -math.inf


def test_no_shear_strength_means_immediate_slip(paper):
    p = paper.replace(tau0=0.0)
    assert me.d_crit(30.0, p, "A") == 0.0
    assert me.d_crit(30.0, p, "A", adhesion=True) == 0.0
    assert me.critical_angle(p, "A") == 90.0


def test_shapes_scalars_and_bad_input(paper):
    assert isinstance(me.d_crit(30.0, paper), float)
    grid = np.linspace(0, 90, 12).reshape(3, 4)
    assert me.d_crit(grid, paper, "B", adhesion=True).shape == (3, 4)
    with pytest.raises(ValueError, match=r"alpha=91.0 .*\[0, 90\]"):
        me.d_crit([10.0, 91.0], paper)
    with pytest.raises(ValueError, match="alpha=nan"):
        me.d_crit(np.nan, paper)
    with pytest.raises(ValueError, match="scenario='C'"):
        me.d_crit(10.0, paper, scenario="C")
    with pytest.raises(ValueError, match="branch='up'"):
        me.d_crit(10.0, paper, scenario="B", branch="up")
    with pytest.raises(TypeError, match="adhesion"):
        me.d_crit(10.0, paper, adhesion="yes")


def test_jkr_round_trip_radius_depth_force(paper):
    g = paper.dgamma1
    jump = me.jump_off(paper, g)
    radius = np.geomspace(jump["contact_radius"] * 1.0001, 5e-3, 50)
    depth = me.jkr_depth(radius, paper, g)
    np.testing.assert_allclose(me.jkr_contact_radius(depth, paper, g), radius, rtol=1e-9)
    force = me.jkr_normal_force(radius, paper, g)
    assert force.min() >= me.pull_off_force(paper, g) * (1 + 1e-12)
    assert me.pull_off_force(paper, g) == pytest.approx(-1.5 * math.pi * g * paper.R, rel=1e-14)
    assert np.isnan(me.jkr_contact_radius(jump["depth"] * 1.01, paper, g))
    assert me.jkr_contact_radius(0.0, paper, g) == pytest.approx(analytic.jump_in_radius(paper, g), rel=1e-12)
    # Hertz limit
    assert me.jkr_contact_radius(1e-4, paper, 0.0) == pytest.approx(math.sqrt(paper.R * 1e-4), rel=1e-14)


def test_polynomial_root_solver_against_numpy_roots():
    rng = np.random.default_rng(1)
    for _ in range(200):
        coeffs = [1.0, *rng.normal(size=3)]
        coeffs[-1] = -abs(coeffs[-1]) - 1e-3  # p(0) < 0: a positive root exists
        roots = np.roots(coeffs)
        real = roots[np.abs(roots.imag) < 1e-9].real
        ours = analytic.positive_polynomial_root(coeffs)
        assert ours == pytest.approx(real.max(), rel=1e-9)


def _radii_near_the_folds(paper) -> dict:
    """Radii of (9) at depths at and just above each branch's fold, arrays of several sizes and scalars."""
    found = {}
    for work in (paper.dgamma0, paper.dgamma1):
        fold = analytic.jump_off(paper, work)["depth"]
        near = fold * (1.0 - np.logspace(-16, -2, 40))
        for size in (1, 2, 3, 9, 40, 300):
            depth = np.concatenate([[fold], near[:size - 1], np.linspace(fold, 1e-4, max(size - 40, 0))])
            found[work, size] = np.asarray(analytic.jkr_contact_radius(depth, paper, work))
        found[work, "scalar"] = np.array([analytic.jkr_contact_radius(float(d), paper, work) for d in near[::5]])
    return found


def test_polynomial_root_of_few_moving_elements_is_that_of_the_arrays(paper, monkeypatch):
    """At the pull-off fold Newton wanders for all its steps: the elements still moving after a few steps, and the
    bracketed iteration of a few, go on in Python floats (roots._finish_few, roots._bracketed_floats); the roots
    are bit for bit those of the whole arrays' iteration."""
    from mdr_events.theory import roots

    found = _radii_near_the_folds(paper)
    monkeypatch.setattr(roots, "_LONG", 10**9)  # the arrays alone, every step
    monkeypatch.setattr(roots, "_FEW", -1)
    expected = _radii_near_the_folds(paper)
    for key, radii in found.items():
        np.testing.assert_array_equal(radii, expected[key], err_msg=str(key))


def _radii_along_the_branches(paper) -> dict:
    """Radii of (9) of a few depths each (1 to 9: the Python floats' path of roots._descend_floats and the arrays'),
    spread from each branch's fold to 10 d_max, through the branch's own route (Branch.radii, as the continuum's
    fill takes it)."""
    from mdr_events.models.continuum.branch import Branch

    rng = np.random.default_rng(7)
    found = {}
    for work in (paper.dgamma0, paper.dgamma1):
        branch = Branch(paper, work)
        for size in range(1, 10):
            for trial in range(20):
                depth = branch.jump_off_depth + (10 * paper.d_max - branch.jump_off_depth) * rng.random(size) ** 3
                found[work, size, trial] = branch.radii(depth)
    return found


def test_polynomial_root_of_few_elements_is_that_of_the_arrays(paper, monkeypatch):
    """Newton's descent of at most roots._FEW elements runs in Python floats (roots._descend_floats): every root is
    bit for bit the arrays' iteration's."""
    from mdr_events.theory import roots

    found = _radii_along_the_branches(paper)
    monkeypatch.setattr(roots, "_LONG", 10**9)  # the arrays alone, every step
    monkeypatch.setattr(roots, "_FEW", -1)
    expected = _radii_along_the_branches(paper)
    for key, radii in found.items():
        np.testing.assert_array_equal(radii, expected[key], err_msg=str(key))


def _roots_over_blocks(rng, size: int) -> list:
    """Roots of ``size`` monic quartics and cubics: scalar and array coefficients of either sign (convex ones, and ones
    whose Newton steps overshoot and go upwards)."""
    found = []
    for trial in range(12):
        middle = [rng.normal(size=size), 0.0, -abs(rng.normal()), np.abs(rng.normal(size=size))][trial % 4]
        coefficients = [1.0, 0.0 if trial % 3 else rng.normal(size=size), middle, rng.normal(),
                        -np.abs(rng.normal(size=size)) - 1e-3][: 5 - trial % 2]
        with np.errstate(all="ignore"):
            found.append(roots.positive_polynomial_root(coefficients))
    return found


#: The block's size in the test of the roots over blocks: large enough that each block holds overshoots and upward
#: steps of the random quartics (counted in the test), small enough for arrays of a few thousand elements.
SMALL_BLOCK = 500


def test_polynomial_roots_over_blocks_are_those_of_one_block(monkeypatch):
    """Newton's descent over several blocks reads the stopping rule block by block until one fails it, and skips the
    threshold |x| rtol of the blocks after (it serves only that rule and an upward step; issue 28), and the bound of
    the start reads the coefficients' signs only where a term may be used: every root, upward steps and overshoots
    among them, is bit for bit that of the whole array as one block. Blocks of SMALL_BLOCK elements: the rule is the
    same for any block's size (the module's 16 000 took 4 s of 48 017-element arrays for the same claim)."""
    monkeypatch.setattr(roots, "_BLOCK", SMALL_BLOCK)
    size = 3 * roots._BLOCK + 17  # (three blocks and a part)
    overshoots, descend = [], roots._descend

    def watched(*arguments):
        flags = descend(*arguments)
        overshoots.append(np.array(flags).reshape(-1))
        return flags

    monkeypatch.setattr(roots, "_descend", watched)
    found = _roots_over_blocks(np.random.default_rng(28), size)
    monkeypatch.setattr(roots, "_descend", descend)
    # every block, the part too, holds elements whose steps went upwards (the rule read block by block meets them)
    assert {int(i) // SMALL_BLOCK for flags in overshoots for i in np.flatnonzero(flags)} == {0, 1, 2, 3}
    monkeypatch.setattr(roots, "_BLOCK", size)
    expected = _roots_over_blocks(np.random.default_rng(28), size)
    for index, (ours, whole) in enumerate(zip(found, expected)):
        np.testing.assert_array_equal(ours, whole, err_msg=str(index))


def test_the_start_s_bound_is_the_least_of_the_usable_terms():
    """roots._upper_root_bound reads the coefficients' signs only where a term may be used (issue 28): the bound is bit
    for bit the least, over the terms, of each term's bound where it is usable (its coefficient positive, none above
    it negative), every term computed everywhere, on coefficients of every sign pattern, scalars and arrays."""
    def reference(coeffs):
        present = [i for i, cf in enumerate(coeffs) if not (np.ndim(cf) == 0 and cf == 0)]
        bound = None
        for j in present[:-1]:
            lower = [i for i in present if i > j]
            candidate = roots._term_bound(coeffs, j, lower, positive=j > 0 or bool(np.all(coeffs[j] > 0.0)))
            if j == 0:
                bound = candidate
                continue
            usable = coeffs[j] > 0.0
            for k in present:
                if k < j:
                    usable = usable & (coeffs[k] >= 0.0)
            bound = np.minimum(bound, np.where(usable, candidate, np.inf))
        return bound

    rng = np.random.default_rng(32)
    for _ in range(400):
        size = int(rng.choice([1, 5, 300]))
        options = (lambda: 0.0, lambda: float(rng.normal()), lambda: abs(float(rng.normal())),
                   lambda: rng.normal(size=size), lambda: np.abs(rng.normal(size=size)))
        coeffs = [1.0 if rng.random() < 0.8 else 2.0] + [options[rng.integers(0, 5)]() for _ in range(rng.integers(1, 4))]
        coeffs.append(-np.abs(rng.normal(size=size)) - 1e-3)
        with np.errstate(all="ignore"):
            expected = np.broadcast_to(reference(coeffs), (size,))
            np.testing.assert_array_equal(np.broadcast_to(roots._upper_root_bound(coeffs), (size,)), expected)


def test_branch_only_for_scenario_B_and_flags_checked(paper):
    with pytest.raises(ValueError, match="branch='indentation' is not allowed with scenario 'A'"):
        me.d_crit(10.0, paper, "A", branch="indentation")
    with pytest.raises(TypeError, match="adhesion='no'"):
        me.critical_angle(paper, "A", adhesion="no")
    assert me.d_crit(20.0, paper, "B") == me.d_crit(20.0, paper, "B", branch="pull-off")


def test_no_warning_at_the_double_root(paper):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert me.d_crit(0.0, paper.replace(dgamma0=0.0), "A", adhesion=True) == 0.0


@pytest.mark.parametrize("adhesion", [True, False])
@pytest.mark.parametrize("final_depth", [None, 4.5e-4])
def test_critical_angle_of_scenario_B_plus_is_slip_onset_at_the_final_depth(paper, adhesion, final_depth):
    """B+: at α_c the "+" branch of (20)/(21) puts slip onset exactly at the path's final depth (default
    2 d_max, the depth :meth:`Path.scenario_B_indentation` turns at); just below α_c it slides before."""
    angle = me.critical_angle(paper, "B+", adhesion=adhesion, final_depth=final_depth)
    final = 2 * paper.d_max if final_depth is None else final_depth
    onset = me.d_crit(angle, paper, "B", adhesion=adhesion, branch="indentation")
    assert onset == pytest.approx(final, rel=1e-12)
    assert me.d_crit(angle * 0.99, paper, "B", adhesion=adhesion, branch="indentation") < final


def test_critical_angle_of_scenario_B_plus_is_what_the_continuum_finds(paper):
    """On the path itself: just below α_c the continuum slides before the turn, just above it does not."""
    angle = me.critical_angle(paper, "B+", adhesion=True)
    for factor, slides in ((0.999, True), (1.001, False)):
        ds = me.simulate(paper, "B+", alpha=[angle * factor], method="continuum", samples=11)
        kinds = list(ds["event_kind"].values[0])
        turn = [i for i, kind in enumerate(kinds) if kind == "corner"][1]  # the turn at the final depth
        assert ("slip_onset" in kinds[:turn]) is slides


def test_critical_angle_rejects_what_it_cannot_use(paper):
    with pytest.raises(ValueError, match="scenario='C' is not allowed; allowed: 'A', 'B', 'B\\+'"):
        me.critical_angle(paper, "C")
    with pytest.raises(ValueError, match="final_depth=0.0003 is not allowed; allowed: a finite depth > d_max"):
        me.critical_angle(paper, "B+", final_depth=3e-4)
    with pytest.raises(ValueError, match="final_depth=0.001 is not allowed with scenario 'A'"):
        me.critical_angle(paper, "A", final_depth=1e-3)


def test_fretting_dissipated_energy_is_the_parallelogram(paper):
    """4 π a² τ0 (X − ū): zero at X = ū (the loop closes to a line), linear in X beyond, and twice the
    plateau π a² τ0 times the travel 2(X − ū) on each plateau."""
    a = 2.5e-3
    cap = float(me.critical_shift(a, paper))
    plateau = paper.tau0 * np.pi * a**2
    assert me.fretting_dissipated_energy(a, cap, paper) == pytest.approx(0.0, abs=1e-15 * plateau * cap)
    for amplitude in (1.5 * cap, 3.0 * cap, 10.0 * cap):
        expected = 2 * plateau * 2 * (amplitude - cap)
        assert me.fretting_dissipated_energy(a, amplitude, paper) == pytest.approx(expected, rel=1e-14)


# --- the phase diagram's curves computed into their rows, and the root finder's shorter passes (issue 28) ----------
@pytest.mark.parametrize("count", [7, 40_001])  # one block, and several (blocks.BLOCK)
@pytest.mark.parametrize("scenario", ["A", "B"])
def test_the_rows_of_the_curves_are_d_crit_bit_for_bit(paper, scenario, count):
    """d_crit_rows writes each curve into its row (root, then onset, in one array; no stacking): every row, and the
    phase diagram's variables made of them, equals d_crit of that branch alone, bit for bit."""
    alphas = np.linspace(0.0, 90.0, count)
    rows = analytic.d_crit_rows(alphas, paper, scenario)
    curves = analytic.d_crit_curves(alphas, paper, scenario)
    diagram = me.phase_diagram(paper, alphas, scenario=scenario)
    branches = [None] if scenario == "A" else list(analytic.BRANCHES)
    for adhesion, key in ((False, "hertz"), (True, "jkr")):
        assert rows[adhesion].shape == (len(branches), count)
        for row, branch in enumerate(branches):
            alone = np.asarray(me.d_crit(alphas, paper, scenario, adhesion=adhesion, branch=branch))
            np.testing.assert_array_equal(rows[adhesion][row], alone)
            np.testing.assert_array_equal(curves[adhesion, branch], alone)
        np.testing.assert_array_equal(diagram[f"d_crit_{key}"].values, rows[adhesion][0] if scenario == "A"
                                      else rows[adhesion])
    assert analytic.d_crit_curves(20.0, paper, scenario)[True, branches[0]].shape == ()  # one angle: 0-d, as before


def _polynomials_with_leading_zeros(rng, size: int) -> list:
    """Monic polynomials ``s^n + 0 s^(n-1) + ... + c_1 s + c_0`` as the model's quartics have them (scalar zeros after
    the leading 1; arrays and scalars below), with a positive root."""
    found = []
    for degree in (2, 3, 4, 5):
        for zeros in range(1, degree):
            coefficients = [1.0] + [0] * zeros
            for _ in range(degree - zeros):
                coefficients.append(rng.normal(size=size) * 1e-5 if rng.random() < 0.5 else float(rng.normal()) * 1e-5)
            coefficients[-1] = -np.abs(np.broadcast_to(coefficients[-1], (size,))) - 1e-12
            found.append(coefficients)
    return found


def test_the_horner_passes_that_skip_the_leading_zeros_give_the_same_roots(monkeypatch):
    """roots._horner_into skips the additions of a monic polynomial's leading zero coefficients (x + 0 is x); the
    roots, with and without out=, are those of the plain passes bit for bit (where an element overshoots too)."""
    from mdr_events.theory import roots

    rng = np.random.default_rng(28)
    cases = _polynomials_with_leading_zeros(rng, 20_001) + [[1.0, 0, rng.normal(size=300), 1.0, -1e-3]]
    found = []
    for coefficients in cases:
        out = np.empty(np.broadcast_shapes(*[np.shape(c) for c in coefficients]))
        root = roots.positive_polynomial_root(coefficients)
        assert roots.positive_polynomial_root(coefficients, out=out) is out
        np.testing.assert_array_equal(out, root)
        found.append(root)
    monkeypatch.setattr(roots, "_leading_zeros", lambda coefficients: 0)
    for coefficients, root in zip(cases, found):
        np.testing.assert_array_equal(roots.positive_polynomial_root(coefficients), root)
    assert roots._leading_zeros is not None
    with pytest.raises(ValueError, match="out of shape"):
        roots.positive_polynomial_root(cases[0], out=np.empty(3))


def test_blockwise_into_a_row_is_blockwise(paper):
    """blockwise(out=) writes the blocks into the given (C-contiguous) row: the values of blockwise without it."""
    from mdr_events.theory.blocks import BLOCK, blockwise

    values = np.linspace(-3.0, 3.0, 2 * BLOCK + 17)
    rows = np.empty((2, values.size))
    row = rows[1]
    assert blockwise(np.sin, values, out=row) is row
    np.testing.assert_array_equal(rows[1], blockwise(np.sin, values))
    small = np.empty(5)
    np.testing.assert_array_equal(blockwise(np.sin, values[:5], out=small), np.sin(values[:5]))
    with pytest.raises(ValueError, match="C-contiguous"):
        blockwise(np.sin, values, out=np.empty((values.size, 2))[:, 0])


def test_the_kept_jump_off_is_the_computed_one_and_a_fresh_dict():
    """jump_off keeps the paraboloid's points (issue 28: a run asks them at every step of its set-up): the kept point
    is the computation's bit for bit, each call gets a dict of its own, and an int R is kept apart from a float one."""
    from mdr_events.theory.analytic import _paraboloid_jump_off

    p = me.Parameters.paper()
    first = analytic.jump_off(p, p.dgamma1)
    first["depth"] = 0.0  # a caller's change stays its own
    again = analytic.jump_off(p, p.dgamma1)
    assert again == dict(_paraboloid_jump_off.__wrapped__(p.R, p.E_star, p.dgamma1, 1.0)) and again["depth"] < 0.0
    assert _paraboloid_jump_off(1, p.E_star, p.dgamma1, 1.0) is not _paraboloid_jump_off(1.0, p.E_star, p.dgamma1, 1.0)
