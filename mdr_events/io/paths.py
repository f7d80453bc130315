"""Paths of result files, checked before anything is computed: an output directory (:func:`prepare_output_directory`),
a file's path (:func:`check_output_file`), a stem a user chose (:func:`check_output_stem`), the name of a temporary
file (:func:`is_temporary_name`), and why an input is no file to read (:func:`input_file_problem`)."""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any

from mdr_events.validation import shown

__all__ = ["check_file_path", "prepare_output_directory", "check_output_file", "check_output_stem",
           "is_temporary_name", "make_directories", "input_file_problem", "TEMPORARY_MARKER", "MAX_STEM_BYTES",
           "MAX_NAME_BYTES",
           "SYSTEM_DIRECTORIES", "ALLOWED_PATH", "ALLOWED_FILE"]

#: What marks a temporary file of :func:`atomic_write`: ``.<target name>.mdr-tmp-<random><suffix>``.
TEMPORARY_MARKER = ".mdr-tmp-"
#: (the random part is ``tempfile``'s: eight lower-case letters, digits or underscores; a user's file that merely holds
#: the marker, ``.results.mdr-tmp-keep.nc``, is not taken for one)
_TEMPORARY_NAME = re.compile(r"^\..+" + re.escape(TEMPORARY_MARKER) + r"[a-z0-9_]{8}(\.[A-Za-z0-9]+)?$")
#: The longest stem :func:`check_output_stem` allows, in bytes of UTF-8: a file name has at most 255 bytes,
#: and a result's name adds a suffix (``_phase_diagram_A.png``) and its temporary file a marker.
MAX_STEM_BYTES = 200
ALLOWED_PATH = "a str or os.PathLike"
_ALLOWED_DIRECTORY = "a directory that exists or can be created, and that this user can write into"
_ALLOWED_STEM = (f"a plain file-name stem: not empty, not '.' or '..', without '/', '\\', control characters or "
                 f"{TEMPORARY_MARKER!r}, at most {MAX_STEM_BYTES} bytes")


def check_file_path(name: str, path: Any, allowed: str = ALLOWED_PATH) -> Path:
    """``path`` as a :class:`~pathlib.Path` if it is a non-empty ``str`` or ``os.PathLike`` (of ``str``).

    Parameters
    ----------
    name : str
        The argument's name, as the user wrote it (``path``, ``--out``).
    path : object
        The value given.
    allowed : str
        What is allowed, for the message.

    Raises
    ------
    TypeError
        If ``path`` is of another type (``None``, bytes, a Dataset, ...).
    ValueError
        If ``path`` is empty or holds a NUL character.
    """
    if not isinstance(path, (str, os.PathLike)) or not isinstance(os.fspath(path), str):
        raise TypeError(f"{name}={shown(path)} ({type(path).__name__}) is not allowed; allowed: {allowed}")
    text = os.fspath(path)
    if not text or "\0" in text:
        raise ValueError(f"{name}={text!r} is not allowed; allowed: {allowed}, not empty and without NUL")
    return Path(text)


def prepare_output_directory(path: Any, name: str) -> Path:
    """Check that ``path`` can take the output, before anything is computed; returns it as a ``Path``.

    ``path`` must be a directory this user can write into, or not exist yet with its nearest existing
    ancestor such a directory (it is created when the first file is written, by :func:`atomic_write`;
    nothing is created here, so that input found wrong later leaves nothing behind).

    Parameters
    ----------
    path : str or os.PathLike
        The output directory.
    name : str
        The argument's name for the message (``--out``, ``[output] directory``, ``out``).

    Raises
    ------
    TypeError
        If ``path`` is not a ``str`` or ``os.PathLike``.
    ValueError
        Naming ``name``, the value and what is allowed: ``path`` is a file, lies below a file, is a
        broken symbolic link, or it (or the directory it would be created in) is not writable.
    """
    directory = check_file_path(name, path, f"{ALLOWED_PATH} naming {_ALLOWED_DIRECTORY}")
    why = _directory_problem(directory)
    if why is not None:
        raise ValueError(f"{name}={shown(os.fspath(path))} is not allowed ({why}); allowed: {_ALLOWED_DIRECTORY}")
    return directory


#: Directories that hold devices and the kernel's views, not files: no output goes there (nor into the root itself).
SYSTEM_DIRECTORIES = ("/dev", "/proc", "/sys")


def _directory_problem(directory: Path) -> str | None:
    """Why ``directory`` cannot take output (:func:`prepare_output_directory`), or ``None``: checked before anything
    is created, a name of it too long for a file system (which would fail after its parents were made) among them."""
    long = [part for part in directory.parts if len(os.fsencode(part)) > MAX_NAME_BYTES]  # (a name's bytes on disk:
    # one not UTF-8 arrives with surrogates, which str.encode refused in a raw UnicodeEncodeError)
    if long:
        return f"its part {shown(long[0])} has {len(os.fsencode(long[0]))} bytes, more than a file system's {MAX_NAME_BYTES}"
    absolute_bytes = len(os.fsencode(os.path.abspath(directory)))
    if absolute_bytes > MAX_DIRECTORY_BYTES:  # (refused at the first write, after the run: 12 s of a simulation lost)
        return (f"its absolute path has {absolute_bytes} bytes, more than the {MAX_DIRECTORY_BYTES} that leave a "
                f"file's name of {MAX_NAME_BYTES} bytes within a path's {MAX_PATH_BYTES}")
    created = [part.name for part in (directory, *directory.parents) if not os.path.lexists(part)]
    controlled = [part for part in created if any(ord(character) < 32 or ord(character) == 127 for character in part)]
    if controlled:  # (a directory this package would create, with a newline in its name, as a file's name may not)
        return f"its part {shown(controlled[-1])}, to be created, holds a control character"
    absolute = directory.absolute()
    real = Path(os.path.realpath(absolute))
    if real == Path(real.anchor):
        return f"it is {real}, the file system's root"
    for system in SYSTEM_DIRECTORIES:
        if real == Path(system) or Path(system) in real.parents:
            return f"it lies in {system}, a directory of devices or of the kernel's views, not of files"
    existing = absolute
    while not os.path.exists(existing):  # the nearest ancestor that exists (os.path: False on any error)
        if os.path.lexists(existing):
            return ("it is a broken symbolic link" if existing == absolute
                    else f"it lies below {existing}, a broken symbolic link")
        if existing.parent == existing:  # pragma: no cover - the root always exists
            break
        existing = existing.parent
    if not os.path.isdir(existing):
        return ("it is a file, not a directory" if existing == absolute
                else f"it lies below {existing}, a file, not a directory")
    if not os.access(existing, os.W_OK | os.X_OK):
        return ("it is not writable" if existing == absolute
                else f"it cannot be created: {existing} is not writable")
    return None


#: The longest file name most file systems take (bytes); a temporary file adds ``.``, :data:`TEMPORARY_MARKER`, eight
#: random characters and the suffix to it.
MAX_NAME_BYTES = 255
_TEMPORARY_EXTRA_BYTES = 1 + len(TEMPORARY_MARKER) + 8 + 8
#: The longest path the system's calls take (bytes, with its terminating NUL: Linux's ``PATH_MAX``; macOS's is 1024).
MAX_PATH_BYTES = 4096
#: The longest output directory (bytes of its absolute path): a file's name of :data:`MAX_NAME_BYTES` and its
#: separator still fit within :data:`MAX_PATH_BYTES` (with the NUL).
MAX_DIRECTORY_BYTES = MAX_PATH_BYTES - MAX_NAME_BYTES - 2
ALLOWED_FILE = (f"a file path (not a directory) of at most {MAX_NAME_BYTES - _TEMPORARY_EXTRA_BYTES} bytes of name, "
                 f"in {_ALLOWED_DIRECTORY}")


def check_output_file(name: str, path: Any) -> Path:
    """``path`` as a ``Path`` if a file can be written there, checked before anything is computed or written.

    Parameters
    ----------
    name : str
        The argument's name for the message (``path``).
    path : str or os.PathLike
        The file to write.

    Raises
    ------
    TypeError
        If ``path`` is not a ``str`` or ``os.PathLike``.
    ValueError
        Naming ``name``, the value and what is allowed: ``path`` is a directory, its name is too long for a file
        system (with the temporary file's marker), or its directory cannot take it
        (:func:`prepare_output_directory`: a file, below a file, not writable).
    """
    target = check_file_path(name, path, ALLOWED_FILE)
    text = os.fspath(path)
    if text.endswith(tuple({"/", os.sep})):  # (pathlib drops the trailing separator: 'x.nc/' would write x.nc)
        raise ValueError(f"{name}={text!r} is not allowed (a trailing separator names a directory); allowed: "
                         f"{ALLOWED_FILE}")
    if os.path.isdir(target):
        raise ValueError(f"{name}={text!r} is not allowed (it is a directory); allowed: {ALLOWED_FILE}")
    if os.path.lexists(target) and (os.path.islink(target) or not os.path.isfile(target)):
        # a FIFO, a device (/dev/null as root), a socket or a symbolic link would be replaced by a regular file
        kind = "a symbolic link" if os.path.islink(target) else "not a regular file"
        raise ValueError(f"{name}={text!r} is not allowed (it is {kind}, which the file would replace); allowed: "
                         f"{ALLOWED_FILE}, a regular file if it exists")
    if any(ord(character) < 32 or ord(character) == 127 for character in target.name):  # (a newline in a file name)
        raise ValueError(f"{name}={shown(text)} is not allowed (its name holds a control character); allowed: "
                         f"{ALLOWED_FILE}, without control characters")
    if TEMPORARY_MARKER in target.name:  # (the next write into its directory would take it for stale and remove it)
        raise ValueError(f"{name}={shown(text)} is not allowed (its name holds {TEMPORARY_MARKER!r}, which marks the "
                         f"temporary files this package removes); allowed: {ALLOWED_FILE}, without that marker")
    if len(os.fsencode(target.name)) + _TEMPORARY_EXTRA_BYTES > MAX_NAME_BYTES:
        raise ValueError(f"{name}={shown(text)} is not allowed (its name has {len(os.fsencode(target.name))} bytes); "
                         f"allowed: {ALLOWED_FILE}")
    why = _directory_problem(target.parent)
    if why is not None:
        raise ValueError(f"{name}={text!r} is not allowed (its directory {str(target.parent)!r}: {why}); "
                         f"allowed: {ALLOWED_FILE}")
    return target


def check_output_stem(name: str, stem: Any) -> str:
    """``stem`` if it is a plain file-name stem that keeps every file in its output directory.

    Parameters
    ----------
    name : str
        The argument's name for the message (``[output] name``, ``stem``).
    stem : str
        The stem a user chose; files are written as ``<stem><suffix>`` in the output directory.

    Raises
    ------
    TypeError
        If ``stem`` is not a ``str``.
    ValueError
        If ``stem`` is empty, ``.`` or ``..``, holds a path separator or a control character, holds
        :data:`TEMPORARY_MARKER` (a later write would take the file for a stale temporary file) or is
        longer than :data:`MAX_STEM_BYTES`.
    """
    if not isinstance(stem, str):
        raise TypeError(f"{name}={shown(stem)} ({type(stem).__name__}) is not allowed; allowed: {_ALLOWED_STEM}")
    separators = {"/", "\\", os.sep, os.altsep or "/"}
    if (stem in ("", ".", "..") or any(character in separators for character in stem)
            or not stem.isprintable() or TEMPORARY_MARKER in stem or len(os.fsencode(stem)) > MAX_STEM_BYTES):
        raise ValueError(f"{name}={shown(stem)} is not allowed; allowed: {_ALLOWED_STEM}")
    return stem


def make_directories(directory: str | os.PathLike) -> None:
    """Create ``directory`` and its missing parents, outermost first, as ``Path.mkdir(parents=True, exist_ok=True)``
    does but without recursion: pathlib and ``os.makedirs`` call themselves once a level to be made, so that an output
    path of 1000 new levels (``--out d/d/.../d``, 2 kB, well within a path's 4096 bytes) ended, after the run, in
    ``RecursionError`` (issue 32, round 30). ``OSError`` as ``mkdir`` raises it (a file where a directory goes
    included: ``FileExistsError``)."""
    missing = []
    current = Path(directory)
    while not current.is_dir() and current.parent != current:
        missing.append(current)
        current = current.parent
    for part in reversed(missing):
        try:
            part.mkdir()
        except FileExistsError:  # (made meanwhile by another writer: as exist_ok; a file there is refused)
            if not part.is_dir():
                raise


def is_temporary_name(name: str) -> bool:
    """Whether a file name is that of a temporary file of :func:`atomic_write`."""
    return _TEMPORARY_NAME.match(name) is not None


def input_file_problem(path: str | os.PathLike) -> str | None:
    """Why ``path`` is no file to read, as the end of a message after its name (`` is a directory``, `` is not a
    regular file (...)``: a FIFO would block the read forever, ``: no such file``); ``None`` for a regular file."""
    if os.path.isfile(path):
        return None
    if os.path.isdir(path):
        return " is a directory"
    return " is not a regular file (a device, FIFO or socket)" if os.path.exists(path) else ": no such file"
