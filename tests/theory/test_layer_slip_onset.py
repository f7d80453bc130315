"""Slip onset on a layer (mdr_events.theory.layer.slip_onset): eqs. (17)–(21) with the layer's cap ``π a² τ0/K_t``
and branches, through the public ``d_crit``, ``critical_angle`` and ``phase_diagram``.

Checked against the half-space's closed forms (a layer 1e9 m thick), the thin bonded layer's limit derived in SymPy
(``ū → τ0 h/G``: first order in ``h``), and each other (the critical angle's onset is at ``d_max``)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.slip_onset import thin_layer_onset_depth

PAPER = me.Contact.paper()
#: The half-space as a layer: ``a/h ≈ 4e-12``, the tables' series ``1 + O(a/h)`` below 1e-11.
THICK = PAPER.replace(h=1e9)
#: The paper's experiment: a 5 mm layer on a rigid base (bonded).
FIVE_MM = PAPER.replace(h=5e-3)
ANGLES = np.array([0.0, 5.0, 10.0, 20.0, 30.0, 60.0])
#: Roots found by bisection to round-off and a tables' series at ``a/h ≈ 4e-12``: 1e-9 relative covers both with
#: room (observed ~1e-12).
ROOT_TOLERANCE = 1e-9
#: Scenario B's critical angle lies at the jump-off, a flat minimum of ``d(a)`` found by Brent's method: its ``ln a``
#: is known to ``sqrt(eps) |ln a|`` (~1e-7), and ``r = (d_max − d)/ū`` changes with ``a`` at first order through
#: ``ū`` (``d ln ū/d ln a ≈ 1``): 1e-7 relative in ``tan α_c``.
FLAT_MINIMUM_TOLERANCE = 1e-7


@pytest.mark.parametrize("scenario, adhesion, branch", [("A", False, None), ("A", True, None),
                                                        ("B", False, "pull-off"), ("B", True, "pull-off"),
                                                        ("B", False, "indentation"), ("B", True, "indentation")])
def test_a_thick_layer_has_the_half_spaces_onsets(scenario, adhesion, branch):
    on_layer = me.d_crit(ANGLES, THICK, scenario, adhesion, branch)
    half_space = me.d_crit(ANGLES, PAPER, scenario, adhesion, branch)
    np.testing.assert_allclose(on_layer, half_space, rtol=ROOT_TOLERANCE, atol=0.0)


@pytest.mark.parametrize("scenario, adhesion", [("A", True), ("A", False), ("B+", True), ("B+", False)])
def test_a_thick_layer_has_the_half_spaces_critical_angles(scenario, adhesion):
    on_layer = me.critical_angle(THICK, scenario, adhesion)
    half_space = me.critical_angle(PAPER, scenario, adhesion)
    assert math.tan(math.radians(on_layer)) == pytest.approx(math.tan(math.radians(half_space)), rel=ROOT_TOLERANCE)


def test_a_thick_layer_has_the_half_spaces_pull_off_critical_angle():
    on_layer, half_space = me.critical_angle(THICK, "B"), me.critical_angle(PAPER, "B")
    assert math.tan(math.radians(on_layer)) == pytest.approx(math.tan(math.radians(half_space)),
                                                             rel=FLAT_MINIMUM_TOLERANCE)
    assert me.critical_angle(THICK, "B", adhesion=False) == 90.0


@pytest.mark.parametrize("nu", [0.3, 0.5])
def test_the_critical_angle_tends_to_the_thin_layers_at_first_order(nu):
    """``tan α_c → d_max/ū_thin`` with ``ū_thin = τ0 h/G`` (SymPy): errors halve with ``h`` (observed order 1)."""
    contact = PAPER.replace(nu=nu)
    errors = []
    for h in (4e-4, 2e-4, 1e-4):  # a ≈ 4 mm at d_max: a/h from 10 to 40
        layer = contact.replace(h=h)
        thin = thin_layer_onset_depth(45.0, layer)  # ū_thin (tan 45° = 1)
        errors.append(math.tan(math.radians(me.critical_angle(layer, "A"))) * thin / 3e-4 - 1.0)
    orders = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert all(0.9 < order < 1.2 for order in orders), orders
    # Richardson: the first-order part removed leaves O(h²) ~ errors[-1]²
    assert abs(2.0 * errors[-1] - errors[-2]) < 2.0 * errors[-1] ** 2 + 1e-3


def test_the_thin_limit_is_the_derived_relation():
    layer = PAPER.replace(nu=0.3, h=1e-4)
    shear_modulus = layer.elastomer.E / (2.0 * 1.3)
    expected = math.tan(math.radians(30.0)) * layer.friction.tau0 * 1e-4 / shear_modulus
    assert thin_layer_onset_depth(30.0, layer) == pytest.approx(expected, rel=1e-15)
    assert thin_layer_onset_depth(90.0, layer) == math.inf
    with pytest.raises(ValueError, match="a layer of finite thickness"):
        thin_layer_onset_depth(30.0, PAPER)


@pytest.mark.parametrize("h", [5e-3, 2e-3])
def test_at_the_critical_angle_scenario_a_slides_at_d_max(h):
    contact = PAPER.replace(h=h)
    for adhesion in (False, True):
        angle = me.critical_angle(contact, "A", adhesion)
        assert me.d_crit(angle, contact, "A", adhesion) == pytest.approx(3e-4, rel=ROOT_TOLERANCE)
    angle = me.critical_angle(contact, "B+", True, final_depth=5e-4)
    assert me.d_crit(angle, contact, "B", True, "indentation") == pytest.approx(5e-4, rel=ROOT_TOLERANCE)


def test_scenario_b_comes_apart_first_above_its_critical_angle():
    angle = me.critical_angle(FIVE_MM, "B")
    jump_off = float(me.phase_diagram(FIVE_MM, [10.0], scenario="B").jump_off_depth)
    below, above = me.d_crit([angle - 0.01, angle + 0.01], FIVE_MM, "B", True)
    assert jump_off < below < 3e-4 and above == -math.inf


def test_the_onsets_move_with_the_angle_as_the_paths_do():
    depths = me.d_crit(ANGLES, FIVE_MM, "A", True)
    assert depths[0] == 0.0 and np.all(np.diff(depths) > 0.0)
    pulled = me.d_crit(ANGLES, FIVE_MM, "B", True)
    assert pulled[0] == pytest.approx(3e-4, rel=ROOT_TOLERANCE) and np.all(np.diff(pulled) < 0.0)
    assert me.d_crit(90.0, FIVE_MM, "A") == math.inf and me.d_crit(90.0, FIVE_MM, "B") == -math.inf


def test_a_thinner_layer_needs_a_steeper_path_to_slide():
    """The cap ``π a² τ0/K_t`` grows as the layer shears more easily: the critical angle rises as ``h`` falls."""
    angles = [me.critical_angle(PAPER.replace(h=h), "A") for h in (1e9, 2e-2, 5e-3, 1e-3)]
    assert np.all(np.diff(angles) > 0.0), angles


def test_the_phase_diagram_on_a_layer_is_made_of_its_onsets():
    diagram = me.phase_diagram(FIVE_MM, ANGLES, scenario="B")
    np.testing.assert_array_equal(diagram.d_crit_jkr.sel(branch="pull-off"), me.d_crit(ANGLES, FIVE_MM, "B", True))
    assert float(diagram.critical_angle_jkr) == me.critical_angle(FIVE_MM, "B")
    assert diagram.attrs["param_layer_thickness"] == 5e-3
    steep = me.phase_diagram(PAPER.replace(h=1e-4), [10.0, 89.0], scenario="A")
    assert np.isfinite(steep.d_crit_jkr[0]) and np.isnan(steep.d_crit_jkr[1])  # (beyond the tables: marked)


@pytest.mark.parametrize("call, words", [
    (lambda: me.d_crit(89.0, PAPER.replace(h=1e-4), "A", True), r"alpha=89.0 is not allowed .* a/h = 64"),
    (lambda: me.d_crit(10.0, dataclasses.replace(PAPER, layer=Layer(5e-3, "frictionless"))), "frictionless"),
    (lambda: me.critical_angle(dataclasses.replace(FIVE_MM, friction=me.FrictionLaw("coulomb", mu=0.5))), "'tau0' of eq. \\(13\\)"),
    (lambda: me.d_crit(10.0, FIVE_MM, "A", branch="pull-off"), "branch='pull-off' is not allowed"),
    (lambda: me.critical_angle(FIVE_MM, "B+", final_depth=1e-4), "final_depth"),
    (lambda: me.d_crit(10.0, FIVE_MM, d_max=-1.0), "d_max=-1.0"),
])
def test_what_the_layers_onsets_refuse_is_named(call, words):
    with pytest.raises((ValueError, TypeError), match=words):
        call()
