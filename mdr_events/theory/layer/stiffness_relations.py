r"""The punch on the layer: its stiffness ``K(a)`` (L2) and slope, the springs' ``k(x) = K'/2``, Heß's ``Δl`` and the
surface's displacement, from the tables or direct solves.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there; the names are also those of
:mod:`mdr_events.theory.layer.relations`).
"""

from __future__ import annotations

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.punch import solve_punch
from mdr_events.theory.layer.relation_factors import _factors, _relative
from mdr_events.validation import check_real

__all__ = ["punch_stiffness", "punch_stiffness_slope", "spring_stiffness_density", "hess_elongation",
           "surface_displacement"]


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
