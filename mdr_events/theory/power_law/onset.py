"""The power law's slip onsets (17), (18), (20), (21) and critical angles, scenarios A, B and B's indentation
branch (each public function hands either indenter to its kind's closed forms, the power law's here).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import PowerLaw, Profile
from mdr_events.theory.power_law.arguments import (_check_adhesive, _forms, _rel, as_output, check_onset_scales,
                                                   final_depth_of, path_angles)
from mdr_events.theory.power_law.convex_roots import convex_root
from mdr_events.theory.power_law.detachment import _jump_off
from mdr_events.theory.power_law.normal import contact_radius
from mdr_events.theory.power_law.prefactors import cap_per_radius, hess_prefactor, prefactor
from mdr_events.validation import check_flag

__all__ = ["d_crit_A", "critical_angle_A", "d_crit_B", "critical_angle_B", "d_crit_B_indentation",
           "critical_angle_B_indentation"]


def d_crit_A(alpha, profile: Profile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario A (the path (14) from first contact at angle ``α`` in degrees).

    - Power law without adhesion, ``n != 1``: the closed form of (17), ``d^((n−1)/n) ∝ tan α``.
    - The cone (``n = 1``) without adhesion: the shift ``d / tan α`` and the cap ``K a = K d / (κ c)`` grow in
      proportion, so the springs slide from first contact (``d = 0``) where ``tan α < κ c / K`` and never (``nan``)
      above it: no onset depth exists in between.
    - Power law with adhesion (``Δγ0`` branch), ``n >= 1``: ``d(a) = tan α K a`` has no closed form; in ``s = √a``
      ``κ c s^(2n−1) − tan α K s − sqrt(2πΔγ0/E*)`` is increasing and convex past its minimum and has one
      positive root (:func:`convex_root`); ``nan`` where it has none.
    - Flat punch: :func:`mdr_events.theory.flat_punch.d_crit_A` (``d = tan α K a``, onset is full slip).

    Depths beyond ``d_max`` are returned as they are (the path turns back before them); ``α = 90°`` never
    slides (``+inf``). Without adhesion the onset (17), with it (18):

    .. math:: \frac{d}{\tan\alpha} = \bar u(a) = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma_0}{E^*}} \qquad (17), (18)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``nan`` where none exists, ``+inf`` at 90°.

    Raises
    ------
    ValueError
        An angle out of range, or a power law with ``n < 1`` with adhesion.
    """
    forms = _forms(profile)
    check_onset_scales(params, profile, adhesion)
    return forms.d_crit_A(alpha, profile, params, adhesion)


def _d_crit_A(alpha, profile: PowerLaw, params: Parameters, adhesion: bool = False):
    """The power law's :func:`d_crit_A`."""
    alpha_arr, vertical = path_angles(alpha, adhesion)  # straight down: never slides (+inf, as (17), (18))
    tan_alpha = np.tan(np.deg2rad(np.where(vertical, 45.0, alpha_arr)))
    K = cap_per_radius(params)
    kc = prefactor(profile)
    if not adhesion or params.dgamma0 == 0.0:
        if profile.n == 1.0:
            return as_output(np.where(vertical, np.inf, np.where(tan_alpha * K < kc, 0.0, np.nan)), alpha_arr)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # (its power 1/(n − 1) near the cone
            # overflows to +inf, "never slides", as the adhesive root beyond the doubles: round twenty)
            depth = _rel("power_law_d_crit_A_hertz").numeric(tan_alpha, profile.c, profile.n, params.tau0,
                                                             params.G_star)
        return as_output(np.where(vertical, np.inf, np.asarray(depth, dtype=float)), alpha_arr)
    if profile.n < 1.0:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed for the adhesive slip onset; allowed: n >= 1 "
                         "(below it the onset condition may have several roots)")
    k = hess_prefactor(params, params.dgamma0)
    power = 2.0 * profile.n - 1.0
    slope = tan_alpha * K
    if power == 1.0:  # the cone: linear in s
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(kc > slope, k / (kc - slope), np.nan)
    else:
        # φ(s) = κc s^p − slope s − k: negative at 0 and convex (p > 1), so it has one positive root
        with np.errstate(over="ignore", divide="ignore"):
            upper = np.maximum((2.0 * slope / kc) ** (1.0 / (power - 1.0)), (2.0 * k / kc) ** (1.0 / power))
        s = convex_root(lambda s: kc * s**power - slope * s - k, lambda s: power * kc * s ** (power - 1.0) - slope,
                        upper, 0.0)
    with np.errstate(over="ignore"):  # (a root near the double range's top: its depth +inf)
        depth = np.asarray(tan_alpha * K * (s * s), dtype=float)
    return as_output(np.where(vertical, np.inf, depth), alpha_arr)


def critical_angle_A(profile: Profile, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario A's critical angle (degrees): slip begins exactly at ``d_max``, ``tan α_c = d_max / ū(a(d_max))``;
    below it the springs slide while indenting. The radius at ``d_max`` is the branch's (``Δγ0``) with adhesion,
    the non-adhesive one without (the flat punch: :func:`mdr_events.theory.flat_punch.critical_angle_A`). The cone
    without adhesion gives ``tan α_c = κ c / K`` at any depth.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{max}}{\bar u(a(d_\mathrm{max}))}
              = \frac{2 G^* d_\mathrm{max}}{\pi a \tau_0} \qquad (17), (18)

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    forms = _forms(profile)
    check_onset_scales(params, profile, adhesion)
    return forms.critical_angle_A(profile, params, adhesion)


def _critical_angle_A(profile: PowerLaw, params: Parameters, adhesion: bool = True) -> float:
    """The power law's :func:`critical_angle_A`."""
    check_flag("adhesion", adhesion)
    radius = contact_radius(params.d_max, profile, params, params.dgamma0 if adhesion else 0.0)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_A").numeric(radius, params.d_max, params.tau0, params.G_star)
    return float(np.rad2deg(angle))


def d_crit_B(alpha, profile: Profile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario B's pull-off (the path (19): vertically in to ``d_max``, out at angle
    ``α`` in degrees), as (20), (21) take it: the radius on the pull-off branch (``Δγ1``; without adhesion the
    non-adhesive radius) from the start of the pull-off.

    - Power law: ``(d_max − d) / tan α = K a`` with ``d = d(a)`` on the branch; in ``s = √a``,
      ``κ c s^(2n) − sqrt(2πΔγ1/E*) s + tan α K s² − d_max`` increases and is convex above the jump-off
      (:func:`convex_root` from the radius at ``d_max``). A root below the jump-off radius means the contact
      comes apart before any spring slides: ``-inf`` (as :func:`mdr_events.theory.analytic.d_crit`).
    - Flat punch: :func:`mdr_events.theory.flat_punch.d_crit_B` (``d = d_max − tan α K a``).

    ``d < d_crit`` is the sliding region; ``α = 90°`` never slides (``-inf``).

    .. math:: \frac{d_\mathrm{max} - d}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma_1}{E^*}} \qquad (20), (21)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ1``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the radius of the ``Δγ1`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``-inf`` where the contact comes apart first.

    Raises
    ------
    ValueError
        An angle out of range, or ``n <= 1/2`` with adhesion.
    """
    forms = _forms(profile)
    check_onset_scales(params, profile, adhesion)
    return forms.d_crit_B(alpha, profile, params, adhesion)


def _d_crit_B(alpha, profile: PowerLaw, params: Parameters, adhesion: bool = False):
    """The power law's :func:`d_crit_B`."""
    alpha_arr, vertical = path_angles(alpha, adhesion)
    tan_alpha = np.tan(np.deg2rad(alpha_arr))
    K = cap_per_radius(params)
    work = params.dgamma1 if adhesion else 0.0
    if work > 0.0:
        _check_adhesive(profile, work)
    kc, k = prefactor(profile), hess_prefactor(params, work)
    two_n = 2.0 * profile.n
    slope = np.where(vertical, 0.0, tan_alpha * K)
    fold = _jump_off(profile, params, work)
    s_fold = math.sqrt(fold["contact_radius"])
    upper = math.sqrt(float(contact_radius(params.d_max, profile, params, work)))
    if not two_n >= 1.0:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed for the pull-off slip onset; allowed: n >= 0.5")
    s = convex_root(lambda s: kc * s**two_n - k * s + slope * s * s - params.d_max,
                    lambda s: two_n * kc * s ** (two_n - 1.0) - k + 2.0 * slope * s,
                    np.full(alpha_arr.shape, upper), s_fold)
    radius = s * s
    depth = params.d_max - slope * radius
    # the root lies below the fold where the function is still negative at it: the contact comes apart first
    apart = (kc * s_fold**two_n - k * s_fold + slope * s_fold**2 - params.d_max > 0.0) if work > 0.0 else False
    return as_output(np.where(vertical | apart, -np.inf, depth), alpha_arr)


def critical_angle_B(profile: Profile, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario B's critical angle (degrees): above it the contact comes apart (the jump-off of the ``Δγ1``
    branch; the flat punch: :func:`mdr_events.theory.flat_punch.critical_angle_B`) before any spring slides,
    ``tan α_c = (d_max − d_j) / ū(a_j)`` at the jump-off ``(a_j, d_j)`` ((21) there). Without adhesion: 90°.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{max} - d_j}{\bar u(a_j)} = \frac{2 G^* (d_\mathrm{max} - d_j)}{\pi a_j \tau_0}
              \qquad (21)

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ1``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the radius of the ``Δγ1`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    forms = _forms(profile)
    check_onset_scales(params, profile, adhesion)
    return forms.critical_angle_B(profile, params, adhesion)


def _critical_angle_B(profile: PowerLaw, params: Parameters, adhesion: bool = True) -> float:
    """The power law's :func:`critical_angle_B`."""
    check_flag("adhesion", adhesion)
    if not adhesion or params.dgamma1 == 0.0:
        return 90.0
    point = _jump_off(profile, params, params.dgamma1)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B").numeric(point["contact_radius"], point["depth"], params.d_max, params.tau0,
                                                 params.G_star)
    return float(np.rad2deg(angle))


def d_crit_B_indentation(alpha, profile: Profile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset on scenario B's indentation branch (the "+" sign of (20), (21); the path
    :meth:`~mdr_events.Path.scenario_B_indentation`: vertically in to ``d_max``, further in at angle ``α``):
    ``(d − d_max) / tan α = K a(d)`` on the ``Δγ0`` branch (without adhesion the non-adhesive radius).

    - Power law, ``n >= 1``: in ``s = √a``, ``κ c s^(2n) − sqrt(2πΔγ0/E*) s − tan α K s² − d_max`` falls, then
      rises convexly through its one positive root (:func:`convex_root` from above); the cone (``n = 1``) is a
      quadratic with a root only where ``tan α K < κ c`` (else ``+inf``: it never slides).
    - Flat punch: :func:`mdr_events.theory.flat_punch.d_crit_B_indentation` (``d = d_max + tan α K a``).

    ``d > d_crit`` is the sliding region; ``α = 90°`` never slides (``+inf``).

    .. math:: \frac{d - d_\mathrm{max}}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma_0}{E^*}} \qquad (20), (21)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``+inf`` where it never slides.

    Raises
    ------
    ValueError
        An angle out of range, or a power law with ``n < 1``.
    """
    forms = _forms(profile)
    check_onset_scales(params, profile, adhesion)
    return forms.d_crit_B_indentation(alpha, profile, params, adhesion)


def _d_crit_B_indentation(alpha, profile: PowerLaw, params: Parameters, adhesion: bool = False):
    """The power law's :func:`d_crit_B_indentation`."""
    alpha_arr, vertical = path_angles(alpha, adhesion)
    slope = np.where(vertical, 0.0, np.tan(np.deg2rad(alpha_arr))) * cap_per_radius(params)
    if profile.n < 1.0:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed for the indentation branch's slip onset; allowed: "
                         "n >= 1")
    work = params.dgamma0 if adhesion else 0.0
    kc, k, two_n = prefactor(profile), hess_prefactor(params, work), 2.0 * profile.n
    if two_n == 2.0:  # the cone: (κc − slope) s² − k s − d_max = 0
        lead = kc - slope
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(lead > 0.0, (k + np.sqrt(k * k + 4.0 * lead * params.d_max)) / (2.0 * lead), np.nan)
    else:
        # κc s^(2n) is at least three times each other term beyond this: the function is positive there
        with np.errstate(over="ignore", divide="ignore"):
            upper = np.maximum.reduce([np.full(alpha_arr.shape, (3.0 * k / kc) ** (1.0 / (two_n - 1.0))),
                                       (3.0 * slope / kc) ** (1.0 / (two_n - 2.0)),
                                       np.full(alpha_arr.shape, (3.0 * params.d_max / kc) ** (1.0 / two_n))])
        s = convex_root(lambda s: kc * s**two_n - k * s - slope * s * s - params.d_max,
                        lambda s: two_n * kc * s ** (two_n - 1.0) - k - 2.0 * slope * s, upper, 0.0)
    with np.errstate(over="ignore"):  # (a root near the double range's top, n -> 1: its depth +inf, as no root's)
        depth = params.d_max + slope * s * s
    return as_output(np.where(vertical | np.isnan(s), np.inf, depth), alpha_arr)


def critical_angle_B_indentation(profile: Profile, params: Parameters, adhesion: bool = True,
                                 final_depth: float | None = None) -> float:
    r"""The "+" branch's critical angle (degrees): slip begins exactly at ``final_depth`` (default ``2 d_max``, as
    :meth:`~mdr_events.Path.scenario_B_indentation`), ``tan α_c = (final − d_max) / ū(a(final))`` with the ``Δγ0``
    branch's radius there (the flat punch: :func:`mdr_events.theory.flat_punch.critical_angle_B_indentation`);
    below it the springs slide before the path turns back.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{final} - d_\mathrm{max}}{\bar u(a(d_\mathrm{final}))} \qquad (21)

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.
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
    forms = _forms(profile)
    check_onset_scales(params, profile, adhesion)
    return forms.critical_angle_B_indentation(profile, params, adhesion, final_depth)


def _critical_angle_B_indentation(profile: PowerLaw, params: Parameters, adhesion: bool = True,
                                  final_depth: float | None = None) -> float:
    """The power law's :func:`critical_angle_B_indentation`."""
    check_flag("adhesion", adhesion)
    final = final_depth_of(params, final_depth)
    radius = float(contact_radius(final, profile, params, params.dgamma0 if adhesion else 0.0))
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B_indentation").numeric(radius, final, params.d_max, params.tau0, params.G_star)
    return float(np.rad2deg(angle))

