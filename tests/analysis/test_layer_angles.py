"""The critical angles against the layer's thickness (mdr_events.analysis.layer_angles): labelled, written and read
back, the half-space at ``h = inf``, scenario A's thin limit, bad input named."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.limits import Limits, ResourceLimitError

PAPER = me.Contact.paper()


@pytest.fixture(scope="module")
def angles():
    return me.critical_angles_against_thickness(PAPER, [2e-4, 5e-3, np.inf])


def test_the_half_space_column_is_the_papers(angles):
    half = angles.sel(thickness=np.inf)
    for scenario in ("A", "B", "B+"):
        assert float(half.critical_angle_jkr.sel(scenario=scenario)) == me.critical_angle(PAPER, scenario)
    assert float(half.critical_angle_hertz.sel(scenario="B")) == 90.0 and float(half.thin_limit_A) == 0.0


def test_the_thin_limit_column_is_g_d_max_over_tau0_h(angles):
    shear_modulus = PAPER.elastomer.E / (2.0 * (1.0 + PAPER.elastomer.nu))
    expected = math.degrees(math.atan(shear_modulus * 3e-4 / (PAPER.friction.tau0 * 2e-4)))
    assert float(angles.thin_limit_A.sel(thickness=2e-4)) == pytest.approx(expected, rel=1e-14)
    # at a/h ≈ 20 the layer's angle lies within ~5 % of the limit's tangent, above it (the edge's stiffer ring)
    layer = math.tan(math.radians(float(angles.critical_angle_jkr.sel(scenario="A", thickness=2e-4))))
    assert 1.0 < layer / math.tan(math.radians(expected)) < 1.1


def test_the_angles_are_labelled_and_read_back(angles, tmp_path):
    for name in ("critical_angle_jkr", "critical_angle_hertz", "thin_limit_A", "thickness"):
        assert angles[name].attrs["units"] and angles[name].attrs["long_name"]
    me.write_netcdf(angles, tmp_path / "angles.nc")
    back = me.open_result(tmp_path / "angles.nc")
    np.testing.assert_array_equal(back.critical_angle_jkr, angles.critical_angle_jkr)
    assert back.attrs["param_layer_base"] == "bonded" and "param_layer_thickness" not in back.attrs


@pytest.mark.parametrize("call, words", [
    (lambda: me.critical_angles_against_thickness(PAPER, [0.0]), "thicknesses=.* is not allowed"),
    (lambda: me.critical_angles_against_thickness(PAPER, [[1e-3]]), "one non-empty axis"),
    (lambda: me.critical_angles_against_thickness(PAPER, []), "one non-empty axis"),
    (lambda: me.critical_angles_against_thickness(PAPER.parameters(3e-4, 1e-3), [1e-3]), "contact=.*Contact"),
    (lambda: me.critical_angles_against_thickness(PAPER, [1e-3], d_max=math.nan), "d_max=nan"),
    (lambda: me.critical_angles_against_thickness(PAPER, np.linspace(1.0, 2.0, 10), limits=Limits(steps=1e4)),
     "10 thicknesses"),
])
def test_bad_input_is_named(call, words):
    with pytest.raises((ValueError, TypeError, ResourceLimitError), match=words):
        call()
