r"""The Nyström solve of the tangential punch's equations (T2) at one ``a/h``: :class:`TangentialPunchSolution`,
its factors (T3) and slope (T4).

Part of :mod:`mdr_events.theory.layer_tangential`, which documents the problem and re-exports the public names.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.limits import Limits
from mdr_events.theory.layer.checks import finite_reals
from mdr_events.theory.layer.punch import solve_size
from mdr_events.theory.layer.tangential_compliance import MODES, _base, _kernel_for, _nu, check_bonded
from mdr_events.validation import check_real

__all__ = ["TangentialPunchSolution", "solve_tangential_punch"]


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

    def modes_at(self, tau) -> np.ndarray:
        r"""``Ψ_L`` and ``Ψ_T`` at any ``τ`` in ``[0, 1]`` by Nyström's interpolation of (T2).

        .. math:: \Psi_m(\tau) = 1 + \frac{\lambda}{\pi}\sum_j w_j \Psi_m(\sigma_j)
                  [k_m(\lambda(\tau-\sigma_j)) + k_m(\lambda(\tau+\sigma_j))]

        Parameters
        ----------
        tau : float or array_like
            ``r/a`` or ``t/a`` in ``[0, 1]``.

        Returns
        -------
        numpy.ndarray
            Shape ``(*tau.shape, 2)``: ``Ψ_L``, ``Ψ_T``.
        """
        tau = finite_reals("tau", tau, "finite numbers in [0, 1] (r/a)", lambda value: (value >= 0.0) & (value <= 1.0))
        if self.lam == 0.0:
            return np.ones((*tau.shape, 2))
        return np.stack([1.0 + _continuation(tau, self.lam, _kernel_for(self.nu, mode, 2.0 * self.lam + 2.0),
                                             self.sigma, self.weights, self.psi[:, j])
                         for j, mode in enumerate(MODES)], axis=-1)

    def traction_functions(self, tau) -> tuple[np.ndarray, np.ndarray]:
        r"""The punch's traction as its order-0 and order-2 functions ``Θ₀(τ)`` and ``X(τ)`` (per ``4Gu₀/(π(2 − ν))``).

        The traction ``q_x + i q_y = Q₀(r) + Q₂(r) e^{2iθ}`` has the Hankel transforms (orders 0 and 2)
        ``Q̂₀(ξ) = ∫₀ᵃ φ₀(t) cos ξt dt``, ``Q̂₂(ξ) = ∫₀ᵃ χ(t) cos ξt dt`` with ``φ₀, χ = (4Gu₀/(π(2 − ν))) Θ₀, X`` at
        ``τ = t/a``; the decoupling of (T2) gives

        .. math:: \Theta_0 \pm X = \frac{(2-\nu)\,\Phi_{L,T}\,\Psi_{T,L}}{(1-\nu)\Phi_T + \Phi_L}

        (``+``: ``Φ_L Ψ_T``; ``−``: ``Φ_T Ψ_L``), so that ``∫₀¹ X = 0`` (``Q₂ = 0`` outside the punch) and
        ``∫₀¹ Θ₀ = Φ_t`` (T3). :func:`~mdr_events.theory.layer_tangential.contact_displacement` checks them.

        Parameters
        ----------
        tau : float or array_like
            ``t/a`` in ``[0, 1]``.

        Returns
        -------
        tuple of numpy.ndarray
            ``Θ₀(τ)`` and ``X(τ)`` (1 and 0 on the half-space).
        """
        return _order_functions(self.nu, self.longitudinal_factor, self.transverse_factor, self.modes_at(tau))


def _order_functions(nu, phi_l, phi_t, modes) -> tuple[np.ndarray, np.ndarray]:
    """``Θ₀`` and ``X`` from ``Ψ_L``, ``Ψ_T`` (last axis of ``modes``): the order-2 step of the decoupling."""
    scale = (2.0 - nu) / ((1.0 - nu) * phi_t + phi_l)
    plus, minus = scale * phi_l * modes[..., 1], scale * phi_t * modes[..., 0]
    return (plus + minus) / 2.0, (plus - minus) / 2.0


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
                           nodes: int | None = None, limits: Limits | None = None) -> TangentialPunchSolution:
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
    limits : Limits or None, default None
        The memory the solve may take (as :func:`mdr_events.theory.layer.solve_punch`; ``None``: the defaults).

    Returns
    -------
    TangentialPunchSolution
        ``Ψ_L``, ``Ψ_T`` and the factors ``Φ_t``, ``Σ_t``.

    Raises
    ------
    ValueError
        ``lam`` negative, not finite or beyond :data:`~mdr_events.theory.layer.LAMBDA_SOLVE_MAX`, ``nu`` outside
        ``[0, 0.5]``, a frictionless or unknown base, ``nodes`` < 2; the nodes' memory beyond ``limits``
        (``ResourceLimitError``).
    """
    lam = check_real("lam", lam, "a finite number >= 0 (a/h)", lambda value: value >= 0.0)
    check_bonded(Layer(1.0, _base(base)))
    nu = _nu(nu)
    return _solve(lam, nu, solve_size(lam, nodes, limits))
