"""The springs of a bonded layer read in one evaluation of the tables (:mod:`mdr_events.theory.layer.spring_factors`):
the relations' values bit for bit, on the tables and on their series below ``LAMBDA_MIN``."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.indenters import Paraboloid, PowerLaw
from mdr_events.contact.layer import Layer
from mdr_events.theory.layer import LAMBDA_MAX, LAMBDA_MIN, power_law_profile, spring_stiffness_density
from mdr_events.theory.layer.spring_factors import SpringFactors
from mdr_events.theory.layer_tangential import tangential_spring_stiffness_density

PAPER = me.Parameters.paper()
#: Coordinates as shares of the thickness: log-uniform from far below the tables' LAMBDA_MIN (their series) to
#: LAMBDA_MAX, both ends, the centre, and negative ones (the relations are even in x).
SHARES = np.concatenate([np.exp(np.random.default_rng(34).uniform(np.log(1e-9), np.log(LAMBDA_MAX), 400)),
                         [0.0, LAMBDA_MIN, np.nextafter(LAMBDA_MIN, 0.0), LAMBDA_MAX], [-0.3, -2e-6]])
#: The two readings do the same arithmetic, but NumPy's vectorised ``log``/``exp`` may take another SIMD path on a
#: block of six columns than on one (bit for bit on the AVX-512 machine results/ was made on; elsewhere each may move
#: by the functions' documented error, under 4 ulp): a factor is a product of at most two such readings and a
#: polynomial of one, so 16 ulp bounds the difference; a wrong column or formula moves them by far more.
ROUTE_RTOL = 16 * np.finfo(float).eps


@pytest.mark.parametrize("profile", [Paraboloid(PAPER.R), PowerLaw(2e3, 3.0)], ids=["paraboloid", "cubic"])
@pytest.mark.parametrize("nu", [PAPER.nu, 0.3])
def test_the_springs_are_the_relations_to_round_off(profile, nu):
    """``g``, ``k`` and ``k_t`` of one evaluation are :func:`power_law_profile`, :func:`spring_stiffness_density` and
    :func:`tangential_spring_stiffness_density` to round-off (:data:`ROUTE_RTOL`; here bit for bit), at every
    coordinate: the per-spring route's results do not move with the faster reading."""
    layer = Layer(5e-3)
    x = SHARES * layer.thickness
    springs = SpringFactors(profile, PAPER.E_star, PAPER.G_star, nu, layer).values(x)
    assert np.count_nonzero(np.abs(x) < LAMBDA_MIN * layer.thickness) >= 50  # (the series are tested)
    np.testing.assert_allclose(springs.profile, power_law_profile(x, profile, nu, layer), rtol=ROUTE_RTOL, atol=0.0)
    np.testing.assert_allclose(springs.normal, spring_stiffness_density(x, PAPER.E_star, nu, layer), rtol=ROUTE_RTOL, atol=0.0)
    np.testing.assert_allclose(springs.tangential, tangential_spring_stiffness_density(x, PAPER.G_star, nu, layer), rtol=ROUTE_RTOL, atol=0.0)


@pytest.mark.parametrize("layer", [Layer(), Layer(5e-3, "frictionless")], ids=["half-space", "frictionless"])
def test_a_body_without_tables_or_tangential_springs_is_refused(layer):
    with pytest.raises(ValueError, match=r"layer=.* is not allowed; allowed: a layer of finite thickness on a bonded"):
        SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, PAPER.nu, layer)


@pytest.mark.parametrize("share", [1e-9, 0.5 * LAMBDA_MIN, 0.3], ids=["far-below", "below", "tables"])
@pytest.mark.parametrize("kind", [float, np.float64, np.asarray], ids=["float", "float64", "0-d"])
def test_a_scalar_coordinate_is_a_one_element_array(share, kind):
    """A float, an ``np.float64`` or a 0-d array, below :data:`LAMBDA_MIN` (the tables' series) or on the tables,
    gives a 0-d ``g``, ``k`` and ``k_t`` equal bit for bit to a one-element array's, which are the relations' to
    round-off (:data:`ROUTE_RTOL`): a scalar below ``LAMBDA_MIN`` once raised a ``TypeError`` (the series written
    into a NumPy scalar)."""
    layer = Layer(5e-3)
    x = share * layer.thickness
    factors = SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, PAPER.nu, layer)
    springs, row = factors.values(kind(x)), factors.values(np.array([x]))
    relations = (power_law_profile(x, Paraboloid(PAPER.R), PAPER.nu, layer),
                 spring_stiffness_density(x, PAPER.E_star, PAPER.nu, layer),
                 tangential_spring_stiffness_density(x, PAPER.G_star, PAPER.nu, layer))
    for value, one, relation in zip(springs, row, relations):
        assert np.shape(value) == () and np.shape(one) == (1,)
        assert value == one[0]
        np.testing.assert_allclose(value, relation, rtol=ROUTE_RTOL, atol=0.0)
