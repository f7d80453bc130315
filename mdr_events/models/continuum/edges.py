"""The contact edge of an adhesion law, as the continuum follows it: the branches (9) its radius moves along.

The paper's law (:class:`~mdr_events.contact.adhesion.Adhesion`) grows the radius along the ``Δγ0`` branch and
shrinks it along the ``Δγ1`` branch (:func:`hysteresis_edge`). Each adhesion law has its rule here, looked up by its
type (:data:`EDGE_RULES`); a law whose edge moves by a rate (the radius a state of the ODE, not a function of the
depth) gives the integrator its ``ȧ`` through the same :class:`Edge`.
"""

from __future__ import annotations

from typing import Callable, NamedTuple

from mdr_events.contact.adhesion import Adhesion, AdhesionLaw, kernel_of
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.parameters import Parameters

from .branch import Branch, make_branch

__all__ = ["Edge", "EDGE_RULES", "edge_of", "check_edge_known", "hysteresis_edge"]


class Edge(NamedTuple):
    """The branches the contact radius follows: growing (springs attach) and shrinking (springs let go)."""

    #: the branch a growing radius follows (the paper's: ``Δγ0``)
    grow: Branch
    #: the branch a shrinking radius follows (the paper's: ``Δγ1``)
    shrink: Branch


def hysteresis_edge(adhesion: Adhesion, params: Parameters, profile: SimulatedProfile = None) -> Edge:
    """The paper's rate-independent law: the ``Δγ0`` branch in, the ``Δγ1`` branch out (9)."""
    return Edge(make_branch(params, adhesion.dgamma0, profile), make_branch(params, adhesion.dgamma1, profile))


#: The edge rule of each adhesion law, by its type.
EDGE_RULES: dict[type, Callable[..., Edge]] = {Adhesion: hysteresis_edge}


def check_edge_known(adhesion: AdhesionLaw) -> None:
    """Refuse an adhesion law without an edge rule in :data:`EDGE_RULES`, naming those with one."""
    kernel_of(adhesion, EDGE_RULES, "continuum")


def edge_of(adhesion: AdhesionLaw, params: Parameters, profile: SimulatedProfile = None) -> Edge:
    """The edge of ``adhesion`` for the material of ``params`` and ``profile`` (``None``: the paraboloid)."""
    return kernel_of(adhesion, EDGE_RULES, "continuum")(adhesion, params, profile)
