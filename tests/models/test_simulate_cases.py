"""``simulate`` with custom paths along ``case``, the continuum's exact extrema, and event directions.

Custom paths (a list, a mapping ``{label: Path}`` or one Path) are labelled along ``case`` for both
methods, with each case's waypoints and speed; a case gives the same numbers alone as among others.
Every continuum result carries the exact extrema of ``F_N``, ``F_x`` and ``A``
(:func:`mdr_events.models.continuum.extrema.solution_extrema`) and its events' directions.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io.datasets import dims_match, required_variables
from mdr_events.io.files import open_result, write_netcdf
from mdr_events.models.continuum import evaluate, solve_path
from mdr_events.models.continuum.extrema import EXTREMA_KINDS, EXTREMA_QUANTITIES, extremum_names, solution_extrema
from mdr_events.models.motion import CASE_DIMENSIONS
from mdr_events.models.simulation_schema import (EVENT_VARIABLES, EXTREMA_VARIABLES, PATH_VARIABLES,
                                                 SIMULATION_CONTENT, SIMULATION_VARIABLES)

METHODS = ("discrete", "continuum")
#: Coarse runs for the labelling tests: the discrete spacing and steps, the continuum's samples.
DISCRETE = dict(dx=4e-6, n_steps=600)
CONTINUUM = dict(samples=101)
#: The samples of the fine run the exact extrema are compared with.
FINE_SAMPLES = 20001
#: The springs' tangential force is a NumPy (pairwise) sum over a block of springs as wide as the widest
#: case still running: run among wider cases, a case's shifts are summed with zeros appended, which
#: regroups the pairwise sum. That moves F_x by rounding only: a few eps times sum |u_j| (below
#: log2(n_springs) eps of the largest |F_x| for the one-signed shifts of these paths); 1e-13 leaves a
#: factor of ~5 over log2(1000) eps = 2.2e-15 * 10 and is still 1e7 below one spring's share.
SPRING_SUM_RTOL = 1e-13
#: Where a sample falls exactly on the time of an extremum (t = 0, a plateau, a corner shared by two
#: spans), the sample and the extremum are the same closed form or interpolant evaluated by the same code,
#: up to rounding of the last bits: the comparison allows this share of the quantity's largest magnitude.
ROUNDING_RTOL = 1e-12
#: The pull-off force of scenario A from the continuum against -(3/2) π Δγ1 R: F_N is flat at its
#: minimum on the Δγ1 branch, so the extremum's time error (1e-12 of the span) and the radius's root error
#: (radius_rtol 1e-14) enter squared; what is left is the rounding of (10), about 1e-15.
PULL_OFF_RTOL = 1e-12


@pytest.fixture(scope="module")
def params():
    return me.Parameters.paper()


@pytest.fixture(scope="module")
def paths(params):
    """Three custom paths: in, across and out at the paper's speed; in at an angle and out at twice the
    speed; in and out at an angle towards -x (solved mirrored by the continuum)."""
    d = params.d_max
    return {
        "across": me.Path([(0.0, 0.0), (0.0, d), (2e-4, d), (2e-4, -1e-4)], params.v),
        "fast": me.Path([(0.0, 0.0), (1e-4, d), (1e-4, -1e-4)], 2 * params.v),
        "backwards": me.Path([(0.0, 0.0), (0.0, d), (-3e-4, -1e-4)], params.v),
    }


def run(params, scenario, method, **options):
    settings = DISCRETE if method == "discrete" else CONTINUUM
    return me.simulate(params, scenario, method=method, **{**settings, **options})


def assert_custom_cases(dataset: xr.Dataset, labels: list[str], paths: list[me.Path]) -> None:
    """Labelled along ``case`` (never ``alpha``), with each case's waypoints and speed, every variable
    with units and long_name."""
    assert "alpha" not in dataset.dims and dataset["case"].dims == ("case",)
    assert list(dataset["case"].values) == labels
    assert dataset["case"].attrs["units"] == "1" and "label" in dataset["case"].attrs["long_name"]
    for name in SIMULATION_VARIABLES:
        assert dataset[name].dims == ("case", "time")
    assert list(dataset["path_waypoints"].values) == [path.describe() for path in paths]
    assert dataset["path_speed"].values.tolist() == [path.speed for path in paths]
    assert dataset["path_speed"].attrs["units"] == "m s-1"
    assert dataset.attrs["scenario"] == "custom"
    for name, variable in dataset.variables.items():
        assert {"units", "long_name"} <= set(variable.attrs), name


# ----------------------------------------------------------------------------------------------
# labels, dimensions, waypoints


@pytest.mark.parametrize("method", METHODS)
def test_a_list_of_paths_is_labelled_path_1_path_2_along_case(params, paths, method):
    chosen = [paths["across"], paths["fast"]]
    dataset = run(params, chosen, method)
    assert_custom_cases(dataset, ["path 1", "path 2"], chosen)
    # each case follows its own path from its first contact (time 0 at d = 0)
    for label, path in zip(["path 1", "path 2"], chosen):
        case = dataset.sel(case=label)
        running = np.isfinite(case["indentation_depth"].values)
        _, depth = path.position(path.first_contact_time() + case["time"].values[running])
        np.testing.assert_allclose(case["indentation_depth"].values[running], depth, rtol=0, atol=1e-15)


@pytest.mark.parametrize("method", METHODS)
def test_a_mapping_of_paths_is_labelled_by_its_keys(params, paths, method):
    dataset = run(params, paths, method)
    assert_custom_cases(dataset, list(paths), list(paths.values()))
    if method == "continuum":  # the event log and the extrema lie along case too
        assert dataset["event_kind"].dims == ("case", "event")
        assert dataset["normal_force_max"].dims == ("case",)


@pytest.mark.parametrize("method", METHODS)
def test_one_path_is_the_case_path_1(params, paths, method):
    dataset = run(params, paths["fast"], method)
    assert_custom_cases(dataset, ["path 1"], [paths["fast"]])
    assert dataset.sizes["case"] == 1


def test_scenarios_keep_the_alpha_dimension(params):
    for method in METHODS:
        dataset = run(params, "B", method, alpha=[20.0, 60.0])
        assert dataset["alpha"].values.tolist() == [20.0, 60.0] and "case" not in dataset.dims
        assert dataset["alpha"].attrs == {"units": "degree", "long_name": "path angle to the surface"}
        assert not set(PATH_VARIABLES) & set(dataset.variables) and "note" not in dataset.attrs


# ----------------------------------------------------------------------------------------------
# a case alone and among others


def test_continuum_case_alone_is_exactly_the_case_among_others(params, paths):
    times = np.linspace(0.0, 1200.0, 301)
    together = me.simulate(params, paths, method="continuum", t=times)
    for label, path in paths.items():
        alone = me.simulate(params, {label: path}, method="continuum", t=times).sel(case=label)
        among = together.sel(case=label)
        for name in (*SIMULATION_VARIABLES, *EXTREMA_VARIABLES, *PATH_VARIABLES):
            np.testing.assert_array_equal(among[name].values, alone[name].values, err_msg=name)
        events = alone.sizes["event"]  # the log among others is padded to the longest log
        for name in EVENT_VARIABLES:
            np.testing.assert_array_equal(among[name].values[:events], alone[name].values, err_msg=name)
        assert set(among["event_kind"].values[events:]) <= {""}
        assert set(among["event_direction"].values[events:]) <= {0}


def test_discrete_case_alone_equals_the_case_among_others_on_the_same_time_grid(params, paths):
    step = 0.5  # s: one grid k dt for every case, whatever its speed
    together = me.simulate(params, paths, dx=4e-6, dt=step)
    for label, path in paths.items():
        alone = me.simulate(params, {label: path}, dx=4e-6, dt=step)
        assert alone.attrs["dt"] == together.attrs["dt"] == step
        shared = alone.sizes["time"]  # the grid alone ends with this case; among others with the longest
        np.testing.assert_array_equal(together["time"].values[:shared], alone["time"].values)
        among = together.sel(case=label).isel(time=slice(0, shared))
        for name in SIMULATION_VARIABLES:
            if name in ("tangential_force", "mean_shear_stress"):
                scale = float(np.nanmax(np.abs(alone[name].values)))
                np.testing.assert_allclose(among[name].values, alone[name].values[0], rtol=0,
                                           atol=SPRING_SUM_RTOL * scale, err_msg=name)
                assert np.array_equal(np.isnan(among[name].values), np.isnan(alone[name].values[0]))
            else:
                np.testing.assert_array_equal(among[name].values, alone[name].values[0], err_msg=name)
        after = together.sel(case=label).isel(time=slice(shared, None))
        assert np.all(np.isnan(after["normal_force"].values))


def test_discrete_cases_of_different_speeds_share_one_time_step(params, paths):
    dataset = me.simulate(params, [paths["across"], paths["fast"]], dx=4e-6, n_steps=600)
    longest = max(path.duration - path.first_contact_time() for path in (paths["across"], paths["fast"]))
    assert dataset.attrs["dt"] == pytest.approx(longest / 600, rel=1e-15)
    np.testing.assert_allclose(np.diff(dataset["time"].values), dataset.attrs["dt"], rtol=1e-9)
    # the fast path ends in about half the time
    ends = [float(dataset["time"].values[np.isfinite(dataset["normal_force"].sel(case=label).values)][-1])
            for label in ("path 1", "path 2")]
    assert ends[1] < 0.6 * ends[0]


# ----------------------------------------------------------------------------------------------
# bad input


class RepeatingMapping(Mapping):
    """A mapping whose keys come out twice (as a careless user-defined mapping might)."""

    def __init__(self, path):
        self.path = path

    def __getitem__(self, key):
        return self.path

    def __iter__(self):
        return iter(["a", "a"])

    def __len__(self):
        return 2


@pytest.mark.parametrize("method", METHODS)
def test_bad_custom_paths_are_named_with_what_is_allowed(params, paths, method):
    path = paths["fast"]
    cases = [
        ([], ValueError, r"scenario=\[\] is not allowed: it holds no path; allowed: 'A', 'B', 'B\+', a Path, "
                         r"a non-empty list of Paths"),
        ({}, ValueError, r"scenario=\{\} is not allowed: it holds no path; allowed: .*mapping"),
        ([path, "A"], TypeError, r"scenario\[1\]='A' \(str\) is not allowed; allowed: a mdr_events.Path"),
        ({"ok": path, "bad": 3}, TypeError, r"scenario\['bad'\]=3 \(int\) is not allowed; allowed: a mdr_events.Path"),
        ({1: path}, TypeError, r"scenario has the label 1 \(int\); allowed: labels that are non-empty strings"),
        ({"": path}, TypeError, r"scenario has the label '' \(str\); allowed: labels that are non-empty strings"),
        (RepeatingMapping(path), ValueError, r"scenario has the label\(s\) \['a'\] more than once; allowed: "
                                             r"distinct labels"),
        (3.0, TypeError, r"scenario=3.0 \(float\) is not allowed; allowed: 'A', 'B', 'B\+', a Path"),
        ("C", ValueError, r"scenario='C' is not allowed; allowed: 'A', 'B', 'B\+', a Path"),
    ]
    for scenario, error, message in cases:
        with pytest.raises(error, match=message):
            me.simulate(params, scenario, method=method)
    for scenario in (path, [path], {"one": path}):
        with pytest.raises(ValueError, match=r"alpha=\[10.0\] is not allowed with custom paths .*; allowed: "
                                             r"alpha=None"):
            me.simulate(params, scenario, alpha=[10.0], method=method)


# ----------------------------------------------------------------------------------------------
# files and schema


@pytest.mark.parametrize("method", METHODS)
def test_custom_cases_read_back_identical_and_pass_the_schema(params, paths, method, tmp_path):
    dataset = run(params, paths, method)
    again = open_result(write_netcdf(dataset, tmp_path / f"{method}.nc"))
    xr.testing.assert_identical(again, dataset)
    assert list(again["case"].values) == list(paths)
    assert list(again["path_waypoints"].values) == [path.describe() for path in paths.values()]


def test_schema_accepts_either_case_dimension_and_nothing_else(params, paths, tmp_path):
    schema = required_variables(SIMULATION_CONTENT, {"method": "continuum", "scenario": "custom"})
    assert set(schema) == {*SIMULATION_VARIABLES, *EVENT_VARIABLES, *EXTREMA_VARIABLES, *PATH_VARIABLES}
    assert schema["normal_force"] == (CASE_DIMENSIONS, "time")
    assert dims_match(("case", "time"), schema["normal_force"]) and dims_match(("alpha", "time"), schema["normal_force"])
    assert not dims_match(("time", "case"), schema["normal_force"]) and not dims_match(("case",), schema["normal_force"])
    assert schema["path_waypoints"] == ("case",) and not dims_match(("alpha",), schema["path_waypoints"])
    dataset = run(params, paths["fast"], "discrete")
    for broken, message in ((dataset.drop_vars("path_speed"), r"lacks the variable\(s\) \['path_speed'\]"),
                            (dataset.rename({"case": "run"}),
                             r"normal_force \('run', 'time'\) \(expected \('alpha' or 'case', 'time'\)\)")):
        with pytest.raises(ValueError, match=message):  # write_netcdf refuses what open_result would
            write_netcdf(broken, tmp_path / "refused.nc")
        path = tmp_path / "broken.nc"
        broken.to_netcdf(path, engine="scipy", format="NETCDF3_64BIT")  # (written by hand)
        with pytest.raises(ValueError, match=message):
            open_result(path)


def test_a_continuum_result_without_its_extrema_or_event_directions_is_refused(params, tmp_path):
    dataset = me.simulate(params, "A", alpha=[30.0], method="continuum", samples=51)
    for name in ("normal_force_max", "contact_area_min_time", "event_direction"):
        path = tmp_path / f"without_{name}.nc"
        dataset.drop_vars(name).to_netcdf(path, engine="scipy", format="NETCDF3_64BIT")  # (write_netcdf refuses it)
        with pytest.raises(ValueError, match=rf"lacks the variable\(s\) \['{name}'\]"):
            open_result(path)


# ----------------------------------------------------------------------------------------------
# exact extrema


@pytest.fixture(scope="module")
def fine_runs(params, paths):
    """Fine continuum runs (:data:`FINE_SAMPLES` samples): scenario A at three angles, scenario B at one,
    the custom paths."""
    return [me.simulate(params, "A", alpha=[10.0, 40.0, 80.0], method="continuum", samples=FINE_SAMPLES),
            me.simulate(params, "B", alpha=[30.0], method="continuum", samples=FINE_SAMPLES),
            me.simulate(params, paths, method="continuum", samples=FINE_SAMPLES)]


def each_case(runs):
    for dataset in runs:
        dimension = "case" if "case" in dataset.dims else "alpha"
        for label in dataset[dimension].values:
            yield f"{dimension}={label}", dataset.sel({dimension: label})


def test_every_continuum_result_has_labelled_extrema(fine_runs):
    for _, case in each_case(fine_runs):
        for name, (units, long_name) in EXTREMA_VARIABLES.items():
            assert case[name].attrs == {"units": units, "long_name": long_name}
            assert "exact" in long_name and "continuum solution" in long_name
        assert case["normal_force_max"].attrs["units"] == "N" and case["contact_area_min"].attrs["units"] == "m2"
        assert case["tangential_force_max_time"].attrs["units"] == "s"


def test_exact_extrema_bound_every_sample_and_lie_within_a_slope_times_spacing_of_the_sampled_ones(fine_runs):
    """The extrema bound every sample (up to :data:`ROUNDING_RTOL`); the sampled extreme is short of the
    exact one by at most what the quantity changes over one sample spacing next to the exact extremum:
    the sample nearest ``t*`` is within ``Δt`` of it, and no closer sample can be further off than the
    largest change between neighbouring samples around ``t*`` (two intervals either side)."""
    for where, case in each_case(fine_runs):
        time = case["time"].values
        for quantity in EXTREMA_QUANTITIES:
            samples = case[quantity].values
            scale = float(np.nanmax(np.abs(samples)))
            slack = ROUNDING_RTOL * scale
            for kind, largest in EXTREMA_KINDS.items():
                value_name, time_name = extremum_names(quantity, kind)
                exact, at = float(case[value_name]), float(case[time_name])
                sign = 1.0 if largest else -1.0
                sampled = sign * float(np.nanmax(sign * samples))
                assert sign * (exact - sampled) >= -slack, f"{where} {value_name}: a sample beyond the extremum"
                near = np.flatnonzero(np.abs(time - at) <= 2.5 * (time[1] - time[0]))
                window = samples[max(near[0] - 1, 0):near[-1] + 2]
                change = float(np.nanmax(np.abs(np.diff(window)), initial=0.0))
                assert sign * (exact - sampled) <= change + slack, (
                    f"{where} {value_name}: exact {exact!r} vs sampled {sampled!r}, allowed {change!r}")


def test_the_extrema_are_the_solutions_values_at_their_times(params, paths):
    """``simulate`` carries :func:`solution_extrema` of each case's solution, and each value is the
    solution's value at its time (or, the value 0 at the end of a run whose contact came apart, the first
    sample after that end)."""
    dataset = me.simulate(params, paths, method="continuum", samples=51)
    for label, path in paths.items():
        solution = solve_path(params, path)
        extrema = solution_extrema(solution)
        for name in EXTREMA_VARIABLES:
            assert float(dataset[name].sel(case=label)) == extrema[name], (label, name)
        for quantity in EXTREMA_QUANTITIES:
            for kind in EXTREMA_KINDS:
                value_name, time_name = extremum_names(quantity, kind)
                value, at = extrema[value_name], extrema[time_name]
                assert 0.0 <= at <= solution.end_time
                if value == 0.0 and at == solution.end_time and solution.ended_by_contact:
                    at = solution.end_time * (1 + 1e-9)  # just after: the contact is gone
                filled = evaluate(solution, np.array([at]))
                radius = filled["contact_radius"]
                found = np.pi * radius**2 if quantity == "contact_area" else filled[quantity]
                scale = max(abs(extrema[extremum_names(quantity, "max")[0]]),
                            abs(extrema[extremum_names(quantity, "min")[0]]))
                assert float(found[0]) == pytest.approx(value, rel=0, abs=ROUNDING_RTOL * scale), (label, value_name)


def test_pull_off_force_of_scenario_A_is_the_jkr_adhesive_force_not_the_jump_off_force(params, fine_runs):
    """Scenario A pulls out vertically on the Δγ1 branch under displacement control. Along the branch
    F_N (10) falls to its minimum -(3/2) π Δγ1 R (JKR's pull-off force under load control, where
    ∂F_N/∂a = 0) and then rises again to -(5/6) π Δγ1 R at the displacement-controlled jump-off
    (∂d/∂a = 0, :func:`mdr_events.jump_off`), where the contact comes apart. So the run's minimum is
    -(3/2) π Δγ1 R, reached before the jump-off: the closed form checked here. (It holds while the pinned
    radius exceeds the radius of that minimum, as for the paper's parameters at every angle.)"""
    adhesive_force = -1.5 * math.pi * params.dgamma1 * params.R
    assert me.pull_off_force(params, params.dgamma1) == pytest.approx(adhesive_force, rel=1e-15)
    jump_off_force = me.jump_off(params, params.dgamma1)["normal_force"]
    assert jump_off_force == pytest.approx(-5.0 / 6.0 * math.pi * params.dgamma1 * params.R, rel=1e-14)
    scenario_a = fine_runs[0]
    for alpha in scenario_a["alpha"].values:
        case = scenario_a.sel(alpha=alpha)
        assert float(case["normal_force_min"]) == pytest.approx(adhesive_force, rel=PULL_OFF_RTOL), alpha
        pull_off = float(case["event_time"].values[case["event_kind"].values == "pull_off"][0])
        assert float(case["normal_force_min_time"]) < pull_off
        # the contact comes apart at the jump-off point, where F_N (10) is the jump-off force, well above
        # the minimum (the fold's radius carries the root finder's error: rel 1e-12 covers it)
        at_pull_off = case["event_kind"].values == "pull_off"
        force_at_pull_off = me.analytic.normal_force(float(case["event_depth"].values[at_pull_off][0]),
                                                     float(case["event_radius"].values[at_pull_off][0]), params)
        assert float(force_at_pull_off) == pytest.approx(jump_off_force, rel=PULL_OFF_RTOL)
        assert jump_off_force - float(case["normal_force_min"]) > 0.4 * abs(adhesive_force)


# ----------------------------------------------------------------------------------------------
# event directions


def test_event_direction_is_the_solutions_direction_padded_with_zero(params, paths):
    dataset = me.simulate(params, paths, method="continuum", samples=51)
    variable = dataset["event_direction"]
    assert variable.dims == ("case", "event") and np.issubdtype(variable.dtype, np.integer)
    assert variable.attrs["units"] == "1" and "direction" in variable.attrs["long_name"]
    for label, path in paths.items():
        events = solve_path(params, path).events
        directions = variable.sel(case=label).values
        assert directions.tolist() == [event.direction for event in events] + [0] * (len(directions) - len(events))
        assert set(directions.tolist()) <= {-1, 0, 1}


def test_slip_events_of_scenario_A_have_the_positive_cap(params):
    """The indenter moves towards +x: springs that slip are dragged to the cap u = +ū; events without a
    direction (first contact, corner, detachment, pull-off) have 0."""
    dataset = me.simulate(params, "A", alpha=[10.0, 40.0], method="continuum", samples=51)
    kinds, directions = dataset["event_kind"].values, dataset["event_direction"].values
    slip = np.isin(kinds, ["slip_onset", "full_slip", "re_stick"])
    assert slip.any() and np.all(directions[slip] == 1)
    assert np.all(directions[np.isin(kinds, ["first_contact", "corner", "detachment_starts", "pull_off", ""])] == 0)


# ----------------------------------------------------------------------------------------------
# the dataset assembled without xarray's merge (issue 28)

@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("motion", ["scenario", "custom"])
def test_the_assembled_dataset_is_the_one_xarray_merges(params, paths, method, motion, monkeypatch, tmp_path):
    """io.datasets.assembled lays a simulation's variables out without xarray's merge: the dataset (its variables,
    their order and classes, the dimensions' order, the coordinates and their indexes, the attributes) and the
    netCDF file written of it are those of xarray.Dataset(data, coords=coords)."""
    from mdr_events.models import simulation_schema

    def simulated():
        if motion == "scenario":
            return run(params, "B", method, alpha=[20.0, 60.0, 30.0])
        return run(params, paths, method)

    fast = simulated()
    monkeypatch.setattr(simulation_schema, "assembled", lambda data, coords: xr.Dataset(data, coords=coords))
    merged = simulated()
    xr.testing.assert_identical(fast, merged)
    assert list(fast.variables) == list(merged.variables) and list(fast.dims) == list(merged.dims)
    assert set(fast.coords) == set(merged.coords) and list(fast.xindexes) == list(merged.xindexes)
    assert all(fast.xindexes[name].equals(merged.xindexes[name]) for name in merged.xindexes)
    for name, index in merged.xindexes.items():  # (the index made at once is from_variables': its pandas.Index too)
        made = fast.xindexes[name]
        assert (type(made), made.dim, made.coord_dtype) == (type(index), index.dim, index.coord_dtype)
        assert (type(made.index), made.index.dtype, made.index.name) == \
            (type(index.index), index.index.dtype, index.index.name)
    assert all(fast[name].encoding == merged[name].encoding for name in merged.variables)
    assert [type(variable) for variable in fast.variables.values()] == \
        [type(variable) for variable in merged.variables.values()]
    assert fast.attrs == merged.attrs and list(fast.attrs) == list(merged.attrs)
    write_netcdf(fast, tmp_path / "fast.nc")
    write_netcdf(merged, tmp_path / "merged.nc")
    assert (tmp_path / "fast.nc").read_bytes() == (tmp_path / "merged.nc").read_bytes()


def test_results_sharing_a_coordinate_index_keep_their_own_coordinates(params):
    """Two runs of the same angles share the angles' and the events' values (made once, read-only) and nothing
    else: each result's index and coordinate its own, whose name, attributes and values a change of the other
    leaves, nor does a later run of the same angles see it."""
    first, second = (run(params, "B", "continuum", alpha=[20.0, 30.0]) for _ in range(2))
    for dim in ("alpha", "event"):
        assert first.indexes[dim] is not second.indexes[dim] and first[dim].variable is not second[dim].variable
        assert np.shares_memory(first.indexes[dim].values, second.indexes[dim].values)
    names = list(second["event_kind"].to_dataframe().index.names)
    first.indexes["alpha"].name = "renamed"
    first.indexes["event"].rename("q", inplace=True)
    assert first.indexes["alpha"].name == "renamed"  # (the rename took, on the first result alone)
    for other in (second, run(params, "B", "continuum", alpha=[20.0, 30.0])):
        assert [other.indexes[dim].name for dim in ("alpha", "event")] == ["alpha", "event"]
        assert list(other["event_kind"].to_dataframe().index.names) == names
    first["alpha"].attrs["units"] = "rad"
    first.coords["event"].attrs.clear()
    assert second["alpha"].attrs == {"units": "degree", "long_name": "path angle to the surface"}
    assert second["event"].attrs == {"units": "1", "long_name": "event number"}
    renamed = first.assign_coords(alpha=[0.1, 0.2])
    assert list(second["alpha"].values) == [20.0, 30.0] and list(renamed["alpha"].values) == [0.1, 0.2]
    assert second.sel(alpha=30.0)["event_kind"].equals(second.isel(alpha=1)["event_kind"])


@pytest.mark.parametrize("method", METHODS)
def test_results_of_the_same_custom_paths_share_their_labels_index_and_keep_their_own(params, paths, method):
    """Two runs of the same custom paths share the labels' index values (pandas' index of text, ~0.3 ms a run, made
    once: issue 28) and nothing else: each result's index and coordinate its own (the labels' NumPy type kept), whose
    name, attributes and labels a change of the other leaves, nor does a later run of the same paths see it; the
    shared labels refuse a change (pandas keeps an index's values read-only)."""
    first, second = (run(params, paths, method) for _ in range(2))
    assert first.indexes["case"] is not second.indexes["case"] and first["case"].variable is not second["case"].variable
    assert first.indexes["case"].array is second.indexes["case"].array  # (shared)
    assert first["case"].dtype == np.dtype("<U9") and list(first["case"].values) == list(paths)
    with pytest.raises(ValueError, match="read-only"):
        first.indexes["case"].array[0] = "changed"
    first.indexes["case"].name = "renamed"
    first["case"].attrs["units"] = "m"
    renamed = first.assign_coords(case=["a", "b", "c"])
    for other in (second, run(params, paths, method)):
        assert other.indexes["case"].name == "case" and list(other["case"].values) == list(paths)
        assert other["case"].attrs == {"units": "1", "long_name": "label of the custom path"}
        assert other.sel(case="fast")["normal_force"].equals(other.isel(case=1)["normal_force"])
    assert list(renamed["case"].values) == ["a", "b", "c"]


def _bytes(dataset: xr.Dataset, path) -> tuple[bytes, bytes]:
    """The bytes of ``dataset.to_netcdf()`` and of the file :func:`write_netcdf` writes of it at ``path``."""
    return bytes(dataset.to_netcdf()), write_netcdf(dataset, path).read_bytes()


def _assert_bit_for_bit(result: xr.Dataset, reference: xr.Dataset) -> None:
    """``result`` is ``reference``: identical (values, dims, attributes, types) with the same indexes (class, pandas
    type, name, type of their values) and encodings."""
    assert result.identical(reference)
    xr.testing.assert_identical(result, reference)
    assert {name: variable.dtype for name, variable in result.variables.items()} == \
        {name: variable.dtype for name, variable in reference.variables.items()}
    assert list(result.xindexes) == list(reference.xindexes)
    for dim, index in reference.xindexes.items():
        made = result.xindexes[dim]
        assert (type(made), made.dim, made.coord_dtype, type(made.index), made.index.dtype, made.index.name) == \
            (type(index), index.dim, index.coord_dtype, type(index.index), index.index.dtype, index.index.name)
        assert made.index.equals(index.index) and result[dim].encoding == reference[dim].encoding


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("motion", ["scenario", "custom"])
def test_a_result_on_a_shared_index_is_the_one_on_a_fresh_index_bit_for_bit(params, paths, method, motion,
                                                                             monkeypatch, tmp_path):
    """Results whose angles, events' numbers or custom paths' labels (text) take a view of a shared index (issue 28)
    are, bit for bit (``identical``, their indexes, the bytes of ``to_netcdf()`` and of write_netcdf), the result made
    on a fresh index (the shared indexes cleared) and the one xarray's merge makes (no index shared), whatever ran in
    between: runs of other labels or angles (other shared indexes, the same names) and of the same ones. The labels
    keep the NumPy type of their texts."""
    from mdr_events.io import datasets
    from mdr_events.models import simulation_schema

    listed = list(paths.values())
    if motion == "scenario":
        inputs = {"mine": ("B", dict(alpha=[20.0, 60.0, 30.0])), "other": ("B", dict(alpha=[20.0, 60.0]))}
    else:  # (the same paths under other labels: texts of another NumPy type, then of the same type)
        inputs = {"mine": (paths, {}), "other": (listed[:2], {}), "relabelled": (dict(zip("xyz", listed)), {})}

    def simulated(key):
        scenario, options = inputs[key]
        return run(params, scenario, method, **options)

    fresh = {}
    for key in inputs:  # (each on a fresh index: made by this run)
        datasets._shared_coordinate.cache_clear()
        fresh[key] = simulated(key)
    with monkeypatch.context() as patched:  # (no index shared: xarray's merge)
        patched.setattr(simulation_schema, "assembled", lambda data, coords: xr.Dataset(data, coords=coords))
        merged = {key: simulated(key) for key in inputs}
    written = {}
    for key, (scenario, _) in inputs.items():
        _assert_bit_for_bit(fresh[key], merged[key])
        written[key] = _bytes(fresh[key], tmp_path / f"{key}_fresh.nc")
        assert _bytes(merged[key], tmp_path / f"{key}_merged.nc") == written[key]
        if motion == "custom":
            labels = list(scenario) if isinstance(scenario, Mapping) else [f"path {i}" for i in (1, 2)]
            assert fresh[key]["case"].dtype == np.asarray(labels).dtype and list(fresh[key]["case"].values) == labels
    order = [*inputs, *inputs, *reversed(inputs)]  # (each warm, after the others and after itself)
    for step, key in enumerate(order):
        hits = datasets._shared_coordinate.cache_info().hits
        warm = simulated(key)
        assert step < len(inputs) or datasets._shared_coordinate.cache_info().hits > hits  # (on a shared index)
        _assert_bit_for_bit(warm, fresh[key])
        assert _bytes(warm, tmp_path / f"{key}_{step}.nc") == written[key]

def test_an_assembled_dataset_refuses_what_a_merge_would():
    """Sizes that disagree, and a data variable named after a dimension, are refused as xarray's merge refuses them."""
    from mdr_events.io.datasets import assembled

    coords = {"time": ("time", np.arange(3.0), {})}
    with pytest.raises(ValueError, match="conflicting sizes"):
        assembled({"x": (("time",), np.zeros(4), {})}, coords)
    with pytest.raises(ValueError, match="named after a coordinate or a dimension"):
        assembled({"time": (("time",), np.zeros(3), {})}, {})
