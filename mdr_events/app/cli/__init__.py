"""Command line: ``mdr-events derive | phase-diagram | simulate | validate | fit | sweep | run | reproduce``.

Every error prints one line ``mdr-events: error: ...`` on stderr (no traceback; ``mdr-events --debug ...``
re-raises it with its traceback). The exit status (:data:`EXIT_STATUSES`):

- 0: done;
- 1: ``mdr-events validate`` (or ``run`` with a ``[validate]`` table): a run is outside its tolerance;
  ``mdr-events fit`` (or ``run`` with a ``[fit]`` table): a free parameter is not determined by the data;
- 2: bad input: an argument, a value, a study file or a file that cannot be read or written (``ValueError``,
  ``TypeError``, ``KeyError``, ``OSError``), named with its value and what is allowed. Output directories
  are checked before anything is computed (:func:`~mdr_events.io.files.prepare_output_directory`);
- 3: the computation failed although the input was accepted: the solver gave up (``RuntimeError``), memory
  or another resource ran out (``MemoryError``), or an internal error (any other exception): please report it;
- 130 / 143: interrupted by Ctrl-C (SIGINT) / terminated (SIGTERM). Both remove the temporary file being
  written (:func:`~mdr_events.io.files.atomic_write`): no file is left half-written.
"""

from __future__ import annotations

import argparse
import importlib
import math
import os
import re
import signal
import sys
import threading
from pathlib import Path
from typing import Sequence

import matplotlib

from mdr_events.limits import DEFAULT_LIMITS, LIMIT_UNITS, Limits, parse_limit
from mdr_events._version import __version__
from mdr_events.app.report import reproduce
from mdr_events.app.result_files import write_phase_diagram, write_simulation
from mdr_events.analysis.fit import FREE_NAMES, fit
from mdr_events.analysis.validate import TIME_ORIGINS, validate
from mdr_events.app.study import load_parameters_file, load_path_file, load_study, run_study, run_sweep, sweep_store
from mdr_events.io.candidates import CANDIDATE_QUANTITIES, unit_factor
from mdr_events.io.files import check_output_stem, prepare_output_directory
from mdr_events.models.methods import DEFAULT_DX, DEFAULT_STEPS, METHODS
from mdr_events.models.motion import SCENARIO_NAMES, scenario_paths
from mdr_events.models.simulate import simulate
from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, PRESETS, Parameters, from_preset
from mdr_events.validation import SCALE_MAX, SCALE_MIN
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.io.candidates import read_profile_table
from mdr_events.contact.friction import FRICTION_LAWS, FrictionLaw
from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile as _check_simulated
from mdr_events.theory import symbolic

#: The first line of ``mdr-events --help`` (plain text: argparse prints it as it is).
DESCRIPTION = ("Adhesive indentation and detachment at an angle with the Method of Dimensionality Reduction "
               "(Lyashenko, Popov & Borysiuk 2023, section 4).")


#: Exit status -> when.
EXIT_STATUSES = {
    0: "done",
    1: "validate: a run is outside its tolerance; fit: a free parameter is not determined or the fit does not "
       "describe the data",
    2: "bad input (an argument, a value, a study file, a file that cannot be read or written)",
    3: "the computation failed although the input was accepted (solver, memory, internal error)",
    130: "interrupted (Ctrl-C)",
    141: "the reader of the output went away (a closed pipe: `mdr-events derive | head`), silently",
    143: "terminated (SIGTERM)",
}
#: The exit status when the output's reader has gone: as a process ended by SIGPIPE (128 + 13).
EXIT_BROKEN_PIPE = 141
#: The exit status of bad input and of a failed computation.
EXIT_BAD_INPUT, EXIT_FAILED = 2, 3
#: Errors that are bad input (exit 2); RuntimeError and MemoryError are a failed computation (exit 3).
INPUT_ERRORS = (ValueError, TypeError, KeyError, OSError)
COMPUTATION_ERRORS = (RuntimeError, MemoryError)


class UsageError(Exception):
    """A user error: reported in one line, exit status 2."""


class _Terminated(BaseException):
    """SIGTERM arrived: raised in the main thread, so that every ``finally`` (temporary files) runs."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, no usage block
        raise UsageError(message)

    def parse_args(self, args=None, namespace=None):  # unknown options named with where to find the allowed
        parsed, extras = self.parse_known_args(args, namespace)
        if extras:
            command = getattr(parsed, "command", None)
            where = f"{self.prog} {command}" if command else self.prog
            raise UsageError(f"unrecognized argument(s) {' '.join(extras)}; allowed: the options listed by "
                             f"{where} --help")
        return parsed


def _parameter_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--preset", choices=sorted(PRESETS), default="paper-R30",
                        help="parameter set of the paper (default paper-R30); the options below override it")
    for name, long_name in PARAMETER_LONG_NAMES.items():
        parser.add_argument(f"--{name}", type=float, default=None, metavar="VALUE",
                            help=f"{long_name} [{PARAMETER_UNITS[name]}]")


def _parameters(args: argparse.Namespace) -> tuple[Parameters, dict[str, str]]:
    """The parameters of ``--preset`` with the options given, and attributes saying which came from the preset."""
    changes = {name: getattr(args, name) for name in PARAMETER_UNITS if getattr(args, name) is not None}
    return from_preset(args.preset, **changes)


def _progress(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


def _command_derive(args: argparse.Namespace) -> None:
    rels = symbolic.relations()
    keys = list(rels) if args.key is None else [args.key]
    for key in keys:
        rel = symbolic.relation(key)
        number = f" {rel.equation}" if rel.equation else ""
        print(f"# {rel.key}{number}: {rel.title}")
        print(rel.latex() if args.latex else rel.pretty())
        print()


def _command_phase_diagram(args: argparse.Namespace) -> None:
    params, provenance = _parameters(args)
    profile = _profile(args, simulated=False)
    friction = _friction(args)
    out = prepare_output_directory(args.out, "--out")
    stem = f"phase_diagram_{args.scenario}"
    for outcome in write_phase_diagram(params, args.scenario, out, stem, attrs=provenance, profile=profile,
                                       friction=friction):
        print(outcome.path)


def _profile_option(parser: argparse.ArgumentParser) -> None:
    indenter = parser.add_mutually_exclusive_group()
    indenter.add_argument("--power-law", type=float, nargs=2, default=None, metavar=("C", "N"),
                          help="the indenter f = c r^n (c in m^(1-n), n >= 1: 1 a cone) instead of the paraboloid of R")
    indenter.add_argument("--flat-punch", type=float, default=None, metavar="RADIUS",
                          help="the flat punch of this radius (m) instead of the paraboloid of R")
    indenter.add_argument("--table", default=None, metavar="FILE",
                          help="a tabulated indenter: a CSV file with the columns r and f (m) instead of the paraboloid")


def _profile(args: argparse.Namespace, simulated: bool = True) -> SimulatedProfile:
    """The ``--power-law C N``, ``--flat-punch RADIUS`` or ``--table FILE`` indenter (``None``: the paraboloid of the
    parameters' ``R``); ``simulated``: one the simulators take (a power law from the cone on), else any the closed
    forms take (the phase diagram's)."""
    check_simulated_profile = _check_simulated if simulated else (lambda profile: profile)
    if getattr(args, "table", None) is not None:
        try:
            return check_simulated_profile(read_profile_table(args.table))
        except (TypeError, ValueError) as error:
            raise UsageError(f"--table {args.table}: {error}") from None
    if getattr(args, "flat_punch", None) is not None:
        try:
            return check_simulated_profile(FlatPunch(args.flat_punch))
        except (TypeError, ValueError) as error:
            raise UsageError(f"--flat-punch {args.flat_punch:g}: {error}") from None
    if getattr(args, "power_law", None) is None:
        return None
    try:
        return check_simulated_profile(PowerLaw(*args.power_law))
    except (TypeError, ValueError) as error:
        raise UsageError(f"--power-law {' '.join(f'{value:g}' for value in args.power_law)}: {error}") from None


def _friction_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--friction", choices=list(FRICTION_LAWS), default=None,
                        help="the cap on the springs' shifts: tau0 (the paper's, default), coulomb (mu times the "
                             "spring's normal force) or tau0+coulomb (their sum)")
    parser.add_argument("--mu", type=float, default=None, help="the coefficient of friction of --friction coulomb "
                        "or tau0+coulomb")


def _friction(args: argparse.Namespace) -> FrictionLaw:
    """The ``--friction LAW [--mu MU]`` law (default the paper's ``tau0``)."""
    try:
        return FrictionLaw(args.friction or "tau0", mu=args.mu)
    except (TypeError, ValueError) as error:
        law = f"--friction {args.friction}" if args.friction else "the default --friction tau0"
        given = law if args.mu is None else (f"--mu {args.mu:g} with {law}" if not args.friction
                                             else f"{law} --mu {args.mu:g}")
        raise UsageError(f"{given}: {error}") from None


def _limit_option(parser: argparse.ArgumentParser) -> None:
    """``--limit NAME=VALUE`` (repeatable): raise a resource limit of :class:`~mdr_events.limits.Limits`."""
    parser.add_argument("--limit", action="append", default=[], metavar="NAME=VALUE",
                        help="raise a resource limit, e.g. --limit steps=1e8 --limit memory=8GiB (names: "
                             + ", ".join(f"{name}: {meaning}" for name, meaning in LIMIT_UNITS.items())
                             + "; inf: none)")


def _limits(args: argparse.Namespace) -> Limits:
    """The limits of ``--limit`` options, on top of the defaults."""
    limits = DEFAULT_LIMITS
    for text in args.limit:
        limits = parse_limit(text, limits)
    return limits


def _command_simulate(args: argparse.Namespace) -> None:
    params, provenance = _parameters(args)
    profile = _profile(args)
    friction = _friction(args)
    out = prepare_output_directory(args.out, "--out")  # before the simulation, which may take minutes
    # the options of the discrete method are passed only when given, so that simulate() rejects them
    # with the continuum method exactly as it does in Python
    options = {name: getattr(args, name) for name in ("dx", "dt", "n_steps") if getattr(args, name) is not None}
    dataset = simulate(params, args.scenario, alpha=args.alpha, method=args.method, limits=_limits(args),
                       profile=profile, friction=friction, **options)
    dataset.attrs.update(provenance)
    stem = f"simulation_{args.scenario.replace('+', 'plus')}_{args.method}"
    for outcome in write_simulation(dataset, out, stem):
        print(outcome.path)


def _command_run(args: argparse.Namespace) -> int:
    outcomes = run_study(load_study(args.study), progress=_progress)
    for outcome in outcomes:
        print(outcome.path)
    failed = [run for run, verdict in getattr(outcomes, "verdicts", {}).items() if verdict != "pass"]
    if failed:
        print(f"{'validation ' if all(not run.startswith('fit ') for run in failed) else ''}failed: {', '.join(failed)}")
    return 1 if failed else 0


#: Where ``mdr-events validate`` finds the convergence study (optional: skipped while the module is missing).
CONVERGENCE_MODULE = "mdr_events.analysis.convergence_study"
#: A spacing in a run's file name: ``dx`` then a number and an optional unit (``run_dx2um.csv``, ``dx=2e-6.csv``).
SPACING_IN_NAME = re.compile(r"(?:^|[^A-Za-z])dx[_=-]?(\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)(nm|um|µm|mm|m)?(?![A-Za-z])")
SPACING_UNITS = {None: 1.0, "m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9}
#: The least number of spacings for a convergence study (an order from a least-squares slope with its spread).
CONVERGENCE_MIN_RUNS = 3
#: The file stem of the convergence study in ``--out``.
CONVERGENCE_STEM = "convergence_study"


def _pairs(option: str, text: str | None, allowed: Sequence[str]) -> dict[str, str]:
    """``time=t,normal_force=Fn`` -> ``{"time": "t", "normal_force": "Fn"}``; a bad item names the option."""
    if text is None:
        return {}
    pairs: dict[str, str] = {}
    for item in text.split(","):
        key, equals, value = (part.strip() for part in item.partition("="))
        if not equals or not key or not value:
            raise UsageError(f"{option} {text!r}: {item.strip()!r} is not allowed; allowed: QUANTITY=VALUE pairs "
                             "separated by commas, e.g. time=t,normal_force=Fn")
        if key not in allowed:
            raise UsageError(f"{option} {text!r}: {key!r} is not allowed; allowed: {', '.join(allowed)}")
        if key in pairs:
            raise UsageError(f"{option} {text!r}: {key!r} is given twice; allowed: each quantity once")
        pairs[key] = value
    return pairs


def _time_origin(text: str) -> str | float:
    if text in TIME_ORIGINS:
        return text
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise UsageError(f"--time-origin {text!r} is not allowed; allowed: {', '.join(TIME_ORIGINS)} or the runs' "
                         "time of first contact in s (a finite number)")
    return value


def _validation_parameters(args: argparse.Namespace):
    changes = {name: getattr(args, name) for name in PARAMETER_UNITS if getattr(args, name) is not None}
    if args.params is not None:
        try:
            return load_parameters_file(args.params, changes)
        except ValueError as error:
            raise UsageError(f"--params {error}") from None
    try:
        return from_preset(args.preset or "paper-R30", **changes)
    except ValueError as error:
        raise UsageError(str(error)) from None


def _validation_path(args: argparse.Namespace, params: Parameters):
    """The path the runs took, and a description of it for the report."""
    if args.path is not None:
        if args.alpha is not None:
            raise UsageError(f"--alpha {args.alpha:g} is not allowed with --path (its waypoints fix the motion)")
        try:
            return load_path_file(args.path, params), f"from the path file {args.path}"
        except ValueError as error:
            raise UsageError(f"--path {error}") from None
    if args.alpha is None:
        raise UsageError(f"--scenario {args.scenario} needs --alpha (one angle in degrees)")
    try:
        paths, _ = scenario_paths(params, args.scenario, [args.alpha], _profile(args))
    except (ValueError, TypeError) as error:
        raise UsageError(f"--alpha {args.alpha:g}: {error}") from None
    return paths[0], f"scenario {args.scenario}, α = {args.alpha:g}°"


def _spacings(args: argparse.Namespace) -> tuple[list[float] | None, str | None]:
    """The spacing of each run for a convergence study: ``--dx`` (one per run), else from every run's file
    name; ``None`` and why not (``None``: nothing to say) where there is no study."""
    if args.dx is not None:
        if len(args.dx) != len(args.runs):
            raise UsageError(f"--dx has {len(args.dx)} values and there are {len(args.runs)} runs; allowed: one "
                             "spacing (m) per run, in the order of the runs")
        bad = [value for value in args.dx if not SCALE_MIN <= value <= SCALE_MAX]
        if bad:
            raise UsageError(f"--dx {bad[0]!r} is not allowed; allowed: spacings (m) from {SCALE_MIN:.2g} to "
                             f"{SCALE_MAX:.2g}")
        if len(set(args.dx)) != len(args.dx):
            raise UsageError(f"--dx {' '.join(f'{value:g}' for value in args.dx)} repeats a spacing; allowed: "
                             "one different spacing (m) per run")
        spacings = list(args.dx)
    else:
        found = [SPACING_IN_NAME.search(Path(run).stem) for run in args.runs]
        if len(args.runs) < CONVERGENCE_MIN_RUNS or not all(found):
            return None, None
        spacings = [float(match.group(1)) * SPACING_UNITS[match.group(2)] for match in found]
        if len(set(spacings)) != len(spacings) or not all(value > 0 for value in spacings):
            return None, "convergence study skipped (the spacings in the runs' names repeat; give --dx)"
    if len(spacings) < CONVERGENCE_MIN_RUNS:
        return None, (f"convergence study skipped (it needs {CONVERGENCE_MIN_RUNS} or more spacings; --dx gives "
                      f"{len(spacings)})")
    return spacings, None


def _convergence(args, spacings, params, path, options) -> tuple[tuple | None, list[str]]:
    """The convergence study of the runs by spacing, computed and drawn but not written (``(dataset, png)``),
    and the lines to print; ``None`` while :data:`CONVERGENCE_MODULE` is missing."""
    try:
        study = importlib.import_module(CONVERGENCE_MODULE).convergence_study
    except (ModuleNotFoundError, AttributeError) as error:
        if isinstance(error, ModuleNotFoundError) and error.name != CONVERGENCE_MODULE:
            raise
        return None, [f"convergence study skipped ({CONVERGENCE_MODULE}.convergence_study is not available)"]
    # every option of validate but the verdict's tolerance (the study's verdict is the observed order)
    dataset = study(dict(zip(spacings, args.runs)), params, path,
                    **{key: value for key, value in options.items() if key != "tolerance"})
    try:
        from mdr_events.plotting.convergence import plot_convergence_study
        from mdr_events.plotting.figures import figure_png
        png = figure_png(plot_convergence_study(dataset))
    except ImportError:
        png = None
    lines = [f"convergence study ({len(spacings)} spacings): {dataset.attrs.get('verdict', '?')}"]
    if "max_error_order" in dataset:
        orders = dataset["max_error_order"]
        spreads = dataset.get("max_error_order_spread", orders * math.nan)
        lines.append("  observed order of the max error: " + ", ".join(
            f"{name} {float(orders.sel(quantity=name)):.2f} ± {float(spreads.sel(quantity=name)):.2f}"
            for name in orders["quantity"].values)
            + (f" (expected {float(dataset['expected_order']):g})" if "expected_order" in dataset else ""))
    return (dataset, png), lines


def _command_validate(args: argparse.Namespace) -> int:
    # here, not at the top: validation_files loads matplotlib.pyplot for the figures
    from mdr_events.app.validation_files import VALIDATION_SUFFIXES, console_summary, render_validation, write_rendered
    from mdr_events.io.files import PendingFile, atomic_write_all, netcdf_writer

    params, provenance = _validation_parameters(args)
    path, description = _validation_path(args, params)
    options = dict(names=_pairs("--names", args.names, list(CANDIDATE_QUANTITIES)),
                   units=_pairs("--units", args.units, list(CANDIDATE_QUANTITIES)),
                   time_origin=_time_origin(args.time_origin), tolerance=args.tolerance, limits=_limits(args),
                   profile=_profile(args), friction=_friction(args))
    if not (math.isfinite(args.tolerance) and args.tolerance > 0):
        raise UsageError(f"--tolerance {args.tolerance!r} is not allowed; allowed: a number > 0")
    out = prepare_output_directory(args.out, "--out")
    spacings, note = _spacings(args)  # a bad --dx is named before any run is read
    stems: dict[str, str] = {}
    inputs = {os.path.realpath(run) for run in args.runs}
    reports = []
    # every run is validated (first) and its files rendered before anything is written: bad input writes nothing
    for run in args.runs:
        stem = Path(run).stem
        if stem in stems:
            raise UsageError(f"the runs {stems[stem]} and {run} would both be written as {stem}.*; allowed: runs "
                             "with different file names")
        if stem == CONVERGENCE_STEM and spacings is not None:
            raise UsageError(f"the run {run} would be written as {stem}.*, the convergence study's files; allowed: "
                             "another file name")
        try:
            check_output_stem("stem", stem)
        except ValueError as error:
            raise UsageError(f"the run {run} would be written as {stem}.*: {error}") from None
        stems[stem] = run
        clash = [target for target in (out / f"{stem}{suffix}" for suffix in VALIDATION_SUFFIXES)
                 if os.path.realpath(target) in inputs]
        if clash:
            raise UsageError(f"--out {args.out}: writing {clash[0]} would overwrite a run; allowed: another directory")
        # a file of several runs along alpha (the package's own simulate output): the one at --alpha
        report = validate(run, params, path, select=None if args.alpha is None else {"alpha": args.alpha},
                          progress=print, **options)
        report.attrs.update(provenance, path_description=description)
        reports.append((run, stem, report))
    rendered = [(run, render_validation(report, stem)) for run, stem, report in reports]
    convergence, convergence_lines = (None, [note] if note else []) if spacings is None else \
        _convergence(args, spacings, params, path, options)
    for run, files in rendered:
        written = write_rendered(files, out)
        print("\n".join(console_summary(files.report, run)))
        print(f"  written: {', '.join(str(outcome.path) for outcome in written)}")
    if convergence is not None:
        dataset, png = convergence
        files = [PendingFile(out / f"{CONVERGENCE_STEM}.nc", netcdf_writer(dataset), ".nc")]
        if png is not None:
            files.append(PendingFile(out / f"{CONVERGENCE_STEM}.png", lambda temporary: Path(temporary).write_bytes(png),
                                     ".png"))
        written = atomic_write_all(files)  # together or not at all
        convergence_lines.append(f"  written: {', '.join(map(str, written))}")
    if convergence_lines:
        print("\n".join(convergence_lines))
    failed = [run for run, files in rendered if files.report.attrs["verdict"] != "pass"]
    passed = len(rendered) - len(failed)
    print(f"{len(rendered)} run{'s' if len(rendered) != 1 else ''}: {passed} pass, {len(failed)} fail")
    return 1 if failed else 0


def _measured_path_options(parser: argparse.ArgumentParser, what: str, start: bool = False) -> None:
    """The parameters (preset, file or values) and the path (scenario and angle, or a path file) of measured
    runs: ``validate`` and ``fit``."""
    role = "the start of the fit" if start else "the parameters"
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--preset", choices=sorted(PRESETS), default=None,
                        help=f"{role}: a parameter set of the paper (default paper-R30); the options below override it")
    source.add_argument("--params", default=None, metavar="FILE",
                        help=f"{role}: a TOML file with a [parameters] table as in a study file (e.g. the study file)")
    for name, long_name in PARAMETER_LONG_NAMES.items():
        parser.add_argument(f"--{name}", type=float, default=None, metavar="VALUE",
                            help=f"{long_name} [{PARAMETER_UNITS[name]}]")
    motion = parser.add_mutually_exclusive_group(required=True)
    motion.add_argument("--scenario", choices=list(SCENARIO_NAMES), help=f"the scenario the {what} took (with --alpha)")
    motion.add_argument("--path", default=None, metavar="FILE",
                        help="a TOML file with a [path] table as in a study file: waypoints = [[x, d], ...] (m), "
                             "speed (m/s, default the parameters' v)")
    parser.add_argument("--alpha", type=float, default=None, metavar="DEG", help="the scenario's angle in degrees")


def _column_options(parser: argparse.ArgumentParser, whose: str) -> None:
    """Your column names, units and time origin (``validate`` and ``fit``)."""
    parser.add_argument("--names", default=None, metavar="Q=COLUMN,...",
                        help="your column names, e.g. time=t,normal_force=Fn (quantities: "
                             f"{', '.join(CANDIDATE_QUANTITIES)})")
    parser.add_argument("--units", default=None, metavar="Q=UNIT,...",
                        help="your units, e.g. time=ms,normal_force=mN,contact_area=mm2 (default SI)")
    parser.add_argument("--time-origin", default="first_contact", metavar="ORIGIN",
                        help=f"what the {whose} time counts from: first_contact (default), path_start, or the "
                             f"{whose} time of first contact in s")


def _numbers(option: str, text: str | None, allowed: Sequence[str]) -> dict[str, float]:
    """``normal_force=1e-3,...`` -> ``{"normal_force": 0.001}``; a value that is not a number names the option."""
    numbers = {}
    for key, value in _pairs(option, text, allowed).items():
        try:
            numbers[key] = float(value)
        except ValueError:
            raise UsageError(f"{option} {key}={value!r} is not allowed; allowed: a number") from None
    return numbers


def _bounds(items: Sequence[str] | None) -> dict[str, tuple[float, float]]:
    """``["tau0=1e3:1e6"]`` -> ``{"tau0": (1e3, 1e6)}``; a bad item names the option."""
    bounds = {}
    for item in items or ():
        name, equals, interval = item.partition("=")
        low, colon, high = interval.partition(":")
        try:
            if not (equals and colon):
                raise ValueError
            bounds[name.strip()] = (float(low), float(high))
        except ValueError:
            raise UsageError(f"--bounds {item!r} is not allowed; allowed: NAME=LOW:HIGH with numbers in SI units, "
                             "e.g. tau0=1e3:1e6") from None
    return bounds


def _command_fit(args: argparse.Namespace) -> int:
    # here, not at the top: fit_files loads matplotlib.pyplot for the figures
    from mdr_events.app.fit_files import FIT_SUFFIXES, fit_console_summary, render_fit
    from mdr_events.app.validation_files import write_rendered

    params, provenance = _validation_parameters(args)
    path, description = _validation_path(args, params)
    friction = _friction(args)  # a bad law is named before anything is written
    out = prepare_output_directory(args.out, "--out")
    stem = f"{Path(args.data).stem}_fit"
    try:
        check_output_stem("stem", stem)
    except ValueError as error:
        raise UsageError(f"the fit of {args.data} would be written as {stem}.*: {error}") from None
    if any(os.path.realpath(out / f"{stem}{suffix}") == os.path.realpath(args.data) for suffix in FIT_SUFFIXES):
        raise UsageError(f"--out {args.out}: writing the fit would overwrite {args.data}; allowed: another directory")
    quantities = list(CANDIDATE_QUANTITIES)
    units = _pairs("--units", args.units, quantities)
    # --noise in the units of --units (SI where none is given)
    noise = {name: value * unit_factor(name, units.get(name, CANDIDATE_QUANTITIES[name]), "--units")
             for name, value in _numbers("--noise", args.noise, quantities[1:]).items()}
    # a scenario is passed by name: the fit rebuilds its way out (below the jump-off) for each trial
    motion = (path, None) if args.path is not None else (args.scenario, args.alpha)
    result = fit(args.data, *motion, free=args.free, start=params, bounds=_bounds(args.bounds),
                 noise=noise, names=_pairs("--names", args.names, quantities), units=units,
                 time_origin=_time_origin(args.time_origin), limits=_limits(args), profile=_profile(args),
                 friction=friction, progress=print)
    result.dataset.attrs.update(provenance, path_description=description)
    rendered = render_fit(result.dataset, stem)
    written = write_rendered(rendered, out)
    print("\n".join(fit_console_summary(result.dataset, args.data, result.optimizer)))
    print(f"  written: {', '.join(str(outcome.path) for outcome in written)}")
    return 0 if result.identifiable and not result.warnings else 1


def _command_sweep(args: argparse.Namespace) -> int:
    if args.workers is not None and args.workers < 1:
        raise UsageError(f"--workers {args.workers} is not allowed; allowed: an integer >= 1")
    study = load_study(args.study)
    store = sweep_store(study)
    if store.exists() and not (args.resume or args.restart):
        raise UsageError(f"{store} holds an earlier sweep; allowed: --resume to continue it (its done chunks are "
                         "kept), --restart to start afresh")
    outcomes = run_sweep(study, progress=_progress, scheduler=args.scheduler, workers=args.workers,
                         resume=args.resume)
    for outcome in outcomes:
        print(outcome.path)
    return 0


def _command_reproduce(args: argparse.Namespace) -> None:
    out = prepare_output_directory(args.out, "--out")
    reproduce(out, progress=_progress, keep_agreeing=not args.rewrite)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="mdr-events", description=DESCRIPTION, epilog="exit status: " + "; ".join(
        f"{status} {meaning}" for status, meaning in EXIT_STATUSES.items()))
    parser.add_argument("--version", action="version", version=f"mdr_events {__version__}")
    parser.add_argument("--debug", action="store_true",
                        help="on an error, show the traceback (re-raise it) instead of one line")
    # not required here: a missing command is reported by main(), after unknown options are named
    commands = parser.add_subparsers(dest="command", parser_class=_Parser)

    derive = commands.add_parser("derive", help="print every relation derived by SymPy")
    derive.add_argument("--latex", action="store_true", help="LaTeX instead of pretty printing")
    derive.add_argument("--key", default=None, help="only this relation (e.g. jkr_depth)")
    derive.set_defaults(run=_command_derive)

    phase = commands.add_parser("phase-diagram", help="write the phase diagram (Fig. 9a/9b) as .nc and .png")
    phase.add_argument("--scenario", choices=["A", "B"], required=True)
    phase.add_argument("--out", required=True, help="output directory")
    _friction_option(phase)
    _profile_option(phase)
    _parameter_options(phase)
    phase.set_defaults(run=_command_phase_diagram)

    sim = commands.add_parser("simulate", help="simulate Fig. 8 (A) / Fig. 10 (B); write .nc and .png")
    sim.add_argument("--scenario", choices=list(SCENARIO_NAMES), required=True)
    sim.add_argument("--method", choices=list(METHODS), default="discrete")
    sim.add_argument("--alpha", type=float, nargs="+", default=None, metavar="DEG",
                     help="angles in degrees (default 10 20 ... 80)")
    sim.add_argument("--dx", type=float, default=None,
                     help=f"discrete method: spring spacing in m (default {DEFAULT_DX:g})")
    steps = sim.add_mutually_exclusive_group()
    steps.add_argument("--dt", type=float, default=None, help="discrete method: time step in s")
    steps.add_argument("--n-steps", type=int, default=None,
                       help=f"discrete method: time steps of the longest case (default {DEFAULT_STEPS})")
    sim.add_argument("--out", required=True, help="output directory")
    _profile_option(sim)
    _friction_option(sim)
    _limit_option(sim)
    _parameter_options(sim)
    sim.set_defaults(run=_command_simulate)

    check = commands.add_parser(
        "validate", help="validate a simulator's runs (CSV or netCDF) against the exact continuum",
        description="Validate runs of a simulator against the exact continuum (mdr_events.validate); write "
                    "<run>.nc, <run>.md and <run>.png per run into --out; exit 0 if every run is within the "
                    "tolerance, 1 if not, 2 for bad input.")
    check.add_argument("runs", nargs="+", metavar="RUN", help="a run: a CSV file with a header row, or netCDF")
    _measured_path_options(check, "runs")
    check.add_argument("--out", required=True, help="output directory")
    _friction_option(check)
    _profile_option(check)
    _limit_option(check)
    check.add_argument("--tolerance", type=float, default=1e-3,
                       help="bound on each quantity's max error relative to its range (default 1e-3)")
    _column_options(check, "runs'")
    check.add_argument("--dx", type=float, nargs="+", default=None, metavar="M",
                       help="the spring spacing of each run (m), in the order of the runs and after them, for a "
                            "convergence study of three or more runs (default: from names such as run_dx2um.csv)")
    check.set_defaults(run=_command_validate)

    fitting = commands.add_parser(
        "fit", help="fit the model's parameters to measured curves (CSV or netCDF)",
        description="Fit free parameters of the continuum model to measured F_N, F_x, A or a (mdr_events.fit); "
                    "write <data>_fit.nc, .md and .png into --out; exit 0 if every free parameter is determined "
                    "and the fit describes the data, 1 if not (a parameter not identifiable, poorly determined or "
                    "at a bound; a warning such as residuals far above the noise), 2 for bad input.")
    fitting.add_argument("data", metavar="DATA", help="the measurement: a CSV file with a header row, or netCDF")
    fitting.add_argument("--free", nargs="+", required=True, metavar="NAME",
                         help=f"the parameters to fit: {', '.join(FREE_NAMES)}")
    _measured_path_options(fitting, "measurement", start=True)
    fitting.add_argument("--out", required=True, help="output directory")
    _friction_option(fitting)
    _profile_option(fitting)
    _limit_option(fitting)
    _column_options(fitting, "measurement's")
    fitting.add_argument("--noise", default=None, metavar="Q=SIGMA,...",
                         help="the noise's standard deviation per quantity, in the units of --units (SI where none "
                              "is given), e.g. normal_force=2 with normal_force=mN (default: estimated from the data)")
    fitting.add_argument("--bounds", nargs="+", default=None, metavar="NAME=LOW:HIGH",
                         help="bounds of free parameters in SI units, e.g. tau0=1e3:1e6 (default: physical ranges)")
    fitting.set_defaults(run=_command_fit)

    sweeping = commands.add_parser(
        "sweep", help="run the [sweep] table of a study file on dask (a local cluster, or --scheduler ADDRESS)",
        description="Run a parameter sweep described by the [sweep] table of a study file (mdr_events.sweep): "
                    "<name>_sweep.zarr is written chunk by chunk (--resume continues an interrupted one) and "
                    "<name>_sweep.nc holds the labelled result.")
    sweeping.add_argument("study", help="the study file, e.g. study.toml")
    sweeping.add_argument("--scheduler", default=None, metavar="ADDRESS",
                          help="'local' (a LocalCluster on this machine, the default), 'serial', or a running dask "
                               "scheduler's address such as tcp://host:8786")
    sweeping.add_argument("--workers", type=int, default=None, metavar="N",
                          help="worker processes of the local cluster (default: the machine's cores)")
    store = sweeping.add_mutually_exclusive_group()
    store.add_argument("--resume", action="store_true",
                       help="continue the store of an interrupted sweep (its done chunks are not run again)")
    store.add_argument("--restart", action="store_true",
                       help="start afresh, replacing the store of an earlier sweep (without --resume or --restart an "
                            "existing store is an error)")
    sweeping.set_defaults(run=_command_sweep)

    run = commands.add_parser("run", help="run a study described in a TOML file (see mdr_events.app.study)")
    run.add_argument("study", help="the study file, e.g. study.toml")
    run.set_defaults(run=_command_run)

    reproduce = commands.add_parser("reproduce", help="regenerate results/ (figures, datasets, report)")
    reproduce.add_argument("--out", default="results", help="output directory (default results)")
    reproduce.add_argument("--rewrite", action="store_true",
                           help="rewrite every file, also those that agree with a fresh computation")
    reproduce.set_defaults(run=_command_reproduce)
    names = ", ".join(commands.choices)

    def missing_command(args: argparse.Namespace) -> None:  # a command's own default replaces this one
        raise UsageError(f"a command is required; allowed: {names}")

    parser.set_defaults(run=missing_command)
    return parser


def _one_line(message: str) -> str:
    """A message on one line: its lines joined (nothing is cut)."""
    return " ".join(line.strip() for line in message.splitlines() if line.strip())


def _message(error: BaseException) -> str:
    """What an error says, for ``mdr-events: error: ...``."""
    if isinstance(error, KeyError) and error.args:
        return str(error.args[0])
    if isinstance(error, OSError) and error.filename is not None:
        files = " -> ".join(os.fsdecode(name) for name in (error.filename, error.filename2) if name is not None)
        return f"{files}: {error.strerror or error}"
    return str(error)


def _on_sigterm(signum: int, frame) -> None:
    signal.signal(signum, signal.SIG_IGN)  # a second SIGTERM must not interrupt the clean-up
    raise _Terminated(signum)


def _outcome(error: BaseException) -> tuple[str, int]:
    """The line to print for an error that ends the command, and the exit status (:data:`EXIT_STATUSES`)."""
    if isinstance(error, UsageError):
        return f"error: {error}", EXIT_BAD_INPUT
    if isinstance(error, _Terminated):
        return "terminated (SIGTERM); no file was left half-written", 128 + signal.SIGTERM
    if isinstance(error, KeyboardInterrupt):
        return "interrupted (Ctrl-C); no file was left half-written", 128 + signal.SIGINT
    if isinstance(error, INPUT_ERRORS):
        return f"error: {_message(error)}", EXIT_BAD_INPUT
    what = "the computation failed" if isinstance(error, COMPUTATION_ERRORS) else "internal error"
    return (f"error: {what} ({type(error).__name__}: {_message(error) or 'no message'}); rerun with --debug for "
            "the traceback, and please report it", EXIT_FAILED)


#: Suffixes of the files the commands read: a value of a multi-value option with one of these is a file it took.
FILE_SUFFIXES = (".csv", ".nc", ".toml")


def _multi_value_options(parser: argparse.ArgumentParser) -> set[str]:
    """The options, of every command, that take several values (``--free E tau0``, ``--dx 1e-6 2e-6``)."""
    found = set()
    for action in parser._actions:  # noqa: SLF001 - argparse keeps its actions there
        if action.nargs in ("+", "*") and action.option_strings:
            found.update(action.option_strings)
        for sub in getattr(action, "choices", None).values() if isinstance(action, argparse._SubParsersAction) else ():
            found |= _multi_value_options(sub)
    return found


def _file_taken_as_value(argv: Sequence[str]) -> str:
    """A hint for a usage error: which multi-value option took a file as one of its values (``--free tau0 run.csv``:
    argparse gives every word up to the next option to ``--free``), and how to write it; "" if none did."""
    multi = _multi_value_options(build_parser())
    option = None
    for token in argv:
        if token == "--":
            return ""
        if token.startswith("--"):
            option = token.split("=", 1)[0] if token.split("=", 1)[0] in multi else None
        elif option is not None and (os.path.isfile(token) or token.lower().endswith(FILE_SUFFIXES)):
            return (f" ({option} took {token!r}, a file, as one of its values: write the file before {option}, or "
                    f"{option} and its values last)")
    return ""


def _silence_stdout() -> None:
    """Point stdout at the null device, so that the interpreter's final flush does not raise again."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # no real file descriptor (captured in a test): nothing to flush
        pass


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``mdr-events``; returns the exit status (:data:`EXIT_STATUSES`).

    An error prints one line on stderr (``mdr-events: error: ...``); with ``--debug`` it is re-raised with
    its traceback (a usage error excepted). SIGTERM is handled like Ctrl-C while the command runs: the file
    being written is removed (its temporary file), and the status is 143.
    """
    handles_sigterm = threading.current_thread() is threading.main_thread()  # signals reach the main thread only
    previous = signal.signal(signal.SIGTERM, _on_sigterm) if handles_sigterm else None
    debug = False
    try:
        args = build_parser().parse_args(argv)
        debug = args.debug
        if getattr(args, "key", None) is not None:
            symbolic.relation(args.key)  # an unknown (or empty) key is bad input before anything is printed
        matplotlib.use("Agg")  # the CLI writes figures to files only: no window, whatever the user's default
        status = args.run(args)
    except BrokenPipeError:  # the reader has gone (`| head`): nothing more to say, and no one to say it to
        _silence_stdout()
        return EXIT_BROKEN_PIPE
    except (Exception, KeyboardInterrupt, _Terminated) as error:
        if debug and not isinstance(error, UsageError):
            raise
        text, code = _outcome(error)
        if isinstance(error, UsageError):
            text += _file_taken_as_value(sys.argv[1:] if argv is None else list(argv))
        print(f"mdr-events: {_one_line(text)}", file=sys.stderr)
        return code
    finally:
        if handles_sigterm:
            signal.signal(signal.SIGTERM, signal.SIG_DFL if previous is None else previous)
    return 0 if status is None else int(status)


def console_main() -> int:
    """The console script ``mdr-events``: :func:`main`; after an interrupt, what the interpreter's shutdown would
    print (a storage library's pending tasks destroyed, thousands of lines after a SIGTERM mid-sweep) is not shown:
    the one line said what happened."""
    status = main()
    for signum in (signal.SIGINT, signal.SIGTERM):  # (the work is done: a signal now would end it silently with 130)
        signal.signal(signum, signal.SIG_IGN)
    if status in (128 + signal.SIGINT, 128 + signal.SIGTERM):
        sys.stderr.flush()
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stderr.fileno())
    return status


if __name__ == "__main__":  # pragma: no cover
    sys.exit(console_main())
