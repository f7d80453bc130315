"""The normal problem of a Contact on its layer as labelled results (issue 34): the half-space's JKR closed forms at
h = inf and h very large, the thin-layer limits of the pull-off derived from the Winkler and thin-film stiffness
(Δl and F_N minimised over a by hand: Winkler −2πRΔγ, thin film −3πRΔγ, against the half-space's −(3/2)πRΔγ),
and the force against the springs' integral F = ∫ k(x)(d − g(x)) dx with the varying stiffness density."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.theory import layer as L

PAPER = me.Contact.paper(0.03)
R, DGAMMA1 = 0.03, PAPER.adhesion.dgamma1
DEPTHS = np.linspace(-1.5e-4, 3e-4, 10)
#: At h = inf the curve's radius is a bisection to the ulp in ln a of the same relation (9) the closed form solves
#: as a quartic: agreement to a few 1e-12 (the quartic's own conditioning).
HALF_SPACE_TOL = 1e-10
#: h = 1 km: a/h ≈ 3e-6, the layer's first-order excess (2k(0)/π) a/h ≈ 2e-6 bounds the difference.
FAR_TOL = 1e-5
#: The thin limits approach at first order in h/a; at the thinnest layers here (a/h ≈ 19 for the thin film, 34 for
#: Winkler) the remainder is below these (the observed: 7 % and 0.5 %).
THIN_FILM_TOL, WINKLER_TOL = 0.1, 0.01
#: Gauss–Legendre with 80 nodes of the springs' integral against F₀ + K(d − g): the tables' 1e-8.
CONSISTENCY_TOL = 1e-8
#: 21 samples of the shrinking stage: the force is quadratic about its minimum, the nearest sample within 1e-2 of it.
SAMPLED_MINIMUM_TOL = 1e-2


def test_at_h_inf_the_branches_are_jkr_s():
    curve = me.layer_normal_curve(PAPER, DEPTHS)
    for branch, dgamma in (("dgamma0", PAPER.adhesion.dgamma0), ("dgamma1", DGAMMA1)):
        radius = curve.contact_radius.sel(branch=branch).values
        expected = me.jkr_contact_radius(DEPTHS, PAPER, dgamma)
        assert np.array_equal(np.isnan(radius), np.isnan(expected)) and np.isnan(radius).any()
        np.testing.assert_allclose(radius, expected, rtol=HALF_SPACE_TOL)
        inside = ~np.isnan(expected)
        np.testing.assert_allclose(curve.normal_force.sel(branch=branch).values[inside],
                                   me.jkr_normal_force(expected[inside], PAPER, dgamma), rtol=HALF_SPACE_TOL)
    for name, variable in curve.variables.items():
        assert variable.attrs["units"] and variable.attrs["long_name"], name
    assert me.Contact.from_attrs(curve.attrs) == PAPER and curve.attrs["param_layer_thickness"] == math.inf


def test_a_very_thick_layer_is_the_half_space_to_first_order():
    far = me.layer_normal_curve(PAPER.replace(h=1e3), DEPTHS).normal_force.values
    near = me.layer_normal_curve(PAPER, DEPTHS).normal_force.values
    inside = ~np.isnan(near)
    assert np.max(np.abs(far[inside] / near[inside] - 1)) < FAR_TOL
    po = me.layer_pull_off_curve(PAPER, [math.inf, 1e3]).pull_off_force.values
    assert po[0] == pytest.approx(-1.5 * math.pi * R * DGAMMA1, rel=1e-12)
    assert po[1] == pytest.approx(po[0], rel=FAR_TOL)


@pytest.mark.parametrize("nu, base, limit, tol", [(0.5, "bonded", 3.0, THIN_FILM_TOL),
                                                   (0.3, "bonded", 2.0, WINKLER_TOL),
                                                   (0.5, "frictionless", 2.0, WINKLER_TOL)])
def test_the_pull_off_approaches_the_thin_limits_from_the_half_space(nu, base, limit, tol):
    contact = PAPER.replace(nu=nu, **{"layer.base": base})
    curve = me.layer_pull_off_curve(contact, [math.inf, 1e-3, 1.6e-4, 4e-5, 1.2e-5])
    ratio = -curve.pull_off_force.values / (math.pi * R * DGAMMA1)
    print(f"({nu}, {base}): |F_po|/(pi R dgamma1) = {ratio}, a/h = {curve.relative_radius.values}")
    assert ratio[0] == pytest.approx(1.5, rel=1e-12)
    assert np.all(np.diff(ratio) > 0) and np.all(ratio < limit)  # (harder and harder, never beyond the limit)
    errors = limit - ratio[2:]
    assert np.all(errors[1:] < errors[:-1]) and errors[-1] / limit < tol


def test_the_force_is_the_springs_integral_on_each_stage_of_a_cycle():
    layer_contact = PAPER.replace(h=5e-3)
    cycle = me.layer_indentation_cycle(layer_contact, 3e-4, 21)
    nodes, weights = np.polynomial.legendre.leggauss(80)
    E_star, nu, layer = PAPER.elastomer.E_star, PAPER.elastomer.nu, layer_contact.layer
    for index in (10, 30, 50, 62):
        d, a = float(cycle.depth[index]), float(cycle.contact_radius[index])
        x, w = a * (nodes + 1) / 2, a * weights / 2
        springs = 2 * np.sum(w * L.spring_stiffness_density(x, E_star, nu, layer)
                             * (d - L.power_law_profile(x, PAPER.indenter, nu, layer)))
        assert float(cycle.normal_force[index]) == pytest.approx(springs, rel=CONSISTENCY_TOL)
    stages = list(dict.fromkeys(cycle.stage.values))
    assert stages == ["loading", "pinned", "shrinking"]
    pinned = cycle.contact_radius.values[cycle.stage.values == "pinned"]
    assert np.all(pinned == pinned[0])
    force_po = me.layer_pull_off_curve(layer_contact, [5e-3]).pull_off_force.values[0]
    least = float(cycle.normal_force.min())  # (the path passes the minimum, sampled: a little above it)
    assert force_po <= least < force_po * (1 - SAMPLED_MINIMUM_TOL)


def test_a_layer_pushes_and_pulls_harder_than_the_half_space():
    half, layer = (me.layer_indentation_cycle(c, 3e-4, 51) for c in (PAPER, PAPER.replace(h=5e-3)))
    assert float(layer.normal_force.max()) > float(half.normal_force.max())
    assert float(layer.normal_force.min()) < float(half.normal_force.min())


@pytest.mark.parametrize("call, words", [
    (lambda: me.layer_normal_curve(PAPER, [np.nan]), "depths="),
    (lambda: me.layer_normal_curve(PAPER.replace(h=1e-5), [3e-4]), "a/h = 64"),
    (lambda: me.layer_pull_off_curve(PAPER, [0.0]), "thicknesses="),
    (lambda: me.layer_indentation_cycle(PAPER, -1.0), "d_max=-1.0"),
    (lambda: me.layer_normal_curve(me.Contact(PAPER.elastomer, me.FlatPunch(1e-3)), [1e-4]), "contact.indenter="),
])
def test_bad_input_is_refused_in_one_line(call, words):
    with pytest.raises(ValueError) as caught:
        call()
    assert words in str(caught.value) and "allowed" in str(caught.value) and "\n" not in str(caught.value)


#: The relative accuracy of the argument of a flat minimum found by Brent's method (its value to eps, its argument to
#: about sqrt(eps)), times 4.
FLAT_MINIMUM_SHARE = 4.0 * math.sqrt(np.finfo(float).eps)


@pytest.mark.parametrize("h", [math.inf, 5e-3], ids=["half-space", "5 mm"])
def test_a_cycle_ends_at_the_jump_off_radius_whatever_the_last_ulp_of_its_inputs(h):
    """The cycle's last depth is the fold of the Δγ1 branch: its radius is the jump-off's (on the half-space the closed
    form, (π Δγ1 R²/(8 E*))^(1/3) for the paraboloid's MDR branch, to a few ulp), finite and the same when the inputs
    move by an ulp. A bisection at the fold gave it to ~sqrt(eps) on the half-space (2.3e-9 off the closed form) and
    nan on the layer when the rounding put the depth below the fold's: a figure's pixels moved between machines."""
    from mdr_events.theory.branches import jump_off

    contact = PAPER.replace(h=h)
    nudged = contact.replace(E=contact.elastomer.E + 3 * np.spacing(contact.elastomer.E))
    last = [float(L.layer_indentation_cycle(c, 3e-4, 41).contact_radius.values[-1]) for c in (contact, nudged)]
    assert all(math.isfinite(radius) for radius in last)
    # (on the half-space an ulp's move of the closed form; on a layer the jump-off radius is Brent's minimum of a flat
    # least depth, determined to sqrt(eps) of itself: FLAT_MINIMUM_SHARE. The fold's bisection gave nan there)
    assert last[1] == pytest.approx(last[0], rel=1e-14 if math.isinf(h) else FLAT_MINIMUM_SHARE)
    if math.isinf(h):
        params = contact.parameters(3e-4, 1e-4)
        closed = jump_off(params, contact.adhesion.dgamma1, None)["contact_radius"]
        assert last[0] == pytest.approx(closed, rel=8 * np.finfo(float).eps)
