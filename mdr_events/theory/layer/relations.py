"""The generalized MDR on a layer: ``K(a)``, ``k(x) = K'/2``, Heß's ``Δl``, ``φ``, the equivalent profile ``g``,
the normal force and the adhesive branch (L2)–(L5), from the tables or direct solves.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.limits import Limits
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.compliance import _nu
# (the relations' parts, one idea a module; their names kept here, where the package and the other modules import them)
from mdr_events.theory.layer.layer_profiles import power_law_profile, power_law_profile_slope
from mdr_events.theory.layer.punch import _solve, check_solves
from mdr_events.theory.layer.relation_factors import _abel_factor, _factors, _power_law, _relative  # noqa: F401
from mdr_events.theory.layer.stiffness_relations import (hess_elongation, punch_stiffness, punch_stiffness_slope,
                                                         spring_stiffness_density, surface_displacement)

__all__ = ["punch_stiffness", "punch_stiffness_slope", "spring_stiffness_density", "hess_elongation",
           "surface_displacement", "equivalent_profile", "power_law_profile", "power_law_profile_slope",
           "normal_force", "branch_depth", "branch_normal_force"]


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
