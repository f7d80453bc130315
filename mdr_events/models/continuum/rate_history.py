r"""The contact radius of a rate-dependent adhesion law as the per-spring route reads it (:mod:`.play_springs`).

Under :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` the radius ``a(t)`` is the state of an ODE
(:func:`~mdr_events.models.continuum.rate_edge.solve_edge`): resting pieces (constant), advancing and receding ones
(the solver's steps). Coulomb's part gives every spring its own cap ``ū(a) + μ (E*/G*) max(d − g(ξ), 0)``, so no
level is shared by the springs (the closed-form play of :mod:`.rate_shifts` and :mod:`.rate_play` holds one cap
``K a`` for all); the per-spring route composes each spring's play operator exactly in time on any radius history.
:class:`RateHistory` is that history: the radius at any time (the steps' polynomials), where it jumps (in: at the
start of the integration a contact's springs within the start radius attach at once, with one anchor, as
:mod:`.rate_shifts` takes them; off: where the contact ends, from the end radius to 0), the pieces where it moves
(their ends join the springs' clamp times: ``ū(a(t))`` has a kink there), each spring's last attachment (the first
time an advancing piece's radius reaches it, Newton's steps on the step's polynomial) and, for the quadrature in
``ξ``, the radii where the attachment's speed ``ȧ`` has changed by :data:`SPEED_RATIO` since the last such radius
(:meth:`RateHistory.breaks`). The attachment time ``τ(ξ)`` has the slope ``1/ȧ``, which the edge's rush at the
jump-in (from ``10⁶ v_ref`` down) and its slowing where it stops change by orders of magnitude over a small range of
radii: a near-kink of the anchors ``x(τ(ξ))`` that no provenance marks; the panels split there keep each panel's
``ȧ`` within a factor :data:`SPEED_RATIO` (graded towards a stop like the square root it is).

The exactness of the composition needs ``ū(a(t))`` concave between the clamp times (``L = x − c`` convex, ``U = x + c``
concave); :class:`~.play_springs.PlaySprings` samples it on every piece and gives each spring the times of its own
extremes where it is not.
"""

from __future__ import annotations

import numpy as np

from .rate_dense import REACH_STEPS, StepPolynomials, step_polynomials
from .rate_edge import EdgeEventKind, EdgeRun

__all__ = ["RateHistory", "SPEED_RATIO", "SETTLED_ULPS"]

#: The panels of the force's quadrature in ``ξ`` are split at the radii where the attachment's speed has changed by
#: this factor since the last split (module docstring): within a panel ``1/ȧ`` varies by at most this factor between
#: the solver's steps. Measured on scenario A at v_ref = 100 m/s (tau0+coulomb, μ = 0.3): without the splits the force
#: is 5e-6 of itself off (the jump-in's rush), with a factor 10 1e-15, with 2 1e-15.
SPEED_RATIO = 2.0
#: Newton's steps towards an attachment time stop, spring by spring, once Newton's step is within this many ulp of the
#: time (converged: a bisection of the bracket beside it would only halve a bracket of a few ulp).
SETTLED_ULPS = 4.0


class _Piece:
    """One piece of the edge: ``[t0, t1]``, its dense output (the steps' polynomials where they are), its radii at the
    ends, and on an advancing piece the steps' ends and radii (for the attachment times) and the split radii."""

    def __init__(self, t0: float, t1: float, dense) -> None:
        self.t0, self.t1 = float(t0), float(t1)
        self.solution = step_polynomials(dense)
        self.a0, self.a1 = (float(self.solution(time)[0]) for time in (self.t0, self.t1))
        self.advancing = self.a1 > self.a0
        self.moving = self.a1 != self.a0 and self.t1 > self.t0
        self.split_times, self.split_radii = np.empty(0), np.empty(0)
        if self.advancing:
            steps = getattr(self.solution, "ts", np.array([self.t0, self.t1]))
            self.steps = np.clip(np.asarray(steps, dtype=float), self.t0, self.t1)
            self.step_radii = np.maximum.accumulate(self.solution(self.steps)[0])
            self._splits()

    def radii(self, times: np.ndarray) -> np.ndarray:
        """The radius at ``times`` within the piece: its ends' radii bound it (the steps' polynomials may overshoot
        an end by the solver's error where the edge stops: a spring beyond the end radius would match no attachment)."""
        if not self.moving:
            return np.full(times.shape, self.a0)
        return np.clip(self.solution(times)[0], min(self.a0, self.a1), max(self.a0, self.a1))

    def _splits(self) -> None:
        """The step ends inside the piece where the mean speed of the step after it differs from that after the last
        split by more than :data:`SPEED_RATIO` (either way)."""
        width, rise = np.diff(self.steps), np.diff(self.step_radii)
        speed = np.where(width > 0.0, rise / np.where(width > 0.0, width, 1.0), 0.0)
        keep, last = [], None
        for k in range(1, len(speed)):  # (step ends 1 … n−1: inside the piece, never its ends)
            if not speed[k] > 0.0 or not self.a0 < self.step_radii[k] < self.a1:
                continue
            if last is None or not speed[k] <= SPEED_RATIO * last or not speed[k] * SPEED_RATIO >= last:
                keep.append(k)
                last = speed[k]
        self.split_times, self.split_radii = self.steps[keep], self.step_radii[keep]

    def attach_times(self, xi: np.ndarray) -> np.ndarray:
        """The first time the radius reaches each ``xi`` (within ``(a0, a1]``): the step bracketing it by the steps'
        radii, then safeguarded Newton steps on its polynomial from the chord's time (bisection where Newton's would
        leave the bracket), each stopping once Newton's step is within :data:`SETTLED_ULPS` ulp."""
        after = np.clip(np.searchsorted(self.step_radii, xi, side="left"), 1, len(self.steps) - 1)
        low, high = self.steps[after - 1], self.steps[after]
        r_low, r_high = self.step_radii[after - 1], self.step_radii[after]
        share = np.where(r_high > r_low, (xi - r_low) / np.where(r_high > r_low, r_high - r_low, 1.0), 1.0)
        t = low + np.clip(share, 0.0, 1.0) * (high - low)
        if not isinstance(self.solution, StepPolynomials):
            return _bisect_radius(self.solution, low, high, xi)
        step = np.clip(after - 1, 0, len(self.solution.origins) - 1)
        settled = np.zeros(t.shape, dtype=bool)
        for _ in range(REACH_STEPS):
            value, slope = self.solution._value_and_slope(t, step)
            above = value >= xi
            high, low = np.where(above, t, high), np.where(above, low, t)
            with np.errstate(divide="ignore", invalid="ignore"):
                newton = t - (value - xi) / slope
            settled |= np.abs(newton - t) <= SETTLED_ULPS * np.spacing(np.abs(t))  # (Newton's own step: converged)
            moved = np.where((newton > low) & (newton < high), newton, 0.5 * (low + high))
            t = np.where(settled, t, moved)
            if np.all(settled):
                break
        return t


def _bisect_radius(solution, low: np.ndarray, high: np.ndarray, xi: np.ndarray) -> np.ndarray:
    """The least time in ``[low, high]`` at which a non-decreasing radius reaches ``xi`` (elementwise), by 64
    halvings (a dense output that is not the steps' polynomials)."""
    for _ in range(REACH_STEPS):
        middle = 0.5 * (low + high)
        above = solution(middle)[0] >= xi
        high, low = np.where(above, middle, high), np.where(above, low, middle)
    return high


class RateHistory:
    """The radius of a contact under a rate-dependent adhesion law (module docstring), as
    :class:`~.play_springs.PlaySprings` reads a history: ``radii``, ``pieces``, ``jumps``, ``attach`` and ``breaks``.

    Parameters
    ----------
    edge : EdgeRun
        The radius along the path (:func:`~mdr_events.models.continuum.rate_edge.solve_edge`).
    """

    def __init__(self, edge: EdgeRun) -> None:
        if not isinstance(edge, EdgeRun):
            raise TypeError(f"edge={edge!r} ({type(edge).__name__}) is not allowed; allowed: an EdgeRun (solve_edge)")
        self.edge = edge
        #: whether springs in contact can be in tension (yes: the adhesive annulus)
        self.adhesive = True
        ends = {event.time for event in edge.events if event.kind is EdgeEventKind.CONTACT_ENDS}
        #: ``(time, radius before, radius after)`` where the radius jumps: in at each contact's start, off at its end
        self.jumps: list[tuple[float, float, float]] = []
        self._pieces: list[_Piece] = []
        ended = True
        for t0, t1, _, dense in edge.pieces:
            piece = _Piece(t0, t1, dense)
            if ended:
                self.jumps.append((piece.t0, 0.0, piece.a0))
            self._pieces.append(piece)
            ended = t1 in ends
            if ended:
                self.jumps.append((piece.t1, piece.a1, 0.0))

    def radii(self, times) -> np.ndarray:
        """``a(t)`` (m) at ``times`` (s, path clock; the later piece's at a common end), 0 out of contact.

        Parameters
        ----------
        times : array_like
            The times.

        Returns
        -------
        numpy.ndarray
            The radii, the shape of ``times``.
        """
        times = np.asarray(times, dtype=float)
        out = np.zeros(times.shape)
        for piece in self._pieces:
            inside = (times >= piece.t0) & (times <= piece.t1)
            if np.any(inside):
                out[inside] = piece.radii(times[inside])
        return out

    def pieces(self) -> list[tuple[float, float]]:
        """The pieces on which the radius moves (advancing or receding).

        Returns
        -------
        list of tuple of float
            Their ``(start, end)`` (s, path clock).
        """
        return [(piece.t0, piece.t1) for piece in self._pieces if piece.moving]

    def attach(self, xi: np.ndarray, t) -> tuple[np.ndarray, np.ndarray]:
        """The last time up to ``t`` (one time, or one per spring) at which each spring attached, and where (a code: ``2 k`` the ``k``-th jump-in,
        ``2 k + 1`` the ``k``-th piece; −2 never).

        Parameters
        ----------
        xi : numpy.ndarray
            The springs' coordinates (m).
        t : float or numpy.ndarray
            The time (s, path clock), or one per spring.

        Returns
        -------
        tuple of numpy.ndarray
            The times (``-inf`` never) and the codes.
        """
        xi = np.asarray(xi, dtype=float)
        t = np.broadcast_to(np.asarray(t, dtype=float), xi.shape)
        latest = float(np.max(t, initial=-np.inf))
        when, code = np.full(xi.shape, -np.inf), np.full(xi.shape, -2)
        for index, (time, before, after) in enumerate(self.jumps):
            take = ((xi > before) | ((before == 0.0) & (xi == 0.0))) & (xi <= after) & (time <= t)  # (0: the centre too)
            when[take], code[take] = time, 2 * index
        for index, piece in enumerate(self._pieces):
            if not piece.advancing or piece.t0 > latest:
                continue
            # (from the previous piece's end where the next starts an ulp above it: its own polynomial's start)
            below = min(piece.a0, self._pieces[index - 1].a1) if index else piece.a0
            rows = np.flatnonzero((xi > below) & (xi <= piece.a1))
            if not rows.size:
                continue
            at = piece.attach_times(xi[rows])
            late = (at <= t[rows]) & (at >= when[rows])
            when[rows[late]], code[rows[late]] = at[late], 2 * index + 1
        return when, code

    def breaks(self, t: float) -> np.ndarray:
        """The radii below ``a(t)`` at which the force's quadrature splits its panels (module docstring): those of the
        advancing pieces before ``t`` where the attachment's speed changed by :data:`SPEED_RATIO`.

        Parameters
        ----------
        t : float
            The time (s, path clock).

        Returns
        -------
        numpy.ndarray
            The radii (m), increasing.
        """
        a = float(self.radii(np.array([t]))[0])
        found = [piece.split_radii[(piece.split_times <= t) & (piece.split_radii < a)] for piece in self._pieces
                 if piece.advancing and piece.t0 <= t]
        return np.unique(np.concatenate(found)) if found else np.empty(0)
