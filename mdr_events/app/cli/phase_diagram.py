"""``mdr-events phase-diagram``: the phase diagram of Fig. 9a (A) or 9b (B), written as .nc and .png; under the
rate-dependent adhesion law (``--adhesion-law rate``) the scenario's critical angle against the speed (``--speeds``),
written as .nc."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from mdr_events.app.cli import _options

if TYPE_CHECKING:
    from mdr_events.app.jobs import PhaseJob


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``phase-diagram``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser("phase-diagram", help="write the phase diagram (Fig. 9a/9b) as .nc and .png", fill=fill)


def fill(phase: argparse.ArgumentParser) -> None:
    """Add the options of ``phase-diagram``."""
    phase.add_argument("--scenario", choices=["A", "B"], required=True)
    phase.add_argument("--out", required=True, help="output directory")
    _options.friction_options(phase)
    _options.profile_options(phase)
    _options.adhesion_options(phase)
    phase.add_argument("--speeds", type=float, nargs="+", default=None, metavar="V",
                       help="--adhesion-law rate: the paths' speeds (m/s) of the scenario's critical angle, written as "
                            "critical_angle_<scenario>_at_speeds.nc (default the parameters' v)")
    _options.parameter_options(phase)
    phase.set_defaults(run=run)


def job(args: argparse.Namespace) -> PhaseJob:
    """The phase diagram the options ask for."""
    from mdr_events.app.jobs import PhaseJob

    from mdr_events.app import inputs

    params, provenance = _options.parameters(args)
    contact = _options.contact(args, params, simulated=False)
    try:
        speeds = inputs.angle_speeds(contact, args.speeds, params)
    except (TypeError, ValueError) as error:
        given = "--adhesion-law rate" if args.speeds is None else \
            f"--speeds {' '.join(map(_options.shown_number, args.speeds))}"
        raise _options.UsageError(f"{given}: {error}") from None
    stem = f"phase_diagram_{args.scenario}" if speeds is None else f"critical_angle_{args.scenario}_at_speeds"
    return PhaseJob(contact, args.scenario, params.d_max, params.v, provenance, stem, speeds)


def run(args: argparse.Namespace) -> None:
    """Compute and write the diagram; print the files written (on stderr, a line now and then while it runs long)."""
    from mdr_events.app.cli import progress

    spec = job(args)
    for outcome in spec.run(_options.output_directory(args), progress):
        print(outcome.path)
