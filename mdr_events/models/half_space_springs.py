r"""The paper's springs on the half-space: all alike, ``E* Δx`` and ``G* Δx`` (5), (6).

One kind of the discrete model's springs (:mod:`mdr_events.models.spring_media`, which looks the kind up): the
paper's own functions, unchanged, for the profile ``g(x)`` (3), Heß's ``Δl`` (8), the cap (13) ``π a τ0/(2G*)`` and
Coulomb's ``μ (E*/G*)(d − g)``; the weights of the sums (15) are 1.
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from mdr_events.contact.adhesion import AdhesionLaw
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models import indenters
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory import analytic, mindlin, symbolic

__all__ = ["HalfSpaceSprings"]


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
