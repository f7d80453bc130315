"""The layer's tables on disk, for the normal and the tangential punch alike: where they are kept, the key of the code
that computed them, their grid in ``ln(a/h)``, and reading one or building and storing it."""

from __future__ import annotations

import hashlib
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from mdr_events.theory.cache_files import cache_directory, read_cached, store_cached
from mdr_events.validation import real_array

__all__ = ["cache_directory", "source_digest", "table_grid", "stored_columns", "table_argument"]


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
                   build: Callable[[], dict[str, np.ndarray]],
                   constants: tuple[str, ...] = ()) -> dict[str, np.ndarray]:
    """A table's columns ``names`` (``s``, the grid, among them), read from ``path`` if it holds them on ``grid`` (each
    column finite floats, one per node but ``constants``), else ``build()`` and stored there atomically (any trouble on
    the disk, a damaged or foreign file, is only a missed shortcut).

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
    constants : tuple of str, optional
        The columns among ``names`` that are not one value per node (the kernel's values at ``a/h = 0``).

    Returns
    -------
    dict of str to numpy.ndarray
        The columns.
    """
    def read(stream) -> dict[str, np.ndarray] | None:
        with np.load(stream, allow_pickle=False) as stored:
            columns = {name: stored[name] for name in names}
        whole = all(is_column(column, name in constants) for name, column in columns.items())
        return columns if whole and np.array_equal(columns["s"], grid) else None

    def is_column(column: np.ndarray, constant: bool) -> bool:  # (a foreign file's 2 values on 135 nodes, NaN: read)
        return (column.dtype == np.float64 and (constant or column.shape == grid.shape)
                and bool(np.isfinite(column).all()))

    columns = read_cached(path, read)  # (a damaged or foreign file, or one the system refuses: rebuilt)
    if columns is None:
        columns = build()
        store_cached(path, lambda stream: np.savez(stream, **columns))
    return columns


def table_argument(lam, highest: float, solver: str) -> np.ndarray:
    """A table's argument ``λ = a/h`` as a float array in ``[0, highest]``, else the one-line error (the normal and the
    tangential tables alike).

    Parameters
    ----------
    lam : float or array_like
        ``a/h``.
    highest : float
        The table's largest ``a/h``.
    solver : str
        The direct solve beyond the table, named in the message.

    Returns
    -------
    numpy.ndarray
        ``λ`` as floats.

    Raises
    ------
    TypeError
        ``lam`` not real numbers.
    ValueError
        A ``λ`` outside ``[0, highest]`` or not a number.
    """
    lam = real_array("lam", lam, f"numbers in [0, {highest:g}] (a/h)")
    inside = (lam >= 0.0) & (lam <= highest)
    if not np.all(inside):
        bad = float(lam[~inside].ravel()[0])
        raise ValueError(f"a/h={bad!r} is not allowed; allowed: 0 <= a/h <= {highest:g} (the table's range; {solver})")
    return lam
