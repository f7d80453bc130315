"""The maps one span of ``"tau0+coulomb"`` with adhesion reads each region from (:class:`SpanMaps`).

The stored map (:class:`~.split_map.SplitAnchorMap`), and for the region the springs cross into, the stored map with
the anchors of the crossing over the swept interval; at the span's end the two are joined at ``x_c`` into the stored
map again (:mod:`.split_map`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .regions import Region
from .split_sums import region_shift_integral, zone_lengths
from .state import Cap

if TYPE_CHECKING:
    from .caps import Caps
    from .split_map import SplitAnchorMap

__all__ = ["SpanMaps"]


@dataclass
class SpanMaps:
    """The maps one span reads each region from: the stored map, and for the region springs cross into, the stored
    map with the anchors of the crossing over the swept interval (:mod:`.split_span`).

    Parameters
    ----------
    compressed : SplitAnchorMap
        The map of the compressed zone.
    tensile : SplitAnchorMap
        The map of the tensile annulus.
    """

    compressed: SplitAnchorMap
    tensile: SplitAnchorMap

    def of(self, region: Region) -> SplitAnchorMap:
        """The map ``region`` is read from.

        Parameters
        ----------
        region : Region
            The region.

        Returns
        -------
        SplitAnchorMap
            Its map.
        """
        return self.compressed if region is Region.COMPRESSED else self.tensile

    def joined(self, boundary: float, t: float) -> SplitAnchorMap:
        """The stored map at the span's end (path time ``t``): the compressed map below ``boundary`` (``x_c``), the
        tensile above.

        Parameters
        ----------
        boundary : float
            ``x_c`` at the span's end (m).
        t : float
            The span's end (s on the path's clock).

        Returns
        -------
        SplitAnchorMap
            The stored map, :attr:`SplitAnchorMap.joined_at` set.
        """
        stored = self.compressed.joined(self.tensile, boundary)
        stored.joined_at = (t, boundary)
        return stored

    def boundary(self, depth: float, radius: float) -> float:
        """``x_c`` of ``depth`` in a contact of radius ``radius`` (at most the radius).

        Parameters
        ----------
        depth : float
            The depth (m).
        radius : float
            The contact radius (m).

        Returns
        -------
        float
            ``x_c`` (m).
        """
        return min(self.compressed.shape.boundary(depth), radius)

    def tangential_force(self, caps: "Caps", G_star: float, x: float, a: float, depth: float = 0.0) -> float:
        """``F_x = 2G* ∫_0^a clip(x − Y, −ū(ξ), ū(ξ)) dξ`` (N), each region from its map, without integration
        (:func:`~.split_sums.region_shift_integral`; 0 out of contact).

        Parameters
        ----------
        caps : Caps
            The friction law's caps.
        G_star : float
            ``G*`` (Pa).
        x : float
            The indenter's tangential position (m).
        a : float
            The contact radius (m).
        depth : float, default 0.0
            The depth ``d`` (m).

        Returns
        -------
        float
            ``F_x`` (N).
        """
        if not a > 0 or not self.compressed.pieces:
            return 0.0
        boundary = self.boundary(depth, a)
        total = sum(region_shift_integral(self.of(region), region, caps, x, a, depth, lower, upper)
                    for region, lower, upper in ((Region.COMPRESSED, 0.0, boundary), (Region.TENSILE, boundary, a)))
        return 2.0 * G_star * total

    def sliding_length(self, caps: "Caps", x: np.ndarray, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
        """The length (m) of the springs at either cap at several instants (vectorised:
        :func:`~.split_sums.zone_lengths` in each region and at each cap).

        Parameters
        ----------
        caps : Caps
            The friction law's caps.
        x, depth, radius : numpy.ndarray
            The indenter's position, the depth and the contact radius at each instant (m).

        Returns
        -------
        numpy.ndarray
            The lengths (m).
        """
        x, depth, radius = (np.asarray(v, dtype=float) for v in (x, depth, radius))
        boundary = np.minimum(self.compressed.shape.boundaries(depth), radius)
        total = np.zeros(np.broadcast(x, depth, radius).shape)
        for cap in Cap:
            for region, lower, upper in ((Region.COMPRESSED, np.zeros_like(boundary), boundary),
                                         (Region.TENSILE, boundary, radius)):
                levels = region.level(cap, x, caps.K, caps.kappa, radius, depth)
                total += zone_lengths(self.of(region), region, cap, levels, lower, upper, caps.kappa)
        return total
