r"""The flat punch's branch on a layer of finite thickness: the face held, then the receding contact under it.

Under the face every spring rests on ``g = 0`` (:mod:`mdr_events.theory.layer_symbolic`, sections 7 and 8): going in
the contact is the face's radius ``a₀`` from the first touch on; going out its edge lets go at ``d = −Δl(a₀)``, and
where Heß's limit ``Δl(a) = sqrt(4π a Δγ/K'(a))`` falls with the radius (``a K'' > K'``, thin nearly incompressible
bonded layers) the next spring inside holds further out: the radius recedes along ``d = −Δl(a)`` (the layer's
branch (9) with ``g = 0``, :class:`~.layer_branch.LayerBranch`'s relations with ``κₙc = 0``) down to where
``dΔl/da = 0`` (``layer_flat_punch_receding_slope``), the jump-off, where the rest comes off at once. Where ``Δl``
rises or stays at ``a₀`` (the half-space's ``√a``, Winkler's constant) the jump-off is the face itself: the
half-space's :class:`~.branch.FlatPunchBranch`'s jump, Kendall's depth on the layer.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from mdr_events.contact.indenters import FlatPunch
from mdr_events.contact.layer import Layer
from mdr_events.parameters import Parameters
from mdr_events.theory.layer.punch_recession import receding_radius
from mdr_events.theory.layer.scalar_factors import NormalFactors

from .layer_branch import LayerBranch, _branch_key
from .tolerances import MAX_RADIUS_RTOL

__all__ = ["LayerPunchBranch", "FACE_SHARE"]

#: A radius this share below the face's still counts as the face's: the held contact's radius, and a growth that reaches
#: the face (where it stops) to its root's accuracy. Ten times the loosest root (``Tolerances.radius_rtol <=``
#: ``MAX_RADIUS_RTOL``), as ``PIECE_SHARE``: a root of the face's radius lands within
#: it at any allowed tolerance, and no root a whole share below it is taken for the face.
FACE_SHARE = 10.0 * MAX_RADIUS_RTOL
#: The receding radii kept (:func:`_receding_radius`): one per material, layer and face, as many as the media's factors
#: (``media.FACTOR_CACHE``). Keyed by those values (floats and the frozen ``Layer``), not by the factors object, so an
#: evicted medium's factors are not held alive here.
RECEDING_CACHE = 256


@functools.lru_cache(maxsize=RECEDING_CACHE)
def _receding_radius(nu: float, layer: Layer, exponent: float, face: float) -> float:
    """:func:`~mdr_events.theory.layer.punch_recession.receding_radius` of the factors ``NormalFactors(nu, layer,
    exponent)`` (what :class:`~.layer_media.LayerMedium` builds, its table cached per ``(ν, base, n)``), kept: it
    depends on the layer and the face alone, not on the work, and a run's two branches (``Δγ0``, ``Δγ1``) and every
    run of the same contact ask it again (a scan of 97 radii and Brent's method, 0.1 ms each)."""
    return receding_radius(NormalFactors(nu, layer, exponent), face)


class LayerPunchBranch(LayerBranch):
    r"""The branch of work ``work`` of a flat punch of radius ``a₀`` on ``layer``: ``d(a) = −Δl(a)`` for ``a <= a₀``.

    .. math:: d(a) = -\sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}}, \qquad
              \frac{\mathrm{d}d}{\mathrm{d}a} = \Delta l\,\frac{a K'' - K'}{2 a K'} \qquad (8)

    The radius of a depth at or above ``d(a₀)`` is ``a₀`` (the face held); below it the root on ``[a_j, a₀]``, ``a_j``
    the jump-off (the largest radius below ``a₀`` where ``dd/da`` turns, or ``a₀`` where it is not positive there);
    ``nan`` below the jump-off's depth. The contact never grows beyond the face (:meth:`growth_depth` ``+inf`` there).

    Parameters
    ----------
    params : Parameters
        The material (``E*``).
    work : float
        The work of adhesion ``Δγ`` (J/m²) of the branch (0: the face from ``d = 0`` on, off above the surface).
    indenter : FlatPunch
        The punch.
    layer : Layer
        The layer (finite thickness).
    factors : NormalFactors
        The layer's tabulated normal factors for one float.
    """

    flat = True
    tip_power = None

    def __init__(self, params: Parameters, work: float, indenter: FlatPunch, layer: Layer, factors: NormalFactors):
        #: the face's radius ``a₀``
        self.face = float(indenter.radius)
        #: the least radius that counts as the face's (:data:`FACE_SHARE` below it)
        self.face_floor = self.face * (1.0 - FACE_SHARE)
        super().__init__(params, work, indenter, layer, factors)
        if work == 0.0:  # (the face comes off at the surface: no root below it, the floor is the face too)
            self.jump_off_radius, self.jump_off_depth = self.face, 0.0
            self._floor = self.face
        self.held_depth = self.depth(self.face) if work > 0.0 else 0.0
        #: a receded contact pressed back in grows along ``d = −Δl(a)`` until the face's edge: there it stops
        self.edge_depth = self.held_depth

    def _power(self, indenter) -> tuple[float, float]:
        return 0.0, 2.0  # (g = 0 under the face: the profile's term vanishes, its table's exponent unread)

    def _ceiling(self, indenter) -> float:
        return float(indenter.radius)

    def _jump_off_radius(self) -> float:
        """The largest radius ``<= a₀`` where the recession stops, ``dΔl/da = 0``
        (:func:`~mdr_events.theory.layer.punch_recession.receding_radius`; the face itself where ``Δl`` does not fall
        there), kept per material, layer and face (:func:`_receding_radius`)."""
        return _receding_radius(self.params.nu, self.layer, self.factors.n, self.face)

    def _key(self) -> tuple:
        return (*_branch_key(self), self.face)

    def depth(self, a: float) -> float:
        """``−Δl(a)`` for ``0 < a <= a₀`` (``−Δl(a₀)`` beyond the face; 0 at ``a = 0``).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``d`` (m).
        """
        return super().depth(min(a, self.face))

    def growth_depth(self, a: float) -> float:
        """The depth beyond which a contact of radius ``a`` grows: ``+inf`` at the face (it never grows beyond it),
        :meth:`depth` below it (a receded contact pressed back in).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The depth (m).
        """
        return math.inf if a >= self.face_floor else self.depth(a)

    def slope(self, a: float) -> float:
        """``dd/da`` below the face (``layer_flat_punch_receding_slope``), ``+inf`` beyond it (the radius stops there).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The slope (1).
        """
        return math.inf if a > self.face else super().slope(a)

    def depth_term(self, a: float) -> float:
        """``g(a) = 0``: the springs rest on the face.

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            0.
        """
        return 0.0

    def _evaluate(self, a: float) -> tuple[float, float]:
        """``d(a)`` and ``∂d/∂a`` at one radius from ``Θ`` alone (``NormalFactors.edge_factor``), as :meth:`_arrays`:
        with ``κₙc = 0`` the profile factor's terms are ``0·γₙ``, so ``γₙ = 0`` leaves both
        :class:`~.layer_branch.LayerBranch`'s bit for bit, without its column's Horner sum and exponential a
        reading (the receding span's events and its radius read the branch some hundred times a run)."""
        theta, theta_slope = self.factors.edge_factor(a)
        return self._pair(a, self.h, self.kc, self.n, 0.0, 0.0, self.hess, theta, theta_slope)

    def _arrays(self, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``d(a)`` and ``∂d/∂a`` for an array of radii (> 0) from ``Θ`` alone (``NormalFactors.edge_arrays``): with
        ``κₙc = 0`` the profile factor's terms are ``0·γₙ``, so ``γₙ = 0`` leaves both bit for bit as
        :class:`~.layer_branch.LayerBranch`'s, without its column's half of the splines' cost."""
        theta, theta_slope = self.factors.edge_arrays(a)
        return self._pair_array(a, self.h, self.kc, self.n, 0.0, 0.0, self.hess, theta, theta_slope)

    def depths(self, a: np.ndarray) -> np.ndarray:
        return super().depths(np.minimum(np.asarray(a, dtype=float), self.face))

    def radius(self, depth: float, rtol: float) -> float:
        """The radius at ``depth``: the face's at or above :attr:`held_depth`, the receding branch's root below it,
        ``nan`` below the jump-off's depth (within :data:`~.branch.FOLD_SHARE` of it, the jump-off radius).

        Parameters
        ----------
        depth : float
            The depth ``d`` (m).
        rtol : float
            The relative accuracy of the root.

        Returns
        -------
        float
            The radius ``a`` (m) or ``nan``.
        """
        if depth >= self.held_depth:
            return self.face
        if self.work == 0.0:  # (no contact above the surface: come off, as the half-space's face)
            return math.nan
        radius = super().radius(depth, rtol)
        return self.face if radius >= self.face_floor else radius  # (the face's, not a root an ulp off)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        depth = np.asarray(depth, dtype=float)
        held = depth >= self.held_depth
        if self.work == 0.0:
            return np.where(held, self.face, np.nan)
        out = np.full(depth.shape, self.face)
        if not np.all(held):
            out[~held] = super().radii(depth[~held])
        return np.where(out >= self.face_floor, self.face, out)

    def sample_radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radii` at a run's samples: on the recession the inverse tabulated once per branch
        (:func:`~.punch_inverse.recession_inverse`, within what :meth:`radii`' roots hold to,
        ``punch_inverse.accuracy``, where it covers them), :meth:`radii` elsewhere (the face held, below the jump-off, an interval the table did
        not keep).

        Parameters
        ----------
        depth : array_like
            The depths (m).

        Returns
        -------
        numpy.ndarray
            The radii (m), the shape of ``depth``.
        """
        depth = np.asarray(depth, dtype=float)
        receding = depth < self.held_depth
        if self.work == 0.0 or self.jump_off_radius >= self.face_floor or not np.any(receding):
            return self.radii(depth)
        from .punch_inverse import recession_inverse

        found, covered = recession_inverse(self).radii(depth[receding])
        if not np.all(covered):
            found[~covered] = self.radii(depth[receding][~covered])
        out = np.full(depth.shape, self.face)
        out[receding] = found
        return np.where(out >= self.face_floor, self.face, out)
