"""sweep takes the contact, the motion and the method as values (issue 35): the same numbers as the keywords of
before, grids of dotted names, an Engine and a SweepOutput, and what does not fit named."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.sweep import sweep_job

PAPER = me.Parameters.paper()
SERIAL = me.Engine(scheduler="serial")


def same_numbers(new: xr.Dataset, old: xr.Dataset) -> None:
    assert dict(new.sizes) == dict(old.sizes)
    for name in old.variables:
        np.testing.assert_array_equal(new[name].values, old[name].values, err_msg=name)


def test_a_contact_and_a_scenario_give_the_keywords_sweep():
    grid = {"tau0": [30e3, 55e3], "alpha": [20.0, 60.0]}
    old = me.sweep(grid, "A", base=PAPER, scheduler="serial")
    new = me.sweep(grid, me.Contact.paper(), "A", engine=SERIAL)
    same_numbers(new, old)
    assert new.attrs == old.attrs  # (the paper's contact stamps the paper's parameters)
    same_numbers(me.sweep({"tau0": [30e3, 55e3]}, me.Contact.paper(), me.Scenario("A", 20.0), engine=SERIAL),
                 me.sweep({"tau0": [30e3, 55e3]}, "A", 20.0, base=PAPER, scheduler="serial"))


def test_dotted_names_sweep_the_friction_law_and_the_elastomer():
    """μ of Coulomb's law (no adhesion in the continuum) by its dotted name: each run is the law at that μ."""
    contact = me.Contact.from_parameters(PAPER.replace(dgamma0=0.0, dgamma1=0.0), friction=me.FrictionLaw("coulomb", 0.3))
    result = me.sweep({"friction.mu": [0.2, 0.5], "elastomer.E": [1.0e6, 2.0e6]}, contact, me.Scenario("A", 30.0),
                      engine=SERIAL, quantities=("tangential_force_max", "normal_force_min"))
    assert result["friction.mu"].attrs["units"] == "1" and result["elastomer.E"].attrs["units"] == "Pa"
    for mu in (0.2, 0.5):
        for E in (1.0e6, 2.0e6):
            one = me.sweep({"alpha": [30.0]}, PAPER.replace(E=E, dgamma0=0.0, dgamma1=0.0), "A", engine=SERIAL,
                           friction=me.FrictionLaw("coulomb", mu), quantities=("tangential_force_max",
                                                                                 "normal_force_min"))
            for name in ("tangential_force_max", "normal_force_min"):
                assert float(result[name].sel({"friction.mu": mu, "elastomer.E": E})) == float(one[name][0])


def test_a_method_value_gives_the_keywords_discrete_sweep():
    grid = {"dx": [4e-6, 2e-6]}
    old = me.sweep(grid, "A", 20.0, base=PAPER, method="discrete", scheduler="serial",
                   quantities=("tangential_force_max",))
    same_numbers(me.sweep(grid, me.Contact.paper(), "A", 20.0, me.Discrete(), engine=SERIAL,
                          quantities=("tangential_force_max",)), old)
    # without dx the keywords of before took simulate's default step; with dx the step follows the spacing
    default = me.sweep({"tau0": [42e3]}, "A", 20.0, base=PAPER, method="discrete", scheduler="serial",
                       quantities=("tangential_force_max",))
    same_numbers(default, me.sweep({"tau0": [42e3]}, me.Contact.paper(), "A", 20.0, me.Discrete(n_steps=10_000),
                                   engine=SERIAL, quantities=("tangential_force_max",)))


def test_a_depth_and_a_speed_are_the_motions():
    grid = {"d_max": [0.2e-3, 0.3e-3], "v": [1e-6, 2e-6]}
    quantities = ("pull_off_time", "tangential_force_max")
    old = me.sweep(grid, "A", 20.0, base=PAPER, scheduler="serial", quantities=quantities)
    new = me.sweep(grid, me.Contact.paper(), me.Scenario("A", 20.0), engine=SERIAL, quantities=quantities)
    same_numbers(new, old)
    # twice the speed: half the time
    assert float(new["pull_off_time"].sel(d_max=0.3e-3, v=2e-6)) == pytest.approx(
        float(new["pull_off_time"].sel(d_max=0.3e-3, v=1e-6)) / 2, rel=1e-9)


def test_an_engine_and_an_output_are_the_keywords_one_by_one(tmp_path):
    grid = {"tau0": [30e3, 55e3, 70e3]}
    calls = []
    engine = me.Engine(scheduler="serial", chunk_size=2, progress=lambda done, runs: calls.append((done, runs)))
    output = me.SweepOutput(quantities=("critical_angle_A",), store=tmp_path / "store.zarr")
    result = me.sweep(grid, me.Contact.paper(), "A", 20.0, engine=engine, output=output)
    assert calls == [(2, 3), (3, 3)]
    same_numbers(result, me.sweep(grid, "A", 20.0, base=PAPER, scheduler="serial", chunk_size=2,
                                  quantities=("critical_angle_A",), store=tmp_path / "other.zarr"))


@pytest.mark.parametrize("arguments, error, message", [
    (dict(engine=me.Engine(scheduler="serial"), scheduler="serial"), ValueError,
     "scheduler is not allowed beside engine=Engine("),
    (dict(output=me.SweepOutput(), store="x.zarr"), ValueError, "store is not allowed beside output=SweepOutput("),
    (dict(engine="serial"), TypeError, "engine='serial' (str) is not allowed; allowed: a Engine"),
    (dict(output=("tangential_force_max",)), TypeError, "allowed: a SweepOutput"),
    (dict(motion=me.Scenario("A", (10.0, 20.0))), ValueError, "scenario='A' needs an angle"),
    (dict(motion=me.Scenario("A", (10.0,)), grid={"alpha": [10.0, 20.0]}), ValueError,
     "is not allowed with 'alpha' in the grid"),
    (dict(motion=me.Paths([me.Path.scenario_A(20.0, PAPER)] * 2)), ValueError, "allowed: one path"),
    (dict(motion=me.Paths(me.Path.scenario_A(20.0, PAPER)), grid={"alpha": [10.0]}), ValueError,
     "not allowed with a Path"),
    (dict(method=me.Continuum(t=[0.0, 1.0])), ValueError, "t is not allowed in a sweep"),
    (dict(grid={"dx": [1e-6]}), ValueError, "'dx' is not allowed with method='continuum'"),
    (dict(grid={"indenter.c": [1.0]}), ValueError, "is not a value of this contact (indenter=Paraboloid(R=0.03))"),
])
def test_what_does_not_fit_is_named(arguments, error, message):
    arguments = {"grid": {"tau0": [30e3]}, "motion": me.Scenario("A", 20.0), **arguments}
    grid, motion = arguments.pop("grid"), arguments.pop("motion")
    with pytest.raises(error) as raised:
        me.sweep(grid, me.Contact.paper(), motion, **arguments)
    assert message in str(raised.value)


def test_the_job_converts_the_keywords_in_one_place():
    """sweep_job: the keywords of before and the values make the same runs."""
    old = sweep_job({"tau0": [30e3]}, "A", 20.0, None, None, {"base": PAPER})
    new = sweep_job({"tau0": [30e3]}, me.Contact.paper(), me.Scenario("A", 20.0), None, None, {})
    assert old.spec == new.spec and old.model.params == new.model.params
