"""The study file's format: its tables and keys (:data:`SCHEMA`), how each is checked, and how the file is read.

A study (:mod:`mdr_events.app.study`) is read in two steps: this module checks the TOML document against the
schema (unknown tables or keys, values of the wrong kind, missing required keys, tables that need each other: each
named with the file, the table and the key); the study then builds its typed jobs from the checked tables through
the shared parsers (:mod:`mdr_events.app.inputs`).
"""

from __future__ import annotations

import os
import sys
import tomllib
from pathlib import Path as FilePath
from typing import Any, Callable

from mdr_events.io.files import check_file_path, check_output_stem
from mdr_events.limits import LIMIT_UNITS, in_study
from mdr_events.parameters import PARAMETER_UNITS
from mdr_events.validation import shown, shown_path, shown_text

__all__ = ["StudyError", "SCHEMA", "REQUIRED_TABLES", "MAX_TOML_BYTES", "check_table", "check_tables", "check_computation",
           "measured_case", "read_toml", "one_table"]


class StudyError(ValueError):
    """A study file that cannot be run; the message names the file, table and key (a limit's advice its ``[limits]``
    table: :func:`mdr_events.limits.in_study`)."""

    def __init__(self, message: str) -> None:
        super().__init__(in_study(message))


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
    "string or strings": (lambda v: isinstance(v, str) or (isinstance(v, list) and len(v) > 0
                                                           and all(isinstance(s, str) for s in v)),
                          "a string or a non-empty list of strings"),
    "boolean": (lambda v: isinstance(v, bool), "true or false"),
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
    "phase_diagram": {"scenarios": ("strings", True), "speeds": ("numbers", False)},
    "validate": {"runs": ("strings", True), "tolerance": ("number", False), "names": ("string table", False),
                 "units": ("string table", False), "time_origin": ("string or number", False),
                 "scenario": ("string", False), "alpha": ("numbers", False)},
    "fit": {"data": ("string or strings", True), "free": ("strings", True), "speeds": ("numbers", False),
            "offsets": ("boolean", False), "names": ("string table", False),
            "units": ("string table", False), "time_origin": ("string or number", False),
            "noise": ("number table", False), "bounds": ("bounds table", False), "scenario": ("string", False),
            "alpha": ("numbers", False)},
    "sweep": {"grid": ("grid table", False), "sets": ("tables", False), "scenario": ("string", False),
              "alpha": ("number", False), "method": ("string", False), "dx": ("number", False),
              "n_steps": ("integer", False), "quantities": ("strings", False), "chunk_size": ("integer", False),
              "scheduler": ("string", False), "workers": ("integer", False), "history_samples": ("integer", False)},
    "lammps_check": {"normal": ("string", True), "tangential": ("string", False), "mu": ("number", False),
                     "steps": ("integer", False), "dt": ("number", False), "tolerance": ("number", False),
                     "scenario": ("string", False), "alpha": ("numbers", False)},
    "limits": {name: ("string or number", False) for name in LIMIT_UNITS},
    "profile": {"c": ("number", False), "n": ("number", False), "radius": ("number", False),
                "table": ("string", False)},
    "friction": {"law": ("string", True), "mu": ("number", False)},
    "layer": {"h": ("number", True), "base": ("string", False)},
    "adhesion": {"law": ("string", True), "v_ref": ("number", False), "n": ("number", False)},
    "output": {"directory": ("string", True), "name": ("string", False)},
}
REQUIRED_TABLES = ("output",)
#: What the keys of the tables that choose among kinds mean (the reference page shows them beside the kinds):
#: ``[profile]`` takes one of three indenters (``c`` and ``n``, ``radius`` or ``table``; without it the paraboloid
#: of ``[parameters] R``), ``[friction]`` one of the laws of :data:`~mdr_events.contact.friction.FRICTION_LAWS`, ``[layer]``
#: the elastomer as a layer on a rigid base.
KEY_NOTES: dict[tuple[str, str], str] = {
    ("profile", "c"): "with n: the power law f = c r^n (c in m^(1-n))",
    ("profile", "n"): "with c: the power law's exponent, >= 1 (1: the cone, 2: a paraboloid)",
    ("profile", "radius"): "alone: the flat punch of this radius (m)",
    ("profile", "table"): "alone: a tabulated profile f(r), a CSV file with the columns r and f (m), relative to "
                          "the study file",
    ("friction", "law"): "'tau0' (the paper's cap (13), tau0 of [parameters]), 'coulomb' (needs mu; tau0 unused) "
                         "or 'tau0+coulomb' (both)",
    ("friction", "mu"): "the coefficient of friction, >= 0: required by 'coulomb' and 'tau0+coulomb', not allowed "
                        "with 'tau0'",
    ("layer", "h"): "the elastomer's thickness in m: a layer on a rigid base (inf: the half-space, as without the "
                    "table); run by both methods, [validate] and [fit] (a continuum [sweep] with the friction law "
                    "'tau0'), "
                    "as --h",
    ("adhesion", "law"): "'paper' (Hess's rule with dgamma0 in and dgamma1 out of [parameters], rate independent: "
                         "the default) or 'rate' (needs v_ref and n; the works at rest dgamma0 > 0, dgamma1 >= "
                         "dgamma0 of [parameters]), as --adhesion-law",
    ("adhesion", "v_ref"): "the rate law's reference speed of the contact's edge in m/s, > 0, as --v-ref",
    ("adhesion", "n"): "the rate law's exponent of the edge's speed, 0 < n <= 1, as --rate-exponent",
    ("layer", "base"): "'bonded' (the default) or 'frictionless' (paths without tangential motion only), as "
                       "--layer-base",
}


def check_table(table: str, content: Any, where: str) -> None:
    """Raise :class:`StudyError` unless ``content`` is a table ``[table]`` of known keys of the right kinds."""
    if not isinstance(content, dict):
        raise StudyError(f"{where}: {table} = {shown(content)} is not allowed; allowed: a table [{table}]")
    keys = SCHEMA[table]
    for key, value in content.items():
        if key not in keys:
            raise StudyError(f"{where}: unknown key {shown(key)} in [{table}]; allowed: {', '.join(keys)}")
        check, allowed = _KINDS[keys[key][0]]
        if not check(value):
            raise StudyError(f"{where}: [{table}] {key} = {shown(value)} is not allowed; allowed: {allowed}")
    missing = [key for key, (_, required) in keys.items() if required and key not in content]
    if missing:
        needed = "; ".join(f"{key}: {KEY_NOTES.get((table, key), _KINDS[keys[key][0]][1])}" for key in missing)
        raise StudyError(f"{where}: [{table}] lacks the required key(s) {', '.join(missing)}; allowed: [{table}] "
                         f"with {needed}")


def check_tables(document: dict[str, Any], where: str) -> None:
    """Raise :class:`StudyError` unless every table is known and of known keys of the right kinds, the required
    tables are there and ``[output] name`` is a plain stem (what the tables together give: :func:`check_computation`)."""
    for table, content in document.items():
        if table not in SCHEMA:
            raise StudyError(f"{where}: unknown table [{shown_text(table)}]; allowed: "
                             + ", ".join(f"[{name}]" for name in SCHEMA))
        check_table(table, content, where)
    for table in REQUIRED_TABLES:
        if table not in document:
            raise StudyError(f"{where}: the required table [{table}] is missing; allowed: a study with an [{table}] "
                             f"table ({', '.join(key for key, (_, required) in SCHEMA[table].items() if required)} "
                             "required)")
    if "name" in document["output"]:
        try:
            check_output_stem("[output] name", document["output"]["name"])
        except ValueError as error:
            raise StudyError(f"{where}: {error}") from None


def check_computation(document: dict[str, Any], where: str) -> None:
    """Raise :class:`StudyError` unless the tables together give something to compute, each what it needs: checked
    after the values every table shares (the parameters, profile, friction, limits and path), so that a bad value is
    named first."""
    if not {"simulation", "phase_diagram", "validate", "fit", "sweep", "lammps_check"} & set(document):
        raise StudyError(f"{where}: nothing to compute; give a [simulation] table, a [phase_diagram] table, "
                         "a [validate] table, a [fit] table, a [sweep] table, a [lammps_check] table or several")
    if "path" in document and not {"simulation", "validate", "fit", "sweep", "lammps_check"} & set(document):
        raise StudyError(f"{where}: a [path] needs a [simulation] table (method, dx, ...), a [validate] table, a "
                         "[fit] table or a [sweep] table")
    if "sweep" in document and ("grid" in document["sweep"]) == ("sets" in document["sweep"]):
        given = "both" if "grid" in document["sweep"] else "neither"
        raise StudyError(f"{where}: [sweep] needs one of grid (names to values: the outer product) and sets "
                         f"(a list of parameter sets), {given} given; allowed: exactly one of them")
    simulation = document.get("simulation", {})
    if "path" in document and ("scenario" in simulation or "alpha" in simulation):
        raise StudyError(f"{where}: [simulation] scenario and alpha are not allowed with a [path] "
                         "(its waypoints fix the motion)")
    if "simulation" in document and "path" not in document and "scenario" not in simulation:
        raise StudyError(f"{where}: [simulation] lacks the required key scenario (or give a [path] table)")
    for table in ("validate", "fit", "lammps_check"):
        if table in document:
            measured_case(document, where, table)


def measured_case(document: dict[str, Any], where: str, name: str) -> tuple[str, float] | None:
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
#: The nesting of arrays and inline tables that is always read (Python's reader recurses once or twice per level).
MAX_TOML_NESTING = 100


def read_toml(path: Any, what: str) -> tuple[dict[str, Any], FilePath]:
    """The TOML document of the file at ``path`` (a ``what``, e.g. "study file") and the file's path.

    Raises ``TypeError`` if ``path`` is not a ``str`` or ``os.PathLike``, and :class:`StudyError` naming the
    file if it is missing, a directory, unreadable, not UTF-8 text or not valid TOML.
    """
    source = check_file_path("path", path, f"a str or os.PathLike naming a {what} (.toml)")
    where = shown_path(source)
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
    except StudyError:  # (the size's, raised above: not the integer's below)
        raise
    except ValueError:  # (int() of an integer of more digits than Python converts: its own message, no file named)
        raise StudyError(f"{where}: an integer of more than {sys.get_int_max_str_digits()} digits cannot be read; "
                         f"{allowed}, integers of fewer digits (a large number written with an exponent, e.g. "
                         "1e300)") from None
    except RecursionError:  # (the reader descends one call per level of arrays or inline tables)
        raise StudyError(f"{where}: its arrays or inline tables nest too deeply to be read; {allowed}, nested at most "
                         f"{MAX_TOML_NESTING} levels deep") from None
    except OSError as error:
        raise StudyError(f"{where} cannot be read ({error.strerror or error}); {allowed}") from None


def one_table(path: str | os.PathLike, table: str, what: str) -> tuple[dict[str, Any], str]:
    document, source = read_toml(path, what)
    where = shown_path(source)
    if table not in document:
        raise StudyError(f"{where}: no [{table}] table; tables found: "
                         f"{', '.join(f'[{name}]' for name in document) or 'none'}; allowed: a TOML file with a "
                         f"[{table}] table as in a study file")
    check_table(table, document[table], where)
    return document[table], where
