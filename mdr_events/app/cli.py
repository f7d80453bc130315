"""Command line: ``mdr-events derive | phase-diagram | simulate | run | reproduce``.

Bad arguments print one line ``mdr-events: error: ...`` on stderr and exit
with status 2 (no traceback).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Sequence

import matplotlib

from mdr_events._version import __version__
from mdr_events.app.report import reproduce
from mdr_events.app.result_files import write_phase_diagram, write_simulation
from mdr_events.app.study import load_study, run_study
from mdr_events.models.simulate import DEFAULT_DX, DEFAULT_STEPS, METHODS, SCENARIO_NAMES, simulate
from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, PRESETS, Parameters, from_preset
from mdr_events.theory import symbolic

#: The first line of ``mdr-events --help`` (plain text: argparse prints it as it is).
DESCRIPTION = ("Adhesive indentation and detachment at an angle with the Method of Dimensionality Reduction "
               "(Lyashenko, Popov & Borysiuk 2023, section 4).")


class UsageError(Exception):
    """A user error: reported in one line, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, no usage block
        raise UsageError(message)


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
    keys = [args.key] if args.key else list(rels)
    for key in keys:
        rel = symbolic.relation(key)
        number = f" {rel.equation}" if rel.equation else ""
        print(f"# {rel.key}{number}: {rel.title}")
        print(rel.latex() if args.latex else rel.pretty())
        print()


def _command_phase_diagram(args: argparse.Namespace) -> None:
    params, provenance = _parameters(args)
    stem = f"phase_diagram_{args.scenario}"
    for outcome in write_phase_diagram(params, args.scenario, Path(args.out), stem, attrs=provenance):
        print(outcome.path)


def _command_simulate(args: argparse.Namespace) -> None:
    params, provenance = _parameters(args)
    # the options of the discrete method are passed only when given, so that simulate() rejects them
    # with the continuum method exactly as it does in Python
    options = {name: getattr(args, name) for name in ("dx", "dt", "n_steps") if getattr(args, name) is not None}
    dataset = simulate(params, args.scenario, alpha=args.alpha, method=args.method, **options)
    dataset.attrs.update(provenance)
    stem = f"simulation_{args.scenario.replace('+', 'plus')}_{args.method}"
    for outcome in write_simulation(dataset, Path(args.out), stem):
        print(outcome.path)


def _command_run(args: argparse.Namespace) -> None:
    for outcome in run_study(load_study(args.study), progress=_progress):
        print(outcome.path)


def _command_reproduce(args: argparse.Namespace) -> None:
    reproduce(Path(args.out), progress=_progress, keep_agreeing=not args.rewrite)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="mdr-events", description=DESCRIPTION)
    parser.add_argument("--version", action="version", version=f"mdr_events {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    derive = commands.add_parser("derive", help="print every relation derived by SymPy")
    derive.add_argument("--latex", action="store_true", help="LaTeX instead of pretty printing")
    derive.add_argument("--key", default=None, help="only this relation (e.g. jkr_depth)")
    derive.set_defaults(run=_command_derive)

    phase = commands.add_parser("phase-diagram", help="write the phase diagram (Fig. 9a/9b) as .nc and .png")
    phase.add_argument("--scenario", choices=["A", "B"], required=True)
    phase.add_argument("--out", required=True, help="output directory")
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
    _parameter_options(sim)
    sim.set_defaults(run=_command_simulate)

    run = commands.add_parser("run", help="run a study described in a TOML file (see mdr_events.app.study)")
    run.add_argument("study", help="the study file, e.g. study.toml")
    run.set_defaults(run=_command_run)

    reproduce = commands.add_parser("reproduce", help="regenerate results/ (figures, datasets, report)")
    reproduce.add_argument("--out", default="results", help="output directory (default results)")
    reproduce.add_argument("--rewrite", action="store_true",
                           help="rewrite every file, also those that agree with a fresh computation")
    reproduce.set_defaults(run=_command_reproduce)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``mdr-events``; returns the exit status."""
    try:
        args = build_parser().parse_args(argv)
        if getattr(args, "key", None):
            symbolic.relation(args.key)
        matplotlib.use("Agg")  # the CLI writes figures to files only: no window, whatever the user's default
        args.run(args)
    except UsageError as error:
        print(f"mdr-events: error: {error}", file=sys.stderr)
        return 2
    except (ValueError, TypeError, KeyError) as error:
        message = str(error.args[0]) if isinstance(error, KeyError) and error.args else str(error)
        print(f"mdr-events: error: {message}".splitlines()[0], file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
