"""``convergence_study``: the observed order per norm and per event from three or more spacings, and its figure."""

import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis import convergence_study as module
from mdr_events.analysis.convergence_study import NORMS, convergence_study, fit_observed_order
from mdr_events.analysis.samples import VALIDATED_EVENTS
from mdr_events.plotting.convergence import REFERENCE_LABEL, plot_convergence_study

ALPHA = 20.0
SPACINGS = (8e-6, 4e-6, 2e-6)
REPOSITORY = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def runs(paper):
    """The package's own spring model, scenario A at 20°, at three spacings (dt = Δx / 2v)."""
    return {dx: me.simulate(paper, "A", alpha=[ALPHA], dx=dx, dt=0.5 * dx / paper.v).isel(alpha=0)
            for dx in SPACINGS}


@pytest.fixture(scope="module")
def study(paper, runs):
    return convergence_study(runs, paper, "A", ALPHA)


@pytest.fixture(scope="module")
def wrong_study(paper, runs):
    """Its tangential force 5 % too high at every spacing: an error that does not shrink."""
    return convergence_study({dx: run.assign(tangential_force=1.05 * run["tangential_force"])
                              for dx, run in runs.items()}, paper, "A", ALPHA)


# ----------------------------------------------------------------------------------------------
# the fit


def test_the_slope_is_the_hand_computed_least_squares_slope():
    """Errors 1, 2, 8 at Δx = 1, 2, 4: in units of ln 2, x = 0, 1, 2 and y = 0, 1, 3, so the slope is
    Σ(x − 1)(y − 4/3) / Σ(x − 1)² = 3/2, the intercept 4/3 − 3/2 = −1/6, the residuals 1/6, −1/3, 1/6 and
    the standard error sqrt((1/6) / (3 − 2) / 2) = 1/sqrt(12)."""
    fit = fit_observed_order([1.0, 2.0, 4.0], [1.0, 2.0, 8.0])
    assert fit.order == pytest.approx(1.5, rel=1e-12)
    assert fit.spread == pytest.approx(1.0 / math.sqrt(12.0), rel=1e-12)
    assert fit.points == 3
    np.testing.assert_allclose(fit.fitted, 2.0 ** (-1.0 / 6.0) * np.array([1.0, 2.0, 4.0]) ** 1.5, rtol=1e-12)
    # the spacings' unit and order do not matter; a sign does not either (magnitudes are fitted)
    again = fit_observed_order([4e-6, 1e-6, 2e-6], [-8.0, 1.0, 2.0])
    assert (again.order, again.spread) == pytest.approx((fit.order, fit.spread), rel=1e-12)


def test_errors_exactly_zero_or_nan_are_left_out_of_a_fit():
    fit = fit_observed_order([1.0, 3.0, 2.0, 5.0, 4.0], [1.0, 0.0, 2.0, math.nan, 8.0])
    assert fit.points == 3
    assert (fit.order, fit.spread) == pytest.approx((1.5, 1.0 / math.sqrt(12.0)), rel=1e-12)
    two = fit_observed_order([1.0, 2.0, 4.0], [3.0, 0.0, 12.0])  # two points: the slope through them, no spread
    assert two.order == pytest.approx(1.0, rel=1e-12) and math.isnan(two.spread)
    one = fit_observed_order([1.0, 2.0, 4.0], [math.nan, 0.0, 5.0])
    assert math.isnan(one.order) and math.isnan(one.spread) and np.all(np.isnan(one.fitted)) and one.points == 1


def test_the_studys_orders_are_the_least_squares_slopes_of_its_own_errors(study):
    """Each order and spread of the study is the fit of the errors it reports (numpy's polyfit, another route)."""
    x = np.log(study["dx"].values)
    for norm in NORMS:
        for quantity in study["quantity"].values:
            y = np.log(study[norm].sel(quantity=quantity).values)
            (slope, intercept), residuals, *_ = np.polyfit(x, y, 1, full=True)
            spread = math.sqrt(residuals[0] / (len(x) - 2) / np.sum((x - x.mean()) ** 2))
            assert float(study[f"{norm}_order"].sel(quantity=quantity)) == pytest.approx(slope, rel=1e-9)
            assert float(study[f"{norm}_order_spread"].sel(quantity=quantity)) == pytest.approx(spread, rel=1e-6)
            np.testing.assert_allclose(study[f"{norm}_fitted"].sel(quantity=quantity).values,
                                       np.exp(intercept + slope * x), rtol=1e-9)


# ----------------------------------------------------------------------------------------------
# the study


def test_the_spring_model_converges_at_first_order(study):
    """The paper's spring model converges to the continuum at first order: F_N, F_x and A (max norm) have
    observed orders in [0.7, 1.5]; every norm of every quantity converges; the verdict says so."""
    for quantity in ("normal_force", "tangential_force", "contact_area"):
        order = float(study["max_error_order"].sel(quantity=quantity))
        assert 0.7 <= order <= 1.5, (quantity, order)
    for norm in NORMS:
        assert np.all(study[f"{norm}_converges"].values == 1), norm
    assert study.attrs["verdict"] == "converges"
    assert float(study["expected_order"]) == 1.0


def test_an_error_that_does_not_shrink_has_order_zero_and_does_not_converge(wrong_study):
    row = wrong_study.sel(quantity="tangential_force")
    assert abs(float(row["max_error_order"])) < 0.2
    assert int(row["max_error_converges"]) == 0
    assert int(wrong_study["max_error_converges"].sel(quantity="normal_force")) == 1
    assert wrong_study.attrs["verdict"] == "does not converge"


def test_a_higher_expected_order_is_not_met(paper, runs):
    """The same first-order model, expected to be of order 3: half of it (1.5) is not reached."""
    strict = convergence_study(runs, paper, "A", ALPHA, expected_order=3.0)
    assert np.all(strict["max_error_converges"].values == 0)
    assert strict.attrs["verdict"] == "does not converge" and float(strict["expected_order"]) == 3.0


def test_the_layout(study, runs):
    assert study["dx"].values.tolist() == sorted(SPACINGS, reverse=True) and study["dx"].attrs["units"] == "m"
    assert study["max_error"].dims == ("dx", "quantity")
    assert study["max_error_order"].dims == ("quantity",)
    assert study["event_time_error"].dims == ("dx", "event")
    assert study["event_depth_error_order"].dims == ("event",)
    assert study["pull_off_force_error"].dims == ("dx",) and study["pull_off_force_error_order"].dims == ()
    assert list(study["event"].values) == list(VALIDATED_EVENTS)
    assert study["event_time_relative_error"].dims == ("dx", "event") and study["validation_verdict"].dims == ("dx",)
    errors = study["event_time_error"].values
    assert np.all(np.isnan(errors) | (errors >= 0)) and np.all(study["pull_off_force_error"].values >= 0)
    # every event the runs show has an error at every spacing; re-contact is in none of them (nan, no fit)
    assert np.all(np.isnan(study["event_time_error"].sel(event="re_contact").values))
    assert np.all(np.isfinite(study["event_time_error"].drop_sel(event="re_contact").values))
    assert np.isnan(float(study["event_time_error_order"].sel(event="re_contact")))
    for name, variable in study.variables.items():
        assert "units" in variable.attrs and "long_name" in variable.attrs, name


def test_the_errors_are_validates(paper, runs, study):
    """Row by row the study holds what validate reports at that spacing (event errors as magnitudes)."""
    report = me.validate(runs[4e-6], paper, "A", ALPHA)
    row = study.sel(dx=4e-6)
    for norm in NORMS:
        np.testing.assert_array_equal(row[norm].sel(quantity=report["quantity"].values).values, report[norm].values)
    np.testing.assert_array_equal(row["event_time_error"].values, np.abs(report["event_time_error"].values))
    np.testing.assert_array_equal(row["event_time_relative_error"].values, report["event_time_relative_error"].values)
    assert int(row["validation_verdict"]) == int(me.ValidationReport.from_dataset(report).passed)
    np.testing.assert_array_equal(row["event_depth_error"].values, np.abs(report["event_depth_error"].values))
    assert float(row["pull_off_force_error"]) == abs(float(report["pull_off_force_candidate"])
                                                     - float(report["pull_off_force_exact"]))


def test_one_validate_per_spacing(paper, runs, monkeypatch):
    calls = []

    def counted(*args, **kwargs):
        calls.append(args[0])
        return me.validate(*args, **kwargs)

    monkeypatch.setattr(module, "validate", counted)
    convergence_study(runs, paper, "A", ALPHA)
    assert len(calls) == len(SPACINGS)


def test_the_study_is_a_labelled_result_that_round_trips(study, tmp_path):
    written = me.write_netcdf(study, tmp_path / "study.nc")
    xr.testing.assert_identical(me.open_result(written), study)


@pytest.mark.parametrize("candidates, match", [
    ({8e-6: "a.csv", 4e-6: "b.csv"}, r"candidates_by_dx has 2 spacing\(s\) .*allowed: a mapping of at least 3"),
    ({8e-6: "a.csv"}, r"candidates_by_dx has 1 spacing"),
    ({8e-6: "a.csv", 0.0: "b.csv", 2e-6: "c.csv"}, r"candidates_by_dx has the spacing\(s\) 0.0; allowed"),
    ({8e-6: "a.csv", math.nan: "b.csv", 2e-6: "c.csv"}, r"candidates_by_dx has the spacing\(s\) nan"),
    ({8e-6: "a.csv", "4um": "b.csv", 2e-6: "c.csv"}, r"spacing\(s\) '4um'"),
    (["a.csv", "b.csv", "c.csv"], r"candidates_by_dx of type list is not allowed"),
])
def test_bad_spacings_are_refused_before_any_validation(paper, candidates, match, monkeypatch):
    monkeypatch.setattr(module, "validate", lambda *args, **kwargs: pytest.fail("validated a bad study"))
    with pytest.raises(ValueError, match=match):
        convergence_study(candidates, paper, "A", ALPHA)


@pytest.mark.parametrize("expected", [0.0, -1.0, math.inf, True, "1"])
def test_a_bad_expected_order_is_refused(paper, runs, expected):
    with pytest.raises(ValueError, match="expected_order=.* is not allowed; allowed: a finite number > 0"):
        convergence_study(runs, paper, "A", ALPHA, expected_order=expected)


# ----------------------------------------------------------------------------------------------
# the figure


def test_the_figure_has_one_line_per_norm_per_quantity_and_a_reference(study):
    figure = plot_convergence_study(study)
    quantities = list(study["quantity"].values)
    assert len(figure.axes) == len(quantities)
    for ax, quantity in zip(figure.axes, quantities):
        assert ax.get_xscale() == ax.get_yscale() == "log"
        fits = {line.get_gid(): line for line in ax.lines if (line.get_gid() or "").startswith("fit:")}
        references = [line for line in ax.lines if line.get_gid() == "reference"]
        assert set(fits) == {f"fit:{norm}" for norm in NORMS} and len(references) == 1
        assert len(ax.lines) == len(NORMS) + 1
        for norm in NORMS:  # the fitted lines are the study's, not recomputed
            np.testing.assert_allclose(fits[f"fit:{norm}"].get_xdata(), study["dx"].values * 1e6)
            np.testing.assert_array_equal(fits[f"fit:{norm}"].get_ydata(),
                                          study[f"{norm}_fitted"].sel(quantity=quantity).values)
            assert f"order {float(study[f'{norm}_order'].sel(quantity=quantity)):.2f}" in fits[f"fit:{norm}"].get_label()
        x, y = references[0].get_xdata(), references[0].get_ydata()
        assert np.log(y[0] / y[-1]) / np.log(x[0] / x[-1]) == pytest.approx(float(study["expected_order"]))
        assert references[0].get_label() == REFERENCE_LABEL.format(order=1.0)
        assert np.all(y > np.nanmax([study[norm].sel(quantity=quantity).values for norm in NORMS], axis=0))


def test_the_figure_draws_what_the_study_holds(study):
    """A study edited by hand is drawn as edited (the figure reads, never recomputes)."""
    edited = study.copy(deep=True)
    edited["max_error_fitted"][:] = 1e-3
    figure = plot_convergence_study(edited)
    line = next(line for line in figure.axes[0].lines if line.get_gid() == "fit:max_error")
    np.testing.assert_array_equal(line.get_ydata(), [1e-3] * len(SPACINGS))


def test_importing_the_figure_module_leaves_the_backend_alone():
    environment = {name: value for name, value in os.environ.items() if name != "MPLBACKEND"}
    code = ("import matplotlib; matplotlib.use('svg'); import mdr_events.plotting.convergence; "
            "print(matplotlib.get_backend())")
    result = subprocess.run([sys.executable, "-c", code], env=environment, cwd=REPOSITORY, capture_output=True,
                            text=True, check=True)
    assert result.stdout.strip().splitlines()[-1] == "svg"


def test_the_convergence_report_is_typed():
    import xarray as xr

    import mdr_events as me
    from mdr_events.analysis.reports import CONVERGENCE_STUDY_CONTENT
    dataset = xr.Dataset(attrs={"content": CONVERGENCE_STUDY_CONTENT, "verdict": "does not converge",
                                "expected_order": 1.0})
    report = me.ConvergenceReport.from_dataset(dataset)
    assert report.verdict is me.ConvergenceVerdict.DOES_NOT_CONVERGE and report.expected_order == 1.0
    assert report.to_dataset() is dataset
