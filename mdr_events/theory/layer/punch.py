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
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.validation import check_count, check_real, shown

__all__ = ["nystrom_nodes", "PunchSolution", "solve_punch", "LAMBDA_SOLVE_MAX", "SOLVE_BYTES_PER_PAIR",
           "SOLVE_STEPS_PER_PAIR"]

#: Gauss–Legendre nodes of the Fredholm equation: ``BASE_NODES + NODES_PER_LAMBDA λ``, rounded up to 16 (converged
#: to 1e-10 relative or better up to ``λ = 200``; the tests check it against more nodes).
BASE_NODES, NODES_PER_LAMBDA = 40, 6
#: Nodes of the quadrature of the outer surface integral (L5) in the angle ``β``.
_OUTER_NODES = 64
#: The largest ``a/h`` of a direct solve: where the default nodes are converged; beyond it the solve grows as ``λ²`` in
#: memory and ``λ³`` in time (1000 took 5 GiB, 1e4 did not end).
LAMBDA_SOLVE_MAX = 200.0
#: Memory of a Nyström solve per pair of nodes (the kernel's interpolants on the ``nodes²`` grid twice and the
#: matrix), in bytes, checked against :class:`~mdr_events.Limits`.
SOLVE_BYTES_PER_PAIR = 400.0
#: What a pair of nodes of a direct solve counts against :attr:`~mdr_events.Limits.steps` (its kernel's entries and
#: its share of the LU: 0.2 to 0.7 µs here, where the discrete model's step takes about 1.5 µs), so that many solves
#: are counted before the first (10**7 radii of an equivalent profile were taken: hours).
SOLVE_STEPS_PER_PAIR = 1.0


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
        return float(edges[self._column(column)] / edges[0])

    def _column(self, column) -> int:
        """``column`` if it names a profile's right-hand side (1 to the number of profiles), else a one-line error."""
        profiles = self.theta.shape[1] - 1
        if profiles == 0:
            raise ValueError(f"column={shown(column)} is not allowed: this solution has no profile's right-hand "
                             "side; allowed: a solution with exponents (solve_punch(..., exponents=(2.0,)))")
        column = check_count("column", column, 1)
        if column > profiles:
            raise ValueError(f"column={column} is not allowed; allowed: 1 to {profiles} (the profiles' right-hand "
                             "sides)")
        return column

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
        column = self._column(column)
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
        from mdr_events.theory.layer.checks import finite_reals

        rho = finite_reals("rho", rho, "finite numbers >= 0 (r/a)", lambda value: value >= 0.0)
        points = _OUTER_NODES * np.ceil(np.maximum(rho - 1.0, 0.0) * max(self.lam, 1.0) / 2.0)
        DEFAULT_LIMITS.check(f"the surface displacement at r/a up to {float(np.max(rho, initial=0.0)):.6g} "
                             f"(a/h = {self.lam:g})", samples=float(np.max(points, initial=0.0)),
                             memory=SOLVE_BYTES_PER_PAIR * float(np.max(points, initial=0.0)) * self.sigma.size)
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


def solve_size(lam: float, nodes: int | None, limits: Limits | None = None) -> int:
    """The nodes of a direct solve at ``λ = a/h`` (the normal punch's or the tangential one's), checked before anything
    is built: ``λ`` up to :data:`LAMBDA_SOLVE_MAX` and the nodes' memory within ``limits``.

    Parameters
    ----------
    lam : float
        ``a/h``, a number ``>= 0`` (checked by the caller).
    nodes : int or None
        The nodes asked (``None``: :func:`nystrom_nodes`).
    limits : Limits or None, default None
        The memory the solve may take (:data:`SOLVE_BYTES_PER_PAIR` per pair of nodes; ``None``: the defaults).

    Returns
    -------
    int
        The nodes.

    Raises
    ------
    ValueError
        ``lam`` beyond :data:`LAMBDA_SOLVE_MAX`, ``nodes`` not an integer >= 2 (``TypeError`` for another type), the
        memory beyond ``limits`` (``ResourceLimitError``).
    """
    if not lam <= LAMBDA_SOLVE_MAX:
        raise ValueError(f"a/h={lam!r} is not allowed for a direct solve; allowed: 0 <= a/h <= {LAMBDA_SOLVE_MAX:g} "
                         "(where its nodes are converged; the thin-layer limits of theory.layer_symbolic beyond)")
    count = nystrom_nodes(lam) if nodes is None else check_count("nodes", nodes, 2)
    check_limits(limits).check(f"the layer's Nyström solve with {count} nodes (a/h = {lam:g})",
                               memory=SOLVE_BYTES_PER_PAIR * float(count) ** 2)
    return count


def check_solves(lams: np.ndarray, limits: Limits | None, what: str) -> None:
    """Direct solves at each of ``lams`` (``a/h``), one each, checked before the first: the largest within
    :data:`LAMBDA_SOLVE_MAX` (and its nodes' memory within ``limits``), and their pairs of nodes
    (:data:`SOLVE_STEPS_PER_PAIR` steps each) within ``limits``.

    Parameters
    ----------
    lams : numpy.ndarray
        The ``a/h`` of the solves, ``>= 0``.
    limits : Limits or None
        The limits (``None``: the defaults).
    what : str
        Names the computation in the message.

    Raises
    ------
    ValueError
        An ``a/h`` beyond :data:`LAMBDA_SOLVE_MAX`; the solves beyond ``limits`` (``ResourceLimitError``).
    """
    solve_size(float(np.max(lams, initial=0.0)), None, limits)
    nodes = 16.0 * np.ceil((BASE_NODES + NODES_PER_LAMBDA * lams) / 16.0)  # (nystrom_nodes, for every solve)
    check_limits(limits).check(f"{what} ({lams.size} direct solves)",
                               steps=SOLVE_STEPS_PER_PAIR * float(np.sum(nodes**2)))


@functools.lru_cache(maxsize=64)
def _gauss_legendre(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights on ``[0, 1]`` (kept: NumPy's eigenvalue solve is the table's main cost)."""
    from scipy.special import roots_legendre

    x, w = roots_legendre(count)
    return (x + 1.0) / 2.0, w / 2.0


def _solve(lam: float, nu: float, base: LayerBase, rhs: Callable[[np.ndarray], np.ndarray],
           rhs_at_edge: tuple[float, ...], exponents: tuple[float, ...], nodes: int | None,
           limits: Limits | None = None) -> PunchSolution:
    """The Nyström solve of (L1) with the right-hand sides ``1`` and ``rhs(σ)`` (columns); ``λ`` up to
    :data:`LAMBDA_SOLVE_MAX` and the nodes' memory within ``limits`` (checked before anything is built)."""
    count = solve_size(lam, nodes, limits)
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
                nodes: int | None = None, limits: Limits | None = None) -> PunchSolution:
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
    limits : Limits or None, default None
        The memory the solve may take (:data:`SOLVE_BYTES_PER_PAIR` per pair of nodes; ``None``: the defaults).

    Returns
    -------
    PunchSolution
        ``Θ`` of the flat punch and of each profile, with their factors.

    Raises
    ------
    ValueError
        ``lam`` negative, not finite or beyond :data:`LAMBDA_SOLVE_MAX`, ``nu`` outside ``[0, 0.5]``, ``base``
        unknown, an exponent ≤ 0; the nodes' memory beyond ``limits`` (``ResourceLimitError``).
    TypeError
        ``exponents`` not a sequence of numbers.
    """
    lam = check_real("lam", lam, f"a finite number >= 0 (a/h), at most {LAMBDA_SOLVE_MAX:g}",
                     lambda value: value >= 0.0)
    if isinstance(exponents, (str, bytes)) or not hasattr(exponents, "__iter__"):
        raise TypeError(f"exponents={shown(exponents)} ({type(exponents).__name__}) is not allowed; allowed: a "
                        "sequence of numbers > 0, e.g. (2.0,)")
    exps = tuple(check_real("exponents", n, "numbers > 0", lambda value: value > 0.0) for n in exponents)
    return _solve(lam, _nu(nu), _base(base), lambda s: np.power.outer(s, np.array(exps, dtype=float)),
                  (1.0,) * len(exps), exps, nodes, limits)

