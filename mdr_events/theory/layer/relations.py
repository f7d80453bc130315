"""The generalized MDR on a layer: ``K(a)``, ``k(x) = K'/2``, Heß's ``Δl``, ``φ``, the equivalent profile ``g``,
the normal force and the adhesive branch (L2)–(L5), from the tables or direct solves.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.compliance import _nu
from mdr_events.limits import Limits
from mdr_events.theory.layer.punch import _solve, check_solves, solve_punch
from mdr_events.theory.layer.tables import layer_table
from mdr_events.validation import check_real

__all__ = ["punch_stiffness", "punch_stiffness_slope", "spring_stiffness_density", "hess_elongation",
           "surface_displacement", "equivalent_profile", "power_law_profile", "power_law_profile_slope",
           "normal_force", "branch_depth", "branch_normal_force"]


@dataclass(frozen=True)
class _HalfSpaceFactors:
    """The factors of the half-space (``λ = 0``), exactly: no table is built."""

    exponent: float

    def stiffness_factor(self, lam) -> np.ndarray:
        return np.ones(np.shape(lam))

    edge_factor = profile_factor = stiffness_factor

    def force_factor(self, lam) -> np.ndarray:
        return np.full(np.shape(lam), self.exponent / (self.exponent + 1.0))

    def force_factors(self, lam) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return self.stiffness_factor(lam), self.profile_factor(lam), self.force_factor(lam)


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


@checked_relation
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


@checked_relation
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


@checked_relation
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


@checked_relation
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


@checked_relation
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

