"""The flat punch on a layer of finite thickness (issue 34): the generalized MDR's simplest case, in the discrete method.

Under the face ``f = 0``, so ``g = 0`` and ``F₀ = 0`` on any layer: ``F_N = K(a₀) d`` with the springs ``k = K'/2``
(``layer_flat_punch_force``), ``π κ a₀² d`` on Winkler's foundation; the face's edge lets go at
``d = −sqrt(4π a Δγ1/K'(a))`` (``layer_flat_punch_hess``), the half-space's Kendall pull-off at ``K' = 2E*``; where
``a/K'(a)`` falls (thin layers) the contact recedes under the face along that depth (``layer_flat_punch_recedes``).
The continuum runs it with ``τ0`` (:mod:`tests.models.test_layer_punch_continuum`) and refuses Coulomb's part there,
naming why and what runs it.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.theory.layer import hess_elongation, punch_stiffness, punch_stiffness_slope
from mdr_events.theory.layer_symbolic import derive_layer_model

#: The face's radius (m) and the depth pressed (m): a contact of a/h = 0.4 on the paper's 5 mm layer.
A0, D_MAX = 2e-3, 1e-5
PUNCH = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(A0))
VERTICAL = me.Scenario("A", alpha=[90.0], d_max=D_MAX)
#: Spacings of the convergence runs (m), each half the last, a₀ a whole number of each.
SPACINGS = (4e-5, 2e-5, 1e-5)
#: The springs' force at the deepest point is the midpoint rule of ``∫ k(x) dx d`` on cells whose outer edges are
#: ``±a₀`` (a smooth ``k``): second order, its error quartering per halving (measured 4.00 on this layer).
FORCE_ORDER, ORDER_SLACK = 2.0, 0.2
#: The pull-off force is met at the sample after the edge spring passes Heß's limit: the limit of the spring at
#: ``a₀ − Δx/2``, not ``a₀``: first order (measured ratios 2.0 per halving).
PULL_OFF_ORDER = 1.0
#: A receding sample's depth lies within one spacing's change of the branch of its radius (the springs let go one
#: spacing at a time), and this share of it beyond (the samples' rounding of the depth: 1e-4 of a step).
LAG_SLACK = 1e-3
#: ``K(a₀)/(2E*a₀) − 1`` is about ``2k(0)λ/π`` for ``λ = a₀/h → 0``: below this many ``λ`` (k(0) < π here).
SERIES_SLOPE = 2.0


def _run(contact: me.Contact, dx: float, **options):
    return me.simulate(contact, VERTICAL, "discrete", dx=dx, **options).isel(alpha=0)


def _deepest(run) -> tuple[float, float]:
    depth, force = run["indentation_depth"].values, run["normal_force"].values
    index = int(np.nanargmax(depth))
    return float(depth[index]), float(force[index])


def _order(errors) -> list[float]:
    return [math.log2(abs(coarse / fine)) for coarse, fine in zip(errors, errors[1:])]


def test_the_springs_press_with_the_layers_punch_stiffness_at_second_order():
    """F_N = K(a₀) d: the springs' k(x_j) Δx summed over the face, against the layer's punch stiffness (L2)."""
    layer = PUNCH.replace(h=5e-3)
    params = layer.parameters(D_MAX, me.Parameters.paper().v)
    K = float(punch_stiffness(A0, params.E_star, params.nu, layer.layer))
    errors = []
    for dx in SPACINGS:
        depth, force = _deepest(_run(layer, dx))
        errors.append(force / (K * depth) - 1.0)
    assert all(abs(order - FORCE_ORDER) <= ORDER_SLACK for order in _order(errors)), errors


def test_the_thick_layers_punch_comes_off_at_once_with_kendalls_force_on_the_layer_at_first_order():
    """On a layer where a/K'(a) rises with a (a/h = 0.2) the whole face lets go at d = −Δl(a₀): the least force is
    −K(a₀) Δl(a₀) (``layer_flat_punch_pull_off``), met at first order in Δx, and the radius never drops below the
    face's while in contact."""
    layer = PUNCH.replace(h=1e-2)
    params = layer.parameters(D_MAX, me.Parameters.paper().v)
    K = float(punch_stiffness(A0, params.E_star, params.nu, layer.layer))
    slope = float(punch_stiffness_slope(A0, params.E_star, params.nu, layer.layer))
    expected = float(derive_layer_model()["layer_flat_punch_pull_off"].numeric(K, A0, params.dgamma1, slope))
    assert expected == pytest.approx(-K * float(hess_elongation(A0, params.dgamma1, params.E_star, params.nu,
                                                                layer.layer)), rel=1e-12)
    errors = []
    for dx in SPACINGS:
        run = _run(layer, dx)
        errors.append(float(np.nanmin(run["normal_force"].values)) / expected - 1.0)
        radius = run["contact_radius"].values
        assert np.all(radius[radius > 0] == A0)
    assert all(abs(order - PULL_OFF_ORDER) <= ORDER_SLACK for order in _order(errors)), errors


def test_on_a_thin_layer_the_contact_recedes_under_the_face_along_hess_depth():
    """a/h = 2 (the paper's ν = 0.5): a/K'(a) falls, a K'' > K' (``layer_flat_punch_recedes``), so a contact smaller
    than the face holds further out: under depth control the radius shrinks from a₀ along d = −Δl(a), each sample's
    depth within the springs' first-order lag (one spacing of radius, the slope of Δl times Δx) of it."""
    layer = PUNCH.replace(h=1e-3)
    params = layer.parameters(D_MAX, me.Parameters.paper().v)
    slope = float(punch_stiffness_slope(A0, params.E_star, params.nu, layer.layer))
    second = (float(punch_stiffness_slope(A0 * (1 + 1e-4), params.E_star, params.nu, layer.layer))
              - float(punch_stiffness_slope(A0 * (1 - 1e-4), params.E_star, params.nu, layer.layer))) / (2e-4 * A0)
    assert float(derive_layer_model()["layer_flat_punch_recedes"].numeric(A0, slope, second)) > 0.0
    dx = SPACINGS[-1]
    run = _run(layer, dx)
    depth, radius = run["indentation_depth"].values, run["contact_radius"].values
    receding = (radius > 0) & (radius < A0 - 2 * dx)
    assert receding.sum() > 50  # (a hundred spacings of radius walked through)
    def branch(a):
        return -hess_elongation(a, params.dgamma1, params.E_star, params.nu, layer.layer)

    on_branch = branch(radius[receding])
    lag = np.abs(branch(radius[receding] + dx) - on_branch)  # (the branch's change over one spacing)
    assert np.all(np.abs(depth[receding] - on_branch) <= lag * (1.0 + LAG_SLACK))


def test_the_winkler_limit_is_pi_kappa_a0_squared_d_at_first_order_in_h_over_a():
    """A thin compressible bonded layer (ν = 0.3) is Winkler's foundation: F/(π κ a₀² d) − 1 → 0 as h/a₀ → 0, at first
    order (the edge's zone of width ~h), the springs' force on the table's K(a₀) d to the quadrature's error."""
    base = PUNCH.replace(nu=0.3)
    E, nu = base.elastomer.E, base.elastomer.nu
    G = E / (2.0 * (1.0 + nu))
    kappa_of = derive_layer_model()["layer_winkler_modulus"].numeric
    winkler = derive_layer_model()["layer_flat_punch_winkler_force"].numeric
    errors = []
    for lam in (8.0, 16.0, 32.0):
        h = A0 / lam
        depth, force = _deepest(_run(base.replace(h=h), 5e-6, n_steps=200))
        K = float(punch_stiffness(A0, base.elastomer.E_star, nu, base.replace(h=h).layer))
        assert force / (K * depth) == pytest.approx(1.0, abs=1e-5)  # (the springs: the table's stiffness)
        errors.append(force / float(winkler(depth, A0, kappa_of(G, nu, h))) - 1.0)
    assert all(error > 0 for error in errors)  # (the layer is stiffer than its Winkler limit at the edge)
    assert all(abs(order - 1.0) <= ORDER_SLACK for order in _order(errors)), errors


def test_a_thick_layers_punch_tends_to_the_half_spaces():
    """h → ∞: the springs' force and pull-off tend to the half-space flat punch's (2E* a₀ d, Kendall), the difference
    about 2k(0)λ/π at λ = a₀/h."""
    half = _run(PUNCH, SPACINGS[0])
    for h in (2.0, 20.0):
        layer = _run(PUNCH.replace(h=h), SPACINGS[0])
        lam = A0 / h
        ratio = _deepest(layer)[1] / _deepest(half)[1] - 1.0
        assert 0.0 < ratio <= SERIES_SLOPE * lam
        # (−K Δl = −2E*a Φ Δl∞/Θ(1): Φ/Θ(1) = 1 on the series, the pull-off's change of order λ² and the springs')
        pull = float(np.nanmin(layer["normal_force"].values)) / float(np.nanmin(half["normal_force"].values)) - 1.0
        assert abs(pull) <= SERIES_SLOPE * lam


SERIAL = me.Engine(scheduler="serial")


COULOMB = dataclasses.replace(PUNCH.replace(h=5e-3), friction=me.FrictionLaw("tau0+coulomb", tau0=42e3, mu=0.3))


def test_the_continuum_runs_coulombs_part_with_the_flat_punch_on_a_layer_spring_by_spring():
    """Refused before (the per-spring route read the layer's profile tabulated for a paraboloid or power law): it reads
    the punch's springs now (``g = 0`` under the face; :mod:`tests.models.test_layer_punch_coulomb` checks the
    values), and with ``μ = 0`` it is the spans' ``τ0`` run."""
    run = me.simulate(COULOMB, VERTICAL, "continuum").isel(alpha=0)
    spans = me.simulate(dataclasses.replace(COULOMB, friction=me.FrictionLaw("tau0", tau0=42e3)), VERTICAL,
                        "continuum", t=run["time"].values).isel(alpha=0)
    np.testing.assert_array_equal(run["normal_force"].values, spans["normal_force"].values)


def test_a_continuum_sweep_runs_the_flat_punch_over_the_thickness_as_simulate_does():
    swept = me.sweep({"h": [5e-3, math.inf]}, PUNCH, "A", 90.0, engine=SERIAL, quantities=("normal_force_min",))
    assert int(swept["failed"].sum()) == 0
    for h in (5e-3, math.inf):
        run = me.simulate(PUNCH.replace(h=h), me.Scenario("A", 90.0), "continuum").isel(alpha=0)
        assert float(swept["normal_force_min"].sel(h=h)) == float(run["normal_force_min"])


def test_a_discrete_sweep_runs_the_flat_punch_over_the_thickness_as_simulate_does():
    springs = me.Discrete(dx=5e-5, n_steps=1000)
    swept = me.sweep({"h": [5e-3, math.inf]}, PUNCH, "A", 90.0, springs, engine=SERIAL,
                     quantities=("normal_force_min",))
    assert int(swept["failed"].sum()) == 0
    for h in (5e-3, math.inf):
        run = me.simulate(PUNCH.replace(h=h), me.Scenario("A", 90.0), springs).isel(alpha=0)
        assert float(swept["normal_force_min"].sel(h=h)) == float(np.nanmin(run["normal_force"].values))


def test_a_sweeps_critical_angles_of_the_punch_on_a_layer_are_critical_angles():
    """The sweep's closed-form angles of the flat punch on a layer (``has_closed_forms``) are ``critical_angle``'s."""
    swept = me.sweep({"h": [2e-4, 5e-3]}, PUNCH, "B", 20.0, engine=SERIAL,
                     quantities=("critical_angle_A", "critical_angle_B"))
    for h in (2e-4, 5e-3):
        for scenario in ("A", "B"):
            expected = me.critical_angle(PUNCH.replace(h=h), scenario)
            assert float(swept[f"critical_angle_{scenario}"].sel(h=h)) == pytest.approx(expected, rel=1e-12)
