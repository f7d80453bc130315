"""``fit``: parameters recovered from synthetic measurements, their intervals, identifiability, bad input."""

import math
import re

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.fit import (FREE_NAMES, Identifiability, estimate_noise, model_curves,
                                     synthetic_measurement)
from mdr_events.analysis.validate import resolve_path
from mdr_events.limits import DEFAULT_LIMITS
from mdr_events.models.continuum import Tolerances

ALPHA = 20.0
#: The paper's scenario A at 20° lasts about 1229 s; the samples reach a little past its end.
SAMPLES = 2001
FREE = ("E", "tau0", "dgamma0", "dgamma1")
#: Noise-free data recovered to this (relative): the issue's figure; the curves are exact to ~1e-10.
NOISE_FREE_RTOL = 1e-6
#: The issue's coverage test: over 40 seeds each 95 % interval holds the truth at least 34 times (binomial
#: with p = 0.95: P(X < 34) ≈ 0.8 %; nominal 38).
COVERAGE_SEEDS, COVERAGE_AT_LEAST = 40, 34


def times_of(params, samples=SAMPLES, past_end=1.02):
    return np.linspace(0.0, past_end * resolve_path(params, "A", ALPHA).duration, samples)


def thirty_percent_off(params, names=FREE):
    """A start 30 % off the truth, alternately above and below."""
    return params.replace(**{name: getattr(params, name) * (1.3 if i % 2 == 0 else 0.7)
                             for i, name in enumerate(names)})


@pytest.fixture(scope="module")
def noisy(paper):
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper), relative_noise=0.01, seed=7)
    return me.fit(data, "A", ALPHA, free=FREE, start=thirty_percent_off(paper), time_origin="path_start")


def test_noise_free_data_are_recovered_to_1e_6_from_30_percent_off(paper):
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper))
    result = me.fit(data, "A", ALPHA, free=FREE, start=thirty_percent_off(paper), time_origin="path_start")
    for name, estimate in result.estimates.items():
        assert estimate.value == pytest.approx(getattr(paper, name), rel=NOISE_FREE_RTOL), name
    assert result.identifiable


def test_with_one_percent_noise_every_parameter_lies_in_its_interval(paper, noisy):
    for name, estimate in noisy.estimates.items():
        assert estimate.lower <= getattr(paper, name) <= estimate.upper, (name, estimate)
        assert estimate.identifiability is Identifiability.DETERMINED
        # the interval is a real one: narrower than ±10 %, and the standard error is positive
        assert 0 < estimate.standard_error and estimate.upper - estimate.lower < 0.2 * estimate.value
    # the noise was estimated near its true level (1 % of each quantity's largest magnitude), and the weighted
    # residuals are then of unit size
    assert np.all(np.abs(noisy.dataset["rms_normalised_residual"].values - 1.0) < 0.1)
    assert noisy.warnings == [] and "but the fit" not in noisy.verdict and "tau0 = " in repr(noisy)


@pytest.mark.slow
def test_the_intervals_cover_the_truth_at_their_nominal_rate(paper):
    """Over 40 seeds of 1 % noise each parameter's 95 % interval holds the truth at least 34 times."""
    times = times_of(paper, samples=801)
    free = ("tau0", "dgamma1", "E")
    start = thirty_percent_off(paper, free)
    covered = dict.fromkeys(free, 0)
    for seed in range(COVERAGE_SEEDS):
        data = synthetic_measurement(paper, "A", ALPHA, times=times, relative_noise=0.01, seed=1000 + seed)
        result = me.fit(data, "A", ALPHA, free=free, start=start, time_origin="path_start")
        for name, estimate in result.estimates.items():
            covered[name] += estimate.lower <= getattr(paper, name) <= estimate.upper
    assert all(count >= COVERAGE_AT_LEAST for count in covered.values()), covered


def test_tau0_from_the_normal_force_alone_is_flagged_not_identifiable(paper):
    """F_N does not depend on friction (uncoupled springs): τ0 is not a confident wrong number."""
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 801), relative_noise=0.01, seed=3,
                                 quantities=("normal_force",))
    result = me.fit(data, "A", ALPHA, free=("tau0", "dgamma1"), start=thirty_percent_off(paper, ("tau0", "dgamma1")),
                    time_origin="path_start")
    tau0 = result.estimates["tau0"]
    assert tau0.identifiability is Identifiability.NOT_IDENTIFIABLE
    assert math.isinf(tau0.standard_error) and tau0.lower == 0.0 and math.isinf(tau0.upper)
    assert result.estimates["dgamma1"].identifiability is Identifiability.DETERMINED
    assert not result.identifiable and "tau0 (not identifiable)" in result.verdict
    assert "tau0 acts only on F_x" in " ".join(result.notes)
    assert math.isinf(result.condition_number) or result.condition_number > 1e6


def test_a_time_offset_of_3_s_is_found(paper):
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 1001), relative_noise=0.005, seed=11,
                                 time_shift=3.0)
    result = me.fit(data, "A", ALPHA, free=("tau0", "time_offset"), start=paper.replace(tau0=0.8 * paper.tau0),
                    time_origin="path_start")
    offset = result.estimates["time_offset"]
    assert offset.lower <= 3.0 <= offset.upper and offset.upper - offset.lower < 1.0
    assert result.time_offset == offset.value
    assert result.estimates["tau0"].lower <= paper.tau0 <= result.estimates["tau0"].upper


def test_a_depth_offset_is_found_without_noise(paper):
    """The path's depth zero lies 5 µm above the real surface: the curves are those of the path shifted down."""
    path = resolve_path(paper, "A", ALPHA)
    shifted = me.Path(path.waypoints - np.array([0.0, 5e-6]), path.speed)
    times = np.linspace(0.0, 1.02 * path.duration, 1001)
    data = synthetic_measurement(paper, shifted, times=times)
    result = me.fit(data, path, free=("depth_offset", "dgamma1"), start=paper.replace(dgamma1=0.12),
                    time_origin="path_start")
    assert result.depth_offset == pytest.approx(5e-6, rel=NOISE_FREE_RTOL)
    assert result.parameters.dgamma1 == pytest.approx(paper.dgamma1, rel=NOISE_FREE_RTOL)


def test_a_clock_that_starts_late_is_flagged_not_fitted_away(paper):
    """A record whose clock reads 5 s at the first contact, fitted with the default time origin (first contact at
    t = 0): Δγ1 can move the pull-off to hide the offset, but the record starts 5 s after the contact, in contact."""
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 801), relative_noise=0.01, seed=8,
                                 time_shift=5.0)
    result = me.fit(data, "A", ALPHA, free=("tau0", "dgamma1"), start=paper)
    assert any("the record starts 5 s after the path's first contact, in contact: if it starts at the first "
               "contact, give time_origin=5" in w for w in result.warnings), result.warnings
    assert "but the fit does not describe the data" in result.verdict
    fixed = me.fit(data, "A", ALPHA, free=("tau0", "dgamma1"), start=paper, time_origin=5.0)
    assert fixed.warnings == [] and fixed.estimates["dgamma1"].lower <= paper.dgamma1 <= fixed.estimates["dgamma1"].upper


def test_a_wrong_unit_is_flagged(paper):
    """Times in ms read as s and forces in mN read as N: warnings name the unit, not the physics."""
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 401), relative_noise=0.01, seed=9)
    data = data.assign_coords(time=data["time"] * 1e3)
    data["normal_force"] = data["normal_force"] * 1e3
    result = me.fit(data, "A", ALPHA, free=("tau0",), start=paper, time_origin="path_start")
    text = " ".join(result.warnings)
    assert "check the unit of time" in text and "normal_force reaches" in text


def test_e_and_nu_are_reported_as_effective_moduli(paper):
    start = paper.replace(E=1.2 * paper.E, nu=0.3)
    data = synthetic_measurement(paper.replace(nu=0.4), "A", ALPHA, times=times_of(paper, 801))
    result = me.fit(data, "A", ALPHA, free=("E", "nu"), start=start, time_origin="path_start")
    truth = paper.replace(nu=0.4)
    assert result.parameters.nu == pytest.approx(0.4, rel=1e-6)
    assert float(result.dataset["E_star"]) == pytest.approx(truth.E_star, rel=1e-6)
    assert float(result.dataset["G_star"]) == pytest.approx(truth.G_star, rel=1e-6)
    assert "E and ν enter the model only through E*" in " ".join(result.notes)


def test_nu_at_its_bound_is_fitted_and_reported_at_the_bound(paper):
    """The paper's ν = 0.5 is the upper bound: the fit ends on it, says so, and reports E* and G* there."""
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 301))
    result = me.fit(data, "A", ALPHA, free=("nu",), start=paper.replace(nu=0.45), time_origin="path_start")
    assert result.parameters.nu == pytest.approx(0.5, abs=1e-9)
    assert result.estimates["nu"].identifiability is Identifiability.AT_BOUND
    assert float(result.dataset["G_star"]) == pytest.approx(paper.G_star, rel=1e-6)


def test_the_contact_mask_does_not_depend_on_the_quantities(paper):
    """Before the first contact the model is out of contact whichever quantities are fitted (the Jacobian's
    jump rule reads this mask)."""
    path = resolve_path(paper, "A", ALPHA)
    times = np.array([-2.0, -1.0, 1.0, 2.0])
    masks = [model_curves(paper, path, times, Tolerances(), DEFAULT_LIMITS, (name,)).in_contact
             for name in ("contact_area", "contact_radius", "normal_force")]
    for mask in masks:
        assert mask.tolist() == [False, False, True, True]


def test_model_curves_follow_the_rule_out_of_contact(paper):
    """0 out of the elastomer (before the path, after the pull-off and past a path that ends outside);
    nan (left out) past a path that ends in contact."""
    path = resolve_path(paper, "A", ALPHA)
    times = np.array([-5.0, 0.5 * path.duration, 1.1 * path.duration])
    curves = model_curves(paper, path, times, Tolerances(), DEFAULT_LIMITS, ("normal_force", "contact_area")).values
    assert curves["normal_force"][0] == 0.0 and curves["normal_force"][2] == 0.0 and curves["normal_force"][1] > 0
    pressed = me.Path([(0.0, -1e-5), (0.0, 2e-4)], paper.v)
    curves = model_curves(paper, pressed, np.array([1.0, 0.5 * pressed.duration, 2.0 * pressed.duration]),
                          Tolerances(), DEFAULT_LIMITS, ("normal_force",)).values
    assert curves["normal_force"][0] == 0.0 and curves["normal_force"][1] > 0 and np.isnan(curves["normal_force"][2])


def test_missing_samples_are_left_out_and_counted(paper):
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 801), relative_noise=0.01, seed=5)
    data["tangential_force"][100:150] = np.nan
    result = me.fit(data, "A", ALPHA, free=("tau0",), start=paper.replace(tau0=30e3), time_origin="path_start")
    assert np.all(np.isnan(result.dataset["residual_tangential_force"].values[100:150]))
    assert np.all(result.dataset["left_out"].values[100:150] == 1)
    assert np.count_nonzero(result.dataset["left_out"].values) == 50
    assert result.estimates["tau0"].lower <= paper.tau0 <= result.estimates["tau0"].upper


def test_estimate_noise_recovers_white_noise_on_a_smooth_curve():
    rng = np.random.default_rng(2)
    t = np.linspace(0.0, 1.0, 4001)
    values = np.sin(3 * t) + 0.02 * rng.standard_normal(t.size)
    values[2000:] += 5.0  # a jump (a pull-off) does not spoil the estimate
    assert estimate_noise(values) == pytest.approx(0.02, rel=0.05)


def test_the_result_writes_and_reads_back_and_plots(tmp_path, paper, noisy):
    written = me.write_netcdf(noisy.dataset, tmp_path / "fit.nc")
    back = me.open_result(written)
    xr.testing.assert_identical(back, noisy.dataset)
    assert me.io.datasets.parameters_of(back) == noisy.parameters  # the fitted parameters, stamped
    # same input, same output: the same fit written twice gives the same bytes
    assert me.write_netcdf(noisy.dataset, tmp_path / "again.nc").read_bytes() == written.read_bytes()
    for name, variable in noisy.dataset.variables.items():
        assert "units" in variable.attrs and "long_name" in variable.attrs, name
    figure = noisy.plot()
    assert len(figure.axes) == 2 * noisy.dataset.sizes["quantity"]
    correlation = noisy.correlation
    assert np.allclose(np.diag(correlation), 1.0) and np.allclose(correlation, correlation.T)
    assert noisy.dataset.attrs["identifiable"] == 1 and noisy.optimizer.continuum_solves > len(FREE)


@pytest.mark.parametrize("change, message", [
    (dict(measured={"time": np.array([]), "normal_force": np.array([])}), "time"),
    (dict(measured={"time": np.arange(5.0), "normal_force": np.full(5, np.nan)}), "normal_force has no finite"),
    (dict(free=("mu",)), "free: 'mu' is not allowed"),
    (dict(free=("d_max",)), "the path's, not the material's"),
    (dict(free=()), "free=() is not allowed"),
    (dict(bounds={"tau0": (50e3, 60e3)}), "excludes the start"),
    (dict(bounds={"E": (1.0, 2.0)}), "bounds: 'E' is not allowed"),
    (dict(noise={"tangential_force": -1.0}), "noise['tangential_force']=-1.0 is not allowed"),
])
def test_bad_input_is_named(paper, change, message):
    arguments = dict(measured={"time": np.linspace(0, 1200, 50), "normal_force": np.linspace(0, 0.5, 50),
                               "tangential_force": np.linspace(0, 0.5, 50)},
                     free=("tau0",), bounds=None, noise=None)
    arguments.update(change)
    measured = arguments.pop("measured")
    with pytest.raises(ValueError, match=re.escape(message)):
        me.fit(measured, "A", ALPHA, start=paper, time_origin="path_start", **arguments)


def test_bounds_may_be_a_numpy_pair_and_bind_the_estimate(paper):
    data = synthetic_measurement(paper, "A", ALPHA, times=times_of(paper, 301))
    result = me.fit(data, "A", ALPHA, free=("tau0",), start=paper.replace(tau0=30e3), time_origin="path_start",
                    bounds={"tau0": np.array([20e3, 40e3])})
    assert result.parameters.tau0 == pytest.approx(40e3, rel=1e-9)  # the truth (42 kPa) lies beyond the bound
    assert result.estimates["tau0"].identifiability is Identifiability.AT_BOUND
    assert "tau0 sits on a bound" in " ".join(result.notes)


def test_a_start_of_zero_cannot_be_fitted_on_a_log_scale(paper):
    with pytest.raises(ValueError, match=r"start.dgamma0=0.0 is not allowed for a free dgamma0"):
        me.fit({"time": np.arange(10.0), "normal_force": np.arange(10.0)}, "A", ALPHA, free=("dgamma0",),
               start=paper.replace(dgamma0=0.0))


def test_every_free_name_is_documented():
    assert set(FREE_NAMES) == {"E", "nu", "R", "tau0", "dgamma0", "dgamma1", "mu", "h", "time_offset", "depth_offset"}


def test_a_cone_experiment_is_fitted_with_its_indenter(paper):
    """Synthetic data of a cone (1 % noise): τ0 and Δγ1 from 30 % off lie in their 95 % intervals when the fit
    knows the indenter, without warnings; the paraboloid's curve lies ten noise levels away. R cannot be free
    with a power law."""
    from mdr_events.contact.indenters import PowerLaw

    cone = PowerLaw.cone(0.1)
    path = me.Path.scenario_A(20.0, paper, profile=cone)
    times = np.linspace(0.0, 1.02 * path.duration, 801)
    measured = synthetic_measurement(paper, "A", 20.0, times=times, relative_noise=0.01, seed=3, profile=cone)
    assert measured.attrs["profile"] == cone.describe()
    start = paper.replace(tau0=1.3 * paper.tau0, dgamma1=0.7 * paper.dgamma1)
    result = me.fit(measured, "A", 20.0, free=["tau0", "dgamma1"], start=start, time_origin="path_start",
                    profile=cone)
    assert result.dataset.attrs["profile"] == cone.describe() and result.warnings == []
    for name in ("tau0", "dgamma1"):
        estimate = result.estimates[name]
        assert estimate.lower <= getattr(paper, name) <= estimate.upper, (name, estimate)
    paraboloid = model_curves(paper, me.Path.scenario_A(20.0, paper), times, Tolerances(), DEFAULT_LIMITS,
                              ("normal_force",)).values["normal_force"]
    assert np.nanmax(np.abs(paraboloid - measured["normal_force"].values)) > 10 * 0.01 * np.nanmax(
        np.abs(measured["normal_force"].values))  # the paraboloid's model is another curve: the indenter matters
    with pytest.raises(ValueError, match=r"frees R with profile=PowerLaw\(c=0.1, n=1.0\)"):
        me.fit(measured, "A", 20.0, free=["R", "tau0"], start=start, time_origin="path_start", profile=cone)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_a_good_cone_fit_is_not_warned_of_a_lost_contact(paper, seed):
    """A cone's area and F_x fade out before its small jump-off radius comes off: the data's last sample above
    the noise moves by the fade's duration (5 s at 1 % noise), which is no clock offset (the warning fired on
    every seed)."""
    from mdr_events.contact.indenters import PowerLaw

    cone = PowerLaw.cone(0.1)
    measured = synthetic_measurement(paper, "A", 20.0, times=np.linspace(0.0, 1250.0, 2001), relative_noise=0.01,
                                     seed=seed, profile=cone)
    result = me.fit(measured, "A", 20.0, free=("tau0",), start=paper.replace(tau0=3e4), time_origin="path_start",
                    profile=cone)
    assert result.warnings == []
    estimate = result.estimates["tau0"]  # within 4 standard errors (a 95 % interval misses one seed in 20)
    assert abs(estimate.value - paper.tau0) <= 4 * estimate.standard_error


def test_a_fit_result_round_trips_through_its_file_and_reads_files_written_before(tmp_path):
    """FitResult.from_dataset: the lists of notes and warnings whole (each text its own attribute), the
    identifiability a bool, the parameters and offsets; a file written before (texts joined by '; ') still reads."""
    import os

    from mdr_events.io.datasets import read_text_list, text_list_attrs
    committed = me.open_result(os.path.join(os.path.dirname(__file__), "..", "..", "results", "fit_A20_R30.nc"))
    result = me.FitResult.from_dataset(committed)
    assert result.identifiable is True and result.optimizer is None
    assert result.to_dataset() is committed and result.parameters == me.Parameters.from_attrs(committed.attrs)
    written = committed.copy()
    written.attrs.update({"warnings": "a; b", "notes": "none"})  # (as files were written before)
    for key in [key for key in written.attrs if key.startswith(("warnings_", "notes_"))]:
        del written.attrs[key]
    before = me.FitResult.from_dataset(written)
    assert before.warnings == ["a", "b"] and before.notes == []
    texts = ["the residuals; of F_N are large", "a unit looks wrong"]
    assert read_text_list(text_list_attrs("warnings", texts), "warnings") == texts  # ("; " inside a text kept)
    assert read_text_list(text_list_attrs("warnings", []), "warnings") == []
