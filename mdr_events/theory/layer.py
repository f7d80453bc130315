r"""The generalized MDR for an elastic layer of thickness ``h`` on a rigid base (issue 34): the punch problem solved
numerically, tabulated against ``a/h``, and the MDR relations built on it.

The layer's punch problem
-------------------------
A rigid flat punch of radius ``a`` pressed by ``w₀`` into the layer (frictionless top; base bonded or frictionless,
:class:`~mdr_events.contact.layer.LayerBase`). In Hankel space the layer's surface displacement under a pressure
``p(r)`` is

.. math:: w(r) = \frac{2}{E^*}\int_0^\infty \hat p(\xi)\, C(\xi h)\, J_0(\xi r)\,\mathrm{d}\xi,
          \qquad \hat p(\xi) = \int_0^\infty p(r)\, r J_0(\xi r)\,\mathrm{d}r,

with the compliance function (:func:`compliance_function`; derived from Love's strain function in
:mod:`mdr_events.theory.layer_symbolic`, ``κ = 3 − 4ν``)

.. math:: C_\mathrm{bonded}(t) = \frac{2\kappa\sinh 2t - 4t}{2\kappa\cosh 2t + 1 + \kappa^2 + 4t^2}, \qquad
          C_\mathrm{frictionless}(t) = \frac{\cosh 2t - 1}{\sinh 2t + 2t},

``C → 1`` as ``t → ∞`` (the half-space). Writing ``p̂(ξ) = ∫₀ᵃ θ(t) cos ξt dt`` and inverting the Abel operator of
the contact condition ``w = w₀`` (``r < a``) gives the Fredholm equation of the second kind of Lebedev & Ufliand
(PMM 22 (1958) 442; the same kernels in Hayes, Keer, Herrmann & Mockros, J. Biomech. 5 (1972) 541), with
``θ(t) = (E* w₀/π) Θ(t/a)`` and ``λ = a/h``:

.. math:: \Theta(\tau) - \frac{\lambda}{\pi}\int_0^1 \Theta(\sigma)\,
          [k(\lambda(\tau-\sigma)) + k(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = 1,
          \qquad k(v) = \int_0^\infty [1 - C(u)] \cos(u v)\,\mathrm{d}u \quad (L1)

(:func:`kernel`). The force is ``F = 2π p̂(0)``: the stiffness ``K(a) = 2E* a Φ(λ)``, ``Φ = ∫₀¹ Θ`` (L2). The
edge value gives the slope: the punch's stress intensity ``K_I = θ(a) sqrt(π/a)`` and Griffith's balance (below)
make ``K'(a) = 2E* Θ(1)²`` (L3), so that ``d(λΦ)/dλ = Θ(1)²`` (checked by the tests). A profile ``f`` enters through
the right-hand side: at depth ``d``, ``θ = (E*/π)[d Θ − Θ_g]``, ``Θ_g`` the solution of (L1) with the right-hand side
``g∞(aτ)`` (``g∞`` the half-space's MDR profile, the Abel transform (3)); its non-adhesive depth, the generalized MDR
profile, is ``g(a) = Θ_g(1)/Θ(1)`` (L4) (no singular pressure at the edge). The surface outside the punch is
``φ(r; a) = (2/π)[arcsin(a/r) − ∫_a^r G(t/a)/sqrt(r² − t²) dt]`` with ``G = Θ − 1`` continued by (L1) (L5).

Numerics: Gauss–Legendre (Nyström) on ``[0, 1]`` with ``N = 40 + 6λ`` nodes (rounded up to 16; spectral: the kernel
is analytic in ``|Im v| < 2``); ``k`` from a Gauss–Legendre quadrature of ``1 − C`` (evaluated without
cancellation), kept as piecewise Chebyshev interpolants on ``v`` (20 points per unit). The solve converges to
round-off (1e-12 relative at ``λ = 20``) and the tables are interpolated to better than 1e-8.

The generalized MDR (Machines 11(4):474, 2023, doi:10.3390/machines11040474, and the works it cites)
----------------------------------------------------------------------------------------------------
The springs' stiffness density ``k(x) = K'(x)/2`` (:func:`spring_stiffness_density`), the equivalent profile from
``f(r) = ∫₀ʳ [1 − φ(r; ã)] g'(ã) dã`` (:func:`equivalent_profile`), the normal force
``F_N = ∫₋ₐᵃ k(x)(d − g(x)) dx = F₀(a) + K(a)(d − g(a))`` (:func:`normal_force`) and Heß's rule
``Δl = sqrt(4π a Δγ / K'(a))`` (:func:`hess_elongation`; from Griffith's balance, derived in
:mod:`mdr_events.theory.layer_symbolic`). At ``h = inf`` each is the half-space's relation exactly
(``Φ = Θ(1) = γ = 1``).

Tables
------
:func:`layer_table` tabulates, per ``(ν, base, n)``, ``Φ``, ``Θ(1)``, the profile factor ``γₙ = g/g∞`` and the force
factor ``χₙ = F₀/(2E* a g∞(a))`` of the power law ``c rⁿ`` against ``s = ln(a/h)`` from ``a/h = 1e-4`` to
:data:`LAMBDA_MAX` (quintic splines of the logarithms, error below 1e-8 against direct solves at the mid-points);
below ``1e-4`` the series ``Φ = Θ(1) = 1/(1 − 2k(0)λ/π)``, ``Θₙ(1) = 1 + (Φ − 1)/(n + 1)``, ``χₙ = n/(n + 1)``
(errors ``O(λ³)``). Built in about 2 s per ``(ν, base, n)`` and cached on disk (:func:`table_cache_path`).
"""

from __future__ import annotations

import functools
import hashlib
import math
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.validation import check_count, check_real, real_array, shown

__all__ = ["LAMBDA_MAX", "LAMBDA_MIN", "LAMBDA_SOLVE_MAX", "KERNEL_V_MAX", "SOLVE_BYTES_PER_PAIR",
           "compliance_function", "kernel", "nystrom_nodes", "PunchSolution",
           "solve_punch", "LayerTable", "layer_table", "table_cache_path", "punch_stiffness", "punch_stiffness_slope",
           "spring_stiffness_density", "hess_elongation", "surface_displacement", "equivalent_profile",
           "power_law_profile", "power_law_profile_slope", "normal_force", "branch_depth", "branch_normal_force",
           "pull_off", "PullOff"]

#: The largest ``a/h`` of a table (the thin side); direct solves (:func:`solve_punch`) go to :data:`LAMBDA_SOLVE_MAX`.
LAMBDA_MAX = 64.0
#: The largest ``a/h`` of a direct solve: the range where the default nodes are converged to 1e-10 (see
#: :data:`BASE_NODES`); beyond it the solve grows as ``λ²`` in memory and ``λ³`` in time (1000 took 5 GiB).
LAMBDA_SOLVE_MAX = 200.0
#: The largest ``|v|`` of :func:`kernel`: the kernel's quadrature is exact to 1e-15 up to it (:data:`_U_PANEL`).
KERNEL_V_MAX = 200.0
#: Memory of a Nyström solve per pair of nodes (the kernel's interpolants evaluated on the ``nodes²`` grid twice,
#: 20 Chebyshev coefficients each, and the matrix), in bytes, checked against :class:`~mdr_events.Limits`.
SOLVE_BYTES_PER_PAIR = 400.0
#: The smallest ``a/h`` of a table: below it the series of the half-space side is exact to ``O(λ³) < 1e-11``.
LAMBDA_MIN = 1e-4
#: Spacing of the table's nodes in ``ln(a/h)``: quintic splines on it interpolate to about 2e-9 (the tests check
#: 1e-8 at every mid-point).
TABLE_STEP = 0.1
#: Gauss–Legendre nodes of the Fredholm equation: ``BASE_NODES + NODES_PER_LAMBDA λ``, rounded up to 16 (converged
#: to 1e-10 relative or better up to ``λ = 200``; the tests check it against more nodes).
BASE_NODES, NODES_PER_LAMBDA = 40, 6
#: The kernel's quadrature in ``u``: panels of this width with 20 nodes each up to :data:`_U_MAX`, where ``1 − C``
#: is below 1e-17 (it decays as ``u² e^{-2u}``); exact to 1e-15 for ``|v| ≤ 200``.
_U_PANEL, _U_NODES, _U_MAX = 0.1, 20, 24.0
#: The kernel's Chebyshev interpolants: unit panels in ``v`` with 20 points (error below 1e-14: ``k`` is analytic in
#: ``|Im v| < 2``).
_V_PANEL, _V_NODES = 1.0, 20
#: Beyond this ``u``, ``e^{-2u}`` is 0 in double precision and so is ``1 − C(u)`` (computed at it: exactly 0).
_U_ZERO = 800.0
#: Nodes of the quadrature of the outer surface integral (L5) in the angle ``β``.
_OUTER_NODES = 64

#: Hash of this module's source: the key of the tables on disk (a change of the code never reads an old table).
_SOURCE_DIGEST = hashlib.sha256(Path(__file__).read_bytes() + np.__version__.encode()).hexdigest()[:16]


def _base(base: LayerBase | str) -> LayerBase:
    return base if isinstance(base, LayerBase) else Layer(1.0, base).base


def _nu(nu: float) -> float:
    return check_real("nu", nu, "a finite number in [0, 0.5]", lambda value: 0.0 <= value <= 0.5)


def _reals(name: str, value, allowed: str, valid=None) -> np.ndarray:
    """``value`` as a float array of finite numbers for which ``valid`` holds everywhere, else a one-line
    ``TypeError``/``ValueError`` naming ``name``, the first bad entry and ``allowed`` (every array argument of
    this module: radii, coordinates, depths, ``ξh``, ``v``, ``ρ``)."""
    array = real_array(name, value, f"{allowed}: a number or an array of numbers")
    bad = ~np.isfinite(array)
    if valid is not None:
        bad |= ~np.where(bad, True, valid(np.where(bad, 0.0, array)))
    if np.any(bad):
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"[{', '.join(map(str, index))}]" if array.ndim else ""
        raise ValueError(f"{name}{where}={float(array[index])!r} is not allowed; allowed: {allowed}")
    return array


def _scalar(name: str, value, allowed: str, valid) -> float:
    return check_real(name, value, allowed, valid)


def _finite_result(name: str, result, **arguments):
    """``result`` if every value of it is finite, else a ``ValueError`` naming the relation and its scalar arguments
    (their product left the double range)."""
    values = result if not isinstance(result, PullOff) else np.array([result.radius, result.depth, result.force])
    if not np.all(np.isfinite(values)):
        shown_arguments = ", ".join(f"{key}={shown(value)}" for key, value in arguments.items())
        raise ValueError(f"{name}({shown_arguments}) is not finite (a product left the double range); allowed: "
                         "arguments whose result is a finite double")
    return result


def _layer(layer) -> Layer:
    if not isinstance(layer, Layer):
        raise TypeError(f"layer={shown(layer)} ({type(layer).__name__}) is not allowed; allowed: a Layer")
    return layer


#: What each argument of the generalized MDR's relations must be (name -> what is allowed, the test on its values).
_ARGUMENTS = {
    "a": ("finite numbers >= 0 (m)", lambda value: value >= 0.0),
    "x": ("finite numbers (m)", None),
    "r": ("finite numbers >= 0 (m)", lambda value: value >= 0.0),
    "d": ("finite numbers (m)", None),
}
#: The scalar arguments of the relations: name -> what is allowed, the test.
_SCALARS = {
    "E_star": ("a finite number > 0 (Pa)", lambda value: value > 0.0),
    "dgamma": ("a finite number >= 0 (J/m²)", lambda value: value >= 0.0),
}


def _relation(function):
    """Check a relation's arguments by their names (:data:`_ARGUMENTS`, :data:`_SCALARS`, ``nu``, ``layer``, a
    callable ``profile_slope``) before it runs, and its result after: a value that is not finite (a product beyond the
    double range, a slope of ``nan``) is a one-line ``ValueError`` naming the relation, never ``nan`` or ``inf``."""
    import inspect

    signature = inspect.signature(function)

    @functools.wraps(function)
    def checked(*args, **kwargs):
        bound = signature.bind(*args, **kwargs)
        bound.apply_defaults()
        given = bound.arguments
        for name, (allowed, valid) in _ARGUMENTS.items():
            if name in given:
                _reals(name, given[name], allowed, valid)
        for name, (allowed, valid) in _SCALARS.items():
            if name in given:
                check_real(name, given[name], allowed, valid)
        if "nu" in given:
            _nu(given["nu"])
        if "layer" in given:
            _layer(given["layer"])
        if "profile_slope" in given and not callable(given["profile_slope"]):
            raise TypeError(f"profile_slope={shown(given['profile_slope'])} is not allowed; allowed: a function of "
                            "an array of radii (m), f'(r)")
        arrays = [np.shape(given[name]) for name in _ARGUMENTS if name in given]
        try:
            np.broadcast_shapes(*arrays)
        except ValueError:
            raise ValueError(f"the arrays of {function.__name__} have the shapes {arrays}, which do not broadcast; "
                             "allowed: arrays of one shape (or numbers)") from None
        scalars = {name: value for name, value in given.items() if np.ndim(value) == 0 and name != "layer"
                   and not callable(value)}
        try:
            with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
                result = function(*args, **kwargs)
        except (ZeroDivisionError, OverflowError):  # (a scale that underflows to 0 or overflows on the way)
            result = math.nan
        return _finite_result(function.__name__, result, **scalars, layer=given.get("layer"))

    return checked


def _one_minus_compliance(u: np.ndarray, nu: float, base: LayerBase) -> np.ndarray:
    """``1 − C(u)`` without cancellation (numerator and denominator scaled by ``e^{-2u}``); 1 at ``u = 0``, 0 beyond
    :data:`_U_ZERO` (where ``e^{-2u}`` underflows: the polynomial factors would overflow to ``inf · 0``)."""
    u = np.where(u > _U_ZERO, _U_ZERO, u)
    e2 = np.exp(-2.0 * u)
    e4 = e2 * e2
    if base is LayerBase.BONDED:
        kappa = 3.0 - 4.0 * nu
        return ((2.0 * kappa * e4 + (1.0 + kappa**2 + 4.0 * u + 4.0 * u**2) * e2)
                / (kappa * (1.0 + e4) + (1.0 + kappa**2 + 4.0 * u**2) * e2))
    numerator = 2.0 * (2.0 * u - np.expm1(-2.0 * u)) * e2
    denominator = -np.expm1(-4.0 * u) + 4.0 * u * e2
    safe = np.where(u == 0.0, 1.0, denominator)
    return np.where(u == 0.0, 1.0, numerator / safe)


def compliance_function(t, nu: float, base: LayerBase | str = LayerBase.BONDED) -> np.ndarray:
    r"""The layer's Hankel-space compliance ``C(ξh)`` relative to the half-space's.

    .. math:: \hat w(\xi) = \frac{2\, C(\xi h)}{E^* \xi}\, \hat p(\xi), \qquad C \to 1 \ (\xi h \to \infty)

    Bonded base: ``(2κ sinh 2t − 4t)/(2κ cosh 2t + 1 + κ² + 4t²)``, ``κ = 3 − 4ν``; frictionless base:
    ``(cosh 2t − 1)/(sinh 2t + 2t)`` (derived in :func:`mdr_events.theory.layer_symbolic.derive_layer_model`).

    Parameters
    ----------
    t : float or array_like
        ``ξ h ≥ 0``.
    nu : float
        Poisson's ratio, in ``[0, 0.5]`` (0.5 included).
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base.

    Returns
    -------
    numpy.ndarray
        ``C(t)``, evaluated as ``1 − (1 − C)`` from the cancellation-free ``1 − C``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]`` or ``base`` unknown.
    """
    t = _reals("t", t, "finite numbers >= 0 (ξh)", lambda value: value >= 0.0)
    return 1.0 - _one_minus_compliance(t, _nu(nu), _base(base))


def _direct_kernel(v: np.ndarray, nu: float, base: LayerBase) -> np.ndarray:
    """``k(v) = ∫₀^∞ (1 − C(u)) cos(uv) du`` by composite Gauss–Legendre quadrature (the reference)."""
    x, w = np.polynomial.legendre.leggauss(_U_NODES)
    starts = np.arange(0.0, _U_MAX, _U_PANEL)
    u = (starts[:, None] + (x[None, :] + 1.0) * _U_PANEL / 2.0).ravel()
    weighted = _one_minus_compliance(u, nu, base) * np.tile(w * _U_PANEL / 2.0, starts.size)
    flat = np.abs(np.asarray(v, dtype=float)).ravel()
    out = np.empty(flat.size)
    for start in range(0, flat.size, 512):
        out[start:start + 512] = np.cos(np.outer(flat[start:start + 512], u)) @ weighted
    return out.reshape(np.shape(v))


@dataclass(frozen=True)
class _ChebyshevKernel:
    """``k(v)`` as piecewise Chebyshev series on unit panels of ``|v|`` up to ``v_max``."""

    coefficients: np.ndarray
    v_max: float

    @classmethod
    def build(cls, nu: float, base: LayerBase, v_max: float) -> "_ChebyshevKernel":
        panels = int(math.ceil(v_max / _V_PANEL)) + 1
        x = np.cos(np.pi * (np.arange(_V_NODES) + 0.5) / _V_NODES)
        v = (np.arange(panels)[:, None] + (x[None, :] + 1.0) / 2.0) * _V_PANEL
        values = _direct_kernel(v, nu, base)
        vandermonde = np.polynomial.chebyshev.chebvander(x, _V_NODES - 1)
        coefficients = np.linalg.solve(vandermonde, values.T).T
        return cls(coefficients, panels * _V_PANEL)

    def __call__(self, v: np.ndarray) -> np.ndarray:
        v = np.abs(v)
        panel = np.minimum((v / _V_PANEL).astype(int), len(self.coefficients) - 1)
        local = 2.0 * (v / _V_PANEL - panel) - 1.0
        c = self.coefficients[panel]
        b1 = np.zeros(v.shape)
        b2 = np.zeros(v.shape)
        for j in range(_V_NODES - 1, 0, -1):
            b1, b2 = c[..., j] + 2.0 * local * b1 - b2, b1
        return c[..., 0] + local * b1 - b2


_KERNELS: dict[tuple[float, LayerBase], _ChebyshevKernel] = {}


def _kernel_for(nu: float, base: LayerBase, v_max: float) -> _ChebyshevKernel:
    """The interpolated kernel of ``(ν, base)`` reaching at least ``v_max`` (built once, widened when needed)."""
    known = _KERNELS.get((nu, base))
    if known is None or known.v_max < v_max:
        known = _ChebyshevKernel.build(nu, base, max(v_max, 2.0 * LAMBDA_MAX + 2.0))
        _KERNELS[nu, base] = known
    return known


def kernel(v, nu: float, base: LayerBase | str = LayerBase.BONDED) -> np.ndarray:
    r"""The kernel of the Fredholm equation (L1): ``k(v) = ∫₀^∞ [1 − C(u)] cos(uv) du``, in units of ``1/h``.

    .. math:: k(v) = \int_0^\infty [1 - C(u)]\cos(uv)\,\mathrm{d}u

    Parameters
    ----------
    v : float or array_like
        The argument (``(t ∓ s)/h``); even in ``v``.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base.

    Returns
    -------
    numpy.ndarray
        ``k(v)`` (from the Chebyshev interpolants, within 1e-14 of the quadrature).

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]`` or ``base`` unknown.
    """
    v = _reals("v", v, f"finite numbers with |v| <= {KERNEL_V_MAX:g} (the quadrature's range)",
               lambda value: np.abs(value) <= KERNEL_V_MAX)
    nu, base = _nu(nu), _base(base)
    return _kernel_for(nu, base, float(np.max(np.abs(v), initial=0.0)) + 1.0)(v)


def nystrom_nodes(lam: float) -> int:
    """The number of Gauss–Legendre nodes of the solve at ``λ = a/h``: ``40 + 6λ``, rounded up to a multiple of 16.

    Parameters
    ----------
    lam : float
        ``a/h ≥ 0``.

    Returns
    -------
    int
        The nodes :func:`solve_punch` uses by default.
    """
    return int(16 * math.ceil((BASE_NODES + NODES_PER_LAMBDA * lam) / 16))


def _continuation(tau: np.ndarray, lam: float, kern: _ChebyshevKernel | None, sigma: np.ndarray,
                  weights: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """``(λ/π) ∫₀¹ Θ(σ) [k(λ(τ − σ)) + k(λ(τ + σ))] dσ`` at any ``τ`` (Nyström's interpolation), one column per
    right-hand side."""
    tau = np.asarray(tau, dtype=float)
    if lam == 0.0:
        return np.zeros(tau.shape + theta.shape[1:])
    rows = (lam / np.pi) * weights * (kern(lam * (tau[..., None] - sigma)) + kern(lam * (tau[..., None] + sigma)))
    return rows @ theta


@dataclass(frozen=True)
class PunchSolution:
    r"""The Nyström solution of the punch equation (L1) at one ``λ = a/h``, with extra right-hand sides ``τⁿ``.

    Parameters
    ----------
    lam : float
        ``a/h``.
    nu : float
        Poisson's ratio.
    base : LayerBase
        The layer's base.
    sigma : numpy.ndarray
        The Gauss–Legendre nodes on ``[0, 1]``.
    weights : numpy.ndarray
        Their weights.
    theta : numpy.ndarray
        ``Θ`` at the nodes, one column per right-hand side: ``1`` first, then ``g∞(aτ)/g∞(a)`` of each profile
        (``τⁿ`` of :attr:`exponents`, or a general profile's).
    exponents : tuple of float
        The power laws' exponents of the columns after the first.
    kern : object
        The interpolated kernel (``None`` at ``λ = 0``).
    rhs_at_edge : tuple of float
        The right-hand sides at ``τ = 1`` (1 for ``τⁿ``).
    """

    lam: float
    nu: float
    base: LayerBase
    sigma: np.ndarray
    weights: np.ndarray
    theta: np.ndarray
    exponents: tuple[float, ...]
    kern: object
    rhs_at_edge: tuple[float, ...]

    def edge_values(self) -> np.ndarray:
        """``Θ(1)`` of every column (Nyström's interpolation at the edge).

        Returns
        -------
        numpy.ndarray
            One value per right-hand side.
        """
        rhs = np.array((1.0, *self.rhs_at_edge))
        return rhs + _continuation(np.array(1.0), self.lam, self.kern, self.sigma, self.weights, self.theta)

    @property
    def stiffness_factor(self) -> float:
        """``Φ = ∫₀¹ Θ = K(a)/(2E* a)`` (L2)."""
        return float(self.weights @ self.theta[:, 0])

    def _column(self, column) -> int:
        """``column`` if it names a profile's right-hand side (1 to the number of profiles), else a one-line error."""
        profiles = self.theta.shape[1] - 1
        if profiles == 0:
            raise ValueError(f"column={shown(column)} is not allowed: this solution has no profile's right-hand "
                             "side; allowed: a solution with exponents (solve_punch(..., exponents=(2.0,)))")
        column = check_count("column", column, 1)
        if column > profiles:
            raise ValueError(f"column={column} is not allowed; allowed: 1 to {profiles} (the profiles' right-hand "
                             "sides)")
        return column

    @property
    def edge_factor(self) -> float:
        """``Θ(1)``: ``K'(a) = 2E* Θ(1)²`` (L3)."""
        return float(self.edge_values()[0])

    def profile_factor(self, column: int = 1) -> float:
        """``γ = g(a)/g∞(a) = Θ_g(1)/Θ(1)`` of a profile's column (L4).

        Parameters
        ----------
        column : int, default 1
            The right-hand side (1: the first profile).

        Returns
        -------
        float
            The generalized MDR profile over the half-space's at ``x = a``.
        """
        edges = self.edge_values()
        return float(edges[self._column(column)] / edges[0])

    def force_factor(self, column: int = 1) -> float:
        """``χ = F₀(a)/(2E* a g∞(a)) = γΦ − ∫₀¹ Θ_g`` of a profile's column: the non-adhesive force.

        Parameters
        ----------
        column : int, default 1
            The right-hand side (1: the first profile).

        Returns
        -------
        float
            ``n/(n + 1)`` for the power law on the half-space.
        """
        return self.profile_factor(column) * self.stiffness_factor - float(self.weights @ self.theta[:, column])

    def surface_displacement(self, rho) -> np.ndarray:
        r"""``φ(r; a)``: the surface's displacement over the punch's, at ``ρ = r/a`` (L5).

        .. math:: \varphi = \frac{2}{\pi}\Big[\arcsin\frac{1}{\rho}
                  - \int_{\arcsin(1/\rho)}^{\pi/2} G(\rho\sin\beta)\,\mathrm{d}\beta\Big]\quad(\rho > 1)

        Parameters
        ----------
        rho : float or array_like
            ``r/a ≥ 0``; 1 at ``ρ ≤ 1``.

        Returns
        -------
        numpy.ndarray
            ``φ``, shaped as ``rho``.
        """
        rho = _reals("rho", rho, "finite numbers >= 0 (r/a)", lambda value: value >= 0.0)
        points = _OUTER_NODES * np.ceil(np.maximum(rho - 1.0, 0.0) * max(self.lam, 1.0) / 2.0)
        DEFAULT_LIMITS.check(f"the surface displacement at r/a up to {float(np.max(rho, initial=0.0)):.6g} "
                             f"(a/h = {self.lam:g})", samples=float(np.max(points, initial=0.0)),
                             memory=SOLVE_BYTES_PER_PAIR * float(np.max(points, initial=0.0)) * self.sigma.size)
        out = np.ones(rho.shape)
        x, w = np.polynomial.legendre.leggauss(_OUTER_NODES)
        for index in np.ndindex(rho.shape):
            value = float(rho[index])
            if value <= 1.0:
                continue
            start = math.asin(1.0 / value)
            panels = max(1, math.ceil((value - 1.0) * max(self.lam, 1.0) / 2.0))
            edges = np.linspace(start, math.pi / 2.0, panels + 1)
            half = np.diff(edges)[:, None] / 2.0
            beta = (edges[:-1, None] + half * (x + 1.0)).ravel()
            correction = _continuation(value * np.sin(beta), self.lam, self.kern, self.sigma, self.weights,
                                       self.theta[:, :1])[:, 0]
            out[index] = 2.0 / np.pi * (start - correction @ (half * w).ravel())
        return out


@functools.lru_cache(maxsize=64)
def _gauss_legendre(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights on ``[0, 1]`` (kept: NumPy's eigenvalue solve is the table's main cost)."""
    from scipy.special import roots_legendre

    x, w = roots_legendre(count)
    return (x + 1.0) / 2.0, w / 2.0


def _solve(lam: float, nu: float, base: LayerBase, rhs: Callable[[np.ndarray], np.ndarray],
           rhs_at_edge: tuple[float, ...], exponents: tuple[float, ...], nodes: int | None,
           limits: Limits | None = None) -> PunchSolution:
    """The Nyström solve of (L1) with the right-hand sides ``1`` and ``rhs(σ)`` (columns); ``λ`` up to
    :data:`LAMBDA_SOLVE_MAX` and the nodes' memory within ``limits`` (checked before anything is built)."""
    if not lam <= LAMBDA_SOLVE_MAX:
        raise ValueError(f"a/h={lam!r} is not allowed for a direct solve; allowed: 0 <= a/h <= {LAMBDA_SOLVE_MAX:g} "
                         "(where its nodes are converged; the thin-layer limits of theory.layer_symbolic beyond)")
    count = nystrom_nodes(lam) if nodes is None else nodes
    check_limits(limits).check(f"the layer's Nyström solve with {count} nodes (a/h = {lam:g})",
                               memory=SOLVE_BYTES_PER_PAIR * float(count) ** 2)
    sigma, weights = _gauss_legendre(count)
    right = np.column_stack([np.ones(count), rhs(sigma)])
    if lam == 0.0:
        return PunchSolution(0.0, nu, base, sigma, weights, right, exponents, None, rhs_at_edge)
    kern = _kernel_for(nu, base, 2.0 * lam + 2.0)
    matrix = np.eye(count) - (lam / np.pi) * weights * (kern(lam * (sigma[:, None] - sigma))
                                                       + kern(lam * (sigma[:, None] + sigma)))
    return PunchSolution(lam, nu, base, sigma, weights, np.linalg.solve(matrix, right), exponents, kern,
                         rhs_at_edge)


def solve_punch(lam: float, nu: float, base: LayerBase | str = LayerBase.BONDED, exponents=(2.0,),
                nodes: int | None = None, limits: Limits | None = None) -> PunchSolution:
    r"""Solve the layer's punch equation (L1) at ``λ = a/h`` directly (no table), with power-law right-hand sides.

    .. math:: \Theta(\tau) - \frac{\lambda}{\pi}\int_0^1 \Theta(\sigma)
              [k(\lambda(\tau-\sigma)) + k(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = \tau^n

    Parameters
    ----------
    lam : float
        ``a/h ≥ 0`` (0: the half-space, ``Θ = τⁿ``).
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base.
    exponents : sequence of float, default (2.0,)
        The exponents ``n > 0`` of the extra right-hand sides ``τⁿ`` (the half-space profile ``g∞ ∝ xⁿ`` of the
        power law ``c rⁿ``; 2 the paraboloid).
    nodes : int or None, default None
        Gauss–Legendre nodes (default :func:`nystrom_nodes`).
    limits : Limits or None, default None
        The memory the solve may take (:data:`SOLVE_BYTES_PER_PAIR` per pair of nodes; ``None``: the defaults).

    Returns
    -------
    PunchSolution
        ``Θ`` of the flat punch and of each profile, with their factors.

    Raises
    ------
    ValueError
        ``lam`` negative, not finite or beyond :data:`LAMBDA_SOLVE_MAX`, ``nu`` outside ``[0, 0.5]``, ``base``
        unknown, an exponent ≤ 0; the nodes' memory beyond ``limits``
        (``ResourceLimitError``).
    """
    lam = check_real("lam", lam, f"a finite number >= 0 (a/h), at most {LAMBDA_SOLVE_MAX:g}", lambda value: value >= 0.0)
    if isinstance(exponents, (str, bytes)) or not hasattr(exponents, "__iter__"):
        raise TypeError(f"exponents={shown(exponents)} ({type(exponents).__name__}) is not allowed; allowed: a "
                        "sequence of numbers > 0, e.g. (2.0,)")
    exps = tuple(check_real("exponents", n, "numbers > 0", lambda value: value > 0.0) for n in exponents)
    if nodes is not None:
        nodes = check_count("nodes", nodes, 2)
    return _solve(lam, _nu(nu), _base(base), lambda s: np.power.outer(s, np.array(exps, dtype=float)),
                  (1.0,) * len(exps), exps, nodes, limits)


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
    if os.environ.get("MDR_EVENTS_NO_CACHE"):
        return None
    root = os.environ.get("MDR_EVENTS_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "mdr_events")
    return Path(root) / f"layer-{_base(base).value}-nu{float(nu)!r}-n{float(exponent)!r}-{_SOURCE_DIGEST}.npz"


#: The tabulated columns, as logarithms: ``Φ``, ``Θ(1)``, ``γₙ``, ``χₙ``.
_COLUMNS = ("stiffness", "edge", "profile", "force")


def _table_grid() -> np.ndarray:
    """The table's nodes in ``s = ln(a/h)``: :data:`TABLE_STEP` apart (at most) from ``LAMBDA_MIN`` to ``LAMBDA_MAX``."""
    low, high = math.log(LAMBDA_MIN), math.log(LAMBDA_MAX)
    return np.linspace(low, high, int(math.ceil((high - low) / TABLE_STEP)) + 1)


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
    if path is not None and path.exists():
        try:
            with np.load(path, allow_pickle=False) as stored:
                columns = {name: stored[name] for name in ("s", "k0", *_COLUMNS)}
            if np.array_equal(columns["s"], _table_grid()):
                return columns
        except Exception:  # a damaged or foreign file is rebuilt
            pass
    columns = _build_table(nu, base, exponent)
    if path is not None:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".npz", dir=path.parent)
            with os.fdopen(handle, "wb") as stream:
                np.savez(stream, **columns)
            os.replace(temporary, path)
        except OSError:
            pass
    return columns


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
        lam = real_array("lam", lam, f"numbers in [0, {LAMBDA_MAX:g}] (a/h)")
        if not np.all((lam >= 0.0) & (lam <= LAMBDA_MAX)):
            bad = float(lam[~((lam >= 0.0) & (lam <= LAMBDA_MAX))].ravel()[0])
            raise ValueError(f"a/h={bad!r} is not allowed; allowed: 0 <= a/h <= {LAMBDA_MAX:g} (the table's range; "
                             "solve_punch solves up to LAMBDA_SOLVE_MAX)")
        return lam

    def _series(self, lam: np.ndarray) -> dict[str, np.ndarray]:
        phi = 1.0 / (1.0 - 2.0 * float(self.columns["k0"]) * lam / np.pi)
        n = self.exponent
        return {"stiffness": phi, "edge": phi, "profile": (1.0 + (phi - 1.0) / (n + 1.0)) / phi,
                "force": np.full(lam.shape, n / (n + 1.0))}

    def _value(self, name: str, lam, derivative: bool = False) -> np.ndarray:
        lam = self._lam(lam)
        small = lam < LAMBDA_MIN
        s = np.log(np.where(small, LAMBDA_MIN, lam))
        value = np.exp(self._splines[name](s))
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

    def edge_factor(self, lam) -> np.ndarray:
        """``Θ(1; λ)``: ``K'(a) = 2E* Θ(1)²`` (L3).

        Parameters
        ----------
        lam : float or array_like
            ``a/h`` in ``[0, LAMBDA_MAX]``.

        Returns
        -------
        numpy.ndarray
            ``Θ(1)`` (1 at ``λ = 0``).

        Raises
        ------
        ValueError
            ``λ`` outside the table.
        """
        return self._value("edge", lam)

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


# ----------------------------------------------------------------------------
# the generalized MDR on a layer
@dataclass(frozen=True)
class _HalfSpaceFactors:
    """The factors of the half-space (``λ = 0``), exactly: no table is built."""

    exponent: float

    def stiffness_factor(self, lam) -> np.ndarray:
        return np.ones(np.shape(lam))

    edge_factor = profile_factor = stiffness_factor

    def force_factor(self, lam) -> np.ndarray:
        return np.full(np.shape(lam), self.exponent / (self.exponent + 1.0))


def _factors(nu: float, layer: Layer, exponent: float = 2.0):
    if not isinstance(layer, Layer):
        raise TypeError(f"layer={layer!r} ({type(layer).__name__}) is not allowed; allowed: a Layer")
    if layer.is_half_space:
        _nu(nu)
        return _HalfSpaceFactors(exponent)
    return layer_table(nu, layer.base, exponent)


def _relative(x, layer: Layer) -> np.ndarray:
    """``|x|/h`` (0 for the half-space)."""
    x = np.abs(np.asarray(x, dtype=float))
    return np.zeros(x.shape) if layer.is_half_space else x / layer.thickness


def _power_law(profile) -> tuple[float, float]:
    """``(c, n)`` of a paraboloid (``1/(2R)``, 2) or a power law."""
    from mdr_events.contact.indenters import Paraboloid, PowerLaw

    if isinstance(profile, Paraboloid):
        return 1.0 / (2.0 * profile.R), 2.0
    if isinstance(profile, PowerLaw):
        return profile.c, profile.n
    raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed; allowed: a Paraboloid or a "
                    "PowerLaw (a general profile: equivalent_profile)")


def _abel_factor(n: float) -> float:
    """``κₙ = √π Γ(n/2 + 1)/Γ(n/2 + 1/2)``: the half-space's ``g∞ = κₙ c xⁿ`` (eq. (3))."""
    return math.exp(0.5 * math.log(math.pi) + math.lgamma(n / 2.0 + 1.0) - math.lgamma(n / 2.0 + 0.5))


@_relation
def punch_stiffness(a, E_star: float, nu: float, layer: Layer):
    r"""The normal stiffness ``K(a)`` of a rigid flat punch of radius ``a`` on the layer (L2).

    .. math:: K(a) = 2E^* a\,\Phi(a/h), \qquad \Phi \to 1 \ (h \to \infty)

    Parameters
    ----------
    a : float or array_like
        The punch's radius in m.
    E_star : float
        ``E* = E/(1 − ν²)`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer (``Layer()``: the half-space, ``K = 2E* a`` exactly).

    Returns
    -------
    numpy.ndarray
        ``K`` in N/m.

    Raises
    ------
    ValueError
        ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    a = np.asarray(a, dtype=float)
    return 2.0 * E_star * a * _factors(nu, layer).stiffness_factor(_relative(a, layer))


@_relation
def punch_stiffness_slope(a, E_star: float, nu: float, layer: Layer):
    r"""``K'(a) = 2E* Θ(1; a/h)²`` (L3): exact, from the punch's edge value and Griffith's balance.

    .. math:: K'(a) = 2E^*\,\Theta(1)^2

    Parameters
    ----------
    a : float or array_like
        The punch's radius in m.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``K'`` in N/m² (``2E*`` for the half-space).

    Raises
    ------
    ValueError
        ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    return 2.0 * spring_stiffness_density(a, E_star, nu, layer)


@_relation
def spring_stiffness_density(x, E_star: float, nu: float, layer: Layer):
    r"""The MDR springs' normal stiffness per width at ``x``: ``k(x) = K'(|x|)/2`` (``E*`` on the half-space, (5)).

    .. math:: k(x) = \tfrac12 K'(|x|) = E^*\,\Theta(1; |x|/h)^2

    Parameters
    ----------
    x : float or array_like
        The springs' coordinate in m.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``k`` in Pa.

    Raises
    ------
    ValueError
        ``|x|/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    edge = _factors(nu, layer).edge_factor(_relative(x, layer))
    return E_star * edge * edge


@_relation
def hess_elongation(a, dgamma: float, E_star: float, nu: float, layer: Layer):
    r"""Heß's rule on the layer: the boundary spring's largest elongation (generalised (8)).

    .. math:: \Delta l = \sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}}
              = \frac{1}{\Theta(1)}\sqrt{\frac{2\pi a\,\Delta\gamma}{E^*}} \qquad (8)

    (Griffith's balance ``½ K'(a) Δl² = 2π a Δγ``, :mod:`mdr_events.theory.layer_symbolic`).

    Parameters
    ----------
    a : float or array_like
        The contact radius in m.
    dgamma : float
        The work of adhesion in J/m².
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``Δl`` in m.

    Raises
    ------
    ValueError
        ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    a = np.asarray(a, dtype=float)
    return np.sqrt(2.0 * np.pi * a * dgamma / E_star) / _factors(nu, layer).edge_factor(_relative(a, layer))


@_relation
def surface_displacement(r, a: float, nu: float, layer: Layer) -> np.ndarray:
    r"""``φ(r; a)``: the layer's surface displacement around a flat punch of radius ``a``, over the punch's (L5).

    .. math:: \varphi(r; a) = 1 \ (r \le a), \qquad
              \varphi = \frac{2}{\pi}\Big[\arcsin\frac{a}{r} - \int_a^r \frac{G(t/a)}{\sqrt{r^2-t^2}}\,\mathrm{d}t\Big]
              \ (r > a)

    (``(2/π) arcsin(a/r)`` on the half-space). A direct solve, no table.

    Parameters
    ----------
    r : float or array_like
        Radii in m.
    a : float
        The punch's radius in m, > 0.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``φ``, shaped as ``r``.

    Raises
    ------
    ValueError
        ``a`` not a finite number > 0, ``nu`` outside ``[0, 0.5]``.
    """
    a = check_real("a", a, "a finite number > 0 (m)", lambda value: value > 0.0)
    lam = 0.0 if layer.is_half_space else a / layer.thickness
    return solve_punch(lam, nu, layer.base, ()).surface_displacement(np.abs(np.asarray(r, dtype=float)) / a)


#: Gauss–Legendre nodes of the angular Abel transform ``g∞(x) = x ∫₀^{π/2} f'(x sin θ) dθ`` in
#: :func:`equivalent_profile`.
_ABEL_NODES = 64


@_relation
def equivalent_profile(x, profile_slope: Callable[[np.ndarray], np.ndarray], nu: float, layer: Layer) -> np.ndarray:
    r"""The generalized MDR profile ``g(x)`` of an axisymmetric profile ``f(r)`` on the layer (L4).

    ``g`` is defined by ``f(r) = ∫₀ʳ [1 − φ(r; ã)] g'(ã) dã`` (the superposition of flat punches); it is the depth
    at which the contact of radius ``|x|`` has no singular pressure at its edge, computed as

    .. math:: g(x) = \frac{\Theta_g(1)}{\Theta(1)}, \qquad
              \Theta_g - \lambda A_\lambda \Theta_g = g_\infty(|x|\tau), \qquad
              g_\infty(x) = |x|\int_0^{|x|}\frac{f'(r)}{\sqrt{x^2 - r^2}}\,\mathrm{d}r \quad (3)

    (``g = g∞``, the Abel transform (3), on the half-space). One direct solve per ``x``; a power law's is tabulated
    (:func:`power_law_profile`).

    Parameters
    ----------
    x : float or array_like
        The springs' coordinates in m.
    profile_slope : callable
        ``f'(r)`` for an array of radii in m (vectorised), finite on ``[0, max |x|]``.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``g(x)`` in m, shaped as ``x``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``.
    """
    x = np.abs(np.asarray(x, dtype=float))
    nodes, weights = np.polynomial.legendre.leggauss(_ABEL_NODES)
    angles, weights = np.pi / 4.0 * (nodes + 1.0), np.pi / 4.0 * weights

    def abel(radius: np.ndarray) -> np.ndarray:
        return radius * (np.asarray(profile_slope(np.multiply.outer(radius, np.sin(angles))), dtype=float)
                         @ weights)

    out = np.empty(x.shape)
    for index in np.ndindex(x.shape):
        radius = float(x[index])
        lam = 0.0 if layer.is_half_space else radius / layer.thickness
        edge = float(abel(np.array(radius)))
        solution = _solve(lam, _nu(nu), layer.base, lambda s: abel(radius * s)[:, None], (edge,), (), None)
        out[index] = solution.profile_factor() if radius > 0.0 else 0.0
    return out


@_relation
def power_law_profile(x, profile, nu: float, layer: Layer) -> np.ndarray:
    r"""The generalized MDR profile of a paraboloid or power law ``f = c rⁿ`` on the layer (tabulated).

    .. math:: g(x) = \kappa_n c |x|^n \gamma_n(|x|/h), \qquad
              \kappa_n = \frac{\sqrt\pi\,\Gamma(n/2 + 1)}{\Gamma(n/2 + 1/2)} \quad (3), (4)

    (``γₙ = 1`` on the half-space: ``g = x²/R`` for the paraboloid, (4); ``γ₂ → 1/2`` on a thin compressible bonded
    layer, ``g = f``; ``→ 1/4`` on a thin incompressible one).

    Parameters
    ----------
    x : float or array_like
        The springs' coordinates in m.
    profile : Paraboloid or PowerLaw
        The indenter.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``g(x)`` in m.

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``|x|/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    c, n = _power_law(profile)
    x = np.abs(np.asarray(x, dtype=float))
    return _abel_factor(n) * c * x**n * _factors(nu, layer, n).profile_factor(_relative(x, layer))


@_relation
def power_law_profile_slope(x, profile, nu: float, layer: Layer) -> np.ndarray:
    r"""``g'(x)`` of :func:`power_law_profile` for ``x ≥ 0`` (odd in ``x``).

    .. math:: g'(x) = \kappa_n c\,[n x^{n-1}\gamma_n(\lambda) + x^n \gamma_n'(\lambda)/h]

    Parameters
    ----------
    x : float or array_like
        The springs' coordinates in m.
    profile : Paraboloid or PowerLaw
        The indenter.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``g'(x)`` (``γₙ'`` from the spline's derivative: about 1e-6 relative).

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``|x|/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    c, n = _power_law(profile)
    x = np.asarray(x, dtype=float)
    size = np.abs(x)
    factors = _factors(nu, layer, n)
    lam = _relative(size, layer)
    slope = n * size ** (n - 1.0) * factors.profile_factor(lam)
    if not layer.is_half_space:
        slope = slope + size**n * factors.profile_factor(lam, derivative=True) / layer.thickness
    return np.sign(x) * _abel_factor(n) * c * slope


@_relation
def normal_force(d, a, profile, E_star: float, nu: float, layer: Layer) -> np.ndarray:
    r"""The normal force of the springs in contact at depth ``d`` and radius ``a`` on the layer (generalised (10)).

    .. math:: F_N = \int_{-a}^{a} k(x)\,(d - g(x))\,\mathrm{d}x = F_0(a) + K(a)\,(d - g(a)), \qquad
              F_0 = 2E^* a\, \kappa_n c a^n \chi_n(a/h) \quad (10)

    (``2E* ∫₀ᵃ (d − g) dx`` on the half-space; ``F₀`` the non-adhesive force at radius ``a``).

    Parameters
    ----------
    d : float or array_like
        The depth in m.
    a : float or array_like
        The contact radius in m.
    profile : Paraboloid or PowerLaw
        The indenter.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``F_N`` in N (positive: compressive).

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    c, n = _power_law(profile)
    a = np.asarray(a, dtype=float)
    factors = _factors(nu, layer, n)
    lam = _relative(a, layer)
    g_half = _abel_factor(n) * c * a**n
    at_edge = g_half * factors.profile_factor(lam)
    return 2.0 * E_star * a * (g_half * factors.force_factor(lam) + factors.stiffness_factor(lam) * (d - at_edge))


@_relation
def branch_depth(a, profile, E_star: float, nu: float, dgamma: float, layer: Layer) -> np.ndarray:
    r"""The depth of the adhesive contact of radius ``a`` on the layer (generalised (9)): ``d = g(a) − Δl(a)``.

    .. math:: d(a) = g(a) - \sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}} \qquad (9)

    Parameters
    ----------
    a : float or array_like
        The contact radius in m.
    profile : Paraboloid or PowerLaw
        The indenter.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    dgamma : float
        The work of adhesion in J/m² (0: the non-adhesive ``d = g(a)``).
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``d`` in m.

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    return power_law_profile(a, profile, nu, layer) - hess_elongation(a, dgamma, E_star, nu, layer)


@_relation
def branch_normal_force(a, profile, E_star: float, nu: float, dgamma: float, layer: Layer) -> np.ndarray:
    r"""The normal force on the adhesive (JKR-type) branch of radius ``a`` on the layer (generalised (10)).

    .. math:: F_N(a) = F_0(a) - K(a)\,\Delta l(a) \qquad (10)

    Parameters
    ----------
    a : float or array_like
        The contact radius in m.
    profile : Paraboloid or PowerLaw
        The indenter.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    dgamma : float
        The work of adhesion in J/m².
    layer : Layer
        The layer.

    Returns
    -------
    numpy.ndarray
        ``F_N`` in N.

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    depth = branch_depth(a, profile, E_star, nu, dgamma, layer)
    return normal_force(depth, a, profile, E_star, nu, layer)


@dataclass(frozen=True)
class PullOff:
    """The pull-off under force control: the minimum of the branch force (:func:`pull_off`).

    Parameters
    ----------
    radius : float
        The contact radius at pull-off in m.
    depth : float
        The depth there in m.
    force : float
        The pull-off force in N (negative: tensile).
    relative_radius : float
        ``a/h`` at pull-off (0 on the half-space).
    """

    radius: float
    depth: float
    force: float
    relative_radius: float


#: Points of the scan of the branch force for its minimum, over ``a₀ · 10^[-3, 3]`` (``a₀`` the half-space's
#: pull-off radius), before Brent's refinement.
_SCAN_POINTS = 241


@_relation
def pull_off(profile, E_star: float, nu: float, dgamma: float, layer: Layer) -> PullOff:
    r"""The pull-off under force control on the layer: the minimum of :func:`branch_normal_force` over ``a``.

    .. math:: F_\mathrm{po} = \min_a\,[F_0(a) - K(a)\,\Delta l(a)] \qquad (10)

    (``−(3/2) π Δγ R`` for the paraboloid on the half-space). The branch is scanned on a logarithmic grid around the
    half-space's pull-off radius ``a₀`` (``a^(2n−1) = 9Δγ/(2E* n² κₙ² c²)``) and its minimum refined by Brent's
    method in ``ln a``.

    Parameters
    ----------
    profile : Paraboloid or PowerLaw
        The indenter.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    dgamma : float
        The work of adhesion in J/m², > 0.
    layer : Layer
        The layer.

    Returns
    -------
    PullOff
        Radius, depth, force and ``a/h`` at pull-off.

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``dgamma`` not > 0, or the minimum beyond the table (``a/h > LAMBDA_MAX``).
    """
    from scipy.optimize import minimize_scalar

    dgamma = check_real("dgamma", dgamma, "a finite number > 0 (J/m²)", lambda value: value > 0.0)
    c, n = _power_law(profile)
    a0 = (9.0 * dgamma / (2.0 * E_star * n**2 * _abel_factor(n) ** 2 * c**2)) ** (1.0 / (2.0 * n - 1.0))
    logs = np.linspace(math.log(a0) - 3.0 * math.log(10.0), math.log(a0) + 3.0 * math.log(10.0), _SCAN_POINTS)
    if not layer.is_half_space:
        logs = logs[logs <= math.log(LAMBDA_MAX * layer.thickness)]

    def force(log_radius):
        return branch_normal_force(np.exp(log_radius), profile, E_star, nu, dgamma, layer)

    forces = force(logs)
    best = int(np.argmin(forces))
    if best in (0, len(logs) - 1):
        raise ValueError(f"the pull-off radius lies beyond a/h = {LAMBDA_MAX:g} or outside a0·10^±3 (a0 = {a0:.6g} m "
                         f"on the half-space); allowed: a layer with h > {a0 / LAMBDA_MAX:.3g} m or so")
    found = minimize_scalar(lambda value: float(force(value)), bracket=(logs[best - 1], logs[best], logs[best + 1]),
                            method="brent", options={"xtol": 1e-12})
    radius = float(np.exp(found.x))
    return PullOff(radius, float(branch_depth(radius, profile, E_star, nu, dgamma, layer)), float(found.fun),
                   float(_relative(radius, layer)))
