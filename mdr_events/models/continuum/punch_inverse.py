r"""The receding punch's radius of a depth read off a table made once per branch (issue 34): what a run's samples take.

On a thin layer a flat punch's contact recedes along ``d = −Δl(a)`` from the face's radius ``a₀`` down to the jump-off
``a_j`` (:class:`~.layer_punch_branch.LayerPunchBranch`), and a run samples that branch at some hundreds of depths.
Newton's iteration from the start scan reads the branch's tables once on all of them and again, in floats, near the
fold (:meth:`~.layer_branch.LayerBranch.radii`); here the inverse is tabulated once per branch (:data:`_TABLES`: every
run of one contact shares it) and a sample's radius is a cubic Hermite interpolant, without reading the tables.

The variable is ``u = sqrt(d − d_j)`` (``d_j`` the jump-off's depth), not ``d``: at the fold ``∂d/∂a = 0`` and ``a(d)``
has a square root, while ``a(u)`` is smooth through it (``d − d_j ≈ ½ d''(a_j)(a − a_j)²``), its slope
``da/du = 2u/(∂d/∂a)``. The nodes are :data:`NODES_PER_DECADE` radii a decade from the jump-off to the face, each
with its depth and slope from one reading of the tables. The cubic Hermite interpolant's error on an interval of width
``Δu`` is ``a''''(ξ) t²(1 − t)² Δu⁴/24`` (``t`` the position in the interval, ``ξ`` somewhere in it), at most
``Δu⁴ max|a''''|/384``. Its largest value is in the middle only where ``a''''`` is constant across the interval; where
``a''''`` changes its sign inside, the middle's error can be near zero while the quarters' is not. So the table's
check is an estimate checked at points, not a bound: each interval's interpolant is compared at
:data:`CHECK_POINTS` (``t = ¼, ½, ¾``) with :meth:`~.layer_branch.LayerBranch.radii`' root there (Newton's, stopped
where its step's own bound is ``1e-2 RADII_RTOL``) and the interval kept where every one lies within
:data:`CHECK_SHARE` (half) of what that root itself holds to (:func:`accuracy`: ``RADII_RTOL · a`` plus the depth's
rounding through ``∂d/∂a``, which near the fold exceeds ``RADII_RTOL`` for the iteration's roots alike). The margin
of two covers ``a''''`` varying by up to a factor two across an interval ``10^(1/N)`` of the radius wide, where it
varies on the scale of ``a`` itself (by ~1e-3 of itself away from the fold); three points catch a sign change that
the middle alone misses. An interval that fails is split at its middle's root (a node of the branch's own depth and
slope) and its halves checked again, :data:`REFINEMENTS` times at most. A depth in an interval still failing, or
beyond the nodes (between the fold and the first node), takes :meth:`~.layer_branch.LayerBranch.radii`.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.theory.layer.scalar_factors import piece_index

from .layer_branch import RADII_RTOL

__all__ = ["RecessionInverse", "recession_inverse", "accuracy", "NODES_PER_DECADE", "DEPTH_ULPS", "CHECK_POINTS",
           "CHECK_SHARE", "REFINEMENTS"]

#: Nodes a decade of radius: the interpolant's truncation error falls as ``Δu⁴``. Measured at ``h/a₀ = 0.1``, 0.075
#: and 0.02 (ν = 0.5, the paper's works): at 2048 a decade the intervals away from the fold fail the check (their
#: truncation above ``RADII_RTOL``), at 4096 every interval passes (truncation 16 times lower, ``<~ 1e-15``); 6144 puts
#: it another ``1.5⁴ = 5`` times below that, ``<~ 3e-16`` of the radius, under the roots' rounding. A table of ~8000
#: nodes costs ~10 ms CPU once per branch (one reading of the tables and Newton's iteration at three points an
#: interval; ~4 ms with the middle alone), 8000-14000 nodes 10-18 ms at ``h/a₀ = 0.1`` to 0.01.
NODES_PER_DECADE = 6144
#: The rounding of a depth as the branch computes it, in ulps of ``|d|`` (Heß's limit over ``Θ`` of the tables: a
#: few operations of an ulp each), with a margin: the roots' error through ``∂d/∂a`` (:func:`accuracy`).
DEPTH_ULPS = 8.0
#: Where in each interval (its share ``t`` of ``Δu``) the table compares its interpolant with Newton's root.
CHECK_POINTS = (0.25, 0.5, 0.75)
#: The share of the roots' accuracy (:func:`accuracy`) an interval's interpolant must lie within at every point of
#: :data:`CHECK_POINTS` to be kept: a margin of two for the truncation error between the points (module docstring).
CHECK_SHARE = 0.5
#: How many times an interval that fails the check is split (each split cuts its truncation error sixteenfold).
REFINEMENTS = 2
#: How many branches' tables are kept (:data:`_TABLES`).
_KEPT = 64


class RecessionInverse:
    """The radius of a depth on a receding punch's branch between its jump-off and its face, by cubic Hermite
    interpolation in ``u = sqrt(d − d_j)`` (module docstring).

    Parameters
    ----------
    branch : LayerPunchBranch
        The branch (with adhesion: a jump-off below the face).
    """

    def __init__(self, branch):
        lowest, highest = branch.jump_off_radius, branch.face
        count = max(int(math.ceil(NODES_PER_DECADE * math.log10(highest / lowest))), 2) + 1
        radii = np.geomspace(lowest, highest, count)[1:]  # (not the jump-off itself: ∂d/∂a = 0 there, da/du 0/0)
        depths, slopes = branch._arrays(radii)
        #: ``d_j``, whose square root of the distance is the variable
        self.fold = branch.jump_off_depth
        u = np.sqrt(np.maximum(depths - self.fold, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            rates = 2.0 * u / slopes  # (da/du)
        #: the nodes: ``u``, ``a`` and ``da/du``
        self.u, self.a, self.rates = u, radii, rates
        #: the depths the nodes cover, ``[d(a_1), d(a₀)]``
        self.low, self.high = float(depths[0]), float(depths[-1])
        self._slopes = slopes
        every = np.arange(u.size - 1)
        #: whether each interval's interpolant is kept (:meth:`_check`)
        self.kept, errors = self._check(branch, every)
        for _ in range(REFINEMENTS):  # (an interval that fails split at its middle's root, the halves checked again)
            failed = np.flatnonzero(~self.kept & self._valid(every))
            if not failed.size:
                break
            left = self._split(branch, failed)
            every = np.arange(self.u.size - 1)
            halves = np.concatenate([left, left + 1])
            self.kept, errors = np.insert(self.kept, failed + 1, False), np.insert(errors, failed + 1, math.nan)
            self.kept[halves], errors[halves] = self._check(branch, halves)
        #: the largest error estimate kept, relative to the radius: the interpolant against Newton's root at the
        #: checked points (``t = ¼, ½, ¾``) of the kept intervals, not a bound over the intervals (module docstring)
        self.largest_error = float(np.max(errors[self.kept])) if self.kept.any() else math.nan

    def _valid(self, index: np.ndarray) -> np.ndarray:
        """Whether the intervals ``index`` can be interpolated: both ends' slopes positive, ``u`` increasing."""
        return (self._slopes[index] > 0.0) & (self._slopes[index + 1] > 0.0) & (self.u[index + 1] > self.u[index])

    def _check(self, branch, index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Whether each interval of ``index`` is kept: its interpolant within :data:`CHECK_SHARE` of the roots'
        accuracy (:func:`accuracy`) of Newton's root (:meth:`~.layer_branch.LayerBranch.radii`) at each of
        :data:`CHECK_POINTS`; and each one's largest error there relative to the radius."""
        u0, width = self.u[index], self.u[index + 1] - self.u[index]
        points = u0[:, None] + width[:, None] * np.asarray(CHECK_POINTS)[None, :]
        depth = self.fold + points * points
        found = branch.radii(depth.ravel()).reshape(points.shape)
        least = np.minimum(self._slopes[index], self._slopes[index + 1])[:, None]
        with np.errstate(invalid="ignore", divide="ignore"):
            error = np.abs(self._interpolate(points, index[:, None]) - found)
            kept = self._valid(index) & np.all(error <= CHECK_SHARE * accuracy(found, depth, least), axis=1)
            relative = np.max(error / found, axis=1)
        return kept, relative

    def _split(self, branch, failed: np.ndarray) -> np.ndarray:
        """Split the intervals ``failed`` at a node of Newton's root at their middles' ``u`` (its depth and slope read
        again, so a node is the branch's own point); the left halves' indices after the split."""
        middle = 0.5 * (self.u[failed] + self.u[failed + 1])
        radii = branch.radii(self.fold + middle * middle)
        depths, slopes = branch._arrays(radii)
        u = np.sqrt(np.maximum(depths - self.fold, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            rates = 2.0 * u / slopes
        self.u, self.a = np.insert(self.u, failed + 1, u), np.insert(self.a, failed + 1, radii)
        self.rates, self._slopes = np.insert(self.rates, failed + 1, rates), np.insert(self._slopes, failed + 1, slopes)
        return failed + np.arange(failed.size)

    def _interpolate(self, u: np.ndarray, index: np.ndarray) -> np.ndarray:
        """The cubic Hermite interpolant on the intervals ``index`` at ``u`` (within them)."""
        u0, u1 = self.u[index], self.u[index + 1]
        a0, a1 = self.a[index], self.a[index + 1]
        width = u1 - u0
        t = (u - u0) / width
        m0, m1, rise = self.rates[index] * width, self.rates[index + 1] * width, a1 - a0
        return a0 + t * (m0 + t * (3.0 * rise - 2.0 * m0 - m1 + t * (m0 + m1 - 2.0 * rise)))

    def radii(self, depth: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The radii at ``depth`` where the table covers them, and where it does.

        Parameters
        ----------
        depth : numpy.ndarray
            The depths (m), one-dimensional.

        Returns
        -------
        tuple of numpy.ndarray
            The radii (m; ``nan`` where not covered) and the mask of the depths covered.
        """
        depth = np.asarray(depth, dtype=float)
        u = np.sqrt(np.maximum(depth - self.fold, 0.0))
        index = piece_index(self.u, u, self.u.size - 2)
        covered = (depth >= self.low) & (depth <= self.high) & self.kept[index]
        return np.where(covered, self._interpolate(u, index), np.nan), covered


def accuracy(radius: np.ndarray, depth: np.ndarray, slope: np.ndarray) -> np.ndarray:
    """What :meth:`~.layer_branch.LayerBranch.radii`' roots hold to at ``radius`` (m), of ``depth`` and ``∂d/∂a``
    ``slope`` there: its stopping tolerance ``RADII_RTOL · a`` plus the depth's rounding carried through the slope,
    :data:`DEPTH_ULPS` ulps of ``|d|`` over ``∂d/∂a`` (unbounded at the fold, where ``∂d/∂a → 0``).

    Parameters
    ----------
    radius, depth, slope : numpy.ndarray
        The radii (m), their depths (m) and the branch's slopes there (1).

    Returns
    -------
    numpy.ndarray
        The accuracy (m).
    """
    return RADII_RTOL * radius + DEPTH_ULPS * np.finfo(float).eps * np.abs(depth) / slope


def recession_inverse(branch) -> RecessionInverse:
    """The :class:`RecessionInverse` of ``branch``, made once per branch's values (and kept)."""
    key = (*branch._key(), branch.jump_off_radius)
    found = _TABLES.get(key)
    if found is None:
        if len(_TABLES) >= _KEPT:
            _TABLES.clear()
        found = _TABLES[key] = RecessionInverse(branch)
    return found


#: The tables made, by the branch's values and its jump-off radius (at most :data:`_KEPT`).
_TABLES: dict[tuple, RecessionInverse] = {}
