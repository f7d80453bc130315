"""``mdr-events sweep``: the ``[sweep]`` table of a study file on dask (a local cluster, or ``--scheduler ADDRESS``);
``--h`` and ``--layer-base`` put the elastomer on a layer, as for ``simulate``, over the study's ``[layer]``."""

from __future__ import annotations

import argparse
import dataclasses
from typing import TYPE_CHECKING

from mdr_events.app.cli import _options
from mdr_events.app.cli._options import UsageError

if TYPE_CHECKING:
    from mdr_events.app.study import Study
    from mdr_events.contact.layer import Layer


def add_arguments(commands: argparse._SubParsersAction) -> None:
    """Add ``sweep``; its options are added when it is used (:func:`fill`)."""
    commands.add_parser(
        "sweep", help="run the [sweep] table of a study file on dask (a local cluster, or --scheduler ADDRESS)",
        fill=fill,
        description="Run a parameter sweep described by the [sweep] table of a study file (mdr_events.sweep): "
                    "<name>_sweep.zarr is written chunk by chunk (--resume continues an interrupted one) and "
                    "<name>_sweep.nc holds the labelled result.")


def fill(sweeping: argparse.ArgumentParser) -> None:
    """Add the options of ``sweep``."""
    sweeping.add_argument("study", help="the study file, e.g. study.toml")
    sweeping.add_argument("--scheduler", default=None, metavar="ADDRESS",
                          help="'local' (a LocalCluster on this machine, the default), 'serial', or a running dask "
                               "scheduler's address such as tcp://host:8786")
    sweeping.add_argument("--workers", type=int, default=None, metavar="N",
                          help="worker processes of the local cluster (default: the machine's cores)")
    store = sweeping.add_mutually_exclusive_group()
    store.add_argument("--resume", action="store_true",
                       help="continue the store of an interrupted sweep (its done chunks are not run again)")
    store.add_argument("--restart", action="store_true",
                       help="start afresh, replacing the store of an earlier sweep (without --resume or --restart an "
                            "existing store is an error)")
    _options.layer_options(sweeping)
    sweeping.set_defaults(run=run)


def _layer_over(args: argparse.Namespace, study: Study) -> Layer | None:
    """The layer of ``--h`` and ``--layer-base`` over the study's ``[layer]`` (each option replaces its own field;
    ``None`` without them), checked against the sweep's method and quantities (the discrete method, or the
    closed-form quantities alone) in one line naming the option."""
    from mdr_events.analysis.sweep_runs import check_layer_run
    from mdr_events.app import inputs

    if args.h is None and args.layer_base is None:
        return None
    job, held = study.sweep, study.contact.layer
    layer = inputs.layer(held.thickness if args.h is None else args.h,
                         held.base.value if args.layer_base is None else args.layer_base)
    try:
        check_layer_run(dataclasses.replace(job.contact, layer=layer), job.motion, job.method, job.output.quantities,
                        job.output.history_samples)
    except (ValueError, TypeError) as error:
        given = " ".join(part for part in (f"--h {_options.shown_number(args.h)}" if args.h is not None else "",
                                           f"--layer-base {args.layer_base}" if args.layer_base else "") if part)
        raise UsageError(f"{given}: {error}") from None
    return layer


def run(args: argparse.Namespace) -> int:
    """Run the study's sweep job with the options' scheduler and workers; print the files written."""
    from mdr_events.analysis.executors import check_scheduler, check_workers
    from mdr_events.app.cli import progress
    from mdr_events.app.study import load_study, run_sweep, sweep_store

    # the options are checked before the files are read: an argument's error before the study's or the store's
    if args.workers is not None and args.workers < 1:
        raise UsageError(f"--workers {args.workers} is not allowed; allowed: an integer >= 1")
    if args.workers is not None:
        check_workers(args.workers)
    check_scheduler(args.scheduler, args.workers)
    _options.layer(args, over_study=True)  # (--h checked before the study is read)
    study = load_study(args.study)
    layer = None if study.sweep is None else _layer_over(args, study)
    store = sweep_store(study)
    if store.exists() and not (args.resume or args.restart):
        raise UsageError(f"{store} holds an earlier sweep; allowed: --resume to continue it (its done chunks are "
                         "kept), --restart to start afresh")
    outcomes = run_sweep(study, progress=progress, scheduler=args.scheduler, workers=args.workers,
                         resume=args.resume, layer=layer)
    for outcome in outcomes:
        print(outcome.path)
    return 0
