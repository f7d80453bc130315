"""Parameter sweeps: many runs of the model, their scalar quantities as one labelled Dataset: :func:`sweep`.

A grid (the outer product of values per name, or a table of parameter sets) is cut into chunks of runs.
Each chunk is one task (:func:`run_chunk`, a plain function of picklable arguments): run serially here,
or on ``dask.distributed`` — a ``LocalCluster`` sized to the machine by default, any dask cluster by its
scheduler's address. The same function computes every run either way, so the numbers are identical.

With a ``store`` (a Zarr directory) every chunk is written as it completes, into its region of a store laid
out before the first run (:func:`~xarray.Dataset.to_zarr` with ``region``). A sweep interrupted for any
reason resumes where it stopped: the chunks the store marks done are read back, not run again. A run that
raises is recorded (``failed``, ``error``) and does not stop the sweep.

The quantities of a run (:data:`QUANTITIES`) are exact for the continuum method (the solution's extrema and
event log, :mod:`mdr_events.models.continuum`); for the discrete method they are read off its samples by the
rules of :mod:`mdr_events.analysis.validate` (first sample sliding, first sample out of contact, ...).
"""

from __future__ import annotations

import concurrent.futures
import dataclasses
import json
import math
import os
from dataclasses import dataclass
from typing import Callable, Mapping, NamedTuple, Sequence

import numpy as np
import xarray as xr

from mdr_events.analysis.executors import check_scheduler, check_workers, open_executor
from mdr_events.analysis.fit import curves_of
from mdr_events.analysis.validate import candidate_events
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.io.files import check_output_file, prepare_output_directory
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.models.continuum import EventKind, Tolerances, extremum, solve_path, tangential_work
from mdr_events.models.continuum.solution import scan_spans
from mdr_events.models import indenters
from mdr_events.contact.friction import TAU0, FrictionLaw, as_friction_law, friction_attrs
from mdr_events.contact.indenters import TabulatedProfile
from mdr_events.models.continuum.caps import check_supported
from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile
from mdr_events.models.paths import Path
from mdr_events.models.methods import METHODS
from mdr_events.models.motion import SCENARIO_NAMES, scenario_paths
from mdr_events.models.simulate import simulate
from mdr_events.parameters import PARAMETER_UNITS, Parameters
from mdr_events.theory.scales import check_representable
from mdr_events.validation import check_choice, check_count, check_flag, check_real, real_array, shown

__all__ = ["sweep", "run_chunk", "SweepSpec", "QUANTITIES", "CLOSED_FORM_QUANTITIES", "SWEEP_CONTENT", "SWEPT_NAMES",
           "TABLE_DIMENSION",
           "ChunkResult"]

#: The ``content`` attribute of a sweep's dataset.
SWEEP_CONTENT = "parameter sweep"
#: Names a grid may sweep besides the :class:`Parameters` fields: the path angle and the discrete spacing.
EXTRA_NAMES = {"alpha": "degree", "dx": "m"}
SWEPT_NAMES = tuple(PARAMETER_UNITS) + tuple(EXTRA_NAMES)
#: The dimension of a sweep over a table of parameter sets.
TABLE_DIMENSION = "set"
#: Runs per chunk (one task) by default: enough that the engine's overhead per run is far below a run's cost.
DEFAULT_CHUNK = 50
#: Characters of a failed run's error kept in the result.
ERROR_CHARACTERS = 200

#: Scalar quantities of each run: name -> (unit, long name).
QUANTITIES: dict[str, tuple[str, str]] = {
    "normal_force_min": ("N", "smallest normal force (largest adhesive pull)"),
    "tangential_force_max": ("N", "largest |F_x|"),
    "contact_area_max": ("m2", "largest contact area"),
    "slip_onset_in_time": ("s", "first slip onset before the path's deepest point (s from the path's start)"),
    "slip_onset_in_depth": ("m", "depth at the first slip onset before the path's deepest point"),
    "slip_onset_out_time": ("s", "first slip onset after the path's deepest point (s from the path's start)"),
    "slip_onset_out_depth": ("m", "depth at the first slip onset after the path's deepest point"),
    "full_slip_time": ("s", "first full slip (s from the path's start)"),
    "pull_off_time": ("s", "pull-off (s from the path's start)"),
    "pull_off_depth": ("m", "depth at the pull-off"),
    "pull_off_force": ("N", "normal force at the pull-off"),
    "tangential_work": ("J", "work of the tangential force over the run, ∫ F_x dx: all of it dissipated where the "
                             "run ends out of contact (the springs detach and forget their shift)"),
    "event_count": ("1", "events logged (continuum) / found (discrete)"),
    "critical_angle_A": ("degree", "critical angle of scenario A (eq. 18; closed form)"),
    "critical_angle_B": ("degree", "angle of scenario B above which the contact comes apart before sliding "
                                   "(eq. 21; closed form)"),
}
#: Bytes per value a sweep holds at once: its array, the dataset built from it and the store's chunk (three float64
#: copies), rounded up.
BYTES_PER_STORED_VALUE = 32
#: Quantities of a run's history (``history_samples``), at times spread evenly over its path.
HISTORY_QUANTITIES: dict[str, tuple[str, str]] = {
    "normal_force": ("N", "normal force"), "tangential_force": ("N", "tangential force"),
    "contact_area": ("m2", "contact area")}
#: Quantities of the closed forms alone: a sweep asking only for these runs no model.
CLOSED_FORM_QUANTITIES = ("critical_angle_A", "critical_angle_B")


@dataclass(frozen=True)
class SweepSpec:
    """What every run of a sweep shares (picklable: sent to the workers once per chunk)."""

    base: Parameters
    scenario: str | Path
    alpha: float | None
    method: str
    names: tuple[str, ...]
    tolerances: Tolerances = Tolerances()
    dx: float | None = None
    n_steps: int | None = None
    quantities: tuple[str, ...] = tuple(QUANTITIES)
    history_samples: int | None = None
    limits: Limits = DEFAULT_LIMITS
    #: the indenter (``None``: the paraboloid of ``R``)
    profile: SimulatedProfile = None
    #: the friction law (:mod:`mdr_events.contact.friction`)
    friction: FrictionLaw = TAU0

    def run(self, values: Sequence[float]) -> tuple[dict[str, float], np.ndarray | None]:
        """The :attr:`quantities` of the run at ``values`` (one per swept name), and its history (rows
        :data:`HISTORY_QUANTITIES`, ``history_samples`` columns over the path's duration) if asked for; the model
        runs only if one of them needs it (not for :data:`CLOSED_FORM_QUANTITIES` alone)."""
        settings = dict(zip(self.names, (float(v) for v in values)))
        alpha = settings.pop("alpha", self.alpha)
        dx = settings.pop("dx", self.dx)
        params = self.base.replace(**settings) if settings else self.base
        out, history = {}, None
        if set(self.quantities) - set(CLOSED_FORM_QUANTITIES) or self.history_samples:
            path = self.scenario if isinstance(self.scenario, Path) else \
                scenario_paths(params, self.scenario, [alpha], self.profile)[0][0]
            times = None if not self.history_samples else np.linspace(0.0, path.duration, self.history_samples)
            out, history = (_continuum_quantities(params, path, self.tolerances, self.limits, times, self.profile,
                                                  self.friction)
                            if self.method == "continuum"
                            else _discrete_quantities(params, path, dx, self.n_steps, self.limits, times, self.profile,
                                                      self.friction))
        for scenario in ("A", "B"):
            if f"critical_angle_{scenario}" in self.quantities:
                out[f"critical_angle_{scenario}"] = indenters.critical_angle(params, scenario, self.profile,
                                                                             self.friction)
        return {name: out[name] for name in self.quantities}, history


def _deepest_time(path: Path) -> float:
    return float(path.corner_times[int(np.argmax(path.waypoints[:, 1]))])


def _continuum_quantities(params: Parameters, path: Path, tolerances: Tolerances, limits: Limits,
                          times: np.ndarray | None, profile: SimulatedProfile = None, friction: FrictionLaw = TAU0
                          ) -> tuple[dict[str, float], np.ndarray | None]:
    solution = solve_path(params, path, tolerances, limits, profile, friction)
    scan = scan_spans(solution)  # one scan serves every extremum
    out = {"normal_force_min": extremum(solution, "normal_force", largest=False, scan=scan)[1],
           "tangential_force_max": max(abs(extremum(solution, "tangential_force", largest=True, scan=scan)[1]),
                                       abs(extremum(solution, "tangential_force", largest=False, scan=scan)[1])),
           "contact_area_max": extremum(solution, "contact_area", largest=True, scan=scan)[1],
           "tangential_work": tangential_work(solution), "event_count": float(len(solution.events))}
    deepest = _deepest_time(path)
    first: dict[str, object] = {}
    for event in solution.events:
        kind = event.kind
        if kind is EventKind.SLIP_ONSET:
            first.setdefault("slip_onset_in" if event.time <= deepest else "slip_onset_out", event)
        elif kind is EventKind.FULL_SLIP:
            first.setdefault("full_slip", event)
        elif kind in (EventKind.PULL_OFF, EventKind.CONTACT_ENDS):
            first.setdefault("pull_off", event)
    for key in ("slip_onset_in", "slip_onset_out", "full_slip", "pull_off"):
        event = first.get(key)
        out[f"{key}_time"] = float(event.time) if event else math.nan
        if key != "full_slip":
            out[f"{key}_depth"] = float(event.depth) if event else math.nan
    pull = first.get("pull_off")
    out["pull_off_force"] = float(solution.model.normal_force(pull.depth, pull.radius)) if pull else math.nan
    if times is None:
        return out, None
    curves = curves_of(solution, path, times, tuple(HISTORY_QUANTITIES)).values
    return out, np.array([curves[name] for name in HISTORY_QUANTITIES])


#: The discrete model's time step per spring spacing of travel when no ``n_steps`` is given: the time step is
#: refined with the spacing (both are first order; a fixed step would stop the convergence).
DISCRETE_STEP_PER_SPACING = 0.5


def _discrete_quantities(params: Parameters, path: Path, dx: float | None, n_steps: int | None, limits: Limits,
                         history_times: np.ndarray | None, profile: SimulatedProfile = None,
                         friction: FrictionLaw = TAU0) -> tuple[dict[str, float], np.ndarray | None]:
    dt = None if n_steps is not None or dx is None else DISCRETE_STEP_PER_SPACING * dx / path.speed
    run = simulate(params, path, method="discrete", dx=dx, dt=dt, n_steps=n_steps, limits=limits,
                   profile=profile, friction=friction).isel(case=0)
    times = run["time"].values
    quantities = {name: run[name].values for name in ("normal_force", "tangential_force", "contact_area",
                                                      "sliding_fraction")}
    contact = np.nan_to_num(quantities["contact_area"]) > 0
    found = candidate_events(times, quantities, contact, params)
    start = path.first_contact_time()
    depth = run["indentation_depth"].values
    deepest = _deepest_time(path)
    slides = np.nan_to_num(quantities["sliding_fraction"]) > 0
    sliding = np.flatnonzero(slides & ~np.concatenate([[False], slides[:-1]]))  # onsets: sliding, not before
    path_times = times + start
    onset_in = sliding[path_times[sliding] <= deepest]
    onset_out = sliding[path_times[sliding] > deepest]
    lost = found["last_in_contact"] + 1 if found["last_in_contact"] >= 0 else -1
    x = run["tangential_displacement"].values
    finite = np.isfinite(quantities["tangential_force"]) & np.isfinite(x)
    history = None if history_times is None else np.array(
        [np.interp(history_times, path_times, np.nan_to_num(run[name].values), left=0.0, right=math.nan)
         for name in HISTORY_QUANTITIES])
    return {
        "normal_force_min": float(np.nanmin(quantities["normal_force"])),
        "tangential_force_max": float(np.nanmax(np.abs(quantities["tangential_force"]))),
        "contact_area_max": float(np.nanmax(quantities["contact_area"])),
        "slip_onset_in_time": float(path_times[onset_in[0]]) if onset_in.size else math.nan,
        "slip_onset_in_depth": float(depth[onset_in[0]]) if onset_in.size else math.nan,
        "slip_onset_out_time": float(path_times[onset_out[0]]) if onset_out.size else math.nan,
        "slip_onset_out_depth": float(depth[onset_out[0]]) if onset_out.size else math.nan,
        "full_slip_time": found["full_slip"] + start if math.isfinite(found["full_slip"]) else math.nan,
        "pull_off_time": found["pull_off"] + start if math.isfinite(found["pull_off"]) else math.nan,
        "pull_off_depth": float(depth[lost]) if lost >= 0 else math.nan,
        "pull_off_force": found["pull_off_force"],
        "tangential_work": float(np.trapezoid(quantities["tangential_force"][finite], x[finite])),
        "event_count": float(sum(math.isfinite(found[k]) for k in ("slip_onset", "full_slip", "detachment_starts",
                                                                    "pull_off"))),
    }, history


class ChunkResult(NamedTuple):
    """The quantities of a chunk's runs (runs × :data:`QUANTITIES`, ``nan`` where a run failed) and each run's
    error (``""``: it ran)."""

    values: np.ndarray
    errors: list[str]
    histories: np.ndarray | None = None  #: runs × :data:`HISTORY_QUANTITIES` × samples (``history_samples``)


def run_chunk(spec: SweepSpec, rows: np.ndarray) -> ChunkResult:
    """Run every row (the swept names' values) of a chunk; a run that raises is recorded, not raised."""
    values = np.full((len(rows), len(spec.quantities)), np.nan)
    histories = None if not spec.history_samples else \
        np.full((len(rows), len(HISTORY_QUANTITIES), spec.history_samples), np.nan)
    errors = []
    for i, row in enumerate(rows):
        try:
            out, history = spec.run(row)
            values[i] = list(out.values())
            if histories is not None:
                histories[i] = history
            errors.append("")
        except Exception as error:  # noqa: BLE001 - a failed run is a result of the sweep, recorded with its error
            errors.append(f"{type(error).__name__}: {error}"[:ERROR_CHARACTERS])
    return ChunkResult(values, errors, histories)


# ------------------------------------------------------------------------------------------------------------
# the grid
class Grid(NamedTuple):
    """The swept names, their coordinates (outer product) or the table, and every run's values (runs × names)."""

    names: tuple[str, ...]
    coords: dict[str, np.ndarray]  #: per name (outer product), or per name along TABLE_DIMENSION
    rows: np.ndarray
    table: bool

    @property
    def shape(self) -> tuple[int, ...]:
        return (len(self.rows),) if self.table else tuple(len(self.coords[name]) for name in self.names)


def _values(name: str, values) -> np.ndarray:
    if name not in SWEPT_NAMES:
        raise ValueError(f"grid: {name!r} is not allowed; allowed: {', '.join(SWEPT_NAMES)}")
    try:
        array = np.atleast_1d(real_array(f"grid[{name!r}]", values, "real numbers (not bools or strings)"))
    except TypeError as error:
        raise ValueError(str(error)) from None
    if array.ndim != 1 or array.size == 0 or not np.all(np.isfinite(array)):
        raise ValueError(f"grid[{name!r}]={shown(values)} is not allowed; allowed: a non-empty list of finite numbers")
    return array


def _check_size(limits: Limits, runs: int, names: int) -> None:
    """The grid's own array (runs × names) within ``limits``, before it is built."""
    limits.check(f"the grid of {runs} runs", memory=BYTES_PER_STORED_VALUE * runs * names)


def make_grid(grid, limits: Limits | None = None) -> Grid:
    """Check a grid: a mapping name → values (outer product) or a sequence of mappings (a table of sets);
    with ``limits``, its size is checked against them before the outer product is built."""
    if isinstance(grid, Mapping):
        if not grid:
            raise ValueError("grid={} is not allowed; allowed: a mapping of names to values, e.g. {'tau0': [...]}")
        coords = {str(name): _values(str(name), values) for name, values in grid.items()}
        for name, values in coords.items():
            if len(np.unique(values)) != values.size:
                raise ValueError(f"grid[{name!r}] repeats a value; allowed: distinct values")
        if limits is not None:  # before the outer product is built
            _check_size(limits, math.prod(values.size for values in coords.values()), len(coords))
        mesh = np.meshgrid(*coords.values(), indexing="ij")
        return Grid(tuple(coords), coords, np.column_stack([m.ravel() for m in mesh]), table=False)
    if isinstance(grid, Sequence) and not isinstance(grid, str) and grid and all(isinstance(r, Mapping) for r in grid):
        names = tuple(str(name) for name in grid[0])
        for index, row in enumerate(grid):
            if set(map(str, row)) != set(names):
                raise ValueError(f"grid[{index}] names {sorted(map(str, row))}; allowed: the names of grid[0] "
                                 f"({', '.join(sorted(names))}) in every set")
        coords = {name: _values(name, [row[name] for row in grid]) for name in names}
        return Grid(names, coords, np.column_stack(list(coords.values())), table=True)
    raise ValueError(f"grid={shown(grid)} is not allowed; allowed: a non-empty mapping of names to values (outer "
                     "product) or a non-empty list of mappings (a table of parameter sets)")


def _check_runs(spec: SweepSpec, grid: Grid) -> None:
    """Every parameter set of the grid is valid (before anything runs): the first refused one is named."""
    if spec.profile is not None and "R" in grid.names:
        raise ValueError(f"grid sweeps R with profile={spec.profile!r}; allowed: any name but R (the power law's "
                         "shape is c and n, R belongs to the paraboloid)")
    fields = [i for i, name in enumerate(grid.names) if name in PARAMETER_UNITS]
    for i, name in enumerate(grid.names):
        if name in EXTRA_NAMES:
            column = grid.rows[:, i]
            bad = ~((column > 0) & (column <= 90) & (np.tan(np.radians(column)) > 0))
            if name == "alpha" and np.any(bad):
                raise ValueError(f"grid['alpha'] holds {float(column[bad][0])!r}; allowed: angles in (0, 90] degrees "
                                 "whose tangent is a number (not 5e-324, whose radians underflow to 0)")
            if name == "dx" and not np.all(column > 0):
                raise ValueError(f"grid['dx'] holds {float(column[column <= 0][0])!r}; allowed: spacings > 0 (m)")
    if not fields:  # (swept sets: below)
        check_representable(spec.base, spec.profile, spec.friction)
        if spec.method == "continuum":  # (Coulomb's part needs no adhesion there)
            check_supported(spec.friction, spec.base, spec.profile)
    # a table's sets are checked whole; an outer product's values one name at a time, beside the first value of
    # every other swept name (a field is valid alone, and the continuum refuses a set by a value of one field alone:
    # a nonzero Δγ with Coulomb's part): not every combination, which for 2000 × 2000 values took minutes
    sets = np.unique(grid.rows[:, fields], axis=0) if grid.table else \
        [(i, value) for i in fields for value in grid.coords[grid.names[i]]]
    firsts = {} if grid.table else {grid.names[i]: float(grid.coords[grid.names[i]][0]) for i in fields}
    for entry in (sets if fields else []):
        changes = ({grid.names[i]: float(value) for i, value in zip(fields, entry)} if grid.table else
                   {**firsts, grid.names[entry[0]]: float(entry[1])})
        try:
            params = spec.base.replace(**changes)
            check_representable(params, spec.profile, spec.friction)  # (E = 1e300 was a failed run, not refused)
            if spec.method == "continuum":
                check_supported(spec.friction, params, spec.profile)
        except (ValueError, TypeError) as error:
            raise ValueError(f"grid: {error}") from None


# ------------------------------------------------------------------------------------------------------------
# the store
def _signature(spec: SweepSpec, grid: Grid) -> str:
    """What makes a store this sweep's: resuming another sweep's store is refused."""
    scenario = spec.scenario if isinstance(spec.scenario, str) else spec.scenario.describe()
    return json.dumps({"base": spec.base.as_dict(), "scenario": scenario, "alpha": spec.alpha, "method": spec.method,
                       "dx": spec.dx, "n_steps": spec.n_steps, "tolerances": dataclasses.asdict(spec.tolerances),
                       "names": grid.names, "rows": grid.rows.tolist(), "quantities": spec.quantities,
                       "history_samples": spec.history_samples,
                       **({} if spec.profile is None else {"profile": spec.profile.describe()}),
                       **({} if not isinstance(spec.profile, TabulatedProfile) else {"table": [spec.profile.r,
                                                                                             spec.profile.f]}),
                       **({} if spec.friction.is_default else {"friction": [spec.friction.law, spec.friction.mu]})},
                      sort_keys=True)


def _run_variables(quantities: Sequence[str], values: np.ndarray, errors: Sequence[str],
                   histories: np.ndarray | None, dims: tuple[str, ...], shape: tuple[int, ...],
                   error_dtype=str) -> dict:
    """The variables of the runs (quantities, histories, ``failed``, ``error``) laid out in ``dims`` of ``shape``:
    the store's flat ``run``, or the grid's dimensions."""
    data = {name: (dims, values[:, i].reshape(shape), {"units": QUANTITIES[name][0], "long_name": QUANTITIES[name][1]})
            for i, name in enumerate(quantities)}
    if histories is not None:
        data.update({f"history_{name}": ((*dims, "sample"), histories[:, i, :].reshape(*shape, histories.shape[-1]),
                                         {"units": unit, "long_name": f"{text} at times spread evenly over the "
                                                                      "run's path"})
                     for i, (name, (unit, text)) in enumerate(HISTORY_QUANTITIES.items())})
    data["failed"] = (dims, np.array([bool(e) for e in errors], dtype=np.int8).reshape(shape),
                      {"units": "1", "long_name": "1: the run raised (see error)"})
    data["error"] = (dims, np.array(errors, dtype=error_dtype).reshape(shape),
                     {"units": "1", "long_name": "the error of a failed run"})
    return data


def _flat_dataset(quantities: Sequence[str], values: np.ndarray, errors: Sequence[str],
                  done: np.ndarray, histories: np.ndarray | None = None) -> xr.Dataset:
    """The store's layout: the runs along ``run`` (errors of a fixed width), and whether each is ``done``."""
    data = _run_variables(quantities, values, errors, histories, ("run",), (len(errors),),
                          error_dtype=f"<U{ERROR_CHARACTERS}")
    data["done"] = (("run",), done.astype(np.int8), {"units": "1", "long_name": "1: the run's chunk is written"})
    return xr.Dataset(data)


def _is_sweep_store(path: str) -> bool:
    """Whether ``path`` holds a Zarr store written by :func:`sweep` (its group has a ``sweep_signature``)."""
    try:
        return "sweep_signature" in xr.open_zarr(path, zarr_format=2).attrs
    except Exception:  # noqa: BLE001 - anything that is not such a store, whatever the reader says of it
        return False


class _Store:
    """A Zarr store holding the sweep's runs along a flat ``run`` dimension, one chunk per task."""

    def __init__(self, path: str | os.PathLike, signature: str, quantities: Sequence[str], runs: int, chunk: int,
                 resume: bool, history_samples: int | None = None):
        self.path, self.chunk, self.quantities = os.fspath(path), chunk, tuple(quantities)
        is_store = _is_sweep_store(self.path)
        if os.path.exists(self.path) and not is_store and (not os.path.isdir(self.path) or os.listdir(self.path)):
            raise ValueError(f"store={self.path!r} exists and is not a sweep's store; allowed: a new path, an empty "
                             "directory or a sweep's store (nothing else is overwritten)")
        if not os.path.exists(self.path):
            prepare_output_directory(self.path, "store")
            # (its parent takes it as an output directory takes a file: not the root, no temporary marker)
            parent = os.path.dirname(os.path.abspath(self.path))
            check_output_file("store", os.path.join(parent, os.path.basename(os.path.normpath(self.path))))
        if resume and is_store:
            existing = xr.open_zarr(self.path, zarr_format=2)
            if existing.attrs.get("sweep_signature") != signature:
                raise ValueError(f"store={self.path!r} holds another sweep (other parameters, grid or options); "
                                 "allowed: this sweep's store to resume, or resume=False to start it afresh")
            self.existing = existing.load()
            return
        histories = None if not history_samples else np.full((runs, len(HISTORY_QUANTITIES), history_samples), np.nan)
        template = _flat_dataset(self.quantities, np.full((runs, len(self.quantities)), np.nan), [""] * runs,
                                 np.zeros(runs, bool), histories)
        template.attrs["sweep_signature"] = signature
        encoding = {name: {"chunks": (chunk,) + template[name].shape[1:]} for name in template.data_vars}
        try:
            template.to_zarr(self.path, mode="w", zarr_format=2, encoding=encoding, compute=True)
        except OSError as error:  # what the checks before cannot see (/proc, a full disk, a read-only mount)
            raise ValueError(f"store={self.path!r} cannot be written ({error.strerror or error}); allowed: "
                             "a directory this user can create and write into") from None
        self.existing = None

    def done(self) -> np.ndarray | None:
        return None if self.existing is None else self.existing["done"].values.astype(bool)

    def write(self, start: int, result: ChunkResult) -> None:
        part = _flat_dataset(self.quantities, result.values, result.errors, np.ones(len(result.errors), bool),
                             result.histories)
        part.to_zarr(self.path, region={"run": slice(start, start + len(result.errors))}, zarr_format=2)


# ------------------------------------------------------------------------------------------------------------
# the engine
def _chunks(runs: int, size: int) -> list[tuple[int, int]]:
    return [(start, min(start + size, runs)) for start in range(0, runs, size)]


def sweep(grid, scenario="A", alpha: float | None = None, *, base: Parameters, method: str = "continuum",
          dx: float | None = None, n_steps: int | None = None, tolerances: Tolerances = Tolerances(),
          quantities: Sequence[str] | None = None, scheduler: str | None = None, workers: int | None = None,
          chunk_size: int = DEFAULT_CHUNK, history_samples: int | None = None, limits: Limits = DEFAULT_LIMITS,
          store: str | os.PathLike | None = None, resume: bool = True,
          progress: Callable[[int, int], None] | None = None, profile: SimulatedProfile = None,
          friction: FrictionLaw | str | None = None) -> xr.Dataset:
    """Run the model over a grid of parameters and return each run's scalar quantities.

    Parameters
    ----------
    grid : mapping or sequence of mappings
        Name → values: the outer product, one dimension per name (in the mapping's order). Or a list of
        mappings (each a parameter set, the same names): along the dimension ``set``. Names: any
        :class:`Parameters` field, ``alpha`` (degrees) and ``dx`` (m, discrete).
    scenario : {"A", "B", "B+"} or Path
        The path of every run; a scenario is rebuilt per run (at its parameters and angle).
    alpha : float, optional
        The angle of a scenario when the grid does not sweep it.
    base : Parameters
        The fields the grid does not sweep.
    method : {"continuum", "discrete"}
        The continuum's quantities are exact (extrema and event log); the discrete model's are read off its
        samples (``dx``, ``n_steps`` as in :func:`mdr_events.simulate`; without ``n_steps`` and with a spacing
        the time step is :data:`DISCRETE_STEP_PER_SPACING` spacings of travel).
    quantities : sequence of str, optional
        Which of :data:`QUANTITIES` (default all); only closed-form ones (:data:`CLOSED_FORM_QUANTITIES`) run no
        model.
    scheduler : "serial", "local", str, distributed.Client or concurrent.futures.Executor, optional
        Where the chunks run (:mod:`mdr_events.analysis.executors`): ``"serial"``: here, one chunk after another;
        ``"local"``: a ``dask.distributed.LocalCluster`` of ``workers`` processes (default: the machine's cores),
        on loopback; an address of a running dask scheduler (``"tcp://host:8786"``); a ``distributed.Client``
        (e.g. the one a notebook made) or any ``concurrent.futures.Executor``, used and left open. Default: the
        active dask client if there is one, else ``"local"`` where ``distributed`` is installed, else
        ``"serial"``. Every engine gives the same numbers.
    chunk_size : int
        Runs per task (and per Zarr chunk of the store).
    history_samples : int, optional
        Also keep each run's F_N, F_x and A (:data:`HISTORY_QUANTITIES`) at this many times spread evenly over
        its path (``history_<q>`` along a ``sample`` dimension; the continuum's by the rule of
        :func:`mdr_events.analysis.fit.model_curves`: 0 out of the elastomer).
    store : path, optional
        A Zarr directory written chunk by chunk as runs complete; with ``resume`` (default) a store of this
        same sweep is continued: its done chunks are read, not run again.
    limits : Limits
        What each run may use (a run past a limit is recorded as failed, with the estimate).
    progress : callable, optional
        Called with (runs done, runs in all) after each chunk.
    profile : PowerLaw, optional
        The indenter of every run, ``f = c rⁿ`` with ``n >= 1`` (default ``None``: the paraboloid of ``R``); the
        critical angles are then the power law's (:mod:`mdr_events.theory.power_law`).
    friction : FrictionLaw or str, optional
        The friction law of every run (default the paper's ``"tau0"``); with Coulomb's part the critical angles are
        the closed forms without adhesion (:mod:`mdr_events.theory.mindlin`; ``nan`` for a set with adhesion).

    Returns
    -------
    xarray.Dataset
        One dimension per swept name (or ``set``), with the swept values as coordinates; the quantities of
        :data:`QUANTITIES`, ``failed`` and ``error`` (a run that raised, and why).

    Raises
    ------
    ValueError
        Before anything runs, naming the argument: an unknown name, an empty or non-finite grid, a value the
        parameters refuse, a scenario without an angle, a store of another sweep.
    """
    check_choice("method", method, METHODS)
    chunk_size = check_count("chunk_size", chunk_size, 1)
    if not isinstance(limits, Limits):
        raise TypeError(f"limits={shown(limits)} ({type(limits).__name__}) is not allowed; allowed: a Limits")
    the_grid = make_grid(grid, limits)
    if "dx" in the_grid.names and method != "discrete":
        raise ValueError("grid: 'dx' is not allowed with method='continuum'; allowed: with method='discrete'")
    check_scheduler(scheduler, workers)
    if workers is not None:
        workers = check_workers(workers)
    if not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances={shown(tolerances)} ({type(tolerances).__name__}) is not allowed; allowed: a "
                        "Tolerances")
    if alpha is not None:
        alpha = check_real("alpha", alpha, "an angle in (0, 90] degrees whose tangent is a number",
                           lambda value: 0 < value <= 90 and math.tan(math.radians(value)) > 0)
    if dx is not None:
        if method != "discrete":  # (simulate refuses it too: the continuum has no springs)
            raise ValueError(f"dx={shown(dx)} is not allowed with method={method!r}; allowed: with method='discrete'")
        dx = check_real("dx", dx, "a spacing > 0 (m)", lambda value: value > 0)
    check_flag("resume", resume)
    if isinstance(scenario, str):
        check_choice("scenario", scenario, SCENARIO_NAMES)
        if alpha is not None and "alpha" in the_grid.names:  # (the grid's angles would silently win)
            raise ValueError(f"alpha={alpha!r} is not allowed with 'alpha' in the grid; allowed: one of them")
        if alpha is None and "alpha" not in the_grid.names:
            raise ValueError(f"scenario={scenario!r} needs an angle; allowed: alpha=DEG or 'alpha' in the grid")
    elif not isinstance(scenario, Path):
        raise ValueError(f"scenario={shown(scenario)} is not allowed; allowed: 'A', 'B', 'B+' or a Path")
    elif "alpha" in the_grid.names or alpha is not None:
        raise ValueError("alpha is not allowed with a Path (its waypoints fix the motion)")
    if not isinstance(base, Parameters):
        raise TypeError(f"base={shown(base)} ({type(base).__name__}) is not allowed; allowed: a Parameters")
    if isinstance(quantities, str):  # (a name alone would be read letter by letter)
        raise TypeError(f"quantities={quantities!r} (str) is not allowed; allowed: a sequence of names, e.g. "
                        f"({quantities!r},)")
    wanted = tuple(QUANTITIES) if quantities is None else tuple(quantities)
    for name in wanted:
        check_choice("quantities", name, QUANTITIES)
    if not wanted or len(set(wanted)) != len(wanted):
        raise ValueError(f"quantities={shown(quantities)} is not allowed; allowed: distinct names from "
                         f"{', '.join(QUANTITIES)}")
    samples = None if history_samples is None else check_count("history_samples", history_samples, 2)
    if progress is not None and not callable(progress):
        raise TypeError(f"progress={shown(progress)} ({type(progress).__name__}) is not allowed; allowed: None or a "
                        "function called with (runs done, runs in all)")
    friction = as_friction_law(friction)
    spec = SweepSpec(base, scenario, alpha, method, the_grid.names, tolerances,
                     dx, n_steps, wanted, samples, limits, check_simulated_profile(profile), friction)
    _check_runs(spec, the_grid)
    runs = len(the_grid.rows)
    stored = runs * (len(wanted) + (0 if samples is None else len(HISTORY_QUANTITIES) * samples))
    limits.check(f"the sweep of {runs} runs" + ("" if samples is None else f" with history_samples={samples}"),
                 memory=BYTES_PER_STORED_VALUE * stored, **({} if samples is None else {"samples": runs * samples}))
    values = np.full((runs, len(wanted)), np.nan)
    histories = None if samples is None else np.full((runs, len(HISTORY_QUANTITIES), samples), np.nan)
    errors = [""] * runs
    the_store = None if store is None else _Store(store, _signature(spec, the_grid), wanted, runs, chunk_size, resume,
                                                  samples)
    pending = _chunks(runs, chunk_size)
    done = the_store.done() if the_store is not None else None
    if done is not None:
        previous = the_store.existing
        values[done] = np.column_stack([previous[name].values for name in wanted])[done]
        if histories is not None:
            histories[done] = np.stack([previous[f"history_{name}"].values for name in HISTORY_QUANTITIES], axis=1)[done]
        for index in np.flatnonzero(done):
            errors[index] = str(previous["error"].values[index])
        pending = [(a, b) for a, b in pending if not np.all(done[a:b])]
    finished = runs - sum(b - a for a, b in pending)

    def record(start: int, result: ChunkResult) -> None:
        nonlocal finished
        values[start:start + len(result.errors)] = result.values
        errors[start:start + len(result.errors)] = result.errors
        if histories is not None:
            histories[start:start + len(result.errors)] = result.histories
        if the_store is not None:
            the_store.write(start, result)
        finished += len(result.errors)
        if progress is not None:
            progress(finished, runs)

    if pending:  # (a store that holds every run starts no engine)
        _run_chunks(spec, the_grid, pending, scheduler, workers, record)
    return _result(spec, the_grid, values, errors, histories)


def _run_chunks(spec: SweepSpec, grid: Grid, pending: list[tuple[int, int]], scheduler, workers: int | None,
                record: Callable[[int, ChunkResult], None]) -> None:
    """Run the pending chunks on the engine of ``scheduler`` (:func:`~mdr_events.analysis.executors.open_executor`),
    recording each here as it completes; on an error, Ctrl-C or a ``record`` that stops, nothing more runs."""
    with open_executor(scheduler, workers) as executor:
        try:
            futures = {executor.submit(run_chunk, spec, grid.rows[start:stop]): start for start, stop in pending}
        except Exception as error:  # noqa: BLE001 - an executor shut down, a client closed: it takes no tasks
            raise ValueError(f"scheduler={shown(scheduler)} takes no tasks ({error}); allowed: a running executor or "
                             "client") from None
        try:
            for future in concurrent.futures.as_completed(futures):
                record(futures[future], future.result())
        finally:
            for future in futures:
                future.cancel()


def _result(spec: SweepSpec, grid: Grid, values: np.ndarray, errors: list[str],
            histories: np.ndarray | None) -> xr.Dataset:
    dims = (TABLE_DIMENSION,) if grid.table else grid.names
    data = _run_variables(spec.quantities, values, errors, histories, dims, grid.shape)
    units = dict(PARAMETER_UNITS, **EXTRA_NAMES)
    coords = {name: ((TABLE_DIMENSION,) if grid.table else (name,), grid.coords[name],
                     {"units": units[name], "long_name": f"swept {name}"}) for name in grid.names}
    scenario = spec.scenario if isinstance(spec.scenario, str) else "custom path"
    attrs = dict(content=SWEEP_CONTENT, scenario=scenario, method=spec.method, swept=", ".join(grid.names),
                 runs=int(len(errors)), failed_runs=int(data["failed"][1].sum()))
    if spec.alpha is not None:
        attrs["alpha"] = spec.alpha
    if not isinstance(spec.scenario, str):
        attrs["path_waypoints"] = spec.scenario.describe()
    return stamp(xr.Dataset(data, coords=coords), spec.base, **attrs, **indenters.profile_attrs(spec.profile),
                 **friction_attrs(spec.friction))


register_schema(SWEEP_CONTENT, {"failed": None, "error": None})
