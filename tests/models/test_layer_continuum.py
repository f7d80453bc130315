"""The continuum on a layer of finite thickness (issue 34): the springs' stiffness varying with ``ξ``
(``mdr_events.models.continuum.media``) gives the half-space as ``h → ∞``, the layer's closed normal curve, full
sliding at ``π a² τ0``, the layer's slip-onset depths, and the discrete model on the layer converges to it at first
order in ``Δx``. Before issue 34's continuum on a layer each of these runs was refused (``check_half_space``).

Tolerances, each from how the compared values are computed:

- the thick layer (``h = 1e9 m``) differs from the half-space by its factors' ``O(k(0) a/h)`` (the tables' series
  ``Φ = 1/(1 − 2k(0)λ/π)``: ``a/h < 1e-11``) and by the two runs' own integration, each to ``rtol = 1e-10`` with
  steps of their own: :data:`LIMIT_SHARE` is ten ``rtol``; their events are located to the same ``rtol`` of the
  run's duration (:data:`EVENT_SHARE` a hundred);
- the closed normal curve inverts the branch by bisection to the last ulp of ``ln a``, the continuum by Newton to
  ``radius_rtol = 1e-14``, from the same tables: :data:`CURVE_SHARE` of the largest force;
- the slip onset: the theory's onset depth is a root found to 1e-13 of itself and the continuum's an event located to
  ``4 eps`` of its variable (:data:`ONSET_SHARE`);
- the algebraic force ``2G* ∫ w clip(x − Y, −ū, ū) dξ`` (adaptive quadrature to 1e-12) against the integrated one
  (``rtol = 1e-10``, ``atol = 1e-14`` N): :data:`FORCE_SHARE` of the largest force.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences, observed_orders
from mdr_events.models.continuum import algebraic_tangential_force, evaluate, solve_path
from mdr_events.models.continuum.layer_media import FrictionlessLayerMedium, LayerMedium
from mdr_events.models.continuum.media import HalfSpaceMedium, medium_of
from mdr_events.theory.layer import layer_normal_curve

PAPER = me.Contact.paper()
#: The integrator's relative tolerance of every run here (the default ``Tolerances().rtol``).
RTOL = me.Tolerances().rtol
#: The thick layer against the half-space, relative to each quantity's largest magnitude: ten ``rtol``.
LIMIT_SHARE = 10.0 * RTOL
#: The events of the thick layer against the half-space's, relative to the run's duration.
EVENT_SHARE = 100.0 * RTOL
#: The continuum's normal force and radius against the closed curve's (relative to the largest).
CURVE_SHARE = 1e-10
#: The continuum's slip-onset depth against the layer's eq. (18)/(21), relative.
ONSET_SHARE = 1e-10
#: The integrated tangential force against the algebraic one, relative to the largest force.
FORCE_SHARE = 100.0 * RTOL
#: The observed order of a first-order error from three halving spacings (20 to 80 springs per radius at d_max: the
#: second-order terms move it by at most about 0.15, as on the half-space and in tests/models/test_layer_discrete.py).
ORDER_RANGE = (0.8, 1.3)
#: The same of a second-order error: without adhesion the edge spring carries ``d − g(a) = 0``, so the radius's
#: ``O(Δx)`` error moves ``F_N`` by ``K'(a)(d − g(a)) δa = 0`` at first order (tests/models/test_layer_discrete.py).
SECOND_ORDER_RANGE = (1.7, 2.3)
#: The spacings of the convergence study (m): 20, 40 and 80 springs per radius at a/h ~ 0.5–2.
SPACINGS = (4e-5, 2e-5, 1e-5)


def fretting(amplitude: float = 20e-6, cycles: int = 2) -> me.Paths:
    """In to the paper's ``d_max``, ``cycles`` tangential cycles of ``±amplitude`` there, and out."""
    d_max, speed = me.Parameters.paper().d_max, me.Parameters.paper().v
    x = np.concatenate([[0.0, 0.0], np.tile([amplitude, -amplitude], cycles), [0.0, 0.0]])
    d = np.concatenate([[-1e-6, d_max], np.full(2 * cycles, d_max), [d_max, -1e-4]])
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), speed)})


MOTIONS = {"A 20°, 60°": me.Scenario("A", alpha=[20.0, 60.0]), "B 20°, 70°": me.Scenario("B", alpha=[20.0, 70.0]),
           "fretting": fretting()}


def test_the_medium_is_looked_up_by_the_body():
    params = PAPER.parameters(3e-4, 1e-4)
    assert isinstance(medium_of(params, PAPER.friction, None), HalfSpaceMedium)
    assert type(medium_of(params, PAPER.friction, None, me.Layer(5e-3))) is LayerMedium
    assert type(medium_of(params, PAPER.friction, None, me.Layer(5e-3, "frictionless"))) is FrictionlessLayerMedium


@pytest.mark.parametrize("motion", MOTIONS.values(), ids=MOTIONS.keys())
def test_a_thick_layer_is_the_half_space_continuum(motion):
    thick = me.simulate(PAPER.replace(h=1e9), motion, "continuum")
    half = me.simulate(PAPER, motion, "continuum", t=thick["time"].values)
    for name in ("normal_force", "tangential_force", "contact_radius"):
        layer, exact = thick[name].values, half[name].values
        assert np.nanmax(np.abs(layer - exact)) <= LIMIT_SHARE * np.nanmax(np.abs(exact)), name
    np.testing.assert_array_equal(thick["event_kind"].values, half["event_kind"].values)
    duration = float(np.nanmax(half["event_time"].values))
    assert np.nanmax(np.abs(thick["event_time"].values - half["event_time"].values)) <= EVENT_SHARE * duration
    assert thick.attrs["param_layer_thickness"] == 1e9 and "param_layer_thickness" not in half.attrs


CONVERGENCE_CASES = {"5 mm bonded, A 30°": (5e-3, "bonded", "A", 30.0),
                     "5 mm bonded, A 30°, no adhesion": (5e-3, "bonded", "A", 30.0, 0.0),
                     "8 mm bonded, A 60°": (8e-3, "bonded", "A", 60.0),
                     "2 mm bonded, A 20°": (2e-3, "bonded", "A", 20.0),
                     "5 mm bonded, B 30°": (5e-3, "bonded", "B", 30.0),
                     "2 mm bonded, B 70°": (2e-3, "bonded", "B", 70.0),
                     "3 mm frictionless, A 90°": (3e-3, "frictionless", "A", 90.0)}


@pytest.mark.parametrize("case", CONVERGENCE_CASES.values(), ids=CONVERGENCE_CASES.keys())
def test_the_springs_on_a_layer_converge_at_first_order_to_its_continuum(case):
    """a/h from 0.45 (8 mm) to 2.3 (2 mm) at the paper's d_max; both bases (the frictionless one vertically); with the
    paper's adhesion and without (``Δγ0 = Δγ1 = 0``, the last element of a case)."""
    h, base, scenario, alpha, *work = case
    contact = PAPER.replace(h=h, **{"layer.base": base})
    if work:
        contact = contact.replace(dgamma0=work[0], dgamma1=work[0])
    motion = me.Scenario(scenario, alpha=[alpha])
    errors = []
    for dx in SPACINGS:
        springs = me.simulate(contact, motion, "discrete", dx=dx)
        exact = me.simulate(contact, motion, "continuum", t=springs["time"].values)
        differences = history_differences(springs, exact)
        errors.append([differences[name][0] for name in ("normal_force", "tangential_force", "contact_area")])
    errors = np.array(errors)
    for column, name in enumerate(("normal_force", "tangential_force", "contact_area")):
        if base == "frictionless" and name == "tangential_force":
            assert not np.any(errors[:, column])  # (no tangential springs: F_x = 0 in both)
            continue
        orders = observed_orders(SPACINGS, errors[:, column])
        low, high = SECOND_ORDER_RANGE if work and name == "normal_force" else ORDER_RANGE
        assert np.all((low < orders) & (orders < high)), (name, errors[:, column], orders)


@pytest.mark.parametrize("h", [5e-3, 2e-3])
def test_the_normal_force_is_the_layers_closed_curve(h):
    """Vertically in and out: the radius and ``F_N`` on the ``Δγ0`` branch going in, pinned at ``a_max`` back to the
    ``Δγ1`` branch, then on it: ``theory.layer.curves``' branches and ``F_N = F₀(a) + K(a)(d − g(a))``."""
    contact = PAPER.replace(h=h)
    run = me.simulate(contact, me.Scenario("A", alpha=[90.0]), "continuum").isel(alpha=0)
    depth, radius, force = (run[name].values for name in ("indentation_depth", "contact_radius", "normal_force"))
    deepest = int(np.argmax(depth))
    curve = layer_normal_curve(contact, depth)
    going_in = np.arange(depth.size) <= deepest
    on_branch = np.where(going_in, curve["contact_radius"].sel(branch="dgamma0").values,
                         curve["contact_radius"].sel(branch="dgamma1").values)
    held_radius = float(np.max(radius))  # (the radius at d_max, pinned until the Δγ1 branch is reached)
    shrinking = ~going_in & (radius < held_radius) & (radius > 0)
    loading = going_in & (radius > 0)
    expected_force = np.where(going_in, curve["normal_force"].sel(branch="dgamma0").values,
                              curve["normal_force"].sel(branch="dgamma1").values)
    scale_a, scale_f = np.max(radius), np.max(np.abs(force))
    for rows in (loading, shrinking):
        assert np.count_nonzero(rows) > 10
        assert np.max(np.abs(radius[rows] - on_branch[rows])) <= CURVE_SHARE * scale_a
        assert np.max(np.abs(force[rows] - expected_force[rows])) <= CURVE_SHARE * scale_f
    pinned = ~going_in & (radius == held_radius)
    held = me.theory.layer.normal_force(depth[pinned], held_radius, contact.indenter, contact.elastomer.E_star,
                                        contact.elastomer.nu, contact.layer)
    assert np.count_nonzero(pinned) > 10 and np.max(np.abs(force[pinned] - held)) <= CURVE_SHARE * scale_f


def test_full_sliding_on_a_layer_is_pi_a2_tau0_and_the_force_is_the_weighted_clip_integral():
    """A fretting loop beyond the layer's cap ``ū = π a² τ0/K_t``: every spring at the cap carries the layer's
    ``k_t ū`` and together ``K_t(a) ū = π a² τ0``, the mean shear stress ``τ0`` on any layer; the integrated force is
    the algebraic ``2G* ∫₀ᵃ w clip(x − Y, −ū, ū) dξ`` throughout (the right-hand side's measures checked)."""
    contact = PAPER.replace(h=5e-3)
    params = contact.parameters(me.Parameters.paper().d_max, me.Parameters.paper().v)
    path = fretting(amplitude=1.5e-3).paths["fretting"]  # (ū ≈ 0.64 mm at d_max on the 5 mm layer)
    solution = solve_path(params, path, layer=contact.layer)
    full = [event for event in solution.events if event.kind.value == "full_slip"]
    assert len(full) >= 3
    times = np.array([event.time for event in full])
    filled = evaluate(solution, times)
    expected = math.pi * filled["contact_radius"] ** 2 * params.tau0
    np.testing.assert_allclose(np.abs(filled["tangential_force"]), expected, rtol=FORCE_SHARE)
    samples = np.linspace(0.0, solution.end_time, 801)
    integrated = evaluate(solution, samples)["tangential_force"]
    algebraic = algebraic_tangential_force(solution, samples)
    scale = np.max(np.abs(integrated))
    assert np.nanmax(np.abs(integrated - algebraic)) <= FORCE_SHARE * scale


@pytest.mark.parametrize("h", [5e-3, 2e-3])
@pytest.mark.parametrize("scenario, alpha", [("A", 10.0), ("A", 20.0), ("B", 20.0), ("B", 40.0)])
def test_the_slip_onset_is_the_layers_onset_depth(h, scenario, alpha):
    """The first slip onset of the continuum on the layer at the depth of eq. (18) (A) or (21) (B) with the layer's
    cap and branches (``theory.layer.slip_onset``, through ``d_crit``)."""
    contact = PAPER.replace(h=h)
    expected = me.d_crit(alpha, contact, scenario, True)
    run = me.simulate(contact, me.Scenario(scenario, alpha=[alpha]), "continuum").isel(alpha=0)
    onsets = run["event_depth"].values[run["event_kind"].values == "slip_onset"]
    assert onsets.size and abs(onsets[0] - expected) <= ONSET_SHARE * expected, (onsets, expected)


def test_a_frictionless_base_carries_no_tangential_force_and_refuses_tangential_motion():
    contact = PAPER.replace(h=3e-3, **{"layer.base": "frictionless"})
    run = me.simulate(contact, me.Scenario("A", alpha=[90.0]), "continuum")
    assert not np.any(run["tangential_force"].values) and float(run["normal_force"].max()) > 0
    with pytest.raises(ValueError) as caught:
        me.simulate(contact, me.Scenario("A", alpha=[30.0]), "continuum")
    assert "K_t = 0" in str(caught.value) and "\n" not in str(caught.value)


def test_a_power_law_runs_on_a_layer_and_its_thick_layer_is_the_half_space():
    cone = dataclasses.replace(PAPER, indenter=me.PowerLaw(0.5, 1.5))
    motion = me.Scenario("A", alpha=[30.0])
    thick = me.simulate(cone.replace(h=1e9), motion, "continuum")
    half = me.simulate(cone, motion, "continuum", t=thick["time"].values)
    for name in ("normal_force", "tangential_force"):
        assert np.nanmax(np.abs(thick[name].values - half[name].values)) <= LIMIT_SHARE * np.nanmax(
            np.abs(half[name].values))


#: A tabulated profile (the layer's profile is tabulated for a paraboloid or power law; the flat punch under Coulomb's
#: part, refused here before, runs spring by spring: tests/models/test_layer_punch_coulomb.py).
_TABLE_RADII = np.linspace(0.0, 4e-3, 41)


@pytest.mark.parametrize("contact, words", [
    (dataclasses.replace(PAPER.replace(h=5e-3), indenter=me.TabulatedProfile(_TABLE_RADII, _TABLE_RADII**2 / 0.06)),
     "profile=TabulatedProfile(<41 points"),
])
def test_what_the_continuum_does_not_take_on_a_layer_is_one_line(contact, words):
    with pytest.raises(ValueError) as caught:
        me.simulate(contact, me.Scenario("A", alpha=[30.0]), "continuum")
    text = str(caught.value)
    assert words in text and "is not allowed on layer h = 0.005 m" in text and "allowed:" in text
    assert "\n" not in text


def test_a_radius_on_a_layer_does_not_depend_on_the_radii_asked_before_it():
    """Same input, same output: a branch's radius of a depth, and a solution evaluated twice, bit for bit whatever was
    asked before. Newton's start was the nearest of the last roots found: the same solution evaluated twice differed
    by an ulp of F_N at two of 1001 samples (on an Intel CPU with AVX-512; not on the AMD one the suite had run on)."""
    contact = PAPER.replace(h=5e-3)
    params = contact.parameters(me.Parameters.paper().d_max, me.Parameters.paper().v)
    solution = solve_path(params, me.Path.scenario_A(20.0, params), layer=contact.layer)
    times = np.linspace(0.0, solution.end_time, 1001)
    first = evaluate(solution, times)
    again = evaluate(solution, times)
    for name, values in first.items():
        np.testing.assert_array_equal(values, again[name], err_msg=name)
    medium = medium_of(params, contact.friction, None, contact.layer)

    def fresh_branch():
        return medium.edge(contact.adhesion, params, None).grow

    branch = fresh_branch()
    depths = np.linspace(0.2, 1.0, 40) * params.d_max
    alone = [fresh_branch().radius(float(d), 1e-14) for d in depths]
    for order in (depths, depths[::-1], np.random.default_rng(5).permutation(depths)):
        asked = {float(d): branch.radius(float(d), 1e-14) for d in order}
        assert [asked[float(d)] for d in depths] == alone


def test_the_shifts_of_runs_of_one_radius_are_each_radius_own():
    """``LayerMedium.shift`` of an array whose radii come in runs (a run's pinned spans: the held face over most of its
    samples) reads each run once and repeats it: bit for bit the element-by-element route over the whole array, in
    any shape, with zeros, a NaN and both signs of zero among them; an array of distinct radii takes that route."""
    contact = PAPER.replace(h=2e-4)
    params = contact.parameters(me.Parameters.paper().d_max, me.Parameters.paper().v)
    medium = medium_of(params, contact.friction, None, contact.layer)
    K = 0.37
    moving = np.linspace(1e-5, 4e-4, 7)
    radii = np.concatenate([np.full(40, 4e-4), moving, np.full(31, 2e-4), [0.0, -0.0, math.nan, math.nan],
                            np.full(25, 4e-4), moving[::-1]])
    for shaped in (radii, radii.reshape(3, -1), moving):
        np.testing.assert_array_equal(medium.shift(K, shaped), medium._shift_values(K, shaped))
        assert medium.shift(K, shaped).shape == shaped.shape
