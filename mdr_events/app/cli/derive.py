"""``mdr-events derive``: print every relation SymPy derives, pretty or LaTeX."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from mdr_events.app.jobs import DeriveJob


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``derive``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser("derive", help="print every relation derived by SymPy", fill=fill)


def fill(derive: argparse.ArgumentParser) -> None:
    """Add the options of ``derive`` (it draws no figure: the CLI leaves matplotlib unloaded)."""
    derive.add_argument("--latex", action="store_true", help="LaTeX instead of pretty printing")
    derive.add_argument("--key", default=None, help="only this relation (e.g. jkr_depth)")
    derive.set_defaults(run=run, figures=False)


def job(args: argparse.Namespace) -> DeriveJob:
    """The relations the options ask for."""
    from mdr_events.app.jobs import DeriveJob

    return DeriveJob(args.latex, args.key)


def run(args: argparse.Namespace) -> None:
    """Print the relations."""
    job(args).run()
