"""The contact, the motion and the method as values (issue 35): simulate(contact, motion, method) gives the numbers
of the keywords of before, bit for bit; each value checks its own options; the keywords convert in one place."""

from __future__ import annotations

import re

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.models.methods import as_method
from mdr_events.models.motion import as_motion

PAPER = me.Parameters.paper()
CONTACT = me.Contact.paper()
FAST_DISCRETE = dict(dx=4e-6, n_steps=2000)


def same_numbers(new: xr.Dataset, old: xr.Dataset) -> None:
    """Every variable and coordinate identical, bit for bit."""
    assert set(new.variables) == set(old.variables)
    for name in old.variables:
        np.testing.assert_array_equal(new[name].values, old[name].values, err_msg=name)


@pytest.mark.parametrize("method, options", [("continuum", {}), ("discrete", FAST_DISCRETE)])
def test_a_contact_and_a_scenario_give_the_keywords_numbers_and_attributes(method, options):
    old = me.simulate(PAPER, "A", alpha=[20.0, 50.0], method=method, **options)
    new = me.simulate(CONTACT, me.Scenario("A", alpha=[20.0, 50.0]), method=method, **options)
    same_numbers(new, old)
    assert new.attrs == old.attrs  # the paper's contact stamps what its Parameters did
    by_value = me.simulate(CONTACT, me.Scenario("A", alpha=[20.0, 50.0]),
                           method=me.Continuum() if method == "continuum" else me.Discrete(**options))
    same_numbers(by_value, old)


def test_another_indenter_and_law_give_the_keywords_numbers_and_name_only_what_they_use():
    cone, coulomb = me.PowerLaw.cone(0.1), me.FrictionLaw("coulomb", mu=0.3)
    old = me.simulate(PAPER, "B", alpha=[60.0], profile=cone, friction=coulomb, **FAST_DISCRETE)
    contact = me.Contact(me.Elastomer(PAPER.E, PAPER.nu), cone, me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                         coulomb)
    new = me.simulate(contact, me.Scenario("B", alpha=60.0), **FAST_DISCRETE)
    same_numbers(new, old)
    assert "param_R" in old.attrs and "param_R" not in new.attrs  # the cone has no radius
    assert new.attrs["profile"] == old.attrs["profile"] and new.attrs["friction_law"] == "coulomb"


def test_custom_paths_as_a_motion():
    path = me.Path([(0.0, -1e-5), (1e-4, 2e-4), (3e-4, 2e-4), (3e-4, -1e-4)], 1e-6)
    old = me.simulate(PAPER, {"zig": path}, method="continuum")
    new = me.simulate(CONTACT, me.Paths.named_by({"zig": path}, PAPER.d_max, PAPER.v), method="continuum")
    same_numbers(new, old)
    assert new.attrs == old.attrs
    default = me.Paths([path])
    assert list(default.paths) == ["path 1"] and default.d_max == 2e-4 and default.v == 1e-6  # its own


@pytest.mark.parametrize("make, words", [
    (lambda: me.Scenario("C"), "scenario='C' is not allowed"),
    (lambda: me.Scenario("A", alpha=[10.0, 10.0]), "alpha=[10.0, 10.0] repeats 10.0"),
    (lambda: me.Scenario("A", alpha=95.0), "alpha"),
    (lambda: me.Scenario("A", d_max=-1.0), "d_max=-1.0 is not allowed; allowed: a finite number > 0 (m)"),
    (lambda: me.Scenario("A", final_depth=1e-3), "final_depth=0.001 is not allowed with scenario 'A'"),
    (lambda: me.Scenario("B+", final_depth=1e-4), "final_depth=0.0001 is not allowed; allowed: a finite number > "
                                                   "d_max = 0.0003 (m)"),
    (lambda: me.Paths([]), "it holds no path"),
    (lambda: me.Paths([me.Path([(0.0, -1.0), (1.0, -2.0)], 1.0)]), "scenario path 'path 1' never enters the elastomer"),
    (lambda: me.Paths([me.Path([(0.0, 0.0), (0.0, 1e-4)], 1e-6)], v=5.0), "unexpected keyword argument 'v'"),
    (lambda: as_motion(me.Scenario("A"), alpha=20.0), "alpha=20.0 is not allowed beside motion=Scenario("),
    (lambda: as_motion(me.Path([(0.0, 0.0), (0.0, 1e-4)], 1e-6), alpha=20.0), "alpha=20.0 is not allowed with "
                                                                              "custom paths"),
    (lambda: as_motion(3.0), "scenario=3.0 (float) is not allowed"),
])
def test_a_motion_checks_itself_when_made(make, words):
    with pytest.raises((TypeError, ValueError), match=re.escape(words)):
        make()


def test_the_scenario_s_final_depth_reaches_the_path():
    params = PAPER
    deeper = me.Scenario("B+", alpha=30.0, final_depth=3 * params.d_max).cases(params)
    assert deeper.paths[0].max_depth == 3 * params.d_max
    assert me.Scenario("B+", alpha=30.0).cases(params).paths[0].max_depth == 2 * params.d_max


@pytest.mark.parametrize("method, options, words", [
    ("continuum", {"dx": 1e-6}, "dx is not allowed with method='continuum'; allowed: tolerances, samples, t"),
    ("discrete", {"samples": 10}, "samples is not allowed with method='discrete'; allowed: dx, dt, n_steps"),
    ("discrete", {"dt": 1.0, "n_steps": 100}, "give dt or n_steps, not both"),
    ("discrete", {"n_steps": 5}, "n_steps=5"),
    ("continuum", {"samples": 1}, "samples=1"),
    ("continuum", {"tolerances": "x"}, "tolerances='x' is not allowed"),
    ("springs", {}, "method='springs' is not allowed; allowed: 'discrete', 'continuum'"),
    (me.Continuum(), {"samples": 10}, "samples is not allowed beside method=Continuum("),
])
def test_a_method_takes_only_its_own_options(method, options, words):
    with pytest.raises((TypeError, ValueError), match=re.escape(words)):
        as_method(method, options)


def test_a_method_s_times_within_the_default_limits_are_checked_when_it_is_made():
    """The continuum's ``t`` within the default limits is read, checked and kept as a read-only copy when the method
    is made (round twenty-four: a method that aliased the caller's array changed under it); more times than that are
    counted by the run before it reads them (round twenty-three V3, tests/test_hostile_round_twenty_four.py)."""
    with pytest.raises(ValueError, match=re.escape("t=[1.0, 0.5] is not allowed")):
        as_method("continuum", {"t": [1.0, 0.5]})
    times = as_method("continuum", {"t": [0.5, 1.0]}).output_times(1, me.Limits())
    assert times.tolist() == [0.5, 1.0] and not times.flags.writeable


def test_options_left_none_are_the_method_s_defaults():
    assert as_method("discrete", {"dx": None, "dt": None}) == me.Discrete()
    assert as_method("continuum", {"samples": None}).samples == 2001


@pytest.mark.parametrize("keyword", ["profile", "friction"])
def test_a_contact_holds_its_indenter_and_law_so_the_keywords_are_refused_beside_it(keyword):
    value = me.PowerLaw.cone(0.1) if keyword == "profile" else "tau0"
    with pytest.raises(ValueError, match=re.escape(f"{keyword}=") + ".*is not allowed beside a Contact"):
        me.simulate(CONTACT, "A", 20.0, **{keyword: value})


def test_a_scenario_s_name_beside_a_contact_takes_the_paper_s_depth_and_speed():
    assert as_motion("A", 20.0) == me.Scenario("A", (20.0,), PAPER.d_max, PAPER.v)
    same_numbers(me.simulate(CONTACT, "A", 20.0, method="continuum"),
                 me.simulate(PAPER, "A", 20.0, method="continuum"))
