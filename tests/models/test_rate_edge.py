"""The radius of a contact under the rate-dependent adhesion law (models.continuum.rate_edge.solve_edge): the flat
punch's detachment against its closed form, the paper's law as v_ref → ∞ (the pull-off force converging at the
order n = 1 gives), a resting edge leaving the band where the branch (9) of Δγ1 says, and a faster unloading pulling
harder."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.models.continuum import evaluate, solve_path
from mdr_events.models.continuum.rate_edge import EdgeEventKind, solve_edge
from mdr_events.theory import rate_adhesion
from mdr_events.theory.analytic import jkr_contact_radius

PAPER = me.Parameters.paper()
#: The ODE's rtol (EDGE_RTOL 1e-10) over a detachment of ~600 s of slow receding: its time to a few 1e-9.
DETACHMENT_RTOL = 1e-8
#: The depth where a resting edge starts to recede, against the branch (9): the crossing of a linear depth with a
#: closed form, to rounding.
BRANCH_DEPTH_RTOL = 1e-12


def _law(v_ref, n=1.0, params=PAPER):
    return RateDependentAdhesion(params.dgamma0, params.dgamma1, v_ref, n)


def _events(run, kind):
    return [event for event in run.events if event.kind is kind]


def test_a_flat_punch_held_beyond_kendall_detaches_when_the_closed_form_says():
    """In to 2 µm, out to −80 µm (beyond Kendall's −57 µm: the edge recedes on the way), held there while sliding."""
    punch = me.FlatPunch(1.5e-3)
    params = PAPER.replace(dgamma0=0.05)
    law = _law(1e-6, params=params)
    path = me.Path(np.array([(0.0, 0.0), (0.0, 2e-6), (0.0, -80e-6), (0.05, -80e-6)]), speed=1e-6)
    run = solve_edge(params, path, law, profile=punch)
    held = path.corner_times[2]
    radius_held = float(run.radius(np.array([held]))[0])
    assert 0.0 < radius_held < punch.radius  # it has receded some on the way out
    ended = _events(run, EdgeEventKind.CONTACT_ENDS)[0]
    closed = rate_adhesion.flat_punch_detachment_time(law, radius_held, -80e-6, params.E_star, radius=ended.radius)
    assert ended.radius < 1e-3 * punch.radius
    assert ended.time - held == pytest.approx(closed, rel=DETACHMENT_RTOL)


def test_a_fast_reference_speed_gives_the_paper_s_pull_off():
    """Vertical in and out: the least F_N approaches JKR's pull-off force −(3/2)πΔγ1 R (the path passes its force
    minimum before the jump-off) as v_ref grows, at first order in 1/v_ref (n = 1), and the forces in contact approach
    the continuum's."""
    path = me.Path.scenario_A(90.0, PAPER)
    exact = solve_path(PAPER, path, friction=me.FrictionLaw("tau0", tau0=0.0))
    # (from 1/1000 of the way in: the rate-dependent jump-in takes a time of a_J/v_ref, the paper's none)
    times = path.first_contact_time() + np.linspace(1e-3, 0.95, 2001) * exact.end_time
    reference = evaluate(exact, times - exact.t_contact)["normal_force"]
    pull_off = -1.5 * math.pi * PAPER.dgamma1 * PAPER.R
    errors, history = [], []
    for v_ref in (1e-2, 1e-1, 1.0):
        run = solve_edge(PAPER, path, _law(v_ref))
        errors.append(abs(run.pull_off_force(path) - pull_off) / abs(pull_off))
        history.append(np.max(np.abs(run.normal_force(times, path) - reference)) / np.ptp(reference))
    orders = -np.diff(np.log10(errors))
    assert np.all(orders > 0.8), errors
    assert np.all(np.diff(history) < 0) and history[-1] < 1e-3, history


def test_a_resting_edge_recedes_where_the_branch_of_dgamma1_says():
    """In to d_max, slide at d_max, out: the edge lags the indentation (v_ref only 10 times the path's speed) and
    creeps on while the indenter slides at d_max, its release rate approaching Δγ0 from below without reaching it (the
    radius below the branch's at d_max); it stops once the depth falls, rests, and starts to recede at the depth of
    the branch (9) of Δγ1 at the held radius."""
    law = _law(1e-5, n=0.6)
    d = PAPER.d_max
    path = me.Path(np.array([(0.0, -1e-6), (0.0, d), (200e-6, d), (200e-6, -30e-6)]), speed=1e-6)
    run = solve_edge(PAPER, path, law)
    turn, slid = path.corner_times[1], path.corner_times[2]
    creeping = run.radius(np.linspace(turn, slid, 50))
    assert np.all(np.diff(creeping) > 0) and creeping[-1] < jkr_contact_radius(d, PAPER, PAPER.dgamma0)
    stops = _events(run, EdgeEventKind.EDGE_STOPS)[0]
    assert slid < stops.time < _events(run, EdgeEventKind.RECEDING_STARTS)[0].time
    resting = np.linspace(stops.time, _events(run, EdgeEventKind.RECEDING_STARTS)[0].time, 50)
    assert np.all(run.radius(resting) == stops.radius)
    receding = _events(run, EdgeEventKind.RECEDING_STARTS)[0]
    a = receding.radius
    branch = a**2 / PAPER.R - math.sqrt(2 * math.pi * a * PAPER.dgamma1 / PAPER.E_star)
    assert receding.depth == pytest.approx(branch, rel=BRANCH_DEPTH_RTOL)


def test_a_faster_unloading_pulls_harder():
    """The same in/out path at four speeds under v_ref = 1e-5 m/s, n = 0.6: the receding edge needs more energy
    the faster it moves (Maugis–Barquins), so the least F_N grows in magnitude with the speed, from the paper's."""
    law = _law(1e-5, n=0.6)
    least = []
    for speed in (1e-8, 1e-7, 1e-6, 1e-5):
        params = PAPER.replace(v=speed)
        path = me.Path.scenario_A(90.0, params)
        run = solve_edge(params, path, law)
        least.append(run.pull_off_force(path))
    exact = solve_path(PAPER, me.Path.scenario_A(90.0, PAPER), friction=me.FrictionLaw("tau0", tau0=0.0))
    paper = np.min(evaluate(exact, np.linspace(0.0, exact.end_time, 20001))["normal_force"])
    assert paper > least[0] and np.all(np.diff(least) < 0), (paper, least)


def test_a_law_of_other_works_is_refused():
    with pytest.raises(ValueError, match="law=.*dgamma0=0.01"):
        solve_edge(PAPER, me.Path.scenario_A(90.0, PAPER), RateDependentAdhesion(0.02, 0.15, 1e-6, 1.0))


def test_the_continuum_method_refuses_what_its_edge_does_not_follow_by_name():
    """Before, Coulomb's part (a cap that differs from spring to spring) was refused here; it runs spring by spring
    (tests/models/test_rate_coulomb.py). What stays refused: a layer of finite thickness (the edge's ODE is Heß's rule
    on the half-space, which a layer's compliance changes), in one line naming the law and the layer."""
    paper = me.Contact.paper()
    coulomb = me.Contact(paper.elastomer, paper.indenter, _law(1e-6), me.FrictionLaw("tau0+coulomb", tau0=4.2e4,
                                                                                      mu=0.3))
    with pytest.raises(TypeError, match=r"adhesion=RateDependentAdhesion.*not allowed on layer h = 0.005 m.*the "
                                        r"rate-dependent law runs on the half-space") as raised:
        me.simulate(dataclasses.replace(coulomb, layer=me.Layer(5e-3)), "A", 20.0, "continuum")
    assert "\n" not in str(raised.value)


#: LSODA's curve against the reference (Radau at REFERENCE_RTOL) on the fit's three speeds: LSODA's error control
#: reaches about 20 times its rtol (1e-10) on these paths, measured 1.7e-9 to 2.3e-9 of the largest force.
LSODA_CURVE_RTOL = 1e-8
#: The reference's rtol: Radau's curve at 1e-11 is within 0.9e-12 to 2.8e-12 of the largest force of its run at 1e-12
#: on these paths (measured), three decades below LSODA's error and four below LSODA_CURVE_RTOL, at half its CPU (the
#: run at 1e-12 took 1.2-2.5 s a speed, this test's whole cost)
REFERENCE_RTOL = 1e-11


@pytest.mark.parametrize("speed", [1e-7, 1e-6, 1e-5])
def test_lsoda_gives_the_reference_curve_within_its_tolerance(speed):
    """The fit's method (analysis.rate_fit.RATE_FIT_METHOD at RATE_FIT_RTOL) against Radau at REFERENCE_RTOL, in and
    out."""
    law = _law(1e-6, n=0.6)
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -200e-6)]), speed=speed)
    times = np.linspace(path.first_contact_time(), path.duration, 400)
    reference = solve_edge(PAPER, path, law, rtol=REFERENCE_RTOL).normal_force(times, path)
    fast = solve_edge(PAPER, path, law, rtol=1e-10, method="LSODA").normal_force(times, path)
    scale = np.max(np.abs(reference))
    assert np.max(np.abs(fast - reference)) <= LSODA_CURVE_RTOL * scale
    assert np.max(np.abs(fast - reference)) > 0.0  # (another integrator: not the reference by accident)


@pytest.mark.parametrize("method", ["RK45", "radau", None, 3])
def test_a_method_that_does_not_take_stiff_pieces_is_named(method):
    with pytest.raises(ValueError, match=r"method=.* is not allowed; allowed: one of Radau, BDF, LSODA"):
        solve_edge(PAPER, me.Path.scenario_A(90.0, PAPER), _law(1e-6), method=method)


#: Where each method stops or lets the edge go, against Radau's: their tolerances at 1e-10 over about 1000 s, a few
#: 1e-7 s measured (LSODA's error control reaches about 20 times its rtol).
EVENT_TIME_RTOL = 1e-8


def test_an_event_the_dense_output_misses_by_rounding_is_still_found():
    """n = 0.3, v_ref = 1e-3 m/s, scenario B at 30°: LSODA's step that starts the receding edge ends beyond the band
    while its dense output, rounded, does not reach it: solve_ivp failed there with Brent's "f(a) and f(b) must have
    different signs" (refusing the law); the edge's own loop puts the crossing at the step's start and every method
    ends the contact where Radau does."""
    law = _law(1e-3, n=0.3)
    path = me.Path.scenario_B(30.0, PAPER)
    ends = {method: _events(solve_edge(PAPER, path, law, method=method), EdgeEventKind.CONTACT_ENDS)[0].time
            for method in ("Radau", "LSODA", "BDF")}
    assert ends["LSODA"] == pytest.approx(ends["Radau"], rel=EVENT_TIME_RTOL)
    assert ends["BDF"] == pytest.approx(ends["Radau"], rel=EVENT_TIME_RTOL)


@pytest.mark.parametrize("method", ["Radau", "LSODA"])
def test_the_edge_s_loop_takes_solve_ivp_s_steps_bit_for_bit(method):
    """One moving piece by rate_march.march and by solve_ivp with the same solver, options and events: the same end,
    event and dense output at 1000 times."""
    from scipy.integrate import solve_ivp

    from mdr_events.models.continuum.rate_edge import _EdgeODE, EdgeMode
    from mdr_events.models.continuum.model import kinematics
    from mdr_events.models.continuum.rate_march import march

    law = _law(1e-6, n=0.6)
    segment = kinematics(me.Path.scenario_A(90.0, PAPER))[0]
    ode = _EdgeODE(law, PAPER, None, segment)
    start, radius = segment.t0 + 1.0, 5e-4  # (its spring stretched: advancing at a finite speed)
    events = ode.moving_events(EdgeMode.ADVANCING, 1e-9)
    with np.errstate(divide="ignore"):  # (Radau's step-size rule divides by an error norm of 0 on a smooth start)
        ours = march(ode.rhs(EdgeMode.ADVANCING), start, segment.t1, radius, method, 1e-10, 1e-15, events)
        theirs = solve_ivp(ode.rhs(EdgeMode.ADVANCING), (start, segment.t1), [radius], method=method, rtol=1e-10,
                           atol=1e-15, dense_output=True, events=events)
    assert (ours.t, ours.y, ours.status) == (theirs.t[-1], theirs.y[0, -1], theirs.status)
    times = np.linspace(start, ours.t, 1000)
    np.testing.assert_array_equal(ours.sol(times), theirs.sol(times))


#: The energy balance of an in/out cycle, both sides by Gauss–Legendre on the solver's steps (exact for their
#: polynomials) of the same radius: they differ by the quadrature of the speed law and F_N between steps and the ODE's
#: tolerance (1e-10), measured 1e-10 of the work.
ENERGY_RTOL = 1e-8


def _cycle_energies(speed: float) -> tuple[float, float]:
    """∮ F_N dd over a vertical in/out cycle at ``speed`` (the indenter's work), and the energy the edge dissipated,
    -∫ Γ dA (A = π a², Γ by Heß's rule), plus the springs' elastic energy E* ∫_0^a (d - g)² dx left where the run ends
    (the last 1e-3 of the jump-in radius, whose collapse it does not follow)."""
    law = _law(1e-6, n=0.6)
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -300e-6)]), speed=speed)
    run = solve_edge(PAPER, path, law)
    nodes, weights = np.polynomial.legendre.leggauss(12)
    work = dissipated = 0.0
    for t0, t1, _, dense in run.pieces:
        knots = np.unique(np.clip(np.concatenate([getattr(dense, "ts", [t0, t1]), [t0, t1], path.corner_times]), t0,
                                  t1))
        low, high = knots[:-1], knots[1:]
        times = 0.5 * (low + high)[:, None] + 0.5 * (high - low)[:, None] * nodes[None, :]
        radius = dense(times.ravel())[0].reshape(times.shape)
        depth = path.position(times)[1]
        rate = (path.position(high)[1] - path.position(low)[1]) / (high - low)
        force = np.asarray(run.model.normal_force(depth, radius))
        work += np.sum(0.5 * (high - low) * rate * (force @ weights))
        release = rate_adhesion.release_rate(radius ** 2 / PAPER.R - depth, radius, PAPER.E_star)
        speed_of_edge = np.nan_to_num(rate_adhesion.edge_speed(law, release), posinf=0.0)
        dissipated -= np.sum(0.5 * (high - low) * ((release * 2.0 * math.pi * radius * speed_of_edge) @ weights))
    end = _events(run, EdgeEventKind.CONTACT_ENDS)[0]
    x = end.radius * 0.5 * (1.0 + nodes)
    left = PAPER.E_star * 0.5 * end.radius * np.sum(weights * (end.depth - x ** 2 / PAPER.R) ** 2)
    return work, dissipated + left


def test_an_in_out_cycle_s_work_is_the_energy_the_edge_dissipated_and_grows_with_the_speed():
    """The indenter's work over the cycle equals the edge's dissipation (Griffith's balance, closed: no elastic energy
    before or after), and a faster cycle dissipates more."""
    works = []
    for speed in (1e-8, 1e-6, 1e-5):
        work, balance = _cycle_energies(speed)
        assert work == pytest.approx(balance, rel=ENERGY_RTOL), speed
        works.append(work)
    assert works[0] < works[1] < works[2]


#: v_ref far below the path's speed: the advancing edge's work is about Δγ0 (v_ref/ȧ)^n, the edge's stretch its square
#: root, so the radius at d_max lies above Hertz's by a share falling as (v_ref/v)^(n/2): by 10^0.3 = 2.0 per decade at
#: n = 0.6 (measured 1.98).
SLOW_LAW_DECADE = (1.6, 2.4)
#: A refusal is "soon": the CPU time of one (measured below 1 ms; the budget of ODE evaluations, MAX_EVALUATIONS, about
#: 4 s, where the refusal is by the budget).
REFUSAL_CPU = 1.0


def test_a_reference_speed_far_below_the_path_s_integrates_towards_hertz_or_is_refused_soon():
    """Vertically in at 1 µm/s: v_ref = 1e-2 and 1e-3 of it integrate, the radius at d_max above Hertz's by a share
    falling at the order n/2; 1e-4 to 1e-8 of it (the indenter outruns the edge's solver) are refused in one line with
    the reason and the advice, at once."""
    import time

    path = me.Path.scenario_A(90.0, PAPER)
    hertz = math.sqrt(PAPER.R * PAPER.d_max)
    deepest = np.array([path.corner_times[1]])
    shares = [solve_edge(PAPER, path, _law(ratio * PAPER.v, n=0.6)).radius(deepest)[0] / hertz - 1.0
              for ratio in (1e-2, 1e-3)]
    assert 0.0 < shares[1] < shares[0] and SLOW_LAW_DECADE[0] < shares[0] / shares[1] < SLOW_LAW_DECADE[1], shares
    for ratio in (1e-4, 1e-6, 1e-8):
        began = time.process_time()
        with pytest.raises(ValueError) as raised:
            solve_edge(PAPER, path, _law(ratio * PAPER.v, n=0.6))
        assert time.process_time() - began < REFUSAL_CPU
        text = str(raised.value)
        assert "\n" not in text and "the indenter outran the advancing edge" in text and "allowed: " in text
        assert "a larger v_ref" in text or "a law whose edge keeps ahead of the indenter" in text, text
