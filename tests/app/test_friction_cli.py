"""--friction LAW --mu MU on the command line: simulate and validate take it, results name it, bad input is one
line and exit 2 with nothing written."""

from __future__ import annotations

import pytest

import mdr_events as me
from mdr_events.app.cli import main

NO_ADHESION = ["--dgamma0", "0", "--dgamma1", "0"]


def run(capsys, *argv):
    status = main(list(argv))
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def test_simulate_and_validate_take_a_friction_law(capsys, tmp_path, without_drawing):
    """A discrete run with Coulomb's law passes validate against the continuum of the same law and fails against
    the paper's law."""
    status, _, _ = run(capsys, "simulate", "--scenario", "A", "--alpha", "70", "--dx", "2e-6", "--friction", "coulomb",
                       "--mu", "0.3", *NO_ADHESION, "--out", str(tmp_path))
    assert status == 0
    ds = me.open_result(tmp_path / "simulation_A_discrete.nc")
    assert ds.attrs["friction_law"] == "coulomb" and ds.attrs["friction_mu"] == 0.3
    candidate = tmp_path / "candidate.nc"
    me.write_netcdf(ds.isel(alpha=0), candidate)
    common = ["validate", str(candidate), "--scenario", "A", "--alpha", "70", *NO_ADHESION]
    status, out, _ = run(capsys, *common, "--friction", "coulomb", "--mu", "0.3", "--out", str(tmp_path / "right"))
    assert status == 0 and "1 pass, 0 fail" in out
    report = me.open_result(tmp_path / "right" / "candidate.nc")
    assert report.attrs["friction_law"] == "coulomb"
    status, out, _ = run(capsys, *common, "--out", str(tmp_path / "wrong"))
    assert status == 1 and "0 pass, 1 fail" in out


@pytest.mark.parametrize("options, fragment", [
    (["--friction", "coulomb"], "--friction coulomb: mu=None is not allowed"),
    (["--friction", "coulomb", "--mu", "-0.2"], "--friction coulomb --mu -0.2: mu=-0.2 is not allowed"),
    (["--mu", "0.3"], "--mu 0.3 with the default --friction tau0: mu=0.3 is not allowed with the friction law 'tau0'"),
    (["--friction", "amontons"], "--friction: invalid choice: 'amontons'"),
])
def test_a_bad_friction_law_is_one_line_exit_2(capsys, tmp_path, options, fragment):
    status, _, err = run(capsys, "simulate", "--scenario", "A", "--alpha", "20", *options, "--out", str(tmp_path / "new"))
    assert status == 2 and err.count("\n") == 1 and fragment in err, err
    assert not (tmp_path / "new").exists()  # nothing written, not even the output directory


def test_phase_diagram_takes_a_friction_law(capsys, tmp_path):
    """mdr-events phase-diagram --friction coulomb --mu 0.3 (without adhesion): the angle of friction, the law named in
    the file and the figure's title."""
    status, out, _ = run(capsys, "phase-diagram", "--scenario", "A", "--friction", "coulomb", "--mu", "0.3",
                         *NO_ADHESION, "--out", str(tmp_path))
    assert status == 0
    ds = me.open_result(tmp_path / "phase_diagram_A.nc")
    hertz = me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)
    assert ds.attrs["friction_law"] == "coulomb"
    assert float(ds["critical_angle_hertz"]) == me.mindlin.critical_angle_A(me.FrictionLaw("coulomb", mu=0.3), hertz)
    axes = me.plotting.plot_phase_diagram(ds)
    assert "friction law 'coulomb'" in axes.get_title()


def test_fit_refuses_a_bad_law_before_writing(capsys, tmp_path):
    data = tmp_path / "measured.csv"
    data.write_text("time,normal_force\n0,0\n1,1\n")
    status, _, err = run(capsys, "fit", str(data), "--scenario", "A", "--alpha", "20", "--free", "E", "--friction",
                         "coulomb", "--out", str(tmp_path / "new"))
    assert status == 2 and err.count("\n") == 1 and "--friction coulomb: mu=None is not allowed" in err, err
    assert not (tmp_path / "new").exists()
