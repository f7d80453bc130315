"""SymPy derivation of every relation of section 4, eqs. (3)–(21).

Nothing here is typed in as a result: each relation is *derived* from the
model's statements (the Abel transform (3), the spring displacement (7),
Heß's rule (8), the stationary-sliding sum (12), the trajectories (14) and
(19)) by integration, differentiation, ``solve`` and polynomial reduction.
The numerical layers (:mod:`mdr_events.theory.analytic`, and later the continuum and
discrete simulators) evaluate these very expressions through
:attr:`Relation.numeric`, built once with :func:`sympy.lambdify` and cached.

Use
---
>>> from mdr_events import symbolic
>>> rel = symbolic.relation("jkr_depth")
>>> rel.equation, rel.eq                                    # doctest: +SKIP
('(9)', Eq(d, a**2/R - sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)))
>>> rel.numeric(a=3e-3, R=0.03, E_star=4.32e5, dgamma=0.01)  # doctest: +SKIP

Symbols (all SI): ``x`` MDR coordinate, ``r`` radial coordinate, ``R``
indenter radius, ``E_star``/``G_star`` effective moduli, ``tau0`` critical
shear stress, ``dgamma`` work of adhesion, ``d`` indentation depth, ``d_max``
turning depth, ``a`` contact radius, ``s = sqrt(a)``, ``alpha`` path angle.

Layout, one derivation a module: ``symbols`` (the symbols and their LaTeX names), ``derived_relation``
(:class:`Relation`, evaluated through the derived expression), ``cache`` (the on-disk cache and the helpers every
module of derivations shares), ``paper`` (the paraboloid's model, (3)–(21), :func:`derive`), ``power_law`` (Heß's rule
for ``c rⁿ`` and the flat punch), ``friction`` (Coulomb's cap, Cattaneo–Mindlin), ``adhesive_friction`` (Coulomb's
law with adhesion), ``rate_adhesion`` (the rate-dependent works of adhesion). This package re-exports their public
names and looks a relation up by key (:func:`relation`, :func:`relations`). The on-disk cache is keyed by the hash of
every module of the package (:func:`cache_path`), so an edit to any of them (the symbols, the :class:`Relation` whose
fields the cache stores, a derivation or its helpers) cannot leave a stale cache behind. Each derivation is split
into sections of one step of the paper each (:func:`derive_afresh`).
"""

from __future__ import annotations

from mdr_events.theory.symbolic.adhesive_friction import (
    ADHESIVE_FRICTION_KEYS, adhesive_friction_model_afresh, derive_adhesive_friction_model,
)
from mdr_events.theory.symbolic.cache import (
    cache_path, cached_relations, derivation_check, sibling_cache_path, source_digest,
)
from mdr_events.theory.symbolic.derived_relation import Relation
from mdr_events.theory.symbolic.friction import FRICTION_KEYS, derive_friction_model, friction_model_afresh
from mdr_events.theory.symbolic.paper import AddRelation, abel_transform, derive, derive_afresh
from mdr_events.theory.symbolic.power_law import (
    POWER_LAW_KEYS, derive_power_law, derive_power_law_model, power_law_afresh, power_law_model_afresh,
)
from mdr_events.theory.symbolic.rate_adhesion import (
    RATE_ADHESION_KEYS, dgamma0, dgamma1, derive_rate_dependent_adhesion, edge_speed,
    rate_dependent_adhesion_afresh, release, v_ref,
)
from mdr_events.theory.symbolic.symbols import (
    E_star, F_N, F_x, G_star, LATEX_NAMES, R, SYMBOLS, W, X, a, alpha, c, d, d_max, dgamma, dl_max, dx, f, g, k, mu,
    n, n_springs, r, s, t, tan_alpha, tau, tau0, theta, u_bar, u_x, u_z, x,
)
from mdr_events.validation import shown

__all__ = [
    "Relation",
    "derive",
    "derive_afresh",
    "cache_path",
    "cached_relations",
    "derivation_check",
    "sibling_cache_path",
    "source_digest",
    "relation",
    "UnknownRelationError",
    "relations",
    "abel_transform",
    "derive_power_law_model",
    "POWER_LAW_KEYS",
    "derive_friction_model",
    "FRICTION_KEYS",
    "derive_adhesive_friction_model",
    "ADHESIVE_FRICTION_KEYS",
    "derive_rate_dependent_adhesion",
    "RATE_ADHESION_KEYS",
    "SYMBOLS",
]


def relations() -> dict[str, Relation]:
    """All derived relations by key, in derivation order (derived once, then cached).

    Returns
    -------
    dict of str to Relation
        The paraboloid's model, the power law's, the friction laws' and the adhesive friction's.
    """
    model = derive()
    power_law = derive_power_law()
    ordered = {"abel_transform": model["abel_transform"], power_law.key: power_law}
    ordered.update(model)
    ordered.update(derive_power_law_model())
    ordered.update(derive_friction_model())
    ordered.update(derive_adhesive_friction_model())
    ordered.update(derive_rate_dependent_adhesion())
    return ordered


class UnknownRelationError(KeyError, ValueError):
    """A key no derived relation has (:func:`relation`): a ``KeyError`` as a look-up by key, and a ``ValueError`` as
    every other unknown name the package is given; its message is shown as written (not quoted as a key)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def relation(key: str) -> Relation:
    """One derived relation by key.

    Parameters
    ----------
    key : str
        The relation's key (``mdr-events derive`` lists them), e.g. ``"jkr_depth"``.

    Returns
    -------
    Relation
        The relation, derived (or read from the cache) once per process.

    Raises
    ------
    TypeError
        If ``key`` is not a ``str``.
    UnknownRelationError
        A ``KeyError`` and ``ValueError`` naming ``key`` and the known keys, if no relation has it.
    """
    if not isinstance(key, str):
        raise TypeError(f"key={shown(key)} ({type(key).__name__}) is not allowed; allowed: a relation's key (str), "
                        "as mdr-events derive lists them")
    if key == "profile_power_law":
        return derive_power_law()
    if key in POWER_LAW_KEYS:
        return derive_power_law_model()[key]
    if key in FRICTION_KEYS:
        return derive_friction_model()[key]
    if key in ADHESIVE_FRICTION_KEYS:
        return derive_adhesive_friction_model()[key]
    if key in RATE_ADHESION_KEYS:
        return derive_rate_dependent_adhesion()[key]
    rels = derive()
    try:
        return rels[key]
    except KeyError:
        known = sorted([*rels, "profile_power_law", *POWER_LAW_KEYS, *FRICTION_KEYS, *ADHESIVE_FRICTION_KEYS,
                        *RATE_ADHESION_KEYS])
        raise UnknownRelationError(f"key={shown(key)} is not allowed (unknown relation {shown(key)}); allowed: "
                                   f"{', '.join(known)}") from None
