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
``Δu`` is ``a''''(ξ) (u − u_i)²(u − u_{i+1})²/24``, at most ``Δu⁴ max|a''''|/384``, largest in the middle where
``a''''`` is about constant across the interval (``a''''`` varies on the scale of ``a``, an interval is ``10^(1/N)``
of it). So the table checks each interval at its middle against :meth:`~.layer_branch.LayerBranch.radii`' root there
(Newton's, stopped where its step's own bound is ``1e-2 RADII_RTOL``) and keeps the intervals where the interpolant
lies within what that root itself holds to (:func:`accuracy`: ``RADII_RTOL · a`` plus the depth's rounding through
``∂d/∂a``, which near the fold exceeds ``RADII_RTOL`` for the iteration's roots alike). A depth in an interval that
fails, or beyond the nodes (between the fold and the first node), takes :meth:`~.layer_branch.LayerBranch.radii`.
"""

from __future__ import annotations

import math

import numpy as np

from .layer_branch import RADII_RTOL

__all__ = ["RecessionInverse", "recession_inverse", "accuracy", "NODES_PER_DECADE", "DEPTH_ULPS"]

#: Nodes a decade of radius: the interpolant's truncation error falls as ``Δu⁴``. Measured at ``h/a₀ = 0.1``, 0.075
#: and 0.02 (ν = 0.5, the paper's works): at 2048 a decade the intervals away from the fold fail the check (their
#: truncation above ``RADII_RTOL``), at 4096 every interval passes (truncation 16 times lower, ``<~ 1e-15``); 6144 puts
#: it another ``1.5⁴ = 5`` times below that, ``<~ 3e-16`` of the radius, under the roots' rounding. A table of ~8000
#: nodes costs ~3 ms once per branch (one reading of the tables and one iteration at the middles).
NODES_PER_DECADE = 6144
#: The rounding of a depth as the branch computes it, in ulps of ``|d|`` (Heß's limit over ``Θ`` of the tables: a
#: few operations of an ulp each), with a margin: the roots' error through ``∂d/∂a`` (:func:`accuracy`).
DEPTH_ULPS = 8.0
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
        # (the intervals' middles in u, against Newton's roots there)
        middle = 0.5 * (u[:-1] + u[1:])
        found = branch.radii(self.fold + middle * middle)
        valid = (slopes[:-1] > 0.0) & (slopes[1:] > 0.0) & (np.diff(u) > 0.0)
        with np.errstate(invalid="ignore", divide="ignore"):
            error = np.abs(self._interpolate(middle, np.arange(middle.size)) - found)
            #: whether each interval's interpolant is kept: within the roots' own accuracy (:func:`accuracy`)
            self.kept = valid & (error <= accuracy(found, self.fold + middle * middle,
                                                   np.minimum(slopes[:-1], slopes[1:])))
        #: the largest error at an interval's middle kept, relative to its radius (what the table's check saw)
        self.largest_error = float(np.max(error[self.kept] / found[self.kept])) if self.kept.any() else math.nan

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
        index = np.clip(np.searchsorted(self.u, u, side="right") - 1, 0, self.u.size - 2)
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
