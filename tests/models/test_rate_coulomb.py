"""Coulomb's part under the rate-dependent adhesion law in the continuum (continuum.rate_history, continuum.rate_coulomb):
the per-spring route on the edge's history is the closed-form play of τ0 where μ = 0, tends to the rate-independent
continuum (the spans) as v_ref -> inf, gives full slip as τ0 π a² + μ F_N^H(d), the discrete springs converge to it at
first order in Δx, and simulate runs it (before, it was refused)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum.play_springs import PlaySprings, spring_line
from mdr_events.models.continuum.rate_edge import solve_edge
from mdr_events.models.continuum.rate_history import RateHistory
from mdr_events.models.continuum.rate_run import RUN_METHOD
from mdr_events.models.continuum.rate_shifts import solve_rate_shifts
from mdr_events.theory import mindlin

PAPER = me.Parameters.paper()
BASE = me.Contact.paper()
D = PAPER.d_max
#: The path's speed (1 µm/s) at the reference speed, Maugis–Barquins' exponent: the edge lags the indenter visibly.
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
TAU0_COULOMB = me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.3)
COULOMB = me.FrictionLaw("coulomb", mu=0.3)
N3 = PowerLaw(2e5, 3.0)
PATHS = {
    "A20": me.Path.scenario_A(20.0, PAPER), "A45": me.Path.scenario_A(45.0, PAPER),
    "B20": me.Path.scenario_B(20.0, PAPER), "B45": me.Path.scenario_B(45.0, PAPER),
    "fretting": me.Path(np.array([(0, 0), (0, D), (3e-5, D), (-3e-5, D), (3e-5, D), (0, -2e-4)]), speed=PAPER.v),
    "sliding": me.Path(np.array([(0, 0), (0, D), (1e-3, D), (-1e-3, D), (1e-3, D), (0, -2e-4)]), speed=PAPER.v),
    "A20 n=3": me.Path.scenario_A(20.0, PAPER, N3),
}
#: The output times the route is evaluated at (its force costs some 50 ms a time: the kinks of every spring's anchor
#: located by bisection).
SAMPLES = 41
#: μ = 0 through the per-spring route against the closed-form play of τ0 (rate_shifts, rate_play) on the same edge:
#: the same anchors summed by Gauss–Legendre panels instead of the records' closed forms, measured 6e-13 of the largest
#: force on A 20° and the fretting path (before the route probed beside the edge, a rim of springs attached after the
#: corner by the edge still growing was summed across its kink: 1.4e-6).
SAME_RTOL = 1e-11
#: v_ref -> inf: the gap to the rate-independent continuum is first order in 1/v_ref (measured: 9.99-10.0 per decade
#: from 10 to 100 m/s on every path), so Richardson's extrapolation of the two, F(100) + (F(100) − F(10))/9, is the
#: limit up to the second order: measured 2e-11 to 1.7e-10 of the largest force (4.4e-10 on the power law n = 3 from 1
#: and 10 m/s, where 100 m/s is too stiff for the edge's solver), against 1e-9.
LIMIT_RTOL = 1e-9
DECADE = (9.0, 11.0)
#: Observed orders of a first-order method over halvings of Δx, each halving at least this (as
#: tests/models/test_coulomb_adhesion.py: the anchors sampled spring by spring and the edge crossing each spring at its
#: own speed, both O(Δx); measured 0.89-1.12 under "tau0+coulomb" on A 20° and the fretting path, 1.6-2.5 under
#: "coulomb" alone, whose compressed zone does not see the edge: errors of 1e-9 to 2e-8 N).
FIRST_ORDER = 0.7
#: The time step as a share of the time the indenter takes to cross a spring, ``dt = TIME_SHARE Δx / v``: refined with
#: Δx (at the default 10 000 steps the step's own error, fixed, is a floor of Coulomb's law alone on the fretting path:
#: 5.1e-7 N at every spacing).
TIME_SHARE = 0.5
#: Full slip against τ0 π a² + μ F_N^H(d): the route's quadrature of caps that are exact polynomials between the kinks,
#: to rounding (measured 1e-15 of the force).
FULL_SLIP_RTOL = 1e-12


def _contact(adhesion, friction, profile=None):
    return me.Contact(BASE.elastomer, BASE.indenter if profile is None else profile, adhesion, friction)


def _play(path, law, friction, profile=None, method=RUN_METHOD):
    edge = solve_edge(PAPER, path, law, profile=profile, method=method)
    return PlaySprings(spring_line(PAPER, profile, friction), path, RateHistory(edge))


def _times(path):
    return np.linspace(path.first_contact_time(), path.duration, SAMPLES)


@pytest.mark.parametrize("name", ["A20", "fretting"])
def test_at_mu_zero_the_route_on_the_edge_s_history_is_the_closed_form_play_of_tau0(name):
    path = PATHS[name]
    times = _times(path)
    closed = solve_rate_shifts(PAPER, path, LAW, method=RUN_METHOD).tangential_force(times)
    route = _play(path, LAW, me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.0)).tangential_force(times)
    np.testing.assert_allclose(route, closed, rtol=0.0, atol=SAME_RTOL * np.max(np.abs(closed)))


def _limit_case(name, friction, speeds):
    path = PATHS[name]
    profile = N3 if name.endswith("n=3") else None
    exact = me.simulate(_contact(me.Adhesion(PAPER.dgamma0, PAPER.dgamma1), friction, profile), me.Paths([path]),
                        "continuum", samples=SAMPLES).isel(case=0)
    times = exact["time"].values + path.first_contact_time()
    reference = exact["tangential_force"].values
    forces = [_play(path, me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, v_ref, 1.0), friction,
                    profile).tangential_force(times) for v_ref in speeds]
    return reference, forces


@pytest.mark.parametrize("name", ["A20", "fretting", pytest.param("A45", marks=pytest.mark.slow),
                                  pytest.param("B20", marks=pytest.mark.slow),
                                  pytest.param("B45", marks=pytest.mark.slow),
                                  pytest.param("A20 n=3", marks=pytest.mark.slow)])
def test_v_ref_to_infinity_is_the_rate_independent_continuum(name):
    """n = 1 at v_ref = 10 and 100 m/s (1e7, 1e8 times the path's speed; 1 and 10 on the power law n = 3) under
    "tau0+coulomb": the gap to the spans' continuum of the works at rest falls tenfold per decade, and the first-order
    extrapolation is the spans' to LIMIT_RTOL of the largest force (slow: about 6 s of CPU each; A at 20° and the
    fretting path in the quick round)."""
    speeds = (1.0, 10.0) if name.endswith("n=3") else (10.0, 100.0)
    reference, (slow, fast) = _limit_case(name, TAU0_COULOMB, speeds)
    held = np.isfinite(reference)
    scale = np.max(np.abs(reference[held]))
    gaps = [np.max(np.abs(force - reference)[held]) for force in (slow, fast)]
    assert DECADE[0] < gaps[0] / gaps[1] < DECADE[1], gaps
    extrapolated = fast + (fast - slow) / 9.0
    assert np.max(np.abs(extrapolated - reference)[held]) < LIMIT_RTOL * scale, (gaps, scale)


def test_coulomb_s_law_alone_does_not_see_the_edge_s_speed():
    """"coulomb" alone: the springs in tension hold nothing and the compressed ones attached at the edge before they
    were pressed, so F_x is the compressed zone's Cattaneo–Mindlin whatever the edge does: the rate law's run at
    v_ref = 1 µm/s (n = 0.6, the edge lagging) is the spans' of the works at rest to LIMIT_RTOL."""
    path = PATHS["fretting"]
    exact = me.simulate(_contact(me.Adhesion(PAPER.dgamma0, PAPER.dgamma1), COULOMB), me.Paths([path]), "continuum",
                        samples=SAMPLES).isel(case=0)
    times = exact["time"].values + path.first_contact_time()
    reference = exact["tangential_force"].values
    held = np.isfinite(reference)
    force = _play(path, LAW, COULOMB).tangential_force(times)
    np.testing.assert_allclose(force[held], reference[held], rtol=0.0,
                               atol=LIMIT_RTOL * np.max(np.abs(reference[held])))


@pytest.mark.slow  # 17 s of CPU (measured on the shared machine, loaded): the events bisected on the route's force
# (48 halvings, some 50 ms each) at every stroke; the quick round runs simulate in tests/models/test_rate_run.py
def test_simulate_runs_it_full_slip_is_tau0_pi_a_squared_and_mu_hertz_and_the_log_holds_the_springs_events():
    """Before, simulate's continuum refused Coulomb's part under the rate law. On the sliding fretting path: where
    every spring slides F_x = ±(τ0 π a² + μ F_N^H(d)) (the springs in tension hold τ0's part alone, so F_N^H, the
    compressed springs' force, not F_N), somewhere it does; the log holds the edge's events and the springs' slip
    onset and full slip; the extrema of F_x bound the samples. (v_ref = 100 µm/s, n = 1: the edge catches up with the
    indenter and rests during the strokes, so every spring slides; at 1 µm/s it still grows, its newest springs
    stuck.)"""
    path = PATHS["sliding"]
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-4, 1.0)
    run = me.simulate(_contact(law, TAU0_COULOMB), me.Paths([path]), "continuum", samples=SAMPLES).isel(case=0)
    share, force = run["sliding_fraction"].values, run["tangential_force"].values
    full = share == 1.0
    assert np.count_nonzero(full) >= 3
    depth, radius = run["indentation_depth"].values[full], run["contact_radius"].values[full]
    assert np.all(depth > 0.0)
    expected = PAPER.tau0 * np.pi * radius ** 2 + np.array(
        [mindlin.full_slip_force(d, COULOMB, PAPER) for d in depth])
    np.testing.assert_allclose(np.abs(force[full]), expected, rtol=FULL_SLIP_RTOL)
    kinds = [str(kind) for kind in run["event_kind"].values if str(kind)]
    assert kinds[0] == "first_contact" and kinds[-1] == "contact_ends", kinds
    assert {"slip_onset", "full_slip", "re_stick", "tangential_reversal"} <= set(kinds), kinds
    slips = [int(way) for kind, way in zip(kinds, run["event_direction"].values) if kind in ("slip_onset", "full_slip")]
    assert slips == [1, 1, -1, -1, 1, 1, 1, 1], slips  # (the strokes' ways, and the let-go's)
    held = np.isfinite(force)
    assert float(run["tangential_force_max"]) >= np.max(force[held])
    assert float(run["tangential_force_min"]) <= np.min(force[held])


def _discrete_errors(name, friction, spacings, stride):
    """The mean |ΔF_x| of the springs at each spacing against the route, at the times every ``stride`` s from first
    contact (each spacing's steps divide it: the same times at every spacing, the route's force computed once)."""
    path = PATHS[name]
    play = _play(path, LAW, friction)
    errors, reference = [], {}
    for dx in spacings:
        dt = TIME_SHARE * dx / path.speed
        run = me.simulate(_contact(LAW, friction), me.Paths([path]), "discrete", dx=dx, dt=dt).isel(case=0)
        run = run.isel(time=slice(None, None, int(round(stride / dt))))
        times = run["time"].values + path.first_contact_time()
        force = run["tangential_force"].values
        key = times.tobytes()
        if key not in reference:  # (every spacing samples the same times: the steps' count does not depend on dx)
            reference[key] = play.tangential_force(times)
        held = np.isfinite(force)
        errors.append(np.mean(np.abs(force - reference[key])[held]))
    return np.array(errors)


@pytest.mark.parametrize("name, friction", [("A20", TAU0_COULOMB),
                                            pytest.param("A20", COULOMB, marks=pytest.mark.slow),
                                            pytest.param("fretting", TAU0_COULOMB, marks=pytest.mark.slow),
                                            pytest.param("fretting", COULOMB, marks=pytest.mark.slow)],
                         ids=["A20-tau0+coulomb", "A20-coulomb", "fretting-tau0+coulomb", "fretting-coulomb"])
def test_the_discrete_springs_converge_to_it_at_first_order(name, friction):
    """The springs under the rate law (rate_springs) at Δx = 4, 2, 1 µm, dt = Δx/(2v): the mean error of F_x over the
    times every 16 s (16 µm of the path) falls at least at first order from each spacing to the next."""
    spacings = (4e-6, 2e-6, 1e-6)
    errors = _discrete_errors(name, friction, spacings, 16.0)
    orders = observed_orders(spacings, errors)
    assert np.all(orders > FIRST_ORDER), (errors, orders)


#: The springs' event times at v_ref = 100 m/s against the spans' of the works at rest: first order in 1/v_ref,
#: measured 4.6e-8 of the clock (the slip onset after the corner of scenario A), so 1e-6.
EVENT_RTOL = 1e-6


@pytest.mark.slow  # 13 s of CPU (measured on the shared machine, loaded): both runs' event logs, the route's bisected
def test_the_log_is_the_spans_as_v_ref_grows_with_the_directions():
    """Scenario A at 20°, v_ref = 100 m/s (n = 1), "tau0+coulomb": the springs' slip onset (after the corner, inside
    the contact) and full slip (on the way out) are the spans' in kind, time and direction. Before, the onset's zone,
    narrower at its time than the 1025 probes' spacing, was found on the quadrature's nodes but given the direction 0
    (no probe at a cap)."""
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 100.0, 1.0)
    scenario = me.Scenario("A", alpha=[20.0])
    logs = []
    for adhesion in (law, me.Adhesion(PAPER.dgamma0, PAPER.dgamma1)):
        run = me.simulate(_contact(adhesion, TAU0_COULOMB), scenario, "continuum", samples=11).isel(alpha=0)
        kinds = [str(kind) for kind in run["event_kind"].values if str(kind)]
        chosen = [k for k, kind in enumerate(kinds) if kind in ("slip_onset", "full_slip")]
        logs.append(([kinds[k] for k in chosen], run["event_direction"].values[chosen],
                     run["event_time"].values[chosen]))
    (kinds, ways, times), (exact_kinds, exact_ways, exact_times) = logs
    assert kinds == exact_kinds == ["slip_onset", "full_slip"], (kinds, exact_kinds)
    np.testing.assert_array_equal(ways, exact_ways)
    np.testing.assert_allclose(times, exact_times, rtol=EVENT_RTOL)


def test_the_flat_punch_runs_too():
    """A flat punch of 1 mm pressed in, rubbed to and fro and pulled off under "tau0+coulomb" at v_ref = 1 m/s: its
    face is in contact at once and rests until it lets go, so F_x is the spans' of the works at rest to LIMIT_RTOL
    (measured 3e-16 of the largest force at 1 and 10 m/s)."""
    punch = me.FlatPunch(1e-3)
    path = me.Path(np.array([(0, -1e-6), (0, 2e-6), (2e-5, 2e-6), (-2e-5, 1e-6), (0, -3e-5)]), speed=1e-7)
    exact = me.simulate(_contact(me.Adhesion(PAPER.dgamma0, PAPER.dgamma1), TAU0_COULOMB, punch), me.Paths([path]),
                        "continuum", samples=SAMPLES).isel(case=0)
    times = exact["time"].values + path.first_contact_time()
    reference = exact["tangential_force"].values
    held = np.isfinite(reference)
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1.0, 1.0)
    force = _play(path, law, TAU0_COULOMB, punch).tangential_force(times)
    np.testing.assert_allclose(force[held], reference[held], rtol=0.0,
                               atol=LIMIT_RTOL * np.max(np.abs(reference[held])))


@pytest.mark.parametrize("law", ["coulomb", "tau0+coulomb"])
def test_a_law_with_coulombs_part_at_mu_zero_runs_as_its_tau0_part(law):
    """``μ = 0`` passed the law's check and was then refused inside the run by ``solve_rate_shifts`` (a message
    that pointed to the very method that raised it): the route takes it, and gives the τ0 part alone (nothing for
    ``"coulomb"``), within the route's agreement with the closed-form play (:data:`SAME_RTOL`)."""
    friction = me.FrictionLaw(law, mu=0.0) if law == "coulomb" else me.FrictionLaw(law, mu=0.0, tau0=BASE.friction.tau0)
    method = me.Continuum(samples=SAMPLES)
    motion = me.Scenario("A", [20.0])
    rate = dataclasses.replace(BASE, adhesion=LAW)
    got = me.simulate(dataclasses.replace(rate, friction=friction), motion, method)["tangential_force"].values
    tau0 = me.simulate(rate, motion, method)["tangential_force"].values
    want = np.zeros_like(tau0) if law == "coulomb" else tau0
    np.testing.assert_allclose(got, want, rtol=0.0, atol=SAME_RTOL * np.nanmax(np.abs(tau0)))
