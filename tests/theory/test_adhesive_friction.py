"""Coulomb's law with adhesion (theory.symbolic.derive_adhesive_friction_model, theory.mindlin with ``radius``): the
compression boundary, the caps on both sides of it, the virgin curve of an adhesive contact against its springs
integrated numerically, Δγ's absence from Coulomb's part, full slip; and the discrete model converging to the closed
form at first order with Δγ0 = Δγ1, Δγ0 < Δγ1 and Δγ1 < Δγ0."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, optimize

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.theory import mindlin
from mdr_events.theory import power_law as pl
from mdr_events.theory import symbolic as S

DEPTH = 1e-4
#: quad's accuracy on the springs' integrals with their kinks given as break points
QUADRATURE_RTOL = 1e-10
#: a relation evaluated twice, or against another relation of the same quantity: rounding of a few operations
ROUNDING = 1e-13
COULOMB = FrictionLaw("coulomb", mu=0.3)
COMBINED = FrictionLaw("tau0+coulomb", mu=0.2)
#: (Δγ0, Δγ1) in J/m²: equal, the paper's Δγ0 < Δγ1, and Δγ1 < Δγ0
ADHESIONS = [(0.05, 0.05), (0.01, 0.15), (0.15, 0.01)]
PROFILES = [None, PowerLaw.cone(0.05), PowerLaw(2e5, 3.0)]


def _params(dgamma0, dgamma1, tau0=1e3):
    return me.Parameters.paper().replace(dgamma0=dgamma0, dgamma1=dgamma1, tau0=tau0)


def _indenter(profile, params):
    return PowerLaw.paraboloid(params.R) if profile is None else profile


def test_the_compression_boundary_is_the_non_adhesive_radius_and_moves_with_the_depth():
    """g(x_c) = d: x_c = sqrt(R d) for the paraboloid, (16) for any power law; dx_c/dd = 1/g'(x_c) against a central
    difference (its truncation error h² x_c''' ~ 1e-8 relative at h = 1e-4 d)."""
    params = _params(0.01, 0.15)
    boundary, rate = S.relation("compression_boundary"), S.relation("compression_boundary_rate")
    for profile in (PowerLaw.paraboloid(params.R), PowerLaw.cone(0.05), PowerLaw(2e5, 3.0)):
        x_c = float(boundary.numeric(DEPTH, profile.c, profile.n))
        assert float(pl.equivalent_profile(x_c, profile)) == pytest.approx(DEPTH, rel=ROUNDING)
        assert x_c == pytest.approx(float(pl.contact_radius(DEPTH, profile, params, 0.0)), rel=ROUNDING)
        h = 1e-4 * DEPTH
        difference = (float(boundary.numeric(DEPTH + h, profile.c, profile.n))
                      - float(boundary.numeric(DEPTH - h, profile.c, profile.n))) / (2 * h)
        assert float(rate.numeric(DEPTH, profile.c, profile.n)) == pytest.approx(difference, rel=1e-7)
    assert float(boundary.numeric(DEPTH, 1 / (2 * params.R), 2.0)) == pytest.approx(math.sqrt(params.R * DEPTH),
                                                                                    rel=ROUNDING)


def test_the_cap_is_continuous_at_the_boundary_and_the_tau0_part_beyond_it():
    """ū = K a + κ max(d − g, 0): K a + κ d at the centre, K a at x_c and over the tensile annulus (the springs of
    "coulomb" alone slide there with no shift)."""
    params = _params(0.01, 0.15)
    a = float(pl.contact_radius(DEPTH, PowerLaw.paraboloid(params.R), params, params.dgamma0))
    x_c = math.sqrt(params.R * DEPTH)
    cap = S.relation("adhesive_friction_cap")
    K = pl.cap_per_radius(params)
    kappa = 0.3 * params.E_star / params.G_star
    values = [float(cap.numeric(xi, DEPTH, a, params.tau0, 0.3, 1 / (2 * params.R), 2.0, params.E_star,
                                params.G_star)) for xi in (0.0, x_c, 0.5 * (x_c + a), a)]
    assert values[0] == pytest.approx(K * a + kappa * DEPTH, rel=ROUNDING)
    for value in values[1:]:
        assert value == pytest.approx(K * a, rel=ROUNDING)
    assert a > 1.05 * x_c  # the annulus is there (else the test could not tell the caps apart)


def _springs_force(shift, depth, a, friction, params, profile):
    """``2G* ∫_0^a min(s, K a + κ max(d − g(ξ), 0)) dξ``: the springs of an adhesive contact from rest, numerically."""
    indenter = _indenter(profile, params)
    g = lambda xi: float(pl.equivalent_profile(xi, indenter))  # noqa: E731
    K = pl.cap_per_radius(params) if friction.uses_tau0 else 0.0
    kappa = friction.coulomb_mu * params.E_star / params.G_star
    cap = lambda xi: K * a + kappa * max(depth - g(xi), 0.0)  # noqa: E731
    x_c = optimize.brentq(lambda xi: g(xi) - depth, 0.0, a, xtol=1e-16 * a)
    points = [x_c]
    if cap(x_c) < shift < cap(0.0):
        points.append(optimize.brentq(lambda xi: cap(xi) - shift, 0.0, x_c, xtol=1e-16 * a))
    value, _ = integrate.quad(lambda xi: min(shift, cap(xi)), 0.0, a, epsabs=0.0, epsrel=1e-12, limit=200,
                              points=sorted(points))
    return 2.0 * params.G_star * value


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
@pytest.mark.parametrize("profile", PROFILES, ids=["paraboloid", "cone", "n3"])
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=["equal", "paper", "reversed"])
def test_the_adhesive_virgin_curve_equals_the_springs_caps_integrated(friction, profile, adhesion):
    params = _params(*adhesion)
    a = float(pl.contact_radius(DEPTH, _indenter(profile, params), params, params.dgamma0))
    full = mindlin.full_slip_shift(DEPTH, friction, params, profile)
    for share in (0.05, 0.3, 0.7, 0.99, 1.5):
        shift = share * full
        expected = _springs_force(shift, DEPTH, a, friction, params, profile)
        assert mindlin.virgin_force(shift, DEPTH, friction, params, profile) == pytest.approx(expected,
                                                                                             rel=QUADRATURE_RTOL)


@pytest.mark.parametrize("profile", PROFILES, ids=["paraboloid", "cone", "n3"])
def test_coulombs_part_does_not_depend_on_the_work_of_adhesion(profile):
    """"coulomb" alone: the same curve with any Δγ and any radius (bit for bit: the compressed zone is the
    non-adhesive contact of the depth); the combined law is τ0's 2G* a min(u, K a) plus that curve at u − K a."""
    hertz = _params(0.0, 0.0)
    shifts = np.linspace(-2.0, 2.0, 41) * mindlin.full_slip_shift(DEPTH, COULOMB, hertz, profile)
    reference = mindlin.virgin_force(shifts, DEPTH, COULOMB, hertz, profile)
    for adhesion in ADHESIONS:
        params = _params(*adhesion)
        np.testing.assert_array_equal(mindlin.virgin_force(shifts, DEPTH, COULOMB, params, profile), reference)
        a = float(pl.contact_radius(DEPTH, _indenter(profile, params), params, params.dgamma1))
        np.testing.assert_array_equal(mindlin.virgin_force(shifts, DEPTH, COULOMB, params, profile, radius=a),
                                      reference)
    params = _params(0.01, 0.15)
    a = float(pl.contact_radius(DEPTH, _indenter(profile, params), params, params.dgamma0))
    K = pl.cap_per_radius(params)
    beyond = np.sign(shifts) * np.maximum(np.abs(shifts) - K * a, 0.0)  # what the Coulomb caps see beyond K a
    expected = 2 * params.G_star * a * np.sign(shifts) * np.minimum(np.abs(shifts), K * a) + mindlin.virgin_force(
        beyond, DEPTH, FrictionLaw("coulomb", mu=COMBINED.mu), hertz, profile)
    np.testing.assert_allclose(mindlin.virgin_force(shifts, DEPTH, COMBINED, params, profile), expected, rtol=0,
                               atol=ROUNDING * mindlin.full_slip_force(DEPTH, COMBINED, params, profile))


def test_full_slip_is_tau0_times_the_area_and_mu_times_the_compressed_springs_push():
    """τ0 π a² + μ F_N^H(d) against JKR's numbers: F_N^H = 4 E* sqrt(R) d^{3/2}/3 = F_N(d, a) + the tensile springs'
    pull, 2 E* ∫_{x_c}^a (g − d) (quadrature); the symbolic relation and theory.mindlin agree."""
    params = _params(0.01, 0.15)
    a = float(pl.contact_radius(DEPTH, PowerLaw.paraboloid(params.R), params, params.dgamma0))
    hertz_force = 4 * params.E_star * math.sqrt(params.R) * DEPTH**1.5 / 3
    c = 1 / (2 * params.R)
    assert float(S.relation("compressed_normal_force").numeric(DEPTH, c, 2.0, params.E_star)) == pytest.approx(
        hertz_force, rel=ROUNDING)
    pull, _ = integrate.quad(lambda xi: xi**2 / params.R - DEPTH, math.sqrt(params.R * DEPTH), a, epsabs=0.0,
                             epsrel=1e-13)
    normal = float(S.relation("power_law_normal_force").numeric(DEPTH, a, c, 2.0, params.E_star))
    assert normal + 2 * params.E_star * pull == pytest.approx(hertz_force, rel=QUADRATURE_RTOL)
    expected = params.tau0 * math.pi * a**2 + 0.2 * hertz_force
    assert float(S.relation("adhesive_full_slip_force").numeric(DEPTH, a, params.tau0, 0.2, c, 2.0,
                                                               params.E_star)) == pytest.approx(expected, rel=ROUNDING)
    assert mindlin.full_slip_force(DEPTH, COMBINED, params) == pytest.approx(expected, rel=ROUNDING)
    assert mindlin.full_slip_force(DEPTH, COULOMB, params) == pytest.approx(0.3 * hertz_force, rel=ROUNDING)
    assert mindlin.full_slip_force(DEPTH, COULOMB, params) > 0.3 * normal * 1.005  # not μ F_N (1 % above it)


#: Depths of the discrete runs (shares of DEPTH): the springs' radius is off by up to Δx/2 by a share that depends on
#: where it falls between springs; the largest over several depths shows the first order.
DISCRETE_DEPTHS = (1.0, 1.07, 1.15, 1.22)


def _fretting_path(depth, friction, params, deeper):
    """In vertically to ``deeper`` (> depth: the radius pinned by the history, or on the Δγ1 branch), out to
    ``depth``, then 0 → 0.8 X → −0.8 X → 0.5 X → −0.3 X → 1.5 X along x (X the full-slip shift)."""
    X = 1.2 * mindlin.full_slip_shift(deeper, friction, params)  # (the shift of the largest radius, and beyond)
    turns = np.array([0.0, 0.8, -0.8, 0.5, -0.3, 1.5]) * X
    return me.Path(np.array([(0.0, -1e-6), (0.0, deeper)] + [(x, depth) for x in turns]), speed=1e-6)


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=["equal", "paper", "reversed"])
def test_the_discrete_model_converges_to_the_adhesive_closed_form_at_first_order(friction, adhesion):
    """The springs at Δx = 4, 2, 1 µm (dt = Δx/(2v)) against Masing's rules on the adhesive virgin curve at the
    contact radius the history pins (the continuum's "tau0" run of the same path, exact for the radius: the
    friction law does not move it), on their own samples at the depth: the largest difference falls at first order
    (observed order > 0.8) and stays within the first-order bound of the radius's quantisation."""
    params = _params(*adhesion)
    depths = [share * DEPTH for share in DISCRETE_DEPTHS]
    paths = [_fretting_path(depth, friction, params, 1.5 * depth) for depth in depths]
    radii = []
    for path, depth in zip(paths, depths):
        corners = path.corner_times - path.first_contact_time()
        exact = me.simulate(params, path, method="continuum", t=[corners[2], corners[-1]])
        radii.append(float(exact["contact_radius"].values[0, 0]))
        assert exact["contact_radius"].values[0, 1] == radii[-1]  # pinned through the fretting
    spacings = (4e-6, 2e-6, 1e-6)
    errors = []
    for dx in spacings:
        run = me.simulate(params, paths, dx=dx, dt=0.5 * dx / 1e-6, friction=friction)
        largest = 0.0
        for case, (depth, radius) in enumerate(zip(depths, radii)):
            held = (run["indentation_depth"].values[case] == depth) & (run["time"].values >= paths[case].corner_times[2]
                                                                       - paths[case].first_contact_time())
            x = run["tangential_displacement"].values[case][held]
            expected = mindlin.tangential_force(np.concatenate([[0.0], x]), depth, friction, params,
                                                radius=radius)[1:]
            difference = np.max(np.abs(run["tangential_force"].values[case][held] - expected))
            largest = max(largest, difference / mindlin.full_slip_force(depth, friction, params, radius=radius))
        errors.append(largest)
    assert observed_orders(spacings[::2], errors[::2])[0] > 0.8, errors
    radius = math.sqrt(params.R * DEPTH)
    assert np.all(np.array(errors) <= 1.5 * np.array(spacings) / radius), errors


@pytest.mark.parametrize("profile", PROFILES, ids=["paraboloid", "cone", "n3"])
def test_a_piece_laid_along_the_adhesive_branch_turns_where_derived(profile):
    """``Z = r d0(ξ) − σ g(ξ)`` (a piece of anchors laid along the Δγ0 branch, as the cap σ = ±κ sees it in the compressed
    zone; the groundwork of "tau0+coulomb" with adhesion): its slope ``r d0' − σ g'`` (the derived slopes of (9) with
    and without adhesion) vanishes at ``adhesive_seen_piece_turn`` and changes sign there where ``r/(r − σ) > 0``;
    where ``r/(r − σ) < 0`` it keeps its sign (no turn)."""
    params = _params(0.01, 0.15)
    indenter = _indenter(profile, params)
    kappa = mindlin.coulomb_cap_ratio(COULOMB, params)
    slope = S.relation("power_law_depth_slope")

    def seen_slope(xi, r, sigma):
        d0 = float(slope.numeric(xi, indenter.c, indenter.n, params.E_star, params.dgamma0))
        g = float(slope.numeric(xi, indenter.c, indenter.n, params.E_star, 0.0))
        return r * d0 - sigma * g, abs(r * d0) + abs(sigma * g)

    turn = S.relation("adhesive_seen_piece_turn")
    for r, sigma in ((2.0 * kappa, kappa), (-0.5 * kappa, kappa), (3.0 * kappa, -kappa)):
        xi = float(turn.numeric(r, sigma, params.dgamma0, indenter.c, indenter.n, params.E_star))
        value, size = seen_slope(xi, r, sigma)
        assert abs(value) < 1e-12 * size, (r, sigma, xi)
        below, above = seen_slope(xi * (1 - 1e-3), r, sigma)[0], seen_slope(xi * (1 + 1e-3), r, sigma)[0]
        assert below * above < 0, (r, sigma)
    signs = {np.sign(seen_slope(xi, 0.5 * kappa, kappa)[0]) for xi in np.geomspace(1e-7, 1e-2, 200)}
    assert len(signs) == 1  # r/(r − σ) = −1: no turn
