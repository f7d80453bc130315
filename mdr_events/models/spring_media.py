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

import functools
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
from mdr_events.contact.layer import HALF_SPACE, Layer, LayerBase
from mdr_events.memo import cached
from mdr_events.models import indenters
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory import analytic, mindlin, symbolic
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import shown

__all__ = ["HalfSpaceSprings", "LayerSprings", "FrictionlessLayerSprings", "Springs", "springs_of"]


@dataclass(frozen=True)
class HalfSpaceSprings:
    """The paper's springs on the half-space: all alike, ``E* Δx`` and ``G* Δx`` (5), (6).

    Parameters
    ----------
    params : Parameters
        The material (``E*``, ``G*``), the works of adhesion and ``τ0``.
    indenter : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter as the simulators take it (``None``: the paraboloid of ``params.R``; also ``None`` for a run
        given ``g(x)`` alone), for its branch radius.
    given_profile : callable, optional
        The springs' profile ``g(x)`` (vectorised, m), if given as a function; default the indenter's
        (:func:`~mdr_events.models.indenters.spring_profile`, made when first used).
    """

    params: Parameters
    indenter: SimulatedProfile = None
    given_profile: Callable[[np.ndarray], np.ndarray] | None = None

    #: Whether the springs are stepped in groups that share a shift
    #: (:class:`~mdr_events.models.spring_groups.SpringGroups`), else each on its own
    #: (:func:`~mdr_events.models.discrete._run_case_per_spring`).
    grouped = True
    #: The bytes a run allocates per spring (thresholds, caps, the kernel's groups), counted against
    #: :attr:`~mdr_events.Limits.memory` before it runs: measured with tracemalloc (260 at 1.5e6 springs).
    bytes_per_spring = 256

    def check(self, adhesion: AdhesionLaw, paths: list[Path]) -> None:
        """Nothing to refuse: the half-space takes every law and path the discrete model takes.

        Parameters
        ----------
        adhesion : Adhesion or RateDependentAdhesion
            The adhesion law.
        paths : list of Path
            The cases' paths.
        """

    @functools.cached_property
    def _profile(self) -> Callable[[np.ndarray], np.ndarray]:
        return indenters.spring_profile(self.params, self.indenter) if self.given_profile is None \
            else self.given_profile

    def profile(self, positions: np.ndarray) -> np.ndarray:
        """The springs' profile ``g(x_j)``: ``x²/R`` (4), a power law's (3), the flat punch's or a table's.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        numpy.ndarray
            ``g`` (m).
        """
        return self._profile(positions)

    def elongation(self, positions: np.ndarray, work: float) -> np.ndarray:
        r"""Heß's largest elongation of the springs at ``positions`` (8).

        .. math:: \Delta l_\mathrm{max}(x) = \sqrt{\frac{2 \pi |x| \Delta\gamma}{E^*}} \qquad (8)

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
        return symbolic.relation("hess_max_elongation").numeric(positions, work, self.params.E_star)

    def branch_radius(self, depth: float) -> float:
        """The contact radius at ``depth`` on the ``Δγ0`` branch (:func:`~mdr_events.models.indenters.branch_radius`).

        Parameters
        ----------
        depth : float
            The depth (m).

        Returns
        -------
        float
            The radius (m; ``nan`` below the branch's jump-off).
        """
        return float(indenters.branch_radius(depth, self.params, self.params.dgamma0, self.indenter))

    def normal_weights(self, positions: np.ndarray) -> np.ndarray:
        """The springs' normal stiffness in units of ``E* Δx``: 1 each (5).

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        numpy.ndarray
            Ones.
        """
        return np.ones(np.shape(positions))

    def caps(self, springs: int, dx: float, friction: FrictionLaw) -> np.ndarray:
        r"""The cap (13) of the law ``τ0`` at the radii ``m Δx``, ``m = 0 … springs`` (0 for a law without ``τ0``).

        .. math:: \bar u(a) = \frac{\pi a \tau_0}{2 G^*} \qquad (13)

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
        # ū is linear in a (13); a law without τ0's part has none
        shift_per_radius = float(analytic.critical_shift(1.0, self.params)) if friction.uses_tau0 else 0.0
        return (shift_per_radius * dx) * np.arange(springs + 1)

    def coulomb_ratios(self, positions: np.ndarray, friction: FrictionLaw) -> np.ndarray:
        r"""Coulomb's cap per compression of each spring, ``κ = μ E*/G*`` (0 without Coulomb's part).

        .. math:: \bar u_j = \kappa \max(d - g(x_j), 0)

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).
        friction : FrictionLaw
            The friction law.

        Returns
        -------
        numpy.ndarray
            ``κ`` at each spring.
        """
        return np.full(np.shape(positions), mindlin.coulomb_cap_ratio(friction, self.params))

    def shift_sum(self, positions: np.ndarray) -> Callable[[np.ndarray], float]:
        """How the shifts of the springs in contact (from the centre out) add up in units of ``G* Δx``: a plain sum.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        callable
            ``Σ u`` of an array of shifts.
        """
        return np.sum

    def weight_prefix(self, positions: np.ndarray) -> tuple[Sequence[int], int]:
        """The springs' tangential weights as integers for the grouped sums: every spring weighs 1.

        Parameters
        ----------
        positions : numpy.ndarray
            The springs' centres (m).

        Returns
        -------
        tuple of (sequence of int, int)
            The sums of the weights below each index (``j``) and their scale's bits (0).
        """
        return range(sys.maxsize), 0

    def most_springs(self, dx: float) -> int:
        """The most springs per side whose relations are known: any number on the half-space (a table's reach is
        checked apart, :func:`~mdr_events.models.indenters.check_reach`).

        Parameters
        ----------
        dx : float
            The spacing (m; any serves here).

        Returns
        -------
        int
            ``sys.maxsize``: no bound.
        """
        return sys.maxsize

    def to_attrs(self) -> dict[str, Any]:
        """The half-space stamps no attribute (its results are those written before layers existed).

        Returns
        -------
        dict
            Empty.
        """
        return {}


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
    #: As :attr:`HalfSpaceSprings.bytes_per_spring`, with the springs' weights and their integer prefix sums (Python
    #: integers): 317 measured at 4e5 and 2e6 springs (counted as the half-space's 256, a run passed the memory limit
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
