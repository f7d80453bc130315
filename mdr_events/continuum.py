"""The continuum (Δx → 0) limit of the spring model, integrated between events.

State
-----
On each straight path segment the indentation depth ``d(t)`` and the
tangential position ``x(t)`` are linear in time. The contact radius ``a(t)``
is *growing* on the ``Δγ0`` branch of (9), *pinned*, or *shrinking* on the
``Δγ1`` branch; because ``d`` is linear, the switches between these regimes
(start of growth, start of detachment, pull-off jump, end of contact) fall at
times known in closed form.

The tangential field is carried by the *anchor map* ``Y(ξ)``: the indenter
position at which the spring at radius ``ξ`` would have zero shift. A spring
attached at time ``t_ξ`` has ``Y = x(t_ξ)`` (for growth on a segment,
``Y(ξ) = x_s + (v_x/v_d)(d_0(ξ) − d_s)`` with ``d_0`` the ``Δγ0`` branch);
its shift is ``u = min(x − Y(ξ), ū(a))`` with ``ū(a) = π a τ0/(2G*)`` (13).
For paths whose tangential motion does not reverse, ``Y`` is non-decreasing in
``ξ``, so the sliding springs form one zone ``[0, c]`` bounded by the slip
front ``Y(c) = x − ū(a)``. Sliding springs that fall behind a cap growing
faster than the indenter moves (*re-sticking*) get the common anchor
``x − ū``, which keeps ``Y`` non-decreasing.

Integration
-----------
The tangential force obeys

    dF_x/dt = 2G* [ c dū/dt + (a − c) dx/dt + (da/dt) u(a) ],

(slip zone follows the cap, stick zone follows the indenter, springs leave at
the edge with their shift); it is integrated with
:func:`scipy.integrate.solve_ivp` (DOP853, dense output) between events found
by event functions with ``terminal`` and ``direction`` set: slip onset
(``x − Y(0) = ū``), full slip (``x − Y(a) = ū``), re-sticking
(``dx/dt = dū/dt`` while sliding). The algebraic form
``F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]`` checks it (see the tests).

Limits: the profile is the paraboloid (4); the tangential motion along the
path must not reverse (``x`` monotone; a non-increasing ``x`` is mirrored).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize
from scipy.integrate import solve_ivp

from . import analytic, symbolic
from .parameters import Parameters
from .paths import Path

__all__ = ["Tolerances", "solve_path", "PathSolution", "EVENT_KINDS", "evaluate", "evaluate_span", "extremum",
           "algebraic_tangential_force"]

#: Event names of the log, in the order they can occur.
EVENT_KINDS = (
    "first_contact",
    "corner",
    "growth_resumes",
    "detachment_starts",
    "slip_onset",
    "full_slip",
    "re_stick",
    "pull_off",
    "contact_ends",
    "path_end",
)


#: Restarts allowed at one instant before the solver reports it is stuck (each restart handles one event).
_MAX_RESTARTS = 50

#: An internal event, not logged: the slip front passes from one piece of the anchor map to the next.
_FRONT_CROSSES = "front_crosses_piece"


@dataclass(frozen=True)
class Tolerances:
    """Solver tolerances of the continuum method.

    Attributes
    ----------
    rtol, atol : float
        Relative tolerance and absolute tolerance (N) of ``solve_ivp`` for ``F_x``.
    radius_rtol : float
        Relative accuracy of the contact radius and slip front root-finding.
    """

    rtol: float = 1e-10
    atol: float = 1e-14
    radius_rtol: float = 1e-14

    def __post_init__(self) -> None:
        for name in ("rtol", "atol", "radius_rtol"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not (0 < value < 1):
                raise ValueError(f"Tolerances.{name}={value!r} is not allowed; allowed: a number in (0, 1)")


class _Branch:
    """Scalar evaluation of one adhesive branch (9) with work of adhesion ``γ``.

    Uses the derived relations compiled for Python floats
    (:attr:`symbolic.Relation.scalar`): these are called thousands of times
    per run from the right-hand side and the event functions.
    """

    def __init__(self, params: Parameters, work: float):
        self.params = params
        self.work = work
        args = (params.R, params.E_star, work)
        depth = symbolic.relation("jkr_depth").scalar
        slope = symbolic.relation("jkr_depth_slope").scalar
        integral = symbolic.relation("jkr_depth_integral").scalar
        coefficients = symbolic.relation("jkr_radius_quartic").scalar_coefficients
        self._depth = lambda a: depth(a, *args)
        self._slope = lambda a: slope(a, *args)
        self._integral = lambda a: integral(a, *args)
        self._coefficients = lambda d: coefficients(d, *args)
        if work > 0:
            self.jump_off_radius = float(symbolic.relation("jump_off_radius").numeric(*args))
            self.jump_off_depth = float(symbolic.relation("jump_off_depth").numeric(*args))
        else:
            self.jump_off_radius = 0.0
            self.jump_off_depth = 0.0
        self._floor = math.sqrt(self.jump_off_radius)

    def depth(self, a: float) -> float:
        return self._depth(a) if a > 0 else 0.0

    def slope(self, a: float) -> float:
        if a > 0:
            return self._slope(a)
        return 0.0 if self.work == 0.0 else -math.inf  # the limits a → 0 (Hertz: 2a/R → 0)

    def integral(self, a: float) -> float:
        return self._integral(a) if a > 0 else 0.0

    def depths(self, a: np.ndarray) -> np.ndarray:
        """:meth:`depth` for an array of radii (vectorised)."""
        a = np.asarray(a, dtype=float)
        value = symbolic.relation("jkr_depth").numeric(np.where(a > 0, a, 1.0), self.params.R,
                                                        self.params.E_star, self.work)
        return np.where(a > 0, value, 0.0)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radius` for an array of depths (vectorised; ``nan`` below the jump-off depth)."""
        return np.asarray(analytic.jkr_contact_radius(np.asarray(depth, dtype=float), self.params, self.work))

    def radius(self, depth: float, rtol: float) -> float:
        """Stable-branch radius at ``depth`` (Newton from above on the quartic in ``s``).

        ``nan`` below the jump-off depth; within rounding of it (1e-9 of it), the jump-off radius
        (a radius pinned just outside the fold is released at a depth that rounds below it).
        """
        if self.work == 0.0:  # Hertz: no contact above the surface (d <= 0, to rounding at first contact)
            return math.sqrt(self.params.R * depth) if depth > 0 else 0.0
        if depth < self.jump_off_depth:
            if depth < self.jump_off_depth * (1.0 + 1e-9):
                return math.nan
            return self.jump_off_radius
        _, _, _, c1, c0 = self._coefficients(depth)
        # term-dominance upper bound on the single positive root (one sign change)
        s = (-c1) ** (1.0 / 3.0) if c0 >= 0 else max((-2.0 * c1) ** (1.0 / 3.0), (-2.0 * c0) ** 0.25)
        s *= 1.0 + 1e-12
        floor = self._floor
        for _ in range(100):
            slope = 4 * s**3 + c1
            if slope <= 0.0:  # at the fold (the double root, the jump-off point) itself
                s = floor
                break
            s_new = max(s - (s**4 + c1 * s + c0) / slope, floor)
            if abs(s_new - s) <= rtol * s_new:
                s = s_new
                break
            s = s_new
        return s * s


@dataclass
class _Piece:
    """``Y(ξ) = x0 + ratio (d0(ξ) − d_ref)`` on ``[start, end]`` (``ratio = 0``: constant ``x0``)."""

    start: float
    end: float
    x0: float
    ratio: float = 0.0
    d_ref: float = 0.0


class AnchorMap:
    """The non-decreasing anchor map ``Y(ξ)`` on ``[0, a]`` as a list of pieces."""

    def __init__(self, attach: _Branch, rtol: float):
        self.pieces: list[_Piece] = []
        self.attach = attach
        self.rtol = rtol

    def reset(self) -> None:
        self.pieces = []

    def extend(self, start: float, piece: _Piece) -> None:
        """Forget everything beyond ``start`` and append ``piece`` (springs attaching from ``start``)."""
        kept = []
        for p in self.pieces:
            if p.start < start:
                kept.append(_Piece(p.start, min(p.end, start), p.x0, p.ratio, p.d_ref))
        if kept and (kept[-1].x0, kept[-1].ratio, kept[-1].d_ref) == (piece.x0, piece.ratio, piece.d_ref):
            kept[-1].end = piece.end  # the same growth resumed (a restart after an event): one piece
        else:
            kept.append(piece)
        self.pieces = kept

    def close(self, end: float) -> None:
        """Fix the end of the last piece (the radius the growth stopped at)."""
        if self.pieces:
            self.pieces[-1].end = end

    def _value(self, p: _Piece, xi: float) -> float:
        return p.x0 if p.ratio == 0.0 else p.x0 + p.ratio * (self.attach.depth(xi) - p.d_ref)

    def value(self, xi: float) -> float:
        """``Y(ξ)``; where ``Y`` jumps at a piece boundary, the value of the piece that starts there."""
        chosen = self.pieces[0]
        for p in self.pieces:
            if p.start <= xi:
                chosen = p
        return self._value(chosen, min(max(xi, chosen.start), chosen.end))

    def end_value(self, index: int, radius: float) -> float:
        """``Y`` at the end of piece ``index`` (the last piece ends at ``radius``), from that piece."""
        p = self.pieces[index]
        return self._value(p, radius if index == len(self.pieces) - 1 else min(p.end, radius))

    def integral(self, lower: float, upper: float) -> float:
        """``∫_lower^upper Y(ξ) dξ``."""
        total = 0.0
        for i, p in enumerate(self.pieces):
            end = p.end if i < len(self.pieces) - 1 else max(p.end, upper)
            lo, hi = max(lower, p.start), min(upper, end)
            if hi <= lo:
                continue
            total += p.x0 * (hi - lo)
            if p.ratio != 0.0:
                total += p.ratio * (self.attach.integral(hi) - self.attach.integral(lo) - p.d_ref * (hi - lo))
        return total

    def front(self, level: float, radius: float) -> float:
        """Slip front ``c = sup{ξ ≤ a: Y(ξ) <= level}`` (0 if none, ``a`` if all); one point of :meth:`fronts`."""
        return float(self.fronts(np.array([level]), np.array([radius]))[0])

    def fronts(self, levels: np.ndarray, radii: np.ndarray) -> np.ndarray:
        """Slip fronts ``c = sup{ξ ≤ a: Y(ξ) <= level}`` for arrays of levels and radii (vectorised over
        points, looped over pieces)."""
        levels = np.asarray(levels, dtype=float)
        radii = np.asarray(radii, dtype=float)
        fronts = radii.copy()  # a point no piece stops slides everywhere
        done = ~(radii > 0)
        fronts[done] = 0.0
        last = len(self.pieces) - 1
        for i, p in enumerate(self.pieces):
            end = radii if i == last else np.minimum(p.end, radii)
            stops_before = ~done & (self._value(p, p.start) > levels)
            fronts[stops_before] = p.start
            done |= stops_before
            end_values = p.x0 + p.ratio * (self.attach.depths(end) - p.d_ref) if p.ratio else np.full_like(end, p.x0)
            within = ~done & (end_values > levels)
            if p.ratio and within.any():
                xi = self.attach.radii(p.d_ref + (levels[within] - p.x0) / p.ratio)
                fronts[within] = np.minimum(np.maximum(np.nan_to_num(xi, nan=p.start), p.start), end[within])
            elif within.any():
                fronts[within] = end[within]
            done |= within | (end >= radii)
        return fronts

    def piece_of_front(self, level: float, radius: float, tolerance: float = 0.0) -> int:
        """Index of the piece that holds the slip front at ``level``: among the pieces that start
        within the contact (``start <= radius``: a growth piece about to start counts), the first
        whose value at its end (or at the radius) exceeds the level by more than ``tolerance`` (a
        front at a piece's end to rounding is in the next); the last of them if none does."""
        chosen = 0
        for i, p in enumerate(self.pieces):
            if p.start > radius:
                break
            chosen = i
            if self._value(p, min(p.end, radius)) > level + tolerance:
                return i
        return chosen

    def front_in_piece(self, index: int, level: float, radius: float) -> float:
        """The slip front continued smoothly within the growth piece ``index`` (the inverse of its
        ``Y``, unclipped). In a constant piece, or one that starts above the level, the front waits
        at the piece's start instead (see ``_integrate_span``).
        """
        p = self.pieces[index]
        xi = self.attach.radius(p.d_ref + (level - p.x0) / p.ratio, self.rtol)
        return xi if xi == xi else p.start  # below the branch's fold: no continuation, hold the start

    def restick(self, front: float, anchor: float) -> None:
        """Sliding springs in ``[0, front]`` stick again with the common anchor ``x − ū``."""
        rest = [_Piece(max(p.start, front), p.end, p.x0, p.ratio, p.d_ref) for p in self.pieces if p.end > front]
        self.pieces = [_Piece(0.0, front, anchor)] + rest


@dataclass
class _Segment:
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


@dataclass
class _Span:
    """An interval with one radius regime; ``solution`` is solve_ivp's dense output of ``F_x``."""

    t_start: float
    t_end: float
    segment: _Segment
    regime: str  # "none", "growing", "pinned", "shrinking"
    pinned_radius: float = 0.0
    solution: object = None
    force: float = 0.0
    pieces: list = field(default_factory=list)
    variable: str = "time"


@dataclass
class PathSolution:
    """The continuum solution of one path: spans with dense output and the event log."""

    params: Parameters
    spans: list[_Span] = field(default_factory=list)
    events: list[tuple[float, str, float, float, float]] = field(default_factory=list)
    mirrored: bool = False
    t_contact: float = 0.0
    end_time: float = 0.0
    solver: object = None


#: A velocity component below this share of the speed is taken as zero (a segment that changes its
#: depth by 1e-90 m over 0.3 mm is a pinned slide: its growth ratio vx/vd would overflow the anchor map).
_NEGLIGIBLE_SHARE = 1e-12


def _segments(path: Path, mirror: bool) -> list[_Segment]:
    points = path.waypoints.copy()
    if mirror:
        points[:, 0] = -points[:, 0]
    times = path.corner_times
    out = []
    for i in range(len(points) - 1):
        dt = times[i + 1] - times[i]
        vx, vd = (points[i + 1, 0] - points[i, 0]) / dt, (points[i + 1, 1] - points[i, 1]) / dt
        vx = 0.0 if abs(vx) < _NEGLIGIBLE_SHARE * path.speed else vx
        vd = 0.0 if abs(vd) < _NEGLIGIBLE_SHARE * path.speed else vd
        out.append(_Segment(times[i], times[i + 1], points[i, 0], points[i, 1], vx, vd))
    return out


class _Solver:
    def __init__(self, params: Parameters, tolerances: Tolerances):
        self.p = params
        self.tol = tolerances
        self.grow = _Branch(params, params.dgamma0)
        self.shrink = _Branch(params, params.dgamma1)
        self.K = float(symbolic.relation("critical_shift").numeric(1.0, params.tau0, params.G_star))
        self.Y = AnchorMap(self.grow, tolerances.radius_rtol)

    # --- the radius in a span ----------------------------------------------------
    def radius(self, span: _Span, t: float) -> float:
        if span.regime == "growing":
            return self.grow.radius(span.segment.d(t), self.tol.radius_rtol)
        if span.regime == "shrinking":
            return self.shrink.radius(span.segment.d(t), self.tol.radius_rtol)
        return span.pinned_radius

    # --- tangential quantities ------------------------------------------------------
    def slip_front(self, x: float, a: float) -> float:
        return self.Y.front(x - self.K * a, a) if a > 0 else 0.0


def solve_path(params: Parameters, path: Path, tolerances: Tolerances = Tolerances()) -> PathSolution:
    """Integrate the continuum model along ``path``; see the module docstring."""
    dx_steps = np.diff(path.waypoints[:, 0])
    if np.any(dx_steps > 0) and np.any(dx_steps < 0):
        raise ValueError("the continuum method needs a path whose tangential motion does not reverse; "
                         "allowed: x non-decreasing or non-increasing along the path (use method='discrete')")
    mirror = bool(np.any(dx_steps < 0))
    solver = _Solver(params, tolerances)
    result = PathSolution(params, mirrored=mirror, t_contact=path.first_contact_time())
    scale = 1e-12 * max(params.d_max, 1e-300)

    def log(t, kind, segment, a):
        x = segment.x(t)
        result.events.append((t - result.t_contact, kind, segment.d(t), a, -x if mirror else x))

    contact = False
    a = 0.0
    force = 0.0
    holding: frozenset[str] = frozenset()  # slip events that have happened and still hold
    segments = _segments(path, mirror)
    finished = False
    for index, seg in enumerate(segments):
        if finished:
            break
        t = max(seg.t0, result.t_contact)
        if t >= seg.t1:
            continue
        stalled, t_last = 0, -math.inf
        while t < seg.t1 and not finished:
            stalled = stalled + 1 if t <= t_last else 0
            if stalled > _MAX_RESTARTS:
                raise RuntimeError(f"the continuum method made no progress at t = {t!r} s after "
                                   f"{_MAX_RESTARTS} event restarts (events {sorted(holding)}); please report "
                                   f"the parameters and path")
            t_last = t
            d = seg.d(t)
            if not contact:
                if seg.vd > 0 and d >= -scale:
                    a = solver.grow.radius(max(d, 0.0), tolerances.radius_rtol)
                    solver.Y.reset()
                    solver.Y.extend(0.0, _Piece(0.0, a, seg.x(t)))
                    contact = True
                    force = 0.0
                    holding = frozenset()
                    log(t, "first_contact", seg, a)
                    if solver.K == 0.0:  # τ0 = 0: no spring holds any shift, all slide from the start
                        holding = frozenset({"slip_onset", "full_slip"})
                        log(t, "slip_onset", seg, a)
                        log(t, "full_slip", seg, a)
                    continue
                t_next = seg.time_at_depth(0.0) if seg.vd > 0 else seg.t1
                t_next = min(max(t_next, t), seg.t1)
                result.spans.append(_Span(t, t_next, seg, "none"))
                t = t_next
                continue
            # in contact: regime and its end (closed form on a linear depth)
            end_kind = ""
            if seg.vd > 0:
                threshold = solver.grow.depth(a)
                if d >= threshold - scale:
                    regime, t_end = "growing", seg.t1
                    holding -= {"full_slip"}  # new springs stick
                    solver.Y.extend(a, _Piece(a, math.inf, seg.xs, seg.vx / seg.vd, seg.ds))
                else:
                    regime, t_end, end_kind = "pinned", min(seg.t1, seg.time_at_depth(threshold)), "growth_resumes"
            elif seg.vd < 0:
                threshold = solver.shrink.depth(a)
                if d <= threshold + scale and a <= solver.shrink.jump_off_radius:
                    # the held radius is inside the fold of the Δγ1 branch: every inner spring has a
                    # higher threshold than the boundary one, so the whole contact comes off at once
                    result.spans.append(_Span(t, t, seg, "pinned", pinned_radius=a, force=force))
                    log(t, "pull_off", seg, a)
                    contact, finished, a, force = False, True, 0.0, 0.0
                    continue
                if d <= threshold + scale:
                    regime = "shrinking"
                    t_end = min(seg.t1, seg.time_at_depth(solver.shrink.jump_off_depth))
                    end_kind = "pull_off" if params.dgamma1 > 0 else "contact_ends"
                else:
                    regime, t_end, end_kind = "pinned", min(seg.t1, seg.time_at_depth(threshold)), "detachment_starts"
            else:
                regime, t_end = "pinned", seg.t1
            if t_end >= seg.t1:
                end_kind = ""  # the segment ends first
            if regime == "shrinking" and result.spans[-1].regime != "shrinking" \
                    and result.events[-1][1] != "detachment_starts":
                # the radius leaves the pinned or growing state at once (Δγ1 <= Δγ0, e.g. Hertz)
                log(t, "detachment_starts", seg, a)
            if regime == "shrinking":
                a_branch = solver.shrink.radius(d, tolerances.radius_rtol)
                if a_branch < a * (1.0 - 1e-12):
                    # Δγ1 < Δγ0: the boundary springs are stretched beyond the Δγ1 limit and the
                    # radius drops onto the Δγ1 branch at once; the springs it loses take their
                    # force with them and the smaller cap ū(a) clips the rest (anchor map form)
                    a = a_branch
                    force = _algebraic_force(solver.Y, solver.K, params.G_star, seg.x(t), a)
            span = _Span(t, t_end, seg, regime, pinned_radius=a)
            fired, t_stop, force = _integrate_span(solver, span, force, holding, tolerances)
            span.t_end = t_stop
            result.spans.append(span)
            a_stop = solver.radius(span, t_stop)
            if regime == "growing":
                solver.Y.close(a_stop)
            span.pieces = [_Piece(p.start, p.end, p.x0, p.ratio, p.d_ref) for p in solver.Y.pieces]
            if fired:
                fired = tuple(kind for kind in fired if kind != _FRONT_CROSSES)  # restart, log nothing
                holding |= set(fired)
                x_stop = seg.x(t_stop)
                if "full_slip" in fired:
                    # every spring sits at the cap: F_x = 2G* ū a = τ0 π a² exactly; taking it from
                    # here drops what the integration accumulated before (long, shallow paths)
                    force = 2.0 * params.G_star * solver.K * a_stop**2
                if "re_stick" in fired:
                    holding = frozenset()
                    c = solver.slip_front(x_stop, a_stop)
                    solver.Y.restick(c, x_stop - solver.K * a_stop)
                for kind in fired:
                    log(t_stop, kind, seg, a_stop)
                a = a_stop
                t = t_stop
                continue
            a = a_stop if np.isfinite(a_stop) else a
            if end_kind == "pull_off":
                a = solver.shrink.jump_off_radius
            t = t_end
            if end_kind:
                log(t, end_kind, seg, a)
                if end_kind in ("pull_off", "contact_ends"):
                    contact = False
                    finished = True
                    a = 0.0
                    force = 0.0
        if not finished and index < len(segments) - 1 and seg.t1 >= result.t_contact:
            log(seg.t1, "corner", seg, a)
    if not finished:
        log(segments[-1].t1, "path_end", segments[-1], a)
    result.end_time = (result.spans[-1].t_end if result.spans else result.t_contact) - result.t_contact
    result.solver = solver
    return result


#: Quantities :func:`evaluate` fills, in its output order.
EVALUATED_QUANTITIES = ("indentation_depth", "tangential_displacement", "normal_force", "tangential_force",
                        "contact_radius", "sliding_fraction")


def evaluate_span(solution: PathSolution, index: int, times: np.ndarray) -> dict[str, np.ndarray]:
    """Every quantity of :data:`EVALUATED_QUANTITIES` at ``times`` (s from first contact) within span
    ``index``, as a vectorised function of time: the kinematics are linear, the radius follows its
    branch of (9) (or is pinned), ``F_N`` is (10), ``F_x`` is the span's dense output and the sliding
    fraction is the slip front of the span's anchor map."""
    solver = solution.solver
    span = solution.spans[index]
    sign = -1.0 if solution.mirrored else 1.0
    t = solution.t_contact + np.asarray(times, dtype=float)
    d, x = span.segment.d(t), span.segment.x(t)
    out = {"indentation_depth": d, "tangential_displacement": sign * x}
    if span.regime == "none":
        zero = np.zeros(t.shape)
        out.update(normal_force=zero, tangential_force=zero, contact_radius=zero,
                   sliding_fraction=np.full(t.shape, np.nan))
        return out
    if span.regime == "growing":  # d >= 0 there; the first sample may sit at -0 to rounding
        a = solver.grow.radii(np.maximum(d, 0.0))
    elif span.regime == "shrinking":  # the last sample may sit on the fold to rounding
        a = solver.shrink.radii(np.maximum(d, solver.shrink.jump_off_depth))
    else:
        a = np.full(t.shape, span.pinned_radius)
    out["contact_radius"] = a
    out["normal_force"] = np.asarray(analytic.normal_force(d, a, solution.params), dtype=float)  # (10)
    if span.solution is None:
        force = np.full(t.shape, span.force)
    else:
        force = span.solution(a if span.variable == "radius" else t)[0]
    out["tangential_force"] = sign * force
    anchors = AnchorMap(solver.grow, solver.tol.radius_rtol)
    anchors.pieces = span.pieces
    with np.errstate(invalid="ignore", divide="ignore"):
        out["sliding_fraction"] = np.where(a > 0, anchors.fronts(x - solver.K * a, a) / a, np.nan)
    return out


def evaluate(solution: PathSolution, times: np.ndarray) -> dict[str, np.ndarray]:
    """Fill a time grid (s from first contact) from the spans' dense output, span by span
    (:func:`evaluate_span`).

    Samples after the end of the run are ``nan``, except the first sample after a
    pull-off, which shows the contact gone (forces and radius 0).
    """
    times = np.asarray(times, dtype=float)
    out = {name: np.full(len(times), np.nan) for name in EVALUATED_QUANTITIES}
    spans = solution.spans
    ends = np.array([span.t_end for span in spans]) - solution.t_contact
    inside = times <= solution.end_time
    owner = np.minimum(np.searchsorted(ends, times, side="left"), len(spans) - 1)
    ended_by_contact = bool(solution.events) and solution.events[-1][1] in ("pull_off", "contact_ends")
    after_end = np.flatnonzero(~inside)
    if ended_by_contact and after_end.size:
        first = after_end[0]
        t = solution.t_contact + times[first]
        sign = -1.0 if solution.mirrored else 1.0
        out["indentation_depth"][first] = spans[-1].segment.d(t)
        out["tangential_displacement"][first] = sign * spans[-1].segment.x(t)
        for name in ("normal_force", "tangential_force", "contact_radius"):
            out[name][first] = 0.0
    for index in range(len(spans)):
        rows = np.flatnonzero(inside & (owner == index))
        if rows.size:
            for name, values in evaluate_span(solution, index, times[rows]).items():
                out[name][rows] = values
    return out


#: Quantities :func:`extremum` finds the extremes of; the means are per contact area ``π a²``.
EXTREMUM_QUANTITIES = ("normal_force", "tangential_force", "contact_radius", "contact_area",
                       "mean_pressure", "mean_shear_stress")
#: Points per span at which :func:`extremum` brackets an interior extremum before refining it.
EXTREMUM_GRID = 65
#: Span-relative time accuracy of the refined extremum; the value is then exact to rounding
#: (it is flat there: its error is second order in the time error).
EXTREMUM_XTOL = 1e-12


def _quantity(filled: dict[str, np.ndarray], quantity: str) -> np.ndarray:
    if quantity in filled:
        return filled[quantity]
    area = np.pi * filled["contact_radius"] ** 2
    if quantity == "contact_area":
        return area
    force = filled["normal_force" if quantity == "mean_pressure" else "tangential_force"]
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(area > 0, force / area, np.nan)


def extremum(solution: PathSolution, quantity: str, largest: bool = True) -> tuple[float, float]:
    """The largest (or smallest) value of ``quantity`` along the run and the time it is reached
    (s from first contact), from the solution itself, not from samples.

    Each span's quantities are smooth in time; the extremum of a span is at one of its ends or
    inside it, where a scan of :data:`EXTREMUM_GRID` points brackets it and a bounded Brent search
    refines it to :data:`EXTREMUM_XTOL` of the span's length. The means (``mean_pressure``,
    ``mean_shear_stress``) are taken over the spans in contact.

    Parameters
    ----------
    solution : PathSolution
    quantity : str
        One of :data:`EXTREMUM_QUANTITIES`.
    largest : bool
        ``True`` for the maximum, ``False`` for the minimum.
    """
    if quantity not in EXTREMUM_QUANTITIES:
        raise ValueError(f"quantity={quantity!r} is not allowed; allowed: {', '.join(EXTREMUM_QUANTITIES)}")
    sign = 1.0 if largest else -1.0
    best_time, best_value = math.nan, -math.inf
    for index, span in enumerate(solution.spans):
        lower, upper = span.t_start - solution.t_contact, span.t_end - solution.t_contact
        times = np.linspace(lower, upper, EXTREMUM_GRID if upper > lower else 1)
        values = sign * _quantity(evaluate_span(solution, index, times), quantity)
        if not np.any(np.isfinite(values)):
            continue
        i = int(np.nanargmax(values))
        time, value = float(times[i]), float(values[i])
        if len(times) > 1:  # the extremum lies within one grid interval of the best point (at an end too)
            def objective(s: float) -> float:
                return -sign * float(_quantity(evaluate_span(solution, index, np.array([s])), quantity)[0])

            bracket = (times[max(i - 1, 0)], times[min(i + 1, len(times) - 1)])
            refined = optimize.minimize_scalar(objective, bounds=bracket, method="bounded",
                                               options={"xatol": EXTREMUM_XTOL * (upper - lower)})
            if -refined.fun > value:
                time, value = float(refined.x), float(-refined.fun)
        if value > best_value:
            best_time, best_value = time, value
    return best_time, sign * best_value


def _algebraic_force(anchors: AnchorMap, K: float, G_star: float, x: float, a: float) -> float:
    """``F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]`` for the anchor map ``anchors`` (``ū = K a``)."""
    if not a > 0:
        return 0.0
    c = anchors.front(x - K * a, a)
    return 2.0 * G_star * (c * K * a + x * (a - c) - anchors.integral(c, a))


def algebraic_tangential_force(solution: PathSolution, times: np.ndarray) -> np.ndarray:
    """``F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]`` from each span's anchor map, without integration.

    The independent check of :func:`evaluate`'s integrated ``F_x`` (same time
    convention, s from first contact; ``nan`` after the end of the run).
    """
    solver = solution.solver
    times = np.asarray(times, dtype=float)
    filled = evaluate(solution, times)
    ends = np.array([span.t_end for span in solution.spans]) - solution.t_contact
    owner = np.minimum(np.searchsorted(ends, times, side="left"), len(solution.spans) - 1)
    sign = -1.0 if solution.mirrored else 1.0
    out = np.full(len(times), np.nan)
    for i, t_rel in enumerate(times):
        if not t_rel <= solution.end_time:
            continue
        span = solution.spans[owner[i]]
        a = filled["contact_radius"][i]
        x = sign * filled["tangential_displacement"][i]
        anchors = AnchorMap(solver.grow, solver.tol.radius_rtol)
        anchors.pieces = span.pieces
        if span.regime == "none" or not a > 0:
            out[i] = 0.0
            continue
        out[i] = sign * _algebraic_force(anchors, solver.K, solution.params.G_star, x, a)
    return out


def _integrate_span(solver: _Solver, span: _Span, force: float, holding: frozenset, tol: Tolerances):
    """Integrate ``F_x`` over a span; stop at the first slip event. Returns (events, t_stop, F_x).

    A pinned span is integrated in time. A growing or shrinking span is
    integrated in the contact radius ``a`` (``dF/da = (dF/dt)/(da/dt)``),
    which is regular where ``da/dt`` is not: at the first contact of a
    non-adhesive indenter and at the pull-off fold ``∂d/∂a = 0``.

    The right-hand side keeps the slip state the span started in (all
    sticking, a slip zone ``[0, c]``, or full slip) and is continued smoothly
    past the span's terminal events, as hybrid-system integration requires:
    the solver then locates the switch by root-finding instead of shrinking
    its steps against a kink (the slip zone of a uniform anchor jumps open at
    onset). A slip event already met at the start (e.g. at a path corner)
    fires at once, with zero length.
    """
    t0, t1 = span.t_start, span.t_end
    if t1 <= t0:
        return (), t0, force
    if solver.K == 0.0:  # τ0 = 0: ū ≡ 0, every spring slides with zero shift, F_x ≡ 0
        span.solution, span.force = None, 0.0
        return (), t1, 0.0
    seg = span.segment
    K = solver.K
    G2 = 2.0 * solver.p.G_star
    moving = span.regime in ("growing", "shrinking")
    shrinking = span.regime == "shrinking"
    branch = solver.grow if span.regime == "growing" else solver.shrink

    def restick(var, y):  # growing only: dx/dt − dū/dt
        slope = branch.slope(var)
        return seg.vx - K * seg.vd / slope if slope > 0 else -math.inf

    if moving:
        start = solver.radius(span, t0)
        if shrinking and t1 == seg.time_at_depth(branch.jump_off_depth):
            stop = branch.jump_off_radius
        else:
            stop = solver.radius(span, t1)
    else:
        start, stop = t0, t1
    span.variable = "radius" if moving else "time"
    a0 = start if moving else span.pinned_radius
    x0 = seg.x(t0)
    onset0 = x0 - solver.Y.value(0.0) - K * a0
    full0 = x0 - solver.Y.value(a0) - K * a0
    shift_scale = 1e-9 * max(K * a0, abs(x0), solver.p.d_max)
    # The rising slip events cross a level a hair above zero: 16 ulp of the lengths involved, just
    # above the rounding of x − Y − ū (an event moves by about 1e-12 s at the paper's speed). A slip
    # function that starts at zero to rounding and first falls (the centre of a Hertz contact at
    # a = 0, the level right after a re-stick) is then not taken for a root at the start; one that
    # starts above it has crossed already and fires at once.
    level = 16 * np.finfo(float).eps * max(K * a0, abs(x0), abs(solver.Y.value(0.0)), solver.p.d_max)
    if K > 0 and a0 > 0:
        met = tuple(kind for kind, value in (("slip_onset", onset0), ("full_slip", full0))
                    if kind not in holding and value > level)
        if met:
            span.solution, span.force = None, force
            return met, t0, force
    # the slip state the span starts in; the right-hand side keeps it (see above)
    state = "full" if "full_slip" in holding else "partial" if "slip_onset" in holding else "stick"
    if state == "partial" and span.regime == "growing" and restick(start, None) <= 0.0:
        # the cap already grows faster than the indenter moves (e.g. after a corner): re-stick now
        span.solution, span.force = None, force
        return ("re_stick",), t0, force
    if start == stop or (not moving and (seg.vx == 0.0 or state == "full")):
        span.solution, span.force = None, force  # F_x does not change
        return (), t1, force

    if state == "partial":
        # a front within 1e-9 of the length scale of a piece's end (e.g. where the last event's root
        # was found, a few ulp of the radius away) is in the next piece
        piece = solver.Y.piece_of_front(x0 - K * a0, a0, shift_scale)
        current = solver.Y.pieces[piece]
        # The front waits at the piece's start while the piece starts above the level (Y jumps up
        # there, or the piece is constant: its springs all start sliding together); otherwise it
        # moves inside the piece. Either way an internal event restarts the span when the level
        # reaches the value that ends this (the piece's start value, or its end value).
        start_value = solver.Y.value(current.start)
        waiting = current.ratio == 0.0 or start_value > x0 - K * a0 + shift_scale
        next_value = start_value if waiting else solver.Y.end_value(piece, a0)
        crossing_inside = waiting or current.end < a0

    def slip_zone(x, a):
        if state == "stick":
            return 0.0
        if state == "full":
            return a
        return current.start if waiting else solver.Y.front_in_piece(piece, x - K * a, a)

    if moving:
        def time_of(a):
            return seg.time_at_depth(branch.depth(a))

        def radius_of(var):
            return var

        def rhs(a, y):
            x = seg.x(time_of(a))
            c = slip_zone(x, a)
            total = c * K + (a - c) * seg.vx * branch.slope(a) / seg.vd
            if shrinking:  # springs leave the edge with their shift
                total += K * a if state == "full" else x - solver.Y.value(a)
            return [G2 * total]
    else:
        def time_of(t):
            return t

        def radius_of(var):
            return span.pinned_radius

        def rhs(t, y):
            a = span.pinned_radius
            return [G2 * (a - slip_zone(seg.x(t), a)) * seg.vx]

    def onset(var, y):
        return seg.x(time_of(var)) - solver.Y.value(0.0) - K * radius_of(var) - level

    def full(var, y):
        a = radius_of(var)
        return seg.x(time_of(var)) - solver.Y.value(a) - K * a - level

    def front_crosses(var, y):  # the slip front starts into its piece, or leaves it
        return seg.x(time_of(var)) - K * radius_of(var) - next_value - level

    candidates = []
    if K > 0:
        # holding: the slip events that have happened and still hold (a state, not a guess)
        if "slip_onset" not in holding:
            candidates.append(("slip_onset", onset))
        if "full_slip" not in holding:
            candidates.append(("full_slip", full))
        if state == "partial" and span.regime == "growing" and restick(start, None) > 0:
            candidates.append(("re_stick", restick))
        if state == "partial" and crossing_inside:
            candidates.append((_FRONT_CROSSES, front_crosses))
    events = []
    for kind, function in candidates:
        function.terminal = True
        # onset and full slip: g rises through 0 in time; in a shrinking radius, a runs backwards
        rising = kind != "re_stick"
        function.direction = 1.0 if rising else -1.0
        events.append(function)
    if not (math.isfinite(start) and math.isfinite(stop) and math.isfinite(force)):
        raise RuntimeError(f"the continuum method lost its state on [{t0!r}, {t1!r}] s ({span.regime}: from "
                           f"{start!r} to {stop!r}, F_x = {force!r}); please report the parameters and path")
    solution = solve_ivp(rhs, (start, stop), [force], method="DOP853", rtol=tol.rtol, atol=tol.atol,
                         dense_output=True, events=events or None)
    if solution.status < 0:
        raise RuntimeError(f"solve_ivp failed on [{start}, {stop}] ({span.regime}): {solution.message}")
    span.solution = solution.sol
    if solution.status == 1:
        hits = sorted((abs(te[0] - start), te[0], candidates[i][0]) for i, te in enumerate(solution.t_events) if len(te))
        first = hits[0][1]
        # events at the same point (e.g. onset and full slip of a uniform field) fire together
        kinds = [kind for distance, var, kind in hits if abs(var - first) <= 1e-12 * max(abs(first), 1e-300)]
        # a rising event whose function is already zero to rounding fires with it (the two
        # roots of identical functions, e.g. onset and full slip of a uniform field, differ by an ulp)
        for kind, function in candidates:
            if kind not in kinds and function.direction > 0 and function(first, None) >= -2 * level:
                kinds.append(kind)
        kinds = tuple(kinds)
        return kinds, float(time_of(first)), float(solution.sol(first)[0])
    return (), t1, float(solution.y[0, -1])


def run_continuum(params: Parameters, paths: list[Path], times: np.ndarray | None = None,
                  samples: int = 2001, tolerances: Tolerances = Tolerances()) -> dict:
    """Solve every path and fill a common time grid (default: ``samples`` points to the longest run).

    Returns the arrays of :func:`evaluate` stacked to (n_cases, n_time), ``time`` and the event
    log ``events`` (one list of ``(time, kind, depth, radius, x)`` per case).
    """
    solutions = [solve_path(params, path, tolerances) for path in paths]
    if times is None:
        longest = max(solution.end_time for solution in solutions)
        times = np.linspace(0.0, longest * (1.0 + 1.0 / samples), samples)
    times = np.asarray(times, dtype=float)
    per_case = [evaluate(solution, times) for solution in solutions]
    out = {name: np.stack([case[name] for case in per_case]) for name in per_case[0]}
    out["time"] = times
    out["events"] = [solution.events for solution in solutions]
    return out
