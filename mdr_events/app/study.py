"""Study files: a whole computation described in TOML, run by ``mdr-events run study.toml``.

A study names its parameters, what to compute and where to write it::

    [parameters]                 # a preset of the paper, then overrides (SI units) ...
    preset = "paper-R30"         # or "paper-R100"
    tau0 = 30e3
                                 # ... or, without preset, all eight: E, nu, R, tau0,
                                 # dgamma0, dgamma1, d_max, v (an error names the missing ones)

    [simulation]                 # optional (a study needs a simulation, a phase diagram or both)
    scenario = "A"               # "A", "B" or "B+"; or give a [path] table instead
    alpha = [10, 20, 30]         # degrees
    method = "continuum"         # or "discrete"
    samples = 2001               # continuum: output times (or dx, dt / n_steps for discrete)

    [path]                       # optional, instead of simulation.scenario: any (x, d) waypoints,
    waypoints = [[0, 0], [0, 3e-4], [2e-4, -1e-4]]   # simulated as the one case "path 1" along `case`
    speed = 1e-6

    [phase_diagram]              # optional: Fig. 9a / 9b
    scenarios = ["A", "B"]

    [output]                     # required
    directory = "out"            # relative to the study file
    name = "my_study"            # file stem (default: the study file's stem)

The file is read with :mod:`tomllib`. Unknown tables or keys, values of the
wrong type and missing required keys are errors that name the table, the
key, the value and what is allowed; the values themselves are then checked
by the functions they go to (:class:`Parameters`, :func:`simulate`, ...).

Without a ``[parameters]`` table the study uses the preset ``paper-R30``. With a preset, every
result says which values came from it (attributes ``parameters_preset`` and
``parameters_from_preset``).
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path as FilePath
from typing import TYPE_CHECKING, Any, Callable

from mdr_events.models.continuum import Tolerances
from mdr_events.models.paths import Path
from mdr_events.models.simulate import simulate
from mdr_events.parameters import PARAMETER_UNITS, PRESETS, Parameters, from_preset

if TYPE_CHECKING:
    from mdr_events.app.result_files import FileOutcome

__all__ = ["Study", "load_study", "run_study", "StudyError"]


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
}

#: Table -> key -> (kind, required).
SCHEMA: dict[str, dict[str, tuple[str, bool]]] = {
    "parameters": {"preset": ("string", False), **{name: ("number", False) for name in PARAMETER_UNITS}},
    "simulation": {"scenario": ("string", False), "alpha": ("numbers", False), "method": ("string", False),
                   "dx": ("number", False), "dt": ("number", False), "n_steps": ("integer", False),
                   "samples": ("integer", False), "rtol": ("number", False), "atol": ("number", False)},
    "path": {"waypoints": ("points", True), "speed": ("number", False)},
    "phase_diagram": {"scenarios": ("strings", True)},
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


def _check_tables(document: dict[str, Any], where: str) -> None:
    for table, content in document.items():
        if table not in SCHEMA:
            raise StudyError(f"{where}: unknown table [{table}]; allowed: "
                             + ", ".join(f"[{name}]" for name in SCHEMA))
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
    for table in REQUIRED_TABLES:
        if table not in document:
            raise StudyError(f"{where}: the required table [{table}] is missing")
    if "simulation" not in document and "phase_diagram" not in document:
        raise StudyError(f"{where}: nothing to compute; give a [simulation] table, a [phase_diagram] table or both")
    if "path" in document and "simulation" not in document:
        raise StudyError(f"{where}: a [path] needs a [simulation] table (method, dx, ...)")
    simulation = document.get("simulation", {})
    if "path" in document and ("scenario" in simulation or "alpha" in simulation):
        raise StudyError(f"{where}: [simulation] scenario and alpha are not allowed with a [path] "
                         "(its waypoints fix the motion)")
    if "simulation" in document and "path" not in document and "scenario" not in simulation:
        raise StudyError(f"{where}: [simulation] lacks the required key scenario (or give a [path] table)")


def load_study(path: str | os.PathLike) -> Study:
    """Read and check a study file; raises :class:`StudyError` (a ``ValueError``) naming what is wrong."""
    source = FilePath(path)
    where = os.fspath(source)
    try:
        with open(source, "rb") as handle:
            document = tomllib.load(handle)
    except FileNotFoundError:
        raise StudyError(f"{where}: no such study file") from None
    except tomllib.TOMLDecodeError as error:
        raise StudyError(f"{where}: not valid TOML ({error})") from None
    _check_tables(document, where)
    settings = {key: value for key, value in document.get("parameters", {}).items() if key != "preset"}
    preset = document.get("parameters", {}).get("preset")
    if preset is None and "parameters" in document:
        missing = [name for name in PARAMETER_UNITS if name not in settings]
        if missing:
            raise StudyError(f"{where}: [parameters] without a preset lacks {', '.join(missing)}; allowed: all "
                             f"eight of {', '.join(PARAMETER_UNITS)}, or preset = "
                             + " or ".join(map(repr, PRESETS)) + " and any of them as overrides")
    values = {key: float(value) for key, value in settings.items()}
    try:
        if preset is None and "parameters" in document:
            params, provenance = Parameters(**values), {}
        else:
            params, provenance = from_preset("paper-R30" if preset is None else preset, **values)
    except ValueError as error:
        raise StudyError(f"{where}: [parameters] {error}") from None
    return Study(source, params, {table: dict(content) for table, content in document.items()}, provenance)


def run_study(study: Study, progress: Callable[[str], None] = print) -> list[FileOutcome]:
    """Compute what the study asks for and write it (netCDF + PNG, event log CSV); returns the files."""
    # here, not at the top: result_files loads matplotlib.pyplot, which `import mdr_events` should not pay for
    from mdr_events.app.result_files import write_phase_diagram, write_simulation

    out = study.output_directory
    written: list[FileOutcome] = []
    where = os.fspath(study.source)
    for scenario in study.tables.get("phase_diagram", {}).get("scenarios", []):
        if scenario not in ("A", "B"):
            raise StudyError(f"{where}: [phase_diagram] scenarios contains {scenario!r}; allowed: 'A', 'B'")
    simulation = study.tables.get("simulation")
    if simulation is not None:
        settings = dict(simulation)
        method = settings.pop("method", "discrete")
        scenario: Any = settings.pop("scenario", None)
        if "path" in study.tables:
            path_table = study.tables["path"]
            scenario = Path(path_table["waypoints"], path_table.get("speed", study.params.v))
        tolerance_names = sorted({"rtol", "atol"} & set(settings))
        alpha = settings.pop("alpha", None)
        progress(f"simulation: scenario {scenario if isinstance(scenario, str) else 'custom path'}, method {method}")
        try:
            if tolerance_names and method != "continuum":
                raise ValueError(f"{', '.join(tolerance_names)} is not allowed with method={method!r}; "
                                 "allowed: with method = 'continuum'")
            if tolerance_names:
                settings["tolerances"] = Tolerances(**{name: float(settings.pop(name)) for name in tolerance_names})
            dataset = simulate(study.params, scenario, alpha=alpha, method=method, **settings)
        except (ValueError, TypeError) as error:
            raise StudyError(f"{where}: [simulation] {error}") from None
        dataset.attrs.update(study.provenance)
        written += write_simulation(dataset, out, f"{study.name}_simulation")
    for scenario in study.tables.get("phase_diagram", {}).get("scenarios", []):
        progress(f"phase diagram: scenario {scenario}")
        written += write_phase_diagram(study.params, scenario, out, f"{study.name}_phase_diagram_{scenario}",
                                       attrs=study.provenance)
    return written

