r"""The springs' tangential shifts on top of a rate-dependent edge: the continuum's ``F_x`` under ``τ0``'s cap.

Under :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` the radius ``a(t)`` is the state of an ODE
(:func:`~mdr_events.models.continuum.rate_edge.solve_edge`). On top of it the springs keep the paper's rules: a spring
attaches at the advancing edge with its anchor at the indenter's ``x`` then, lets go at the receding edge (forgetting
its anchor), and its shift is capped at ``ū = K a(t)`` (13), the same for every spring: each anchor is a play operator
of the window ``[L, U] = [x − K a, x + K a]``.

Along a path whose ``x`` does not turn back (scenarios A and B, any path with ``x`` monotone; ``σ = ±1`` its way) this
play is a closed form. With ``σx`` non-decreasing every anchor lies at or below the indenter (``Y <= σx <= U``), so only
the lower level ``L = σx − K a`` pushes, and it pushes every spring to its running maximum ``M(t) = max_{τ<=t} L(τ)``
(for ``τ`` before a spring's attachment ``L(τ) <= σx(τ) <= X``, so the maximum over the whole run is that since it
attached). A spring attached at ``τ`` carries the anchor ``max(X(τ), M(t))`` with ``X = σx(τ)``; the springs attached
later lie further out, so ``X`` grows outwards and the springs sliding at the cap are the central ones. The force is

.. math:: F_x = 2 G^* \sigma \int_0^{a} \left(\sigma x - \max(X(\xi), M)\right) d\xi \qquad (11), (13)

over the records of springs still attached: the advancing pieces of the edge, each cut where a later receding edge
took its springs (:func:`~mdr_events.theory.symbolic.derive_rate_dependent_adhesion`'s ``rate_springs_record_force``:
in the attachment time, by parts, ``∫ X ȧ dτ = [X a] − ∫ Ẋ a dτ``, the last integral by Gauss–Legendre on the solver's
steps, exact for its dense polynomials). ``M`` is the running maximum of ``L`` over the solver's steps, with a step's
interior maximum found by bounded minimisation. The springs that attached in the jump-in's first instant (radius below
the integration's start, :data:`~mdr_events.models.continuum.rate_edge.START_SPEED`) carry the anchor of its start (off
by ``|ẋ|`` times the jump-in's lag, about ``a_J / (1e6 v_ref)``).

A path whose ``x`` turns back needs the upper level too (the anchors' nested clips): :func:`solve_rate_shifts` hands it
to :class:`~mdr_events.models.continuum.rate_play.RatePlay`, every anchor a play operator of the window. The laws with
Coulomb's part (a cap that differs from spring to spring) are refused here; the continuum method runs them spring by
spring on the same edge (:mod:`~mdr_events.models.continuum.rate_coulomb`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law, symbolic
from mdr_events.validation import shown

from .rate_edge import EDGE_RTOL, EdgeEventKind, EdgeRun, normal_force_at, solve_edge
# (the parts, one idea a module; the names kept here, where users, rate_play and the tests import them)
from .rate_levels import STEP_PROBES, _knots, _level_candidates, _peaks, _reach  # noqa: F401
from .rate_quadrature import GAUSS_NODES, _swept, gauss_radius  # noqa: F401
from .rate_records import BISECTIONS, _bisect, _first_radius, _in_contact, _timeline, _View  # noqa: F401

__all__ = ["RateShifts", "solve_rate_shifts", "check_rate_friction", "path_way", "gauss_radius", "GAUSS_NODES", "BISECTIONS",
           "STEP_PROBES"]


def _relation() -> symbolic.Relation:
    return symbolic.derive_rate_dependent_adhesion()["rate_springs_record_force"]


@dataclass
class RateShifts:
    """``F_x`` along a path whose ``x`` does not turn back, on top of the rate-dependent edge (module docstring).

    Parameters
    ----------
    edge : EdgeRun
        The radius along the path (:func:`~mdr_events.models.continuum.rate_edge.solve_edge`).
    path : Path
        The path.
    cap : float
        ``K`` of ``ū = K a`` (13) (m per m).
    G_star : float
        The effective shear modulus ``G*`` (Pa).
    sign : float
        ``σ``: +1 where ``x`` never falls, -1 where it never rises.
    """

    edge: EdgeRun
    path: Path
    cap: float
    G_star: float
    sign: float
    views: list = field(default_factory=list, init=False)

    def __post_init__(self) -> None:
        self._corners = (self.path.corner_times, self.sign * self.path.waypoints[:, 0])
        self.views = _timeline(self.edge, self._x)
        self._candidates = _level_candidates(self)
        self._running = np.maximum.accumulate(self._candidates[1])
        self._sweeps: dict = {}  # (the records' cumulative integrals, by piece and start: _swept)

    def _x(self, times) -> np.ndarray:
        """``σx`` (m) at ``times`` (the path's ``x``, its corners read once)."""
        corners, along = self._corners
        return np.interp(times, corners, along)  # (held at the ends beyond them)

    def _radius(self, times) -> np.ndarray:
        """The radius (m) at ``times`` (the edge's, from its steps' polynomials), 0 out of contact."""
        times = np.asarray(times, dtype=float)
        out = np.zeros(times.shape)
        for view in self.views:
            inside = (times >= view.t0) & (times <= view.t1)
            if inside.any():
                out[inside] = view.solution(times[inside])[0]
        return out

    def normal_force(self, times) -> np.ndarray:
        """``F_N`` (N, (10)) at ``times`` (s, path clock), from the edge's steps' polynomials; 0 out of contact.

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        numpy.ndarray
            The normal force, the shape of ``times``.
        """
        times = np.asarray(times, dtype=float)
        return normal_force_at(self.edge.model, self.path.position(times)[1], self._radius(times))

    def _level(self, times) -> np.ndarray:
        """``L = σx − K a`` (m) at ``times``."""
        return self._x(times) - self.cap * self._radius(times)

    def running_level(self, times) -> np.ndarray:
        """``M(t) = max_{τ<=t} L(τ)`` (m, in ``σ``'s coordinates) at ``times`` (s, path clock), over the contact.

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        numpy.ndarray
            The running maximum; ``-inf`` before the first contact.
        """
        times = np.atleast_1d(np.asarray(times, dtype=float))
        stamps, running = self._candidates[0], self._running
        at = np.searchsorted(stamps, times, side="right") - 1
        held = np.where(at >= 0, running[np.maximum(at, 0)], -np.inf)
        # since the last candidate (a knot, or a step's interior maximum) L has no maximum inside: its largest is at
        # one of the ends
        inside = _in_contact(self.views, times)
        return np.where(inside, np.maximum(held, np.where(inside, self._level(times), -np.inf)), held)

    def tangential_force(self, times) -> np.ndarray:
        """``F_x`` (N) at ``times`` (s, path clock); 0 out of contact.

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        numpy.ndarray
            The tangential force, the shape of ``times``.
        """
        return self._evaluate(times)[0]

    def slip_radius(self, times) -> np.ndarray:
        """The radius (m) out to which the springs are at the cap (the central ones), 0 out of contact: those pushed to
        the running maximum ``M`` while the level ``L`` is at it (where it has turned back they stick again).

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        numpy.ndarray
            The sliding springs' extent, at most the contact radius.
        """
        return self._evaluate(times, forces=False)[1]

    def slip_onset_time(self) -> float:
        """The first time (s, path clock) at which springs slide: ``L`` reaches the first springs' anchor.

        Returns
        -------
        float
            The time, or ``nan`` where no spring slides during the first contact.
        """
        first = self.views[0]
        anchor = first.block.anchor
        ended = [event.time for event in self.edge.events if event.kind is EdgeEventKind.CONTACT_ENDS]
        stamps, values = self._candidates
        beyond = np.flatnonzero((stamps <= (ended[0] if ended else np.inf)) & (values > anchor))
        if not beyond.size:
            return float("nan")
        after = float(stamps[beyond[0]])
        before = float(stamps[beyond[0] - 1]) if beyond[0] > 0 else first.t0
        if not self._level(np.array([before]))[0] <= anchor:
            return before
        return float(brentq(lambda t: float(self._level(np.array([t]))[0]) - anchor, before, after,
                            xtol=4.0 * np.finfo(float).eps * abs(after)))

    def _evaluate_each(self, *times: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
        """:meth:`_evaluate` of each one-dimensional array of ``times``, all in one pass (each time's values are its
        own: the same as asked alone)."""
        cuts = np.cumsum([np.size(part) for part in times])[:-1]
        force, sliding = self._evaluate(np.concatenate([np.atleast_1d(part) for part in times]))
        return list(zip(np.split(force, cuts), np.split(sliding, cuts)))

    def _evaluate(self, times, forces: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """``F_x`` (N; zeros where ``forces`` is false: the sliding springs' extent alone is asked, which needs no
        quadrature and no time where a receding edge's radius was reached) and the sliding springs' extent (m)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        force, sliding = np.zeros(times.shape), np.zeros(times.shape)
        starts = np.array([view.t0 for view in self.views])
        owner = np.searchsorted(starts, times, side="right") - 1
        levels = self.running_level(times)
        for index, view in enumerate(self.views):
            rows = np.flatnonzero((owner == index) & (times <= view.t1))
            if rows.size:
                force[rows], sliding[rows] = _view_force(self, view, times[rows], levels[rows], forces)
        at_cap = self._level(times) >= levels  # (the level at its running maximum: M is L there, bit for bit)
        return self.sign * force, np.where(at_cap, sliding, 0.0)


def _view_force(shifts: RateShifts, view: _View, times: np.ndarray, levels: np.ndarray, forces: bool = True):
    """``F_x / σ`` (N) and the sliding springs' extent (m) at ``times`` within one piece; where ``forces`` is false the
    extent alone (the force zeros): a record's sliding springs reach to its radius when ``σx`` reached the level, at
    most the radius now, without the time the radius was reached (the springs beyond it gone) or the quadrature."""
    radius = view.solution(times)[0]
    x_now = shifts._x(times)
    force, sliding = np.zeros(times.shape), np.zeros(times.shape)
    relation = _relation()
    block = view.block
    kept = np.minimum(block.radius, radius)
    slides = np.where(block.anchor < levels, kept, 0.0)
    force += relation.numeric(x_now, levels, 0.0, slides, kept, block.anchor, block.anchor, 0.0, shifts.G_star)
    sliding = np.maximum(sliding, slides)
    records = [(record.lo, np.full(times.shape, record.hi), record.solution) for record in view.records]
    if view.way > 0:
        records.append((view.t0, times, view.solution))
    for lo, hi, solution in records:
        a_lo = float(solution(lo)[0])
        present = a_lo < radius
        if not present.any():
            continue
        rows = np.flatnonzero(present)
        top, level = hi[rows], levels[rows]
        if view.way < 0 and forces:  # (the receding edge has taken the springs beyond the radius now)
            beyond = solution(top)[0] > radius[rows]
            if beyond.any():
                top[beyond] = _first_radius(solution, lo, top[beyond], radius[rows][beyond])
        star = np.where(shifts._x(np.full(rows.size, lo)) >= level, lo, _reach(shifts, top, level))
        a_star = solution(star)[0]
        if not forces:  # (beyond the radius now where the receding edge took them: all of its springs slide)
            sliding[rows] = np.maximum(sliding[rows], np.where(star > lo, np.minimum(a_star, radius[rows]), 0.0))
            continue
        a_hi, x_star, x_hi = solution(top)[0], shifts._x(star), shifts._x(top)
        force[rows] += relation.numeric(x_now[rows], level, a_lo, a_star, a_hi, x_star, x_hi,
                                        _swept(shifts, solution, lo, star, top),
                                        shifts.G_star)
        sliding[rows] = np.maximum(sliding[rows], np.where(star > lo, a_star, 0.0))  # (none slide where star is lo)
    return force, sliding


def check_rate_friction(friction: FrictionLaw, law: RateDependentAdhesion | None = None) -> None:
    """Refuse a friction law the closed-form play on the rate-dependent edge does not follow: only ``"tau0"`` (one cap
    ``K a`` for every spring); the continuum method runs the laws with Coulomb's part spring by spring
    (:mod:`~mdr_events.models.continuum.rate_coulomb`).

    Parameters
    ----------
    friction : FrictionLaw
        The friction law.
    law : RateDependentAdhesion or None, optional
        The adhesion law, named in the refusal.

    Raises
    ------
    TypeError
        Not a :class:`~mdr_events.contact.friction.FrictionLaw`.
    ValueError
        Another law than ``"tau0"``, in one line naming both laws and what runs them.
    """
    if not isinstance(friction, FrictionLaw):
        raise TypeError(f"friction={shown(friction)} ({type(friction).__name__}) is not allowed; allowed: a "
                        "FrictionLaw('tau0') or None")
    if friction.law != "tau0":
        named = "a rate-dependent adhesion law" if law is None else f"adhesion={law!r}"
        raise ValueError(f"friction={friction!r} is not allowed with {named} in solve_rate_shifts (Coulomb's part "
                         "gives each spring its own cap, growing with its compression, where this closed-form play "
                         "holds one cap K a for every spring); allowed: FrictionLaw('tau0') here; simulate's "
                         "continuum method runs every friction law under this adhesion law (Coulomb's part spring by "
                         "spring, continuum.rate_coulomb)")


def path_way(path: Path) -> tuple[float, int | None]:
    """``σ`` of a path and the waypoint where its ``x`` turns back (``None`` where it does not).

    Parameters
    ----------
    path : Path
        The indenter's path.

    Returns
    -------
    tuple of (float, int or None)
        ``σ`` (+1 where ``x`` first rises or never moves, -1 where it first falls) and the turning waypoint.

    Raises
    ------
    TypeError
        Not a :class:`~mdr_events.models.paths.Path`.
    """
    if not isinstance(path, Path):
        raise TypeError(f"path={shown(path)} ({type(path).__name__}) is not allowed; allowed: a Path")
    ways = np.sign(np.diff(path.waypoints[:, 0]))
    sign = float(ways[ways != 0.0][0]) if np.any(ways != 0.0) else 1.0
    turns = np.flatnonzero(ways == -sign)
    return sign, (int(turns[0]) if turns.size else None)


def solve_rate_shifts(params: Parameters, path: Path, law: RateDependentAdhesion, profile: SimulatedProfile = None,
                      friction: FrictionLaw | None = None, rtol: float = EDGE_RTOL,
                      method: str = "Radau") -> RateShifts:
    """The continuum's tangential force on top of the rate-dependent edge along ``path`` (module docstring).

    Parameters
    ----------
    params : Parameters
        The material, ``τ0`` and ``R`` (the paraboloid's); its works of adhesion are the law's at rest.
    path : Path
        The indenter's path.
    law : RateDependentAdhesion
        The adhesion law.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    friction : FrictionLaw or None, optional
        ``"tau0"`` (its ``τ0``, else ``params.tau0``); ``None``: the paper's ``"tau0"`` of ``params.tau0``.
    rtol : float, optional
        The edge's ODE tolerance (:func:`~mdr_events.models.continuum.rate_edge.solve_edge`).
    method : str, optional
        The edge's ``solve_ivp`` method.

    Returns
    -------
    RateShifts
        ``F_x``, the sliding springs and the slip onset along the path (a
        :class:`~mdr_events.models.continuum.rate_play.RatePlay` where its ``x`` turns back).

    Raises
    ------
    TypeError
        ``params``, ``path`` or ``friction`` of another type.
    ValueError
        A friction law other than ``"tau0"``, or what ``solve_edge`` refuses.
    """
    if not isinstance(params, Parameters):
        raise TypeError(f"params={shown(params)} ({type(params).__name__}) is not allowed; allowed: a Parameters")
    sign, turn = path_way(path)
    tau0 = params.tau0
    if friction is not None:
        check_rate_friction(friction, law)
        tau0 = params.tau0 if friction.tau0 is None else friction.tau0
    edge = solve_edge(params, path, law, profile=profile, rtol=rtol, method=method)
    cap = power_law.cap_per_radius(params.replace(tau0=tau0))
    if turn is not None:  # (both levels push: every anchor a play operator, continuum.rate_play)
        from .rate_play import RatePlay

        return RatePlay(edge, path, cap, params.G_star, 1.0)
    return RateShifts(edge, path, cap, params.G_star, sign)
