"""The springs' edge under a rate-dependent adhesion law: how many springs are in contact at each sample.

Under :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` the edge moves at the speed its energy release rate
gives it (:mod:`mdr_events.theory.rate_adhesion`). On the springs of width ``Δx`` the next spring out (at ``x_m``)
attaches once the edge has advanced ``Δx`` at the speed of ``Γ_m = E* (g(x_m) − d)² / (2π x_m)`` (below ``Δγ0``;
unbounded where that spring is already compressed), and the boundary spring (``x_{m−1}``) lets go once the edge has
receded ``Δx`` at the speed of ``Γ_{m−1}`` (above ``Δγ1``); in between it rests. Within a time step the depth is the
step's end (the rule of the rate-independent springs), the edge moves spring by spring for the time the step has, and
the part of a spring it has crossed carries over to the next step. As ``v_ref → ∞`` every crossing takes no time and
this is the paper's rule: a spring attaches where ``Γ_m <= Δγ0``, i.e. ``d >= g − Δl(Δγ0)`` (8), and lets go where
``Γ_{m−1} > Δγ1``.

The edge does not depend on the springs' shifts, so the counts are computed before the tangential stepping
(:func:`~mdr_events.models.discrete.run_discrete` passes them to its loop).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.theory.rate_adhesion import edge_speed_scalar

__all__ = ["rate_edge_counts"]


def rate_edge_counts(law: RateDependentAdhesion, positions: np.ndarray, g: np.ndarray, E_star: float, depth: np.ndarray,
                     time: np.ndarray, last: int, first_touch: float) -> np.ndarray:
    """The springs in contact per side at each sample ``0 … last`` of one case (module docstring).

    Parameters
    ----------
    law : RateDependentAdhesion
        The adhesion law.
    positions : numpy.ndarray
        The springs' centres ``x_j`` (m), from the centre out.
    g : numpy.ndarray
        The profile at them, ``g(x_j)`` (m).
    E_star : float
        The effective modulus ``E*`` (Pa).
    depth : numpy.ndarray
        The case's depth at each sample (m).
    time : numpy.ndarray
        The samples' times (s).
    last : int
        The case's last sample.
    first_touch : float
        The depth at which the first spring touches, ``g(x_0)``.

    Returns
    -------
    numpy.ndarray of int
        The springs in contact per side, ``last + 1`` samples.
    """
    xs, gs, ds, ts = positions.tolist(), g.tolist(), depth.tolist(), time.tolist()
    n, dx = len(xs), float(positions[1] - positions[0]) if len(xs) > 1 else float(2 * positions[0])
    counts = np.zeros(last + 1, dtype=np.int64)
    m = 0
    crossed, heading = 0.0, 0  # the share of a spring the edge has crossed, and which way (+1 out, −1 in)

    def release(j: int, d: float) -> float:
        stretch = gs[j] - d
        return E_star * stretch * stretch / (2.0 * math.pi * xs[j]) if stretch > 0.0 else 0.0

    for k in range(1, last + 1):
        d, remaining = ds[k], ts[k] - ts[k - 1]
        if m == 0 and d < first_touch:
            crossed, heading = 0.0, 0
            continue
        while True:
            speed = 0.0
            if m < n and release(m, d) < law.dgamma0:
                speed = edge_speed_scalar(law, release(m, d))
            elif m > 0:
                speed = min(edge_speed_scalar(law, release(m - 1, d)), 0.0)
            if speed == 0.0:
                crossed, heading = 0.0, 0
                break
            way = 1 if speed > 0.0 else -1
            if way != heading:
                crossed, heading = 0.0, way
            needed = (1.0 - crossed) * dx / abs(speed)
            if needed <= remaining:
                remaining -= needed
                m += way
                crossed = 0.0
                if m == 0:
                    heading = 0
                    break
                continue
            crossed += remaining * abs(speed) / dx
            break
        counts[k] = m
    return counts
