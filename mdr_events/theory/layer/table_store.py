"""The layer's tables on disk, for the normal and the tangential punch alike: where they are kept, the key of the code
that computed them, their grid in ``ln(a/h)``, and reading one or building and storing it."""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from mdr_events.theory.cache_files import cache_directory, read_cached, store_cached

__all__ = ["cache_directory", "source_digest", "table_grid", "stored_columns"]


def source_digest(*modules: str) -> str:
    """The key of tables computed by ``modules`` (file names in this package) and this module: a hash of their
    source and NumPy's version, so that a change of the code never reads an old table.

    Parameters
    ----------
    *modules : str
        File names in :mod:`mdr_events.theory.layer`.

    Returns
    -------
    str
        16 hexadecimal digits.
    """
    here = Path(__file__).parent
    source = b"".join((here / name).read_bytes() for name in (*modules, Path(__file__).name))
    return hashlib.sha256(source + np.__version__.encode()).hexdigest()[:16]


def table_grid(lowest: float, highest: float, step: float) -> np.ndarray:
    """A table's nodes in ``s = ln(a/h)``: at most ``step`` apart from ``lowest`` to ``highest`` (``a/h``).

    Parameters
    ----------
    lowest, highest : float
        The range of ``a/h``.
    step : float
        The largest spacing in ``ln(a/h)``.

    Returns
    -------
    numpy.ndarray
        The nodes.
    """
    low, high = math.log(lowest), math.log(highest)
    return np.linspace(low, high, int(math.ceil((high - low) / step)) + 1)


def stored_columns(path: Path | None, names: tuple[str, ...], grid: np.ndarray,
                   build: Callable[[], dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
    """A table's columns ``names`` (``s``, the grid, among them), read from ``path`` if it holds them on ``grid``, else
    ``build()`` and stored there atomically (any trouble on the disk is only a missed shortcut).

    Parameters
    ----------
    path : pathlib.Path or None
        The table's file (``None``: no caching).
    names : tuple of str
        The columns, ``"s"`` the grid's.
    grid : numpy.ndarray
        The grid the stored table must have.
    build : callable
        Computes the columns.

    Returns
    -------
    dict of str to numpy.ndarray
        The columns.
    """
    def read(stream) -> dict[str, np.ndarray] | None:
        with np.load(stream, allow_pickle=False) as stored:
            columns = {name: stored[name] for name in names}
        return columns if np.array_equal(columns["s"], grid) else None

    columns = read_cached(path, read)  # (a damaged or foreign file, or one the system refuses: rebuilt)
    if columns is None:
        columns = build()
        store_cached(path, lambda stream: np.savez(stream, **columns))
    return columns

