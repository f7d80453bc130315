"""What the continuum reads of a layer (issue 34): the relations of ``theory/layer_continuum_symbolic.py`` (derived
afresh, each checked there against the half-space's), the tables' factors for one float
(``theory/layer/scalar_factors.py``) against the tables themselves, and the layer's medium's springs (their measure
``K_t/(2G*)``, weight ``w = M'`` and cap ``π a² τ0/K_t``) against the theory's ``K_t``, ``k_t`` and cap.

Tolerances: the pure-Python pieces are the same splines as the tables' (SciPy's ``PPoly`` of the B-spline), so values
agree to rounding (:data:`ROUNDING`); the weight ``w = d(ξ Φ_t)/dξ`` differentiates the interpolated ``Φ_t`` while the
theory's ``k_t = G* Σ_t`` is tabulated from the punch's edge values, the two agreeing to the tables' accuracy (1e-8
checked on their values, the derivative an order less: :data:`SLOPE_ACCURACY`); a central difference of step
``1e-4 λ`` is exact to ``O(step²)`` (:data:`DIFFERENCE_ACCURACY`).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum.media import medium_of
from mdr_events.theory.layer import layer_table
from mdr_events.theory.layer.scalar_factors import NormalFactors, TangentialFactors, piece_index
from mdr_events.theory.layer.tangential_tables import tangential_table
from mdr_events.theory.layer_continuum_symbolic import CONTINUUM_KEYS, continuum_model_afresh, derive_continuum_model
from mdr_events.theory.layer_tangential import sliding_cap, tangential_punch_stiffness, tangential_spring_stiffness_density

#: The pure-Python evaluation against the tables' vectorised one (the same polynomials, summed otherwise).
ROUNDING = 1e-13
#: The weight from the interpolated ``Φ_t`` against the tabulated ``Σ_t``.
SLOPE_ACCURACY = 5e-8
#: A central difference of step ``1e-4`` of the variable against the exact slope (relative).
DIFFERENCE_ACCURACY = 1e-6
#: Radii across the tables: below ``LAMBDA_MIN`` (the series), through the nodes, to ``a/h = 60``.
RADII = np.geomspace(1e-9, 0.3, 97)
LAYER = me.Layer(5e-3)


def test_the_relations_are_derived_afresh_and_checked_against_the_half_space():
    assert set(continuum_model_afresh()) == set(CONTINUUM_KEYS) == set(derive_continuum_model())


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_the_normal_factors_for_one_float_are_the_tables(nu):
    factors, table = NormalFactors(nu, LAYER, 2.0), layer_table(nu, LAYER.base, 2.0)
    lam = RADII / LAYER.thickness
    edge = np.array([factors.edge_factor(a)[0] for a in RADII])
    profile = np.array([factors.profile_factor(a) for a in RADII])
    stiffness = np.array([factors.stiffness_factor(a) for a in RADII])
    np.testing.assert_allclose(edge, table.edge_factor(lam), rtol=ROUNDING)
    np.testing.assert_allclose(profile[:, 0], table.profile_factor(lam), rtol=ROUNDING)
    np.testing.assert_allclose(stiffness, table.stiffness_factor(lam), rtol=ROUNDING)
    inside = lam >= 1e-3  # (the tables' own slope below LAMBDA_MIN is a difference of the series)
    np.testing.assert_allclose(profile[inside, 1], table.profile_factor(lam[inside], derivative=True), rtol=1e-11,
                               atol=ROUNDING)
    theta, theta_slope, gamma, gamma_slope = factors.arrays(RADII)
    np.testing.assert_allclose(theta, edge, rtol=ROUNDING)
    np.testing.assert_allclose(gamma, profile[:, 0], rtol=ROUNDING)
    np.testing.assert_allclose(gamma_slope, profile[:, 1], rtol=1e-11, atol=ROUNDING)
    np.testing.assert_allclose(theta_slope, [factors.edge_factor(a)[1] for a in RADII], rtol=1e-11, atol=ROUNDING)


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_the_tangential_factor_for_one_float_is_the_tables_and_its_slope_its_derivative(nu):
    pair = derive_continuum_model()["layer_continuum_tangential_factor_pair"].scalar
    factors = TangentialFactors(nu, LAYER, pair)
    lam = RADII / LAYER.thickness
    values = np.array([factors.stiffness_factor(a) for a in RADII])
    np.testing.assert_allclose(values[:, 0], tangential_table(nu).stiffness_factor(lam), rtol=ROUNDING)
    step = 1e-4 * RADII
    above = np.array([factors.stiffness_factor(a)[0] for a in RADII + step])
    below = np.array([factors.stiffness_factor(a)[0] for a in RADII - step])
    difference = (above - below) / (2.0 * step / LAYER.thickness)
    inside = lam >= 1e-3  # (away from the series' seam at LAMBDA_MIN, whose slope jumps there)
    np.testing.assert_allclose(values[inside, 1], difference[inside], rtol=DIFFERENCE_ACCURACY, atol=1e-9)


@pytest.mark.parametrize("nu", [0.0, 0.5])
def test_the_layers_springs_are_the_theorys_k_t_and_their_cap_the_theorys(nu):
    contact = me.Contact.paper().replace(h=LAYER.thickness, nu=nu)
    params = contact.parameters(3e-4, 1e-4)
    medium = medium_of(params, contact.friction, None, contact.layer)
    K = math.pi * params.tau0 / (2.0 * params.G_star)  # (the half-space's cap per radius, (13))
    measure = np.array([medium.measure(0.0, a) for a in RADII])
    weight = np.array([medium.density(a) for a in RADII])
    cap = np.array([medium.shift(K, a) for a in RADII])
    np.testing.assert_allclose(measure, tangential_punch_stiffness(RADII, params.G_star, nu, contact.layer)
                               / (2.0 * params.G_star), rtol=ROUNDING)
    np.testing.assert_allclose(weight, tangential_spring_stiffness_density(RADII, params.G_star, nu, contact.layer)
                               / params.G_star, rtol=SLOPE_ACCURACY)
    np.testing.assert_allclose(cap, sliding_cap(RADII, params.tau0, params.G_star, nu, contact.layer), rtol=ROUNDING)
    np.testing.assert_allclose(medium.shift(K, RADII), cap, rtol=ROUNDING)  # (vectorised: the sliding fraction's)
    slope = np.array([medium.shift_slope(K, a) for a in RADII])
    step = 1e-4 * RADII
    difference = (np.array([medium.shift(K, a) for a in RADII + step])
                  - np.array([medium.shift(K, a) for a in RADII - step])) / (2.0 * step)
    inside = RADII / LAYER.thickness >= 1e-3
    np.testing.assert_allclose(slope[inside], difference[inside], rtol=DIFFERENCE_ACCURACY)
    # full slip: every spring at the cap carries K_t(a) ū(a) = π a² τ0 on any layer
    np.testing.assert_allclose(2.0 * params.G_star * measure * cap, math.pi * RADII**2 * params.tau0, rtol=ROUNDING)


def test_piece_index_is_the_clipped_search_and_a_float_reading_s_piece():
    """``piece_index`` (the tables' pieces located without ``np.clip``'s checks) gives ``np.clip``'s integers, shape
    and all, for points before the first break, on breaks, inside and beyond the last piece, arrays of any shape and
    one point; and each is the piece ``bisect`` gives one float (``LogColumn.value_and_slope``'s)."""
    import bisect

    rng = np.random.default_rng(3)
    breaks = np.sort(rng.uniform(-2.0, 2.0, 41))
    last = breaks.size - 2
    for points in (rng.uniform(-3.0, 3.0, 2000), breaks.copy(), rng.uniform(-3.0, 3.0, (4, 7)), np.array(0.25),
                   float(breaks[5]), -5.0, 5.0):
        found = piece_index(breaks, points, last)
        clipped = np.clip(np.searchsorted(breaks, points, side="right") - 1, 0, last)
        assert np.array_equal(found, clipped) and np.shape(found) == np.shape(clipped)
        scalar = [min(max(bisect.bisect_right(breaks.tolist(), s) - 1, 0), last) for s in np.ravel(points).tolist()]
        assert np.ravel(found).tolist() == scalar
