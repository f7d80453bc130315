"""The punch equation (L1) of Lebedev & Ufliand solved by Nyström at one ``λ = a/h``: :class:`PunchSolution`.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from mdr_events.contact.layer import LayerBase
from mdr_events.theory.layer.compliance import _base, _ChebyshevKernel, _kernel_for, _nu
from mdr_events.validation import check_real

__all__ = ["nystrom_nodes", "PunchSolution", "solve_punch"]

#: Gauss–Legendre nodes of the Fredholm equation: ``BASE_NODES + NODES_PER_LAMBDA λ``, rounded up to 16 (converged
#: to 1e-10 relative or better up to ``λ = 200``; the tests check it against more nodes).
BASE_NODES, NODES_PER_LAMBDA = 40, 6
#: Nodes of the quadrature of the outer surface integral (L5) in the angle ``β``.
_OUTER_NODES = 64


def nystrom_nodes(lam: float) -> int:
    """The number of Gauss–Legendre nodes of the solve at ``λ = a/h``: ``40 + 6λ``, rounded up to a multiple of 16.

    Parameters
    ----------
    lam : float
        ``a/h ≥ 0``.

    Returns
    -------
    int
        The nodes :func:`solve_punch` uses by default.
    """
    return int(16 * math.ceil((BASE_NODES + NODES_PER_LAMBDA * lam) / 16))


def _continuation(tau: np.ndarray, lam: float, kern: _ChebyshevKernel | None, sigma: np.ndarray,
                  weights: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """``(λ/π) ∫₀¹ Θ(σ) [k(λ(τ − σ)) + k(λ(τ + σ))] dσ`` at any ``τ`` (Nyström's interpolation), one column per
    right-hand side."""
    tau = np.asarray(tau, dtype=float)
    if lam == 0.0:
        return np.zeros(tau.shape + theta.shape[1:])
    rows = (lam / np.pi) * weights * (kern(lam * (tau[..., None] - sigma)) + kern(lam * (tau[..., None] + sigma)))
    return rows @ theta


@dataclass(frozen=True)
class PunchSolution:
    r"""The Nyström solution of the punch equation (L1) at one ``λ = a/h``, with extra right-hand sides ``τⁿ``.

    Parameters
    ----------
    lam : float
        ``a/h``.
    nu : float
        Poisson's ratio.
    base : LayerBase
        The layer's base.
    sigma : numpy.ndarray
        The Gauss–Legendre nodes on ``[0, 1]``.
    weights : numpy.ndarray
        Their weights.
    theta : numpy.ndarray
        ``Θ`` at the nodes, one column per right-hand side: ``1`` first, then ``g∞(aτ)/g∞(a)`` of each profile
        (``τⁿ`` of :attr:`exponents`, or a general profile's).
    exponents : tuple of float
        The power laws' exponents of the columns after the first.
    kern : object
        The interpolated kernel (``None`` at ``λ = 0``).
    rhs_at_edge : tuple of float
        The right-hand sides at ``τ = 1`` (1 for ``τⁿ``).
    """

    lam: float
    nu: float
    base: LayerBase
    sigma: np.ndarray
    weights: np.ndarray
    theta: np.ndarray
    exponents: tuple[float, ...]
    kern: object
    rhs_at_edge: tuple[float, ...]

    def edge_values(self) -> np.ndarray:
        """``Θ(1)`` of every column (Nyström's interpolation at the edge).

        Returns
        -------
        numpy.ndarray
            One value per right-hand side.
        """
        rhs = np.array((1.0, *self.rhs_at_edge))
        return rhs + _continuation(np.array(1.0), self.lam, self.kern, self.sigma, self.weights, self.theta)

    @property
    def stiffness_factor(self) -> float:
        """``Φ = ∫₀¹ Θ = K(a)/(2E* a)`` (L2)."""
        return float(self.weights @ self.theta[:, 0])

    @property
    def edge_factor(self) -> float:
        """``Θ(1)``: ``K'(a) = 2E* Θ(1)²`` (L3)."""
        return float(self.edge_values()[0])

    def profile_factor(self, column: int = 1) -> float:
        """``γ = g(a)/g∞(a) = Θ_g(1)/Θ(1)`` of a profile's column (L4).

        Parameters
        ----------
        column : int, default 1
            The right-hand side (1: the first profile).

        Returns
        -------
        float
            The generalized MDR profile over the half-space's at ``x = a``.
        """
        edges = self.edge_values()
        return float(edges[column] / edges[0])

    def force_factor(self, column: int = 1) -> float:
        """``χ = F₀(a)/(2E* a g∞(a)) = γΦ − ∫₀¹ Θ_g`` of a profile's column: the non-adhesive force.

        Parameters
        ----------
        column : int, default 1
            The right-hand side (1: the first profile).

        Returns
        -------
        float
            ``n/(n + 1)`` for the power law on the half-space.
        """
        return self.profile_factor(column) * self.stiffness_factor - float(self.weights @ self.theta[:, column])

    def surface_displacement(self, rho) -> np.ndarray:
        r"""``φ(r; a)``: the surface's displacement over the punch's, at ``ρ = r/a`` (L5).

        .. math:: \varphi = \frac{2}{\pi}\Big[\arcsin\frac{1}{\rho}
                  - \int_{\arcsin(1/\rho)}^{\pi/2} G(\rho\sin\beta)\,\mathrm{d}\beta\Big]\quad(\rho > 1)

        Parameters
        ----------
        rho : float or array_like
            ``r/a ≥ 0``; 1 at ``ρ ≤ 1``.

        Returns
        -------
        numpy.ndarray
            ``φ``, shaped as ``rho``.
        """
        rho = np.asarray(rho, dtype=float)
        out = np.ones(rho.shape)
        x, w = np.polynomial.legendre.leggauss(_OUTER_NODES)
        for index in np.ndindex(rho.shape):
            value = float(rho[index])
            if value <= 1.0:
                continue
            start = math.asin(1.0 / value)
            panels = max(1, math.ceil((value - 1.0) * max(self.lam, 1.0) / 2.0))
            edges = np.linspace(start, math.pi / 2.0, panels + 1)
            half = np.diff(edges)[:, None] / 2.0
            beta = (edges[:-1, None] + half * (x + 1.0)).ravel()
            correction = _continuation(value * np.sin(beta), self.lam, self.kern, self.sigma, self.weights,
                                       self.theta[:, :1])[:, 0]
            out[index] = 2.0 / np.pi * (start - correction @ (half * w).ravel())
        return out


@functools.lru_cache(maxsize=64)
def _gauss_legendre(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights on ``[0, 1]`` (kept: NumPy's eigenvalue solve is the table's main cost)."""
    from scipy.special import roots_legendre

    x, w = roots_legendre(count)
    return (x + 1.0) / 2.0, w / 2.0


def _solve(lam: float, nu: float, base: LayerBase, rhs: Callable[[np.ndarray], np.ndarray],
           rhs_at_edge: tuple[float, ...], exponents: tuple[float, ...], nodes: int | None) -> PunchSolution:
    """The Nyström solve of (L1) with the right-hand sides ``1`` and ``rhs(σ)`` (columns)."""
    count = nystrom_nodes(lam) if nodes is None else nodes
    sigma, weights = _gauss_legendre(count)
    right = np.column_stack([np.ones(count), rhs(sigma)])
    if lam == 0.0:
        return PunchSolution(0.0, nu, base, sigma, weights, right, exponents, None, rhs_at_edge)
    kern = _kernel_for(nu, base, 2.0 * lam + 2.0)
    matrix = np.eye(count) - (lam / np.pi) * weights * (kern(lam * (sigma[:, None] - sigma))
                                                       + kern(lam * (sigma[:, None] + sigma)))
    return PunchSolution(lam, nu, base, sigma, weights, np.linalg.solve(matrix, right), exponents, kern,
                         rhs_at_edge)


def solve_punch(lam: float, nu: float, base: LayerBase | str = LayerBase.BONDED, exponents=(2.0,),
                nodes: int | None = None) -> PunchSolution:
    r"""Solve the layer's punch equation (L1) at ``λ = a/h`` directly (no table), with power-law right-hand sides.

    .. math:: \Theta(\tau) - \frac{\lambda}{\pi}\int_0^1 \Theta(\sigma)
              [k(\lambda(\tau-\sigma)) + k(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = \tau^n

    Parameters
    ----------
    lam : float
        ``a/h ≥ 0`` (0: the half-space, ``Θ = τⁿ``).
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    base : LayerBase or str, default LayerBase.BONDED
        The layer's base.
    exponents : sequence of float, default (2.0,)
        The exponents ``n > 0`` of the extra right-hand sides ``τⁿ`` (the half-space profile ``g∞ ∝ xⁿ`` of the
        power law ``c rⁿ``; 2 the paraboloid).
    nodes : int or None, default None
        Gauss–Legendre nodes (default :func:`nystrom_nodes`).

    Returns
    -------
    PunchSolution
        ``Θ`` of the flat punch and of each profile, with their factors.

    Raises
    ------
    ValueError
        ``lam`` negative or not finite, ``nu`` outside ``[0, 0.5]``, ``base`` unknown, an exponent ≤ 0.
    """
    lam = check_real("lam", lam, "a finite number >= 0 (a/h)", lambda value: value >= 0.0)
    exps = tuple(check_real("exponents", n, "numbers > 0", lambda value: value > 0.0) for n in exponents)
    if nodes is not None and (isinstance(nodes, bool) or not isinstance(nodes, int) or nodes < 2):
        raise ValueError(f"nodes={nodes!r} is not allowed; allowed: an integer >= 2 or None")
    return _solve(lam, _nu(nu), _base(base), lambda s: np.power.outer(s, np.array(exps, dtype=float)),
                  (1.0,) * len(exps), exps, nodes)

