"""The normal problem of a rate-dependent adhesion law along a path: the contact radius ``a(t)`` as the state of an ODE.

Under :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` the edge is not on a branch (9): it moves at the
speed its energy release rate gives it, ``ȧ = edge_speed(Γ(a, d(t)))`` with ``Γ = E* (g(a) − d)² / (2π a)``
(:mod:`mdr_events.theory.rate_adhesion`), and rests while ``Δγ0 <= Γ <= Δγ1``. :func:`solve_edge` integrates it with
``solve_ivp`` (Radau: the ODE is stiff where ``v_ref`` is far above the path's speed, the rate-independent limit) over
each straight segment of the path, and logs where the edge starts and stops moving (events on ``Γ``) and where the
contact ends (``a`` down to :data:`END_SHARE` of the jump-in radius: the receding edge runs away in a finite time; one
that runs away faster than the clock resolves ends where the solver gives up, :data:`COLLAPSE_ULPS`). The springs'
tangential shifts are not part of it (yet): this is the radius and the normal force (10) of such a contact.

At first contact (``d = 0``) the radius starts from 0 at an unbounded speed: near ``a = 0`` the stretched edge
releases ``Γ ≈ Δγ0 (a/a_J)³`` (``a_J``: the jump-in radius of the law at rest) on the paraboloid, so
``ȧ ≈ v_ref (a_J/a)^(3/n)``, whose solution from ``a = 0`` reaches ``a0`` after
``a0^(1+3/n) / ((1 + 3/n) v_ref a_J^(3/n))``: the integration starts there, at the radius :data:`START_SPEED` gives. The
flat punch's face touches at once: its radius starts at the punch's and cannot grow beyond it.
"""

from __future__ import annotations

import enum
import math
import warnings

import numpy as np

from mdr_events.contact.adhesion import RateDependentAdhesion, check_rate_law
from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory.kinds import theory_of
from mdr_events.theory.rate_adhesion import edge_speed_scalar
from mdr_events.validation import check_real, shown

from .branch import make_branch
from .model import ContinuumModel, Segment, kinematics
from .rate_edge_run import (PULL_OFF_BYTES_PER_SAMPLE, PULL_OFF_MIN_SAMPLES, PULL_OFF_SAMPLES,  # noqa: F401
                            PULL_OFF_XTOL, EdgeEvent, EdgeEventKind, EdgeRun, normal_force_at)
from .rate_march import march
from .tolerances import Tolerances

__all__ = ["EdgeEventKind", "EdgeEvent", "EdgeMode", "EdgeRun", "EdgeUnresolved", "solve_edge", "normal_force_at", "START_SPEED",
           "END_SHARE", "EDGE_RTOL",
           "EDGE_METHODS", "BAND_SHARE", "MAX_PIECES_PER_SEGMENT"]

#: The integration starts at first contact from the radius whose advancing speed is this many times ``v_ref``,
#: ``a0 = a_J START_SPEED^(−n/3)`` (module docstring): the time it takes to get there from 0 is below
#: ``a0 / (START_SPEED v_ref)``, and the solver's first steps resolve a speed of ``START_SPEED v_ref``.
START_SPEED = 1e6

#: The contact has come apart once the receding radius is this share of the jump-in radius (it gets there in a finite
#: time, the speed growing as ``a^(−1/n)``: the last 1e-4 of the radius take a vanishing time).
END_SHARE = 1e-3

#: A release rate within this share of a work at rest is at it (an event's root, or the closed form of a branch
#: (9), rounds it): where the depth moves it out of the band, the edge moves.
BAND_SHARE = 1e-9

#: The machine epsilon of the clock's doubles.
EPS = float(np.finfo(float).eps)

#: A segment holds at most this many pieces (rest, motion, ...): more means no progress.
MAX_PIECES_PER_SEGMENT = 1000

#: The relative tolerance of the radius ODE.
EDGE_RTOL = 1e-10

#: The ``solve_ivp`` methods the radius ODE may be integrated with: those that take stiff pieces (the edge near rest,
#: a small ``v_ref``). Radau (the default, implicit, order 5) is the reference; LSODA switches between Adams and BDF
#: by itself and costs about a seventh of Radau's time at the same accuracy on the paper's paths (a fit's choice,
#: :mod:`mdr_events.analysis.rate_fit`).
EDGE_METHODS = ("Radau", "BDF", "LSODA")

#: The range of ``solve_edge``'s ``rtol``: finer than the clock's doubles resolve, Radau never ends; coarser, the
#: events (where the edge stops) are not found.
RTOL_RANGE = (1e-13, 1e-3)

#: A receding edge whose solver gave up (its step below the clock's spacing) has come apart if the rest of its collapse
#: (its radius over its speed, an upper bound: the speed grows as the radius shrinks) is below this many ulp of the
#: clock: it runs away faster than the clock resolves.
COLLAPSE_ULPS = 1e7

#: The right-hand side evaluations one straight segment of the path may take: a law the path's clock cannot resolve
#: (``v_ref`` many orders above the path's speed, or ``n`` near 0: the speed a step of the release rate) is refused,
#: not integrated for hours.
MAX_EVALUATIONS = 200_000


class _TooStiff(Exception):
    """The right-hand side's budget (:data:`MAX_EVALUATIONS`) is spent."""


class EdgeUnresolved(ValueError):
    """A law whose edge the path's clock cannot follow (:func:`solve_edge`'s refusal, with the reason): a ``v_ref``
    many orders above the path's speed (the ODE too stiff for :data:`MAX_EVALUATIONS` steps), ``n`` near 0, or an
    indenter that outruns the advancing edge. The arguments were valid; this law on this path is not followed, which a
    fit takes as a rejected trial (:mod:`mdr_events.analysis.rate_fit`)."""


class EdgeMode(enum.Enum):
    """What the edge does on a piece: rest (the release rate in the band ``[Δγ0, Δγ1]``), advance or recede."""

    RESTING = "resting"
    ADVANCING = "advancing"
    RECEDING = "receding"


class _EdgeODE:
    """The right-hand side ``ȧ``, the release rate and the event functions on one segment."""

    def __init__(self, law: RateDependentAdhesion, params: Parameters, profile: SimulatedProfile, segment: Segment):
        self.law, self.segment = law, segment
        self.profile_depth = make_branch(params, 0.0, profile).depth  # g(a): the branch without adhesion
        self.limit = profile.radius if theory_of(profile).flat_face else math.inf  # (the face's edge)
        self.E_star = params.E_star
        self.evaluations = 0
        self.compressed_at: float | None = None
        self.release = self._release()

    def _release(self):
        """``Γ(t, a) = E* (g(a) − d(t))² / (2π a)`` (0 where the spring is not stretched) as one function of two floats,
        the segment's depth ``d(t) = ds + vd (t − t0)`` written out (the right-hand side and the events call it some
        three thousand times a piece: the same operations, without two calls)."""
        depth, E_star, two_pi = self.profile_depth, self.E_star, 2.0 * math.pi
        segment = self.segment
        ds, vd, t0 = segment.ds, segment.vd, segment.t0

        def release(t: float, a: float) -> float:
            stretch = depth(a) - (ds + vd * (t - t0))
            return E_star * stretch * stretch / (two_pi * a) if stretch > 0.0 and a > 0.0 else 0.0
        return release

    def rhs(self, mode: "EdgeMode"):
        """``ȧ(t, a)`` of a moving edge, continued smoothly past the work at rest where it stops (the speed's law
        with the sign of ``Γ − Δγ``, so that the solver finds the stop by its event, not against a kink)."""
        law = self.law
        receding = mode is EdgeMode.RECEDING
        rest, sign = (law.dgamma1, -1.0) if receding else (law.dgamma0, 1.0)
        exponent, v_ref, rate, copysign = 1.0 / law.n, law.v_ref, self.release, math.copysign

        def speed(t: float, y) -> list[float]:
            self.evaluations += 1
            if self.evaluations > MAX_EVALUATIONS:
                raise _TooStiff
            release = rate(t, float(y[0]))
            if not receding and release <= 0.0:
                self.compressed_at = t  # (the indenter outran the edge: an unbounded speed, which the solver may fail on)
                return [edge_speed_scalar(law, release)]
            excess = release / rest - 1.0 if receding else rest / release - 1.0
            try:
                return [sign * v_ref * copysign(abs(excess) ** exponent, excess)]
            except OverflowError:  # (n near 0: the speed beyond a double; the solver gives up, which _piece reports)
                return [sign * math.copysign(math.inf, excess)]
        return speed

    def mode(self, t: float, a: float) -> EdgeMode:
        """The edge's mode at ``t`` with radius ``a``: by the release rate, and at a work at rest (to
        :data:`BAND_SHARE`) by where the depth goes (out of the band when it moves the rate out)."""
        release, law, vd = self.release(t, a), self.law, self.segment.vd
        if release > law.dgamma1 * (1.0 + BAND_SHARE) or (release >= law.dgamma1 * (1.0 - BAND_SHARE) and vd < 0.0):
            return EdgeMode.RECEDING
        if a >= self.limit:  # the punch's face is all there is: it cannot grow
            return EdgeMode.RESTING
        if release < law.dgamma0 * (1.0 - BAND_SHARE) or (release <= law.dgamma0 * (1.0 + BAND_SHARE) and vd > 0.0):
            return EdgeMode.ADVANCING
        return EdgeMode.RESTING

    def leaves_rest(self, t: float, a: float) -> tuple[float, EdgeMode] | None:
        """When a resting edge of radius ``a`` starts to move on the segment after ``t``, in closed form: where the
        depth reaches that of the branch (9) of ``Δγ1`` (receding, the depth falling) or of ``Δγ0`` (advancing)."""
        vd, g = self.segment.vd, self.profile_depth(a)
        if vd < 0.0:
            work, mode = self.law.dgamma1, EdgeMode.RECEDING
        elif vd > 0.0 and a < self.limit:
            work, mode = self.law.dgamma0, EdgeMode.ADVANCING
        else:
            return None
        when = self.segment.time_at_depth(g - math.sqrt(2.0 * math.pi * a * work / self.E_star))
        return (when, mode) if when < self.segment.t1 else None

    def moving_events(self, mode: EdgeMode, end_radius: float) -> list:
        """Terminal events of a moving edge: it stops (the rate back at the work at rest) or the contact ends."""
        rest = self.law.dgamma1 if mode is EdgeMode.RECEDING else self.law.dgamma0

        rate = self.release

        def stops(t, y):
            return rate(t, float(y[0])) - rest
        stops.terminal, stops.direction = True, -1.0 if mode is EdgeMode.RECEDING else 1.0

        def ends(t, y):  # (a collapse faster than the clock resolves ends where the solver gives up: _collapsed)
            return y[0] - end_radius
        ends.terminal, ends.direction = True, -1.0
        events = [stops, ends]
        if mode is EdgeMode.ADVANCING and math.isfinite(self.limit):
            def fills(t, y):
                return y[0] - self.limit
            fills.terminal, fills.direction = True, 1.0
            events.append(fills)
        return events


class _Constant:
    """A resting radius, called like ``solve_ivp``'s dense output."""

    def __init__(self, radius: float):
        self.value = radius

    def __call__(self, t) -> np.ndarray:
        return np.full((1,) + np.shape(t), self.value)


def solve_edge(params: Parameters, path: Path, law: RateDependentAdhesion, profile: SimulatedProfile = None,
               rtol: float = EDGE_RTOL, method: str = "Radau") -> EdgeRun:
    """Integrate the radius of a contact under ``law`` along ``path`` (module docstring).

    Parameters
    ----------
    params : Parameters
        The material and ``R`` (the paraboloid's); its works of adhesion must be the law's at rest.
    path : Path
        The indenter's path.
    law : RateDependentAdhesion
        The adhesion law.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    rtol : float, optional
        The ODE's relative tolerance.
    method : str, optional
        The ``solve_ivp`` method, one of :data:`EDGE_METHODS` (default Radau, the reference).

    Returns
    -------
    EdgeRun
        The radius's pieces and the edge's events.

    Raises
    ------
    TypeError
        ``params``, ``path`` or ``law`` of another type.
    ValueError
        A law whose works at rest are not the parameters', an ``rtol`` out of :data:`RTOL_RANGE`, a ``method`` not in
        :data:`EDGE_METHODS`; or, as :class:`EdgeUnresolved` (a ``ValueError``), a law whose edge the path's clock
        cannot follow (the solver gave up, or would take more than :data:`MAX_EVALUATIONS` steps of the ODE on a
        segment: ``v_ref`` many orders above the path's speed, ``n`` near 0; or the indenter outran the advancing
        edge), with the reason.
    """
    if not isinstance(params, Parameters):
        raise TypeError(f"params={shown(params)} ({type(params).__name__}) is not allowed; allowed: a Parameters")
    if not isinstance(path, Path):
        raise TypeError(f"path={shown(path)} ({type(path).__name__}) is not allowed; allowed: a Path")
    law = check_rate_law(law)
    rtol = check_real("rtol", rtol, f"a number with {RTOL_RANGE[0]:g} <= rtol <= {RTOL_RANGE[1]:g}",
                      lambda value: RTOL_RANGE[0] <= value <= RTOL_RANGE[1])
    if not isinstance(method, str) or method not in EDGE_METHODS:
        raise ValueError(f"method={shown(method)} is not allowed; allowed: one of {', '.join(EDGE_METHODS)}")
    profile = check_simulated_profile(profile)
    model = ContinuumModel(params, Tolerances(), profile)
    if law.works_at_rest != (params.dgamma0, params.dgamma1):
        raise ValueError(f"law={law!r} is not allowed with dgamma0={params.dgamma0!r}, dgamma1={params.dgamma1!r} "
                         "J/m²; allowed: a law whose works at rest are the parameters'")
    jump_in = profile.radius if theory_of(profile).flat_face else model.grow.radius(0.0, 1e-14)
    run = EdgeRun(model)
    entries = list(path.entry_times())
    state = None  # (t, a) in contact, or None
    touched = None  # the time of a contact whose jump-in has not yet ended, or None
    for segment in kinematics(path):
        ode = _EdgeODE(law, params, profile, segment)
        t = segment.t0
        for _ in range(MAX_PIECES_PER_SEGMENT):
            if state is None:
                starts = [entry for entry in entries if t <= entry < segment.t1]
                if not starts:
                    break
                state = _touch(run, law, profile, segment, starts[0], jump_in)
                touched = starts[0]
            if state[0] >= segment.t1:
                break
            touched = None
            state = _piece(run, ode, state, jump_in, rtol, method)
            if state is not None:
                t = state[0]
            else:
                t = run.events[-1].time
        else:
            raise _unresolved(law, f"no progress on [{float(segment.t0)!r}, {float(segment.t1)!r}] s of the path after "
                                   f"{MAX_PIECES_PER_SEGMENT} pieces (rest, motion, ...)")
    if touched is not None and path.max_depth > 0.0:  # (the path ended inside the jump-in's lag: radius 0 at any depth)
        raise EdgeUnresolved(
            f"law={law!r} is not allowed on this path: its edge cannot be followed (the contact made at "
            f"t={float(touched)!r} s jumps in over {float(state[0] - touched):.3g} s, beyond the path's end at "
            f"{float(path.duration):.6g} s: the indenter outran the advancing edge, which would leave no contact at its "
            "depth); allowed: a law whose edge keeps ahead of the indenter (a larger v_ref, or a slower path), or "
            "Adhesion(dgamma0, dgamma1), the limit v_ref -> inf")
    return run


def _unresolved(law: RateDependentAdhesion, reason: str, ode: _EdgeODE | None = None) -> EdgeUnresolved:
    """The refusal of a law whose edge the path's clock cannot follow, with the reason and what would be followed: where
    the indenter outran the advancing edge (``ode.compressed_at``), an edge fast enough to keep ahead of it (the
    advancing speed ``v_ref (Δγ0/G − 1)^(1/n)`` grows with ``v_ref``); otherwise one the clock resolves."""
    if ode is not None and ode.compressed_at is not None:
        return EdgeUnresolved(f"law={law!r} is not allowed on this path: its edge cannot be followed ({_compressed(ode)}"
                          f"{reason}); allowed: a law whose advancing edge keeps ahead of the indenter (a larger v_ref "
                          "than this one: the edge's advancing speed grows with it; or a blunter indenter), or "
                          "Adhesion(dgamma0, dgamma1), the limit v_ref -> inf")
    return EdgeUnresolved(f"law={law!r} is not allowed on this path: its edge cannot be followed ({reason}); allowed: a "
                      "law whose edge speed the path's clock resolves (v_ref fewer orders of magnitude above the path's "
                      "speed, n nearer 1), or Adhesion(dgamma0, dgamma1), the limit v_ref -> inf")


def _touch(run: EdgeRun, law: RateDependentAdhesion, profile, segment: Segment, when: float, jump_in: float):
    """A contact made at ``when`` (``d = 0``): the radius just after the jump-in's start (module docstring)."""
    kind = EdgeEventKind.RE_CONTACT if run.events else EdgeEventKind.FIRST_CONTACT
    run.events.append(EdgeEvent(when, kind, float(segment.d(when)), 0.0))
    if theory_of(profile).flat_face:  # the whole face at once
        return (when, jump_in)
    start = START_SPEED ** (-law.n / 3.0) * jump_in
    power = 1.0 + 3.0 / law.n
    # start^power / (power v_ref a_J^(3/n)) with start = a_J START_SPEED^(-n/3), simplified (a_J^(3/n) underflows
    # to 0 for n near 0)
    lag = jump_in / (power * law.v_ref * START_SPEED ** (1.0 + law.n / 3.0))
    return (when + lag, start)


def _compressed(ode: _EdgeODE) -> str:
    """The start of the reason where the indenter outran the advancing edge (its spring compressed), else ""."""
    if ode.compressed_at is None:
        return ""
    return (f"at t={float(ode.compressed_at)!r} s the indenter outran the advancing edge, its spring compressed, where "
            "the edge's speed is unbounded (the jump of a contact without adhesion), which solve_edge does not follow; ")


def _collapsed(ode: _EdgeODE, speed, t: float, a: float) -> bool:
    """Whether a receding edge of radius ``a`` at ``t`` comes apart faster than the clock resolves
    (:data:`COLLAPSE_ULPS`)."""
    try:
        rate = abs(speed(t, [a])[0])
    except _TooStiff:
        return False
    return math.isinf(rate) or a <= COLLAPSE_ULPS * EPS * abs(t) * rate


def _piece(run: EdgeRun, ode: _EdgeODE, state, jump_in: float, rtol: float, method: str):
    """One piece from ``state`` (``(t, a)``): resting to the segment's end or where the edge starts to move (closed
    form), or moving (the ODE) to the segment's end, where it stops, or where the contact ends (``None``)."""
    t0, a0 = state
    segment = ode.segment
    mode = ode.mode(t0, a0)
    if mode is EdgeMode.RESTING:
        leaving = ode.leaves_rest(t0, a0)
        t_end = segment.t1 if leaving is None else max(leaving[0], t0)
        run.pieces.append((t0, t_end, segment, _Constant(a0)))
        if leaving is not None:
            kind = EdgeEventKind.RECEDING_STARTS if leaving[1] is EdgeMode.RECEDING else EdgeEventKind.GROWTH_STARTS
            run.events.append(EdgeEvent(t_end, kind, float(segment.d(t_end)), a0))
        return (t_end, a0)
    speed = ode.rhs(mode)
    try:
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")  # (a failure is reported below, whole: LSODA warned of it beforehand)
            solution = march(speed, t0, segment.t1, a0, method, rtol, rtol * jump_in,
                             ode.moving_events(mode, END_SHARE * jump_in))
    except _TooStiff:
        raise _unresolved(ode.law, f"{MAX_EVALUATIONS} evaluations of the ODE from t={float(t0)!r} s "
                                   f"({mode.value}) did not reach the segment's end {float(segment.t1)!r} s", ode) from None
    except (ValueError, ArithmeticError) as error:  # an infinite speed (n near 0) reached the solver, or a radius
        # beyond the profile's doubles
        raise _unresolved(ode.law, f"the solver failed from t={float(t0)!r} s ({mode.value}): "
                                   f"{type(error).__name__}: {error}", ode) from None
    t_end, a_end = solution.t, solution.y
    if solution.status < 0:
        if mode is EdgeMode.RECEDING and _collapsed(ode, speed, t_end, a_end):  # it ran away faster than the clock
            run.pieces.append((t0, t_end, segment, solution.sol or _Constant(a0)))
            run.events.append(EdgeEvent(t_end, EdgeEventKind.CONTACT_ENDS, float(segment.d(t_end)), a_end))
            return None
        raise _unresolved(ode.law, f"the solver failed on [{float(t0)!r}, {float(segment.t1)!r}] s "
                                   f"({mode.value}): {solution.message}", ode)
    run.pieces.append((t0, t_end, segment, solution.sol))
    if solution.status == 1 and solution.event == 1:  # the contact has come apart
        run.events.append(EdgeEvent(t_end, EdgeEventKind.CONTACT_ENDS, float(segment.d(t_end)), a_end))
        return None
    if solution.status == 1:  # it stops (or fills the punch's face)
        run.events.append(EdgeEvent(t_end, EdgeEventKind.EDGE_STOPS, float(segment.d(t_end)), a_end))
    return (t_end, a_end)
