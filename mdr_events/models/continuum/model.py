"""What the continuum method knows of the model: the two branches, the cap per radius, and the path's
segments as linear motions."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mdr_events.theory import symbolic
from mdr_events.parameters import Parameters
from mdr_events.models.paths import Path
from .branch import Branch
from .state import Regime
from .tolerances import NEGLIGIBLE_SHARE, SEGMENT_RESOLUTION, Tolerances


class ContinuumModel:
    """Parameters, tolerances and the derived pieces every span needs.

    Attributes
    ----------
    grow, shrink : Branch
        The ``Δγ0`` (attach) and ``Δγ1`` (detach) branches of (9).
    K : float
        Critical shift per contact radius, ``ū(a) = K a`` (13).
    """

    def __init__(self, params: Parameters, tolerances: Tolerances):
        self.params = params
        self.tolerances = tolerances
        self.grow = Branch(params, params.dgamma0)
        self.shrink = Branch(params, params.dgamma1)
        self.K = float(symbolic.relation("critical_shift").numeric(1.0, params.tau0, params.G_star))

    def branch(self, regime: Regime) -> Branch:
        """The branch a moving radius follows in ``regime`` (GROWING or SHRINKING)."""
        return self.grow if regime is Regime.GROWING else self.shrink


@dataclass(frozen=True)
class Segment:
    """A straight piece of the path: ``x`` and ``d`` linear in time on ``[t0, t1]``."""

    t0: float
    t1: float
    xs: float
    ds: float
    vx: float
    vd: float

    def x(self, t):
        return self.xs + self.vx * (t - self.t0)

    def d(self, t):
        return self.ds + self.vd * (t - self.t0)

    def time_at_depth(self, depth: float) -> float:
        return self.t0 + (depth - self.ds) / self.vd


def kinematics(path: Path) -> list[Segment]:
    """The path's straight segments, with their velocities (a component below NEGLIGIBLE_SHARE of the
    speed is zero).

    Raises ``ValueError`` naming the waypoints of a segment too short for the solver to separate its
    corners: one lasting less than :data:`SEGMENT_RESOLUTION` of its end time (the event times'
    rounding).
    """
    points = path.waypoints
    times = path.corner_times
    durations = np.diff(times)
    unresolved = np.flatnonzero(durations <= SEGMENT_RESOLUTION * times[1:])
    if unresolved.size:
        i = int(unresolved[0])
        raise ValueError(f"waypoints {i} {tuple(points[i].tolist())} and {i + 1} {tuple(points[i + 1].tolist())} are "
                         f"{durations[i]:.3g} s apart at t = {times[i + 1]:.6g} s; allowed for the continuum method: "
                         f"more than {SEGMENT_RESOLUTION:g} of the time (the solver cannot separate closer corners)")
    segments = []
    for i in range(len(points) - 1):
        dt = times[i + 1] - times[i]
        vx, vd = (points[i + 1, 0] - points[i, 0]) / dt, (points[i + 1, 1] - points[i, 1]) / dt
        vx = 0.0 if abs(vx) < NEGLIGIBLE_SHARE * path.speed else vx
        vd = 0.0 if abs(vd) < NEGLIGIBLE_SHARE * path.speed else vd
        segments.append(Segment(times[i], times[i + 1], points[i, 0], points[i, 1], vx, vd))
    return segments
