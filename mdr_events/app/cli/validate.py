"""``mdr-events validate``: a simulator's runs against the exact continuum (and, over three or more spacings, the
convergence study); per run a .nc report, a Markdown summary and a figure."""

from __future__ import annotations

import argparse
import math
import re
from pathlib import Path
from typing import TYPE_CHECKING

from mdr_events.app.cli import _columns, _options
from mdr_events.app.cli._options import UsageError

if TYPE_CHECKING:
    from mdr_events.app.jobs import ValidateJob, Validated

#: A spacing in a run's file name: ``dx`` then a number and an optional unit (``run_dx2um.csv``, ``dx=2e-6.csv``).
SPACING_IN_NAME = re.compile(r"(?:^|[^A-Za-z])dx[_=-]?([0-9]+(?:\.[0-9]+)?(?:[eE][-+]?[0-9]+)?)(nm|um|µm|mm|m)?(?![A-Za-z])")
SPACING_UNITS = {None: 1.0, "m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9}
#: The least number of spacings for a convergence study (an order from a least-squares slope with its spread).
CONVERGENCE_MIN_RUNS = 3


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``validate``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser(
        "validate", help="validate a simulator's runs (CSV or netCDF) against the exact continuum", fill=fill,
        description="Validate runs of a simulator against the exact continuum (mdr_events.validate); write "
                    "<run>.nc, <run>.md and <run>.png per run into --out; exit 0 if every run is within the "
                    "tolerance, 1 if not, 2 for bad input.")


def fill(check: argparse.ArgumentParser) -> None:
    """Add the options of ``validate``."""
    check.add_argument("runs", nargs="+", metavar="RUN", help="a run: a CSV file with a header row, or netCDF")
    _options.measured_path_options(check, "runs")
    check.add_argument("--out", required=True, help="output directory")
    _options.friction_options(check)
    _options.profile_options(check)
    _options.layer_options(check)
    _options.adhesion_options(check)
    _options.limit_options(check)
    check.add_argument("--tolerance", type=float, default=1e-3,
                       help="bound on each quantity's max error relative to its range (default 1e-3)")
    _columns.column_options(check, "runs'")
    check.add_argument("--dx", type=float, nargs="+", default=None, metavar="M",
                       help="the spring spacing of each run (m), in the order of the runs and after them, for a "
                            "convergence study of three or more runs (default: from names such as run_dx2um.csv)")
    check.set_defaults(run=run)


def spacings(args: argparse.Namespace) -> tuple[list[float] | None, str | None]:
    """The spacing of each run for a convergence study: ``--dx`` (one per run), else from every run's file
    name; ``None`` and why not (``None``: nothing to say) where there is no study."""
    from mdr_events.io.candidates import unit_spelling
    from mdr_events.validation import SCALE_MAX, SCALE_MIN

    if args.dx is not None:
        if len(args.dx) != len(args.runs):
            raise UsageError(f"--dx has {len(args.dx)} values and there are {len(args.runs)} runs; allowed: one "
                             "spacing (m) per run, in the order of the runs")
        bad = [value for value in args.dx if not SCALE_MIN <= value <= SCALE_MAX]
        if bad:
            raise UsageError(f"--dx {bad[0]!r} is not allowed; allowed: spacings (m) from {SCALE_MIN:.2g} to "
                             f"{SCALE_MAX:.2g}")
        if len(set(args.dx)) != len(args.dx):
            raise UsageError(f"--dx {' '.join(map(_options.shown_number, args.dx))} repeats a spacing; allowed: "
                             "one different spacing (m) per run")
        found = list(args.dx)
    else:
        matches = [SPACING_IN_NAME.search(unit_spelling(Path(run).stem)) for run in args.runs]  # (μm: µm)
        if len(args.runs) < CONVERGENCE_MIN_RUNS or not all(matches):
            return None, None
        found = [float(match.group(1)) * SPACING_UNITS[match.group(2)] for match in matches]
        if len(set(found)) != len(found) or not all(value > 0 for value in found):
            return None, "convergence study skipped (the spacings in the runs' names repeat; give --dx)"
    if len(found) < CONVERGENCE_MIN_RUNS:
        return None, (f"convergence study skipped (it needs {CONVERGENCE_MIN_RUNS} or more spacings; --dx gives "
                      f"{len(found)})")
    return found, None


def _stems(args: argparse.Namespace, study: bool) -> tuple[str, ...]:
    """Each run's report stem (its file's stem), checked: distinct, plain, not the convergence study's."""
    from mdr_events.app.jobs import CONVERGENCE_STEM
    from mdr_events.io.files import check_output_stem
    from mdr_events.validation import shown_path

    stems: dict[str, str] = {}
    for run in args.runs:
        stem = Path(run).stem
        as_stem = f"{shown_path(stem)}.*"  # (a long text given as a run: cut, as the run's path is)
        written = f"{shown_path(run)} would be written as {as_stem}"
        if stem in stems:
            raise UsageError(f"the runs {shown_path(stems[stem])} and {shown_path(run)} would both be written as "
                             f"{as_stem}; allowed: runs with different file names")
        if stem == CONVERGENCE_STEM and study:
            raise UsageError(f"the run {written}, the convergence study's files; allowed: another file name")
        try:
            check_output_stem("stem", stem)
        except ValueError as error:
            raise UsageError(f"the run {written}: {error}") from None
        stems[stem] = run
    return tuple(stems)


def job(args: argparse.Namespace) -> tuple[ValidateJob, str | None]:
    """The validation the options ask for, and a note on the convergence study (``None``: nothing to say)."""
    from mdr_events.app.jobs import ValidateJob
    from mdr_events.io.candidates import CANDIDATE_QUANTITIES

    from mdr_events.app import inputs
    from mdr_events.models.methods import Continuum

    params, provenance = _options.measured_parameters(args)
    contact = _options.contact(args, params)
    motion, description = _options.measured_motion(args, params, contact)
    try:  # (the rate law's reference is its own continuum: what that does not run, named before a run is read)
        inputs.check_reference_run(contact, motion, "validate")
    except (TypeError, ValueError) as error:
        raise UsageError(f"--adhesion-law rate: {error}") from None
    _options.check_reference_layer(contact, motion, "validate")
    names = _columns.pairs("--names", args.names, list(CANDIDATE_QUANTITIES))
    units = _columns.pairs("--units", args.units, list(CANDIDATE_QUANTITIES))
    origin, limits = _columns.time_origin(args.time_origin), _options.limits(args)
    if not (math.isfinite(args.tolerance) and 0 < args.tolerance <= 1):
        raise UsageError(f"--tolerance {args.tolerance!r} is not allowed; allowed: a number in (0, 1] (the largest "
                         "error relative to the quantity's range)")
    found, note = spacings(args)  # a bad --dx is named before any run is read
    spec = ValidateJob(tuple(args.runs), tuple(Path(run) for run in args.runs), _stems(args, found is not None),
                       contact, motion, description, args.tolerance, names, units, origin, limits, provenance,
                       None if found is None else tuple(found))
    return spec, note


def _print(validated: Validated, note: str | None, out: Path) -> int:
    """Write the reports (and the convergence study), print what they say; the exit status."""
    from mdr_events.analysis.reports import ValidationReport
    from mdr_events.app.jobs import ValidateJob
    from mdr_events.app.validation_files import console_summary, write_rendered

    lines = [note] if note else []
    for run, files in validated.reports:
        written = write_rendered(files, out)
        print("\n".join(console_summary(files.report, run)))
        print(f"  written: {', '.join(str(outcome.path) for outcome in written)}")
    if validated.convergence is not None:
        lines = list(validated.convergence.lines)
        if validated.convergence.dataset is not None:
            written = ValidateJob.write_convergence(validated.convergence, out)  # together or not at all
            lines.append(f"  written: {', '.join(map(str, written))}")
    if lines:
        print("\n".join(lines))
    failed = [run for run, files in validated.reports if not ValidationReport.from_dataset(files.report).passed]
    count = len(validated.reports)
    print(f"{count} run{'s' if count != 1 else ''}: {count - len(failed)} pass, {len(failed)} fail")
    return 1 if failed else 0


def run(args: argparse.Namespace) -> int:
    """Validate every run (first) and render its files, then write them: bad input writes nothing."""
    from mdr_events.app.validation_files import VALIDATION_SUFFIXES

    spec, note = job(args)
    out = _options.output_directory(args)
    for stem in spec.stems:
        _options.check_not_overwritten(args, out, stem, VALIDATION_SUFFIXES, args.runs, "{target} would overwrite a run")
    with _columns.names_on_the_command_line():
        validated = spec.compute(progress=print)
    return _print(validated, note, out)
