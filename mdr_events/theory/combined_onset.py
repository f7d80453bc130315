"""Scenario A's slip onset with adhesion under both parts of the cap (``"tau0+coulomb"``) on a power law.

Along ``x = d cot α`` from the first contact at ``d = 0`` every spring sticks until the first reaches its cap: the
springs under the jump-in radius ``a_J`` hold ``d cot α``, those grown since along the ``Δγ0`` branch
``(d − d0(ξ)) cot α``, against ``K a + κ max(d − g(ξ), 0)``. The largest excess of shift over cap lies at ``a_J``, at
the compression boundary ``x_c`` (``g(x_c) = d``) or at the turn ``ξ*`` of the compressed grown springs
(``symbolic.derive_adhesive_friction_model``: ``adhesive_onset_excess_A``, ``adhesive_onset_turn_A``), wherever they
lie in the contact (:func:`onset_excess_A`); the onset is the least depth where it reaches 0 (:func:`d_crit_A`), found
on a grid of :data:`GRID` depths to ``d_max`` and refined by bisection to :data:`BISECTIONS` halvings. No spring slides
on the negative side: every shift is ``>= 0``. The critical angle (slip at ``d_max``) is where that first depth is
``d_max`` (:func:`critical_angle_A`): the excess grows with ``cot α`` at every spring and depth, so the angles that
slide before ``d_max`` are those below it.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law, symbolic

__all__ = ["GRID", "BISECTIONS", "onset_excess_A", "d_crit_A", "critical_angle_A"]

#: Depths to ``d_max`` at which the excess is sampled for its first change of sign (its parts are smooth in the depth)
GRID = 2048
#: Halvings of a bracketing grid interval: the onset to 2⁻⁶⁰ of ``d_max``, below its rounding
BISECTIONS = 60


def onset_excess_A(depth, cot: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> np.ndarray:
    """The largest excess of shift over cap (m) of scenario A's springs at ``depth`` (array) on the path of
    ``cot α`` (array, broadcast with it), before any slides (module docstring).

    Parameters
    ----------
    depth : array_like
        Depths ``d > 0`` (m).
    cot : array_like
        ``cot α`` of the paths.
    friction : FrictionLaw
        ``"tau0+coulomb"`` (its ``μ``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0``.
    profile : PowerLaw
        The indenter.

    Returns
    -------
    numpy.ndarray
        ``max_ξ [(d − d_ξ) cot α − ū(ξ)]`` (m), the broadcast shape.
    """
    depth, cot = np.broadcast_arrays(np.asarray(depth, dtype=float), np.asarray(cot, dtype=float))
    K, kappa = power_law.cap_per_radius(params), friction.coulomb_mu * params.E_star / params.G_star
    radius = np.asarray(power_law.contact_radius(depth, profile, params, params.dgamma0), dtype=float)
    jump_in = power_law.jump_in_radius(profile, params, params.dgamma0) if params.dgamma0 > 0 else 0.0
    g_jump_in = float(power_law.equivalent_profile(jump_in, profile))
    best = depth * cot - K * radius - kappa * np.maximum(depth - g_jump_in, 0.0)  # the jump-in ring's edge
    boundary = np.asarray(power_law.contact_radius(depth, profile, params, 0.0), dtype=float)  # x_c
    hess = power_law.hess_prefactor(params, params.dgamma0)
    at_boundary = cot * hess * np.sqrt(boundary) - K * radius  # (d − d0(x_c) = Δl0(x_c))
    best = np.where((boundary > jump_in) & (boundary < radius), np.maximum(best, at_boundary), best)
    turning = cot > kappa  # the compressed grown springs' excess has its one maximum at ξ* (free of d)
    if np.any(turning) and params.dgamma0 > 0:
        arguments = (friction.coulomb_mu, params.dgamma0, profile.c, profile.n, params.E_star, params.G_star)
        with np.errstate(divide="ignore", invalid="ignore"):
            turn = np.asarray(symbolic.relation("adhesive_onset_turn_A").numeric(cot, *arguments), dtype=float)
            at_turn = np.asarray(symbolic.relation("adhesive_onset_excess_A").numeric(
                turn, depth, radius, cot, params.tau0, *arguments), dtype=float)
        inside = turning & (turn > jump_in) & (turn < boundary)
        best = np.where(inside, np.maximum(best, at_turn), best)
    return best


def d_crit_A(alpha: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> np.ndarray:
    """The onset depth (m) of scenario A at the angles ``alpha`` (degrees, in (0, 90)): the least depth up to
    ``d_max`` where :func:`onset_excess_A` reaches 0; 0 where it is reached at the least depth bisected (the springs
    slide from first contact: a cone without adhesion), ``nan`` where none is by ``d_max``.

    Parameters
    ----------
    alpha : numpy.ndarray
        Path angles (degrees), in (0, 90).
    friction : FrictionLaw
        ``"tau0+coulomb"``.
    params : Parameters
        The material, ``τ0``, ``Δγ0`` and ``d_max``.
    profile : PowerLaw
        The indenter.

    Returns
    -------
    numpy.ndarray
        The onset depths (m), the shape of ``alpha``.
    """
    cot = 1.0 / np.tan(np.radians(np.asarray(alpha, dtype=float)))
    depths = params.d_max * np.arange(1, GRID + 1) / GRID
    excess = onset_excess_A(depths[None, :], cot.reshape(-1, 1), friction, params, profile)
    reached = excess >= 0.0
    first = np.argmax(reached, axis=1)
    found = reached[np.arange(len(first)), first]
    low = np.where(first > 0, depths[np.maximum(first - 1, 0)], 0.0)
    high = depths[first]
    flat = cot.reshape(-1)
    for _ in range(BISECTIONS):  # the excess is < 0 at low (or d = 0: −K a_J) and >= 0 at high
        middle = 0.5 * (low + high)
        up = onset_excess_A(middle, flat, friction, params, profile) >= 0.0
        low, high = np.where(up, low, middle), np.where(up, middle, high)
    # an excess already reached at the smallest depth bisected: the springs slide from first contact (0)
    at_once = found & (low == 0.0) & (onset_excess_A(high, flat, friction, params, profile) >= 0.0)
    return np.where(at_once, 0.0, np.where(found, high, np.nan)).reshape(np.shape(alpha))


def critical_angle_A(friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> float:
    """The angle (degrees) below which scenario A slides before ``d_max``: bisection on whether :func:`d_crit_A`
    finds an onset (monotone in the angle: module docstring); 90° where even a path along the surface slides, 0 where
    none does.

    Parameters
    ----------
    friction : FrictionLaw
        ``"tau0+coulomb"``.
    params : Parameters
        The material, ``τ0``, ``Δγ0`` and ``d_max``.
    profile : PowerLaw
        The indenter.

    Returns
    -------
    float
        ``α_c`` (degrees).
    """
    low, high = 0.0, 90.0
    for _ in range(BISECTIONS):
        middle = 0.5 * (low + high)
        if math.isnan(float(d_crit_A(np.array([middle]), friction, params, profile)[0])):
            high = middle
        else:
            low = middle
    return 0.5 * (low + high)
