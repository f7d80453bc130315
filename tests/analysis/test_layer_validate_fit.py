"""validate and fit on a layer of finite thickness (issue 34): their continuum reference is the layer's (its thickness
fixed), on the command line (``--h``, ``--layer-base``) and in a study's ``[layer]`` too. Before issue 34's continuum
on a layer both refused a finite layer (``check_half_space``).

Tolerances: a continuum run validated against its own reference differs by its samples' evaluation alone (the same
solution's dense output: :data:`SELF_SHARE`); noise-free synthetic data are fitted to the optimizer's tolerance
(``FIT_TOLERANCE = 1e-12`` on the residuals: the estimates to about 1e-6, :data:`RECOVERED`, as on the half-space).
"""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.fit import synthetic_measurement
from mdr_events.app.cli import main

PAPER = me.Contact.paper()
LAYERED = PAPER.replace(h=5e-3)
#: A continuum run against its own reference: both evaluate one solution, to rounding of the quantities' ranges.
SELF_SHARE = 1e-9
#: Noise-free data fitted: the estimates within this of the values that made them (relative).
RECOVERED = 1e-6


def test_validate_takes_the_layers_continuum_as_its_reference():
    own = me.simulate(LAYERED, me.Scenario("A", alpha=[20.0]), "continuum").isel(alpha=0)
    report = me.validate(own, LAYERED, "A", 20.0)
    assert report.attrs["verdict"] == "pass" and report.attrs["param_layer_thickness"] == 5e-3
    assert float(np.max(report["max_error"].values)) <= SELF_SHARE
    half_space = me.simulate(PAPER, me.Scenario("A", alpha=[20.0]), "continuum").isel(alpha=0)
    assert me.validate(half_space, LAYERED, "A", 20.0).attrs["verdict"] == "fail"  # (the layer's reference, not the
    assert "param_layer_thickness" not in me.validate(half_space, PAPER, "A", 20.0).attrs  # half-space's)


def test_the_discrete_springs_on_a_layer_pass_validate_within_their_first_order_error():
    springs = me.simulate(LAYERED, me.Scenario("B", alpha=[30.0]), "discrete", dx=2e-6).isel(alpha=0)
    report = me.validate(springs, LAYERED, "B", 30.0)
    assert report.attrs["verdict"] == "pass", report.attrs.get("failures_0")


def path_times(samples: int) -> np.ndarray:
    """``samples`` times over scenario A's path at 15° (s on the path's clock)."""
    params = LAYERED.parameters(me.Parameters.paper().d_max, me.Parameters.paper().v)
    path = me.Scenario("A", alpha=[15.0]).cases(params, None, LAYERED.friction).paths[0]
    return np.linspace(0.0, path.duration, samples)


def test_fit_recovers_the_modulus_and_tau0_on_a_layer_of_fixed_thickness():
    times = path_times(300)
    measured = synthetic_measurement(LAYERED, "A", 15.0, times=times)
    start = LAYERED.replace(E=0.8 * PAPER.elastomer.E, tau0=1.3 * PAPER.friction.tau0)
    result = me.fit(measured, start, "A", 15.0, free=["E", "tau0"], time_origin="path_start")
    assert result.parameters.E == pytest.approx(PAPER.elastomer.E, rel=RECOVERED)
    assert result.parameters.tau0 == pytest.approx(PAPER.friction.tau0, rel=RECOVERED)
    assert result.dataset.attrs["param_layer_thickness"] == 5e-3


def test_fit_refuses_nu_free_on_a_layer_in_one_line():
    measured = synthetic_measurement(LAYERED, "A", 15.0, times=path_times(50))
    with pytest.raises(ValueError) as caught:
        me.fit(measured, LAYERED, "A", 15.0, free=["E", "nu"], time_origin="path_start")
    text = str(caught.value)
    assert "frees nu on layer h = 0.005 m, bonded base" in text and "allowed:" in text and "\n" not in text


def test_the_command_line_validates_on_the_layer_of_h(capsys, tmp_path, without_drawing):
    run = me.simulate(LAYERED, me.Scenario("A", alpha=[20.0]), "continuum").isel(alpha=0)
    candidate = tmp_path / "candidate.nc"
    me.write_netcdf(run, candidate)
    common = ["validate", str(candidate), "--scenario", "A", "--alpha", "20"]
    assert main([*common, "--h", "5e-3", "--out", str(tmp_path / "layer")]) == 0
    assert "1 pass, 0 fail" in capsys.readouterr().out
    assert me.open_result(tmp_path / "layer" / "candidate.nc").attrs["param_layer_thickness"] == 5e-3
    assert main([*common, "--out", str(tmp_path / "half")]) == 1  # (the half-space's reference)


def test_fit_recovers_the_layers_thickness_where_h_is_free():
    """``h`` free: each trial the same tables at another ``a/h`` (no table built), the fitted thickness stamped."""
    measured = synthetic_measurement(LAYERED, "A", 15.0, times=path_times(300))
    start = LAYERED.replace(h=8e-3, E=0.9 * PAPER.elastomer.E)
    result = me.fit(measured, start, "A", 15.0, free=["E", "h"], time_origin="path_start")
    estimates = dict(zip(result.dataset["parameter"].values, result.dataset["estimate"].values))
    assert estimates["h"] == pytest.approx(5e-3, rel=RECOVERED)
    assert result.parameters.E == pytest.approx(PAPER.elastomer.E, rel=RECOVERED)
    assert result.dataset.attrs["param_layer_thickness"] == pytest.approx(5e-3, rel=RECOVERED)


def test_h_free_on_the_half_space_is_refused_in_one_line():
    measured = synthetic_measurement(PAPER, "A", 15.0, times=path_times(50))
    with pytest.raises(ValueError) as caught:
        me.fit(measured, PAPER, "A", 15.0, free=["E", "h"], time_origin="path_start")
    assert "free: 'h' is not allowed on the half-space" in str(caught.value) and "\n" not in str(caught.value)
