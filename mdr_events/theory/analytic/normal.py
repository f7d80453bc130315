"""The paraboloid's normal relations: the JKR branch's depth (9) and force (10), the force of any radius (10), Hertz's
radius (16), the jump-off, the radius at first touch, the pull-off force and the radius on the stable branch at a depth
(:func:`~mdr_events.theory.roots.positive_polynomial_root` of the quartic of (9)).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from mdr_events.theory.analytic.arguments import _as_output, _finite, _one_work, _rel, representable_result
from mdr_events.theory.roots import positive_polynomial_root
from mdr_events.theory.job import ContactLike, on_layer, paper_parameters

__all__ = ["jkr_depth", "jkr_normal_force", "normal_force", "hertz_contact_radius", "jump_off", "jump_in_radius",
           "pull_off_force", "jkr_contact_radius", "JUMP_OFF_CACHE"]


def jkr_depth(contact_radius, contact: ContactLike, work_of_adhesion: float):
    r"""Indentation depth of the adhesive contact of radius ``a``, eq. (9).

    .. math:: d = \frac{a^2}{R} - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The depth ``d`` (m), the shape of ``contact_radius``.
    """
    contact_radius, _ = _finite(contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)
    params = paper_parameters(contact, "jkr_depth")
    relation = _rel("jkr_depth").numeric
    return representable_result(lambda: relation(contact_radius, params.R, params.E_star, work_of_adhesion),
                                "jkr_depth", contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)


def jkr_normal_force(contact_radius, contact: ContactLike, work_of_adhesion: float):
    r"""Normal force of the adhesive contact of radius ``a``, eq. (10).

    .. math:: F_N = \frac{4 E^* a^3}{3 R} - \sqrt{8 \pi E^* \Delta\gamma\, a^3} \qquad (10)

    (the force (10) at the depth (9)).

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The normal force ``F_N`` (N; negative: tensile), the shape of ``contact_radius``.
    """
    contact_radius, _ = _finite(contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)
    params = paper_parameters(contact, "jkr_normal_force")
    relation = _rel("jkr_normal_force").numeric
    return representable_result(lambda: relation(contact_radius, params.R, params.E_star, work_of_adhesion),
                                "jkr_normal_force", contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)


def normal_force(depth, contact_radius, contact: ContactLike):
    r"""Normal force of the springs in ``|x| < a`` at depth ``d`` (any, e.g. pinned ``a``), eq. (10).

    .. math:: F_N = 2 E^* a d - \frac{2 E^* a^3}{3 R} \qquad (10)

    Parameters
    ----------
    depth : float or array_like
        The indentation depth ``d`` (m).
    contact_radius : float or array_like
        The contact radius ``a`` (m), any (e.g. pinned).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The normal force ``F_N`` (N).
    """
    depth, contact_radius = _finite(depth=depth, contact_radius=contact_radius)
    params = paper_parameters(contact, "normal_force")
    return _rel("normal_force").numeric(depth, contact_radius, params.R, params.E_star)


def hertz_contact_radius(depth, contact: ContactLike):
    r"""Non-adhesive contact radius ``a = sqrt(R d)``, eq. (16).

    .. math:: a = \sqrt{R d} \qquad (16)

    Parameters
    ----------
    depth : float or array_like
        The indentation depth ``d`` (m); negative depths give ``a = 0``.
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The contact radius ``a`` (m).
    """
    (depth,) = _finite(depth=depth)
    params = paper_parameters(contact, "hertz_contact_radius")
    return _rel("hertz_radius").numeric(np.maximum(depth, 0.0), params.R)


#: How many paraboloids' jump-off points :func:`jump_off` keeps (a sweep of ``R`` or ``Δγ`` asks each once).
JUMP_OFF_CACHE = 64


def jump_off(contact: ContactLike, work_of_adhesion: float) -> dict[str, float]:
    r"""Jump-off point under displacement control (``∂d/∂a = 0`` on the branch (9)).

    Returns ``contact_radius``, ``depth`` and ``normal_force`` (10) at the jump-off.

    .. math::

       a = \frac{1}{2} \left(\frac{\pi R^2 \Delta\gamma}{E^*}\right)^{1/3}, \quad
       d = -\frac{3}{4} \left(\frac{\pi^2 R \Delta\gamma^2}{E^{*2}}\right)^{1/3}, \quad
       F_N = -\frac{5}{6} \pi R \Delta\gamma

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before). A contact on a layer of finite thickness
        (``Contact.layer``; a paraboloid or power law, either base): the least depth on the layer's branch, found in
        ``a`` (:func:`~mdr_events.theory.layer.branch_points.layer_jump_off`; one beyond the tables, ``a/h > 64``, is
        refused).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    dict of str to float
        ``contact_radius`` (m), ``depth`` (m) and ``normal_force`` (N) at the jump-off.
    """
    work_of_adhesion = _one_work(work_of_adhesion)
    if on_layer(contact):
        from mdr_events.theory.layer.branch_points import layer_jump_off

        return layer_jump_off(contact, work_of_adhesion)
    params = paper_parameters(contact, "jump_off")
    # (a fresh dict each call: the caller may change it)
    return dict(_paraboloid_jump_off(params.R, params.E_star, work_of_adhesion, math.copysign(1.0, work_of_adhesion)))


@functools.lru_cache(maxsize=JUMP_OFF_CACHE, typed=True)
def _paraboloid_jump_off(R: float, E_star: float, work_of_adhesion: float, sign: float) -> tuple:
    """:func:`jump_off` of the paraboloid as ``(name, value)`` pairs, kept for the last :data:`JUMP_OFF_CACHE`
    arguments: a run asks it of the same contact at every step of its set-up (the checks of scales, the paths, each
    branch), some 40 µs a time. ``sign``: that of the work, so that ``-0.0`` and ``0.0``, equal as keys, are kept
    apart; the arguments' types too (``typed``: an ``int`` ``R`` computes as it did)."""
    args = (R, E_star, work_of_adhesion)
    point = representable_result(lambda: {
        "contact_radius": float(_rel("jump_off_radius").numeric(*args)),
        "depth": float(_rel("jump_off_depth").numeric(*args)),
        "normal_force": float(_rel("jump_off_force").numeric(R, work_of_adhesion)),
    }, "jump_off", work_of_adhesion=work_of_adhesion)
    return tuple(point.items())


def jump_in_radius(contact: ContactLike, work_of_adhesion: float) -> float:
    r"""Contact radius on first touch (``d = 0`` on the stable branch of (9)).

    .. math:: a = \left(\frac{2 \pi R^2 \Delta\gamma}{E^*}\right)^{1/3}

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before). A contact on a layer of finite thickness
        (``Contact.layer``; a paraboloid or power law, either base): the stable radius at ``d = 0`` on the layer's
        branch, found in ``a`` (:func:`~mdr_events.theory.layer.branch_points.layer_jump_in_radius`; one beyond the
        tables, ``a/h > 64``, is refused).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float
        The contact radius (m) at first touch.
    """
    work_of_adhesion = _one_work(work_of_adhesion)
    if on_layer(contact):
        from mdr_events.theory.layer.branch_points import layer_jump_in_radius

        return layer_jump_in_radius(contact, work_of_adhesion)
    params = paper_parameters(contact, "jump_in_radius")
    return representable_result(
        lambda: float(_rel("jump_in_radius").numeric(params.R, params.E_star, work_of_adhesion)), "jump_in_radius",
        work_of_adhesion=work_of_adhesion)


def pull_off_force(contact: ContactLike, work_of_adhesion: float) -> float:
    r"""JKR pull-off force ``−(3/2) π Δγ R``: the minimum of (10) along the branch (9).

    .. math:: F_\mathrm{pull\text{-}off} = -\frac{3}{2} \pi \Delta\gamma R

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before). A contact on a layer of finite thickness
        (``Contact.layer``; a paraboloid or power law, either base): the least force on the layer's branch, found in
        ``a`` (:func:`~mdr_events.theory.layer.branch_points.layer_pull_off_force`; one beyond the tables, ``a/h > 64``,
        is refused).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float
        The pull-off force (N, negative) under force control.
    """
    work_of_adhesion = _one_work(work_of_adhesion)
    if on_layer(contact):
        from mdr_events.theory.layer.branch_points import layer_pull_off_force

        return layer_pull_off_force(contact, work_of_adhesion)
    params = paper_parameters(contact, "pull_off_force")
    return representable_result(lambda: float(_rel("pull_off_force").numeric(params.R, work_of_adhesion)),
                                "pull_off_force", work_of_adhesion=work_of_adhesion)


def jkr_contact_radius(depth, contact: ContactLike, work_of_adhesion: float):
    """Contact radius on the stable branch of (9) for a depth ``d``.

    The stable branch is ``a >= a_jump-off`` (``∂d/∂a >= 0``). Depths below the
    jump-off depth have no contact: the result is ``nan`` there.

    Parameters
    ----------
    depth : float or array_like
        The indentation depth ``d`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The contact radius ``a`` (m) on the stable branch of (9), ``nan`` below the jump-off depth; the shape of
        ``depth``.
    """
    (depth,) = _finite(depth=depth)
    work_of_adhesion = _one_work(work_of_adhesion)
    params = paper_parameters(contact, "jkr_contact_radius")
    depth_arr = np.asarray(depth, dtype=float)
    if work_of_adhesion == 0.0:
        return _as_output(np.where(depth_arr >= 0, hertz_contact_radius(depth_arr, params), np.nan), depth_arr)
    rel = _rel("jkr_radius_quartic")
    coefficients = rel.coefficients(depth_arr, params.R, params.E_star, work_of_adhesion)
    point = jump_off(params, work_of_adhesion)
    s_min = np.sqrt(point["contact_radius"])
    root = positive_polynomial_root(coefficients, lower=s_min)
    radius = np.where(depth_arr >= point["depth"], root**2, np.nan)
    return _as_output(radius, depth_arr)

