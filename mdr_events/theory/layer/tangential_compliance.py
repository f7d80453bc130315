r"""The tangential compliances of a layer's top, ``C_L`` and ``C_T`` (T1), and the kernels ``k_m`` of the
tangential punch's equations (T2), interpolated; what a layer must be to have a tangential stiffness.

Part of :mod:`mdr_events.theory.layer_tangential`, which documents the problem and re-exports the public names.
"""

from __future__ import annotations


import numpy as np

from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.theory.layer.compliance import _ChebyshevKernel, _cosine_transform, _finite_reals, _kernel_argument, _nu

__all__ = ["MODES", "LAMBDA_MAX", "check_bonded", "tangential_compliance", "tangential_kernel"]

#: The two parts of the top's tangential response: ``"longitudinal"`` (P–SV, ``C_L``) and ``"transverse"`` (anti-plane,
#: ``C_T``).
MODES = ("longitudinal", "transverse")
#: The largest ``a/h`` of a table (direct solves take any ``λ``).
LAMBDA_MAX = 64.0
#: (The kernels' quadrature and Chebyshev panels are the normal kernel's, :mod:`.compliance`: ``1 − C_m`` is below
#: 1e-17 at its end, ``2e^{−2u}`` and ``≈ (4u² − 4u + 1 + κ²)e^{−2u}/κ``.)


#: What ``t`` may be on a frictionless base.
_FRICTIONLESS_T = "finite numbers > 0 (ξh) on a frictionless base"


def _mode(mode: str) -> str:
    if not isinstance(mode, str) or mode not in MODES:
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
        ``nu`` outside ``[0, 0.5]``, ``mode`` or ``base`` unknown, ``t`` not finite, negative (or 0, or so small that
        the compliance overflows, on a frictionless base).
    TypeError
        ``t`` not real numbers.
    """
    nu, mode, base = _nu(nu), _mode(mode), _base(base)
    if base is LayerBase.BONDED:
        t = _finite_reals("t", t, "finite numbers >= 0 (ξh)", lambda value: value >= 0.0)
        return 1.0 - _one_minus(t, nu, mode)
    t = _finite_reals("t", t, _FRICTIONLESS_T, lambda value: value > 0.0)  # (C_m grows as 1/t: infinite at 0)
    with np.errstate(divide="ignore", over="ignore"):
        if mode == "transverse":
            value = 1.0 / np.tanh(t)
        else:
            e2 = np.exp(-2.0 * t)
            value = (1.0 + e2) ** 2 / (-np.expm1(-4.0 * t) + 4.0 * t * e2)
    if not np.all(np.isfinite(value)):  # (a t so small that 1/t overflows)
        bad = float(np.ravel(t)[np.argmin(np.isfinite(np.ravel(value)))])
        raise ValueError(f"t={bad!r} is not allowed: C_{mode[0].upper()} overflows there; allowed: {_FRICTIONLESS_T}, "
                         "whose compliance is a finite double")
    return value


def _direct_kernel(v: np.ndarray, nu: float, mode: str) -> np.ndarray:
    """``k_m(v)`` by composite Gauss–Legendre quadrature of ``∫₀^∞ (1 − C_m(u)) cos(uv) du`` (the reference)."""
    return _cosine_transform(lambda u: _one_minus(u, nu, mode), v)


_KERNELS: dict[tuple[float, str], _ChebyshevKernel] = {}


def _kernel_for(nu: float, mode: str, v_max: float) -> _ChebyshevKernel:
    known = _KERNELS.get((nu, mode))
    if known is None or known.v_max < v_max:
        known = _ChebyshevKernel.build(lambda v: _direct_kernel(v, nu, mode),
                                       max(v_max, 2.0 * LAMBDA_MAX + 2.0))
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
        ``nu`` outside ``[0, 0.5]``, ``mode`` unknown, ``v`` not finite or beyond
        :data:`~mdr_events.theory.layer.KERNEL_V_MAX` (the quadrature's range).
    TypeError
        ``v`` not real numbers.
    """
    v = _kernel_argument(v)
    nu, mode = _nu(nu), _mode(mode)
    return _kernel_for(nu, mode, float(np.max(np.abs(v), initial=0.0)) + 1.0)(v)
