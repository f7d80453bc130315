"""The discrete model on a layer of finite thickness (issue 34): the springs of the generalized MDR converge to the
layer's theory at first order in Δx, the thick layer is the half-space, the caps give full sliding exactly, and the
sticking springs carry the layer's tangential punch stiffness.

Each tolerance is derived from how the springs discretise the contact (the spring at ``x_j = (j + 1/2) Δx`` stands
for the strip ``[jΔx, (j + 1)Δx]``, its threshold, stiffness and cap taken at its centre):

- The discrete radius ``mΔx`` is within ``Δx/2`` of the branch's at the same depth: the boundary spring's threshold
  ``g − Δl`` is met at its centre, so the true radius lies between the centres of the last spring in and the first
  one out.
- The normal force at a depth is the branch's plus ``∂F/∂a|_d δa = K'(a)(d − g(a)) δa`` (``F₀' = K g'``), and the
  midpoint rule's ``O(Δx²)``: first order wherever the edge is adhesive (``d − g = −Δl``).
- The pull-off under depth control passes the force-control minimum of ``F_N`` along the ``Δγ1`` branch; the
  discrete minimum is below it by at most ``K'(a_F) Δl(a_F) Δx/2`` (the sawtooth of ``δa`` within a spring).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mdr_events as me
from mdr_events.contact.layer import Layer
from mdr_events.models.paths import Path
from mdr_events.theory.layer import (hess_elongation, normal_force, power_law_profile, punch_stiffness_slope,
                                     spring_stiffness_density)
from mdr_events.theory.layer_tangential import (coulomb_cap, sliding_cap, tangential_punch_stiffness,
                                                tangential_spring_stiffness_density)

from quick_round import examples, grid

PAPER = me.Contact.paper()
PARAMS = me.Parameters.paper()
D_MAX = PARAMS.d_max
#: The thicknesses of the convergence study: a/h ≈ 0.1, ≈ 1 and ≈ 5 at d_max on either base.
THICKNESSES = {"a/h~0.1": 30e-3, "a/h~1": 3e-3, "a/h~5": 1e-3}
BASES = ["bonded", "frictionless"]
#: Springs per contact radius at d_max of the three spacings of a convergence study (each half the one before).
SPRINGS_PER_RADIUS = (20, 40, 80)
#: Steps of a run: the depths are sampled finely enough that the time step adds nothing at first order (the radius
#: and the force are compared at the samples' own depths).
STEPS = 3000
#: Slack of ``|δa| <= Δx/2`` for the reference's own error: the branch is inverted by 60 bisections in ln a (far below
#: 1e-12 of a) and both sides read the same tables.
RADIUS_SLACK = 1e-9
#: The observed order of a first-order error from the last two spacings: 1 up to the second-order terms, which at 40
#: and 80 springs per radius move it by at most about 0.15 (measured 0.99–1.14 over the six layers).
ORDER_RANGE = (0.8, 1.3)
#: The pull-off's bound ``K'(a_F) Δl(a_F) Δx/2`` with room for its O(Δx²) terms: with 20 springs in the pull-off
#: radius they add at most 8 % (measured at 10 springs: 0.76–1.08 of the first-order term).
PULL_OFF_MARGIN = 1.25
#: The midpoint rule's share in ``Σ 2 k_t(x_j) Δx`` against ``K_t(mΔx)``: O((Δx/h)²), below 1e-4 at 20 springs per
#: radius even at a/h ≈ 5 (measured 4e-5).
MIDPOINT_SHARE = 1e-4
#: The shifts stepped spring by spring against the grouped exact sums: about 1e-14 of the largest force
#: (tests/models/test_discrete.py); and the layer's sums' own rounding.
ROUND_OFF_SHARE = 1e-12


def layered(h, base="bonded", **parts):
    """The paper's contact on a layer of thickness ``h`` and base ``base``, with other parts (``adhesion=``, ...)."""
    return dataclasses.replace(PAPER.replace(h=h, **{"layer.base": base}), **parts)


def loading_radius(contact, depth):
    """The contact radius at ``depth`` on the layer's ``Δγ0`` branch (m)."""
    return float(me.layer_normal_curve(contact, [depth])["contact_radius"].sel(branch="dgamma0").values[0])


def vertical_run(contact, dx, steps=STEPS):
    """Scenario A at 90°: straight in to d_max and straight out below the jump-off."""
    return me.simulate(contact, me.Scenario("A", alpha=[90.0]), "discrete", dx=dx, n_steps=steps).isel(alpha=0)


def reference_cycle(contact, depth):
    """The layer's radius and force at the samples ``depth`` of an indentation to its deepest sample and back under
    depth control: the ``Δγ0`` branch going in, pinned at ``a_max`` until the ``Δγ1`` branch, then along it (``nan``
    below its jump-off: no contact)."""
    turn = int(np.argmax(depth))
    curve = me.layer_normal_curve(contact, depth)
    going_in = curve["contact_radius"].sel(branch="dgamma0").values
    going_out = curve["contact_radius"].sel(branch="dgamma1").values
    radius = np.where(np.arange(depth.size) <= turn, going_in, np.fmin(going_in[turn], going_out))
    inside = np.isfinite(radius)
    E_star, nu = contact.elastomer.E_star, contact.elastomer.nu
    force = np.full(depth.size, np.nan)
    force[inside] = normal_force(depth[inside], radius[inside], contact.indenter, E_star, nu, contact.layer)
    return radius, force


def cycle_errors(contact, dx):
    """The largest radius error (m) and force error (N) of a vertical cycle against the layer's theory, the radius'
    bound holding at every sample in contact."""
    run = vertical_run(contact, dx)
    depth = run["indentation_depth"].values
    kept = np.isfinite(depth)
    radius, force = reference_cycle(contact, depth[kept])
    springs_radius, springs_force = run["contact_radius"].values[kept], run["normal_force"].values[kept]
    touching = springs_radius > 0.0
    # the springs come off at their least threshold, never below the branch's least depth: in contact only where
    # the theory is
    assert np.all(np.isfinite(radius[touching]))
    a_max = np.nanmax(radius)
    radius_error = np.abs(springs_radius[touching] - radius[touching])
    assert np.all(radius_error <= dx / 2 + RADIUS_SLACK * a_max), radius_error.max() / dx
    return radius_error.max(), np.max(np.abs(springs_force[touching] - force[touching])), float(run["normal_force"].min())


@pytest.mark.parametrize("h, base", grid(  # (0.35 s of CPU each: each thickness and base once in the quick round)
    {"h": THICKNESSES, "base": {base: base for base in BASES}},
    {("a/h~0.1", "bonded"), ("a/h~1", "frictionless"), ("a/h~5", "bonded")}))
def test_the_normal_cycle_converges_at_first_order_to_the_layers_theory(h, base):
    """Radius and force of an indentation cycle with Δγ1 = 15 Δγ0 against layer_normal_curve's branches, and the
    pull-off against layer_pull_off_curve (a/h ≈ 0.1, 1, 5 at d_max)."""
    contact = layered(h, base)
    a_max = loading_radius(contact, D_MAX)
    pulled = me.layer_pull_off_curve(contact, [h])
    pull_off, a_F = float(pulled["pull_off_force"][0]), float(pulled["pull_off_radius"][0])
    E_star, nu = contact.elastomer.E_star, contact.elastomer.nu
    sawtooth = float(punch_stiffness_slope(a_F, E_star, nu, contact.layer)
                     * hess_elongation(a_F, contact.adhesion.dgamma1, E_star, nu, contact.layer))
    spacings = [a_max / n for n in SPRINGS_PER_RADIUS]
    errors = np.array([cycle_errors(contact, dx) for dx in spacings])
    radius_order, force_order = np.log2(errors[-2, :2] / errors[-1, :2])
    print(f"h = {h} m ({base}): a/h = {a_max / h:.3g}, observed orders radius {radius_order:.3f}, "
          f"force {force_order:.3f}; pull-off errors {errors[:, 2] - pull_off}")
    assert ORDER_RANGE[0] < radius_order < ORDER_RANGE[1]
    assert ORDER_RANGE[0] < force_order < ORDER_RANGE[1]
    # the pull-off at 20, 40 and 80 springs in its own radius (a_max/a_F ≈ 6, so a finer spacing than the cycle's)
    for n in SPRINGS_PER_RADIUS:
        dx = a_F / n
        minimum = float(vertical_run(contact, dx)["normal_force"].min())
        assert abs(minimum - pull_off) <= PULL_OFF_MARGIN * sawtooth * dx / 2, (n, minimum, pull_off)


#: A layer so thick that a/h ≈ 3e-12 at d_max: its factors differ from 1 by O(a/h), far below the spacing of the
#: samples' depths, so the springs in contact are the half-space's at every sample.
THICK = 1e9


def test_a_thick_layer_is_the_half_space():
    """Scenario A at 20° and 60°: the springs in contact equal, the forces within the layer's deviation of its
    stiffness, profile and caps from the half-space's (computed at the springs), times the forces' scale."""
    dx = 2e-5
    scenario = me.Scenario("A", alpha=[20.0, 60.0])
    thick = me.simulate(layered(THICK), scenario, "discrete", dx=dx, n_steps=4000)
    half = me.simulate(PAPER, scenario, "discrete", dx=dx, n_steps=4000)
    np.testing.assert_array_equal(thick["contact_radius"].values, half["contact_radius"].values)
    assert thick.attrs["param_layer_thickness"] == THICK and thick.attrs["param_layer_base"] == "bonded"
    assert "param_layer_thickness" not in half.attrs
    layer, E_star, G_star, nu = Layer(THICK), PARAMS.E_star, PARAMS.G_star, PARAMS.nu
    springs = (np.arange(int(thick.attrs["spring_count_per_side"])) + 0.5) * dx
    radii = springs + dx / 2
    stiffness = np.max(np.abs(spring_stiffness_density(springs, E_star, nu, layer) / E_star - 1))
    profile = np.max(np.abs(power_law_profile(springs, me.Paraboloid(PARAMS.R), nu, layer) * PARAMS.R / springs**2 - 1))
    shear = np.max(np.abs(tangential_spring_stiffness_density(springs, G_star, nu, layer) / G_star - 1))
    caps = np.max(np.abs(sliding_cap(radii, PARAMS.tau0, G_star, nu, layer)
                         / me.critical_shift(radii, PARAMS) - 1))
    assert 0 < max(stiffness, profile, shear, caps) < 1e-9  # (the layer is a layer, and thick)
    # F_N = 2E*Δx Σ w (d − g): each term moves by (stiffness |d − g| + profile g); bounded by the terms' magnitudes
    m = np.rint(half["contact_radius"].values / dx)
    depth = np.abs(half["indentation_depth"].values)
    g_sum = 2 * E_star * dx * m**3 * dx**2 / (3 * PARAMS.R)  # 2E*Δx Σ x_j²/R <= this
    normal_scale = 2 * E_star * dx * m * depth + 2 * g_sum
    ran = np.isfinite(m)  # (the same samples: the radii are equal, nan included)
    normal = half["normal_force"].values
    assert np.all(np.abs(thick["normal_force"].values[ran] - normal[ran])
                  <= (stiffness + 2 * profile) * normal_scale[ran] + ROUND_OFF_SHARE * np.nanmax(np.abs(normal)))
    # F_x = 2G*Δx Σ w_t u, |u| <= ū: each term moves by (shear + caps) |ū|, and by the sums' rounding
    tangential_scale = 2 * G_star * dx * m[ran] * me.critical_shift(m[ran] * dx, PARAMS)
    tangential = half["tangential_force"].values
    assert np.all(np.abs(thick["tangential_force"].values[ran] - tangential[ran])
                  <= (shear + 2 * caps) * tangential_scale + ROUND_OFF_SHARE * np.nanmax(np.abs(tangential)))


def slide(contact, dx, length, depth=D_MAX):
    """Straight in to ``depth``, then along the surface by ``length``: the run's last sample."""
    path = Path([(0.0, 0.0), (0.0, depth), (length, depth)], PARAMS.v)
    return me.simulate(contact, [path], "discrete", dx=dx, n_steps=STEPS).isel(case=0, time=-1)


def offset_spacing(a, n):
    """A spacing with ``a`` a third of a spring beyond the ``n``-th spring's edge: the discrete radius is
    ``a − Δx/3``, a first-order error (a spacing dividing ``a`` would leave only the midpoint rule's)."""
    return a / (n + 1.0 / 3.0)


@pytest.mark.parametrize("h", THICKNESSES.values(), ids=THICKNESSES.keys())
def test_full_sliding_under_tau0_carries_pi_a2_tau0(h):
    """Every spring at its cap ``π a² τ0/K_t(a)``: F_x = ū(a_m) Σ 2 k_t Δx = π a_m² τ0 up to the midpoint rule, and
    π a² τ0 at first order in Δx."""
    contact = layered(h)
    a = loading_radius(contact, D_MAX)
    cap = float(sliding_cap(a, PARAMS.tau0, PARAMS.G_star, PARAMS.nu, contact.layer))
    errors = []
    for n in SPRINGS_PER_RADIUS:
        dx = offset_spacing(a, n)
        last = slide(contact, dx, 4 * cap)
        assert float(last["sliding_fraction"]) == 1.0
        a_m = float(last["contact_radius"])
        force = float(last["tangential_force"])
        assert abs(force / (math.pi * a_m**2 * PARAMS.tau0) - 1) <= MIDPOINT_SHARE
        # |a_m − a| <= Δx/2: |π a_m² − π a²| <= π (a Δx + Δx²/4)
        assert abs(force - math.pi * a**2 * PARAMS.tau0) <= (1 + MIDPOINT_SHARE) * math.pi * PARAMS.tau0 * (
            a * dx + dx**2 / 4)
        errors.append(abs(force - math.pi * a**2 * PARAMS.tau0))
    order = math.log2(errors[-2] / errors[-1])
    print(f"h = {h}: full sliding errors {errors}, observed order {order:.3f}")
    assert ORDER_RANGE[0] < order < ORDER_RANGE[1]


#: The coefficient of friction of the Coulomb tests.
MU = 0.3


@pytest.mark.parametrize("law", ["coulomb", "tau0+coulomb"])
@pytest.mark.parametrize("h", THICKNESSES.values(), ids=THICKNESSES.keys())
def test_full_sliding_under_coulomb_carries_mu_times_the_compressed_springs(h, law):
    """Without adhesion every spring is compressed and its cap is ``μ (k/k_t)(d − g)``: at full sliding F_x = μ F_N
    of the springs to round-off (plus π a_m² τ0 with τ0's part), and μ F_N of the layer's theory at first order."""
    friction = me.FrictionLaw(law, mu=MU, tau0=PARAMS.tau0 if law != "coulomb" else None)
    contact = layered(h, adhesion=me.Adhesion(0.0, 0.0), friction=friction)
    a = loading_radius(contact, D_MAX)
    theory = float(normal_force(D_MAX, a, contact.indenter, PARAMS.E_star, PARAMS.nu, contact.layer))
    # the largest cap: τ0's and Coulomb's at g = 0 (an upper bound), over the contact
    widest = float(sliding_cap(a, PARAMS.tau0, PARAMS.G_star, PARAMS.nu, contact.layer)) + float(np.max(coulomb_cap(
        np.linspace(0.0, a, 101), D_MAX, 0.0, MU, PARAMS.E_star, PARAMS.G_star, PARAMS.nu, contact.layer)))
    for n in SPRINGS_PER_RADIUS:
        dx = offset_spacing(a, n)
        last = slide(contact, dx, 2 * widest)
        assert float(last["sliding_fraction"]) == 1.0
        a_m, normal = float(last["contact_radius"]), float(last["normal_force"])
        tau0_part = 0.0 if law == "coulomb" else math.pi * a_m**2 * PARAMS.tau0 * (1 + MIDPOINT_SHARE)
        assert abs(float(last["tangential_force"]) - MU * normal) <= tau0_part + ROUND_OFF_SHARE * MU * normal
        # without adhesion d = g(a) at the edge: ∂F/∂a|_d = 0, the force's error is of the midpoint rule and δa²
        slope = float(punch_stiffness_slope(a, PARAMS.E_star, PARAMS.nu, contact.layer))
        g_slope = 2 * a / PARAMS.R  # g' of the half-space; the layer's is smaller (γ <= 1)
        assert abs(normal - theory) <= slope * g_slope * dx**2 + MIDPOINT_SHARE * theory


@pytest.mark.parametrize("h", THICKNESSES.values(), ids=THICKNESSES.keys())
def test_sticking_springs_carry_the_layers_tangential_punch_stiffness(h):
    """A shift u0 = ū(a)/4 at d_max after a vertical indentation: no spring slides and F_x = u0 Σ 2 k_t Δx, which is
    K_t(a) u0 within k_t(a) Δx u0 (the radius within Δx/2, K_t' = 2 k_t)."""
    contact = layered(h)
    a = loading_radius(contact, D_MAX)
    G_star, nu = PARAMS.G_star, PARAMS.nu
    shift = float(sliding_cap(a, PARAMS.tau0, G_star, nu, contact.layer)) / 4
    stiffness = float(tangential_punch_stiffness(a, G_star, nu, contact.layer))
    density = float(tangential_spring_stiffness_density(a, G_star, nu, contact.layer))
    errors = []
    for n in SPRINGS_PER_RADIUS:
        dx = offset_spacing(a, n)
        path = Path([(0.0, 0.0), (0.0, D_MAX), (shift, D_MAX)], PARAMS.v)
        run = me.simulate(contact, [path], "discrete", dx=dx, n_steps=STEPS).isel(case=0)
        assert np.nanmax(run["sliding_fraction"].values) == 0.0
        force = float(run["tangential_force"][-1])
        assert abs(force - stiffness * shift) <= (1 + MIDPOINT_SHARE) * density * dx * shift
        errors.append(abs(force - stiffness * shift))
    order = math.log2(errors[-2] / errors[-1])
    print(f"h = {h}: sticking errors {errors}, observed order {order:.3f}")
    assert ORDER_RANGE[0] < order < ORDER_RANGE[1]


def test_a_frictionless_base_runs_the_normal_problem_and_refuses_tangential_motion():
    contact = layered(3e-3, "frictionless")
    run = vertical_run(contact, 1e-4)
    forces = run["tangential_force"].values
    assert np.all(forces[np.isfinite(forces)] == 0.0) and np.nanmax(run["normal_force"].values) > 0.0
    assert run.attrs["param_layer_base"] == "frictionless"
    with pytest.raises(ValueError) as caught:
        me.simulate(contact, me.Scenario("A", alpha=[30.0]), "discrete", dx=1e-4)
    text = str(caught.value)
    assert text.startswith("path 0 moves the indenter tangentially") and "not allowed on layer h = 0.003 m, " \
        "frictionless base" in text and "allowed: paths without tangential motion" in text and "\n" not in text


@pytest.mark.parametrize("contact, words", [
    (layered(3e-3, indenter=me.TabulatedProfile([0.0, 1e-3, 2e-3], [0.0, 1e-6, 4e-6])),
     "profile=TabulatedProfile("),
    (layered(3e-3, adhesion=me.RateDependentAdhesion(0.01, 0.15, 1e-3, 0.5)), "adhesion=RateDependentAdhesion"),
])
def test_what_the_layer_does_not_take_is_refused_in_one_line(contact, words):
    with pytest.raises((ValueError, TypeError)) as caught:
        me.simulate(contact, me.Scenario("A", alpha=[90.0]), "discrete", dx=1e-4)
    assert words in str(caught.value) and "allowed:" in str(caught.value) and "\n" not in str(caught.value)


def test_the_continuum_runs_coulombs_law_on_an_adhesive_layer_as_the_discrete_method_does():
    """Issues 26 and 34: nothing the discrete model runs on a layer is refused by the continuum (Coulomb's part with the
    paper's adhesion spring by spring, tests/models/test_layer_coulomb.py): both give a contact's ``F_x`` on the same
    samples, within the springs' first-order error at this spacing (:data:`COULOMB_SHARE`)."""
    coulomb = dataclasses.replace(layered(3e-3), friction=me.FrictionLaw("coulomb", mu=0.3))
    assert coulomb.adhesion.dgamma0 > 0.0
    springs = me.simulate(coulomb, me.Scenario("A", alpha=[30.0]), "discrete", dx=2e-5, n_steps=200).isel(alpha=0)
    times = springs["time"].values[::20]
    exact = me.simulate(coulomb, me.Scenario("A", alpha=[30.0]), "continuum", t=times).isel(alpha=0)
    expected, approx = exact["tangential_force"].values, springs["tangential_force"].sel(time=times).values
    inside = np.isfinite(expected) & np.isfinite(approx)
    assert np.count_nonzero(inside) >= 5
    assert np.max(np.abs(approx[inside] - expected[inside])) <= COULOMB_SHARE * np.max(np.abs(expected[inside]))


#: The discrete model's Coulomb force against the continuum's at 2e-5 m spacing (about 100 springs per radius): its
#: first-order error, a few per cent at most (tests/models/test_layer_coulomb.py measures its order).
COULOMB_SHARE = 0.05


@st.composite
def layer_cases(draw):
    """A paraboloid on a layer: h log-uniform 0.5–50 mm, ν of three values (their tables are built once), either
    base; the paper's adhesion and τ0; Scenario A at an angle (90° on a frictionless base) to a depth of 0.1–0.4 mm."""
    h = 10 ** draw(st.floats(math.log10(5e-4), math.log10(5e-2)))
    nu = draw(st.sampled_from([0.0, 0.3, 0.5]))
    base = draw(st.sampled_from(BASES))
    alpha = 90.0 if base == "frictionless" else draw(st.floats(15.0, 90.0))
    d_max = draw(st.floats(1e-4, 4e-4))
    contact = PAPER.replace(h=h, nu=nu, **{"layer.base": base})
    return contact, alpha, d_max


@settings(max_examples=examples(12), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(layer_cases())
def test_properties_of_a_run_on_any_layer(case):
    """On any layer and path: going in, the radius is within Δx/2 of the layer's Δγ0 branch at each sample's depth;
    no spring's shift passes its cap, so |F_x| <= ū(a_m) Σ 2 k_t Δx; the sliding fraction is a fraction; the minimum
    of F_N is the layer's pull-off within the sawtooth bound."""
    contact, alpha, d_max = case
    E_star, G_star, nu, layer = (contact.elastomer.E_star, contact.elastomer.G_star, contact.elastomer.nu,
                                 contact.layer)
    pulled = me.layer_pull_off_curve(contact, [layer.thickness])
    pull_off, a_F = float(pulled["pull_off_force"][0]), float(pulled["pull_off_radius"][0])
    dx = min(loading_radius(contact, d_max), a_F) / SPRINGS_PER_RADIUS[0]
    run = me.simulate(contact, me.Scenario("A", alpha=[alpha], d_max=d_max), "discrete", dx=dx,
                      n_steps=2000).isel(alpha=0)
    depth, radius = run["indentation_depth"].values, run["contact_radius"].values
    turn = int(np.nanargmax(depth))
    going_in = slice(1, turn + 1)  # (sample 0 is the first touch, d = 0)
    branch = me.layer_normal_curve(contact, depth[going_in])["contact_radius"].sel(branch="dgamma0").values
    assert np.all(np.abs(radius[going_in] - branch) <= dx / 2 + RADIUS_SLACK * np.nanmax(radius))
    fraction = run["sliding_fraction"].values
    assert np.all((fraction[radius > 0] >= 0) & (fraction[radius > 0] <= 1))
    touching = radius > 0
    if layer.base.value == "bonded":
        springs = (np.arange(int(np.nanmax(radius) / dx + 0.5)) + 0.5) * dx
        weights = np.concatenate([[0.0], np.cumsum(2 * dx * tangential_spring_stiffness_density(springs, G_star, nu,
                                                                                                   layer))])
        m = np.rint(radius[touching] / dx).astype(int)
        most = sliding_cap(radius[touching], PARAMS.tau0, G_star, nu, layer) * weights[m]
        assert np.all(np.abs(run["tangential_force"].values[touching]) <= most * (1 + ROUND_OFF_SHARE))
    else:
        assert np.all(run["tangential_force"].values[touching] == 0.0)
    sawtooth = float(punch_stiffness_slope(a_F, E_star, nu, layer)
                     * hess_elongation(a_F, contact.adhesion.dgamma1, E_star, nu, layer))
    assert abs(float(run["normal_force"].min()) - pull_off) <= PULL_OFF_MARGIN * sawtooth * dx / 2


#: The grouped kernel's F_x against the per-spring stepping's, as a share of the largest |F_x|: the weights rounded to
#: 53 bits of the largest (2**-53) and the per-spring float sums' rounding (tests/models/test_discrete.py's SUM_RTOL).
SUM_RTOL = 1e-12


def reciprocating(amplitude, strokes, depth=D_MAX):
    """In, then back and forth by ±amplitude at depths varied stroke by stroke, then out: caps reached, released,
    springs detaching and attaching again."""
    points = [(0.0, 0.0), (0.0, depth)]
    for i in range(strokes):
        points.append(((1.0 if i % 2 == 0 else -1.0) * amplitude * (0.7 if i % 3 == 0 else 1.0),
                       depth * (0.35 if i % 4 == 1 else 1.0 - 0.1 * (i % 3))))
    points.append((points[-1][0], -0.2 * depth))
    return Path(points, PARAMS.v)


@pytest.mark.parametrize("steps", [60, 2500], ids=["steps-beyond-2ū", "fine-steps"])
@pytest.mark.parametrize("h", THICKNESSES.values(), ids=THICKNESSES.keys())
def test_the_grouped_kernel_equals_the_springs_stepped_one_by_one_on_a_layer(h, steps):
    """The groups with integer weights k_t(x_j)/G* against every spring's shift moved, clipped and weighed at every
    step: the same springs in contact and at a cap, Σ w u to round-off; also with steps beyond a whole cap."""
    from mdr_events.contact.adhesion import law_of
    from mdr_events.models import discrete
    from mdr_events.models.spring_media import springs_of

    contact = layered(h)
    a = loading_radius(contact, D_MAX)
    cap = float(sliding_cap(a, PARAMS.tau0, PARAMS.G_star, PARAMS.nu, contact.layer))
    paths = [Path.scenario_A(20.0, PARAMS), Path.scenario_B(30.0, PARAMS), reciprocating(1.5 * cap, 12)]
    dt = max(path.duration - path.first_contact_time() for path in paths) / steps
    springs = springs_of(PARAMS, None, None, contact.layer)
    run = discrete._prepare(PARAMS, paths, a / 40, dt, None, contact.friction, law_of(PARAMS), springs)
    n = run.time.size
    wholly = False
    for case in range(len(paths)):
        outputs = {}
        for kernel in (discrete._run_case, discrete._run_case_per_spring):
            counts, sums, sliding = np.zeros(n, np.int64), np.zeros(n), np.zeros(n, np.int64)
            last = kernel(run.grid, run.x[:, case], run.d[:, case], run.time, int(run.last_sample[case]),
                          float(run.last_entries[case]), counts, sums, sliding)
            outputs[kernel.__name__] = last, counts[:last + 1], sums[:last + 1], sliding[:last + 1]
        grouped, reference = outputs["_run_case"], outputs["_run_case_per_spring"]
        assert grouped[0] == reference[0]
        np.testing.assert_array_equal(grouped[1], reference[1])
        np.testing.assert_array_equal(grouped[3], reference[3])
        scale = np.abs(reference[2]).max()
        np.testing.assert_allclose(grouped[2], reference[2], rtol=0.0, atol=SUM_RTOL * scale)
        wholly |= bool(np.any((reference[3] == reference[1]) & (reference[1] > 0)))
    assert wholly  # (the caps were reached by every spring somewhere)
