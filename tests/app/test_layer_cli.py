"""The layer on the command line (``--h``, ``--layer-base``) and in a study file (``[layer]``): both front ends build
the same job, the discrete run stamps the layer, and bad values are one line with exit 2 and nothing written."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import build_parser, main
from mdr_events.app.cli import simulate as simulate_verb
from mdr_events.app.study import StudyError, load_study
from mdr_events.contact.layer import Layer, LayerBase

#: A short discrete run on the paper's contact: 50 µm springs (about 80 per side at d_max on a 5 mm layer).
QUICK = ["--scenario", "A", "--alpha", "30", "--dx", "5e-5", "--n-steps", "1000"]


def run(capsys, *argv):
    status = main(list(argv))
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def study_of(tmp_path: Path, text: str):
    path = tmp_path / "study.toml"
    path.write_text(text + '\n[output]\ndirectory = "out"\n')
    return load_study(path)


def test_both_front_ends_build_the_same_job_on_a_layer(tmp_path):
    cli = simulate_verb.job(build_parser().parse_args([
        "simulate", "--scenario", "A", "--alpha", "90", "--dx", "5e-5", "--h", "5e-3", "--layer-base", "frictionless",
        "--out", "o"]))
    study = study_of(tmp_path, '[simulation]\nscenario = "A"\nalpha = [90]\ndx = 5e-5\n'
                               '[layer]\nh = 5e-3\nbase = "frictionless"\n').simulation
    assert dataclasses.replace(cli, stem=study.stem) == study
    assert cli.contact.layer == Layer(5e-3, LayerBase.FRICTIONLESS)
    default = simulate_verb.job(build_parser().parse_args(["simulate", *QUICK, "--out", "o"]))
    assert default.contact == me.Contact.paper() and default.contact.layer.is_half_space


def test_simulate_writes_a_run_on_the_layer_that_names_it(capsys, tmp_path):
    status, _, _ = run(capsys, "simulate", *QUICK, "--h", "5e-3", "--out", str(tmp_path))
    assert status == 0
    ds = me.open_result(tmp_path / "simulation_A_discrete.nc")
    assert ds.attrs["param_layer_thickness"] == 5e-3 and ds.attrs["param_layer_base"] == "bonded"
    assert me.Contact.from_attrs(ds.attrs).layer == Layer(5e-3)
    direct = me.simulate(me.Contact.paper().replace(h=5e-3), me.Scenario("A", alpha=[30.0]), "discrete", dx=5e-5,
                         n_steps=1000)
    np.testing.assert_array_equal(ds["normal_force"].values, direct["normal_force"].values)


def test_simulate_runs_the_flat_punch_on_a_layer_in_the_discrete_method(capsys, tmp_path, without_drawing):
    """The command line's flat punch on a layer: the discrete run of simulate, bit for bit, stamped with both."""
    status, _, err = run(capsys, "simulate", "--scenario", "A", "--alpha", "90", "--d_max", "1e-5", "--dx", "5e-5",
                         "--n-steps", "1000", "--h", "5e-3", "--flat-punch", "1e-3", "--out", str(tmp_path))
    assert status == 0, err
    ds = me.open_result(tmp_path / "simulation_A_discrete.nc")
    assert ds.attrs["param_layer_thickness"] == 5e-3 and ds.attrs["profile_radius"] == 1e-3
    contact = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(1e-3)).replace(h=5e-3)
    direct = me.simulate(contact, me.Scenario("A", alpha=[90.0], d_max=1e-5), "discrete", dx=5e-5, n_steps=1000)
    np.testing.assert_array_equal(ds["normal_force"].values, direct["normal_force"].values)


def test_simulate_runs_the_flat_punch_on_a_layer_in_the_continuum(capsys, tmp_path, without_drawing):
    """The command line's flat punch on a thin layer in the continuum (the face held, then receding): simulate's run,
    bit for bit."""
    status, _, err = run(capsys, "simulate", "--scenario", "A", "--alpha", "90", "--d_max", "1e-5", "--h", "2e-4",
                         "--flat-punch", "2e-3", "--method", "continuum", "--out", str(tmp_path))
    assert status == 0, err
    ds = me.open_result(tmp_path / "simulation_A_continuum.nc")
    contact = dataclasses.replace(me.Contact.paper(), indenter=me.FlatPunch(2e-3)).replace(h=2e-4)
    direct = me.simulate(contact, me.Scenario("A", alpha=[90.0], d_max=1e-5), "continuum")
    np.testing.assert_array_equal(ds["normal_force"].values, direct["normal_force"].values)
    assert float(np.nanmin(ds["contact_radius"].values[ds["contact_radius"].values > 0])) < 2e-3  # (it receded)


@pytest.mark.parametrize("options, fragment", [
    (["--h", "0"], "--h 0: Layer.thickness=0.0 is not allowed; allowed: a number > 0 (m)"),
    (["--h", "-1e-3"], "--h -0.001: Layer.thickness=-0.001 is not allowed"),
    (["--h", "nan"], "--h nan: Layer.thickness=nan is not allowed"),
    (["--layer-base", "glued"], "argument --layer-base: invalid choice: 'glued'; allowed: bonded, frictionless"),
    (["--h", "5e-3", "--layer-base", "frictionless"], "path 0 moves the indenter tangentially"),
    (["--h", "2e-5", "--flat-punch", "2e-3", "--method", "continuum"],
     "contact.indenter=FlatPunch(radius=0.002) is not allowed in the continuum method on layer h = 2e-05 m, bonded "
     "base: its face exceeds a/h = 64 (the layer's tables); allowed: a radius up to 0.00128 m, or a layer h >= "
     "3.125e-05 m, or h = inf (the half-space)"),
])
def test_a_bad_layer_is_one_line_exit_2_and_nothing_written(capsys, tmp_path, options, fragment):
    status, _, err = run(capsys, "simulate", "--scenario", "A", "--alpha", "30", *options, "--out",
                         str(tmp_path / "new"))
    assert status == 2 and err.count("\n") == 1 and fragment in err, err
    assert not (tmp_path / "new").exists()


@pytest.mark.parametrize("table, fragment", [
    ("h = 0", "[layer] Layer.thickness=0 is not allowed; allowed: a number > 0 (m)"),
    ('h = 5e-3\nbase = "glued"', "[layer] Layer.base='glued' is not allowed; allowed: one of LayerBase.BONDED"),
    ('base = "bonded"', "[layer] lacks the required key(s) h"),
    ('h = "thin"', "[layer] h = 'thin' is not allowed; allowed: a number"),
    ("h = 5e-3\nthickness = 1", "unknown key 'thickness' in [layer]; allowed: h, base"),
])
def test_a_bad_layer_table_is_named(tmp_path, table, fragment):
    with pytest.raises(StudyError) as caught:
        study_of(tmp_path, f'[simulation]\nscenario = "A"\nalpha = [30]\n[layer]\n{table}\n')
    assert fragment in str(caught.value) and "\n" not in str(caught.value)


def test_a_study_with_coulombs_law_on_an_adhesive_layer_is_read_for_the_continuum(tmp_path):
    """Coulomb's part with adhesion on a layer runs in the continuum (issues 34 and 26): each table that runs it reads."""
    coulomb = '[friction]\nlaw = "tau0+coulomb"\nmu = 0.3\n'
    for table, name in (('[simulation]\nscenario = "A"\nalpha = [30]\nmethod = "continuum"\n', "simulation"),
                        ('[validate]\nruns = ["run.csv"]\nscenario = "A"\nalpha = 30\n', "validation"),
                        ('[fit]\ndata = "run.csv"\nfree = ["E"]\nscenario = "A"\nalpha = 30\n', "fit")):
        study = study_of(tmp_path, f'{table}{coulomb}[layer]\nh = 5e-3\n')
        assert getattr(study, name) is not None
        assert study.contact.layer == Layer(5e-3) and study.contact.friction.law == "tau0+coulomb"
    study = study_of(tmp_path, '[simulation]\nscenario = "A"\nalpha = [30]\nmethod = "continuum"\n[layer]\nh = 5e-3\n')
    assert study.simulation.contact.layer == Layer(5e-3)
