"""Parameter sweeps: many runs of the model, their scalar quantities as one labelled Dataset: :func:`sweep`.

``sweep(grid, contact, motion, alpha, method)`` runs a :class:`~mdr_events.Contact` along a motion with a method at
every point of a grid (the outer product of values per name, or a table of sets) of the contact's values (dotted or
short names), the motion's angle, depth and speed, and the discrete spacing (:mod:`~mdr_events.analysis.sweep_grid`).
The runs are cut into chunks; each chunk is one task (:func:`~mdr_events.analysis.sweep_runs.run_chunk`) on an
:class:`~mdr_events.analysis.executors.Engine`: serially here, on a ``dask.distributed`` cluster, a client or any
executor. The same function computes every run either way, so the numbers are identical.

What a sweep keeps is a :class:`SweepOutput`: the quantities, each run's history, and a ``store`` (a Zarr directory,
:mod:`~mdr_events.analysis.sweep_store`) written chunk by chunk as runs complete. A sweep interrupted for any reason
resumes where it stopped: the chunks the store marks done are read back, not run again. A run that raises is recorded
(``failed``, ``error``) and does not stop the sweep.

A contact on a layer of finite thickness (``Contact.layer``), or a grid over its thickness ``h`` (``inf``: the
half-space), runs where the method takes a layer (the discrete method, as :func:`~mdr_events.simulate`) or where only
the closed-form quantities are asked (:data:`CLOSED_FORM_QUANTITIES`: :func:`~mdr_events.critical_angle` of each run's
contact); the result stamps the layer as a discrete run does.

The keywords of before, ``sweep(grid, "A", 20, base=params, method=..., dx=..., scheduler=..., store=...,
profile=..., friction=...)``, are read by :func:`sweep_job`, the one place that converts them; either form gives the
same numbers.
"""

from __future__ import annotations

import concurrent.futures
import dataclasses
import json
import math
import os
from dataclasses import dataclass
from typing import Any, Mapping, NamedTuple, Sequence

import numpy as np
import xarray as xr

from mdr_events.analysis.executors import DEFAULT_CHUNK, Engine
from mdr_events.analysis.sweep_grid import (BYTES_PER_STORED_VALUE, TABLE_DIMENSION, Grid, check_runs, make_grid,
                                            name_unit, swept_names, sweeps_thickness)
from mdr_events.analysis.sweep_runs import (CLOSED_FORM_QUANTITIES, DISCRETE_STEP_PER_SPACING, HISTORY_QUANTITIES,
                                            QUANTITIES, ChunkResult, SweepSpec, run_chunk)
from mdr_events.analysis.sweep_store import Store, run_variables, store_bytes
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.io.paths import ALLOWED_PATH, check_file_path
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.models import indenters
from mdr_events.contact.friction import friction_attrs
from mdr_events.models.continuum.tolerances import EVALUATION_BYTES_PER_SAMPLE
from mdr_events.models.methods import DEFAULT_STEPS, Continuum, Discrete, Method, as_method
from mdr_events.models.motion import FIGURE_ANGLES, Motion, Paths, Scenario
from mdr_events.models.job import ModelJob
from mdr_events.models.simulate import model_job
from mdr_events.parameters import Parameters
from mdr_events.validation import check_choice, check_count, check_flag, check_real, shown

__all__ = ["sweep", "sweep_job", "SweepJob", "SweepOutput", "Engine", "run_chunk", "SweepSpec", "QUANTITIES",
           "CLOSED_FORM_QUANTITIES", "HISTORY_QUANTITIES", "SWEEP_CONTENT", "TABLE_DIMENSION", "ChunkResult",
           "DEFAULT_CHUNK", "DISCRETE_STEP_PER_SPACING", "DEFAULT_METHOD", "simulate_steps_unless_given"]

#: The ``content`` attribute of a sweep's dataset.
SWEEP_CONTENT = "parameter sweep"
#: The keywords that make an :class:`Engine` and a :class:`SweepOutput` when given one by one.
ENGINE_OPTIONS = ("scheduler", "workers", "chunk_size", "progress")
OUTPUT_OPTIONS = ("quantities", "history_samples", "store", "resume")
#: The method of a sweep unless given: the exact continuum.
DEFAULT_METHOD = "continuum"
#: What an angle of a sweep may be (as the grid's angles).
ANGLE_ALLOWED = "an angle in (0, 90] degrees whose tangent is a number"


@dataclass(frozen=True)
class SweepOutput:
    """What a sweep keeps of each run, and where it writes as it goes.

    Parameters
    ----------
    quantities : sequence of str, optional
        Which of :data:`QUANTITIES` (default all); only closed-form ones (:data:`CLOSED_FORM_QUANTITIES`) run no
        model.
    history_samples : int, optional
        Also keep each run's F_N, F_x and A (:data:`HISTORY_QUANTITIES`) at this many times spread evenly over its
        path (``history_<q>`` along a ``sample`` dimension; the continuum's by the rule of
        :func:`mdr_events.analysis.fit.model_curves`: 0 out of the elastomer).
    store : path, optional
        A Zarr directory written chunk by chunk as runs complete; with ``resume`` (default) a store of this same
        sweep is continued: its done chunks are read, not run again.
    resume : bool, default True
        Continue a store of this sweep (``False``: start it afresh).

    Raises
    ------
    TypeError
        ``quantities`` given as one string.
    ValueError
        An unknown or repeated quantity, none, or ``history_samples`` < 2.
    """

    quantities: tuple[str, ...] | None = None
    history_samples: int | None = None
    store: str | os.PathLike | None = None
    resume: bool = True

    def __post_init__(self) -> None:
        quantities = self.quantities
        if isinstance(quantities, str):  # (a name alone would be read letter by letter)
            raise TypeError(f"quantities={quantities!r} (str) is not allowed; allowed: a sequence of names, e.g. "
                            f"({quantities!r},)")
        wanted = tuple(QUANTITIES) if quantities is None else tuple(quantities)
        wanted = tuple(check_choice("quantities", name, QUANTITIES) for name in wanted)
        if not wanted or len(set(wanted)) != len(wanted):
            raise ValueError(f"quantities={shown(quantities)} is not allowed; allowed: distinct names from "
                             f"{', '.join(QUANTITIES)}")
        object.__setattr__(self, "quantities", wanted)
        if self.history_samples is not None:
            object.__setattr__(self, "history_samples", check_count("history_samples", self.history_samples, 2))
        check_flag("resume", self.resume)
        if self.store is not None:  # (an array or bytes reached os.fspath only when the sweep ran: a raw TypeError)
            check_file_path("store", self.store, f"None or {ALLOWED_PATH} naming a Zarr directory")


class SweepJob(NamedTuple):
    """What a sweep runs: the runs (:class:`SweepSpec`) over the grid, the model as given (its attributes are the
    result's), where the runs go and what is kept."""

    spec: SweepSpec
    grid: Grid
    model: ModelJob
    engine: Engine
    output: SweepOutput


# ------------------------------------------------------------------------------------------------------------
# the one conversion of what sweep is given
def _before(contact, motion, alpha, method, options: dict[str, Any], grid) -> tuple:
    """The keywords of before, ``sweep(grid, scenario, alpha, *, base=params, ...)``, as (contact, motion, alpha):
    the discrete model's time step without ``dx`` or ``n_steps`` is :func:`~mdr_events.simulate`'s default, as it
    was."""
    base = options.pop("base")
    if not isinstance(base, Parameters):
        raise TypeError(f"base={shown(base)} ({type(base).__name__}) is not allowed; allowed: a Parameters")
    if "scenario" in options and contact is not None:
        raise ValueError("scenario is given twice (second and by keyword); allowed: one")
    scenario = options.pop("scenario", "A" if contact is None else contact)
    if motion is not None and alpha is not None:
        raise ValueError(f"alpha is given twice ({motion!r} third and alpha={shown(alpha)}); allowed: one")
    simulate_steps_unless_given(method, options, grid)
    return base, scenario, alpha if motion is None else motion


def simulate_steps_unless_given(method, options: dict[str, Any], grid) -> None:
    """The keywords of before and study files: the discrete model without ``dx``, ``dt`` or ``n_steps`` (in
    ``options`` or, ``dx``, in the ``grid``) takes :func:`~mdr_events.simulate`'s :data:`DEFAULT_STEPS`, put into
    ``options`` (the sweep's own default is :data:`DISCRETE_STEP_PER_SPACING`)."""
    if method == "discrete" and "dx" not in _grid_names(grid) and all(options.get(name) is None for name in
                                                                ("dx", "dt", "n_steps")):
        options["n_steps"] = DEFAULT_STEPS


def _parts(options: dict[str, Any], names: Sequence[str], given, kind: type, label: str):
    """``given`` (an Engine or SweepOutput) or the one made of its keywords in ``options``, not both."""
    loose = {name: options.pop(name) for name in names if name in options}
    if given is None:
        return kind(**loose)
    if loose:
        raise ValueError(f"{', '.join(loose)} is not allowed beside {label}={given!r}; allowed: one of them")
    if not isinstance(given, kind):
        raise TypeError(f"{label}={shown(given)} ({type(given).__name__}) is not allowed; allowed: a {kind.__name__}")
    return given


def _one_run_motion(motion: Motion, alpha, grid_names: Sequence[str]) -> Motion:
    """The motion every run starts from: a scenario of one angle (any, if the grid sweeps ``alpha``) or one path."""
    if isinstance(motion, Paths):
        if alpha is not None or "alpha" in grid_names:
            raise ValueError("alpha is not allowed with a Path (its waypoints fix the motion)")
        if len(motion.paths) != 1:
            raise ValueError(f"motion={motion!r} is not allowed; allowed: one path (a sweep runs one path per run)")
        return motion
    if "alpha" in grid_names:
        if alpha is not None or motion.alpha != FIGURE_ANGLES:  # (the grid's angles would silently win)
            raise ValueError(f"alpha={alpha if alpha is not None else motion.alpha!r} is not allowed with 'alpha' in "
                             "the grid; allowed: one of them")
        return dataclasses.replace(motion, alpha=(FIGURE_ANGLES[0],))  # (each run puts its angle in)
    if len(motion.alpha) != 1:
        raise ValueError(f"scenario={motion.name!r} needs an angle; allowed: alpha=DEG (one angle) or 'alpha' in the "
                         "grid")
    return motion


def _grid_names(grid) -> tuple[str, ...]:
    rows = [grid] if isinstance(grid, Mapping) else grid if isinstance(grid, Sequence) and grid else []
    return tuple(str(name) for name in (rows[0] if rows and isinstance(rows[0], Mapping) else ()))


def sweep_job(grid, contact, motion, alpha, method, options: Mapping[str, Any]) -> SweepJob:
    """The job of ``sweep(grid, contact, motion, alpha, method, **options)``, ``options`` holding ``output``,
    ``engine`` and ``limits`` (each may be absent); the keywords of before (``base=``, ``scenario=``, ``profile=``,
    ``friction=``, the engine's and the output's one by one) are converted here and nowhere else. Every value is
    checked; nothing runs."""
    options, grid_names = dict(options), _grid_names(grid)
    output, engine = options.pop("output", None), options.pop("engine", None)
    limits = options.pop("limits", DEFAULT_LIMITS)
    if "base" in options:
        contact, motion, alpha = _before(contact, motion, alpha, method, options, grid)
    limits = check_limits(limits)
    engine = _parts(options, ENGINE_OPTIONS, engine, Engine, "engine")
    output = _parts(options, OUTPUT_OPTIONS, output, SweepOutput, "output")
    if alpha is not None:
        alpha = check_real("alpha", alpha, ANGLE_ALLOWED,
                           lambda value: 0 < value <= 90 and math.tan(math.radians(value)) > 0)
    model = model_job(contact, "A" if motion is None else motion, alpha, options)
    the_method = as_method(DEFAULT_METHOD if method is None else method, options)
    if isinstance(the_method, Continuum) and the_method.t is not None:
        raise ValueError("t is not allowed in a sweep; allowed: history_samples (times spread over each run's path)")
    if "dx" in grid_names and not isinstance(the_method, Discrete):
        raise ValueError(f"grid: 'dx' is not allowed with method={the_method.name!r}; allowed: with "
                         "method='discrete'")
    start = _one_run_motion(model.motion, alpha, grid_names)
    the_grid = make_grid(grid, swept_names(model.contact, model.motion, the_method), limits, model.contact)
    spec = SweepSpec(model.contact, start, the_method, the_grid.names, output.quantities, output.history_samples,
                     limits)
    check_runs(spec, the_grid)
    return SweepJob(spec, the_grid, model._replace(motion=start), engine, output)


# ------------------------------------------------------------------------------------------------------------
# the sweep
def sweep(grid, contact=None, motion=None, alpha: float | None = None, method: str | Method | None = None, *,
          output: SweepOutput | None = None, engine: Engine | None = None, limits: Limits = DEFAULT_LIMITS,
          **options: Any) -> xr.Dataset:
    """Run the model over a grid of values and return each run's scalar quantities.

    Parameters
    ----------
    grid : mapping or sequence of mappings
        Name → values: the outer product, one dimension per name (in the mapping's order). Or a list of mappings
        (each a set, the same names): along the dimension ``set``. Names: any value of the contact, dotted or short
        (``"friction.mu"``, ``"tau0"``, ``"E"``, ``"h"``, :meth:`Contact.names <mdr_events.Contact.names>`),
        ``alpha`` (a scenario's angle, degrees), ``d_max`` and ``v`` (the motion's depth and speed) and ``dx`` (the
        discrete spacing, m). The layer's thickness ``h`` (``layer.thickness``, m) may hold ``inf``, the
        half-space; its base (``layer.base``), a choice, is the contact's.
    contact : Contact or Parameters
        The model of every run before the grid's values are put in (a :class:`~mdr_events.Parameters` with
        ``profile=`` and ``friction=`` as in :func:`~mdr_events.simulate`). On a layer of finite thickness (or with
        ``h`` in the grid) the runs take the layer with the discrete method, or with any method where only the
        closed-form quantities are asked (:data:`CLOSED_FORM_QUANTITIES`); else the sweep is refused.
    motion : Scenario, {"A", "B", "B+"}, Path or Paths
        The motion of every run: a scenario of one angle (or any, with ``alpha`` in the grid), rebuilt per run at
        its values; or one path. Default ``"A"``.
    alpha : float, optional
        With a scenario's name: its angle when the grid does not sweep it.
    method : {"continuum", "discrete"}, Continuum or Discrete
        The continuum's quantities are exact (extrema and event log); the discrete model's are read off its samples
        (:mod:`~mdr_events.analysis.sweep_runs`; a :class:`~mdr_events.Discrete` without ``dt`` or ``n_steps`` takes
        :data:`DISCRETE_STEP_PER_SPACING` spacings of travel per step). By name, its options are given beside it.
        Default the continuum.
    output : SweepOutput, optional
        The quantities, histories and store (:class:`SweepOutput`; or its fields given one by one).
    engine : Engine, optional
        Where the chunks run and who hears of their progress (:class:`~mdr_events.analysis.executors.Engine`: a
        scheduler, its workers, the runs per chunk; or its fields given one by one). Every engine gives the same
        numbers.
    limits : Limits
        What each run may use (a run past a limit is recorded as failed, with the estimate); the sweep's own memory
        (the grid, the quantities, histories and a store's set-up) is checked against ``memory`` before anything runs.
    **options
        The method's options; the fields of ``output`` and ``engine`` one by one; and the keywords of before
        (``sweep(grid, scenario, alpha, base=params, profile=..., friction=...)``), read by :func:`sweep_job`.

    Returns
    -------
    xarray.Dataset
        One dimension per swept name (or ``set``), with the swept values as coordinates; the quantities of
        :data:`QUANTITIES`, ``failed`` and ``error`` (a run that raised, and why). On a layer (or over ``h``) the
        attributes ``param_layer_thickness`` (the contact's, before the grid's values) and ``param_layer_base``.

    Raises
    ------
    ValueError, TypeError
        Before anything runs, naming the argument: an unknown name, an empty or non-finite grid, a value the contact
        refuses, a scenario without an angle, a store of another sweep, a layer of finite thickness the method does
        not take (beyond the closed-form quantities) or the layer's closed forms refuse.
    """
    limits = check_limits(limits)
    job = sweep_job(grid, contact, motion, alpha, method, dict(options, output=output, engine=engine, limits=limits))
    spec, runs = job.spec, len(job.grid.rows)
    samples = spec.history_samples
    has_store = job.output.store is not None  # (its set-up counted too: X4, 4.6 GB held under a 2 GiB limit)
    limits.check(f"the sweep of {runs} runs" + ("" if samples is None else f" with history_samples={samples}")
                 + (" with a store" if has_store else ""), memory=_sweep_bytes(job, runs),
                 **({} if samples is None else {"samples": runs * samples}))
    runs_done = _Runs.empty(spec, runs)
    chunk = min(job.engine.chunk_size, runs)  # (a store's chunk of chunk_size=1e11 allocated 745 GiB for 2 runs)
    store = None if job.output.store is None else Store(job.output.store, _signature(job), spec.quantities, runs,
                                                        chunk, job.output.resume, samples)
    pending = [(start, min(start + chunk, runs)) for start in range(0, runs, chunk)]
    try:
        if store is not None and store.done() is not None:
            pending = runs_done.restore(store, pending)
        if pending:  # (a store that holds every run starts no engine)
            _run_chunks(job, pending, runs_done, store)
    finally:
        if store is not None:
            store.close()
    return _result(job, runs_done)


def _sweep_bytes(job: SweepJob, runs: int) -> int:
    """The memory a sweep holds at once: its quantities and histories (:data:`BYTES_PER_STORED_VALUE` a value), a
    store's set-up, and a continuum run's evaluation at its history's times beside them
    (:data:`~mdr_events.models.continuum.tolerances.EVALUATION_BYTES_PER_SAMPLE`: measured with tracemalloc, one run
    of 1e5 history samples peaked at 390 B a sample where 96 B were counted; 4.1 times, issue 32 round 30)."""
    spec, samples = job.spec, job.spec.history_samples
    stored = runs * (len(spec.quantities) + (0 if samples is None else len(HISTORY_QUANTITIES) * samples))
    evaluated = EVALUATION_BYTES_PER_SAMPLE * samples if samples and isinstance(spec.method, Continuum) else 0
    has_store = job.output.store is not None
    return BYTES_PER_STORED_VALUE * stored + evaluated + (store_bytes(runs, len(job.grid.names)) if has_store else 0)


@dataclass
class _Runs:
    """The runs' values, errors and histories as chunks complete, and how many are done."""

    values: np.ndarray
    errors: list[str]
    histories: np.ndarray | None
    finished: int = 0

    @classmethod
    def empty(cls, spec: SweepSpec, runs: int) -> "_Runs":
        return cls(np.full((runs, len(spec.quantities)), np.nan), [""] * runs,
                   None if spec.history_samples is None else
                   np.full((runs, len(HISTORY_QUANTITIES), spec.history_samples), np.nan))

    def restore(self, store: Store, pending: list[tuple[int, int]]) -> list[tuple[int, int]]:
        """Read back the runs a store holds; the chunks still to run."""
        done, previous = store.done(), store.existing
        self.values[done] = np.column_stack([previous[name].values for name in store.quantities])[done]
        if self.histories is not None:
            self.histories[done] = np.stack([previous[f"history_{name}"].values for name in HISTORY_QUANTITIES],
                                            axis=1)[done]
        for index in np.flatnonzero(done):
            self.errors[index] = str(previous["error"].values[index])
        pending = [(a, b) for a, b in pending if not np.all(done[a:b])]
        self.finished = len(self.errors) - sum(b - a for a, b in pending)
        return pending

    def record(self, start: int, result: ChunkResult) -> None:
        stop = start + len(result.errors)
        self.values[start:stop] = result.values
        self.errors[start:stop] = result.errors
        if self.histories is not None:
            self.histories[start:stop] = result.histories
        self.finished += len(result.errors)


def _run_chunks(job: SweepJob, pending: list[tuple[int, int]], runs: _Runs, store: Store | None) -> None:
    """Run the pending chunks on the job's engine, recording each here (and in the store) as it completes; on an
    error, Ctrl-C or a ``progress`` that raises, nothing more runs."""
    engine = job.engine
    with engine.open() as executor:
        try:
            futures = {executor.submit(run_chunk, job.spec, job.grid.rows[start:stop]): start
                       for start, stop in pending}
        except Exception as error:  # noqa: BLE001 - an executor shut down, a client closed: it takes no tasks
            raise ValueError(f"scheduler={shown(engine.scheduler)} takes no tasks ({error}); allowed: a running "
                             "executor or client") from None
        try:
            for future in concurrent.futures.as_completed(futures):
                result = future.result()
                runs.record(futures[future], result)
                if store is not None:
                    store.write(futures[future], result)
                if engine.progress is not None:
                    engine.progress(runs.finished, len(runs.errors))
        finally:
            for future in futures:
                future.cancel()


def _signature(job: SweepJob) -> str:
    """What makes a store this sweep's: resuming another sweep's store is refused."""
    spec, model, method = job.spec, job.model, job.spec.method
    scenario = spec.motion.name if isinstance(spec.motion, Scenario) else next(iter(spec.motion.paths.values())
                                                                               ).describe()
    alpha = spec.motion.alpha[0] if isinstance(spec.motion, Scenario) and "alpha" not in job.grid.names else None
    profile = model.profile
    return json.dumps({"base": model.params.as_dict(), "scenario": scenario, "alpha": alpha, "method": method.name,
                       "dx": getattr(method, "dx", None), "n_steps": getattr(method, "n_steps", None),
                       "dt": getattr(method, "dt", None),
                       "tolerances": dataclasses.asdict(getattr(method, "tolerances", Continuum().tolerances)),
                       "names": job.grid.names, "rows": job.grid.rows.tolist(), "quantities": spec.quantities,
                       "history_samples": spec.history_samples,
                       **({} if profile is None else {"profile": profile.to_attrs()}),  # (a table's points too)
                       **({} if model.friction.is_default else {"friction": [model.friction.law, model.friction.mu]}),
                       **_layer_attrs(job)},  # (the half-space's signature as before layers: its stores resume)
                      sort_keys=True)


def _layer_attrs(job: SweepJob) -> dict[str, Any]:
    """The layer's attributes (:meth:`Layer.to_attrs <mdr_events.contact.layer.Layer.to_attrs>`, as a discrete run
    stamps them) where the sweep's contact is on a layer of finite thickness or its grid sweeps the thickness (then
    the contact's before the grid's values are put in, as every swept value); none on the half-space."""
    layer = job.model.contact.layer
    return layer.to_attrs() if sweeps_thickness(job.grid.names) or not layer.is_half_space else {}


def _result(job: SweepJob, runs: _Runs) -> xr.Dataset:
    spec, grid, model = job.spec, job.grid, job.model
    dims = (TABLE_DIMENSION,) if grid.table else grid.names
    data = run_variables(spec.quantities, runs.values, runs.errors, runs.histories, dims, grid.shape)
    coords = {name: ((TABLE_DIMENSION,) if grid.table else (name,), grid.coords[name],
                     {"units": name_unit(model.contact, name), "long_name": f"swept {name}"}) for name in grid.names}
    scenario = spec.motion.name if isinstance(spec.motion, Scenario) else "custom path"
    attrs = dict(content=SWEEP_CONTENT, scenario=scenario, method=spec.method.name, swept=", ".join(grid.names),
                 runs=int(len(runs.errors)), failed_runs=int(data["failed"][1].sum()))
    if isinstance(spec.motion, Scenario) and "alpha" not in grid.names:
        attrs["alpha"] = spec.motion.alpha[0]
    if isinstance(spec.motion, Paths):
        attrs["path_waypoints"] = next(iter(spec.motion.paths.values())).describe()
    return stamp(xr.Dataset(data, coords=coords), model.params, **attrs, **indenters.profile_attrs(model.profile),
                 **friction_attrs(model.friction), **_layer_attrs(job))


register_schema(SWEEP_CONTENT, {"failed": None, "error": None})
