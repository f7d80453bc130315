"""The rate-dependent adhesion law (:class:`~mdr_events.contact.adhesion.RateDependentAdhesion`) evaluated: the energy
an edge releases, the work of adhesion at a speed and the speed at a release rate, as
:func:`~mdr_events.theory.symbolic.derive_rate_dependent_adhesion` derives them (vectorised, and for Python floats
where an ODE's right-hand side calls them).

The edge of a contact of radius ``a`` at depth ``d`` has its spring stretched by ``Δl = g(a) − d`` and releases
``Γ = E* Δl² / (2π a)`` (Heß's rule (8) read the other way). It rests while ``Δγ0 <= Γ <= Δγ1``, recedes where
``Γ > Δγ1`` and advances where ``Γ < Δγ0``; an edge whose spring is not stretched (``Δl <= 0``: compressed) advances
at an unbounded speed, as a contact without adhesion grows at once.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.adhesion import RateDependentAdhesion, check_rate_law
from mdr_events.theory import symbolic
from mdr_events.validation import check_real, real_array, shown

__all__ = ["release_rate", "work_of_adhesion", "edge_speed", "edge_speed_scalar", "flat_punch_detachment_time"]


def _relation(key: str) -> symbolic.Relation:
    return symbolic.derive_rate_dependent_adhesion()[key]


def _values(name: str, value, allowed: str, valid=None) -> np.ndarray:
    """``value`` as a float array of real numbers, none nan, each ``valid`` (a predicate on the array); else the error
    naming ``name``."""
    array = real_array(name, value, allowed)
    if np.any(np.isnan(array)) or (valid is not None and not np.all(valid(array))):
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: {allowed}")
    return array


def _finite_result(result, what: str, inputs: str):
    """``result`` if every value is finite; else the ``ValueError`` saying that ``what`` overflows a double."""
    if not np.all(np.isfinite(result)):
        raise ValueError(f"{inputs} is not allowed: {what} overflows a double; allowed: values whose {what} is a finite "
                         "double")
    return result


def release_rate(elongation, radius, E_star: float) -> np.ndarray:
    """``Γ = E* Δl² / (2π a)`` (J/m², (8)): the energy the edge of a contact of radius ``radius`` releases with its
    spring stretched by ``elongation`` (m); 0 where it is not stretched (``Δl <= 0``).

    Parameters
    ----------
    elongation : array_like
        ``Δl = g(a) − d`` (m).
    radius : array_like
        The contact radius ``a`` (m, > 0).
    E_star : float
        The effective modulus ``E*`` (Pa).

    Returns
    -------
    numpy.ndarray
        The release rate ``Γ`` (J/m²).
    """
    elongation = _values("elongation", elongation, "real numbers (m), finite", np.isfinite)
    radius = _values("radius", radius, "real numbers > 0 (m), finite", lambda a: np.isfinite(a) & (a > 0.0))
    E_star = check_real("E_star", E_star, "a finite number > 0 (Pa)", lambda value: value > 0.0)
    stretched = np.maximum(elongation, 0.0)
    with np.errstate(over="ignore", invalid="ignore"):
        rate = np.asarray(_relation("energy_release_rate").numeric(stretched, radius, E_star), dtype=float)
    return _finite_result(rate, "the release rate E* dl^2 / (2 pi a)",
                          f"elongation={shown(elongation)}, radius={shown(radius)}, E_star={E_star!r}")


def work_of_adhesion(law: RateDependentAdhesion, speed) -> np.ndarray:
    """The work of adhesion ``Δγ(ȧ)`` (J/m²) of an edge moving at ``speed`` (m/s): ``Δγ1 [1 + (|ȧ|/v_ref)^n]``
    receding (``ȧ < 0``), ``Δγ0 / [1 + (ȧ/v_ref)^n]`` advancing; ``nan`` at rest, where it lies anywhere between.

    Parameters
    ----------
    law : RateDependentAdhesion
        The law.
    speed : array_like
        The edge's speed ``ȧ`` (m/s).

    Returns
    -------
    numpy.ndarray
        The work of adhesion (J/m²).
    """
    law = check_rate_law(law)
    speed = _values("speed", speed, "real numbers (m/s; +-inf allowed), not nan")
    magnitude = np.abs(speed)
    receding = _relation("receding_work_of_adhesion").numeric(magnitude, law.dgamma1, law.v_ref, law.n)
    advancing = _relation("advancing_work_of_adhesion").numeric(magnitude, law.dgamma0, law.v_ref, law.n)
    return np.where(speed < 0.0, receding, np.where(speed > 0.0, advancing, np.nan))


def edge_speed(law: RateDependentAdhesion, release) -> np.ndarray:
    """The edge's speed ``ȧ`` (m/s) where it releases ``release`` (J/m²): ``−v_ref (Γ/Δγ1 − 1)^(1/n)`` beyond
    ``Δγ1``, ``v_ref (Δγ0/Γ − 1)^(1/n)`` below ``Δγ0`` (``+inf`` at ``Γ = 0``), 0 between.

    Parameters
    ----------
    law : RateDependentAdhesion
        The law.
    release : array_like
        The energy release rate ``Γ >= 0`` (J/m², :func:`release_rate`).

    Returns
    -------
    numpy.ndarray
        The speed ``ȧ`` (m/s; negative receding).
    """
    law = check_rate_law(law)
    release = _values("release", release, "real numbers >= 0 (J/m^2; inf allowed), not nan", lambda g: g >= 0.0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        receding = _relation("receding_edge_speed").numeric(np.maximum(release, law.dgamma1), law.dgamma1, law.v_ref,
                                                            law.n)
        advancing = _relation("advancing_edge_speed").numeric(np.minimum(release, law.dgamma0), law.dgamma0,
                                                              law.v_ref, law.n)
    return np.where(release > law.dgamma1, -receding, np.where(release < law.dgamma0, advancing, 0.0))


def edge_speed_scalar(law: RateDependentAdhesion, release: float) -> float:
    """:func:`edge_speed` for one Python float (the compiled relations: an ODE's right-hand side calls it).

    Parameters
    ----------
    law : RateDependentAdhesion
        The law.
    release : float
        The energy release rate ``Γ >= 0`` (J/m²).

    Returns
    -------
    float
        The speed ``ȧ`` (m/s; negative receding, ``inf`` at ``Γ = 0``, and ``±inf`` where it overflows a double).
    """
    law = check_rate_law(law)
    release = check_real("release", release, "a number >= 0 (J/m^2; inf allowed), not nan", lambda g: g >= 0.0,
                         finite=False)
    try:
        if release > law.dgamma1:
            return -_relation("receding_edge_speed").scalar(release, law.dgamma1, law.v_ref, law.n)
        if release >= law.dgamma0:
            return 0.0
        if release <= 0.0:
            return math.inf
        return _relation("advancing_edge_speed").scalar(release, law.dgamma0, law.v_ref, law.n)
    except OverflowError:  # (math's pow raises where NumPy's gives inf)
        return -math.inf if release > law.dgamma1 else math.inf


def flat_punch_detachment_time(law: RateDependentAdhesion, punch_radius: float, depth: float, E_star: float,
                               radius: float = 0.0) -> float:
    """The time (s) the edge of a flat punch of radius ``punch_radius`` held at ``depth`` takes to recede to
    ``radius`` (0: to detach), in closed form for ``n = 1`` (:func:`~mdr_events.theory.symbolic.derive_rate_dependent_adhesion`).

    Parameters
    ----------
    law : RateDependentAdhesion
        The law, with ``n = 1``.
    punch_radius : float
        The punch's radius ``a0`` (m).
    depth : float
        The depth held (m), beyond Kendall's pull-off ``−sqrt(2π a0 Δγ1 / E*)`` (the edge recedes from the start).
    E_star : float
        The effective modulus ``E*`` (Pa).
    radius : float, optional
        The radius reached (m, ``0 <= radius <= punch_radius``).

    Returns
    -------
    float
        The time (s).

    Raises
    ------
    ValueError
        ``n`` other than 1, or a depth at which the edge does not recede.
    """
    law = check_rate_law(law)
    punch_radius = check_real("punch_radius", punch_radius, "a finite number > 0 (m)", lambda value: value > 0.0)
    depth = check_real("depth", depth, "a finite number (m)")
    E_star = check_real("E_star", E_star, "a finite number > 0 (Pa)", lambda value: value > 0.0)
    radius = check_real("radius", radius, f"a finite number with 0 <= radius <= punch_radius = {punch_radius!r} m",
                        lambda value: 0.0 <= value <= punch_radius)
    if law.n != 1.0:
        raise ValueError(f"n={law.n!r} is not allowed here; allowed: n = 1 (the closed form's)")
    kendall = -math.sqrt(2.0 * math.pi * punch_radius * law.dgamma1 / E_star)
    if not depth < kendall:
        raise ValueError(f"depth={depth!r} m is not allowed; allowed: below Kendall's pull-off {kendall!r} m of the "
                         "punch (the edge recedes from the start)")
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        time = float(_relation("flat_punch_detachment_time").numeric(radius, punch_radius, -depth, law.dgamma1,
                                                                     law.v_ref, E_star))
    return _finite_result(time, "the detachment time", f"law={law!r}, punch_radius={punch_radius!r}, "
                          f"depth={depth!r}, E_star={E_star!r}, radius={radius!r}")
