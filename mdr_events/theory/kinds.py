"""Each kind of indenter's theory, looked up by its type in one place (:func:`theory_of`).

The indenter types (:mod:`mdr_events.contact.indenters`) are data and sit below the theory, so what the theory
computes for each kind is filed here by type: the contact radius of a depth on an adhesive branch, the branch's
jump-off, how deep the indenter reaches, the springs' profile ``g(x)``, the critical angles of the paper's friction
law ``τ0``, whether the closed forms of the other friction laws (:mod:`mdr_events.theory.mindlin`) serve it, and the
closed forms :mod:`mdr_events.theory.power_law`'s functions of either indenter hand it to (the power law's own, the
flat punch's in :mod:`mdr_events.theory.flat_punch`).
The layers above ask for these by name instead of testing the type. ``None`` is the paper's paraboloid of
``Parameters.R``, served by the paper's own functions (:mod:`mdr_events.theory.analytic`) bit for bit.

A new kind of indenter is one more entry of :data:`_THEORIES` (with its relations in
:mod:`mdr_events.theory.symbolic` and its closed forms in a module of its own).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from mdr_events.contact.indenters import FlatPunch, PowerLaw, Profile, TabulatedProfile, indenter_kind
from mdr_events.parameters import Parameters
from mdr_events.theory import analytic, flat_punch, power_law, symbolic, tabulated
from mdr_events.theory.power_law.normal import _equivalent_profile as _power_law_profile
from mdr_events.theory.forms import ClosedForms, FrictionForms

__all__ = ["IndenterTheory", "theory_of"]

#: The springs' profile ``g(x)`` as a function of positions (m).
SpringProfile = Callable[[np.ndarray], np.ndarray]


@dataclass(frozen=True)
class IndenterTheory:
    """What the theory computes for one kind of indenter (``profile`` is the indenter, ``None`` the paraboloid).

    Attributes
    ----------
    branch_radius : callable
        ``(depth, profile, params, work_of_adhesion)``: the contact radius on the branch of ``work_of_adhesion`` at
        ``depth`` (``nan`` below its jump-off; the flat punch's own radius down to it).
    jump_off : callable
        ``(profile, params, work_of_adhesion)``: the branch's jump-off under displacement control
        (``contact_radius``, ``depth``, ``normal_force``).
    deepest : callable
        ``(profile, params, work_of_adhesion)``: the deepest depth a path may reach (m): ``+inf`` for an indenter of
        any extent, a table's where the contact radius on the branch of ``work_of_adhesion`` reaches its last radius.
    spring_profile : callable
        ``(profile, params)``: the springs' profile ``g(x)`` as derived by :mod:`~mdr_events.theory.symbolic`.
    critical_angle : callable
        ``(profile, params, scenario)``: scenario A's or B's adhesive critical angle under ``τ0`` (degrees).
    friction_closed_forms : bool
        Whether :mod:`mdr_events.theory.mindlin`'s closed forms of the other friction laws take the kind.
    flat_face : bool, default False
        Whether the indenter's face is flat (``f = 0`` under it): its springs' profile ``0`` there and its branch's
        radius the face's on a layer of any thickness too (the generalized MDR's ``g`` of ``f = 0``).
    closed_forms : ClosedForms or None, default None
        The kind's closed forms behind :mod:`~mdr_events.theory.power_law`'s functions of either indenter (``None``:
        they do not take the kind).
    friction_forms : FrictionForms or None, default None
        The kind's own closed forms under :mod:`~mdr_events.theory.mindlin`'s friction laws (``None``: a curved
        indenter's serve it).
    """

    branch_radius: Callable[..., object]
    jump_off: Callable[[Profile | None, Parameters, float], dict[str, float]]
    deepest: Callable[[Profile | None, Parameters, float], float]
    spring_profile: Callable[[Profile | None, Parameters], SpringProfile]
    critical_angle: Callable[[Profile | None, Parameters, str], float]
    friction_closed_forms: bool
    flat_face: bool = False
    closed_forms: ClosedForms | None = None
    friction_forms: FrictionForms | None = None


def _any_depth(profile: Profile | None, params: Parameters, work_of_adhesion: float) -> float:
    """An indenter of any extent reaches any depth."""
    return math.inf


def _paraboloid_springs(profile: None, params: Parameters) -> SpringProfile:
    """``g(x) = x²/R`` (4)."""
    relation = symbolic.relation("profile_paraboloid")
    return lambda x: relation.numeric(x, params.R)


def _power_law_springs(profile: PowerLaw, params: Parameters) -> SpringProfile:
    """``g(x) = κ c |x|ⁿ`` (3)."""
    return lambda x: _power_law_profile(x, profile)  # (unchecked: the springs' own coordinates)


def _flat_punch_springs(profile: FlatPunch, params: Parameters) -> SpringProfile:
    """``0`` under the punch's face and ``+inf`` beyond it (no spring there is ever touched)."""
    return lambda x: np.where(np.abs(np.asarray(x, dtype=float)) <= profile.radius, 0.0, np.inf)


def _power_law_critical_angle(profile: PowerLaw | FlatPunch, params: Parameters, scenario: str) -> float:
    return power_law.critical_angle_A(profile, params) if scenario == "A" else power_law.critical_angle_B(profile,
                                                                                                          params)


def _table_critical_angle(profile: TabulatedProfile, params: Parameters, scenario: str) -> float:
    if scenario != "A":
        raise ValueError(f"scenario={scenario!r} is not allowed for a tabulated profile's critical angle; allowed: "
                         "'A' (scenario B's onset on a table is not derived yet)")
    return tabulated.critical_angle_A(profile, params)


_PARABOLOID = IndenterTheory(
    branch_radius=lambda depth, profile, params, work: analytic.jkr_contact_radius(depth, params, work),
    jump_off=lambda profile, params, work: analytic.jump_off(params, work),
    deepest=_any_depth,
    spring_profile=_paraboloid_springs,
    critical_angle=lambda profile, params, scenario: analytic.critical_angle(params, scenario),
    friction_closed_forms=True)
_POWER_LAW = IndenterTheory(
    branch_radius=power_law.contact_radius,
    jump_off=power_law.jump_off,
    deepest=_any_depth,
    spring_profile=_power_law_springs,
    critical_angle=_power_law_critical_angle,
    friction_closed_forms=True,
    closed_forms=power_law.CLOSED_FORMS)
_FLAT_PUNCH = IndenterTheory(
    branch_radius=flat_punch.radius,
    jump_off=flat_punch.jump_off,
    deepest=_any_depth,
    spring_profile=_flat_punch_springs,
    critical_angle=_power_law_critical_angle,
    friction_closed_forms=True,
    flat_face=True,
    closed_forms=flat_punch.CLOSED_FORMS,
    friction_forms=flat_punch.FRICTION_FORMS)
_TABLE = IndenterTheory(
    branch_radius=tabulated.contact_radius,
    jump_off=tabulated.jump_off,
    deepest=lambda profile, params, work: tabulated.branch(profile, params, work).deepest,
    spring_profile=lambda profile, params: tabulated.equivalent(profile),
    critical_angle=_table_critical_angle,
    friction_closed_forms=False)

#: Each kind's theory by the indenter's type (``NoneType``: the paraboloid of ``Parameters.R``).
_THEORIES: dict[type, IndenterTheory] = {type(None): _PARABOLOID, PowerLaw: _POWER_LAW, FlatPunch: _FLAT_PUNCH,
                                         TabulatedProfile: _TABLE}


def theory_of(profile: Profile | None) -> IndenterTheory:
    """The theory of ``profile``'s kind (``None``: the paraboloid of ``Parameters.R``).

    A subclass of an indenter type is of its base's kind (the first filed type along its MRO). Anything else is
    handed to the power law's functions, which name what they take (``TypeError``).

    Parameters
    ----------
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter.

    Returns
    -------
    IndenterTheory
        What the theory computes for its kind.
    """
    return _THEORIES.get(indenter_kind(profile), _POWER_LAW)
