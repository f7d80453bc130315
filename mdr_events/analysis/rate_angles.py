r"""The critical angle of scenario A against the path's speed, under rate-dependent adhesion.

In scenario A (14) every spring in contact attached while the indenter moved at the angle α; the first one, at the
centre, carries the largest shift ``x(t)``, while ``τ0``'s cap ``ū = K a(t)`` (13) is the same for all. Slip begins
where ``x = K a``: with ``x = d cot α``, at ``d_max`` exactly when

.. math:: \tan\alpha_c\, K\, a(d_\mathrm{max}) = d_\mathrm{max} \qquad (17), (18)

as in the paper, but with the radius the rate-dependent edge reaches at ``d_max``
(:func:`~mdr_events.models.continuum.solve_edge`: the normal problem, which sees the depth only, ``ḋ = v sin α``).
The advancing edge's work ``Δγ0 / [1 + (ȧ/v_ref)^n]`` falls with its speed, so a faster path reaches a smaller
radius, and the angle rises from the adhesive value (18) (``v → 0``, or ``v_ref → ∞``: the paper) towards the
non-adhesive one (17) (the edge's work → 0). The angle solves one equation in α (Brent's method), each evaluation a
solve of the way in at the vertical speed ``v sin α``.

Scenario B's angle is not defined this way at a finite ``v_ref``: the paper's contact jumps off at a finite radius
before its springs slide (eq. (21) at the jump-off), while a rate-dependent edge comes apart over a finite time in
which its radius, and with it the cap ``K a``, falls to 0 while the indenter's shift does not: the exact springs slide
in the last instants at every angle, the discrete ones (which let go within one time step) at none. An angle needs a
criterion for when the contact has let go (left open).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import xarray as xr
from scipy import optimize

from mdr_events.contact.adhesion import RateDependentAdhesion, check_rate_law
from mdr_events.models.continuum.rate_edge import EDGE_RTOL, solve_edge
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law
from mdr_events.validation import check_real, shown

__all__ = ["critical_angle_at_speed", "critical_angles_at_speeds", "ANGLE_XTOL"]

#: Brent's tolerance on the angle (rad): the radius at ``d_max`` is known to about 1e-9 of itself (the edge's ODE at
#: its ``rtol``), which moves the angle by about as much; 1e-12 rad lies below it.
ANGLE_XTOL = 1e-12
#: The bracket of the angle (rad): a path at 1e-6 rad from the surface or the vertical (its ``v sin α`` or
#: ``cot α`` at the ends of the double range of a path's clock).
_BRACKET = (1e-6, 0.5 * math.pi - 1e-6)


def _radius_at_depth(params: Parameters, law: RateDependentAdhesion, speed: float, alpha: float,
                     profile: SimulatedProfile, rtol: float) -> float:
    """The radius the edge reaches at ``d_max`` on the way in at the angle ``alpha`` (rad) and ``speed``."""
    path = Path(np.array([(0.0, 0.0), (params.d_max / math.tan(alpha), params.d_max)]), speed=speed)
    return float(solve_edge(params, path, law, profile=profile, rtol=rtol).radius(np.array([path.duration]))[0])


def critical_angle_at_speed(params: Parameters, law: RateDependentAdhesion, speed: float,
                            profile: SimulatedProfile = None, rtol: float = EDGE_RTOL) -> float:
    r"""The critical angle of scenario A (degrees) at the path's ``speed`` under the rate-dependent ``law``.

    .. math:: \tan\alpha_c\, \frac{\pi \tau_0}{2 G^*}\, a(d_\mathrm{max};\ v \sin\alpha_c) = d_\mathrm{max}
              \qquad (13), (17), (18)

    Parameters
    ----------
    params : Parameters
        The material, ``τ0``, ``d_max`` and ``R`` (the paraboloid's); its works of adhesion are the law's at rest.
    law : RateDependentAdhesion
        The adhesion law.
    speed : float
        The path's speed ``v`` (m/s), finite and > 0.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    rtol : float, optional
        The edge's ODE tolerance (:func:`~mdr_events.models.continuum.solve_edge`).

    Returns
    -------
    float
        ``α_c`` in degrees: below it the springs slide before ``d_max`` (90 where ``τ0 = 0``: slip from the start).

    Raises
    ------
    ValueError
        A ``speed`` that is not a finite number > 0, or what :func:`~mdr_events.models.continuum.solve_edge` refuses.
    """
    law = check_rate_law(law)
    speed = check_real("speed", speed, "a finite number > 0 (m/s)", lambda value: value > 0.0)
    if not isinstance(params, Parameters):
        raise TypeError(f"params={shown(params)} ({type(params).__name__}) is not allowed; allowed: a Parameters")
    cap = power_law.cap_per_radius(params)
    if cap == 0.0:
        return 90.0

    def margin(alpha: float) -> float:  # K a tan α − d_max over d_max: < 0 slides before d_max
        radius = _radius_at_depth(params, law, speed, alpha, profile, rtol)
        return cap * radius * math.tan(alpha) / params.d_max - 1.0

    return math.degrees(optimize.brentq(margin, *_BRACKET, xtol=ANGLE_XTOL))


def critical_angles_at_speeds(params: Parameters, law: RateDependentAdhesion, speeds: Sequence[float],
                              profile: SimulatedProfile = None) -> xr.Dataset:
    """:func:`critical_angle_at_speed` at each of ``speeds``, labelled, with the rate-independent limits.

    Parameters
    ----------
    params : Parameters
        The material, ``τ0``, ``d_max`` and ``R``; its works of adhesion are the law's at rest.
    law : RateDependentAdhesion
        The adhesion law.
    speeds : sequence of float
        The paths' speeds (m/s).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).

    Returns
    -------
    xarray.Dataset
        ``critical_angle`` (degree) and ``contact_radius`` (m, at ``d_max`` on the way in at that angle) against
        ``speed``; the attributes ``critical_angle_adhesive`` (the paper's (18), the limit ``v → 0``) and
        ``critical_angle_hertz`` ((17), the edge's work → 0) where the paraboloid has them, and the law's values.

    Raises
    ------
    ValueError
        A speed that is not a finite number > 0, or what :func:`critical_angle_at_speed` refuses.
    """
    speeds = [check_real(f"speeds[{index}]", value, "a finite number > 0 (m/s)", lambda v: v > 0.0)
              for index, value in enumerate(np.atleast_1d(np.asarray(speeds, dtype=object)).tolist())]
    angles = np.array([critical_angle_at_speed(params, law, speed, profile) for speed in speeds])
    radii = np.array([_radius_at_depth(params, law, speed, math.radians(angle), profile, EDGE_RTOL)
                      if angle < 90.0 else math.nan for speed, angle in zip(speeds, angles)])
    dataset = xr.Dataset(
        {"critical_angle": ("speed", angles, {"units": "degree", "long_name": "critical angle of scenario A"}),
         "contact_radius": ("speed", radii, {"units": "m", "long_name": "contact radius at d_max at that angle"})},
        coords={"speed": ("speed", np.array(speeds), {"units": "m s-1", "long_name": "the path's speed"})})
    dataset.attrs.update(scenario="A", adhesion_law="rate_dependent", v_ref=law.v_ref, n=law.n,
                         dgamma0=law.dgamma0, dgamma1=law.dgamma1)
    if profile is None:
        from mdr_events.theory.analytic import critical_angle  # (the paraboloid's closed forms)
        dataset.attrs.update(critical_angle_adhesive=critical_angle(params, "A", adhesion=True),
                             critical_angle_hertz=critical_angle(params, "A", adhesion=False))
    return dataset
