"""Tangential loading at a constant depth (theory.mindlin): the virgin curve against quadrature of the springs'
caps and against the Cattaneo–Mindlin closed form; Masing's rules with memory against an ensemble of play
operators stepped spring by spring; bad input named."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, optimize

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.theory import analytic, mindlin
from mdr_events.theory import power_law as pl
from mdr_events.theory import symbolic as S

DEPTH = 1e-4
#: quad's accuracy on the springs' integrals with their kink given as a break point
QUADRATURE_RTOL = 1e-10
LAWS = [FrictionLaw(), FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.2)]
PROFILES = [None, PowerLaw.cone(0.05), PowerLaw(40.0, 1.5), PowerLaw(2e5, 3.0), FlatPunch(1e-3)]


@pytest.fixture(scope="module")
def hertz():
    return me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)


def _radius_and_g(profile, params):
    if profile is None:
        profile = PowerLaw.paraboloid(params.R)
    if isinstance(profile, FlatPunch):
        return profile.radius, lambda xi: 0.0
    return float(pl.contact_radius(DEPTH, profile, params, 0.0)), lambda xi: float(pl.equivalent_profile(xi, profile))


def _springs_force(shift, friction, params, profile):
    """``2G* ∫_0^a min(s, K a + κ (d − g(ξ))) dξ``: the springs' caps integrated numerically."""
    a, g = _radius_and_g(profile, params)
    K = pl.cap_per_radius(params) if friction.uses_tau0 else 0.0
    kappa = friction.coulomb_mu * params.E_star / params.G_star
    if shift == 0.0:  # (no relative accuracy to ask of a zero integrand)
        return 0.0
    cap = lambda xi: K * a + kappa * (DEPTH - g(xi))  # noqa: E731
    # the kink where the caps pass the shift (the stick zone's edge), found by bisection, as quad's break point
    kink = [optimize.brentq(lambda xi: cap(xi) - shift, 0.0, a, xtol=1e-16 * a)] if cap(a) < shift < cap(0.0) else None
    value, _ = integrate.quad(lambda xi: min(shift, cap(xi)), 0.0, a, epsabs=0.0, epsrel=1e-12, limit=200,
                              points=kink)
    return 2.0 * params.G_star * value


def test_the_coulomb_cap_is_mu_times_the_normal_over_the_tangential_stiffness():
    rel = S.relation("coulomb_critical_shift")
    assert rel.numeric(2e-6, 0.3, 3e5, 2e5) == pytest.approx(0.3 * 3e5 / 2e5 * 2e-6, rel=1e-15)
    assert mindlin.coulomb_cap_ratio(FrictionLaw("coulomb", mu=0.3), me.Parameters.paper()) == pytest.approx(
        0.3 * me.Parameters.paper().E_star / me.Parameters.paper().G_star, rel=1e-15)
    assert mindlin.coulomb_cap_ratio(FrictionLaw(), me.Parameters.paper()) == 0.0


@pytest.mark.parametrize("friction", LAWS, ids=lambda f: f.law)
@pytest.mark.parametrize("profile", PROFILES, ids=lambda p: "paraboloid" if p is None else p.describe()[:24])
def test_virgin_curve_equals_the_springs_caps_integrated(hertz, friction, profile):
    """Every law and indenter: F₀(s) against quadrature of 2G* ∫ min(s, ū(ξ)) dξ from 0 past full slip."""
    full = mindlin.full_slip_shift(DEPTH, friction, hertz, profile)
    shifts = np.linspace(0.0, 1.3, 27) * full
    closed = mindlin.virgin_force(shifts, DEPTH, friction, hertz, profile)
    numeric = np.array([_springs_force(s, friction, hertz, profile) for s in shifts])
    np.testing.assert_allclose(closed, numeric, rtol=QUADRATURE_RTOL, atol=QUADRATURE_RTOL * numeric.max())
    np.testing.assert_allclose(mindlin.virgin_force(-shifts, DEPTH, friction, hertz, profile), -closed, rtol=0, atol=0)
    assert mindlin.full_slip_force(DEPTH, friction, hertz, profile) == pytest.approx(numeric[-1], rel=QUADRATURE_RTOL)


@pytest.mark.parametrize("n", [1.0, 1.5, 2.0, 3.0])
def test_cattaneo_mindlin_closed_form(hertz, n):
    """Coulomb's law on a power law: F = μ F_N (1 − (1 − s/s*)^((n+1)/n)), s* = μ E* d/G* (Cattaneo 1938, Mindlin
    1949 for the sphere, n = 2, exponent 3/2; F_N ∝ d^((n+1)/n) for the power law); the paraboloid's F_N is
    Hertz's (4/3) E* √R d^(3/2)."""
    friction = FrictionLaw("coulomb", mu=0.4)
    profile = pl.with_radius_at(n, 2e-3, DEPTH)
    full = 0.4 * hertz.E_star * DEPTH / hertz.G_star
    assert mindlin.full_slip_shift(DEPTH, friction, hertz, profile) == pytest.approx(full, rel=1e-15)
    normal = float(pl.normal_force(DEPTH, 2e-3, profile, hertz))
    shifts = np.linspace(0.0, 1.0, 41) * full
    expected = 0.4 * normal * (1.0 - (1.0 - shifts / full) ** ((n + 1.0) / n))
    np.testing.assert_allclose(mindlin.virgin_force(shifts, DEPTH, friction, hertz, profile), expected, rtol=0,
                               atol=1e-13 * 0.4 * normal)
    sphere = 4.0 / 3.0 * hertz.E_star * math.sqrt(hertz.R) * DEPTH**1.5
    assert mindlin.full_slip_force(DEPTH, friction, hertz) == pytest.approx(0.4 * sphere, rel=1e-14)


def test_tau0_and_coulomb_add(hertz):
    """Full slip of the combined law: τ0 π a² + μ F_N at the shift K a + κ d."""
    friction = FrictionLaw("tau0+coulomb", mu=0.2)
    a = math.sqrt(hertz.R * DEPTH)
    sphere = 4.0 / 3.0 * hertz.E_star * math.sqrt(hertz.R) * DEPTH**1.5
    assert mindlin.full_slip_force(DEPTH, friction, hertz) == pytest.approx(hertz.tau0 * math.pi * a**2 + 0.2 * sphere,
                                                                            rel=1e-14)
    assert mindlin.full_slip_shift(DEPTH, friction, hertz) == pytest.approx(
        math.pi * a * hertz.tau0 / (2 * hertz.G_star) + 0.2 * hertz.E_star * DEPTH / hertz.G_star, rel=1e-14)


#: Springs of the play-operator ensemble; its midpoint rule is second order, 1e-6 of the force at this count.
ENSEMBLE_SPRINGS = 4000
ENSEMBLE_RTOL = 1e-6


def _play_ensemble(x, friction, params, profile):
    """Each spring a play operator of its own cap, stepped sample by sample: ``u ← clip(u + Δx, −ū, ū)``."""
    a, g = _radius_and_g(profile, params)
    xi = (np.arange(ENSEMBLE_SPRINGS) + 0.5) * a / ENSEMBLE_SPRINGS
    K = pl.cap_per_radius(params) if friction.uses_tau0 else 0.0
    kappa = friction.coulomb_mu * params.E_star / params.G_star
    caps = K * a + kappa * (DEPTH - np.array([g(v) for v in xi]))
    shift, forces = np.zeros_like(xi), [0.0]
    for step in np.diff(x):
        shift = np.clip(shift + step, -caps, caps)
        forces.append(2.0 * params.G_star * shift.sum() * a / ENSEMBLE_SPRINGS)
    return np.array(forces)


@pytest.mark.parametrize("friction", LAWS[1:], ids=lambda f: f.law)
@pytest.mark.parametrize("profile", [None, PowerLaw.cone(0.05)], ids=["paraboloid", "cone"])
def test_masing_rules_with_memory_equal_an_ensemble_of_play_operators(hertz, friction, profile):
    """A fretting history with nested loops (each inner loop closed and forgotten where the motion passes its
    start, then the outer branch and the virgin curve resumed), sampled with its turning points."""
    full = mindlin.full_slip_shift(DEPTH, friction, hertz, profile)
    turns = np.array([0.0, 0.6, -0.3, 0.4, -0.1, 0.7, -0.8, 0.5, -0.5, 0.9, 1.2, -1.1]) * full
    x = np.concatenate([np.linspace(start, end, 40, endpoint=False) for start, end in zip(turns[:-1], turns[1:])]
                       + [turns[-1:]])
    closed = mindlin.tangential_force(x, DEPTH, friction, hertz, profile)
    ensemble = _play_ensemble(x, friction, hertz, profile)
    scale = mindlin.full_slip_force(DEPTH, friction, hertz, profile)
    np.testing.assert_allclose(closed, ensemble, rtol=0, atol=ENSEMBLE_RTOL * scale)
    # the memory at work: past 0.7 the branch from -0.1 has closed the loops back to the virgin curve
    beyond = np.flatnonzero((x > 0.65 * full) & (np.arange(x.size) < 5 * 40))
    np.testing.assert_allclose(closed[beyond], mindlin.virgin_force(x[beyond], DEPTH, friction, hertz, profile),
                               rtol=0, atol=1e-12 * scale)


def test_a_mindlin_loop_is_closed_and_symmetric(hertz):
    """0 → X → −X → X: the unloading branch ends at −F₀(X), the reloading one at F₀(X) (Mindlin & Deresiewicz)."""
    friction = FrictionLaw("coulomb", mu=0.3)
    X = 0.5 * mindlin.full_slip_shift(DEPTH, friction, hertz)
    x = np.concatenate([np.linspace(0, X, 50), np.linspace(X, -X, 100)[1:], np.linspace(-X, X, 100)[1:]])
    force = mindlin.tangential_force(x, DEPTH, friction, hertz)
    peak = mindlin.virgin_force(X, DEPTH, friction, hertz)
    assert force[49] == peak and force[148] == pytest.approx(-peak, rel=1e-14) and force[-1] == pytest.approx(peak, rel=1e-14)
    # the unloading branch F(X) − 2 F₀((X − x)/2)
    np.testing.assert_allclose(force[49:149], peak - 2 * mindlin.virgin_force((X - x[49:149]) / 2, DEPTH, friction, hertz),
                               rtol=0, atol=1e-15 * peak)


@pytest.mark.parametrize("call, exception, words", [
    (lambda p: mindlin.virgin_force(1e-6, DEPTH, "coulomb", p), ValueError, ["mu=None"]),
    (lambda p: mindlin.virgin_force(1e-6, 0.0, None, p), ValueError, ["depth=0.0", "> 0"]),
    (lambda p: mindlin.virgin_force([1e-6, math.nan], DEPTH, None, p), ValueError, ["shift=", "nan"]),
    (lambda p: mindlin.virgin_force(1e-6, DEPTH, None, me.Parameters.paper(), radius=1e-4), ValueError,
     ["radius=0.0001", "x_c"]),
    (lambda p: mindlin.tangential_force(np.zeros((2, 2)), DEPTH, None, p), ValueError, ["shape (2, 2)", "1-D"]),
    (lambda p: mindlin.tangential_force([0.0, math.inf], DEPTH, None, p), ValueError, ["finite"]),
    (lambda p: mindlin.virgin_force(1e-6, DEPTH, None, p, profile="cone"), TypeError, ["profile='cone'"]),
])
def test_bad_input_is_named(hertz, call, exception, words):
    with pytest.raises(exception) as caught:
        call(hertz)
    for word in words:
        assert word in str(caught.value)


def test_scenario_a_closed_forms_of_the_laws(hertz):
    """The angle of friction for Coulomb's law; the combined law's onset at its critical angle is d_max; the paper's
    law is power_law's (17); μ = 0 slides from first contact; α = 90° never."""
    coulomb, combined = FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.2)
    assert mindlin.critical_angle_A(coulomb, hertz) == pytest.approx(
        math.degrees(math.atan(hertz.G_star / (0.3 * hertz.E_star))), rel=1e-15)
    angle = mindlin.critical_angle_A(combined, hertz)
    assert mindlin.d_crit_A(angle, combined, hertz) == pytest.approx(hertz.d_max, rel=1e-12)
    tau0_angle = pl.critical_angle_A(PowerLaw.paraboloid(hertz.R), hertz, adhesion=False)
    assert 1 / math.tan(math.radians(angle)) == pytest.approx(1 / math.tan(math.radians(tau0_angle))
                                                              + 0.2 * hertz.E_star / hertz.G_star, rel=1e-13)
    alphas = np.array([10.0, 40.0, 89.0, 90.0])
    np.testing.assert_array_equal(mindlin.d_crit_A(alphas, None, hertz),
                                  pl.d_crit_A(alphas, PowerLaw.paraboloid(hertz.R), hertz))
    below, above = mindlin.d_crit_A([0.9 * mindlin.critical_angle_A(coulomb, hertz),
                                     1.1 * mindlin.critical_angle_A(coulomb, hertz)], coulomb, hertz)
    assert below == 0.0 and math.isnan(above)
    np.testing.assert_array_equal(mindlin.d_crit_A([30.0, 90.0], FrictionLaw("coulomb", mu=0.0), hertz), [0.0, np.inf])
    assert math.isinf(mindlin.d_crit_A(90.0, combined, hertz))


def test_scenario_b_closed_forms_of_the_laws(hertz):
    """Out at α: the edge (compression 0) slides first, so the combined law's onset is τ0's (20) and Coulomb's alone
    slides at once; further in, the "+" branch at α' and its critical angle, at which the onset is 2 d_max."""
    coulomb, combined = FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.2)
    alphas = np.array([10.0, 40.0, 70.0, 90.0])
    paraboloid = PowerLaw.paraboloid(hertz.R)
    np.testing.assert_array_equal(mindlin.d_crit_B(alphas, combined, hertz), pl.d_crit_B(alphas, paraboloid, hertz))
    np.testing.assert_array_equal(mindlin.d_crit_B(alphas, coulomb, hertz), [hertz.d_max] * 3 + [-np.inf])
    angle = mindlin.critical_angle_B_indentation(combined, hertz)
    assert mindlin.d_crit_B_indentation(angle, combined, hertz) == pytest.approx(2 * hertz.d_max, rel=1e-12)
    friction_angle = mindlin.critical_angle_B_indentation(coulomb, hertz)
    assert friction_angle == pytest.approx(mindlin.critical_angle_A(coulomb, hertz), rel=1e-15)
    below, above = mindlin.d_crit_B_indentation([0.99 * friction_angle, 1.01 * friction_angle], coulomb, hertz)
    assert below == hertz.d_max and math.isinf(above)
    np.testing.assert_array_equal(mindlin.d_crit_B_indentation(alphas, None, hertz),
                                  pl.d_crit_B_indentation(alphas, paraboloid, hertz))


def test_loop_energy(hertz):
    """τ0 alone: the parallelogram's 4 π a² τ0 (X − ū) beyond the stick range and 0 within it; Coulomb's law: the
    area between an ensemble of play operators' branches over the closed loop (its midpoint rule to 1e-5), growing
    as X³ for small loops (Mindlin & Deresiewicz: the slip annulus's width and the force both grow with X)."""
    a = math.sqrt(hertz.R * DEPTH)
    cap = pl.cap_per_radius(hertz) * a
    for X in (0.5 * cap, 2.0 * cap, 10.0 * cap):
        expected = analytic.fretting_dissipated_energy(a, X, hertz) if X > cap else 0.0
        assert mindlin.loop_energy(X, DEPTH, None, hertz) == pytest.approx(expected, rel=1e-10, abs=1e-25)
    coulomb = FrictionLaw("coulomb", mu=0.3)
    X = 0.4 * mindlin.full_slip_shift(DEPTH, coulomb, hertz)
    x = np.concatenate([np.linspace(0, X, 200), np.linspace(X, -X, 400)[1:], np.linspace(-X, X, 400)[1:],
                        np.linspace(X, -X, 400)[1:]])
    force = _play_ensemble(x, coulomb, hertz, None)
    cycle = slice(598, 1397)  # −X → X → −X: one full cycle of the closed loop, from the second reversal on
    work = float(np.trapezoid(force[cycle], x[cycle])) if hasattr(np, "trapezoid") else float(np.trapz(force[cycle],
                                                                                                         x[cycle]))
    assert mindlin.loop_energy(X, DEPTH, coulomb, hertz) == pytest.approx(work, rel=1e-4)
    small = mindlin.loop_energy(np.array([1e-3, 2e-3]) * X, DEPTH, coulomb, hertz)
    assert small[1] / small[0] == pytest.approx(8.0, rel=1e-2)
