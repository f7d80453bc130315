"""The contact of the MDR as LAMMPS's granular wall models take it: which models, and with which numbers.

LAMMPS (``fix wall/gran ... granular``, GRANULAR package, read in ``src/GRANULAR/gran_sub_mod*.cpp`` of the
22 Jul 2025 release) models a sphere of radius ``R`` against a flat wall. Its numbers follow from the sources:

**Moduli of a particle–wall contact.** The wall is given no material of its own: LAMMPS mixes the particle's
``E_L``, ``ν_L`` with an identical wall, ``E_mix = E_L / (2 (1 - ν_L²))`` (``mix_stiffnessE_wall``) and
``G_mix = E_L / (4 (2 - ν_L)(1 + ν_L))`` (``mix_stiffnessG_wall``). The MDR's indenter is rigid and the
elastomer has ``E``, ``ν``: ``E* = E / (1 - ν²)`` (5) and the Mindlin stiffness ``8 G a / (2 - ν) = 2 a G*``
(``G* = 4G/(2-ν)``, (6)). Both hold with ``E_L = 2 E`` and ``ν_L = ν``:

    E_mix = 2E / (2 (1-ν²)) = E*,   8 G_mix = 8 · 2E / (4 (2-ν)(1+ν)) = 8 G / (2-ν) = 2 G*.

**Normal models** (``gran_sub_mod_normal``), with the overlap ``δ = d`` (the depth) and ``R_eff = R`` at a wall:

- ``hertz/material E_L damp ν_L``: ``F = (4/3) E_mix a δ`` with ``a = sqrt(R δ)``: Hertz, the MDR without
  adhesion, exactly. Assumes no adhesion (``Δγ0``, ``Δγ1`` are not used).
- ``jkr E_L damp ν_L γ``: ``F = (4/3) E_mix a³/R - 2π a² sqrt(4 γ E_mix / (π a))`` =
  ``4E*a³/(3R) - sqrt(8π (2γ) E* a³)``: JKR with the work of adhesion ``Δγ = 2γ`` (``γ`` is a surface energy,
  the work of adhesion of two equal surfaces is twice it), so ``γ = Δγ/2``; the pull-off force ``3πγR`` is
  ``(3/2)πΔγR``. One ``γ`` serves both ways: LAMMPS's loading curve is the MDR's with ``Δγ0 = Δγ1``; the
  mapping takes ``γ = Δγ1/2`` (the unloading, which sets the pull-off), and a contact with ``Δγ0 ≠ Δγ1``
  differs on the way in. Contact begins at ``δ = 0`` (the jump onto the JKR curve, as Heß's rule at ``d = 0``)
  and ends at the separation ``δ_L = (3π²γ²R/(16 E_mix²))^(1/3)`` below the surface (``pulloff_distance``),
  which is ``9^(-1/3) ≈ 0.48`` of the displacement-controlled jump-off of JKR and of the MDR,
  ``(3/4)(π²Δγ²R/E*²)^(1/3)``: LAMMPS lets go early, at about half the separation.
- ``dmt E_L damp ν_L γ``: ``F = (4/3) E_mix a δ - 4πγR``: Hertz minus the constant DMT pull-off ``2πΔγR``
  while ``δ > 0``. No case of the MDR with Heß's rule (which gives JKR's ``F(δ)``); compared with it, the
  difference is what DMT's rigid-sphere adhesion assumes.
- ``mdr``: Zunker & Kamrin's elastic–plastic MDR for particles under compaction (yield stress, bulk response,
  a per-particle volume history). Not an elastic half-space against a rigid indenter, and not offered here.

**Tangential models** (``gran_sub_mod_tangential``): a linear spring on the tangential displacement (the
history ``ξ`` integrates the relative tangential velocity times ``dt``), with the whole contact's force capped at
``μ F_crit`` (Coulomb on the total force: no partial slip), ``F_crit = |F_N|`` for ``hertz/material`` and
``|F_N + 2 F_pulloff|`` for ``jkr`` and ``dmt`` (Thornton's heuristic for friction with adhesion).

- ``mindlin NULL damp μ``: stiffness ``8 G_mix a = 2 a G*``, the MDR's stick stiffness; the MDR with the local
  Coulomb law (``friction="coulomb"``) slips partially from the edge first (Cattaneo–Mindlin), LAMMPS does not.
- ``mindlin_rescale``: as ``mindlin``, the history scaled by ``a_new/a_old`` while the contact shrinks.
- ``mindlin/force``, ``mindlin_rescale/force``: the force itself is the history, incremented by
  ``-8 G_mix a v_t dt`` (incremental stiffness).
- ``linear_history k_t damp μ``: a constant stiffness; the mapping takes ``k_t = 2 a_max G*`` at the deepest
  contact of the path.

Damping is off: ``damping velocity`` with the normal damping 0 and the tangential ``x_γt = 0``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from mdr_events.contact import Contact
from mdr_events.contact.indenters import Paraboloid
from mdr_events.contact.model import check_half_space
from mdr_events.validation import SCALE_MAX, check_choice, check_real, shown

__all__ = ["NORMAL_MODELS", "TANGENTIAL_MODELS", "LammpsModel", "WallCoefficients", "wall_coefficients",
           "wall_model_arguments"]

#: LAMMPS's normal models offered, and what each assumes that the MDR does not.
NORMAL_MODELS: dict[str, str] = {
    "hertz/material": "no adhesion: the MDR's contact without Δγ0, Δγ1 (Hertz)",
    "jkr": "one work of adhesion 2γ both ways (the MDR's Δγ0 = Δγ1 = Δγ1), and the contact ends at "
           "9^(-1/3) of the JKR jump-off separation",
    "dmt": "Hertz minus a constant adhesive force 2πΔγR while the overlap is positive: no MDR case",
}
#: LAMMPS's tangential models offered (``"none"``: no tangential force), and what each assumes.
TANGENTIAL_MODELS: dict[str, str] = {
    "none": "no friction (linear_nohistory without damping: F_x = 0)",
    "mindlin": "stick stiffness 2aG*, Coulomb's cap on the whole force (no partial slip)",
    "mindlin_rescale": "as mindlin, the history scaled with a while the contact shrinks",
    "mindlin/force": "the force incremented by 2aG* times the tangential step (incremental stiffness)",
    "mindlin_rescale/force": "as mindlin/force, rescaled with a while the contact shrinks",
    "linear_history": "a constant stiffness 2 a_max G* (at the deepest contact), Coulomb's cap on the whole force",
}
#: The normal models with adhesion (LAMMPS's ``cohesion`` coefficient γ).
ADHESIVE_MODELS = ("jkr", "dmt")


@dataclass(frozen=True)
class LammpsModel:
    """A LAMMPS granular model by name: the normal model and the tangential model (:data:`NORMAL_MODELS`,
    :data:`TANGENTIAL_MODELS`).

    Raises
    ------
    ValueError
        An unsupported name, listing the supported ones.
    """

    normal: str = "hertz/material"
    tangential: str = "none"

    def __post_init__(self) -> None:
        object.__setattr__(self, "normal", check_choice("normal", self.normal, NORMAL_MODELS))
        object.__setattr__(self, "tangential", check_choice("tangential", self.tangential, TANGENTIAL_MODELS))

    @property
    def adhesive(self) -> bool:
        """Whether the normal model has adhesion (LAMMPS's ``γ``)."""
        return self.normal in ADHESIVE_MODELS

    @property
    def has_friction(self) -> bool:
        """Whether the tangential model carries a force (it needs ``μ``)."""
        return self.tangential != "none"


@dataclass(frozen=True)
class WallCoefficients:
    """The numbers LAMMPS is given for the contact (SI units): ``E_L``, ``ν_L``, the surface energy ``γ``
    (0 without adhesion), the tangential stiffness ``k_t`` of ``linear_history`` (``None``: Mindlin's ``NULL``)
    and ``μ`` (0 without friction)."""

    E: float
    nu: float
    gamma: float
    kt: float | None
    mu: float

    def to_attrs(self) -> dict[str, Any]:
        """A result's attributes: ``lammps_E``, ``lammps_nu``, ``lammps_gamma``, ``lammps_kt``, ``lammps_mu``."""
        return {"lammps_E": self.E, "lammps_nu": self.nu, "lammps_gamma": self.gamma,
                "lammps_kt": math.nan if self.kt is None else self.kt, "lammps_mu": self.mu}


def check_model(model: Any) -> LammpsModel:
    """``model`` if it is a :class:`LammpsModel`; else the one-line ``TypeError`` naming it (a name such as ``"jkr"``
    was an ``AttributeError`` in :func:`wall_coefficients`)."""
    if not isinstance(model, LammpsModel):
        raise TypeError(f"model={shown(model)} ({type(model).__name__}) is not allowed; allowed: a LammpsModel, e.g. "
                        "LammpsModel('jkr', 'mindlin')")
    return model


def _check_contact(contact: Contact, model: LammpsModel) -> None:
    """Refuse a contact LAMMPS's sphere cannot stand for: another indenter, or friction without ``μ``; and a model of
    another type."""
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a Contact")
    check_model(model)
    check_half_space(contact, "the LAMMPS check (LAMMPS has no layers)")
    if not isinstance(contact.indenter, Paraboloid):
        raise ValueError(f"contact.indenter={contact.indenter!r} is not allowed; allowed: a Paraboloid (LAMMPS "
                         "models a sphere, whose tip is the paraboloid of its radius R)")
    law = contact.friction
    if model.has_friction and not law.uses_mu:
        raise ValueError(f"tangential={model.tangential!r} with contact.friction={law!r} is not allowed; allowed: "
                         "a contact with Coulomb's law (FrictionLaw('coulomb', mu=...): LAMMPS caps the tangential "
                         "force at μ times the normal force), or tangential='none'")
    if not model.has_friction and (law.uses_mu or (law.tau0 or 0.0) > 0.0):
        raise ValueError(f"tangential='none' with contact.friction={law!r} is not allowed; allowed: a frictionless "
                         "contact (FrictionLaw('tau0', tau0=0)), or a tangential model with Coulomb's law")
    if law.uses_tau0 and (law.tau0 or 0.0) > 0.0:
        raise ValueError(f"contact.friction={law!r} is not allowed: LAMMPS has no critical shear stress τ0; "
                         "allowed: FrictionLaw('coulomb', mu=...)")


def wall_coefficients(contact: Contact, model: LammpsModel, deepest_radius: float | None = None) -> WallCoefficients:
    """The numbers LAMMPS takes for ``contact`` (module docstring): ``E_L = 2E``, ``ν_L = ν``, ``γ = Δγ1/2``,
    ``μ``; ``k_t = 2 a_max G*`` for ``linear_history`` (``deepest_radius`` the contact radius ``a_max`` at the
    deepest point of the path, m)."""
    _check_contact(contact, model)
    elastomer = contact.elastomer
    gamma = contact.adhesion.dgamma1 / 2.0 if model.adhesive else 0.0
    kt = None
    if model.tangential == "linear_history":  # (a string was Python's TypeError, True read as 1 m, 1e300 k_t = inf)
        deepest_radius = check_real("deepest_radius", deepest_radius, "with linear_history, the contact radius at "
                                    f"the path's deepest point (m, > 0 and at most {SCALE_MAX:.2g})",
                                    lambda value: 0.0 < value <= SCALE_MAX)
        kt = 2.0 * deepest_radius * elastomer.G_star
    mu = contact.friction.coulomb_mu if model.has_friction else 0.0
    return WallCoefficients(2.0 * elastomer.E, elastomer.nu, gamma, kt, mu)


def wall_model_arguments(model: LammpsModel, numbers: WallCoefficients) -> str:
    """The model part of ``fix wall/gran ... granular``: the normal model with its coefficients, damping off, the
    tangential model (``%.17g``: the numbers as they are)."""
    E, nu = f"{numbers.E:.17g}", f"{numbers.nu:.17g}"
    normal = f"{model.normal} {E} 0 {nu}" + (f" {numbers.gamma:.17g}" if model.adhesive else "")
    if model.tangential == "none":
        tangential = "tangential linear_nohistory 0 0"
    else:
        stiffness = "NULL" if numbers.kt is None else f"{numbers.kt:.17g}"
        tangential = f"tangential {model.tangential} {stiffness} 0 {numbers.mu:.17g}"
    return f"{normal} damping velocity {tangential}"
