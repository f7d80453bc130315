"""Result files: atomic netCDF writing, and reading back with a check against the result's schema.

A file is written to a temporary name beside its target and renamed into
place (:func:`atomic_write`), so that it is never seen half-written.
:func:`open_result` reads a file this package wrote and checks it against
the schema registered for its kind of result
(:func:`mdr_events.io.datasets.register_schema`).
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Any, Callable

import xarray as xr

from mdr_events.io.datasets import (PROGRAM, STAMP_ATTRIBUTES, describe_dims, dims_match, parameters_of,
                                   required_variables)

__all__ = ["atomic_write", "write_netcdf", "open_result"]


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


def open_result(path: str | os.PathLike) -> xr.Dataset:
    """Read a file written by this package, fully loaded, and check it against its schema.

    Raises ``ValueError`` naming what is wrong when the file is not a
    readable netCDF file, was not written by this package, lacks a stamp
    attribute or a parameter, or lacks a variable (or its ``units`` /
    ``long_name``) that its kind of result (``content``) must hold.
    """
    where = repr(os.fspath(path))
    dataset = _load_netcdf(path, where)
    _check_stamp(dataset, where)
    _check_variables(dataset, where)
    return dataset


def _load_netcdf(path: str | os.PathLike, where: str) -> xr.Dataset:
    """The netCDF file at ``path``, fully loaded (``ValueError`` if missing or unreadable)."""
    try:
        with xr.open_dataset(path, engine="scipy") as handle:
            return handle.load()
    except FileNotFoundError:
        raise ValueError(f"{where}: no such file") from None
    except (OSError, ValueError, TypeError, IndexError, KeyError) as error:
        raise ValueError(f"{where} is not a readable netCDF file ({type(error).__name__}: {error})") from None


def _check_stamp(dataset: xr.Dataset, where: str) -> None:
    """Raise ``ValueError`` unless this package wrote ``dataset`` with its full stamp and parameters."""
    if dataset.attrs.get("program") != PROGRAM:
        raise ValueError(f"{where} was not written by {PROGRAM} (attribute 'program' missing or different)")
    missing = [name for name in STAMP_ATTRIBUTES if name not in dataset.attrs]
    if missing:
        raise ValueError(f"{where} lacks the attribute(s) {missing}")
    try:
        parameters_of(dataset)
    except (ValueError, TypeError) as error:
        raise ValueError(f"{where}: {error}") from None


def _check_variables(dataset: xr.Dataset, where: str) -> None:
    """Raise ``ValueError`` unless ``dataset`` holds the labelled variables its kind of result must hold."""
    content = dataset.attrs["content"]
    try:
        schema = required_variables(content, dataset.attrs)
    except ValueError as error:
        raise ValueError(f"{where}: {error}") from None
    missing = [name for name in schema if name not in dataset.variables]
    if missing:
        raise ValueError(f"{where} ({content}) lacks the variable(s) {missing}")
    wrong = [f"{name} {dataset[name].dims} (expected {describe_dims(dims)})" for name, dims in schema.items()
             if not dims_match(dataset[name].dims, dims)]
    if wrong:
        raise ValueError(f"{where} ({content}) has variable(s) with the wrong dimensions: {'; '.join(wrong)}")
    unlabelled = [name for name in dataset.variables
                  if not {"units", "long_name"} <= set(dataset[name].attrs)]
    if unlabelled:
        raise ValueError(f"{where} ({content}) has variable(s) without units or long_name: {unlabelled}")
