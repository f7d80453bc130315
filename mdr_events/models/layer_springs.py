r"""The discrete model's springs on a layer of finite thickness: the generalized MDR's ``k(x_j) Δx``, ``k_t(x_j) Δx``.

Two kinds of the discrete model's springs (:mod:`mdr_events.models.spring_media`, which looks the kind up), from
the layer's relations (:mod:`mdr_events.theory.layer`, :mod:`mdr_events.theory.layer_tangential`):
:class:`LayerSprings` on a bonded base (``k = K'/2``, ``k_t = K_t'/2``, the layer's profile ``g(x)`` (L4),
``Δl = sqrt(4π a Δγ/K'(a))``, the caps ``π a² τ0/K_t(a)`` and ``μ (k/k_t)(d − g)``) and
:class:`FrictionlessLayerSprings` on a frictionless one (no tangential springs).
"""

from __future__ import annotations

import itertools
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mdr_events.contact.adhesion import Adhesion, AdhesionLaw
from mdr_events.contact.elastomer import Elastomer
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, Paraboloid, PowerLaw
from mdr_events.contact.layer import Layer
from mdr_events.memo import cached
from mdr_events.models import indenters
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import shown

__all__ = ["LayerSprings", "FrictionlessLayerSprings"]


@dataclass(frozen=True)
class LayerSprings:
    """The springs of the generalized MDR on a layer bonded to its base: ``k(x_j) Δx`` and ``k_t(x_j) Δx``.

    Parameters
    ----------
    params : Parameters
        The material (``E*``, ``G*``, ``ν``), the works of adhesion and ``τ0``.
    indenter : Paraboloid, PowerLaw or FlatPunch
        The indenter (the layer's profile is tabulated for the first two; the flat punch's is ``0`` under its face).
    layer : Layer
        The layer (finite thickness).
    """

    params: Parameters
    indenter: Paraboloid | PowerLaw | FlatPunch
    layer: Layer

    grouped = True
    #: As :attr:`HalfSpaceSprings.bytes_per_spring
    #: <mdr_events.models.half_space_springs.HalfSpaceSprings.bytes_per_spring>`, with the springs' weights and their
    #: integer prefix sums (Python integers): 317 measured at 4e5 and 2e6 springs (counted as the half-space's 256, a run passed the memory limit
    #: by a quarter).
    bytes_per_spring = 384

    def check(self, adhesion: AdhesionLaw, paths: list[Path]) -> None:
        """Refuse an adhesion law other than the paper's (Heß's rule on the layer is the rate-independent one).

        Parameters
        ----------
        adhesion : Adhesion or RateDependentAdhesion
            The adhesion law.
        paths : list of Path
            The cases' paths.

        Raises
        ------
        TypeError
            A law other than :class:`~mdr_events.Adhesion`.
        """
        if type(adhesion) is not Adhesion:
            raise TypeError(f"adhesion={shown(adhesion)} ({type(adhesion).__name__}) is not allowed on "
                            f"{self.layer.describe()} (either method); allowed: Adhesion (the rate-dependent "
                            "law runs on the half-space)")

    @property
    def _material(self) -> tuple[float, float]:
        return self.params.E_star, self.params.nu

    def profile(self, positions: np.ndarray) -> np.ndarray:
        """The layer's generalized MDR profile ``g(x_j)`` (L4) (:func:`~mdr_events.theory.layer.power_law_profile`).

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        numpy.ndarray
            ``g`` (m).
        """
        if theory_of(self.indenter).flat_face:  # (f = 0 under the face: g = 0 there on any layer, (L4))
            return indenters.spring_profile(self.params, self.indenter)(positions)
        from mdr_events.theory.layer import power_law_profile

        return power_law_profile(positions, self.indenter, self.params.nu, self.layer)

    def elongation(self, positions: np.ndarray, work: float) -> np.ndarray:
        r"""Heß's largest elongation on the layer (generalised (8), :func:`~mdr_events.theory.layer.hess_elongation`).

        .. math:: \Delta l_\mathrm{max}(x) = \sqrt{\frac{4\pi |x|\,\Delta\gamma}{K'(|x|)}}

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).
        work : float
            The work of adhesion ``Δγ`` (J/m²).

        Returns
        -------
        numpy.ndarray
            ``Δl_max`` (m).
        """
        from mdr_events.theory.layer import hess_elongation

        return hess_elongation(positions, work, *self._material, self.layer)

    def branch_radius(self, depth: float) -> float:
        """The contact radius at ``depth`` on the layer's ``Δγ0`` branch (:func:`~mdr_events.layer_normal_curve`).

        Parameters
        ----------
        depth : float
            The depth (m).

        Returns
        -------
        float
            The radius (m; ``nan`` below the branch's jump-off).
        """
        if theory_of(self.indenter).flat_face:  # (the face's radius from the first touch on)
            return float(indenters.branch_radius(depth, self.params, self.params.dgamma0, self.indenter))
        return _layer_branch_radius(self.params, self.indenter, self.layer, float(depth))

    def normal_weights(self, positions: np.ndarray) -> np.ndarray:
        r"""The springs' normal stiffness in units of ``E* Δx``: ``k(x_j)/E*``
        (:func:`~mdr_events.theory.layer.spring_stiffness_density`).

        .. math:: k(x) = \tfrac12 K'(|x|) = E^*\,\Theta(1; |x|/h)^2

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        numpy.ndarray
            ``k(x_j)/E*``.
        """
        from mdr_events.theory.layer import spring_stiffness_density

        return spring_stiffness_density(positions, *self._material, self.layer) / self.params.E_star

    def tangential_weights(self, positions: np.ndarray) -> np.ndarray:
        r"""The springs' tangential stiffness in units of ``G* Δx``: ``k_t(x_j)/G*``
        (:func:`~mdr_events.theory.layer_tangential.tangential_spring_stiffness_density`).

        .. math:: k_t(x) = \tfrac12 K_t'(|x|) = G^*\,\Sigma_t(|x|/h) \quad (T4)

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        numpy.ndarray
            ``k_t(x_j)/G*``.
        """
        from mdr_events.theory.layer_tangential import tangential_spring_stiffness_density

        G_star = self.params.G_star
        return tangential_spring_stiffness_density(positions, G_star, self.params.nu, self.layer) / G_star

    def caps(self, springs: int, dx: float, friction: FrictionLaw) -> np.ndarray:
        r"""The cap of the law ``τ0`` on the layer at the radii ``m Δx`` (0 for a law without ``τ0``;
        :func:`~mdr_events.theory.layer_tangential.sliding_cap`).

        .. math:: \bar u(a) = \frac{\pi a^2 \tau_0}{K_t(a)} \qquad (13)

        Parameters
        ----------
        springs : int
            The springs per side.
        dx : float
            The spacing (m).
        friction : FrictionLaw
            The friction law (``τ0`` is ``params.tau0``).

        Returns
        -------
        numpy.ndarray
            ``ū(m Δx)`` (m), ``springs + 1`` of them.
        """
        from mdr_events.theory.layer_tangential import sliding_cap

        radii = dx * np.arange(springs + 1)
        if not friction.uses_tau0:
            return np.zeros(radii.shape)
        return sliding_cap(radii, self.params.tau0, self.params.G_star, self.params.nu, self.layer)

    def coulomb_ratios(self, positions: np.ndarray, friction: FrictionLaw) -> np.ndarray:
        r"""Coulomb's cap per compression of each spring on the layer, ``μ k(x_j)/k_t(x_j)``
        (:func:`~mdr_events.theory.layer_tangential.coulomb_cap` per unit of ``d − g``).

        .. math:: \bar u_j = \mu\,\frac{k(x_j)}{k_t(x_j)}\,\max(d - g(x_j), 0)

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).
        friction : FrictionLaw
            The friction law.

        Returns
        -------
        numpy.ndarray
            The ratios (0 without Coulomb's part).
        """
        from mdr_events.theory.layer_tangential import coulomb_cap

        if not friction.coulomb_mu > 0.0:
            return np.zeros(np.shape(positions))
        return coulomb_cap(positions, 1.0, 0.0, friction.coulomb_mu, self.params.E_star, self.params.G_star,
                           self.params.nu, self.layer)

    def shift_sum(self, positions: np.ndarray) -> Callable[[np.ndarray], float]:
        """How the shifts of the springs in contact (from the centre out) add up in units of ``G* Δx``:
        ``Σ (k_t(x_j)/G*) u_j``.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        callable
            The weighted sum of an array of shifts of the first springs.
        """
        weights = self.tangential_weights(positions)

        def weighted(shifts: np.ndarray) -> float:
            return float(shifts @ weights[:shifts.size])

        return weighted

    def weight_prefix(self, positions: np.ndarray) -> tuple[Sequence[int], int]:
        """The springs' tangential weights ``k_t(x_j)/G*`` as integers in units of ``2**-bits`` for the grouped sums
        (:class:`~mdr_events.models.spring_groups.SpringGroups`): each rounded to 53 bits of the largest, so that the
        sums of the groups are exact and a weight is within ``2**-53`` of the largest of its value.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        tuple of (list of int, int)
            The sums of the integer weights below each index (``len(positions) + 1`` of them) and ``bits``.
        """
        weights = self.tangential_weights(positions)
        bits = 53 - int(np.frexp(np.max(weights))[1]) if weights.size else 0
        integers = np.rint(np.ldexp(weights, bits)).astype(np.int64).tolist()
        return list(itertools.accumulate(integers, initial=0)), bits

    def most_springs(self, dx: float) -> int:
        """The most springs per side whose relations the layer's tables give: the radius ``m Δx`` of the last one
        (its cap) within ``a/h = 64`` (the tables' last radius, :data:`~mdr_events.theory.layer.compliance.LAMBDA_MAX`).

        Parameters
        ----------
        dx : float
            The spacing (m).

        Returns
        -------
        int
            ``floor(64 h / Δx)`` (``sys.maxsize`` if beyond: a layer so thick that ``64 h`` overflows is no bound).
        """
        from mdr_events.theory.layer.compliance import LAMBDA_MAX

        most = LAMBDA_MAX * self.layer.thickness // dx
        return int(most) if most < sys.maxsize else sys.maxsize

    def to_attrs(self) -> dict[str, Any]:
        """The layer's attributes (``param_layer_thickness``, ``param_layer_base``; :meth:`Layer.to_attrs
        <mdr_events.contact.layer.Layer.to_attrs>`).

        Returns
        -------
        dict
            The thickness with its units and the base.
        """
        return self.layer.to_attrs()


class FrictionlessLayerSprings(LayerSprings):
    """A layer on a frictionless base: the normal springs of :class:`LayerSprings`, without tangential ones.

    Such a layer slides on its base as a plate: the tangential stiffness of a punch on an unbounded layer is 0
    (:func:`~mdr_events.theory.layer_tangential.check_bonded`), so a path that moves the indenter tangentially is
    refused; on a path without tangential motion no spring is shifted, ``F_x = 0`` and none slides.
    """

    def check(self, adhesion: AdhesionLaw, paths: list[Path]) -> None:
        """Refuse another adhesion law than the paper's, and a path with tangential motion.

        Parameters
        ----------
        adhesion : Adhesion or RateDependentAdhesion
            The adhesion law.
        paths : list of Path
            The cases' paths.

        Raises
        ------
        TypeError
            A law other than :class:`~mdr_events.Adhesion`.
        ValueError
            A path whose tangential position changes.
        """
        super().check(adhesion, paths)
        for index, path in enumerate(paths):
            x = path.waypoints[:, 0]
            if np.any(x != x[0]):
                raise ValueError(f"path {index} moves the indenter tangentially (x from {x.min():.6g} m to "
                                 f"{x.max():.6g} m), which is not allowed on {self.layer.describe()}: a layer on a "
                                 "frictionless base has no tangential stiffness (K_t = 0); allowed: paths without "
                                 "tangential motion (alpha = 90), or a bonded base")

    def tangential_weights(self, positions: np.ndarray) -> np.ndarray:
        """No tangential springs: 0 each.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        numpy.ndarray
            Zeros.
        """
        return np.zeros(np.shape(positions))

    def caps(self, springs: int, dx: float, friction: FrictionLaw) -> np.ndarray:
        """No cap is ever reached (no spring is shifted): the largest double, a finite cap for the groups' integers.

        Parameters
        ----------
        springs : int
            The springs per side.
        dx : float
            The spacing (m).
        friction : FrictionLaw
            The friction law.

        Returns
        -------
        numpy.ndarray
            ``sys.float_info.max``, ``springs + 1`` of them.
        """
        return np.full(springs + 1, sys.float_info.max)

    def coulomb_ratios(self, positions: np.ndarray, friction: FrictionLaw) -> np.ndarray:
        """No Coulomb cap: 0 each.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).
        friction : FrictionLaw
            The friction law.

        Returns
        -------
        numpy.ndarray
            Zeros.
        """
        return np.zeros(np.shape(positions))


@cached(64)  # (a user's unhashable indenter subclass by its exact value: issue 32 round 28 A3)
def _layer_branch_radius(params: Parameters, indenter: Paraboloid | PowerLaw, layer: Layer, depth: float) -> float:
    """The radius at ``depth`` on the layer's ``Δγ0`` branch (:func:`~mdr_events.layer_normal_curve`), kept for the
    checks of a run that ask it twice (the spacing and the size)."""
    from mdr_events.contact.model import Contact
    from mdr_events.theory.layer import layer_normal_curve

    contact = Contact(Elastomer(params.E, params.nu), indenter, Adhesion(params.dgamma0, params.dgamma1), layer=layer)
    curve = layer_normal_curve(contact, [depth])
    return float(curve["contact_radius"].sel(branch="dgamma0").values[0])
