"""validate takes the contact, the motion and the exact reference as values (issue 35): the same report as the
keywords of before, each conversion in one place, and what does not fit named."""

from __future__ import annotations

import re

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import Tolerances, solve_path

PAPER = me.Parameters.paper()


@pytest.fixture(scope="module")
def run():
    discrete = me.simulate(PAPER, "A", [20.0], method="discrete", dx=4e-6, n_steps=2000).isel(alpha=0)
    return {name: discrete[name].values for name in ("time", "normal_force", "tangential_force", "contact_area")}


def same_report(new, old):
    assert new.attrs == old.attrs
    for name in old.variables:
        np.testing.assert_array_equal(new[name].values, old[name].values, err_msg=name)


def test_a_contact_and_a_scenario_give_the_keywords_report(run):
    old = me.validate(run, PAPER, "A", 20.0, tolerance=0.05)
    same_report(me.validate(run, me.Contact.paper(), me.Scenario("A", 20.0), tolerance=0.05), old)
    same_report(me.validate(run, me.Contact.paper(), "A", 20.0, tolerance=0.05), old)
    tight = Tolerances(rtol=1e-11)
    same_report(me.validate(run, PAPER, "A", 20.0, tolerance=0.05, reference=me.Continuum(tolerances=tight)),
                me.validate(run, PAPER, "A", 20.0, tolerance=0.05, tolerances=tight))


def test_a_solution_at_hand_is_a_reference(run):
    path = me.Path.scenario_A(20.0, PAPER)
    solution = solve_path(PAPER, path)
    same_report(me.validate(run, PAPER, path, reference=solution, tolerance=0.05),
                me.validate(run, PAPER, path, solution=solution, tolerance=0.05))


@pytest.mark.parametrize("call, error, words", [
    (lambda run: me.validate(run, PAPER, "A", 20.0, reference=me.Continuum(), tolerances=Tolerances()), ValueError,
     "reference and tolerances are not allowed together"),
    (lambda run: me.validate(run, PAPER, "A", 20.0, reference="exact"), TypeError, "reference='exact' (str)"),
    (lambda run: me.validate(run, PAPER, "A", 20.0, nmaes={"time": "t"}), TypeError,
     "unexpected keyword argument 'nmaes'; allowed: names, units, time_origin, select"),
    (lambda run: me.validate(run, me.Contact.paper(), me.Scenario("A", [20.0, 30.0])), ValueError,
     "holds 2 angles; allowed: the one the candidate ran"),
    (lambda run: me.validate(run, PAPER, "A"), ValueError, "alpha=None is not allowed with scenario 'A'"),
    (lambda run: me.validate(run, me.Contact.paper(), "A", 20.0, profile=me.PowerLaw.cone(0.1)), ValueError,
     "is not allowed beside a Contact"),
])
def test_what_does_not_fit_is_named(run, call, error, words):
    with pytest.raises(error, match=re.escape(words)):
        call(run)


def test_a_convergence_study_takes_the_same_values():
    runs = {}
    for dx in (8e-6, 4e-6, 2e-6):
        discrete = me.simulate(PAPER, "A", [20.0], method="discrete", dx=dx, n_steps=2000).isel(alpha=0)
        runs[dx] = {name: discrete[name].values for name in ("time", "normal_force", "contact_area")}
    old = me.convergence_study(runs, PAPER, "A", 20.0)
    new = me.convergence_study(runs, me.Contact.paper(), me.Scenario("A", 20.0), reference=me.Continuum())
    same_report(new, old)
    assert old.attrs["verdict"] == "converges"


def test_a_synthetic_measurement_takes_the_same_values():
    times = np.linspace(0.0, 1200.0, 51)
    from mdr_events.analysis.fit import synthetic_measurement
    old = synthetic_measurement(PAPER, "A", 20.0, times=times, relative_noise=0.01, seed=3, time_shift=2.0)
    new = synthetic_measurement(me.Contact.paper(), me.Scenario("A", 20.0), times=times, relative_noise=0.01,
                                seed=3, time_shift=2.0, reference=me.Continuum())
    same_report(new, old)
    with pytest.raises(TypeError, match="unexpected keyword argument 'sed'"):
        synthetic_measurement(PAPER, "A", 20.0, times=times, sed=3)


def test_a_fit_takes_the_same_values():
    """fit(measured, contact, motion, free=...) and the keywords of before, fit(measured, path, alpha, start=...),
    find the same parameters, bit for bit."""
    from mdr_events.analysis.fit import synthetic_measurement
    truth = PAPER.replace(tau0=30e3)
    times = np.linspace(0.0, 1200.0, 41)
    data = synthetic_measurement(truth, "A", 20.0, times=times, relative_noise=0.01, seed=1)
    old = me.fit(data, "A", 20.0, free=["tau0"], start=PAPER, time_origin="path_start")
    new = me.fit(data, me.Contact.paper(), me.Scenario("A", 20.0), free=["tau0"], time_origin="path_start",
                 reference=me.Continuum())
    assert new.parameters == old.parameters and new.dataset.attrs == old.dataset.attrs
    with pytest.raises(TypeError, match="unexpected keyword argument 'boundz'"):
        me.fit(data, me.Contact.paper(), "A", 20.0, free=["tau0"], boundz={})


def test_the_report_is_typed_and_round_trips_through_a_file(run, tmp_path):
    """ValidationReport: the verdict an enum, what fails in words by the rule the verdict is set by; the file read
    back gives the same report."""
    passing = me.validate(run, PAPER, "A", 20.0, tolerance=0.05)
    failing = me.validate(run, PAPER, "A", 20.0, tolerance=1e-6)
    for dataset, verdict in ((passing, me.Verdict.PASS), (failing, me.Verdict.FAIL)):
        report = me.ValidationReport.from_dataset(dataset)
        assert report.verdict is verdict and report.passed == (verdict is me.Verdict.PASS)
        assert bool(report.failures) == (verdict is me.Verdict.FAIL)
        read = me.ValidationReport.from_dataset(me.open_result(me.write_netcdf(dataset, tmp_path / f"{verdict}.nc")))
        assert read.verdict is verdict and read.failures == report.failures and read.to_dataset().identical(
            me.open_result(tmp_path / f"{verdict}.nc"))
    failures = me.ValidationReport.from_dataset(failing).failures
    assert any(text.startswith("normal_force: max error") and "> tolerance 1e-06" in text for text in failures)
    assert me.Verdict.PASS == "pass" and str(me.Verdict.FAIL) == "fail"  # (the attribute's text)
    with pytest.raises(ValueError, match="allowed: a validation"):
        me.ValidationReport.from_dataset(me.simulate(PAPER, "A", [20.0], method="continuum", samples=5))


def test_the_rule_of_the_verdict_names_each_failure():
    from mdr_events.analysis.reports import ValidationMeasures, validation_failures
    assert validation_failures(ValidationMeasures([], [], 0.0, []), 0.1) == ["no quantity compared"]
    assert validation_failures(ValidationMeasures(["normal_force"], [0.05], 0.0, [0.5]), 0.1) == []
    assert len(validation_failures(ValidationMeasures(["normal_force", "contact_area"], [0.2, float("nan")], 0.3,
                                                      [2.0, 0.0]), 0.1)) == 4
    assert validation_failures(ValidationMeasures(["tangential_force"], [0.05], float("nan"), [0.0]), 0.1) == []
    # (no contact shown)
