"""What the power law's closed forms are given, checked: the indenter (a power law or the flat punch), the work
of adhesion, the path angles and the "+" branch's deepest point; their output's shape; each kind's closed forms looked
up (:func:`_forms`).
"""

from __future__ import annotations

import numpy as np

from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, PowerLaw, Profile
from mdr_events.theory import symbolic
from mdr_events.theory.analytic.arguments import check_work, final_depth_of  # noqa: F401 - re-exported
from mdr_events.theory.forms import ClosedForms
from mdr_events.validation import check_flag, validate_alpha

__all__ = ["check_profile", "check_work", "as_output", "path_angles", "final_depth_of", "ADHESIVE_MIN_EXPONENT",
           "check_onset_scales"]


def _rel(key: str):
    return symbolic.relation(key)


#: With adhesion a power law needs ``n`` above this: below it ``√a`` outgrows ``aⁿ`` and no contact is stable.
ADHESIVE_MIN_EXPONENT = 0.5


def check_profile(profile) -> Profile:
    """``profile`` if it is a :class:`PowerLaw` or a :class:`FlatPunch`; else ``TypeError`` naming it.

    Parameters
    ----------
    profile : object
        The indenter to check.

    Returns
    -------
    PowerLaw or FlatPunch
        ``profile`` itself.

    Raises
    ------
    TypeError
        Any other type (the paraboloid and a table have their own modules).
    """
    if not isinstance(profile, (PowerLaw, FlatPunch)):  # (what the package takes; each kind's forms: _forms)
        raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed; allowed: a PowerLaw or "
                        "a FlatPunch (mdr_events.contact.indenters)")
    return profile


_check_work = check_work


def _check_adhesive(profile: PowerLaw, work_of_adhesion: float) -> None:
    if work_of_adhesion > 0.0 and not profile.n > ADHESIVE_MIN_EXPONENT:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed with adhesion (work of adhesion "
                         f"{work_of_adhesion!r} J/m²); allowed: n > {ADHESIVE_MIN_EXPONENT:g} (below it no "
                         "adhesive contact is stable)")


def _power_law_only(profile, what: str) -> PowerLaw:
    if not isinstance(check_profile(profile), PowerLaw):
        raise TypeError(f"profile={profile!r} is not allowed for {what}; allowed: a PowerLaw (a flat punch keeps "
                        "its radius while in contact)")
    return profile


def as_output(values: np.ndarray, like) -> np.ndarray | float:
    """``values`` as a float where ``like`` is a scalar, else as they are."""
    return float(values) if np.ndim(like) == 0 else values


def path_angles(alpha, adhesion) -> tuple[np.ndarray, np.ndarray]:
    """``adhesion`` checked as a flag, ``alpha`` as path angles (degrees, :func:`validate_alpha`), and where they are
    vertical (``>= 90°``: no tangential shift, never slides)."""
    check_flag("adhesion", adhesion)
    alpha_arr = validate_alpha(alpha)
    return alpha_arr, alpha_arr >= 90.0


def _forms(profile) -> ClosedForms:
    """The closed forms of ``profile``'s kind, ``profile`` checked (a power law or the flat punch).

    Looked up by :func:`mdr_events.theory.kinds.theory_of`, imported when called: kinds files the package's functions
    (and :mod:`mdr_events.theory.flat_punch` imports the package), so it cannot be imported on the package's import.
    """
    from mdr_events.theory.kinds import theory_of

    return theory_of(check_profile(profile)).closed_forms


def check_onset_scales(params: Parameters, profile: Profile, adhesion: bool, friction: FrictionLaw = TAU0) -> None:
    """The scales of a slip onset's closed form checked as the phase diagram's and the runs' are, before it is
    computed (:func:`~mdr_events.theory.scales.check_representable`; the paraboloid's of ``analytic`` are already).

    With ``adhesion`` the works' branches are the onset's (their jump-off among the scales), without it they are not
    read (a non-adhesive onset takes any exponent): ``check_representable``'s ``adhesion=False`` on the caller's own
    ``Parameters``, so that a sweep's repeated check is found kept and a refusal names the works given. A power law
    near ``n = 1/2`` with adhesion raises its radii to ``1/(2n − 1)``: ``n = 0.501`` gave ``nan`` onsets and critical
    angles with NumPy's overflow, ``n = 0.5 + 1e-10`` with ``Δγ0 = 1e4`` J/m² Python's own ``OverflowError``; now
    refused naming the scale that does not fit (issue 32 round 29 B2).

    Parameters
    ----------
    params : Parameters
        The material, ``τ0``, the works and ``d_max``.
    profile : PowerLaw or FlatPunch
        The indenter, checked.
    adhesion : bool
        Whether the onset is that of the adhesive branches (checked as a flag).
    friction : FrictionLaw, optional
        The law, whose Coulomb part is a scale of its own (default the paper's ``"tau0"``).

    Raises
    ------
    ValueError
        Naming the first scale that does not fit in double precision, and the bound.
    """
    from mdr_events.theory.scales import check_representable  # (scales imports the closed forms)

    check_flag("adhesion", adhesion)
    check_representable(params, profile, friction, adhesion)
