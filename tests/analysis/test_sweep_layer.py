"""``sweep`` on a layer of finite thickness (issue 34, item 4): the thickness ``h`` as an axis (``inf`` the
half-space), the discrete method's runs and the closed-form angles of each run's contact, what is refused, the store;
and the universal map's layer group ``λ = √(R d_max)/h``."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.samples import sliding
from mdr_events.analysis.sweep import CLOSED_FORM_QUANTITIES, _signature, sweep_job
from mdr_events.analysis.universal_map import thickness_of_thinness, universal_map
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.analytic import dimensionless_groups

PAPER = me.Contact.paper()
LAYERED = PAPER.replace(h=5e-3)
#: Coulomb's part with the paper's adhesion (simulate's continuum and a continuum sweep run it on a layer spring by
#: spring).
COULOMB = dataclasses.replace(PAPER, friction=me.FrictionLaw("tau0+coulomb", tau0=PAPER.friction.tau0, mu=0.3))
SERIAL = me.Engine(scheduler="serial")
#: The discrete springs, coarse enough for seconds per run (the sweep and simulate take the same method).
SPRINGS = me.Discrete(dx=5e-5, n_steps=1000)
#: Quantities read off the springs' samples, each a plain reduction of simulate's arrays.
SAMPLED = ("tangential_force_max", "normal_force_min", "contact_area_max", "slip_onset_in_depth", "pull_off_depth")
THICKNESSES = [2e-3, 5e-3, math.inf]

#: Scenario A's angle on a layer is atan of the travel per cap at the radius of d_max, found by bisection in ln a to
#: round-off (:mod:`mdr_events.theory.layer.slip_onset`); two sets of equal groups evaluate the tables at equal
#: a/h and ν: equal to a few ulps (2.8e-15 measured), here within 1e-12.
SCENARIO_A_UNIVERSAL = 1e-12
#: Scenario B's angle is read at the jump-off, a minimum of the depth along the branch found by Brent's method: its
#: abscissa is determined to about √ε ≈ 1.5e-8 (the depth is flat there), and the travel per cap, whose logarithmic
#: slope in a is O(1) there, moves the angle by as much (1.1e-8 measured); 1e-7 is that bound with a margin.
SCENARIO_B_UNIVERSAL = 1e-7


def _angles(contact: me.Contact, scenario: str, d_max: float) -> float:
    return me.critical_angle(contact, scenario, d_max=d_max)


def test_a_discrete_sweep_over_the_thickness_is_the_simulate_runs_one_by_one():
    """Each cell is simulate of the contact at that thickness and angle, bit for bit (its extrema, its first
    sliding sample, its last sample in contact, its history); h = inf is the half-space."""
    swept = me.sweep({"h": THICKNESSES, "alpha": [20.0, 40.0]}, PAPER, "A", method=SPRINGS, engine=SERIAL,
                     quantities=SAMPLED, history_samples=7)
    assert int(swept["failed"].sum()) == 0 and swept["h"].attrs["units"] == "m"
    assert swept.attrs["param_layer_base"] == "bonded" and swept.attrs["param_layer_thickness"] == math.inf
    for h in THICKNESSES:
        for alpha in (20.0, 40.0):
            run = me.simulate(PAPER.replace(h=h), me.Scenario("A", alpha), SPRINGS).isel(alpha=0)
            cell = swept.sel(h=h, alpha=alpha)
            assert float(cell["tangential_force_max"]) == float(np.nanmax(np.abs(run["tangential_force"].values)))
            assert float(cell["normal_force_min"]) == float(np.nanmin(run["normal_force"].values))
            assert float(cell["contact_area_max"]) == float(np.nanmax(run["contact_area"].values))
            depth = run["indentation_depth"].values
            touching = np.nan_to_num(run["contact_area"].values) > 0
            assert float(cell["pull_off_depth"]) == float(depth[np.flatnonzero(touching[:-1] & ~touching[1:])[0] + 1])
            path = me.Path.scenario_A(alpha, PAPER.parameters(PAPER_D_MAX, PAPER_V))
            times = run["time"].values + path.first_contact_time()  # (simulate's time: from first contact)
            going_in = times <= path.corner_times[1]  # (scenario A: in to d_max, then out)
            slides = np.flatnonzero(sliding(run["sliding_fraction"].values).partly & going_in)
            np.testing.assert_array_equal(float(cell["slip_onset_in_depth"]),
                                          float(depth[slides[0]]) if slides.size else math.nan)
            history = np.interp(np.linspace(0.0, path.duration, 7), times,
                                np.nan_to_num(run["tangential_force"].values), left=0.0, right=math.nan)
            np.testing.assert_array_equal(cell["history_tangential_force"].values, history)
    # (the layer matters: a thinner layer is stiffer, its tangential force larger at the same angle)
    assert float(swept["tangential_force_max"].sel(h=2e-3, alpha=40.0)) > \
        float(swept["tangential_force_max"].sel(h=math.inf, alpha=40.0))


def test_a_discrete_sweep_of_a_contact_on_a_layer_stamps_the_layer():
    swept = me.sweep({"alpha": [30.0]}, LAYERED, "A", method=SPRINGS, engine=SERIAL, quantities=SAMPLED)
    run = me.simulate(LAYERED, me.Scenario("A", 30.0), SPRINGS)
    assert {key: swept.attrs[key] for key in ("param_layer_thickness", "param_layer_base")} == \
        {key: run.attrs[key] for key in ("param_layer_thickness", "param_layer_base")}
    assert me.Contact.from_attrs(swept.attrs) == LAYERED
    assert float(swept["normal_force_min"][0]) == float(np.nanmin(run["normal_force"].values))


def test_the_closed_form_quantities_over_the_thickness_are_critical_angle_of_each_runs_contact():
    """Any method: critical_angle(contact.replace(h=...)) at the run's d_max, bit for bit; inf: the half-space's
    closed forms as before layers."""
    grid = {"h": [1e-3, 2e-3, 5e-3, 2e-2, math.inf], "tau0": [30e3, 42e3], "d_max": [0.2e-3, 0.3e-3]}
    swept = me.sweep(grid, PAPER, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES)
    assert int(swept["failed"].sum()) == 0
    for h in grid["h"]:
        for tau0 in grid["tau0"]:
            for d_max in grid["d_max"]:
                contact = PAPER.replace(h=h, tau0=tau0)
                for scenario in ("A", "B"):
                    assert float(swept[f"critical_angle_{scenario}"].sel(h=h, tau0=tau0, d_max=d_max)) == \
                        _angles(contact, scenario, d_max)
    half_space = me.sweep({"tau0": grid["tau0"], "d_max": grid["d_max"]}, PAPER, "A", 20.0, engine=SERIAL,
                          quantities=CLOSED_FORM_QUANTITIES)
    for name in CLOSED_FORM_QUANTITIES:
        np.testing.assert_array_equal(swept[name].sel(h=math.inf).values, half_space[name].values)
    # a thinner layer: a stiffer tangential contact at a smaller radius, slip later (a larger critical angle)
    assert np.all(np.diff(swept["critical_angle_A"].sel(tau0=42e3, d_max=0.3e-3).values) < 0)
    # a contact on a layer (no h in the grid), the discrete method: the same closed forms, no model run
    layered = me.sweep({"tau0": grid["tau0"]}, LAYERED, "A", 20.0, SPRINGS, engine=SERIAL,
                       quantities=("critical_angle_B",))
    assert layered["critical_angle_B"].values.tolist() == [_angles(LAYERED.replace(tau0=tau0), "B", PAPER_D_MAX)
                                                            for tau0 in grid["tau0"]]


def test_a_discrete_sweep_of_coulombs_part_on_a_layer_is_the_simulate_runs():
    """The discrete sweep's cell is simulate's discrete run bit for bit (the continuum sweep's:
    tests/analysis/test_play_sweep.py)."""
    swept = me.sweep({"h": [5e-3, math.inf]}, COULOMB, "A", 20.0, SPRINGS, engine=SERIAL,
                     quantities=("tangential_force_max", "normal_force_min"))
    assert int(swept["failed"].sum()) == 0
    for h in (5e-3, math.inf):
        run = me.simulate(COULOMB.replace(h=h), me.Scenario("A", 20.0), SPRINGS).isel(alpha=0)
        cell = swept.sel(h=h)
        assert float(cell["tangential_force_max"]) == float(np.nanmax(np.abs(run["tangential_force"].values)))
        assert float(cell["normal_force_min"]) == float(np.nanmin(run["normal_force"].values))


@pytest.mark.parametrize("call, fragment", [
    (lambda: me.sweep({"alpha": [90.0, 30.0]}, LAYERED.replace(**{"layer.base": "frictionless"}), "A", None,
                      SPRINGS, engine=SERIAL),
     "path 0 moves the indenter tangentially (x from 0 m to 0.000519615 m), which is not allowed on layer h = "
     "0.005 m, frictionless base"),
    (lambda: me.sweep({"tau0": [3e4]}, LAYERED.replace(**{"layer.base": "frictionless"}), "A", 20.0, engine=SERIAL,
                      quantities=("critical_angle_A",)),
     "Layer.base='frictionless' is not allowed for tangential contact"),
    (lambda: me.sweep({"h": [1e-5]}, PAPER, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES),
     "grid: depth=0.0003 m is not allowed on layer h = 1e-05 m, bonded base: its contact radius exceeds a/h = 64"),
    (lambda: me.sweep({"layer.base": [0.0]}, PAPER, "A", 20.0, engine=SERIAL),
     "grid: 'layer.base' is not allowed: a choice, not a number"),
    (lambda: me.sweep({"h": [5e-3, math.nan]}, PAPER, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES),
     "allowed: a non-empty list of finite numbers (or inf: the half-space)"),
    (lambda: me.sweep({"tau0": [3e4, -math.inf]}, PAPER, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES),
     "allowed: a non-empty list of finite numbers"),
    (lambda: me.sweep({"h": [5e-3, 0.0]}, PAPER, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES),
     "grid: Layer.thickness=0.0 is not allowed; allowed: a number > 0 (m)"),
])
def test_what_a_sweep_on_a_layer_cannot_run_is_refused_in_one_line_before_it_runs(call, fragment):
    with pytest.raises((ValueError, TypeError)) as caught:
        call()
    assert fragment in str(caught.value) and "\n" not in str(caught.value), str(caught.value)


def test_the_store_of_a_layer_sweep_resumes_and_holds_its_layer(tmp_path):
    """Interrupted after its first chunk, a sweep over h resumes and ends as an uninterrupted one; a store of the
    half-space is not resumed on a layer (the signature holds it) and the half-space's signature is as before."""
    class Interrupted(Exception):
        pass

    def stop(done, total):
        if done >= 2:
            raise Interrupted

    grid, store = {"h": THICKNESSES, "tau0": [30e3, 42e3]}, tmp_path / "layer.zarr"
    options = dict(quantities=CLOSED_FORM_QUANTITIES, store=store)
    with pytest.raises(Interrupted):
        me.sweep(grid, PAPER, "A", 20.0, scheduler="serial", chunk_size=2, progress=stop, **options)
    seen = []
    resumed = me.sweep(grid, PAPER, "A", 20.0, scheduler="serial", chunk_size=2,
                       progress=lambda done, total: seen.append(done), **options)
    assert seen == [4, 6]  # the first chunk was read back, not run again
    whole = me.sweep(grid, PAPER, "A", 20.0, scheduler="serial", chunk_size=2, quantities=CLOSED_FORM_QUANTITIES)
    xr.testing.assert_identical(resumed, whole)
    half = tmp_path / "half.zarr"
    me.sweep({"tau0": [30e3]}, PAPER, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES, store=half)
    with pytest.raises(ValueError, match="holds another sweep"):
        me.sweep({"tau0": [30e3]}, LAYERED, "A", 20.0, engine=SERIAL, quantities=CLOSED_FORM_QUANTITIES, store=half)
    signature = json.loads(_signature(sweep_job({"tau0": [30e3]}, PAPER, "A", 20.0, None, {})))
    assert "layer" not in signature  # (a half-space store written before layers still resumes)


# ------------------------------------------------------------------------------------------------------------
# the universal map's layer group
#: The map's corners in (S, Γ): the lowest and highest slip, without adhesion (B never jumps off: 90°) and with it
#: (make test's time, issue 28 item 4: each of the three maps below 16 cells rather than 36; what varies along an
#: axis between its ends, the thinness, keeps its four values).
SLIP = np.array([0.5, 8.0])
ADHESION = np.array([0.0, 0.2])
THINNESS = np.array([0.0, 0.3, 1.0, 3.0])
#: One cell between the corners, (S, Γ, λ) = (2, 0.05, 1), mapped alone for each base: universality is checked
#: inside the map too, not only at its corners.
INTERIOR = dict(slip=2.0, adhesion_in=0.05, thinness=1.0)
#: Another base of the paper's ν: another elastomer, indenter, depth, works of adhesion and τ0 (the map scales τ0
#: and the works to reach the groups, and h to reach λ).
OTHER = me.Parameters.paper().replace(R=0.1, d_max=1e-3, E=1e6, dgamma0=0.3, dgamma1=0.9, tau0=1e5)


@pytest.fixture(scope="module")
def layered_maps():
    return [universal_map(SLIP, ADHESION, base, thinness=THINNESS, scheduler="serial")
            for base in (me.Parameters.paper(), OTHER)]


@pytest.fixture(scope="module")
def interior_maps():
    """The interior cell's one-cell maps, for the paper's base and the other."""
    return [universal_map([INTERIOR["slip"]], [INTERIOR["adhesion_in"]], base, thinness=[INTERIOR["thinness"]],
                          scheduler="serial") for base in (me.Parameters.paper(), OTHER)]


def test_the_universal_map_is_universal_in_the_layer_group(layered_maps, interior_maps):
    """Two bases with the same (S, Γ, λ, ν) give the same angles to the root finders' accuracy, at the map's corners
    and inside it; another ν does not (on a layer the map holds for one ν); λ moves the angles."""
    for paper, other in (layered_maps, interior_maps):
        assert int(paper["failed"].sum()) == int(other["failed"].sum()) == 0
        np.testing.assert_allclose(other["critical_angle_A"].values, paper["critical_angle_A"].values,
                                   rtol=SCENARIO_A_UNIVERSAL, atol=0)
        np.testing.assert_allclose(other["critical_angle_B"].values, paper["critical_angle_B"].values,
                                   rtol=SCENARIO_B_UNIVERSAL, atol=0)
    paper, other = layered_maps
    assert paper["critical_angle_A"].dims == ("slip", "adhesion_in", "thinness")
    base = me.Parameters.paper()
    compressible = base.replace(nu=0.3, E=base.E_star * (1 - 0.3**2))  # (E* kept: the same Γ)
    compressible = compressible.replace(tau0=base.tau0 * compressible.G_star / base.G_star)  # (the same S)
    np.testing.assert_allclose(dimensionless_groups(compressible), dimensionless_groups(me.Parameters.paper()),
                               rtol=1e-15)
    moved = universal_map(SLIP, ADHESION, compressible, thinness=THINNESS, scheduler="serial")
    shift = np.abs(moved["critical_angle_A"].values - paper["critical_angle_A"].values)
    # the half-space's angles do not see ν (round-off); on a layer ν = 0.3 moves each of A's by 0.16° or more
    assert shift[..., 0].max() < 1e-12 * 90.0 and shift[..., 1:].min() > 0.1
    assert np.all(np.diff(paper["critical_angle_A"].values, axis=2) > 0)  # thinner: slides later


def test_the_layer_group_is_the_layers_critical_angle_and_zero_the_half_space_map(layered_maps, interior_maps):
    paper = layered_maps[0]
    half = universal_map(SLIP, ADHESION, me.Parameters.paper(), scheduler="serial")
    assert "thinness" not in half.dims and "param_layer_base" not in half.attrs
    for name in ("critical_angle_A", "critical_angle_B"):
        np.testing.assert_array_equal(paper[name].sel(thinness=0.0).values, half[name].values)
    assert paper.attrs["param_layer_base"] == "bonded" and paper.attrs["param_nu"] == 0.5
    base = me.Parameters.paper()
    groups = dimensionless_groups(base)
    h = float(thickness_of_thinness([1.0], base)[0])
    assert h == math.sqrt(base.R * base.d_max)
    for cell, map_ in ((dict(slip=8.0, adhesion_in=0.2, thinness=1.0), paper), (INTERIOR, interior_maps[0])):
        contact = PAPER.replace(h=h, tau0=base.tau0 * cell["slip"] / groups.slip,
                                dgamma0=base.dgamma0 * cell["adhesion_in"] / groups.adhesion_in)
        assert float(map_["critical_angle_A"].sel(**cell)) == \
            pytest.approx(_angles(contact, "A", base.d_max), rel=1e-13)


def test_a_map_over_the_layer_group_is_written_read_and_drawn(layered_maps, tmp_path):
    from mdr_events.plotting.universal import plot_universal_map

    path = me.write_netcdf(layered_maps[0], tmp_path / "map.nc")
    read = me.open_result(path)
    np.testing.assert_array_equal(read["critical_angle_B"].values, layered_maps[0]["critical_angle_B"].values)
    assert "λ = √(R d_max)/h = 1 " in plot_universal_map(read, thinness=1.0).get_suptitle()
    with pytest.raises(ValueError, match="allowed: one of the map's thinness values 0, 0.3, 1, 3"):
        plot_universal_map(read, thinness=2.0)


@pytest.mark.parametrize("thinness", [[-1.0], [0.5, 0.5], [], [math.inf]])
def test_bad_thinness_is_named(thinness):
    with pytest.raises(ValueError, match="thinness=.* is not allowed; allowed: a non-empty list of distinct finite"):
        universal_map(SLIP, ADHESION, me.Parameters.paper(), thinness=thinness, scheduler="serial")
