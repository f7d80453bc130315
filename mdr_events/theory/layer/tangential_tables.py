r"""The tangential punch's factors of a bonded layer against ``a/h``, cached on disk: :class:`TangentialTable`.

Part of :mod:`mdr_events.theory.layer_tangential`, which documents the problem and re-exports the public names.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from mdr_events.theory.layer.punch import nystrom_nodes
from mdr_events.theory.layer.table_store import (cache_directory, source_digest, stored_columns, table_argument,
                                                 table_grid)
from mdr_events.theory.layer.tangential_compliance import LAMBDA_MAX, MODES, _nu, tangential_kernel
from mdr_events.theory.layer.tangential_punch import _combine, _slope, _solve

__all__ = ["LAMBDA_MIN", "TABLE_STEP", "TangentialTable", "tangential_table", "tangential_table_cache_path"]

#: The smallest ``a/h`` of a table: below it the half-space side's series ``Φ_m = Ψ_m(1) = 1/(1 − 2k_m(0)λ/π)``
#: (error ``O(λ³) < 1e-11``).
LAMBDA_MIN = 1e-4
#: Spacing of the table's nodes in ``ln(a/h)`` (quintic splines: interpolation error about 2e-9; tests check 1e-8).
TABLE_STEP = 0.1

#: Hash of the tangential solver's source (the compliances and kernels, the punch's solve and the tables) and NumPy's
#: version: the key of the tables on disk (a change of the code never reads an old table).
_SOURCE_DIGEST = source_digest("compliance.py", "tangential_compliance.py", "tangential_punch.py", "tangential_tables.py")


def tangential_table_cache_path(nu: float) -> Path | None:
    """Where the tangential table of ``ν`` is kept between processes (``None``: caching is off).

    The directory of the normal tables (``$MDR_EVENTS_CACHE_DIR`` or ``$XDG_CACHE_HOME/mdr_events`` or
    ``~/.cache/mdr_events``; ``MDR_EVENTS_NO_CACHE=1`` turns it off), the name keyed by this module's source.

    Parameters
    ----------
    nu : float
        Poisson's ratio.

    Returns
    -------
    pathlib.Path or None
        ``layer-tangential-nu<ν>-<hash>.npz`` in that directory, or ``None``.
    """
    root = cache_directory()
    return None if root is None else root / f"layer-tangential-nu{float(nu)!r}-{_SOURCE_DIGEST}.npz"


#: The tabulated columns (logarithms): ``Φ_L``, ``Φ_T``, ``Ψ_L(1)``, ``Ψ_T(1)``.
_COLUMNS = ("phi_l", "phi_t", "edge_l", "edge_t")
#: The columns of ``Φ_t`` (T3), :meth:`TangentialTable.stiffness_factor`.
_STIFFNESS_COLUMNS = ("phi_l", "phi_t")


def _table_grid() -> np.ndarray:
    return table_grid(LAMBDA_MIN, LAMBDA_MAX, TABLE_STEP)


def _build_table(nu: float) -> dict[str, np.ndarray]:
    grid = _table_grid()
    rows = []
    for lam in np.exp(grid):
        solution = _solve(float(lam), nu, nystrom_nodes(float(lam)))
        rows.append((solution.longitudinal_factor, solution.transverse_factor, *solution.edges))
    rows = np.array(rows)
    out = {"s": grid, "k0": np.array([float(tangential_kernel(0.0, nu, mode)) for mode in MODES])}
    out.update({name: np.log(rows[:, j]) for j, name in enumerate(_COLUMNS)})
    return out


def _stored_table(nu: float) -> dict[str, np.ndarray]:
    """The table's columns from the disk cache if there, else built and stored (trouble: only a missed shortcut)."""
    path = tangential_table_cache_path(nu)
    return stored_columns(path, ("s", "k0", *_COLUMNS), _table_grid(), lambda: _build_table(nu),
                          constants=("k0",))


@dataclass(frozen=True)
class TangentialTable:
    r"""The tangential punch's factors of a bonded layer against ``λ = a/h`` (quintic splines of their logarithms in
    ``ln λ``), for one ``ν``; below :data:`LAMBDA_MIN` the series ``Φ_m = Ψ_m(1) = 1/(1 − 2k_m(0)λ/π)``.

    Parameters
    ----------
    nu : float
        Poisson's ratio.
    columns : dict of str to numpy.ndarray
        ``s = ln λ``, ``k0 = (k_L(0), k_T(0))`` and the logarithms of ``Φ_L``, ``Φ_T``, ``Ψ_L(1)``, ``Ψ_T(1)``.
    """

    nu: float
    columns: dict

    @functools.cached_property
    def _splines(self) -> dict:
        from scipy.interpolate import make_interp_spline

        return {name: make_interp_spline(self.columns["s"], self.columns[name], k=5) for name in _COLUMNS}

    def _series(self, lam: np.ndarray) -> dict[str, np.ndarray]:
        """The four columns below :data:`LAMBDA_MIN`: ``Φ_m = Ψ_m(1) = 1/(1 − 2k_m(0)λ/π)``."""
        k_l, k_t = (float(value) for value in self.columns["k0"])
        series = {"phi_l": 1.0 / (1.0 - 2.0 * k_l * lam / np.pi), "phi_t": 1.0 / (1.0 - 2.0 * k_t * lam / np.pi)}
        series.update(edge_l=series["phi_l"], edge_t=series["phi_t"])
        return series

    def _values(self, lam, names: tuple[str, ...] = _COLUMNS) -> tuple[np.ndarray, ...]:
        """The columns ``names`` (default all four) at ``λ``: the series below :data:`LAMBDA_MIN`."""
        lam = table_argument(lam, LAMBDA_MAX, "solve_tangential_punch solves up to LAMBDA_SOLVE_MAX")
        small = lam < LAMBDA_MIN
        s = np.log(np.where(small, LAMBDA_MIN, lam))
        series = self._series(lam)
        if names == _STIFFNESS_COLUMNS:  # (one spline of both columns: the same values, each column contiguous)
            logarithms = np.moveaxis(self._stiffness_splines(s), -1, 0).copy()
            return tuple(np.where(small, series[name], np.exp(logarithm)) for name, logarithm in zip(names, logarithms))
        return tuple(np.where(small, series[name], np.exp(self._splines[name](s))) for name in names)

    @functools.cached_property
    def _stiffness_splines(self):
        """The splines of ``Φ_L``, ``Φ_T`` as one spline of two columns (one knot vector: each column's sum taken as
        its own spline's, at half the calls)."""
        from scipy.interpolate import BSpline

        first, second = (self._splines[name] for name in _STIFFNESS_COLUMNS)
        if not np.array_equal(first.t, second.t):
            raise ValueError("columns of different knots are not allowed; allowed: the columns of one table")
        return BSpline(first.t, np.stack([first.c, second.c], axis=-1), first.k)

    def stiffness_factor(self, lam) -> np.ndarray:
        """``Φ_t(λ) = K_t(a)/(2G* a)`` (T3).

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.

        Returns
        -------
        numpy.ndarray
            ``Φ_t`` (1 at ``λ = 0``).

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        phi_l, phi_t = self._values(lam, _STIFFNESS_COLUMNS)  # (the edges' columns are not read)
        return _combine(self.nu, phi_l, phi_t)

    def slope_factor(self, lam) -> np.ndarray:
        """``Σ_t(λ) = K_t'(a)/(2G*)`` (T4), from the tabulated edge values (no derivative of a spline).

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.

        Returns
        -------
        numpy.ndarray
            ``Σ_t`` (1 at ``λ = 0``).

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        return _slope(self.nu, *self._values(lam))


@functools.lru_cache(maxsize=None)
def _tangential_table(nu: float) -> TangentialTable:
    return TangentialTable(nu, _stored_table(nu))


def tangential_table(nu: float) -> TangentialTable:
    """The table of a bonded layer's tangential punch factors for ``ν``: built once per process, cached on disk.

    Building one takes about 2 s (two solves per node, :data:`TABLE_STEP`-spaced from ``a/h = 1e-4`` to
    :data:`LAMBDA_MAX`); reading it from the cache a few milliseconds.

    Parameters
    ----------
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.

    Returns
    -------
    TangentialTable
        The interpolated factors.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``.
    """
    return _tangential_table(_nu(nu))
