"""The continuum's springs on a layer of finite thickness (:mod:`.media`): bonded to its base, or resting on it without
friction.

On a layer the springs' stiffness varies with ``ξ`` (``k = K'/2``, ``k_t = K_t'/2``): a zone ``[ξ₁, ξ₂]`` weighs
``M(ξ₂) − M(ξ₁)``, ``M(ξ) = K_t(ξ)/(2G*) = ξ Φ_t(ξ/h)``, the springs leaving the edge ``w(a) = M'(a)``, the cap of
``τ0`` is ``ū = π a² τ0/K_t(a) = K a/Φ_t`` (the relations of :mod:`mdr_events.theory.layer_continuum_symbolic` on the
tables' factors for one float, :mod:`mdr_events.theory.layer.scalar_factors`), the branches are the layer's
(:class:`~.layer_branch.LayerBranch`) and the normal force is ``F₀(a) + K(a)(d − g(a))``.
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING

import numpy as np

from mdr_events.contact.indenters import indenter_kind
from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.parameters import Parameters

from .media import FACTOR_CACHE, HalfSpaceMedium

if TYPE_CHECKING:
    from .anchors import AnchorMap, Piece

__all__ = ["LayerMedium", "FrictionlessLayerMedium", "LAYER_MEDIA"]


#: How many branches a medium keeps (:meth:`LayerMedium._branch`): a run asks for two, a rate law's run a few more.
BRANCHES_KEPT = 16
#: At most this share of an array's radii starting a run of equal ones (:meth:`LayerMedium._shifts`), each run's shift
#: is read once: a run's pinned spans repeat their radius over most of its samples, and below half the table's reading
#: of the runs alone saves more than finding them costs.
RUNS_SHARE = 0.5


class LayerMedium(HalfSpaceMedium):
    r"""A layer bonded to its rigid base: the springs' stiffness varies with ``ξ`` (generalized MDR).

    .. math:: M(\xi) = \frac{K_t(\xi)}{2G^*} = \xi\,\Phi_t(\xi/h), \quad w = M', \quad
              \bar u(a) = \frac{\pi a^2 \tau_0}{K_t(a)} = \frac{K a}{\Phi_t(a/h)} \qquad (13), (T3)

    Parameters
    ----------
    params : Parameters
        The material (``E*``, ``G*``, ``ν``).
    indenter : Paraboloid, PowerLaw or FlatPunch
        The indenter.
    layer : Layer
        The layer (finite thickness).
    """

    #: ``ū = K a/Φ_t(a/h)`` is not linear in the radius (:attr:`~.media.HalfSpaceMedium.linear_cap`)
    linear_cap = False

    def __init__(self, params: Parameters, indenter, layer: Layer):
        from mdr_events.theory.layer.scalar_factors import NormalFactors
        from mdr_events.theory.layer_continuum_symbolic import derive_continuum_model

        from .layer_normals import LAYER_NORMALS

        self.params, self.indenter, self.layer = params, indenter, layer
        #: the branches made (:meth:`edge`), by the material and the work: a branch is a function of those values on
        #: this medium, and every run of the contact asks for the same two (at most :data:`BRANCHES_KEPT`)
        self._branches: dict[tuple, object] = {}
        #: what the indenter's kind makes of the normal springs (:mod:`.layer_normals`)
        self.springs = LAYER_NORMALS[indenter_kind(indenter)]
        self.normal = NormalFactors(params.nu, layer, self.springs.exponent(indenter))
        #: the normal force ``F_N(d, a)`` of this medium's springs (:meth:`normal_force`)
        self._force = self.springs.force_reader(params, indenter, layer)
        relations = derive_continuum_model()
        self._pair_array = relations["layer_continuum_tangential_factor_pair"].numeric
        self._factor_array = relations["layer_continuum_tangential_factor"].numeric
        self._weight_array = relations["layer_continuum_weight"].numeric
        self._measure_array = relations["layer_continuum_measure"].numeric
        self._cap = relations["layer_continuum_cap"].scalar
        self._cap_array = relations["layer_continuum_cap"].numeric
        self._cap_slope = relations["layer_continuum_cap_slope"].scalar
        self._weight = relations["layer_continuum_weight"].scalar
        self._measure = relations["layer_continuum_measure"].scalar
        self.tangential = self._tangential_factors(relations)
        #: ``Φ_t`` and its slope of a radius, remembered: one right-hand side asks for the same radius several times
        #: (the cap, its slope, the measure of the contact) and for the pieces' fixed ends again and again
        self._factor = functools.lru_cache(maxsize=FACTOR_CACHE)(self.tangential.stiffness_factor) \
            if self.tangential is not None else None

    def _tangential_factors(self, relations):
        from mdr_events.theory.layer.scalar_factors import TangentialFactors

        return TangentialFactors(self.params.nu, self.layer, relations["layer_continuum_tangential_factor_pair"].scalar)

    def shift(self, K: float, a: float) -> float:
        """``ū(a) = K a/Φ_t(a/h)`` (``layer_continuum_cap``).

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : float or numpy.ndarray
            The contact radius (m), or radii (the table's vectorised factor).

        Returns
        -------
        float or numpy.ndarray
            ``ū`` (m).
        """
        if type(a) is not float:  # (a NumPy scalar as a float: its hash and arithmetic cost microseconds)
            if np.ndim(a):
                return self._shifts(K, a)
            a = float(a)
        return self._cap(a, K, self._factor(a)[0]) if a > 0 else 0.0

    def _shifts(self, K: float, a: np.ndarray) -> np.ndarray:
        """:meth:`shift` of an array of radii (the factor's splines by Horner's rule on the arrays,
        :meth:`~mdr_events.theory.layer.scalar_factors.TangentialFactors.parts_array`)."""
        radii = np.asarray(a, dtype=float)
        flat = radii.reshape(-1)
        if flat.size > 1 and np.ndim(K) == 0:
            # (runs of one radius, a pinned span's samples: each run's shift read once and repeated, the same value
            # as each of the array's elementwise operations gives every element; a held punch's face, some thousand
            # of a run's samples. Only for one K: an array of K would give each element its own shift)
            starts = np.flatnonzero(np.concatenate([[True], flat[1:] != flat[:-1]]))
            if starts.size <= RUNS_SHARE * flat.size:
                repeats = np.diff(np.append(starts, flat.size))
                return np.repeat(self._shift_values(K, flat[starts]), repeats).reshape(radii.shape)
        return self._shift_values(K, radii)

    def _shift_values(self, K: float, radii: np.ndarray) -> np.ndarray:
        """:meth:`_shifts` element by element."""
        lam = np.maximum(radii, 0.0) / self.layer.thickness
        factor = self._factor_array(self.params.nu, *self.tangential.factors_array(lam))
        return np.where(radii > 0, self._cap_array(radii, K, factor), 0.0)

    def measures_and_shifts(self, K: float, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``M(a)`` (:meth:`measure` from 0) and ``ū(a)`` (:meth:`shift`) at an array of radii ``> 0``, from one
        vectorised factor (the closed form's, :mod:`.layer_closed_form`).

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : numpy.ndarray
            The contact radii (m), ``> 0``.

        Returns
        -------
        tuple of numpy.ndarray
            ``M`` (m) and ``ū`` (m).
        """
        factor = self._factor_array(self.params.nu, *self.tangential.factors_array(a / self.layer.thickness))
        return self._measure_array(a, factor), self._cap_array(a, K, factor)

    def weights_and_caps(self, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``w(a)`` (:meth:`density`: the same splines' slopes) and ``ū(a)/K = a/Φ_t`` at an array of radii ``> 0``
        (the integrands of :class:`~.layer_closed_form.BranchIntegrals`).

        Parameters
        ----------
        a : numpy.ndarray
            The radii (m), ``> 0``.

        Returns
        -------
        tuple of numpy.ndarray
            ``w`` (1) and ``ū/K`` (m).
        """
        h = self.layer.thickness
        factor, slope = self._pair_array(self.params.nu, *self.tangential.parts_array(a / h))
        return self._weight_array(a, h, factor, slope), self._cap_array(a, 1.0, factor)

    def rate_parts(self, K: float, a: float) -> tuple[float, float, float, float]:
        """``M(a)``, ``ū(a)``, ``dū/da`` and ``w(a)`` at one radius ``a > 0`` from one look-up of ``Φ_t`` (the values
        of :meth:`measure` from 0, :meth:`shift`, :meth:`shift_slope` and :meth:`density`, bit for bit: what the
        closed form's rate reads, :meth:`~.layer_closed_form.LayerPrimitive.rate`).

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m), ``> 0``.

        Returns
        -------
        tuple of float
            ``M`` (m), ``ū`` (m), ``dū/da`` (1), ``w`` (1).
        """
        a, h = float(a), self.layer.thickness
        factor, slope = self._factor(a)
        return (self._measure(a, factor) - 0.0, self._cap(a, K, factor), self._cap_slope(a, h, K, factor, slope),
                self._weight(a, h, factor, slope))

    def span_primitive(self, integrator):
        """A moving span's force in closed form on the bonded layer (:func:`~.layer_closed_form.layer_span_primitive`).

        Parameters
        ----------
        integrator : SpanIntegrator
            A moving span without a front.

        Returns
        -------
        LayerPrimitive or None
            ``P``, or ``None`` where the span has no closed form here.
        """
        from .layer_closed_form import layer_span_primitive

        return layer_span_primitive(integrator)

    def shift_slope(self, K: float, a: float) -> float:
        """``dū/da`` (``layer_continuum_cap_slope``; ``K`` at ``a = 0``).

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``dū/da`` (1).
        """
        return self._cap_slope(a, self.layer.thickness, K, *self._factor(float(a))) if a > 0 else K

    def _cumulative(self, x: float) -> float:
        return self._measure(x, self._factor(float(x))[0]) if x > 0 else 0.0

    def measure(self, lower: float, upper: float) -> float:
        """``M(upper) − M(lower)``, ``M(ξ) = K_t(ξ)/(2G*)`` (``layer_continuum_measure``).

        Parameters
        ----------
        lower, upper : float
            The interval's ends (m).

        Returns
        -------
        float
            The measure (m).
        """
        return self._cumulative(upper) - self._cumulative(lower)

    def density(self, x: float) -> float:
        """``w(ξ) = k_t(ξ)/G* = M'(ξ)`` (``layer_continuum_weight``).

        Parameters
        ----------
        x : float
            The coordinate (m).

        Returns
        -------
        float
            ``w`` (1).
        """
        return self._weight(x, self.layer.thickness, *self._factor(float(x))) if x > 0 else 1.0

    def piece_integral(self, anchors: "AnchorMap", piece: "Piece", lower: float, upper: float) -> float:
        """``∫ w(ξ) Y(ξ) dξ`` over ``[lower, upper]`` of ``piece``: ``x0 (M(upper) − M(lower))`` and, on a growth
        piece, ``ratio ∫ w (d0 − d_ref) dξ`` by adaptive quadrature.

        Parameters
        ----------
        anchors : AnchorMap
            The map holding ``piece``.
        piece : Piece
            The piece.
        lower, upper : float
            The bounds (m).

        Returns
        -------
        float
            The integral (m²).
        """
        from scipy.integrate import quad

        total = piece.x0 * self.measure(lower, upper)
        if not piece.constant and upper > lower:
            def grown(xi: float) -> float:
                return self.density(xi) * (anchors.attach.depth(xi) - piece.d_ref)

            total += piece.ratio * quad(grown, lower, upper, epsabs=0.0, epsrel=1e-12, limit=200)[0]
        return total

    def edge(self, adhesion, params: Parameters, profile):
        """The layer's branches of ``Δγ0`` (growing) and ``Δγ1`` (shrinking) (:class:`~.layer_branch.LayerBranch`).

        Parameters
        ----------
        adhesion : Adhesion
            The paper's adhesion law.
        params : Parameters
            The material and the works.
        profile : PowerLaw, FlatPunch or None
            The indenter (``None``: the paraboloid of ``params.R``).

        Returns
        -------
        Edge
            The growing and shrinking branches.
        """
        from .edges import Edge, check_edge_known

        check_edge_known(adhesion)
        return Edge(*(self._branch(params, work) for work in (adhesion.dgamma0, adhesion.dgamma1)))

    def _branch(self, params: Parameters, work: float):
        """The branch of ``work`` for the material ``params`` on this medium, made once and kept (its scan, jump-off
        and remembered radii with it: 0.2 ms a run's two on a thin layer's punch, against 0.03 ms the half-space's);
        a branch's values depend on these alone, so a kept one gives every run the same numbers as a new one. The
        branch handed out is shared by every run of the contact: read-only to them (nothing outside its class sets its
        attributes; what it fills itself, its scan and remembered depths, is a function of its values alone)."""
        key = (params, work)
        branch = self._branches.get(key)
        if branch is None:
            if len(self._branches) >= BRANCHES_KEPT:
                self._branches.clear()
            branch = self._branches[key] = self.springs.branch(params, work, self.indenter, self.layer, self.normal)
        return branch

    def normal_force(self, params: Parameters, profile, depth, radius):
        r"""``F_N = F₀(a) + K(a)(d − g(a))`` on the layer (generalised (10),
        :func:`~mdr_events.theory.layer.normal_force`; the flat punch's ``K(a) d``, :mod:`.layer_normals`).

        Parameters
        ----------
        params : Parameters
            The material.
        profile : PowerLaw, FlatPunch or None
            The indenter.
        depth, radius : float or array_like
            ``d`` and ``a`` (m).

        Returns
        -------
        numpy.ndarray
            ``F_N`` (N).
        """
        return self._force(depth, radius)


class FrictionlessLayerMedium(LayerMedium):
    """A layer on a frictionless base: the normal springs of :class:`LayerMedium`, no tangential ones (``K_t = 0``).

    No spring carries a shift (only paths without tangential motion run on it: ``F_x = 0``); the cap is the
    half-space's ``K a``, never reached while the indenter does not move tangentially.
    """

    def _tangential_factors(self, relations):
        return None

    def shift(self, K: float, a: float) -> float:
        """``K a`` (no cap is reached: no spring is shifted).

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``K a`` (m).
        """
        return K * a

    def shift_slope(self, K: float, a: float) -> float:
        """``K``.

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``K``.
        """
        return K

    def span_primitive(self, integrator):
        """No tangential springs, no closed form (the force stays 0).

        Parameters
        ----------
        integrator : SpanIntegrator
            A moving span without a front.

        Returns
        -------
        None
            None.
        """
        return None

    def measure(self, lower: float, upper: float) -> float:
        """No tangential springs: 0.

        Parameters
        ----------
        lower, upper : float
            The interval's ends (m).

        Returns
        -------
        float
            0.
        """
        return 0.0

    def density(self, x: float) -> float:
        """No tangential springs: 0.

        Parameters
        ----------
        x : float
            The coordinate (m).

        Returns
        -------
        float
            0.
        """
        return 0.0

    def piece_integral(self, anchors: "AnchorMap", piece: "Piece", lower: float, upper: float) -> float:
        """No tangential springs: 0.

        Parameters
        ----------
        anchors : AnchorMap
            The map holding ``piece``.
        piece : Piece
            The piece.
        lower, upper : float
            The bounds (m).

        Returns
        -------
        float
            0.
        """
        return 0.0

    def full_slip_force(self, G_star: float, K: float, a: float) -> float:
        """No tangential springs: 0.

        Parameters
        ----------
        G_star : float
            ``G*`` (Pa).
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m).

        Returns
        -------
        float
            0.
        """
        return 0.0


#: The kind of a finite layer's medium, by its base.
LAYER_MEDIA: dict[LayerBase, type] = {LayerBase.BONDED: LayerMedium, LayerBase.FRICTIONLESS: FrictionlessLayerMedium}
