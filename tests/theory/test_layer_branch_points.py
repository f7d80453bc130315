"""jump_off, jump_in_radius and pull_off_force take a contact on a layer (issue 34): the half-space's closed forms on
a 1e9 m layer (paraboloid and power law), the thin-film limit −3πΔγR of the pull-off, the pull-off of
layer_pull_off_curve and the branch of layer_normal_curve at the same thickness, and the refusals in one line.

The tables of (ν, base) = (0.5, bonded) and (0.5, frictionless) are read from the user's cache (built once).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory import analytic, power_law

#: Where the closed forms are the value itself (the least depth, the stable radius at d = 0 by 60 bisections, the
#: least force): the layer's own departure from the half-space at a/h ≈ 1e-12 (Φ − 1 ≈ 2k(0)(a/h)/π, the tables'
#: series below a/h = 1e-4) and round-off; a hundred times the 1e-12 of that departure.
SERIES_TOL = 1e-10
#: Where the value is read at the argument of a minimum (the jump-off's radius, and its force, linear in the radius
#: there): Brent's method at a flat minimum resolves ln a only to about sqrt(eps) = 1.5e-8 (the depth is quadratic
#: about it, d(a(1 + δ)) − d(a) ∝ δ², below an ulp of d for δ < sqrt(eps)); four times that.
FLAT_MINIMUM_TOL = 4.0 * math.sqrt(np.finfo(float).eps)
#: The thin-film limit's first-order Richardson extrapolation from a/h ≈ 40 and 51 leaves the second-order term
#: c₂ (h/a)₁ (h/a)₂: c₂ ≈ 2.4 from the change of (F/F_lim − 1)·a/h from a/h ≈ 24 to 51 (−1.365 to −1.416), so
#: ≈ 1.2e-3; two thirds as much again.
RICHARDSON_TOL = 2e-3
#: The observed order of the thin-film error in h/a at a/h ≈ 40–51: 1 (an edge boundary layer of width ~h), within the
#: 0.05 of tests/theory/test_layer_pull_off_limits.py (0.965 at this pair, the (h/a)² term still seen).
ORDER_TOL = 0.05

PAPER = me.Contact.paper()
FIVE_MM = PAPER.replace(h=5e-3)
POWER = dataclasses.replace(PAPER, indenter=me.PowerLaw(c=1.0, n=1.5))


def _close(value: float, reference: float, tol: float) -> bool:
    return abs(value / reference - 1.0) < tol


@pytest.mark.parametrize("base", ["bonded", "frictionless"])
@pytest.mark.parametrize("work", [PAPER.adhesion.dgamma0, PAPER.adhesion.dgamma1])
def test_a_very_thick_layer_gives_the_half_space_closed_forms_of_the_paraboloid(base, work):
    thick = PAPER.replace(h=1e9, **{"layer.base": base})
    point, reference = analytic.jump_off(thick, work), analytic.jump_off(PAPER, work)
    assert _close(point["depth"], reference["depth"], SERIES_TOL)
    assert _close(point["contact_radius"], reference["contact_radius"], FLAT_MINIMUM_TOL)
    assert _close(point["normal_force"], reference["normal_force"], FLAT_MINIMUM_TOL)
    assert _close(analytic.jump_in_radius(thick, work), analytic.jump_in_radius(PAPER, work), SERIES_TOL)
    assert _close(me.pull_off_force(thick, work), me.pull_off_force(PAPER, work), SERIES_TOL)


def test_a_very_thick_layer_gives_the_half_space_closed_forms_of_a_power_law():
    thick, work = POWER.replace(h=1e9), POWER.adhesion.dgamma1
    params = POWER.parameters(PAPER_D_MAX, PAPER_V)
    point, reference = me.jump_off(thick, work), power_law.jump_off(POWER.indenter, params, work)
    assert _close(point["depth"], reference["depth"], SERIES_TOL)
    assert _close(point["contact_radius"], reference["contact_radius"], FLAT_MINIMUM_TOL)
    assert _close(point["normal_force"], reference["normal_force"], FLAT_MINIMUM_TOL)
    assert _close(analytic.jump_in_radius(thick, work), power_law.jump_in_radius(POWER.indenter, params, work),
                  SERIES_TOL)
    assert _close(me.pull_off_force(thick, work), power_law.pull_off_force(POWER.indenter, params, work), SERIES_TOL)


def test_the_pull_off_on_a_thin_incompressible_bonded_layer_tends_to_three_pi_dgamma_r():
    work, R = PAPER.adhesion.dgamma1, PAPER.indenter.R
    limit = -3.0 * math.pi * work * R
    thicknesses = (2.870489461535399e-6, 1.8e-6)  # a/h ≈ 40 and 51 at pull-off
    forces = np.array([me.pull_off_force(PAPER.replace(h=h), work) for h in thicknesses])
    eps = np.array([float(me.layer_pull_off_curve(PAPER, [h]).relative_radius[0]) ** -1 for h in thicknesses])
    error = forces / limit - 1.0
    assert np.all(error < 0.0)  # from the half-space's −(3/2)πΔγR side
    assert abs(math.log(error[1] / error[0]) / math.log(eps[1] / eps[0]) - 1.0) < ORDER_TOL
    extrapolated = (eps[0] * forces[1] - eps[1] * forces[0]) / (eps[0] - eps[1])
    assert abs(extrapolated / limit - 1.0) < RICHARDSON_TOL


@pytest.mark.parametrize("contact", [FIVE_MM, FIVE_MM.replace(**{"layer.base": "frictionless"}), POWER.replace(h=5e-3)],
                         ids=["bonded", "frictionless", "power law"])
def test_the_points_are_those_of_the_layer_s_curves_at_the_same_thickness(contact):
    """The same relations at the same thickness: the same numbers, bit for bit; the cycle's last radius is bisected
    at the least depth, so that it agrees with the jump-off's to the flat minimum's resolution."""
    curve = me.layer_pull_off_curve(contact, [contact.layer.thickness])
    assert me.pull_off_force(contact, contact.adhesion.dgamma1) == float(curve.pull_off_force[0])
    branches = me.layer_normal_curve(contact, [0.0])
    assert analytic.jump_in_radius(contact, contact.adhesion.dgamma0) == float(branches.contact_radius[0, 0])
    cycle = me.layer_indentation_cycle(contact, 1e-4, samples=3)
    point = me.jump_off(contact, contact.adhesion.dgamma1)
    assert point["depth"] == float(cycle.depth[-1])
    assert point["contact_radius"] == pytest.approx(float(cycle.contact_radius[-1]), rel=FLAT_MINIMUM_TOL)
    assert point["normal_force"] == pytest.approx(float(cycle.normal_force[-1]), rel=FLAT_MINIMUM_TOL)


def test_the_five_mm_layer_pulls_off_harder_and_jumps_off_earlier_than_the_half_space():
    work = PAPER.adhesion.dgamma1
    assert me.pull_off_force(FIVE_MM, work) < me.pull_off_force(PAPER, work) < 0.0
    assert me.jump_off(FIVE_MM, work)["contact_radius"] < me.jump_off(PAPER, work)["contact_radius"]


def test_without_adhesion_each_point_is_the_first_touch():
    assert me.jump_off(FIVE_MM, 0.0) == {"contact_radius": 0.0, "depth": 0.0, "normal_force": 0.0}
    assert analytic.jump_in_radius(FIVE_MM, 0.0) == 0.0 and me.pull_off_force(FIVE_MM, 0.0) == 0.0


RATE = dataclasses.replace(FIVE_MM, adhesion=me.RateDependentAdhesion(0.01, 0.15, v_ref=1e-4, n=0.6))


@pytest.mark.parametrize("call, words", [
    (lambda f: f(dataclasses.replace(FIVE_MM, indenter=me.FlatPunch(1e-3)), 0.15), "contact.indenter=FlatPunch("),
    (lambda f: f(RATE, 0.15), "(RateDependentAdhesion) is not allowed in {name} on a layer"),
    (lambda f: f(PAPER.replace(h=1e-7), 0.15), "contact.layer=Layer(thickness=1e-07"),
    (lambda f: f(FIVE_MM.replace(R=1e-300), 0.15), "the half-space's radii overflow"),
], ids=["flat punch", "rate law", "beyond the tables", "scales"])
@pytest.mark.parametrize("function", [me.jump_off, analytic.jump_in_radius, me.pull_off_force],
                         ids=["jump_off", "jump_in_radius", "pull_off_force"])
def test_what_the_layer_does_not_take_is_refused_in_one_line_naming_it(call, words, function):
    with pytest.raises((TypeError, ValueError)) as caught:
        call(function)
    text = str(caught.value)
    assert words.format(name=function.__name__) in text and "allowed" in text and "\n" not in text


@pytest.mark.parametrize("name", ["layer_jump_off", "layer_jump_in_radius", "layer_pull_off_force"])
def test_the_layer_s_points_refuse_a_negative_work_naming_it(name):
    """(The analytic functions refuse it before they look at the layer; the layer's module on its own too.)"""
    from mdr_events.theory.layer import branch_points

    with pytest.raises(ValueError) as caught:
        getattr(branch_points, name)(FIVE_MM, -0.1)
    text = str(caught.value)
    assert text.startswith("work_of_adhesion=-0.1 is not allowed; allowed: a finite number >= 0") and "\n" not in text
