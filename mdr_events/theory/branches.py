"""The contact radius of a depth on an adhesive branch and the branch's jump-off, for any indenter: the paper's
paraboloid (``profile=None``, of ``Parameters.R``; its own functions bit for bit), a power law, the flat punch or a
table."""

from __future__ import annotations

from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, Profile, TabulatedProfile
from mdr_events.theory import analytic, power_law, tabulated

__all__ = ["branch_radius", "jump_off"]


def branch_radius(depth, params: Parameters, work_of_adhesion: float, profile: Profile | None = None):
    """The contact radius on the branch of ``work_of_adhesion`` at ``depth`` (``nan`` below its jump-off; the
    flat punch's radius down to its jump-off)."""
    if profile is None:
        return analytic.jkr_contact_radius(depth, params, work_of_adhesion)
    if isinstance(profile, FlatPunch):
        return power_law.flat_punch_radius(depth, profile, params, work_of_adhesion)
    if isinstance(profile, TabulatedProfile):
        return tabulated.contact_radius(depth, profile, params, work_of_adhesion)
    return power_law.contact_radius(depth, profile, params, work_of_adhesion)


def jump_off(params: Parameters, work_of_adhesion: float, profile: Profile | None = None) -> dict[str, float]:
    """The branch's jump-off under displacement control (``contact_radius``, ``depth``, ``normal_force``)."""
    if profile is None:
        return analytic.jump_off(params, work_of_adhesion)
    if isinstance(profile, TabulatedProfile):
        return tabulated.jump_off(profile, params, work_of_adhesion)
    return power_law.jump_off(profile, params, work_of_adhesion)
