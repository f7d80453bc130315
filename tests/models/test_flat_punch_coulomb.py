"""Coulomb's part on the flat punch in the continuum, with and without adhesion: every spring under the face has the
cap ``K a + κ max(d, 0)`` and one anchor history, so the springs are one play operator
(``symbolic.derive_adhesive_friction_model``: ``flat_punch_friction_cap``, ``flat_punch_full_slip_force``,
``flat_punch_loop_energy``; ``mindlin.flat_punch_force``). The continuum against those closed forms and Masing's
loops to CONTINUUM_RTOL, and the discrete model equal to the continuum of its own punch (its springs' radius m Δx) to
rounding, which converges to the punch's at first order in Δx."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch
from mdr_events.models.continuum import EventKind, evaluate, solve_path, tangential_work
from mdr_events.models.continuum.work import algebraic_tangential_force
from mdr_events.theory import mindlin
from mdr_events.theory import power_law as pl
from mdr_events.theory import symbolic as S

PUNCH = FlatPunch(1.5e-3)
DEPTH = 1e-4
#: The continuum against the closed forms, as a share of full slip (its rtol is 1e-10; a pinned span is a closed form,
#: linear in time between events: what is left is the events' rounding)
CONTINUUM_RTOL = 1e-9
#: The discrete model against the continuum of a punch of its springs' radius: the same play operator stepped at the
#: path's samples, exact for linear steps (mindlin.flat_punch_force), so only rounding of a few hundred springs' sum
ROUNDING = 1e-12
LAWS = [FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.3)]
#: (Δγ0, Δγ1) in J/m²: none, equal, the paper's Δγ0 < Δγ1, and Δγ1 < Δγ0
ADHESIONS = [(0.0, 0.0), (0.05, 0.05), (0.01, 0.15), (0.15, 0.01)]
IDS = ["none", "equal", "paper", "reversed"]


def _params(dgamma0, dgamma1):
    return me.Parameters.paper().replace(dgamma0=dgamma0, dgamma1=dgamma1)


def _cap(depth, friction, params, punch=PUNCH):
    """``ū = K a + κ max(d, 0)`` of every spring under the face (``flat_punch_friction_cap``)."""
    tau0 = params.tau0 if friction.uses_tau0 else 0.0
    return float(S.relation("flat_punch_friction_cap").numeric(depth, punch.radius, tau0, friction.coulomb_mu,
                                                               params.E_star, params.G_star))


def test_the_flat_punch_relations_are_the_springs_summed():
    """The cap is K a + κ d pressed, K a in tension; full slip τ0 π a² + μ 2E* a max(d, 0) (and μ F_N of (10) pressed,
    as mindlin.full_slip_force); the parallelogram loop 8 G* a ū (X − ū) is Masing's loop of the virgin curve
    (mindlin.loop_energy, by quadrature to 1e-12)."""
    params = _params(0.01, 0.15)
    law = LAWS[1]
    K = pl.cap_per_radius(params)
    kappa = mindlin.coulomb_cap_ratio(law, params)
    assert _cap(DEPTH, law, params) == pytest.approx(K * PUNCH.radius + kappa * DEPTH, rel=1e-14)
    assert _cap(-2e-6, law, params) == pytest.approx(K * PUNCH.radius, rel=1e-14)
    assert _cap(-2e-6, LAWS[0], params) == 0.0
    full = S.relation("flat_punch_full_slip_force")
    pressed = float(full.numeric(DEPTH, PUNCH.radius, params.tau0, 0.3, params.E_star))
    assert pressed == pytest.approx(mindlin.full_slip_force(DEPTH, law, params, PUNCH), rel=1e-14)
    assert pressed == pytest.approx(params.tau0 * np.pi * PUNCH.radius**2 + 0.3 * 2 * params.E_star * PUNCH.radius
                                    * DEPTH, rel=1e-14)
    assert float(full.numeric(-2e-6, PUNCH.radius, params.tau0, 0.3, params.E_star)) == pytest.approx(
        params.tau0 * np.pi * PUNCH.radius**2, rel=1e-14)
    cap = _cap(DEPTH, law, params)
    for amplitude in (1.2 * cap, 3.0 * cap):
        energy = float(S.relation("flat_punch_loop_energy").numeric(amplitude, PUNCH.radius, cap, params.G_star))
        assert energy == pytest.approx(mindlin.loop_energy(amplitude, DEPTH, law, params, PUNCH), rel=1e-10)


def _fretting_path(params, friction, speed=1e-6):
    """In to 1.5 DEPTH, out to DEPTH, then 0 → 1.2 X → −1.2 X → 1.2 X → −0.3 X → 1.5 X along x (X the cap at
    DEPTH rounded to 10 µm, so 1.2 X > ū: full slip, a closed loop, a reversal within the stick range), out along a
    3-4-5 slant to −4 µm (an adhesive punch held in tension, above every jump-off here, the shallowest −14.8 µm; else
    off), sideways by 20 µm there, in vertically to 10 µm (the re-contact of a punch without adhesion falls on a
    sample, where the discrete model's springs attach one step late: vertically they attach where the continuum's do)
    and along a 3-4-5 slant to 122 µm. Every corner and every crossing of d = 0 lie a whole number of seconds after
    first contact."""
    X = round(_cap(DEPTH, friction, params) / 10e-6) * 10e-6
    turns = np.array([0.0, 1.2, -1.2, 1.2, -0.3, 1.5]) * X
    points = [(0.0, -1e-6), (0.0, 1.5 * DEPTH)] + [(x, DEPTH) for x in turns]
    points += [(1.5 * X + 78e-6, -4e-6), (1.5 * X + 98e-6, -4e-6), (1.5 * X + 98e-6, 10e-6), (1.5 * X + 14e-6, 122e-6)]
    return me.Path(np.array(points), speed=speed), X


def _sample_times(path, n=4001):
    """Times from first contact holding every corner and every crossing of d = 0 (the closed form's steps are exact
    between them)."""
    corners = path.corner_times - path.first_contact_time()
    times = np.linspace(0.0, corners[-1], n)
    crossings = []
    waypoints = path.waypoints
    for i in range(len(waypoints) - 1):
        d0, d1 = waypoints[i, 1], waypoints[i + 1, 1]
        if d0 * d1 < 0:
            crossings.append(corners[i] + (corners[i + 1] - corners[i]) * d0 / (d0 - d1))
    return np.union1d(times, np.concatenate([corners[1:], crossings]))


@pytest.mark.parametrize("friction", LAWS, ids=lambda f: f.law)
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_the_continuum_is_the_play_operator_of_the_face(adhesion, friction):
    """F_x along the fretting path is mindlin.flat_punch_force (the play operator of ū = K a + κ max(d, 0), exact at
    the corners and the crossings of d = 0) while in contact, and Masing's loops of mindlin.tangential_force at the
    constant depth; full slip is flat_punch_full_slip_force exactly; the work of the closed loop −1.2 X → 1.2 X →
    −1.2 X is flat_punch_loop_energy (a parallelogram: it dissipates); the algebraic force on the stored anchors
    agrees."""
    params = _params(*adhesion)
    path, X = _fretting_path(params, friction)
    solution = solve_path(params, path, profile=PUNCH, friction=friction)
    times = _sample_times(path)
    out = evaluate(solution, times)
    full = mindlin.full_slip_force(DEPTH, friction, params, PUNCH)
    touching = out["contact_radius"] > 0
    first_off = np.flatnonzero(~touching)[0] if not touching.all() else times.size
    held = slice(0, first_off)  # the first contact (until the punch comes off, if it does)
    expected = mindlin.flat_punch_force(out["tangential_displacement"][held], out["indentation_depth"][held], friction,
                                        params, PUNCH)
    np.testing.assert_allclose(out["tangential_force"][held], expected, rtol=0, atol=CONTINUUM_RTOL * full)
    corners = path.corner_times - path.first_contact_time()
    level = (times >= corners[2]) & (times <= corners[7])
    masing = mindlin.tangential_force(out["tangential_displacement"][level], DEPTH, friction, params, PUNCH)
    np.testing.assert_allclose(out["tangential_force"][level], masing, rtol=0, atol=CONTINUUM_RTOL * full)
    at_full = out["tangential_force"][np.searchsorted(times, corners[7])]
    assert at_full == pytest.approx(full, rel=1e-12)
    work = tangential_work(solution, corners[3], corners[5])
    loop = float(S.relation("flat_punch_loop_energy").numeric(1.2 * X, PUNCH.radius, _cap(DEPTH, friction, params),
                                                              params.G_star))
    assert loop > 0.0 and work == pytest.approx(loop, rel=1e-8)
    np.testing.assert_allclose(algebraic_tangential_force(solution, times)[touching], out["tangential_force"][touching],
                               rtol=0, atol=CONTINUUM_RTOL * full)
    kinds = [event.kind for event in solution.events]
    assert kinds.count(EventKind.FULL_SLIP) >= 3 and kinds.count(EventKind.RE_STICK) >= 3
    onsets = [event.time for event in solution.events if event.kind is EventKind.SLIP_ONSET]
    assert onsets == [event.time for event in solution.events if event.kind is EventKind.FULL_SLIP]  # all at once


@pytest.mark.parametrize("adhesion", ADHESIONS[1:], ids=IDS[1:])
def test_in_tension_the_punch_keeps_tau0s_part_alone(adhesion):
    """Held above the surface (d = −4 µm) and moved sideways by 20 µm: "tau0+coulomb" slides at τ0 π a² (its cap K a,
    below the 20 µm), "coulomb" alone holds nothing (every spring slides with zero shift)."""
    params = _params(*adhesion)
    for friction, expected in zip(LAWS, (0.0, params.tau0 * np.pi * PUNCH.radius**2)):
        path, _ = _fretting_path(params, friction)
        corners = path.corner_times - path.first_contact_time()
        out = evaluate(solve_path(params, path, profile=PUNCH, friction=friction), corners[9:10])
        assert out["indentation_depth"][0] == pytest.approx(-4e-6, rel=1e-12) and out["contact_radius"][0] > 0
        assert abs(out["tangential_force"][0]) == pytest.approx(expected, rel=1e-12, abs=1e-15)


def _discrete_and_own_punch(params, cases, dx, friction, speed, share=0.5, **options):
    """The discrete run at ``dx`` and the continuum of the punch of its springs' radius, at its times."""
    discrete = me.simulate(params, cases, dx=dx, dt=share * dx / speed, profile=PUNCH, friction=friction, **options)
    own = FlatPunch(float(np.nanmax(discrete["contact_radius"].values)))
    exact = me.simulate(params, cases, method="continuum", t=discrete["time"].values, profile=own, friction=friction,
                        **options)
    return discrete, exact, own


@pytest.mark.parametrize("friction", LAWS, ids=lambda f: f.law)
@pytest.mark.parametrize("adhesion", ADHESIONS, ids=IDS)
def test_the_discrete_model_is_the_continuum_of_its_own_punch(adhesion, friction):
    """Scenarios A and B at 15°, 30° and 60° and the fretting path with re-contact: the springs at Δx = 8 µm cover
    188 Δx = 1.504 mm of the punch, and their F_x, F_N and A are the continuum's for that punch to ROUNDING; at 4 µm
    they tile the face and are the continuum's of the punch itself: the error is the radius's, first order in Δx."""
    params = _params(*adhesion)
    path, _ = _fretting_path(params, friction)
    runs = [(scenario, {"alpha": [15.0, 30.0, 60.0]}, params.v, 0.5) for scenario in ("A", "B")]
    runs.append((path, {}, 1e-6, 0.125))  # dt = 1 s, 0.5 s: the corners and the crossings of d = 0 on the grid
    for cases, options, speed, share in runs:
        for dx, radius in ((8e-6, 188 * 8e-6), (4e-6, PUNCH.radius)):
            discrete, exact, own = _discrete_and_own_punch(params, cases, dx, friction, speed, share, **options)
            assert own.radius == pytest.approx(radius, rel=1e-15)
            for name, values in history_differences(discrete, exact).items():
                if name != "samples_left_out":
                    assert np.all(values < ROUNDING), (dx, name, values)
