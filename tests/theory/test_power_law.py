"""The power-law and flat-punch relations: derived, checked against the paper's paraboloid, the literature's
closed forms (Sneddon's cone, JKR, Kendall) and independent numerical routes (quadrature of the Abel transform
and of the springs' force, a bounded minimisation)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy import integrate, optimize

import mdr_events as me
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.theory import analytic
from mdr_events.theory import power_law as pl
from mdr_events.theory import symbolic as S

EPS = float(np.finfo(float).eps)
#: Exponents checked: below the cone, the cone, between, the paraboloid, beyond it, a nearly flat punch.
EXPONENTS = [0.75, 1.0, 1.5, 2.0, 3.0, 6.0]


@pytest.fixture(scope="module")
def paper():
    return me.Parameters.paper()


def _profile_with_paper_scale(n: float, params: me.Parameters) -> PowerLaw:
    """A power law with the paraboloid's height at the paper's radius scale (f(√(R d_max)) equal)."""
    radius = math.sqrt(params.R * params.d_max)
    return PowerLaw(radius**2 / (2 * params.R) / radius**n, n)


def test_with_radius_at_puts_the_non_adhesive_radius_there(paper):
    """with_radius_at(n, a, d): the non-adhesive radius at d is a, for every n; n = 2 is the paraboloid whose
    Hertz radius √(R d) is a."""
    for n in EXPONENTS:
        profile = pl.with_radius_at(n, 2e-3, 1e-4)
        assert pl.contact_radius(1e-4, profile, paper, 0.0) == pytest.approx(2e-3, rel=1e-14)
    assert pl.with_radius_at(2.0, math.sqrt(paper.R * paper.d_max), paper.d_max).c == pytest.approx(
        PowerLaw.paraboloid(paper.R).c, rel=1e-14)


# --- symbolic: the paraboloid and the literature's cases -------------------------------------------------
PARABOLOID_PAIRS = [  # power-law key, paper key, the paper's arguments from the power law's (n = 2, c = 1/(2R))
    ("power_law_depth", "jkr_depth"),
    ("power_law_depth_slope", "jkr_depth_slope"),
    ("power_law_depth_integral", "jkr_depth_integral"),
    ("power_law_normal_force", "normal_force"),
    ("power_law_branch_normal_force", "jkr_normal_force"),
    ("power_law_hertz_radius", "hertz_radius"),
    ("power_law_jump_in_radius", "jump_in_radius"),
    ("power_law_pull_off_radius", "pull_off_radius"),
    ("power_law_pull_off_force", "pull_off_force"),
    ("power_law_jump_off_radius", "jump_off_radius"),
    ("power_law_jump_off_depth", "jump_off_depth"),
    ("power_law_jump_off_force", "jump_off_force"),
    ("power_law_d_crit_A_hertz", "d_crit_A_hertz"),
]


@pytest.mark.parametrize("power_law_key, paper_key", PARABOLOID_PAIRS)
def test_the_paraboloid_case_is_the_papers_relation(power_law_key, paper_key):
    """n = 2, c = 1/(2R): each power-law relation simplifies to the paper's, exactly."""
    general = S.relation(power_law_key).rhs.subs({S.n: 2, S.c: 1 / (2 * S.R)})
    assert sp.simplify(general - S.relation(paper_key).rhs) == 0


def test_the_cone_is_sneddons():
    """n = 1, c = tan θ, no adhesion: d = (π/2) a tan θ and F = (π/2) E* a² tan θ (Sneddon, Int. J. Eng. Sci. 3
    (1965) 47, with the half-angle's cotangent tan θ)."""
    cone = {S.n: 1, S.c: sp.tan(S.theta), S.dgamma: 0}
    depth = S.relation("power_law_depth").rhs.subs(cone)
    force = S.relation("power_law_branch_normal_force").rhs.subs(cone)
    assert sp.simplify(depth - sp.pi / 2 * S.a * sp.tan(S.theta)) == 0
    assert sp.simplify(force - sp.pi / 2 * S.E_star * S.a**2 * sp.tan(S.theta)) == 0


def test_the_flat_punch_comes_off_at_kendalls_force():
    """F = −sqrt(8π a³ E* Δγ) (Kendall, J. Phys. D 4 (1971) 1186)."""
    force = S.relation("flat_punch_pull_off_force").rhs
    assert sp.simplify(force + sp.sqrt(8 * sp.pi * S.a**3 * S.E_star * S.dgamma)) == 0


def test_the_pull_off_radius_is_hess_power_law_result():
    """a^(2n−1) = 9 Δγ / (2 E* n² κ² c²)·π with κ = √π Γ(n/2+1)/Γ(n/2+1/2), i.e. 9πΔγ/(2E* n² (κc)²) (Heß's
    general power-law result; JKR's 9πΔγR²/(8E*) at n = 2)."""
    kappa = sp.sqrt(sp.pi) * sp.gamma(S.n / 2 + 1) / sp.gamma(S.n / 2 + sp.Rational(1, 2))
    expected = (9 * sp.pi * S.dgamma / (2 * S.E_star * S.n**2 * kappa**2 * S.c**2)) ** (1 / (2 * S.n - 1))
    derived = S.relation("power_law_pull_off_radius").rhs
    for n_value in (sp.Rational(3, 4), 1, sp.Rational(3, 2), 2, 3, 7):
        point = {S.n: n_value, S.c: sp.Rational(7, 3), S.dgamma: sp.Rational(1, 50), S.E_star: 10**6}
        assert sp.N(derived.subs(point) - expected.subs(point), 30) == pytest.approx(0.0, abs=1e-25)


# --- independent numerical routes --------------------------------------------------------------------------
@pytest.mark.parametrize("n", [0.8, 2.7, 4.0])
def test_the_equivalent_profile_is_the_abel_transform_by_quadrature(n):
    """g(x) = x ∫_0^x f'(r)/sqrt(x² − r²) dr by adaptive quadrature (substitution r = x sin φ) equals κ c xⁿ."""
    profile = PowerLaw(3.0, n)
    for x in (1e-3, 0.5, 2.0):
        quadrature, _ = integrate.quad(lambda phi: profile.c * n * (x * math.sin(phi)) ** (n - 1) * x,
                                       0.0, math.pi / 2, epsabs=0.0, epsrel=1e-13)
        assert pl.equivalent_profile(x, profile) == pytest.approx(quadrature, rel=1e-12)


@pytest.mark.parametrize("n", [0.75, 1.0, 1.5, 3.0])
def test_the_pull_off_force_is_the_minimum_of_the_springs_force(paper, n):
    """The closed form against a bounded minimisation of F(a) = 2E* ∫_0^a (d(a) − g(x)) dx summed by quadrature,
    d(a) by Heß's rule from g: the minimiser is known to sqrt(eps) of a, the force to eps of its curvature."""
    profile = _profile_with_paper_scale(n, paper)
    work = paper.dgamma1

    def springs_force(a):
        depth = float(pl.equivalent_profile(a, profile)) - math.sqrt(2 * math.pi * a * work / paper.E_star)
        # x = a t^2 takes the x^(n−1) of g' at 0 out of the integrand (n < 1: an infinite slope there)
        value, _ = integrate.quad(lambda t: (depth - float(pl.equivalent_profile(a * t * t, profile))) * 2 * a * t,
                                  0.0, 1.0, epsabs=0.0, epsrel=1e-12)
        return 2 * paper.E_star * value

    closed_radius = float(S.relation("power_law_pull_off_radius").numeric(profile.c, profile.n, paper.E_star, work))
    found = optimize.minimize_scalar(springs_force, bounds=(0.2 * closed_radius, 5 * closed_radius),
                                     method="bounded", options={"xatol": 1e-10 * closed_radius})
    assert found.x == pytest.approx(closed_radius, rel=1e-6)
    assert pl.pull_off_force(profile, paper, work) == pytest.approx(found.fun, rel=1e-11)


# --- the analytic layer against the paper's functions and its own inverses ---------------------------------
def test_the_paraboloid_gives_the_papers_numbers(paper):
    """PowerLaw.paraboloid(R) with the paper's parameters: radii, forces, jump-off and slip onset equal the
    analytic layer's to a few ulp."""
    profile = PowerLaw.paraboloid(paper.R)
    depth = np.linspace(-3e-5, 2 * paper.d_max, 41)
    for work in (0.0, paper.dgamma0, paper.dgamma1):
        np.testing.assert_allclose(pl.contact_radius(depth, profile, paper, work),
                                   analytic.jkr_contact_radius(depth, paper, work), rtol=1e-13, equal_nan=True)
    a = np.linspace(1e-4, 4e-3, 9)
    np.testing.assert_allclose(pl.branch_normal_force(a, profile, paper, paper.dgamma0),
                               analytic.jkr_normal_force(a, paper, paper.dgamma0), rtol=1e-13)
    assert pl.pull_off_force(profile, paper, paper.dgamma1) == pytest.approx(-1.5 * math.pi * paper.dgamma1 * paper.R,
                                                                              rel=4 * EPS)
    for key, value in pl.jump_off(profile, paper, paper.dgamma1).items():
        assert value == pytest.approx(analytic.jump_off(paper, paper.dgamma1)[key], rel=1e-14)
    alpha = np.array([1.0, 5.0, 20.0, 45.0, 80.0])
    for adhesion in (False, True):
        np.testing.assert_allclose(pl.d_crit_A(alpha, profile, paper, adhesion),
                                   analytic.d_crit(alpha, paper, "A", adhesion=adhesion), rtol=1e-13)
        assert pl.critical_angle_A(profile, paper, adhesion) == pytest.approx(
            analytic.critical_angle(paper, "A", adhesion=adhesion), rel=1e-13)


@pytest.mark.parametrize("n", EXPONENTS)
@pytest.mark.parametrize("adhesive", [False, True])
def test_the_radius_of_a_depth_lies_on_the_branch(paper, n, adhesive):
    """contact_radius inverts the branch: d(a(d)) = d to a few ulp of the depths involved; nan above the
    jump-off (or the surface), and the radius grows with the depth."""
    profile = _profile_with_paper_scale(n, paper)
    work = paper.dgamma0 if adhesive else 0.0
    fold = pl.jump_off(profile, paper, work)
    depth = np.concatenate([np.linspace(fold["depth"], 3 * paper.d_max, 60), [fold["depth"] - 1e-6 - abs(fold["depth"])]])
    radius = pl.contact_radius(depth, profile, paper, work)
    assert np.isnan(radius[-1])
    back = pl.branch_depth(radius[:-1], profile, paper, work)
    scale = max(abs(fold["depth"]), paper.d_max)
    np.testing.assert_allclose(back, depth[:-1], rtol=0.0, atol=64 * EPS * 3 * scale)
    assert np.all(np.diff(radius[:-1]) > 0)


@pytest.mark.parametrize("n", [1.0, 1.5, 2.0, 3.0, 6.0])
@pytest.mark.parametrize("adhesion", [False, True])
def test_the_slip_onset_depth_is_where_the_shift_reaches_the_cap(paper, n, adhesion):
    """At d_crit the path's shift d / tan α equals ū(a(d)) = K a(d), with the radius of the branch the path is
    on; where no onset exists (the cone above its angle) the result is nan."""
    profile = _profile_with_paper_scale(n, paper)
    alpha = np.array([2.0, 10.0, 30.0])
    depth = pl.d_crit_A(alpha, profile, paper, adhesion)
    work = paper.dgamma0 if adhesion else 0.0
    found = np.isfinite(depth)
    assert np.count_nonzero(found) >= 2
    radius = pl.contact_radius(depth[found], profile, paper, work)
    shift = depth[found] / np.tan(np.deg2rad(alpha[found]))
    np.testing.assert_allclose(shift, analytic.critical_shift(radius, paper), rtol=1e-12)


def test_the_paraboloid_gives_the_papers_scenario_B(paper):
    """The pull-off branch of (20), (21) and its critical angle: the paraboloid's numbers to a few ulp."""
    profile = PowerLaw.paraboloid(paper.R)
    alpha = np.array([1.0, 5.0, 20.0, 45.0, 60.0, 80.0, 90.0])
    for adhesion in (False, True):
        np.testing.assert_allclose(pl.d_crit_B(alpha, profile, paper, adhesion),
                                   analytic.d_crit(alpha, paper, "B", adhesion=adhesion), rtol=1e-13)
        assert pl.critical_angle_B(profile, paper, adhesion) == pytest.approx(
            analytic.critical_angle(paper, "B", adhesion=adhesion), rel=1e-13)


@pytest.mark.parametrize("n", [0.75, 1.0, 1.5, 3.0, 6.0])
def test_scenario_B_slides_where_the_pull_off_shift_reaches_the_cap(paper, n):
    """At d_crit (pull-off) the shift (d_max − d) / tan α equals K a(d) on the Δγ1 branch; above the critical
    angle the contact comes apart first (-inf), below it it slides, and the critical angle is where the onset
    reaches the jump-off."""
    profile = _profile_with_paper_scale(n, paper)
    critical = pl.critical_angle_B(profile, paper)
    alpha = np.array([1.0, 10.0, 0.9 * critical, 0.999 * critical, 1.001 * critical])
    depth = pl.d_crit_B(alpha, profile, paper, adhesion=True)
    assert np.all(np.isfinite(depth[:4])) and depth[4] == -np.inf
    radius = pl.contact_radius(depth[:4], profile, paper, paper.dgamma1)
    shift = (paper.d_max - depth[:4]) / np.tan(np.deg2rad(alpha[:4]))
    np.testing.assert_allclose(shift, analytic.critical_shift(radius, paper), rtol=1e-11)
    fold = pl.jump_off(profile, paper, paper.dgamma1)
    assert depth[3] == pytest.approx(fold["depth"], abs=1e-2 * abs(paper.d_max - fold["depth"]))


def test_the_cone_slides_from_first_contact_or_never(paper):
    """Without adhesion the cone's shift and cap grow in proportion: d_crit is 0 below α_c = atan(κ c / K) and
    nan above it; the critical angle is the same at any d_max."""
    cone = PowerLaw.cone(0.02)
    angle = pl.critical_angle_A(cone, paper, adhesion=False)
    kappa_c = math.pi / 2 * 0.02
    K = math.pi * paper.tau0 / (2 * paper.G_star)
    assert angle == pytest.approx(math.degrees(math.atan(kappa_c / K)), rel=1e-13)
    assert pl.critical_angle_A(cone, paper.replace(d_max=7 * paper.d_max), adhesion=False) == pytest.approx(angle,
                                                                                                              rel=1e-13)
    below, above = pl.d_crit_A([0.99 * angle, 1.01 * angle], cone, paper)
    assert below == 0.0 and math.isnan(above)


def test_the_flat_punch(paper):
    """F = 2 E* a d in contact; slip onset (all at once) at d = tan α ū(a); α_c from d_max; Kendall's pull-off
    at the depth −sqrt(2π a Δγ / E*) where every spring reaches Heß's limit."""
    punch = FlatPunch(1.5e-3)
    assert pl.normal_force(1e-4, None, punch, paper) == pytest.approx(2 * paper.E_star * 1.5e-3 * 1e-4, rel=4 * EPS)
    point = pl.jump_off(punch, paper, paper.dgamma1)
    assert point["depth"] == pytest.approx(-math.sqrt(2 * math.pi * 1.5e-3 * paper.dgamma1 / paper.E_star), rel=4 * EPS)
    assert point["normal_force"] == pytest.approx(-math.sqrt(8 * math.pi * 1.5e-3**3 * paper.E_star * paper.dgamma1),
                                                  rel=4 * EPS)
    assert pl.pull_off_force(punch, paper, paper.dgamma1) == point["normal_force"]
    cap = float(analytic.critical_shift(1.5e-3, paper))
    assert pl.d_crit_A(20.0, punch, paper) == pytest.approx(math.tan(math.radians(20.0)) * cap, rel=4 * EPS)
    assert pl.critical_angle_A(punch, paper) == pytest.approx(math.degrees(math.atan(paper.d_max / cap)), rel=1e-14)
    # scenario B: all anchored at x = 0, all slide at d_max − tan α ū, unless Kendall's depth comes first
    assert pl.d_crit_B(20.0, punch, paper, True) == pytest.approx(paper.d_max - math.tan(math.radians(20.0)) * cap,
                                                                  rel=1e-14)
    critical = math.degrees(math.atan((paper.d_max - point["depth"]) / cap))
    assert pl.critical_angle_B(punch, paper) == pytest.approx(critical, rel=1e-14)
    assert pl.d_crit_B(1.001 * critical, punch, paper, True) == -np.inf


# --- bad input ---------------------------------------------------------------------------------------------
@pytest.mark.parametrize("make, error, message", [
    (lambda: PowerLaw(1.0, 0.0), ValueError, r"PowerLaw.n=0.0 is not allowed; allowed: a finite number > 0"),
    (lambda: PowerLaw(-1.0, 2.0), ValueError, r"PowerLaw.c=-1.0 is not allowed; allowed: a finite number > 0"),
    (lambda: PowerLaw(float("nan"), 2.0), ValueError, r"PowerLaw.c=nan is not allowed"),
    (lambda: PowerLaw(1.0, True), TypeError, r"PowerLaw.n=True \(bool\) is not allowed"),
    (lambda: PowerLaw.paraboloid(0.0), ValueError, r"R=0.0 is not allowed; allowed: a finite number > 0 \(m\)"),
    (lambda: PowerLaw.cone(-0.1), ValueError, r"slope=-0.1 is not allowed"),
    (lambda: FlatPunch(float("inf")), ValueError, r"FlatPunch.radius=inf is not allowed; allowed: a finite number > 0"),
])
def test_bad_profiles_name_the_argument(make, error, message):
    with pytest.raises(error, match=message):
        make()


def test_bad_uses_name_the_argument(paper):
    with pytest.raises(ValueError, match=r"PowerLaw.n=0.4 is not allowed with adhesion .* allowed: n > 0.5"):
        pl.contact_radius(1e-4, PowerLaw(1.0, 0.4), paper, paper.dgamma0)
    with pytest.raises(TypeError, match=r"profile='cone' \(str\) is not allowed; allowed: a PowerLaw or a FlatPunch"):
        pl.pull_off_force("cone", paper, paper.dgamma1)
    with pytest.raises(TypeError, match=r"profile=FlatPunch\(radius=0.001\) is not allowed for contact_radius"):
        pl.contact_radius(1e-4, FlatPunch(1e-3), paper, 0.0)
    with pytest.raises(ValueError, match=r"contact_radius=0.002 is not allowed for FlatPunch"):
        pl.normal_force(1e-4, 2e-3, FlatPunch(1e-3), paper)
    with pytest.raises(ValueError, match=r"PowerLaw.n=0.75 is not allowed for the adhesive slip onset"):
        pl.d_crit_A(20.0, PowerLaw(1.0, 0.75), paper, adhesion=True)


# --- scenario B's indentation branch and the phase diagrams -------------------------------------------------
def test_the_paraboloid_gives_the_papers_indentation_branch(paper):
    profile = PowerLaw.paraboloid(paper.R)
    alpha = np.array([0.0, 1.0, 5.0, 20.0, 45.0, 80.0, 90.0])
    for adhesion in (False, True):
        np.testing.assert_allclose(pl.d_crit_B_indentation(alpha, profile, paper, adhesion),
                                   analytic.d_crit(alpha, paper, "B", adhesion=adhesion, branch="indentation"),
                                   rtol=1e-13)
        assert pl.critical_angle_B_indentation(profile, paper, adhesion) == pytest.approx(
            analytic.critical_angle(paper, "B+", adhesion=adhesion), rel=1e-13)


@pytest.mark.parametrize("n", [1.0, 1.5, 3.0, 6.0])
def test_the_indentation_branch_slides_where_the_shift_reaches_the_cap(paper, n):
    """(d − d_max) / tan α = K a(d) on the Δγ0 branch; the cone never slides once tan α K >= κ c (+inf)."""
    profile = _profile_with_paper_scale(n, paper)
    alpha = np.array([1.0, 10.0, 30.0, 60.0])
    depth = pl.d_crit_B_indentation(alpha, profile, paper, adhesion=True)
    found = np.isfinite(depth)
    assert np.count_nonzero(found) >= 2
    radius = pl.contact_radius(depth[found], profile, paper, paper.dgamma0)
    shift = (depth[found] - paper.d_max) / np.tan(np.deg2rad(alpha[found]))
    np.testing.assert_allclose(shift, analytic.critical_shift(radius, paper), rtol=1e-11)
    if n == 1.0:
        slope = np.tan(np.deg2rad(alpha)) * float(analytic.critical_shift(1.0, paper))
        np.testing.assert_array_equal(~found, slope >= pl.prefactor(profile))


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_the_phase_diagram_of_the_paraboloid_as_a_power_law_is_the_papers(paper, scenario):
    """Same numbers (1e-12, of d_max for the depths: near 90° the pull-off onset d_max − tan α ū cancels to
    1e-4 d_max, which the paper's Vieta form keeps to a few ulp of itself), same encoding of 'never slides'
    (±inf), the profile named, no paper figure."""
    default = me.phase_diagram(paper, scenario=scenario)
    other = me.phase_diagram(paper, scenario=scenario, profile=PowerLaw.paraboloid(paper.R))
    assert set(other.data_vars) == set(default.data_vars)
    for name in default.data_vars:
        expected, found = default[name].values, other[name].values
        np.testing.assert_array_equal(np.isinf(found), np.isinf(expected))
        finite = np.isfinite(expected)
        np.testing.assert_allclose(found[finite], expected[finite], rtol=1e-12,
                                   atol=1e-12 * paper.d_max if name.startswith("d_") else 0.0)
    assert other.attrs["profile"].startswith("power law") and "figure" not in other.attrs


def test_the_phase_diagrams_of_other_indenters(paper):
    """A cone without adhesion: 0 below its angle, +inf (never while indenting) above; the flat punch's
    onsets are straight lines in tan α; each diagram's critical angles are the functions'."""
    cone = PowerLaw.cone(0.08)
    diagram = me.phase_diagram(paper, alpha=np.array([5.0, 80.0]), scenario="A", profile=cone)
    assert list(diagram["d_crit_hertz"].values) == [0.0, np.inf]
    assert float(diagram["critical_angle_jkr"]) == pl.critical_angle_A(cone, paper, adhesion=True)
    punch = FlatPunch(1e-3)
    diagram = me.phase_diagram(paper, alpha=np.array([10.0, 20.0]), scenario="B", profile=punch)
    cap = float(analytic.critical_shift(1e-3, paper))
    np.testing.assert_allclose(diagram["d_crit_hertz"].sel(branch="indentation").values,
                               paper.d_max + np.tan(np.deg2rad([10.0, 20.0])) * cap, rtol=1e-14)
    assert float(diagram["critical_angle_jkr"]) == pl.critical_angle_B(punch, paper)
    with pytest.raises(TypeError, match=r"profile='cone' \(str\) is not allowed"):
        me.phase_diagram(paper, profile="cone")


def test_a_flat_punch_without_adhesion_comes_off_at_the_surface_in_scenario_B(paper):
    """The punch keeps its radius and comes off whole at d = 0 without adhesion (Kendall's depth with it): an
    onset that would lie above the surface is -inf, and the critical angle is where the onset reaches it."""
    punch = FlatPunch(1e-4)
    cap = float(analytic.critical_shift(1e-4, paper))
    critical = math.degrees(math.atan(paper.d_max / cap))
    assert pl.critical_angle_B(punch, paper, adhesion=False) == pytest.approx(critical, rel=1e-14)
    assert pl.d_crit_B(1.001 * critical, punch, paper, adhesion=False) == -np.inf
    assert pl.d_crit_B(0.999 * critical, punch, paper, adhesion=False) > 0.0


@pytest.mark.parametrize("n", [1.0, 1.0001, 1.001, 1.01])
def test_exponents_near_one_keep_their_roots(paper, n):
    """Near n = 1 the closed-form bounds' exponents 1/(2n − 2) overflow; the roots are still found and move
    continuously with n (the onset of a cone with c = 0.5 at 68.75°: 2.2e-6 m at n = 1)."""
    profile = PowerLaw(0.5, n)
    depth = pl.d_crit_A(68.75, profile, paper, adhesion=True)
    if n == 1.0001:  # c xⁿ changes by x^0.0001 ≈ 1 − 1e-3 over the contact: the onset by about as much
        assert depth == pytest.approx(pl.d_crit_A(68.75, PowerLaw(0.5, 1.0), paper, adhesion=True), rel=2e-2)
    radius = float(pl.contact_radius(depth, profile, paper, paper.dgamma0))
    assert depth / math.tan(math.radians(68.75)) == pytest.approx(float(analytic.critical_shift(radius, paper)),
                                                                 rel=1e-11)
    indentation = pl.d_crit_B_indentation([10.0, 30.0], profile, paper, adhesion=True)
    assert np.all(np.isfinite(indentation)) and np.all(indentation > paper.d_max)


def test_bad_angles_and_works_of_adhesion_are_named(paper):
    """As for the paraboloid's functions: angles in [0, 90] (a string or 100° refused), works of adhesion >= 0."""
    cone = PowerLaw.cone(0.1)
    with pytest.raises(ValueError, match=r"alpha=100.0 \(degrees\) is not allowed; allowed: finite angles in \[0, 90\]"):
        pl.d_crit_A(100.0, cone, paper)
    with pytest.raises(TypeError, match=r"alpha='20'"):
        pl.d_crit_B("20", cone, paper)
    with pytest.raises(ValueError, match=r"work_of_adhesion=-0.1 is not allowed; allowed: a finite number >= 0"):
        pl.pull_off_force(cone, paper, -0.1)
    with pytest.raises(TypeError, match=r"work_of_adhesion='0.1' \(str\) is not allowed"):
        pl.contact_radius(1e-4, cone, paper, "0.1")


def test_straight_down_never_slides_in_scenario_A(paper):
    """α = 90°: no tangential shift, +inf for every indenter (the closed forms gave 4e29 m and 3.7e12 m)."""
    for profile in (PowerLaw.paraboloid(paper.R), PowerLaw(2e3, 3.0), PowerLaw.cone(0.1), FlatPunch(1e-3)):
        for adhesion in (False, True):
            assert pl.d_crit_A(90.0, profile, paper, adhesion) == np.inf, (profile, adhesion)
