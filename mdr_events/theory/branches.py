"""The contact radius of a depth on an adhesive branch and the branch's jump-off, for any indenter: the paper's
paraboloid (``profile=None``, of ``Parameters.R``; its own functions bit for bit), a power law, the flat punch or a
table (each kind's own, :func:`mdr_events.theory.kinds.theory_of`)."""

from __future__ import annotations

from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import Profile
from mdr_events.theory.kinds import theory_of

__all__ = ["branch_radius", "jump_off"]


def branch_radius(depth, params: Parameters, work_of_adhesion: float, profile: Profile | None = None):
    """The contact radius on the branch of ``work_of_adhesion`` at ``depth`` (``nan`` below its jump-off; the
    flat punch's radius down to its jump-off)."""
    return theory_of(profile).branch_radius(depth, profile, params, work_of_adhesion)


def jump_off(params: Parameters, work_of_adhesion: float, profile: Profile | None = None) -> dict[str, float]:
    """The branch's jump-off under displacement control (``contact_radius``, ``depth``, ``normal_force``)."""
    return theory_of(profile).jump_off(profile, params, work_of_adhesion)
