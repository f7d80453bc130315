"""The power law's normal relations: its MDR profile (3), the branch's depth (9) and force (10), the radius at first
touch and on the stable branch at a depth (:func:`~mdr_events.theory.power_law.convex_root` where no closed form
exists).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.parameters import Parameters
from mdr_events.validation import SCALE_MAX, check_real
from mdr_events.contact.indenters import PowerLaw, Profile
from mdr_events.theory.power_law.arguments import (_check_adhesive, _check_work, _forms, _power_law_only, _rel,
                                                   as_output)
from mdr_events.theory.analytic.arguments import _finite
from mdr_events.theory.power_law.convex_roots import convex_root
from mdr_events.theory.power_law.detachment import _jump_off
from mdr_events.theory.power_law.prefactors import hess_prefactor, prefactor

__all__ = ["with_radius_at", "equivalent_profile", "branch_depth", "normal_force", "branch_normal_force",
           "jump_in_radius", "contact_radius"]


def with_radius_at(n: float, radius: float, depth: float) -> PowerLaw:
    """The power law ``f = c rⁿ`` whose non-adhesive contact radius at ``depth`` is ``radius``: ``c`` from
    ``κₙ c radiusⁿ = depth`` (to compare indenters of equal size, e.g. with the paraboloid's ``√(R d_max)``).

    Parameters
    ----------
    n : float
        The exponent, > 0.
    radius : float
        The contact radius (m) it should have at ``depth`` without adhesion.
    depth : float
        The depth (m).

    Returns
    -------
    PowerLaw
        The power law of exponent ``n`` and that ``c``.
    """
    # (one number each, > 0: an array or a list ended in NumPy's own TypeError, issue 32 round 28 A2)
    radius = check_real("radius", radius, f"a finite number > 0 (m), at most {SCALE_MAX:.2g}",
                        lambda value: 0.0 < value <= SCALE_MAX)
    depth = check_real("depth", depth, f"a finite number > 0 (m), at most {SCALE_MAX:.2g}",
                       lambda value: 0.0 < value <= SCALE_MAX)
    return PowerLaw(depth / float(equivalent_profile(radius, PowerLaw(1.0, n))), n)


def equivalent_profile(x, profile: PowerLaw):
    r"""``g(x) = κₙ c |x|ⁿ``: the MDR profile of the power law, the Abel transform (3).

    .. math:: g(x) = |x| \int_0^{|x|} \frac{f'(r)}{\sqrt{x^2 - r^2}}\, \mathrm{d}r = \kappa_n c |x|^n \qquad (3)

    Parameters
    ----------
    x : float or array_like
        The spring's coordinate (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).

    Returns
    -------
    float or numpy.ndarray
        ``g(x)`` (m), the shape of ``x``.
    """
    (x,) = _finite(x=x)
    return _equivalent_profile(x, _power_law_only(profile, "equivalent_profile"))


def _equivalent_profile(x, profile: PowerLaw):
    """:func:`equivalent_profile` unchecked (the springs' own coordinates: the simulators' profile)."""
    return _rel("profile_power_law").numeric(np.abs(np.asarray(x, dtype=float)), profile.c, profile.n)


def branch_depth(contact_radius, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    r"""Depth of the adhesive contact of radius ``a``, ``κ c aⁿ − sqrt(2π a Δγ / E*)`` (generalised (9)).

    .. math:: d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The depth ``d`` (m), the shape of ``contact_radius``.
    """
    (contact_radius,) = _finite(contact_radius=contact_radius)
    return _branch_depth(contact_radius, _power_law_only(profile, "branch_depth"), params,
                         _check_work(work_of_adhesion))


def _branch_depth(contact_radius, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    """:func:`branch_depth` unchecked (the continuum's branch: its work checked once, its radii its own)."""
    return _rel("power_law_depth").numeric(contact_radius, profile.c, profile.n, params.E_star, work_of_adhesion)


def normal_force(depth, contact_radius, profile: Profile, params: Parameters):
    r"""Normal force (N) of the springs in ``|x| < a`` at depth ``d`` (10); the flat punch's:
    :func:`mdr_events.theory.flat_punch.normal_force`.

    .. math:: F_N = 2 E^* \int_0^a \left(d - g(x)\right) \mathrm{d}x
              = 2 E^* \left(a d - \frac{\kappa_n c\, a^{n+1}}{n + 1}\right) \qquad (10)

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    contact_radius : float, array_like or None
        The contact radius ``a`` (m), any (e.g. pinned); for the flat punch ``None`` or its radius.
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.

    Returns
    -------
    float or numpy.ndarray
        ``F_N`` (N; negative: tensile).

    Raises
    ------
    ValueError
        A ``contact_radius`` other than the flat punch's own.
    """
    (depth,) = _finite(depth=depth)
    if contact_radius is not None:
        (contact_radius,) = _finite(contact_radius=contact_radius)
    return _forms(profile).normal_force(depth, contact_radius, profile, params)


def _normal_force(depth, contact_radius, profile: PowerLaw, params: Parameters):
    """The power law's :func:`normal_force` (10)."""
    return _rel("power_law_normal_force").numeric(depth, contact_radius, profile.c, profile.n, params.E_star)


def branch_normal_force(contact_radius, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    r"""Normal force of the adhesive power-law contact of radius ``a`` on its branch (10).

    .. math:: F_N = 2 E^* \left(a d(a) - \frac{\kappa_n c\, a^{n+1}}{n + 1}\right), \qquad
              d(a) = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9), (10)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        ``F_N`` (N; negative: tensile), the shape of ``contact_radius``.
    """
    (contact_radius,) = _finite(contact_radius=contact_radius)
    work_of_adhesion = _check_work(work_of_adhesion)
    profile = _power_law_only(profile, "branch_normal_force")
    return _rel("power_law_branch_normal_force").numeric(contact_radius, profile.c, profile.n, params.E_star,
                                                         work_of_adhesion)


def jump_in_radius(profile: PowerLaw, params: Parameters, work_of_adhesion: float) -> float:
    """Contact radius on first touch, ``d = 0`` on the branch: ``a^(2n−1) = 2π Δγ / (E* (κ c)²)`` (0 without
    adhesion).

    Parameters
    ----------
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ0`` (J/m², >= 0), the work of adhesion of the way in.

    Returns
    -------
    float
        The radius ``a`` (m).

    Raises
    ------
    ValueError
        ``n <= 1/2`` with adhesion (no stable contact).
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    profile = _power_law_only(profile, "jump_in_radius")
    if work_of_adhesion == 0.0:
        return 0.0
    _check_adhesive(profile, work_of_adhesion)
    return float(_rel("power_law_jump_in_radius").numeric(profile.c, profile.n, params.E_star, work_of_adhesion))


def contact_radius(depth, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    """Contact radius on the stable branch (``a >=`` the jump-off radius) at depth ``d``; ``nan`` where the depth
    lies below the jump-off (no contact).

    Without adhesion ``a = (d / (κ c))^(1/n)`` (``nan`` above the surface, ``d < 0``). With adhesion the branch in
    ``s = √a``, ``κ c s^(2n) − sqrt(2πΔγ/E*) s − d``, increases and is convex above the jump-off (``2n >= 1``):
    :func:`convex_root` from an upper bound.

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The radius ``a`` (m) or ``nan``, the shape of ``depth``.

    Raises
    ------
    ValueError
        ``n <= 1/2`` with adhesion.
    """
    (depth,) = _finite(depth=depth)
    return _contact_radius(depth, _power_law_only(profile, "contact_radius"), params, _check_work(work_of_adhesion))


def _contact_radius(depth, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    """:func:`contact_radius` unchecked (the continuum's branch: its work checked once, its depths its own)."""
    depth_arr = np.asarray(depth, dtype=float)
    if work_of_adhesion == 0.0:
        with np.errstate(invalid="ignore"):
            radius = _rel("power_law_hertz_radius").numeric(np.maximum(depth_arr, 0.0), profile.c, profile.n)
        return as_output(np.where(depth_arr >= 0.0, radius, np.nan), depth_arr)
    _check_adhesive(profile, work_of_adhesion)
    kc, k = prefactor(profile), hess_prefactor(params, work_of_adhesion)
    two_n = 2.0 * profile.n
    point = _jump_off(profile, params, work_of_adhesion)
    s_fold = math.sqrt(point["contact_radius"])
    # κc s^(2n) >= k s + |d| once κc s^(2n) >= 2|d| and κc s^(2n−1) >= 2k (each half covers one term)
    with np.errstate(over="ignore", divide="ignore"):
        upper = np.maximum.reduce([np.full(depth_arr.shape, s_fold),
                                   (2.0 * np.abs(depth_arr) / kc) ** (1.0 / two_n),
                                   np.full(depth_arr.shape, (2.0 * k / kc) ** (1.0 / (two_n - 1.0)))])
    s = convex_root(lambda s: kc * s**two_n - k * s - depth_arr, lambda s: two_n * kc * s ** (two_n - 1.0) - k,
                    upper, s_fold)
    return as_output(np.where(depth_arr >= point["depth"], s * s, np.nan), depth_arr)

