"""The discrete spring model against what section 4 says its figures show, and exact limits."""

import math

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.convergence import discrete_errors, exact_references_A, observed_orders
from mdr_events.models.discrete import run_discrete
from mdr_events.models.paths import Path, exit_depth
from mdr_events.models.motion import FIGURE_ANGLES
from mdr_events.models.simulate import simulate
from mdr_events.models.simulation_schema import SIMULATION_VARIABLES

DX = 2e-6  # 1 550 springs per side at d_max for R = 30 mm


@pytest.fixture(scope="module")
def fig8(paper):
    return simulate(paper, "A", dx=DX, n_steps=6000)


@pytest.fixture(scope="module")
def fig10(paper):
    return simulate(paper, "B", dx=DX, n_steps=6000)


def pinned_radius(p):
    return float(me.jkr_contact_radius(p.d_max, p, p.dgamma0))


def test_schema(fig8, paper, tmp_path):
    assert fig8["normal_force"].dims == ("alpha", "time")
    assert list(fig8["alpha"].values) == list(FIGURE_ANGLES)
    for name, (units, _) in SIMULATION_VARIABLES.items():
        assert fig8[name].attrs["units"] == units and fig8[name].attrs["long_name"]
    assert fig8.attrs["method"] == "discrete" and fig8.attrs["dx"] == DX and fig8.attrs["dt"] > 0
    assert fig8.attrs["program_version"] == me.__version__ and fig8.attrs["doi"] == me.DOI
    assert fig8["time"].values[0] == 0.0
    path = me.write_netcdf(fig8, tmp_path / "fig8.nc")
    xr.testing.assert_identical(me.open_result(path), fig8)


def test_pull_off_force_is_the_same_for_every_angle_and_jkr(fig8, fig10, paper):
    """Section 4.2 (1): |F_N,min| equal for all angles, the JKR pull-off (3/2)πΔγ1R."""
    jkr = 1.5 * math.pi * paper.dgamma1 * paper.R
    # discretisation error: the boundary threshold sits Δx/2 inside a = mΔx, so
    # |ΔF| <~ E* a_F (∂d/∂a) Δx (about 1e-3 of F per µm here); allow 2 Δx worth
    a_F = float(me.symbolic.relation("pull_off_radius").numeric(paper.R, paper.E_star, paper.dgamma1))
    slope = 2 * a_F / paper.R - 0.5 * math.sqrt(2 * math.pi * paper.dgamma1 / (paper.E_star * a_F))
    tolerance = 2 * paper.E_star * a_F * slope * DX
    for ds in (fig8, fig10):
        minima = -ds["normal_force"].min("time").values
        assert np.all(np.abs(minima - jkr) < tolerance), (minima, jkr, tolerance)


def test_scenario_A_constant_area_and_force_at_the_start_of_pull_off(fig8, paper):
    """Section 4.2 (1): A is constant at the start of pull-off, and F_x too."""
    a_max = pinned_radius(paper)
    # the radius stays pinned until d falls to the Δγ1 branch at that radius
    d_release = float(me.jkr_depth(a_max, paper, paper.dgamma1))
    for alpha in fig8["alpha"].values:
        case = fig8.sel(alpha=alpha)
        t_turn = paper.d_max / (paper.v * math.sin(math.radians(alpha)))
        pulling = (case["time"] > t_turn) & (case["contact_radius"] == case["contact_radius"].max())
        depth = case["indentation_depth"].where(pulling, drop=True)
        assert depth.size > 10
        assert float(depth.min()) == pytest.approx(d_release, abs=2 * DX * 0.2 + paper.v * fig8.attrs["dt"])
        force = case["tangential_force"].where(pulling, drop=True).values
        assert np.all(force == force[0])


def test_shear_stress_reaches_tau0_in_pull_off_where_the_model_says(fig8, paper):
    """Section 4.2 (3): during pull-off τ rises to τ0 — once the shrinking radius makes
    ū(a) smaller than the indenter's travel x1 before the jump-off radius is reached."""
    a_jump = me.jump_off(paper, paper.dgamma1)["contact_radius"]
    for alpha in fig8["alpha"].values:
        x1 = paper.d_max / math.tan(math.radians(alpha))
        reaches = me.critical_shift(a_jump, paper) < x1
        tau_max = float(fig8["mean_shear_stress"].sel(alpha=alpha).max())
        if reaches:
            assert tau_max == pytest.approx(paper.tau0, rel=1e-12)
        else:
            assert tau_max < 0.99 * paper.tau0
    assert fig8["mean_shear_stress"].max() <= paper.tau0 * (1 + 1e-12)


def test_first_slip_during_indentation_is_at_d_crit_18(paper):
    alpha_c = me.critical_angle(paper, "A", adhesion=True)
    angles = [8.0, 15.0, 21.0, 24.0, 40.0, 70.0]
    ds = simulate(paper, "A", alpha=angles, dx=1e-6, n_steps=20000)
    for alpha in angles:
        case = ds.sel(alpha=alpha)
        t_turn = paper.d_max / (paper.v * math.sin(math.radians(alpha)))
        indentation = case.where(case["time"] <= t_turn, drop=True)
        sliding = indentation["sliding_fraction"].values > 0
        if alpha > alpha_c:
            assert not sliding.any(), alpha
            continue
        first = int(np.argmax(sliding))
        assert sliding[first]
        depth = float(indentation["indentation_depth"][first])
        expected = me.d_crit(alpha, paper, "A", adhesion=True)
        # d = K a on the slip line: a radius error of a few Δx is K·Δx each, plus one time step of depth
        K = math.tan(math.radians(alpha)) * math.pi * paper.tau0 / (2 * paper.G_star)
        step = paper.v * ds.attrs["dt"] * math.sin(math.radians(alpha))
        assert abs(depth - expected) <= 3 * K * ds.attrs["dx"] + step, (alpha, depth, expected)


def test_vertical_path_has_no_tangential_force(paper):
    ds = simulate(paper, "A", alpha=[90.0], dx=DX, n_steps=2000)
    forces = ds["tangential_force"].values
    assert np.all(forces[np.isfinite(forces)] == 0.0)
    assert np.all(ds["sliding_fraction"].values[np.isfinite(forces) & (ds["contact_radius"].values > 0)] == 0.0)


def test_without_adhesion_loading_is_hertz(paper):
    p = paper.replace(dgamma0=0.0, dgamma1=0.0)
    ds = simulate(p, "A", alpha=[90.0], dx=DX, n_steps=3000).sel(alpha=90.0)
    t_turn = p.d_max / p.v
    loading = ds.where((ds["time"] <= t_turn) & (ds["indentation_depth"] > 0.2 * p.d_max), drop=True)
    d = loading["indentation_depth"].values
    hertz = 4 * p.E_star * math.sqrt(p.R) * d**1.5 / 3
    a = np.sqrt(p.R * d)
    # the radius is resolved to Δx: |ΔF|/F <~ (3/2)·Δx/a
    np.testing.assert_array_less(np.abs(loading["normal_force"].values - hertz) / hertz, 1.5 * DX / a + 1e-12)
    # no jump-in, no jump-off: the contact ends at d = 0
    assert np.nanmin(ds["normal_force"].values) >= 0.0


def test_scenario_B_slips_all_at_once_at_d_crit_21_where_radius_follows_jkr(fig10, paper):
    """Scenario B: every spring has the same shift, so the contact goes from stick to full slip."""
    for alpha in fig10["alpha"].values:
        fraction = fig10["sliding_fraction"].sel(alpha=alpha).values
        values = fraction[np.isfinite(fraction)]
        assert set(np.unique(values)) <= {0.0, 1.0}


def test_convergence_order_against_exact_references(paper):
    spacings = [8e-6, 4e-6, 2e-6]
    errors = discrete_errors(paper, 30.0, spacings, steps_per_spacing=0.5)
    forces = errors["tangential_force_max"]
    assert np.all(np.diff(forces) < 0)
    assert np.all(observed_orders(spacings, forces) > 0.8)
    assert np.all(errors["contact_area_max"] <= 2 * np.array(spacings) / pinned_radius(paper))
    reference = exact_references_A(paper, 30.0)
    assert reference["normal_force_min"] == pytest.approx(-1.5 * math.pi * paper.dgamma1 * paper.R)


@pytest.mark.parametrize("alpha", [10.0, 30.0, 60.0])
def test_the_continuum_extrema_equal_scenario_As_closed_forms(paper, alpha):
    """The references discrete_errors uses for any path (the continuum solution's exact extrema) equal the
    closed forms of scenario A (F_N,min = −(3/2)πΔγ1 R, A_max = π a(d_max)², F_x,max from the stick/slip
    integral at d_max) to the solver's tolerance: two independent routes."""
    extrema = me.continuum.extrema.solution_extrema(me.continuum.solve_path(paper, Path.scenario_A(alpha, paper)))
    for key, value in exact_references_A(paper, alpha).items():
        assert extrema[key] == pytest.approx(value, rel=1e-8), key


def test_same_input_same_output(paper):
    one = simulate(paper, "B", alpha=[20.0, 50.0], dx=4e-6, n_steps=500)
    two = simulate(paper, "B", alpha=[20.0, 50.0], dx=4e-6, n_steps=500)
    xr.testing.assert_identical(one, two)
    for name in SIMULATION_VARIABLES:
        assert one[name].values.tobytes() == two[name].values.tobytes()


def test_custom_path_and_scenario_B_indentation(paper):
    path = Path([(0.0, -1e-5), (0.0, paper.d_max), (2e-4, paper.d_max), (2e-4, -1e-4)], paper.v)
    ds = simulate(paper, path, dx=4e-6, n_steps=2000)
    assert ds["case"].values.tolist() == ["path 1"] and "alpha" not in ds.dims
    assert ds.attrs["scenario"] == "custom" and "(0.0002" in str(ds["path_waypoints"].values[0])
    # time runs from first contact (d = 0 at t = 0)
    assert ds["indentation_depth"].values[0, 0] == pytest.approx(0.0, abs=1e-15)
    plus = simulate(paper, "B+", alpha=[30.0], dx=4e-6, n_steps=3000)
    assert float(plus["indentation_depth"].max()) == pytest.approx(2 * paper.d_max, rel=1e-3)


def test_bad_input(paper):
    with pytest.raises(ValueError, match=r"dx=0.0005 m puts 6 springs per side .* dx <= 0.00031"):
        simulate(paper, "A", alpha=[30.0], dx=5e-4)
    with pytest.raises(ValueError, match="scenario='C'"):
        simulate(paper, "C")
    with pytest.raises(ValueError, match="method='magic'"):
        simulate(paper, "A", method="magic")
    with pytest.raises(ValueError, match="alpha=0.0 in scenario A"):
        simulate(paper, "A", alpha=[0.0])
    with pytest.raises(ValueError, match="alpha=95.0"):
        simulate(paper, "B", alpha=[95.0])
    with pytest.raises(ValueError, match="dt or n_steps"):
        simulate(paper, "A", dt=1.0, n_steps=100)
    with pytest.raises(ValueError, match="n_steps=5"):
        simulate(paper, "A", n_steps=5)
    with pytest.raises(ValueError, match="coincide"):
        Path([(0.0, 0.0), (0.0, 0.0)], 1.0)
    with pytest.raises(ValueError, match="never enters the elastomer"):
        simulate(paper, Path([(0.0, -1.0), (1.0, -1.0)], 1.0))


def test_path_kinematics(paper):
    path = Path.scenario_A(30.0, paper)
    t_turn = paper.d_max / (paper.v * math.sin(math.radians(30.0)))
    assert path.corner_times[1] == pytest.approx(t_turn)
    x, d = path.position([0.0, t_turn / 2, t_turn])
    np.testing.assert_allclose(d, [0.0, paper.d_max / 2, paper.d_max])
    np.testing.assert_allclose(x, [0.0, paper.d_max / 2 / math.tan(math.radians(30.0)),
                                   paper.d_max / math.tan(math.radians(30.0))])
    b = Path.scenario_B(0.0, paper)  # purely tangential: ends after a few ū
    assert b.waypoints[-1, 1] == paper.d_max


def test_pinned_radius_below_the_jump_off_radius_comes_off_at_once(paper):
    """A shallow indentation (held radius a0 < jump-off radius of Δγ1) separates when d falls to
    g(a0) − Δl_max(a0; Δγ1), whatever other, deeper paths run in the same batch."""
    p = paper.replace(dgamma1=1.0, d_max=10e-6)
    shallow = Path([(0.0, 0.0), (0.0, p.d_max), (0.0, -3e-4)], p.v)
    deep = Path([(0.0, 0.0), (0.0, 3e-4), (0.0, -3e-4)], p.v)
    a0 = float(me.jkr_contact_radius(p.d_max, p, p.dgamma0))
    assert a0 < me.jump_off(p, p.dgamma1)["contact_radius"]
    release = float(me.jkr_depth(a0, p, p.dgamma1))
    for batch in ([shallow], [shallow, deep]):
        raw = run_discrete(p, batch, 0.5e-6, 0.05e-6 / p.v)
        radius = raw["contact_radius"][0]
        depth = raw["indentation_depth"][0]
        in_contact = depth[radius > 0]
        assert in_contact.min() == pytest.approx(release, abs=0.2e-6)



# ----------------------------------------------------------------------------------------------
# Entry times and several contact cycles along one path

#: The hand-computed entry times are a few segment lengths over the speed: round-off only.
ENTRY_TIME_RTOL = 1e-12


@pytest.mark.parametrize(
    "waypoints, speed, expected",
    [
        # one entry, crossing d = 0 half-way along a 6-8-10 segment
        ([(0.0, -3.0), (8.0, 3.0), (8.0, -1.0)], 2.0, [5.0 / 2.0]),
        # one entry exactly at a corner on the surface, the next segment going in (3-4-5 segment)
        ([(0.0, -3.0), (4.0, 0.0), (4.0, 2.0)], 2.0, [5.0 / 2.0]),
        # two entries: in a third of the way down the first segment (length 3), out, and in a third
        # of the way along the 3-4-5 segment that starts at t = (3 + 3) / 2
        ([(0.0, -1.0), (0.0, 2.0), (0.0, -1.0), (4.0, 2.0), (4.0, -1.0)], 2.0, [0.5, 3.0 + 5.0 / 3.0 / 2.0]),
        # starts inside (entry at 0), comes out, and goes in again half-way up the last segment
        ([(0.0, 1.0), (0.0, -1.0), (0.0, 1.0)], 2.0, [0.0, 1.0 + 0.5]),
        # touches the surface at t = 1 and turns back: no entry there; in a third of the way up the last segment
        ([(0.0, -1.0), (0.0, 0.0), (0.0, -1.0), (0.0, 2.0)], 1.0, [2.0 + 1.0]),
        # comes out to exactly d = 0 at a corner and goes back in: leaves and re-enters at that corner
        ([(0.0, -1.0), (0.0, 1.0), (0.0, 0.0), (0.0, 1.0)], 1.0, [1.0, 3.0]),
        # ends touching the surface: never enters
        ([(0.0, -1.0), (0.0, 0.0)], 1.0, []),
        # stays outside
        ([(0.0, -1.0), (3.0, -1.0), (3.0, -2.0)], 1.0, []),
    ],
    ids=["one", "one-at-corner", "two", "start-inside", "touch-and-turn-back", "out-to-surface-and-in",
         "ends-at-surface", "never"],
)
def test_entry_times_of_hand_made_paths(waypoints, speed, expected):
    path = Path(waypoints, speed)
    entries = path.entry_times()
    assert isinstance(entries, np.ndarray) and entries.ndim == 1 and entries.dtype == float
    assert entries.shape == (len(expected),)
    np.testing.assert_allclose(entries, expected, rtol=ENTRY_TIME_RTOL, atol=0.0)
    if expected:
        assert entries[0] == path.first_contact_time()
        assert np.all(np.diff(entries) > 0)
    else:
        with pytest.raises(ValueError, match="never enters the elastomer"):
            path.first_contact_time()


def test_entry_times_start_with_first_contact_time_of_the_scenarios(paper):
    for build in (Path.scenario_A, Path.scenario_B, Path.scenario_B_indentation):
        for alpha in (10.0, 45.0, 90.0):
            path = build(alpha, paper)
            assert path.entry_times().tolist() == [path.first_contact_time()]


#: How far below ``exit_depth`` (as a share of d_max) the re-contact paths pull out: well beyond pull-off.
BEYOND_EXIT_SHARE = 0.1
#: Time steps per contact cycle: the cycle lasts exactly this many steps, so that the second cycle is
#: sampled at the same offsets from its entry as the first.
STEPS_PER_CYCLE = 400
#: Spring spacing of the re-contact runs (about 780 springs per side at d_max).
CYCLE_DX = 4e-6
#: Allowed difference between two cycles that see the same depths, as a share of the largest |force|:
#: the depths and tangential steps come from interpolating the path at different times (round-off).
CYCLE_ROUND_OFF = 1e-9
#: The horizontal move out of contact between two cycles at different x (m).
CYCLE_MOVE = 1e-3


def cycle_paths(p, alpha: float, move: float, end_in_contact: bool = False) -> tuple[Path, float]:
    """A path of two contact cycles and its period (s): each in at ``alpha`` (degrees) from below
    ``exit_depth`` to d_max and vertically out below ``exit_depth`` again; between the cycles a
    horizontal move by ``move`` (m) out of contact. With ``end_in_contact`` the path stops at d_max
    in the second cycle."""
    out = exit_depth(p) - BEYOND_EXIT_SHARE * p.d_max
    run_in = 0.0 if alpha == 90.0 else (p.d_max - out) / math.tan(math.radians(alpha))
    points = [(0.0, out), (run_in, p.d_max), (run_in, out)]
    second = run_in + move
    if move:
        points.append((second, out))
    period_corner = len(points) - 1  # the second cycle starts here, in the same state as the first
    points.append((second + run_in, p.d_max))
    if not end_in_contact:
        points.append((second + run_in, out))
    path = Path(points, p.v)
    return path, float(path.corner_times[period_corner])


CYCLE_CASES = pytest.mark.parametrize(
    "alpha, move", [(90.0, 0.0), (90.0, CYCLE_MOVE), (30.0, CYCLE_MOVE)],
    ids=["vertical-same-line", "vertical-other-x", "slanted-other-x"])


@CYCLE_CASES
def test_second_contact_cycle_repeats_the_first(paper, alpha, move):
    """In again after a pull-off: the second cycle starts afresh (no springs, zero shifts) and is the
    first shifted in time. dt divides the cycle's duration exactly (STEPS_PER_CYCLE steps), so both
    cycles are sampled at the same depths (to round-off) at the same offsets from their entry."""
    path, period = cycle_paths(paper, alpha, move)
    entries = path.entry_times()
    assert entries.size == 2 and entries[1] - entries[0] == pytest.approx(period, rel=ENTRY_TIME_RTOL)
    raw = run_discrete(paper, [path], CYCLE_DX, period / STEPS_PER_CYCLE)
    radius = raw["contact_radius"][0]
    # the second cycle runs from sample STEPS_PER_CYCLE to its pull-off, after which the case ends
    second_length = int(np.count_nonzero(np.isfinite(radius[STEPS_PER_CYCLE:])))
    assert np.all(np.isfinite(radius[:STEPS_PER_CYCLE + second_length]))
    first = slice(0, second_length)
    second = slice(STEPS_PER_CYCLE, STEPS_PER_CYCLE + second_length)
    assert radius[second].max() > 0.0 and radius[second][-1] == 0.0  # a whole contact, up to its pull-off
    assert np.all(np.isnan(radius[STEPS_PER_CYCLE + second_length:]))
    np.testing.assert_array_equal(radius[second], radius[first])
    np.testing.assert_array_equal(raw["springs_in_contact"][0, second], raw["springs_in_contact"][0, first])
    for key in ("normal_force", "tangential_force"):
        values = raw[key][0]
        scale = np.abs(values[first]).max()
        np.testing.assert_allclose(values[second], values[first], rtol=0.0, atol=CYCLE_ROUND_OFF * scale,
                                   err_msg=key)
    tangential = raw["tangential_force"][0, first]
    assert (np.abs(tangential).max() > 0.0) == (alpha != 90.0)


@pytest.mark.parametrize("alpha", [90.0, 30.0], ids=["vertical", "slanted"])
def test_between_contact_cycles_everything_is_zero_and_the_case_goes_on(paper, alpha):
    """Out of contact between two cycles (including a horizontal move) F_N, F_x and the radius are
    exactly 0, the sliding fraction nan, and the case is not cut: it ends at its path's end, here in
    contact at d_max."""
    path, period = cycle_paths(paper, alpha, CYCLE_MOVE, end_in_contact=True)
    dt = period / STEPS_PER_CYCLE
    raw = run_discrete(paper, [path], CYCLE_DX, dt)
    time = raw["time"]
    start = path.first_contact_time()
    radius = raw["contact_radius"][0]
    touching = radius > 0.0
    pull_off = int(np.argmax(touching)) + int(np.argmax(~touching[np.argmax(touching):]))
    contact_again = pull_off + int(np.argmax(touching[pull_off:]))
    assert contact_again > pull_off and touching[contact_again]
    # the gap holds the whole move out of contact (corners 2 and 3) and ends at or after the second entry
    assert time[pull_off] < path.corner_times[2] - start and path.corner_times[3] - start < time[contact_again]
    assert time[contact_again] >= path.entry_times()[1] - start
    gap = slice(pull_off, contact_again)
    for key in ("contact_radius", "normal_force", "tangential_force", "springs_in_contact"):
        assert np.all(raw[key][0, gap] == 0.0), key
    assert np.all(np.isnan(raw["sliding_fraction"][0, gap]))
    within_path = time <= path.duration - start
    for key in ("contact_radius", "normal_force", "tangential_force", "springs_in_contact",
                "indentation_depth", "tangential_displacement"):
        assert np.all(np.isfinite(raw[key][0, within_path])), key
    assert radius[within_path][-1] > 0.0  # still in contact where the path ends
    assert np.all(np.isfinite(raw["sliding_fraction"][0, within_path][touching[within_path]]))


def test_a_single_contact_still_ends_after_its_pull_off_sample(paper):
    """Without a later entry the case ends at the first sample without contact after the contact:
    that sample is kept (radius and forces 0), all after it is nan, also when the path goes on
    outside, or touches the surface (d = 0) and turns back; in a batch with a path that does go in
    again, as on its own."""
    out = exit_depth(paper) - BEYOND_EXIT_SHARE * paper.d_max
    moves_on_outside = Path([(0.0, out), (0.0, paper.d_max), (0.0, out), (CYCLE_MOVE, out)], paper.v)
    touches_surface = Path([(0.0, out), (0.0, paper.d_max), (0.0, out), (0.0, 0.0), (0.0, out)], paper.v)
    twice, period = cycle_paths(paper, 90.0, 0.0)
    dt = period / STEPS_PER_CYCLE
    batch = run_discrete(paper, [moves_on_outside, twice, touches_surface], CYCLE_DX, dt)
    for row, path in ((0, moves_on_outside), (2, touches_surface)):
        assert path.entry_times().size == 1
        single = run_discrete(paper, [path], CYCLE_DX, dt)
        radius = single["contact_radius"][0]
        touching = radius > 0.0
        pull_off = int(np.argmax(touching)) + int(np.argmax(~touching[np.argmax(touching):]))
        assert single["time"][pull_off] < path.duration - path.first_contact_time()  # cut before the end
        for key in ("contact_radius", "normal_force", "tangential_force", "springs_in_contact"):
            values = single[key][0]
            assert np.all(np.isfinite(values[:pull_off + 1])) and values[pull_off] == 0.0, key
            assert pull_off + 1 < values.size and np.all(np.isnan(values[pull_off + 1:])), key
        for key, values in single.items():
            if key not in ("time", "spring_count"):
                assert np.array_equal(batch[key][row, :values.shape[1]], values[0], equal_nan=True), key
    # the path that goes in again does so in the same batch
    assert np.nanmax(batch["contact_radius"][1, STEPS_PER_CYCLE:]) > 0.0


def test_re_entry_in_the_step_the_contact_comes_apart_goes_on(paper):
    """Without adhesion the contact comes apart at d = 0; a path that comes out to d = 0 at a corner and
    goes straight back in comes apart at the very sample (on the corner) at which it re-enters. The
    case goes on, as the path enters after the last sample in contact; dt puts the corners on samples."""
    p = paper.replace(dgamma0=0.0, dgamma1=0.0)
    path = Path([(0.0, 0.0), (0.0, p.d_max), (0.0, 0.0), (0.0, p.d_max), (0.0, 0.0)], p.v)
    period = float(path.corner_times[2])
    raw = run_discrete(p, [path], CYCLE_DX, period / STEPS_PER_CYCLE)
    radius = raw["contact_radius"][0]
    assert radius[STEPS_PER_CYCLE] == 0.0 and radius[STEPS_PER_CYCLE - 1] > 0.0  # apart on the corner
    assert radius[STEPS_PER_CYCLE + 1] > 0.0  # and in contact again at the next sample
    np.testing.assert_array_equal(radius[STEPS_PER_CYCLE:2 * STEPS_PER_CYCLE + 1], radius[:STEPS_PER_CYCLE + 1])


# ----------------------------------------------------------------------------------------------
# The stepping kernel: exact running sums, the rules stepped spring by spring, batches

from mdr_events.models import discrete, spring_groups  # noqa: E402  (the kernel's internals)
from mdr_events.contact.adhesion import law_of  # noqa: E402
from mdr_events.contact.friction import TAU0  # noqa: E402

#: Spring spacing of the long runs: about 155 springs per side at d_max.
LONG_DX = 20e-6
#: Allowed difference between the kernel's F_x and a sum of per-spring shifts, as a share of the largest |F_x|.
SUM_RTOL = 1e-12


def reciprocating_path(p, strokes: int) -> Path:
    """In to d_max, then ``strokes`` tangential strokes of about ±2ū (full slip, both caps) with the
    depth going up and down (springs detach and attach again); at the end a stroke on in the same
    direction while pressing deeper than ever (new springs attach along it: many shifts, partial slip)."""
    amplitude = 1.5e-3  # ū(a) at d_max is 0.71 mm
    points = [(0.0, 0.0), (0.0, p.d_max)]
    for i in range(strokes):
        x = (1.0 if i % 2 == 0 else -1.0) * amplitude * (0.7 if i % 3 == 0 else 1.0)
        depth = p.d_max * (0.35 if i % 4 == 1 else 1.0 - 0.1 * (i % 3))
        points.append((x, depth))
    x = points[-1][0]
    points.append((x + math.copysign(1.5e-3, x), 1.3 * p.d_max))
    return Path(points, p.v)


def step_case(kernel, run, case=0, springs=None):
    """``kernel`` (``_run_case`` or ``_run_case_per_spring``) over one case of a prepared run."""
    n = run.time.size
    counts, sums, sliding = np.zeros(n, np.int64), np.zeros(n), np.zeros(n, np.int64)
    extra = {} if springs is None else {"springs": springs}
    last = kernel(run.grid, run.x[:, case], run.d[:, case], run.time, int(run.last_sample[case]),
                  float(run.last_entries[case]), counts, sums, sliding, **extra)
    return last, counts[:last + 1], sums[:last + 1], sliding[:last + 1]


def prepare(p, paths, dx, steps):
    longest = max(path.duration - path.first_contact_time() for path in paths)
    return discrete._prepare(p, paths, dx, longest / steps, discrete.paraboloid_profile(p), TAU0, law_of(p))


def test_running_sums_equal_a_full_re_sum_after_a_million_steps(paper, monkeypatch):
    """10⁶ steps of reciprocating sliding (200 strokes through full slip at both caps, springs detaching
    and attaching again): at the end F_N and F_x of the run equal the sums over the springs in contact
    (every spring's shift from the final state) to 1e-12, the shifts lie within ±ū, the springs at
    a cap are the sliding ones, and the kernel's state is bounded by the springs, not the steps.

    The run's own kernel call is watched (its arguments, its springs' final state): the million steps run once."""
    stepped = {}

    def watched(grid, x, d, time, last, last_entry, counts, sums, sliding, **options):
        stepped.update(grid=grid, x=x, d=d, counts=counts, sums=sums, sliding=sliding)
        options["springs"] = stepped["springs"] = spring_groups.SpringGroups(grid.weight_prefix)
        stepped["last"] = run_case(grid, x, d, time, last, last_entry, counts, sums, sliding, **options)
        return stepped["last"]

    run_case = discrete._run_case
    monkeypatch.setattr(discrete, "_run_case", watched)
    path = reciprocating_path(paper, 200)
    dt = (path.duration - path.first_contact_time()) / 1_000_000
    raw = run_discrete(paper, [path], LONG_DX, dt)
    run, springs, last = stepped["grid"], stepped["springs"], stepped["last"]
    counts, sums, sliding = (stepped[key][:last + 1] for key in ("counts", "sums", "sliding"))
    assert last == 1_000_000 == raw["time"].size - 1
    m = int(counts[-1])
    assert m == raw["springs_in_contact"][0, -1] and 0 < sliding[-1] < m  # partial slip at the end

    p, dx = paper, LONG_DX
    depth = float(stepped["d"][-1])
    g = discrete.paraboloid_profile(p)((np.arange(m) + 0.5) * dx)
    normal = raw["normal_force"][0]
    resummed = 2.0 * p.E_star * dx * math.fsum(depth - g)
    assert abs(normal[-1] - resummed) <= SUM_RTOL * np.abs(normal).max()

    position = spring_groups.scaled(stepped["x"][-1:], run.bits)[0]
    shifts = springs.shifts(position, m)
    assert len(shifts) == m
    tangential = raw["tangential_force"][0]
    resummed = 2.0 * p.G_star * dx * math.fsum(run.to_float(u) for u in shifts)
    assert abs(tangential[-1] - resummed) <= SUM_RTOL * np.abs(tangential).max()
    assert 2.0 * p.G_star * dx * sums[-1] == tangential[-1]

    cap = run.caps_scaled[m]
    assert all(-cap <= u <= cap for u in shifts)
    assert sum(abs(u) == cap for u in shifts) == sliding[-1] == round(raw["sliding_fraction"][0, -1] * m)
    assert len(set(shifts)) > 10  # springs that attached along the last stroke: many shifts
    entries = len(springs.parent) + len(springs.lows) + len(springs.highs)
    assert entries <= 8 * run.n_springs + spring_groups.SpringGroups.SLACK


REFERENCE_PATHS = {
    "A 20°": lambda p: Path.scenario_A(20.0, p),
    "B 20°": lambda p: Path.scenario_B(20.0, p),
    "B+ 10°": lambda p: Path.scenario_B_indentation(10.0, p),
    "zigzag": lambda p: Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4),
                              (2e-4, -1e-4)], p.v),
    "re-contact": lambda p: cycle_paths(p, 30.0, CYCLE_MOVE)[0],
}


@pytest.mark.parametrize("steps", [60, 2500], ids=["steps-beyond-2ū", "fine-steps"])
@pytest.mark.parametrize("variant", ["paper", "tau0=0", "hertz", "dgamma1<dgamma0"])
def test_kernel_equals_the_rules_stepped_spring_by_spring(paper, variant, steps):
    """The kernel (anchors, groups, exact sums) against every spring's shift moved, clipped and summed
    at every step: the same springs in contact and at a cap, F_x to round-off; also with steps so
    long that the window jumps past a whole cap (``steps=60``) and where ū = 0."""
    p = {"paper": paper, "tau0=0": paper.replace(tau0=0.0), "hertz": paper.replace(dgamma0=0.0, dgamma1=0.0),
         "dgamma1<dgamma0": paper.replace(dgamma1=0.5 * paper.dgamma0)}[variant]
    paths = [build(p) for build in REFERENCE_PATHS.values()]
    run = prepare(p, paths, CYCLE_DX, steps)
    for case, name in enumerate(REFERENCE_PATHS):
        last, counts, sums, sliding = step_case(discrete._run_case, run, case)
        reference = step_case(discrete._run_case_per_spring, run, case)
        assert last == reference[0], name
        np.testing.assert_array_equal(counts, reference[1], err_msg=name)
        np.testing.assert_array_equal(sliding, reference[3], err_msg=name)
        scale = np.abs(reference[2]).max()
        np.testing.assert_allclose(sums, reference[2], rtol=0.0, atol=SUM_RTOL * scale, err_msg=name)
        assert (scale > 0.0) == (p.tau0 > 0.0), name
        if steps == 60 and p.tau0 > 0.0 and name == "zigzag":  # a step moves the indenter by more than 2ū
            caps = np.asarray(run.grid.caps)[counts[1:]]
            assert np.any(np.abs(np.diff(run.x[:last + 1, case])) > 2.0 * caps), name


def test_kernel_equals_the_rules_over_a_long_reciprocating_run(paper):
    """10⁵ steps of the reciprocating path (groups detach, caps release and catch up, compaction):
    the kernel and the spring-by-spring stepping agree at every sample."""
    run = prepare(paper, [reciprocating_path(paper, 20)], LONG_DX, 100_000)
    last, counts, sums, sliding = step_case(discrete._run_case, run)
    reference = step_case(discrete._run_case_per_spring, run)
    assert last == reference[0] == 100_000
    np.testing.assert_array_equal(counts, reference[1])
    np.testing.assert_array_equal(sliding, reference[3])
    np.testing.assert_allclose(sums, reference[2], rtol=0.0, atol=SUM_RTOL * np.abs(reference[2]).max())
    assert np.any(np.diff(counts[counts > 0]) < 0) and np.any((sliding == counts) & (counts > 0))  # detach, full slip


def test_a_case_in_a_batch_is_the_case_alone_bit_for_bit(paper):
    """Cases are stepped one by one with exact sums, so a batch (other paths, another spring count and
    integer scale) changes nothing in any case, to the last bit."""
    paths = [Path.scenario_A(20.0, paper), Path.scenario_B(60.0, paper), REFERENCE_PATHS["zigzag"](paper),
             cycle_paths(paper, 30.0, CYCLE_MOVE)[0], Path.scenario_B_indentation(10.0, paper)]
    dt = max(path.duration - path.first_contact_time() for path in paths) / 3000
    batch = run_discrete(paper, paths, CYCLE_DX, dt)
    for row, path in enumerate(paths):
        single = run_discrete(paper, [path], CYCLE_DX, dt)
        n = single["time"].size
        for key, values in single.items():
            if key in ("time", "spring_count"):
                continue
            assert batch[key][row, :n].tobytes() == values[0].tobytes(), (row, key)
            assert np.all(np.isnan(batch[key][row, n:])), (row, key)
    assert batch["spring_count"] > run_discrete(paper, paths[:1], CYCLE_DX, dt)["spring_count"]


@pytest.mark.parametrize("block", [1, 7])
def test_blocks_of_samples_do_not_change_the_result(paper, monkeypatch, block):
    """The per-sample values are made block by block (memory): tiny blocks give the same bits."""
    paths = [REFERENCE_PATHS["zigzag"](paper), cycle_paths(paper, 90.0, 0.0)[0], reciprocating_path(paper, 6)]
    dt = max(path.duration - path.first_contact_time() for path in paths) / 2000
    whole = run_discrete(paper, paths, CYCLE_DX, dt)
    monkeypatch.setattr(discrete, "_BLOCK", block)
    blocks = run_discrete(paper, paths, CYCLE_DX, dt)
    for key, values in whole.items():
        assert np.asarray(blocks[key]).tobytes() == np.asarray(values).tobytes(), key


def test_the_integer_scale_holds_every_position_exactly():
    """Positions and caps become integers in units of 2**-bits with no rounding, from subnormal to
    kilometres (the fast ldexp route and the exact fallback), and an integer sum comes back as the
    correctly rounded float."""
    values = np.array([0.0, 5e-324, -1e-300, 1e-20, 0.1, -1.5, 3.0e3, 2.0 / 3.0])
    for chosen in (values[3:], values):  # bits small enough for ldexp; subnormals need the fallback
        bits = spring_groups.scale_bits(chosen)
        scaled = spring_groups.scaled(chosen, bits)
        assert [spring_groups.unscaled(v, bits) for v in scaled] == chosen.tolist()
        assert spring_groups.unscaled(sum(scaled), bits) == math.fsum(chosen)
    assert spring_groups.scale_bits(values) > 1000 > spring_groups.scale_bits(values[3:])
