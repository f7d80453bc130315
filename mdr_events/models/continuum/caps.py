"""The friction law's caps on the springs' shifts, as the continuum uses them.

A spring at ``ξ`` of a contact of radius ``a`` at depth ``d`` slides once its shift reaches
``ū(ξ) = K a + κ (d − g(ξ))`` (:mod:`mdr_events.contact.friction`): ``K a`` is the part of ``τ0`` (13), the same for every
spring, and ``κ = μ E*/G*`` Coulomb's, proportional to the spring's compression. Each cap's *level*, where the
anchors of its springs sit, is ``x − cap (K a + κ d)`` in the coordinates the cap sees the anchors in
(:meth:`~.anchors.AnchorMap.seen_by`: ``Y − cap κ g``), so the slip zones are laid out as for ``τ0`` alone.
Without adhesion every spring in contact is compressed and springs attach along ``d0 = g``. With adhesion the springs
beyond ``x_c`` (``g(x_c) = d``) are in tension, with the cap ``K a`` alone
(:func:`~mdr_events.theory.symbolic.derive_adhesive_friction_model`). Coulomb's law alone (``K = 0``) is then exact by
the compressed zone (:func:`compressed_zone_alone`): the springs in tension slide with no shift and enter compression
at ``x_c`` with none, as springs attaching to a contact without adhesion do, so the tangential force is that of the
non-adhesive contact of the same path (``solve_path`` runs it beside the adhesive contact's radius). On the flat punch
every spring rests on ``g = 0``: all share the cap ``K a + κ max(d, 0)`` (``flat_punch_friction_cap``; ``K a`` alone
in tension, an adhesive punch held above the surface) and one anchor history, one play operator; the anchors are seen
as they are (the branch's ``flat``), every span is pinned, linear in time, and the planner ends a span where the depth
crosses 0 (the caps' kink). Both parts with adhesion on a curved indenter split the contact at ``x_c`` into two
regions with caps of their own (:func:`split_regions`, :mod:`.split_span`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from mdr_events.contact.friction import FrictionLaw
from mdr_events.parameters import Parameters
from mdr_events.theory import mindlin, power_law
from mdr_events.theory.kinds import theory_of

from .media import HALF_SPACE_MEDIUM, HalfSpaceMedium


class Caps(NamedTuple):
    """``ū(ξ) = K a + κ (d − g(ξ))``: the two parts of a friction law's cap."""

    #: the cap per contact radius of ``τ0``'s part (13) (0 without it)
    K: float
    #: Coulomb's cap per unit of compression, ``μ E*/G*`` (0 without it)
    kappa: float
    #: what the springs are made of (:mod:`.media`): on a layer ``τ0``'s part is ``ū(a) = K a/Φ_t(a/h)``
    medium: HalfSpaceMedium = HALF_SPACE_MEDIUM

    @property
    def frictionless(self) -> bool:
        """No spring holds a shift: every spring slides from the start and ``F_x ≡ 0``."""
        return self.K == 0.0 and self.kappa == 0.0

    def centre_shift(self, radius: float, depth: float) -> float:
        """The cap of the spring at the centre, ``K a + κ max(d, 0)``, by which each level stands off ``x`` (in
        tension, ``d < 0``: an adhesive flat punch held above the surface, ``K a`` alone)."""
        if not self.kappa:
            return self.medium.shift(self.K, radius)
        pressed = (depth if depth > 0.0 else 0.0) if type(depth) is float else np.maximum(depth, 0.0)
        return self.K * radius + self.kappa * pressed


def caps_of(friction: FrictionLaw, params: Parameters, medium: HalfSpaceMedium = HALF_SPACE_MEDIUM) -> Caps:
    """The parts of ``friction``'s caps for the material of ``params`` in ``medium`` (default the half-space)."""
    K = power_law.cap_per_radius(params) if friction.uses_tau0 else 0.0
    return Caps(K, mindlin.coulomb_cap_ratio(friction, params), medium)


def compressed_zone_alone(caps: Caps, dgamma0: float, dgamma1: float) -> bool:
    """Whether the tangential force is the compressed zone's alone: Coulomb's caps without ``τ0``'s part (``K = 0``)
    in an adhesive contact (``Δγ0`` or ``Δγ1`` > 0; module docstring)."""
    return caps.K == 0.0 and caps.kappa > 0.0 and (dgamma0 != 0.0 or dgamma1 != 0.0)


def split_regions(caps: Caps, dgamma0: float, dgamma1: float, profile=None) -> bool:
    """Whether the contact has two regions with different caps: both parts of the law (``K > 0``, ``κ > 0``) with
    adhesion (``Δγ0`` or ``Δγ1`` > 0) on a curved indenter. The springs in tension keep ``τ0``'s cap ``K a``, the
    compressed ones add Coulomb's: the compressed zone and the tensile annulus are laid out apart, split at the moving
    ``x_c`` (:mod:`.split_span`). On the flat punch every spring shares one cap (module docstring)."""
    adhesive = dgamma0 != 0.0 or dgamma1 != 0.0
    return caps.K > 0.0 and caps.kappa > 0.0 and adhesive and not theory_of(profile).flat_face
