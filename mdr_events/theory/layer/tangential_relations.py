r"""The generalized MDR's tangential springs and caps on a bonded layer: ``K_t``, ``K_t'``, ``k_t = K_t'/2``, the cap
(13) as ``π a² τ0 / K_t`` and Coulomb's cap.

Part of :mod:`mdr_events.theory.layer_tangential`, which documents the problem and re-exports the public names.
"""

from __future__ import annotations

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.relations import spring_stiffness_density
from mdr_events.theory.layer.tangential_compliance import _nu, check_bonded
from mdr_events.theory.layer.tangential_tables import tangential_table
from mdr_events.validation import check_real

__all__ = ["tangential_punch_stiffness", "tangential_punch_stiffness_slope", "tangential_spring_stiffness_density",
           "sliding_cap", "coulomb_cap"]


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


@checked_relation
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


@checked_relation
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


@checked_relation
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


@checked_relation
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


@checked_relation
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
