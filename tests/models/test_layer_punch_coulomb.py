"""Coulomb's part with the flat punch on a layer in the continuum (issue 34): the per-spring route
(``mdr_events.models.continuum.play_springs``) on the punch's springs, ``g = 0`` under the face (``+inf`` beyond it)
with the tables' ``k`` and ``k_t`` (``layer_normals.PunchNormal.spring_factors``), its radius the face's, or with
adhesion the spans' receding branch (``LayerPunchBranch``).

Checked against:

- the half-space's flat punch under the same law, whose spans run Coulomb's part (one shared level), at ``h = 1e9 m``:
  the tables differ from the half-space by ``O(a/h)`` (``2e-12`` at ``a₀ = 2 mm``) and the route's quadrature sums
  Gauss–Legendre panels between located kinks against the spans' DOP853 at ``rtol``: :data:`LIMIT_SHARE` as
  ``tests/models/test_layer_coulomb.py`` (measured at most 2.3e-12);
- full slip, the closed form of the springs at their caps: in compression ``Σ k_t(ū + μ(k/k_t) d) = K_t ū + μ K d =
  τ0 π a₀² + μ F_N``, in tension (Coulomb's part off) ``τ0 π a²`` at the receding radius; both by the route's
  quadrature of the tables' splines: :data:`FULL_SLIP_SHARE`;
- the discrete model on a thin layer where the contact recedes: its radius is a whole number of spacings, so it
  converges at first order in ``Δx`` (:func:`receding_path`).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.theory.layer import hess_elongation

#: The face's radius (m), the depth pressed (m) and the tangential stroke (m: beyond the face's cap
#: ``ū(a₀) = π a₀² τ0/K_t(a₀)``, 0.46 mm on the half-space, so the springs slide).
A0, D_MAX, STROKE = 2e-3, 2e-5, 1e-3
MU, TAU0 = 0.3, 42000.0
LAWS = {"coulomb": me.FrictionLaw("coulomb", mu=MU), "tau0+coulomb": me.FrictionLaw("tau0+coulomb", mu=MU, tau0=TAU0)}
PUNCH = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(A0))
SPEED = me.Parameters.paper().v
#: The thick layer against the half-space, relative to the largest force (tests/models/test_layer_coulomb.py's).
LIMIT_SHARE = 1e-8
#: The sliding fractions of the two: the quadrature's against the zones' lengths, each to round-off of the radius.
SLIDING_SHARE = 1e-9
#: Full slip against its closed form, relative: the route's quadrature of the tables' splines (as
#: tests/models/test_layer_coulomb.py's ``FULL_SLIP_SHARE``).
FULL_SLIP_SHARE = 1e-8
#: The events' times of the two, relative to the run's duration: 100 ``rtol`` (the spans' roots at ``rtol``, the
#: route's bisections to ``2^-48`` of the output spacing).
EVENT_SHARE = 100.0 * me.Tolerances().rtol
#: The observed order in ``Δx`` where the radius recedes (first: a spring lets go at its own centre's limit, the
#: radius a whole number of spacings, :data:`GRID_PHASE` of one off) and its slack (measured 0.988 and 0.998).
ORDER, ORDER_SLACK = 1.0, 0.1
#: The thin layer of the convergence (``h/a₀ = 0.1``, ``ν = 0.5`` bonded: the contact recedes from the face to
#: ``a/h ≈ 0.46``) and its work of adhesion (J/m²).
THIN, WORK = 0.1 * A0, 0.05
#: Springs under the face at the coarsest spacing, and the spacings' ratio: ``a₀`` a whole number of each spacing (the
#: held face exact) and the receding radius ``(k + GRID_PHASE) Δx₀`` of the coarsest keeps its phase at every
#: spacing (``5 GRID_PHASE ≡ GRID_PHASE`` modulo 1), so the radius's error is ``GRID_PHASE Δx`` with one constant.
FACE_SPRINGS, REFINE, GRID_PHASE = 20, 5, 0.25
#: The receding radius of the path, in coarsest spacings (``4.25 Δx₀ = 0.425 mm``, ``a/h = 2.1``: inside the recession).
RECEDED_SPRINGS = 4
#: The discrete model's time step (s): corners at whole steps where they can be, the same at every spacing.
STEP = 0.25


def punch(law: str, h: float = 1e9, work: float = 0.0) -> me.Contact:
    return dataclasses.replace(PUNCH, friction=LAWS[law]).replace(h=h, dgamma0=work, dgamma1=work)


def fretting(back: float = -1e-5) -> me.Paths:
    """In vertically to :data:`D_MAX`, two strokes of ``±STROKE`` there, and out to ``back``."""
    x = [0.0, 0.0, STROKE, -STROKE, STROKE, 0.0]
    d = [0.0, D_MAX, D_MAX, D_MAX, D_MAX, back]
    return me.Paths({"fretting": me.Path(np.column_stack([x, d]), SPEED)})


def receding_path(depth: float) -> me.Paths:
    """In to :data:`D_MAX`, a stroke to ``+STROKE`` (the compressed face slides), out to ``depth`` (the contact
    recedes under the face: its springs in tension hold ``τ0``'s part alone), a stroke to ``−STROKE`` there (they
    slide at the receding radius) and out beyond the pull-off."""
    x = [0.0, 0.0, STROKE, STROKE, -STROKE, -STROKE]
    d = [0.0, D_MAX, D_MAX, depth, depth, -2 * D_MAX]
    return me.Paths({"receding": me.Path(np.column_stack([x, d]), SPEED)})


MOTIONS = {"A 20°": me.Scenario("A", alpha=[20.0], d_max=D_MAX), "B 20°": me.Scenario("B", alpha=[20.0], d_max=D_MAX),
           "fretting": fretting()}
SPRING_EVENTS = ("slip_onset", "full_slip", "re_stick")


def spring_log(run) -> list[tuple[str, float, int]]:
    kinds, times, directions = (run[name].values[0] for name in ("event_kind", "event_time", "event_direction"))
    return [(str(kind), float(time), int(direction)) for kind, time, direction in zip(kinds, times, directions)
            if kind in SPRING_EVENTS]


@pytest.mark.parametrize("motion, law", [("A 20°", "coulomb"), ("B 20°", "coulomb"), ("fretting", "coulomb"),
                                         ("fretting", "tau0+coulomb")])  # (A, B: within τ0's cap under both parts)
def test_a_thick_layers_punch_under_coulombs_part_is_the_half_spaces(law, motion):
    """``h = 1e9 m`` (the per-spring route on the punch's springs) against the half-space's flat punch (the spans):
    ``F_x`` and the sliding fraction at every sample and the springs' event log (kind, time, cap)."""
    thick = me.simulate(punch(law), MOTIONS[motion], "continuum", samples=41)
    half = me.simulate(punch(law, h=np.inf), MOTIONS[motion], "continuum", t=thick["time"].values)
    force, expected = thick["tangential_force"].values, half["tangential_force"].values
    assert np.array_equal(np.isnan(force), np.isnan(expected))
    assert np.nanmax(np.abs(force - expected)) <= LIMIT_SHARE * np.nanmax(np.abs(expected))
    assert np.nanmax(np.abs(thick["sliding_fraction"].values - half["sliding_fraction"].values)) <= SLIDING_SHARE
    mine, theirs = spring_log(thick), spring_log(half)
    assert mine, "no spring slid: the path does not test the log"
    assert [(kind, direction) for kind, _, direction in mine] == [(kind, direction) for kind, _, direction in theirs]
    duration = float(thick["time"].values[-1])
    assert np.allclose([time for _, time, _ in mine], [time for _, time, _ in theirs], rtol=0.0,
                       atol=EVENT_SHARE * duration)


@pytest.mark.parametrize("work", [0.0, WORK], ids=["no adhesion", "adhesion"])
def test_with_or_without_adhesion_a_thick_layers_fretting_punch_is_the_half_spaces(work):
    """With adhesion, along the fretting path the face is held (``d >= −Δl(a₀)``): the thick layer's ``F_x`` is the
    half-space's under both parts of the law."""
    thick = me.simulate(punch("tau0+coulomb", work=work), MOTIONS["fretting"], "continuum", samples=41)
    half = me.simulate(punch("tau0+coulomb", h=np.inf, work=work), MOTIONS["fretting"], "continuum",
                       t=thick["time"].values)
    force, expected = thick["tangential_force"].values, half["tangential_force"].values
    assert np.nanmax(np.abs(force - expected)) <= LIMIT_SHARE * np.nanmax(np.abs(expected))


def receded_depth() -> float:
    """The depth at which the thin layer's contact has receded to ``(RECEDED_SPRINGS + GRID_PHASE) Δx₀``: Heß's limit
    there, ``−Δl(a)``."""
    radius = A0 * (RECEDED_SPRINGS + GRID_PHASE) / FACE_SPRINGS
    contact = punch("tau0+coulomb", THIN, WORK)
    return -float(hess_elongation(radius, WORK, contact.elastomer.E_star, contact.elastomer.nu, contact.layer))


@pytest.mark.parametrize("law", LAWS)
def test_full_slip_is_the_springs_caps_held_and_receding(law):
    """On the thin layer along :func:`receding_path`: where every spring slides, ``F_x`` is ``τ0 π a₀² + μ F_N``
    with the face compressed (``F_N >= 0``), and ``τ0 π a²`` at the receding radius: there ``d = −Δl(a) < 0``, the
    springs under the face in tension (``F_N < 0``) and Coulomb's part ``μ k max(d, 0)`` off, so under Coulomb's law
    alone ``F_x = 0``."""
    contact = punch(law, THIN, WORK)
    run = me.simulate(contact, receding_path(receded_depth()), "continuum", samples=81).isel(case=0)
    full = run["sliding_fraction"].values == 1.0
    radius, normal = run["contact_radius"].values, run["normal_force"].values
    force = np.abs(run["tangential_force"].values)
    tau0 = TAU0 if contact.friction.uses_tau0 else 0.0
    held, receding = full & (radius == A0), full & (radius < A0)
    assert np.count_nonzero(held) >= 3 and np.count_nonzero(receding) >= 3
    assert np.all(normal[held] >= 0.0) and np.all(normal[receding] < 0.0)
    assert np.allclose(force[held], tau0 * np.pi * A0**2 + MU * normal[held], rtol=FULL_SLIP_SHARE, atol=0.0)
    # Coulomb's law alone: exactly no force (every spring's cap is 0); with τ0: τ0 π a² to the quadrature's share.
    assert np.allclose(force[receding], tau0 * np.pi * radius[receding]**2, rtol=FULL_SLIP_SHARE, atol=0.0)


def test_the_discrete_model_converges_to_it_at_first_order_where_the_contact_recedes():
    """The discrete model (each spring its own Heß limit, ``k(x_j)``, ``k_t(x_j)``, Coulomb's ratios) on the thin
    layer along :func:`receding_path` converges to the per-spring continuum at first order in ``Δx``: the held face's
    springs sum by the midpoint rule (second order), the receding radius is a whole number of spacings
    (:data:`GRID_PHASE` of one off at every spacing)."""
    contact = punch("tau0+coulomb", THIN, WORK)
    motion = receding_path(receded_depth())
    spacings = tuple(A0 / (FACE_SPRINGS * REFINE**k) for k in range(3))
    errors, times, expected = [], None, None
    for dx in spacings:
        springs = me.simulate(contact, motion, "discrete", dx=dx, dt=STEP).isel(case=0)
        if times is None:
            times = springs["time"].values[::max(1, springs["time"].size // 60)]
            exact = me.simulate(contact, motion, "continuum", t=times).isel(case=0)
            expected = exact["tangential_force"].values
            assert np.any(exact["contact_radius"].values < A0)  # (the path recedes)
        approx = springs["tangential_force"].sel(time=times).values
        inside = np.isfinite(approx) & np.isfinite(expected)
        errors.append(np.max(np.abs(approx[inside] - expected[inside])) / np.max(np.abs(expected[inside])))
    orders = observed_orders(np.array(spacings), np.array(errors))
    assert np.all(np.abs(orders - ORDER) < ORDER_SLACK), (errors, orders)
