import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app.cli import main
from mdr_events.app.result_files import event_log_csv


def run(capsys, *argv):
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.parametrize(
    "argv, fragment",
    [
        (["phase-diagram", "--scenario", "C", "--out", "x"], "--scenario"),
        (["phase-diagram", "--scenario", "A", "--E", "-1", "--out", "x"], "Parameters.E=-1.0"),
        (["phase-diagram", "--scenario", "A", "--nu", "0.7", "--out", "x"], "Parameters.nu=0.7"),
        (["phase-diagram", "--scenario", "A", "--E", "abc", "--out", "x"], "--E"),
        (["phase-diagram", "--scenario", "A"], "--out"),
        (["phase-diagram", "--scenario", "A", "--preset", "paper-R50", "--out", "x"], "--preset"),
        (["derive", "--key", "nope"], "unknown relation 'nope'"),
        (["frobnicate"], "frobnicate"),
        ([], "command"),
    ],
)
def test_bad_arguments_one_line_exit_2(capsys, tmp_path, argv, fragment):
    status, out, err = run(capsys, *argv)
    assert status == 2
    assert err.count("\n") == 1 and err.startswith("mdr-events: error:")
    assert fragment in err
    assert "Traceback" not in err


def test_derive_pretty_and_latex(capsys):
    status, out, _ = run(capsys, "derive", "--key", "jkr_depth")
    assert status == 0 and "jkr_depth (9)" in out
    status, out, _ = run(capsys, "derive", "--latex", "--key", "slip_A_jkr_cubic")
    assert status == 0 and r"\tau_{0}" in out


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_phase_diagram_writes_nc_and_png(capsys, tmp_path, scenario):
    status, out, _ = run(capsys, "phase-diagram", "--scenario", scenario, "--preset", "paper-R100",
                         "--tau0", "30000", "--out", str(tmp_path))
    assert status == 0
    ds = me.open_result(tmp_path / f"phase_diagram_{scenario}.nc")
    assert ds.attrs["param_R"] == 0.1 and ds.attrs["param_tau0"] == 30000.0
    assert (tmp_path / f"phase_diagram_{scenario}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_console_script_is_installed_and_exits_2():
    exe = shutil.which("mdr-events") or str(Path(sys.executable).parent / "mdr-events")
    if not Path(exe).exists():
        pytest.skip("console script not installed (package not pip-installed)")
    result = subprocess.run([exe, "phase-diagram", "--scenario", "Z", "--out", "x"],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1


def test_simulate_writes_nc_and_png(capsys, tmp_path):
    status, out, err = run(capsys, "simulate", "--scenario", "B", "--alpha", "20", "60", "--dx", "4e-6",
                           "--n-steps", "400", "--out", str(tmp_path))
    assert status == 0, err
    ds = me.open_result(tmp_path / "simulation_B_discrete.nc")
    assert list(ds["alpha"].values) == [20.0, 60.0] and ds.attrs["dx"] == 4e-6
    assert (tmp_path / "simulation_B_discrete.png").exists()


@pytest.mark.parametrize(
    "argv, fragment",
    [
        (["--dx", "1e-3"], "dx=0.001"),
        (["--alpha", "100"], "alpha=100.0"),
        (["--dt", "1", "--n-steps", "10"], "not allowed with argument"),
        (["--method", "magic"], "--method"),
        (["--method", "continuum", "--dx", "1e-6"], "dx is not allowed with method='continuum'"),
        (["--method", "continuum", "--dt", "0.5"], "dt is not allowed with method='continuum'"),
        (["--method", "continuum", "--n-steps", "100"], "n_steps is not allowed with method='continuum'"),
    ],
)
def test_simulate_bad_arguments(capsys, tmp_path, argv, fragment):
    status, _, err = run(capsys, "simulate", "--scenario", "A", "--out", str(tmp_path), *argv)
    assert status == 2 and err.count("\n") == 1 and fragment in err


def test_simulate_continuum_writes_the_event_log_csv(capsys, tmp_path, without_drawing):
    status, out, err = run(capsys, "simulate", "--scenario", "A", "--method", "continuum", "--alpha", "15", "60",
                           "--out", str(tmp_path))
    assert status == 0, err
    ds = me.open_result(tmp_path / "simulation_A_continuum.nc")
    rows = (tmp_path / "simulation_A_continuum_events.csv").read_text().splitlines()
    assert rows[0].startswith("alpha_degree,event,time_s,kind")
    onset = [r.split(",") for r in rows[1:] if r.split(",")[3] == "slip_onset" and r.startswith("15,")]
    assert float(onset[0][4]) == pytest.approx(me.d_crit(15.0, ds_params(ds), "A", adhesion=True), rel=1e-9)


def test_event_log_csv_of_custom_paths_names_each_case_by_its_label(paper):
    """A custom path's case is written by its label (quoted where it holds a comma), a scenario's by its angle."""
    path = me.Path([(0.0, 0.0), (0.0, paper.d_max), (2e-4, -1e-4)], paper.v)
    dataset = me.simulate(paper, {"in, then out": path, "plain": path}, method="continuum", samples=11)
    rows = event_log_csv(dataset).splitlines()
    assert rows[0] == "case,event,time_s,kind,depth_m,radius_m,x_m,direction"
    assert rows[1].startswith('"in, then out",0,') and rows[1].split(",")[4] == "first_contact"
    labels = {row.rsplit(",", 7)[0] for row in rows[1:]}
    assert labels == {'"in, then out"', "plain"}
    scenario = me.simulate(paper, "A", alpha=[15.0], method="continuum", samples=11)
    assert event_log_csv(scenario).splitlines()[1].startswith("15,0,")


def ds_params(ds):
    return me.Parameters.from_attrs(ds.attrs)


def test_top_level_help_is_plain_text(capsys):
    """``mdr-events --help`` shows a sentence, not the module docstring's reST markup."""
    with pytest.raises(SystemExit) as exit_info:
        main(["--help"])
    out, _ = capsys.readouterr()
    assert exit_info.value.code == 0
    text = " ".join(out.split())  # argparse wraps the description
    assert "``" not in text and "Method of Dimensionality Reduction" in text


def test_cli_results_say_which_parameters_came_from_the_preset(capsys, tmp_path, without_drawing):
    status, _, err = run(capsys, "phase-diagram", "--scenario", "A", "--preset", "paper-R100", "--tau0", "30000",
                         "--out", str(tmp_path))
    assert status == 0, err
    ds = me.open_result(tmp_path / "phase_diagram_A.nc")
    assert ds.attrs["parameters_preset"] == "paper-R100"
    assert ds.attrs["parameters_from_preset"] == "E, nu, R, dgamma0, dgamma1, d_max, v"


def test_simulate_and_validate_take_a_power_law(capsys, tmp_path, without_drawing, without_run_figures):
    """--power-law C N: the simulation names its profile (attribute and figure title, not the paper's figure
    number); the discrete run passes validate against the same indenter and fails against the paraboloid."""
    status, out, _ = run(capsys, "simulate", "--scenario", "A", "--alpha", "20", "--dx", "2e-6", "--power-law", "2000",
                         "3", "--out", str(tmp_path))
    assert status == 0
    run_file = tmp_path / "simulation_A_discrete.nc"
    ds = me.open_result(run_file)
    assert ds.attrs["profile"] == "power law f = c r^n, c = 2000 m^(1-n), n = 3"
    figure = me.plotting.plot_simulation(ds)
    assert "power law" in figure._suptitle.get_text() and "Fig." not in figure._suptitle.get_text()
    candidate = tmp_path / "candidate.nc"
    me.write_netcdf(ds.isel(alpha=0), candidate)
    common = ["validate", str(candidate), "--scenario", "A", "--alpha", "20", "--preset", "paper-R30"]
    status, out, _ = run(capsys, *common, "--power-law", "2000", "3", "--out", str(tmp_path / "right"))
    assert status == 0 and "1 pass, 0 fail" in out
    without_run_figures()  # (a failing report's figure is drawn in tests/app/test_validate_cli.py)
    status, out, _ = run(capsys, *common, "--out", str(tmp_path / "wrong"))
    assert status == 1 and "0 pass, 1 fail" in out


@pytest.mark.parametrize("values, fragment", [(["2000", "0.5"], "--power-law 2000 0.5: PowerLaw.n=0.5 is not allowed "
                                                                "in the simulators; allowed: n >= 1"),
                                              (["-1", "2"], "--power-law -1 2: PowerLaw.c=-1.0 is not allowed"),
                                              (["1"], "--power-law")])
def test_a_bad_power_law_is_one_line_exit_2(capsys, tmp_path, values, fragment):
    status, out, err = run(capsys, "simulate", "--scenario", "A", "--power-law", *values, "--out", str(tmp_path / "new"))
    assert status == 2 and err.count("\n") == 1 and fragment in err
    assert not (tmp_path / "new").exists()  # nothing written, not even the output directory


def test_cli_validate_builds_the_path_of_the_power_law(capsys, tmp_path, without_drawing):
    """A profile whose jump-off lies below the paraboloid's way out: the reference the CLI builds for
    --scenario/--alpha ends below that profile's jump-off, so it pulls off (as validate() in Python)."""
    from mdr_events.theory import power_law

    paper = me.Parameters.paper()
    flat = me.PowerLaw(1.286e11, 6.0)  # a blunt indenter whose jump-off lies 5.25e-5 m above the surface
    assert power_law.jump_off(flat, paper, paper.dgamma1)["depth"] < me.Path.scenario_A(20.0, paper).waypoints[-1, 1]
    run_file = tmp_path / "run.nc"
    me.write_netcdf(me.simulate(paper, "A", alpha=20.0, dx=1e-6, profile=flat).isel(alpha=0), run_file)
    status, out, _ = run(capsys, "validate", str(run_file), "--scenario", "A", "--alpha", "20", "--preset", "paper-R30",
                         "--power-law", repr(flat.c), "6", "--out", str(tmp_path / "out"))
    report = me.open_result(tmp_path / "out" / "run.nc")
    assert np.isfinite(float(report["pull_off_force_exact"]))
    direct = me.validate(run_file, paper, "A", 20.0, profile=flat)
    assert float(report["pull_off_force_exact"]) == float(direct["pull_off_force_exact"])


def test_phase_diagram_takes_a_power_law(capsys, tmp_path, without_drawing):
    """--power-law: the diagram is the power law's (its critical angle), names it, says that R is unused, and its
    figure does not cite the paraboloid's equation numbers."""
    status, out, _ = run(capsys, "phase-diagram", "--scenario", "A", "--power-law", "0.1", "1", "--out", str(tmp_path))
    assert status == 0
    diagram = me.open_result(tmp_path / "phase_diagram_A.nc")
    cone = me.PowerLaw.cone(0.1)
    assert diagram.attrs["profile"] == cone.describe() and diagram.attrs["profile_n"] == 1.0
    assert float(diagram["critical_angle_jkr"]) == me.power_law.critical_angle_A(cone, me.Parameters.paper())
    figure = me.plotting.plot_phase_diagram(diagram).figure
    labels = [line.get_label() for line in figure.axes[0].get_lines()]
    assert "non-adhesive" in labels and "adhesive (Heß)" in labels and not any("(17)" in label for label in labels)
    simulation = me.simulate(me.Parameters.paper(), "A", alpha=20.0, method="continuum", samples=11, profile=cone)
    assert "param_R" in simulation.attrs and "not used" in simulation.attrs["profile_note"]


def test_simulate_takes_a_flat_punch(capsys, tmp_path, without_drawing):
    """--flat-punch RADIUS: the simulation is the punch's (attributes), its least F_N Kendall's pull-off force."""
    status, _, _ = run(capsys, "simulate", "--scenario", "A", "--alpha", "20", "--method", "continuum", "--flat-punch",
                       "1.5e-3", "--out", str(tmp_path))
    assert status == 0
    ds = me.open_result(tmp_path / "simulation_A_continuum.nc")
    assert ds.attrs["profile_radius"] == 1.5e-3 and ds.attrs["profile"] == "flat punch of radius 0.0015 m"
    assert float(ds["normal_force_min"].values[0]) == pytest.approx(
        me.power_law.pull_off_force(me.FlatPunch(1.5e-3), me.Parameters.paper(), 0.15), rel=1e-12)


@pytest.mark.parametrize("options, fragment", [(["--flat-punch", "-1"], "--flat-punch -1: FlatPunch.radius=-1.0 is not "
                                                                        "allowed"),
                                               (["--flat-punch", "1e-3", "--power-law", "2000", "3"],
                                                "not allowed with argument")])
def test_a_bad_flat_punch_is_one_line_exit_2(capsys, tmp_path, options, fragment):
    status, _, err = run(capsys, "simulate", "--scenario", "A", *options, "--out", str(tmp_path / "new"))
    assert status == 2 and err.count("\n") == 1 and fragment in err, err
    assert not (tmp_path / "new").exists()


def _write_table(path, points=41):
    r = np.linspace(0.0, 4e-3, points)
    path.write_text("# a paraboloid of R = 30 mm, as a measured tip would be given\nr,f\n"
                    + "".join(f"{float(a)!r},{float(a * a / 0.06)!r}\n" for a in r))
    return me.TabulatedProfile(r, r * r / 0.06)


def test_simulate_takes_a_table(capsys, tmp_path, without_drawing):
    """--table FILE: a CSV of r and f (m) is the indenter; the result carries the table exactly."""
    table = _write_table(tmp_path / "tip.csv")
    status, _, _ = run(capsys, "simulate", "--scenario", "A", "--alpha", "20", "--method", "continuum", "--table",
                       str(tmp_path / "tip.csv"), "--out", str(tmp_path / "out"))
    assert status == 0
    ds = me.open_result(tmp_path / "out" / "simulation_A_continuum.nc")
    assert ds.attrs["profile_table_r"] == ", ".join(map(repr, table.r))
    direct = me.simulate(me.Parameters.paper(), "A", alpha=[20.0], method="continuum", profile=table)
    np.testing.assert_array_equal(ds["tangential_force"].values, direct["tangential_force"].values)


@pytest.mark.parametrize("text, fragment", [("x,f\n0,0\n1e-3,1e-5\n2e-3,4e-5\n", "no column 'r'"),
                                            ("r,f\n0,0\n1e-3,2e-5\n2e-3,1e-5\n", "TabulatedProfile.f=")])
def test_a_bad_table_is_one_line_exit_2(capsys, tmp_path, text, fragment):
    (tmp_path / "tip.csv").write_text(text)
    status, _, err = run(capsys, "simulate", "--scenario", "A", "--table", str(tmp_path / "tip.csv"), "--out",
                         str(tmp_path / "new"))
    assert status == 2 and err.count("\n") == 1 and "--table" in err and fragment in err, err
    assert not (tmp_path / "new").exists()
