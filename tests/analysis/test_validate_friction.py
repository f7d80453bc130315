"""validate and convergence_study with a friction law: the door for a simulator with Coulomb friction (e.g. a DEM
contact model's Mindlin tangential model) under Cattaneo–Mindlin loading."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.analysis.fit import synthetic_measurement
from mdr_events.models.continuum import solve_path
from mdr_events.theory import mindlin

COULOMB = FrictionLaw("coulomb", mu=0.3)
DEPTH = 1e-4


@pytest.fixture(scope="module")
def hertz():
    return me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)


@pytest.fixture(scope="module")
def fretting(hertz):
    """In to DEPTH, then a Mindlin loop at ±0.6 of the full-slip shift and out again."""
    X = mindlin.full_slip_shift(DEPTH, COULOMB, hertz)
    return me.Path(np.array([(0.0, 0.0), (0.0, DEPTH), (0.6 * X, DEPTH), (-0.6 * X, DEPTH), (0.0, DEPTH),
                             (0.0, 0.0)]), speed=1e-6)


def test_a_coulomb_simulator_converges_to_the_exact_reference(hertz, fretting):
    """The spring model with Coulomb's law at three spacings: convergence_study finds first order and names the
    law; each report passes; against the paper's law the same runs fail."""
    runs = {dx: me.simulate(hertz, fretting, dx=dx, dt=0.25 * dx / fretting.speed, friction=COULOMB).isel(case=0)
            for dx in (4e-6, 2e-6, 1e-6)}
    study = me.convergence_study(runs, hertz, fretting, friction=COULOMB)
    assert study.attrs["verdict"] == "converges" and study.attrs["friction_law"] == "coulomb"
    order = float(study["max_error_order"].sel(quantity="tangential_force"))
    assert order > 0.8
    report = me.validate(runs[1e-6], hertz, fretting, friction=COULOMB)
    assert report.attrs["verdict"] == "pass" and report.attrs["friction_mu"] == 0.3
    assert me.validate(runs[1e-6], hertz, fretting).attrs["verdict"] == "fail"


def test_a_solution_of_another_law_is_refused(hertz, fretting):
    solution = solve_path(hertz, fretting)
    with pytest.raises(ValueError, match=r"solution= was solved for friction=FrictionLaw\('tau0'\)"):
        me.validate({"time": [0.0, 1.0], "normal_force": [0.0, 1.0]}, hertz, fretting, solution=solution,
                    friction=COULOMB)


def test_a_sweep_takes_a_friction_law(hertz):
    """sweep(..., friction=): each run is the law's. Coulomb's law at 10° (below the angle of friction) slides from
    first contact, so the largest F_x is μ F_N at d_max (Hertz's F_N: the closed form, for each E); the combined law's
    critical angle of scenario A is mindlin's; the law is named; a set with adhesion runs as its own simulation."""
    result = me.sweep({"E": [2e5, 6e5]}, "A", alpha=10.0, base=hertz, friction=COULOMB, scheduler="serial",
                      quantities=["tangential_force_max"])
    assert result.attrs["friction_law"] == "coulomb"
    for E in (2e5, 6e5):
        params = hertz.replace(E=E)
        hertz_force = 4.0 / 3.0 * params.E_star * params.R**0.5 * params.d_max**1.5
        assert float(result["tangential_force_max"].sel(E=E)) == pytest.approx(0.3 * hertz_force, rel=1e-9)
    combined = FrictionLaw("tau0+coulomb", mu=0.2)
    angles = me.sweep({"tau0": [1e3, 4e3]}, "A", alpha=10.0, base=hertz, friction=combined, scheduler="serial",
                      quantities=["critical_angle_A"])
    for tau0 in (1e3, 4e3):
        assert float(angles["critical_angle_A"].sel(tau0=tau0)) == mindlin.critical_angle_A(combined,
                                                                                           hertz.replace(tau0=tau0))
    # with adhesion too (the compressed zone and the tensile annulus of the continuum): each set its own run's
    swept = me.sweep({"dgamma0": [0.0, 0.01]}, "A", alpha=10.0, base=hertz, friction=combined, scheduler="serial",
                     quantities=["tangential_force_max"])
    for dgamma0 in (0.0, 0.01):
        run = me.simulate(hertz.replace(dgamma0=dgamma0), "A", alpha=[10.0], method="continuum", friction=combined)
        assert float(swept["tangential_force_max"].sel(dgamma0=dgamma0)) == float(run["tangential_force_max"][0])


def test_a_fit_with_coulombs_law_recovers_the_modulus(hertz, fretting):
    """Synthetic measurements of the Cattaneo–Mindlin path with Coulomb's law (1 % noise); a fit of E from 30 % off,
    with the law fixed, finds it within its 95 % interval; the files name the law."""
    times = np.linspace(0.0, fretting.duration - fretting.first_contact_time(), 401)
    measured = synthetic_measurement(hertz, fretting, times=times, relative_noise=0.01, seed=0,
                                                     friction=COULOMB)
    assert measured.attrs["friction_law"] == "coulomb"
    result = me.fit(measured, fretting, free=["E"], start=hertz.replace(E=1.3 * hertz.E), friction=COULOMB)
    estimate = result.estimates["E"]
    assert estimate.lower <= hertz.E <= estimate.upper and abs(estimate.value / hertz.E - 1) < 0.01
    assert result.dataset.attrs["friction_law"] == "coulomb"


def test_a_sweep_that_takes_the_adhesion_away_runs_coulombs_law():
    """The base set has adhesion, but every swept set has none: the continuum sweep of Coulomb's law runs."""
    result = me.sweep({"dgamma0": [0.0], "dgamma1": [0.0], "E": [3e5, 4e5]}, "A", alpha=10.0,
                      base=me.Parameters.paper(), friction=COULOMB, scheduler="serial",
                      quantities=["tangential_force_max"])
    assert int(result.attrs["failed_runs"]) == 0 and np.all(result["tangential_force_max"].values > 0)


def test_a_fit_finds_the_coefficient_of_friction(hertz, fretting):
    """μ free (with E): from curves of μ = 0.3 with 1 % noise, started at 0.45 and 30 % off in E, the fit finds both
    within their 95 % intervals and to 1 %; the result names the fitted law. 'mu' with the paper's law is refused."""
    times = np.linspace(0.0, fretting.duration - fretting.first_contact_time(), 401)
    measured = synthetic_measurement(hertz, fretting, times=times, relative_noise=0.01, seed=0, friction=COULOMB)
    result = me.fit(measured, fretting, free=["E", "mu"], start=hertz.replace(E=1.3 * hertz.E),
                    friction=FrictionLaw("coulomb", mu=0.45))
    for name, truth in (("E", hertz.E), ("mu", 0.3)):
        estimate = result.estimates[name]
        assert estimate.lower <= truth <= estimate.upper and abs(estimate.value / truth - 1) < 0.01, (name, estimate)
    assert result.dataset.attrs["friction_mu"] == pytest.approx(result.estimates["mu"].value, rel=1e-15)
    with pytest.raises(ValueError, match=r"free: 'mu' is not allowed with the friction law 'tau0'"):
        me.fit(measured, fretting, free=["mu"], start=hertz)


def test_validate_takes_a_simulation_of_one_case(hertz, fretting):
    """A simulate() result of one case (dims case × time) is that case's run; one of several cases is refused, naming
    the dimension and how to select."""
    run = me.simulate(hertz, fretting, dx=2e-6, friction=COULOMB)
    whole, selected = (me.validate(candidate, hertz, fretting, friction=COULOMB) for candidate in (run, run.isel(case=0)))
    np.testing.assert_array_equal(whole["max_error"].values, selected["max_error"].values)
    two = me.simulate(hertz, {"a": fretting, "b": fretting}, dx=2e-6, friction=COULOMB)
    with pytest.raises(ValueError, match=r"holds several runs along 'case' \(2\); allowed: one run"):
        me.validate(two, hertz, fretting, friction=COULOMB)
