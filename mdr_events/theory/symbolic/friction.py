"""The local Coulomb law of the MDR springs and the Cattaneo–Mindlin solution it gives (:func:`derive_friction_model`)."""

from __future__ import annotations

import functools

import sympy as sp

from mdr_events.theory.symbolic.symbols import a, c, d, dx, E_star, F_x, G_star, mu, n, u_bar, u_x, u_z, x
from mdr_events.theory.symbolic.derived_relation import Relation
from mdr_events.theory.symbolic.cache import cached_relations
from mdr_events.theory.symbolic.power_law import derive_power_law, derive_power_law_model

__all__ = ["derive_friction_model", "FRICTION_KEYS"]


#: Keys of the friction-law relations (:func:`derive_friction_model`).
FRICTION_KEYS = ("coulomb_critical_shift", "cattaneo_mindlin_stick_radius", "cattaneo_mindlin_force",
                 "cattaneo_mindlin_full_slip_shift")


@functools.cache
def derive_friction_model() -> dict[str, Relation]:
    """The local Coulomb law of the MDR springs and the Cattaneo–Mindlin solution it gives.

    A spring of width ``Δx`` holds the tangential force ``G* Δx u`` up to ``μ`` times its normal force
    ``E* Δx u_z``: its cap is ``ū = μ (E*/G*) u_z`` (Popov & Heß 2015, ch. 5). Under a constant depth ``d``
    of a non-adhesive power-law indenter, a tangential shift ``u_x`` of the indenter from rest leaves the
    springs with ``μ (E*/G*) (d − g(ξ)) > u_x`` sticking: the stick radius ``c`` has ``g(c) = d − u_x G*/(μ E*)``,
    and ``F_x = 2G* (u_x c + ∫_c^a μ (E*/G*)(d − g) dξ)``. The derivation checks that this is
    ``μ (F_N(d) − F_N(d − u_x G*/(μ E*)))`` (Cattaneo 1938, Mindlin 1949; for any profile, Jäger 1998 and
    Ciavarella 1998): the tangential curve is the normal one, shifted and scaled.
    """
    return cached_relations("friction_model", friction_model_afresh)


def friction_model_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_friction_model` with SymPy (about 15 s), bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    # the spring slides once its tangential force reaches μ times its normal force
    cap = sp.solve(sp.Eq(G_star * dx * u_bar, mu * E_star * dx * u_z), u_bar)[0]
    add(Relation("coulomb_critical_shift", "(13)", "Coulomb's critical spring shift: mu (E*/G*) times the "
                 "spring's compression", u_bar, cap, (u_z, mu, E_star, G_star)))
    model = derive_power_law_model()
    hertz_radius = model["power_law_hertz_radius"].rhs  # a(d) of the non-adhesive power law
    normal_force = model["power_law_normal_force"].rhs.subs(a, hertz_radius)  # F_N(d)
    lowered = d - u_x / cap.subs(u_z, 1)  # the depth whose radius is the stick radius
    stick = hertz_radius.subs(d, lowered)
    profile = derive_power_law().rhs
    force = 2 * G_star * (u_x * stick + cap.subs(u_z, 1) * sp.integrate(d - profile, (x, stick, hertz_radius)))
    jager_ciavarella = mu * (normal_force - normal_force.subs(d, lowered))
    if sp.simplify(sp.expand(force - jager_ciavarella)) != 0:
        raise RuntimeError("the Cattaneo-Mindlin force of the springs is not mu (F_N(d) - F_N(d - u_x/kappa))")
    arguments = (u_x, d, mu, c, n, E_star, G_star)
    add(Relation("cattaneo_mindlin_stick_radius", "", "stick radius of a power-law contact at depth d shifted "
                 "by u_x (Coulomb's law, from rest)", a, stick, arguments))
    add(Relation("cattaneo_mindlin_force", "", "tangential force of a power-law contact at depth d shifted by u_x "
                 "from rest (Cattaneo-Mindlin), u_x below full slip", F_x, jager_ciavarella, arguments))
    add(Relation("cattaneo_mindlin_full_slip_shift", "", "tangential shift at which the whole contact slides "
                 "(Coulomb's law, from rest): the centre's cap", u_x, sp.solve(sp.Eq(lowered, 0), u_x)[0],
                 (d, mu, E_star, G_star)))
    return out
