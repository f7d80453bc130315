"""Property-based tests over the whole parameter space (hypothesis; bounded example counts).

Parameters are drawn log-uniformly over ranges well beyond the paper's
(E 0.1–5 MPa, R 5–200 mm, d_max 20 µm–1 mm, works of adhesion 1e-3–0.5 J/m²
in either order or zero, τ0 0–200 kPa), with both scenarios and any angle.
"""

import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mdr_events as me
from mdr_events import analytic, symbolic
from mdr_events.convergence import HISTORY_QUANTITIES, history_differences
from mdr_events.simulate import scenario_paths


#: HYPOTHESIS_PROFILE=explore (see conftest.py) draws five times as many fresh examples.
SCALE = 5 if os.environ.get("HYPOTHESIS_PROFILE") == "explore" else 1
#: Discrete runs longer than this many steps are skipped (each example must stay within seconds).
MAX_STEPS = 40_000


def log_uniform(low, high):
    return st.floats(math.log10(low), math.log10(high)).map(lambda exponent: 10.0**exponent)


def work_of_adhesion():
    return st.one_of(st.just(0.0), log_uniform(1e-3, 0.5))


@st.composite
def cases(draw, adhesion=work_of_adhesion(), friction=st.one_of(st.just(0.0), log_uniform(1e3, 2e5)),
          smallest_angle=0.0):
    params = me.Parameters(E=draw(log_uniform(0.1e6, 5e6)), nu=draw(st.floats(0.0, 0.5)),
                           R=draw(log_uniform(5e-3, 0.2)), tau0=draw(friction), dgamma0=draw(adhesion),
                           dgamma1=draw(adhesion), d_max=draw(log_uniform(2e-5, 1e-3)), v=1e-6)
    scenario = draw(st.sampled_from(["A", "B"]))
    # A at 0° never reaches d_max; below about 1e-5° the path is kilometres long and rejected (tested
    # in test_edges), so the angles are 0 (B) or at least 1e-3°
    low = max(smallest_angle, 1.0 if scenario == "A" else 1e-3)
    angles = st.floats(low, 90.0)
    alpha = draw(angles if scenario == "A" or smallest_angle > 0 else st.one_of(st.just(0.0), angles))
    return params, scenario, alpha


def branch_depth(radius, params, work):
    return np.asarray(analytic.jkr_depth(radius, params, work))


def in_contact(dataset):
    radius = dataset["contact_radius"].values[0]
    return np.isfinite(radius) & (radius > 0)


@settings(max_examples=40 * SCALE, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases())
def test_continuum_invariants(case):
    """No NaN in contact; |F_x| <= τ0 A; d lies on or between the adhesive branches (9) of the radius and
    F_N is JKR (10) wherever it lies on one; the same input gives the same bits."""
    params, scenario, alpha = case
    ds = me.simulate(params, scenario, alpha=[alpha], method="continuum", samples=501)
    touching = in_contact(ds)
    assert touching.any()
    for name in ("indentation_depth", "tangential_displacement", "normal_force", "tangential_force",
                 "contact_area", "mean_pressure", "mean_shear_stress", "sliding_fraction"):
        assert np.all(np.isfinite(ds[name].values[0][touching])), name
    force = np.abs(ds["tangential_force"].values[0][touching])
    cap = params.tau0 * ds["contact_area"].values[0][touching]
    # the integrated F_x carries an absolute error of order rtol (1e-10) times its largest value, so a
    # contact shrinking to nothing (Hertz) meets its cap to that, not relatively
    assert np.all(force <= cap + 1e-9 * cap.max())
    radius = ds["contact_radius"].values[0][touching]
    depth = ds["indentation_depth"].values[0][touching]
    normal = ds["normal_force"].values[0][touching]
    tolerance = 1e-9 * params.d_max
    branches = [(work, branch_depth(radius, params, work)) for work in (params.dgamma0, params.dgamma1)]
    lowest = np.minimum(branches[0][1], branches[1][1])
    highest = np.maximum(branches[0][1], branches[1][1])
    assert np.all(depth >= lowest - tolerance) and np.all(depth <= highest + tolerance)
    scale = np.max(np.abs(normal))
    for work, on_branch_depth in branches:
        on = np.abs(depth - on_branch_depth) <= tolerance
        jkr = np.asarray(analytic.jkr_normal_force(radius[on], params, work))
        np.testing.assert_allclose(normal[on], jkr, rtol=0, atol=1e-8 * scale)
    again = me.simulate(params, scenario, alpha=[alpha], method="continuum", samples=501)
    assert again.identical(ds)


def resolving_time_step(params, dx):
    """A time step whose own error stays below the spacing's: it moves the radius by at most Δx/4, the
    indenter by at most Δx/4 and by at most ū(a_min) Δx/a_max, a share Δx/a_max of the critical shift
    of the smallest radius (stiff springs with a small τ0 have ū well below Δx; the discrete model's
    first springs attach one step late, which offsets F_x by one step of travel against ū)."""
    a_max = float(me.jkr_contact_radius(params.d_max, params, params.dgamma0))
    a0 = analytic.jump_in_radius(params, params.dgamma0) if params.dgamma0 > 0 else 0.0
    radii = np.linspace(max(a0, a_max / 10), a_max, 50)
    slope = float(np.min(symbolic.relation("jkr_depth_slope").numeric(radii, params.R, params.E_star,
                                                                      params.dgamma0)))
    moves = [dx / 4, dx * slope / 4]
    if params.tau0 > 0:
        moves.append(float(analytic.critical_shift(radii[0], params)) * dx / a_max)
    return min(moves) / params.v


def assert_contact_differs_only_at_the_jumps(discrete, continuum, params, dx, a_max):
    """Where one method is in contact and the other not, the depth is within 2 a_max Δx / R (the depth
    that one spring of radius makes on the Hertz branch) plus one step of a jump-in (d = 0) or of the
    continuum's pull-off depth: the discrete model meets these jumps with its quantised radius."""
    area_d, area_c = discrete["contact_area"].values[0], continuum["contact_area"].values[0]
    depth = discrete["indentation_depth"].values[0]
    finite = np.isfinite(area_d) & np.isfinite(area_c)
    differs = finite & ((area_d > 0) != (area_c > 0))
    kinds = list(continuum["event_kind"].values[0])
    jumps = [0.0] + [float(continuum["event_depth"].values[0][i]) for i, kind in enumerate(kinds)
                     if kind in ("pull_off", "contact_ends")]
    step = np.max(np.abs(np.diff(depth[np.isfinite(depth)])))
    window = 2 * a_max * dx / params.R + step
    for value in depth[differs]:
        assert min(abs(value - jump) for jump in jumps) <= window, (value, jumps, window)


@settings(max_examples=8 * SCALE, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases(smallest_angle=5.0))
def test_discrete_agrees_with_the_continuum_within_its_spacing(case):
    """With Δx = a_max/200 and a time step that resolves the radius, max_t |discrete − continuum| of F_N,
    F_x and A stays below 4 Δx/a_max of each quantity's largest value (observed: at most 2.4; one spring
    of radius is Δx/a of A and about 2Δx/a of the forces). The discrete model also keeps |F_x| <= τ0 A,
    has no NaN in contact and repeats bit for bit."""
    params, scenario, alpha = case
    a_max = float(me.jkr_contact_radius(params.d_max, params, params.dgamma0))
    dx = a_max / 200
    step = resolving_time_step(params, dx)
    path = scenario_paths(params, scenario, [alpha])[0][0]
    if (path.duration - path.first_contact_time()) / step > MAX_STEPS:
        return  # a stiff, low-friction case needing too many steps for a test
    discrete = me.simulate(params, scenario, alpha=[alpha], dx=dx, dt=step)
    continuum = me.simulate(params, scenario, alpha=[alpha], method="continuum", t=discrete["time"].values)
    differences = history_differences(discrete, continuum)
    for name in HISTORY_QUANTITIES:
        assert differences[name][0] <= 4 * dx / a_max, (name, differences[name][0] / (dx / a_max))
    assert_contact_differs_only_at_the_jumps(discrete, continuum, params, dx, a_max)
    touching = in_contact(discrete)
    force = np.abs(discrete["tangential_force"].values[0][touching])
    assert np.all(force <= params.tau0 * discrete["contact_area"].values[0][touching] * (1 + 1e-12))
    for name in ("normal_force", "tangential_force", "contact_area"):
        assert np.all(np.isfinite(discrete[name].values[0][touching])), name
    again = me.simulate(params, scenario, alpha=[alpha], dx=dx, dt=step)
    assert again.identical(discrete)


@settings(max_examples=60 * SCALE, deadline=None)
@given(cases(smallest_angle=1.0))
def test_closed_form_18_agrees_with_the_continuum_slip_onset(case):
    """Scenario A: where (18) puts slip onset inside the indentation, the continuum logs it there (1e-9)."""
    params, _, alpha = case
    if params.tau0 == 0.0 or params.dgamma0 == 0.0:
        return
    onset = float(me.d_crit(alpha, params, "A", adhesion=True))
    if not onset < params.d_max * (1 - 1e-6):
        return
    ds = me.simulate(params, "A", alpha=[alpha], method="continuum", samples=11)
    kinds = list(ds["event_kind"].values[0])
    depth = ds["event_depth"].values[0][kinds.index("slip_onset")]
    assert kinds.index("slip_onset") < kinds.index("corner")
    assert depth == pytest.approx(onset, rel=1e-9)


@st.composite
def monotone_paths(draw):
    """Random paths of 2–5 segments whose tangential motion does not reverse (the continuum's domain):
    in and out of the elastomer, pinned slides, re-indentation, ending below the jump-off depth."""
    params, _, _ = draw(cases(friction=log_uniform(1e3, 2e5)))
    scale = params.d_max
    points = [(0.0, 0.0)]
    # shares of d_max in steps of 1e-3: meaningful corners, not subnormal grazes of the surface
    def share(low, high):
        return st.integers(round(low * 1000), round(high * 1000)).map(lambda k: k / 1000 * scale)

    for _ in range(draw(st.integers(1, 4))):
        x = points[-1][0] + draw(st.sampled_from([0.0, 1.0])) * draw(share(0.05, 3.0))
        depth = draw(share(-0.2, 1.2))
        if (x, depth) != points[-1]:
            points.append((x, depth))
    if max(depth for _, depth in points) <= 0.0:
        points.append((points[-1][0], scale))
    exit_depth = me.paths.exit_depth(params)
    points.append((points[-1][0] + draw(share(0.0, 2.0)), exit_depth))
    return params, me.Path(points, params.v)


@settings(max_examples=25 * SCALE, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(monotone_paths())
def test_general_paths_integrated_force_is_the_algebraic_form(case):
    """Along any monotone path the integrated F_x equals F_x = 2G*[cū + ∫_c^a (x − Y) dξ] from the
    anchor map in force (1e-7 of its largest value: rtol = 1e-10 per step, accumulated over the
    spans), stays within τ0 A and is finite in contact."""
    params, path = case
    solution = me.continuum.solve_path(params, path)
    times = np.linspace(0.0, solution.end_time, 301)[:-1]
    filled = me.continuum.evaluate(solution, times)
    algebraic = me.continuum.algebraic_tangential_force(solution, times)
    scale = max(np.max(np.abs(algebraic)), 1e-300)
    np.testing.assert_allclose(filled["tangential_force"], algebraic, rtol=0, atol=1e-7 * scale)
    area = np.pi * filled["contact_radius"] ** 2
    assert np.all(np.abs(filled["tangential_force"]) <= params.tau0 * area + 1e-7 * scale)
    touching = filled["contact_radius"] > 0
    for name, values in filled.items():
        assert np.all(np.isfinite(values[touching])), name


@settings(max_examples=4 * SCALE, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(monotone_paths())
def test_general_paths_discrete_agrees_with_the_continuum(case):
    """The discrete model follows the continuum along random monotone paths as along the scenarios
    (4 Δx/a_max; corner-straddling steps and jump samples left out)."""
    params, path = case
    a_max = float(me.jkr_contact_radius(min(path.max_depth, params.d_max * 1.2), params, params.dgamma0))
    dx = a_max / 200
    step = resolving_time_step(params, dx)
    if (path.duration - path.first_contact_time()) / step > MAX_STEPS:
        return  # a long, shallow path: too many steps for a test
    discrete = me.simulate(params, path, dx=dx, dt=step)
    continuum = me.simulate(params, path, method="continuum", t=discrete["time"].values)
    differences = history_differences(discrete, continuum)
    for name in HISTORY_QUANTITIES:
        assert differences[name][0] <= 4 * dx / a_max, (name, differences[name][0] / (dx / a_max))
    assert_contact_differs_only_at_the_jumps(discrete, continuum, params, dx, a_max)
