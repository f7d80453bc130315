"""Hostile round thirty (issue 32), the statistical referees: the convergence study's verdict must be earned.

Class found: an error that stops falling at the finest spacing was reported ``converges`` (five spacings whose last
error equals the one before: the least-squares order over all of them, 0.80 ± 0.12, passed ``order − 2·spread ≥
0.5``). The rule now also asks the slope through the two finest usable spacings (``*_finest_order``) to reach
``CONVERGES_SHARE · expected_order``. The candidates here are the exact continuum scaled by ``1 + K·Δx``: each
quantity's error is then exactly proportional to ``Δx`` (first order), and any spacing may be given another's run.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence_study import CONVERGES_SHARE, NORMS, convergence_study, fit_observed_order

ALPHA = 20.0
QUANTITIES = ("normal_force", "tangential_force", "contact_area")
#: The candidate's relative error per metre of spacing: 1 % at Δx = 10 µm (a spring model's size of error).
ERROR_PER_METRE = 1e3
#: The spacings of a study, coarsest first (m): factors of two, as a user refines.
SPACINGS = (32e-6, 16e-6, 8e-6, 4e-6, 2e-6, 1e-6)
#: The slope through two exact points is exact up to the rounding of two logarithms.
SLOPE_ROUNDING = 1e-9


@pytest.fixture(scope="module")
def exact():
    run = me.simulate(me.Contact.paper(), me.Scenario("A", alpha=[ALPHA]), "continuum").sel(alpha=ALPHA)
    return {"time": run["time"].values, **{name: run[name].values for name in QUANTITIES}}


def _candidate(exact, dx: float) -> dict:
    """The exact curves with a relative error ``ERROR_PER_METRE · dx``: first order in ``dx``, contact unchanged."""
    return {"time": exact["time"], **{name: exact[name] * (1.0 + ERROR_PER_METRE * dx) for name in QUANTITIES}}


def _study(exact, errors_at: list[float]):
    """A study over :data:`SPACINGS` (as many as ``errors_at``), spacing i given the run of spacing ``errors_at[i]``."""
    spacings = SPACINGS[:len(errors_at)]
    return convergence_study({dx: _candidate(exact, at) for dx, at in zip(spacings, errors_at)},
                             me.Contact.paper(), "A", ALPHA)


def test_first_order_errors_converge_with_finest_order_one(exact):
    study = _study(exact, list(SPACINGS[:5]))
    assert study.attrs["verdict"] == "converges"
    for norm in NORMS:
        np.testing.assert_allclose(study[f"{norm}_finest_order"].values, 1.0, atol=1e-6)
        assert np.all(study[f"{norm}_converges"].values == 1), norm


@pytest.mark.parametrize("errors_at", [
    # five spacings, the finest run the same as the one before (its error does not fall): order 0.80 ± 0.12 passed
    [32e-6, 16e-6, 8e-6, 4e-6, 4e-6],
    # six spacings, the same
    [32e-6, 16e-6, 8e-6, 4e-6, 2e-6, 2e-6],
    # six spacings, the finest error twice the one before (it rose)
    [32e-6, 16e-6, 8e-6, 4e-6, 2e-6, 4e-6],
    # the error falls by only 10 % at the finest halving (a local order of 0.15)
    [32e-6, 16e-6, 8e-6, 4e-6, 2e-6, 1.8e-6],
], ids=["5-flat", "6-flat", "6-rises", "6-stalls"])
def test_an_error_that_stops_falling_at_the_finest_spacing_does_not_converge(exact, errors_at):
    study = _study(exact, errors_at)
    assert study.attrs["verdict"] == "does not converge", study.attrs["verdict"]
    for norm in NORMS:
        assert np.all(study[f"{norm}_converges"].values == 0), norm
        finest = math.log(errors_at[-1] / errors_at[-2]) / math.log(SPACINGS[len(errors_at) - 1]
                                                                     / SPACINGS[len(errors_at) - 2])
        np.testing.assert_allclose(study[f"{norm}_finest_order"].values, finest, atol=1e-6)
    assert "finest order" in study.attrs["converges_rule"]


def test_the_coarse_spacings_outside_the_asymptotic_range_still_converge(exact):
    """The coarsest step flat (not yet asymptotic), the finest ones first order: converges (the finest step decides
    beside the overall order, not every step)."""
    study = _study(exact, [16e-6, 16e-6, 8e-6, 4e-6, 2e-6])
    assert study.attrs["verdict"] == "converges"


def test_the_finest_order_is_the_slope_through_the_two_finest_usable_spacings():
    fit = fit_observed_order([4.0, 2.0, 1.0, 0.5], [8.0, 4.0, 2.0, 2.0])
    assert abs(fit.finest_order) < SLOPE_ROUNDING and fit.order > CONVERGES_SHARE
    # a 0 or nan error is left out: the finest usable pair is the next one
    fit = fit_observed_order([4.0, 2.0, 1.0, 0.5], [8.0, 4.0, 2.0, 0.0])
    assert abs(fit.finest_order - 1.0) < SLOPE_ROUNDING
    fit = fit_observed_order([0.5, 4.0, 1.0, 2.0], [math.nan, 16.0, 1.0, 4.0])  # any order of the spacings
    assert abs(fit.finest_order - 2.0) < SLOPE_ROUNDING
    assert math.isnan(fit_observed_order([1.0, 2.0, 4.0], [math.nan, 0.0, 5.0]).finest_order)
    # a repeated spacing: its errors averaged in log (no division by a zero step)
    fit = fit_observed_order([1.0, 1.0, 2.0], [1.0, 4.0, 8.0])
    assert abs(fit.finest_order - 2.0) < SLOPE_ROUNDING


# ----------------------------------------------------------------------------------------------------------------------
# fit: the contact-loss warning on data of the right model at the right clock
#
# Class found: the warning "the data lose contact at ..., the fit at ...: free time_offset or give time_origin" fired
# on synthetic data of the fit's own model, on the right clock: in 2 of 12 seeds at 10 % noise (E, Δγ1 free; the
# threshold of 5σ lies at half the curves' largest values, which the fit never exceeds three times: its fade counted
# 0) and in 2 of 8 at 1 % (E, R from F_N alone, whose pull-off force sits at the threshold for the last 100 s, the
# data's crossing after the fit's). The fade is now the time the fit spends between FADE_MULTIPLE thresholds and one
# over FADE_MULTIPLE (its whole contact where it never reaches the upper one). A clock 5 % off still warns.

#: The relative noise at which the fade of 0 showed, and the seeds that warned on eff932a (of 0..11).
HIGH_NOISE, HIGH_NOISE_SEEDS = 0.10, (2, 5)
#: The seeds (of 0..7) whose F_N alone at 1 % noise warned on eff932a.
PULL_OFF_SEEDS = (2, 5)
#: The samples of those records (uniform over the path).
RECORD_SAMPLES = 120
#: A clock off by this share of the path's duration: the warning must stay (eff932a and now: 3 of 3 seeds).
CLOCK_OFF_SHARE = 0.05


def _record(rel: float, seed: int, quantities=QUANTITIES, samples: int = RECORD_SAMPLES, shift_share: float = 0.0):
    from mdr_events.analysis.fit import synthetic_measurement
    from mdr_events.analysis.validate import resolve_path
    duration = resolve_path(me.Contact.paper(), "A", ALPHA).duration
    return synthetic_measurement(me.Contact.paper(), "A", ALPHA, times=np.linspace(0.0, duration, samples),
                                 relative_noise=rel, seed=seed, quantities=quantities,
                                 time_shift=shift_share * duration)


def _loses_contact(result) -> bool:
    return any("lose contact" in warning for warning in result.warnings)


@pytest.mark.parametrize("seed", HIGH_NOISE_SEEDS)
def test_ten_percent_noise_of_the_right_model_does_not_blame_the_clock(seed):
    result = me.fit(_record(HIGH_NOISE, seed), me.Contact.paper(), "A", ALPHA, free=["dgamma1", "E"],
                    time_origin="path_start")
    assert not _loses_contact(result), result.warnings
    assert not result.warnings, result.warnings  # (the residuals at the noise: nothing else to say either)


@pytest.mark.parametrize("seed", PULL_OFF_SEEDS)
def test_a_pull_off_force_at_the_contact_threshold_does_not_blame_the_clock(seed):
    """E and R from F_N alone at 1 % noise (given)."""
    record = _record(0.01, seed, quantities=("normal_force",), samples=150)
    clean = _record(0.0, 0, quantities=("normal_force",), samples=150)
    noise = {"normal_force": 0.01 * float(np.max(np.abs(clean["normal_force"].values)))}
    result = me.fit(record, me.Contact.paper(), "A", ALPHA, free=["E", "R"], noise=noise, time_origin="path_start")
    assert not _loses_contact(result), result.warnings


def test_a_clock_five_percent_off_still_warns():
    result = me.fit(_record(0.01, 0, samples=150, shift_share=CLOCK_OFF_SHARE), me.Contact.paper(), "A", ALPHA,
                    free=["dgamma1"], time_origin="path_start")
    assert _loses_contact(result), result.warnings


# ----------------------------------------------------------------------------------------------------------------------
# fit: an interval within the bounds the fit holds its parameter in
#
# Class found: ν fitted at its bound 0.5 (the paper's elastomer) was reported within [0.4958, 0.5042], an upper end no
# elastomer has; a Δγ1 held within bounds=(0.14, 0.16) reached beyond them. The linearised interval is now cut to the
# bounds (the truth lies within them, so the coverage, 37–40 of 40 at 95 % in /tmp/h129w/cov.py, can only grow).

#: The relative noise of those records: 1 % of each quantity's largest value.
LOW_NOISE = 0.01


def test_nu_at_its_bound_has_no_interval_above_a_half():
    result = me.fit(_record(LOW_NOISE, 0), me.Contact.paper(), "A", ALPHA, free=["E", "nu"], time_origin="path_start")
    nu = result.estimates["nu"]
    assert nu.upper <= 0.5 and nu.lower <= nu.value <= nu.upper, nu
    assert float(result.dataset["upper_95"].sel(parameter="nu")) <= 0.5


def test_an_interval_stays_within_the_bounds_given():
    bounds = {"dgamma1": (0.149, 0.151)}  # (narrower than the data's interval, ±0.003 at 1 % noise)
    result = me.fit(_record(LOW_NOISE, 0), me.Contact.paper(), "A", ALPHA, free=["dgamma1"], bounds=bounds,
                    time_origin="path_start")
    estimate = result.estimates["dgamma1"]
    assert bounds["dgamma1"][0] <= estimate.lower <= estimate.value <= estimate.upper <= bounds["dgamma1"][1], estimate


def test_nu_the_data_do_not_see_spans_its_bounds_not_the_real_line():
    """E and ν from F_N and A alone: they see E* = E/(1−ν²) only, so ν is not determined; its interval is the whole of
    (−1, 0.5], not the real line."""
    result = me.fit(_record(LOW_NOISE, 0, quantities=("normal_force", "contact_area")), me.Contact.paper(), "A",
                    ALPHA, free=["E", "nu"], time_origin="path_start")
    nu = result.estimates["nu"]
    assert nu.identifiability is not me.analysis.fit.Identifiability.DETERMINED
    from mdr_events.analysis.fit_parameters import NU_MARGIN
    assert nu.lower == pytest.approx(-1.0, abs=NU_MARGIN) and nu.upper == 0.5, nu  # (ν > −1 by NU_MARGIN)
