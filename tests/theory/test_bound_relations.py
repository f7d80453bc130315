"""``Relation.bound_numeric`` and ``bound_coefficients``: a relation's NumPy forms with a model's constants fixed once
(the continuum's branches read them at every fill) give ``numeric``'s and ``coefficients``' values bit for bit, Python
numbers converted as ``numeric`` converts them, and refuse a wrong count of arguments naming the relation."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.theory import symbolic

PAPER = me.Parameters.paper()
CONSTANTS = (PAPER.R, PAPER.E_star, PAPER.dgamma0)


@pytest.mark.parametrize("key", ["jkr_depth", "jkr_depth_integral", "jkr_depth_slope"])
def test_a_bound_relation_is_numeric_bit_for_bit(key):
    relation = symbolic.relation(key)
    radii = np.geomspace(1e-7, 1e-2, 97)
    bound = relation.bound_numeric(*CONSTANTS)
    np.testing.assert_array_equal(bound(radii), relation.numeric(radii, *CONSTANTS))
    assert bound(1e-4) == relation.numeric(1e-4, *CONSTANTS)
    # (a Python 0 as NumPy's: a division by it is inf or nan, not ZeroDivisionError, as numeric gives it)
    with np.errstate(divide="ignore", invalid="ignore"):
        np.testing.assert_array_equal(relation.bound_numeric(PAPER.R, PAPER.E_star, 0)(radii),
                                      relation.numeric(radii, PAPER.R, PAPER.E_star, 0))


def test_bound_coefficients_are_the_coefficients_bit_for_bit():
    relation = symbolic.relation("jkr_radius_quartic")
    depths = np.linspace(-2e-5, 3e-4, 101)
    found, expected = relation.bound_coefficients(*CONSTANTS)(depths), relation.coefficients(depths, *CONSTANTS)
    assert len(found) == len(expected)
    for got, want in zip(found, expected):
        np.testing.assert_array_equal(got, want)


def test_a_wrong_count_of_arguments_is_refused_naming_the_relation():
    bound = symbolic.relation("jkr_depth").bound_numeric(*CONSTANTS)
    with pytest.raises(TypeError, match="jkr_depth: expected 1 arguments"):
        bound(1e-4, 2e-4)
    with pytest.raises(TypeError, match="jkr_depth: expected at most 4 arguments"):
        symbolic.relation("jkr_depth").bound_numeric(*CONSTANTS, 1.0, 2.0)
