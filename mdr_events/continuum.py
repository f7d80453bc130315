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
from scipy.integrate import solve_ivp

from . import symbolic
from .parameters import Parameters
from .paths import Path

__all__ = ["Tolerances", "solve_path", "PathSolution", "EVENT_KINDS"]

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


class _Branch:
    """Scalar evaluation of one adhesive branch (9) with work of adhesion ``γ``."""

    def __init__(self, params: Parameters, work: float):
        self.params = params
        self.work = work
        args = (params.R, params.E_star, work)
        self._depth = lambda a: symbolic.relation("jkr_depth")._numeric(a, *args)
        self._slope = lambda a: symbolic.relation("jkr_depth_slope")._numeric(a, *args)
        self._integral = lambda a: symbolic.relation("jkr_depth_integral")._numeric(a, *args)
        self._quartic = symbolic.relation("jkr_radius_quartic")
        if work > 0:
            self.jump_off_radius = float(symbolic.relation("jump_off_radius").numeric(*args))
            self.jump_off_depth = float(symbolic.relation("jump_off_depth").numeric(*args))
        else:
            self.jump_off_radius = 0.0
            self.jump_off_depth = 0.0

    def depth(self, a: float) -> float:
        return float(self._depth(a)) if a > 0 else 0.0

    def slope(self, a: float) -> float:
        return float(self._slope(a))

    def integral(self, a: float) -> float:
        return float(self._integral(a)) if a > 0 else 0.0

    def radius(self, depth: float, rtol: float) -> float:
        """Stable-branch radius at ``depth`` (Newton from above on the quartic in ``s``)."""
        if depth < self.jump_off_depth:
            return math.nan
        if self.work == 0.0:
            return math.sqrt(self.params.R * depth) if depth > 0 else 0.0
        _, _, _, c1, c0 = (float(v) for v in self._quartic.coefficients(depth, self.params.R,
                                                                         self.params.E_star, self.work))
        negatives = [(1, -c1)] + ([(0, -c0)] if c0 < 0 else [])
        s = max((len(negatives) * coefficient) ** (1.0 / (4 - power)) for power, coefficient in negatives)
        s *= 1.0 + 1e-12
        floor = math.sqrt(self.jump_off_radius)
        for _ in range(100):
            value = s**4 + c1 * s + c0
            step = value / (4 * s**3 + c1)
            s_new = max(s - step, floor)
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
        kept.append(piece)
        self.pieces = kept

    def close(self, end: float) -> None:
        """Fix the end of the last piece (the radius the growth stopped at)."""
        if self.pieces:
            self.pieces[-1].end = end

    def _value(self, p: _Piece, xi: float) -> float:
        return p.x0 if p.ratio == 0.0 else p.x0 + p.ratio * (self.attach.depth(xi) - p.d_ref)

    def value(self, xi: float) -> float:
        for p in self.pieces:
            if xi <= p.end:
                return self._value(p, max(xi, p.start))
        return self._value(self.pieces[-1], xi)

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
        """Slip front ``c = sup{ξ ≤ a: Y(ξ) <= level}`` (0 if none, ``a`` if all)."""
        for i, p in enumerate(self.pieces):
            end = radius if i == len(self.pieces) - 1 else min(p.end, radius)
            if self._value(p, p.start) > level:
                return p.start
            if end >= radius:
                if self._value(p, radius) <= level:
                    return radius
            elif self._value(p, end) <= level:
                continue
            if p.ratio == 0.0:
                return min(end, radius)
            depth = p.d_ref + (level - p.x0) / p.ratio
            xi = self.attach.radius(depth, self.rtol)
            return min(max(xi, p.start), end, radius)
        return radius

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


def _segments(path: Path, mirror: bool) -> list[_Segment]:
    points = path.waypoints.copy()
    if mirror:
        points[:, 0] = -points[:, 0]
    times = path.corner_times
    out = []
    for i in range(len(points) - 1):
        dt = times[i + 1] - times[i]
        out.append(_Segment(times[i], times[i + 1], points[i, 0], points[i, 1],
                            (points[i + 1, 0] - points[i, 0]) / dt, (points[i + 1, 1] - points[i, 1]) / dt))
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

    def algebraic_force(self, x: float, a: float) -> float:
        """``F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]`` (the check of the integration)."""
        if not a > 0:
            return 0.0
        c = self.slip_front(x, a)
        return 2.0 * self.p.G_star * (c * self.K * a + x * (a - c) - self.Y.integral(c, a))


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
        while t < seg.t1 and not finished:
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
            span = _Span(t, t_end, seg, regime, pinned_radius=a)
            fired, t_stop, force = _integrate_span(solver, span, force, holding, tolerances)
            span.t_end = t_stop
            result.spans.append(span)
            a_stop = solver.radius(span, t_stop)
            if regime == "growing":
                solver.Y.close(a_stop)
            span.pieces = [_Piece(p.start, p.end, p.x0, p.ratio, p.d_ref) for p in solver.Y.pieces]
            if fired:
                holding |= set(fired)
                x_stop = seg.x(t_stop)
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


def evaluate(solution: PathSolution, times: np.ndarray) -> dict[str, np.ndarray]:
    """Fill a time grid (s from first contact) from the spans' dense output.

    Samples after the end of the run are ``nan``, except the first sample
    after a pull-off, which shows the contact gone (forces and radius 0).
    """
    solver = solution.solver
    names = ("indentation_depth", "tangential_displacement", "normal_force", "tangential_force",
             "contact_radius", "sliding_fraction")
    out = {name: np.full(len(times), np.nan) for name in names}
    spans = solution.spans
    ends = np.array([span.t_end for span in spans]) - solution.t_contact
    ended_by_contact = bool(solution.events) and solution.events[-1][1] in ("pull_off", "contact_ends")
    after_end = np.flatnonzero(times > solution.end_time)
    keep_one = after_end[:1] if ended_by_contact else after_end[:0]
    sign = -1.0 if solution.mirrored else 1.0
    anchor_maps: dict[int, AnchorMap] = {}  # the anchor map in force during each span
    for i, t_rel in enumerate(times):
        if t_rel > solution.end_time:
            if i in keep_one:
                last = spans[-1]
                out["indentation_depth"][i] = last.segment.d(solution.t_contact + t_rel)
                out["tangential_displacement"][i] = sign * last.segment.x(solution.t_contact + t_rel)
                for name in ("normal_force", "tangential_force", "contact_radius"):
                    out[name][i] = 0.0
            continue
        index = min(int(np.searchsorted(ends, t_rel, side="left")), len(spans) - 1)
        span = spans[index]
        t = solution.t_contact + t_rel
        d, x = span.segment.d(t), span.segment.x(t)
        out["indentation_depth"][i] = d
        out["tangential_displacement"][i] = sign * x
        if span.regime == "none":
            out["normal_force"][i] = out["tangential_force"][i] = out["contact_radius"][i] = 0.0
            continue
        a = solver.radius(span, t)
        out["contact_radius"][i] = a
        out["normal_force"][i] = 2.0 * solution.params.E_star * (a * d - a**3 / (3.0 * solution.params.R))
        if span.solution is None:
            force = span.force
        else:
            force = float(span.solution(a if span.variable == "radius" else t)[0])
        out["tangential_force"][i] = sign * force
        if index not in anchor_maps:
            anchor_maps[index] = AnchorMap(solver.grow, solver.tol.radius_rtol)
            anchor_maps[index].pieces = span.pieces
        anchors = anchor_maps[index]
        if a > 0:
            front = anchors.front(x - solver.K * a, a)
            out["sliding_fraction"][i] = front / a
    return out


def _integrate_span(solver: _Solver, span: _Span, force: float, holding: frozenset, tol: Tolerances):
    """Integrate ``F_x`` over a span; stop at the first slip event. Returns (event, t_stop, F_x).

    A pinned span is integrated in time. A growing or shrinking span is
    integrated in the contact radius ``a`` (``dF/da = (dF/dt)/(da/dt)``),
    which is regular where ``da/dt`` is not: at the first contact of a
    non-adhesive indenter and at the pull-off fold ``∂d/∂a = 0``.
    """
    t0, t1 = span.t_start, span.t_end
    if t1 <= t0:
        return (), t0, force
    seg = span.segment
    K = solver.K
    G2 = 2.0 * solver.p.G_star
    moving = span.regime in ("growing", "shrinking")
    branch = solver.grow if span.regime == "growing" else solver.shrink

    if moving:
        def time_of(a):
            return seg.time_at_depth(branch.depth(a))

        def radius_of(var):
            return var

        start = solver.radius(span, t0)
        if span.regime == "shrinking" and t1 == seg.time_at_depth(branch.jump_off_depth):
            stop = branch.jump_off_radius
        else:
            stop = solver.radius(span, t1)

        def rhs(a, y):
            t = time_of(a)
            x = seg.x(t)
            c = solver.slip_front(x, a)
            total = c * K + (a - c) * seg.vx * branch.slope(a) / seg.vd
            if span.regime == "shrinking":
                total += min(x - solver.Y.value(a), K * a)
            return [G2 * total]
    else:
        def time_of(t):
            return t

        def radius_of(var):
            return span.pinned_radius

        start, stop = t0, t1

        def rhs(t, y):
            a = span.pinned_radius
            return [G2 * (a - solver.slip_front(seg.x(t), a)) * seg.vx]

    a0 = radius_of(start)
    x0 = seg.x(t0)
    shift_scale = 1e-9 * max(K * a0, abs(x0), solver.p.d_max)
    onset0 = x0 - solver.Y.value(0.0) - K * a0
    full0 = x0 - solver.Y.value(a0) - K * a0
    sliding = a0 > 0 and solver.slip_front(x0, a0) > 0.0 and onset0 > -shift_scale

    def onset(var, y):
        return seg.x(time_of(var)) - solver.Y.value(0.0) - K * radius_of(var)

    def full(var, y):
        a = radius_of(var)
        return seg.x(time_of(var)) - solver.Y.value(a) - K * a

    def restick(var, y):  # growing only: dx/dt − dū/dt
        return seg.vx - K * seg.vd / branch.slope(var)

    candidates = []
    if K > 0 and start != stop:
        # holding: the slip events that have happened and still hold (a state, not a guess)
        if "slip_onset" not in holding and onset0 < 0:
            candidates.append(("slip_onset", onset))
        if "full_slip" not in holding and full0 < 0:
            candidates.append(("full_slip", full))
        if sliding and span.regime == "growing" and restick(start, None) > 0:
            candidates.append(("re_stick", restick))
    events = []
    for kind, function in candidates:
        function.terminal = True
        # onset and full slip: g rises through 0 in time; in a shrinking radius, a runs backwards
        rising = kind != "re_stick"
        function.direction = 1.0 if rising else -1.0
        events.append(function)
    span.variable = "radius" if moving else "time"
    if start == stop:
        span.solution = None
        span.force = force
        return (), t1, force
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
            if kind not in kinds and function.direction > 0 and function(first, None) >= -shift_scale * 1e-3:
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
