"""One adhesive branch (9) of the contact radius, evaluated for Python floats and arrays."""

from __future__ import annotations

import math

import numpy as np

from mdr_events.theory import analytic, symbolic
from mdr_events.parameters import Parameters

#: A depth this share below the jump-off depth still gives the jump-off radius: a radius pinned just
#: outside the fold is released at a depth that rounds below it.
FOLD_SHARE = 1e-9


class Branch:
    """The branch (9) of the contact radius with work of adhesion ``work``: depth, slope and integral
    of a radius, radius of a depth.

    The scalar methods use the derived relations compiled for Python floats
    (:attr:`mdr_events.symbolic.Relation.scalar`): the right-hand side and the event functions of
    the continuum method call them thousands of times per run. The radius of a depth is the largest
    positive root of the quartic in ``s = sqrt(a)`` (:func:`mdr_events.analytic.positive_polynomial_root`),
    above the jump-off radius (the stable branch).
    """

    def __init__(self, params: Parameters, work: float):
        self.params = params
        self.work = work
        self._arguments = (params.R, params.E_star, work)
        self._depth = symbolic.relation("jkr_depth").scalar
        self._slope = symbolic.relation("jkr_depth_slope").scalar
        self._integral = symbolic.relation("jkr_depth_integral").scalar
        self._coefficients = symbolic.relation("jkr_radius_quartic").scalar_coefficients
        if work > 0:
            point = analytic.jump_off(params, work)
            self.jump_off_radius, self.jump_off_depth = point["contact_radius"], point["depth"]
        else:
            self.jump_off_radius = self.jump_off_depth = 0.0
        self._floor = math.sqrt(self.jump_off_radius)

    def depth(self, a: float) -> float:
        """Depth of the contact of radius ``a`` on this branch, eq. (9) (0 at ``a = 0``)."""
        return self._depth(a, *self._arguments) if a > 0 else 0.0

    def slope(self, a: float) -> float:
        """``dd/da`` on this branch; its limits at ``a → 0``: 0 for Hertz, ``-inf`` with adhesion."""
        if a > 0:
            return self._slope(a, *self._arguments)
        return 0.0 if self.work == 0.0 else -math.inf

    def integral(self, a: float) -> float:
        """``∫_0^a d(ξ) dξ`` along this branch."""
        return self._integral(a, *self._arguments) if a > 0 else 0.0

    def depths(self, a: np.ndarray) -> np.ndarray:
        """:meth:`depth` for an array of radii (vectorised)."""
        a = np.asarray(a, dtype=float)
        value = symbolic.relation("jkr_depth").numeric(np.where(a > 0, a, 1.0), *self._arguments)
        return np.where(a > 0, value, 0.0)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radius` for an array of depths (vectorised; ``nan`` below the jump-off depth)."""
        return np.asarray(analytic.jkr_contact_radius(np.asarray(depth, dtype=float), self.params, self.work))

    def radius(self, depth: float, rtol: float) -> float:
        """Stable-branch radius at ``depth``, converged to ``rtol``.

        ``nan`` below the jump-off depth; within :data:`FOLD_SHARE` of it, the jump-off radius.
        """
        if self.work == 0.0:  # Hertz: no contact above the surface (d <= 0, to rounding at first contact)
            return math.sqrt(self.params.R * depth) if depth > 0 else 0.0
        if depth < self.jump_off_depth:
            if depth < self.jump_off_depth * (1.0 + FOLD_SHARE):
                return math.nan
            return self.jump_off_radius
        coefficients = self._coefficients(depth, *self._arguments)
        root = analytic.positive_polynomial_root(coefficients, lower=self._floor, rtol=rtol)
        return root * root
