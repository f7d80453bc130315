"""The paper's own numerical model: a row of independent springs (Fig. 7b).

Springs sit at ``x_j = ±(j + 1/2) Δx`` over the MDR profile ``g(x)``, with
normal stiffness ``E* Δx`` (5) and tangential stiffness ``G* Δx`` (6). The
contact is symmetric, so one half (``x > 0``) is simulated and the sums (15)
are doubled.

Rules, applied at every time step (all vectorised over springs and cases):

- **Heß's rule (8) with hysteresis.** The contact is ``m`` springs per side,
  contiguous from the centre, radius ``a = m Δx`` (``a = (n/2) Δx``).
  While the indenter goes in, the first spring attaches when touched
  (``d >= g(x_0)``) and then every spring with
  ``d >= g(x_j) − Δl_max(x_j; Δγ0)``; while it comes out, boundary springs
  detach, from the edge inwards, while ``d < g(x_j) − Δl_max(x_j; Δγ1)``.
  The threshold ``g − Δl_max`` falls to a minimum and then rises, so the
  contact stays contiguous: growth beyond the minimum and detachment from it
  are a ``searchsorted`` on the rising part; a boundary spring inside the
  minimum takes every spring up to it along (jump-in) or, detaching, the
  whole contact off (jump-off).
- **Tangential springs.** A spring's shift is 0 when it attaches and then
  follows the indenter's tangential motion; where ``|u| > ū(a)`` (13) it is
  set to ``±ū(a)``; a detached spring forgets its shift.
- **Forces (15).** ``F_N = 2 Σ E* Δx (d − g(x_j))`` (from prefix sums of
  ``g``) and ``F_x = 2 Σ G* Δx u_j`` over the springs in contact.

A run starts at the path's first entry into the elastomer
(:meth:`~mdr_events.models.paths.Path.entry_times`) and may go through any
number of contact cycles. When a contact comes apart (the pull-off jump), the
run goes on if the path enters the elastomer again later than the last sample
in contact: out of contact ``F_N = F_x = a = 0`` (sliding fraction ``nan``),
and the next contact starts afresh (springs attach with zero shift). If the
path never enters again, the run ends at that first sample without contact
(kept; ``nan`` after it). In any case a run ends when its path ends.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

from mdr_events.theory import analytic

from mdr_events.theory import symbolic
from mdr_events.parameters import Parameters
from mdr_events.models.paths import Path

__all__ = ["run_discrete", "paraboloid_profile", "MIN_SPRINGS_IN_CONTACT"]

#: Fewer springs than this per side at ``d_max`` is too coarse (an error).
MIN_SPRINGS_IN_CONTACT = 10


def paraboloid_profile(params: Parameters) -> Callable[[np.ndarray], np.ndarray]:
    """``g(x) = x²/R``, eq. (4), as derived by :mod:`mdr_events.theory.symbolic`."""
    relation = symbolic.relation("profile_paraboloid")
    return lambda x: relation.numeric(x, params.R)


class _Threshold:
    """Depths at which each spring can be in contact: ``g(x_j) − Δl_max(x_j; Δγ)``.

    ``count(d)`` is the number of springs (from the centre) that satisfy
    ``depth >= threshold``; the set is contiguous because the threshold
    falls to its minimum and then rises.
    """

    def __init__(self, g: np.ndarray, positions: np.ndarray, params: Parameters, work_of_adhesion: float):
        elongation = symbolic.relation("hess_max_elongation").numeric(positions, work_of_adhesion, params.E_star)
        threshold = g - elongation
        self.threshold = np.append(threshold, np.inf)  # a spring beyond the array never qualifies
        self.lowest = int(np.argmin(threshold))
        self.minimum = float(threshold[self.lowest])
        self.rising = threshold[self.lowest + 1:]

    def count(self, depth: np.ndarray) -> np.ndarray:
        above = self.lowest + 1 + np.searchsorted(self.rising, depth, side="right")
        return np.where(depth >= self.minimum, above, 0)

    def grow(self, m: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Going in: the next spring attaches if ``depth`` reaches its threshold, then all that follow.

        If the next spring is inside the minimum of the threshold, every spring up to
        the minimum has a lower threshold and attaches with it (a jump-in).
        """
        return np.where(depth >= self.threshold[m], np.maximum(m, self.count(depth)), m)

    def shrink(self, m: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Going out: the boundary spring detaches if ``depth`` falls below its threshold, then
        the next inner one, and so on. On the falling side of the threshold every inner spring
        has a higher threshold, so the whole contact comes off (a jump-off)."""
        boundary = np.maximum(m - 1, 0)
        holds = (m == 0) | (depth >= self.threshold[boundary])
        inner = np.where(boundary > self.lowest, np.minimum(m, self.count(depth)), 0)
        return np.where(holds, m, inner)


def _spring_count(params: Parameters, dx: float, max_depth: float, profile) -> int:
    """Springs per side needed to hold the largest contact of the path, with margin."""
    count = 64
    while True:
        positions = (np.arange(count) + 0.5) * dx
        attach = _Threshold(profile(positions), positions, params, params.dgamma0)
        needed = int(attach.count(np.array([max_depth]))[0])
        if needed < count - 1:
            return needed + 2
        count *= 2


def check_spacing(params: Parameters, dx: float, depth: float | None = None) -> None:
    """Reject a spring spacing that puts fewer than 10 springs per side in contact at the
    deepest point (``d_max``, or the given ``depth`` of a custom path)."""
    if not (isinstance(dx, (int, float)) and math.isfinite(dx) and dx > 0):
        raise ValueError(f"dx={dx!r} is not allowed; allowed: a finite spring spacing > 0 (m)")
    depth = params.d_max if depth is None else depth
    radius = float(analytic.jkr_contact_radius(depth, params, params.dgamma0))
    if not radius / dx >= MIN_SPRINGS_IN_CONTACT:
        raise ValueError(
            f"dx={dx!r} m puts {int(radius // dx) if radius == radius else 0} springs per side in contact "
            f"at the deepest point d = {depth!r} m; "
            f"allowed: at least {MIN_SPRINGS_IN_CONTACT}, i.e. dx <= {radius / MIN_SPRINGS_IN_CONTACT:.6g} m"
        )


def run_discrete(
    params: Parameters,
    paths: list[Path],
    dx: float,
    dt: float,
    profile: Callable[[np.ndarray], np.ndarray] | None = None,
) -> dict[str, np.ndarray]:
    """Run the spring model for several paths at once on a common time grid.

    Parameters
    ----------
    params : Parameters
    paths : list of Path
        One case per path; time runs from each path's first contact. A path
        may enter the elastomer several times (see the module docstring).
    dx : float
        Spring spacing Δx in m.
    dt : float
        Time step in s (the grid is ``k dt``, shared by all cases).
    profile : callable, optional
        ``g(x)`` (vectorised); default the paraboloid (4).

    Returns
    -------
    dict
        ``time`` (n_time,) and, each of shape (n_cases, n_time) with ``nan``
        after a case has ended (pull-off with no later entry, or the end of
        its path): ``indentation_depth``,
        ``tangential_displacement``, ``normal_force``, ``tangential_force``,
        ``contact_radius``, ``sliding_fraction``, ``springs_in_contact``.
    """
    profile = paraboloid_profile(params) if profile is None else profile
    # cases run longest first, so that the cases still running are always a leading block of rows
    order = np.argsort([-(path.duration - path.first_contact_time()) for path in paths], kind="stable")
    paths = [paths[i] for i in order]
    starts = np.array([path.first_contact_time() for path in paths])
    # the last entry into the elastomer, in time from first contact (0 for a path with one entry)
    last_entries = np.array([path.entry_times()[-1] for path in paths]) - starts
    durations = np.array([path.duration for path in paths]) - starts
    n_time = int(math.ceil(durations.max() / dt)) + 1
    time = np.arange(n_time) * dt
    positions = np.empty((2, n_time, len(paths)))
    for case, path in enumerate(paths):
        positions[0, :, case], positions[1, :, case] = path.position(starts[case] + time)
    x_path, d_path = positions
    last_sample = np.minimum(np.floor(durations / dt + 0.5).astype(np.int64), n_time - 1)

    n_springs = _spring_count(params, dx, max(path.max_depth for path in paths), profile)
    xi = (np.arange(n_springs) + 0.5) * dx
    g = profile(xi)
    g_prefix = np.concatenate([[0.0], np.cumsum(g)])
    attach = _Threshold(g, xi, params, params.dgamma0)
    detach = _Threshold(g, xi, params, params.dgamma1)
    first_touch = g[0]
    shift_per_radius = float(analytic.critical_shift(1.0, params))  # ū is linear in a
    spring_index = np.arange(n_springs)

    n_cases = len(paths)
    shift = np.zeros((n_cases, n_springs))
    out_m = np.zeros((n_cases, n_time), dtype=np.int64)
    out_sum = np.zeros((n_cases, n_time))
    out_sliding = np.zeros((n_cases, n_time), dtype=np.int64)

    m = np.where(d_path[0] >= first_touch, attach.count(d_path[0]), 0)
    out_m[:, 0] = m
    running = n_cases
    for k in range(1, n_time):
        while running and last_sample[running - 1] < k:
            running -= 1
        if not running:
            break
        rows = slice(0, running)
        m = m[rows]
        d_new = d_path[k, rows]
        step_x = x_path[k, rows] - x_path[k - 1, rows]
        step_depth = d_new - d_path[k - 1, rows]
        grow = np.where(m > 0, attach.grow(m, d_new),
                        np.where(d_new >= first_touch, attach.count(d_new), 0))
        shrink = detach.shrink(m, d_new)
        m_new = np.where(step_depth > 0, grow, np.where(step_depth < 0, shrink, m))
        width = int(max(m.max(), m_new.max()))
        if width:
            u = shift[rows, :width]
            kept = np.minimum(m, m_new)
            if np.any(step_x != 0.0):
                u += step_x[:, None]
                u *= spring_index[:width] < kept[:, None]  # only springs in contact move ...
            elif np.any(kept < m):
                u *= spring_index[:width] < kept[:, None]  # ... and detached ones forget
            cap = ((shift_per_radius * dx) * m_new)[:, None]
            np.minimum(u, cap, out=u)
            np.maximum(u, -cap, out=u)
            out_sum[rows, k] = u.sum(axis=1)
            at_cap = np.count_nonzero(np.abs(u) >= cap, axis=1)
            out_sliding[rows, k] = np.where(cap[:, 0] > 0.0, at_cap, m_new)  # ū = 0: every spring in contact
        out_m[rows, k] = m_new
        # the pull-off jump ends a case (keeping this first sample without contact) unless its path
        # enters again after the last sample in contact; a case that goes on keeps m = 0 (no springs,
        # zero shifts) until the next contact
        apart = (m > 0) & (m_new == 0) & (last_entries[rows] <= time[k - 1])
        last_sample[rows] = np.where(apart, np.minimum(last_sample[rows], k), last_sample[rows])
        m = m_new

    inverse = np.argsort(order)
    valid = np.arange(n_time)[None, :] <= last_sample[:, None]
    radius = out_m * dx
    with np.errstate(invalid="ignore", divide="ignore"):
        normal = 2.0 * params.E_star * dx * (out_m * d_path.T - g_prefix[out_m])
        tangential = 2.0 * params.G_star * dx * out_sum
        sliding = np.where(out_m > 0, out_sliding / out_m, np.nan)
    result = {
        "time": time,
        "indentation_depth": d_path.T,
        "tangential_displacement": x_path.T,
        "normal_force": normal,
        "tangential_force": tangential,
        "contact_radius": radius.astype(float),
        "sliding_fraction": sliding,
        "springs_in_contact": out_m.astype(float),
    }
    for key, values in result.items():
        if key != "time":
            result[key] = np.where(valid, values, np.nan)[inverse]
    result["spring_count"] = n_springs
    return result
