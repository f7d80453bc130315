"""A sweep on a layer from the front ends: a study's ``[layer]`` table and a grid over ``h`` (``inf`` the half-space),
``mdr-events sweep --h/--layer-base`` over the study's layer; the same numbers as :func:`mdr_events.sweep`, bad input
one line with exit 2 and nothing run."""

from __future__ import annotations

import importlib.util
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.sweep import CLOSED_FORM_QUANTITIES
from mdr_events.app.cli import main
from mdr_events.app.study import load_study

from test_validate_cli import assert_one_error_line

# looked up, not imported (dask.distributed costs a worker about a second at collection; a run imports it where it
# starts a cluster)
if importlib.util.find_spec("distributed") is None:
    pytest.skip("the extra 'scale' is not installed (make installs it)", allow_module_level=True)

#: The discrete springs of a quick run (the sweep's own step unless given: n_steps fixes it).
SPRINGS = me.Discrete(dx=5e-5, n_steps=1000)
DISCRETE = 'method = "discrete"\ndx = 5e-5\nn_steps = 1000\nquantities = ["tangential_force_max", "normal_force_min"]'


def write_study(folder, sweep: str, extra: str = ""):
    path = folder / "study.toml"
    path.write_text(f'[sweep]\nscenario = "A"\nscheduler = "serial"\n{sweep}\n{extra}\n[output]\ndirectory = "out"\n')
    return path


def result(folder):
    return me.open_result(folder / "out" / "study_sweep.nc")


def test_a_study_grid_over_h_gives_the_layers_critical_angles(capsys, tmp_path):
    study = write_study(tmp_path, 'grid = { h = [2e-3, 5e-3, inf], tau0 = [30e3, 42e3] }\nalpha = 20\n'
                                  'quantities = ["critical_angle_A", "critical_angle_B"]')
    assert main(["sweep", str(study)]) == 0
    swept = result(tmp_path)
    direct = me.sweep({"h": [2e-3, 5e-3, math.inf], "tau0": [30e3, 42e3]}, me.Contact.paper(), "A", 20.0,
                      scheduler="serial", quantities=CLOSED_FORM_QUANTITIES)
    for name in CLOSED_FORM_QUANTITIES:
        np.testing.assert_array_equal(swept[name].values, direct[name].values)
    assert swept["h"].values.tolist() == [2e-3, 5e-3, math.inf] and swept.attrs["param_layer_base"] == "bonded"


def test_a_study_layer_table_runs_the_discrete_sweep_on_the_layer(capsys, tmp_path):
    study = write_study(tmp_path, f'grid = {{ alpha = [20, 40] }}\n{DISCRETE}', '[layer]\nh = 5e-3')
    assert main(["sweep", str(study)]) == 0
    swept = result(tmp_path)
    layered = me.Contact.paper().replace(h=5e-3)
    direct = me.sweep({"alpha": [20.0, 40.0]}, layered, "A", method=SPRINGS, scheduler="serial",
                      quantities=("tangential_force_max", "normal_force_min"))
    np.testing.assert_array_equal(swept["tangential_force_max"].values, direct["tangential_force_max"].values)
    assert me.Contact.from_attrs(swept.attrs) == layered


def test_h_on_the_command_line_puts_the_studys_sweep_on_a_layer(capsys, tmp_path):
    """--h replaces the study's [layer] thickness (its base kept); the store holds the layer, so one of another
    thickness is not resumed."""
    study = write_study(tmp_path, f'grid = {{ alpha = [30] }}\n{DISCRETE}', '[layer]\nh = 5e-3')
    assert main(["sweep", str(study), "--h", "2e-3"]) == 0
    swept = result(tmp_path)
    assert swept.attrs["param_layer_thickness"] == 2e-3 and swept.attrs["param_layer_base"] == "bonded"
    run = me.simulate(me.Contact.paper().replace(h=2e-3), me.Scenario("A", 30.0), SPRINGS)
    assert float(swept["normal_force_min"][0]) == float(np.nanmin(run["normal_force"].values))
    capsys.readouterr()
    assert main(["sweep", str(study), "--resume"]) == 2  # (the study's own 5 mm: another sweep)
    assert_one_error_line(capsys.readouterr().err, "holds another sweep")


#: Coulomb's part on a layer, which a continuum sweep runs spring by spring (the study's [friction] table).
COULOMB = '[friction]\nlaw = "tau0+coulomb"\nmu = 0.3'


@pytest.mark.parametrize("sweep, extra, argv, fragment", [
    ("grid = { alpha = [30] }", "", ["--h", "0"], "--h 0: Layer.thickness=0.0 is not allowed"),
    (f"grid = {{ alpha = [30] }}\n{DISCRETE}", "", ["--h", "5e-3", "--layer-base", "frictionless"],
     "--h 0.005 --layer-base frictionless: path 0 moves the indenter tangentially"),
    (f"grid = {{ alpha = [30] }}\n{DISCRETE}", "[layer]\nh = 5e-3", ["--layer-base", "glued"],
     "argument --layer-base: invalid choice: 'glued'"),
    ('grid = { "layer.base" = [1] }\nalpha = 30', "", [], "[sweep] grid: 'layer.base' is not allowed: a choice"),
])
def test_a_layer_the_sweep_cannot_run_is_one_line_exit_2_and_nothing_run(capsys, tmp_path, sweep, extra, argv,
                                                                          fragment):
    study = write_study(tmp_path, sweep, extra)
    assert main(["sweep", str(study), *argv]) == 2
    assert_one_error_line(capsys.readouterr().err, fragment)
    assert not (tmp_path / "out" / "study_sweep.zarr").exists()


def test_a_continuum_sweep_study_of_coulombs_law_on_a_layer_is_read(tmp_path):
    """A continuum sweep runs Coulomb's part on a layer spring by spring, as simulate's continuum does (refused when
    read before: its quantities read the spans' solution; tests/analysis/test_play_sweep.py checks the values)."""
    study = load_study(write_study(tmp_path, "grid = { alpha = [30] }", f"[layer]\nh = 5e-3\n{COULOMB}"))
    assert study.sweep.contact.layer == me.Layer(5e-3) and study.sweep.contact.friction.law == "tau0+coulomb"
    assert load_study(write_study(tmp_path, "grid = { alpha = [30] }", "[layer]\nh = 5e-3")).sweep.contact.layer \
        == me.Layer(5e-3)
    closed = load_study(write_study(tmp_path, 'grid = { tau0 = [3e4] }\nalpha = 30\n'
                                              'quantities = ["critical_angle_A"]', "[layer]\nh = 5e-3"))
    assert closed.sweep.contact.layer == me.Layer(5e-3)
