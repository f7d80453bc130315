r"""Where no spring can be at a cap before the slip onset, bounded in closed form: the probes need not be read there.

The per-spring route (:mod:`.play_run`) reads, at every time where no node of the quadrature is at a cap,
:data:`~.play_run.PROBE_POINTS` probes to find a zone opening between the nodes. Under ``τ0``'s part that is every
output time before the slip onset (along scenario A at 20° on the paper's layer some 170 times of 1025 probes: half of
the run). This module proves, where it can, that no spring is at a cap, so that those probes read nothing.

Along the path's first segment in contact ``x`` and ``d`` are linear in time from the first contact ``t_c`` and every
spring in contact at ``t`` attached at some ``τ`` in ``[t_c, t]`` with its anchor at ``x(τ)``. Along a monotone ``x`` a
play operator's anchor only follows ``x``: each clamp raises it to ``x − c ≤ x`` (or lowers it to ``x + c``), so it
stays between ``x(τ)`` and ``x(t)`` whether the spring slid before or not, and its distance outside its window at
``t`` is at most ``|x(t) − x(τ)| − c(t)``. Without adhesion (:class:`~.play_history.DepthHistory`) the spring attached
where ``d`` rose through ``g(ξ)``, so its compression is ``d(t) − g(ξ) = ḋ (t − τ)`` and its cap
``c = ū(a) + μρ(ξ)(d − g)``:

``|ẋ|(t − τ) − μρ(ξ) ḋ (t − τ) − ū(a(t)) ≤ β (t − t_c) − ū(a(t))``, ``β = max(|ẋ| − r ḋ, 0)``,

``r`` a lower bound of ``μρ`` on ``[0, a(t)]`` (the springs' ratios on a grid of :data:`BOUND_GRID` radii, their
running minimum, and at ``a(t)`` itself, less :data:`BOUND_MARGIN`). With adhesion (:class:`~.play_history.SpanHistory`:
springs jump in, some in tension, Coulomb's part off) ``c ≥ ū(a)`` alone and ``β = |ẋ|``. A time passes where
``β (t − t_c)`` plus the anchors' round-off (:data:`BOUND_ROUND_OFF` of the path's largest ``|x|`` and ``d``) lies
below ``ū(a(t))`` less :data:`BOUND_MARGIN`: then no spring is at a cap, and the probes would find none. Under
Coulomb's law alone (``ū = 0``), after the first segment, or where the path starts in contact no time passes: the
probes are read as before. Along scenario A at 20° on the paper's layer ``μρ`` is least at the centre, the first
spring to slide, so the bound passes up to the output time before the slip onset.

The bound decides only whether the probes are read: where it passes, they would have found no spring at a cap
(``tests/models/test_play_bound.py``: the probes at every time it passes, on the layer and on springs built to
defeat it; the runs with and without it the same at every output).
"""

from __future__ import annotations

import numpy as np

from .play_history import DepthHistory, SpanHistory

__all__ = ["sticking", "BOUND_MARGIN", "BOUND_ROUND_OFF", "BOUND_GRID"]

#: The share by which the bound's lower bounds (``ū`` and ``μρ``) are lowered: ``μρ`` is read on a grid of a smooth
#: function (a dip between two of :data:`BOUND_GRID` points is some ``(1/1024)²/8`` of its relative curvature, below
#: 1e-8 on a layer's tables), and a spring within this share of its cap is probed as before.
BOUND_MARGIN = 1e-6
#: The anchors' round-off the bound leaves room for, as a share of the path's largest ``|x|`` and ``d``: the route
#: reads ``x(t) − x(τ)`` and ``d − g`` from interpolated times, some ulps of those scales (1e-16), this far above them.
BOUND_ROUND_OFF = 1e-9
#: Points of the grid of radii on which ``μρ``'s least value is read.
BOUND_GRID = 1025


def sticking(play, times: np.ndarray) -> np.ndarray:
    """Whether, at each of ``times``, no spring in contact can be at a cap (module docstring).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    times : numpy.ndarray
        The times (s, path clock), each in contact.

    Returns
    -------
    numpy.ndarray
        ``True`` where the bound proves every spring sticks (its probes need not be read), else ``False``.
    """
    times = np.asarray(times, dtype=float)
    out = np.zeros(times.shape, bool)
    known = isinstance(play.history, (DepthHistory, SpanHistory))
    segment = _first_segment(play) if known and play.line.shifts else None
    if segment is None:
        return out
    t_c, t_end, x_speed, d_speed = segment
    inside = np.flatnonzero((times > t_c) & (times <= t_end))
    if not inside.size:
        return out
    t = times[inside]
    shifts = np.array([play.shift(float(time)) for time in t])
    beta = np.full(t.shape, abs(x_speed))
    if not play.history.adhesive:  # (every spring compressed by ḋ (t − τ): Coulomb's part helps)
        radii = np.array([play.radius(float(time)) for time in t])
        beta = np.maximum(beta - _ratio_floor(play, radii) * d_speed, 0.0)
    _, corner_x, corner_d = play.path_corners()
    round_off = BOUND_ROUND_OFF * (float(np.max(np.abs(corner_x))) + float(np.max(np.abs(corner_d))))
    out[inside] = beta * (t - t_c) + round_off < (1.0 - BOUND_MARGIN) * shifts
    return out


def _first_segment(play) -> tuple[float, float, float, float] | None:
    """The first contact ``t_c`` (where ``d`` first rises through 0), the end of its segment and the segment's ``ẋ``
    and ``ḋ``; ``None`` where the path starts in contact."""
    corner_t, corner_x, corner_d = play.path_corners()
    if corner_d[0] > 0.0 or not np.any(corner_d > 0.0):
        return None
    k = int(np.argmax(corner_d > 0.0))
    (t0, t1), (x0, x1), (d0, d1) = corner_t[k - 1:k + 1], corner_x[k - 1:k + 1], corner_d[k - 1:k + 1]
    t_c = t0 + (t1 - t0) * (0.0 - d0) / (d1 - d0)  # (the first contact, as DepthHistory.pieces reads it)
    return float(t_c), float(t1), float((x1 - x0) / (t1 - t0)), float((d1 - d0) / (t1 - t0))


def _ratio_floor(play, radii: np.ndarray) -> np.ndarray:
    """A lower bound of ``μρ(ξ)`` on ``[0, a]`` at each of ``radii``: the running minimum of the springs' ratios on a
    grid up to the largest radius, read at the last grid point not beyond each radius and at the radius itself, less
    :data:`BOUND_MARGIN`."""
    grid = np.linspace(0.0, float(np.max(radii)), BOUND_GRID)
    floor = np.minimum.accumulate(play.line.ratio(grid))
    below = floor[np.searchsorted(grid, radii, side="right") - 1]
    return (1.0 - BOUND_MARGIN) * np.minimum(below, play.line.ratio(radii))
