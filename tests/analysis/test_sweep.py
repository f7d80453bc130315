"""``sweep``: the same numbers serially and on a dask cluster, resumable stores, recorded failures, bad grids;
the quantities against the closed forms; the dimensionless groups."""

import importlib.util
import math
import os
import re

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.executors import LOOPBACK_DASHBOARD
from mdr_events.analysis.sweep import CLOSED_FORM_QUANTITIES, QUANTITIES, sweep

from dask_settings import connect_timeout
from mdr_events.theory.analytic import d_crit, dimensionless_groups

# looked up, not imported: dask.distributed costs a pytest-xdist worker about a second at collection; the tests that
# start a cluster import it (``_distributed``)
if importlib.util.find_spec("distributed") is None:
    pytest.skip("the extra 'scale' is not installed (make installs it)", allow_module_level=True)


def _distributed():
    """dask.distributed, imported where a test starts or joins a cluster."""
    import distributed

    return distributed

GRID = {"tau0": [30e3, 42e3, 55e3], "alpha": [10.0, 20.0, 40.0, 70.0]}


@pytest.fixture(scope="module")
def serial(paper):
    return sweep(GRID, "A", base=paper, scheduler="serial", chunk_size=5)


@pytest.fixture(scope="module")
def cluster():
    """A 2-worker LocalCluster on loopback (processes, one thread each), shared by the tests that need one."""
    with _distributed().LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=LOOPBACK_DASHBOARD) as local:
        yield local


def test_the_grid_is_an_outer_product_with_labelled_dimensions(paper, serial):
    assert dict(serial.sizes) == {"tau0": 3, "alpha": 4}
    assert serial["tau0"].values.tolist() == GRID["tau0"] and serial["alpha"].attrs["units"] == "degree"
    assert set(QUANTITIES) <= set(serial.data_vars) and int(serial["failed"].sum()) == 0
    for name in QUANTITIES:
        assert serial[name].attrs["units"] == QUANTITIES[name][0]
    # each cell is the run at its coordinates: one recomputed alone
    alone = sweep({"alpha": [20.0]}, "A", base=paper.replace(tau0=55e3), scheduler="serial")
    for name in QUANTITIES:
        np.testing.assert_array_equal(alone[name].values[0], serial[name].sel(tau0=55e3, alpha=20.0).values)


def test_slip_onset_and_the_critical_angle_agree_with_the_closed_forms(paper, serial):
    """Below α_c (18) the springs slide while indenting, at d_crit (18); above it they do not."""
    for tau0 in GRID["tau0"]:
        params = paper.replace(tau0=tau0)
        critical = float(serial["critical_angle_A"].sel(tau0=tau0, alpha=10.0))
        for alpha in GRID["alpha"]:
            depth = float(serial["slip_onset_in_depth"].sel(tau0=tau0, alpha=alpha))
            if alpha < critical:
                assert depth == pytest.approx(float(d_crit(alpha, params, "A", adhesion=True)), rel=1e-9)
            else:
                assert math.isnan(depth)


def test_a_local_cluster_gives_the_serial_numbers_bit_for_bit(paper, serial, cluster):
    on_cluster = sweep(GRID, "A", base=paper, scheduler=cluster.scheduler_address, chunk_size=5)
    xr.testing.assert_identical(on_cluster, serial)


def test_a_client_object_the_active_client_and_an_executor_give_the_serial_numbers_bit_for_bit(paper, serial,
                                                                                               cluster):
    """One seam (concurrent.futures): a distributed.Client passed in, the client made current (scheduler=None) and
    a ProcessPoolExecutor; the caller's client and executor stay open."""
    import concurrent.futures

    with _distributed().Client(cluster.scheduler_address) as client:
        xr.testing.assert_identical(sweep(GRID, "A", base=paper, scheduler=client, chunk_size=5), serial)
        xr.testing.assert_identical(sweep(GRID, "A", base=paper, chunk_size=5), serial)  # the active client
        assert client.status == "running"
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        xr.testing.assert_identical(sweep(GRID, "A", base=paper, scheduler=pool, chunk_size=5), serial)
        assert pool.submit(abs, -1).result() == 1  # still open


def test_a_worker_killed_mid_sweep_does_not_change_the_result(paper, serial, cluster):
    killed = []

    def kill_one_worker(done, total):
        if not killed:
            with _distributed().Client(cluster.scheduler_address) as client:
                victim = sorted(client.scheduler_info()["workers"])[0]
                killed.append(victim)
                try:
                    client.run(os._exit, 1, workers=[victim])
                except Exception:  # noqa: BLE001 - the worker dies while answering
                    pass

    result = sweep(GRID, "A", base=paper, scheduler=cluster.scheduler_address, chunk_size=1,
                   progress=kill_one_worker)
    assert killed
    xr.testing.assert_identical(result, serial)
    with _distributed().Client(cluster.scheduler_address) as client:
        client.wait_for_workers(2, timeout=60)  # the nanny has restarted it


def test_an_interrupted_sweep_resumes_and_ends_as_an_uninterrupted_one(paper, serial, tmp_path):
    class Interrupted(Exception):
        pass

    def stop_after_two_chunks(done, total):
        if done >= 10:
            raise Interrupted

    store = tmp_path / "sweep.zarr"
    with pytest.raises(Interrupted):
        sweep(GRID, "A", base=paper, scheduler="serial", chunk_size=5, store=store, progress=stop_after_two_chunks)
    assert int(xr.open_zarr(store, zarr_format=2)["done"].sum()) == 10
    seen = []
    resumed = sweep(GRID, "A", base=paper, scheduler="serial", chunk_size=5, store=store,
                    progress=lambda done, total: seen.append(done))
    assert seen == [12]  # only the third chunk (2 runs) was run again
    xr.testing.assert_identical(resumed, serial)
    whole = tmp_path / "whole.zarr"
    sweep(GRID, "A", base=paper, scheduler="serial", chunk_size=5, store=whole)
    xr.testing.assert_identical(xr.open_zarr(store, zarr_format=2).load(), xr.open_zarr(whole, zarr_format=2).load())


def test_a_store_of_another_sweep_is_not_resumed(paper, tmp_path):
    store = tmp_path / "sweep.zarr"
    sweep({"alpha": [20.0]}, "A", base=paper, scheduler="serial", store=store, quantities=CLOSED_FORM_QUANTITIES)
    with pytest.raises(ValueError, match="holds another sweep"):
        sweep({"alpha": [30.0]}, "A", base=paper, scheduler="serial", store=store, quantities=CLOSED_FORM_QUANTITIES)
    fresh = sweep({"alpha": [30.0]}, "A", base=paper, scheduler="serial", store=store, resume=False,
                  quantities=CLOSED_FORM_QUANTITIES)
    assert int(fresh["failed"].sum()) == 0


def test_a_run_that_raises_is_recorded_and_the_sweep_goes_on(paper):
    """At 1e-6° the path reaches 17 km, where double precision cannot resolve the slip criterion: that run
    refuses (its path is built only when it runs; the grid's values themselves are valid); the other runs."""
    result = sweep({"alpha": [1e-6, 20.0]}, "A", base=paper, scheduler="serial")
    assert result["failed"].values.tolist() == [1, 0]
    assert "cannot resolve the slip criterion" in str(result["error"].values[0])
    assert str(result["error"].values[1]) == ""
    assert math.isnan(float(result["tangential_force_max"][0])) and float(result["tangential_force_max"][1]) > 0
    assert result.attrs["failed_runs"] == 1


def test_a_table_of_parameter_sets_runs_along_set(paper):
    table = [{"tau0": 30e3, "dgamma1": 0.1}, {"tau0": 42e3, "dgamma1": 0.15}]
    result = sweep(table, "B", 60.0, base=paper, scheduler="serial", quantities=("pull_off_force",))
    assert dict(result.sizes) == {"set": 2} and result["dgamma1"].values.tolist() == [0.1, 0.15]
    # the pull-off force of a displacement-controlled JKR contact lies between 0 and the force-controlled one
    for row, params in zip(result["pull_off_force"].values, table):
        assert -1.5 * math.pi * params["dgamma1"] * paper.R < row < 0


def test_the_discrete_method_converges_to_the_continuum_quantities(paper):
    continuum = sweep({"alpha": [20.0]}, "A", base=paper, scheduler="serial", quantities=("tangential_force_max",))
    discrete = sweep({"dx": [4e-6, 2e-6]}, "A", 20.0, base=paper, method="discrete", scheduler="serial",
                     quantities=("tangential_force_max",))
    exact = float(continuum["tangential_force_max"][0])
    errors = np.abs(discrete["tangential_force_max"].values - exact) / exact
    assert errors[1] < errors[0] < 1e-2  # first order: halving Δx about halves the error


@pytest.mark.parametrize("grid, message", [
    ({"mu": [1.0]}, "grid: 'mu' is not a value of this contact (friction=FrictionLaw('tau0'"),
    ({}, "grid={} is not allowed"),
    ({"tau0": []}, "allowed: a non-empty list of finite numbers"),
    ({"tau0": [1e3, float("nan")]}, "allowed: a non-empty list of finite numbers"),
    ({"nu": [0.3, 0.7]}, "Elastomer.nu=0.7 is not allowed"),
    ({"alpha": [20.0, 95.0]}, "grid['alpha'] holds 95.0"),
    ({"tau0": [1e3, 1e3]}, "repeats a value"),
    ({"dx": [1e-6]}, "'dx' is not allowed with method='continuum'"),
    ([{"tau0": 1.0}, {"E": 1.0}], "allowed: the names of grid[0]"),
])
def test_bad_grids_are_named_before_anything_runs(paper, grid, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        sweep(grid, "A", 20.0 if "alpha" not in grid else None, base=paper, scheduler="serial")


def test_other_bad_arguments_are_named(paper):
    with pytest.raises(ValueError, match="scenario='A' needs an angle"):
        sweep({"tau0": [1e3]}, "A", base=paper, scheduler="serial")
    with pytest.raises(ValueError, match="scheduler='nowhere' is not allowed"):
        sweep({"tau0": [1e3]}, "A", 20.0, base=paper, scheduler="nowhere")
    with pytest.raises(ValueError, match="quantities"):
        sweep({"tau0": [1e3]}, "A", 20.0, base=paper, scheduler="serial", quantities=("pressure",))


def test_two_parameter_sets_with_the_same_groups_give_the_same_dimensionless_results(paper):
    """Depths over d_max, angles and F_x,max/(π a_max² τ0) depend on (S, Γ0, Γ1) and α alone: another elastomer
    (ν = 0.3, twice E*), a 4× larger indenter and depth, and works of adhesion and τ0 chosen to keep the groups."""
    other = paper.replace(R=4 * paper.R, d_max=4 * paper.d_max, nu=0.3, E=2 * paper.E_star * (1 - 0.3**2),
                          dgamma0=8 * paper.dgamma0, dgamma1=8 * paper.dgamma1)
    other = other.replace(tau0=paper.tau0 * other.G_star / paper.G_star)
    assert np.allclose(dimensionless_groups(other), dimensionless_groups(paper), rtol=1e-14)
    results = [sweep({"alpha": [10.0, 20.0, 30.0]}, "A", base=params, scheduler="serial") for params in (paper, other)]
    for result, params in zip(results, (paper, other)):
        result["reduced_force"] = result["tangential_force_max"] / (result["contact_area_max"] * params.tau0)
        result["reduced_depth"] = result["slip_onset_in_depth"] / params.d_max
    for name in ("reduced_force", "reduced_depth", "critical_angle_A", "critical_angle_B"):
        np.testing.assert_allclose(results[1][name].values, results[0][name].values, rtol=1e-9, equal_nan=True)
    # and the groups matter: another slip parameter moves the critical angle
    assert me.critical_angle(paper.replace(tau0=2 * paper.tau0), "A") < me.critical_angle(paper, "A") - 1.0


def test_closed_form_quantities_alone_run_no_model(paper):
    """A map of critical angles over 400 parameter sets runs the closed forms only."""
    result = sweep({"tau0": np.linspace(1e4, 1e5, 20), "dgamma0": np.linspace(0.0, 0.05, 20)}, "A", 20.0,
                   base=paper, scheduler="serial", quantities=CLOSED_FORM_QUANTITIES)
    assert set(result.data_vars) == {*CLOSED_FORM_QUANTITIES, "failed", "error"}
    # more friction: the springs hold a larger shift, the path must be flatter to make them slide (tan α_c = d_max/ū)
    assert np.all(np.diff(result["critical_angle_A"].values, axis=0) < 0)
    tau0 = result["tau0"].values
    expected = [me.critical_angle(paper.replace(tau0=value, dgamma0=0.05), "A") for value in tau0]
    np.testing.assert_array_equal(result["critical_angle_A"].sel(dgamma0=0.05).values, expected)


def test_the_universal_map_is_the_same_from_any_base_and_holds_the_papers_angles(paper):
    """The map reached through another base set (another elastomer, indenter and depth) is the same map; at
    the paper's groups it holds the paper's critical angles."""
    from mdr_events.analysis.universal_map import universal_map
    from mdr_events.plotting.universal import plot_universal_map

    groups = dimensionless_groups(paper)
    slip = np.array([0.5, groups.slip, 8.0])
    adhesion = np.array([0.0, groups.adhesion_in, groups.adhesion_out, 0.2])
    other = paper.replace(R=0.1, d_max=1e-3, E=1e6, nu=0.4, dgamma0=0.3, dgamma1=0.9, tau0=1e5)
    maps = [universal_map(slip, adhesion, base, scheduler="serial", marked={"R30": paper})
            for base in (paper, other)]
    for name in ("critical_angle_A", "critical_angle_B"):
        np.testing.assert_allclose(maps[1][name].values, maps[0][name].values, rtol=1e-9)
    assert float(maps[0]["critical_angle_A"].sel(slip=groups.slip, adhesion_in=groups.adhesion_in)) == \
        pytest.approx(me.critical_angle(paper, "A"), rel=1e-12)
    assert float(maps[0]["critical_angle_B"].sel(slip=groups.slip, adhesion_out=groups.adhesion_out)) == \
        pytest.approx(me.critical_angle(paper, "B"), rel=1e-12)
    assert maps[0].attrs["mark_R30_slip"] == groups.slip
    assert len(plot_universal_map(maps[0]).axes) == 4  # two panels and their colour bars


def test_histories_are_the_runs_curves_and_resume_with_the_store(paper, tmp_path):
    """history_samples keeps each run's F_N, F_x, A over its path: the continuum's equal model_curves (another
    solve) bit for bit; a store with histories resumes like any other."""
    from mdr_events.analysis.fit import model_curves
    from mdr_events.limits import DEFAULT_LIMITS
    from mdr_events.models.motion import scenario_paths

    grid = {"alpha": [15.0, 30.0, 60.0]}
    store = tmp_path / "histories.zarr"
    whole = sweep(grid, "A", base=paper, scheduler="serial", chunk_size=1, history_samples=41, store=store)
    assert whole["history_normal_force"].dims == ("alpha", "sample") and whole.sizes["sample"] == 41
    for alpha in grid["alpha"]:
        path = scenario_paths(paper, "A", [alpha])[0][0]
        times = np.linspace(0.0, path.duration, 41)
        expected = model_curves(paper, path, times, me.Tolerances(), DEFAULT_LIMITS, ("tangential_force",)).values
        np.testing.assert_array_equal(whole["history_tangential_force"].sel(alpha=alpha).values,
                                      expected["tangential_force"])
    resumed = sweep(grid, "A", base=paper, scheduler="serial", chunk_size=1, history_samples=41, store=store,
                    progress=lambda done, total: pytest.fail("a finished store runs nothing again"))
    xr.testing.assert_identical(resumed, whole)
    discrete = sweep({"alpha": [30.0]}, "A", base=paper, method="discrete", dx=2e-6, scheduler="serial",
                     history_samples=41, quantities=("contact_area_max",))
    exact = whole["history_contact_area"].sel(alpha=30.0).values
    # from the second sample on: at t = 0 the continuum has jumped in (A = π a0², adhesion), the springs not yet
    # (a contact made is a jump in time that a stepping model meets one step later, as validate leaves it out)
    assert np.nanmax(np.abs(discrete["history_contact_area"].values[0][1:] - exact[1:])) < 0.02 * np.nanmax(exact)


def test_a_store_path_holding_something_else_is_never_overwritten(paper, tmp_path):
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "important.txt").write_text("keep")
    afile = tmp_path / "afile"
    afile.write_text("keep")
    for store in (folder, afile):
        for resume in (True, False):
            with pytest.raises(ValueError, match=re.escape(f"store={str(store)!r} exists and is not a sweep's store")):
                sweep({"alpha": [10.0]}, "A", base=paper, scheduler="serial", quantities=CLOSED_FORM_QUANTITIES,
                      store=store, resume=resume)
    assert (folder / "important.txt").read_text() == "keep" and afile.read_text() == "keep"
    empty = tmp_path / "empty"
    empty.mkdir()
    assert int(sweep({"alpha": [10.0]}, "A", base=paper, scheduler="serial", quantities=CLOSED_FORM_QUANTITIES,
                     store=empty)["failed"].sum()) == 0


@pytest.mark.parametrize("options, message", [
    (dict(workers=0), "workers=0 is not allowed"),
    (dict(workers=-1), "workers=-1 is not allowed"),
    (dict(alpha="abc"), "alpha='abc'"),
    (dict(alpha=120.0), "alpha=120.0 is not allowed"),
    (dict(tolerances="x"), "tolerances='x'"),
])
def test_engine_and_angle_arguments_are_named(paper, options, message):
    arguments = dict(alpha=20.0, scheduler="local", quantities=CLOSED_FORM_QUANTITIES)
    arguments.update(options)
    with pytest.raises((ValueError, TypeError), match=re.escape(message)):
        sweep({"tau0": [1e3]}, "A", base=paper, **arguments)


def test_a_table_may_name_its_fields_in_any_order(paper):
    table = [{"alpha": 10.0, "tau0": 30e3}, {"tau0": 42e3, "alpha": 20.0}]
    result = sweep(table, "A", base=paper, scheduler="serial", quantities=("critical_angle_A",))
    assert result["tau0"].values.tolist() == [30e3, 42e3] and result["alpha"].values.tolist() == [10.0, 20.0]


def test_a_sweep_of_a_power_law_indenter_meets_its_closed_forms(paper):
    """profile=PowerLaw: the onset depths are the power law's (18) to 1e-9 (nan where it lies beyond d_max and
    the run slides later), the critical angles its own, the result names the indenter."""
    from mdr_events.contact.indenters import PowerLaw
    from mdr_events.theory import power_law

    cone = PowerLaw.cone(0.1)
    result = me.sweep({"tau0": [2e4, 4e4], "alpha": [10.0, 40.0]}, "A", base=paper, scheduler="serial", profile=cone)
    assert result.attrs["profile"] == cone.describe()
    for tau0 in (2e4, 4e4):
        params = paper.replace(tau0=tau0)
        assert float(result["critical_angle_A"].sel(tau0=tau0, alpha=10.0)) == power_law.critical_angle_A(cone, params)
        for alpha in (10.0, 40.0):
            expected = float(power_law.d_crit_A(alpha, cone, params, adhesion=True))
            found = float(result["slip_onset_in_depth"].sel(tau0=tau0, alpha=alpha))
            if expected < params.d_max:
                assert found == pytest.approx(expected, rel=1e-9)
            else:
                assert math.isnan(found)


def test_a_power_law_sweep_reports_its_own_pull_off_force_and_refuses_R(paper):
    """The pull-off force is F_N (10) of the power law at the pull-off (the least normal force, its force-control
    minimum, lies below it), not the paraboloid's; sweeping R with a power law is refused by name."""
    from mdr_events.contact.indenters import PowerLaw
    from mdr_events.theory import power_law

    quartic = power_law.with_radius_at(4.0, math.sqrt(paper.R * paper.d_max), paper.d_max)
    result = me.sweep({"alpha": [20.0]}, "A", base=paper, scheduler="serial", profile=quartic,
                      quantities=["pull_off_force", "normal_force_min", "pull_off_depth"])
    depth = float(result["pull_off_depth"].values[0])
    fold = power_law.jump_off(quartic, paper, paper.dgamma1)
    assert depth == pytest.approx(fold["depth"], rel=1e-9)
    assert float(result["pull_off_force"].values[0]) == pytest.approx(fold["normal_force"], rel=1e-9)
    assert float(result["normal_force_min"].values[0]) <= float(result["pull_off_force"].values[0])
    with pytest.raises(ValueError, match=r"grid: .R. is not a value of this contact \(indenter=PowerLaw\(c=2000.0, n=3.0\)\)"):
        me.sweep({"R": [0.01, 0.03]}, "A", 20.0, base=paper, scheduler="serial", profile=PowerLaw(2e3, 3.0))


def test_a_store_that_cannot_be_written_is_named_before_anything_runs(paper, tmp_path):
    """Below a file, a name part longer than a file system takes, or a place the checks cannot foresee (/proc):
    one ValueError naming store, nothing written (not a raw OSError after the runs)."""
    afile = tmp_path / "afile"
    afile.write_text("keep")
    cases = [(afile / "x.zarr", "a file, not a directory"), (tmp_path / ("a" * 300), "more than a file system's 255")]
    if os.path.isdir("/proc/self"):
        cases.append(("/proc/x.zarr", "it lies in /proc"))
    for store, reason in cases:
        with pytest.raises(ValueError, match=re.escape(f"store={str(store)[:40]!r}"[:-1]) + ".*" + re.escape(reason)):
            sweep({"alpha": [10.0]}, "A", base=paper, scheduler="serial", quantities=CLOSED_FORM_QUANTITIES,
                  store=store)
    assert afile.read_text() == "keep" and sorted(p.name for p in tmp_path.iterdir()) == ["afile"]


def test_workers_are_bounded_by_the_cores_and_belong_to_the_local_cluster(paper):
    cores = os.cpu_count() or 1
    with pytest.raises(ValueError, match=re.escape(f"workers={cores + 1} is not allowed; allowed: 1 to {cores}")):
        sweep({"tau0": [1e3]}, "A", 20.0, base=paper, scheduler="local", workers=cores + 1)
    with pytest.raises(ValueError, match=re.escape("workers=1 is not allowed with scheduler='serial'")):
        sweep({"tau0": [1e3]}, "A", 20.0, base=paper, scheduler="serial", workers=1)


def test_a_grid_too_large_is_refused_before_its_outer_product_is_built(paper):
    """10^10 runs: refused at once by the memory limit (the outer product alone would need ~600 GiB)."""
    grid = {"tau0": np.arange(1.0, 1e5 + 1), "E": np.arange(1.0, 1e5 + 1)}
    with pytest.raises(me.ResourceLimitError, match="the grid of 10000000000 runs needs"):
        sweep(grid, "A", 20.0, base=paper, scheduler="serial")


@pytest.mark.parametrize("values, kind", [([True, False], "bool"), (["1e4", "2e4"], "str"), ([1e4, 2j], "complex")])
def test_grid_values_that_are_not_real_numbers_are_named(paper, values, kind):
    with pytest.raises(ValueError, match=re.escape(f"grid['tau0']={values!r} (of {kind} values) is not allowed")):
        sweep({"tau0": values}, "A", 20.0, base=paper, scheduler="serial")


def test_a_scheduler_that_cannot_be_reached_is_named(paper):
    """A raw OSError after dask's connect timeout (shortened here)."""
    with connect_timeout("1s"):
        with pytest.raises(ValueError, match=re.escape("scheduler='tcp://127.0.0.1:1' cannot be reached")):
            sweep({"tau0": [1e3, 2e3]}, "A", 20.0, base=paper, scheduler="tcp://127.0.0.1:1",
                  quantities=CLOSED_FORM_QUANTITIES)


def test_a_closed_client_is_named(paper, cluster):
    client = _distributed().Client(cluster.scheduler_address)
    client.close()
    with pytest.raises(ValueError, match="takes no tasks"):
        sweep({"tau0": [3e4]}, "A", 20.0, base=paper, scheduler=client, quantities=CLOSED_FORM_QUANTITIES)
