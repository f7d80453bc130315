r"""The layer's tabulated factors for one Python float, with their slopes: what the continuum's right-hand side reads.

The tables (:class:`~mdr_events.theory.layer.tables.LayerTable`,
:class:`~mdr_events.theory.layer.tangential_tables.TangentialTable`) interpolate the logarithm of each factor by a
quintic spline in ``s = ln λ``; their vectorised evaluation costs tens of microseconds a call, and the continuum calls
a factor thousands of times per span. Here the same splines are held as piecewise polynomials (SciPy's ``PPoly`` of
the B-spline: the same function to round-off) evaluated in pure Python: the interval by bisection, the value and the
slope by Horner's rule, ``y = exp(p(s))`` and ``dy/dλ = p'(s) y/λ``. Below :data:`~.tables.LAMBDA_MIN` the tables'
own series, with their exact slopes.

Part of :mod:`mdr_events.theory.layer`.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.tables import LAMBDA_MIN, layer_table
from mdr_events.theory.layer.tangential_tables import LAMBDA_MIN as TANGENTIAL_LAMBDA_MIN, tangential_table

__all__ = ["LogColumn", "NormalFactors", "TangentialFactors", "DEGREE", "piece_index"]

#: The tables' splines' degree (quintic), whose pieces :class:`LogColumn` evaluates by Horner's rule unrolled.
DEGREE = 5


def piece_index(breaks: np.ndarray, s: np.ndarray, last: int) -> np.ndarray:
    """The piece of each ``s`` among the pieces that start at ``breaks``: ``searchsorted(breaks, s, "right") − 1``
    kept within ``[0, last]`` (below the first break the first piece, beyond the last the last, as
    ``bisect.bisect_right`` with the scalar routes' bounds).

    ``np.clip`` of the indices, the same integers: NumPy's ``clip`` costs ~10 µs a call in its checks, these two
    in-place bounds ~1 µs each, and a run reads a table's pieces this way some ten times.

    Parameters
    ----------
    breaks : numpy.ndarray
        The pieces' starts, increasing.
    s : numpy.ndarray
        The points.
    last : int
        The index of the last piece (``>= 0``).

    Returns
    -------
    numpy.ndarray
        The pieces' indices (integers), the shape of ``s``.
    """
    index = np.asarray(np.searchsorted(breaks, s, side="right"))  # (a new array: bounded in place; 0-d for one s)
    index -= 1
    np.maximum(index, 0, out=index)
    np.minimum(index, last, out=index)
    return index


class LogColumn:
    """One tabulated column ``ln y(s)`` (a spline of degree 5) as a piecewise polynomial evaluated in pure Python.

    Parameters
    ----------
    spline : scipy.interpolate.BSpline
        The table's spline of ``ln y`` in ``s = ln λ``.
    """

    def __init__(self, spline):
        from scipy.interpolate import PPoly

        self.spline = spline
        pieces = PPoly.from_spline(spline)
        self.breaks = [float(value) for value in pieces.x]
        if pieces.c.shape[0] != DEGREE + 1:
            raise ValueError(f"a spline of degree {pieces.c.shape[0] - 1} is not allowed; allowed: degree {DEGREE}")
        self.coefficients = [tuple(float(value) for value in pieces.c[:, i]) for i in range(pieces.c.shape[1])]
        self.last = len(self.coefficients) - 1
        self._arrays: tuple[np.ndarray, np.ndarray] | None = None  # (:meth:`values_array`'s, made when first asked)

    def value_and_slope(self, lam: float) -> tuple[float, float]:
        """``y(λ)`` and ``dy/dλ`` for ``λ`` within the table (``λ ≥ LAMBDA_MIN``).

        Parameters
        ----------
        lam : float
            ``a/h``.

        Returns
        -------
        tuple of float
            The factor and its derivative in ``λ``.
        """
        s = math.log(lam)
        index = bisect.bisect_right(self.breaks, s) - 1
        index = 0 if index < 0 else (self.last if index > self.last else index)
        x = s - self.breaks[index]
        c5, c4, c3, c2, c1, c0 = self.coefficients[index]  # (highest power first: Horner's rule, unrolled)
        value = ((((c5 * x + c4) * x + c3) * x + c2) * x + c1) * x + c0
        slope = (((5.0 * c5 * x + 4.0 * c4) * x + 3.0 * c3) * x + 2.0 * c2) * x + c1
        y = math.exp(value)
        return y, slope * y / lam

    def values_array(self, lam: np.ndarray) -> np.ndarray:
        """``y(λ)`` for an array of ``λ ≥ LAMBDA_MIN``: the same pieces by Horner's rule on the arrays (one spline
        call of SciPy's costs its checks and a copy; these few operations on NumPy's arrays cost less for a run's
        samples, and their values are the B-spline's to round-off, ``PPoly.from_spline``).

        Parameters
        ----------
        lam : numpy.ndarray
            ``a/h``.

        Returns
        -------
        numpy.ndarray
            The factor.
        """
        if self._arrays is None:
            self._arrays = np.array(self.breaks), np.array(self.coefficients).T
        breaks, coefficients = self._arrays
        s = np.log(lam)
        index = piece_index(breaks, s, self.last)
        x = s - breaks[index]
        c5, c4, c3, c2, c1, c0 = coefficients[:, index]
        return np.exp(((((c5 * x + c4) * x + c3) * x + c2) * x + c1) * x + c0)


class LogPair:
    """Two tabulated columns on the same nodes (one table's splines share their knots), evaluated together: one
    logarithm and one bisection for both (:meth:`LogColumn.value_and_slope` each otherwise).

    Parameters
    ----------
    first, second : LogColumn
        The columns.

    Raises
    ------
    ValueError
        Columns whose pieces do not share their breaks.
    """

    def __init__(self, first: LogColumn, second: LogColumn):
        if first.breaks != second.breaks:
            raise ValueError("columns of different nodes are not allowed; allowed: two columns of one table")
        self.breaks, self.last = first.breaks, first.last
        self.coefficients = list(zip(first.coefficients, second.coefficients))
        #: the same for arrays: the breaks, and the coefficients as ``(column, power, piece)``
        self._breaks = np.array(self.breaks)
        self._coefficients = np.array([np.array(first.coefficients).T, np.array(second.coefficients).T])

    def values_and_slopes(self, lam: float) -> tuple[float, float, float, float]:
        """Both columns' ``y(λ)`` and ``dy/dλ`` for ``λ`` within the table (``λ ≥ LAMBDA_MIN``).

        Parameters
        ----------
        lam : float
            ``a/h``.

        Returns
        -------
        tuple of float
            The first factor and its derivative in ``λ``, then the second's.
        """
        s = math.log(lam)
        index = bisect.bisect_right(self.breaks, s) - 1
        index = 0 if index < 0 else (self.last if index > self.last else index)
        x = s - self.breaks[index]
        out = []
        for c5, c4, c3, c2, c1, c0 in self.coefficients[index]:  # (Horner's rule, unrolled, as LogColumn's)
            value = ((((c5 * x + c4) * x + c3) * x + c2) * x + c1) * x + c0
            slope = (((5.0 * c5 * x + 4.0 * c4) * x + 3.0 * c3) * x + 2.0 * c2) * x + c1
            y = math.exp(value)
            out += (y, slope * y / lam)
        return tuple(out)


    def values_array(self, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Both columns' ``y(λ)`` for an array of ``λ ≥ LAMBDA_MIN`` (:meth:`values_and_slopes_array`'s values, the
        same operations: the same values bit for bit).

        Parameters
        ----------
        lam : numpy.ndarray
            ``a/h``.

        Returns
        -------
        tuple of numpy.ndarray
            The first factor, then the second.
        """
        s = np.log(lam)
        index = piece_index(self._breaks, s, self.last)
        x = s - self._breaks[index]
        return tuple(np.exp(((((c5 * x + c4) * x + c3) * x + c2) * x + c1) * x + c0)
                     for c5, c4, c3, c2, c1, c0 in self._coefficients[:, :, index])

    def values_and_slopes_array(self, lam: np.ndarray, columns: int = 2) -> tuple[np.ndarray, ...]:
        """:meth:`values_and_slopes` for an array of ``λ ≥ LAMBDA_MIN`` (Horner's rule on the arrays).

        Parameters
        ----------
        lam : numpy.ndarray
            ``a/h``.
        columns : int, default 2
            How many columns, the first first (1: the first alone, its values bit for bit those of both).

        Returns
        -------
        tuple of numpy.ndarray
            The first factor and its derivative in ``λ``, then the second's (with ``columns=2``).
        """
        s = np.log(lam)
        index = piece_index(self._breaks, s, self.last)
        x = s - self._breaks[index]
        out = []
        for c5, c4, c3, c2, c1, c0 in self._coefficients[:columns, :, index]:
            value = ((((c5 * x + c4) * x + c3) * x + c2) * x + c1) * x + c0
            slope = (((5.0 * c5 * x + 4.0 * c4) * x + 3.0 * c3) * x + 2.0 * c2) * x + c1
            y = np.exp(value)
            out += (y, slope * y / lam)
        return tuple(out)


class NormalFactors:
    """The normal table's ``Θ(1)`` (``K' = 2E* Θ²``) and profile factor ``γₙ`` of a layer, for one float, with slopes.

    Parameters
    ----------
    nu : float
        Poisson's ratio.
    layer : Layer
        The layer (finite thickness).
    exponent : float
        The profile's power ``n`` (2: the paraboloid).
    """

    def __init__(self, nu: float, layer: Layer, exponent: float):
        table = layer_table(nu, layer.base, exponent)
        self.h, self.n = layer.thickness, exponent
        self.k0 = float(table.columns["k0"])
        self.edge = LogColumn(table._splines["edge"])
        self.profile = LogColumn(table._splines["profile"])
        self.stiffness = LogColumn(table._splines["stiffness"])
        self.both = LogPair(self.edge, self.profile)

    def edge_and_profile(self, a: float) -> tuple[float, float, float, float]:
        """:meth:`edge_factor` and :meth:`profile_factor` at once: ``Θ``, ``dΘ/dλ``, ``γₙ``, ``dγₙ/dλ``.

        Parameters
        ----------
        a : float
            The radius (m).

        Returns
        -------
        tuple of float
            ``Θ`` and its derivative in ``λ``, ``γₙ`` and its derivative.
        """
        lam = a / self.h
        if lam < LAMBDA_MIN:
            return (*self.edge_factor(a), *self.profile_factor(a))
        return self.both.values_and_slopes(lam)

    def arrays(self, a: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``Θ(1)``, ``dΘ/dλ``, ``γₙ`` and ``dγₙ/dλ`` at the radii ``a`` (the pieces of :meth:`edge_and_profile`
        evaluated on the arrays; the series' slopes below ``LAMBDA_MIN`` exact, as :meth:`edge_factor` and
        :meth:`profile_factor` give them).

        Parameters
        ----------
        a : numpy.ndarray
            The radii (m), ``0 <= a/h <= LAMBDA_MAX``.

        Returns
        -------
        tuple of numpy.ndarray
            ``Θ``, ``dΘ/dλ``, ``γₙ``, ``dγₙ/dλ``.
        """
        lam = np.asarray(a, dtype=float) / self.h
        small = lam < LAMBDA_MIN
        values = list(self.both.values_and_slopes_array(np.where(small, LAMBDA_MIN, lam)))
        if np.any(small):
            theta, theta_slope = self._edge_series(lam)
            share = self.n / (self.n + 1.0)
            series = (theta, theta_slope, share / theta + 1.0 / (self.n + 1.0), -share * theta_slope / (theta * theta))
            values = [np.where(small, exact, value) for exact, value in zip(series, values)]
        return tuple(values)

    def edge_arrays(self, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``Θ(1)`` and ``dΘ/dλ`` at the radii ``a``: :meth:`arrays`' first two bit for bit, without the profile
        factor's column (a flat punch's springs rest on ``g = 0`` and read none).

        Parameters
        ----------
        a : numpy.ndarray
            The radii (m), ``0 <= a/h <= LAMBDA_MAX``.

        Returns
        -------
        tuple of numpy.ndarray
            ``Θ`` and ``dΘ/dλ``.
        """
        lam = np.asarray(a, dtype=float) / self.h
        small = lam < LAMBDA_MIN
        theta, theta_slope = self.both.values_and_slopes_array(np.where(small, LAMBDA_MIN, lam), columns=1)
        if np.any(small):
            exact, exact_slope = self._edge_series(lam)
            theta, theta_slope = np.where(small, exact, theta), np.where(small, exact_slope, theta_slope)
        return theta, theta_slope

    def _edge_series(self, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``Θ = 1/(1 − 2k(0)λ/π)`` and ``dΘ/dλ = 2k(0)Θ²/π`` at ``λ``: the series below ``LAMBDA_MIN`` that
        :meth:`arrays` and :meth:`edge_arrays` read there."""
        theta = 1.0 / (1.0 - 2.0 * self.k0 * lam / math.pi)
        return theta, 2.0 * self.k0 / math.pi * theta * theta

    def stiffness_factor(self, a: float) -> float:
        """``Φ(λ) = K(a)/(2E* a)`` at ``λ = a/h`` (the series ``1/(1 − 2k(0)λ/π)`` below ``LAMBDA_MIN``).

        Parameters
        ----------
        a : float
            The radius (m).

        Returns
        -------
        float
            ``Φ``.
        """
        lam = a / self.h
        if lam < LAMBDA_MIN:
            return 1.0 / (1.0 - 2.0 * self.k0 * lam / math.pi)
        return self.stiffness.value_and_slope(lam)[0]

    def edge_factor(self, a: float) -> tuple[float, float]:
        """``Θ(1; λ)`` and ``dΘ/dλ`` at ``λ = a/h`` (the series ``1/(1 − 2k(0)λ/π)`` below ``LAMBDA_MIN``).

        Parameters
        ----------
        a : float
            The radius (m).

        Returns
        -------
        tuple of float
            ``Θ`` and its derivative in ``λ``.
        """
        lam = a / self.h
        if lam < LAMBDA_MIN:
            theta = 1.0 / (1.0 - 2.0 * self.k0 * lam / math.pi)
            return theta, 2.0 * self.k0 / math.pi * theta * theta
        return self.edge.value_and_slope(lam)

    def profile_factor(self, a: float) -> tuple[float, float]:
        """``γₙ(λ)`` and ``dγₙ/dλ`` at ``λ = a/h`` (the series ``(n/(n+1))/Φ + 1/(n+1)`` below ``LAMBDA_MIN``).

        Parameters
        ----------
        a : float
            The radius (m).

        Returns
        -------
        tuple of float
            ``γₙ`` and its derivative in ``λ``.
        """
        lam = a / self.h
        if lam < LAMBDA_MIN:
            phi, phi_slope = self.edge_factor(a)  # (Φ = Θ(1) on the series)
            share = self.n / (self.n + 1.0)
            return share / phi + 1.0 / (self.n + 1.0), -share * phi_slope / (phi * phi)
        return self.profile.value_and_slope(lam)


class TangentialFactors:
    """The tangential table's ``Φ_L``, ``Φ_T`` of a bonded layer, combined into ``Φ_t`` (T3), with its slope.

    Parameters
    ----------
    nu : float
        Poisson's ratio.
    layer : Layer
        The layer (finite thickness, bonded base).
    combine : callable
        ``(Φ_t, dΦ_t/dλ)(ν, Φ_L, Φ_T, Φ_L', Φ_T')`` (``layer_continuum_tangential_factor_pair``).
    """

    def __init__(self, nu: float, layer: Layer, combine: Callable[..., tuple[float, float]]):
        table = tangential_table(nu)
        self.nu, self.h = nu, layer.thickness
        self.k0 = tuple(float(value) for value in table.columns["k0"])
        self.columns = LogPair(LogColumn(table._splines["phi_l"]), LogColumn(table._splines["phi_t"]))
        self.combine = combine

    def _parts(self, lam: float) -> tuple[float, float, float, float]:
        """``Φ_L``, ``Φ_T`` and their slopes in ``λ`` (the series ``1/(1 − 2k_m(0)λ/π)`` below ``LAMBDA_MIN``)."""
        if lam >= TANGENTIAL_LAMBDA_MIN:
            phi_l, slope_l, phi_t, slope_t = self.columns.values_and_slopes(lam)
            return phi_l, phi_t, slope_l, slope_t
        (phi_l, slope_l), (phi_t, slope_t) = ((1.0 / (1.0 - 2.0 * k * lam / math.pi),
                                               2.0 * k / math.pi / (1.0 - 2.0 * k * lam / math.pi) ** 2)
                                              for k in self.k0)
        return phi_l, phi_t, slope_l, slope_t

    def parts_array(self, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`_parts` for an array of ``λ`` (the same splines by Horner's rule on the arrays, the same series below
        ``LAMBDA_MIN``): what ``combine``'s array form takes.

        Parameters
        ----------
        lam : numpy.ndarray
            ``a/h`` (``0 <= λ <= LAMBDA_MAX``).

        Returns
        -------
        tuple of numpy.ndarray
            ``Φ_L``, ``Φ_T`` and their slopes in ``λ``.
        """
        lam = np.asarray(lam, dtype=float)
        small = lam < TANGENTIAL_LAMBDA_MIN
        phi_l, slope_l, phi_t, slope_t = self.columns.values_and_slopes_array(np.where(small, TANGENTIAL_LAMBDA_MIN,
                                                                                         lam))
        if np.any(small):
            series = []
            for k in self.k0:
                factor = 1.0 / (1.0 - 2.0 * k * lam / math.pi)
                series += (factor, 2.0 * k / math.pi * factor * factor)
            phi_l, slope_l, phi_t, slope_t = (np.where(small, exact, value) for exact, value
                                              in zip(series, (phi_l, slope_l, phi_t, slope_t)))
        return phi_l, phi_t, slope_l, slope_t

    def factors_array(self, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`parts_array`'s ``Φ_L`` and ``Φ_T`` alone, without their slopes (the same values bit for bit).

        Parameters
        ----------
        lam : numpy.ndarray
            ``a/h`` (``0 <= λ <= LAMBDA_MAX``).

        Returns
        -------
        tuple of numpy.ndarray
            ``Φ_L`` and ``Φ_T``.
        """
        lam = np.asarray(lam, dtype=float)
        small = lam < TANGENTIAL_LAMBDA_MIN
        values = self.columns.values_array(np.where(small, TANGENTIAL_LAMBDA_MIN, lam))
        if np.any(small):
            values = tuple(np.where(small, 1.0 / (1.0 - 2.0 * k * lam / math.pi), value)
                           for k, value in zip(self.k0, values))
        return values

    def stiffness_factor(self, a: float) -> tuple[float, float]:
        """``Φ_t(λ) = K_t/(2G* a)`` and ``dΦ_t/dλ`` at ``λ = a/h``.

        Parameters
        ----------
        a : float
            The radius (m).

        Returns
        -------
        tuple of float
            ``Φ_t`` and its derivative in ``λ``.
        """
        return self.combine(self.nu, *self._parts(a / self.h))
