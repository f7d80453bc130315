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
    scenarios = ["A", "B"]

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

    [limits]                     # optional: the resource limits (mdr_events.Limits), as --limit
    steps = 1e8                  # memory = "8GiB", springs, samples, waypoints; inf: no limit

    [profile]                    # optional: a power-law indenter f = c r^n (n >= 1) for every table, as
    c = 2000.0                   # --power-law C N; without it the paraboloid of R
    n = 3.0

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

The ``[parameters]`` and ``[path]`` tables can also be read alone (:func:`load_parameters_file`,
:func:`load_path_file`): ``mdr-events validate --params FILE --path FILE`` takes them from any TOML file
holding them, a study file among others.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path as FilePath
from typing import TYPE_CHECKING, Any, Callable, Iterable

from mdr_events.analysis.fit import fit
from mdr_events.analysis.sweep import sweep
from mdr_events.analysis.validate import validate
from mdr_events.io.files import check_file_path, check_output_stem, prepare_output_directory
from mdr_events.limits import DEFAULT_LIMITS, LIMIT_UNITS, Limits, parse_limit
from mdr_events.models.continuum import Tolerances
from mdr_events.models.paths import Path
from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile
from mdr_events.models.motion import scenario_paths
from mdr_events.models.simulate import simulate
from mdr_events.parameters import PARAMETER_UNITS, PRESETS, Parameters, from_preset
from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.io.candidates import read_profile_table
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.validation import shown

if TYPE_CHECKING:
    from mdr_events.app.result_files import FileOutcome
    from mdr_events.app.validation_files import RenderedReport

__all__ = ["Study", "StudyOutcomes", "load_study", "run_study", "run_sweep", "sweep_store", "StudyError", "load_parameters_file",
           "load_path_file"]


class StudyError(ValueError):
    """A study file that cannot be run; the message names the file, table and key."""


# kind -> (check, description of what is allowed)
def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


_KINDS: dict[str, tuple[Callable[[Any], bool], str]] = {
    "number": (_is_number, "a number"),
    "integer": (lambda v: isinstance(v, int) and not isinstance(v, bool), "an integer"),
    "string": (lambda v: isinstance(v, str), "a string"),
    "numbers": (lambda v: _is_number(v) or (isinstance(v, list) and len(v) > 0 and all(map(_is_number, v))),
                "a number or a non-empty list of numbers"),
    "strings": (lambda v: isinstance(v, list) and len(v) > 0 and all(isinstance(s, str) for s in v),
                "a non-empty list of strings"),
    "points": (lambda v: isinstance(v, list) and len(v) >= 2
               and all(isinstance(p, list) and len(p) == 2 and all(map(_is_number, p)) for p in v),
               "a list of at least two [x, d] pairs of numbers (m)"),
    "string table": (lambda v: isinstance(v, dict) and all(isinstance(s, str) for s in v.values()),
                     'a table of strings, e.g. { time = "t", normal_force = "Fn" }'),
    "string or number": (lambda v: isinstance(v, str) or _is_number(v), "a string or a number"),
    "number table": (lambda v: isinstance(v, dict) and all(map(_is_number, v.values())),
                     "a table of numbers, e.g. { normal_force = 1e-3 }"),
    "bounds table": (lambda v: isinstance(v, dict) and all(isinstance(p, list) and len(p) == 2
                                                            and all(map(_is_number, p)) for p in v.values()),
                     "a table of [lower, upper] pairs, e.g. { tau0 = [1e3, 1e6] }"),
    "grid table": (lambda v: isinstance(v, dict) and len(v) > 0 and all(
        _is_number(p) or (isinstance(p, list) and len(p) > 0 and all(map(_is_number, p))) for p in v.values()),
                   "a table of names to lists of numbers, e.g. { tau0 = [30e3, 42e3], alpha = [10, 20] }"),
    "tables": (lambda v: isinstance(v, list) and len(v) > 0 and all(
        isinstance(row, dict) and all(map(_is_number, row.values())) for row in v),
               "a list of tables of numbers (parameter sets), e.g. [{ tau0 = 30e3 }, { tau0 = 42e3 }]"),
}

#: Table -> key -> (kind, required).
SCHEMA: dict[str, dict[str, tuple[str, bool]]] = {
    "parameters": {"preset": ("string", False), **{name: ("number", False) for name in PARAMETER_UNITS}},
    "simulation": {"scenario": ("string", False), "alpha": ("numbers", False), "method": ("string", False),
                   "dx": ("number", False), "dt": ("number", False), "n_steps": ("integer", False),
                   "samples": ("integer", False), "rtol": ("number", False), "atol": ("number", False)},
    "path": {"waypoints": ("points", True), "speed": ("number", False)},
    "phase_diagram": {"scenarios": ("strings", True)},
    "validate": {"runs": ("strings", True), "tolerance": ("number", False), "names": ("string table", False),
                 "units": ("string table", False), "time_origin": ("string or number", False),
                 "scenario": ("string", False), "alpha": ("numbers", False)},
    "fit": {"data": ("string", True), "free": ("strings", True), "names": ("string table", False),
            "units": ("string table", False), "time_origin": ("string or number", False),
            "noise": ("number table", False), "bounds": ("bounds table", False), "scenario": ("string", False),
            "alpha": ("numbers", False)},
    "sweep": {"grid": ("grid table", False), "sets": ("tables", False), "scenario": ("string", False),
              "alpha": ("number", False), "method": ("string", False), "dx": ("number", False),
              "n_steps": ("integer", False), "quantities": ("strings", False), "chunk_size": ("integer", False),
              "scheduler": ("string", False), "workers": ("integer", False), "history_samples": ("integer", False)},
    "limits": {name: ("string or number", False) for name in LIMIT_UNITS},
    "profile": {"c": ("number", False), "n": ("number", False), "radius": ("number", False),
                "table": ("string", False)},
    "friction": {"law": ("string", True), "mu": ("number", False)},
    "output": {"directory": ("string", True), "name": ("string", False)},
}
REQUIRED_TABLES = ("output",)


@dataclass(frozen=True)
class Study:
    """A checked study: the tables of the file, with the study file's location."""

    source: FilePath
    params: Parameters
    tables: dict[str, dict[str, Any]] = field(default_factory=dict)
    #: Attributes every result of the study carries: which parameter values came from a preset.
    provenance: dict[str, str] = field(default_factory=dict)

    @property
    def output_directory(self) -> FilePath:
        directory = FilePath(self.tables["output"]["directory"])
        return directory if directory.is_absolute() else self.source.parent / directory

    @property
    def name(self) -> str:
        return self.tables["output"].get("name", self.source.stem)

    @property
    def limits(self) -> Limits:
        """The ``[limits]`` table over the defaults (:class:`~mdr_events.limits.Limits`; ``memory`` may be
        ``"8GiB"``; ``inf`` switches a limit off), as ``--limit NAME=VALUE`` on the command line."""
        limits = DEFAULT_LIMITS
        for name, value in self.tables.get("limits", {}).items():
            try:
                limits = parse_limit(f"{name}={value}", limits)
            except ValueError as error:
                raise StudyError(f"{os.fspath(self.source)}: [limits] {error}".replace("--limit ", "")) from None
        return limits

    @property
    def profile(self) -> SimulatedProfile:
        """The ``[profile]`` table's indenter: ``c`` and ``n`` for ``f = c rⁿ`` (``n >= 1``), as ``--power-law C N``
        on the command line, or ``radius`` for the flat punch, as ``--flat-punch RADIUS``; ``None`` without it: the
        paraboloid of ``R``."""
        if "profile" not in self.tables:
            return None
        table = self.tables["profile"]
        where = f"{os.fspath(self.source)}: [profile]"
        if sorted(table) not in (["c", "n"], ["radius"], ["table"]):
            raise StudyError(f"{where} has the keys {sorted(table)}; allowed: c and n (a power law f = c r^n), radius "
                             "(a flat punch) or table (a CSV file with the columns r and f, relative to the study file)")
        try:
            if "table" in table:
                file = FilePath(table["table"])
                profile = read_profile_table(file if file.is_absolute() else self.source.parent / file)
            else:
                profile = FlatPunch(table["radius"]) if "radius" in table else PowerLaw(table["c"], table["n"])
            return check_simulated_profile(profile)
        except (ValueError, TypeError) as error:
            raise StudyError(f"{where} {error}") from None

    @property
    def friction(self) -> FrictionLaw:
        """The ``[friction]`` table's law (``law``, and ``mu`` for a law with Coulomb's part), as ``--friction LAW --mu
        MU`` on the command line; the paper's ``"tau0"`` without it."""
        if "friction" not in self.tables:
            return TAU0
        table = self.tables["friction"]
        try:
            return FrictionLaw(table["law"], mu=table.get("mu"))
        except (ValueError, TypeError) as error:
            raise StudyError(f"{os.fspath(self.source)}: [friction] {error}") from None


def _check_table(table: str, content: Any, where: str) -> None:
    """Raise :class:`StudyError` unless ``content`` is a table ``[table]`` of known keys of the right kinds."""
    if not isinstance(content, dict):
        raise StudyError(f"{where}: {table} = {content!r} is not allowed; allowed: a table [{table}]")
    keys = SCHEMA[table]
    for key, value in content.items():
        if key not in keys:
            raise StudyError(f"{where}: unknown key {key!r} in [{table}]; allowed: {', '.join(keys)}")
        check, allowed = _KINDS[keys[key][0]]
        if not check(value):
            raise StudyError(f"{where}: [{table}] {key} = {value!r} is not allowed; allowed: {allowed}")
    missing = [key for key, (_, required) in keys.items() if required and key not in content]
    if missing:
        raise StudyError(f"{where}: [{table}] lacks the required key(s) {', '.join(missing)}")


def _check_tables(document: dict[str, Any], where: str) -> None:
    for table, content in document.items():
        if table not in SCHEMA:
            raise StudyError(f"{where}: unknown table [{table}]; allowed: "
                             + ", ".join(f"[{name}]" for name in SCHEMA))
        _check_table(table, content, where)
    for table in REQUIRED_TABLES:
        if table not in document:
            raise StudyError(f"{where}: the required table [{table}] is missing")
    if not {"simulation", "phase_diagram", "validate", "fit", "sweep"} & set(document):
        raise StudyError(f"{where}: nothing to compute; give a [simulation] table, a [phase_diagram] table, "
                         "a [validate] table, a [fit] table, a [sweep] table or several")
    if "path" in document and not {"simulation", "validate", "fit", "sweep"} & set(document):
        raise StudyError(f"{where}: a [path] needs a [simulation] table (method, dx, ...), a [validate] table, a "
                         "[fit] table or a [sweep] table")
    if "sweep" in document and ("grid" in document["sweep"]) == ("sets" in document["sweep"]):
        raise StudyError(f"{where}: [sweep] needs one of grid (names to values: the outer product) and sets "
                         "(a list of parameter sets)")
    simulation = document.get("simulation", {})
    if "path" in document and ("scenario" in simulation or "alpha" in simulation):
        raise StudyError(f"{where}: [simulation] scenario and alpha are not allowed with a [path] "
                         "(its waypoints fix the motion)")
    if "simulation" in document and "path" not in document and "scenario" not in simulation:
        raise StudyError(f"{where}: [simulation] lacks the required key scenario (or give a [path] table)")
    for table in ("validate", "fit"):
        if table in document:
            _measured_case(document, where, table)
    if "name" in document["output"]:
        try:
            check_output_stem("[output] name", document["output"]["name"])
        except ValueError as error:
            raise StudyError(f"{where}: {error}") from None


def _measured_case(document: dict[str, Any], where: str, name: str) -> tuple[str, float] | None:
    """The scenario and angle the measured runs of table ``[name]`` (``validate``, ``fit``) took, or ``None`` for
    the study's ``[path]``."""
    table, simulation = document[name], document.get("simulation", {})
    if "path" in document:
        if "scenario" in table or "alpha" in table:
            raise StudyError(f"{where}: [{name}] scenario and alpha are not allowed with a [path] "
                             "(the runs are taken along its waypoints)")
        return None
    owner = name if "scenario" in table else "simulation"
    scenario = table.get("scenario", simulation.get("scenario"))
    if scenario is None:
        raise StudyError(f"{where}: [{name}] lacks the key scenario; allowed: scenario and alpha in [{name}], "
                         "a [simulation] scenario and alpha, or a [path] table")
    owner = name if "alpha" in table else owner
    alpha = table.get("alpha", simulation.get("alpha"))
    angles = alpha if isinstance(alpha, list) else [] if alpha is None else [alpha]
    if len(angles) != 1:
        raise StudyError(f"{where}: [{name}] needs one angle; [{owner}] alpha = {alpha!r} is not allowed; "
                         f"allowed: one angle in degrees (give alpha in [{name}])")
    return str(scenario), float(angles[0])


#: The largest study or parameter file read (bytes): far above any study, far below what would take long to parse.
MAX_TOML_BYTES = 2**22


def _read_toml(path: Any, what: str) -> tuple[dict[str, Any], FilePath]:
    """The TOML document of the file at ``path`` (a ``what``, e.g. "study file") and the file's path.

    Raises ``TypeError`` if ``path`` is not a ``str`` or ``os.PathLike``, and :class:`StudyError` naming the
    file if it is missing, a directory, unreadable, not UTF-8 text or not valid TOML.
    """
    source = check_file_path("path", path, f"a str or os.PathLike naming a {what} (.toml)")
    where = os.fspath(source)
    allowed = f"allowed: a {what}, TOML in UTF-8 text"
    if os.path.exists(source) and not os.path.isdir(source) and not os.path.isfile(source):
        raise StudyError(f"{where} is not a regular file (a device, FIFO or socket); {allowed}")
    try:
        if os.path.getsize(source) > MAX_TOML_BYTES:
            raise StudyError(f"{where} has {os.path.getsize(source)} bytes; {allowed}, at most {MAX_TOML_BYTES} bytes")
        with open(source, "rb") as handle:  # (a byte-order mark, as "UTF-8 with BOM" editors write, is read)
            return tomllib.loads(handle.read().decode("utf-8-sig")), source
    except FileNotFoundError:
        raise StudyError(f"{where}: no such {what}") from None
    except IsADirectoryError:
        raise StudyError(f"{where} is a directory; {allowed}") from None
    except UnicodeDecodeError as error:
        raise StudyError(f"{where}: not UTF-8 text (byte {error.start}: {error.reason}); {allowed}") from None
    except tomllib.TOMLDecodeError as error:
        raise StudyError(f"{where}: not valid TOML ({error}); {allowed}") from None
    except OSError as error:
        raise StudyError(f"{where} cannot be read ({error.strerror or error}); {allowed}") from None


def _parameters(table: dict[str, Any] | None, where: str,
                overrides: dict[str, float] | None = None) -> tuple[Parameters, dict[str, str]]:
    """The parameters of a checked ``[parameters]`` table (``None``: none given, the preset paper-R30), with
    ``overrides`` on top, and the provenance attributes."""
    settings = {key: value for key, value in (table or {}).items() if key != "preset"}
    preset = (table or {}).get("preset")
    if preset is None and table is not None:
        missing = [name for name in PARAMETER_UNITS if name not in settings]
        if missing:
            raise StudyError(f"{where}: [parameters] without a preset lacks {', '.join(missing)}; allowed: all "
                             f"eight of {', '.join(PARAMETER_UNITS)}, or preset = "
                             + " or ".join(map(repr, PRESETS)) + " and any of them as overrides")
    values = {key: float(value) for key, value in {**settings, **(overrides or {})}.items()}
    try:
        if preset is None and table is not None:
            return Parameters(**values), {}
        return from_preset("paper-R30" if preset is None else preset, **values)
    except ValueError as error:
        raise StudyError(f"{where}: [parameters] {error}") from None


def load_study(path: str | os.PathLike) -> Study:
    """Read and check a study file.

    Raises
    ------
    TypeError
        If ``path`` is not a ``str`` or ``os.PathLike`` (e.g. ``None``).
    StudyError
        A ``ValueError`` naming the file, the table, the key and what is allowed: a file that is missing, a
        directory, not UTF-8 text or not valid TOML, and every table or key that cannot be run.
    """
    document, source = _read_toml(path, "study file")
    where = os.fspath(source)
    _check_tables(document, where)
    params, provenance = _parameters(document.get("parameters"), where)
    study = Study(source, params, {table: dict(content) for table, content in document.items()}, provenance)
    study.limits  # a bad [limits] value is named now, not after the first computation
    study.profile  # so is a bad [profile]
    study.friction  # and a bad [friction]
    return study


def _one_table(path: str | os.PathLike, table: str, what: str) -> tuple[dict[str, Any], str]:
    document, source = _read_toml(path, what)
    where = os.fspath(source)
    if table not in document:
        raise StudyError(f"{where}: no [{table}] table; tables found: "
                         f"{', '.join(f'[{name}]' for name in document) or 'none'}; allowed: a TOML file with a "
                         f"[{table}] table as in a study file")
    _check_table(table, document[table], where)
    return document[table], where


def load_parameters_file(path: str | os.PathLike,
                         overrides: dict[str, float] | None = None) -> tuple[Parameters, dict[str, str]]:
    """The parameters of the ``[parameters]`` table of a TOML file (a study file's, or one of its own), with
    ``overrides`` on top, and the provenance attributes; other tables in the file are ignored."""
    table, where = _one_table(path, "parameters", "parameters file")
    return _parameters(table, where, overrides)


def load_path_file(path: str | os.PathLike, params: Parameters) -> Path:
    """The path of the ``[path]`` table of a TOML file (``waypoints`` (x, d) in m, ``speed`` in m/s, default
    ``params.v``), as in a study file; other tables in the file are ignored."""
    table, where = _one_table(path, "path", "path file")
    try:
        return Path(table["waypoints"], table.get("speed", params.v))
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [path] {error}") from None


class StudyOutcomes(list):
    """The files a study wrote (a list of :class:`~mdr_events.app.result_files.FileOutcome`), and
    ``verdicts``: each ``[validate]`` run (as written in the study) -> ``"pass"`` or ``"fail"``, and
    ``"fit <data>"`` -> ``"pass"`` (every free parameter determined) or ``"fail"``."""

    def __init__(self, outcomes: Iterable[FileOutcome] = (), verdicts: dict[str, str] | None = None) -> None:
        super().__init__(outcomes)
        self.verdicts: dict[str, str] = dict(verdicts or {})


def _study_path(study: Study) -> Path | None:
    """The study's ``[path]`` as a :class:`Path` (speed default: the parameters' ``v``), or ``None``."""
    if "path" not in study.tables:
        return None
    table = study.tables["path"]
    try:
        return Path(table["waypoints"], table.get("speed", study.params.v))
    except (ValueError, TypeError) as error:
        raise StudyError(f"{os.fspath(study.source)}: [path] {error}") from None


def _validations(study: Study, progress: Callable[[str], None]) -> list[tuple[str, RenderedReport]]:
    """Validate every run of the ``[validate]`` table and render its files (nothing written yet)."""
    from mdr_events.app.validation_files import render_validation

    table = study.tables.get("validate")
    if table is None:
        return []
    where = os.fspath(study.source)
    case = _measured_case(study.tables, where, "validate")
    try:
        if case is None:
            path, description = _study_path(study), "the study's [path]"
        else:
            path, description = scenario_paths(study.params, case[0], [case[1]], study.profile)[0][0], \
                f"scenario {case[0]}, α = {case[1]:g}°"
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [validate] {error}") from None
    options = {key: table[key] for key in ("tolerance", "names", "units", "time_origin") if key in table}
    stems: dict[str, str] = {}
    files = []
    for run in table["runs"]:  # every run's file names are checked before the first run is validated
        file = FilePath(run) if FilePath(run).is_absolute() else study.source.parent / run
        stem = f"{study.name}_validation_{file.stem}"
        if stem in stems:
            raise StudyError(f"{where}: [validate] runs {stems[stem]!r} and {run!r} would both be written as "
                             f"{stem}.*; allowed: runs with different file names")
        try:
            check_output_stem("stem", stem)
        except ValueError as error:
            raise StudyError(f"{where}: [validate] run {run!r} would be written as {stem}.*: {error}") from None
        stems[stem] = run
        files.append((run, file, stem))
    reports = []
    for run, file, stem in files:
        try:
            report = validate(file, study.params, path, limits=study.limits, profile=study.profile,
                              friction=study.friction, **options)
        except (ValueError, TypeError) as error:
            raise StudyError(f"{where}: [validate] {error}") from None
        report.attrs.update(study.provenance, path_description=description)
        reports.append((run, stem, report))
    for run, _, _ in reports:  # said once every run was read: a bad one prints its one line, no progress before it
        progress(f"validate: {run}")
    return [(run, render_validation(report, stem)) for run, stem, report in reports]


def _fit_report(study: Study, progress: Callable[[str], None]) -> tuple[str, RenderedReport] | None:
    """Fit the ``[fit]`` table's measurement and render its files (nothing written yet)."""
    from mdr_events.app.fit_files import render_fit

    table = study.tables.get("fit")
    if table is None:
        return None
    where = os.fspath(study.source)
    case = _measured_case(study.tables, where, "fit")
    data = FilePath(table["data"]) if FilePath(table["data"]).is_absolute() else study.source.parent / table["data"]
    stem = f"{study.name}_fit_{data.stem}"
    try:
        check_output_stem("stem", stem)
        motion = (_study_path(study), None) if case is None else case
        description = "the study's [path]" if case is None else f"scenario {case[0]}, α = {case[1]:g}°"
        options = {key: table[key] for key in ("names", "units", "time_origin", "noise") if key in table}
        bounds = {name: tuple(pair) for name, pair in table.get("bounds", {}).items()}
        result = fit(data, *motion, free=table["free"], start=study.params, bounds=bounds, limits=study.limits,
                     profile=study.profile, friction=study.friction, **options)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [fit] {error}") from None
    progress(f"fit: {table['data']} (free: {', '.join(table['free'])})")  # once it ran: no line before an error
    result.dataset.attrs.update(study.provenance, path_description=description)
    return f"fit {table['data']}", render_fit(result.dataset, stem)


def sweep_store(study: Study) -> FilePath:
    """Where the study's ``[sweep]`` store goes: ``<output directory>/<name>_sweep.zarr``."""
    return study.output_directory / f"{study.name}_sweep.zarr"


def run_sweep(study: Study, progress: Callable[[str], None] = print, scheduler: str | None = None,
              workers: int | None = None, resume: bool = False) -> list[FileOutcome]:
    """Run the study's ``[sweep]`` table and write ``<name>_sweep.zarr`` (the store, chunk by chunk; with
    ``resume`` an interrupted one is continued) and ``<name>_sweep.nc`` (the labelled result).

    ``scheduler`` and ``workers`` override the table's (``mdr-events sweep --scheduler/--workers``).
    """
    from mdr_events.app.result_files import FileOutcome, FileStatus
    from mdr_events.io.files import write_netcdf

    table = study.tables.get("sweep")
    where = os.fspath(study.source)
    if table is None:
        raise StudyError(f"{where}: no [sweep] table; tables found: {', '.join(f'[{t}]' for t in study.tables)}")
    out = prepare_output_directory(study.output_directory, "[output] directory")
    grid = table.get("grid") or table["sets"]
    if isinstance(grid, dict):
        grid = {name: value if isinstance(value, list) else [value] for name, value in grid.items()}
    scenario = _study_path(study) if "path" in study.tables else table.get("scenario", "A")
    options = {key: table[key] for key in ("method", "dx", "n_steps", "chunk_size", "history_samples") if key in table}
    if "quantities" in table:
        options["quantities"] = tuple(table["quantities"])
    store = sweep_store(study)

    def report(done: int, total: int) -> None:
        progress(f"sweep: {done}/{total} runs")

    try:
        result = sweep(grid, scenario, table.get("alpha"), base=study.params, store=store, resume=resume,
                       limits=study.limits, profile=study.profile, friction=study.friction,
                       scheduler=scheduler or table.get("scheduler"),
                       workers=workers or table.get("workers"), progress=report, **options)
    except (ValueError, TypeError) as error:
        raise StudyError(f"{where}: [sweep] {error}") from None
    result.attrs.update(study.provenance)
    progress(f"sweep: {result.attrs['runs']} runs, {result.attrs['failed_runs']} failed")
    return [FileOutcome(store, FileStatus.WRITTEN),
            FileOutcome(write_netcdf(result, out / f"{study.name}_sweep.nc"), FileStatus.WRITTEN)]


def run_study(study: Study, progress: Callable[[str], None] = print) -> StudyOutcomes:
    """Compute what the study asks for and write it (netCDF + PNG, event log CSV; the ``[validate]`` runs'
    reports as .nc, .md and .png); returns the files and the runs' verdicts (:class:`StudyOutcomes`).

    The output directory (``[output] directory``: a directory that exists or can be created, writable) and
    the files' stem are checked before anything is computed, and the ``[validate]`` runs are validated before
    anything is written: a run that cannot be read writes nothing.

    Raises
    ------
    TypeError
        If ``study`` is not a :class:`Study` (see :func:`load_study`).
    StudyError
        Naming the study file, the table and the key of what cannot be run.
    """
    # here, not at the top: result_files loads matplotlib.pyplot, which `import mdr_events` should not pay for
    from mdr_events.app.result_files import write_phase_diagram, write_simulation
    from mdr_events.app.validation_files import write_rendered

    if not isinstance(study, Study):
        raise TypeError(f"study={shown(study)} ({type(study).__name__}) is not allowed; allowed: a Study "
                        "(mdr_events.load_study)")
    where = os.fspath(study.source)
    try:
        out = prepare_output_directory(study.output_directory, "[output] directory")
        check_output_stem("[output] name" if "name" in study.tables["output"] else
                          "[output] name (by default the study file's stem)", study.name)
    except ValueError as error:
        raise StudyError(f"{where}: {error}") from None
    written = StudyOutcomes()
    scenarios = study.tables.get("phase_diagram", {}).get("scenarios", [])
    for scenario in scenarios:
        if scenario not in ("A", "B"):
            raise StudyError(f"{where}: [phase_diagram] scenarios contains {scenario!r}; allowed: 'A', 'B'")
    if len(set(scenarios)) != len(scenarios):  # (each would be computed and written again)
        raise StudyError(f"{where}: [phase_diagram] scenarios={scenarios!r} repeats a scenario; allowed: each once")
    validations = _validations(study, progress)
    fitted = _fit_report(study, progress)
    simulation = study.tables.get("simulation")
    if simulation is not None:
        settings = dict(simulation)
        method = settings.pop("method", "discrete")
        scenario: Any = settings.pop("scenario", None)
        if "path" in study.tables:
            scenario = _study_path(study)
        tolerance_names = sorted({"rtol", "atol"} & set(settings))
        alpha = settings.pop("alpha", None)
        try:
            if tolerance_names and method != "continuum":
                raise ValueError(f"{', '.join(tolerance_names)} is not allowed with method={method!r}; "
                                 "allowed: with method = 'continuum'")
            if tolerance_names:
                settings["tolerances"] = Tolerances(**{name: float(settings.pop(name)) for name in tolerance_names})
            dataset = simulate(study.params, scenario, alpha=alpha, method=method, limits=study.limits,
                               profile=study.profile, friction=study.friction, **settings)
        except (ValueError, TypeError) as error:
            raise StudyError(f"{where}: [simulation] {error}") from None
        # (said once it ran: a value found wrong prints its one line, not a progress line before it)
        progress(f"simulation: scenario {scenario if isinstance(scenario, str) else 'custom path'}, method {method}")
        dataset.attrs.update(study.provenance)
        written += write_simulation(dataset, out, f"{study.name}_simulation")
    for scenario in study.tables.get("phase_diagram", {}).get("scenarios", []):
        progress(f"phase diagram: scenario {scenario}")
        written += write_phase_diagram(study.params, scenario, out, f"{study.name}_phase_diagram_{scenario}",
                                       attrs=study.provenance, profile=study.profile, friction=study.friction)
    for run, rendered in validations:
        written += write_rendered(rendered, out)
        written.verdicts[run] = str(rendered.report.attrs["verdict"])
        progress(f"validate: {run}: {written.verdicts[run]}")
    if "sweep" in study.tables:
        written += run_sweep(study, progress)
    if fitted is not None:
        label, rendered = fitted
        written += write_rendered(rendered, out)
        written.verdicts[label] = "pass" if rendered.report.attrs["identifiable"] else "fail"
        progress(f"{label}: {rendered.report.attrs['verdict']}")
    return written

