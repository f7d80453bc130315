"""The twelfth hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io.files import open_result, write_netcdf

PAPER = me.Parameters.paper()


@pytest.fixture(scope="module")
def simulation():
    return me.simulate(PAPER, "A", [10.0, 20.0], method="continuum", samples=51)


# --- M1: write_netcdf wrote what open_result then refused (a case selected away, `ds.isel(alpha=0)`, read as "wrong
# dimensions"; a dropped or transposed variable; CF attributes the reader decodes: _FillValue, scale_factor, a time's
# units, coordinates; a one-element list or bytes attribute; a zero-length record dimension, read by SciPy as a
# SyntaxError). Every dataset the writer accepts now reads back identical, and the reader takes one case selected -----

@pytest.mark.parametrize("select", [{"alpha": 0}, {"time": 0}, {"alpha": [0]}, {"time": slice(0, 5)}])
def test_a_selection_written_reads_back_identical(simulation, select, tmp_path):
    dataset = simulation.isel(select)
    again = open_result(write_netcdf(dataset, tmp_path / "one.nc"))
    xr.testing.assert_identical(again, dataset)


def _labelled(values):
    return {"units": "1", "long_name": "extra"} | values


@pytest.mark.parametrize("change, words", [
    (lambda ds: ds.drop_vars("normal_force"), "lacks the variable(s) ['normal_force']"),
    (lambda ds: ds.transpose("time", "alpha", "event"), "has variable(s) with the wrong dimensions"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2))), "without units or long_name: ['extra']"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2), _labelled({"_FillValue": 1.0}))),
     "attribute '_FillValue'=1.0 reads back as absent"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2), _labelled({"scale_factor": 2.0}))), "'scale_factor'"),
    (lambda ds: ds.assign(extra=("alpha", np.ones(2), _labelled({"units": "days since 2000-01-01"}))),
     "'units'='days since 2000-01-01' reads back as absent"),
    (lambda ds: ds.assign_attrs(note=[1.5]), "attribute 'note'=[1.5] reads back as"),
    (lambda ds: ds.assign_attrs(note=b"ab"), "attribute 'note'=b'ab' reads back as 'ab'"),
    (lambda ds: ds.assign_attrs(coordinates="alpha"), "attribute 'coordinates'='alpha' reads back as absent"),
    (lambda ds: ds.isel(alpha=slice(0, 0), event=slice(0, 0), time=slice(0, 0)), "it is not read (TypeError"),
])
def test_what_would_not_read_back_is_refused_before_it_is_placed(simulation, change, words, tmp_path):
    with pytest.raises(ValueError, match=re.escape(words)) as caught:
        write_netcdf(change(simulation), tmp_path / "x.nc")
    assert "allowed" in str(caught.value) and "\n" not in str(caught.value)
    assert list(tmp_path.iterdir()) == []  # (the temporary removed, nothing placed)


def test_a_file_scipy_cannot_read_is_named_not_a_syntax_error(tmp_path):
    path = tmp_path / "empty_record.nc"
    diagram = me.phase_diagram(PAPER, scenario="B")
    diagram.isel({name: slice(0, 0) for name in diagram.dims}).to_netcdf(path, engine="scipy")
    with pytest.raises(ValueError, match="is not a readable netCDF file \\(SyntaxError"):
        open_result(path)


# --- M2: the layer's theory (mdr_events.theory.layer, Layer) took what it cannot compute: nan and inf results from
# a negative radius, a negative or nan work of adhesion, E* of nan/inf or a product beyond the double range; raw
# TypeError/IndexError/OverflowError/ZeroDivisionError from strings, None, a bad column, kernel(nan), a paraboloid of
# R = 1e300; a direct solve at a/h = 1000 (MemoryError, 5 GiB) or 1e4 (no end), kernel(1e6) (minutes), nodes=10**12,
# the surface displacement at r/a = 1e300; Layer(10**400) read as the half-space, LayerBase('x') and
# Layer.from_attrs in Python's words. Each argument is checked by its name before a relation runs, its result after --
from mdr_events.theory import layer as L  # noqa: E402

E_STAR, NU, PARABOLOID = 1e6, 0.3, me.Paraboloid(0.03)
THIN = me.Layer(1e-3)


@pytest.mark.parametrize("call, named", [
    (lambda: L.hess_elongation(-1e-4, 0.05, E_STAR, NU, THIN), "a=-0.0001 is not allowed"),
    (lambda: L.hess_elongation(1e-4, -0.05, E_STAR, NU, THIN), "dgamma=-0.05 is not allowed"),
    (lambda: L.punch_stiffness(1e-4, math.nan, NU, THIN), "E_star=nan is not allowed"),
    (lambda: L.punch_stiffness(1e-4, "x", NU, THIN), "E_star='x' (str) is not allowed"),
    (lambda: L.punch_stiffness("x", E_STAR, NU, THIN), "a='x' (of str values) is not allowed"),
    (lambda: L.punch_stiffness(1e300, 1e300, NU, me.Layer()), "punch_stiffness(a=1e+300, E_star=1e+300"),
    (lambda: L.normal_force(math.nan, 1e-4, PARABOLOID, E_STAR, NU, THIN), "d=nan is not allowed"),
    (lambda: L.normal_force(np.ones(3) * 1e-5, np.ones(2) * 1e-4, PARABOLOID, E_STAR, NU, THIN), "do not broadcast"),
    (lambda: L.pull_off(me.Paraboloid(1e300), E_STAR, NU, 0.05, THIN), "pull_off(profile=Paraboloid(R=1e+300)"),
    (lambda: L.equivalent_profile(np.array([1e-4]), lambda r: r * np.nan, NU, THIN), "equivalent_profile("),
    (lambda: L.surface_displacement(math.nan, 1e-4, NU, THIN), "r=nan is not allowed"),
    (lambda: L.surface_displacement(1e300, 1e-4, NU, THIN), "the surface displacement at r/a up to 1e+304"),
    (lambda: L.punch_stiffness(1e-4, E_STAR, NU, None), "layer=None (NoneType) is not allowed"),
    (lambda: L.compliance_function(1e300, NU) + L.compliance_function(-1.0, NU), "t=-1.0 is not allowed"),
    (lambda: L.kernel(math.nan, NU), "v=nan is not allowed"),
    (lambda: L.kernel(1e6, NU), "v=1000000.0 is not allowed; allowed: finite numbers with |v| <= 200"),
    (lambda: L.solve_punch(1000.0, NU), "a/h=1000.0 is not allowed for a direct solve"),
    (lambda: L.solve_punch(1.0, NU, nodes=10**12), "the layer's Nyström solve with 1000000000000 nodes"),
    (lambda: L.solve_punch(1.0, NU, exponents=2.0), "exponents=2.0 (float) is not allowed"),
    (lambda: L.solve_punch(1.0, NU).profile_factor(2), "column=2 is not allowed; allowed: 1 to 1"),
    (lambda: L.solve_punch(1.0, NU, exponents=()).force_factor(), "this solution has no profile's right-hand side"),
    (lambda: L.layer_table(NU).stiffness_factor("x"), "lam='x' (of str values) is not allowed"),
    (lambda: me.Layer(10**400), "(an integer beyond the double range is none)"),
    (lambda: me.Layer(1e-3).relative_radius(math.nan), "radius=nan is not allowed"),
    (lambda: me.LayerBase("x"), "LayerBase('x') is not allowed; allowed: 'bonded', 'frictionless'"),
    (lambda: me.Layer.from_attrs({"param_layer_thickness": "abc"}), "attrs do not describe a layer"),
    (lambda: me.Layer.from_attrs(None), "attrs of type NoneType are not allowed"),
])
def test_the_layer_theory_names_what_it_cannot_compute(call, named):
    with pytest.raises((ValueError, TypeError)) as caught:
        call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message


def test_the_layer_theory_is_unchanged_where_it_computes():
    """The checks are before and after: a valid call gives the same numbers (the tables' own tests cover them)."""
    assert L.compliance_function(np.array([0.0, 1.0, 900.0]), NU)[2] == 1.0  # (1 − C underflows to 0, no nan)
    assert L.punch_stiffness(0.0, E_STAR, NU, THIN) == 0.0
    assert L.pull_off(PARABOLOID, E_STAR, NU, 0.05, me.Layer()).force == pytest.approx(-1.5 * math.pi * 0.05 * 0.03,
                                                                                       rel=1e-12)


# --- M3: `lammps-check --E 1e308` started LAMMPS, which stopped on 'inf' in its input ("LAMMPS: ERROR: Expected
# floating point parameter instead of 'inf'"): the LAMMPS check did not refuse the scales simulate and validate refuse.
# The one path of every referee is checked for its scales where it is taken --------------------------------------------

def test_the_lammps_check_refuses_scales_beyond_the_double_range_before_it_runs(monkeypatch):
    from mdr_events.dem import check

    def never(*args, **kwargs):
        raise AssertionError("LAMMPS was started")

    monkeypatch.setattr(check, "run_lammps", never)
    contact = me.Contact.paper().replace(E=1e308)
    with pytest.raises(ValueError, match=re.escape("E* is 1.33e+308 Pa; allowed: parameters whose scales lie within")):
        check.lammps_check(contact, "A", 20.0, model=check.LammpsModel("jkr"))


# --- M4: the rate-dependent angles (analysis.rate_angles, new since round eleven): slip_onset_depth_at_speed(None, ...)
# an AttributeError, speed=1e300 an IndexError (a path of 1e-304 s), a critical angle outside Brent's bracket scipy's
# "f(a) and f(b) must have different signs", an empty grid xarray's words, 1e5 angles or 2000 speeds hours unchecked;
# solve_edge on a path shorter than the jump-in's lag returned radius 0 at d_max (the critical angle then "found") ---
RATE_LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)


@pytest.mark.parametrize("call, named", [
    (lambda: me.slip_onset_depth_at_speed(None, RATE_LAW, 1e-6, 20.0), "params=None (NoneType) is not allowed"),
    (lambda: me.slip_onset_depth_at_speed(PAPER, RATE_LAW, 1e300, 20.0), "speed=1e+300 m/s: "),
    (lambda: me.critical_angle_at_speed(PAPER.replace(E=1e12), RATE_LAW, 1e-6),
     "the springs slide before d_max at every angle up to 90° - 1e-6 rad"),
    (lambda: me.phase_diagram_at_speeds(PAPER, RATE_LAW, [], [20.0]), "speeds=[] is not allowed"),
    (lambda: me.phase_diagram_at_speeds(PAPER, RATE_LAW, [1e-6], np.linspace(1.0, 89.0, 100_000)),
     "the phase diagram at 1 speeds and 100000 angles, a solve each at least (100000 solves of the edge)"),
    # (counted before the angles are read, at one solve each: round eighteen)
    (lambda: me.critical_angles_at_speeds(PAPER, RATE_LAW, np.linspace(1e-9, 1e-5, 2000)),
     "critical_angles_at_speeds of 2000 speeds"),
    (lambda: me.critical_angle_at_speed(PAPER, RATE_LAW, 1e3), "jumps in over 5.34e-06 s, beyond the path's end"),
])
def test_the_rate_angles_name_what_they_cannot_compute(call, named):
    with pytest.raises((ValueError, TypeError)) as caught:
        call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message


def test_an_edge_still_jumping_in_at_the_paths_end_is_refused():
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max)]), speed=1e3)
    from mdr_events.models.continuum import solve_edge

    with pytest.raises(ValueError, match="the indenter outran the advancing edge, which would leave no contact"):
        solve_edge(PAPER, path, RATE_LAW)


# --- M5: two sweeps started together on one store (two study files whose output is one directory) both exited 0 and
# left a store no later sweep reads ("exists and is not a sweep's store": --resume and --restart refused it); a second
# sweep laying out the store under the first could mark the first's runs done with its own values. A sweep holds an
# exclusive lock on its store while it runs --------------------------------------------------------------------------

def test_a_store_in_use_by_another_sweep_is_refused_and_released_after(tmp_path):
    from mdr_events.analysis.sweep_store import _locked

    store = tmp_path / "s.zarr"
    holder = _locked(str(store))  # (what a sweep running in another process holds)
    with pytest.raises(ValueError, match=re.escape("is in use by another sweep (its lock")) as caught:
        me.sweep({"tau0": [3e4, 4e4]}, "A", 20.0, base=PAPER, scheduler="serial", store=store,
                 quantities=("critical_angle_A",))
    assert "allowed" in str(caught.value) and not store.exists()
    holder.close()
    first = me.sweep({"tau0": [3e4, 4e4]}, "A", 20.0, base=PAPER, scheduler="serial", store=store,
                     quantities=("critical_angle_A",))
    again = me.sweep({"tau0": [3e4, 4e4]}, "A", 20.0, base=PAPER, scheduler="serial", store=store,
                     quantities=("critical_angle_A",))  # (the lock released when the first ended)
    np.testing.assert_array_equal(first["critical_angle_A"].values, again["critical_angle_A"].values)
