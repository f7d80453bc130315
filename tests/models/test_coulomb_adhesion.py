"""Coulomb's law alone with adhesion in the continuum (models.continuum.caps.compressed_zone_alone): against the
closed forms at a constant depth (Cattaneo–Mindlin of the compressed zone, Masing's loops, the loop energy, full slip)
to CONTINUUM_RTOL, and the discrete model converging to it at first order on scenarios A and B at three angles and on
a fretting path with re-contact, for Δγ0 = Δγ1, Δγ0 < Δγ1 and Δγ1 < Δγ0."""

from __future__ import annotations

import contextlib

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences, observed_orders
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import EventKind, evaluate, solve_path, tangential_work
from mdr_events.models.continuum.work import algebraic_tangential_force
from mdr_events.theory import mindlin

DEPTH = 1e-4
#: The continuum against the closed forms, as a share of full slip (its rtol is 1e-10; a loop's branches are exact
#: between events), as in tests/models/test_friction_laws.py.
CONTINUUM_RTOL = 1e-9
COULOMB = FrictionLaw("coulomb", mu=0.3)
#: (Δγ0, Δγ1) in J/m²: equal, the paper's Δγ0 < Δγ1, and Δγ1 < Δγ0
ADHESIONS = [(0.05, 0.05), (0.01, 0.15), (0.15, 0.01)]
IDS = ["equal", "paper", "reversed"]


def _params(dgamma0, dgamma1):
    return me.Parameters.paper().replace(dgamma0=dgamma0, dgamma1=dgamma1)


#: The fretting amplitude (m): Coulomb's full slip shift is κ d = 45 µm at DEPTH for any profile (μ = 0.3), so 0.8 X
#: slides partly and 1.5 X wholly; whole µm keep the path's corners on the discrete runs' time grids.
X = 50e-6


def _fretting_path(params, profile=None, speed=1e-6):
    """In to 1.5 DEPTH (the radius pinned by the history, or on the Δγ1 branch), out to DEPTH, then
    0 → 0.8 X → −0.8 X → 0.8 X → −0.3 X → 1.5 X along x, out to −2 µm (the compressed zone gone, the adhesive contact
    still there or off) and in again along a 3-4-5 line to 98 µm: a Mindlin loop, an inner loop, full slip and a
    re-contact. Every corner lies a whole number of seconds after first contact (1 s after the start)."""
    assert 0.8 * X < mindlin.full_slip_shift(DEPTH, COULOMB, params, profile) < 1.5 * X
    turns = np.array([0.0, 0.8, -0.8, 0.8, -0.3, 1.5]) * X
    points = [(0.0, -1e-6), (0.0, 1.5 * DEPTH)] + [(x, DEPTH) for x in turns] + [(1.5 * X, -2e-6), (0.0, 98e-6)]
    return me.Path(np.array(points), speed=speed)


@pytest.mark.parametrize("profile", [None, PowerLaw.cone(0.05), PowerLaw(2e5, 3.0)], ids=["paraboloid", "cone", "n3"])
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_the_continuum_gives_cattaneo_mindlin_of_the_compressed_zone(adhesion, profile):
    """At the depth DEPTH, after a deeper stroke: F_x is Masing's rules on μ (F_N^H(d) − F_N^H(d − u/κ)), free of Δγ
    and of the pinned radius; full slip is μ F_N^H(d) exactly (not μ F_N), every spring sliding (those in tension
    at a zero cap); the algebraic force on the stored anchors agrees; the work of the Mindlin loop is its energy."""
    params = _params(*adhesion)
    path = _fretting_path(params, profile)
    solution = solve_path(params, path, profile=profile, friction=COULOMB)
    corners = path.corner_times - path.first_contact_time()
    times = np.union1d(np.linspace(corners[2], corners[7], 3001), corners[2:8])
    out = evaluate(solution, times)
    assert np.all(out["indentation_depth"] == DEPTH)
    expected = mindlin.tangential_force(out["tangential_displacement"], DEPTH, COULOMB, params, profile)
    full = mindlin.full_slip_force(DEPTH, COULOMB, params, profile)
    np.testing.assert_allclose(out["tangential_force"], expected, rtol=0, atol=CONTINUUM_RTOL * full)
    assert out["tangential_force"][-1] == pytest.approx(full, rel=1e-12)
    x_c = evaluate(solution.compressed, times[-1:])["contact_radius"][0]
    assert out["sliding_fraction"][-1] == 1.0 and out["contact_radius"][-1] > 1.01 * x_c  # (a tensile annulus)
    assert full > (1 + 1e-4) * COULOMB.mu * out["normal_force"][-1]  # μ F_N^H(d), above μ F_N
    np.testing.assert_allclose(algebraic_tangential_force(solution, times), out["tangential_force"], rtol=0,
                               atol=CONTINUUM_RTOL * full)
    # the work over the closed loop −0.8 X → 0.8 X → −0.8 X (corners 3 to 5), then the energy of Masing's loop
    work = tangential_work(solution, corners[3], corners[5])
    assert work == pytest.approx(float(mindlin.loop_energy(0.8 * X, DEPTH, COULOMB, params, profile)), rel=1e-8)
    kinds = [event.kind for event in solution.events]
    assert kinds[0] is EventKind.FIRST_CONTACT and EventKind.FULL_SLIP in kinds and EventKind.RE_STICK in kinds
    slips = [event for event in solution.events if event.kind is EventKind.FULL_SLIP]
    assert all(event.radius == evaluate(solution, np.array([event.time]))["contact_radius"][0] for event in slips)


@contextlib.contextmanager
def each_path_solved_once():
    """Within the block the continuum's ``solve_path`` solves each path once: the exact references of a convergence
    study at each spacing's own output times are one solution filled at those times (``solve_path`` is deterministic
    and its solution is only read after it returns: the same values bit for bit). The solve, not the springs, was
    most of such a study's cost (1.2 s of 1.5 s per spacing on the crossing paths of test_tau0_coulomb_adhesion).
    The block's value: the solutions kept, by ``(params, the path's waypoints' bytes, its speed, the other
    arguments)``."""
    from mdr_events.models.continuum import solve as solve_module

    original, solved = solve_module.solve_path, {}

    def once(params, path, *args, **kwargs):
        key = (params, path.waypoints.tobytes(), path.speed, args, tuple(sorted(kwargs.items())))
        if key not in solved:
            solved[key] = original(params, path, *args, **kwargs)
        return solved[key]

    solve_module.solve_path = once
    try:
        yield solved
    finally:
        solve_module.solve_path = original


def _convergence(params, cases, spacings, speed=1e-6, share=0.5, friction=COULOMB, **options):
    """max_t |discrete − continuum| of F_x, F_N and A per case at each spacing (dt = ``share`` Δx/v) under
    ``friction`` (the continuum solved once per path, :func:`each_path_solved_once`)."""
    differences = {}
    with each_path_solved_once():
        for dx in spacings:
            discrete = me.simulate(params, cases, dx=dx, dt=share * dx / speed, friction=friction, **options)
            exact = me.simulate(params, cases, method="continuum", t=discrete["time"].values, friction=friction,
                                **options)
            for name, values in history_differences(discrete, exact).items():
                differences.setdefault(name, []).append(np.atleast_1d(values))
    return {name: np.array(values) for name, values in differences.items()}


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_the_discrete_model_converges_to_the_continuum_on_scenarios_a_and_b(adhesion, scenario):
    """Scenarios A and B at 15°, 30° and 60° with μ = 0.3 (the angle of friction about 60°): F_x, F_N and A of the
    springs at Δx = 8, 4, 2 µm fall at first order onto the continuum's (:func:`_assert_first_order`)."""
    params = _params(*adhesion)
    spacings = (8e-6, 4e-6, 2e-6)
    differences = _convergence(params, scenario, spacings, alpha=[15.0, 30.0, 60.0])
    _assert_first_order(spacings, differences, 3)


def _assert_first_order(spacings, differences, cases):
    """F_x falls at first order from each spacing to the next (observed orders above 0.7); F_N and A, which the
    friction law does not change, over the whole range (their jump-off falls between time samples, where a sample's
    difference is the quantised radius's share of the jump: not monotone from one spacing to the next)."""
    for case in range(cases):
        orders = observed_orders(spacings, differences["tangential_force"][:, case])
        assert np.all(orders > 0.7), (case, differences["tangential_force"][:, case])
        for name in ("normal_force", "contact_area"):
            overall = observed_orders(spacings[::2], differences[name][::2, case])
            assert np.all(overall > 0.7), (name, case, differences[name][:, case])


@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_the_discrete_model_converges_to_the_continuum_on_a_fretting_path_with_re_contact(adhesion):
    params = _params(*adhesion)
    spacings = (8e-6, 4e-6, 2e-6)
    differences = _convergence(params, _fretting_path(params), spacings, share=0.125)  # dt = 1, 0.5, 0.25 s
    _assert_first_order(spacings, differences, 1)


#: Slip events as the sliding fraction shows them: the adhesion cases and Δγ0 = 0 (the contact grows without an annulus,
#: which opens where the depth first falls below g(a)).
EVENT_ADHESIONS = ADHESIONS + [(0.0, 0.15)]


@pytest.mark.parametrize("adhesion", EVENT_ADHESIONS, ids=IDS + ["grows-without"])
@pytest.mark.parametrize("path", ["A", "B", "vertical", "fretting"])
def test_the_slip_events_are_those_the_sliding_fraction_shows(adhesion, path):
    """The first slip onset and full slip of the log (the compressed zone's and the tensile annulus's, which slides at a
    zero cap) are the first samples where the exact sliding fraction slides (partly, wholly: validate's rules) on a
    grid of 50 001 samples, to one spacing; the instant of first contact (every spring in tension for that instant
    only) is no full slip."""
    from mdr_events.analysis.samples import sliding as sliding_samples
    params = _params(*adhesion)
    paths = {"A": me.Path.scenario_A(20.0, params), "B": me.Path.scenario_B(30.0, params),
             "vertical": me.Path.scenario_A(90.0, params), "fretting": _fretting_path(params)}
    solution = solve_path(params, paths[path], friction=COULOMB)
    times = np.linspace(0.0, solution.end_time, 50001)
    sliding = evaluate(solution, times)["sliding_fraction"]
    spacing = times[1]
    for kind, shown in zip((EventKind.SLIP_ONSET, EventKind.FULL_SLIP), sliding_samples(sliding)):
        logged = [event.time for event in solution.events if event.kind is kind]
        shown[0] = shown[0] and kind is EventKind.SLIP_ONSET  # (the instant of first contact)
        assert bool(logged) == bool(np.any(shown)), (kind, logged)
        if logged:
            first = times[np.flatnonzero(shown)[0]]
            assert logged[0] <= first <= logged[0] + spacing * (1 + 1e-9), (kind, logged[0], first)
    if adhesion[0] > 0:  # the jump-in radius is all annulus: the contact slides from its first instant
        assert solution.events[0].kind is EventKind.FIRST_CONTACT
        assert any(e.kind is EventKind.SLIP_ONSET and e.time == 0.0 and e.direction == 0 for e in solution.events)


def test_a_vertical_coulomb_indentation_without_adhesion_does_not_slide():
    """Without adhesion and tangential motion nothing slides: the one spring at the growing edge (zero compression,
    zero cap) is a zone of round-off in the exact sliding fraction (4e-16 of the contact), below SLIDING_SHARE."""
    from mdr_events.analysis.samples import SLIDING_SHARE, sliding as sliding_samples
    params = _params(0.0, 0.0)
    path = me.Path.scenario_A(90.0, params)
    solution = solve_path(params, path, friction=COULOMB)
    sliding = evaluate(solution, np.linspace(0.0, solution.end_time, 20001))["sliding_fraction"]
    assert np.nanmax(sliding) < SLIDING_SHARE and not np.any(sliding_samples(sliding).partly)
    assert not [event for event in solution.events if event.kind is EventKind.SLIP_ONSET]
