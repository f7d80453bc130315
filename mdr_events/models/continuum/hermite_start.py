"""The start of Newton's iteration for a layer branch's radius (:class:`~.layer_branch.LayerBranch`): the inverse
``a(d)`` between two points of the branch's scan as a cubic Hermite interpolant, for one depth or an array of them.
"""

from __future__ import annotations

import numpy as np

__all__ = ["hermite_start"]


def hermite_start(depth, radii: np.ndarray, depths: np.ndarray, slopes: np.ndarray):
    """The radius of ``depth`` on the cubic Hermite interpolant of the inverse ``a(d)`` between two scanned points,
    within about 1e-9 of the root at :data:`~.layer_branch.START_SCAN_PER_DECADE`: one of Newton's steps from
    :data:`~.layer_branch.RADII_RTOL`. Where a slope is not positive (the jump-off's, where the inverse has a square
    root) or the cubic leaves the interval, the chord.

    Parameters
    ----------
    depth : float or numpy.ndarray
        The depth (m), one float (the scalar start's, in floats) or an array.
    radii, depths, slopes : sequence of numpy.ndarray
        The two scanned points' radii (m), depths (m) and slopes ``∂d/∂a``: each of two rows, the lower point first.

    Returns
    -------
    float or numpy.ndarray
        The start's radius (m), as ``depth``.
    """
    (r0, r1), (d0, d1), (s0, s1) = radii, depths, slopes
    width, rise = d1 - d0, r1 - r0
    t = (depth - d0) / width
    chord = r0 + t * rise
    if type(depth) is float:  # (one depth, in floats: the scalar start's)
        if not (s0 > 0.0 and s1 > 0.0):
            return chord
        m0, m1 = width / s0, width / s1
        cubic = r0 + t * (m0 + t * (3.0 * rise - 2.0 * m0 - m1 + t * (m0 + m1 - 2.0 * rise)))
        return cubic if r0 <= cubic <= r1 else chord
    with np.errstate(divide="ignore", invalid="ignore"):
        m0, m1 = width / s0, width / s1
        cubic = r0 + t * (m0 + t * (3.0 * rise - 2.0 * m0 - m1 + t * (m0 + m1 - 2.0 * rise)))
    good = (s0 > 0.0) & (s1 > 0.0) & (cubic >= r0) & (cubic <= r1)
    return np.where(good, cubic, chord)
