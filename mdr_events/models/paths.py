"""Indenter trajectories as data: straight segments in the (x, d) plane.

A :class:`Path` is a list of waypoints ``(x, d)`` (tangential position and
indentation depth, metres) joined by straight segments traversed at the
constant speed ``v``. The paper's scenarios are constructors on it:

- :meth:`Path.scenario_A`, eq. (14): in at angle α to ``d_max``, then out
  vertically;
- :meth:`Path.scenario_B`, eq. (19): in vertically to ``d_max``, then out at
  angle α;
- :meth:`Path.scenario_B_indentation`: the "+" branch of Fig. 9b, in
  vertically to ``d_max``, further in at angle α, then out vertically.

Every constructor ends the path below the jump-off depth of the ``Δγ1``
branch, so that the contact certainly comes apart before the path ends.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from mdr_events.theory import analytic
from mdr_events.parameters import Parameters, check_parameters
from mdr_events.models import indenters
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.validation import check_real, real_array, shown, validate_alpha

__all__ = ["Path", "exit_depth"]


#: The scenarios' paths come out to below the jump-off of the Δγ1 branch; it may lie at most this many
#: ``d_max`` below the surface (the path's segments must stay within 1e12 of each other in length).
MAX_JUMP_OFF_DEPTHS = 1e6


def exit_depth(params: Parameters, profile: SimulatedProfile = None) -> float:
    """A depth safely below the displacement-controlled jump-off of the ``Δγ1`` branch (of ``profile``:
    ``None`` is the paper's paraboloid).

    Raises ``ValueError`` naming the parameters if the jump-off lies more than
    :data:`MAX_JUMP_OFF_DEPTHS` ``d_max`` below the surface (adhesion so strong against the stiffness,
    e.g. ``E = 1e-300`` Pa, that the way out would be 1e199 m long).
    """
    jump = indenters.jump_off(params, params.dgamma1, profile)["depth"] if params.dgamma1 > 0 else 0.0
    if not -jump <= MAX_JUMP_OFF_DEPTHS * params.d_max:
        indenter = f"R={params.R!r} m" if profile is None else f"profile={profile!r}"
        raise ValueError(
            f"E={params.E!r} Pa, nu={params.nu!r}, {indenter} and dgamma1={params.dgamma1!r} J/m² put the "
            f"jump-off of the Δγ1 branch at d = {jump:.3g} m, {-jump / params.d_max:.3g} d_max below the surface; "
            f"allowed: at most {MAX_JUMP_OFF_DEPTHS:.0e} d_max (a stiffer elastomer, a smaller dgamma1 or a "
            "larger d_max)")
    return 1.5 * jump - 0.05 * params.d_max


def _check_angle(alpha: float) -> float:
    values = validate_alpha(alpha)
    if values.ndim != 0:
        raise TypeError(f"alpha={shown(alpha)} is not allowed; allowed: one angle in degrees (a path takes one)")
    angle = float(values)
    if angle > 0.0 and math.tan(math.radians(angle)) == 0.0:  # (5e-324°: its radians underflow to 0)
        raise ValueError(f"alpha={shown(alpha)} (degrees) is not allowed: its tangent underflows to 0 in double precision; "
                         "allowed: 0, or an angle whose path stays finite (see the path's extent limit)")
    return angle


def _read_only(array: np.ndarray) -> np.ndarray:
    """``array``, made read-only (what a path keeps and hands out)."""
    array.setflags(write=False)
    return array


#: The shortest segment a path may have, as a share of its longest.
MIN_SEGMENT_SHARE = 1e-12


@dataclass(frozen=True)
class Path:
    """Straight segments through ``waypoints`` (``(x, d)`` pairs, m) at speed ``speed`` (m/s).

    Parameters
    ----------
    waypoints : array_like, shape (n, 2)
        ``(x, d)`` of each corner; ``d > 0`` is into the elastomer. At least
        two points, all finite, consecutive points distinct.
    speed : float
        Speed along the path, > 0.
    alpha : float
        The path angle in degrees, for the paper's scenarios (``nan`` for a
        custom path); only a label.
    """

    waypoints: np.ndarray
    speed: float
    alpha: float = math.nan

    def __post_init__(self) -> None:
        allowed = "at least two (x, d) pairs of finite real numbers (m), shape (n >= 2, 2)"
        points = real_array("waypoints", self.waypoints, allowed)
        if points.ndim != 2 or points.shape[1] != 2 or points.shape[0] < 2:
            raise ValueError(f"waypoints of shape {points.shape} are not allowed; allowed: {allowed}")
        if not np.all(np.isfinite(points)):
            raise ValueError(f"waypoints={shown(self.waypoints)} is not allowed; allowed: {allowed}")
        lengths = np.hypot(*np.diff(points, axis=0).T)
        if np.any(lengths == 0.0):  # (round twenty: "waypoints 0 and 1 coincide; consecutive waypoints must differ"
            # named neither the value nor, in the package's words, what is allowed)
            index = int(np.argmin(lengths))
            raise ValueError(f"waypoints[{index + 1}]={shown(tuple(float(v) for v in points[index + 1]))} is not "
                             f"allowed: it coincides with waypoints[{index}], a segment of length 0 (no direction); "
                             "allowed: consecutive waypoints that differ")
        if np.any(lengths < MIN_SEGMENT_SHARE * lengths.max()):
            index = int(np.argmin(lengths))
            raise ValueError(f"waypoints {index} and {index + 1} are {lengths[index]:.3g} m apart; allowed: at least "
                             f"{MIN_SEGMENT_SHARE:g} of the longest segment ({lengths.max():.3g} m), below which a "
                             "segment's direction is lost to rounding")
        speed = check_real("speed", self.speed, "a finite number > 0 (m/s)", lambda value: value > 0)
        object.__setattr__(self, "speed", speed)
        points.setflags(write=False)
        object.__setattr__(self, "waypoints", points)

    # ------------------------------------------------------------------
    @classmethod
    def from_segments(cls, segments, speed: float, tolerance: float = 1e-12) -> "Path":
        """A path from straight segments ``[((x0, d0), (x1, d1)), ...]`` that must connect.

        Each segment must start where the previous one ended (to ``tolerance``
        m); otherwise ``ValueError`` names the segments and the gap.

        Parameters
        ----------
        segments : array_like, shape (n, 2, 2)
            The segments' end points ``((x0, d0), (x1, d1))`` in m, ``n >= 1``.
        speed : float
            Speed along the path (m/s), > 0.
        tolerance : float, default 1e-12
            The largest gap (m) between a segment's end and the next one's start.

        Returns
        -------
        Path
            The path through the segments' starts and the last segment's end.

        Raises
        ------
        ValueError
            Segments of another shape, or two consecutive segments that do not connect.
        """
        pieces = np.array(segments, dtype=float)
        if pieces.ndim != 3 or pieces.shape[1:] != (2, 2) or pieces.shape[0] < 1:
            raise ValueError(f"segments of shape {pieces.shape} are not allowed; allowed: "
                             "(n >= 1, 2, 2): pairs of (x, d) end points")
        gaps = np.hypot(*(pieces[1:, 0] - pieces[:-1, 1]).T)
        if np.any(gaps > tolerance):
            index = int(np.argmax(gaps > tolerance))
            raise ValueError(f"segments {index} and {index + 1} do not connect: segment {index} ends at "
                             f"{tuple(pieces[index, 1].tolist())} but segment {index + 1} starts at "
                             f"{tuple(pieces[index + 1, 0].tolist())} "
                             f"(gap {gaps[index]:.3g} m); allowed: a gap <= {tolerance:g} m")
        return cls(np.vstack([pieces[:, 0], pieces[-1:, 1]]), speed)

    @classmethod
    def scenario_A(cls, alpha: float, params: Parameters, profile: SimulatedProfile = None) -> "Path":
        r"""Eq. (14): in at angle α from the surface to ``d_max``, then vertically out.

        .. math:: d = v t \sin\alpha, \quad x = v t \cos\alpha \quad (d \le d_\mathrm{max}); \qquad
                  \text{then } v_z = -v,\ v_x = 0 \qquad (14)

        Parameters
        ----------
        alpha : float
            The path angle to the surface in degrees, in (0, 90].
        params : Parameters
            The contact's values: ``d_max`` the turning depth, ``v`` the speed, the rest sizes the way out.
        profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
            The indenter; ``None``: the paraboloid of ``params.R``.

        Returns
        -------
        Path
            Waypoints ``(0, 0)``, ``(d_max / tan α, d_max)`` and, straight up, a depth below the jump-off of the
            ``Δγ1`` branch (:func:`exit_depth`).

        Raises
        ------
        ValueError
            ``alpha`` not in (0, 90], or a jump-off too far below the surface.
        """
        check_parameters(params)
        angle = _check_angle(alpha)
        if angle == 0.0:
            raise ValueError("alpha=0.0 in scenario A: a path parallel to the surface never reaches d_max; "
                             "allowed: 0 < alpha <= 90")
        x1 = 0.0 if angle == 90.0 else params.d_max / math.tan(math.radians(angle))
        return cls([(0.0, 0.0), (x1, params.d_max), (x1, exit_depth(params, profile))], params.v, angle)

    @classmethod
    def scenario_B(cls, alpha: float, params: Parameters, slide_length: float | None = None,
                   profile: SimulatedProfile = None) -> "Path":
        r"""Eq. (19): vertically to ``d_max``, then out at angle α below the jump-off depth.

        .. math:: d = d_\mathrm{max} - v \tilde t \sin\alpha, \quad x = v \tilde t \cos\alpha \qquad (19)

        (``t̃`` from the end of the vertical stroke). At α = 0 the motion is purely tangential at ``d_max`` and
        never comes out: it then ends after ``slide_length`` (default: four times the critical shift ``ū`` of the
        contact at ``d_max``).

        Parameters
        ----------
        alpha : float
            The path angle to the surface in degrees, in [0, 90].
        params : Parameters
            The contact's values: ``d_max`` the turning depth, ``v`` the speed, the rest sizes the way out.
        slide_length : float, optional
            At α = 0 only: the tangential travel at ``d_max`` (m).
        profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
            The indenter; ``None``: the paraboloid of ``params.R``.

        Returns
        -------
        Path
            Waypoints ``(0, 0)``, ``(0, d_max)`` and the end at angle α, a depth below the jump-off of the ``Δγ1``
            branch (:func:`exit_depth`).

        Raises
        ------
        ValueError
            ``alpha`` out of [0, 90], or a jump-off too far below the surface.
        """
        check_parameters(params)
        angle = _check_angle(alpha)
        end = exit_depth(params, profile)
        if angle == 0.0:
            if slide_length is None:
                radius = indenters.branch_radius(params.d_max, params, params.dgamma0, profile)
                slide_length = 4.0 * float(analytic.critical_shift(radius, params))
                if slide_length == 0.0:
                    slide_length = params.d_max
            return cls([(0.0, 0.0), (0.0, params.d_max), (slide_length, params.d_max)], params.v, angle)
        x2 = 0.0 if angle == 90.0 else (params.d_max - end) / math.tan(math.radians(angle))
        return cls([(0.0, 0.0), (0.0, params.d_max), (x2, end)], params.v, angle)

    @classmethod
    def scenario_B_indentation(cls, alpha: float, params: Parameters, final_depth: float | None = None,
                               profile: SimulatedProfile = None) -> "Path":
        """The "+" branch of Fig. 9b: vertically to ``d_max``, further in at angle α to
        ``final_depth`` (default ``2 d_max``), then vertically out.

        Parameters
        ----------
        alpha : float
            The path angle to the surface in degrees, in (0, 90].
        params : Parameters
            The contact's values: ``d_max`` the turning depth, ``v`` the speed, the rest sizes the way out.
        final_depth : float, optional
            The deepest point (m), > ``d_max``; default ``2 d_max``.
        profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
            The indenter; ``None``: the paraboloid of ``params.R``.

        Returns
        -------
        Path
            Waypoints ``(0, 0)``, ``(0, d_max)``, ``((final_depth − d_max) / tan α, final_depth)`` and, straight
            up, a depth below the jump-off of the ``Δγ1`` branch.

        Raises
        ------
        ValueError
            ``alpha`` not in (0, 90], or ``final_depth`` not beyond ``d_max``.
        """
        check_parameters(params)
        angle = _check_angle(alpha)
        final = analytic.arguments.final_depth_of(params, final_depth)
        if angle == 0.0:
            raise ValueError("alpha=0.0: a path parallel to the surface never goes deeper than d_max; "
                             "allowed: 0 < alpha <= 90")
        x2 = 0.0 if angle == 90.0 else (final - params.d_max) / math.tan(math.radians(angle))
        return cls([(0.0, 0.0), (0.0, params.d_max), (x2, final), (x2, exit_depth(params, profile))], params.v,
                   angle)

    # ------------------------------------------------------------------
    # (a path is immutable: what it is asked again and again, by a run's set-up, its solve and its sampling, is
    # computed once and kept on it, its arrays read-only)
    @functools.cached_property
    def segment_lengths(self) -> np.ndarray:
        """The length of each segment (m), one fewer than the waypoints (read-only)."""
        return _read_only(np.hypot(*np.diff(self.waypoints, axis=0).T))

    @functools.cached_property
    def corner_times(self) -> np.ndarray:
        """Times at the waypoints (s), starting at 0 (read-only)."""
        return _read_only(np.concatenate([[0.0], np.cumsum(self.segment_lengths) / self.speed]))

    @functools.cached_property
    def duration(self) -> float:
        """The time from the first waypoint to the last at :attr:`speed` (s)."""
        return float(self.corner_times[-1])

    @property
    def max_depth(self) -> float:
        """The deepest waypoint's depth ``d`` (m)."""
        return float(self.waypoints[:, 1].max())

    def position(self, time) -> tuple[np.ndarray, np.ndarray]:
        """``(x, d)`` at the given times (s, clipped to the path), vectorised.

        Parameters
        ----------
        time : float or array_like
            Times in s from the path's start; those before 0 or after :attr:`duration` are clipped.

        Returns
        -------
        x : numpy.ndarray
            The tangential position (m), the shape of ``time``.
        d : numpy.ndarray
            The depth (m), the shape of ``time``.
        """
        t = np.clip(np.asarray(time, dtype=float), 0.0, self.duration)
        corners = self.corner_times
        x = np.interp(t, corners, self.waypoints[:, 0])
        d = np.interp(t, corners, self.waypoints[:, 1])
        return x, d

    def entry_times(self) -> np.ndarray:
        """The times at which the indenter enters the elastomer.

        The indenter enters where the path starts inside (``d > 0`` at the
        first waypoint) or reaches ``d >= 0`` while moving in (``d``
        increasing); a path that only touches the surface (``d = 0`` at a
        corner, then back out) does not enter there. After an entry the
        indenter is inside until the path reaches ``d <= 0`` again; only then
        can it enter once more. A path that comes out to exactly ``d = 0`` at
        a corner and goes back in leaves and re-enters at that corner.

        Returns
        -------
        numpy.ndarray
            Entry times in s from the path's start, increasing; empty if the
            path never enters the elastomer. The first is
            :meth:`first_contact_time`. Read-only (kept on the path).
        """
        return self._entries

    @functools.cached_property
    def _entries(self) -> np.ndarray:
        """:meth:`entry_times`, computed once."""
        depths = self.waypoints[:, 1]
        corners = self.corner_times
        entries: list[float] = []
        inside = False
        for i in range(len(depths) - 1):
            start, end = depths[i], depths[i + 1]
            if not inside:
                if start > 0.0:  # only at the first waypoint: every later one outside has d <= 0
                    entries.append(float(corners[i]))
                    inside = True
                elif end >= 0.0 and end > start:  # reaches the surface on this segment, moving in
                    if end == 0.0 and (i + 2 == len(depths) or depths[i + 2] <= 0.0):
                        continue  # touches the surface and turns back
                    fraction = -start / (end - start)
                    entries.append(float(corners[i] + fraction * (corners[i + 1] - corners[i])))
                    inside = True
                    continue  # ends inside, or at the surface with the next segment going in
            if inside and end <= 0.0:  # leaves the elastomer on this segment
                inside = False
        return _read_only(np.array(entries, dtype=float))

    def first_contact_time(self) -> float:
        """The first time at which the indenter is in the elastomer or enters it (``d >= 0``, moving in).

        The first of :meth:`entry_times`: a path that only touches the surface (``d = 0`` at a
        corner, then back out) does not make contact there.

        Returns
        -------
        float
            The time in s from the path's start.

        Raises
        ------
        ValueError
            If the path never enters the elastomer.
        """
        entries = self.entry_times()
        if entries.size == 0:
            raise ValueError("the path never enters the elastomer (d > 0); there is no contact to simulate")
        return float(entries[0])

    def describe(self) -> str:
        """The waypoints as a netCDF-safe string.

        Returns
        -------
        str
            ``"(x0, d0); (x1, d1); ..."`` in m, to 9 significant digits.
        """
        # (Python's floats: the same digits as NumPy's, formatted a third as long: ~20 us of a custom run's dataset)
        return "; ".join(f"({x:.9g}, {d:.9g})" for x, d in self.waypoints.tolist())
