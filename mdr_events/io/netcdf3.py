"""Writing a dataset in memory as a netCDF-3 file (the scipy backend, 64-bit offsets) without asking dask for its
scheduler.

xarray's ``Dataset.to_netcdf`` asks dask which scheduler is active twice on every write (to pick the file's write
lock, ``backends.locks.get_write_lock``, and whether to close the file after each write,
``backends.writers._get_netcdf_autoclose``), and that question imports ``dask.distributed`` (some 0.4 s, each
command line verb paying it). A dataset whose arrays are in memory needs neither answer: no task writes to the file
but this thread. :func:`write_netcdf3` opens xarray's scipy store with a lock of its own (a fresh
``threading.Lock``: the store is the file's only writer) and dumps the dataset into it
(``Dataset.dump_to_store``: each array written as it is), so that the file is the one ``to_netcdf`` writes, byte for
byte (``tests/io/test_netcdf3.py``). A dataset with chunked (dask) arrays goes through ``to_netcdf``, whose scheduler
computes them.
"""

from __future__ import annotations

import numbers
import threading
from pathlib import Path

import numpy as np
import xarray as xr

__all__ = ["NETCDF3_FORMAT", "ATTRIBUTE_TYPES", "write_netcdf3", "check_netcdf_names"]

#: The netCDF format written: netCDF-3 with 64-bit offsets (files over 2 GiB), which the scipy backend writes.
NETCDF3_FORMAT = "NETCDF3_64BIT"
#: The values an attribute may take, as ``to_netcdf`` allows them (a number, a text, an array or a list of them).
ATTRIBUTE_TYPES = (str, numbers.Number, np.ndarray, np.number, list, tuple, bytes)


def check_netcdf_names(dataset: xr.Dataset) -> None:
    """Refuse a variable or attribute name that is not a non-empty text, and an attribute value of none of
    :data:`ATTRIBUTE_TYPES`: the checks ``to_netcdf`` makes before it writes.

    Parameters
    ----------
    dataset : xarray.Dataset
        The dataset to write.

    Raises
    ------
    ValueError
        An empty name.
    TypeError
        A name that is no text, or an attribute value of another type (named with its value).
    """
    def check_name(name, what: str) -> None:
        if not isinstance(name, str):
            raise TypeError(f"Invalid name {name!r} for {what}: must be a string for serialization to netCDF files")
        if not name:
            raise ValueError(f"Invalid name {name!r} for {what}: string must be length 1 or greater for "
                             "serialization to netCDF files")

    for attrs in [dataset.attrs, *(variable.attrs for variable in dataset.variables.values())]:
        for name, value in attrs.items():
            check_name(name, "attr")
            if not isinstance(value, ATTRIBUTE_TYPES):
                raise TypeError(f"Invalid value for attr {name!r}: {value!r}. For serialization to netCDF files, its "
                                f"value must be of one of the following types: "
                                f"{', '.join(kind.__name__ for kind in ATTRIBUTE_TYPES)}")
    for name in dataset.variables:
        check_name(name, "a variable")


def write_netcdf3(dataset: xr.Dataset, path: str | Path) -> None:
    """Write ``dataset`` to ``path`` as netCDF-3 (:data:`NETCDF3_FORMAT`, the scipy backend), the file
    ``dataset.to_netcdf(path, engine="scipy", format=NETCDF3_FORMAT)`` writes, without asking dask for its scheduler.

    Parameters
    ----------
    dataset : xarray.Dataset
        The dataset; with chunked (dask) arrays it is written by ``to_netcdf`` (the scheduler computes them).
    path : str or pathlib.Path
        The file (created or overwritten).

    Raises
    ------
    ValueError, TypeError, OverflowError
        What netCDF-3 cannot hold (:func:`check_netcdf_names`; an integer beyond 32 bits, in xarray's words).
    """
    if any(variable.chunks is not None for variable in dataset.variables.values()):
        dataset.to_netcdf(path, engine="scipy", format=NETCDF3_FORMAT)
        return
    check_netcdf_names(dataset)
    unlimited = dataset.encoding.get("unlimited_dims")  # (as to_netcdf reads it: a dataset read from a file)
    if isinstance(unlimited, str):
        unlimited = [unlimited]
    store = xr.backends.ScipyDataStore(str(path), mode="w", format=NETCDF3_FORMAT, lock=threading.Lock())
    try:
        dataset.dump_to_store(store, unlimited_dims=None if unlimited is None else set(unlimited))
    finally:
        store.close()
