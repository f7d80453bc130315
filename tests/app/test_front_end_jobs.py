"""One set of typed jobs for both front ends: for the same input the command line and a study file build equal jobs
(they differ only in the stem of the files they write), and each input has one parser (``mdr_events.app.inputs``)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.app import inputs
from mdr_events.app.cli import build_parser
from mdr_events.app.cli import fit as fit_verb
from mdr_events.app.cli import phase_diagram as phase_verb
from mdr_events.app.cli import simulate as simulate_verb
from mdr_events.app.cli import validate as validate_verb
from mdr_events.app.jobs import FitJob, PhaseJob, SimulateJob, SweepJob, ValidateJob
from mdr_events.app.study import StudyError, load_study
from mdr_events.models.methods import Continuum, Discrete
from mdr_events.models.motion import Paths, Scenario


def cli_args(*argv: str):
    return build_parser().parse_args(list(argv))


def study_of(tmp_path: Path, text: str):
    path = tmp_path / "study.toml"
    path.write_text(text + '\n[output]\ndirectory = "out"\n')
    return load_study(path)


# --- the command line and a study file build equal jobs, one test per verb -------------------------------------

def test_simulate_builds_the_same_job_from_both_front_ends(tmp_path):
    cli = simulate_verb.job(cli_args("simulate", "--scenario", "B", "--alpha", "20", "60", "--method", "discrete",
                                     "--dx", "2e-6", "--n-steps", "2000", "--tau0", "30e3", "--power-law", "2000", "3",
                                     "--limit", "steps=1e8", "--out", "o"))
    study = study_of(tmp_path, '[parameters]\npreset = "paper-R30"\ntau0 = 30e3\n[simulation]\nscenario = "B"\n'
                               'alpha = [20, 60]\nmethod = "discrete"\ndx = 2e-6\nn_steps = 2000\n'
                               '[profile]\nc = 2000.0\nn = 3.0\n[limits]\nsteps = 1e8\n').simulation
    assert isinstance(cli, SimulateJob) and dataclasses.replace(cli, stem=study.stem) == study
    assert cli.motion == Scenario("B", (20.0, 60.0), 0.3e-3, 1e-6) and cli.method == Discrete(dx=2e-6, n_steps=2000)
    assert cli.contact.indenter == me.PowerLaw(2000.0, 3.0) and cli.limits == me.Limits(steps=1e8)
    assert (cli.stem, study.stem) == ("simulation_B_discrete", "study_simulation")


def test_simulate_with_the_continuum_and_a_friction_law(tmp_path):
    cli = simulate_verb.job(cli_args("simulate", "--scenario", "A", "--method", "continuum", "--friction",
                                     "tau0+coulomb", "--mu", "0.2", "--out", "o"))
    study = study_of(tmp_path, '[simulation]\nscenario = "A"\nmethod = "continuum"\n'
                               '[friction]\nlaw = "tau0+coulomb"\nmu = 0.2\n').simulation
    assert dataclasses.replace(cli, stem=study.stem) == study
    assert cli.method == Continuum() and cli.motion.alpha == me.models.motion.FIGURE_ANGLES
    assert cli.contact.friction == me.FrictionLaw("tau0+coulomb", tau0=me.Parameters.paper().tau0, mu=0.2)


def test_phase_diagram_builds_the_same_job_from_both_front_ends(tmp_path):
    cli = phase_verb.job(cli_args("phase-diagram", "--scenario", "B", "--preset", "paper-R100", "--flat-punch", "1e-3",
                                  "--out", "o"))
    study = study_of(tmp_path, '[parameters]\npreset = "paper-R100"\n[phase_diagram]\nscenarios = ["A", "B"]\n'
                               '[profile]\nradius = 1e-3\n')
    assert isinstance(cli, PhaseJob) and [job.scenario for job in study.phase_diagrams] == ["A", "B"]
    assert dataclasses.replace(cli, stem=study.phase_diagrams[1].stem) == study.phase_diagrams[1]
    assert cli.contact.indenter == me.FlatPunch(1e-3) and cli.provenance["parameters_preset"] == "paper-R100"


def test_validate_builds_the_same_job_from_both_front_ends(tmp_path):
    run = str(tmp_path / "run_dx2um.csv")  # (read when the job runs, not when it is built)
    cli, note = validate_verb.job(cli_args("validate", run, "--scenario", "A", "--alpha", "20", "--out", "o",
                                           "--names", "time=t,normal_force=Fn", "--units", "time=ms",
                                           "--time-origin", "path_start", "--tolerance", "1e-2", "--E", "2e6"))
    study = study_of(tmp_path, f'[parameters]\npreset = "paper-R30"\nE = 2e6\n[validate]\nruns = ["{run}"]\n'
                               'names = { time = "t", normal_force = "Fn" }\nunits = { time = "ms" }\n'
                               'time_origin = "path_start"\ntolerance = 1e-2\nscenario = "A"\nalpha = 20\n').validation
    assert isinstance(cli, ValidateJob) and note is None
    assert dataclasses.replace(cli, stems=study.stems) == study
    assert cli.motion == Scenario("A", (20.0,), 0.3e-3, 1e-6) and cli.description == "scenario A, α = 20°"
    assert (cli.stems, study.stems) == (("run_dx2um",), ("study_validation_run_dx2um",))


def test_validate_builds_the_convergence_study_from_the_command_line_only():
    cli, _ = validate_verb.job(cli_args("validate", "a.csv", "b.csv", "c.csv", "--scenario", "A", "--alpha", "20",
                                        "--out", "o", "--dx", "8e-6", "4e-6", "2e-6"))
    assert cli.spacings == (8e-6, 4e-6, 2e-6) and cli.files == (Path("a.csv"), Path("b.csv"), Path("c.csv"))


def test_fit_builds_the_same_job_from_both_front_ends(tmp_path):
    data = str(tmp_path / "measured.csv")
    cli = fit_verb.job(cli_args("fit", data, "--scenario", "A", "--alpha", "20", "--free", "tau0", "dgamma1",
                                "--out", "o", "--bounds", "tau0=1e3:1e6", "--noise", "normal_force=2e-3",
                                "--tau0", "30e3", "--limit", "memory=8GiB"))
    study = study_of(tmp_path, f'[parameters]\npreset = "paper-R30"\ntau0 = 30e3\n[fit]\ndata = "{data}"\n'
                               'free = ["tau0", "dgamma1"]\nbounds = {{ tau0 = [1e3, 1e6] }}\n'
                               'noise = {{ normal_force = 2e-3 }}\nscenario = "A"\nalpha = 20\n'
                               '[limits]\nmemory = "8GiB"\n'.replace("{{", "{").replace("}}", "}")).fit
    assert isinstance(cli, FitJob) and dataclasses.replace(cli, stem=study.stem) == study
    assert cli.free == ("tau0", "dgamma1") and cli.bounds == {"tau0": (1e3, 1e6)}
    assert (cli.stem, study.stem) == ("measured_fit", "study_fit_measured")


def test_sweep_is_the_study_s_job(tmp_path):
    """``mdr-events sweep`` runs the study file's [sweep] job (with --scheduler and --workers over the table's)."""
    study = study_of(tmp_path, '[sweep]\ngrid = { tau0 = [30e3, 42e3], alpha = 20 }\nscenario = "B"\n'
                               'method = "continuum"\nquantities = ["tangential_force_max"]\nscheduler = "serial"\n')
    job = study.sweep
    assert isinstance(job, SweepJob) and job.grid == {"tau0": [30e3, 42e3], "alpha": [20]}
    assert job.contact == me.Contact.from_parameters(study.params)
    assert job.motion == me.Scenario("B", d_max=study.params.d_max, v=study.params.v)  # (the grid puts its angle in)
    assert job.method == me.Continuum() and job.output.quantities == ("tangential_force_max",)
    assert job.store == tmp_path / "out" / "study_sweep.zarr" and job.engine == me.Engine("serial")
    # the study's sweep gives what sweep() gives of the same values
    swept = job.compute()
    again = me.sweep(job.grid, job.contact, job.motion, method="continuum", quantities=("tangential_force_max",),
                     scheduler="serial")
    np.testing.assert_array_equal(swept["tangential_force_max"].values, again["tangential_force_max"].values)


def test_a_study_holds_typed_jobs_in_the_order_it_writes_them(tmp_path):
    study = study_of(tmp_path, '[simulation]\nscenario = "A"\nalpha = 20\n[phase_diagram]\nscenarios = ["B"]\n'
                               '[sweep]\nsets = [{ tau0 = 3e4 }]\nalpha = 20\n')
    assert [type(job).__name__ for job in study.jobs] == ["SimulateJob", "PhaseJob", "SweepJob"]
    assert study.validation is None and study.fit is None and not hasattr(study, "tables")


def test_a_study_s_path_is_one_custom_case_named_by_its_parameters(tmp_path):
    study = study_of(tmp_path, '[simulation]\nmethod = "continuum"\nsamples = 11\n'
                               '[path]\nwaypoints = [[0, 0], [0, 3e-4], [2e-4, -1e-4]]\nspeed = 2e-6\n')
    motion = study.simulation.motion
    assert isinstance(motion, Paths) and list(motion.paths) == ["path 1"]
    assert (motion.d_max, motion.v) == (study.params.d_max, study.params.v)
    assert study.simulation.method == Continuum(samples=11)


# --- the shared parsers ---------------------------------------------------------------------------------------

def test_parameters_parser():
    params, provenance = inputs.parameters(None, {"tau0": 3e4})
    assert params == me.Parameters.paper().replace(tau0=3e4) and provenance["parameters_preset"] == "paper-R30"
    assert "tau0" not in provenance["parameters_from_preset"]
    full = dict(E=1e6, nu=0.4, R=0.05, tau0=2e4, dgamma0=0.02, dgamma1=0.1, d_max=2e-4, v=2e-6)
    assert inputs.parameters(None, full, complete=True) == (me.Parameters(**full), {})
    assert inputs.parameters(None, full, {"E": 2e6}, complete=True)[0].E == 2e6
    with pytest.raises(ValueError, match="without a preset lacks nu, R"):
        inputs.parameters(None, {"E": 1e6}, {"nu": 0.4}, complete=True)  # (the table itself must hold all eight)
    with pytest.raises(ValueError, match="preset='paper-R50' is not allowed"):
        inputs.parameters("paper-R50", {})


def test_indenter_parser(tmp_path):
    assert inputs.indenter() is None
    assert inputs.indenter(power_law=(2000.0, 3.0)) == me.PowerLaw(2000.0, 3.0)
    assert inputs.indenter(radius=1e-3) == me.FlatPunch(1e-3)
    table = tmp_path / "tip.csv"
    table.write_text("r,f\n" + "".join(f"{r!r},{r * r / 0.2!r}\n" for r in (0.0, 1e-3, 2e-3, 3e-3, 4e-3)))
    assert isinstance(inputs.indenter(table=table), me.TabulatedProfile)
    with pytest.raises(ValueError, match="PowerLaw.n=0.5 is not allowed in the simulators"):
        inputs.indenter(power_law=(2000.0, 0.5))
    assert inputs.indenter(power_law=(2000.0, 0.5), simulated=False) == me.PowerLaw(2000.0, 0.5)


def test_friction_parser():
    assert inputs.friction() == me.FrictionLaw() and inputs.friction("coulomb", 0.3) == me.FrictionLaw("coulomb", mu=0.3)
    with pytest.raises(ValueError, match="mu=None is not allowed"):
        inputs.friction("coulomb")
    with pytest.raises(ValueError, match="law='amontons' is not allowed"):
        inputs.friction("amontons")


def test_limits_parser():
    assert inputs.limits([]) == me.Limits()
    assert inputs.limits(["steps=1e8", "memory=8GiB"]) == me.Limits(steps=1e8, memory=8 * 2**30)
    with pytest.raises(ValueError, match="'speed=1' is not allowed"):
        inputs.limits(["speed=1"])


def test_path_and_motion_parsers():
    params = me.Parameters.paper()
    path = inputs.path([[0, 0], [0, 3e-4]], None, params)
    assert path.speed == params.v and inputs.path([[0, 0], [0, 3e-4]], 2e-6, params).speed == 2e-6
    assert inputs.scenario("A", None, params) == Scenario("A", me.models.motion.FIGURE_ANGLES, params.d_max, params.v)
    assert inputs.scenario("B+", [20], params).alpha == (20.0,)
    assert inputs.paths(path, params).d_max == params.d_max
    with pytest.raises(ValueError, match="scenario='D' is not allowed"):
        inputs.scenario("D", None, params)
    with pytest.raises(ValueError):
        inputs.path([[0, 0]], None, params)


def test_contact_and_method_parsers():
    params = me.Parameters.paper()
    assert inputs.contact(params) == me.Contact.paper()
    assert inputs.method("discrete", {"dx": 2e-6, "dt": None}) == Discrete(dx=2e-6)
    assert inputs.method("continuum", {}) == Continuum()
    with pytest.raises(ValueError, match="dx is not allowed with method='continuum'"):
        inputs.method("continuum", {"dx": 1e-6})


def test_both_front_ends_name_a_bad_value_where_it_came_from(tmp_path):
    from mdr_events.app.cli._options import UsageError

    with pytest.raises(UsageError, match=r"^--power-law 2000 0.5: PowerLaw.n=0.5 is not allowed"):
        simulate_verb.job(cli_args("simulate", "--scenario", "A", "--power-law", "2000", "0.5", "--out", "o"))
    with pytest.raises(StudyError, match=r"study.toml: \[profile\] PowerLaw.n=0.5 is not allowed"):
        study_of(tmp_path, '[simulation]\nscenario = "A"\n[profile]\nc = 2000.0\nn = 0.5\n')
