"""``mdr-events run``: a study described in a TOML file (:mod:`mdr_events.app.study`)."""

from __future__ import annotations

import argparse


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``run``; its argument is added when it is used (:func:`fill`)."""
    commands.add_parser("run", help="run a study described in a TOML file (see mdr_events.app.study)", fill=fill)


def fill(run_: argparse.ArgumentParser) -> None:
    """Add the argument of ``run``."""
    run_.add_argument("study", help="the study file, e.g. study.toml")
    run_.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    """Run every job of the study; print the files written and which runs failed; exit 1 if one did."""
    from mdr_events.app.cli import progress
    from mdr_events.analysis.reports import Verdict
    from mdr_events.app.study import load_study, run_study

    outcomes = run_study(load_study(args.study), progress=progress)
    for outcome in outcomes:
        print(outcome.path)
    failed = [run for run, verdict in getattr(outcomes, "verdicts", {}).items() if verdict is not Verdict.PASS]
    if failed:
        print(f"{'validation ' if all(not run.startswith('fit ') for run in failed) else ''}failed: {', '.join(failed)}")
    return 1 if failed else 0
