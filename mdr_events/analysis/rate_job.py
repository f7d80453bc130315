"""What the rate-dependent angles are given, read in one place: a :class:`~mdr_events.Contact` whose adhesion is a
:class:`~mdr_events.RateDependentAdhesion`, with the speeds and the depth ``d_max``; or the form of before,
``(params, law, speeds[, profile, method, limits])``.

:func:`rate_job` is the one conversion of :func:`~mdr_events.analysis.rate_angles.critical_angles_at_speeds` and
:func:`~mdr_events.analysis.rate_let_go.critical_angles_B_at_speeds` (as :func:`~mdr_events.theory.job.theory_job` is
the closed forms'): a contact holds its own indenter, adhesion law and friction law (``"tau0"``: the angles compare
the springs' shift with ``τ0``'s cap ``K a`` (13)), on the half-space.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from mdr_events.contact.adhesion import RateDependentAdhesion, check_rate_law
from mdr_events.contact.model import Contact, check_half_space
from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile
from mdr_events.parameters import PAPER_D_MAX, PAPER_V, Parameters
from mdr_events.validation import check_real, shown

__all__ = ["RateJob", "rate_job", "OLD_TAIL"]

#: The positional arguments the form of before took after the speeds, in order.
OLD_TAIL = ("profile", "method", "limits")


class RateJob(NamedTuple):
    """The flat values a rate-dependent angle reads (:func:`rate_job`).

    Parameters
    ----------
    params : Parameters
        The material, ``R`` (``None`` for another indenter), ``τ0``, the works at rest and ``d_max``.
    law : RateDependentAdhesion
        The adhesion law.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        Another indenter than the paraboloid of ``params.R``.
    speeds : object
        The speeds as given (each function checks its grid).
    options : dict
        ``method`` and ``limits`` where the form of before gave them by position.
    """

    params: Parameters
    law: RateDependentAdhesion
    profile: SimulatedProfile
    speeds: Any
    options: dict


def rate_job(contact: Any, speeds: Any, old: tuple, law: Any = None, profile: Any = None, d_max: Any = None,
             what: str = "the rate-dependent angles") -> RateJob:
    """The values of ``contact`` (a :class:`~mdr_events.Contact`) with ``speeds`` and ``d_max``, or of the form of
    before ``(params, law, speeds, ...)`` (module docstring).

    Parameters
    ----------
    contact : Contact or Parameters
        A contact whose ``adhesion`` is a :class:`~mdr_events.RateDependentAdhesion` and whose friction law is
        ``"tau0"``, on the half-space; or :class:`~mdr_events.Parameters` (the form of before).
    speeds : object
        The speeds beside a Contact; beside Parameters given by position, the law (the form of before).
    old : tuple
        The further positional arguments: none beside a Contact; beside Parameters the speeds, then
        :data:`OLD_TAIL`.
    law : RateDependentAdhesion, optional
        Only beside Parameters, by keyword.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        Only beside Parameters (a contact holds its own indenter).
    d_max : float, optional
        The depth of scenarios A (14) and B (19) (m, finite, > 0; default the paper's 0.3 mm); only beside a Contact.
    what : str, optional
        The function asked, named in the errors.

    Returns
    -------
    RateJob
        The values the angles read.

    Raises
    ------
    TypeError
        ``contact`` of another type, a contact whose adhesion law is rate-independent, a law that is not a
        RateDependentAdhesion, or more positional arguments than the form allows.
    ValueError
        ``law`` or ``profile`` beside a Contact, ``d_max`` beside Parameters, a depth
        that is not a finite number > 0, a friction law other than ``"tau0"``, a layer of finite thickness, or a
        law whose works at rest are not the parameters'.
    """
    if isinstance(contact, Parameters):
        return _old_job(contact, speeds, old, law, profile, d_max, what)
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed in {what}; allowed: a "
                        "mdr_events.Contact with a RateDependentAdhesion, or Parameters with the law (params, law, "
                        "speeds)")
    if old:
        raise TypeError(f"{what} takes the speeds alone by position beside a Contact; {2 + len(old)} positional "
                        "arguments were given (allowed: contact, speeds; the rest by keyword)")
    for name, value in (("law", law), ("profile", profile)):
        if value is not None:
            raise ValueError(f"{name}={shown(value)} is not allowed beside a Contact in {what}; allowed: the "
                             "contact's own (Contact.adhesion, Contact.indenter)")
    if not isinstance(contact.adhesion, RateDependentAdhesion):
        raise TypeError(f"contact.adhesion={contact.adhesion!r} ({type(contact.adhesion).__name__}) is not allowed in "
                        f"{what}; allowed: a RateDependentAdhesion (the rate-independent angles: critical_angle)")
    if contact.friction.law != "tau0":
        raise ValueError(f"contact.friction={contact.friction!r} is not allowed in {what}; allowed: FrictionLaw("
                         "'tau0', tau0=...) (the angles compare the shift with tau0's cap K a, eq. (13))")
    check_half_space(contact, what)
    depth = PAPER_D_MAX if d_max is None else check_real("d_max", d_max, "a finite number > 0 (m)",
                                                         lambda value: value > 0.0)
    return RateJob(contact.parameters(depth, PAPER_V), contact.adhesion, contact.profile, speeds, {})


def _old_job(params: Parameters, second: Any, old: tuple, law: Any, profile: Any, d_max: Any, what: str) -> RateJob:
    """The form of before: ``(params, law, speeds[, profile, method, limits])``, the law by position or keyword."""
    if d_max is not None:
        raise ValueError(f"d_max={shown(d_max)} is not allowed beside Parameters in {what}; allowed: None (its own "
                         f"d_max = {params.d_max!r} m)")
    if law is None:
        law, (speeds, *tail) = second, (old or (None,))
    else:
        speeds, tail = second, list(old)
    if len(tail) > len(OLD_TAIL):
        raise TypeError(f"{what} takes at most {3 + len(OLD_TAIL)} positional arguments beside Parameters (params, "
                        f"law, speeds, {', '.join(OLD_TAIL)}); {3 + len(tail)} were given")
    options = dict(zip(OLD_TAIL, tail))
    if "profile" in options:
        if profile is not None:
            raise TypeError(f"profile was given twice in {what} (by position and keyword); allowed: once")
        profile = options.pop("profile")
    law = check_rate_law(law)
    if law.works_at_rest != (params.dgamma0, params.dgamma1):
        raise ValueError(f"law={law!r} is not allowed with dgamma0={params.dgamma0!r}, dgamma1={params.dgamma1!r} "
                         "J/m²; allowed: a law whose works at rest are the parameters'")
    return RateJob(params, law, check_simulated_profile(profile), speeds, options)
