"""The model's dimensionless groups: the slip parameter ``S`` and the adhesion parameters ``Γ0``, ``Γ1``.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from mdr_events.theory.job import ContactLike, paper_parameters

__all__ = ["DimensionlessGroups", "dimensionless_groups"]


class DimensionlessGroups(NamedTuple):
    r"""The three numbers the model's dimensionless results depend on (:func:`dimensionless_groups`).

    Parameters
    ----------
    slip : float
        The slip parameter :math:`S = \pi \tau_0 \sqrt{R} / (2 G^* \sqrt{d_\mathrm{max}})`.
    adhesion_in : float
        The adhesion parameter of the way in,
        :math:`\Gamma_0 = 2 \pi \Delta\gamma_0 \sqrt{R} / (E^* d_\mathrm{max}^{3/2})`.
    adhesion_out : float
        The adhesion parameter of the way out,
        :math:`\Gamma_1 = 2 \pi \Delta\gamma_1 \sqrt{R} / (E^* d_\mathrm{max}^{3/2})`.
    """

    slip: float  #: S = π τ0 √R / (2 G* √d_max)
    adhesion_in: float  #: Γ0 = 2π Δγ0 √R / (E* d_max^(3/2))
    adhesion_out: float  #: Γ1 = 2π Δγ1 √R / (E* d_max^(3/2))


def dimensionless_groups(contact: ContactLike, *, d_max: float | None = None) -> DimensionlessGroups:
    r"""The slip parameter and the two adhesion parameters of the model.

    Measure depths in ``d_max`` (``d = d_max d̂``), radii in ``√(R d_max)`` (``a = √(R d_max) â``) and tangential
    lengths in ``d_max`` (the paths (14), (19) move ``x = d / tan α``). Then the branch (9) reads
    ``d̂ = â² − √(Γ â)`` with ``Γ = 2π Δγ √R / (E* d_max^(3/2))``, one per work of adhesion, and the cap (13)
    ``ū/d_max = S â`` with ``S = π τ0 √R / (2 G* √d_max)`` (the slip parameter ``k/(tan α √d_max)`` of (20)).
    The springs' forces scale as ``E* (R d_max)^(1/2) d_max`` (normal) and ``τ0 R d_max`` (tangential), so
    every angle, every depth over ``d_max`` and every ratio such as ``F_x / (π a² τ0)`` depends on
    ``(S, Γ0, Γ1)`` and the path's angle alone: two parameter sets with the same groups have the same
    critical angles (17), (18), (21).

    ``contact``: a :class:`~mdr_events.Contact` of the paraboloid under the law (13) with the depth ``d_max`` (m;
    default the paper's 0.3 mm), or a :class:`~mdr_events.Parameters` (its own ``d_max``).

    .. math:: S = \frac{\pi \tau_0 \sqrt{R}}{2 G^* \sqrt{d_\mathrm{max}}}, \qquad
              \Gamma_{0,1} = \frac{2 \pi \Delta\gamma_{0,1} \sqrt{R}}{E^* d_\mathrm{max}^{3/2}}

    Parameters
    ----------
    contact : Contact or Parameters
        A :class:`~mdr_events.Contact` of the paraboloid under the law (13), or a :class:`~mdr_events.Parameters`
        (its own ``d_max``).
    d_max : float, optional
        With a Contact: the motion's depth (m; default the paper's 0.3 mm).

    Returns
    -------
    DimensionlessGroups
        ``(S, Γ0, Γ1)``.
    """
    params = paper_parameters(contact, "dimensionless_groups", d_max)
    root = math.sqrt(params.R)
    scale = params.E_star * params.d_max**1.5
    return DimensionlessGroups(math.pi * params.tau0 * root / (2.0 * params.G_star * math.sqrt(params.d_max)),
                               2.0 * math.pi * params.dgamma0 * root / scale,
                               2.0 * math.pi * params.dgamma1 * root / scale)

