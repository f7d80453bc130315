"""The layer's equivalent profile ``g(x)`` (L4): of any indenter by an Abel transform and a direct solve, and of a
paraboloid or a power law from the tables, with its slope.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there; the names are also those of
:mod:`mdr_events.theory.layer.relations`).
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.limits import Limits
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.compliance import _nu
from mdr_events.theory.layer.punch import _solve, check_solves
from mdr_events.theory.layer.relation_factors import _abel_factor, _factors, _power_law, _relative

__all__ = ["equivalent_profile", "power_law_profile", "power_law_profile_slope"]


#: Gauss–Legendre nodes of the angular Abel transform ``g∞(x) = x ∫₀^{π/2} f'(x sin θ) dθ`` in
#: :func:`equivalent_profile`.
_ABEL_NODES = 64


@checked_relation
def equivalent_profile(x, profile_slope: Callable[[np.ndarray], np.ndarray], nu: float, layer: Layer,
                       limits: Limits | None = None) -> np.ndarray:
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
    limits : Limits or None, default None
        The work the solves may take (:data:`~mdr_events.theory.layer.punch.SOLVE_STEPS_PER_PAIR` steps per pair of
        each solve's nodes; ``None``: the defaults), checked before the first.

    Returns
    -------
    numpy.ndarray
        ``g(x)`` in m, shaped as ``x``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``, an ``|x|/h`` beyond :data:`~mdr_events.theory.layer.LAMBDA_SOLVE_MAX`, the
        solves beyond ``limits`` (``ResourceLimitError``).
    """
    x = np.abs(np.asarray(x, dtype=float))
    check_solves(np.zeros(x.shape) if layer.is_half_space else x / layer.thickness, limits,
                 f"equivalent_profile at {x.size} radii")
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


@checked_relation
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


@checked_relation
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
