"""Result files: atomic writing and reading back with a check against the result's schema (the paths are checked
first by :mod:`mdr_events.io.paths`, whose checks this module also gives).

A file is written to a temporary name beside its target and renamed into
place (:func:`atomic_write`), so that it is never seen half-written.
:func:`prepare_output_directory` checks an output directory before anything
is computed; :func:`check_output_stem` checks a file-name stem that a user
chose. :func:`open_result` reads a file this package wrote and checks it
against the schema registered for its kind of result
(:func:`mdr_events.io.datasets.register_schema`).

Temporary files
---------------
A temporary file is named ``.<target name>.mdr-tmp-<random><suffix>``
(:data:`TEMPORARY_MARKER`, :func:`is_temporary_name`). Its writer holds an
exclusive lock (``flock``) on it while writing; an exception, Ctrl-C or (in
``mdr-events``) SIGTERM removes it. A writer killed outright (SIGKILL, power
loss) leaves it behind: every :func:`atomic_write` first removes the *stale*
temporary files of its directory (:func:`remove_stale_temporaries`), those
last modified before the running process started and not locked by any
process, i.e. left by a writer that is gone.
"""

from __future__ import annotations

import os
import signal
import tempfile
import threading
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable, NamedTuple, Sequence

import xarray as xr

from mdr_events.io.datasets import (PROGRAM, STAMP_ATTRIBUTES, describe_dims, dims_match, parameters_of,
                                   required_variables)
from mdr_events.contact import Contact
from mdr_events.io import netcdf3
from mdr_events.limits import ResourceLimitError
from mdr_events.io.paths import (ALLOWED_FILE, ALLOWED_PATH, TEMPORARY_MARKER, check_file_path,  # noqa: F401 - as before
                                 check_output_file, check_output_stem, input_file_problem, is_temporary_name,
                                 make_directories, prepare_output_directory)
from mdr_events.validation import shown, shown_path

try:  # POSIX: a writer locks its temporary file, so that another process never takes it for stale
    import fcntl
except ImportError:  # pragma: no cover - Windows: only the age counts (see STALE_WITHOUT_LOCKS)
    fcntl = None  # type: ignore[assignment]

__all__ = ["atomic_write", "atomic_write_all", "PendingFile", "netcdf_writer", "write_netcdf", "open_result", "prepare_output_directory", "check_output_stem",
           "check_output_file", "load_netcdf", "input_file_problem",
           "check_file_path", "remove_stale_temporaries", "is_temporary_name", "TEMPORARY_MARKER"]

#: When this process started (close enough: when this module was imported). A temporary file modified
#: later may belong to a writer that has just created it and not yet locked it; it is never stale.
PROCESS_STARTED = time.time()
#: Without file locks (no :mod:`fcntl`), a temporary file is stale only when it is this old as well (s).
STALE_WITHOUT_LOCKS = 24 * 3600.0


def _is_stale(path: str, modified: float) -> bool:
    """Whether the temporary file at ``path`` (last modified at ``modified``) was left by a writer that is gone."""
    if modified >= PROCESS_STARTED:
        return False
    if fcntl is None:  # pragma: no cover - Windows
        return time.time() - modified > STALE_WITHOUT_LOCKS
    try:
        handle = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    except OSError:  # gone meanwhile (renamed into place), or not ours to read
        return False
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:  # locked: its writer is still at work
        return False
    finally:
        os.close(handle)  # releases the lock taken, if any
    return True


def remove_stale_temporaries(directory: str | os.PathLike) -> list[Path]:
    """Remove the temporary files of :func:`atomic_write` in ``directory`` left by writers that are gone.

    A file is removed when its name matches the pattern (:func:`is_temporary_name`), it is a regular file
    (not a symbolic link), it was last modified before this process started (:data:`PROCESS_STARTED`) and
    no process holds its lock (every writer holds one while writing; a killed process holds none). Where
    there are no file locks (Windows), it must also be :data:`STALE_WITHOUT_LOCKS` seconds old.

    Returns
    -------
    list of pathlib.Path
        The files removed; a directory that cannot be listed gives ``[]``.
    """
    removed = []
    try:
        entries = list(os.scandir(directory))
    except OSError:
        return removed
    for entry in entries:
        if not is_temporary_name(entry.name):
            continue
        try:
            if not entry.is_file(follow_symlinks=False):
                continue
            if not _is_stale(entry.path, entry.stat(follow_symlinks=False).st_mtime):
                continue
            os.unlink(entry.path)
        except OSError:
            continue
        removed.append(Path(entry.path))
    return removed


class PendingFile(NamedTuple):
    """A file to write: where, a function writing its content to the path it is given, the temporary's suffix."""

    path: str | os.PathLike
    write: Callable[[str], Any]
    suffix: str = ".tmp"


def atomic_write(path: str | os.PathLike, write: Callable[[str], Any], suffix: str = ".tmp") -> Path:
    """Call ``write(temporary_path)``, then rename the file onto ``path`` (:func:`atomic_write_all` of one file).

    An interrupted or failing writer leaves the old file (or none), never a
    half-written one; the temporary file sits beside the target so that the
    rename is atomic. It is named ``.<name>.mdr-tmp-<random><suffix>`` and locked (``flock``, exclusive)
    while being written, so ``write`` must not lock it itself; the stale temporary files of the directory
    (:func:`remove_stale_temporaries`) are removed first. An ``OSError`` about the temporary file names
    ``path`` instead.

    Parameters
    ----------
    path : str or os.PathLike
        The file to write; its directory is created if missing.
    write : callable
        Writes the content to the path it is given.
    suffix : str
        The temporary file's suffix (e.g. ``.png``).

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    ValueError
        If no file can be written at ``path`` (:func:`check_output_file`, or the file system refuses one there);
        an ``OSError`` while writing (a full disk) names ``path``.
    """
    return atomic_write_all([PendingFile(path, write, suffix)])[0]


#: What a file's write needs, named where the writer's error names no file (a full disk, ``ulimit -f``).
ROOM_TO_WRITE = "a file system with room for the file, within the process's file size limit (ulimit -f)"

#: The signals :func:`atomic_write_all` holds while it renames a run's files into place.
HELD_SIGNALS = (signal.SIGINT, signal.SIGTERM)


@contextmanager
def _signals_held():
    """Hold Ctrl-C (SIGINT) and SIGTERM while the body runs; the first that arrived is raised again right after it,
    to the handlers that were in place. In the main thread the Python handlers are swapped for ones that note the
    signal (Python runs its handlers there, whichever thread the signal reached); elsewhere the signals are blocked
    in that thread (``pthread_sigmask``)."""
    if threading.current_thread() is not threading.main_thread():
        if not hasattr(signal, "pthread_sigmask"):  # pragma: no cover - Windows
            yield
            return
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, set(HELD_SIGNALS))
        try:
            yield
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        return
    arrived: list[int] = []
    previous = {number: signal.signal(number, lambda number, frame: arrived.append(number)) for number in HELD_SIGNALS}
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
        if arrived:
            signal.raise_signal(arrived[0])


def _prepared_target(path: str | os.PathLike) -> Path:
    target = check_output_file("path", path)
    try:
        make_directories(target.parent)
    except OSError as error:  # a race, or a file system that refuses (a read-only mount, /proc)
        raise ValueError(f"path={shown_path(path, quoted=True)} is not allowed (its directory cannot be created: "
                         f"{error.strerror}); allowed: {ALLOWED_FILE}") from None
    return target


@contextmanager
def _directories_locked(directories: Sequence[Path]):
    """Hold an exclusive ``flock`` on each of ``directories`` (in a sorted order, so that two writers never wait on
    each other crosswise) while the body runs: two processes writing the files of their runs into one directory
    placed them one after the other, each set whole (their renames interleaved: the ``.nc`` of one run beside the
    ``.png`` of the other). Where a directory cannot be opened or locked (no ``fcntl``), nothing is held."""
    handles = []
    try:
        for directory in sorted(dict.fromkeys(os.path.abspath(d) for d in directories)):
            if fcntl is None:
                break
            try:
                handle = os.open(directory, os.O_RDONLY)
            except OSError:
                continue
            handles.append(handle)
            fcntl.flock(handle, fcntl.LOCK_EX)
        yield
    finally:
        for handle in handles:
            os.close(handle)  # (closing releases the lock)


def atomic_write_all(files: Sequence[PendingFile]) -> list[Path]:
    """Write several files as one: each to its temporary (as :func:`atomic_write`), then all renamed into place with
    Ctrl-C and SIGTERM held and their directories locked against another writer's renames, so that the files of one
    run are replaced together or not at all (an interrupt or an error while writing leaves every old file as it was;
    one during the renames waits until they are done).

    Returns the paths, in order; raises as :func:`atomic_write`.
    """
    targets = [_prepared_target(file.path) for file in files]
    for directory in dict.fromkeys(target.parent for target in targets):
        remove_stale_temporaries(directory)
    handles: list[int] = []
    temporaries: list[str] = []
    names = {}
    placed = 0
    writing = None  # (the file being written: its writer's errors name no file, round twenty-four)
    try:
        for file, target in zip(files, targets):
            writing = file.path
            try:
                handle, temporary = tempfile.mkstemp(prefix=f".{target.name}{TEMPORARY_MARKER}", suffix=file.suffix,
                                                     dir=target.parent)
            except OSError as error:  # the directory takes no new file (a read-only mount, /proc)
                raise ValueError(f"path={shown_path(file.path, quoted=True)} is not allowed (no file can be created "
                                 f"there: {error.strerror}); allowed: {ALLOWED_FILE}") from None
            handles.append(handle)
            temporaries.append(temporary)
            names[temporary] = os.fspath(target)
            if fcntl is not None:
                fcntl.flock(handle, fcntl.LOCK_EX)  # held until the file is in place (closed in the finally)
            file.write(temporary)
            mask = os.umask(0)  # mkstemp makes the file owner-only; give it the usual permissions
            os.umask(mask)
            os.chmod(temporary, 0o666 & ~mask)
        writing = None
        with _directories_locked([target.parent for target in targets]), _signals_held():
            for temporary, target in zip(temporaries, targets):
                os.replace(temporary, target)
                placed += 1
    except OSError as error:
        if error.filename in names:  # name the file the user asked for, not a temporary one now gone
            error.filename = names[error.filename]
        elif error.filename is None and writing is not None and not isinstance(error, BrokenPipeError):
            # (a write's error names no file: "[Errno 27] File too large" under `ulimit -f`, ENOSPC on a full disk)
            raise OSError(error.errno, f"{error.strerror or error} (while writing it); allowed: {ROOM_TO_WRITE}",
                          os.fspath(writing)) from error
        raise
    finally:
        for temporary in temporaries[placed:]:
            Path(temporary).unlink(missing_ok=True)
        for handle in handles:
            os.close(handle)
    return targets


#: What :func:`netcdf_writer` writes: what reads back as it was written.
ALLOWED_NETCDF = ("variables and attributes netCDF-3 holds as they are (integers of at most 32 bits, floats, text; "
                  "attributes of numbers or text; no CF encoding attributes such as _FillValue, scale_factor, "
                  "coordinates or a time's units)")


def netcdf_writer(dataset: xr.Dataset) -> Callable[[str], Any]:
    """What writes ``dataset`` as netCDF to a path (the scipy backend, netCDF3 64-bit offset: no further
    dependency), for :class:`PendingFile`. A result of this package is checked first as :func:`open_result`
    checks the file (its stamp, parameters and schema; a case selected away with ``isel`` is read), and
    the written file is read back: a dataset that does not read back identical is refused (the temporary
    file removed), so that every dataset written reads back as it was."""
    if dataset.attrs.get("program") == PROGRAM:
        _check_stamp(dataset, "dataset")  # (open_result would refuse it: param_E = inf, a variable dropped, ...)
        _check_variables(dataset, "dataset")

    def write(temporary: str) -> None:
        try:
            netcdf3.write_netcdf3(dataset, temporary)  # (to_netcdf's file, without its question to dask.distributed)
        except (ValueError, TypeError, OverflowError) as error:  # (what netCDF-3 cannot hold, in xarray's words)
            reason = " ".join(str(error).split())
            raise ValueError(f"dataset cannot be written as netCDF-3 ({type(error).__name__}: {reason}); allowed: "
                             f"{ALLOWED_NETCDF}") from None
        difference = _read_back_difference(dataset, temporary)
        if difference is not None:
            raise ValueError(f"dataset does not read back as written: {difference}; allowed: {ALLOWED_NETCDF}")

    return write


def _read_back_difference(dataset: xr.Dataset, path: str) -> str | None:
    """How the netCDF file at ``path``, read as :func:`load_netcdf` reads it, differs from ``dataset``
    (``None``: identical); one variable in memory at a time."""
    try:
        with xr.open_dataset(path, engine="scipy", cache=False) as back:
            if back.identical(dataset):
                return None
            return _first_difference(dataset, back)
    except Exception as error:  # noqa: BLE001 - the reader's failure on what was written, named
        return f"it is not read ({type(error).__name__}: {' '.join(str(error).split())})"


def _first_difference(dataset: xr.Dataset, back: xr.Dataset) -> str:
    """The first difference between ``dataset`` and ``back`` (attributes, then variables), for a message."""
    def attribute_differs(attrs, other, name):
        return name not in other or not xr.Variable((), 0, {name: attrs[name]}).identical(
            xr.Variable((), 0, {name: other[name]}))

    for owner, attrs, other in [("", dataset.attrs, back.attrs)] + [
            (f"variable {name!r}'s ", dataset[name].attrs, back[name].attrs if name in back.variables else {})
            for name in dataset.variables]:
        for name in list(attrs) + [name for name in other if name not in attrs]:
            if name not in attrs or attribute_differs(attrs, other, name):
                return (f"{owner}attribute {name!r}={shown(attrs.get(name))} reads back as "
                        f"{shown(other[name]) if name in other else 'absent'}")
    for name in list(dataset.variables) + [name for name in back.variables if name not in dataset.variables]:
        if name not in dataset.variables or name not in back.variables:
            return f"variable {name!r} is {'absent' if name not in back.variables else 'added'} on reading"
        mine, theirs = dataset[name].variable, back[name].variable
        if not mine.identical(theirs):
            return (f"variable {name!r} {mine.dims} {mine.dtype} reads back as {theirs.dims} {theirs.dtype} "
                    "with other values")
    return "its dimensions differ"


def write_netcdf(dataset: xr.Dataset, path: str | os.PathLike) -> Path:
    """Write ``dataset`` as netCDF to ``path`` atomically (see :func:`atomic_write`).

    The scipy backend (netCDF3, 64-bit offset) is used so that no further
    dependency is needed.

    Parameters
    ----------
    dataset : xarray.Dataset
        The result to write (its attributes as they are; :func:`open_result` reads it back).
    path : str or os.PathLike
        The file to write; its folder must exist. A file there is replaced only once the new one is complete.

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    TypeError
        If ``dataset`` is not an ``xarray.Dataset`` or ``path`` not a ``str`` or ``os.PathLike``
        (nothing is written).
    """
    if not isinstance(dataset, xr.Dataset):
        raise TypeError(f"dataset={shown(dataset)} ({type(dataset).__name__}) is not allowed; allowed: an "
                        "xarray.Dataset")
    return atomic_write(path, netcdf_writer(dataset), suffix=".nc")  # (it checks the path before writing)


def open_result(path: str | os.PathLike) -> xr.Dataset:
    """Read a file written by this package, fully loaded, and check it against its schema.

    Raises ``TypeError`` if ``path`` is not a ``str`` or ``os.PathLike``, and ``ValueError`` naming
    the file and what is wrong when it is missing, a directory, not a readable netCDF file, was not
    written by this package, lacks a stamp attribute or a parameter, or lacks a variable (or its
    ``units`` / ``long_name``) that its kind of result (``content``) must hold.

    Parameters
    ----------
    path : str or os.PathLike
        A netCDF file written by :func:`write_netcdf` (a simulation, a phase diagram, a report, a fit, ...).

    Returns
    -------
    xarray.Dataset
        The result, loaded into memory (the file is closed), with its stamp and parameters as attributes.
    """
    where = shown_path(check_file_path("path", path, f"{ALLOWED_PATH} naming a netCDF file"), quoted=True)
    dataset = load_netcdf(path, where)
    _check_stamp(dataset, where)
    _check_variables(dataset, where)
    return dataset


#: The first bytes of a netCDF-3 file (the classic and 64-bit offset formats, what SciPy reads and this package writes).
NETCDF3_MAGIC = b"CDF"
#: The first bytes of an HDF5 file (netCDF-4), which needs a reader this package does not install.
HDF5_MAGIC = b"\x89HDF"


def _netcdf_kind_problem(path: str | os.PathLike) -> str | None:
    """Why ``path`` is no netCDF-3 file, from its first bytes (``None`` if it may be one)."""
    with open(path, "rb") as handle:
        head = handle.read(len(HDF5_MAGIC))
    if not head:
        return "it is empty"
    if head.startswith(HDF5_MAGIC):
        return ("it is netCDF-4 (HDF5), which needs h5netcdf or netCDF4; write it as netCDF-3, e.g. "
                "dataset.to_netcdf(path, format='NETCDF3_64BIT'), or give a CSV file")
    if not head.startswith(NETCDF3_MAGIC):
        return f"it does not start as a netCDF file does: {head!r}"
    return None


def load_netcdf(path: str | os.PathLike, where: str, allowed: str = f"a netCDF file written by {PROGRAM}",
                before_load: Callable[[xr.Dataset], None] | None = None) -> xr.Dataset:
    """The netCDF-3 file at ``path``, fully loaded and closed; ``ValueError`` naming ``where`` and ``allowed`` if it is
    missing, a directory, empty, netCDF-4 or unreadable (the reader's message on one line). ``before_load`` is given
    the file opened lazily (its header read: every variable's declared shape and type) before anything is loaded; what
    it raises (a :class:`~mdr_events.limits.ResourceLimitError`) is raised as it is."""
    problem = input_file_problem(path)
    if problem is not None:
        raise ValueError(f"{where}{problem}; allowed: {allowed}")
    try:
        why = _netcdf_kind_problem(path)
        if why is None:
            with xr.open_dataset(path, engine="scipy") as handle:
                if before_load is not None:
                    before_load(handle)
                return handle.load()
    except ResourceLimitError:
        raise
    except FileNotFoundError:
        raise ValueError(f"{where}: no such file; allowed: {allowed}") from None
    except Exception as error:  # noqa: BLE001 - whatever the reader raises on a file's bytes (SyntaxError too)
        why = f"{type(error).__name__}: {' '.join(str(error).split())}"  # one line: the reader's may span several
    raise ValueError(f"{where} is not a readable netCDF file ({why}); allowed: {allowed}")


#: What a result file (or a result to be written) may be, for the messages of :func:`_check_stamp` and
#: :func:`_check_variables` (which said what was wrong, not what is allowed).
ALLOWED_RESULT = (f"a result as {PROGRAM} makes it (its stamp and parameters as attributes; its variables with their "
                  "dimensions, units and long_name; one case selected with isel)")


def _check_stamp(dataset: xr.Dataset, where: str) -> None:
    """Raise ``ValueError`` unless this package wrote ``dataset`` with its full stamp and parameters."""
    if dataset.attrs.get("program") != PROGRAM:
        raise ValueError(f"{where} was not written by {PROGRAM} (attribute 'program' missing or different); "
                         f"allowed: {ALLOWED_RESULT}")
    missing = [name for name in STAMP_ATTRIBUTES if name not in dataset.attrs]
    if missing:
        raise ValueError(f"{where} lacks the attribute(s) {missing}; allowed: {ALLOWED_RESULT}")
    try:
        parameters_of(dataset)
        Contact.from_attrs(dataset.attrs)  # (the indenter and the friction law it names, consistently)
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
        raise ValueError(f"{where} ({content}) lacks the variable(s) {missing}; allowed: {ALLOWED_RESULT}")
    selected = [name for name, coordinate in dataset.coords.items() if coordinate.ndim == 0]  # (isel of one label)
    wrong = [f"{name} {dataset[name].dims} (expected {describe_dims(dims)})" for name, dims in schema.items()
             if not dims_match(dataset[name].dims, dims, selected)]
    if wrong:
        raise ValueError(f"{where} ({content}) has variable(s) with the wrong dimensions: {'; '.join(wrong)}; "
                         f"allowed: {ALLOWED_RESULT}")
    unlabelled = [name for name in dataset.variables
                  if not {"units", "long_name"} <= set(dataset[name].attrs)]
    if unlabelled:
        raise ValueError(f"{where} ({content}) has variable(s) without units or long_name: {unlabelled}; "
                         f"allowed: {ALLOWED_RESULT}")
