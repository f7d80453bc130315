"""Labelled results: stamping, atomic netCDF writing and reading back.

Every dataset the package writes carries ``units`` and ``long_name`` on each
variable and, in its attributes, the program, its version, the paper's DOI
and every model parameter (tamaas-style provenance), all netCDF-safe (str,
float, int), so that :func:`open_result` can rebuild the :class:`Parameters`.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Any, Callable

import numpy as np
import xarray as xr

from mdr_events._version import __version__
from mdr_events.parameters import Parameters

__all__ = ["DOI", "REFERENCE", "stamp", "atomic_write", "write_netcdf", "open_result", "parameters_of",
           "RESULT_RTOL", "result_differences", "assert_results_agree"]

DOI = "10.3390/biomimetics8060477"
REFERENCE = (
    "I. A. Lyashenko, V. L. Popov, V. Borysiuk, Indentation and Detachment in Adhesive "
    "Contacts between Soft Elastomer and Rigid Indenter at Simultaneous Motion in Normal "
    "and Tangential Direction: Experiments and Simulations, Biomimetics 8(6), 477 (2023), section 4"
)
PROGRAM = "mdr_events"


def _netcdf_safe(value: Any) -> Any:
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
    dataset.attrs.update(
        {
            "program": PROGRAM,
            "program_version": __version__,
            "doi": DOI,
            "reference": REFERENCE,
            "Conventions": "CF-1.8",
        }
    )
    dataset.attrs.update(params.to_attrs())
    if params.preset_name() is not None:
        dataset.attrs["inferred_parameters"] = ", ".join(Parameters.INFERRED_FIELDS)
        dataset.attrs["inferred_parameters_note"] = (
            f"{params.preset_name()}: these fields are inferred, not stated in section 4 of the paper "
            "(see mdr_events.Parameters.paper)")
    dataset.attrs.update({key: _netcdf_safe(value) for key, value in attrs.items()})
    for name, variable in dataset.variables.items():
        missing = [key for key in ("units", "long_name") if key not in variable.attrs]
        if missing:
            raise ValueError(f"variable {name!r} lacks attribute(s) {missing}")
    return dataset


def atomic_write(path: str | os.PathLike, write: Callable[[str], Any], suffix: str = ".tmp") -> Path:
    """Call ``write(temporary_path)``, then rename the file onto ``path``.

    An interrupted or failing writer leaves the old file (or none), never a
    half-written one; the temporary file sits beside the target so that the
    rename is atomic.
    """
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=suffix, dir=target.parent)
    os.close(handle)
    try:
        write(temporary)
        mask = os.umask(0)  # mkstemp makes the file owner-only; give it the usual permissions
        os.umask(mask)
        os.chmod(temporary, 0o666 & ~mask)
        os.replace(temporary, target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return target


def write_netcdf(dataset: xr.Dataset, path: str | os.PathLike) -> Path:
    """Write ``dataset`` as netCDF to ``path`` atomically (see :func:`atomic_write`).

    The scipy backend (netCDF3, 64-bit offset) is used so that no further
    dependency is needed.
    """
    return atomic_write(path, lambda temporary: dataset.to_netcdf(
        temporary, engine="scipy", format="NETCDF3_64BIT"), suffix=".nc")


#: What each kind of result must hold: ``content`` attribute → {variable: dims}.
#: (Simulation variables are added below, once :data:`SIMULATION_VARIABLES` is defined.)
RESULT_SCHEMAS: dict[str, dict[str, tuple[str, ...]]] = {
    "phase diagram of slip onset": {"d_crit_hertz": None, "d_crit_jkr": None, "d_max": (),
                                    "critical_angle_hertz": (), "critical_angle_jkr": ()},
    "slip-onset cross-check": {name: ("alpha",) for name in (
        "d_crit_closed_form", "d_crit_continuum", "d_crit_discrete", "discrete_minus_continuum",
        "discrete_tolerance", "pinned_radius", "disagree")},
}
#: Variables of the continuum event log (dims ``("alpha", "event")``).
EVENT_VARIABLES = ("event_time", "event_kind", "event_depth", "event_radius", "event_x")
#: Attributes every result carries.
STAMP_ATTRIBUTES = ("program", "program_version", "doi", "content")


def open_result(path: str | os.PathLike) -> xr.Dataset:
    """Read a file written by this package, fully loaded, and check it against its schema.

    Raises ``ValueError`` naming what is wrong when the file is not a
    readable netCDF file, was not written by this package, lacks a stamp
    attribute or a parameter, or lacks a variable (or its ``units`` /
    ``long_name``) that its kind of result (``content``) must hold.
    """
    where = repr(os.fspath(path))
    try:
        with xr.open_dataset(path, engine="scipy") as handle:
            dataset = handle.load()
    except FileNotFoundError:
        raise ValueError(f"{where}: no such file") from None
    except (OSError, ValueError, TypeError, IndexError, KeyError) as error:
        raise ValueError(f"{where} is not a readable netCDF file ({type(error).__name__}: {error})") from None
    if dataset.attrs.get("program") != PROGRAM:
        raise ValueError(f"{where} was not written by {PROGRAM} (attribute 'program' missing or different)")
    missing = [name for name in STAMP_ATTRIBUTES if name not in dataset.attrs]
    if missing:
        raise ValueError(f"{where} lacks the attribute(s) {missing}")
    try:
        parameters_of(dataset)
    except (ValueError, TypeError) as error:
        raise ValueError(f"{where}: {error}") from None
    content = dataset.attrs["content"]
    if content not in RESULT_SCHEMAS:
        raise ValueError(f"{where}: unknown content {content!r}; allowed: {sorted(RESULT_SCHEMAS)}")
    schema = dict(RESULT_SCHEMAS[content])
    if dataset.attrs.get("method") == "continuum":
        schema.update({name: ("alpha", "event") for name in EVENT_VARIABLES})
    missing = [name for name in schema if name not in dataset.variables]
    if missing:
        raise ValueError(f"{where} ({content}) lacks the variable(s) {missing}")
    wrong = [f"{name} {dataset[name].dims} (expected {dims})" for name, dims in schema.items()
             if dims is not None and dataset[name].dims != dims]
    if wrong:
        raise ValueError(f"{where} ({content}) has variable(s) with the wrong dimensions: {'; '.join(wrong)}")
    unlabelled = [name for name in dataset.variables
                  if not {"units", "long_name"} <= set(dataset[name].attrs)]
    if unlabelled:
        raise ValueError(f"{where} ({content}) has variable(s) without units or long_name: {unlabelled}")
    return dataset


def parameters_of(dataset: xr.Dataset) -> Parameters:
    """The :class:`Parameters` a dataset was computed with."""
    return Parameters.from_attrs(dataset.attrs)


#: The schema of a simulation result, shared by every method: name -> (units, long_name).
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
RESULT_SCHEMAS["simulation of indentation and detachment along straight paths"] = {
    name: ("alpha", "time") for name in SIMULATION_VARIABLES}


def simulation_dataset(
    params: Parameters,
    alpha: np.ndarray,
    time: np.ndarray,
    values: dict[str, np.ndarray],
    **attrs: Any,
) -> xr.Dataset:
    """Assemble a simulation result with dims ``("alpha", "time")``.

    ``values`` holds the kinematics, forces, radius and sliding fraction of
    :data:`SIMULATION_VARIABLES` (shape (n_alpha, n_time), ``nan`` after a
    case has ended); the area, mean pressure and mean shear stress are
    derived here, identically for every method.
    """
    radius = values["contact_radius"]
    area = np.pi * radius**2
    with np.errstate(invalid="ignore", divide="ignore"):
        derived = {
            "contact_area": area,
            "mean_pressure": np.where(area > 0, values["normal_force"] / area, np.nan),
            "mean_shear_stress": np.where(area > 0, values["tangential_force"] / area, np.nan),
        }
    data = {}
    for name, (units, long_name) in SIMULATION_VARIABLES.items():
        array = derived[name] if name in derived else values[name]
        data[name] = (("alpha", "time"), np.asarray(array, dtype=float), {"units": units, "long_name": long_name})
    coords = {
        "alpha": ("alpha", np.asarray(alpha, dtype=float), {"units": "degree", "long_name": "path angle to the surface"}),
        "time": ("time", np.asarray(time, dtype=float), {"units": "s", "long_name": "time from first contact"}),
    }
    return stamp(xr.Dataset(data, coords=coords), params, **attrs)


#: Relative tolerance within which a result computed on another machine or with other library versions
#: agrees with a committed one. The continuum method integrates ``F_x`` with ``rtol = 1e-10``: a rounding
#: difference (another NumPy's SIMD path, another SciPy's lambdified ``math``) that tips one step of the
#: adaptive integrator from accepted to rejected moves ``F_x`` by up to that local error control. All other
#: values (closed forms, roots converged to a few ulp, sums over springs) differ by about 1e-13, far below
#: it. The differences seen between library versions were 2.5e-14 (simulations) and 6e-16 (phase diagrams).
RESULT_RTOL = 1e-10


def _float_differences(name: str, actual: np.ndarray, expected: np.ndarray, rtol: float) -> list[str]:
    """Differences of one floating-point array: non-finite entries exactly, finite ones within ``rtol``
    of the array's largest finite magnitude (values near a zero crossing carry the rounding of the
    larger terms they are computed from, e.g. ``F_N`` as a difference of two integrals)."""
    same_pattern = (np.isnan(actual) == np.isnan(expected)) & (np.isinf(actual) == np.isinf(expected))
    if not np.all(same_pattern):
        return [f"{name}: nan/inf at {int(np.count_nonzero(~same_pattern))} other place(s)"]
    infinite = np.isinf(expected)
    if np.any(actual[infinite] != expected[infinite]):
        return [f"{name}: infinities of other sign"]
    finite = np.isfinite(expected)
    if not finite.any():
        return []
    scale = float(np.max(np.abs(expected[finite])))
    worst = float(np.max(np.abs(actual[finite] - expected[finite])))
    if worst > rtol * scale:
        return [f"{name}: differs by {worst:.3g}, {worst / scale:.3g} of its largest magnitude {scale:.3g} "
                f"(allowed: {rtol:g})"]
    return []


#: NumPy dtype kinds that hold strings (unicode, bytes, or Python objects as netCDF returns them).
_STRING_KINDS = {"U", "S", "O"}


def result_differences(actual: xr.Dataset, expected: xr.Dataset, rtol: float = RESULT_RTOL) -> list[str]:
    """How ``actual`` differs from ``expected`` beyond the tolerance of another environment ([] if not).

    Exact: dimensions and their sizes, the names of variables and coordinates, every attribute (of the
    dataset and of each variable), and arrays of integers and strings (e.g. event kinds). Floating-point
    arrays agree where their ``nan`` and ``inf`` match exactly and their finite values agree within
    ``rtol`` of the array's largest finite magnitude (:data:`RESULT_RTOL`).
    """
    found: list[str] = []
    if dict(actual.sizes) != dict(expected.sizes):
        return [f"dimensions {dict(actual.sizes)} instead of {dict(expected.sizes)}"]
    if set(actual.variables) != set(expected.variables):
        return [f"variables {sorted(actual.variables)} instead of {sorted(expected.variables)}"]
    if actual.attrs != expected.attrs:
        keys = sorted(key for key in set(actual.attrs) | set(expected.attrs)
                      if actual.attrs.get(key) != expected.attrs.get(key))
        found.append(f"attributes {keys} differ")
    for name in sorted(expected.variables):
        mine, theirs = actual[name].variable, expected[name].variable
        if mine.dims != theirs.dims or mine.attrs != theirs.attrs:
            found.append(f"{name}: dimensions or attributes differ")
            continue
        values, reference = np.asarray(mine.values), np.asarray(theirs.values)
        kinds = {values.dtype.kind, reference.dtype.kind}
        if kinds == {"f"}:
            found += _float_differences(name, values, reference, rtol)
        elif kinds <= _STRING_KINDS:  # netCDF gives strings back as objects
            if values.shape != reference.shape or not np.array_equal(values.astype(str), reference.astype(str)):
                found.append(f"{name}: strings differ")
        elif len(kinds) > 1 or not np.array_equal(values, reference):
            found.append(f"{name}: values differ ({values.dtype} and {reference.dtype} compared exactly)")
    return found


def assert_results_agree(actual: xr.Dataset, expected: xr.Dataset, rtol: float = RESULT_RTOL) -> None:
    """Raise ``AssertionError`` listing :func:`result_differences` if there are any."""
    found = result_differences(actual, expected, rtol)
    if found:
        raise AssertionError("results disagree: " + "; ".join(found))
