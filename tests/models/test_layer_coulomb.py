"""Coulomb's part of the friction law on a layer of finite thickness in the continuum (issues 34 and 26): every
spring's play operator composed on its own (``mdr_events.models.continuum.play_springs``) is the spans' continuum on
the half-space (with and without adhesion: the route takes both, the method runs it on a layer without adhesion), a
thick layer is the half-space, full slip is ``τ0 π a² + μ F_N``, and
the discrete model on the layer converges to it at first order in ``Δx``.

Tolerances, each from how the compared values are computed:

- the spans integrate ``F_x`` to ``rtol = 1e-10`` per step (DOP853) over some tens of steps, the per-spring route sums
  Gauss–Legendre panels between located kinks (to round-off): :data:`ROUTE_SHARE` of the largest force, twenty
  ``rtol`` (observed at most 5e-10);
- the thick layer (``h = 1e9 m``) differs from the half-space by the tables' ``O(a/h)`` (``< 1e-11``) and by the
  quadrature of the tables' splines: :data:`LIMIT_SHARE`;
- full slip: the springs' caps ``ū(a) + μρ(d − g)`` summed by the quadrature against ``π a² τ0 + μ F_N`` with ``F_N``
  the layer's closed ``F₀(a) + K(a)(d − g(a))``: the two differ by the quadrature of the tables' cubic splines across
  their knots (``O(width⁴)`` per panel): :data:`FULL_SLIP_SHARE`;
- the events are bisected to ``2^-48`` of the output spacing and located against the spans' events to their
  ``rtol`` of the run's duration: :data:`EVENT_SHARE`.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum.play_springs import PlaySprings, SpanHistory, spring_line

from quick_round import grid

RTOL = me.Tolerances().rtol
#: The per-spring route against the spans' continuum on the half-space, relative to the largest force.
ROUTE_SHARE = 20.0 * RTOL
#: The same with adhesion: the spans' split regions are integrated by panels (1e-13 of the force) and under Coulomb's
#: law alone the compressed zone by DOP853 at ``rtol`` (2.1e-11 measured over the cases below): one ``rtol``. (A sample
#: of A 20°, Δγ0 = Δγ1, both parts of the law, was 5e-8 off: the stick zone left at the edge just before full slip,
#: 3e-4 of the radius, lay between the last quadrature node and the edge, where no kink was looked for; the spans at
#: ``rtol = 1e-12`` moved by 2e-14 there and the route with 64 panels of 20 nodes came within 2e-14 of them.)
ADHESIVE_ROUTE_SHARE = RTOL
#: A thick layer (h = 1e9 m) against the half-space, relative to the largest force.
LIMIT_SHARE = 1e-8
#: Full slip against ``π a² τ0 + μ F_N``, relative.
FULL_SLIP_SHARE = 1e-8
#: The events of the thick layer against the half-space's spans, relative to the run's duration.
EVENT_SHARE = 100.0 * RTOL
#: The observed order of a first-order error from three halving spacings (as tests/models/test_layer_continuum.py).
ORDER_RANGE = (0.8, 1.3)
#: The same under Coulomb's law alone: its caps ``μρ(d − g)`` vanish at the edge, so the radius's ``O(Δx)`` error
#: moves ``F_x`` at second order (as ``F_N`` without adhesion, tests/models/test_layer_continuum.py), and the
#: springs' sampling of the slip fronts at first: the observed order lies between (1.5–1.9 measured).
COULOMB_ORDER_RANGE = (0.8, 2.3)
#: The spacings of the convergence study (m): 20, 40 and 80 springs per radius at a/h ~ 0.5.
SPACINGS = (4e-5, 2e-5, 1e-5)
MU = 0.3
LAWS = {"coulomb": me.FrictionLaw("coulomb", mu=MU), "tau0+coulomb": me.FrictionLaw("tau0+coulomb", mu=MU,
                                                                                      tau0=42000.0)}
HERTZ = me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)
#: The normal run's springs (:mod:`mdr_events.models.continuum.play_run`)
FRICTIONLESS = me.FrictionLaw("coulomb", mu=0.0)


def fretting(amplitude: float = 1e-3, cycles: int = 2) -> me.Paths:
    """In to the paper's ``d_max`` obliquely, ``cycles`` tangential cycles of ``±amplitude`` there, and out."""
    d_max, speed = me.Parameters.paper().d_max, me.Parameters.paper().v
    x = np.concatenate([[0.0, 50e-6], np.tile([amplitude, -amplitude], cycles), [0.0]])
    d = np.concatenate([[-1e-6, d_max], np.full(2 * cycles, d_max), [-1e-5]])
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), speed)})


def fretting_on_grid(amplitude: float = 1e-3) -> me.Paths:
    """In vertically from the surface, two tangential cycles of ``±amplitude`` and out: every corner at a whole number
    of :data:`STEP_TRAVEL` from the first contact, so that the discrete model's samples hit them (a play operator's
    corner missed by a step's travel ``δ`` moves ``F_x`` by ``O(δ/c)``, far above the springs' ``O(Δx)`` where
    Coulomb's caps ``c`` are small)."""
    d_max, speed = me.Parameters.paper().d_max, me.Parameters.paper().v
    x = [0.0, 0.0, amplitude, -amplitude, amplitude, 0.0, 0.0]
    d = [0.0, d_max, d_max, d_max, d_max, d_max, -1e-5]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), speed)})


#: The discrete model's travel per step along :func:`fretting_on_grid` (m).
STEP_TRAVEL = 1e-6
MOTIONS = {"A 20°": me.Scenario("A", alpha=[20.0]), "A 70°": me.Scenario("A", alpha=[70.0]),
           "B 20°": me.Scenario("B", alpha=[20.0]), "B 70°": me.Scenario("B", alpha=[70.0]), "fretting": fretting()}


def with_law(contact: me.Contact, law: str) -> me.Contact:
    return dataclasses.replace(contact, friction=LAWS[law])


def paths_of(contact: me.Contact, motion):
    params = contact.parameters(me.Parameters.paper().d_max, me.Parameters.paper().v)
    return params, motion.cases(params, None, contact.friction).paths


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("motion", MOTIONS.values(), ids=MOTIONS.keys())
def test_every_spring_on_its_own_is_the_spans_on_the_half_space(law, motion):
    """On the half-space the springs share one level and the spans run Coulomb's part: the per-spring route, which
    does not use that, gives their ``F_x`` at every sample (a third route, before it is trusted on a layer)."""
    contact = with_law(HERTZ, law)
    spans = me.simulate(contact, motion, "continuum", samples=41)
    params, paths = paths_of(contact, motion)
    for case, path in enumerate(paths):
        play = PlaySprings(spring_line(params, None, contact.friction), path)
        expected = spans["tangential_force"].values[case]
        inside = np.isfinite(expected)
        got = play.tangential_force(spans["time"].values[inside] + path.first_contact_time())
        scale = np.max(np.abs(expected[inside]))
        assert np.max(np.abs(got - expected[inside])) <= ROUTE_SHARE * scale


#: The springs' events the per-spring route logs (the others are the spans' normal run's).
SPRING_EVENTS = ("slip_onset", "full_slip", "re_stick")


def spring_log(run, case: int = 0) -> list[tuple[str, float, int]]:
    kinds, times, directions = (run[name].values[case] for name in ("event_kind", "event_time", "event_direction"))
    return [(str(kind), float(time), int(direction)) for kind, time, direction in zip(kinds, times, directions)
            if kind in SPRING_EVENTS]


@pytest.mark.parametrize("motion, law", [  # (A and B 0.6 s of CPU each, each law once quick; fretting about 6 s)
    *grid({"motion": {name: MOTIONS[name] for name in ("A 20°", "B 20°")}, "law": {law: law for law in LAWS}},
          {("A 20°", "coulomb"), ("B 20°", "tau0+coulomb")}),
    *(pytest.param(MOTIONS["fretting"], law, id=f"fretting-{law}", marks=pytest.mark.slow) for law in LAWS)])
def test_a_thick_layer_is_the_half_space(law, motion):
    """``simulate`` on a layer of ``h = 1e9 m`` (the per-spring route with the tables' springs) is the half-space's
    spans: ``F_x`` at every sample, and the springs' event log (slip onset, full slip, re-stick at each reversal:
    kind, time and cap)."""
    thick = me.simulate(with_law(HERTZ.replace(h=1e9), law), motion, "continuum", samples=41)
    half = me.simulate(with_law(HERTZ, law), motion, "continuum", t=thick["time"].values)
    force, expected = thick["tangential_force"].values, half["tangential_force"].values
    assert np.array_equal(np.isnan(force), np.isnan(expected))
    scale = np.nanmax(np.abs(expected))
    assert np.nanmax(np.abs(force - expected)) <= LIMIT_SHARE * scale
    mine, theirs = spring_log(thick), spring_log(half)
    assert [(kind, direction) for kind, _, direction in mine] == [(kind, direction) for kind, _, direction in theirs]
    assert mine, "no spring slid: the path does not test the log"
    duration = float(thick["time"].values[-1])
    assert np.allclose([time for _, time, _ in mine], [time for _, time, _ in theirs], rtol=0.0,
                       atol=EVENT_SHARE * duration)


@pytest.mark.parametrize("law", LAWS)
def test_full_slip_is_tau0_area_and_mu_normal_force(law):
    """Scenario B at 20° slides the whole contact of the paper's 5 mm layer: there ``F_x = τ0 π a² + μ F_N``."""
    contact = with_law(HERTZ.replace(h=5e-3), law)
    run = me.simulate(contact, me.Scenario("B", alpha=[20.0]), "continuum", samples=41).isel(alpha=0)
    full = run["sliding_fraction"].values == 1.0
    assert np.count_nonzero(full) >= 3
    tau0 = contact.friction.tau0 if contact.friction.uses_tau0 else 0.0
    radius, normal = run["contact_radius"].values[full], run["normal_force"].values[full]
    expected = tau0 * np.pi * radius**2 + MU * normal
    assert np.allclose(np.abs(run["tangential_force"].values[full]), expected, rtol=FULL_SLIP_SHARE, atol=0.0)
    assert "full_slip" in run["event_kind"].values


#: The springs per hold radius of the fretting path's convergence study: about the spacings of :data:`SPACINGS`.
SPRINGS_PER_RADIUS = (96, 192, 384)
#: The hold radius's phase on the fretting path's grids, in spacings: the discrete model's springs sit at
#: ``(j + 1/2) Δx`` and its radius is ``Δx`` times the springs in contact, so at ``Δx = a/(N + GRID_PHASE)`` its radius
#: through the strokes is ``N Δx = a − GRID_PHASE Δx`` at every spacing: ``O(Δx)`` with one constant. (At the nested
#: SPACINGS the hold radius 3.84588e-3 m lies 5.9, 5.9 and −4.1 um from the grid's: τ0's part of full slip, ``τ0 π a²``,
#: followed that phase, not ``Δx``, errors 2.53e-3, 2.54e-3, 1.77e-3 of the largest force.) A quarter: off both the
#: grid's points and its mid-points, where a spring's centre would lie on the edge.
GRID_PHASE = 0.25


def phased_spacings(contact: me.Contact, motion) -> tuple[float, ...]:
    """The spacings (m) at which the continuum's radius held at ``d_max`` lies :data:`GRID_PHASE` of a spacing
    beyond the discrete model's grid radius, :data:`SPRINGS_PER_RADIUS` springs in it."""
    radius = float(np.nanmax(me.simulate(contact, motion, "continuum", samples=41)["contact_radius"].values))
    return tuple(radius / (springs + GRID_PHASE) for springs in SPRINGS_PER_RADIUS)


@pytest.mark.slow  # (three discrete runs on the layer, stepped spring by spring, and the continuum at their samples)
@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("motion, works", [(MOTIONS["A 20°"], (0.0, 0.0)), (fretting_on_grid(), (0.0, 0.0))],
                         ids=["A 20°", "fretting"])
def test_the_discrete_model_on_a_layer_converges_to_it(law, motion, works):
    """The discrete model on the 5 mm layer (its ``k(x_j)``, ``k_t(x_j)``, Coulomb's ratios ``μ k/k_t``) converges
    to the per-spring continuum at first order in ``Δx`` (Coulomb's law alone: between first and second order, its
    edge springs holding no force) along scenario A (its radius ramps: the grid's phase varies along it) and a
    fretting path (its radius held at ``d_max``: spacings of one grid phase, :func:`phased_spacings`)."""
    contact = with_law(HERTZ.replace(h=5e-3, dgamma0=works[0], dgamma1=works[1]), law)
    spacings = SPACINGS if isinstance(motion, me.Scenario) else phased_spacings(contact, motion)
    errors = []
    for dx in spacings:
        steps = {} if isinstance(motion, me.Scenario) else {"dt": STEP_TRAVEL / me.Parameters.paper().v}
        springs = me.simulate(contact, motion, "discrete", dx=dx, **steps).isel({motion_dim(motion): 0})
        times = springs["time"].values[::max(1, springs["time"].size // 40)]
        exact = me.simulate(contact, motion, "continuum", t=times).isel({motion_dim(motion): 0})
        approx = springs["tangential_force"].sel(time=times).values
        expected = exact["tangential_force"].values
        inside = np.isfinite(approx) & np.isfinite(expected)
        errors.append(np.max(np.abs(approx[inside] - expected[inside])) / np.max(np.abs(expected[inside])))
    orders = observed_orders(np.array(spacings), np.array(errors))
    low, high = COULOMB_ORDER_RANGE if law == "coulomb" else ORDER_RANGE
    assert np.all((low < orders) & (orders < high)), (errors, orders)


def fretting_with_re_contact(amplitude: float = 5e-4) -> me.Paths:
    """In vertically from the surface, a tangential stroke to ``+amplitude`` and back to ``−amplitude``, out beyond the
    jump-off (pull-off), in again, a stroke to ``+amplitude``, back to the centre and out: every corner at a whole
    number of the coarsest run's step travel (:data:`STEP_SHARE` × 4e-5 m) from the first contact
    (:func:`fretting_on_grid`)."""
    d_max, speed = me.Parameters.paper().d_max, me.Parameters.paper().v
    x = [0.0, 0.0, amplitude, -amplitude, -amplitude, -amplitude, amplitude, 0.0, 0.0]
    d = [0.0, d_max, d_max, d_max, -PULLED_OUT, d_max, d_max, d_max, -PULLED_OUT]
    return me.Paths({"re-contact": me.Path(np.column_stack([x, d]), speed)})


#: The depth the indenter is pulled out to: beyond the 5 mm layer's jump-off at the largest work of adhesion used,
#: ``Δγ = 0.15 J/m²`` (−2.2e-5 m, ``me.jump_off``), on the steps' grid.
PULLED_OUT = 4e-5
#: The discrete model's time step per spacing (s per m of ``Δx/v``): half a spacing's travel, so that the steps' error
#: falls with the springs' (as tests/models/test_coulomb_adhesion.py: at a fixed step the steps' error, 1e-4 of the
#: largest force along A and 8e-4 along the fretting path with adhesion, hides the springs').
STEP_SHARE = 0.5
#: The sample times of two spacings agree to the rounding of their steps' sums (relative to the run's duration).
TIME_ROUND_OFF = 1e-9
#: Adhesive cases of the discrete convergence: ``Δγ0 = Δγ1`` along A, ``Δγ1 < Δγ0`` along B, ``Δγ0 < Δγ1`` along a
#: fretting path with a pull-off and a re-contact.
ADHESIVE_CONVERGENCE = {"A 20°, Dg0 = Dg1": (MOTIONS["A 20°"], (0.05, 0.05)),
                        "B 20°, Dg1 < Dg0": (MOTIONS["B 20°"], (0.15, 0.01)),
                        "re-contact, Dg0 < Dg1": (fretting_with_re_contact(), (0.01, 0.15))}


@pytest.mark.slow  # (three discrete runs on the layer and the route at 41 times: about 15-30 s of CPU each case)
@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("case", ADHESIVE_CONVERGENCE, ids=ADHESIVE_CONVERGENCE.keys())
def test_with_adhesion_the_discrete_model_on_a_layer_converges_to_it(law, case):
    """Issue 34 with adhesion: the discrete model on the 5 mm layer converges to the per-spring continuum (its radius
    the spans' frictionless run, springs in tension holding ``τ0``'s part alone) at first order in ``Δx`` (Coulomb's
    law alone between first and second order, :data:`COULOMB_ORDER_RANGE`). Compared at the coarsest run's sample
    times (each finer run steps through them) and at each run's own first step in contact (where it attaches the
    springs of the jump-in in one step: an ``O(Δt)`` error the coarse samples would see at the coarsest spacing
    alone). The largest error falls from each spacing to the next; its order is taken over the whole range (with
    adhesion the radius's quantisation at the jumps makes one step's ratio scatter, 0.7–1.4 measured, as ``F_N``'s in
    tests/models/test_coulomb_adhesion.py)."""
    motion, works = ADHESIVE_CONVERGENCE[case]
    contact = with_law(HERTZ.replace(h=5e-3, dgamma0=works[0], dgamma1=works[1]), law)
    dim, speed = motion_dim(motion), me.Parameters.paper().v
    errors, times, expected = [], None, None
    for dx in SPACINGS:
        springs = me.simulate(contact, motion, "discrete", dx=dx, dt=STEP_SHARE * dx / speed).isel({dim: 0})
        if times is None:
            times = springs["time"].values[::max(1, springs["time"].size // 40)]
            expected = me.simulate(contact, motion, "continuum", t=times).isel({dim: 0})["tangential_force"].values
        first = springs["time"].values[np.flatnonzero(springs["contact_radius"].values > 0.0)[:1]]
        at_first = me.simulate(contact, motion, "continuum", t=first).isel({dim: 0})["tangential_force"].values
        within = times <= springs["time"].values[-1]  # (a run's last step lies within its last step's length)
        when = np.concatenate([times[within], first])
        approx = springs["tangential_force"].sel(time=when, method="nearest", tolerance=TIME_ROUND_OFF * times[-1])
        exact = np.concatenate([expected[within], at_first])
        inside = np.isfinite(approx.values) & np.isfinite(exact)
        assert np.count_nonzero(inside) >= 20
        errors.append(np.max(np.abs(approx.values[inside] - exact[inside])) / np.max(np.abs(exact[inside])))
    order = observed_orders(SPACINGS[::2], np.array(errors[::2]))[0]
    low, high = COULOMB_ORDER_RANGE if law == "coulomb" else ORDER_RANGE
    assert errors[0] > errors[1] > errors[2] and low < order < high, (errors, order)


#: A slip zone opening inside the contact (with adhesion: in the tensile annulus) is found once it reaches one of the
#: route's probes (``play_samples.PROBE_POINTS``, ``a/1024`` apart): its onset late by its growth to that width, measured
#: 4e-5 of the run along scenario A at 20°; 1e-4 bounds it.
ONSET_SHARE = 1e-4
#: The sliding fractions of the thick layer and the half-space: the quadrature's (the route) against the zones'
#: lengths (the spans), each to round-off of the radius.
SLIDING_SHARE = 1e-9
#: The adhesive cases of the thick layer against the half-space (the first runs in the quick round).
THICK_ADHESIVE = {"A 20°, Dg0 < Dg1": (MOTIONS["A 20°"], (0.01, 0.15)),
                  "A 20°, Dg0 = Dg1": (MOTIONS["A 20°"], (0.05, 0.05)),
                  "B 20°, Dg1 < Dg0": (MOTIONS["B 20°"], (0.15, 0.01)),
                  "re-contact, Dg0 < Dg1": (fretting_with_re_contact(), (0.01, 0.15))}


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("case", [case if k == 0 else pytest.param(case, marks=pytest.mark.slow)  # (3-8 s each)
                                  for k, case in enumerate(THICK_ADHESIVE)], ids=THICK_ADHESIVE.keys())
def test_with_adhesion_a_thick_layer_is_the_half_space(law, case):
    """``simulate`` on a thick adhesive layer (``h = 1e9 m``: the per-spring route on the layer's tables) against the
    half-space's spans: ``F_x`` and the sliding fraction, and under both parts of the law the springs' event log
    (Coulomb's law alone slides its tensile annulus from the first contact on, where the spans log their first
    instant's events). Along the re-contact path under both parts the compressed zone reaches its lower cap on the
    way out all at once (``ρ(ξ)`` constant to 7e-13 on ``h = 1e9 m``): its springs lie on their window's edge to
    1e-16 m, their provenances differing by round-off, which the kink search must not take for kinks
    (``play_springs.EDGE_ROUND_OFF``)."""
    motion, works = THICK_ADHESIVE[case]
    contact = with_law(me.Contact.paper().replace(dgamma0=works[0], dgamma1=works[1]), law)
    thick = me.simulate(contact.replace(h=1e9), motion, "continuum", samples=21)
    half = me.simulate(contact, motion, "continuum", t=thick["time"].values)
    force, expected = thick["tangential_force"].values, half["tangential_force"].values
    assert np.array_equal(np.isnan(force), np.isnan(expected))
    assert np.nanmax(np.abs(force - expected)) <= LIMIT_SHARE * np.nanmax(np.abs(expected))
    assert np.allclose(thick["sliding_fraction"].values, half["sliding_fraction"].values, rtol=0.0,
                       atol=SLIDING_SHARE, equal_nan=True)
    if law == "coulomb":
        return
    mine, theirs = spring_log(thick), spring_log(half)
    assert mine and [(kind, direction) for kind, _, direction in mine] == [(kind, d) for kind, _, d in theirs]
    duration = float(thick["time"].values[-1])
    for (kind, time, _), (_, expected_time, _) in zip(mine, theirs):
        share = ONSET_SHARE if kind == "slip_onset" else EVENT_SHARE
        assert abs(time - expected_time) <= share * duration, (kind, time, expected_time)


#: The two runs' depths at the same times: one path, each clock's first contact found to the rounding of the path.
DEPTH_ROUND_OFF = 1e-12


@pytest.mark.parametrize("law, works", [("tau0+coulomb", (0.05, 0.05)),
                                        pytest.param("coulomb", (0.05, 0.05), marks=pytest.mark.slow),  # (4-8 s each)
                                        pytest.param("tau0+coulomb", (0.15, 0.01), marks=pytest.mark.slow),
                                        pytest.param("coulomb", (0.15, 0.01), marks=pytest.mark.slow)],
                         ids=["tau0+coulomb, Dg0 = Dg1", "coulomb, Dg0 = Dg1", "tau0+coulomb, Dg1 < Dg0",
                              "coulomb, Dg1 < Dg0"])
def test_with_adhesion_full_slip_is_tau0_area_and_mu_the_compressed_springs_force(law, works):
    """Scenario B at 20° slides the whole adhesive contact of the paper's 5 mm layer: the springs in tension
    (``d < g(ξ)``) hold ``τ0``'s cap alone, the compressed ones ``ū + μρ(d − g)``, so ``F_x = τ0 π a² + μ F_c`` with
    ``F_c = 2∫₀^{x_c} k (d − g) dξ`` the compressed springs' force: the normal force of the same layer without
    adhesion at the same depth (its radius ``x_c``; 0 where it is out of contact), not ``F_N``."""
    contact = with_law(HERTZ.replace(h=5e-3, dgamma0=works[0], dgamma1=works[1]), law)
    motion = me.Scenario("B", alpha=[20.0])
    run = me.simulate(contact, motion, "continuum", samples=21).isel(alpha=0)
    dry = me.simulate(contact.replace(dgamma0=0.0, dgamma1=0.0), motion, "continuum",
                      t=run["time"].values).isel(alpha=0)
    touching = np.isfinite(dry["indentation_depth"].values)  # (the dry contact ends before the adhesive one)
    assert np.allclose(run["indentation_depth"].values[touching], dry["indentation_depth"].values[touching], rtol=0.0,
                       atol=DEPTH_ROUND_OFF * me.Parameters.paper().d_max)
    full = run["sliding_fraction"].values == 1.0
    assert np.count_nonzero(full) >= 3
    tau0 = contact.friction.tau0 if contact.friction.uses_tau0 else 0.0
    compressed = np.nan_to_num(dry["normal_force"].values[full], nan=0.0)
    expected = tau0 * np.pi * run["contact_radius"].values[full] ** 2 + MU * compressed
    assert np.allclose(np.abs(run["tangential_force"].values[full]), expected, rtol=FULL_SLIP_SHARE, atol=0.0)
    assert np.any(run["normal_force"].values[full] < compressed)  # (the adhesive annulus pulls: F_c is not F_N)
    assert "full_slip" in run["event_kind"].values


def motion_dim(motion) -> str:
    return "alpha" if isinstance(motion, me.Scenario) else "case"


def regrowing() -> me.Paths:
    """In to ``d_max``, 3 mm sideways (the springs reach a cap), out to 0.7 ``d_max`` (the radius pinned) and in again
    obliquely to 1.6 ``d_max``: the radius starts to grow again while springs are at a cap, a kink of ``ū(a(t))``
    inside a segment where a window's extremum lies (the route missed it before: 3.5e-2 of the force)."""
    d_max, speed = me.Parameters.paper().d_max, me.Parameters.paper().v
    corners = np.array([[0.0, -1e-6], [0.0, d_max], [3e-3, d_max], [3e-3, 0.7 * d_max], [3e-3 + 3e-4, 1.6 * d_max]])
    return me.Paths({"re-growing": me.Path(corners, speed)})


ADHESIVE = {"A 20°": me.Scenario("A", alpha=[20.0]), "A 70°": me.Scenario("A", alpha=[70.0]),
            "B 20°": me.Scenario("B", alpha=[20.0]), "fretting": fretting(), "re-growing": regrowing()}


#: The quick round's cases of the adhesive route (0.3-0.5 s of CPU each): every motion, law and pair of works, the
#: re-growing path under both laws; the other 14 run in make test-all and CI (tests/quick_round.py).
ADHESIVE_QUICK = {("A 20°", "coulomb", "Dg0 < Dg1"), ("A 70°", "tau0+coulomb", "Dg0 = Dg1"),
                  ("B 20°", "coulomb", "Dg0 = Dg1"), ("fretting", "tau0+coulomb", "Dg0 < Dg1"),
                  ("re-growing", "coulomb", "Dg0 < Dg1"), ("re-growing", "tau0+coulomb", "Dg0 = Dg1")}


@pytest.mark.parametrize("motion, law, works", grid(
    {"motion": ADHESIVE, "law": {law: law for law in LAWS}, "works": {"Dg0 < Dg1": (0.01, 0.15),
                                                                       "Dg0 = Dg1": (0.05, 0.05)}}, ADHESIVE_QUICK))
def test_with_adhesion_every_spring_on_its_own_is_the_spans_on_the_half_space(law, motion, works):
    """With adhesion the springs beyond ``x_c`` are in tension (Coulomb's part off) and the radius follows the
    hysteresis: the per-spring route on the spans' frictionless radius (``SpanHistory``) gives the spans' ``F_x``
    (Coulomb's law alone: the compressed zone's run; both parts: the split regions)."""
    contact = with_law(me.Contact.paper().replace(dgamma0=works[0], dgamma1=works[1]), law)
    spans = me.simulate(contact, motion, "continuum", samples=41)
    params, paths = paths_of(contact, motion)
    for case, path in enumerate(paths):
        solution = solve_path(params, path, me.Tolerances(), me.Limits(), None, FRICTIONLESS, contact.adhesion)
        play = PlaySprings(spring_line(params, None, contact.friction), path, SpanHistory(solution))
        expected = spans["tangential_force"].values[case]
        inside = np.isfinite(expected)
        got = play.tangential_force(spans["time"].values[inside] + path.first_contact_time())
        scale = np.max(np.abs(expected[inside]))
        assert np.max(np.abs(got - expected[inside])) <= ADHESIVE_ROUTE_SHARE * scale


@pytest.mark.parametrize("indenter, law", grid(  # (0.6 s of CPU each: each exponent and law once in the quick round)
    {"indenter": {"n = 1.5": me.PowerLaw(0.5, 1.5), "n = 3": me.PowerLaw(2e4, 3.0)}, "law": {law: law for law in LAWS}},
    {("n = 1.5", "coulomb"), ("n = 3", "tau0+coulomb")}))
def test_a_power_law_on_a_thick_layer_is_the_half_space(law, indenter):
    """A power law's springs on a thick layer against the half-space's spans (both without adhesion), scenario A."""
    contact = dataclasses.replace(with_law(HERTZ, law), indenter=indenter)
    motion = me.Scenario("A", alpha=[30.0])
    thick = me.simulate(contact.replace(h=1e9), motion, "continuum", samples=41)
    half = me.simulate(contact, motion, "continuum", t=thick["time"].values)
    scale = np.nanmax(np.abs(half["tangential_force"].values))
    assert np.nanmax(np.abs(thick["tangential_force"].values - half["tangential_force"].values)) <= LIMIT_SHARE * scale
    assert spring_log(thick) and [kind for kind, _, _ in spring_log(thick)] == [kind for kind, _, _ in spring_log(half)]
