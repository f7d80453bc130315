"""The continuum where the caps jump or start at zero: a radius dropping onto the Δγ1 branch (Δγ1 < Δγ0: the caps
jump in with it and clip the springs beyond them at once) and a cone growing from a = 0 without adhesion (its
springs attach at the growing edge with no shift, never at a cap K a > 0). Against a closed form, the algebraic
force on the stored anchors (2G* ∫ clip(x − Y, −ū, ū) dξ) and the events the sliding fraction shows."""

from __future__ import annotations

import functools

import numpy as np
import pytest
import sympy as sp

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models import continuum
from mdr_events.models.continuum import EventKind
from mdr_events.models.paths import exit_depth
from mdr_events.theory import mindlin, power_law

#: The continuum against a closed form, as a share of the force (its rtol is 1e-10; the spans here have no event
#: inside), as in tests/models/test_friction_laws.py.
CONTINUUM_RTOL = 1e-9
COMBINED = FrictionLaw("tau0+coulomb", mu=0.3)
#: What a change of a slip zone logs (the table of models.continuum.state)
SLIP_KINDS = (EventKind.SLIP_ONSET, EventKind.FULL_SLIP, EventKind.RE_STICK, EventKind.FRONT_AT_CENTRE,
              EventKind.FRONT_AT_EDGE)


# --- a cone growing from first contact --------------------------------------------------------------------------
def _self_similar_force(K, kappa, slope, ratio, a):
    """F_x of a cone growing from a = 0 along a straight line (g(ξ) = slope ξ, dx/dd = ratio), derived here: a spring
    at ξ attached at the depth slope ξ carries the shift ratio · slope (a − ξ) while it sticks, its cap is
    K a + κ slope (a − ξ) (d − g(ξ) = slope (a − ξ)); the ratio of the two is largest at the centre, so the springs of
    [0, ξ*] slide (the front where they are equal: ξ* = a (1 − K/((ratio − κ) slope)), a fixed share of the contact)
    and F_x / 2G* = ∫ min(shift, cap) dξ. Returns (F_x / 2G*, the sliding share ξ*/a)."""
    A, integral, share = _self_similar_expressions(K, kappa, slope, ratio)
    return float(integral.subs(A, a)), float(share)


@functools.cache
def _self_similar_expressions(K, kappa, slope, ratio):
    """:func:`_self_similar_force`'s integral and share as expressions of the radius symbol (derived once per case,
    evaluated at each sample's radius: the same numbers as deriving them at each)."""
    xi, A = sp.symbols("xi a", positive=True)
    shift = ratio * slope * (A - xi)
    cap = K * A + kappa * slope * (A - xi)
    front = sp.solve(sp.Eq(shift, cap), xi)[0]
    integral = sp.integrate(cap, (xi, 0, front)) + sp.integrate(shift, (xi, front, A))
    share = sp.simplify(front / A)
    return A, integral, share


@pytest.mark.parametrize("friction", ["tau0", COMBINED], ids=["tau0", "tau0+coulomb"])
@pytest.mark.parametrize("slope_angle", [10.0, 25.0])
def test_a_cone_growing_from_first_contact_slides_on_a_fixed_share(friction, slope_angle):
    """A cone without adhesion entering along a straight line at a small angle: the springs of a fixed share of the
    contact, from the centre, slide from first contact on and the rest stick; F_x is the self-similar closed form
    and the sliding fraction that share at every instant; never full slip (the edge's springs have no shift).
    Before, the growth piece counted wholly at the cap at a → 0 (its values within the tolerance): F_x was half
    of full slip, 37 % low, and FULL_SLIP was logged at first contact."""
    params = me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0, tau0=2e4)
    cone = me.PowerLaw.cone(0.05)
    depth = 1e-4
    x_end = depth / np.tan(np.radians(slope_angle))
    path = me.Path(np.array([(0.0, -1e-5), (x_end * 1.1, depth)]), params.v)
    solution = continuum.solve_path(params, path, profile=cone, friction=friction)
    K, kappa = solution.model.caps.K, solution.model.caps.kappa
    slope = float(power_law.equivalent_profile(1.0, cone))  # g(ξ) = slope ξ (n = 1)
    ratio = x_end * 1.1 / (depth + 1e-5)
    times = np.linspace(0.0, solution.end_time, 41)[1:]
    out = continuum.evaluate(solution, times)
    radii = out["contact_radius"]
    expected = np.array([_self_similar_force(K, kappa, slope, ratio, a)[0] for a in radii])
    share = _self_similar_force(K, kappa, slope, ratio, 1.0)[1]
    assert 0.05 < share < 0.95  # a front inside the contact
    scale = float(np.max(np.abs(expected))) * 2 * params.G_star
    np.testing.assert_allclose(out["tangential_force"], 2 * params.G_star * expected, rtol=0,
                               atol=CONTINUUM_RTOL * scale)
    np.testing.assert_allclose(out["sliding_fraction"], share, rtol=0, atol=CONTINUUM_RTOL)
    kinds = [event.kind for event in solution.events]
    assert EventKind.SLIP_ONSET in kinds and EventKind.FULL_SLIP not in kinds


# --- a drop onto the Δγ1 branch ------------------------------------------------------------------------------
def _restick_then_drop(params, profile=None):
    """In at 10° to 0.9 d_max (the springs slide), straight in to d_max (a corner where the level turns back: every
    spring sticks again), then out backwards to 0.6 d_max (the radius drops onto the Δγ1 branch at once, the caps
    with it; the level moves away from the clipped springs: they stick at once) and out to the pull-off."""
    d_max = params.d_max
    x1 = 0.9 * d_max / np.tan(np.radians(10.0))
    points = [(0.0, 0.0), (x1, 0.9 * d_max), (x1, d_max), (x1 - 1.5 * d_max, 0.6 * d_max),
              (x1 - 1.5 * d_max, exit_depth(params, profile))]
    return me.Path(np.array(points), params.v)


@pytest.mark.parametrize("friction", ["tau0", COMBINED], ids=["tau0", "tau0+coulomb"])
@pytest.mark.parametrize("profile", [None, me.PowerLaw(2e5, 3.0)], ids=["paraboloid", "n3"])
def test_a_drop_onto_the_dgamma1_branch_clips_the_springs_at_once(profile, friction):
    """After the drop the integrated F_x is the algebraic force on the stored anchors along the whole path (before,
    the springs beyond the smaller caps kept their anchors when no cap slid at the drop: the algebraic force and the
    sliding fraction read them as at the caps, 4 % off, and the integration took the edge's shift from them), and
    the drop logs the springs' slip and their re-stick at once (the level moves away) where any is clipped."""
    params = me.Parameters.paper().replace(dgamma0=0.15, dgamma1=0.01)
    path = _restick_then_drop(params, profile)
    solution = continuum.solve_path(params, path, profile=profile, friction=friction)
    drop = path.corner_times[2] - path.first_contact_time()
    times = np.union1d(np.linspace(0.0, solution.end_time, 2001)[:-1], drop + np.array([0.0, 1e-6, 1e-3, 1.0]))
    integrated = continuum.evaluate(solution, times)["tangential_force"]
    algebraic = continuum.algebraic_tangential_force(solution, times)
    scale = float(np.nanmax(np.abs(algebraic)))
    np.testing.assert_allclose(integrated, algebraic, rtol=0, atol=CONTINUUM_RTOL * scale)
    at_drop = [event.kind for event in solution.events if event.time == drop and event.kind in SLIP_KINDS]
    # τ0 alone: the springs stuck at the corner sat at the caps of a larger radius than the one dropped onto, so some
    # are clipped; with Coulomb's part the caps grew with the depth since, by κ d_max / 10, and on n = 3 none is
    clipped = friction == "tau0" or profile is None
    assert at_drop == ([EventKind.SLIP_ONSET, EventKind.RE_STICK] if clipped else [])


@pytest.mark.parametrize("friction", ["tau0", COMBINED], ids=["tau0", "tau0+coulomb"])
@pytest.mark.parametrize("profile", [None, me.PowerLaw.cone(0.05)], ids=["paraboloid", "cone"])
def test_scenario_a_logs_full_slip_at_the_drop(profile, friction):
    """Scenario A at 5° with Δγ1 = 0 < Δγ0: at the corner the radius drops onto the Δγ1 branch and every spring left
    is beyond the smaller caps: FULL_SLIP is logged there (before: nothing, or much later) and F_x is the full-slip
    force of the smaller contact at once (τ0 π a² + μ F_N^H(d) with Coulomb's part, adhesive_full_slip_force)."""
    params = me.Parameters.paper().replace(dgamma0=0.15, dgamma1=0.0)
    path = me.Path.scenario_A(5.0, params, profile)
    solution = continuum.solve_path(params, path, profile=profile, friction=friction)
    corner = path.corner_times[1] - path.first_contact_time()
    full = [event for event in solution.events if event.kind is EventKind.FULL_SLIP]
    assert [event.time for event in full] == [corner]
    after = continuum.evaluate(solution, corner + np.array([1e-9, 1e-3]))
    radius = after["contact_radius"]
    law = friction if isinstance(friction, FrictionLaw) else FrictionLaw(friction)
    expected = [mindlin.full_slip_force(after["indentation_depth"][i], law, params, profile, radius=radius[i])
                for i in range(2)]
    np.testing.assert_allclose(after["tangential_force"], expected, rtol=1e-12)
