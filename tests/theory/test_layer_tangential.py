"""Tangential contact on a layer (issue 34, item 3): the compliance against its SymPy derivation, the punch's
Nyström solve against an independent solve of the coupled pair, its convergence, the half-space and thin-layer limits,
the springs and caps, and the refusals.

The table of ν = 0.5 is read from the user's cache (built once, about 10 s); the rest solves directly at few points.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.theory import layer as L
from mdr_events.theory import layer_tangential as T
from mdr_events.theory import layer_tangential_symbolic as S
from mdr_events.theory.layer import tangential_punch as TP
from mdr_events.theory.layer import tangential_tables as TT

#: The half-space through the layer's functions: the same formulas with factors exactly 1 (or 1 + O(a/h) at
#: a/h = 1e-14), so a few ulps.
ROUND_OFF = 8 * np.finfo(float).eps
#: The closed forms evaluated against SymPy's exponential forms (round-off amplified by e^{4t} cancellations).
SYMBOLIC_TOL = 1e-12
#: Default nodes against 64 more: spectral convergence, the remainder conditioning times round-off (1e-13 seen).
NODES_TOL = 1e-10
#: The decoupled pair (T2)–(T3) against the coupled pair solved as one system: the same discretisation, round-off.
COUPLED_TOL = 1e-11
#: The edge identity d(λΦ_t)/dλ = Σ_t against a central difference of step 1e-4 (truncation ~1e-8·Φ''').
EDGE_TOL = 1e-7
#: The table's quintic splines against direct solves at mid-points: the issue's 1e-8 (about 2e-9 reached).
TABLE_TOL = 1e-8
#: The thin limit K_t → π a² G/h: the issue's 1e-6 for the extrapolated ratio (Richardson in 1/λ three times, λ = 10 ... 80: about 7e-7 at ν = 0.5).
THIN_TOL = 1e-6
#: The observed order of the thin limit's error in h/a: 1 (an edge boundary layer of width ~h), within this.
ORDER_TOL = 0.06

#: The top's displacement under the solved traction, by direct Hankel quadrature, against the contact condition
#: (U₀ = u₀, U₂ = 0 inside the punch): the quadratures converge to round-off (at most 2e-15 seen; sums of some 4000
#: terms of order 1), and the Nyström solution is exact to ~1e-13 (NODES_TOL's margin).
DISPLACEMENT_TOL = 1e-12
#: What a wrong order-2 step leaves in the displacement: at least 1e-3 in the cases below (1.3e-3 the smallest seen,
#: roles of L and T swapped at ν = 0, a/h = 0.3); far above DISPLACEMENT_TOL.
WRONG_STEP = 1e-4
#: Where the contact condition is checked (r/a), the edge included closely.
RHO = np.array([0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999])

G, NU = 1.0e5, 0.5
G_STAR = 4.0 * G / (2.0 - NU)
E_STAR = 2.0 * G / (1.0 - NU)


def test_the_compliances_are_those_derived_in_sympy():
    rels = S.derive_tangential_model()
    t = np.array([0.05, 0.7, 2.0, 6.0])
    for nu in (0.0, 0.3, 0.5):
        for mode in T.MODES:
            for base in ("bonded", "frictionless"):
                derived = rels[f"layer_compliance_{mode}_{base}"].numeric(t, nu)
                np.testing.assert_allclose(T.tangential_compliance(t, nu, mode, base), derived, rtol=SYMBOLIC_TOL)
        c_zz = (1 - nu) * L.compliance_function(t, nu)
        c_xx = (1 - nu) * T.tangential_compliance(t, nu, "longitudinal")
        ratio = np.abs(rels["layer_coupling_bonded"].numeric(t, nu)) / np.sqrt(c_zz * c_xx)
        np.testing.assert_allclose(T.coupling_ratio(t, nu), ratio, rtol=1e-10)


def test_the_coupling_s_limits_and_bound():
    for nu in (0.0, 0.2, 0.5):
        assert T.coupling_ratio(1e3, nu) == pytest.approx((1 - 2 * nu) / (2 * (1 - nu)), abs=1e-15)
    assert T.coupling_ratio(0.0, 0.5) == pytest.approx(math.sqrt(3) / 2, rel=1e-15)
    assert T.coupling_ratio(1e-4, 0.5) == pytest.approx(math.sqrt(3) / 2, rel=1e-7)
    assert T.coupling_bound(0.0) == pytest.approx(0.5, rel=1e-12)  # the half-space's, reached as t → ∞
    assert T.coupling_bound(0.5) == pytest.approx(math.sqrt(3) / 2, rel=1e-9)
    assert T.coupling_bound(0.45) > 0.1 / 1.1  # above the half-space's (1 − 2ν)/(2(1 − ν))


def test_the_half_space_is_exact():
    a = np.array([1e-4, 3e-3, 0.2])
    np.testing.assert_array_equal(T.tangential_punch_stiffness(a, G_STAR, NU, HALF_SPACE), 2 * G_STAR * a)
    np.testing.assert_array_equal(T.tangential_spring_stiffness_density(a, G_STAR, NU, HALF_SPACE), G_STAR)
    tau0 = 4.2e4
    np.testing.assert_allclose(T.sliding_cap(a, tau0, G_STAR, NU, HALF_SPACE), np.pi * a * tau0 / (2 * G_STAR),
                               rtol=ROUND_OFF)  # (13)
    d, g, mu = 3e-4, np.array([0.0, 1e-4, 2e-4]), 0.4
    np.testing.assert_allclose(T.coulomb_cap(a, d, g, mu, E_STAR, G_STAR, NU, HALF_SPACE),
                               mu * E_STAR / G_STAR * (d - g), rtol=ROUND_OFF)
    thick = Layer(1e16)  # a/h ≤ 2e-17: the table's series 1 + O(a/h), below round-off
    np.testing.assert_allclose(T.sliding_cap(a, tau0, G_STAR, NU, thick), np.pi * a * tau0 / (2 * G_STAR),
                               rtol=ROUND_OFF)
    np.testing.assert_allclose(T.tangential_punch_stiffness(a, G_STAR, NU, thick), 2 * G_STAR * a, rtol=ROUND_OFF)
    rels = S.derive_tangential_model()
    assert rels["layer_tangential_half_space_stiffness"].numeric(1.0, G, NU) == pytest.approx(2 * G_STAR, rel=1e-15)
    assert T.solve_tangential_punch(0.0, NU).stiffness_factor == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize("lam,coarse", [(0.6, 2), (5.0, 8), (20.0, 24)])
def test_nystrom_converges_spectrally(lam, coarse):
    ref = T.solve_tangential_punch(lam, NU, nodes=L.nystrom_nodes(lam) + 64)
    got = T.solve_tangential_punch(lam, NU)
    assert got.stiffness_factor == pytest.approx(ref.stiffness_factor, rel=NODES_TOL)
    assert got.slope_factor == pytest.approx(ref.slope_factor, rel=NODES_TOL)
    errors = [abs(T.solve_tangential_punch(lam, NU, nodes=n).stiffness_factor / ref.stiffness_factor - 1)
              for n in (coarse, 2 * coarse)]
    assert errors[1] < errors[0] ** 1.5  # faster than any power: doubling the nodes squares the error or so


@pytest.mark.parametrize("nu,lam", [(0.0, 0.7), (0.3, 3.0), (0.5, 12.0)])
def test_the_decoupled_pair_is_the_coupled_pair(nu, lam):
    """Solve (Θ₀, X, b) of the order-0 and order-2 equations as one system with ∫X = 0, as derived, and compare."""
    n = L.nystrom_nodes(lam)
    sigma, weights = np.polynomial.legendre.leggauss(n)
    sigma, weights = (sigma + 1) / 2, weights / 2
    ops = {}
    for mode in T.MODES:
        k = T.tangential_kernel
        ops[mode] = (lam / np.pi) * weights * (k(lam * (sigma[:, None] - sigma), nu, mode)
                                               + k(lam * (sigma[:, None] + sigma), nu, mode))
    s, eye = 2 - nu, np.eye(n)
    diag = s * eye - ((1 - nu) * ops["longitudinal"] + ops["transverse"])
    off = nu * eye + ((1 - nu) * ops["longitudinal"] - ops["transverse"])
    matrix = np.zeros((2 * n + 1, 2 * n + 1))
    matrix[:n, :n], matrix[:n, n:2 * n] = diag, off
    matrix[n:2 * n, :n], matrix[n:2 * n, n:2 * n], matrix[n:2 * n, -1] = off, diag, -1.0
    matrix[-1, n:2 * n] = weights
    rhs = np.concatenate([np.full(n, s), np.zeros(n + 1)])
    solution = np.linalg.solve(matrix, rhs)
    coupled = float(weights @ solution[:n])
    assert coupled == pytest.approx(T.solve_tangential_punch(lam, nu).stiffness_factor, rel=COUPLED_TOL)


@pytest.mark.parametrize("lam", [0.5, 3.0])
def test_the_slope_is_the_edge_identity(lam):
    step = 1e-4

    def force(value):
        return value * T.solve_tangential_punch(value, NU).stiffness_factor

    difference = (force(lam + step) - force(lam - step)) / (2 * step)
    assert difference == pytest.approx(T.solve_tangential_punch(lam, NU).slope_factor, rel=EDGE_TOL)


def test_the_table_interpolates_direct_solves():
    table = T.tangential_table(NU)
    grid = TT._table_grid()
    for s in grid[[3, 40, 90, 111]] + T.TABLE_STEP / 2:
        lam = math.exp(s)
        direct = T.solve_tangential_punch(lam, NU)
        assert table.stiffness_factor(lam) == pytest.approx(direct.stiffness_factor, rel=TABLE_TOL)
        assert table.slope_factor(lam) == pytest.approx(direct.slope_factor, rel=TABLE_TOL)
    a, layer = 4e-3, Layer(5e-3)
    x, w = np.polynomial.legendre.leggauss(40)
    springs = 2 * np.sum(w * a / 2 * T.tangential_spring_stiffness_density(a * (x + 1) / 2, G_STAR, NU, layer))
    assert springs == pytest.approx(float(T.tangential_punch_stiffness(a, G_STAR, NU, layer)), rel=TABLE_TOL)


@pytest.mark.parametrize("nu", [0.0, 0.5])
def test_the_thin_layer_is_a_winkler_foundation_in_shear(nu):
    rels = S.derive_tangential_model()
    lams = np.array([10.0, 20.0, 40.0, 80.0])
    g_star = 4.0 / (2.0 - nu)  # G = h = 1: K_t = 2G* a Φ_t with a = λ
    winkler = rels["layer_shear_winkler_stiffness"].numeric(lams, 1.0, 1.0)
    ratio = np.array([2 * g_star * lam * T.solve_tangential_punch(lam, nu).stiffness_factor for lam in lams]) / winkler
    errors = ratio - 1.0
    orders = np.log2(errors[:-1] / errors[1:])
    assert abs(orders[-1] - 1.0) < ORDER_TOL
    once = 2 * ratio[1:] - ratio[:-1]  # Richardson in 1/λ, three times (the errors fall as 1/λ, 1/λ², 1/λ³)
    twice = (4 * once[1:] - once[:-1]) / 3
    thrice = (8 * twice[1:] - twice[:-1]) / 7
    assert abs(thrice[-1] - 1.0) < THIN_TOL


def test_the_caps_give_the_fully_sliding_forces():
    layer, a, tau0 = Layer(5e-3), 3e-3, 4.2e4
    cap = T.sliding_cap(a, tau0, G_STAR, NU, layer)
    assert float(T.tangential_punch_stiffness(a, G_STAR, NU, layer) * cap) == pytest.approx(np.pi * a**2 * tau0,
                                                                                            rel=ROUND_OFF)
    assert cap > np.pi * a * tau0 / (2 * G_STAR) * 0.5 and cap < np.pi * a * tau0 / (2 * G_STAR)  # stiffer layer
    x, d, g, mu = np.array([0.0, 1e-3, 2.5e-3]), 3e-4, np.array([0.0, 5e-5, 2e-4]), 0.3
    caps = T.coulomb_cap(x, d, g, mu, E_STAR, G_STAR, NU, layer)
    forces = T.tangential_spring_stiffness_density(x, G_STAR, NU, layer) * caps
    np.testing.assert_allclose(forces, mu * L.spring_stiffness_density(x, E_STAR, NU, layer) * (d - g), rtol=1e-14)


def test_bad_input_is_refused_in_one_line():
    frictionless = Layer(5e-3, "frictionless")
    cases = [(lambda: Layer(0.0), "Layer.thickness"), (lambda: Layer(-1.0), "Layer.thickness"),
             (lambda: T.tangential_punch_stiffness(1e-3, G_STAR, NU, frictionless), "Layer.base='frictionless'"),
             (lambda: T.solve_tangential_punch(1.0, NU, "frictionless"), "Layer.base='frictionless'"),
             (lambda: T.tangential_punch_stiffness(1e-3, G_STAR, 0.6, Layer(1e-2)), "nu=0.6"),
             (lambda: T.tangential_compliance(1.0, -0.1, "transverse"), "nu=-0.1"),
             (lambda: T.tangential_compliance(1.0, 0.3, "sideways"), "mode='sideways'"),
             (lambda: T.solve_tangential_punch(-1.0, NU), "lam=-1.0"),
             (lambda: T.sliding_cap(1e-3, -1.0, G_STAR, NU, HALF_SPACE), "tau0=-1.0"),
             (lambda: T.tangential_punch_stiffness(1.0, G_STAR, NU, Layer(1e-3)), "a/h=1000.0")]
    for call, named in cases:
        with pytest.raises(ValueError) as caught:
            call()
        message = str(caught.value)
        assert named in message and "allowed" in message and "\n" not in message, message
    with pytest.raises(TypeError, match="allowed: a Layer"):
        T.tangential_punch_stiffness(1e-3, G_STAR, NU, 5e-3)
    assert not T.solve_tangential_punch(0.0, NU).lam  # the half-space needs no base
    assert np.all(T.tangential_compliance(np.array([0.01, 0.1]), 0.3, "transverse", "frictionless") > 9.0)


def _condition_error(solution):
    u0, u2 = T.contact_displacement(solution, RHO)
    return max(np.max(np.abs(u0 - 1.0)), np.max(np.abs(u2)))


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
@pytest.mark.parametrize("lam", [0.3, 1.0, 3.0])
def test_the_solved_traction_moves_the_contact_uniformly(nu, lam):
    """The check of the reduction (T2) without it: Hankel quadrature of (T1) under the traction of Θ₀ and X."""
    solution = T.solve_tangential_punch(lam, nu)
    assert _condition_error(solution) < DISPLACEMENT_TOL
    tau, weights = np.polynomial.legendre.leggauss(200)
    theta0, chi = solution.traction_functions((tau + 1) / 2)
    assert abs(weights @ chi / 2) < DISPLACEMENT_TOL  # ∫X = 0: Q₂ vanishes outside the punch
    assert weights @ theta0 / 2 == pytest.approx(solution.stiffness_factor, rel=DISPLACEMENT_TOL)  # F_x, (T3)


@pytest.mark.parametrize("wrong", ["roles of L and T swapped", "sign of the order-2 part"])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
@pytest.mark.parametrize("lam", [0.3, 3.0])
def test_the_displacement_check_sees_a_wrong_order_2_step(monkeypatch, wrong, nu, lam):
    right = TP._order_functions

    def perturbed(nu_, phi_l, phi_t, modes):
        if wrong == "roles of L and T swapped":
            return right(nu_, phi_t, phi_l, modes[..., ::-1])
        theta0, chi = right(nu_, phi_l, phi_t, modes)
        return theta0, -chi

    monkeypatch.setattr(TP, "_order_functions", perturbed)
    assert _condition_error(T.solve_tangential_punch(lam, nu)) > WRONG_STEP


def test_the_displacement_check_on_the_half_space_and_bad_input():
    u0, u2 = T.contact_displacement(T.solve_tangential_punch(0.0, NU), RHO)
    np.testing.assert_allclose(u0, 1.0, rtol=ROUND_OFF)
    np.testing.assert_allclose(u2, 0.0, atol=ROUND_OFF)
    with pytest.raises(ValueError, match=re.escape("rho[1]=1.0 is not allowed")):
        T.contact_displacement(T.solve_tangential_punch(1.0, NU), [0.5, 1.0])
