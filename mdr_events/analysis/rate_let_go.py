r"""The critical angle of scenario B against the path's speed, under rate-dependent adhesion.

In scenario B (19) every spring attached on the vertical way in, with its anchor at ``x = 0``; on the way out at the
angle α the shift ``x = (d_max − d) cot α`` grows while ``τ0``'s cap ``K a`` (13), the same for all, can only stay or
shrink, so all the springs slide together the first time ``x = K a``. The paper's contact jumps off at a finite radius
(the turning point of the ``Δγ1`` branch), and its critical angle (21) is the one at which they slide exactly there. A
rate-dependent edge has no jump: its radius falls to 0 over a finite time in which ``K a`` vanishes while ``x`` does
not, so the springs slide in the collapse's last instants at every angle. What separates the angles is whether they
slide before the contact *lets go* (:func:`~mdr_events.models.continuum.edge_let_go.let_go`: the edge's release rate rising
as it shrinks, ``d <= g(a) − 2a g'(a)``, after which it collapses whatever the path does): the critical angle solves

.. math:: \tan\alpha_c\, K\, a_u = d_\mathrm{max} - d_u \qquad (13), (21)

with ``(a_u, d_u)`` the let-go of the edge on the way out at ``α_c`` (vertical speed ``v sin α_c``). As
``v_ref → ∞`` the let-go is the branch's turning point and this is the paper's (21). Below ``α_c`` the springs slide
before the contact lets go, above it they let go sticking. One equation in α (Brent's method, as scenario A's angle
in :mod:`~mdr_events.analysis.rate_angles`), each evaluation a solve of the edge along the path.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import xarray as xr
from scipy import optimize

from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.model import Contact
from mdr_events.limits import Limits
from mdr_events.models.continuum.edge_let_go import LetGo, let_go
from mdr_events.models.continuum.rate_edge import EDGE_RTOL, solve_edge
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path, exit_depth
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law

from .rate_angles import (_BRACKET, ANGLE_XTOL, CRITICAL_ANGLE_SOLVES, RATE_ANGLES_CONTENT, _check_solves, _checked, _job,
                          _law_attrs)

__all__ = ["let_go_B_at_speed", "critical_angle_B_at_speed", "critical_angles_B_at_speeds"]

#: The way out reaches the exit depth below the paper's jump-off first, and twice as deep each time the edge had not
#: let go on it, at most this many times.
_MAX_DOUBLINGS = 20


def _path_B(params: Parameters, alpha: float, speed: float, end: float) -> Path:
    """Vertically in to ``d_max``, out at ``alpha`` (rad) to the depth ``end`` (< 0), at ``speed``."""
    out = 0.0 if alpha >= 0.5 * math.pi else (params.d_max - end) / math.tan(alpha)
    return Path(np.array([(0.0, 0.0), (0.0, params.d_max), (out, end)]), speed=speed)


def _let_go(params: Parameters, law: RateDependentAdhesion, speed: float, alpha: float, profile: SimulatedProfile,
            rtol: float, method: str) -> tuple[LetGo, Path]:
    """The let-go on the way out at ``alpha`` (rad), the way out deepened until the edge lets go on it."""
    end = exit_depth(params, profile)
    for _ in range(_MAX_DOUBLINGS):
        path = _path_B(params, alpha, speed, end)
        found = let_go(solve_edge(params, path, law, profile=profile, rtol=rtol, method=method), path, params, profile)
        if found is not None:
            return found, path
        end *= 2.0
    raise ValueError(f"law={law!r} at speed={speed!r} m/s: the edge did not let go on the way out to {end!r} m; "
                     "allowed: a law whose receding edge lets go within 2^20 times the exit depth")


def let_go_B_at_speed(params: Parameters, law: RateDependentAdhesion, speed: float, alpha: float,
                      profile: SimulatedProfile = None, rtol: float = EDGE_RTOL, method: str = "Radau") -> LetGo:
    """Where the contact of scenario B at the angle ``alpha`` and the path's ``speed`` lets go (module docstring).

    Parameters
    ----------
    params : Parameters
        The material, ``d_max`` and ``R`` (the paraboloid's); its works of adhesion are the law's at rest.
    law : RateDependentAdhesion
        The adhesion law.
    speed : float
        The path's speed ``v`` (m/s), finite and > 0.
    alpha : float
        The angle of the way out (degrees), in (0, 90].
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    rtol : float, optional
        The edge's ODE tolerance.
    method : str, optional
        The edge's ``solve_ivp`` method.

    Returns
    -------
    LetGo
        The time (s on the path's clock: vertically in to ``d_max`` at ``speed``, then out at ``alpha``), depth and
        radius at which the edge lets go.

    Raises
    ------
    ValueError
        A ``speed`` or ``alpha`` out of range, or what :func:`~mdr_events.models.continuum.solve_edge` refuses.
    """
    from mdr_events.validation import check_real

    law, speed = _checked(params, law, speed, profile)
    alpha = check_real("alpha", alpha, "a number of degrees in (0, 90]", lambda value: 0.0 < value <= 90.0)
    return _let_go(params, law, speed, math.radians(alpha), profile, rtol, method)[0]


def critical_angle_B_at_speed(params: Parameters, law: RateDependentAdhesion, speed: float,
                              profile: SimulatedProfile = None, rtol: float = EDGE_RTOL,
                              method: str = "Radau") -> float:
    r"""The critical angle of scenario B (degrees) at the path's ``speed`` under the rate-dependent ``law``.

    .. math:: \tan\alpha_c\, \frac{\pi \tau_0}{2 G^*}\, a_u = d_\mathrm{max} - d_u \qquad (13), (21)

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
        The edge's ODE tolerance.
    method : str, optional
        The edge's ``solve_ivp`` method (Radau, the reference, or LSODA).

    Returns
    -------
    float
        ``α_c`` in degrees: below it the springs slide before the contact lets go (90 where ``τ0 = 0``).

    Raises
    ------
    ValueError
        A ``speed`` out of range, a critical angle outside ``[1e-6 rad, 90° − 1e-6 rad]``, or what
        :func:`~mdr_events.models.continuum.solve_edge` refuses.
    """
    law, speed = _checked(params, law, speed, profile)
    cap = power_law.cap_per_radius(params)
    if cap == 0.0:
        return 90.0

    def margin(alpha: float) -> float:  # (tan α K a_u − (d_max − d_u)) / d_max: < 0 slides before the let-go
        point, _ = _let_go(params, law, speed, alpha, profile, rtol, method)
        return (math.tan(alpha) * cap * point.radius - (params.d_max - point.depth)) / params.d_max

    return math.degrees(_root(margin, _low_angle(params, profile, cap), speed))


def _low_angle(params: Parameters, profile: SimulatedProfile, cap: float) -> float:
    """An angle (rad) below the critical one without a solve: the let-go radius is below the ``Δγ0`` branch's at
    ``d_max`` (an advancing edge's work is below ``Δγ0``, and the way out only shrinks it), so at
    ``tan α = d_max / (K a0(d_max))`` the springs slide before the let-go wherever it lies below the surface."""
    from mdr_events.models.indenters import branch_radius

    reach = float(branch_radius(params.d_max, params, params.dgamma0, profile))
    return max(math.atan(params.d_max / (cap * reach)) if reach > 0.0 else _BRACKET[0], _BRACKET[0])


def _root(margin, low: float, speed: float) -> float:
    """The angle (rad) in ``[low, 90° − 1e-6 rad]`` where ``margin`` changes sign (Brent's method); ``low`` lowered
    (its tangent halved) while the springs do not slide before the let-go there (a let-go above the surface)."""
    what = f"the critical angle of scenario B at speed={speed!r} m/s"
    high = _BRACKET[1]
    top = margin(high)
    if top < 0.0:
        raise ValueError(f"{what}: the springs slide before the let-go at every angle up to 90° - 1e-6 rad; allowed: "
                         "parameters, law and speed whose critical angle lies below it")
    for _ in range(_MAX_DOUBLINGS):
        bottom = margin(low)
        if bottom < 0.0:
            return optimize.brentq(margin, low, high, xtol=ANGLE_XTOL)
        if low <= _BRACKET[0]:
            break
        low = max(math.atan(0.5 * math.tan(low)), _BRACKET[0])
    raise ValueError(f"{what}: no spring slides before the let-go at any angle down to {low!r} rad; allowed: "
                     "parameters, law and speed whose critical angle lies above it")


def critical_angles_B_at_speeds(contact: Contact | Parameters, speeds: Sequence[float] | None = None, *old: Any,
                                law: RateDependentAdhesion | None = None, profile: SimulatedProfile = None,
                                method: str = "Radau", limits: Limits | None = None, d_max: float | None = None) -> xr.Dataset:
    """:func:`critical_angle_B_at_speed` at each of ``speeds``, labelled, with the paper's (21) where it has it.

    Parameters
    ----------
    contact : Contact or Parameters
        A :class:`~mdr_events.Contact` whose adhesion is a :class:`~mdr_events.RateDependentAdhesion`, its friction law
        ``"tau0"``, on the half-space (:func:`~mdr_events.analysis.rate_job.rate_job`). Or the form of before:
        :class:`~mdr_events.Parameters` (the material, ``τ0``, ``d_max``, ``R``; its works of adhesion the law's at
        rest), called ``critical_angles_B_at_speeds(params, law, speeds[, profile, method, limits])``.
    speeds : sequence of float
        The paths' speeds (m/s); in the form of before, by position, the law (the speeds after it).
    *old
        Only in the form of before: the speeds, then ``profile``, ``method``, ``limits`` by position.
    law : RateDependentAdhesion, optional
        Only beside Parameters (a contact holds its own).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        Only beside Parameters: the indenter (``None``: the paraboloid of ``params.R``).
    method : str, optional
        The edge's ``solve_ivp`` method.
    limits : Limits or None, optional
        The solves of the edge allowed (as :func:`~mdr_events.analysis.rate_angles.critical_angles_at_speeds`),
        checked before the first.
    d_max : float, optional
        Only beside a Contact: the depth of the scenario (m, finite, > 0; default the paper's 0.3 mm).

    Returns
    -------
    xarray.Dataset
        ``critical_angle`` (degree) and ``let_go_radius`` (m, at that angle) against ``speed``; the attribute
        ``critical_angle_paper`` ((21), the limit ``v → 0``) for the paraboloid, and the law's values.

    Raises
    ------
    ValueError
        A speed that is not a finite number > 0, or what :func:`critical_angle_B_at_speed` refuses.
    """
    params, law, profile, speeds, method, limits = _job(contact, speeds, old, law, profile, d_max, method, limits,
                                                        "critical_angles_B_at_speeds")
    angles = np.array([critical_angle_B_at_speed(params, law, speed, profile, EDGE_RTOL, method) for speed in speeds])
    radii = np.array([_let_go(params, law, speed, math.radians(angle), profile, EDGE_RTOL, method)[0].radius
                      if angle < 90.0 else math.nan for speed, angle in zip(speeds, angles)])
    dataset = xr.Dataset(
        {"critical_angle": ("speed", angles, {"units": "degree", "long_name": "critical angle of scenario B"}),
         "let_go_radius": ("speed", radii, {"units": "m", "long_name": "contact radius where the edge lets go"})},
        coords={"speed": ("speed", np.array(speeds), {"units": "m s-1", "long_name": "the path's speed"})})
    dataset.attrs.update(_law_attrs(law), scenario="B", edge_method=method, content=RATE_ANGLES_CONTENT)
    if profile is None:
        from mdr_events.theory.analytic import critical_angle  # (the paraboloid's closed forms)
        dataset.attrs.update(critical_angle_paper=critical_angle(params, "B", adhesion=True))
    return dataset
