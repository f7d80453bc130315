"""The package's caches on disk (the derived relations, the layer's tables): where they are kept, and reading and
storing one file of them, so that any trouble with the disk is only a missed shortcut.

A cache file is read in one ``try`` from opening it on (issue 32, round thirteen: a path the system refuses to look
at, too long or below a directory without search permission, raised ``OSError`` from a check of its existence before
the ``try``, and every derivation failed with it); one is stored through a temporary beside it, renamed into place,
the temporary removed when the store fails (it was left behind), or is interrupted (round twenty-nine: Ctrl-C
while a derivation was stored left a ``.relations-<key>.pickle.<random>`` in the cache directory).
"""

from __future__ import annotations

import os
import stat
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import IO, Any

from mdr_events.io.paths import make_directories

__all__ = ["cache_directory", "read_cached", "store_cached"]


def cache_directory() -> Path | None:
    """The directory of the derivations' and the tables' caches (``None``: caching is off).

    ``$MDR_EVENTS_CACHE_DIR`` or ``$XDG_CACHE_HOME/mdr_events`` or ``~/.cache/mdr_events``; ``MDR_EVENTS_NO_CACHE=1``
    turns it off.

    Returns
    -------
    pathlib.Path or None
        The directory, or ``None``.
    """
    if os.environ.get("MDR_EVENTS_NO_CACHE"):
        return None
    return Path(os.environ.get("MDR_EVENTS_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "mdr_events"))


def read_cached(path: Path | None, read: Callable[[IO[bytes]], Any]) -> Any:
    """``read(stream)`` of the cache file at ``path``, or ``None`` where there is none or it cannot be read.

    Parameters
    ----------
    path : pathlib.Path or None
        The cache file (``None``: caching is off).
    read : callable
        Reads what the file holds from a binary stream (and checks it: whatever it raises is a damaged or foreign
        file).

    Returns
    -------
    object or None
        What ``read`` returned; ``None`` if the file is missing, is not a regular file (a FIFO, a device, a
        directory), the system refuses the path, or ``read`` raised.
    """
    if path is None:
        return None
    try:
        # (without blocking, and only a regular file: a FIFO in the cache file's place held every derivation at its
        # open until a writer came, for ever; a device read on without end; issue 32, round twenty-nine)
        handle = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with open(handle, "rb") as stream:
            if not stat.S_ISREG(os.fstat(handle).st_mode):
                return None
            return read(stream)
    except Exception:  # noqa: BLE001 - a missing, unreachable, damaged or foreign file is only a missed shortcut
        return None


def store_cached(path: Path | None, write: Callable[[IO[bytes]], None]) -> None:
    """Store a cache file atomically: ``write(stream)`` into a temporary beside ``path``, renamed to ``path``.

    Any ``OSError`` (no directory can be made, the disk is full or read-only, ``path`` is a directory) stores nothing
    and removes the temporary; so does anything else that ends the write (Ctrl-C, SIGTERM, an error of ``write``),
    which then goes on.

    Parameters
    ----------
    path : pathlib.Path or None
        The cache file (``None``: caching is off, nothing is stored).
    write : callable
        Writes the content to a binary stream.
    """
    if path is None:
        return
    temporary = None
    try:
        make_directories(path.parent)
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
        with os.fdopen(handle, "wb") as stream:
            write(stream)
        os.replace(temporary, path)
        temporary = None
    except OSError:
        pass
    finally:  # (also on Ctrl-C, SIGTERM or a writer's own error: issue 32, round 29, the temporary was left behind)
        if temporary is not None:
            try:
                os.unlink(temporary)
            except OSError:
                pass
