"""``mdr-events simulate``: a simulation of Fig. 8 (A) or Fig. 10 (B), written as .nc and .png."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from mdr_events.app.cli import _options

if TYPE_CHECKING:
    from mdr_events.app.jobs import SimulateJob

#: The options of the discrete method, passed only when given (so that the continuum names them as in Python).
DISCRETE_OPTIONS = ("dx", "dt", "n_steps")


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``simulate``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser("simulate", help="simulate Fig. 8 (A) / Fig. 10 (B); write .nc and .png", fill=fill)


def fill(sim: argparse.ArgumentParser) -> None:
    """Add the options of ``simulate``."""
    from mdr_events.models.methods import DEFAULT_DX, DEFAULT_STEPS, METHODS
    from mdr_events.models.motion import SCENARIO_NAMES

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
    _options.profile_options(sim)
    _options.friction_options(sim)
    _options.layer_options(sim)
    _options.adhesion_options(sim)
    _options.limit_options(sim)
    _options.parameter_options(sim)
    sim.set_defaults(run=run)


def job(args: argparse.Namespace) -> SimulateJob:
    """The simulation the options ask for."""
    from mdr_events.app import inputs
    from mdr_events.app.jobs import SimulateJob
    from mdr_events.models.simulate import check_layer_taken

    params, provenance = _options.parameters(args)
    contact = _options.contact(args, params)
    options = {name: getattr(args, name) for name in DISCRETE_OPTIONS if getattr(args, name) is not None}
    method, motion = inputs.method(args.method, options), inputs.scenario(args.scenario, args.alpha, params)
    try:
        check_layer_taken(contact, motion, method)
    except (ValueError, TypeError) as error:
        raise _options.UsageError(f"--h {_options.shown_number(args.h)}: {error}") from None
    _options.check_rate_run(contact, motion, method, "simulate")
    return SimulateJob(contact, motion, method, _options.limits(args), provenance,
                       f"simulation_{args.scenario.replace('+', 'plus')}_{args.method}")


def run(args: argparse.Namespace) -> None:
    """Simulate and write; print the files written (on stderr, a line now and then while a long run runs)."""
    from mdr_events.app.cli import progress

    spec = job(args)  # every value checked (the method's options too) before the output directory is made
    out = _options.output_directory(args)  # before the simulation, which may take minutes
    for outcome in spec.run(out, progress):
        print(outcome.path)
