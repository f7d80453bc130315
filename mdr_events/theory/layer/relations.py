"""The generalized MDR on a layer: ``K(a)``, ``k(x) = K'/2``, Heß's ``Δl``, ``φ``, the equivalent profile ``g``,
the normal force and the adhesive branch (L2)–(L5), from the tables or direct solves.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.checks import checked_relation
# (the relations' parts, one idea a module; their names kept here, where the package and the other modules import them)
from mdr_events.theory.layer.layer_profiles import equivalent_profile, power_law_profile, power_law_profile_slope
from mdr_events.theory.layer.relation_factors import _abel_factor, _factors, _power_law, _relative  # noqa: F401
from mdr_events.theory.layer.stiffness_relations import (hess_elongation, punch_stiffness, punch_stiffness_slope,
                                                         spring_stiffness_density, surface_displacement)

__all__ = ["punch_stiffness", "punch_stiffness_slope", "spring_stiffness_density", "hess_elongation",
           "surface_displacement", "equivalent_profile", "power_law_profile", "power_law_profile_slope",
           "normal_force", "branch_depth", "branch_normal_force"]


@checked_relation
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
    factors = _factors(nu, layer, n).force_factors(_relative(a, layer))
    return _force_of_factors(d, a, _abel_factor(n) * c, n, E_star, factors)


def _force_of_factors(d, a: np.ndarray, kc: float, n: float, E_star: float, factors: tuple) -> np.ndarray:
    r""":func:`normal_force` of its table's factors, unchecked (the continuum's samples: valid radii and depths).

    .. math:: F_N = 2E^* a \left(g_\infty \chi_n + \Phi\,(d - g_\infty \gamma_n)
ight), \qquad g_\infty = \kappa_n c a^n

    Parameters
    ----------
    d : float or numpy.ndarray
        The depth (m).
    a : numpy.ndarray
        The contact radius (m).
    kc : float
        ``κₙ c`` (the half-space's profile ``g∞ = κₙ c aⁿ``).
    n : float
        The power.
    E_star : float
        ``E*`` (Pa).
    factors : tuple of numpy.ndarray
        ``Φ``, ``γₙ``, ``χₙ`` at ``λ = a/h`` (the table's ``force_factors``).

    Returns
    -------
    numpy.ndarray
        ``F_N`` (N).
    """
    g_half = kc * a**n
    stiffness, profile_factor, force_factor = factors
    at_edge = g_half * profile_factor
    return 2.0 * E_star * a * (g_half * force_factor + stiffness * (d - at_edge))


@checked_relation
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


@checked_relation
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
