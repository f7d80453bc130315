"""Property-based tests over the whole parameter space (hypothesis; bounded example counts).

Parameters are drawn log-uniformly over ranges well beyond the paper's
(E 0.1–5 MPa, R 5–200 mm, d_max 20 µm–1 mm, works of adhesion 1e-3–0.5 J/m²
in either order or zero, τ0 0–200 kPa), with both scenarios and any angle.

Every test checks what it states in (nearly) every example: where a property
needs a condition (friction and adhesion, slip during indentation, a discrete
run short enough for a test), the strategy draws the parameters so that the
condition holds, and ``assume`` is left only for rare leftovers. Each test
labels its examples with ``hypothesis.event``; ``pytest
--hypothesis-show-statistics`` shows the shares and the filtered examples.
"""

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, event, example, given, note, settings
from hypothesis import strategies as st

import mdr_events as me
from mdr_events.models import paths
from mdr_events.models import continuum
from mdr_events.theory import analytic
from mdr_events.theory import symbolic
from mdr_events.analysis.convergence import HISTORY_QUANTITIES, compared_samples, first_order_error_bound
from mdr_events.models.methods import MIN_STEPS_PER_SEGMENT
from mdr_events.models.motion import scenario_paths
from quick_round import examples


#: Discrete runs are drawn to need at most this many time steps: the spring model takes about 50 µs a
#: step at Δx = a_max/200, so a run stays within about a second (the spacing test runs it twice).
MAX_STEPS = 20_000
#: The range of τ0 (Pa) where friction is drawn nonzero.
FRICTION = (1e3, 2e5)


def log_uniform(low, high):
    return st.floats(math.log10(low), math.log10(high)).map(lambda exponent: 10.0**exponent)


def work_of_adhesion():
    return st.one_of(st.just(0.0), log_uniform(1e-3, 0.5))


def friction():
    return st.one_of(st.just(0.0), log_uniform(*FRICTION))


@st.composite
def parameters(draw, adhesion=work_of_adhesion(), friction=friction()):
    return me.Parameters(E=draw(log_uniform(0.1e6, 5e6)), nu=draw(st.floats(0.0, 0.5)),
                         R=draw(log_uniform(5e-3, 0.2)), tau0=draw(friction), dgamma0=draw(adhesion),
                         dgamma1=draw(adhesion), d_max=draw(log_uniform(2e-5, 1e-3)), v=1e-6)


def angles(scenario, smallest_angle=0.0):
    # A at 0° never reaches d_max; below about 1e-5° the path is kilometres long and rejected (tested
    # in test_edges), so the angles are 0 (B) or at least 1e-3°
    low = max(smallest_angle, 1.0 if scenario == "A" else 1e-3)
    drawn = st.floats(low, 90.0)
    return drawn if scenario == "A" or smallest_angle > 0 else st.one_of(st.just(0.0), drawn)


@st.composite
def cases(draw, adhesion=work_of_adhesion(), friction=friction(), smallest_angle=0.0):
    params = draw(parameters(adhesion, friction))
    scenario = draw(st.sampled_from(["A", "B"]))
    return params, scenario, draw(angles(scenario, smallest_angle))


def label_parameters(params):
    """``event`` labels: which works of adhesion and friction an example has."""
    if params.dgamma0 == params.dgamma1:
        event("adhesion: none" if params.dgamma0 == 0 else "adhesion: dgamma1 = dgamma0")
    else:
        event("adhesion: dgamma1 > dgamma0" if params.dgamma1 > params.dgamma0 else "adhesion: dgamma1 < dgamma0")
    event("friction: tau0 = 0" if params.tau0 == 0 else "friction: tau0 > 0")


def branch_depth(radius, params, work):
    return np.asarray(analytic.jkr_depth(radius, params, work))


def in_contact(dataset):
    radius = dataset["contact_radius"].values[0]
    return np.isfinite(radius) & (radius > 0)


@settings(max_examples=examples(40), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cases())
def test_continuum_invariants(case):
    """No NaN in contact; |F_x| <= τ0 A; d lies on or between the adhesive branches (9) of the radius and
    F_N is JKR (10) wherever it lies on one; the same input gives the same bits."""
    params, scenario, alpha = case
    event(f"scenario {scenario}")
    label_parameters(params)
    ds = me.simulate(params, scenario, alpha=[alpha], method="continuum", samples=501)
    touching = in_contact(ds)
    assert touching.any()
    event("slides" if np.nanmax(ds["sliding_fraction"].values[0]) > 0 else "never slides")
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


def time_step_moves(params, dx):
    """The largest path move per step of :func:`resolving_time_step`: ``(geometric, shift)`` with the
    friction-free part ``min(Δx/4, Δx (∂d/∂a)/4)`` and the friction part ``ū(a_min) Δx/a_max`` (0
    without friction)."""
    a_max = float(me.jkr_contact_radius(params.d_max, params, params.dgamma0))
    a0 = analytic.jump_in_radius(params, params.dgamma0) if params.dgamma0 > 0 else 0.0
    radii = np.linspace(max(a0, a_max / 10), a_max, 50)
    slope = float(np.min(symbolic.relation("jkr_depth_slope").numeric(radii, params.R, params.E_star,
                                                                      params.dgamma0)))
    shift = float(analytic.critical_shift(radii[0], params)) * dx / a_max
    return min(dx / 4, dx * slope / 4), shift


def resolving_time_step(params, dx):
    """A time step whose own error stays below the spacing's: it moves the radius by at most Δx/4, the
    indenter by at most Δx/4 and by at most ū(a_min) Δx/a_max, a share Δx/a_max of the critical shift
    of the smallest radius (stiff springs with a small τ0 have ū well below Δx; the discrete model's
    first springs attach one step late, which offsets F_x by one step of travel against ū)."""
    geometric, shift = time_step_moves(params, dx)
    return (min(geometric, shift) if params.tau0 > 0 else geometric) / params.v


def segment_time_step(path):
    """The largest time step the discrete model accepts on ``path``: MIN_STEPS_PER_SEGMENT steps on its
    shortest segment in contact (``mdr_events.simulate.check_time_step``)."""
    start = path.first_contact_time()
    times = path.corner_times
    shortest = min(t1 - max(t0, start) for t0, t1 in zip(times[:-1], times[1:]) if t1 > start)
    return shortest / MIN_STEPS_PER_SEGMENT


def path_time_step(params, path, dx):
    """:func:`resolving_time_step`, refined where a short segment of ``path`` needs it."""
    return min(resolving_time_step(params, dx), segment_time_step(path))


def steps_in_contact(params, path, dx):
    return (path.duration - path.first_contact_time()) / path_time_step(params, path, dx)


def resolvable_friction(draw, params, path, dx, frictionless=True):
    """Draw τ0 for ``params`` (whose τ0 is ignored) so that the discrete run along ``path`` needs at
    most :data:`MAX_STEPS` steps: the friction part of the time step, ``ū(a_min) Δx/a_max``, is
    proportional to τ0, so τ0 is drawn log-uniformly above the τ0 at which it allows exactly
    MAX_STEPS (and 0 if ``frictionless``). A case whose friction-free step already needs more steps
    (a path far longer than the contact, or with a very short segment in contact) is filtered by
    ``assume``: rare (see the statistics)."""
    length = path.duration - path.first_contact_time()
    geometric, shift_per_pascal = time_step_moves(params.replace(tau0=1.0), dx)
    fits = length / min(geometric / params.v, segment_time_step(path)) <= MAX_STEPS
    if not fits:
        event("steps: too many even without friction (filtered)")
    assume(fits)
    lowest = max(FRICTION[0], length * params.v / (MAX_STEPS * shift_per_pascal))
    choices = ([st.just(0.0)] if frictionless else []) + ([log_uniform(lowest, FRICTION[1])]
                                                          if lowest <= FRICTION[1] else [])
    if not choices:
        event("steps: no tau0 in range fits (filtered)")
    assume(choices)
    tau0 = draw(st.one_of(choices))
    if tau0 > 0 and lowest > FRICTION[0]:
        event("tau0 raised to bound the steps")
    return params.replace(tau0=tau0)


@st.composite
def resolvable_cases(draw, smallest_angle=5.0):
    """:func:`cases` whose discrete run at Δx = a_max/200 needs at most :data:`MAX_STEPS` steps.

    The friction-free part of the time step fixes the steps a path needs without friction; the
    path shortens as α grows (in or out at α over d_max/sin α), so the angle is drawn above the
    smallest one that fits (found by bisection), and then τ0 by :func:`resolvable_friction`."""
    params = draw(parameters(friction=st.just(0.0)))
    scenario = draw(st.sampled_from(["A", "B"]))
    dx = float(me.jkr_contact_radius(params.d_max, params, params.dgamma0)) / 200
    geometric, _ = time_step_moves(params, dx)

    def path_at(alpha):
        return scenario_paths(params, scenario, [alpha])[0][0]

    def fits(alpha):
        path = path_at(alpha)
        return (path.duration - path.first_contact_time()) / min(geometric / params.v,
                                                                   segment_time_step(path)) <= MAX_STEPS

    low = smallest_angle
    if not fits(low):
        event("angle raised to bound the steps")
        high = 90.0
        event("steps: fit at some angle" if fits(high) else "steps: too many even at 90° (filtered)")
        assume(fits(high))
        while high - low > 1e-9 * high:
            middle = 0.5 * (low + high)
            low, high = (low, middle) if fits(middle) else (middle, high)
        low = high
    alpha = draw(st.floats(low, 90.0))
    return resolvable_friction(draw, params, path_at(alpha), dx), scenario, alpha


def assert_contact_differs_only_at_the_jumps(discrete, continuum_run, params, dx, a_max):
    """Where one method is in contact and the other not, the depth is within one step of a jump-in
    (d = 0) or of the continuum's pull-off depth, plus the change of the depth threshold of the spring
    at the edge over the discrete radius's error (< Δx): 2 a_max Δx / R on the Hertz part, and at a
    pull-off Δx |∂d1/∂a| of the Δγ1 branch (9) next to the pull-off radius (zero at the fold, large
    where a held radius inside the fold comes off at once)."""
    area_d, area_c = discrete["contact_area"].values[0], continuum_run["contact_area"].values[0]
    depth = discrete["indentation_depth"].values[0]
    finite = np.isfinite(area_d) & np.isfinite(area_c)
    differs = finite & ((area_d > 0) != (area_c > 0))
    kinds = list(continuum_run["event_kind"].values[0])
    step = np.max(np.abs(np.diff(depth[np.isfinite(depth)])))
    window = 2 * a_max * dx / params.R + step
    detach = continuum.Branch(params, params.dgamma1)
    jumps = [(0.0, window)]
    for i, kind in enumerate(kinds):
        if kind in ("pull_off", "contact_ends"):
            radius = float(continuum_run["event_radius"].values[0][i])
            slopes = [abs(detach.slope(r)) for r in (max(radius - dx, 0.5 * radius), radius + dx) if r > 0]
            jumps.append((float(continuum_run["event_depth"].values[0][i]), window + dx * max(slopes, default=0.0)))
    for value in depth[differs]:
        assert any(abs(value - jump) <= allowed for jump, allowed in jumps), (value, jumps)


#: Rounding of the algebraic form F_x = 2G*[c ū + x (a − c) − ∫_c^a Y dξ]: x (a − c) and ∫ Y are
#: positions of size max|x| times a length a, and each of them, their difference and c ū rounds to
#: eps of that, so the form is exact to 4 eps · 2G* a max|x|. It matters only where F_x vanishes while
#: x does not (a path that slides outside the elastomer and then indents vertically). Besides, the
#: integration takes a velocity component below 1e-12 of the speed as zero (x of a path at 90° − 1e-14°
#: is 2e-16 of its length): 2G* a · 1e-12 · (path length) (``continuum.NEGLIGIBLE_SHARE``).
ALGEBRAIC_ROUNDING = 4 * np.finfo(float).eps


def assert_integrated_force_is_the_algebraic_form(params, path):
    """The continuum's integrated F_x along ``path`` (at 300 times) equals the algebraic form
    F_x = 2G*[cū + ∫_c^a (x − Y) dξ] from the anchor map in force, to 1e-7 of its largest value
    (rtol = 1e-10 per step, accumulated over the spans) plus its rounding and the velocity components
    the integration drops (:data:`ALGEBRAIC_ROUNDING`). Returns the evaluated samples and that
    tolerance."""
    solution = continuum.solve_path(params, path)
    times = np.linspace(0.0, solution.end_time, 301)[:-1]
    filled = continuum.evaluate(solution, times)
    algebraic = continuum.algebraic_tangential_force(solution, times)
    scale = max(np.max(np.abs(algebraic)), 1e-300)
    rounding = 2 * params.G_star * np.nanmax(filled["contact_radius"]) * (
        ALGEBRAIC_ROUNDING * np.nanmax(np.abs(filled["tangential_displacement"]))
        + continuum.NEGLIGIBLE_SHARE * path.speed * path.duration)
    tolerance = 1e-7 * scale + rounding
    np.testing.assert_allclose(filled["tangential_force"], algebraic, rtol=0, atol=tolerance,
                               err_msg="the continuum's integrated F_x is off its own algebraic form")
    return filled, tolerance


def assert_within_first_order_bound(discrete, continuum, params, dx):
    """``max_t |discrete − continuum|`` of F_N, F_x and A over the compared samples (jumps and
    corner-straddling samples left out) stays within :func:`mdr_events.convergence.first_order_error_bound`:
    the change of each quantity with the radius at fixed depth, over the radius error Δx/2 (rounding)
    plus the growth missed at a cut corner, and for F_x one step of travel of springs attaching late.
    No factor is added to it: the bound is the worst case of these errors, and the error reaches it
    (error/bound up to 0.998 over 180 scenario and 130 path examples; the ratio is noted)."""
    compared = compared_samples(discrete, continuum)
    assert compared[0].any()
    bounds = first_order_error_bound(continuum, params, dx, compared, discrete)
    for name in HISTORY_QUANTITIES:
        error = float(np.max(np.abs(discrete[name].values[0] - continuum[name].values[0])[compared[0]]))
        bound = bounds[name][0]
        note(f"{name}: error {error:.4g}, bound {bound:.4g}, ratio {error / bound if bound else 0.0:.3f}")
        assert error <= bound, (name, error, bound, error / bound if bound else math.inf)


@settings(max_examples=examples(8), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(resolvable_cases())
# found by the explore profile: F_x of B peaks after Δγ1 = 0 dropped the radius to a quarter of a_max
@example((me.Parameters(E=1e5, nu=0.0, R=10**-0.75, tau0=1e3, dgamma0=10**-0.375, dgamma1=0.0, d_max=10**-4.5,
                        v=1e-6), "B", 5.0))
def test_discrete_agrees_with_the_continuum_within_its_spacing(case):
    """With Δx = a_max/200 and a time step that resolves the radius, max_t |discrete − continuum| of F_N,
    F_x and A stays within the first-order error bound (:func:`assert_within_first_order_bound`). The
    discrete model also keeps |F_x| <= τ0 A, has no NaN in contact and repeats bit for bit."""
    params, scenario, alpha = case
    event(f"scenario {scenario}")
    label_parameters(params)
    a_max = float(me.jkr_contact_radius(params.d_max, params, params.dgamma0))
    dx = a_max / 200
    path = scenario_paths(params, scenario, [alpha])[0][0]
    step = path_time_step(params, path, dx)
    assert steps_in_contact(params, path, dx) <= MAX_STEPS * (1 + 1e-9)
    assert_integrated_force_is_the_algebraic_form(params, path)  # the reference first
    discrete = me.simulate(params, scenario, alpha=[alpha], dx=dx, dt=step)
    continuum = me.simulate(params, scenario, alpha=[alpha], method="continuum", t=discrete["time"].values)
    assert_within_first_order_bound(discrete, continuum, params, dx)
    assert_contact_differs_only_at_the_jumps(discrete, continuum, params, dx, a_max)
    touching = in_contact(discrete)
    force = np.abs(discrete["tangential_force"].values[0][touching])
    assert np.all(force <= params.tau0 * discrete["contact_area"].values[0][touching] * (1 + 1e-12))
    for name in ("normal_force", "tangential_force", "contact_area"):
        assert np.all(np.isfinite(discrete[name].values[0][touching])), name
    again = me.simulate(params, scenario, alpha=[alpha], dx=dx, dt=step)
    assert again.identical(discrete)


#: The smallest angle of the slip-onset test (the paths of smaller ones are long; see cases()).
SLIP_ONSET_SMALLEST_ANGLE = 1.0


@st.composite
def slip_during_indentation(draw):
    """Scenario A cases with τ0 > 0 and Δγ0 > 0 at an angle below the critical one (so that slip
    begins before d_max): the angle is drawn from [1°, α_c). A critical angle below 1° (large τ0, soft
    elastomer, shallow d_max) is filtered by ``assume``: rare (see the statistics)."""
    params = draw(parameters(adhesion=log_uniform(1e-3, 0.5), friction=log_uniform(*FRICTION)))
    critical = me.critical_angle(params, "A", adhesion=True)
    event("critical angle >= 1°" if critical > SLIP_ONSET_SMALLEST_ANGLE else "critical angle < 1° (filtered)")
    assume(critical > SLIP_ONSET_SMALLEST_ANGLE)
    alpha = draw(st.floats(SLIP_ONSET_SMALLEST_ANGLE, critical, exclude_max=True))
    return params, "A", alpha


@settings(max_examples=examples(60), deadline=None)
@given(slip_during_indentation())
def test_closed_form_18_agrees_with_the_continuum_slip_onset(case):
    """Scenario A: where (18) puts slip onset inside the indentation, the continuum logs it there (1e-9)."""
    params, _, alpha = case
    onset = float(me.d_crit(alpha, params, "A", adhesion=True))
    # below α_c the onset lies below d_max; only angles within rounding of α_c meet it at d_max
    inside = onset < params.d_max * (1 - 1e-6)
    event("onset inside the indentation" if inside else "onset at d_max to rounding (filtered)")
    assume(inside)
    tenth = min(int(10 * onset / params.d_max), 9)
    event(f"onset at {tenth / 10:.1f}–{(tenth + 1) / 10:.1f} d_max")
    ds = me.simulate(params, "A", alpha=[alpha], method="continuum", samples=11)
    kinds = list(ds["event_kind"].values[0])
    assert "slip_onset" in kinds, kinds
    depth = ds["event_depth"].values[0][kinds.index("slip_onset")]
    assert kinds.index("slip_onset") < kinds.index("corner")
    assert depth == pytest.approx(onset, rel=1e-9)


def path_points(draw, params, slide=3.0):
    """Random waypoints of 2–7 segments, any tangential direction (reversals in and out of contact): in
    and out of the elastomer, pinned slides, re-indentation, at most one pull-off well below the
    jump-off depth followed by a new contact, ending below the jump-off depth. Each segment moves at most
    ``slide`` d_max sideways (0.05–3 d_max by default)."""
    scale = params.d_max
    points = [(0.0, 0.0)]
    # shares of d_max in steps of 1e-3: meaningful corners, not subnormal grazes of the surface
    def share(low, high):
        return st.integers(round(low * 1000), round(high * 1000)).map(lambda k: k / 1000 * scale)

    exit_depth = paths.exit_depth(params)
    pull_off_after = draw(st.sampled_from([None, 1, 2]))
    for index in range(draw(st.integers(1, 4))):
        x = points[-1][0] + draw(st.sampled_from([-1.0, 0.0, 1.0])) * draw(share(0.05, slide))
        depth = draw(share(-0.2, 1.2))
        if (x, depth) != points[-1]:
            points.append((x, depth))
        if index + 1 == pull_off_after and max(d for _, d in points) > 0.0:
            points.append((points[-1][0], exit_depth))  # out well beyond the pull-off, then in again
            event("pulled off and in again")
    if max(depth for _, depth in points) <= 0.0 or points[-1][1] <= exit_depth:
        points.append((points[-1][0], scale))
    points.append((points[-1][0] + draw(st.sampled_from([-1.0, 1.0])) * draw(share(0.0, 2.0 * slide / 3.0)),
                   exit_depth))
    return points


@st.composite
def any_paths(draw):
    """Random paths (:func:`path_points`) with τ0 > 0."""
    params, _, _ = draw(cases(friction=log_uniform(*FRICTION)))
    return params, me.Path(path_points(draw, params), params.v)


def path_spacing(params, path):
    """Δx = a_max/200 with a_max the radius at the path's deepest point (at most 1.2 d_max)."""
    return float(me.jkr_contact_radius(min(path.max_depth, params.d_max * 1.2), params, params.dgamma0)) / 200


#: Sideways extent of the segments of the discrete model's random paths, in d_max: without adhesion
#: the friction-free time step moves the indenter by d_max/4000, so a path much longer than 5 d_max
#: cannot fit MAX_STEPS; 1 instead of 3 (the continuum's paths) keeps nearly all of them within it.
DISCRETE_PATH_SLIDE = 1.0


@st.composite
def resolvable_paths(draw):
    """Random paths whose discrete run at :func:`path_spacing` needs at most MAX_STEPS steps
    (shorter slides, :data:`DISCRETE_PATH_SLIDE`; τ0 > 0 drawn by :func:`resolvable_friction`, the
    path does not depend on τ0)."""
    params, _, _ = draw(cases(friction=st.just(FRICTION[0])))
    path = me.Path(path_points(draw, params, slide=DISCRETE_PATH_SLIDE), params.v)
    return resolvable_friction(draw, params, path, path_spacing(params, path), frictionless=False), path


def label_path(path):
    event(f"{len(path.waypoints) - 1} segments")
    steps = np.diff(path.waypoints[:, 0])
    moving = np.sign(steps[steps != 0.0])
    event("tangential reversal" if np.any(moving[1:] != moving[:-1]) else "no tangential reversal")


#: Hertz contact, in at two slopes and out vertically: the continuum's integrated F_x is 8% of its
#: largest value off its own algebraic form and 9% above τ0 A, while the discrete model follows the
#: algebraic form (to 1e-3 at Δx = a_max/800). A bug of the continuum's integration, not of this test:
#: this example fails until it is fixed.
HERTZ_TWO_SLOPES = (me.Parameters(E=6e5, nu=0.0, R=0.06, tau0=3e4, dgamma0=0.0, dgamma1=0.0, d_max=5e-4, v=1e-6),
                    me.Path([(0.0, 0.0), (1e-3, 5e-5), (1.5e-3, 1e-4), (1.5e-3, -2.5e-5)], 1e-6))
#: Δγ1 = 0 < Δγ0: in at an angle, a short vertical pull (the radius drops to the Δγ1 branch), then
#: slides in and out: the algebraic form reaches 7.8 τ0 A and the integrated F_x peaks at 0.80 N where
#: the discrete model peaks at 1.19 N (1.188 and 1.187 at Δx = a_max/200 and a_max/800). Also a bug of
#: the continuum: this example fails until it is fixed.
SHRINK_THEN_SLIDE = (me.Parameters(E=3.5e5, nu=0.0, R=0.13, tau0=1e4, dgamma0=0.4, dgamma1=0.0, d_max=2e-4, v=1e-6),
                     me.Path([(0.0, 0.0), (2e-4, 1.06e-4), (2e-4, 1.02e-4), (2.2e-4, 7.6e-5), (5e-4, 8.2e-5),
                              (5.1e-4, -1e-5)], 1e-6))


@settings(max_examples=examples(25), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(any_paths())
@example(HERTZ_TWO_SLOPES)
@example(SHRINK_THEN_SLIDE)
def test_general_paths_integrated_force_is_the_algebraic_form(case):
    """Along any path (reversals, re-contact) the integrated F_x equals the algebraic form
    (:func:`assert_integrated_force_is_the_algebraic_form`), stays within τ0 A (to the same
    tolerance) and is finite in contact."""
    params, path = case
    label_path(path)
    label_parameters(params)
    filled, tolerance = assert_integrated_force_is_the_algebraic_form(params, path)
    event("slides" if np.nanmax(filled["sliding_fraction"]) > 0 else "never slides")
    area = np.pi * filled["contact_radius"] ** 2
    assert np.all(np.abs(filled["tangential_force"]) <= params.tau0 * area + tolerance)
    touching = filled["contact_radius"] > 0
    for name, values in filled.items():
        assert np.all(np.isfinite(values[touching])), name


@settings(max_examples=examples(4), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(resolvable_paths())
def test_general_paths_discrete_agrees_with_the_continuum(case):
    """The discrete model follows the continuum along random paths (reversals, re-contact) as along the
    scenarios:
    within the first-order error bound (:func:`assert_within_first_order_bound`; corner-straddling
    steps and jump samples left out)."""
    params, path = case
    label_path(path)
    label_parameters(params)
    dx = path_spacing(params, path)
    a_max = dx * 200
    step = path_time_step(params, path, dx)
    assert steps_in_contact(params, path, dx) <= MAX_STEPS * (1 + 1e-9)
    # the reference first: where the continuum's F_x is off its own algebraic form, no bound on the
    # discrete model's distance to it can hold
    assert_integrated_force_is_the_algebraic_form(params, path)
    discrete = me.simulate(params, path, dx=dx, dt=step)
    continuum = me.simulate(params, path, method="continuum", t=discrete["time"].values)
    assert_within_first_order_bound(discrete, continuum, params, dx)
    assert_contact_differs_only_at_the_jumps(discrete, continuum, params, dx, a_max)
