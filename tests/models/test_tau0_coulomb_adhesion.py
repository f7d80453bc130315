"""``"tau0+coulomb"`` with adhesion on curved indenters in the continuum (models.continuum.split_span: the compressed
zone and the tensile annulus split at the moving x_c): against the closed forms at a constant depth (Masing's rules on
the virgin curve 2G* a min(u, K a) + μ (F_N^H(d) − F_N^H(d − (u − K a)/κ)), full slip τ0 π a² + μ F_N^H, the loop
energy) to CONTINUUM_RTOL; the discrete model converging to it at first order on scenarios A and B at three angles, a
fretting path with re-contact, a zigzag and a path whose springs cross x_c at a cap, for Δγ0 = Δγ1, Δγ0 < Δγ1 and
Δγ1 < Δγ0; its slip events as its sliding fraction shows them; a table of the paraboloid."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import EventKind, evaluate, solve_path, tangential_work
from mdr_events.models.continuum.work import algebraic_tangential_force
from mdr_events.models.continuum.split_map import SpanMaps
from mdr_events.theory import mindlin, symbolic

from quick_round import grid
from test_coulomb_adhesion import _convergence as coulomb_adhesion_convergence, each_path_solved_once

DEPTH = 1e-4
#: The continuum against the closed forms, as a share of full slip (its rtol is 1e-10; a loop's branches are exact
#: between events), as in tests/models/test_friction_laws.py.
CONTINUUM_RTOL = 1e-9
COMBINED = FrictionLaw("tau0+coulomb", mu=0.3)
#: (Δγ0, Δγ1) in J/m²: equal, the paper's Δγ0 < Δγ1, and Δγ1 < Δγ0
ADHESIONS = [(0.05, 0.05), (0.01, 0.15), (0.15, 0.01)]
IDS = ["equal", "paper", "reversed"]
#: τ0 = 1 kPa: the two parts of the cap at DEPTH about 1 : 4 (K a ≈ 12 µm, κ d = 45 µm), each visible
TAU0 = 1e3
#: The fretting amplitude (m): the full slip shift K a + κ d is 55–60 µm at DEPTH, so 0.8 X slides partly and
#: 1.5 X wholly; whole µm keep the path's corners on the discrete runs' time grids.
X = 50e-6


def _params(dgamma0, dgamma1, tau0=TAU0):
    return me.Parameters.paper().replace(dgamma0=dgamma0, dgamma1=dgamma1, tau0=tau0)


def _fretting_path(speed=1e-6):
    """In to 1.5 DEPTH, out to DEPTH (the radius pinned by the history, or on the Δγ1 branch), then
    0 → 0.8 X → −0.8 X → 0.8 X → −0.3 X → 1.5 X along x, out to −2 µm (the compressed zone gone, every spring in
    tension, the contact held or off) and in again along a 3-4-5 line to 98 µm: a Mindlin loop, an inner loop, full
    slip and a re-contact. Every corner lies a whole number of seconds after first contact (1 s after the start)."""
    turns = np.array([0.0, 0.8, -0.8, 0.8, -0.3, 1.5]) * X
    points = [(0.0, -1e-6), (0.0, 1.5 * DEPTH)] + [(x, DEPTH) for x in turns] + [(1.5 * X, -2e-6), (0.0, 98e-6)]
    return me.Path(np.array(points), speed=speed)


@pytest.mark.parametrize("adhesion, profile", grid(  # (each 0.2-0.3 s of CPU: each adhesion and indenter once quick)
    {"adhesion": dict(zip(IDS, ADHESIONS)), "profile": {"paraboloid": None, "cone": PowerLaw.cone(0.05),
                                                         "n3": PowerLaw(2e5, 3.0)}},
    {("equal", "paraboloid"), ("paper", "cone"), ("reversed", "n3")}))
def test_the_continuum_gives_masings_loops_on_the_pinned_radius(adhesion, profile):
    """At the depth DEPTH after a deeper stroke: F_x is Masing's rules on the virgin curve of the pinned radius (the
    τ0 part over the whole contact, Coulomb's over the compressed zone), full slip τ0 π a² + μ F_N^H(d) exactly (the
    derived adhesive_full_slip_force, above τ0 π a² + μ F_N), the algebraic force on the stored anchors agrees along
    the whole path (the out stroke into tension and the re-contact too), and the work of the Mindlin loop is its
    energy."""
    params = _params(*adhesion)
    path = _fretting_path()
    solution = solve_path(params, path, profile=profile, friction=COMBINED)
    corners = path.corner_times - path.first_contact_time()
    times = np.union1d(np.linspace(corners[2], corners[7], 3001), corners[2:8])
    out = evaluate(solution, times)
    assert np.all(out["indentation_depth"] == DEPTH)
    radius = float(out["contact_radius"][0])
    assert np.all(out["contact_radius"] == radius)
    expected = mindlin.tangential_force(out["tangential_displacement"], DEPTH, COMBINED, params, profile, radius=radius)
    full = mindlin.full_slip_force(DEPTH, COMBINED, params, profile, radius=radius)
    np.testing.assert_allclose(out["tangential_force"], expected, rtol=0, atol=CONTINUUM_RTOL * full)
    assert out["tangential_force"][-1] == pytest.approx(full, rel=1e-12)
    indenter = profile or PowerLaw.paraboloid(params.R)
    derived = symbolic.relation("adhesive_full_slip_force").numeric(DEPTH, radius, params.tau0, COMBINED.mu,
                                                                      indenter.c, indenter.n, params.E_star)
    assert full == pytest.approx(float(derived), rel=1e-12)
    assert full > (1 + 1e-4) * (params.tau0 * np.pi * radius**2 + COMBINED.mu * out["normal_force"][-1])
    everywhere = np.linspace(0.0, solution.end_time, 4001)
    np.testing.assert_allclose(algebraic_tangential_force(solution, everywhere),
                               evaluate(solution, everywhere)["tangential_force"], rtol=0, atol=CONTINUUM_RTOL * full)
    work = tangential_work(solution, corners[3], corners[5])  # the closed loop −0.8 X → 0.8 X → −0.8 X
    energy = mindlin.loop_energy(0.8 * X, DEPTH, COMBINED, params, profile, radius=radius)
    assert work == pytest.approx(float(energy), rel=1e-8)
    kinds = [event.kind for event in solution.events]
    assert EventKind.FULL_SLIP in kinds and EventKind.RE_STICK in kinds


def _convergence(params, cases, spacings, share=0.5, **options):
    """max_t |discrete − continuum| of F_x, F_N and A per case at each spacing (dt = ``share`` Δx/v), both parts."""
    return coulomb_adhesion_convergence(params, cases, spacings, share=share, friction=COMBINED, **options)


def _assert_first_order(spacings, differences, least=0.7):
    """F_x falls at first order from each spacing to the next (observed orders above ``least``), its largest error
    over the cases taken (a case's own error follows where the radius falls between springs, by a share that need not
    shrink with Δx: tests/models/test_friction_laws.py); F_N and A, which the friction law does not change, over the
    whole range (their jump-off falls between time samples)."""
    orders = observed_orders(spacings, differences["tangential_force"].max(axis=1))
    assert np.all(orders > least), differences["tangential_force"]
    for name in ("normal_force", "contact_area"):
        overall = observed_orders(spacings[::2], differences[name][::2].max(axis=1))
        assert np.all(overall > least), (name, differences[name])


#: The angles of scenarios A and B (degrees): B at 60° slides wholly in tension a few µm before the pull-off, where
#: the springs' quantised radius decides F_x = τ0 π a² alone, sample by sample
ANGLES = [15.0, 30.0, 45.0]


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_the_discrete_model_converges_on_scenarios_a_and_b(adhesion, scenario):
    """Scenarios A and B at 15°, 30° and 45° with the paper's τ0 and μ = 0.3: F_x, F_N and A of the springs at
    Δx = 8, 4, 2 µm fall at first order onto the continuum's."""
    params = _params(*adhesion, tau0=me.Parameters.paper().tau0)
    spacings = (8e-6, 4e-6, 2e-6)
    _assert_first_order(spacings, _convergence(params, scenario, spacings, alpha=ANGLES))


def _zigzag(depth):
    """In and out along x while going deeper: six strokes of ±60 µm from 0.6 to 1.85 ``depth``, back to 0.3
    ``depth``, in to 1.5 ``depth`` and out beyond the pull-off (reversals with the radius growing, pinned and
    shrinking)."""
    points = [(0.0, -1e-6)] + [((-1) ** k * 60e-6, (0.6 + 0.25 * k) * depth) for k in range(6)]
    return me.Path(np.array(points + [(0.0, 0.3 * depth), (40e-6, 1.5 * depth), (-20e-6, -5e-6)]), speed=1e-6)


#: The depths (shares of DEPTH) of the zigzag and of the crossing path: at one depth the springs' radius can fall as
#: far between springs at 1, 0.5 and 0.25 µm (1739.9 µm is 0.1 µm short of a whole number of each), and the largest
#: error over several depths shows the first order
DEPTHS = (1.0, 1.07, 1.15)


@pytest.mark.parametrize("adhesion, motion", grid(  # (each 0.4-0.7 s of CPU: each adhesion and each path once quick)
    {"adhesion": dict(zip(IDS, ADHESIONS)), "motion": {"fretting": "fretting", "zigzag": "zigzag"}},
    {("equal", "fretting"), ("paper", "zigzag"), ("reversed", "fretting")}))
def test_the_discrete_model_converges_on_a_fretting_path_with_re_contact_and_a_zigzag(adhesion, motion):
    """The fretting path (out into tension and in again) and the zigzags at DEPTHS: F_x of the springs at
    Δx = 8, 4, 2 µm (dt = Δx/(8v)) falls at first order onto the continuum's."""
    params = _params(*adhesion)
    spacings = (8e-6, 4e-6, 2e-6)
    if motion == "fretting":
        _assert_first_order(spacings, _convergence(params, [_fretting_path()], spacings, share=0.125))
    else:  # (the zigzags with the paper's τ0: both parts of the cap slide)
        zigzags = [_zigzag(share * DEPTH) for share in DEPTHS]
        paper_tau0 = params.replace(tau0=me.Parameters.paper().tau0)
        _assert_first_order(spacings, _convergence(paper_tau0, zigzags, spacings, share=0.125))


def _crossing_path(depth):
    """Full slip at depth, then out and back against the slide (the compressed zone's caps shrinking faster than
    x turns back: its level pushes, the annulus's does not), in again with the slide (the annulus's level pushes, the
    compressed zone's does not), a slide, and out beyond the pull-off and in again along a line."""
    points = [(0.0, -1e-6), (0.0, 1.5 * depth), (0.0, depth), (1.5 * X, depth), (1.5 * X - 10e-6, 0.4 * depth),
              (1.5 * X + 5e-6, 0.8 * depth), (1.5 * X + 40e-6, 0.8 * depth), (0.0, -3e-6), (-20e-6, 90e-6)]
    return me.Path(np.array(points), speed=1e-6)


@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_springs_crossing_x_c_at_a_cap_keep_the_window_of_the_crossing(adhesion):
    """Along :func:`_crossing_path` springs at a cap of the compressed zone cross into the annulus whose level moves
    away, and springs at a cap of the annulus into the compressed zone whose level moves away: each keeps the window
    of its crossing (the continuum reads the destination from a map of those anchors, in both directions). From the
    full slip to the slide after the strokes the springs at Δx = 2, 1, 0.5 µm (dt = Δx/(4v)) fall at first order
    onto the continuum's F_x (the largest relative error over DEPTHS), and the integrated force is the
    algebraic one on the maps along the whole path."""
    params = _params(*adhesion)
    paths = [_crossing_path(share * DEPTH) for share in DEPTHS]
    spacings = (2e-6, 1e-6, 0.5e-6)
    errors = np.zeros((len(spacings), len(paths)))
    with each_path_solved_once() as solved:  # (each path's solution filled at each spacing's times)
        for row, dx in enumerate(spacings):
            discrete = me.simulate(params, paths, dx=dx, dt=0.25 * dx / 1e-6, friction=COMBINED)
            exact = me.simulate(params, paths, method="continuum", t=discrete["time"].values, friction=COMBINED)
            t = discrete["time"].values
            for column, path in enumerate(paths):
                corners = path.corner_times - path.first_contact_time()
                window = (t >= corners[3]) & (t <= corners[6])
                springs = discrete["tangential_force"].values[column][window]
                reference = exact["tangential_force"].values[column][window]
                errors[row, column] = np.max(np.abs(springs - reference)) / np.max(np.abs(reference))
    assert np.all(observed_orders(spacings, errors.max(axis=1)) > 0.7), errors
    # the continuum's solution of the first path, as simulate solved it above (not solved again: ~0.3 s of CPU)
    (solution,) = [kept for key, kept in solved.items() if key[1:3] == (paths[0].waypoints.tobytes(), paths[0].speed)]
    crossed = {np.sign(span.segment.vd) for span in solution.spans
               if isinstance(span.anchors, SpanMaps) and span.anchors.compressed is not span.anchors.tensile}
    assert crossed == {-1.0, 1.0}
    times = np.linspace(0.0, solution.end_time, 2001)
    full = mindlin.full_slip_force(DEPTH, COMBINED, params, radius=float(evaluate(solution, times[:1] + 200.0)
                                                                            ["contact_radius"][0]))
    np.testing.assert_allclose(algebraic_tangential_force(solution, times),
                               evaluate(solution, times)["tangential_force"], rtol=0, atol=CONTINUUM_RTOL * full)


#: The cases of the event test: every adhesion and Δγ0 = 0 (the contact grows without an annulus) on scenario A, B, a
#: vertical path and the fretting path (scenario A with Δγ1 < Δγ0 too: the drop onto the Δγ1 branch logs what the
#: smaller caps do to the springs, models.continuum.solve.drop_onto_branch)
EVENT_CASES = [(adhesion, path) for adhesion in ADHESIONS + [(0.0, 0.15)] for path in ("A", "B", "vertical", "fretting")]


@pytest.mark.parametrize("adhesion, path", EVENT_CASES)
def test_the_slip_events_are_those_the_sliding_fraction_shows(adhesion, path):
    """The first slip onset and full slip of the log are the first samples where the exact sliding fraction slides
    (partly, wholly: validate's rules) on a grid of 50 001 samples, to one spacing (:data:`EVENT_CASES`)."""
    from mdr_events.analysis.samples import sliding as sliding_samples
    params = _params(*adhesion)
    paths = {"A": me.Path.scenario_A(20.0, params), "B": me.Path.scenario_B(30.0, params),
             "vertical": me.Path.scenario_A(90.0, params), "fretting": _fretting_path()}
    solution = solve_path(params, paths[path], friction=COMBINED)
    times = np.linspace(0.0, solution.end_time, 50001)
    sliding = evaluate(solution, times)["sliding_fraction"]
    for kind, shown in zip((EventKind.SLIP_ONSET, EventKind.FULL_SLIP), sliding_samples(sliding)):
        logged = [event.time for event in solution.events if event.kind is kind]
        assert bool(logged) == bool(np.any(shown)), (kind, logged)
        if logged:
            first = times[np.flatnonzero(shown)[0]]
            assert logged[0] <= first <= logged[0] + times[1] * (1 + 1e-9), (kind, logged[0], first)


def test_a_table_of_the_paraboloid_runs_as_the_paraboloid():
    """A table of the paraboloid (401 points) with both parts of the cap and the paper's adhesion: the continuum's
    F_x along scenario B at 30° is the paraboloid's to the table's interpolation error (1e-4 of the largest force;
    2e-5 measured, 4e-7 with 1601 points)."""
    paper = me.Parameters.paper()
    r = np.linspace(0.0, 4e-3, 401)
    table = me.TabulatedProfile(r, r**2 / (2 * paper.R))
    exact = me.simulate(paper, "B", alpha=[30.0], method="continuum", friction=COMBINED)
    tabulated = me.simulate(paper, "B", alpha=[30.0], method="continuum", friction=COMBINED, profile=table,
                            t=exact["time"].values)
    force, reference = tabulated["tangential_force"].values[0], exact["tangential_force"].values[0]
    both = np.isfinite(force) & np.isfinite(reference)
    assert np.count_nonzero(both) > 1000
    np.testing.assert_allclose(force[both], reference[both], rtol=0, atol=1e-4 * np.nanmax(np.abs(reference)))
