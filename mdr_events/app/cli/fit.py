"""``mdr-events fit``: free parameters of the continuum fitted to measured curves; <data>_fit.nc, .md and .png."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Sequence

from mdr_events.app.cli import _columns, _options
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
                    "at a bound; a warning such as residuals far above the noise), 2 for bad input. With "
                    "--adhesion-law rate the rate-dependent law's v_ref and n (and works at rest) are fitted jointly to "
                    "the normal force of several measurements, each at its speed (--speeds; mdr_events."
                    "fit_rate_adhesion), written as <first data>_rate_fit.nc.")


def fill(fitting: argparse.ArgumentParser) -> None:
    """Add the options of ``fit``."""
    from mdr_events.analysis.fit import FREE_NAMES

    from mdr_events.analysis.rate_fit import RATE_FREE_NAMES

    fitting.add_argument("data", metavar="DATA", nargs="+",
                         help="the measurement: a CSV file with a header row, or netCDF (with --adhesion-law rate: "
                              "one or more, each at its speed of --speeds)")
    fitting.add_argument("--free", nargs="+", required=True, metavar="NAME",
                         help=f"the parameters to fit: {', '.join(FREE_NAMES)} (with --adhesion-law rate: "
                              f"{', '.join(RATE_FREE_NAMES)})")
    fitting.add_argument("--speeds", type=float, nargs="+", default=None, metavar="V",
                         help="--adhesion-law rate: each measurement's speed along the path in m/s, one per DATA "
                              "(default: the path's speed for every one)")
    fitting.add_argument("--offsets", action="store_true",
                         help="--adhesion-law rate: a free force offset per measurement (a load cell's zero)")
    _options.measured_path_options(fitting, "measurement", start=True)
    fitting.add_argument("--out", required=True, help="output directory")
    _options.friction_options(fitting)
    _options.profile_options(fitting)
    _options.layer_options(fitting)
    _options.adhesion_options(fitting)
    _options.limit_options(fitting)
    _columns.column_options(fitting, "measurement's")
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
    for key, value in _columns.pairs(option, text, allowed).items():
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


def _noise(args: argparse.Namespace, units: dict[str, str]) -> dict[str, float]:
    """``--noise`` in SI (given in the units of ``--units``, SI where none is given)."""
    from mdr_events.io.candidates import CANDIDATE_QUANTITIES, unit_factor

    quantities = list(CANDIDATE_QUANTITIES)
    return {name: value * unit_factor(name, units.get(name, CANDIDATE_QUANTITIES[name]), "--units")
            for name, value in numbers("--noise", args.noise, quantities[1:]).items()}


def rate_job(args: argparse.Namespace, contact, params, motion, description: str, provenance):
    """The joint fit of the rate law (``--adhesion-law rate``): every DATA along the path at its speed of
    ``--speeds``, written as ``<first data's stem>_rate_fit.nc``."""
    from mdr_events.analysis.rate_fit import RATE_FREE_NAMES
    from mdr_events.app.jobs import RateFitJob
    from mdr_events.contact.model import check_half_space
    from mdr_events.io.candidates import CANDIDATE_QUANTITIES
    from mdr_events.io.files import check_output_stem
    from mdr_events.models.motion import Paths
    from mdr_events.models.paths import Path as MotionPath
    from mdr_events.validation import shown_path

    if args.bounds is not None:
        raise UsageError(f"--bounds {' '.join(args.bounds)} is not allowed with --adhesion-law rate; allowed: --free "
                         f"among {', '.join(RATE_FREE_NAMES)} (v_ref and the works on a log scale, 0.001 <= n <= 1)")
    try:
        check_half_space(contact, "the joint fit of the rate law (its forward model solve_edge)")
    except ValueError as error:
        raise UsageError(f"--h {_options.shown_number(contact.layer.thickness)} with --adhesion-law rate: "
                         f"{error}") from None
    unknown = [name for name in args.free if name not in RATE_FREE_NAMES]
    if unknown or len(set(args.free)) != len(args.free):
        raise UsageError(f"--free {' '.join(args.free)} is not allowed with --adhesion-law rate; allowed: distinct "
                         f"names among {', '.join(RATE_FREE_NAMES)}")
    path = next(iter(motion.paths.values())) if isinstance(motion, Paths) else \
        motion.cases(params, contact.profile).paths[0]
    speeds = args.speeds if args.speeds is not None else [path.speed] * len(args.data)
    if len(speeds) != len(args.data):
        raise UsageError(f"--speeds {' '.join(map(_options.shown_number, speeds))} is not allowed with "
                         f"{len(args.data)} measurement(s); allowed: one speed per DATA, in their order")
    try:
        paths = tuple(MotionPath(path.waypoints, speed) for speed in speeds)
    except (TypeError, ValueError) as error:
        raise UsageError(f"--speeds: {error}") from None
    quantities = list(CANDIDATE_QUANTITIES)
    units = _columns.pairs("--units", args.units, quantities)
    noise = _noise(args, units)
    if set(noise) - {"normal_force"}:
        raise UsageError(f"--noise {args.noise} is not allowed with --adhesion-law rate; allowed: normal_force=SIGMA "
                         "alone (the joint fit reads F_N)")
    stem = f"{Path(args.data[0]).stem}_rate_fit"
    try:
        check_output_stem("stem", stem)
        return RateFitJob(tuple(args.data), tuple(Path(data) for data in args.data), stem, contact, paths,
                          f"{description} at {', '.join(map(_options.shown_number, speeds))} m/s", tuple(args.free),
                          args.offsets, noise.get("normal_force"), _columns.pairs("--names", args.names, quantities),
                          units, _columns.time_origin(args.time_origin), params.d_max, _options.limits(args),
                          provenance)
    except ValueError as error:
        raise UsageError(f"the fit of {shown_path(args.data[0])} would be written as {shown_path(stem)}.*: "
                         f"{error}") from None


def job(args: argparse.Namespace):
    """The fit the options ask for (:class:`~mdr_events.app.jobs.FitJob`, or with ``--adhesion-law rate``
    :class:`~mdr_events.app.jobs.RateFitJob`)."""
    from mdr_events.app.jobs import FitJob
    from mdr_events.io.candidates import CANDIDATE_QUANTITIES
    from mdr_events.io.files import check_output_stem
    from mdr_events.validation import shown_path

    params, provenance = _options.measured_parameters(args)
    contact = _options.contact(args, params)  # a bad law is named before anything is written
    motion, description = _options.measured_motion(args, params, contact)
    if _options.is_rate_law(contact):
        return rate_job(args, contact, params, motion, description, provenance)
    for name, value in (("--speeds", args.speeds), ("--offsets", args.offsets or None)):
        if value is not None:
            raise UsageError(f"{name} is not allowed with the adhesion law 'paper'; allowed: with --adhesion-law rate "
                             "(the joint fit over speeds)")
    if len(args.data) != 1:
        raise UsageError(f"{len(args.data)} measurements ({shown_path(' '.join(args.data))}) are not allowed with the "
                         "adhesion law 'paper'; allowed: one DATA (several at their --speeds with --adhesion-law rate)")
    args.data = args.data[0]
    _options.check_reference_layer(contact, motion, "fit")
    stem = f"{Path(args.data).stem}_fit"
    try:
        check_output_stem("stem", stem)
    except ValueError as error:
        raise UsageError(f"the fit of {shown_path(args.data)} would be written as {shown_path(stem)}.*: {error}") \
            from None
    quantities = list(CANDIDATE_QUANTITIES)
    units = _columns.pairs("--units", args.units, quantities)
    noise = _noise(args, units)  # (in the units of --units, SI where none is given)
    return FitJob(args.data, Path(args.data), stem, contact, motion, description, tuple(args.free),
                  bounds(args.bounds), noise, _columns.pairs("--names", args.names, quantities), units,
                  _columns.time_origin(args.time_origin), _options.limits(args), provenance)


def run(args: argparse.Namespace) -> int:
    """Fit, write and print the summary; exit 0 if every free parameter is determined and the fit describes the
    data, else 1."""
    from mdr_events.app.fit_files import FIT_SUFFIXES, fit_console_summary
    from mdr_events.app.jobs import RateFitJob
    from mdr_events.app.validation_files import write_rendered

    spec = job(args)
    if isinstance(spec, RateFitJob):
        return run_rate(args, spec)
    out = _options.output_directory(args)
    _options.check_not_overwritten(args, out, spec.stem, FIT_SUFFIXES, [args.data],
                                   f"the fit would overwrite {args.data}")
    with _columns.names_on_the_command_line():
        result, rendered = spec.compute(progress=print)
    written = write_rendered(rendered, out)
    print("\n".join(fit_console_summary(result.dataset, args.data, result.optimizer)))
    print(f"  written: {', '.join(str(outcome.path) for outcome in written)}")
    return 0 if result.identifiable and not result.warnings else 1


def rate_summary(result) -> list[str]:
    """The lines a joint fit of the rate law prints: each value with its interval."""
    lines = []
    for name in result["parameter"].values:
        row = result.sel(parameter=name)
        lines.append(f"  {name} = {float(row['estimate']):.6g} ({result.attrs['confidence']:.0%} interval "
                     f"[{float(row['interval_lower']):.6g}, {float(row['interval_upper']):.6g}])"
                     + (f" ({row['identifiability'].values})" if "identifiability" in row else ""))
    return lines


def run_rate(args: argparse.Namespace, spec) -> int:
    """The joint fit of the rate law: fit (every measurement read first), write ``<stem>.nc``, print the estimates;
    exit 0 if every free value is determined, else 1."""
    out = _options.output_directory(args)
    _options.check_not_overwritten(args, out, spec.stem, (".nc",), args.data, f"the fit would overwrite {{target}}")
    with _columns.names_on_the_command_line():
        result = spec.compute()
    written = spec.write(result, out)
    print(f"joint fit of the rate law to {len(spec.data)} measurement(s) ({spec.description}): "
          f"{result.attrs['message']}")
    print("\n".join(rate_summary(result)))
    for index in spec.misfits(result):
        print(f"  warning: the residuals of {args.data[index]} are {float(result['misfit'].values[index]):.3g} times "
              "its noise: the law does not describe it (check its unit, --time-origin, --speeds and the path)")
    print(f"  written: {', '.join(str(outcome.path) for outcome in written)}")
    return 0 if spec.determined(result) else 1
