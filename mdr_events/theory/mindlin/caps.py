"""The friction laws' caps at a constant depth: Coulomb's cap ratio ``κ = μ E*/G*``, ``τ0``'s cap per radius ``K``,
and the contact they act on (the indenter, the compressed zone ``x_c`` and the contact's radius ``a >= x_c``), its
arguments checked.
"""

from __future__ import annotations

from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import PowerLaw, Profile
from mdr_events.theory import power_law, symbolic
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import check_real

__all__ = ["coulomb_cap_ratio"]


def coulomb_cap_ratio(friction: FrictionLaw, params: Parameters) -> float:
    r"""``κ = μ E*/G*``: Coulomb's cap is ``κ`` times the spring's compression (0 without Coulomb's part).

    .. math:: \bar u(\xi) = \kappa \max(d - g(\xi), 0), \qquad \kappa = \mu \frac{E^*}{G^*}

    Parameters
    ----------
    friction : FrictionLaw or str
        The friction law; its ``μ`` (0 for ``"tau0"``).
    params : Parameters
        The material (``E*``, ``G*``).

    Returns
    -------
    float
        ``κ`` (1).
    """
    friction = as_friction_law(friction)
    return float(symbolic.relation("coulomb_critical_shift").numeric(1.0, friction.coulomb_mu, params.E_star,
                                                                     params.G_star))


def _checked(depth, friction, params: Parameters, profile) -> tuple[float, FrictionLaw, Profile]:
    depth = check_real("depth", depth, "a finite number > 0 (m)", lambda value: value > 0.0)
    return depth, as_friction_law(friction), _indenter(profile, params)


def _contact_radius(depth: float, params: Parameters, profile: Profile, radius) -> float:
    """The radius ``a`` of the contact at ``depth`` (m): ``radius`` checked, or without it the radius indented to
    ``depth`` (the ``Δγ0`` branch (9); without adhesion the compressed zone's ``x_c``). A radius below ``x_c`` (where
    ``g(x_c) = d``) is no contact at that depth: every spring under the indenter is in contact."""
    zone = _radius(depth, profile)
    if radius is None:
        if params.dgamma0 == 0.0:
            return zone
        return float(theory_of(profile).branch_radius(depth, profile, params, params.dgamma0))
    allowed = f"a finite radius >= the compressed zone's x_c = {zone!r} m at depth {depth!r} m, or None"
    return check_real("radius", radius, allowed, lambda value: value >= zone * (1.0 - _RADIUS_SHARE))


#: A given contact radius may lie this share below the compressed zone's ``x_c`` (the rounding of a radius found
#: by a root of (9) at a depth whose zone it equals, without adhesion).
_RADIUS_SHARE = 1e-12


def _indenter(profile: Profile | None, params: Parameters) -> Profile:
    """``profile``, checked; ``None`` is the paraboloid of ``params.R``."""
    return PowerLaw.paraboloid(params.R) if profile is None else power_law.check_profile(profile)


def _tau0_per_radius(friction: FrictionLaw, params: Parameters) -> float:
    """``K`` of the law's ``τ0`` part, ``ū = K a`` (13); 0 without it."""
    return power_law.cap_per_radius(params) if friction.uses_tau0 else 0.0


def _radius(depth: float, profile: Profile) -> float:
    """The contact radius at ``depth`` (> 0) without adhesion (the flat punch's own)."""
    return float(theory_of(profile).branch_radius(depth, profile, _NO_ADHESION, 0.0))


#: The non-adhesive radius needs no material (any valid parameters serve :func:`power_law.contact_radius`).
_NO_ADHESION = Parameters(E=1.0, nu=0.0, R=1.0, tau0=0.0, dgamma0=0.0, dgamma1=0.0, d_max=1.0, v=1.0)

