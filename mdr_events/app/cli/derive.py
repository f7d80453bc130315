"""``mdr-events derive``: print every relation SymPy derives, pretty or LaTeX."""

from __future__ import annotations

import argparse

from mdr_events.app.jobs import DeriveJob


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``derive`` and its options."""
    derive = commands.add_parser("derive", help="print every relation derived by SymPy")
    derive.add_argument("--latex", action="store_true", help="LaTeX instead of pretty printing")
    derive.add_argument("--key", default=None, help="only this relation (e.g. jkr_depth)")
    derive.set_defaults(run=run)


def job(args: argparse.Namespace) -> DeriveJob:
    """The relations the options ask for."""
    return DeriveJob(args.latex, args.key)


def run(args: argparse.Namespace) -> None:
    """Print the relations."""
    job(args).run()
