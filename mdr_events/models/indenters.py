"""The indenter the simulators take: the paper's paraboloid (``profile=None``, of ``Parameters.R``), a
power law ``f = c rⁿ`` (:class:`~mdr_events.contact.indenters.PowerLaw`, ``n >= 1``) or the flat punch
(:class:`~mdr_events.contact.indenters.FlatPunch`), and what the paths and the discrete model read off it: the radius
of a depth on a branch, the jump-off, the springs' profile ``g(x)``.

For ``profile=None`` every function is the paper's own (:mod:`mdr_events.theory.analytic`), so that the
paraboloid's runs are those of before, bit for bit.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, Paraboloid, PowerLaw, TabulatedProfile, indenter_kind, profile_attrs
from mdr_events.theory import mindlin, tabulated
from mdr_events.theory.branches import branch_radius, jump_off
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import allowed_bound

__all__ = ["MIN_SIMULATED_EXPONENT", "SimulatedProfile", "check_simulated_profile", "check_reach", "branch_radius", "jump_off", "spring_profile",
           "profile_attrs", "critical_angle"]

#: The simulators take power laws from the cone on (a profile with ``n < 1`` has an infinite slope at the
#: centre, where the contact of a non-adhesive indenter starts).
MIN_SIMULATED_EXPONENT = 1.0


#: An indenter the simulators take (``None``: the paraboloid of ``Parameters.R``).
SimulatedProfile = PowerLaw | FlatPunch | TabulatedProfile | None


def check_simulated_profile(profile) -> SimulatedProfile:
    """``profile`` if the simulators take it (``None``, a :class:`PowerLaw` with ``n >= 1``, a :class:`FlatPunch` or
    a :class:`TabulatedProfile` whose ``g(x)`` increases); else an error naming it and what is allowed."""
    check = _SIMULATOR_CHECKS.get(indenter_kind(profile))
    if check is None:
        hint = (" (the paraboloid is Parameters.R's: leave profile=None, or give a Contact with it)"
                if isinstance(profile, Paraboloid) else "")
        raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed{hint}; allowed: None (the "
                        f"paraboloid of R), a PowerLaw with n >= {MIN_SIMULATED_EXPONENT:g}, a FlatPunch or a "
                        "TabulatedProfile")
    check(profile)
    return profile


def _check_simulated_exponent(profile: PowerLaw) -> None:
    if not profile.n >= MIN_SIMULATED_EXPONENT:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed in the simulators; allowed: n >= "
                         f"{MIN_SIMULATED_EXPONENT:g} (the cone and blunter)")


#: What the simulators check of each kind they take, by its type (a table: its ``g(x)`` must increase, an error
#: names where).
_SIMULATOR_CHECKS: dict[type, Callable[[object], object]] = {
    type(None): lambda profile: None, FlatPunch: lambda profile: None, PowerLaw: _check_simulated_exponent,
    TabulatedProfile: tabulated.equivalent}


def check_reach(params: Parameters, depth: float, profile: SimulatedProfile, label: str) -> None:
    """Refuse a path going deeper than the indenter reaches: a tabulated profile's contact radius on the ``Δγ0``
    branch would pass the table's last radius at ``depth`` (``ValueError`` naming both). Other profiles reach any
    depth."""
    deepest = theory_of(profile).deepest(profile, params, params.dgamma0)
    if depth > deepest:
        where = (f"at most {allowed_bound(deepest, lambda most: most <= deepest, True)} m, where the contact radius "
                 "reaches the table's last radius" if deepest > 0 else
                 f"none: with this adhesion the contact radius reaches the table's last radius above the surface "
                 f"(at d = {deepest:.3g} m)")
        raise ValueError(f"{label} reaches the depth {depth:.6g} m; allowed for {profile.describe()!r}: {where} (a "
                         "table reaching further, or a shallower path)")


def spring_profile(params: Parameters, profile: SimulatedProfile = None) -> Callable[[np.ndarray], np.ndarray]:
    """The springs' profile ``g(x)``: ``x²/R`` (4), or ``κ c |x|ⁿ`` (3), as derived by :mod:`~mdr_events.theory.symbolic`;
    the flat punch's ``0`` under its face and ``+inf`` beyond it (no spring there is ever touched); a table's
    numerical Abel transform."""
    return theory_of(profile).spring_profile(profile, params)


def critical_angle(params: Parameters, scenario: str, profile: SimulatedProfile = None,
                   friction: FrictionLaw = TAU0) -> float:
    """Scenario A's or B's critical angle (adhesive) for ``profile`` (:func:`mdr_events.theory.analytic.critical_angle`
    for the paraboloid, :mod:`mdr_events.theory.power_law` for a power law, :mod:`mdr_events.theory.tabulated` for a
    table's scenario A); for a friction law with Coulomb's part the closed forms without adhesion
    (:mod:`mdr_events.theory.mindlin`), ``nan`` with adhesion or a table (there are none)."""
    kind = theory_of(profile)
    if friction.coulomb_mu > 0.0 or not friction.uses_tau0:
        if params.dgamma0 > 0.0 or params.dgamma1 > 0.0 or not kind.friction_closed_forms:
            return math.nan
        return (mindlin.critical_angle_A if scenario == "A" else mindlin.critical_angle_B)(friction, params, profile)
    return kind.critical_angle(profile, params, scenario)
