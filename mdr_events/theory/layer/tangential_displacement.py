r"""The surface displacement under the tangential punch, inside the contact, by direct Hankel quadrature: the check of
the tangential punch's reduction to (T2) that does not go through it.

The traction of :meth:`~mdr_events.theory.layer.tangential_punch.TangentialPunchSolution.traction_functions`,
``q_x + i q_y = Q₀(r) + Q₂(r) e^{2iθ}`` with Hankel transforms ``Q̂₀ = ∫₀ᵃ φ₀ cos ξt dt`` (order 0) and
``Q̂₂ = ∫₀ᵃ χ cos ξt dt`` (order 2), moves the top by ``u_x + i u_y = U₀(r) + U₂(r) e^{2iθ}``. The compliance of (T1)
acts on a Fourier mode as ``A q̂ + B e^{2iψ} q̄̂`` (``ψ`` the wave vector's angle), with

.. math:: A = \frac{(1-\nu)C_L + C_T}{2}, \qquad B = \frac{(1-\nu)C_L - C_T}{2},

and the 2-D Fourier transform of ``f(r)e^{inθ}`` is ``2π(−i)ⁿ e^{inψ}`` times its order-``n`` Hankel transform, so

.. math:: U_0(r) = \frac1G\int_0^\infty (A\hat Q_0 - B\hat Q_2)\,J_0(\xi r)\,\mathrm{d}\xi, \qquad
          U_2(r) = -\frac1G\int_0^\infty (B\hat Q_0 - A\hat Q_2)\,J_2(\xi r)\,\mathrm{d}\xi .

A sticking punch moved by ``u₀`` along ``x`` needs ``U₀ = u₀`` and ``U₂ = 0`` for ``r < a`` (a uniform displacement:
no ``e^{2iθ}`` part, no motion across). The half-space's ``A∞ = (2 − ν)/2``, ``B∞ = −ν/2`` are integrated in
closed form (Gradshteyn & Ryzhik 6.671: ``∫₀^∞ cos(ξt) J₀(ξr) dξ = 1/sqrt(r² − t²)`` and
``∫₀^∞ cos(ξt) J₂(ξr) dξ = cos(2 arcsin(t/r))/sqrt(r² − t²)`` for ``t < r``, both 0 for ``t > r``; then
``t = r sin ϑ``); the layer's remainder ``A − A∞``, ``B − B∞``, which falls as ``e^{−2ξh}``, by composite
Gauss–Legendre quadrature in ``u = ξh`` of the Bessel functions themselves. Nothing of the Abel operators that reduce
the contact conditions to (T2) is used: the check holds only if the reduction, its order-2 step included, is right.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.limits import DEFAULT_LIMITS
from mdr_events.theory.layer.checks import finite_reals
from mdr_events.theory.layer.tangential_compliance import tangential_compliance
from mdr_events.theory.layer.tangential_punch import TangentialPunchSolution
from mdr_events.validation import shown

__all__ = ["contact_displacement"]

#: The remainder's quadrature in ``u = ξh``: the end (``1 − C_m < 1e-30`` beyond), panels of at most this width
#: (and ``1/λ``: the integrand oscillates at up to ``2λ`` per unit ``u``) and Gauss–Legendre nodes per panel.
_U_END, _U_PANEL, _U_NODES = 40.0, 0.25, 24
#: Gauss–Legendre nodes of the half-space part in ``ϑ`` (the integrand is smooth: ``Θ₀(ρ sin ϑ)``).
_THETA_NODES = 160
#: The arrays of the quadrature, in doubles per pair of nodes: the cosines on ``u × τ`` (with their argument), the
#: Bessel functions on ``ρ × u`` (with theirs and the product): counted against :class:`~mdr_events.Limits`.
_DOUBLES_PER_COSINE, _DOUBLES_PER_BESSEL = 2.0, 3.0


def _panels(lam: float) -> tuple[float, int]:
    """The remainder's panel width in ``u`` and their number at ``λ``."""
    panel = min(_U_PANEL, 1.0 / lam)
    return panel, int(math.ceil(_U_END / panel))


def _tau_nodes(lam: float) -> int:
    """The Gauss–Legendre nodes in ``τ`` of the cosine transforms at ``λ``."""
    return 64 + int(math.ceil(_U_END * lam))


def _check_size(solution: TangentialPunchSolution, points: int) -> None:
    """The quadrature's memory at ``solution``'s ``λ`` for ``points`` radii, against the default limits."""
    if solution.lam == 0.0:
        return
    u_nodes = _panels(solution.lam)[1] * _U_NODES
    doubles = u_nodes * (_DOUBLES_PER_COSINE * _tau_nodes(solution.lam) + _DOUBLES_PER_BESSEL * points)
    DEFAULT_LIMITS.check(f"the tangential displacement at {points} radii (a/h = {solution.lam:g})",
                         memory=8.0 * doubles)


def _gauss(count: int, low: float, high: float) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(count)
    return low + (high - low) * (x + 1.0) / 2.0, w * (high - low) / 2.0


def _remainder_parts(solution: TangentialPunchSolution) -> tuple[np.ndarray, ...]:
    """The ``u`` nodes and weights, ``A − A∞``, ``B − B∞`` and the cosine transforms of ``Θ₀``, ``X`` there."""
    lam, nu = solution.lam, solution.nu
    panel, count = _panels(lam)
    starts = np.arange(count) * panel
    x, w = np.polynomial.legendre.leggauss(_U_NODES)
    u = (starts[:, None] + (x + 1.0) * panel / 2.0).ravel()
    wu = np.tile(w * panel / 2.0, starts.size)
    tau, wt = _gauss(_tau_nodes(lam), 0.0, 1.0)
    theta0, chi = solution.traction_functions(tau)
    cosines = np.cos(np.outer(u * lam, tau)) * wt
    long_rest = (1.0 - nu) * (1.0 - tangential_compliance(u, nu, "longitudinal"))
    trans_rest = 1.0 - tangential_compliance(u, nu, "transverse")
    return u, wu, -(long_rest + trans_rest) / 2.0, -(long_rest - trans_rest) / 2.0, cosines @ theta0, cosines @ chi


def contact_displacement(solution: TangentialPunchSolution, rho) -> tuple[np.ndarray, np.ndarray]:
    r"""The top's displacement ``U₀`` and ``U₂`` inside the tangential punch, per ``u₀``, by direct Hankel quadrature.

    .. math:: \frac{U_0}{u_0} = \frac{4}{\pi(2-\nu)}\Big[\int_0^{\pi/2} (A_\infty\Theta_0 - B_\infty X)(\rho\sin\vartheta)
              \,\mathrm{d}\vartheta + \lambda\int_0^\infty (\Delta A\,\hat\Theta_0 - \Delta B\,\hat X)(u)\,
              J_0(u\lambda\rho)\,\mathrm{d}u\Big]

    and ``U₂/u₀`` likewise with ``−(B Θ₀ − A X)``, ``cos 2ϑ`` and ``J₂`` (``Θ̂(u) = ∫₀¹ Θ(τ) cos(uλτ) dτ``,
    ``ρ = r/a``, ``λ = a/h``); the module's docstring derives it. Both are ``1`` and ``0`` for a right solution.

    Parameters
    ----------
    solution : TangentialPunchSolution
        A solved punch (:func:`~mdr_events.theory.layer_tangential.solve_tangential_punch`).
    rho : float or array_like
        ``r/a`` in ``[0, 1)``.

    Returns
    -------
    tuple of numpy.ndarray
        ``U₀/u₀`` and ``U₂/u₀`` at ``rho``.

    Raises
    ------
    TypeError
        ``solution`` not a :class:`~mdr_events.theory.layer_tangential.TangentialPunchSolution`, ``rho`` not real
        numbers.
    ValueError
        ``rho`` outside ``[0, 1)`` or not finite; the quadrature's memory beyond the default
        :class:`~mdr_events.Limits` (``ResourceLimitError``).
    """
    from scipy.special import jv

    if not isinstance(solution, TangentialPunchSolution):
        raise TypeError(f"solution={shown(solution)} ({type(solution).__name__}) is not allowed; allowed: a "
                        "TangentialPunchSolution (solve_tangential_punch)")
    rho = finite_reals("rho", rho, "finite numbers with 0 <= r/a < 1 (inside the contact)",
                       lambda value: (value >= 0.0) & (value < 1.0))
    _check_size(solution, rho.size)
    nu, lam = solution.nu, solution.lam
    a_far, b_far = (2.0 - nu) / 2.0, -nu / 2.0
    theta, w_theta = _gauss(_THETA_NODES, 0.0, np.pi / 2.0)
    theta0, chi = solution.traction_functions(rho[..., None] * np.sin(theta))
    u0 = (a_far * theta0 - b_far * chi) @ w_theta
    u2 = -((b_far * theta0 - a_far * chi) * np.cos(2.0 * theta)) @ w_theta
    if lam > 0.0:
        u, wu, d_a, d_b, theta0_hat, chi_hat = _remainder_parts(solution)
        argument = np.multiply.outer(rho, u * lam)
        u0 = u0 + lam * (jv(0, argument) @ (wu * (d_a * theta0_hat - d_b * chi_hat)))
        u2 = u2 - lam * (jv(2, argument) @ (wu * (d_b * theta0_hat - d_a * chi_hat)))
    scale = 4.0 / (np.pi * (2.0 - nu))
    return scale * u0, scale * u2
