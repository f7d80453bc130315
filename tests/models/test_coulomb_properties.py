"""Property-based tests of Coulomb's part with adhesion and on the flat punch (hypothesis; bounded example counts),
as tests/models/test_properties.py draws the τ0 law's: parameters log-uniformly over ranges well beyond the paper's
(works of adhesion in either order or zero), μ 0.05–1, random paths (reversals, pinned slides, re-indentation, a
pull-off and a new contact).

- Coulomb's law alone with adhesion (the compressed zone): the integrated F_x is the algebraic form on the stored
  anchors, and never beyond full slip μ F_N^H(d), the compressed springs' push (free of Δγ).
- The flat punch, both laws, with or without adhesion: F_x is the play operator of the face
  (mindlin.flat_punch_force) while the first contact holds, exact at the corners and the crossings of d = 0.
- Both parts with adhesion on a curved indenter (the compressed zone and the tensile annulus split at x_c): the
  integrated F_x is the algebraic form on the maps each span read its regions from, and never beyond full slip
  τ0 π a² + μ F_N^H(d).
"""

import math

import numpy as np
from hypothesis import HealthCheck, assume, event, example, given, settings
from hypothesis import strategies as st

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models import continuum
from mdr_events.theory import mindlin

from test_properties import (ALGEBRAIC_ROUNDING, label_parameters, label_path, log_uniform, parameters, path_points,
                             work_of_adhesion)
from mdr_events.theory import power_law
from quick_round import examples

#: The integrated force against the algebraic form and the closed forms, as a share of the run's largest force: the
#: integration's rtol (1e-10) accumulated over the spans, with room for the positions' rounding (the τ0 law's
#: property test takes 1e-7 of its largest value as well)
FORCE_SHARE = 1e-7


def coefficients():
    return st.floats(0.05, 1.0)


@st.composite
def adhesive_coulomb_paths(draw):
    """A paraboloid with adhesion (both works > 0, in either order), Coulomb's law alone, a random path."""
    params = draw(parameters(adhesion=st.floats(1e-3, 0.5), friction=st.just(0.0)))
    return params, FrictionLaw("coulomb", mu=draw(coefficients())), me.Path(path_points(draw, params), params.v)


#: A path that re-sticks at a corner (the vertical stroke after sliding in), leaving pieces an ulp long at the radius
#: there, then shrinks past them: the edge dropped the last piece but kept one starting at its new radius, of no
#: springs, whose anchor the level had passed (a target met at once, for ever: "no progress after 50 event restarts",
#: reported by two helpers); models.continuum.anchors.AnchorMap.drop_edge_piece
STUCK_AT_A_CORNERS_PIECES = (me.Parameters(E=1e5, nu=0.0, R=0.1, tau0=0.0, dgamma0=0.5, dgamma1=0.5, d_max=1e-3, v=1e-6),
                             FrictionLaw("coulomb", mu=1.0),
                             me.Path(np.array([[0.0, 0.0], [-5e-5, 3.1e-5], [-5e-5, 3.2e-5], [-5.1e-5, -3.77515939e-4]]),
                                     1e-6))


@settings(max_examples=examples(20), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(adhesive_coulomb_paths())
@example(STUCK_AT_A_CORNERS_PIECES)
def test_coulomb_with_adhesion_is_its_algebraic_form_within_full_slip(case):
    params, friction, path = case
    label_parameters(params)
    label_path(path)
    solution = continuum.solve_path(params, path, friction=friction)
    times = np.linspace(0.0, solution.end_time, 301)[:-1]
    filled = continuum.evaluate(solution, times)
    algebraic = continuum.algebraic_tangential_force(solution, times)
    scale = max(float(np.max(np.abs(algebraic))), 1e-300)
    # as the τ0 law's property test: plus the algebraic form's rounding of x − Y and the velocity components the
    # integration drops (a vertical path has F_x ≡ 0 integrated, and 1e-16 N of rounding in the algebraic form)
    rounding = 2 * params.G_star * np.nanmax(filled["contact_radius"]) * (
        ALGEBRAIC_ROUNDING * np.nanmax(np.abs(filled["tangential_displacement"]))
        + continuum.NEGLIGIBLE_SHARE * path.speed * path.duration)
    # plus the integration's absolute tolerance per step of the compressed zone's run (atol 1e-14 N: a contact of a
    # few µm carries 1e-9 N, and one of 1.5e-9 N was 2.3e-15 N off, above 1e-7 of it)
    zone = solution.compressed if solution.compressed is not None else solution
    steps = sum(len(span.interpolant.ts) - 1 for span in zone.spans if span.interpolant is not None)
    tolerance = FORCE_SHARE * scale + rounding + steps * continuum.Tolerances().atol
    np.testing.assert_allclose(filled["tangential_force"], algebraic, rtol=0, atol=tolerance)
    depth = np.maximum(filled["indentation_depth"], 0.0)
    push = 4.0 / 3.0 * params.E_star * math.sqrt(params.R) * depth**1.5  # F_N^H(d) of the paraboloid
    assert np.all(np.abs(filled["tangential_force"]) <= friction.mu * push + tolerance)
    wholly = (push > 0.0) & (np.abs(filled["tangential_force"]) >= friction.mu * push * (1 - 1e-9))
    event("slides wholly" if np.any(wholly) else "never slides wholly")


@st.composite
def punch_paths(draw):
    """A flat punch of 0.5–5 mm, either law (τ0 > 0 for the combined one), adhesion or none, a random path."""
    params = draw(parameters(adhesion=work_of_adhesion(), friction=st.floats(1e3, 2e5).map(float)))
    law = draw(st.sampled_from(["coulomb", "tau0+coulomb"]))
    punch = me.FlatPunch(draw(st.floats(5e-4, 5e-3)))
    return params, FrictionLaw(law, mu=draw(coefficients())), punch, me.Path(path_points(draw, params), params.v)


def _samples(path, n=2001):
    """Times from first contact holding every corner and every crossing of d = 0."""
    corners = path.corner_times - path.first_contact_time()
    waypoints = path.waypoints
    crossings = [corners[i] + (corners[i + 1] - corners[i]) * waypoints[i, 1] / (waypoints[i, 1] - waypoints[i + 1, 1])
                 for i in range(len(waypoints) - 1) if waypoints[i, 1] * waypoints[i + 1, 1] < 0]
    times = np.union1d(np.linspace(0.0, corners[-1], n), np.concatenate([corners, crossings]))
    return times[times >= 0.0]


@settings(max_examples=examples(30), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(punch_paths())
def test_the_flat_punch_is_one_play_operator(case):
    params, friction, punch, path = case
    label_parameters(params)
    label_path(path)
    event(friction.law)
    solution = continuum.solve_path(params, path, profile=punch, friction=friction)
    times = _samples(path)
    times = times[times <= solution.end_time]
    filled = continuum.evaluate(solution, times)
    touching = filled["contact_radius"] > 0
    held = np.flatnonzero(~touching)[0] if not touching.all() else times.size  # the first contact
    event("pulled off" if held < times.size else "held to the end")
    expected = mindlin.flat_punch_force(filled["tangential_displacement"][:held], filled["indentation_depth"][:held],
                                        friction, params, punch)
    scale = max(float(np.max(np.abs(expected), initial=0.0)), 1e-300)
    np.testing.assert_allclose(filled["tangential_force"][:held], expected, rtol=0, atol=FORCE_SHARE * scale)


#: The curved indenters drawn with both parts of the cap: the paraboloid, a cone, n = 1.5 and n = 3
CURVED = (None, me.PowerLaw.cone(0.05), me.PowerLaw(50.0, 1.5), me.PowerLaw(2e5, 3.0))


@st.composite
def adhesive_combined_paths(draw):
    """Both parts of the cap (τ0 1–200 kPa, μ 0.05–1), adhesion (either work 0 or 1e-3–0.5 J/m², not both 0), a curved
    indenter (:data:`CURVED`), a random path."""
    params = draw(parameters(adhesion=work_of_adhesion(), friction=log_uniform(1e3, 2e5)))
    if params.dgamma0 == params.dgamma1 == 0.0:  # (adhesion at least on the way out)
        params = params.replace(dgamma1=draw(log_uniform(1e-3, 0.5)))
    profile = draw(st.sampled_from(CURVED))
    friction = FrictionLaw("tau0+coulomb", mu=draw(coefficients()))
    return params, friction, profile, me.Path(path_points(draw, params), params.v)


def _compressed_push(depth, params, profile):
    """F_N^H(d): the compressed springs' push, the normal force without adhesion of each depth (0 in tension)."""
    indenter = profile or me.PowerLaw.paraboloid(params.R)
    pressed = np.maximum(depth, 0.0)
    radius = np.asarray(power_law.contact_radius(pressed, indenter, params, 0.0), dtype=float)
    return np.where(pressed > 0.0, np.asarray(power_law.normal_force(pressed, radius, indenter, params)), 0.0)


@settings(max_examples=examples(30), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(adhesive_combined_paths())
def test_both_parts_with_adhesion_are_the_algebraic_form_within_full_slip(case):
    params, friction, profile, path = case
    label_parameters(params)
    label_path(path)
    event(f"profile: {profile.describe() if profile is not None else 'paraboloid'}")
    try:
        solution = continuum.solve_path(params, path, friction=friction, profile=profile)
    except ValueError as refused:  # a travel the slip criterion cannot resolve against ū: named, as for τ0 alone
        assume("travels" not in str(refused))
        raise
    times = np.linspace(0.0, solution.end_time, 301)[:-1]
    filled = continuum.evaluate(solution, times)
    algebraic = continuum.algebraic_tangential_force(solution, times)
    scale = max(float(np.max(np.abs(algebraic))), 1e-300)
    # as Coulomb's law alone's, plus the integration's absolute tolerance per step (atol, 1e-14 N: a contact of a few
    # µm carries 1e-8 N)
    steps = sum(len(span.interpolant.ts) - 1 for span in solution.spans if span.interpolant is not None)
    rounding = 2 * params.G_star * np.nanmax(filled["contact_radius"]) * (
        ALGEBRAIC_ROUNDING * np.nanmax(np.abs(filled["tangential_displacement"]))
        + continuum.NEGLIGIBLE_SHARE * path.speed * path.duration)
    tolerance = FORCE_SHARE * scale + rounding + steps * continuum.Tolerances().atol
    np.testing.assert_allclose(filled["tangential_force"], algebraic, rtol=0, atol=tolerance)
    radius = np.nan_to_num(filled["contact_radius"])
    full = params.tau0 * math.pi * radius**2 + friction.mu * _compressed_push(filled["indentation_depth"], params,
                                                                              profile)
    assert np.all(np.abs(np.nan_to_num(filled["tangential_force"])) <= full + tolerance)
    wholly = (full > 0.0) & (np.abs(filled["tangential_force"]) >= full * (1 - 1e-9))
    event("slides wholly" if np.any(wholly) else "never slides wholly")
