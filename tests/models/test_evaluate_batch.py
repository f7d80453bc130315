"""``evaluate``'s fill of a run's samples with every span in contact at once (issue 28: one pass over the spans, not one
call per span) against the route span by span it replaces, kept here as the reference: the same values bit for bit,
since every value is computed by the same operations element by element; and ``simulate``'s dataset through either
route, ``xarray.testing.assert_identical``, on every kind of run."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum import solution as S
from mdr_events.models.continuum.branch import NEAR_FOLD, Branch, TabulatedBranch
from mdr_events.models.continuum.sample_forces import FillRoute
from mdr_events.theory import quartic

from bench_paths import HERTZ, PAPER, ZIGZAG, paper_table as _table, reciprocating as _reciprocating


#: label -> (params, path, solve_path's keywords): anchor maps of one to four pieces, constant and growing, both caps
#: reached, a table's and a power law's branches (their own roots), the flat punch, Coulomb's caps with and without
#: adhesion (the compressed zone's route; the split layouts' zones), a layer, many pinned spans.
CASES = {
    "A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER), {}),
    "B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER), {}),
    "zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {}),
    "reciprocating": lambda: (PAPER, _reciprocating(), {}),
    "table, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=_table()), {"profile": _table()}),
    "cone, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER, profile=PowerLaw.cone(0.05)),
                            {"profile": PowerLaw.cone(0.05)}),
    "flat punch, A 20°": lambda: (PAPER, me.Path.scenario_A(20.0, PAPER, profile=me.FlatPunch(1e-3)),
                                  {"profile": me.FlatPunch(1e-3)}),
    "Hertz, Coulomb, zigzag": lambda: (HERTZ, me.Path(ZIGZAG, HERTZ.v), {"friction": FrictionLaw("coulomb", mu=0.3)}),
    "Coulomb with adhesion, B 30°": lambda: (PAPER, me.Path.scenario_B(30.0, PAPER),
                                             {"friction": FrictionLaw("coulomb", mu=0.3)}),
    "tau0+coulomb, zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v),
                                     {"friction": FrictionLaw("tau0+coulomb", mu=0.2)}),
    "thin layer, zigzag": lambda: (PAPER, me.Path(ZIGZAG, PAPER.v), {"layer": me.Layer(1e-3)}),
}


def _reference_fill(solution, times, spans_rows, out):
    """``evaluate``'s fill as it was, span by span: the radii of each branch's spans in one call (``_moving_radii``),
    each span then evaluated alone (``evaluate_span``: its kinematics, ``F_N``, ``F_x`` and its anchor map's sliding
    length)."""
    radii = S._moving_radii(solution, times, spans_rows)
    for index, rows in spans_rows:
        for name, values in S.evaluate_span(solution, index, times[rows], radii=radii.get(index)).items():
            out[name][rows] = values


def _both_forms(positive, argument):
    """The quartic's hyperbolic factor as it was: both forms computed everywhere, one chosen by ``np.where``."""
    with np.errstate(invalid="ignore"):
        return np.where(positive, np.sinh(np.arcsinh(argument) / 3.0),
                        np.cosh(np.arccosh(np.maximum(argument, 1.0)) / 3.0))


def _run(case):
    params, path, options = CASES[case]()
    solution = solve_path(params, path, **options)
    return solution


@pytest.mark.parametrize("case", list(CASES))
def test_the_fill_of_all_spans_at_once_is_the_fill_span_by_span(case, monkeypatch):
    """``evaluate`` at a run's 2001 samples, at times out of order (each span's rows gathered by index) and at times
    before the first contact and beyond the run: every quantity the same, bit for bit, as span by span (the forces by
    the spans' own terms, ``FillRoute.TERMS``, on both sides; ``test_sample_forces.py`` compares the polynomials'
    route with it)."""
    monkeypatch.setattr(S, "FILL_ROUTE", FillRoute.TERMS)
    solution = _run(case)
    samples = np.linspace(0.0, solution.end_time * (1.0 + 1.0 / 2001), 2001)
    shuffled = np.random.default_rng(7).permutation(samples[::3])
    grids = [samples, shuffled, np.linspace(-solution.t_contact, solution.end_time * 1.2, 301)]
    found = [S.evaluate(solution, times) for times in grids]
    with monkeypatch.context() as patch:
        patch.setattr(S, "_fill_spans", _reference_fill)
        patch.setattr(quartic, "_hyperbolic", _both_forms)
        reference = [S.evaluate(solution, times) for times in grids]
    for got, expected in zip(found, reference):
        for name in S.EVALUATED_QUANTITIES:
            np.testing.assert_array_equal(got[name], expected[name], err_msg=name)


def test_the_grouped_sample_radii_are_each_groups_own():
    """``grouped_sample_radii``: the closed form over every group at once, the iteration near the fold group by group,
    as each group's own ``sample_radii`` runs it; groups of one depth, of depths on and just above the fold (where the
    iteration runs, ``NEAR_FOLD``), below the jump-off (``nan``) and far above it."""
    branch = Branch(PAPER, PAPER.dgamma0)
    fold = branch.jump_off_depth
    groups = [np.array([PAPER.d_max]), fold + np.abs(fold) * np.array([0.0, 1e-12, 1e-9, 1e-6, 1e-3]),
              np.linspace(fold * 1.5, PAPER.d_max, 257), fold + np.abs(fold) * np.array([1e-10, 2e-7]),
              np.linspace(0.0, 1e-6, 3)]
    found = branch.grouped_sample_radii(groups)
    assert len(found) == len(groups)
    for got, depth in zip(found, groups):
        np.testing.assert_array_equal(got, branch.sample_radii(depth))
    # the groups near the fold do run the iteration (else this test would not tell a grouped iteration from its own)
    root = np.sqrt(branch.sample_radii(groups[1]))
    linear = float(branch._array_coefficients(groups[1], *branch._arguments)[3])
    assert np.any(4.0 * root**3 + linear < NEAR_FOLD * 4.0 * root**3)


@pytest.mark.parametrize("branch", [TabulatedBranch(PAPER, PAPER.dgamma0, _table()),
                                    TabulatedBranch(PAPER, PAPER.dgamma1, _table()),
                                    TabulatedBranch(HERTZ, 0.0, _table())], ids=["table", "table, Δγ1", "table, Hertz"])
def test_a_tables_grouped_sample_radii_are_each_groups_own(branch):
    """A table's radii are element by element (``elementwise_radii``): one call for all groups gives each group's own,
    on the grid's depths, between them, at and below the jump-off and beyond the table's deepest depth."""
    assert branch.elementwise_radii
    fold, deepest = branch.jump_off_depth, branch.line.deepest
    groups = [np.array([fold]), np.linspace(fold, deepest, 301), np.array(branch.line._depths[:7]),
              np.array([fold - abs(fold) - 1e-9, deepest * (1 + 1e-6), 0.5 * deepest]), np.linspace(0.0, 1e-6, 5)]
    found = branch.grouped_sample_radii(groups)
    for got, depth in zip(found, groups):
        np.testing.assert_array_equal(got, branch.sample_radii(depth))


def test_a_subclass_of_a_tables_branch_does_not_inherit_element_by_element_radii():
    """``elementwise_radii`` fails closed as ``quartic_samples`` and ``convex`` do: a branch type that does not declare
    it in its own body (here a subclass of the table's) takes its radii group by group, never one call for all."""

    class Derived(TabulatedBranch):
        pass

    class Declared(TabulatedBranch):
        elementwise_radii = True

    assert TabulatedBranch.elementwise_radii and not Derived.elementwise_radii and Declared.elementwise_radii


@pytest.mark.parametrize("delta", [np.linspace(-0.47, 3.0, 1001), np.geomspace(1e-40, 1e3, 64),
                                   -np.geomspace(1e-40, 0.47, 64), np.array(0.2), np.array(-0.2), np.array([])])
def test_the_quartics_hyperbolic_factor_is_each_forms_own(delta):
    """Each form of the resolvent's factor computed only where it is taken: the values of both computed everywhere and
    chosen (mixed signs, one sign alone, a 0-d value, none)."""
    size = np.abs(delta)
    with np.errstate(divide="ignore"):
        argument = 3.0 / (16.0 * size) * np.sqrt(3.0 / size)
    np.testing.assert_array_equal(quartic._hyperbolic(delta > 0, argument), _both_forms(delta > 0, argument))


def _rate_contact():
    return dataclasses.replace(me.Contact.from_parameters(PAPER),
                               adhesion=me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6))


#: label -> a continuum ``simulate`` call: the scenarios, custom paths, a table, a power law, a layer, a rate law.
SIMULATIONS = {
    "A": lambda: me.simulate(PAPER, "A", alpha=[20, 45, 80], method="continuum"),
    "B": lambda: me.simulate(PAPER, "B", alpha=[20, 60], method="continuum"),
    "zigzag and reciprocating": lambda: me.simulate(PAPER, [me.Path(ZIGZAG, PAPER.v), _reciprocating()],
                                                    method="continuum"),
    "table": lambda: me.simulate(PAPER, "A", alpha=[20], method="continuum", profile=_table()),
    "power law": lambda: me.simulate(PAPER, "B", alpha=[30], method="continuum", profile=PowerLaw(3e4, 3.0)),
    "layer": lambda: me.simulate(me.Contact.from_parameters(PAPER).replace(h=1e-3),
                                 me.Scenario("A", [20.0], PAPER.d_max, PAPER.v), method="continuum"),
    "rate law": lambda: me.simulate(_rate_contact(), me.Scenario("B", [30.0], PAPER.d_max, PAPER.v),
                                    method="continuum"),
    "Coulomb, times given": lambda: me.simulate(PAPER, "A", alpha=[30], method="continuum", t=np.linspace(0, 0.4, 99),
                                                friction=FrictionLaw("tau0+coulomb", mu=0.2)),
}


@pytest.mark.parametrize("case", list(SIMULATIONS))
def test_simulate_through_the_fill_at_once_is_simulate_span_by_span(case, monkeypatch):
    """``simulate``'s dataset through the fill at once and span by span, identical (the forces by the spans' own
    terms on both sides)."""
    monkeypatch.setattr(S, "FILL_ROUTE", FillRoute.TERMS)
    found = SIMULATIONS[case]()
    with monkeypatch.context() as patch:
        patch.setattr(S, "_fill_spans", _reference_fill)
        patch.setattr(quartic, "_hyperbolic", _both_forms)
        reference = SIMULATIONS[case]()
    xr.testing.assert_identical(found, reference)
