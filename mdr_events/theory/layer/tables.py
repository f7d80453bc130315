"""The punch factors tabulated against ``a/h`` per ``(ν, base, n)``, cached on disk: :class:`LayerTable`.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from mdr_events.contact.layer import LayerBase
from mdr_events.theory.layer.compliance import LAMBDA_MAX, _base, _nu, kernel
from mdr_events.theory.layer.punch import solve_punch
from mdr_events.theory.layer.table_store import (cache_directory, source_digest, stored_columns, table_argument,
                                                 table_grid)
from mdr_events.validation import check_real

__all__ = ["LAMBDA_MIN", "TABLE_STEP", "LayerTable", "layer_table", "table_cache_path"]

#: The smallest ``a/h`` of a table: below it the series of the half-space side is exact to ``O(λ³) < 1e-11``.
LAMBDA_MIN = 1e-4
#: Spacing of the table's nodes in ``ln(a/h)``: quintic splines on it interpolate to about 2e-9 (the tests check
#: 1e-8 at every mid-point).
TABLE_STEP = 0.1

#: Hash of the solver's source (the compliance, the punch's solve and the tables) and NumPy's version: the key of the
#: tables on disk (a change of the code never reads an old table).
_SOURCE_DIGEST = source_digest("compliance.py", "punch.py", "tables.py")


def table_cache_path(nu: float, base: LayerBase | str, exponent: float) -> Path | None:
    """Where the table of ``(ν, base, n)`` is kept between processes (``None``: caching is off).

    The directory of the SymPy relations (:func:`mdr_events.theory.symbolic.cache_path`): ``$MDR_EVENTS_CACHE_DIR``
    or ``$XDG_CACHE_HOME/mdr_events`` or ``~/.cache/mdr_events``; ``MDR_EVENTS_NO_CACHE=1`` turns it off. The name
    carries a hash of this module's source and NumPy's version, so a changed solver never reads an old table.

    Parameters
    ----------
    nu : float
        Poisson's ratio.
    base : LayerBase or str
        The layer's base.
    exponent : float
        The power law's exponent ``n`` of the table's profile columns.

    Returns
    -------
    pathlib.Path or None
        ``layer-<base>-nu<ν>-n<n>-<hash>.npz`` in that directory, or ``None``.
    """
    root = cache_directory()
    return None if root is None else root / f"layer-{_base(base).value}-nu{float(nu)!r}-n{float(exponent)!r}-{_SOURCE_DIGEST}.npz"


#: The tabulated columns, as logarithms: ``Φ``, ``Θ(1)``, ``γₙ``, ``χₙ``.
_COLUMNS = ("stiffness", "edge", "profile", "force")
#: The columns of the normal force (10), :meth:`LayerTable.force_factors`.
_FORCE_COLUMNS = ("stiffness", "profile", "force")


def _table_grid() -> np.ndarray:
    """The table's nodes in ``s = ln(a/h)``: :data:`TABLE_STEP` apart (at most) from ``LAMBDA_MIN`` to ``LAMBDA_MAX``."""
    return table_grid(LAMBDA_MIN, LAMBDA_MAX, TABLE_STEP)


def _table_row(lam: float, nu: float, base: LayerBase, exponent: float) -> tuple[float, float, float, float]:
    """``Φ, Θ(1), γₙ, χₙ`` at one ``λ`` by a direct solve."""
    solution = solve_punch(lam, nu, base, (exponent,))
    return (solution.stiffness_factor, solution.edge_factor, solution.profile_factor(), solution.force_factor())


def _build_table(nu: float, base: LayerBase, exponent: float) -> dict[str, np.ndarray]:
    grid = _table_grid()
    rows = np.array([_table_row(float(lam), nu, base, exponent) for lam in np.exp(grid)])
    if not np.all(rows > 0.0):  # (χₙ ≈ n/(n + 1) is lost to round-off when n is near 0: its logarithm is not finite)
        raise ValueError(f"exponent={exponent!r} is not allowed: its table's factors are lost to round-off (χₙ = "
                         f"{float(np.min(rows)):.3g}); allowed: an exponent whose factors are positive doubles "
                         "(n of 1e-10 and above)")
    out = {"s": grid, "k0": np.array(float(kernel(0.0, nu, base)))}
    out.update({name: np.log(rows[:, j]) for j, name in enumerate(_COLUMNS)})
    return out


def _stored_table(nu: float, base: LayerBase, exponent: float) -> dict[str, np.ndarray]:
    """The table's columns, read from the disk cache if there, else built (and stored: any trouble is only a missed
    shortcut)."""
    path = table_cache_path(nu, base, exponent)
    return stored_columns(path, ("s", "k0", *_COLUMNS), _table_grid(), lambda: _build_table(nu, base, exponent),
                          constants=("k0",))


@dataclass(frozen=True)
class LayerTable:
    r"""The punch factors of a layer against ``λ = a/h``, interpolated (quintic splines of their logarithms in
    ``ln λ``), for one ``(ν, base)`` and the power law's exponent ``n``.

    Below :data:`LAMBDA_MIN` the half-space side's series (exact to ``O(λ³)``):

    .. math:: \Phi = \Theta(1) = \frac{1}{1 - 2k(0)\lambda/\pi}, \quad
              \gamma_n = \frac{1 + (\Phi - 1)/(n+1)}{\Phi}, \quad \chi_n = \frac{n}{n+1}

    Parameters
    ----------
    nu : float
        Poisson's ratio.
    base : LayerBase
        The layer's base.
    exponent : float
        ``n`` of the profile's columns.
    columns : dict of str to numpy.ndarray
        ``s = ln λ`` at the nodes, ``k0 = k(0)`` and the logarithms of ``Φ``, ``Θ(1)``, ``γₙ``, ``χₙ``.
    """

    nu: float
    base: LayerBase
    exponent: float
    columns: dict

    @functools.cached_property
    def _splines(self) -> dict:
        from scipy.interpolate import make_interp_spline

        return {name: make_interp_spline(self.columns["s"], self.columns[name], k=5) for name in _COLUMNS}

    def _lam(self, lam) -> np.ndarray:
        return table_argument(lam, LAMBDA_MAX, "solve_punch solves up to LAMBDA_SOLVE_MAX")

    def _series(self, lam: np.ndarray) -> dict[str, np.ndarray]:
        phi = 1.0 / (1.0 - 2.0 * float(self.columns["k0"]) * lam / np.pi)
        n = self.exponent
        return {"stiffness": phi, "edge": phi, "profile": (1.0 + (phi - 1.0) / (n + 1.0)) / phi,
                "force": np.full(lam.shape, n / (n + 1.0))}

    def _value(self, name: str, lam, derivative: bool = False) -> np.ndarray:
        lam = self._lam(lam)
        small = lam < LAMBDA_MIN
        s = np.log(np.where(small, LAMBDA_MIN, lam))
        return self._column(name, lam, small, s, derivative)

    @functools.cached_property
    def _force_splines(self):
        """The splines of ``Φ``, ``γₙ``, ``χₙ`` as one spline of three columns (one knot vector: the same values, each
        column's sum taken as its own spline's, at a third of the calls)."""
        from scipy.interpolate import BSpline

        first = self._splines["stiffness"]
        columns = [self._splines[name] for name in _FORCE_COLUMNS]
        if not all(np.array_equal(first.t, column.t) for column in columns):
            raise ValueError("columns of different knots are not allowed; allowed: the columns of one table")
        return BSpline(first.t, np.stack([column.c for column in columns], axis=-1), first.k)

    def _column(self, name: str, lam: np.ndarray, small: np.ndarray, s: np.ndarray,
                derivative: bool = False, logarithm: np.ndarray | None = None) -> np.ndarray:
        """Column ``name`` (or its derivative) at the checked ``λ``, ``small = λ < LAMBDA_MIN``, ``s = ln λ`` (clamped
        to the table's first node): :meth:`_value`'s, and :meth:`force_factors`' three at one logarithm
        (``logarithm``: the spline's value at ``s``, where already evaluated)."""
        value = np.exp(self._splines[name](s) if logarithm is None else logarithm)
        if derivative:  # d/dλ = (d ln y/ds) y / λ
            value = self._splines[name](s, 1) * value / np.where(small, LAMBDA_MIN, lam)
        if np.any(small):
            series = self._series(lam)[name]
            if derivative:
                step = LAMBDA_MIN / 2.0
                lower = self._series(np.maximum(lam - step, 0.0))[name]
                series = (self._series(lam + step)[name] - lower) / (lam + step - np.maximum(lam - step, 0.0))
            value = np.where(small, series, value)
        return value

    def stiffness_factor(self, lam) -> np.ndarray:
        """``Φ(λ) = K(a)/(2E* a)`` (L2).

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.

        Returns
        -------
        numpy.ndarray
            ``Φ`` (1 at ``λ = 0``).

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        return self._value("stiffness", lam)

    def edge_factor(self, lam, derivative: bool = False) -> np.ndarray:
        """``Θ(1; λ)``: ``K'(a) = 2E* Θ(1)²`` (L3), or its derivative in ``λ``.

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.
        derivative : bool, default False
            ``dΘ(1)/dλ`` instead (the spline's derivative: the slope of the interpolant :meth:`edge_factor` reads).

        Returns
        -------
        numpy.ndarray
            ``Θ(1)`` (1 at ``λ = 0``) or its derivative.

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        return self._value("edge", lam, derivative)

    def profile_factor(self, lam, derivative: bool = False) -> np.ndarray:
        """``γₙ(λ) = g(a)/g∞(a)`` of the power law (L4), or its derivative in ``λ``.

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.
        derivative : bool, default False
            ``dγₙ/dλ`` instead (the spline's derivative: about 1e-6 relative).

        Returns
        -------
        numpy.ndarray
            ``γₙ`` (1 at ``λ = 0``) or its derivative.

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        return self._value("profile", lam, derivative)

    def force_factors(self, lam) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`stiffness_factor`, :meth:`profile_factor` and :meth:`force_factor` at once (one check of ``λ``, one
        logarithm: the same values).

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.

        Returns
        -------
        tuple of numpy.ndarray
            ``Φ``, ``γₙ``, ``χₙ``.

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        lam = self._lam(lam)
        small = lam < LAMBDA_MIN
        s = np.log(np.where(small, LAMBDA_MIN, lam))
        logarithms = np.moveaxis(self._force_splines(s), -1, 0).copy()  # (each column contiguous, as one spline's)
        return tuple(self._column(name, lam, small, s, logarithm=logarithm)
                     for name, logarithm in zip(_FORCE_COLUMNS, logarithms))

    def spline_force_factors(self, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`force_factors` of ``λ`` within the splines, ``LAMBDA_MIN <= λ <= LAMBDA_MAX``, unchecked (the
        continuum's samples; the same values bit for bit).

        Parameters
        ----------
        lam : numpy.ndarray
            ``a/h`` in ``[LAMBDA_MIN, LAMBDA_MAX]``.

        Returns
        -------
        tuple of numpy.ndarray
            ``Φ``, ``γₙ``, ``χₙ``.
        """
        return tuple(np.exp(np.moveaxis(self._force_splines(np.log(lam)), -1, 0)))

    def force_factor(self, lam) -> np.ndarray:
        """``χₙ(λ) = F₀(a)/(2E* a g∞(a))``: the non-adhesive force of the power law.

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.

        Returns
        -------
        numpy.ndarray
            ``χₙ`` (``n/(n + 1)`` at ``λ = 0``).

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        return self._value("force", lam)


@functools.lru_cache(maxsize=None)
def _layer_table(nu: float, base: LayerBase, exponent: float) -> LayerTable:
    return LayerTable(nu, base, exponent, _stored_table(nu, base, exponent))


def layer_table(nu: float, base: LayerBase | str = LayerBase.BONDED, exponent: float = 2.0) -> LayerTable:
    """The table of a layer's punch factors for ``(ν, base, n)``: built once per process, cached on disk.

    Building one takes about 2 s (:data:`TABLE_STEP`-spaced solves from ``a/h = 1e-4`` to :data:`LAMBDA_MAX`, the
    kernel's interpolants included); reading it from the cache a few milliseconds.

    Parameters
    ----------
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base.
    exponent : float, default 2.0
        The power law's exponent ``n > 0`` (2: the paraboloid).

    Returns
    -------
    LayerTable
        The interpolated factors ``Φ``, ``Θ(1)``, ``γₙ``, ``χₙ``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``, ``base`` unknown or ``exponent`` ≤ 0.
    """
    exponent = check_real("exponent", exponent, "a finite number > 0", lambda value: value > 0.0)
    return _layer_table(_nu(nu), _base(base), exponent)

