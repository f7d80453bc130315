"""The layer's compliance ``C(ξh)`` and the kernel ``k(v)`` of the punch equation (L1), interpolated.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from mdr_events.contact.layer import NU_RANGE, Layer, LayerBase
from mdr_events.validation import check_real

__all__ = ["LAMBDA_MAX", "KERNEL_V_MAX", "compliance_function", "kernel"]

#: The largest ``a/h`` of a table (the thin side); direct solves (:func:`solve_punch`) take any ``λ``.
LAMBDA_MAX = 64.0
#: The largest ``|v|`` of :func:`kernel`: its quadrature's range (1e6 took minutes, ``nan`` an IndexError).
KERNEL_V_MAX = 200.0
#: Beyond this ``u``, ``e^{-2u}`` is 0 in double precision and so is ``1 − C(u)``.
_U_ZERO = 800.0
#: The kernel's quadrature in ``u``: panels of this width with 20 nodes each up to :data:`_U_MAX`, where ``1 − C``
#: is below 1e-17 (it decays as ``u² e^{-2u}``); exact to 1e-15 for ``|v| ≤ 200``.
_U_PANEL, _U_NODES, _U_MAX = 0.1, 20, 24.0
#: The kernel's Chebyshev interpolants: unit panels in ``v`` with 20 points (error below 1e-14: ``k`` is analytic in
#: ``|Im v| < 2``).
_V_PANEL, _V_NODES = 1.0, 20


def _finite_reals(name: str, value, allowed: str, valid) -> np.ndarray:
    """:func:`mdr_events.theory.layer.checks.finite_reals` (imported when called: checks imports this module)."""
    from mdr_events.theory.layer.checks import finite_reals

    return finite_reals(name, value, allowed, valid)


def _kernel_argument(v) -> np.ndarray:
    """A kernel's argument ``v`` (the normal one's and the tangential ones'): finite, ``|v| <=`` :data:`KERNEL_V_MAX`."""
    return _finite_reals("v", v, f"finite numbers with |v| <= {KERNEL_V_MAX:g} (the quadrature's range)",
                         lambda value: np.abs(value) <= KERNEL_V_MAX)


def _base(base: LayerBase | str) -> LayerBase:
    return base if isinstance(base, LayerBase) else Layer(1.0, base).base


def _nu(nu: float) -> float:
    """``nu`` checked against a layer's range, :data:`~mdr_events.contact.layer.NU_RANGE` (the normal and tangential
    compliances')."""
    low, high = NU_RANGE
    return check_real("nu", nu, f"a finite number in [{low:g}, {high:g}]", lambda value: low <= value <= high)


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
    t = _finite_reals("t", t, "finite numbers >= 0 (ξh)", lambda value: value >= 0.0)
    return 1.0 - _one_minus_compliance(t, _nu(nu), _base(base))


def _cosine_transform(one_minus: Callable[[np.ndarray], np.ndarray], v) -> np.ndarray:
    """``∫₀^∞ one_minus(u) cos(uv) du`` by composite Gauss–Legendre quadrature on ``[0, _U_MAX]`` (``one_minus``: a
    compliance's ``1 − C``, normal or tangential, 0 beyond ``_U_MAX`` to double precision)."""
    x, w = np.polynomial.legendre.leggauss(_U_NODES)
    starts = np.arange(0.0, _U_MAX, _U_PANEL)
    u = (starts[:, None] + (x[None, :] + 1.0) * _U_PANEL / 2.0).ravel()
    weighted = one_minus(u) * np.tile(w * _U_PANEL / 2.0, starts.size)
    flat = np.abs(np.asarray(v, dtype=float)).ravel()
    out = np.empty(flat.size)
    for start in range(0, flat.size, 512):
        out[start:start + 512] = np.cos(np.outer(flat[start:start + 512], u)) @ weighted
    return out.reshape(np.shape(v))


def _direct_kernel(v: np.ndarray, nu: float, base: LayerBase) -> np.ndarray:
    """``k(v) = ∫₀^∞ (1 − C(u)) cos(uv) du`` by composite Gauss–Legendre quadrature (the reference)."""
    return _cosine_transform(lambda u: _one_minus_compliance(u, nu, base), v)


@dataclass(frozen=True)
class _ChebyshevKernel:
    """A kernel ``k(v)`` as piecewise Chebyshev series on unit panels of ``|v|`` up to ``v_max`` (the normal one's
    and the tangential ones')."""

    coefficients: np.ndarray
    v_max: float

    @classmethod
    def build(cls, direct: Callable[[np.ndarray], np.ndarray], v_max: float) -> "_ChebyshevKernel":
        """Interpolate ``direct`` (the kernel by quadrature) on panels up to ``v_max``."""
        panels = int(math.ceil(v_max / _V_PANEL)) + 1
        x = np.cos(np.pi * (np.arange(_V_NODES) + 0.5) / _V_NODES)
        v = (np.arange(panels)[:, None] + (x[None, :] + 1.0) / 2.0) * _V_PANEL
        values = direct(v)
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
        known = _ChebyshevKernel.build(lambda v: _direct_kernel(v, nu, base),
                                       max(v_max, 2.0 * LAMBDA_MAX + 2.0))
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
    v = _kernel_argument(v)
    nu, base = _nu(nu), _base(base)
    return _kernel_for(nu, base, float(np.max(np.abs(v), initial=0.0)) + 1.0)(v)

