"""Closed forms of the flat punch of radius ``a`` (:class:`~mdr_events.contact.indenters.FlatPunch`), vectorised.

Every spring under the punch's face has ``g = 0``: the contact is the whole face from the first touch (``d >= 0``)
on, and the springs reach Heß's limit (8) together, at Kendall's depth ``−sqrt(2π a Δγ/E*)``, where the punch comes
off whole with Kendall's force ``−sqrt(8π a³ E* Δγ)`` (Kendall, J. Phys. D 4 (1971) 1186). Under the paper's friction
law ``τ0`` every spring anchored at one ``x`` reaches its cap ``ū = K a`` (13) together: the slip onset is full slip;
under a cap ``K a + κ d`` with Coulomb's part (:mod:`mdr_events.theory.mindlin`) every spring is compressed by ``d``
alike, so the springs are one play operator (:func:`tangential_force`) and the onsets closed forms in ``d``. The
relations are derived in :mod:`mdr_events.theory.symbolic` (``flat_punch_*``).

:mod:`mdr_events.theory.power_law`'s functions of either indenter hand a flat punch to these (:data:`CLOSED_FORMS`),
:mod:`mdr_events.theory.mindlin`'s friction laws to its :data:`FRICTION_FORMS`, both filed by
:func:`mdr_events.theory.kinds.theory_of`; the material, the friction and the works of adhesion come from
:class:`~mdr_events.Parameters` (its ``R`` is the paraboloid's and is not used).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.contact.indenters import FlatPunch
from mdr_events.parameters import Parameters
from mdr_events.theory import symbolic
from mdr_events.theory.analytic.arguments import _finite
from mdr_events.theory.forms import ClosedForms, FrictionForms
from mdr_events.theory.power_law import as_output, cap_per_radius, check_work, final_depth_of, path_angles
from mdr_events.validation import check_flag, real_array

__all__ = ["normal_force", "jump_off", "radius", "pull_off_force", "d_crit_A", "critical_angle_A", "d_crit_B",
           "critical_angle_B", "d_crit_B_indentation", "critical_angle_B_indentation", "tangential_force",
           "coulomb_force", "capped_d_crit_B", "capped_d_crit_B_indentation", "capped_critical_angle_B_indentation",
           "CLOSED_FORMS", "FRICTION_FORMS"]


def _rel(key: str):
    return symbolic.relation(key)


def _punch(profile, what: str) -> FlatPunch:
    """``profile`` if it is a :class:`FlatPunch`; else ``TypeError`` naming it and ``what`` took it."""
    if not isinstance(profile, FlatPunch):
        raise TypeError(f"profile={profile!r} is not allowed for {what}; allowed: a FlatPunch")
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
    (depth,) = _finite(depth=depth)
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
    (depth,) = _finite(depth=depth)
    return _radius(depth, profile, params, work_of_adhesion, fold_share)


def _radius(depth, profile: FlatPunch, params: Parameters, work_of_adhesion: float, fold_share: float = 0.0):
    """:func:`radius` unchecked (the continuum's branch: its depths its own)."""
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
    final = final_depth_of(params, final_depth)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B_indentation").numeric(profile.radius, final, params.d_max, params.tau0,
                                                             params.G_star)
    return float(np.rad2deg(angle))


def tangential_force(x, depth, friction: FrictionLaw | str | None, params: Parameters, profile: FlatPunch):
    """The tangential force (N) of a flat punch in contact along the samples ``(x, depth)`` of a path, the springs at
    rest at the first sample (``flat_punch_friction_cap``, ``flat_punch_full_slip_force``).

    Every spring under the face has the cap ``ū = K a + κ max(d, 0)`` (``a`` the punch's radius; ``K a`` alone in
    tension, an adhesive punch held above the surface) and one anchor history: the springs are one play operator,
    ``F_x = 2G* a u`` with ``u_k = clip(u_{k−1} + x_k − x_{k−1}, −ū_k, ū_k)``. Between samples on a straight piece of
    the path, ``x`` and ``ū`` linear (``d`` not crossing 0), ``min_s (ū(s) − x(s))`` lies at an end, so each step is
    exact: the force is exact at samples that hold the path's corners and its crossings of ``d = 0``.

    Parameters
    ----------
    x, depth : array_like
        The indenter's tangential position and depth at successive instants (1-D, equal lengths, finite, m), the
        contact held throughout (no pull-off between them).
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material and ``τ0``.
    profile : FlatPunch
        The punch (its radius is the contact's).

    Returns
    -------
    numpy.ndarray
        ``F_x`` (N) at each sample, the shape of ``x``.
    """
    profile = _punch(profile, "flat_punch_force")
    friction = as_friction_law(friction)
    positions = real_array("x", x, "a 1-D array of finite tangential positions (m)")
    depths = real_array("depth", depth, "a 1-D array of finite depths (m), one per x")
    finite = np.all(np.isfinite(positions)) and np.all(np.isfinite(depths))
    if positions.ndim != 1 or depths.shape != positions.shape or not finite:
        raise ValueError(f"x of shape {positions.shape} and depth of shape {depths.shape} are not allowed; allowed: "
                         "1-D arrays of finite numbers of one length (m)")
    cap = symbolic.relation("flat_punch_friction_cap").numeric(depths, profile.radius, params.tau0 if friction.uses_tau0
                                                               else 0.0, friction.coulomb_mu, params.E_star,
                                                               params.G_star)
    caps = np.broadcast_to(np.asarray(cap, dtype=float), positions.shape)
    shift = np.empty_like(positions)
    u = 0.0
    for k in range(positions.size):
        step = positions[k] - positions[k - 1] if k else 0.0
        u = min(max(u + step, -caps[k]), caps[k])
        shift[k] = u
    return 2.0 * params.G_star * profile.radius * shift


def coulomb_force(sliding, params: Parameters, contact_radius: float):
    """Coulomb's part of the virgin curve at a constant depth (N): every spring is compressed by ``d`` alike, so those
    beyond ``K a`` all slide by ``sliding`` at once, ``2 G* a sliding`` (``F_N`` is linear in the depth).

    Parameters
    ----------
    sliding : float or numpy.ndarray
        The shift beyond ``K a``, at most ``κ d`` (m).
    params : Parameters
        The material (``G*``).
    contact_radius : float
        The punch's radius ``a`` (m).

    Returns
    -------
    float or numpy.ndarray
        The force (N), the shape of ``sliding``.
    """
    sliding, contact_radius = _finite(sliding=sliding, contact_radius=contact_radius)
    return 2.0 * params.G_star * contact_radius * sliding


def capped_d_crit_B(alpha_arr: np.ndarray, cot: np.ndarray, cap: float, kappa: float, params: Parameters,
                    profile: FlatPunch, held: bool) -> np.ndarray:
    r"""Scenario B's pull-off onset under every spring's cap ``K a + κ d`` against the shift ``(d_max − d) cot α``:
    ``d = (d_max cot α − K a)/(cot α + κ)``, ``-inf`` below the surface (it comes off first) or at 90°.

    .. math:: \frac{d_\mathrm{max} - d}{\tan\alpha} = K a + \kappa d \qquad (20)

    Parameters
    ----------
    alpha_arr : numpy.ndarray
        The path angles (degrees, checked).
    cot : numpy.ndarray
        Their cotangents (``+inf`` at 0°).
    cap : float
        ``K`` of the law's ``τ0`` part (0 without it).
    kappa : float
        ``κ = μ E*/G*`` of its Coulomb part (0 without it).
    params : Parameters
        The material, ``τ0``, ``Δγ1`` and ``d_max``.
    profile : FlatPunch
        The punch.
    held : bool
        Whether an adhesive punch is held above the surface under ``τ0``'s part: the caps are ``K a`` alone there,
        (21) down to Kendall's depth (:func:`d_crit_B`).

    Returns
    -------
    numpy.ndarray
        The onset depths (m), the shape of ``alpha_arr``.
    """
    vertical = alpha_arr >= 90.0
    with np.errstate(invalid="ignore"):  # α = 0: cot α = +inf, the onset at d_max
        depth = np.where(np.isinf(cot), params.d_max, (params.d_max * cot - cap * profile.radius) / (cot + kappa))
    if held:  # held above the surface the caps are K a alone: (21) to the pull-off
        below = np.asarray(d_crit_B(alpha_arr, profile, params, adhesion=True), dtype=float)
        return np.where(vertical, -np.inf, np.where(depth < 0.0, below, depth))
    return np.where(vertical | (depth < 0.0), -np.inf, depth)


def capped_d_crit_B_indentation(alpha_arr: np.ndarray, cot: np.ndarray, cap: float, kappa: float,
                                params: Parameters, profile: FlatPunch) -> np.ndarray:
    r"""The onset on scenario B's indentation branch under every spring's cap ``K a + κ d`` against the shift
    ``(d − d_max) cot α``: ``d = (K a + d_max cot α)/(cot α − κ)`` where ``cot α > κ``, else ``+inf`` (never), with
    adhesion or without.

    .. math:: \frac{d - d_\mathrm{max}}{\tan\alpha} = K a + \kappa d \qquad (20)

    Parameters
    ----------
    alpha_arr : numpy.ndarray
        The path angles (degrees, checked).
    cot : numpy.ndarray
        Their cotangents (``+inf`` at 0°).
    cap : float
        ``K`` of the law's ``τ0`` part (0 without it).
    kappa : float
        ``κ = μ E*/G*`` of its Coulomb part (0 without it).
    params : Parameters
        The material, ``τ0`` and ``d_max``.
    profile : FlatPunch
        The punch.

    Returns
    -------
    numpy.ndarray
        The onset depths (m), the shape of ``alpha_arr``.
    """
    slides = (cot > kappa) & ~(alpha_arr >= 90.0)
    with np.errstate(divide="ignore", invalid="ignore"):  # (α = 0: the limit d_max)
        depth = np.where(np.isinf(cot), params.d_max, (cap * profile.radius + params.d_max * cot) / (cot - kappa))
    return np.where(slides, depth, np.inf)


def capped_critical_angle_B_indentation(cap: float, kappa: float, params: Parameters, profile: FlatPunch,
                                        final_depth: float | None = None) -> float:
    """The "+" branch's critical angle (degrees) under every spring's cap ``K a + κ d``: slip exactly at the final
    depth ``F``, ``cot α_c = (K a + κ F)/(F − d_max)``.

    Parameters
    ----------
    cap : float
        ``K`` of the law's ``τ0`` part (0 without it).
    kappa : float
        ``κ = μ E*/G*`` of its Coulomb part (0 without it).
    params : Parameters
        The material, ``τ0`` and ``d_max``.
    profile : FlatPunch
        The punch.
    final_depth : float, optional
        The deepest point ``F`` (m); default ``2 d_max``.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    final = 2.0 * params.d_max if final_depth is None else final_depth
    return float(math.degrees(math.atan2(final - params.d_max, cap * profile.radius + kappa * final)))


#: The flat punch's closed forms behind :mod:`mdr_events.theory.power_law`'s functions of either indenter.
CLOSED_FORMS = ClosedForms(normal_force=normal_force, jump_off=jump_off, pull_off_force=pull_off_force,
                           d_crit_A=d_crit_A, critical_angle_A=critical_angle_A, d_crit_B=d_crit_B,
                           critical_angle_B=critical_angle_B, d_crit_B_indentation=d_crit_B_indentation,
                           critical_angle_B_indentation=critical_angle_B_indentation)
#: The flat punch's closed forms under :mod:`mdr_events.theory.mindlin`'s friction laws.
FRICTION_FORMS = FrictionForms(coulomb_force=coulomb_force, d_crit_B=capped_d_crit_B,
                               d_crit_B_indentation=capped_d_crit_B_indentation,
                               critical_angle_B_indentation=capped_critical_angle_B_indentation)
