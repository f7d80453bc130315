r"""Where no probe can be at a cap before the slip onset, bounded in closed form: the probes need not be read there.

The per-spring route (:mod:`.play_run`) reads, at every time where no node of the quadrature is at a cap,
:data:`~.play_samples.PROBE_POINTS` probes to find a zone opening between the nodes. Under ``τ0``'s part that is every
output time before the slip onset (along scenario A at 20° on the paper's layer some 170 times of 1025 probes: half of
the run). This module proves, where it can, that none of those probes is at a cap, so that they need not be read.

Along the path's first segment in contact ``x`` and ``d`` are linear in time from the first contact ``t_c`` and every
spring in contact at ``t`` attached at some ``τ`` in ``[t_c, t]`` with its anchor at ``x(τ)``. Along a monotone ``x`` a
play operator's anchor only follows ``x``: each clamp raises it to ``x − c ≤ x`` (or lowers it to ``x + c``), so it
stays between ``x(τ)`` and ``x(t)`` whether the spring slid before or not, and its distance outside its window at
``t`` is at most ``|x(t) − x(τ)| − c(t)``. Without adhesion (:class:`~.play_history.DepthHistory`) the spring attached
where ``d`` rose through ``g(ξ)``, so its compression is ``d(t) − g(ξ) = ḋ (t − τ)`` and its cap
``c = ū(a) + μρ(ξ)(d − g)``:

``|ẋ|(t − τ) − μρ(ξ) ḋ (t − τ) − ū(a(t)) ≤ β (t − t_c) − ū(a(t))``, ``β = max(|ẋ| − r ḋ, 0)``,

``r`` at most ``μρ`` at every probe (``a(t)`` times the route's shares, the same products the route reads, and,
at or below them, the springs' ratios on a grid of :data:`BOUND_GRID` radii, their running minimum, and at ``a(t)``
itself; less :data:`BOUND_MARGIN`), so the inequality holds for each probe exactly; ``μρ ≥ 0`` (``μ ≥ 0``), so where
``|ẋ| (t − t_c)`` alone passes ``μρ`` is not read. Between the probes the grid is an estimate, not a bound: a dip of
``μρ`` narrower than its spacing may let a spring there slide unseen, as the probes themselves would miss it; the
skip is the probes' route, not more. On a layer ``μρ`` at the probes is first bounded from below without reading
them (:data:`RATIO_FLOOR`: the floor of :class:`~.play_line.FlooredRatio` over ``[0, a(t)]``, from the tables'
B-spline coefficients, a bound at or below every probe's value, ``0`` where ``a(t)`` lies beyond the tables): a time
that passes with it passes with the probes' own least value too (and with the grid's, below), so the grid and the
probes' ``μρ`` are read only where it does not (along scenario A at 20° on the paper's layer, nowhere). With
adhesion (:class:`~.play_history.SpanHistory`: springs jump in, some in tension, Coulomb's part off) ``c ≥ ū(a)``
alone and ``β = |ẋ|``. A time passes where
``β (t − t_c)`` plus the anchors' round-off (:data:`BOUND_ROUND_OFF` of the path's largest ``|x|`` and ``d``) lies
below ``ū(a(t))`` less :data:`BOUND_MARGIN`: then no probe is at a cap, and reading them would find none. Under
Coulomb's law alone (``ū = 0``), after the first segment, or where the path starts in contact no time passes: the
probes are read as before. Along scenario A at 20° on the paper's layer ``μρ`` is least at the centre, the first
spring to slide, so the bound passes up to the output time before the slip onset.

The bound decides only whether the probes are read: where it passes, they would have found no spring at a cap
(``tests/models/test_play_bound.py``: the probes at every time it passes, on the layer and on springs built to
defeat it, among them a dip of ``μρ`` narrower than the grid's spacing centred on a probe; the runs with and without
it the same at every output).
"""

from __future__ import annotations

import numpy as np

from mdr_events.theory.layer.spring_factors import RATIO_FLOOR_ROUNDING

from .play_history import DepthHistory, SpanHistory
from .play_line import FlooredRatio

__all__ = ["sticking", "BOUND_MARGIN", "BOUND_ROUND_OFF", "BOUND_GRID", "RATIO_FLOOR"]

#: The share by which the bound's lower bounds (``ū`` and ``μρ``) are lowered: a probe within this share of its cap
#: is read as before (the anchors' and the cap's table's round-off, some ulps, far below it).
BOUND_MARGIN = 1e-6
#: The anchors' round-off the bound leaves room for, as a share of the path's largest ``|x|`` and ``d``: the route
#: reads ``x(t) − x(τ)`` and ``d − g`` from interpolated times, some ulps of those scales (1e-16), this far above them.
BOUND_ROUND_OFF = 1e-9
#: Points of the grid of radii on which ``μρ``'s least value is estimated first (the probes are read where it passes).
BOUND_GRID = 1025
#: Whether a layer's floor of ``μρ`` over ``[0, a]`` from its tables' B-spline coefficients
#: (:class:`~.play_line.FlooredRatio`, a bound, not an estimate: at or below ``μρ`` at every probe and at every point
#: of the grid up to ``a``) is tried before the grid and the probes are read (``False``: the grid's estimate, then
#: ``μρ`` at the probes where it passes, the route of before; a time the floor passes passes with the grid's and the
#: probes' own least value too, so the decisions are the same; the grid spans the same radii either way).
RATIO_FLOOR = True


def sticking(play, times: np.ndarray, shares: np.ndarray) -> np.ndarray:
    """Whether, at each of ``times``, none of the probes (``shares`` of the radius) can be at a cap (module
    docstring).

    Parameters
    ----------
    play : PlaySprings
        The springs.
    times : numpy.ndarray
        The times (s, path clock), each in contact.
    shares : numpy.ndarray
        The probes as shares of the radius, as the route reads them (:func:`~.play_samples._probed_all`).

    Returns
    -------
    numpy.ndarray
        ``True`` where the bound proves every probe sticks (they need not be read), else ``False``.
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
    _, corner_x, corner_d = play.path_corners()
    round_off = BOUND_ROUND_OFF * (float(np.max(np.abs(corner_x))) + float(np.max(np.abs(corner_d))))

    def passes(beta: np.ndarray, rows: np.ndarray) -> np.ndarray:
        return beta * (t[rows] - t_c) + round_off < (1.0 - BOUND_MARGIN) * shifts[rows]

    passed = passes(np.full(t.shape, abs(x_speed)), np.arange(t.size))  # (μρ ≥ 0: Coulomb's part only helps)
    rows = np.flatnonzero(~passed)
    if not play.history.adhesive and rows.size:  # (every spring compressed by ḋ (t − τ): μρ read where needed)
        radii = np.array([play.radius(float(time)) for time in t[rows]])
        top = float(np.max(radii))  # (the grid's extent: every such row's, whichever the floor settles)
        if RATIO_FLOOR and isinstance(play.line.ratio, FlooredRatio):
            rows, radii = _floored(play, passes, rows, radii, passed, (abs(x_speed), d_speed))
        if rows.size:
            floor = _ratio_floor(play, radii, top)
            kept = passes(np.maximum(abs(x_speed) - floor * d_speed, 0.0), rows)  # (the probes read where it passes)
            rows, radii, floor = rows[kept], radii[kept], floor[kept]
            floor = np.minimum(floor, (1.0 - BOUND_MARGIN) * _probes_least(play, radii, shares))
            passed[rows] = passes(np.maximum(abs(x_speed) - floor * d_speed, 0.0), rows)
    out[inside] = passed
    return out


def _floored(play, passes, rows: np.ndarray, radii: np.ndarray, passed: np.ndarray,
             speeds: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """:data:`RATIO_FLOOR`: the rows ``passes`` with ``μρ``'s floor over ``[0, a]`` (at or below the grid's estimate
    and every probe's ``μρ``) set in ``passed``; those it fails with the centre's ``μρ`` (at or above the grid's
    estimate, whose running minimum starts there) dropped, as the grid would drop them; the rest, and their radii,
    returned for the grid and the probes."""
    x_speed, d_speed = speeds
    floor = (1.0 - BOUND_MARGIN) * play.line.ratio.floor(radii)
    settled = passes(np.maximum(x_speed - floor * d_speed, 0.0), rows)
    passed[rows[settled]] = True
    ceiling = (1.0 - BOUND_MARGIN) * (1.0 + RATIO_FLOOR_ROUNDING) * play.line.ratio.centre()
    open_ = ~settled & passes(np.full(rows.shape, max(x_speed - ceiling * d_speed, 0.0)), rows)
    return rows[open_], radii[open_]


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


def _ratio_floor(play, radii: np.ndarray, top: float) -> np.ndarray:
    """An estimate of ``μρ(ξ)``'s least value on ``[0, a]`` at each of ``radii``: the running minimum of the springs'
    ratios on a grid up to ``top`` (the largest radius of the times asked), read at the last grid point not beyond
    each radius and at the radius itself, less :data:`BOUND_MARGIN` (a dip between two grid points is missed:
    :func:`_probes_least` reads the probes themselves)."""
    grid = np.linspace(0.0, top, BOUND_GRID)
    floor = np.minimum.accumulate(play.line.ratio(grid))
    below = floor[np.searchsorted(grid, radii, side="right") - 1]
    return (1.0 - BOUND_MARGIN) * np.minimum(below, play.line.ratio(radii))


def _probes_least(play, radii: np.ndarray, shares: np.ndarray) -> np.ndarray:
    """``μρ``'s least value on the probes at each of ``radii``: the springs ``radius · shares``, the same products the
    route reads (:func:`~.play_probes.probes_at_cap`), so the bound holds for each probe exactly."""
    return np.array([np.min(play.line.ratio(radius * shares)) for radius in radii])
