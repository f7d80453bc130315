"""The pull-off of a paraboloid or power law on a layer under force control: the minimum of the branch force.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.branch_slopes import flat_least, force_slope
from mdr_events.theory.layer.checks import checked_relation
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.relations import _abel_factor, _power_law, _relative, branch_depth, branch_normal_force
from mdr_events.validation import check_real

__all__ = ["PullOff", "pull_off"]


@dataclass(frozen=True)
class PullOff:
    """The pull-off under force control: the minimum of the branch force (:func:`pull_off`).

    Parameters
    ----------
    radius : float
        The contact radius at pull-off in m.
    depth : float
        The depth there in m.
    force : float
        The pull-off force in N (negative: tensile).
    relative_radius : float
        ``a/h`` at pull-off (0 on the half-space).
    """

    radius: float
    depth: float
    force: float
    relative_radius: float


#: Points of the scan of the branch force for its minimum, over ``a₀ · 10^[-3, 3]`` (``a₀`` the half-space's
#: pull-off radius), before the root of its slope (:func:`~.branch_slopes.flat_least`).
_SCAN_POINTS = 241


@checked_relation
def pull_off(profile, E_star: float, nu: float, dgamma: float, layer: Layer) -> PullOff:
    r"""The pull-off under force control on the layer: the minimum of :func:`branch_normal_force` over ``a``.

    .. math:: F_\mathrm{po} = \min_a\,[F_0(a) - K(a)\,\Delta l(a)] \qquad (10)

    (``−(3/2) π Δγ R`` for the paraboloid on the half-space). The branch is scanned on a logarithmic grid around the
    half-space's pull-off radius ``a₀`` (``a^(2n−1) = 9Δγ/(2E* n² κₙ² c²)``) and its minimum placed at the root of
    the force's slope in ``ln a`` (:func:`~.branch_slopes.flat_least`).

    Parameters
    ----------
    profile : Paraboloid or PowerLaw
        The indenter.
    E_star : float
        ``E*`` in Pa.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    dgamma : float
        The work of adhesion in J/m², > 0.
    layer : Layer
        The layer.

    Returns
    -------
    PullOff
        Radius, depth, force and ``a/h`` at pull-off.

    Raises
    ------
    TypeError
        ``profile`` not a paraboloid or power law.
    ValueError
        ``dgamma`` not > 0, or the minimum beyond the table (``a/h > LAMBDA_MAX``).
    """
    dgamma = check_real("dgamma", dgamma, "a finite number > 0 (J/m²)", lambda value: value > 0.0)
    c, n = _power_law(profile)
    a0 = (9.0 * dgamma / (2.0 * E_star * n**2 * _abel_factor(n) ** 2 * c**2)) ** (1.0 / (2.0 * n - 1.0))
    logs = np.linspace(math.log(a0) - 3.0 * math.log(10.0), math.log(a0) + 3.0 * math.log(10.0), _SCAN_POINTS)
    if not layer.is_half_space:
        logs = logs[logs <= math.log(LAMBDA_MAX * layer.thickness)]

    def force(log_radius):
        return branch_normal_force(np.exp(log_radius), profile, E_star, nu, dgamma, layer)

    best = int(np.argmin(force(logs))) if logs.size >= 3 else 0  # (a layer so thin that no scan point fits on it)
    if best in (0, len(logs) - 1):
        raise ValueError(f"the pull-off radius lies beyond a/h = {LAMBDA_MAX:g} or outside a0·10^±3 (a0 = {a0:.6g} m "
                         f"on the half-space); allowed: a layer with h > {a0 / LAMBDA_MAX:.3g} m or so")
    least, at = flat_least(lambda value: float(force(value)),
                           lambda value: force_slope(math.exp(value), profile, E_star, nu, dgamma, layer), logs, best)
    radius = float(np.exp(at))
    return PullOff(radius, float(branch_depth(radius, profile, E_star, nu, dgamma, layer)), least,
                   float(_relative(radius, layer)))
