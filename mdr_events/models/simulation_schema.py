"""A simulation's result, one schema for every method: its variables, how each is computed (its accuracy), and the
dataset assembled from a method's raw arrays (:func:`simulation_dataset`, the continuum's :func:`event_log` and
:func:`extrema_dataset`)."""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
import xarray as xr

from mdr_events.io.agreement import (ExtremumTime, Integrated, Quotient, RootFound, RoundOff, force_sensitivity,
                                     register_accuracy)
from mdr_events.io.datasets import assembled, register_schema, stamp
from mdr_events.models.continuum.extrema import EXTREMA_KINDS, EXTREMA_QUANTITIES, extremum_names
from mdr_events.models.continuum.span_extrema import EXTREMUM_XTOL
from mdr_events.models.motion import ANGLE_DIMENSION, CASE_DIMENSIONS, CUSTOM_DIMENSION, CUSTOM_SCENARIO, Cases
from mdr_events.parameters import Parameters

__all__ = ["SIMULATION_CONTENT", "SIMULATION_VARIABLES", "EVENT_VARIABLES", "PATH_VARIABLES", "EXTREMA_VARIABLES",
           "CONTINUUM_ACCURACY", "simulation_dataset", "continuum_dataset", "event_log", "extrema_dataset",
           "coordinates_last"]

#: The ``content`` attribute of a simulation.
SIMULATION_CONTENT = "simulation of indentation and detachment along straight paths"
#: The variables of a simulation, shared by every method (dims ``(case dimension, "time")``): name -> (units, long_name).
SIMULATION_VARIABLES: dict[str, tuple[str, str]] = {
    "indentation_depth": ("m", "indentation depth d"),
    "tangential_displacement": ("m", "tangential displacement of the indenter x"),
    "normal_force": ("N", "normal force F_N"),
    "tangential_force": ("N", "tangential force F_x"),
    "contact_radius": ("m", "contact radius a"),
    "contact_area": ("m2", "contact area A"),
    "mean_pressure": ("Pa", "mean contact pressure <p> = F_N / A"),
    "mean_shear_stress": ("Pa", "mean shear stress tau = F_x / A"),
    "sliding_fraction": ("1", "share of the springs in contact that are at the critical shift"),
}
#: The continuum method's event log (dims ``(case dimension, "event")``): name -> (units, long_name).
EVENT_VARIABLES: dict[str, tuple[str, str]] = {
    "event_time": ("s", "time of the event from first contact"),
    "event_kind": ("1", "kind of event"),
    "event_depth": ("m", "indentation depth at the event"),
    "event_radius": ("m", "contact radius at the event"),
    "event_x": ("m", "tangential displacement at the event"),
    "event_direction": ("1", "direction of the event: +1 or -1 the cap u = +ū or -ū of a slip event, or the new "
                             "direction of the tangential motion at a reversal; 0 for other events and padding"),
}
#: Custom paths: what each case's path is (dims ``("case",)``): name -> (units, long_name).
PATH_VARIABLES: dict[str, tuple[str, str]] = {
    "path_waypoints": ("m", "waypoints (x, d) of the custom path, joined by straight segments"),
    "path_speed": ("m s-1", "speed along the custom path (replaces param_v)"),
}
#: Symbols of the quantities of :data:`EXTREMA_QUANTITIES` and their units, for the long names.
EXTREMA_SYMBOLS = {"normal_force": ("F_N", "N"), "tangential_force": ("F_x", "N"), "contact_area": ("A", "m2")}
EXTREMA_WORDS = {"max": "maximum", "min": "minimum"}


def _extrema_variables() -> dict[str, tuple[str, str]]:
    """Name -> (units, long_name) of every key of :func:`solution_extrema`."""
    variables = {}
    for quantity in EXTREMA_QUANTITIES:
        symbol, units = EXTREMA_SYMBOLS[quantity]
        for kind in EXTREMA_KINDS:
            value_name, time_name = extremum_names(quantity, kind)
            word = EXTREMA_WORDS[kind]
            variables[value_name] = (units, f"{word} of {symbol} over the run, exact from the continuum solution "
                                            "(not from the samples)")
            variables[time_name] = ("s", f"time of the {word} of {symbol} from first contact, exact from the "
                                         "continuum solution")
    return variables


#: The continuum method's exact extrema (dims ``(case dimension,)``; :func:`solution_extrema`, where the
#: value 0 after a pull-off counts, at the end of the run): name -> (units, long_name).
EXTREMA_VARIABLES: dict[str, tuple[str, str]] = _extrema_variables()

#: Each variable's attributes, built once (a variable copies what it is given): name -> {"units", "long_name"}.
VARIABLE_ATTRS = {name: {"units": units, "long_name": long_name} for name, (units, long_name) in
                  {**SIMULATION_VARIABLES, **EVENT_VARIABLES, **PATH_VARIABLES, **EXTREMA_VARIABLES}.items()}
#: The attributes of the coordinates: the angles, a custom path's label, the time and the event's number.
ANGLE_ATTRS = {"units": "degree", "long_name": "path angle to the surface"}
LABEL_ATTRS = {"units": "1", "long_name": "label of the custom path"}
TIME_ATTRS = {"units": "s", "long_name": "time from first contact"}
EVENT_NUMBER_ATTRS = {"units": "1", "long_name": "event number"}

register_schema(SIMULATION_CONTENT, {name: (CASE_DIMENSIONS, "time") for name in SIMULATION_VARIABLES})
register_schema(SIMULATION_CONTENT, {**{name: (CASE_DIMENSIONS, "event") for name in EVENT_VARIABLES},
                                     **{name: (CASE_DIMENSIONS,) for name in EXTREMA_VARIABLES}},
                when=("method", "continuum"))
register_schema(SIMULATION_CONTENT, {name: (CUSTOM_DIMENSION,) for name in PATH_VARIABLES},
                when=("scenario", CUSTOM_SCENARIO))

#: How each quantity of a simulation is computed (:mod:`mdr_events.io.agreement`). The discrete model: closed
#: forms of the path and sums over the springs; the means are quotients by the area.
MEANS = {"mean_pressure": Quotient("normal_force", "contact_area"),
         "mean_shear_stress": Quotient("tangential_force", "contact_area")}
register_accuracy(SIMULATION_CONTENT, {**{name: RoundOff() for name in SIMULATION_VARIABLES}, **MEANS,
                                       "time": RoundOff(), ANGLE_DIMENSION: RoundOff(), "path_speed": RoundOff()})


def _continuum_accuracy() -> dict:
    """How the continuum computes what differs from the discrete model: the path is a closed form of time; ``F_N``,
    ``a`` and ``A`` closed forms of the radius, a root found to ``radius_rtol``; ``F_x`` and the springs' slip
    integrated to ``rtol``, and so the events (crossings of integrated quantities); each extremum as accurate as
    its quantity, its time as the curvature there allows."""
    integrated = {name: Integrated() for name in EVENT_VARIABLES if name not in ("event_kind", "event_direction")}
    declared = {"normal_force": RootFound(sensitivity=force_sensitivity), "contact_radius": RootFound(),
                "contact_area": RootFound(sensitivity=2.0),
                "tangential_force": Integrated(), "sliding_fraction": Integrated(), **integrated}
    for quantity in EXTREMA_QUANTITIES:
        for kind in EXTREMA_KINDS:
            value, time = extremum_names(quantity, kind)
            declared[value] = dataclasses.replace(declared[quantity], scale_of=quantity)
            declared[time] = ExtremumTime(value, quantity, search_share=EXTREMUM_XTOL)
    return declared


CONTINUUM_ACCURACY = _continuum_accuracy()
register_accuracy(SIMULATION_CONTENT, CONTINUUM_ACCURACY, when=("method", "continuum"))



def coordinates_last(dataset: xr.Dataset) -> xr.Dataset:
    """The same dataset with its data variables first and its coordinates last, as xarray reads a file back.

    The netCDF3 writer orders variables by shape and keeps the dataset's order among equal shapes (a
    coordinate along the cases and a per-case variable); in the order a file is read back, a result read
    and written again gives the same bytes.
    """
    return xr.Dataset({name: dataset[name].variable for name in dataset.data_vars},
                      coords={name: dataset[name].variable for name in dataset.coords}, attrs=dataset.attrs)


def event_log(events: list[list[tuple]], dimension: str = ANGLE_DIMENSION) -> xr.Dataset:
    """The continuum event log: one row per event per case along ``(dimension, "event")`` (padded with
    nan / "" / direction 0); the variables of :data:`EVENT_VARIABLES`."""
    variables, coords = _event_parts(events, dimension)
    return xr.Dataset(variables, coords=coords)


def _event_parts(events: list[list[tuple]], dimension: str) -> tuple[dict, dict]:
    """The variables and the coordinate of :func:`event_log`, as ``xarray.Dataset`` takes them."""
    rows = max(len(case) for case in events)
    table = {name: np.full((len(events), rows), np.nan) for name in ("time", "depth", "radius", "x")}
    kinds = np.full((len(events), rows), "", dtype=object)
    directions = np.zeros((len(events), rows), dtype=np.int32)  # int32: netCDF3 has no 64-bit integers
    for i, case in enumerate(events):
        for j, (time, kind, depth, radius, x, direction) in enumerate(case):
            table["time"][i, j], table["depth"][i, j] = time, depth
            table["radius"][i, j], table["x"][i, j] = radius, x
            kinds[i, j], directions[i, j] = kind, direction
    values = {"event_time": table["time"], "event_kind": kinds.astype(str), "event_depth": table["depth"],
              "event_radius": table["radius"], "event_x": table["x"], "event_direction": directions}
    return ({name: ((dimension, "event"), values[name], VARIABLE_ATTRS[name]) for name in EVENT_VARIABLES},
            {"event": ("event", np.arange(rows), EVENT_NUMBER_ATTRS)})


def extrema_dataset(extrema: list[dict[str, float]], dimension: str = ANGLE_DIMENSION) -> xr.Dataset:
    """The variables of :data:`EXTREMA_VARIABLES` along ``dimension``, one
    :func:`~mdr_events.models.continuum.extrema.solution_extrema` per case."""
    return xr.Dataset(_extrema_parts(extrema, dimension))


def _extrema_parts(extrema: list[dict[str, float]], dimension: str) -> dict:
    """The variables of :func:`extrema_dataset`, as ``xarray.Dataset`` takes them."""
    return {name: ((dimension,), np.array([case[name] for case in extrema], dtype=float), VARIABLE_ATTRS[name])
            for name in EXTREMA_VARIABLES}


def simulation_dataset(
    params: Parameters,
    cases: Cases,
    time: np.ndarray,
    values: dict[str, np.ndarray],
    **attrs: Any,
) -> xr.Dataset:
    """Assemble a simulation result with dims ``(cases.dimension, "time")``.

    ``values`` holds the kinematics, forces, radius and sliding fraction of
    :data:`SIMULATION_VARIABLES` (shape (n_cases, n_time), ``nan`` after a
    case has ended); the area, mean pressure and mean shear stress are
    derived here, identically for every method. Custom paths add
    :data:`PATH_VARIABLES` along ``case``. ``attrs`` go to
    :func:`mdr_events.io.datasets.stamp`.
    """
    data, coords = _simulation_parts(cases, time, values, attrs)
    return stamp(assembled(data, coords), params, **attrs)


def continuum_dataset(params: Parameters, cases: Cases, time: np.ndarray, values: dict[str, np.ndarray],
                      events: list[list[tuple]], extrema: list[dict[str, float]], **attrs: Any) -> xr.Dataset:
    """A continuum result: :func:`simulation_dataset`, then the variables of :func:`event_log` and of
    :func:`extrema_dataset`, built as one dataset (variables, coordinates and attributes in the order that merging
    the three gives; assembled at once, :func:`~mdr_events.io.datasets.assembled`, instead of four merges).

    Parameters
    ----------
    params : Parameters
        The parameters stamped on the result.
    cases : Cases
        The cases (their dimension, labels and paths).
    time : numpy.ndarray
        The output times (s from first contact).
    values : dict of str to numpy.ndarray
        The filled quantities, as for :func:`simulation_dataset`.
    events : list of list of tuple
        Each case's event log, as for :func:`event_log`.
    extrema : list of dict of str to float
        Each case's extrema, as for :func:`extrema_dataset`.
    **attrs
        Attributes, as for :func:`simulation_dataset`.

    Returns
    -------
    xarray.Dataset
        The dataset.
    """
    data, coords = _simulation_parts(cases, time, values, attrs)
    event_data, event_coords = _event_parts(events, cases.dimension)
    return stamp(assembled({**data, **event_data, **_extrema_parts(extrema, cases.dimension)},
                           {**coords, **event_coords}), params, **attrs)


def _simulation_parts(cases: Cases, time: np.ndarray, values: dict[str, np.ndarray],
                      attrs: dict[str, Any]) -> tuple[dict, dict]:
    """The variables and coordinates of :func:`simulation_dataset` (a custom path's note added to ``attrs``)."""
    dimension = cases.dimension
    radius = values["contact_radius"]
    area = np.pi * radius**2
    in_contact = area > 0  # (the means where there is an area; nan elsewhere, without dividing there)
    derived = {
        "contact_area": area,
        "mean_pressure": np.divide(values["normal_force"], area, out=np.full_like(area, np.nan), where=in_contact),
        "mean_shear_stress": np.divide(values["tangential_force"], area, out=np.full_like(area, np.nan),
                                       where=in_contact),
    }
    data = {}
    for name in SIMULATION_VARIABLES:
        array = derived[name] if name in derived else values[name]
        data[name] = ((dimension, "time"), np.asarray(array, dtype=float), VARIABLE_ATTRS[name])
    if cases.custom:
        described = {"path_waypoints": np.array([path.describe() for path in cases.paths], dtype=str),
                     "path_speed": np.array([path.speed for path in cases.paths], dtype=float)}
        for name in PATH_VARIABLES:
            data[name] = ((dimension,), described[name], VARIABLE_ATTRS[name])
        attrs["note"] = "custom paths: each case's speed path_speed replaces param_v"
        label = LABEL_ATTRS
        case_coordinate = np.asarray(cases.labels, dtype=str)
    else:
        label = ANGLE_ATTRS
        case_coordinate = np.asarray(cases.labels, dtype=float)
    coords = {dimension: (dimension, case_coordinate, label), "time": ("time", np.asarray(time, dtype=float), TIME_ATTRS)}
    return data, coords
