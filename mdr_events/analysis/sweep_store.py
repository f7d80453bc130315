"""A sweep's Zarr store: its runs along a flat ``run`` dimension, one chunk per task, written as chunks complete and
read back on resuming (:class:`Store`); and the variables of the runs in any layout (:func:`run_variables`)."""

from __future__ import annotations

import os
from typing import Sequence

try:  # POSIX: a sweep locks its store while it runs, so that a second sweep never lays one out under it
    import fcntl
except ImportError:  # pragma: no cover - Windows: no lock (one sweep at a time per store is the user's care)
    fcntl = None  # type: ignore[assignment]

import numpy as np
import xarray as xr

from mdr_events._version import __version__
from mdr_events.analysis.sweep_runs import ERROR_CHARACTERS, HISTORY_QUANTITIES, QUANTITIES, ChunkResult
from mdr_events.io.files import check_output_file, prepare_output_directory
from mdr_events.validation import shown, shown_path
from mdr_events.io.paths import make_directories

__all__ = ["Store", "run_variables", "BYTES_PER_STORE_RUN", "BYTES_PER_SIGNATURE_RUN", "BYTES_PER_SIGNATURE_VALUE",
           "store_bytes"]

#: Bytes per run a store's set-up holds at once beyond the sweep's own arrays: its layout's ``error`` column (4 B a
#: character of :data:`~mdr_events.analysis.sweep_runs.ERROR_CHARACTERS`, 800 B) and its other columns, lists and the
#: writer's copy (measured with tracemalloc: 882 B a run between 2e3 and 2e4 runs of 2 names; 4 B a character plus
#: 160, rounded up; issue 32 round 28, X4: a 4e6-run sweep held 4.6 GB before its first run, under a 2 GiB limit).
BYTES_PER_STORE_RUN = 4 * ERROR_CHARACTERS + 160
#: Bytes per run and per swept value the store's signature peaks at (the grid's rows as JSON, through Python's
#: lists: measured 219, 312, 443 and 636 B a run for 1, 2, 4 and 8 names; 192 + 64 per name bounds each).
BYTES_PER_SIGNATURE_RUN, BYTES_PER_SIGNATURE_VALUE = 192, 64


def store_bytes(runs: int, names: int) -> int:
    """The memory a store takes before the first run (its signature and layout, or the store read back on resuming).

    Parameters
    ----------
    runs : int
        The sweep's runs.
    names : int
        The grid's swept names.

    Returns
    -------
    int
        Bytes, to count against ``Limits.memory`` (:data:`BYTES_PER_STORE_RUN` and the signature's per run).
    """
    return runs * (BYTES_PER_STORE_RUN + BYTES_PER_SIGNATURE_RUN + BYTES_PER_SIGNATURE_VALUE * names)


def run_variables(quantities: Sequence[str], values: np.ndarray, errors: Sequence[str],
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
    data = run_variables(quantities, values, errors, histories, ("run",), (len(errors),),
                         error_dtype=f"<U{ERROR_CHARACTERS}")
    data["done"] = (("run",), done.astype(np.int8), {"units": "1", "long_name": "1: the run's chunk is written"})
    return xr.Dataset(data)


def _flat_names(quantities: Sequence[str], history_samples: int | None) -> list[str]:
    """The variables of the store's layout (:func:`_flat_dataset`), each of which a resumed store must hold."""
    histories = [f"history_{name}" for name in HISTORY_QUANTITIES] if history_samples else []
    return [*quantities, *histories, "failed", "error", "done"]


#: The store's attribute naming the version of ``mdr_events`` that laid it out (its runs are that version's).
VERSION_ATTRIBUTE = "sweep_package_version"


def check_same_version(path: str, attrs: dict) -> None:
    """Refuse, in one line, to resume a store laid out by another version of ``mdr_events`` (or by one before the
    version was recorded): its runs were computed by that version's models, and resuming it would mix them with
    this version's in one result (issue 32, round 30)."""
    written = attrs.get(VERSION_ATTRIBUTE)
    if written != __version__:
        by = ("an earlier mdr_events that did not record its version" if written is None else
              f"mdr_events version {shown(written)}")
        raise ValueError(f"store={shown_path(path, quoted=True)} was written by {by}, not by this mdr_events "
                         f"{__version__} (its runs would "
                         "mix with this version's); allowed: resume=False (--restart) to run it afresh with this "
                         "version, or resume it with the version that wrote it")


def _read_back(path: str, signature: str, names: Sequence[str], runs: int) -> xr.Dataset:
    """The store of this sweep at ``path``, read whole to resume it; a one-line ``ValueError`` if it was written by
    another version of ``mdr_events`` (:func:`check_same_version`), if it holds another sweep, or if its layout or a
    chunk was cut short (a variable missing, of another length, unreadable).

    Read without its consolidated metadata, which the layout writes last: a store whose layout was interrupted
    printed xarray's warning of five lines, twice, and then ``No variable named 'done'. Variables on the dataset
    include [...]`` (issue 32, round 29)."""
    existing = xr.open_zarr(path, zarr_format=2, consolidated=False)
    check_same_version(path, existing.attrs)
    if existing.attrs.get("sweep_signature") != signature:
        raise ValueError(f"store={path!r} holds another sweep (other parameters, grid or options); "
                         "allowed: this sweep's store to resume, or resume=False to start it afresh")
    missing = [name for name in names if name not in existing.variables]
    loaded, damage = None, f"no variable {missing[0]!r}" if missing else None
    if not missing:
        try:
            loaded = existing[list(names)].load()
        except Exception as error:  # noqa: BLE001 - whatever the reader says of a damaged chunk, in one line
            damage = f"a chunk that cannot be read: {type(error).__name__}"
    if loaded is not None and loaded.sizes.get("run") != runs:
        damage = f"{loaded.sizes.get('run')} runs where the sweep has {runs}"
    if damage is not None:
        raise ValueError(f"store={path!r} holds this sweep cut short ({damage}; its layout or a write was "
                         "interrupted); allowed: resume=False (--restart) to start it afresh")
    return loaded


def _is_sweep_store(path: str) -> bool:
    """Whether ``path`` holds a Zarr store written by a sweep (its group has a ``sweep_signature``)."""
    try:
        return "sweep_signature" in xr.open_zarr(path, zarr_format=2, consolidated=False).attrs
    except Exception:  # noqa: BLE001 - anything that is not such a store, whatever the reader says of it
        return False


#: The lock file of a store ``<name>``: ``.<name>.lock`` beside it, held (``flock``, exclusive) while a sweep uses it.
LOCK_SUFFIX = ".lock"


def _locked(path: str):
    """An open file holding the exclusive lock of the store at ``path`` for this process (``None`` without locks),
    or a one-line ``ValueError`` if another sweep holds it (two sweeps laying out one store left it unreadable)."""
    if fcntl is None:
        return None
    name = os.path.join(os.path.dirname(os.path.abspath(path)), f".{os.path.basename(os.path.normpath(path))}"
                                                                  f"{LOCK_SUFFIX}")
    try:  # (the store's directory checked before, by prepare_output_directory)
        make_directories(os.path.dirname(name))
        handle = open(name, "a")  # noqa: SIM115 - held open while the sweep runs; closed by Store.close
    except OSError as error:
        raise ValueError(f"store={path!r} cannot be locked ({error.strerror or error}: {name!r}); allowed: a store in "
                         "a directory this user can write into") from None
    try:
        fcntl.flock(handle.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        handle.close()
        raise ValueError(f"store={path!r} is in use by another sweep (its lock {name!r} is held); allowed: a store "
                         "no other sweep is writing (wait for it to end, or give this sweep another store)") from None
    return handle


class Store:
    """A Zarr store holding the sweep's runs along a flat ``run`` dimension, one chunk per task.

    ``signature`` says which sweep a store holds: resuming another sweep's store is refused.
    """

    def __init__(self, path: str | os.PathLike, signature: str, quantities: Sequence[str], runs: int, chunk: int,
                 resume: bool, history_samples: int | None = None):
        self.path, self.chunk, self.quantities = os.fspath(path), chunk, tuple(quantities)
        if not os.path.exists(self.path):
            prepare_output_directory(self.path, "store")
            # (its parent takes it as an output directory takes a file: not the root, no temporary marker)
            parent = os.path.dirname(os.path.abspath(self.path))
            check_output_file("store", os.path.join(parent, os.path.basename(os.path.normpath(self.path))))
        self._lock = _locked(self.path)  # (before the store is read: a sweep laying it out is not "another's")
        try:
            is_store = _is_sweep_store(self.path)
            if os.path.exists(self.path) and not is_store and (not os.path.isdir(self.path) or os.listdir(self.path)):
                raise ValueError(f"store={self.path!r} exists and is not a sweep's store; allowed: a new path, an empty "
                                 "directory or a sweep's store (nothing else is overwritten)")
            if resume and is_store:
                self.existing = _read_back(self.path, signature, _flat_names(self.quantities, history_samples), runs)
                return
            self._lay_out(signature, runs, chunk, history_samples)
            self.existing = None
        except BaseException:  # (a refusal releases the lock: its traceback may keep this object alive)
            self.close()
            raise

    def _lay_out(self, signature: str, runs: int, chunk: int, history_samples: int | None) -> None:
        """Write the empty store (every run not done) before the first run."""
        histories = None if not history_samples else np.full((runs, len(HISTORY_QUANTITIES), history_samples), np.nan)
        template = _flat_dataset(self.quantities, np.full((runs, len(self.quantities)), np.nan), [""] * runs,
                                 np.zeros(runs, bool), histories)
        template.attrs["sweep_signature"] = signature
        template.attrs[VERSION_ATTRIBUTE] = __version__
        encoding = {name: {"chunks": (chunk,) + template[name].shape[1:]} for name in template.data_vars}
        try:
            template.to_zarr(self.path, mode="w", zarr_format=2, encoding=encoding, compute=True)
        except OSError as error:  # what the checks before cannot see (/proc, a full disk, a read-only mount)
            raise ValueError(f"store={self.path!r} cannot be written ({error.strerror or error}); allowed: "
                             "a directory this user can create and write into") from None

    def close(self) -> None:
        """Release the store's lock (another sweep may then use it)."""
        if self._lock is not None:
            self._lock.close()
            self._lock = None

    def done(self) -> np.ndarray | None:
        """Which runs the store holds already (``None``: a new store)."""
        return None if self.existing is None else self.existing["done"].values.astype(bool)

    def write(self, start: int, result: ChunkResult) -> None:
        """Write a chunk's runs into their region, marked done."""
        part = _flat_dataset(self.quantities, result.values, result.errors, np.ones(len(result.errors), bool),
                             result.histories)
        part.to_zarr(self.path, region={"run": slice(start, start + len(result.errors))}, zarr_format=2,
                     consolidated=False)  # (the layout's metadata, consolidated or not if it was cut short: as it is)
