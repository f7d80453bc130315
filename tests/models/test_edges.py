"""Edges of the model (issue 6): each handled, by both methods where both apply."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import mdr_events as me
from mdr_events.models import continuum
from mdr_events.models.continuum import solve_path
from mdr_events.models.paths import Path

METHODS = ("continuum", "discrete")


def kinds(dataset, alpha):
    return [str(kind) for kind in dataset["event_kind"].sel(alpha=alpha).values if kind]


def in_contact(dataset, name):
    values = dataset[name].values
    return values[np.isfinite(dataset["contact_radius"].values) & (dataset["contact_radius"].values > 0)]


def test_alpha_0_scenario_A_is_rejected_because_it_never_reaches_d_max(paper):
    for method in METHODS:
        with pytest.raises(ValueError, match="alpha=0.0 in scenario A: a path parallel to the surface never reaches d_max"):
            me.simulate(paper, "A", alpha=[0.0], method=method)


def test_alpha_0_scenario_B_slips_at_d_max(paper):
    """Pulling parallel to the surface: (20)/(21) give slip at d_max (it takes ū(a)/v to get there)."""
    continuum = me.simulate(paper, "B", alpha=[0.0], method="continuum")
    events = continuum.sel(alpha=0.0)
    onset = events["event_depth"].values[events["event_kind"].values == "slip_onset"]
    assert onset == pytest.approx([paper.d_max], rel=1e-12)
    assert float(me.d_crit(0.0, paper, "B", adhesion=True)) == pytest.approx(paper.d_max, rel=1e-12)
    discrete = me.simulate(paper, "B", alpha=[0.0], dx=2e-6)
    assert np.nanmax(discrete["sliding_fraction"].values) == 1.0
    assert np.nanmax(np.abs(discrete["mean_shear_stress"].values)) == pytest.approx(paper.tau0, rel=1e-9)


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("method", METHODS)
def test_alpha_90_no_tangential_force_no_slip(paper, scenario, method):
    ds = me.simulate(paper, scenario, alpha=[90.0], method=method, **({"dx": 2e-6} if method == "discrete" else {}))
    assert np.all(in_contact(ds, "tangential_force") == 0.0)
    assert np.all(in_contact(ds, "sliding_fraction") == 0.0)
    if method == "continuum":
        assert not {"slip_onset", "full_slip"} & set(kinds(ds, 90.0))


@pytest.mark.parametrize("method", METHODS)
def test_no_adhesion_is_hertz_without_jumps(paper, method):
    """Δγ0 = Δγ1 = 0: a = sqrt(R d), F_N = (4/3) E* R^1/2 d^3/2 on loading and unloading; no jump-in, no
    jump-off (the contact ends at d = 0). Continuum to 1e-10; discrete within its O(Δx) radius."""
    p = paper.replace(dgamma0=0.0, dgamma1=0.0)
    dx = 2e-6
    ds = me.simulate(p, "A", alpha=[30.0], method=method, **({"dx": dx} if method == "discrete" else {}))
    depth = ds["indentation_depth"].values[0]
    radius = ds["contact_radius"].values[0]
    force = ds["normal_force"].values[0]
    touching = np.isfinite(radius) & (depth > 0)
    hertz_radius = np.sqrt(p.R * depth[touching])
    hertz_force = 4.0 / 3.0 * p.E_star * math.sqrt(p.R) * depth[touching] ** 1.5
    if method == "continuum":
        np.testing.assert_allclose(radius[touching], hertz_radius, rtol=1e-10)
        np.testing.assert_allclose(force[touching], hertz_force, rtol=1e-10, atol=1e-12 * hertz_force.max())
        assert radius[0] == 0.0
        log = kinds(ds, 30.0)
        assert "pull_off" not in log and log[-1] == "contact_ends"
        end = ds["event_depth"].sel(alpha=30.0).values[len(log) - 1]
        assert end == pytest.approx(0.0, abs=1e-15)
    else:
        assert np.all(np.abs(radius[touching] - hertz_radius) <= dx)
        assert np.nanmin(force) >= 0.0  # no adhesive (negative) force anywhere
    assert np.nanmin(force) >= -1e-12 * np.nanmax(force)


@pytest.mark.parametrize("method", METHODS)
def test_weaker_adhesion_on_the_way_out_shrinks_at_once(paper, method):
    """Δγ1 < Δγ0 is allowed: at d_max the radius is already above the Δγ1 branch, so it shrinks at once."""
    p = paper.replace(dgamma0=0.15, dgamma1=0.01)
    options = {"dx": 1e-6, "n_steps": 20_000} if method == "discrete" else {"samples": 20_001}
    ds = me.simulate(p, "B", alpha=[60.0], method=method, **options)
    depth = ds["indentation_depth"].values[0]
    radius = ds["contact_radius"].values[0]
    turn = int(np.nanargmax(depth))
    after = radius[turn + 1: turn + 40]
    assert np.all(np.diff(np.concatenate([[radius[turn]], after])) <= 0)
    assert after[-1] < radius[turn] - 2e-6  # it moved off by more than one spring
    if method == "continuum":
        log = kinds(ds, 60.0)
        times = ds["event_time"].sel(alpha=60.0).values
        corner = times[log.index("corner")]
        assert times[log.index("detachment_starts")] == corner


@pytest.mark.parametrize("method", METHODS)
def test_no_friction_no_tangential_force(paper, method):
    p = paper.replace(tau0=0.0)
    ds = me.simulate(p, "A", alpha=[30.0], method=method, **({"dx": 2e-6} if method == "discrete" else {}))
    assert np.all(in_contact(ds, "tangential_force") == 0.0)
    np.testing.assert_allclose(in_contact(ds, "sliding_fraction"), 1.0, rtol=1e-12)  # front / a, to rounding
    if method == "continuum":
        assert kinds(ds, 30.0)[:3] == ["first_contact", "slip_onset", "full_slip"]


def test_tiny_d_max_stays_at_the_jump_in_radius(paper):
    """d_max = 10 nm: the radius grows by 0.4 µm beyond the jump-in radius a0 (less than one spring).
    The continuum resolves it; the discrete model needs a time step that resolves the 20 ms of
    indentation, and says which; given one, it stays at a0 to within one spring."""
    p = paper.replace(d_max=1e-8)
    a0 = me.analytic.jump_in_radius(p, p.dgamma0)
    a_max = float(me.jkr_contact_radius(p.d_max, p, p.dgamma0))
    assert 0 < a_max - a0 < 1e-6
    continuum = me.simulate(p, "A", alpha=[30.0], method="continuum")
    assert np.nanmax(continuum["contact_radius"].values) == pytest.approx(a_max, rel=1e-9)
    assert kinds(continuum, 30.0)[-1] == "pull_off"
    with pytest.raises(ValueError, match=r"n_steps=10000 is too few: .* allowed: n_steps >= \d+ \(or dt <= "):
        me.simulate(p, "A", alpha=[30.0])
    discrete = me.simulate(p, "A", alpha=[30.0], dt=1e-3)
    assert np.nanmax(discrete["contact_radius"].values) == pytest.approx(a0, abs=1e-6)
    # the contact never grows to the radius of the JKR force minimum on the Δγ1 branch, so the
    # adhesive strength is not (3/2)πΔγ1R but the force where detachment starts, F_N(a_max; Δγ1)
    strongest = float(me.jkr_normal_force(a_max, p, p.dgamma1))
    assert strongest > me.pull_off_force(p, p.dgamma1) * 0.6
    assert np.nanmin(continuum["normal_force"].values) >= strongest * (1 + 1e-12)
    assert np.nanmin(continuum["normal_force"].values) == pytest.approx(strongest, rel=1e-3)  # 2001 samples
    assert np.nanmin(discrete["normal_force"].values) == pytest.approx(strongest, rel=2e-3)  # radius to Δx


@pytest.mark.parametrize("offset", [5e-10, -5e-10])
def test_slip_onset_within_a_nanosecond_of_d_max_is_not_missed(paper, offset):
    """Two events in one step: the angle is chosen so that slip onset (18) falls 0.5 ns before (or
    after) d_max is reached. Before: the log has slip_onset then corner, 0.5 ns apart (to 0.1 ns);
    after: no slip during indentation at all (the pull-off is vertical, x stays put)."""
    alpha_c = me.critical_angle(paper, "A", adhesion=True)

    def gap(alpha):  # d_crit(α) − depth reached 'offset' s before d_max
        return float(me.d_crit(alpha, paper, "A", adhesion=True)) - (
            paper.d_max - paper.v * math.sin(math.radians(alpha)) * offset)

    alpha = brentq(gap, alpha_c - 0.5, alpha_c + 0.5, xtol=1e-15, rtol=1e-15)
    solution = solve_path(paper, Path.scenario_A(alpha, paper))
    log = [(kind, time) for time, kind, *_ in solution.events]
    corner = next(time for kind, time in log if kind == "corner")
    onsets = [time - corner for kind, time in log if kind == "slip_onset"]
    if offset > 0:
        assert [kind for kind, _ in log][:3] == ["first_contact", "slip_onset", "corner"]
        assert onsets[0] == pytest.approx(-offset, abs=1e-10)
    else:
        assert all(onset > 1.0 for onset in onsets)  # only in pull-off, a minute later


def test_bad_inputs_name_the_argument_its_value_and_what_is_allowed(paper):
    cases = [
        (lambda: me.simulate(paper, "A", alpha=[95.0]), "alpha=95.0 (degrees) is not allowed; allowed: finite angles in [0, 90]"),
        (lambda: me.simulate(paper, "B", alpha=[1e-9], method="continuum"),
         "alpha=1e-09 (degrees) in scenario B: the path reaches x = 2.02e+07 m; allowed: |x| <= 3.2e+03 m"),
        (lambda: me.simulate(paper, "A", alpha=[-1.0], method="continuum"), "alpha=-1.0 (degrees) is not allowed"),
        (lambda: me.simulate(paper, "A", alpha=[float("nan")]), "alpha=nan (degrees) is not allowed"),
        (lambda: me.d_crit(91.0, paper, "A"), "alpha=91.0 (degrees) is not allowed"),
        (lambda: me.phase_diagram(paper, scenario="A", alpha=[10.0, 100.0]), "alpha=100.0"),
        (lambda: me.simulate(paper, "C"), "scenario='C' is not allowed; allowed"),
        (lambda: me.simulate(paper, "A", method="fem"), "method='fem' is not allowed; allowed"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], method="continuum", t=[]), "t=[] is not allowed"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], method="continuum", t=[0.0, 2.0, 1.0]), "strictly increasing"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], method="continuum", dt=1.0), "dt is not allowed with method='continuum'"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], method="continuum", samples=1), "samples=1 is not allowed"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], t=[0.0, 1.0]), "t is not allowed with method='discrete'"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], dx=1e-3), "dx=0.001 m puts 3 springs per side in contact"),
        (lambda: me.simulate(paper, "A", alpha=[30.0], dt=-1.0), "dt=-1.0 is not allowed"),
        (lambda: continuum.Tolerances(rtol=0.0), "Tolerances.rtol=0.0 is not allowed"),
        (lambda: Path.from_segments([((0, 0), (0, 3e-4)), ((0, 2e-4), (1e-4, -1e-4))], 1e-6),
         "segments 0 and 1 do not connect"),
        (lambda: Path([(0, 0), (0, 0)], 1e-6), "coincide"),
        (lambda: Path([(0, 0), (0, 1e-300), (1e-4, 3e-4)], 1e-6),
         "waypoints 0 and 1 are 1e-300 m apart; allowed: at least 1e-12 of the longest segment"),
        (lambda: paper.replace(nu=0.7), "Parameters.nu=0.7 is not allowed; allowed:"),
        (lambda: paper.replace(E=float("inf")), "Parameters.E=inf is not allowed; allowed:"),
    ]
    for call, fragment in cases:
        with pytest.raises(ValueError) as error:
            call()
        assert fragment in str(error.value), (fragment, str(error.value))


def test_coarse_spacing_error_names_the_largest_spacing_that_would_do(paper):
    with pytest.raises(ValueError, match=r"dx=0\.001 m puts 3 springs .* allowed: at least 10, i\.e\. dx <= ") as error:
        me.simulate(paper, "A", alpha=[30.0], dx=1e-3)
    largest = float(str(error.value).split("dx <= ")[1].split()[0])
    me.simulate(paper, "A", alpha=[30.0], dx=largest * (1 - 1e-6), n_steps=200)  # that spacing is accepted
