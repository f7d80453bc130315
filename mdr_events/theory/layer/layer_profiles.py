"""The layer's equivalent profile ``g(x)`` (L4) of a paraboloid or a power law from the tables, with its slope (of any
indenter, by an Abel transform and a direct solve: ``relations.equivalent_profile``).

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there; the names are also those of
:mod:`mdr_events.theory.layer.relations`).
"""

from __future__ import annotations

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.relation_factors import _abel_factor, _factors, _power_law, _relative

__all__ = ["power_law_profile", "power_law_profile_slope"]


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
