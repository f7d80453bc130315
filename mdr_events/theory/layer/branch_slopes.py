r"""The slopes in ``ln a`` of a branch's depth and force on a layer, and the least of either placed at its slope's
root (:func:`flat_least`): the jump-off (the least depth, :func:`~.branch_scan.branch_jump_off`) and the pull-off
under force control (the least force, :func:`~.force_control.pull_off`).

Part of :mod:`mdr_events.theory.layer` (the relations (L1)–(L5) are stated there). A least is flat: the rounding of
the value (some ulps) moves a minimiser anywhere within ``√(ε |f| / f'')`` of it, ``~√ε`` of ``ln a``, and with it the
radius and whatever is read there (issue 32 round 30: the jump-off radius and force on a layer moved by up to 5.6e-8
of themselves under the stress scaling ``(E, τ0, Δγ) → λ(...)``, which leaves every length unchanged). The slope
crosses 0 with ``f''``: its root moves with the slope's rounding alone. The slopes are those of the interpolants the
values read (the splines' derivatives of ``γₙ`` and ``Θ(1)``), so the root is the least of the same function.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.relation_factors import _factors, _relative
from mdr_events.theory.layer.relations import hess_elongation, power_law_profile_slope
from mdr_events.theory.layer.stiffness_relations import punch_stiffness, punch_stiffness_slope

__all__ = ["depth_slope", "force_slope", "flat_least", "LEAST_XTOL"]

#: Relative accuracy in ``ln a`` of a least's radius (:func:`flat_least`): 4 ulps, Brent's root's least.
LEAST_XTOL = 4.0 * float(np.finfo(float).eps)
#: Brent's minimiser where the slope does not change sign between the nodes around the scan's least (a least at a
#: node's end of the scan): its tolerance in ``ln a``.
MINIMISER_XTOL = 1e-12


def depth_slope(a: float, profile, E_star: float, nu: float, dgamma: float, layer: Layer) -> float:
    r"""``∂d/∂ln a`` of the branch ``d(a) = g(a) − Δl(a)`` (generalised (9)) at the radius ``a`` (m):

    .. math:: \frac{\partial d}{\partial \ln a} = a\,g'(a) - \Delta l(a)\left(\frac12
              - \frac{\lambda\,\Theta'(1; \lambda)}{\Theta(1; \lambda)}\right), \qquad \lambda = a/h

    (``Θ' = 0`` on the half-space)."""
    lam = _relative(a, layer)
    logarithmic = 0.0
    if not layer.is_half_space:
        edge = _factors(nu, layer)
        logarithmic = lam * edge.edge_factor(lam, derivative=True) / edge.edge_factor(lam)
    return float(a * power_law_profile_slope(a, profile, nu, layer)
                 - hess_elongation(a, dgamma, E_star, nu, layer) * (0.5 - logarithmic))


def force_slope(a: float, profile, E_star: float, nu: float, dgamma: float, layer: Layer) -> float:
    r"""``∂F/∂ln a`` of the branch force ``F(a) = F₀(a) − K(a) Δl(a)`` (10) at the radius ``a`` (m): ``F₀' = K g'``
    (the springs at the edge carry nothing at ``d = g(a)``), so

    .. math:: \frac{\partial F}{\partial \ln a} = K(a)\,\frac{\partial d}{\partial \ln a} - a\,K'(a)\,\Delta l(a)."""
    return float(punch_stiffness(a, E_star, nu, layer) * depth_slope(a, profile, E_star, nu, dgamma, layer)
                 - a * punch_stiffness_slope(a, E_star, nu, layer) * hess_elongation(a, dgamma, E_star, nu, layer))


def flat_least(value_of, slope_of, logs: np.ndarray, best: int) -> tuple[float, float]:
    """The least of ``value_of`` (of ``ln a``) near the scan's node ``best`` of ``logs`` and its ``ln a``: the root of
    ``slope_of`` between the nodes around it where it changes sign there (to :data:`LEAST_XTOL`), else Brent's minimum
    on them (module docstring).

    Parameters
    ----------
    value_of, slope_of : callable
        The value and its slope in ``ln a``, of one ``ln a``.
    logs : numpy.ndarray
        The scan's ``ln a``, increasing.
    best : int
        The scan's least node.

    Returns
    -------
    tuple of (float, float)
        The least value and its ``ln a``.
    """
    from scipy.optimize import brentq, minimize_scalar

    best = min(max(best, 1), logs.size - 2)
    ends = (float(logs[best - 1]), float(logs[best + 1]))
    if slope_of(ends[0]) < 0.0 < slope_of(ends[1]):
        at = brentq(slope_of, *ends, xtol=LEAST_XTOL * max(abs(ends[0]), abs(ends[1]), math.ulp(1.0)),
                    rtol=LEAST_XTOL)
        return float(value_of(at)), float(at)
    found = minimize_scalar(lambda value: float(value_of(value)), bracket=(logs[best - 1], logs[best], logs[best + 1]),
                            method="brent", options={"xtol": MINIMISER_XTOL})
    return float(found.fun), float(found.x)
