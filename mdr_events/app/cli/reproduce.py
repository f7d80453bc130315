"""``mdr-events reproduce``: regenerate ``results/`` (figures, datasets, report)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from mdr_events.app.cli import _options

if TYPE_CHECKING:
    from mdr_events.app.jobs import ReproduceJob


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``reproduce``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser("reproduce", help="regenerate results/ (figures, datasets, report)", fill=fill)


def fill(reproduce: argparse.ArgumentParser) -> None:
    """Add the options of ``reproduce``."""
    reproduce.add_argument("--out", default="results", help="output directory (default results)")
    reproduce.add_argument("--rewrite", action="store_true",
                           help="rewrite every file, also those that agree with a fresh computation")
    reproduce.set_defaults(run=run)


def job(args: argparse.Namespace) -> ReproduceJob:
    """The reproduction the options ask for."""
    from mdr_events.app.jobs import ReproduceJob

    return ReproduceJob(args.rewrite)


def run(args: argparse.Namespace) -> None:
    """Recompute and write ``results/``, saying what happens on stderr."""
    from mdr_events.app.cli import progress

    job(args).run(_options.output_directory(args), progress)
