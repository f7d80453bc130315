"""The fourth hostile round (issue 32): the values of issue 35 and what the third round's fixes left."""

from __future__ import annotations

import concurrent.futures
import re

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import main
from mdr_events.io.files import write_netcdf
from test_hostile_round_two import one_line

PAPER = me.Parameters.paper()
CONTACT = me.Contact.paper()




@pytest.mark.parametrize("call", [
    lambda: me.simulate(CONTACT, me.Scenario("A", alpha=[5e-324]), "continuum"),
    lambda: me.validate({"time": [0.0, 1.0], "normal_force": [0.0, 1.0]}, PAPER, "A", 5e-324),
    lambda: me.sweep({"tau0": [1e4]}, "A", 5e-324, base=PAPER, scheduler="serial"),
    lambda: me.sweep({"alpha": [5e-324, 20.0]}, "A", base=PAPER, scheduler="serial"),
])
def test_an_angle_whose_tangent_underflows_is_refused_not_divided_by(call):
    """5e-324°: ZeroDivisionError (exit 3 on the command line), or a failed run in a sweep."""
    with pytest.raises(ValueError, match="5e-324"):
        call()


def test_the_method_may_follow_the_motion():
    """simulate(contact, motion, method), as the module documents it, read "continuum" as alpha."""
    assert me.simulate(CONTACT, me.Scenario("A", 20.0), "continuum").attrs["method"] == "continuum"
    assert me.simulate(CONTACT, me.Scenario("A", 20.0), me.Discrete(n_steps=2000, dx=4e-6)).attrs["method"] == \
        "discrete"


@pytest.mark.parametrize("attrs, words", [
    ({}, "attrs lack the attribute 'param_E'"),
    ({"param_E": 1e6, "param_nu": 0.5}, "attrs lack the attribute 'param_R'"),
    ({**CONTACT.to_attrs(), "friction_law": "coulomb"}, "attrs lack the attribute 'friction_mu'"),
    ({**CONTACT.to_attrs(), "profile": "power law"}, "profile='power law' without its shape"),
    ({**CONTACT.to_attrs(), "param_E": "abc"}, "the attribute param_E='abc' is not allowed; allowed: a number"),
    ({**CONTACT.to_attrs(), "friction_law": "bogus"}, "FrictionLaw.law='bogus' is not allowed"),
])
def test_a_contact_s_attributes_that_do_not_describe_one_are_named(attrs, words):
    with pytest.raises(ValueError, match=re.escape(words)):
        me.Contact.from_attrs(attrs)


def test_open_result_refuses_a_file_whose_contact_does_not_add_up(tmp_path):
    """A profile in words without its shape read back as the paraboloid, and validate passed against it."""
    result = me.simulate(PAPER, "A", [20.0], method="continuum")
    for name, change in (("bogus", {"friction_law": "bogus"}), ("shapeless", {"profile": "power law"})):
        path = tmp_path / f"{name}.nc"
        result.assign_attrs(change).to_netcdf(path, engine="scipy")
        with pytest.raises(ValueError, match="do not describe a contact"):
            me.open_result(path)


@pytest.mark.parametrize("call, error, words", [
    (lambda: me.Contact(me.Elastomer(1e6, 0.5), None), TypeError, "Contact.indenter=None"),
    (lambda: me.Contact.from_attrs(None), TypeError, "attrs of type NoneType are not allowed"),
    (lambda: me.Contact.from_parameters({"E": 1}), TypeError, "params={'E': 1} (dict) is not allowed"),
    (lambda: me.FrictionLaw(["tau0"]), ValueError, "FrictionLaw.law=['tau0'] is not allowed"),
    (lambda: me.validate({"time": [0.0, 1.0], "normal_force": [0.0, 1.0]}, PAPER, "A", 20.0, units={"time": ["ms"]}),
     ValueError, "units['time']=['ms'] is not allowed"),
    (lambda: me.validate(me.simulate(PAPER, "A", [10.0, 20.0], method="continuum"), PAPER, "A", 20.0,
                         select={"alpha": [10, 20]}), TypeError, "select['alpha']=[10, 20] (list) is not allowed"),
    (lambda: me.Paths([me.Path([(0.0, 0.0), (0.0, 1e-4)], 1e-6)], v=5.0), TypeError, "unexpected keyword argument 'v'"),
])
def test_values_of_the_wrong_kind_are_named(call, error, words):
    with pytest.raises(error, match=re.escape(words)):
        call()


def test_an_executor_that_is_shut_down_is_named():
    pool = concurrent.futures.ThreadPoolExecutor(1)
    pool.shutdown()
    with pytest.raises(ValueError, match="takes no tasks"):
        me.sweep({"tau0": [1e4]}, "A", 20.0, base=PAPER, scheduler=pool, quantities=("critical_angle_A",))


@pytest.mark.parametrize("change, words", [
    (lambda ds: ds.assign(big=("alpha", np.array([2**62, 1]), {"units": "1", "long_name": "big"})),
     "dataset cannot be written as netCDF-3"),
    (lambda ds: ds.assign_attrs(weird={"a": 1}), "dataset cannot be written as netCDF-3"),
    (lambda ds: ds.assign_attrs(param_E=float("inf")), "dataset: Parameters.E=inf is not allowed"),
])
def test_write_netcdf_refuses_what_it_cannot_write_or_open_result_would_refuse(tmp_path, change, words):
    dataset = change(me.phase_diagram(PAPER, [10.0, 20.0]))
    with pytest.raises(ValueError, match=re.escape(words)):
        write_netcdf(dataset, tmp_path / "out.nc")
    assert list(tmp_path.iterdir()) == []


def test_a_noise_whose_weight_underflows_is_refused():
    data = me.simulate(PAPER, "A", [20.0], method="continuum").isel(alpha=0)
    run = {name: data[name].values for name in ("time", "normal_force", "tangential_force")}
    with pytest.raises(ValueError, match=re.escape("noise['tangential_force']=1e+200 is not allowed")):
        me.fit(run, "A", 20.0, free=["tau0"], start=PAPER, noise={"tangential_force": 1e200},
               time_origin="first_contact")


def test_a_spacing_beyond_double_precision_is_refused(tmp_path, capsys):
    runs = {1e300: {}, 4e-6: {}, 2e-6: {}}
    with pytest.raises(ValueError, match="candidates_by_dx has the spacing\\(s\\) 1e\\+300"):
        me.convergence_study(runs, PAPER, "A", 20.0)
    csv = tmp_path / "run.csv"
    csv.write_text("time,normal_force\n0,0\n1,1\n")
    err = one_line(capsys, main(["validate", str(csv), str(csv), str(csv), "--scenario", "A", "--alpha", "20",
                                 "--dx", "1e300", "4e-6", "2e-6", "--out", str(tmp_path / "o")]))
    assert "--dx 1e+300 is not allowed" in err


def test_a_repeated_csv_header_is_named(tmp_path):
    path = tmp_path / "run.csv"
    path.write_text("time,normal_force,normal_force\n0,0,0\n1,1,1\n")
    with pytest.raises(ValueError, match="the header names 'normal_force' more than once"):
        me.validate(path, PAPER, "A", 20.0)


def test_a_path_that_never_touches_is_named_by_its_label():
    touching = me.Path([(0.0, 0.0), (0.0, 2e-4), (0.0, -1e-4)], 1e-6)
    apart = me.Path([(0.0, -1e-4), (1e-4, -1e-4)], 1e-6)
    with pytest.raises(ValueError, match="scenario path 'b': the path never enters the elastomer"):
        me.simulate(PAPER, {"a": touching, "b": apart}, method="continuum")


def test_a_numpy_tolerance_is_a_number():
    data = me.simulate(PAPER, "A", [20.0], method="continuum").isel(alpha=0)
    run = {name: data[name].values for name in ("time", "normal_force")}
    assert me.validate(run, PAPER, "A", 20.0, tolerance=np.float32(1e-3)).attrs["verdict"] == "pass"


def test_a_table_too_short_for_any_contact_says_so():
    radii = np.linspace(0.0, 5e-3, 5)
    table = me.TabulatedProfile(tuple(radii), tuple(1e-9 * radii / radii[-1]))
    with pytest.raises(ValueError, match="allowed for .*: none: with this adhesion the contact radius reaches the "
                                         "table's last radius above the surface"):
        me.simulate(PAPER, "A", [20.0], profile=table)


def test_a_sweep_refuses_a_value_beyond_double_precision_before_running():
    with pytest.raises(ValueError, match=re.escape("grid: ") + ".*E\\* is 1.33e\\+300 Pa"):
        me.sweep({"E": [1e300]}, "A", 20.0, base=PAPER, scheduler="serial")


@pytest.fixture(scope="module")
def exact_run():
    run = me.simulate(PAPER, "A", [20.0], method="continuum").isel(alpha=0)
    return {name: run[name].values.copy() for name in ("time", "normal_force", "tangential_force", "contact_area",
                                                       "sliding_fraction")}


def zeroed(run, where):
    copy = {name: values.copy() for name, values in run.items()}
    for name in ("normal_force", "tangential_force", "contact_area", "sliding_fraction"):
        copy[name][where] = 0.0
    return copy


@pytest.mark.parametrize("case", ["cut short", "blanked in the middle", "fifteen samples", "area blanked"])
def test_a_run_in_contact_for_less_than_the_exact_one_fails(exact_run, case):
    """Zeros instead of the contact: the samples where one run is in contact were left out of the norms, and a run
    cut short at half its contact passed with every error 0. Now their time counts against the tolerance."""
    inside = np.flatnonzero(exact_run["contact_area"] > 0)
    if case == "cut short":
        run = zeroed(exact_run, slice(1000, None))
    elif case == "blanked in the middle":
        run = zeroed(exact_run, slice(inside[100], inside[-100]))
    elif case == "fifteen samples":
        keep = np.zeros(exact_run["time"].size, bool)
        keep[inside[:: inside.size // 15][:15]] = True
        run = zeroed(exact_run, ~keep & (exact_run["contact_area"] > 0))
    else:
        run = {name: values.copy() for name, values in exact_run.items()}
        run["contact_area"][inside[100]:inside[-100]] = 0.0
    report = me.validate(run, PAPER, "A", 20.0)
    assert report.attrs["verdict"] == "fail" and float(report["contact_differs_share"]) > 0.4


def test_the_exact_run_and_a_fine_discrete_one_keep_their_contact():
    """The share of a discrete run is its pull-off's few samples: far below the tolerance, the verdict its norms'."""
    for run, expected in ((me.simulate(PAPER, "A", [20.0], method="continuum"), 0.0),
                          (me.simulate(PAPER, "A", [20.0], method="discrete", dx=2e-6), 1e-4)):
        report = me.validate(run, PAPER, "A", 20.0)
        assert report.attrs["verdict"] == "pass" and float(report["contact_differs_share"]) <= expected


# --- the fifth round ------------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def exact_columns():
    run = me.simulate(PAPER, "A", [20.0], method="continuum").isel(alpha=0)
    return {name: run[name].values.copy() for name in ("time", "normal_force", "tangential_force", "contact_area",
                                                       "contact_radius", "sliding_fraction")}


@pytest.mark.parametrize("rows", [slice(200, None), slice(1000, None), slice(1800, None), np.r_[0:1000, 2000],
                                  np.r_[0, 1000:2001]], ids=["start cut 10 %", "start cut 50 %", "start cut 90 %",
                                                            "middle cut out", "only the first row before"])
def test_a_run_that_does_not_sample_the_exact_contact_fails(exact_columns, rows):
    """Its samples were the exact values where it had them: a pass. The exact contact's time before the first sample
    and inside gaps of ten median spacings now counts as not matched."""
    report = me.validate({name: values[rows] for name, values in exact_columns.items()}, PAPER, "A", 20.0)
    assert report.attrs["verdict"] == "fail" and float(report["contact_differs_share"]) > 0.09


@pytest.mark.parametrize("change", ["garbage out of contact", "spike at the corner"])
def test_a_sample_left_out_still_lies_within_one_range(exact_columns, change):
    """A left-out sample (contact differs, straddles an event) was not bounded at all: 5 N hidden as "no contact",
    100 ranges after the corner. Within one range is what an event's timing changes (a fine discrete run: 0.2)."""
    run = {name: values.copy() for name, values in exact_columns.items()}
    if change == "garbage out of contact":
        run["normal_force"][1000], run["contact_area"][1000], run["contact_radius"][1000] = 5.0, 0.0, 0.0
    else:
        run["normal_force"][1459] += 100 * float(np.ptp(run["normal_force"]))
    report = me.validate(run, PAPER, "A", 20.0)
    assert report.attrs["verdict"] == "fail" and float(report["left_out_max_error"].max()) > 1.0
    fine = me.validate(me.simulate(PAPER, "A", [20.0], method="discrete", dx=2e-6), PAPER, "A", 20.0)
    assert float(fine["left_out_max_error"].max()) < 0.5


def test_a_store_goes_where_a_file_would(tmp_path):
    """A sweep's store was created in the root; one named with the temporary marker was taken."""
    for store, words in (("/mdr_x.zarr", "it is /, the file system's root"),
                         (tmp_path / ".x.mdr-tmp-1.zarr", "its name holds '.mdr-tmp-'")):
        with pytest.raises(ValueError, match=re.escape(words)):
            me.sweep({"tau0": [3e4]}, "A", 20.0, base=PAPER, scheduler="serial", store=store,
                     quantities=("critical_angle_A",))
    with pytest.raises(ValueError, match="control character"):
        write_netcdf(me.phase_diagram(PAPER, [10.0]), tmp_path / "a\nb.nc")


@pytest.mark.parametrize("call, error, words", [
    (lambda: CONTACT.value(1), TypeError, "name=1 (int) is not allowed"),
    (lambda: me.Contact.from_attrs({**CONTACT.to_attrs(), "param_E": 10**400}), ValueError, "param_E="),
    (lambda: me.Contact.from_attrs({**CONTACT.to_attrs(), "param_E": True}), ValueError, "param_E=True"),
    (lambda: me.Contact.from_attrs(me.simulate(PAPER, "A", [20.0], method="continuum")), TypeError,
     "attrs of type Dataset are not allowed"),
    (lambda: me.Paths(None), TypeError, "paths=None (NoneType) is not allowed"),
    (lambda: me.Scenario(np.array(["A", "B"])), ValueError, "is not allowed"),
    (lambda: me.sweep({"tau0": [3e4]}, "A", 20.0, base=PAPER, scheduler="tcp://"), ValueError,
     "scheduler='tcp://' is not allowed: missing port number"),
    (lambda: me.simulate(CONTACT, "A", "20"), TypeError, "alpha='20' (of str values) is not allowed"),
    (lambda: me.simulate(CONTACT, "A", me.Continuum(), method="discrete"), ValueError, "allowed: one method"),
    (lambda: me.Paths.named_by([me.Path([(0.0, 0.0), (0.0, 1e-4)], 1e-6)], -1.0, 1e-6), ValueError, "d_max=-1.0"),
    (lambda: me.Discrete(dx=float("nan")), ValueError, "dx=nan is not allowed"),
    (lambda: me.sweep({"tau0": [3e4]}, "A", 20.0, base=PAPER, method="continuum", dx=1e-6), ValueError,
     "dx is not allowed with method='continuum'; allowed: tolerances"),
    (lambda: CONTACT.replace(E=1e6, **{"elastomer.E": 2e6}), ValueError, "which another name changes too"),
    (lambda: me.Contact.from_parameters(PAPER, profile="cone"), TypeError, "profile='cone' (str) is not allowed"),
    (lambda: me.convergence_study({8e-6: {}, 4e-6: {}, 2e-6: {}}, PAPER, "A", 20.0, foo=1), TypeError,
     "convergence_study() got an unexpected keyword argument 'foo'"),
    (lambda: me.sweep({"tau0": [3e4]}, "A", 20.0, base=PAPER, scheduler="serial", resume="yes"), TypeError,
     "resume='yes' is not allowed"),
])
def test_the_fifth_round_s_values_are_named(call, error, words):
    with pytest.raises(error, match=re.escape(words)):
        call()


def test_continuum_values_compare_by_value_and_paths_say_their_labels():
    assert me.Continuum() == me.Continuum() and me.Continuum(t=[0.0, 1.0]) == me.Continuum(t=[0.0, 1.0])
    assert me.Continuum(samples=5) != me.Continuum()
    path = me.Path([(0.0, 0.0), (0.0, 1e-4)], 1e-6)
    assert repr(me.Paths({"in": path, "again": path})) == "Paths(<2 paths: 'in', 'again'>)"


def test_a_file_of_several_runs_points_to_select_and_a_paraboloid_profile_to_its_place():
    several = me.simulate(PAPER, "A", [10.0, 20.0], method="continuum")
    path = me.Path.scenario_A(20.0, PAPER)
    with pytest.raises(ValueError, match=re.escape("select={'alpha': its angle}")):
        me.validate(several, PAPER, path)
    with pytest.raises(TypeError, match=re.escape("the paraboloid is Parameters.R's: leave profile=None")):
        me.simulate(PAPER, "A", [20.0], profile=me.Paraboloid(0.03))
