"""The paraboloid's tangential springs (13): the critical shift ``ū(a)`` and the energy a fretting cycle dissipates.
"""

from __future__ import annotations

import numpy as np

from mdr_events.theory.analytic.arguments import _finite, _rel, representable_result
from mdr_events.theory.job import ContactLike, paper_parameters

__all__ = ["critical_shift", "fretting_dissipated_energy"]


def critical_shift(contact_radius, contact: ContactLike):
    r"""Critical spring shift ``ū(a) = π a τ0 / (2 G*)``, eq. (13).

    .. math:: \bar u(a) = \frac{\pi a \tau_0}{2 G^*} \qquad (13)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4) under the law (13) (its ``τ0`` and ``G*``): a :class:`~mdr_events.Contact`, or
        a :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The critical shift ``ū`` (m) of a spring: beyond it the spring slides.
    """
    (contact_radius,) = _finite(contact_radius=contact_radius)
    params = paper_parameters(contact, "critical_shift")
    relation = _rel("critical_shift").numeric
    return representable_result(lambda: relation(contact_radius, params.tau0, params.G_star), "critical_shift",
                                contact_radius=contact_radius)


def fretting_dissipated_energy(contact_radius, amplitude, contact: ContactLike):
    r"""Energy dissipated per cycle ``x: −X → X → −X`` by a fixed contact of radius ``a`` (J): the area
    ``4 π a² τ0 (X − ū)`` of the parallelogram ``F_x = 2G* a (x − Y)``, ``Y`` clipped to
    ``[x − ū, x + ū]`` (plateaus ``±π a² τ0``, (13)), for ``X > ū``; smaller loops stick and dissipate nothing (0).

    .. math:: W = 4 \pi a^2 \tau_0 (X - \bar u), \qquad \bar u = \frac{\pi a \tau_0}{2 G^*} \quad (13)

    Parameters
    ----------
    contact_radius : float or array_like
        The fixed contact radius ``a`` (m).
    amplitude : float or array_like
        The amplitude ``X`` (m) of the tangential motion, ``X > ū``.
    contact : Contact or Parameters
        The paper's paraboloid (4) under the law (13) (its ``τ0`` and ``G*``): a :class:`~mdr_events.Contact`, or
        a :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The energy dissipated per cycle ``W`` (J): 0 where ``X <= ū`` (the loop sticks).
    """
    contact_radius, amplitude = _finite(contact_radius=contact_radius, amplitude=amplitude)
    params = paper_parameters(contact, "fretting_dissipated_energy")
    relation = _rel("fretting_dissipated_energy").numeric
    energy = representable_result(lambda: relation(contact_radius, amplitude, params.tau0, params.G_star),
                                  "fretting_dissipated_energy", contact_radius=contact_radius, amplitude=amplitude)
    # (a loop within the critical shift, X <= ū, sticks: none dissipated; the parallelogram's formula gave a negative
    # energy there, issue 32 round 28 A5)
    if np.ndim(energy) == 0:  # (its type as the relation gave it)
        return energy if energy >= 0.0 else type(energy)(0.0)
    return np.maximum(energy, 0.0)

