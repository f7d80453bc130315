r"""The flat punch's receding branch on a layer: where its contact stops receding under the face.

Part of :mod:`mdr_events.theory.layer`. Under the face every spring rests on ``g = 0``; once the edge's spring reaches
Heß's limit, ``d = −Δl(a₀)``, the contact recedes along ``d = −Δl(a)`` while ``Δl`` falls with the radius
(:mod:`mdr_events.theory.layer_symbolic`, section 8). With ``Δl = sqrt(2π a Δγ/E*)/Θ(1; a/h)``,

.. math:: \frac{\mathrm{d}\ln\Delta l}{\mathrm{d}a} = \frac{1}{2a} - \frac{\Theta'(\lambda)}{h\,\Theta(\lambda)},

whose sign is that of ``K' − a K''`` (``layer_flat_punch_receding_slope``): the recession stops, and the rest of the
contact comes off at once, at the largest radius below the face where it turns non-negative (:func:`receding_radius`;
the face itself where it is not negative there: the half-space's jump, Kendall's depth on the layer). On the half-space
(``Θ = 1``) it is ``1/(2a) > 0`` at every radius.
"""

from __future__ import annotations

import numpy as np

from mdr_events.theory.layer.scalar_factors import NormalFactors

__all__ = ["receding_radius", "hess_log_slope", "RECEDING_SCAN", "RECEDING_FLOOR"]

#: Points of the scan from the face inwards, geometric down to :data:`RECEDING_FLOOR` of it (16 a decade), that brackets
#: where the recession stops (Brent's method refines). The slope turns once at most on the tables (``Δl`` has a single
#: hump, every ``ν``), so any spacing brackets it; the nodes inside the bracket check that it does not turn back.
RECEDING_SCAN = 97
#: The scan's innermost radius, a share of the face: ``d ln Δl/da = 1/(2a) − Θ'/(hΘ) > 0`` wherever ``a < 0.4 h``
#: (the tables' largest ``Θ'/Θ`` is 1.24, at ``ν = 0.5``, ``λ ≈ 0.18``), and a face within the tables (``a₀ <= 64 h``)
#: puts ``0.4 h`` at ``1/160`` of it or beyond; ``1e-6`` is far inside that.
RECEDING_FLOOR = 1e-6


def hess_log_slope(factors: NormalFactors, a: float) -> float:
    """``d ln Δl/da = 1/(2a) − Θ'/(hΘ)`` at the radius ``a`` (1/m): negative where the punch's contact recedes.

    It is ``layer_flat_punch_receding_slope`` over ``−Δl`` with ``K' = 2E*Θ²``, ``K'' = 4E*ΘΘ'/h`` (the tables' ``Θ``,
    ``Θ'`` without a difference quotient for ``K''``); a test evaluates the derived relation against it.

    Parameters
    ----------
    factors : NormalFactors
        The layer's normal factors for one float.
    a : float
        The radius (m, > 0).

    Returns
    -------
    float
        The slope (1/m).
    """
    theta, theta_slope = factors.edge_factor(a)
    return 0.5 / a - theta_slope / (factors.h * theta)


def receding_radius(factors: NormalFactors, face: float) -> float:
    """The radius where the flat punch's receding contact comes off: the largest radius ``<= face`` at which
    ``d ln Δl/da`` turns non-negative going inwards (the face where it is not negative there).

    Parameters
    ----------
    factors : NormalFactors
        The layer's normal factors for one float.
    face : float
        The punch's radius ``a₀`` (m), within the tables.

    Returns
    -------
    float
        The jump-off radius (m).

    Raises
    ------
    RuntimeError
        The slope negative down to :data:`RECEDING_FLOOR` of the face (not on a layer of the tables: the half-space's ``1/(2a)``
        wins there).
    """
    from scipy.optimize import brentq

    def slope(a: float) -> float:
        return hess_log_slope(factors, a)

    if not slope(face) < 0.0:
        return face
    radii = face * np.geomspace(1.0, RECEDING_FLOOR, RECEDING_SCAN)
    for index, (outer, inner) in enumerate(zip(radii.tolist(), radii[1:].tolist())):
        if not slope(inner) < 0.0:
            _check_single_hump(slope, radii[index + 2:], face, factors.h)
            return float(brentq(slope, inner, outer, xtol=1e-15 * inner, rtol=4.0 * np.finfo(float).eps))
    raise RuntimeError(f"receding_radius: d ln Δl/da stays negative from the face {face!r} m down to "
                       f"{radii[-1]!r} m on h = {factors.h!r} m; the half-space's 1/(2a) should win there")


def _check_single_hump(slope, inner: np.ndarray, face: float, h: float) -> None:
    """Refuse a ``Δl`` that falls again inside the jump-off (a second hump on the scan's nodes ``inner``): there a
    smaller contact would hold after the jump instead of the rest coming off at once, which the branch does not take.
    The tables' ``Δl`` has a single hump at every ``ν`` (tested), so this holds on every layer they cover."""
    for radius in inner.tolist():
        if slope(radius) < 0.0:
            raise RuntimeError(f"receding_radius: Heß's limit falls again at {radius!r} m, inside the jump-off, under the "
                               f"face {face!r} m on h = {h!r} m; allowed: a single hump of Δl (the rest comes off at "
                               "once)")


def punch_jump_off(contact, dgamma: float) -> tuple[float, float]:
    """The flat punch's jump-off on the contact's layer under depth control: ``(−Δl(a_j), a_j)`` with ``a_j`` from
    :func:`receding_radius` (``(0, a₀)`` without adhesion: the face comes off at the surface).

    Parameters
    ----------
    contact : Contact
        A flat punch on a layer of finite thickness (its radius within the tables).
    dgamma : float
        The work of adhesion of the way out (J/m², ≥ 0).

    Returns
    -------
    tuple of (float, float)
        The depth (m, ≤ 0) and the radius (m).
    """
    from mdr_events.theory.layer.relations import hess_elongation

    face = float(contact.indenter.radius)
    if dgamma == 0.0:
        return 0.0, face
    elastomer, layer = contact.elastomer, contact.layer
    radius = receding_radius(NormalFactors(elastomer.nu, layer, 2.0), face)
    return -float(hess_elongation(radius, dgamma, elastomer.E_star, elastomer.nu, layer)), radius
