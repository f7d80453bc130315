"""``mdr-events phase-diagram``: the phase diagram of Fig. 9a (A) or 9b (B), written as .nc and .png."""

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
    _options.parameter_options(phase)
    phase.set_defaults(run=run)


def job(args: argparse.Namespace) -> PhaseJob:
    """The phase diagram the options ask for."""
    from mdr_events.app.jobs import PhaseJob

    params, provenance = _options.parameters(args)
    return PhaseJob(_options.contact(args, params, simulated=False), args.scenario, params.d_max, params.v,
                    provenance, f"phase_diagram_{args.scenario}")


def run(args: argparse.Namespace) -> None:
    """Compute and write the diagram; print the files written."""
    spec = job(args)
    for outcome in spec.run(_options.output_directory(args)):
        print(outcome.path)
