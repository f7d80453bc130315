"""Labelled results: provenance stamp, schemas of the kinds of result, comparison.

Every dataset the package writes carries ``units`` and ``long_name`` on each
variable and, in its attributes, the program, its version, the paper's DOI
and every model parameter (tamaas-style provenance), all netCDF-safe (str,
float, int), so that :func:`parameters_of` can rebuild the :class:`Parameters`.

Its ``content`` attribute names the kind of result; the module that makes a
kind of result registers what it must hold (:func:`register_schema`) when it
is imported, and :func:`mdr_events.io.files.open_result` checks a file read
back against it (:func:`required_variables`), and declares how each of its quantities is computed
(:func:`mdr_events.io.agreement.register_accuracy`), which sets the tolerance within which a result computed
elsewhere agrees with it. Reading and writing files is :mod:`mdr_events.io.files`.
"""

from __future__ import annotations

import functools
from typing import Any, Collection, Mapping, Sequence

import numpy as np
import pandas as pd
import xarray as xr
from xarray.indexes import PandasIndex

from mdr_events._version import __version__
from mdr_events.io.registrars import load_registrars
from mdr_events.memo import kept
from mdr_events.parameters import Parameters

__all__ = ["DOI", "REFERENCE", "PROGRAM", "STAMP_ATTRIBUTES", "stamp", "assembled", "parameters_of", "text_list_attrs",
           "read_text_list", "Dims", "register_schema",
           "registered_contents", "required_variables", "register_figure", "figure_of", "dims_match", "describe_dims"]

DOI = "10.3390/biomimetics8060477"
REFERENCE = (
    "I. A. Lyashenko, V. L. Popov, V. Borysiuk, Indentation and Detachment in Adhesive "
    "Contacts between Soft Elastomer and Rigid Indenter at Simultaneous Motion in Normal "
    "and Tangential Direction: Experiments and Simulations, Biomimetics 8(6), 477 (2023), section 4"
)
PROGRAM = "mdr_events"
#: The kinds of NumPy array (``dtype.kind``) whose default index :func:`_default_index` makes at once: real numbers.
NUMERIC_KINDS = "fiu"
#: The kind of NumPy array (``dtype.kind``) of text whose index results of the same texts share: custom paths' labels.
TEXT_KIND = "U"
#: The most numbers or texts a coordinate may hold for results of the same values to share its index
#: (:func:`_shared_coordinate`: an event log's numbers, a run's angles, custom paths' labels).
SHARED_INDEX_SIZE = 256
#: How many such coordinates are kept.
SHARED_INDEXES = 64
#: How many parameter sets' attributes :func:`stamp` keeps.
PARAMETER_ATTRS_KEPT = 64


#: The attributes :func:`stamp` puts on every result first: the program and the paper.
PROVENANCE = {"program": PROGRAM, "program_version": __version__, "doi": DOI, "reference": REFERENCE,
              "Conventions": "CF-1.8"}
#: The types of attribute values that are netCDF-safe as they are.
_SAFE_AS_THEY_ARE = (str, float, int)


def _netcdf_safe(value: Any) -> Any:
    if type(value) in _SAFE_AS_THEY_ARE:  # (what the conversions below would return unchanged)
        return value
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value)
    if isinstance(value, str):
        return value
    raise TypeError(f"attribute value {value!r} of type {type(value).__name__} is not netCDF-safe")


def stamp(dataset: xr.Dataset, params: Parameters, **attrs: Any) -> xr.Dataset:
    """Attach provenance and parameters to ``dataset`` (in place) and return it.

    ``attrs`` are extra netCDF-safe attributes (str, int, float; bools are
    stored as 0/1).
    """
    dataset.attrs.update(PROVENANCE)
    dataset.attrs.update(_parameter_attrs(params))
    dataset.attrs.update({key: _netcdf_safe(value) for key, value in attrs.items()})
    for name, variable in dataset.variables.items():
        held = variable.attrs
        if "units" not in held or "long_name" not in held:
            missing = [key for key in ("units", "long_name") if key not in held]
            raise ValueError(f"variable {name!r} lacks attribute(s) {missing}")
    return dataset


@kept(PARAMETER_ATTRS_KEPT)
def _parameter_attrs(params: Parameters) -> dict[str, Any]:
    """What :func:`stamp` says of ``params``: :meth:`~mdr_events.Parameters.to_attrs` and, for a preset of the paper,
    which fields are inferred; kept per value (:func:`~mdr_events.memo.kept`; read, never changed)."""
    attrs = params.to_attrs()
    preset = params.preset_name()
    if preset is not None:
        attrs["inferred_parameters"] = ", ".join(Parameters.INFERRED_FIELDS)
        attrs["inferred_parameters_note"] = (
            f"{preset}: these fields are inferred, not stated in section 4 of the paper "
            "(see mdr_events.Parameters.paper)")
    return attrs


def assembled(data_vars: Mapping[str, tuple], coords: Mapping[str, tuple]) -> xr.Dataset:
    """``xarray.Dataset(data_vars, coords=coords)`` of variables laid out together, without xarray's merge.

    The merge aligns and compares every variable with the others (some 15 µs each: for a continuum run's thirty
    variables as long as a third of the solve); variables made for one result share their dimensions by
    construction, so that only their sizes are checked here. The dataset is the one ``xarray.Dataset`` gives, to
    the order of its variables and dimensions (the data, then the coordinates, each in the order given) and its
    indexes (a coordinate named after its one dimension gets the default index, as ``xarray.Coordinates`` makes
    it); ``tests/models/test_simulate_cases.py`` compares both on every kind of simulation.

    Parameters
    ----------
    data_vars : mapping of str to tuple
        Name -> ``(dims, values, attrs)`` of each data variable (none named after a dimension).
    coords : mapping of str to tuple
        Name -> ``(dims, values, attrs)`` of each coordinate.

    Returns
    -------
    xarray.Dataset
        The dataset, without attributes.

    Raises
    ------
    ValueError
        A dimension of two sizes, or a data variable named after a dimension or a coordinate.
    """
    coordinates, indexes = _coordinates(coords)
    variables = {name: _variable(dims, values, attrs) for name, (dims, values, attrs) in data_vars.items()}
    clash = sorted(set(variables) & (set(coordinates) | {dim for var in variables.values() for dim in var.dims}))
    if clash:
        raise ValueError(f"data variables {clash} are not allowed: named after a coordinate or a dimension; allowed: "
                         "the coordinates in coords")
    variables.update(coordinates)
    return xr.Dataset._construct_direct(variables, set(coordinates), dims=_dimensions(variables), indexes=indexes)


def _dimensions(variables: dict[str, xr.Variable]) -> dict:
    """The dataset's dimensions and sizes, as ``xarray.Dataset`` gives them (in the order the variables name them),
    read off each variable's dimensions and shape; a dimension of two sizes, or one named after a variable of no
    dimensions, refused as ``xarray.Dataset`` refuses it (``ValueError``, xarray's words)."""
    dims: dict = {}
    for name, variable in variables.items():
        for dim, size in zip(variable.dims, variable.shape):
            if dims.setdefault(dim, size) != size:
                first = next(other for other, held in variables.items() if dim in held.dims)
                raise ValueError(f"conflicting sizes for dimension {dim!r}: length {size} on {name!r} and length "
                                 f"{dims[dim]} on {first!r}; allowed: one size for each dimension")
    scalars = [dim for dim in dims if dim in variables and not variables[dim].dims]
    if scalars:
        raise ValueError(f"dimension {scalars[0]!r} already exists as a scalar variable; allowed: a dimension named "
                         "after no variable, or after a variable of that dimension")
    return dims


def _variable(dims, values, attrs: dict) -> xr.Variable:
    """``xarray.Variable(dims, values, attrs)``; a NumPy array of numbers or text taken as it is (what xarray's
    conversion would leave it), without the conversion's checks."""
    return xr.Variable(dims, values, attrs, fastpath=type(values) is np.ndarray and values.dtype.kind not in "OMm")


def _coordinates(coords: Mapping[str, tuple]) -> tuple[dict[str, xr.Variable], dict[str, Any]]:
    """The coordinates' variables and indexes as ``xarray.Coordinates(coords)`` makes them, without its merge: a
    coordinate of one dimension named after it gets the default index (:func:`_default_index`) and the index's
    variable; one of at most :data:`SHARED_INDEX_SIZE` numbers a ``pandas.Index.view`` of the last results' of the
    same values (:func:`_shared_coordinate`): its own index and variable (a name or attribute set on one is the
    other's no more), the read-only values shared; one of more numbers (a run's times) the ``pandas.Index`` of its
    values, wrapped at once in its index and variable (what ``PandasIndex.create_variables`` makes of it); one of at
    most :data:`SHARED_INDEX_SIZE` texts (custom paths' labels, ``"path 1"``, ...) a view of the last results' index of
    the same texts too, its variable made by the index's ``create_variables`` (as of a new index: the text's NumPy
    type kept; pandas' index of text took ~0.3 ms, as long as the rest of a dataset); any other is a plain variable."""
    variables, indexes = {}, {}
    for name, (dims, values, attrs) in coords.items():
        own = type(dims) in (str, tuple) and dims in (name, (name,)) and type(values) is np.ndarray and values.ndim == 1
        if own and values.dtype.kind == TEXT_KIND and values.size <= SHARED_INDEX_SIZE:  # (custom paths' labels)
            shared = _shared_coordinate(name, values.dtype.str, values.tobytes()).index
            index = indexes[name] = PandasIndex(shared.view(), name, coord_dtype=values.dtype, fastpath=True)
            variable = index.create_variables({name: _variable(dims, values, attrs)})[name]
        elif own and _numbers(values):
            if values.size <= SHARED_INDEX_SIZE:
                shared = _shared_coordinate(name, values.dtype.str, values.tobytes()).index
                view = shared.view()  # (its own pandas.Index, named apart; the values and their lookup table shared)
            else:  # (a run's times: the index of its values, made at once as _default_index makes it)
                view = shared = pd.Index(values, name=name)
            indexes[name] = PandasIndex(view, name, coord_dtype=shared.dtype, fastpath=True)
            variable = xr.IndexVariable((name,), view, attrs, fastpath=True)
        else:
            variable = _variable(dims, values, attrs)
            if variable.dims == (name,):
                index = _default_index(name, variable)
                variable = index.create_variables({name: variable})[name]
                indexes[name] = index
        variables[name] = variable
    return variables, indexes


def _numbers(values: Any) -> bool:
    """Whether ``values`` is a NumPy array of real numbers."""
    return type(values) is np.ndarray and values.dtype.kind in NUMERIC_KINDS


def _default_index(name: str, variable: xr.Variable) -> PandasIndex:
    """The index ``PandasIndex.from_variables`` makes of the coordinate ``name``: of a NumPy array of numbers, the
    ``pandas.Index`` of its values named ``name`` wrapped at once (``fastpath``: what ``from_variables`` reaches
    through two shallow copies to rename it, some 15 µs a coordinate); of anything else, by ``from_variables``
    (text, whose conversion it decides)."""
    values = variable.data
    if _numbers(values) and values.ndim == 1:
        return PandasIndex(pd.Index(values, name=name), name, coord_dtype=values.dtype, fastpath=True)
    return PandasIndex.from_variables({name: variable}, options={})


@functools.lru_cache(maxsize=SHARED_INDEXES)
def _shared_coordinate(name: str, dtype: str, data: bytes) -> PandasIndex:
    """The default index of the coordinate ``name`` of the numbers or texts ``data`` (their bytes, of type ``dtype``,
    read-only), made once for the last :data:`SHARED_INDEXES` coordinates (an event log's numbers, a run's angles,
    custom paths' labels). Never handed out: a ``pandas.Index`` takes a new name in place, so that each result gets a
    view of it (:func:`_coordinates`)."""
    return _default_index(name, xr.Variable((name,), np.frombuffer(data, dtype=np.dtype(dtype))))


def parameters_of(dataset: xr.Dataset) -> Parameters:
    """The :class:`Parameters` a dataset was computed with."""
    return Parameters.from_attrs(dataset.attrs)


def text_list_attrs(name: str, items: Sequence[str]) -> dict[str, Any]:
    """A list of texts as attributes netCDF-3 holds, each whole: ``name`` (how many) and ``name_1``, ``name_2``, ...
    (:func:`read_text_list` reads them back, and the joined text of files written before)."""
    return {name: len(items), **{f"{name}_{index}": str(text) for index, text in enumerate(items, start=1)}}


def read_text_list(attrs: Mapping[str, Any], name: str) -> list[str]:
    """The texts of :func:`text_list_attrs`; of a file written before them, its ``"; "``-joined text (``"none"``:
    none)."""
    count = attrs.get(name, 0)
    if isinstance(count, str):  # (written before: the texts joined)
        return [] if count in ("none", "") else count.split("; ")
    return [str(attrs[f"{name}_{index}"]) for index in range(1, int(count) + 1)]


#: Attributes every result carries.
STAMP_ATTRIBUTES = ("program", "program_version", "doi", "content")

#: The dimensions a schema requires of a variable, in order (``None``: any). Each entry is a dimension's
#: name or a tuple of names any one of which will do (e.g. ``(("alpha", "case"), "time")``: a simulation's
#: cases are labelled by angle or by name).
Dims = tuple[str | tuple[str, ...], ...] | None

#: What each kind of result must hold: ``content`` attribute -> condition -> {variable: dims}. The
#: condition ``None`` holds always, ``(attribute, value)`` when the result's attribute has that value.
_SCHEMAS: dict[str, dict[tuple[str, Any] | None, dict[str, Dims]]] = {}


def register_schema(content: str, variables: Mapping[str, Dims], when: tuple[str, Any] | None = None) -> None:
    """Declare the variables every result of kind ``content`` must hold.

    Called by the module that makes that kind of result, when it is imported.

    Parameters
    ----------
    content : str
        The result's ``content`` attribute, naming its kind.
    variables : mapping of str to tuple of str or None
        Variable name -> the dimensions it must have (``None``: any).
    when : (str, object), optional
        ``(attribute, value)``: the variables are required only of results
        whose attribute has that value (e.g. ``("method", "continuum")``);
        default: of every result of this kind.

    Registering the same ``content`` and ``when`` again replaces the variables.
    """
    _SCHEMAS.setdefault(content, {})[when] = dict(variables)


#: The figure of each kind of result: ``content`` attribute -> a function drawing a dataset of that kind.
_FIGURES: dict[str, Any] = {}


def register_figure(content: str, draw) -> None:
    """Declare how a result of kind ``content`` is drawn (called by the plotting module that draws it, when
    it is imported), so that a result object of a lower layer can offer ``.plot()`` without importing the
    plotting layer."""
    _FIGURES[content] = draw


def figure_of(dataset: xr.Dataset):
    """The drawing function registered for ``dataset``'s kind (its ``content`` attribute)."""
    load_registrars("figures")
    content = dataset.attrs.get("content")
    if content not in _FIGURES:
        raise ValueError(f"no figure is registered for content={content!r}; allowed: {sorted(_FIGURES)} "
                         "(the modules named in mdr_events/__init__.py register them)")
    return _FIGURES[content]


def dims_match(actual: tuple[str, ...], required: Dims, selected: Collection[str] = ()) -> bool:
    """Whether a variable's dimensions ``actual`` are the ``required`` ones of a schema (:data:`Dims`).

    ``None`` allows any; otherwise each dimension must be the one named, or one of the names of a tuple
    of alternatives, at its position. A required dimension named in ``selected`` (the dataset's scalar
    coordinates: what ``isel``/``sel`` of one label leaves, e.g. ``ds.isel(alpha=0)``) may be absent.
    """
    if required is None:
        return True
    names = [allowed if isinstance(allowed, tuple) else (allowed,) for allowed in required]
    kept = [allowed for allowed in names if not set(allowed) & set(selected) or set(allowed) & set(actual)]
    return len(actual) == len(kept) and all(name in allowed for name, allowed in zip(actual, kept))


def describe_dims(required: Dims) -> str:
    """A schema's dimensions for a message: ``('alpha' or 'case', 'time')``; ``any`` for ``None``."""
    if required is None:
        return "any"
    names = [" or ".join(map(repr, allowed)) if isinstance(allowed, tuple) else repr(allowed)
             for allowed in required]
    return f"({', '.join(names)}{',' if len(names) == 1 else ''})"


def registered_contents() -> list[str]:
    """The kinds of result (``content`` attributes) with a schema, sorted."""
    load_registrars("schemas")
    return sorted(_SCHEMAS)


def required_variables(content: str, attrs: Mapping[str, Any]) -> dict[str, Dims]:
    """The variables (name -> dims, ``None``: any) a result of kind ``content`` with ``attrs`` must hold.

    Raises ``ValueError`` if no schema is registered for ``content``.
    """
    load_registrars("schemas")
    if content not in _SCHEMAS:
        raise ValueError(f"unknown content {content!r}; allowed: {registered_contents()}")
    schema = dict(_SCHEMAS[content].get(None, {}))
    for condition, variables in _SCHEMAS[content].items():
        if condition is not None and attrs.get(condition[0]) == condition[1]:
            schema.update(variables)
    return schema
