"""Everything downstream takes Coulomb's law with adhesion (the compressed zone, models.continuum.caps) and Coulomb's
part on the flat punch (one play operator of the face): validate, convergence_study, fit with μ free, sweep, and a
tabulated profile."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.fit import synthetic_measurement
from mdr_events.contact.friction import FrictionLaw
from mdr_events.theory import mindlin

COULOMB = FrictionLaw("coulomb", mu=0.3)
COMBINED = FrictionLaw("tau0+coulomb", mu=0.3)
DEPTH = 1e-4
PUNCH = me.FlatPunch(1.5e-3)


@pytest.fixture(scope="module")
def paper():
    return me.Parameters.paper()


@pytest.fixture(scope="module")
def fretting(paper):
    """From the surface in to DEPTH with the paper's adhesion (Δγ0 < Δγ1), a Mindlin loop at ±0.6 of the full-slip
    shift, out to −2 µm (the compressed zone gone, the adhesive contact held) and back in to DEPTH: whole µm, whole
    seconds. (It starts at the surface: synthetic_measurement's times count from the path's start, the fit's model
    from first contact, which differ for a path starting above the surface.)"""
    X = round(0.6 * mindlin.full_slip_shift(DEPTH, COULOMB, paper) * 1e6) * 1e-6
    return me.Path(np.array([(0.0, 0.0), (0.0, DEPTH), (X, DEPTH), (-X, DEPTH), (0.0, DEPTH), (0.0, -2e-6),
                             (0.0, DEPTH)]), speed=1e-6)


def test_an_adhesive_coulomb_simulator_converges_and_validates(paper, fretting):
    """The springs with Coulomb's law and the paper's adhesion at three spacings: convergence_study finds first order
    in F_x and names the law; the finest run passes validate with every event compared (its sliding fraction counts
    the tensile annulus, zero cap, as sliding, and so does the exact log: slip onset at first contact, full slip where
    the path leaves the compressed zone at -2 µm), and fails against the law without Coulomb's part."""
    runs = {dx: me.simulate(paper, fretting, dx=dx, dt=0.25 * dx / fretting.speed, friction=COULOMB).isel(case=0)
            for dx in (4e-6, 2e-6, 1e-6)}
    study = me.convergence_study(runs, paper, fretting, friction=COULOMB)
    assert study.attrs["verdict"] == "converges" and study.attrs["friction_law"] == "coulomb"
    assert float(study["max_error_order"].sel(quantity="tangential_force")) > 0.8
    report = me.validate(runs[1e-6], paper, fretting, friction=COULOMB)
    assert report.attrs["verdict"] == "pass" and report.attrs["friction_mu"] == 0.3
    assert report.attrs["events_not_compared"] == "none"
    exact = dict(zip(report["event"].values, report["event_time_exact"].values))
    assert exact["slip_onset"] == 0.0 and exact["full_slip"] > 0.0
    assert me.validate(runs[1e-6], paper, fretting).attrs["verdict"] == "fail"


def test_a_flat_punch_simulator_with_both_laws_validates(paper):
    """The springs on the flat punch (Δx tiles the face) with either law and adhesion pass validate against the
    continuum (the combined law's slip events too: its tensile springs keep K a); against the other law they fail.
    The path slides: ±100 µm at DEPTH, beyond both laws' caps (45 µm and 45 µm + K a), then out to −2 µm and in."""
    fretting = me.Path(np.array([(0.0, 0.0), (0.0, DEPTH), (100e-6, DEPTH), (-100e-6, DEPTH), (0.0, DEPTH),
                                 (0.0, -2e-6), (0.0, DEPTH)]), speed=1e-6)
    for friction, other in ((COULOMB, COMBINED), (COMBINED, COULOMB)):
        run = me.simulate(paper, fretting, dx=2e-6, dt=0.5, profile=PUNCH, friction=friction).isel(case=0)
        assert me.validate(run, paper, fretting, profile=PUNCH, friction=friction).attrs["verdict"] == "pass"
        assert me.validate(run, paper, fretting, profile=PUNCH, friction=other).attrs["verdict"] == "fail"


def test_a_fit_finds_mu_with_adhesion(paper, fretting):
    """μ free (with E), Coulomb's law with the paper's adhesion: from curves of μ = 0.3 with 1 % noise, started at
    0.45 and 30 % off in E, both within their 95 % intervals and to 1 %."""
    times = np.linspace(0.0, fretting.duration - fretting.first_contact_time(), 401)
    measured = synthetic_measurement(paper, fretting, times=times, relative_noise=0.01, seed=0, friction=COULOMB)
    result = me.fit(measured, fretting, free=["E", "mu"], start=paper.replace(E=1.3 * paper.E),
                    friction=FrictionLaw("coulomb", mu=0.45))
    for name, truth in (("E", paper.E), ("mu", 0.3)):
        estimate = result.estimates[name]
        assert estimate.lower <= truth <= estimate.upper and abs(estimate.value / truth - 1) < 0.01, (name, estimate)


def test_a_sweep_takes_coulomb_with_adhesion(paper):
    """The continuum sweep of Coulomb's law over Δγ0 with adhesion: at 10° (below the angle of friction) every
    compressed spring slides from first contact, so the largest F_x is μ F_N^H(d_max), free of Δγ (the compressed
    zone's push); on the flat punch the combined law's largest F_x is τ0 π a² + μ 2E* a d_max."""
    result = me.sweep({"dgamma0": [0.01, 0.05]}, "A", alpha=10.0, base=paper, friction=COULOMB, scheduler="serial",
                      quantities=["tangential_force_max"])
    assert int(result.attrs["failed_runs"]) == 0
    hertz_force = 4.0 / 3.0 * paper.E_star * paper.R**0.5 * paper.d_max**1.5
    np.testing.assert_allclose(result["tangential_force_max"].values, 0.3 * hertz_force, rtol=1e-9)
    punch = me.sweep({"dgamma0": [0.01, 0.05]}, "A", alpha=10.0, base=paper, friction=COMBINED, scheduler="serial",
                     quantities=["tangential_force_max"], profile=PUNCH)
    full = paper.tau0 * np.pi * PUNCH.radius**2 + 0.3 * 2 * paper.E_star * PUNCH.radius * paper.d_max
    np.testing.assert_allclose(punch["tangential_force_max"].values, full, rtol=1e-9)


def test_a_table_takes_coulomb_with_adhesion(paper):
    """A table of the paraboloid (401 points) with Coulomb's law and the paper's adhesion: the continuum's F_x along
    scenario B at 30° is the paraboloid's to the table's interpolation error (1e-4 of the largest force)."""
    r = np.linspace(0.0, 4e-3, 401)
    table = me.TabulatedProfile(r, r**2 / (2 * paper.R))
    exact = me.simulate(paper, "B", alpha=[30.0], method="continuum", friction=COULOMB)
    tabulated = me.simulate(paper, "B", alpha=[30.0], method="continuum", friction=COULOMB, profile=table,
                            t=exact["time"].values)
    force, reference = tabulated["tangential_force"].values[0], exact["tangential_force"].values[0]
    both = np.isfinite(force) & np.isfinite(reference)
    assert np.count_nonzero(both) > 1000
    np.testing.assert_allclose(force[both], reference[both], rtol=0, atol=1e-4 * np.nanmax(np.abs(reference)))


def test_both_parts_with_adhesion_converge_validate_and_fit(paper):
    """``"tau0+coulomb"`` with the paper's adhesion on the paraboloid (the continuum's two regions), τ0 = 1 kPa (K a
    about a quarter of κ d) and a Mindlin loop at ±0.8 of the full slip shift: the springs at four spacings converge at
    first order and name the law, the finest passes validate with every event compared and fails against Coulomb's law
    alone; a fit of E and μ from curves of μ = 0.3 with 1 % noise, started 30 % off in E and at μ = 0.45, finds both
    within their 95 % intervals and to 1 %."""
    paper = paper.replace(tau0=1e3)
    X = round(0.8 * mindlin.full_slip_shift(DEPTH, COMBINED, paper) * 1e6) * 1e-6
    fretting = me.Path(np.array([(0.0, 0.0), (0.0, DEPTH), (X, DEPTH), (-X, DEPTH), (0.0, DEPTH), (0.0, -2e-6),
                                 (0.0, DEPTH)]), speed=1e-6)
    runs = {dx: me.simulate(paper, fretting, dx=dx, dt=0.25 * dx / fretting.speed, friction=COMBINED).isel(case=0)
            for dx in (4e-6, 2e-6, 1e-6, 0.5e-6)}  # (four: the pinned radius lies as far between springs at 2, 1 µm)
    study = me.convergence_study(runs, paper, fretting, friction=COMBINED)
    assert study.attrs["verdict"] == "converges" and study.attrs["friction_law"] == "tau0+coulomb"
    assert float(study["max_error_order"].sel(quantity="tangential_force")) > 0.8
    report = me.validate(runs[0.5e-6], paper, fretting, friction=COMBINED)
    assert report.attrs["verdict"] == "pass" and report.attrs["events_not_compared"] == "none"
    assert me.validate(runs[0.5e-6], paper, fretting, friction=COULOMB).attrs["verdict"] == "fail"
    times = np.linspace(0.0, fretting.duration - fretting.first_contact_time(), 401)
    measured = synthetic_measurement(paper, fretting, times=times, relative_noise=0.01, seed=0, friction=COMBINED)
    result = me.fit(measured, fretting, free=["E", "mu"], start=paper.replace(E=1.3 * paper.E),
                    friction=FrictionLaw("tau0+coulomb", mu=0.45))
    for name, truth in (("E", paper.E), ("mu", 0.3)):
        estimate = result.estimates[name]
        assert estimate.lower <= truth <= estimate.upper and abs(estimate.value / truth - 1) < 0.01, (name, estimate)
