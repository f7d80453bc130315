r"""Tangential contact on an elastic layer bonded to a rigid base (issue 34, item 3): the layer's tangential punch
problem solved exactly (within the decoupled problem stated below), tabulated against ``a/h``, and what it makes of the
MDR's tangential springs and of the slip cap (13).

The tangential punch problem
----------------------------
A rigid circular punch of radius ``a`` sticks to the layer's top and is moved tangentially by ``u₀`` (along ``x``);
the top carries no normal traction (``σ_zz = 0`` everywhere: the tangential problem decoupled from the normal one, as
the MDR and Cattaneo–Mindlin treat it); the base is bonded. In Fourier space (wave number ``ξ``) the top's tangential
response to a tangential traction splits into a *longitudinal* part (along ``ξ``: the plane-strain P–SV problem with
``σ_zz = 0``) and a *transverse* part (across ``ξ``: anti-plane shear)

.. math:: \hat u_L = \frac{(1-\nu)\,C_L(\xi h)}{G\xi}\,\hat q_L, \qquad
          \hat u_T = \frac{C_T(\xi h)}{G\xi}\,\hat q_T,

.. math:: C_L(t) = \frac{2\kappa\sinh 2t + 4t}{2\kappa\cosh 2t + 1 + \kappa^2 + 4t^2}, \qquad C_T(t) = \tanh t,
          \qquad \kappa = 3 - 4\nu \quad (T1)

(:func:`tangential_compliance`; derived from the Papkovich–Neuber solution in
:mod:`mdr_events.theory.layer_tangential_symbolic`, which also recovers the normal compliance of
:func:`mdr_events.theory.layer.compliance_function` with ``−4t`` in place of ``+4t``). Both tend to 1 as ``t → ∞``:
the half-space's ``(1 − ν k̂k̂ᵀ)/(Gξ)``. The punch's traction is ``q_x + i q_y = Q₀(r) + Q₂(r) e^{2iθ}``; with the
representations ``Q̂₀(ξ) = ∫₀ᵃ φ₀(t) cos ξt dt`` (order-0 Hankel transform) and ``Q̂₂(ξ) = ∫₀ᵃ χ(t) cos ξt dt``
(order 2, with ``∫₀ᵃ χ = 0``: then ``Q₂`` vanishes outside the punch), the order-0 Abel operator turns
``U₀ = u₀`` and the order-2 one turns ``U₂ = 0`` (``r < a``) into equations on ``[0, a]``; in the combinations
``P = Θ₀ + X`` and ``Q = Θ₀ − X`` (``φ₀, χ = (4Gu₀/(π(2 − ν))) Θ₀, X``) they decouple into two equations of the
Lebedev–Ufliand type (the normal punch's (L1) of :mod:`mdr_events.theory.layer`), ``λ = a/h``:

.. math:: \Psi_m(\tau) - \frac{\lambda}{\pi}\int_0^1 \Psi_m(\sigma)\,[k_m(\lambda(\tau-\sigma))
          + k_m(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = 1, \qquad
          k_m(v) = \int_0^\infty [1 - C_m(u)]\cos(uv)\,\mathrm{d}u, \quad m = L, T \quad (T2)

(:func:`tangential_kernel`, :func:`solve_tangential_punch`), and the constraint ``∫X = 0`` fixes the constant of the
order-2 equation. The force ``F_x = 2π Q̂₀(0)`` gives the tangential stiffness

.. math:: K_t(a) = 2G^* a\,\Phi_t(\lambda), \qquad
          \frac{2-\nu}{\Phi_t} = \frac{1-\nu}{\Phi_L} + \frac{1}{\Phi_T}, \qquad \Phi_m = \int_0^1 \Psi_m
          \quad (T3)

(``G* = 4G/(2 − ν)``; ``Φ_L = Φ_T = 1``, ``K_t = 8Ga/(2 − ν)`` on the half-space). Each ``Φ_m`` obeys the edge
identity of the normal punch, ``d(λΦ_m)/dλ = Ψ_m(1)²``, so the slope is exact from the edge values:

.. math:: K_t'(a) = 2G^*\,\Sigma_t(\lambda), \qquad \Sigma_t = \frac{\Phi_t^2}{2-\nu}
          \Big[(1-\nu)\frac{\Psi_L(1)^2}{\Phi_L^2} + \frac{\Psi_T(1)^2}{\Phi_T^2}\Big] \quad (T4)

The thin layer is a Winkler foundation in shear (``û = (h/G) q̂``): ``K_t → π a² G/h``, approached at first order in
``h/a`` (an edge boundary layer of width ``h``).

A frictionless base has no tangential stiffness at the scale of the layer: ``C_T = coth t`` and
``(1 − ν)C_L = (1 − ν)(cosh 2t + 1)/(sinh 2t + 2t)`` grow as ``1/t`` for ``t → 0`` (the layer slides on its base as a
plate in plane stress), so the displacement of a punch under a net force diverges as ``∫ dξ/ξ``: logarithmically in
the layer's lateral extent ``L`` (``u₀ ∝ F_x ln(L/a)/(G h)``); ``K_t = 0`` for an unbounded layer. The
functions below refuse such a layer, naming it (:func:`check_bonded`).

What the decoupling neglects
----------------------------
The exact problem of a sticking punch couples the two: a shear traction moves the top normally and a pressure moves
it tangentially, by the off-diagonal compliance ``C_zx`` (:func:`coupling_ratio`: ``m = |C_zx|/sqrt(C_zz C_xx)``,
``(1 − 2ν)/(2(1 − ν))`` on the half-space, 0 at ``ν = 0.5``; on a bonded layer non-zero even at ``ν = 0.5``, rising
to ``√3/2`` in the thin incompressible limit ``t → 0``). Minimising the complementary energy over the pressure as well
bounds the effect on the tangential stiffness: ``K_t ≤ K_t,coupled ≤ K_t/(1 − m_max²)``
(:func:`coupling_bound`).

The generalized MDR's tangential springs and caps
--------------------------------------------------
A flat punch moved by ``u₀`` is ``K_t(a) u₀ = ∫₋ₐᵃ k_t(x) u₀ dx``, so the springs' tangential stiffness per width is
``k_t(x) = K_t'(|x|)/2 = G* Σ_t(|x|/h)`` (:func:`tangential_spring_stiffness_density`; ``G*`` on the half-space).
By the superposition of incremental sticking punches this is exact for a sticking contact with any history of the
radius and of ``u`` (within the decoupled problem), as on the half-space. The cap (12)–(13), "every spring in contact
shifted by the same ``ū`` when the contact slides stationarily, the mean shear stress then ``τ0``", becomes
``ū(a) = π a² τ0 / K_t(a)`` (:func:`sliding_cap`); Coulomb's cap becomes ``μ (k(x)/k_t(x)) (d − g(x))``
(:func:`coulomb_cap`). Both give exactly the fully sliding forces ``π a² τ0`` and ``μ F_N``; which springs slide
first (partial slip) is an approximation on a layer (the normal and tangential punches' tractions no longer share one
radial profile, and the tangential one is anisotropic at the edge: :attr:`TangentialPunchSolution.edge_anisotropy`).

Numerics: the same as the normal punch's (Gauss–Legendre Nyström with :func:`mdr_events.theory.layer.nystrom_nodes`,
spectral; the kernels from a Gauss–Legendre quadrature of ``1 − C_m`` evaluated without cancellation, kept as
piecewise Chebyshev interpolants), tables of ``Φ_L, Φ_T, Ψ_L(1), Ψ_T(1)`` against ``ln λ`` (quintic splines of the
logarithms, within 1e-8 of direct solves), cached on disk (:func:`tangential_table_cache_path`).
"""

from __future__ import annotations

import functools
import hashlib
import math
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.theory.layer import nystrom_nodes, spring_stiffness_density
from mdr_events.validation import check_real

__all__ = ["MODES", "LAMBDA_MAX", "LAMBDA_MIN", "TABLE_STEP", "check_bonded", "tangential_compliance",
           "coupling_ratio", "coupling_bound", "tangential_kernel", "TangentialPunchSolution", "solve_tangential_punch",
           "TangentialTable", "tangential_table", "tangential_table_cache_path", "tangential_punch_stiffness",
           "tangential_punch_stiffness_slope", "tangential_spring_stiffness_density", "sliding_cap", "coulomb_cap"]

#: The two parts of the top's tangential response: ``"longitudinal"`` (P–SV, ``C_L``) and ``"transverse"`` (anti-plane,
#: ``C_T``).
MODES = ("longitudinal", "transverse")
#: The largest ``a/h`` of a table (direct solves take any ``λ``).
LAMBDA_MAX = 64.0
#: The smallest ``a/h`` of a table: below it the half-space side's series ``Φ_m = Ψ_m(1) = 1/(1 − 2k_m(0)λ/π)``
#: (error ``O(λ³) < 1e-11``).
LAMBDA_MIN = 1e-4
#: Spacing of the table's nodes in ``ln(a/h)`` (quintic splines: interpolation error about 2e-9; tests check 1e-8).
TABLE_STEP = 0.1
#: The kernel's quadrature in ``u``: panels of this width, Gauss–Legendre nodes per panel, and the end, where
#: ``1 − C_m`` is below 1e-17 (``2e^{−2u}`` and ``≈ (4u² − 4u + 1 + κ²)e^{−2u}/κ``).
_U_PANEL, _U_NODES, _U_MAX = 0.1, 20, 24.0
#: The kernel's Chebyshev interpolants: unit panels in ``v``, 20 points each (``k_m`` is analytic in ``|Im v| < 2``).
_V_PANEL, _V_NODES = 1.0, 20
#: ``t`` beyond which :func:`coupling_ratio` takes its value at this ``t`` (equal to the limit to round-off).
_T_FAR = 30.0

_SOURCE_DIGEST = hashlib.sha256(Path(__file__).read_bytes() + np.__version__.encode()).hexdigest()[:16]


def _nu(nu: float) -> float:
    return check_real("nu", nu, "a finite number in [0, 0.5]", lambda value: 0.0 <= value <= 0.5)


def _mode(mode: str) -> str:
    if mode not in MODES:
        raise ValueError(f"mode={mode!r} is not allowed; allowed: one of {', '.join(map(repr, MODES))}")
    return mode


def _base(base: LayerBase | str) -> LayerBase:
    return base if isinstance(base, LayerBase) else Layer(1.0, base).base


def check_bonded(layer: Layer) -> Layer:
    """``layer`` if it has a tangential punch stiffness: the half-space or a layer bonded to its base.

    Parameters
    ----------
    layer : Layer
        The layer.

    Returns
    -------
    Layer
        The same layer.

    Raises
    ------
    TypeError
        ``layer`` not a :class:`~mdr_events.contact.layer.Layer`.
    ValueError
        A finite layer on a frictionless base: it slides on its base as a plate in plane stress, a punch's tangential
        displacement under a net force grows as ``ln(L/a)`` with the layer's lateral extent ``L``, ``K_t = 0``.
    """
    if not isinstance(layer, Layer):
        raise TypeError(f"layer={layer!r} ({type(layer).__name__}) is not allowed; allowed: a Layer")
    if not layer.is_half_space and layer.base is LayerBase.FRICTIONLESS:
        raise ValueError(f"Layer.base={layer.base.value!r} is not allowed for tangential contact (a layer free to "
                         "slide on its base has no tangential punch stiffness: K_t = 0, the displacement grows as "
                         "ln(L/a) with its lateral extent L); allowed: LayerBase.BONDED or the half-space")
    return layer


def _one_minus(u: np.ndarray, nu: float, mode: str) -> np.ndarray:
    """``1 − C_m(u)`` of the bonded layer without cancellation (scaled by ``e^{−2u}``); 1 at ``u = 0``."""
    e2 = np.exp(-2.0 * u)
    if mode == "transverse":
        return 2.0 * e2 / (1.0 + e2)
    kappa = 3.0 - 4.0 * nu
    e4 = e2 * e2
    return ((2.0 * kappa * e4 + (1.0 + kappa**2 - 4.0 * u + 4.0 * u**2) * e2)
            / (kappa * (1.0 + e4) + (1.0 + kappa**2 + 4.0 * u**2) * e2))


def tangential_compliance(t, nu: float, mode: str, base: LayerBase | str = LayerBase.BONDED) -> np.ndarray:
    r"""The layer's tangential compliance in Fourier space relative to the half-space's, ``C_L`` or ``C_T`` (T1).

    .. math:: \hat u_L = \frac{(1-\nu) C_L(\xi h)}{G\xi}\hat q_L, \quad \hat u_T = \frac{C_T(\xi h)}{G\xi}\hat q_T

    Bonded base: ``C_L = (2κ sinh 2t + 4t)/(2κ cosh 2t + 1 + κ² + 4t²)``, ``κ = 3 − 4ν``, ``C_T = tanh t``;
    frictionless base: ``C_L = (cosh 2t + 1)/(sinh 2t + 2t)``, ``C_T = coth t`` (both ``∝ 1/t`` as ``t → 0``: no
    stiffness at the layer's scale). Derived in :mod:`mdr_events.theory.layer_tangential_symbolic`.

    Parameters
    ----------
    t : float or array_like
        ``ξ h ≥ 0`` (``> 0`` for a frictionless base).
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    mode : str
        ``"longitudinal"`` or ``"transverse"``.
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base.

    Returns
    -------
    numpy.ndarray
        ``C_m(t)`` (1 as ``t → ∞``).

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``, ``mode`` or ``base`` unknown.
    """
    t = np.asarray(t, dtype=float)
    nu, mode, base = _nu(nu), _mode(mode), _base(base)
    if base is LayerBase.BONDED:
        return 1.0 - _one_minus(t, nu, mode)
    with np.errstate(divide="ignore"):
        if mode == "transverse":
            return 1.0 / np.tanh(t)
        e2 = np.exp(-2.0 * t)
        return (1.0 + e2) ** 2 / (-np.expm1(-4.0 * t) + 4.0 * t * e2)


def _sinhc_minus_one(x: np.ndarray) -> np.ndarray:
    """``sinh(x)/x − 1`` without cancellation (its series below 0.5)."""
    small = np.abs(x) < 0.5
    safe = np.where(small, 1.0, x)
    series = sum(x ** (2 * k) / math.factorial(2 * k + 1) for k in range(1, 9))
    return np.where(small, series, np.sinh(safe) / safe - 1.0)


def coupling_ratio(t, nu: float) -> np.ndarray:
    r"""The normal–tangential coupling of the bonded layer's top, ``m = |C_zx| / sqrt(C_zz C_xx)`` at ``ξh = t``.

    .. math:: m(t) = \frac{|t^2 - \kappa(1-2\nu)\sinh^2 t|}
              {(1-\nu)\sqrt{(\kappa\sinh 2t)^2 - 4t^2}}, \qquad m(\infty) = \frac{1-2\nu}{2(1-\nu)}

    (``C_zz``, ``C_xx`` the normal and longitudinal compliances, ``C_zx`` the normal displacement per shear traction,
    :mod:`mdr_events.theory.layer_tangential_symbolic`). 0 on the half-space at ``ν = 0.5``; on a bonded layer at
    ``ν = 0.5`` it is ``2t²/sqrt(sinh² 2t − 4t²)``, ``→ √3/2`` as ``t → 0``.

    Parameters
    ----------
    t : float or array_like
        ``ξ h ≥ 0``.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.

    Returns
    -------
    numpy.ndarray
        ``m(t)`` in ``[0, 1)``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``.
    """
    nu = _nu(nu)
    t = np.minimum(np.asarray(t, dtype=float), _T_FAR)
    kappa = 3.0 - 4.0 * nu
    excess = _sinhc_minus_one(2.0 * t)  # S − 1, S = sinh 2t/(2t)
    root = np.sqrt((kappa * excess + (kappa - 1.0)) * (kappa * (1.0 + excess) + 1.0))  # sqrt(κ²S² − 1)
    sinh_over_t = 1.0 + _sinhc_minus_one(t)
    numerator = np.abs(1.0 - kappa * (1.0 - 2.0 * nu) * sinh_over_t**2)  # (t² − κ(1−2ν) sinh² t)/t²
    with np.errstate(invalid="ignore", divide="ignore"):
        value = t * numerator / (2.0 * (1.0 - nu) * root)
    limit_zero = math.sqrt(3.0) / 2.0 if nu == 0.5 else 0.0
    return np.where(t == 0.0, limit_zero, value)


def coupling_bound(nu: float, points: int = 2001) -> float:
    r"""The largest coupling ``m_max = sup_t m(t)`` of :func:`coupling_ratio`, and so the bound of the decoupling.

    .. math:: K_t \le K_{t,\mathrm{coupled}} \le \frac{K_t}{1 - m_\max^2}

    (the complementary energy minimised over the shear traction alone and over shear and pressure: per Fourier
    mode the pressure lowers the longitudinal compliance by at most the factor ``1 − m²``). On the half-space
    ``m ≡ (1 − 2ν)/(2(1 − ν))``.

    Parameters
    ----------
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    points : int, default 2001
        Points of the scan of ``t`` in ``[0, 30]`` (refined by the golden section around the largest).

    Returns
    -------
    float
        ``m_max``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``.
    """
    nu = _nu(nu)
    grid = np.linspace(0.0, _T_FAR, int(points))
    values = coupling_ratio(grid, nu)
    best = int(np.argmax(values))
    low, high = grid[max(best - 1, 0)], grid[min(best + 1, grid.size - 1)]
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(80):
        left, right = high - ratio * (high - low), low + ratio * (high - low)
        if coupling_ratio(left, nu) >= coupling_ratio(right, nu):
            high = right
        else:
            low = left
    return float(max(values[best], coupling_ratio((low + high) / 2.0, nu), values[0], values[-1]))


def _direct_kernel(v: np.ndarray, nu: float, mode: str) -> np.ndarray:
    """``k_m(v)`` by composite Gauss–Legendre quadrature of ``∫₀^∞ (1 − C_m(u)) cos(uv) du`` (the reference)."""
    x, w = np.polynomial.legendre.leggauss(_U_NODES)
    starts = np.arange(0.0, _U_MAX, _U_PANEL)
    u = (starts[:, None] + (x[None, :] + 1.0) * _U_PANEL / 2.0).ravel()
    weighted = _one_minus(u, nu, mode) * np.tile(w * _U_PANEL / 2.0, starts.size)
    flat = np.abs(np.asarray(v, dtype=float)).ravel()
    out = np.empty(flat.size)
    for start in range(0, flat.size, 512):
        out[start:start + 512] = np.cos(np.outer(flat[start:start + 512], u)) @ weighted
    return out.reshape(np.shape(v))


@dataclass(frozen=True)
class _Chebyshev:
    """``k_m(v)`` as piecewise Chebyshev series on unit panels of ``|v|`` up to ``v_max``."""

    coefficients: np.ndarray
    v_max: float

    @classmethod
    def build(cls, nu: float, mode: str, v_max: float) -> "_Chebyshev":
        panels = int(math.ceil(v_max / _V_PANEL)) + 1
        x = np.cos(np.pi * (np.arange(_V_NODES) + 0.5) / _V_NODES)
        v = (np.arange(panels)[:, None] + (x[None, :] + 1.0) / 2.0) * _V_PANEL
        values = _direct_kernel(v, nu, mode)
        coefficients = np.linalg.solve(np.polynomial.chebyshev.chebvander(x, _V_NODES - 1), values.T).T
        return cls(coefficients, panels * _V_PANEL)

    def __call__(self, v: np.ndarray) -> np.ndarray:
        v = np.abs(v)
        panel = np.minimum((v / _V_PANEL).astype(int), len(self.coefficients) - 1)
        local = 2.0 * (v / _V_PANEL - panel) - 1.0
        c = self.coefficients[panel]
        b1, b2 = np.zeros(v.shape), np.zeros(v.shape)
        for j in range(_V_NODES - 1, 0, -1):
            b1, b2 = c[..., j] + 2.0 * local * b1 - b2, b1
        return c[..., 0] + local * b1 - b2


_KERNELS: dict[tuple[float, str], _Chebyshev] = {}


def _kernel_for(nu: float, mode: str, v_max: float) -> _Chebyshev:
    known = _KERNELS.get((nu, mode))
    if known is None or known.v_max < v_max:
        known = _Chebyshev.build(nu, mode, max(v_max, 2.0 * LAMBDA_MAX + 2.0))
        _KERNELS[nu, mode] = known
    return known


def tangential_kernel(v, nu: float, mode: str) -> np.ndarray:
    r"""The kernel of the tangential punch's equations (T2) on a bonded layer, in units of ``1/h``.

    .. math:: k_m(v) = \int_0^\infty [1 - C_m(u)]\cos(uv)\,\mathrm{d}u

    Parameters
    ----------
    v : float or array_like
        The argument (even in ``v``).
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    mode : str
        ``"longitudinal"`` or ``"transverse"``.

    Returns
    -------
    numpy.ndarray
        ``k_m(v)`` (Chebyshev interpolants, within 1e-14 of the quadrature).

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]`` or ``mode`` unknown.
    """
    v = np.asarray(v, dtype=float)
    nu, mode = _nu(nu), _mode(mode)
    return _kernel_for(nu, mode, float(np.max(np.abs(v), initial=0.0)) + 1.0)(v)


@functools.lru_cache(maxsize=64)
def _gauss_legendre(count: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(count)
    return (x + 1.0) / 2.0, w / 2.0


@dataclass(frozen=True)
class TangentialPunchSolution:
    r"""The Nyström solution of the tangential punch's equations (T2) at one ``λ = a/h`` on a bonded layer.

    Parameters
    ----------
    lam : float
        ``a/h``.
    nu : float
        Poisson's ratio.
    sigma : numpy.ndarray
        The Gauss–Legendre nodes on ``[0, 1]``.
    weights : numpy.ndarray
        Their weights.
    psi : numpy.ndarray
        ``Ψ_L`` and ``Ψ_T`` at the nodes (two columns).
    edges : numpy.ndarray
        ``Ψ_L(1)`` and ``Ψ_T(1)`` (Nyström's interpolation at the edge).
    """

    lam: float
    nu: float
    sigma: np.ndarray
    weights: np.ndarray
    psi: np.ndarray
    edges: np.ndarray

    @property
    def longitudinal_factor(self) -> float:
        """``Φ_L = ∫₀¹ Ψ_L`` (T3)."""
        return float(self.weights @ self.psi[:, 0])

    @property
    def transverse_factor(self) -> float:
        """``Φ_T = ∫₀¹ Ψ_T`` (T3)."""
        return float(self.weights @ self.psi[:, 1])

    @property
    def stiffness_factor(self) -> float:
        """``Φ_t = K_t/(2G* a)``: ``(2 − ν)/Φ_t = (1 − ν)/Φ_L + 1/Φ_T`` (T3)."""
        return _combine(self.nu, self.longitudinal_factor, self.transverse_factor)

    @property
    def slope_factor(self) -> float:
        """``Σ_t = K_t'(a)/(2G*)`` from the edge values (T4)."""
        return _slope(self.nu, self.longitudinal_factor, self.transverse_factor, *self.edges)

    @property
    def edge_anisotropy(self) -> float:
        """The punch's edge traction along its motion (``θ = 0``, radial) over across it (``θ = π/2``, hoop).

        With ``P = (2 − ν)Φ_L Ψ_T/D`` and ``Q = (2 − ν)Φ_T Ψ_L/D`` (``D = (1 − ν)Φ_T + Φ_L``) the traction along
        ``x`` at the edge is ``∝ Θ₀(1) − X(1) cos 2θ`` (leading asymptotics, ``J₂ ~ −J₀``): ``Q(1)`` at ``θ = 0``,
        ``P(1)`` at ``θ = π/2``, their ratio ``Φ_T Ψ_L(1)/(Φ_L Ψ_T(1))``. 1 on the half-space, where the traction is
        ``∝ 1/sqrt(a² − r²)`` along ``x``; a measure of how far the layer's tangential punch is from one radial
        profile, which the MDR's cap assumes.
        """
        edge_l, edge_t = self.edges
        return float(self.transverse_factor * edge_l / (self.longitudinal_factor * edge_t))


def _combine(nu, phi_l, phi_t):
    """``Φ_t`` of (T3)."""
    return (2.0 - nu) * phi_l * phi_t / ((1.0 - nu) * phi_t + phi_l)


def _slope(nu, phi_l, phi_t, edge_l, edge_t):
    """``Σ_t`` of (T4)."""
    phi = _combine(nu, phi_l, phi_t)
    return phi * phi * ((1.0 - nu) * (edge_l / phi_l) ** 2 + (edge_t / phi_t) ** 2) / (2.0 - nu)


def _continuation(tau, lam, kern, sigma, weights, psi) -> np.ndarray:
    rows = (lam / np.pi) * weights * (kern(lam * (tau[..., None] - sigma)) + kern(lam * (tau[..., None] + sigma)))
    return rows @ psi


def _solve(lam: float, nu: float, nodes: int) -> TangentialPunchSolution:
    sigma, weights = _gauss_legendre(nodes)
    if lam == 0.0:
        return TangentialPunchSolution(0.0, nu, sigma, weights, np.ones((nodes, 2)), np.ones(2))
    columns, edges = [], []
    for mode in MODES:
        kern = _kernel_for(nu, mode, 2.0 * lam + 2.0)
        matrix = np.eye(nodes) - (lam / np.pi) * weights * (kern(lam * (sigma[:, None] - sigma))
                                                           + kern(lam * (sigma[:, None] + sigma)))
        psi = np.linalg.solve(matrix, np.ones(nodes))
        columns.append(psi)
        edges.append(1.0 + float(_continuation(np.array(1.0), lam, kern, sigma, weights, psi)))
    return TangentialPunchSolution(lam, nu, sigma, weights, np.column_stack(columns), np.array(edges))


def solve_tangential_punch(lam: float, nu: float, base: LayerBase | str = LayerBase.BONDED,
                           nodes: int | None = None) -> TangentialPunchSolution:
    r"""Solve the tangential punch's equations (T2) at ``λ = a/h`` directly (no table).

    .. math:: \Psi_m(\tau) - \frac{\lambda}{\pi}\int_0^1 \Psi_m(\sigma)
              [k_m(\lambda(\tau-\sigma)) + k_m(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = 1 \quad (T2)

    Parameters
    ----------
    lam : float
        ``a/h ≥ 0`` (0: the half-space, ``Ψ_m = 1``).
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base: only ``BONDED`` has a tangential stiffness (:func:`check_bonded`).
    nodes : int or None, default None
        Gauss–Legendre nodes (default :func:`mdr_events.theory.layer.nystrom_nodes`).

    Returns
    -------
    TangentialPunchSolution
        ``Ψ_L``, ``Ψ_T`` and the factors ``Φ_t``, ``Σ_t``.

    Raises
    ------
    ValueError
        ``lam`` negative or not finite, ``nu`` outside ``[0, 0.5]``, a frictionless or unknown base, ``nodes`` < 2.
    """
    lam = check_real("lam", lam, "a finite number >= 0 (a/h)", lambda value: value >= 0.0)
    check_bonded(Layer(1.0, _base(base)))
    if nodes is not None and (isinstance(nodes, bool) or not isinstance(nodes, int) or nodes < 2):
        raise ValueError(f"nodes={nodes!r} is not allowed; allowed: an integer >= 2 or None")
    return _solve(lam, _nu(nu), nystrom_nodes(lam) if nodes is None else nodes)


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
    if os.environ.get("MDR_EVENTS_NO_CACHE"):
        return None
    root = os.environ.get("MDR_EVENTS_CACHE_DIR") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache"), "mdr_events")
    return Path(root) / f"layer-tangential-nu{float(nu)!r}-{_SOURCE_DIGEST}.npz"


#: The tabulated columns (logarithms): ``Φ_L``, ``Φ_T``, ``Ψ_L(1)``, ``Ψ_T(1)``.
_COLUMNS = ("phi_l", "phi_t", "edge_l", "edge_t")


def _table_grid() -> np.ndarray:
    low, high = math.log(LAMBDA_MIN), math.log(LAMBDA_MAX)
    return np.linspace(low, high, int(math.ceil((high - low) / TABLE_STEP)) + 1)


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
    if path is not None and path.exists():
        try:
            with np.load(path, allow_pickle=False) as stored:
                columns = {name: stored[name] for name in ("s", "k0", *_COLUMNS)}
            if np.array_equal(columns["s"], _table_grid()):
                return columns
        except Exception:  # a damaged or foreign file is rebuilt
            pass
    columns = _build_table(nu)
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

    def _values(self, lam) -> tuple[np.ndarray, ...]:
        lam = np.asarray(lam, dtype=float)
        inside = (lam >= 0.0) & (lam <= LAMBDA_MAX)
        if not np.all(inside):
            bad = float(lam[~inside].ravel()[0])
            raise ValueError(f"a/h={bad!r} is not allowed; allowed: 0 <= a/h <= {LAMBDA_MAX:g} (the table's range; "
                             "solve_tangential_punch solves beyond it)")
        small = lam < LAMBDA_MIN
        s = np.log(np.where(small, LAMBDA_MIN, lam))
        k_l, k_t = (float(value) for value in self.columns["k0"])
        series = {"phi_l": 1.0 / (1.0 - 2.0 * k_l * lam / np.pi), "phi_t": 1.0 / (1.0 - 2.0 * k_t * lam / np.pi)}
        series.update(edge_l=series["phi_l"], edge_t=series["phi_t"])
        return tuple(np.where(small, series[name], np.exp(self._splines[name](s))) for name in _COLUMNS)

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
        phi_l, phi_t, _, _ = self._values(lam)
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


class _HalfSpace:
    """The half-space's factors, exactly 1 (no table)."""

    @staticmethod
    def stiffness_factor(lam) -> np.ndarray:
        return np.ones(np.shape(lam))

    slope_factor = stiffness_factor


def _factors(nu: float, layer: Layer):
    check_bonded(layer)
    nu = _nu(nu)
    return _HalfSpace() if layer.is_half_space else tangential_table(nu)


def _relative(x, layer: Layer) -> np.ndarray:
    x = np.abs(np.asarray(x, dtype=float))
    return np.zeros(x.shape) if layer.is_half_space else x / layer.thickness


def tangential_punch_stiffness(a, G_star: float, nu: float, layer: Layer) -> np.ndarray:
    r"""The tangential stiffness of a sticking flat punch of radius ``a`` on the layer (T3).

    .. math:: K_t(a) = 2G^* a\,\Phi_t(a/h), \qquad G^* = \frac{4G}{2-\nu} \quad (6)

    (``2G* a`` on the half-space; ``→ π a² G/h`` on a thin layer).

    Parameters
    ----------
    a : float or array_like
        The punch's radius in m.
    G_star : float
        ``G*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer (half-space or bonded base).

    Returns
    -------
    numpy.ndarray
        ``K_t`` in N/m.

    Raises
    ------
    ValueError
        A frictionless base (:func:`check_bonded`), ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    a = np.asarray(a, dtype=float)
    return 2.0 * G_star * a * _factors(nu, layer).stiffness_factor(_relative(a, layer))


def tangential_punch_stiffness_slope(a, G_star: float, nu: float, layer: Layer) -> np.ndarray:
    r"""``K_t'(a) = 2G* Σ_t(a/h)`` (T4): exact from the edge values of (T2).

    .. math:: K_t'(a) = 2G^*\,\Sigma_t(a/h)

    Parameters
    ----------
    a : float or array_like
        The punch's radius in m.
    G_star : float
        ``G*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer (half-space or bonded base).

    Returns
    -------
    numpy.ndarray
        ``K_t'`` in N/m² (``2G*`` on the half-space).

    Raises
    ------
    ValueError
        A frictionless base, ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    return 2.0 * tangential_spring_stiffness_density(a, G_star, nu, layer)


def tangential_spring_stiffness_density(x, G_star: float, nu: float, layer: Layer) -> np.ndarray:
    r"""The MDR springs' tangential stiffness per width at ``x``: ``k_t(x) = K_t'(|x|)/2`` (``G*`` on the half-space).

    .. math:: k_t(x) = \tfrac12 K_t'(|x|) = G^*\,\Sigma_t(|x|/h) \quad (T4)

    Parameters
    ----------
    x : float or array_like
        The springs' coordinate in m.
    G_star : float
        ``G*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer (half-space or bonded base).

    Returns
    -------
    numpy.ndarray
        ``k_t`` in Pa.

    Raises
    ------
    ValueError
        A frictionless base, ``|x|/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    return G_star * _factors(nu, layer).slope_factor(_relative(x, layer))


def sliding_cap(a, tau0: float, G_star: float, nu: float, layer: Layer) -> np.ndarray:
    r"""The springs' critical shift under the law ``τ0`` on the layer: (12)–(13) with the layer's ``K_t``.

    .. math:: \bar u(a) = \frac{\pi a^2 \tau_0}{K_t(a)} = \frac{\pi a\,\tau_0}{2G^*\,\Phi_t(a/h)} \qquad (13)

    Every spring in contact shifted by ``ū`` carries ``F_x = ∫ k_t ū dx = K_t(a) ū = π a² τ0``: the mean shear stress
    of the fully sliding contact is ``τ0``, exactly, on any layer (``π a τ0/(2G*)`` on the half-space).

    Parameters
    ----------
    a : float or array_like
        The contact radius in m.
    tau0 : float
        The shear strength ``τ0`` in Pa, ≥ 0.
    G_star : float
        ``G*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer (half-space or bonded base).

    Returns
    -------
    numpy.ndarray
        ``ū`` in m.

    Raises
    ------
    ValueError
        ``tau0`` negative, a frictionless base, ``a/h`` beyond :data:`LAMBDA_MAX`, ``nu`` outside ``[0, 0.5]``.
    """
    tau0 = check_real("tau0", tau0, "a finite number >= 0 (Pa)", lambda value: value >= 0.0)
    a = np.asarray(a, dtype=float)
    return np.pi * a * tau0 / (2.0 * G_star * _factors(nu, layer).stiffness_factor(_relative(a, layer)))


def coulomb_cap(x, depth, profile_depth, mu: float, E_star: float, G_star: float, nu: float,
                layer: Layer) -> np.ndarray:
    r"""Coulomb's cap of the spring at ``x`` on the layer: its tangential force at most ``μ`` times its normal force.

    .. math:: \bar u(x) = \mu\,\frac{k(x)}{k_t(x)}\,(d - g(x)), \qquad k = \tfrac12 K'(|x|),\ k_t = \tfrac12 K_t'(|x|)

    (``μ (E*/G*)(d − g)`` on the half-space, the Coulomb part of the caps of ``theory.mindlin``).

    Parameters
    ----------
    x : float or array_like
        The springs' coordinates in m.
    depth : float or array_like
        The depth ``d`` in m.
    profile_depth : float or array_like
        The springs' profile ``g(x)`` in m (the layer's generalized MDR profile).
    mu : float
        The coefficient of friction, ≥ 0.
    E_star : float
        ``E*`` in Pa.
    G_star : float
        ``G*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    layer : Layer
        The layer (half-space or bonded base).

    Returns
    -------
    numpy.ndarray
        ``ū`` in m (negative where the spring is in tension: it cannot hold a shift).

    Raises
    ------
    ValueError
        ``mu`` negative, a frictionless base, ``|x|/h`` beyond the tables, ``nu`` outside ``[0, 0.5]``.
    """
    mu = check_real("mu", mu, "a finite number >= 0", lambda value: value >= 0.0)
    ratio = (spring_stiffness_density(x, E_star, nu, check_bonded(layer))
             / tangential_spring_stiffness_density(x, G_star, nu, layer))
    return mu * ratio * (np.asarray(depth, dtype=float) - np.asarray(profile_depth, dtype=float))
