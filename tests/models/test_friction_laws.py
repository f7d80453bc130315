"""The friction laws in the simulators: the continuum against Cattaneo–Mindlin and Masing's loops (to 1e-9), and
against the closed form of proportional loading; the discrete model converging to both at first order; the
paper's law unchanged; what the continuum refuses, named."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences, observed_orders
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.continuum import EventKind, evaluate, solve_path
from mdr_events.contact.indenters import PowerLaw
from mdr_events.theory import mindlin
from mdr_events.theory import power_law as pl

DEPTH = 1e-4
#: The continuum's force against the closed forms, as a share of the force of full slip (its rtol is 1e-10 and
#: a loop's branches are exact between events).
CONTINUUM_RTOL = 1e-9
COULOMB = FrictionLaw("coulomb", mu=0.3)
COMBINED = FrictionLaw("tau0+coulomb", mu=0.2)


@pytest.fixture(scope="module")
def hertz():
    """The paper's material without adhesion; τ0 = 1 kPa puts the combined law's two parts at 1 : 3 at DEPTH."""
    return me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0, tau0=1e3)


def _fretting_path(friction, params, profile=None, speed=1e-6):
    """In vertically to DEPTH, then 0 → 0.8 X → −0.8 X → 0.5 X → −0.3 X → 1.5 X along x (X the full slip shift):
    loading, a Mindlin loop, an inner loop, and full slip."""
    X = mindlin.full_slip_shift(DEPTH, friction, params, profile)
    turns = np.array([0.0, 0.8, -0.8, 0.5, -0.3, 1.5]) * X
    return me.Path(np.array([(0.0, -1e-6)] + [(x, DEPTH) for x in turns]), speed=speed)


def _at_depth(path, solution, samples=3001):
    """Times from first contact: a grid and the path's corners; the samples at DEPTH."""
    times = np.union1d(np.linspace(0.0, solution.end_time, samples), path.corner_times - path.first_contact_time())
    out = evaluate(solution, times)
    held = out["indentation_depth"] == DEPTH
    return out["tangential_displacement"][held], out["tangential_force"][held]


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
@pytest.mark.parametrize("profile", [None, PowerLaw.cone(0.05), PowerLaw(2e5, 3.0)], ids=["paraboloid", "cone", "n3"])
def test_the_continuum_gives_cattaneo_mindlin_and_masings_loops(hertz, friction, profile):
    path = _fretting_path(friction, hertz, profile)
    solution = solve_path(hertz, path, profile=profile, friction=friction)
    x, force = _at_depth(path, solution)
    expected = mindlin.tangential_force(x, DEPTH, friction, hertz, profile)
    scale = mindlin.full_slip_force(DEPTH, friction, hertz, profile)
    np.testing.assert_allclose(force, expected, rtol=0, atol=CONTINUUM_RTOL * scale)
    assert force[-1] == pytest.approx(scale, rel=1e-12)  # full slip, set exactly
    kinds = [event.kind for event in solution.events]
    assert EventKind.FULL_SLIP in kinds and EventKind.RE_STICK in kinds


def _proportional(params, alpha, friction, d_end=DEPTH):
    """In from the surface along x = d / tan α, then out along the same line (the contact ends at d = 0)."""
    tan = math.tan(math.radians(alpha))
    return me.Path(np.array([(-1e-7 / tan, -1e-7), (d_end / tan, d_end), (-1e-7 / tan, -1e-7)]), speed=1e-6)


@pytest.mark.parametrize("profile", [None, PowerLaw(2e5, 3.0)], ids=["paraboloid", "n3"])
def test_proportional_loading_sticks_above_the_angle_of_friction_and_slides_below(hertz, profile):
    """Coulomb's law along x = d / tan α: every spring's shift (d − d_ξ)/tan α and cap κ (d − d_ξ) grow in
    proportion, so all stick where tan α > 1/κ, F_x = F_N G*/(E* tan α), and all slide from first contact below
    it, F_x = μ F_N (the springs' ratio of tangential to normal force is the path's)."""
    kappa = mindlin.coulomb_cap_ratio(COULOMB, hertz)
    critical = math.degrees(math.atan(1.0 / kappa))
    for alpha, sticks in ((critical * 1.05, True), (critical * 0.95, False)):
        path = _proportional(hertz, alpha, COULOMB)
        solution = solve_path(hertz, path, profile=profile, friction=COULOMB)
        out = evaluate(solution, np.linspace(0.0, 0.5 * (path.corner_times[1] - path.first_contact_time()), 401)[1:])
        normal = out["normal_force"]
        expected = normal * hertz.G_star / (hertz.E_star * math.tan(math.radians(alpha))) if sticks else 0.3 * normal
        np.testing.assert_allclose(out["tangential_force"], expected, rtol=0, atol=CONTINUUM_RTOL * np.abs(expected).max())
        kinds = {event.kind for event in solution.events if event.time < path.corner_times[1]}
        assert (EventKind.SLIP_ONSET in kinds) != sticks


#: Depths of the discrete runs (shares of DEPTH): a contact of Δx-spaced springs has a radius off by up to Δx/2,
#: by a share of it that depends on where the radius falls between springs; the largest over several depths
#: shows the bound's first order (at one depth the share may happen to shrink as Δx does not).
DISCRETE_DEPTHS = (1.0, 1.07, 1.15, 1.22)


def _fretting_path_at(depth, friction, params):
    X = mindlin.full_slip_shift(depth, friction, params)
    turns = np.array([0.0, 0.8, -0.8, 0.5, -0.3, 1.5]) * X
    return me.Path(np.array([(0.0, -1e-6)] + [(x, depth) for x in turns]), speed=1e-6)


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
def test_the_discrete_model_converges_to_cattaneo_mindlin_at_first_order(hertz, friction):
    """The springs at Δx = 4, 2, 1 µm (dt = Δx/(2v)) against Masing's closed form on their own samples, at the depths
    DISCRETE_DEPTHS: the largest difference falls at least at first order from 4 to 1 µm (observed order > 0.8) and
    stays within the first-order bound of the radius's quantisation."""
    depths = [share * DEPTH for share in DISCRETE_DEPTHS]
    paths = [_fretting_path_at(depth, friction, hertz) for depth in depths]
    spacings = (4e-6, 2e-6, 1e-6)
    errors = []
    for dx in spacings:
        run = me.simulate(hertz, paths, dx=dx, dt=0.5 * dx / 1e-6, friction=friction)
        largest = 0.0
        for case, depth in enumerate(depths):
            held = run["indentation_depth"].values[case] == depth
            x = run["tangential_displacement"].values[case][held]
            # the springs were at rest at the corner (0, depth), which the samples may step over
            expected = mindlin.tangential_force(np.concatenate([[0.0], x]), depth, friction, hertz)[1:]
            difference = np.max(np.abs(run["tangential_force"].values[case][held] - expected))
            largest = max(largest, difference / mindlin.full_slip_force(depth, friction, hertz))
        errors.append(largest)
    # over the whole range at least first order, and below the bound of a radius off by Δx/2 in a force that goes as
    # a³ at most (μ F_N; τ0 π a² as a²): 3 (Δx/2)/a of full slip
    assert observed_orders(spacings[::2], errors[::2])[0] > 0.8, errors
    radius = math.sqrt(hertz.R * DEPTH)
    assert np.all(np.array(errors) <= 1.5 * np.array(spacings) / radius), errors


def test_the_discrete_model_converges_to_the_continuum_along_an_oblique_path(hertz):
    """Growth in full slip from first contact, reversals while shrinking and growing, and shrinking to zero with
    Coulomb's law: max_t |discrete − continuum| of F_N, F_x and A falls at first order (observed orders above 0.7),
    as for the paper's law. The segments (3-4-5 triangles, µm) end on the time grid of every spacing."""
    path = me.Path(np.array([(0.0, 0.0), (60e-6, 80e-6), (20e-6, 50e-6), (50e-6, 90e-6), (-70e-6, 0.0)]), speed=1e-6)
    spacings = (8e-6, 4e-6, 2e-6)
    differences = {}
    for dx in spacings:
        discrete = me.simulate(hertz, path, dx=dx, dt=0.5 * dx / path.speed, friction=COULOMB)
        exact = me.simulate(hertz, path, method="continuum", t=discrete["time"].values, friction=COULOMB)
        for name, values in history_differences(discrete, exact).items():
            differences.setdefault(name, []).append(values[0])
    for name in ("tangential_force", "normal_force", "contact_area"):
        assert np.all(observed_orders(spacings, differences[name]) > 0.7), (name, differences[name])


def test_the_papers_law_is_unchanged(hertz):
    """friction=None, "tau0" and FrictionLaw() are one run; "tau0+coulomb" with μ = 0 is the paper's law too, bit for
    bit in both methods (κ = 0 takes the same code; the per-spring kernel of Coulomb's caps is checked against the
    grouped one in tests/models/test_discrete.py)."""
    paper = me.Parameters.paper()
    runs = [me.simulate(paper, "A", alpha=[20.0], method="continuum", samples=301, friction=friction)
            for friction in (None, "tau0", FrictionLaw())]
    for run in runs[1:]:
        assert run.identical(runs[0])
    assert "friction_law" not in runs[0].attrs
    zero = me.simulate(paper, "A", alpha=[20.0], method="continuum", samples=301,
                       friction=FrictionLaw("tau0+coulomb", mu=0.0))
    np.testing.assert_array_equal(zero["tangential_force"].values, runs[0]["tangential_force"].values)
    assert zero.attrs["friction_law"] == "tau0+coulomb" and zero.attrs["friction_mu"] == 0.0
    grouped = me.simulate(paper, "B", alpha=[40.0], dx=4e-6)
    combined = me.simulate(paper, "B", alpha=[40.0], dx=4e-6, friction=FrictionLaw("tau0+coulomb", mu=0.0))
    for name in ("tangential_force", "normal_force", "contact_radius", "sliding_fraction"):  # the same kernel
        np.testing.assert_array_equal(combined[name].values, grouped[name].values)


def test_the_discrete_model_runs_coulombs_law_with_adhesion():
    """Springs in tension hold no Coulomb shift: with adhesion and μ but no τ0, |F_x| is at most μ times the normal
    force of the compressed springs alone, 2 E* Δx Σ_{d > g} (d − g) (not μ F_N, which the springs in tension lower),
    and equals it where every spring slides (the springs in tension, with a zero cap, count as sliding)."""
    paper = me.Parameters.paper()
    dx = 4e-6
    run = me.simulate(paper, "B", alpha=[30.0], dx=dx, friction=COULOMB)
    assert run.attrs["friction_law"] == "coulomb" and "param_tau0 is not used" in run.attrs["friction_note"]
    depth, springs = run["indentation_depth"].values[0], np.round(run["contact_radius"].values[0] / dx)
    force, sliding = run["tangential_force"].values[0], run["sliding_fraction"].values[0]
    xi = (np.arange(int(np.nanmax(springs))) + 0.5) * dx
    compressed = np.array([2 * paper.E_star * dx * np.sum(np.maximum(d - xi[:int(m)] ** 2 / paper.R, 0.0))
                           if m > 0 else 0.0 for d, m in zip(np.nan_to_num(depth), np.nan_to_num(springs))])
    bound = 0.3 * compressed
    touching = np.nan_to_num(springs) > 0
    assert np.all(np.abs(force[touching]) <= bound[touching] * (1 + 1e-12) + 1e-15)
    full = touching & (sliding == 1.0) & (bound > 0)
    assert np.count_nonzero(full) > 10
    np.testing.assert_allclose(np.abs(force[full]), bound[full], rtol=1e-9)
    tension = touching & (compressed < 2 * paper.E_star * dx * np.nan_to_num(springs) * np.nan_to_num(depth) - 1e-18)
    assert np.any(tension)  # some samples have springs in tension (else the test would not tell the laws apart)


@pytest.mark.parametrize("call, exception, words", [
    (lambda: me.simulate(me.Parameters.paper(), "A", alpha=[20.0], friction="amontons"), ValueError,
     ["FrictionLaw.law='amontons'"]),
    (lambda: me.simulate(me.Parameters.paper(), "A", alpha=[20.0], friction="coulomb"), ValueError, ["mu=None"]),
    (lambda: me.simulate(me.Parameters.paper(), "A", alpha=[20.0], friction=0.3), TypeError, ["friction=0.3"]),
])
def test_what_the_simulators_refuse_is_named(call, exception, words):
    with pytest.raises(exception) as caught:
        call()
    for word in words:
        assert word in str(caught.value)


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
@pytest.mark.parametrize("profile", [None, PowerLaw(2e5, 3.0)], ids=["paraboloid", "n3"])
def test_scenario_a_onsets_meet_the_closed_forms(hertz, friction, profile):
    """The continuum's first slip onset while indenting along (14) without adhesion against mindlin.d_crit_A (to 1e-9
    of d_max), and none above the closed-form critical angle (checked at 0.98 and 1.02 of it)."""
    critical = mindlin.critical_angle_A(friction, hertz, profile)
    for alpha in (20.0, 45.0, 0.98 * critical, 1.02 * critical):
        path = me.Path.scenario_A(alpha, hertz, profile=profile)
        solution = solve_path(hertz, path, profile=profile, friction=friction)
        deepest = path.corner_times[1] - path.first_contact_time()  # the onsets while indenting
        onsets = [event.depth for event in solution.events if event.kind is EventKind.SLIP_ONSET
                  and event.time < deepest]
        expected = mindlin.d_crit_A(alpha, friction, hertz, profile)
        if alpha > critical:
            assert not onsets, (alpha, onsets)
            assert math.isnan(expected) or expected > hertz.d_max
        else:
            assert onsets[0] == pytest.approx(expected, abs=1e-9 * hertz.d_max), (alpha, onsets, expected)


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
@pytest.mark.parametrize("scenario", ["B", "B+"])
def test_scenario_b_onsets_meet_the_closed_forms(hertz, friction, scenario):
    """Scenario B (out at α from d_max) and B+ (further in at α) without adhesion: the continuum's first slip onset
    after the corner at d_max against mindlin.d_crit_B and d_crit_B_indentation (1e-9 of d_max); none on B+ above
    its critical angle (with the default final depth 2 d_max)."""
    closed = mindlin.d_crit_B if scenario == "B" else mindlin.d_crit_B_indentation
    build = me.Path.scenario_B if scenario == "B" else me.Path.scenario_B_indentation
    angles = [20.0, 50.0]
    if scenario == "B+":
        angles.append(1.02 * mindlin.critical_angle_B_indentation(friction, hertz))
    for alpha in angles:
        path = build(alpha, hertz)
        solution = solve_path(hertz, path, friction=friction)
        start = path.first_contact_time()
        corner, turn = path.corner_times[1] - start, path.corner_times[2] - start  # d_max; the far end of the motion
        onsets = [event.depth for event in solution.events
                  if event.kind is EventKind.SLIP_ONSET and corner <= event.time < turn]
        expected = closed(alpha, friction, hertz)
        reached = expected <= path.waypoints[2, 1] if scenario == "B+" else expected >= path.waypoints[2, 1]
        if reached:
            assert onsets[0] == pytest.approx(expected, abs=1e-9 * hertz.d_max), (alpha, onsets, expected)
        else:
            assert not onsets, (alpha, onsets, expected)


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
def test_the_integrated_force_is_the_springs_caps_on_the_stored_anchors(hertz, friction):
    """Along growth in slip, reversals while shrinking and growing, and shrinking to zero: F_x from the ODE equals
    2G* ∫ clip(x − Y, −ū(ξ), ū(ξ)) dξ on the stored anchors with the law's caps (AnchorMap.coulomb_shift_integral,
    independent of the right-hand side), to 1e-9 of the largest force."""
    from mdr_events.models.continuum import algebraic_tangential_force
    path = me.Path(np.array([(0.0, 0.0), (60e-6, 80e-6), (20e-6, 50e-6), (50e-6, 90e-6), (-70e-6, 0.0)]), speed=1e-6)
    solution = solve_path(hertz, path, friction=friction)
    times = np.linspace(0.0, solution.end_time, 997)
    integrated = evaluate(solution, times)["tangential_force"]
    algebraic = algebraic_tangential_force(solution, times)
    np.testing.assert_allclose(integrated, algebraic, rtol=0, atol=1e-9 * np.nanmax(np.abs(integrated)))


@pytest.mark.parametrize("friction", [COULOMB, COMBINED], ids=lambda f: f.law)
def test_the_continuums_work_over_a_mindlin_cycle_is_the_loop_energy(hertz, friction):
    """x: 0 → X → −X → X → −X at DEPTH: the continuum's ∫ F_x dx over the closed cycle −X → X → −X equals
    mindlin.loop_energy(X) to 1e-8 (the solver's rtol over a loop whose area is a small difference of large
    integrals)."""
    from mdr_events.models.continuum import tangential_work
    X = 0.5 * mindlin.full_slip_shift(DEPTH, friction, hertz)
    path = me.Path(np.array([(0.0, 0.0), (0.0, DEPTH), (X, DEPTH), (-X, DEPTH), (X, DEPTH), (-X, DEPTH)]), speed=1e-6)
    solution = solve_path(hertz, path, friction=friction)
    start = path.first_contact_time()
    work = tangential_work(solution, path.corner_times[3] - start, path.corner_times[5] - start)
    assert work == pytest.approx(mindlin.loop_energy(X, DEPTH, friction, hertz), rel=1e-8)
