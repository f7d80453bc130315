"""What the closed forms are given, read in one place: a :class:`~mdr_events.Contact` with a depth, or the keywords
of before (:class:`~mdr_events.Parameters` with ``profile=`` and ``friction=``).

The theory sits below the motion (:mod:`mdr_events.models.motion`), so it takes the one number of a motion that its
closed forms use, the depth ``d_max`` of scenarios A (14) and B (19); the speed enters none of them. A contact's
results carry the paper's speed ``v`` in their stamp (:data:`~mdr_events.parameters.PAPER_V`), so that they carry
the attributes a result of :class:`~mdr_events.Parameters` carries and are read back the same way
(:func:`mdr_events.io.datasets.parameters_of`). :func:`theory_job` is the one conversion of the theory's public
functions; :func:`paper_parameters` asks of it the paper's paraboloid (4) under the paper's law (13).
"""

from __future__ import annotations

import dataclasses
from typing import Any, NamedTuple

from mdr_events.contact.adhesion import Adhesion
from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.contact.indenters import Profile
from mdr_events.contact.model import Contact, check_half_space
from mdr_events.parameters import PAPER_D_MAX, PAPER_V, Parameters
from mdr_events.validation import check_real, shown

__all__ = ["TheoryJob", "theory_job", "contact_alone", "rate_independent", "paper_parameters", "ContactLike"]

#: What the theory's public functions take as the physical model.
ContactLike = Contact | Parameters


class TheoryJob(NamedTuple):
    """The flat values the closed forms read (:func:`theory_job`)."""

    #: material, indenter radius ``R`` (``None`` for another indenter), ``τ0``, ``Δγ0``, ``Δγ1``, ``d_max``, ``v``
    params: Parameters
    #: another indenter than the paraboloid of ``params.R`` (``None``: that paraboloid, eq. (4))
    profile: Profile | None
    #: the friction law, its ``τ0`` in ``params`` (the law of (13) by default)
    friction: FrictionLaw


def contact_alone(contact: Any, profile: Any = None, friction: Any = None) -> Contact:
    """``contact`` if it is a :class:`~mdr_events.Contact` with no ``profile`` or ``friction`` beside it (it holds its
    own); else the error naming it (the check of every entry point's contact form, :func:`theory_job` and
    :func:`mdr_events.models.simulate.model_job`)."""
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a "
                        "mdr_events.Contact (e.g. Contact.paper()) or a mdr_events.Parameters")
    for name, value, own in (("profile", profile, "Contact.indenter"), ("friction", friction, "Contact.friction")):
        if value is not None:
            raise ValueError(f"{name}={shown(value)} is not allowed beside a Contact; allowed: the contact's own "
                             f"({own})")
    return contact


def rate_independent(contact: Contact, what: str) -> Contact:
    """``contact`` if its adhesion law is rate-independent (the paper's :class:`~mdr_events.Adhesion`, which ``what``
    models); else the ``TypeError`` naming the law and what runs it (a Contact's ``RateDependentAdhesion`` would be
    read as the paper's law of its works at rest)."""
    law = contact.adhesion
    if isinstance(law, Adhesion):
        return contact
    elsewhere = getattr(type(law), "runs_in", None)
    raise TypeError(f"contact.adhesion={law!r} ({type(law).__name__}) is not allowed in {what}; allowed: Adhesion("
                    "dgamma0, dgamma1), the rate-independent law " + (f"({type(law).__name__}: {elsewhere})"
                                                                      if elsewhere else ""))


def theory_job(contact: Any, d_max: float | None = None, profile: Any = None, friction: Any = None,
               what: str = "the half-space's closed forms") -> TheoryJob:
    """The values of ``contact`` and the depth ``d_max``; the one conversion of the theory's public functions.

    Parameters
    ----------
    contact : Contact or Parameters
        A :class:`~mdr_events.Contact`: its indenter, adhesion and friction law, with the depth ``d_max`` (default
        the paper's 0.3 mm, :data:`~mdr_events.parameters.PAPER_D_MAX`) and the paper's speed (unused by the closed
        forms, stamped). Or the keywords of before: a :class:`~mdr_events.Parameters` (its own ``d_max``; then
        ``d_max`` must be ``None``) with ``profile`` and ``friction`` beside it, passed on as given.
    d_max : float, optional
        The depth of the motion, eqs. (14) and (19) (m, finite, > 0); only with a Contact.
    profile, friction : optional
        Only beside a :class:`~mdr_events.Parameters` (a contact holds its own).
    what : str, default "the half-space's closed forms"
        The function asked, named where a contact's layer of finite thickness is refused (the closed forms are the
        half-space's).

    Returns
    -------
    TheoryJob
        ``params``, ``profile`` and ``friction`` as the closed forms take them; a contact's friction law with its
        ``τ0`` in ``params`` (as ``friction=`` beside a :class:`~mdr_events.Parameters`).

    Raises
    ------
    TypeError
        ``contact`` of another type, naming it.
    ValueError
        ``d_max`` beside a :class:`~mdr_events.Parameters`, ``profile`` or ``friction`` beside a Contact, a depth
        that is not a finite number > 0, or a contact on a layer of finite thickness (``Contact.layer``).
    """
    if isinstance(contact, Parameters):
        if d_max is not None:
            raise ValueError(f"d_max={shown(d_max)} is not allowed beside Parameters; allowed: None (its own "
                             f"d_max = {contact.d_max!r} m; Parameters.replace(d_max=...) changes it)")
        return TheoryJob(contact, profile, as_friction_law(friction))
    contact = rate_independent(contact_alone(contact, profile, friction), "the closed forms (rate-independent)")
    check_half_space(contact, what)
    depth = PAPER_D_MAX if d_max is None else check_real("d_max", d_max, "a finite number > 0 (m)",
                                                         lambda value: value > 0.0)
    return TheoryJob(contact.parameters(depth, PAPER_V), contact.profile,
                     dataclasses.replace(contact.friction, tau0=None))


def on_layer(contact: Any) -> bool:
    """Whether ``contact`` is a :class:`~mdr_events.Contact` on a layer of finite thickness (``Contact.layer``): the
    closed forms that take a layer hand it to :mod:`mdr_events.theory.layer`."""
    return isinstance(contact, Contact) and not contact.layer.is_half_space


def paper_parameters(contact: Any, what: str, d_max: float | None = None) -> Parameters:
    """The :class:`~mdr_events.Parameters` of :func:`theory_job` for the closed forms of the paper's paraboloid (4)
    under its friction law (13) (:mod:`mdr_events.theory.analytic`); a contact of another indenter or law is refused,
    naming the closed forms that serve it (``what`` names the function asked)."""
    job = theory_job(contact, d_max, what=what)
    if job.profile is not None:
        raise ValueError(f"{what} of contact.indenter={job.profile!r} is not allowed here; allowed: a Contact of a "
                         "Paraboloid (the closed forms of eqs. (9)-(21)). Another indenter's are in "
                         "mdr_events.power_law and mdr_events.tabulated, and phase_diagram(contact, ...) takes any")
    if not job.friction.is_default:
        raise ValueError(f"{what} under contact.friction={contact.friction!r} is not allowed here; allowed: the law "
                         "'tau0' of eq. (13). The other laws' closed forms are in mdr_events.mindlin, and "
                         "phase_diagram(contact, ...) takes any")
    return job.params
