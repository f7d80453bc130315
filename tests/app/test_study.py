"""Study files: `mdr-events run study.toml`, and every way a study file can be wrong."""

import numpy as np
import pytest

import mdr_events as me
from mdr_events.io import datasets
from mdr_events.app.cli import main
from mdr_events.app.study import StudyError, load_study

STUDY = """
[parameters]
preset = "paper-R100"
tau0 = 30e3

[simulation]
scenario = "B"
alpha = [20, 60]
method = "continuum"
samples = 301

[phase_diagram]
scenarios = ["A", "B"]

[output]
directory = "out"
name = "demo"
"""


def assert_one_error_line(err, fragment):
    """Progress lines may come first; the error is one line, the last, without a traceback."""
    errors = [line for line in err.splitlines() if line.startswith("mdr-events: error:")]
    assert len(errors) == 1 and err.splitlines()[-1] == errors[0] and fragment in errors[0]
    assert "Traceback" not in err


def write(tmp_path, text, name="study.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_run_writes_what_the_study_asks_for(tmp_path, capsys):
    path = write(tmp_path, STUDY)
    assert main(["run", str(path)]) == 0
    out = tmp_path / "out"  # relative to the study file
    names = sorted(p.name for p in out.iterdir())
    assert names == ["demo_phase_diagram_A.nc", "demo_phase_diagram_A.png", "demo_phase_diagram_B.nc",
                     "demo_phase_diagram_B.png", "demo_simulation.nc", "demo_simulation.png",
                     "demo_simulation_events.csv"]
    ds = me.open_result(out / "demo_simulation.nc")
    params = datasets.parameters_of(ds)
    assert params == me.Parameters.paper(R=0.1).replace(tau0=30e3)
    assert list(ds["alpha"].values) == [20.0, 60.0] and ds.sizes["time"] == 301
    assert ds.attrs["method"] == "continuum" and ds.attrs["scenario"] == "B"
    # the same computation through the Python API gives the same numbers, bit for bit
    direct = me.simulate(params, "B", alpha=[20, 60], method="continuum", samples=301)
    np.testing.assert_array_equal(ds["tangential_force"].values, direct["tangential_force"].values)


def test_custom_path_and_discrete_options(tmp_path, without_drawing):
    path = write(tmp_path, """
[simulation]
method = "discrete"
dx = 2e-6
n_steps = 2000
[path]
waypoints = [[0, 0], [0, 3e-4], [2e-4, 3e-4], [2e-4, -1e-4]]
[output]
directory = "o"
""")
    study = load_study(path)
    assert study.name == "study" and study.output_directory == tmp_path / "o"
    written = me.run_study(study, progress=lambda message: None)
    ds = me.open_result(written[0].path)
    assert ds.attrs["scenario"] == "custom" and ds.attrs["dx"] == 2e-6
    # a [path] is one custom case along case, with its waypoints and speed (default: the parameters' v)
    assert ds["case"].values.tolist() == ["path 1"] and "alpha" not in ds.dims
    assert ds["path_waypoints"].values.tolist() == ["(0, 0); (0, 0.0003); (0.0002, 0.0003); (0.0002, -0.0001)"]
    assert ds["path_speed"].values.tolist() == [study.params.v]


@pytest.mark.parametrize("text, fragment", [
    ("[simulation]\nscenario = 'A'\n", "the required table [output] is missing"),
    ("[output]\ndirectory = 'o'\n", "nothing to compute"),
    ("[output]\ndirectory = 'o'\n[simulaton]\nscenario = 'A'\n", "unknown table [simulaton]; allowed: [parameters]"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nalpah = 3\n", "unknown key 'alpah' in [simulation]"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nalpha = 'steep'\n",
     "[simulation] alpha = 'steep' is not allowed; allowed: a number or a non-empty list of numbers"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nn_steps = 1.5\n",
     "[simulation] n_steps = 1.5 is not allowed; allowed: an integer"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nsamples = true\n", "samples = True is not allowed"),
    ("[output]\ndirectory = 'o'\n[simulation]\nmethod = 'discrete'\n", "[simulation] lacks the required key scenario"),
    ("[output]\n[phase_diagram]\nscenarios = ['A']\n", "[output] lacks the required key(s) directory"),
    ("[output]\ndirectory = 'o'\n[phase_diagram]\n", "[phase_diagram] lacks the required key(s) scenarios"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\n[parameters]\npreset = 'paper-R30'\nE = -1.0\n", "[parameters] Parameters.E=-1.0 is not allowed; allowed: a finite number > 0"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\n[parameters]\nE = '1 MPa'\n",
     "[parameters] E = '1 MPa' is not allowed; allowed: a number"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\n[parameters]\npreset = 'paper-R50'\n",
     "[parameters] preset='paper-R50' is not allowed; allowed: 'paper-R30', 'paper-R100'"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\n[path]\nwaypoints = [[0, 0], [0, 1e-4]]\n",
     "scenario and alpha are not allowed with a [path]"),
    ("[output]\ndirectory = 'o'\n[simulation]\n[path]\nwaypoints = [[0, 0]]\n",
     "[path] waypoints = [[0, 0]] is not allowed; allowed: a list of at least two [x, d] pairs"),
    ("output = 3\n", "output = 3 is not allowed; allowed: a table [output]"),
    ("[output\n", "not valid TOML"),
])
def test_bad_study_files_are_named_precisely(tmp_path, capsys, text, fragment):
    path = write(tmp_path, text)
    with pytest.raises(StudyError) as error:
        load_study(path)
    assert fragment in str(error.value) and str(path) in str(error.value)
    assert main(["run", str(path)]) == 2
    assert_one_error_line(capsys.readouterr().err, fragment)


@pytest.mark.parametrize("text, fragment", [
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'D'\n", "[simulation] scenario='D' is not allowed"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nalpha = 120\n", "alpha"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nmethod = 'continuum'\ndx = 1e-6\n",
     "dx is not allowed with method='continuum'"),
    ("[output]\ndirectory = 'o'\n[phase_diagram]\nscenarios = ['A', 'Q']\n", "scenarios contains 'Q'"),
    # settings of the other method are named, not silently ignored (found by review)
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nsamples = 5\n",
     "[simulation] samples is not allowed with method='discrete'"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nrtol = 1e-8\n",
     "[simulation] rtol is not allowed with method='discrete'"),
    ("[output]\ndirectory = 'o'\n[simulation]\nscenario = 'A'\nmethod = 'continuum'\nrtol = 2.0\n",
     "[simulation] Tolerances.rtol=2.0 is not allowed; allowed: a number in [2.22e-14, 1)"),
])
def test_bad_values_are_reported_by_the_function_they_go_to(tmp_path, capsys, text, fragment):
    path = write(tmp_path, text)
    assert main(["run", str(path)]) == 2
    assert_one_error_line(capsys.readouterr().err, fragment)
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())  # nothing written


def test_missing_study_file(tmp_path, capsys):
    assert main(["run", str(tmp_path / "nope.toml")]) == 2
    assert "no such study file" in capsys.readouterr().err


ALL_EIGHT = """
[parameters]
E = 1e6
nu = 0.4
R = 0.05
tau0 = 20e3
dgamma0 = 0.02
dgamma1 = 0.1
d_max = 2e-4
v = 2e-6

[phase_diagram]
scenarios = ["A"]

[output]
directory = "out"
"""


def test_without_a_preset_all_eight_parameters_are_required(tmp_path):
    """A [parameters] table that gives only E must not silently take the other seven from a preset."""
    path = write(tmp_path, "[parameters]\nE = 1e6\n[phase_diagram]\nscenarios = ['A']\n[output]\ndirectory = 'o'\n")
    with pytest.raises(StudyError, match="without a preset lacks nu, R, tau0, dgamma0, dgamma1, d_max, v"):
        load_study(path)
    study = load_study(write(tmp_path, ALL_EIGHT, "full.toml"))
    assert study.params == me.Parameters(E=1e6, nu=0.4, R=0.05, tau0=20e3, dgamma0=0.02, dgamma1=0.1,
                                         d_max=2e-4, v=2e-6)
    assert study.provenance == {}


def test_results_say_which_parameters_came_from_the_preset(tmp_path, capsys, without_drawing):
    assert main(["run", str(write(tmp_path, STUDY))]) == 0
    for name in ("demo_simulation.nc", "demo_phase_diagram_A.nc"):
        ds = me.open_result(tmp_path / "out" / name)
        assert ds.attrs["parameters_preset"] == "paper-R100"
        assert ds.attrs["parameters_from_preset"] == "E, nu, R, dgamma0, dgamma1, d_max, v"  # not tau0
    assert main(["run", str(write(tmp_path, ALL_EIGHT, "full.toml"))]) == 0
    assert "parameters_preset" not in me.open_result(tmp_path / "out" / "full_phase_diagram_A.nc").attrs


@pytest.mark.parametrize("text, fragment", [
    ("[validate]\nscenario = 'A'\nalpha = 20\n", "[validate] lacks the required key(s) runs"),
    ("[validate]\nruns = 'run.csv'\nscenario = 'A'\nalpha = 20\n",
     "[validate] runs = 'run.csv' is not allowed; allowed: a non-empty list of strings"),
    ("[validate]\nruns = ['r.csv']\nscenario = 'A'\nalpha = 20\nnames = 3\n",
     "[validate] names = 3 is not allowed; allowed: a table of strings"),
    ("[validate]\nruns = ['r.csv']\nscenario = 'A'\nalpha = 20\ntolerance = 'tight'\n",
     "[validate] tolerance = 'tight' is not allowed; allowed: a number"),
    ("[validate]\nruns = ['r.csv']\nscenario = 'A'\nalpha = 20\ntime_origin = [1]\n",
     "[validate] time_origin = [1] is not allowed; allowed: a string or a number"),
    ("[validate]\nruns = ['r.csv']\nalpha = 20\n", "[validate] lacks the key scenario"),
    ("[validate]\nruns = ['r.csv']\n[simulation]\nscenario = 'A'\nalpha = [10, 20]\n",
     "[validate] needs one angle; [simulation] alpha = [10, 20] is not allowed"),
    ("[validate]\nruns = ['r.csv']\nscenario = 'A'\nalpha = 20\n[path]\nwaypoints = [[0, 0], [0, 1e-4]]\n",
     "[validate] scenario and alpha are not allowed with a [path]"),
    ("[validate]\nruns = ['r.csv']\nscenario = 'A'\nalpah = 20\n", "unknown key 'alpah' in [validate]"),
    ('[fit]\ndata = "x.csv"\n', "[fit] lacks the required key(s) free"),
    ('[fit]\ndata = "x.csv"\nfree = ["tau0"]\nbounds = { tau0 = 3 }\nscenario = "A"\nalpha = 20\n',
     "[fit] bounds = {'tau0': 3} is not allowed"),
    ('[fit]\ndata = "x.csv"\nfree = ["tau0"]\n', "[fit] lacks the key scenario"),
    ('[fit]\ndata = "x.csv"\nfree = ["tau0"]\nscenario = "A"\nalpha = [10, 20]\n', "[fit] needs one angle"),
    ('[sweep]\nscenario = "A"\n', "[sweep] needs one of grid"),
    ('[sweep]\ngrid = { tau0 = [1e3] }\nsets = [{ tau0 = 1e3 }]\n', "[sweep] needs one of grid"),
    ('[sweep]\ngrid = { tau0 = "x" }\n', "[sweep] grid = {'tau0': 'x'} is not allowed"),
    ('[sweep]\ngrid = { tau0 = [1e3] }\nworkers = "2"\n', "[sweep] workers = '2' is not allowed"),
    ('[sweep]\ngrid = { tau0 = [1e3] }\n[limits]\nsteps = "many"\n', "[limits] 'steps=many' is not allowed"),
    ('[profile]\nc = 2000.0\n[phase_diagram]\nscenarios = ["A"]\n', "[profile] has the keys ['c']; allowed: c and n"),
    ('[profile]\nradius = 1e-3\nn = 2.0\n[phase_diagram]\nscenarios = ["A"]\n', "[profile] has the keys ['n', 'radius']"),
    ('[profile]\nradius = -1e-3\n[phase_diagram]\nscenarios = ["A"]\n', "[profile] FlatPunch.radius=-0.001 is not allowed"),
    ('[profile]\nc = 2000.0\nn = 0.5\n[phase_diagram]\nscenarios = ["A"]\n', "[profile] PowerLaw.n=0.5 is not allowed in the simulators; allowed: n >= 1"),
    ('[profile]\nc = -1.0\nn = 2.0\n[phase_diagram]\nscenarios = ["A"]\n', "[profile] PowerLaw.c=-1.0 is not allowed"),
    ('[friction]\nlaw = "amontons"\n[phase_diagram]\nscenarios = ["A"]\n', "[friction] FrictionLaw.law='amontons' is "
                                                                           "not allowed"),
    ('[friction]\nlaw = "coulomb"\n[phase_diagram]\nscenarios = ["A"]\n', "[friction] mu=None is not allowed"),
    ('[friction]\nmu = 0.3\n[phase_diagram]\nscenarios = ["A"]\n', "[friction] lacks the required key(s) law"),
])
def test_bad_validate_fit_sweep_and_limits_tables_are_named(capsys, tmp_path, text, fragment):
    """Named when the study is read, and by `mdr-events run` in one line with exit status 2."""
    path = tmp_path / "study.toml"
    path.write_text(text + '[output]\ndirectory = "out"\n')
    with pytest.raises(StudyError) as error:
        load_study(path)
    assert fragment in str(error.value) and str(path) in str(error.value)
    assert main(["run", str(path)]) == 2
    assert fragment in capsys.readouterr().err


def test_a_profile_table_gives_every_table_its_indenter(tmp_path, without_drawing):
    """[profile] c, n: the simulation and the phase diagram are the power law's, as through the Python API."""
    path = write(tmp_path, STUDY.replace("[output]", "[profile]\nc = 2000.0\nn = 3.0\n\n[output]"))
    assert main(["run", str(path)]) == 0
    out = tmp_path / "out"
    profile = me.PowerLaw(2000.0, 3.0)
    ds = me.open_result(out / "demo_simulation.nc")
    assert ds.attrs["profile"] == profile.describe()
    params = me.Parameters.paper(R=0.1).replace(tau0=30e3)
    direct = me.simulate(params, "B", alpha=[20, 60], method="continuum", samples=301, profile=profile)
    np.testing.assert_array_equal(ds["tangential_force"].values, direct["tangential_force"].values)
    diagram = me.open_result(out / "demo_phase_diagram_A.nc")
    assert diagram.attrs["profile"] == profile.describe()
    assert float(diagram["critical_angle_jkr"]) == me.power_law.critical_angle_A(profile, params)


def test_a_friction_table_gives_every_table_its_law(tmp_path, without_drawing):
    """[friction] law, mu: the simulation and both phase diagrams are the law's, as through the Python API (the
    study's parameters without adhesion, which Coulomb's part needs in the continuum)."""
    text = STUDY.replace("tau0 = 30e3\n", "tau0 = 30e3\ndgamma0 = 0.0\ndgamma1 = 0.0\n").replace(
        "[output]", '[friction]\nlaw = "tau0+coulomb"\nmu = 0.2\n\n[output]')
    path = write(tmp_path, text)
    assert main(["run", str(path)]) == 0
    out = tmp_path / "out"
    friction = me.FrictionLaw("tau0+coulomb", mu=0.2)
    params = me.Parameters.paper(R=0.1).replace(tau0=30e3, dgamma0=0.0, dgamma1=0.0)
    ds = me.open_result(out / "demo_simulation.nc")
    assert ds.attrs["friction_law"] == "tau0+coulomb" and ds.attrs["friction_mu"] == 0.2
    direct = me.simulate(params, "B", alpha=[20, 60], method="continuum", samples=301, friction=friction)
    np.testing.assert_array_equal(ds["tangential_force"].values, direct["tangential_force"].values)
    diagram = me.open_result(out / "demo_phase_diagram_A.nc")
    assert float(diagram["critical_angle_hertz"]) == me.mindlin.critical_angle_A(friction, params)


def test_a_profile_table_may_name_a_tabulated_tip(tmp_path, without_drawing):
    """[profile] table = "tip.csv" (relative to the study file): the simulation is the table's."""
    r = np.linspace(0.0, 1e-2, 41)  # (the study's R = 100 mm: g reaches 1 mm of depth at 10 mm)
    (tmp_path / "tip.csv").write_text("r,f\n" + "".join(f"{float(a)!r},{float(a * a / 0.2)!r}\n" for a in r))
    text = STUDY.replace("[output]", '[profile]\ntable = "tip.csv"\n\n[output]').replace(
        'scenarios = ["A", "B"]', 'scenarios = ["A"]')
    path = write(tmp_path, text)
    assert main(["run", str(path)]) == 0
    ds = me.open_result(tmp_path / "out" / "demo_simulation.nc")
    assert ds.attrs["profile"].startswith("tabulated profile f(r), 41 points")
