"""``mdr-events fit``: free parameters of the continuum fitted to measured curves; <data>_fit.nc, .md and .png."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Sequence

from mdr_events.app.cli import _options
from mdr_events.app.cli._options import UsageError

if TYPE_CHECKING:
    from mdr_events.app.jobs import FitJob


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``fit``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser(
        "fit", help="fit the model's parameters to measured curves (CSV or netCDF)", fill=fill,
        description="Fit free parameters of the continuum model to measured F_N, F_x, A or a (mdr_events.fit); "
                    "write <data>_fit.nc, .md and .png into --out; exit 0 if every free parameter is determined "
                    "and the fit describes the data, 1 if not (a parameter not identifiable, poorly determined or "
                    "at a bound; a warning such as residuals far above the noise), 2 for bad input.")


def fill(fitting: argparse.ArgumentParser) -> None:
    """Add the options of ``fit``."""
    from mdr_events.analysis.fit import FREE_NAMES

    fitting.add_argument("data", metavar="DATA", help="the measurement: a CSV file with a header row, or netCDF")
    fitting.add_argument("--free", nargs="+", required=True, metavar="NAME",
                         help=f"the parameters to fit: {', '.join(FREE_NAMES)}")
    _options.measured_path_options(fitting, "measurement", start=True)
    fitting.add_argument("--out", required=True, help="output directory")
    _options.friction_options(fitting)
    _options.profile_options(fitting)
    _options.layer_options(fitting)
    _options.limit_options(fitting)
    _options.column_options(fitting, "measurement's")
    fitting.add_argument("--noise", default=None, metavar="Q=SIGMA,...",
                         help="the noise's standard deviation per quantity, in the units of --units (SI where none "
                              "is given), e.g. normal_force=2 with normal_force=mN (default: estimated from the data)")
    fitting.add_argument("--bounds", nargs="+", default=None, metavar="NAME=LOW:HIGH",
                         help="bounds of free parameters in SI units, e.g. tau0=1e3:1e6 (default: physical ranges)")
    fitting.set_defaults(run=run)


def numbers(option: str, text: str | None, allowed: Sequence[str]) -> dict[str, float]:
    """``normal_force=1e-3,...`` -> ``{"normal_force": 0.001}``; a value that is not a number names the option."""
    from mdr_events.validation import PLAIN_NUMBER, plain_number

    found = {}
    for key, value in _options.pairs(option, text, allowed).items():
        try:
            found[key] = plain_number(value)
        except ValueError:
            raise UsageError(f"{option} {key}={value!r} is not allowed; allowed: {PLAIN_NUMBER}") from None
    return found


def bounds(items: Sequence[str] | None) -> dict[str, tuple[float, float]]:
    """``["tau0=1e3:1e6"]`` -> ``{"tau0": (1e3, 1e6)}``; a bad item names the option."""
    from mdr_events.validation import PLAIN_NUMBER, plain_number

    found = {}
    for item in items or ():
        name, equals, interval = item.partition("=")
        low, colon, high = interval.partition(":")
        try:
            if not (equals and colon):
                raise ValueError
            found[name.strip()] = (plain_number(low), plain_number(high))
        except ValueError:
            raise UsageError(f"--bounds {item!r} is not allowed; allowed: NAME=LOW:HIGH with numbers in SI units "
                             f"({PLAIN_NUMBER}), e.g. tau0=1e3:1e6") from None
    return found


def job(args: argparse.Namespace) -> FitJob:
    """The fit the options ask for."""
    from mdr_events.app.jobs import FitJob
    from mdr_events.io.candidates import CANDIDATE_QUANTITIES, unit_factor
    from mdr_events.io.files import check_output_stem

    params, provenance = _options.measured_parameters(args)
    contact = _options.contact(args, params)  # a bad law is named before anything is written
    motion, description = _options.measured_motion(args, params, contact)
    _options.check_reference_layer(contact, motion, "fit")
    stem = f"{Path(args.data).stem}_fit"
    try:
        check_output_stem("stem", stem)
    except ValueError as error:
        raise UsageError(f"the fit of {args.data} would be written as {stem}.*: {error}") from None
    quantities = list(CANDIDATE_QUANTITIES)
    units = _options.pairs("--units", args.units, quantities)
    # --noise in the units of --units (SI where none is given)
    noise = {name: value * unit_factor(name, units.get(name, CANDIDATE_QUANTITIES[name]), "--units")
             for name, value in numbers("--noise", args.noise, quantities[1:]).items()}
    return FitJob(args.data, Path(args.data), stem, contact, motion, description, tuple(args.free),
                  bounds(args.bounds), noise, _options.pairs("--names", args.names, quantities), units,
                  _options.time_origin(args.time_origin), _options.limits(args), provenance)


def run(args: argparse.Namespace) -> int:
    """Fit, write and print the summary; exit 0 if every free parameter is determined and the fit describes the
    data, else 1."""
    from mdr_events.app.fit_files import FIT_SUFFIXES, fit_console_summary
    from mdr_events.app.validation_files import write_rendered

    spec = job(args)
    out = _options.output_directory(args)
    _options.check_not_overwritten(args, out, spec.stem, FIT_SUFFIXES, [args.data],
                                   f"the fit would overwrite {args.data}")
    result, rendered = spec.compute(progress=print)
    written = write_rendered(rendered, out)
    print("\n".join(fit_console_summary(result.dataset, args.data, result.optimizer)))
    print(f"  written: {', '.join(str(outcome.path) for outcome in written)}")
    return 0 if result.identifiable and not result.warnings else 1
