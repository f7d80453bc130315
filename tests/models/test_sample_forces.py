"""``evaluate``'s ``F_N`` and ``F_x`` by the spans' polynomials in one pass (``FillRoute.POLYNOMIAL``,
:mod:`mdr_events.models.continuum.sample_forces`) against the spans' own terms (``FillRoute.TERMS``, the route before):
within the rounding both routes' sums allow, derived below, on every kind of continuum run; the radii, kinematics and
sliding fractions (both branches' radii in one pass, ``sample_radii._quartic_radii``) the same bits; a linear or constant
force, and any span that is no polynomial here, the same bits too.

The bounds (``ε`` the double's epsilon):

- ``F_N = 2E* a d − 2E* a³/(3R)`` (the relation's form: ``a**3`` and four products or quotients, at most 5 roundings
  of its terms' size) against ``2E* a (d − a·a/(3R))`` (6 roundings): both within ``11 ε`` of the exact value times
  ``T_N = 2E* (a |d| + a³/(3R))``, their difference within :data:`NORMAL_FORCE_ROUNDINGS` ``ε T_N``;
- ``F_x = F₀ + G (P(s) − P(s₀))`` of a closed-form span: the terms' route sums six terms of ``P``, each of at most six
  roundings of the branch's relations, and six sums (``12 ε T``, ``T`` the sum of the terms' magnitudes before they
  cancel, :func:`_terms_size`); Horner's rule of degree 6 at most ``2·6`` roundings of ``Σ|q_i| s^i <= T``, and each
  coefficient ``q_i`` up to 4 (``16 ε T``); ``s = √a`` against the terms' ``a`` read back as ``(a/scale)·scale``
  (``1.5 ε`` relative in ``s``) moves ``P`` by at most ``Σ i |q_i| s^i · 1.5 ε <= 9 ε T``; and ``− P(s₀)``, ``× G``,
  ``+ F₀`` three roundings of ``|F₀| + |G| (|P| + |P(s₀)|)``: :data:`FORCE_ROUNDINGS` = 12 + 16 + 9 + 3.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import solution as S
from mdr_events.models.continuum import span_rows
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum.branch import Branch
from mdr_events.models.continuum.closed_form import ClosedForce
from mdr_events.models.continuum.sample_forces import (FillRoute, force_rows, normal_forces, paraboloid_on_half_space,
                                                       polynomial_forces)
from mdr_events.models.continuum.state import Regime

from bench_paths import PAPER, ZIGZAG, paper_table, reciprocating

EPS = np.finfo(float).eps
#: ``|ΔF_N| <= NORMAL_FORCE_ROUNDINGS · ε · 2E* (a |d| + a³/(3R))``: 5 roundings of one form, 6 of the other and the
#: difference's own (module docstring).
NORMAL_FORCE_ROUNDINGS = 12
#: ``|ΔF_x| <= FORCE_ROUNDINGS · ε · (|F₀| + |G| (|P(s₀)| + T))`` on a closed-form span (module docstring).
FORCE_ROUNDINGS = 12 + 16 + 9 + 3


def _contact(**changes) -> me.Contact:
    return dataclasses.replace(me.Contact.paper(), **changes)


#: label -> (params, path, solve_path's keywords): the kinds of run the task names, solved by the spans.
RUNS = {
    "A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {}),
    "B 20°, ends at pull-off": lambda: (PAPER, me.Path.scenario_B(20.0, PAPER), {}),
    "zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {}),
    "reciprocating": lambda: (PAPER, reciprocating(), {}),
    "table": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=paper_table()), {"profile": paper_table()}),
    "power law": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER, profile=me.PowerLaw(2.0e3, 3.0)),
                          {"profile": me.PowerLaw(2.0e3, 3.0)}),
    "layer": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {"layer": me.Layer(5e-3)}),
    "Coulomb": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER),
                        {"friction": me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.3)}),
    "Coulomb with adhesion": lambda: (PAPER, me.Path.scenario_B(20.0, PAPER),
                                      {"friction": me.FrictionLaw("coulomb", mu=0.3)}),
    "Hertz (no adhesion)": lambda: (PAPER.replace(dgamma0=0.0, dgamma1=0.0), me.Path.scenario_B(30.0, PAPER), {}),
}


def _both(solution, times, monkeypatch):
    """``evaluate`` by the polynomials and by the terms."""
    found = S.evaluate(solution, times)
    with monkeypatch.context() as patched:
        patched.setattr(S, "FILL_ROUTE", FillRoute.TERMS)
        reference = S.evaluate(solution, times)
    return found, reference


def _branch_k(branch) -> float:
    return math.sqrt(2.0 * math.pi * branch.work / branch.params.E_star)


def _terms_size(force: ClosedForce, a: np.ndarray) -> np.ndarray:
    """``T``: the magnitudes of the primitive's terms before they cancel, ``|A₀| a + |A₁| a²/2 + |B₀| |d| + |B₁| (a |d|
    + |∫d|) + |C| |∫d| + |C₀| |∫d₀|`` with each relation's terms bounded apart (``|d| <= a²/R + k√a``, ``|∫d| <= a³/(3R)
    + 2k a^{3/2}/3``)."""
    p = force.primitive
    R, k = p.branch.params.R, _branch_k(p.branch)
    k0 = _branch_k(p.attach) if p.C0 else 0.0
    depth = a**2 / R + k * np.sqrt(a)
    integral, integral0 = (a**3 / (3 * R) + 2 * kk * a**1.5 / 3 for kk in (k, k0))
    return (abs(p.A0) * a + abs(p.A1) * a**2 / 2 + abs(p.B0) * depth + abs(p.B1) * (a * depth + integral)
            + abs(p.C) * integral + abs(p.C0) * integral0)


def _force_bounds(solution, times, radius: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per sample: the bound of ``|ΔF_x|`` on a closed-form span on the paraboloid's branches (module docstring), and
    whether the sample is on such a span (elsewhere the routes give the same bits)."""
    owner = solution.span_index(times)
    inside = (times >= 0) & (times <= solution.end_time)
    bound, polynomial = np.zeros(times.shape), np.zeros(times.shape, dtype=bool)
    spans = solution.spans
    rows = force_rows([span for span in spans])
    for index, (span, row) in enumerate(zip(spans, rows)):
        mine = inside & (owner == index)
        if row is None or not row[0] or span.regime is Regime.NONE or not mine.any():
            continue
        force, a = span.interpolant, radius[mine]
        bound[mine] = FORCE_ROUNDINGS * EPS * (abs(force.force) + abs(force.G2) * (abs(force.origin)
                                                                                  + _terms_size(force, a)))
        polynomial[mine] = True
    return bound, polynomial


@pytest.mark.parametrize("grid", ["2001 samples", "one sample", "the last instant"])
@pytest.mark.parametrize("label", list(RUNS))
def test_the_polynomials_route_is_the_terms_route_to_rounding(label, grid, monkeypatch):
    """At a run's 2001 samples (and past its end), at one sample inside and at the run's last instant (the pull-off
    where the run ends at it): ``F_N`` and ``F_x`` within the derived bounds, every other quantity, and the forces of
    the spans that are no closed form on the paraboloid, the same bits."""
    params, path, options = RUNS[label]()
    solution = solve_path(params, path, **options)
    times = {"2001 samples": np.linspace(0.0, solution.end_time * (1.0 + 1.0 / 2000), 2001),
             "one sample": np.array([0.37 * solution.end_time]),
             "the last instant": np.array([solution.end_time])}[grid]
    found, reference = _both(solution, times, monkeypatch)
    for name in ("indentation_depth", "tangential_displacement", "contact_radius", "sliding_fraction"):
        assert found[name].tobytes() == reference[name].tobytes(), name
    a, d = reference["contact_radius"], reference["indentation_depth"]
    if paraboloid_on_half_space(solution.model) and solution.compressed is None:
        size = 2.0 * params.E_star * (a * np.abs(d) + a**3 / (3.0 * params.R))
        np.testing.assert_array_less(np.abs(found["normal_force"] - reference["normal_force"]),
                                     NORMAL_FORCE_ROUNDINGS * EPS * size + np.finfo(float).tiny)
    else:
        assert found["normal_force"].tobytes() == reference["normal_force"].tobytes()
    bound, polynomial = _force_bounds(solution, times, a)
    if solution.compressed is not None:  # (the compressed zone's run gives F_x: its own evaluate, by either route)
        polynomial[:] = False
        bound, _ = _force_bounds(solution.compressed, times, S.evaluate(solution.compressed, times)["contact_radius"])
        polynomial = bound > 0
    difference = np.abs(found["tangential_force"] - reference["tangential_force"])
    assert np.all(difference[polynomial] <= bound[polynomial]), np.max(difference[polynomial] / bound[polynomial])
    assert found["tangential_force"][~polynomial].tobytes() == reference["tangential_force"][~polynomial].tobytes()


@pytest.mark.parametrize("label", ["A 20°", "B 20°, ends at pull-off", "zigzag"])
def test_the_paraboloids_closed_spans_take_the_polynomials(label):
    """The route is taken (a comparison of a route with itself would pass anyway): the paraboloid's runs have
    closed-form spans with a row in ``√a``, and the rows reproduce ``ClosedForce`` at its own radii to rounding."""
    params, path, options = RUNS[label]()
    solution = solve_path(params, path, **options)
    rows = force_rows(solution.spans)
    closed = [(span, row) for span, row in zip(solution.spans, rows) if row is not None and row[0]]
    assert closed
    for span, row in closed:
        force = span.interpolant
        branch = span_branch = solution.model.grow if span.regime is Regime.GROWING else solution.model.shrink
        assert type(span_branch) is Branch
        low = max(branch.jump_off_radius, 1e-6) if span.regime is not Regime.PINNED else span.pinned_radius
        a = np.linspace(low, 3e-3, 9)
        found = polynomial_forces([row], np.zeros(9), a, [9])
        expected = force(a / force.scale)[0]
        bound = FORCE_ROUNDINGS * EPS * (abs(force.force) + abs(force.G2) * (abs(force.origin)
                                                                             + _terms_size(force, a)))
        assert np.all(np.abs(found - expected) <= bound)


def test_a_linear_and_a_constant_force_are_their_own_bits():
    """A pinned span's ``F₀ + rate (t − t₀)`` and a constant force (a zero's sign too) are the same bits through the
    rows as through their own calls."""
    from mdr_events.models.continuum.span import LinearForce

    t = np.linspace(300.0, 478.5, 257)
    linear = LinearForce(300.0, 478.5, -1.234e-3, 3.3e-6)
    span = type("Span", (), {"interpolant": linear, "grading": None, "force": 0.0})()
    constant = type("Span", (), {"interpolant": None, "grading": None, "force": -0.0})()
    found = polynomial_forces(force_rows([span, constant]), np.concatenate([t, t]),
                                              np.full(2 * t.size, 1e-3), [t.size, t.size])
    assert found[:t.size].tobytes() == linear(t)[0].tobytes()
    assert found[t.size:].tobytes() == np.full(t.size, -0.0).tobytes()


def test_the_paraboloids_normal_force_is_the_relations_to_rounding():
    """``normal_forces`` against the model's ``F_N`` (10), over depths in tension and compression and radii up to
    ``d_max``'s, within the derived bound."""
    from mdr_events.theory import analytic

    d, a = np.meshgrid(np.linspace(-2e-4, PAPER.d_max, 41), np.linspace(0.0, 4e-3, 41))
    found, expected = normal_forces(PAPER, d, a), analytic.normal_force(d, a, PAPER)
    size = 2.0 * PAPER.E_star * (a * np.abs(d) + a**3 / (3.0 * PAPER.R))
    assert np.all(np.abs(found - expected) <= NORMAL_FORCE_ROUNDINGS * EPS * size)


def _rate_contact() -> me.Contact:
    return _contact(adhesion=me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6))


@pytest.mark.parametrize("label", ["rate law", "B 20°"])
def test_simulate_by_either_route_agrees(label, monkeypatch):
    """``simulate``'s dataset by either route: the same variables and attributes; every value the same bits but the
    forces, within the bounds per sample derived above (the rate law's own run reads no span: all its bits the same),
    and the means, each its force over the same area."""
    contact = _rate_contact() if label == "rate law" else _contact()
    motion = me.Scenario("B", 30.0 if label == "rate law" else 20.0)
    found = me.simulate(contact, motion, "continuum", samples=401)
    with monkeypatch.context() as patched:
        patched.setattr(S, "FILL_ROUTE", FillRoute.TERMS)
        reference = me.simulate(contact, motion, "continuum", samples=401)
    assert list(found.variables) == list(reference.variables) and found.attrs == reference.attrs
    bounds = {}
    if label != "rate law":
        solution = solve_path(PAPER, me.Path.scenario_B(20.0, PAPER))
        times, a = reference["time"].values, reference["contact_radius"].values[0]
        d = reference["indentation_depth"].values[0]
        bounds["tangential_force"] = _force_bounds(solution, times, a)[0]
        bounds["normal_force"] = NORMAL_FORCE_ROUNDINGS * EPS * 2.0 * PAPER.E_star * (a * np.abs(d)
                                                                                      + a**3 / (3.0 * PAPER.R))
    for name, variable in found.variables.items():
        assert variable.attrs == reference[name].attrs, name
        if name in bounds:
            difference = np.abs(variable.values[0] - reference[name].values[0])
            assert np.all((difference <= bounds[name]) | np.isnan(difference)), name
            assert np.array_equal(np.isnan(variable.values), np.isnan(reference[name].values)), name
        elif name in ("mean_pressure", "mean_shear_stress"):
            force = found["normal_force" if name == "mean_pressure" else "tangential_force"].values
            area = found["contact_area"].values
            with np.errstate(invalid="ignore", divide="ignore"):
                np.testing.assert_array_equal(variable.values, np.where(area > 0, force / area, np.nan))
        else:
            assert np.asarray(variable.values).tobytes() == np.asarray(reference[name].values).tobytes(), name


def _span_rows_of_index(solution, times):
    """The rows of each span as ``evaluate`` found them before: ``span_index`` of every time, then ``_span_rows``."""
    before = times < 0.0
    inside = (times <= solution.end_time) & ~before
    return span_rows._span_rows(solution.span_index(times), inside, len(solution.spans))


@pytest.mark.parametrize("label", ["zigzag", "B 20°, ends at pull-off", "from above the surface"])
def test_the_sorted_times_rows_are_the_span_index_rows(label):
    """``_sorted_span_rows`` (one ``searchsorted`` of the spans' ends) against ``span_index`` and ``_span_rows``: the
    same slices on a run's samples, on grids through every span's end exactly (a contact made at an approach's end
    belongs to the span after it), with repeated times, before the first contact and past the run, and on one
    sample; times out of order are left to ``_span_rows``."""
    if label == "from above the surface":
        solution = solve_path(PAPER, me.Path([(0.0, -1e-4), (1e-4, 2e-4), (2e-4, -1e-4), (3e-4, 1e-4),
                                              (4e-4, -1e-4)], PAPER.v))
        assert any(span.regime is Regime.NONE for span in solution.spans[1:])  # (a contact made again)
    else:
        solution = solve_path(*RUNS[label]()[:2], **RUNS[label]()[2])
    ends = np.array([span.t_end for span in solution.spans]) - solution.t_contact
    grids = [np.linspace(0.0, solution.end_time, 2001), np.sort(np.concatenate([ends, ends, np.linspace(
        -solution.t_contact, 1.2 * solution.end_time, 97)])), np.array([solution.end_time]), np.array([0.0]),
        np.array([-1.0]), np.array([solution.end_time * 2])]
    for times in grids:
        assert span_rows._sorted_span_rows(solution, times) == _span_rows_of_index(solution, times)
    assert span_rows._sorted_span_rows(solution, grids[0][::-1].copy()) is None
