r"""The springs of a bonded layer at many coordinates in one evaluation of the tables: ``g``, ``k`` and ``k_t``.

The per-spring route of the continuum (:mod:`mdr_events.models.continuum.play_springs`) reads the springs' profile
``g(x) = κₙ c |x|ⁿ γₙ(λ)`` (L4), normal stiffness ``k(x) = E* Θ(1; λ)²`` (L3) and tangential stiffness
``k_t(x) = G* Σ_t(λ)`` (T4), ``λ = |x|/h``, at the quadrature's nodes and the kinks' bisection points: some thousand
times a run, each on a few hundred coordinates. Through the relations (:func:`~.relations.power_law_profile`,
:func:`~.relations.spring_stiffness_density`, :func:`~.tangential_relations.tangential_spring_stiffness_density`)
that is nine spline calls, three argument checks and three table look-ups an evaluation. The six columns they read
(``γₙ`` and ``Θ(1)`` of the normal tables, ``Φ_L``, ``Φ_T``, ``Ψ_L(1)``, ``Ψ_T(1)`` of the tangential one) are
quintic splines on the same nodes in ``s = ln λ`` (both tables' grids are ``table_grid(1e-4, 64, 0.1)``), so here
they are one spline of six columns: one logarithm, one spline call, one exponential. A multi-column spline sums each
column as its own spline does and each column's exponential is taken on a contiguous array, so the values are the
relations' bit for bit (``tests/theory/test_layer_spring_factors.py`` checks it); below ``LAMBDA_MIN`` the tables'
own series. The coordinates are not checked: the caller's contact lies within the tables (the continuum's reach check,
:mod:`mdr_events.models.continuum.layer_reach`).

:meth:`SpringFactors.ratio_floor` bounds ``k/k_t`` from below over ``0 <= |x| <= X`` without reading the springs: on
each knot interval of the spline each column lies within the least and largest of the quintic's six B-spline
coefficients active there (the convex-hull property: the basis is non-negative and sums to one), so each factor
within their exponentials; below ``LAMBDA_MIN`` the series ``1/(1 − 2k(0)λ/π)`` are monotone in ``λ``, bounded by
their ends. ``Σ_t`` (T4) is bounded above by interval arithmetic on its monotone parts (``Φ_t/Φ_L`` falls with
``Φ_L`` and rises with ``Φ_T``, ``Φ_t/Φ_T`` the other way), the ratio's bound per interval is ``E* Θ_lo²/(G* Σ_hi)``
and its running minimum from ``λ = 0`` the floor; lowered by :data:`RATIO_FLOOR_ROUNDING` for the floats' round-off.
Beyond the tables' last knot (``λ > LAMBDA_MAX``) the spline extrapolates its last piece, which its coefficients do
not bound (on the paper's ``ν`` the extrapolated ratio falls to nothing near ``λ`` 1e6): the floor there is ``0``.

Part of :mod:`mdr_events.theory.layer`.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.theory.layer.relations import _abel_factor, _power_law
from mdr_events.theory.layer.tables import LAMBDA_MIN, layer_table
from mdr_events.theory.layer.tangential_punch import _slope
from mdr_events.theory.layer.tangential_tables import LAMBDA_MIN as TANGENTIAL_LAMBDA_MIN, tangential_table

__all__ = ["SpringValues", "SpringFactors", "PunchSpringFactors", "RATIO_FLOOR_ROUNDING"]

#: The share by which :meth:`SpringFactors.ratio_floor` is lowered below its bound in exact arithmetic: the values
#: it bounds are some twenty floating-point operations on doubles (the spline's sum, the exponentials, ``Σ_t``'s
#: arithmetic), each within half an ulp (1.1e-16), so within some 5e-15 of the exact ones; 1e-12 leaves room.
RATIO_FLOOR_ROUNDING = 1e-12

#: The columns of the one spline: the normal tables' ``γₙ`` (of the profile's ``n``) and ``Θ(1)`` (of ``n = 2``, as
#: :func:`~.relations.spring_stiffness_density` reads it), then the tangential table's four.
_NORMAL_COLUMNS = ("profile", "edge")
_TANGENTIAL_COLUMNS = ("phi_l", "phi_t", "edge_l", "edge_t")


class SpringValues(NamedTuple):
    """The springs' values at the coordinates asked (:meth:`SpringFactors.values`)."""

    #: ``g(x)`` (m)
    profile: np.ndarray
    #: ``k(x)`` (Pa)
    normal: np.ndarray
    #: ``k_t(x)`` (Pa)
    tangential: np.ndarray


class SpringFactors:
    """``g``, ``k`` and ``k_t`` of a power law's springs on a bonded layer, vectorised over the coordinates (module
    docstring).

    Parameters
    ----------
    profile : Paraboloid or PowerLaw
        The indenter.
    E_star, G_star : float
        ``E*`` and ``G*`` (Pa).
    nu : float
        Poisson's ratio.
    layer : Layer
        The layer: finite thickness, bonded base.

    Raises
    ------
    ValueError
        A half-space or a frictionless base (no tangential table), or tables whose nodes differ.
    """

    def __init__(self, profile, E_star: float, G_star: float, nu: float, layer: Layer):
        from scipy.interpolate import BSpline

        if layer.is_half_space or layer.base is not LayerBase.BONDED:
            raise ValueError(f"layer={layer!r} is not allowed; allowed: a layer of finite thickness on a bonded base "
                             "(the half-space's springs need no table, a frictionless base has no tangential ones)")
        c, n = self._power(profile)
        normal, edge, tangential = layer_table(nu, layer.base, n), layer_table(nu, layer.base), tangential_table(nu)
        splines = [*(table._splines[name] for table, name in zip((normal, edge), _NORMAL_COLUMNS)),
                   *(tangential._splines[name] for name in _TANGENTIAL_COLUMNS)]
        if LAMBDA_MIN != TANGENTIAL_LAMBDA_MIN or not all(np.array_equal(splines[0].t, spline.t)
                                                          and spline.k == splines[0].k for spline in splines):
            raise ValueError("tables of different nodes are not allowed; allowed: the normal and tangential tables of "
                             "one grid")
        self._spline = BSpline(splines[0].t, np.stack([spline.c for spline in splines], axis=-1), splines[0].k)
        self.h, self.n, self.nu = layer.thickness, n, tangential.nu
        self.E_star, self.G_star = E_star, G_star
        #: ``κₙ c`` of ``g∞ = κₙ c xⁿ`` (3)
        self.scale = _abel_factor(n) * c
        self._tables = (normal, edge, tangential)

    @staticmethod
    def _power(profile) -> tuple[float, float]:
        """``c`` and ``n`` of the profile ``f = c rⁿ`` whose layer's table ``γₙ`` gives ``g``."""
        return _power_law(profile)

    def _profile(self, x: np.ndarray, gamma: np.ndarray) -> np.ndarray:
        """``g(x) = κₙ c xⁿ γₙ(x/h)`` (L4) at ``|x|``."""
        return self.scale * x**self.n * gamma

    def _factors(self, lam: np.ndarray) -> tuple[np.ndarray, ...]:
        """``γₙ``, ``Θ(1)``, ``Φ_L``, ``Φ_T``, ``Ψ_L(1)``, ``Ψ_T(1)`` at ``λ`` as the tables give them, each of
        ``λ``'s shape (a 0-d ``λ`` read as one element: the series are written into the rows)."""
        shape, lam = np.shape(lam), np.atleast_1d(lam)
        small = lam < LAMBDA_MIN
        s = np.log(np.where(small, LAMBDA_MIN, lam))
        # (the columns as contiguous rows, as each spline's own value: NumPy's exponential on contiguous doubles)
        factors = list(np.exp(np.ascontiguousarray(self._spline(s).T)))
        if np.any(small):  # (the tables' own series, elementwise: read at the small λ alone)
            normal, edge, tangential = self._tables
            few = lam[small]
            tangential_series = tangential._series(few)
            series = (*(table._series(few)[name] for table, name in zip((normal, edge), _NORMAL_COLUMNS)),
                      *(tangential_series[name] for name in _TANGENTIAL_COLUMNS))
            for value, exact in zip(factors, series):
                value[small] = exact
        return tuple(value.reshape(shape) for value in factors)

    def ratio_floor(self, x) -> np.ndarray:
        """A lower bound of ``k(ξ)/k_t(ξ)`` over ``0 <= |ξ| <= x`` at each ``x`` (module docstring), at or below the
        values :meth:`values` gives at every such ``ξ``, without reading the springs.

        Parameters
        ----------
        x : array_like
            The extents (m). Where ``|x|/h`` lies beyond the tables' last knot (``LAMBDA_MAX``) the spline
            extrapolates, its coefficients bound nothing there, and the floor is ``0`` (``k/k_t >= 0``: no bound
            claimed, the caller reads the springs).

        Returns
        -------
        numpy.ndarray
            The floors, of ``x``'s shape.
        """
        lefts, floors, end = self._floors
        s = np.log(np.maximum(np.abs(np.asarray(x, dtype=float)) / self.h, LAMBDA_MIN))
        # (``floors[i]`` ends with the interval ``i − 1``: through the one holding ``s`` and the next, so that a
        # coordinate at a knot, rounded either way, is covered)
        floor = floors[np.minimum(np.searchsorted(lefts, s, side="right") + 1, floors.size - 1)]
        return np.where(s > end, 0.0, floor)

    @functools.cached_property
    def _floors(self) -> tuple[np.ndarray, np.ndarray, float]:
        """The left knots of the spline's intervals, the running minimum of ``k/k_t``'s bound from ``λ = 0`` to
        the end of each, the series' stretch first, and the last interval's right knot, ``ln LAMBDA_MAX`` (beyond it
        the spline extrapolates: :meth:`ratio_floor`)."""
        knots, c, k = self._spline.t, self._spline.c[:, 1:], self._spline.k
        pieces = np.flatnonzero(knots[k:c.shape[0]] < knots[k + 1:c.shape[0] + 1]) + k
        active = np.stack([c[piece - k:piece + 1] for piece in pieces])  # (piece, the six coefficients, column)
        low, high = np.exp(active.min(axis=1)), np.exp(active.max(axis=1))
        _, edge, tangential = self._tables
        ends = np.array([0.0, LAMBDA_MIN])
        theta, phi_l, phi_t = edge._series(ends)["edge"], *(tangential._series(ends)[name] for name in ("phi_l",
                                                                                                       "phi_t"))
        series = np.column_stack([theta, phi_l, phi_t, phi_l, phi_t])  # (Ψ_m(1) = Φ_m below LAMBDA_MIN)
        low, high = np.vstack([series.min(axis=0), low]), np.vstack([series.max(axis=0), high])
        bound = self.E_star * low[:, 0] ** 2 / (self.G_star * self._slope_ceiling(low[:, 1:], high[:, 1:]))
        return (knots[pieces], np.minimum.accumulate(bound) * (1.0 - RATIO_FLOOR_ROUNDING),
                float(knots[pieces[-1] + 1]))

    def _slope_ceiling(self, low: np.ndarray, high: np.ndarray) -> np.ndarray:
        """An upper bound of ``Σ_t`` (T4) where ``Φ_L, Φ_T, Ψ_L(1), Ψ_T(1)`` lie between ``low`` and ``high`` (columns
        in that order, all positive): ``Σ_t = ((1 − ν) Ψ_L² (Φ_t/Φ_L)² + Ψ_T² (Φ_t/Φ_T)²)/(2 − ν)``, ``Φ_t/Φ_L =
        (2 − ν)Φ_T/((1 − ν)Φ_T + Φ_L)`` and ``Φ_t/Φ_T = (2 − ν)Φ_L/((1 − ν)Φ_T + Φ_L)``, each monotone in both."""
        nu = self.nu
        over_l = (2.0 - nu) * high[:, 1] / ((1.0 - nu) * high[:, 1] + low[:, 0])
        over_t = (2.0 - nu) * high[:, 0] / ((1.0 - nu) * low[:, 1] + high[:, 0])
        return ((1.0 - nu) * (high[:, 2] * over_l) ** 2 + (high[:, 3] * over_t) ** 2) / (2.0 - nu)

    def values(self, x) -> SpringValues:
        """``g``, ``k`` and ``k_t`` at ``x`` (the relations' arithmetic on the same factors: their values bit for bit).

        Parameters
        ----------
        x : array_like
            The springs' coordinates (m), ``|x|/h <= LAMBDA_MAX`` (not checked).

        Returns
        -------
        SpringValues
            The profile, the normal and the tangential stiffness densities.
        """
        x = np.abs(np.asarray(x, dtype=float))
        gamma, theta, phi_l, phi_t, edge_l, edge_t = self._factors(x / self.h)
        return SpringValues(self._profile(x, gamma), self.E_star * theta * theta,
                            self.G_star * _slope(self.nu, phi_l, phi_t, edge_l, edge_t))


class PunchSpringFactors(SpringFactors):
    """``g``, ``k`` and ``k_t`` of the flat punch's springs on a bonded layer: ``g = 0`` under the face and ``+inf``
    beyond it (no spring there is ever touched), the discrete model's
    (:meth:`~mdr_events.models.spring_media.LayerSprings.profile`), ``k`` and ``k_t`` as :class:`SpringFactors`
    (``f = 0`` under the face makes ``g = 0`` on any layer, (L4); the normal table of ``n = 2`` gives ``Θ(1)``, its
    ``γ₂`` unread).

    Parameters
    ----------
    profile : FlatPunch
        The punch.
    E_star, G_star, nu, layer
        As :class:`SpringFactors`.

    Raises
    ------
    ValueError
        As :class:`SpringFactors`.
    """

    def __init__(self, profile, E_star: float, G_star: float, nu: float, layer: Layer):
        #: the face's radius ``a₀`` (m)
        self.face = float(profile.radius)
        super().__init__(profile, E_star, G_star, nu, layer)

    @staticmethod
    def _power(profile) -> tuple[float, float]:
        return 0.0, 2.0  # (the normal table of n = 2 for Θ(1); its γ₂ unread: g is the face's, :meth:`_profile`)

    def _profile(self, x: np.ndarray, gamma: np.ndarray) -> np.ndarray:
        """``0`` under the face, ``+inf`` beyond it (``|x|``)."""
        return np.where(x <= self.face, 0.0, np.inf)
