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
make ``K'(a) = 2E* Θ(1)²`` (L3), so that ``d(λΦ)/dλ = Θ(1)²`` (checked by the tests). A profile with the
half-space MDR profile ``g∞(x)`` (the Abel transform (3)) has the right-hand side ``(d − g∞(aτ))·π/(E* … )``: its
non-adhesive depth is the generalized MDR profile ``g(a) = Θ_g(1)/Θ(1)`` (L4), ``Θ_g`` the solution with the
right-hand side ``g∞(aτ)`` (no singular pressure at the edge). The surface outside the punch is
``φ(r; a) = (2/π)[arcsin(a/r) − ∫_a^r G(t/a)/sqrt(r² − t²) dt]`` with ``G = Θ − 1`` continued by (L1) (L5).

Numerics: Gauss–Legendre (Nyström) on ``[0, 1]`` with ``N = 40 + 6λ`` nodes (rounded up to 16; spectral: the kernel
is analytic in ``|Im v| < 2``); ``k`` from a Gauss–Legendre quadrature of ``1 − C`` (evaluated without
cancellation), kept as piecewise Chebyshev interpolants on ``v`` (20 points per unit). The solve converges to
round-off (1e-12 relative at ``λ = 20``) and the tables are interpolated to better than 1e-8.

The generalized MDR (Popov, Heß & Willert, Machines 11(4):474, 2023, and Argatov, Li, Popov's works it cites)
---------------------------------------------------------------------------------------------------------------
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
from mdr_events.validation import check_real

__all__ = ["LAMBDA_MAX", "LAMBDA_MIN", "compliance_function", "kernel", "nystrom_nodes", "PunchSolution",
           "solve_punch", "LayerTable", "layer_table", "table_cache_path", "punch_stiffness", "punch_stiffness_slope",
           "spring_stiffness_density", "hess_elongation", "surface_displacement", "equivalent_profile",
           "power_law_profile", "power_law_profile_slope", "normal_force", "branch_depth", "branch_normal_force",
           "pull_off", "PullOff"]

#: The largest ``a/h`` of a table (the thin side); direct solves (:func:`solve_punch`) take any ``λ``.
LAMBDA_MAX = 64.0
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
#: Nodes of the quadrature of the outer surface integral (L5) in the angle ``β``.
_OUTER_NODES = 64

#: Hash of this module's source: the key of the tables on disk (a change of the code never reads an old table).
_SOURCE_DIGEST = hashlib.sha256(Path(__file__).read_bytes() + np.__version__.encode()).hexdigest()[:16]


def _base(base: LayerBase | str) -> LayerBase:
    return base if isinstance(base, LayerBase) else Layer(1.0, base).base


def _nu(nu: float) -> float:
    return check_real("nu", nu, "a finite number in [0, 0.5]", lambda value: 0.0 <= value <= 0.5)


def _one_minus_compliance(u: np.ndarray, nu: float, base: LayerBase) -> np.ndarray:
    """``1 − C(u)`` without cancellation (numerator and denominator scaled by ``e^{-2u}``); 1 at ``u = 0``."""
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
    return 1.0 - _one_minus_compliance(np.asarray(t, dtype=float), _nu(nu), _base(base))


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
    v = np.asarray(v, dtype=float)
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
        return float(edges[column] / edges[0])

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
        rho = np.asarray(rho, dtype=float)
        out = np.ones(rho.shape)
        x, w = np.polynomial.legendre.leggauss(_OUTER_NODES)
        for index in zip(*np.nonzero(rho > 1.0)):
            value = rho[index]
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
           rhs_at_edge: tuple[float, ...], exponents: tuple[float, ...], nodes: int | None) -> PunchSolution:
    """The Nyström solve of (L1) with the right-hand sides ``1`` and ``rhs(σ)`` (columns)."""
    count = nystrom_nodes(lam) if nodes is None else nodes
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
                nodes: int | None = None) -> PunchSolution:
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

    Returns
    -------
    PunchSolution
        ``Θ`` of the flat punch and of each profile, with their factors.

    Raises
    ------
    ValueError
        ``lam`` negative or not finite, ``nu`` outside ``[0, 0.5]``, ``base`` unknown, an exponent ≤ 0.
    """
    lam = check_real("lam", lam, "a finite number >= 0 (a/h)", lambda value: value >= 0.0)
    exps = tuple(check_real("exponents", n, "numbers > 0", lambda value: value > 0.0) for n in exponents)
    if nodes is not None and (isinstance(nodes, bool) or not isinstance(nodes, int) or nodes < 2):
        raise ValueError(f"nodes={nodes!r} is not allowed; allowed: an integer >= 2 or None")
    return _solve(lam, _nu(nu), _base(base), lambda s: np.column_stack([s**n for n in exps]).reshape(len(s), -1),
                  (1.0,) * len(exps), exps, nodes)


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
        lam = np.asarray(lam, dtype=float)
        if not np.all((lam >= 0.0) & (lam <= LAMBDA_MAX)):
            bad = lam[~((lam >= 0.0) & (lam <= LAMBDA_MAX))].ravel()[0]
            raise ValueError(f"a/h={bad!r} is not allowed; allowed: 0 <= a/h <= {LAMBDA_MAX:g} (the table's range; "
                             "solve_punch solves beyond it)")
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
