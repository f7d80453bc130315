"""The seventh hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.fit import synthetic_measurement
from mdr_events.app.cli import main

PAPER = me.Parameters.paper()
CONTACT = me.Contact.paper()


@pytest.fixture(scope="module")
def exact_run():
    """The continuum's own run of scenario A at 20° (every quantity, s from first contact): it passes."""
    run = me.simulate(CONTACT, me.Scenario("A", 20.0), "continuum").isel(alpha=0)
    names = ("normal_force", "tangential_force", "contact_area", "contact_radius")
    return {"time": run["time"].values, **{name: run[name].values for name in names}}


# --- R1: the referee, a tangential force alone with the contact's start cut off ------------------------------------
@pytest.mark.parametrize("rows, share", [(slice(300, None), 0.15), (np.r_[0:800, 1200:2001], 0.2)])
def test_a_tangential_force_alone_with_the_contact_cut_out_fails(exact_run, rows, share):
    """A tangential force alone does not show the contact, but its time axis shows what it does not sample: 15 % of
    the contact's start or 20 % of its middle cut out passed (the share was nan, not judged)."""
    run = {"time": exact_run["time"][rows], "tangential_force": exact_run["tangential_force"][rows]}
    report = me.validate(run, CONTACT, "A", 20.0)
    assert report.attrs["verdict"] == "fail"
    assert float(report["contact_differs_share"]) == pytest.approx(share, abs=0.01)
    whole = me.validate({"time": exact_run["time"], "tangential_force": exact_run["tangential_force"]}, CONTACT,
                        "A", 20.0)
    assert whole.attrs["verdict"] == "pass" and float(whole["contact_differs_share"]) == 0.0


# --- R2: a Dataset's column of complex numbers or timedeltas was read as real seconds or numbers ---------------------
@pytest.mark.parametrize("make, names, words", [
    (lambda run: xr.Dataset({"normal_force": ("time", run["normal_force"] + 1j)}, coords={"time": run["time"]}),
     None, "column 'normal_force' holds complex128 values; allowed: real numbers"),
    (lambda run: xr.Dataset({"normal_force": ("time", run["normal_force"])},
                            coords={"time": pd.to_timedelta(run["time"], unit="s")}),
     None, "column 'time' holds timedelta64[ns] values; allowed: real numbers (timedeltas: give seconds"),
    (lambda run: xr.Dataset({"Fn": ("time", run["normal_force"] + 0j)}, coords={"time": run["time"]}),
     {"normal_force": "Fn"}, "column 'Fn' holds complex128 values"),
    (lambda run: {"time": run["time"], "normal_force": run["normal_force"]}, {"time": ["t"]},
     "names['time']=['t'] (list) is not allowed; allowed: a column's name (str)"),
])
def test_a_column_that_is_not_of_real_numbers_is_named(exact_run, make, names, words):
    """The imaginary part was dropped silently (a pass), timedeltas were read in nanoseconds as seconds (a message on
    the time's unit), a list as a column's name was a raw TypeError (unhashable)."""
    with pytest.raises(TypeError) as raised:
        me.validate(make(exact_run), CONTACT, "A", 20.0, names=names)
    assert words in str(raised.value)


def test_another_column_of_timestamps_is_left_alone(exact_run):
    stamps = pd.to_datetime(exact_run["time"], unit="s")
    run = xr.Dataset({"normal_force": ("time", exact_run["normal_force"]), "stamp": ("time", stamps)},
                     coords={"time": exact_run["time"]})
    assert me.validate(run, CONTACT, "A", 20.0).attrs["verdict"] == "pass"


# --- C1: a limits of another type was an AttributeError in convergence_study and solve_path -------------------------
@pytest.mark.parametrize("call", [
    lambda limits, run: me.convergence_study({1e-6: run, 2e-6: run, 4e-6: run}, CONTACT, "A", 20.0, limits=limits),
    lambda limits, run: me.continuum.solve_path(PAPER, me.Path.scenario_A(20.0, PAPER), limits=limits),
    lambda limits, run: me.simulate(CONTACT, me.Scenario("A", 20.0), "continuum", limits=limits),
    lambda limits, run: me.phase_diagram(CONTACT, [10.0, 20.0], limits=limits),
    lambda limits, run: me.sweep({"tau0": [3e4]}, CONTACT, "A", 20.0, limits=limits,
                                 output=me.SweepOutput(quantities=("critical_angle_A",)),
                                 engine=me.Engine(scheduler="serial")),
])
def test_every_function_of_limits_names_one_of_another_type_and_takes_none(exact_run, call):
    """convergence_study and solve_path: AttributeError ('str' object has no attribute 'check'); phase_diagram and
    sweep refused None, which validate, fit and simulate take for the defaults."""
    with pytest.raises(TypeError, match=r"limits='x' \(str\) is not allowed; allowed: a mdr_events.Limits"):
        call("x", exact_run)
    call(None, exact_run)


# --- C2: the CLI, an option given twice: the last one won silently ---------------------------------------------------
@pytest.mark.parametrize("argv, words", [
    (["simulate", "--scenario", "A", "--alpha", "20", "--alpha", "30"],
     "argument --alpha: given twice ([20.0] and [30.0]); allowed: once, with every value after it (--alpha 20.0 30.0)"),
    (["simulate", "--scenario", "A", "--scenario", "B"], "argument --scenario: given twice ('A' and 'B')"),
    (["simulate", "--scenario", "A", "--E", "1e6", "--E", "2e6"],
     "argument --E: given twice (1000000.0 and 2000000.0)"),
    (["derive", "--key", "jkr_depth", "--key", "jkr_radius"], "argument --key: given twice ('jkr_depth' and"),
    (["validate", "run.csv", "--scenario", "A", "--alpha", "20", "--tolerance", "1e-3", "--tolerance", "1e-2"],
     "argument --tolerance: given twice (0.001 and 0.01)"),
    (["fit", "run.csv", "--scenario", "A", "--alpha", "20", "--free", "tau0", "--free", "E"],
     "argument --free: given twice (['tau0'] and ['E']); allowed: once, with every value after it (--free tau0 E)"),
])
def test_an_option_given_twice_is_refused_in_one_line(tmp_path, capsys, argv, words):
    out = [] if argv[0] == "derive" else ["--out", str(tmp_path / "out")]
    assert main([*argv, *out]) == 2
    error = capsys.readouterr().err.strip().splitlines()
    assert len(error) == 1 and words in error[0]
    assert not (tmp_path / "out").exists()


def test_an_option_that_takes_several_values_takes_them_after_one_flag(tmp_path, capsys):
    assert main(["validate", str(tmp_path / "a.csv"), "--scenario", "A", "--alpha", "20", "--limit", "steps=1e8",
                 "--limit", "samples=1e8", "--out", str(tmp_path / "out")]) == 2
    assert "a.csv': no such file" in capsys.readouterr().err  # (the repeatable --limit reached the run's file)


# --- C3: a CSV with blank lines was refused; its errors named the wrong line after comments -------------------------
@pytest.fixture()
def csv_lines(exact_run):
    header = ",".join(exact_run)
    return [header] + [",".join(repr(float(exact_run[name][i])) for name in exact_run)
                       for i in range(exact_run["time"].size)]


@pytest.mark.parametrize("change", [
    lambda lines: lines + ["", ""],                       # an editor's or a spreadsheet's blank lines at the end
    lambda lines: lines[:50] + ["", "   "] + lines[50:],  # blank lines inside
    lambda lines: ["# written by my simulator", ""] + lines,
])
def test_blank_lines_in_a_csv_are_skipped(tmp_path, csv_lines, change):
    path = tmp_path / "run.csv"
    path.write_text("\n".join(change(csv_lines)) + "\n")
    assert me.validate(path, CONTACT, "A", 20.0).attrs["verdict"] == "pass"


@pytest.mark.parametrize("bad, words", [("abc", "line 9, column 'normal_force': 'abc' is not a number"),
                                        (None, "line 9 has 6 fields; allowed: 5 as in the header")])
def test_a_csv_error_names_the_file_s_own_line(tmp_path, csv_lines, bad, words):
    """Three comment lines before the sixth data row: the error said line 6 of a file whose line 9 it was."""
    row = csv_lines[5].split(",")
    if bad is None:
        row.append("1")
    else:
        row[1] = bad
    lines = csv_lines[:5] + ["# a comment", "", "# another"] + [",".join(row)] + csv_lines[6:]
    path = tmp_path / "run.csv"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError) as raised:
        me.validate(path, CONTACT, "A", 20.0)
    assert words in str(raised.value)


# --- C4: a fit whose residuals overflow: a RuntimeWarning and "Parameters.tau0=nan" --------------------------------
@pytest.mark.parametrize("noise", [None, {"normal_force": 1e-200}])
def test_a_fit_whose_residuals_would_overflow_is_refused_naming_the_magnitudes(noise):
    """Curves of 1e-200 N (a wrong unit): their estimated (or given) noise made the residuals 1e202, the optimizer's
    steps nan, and the error named a tau0=nan the user never gave."""
    measured = synthetic_measurement(CONTACT, "A", 20.0, times=np.linspace(0, 1300, 201), relative_noise=0.01,
                                     seed=1)
    tiny = {"time": measured["time"].values, **{name: measured[name].values * 1e-200 for name in measured.data_vars}}
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(ValueError) as raised:
            me.fit(tiny, CONTACT.replace(tau0=30e3), "A", 20.0, free=("tau0",), time_origin="path_start",
                   noise=noise)
    message = str(raised.value)
    assert "normal_force's residual (model − measured)/σ reaches" in message and "check the data's unit" in message
    assert "nan" not in message


def test_the_residual_bound_keeps_the_normal_equations_finite():
    from mdr_events.analysis.fit_problem import largest_residual

    samples = 10_000
    bound = largest_residual(samples)
    column = 2.0 * bound / 1e-6  # (the forward difference of FD_STEP = 1e-6 of a residual of the bound, doubled)
    assert np.isfinite(samples * column**2) and not np.isfinite(samples * (2.0 * column)**2 * 2.0)


# --- C5: the closed forms took a negative work of adhesion or radius and magnitudes beyond the double range --------
@pytest.mark.parametrize("call, words", [
    (lambda: me.pull_off_force(CONTACT, -1.0), "work_of_adhesion=-1.0 is not allowed"),     # gave +0.14 N
    (lambda: me.jump_off(CONTACT, -1.0), "work_of_adhesion=-1.0 is not allowed"),           # gave nan
    (lambda: me.jkr_depth(1e-4, CONTACT, -0.1), "work_of_adhesion=-0.1 is not allowed"),
    (lambda: me.critical_shift(-1e-3, CONTACT), "contact_radius=-0.001 is not allowed"),    # gave -2.3e-4 m
    (lambda: me.critical_shift(np.array([1e-4, -1e-3]), CONTACT), "contact_radius=array([ 0.0001, -0.001 ])"),
    (lambda: me.fretting_dissipated_energy(1e-3, -1e-4, CONTACT), "amplitude=-0.0001 is not allowed"),
    (lambda: me.jkr_depth(1e300, CONTACT, 0.1), "contact_radius=1e+300 is not allowed"),    # gave inf
    (lambda: me.pull_off_force(CONTACT, 1e200), "work_of_adhesion=1e+200 is not allowed"),
    (lambda: me.jkr_depth(1.2e154, CONTACT, 0.1), "jkr_depth(contact_radius=1.2e+154, work_of_adhesion=0.1) is not "
                                                "allowed: its result overflows double precision"),
    (lambda: me.tabulated.pull_off_force(me.TabulatedProfile(np.linspace(0, 4e-3, 41),
                                                             np.linspace(0, 4e-3, 41)**2 / 0.06), PAPER, -1.0),
     "work_of_adhesion=-1.0 is not allowed; allowed: a finite number >= 0 (J/m²), at most 1.3e+154"),   # gave nan
])
def test_the_closed_forms_refuse_what_the_parameters_refuse(call, words):
    with pytest.raises(ValueError) as raised:
        call()
    assert words in str(raised.value)


# --- C6: a bool among the numbers of a list was read as 1 (an angle of 1°, a time of 1 s, a coordinate of 1 m) ------
@pytest.mark.parametrize("call, error, words", [
    (lambda: me.Scenario("A", [True, 20]), TypeError, "alpha=[True, 20] (holding a bool) is not allowed"),
    (lambda: me.phase_diagram(CONTACT, [True, 30.0]), TypeError, "alpha=[True, 30.0] (holding a bool) is not allowed"),
    (lambda: me.Path([(True, 0), (0, 3e-4), (0, -1e-4)], 1e-6), TypeError,
     "waypoints=[(True, 0), (0, 0.0003), (0, -0.0001)]"),
    (lambda: me.Path([(np.bool_(True), 0), (0, 3e-4), (0, -1e-4)], 1e-6), TypeError,
     "(holding a bool) is not allowed"),
    # (the times are read when the run starts, counted against its limits first: round twenty-three V3)
    (lambda: me.simulate(CONTACT, "A", 20.0, me.Continuum(t=[0, True, 2])), TypeError,
     "t=[0, True, 2] (holding a bool) is not allowed"),
    (lambda: me.sweep({"tau0": [True, 3e4]}, CONTACT, "A", 20.0, engine=me.Engine(scheduler="serial"),
                      output=me.SweepOutput(quantities=("critical_angle_A",))), ValueError,
     "grid['tau0']=[True, 30000.0]"),
    (lambda: synthetic_measurement(CONTACT, "A", 20.0, times=[0, True, 5]), TypeError, "times=[0, True, 5]"),
    (lambda: me.d_crit([True, 20], CONTACT), TypeError, "alpha=[True, 20] (holding a bool)"),
])
def test_a_bool_among_numbers_is_named(call, error, words):
    """A bool alone was refused (alpha=True); NumPy turned one in a list into the number 1 and the run went on (the
    sweep's grid names its values' errors as ValueError)."""
    with pytest.raises(error) as raised:
        call()
    assert words in str(raised.value)


# --- C7: a scheduler's address of an unknown protocol was said to need certificates or UCX ---------------------------
@pytest.mark.parametrize("address, words", [
    ("foo://host:1", "foo:// is no protocol of a dask scheduler; allowed: an address of tcp://"),
    ("http://host:1", "http:// is no protocol of a dask scheduler"),
    ("tls://host:1", "its protocol needs a setup of its own (certificates for tls://, UCX for ucx://)"),
])
def test_a_scheduler_s_protocol_is_named_for_what_it_is(address, words):
    with pytest.raises(ValueError) as raised:
        me.Engine(scheduler=address)
    assert words in str(raised.value)


# --- C8: the continuum solution's functions took any times: a time before the first contact extrapolated -----------
@pytest.fixture(scope="module")
def solution():
    return me.continuum.solve_path(PAPER, me.Path.scenario_A(20.0, PAPER))


@pytest.mark.parametrize("times, error, words", [
    ([-5.0], ValueError, "times=[-5.0] is not allowed; allowed: one time or a 1-D array of finite times >= -0 (s "
                         "from first contact: the path's start"),
    ([np.nan], ValueError, "times=[nan] is not allowed"),
    ("abc", TypeError, "times='abc' (of str values) is not allowed"),           # could not convert string to float
    ([[1.0, 2.0]], ValueError, "times=[[1.0, 2.0]] is not allowed"),          # IndexError
])
def test_evaluate_refuses_times_the_solution_does_not_cover(solution, times, error, words):
    """At -5 s (before the path's start, at the first contact) it gave F_N = -1.41 mN, extrapolated; 'abc' and a 2-D
    grid were NumPy's errors (ValueError: could not convert, IndexError)."""
    with pytest.raises(error) as raised:
        me.continuum.evaluate(solution, times)
    assert words in str(raised.value)


@pytest.mark.parametrize("start, end, error, words", [
    (100.0, 50.0, ValueError, "start=100.0 and end=50.0 are not allowed; allowed: start <= end"),   # 0 J
    (float("nan"), 50.0, ValueError, "start=nan is not allowed; allowed: a finite time >= -0 (s from first"),
    (-10.0, None, ValueError, "start=-10.0 is not allowed"),
    ("abc", None, TypeError, "start='abc' (str) is not allowed"),                                      # float('abc')
])
def test_the_tangential_work_names_its_bounds(solution, start, end, error, words):
    with pytest.raises(error) as raised:
        me.continuum.tangential_work(solution, start, end)
    assert words in str(raised.value)
    assert me.continuum.tangential_work(solution, None, None) == me.continuum.tangential_work(solution, 0.0,
                                                                                             solution.end_time)


def test_before_the_first_contact_a_solution_is_out_of_contact():
    """A path that starts 100 s above the surface: its times before the first contact were the first span's values
    extrapolated back (a force where there is no contact); now the path's position, forces and radius 0."""
    path = me.Path([(0.0, -1e-4), (0.0, 3e-4), (0.0, -2e-4)], 1e-6)
    solution = me.continuum.solve_path(PAPER, path)
    out = me.continuum.evaluate(solution, [-100.0, -50.0, 0.0])
    assert list(out["normal_force"][:2]) == [0.0, 0.0] and list(out["contact_radius"][:2]) == [0.0, 0.0]
    # (the depth from the path's clock, t_contact - 100 s: its round-off, a few ulp of the time over the speed)
    np.testing.assert_allclose(out["indentation_depth"][:2], [-1e-4, -5e-5], rtol=64 * np.finfo(float).eps, atol=0)
    assert out["contact_radius"][2] > 0.0
    with pytest.raises(ValueError, match=r"times=\[-101.0\] is not allowed; allowed: .* finite times >= -100"):
        me.continuum.evaluate(solution, [-101.0])


def test_a_file_path_with_a_trailing_separator_is_refused_and_nothing_is_written(tmp_path):
    """``write_netcdf('x.nc/')`` wrote ``x.nc`` (pathlib drops the separator): a path naming a directory is refused."""
    dataset = me.simulate(me.Contact.paper(), me.Scenario("A", 20.0), "continuum", samples=11)
    with pytest.raises(ValueError, match=r"path='.*x\.nc/' is not allowed \(a trailing separator names a directory\)"):
        me.write_netcdf(dataset, f"{tmp_path}/x.nc/")
    assert list(tmp_path.iterdir()) == []
