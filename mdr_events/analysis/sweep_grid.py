"""The grid of a sweep: the names it may sweep, their values (an outer product or a table of sets), and every
run's values checked before anything runs (:func:`check_runs`).

The layer's thickness is swept as any value of the contact (``h``, dotted ``layer.thickness``, in m; ``inf`` is the
half-space, the one value a grid may hold that is not finite). Its base (``layer.base``) is a choice, not a number:
a grid holds numbers (one row of floats per run), so the base is the contact's, the same for every run.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Mapping, NamedTuple, Sequence, Sized

import numpy as np

from mdr_events.analysis.sweep_runs import METHOD_NAMES, MOTION_NAMES, SweepSpec, check_layer_run
from mdr_events.contact import Contact
from mdr_events.contact.model import CHOICES, SHORT_NAMES, UNITS
from mdr_events.limits import Limits
from mdr_events.models.methods import Discrete, Method
from mdr_events.models.motion import Motion, Scenario
from mdr_events.validation import real_array, shown

__all__ = ["Grid", "make_grid", "swept_names", "name_unit", "check_runs", "sweeps_thickness", "TABLE_DIMENSION",
           "BYTES_PER_STORED_VALUE", "UNBOUNDED_NAMES"]

#: The dimension of a sweep over a table of parameter sets.
TABLE_DIMENSION = "set"
#: Bytes per value a sweep holds at once: its array, the dataset built from it and the store's chunk (three float64
#: copies), rounded up.
BYTES_PER_STORED_VALUE = 32
#: The swept names that may hold ``inf``: the layer's thickness (``inf``: the half-space).
UNBOUNDED_NAMES = ("h", "layer.thickness")


class Grid(NamedTuple):
    """The swept names, their coordinates (outer product) or the table, and every run's values (runs × names)."""

    names: tuple[str, ...]
    coords: dict[str, np.ndarray]  #: per name (outer product), or per name along TABLE_DIMENSION
    rows: np.ndarray
    table: bool

    @property
    def shape(self) -> tuple[int, ...]:
        return (len(self.rows),) if self.table else tuple(len(self.coords[name]) for name in self.names)


def swept_names(contact: Contact, motion: Motion, method: Method) -> tuple[str, ...]:
    """The names a grid may sweep: the contact's values (dotted and short names), the motion's angle (a scenario's),
    depth and speed, and the discrete method's spacing."""
    held = contact.names()
    short = [name for name, dotted in SHORT_NAMES.items() if dotted in held]
    motion_names = [name for name in MOTION_NAMES if name != "alpha" or isinstance(motion, Scenario)]
    return (*short, *held, *motion_names, *(METHOD_NAMES if isinstance(method, Discrete) else ()))


def name_unit(contact: Contact, name: str) -> str:
    """The unit of a swept name."""
    return MOTION_NAMES.get(name) or METHOD_NAMES.get(name) or contact.unit(name)


def _values(name: str, values, allowed: Sequence[str], contact: Contact | None) -> np.ndarray:
    if name not in allowed:
        dotted = SHORT_NAMES.get(name, name)
        if dotted in CHOICES:
            raise ValueError(f"grid: {name!r} is not allowed: a choice, not a number (a grid's values are numbers); "
                             f"allowed: the contact's own (Contact.replace(**{{{dotted!r}: ...}})), one per sweep")
        part = dotted.partition(".")[0]
        whose = f" is not a value of this contact ({part}={getattr(contact, part)!r})" \
            if contact is not None and dotted in UNITS else " is not allowed"
        raise ValueError(f"grid: {shown(name)}{whose}; allowed: {', '.join(allowed)}")
    try:
        array = np.atleast_1d(real_array(f"grid[{name!r}]", values, "real numbers (not bools or strings)"))
    except TypeError as error:
        raise ValueError(str(error)) from None
    finite = np.isfinite(array) | (name in UNBOUNDED_NAMES and np.isposinf(array))  # (h = inf: the half-space)
    if array.ndim != 1 or array.size == 0 or not np.all(finite):
        also = " (or inf: the half-space)" if name in UNBOUNDED_NAMES else ""
        raise ValueError(f"grid[{name!r}]={shown(values)} is not allowed; allowed: a non-empty list of finite "
                         f"numbers{also}")
    return array


def _count(values) -> int:
    """How many values a grid's entry gives, read without converting them: its size (an array), its length (a list,
    a range), or 1 (a number; anything else is refused when read)."""
    if isinstance(values, np.ndarray):
        return values.size
    return len(values) if isinstance(values, Sized) and not isinstance(values, (str, bytes)) else 1


def _check_size(limits: Limits, runs: int, names: int) -> None:
    """The grid's own array (runs × names) within ``limits``, before it is built."""
    limits.check(f"the grid of {runs} runs", memory=BYTES_PER_STORED_VALUE * runs * names)


def make_grid(grid, allowed: Sequence[str], limits: Limits | None = None, contact: Contact | None = None) -> Grid:
    """Check a grid of ``allowed`` names: a mapping name → values (outer product) or a sequence of mappings (a table
    of sets); with ``limits``, its size is checked against them before the outer product is built; a name of
    another ``contact`` is named as such."""
    if isinstance(grid, Mapping):
        if not grid:
            raise ValueError("grid={} is not allowed; allowed: a mapping of names to values, e.g. {'tau0': [...]}")
        if limits is not None:  # before the values are read (range(10**9) is 8 GB as an array) and multiplied out
            _check_size(limits, math.prod(_count(values) for values in grid.values()), len(grid))
        coords = {str(name): _values(str(name), values, allowed, contact) for name, values in grid.items()}
        for name, values in coords.items():
            if len(np.unique(values)) != values.size:
                raise ValueError(f"grid[{name!r}] repeats a value; allowed: distinct values")
        mesh = np.meshgrid(*coords.values(), indexing="ij")
        return Grid(tuple(coords), coords, np.column_stack([m.ravel() for m in mesh]), table=False)
    if isinstance(grid, Sequence) and not isinstance(grid, str) and grid and all(isinstance(r, Mapping) for r in grid):
        names = tuple(str(name) for name in grid[0])
        if not names:
            raise ValueError("grid=[{}] is not allowed; allowed: parameter sets that each name at least one value, e.g. "
                             "[{'tau0': 3e4}, {'tau0': 4e4}]")
        for index, row in enumerate(grid):
            if set(map(str, row)) != set(names):
                raise ValueError(f"grid[{index}] names {sorted(map(str, row))}; allowed: the names of grid[0] "
                                 f"({', '.join(sorted(names))}) in every set")
        coords = {name: _values(name, [row[name] for row in grid], allowed, contact) for name in names}
        return Grid(names, coords, np.column_stack(list(coords.values())), table=True)
    raise ValueError(f"grid={shown(grid)} is not allowed; allowed: a non-empty mapping of names to values (outer "
                     "product) or a non-empty list of mappings (a table of parameter sets)")


def _check_angles_and_spacings(grid: Grid) -> None:
    """The swept angles and spacings, all at once."""
    for i, name in enumerate(grid.names):
        column = grid.rows[:, i]
        if name == "alpha":
            bad = ~((column > 0) & (column <= 90) & (np.tan(np.radians(column)) > 0))
            if np.any(bad):
                raise ValueError(f"grid['alpha'] holds {float(column[bad][0])!r}; allowed: angles in (0, 90] degrees "
                                 "whose tangent is a number (not 5e-324, whose radians underflow to 0)")
        if name == "dx" and not np.all(column > 0):
            raise ValueError(f"grid['dx'] holds {float(column[column <= 0][0])!r}; allowed: spacings > 0 (m)")


def _rows_to_check(grid: Grid) -> np.ndarray:
    """The runs whose model is checked: a table's distinct sets whole; for an outer product each value of a name
    beside the first value of every other (a value is valid alone, and the continuum refuses a set by a value of
    one name alone: a nonzero Δγ with Coulomb's part), not every combination (2000 × 2000 values took minutes).
    The angles too: the springs of a frictionless base refuse a path that moves tangentially."""
    models = [i for i, name in enumerate(grid.names) if name != "dx"]
    if grid.table:
        return np.unique(grid.rows, axis=0)
    first = grid.rows[0]
    rows = [first]
    for i in models:
        for value in grid.coords[grid.names[i]][1:]:
            row = first.copy()
            row[i] = value
            rows.append(row)
    return np.array(rows)


def sweeps_thickness(names: Sequence[str]) -> bool:
    """Whether a grid of ``names`` sweeps the layer's thickness (``h`` or ``layer.thickness``)."""
    return any(SHORT_NAMES.get(name, name) == "layer.thickness" for name in names)


def _check_contact_layer(spec: SweepSpec, grid: Grid) -> None:
    """The contact's own layer of finite thickness, where the grid does not sweep it, refused as the contact's (not
    the grid's): along every angle the grid sweeps (a frictionless base refuses a path that moves tangentially)."""
    if spec.contact.layer.is_half_space or sweeps_thickness(grid.names):
        return
    motion = spec.motion
    if "alpha" in grid.names:
        motion = dataclasses.replace(motion, alpha=tuple(float(angle) for angle in np.unique(grid.coords["alpha"])))
    check_layer_run(spec.contact, motion, spec.method, spec.quantities, spec.history_samples)


def check_runs(spec: SweepSpec, grid: Grid) -> None:
    """Every run of the grid is valid (before anything runs): the contact's layer (:func:`check_layer_run`), then the
    first refused run is named."""
    _check_angles_and_spacings(grid)
    _check_contact_layer(spec, grid)
    for row in _rows_to_check(grid):
        try:
            spec.check(row)
        except (ValueError, TypeError) as error:
            raise ValueError(f"grid: {error}") from None
