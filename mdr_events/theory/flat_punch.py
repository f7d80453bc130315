"""Closed forms of the flat punch of radius ``a`` (:class:`~mdr_events.contact.indenters.FlatPunch`), vectorised.

Every spring under the punch's face has ``g = 0``: the contact is the whole face from the first touch (``d >= 0``)
on, and the springs reach Heß's limit (8) together, at Kendall's depth ``−sqrt(2π a Δγ/E*)``, where the punch comes
off whole with Kendall's force ``−sqrt(8π a³ E* Δγ)`` (Kendall, J. Phys. D 4 (1971) 1186). Under the paper's friction
law ``τ0`` every spring anchored at one ``x`` reaches its cap ``ū = K a`` (13) together: the slip onset is full slip.
The relations are derived in :mod:`mdr_events.theory.symbolic` (``flat_punch_*``).

:mod:`mdr_events.theory.power_law`'s functions of either indenter hand a flat punch to these
(:data:`CLOSED_FORMS`, filed by :func:`mdr_events.theory.kinds.theory_of`); the material, the friction and the
works of adhesion come from :class:`~mdr_events.Parameters` (its ``R`` is the paraboloid's and is not used).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.indenters import FlatPunch
from mdr_events.parameters import Parameters
from mdr_events.theory import symbolic
from mdr_events.theory.power_law import ClosedForms, as_output, cap_per_radius, check_work, path_angles
from mdr_events.validation import check_flag

__all__ = ["normal_force", "jump_off", "radius", "pull_off_force", "d_crit_A", "critical_angle_A", "d_crit_B",
           "critical_angle_B", "d_crit_B_indentation", "critical_angle_B_indentation", "CLOSED_FORMS"]


def _rel(key: str):
    return symbolic.relation(key)


def _punch(profile, what: str) -> FlatPunch:
    """``profile`` if it is a :class:`FlatPunch`; else ``TypeError`` naming it and ``what`` took it."""
    if not isinstance(profile, FlatPunch):
        raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed for {what}; allowed: a "
                        "FlatPunch (mdr_events.contact.indenters)")
    return profile


def normal_force(depth, contact_radius, profile: FlatPunch, params: Parameters):
    r"""Normal force (N) of the punch at depth ``d``, ``2 E* a d`` (10) with its own radius ``a``.

    .. math:: F_N = 2 E^* a d \qquad (10)

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    contact_radius : float, array_like or None
        ``None`` or the punch's radius (m).
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.

    Returns
    -------
    float or numpy.ndarray
        ``F_N`` (N; negative: tensile).

    Raises
    ------
    ValueError
        A ``contact_radius`` other than the punch's own.
    """
    profile = _punch(profile, "normal_force")
    if contact_radius is not None and not np.all(np.asarray(contact_radius) == profile.radius):
        raise ValueError(f"contact_radius={contact_radius!r} is not allowed for {profile!r}; allowed: None or "
                         f"the punch's radius {profile.radius!r} m")
    return _rel("flat_punch_normal_force").numeric(depth, profile.radius, params.E_star)


def jump_off(profile: FlatPunch, params: Parameters, work_of_adhesion: float) -> dict[str, float]:
    """The end of contact, under displacement control as under force control: the punch's radius at the depth where
    every spring reaches Heß's limit (8) at once, with Kendall's force ``−sqrt(8π a³ E* Δγ)``.

    Parameters
    ----------
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.

    Returns
    -------
    dict of str to float
        ``contact_radius`` (m, the punch's), ``depth`` (m; 0 without adhesion) and ``normal_force`` (N) there.
    """
    work_of_adhesion = check_work(work_of_adhesion)
    profile = _punch(profile, "jump_off")
    args = (profile.radius, params.E_star, work_of_adhesion)
    return {"contact_radius": profile.radius,
            "depth": float(_rel("flat_punch_pull_off_depth").numeric(*args)),
            "normal_force": float(_rel("flat_punch_pull_off_force").numeric(*args))}


def radius(depth, profile: FlatPunch, params: Parameters, work_of_adhesion: float, fold_share: float = 0.0):
    """The punch's contact radius at ``depth``: its own radius down to the jump-off depth (``fold_share`` of it
    below still holds), ``nan`` below.

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.
    fold_share : float, default 0.0
        The share of the jump-off depth below it at which the contact still holds (a tolerance of rounding).

    Returns
    -------
    float or numpy.ndarray
        The punch's radius (m), or ``nan`` where the contact has come apart; the shape of ``depth``.
    """
    bottom = jump_off(profile, params, work_of_adhesion)["depth"] * (1.0 + fold_share)
    depth = np.asarray(depth, dtype=float)
    return as_output(np.where(depth >= bottom, profile.radius, np.nan), depth)


def pull_off_force(profile: FlatPunch, params: Parameters, work_of_adhesion: float) -> float:
    """The pull-off force (N, <= 0), Kendall's ``−sqrt(8π a³ E* Δγ)``, the same under force and displacement control.

    Parameters
    ----------
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.

    Returns
    -------
    float
        The pull-off force (N, <= 0; 0 without adhesion).
    """
    return jump_off(profile, params, work_of_adhesion)["normal_force"]


def d_crit_A(alpha, profile: FlatPunch, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario A (the path (14) from first contact at angle ``α`` in degrees): every spring
    attaches at first contact at one ``x`` and all reach ``ū = K a`` together, ``d = tan α K a`` (onset is full slip),
    with or without adhesion; ``α = 90°`` never slides (``+inf``).

    .. math:: \frac{d}{\tan\alpha} = \bar u(a) = \frac{\pi a \tau_0}{2 G^*} \qquad (17)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``G*``, ``τ0``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        Whether the contact is adhesive (the onset is the same).

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``+inf`` at 90°.
    """
    profile = _punch(profile, "d_crit_A")
    alpha_arr, vertical = path_angles(alpha, adhesion)
    tan_alpha = np.tan(np.deg2rad(np.where(vertical, 45.0, alpha_arr)))
    depth = np.asarray(_rel("flat_punch_d_crit_A").numeric(profile.radius, tan_alpha, params.tau0, params.G_star),
                       dtype=float)
    return as_output(np.where(vertical, np.inf, depth), alpha_arr)


def critical_angle_A(profile: FlatPunch, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario A's critical angle (degrees): slip begins exactly at ``d_max``, ``tan α_c = d_max / (K a)`` with the
    punch's radius ``a``, with or without adhesion.

    .. math:: \tan\alpha_c = \frac{2 G^* d_\mathrm{max}}{\pi a \tau_0} \qquad (17)

    Parameters
    ----------
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``G*``, ``τ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        Whether the contact is adhesive (the angle is the same).

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    profile = _punch(profile, "critical_angle_A")
    check_flag("adhesion", adhesion)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_A").numeric(profile.radius, params.d_max, params.tau0, params.G_star)
    return float(np.rad2deg(angle))


def d_crit_B(alpha, profile: FlatPunch, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario B's pull-off (the path (19)): every spring was anchored at ``x = 0``; all
    slide when ``x = K a``, ``d = d_max − tan α K a``, unless that lies below Kendall's pull-off depth (``-inf``: it
    comes off whole first; at the surface without adhesion); ``α = 90°`` never slides (``-inf``).

    .. math:: \frac{d_\mathrm{max} - d}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*} \qquad (20)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ1``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: Kendall's depth of ``Δγ1``; without: the surface.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``-inf`` where the contact comes apart first.
    """
    profile = _punch(profile, "d_crit_B")
    alpha_arr, vertical = path_angles(alpha, adhesion)
    depth = params.d_max - np.tan(np.deg2rad(alpha_arr)) * cap_per_radius(params) * profile.radius
    apart = depth < jump_off(profile, params, params.dgamma1 if adhesion else 0.0)["depth"]
    return as_output(np.where(vertical | apart, -np.inf, depth), alpha_arr)


def critical_angle_B(profile: FlatPunch, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario B's critical angle (degrees): above it the punch comes off whole, at Kendall's depth ``d_j`` (at the
    surface without adhesion), before any spring slides, ``tan α_c = (d_max − d_j) / (K a)`` ((21) there).

    .. math:: \tan\alpha_c = \frac{2 G^* (d_\mathrm{max} - d_j)}{\pi a \tau_0} \qquad (21)

    Parameters
    ----------
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ1``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: Kendall's depth of ``Δγ1``; without: the surface.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    profile = _punch(profile, "critical_angle_B")
    check_flag("adhesion", adhesion)
    point = jump_off(profile, params, params.dgamma1 if adhesion else 0.0)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B").numeric(point["contact_radius"], point["depth"], params.d_max, params.tau0,
                                                 params.G_star)
    return float(np.rad2deg(angle))


def d_crit_B_indentation(alpha, profile: FlatPunch, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset on scenario B's indentation branch (the "+" sign of (20); the path
    :meth:`~mdr_events.Path.scenario_B_indentation`): every spring anchored at ``x = 0``, all slide at
    ``d = d_max + tan α K a``, with or without adhesion; ``α = 90°`` never slides (``+inf``).

    .. math:: \frac{d - d_\mathrm{max}}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*} \qquad (20)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``G*``, ``τ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        Whether the contact is adhesive (the onset is the same).

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``+inf`` at 90°.
    """
    profile = _punch(profile, "d_crit_B_indentation")
    alpha_arr, vertical = path_angles(alpha, adhesion)
    slope = np.where(vertical, 0.0, np.tan(np.deg2rad(alpha_arr))) * cap_per_radius(params)
    return as_output(np.where(vertical, np.inf, params.d_max + slope * profile.radius), alpha_arr)


def critical_angle_B_indentation(profile: FlatPunch, params: Parameters, adhesion: bool = True,
                                 final_depth: float | None = None) -> float:
    r"""The "+" branch's critical angle (degrees): slip begins exactly at ``final_depth`` (default ``2 d_max``),
    ``tan α_c = (final − d_max) / (K a)`` with the punch's radius ``a``, with or without adhesion.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{final} - d_\mathrm{max}}{\bar u(a)} \qquad (21)

    Parameters
    ----------
    profile : FlatPunch
        The punch.
    params : Parameters
        The material (``G*``, ``τ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        Whether the contact is adhesive (the angle is the same).
    final_depth : float, optional
        The deepest point (m), > ``d_max``; default ``2 d_max``.

    Returns
    -------
    float
        ``α_c`` in degrees.

    Raises
    ------
    ValueError
        A ``final_depth`` not beyond ``d_max``.
    """
    profile = _punch(profile, "critical_angle_B_indentation")
    check_flag("adhesion", adhesion)
    final = 2.0 * params.d_max if final_depth is None else final_depth
    if not (isinstance(final, (int, float)) and math.isfinite(final) and final > params.d_max):
        raise ValueError(f"final_depth={final!r} is not allowed; allowed: a finite depth > d_max = {params.d_max!r} m")
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B_indentation").numeric(profile.radius, final, params.d_max, params.tau0,
                                                             params.G_star)
    return float(np.rad2deg(angle))


#: The flat punch's closed forms behind :mod:`mdr_events.theory.power_law`'s functions of either indenter.
CLOSED_FORMS = ClosedForms(normal_force=normal_force, jump_off=jump_off, pull_off_force=pull_off_force,
                           d_crit_A=d_crit_A, critical_angle_A=critical_angle_A, d_crit_B=d_crit_B,
                           critical_angle_B=critical_angle_B, d_crit_B_indentation=d_crit_B_indentation,
                           critical_angle_B_indentation=critical_angle_B_indentation)
