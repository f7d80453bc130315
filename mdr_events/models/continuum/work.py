"""The tangential force read off a continuum run's stored anchors (:func:`algebraic_tangential_force`, the check of the
integrated force) and its work along the run (:func:`tangential_work`)."""

from __future__ import annotations

import numpy as np

from mdr_events.validation import check_real, shown
from .graded import natural_variable, span_variable
from .model import ContinuumModel
from .solution import PathSolution, evaluate
from .span_record import Span, Variable
from .state import Regime

__all__ = ["WORK_NODES", "algebraic_tangential_force", "tangential_work"]

def algebraic_tangential_force(solution: PathSolution, times: np.ndarray) -> np.ndarray:
    """``F_x = 2G* ∫_0^a clip(x − Y, −ū, ū) dξ`` from each span's stored anchors, without integration.

    The independent check of :func:`~.solution.evaluate`'s integrated ``F_x`` (same time convention, s from
    first contact; ``nan`` after the end of the run).

    Parameters
    ----------
    solution : PathSolution
        The solution.
    times : array_like
        Times (s from first contact).

    Returns
    -------
    numpy.ndarray
        ``F_x`` (N) at each time.
    """
    model = solution.model
    times = np.asarray(times, dtype=float)
    if solution.compressed is not None:  # the compressed zone's anchors (0 where it has no contact)
        zone = np.nan_to_num(algebraic_tangential_force(solution.compressed, times))
        return np.where(times <= solution.end_time, zone, np.nan)
    filled = evaluate(solution, times)
    owner = solution.span_index(times)
    out = np.full(len(times), np.nan)
    for i, t_rel in enumerate(times):
        if not t_rel <= solution.end_time:
            continue
        span = solution.spans[owner[i]]
        a = filled["contact_radius"][i]
        if span.regime is Regime.NONE or not a > 0:
            out[i] = 0.0
            continue
        x = filled["tangential_displacement"][i]
        out[i] = span.anchors.tangential_force(model.caps, solution.params.G_star, x, a,
                                               filled["indentation_depth"][i])
    return out


#: Gauss–Legendre nodes per step of a span's dense output in :func:`tangential_work`: exact for the
#: polynomial pieces of DOP853's interpolant (degree 7) times a linear ``dx/dt``.
WORK_NODES = 8


def tangential_work(solution: PathSolution, start: float | None = None, end: float | None = None) -> float:
    """The work of the tangential force on the indenter's tangential motion, ``W = ∫ F_x dx`` (J), over
    ``[start, end]`` (s from first contact; default the whole run).

    Over a closed tangential cycle at a fixed contact (a fretting loop) it is the energy dissipated by the
    springs sliding at the caps, ``4 π a² τ0 (X − ū)`` for a loop ``x: −X → X`` with ``X > ū`` (the area of
    the parallelogram). Evaluated from each span's interpolant, step by step, with
    :data:`WORK_NODES`-point Gauss–Legendre quadrature: in time on pinned spans (``dx = v_x dt``), in the
    radius on moving ones (``dx = v_x (∂d/∂a)/v_d da``).

    Parameters
    ----------
    solution : PathSolution
        The solution.
    start : float, optional
        The lower end (s from first contact); default 0.
    end : float, optional
        The upper end (s from first contact), at most the run's end; default the run's end.

    Returns
    -------
    float
        ``W`` (J).

    Raises
    ------
    ValueError
        A bound before the path's start, or not finite.
    """
    earliest = -solution.t_contact if solution.path is not None else 0.0
    allowed = f"a finite time >= {earliest:.9g} (s from first contact: the path's start) or None"
    lower = 0.0 if start is None else check_real("start", start, allowed, lambda value: value >= earliest)
    upper = solution.end_time if end is None else min(check_real("end", end, allowed, lambda value: value >= earliest),
                                                      solution.end_time)
    if start is not None and end is not None and not lower <= upper:  # (reversed: 0 J, silently)
        raise ValueError(f"start={shown(start)} and end={shown(end)} are not allowed; allowed: start <= end (s from "
                         "first contact)")
    if solution.compressed is not None:  # the compressed zone's force (none after its run: no contact)
        return tangential_work(solution.compressed, lower, upper) if upper > lower else 0.0
    nodes, weights = np.polynomial.legendre.leggauss(WORK_NODES)
    total = 0.0
    for span in solution.spans:
        t0 = max(span.t_start - solution.t_contact, lower)
        t1 = min(span.t_end - solution.t_contact, upper)
        if t1 <= t0 or span.regime is Regime.NONE or span.segment.vx == 0.0:
            continue
        segment = span.segment
        if span.interpolant is None:
            total += span.force * segment.vx * (t1 - t0)
            continue
        t_path = (solution.t_contact + t0, solution.t_contact + t1)
        if span.variable is Variable.TIME:
            bounds = t_path
        else:
            rtol = solution.model.tolerances.radius_rtol
            bounds = tuple(solution.model.branch(span.regime).radius(segment.d(t), rtol) / span.scale for t in t_path)
        bounds = tuple(span_variable(span, bound) for bound in bounds)
        low, high = min(bounds), max(bounds)
        sign = 1.0 if bounds[1] >= bounds[0] else -1.0
        breaks = np.asarray(span.interpolant.ts)
        edges = np.unique(np.concatenate([[low, high], breaks[(breaks > low) & (breaks < high)]]))
        for a, b in zip(edges[:-1], edges[1:]):
            var = 0.5 * (a + b) + 0.5 * (b - a) * nodes
            rate = _tangential_rate(solution.model, span, var)
            total += sign * 0.5 * (b - a) * float(np.sum(weights * span.interpolant(var)[0] * rate))
    return total


def _tangential_rate(model: ContinuumModel, span: Span, var: np.ndarray) -> np.ndarray:
    """``dx/d(var)`` of a span: ``v_x`` in time, ``v_x (∂d/∂a)/v_d`` times the scale in the radius over
    :attr:`Span.scale`; on a graded span (:mod:`.graded`) times ``dv/du``."""
    segment = span.segment
    graded = 1.0 if span.grading is None else span.grading.rate(np.asarray(var, dtype=float))  # (dv/du, graded)
    natural = natural_variable(span, var)
    if span.variable is Variable.TIME:
        return np.full(np.shape(var), segment.vx) * graded
    branch = model.branch(span.regime)
    return segment.vx * span.scale * np.array([branch.slope(float(v) * span.scale) for v in natural]) / segment.vd \
        * graded
