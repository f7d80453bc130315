"""The springs that slide during a span of ``"tau0+coulomb"`` with adhesion, read off the span's own layouts.

A span of :class:`~.split_span.SplitSpanIntegrator` lays out each cap of each region once, at its start
(:class:`~.regions.RegionLayout`), and the layouts stay right until the event that ends it: the right-hand side reads
the zones' sizes off them. :class:`SpanZones` keeps them with the span, so that the sliding fraction at any instant of
it is the same sum (:meth:`~.regions.RegionLayout.sizes`, vectorised over the instants: the parts inside a zone by
their lengths, a front by its root) instead of a scan of every part of the anchors
(:meth:`~.split_map.SpanMaps.sliding_length`, which the spans without layouts, those of zero length, still use).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from .formulas import Shape
from .regions import Region, RegionLayout

if TYPE_CHECKING:
    from .caps import Caps

__all__ = ["SpanZones"]


class SpanZones:
    """The layouts of one span and what its regions' extents follow.

    Parameters
    ----------
    layouts : dict
        Each cap's layout in each region (keys ``(Region, Cap)``), as the span laid them out.
    shape : Shape
        The functions of the contact (``x_c`` of a depth).
    pressed : bool
        Whether the depth is positive during the span (else every spring is in tension: ``x_c = 0``).
    x_c_is_edge : bool
        Whether ``x_c`` is the contact's edge (a moving radius on a branch without adhesion).
    """

    def __init__(self, layouts: dict[tuple, RegionLayout], shape: Shape, pressed: bool, x_c_is_edge: bool):
        self.layouts, self.shape, self.pressed, self.x_c_is_edge = layouts, shape, pressed, x_c_is_edge

    def boundaries(self, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
        """``x_c`` at each instant, as the span's integrator has it (``SplitSpanIntegrator.boundary``).

        Parameters
        ----------
        depth : numpy.ndarray
            The depths (m).
        radius : numpy.ndarray
            The contact radii (m).

        Returns
        -------
        numpy.ndarray
            ``x_c`` (m).
        """
        if self.x_c_is_edge:
            return radius
        if self.pressed:
            return np.minimum(self.shape.boundaries(depth), radius)
        return np.zeros(np.shape(radius))

    def sliding_length(self, caps: "Caps", x: np.ndarray, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
        """The length (m) of the springs at either cap at several instants of the span: the sum of its layouts'
        sizes (the right-hand side's sum, vectorised).

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
        boundary = self.boundaries(depth, radius)
        total = np.zeros(np.broadcast(x, depth, radius).shape)
        for (region, cap), layout in self.layouts.items():
            lower, upper = (0.0, boundary) if region is Region.COMPRESSED else (boundary, radius)
            total = total + layout.sizes(region.level(cap, x, caps.K, caps.kappa, radius, depth), lower, upper)
        return total
