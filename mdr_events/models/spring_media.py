r"""What the discrete model's springs are made of: the elastomer as a half-space or as a layer on a rigid base.

The springs of the discrete model (:mod:`mdr_events.models.discrete`) sit at ``x_j = (j + 1/2) Δx``; what each one
is depends on the body under the indenter, its *kind*, looked up once per run (:func:`springs_of`):

=================================  =====================================================================================
kind                               the springs
=================================  =====================================================================================
:class:`HalfSpaceSprings`          the paper's: stiffness ``E* Δx`` (5), ``G* Δx`` (6), all alike; profile ``g(x)``
                                   (3), Heß's ``Δl`` (8), the cap (13) ``π a τ0/(2G*)``, Coulomb's ``μ (E*/G*)(d − g)``
:class:`LayerSprings`              a layer of thickness ``h`` bonded to its base (:mod:`mdr_events.theory.layer`,
                                   :mod:`mdr_events.theory.layer_tangential`): ``k(x_j) Δx``, ``k_t(x_j) Δx`` with
                                   ``k = K'/2``, ``k_t = K_t'/2``; the layer's profile ``g(x)`` (L4) and
                                   ``Δl = sqrt(4π a Δγ/K'(a))``; the caps ``π a² τ0/K_t(a)`` and
                                   ``μ (k/k_t)(d − g)``
:class:`FrictionlessLayerSprings`  a layer on a frictionless base: the normal springs of :class:`LayerSprings`, no
                                   tangential ones (such a layer slides on its base: ``K_t = 0``), so only paths
                                   without tangential motion run on it
=================================  =====================================================================================

Each kind gives the run the springs' profile, Heß's elongation, the weights of the sums (15) in units of the
half-space's springs (``k(x_j)/E*`` and ``k_t(x_j)/G*``; 1 on the half-space), the caps per radius and Coulomb's
ratio per spring, so that

.. math:: F_N = 2 E^* \Delta x \sum_{j<m} w_j\,(d - g(x_j)), \qquad F_x = 2 G^* \Delta x \sum_{j<m} w^t_j\, u_j
          \qquad (15)

on any of them. The half-space's are the paper's own functions, unchanged: its runs are those of before, bit for bit.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from mdr_events.contact.indenters import FlatPunch, Paraboloid, PowerLaw
from mdr_events.contact.layer import HALF_SPACE, Layer, LayerBase
from mdr_events.models.half_space_springs import HalfSpaceSprings
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.layer_springs import FrictionlessLayerSprings, LayerSprings
from mdr_events.parameters import Parameters
from mdr_events.validation import shown

__all__ = ["HalfSpaceSprings", "LayerSprings", "FrictionlessLayerSprings", "Springs", "springs_of"]


#: A kind of springs.
Springs = HalfSpaceSprings | LayerSprings | FrictionlessLayerSprings


def springs_of(params: Parameters, indenter: SimulatedProfile, profile: Callable[[np.ndarray], np.ndarray] | None,
               layer: Layer = HALF_SPACE) -> Springs:
    """The kind of springs of a run on ``layer`` (the one place the body's kind is looked up).

    Parameters
    ----------
    params : Parameters
        The material, adhesion and ``τ0``.
    indenter : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter (``None``: the paraboloid of ``params.R``).
    profile : callable, optional
        A half-space run's springs' profile ``g(x)`` given as a function (default: the indenter's).
    layer : Layer, default the half-space
        The body.

    Returns
    -------
    HalfSpaceSprings, LayerSprings or FrictionlessLayerSprings
        The springs' kind.

    Raises
    ------
    TypeError
        ``layer`` not a Layer.
    ValueError
        On a finite layer: an indenter other than the paraboloid or a power law, or a profile given as a function.
    """
    if not isinstance(layer, Layer):
        raise TypeError(f"layer={shown(layer)} ({type(layer).__name__}) is not allowed; allowed: a mdr_events.Layer")
    if layer.is_half_space:
        return HalfSpaceSprings(params, indenter, profile)
    if profile is not None or not isinstance(indenter, (type(None), PowerLaw, FlatPunch)):
        given = "a profile g(x) given as a function" if profile is not None else f"profile={indenter!r}"
        raise ValueError(f"{given} is not allowed on {layer.describe()} (either method); allowed: the "
                         "paraboloid (profile=None), a PowerLaw (the layer's profile is tabulated for these) or a "
                         "FlatPunch (g = 0 under its face)")
    body = Paraboloid(params.R) if indenter is None else indenter
    return _LAYER_KINDS[layer.base](params, body, layer)


#: The kind of a finite layer's springs, by its base.
_LAYER_KINDS: dict[LayerBase, type] = {LayerBase.BONDED: LayerSprings, LayerBase.FRICTIONLESS: FrictionlessLayerSprings}
