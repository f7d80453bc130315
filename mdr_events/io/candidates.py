"""Reading a simulator's output to validate it: a Dataset, a mapping of arrays, or a CSV / netCDF file
from any program, with the user's own column names and units.

:func:`read_candidate` returns a :class:`Candidate`: the time and the quantities it found, in SI units.
Errors name the source, the column and what is allowed (the columns found among them).
"""

from __future__ import annotations

import os
import unicodedata
from pathlib import Path
from typing import Callable, Collection, Mapping, NamedTuple

import numpy as np
import xarray as xr

from mdr_events.io.files import input_file_problem, load_netcdf
from mdr_events.io.text_tables import (BYTES_PER_CSV_VALUE, LISTED_CHARACTERS, columns_listed, is_text, read_csv,
                                       read_profile_table)
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.validation import SCALE_MAX, check_mapping, check_real, real_array, shown, shown_path

__all__ = ["CANDIDATE_QUANTITIES", "UNITS", "Candidate", "UnnamedColumnError", "read_candidate", "unit_factor",
           "check_run_is_finite", "UNDEFINED_OUT_OF_CONTACT",
           # (read from :mod:`.text_tables`, named here as before)
           "BYTES_PER_CSV_VALUE", "LISTED_CHARACTERS", "columns_listed", "read_profile_table"]

#: How far a run's coordinate (an angle in degrees) may lie from the one ``select`` names and still be that run.
SELECT_ATOL = 1e-9
#: ... or, for a coordinate stored in fewer digits (float32: an angle of 20.1° is 20.100000381°), this many of its
#: own ulps at the value: the label rounded to its type lies within half an ulp of the value it was made from.
SELECT_ULPS = 2.0
#: The kinds of NumPy arrays a column of real numbers has: integers and floats (not bools, complex numbers, times).
REAL_KINDS = "iuf"
#: What the mapping arguments of :func:`read_candidate` look like, for a message.
MAPPING_EXAMPLES = {"names": "{'time': 't', 'normal_force': 'Fn'}", "units": "{'time': 'ms', 'normal_force': 'mN'}",
                    "select": "{'alpha': 20}"}
#: The quantities a candidate may hold, with their SI unit; ``time`` is required, and at least one other.
CANDIDATE_QUANTITIES: dict[str, str] = {
    "time": "s",
    "normal_force": "N",
    "tangential_force": "N",
    "contact_area": "m2",
    "contact_radius": "m",
    "sliding_fraction": "1",
}

#: Units understood, by the SI unit they convert to: name -> factor to SI.
UNITS: dict[str, dict[str, float]] = {
    "s": {"s": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6, "min": 60.0, "h": 3600.0},
    "N": {"N": 1.0, "mN": 1e-3, "uN": 1e-6, "µN": 1e-6, "kN": 1e3},
    "m": {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9},
    "m2": {"m2": 1.0, "m^2": 1.0, "mm2": 1e-6, "mm^2": 1e-6, "um2": 1e-12, "µm2": 1e-12, "um^2": 1e-12,
           "µm^2": 1e-12},
    "1": {"1": 1.0, "": 1.0, "%": 1e-2},
}


class Candidate(NamedTuple):
    """A simulator's output in SI units: ``time`` (s) and the quantities found (name -> array)."""

    time: np.ndarray
    quantities: dict[str, np.ndarray]
    source: str  #: where it came from: its file's path whole (a report's attribute), or "candidate (Dataset)"
    unused: tuple[str, ...] = ()  #: the candidate's columns that were not read (not named as a quantity)

    @property
    def where(self) -> str:
        """The source as a message names it (:func:`~mdr_events.validation.shown_path`: one line, a long path cut)."""
        return shown_path(self.source)


class UnnamedColumnError(ValueError):
    """A candidate without a column of ``time``, or of any other quantity, by its name or by ``names``: the message
    says ``names={...}`` as Python writes it, and ``quantities`` are those missing (``("time",)``, or every quantity
    but the time), for a caller that says how to name them in its own words (the command line's ``--names``,
    :mod:`mdr_events.app.cli`)."""

    def __init__(self, message: str, quantities: tuple[str, ...]) -> None:
        super().__init__(message)
        self.quantities = tuple(quantities)

    def __reduce__(self):  # (pickled across processes with its quantities)
        return type(self), (str(self), self.quantities)


def unit_factor(quantity: str, unit: str, source: str) -> float:
    """The factor to SI of ``unit`` for ``quantity`` (:data:`UNITS`); ``ValueError`` naming ``source`` else."""
    allowed = UNITS[CANDIDATE_QUANTITIES[quantity]]
    spelled = unit_spelling(unit) if isinstance(unit, str) else None  # (a list is no unit, and unhashable)
    if spelled not in allowed:
        raise ValueError(f"{source}: units[{quantity!r}]={shown(unit)} is not allowed; allowed: "
                         f"{', '.join(repr(name) for name in allowed)}")
    return allowed[spelled]


def unit_spelling(unit: str) -> str:
    """``unit`` as :data:`UNITS` spells it: Unicode's compatibility forms folded (NFKC: a superscript ``²`` is ``2``)
    and the Greek letter mu (U+03BC, what a Greek keyboard and NFKC write) read as the micro sign (U+00B5) the table
    uses. The two look the same: ``'μm'`` was refused beside an allowed ``'µm'`` that a user could not tell from it,
    and ``'mm²'`` beside ``'mm2'`` (round 30)."""
    return unicodedata.normalize("NFKC", unit).replace("\u03bc", "\u00b5")


def _columns_and_units(candidate, source: str, limits: Limits = DEFAULT_LIMITS,
                       select: Mapping[str, object] | None = None,
                       progress: Callable[[str], None] | None = None,
                       wanted: Collection[str] = ()) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """The candidate's columns and the units they declare (a Dataset's or netCDF file's ``units``); a Dataset's column
    read as a quantity (its name ``wanted``, or a quantity's) must hold real numbers."""
    if isinstance(candidate, (str, os.PathLike)):
        path = Path(candidate)
        problem = input_file_problem(path)
        if problem is not None:
            raise ValueError(f"candidate={shown_path(candidate, quoted=True)}{problem}; allowed: a CSV or netCDF file, "
                             "a Dataset or a mapping of arrays")
        # (a text table of any name but .nc; its other columns are named, not parsed: any text)
        if path.suffix.lower() == ".csv" or (path.suffix.lower() != ".nc" and is_text(path)):
            return read_csv(path, limits, progress, {*CANDIDATE_QUANTITIES, *wanted}), {}
        # (loaded whole: the values its header declares count as memory before it is read, as a CSV's rows do)
        candidate = load_netcdf(path, source, "a CSV file with a header or a netCDF-3 file",
                                lambda lazy: _check_declared(source, path, lazy, limits))
    if isinstance(candidate, xr.Dataset):
        candidate = _selected(candidate, source, select or {})
        # a simulation of one case (dims ``alpha`` or ``case`` of size 1 beside ``time``) is that case's run
        single = [dim for dim, size in candidate.sizes.items() if dim != "time" and size == 1]
        several = [f"{dim!r} ({size})" for dim, size in candidate.sizes.items()
                   if dim != "time" and size > 1 and any(dim in v.dims and "time" in v.dims
                                                         for v in candidate.data_vars.values())]
        if several:
            raise ValueError(f"{source} holds several runs along {', '.join(several)}; allowed: one run (select it: "
                             "select={'alpha': its angle}, or alpha= with a scenario; on the command line --alpha; or "
                             "dataset.sel(case='...'))")
        if single:
            candidate = candidate.isel({dim: 0 for dim in single})
        for name, variable in candidate.data_vars.items():  # (time named otherwise: a column of two runs was dropped)
            if sum(size > 1 for size in variable.shape) > 1 and np.issubdtype(variable.dtype, np.number):
                raise ValueError(f"{source}: column {str(name)!r} of dims {dict(variable.sizes)} holds several runs; "
                                 "allowed: one run, a column along one dimension (select the run: "
                                 "dataset.isel(...) or select=)")
        names = list(candidate.variables)
        # (a quantity's column of text was dropped silently, a pass on the others; one of complex numbers lost its
        # imaginary part, one of timedeltas was read in nanoseconds as seconds)
        other = [name for name in names if (name in CANDIDATE_QUANTITIES or name in wanted) and
                 candidate[name].dtype.kind not in REAL_KINDS]
        if other:
            hint = " (timedeltas: give seconds, e.g. time / numpy.timedelta64(1, 's'))" \
                if candidate[other[0]].dtype.kind in "mM" else ""
            raise TypeError(f"{source}: column {str(other[0])!r} holds {candidate[other[0]].dtype} values; allowed: "
                            f"real numbers{hint}")
        return ({name: np.asarray(candidate[name].values, dtype=float).ravel() for name in names
                 if candidate[name].ndim <= 1 and candidate[name].dtype.kind in REAL_KINDS},
                {name: str(candidate[name].attrs["units"]) for name in names if "units" in candidate[name].attrs})
    if isinstance(candidate, Mapping):
        columns = {str(name): real_array(f"{source}: column {str(name)!r}", values,
                                         "real numbers (not bools, complex numbers or strings)")
                   for name, values in candidate.items()}
        for name, column in columns.items():
            if sum(size > 1 for size in column.shape) > 1:  # (a (1, n) array is one run; (2, n) would be two)
                raise ValueError(f"{source}: column {name!r} of shape {column.shape} is not allowed; allowed: one "
                                 "run, a 1-D array")
        return {name: column.ravel() for name, column in columns.items()}, {}
    raise TypeError(f"candidate of type {type(candidate).__name__} is not allowed; allowed: an xarray.Dataset, a "
                    "mapping of arrays, or the path of a CSV or netCDF file")


#: Bytes a netCDF value takes once read as a candidate's column beside its value as stored (a float64).
NETCDF_BYTES_PER_VALUE = 8


def _check_declared(source: str, path: Path, lazy: xr.Dataset, limits: Limits) -> None:
    """Count the values a netCDF file's header declares against ``limits.memory`` before they are loaded: each as stored
    and as the float64 column it is read into (a file of bytes, int8, took 9 times its size: a file's size alone
    counted 1/9 of it; a header may declare more than the file holds)."""
    values = sum(int(variable.size) for variable in lazy.variables.values())
    stored = sum(int(variable.size) * variable.dtype.itemsize for variable in lazy.variables.values())
    limits.check(f"reading {source} ({path.stat().st_size} bytes; {values} values declared)",
                 memory=stored + NETCDF_BYTES_PER_VALUE * values)


def _selected(dataset: xr.Dataset, source: str, select: Mapping[str, object]) -> xr.Dataset:
    """The run of a dataset of several (a simulation along ``alpha``) that ``select`` names (e.g. ``{"alpha": 20}``,
    the angle the candidate is validated at); a dimension of one run, or absent, is left as it is, but one run labelled
    at another number (a dimension of one, or a scalar coordinate: ``simulate``'s run at 21° judged at 20°) is
    refused, as one missing from several is (:func:`_check_labelled_at`)."""
    for dimension, value in select.items():
        if dimension in dataset.coords and dataset[dimension].size == 1 and \
                np.issubdtype(dataset[dimension].dtype, np.number):
            _check_labelled_at(dataset, source, dimension, value)
        if dimension in dataset.dims and dataset.sizes[dimension] > 1:
            value = check_real(f"select[{dimension!r}]", value, "one coordinate value, a number")
            values = dataset[dimension].values
            matches = np.flatnonzero(_labelled_as(values, value))
            if matches.size != 1:
                raise ValueError(f"{source} holds runs along {dimension!r} at {', '.join(f'{v:g}' for v in values)}, "
                                 f"not at {dimension}={value!r}; allowed: one of those")
            dataset = dataset.isel({dimension: int(matches[0])})
    return dataset


def _labelled_as(labels: np.ndarray, value: float) -> np.ndarray:
    """Which ``labels`` (a coordinate's values) name the run at ``value``: within :data:`SELECT_ATOL`, or
    :data:`SELECT_ULPS` of the labels' own precision (a float32 coordinate)."""
    labels = np.asarray(labels)
    spacing = np.finfo(labels.dtype).eps * abs(value) if np.issubdtype(labels.dtype, np.floating) else 0.0
    return np.isclose(labels.astype(float), value, rtol=0.0, atol=max(SELECT_ATOL, SELECT_ULPS * spacing))


def _check_labelled_at(dataset: xr.Dataset, source: str, dimension: str, value: object) -> None:
    """Refuse one run whose numeric coordinate ``dimension`` is not ``value`` (within the tolerance of several runs'
    selection, :data:`SELECT_ATOL`)."""
    value = check_real(f"select[{dimension!r}]", value, "one coordinate value, a number")
    labels = dataset[dimension].values.ravel()
    if not _labelled_as(labels, value)[0]:
        raise ValueError(f"{source} holds one run at {dimension}={float(labels[0])!r}, not at {dimension}={value!r}; "
                         "allowed: "
                         f"the run's own {dimension} (another run's output judged as this one's would pass or fail "
                         "for the wrong reason)")


def _check_units_have_columns(source: str, units: dict, names: dict, columns) -> None:
    """Refuse a unit for a quantity the run has no column of (it was dropped silently; a column named by ``names``
    that is missing is refused as such)."""
    for quantity, unit in units.items():
        column = names.get(quantity, quantity)
        if quantity not in names and column not in columns:
            raise ValueError(f"{source}: units[{shown(quantity)}]={shown(unit)} is not allowed: no column {shown(column)}; "
                             f"allowed: units of the columns found: {columns_listed(columns)}")


def read_candidate(candidate, names: Mapping[str, str] | None = None,
                   units: Mapping[str, str] | None = None, limits: Limits = DEFAULT_LIMITS,
                   select: Mapping[str, object] | None = None,
                   progress: Callable[[str], None] | None = None) -> Candidate:
    """Read a simulator's output: time and any of :data:`CANDIDATE_QUANTITIES`, converted to SI.

    Parameters
    ----------
    candidate : xarray.Dataset, mapping of str to array, str or os.PathLike
        The output: a Dataset (variables by name), a mapping of arrays, or a file: a text table whatever its name
        (``.csv``, ``.txt``, ``.tsv``, ...; a header row, lines starting with ``#`` skipped, fields separated by
        commas, else semicolons, tabs or blanks), else netCDF-3 (told by its first bytes).
    names : mapping, optional
        Quantity -> the candidate's column name, for columns not named as in :data:`CANDIDATE_QUANTITIES`.
    units : mapping, optional
        Quantity -> unit (:data:`UNITS`, e.g. ``"mN"``, ``"ms"``, ``"um"``); default the ``units`` attribute of
        a Dataset's or netCDF file's variable, else SI.
    limits : Limits, optional
        A CSV file's rows count as ``samples`` and :data:`~mdr_events.io.text_tables.BYTES_PER_CSV_VALUE` each as
        ``memory``, checked before they are read (``ResourceLimitError``).
    select : mapping, optional
        A dataset of several runs (a simulation along ``alpha``): the one at these coordinates (``{"alpha": 20}``).
    progress : callable, optional
        Hears how far a long CSV file's read is (every :data:`~mdr_events.io.text_tables.PROGRESS_ROWS` rows).

    Raises
    ------
    ValueError
        Naming the source and the column: a missing time or no quantity (:class:`UnnamedColumnError`, listing the
        columns found), a unit that is not allowed, columns of different lengths, times that are not finite or not
        increasing, an infinite value (with its first row; ``nan`` is a missing sample).
    """
    source = str(candidate) if isinstance(candidate, (str, os.PathLike)) else f"candidate ({type(candidate).__name__})"
    where = shown_path(source)  # (as messages name it: one line, a long path cut)
    for argument, given in (("names", names), ("units", units), ("select", select)):
        check_mapping(argument, given, MAPPING_EXAMPLES[argument])
    names = dict(names or {})
    for quantity, column in names.items():  # (a list was unhashable: a raw TypeError)
        if not isinstance(column, str):
            raise TypeError(f"{where}: names[{quantity!r}]={shown(column)} ({type(column).__name__}) is not allowed; "
                            "allowed: a column's name (str)")
    columns, declared = _columns_and_units(candidate, where, limits, select, progress, set(names.values()))
    units = dict(units or {})
    for quantity in list(names) + list(units):
        if quantity not in CANDIDATE_QUANTITIES:
            raise ValueError(f"{where}: {shown(quantity)} in names/units is not allowed; allowed: "
                             f"{', '.join(CANDIDATE_QUANTITIES)}")
    _check_units_have_columns(where, units, names, columns)
    found, given, used = _quantities_read(where, columns, names, units, declared)
    if "time" not in found:
        raise UnnamedColumnError(f"{where}: no time column; columns found: {columns_listed(columns)}; allowed: a "
                                 "column 'time' or names={'time': <your column>}", ("time",))
    time = found.pop("time")
    limits.check(f"{where} ({time.size} samples)", samples=time.size)  # (an array or a Dataset as a file's rows)
    if not found:
        others = tuple(quantity for quantity in CANDIDATE_QUANTITIES if quantity != "time")
        raise UnnamedColumnError(f"{where}: none of {', '.join(others)} found; columns found: "
                                 f"{columns_listed(columns)}; allowed: name yours with names={{quantity: column}}",
                                 others)
    for quantity, values in found.items():
        if values.shape != time.shape:
            raise ValueError(f"{where}: column {names.get(quantity, quantity)!r} has {values.size} values and the "
                             f"time {time.size}; allowed: the same length")
    for quantity in ("time", *found):
        _refuse_magnitudes(where, names.get(quantity, quantity), *given[quantity], time)
    if time.size < 2 or not np.all(np.isfinite(time)) or np.any(np.diff(time) <= 0):
        raise ValueError(f"{where}: column {names.get('time', 'time')!r} is not allowed as the time; allowed: at "
                         "least two finite, strictly increasing values")
    # a share: of the springs in contact, those that slide
    shares = found.get("sliding_fraction", np.zeros(0))
    _refuse_rows(where, names.get("sliding_fraction", "sliding_fraction"), shares, (shares < 0) | (shares > 1), time,
                 "shares from 0 to 1 (nan where no spring is in contact); a percentage needs "
                 "units={'sliding_fraction': '%'}", written=lambda value: repr(float(value)))
    for quantity, values in found.items():
        _refuse_rows(where, names.get(quantity, quantity), values, np.isinf(values), time,
                     "finite values (nan or an empty field for a missing sample)")
    return Candidate(time, found, source, tuple(name for name in columns if name not in used))


#: A quantity's column as read, its unit and that unit's factor to SI.
_Given = tuple[np.ndarray, str, float]


def _quantities_read(source: str, columns: dict[str, np.ndarray], names: dict[str, str], units: dict[str, str],
                     declared: dict[str, str]) -> tuple[dict[str, np.ndarray], dict[str, _Given], set[str]]:
    """The quantities found among ``columns`` (by ``names``, else by their own name) in SI units; each one's column as
    read, its unit (``units``, else the column's ``declared`` unit, else SI) and factor to SI; the columns used. A
    column ``names`` gives that is not there, or one named for two quantities, is refused (``ValueError``)."""
    found: dict[str, np.ndarray] = {}
    given: dict[str, _Given] = {}
    used: set[str] = set()
    for quantity in CANDIDATE_QUANTITIES:
        column = names.get(quantity, quantity)
        if column not in columns:
            if quantity in names:
                raise ValueError(f"{source}: names[{quantity!r}]={shown(column)} is not a column; allowed: one of the "
                                 f"columns found: {columns_listed(columns)}")
            continue
        if column in used:  # (one column read as two quantities, e.g. names={'normal_force': 'time'})
            other = next(name for name in found if names.get(name, name) == column)
            raise ValueError(f"{source}: names[{quantity!r}]={shown(column)} is the column of {other!r} too; allowed: one "
                             "column per quantity")
        unit = units.get(quantity, declared.get(column, CANDIDATE_QUANTITIES[quantity]))
        given[quantity] = columns[column], unit, unit_factor(quantity, unit, source)
        with np.errstate(over="ignore"):  # (a value beyond the doubles in SI: refused by _refuse_magnitudes, named)
            found[quantity] = given[quantity][0] * given[quantity][2]
        used.add(column)
    return found, given, used


def _refuse_magnitudes(source: str, column: str, values: np.ndarray, unit: str, factor: float,
                       time: np.ndarray) -> None:
    """Refuse a finite value of ``column`` (as read, in ``unit``) whose magnitude in SI units exceeds
    :data:`~mdr_events.validation.SCALE_MAX`, compared before it is scaled (round twenty-five: 1e306 kN overflowed
    to inf in the scaling, with NumPy's warning, and was named as a value of ``inf``; 1e306 min as the time ran
    to the figure's overflow), naming the row, the value in its unit and in SI."""
    with np.errstate(over="ignore"):
        _refuse_rows(source, column, values, np.isfinite(values) & (np.abs(values) > SCALE_MAX / factor), time,
                     f"magnitudes up to {SCALE_MAX:.2g} in SI units, so that their squares stay finite (check the "
                     "unit)", written=lambda value: f"{float(value):.3g} {unit} ({float(value) * factor:.3g} in SI "
                                                    "units)")


def _refuse_rows(source: str, column: str, values: np.ndarray, bad: np.ndarray, time: np.ndarray, allowed: str,
                 written: Callable[[float], str] = str, context: str = "") -> None:
    """Raise ``ValueError`` naming the column, the first ``bad`` row (its value and time) and how many more, if any."""
    rows = np.flatnonzero(bad)
    if rows.size:
        row = int(rows[0])
        more = f" and {rows.size - 1} more" if rows.size > 1 else ""
        raise ValueError(f"{source}: column {column!r} holds {written(values[row])} at data row {row + 1} (time "
                         f"{time[row]:.9g} s){more}{context}; allowed: {allowed}")


#: Quantities undefined out of contact (the share of the springs in contact that slide, with none in contact).
UNDEFINED_OUT_OF_CONTACT = ("sliding_fraction",)


def check_run_is_finite(candidate: Candidate, in_contact: np.ndarray, names: Mapping[str, str] | None = None) -> None:
    """Refuse a simulator's run with a missing (``nan``) sample inside it: a run ends with its last finite samples
    (``nan`` after its end, as :func:`mdr_events.simulate` writes, is fine), so a ``nan`` followed by a finite value
    of the same column is a broken run, not one to pass (``ValueError`` naming the column and the first row). The
    quantities of :data:`UNDEFINED_OUT_OF_CONTACT` may be ``nan`` where the run is not ``in_contact``."""
    names = dict(names or {})
    for quantity, values in candidate.quantities.items():
        finite = np.isfinite(values) | ((~in_contact) if quantity in UNDEFINED_OUT_OF_CONTACT else False)
        if not finite.any():
            raise ValueError(f"{candidate.where}: column {names.get(quantity, quantity)!r} holds no finite value; "
                             "allowed: a run's samples (leave the column out if the simulator does not write it)")
        last = int(np.flatnonzero(finite)[-1])
        _refuse_rows(candidate.where, names.get(quantity, quantity), values, ~finite & (np.arange(values.size) < last),
                     candidate.time, "a finite value at every sample up to the run's end (nan only after it)",
                     context=f", inside the run (finite values follow up to row {last + 1})")
