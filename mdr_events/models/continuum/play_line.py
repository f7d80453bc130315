"""The springs as the per-spring route (:mod:`.play_springs`) reads them: ``g(ξ)``, ``k_t(ξ)/G*``, Coulomb's cap per
compression ``μ k/k_t``, the cap of ``τ0``'s part ``ū(a)`` and the radius of a depth, vectorised (the discrete model's
own springs, :mod:`~mdr_events.models.spring_media`; on a layer the three read in one spline call of the tables,
:class:`~mdr_events.theory.layer.spring_factors.SpringFactors`, and remembered for the last coordinates asked).
"""

from __future__ import annotations

import functools
from typing import Callable, NamedTuple

import numpy as np

from mdr_events.contact.adhesion import Adhesion
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import indenter_kind
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.parameters import Parameters

__all__ = ["SpringLine", "spring_line", "FlooredRatio"]


class SpringLine(NamedTuple):
    """What the per-spring route reads of the springs, vectorised in ``ξ`` or the depth."""

    #: ``g(ξ)`` (m)
    profile: Callable[[np.ndarray], np.ndarray]
    #: ``w(ξ) = k_t(ξ)/G*``
    weight: Callable[[np.ndarray], np.ndarray]
    #: Coulomb's cap per compression ``μ k(ξ)/k_t(ξ)`` (0 without Coulomb's part)
    ratio: Callable[[np.ndarray], np.ndarray]
    #: the cap of ``τ0``'s part ``ū(a)`` (m; 0 without it)
    shift: Callable[[np.ndarray], np.ndarray]
    #: the contact radius of a depth without adhesion, ``g⁻¹(d)`` (0 at ``d <= 0``)
    radius: Callable[[np.ndarray], np.ndarray]
    #: ``G*`` (Pa)
    G_star: float
    #: whether ``shift`` is not 0 (a law with ``τ0``'s part): without it no clamp reads the radius
    shifts: bool = True


def spring_line(params: Parameters, profile, friction: FrictionLaw, layer: Layer = HALF_SPACE) -> SpringLine:
    """The springs of a run without adhesion as the per-spring route reads them: the discrete model's own ``g``,
    ``k_t/G*`` and Coulomb's ratios (:mod:`~mdr_events.models.spring_media`), the continuum's cap of ``τ0``
    (:mod:`.media`) and its branch of ``Δγ = 0``.

    Parameters
    ----------
    params : Parameters
        The material and ``τ0``.
    profile : PowerLaw or None
        The indenter (``None``: the paraboloid of ``params.R``).
    friction : FrictionLaw
        The friction law.
    layer : Layer, default the half-space
        The body.

    Returns
    -------
    SpringLine
        The springs.
    """
    from mdr_events.models.spring_media import springs_of

    from .caps import caps_of
    from .media import HALF_SPACE_MEDIUM, layer_medium

    springs = springs_of(params, profile, None, layer)
    medium = HALF_SPACE_MEDIUM if layer.is_half_space else layer_medium(params, profile, layer)
    K = caps_of(friction, params, medium).K
    branch = medium.edge(Adhesion(), params, profile).grow

    def shift(a):
        return medium.shift(K, np.asarray(a, dtype=float)) if K > 0.0 else np.zeros(np.shape(a))

    def radius(d):
        d = np.asarray(d, dtype=float)
        out = np.zeros(d.shape)
        inside = d > 0.0
        if np.any(inside):
            out[inside] = branch.radii(d[inside])
        return out

    if layer.is_half_space:  # (the half-space's springs weigh 1 each)
        return SpringLine(_remembered(springs.profile), _unit_weights,
                          _remembered(lambda xi: springs.coulomb_ratios(xi, friction)), shift, radius, params.G_star,
                          K > 0.0)
    return SpringLine(*_layer_springs(params, springs.indenter, friction, layer), shift, radius, params.G_star,
                      K > 0.0)


def _remembered(function: Callable[[np.ndarray], np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """``function`` of the springs' coordinates remembering its last argument and value (read-only): one evaluation
    of the route asks the same springs' ``g``, ``k_t`` and ratios several times (the anchors, their attachment, the
    force's weights)."""
    last: list = [None, None]

    def remembered(xi):
        xi = np.asarray(xi, dtype=float)
        if last[0] is None or last[0].shape != xi.shape or not np.array_equal(last[0], xi):
            value = np.asarray(function(xi))
            value.flags.writeable = False
            last[0], last[1] = xi.copy(), value
        return last[1]

    return remembered


def _layer_springs(params: Parameters, indenter, friction: FrictionLaw, layer: Layer):
    """``g``, ``k_t/G*`` and ``μ k/k_t`` of the discrete model's :class:`~mdr_events.models.spring_media.LayerSprings`
    with the same arithmetic, their bit for bit, the three read in one evaluation of the tables' splines
    (:class:`~mdr_events.theory.layer.spring_factors.SpringFactors`, the flat punch's ``PunchSpringFactors``: by the
    indenter's kind, :data:`~.layer_normals.LAYER_NORMALS`; unchecked: a run evaluates them some thousand
    times on arrays of radii within its contact, which the layer's reach check has bounded before,
    :mod:`.layer_reach`) and remembered for the last coordinates asked (one evaluation of the route asks the same
    springs' ``g``, ``k_t`` and ratios several times)."""
    from .layer_normals import LAYER_NORMALS

    factors = LAYER_NORMALS[indenter_kind(indenter)].spring_factors(params, indenter, layer)
    G_star, mu = params.G_star, friction.coulomb_mu

    def springs(xi):
        profile, normal, tangential = factors.values(xi)
        # (coulomb_cap(x, 1, 0, μ, ...): μ (k/k_t)(1 − 0))
        ratio = mu * (normal / tangential) * (1.0 - 0.0) if mu > 0.0 else np.zeros(np.shape(xi))
        return np.stack([profile, tangential / G_star, ratio])

    once = _once_a_block(springs)
    springs = _remembered(once)  # (the three as the rows of one array)
    # (the centre's μρ read once, past the memory: the bound's each call would evict the last coordinates asked)
    centre = functools.cache(lambda: float(once(np.zeros(1))[2][0]))
    return ((lambda xi: springs(xi)[0]), (lambda xi: springs(xi)[1]),
            FlooredRatio(lambda xi: springs(xi)[2], lambda extent: mu * factors.ratio_floor(extent), centre))


class FlooredRatio(NamedTuple):
    """Coulomb's cap per compression ``μ k/k_t`` of a layer's springs (called as :attr:`SpringLine.ratio` is) with a
    lower bound of it over ``[0, X]`` that reads no spring (:meth:`floor`: ``μ`` times
    :meth:`~mdr_events.theory.layer.spring_factors.SpringFactors.ratio_floor`, the tables' B-spline coefficients;
    :mod:`.play_bound` tries it before reading the probes, with the centre's value, :attr:`centre`). A line whose
    ratio is replaced (``_replace(ratio=...)``) has no floor."""

    #: ``μ k(ξ)/k_t(ξ)`` at the springs' coordinates
    ratio: Callable[[np.ndarray], np.ndarray]
    #: a lower bound of it over ``0 <= ξ <= X`` at each extent ``X`` (m), at or below every value :attr:`ratio` gives
    #: there
    floor: Callable[[np.ndarray], np.ndarray]
    #: :attr:`ratio` at ``ξ = 0``, its value bit for bit, read once (not through the springs' memory of the last
    #: coordinates asked, which it would evict)
    centre: Callable[[], float]

    def __call__(self, xi) -> np.ndarray:
        """:attr:`ratio` at ``xi``."""
        return self.ratio(xi)


def _once_a_block(function: Callable[[np.ndarray], np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """``function`` (elementwise, its values stacked in rows) read once per block where ``xi`` is blocks of one length
    each equal to the one before it (the probes of many times at one radius: the same springs, each time's own), the
    others' values copied: the same values (each element's its own), the tables' spline read for the distinct blocks
    alone. A block starts wherever ``xi[0]`` recurs; where no block repeats its predecessor, one call on the whole.
    Blocks are compared by ``==``, so a ``-0.0`` reads ``+0.0``'s values: the same bit for bit while ``function`` is
    even in ``xi`` (here ``g``, ``k_t/G*`` and ``μ k/k_t``, each read at ``|xi|``,
    :meth:`~mdr_events.theory.layer.spring_factors.SpringFactors.values`); an odd ``function`` would need the signs
    compared too."""

    def once(xi):
        xi = np.asarray(xi, dtype=float)
        starts = np.flatnonzero(xi == xi[0]) if xi.ndim == 1 and xi.size > 1 else np.empty(0, dtype=np.intp)
        length = int(starts[1]) if starts.size > 1 else 0
        if not length or xi.size % length:
            return function(xi)
        blocks = xi.reshape(-1, length)
        heads = np.concatenate([[True], ~np.all(blocks[1:] == blocks[:-1], axis=1)])
        if np.all(heads):
            return function(xi)
        values = function(blocks[heads].ravel())
        return values.reshape(values.shape[0], -1, length)[:, np.cumsum(heads) - 1].reshape(values.shape[0], -1)

    return once


def _unit_weights(xi: np.ndarray) -> np.ndarray:
    return np.ones(np.shape(xi))
