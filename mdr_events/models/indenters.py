"""The indenter the simulators take: the paper's paraboloid (``profile=None``, of ``Parameters.R``) or a
power law ``f = c rⁿ`` (:class:`~mdr_events.profiles.PowerLaw`, ``n >= 1``), and what the paths and the
discrete model read off it: the radius of a depth on a branch, the jump-off, the springs' profile ``g(x)``.

For ``profile=None`` every function is the paper's own (:mod:`mdr_events.theory.analytic`), so that the
paraboloid's runs are those of before, bit for bit.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from mdr_events.parameters import Parameters
from mdr_events.profiles import FlatPunch, PowerLaw, profile_attrs
from mdr_events.theory import analytic, power_law, symbolic

__all__ = ["MIN_SIMULATED_EXPONENT", "check_simulated_profile", "branch_radius", "jump_off", "spring_profile",
           "profile_attrs", "critical_angle"]

#: The simulators take power laws from the cone on (a profile with ``n < 1`` has an infinite slope at the
#: centre, where the contact of a non-adhesive indenter starts).
MIN_SIMULATED_EXPONENT = 1.0


def check_simulated_profile(profile) -> PowerLaw | None:
    """``profile`` if the simulators take it (``None`` or a :class:`PowerLaw` with ``n >= 1``); else an error
    naming it and what is allowed."""
    if profile is None:
        return None
    if isinstance(profile, FlatPunch):
        raise ValueError(f"profile={profile!r} is not allowed in the simulators (a flat punch keeps its radius in "
                         "contact: its closed forms are in mdr_events.power_law); allowed: None (the paraboloid of "
                         f"R) or a PowerLaw with n >= {MIN_SIMULATED_EXPONENT:g}")
    if not isinstance(profile, PowerLaw):
        raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed; allowed: None (the "
                        f"paraboloid of R) or a PowerLaw with n >= {MIN_SIMULATED_EXPONENT:g}")
    if not profile.n >= MIN_SIMULATED_EXPONENT:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed in the simulators; allowed: n >= "
                         f"{MIN_SIMULATED_EXPONENT:g} (the cone and blunter)")
    return profile


def branch_radius(depth, params: Parameters, work_of_adhesion: float, profile: PowerLaw | None = None):
    """The contact radius on the branch of ``work_of_adhesion`` at ``depth`` (``nan`` below its jump-off)."""
    if profile is None:
        return analytic.jkr_contact_radius(depth, params, work_of_adhesion)
    return power_law.contact_radius(depth, profile, params, work_of_adhesion)


def jump_off(params: Parameters, work_of_adhesion: float, profile: PowerLaw | None = None) -> dict[str, float]:
    """The branch's jump-off under displacement control (``contact_radius``, ``depth``, ``normal_force``)."""
    if profile is None:
        return analytic.jump_off(params, work_of_adhesion)
    return power_law.jump_off(profile, params, work_of_adhesion)


def spring_profile(params: Parameters, profile: PowerLaw | None = None) -> Callable[[np.ndarray], np.ndarray]:
    """The springs' profile ``g(x)``: ``x²/R`` (4), or ``κ c |x|ⁿ`` (3), as derived by :mod:`~mdr_events.theory.symbolic`."""
    if profile is None:
        relation = symbolic.relation("profile_paraboloid")
        return lambda x: relation.numeric(x, params.R)
    return lambda x: power_law.equivalent_profile(x, profile)


def critical_angle(params: Parameters, scenario: str, profile: PowerLaw | None = None) -> float:
    """Scenario A's or B's critical angle (adhesive) for ``profile`` (:func:`mdr_events.theory.analytic.critical_angle`
    for the paraboloid, :mod:`mdr_events.theory.power_law` for a power law)."""
    if profile is None:
        return analytic.critical_angle(params, scenario)
    return power_law.critical_angle_A(profile, params) if scenario == "A" else power_law.critical_angle_B(profile,
                                                                                                          params)
