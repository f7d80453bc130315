"""``validate`` referees a run under the rate-dependent adhesion law (issue 29): its reference is the rate law's own
continuum (the run of ``simulate(method="continuum")``, :func:`mdr_events.models.methods.exact_solution`) evaluated at
the candidate's times, with that run's events; the discrete model converges to it at first order and passes within
the error of its spacing, a coarser one and a run of the paper's law fail."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum.rate_reference import RateSolution
from tests.hostile_checks import one_line_naming

#: The paper's works at rest, an edge's reference speed at the path's speed (1 µm/s: the rate law far from the
#: paper's) and Maugis & Barquins' exponent of about one half.
LAW = me.RateDependentAdhesion(0.01, 0.15, 1e-6, 0.5)
#: The springs' spacing of the fine run and of the coarse one (eight times wider).
FINE, COARSE = 2e-6, 16e-6
#: The verdict's bound: the springs' first-order error at twice the fine spacing (measured on scenario A at 20°:
#: 2.0e-3 of the range for the tangential force at 4 µm, 8.4e-4 at 2 µm, 3.7e-4 at 1 µm: halving Δx halves it), so the
#: fine run passes with a factor two to spare and the coarse one, four times the error of 4 µm, cannot.
TOLERANCE = 2e-3
#: The continuum's own output against its reference: the same run evaluated at the same times, equal to rounding.
ROUNDING = 1e-12


def rate_contact(law=LAW) -> me.Contact:
    return dataclasses.replace(me.Contact.paper(), adhesion=law)


def discrete(contact: me.Contact, dx: float):
    return me.simulate(contact, me.Scenario("A", alpha=[20.0]), "discrete", dx=dx).isel(alpha=0)


@pytest.fixture(scope="module")
def fine():
    return discrete(rate_contact(), FINE)


def test_the_springs_pass_within_their_first_order_error_and_a_coarse_run_fails(fine):
    report = me.validate(fine, rate_contact(), "A", 20.0, tolerance=TOLERANCE)
    assert report.attrs["verdict"] == "pass", report.attrs.get("failures")
    assert np.all(report["max_error"].values <= TOLERANCE)
    assert report.attrs["adhesion_law"] == "rate_dependent" and report.attrs["adhesion_v_ref"] == LAW.v_ref
    coarse = me.validate(discrete(rate_contact(), COARSE), rate_contact(), "A", 20.0, tolerance=TOLERANCE)
    assert coarse.attrs["verdict"] == "fail"
    assert float(coarse["max_error"].max()) > TOLERANCE


def test_the_errors_fall_at_first_order(fine):
    """Halving the spacing halves the largest error of the tangential force (observed order within 0.3 of 1)."""
    wide = me.validate(discrete(rate_contact(), 2 * FINE), rate_contact(), "A", 20.0, tolerance=1.0)
    narrow = me.validate(fine, rate_contact(), "A", 20.0, tolerance=1.0)
    errors = [float(report["max_error"].sel(quantity="tangential_force")) for report in (wide, narrow)]
    assert abs(np.log2(errors[0] / errors[1]) - 1.0) < 0.3, errors


def test_a_run_of_the_paper_s_law_fails_against_the_rate_law_and_passes_its_own(fine):
    """The same springs and path under the works at rest alone: the paper's reference passes them, the rate law's
    (an advancing edge held back, a receding one held on) fails them; a referee reading the paper's continuum under
    the rate law would pass them."""
    paper = discrete(me.Contact.paper(), FINE)
    assert me.validate(paper, me.Contact.paper(), "A", 20.0, tolerance=TOLERANCE).attrs["verdict"] == "pass"
    against = me.validate(paper, rate_contact(), "A", 20.0, tolerance=TOLERANCE)
    assert against.attrs["verdict"] == "fail"
    assert float(against["max_error"].sel(quantity="normal_force")) > 10 * TOLERANCE


def test_the_continuum_s_own_run_is_its_reference_to_rounding():
    run = me.simulate(rate_contact(), me.Scenario("A", alpha=[20.0]), "continuum").isel(alpha=0)
    report = me.validate(run, rate_contact(), "A", 20.0, tolerance=ROUNDING)
    assert report.attrs["verdict"] == "pass"
    assert float(report["max_error"].max()) <= ROUNDING
    events = dict(zip(report["event"].values, report["event_time_exact"].values))
    assert events["first_contact"] == 0.0 and np.isfinite(events["slip_onset"])


def test_the_events_are_the_rate_law_s_and_the_receding_start_is_named_as_not_timed(fine):
    """The slip onset is the rate run's (its time differs from the paper's, whose edge grows faster); the detachment's
    start is flat to order 1 + 1/n (a sampled run shows it at order n/(n+1)) and says so instead of failing."""
    report = me.validate(fine, rate_contact(), "A", 20.0, tolerance=TOLERANCE)
    paper = me.validate(discrete(me.Contact.paper(), FINE), me.Contact.paper(), "A", 20.0, tolerance=TOLERANCE)
    onset = [float(r["event_time_exact"].sel(event="slip_onset")) for r in (report, paper)]
    assert onset[0] != pytest.approx(onset[1], rel=1e-3)
    assert "detachment_starts (the rate law's receding edge starts from rest" in report.attrs["events_not_compared"]
    assert np.isnan(float(report["event_time_relative_error"].sel(event="detachment_starts")))
    assert np.isfinite(float(report["event_time_exact"].sel(event="detachment_starts")))


def test_a_solution_at_hand_of_the_rate_law_is_the_reference_and_one_of_the_paper_s_is_refused(fine):
    from mdr_events.models.methods import exact_solution
    from mdr_events.models.simulate import model_job
    from mdr_events.models.continuum import Tolerances
    from mdr_events.limits import DEFAULT_LIMITS

    path = me.Path.scenario_A(20.0, me.Parameters.paper())
    job = model_job(rate_contact(), me.Paths({"A": path}), None, {})
    solution = exact_solution(job, path, Tolerances(), DEFAULT_LIMITS)
    assert isinstance(solution, RateSolution)
    at_hand = me.validate(fine, rate_contact(), "A", 20.0, tolerance=TOLERANCE, reference=solution)
    direct = me.validate(fine, rate_contact(), "A", 20.0, tolerance=TOLERANCE)
    np.testing.assert_array_equal(at_hand["max_error"].values, direct["max_error"].values)
    paper = me.models.continuum.solve_path(me.Parameters.paper(), path)
    text = one_line_naming(lambda: me.validate(fine, rate_contact(), "A", 20.0, reference=paper), "adhesion=",
                           ValueError)
    assert "allowed: a solution of this adhesion law" in text


def test_coulomb_under_the_rate_law_is_refused_naming_both_laws(fine):
    """The rate law's continuum runs ``τ0``'s cap alone (each spring its own cap under Coulomb's law)."""
    contact = dataclasses.replace(rate_contact(), friction=me.FrictionLaw("coulomb", mu=0.3))
    text = one_line_naming(lambda: me.validate(fine, contact, "A", 20.0), "coulomb", ValueError)
    assert "adhesion=RateDependentAdhesion(" in text and "allowed: FrictionLaw('tau0')" in text


def test_the_convergence_study_of_the_rate_law_finds_first_order(fine):
    """One solve of the rate law's continuum serves every spacing (``convergence_study``): the max error's observed
    order of the tangential force within 0.3 of 1, and the report names the law."""
    runs = {4 * FINE: discrete(rate_contact(), 4 * FINE), 2 * FINE: discrete(rate_contact(), 2 * FINE), FINE: fine}
    study = me.convergence_study(runs, rate_contact(), "A", 20.0)
    assert abs(float(study["max_error_order"].sel(quantity="tangential_force")) - 1.0) < 0.3
    assert study.attrs["adhesion_law"] == "rate_dependent"
