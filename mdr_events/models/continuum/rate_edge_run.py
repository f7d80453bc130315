"""What :func:`~mdr_events.models.continuum.rate_edge.solve_edge` returns: the edge's pieces and events, and the
normal force (10) read off them.

An :class:`EdgeRun` holds the radius ``a(t)`` of a rate-dependent adhesion law along a path as pieces (a resting
radius, or a moving edge's dense output) and the events where the edge starts and stops moving and where the contact
ends (:class:`EdgeEvent`, :class:`EdgeEventKind`); it reads the normal force at any time and the pull-off force.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from scipy.optimize import minimize_scalar

from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.models.paths import Path
from mdr_events.validation import check_count, real_array, shown

from .model import ContinuumModel

__all__ = ["EdgeEventKind", "EdgeEvent", "EdgeRun", "normal_force_at"]


#: The samples :meth:`EdgeRun.pull_off_force` brackets the least ``F_N`` with, and the share of their spacing its
#: minimisation resolves the time to (the force's error, flat at its minimum, is of the square of that).
PULL_OFF_SAMPLES = 20001

PULL_OFF_XTOL = 1e-6

#: The fewest samples that bracket the pull-off force (one each side of the least), and the bytes one takes (its time,
#: radius, depth and force, with NumPy's temporaries: counted against ``Limits.memory``).
PULL_OFF_MIN_SAMPLES = 3

PULL_OFF_BYTES_PER_SAMPLE = 128


class EdgeEventKind(str, enum.Enum):
    """What the edge does (values as written to files)."""

    FIRST_CONTACT = "first_contact"
    RE_CONTACT = "re_contact"
    EDGE_STOPS = "edge_stops"          #: the release rate enters the band of rest
    GROWTH_STARTS = "growth_starts"    #: it falls below Δγ0
    RECEDING_STARTS = "receding_starts"  #: it rises above Δγ1
    CONTACT_ENDS = "contact_ends"


class EdgeEvent(NamedTuple):
    """One logged event of the edge.

    Parameters
    ----------
    time : float
        s on the path's clock.
    kind : EdgeEventKind
        What the edge did.
    depth : float
        The indentation depth (m).
    radius : float
        The contact radius (m); at the contact's end, where the integration stopped.
    """

    time: float  #: s on the path's clock
    kind: EdgeEventKind
    depth: float  #: m
    radius: float  #: m (at the contact's end: where the integration stopped, the rest of the collapse unresolved)


@dataclass
class EdgeRun:
    """The radius along a path: one dense output per integrated piece, and the events.

    Parameters
    ----------
    model : ContinuumModel
        The indenter's normal force (10) and branches.
    pieces : list of tuple
        ``(t_start, t_end, segment, solution)``: the radius on ``[t_start, t_end]`` (path clock) is
        ``solution(t)[0]`` (``solve_ivp``'s dense output).
    events : list of EdgeEvent
        What the edge did, in time order.
    """

    model: ContinuumModel
    pieces: list = field(default_factory=list)
    events: list = field(default_factory=list)

    def radius(self, times) -> np.ndarray:
        """The contact radius (m) at ``times`` (s, path clock); 0 out of contact.

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).

        Returns
        -------
        numpy.ndarray
            The radius, the shape of ``times``.
        """
        times = _checked_times(times)
        out = np.zeros(times.shape)
        for t_start, t_end, _, solution in self.pieces:
            inside = (times >= t_start) & (times <= t_end)
            if np.any(inside):
                out[inside] = solution(times[inside])[0]
        return out

    def normal_force(self, times, path: Path) -> np.ndarray:
        """``F_N`` (N, (10)) at ``times`` (s, path clock) of the contact along ``path``.

        Parameters
        ----------
        times : array_like
            The times (s on the path's clock).
        path : Path
            The path the run followed (its depth at ``times``).

        Returns
        -------
        numpy.ndarray
            The normal force, 0 out of contact.
        """
        if not isinstance(path, Path):
            raise TypeError(f"path={shown(path)} ({type(path).__name__}) is not allowed; allowed: the Path the run "
                            "followed")
        times = _checked_times(times)
        return normal_force_at(self.model, path.position(times)[1], self.radius(times))


    def pull_off_force(self, path: Path, samples: int = PULL_OFF_SAMPLES, limits: Limits = DEFAULT_LIMITS) -> float:
        """The least ``F_N`` (N) of the run along ``path``: the least of ``samples`` samples over the path, refined by
        a bounded minimisation between the samples beside it (the minimum is flat: a sample is off by ``F'' δt²``).

        Parameters
        ----------
        path : Path
            The path the run followed.
        samples : int, optional
            The samples the minimum is bracketed with (at least :data:`PULL_OFF_MIN_SAMPLES`).
        limits : Limits, optional
            The resource limits ``samples`` is checked against before the times are allocated.

        Returns
        -------
        float
            The pull-off force (negative: tensile).

        Raises
        ------
        TypeError, ValueError
            A ``samples`` that is not an integer of at least :data:`PULL_OFF_MIN_SAMPLES`, or beyond ``limits``.
        """
        samples = check_count("samples", samples, PULL_OFF_MIN_SAMPLES)
        check_limits(limits).check(f"the pull-off force's {samples} samples", samples=samples,
                                   memory=PULL_OFF_BYTES_PER_SAMPLE * samples)
        times = np.linspace(path.first_contact_time(), path.duration, samples)
        at = int(np.argmin(self.normal_force(times, path)))
        bracket = (times[max(at - 1, 0)], times[min(at + 1, samples - 1)])
        found = minimize_scalar(lambda t: float(self.normal_force(np.array([t]), path)[0]), method="bounded",
                                bounds=bracket, options={"xatol": PULL_OFF_XTOL * (bracket[1] - bracket[0])})
        return float(min(found.fun, np.min(self.normal_force(np.array(bracket), path))))


def normal_force_at(model: ContinuumModel, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """``F_N`` (N, (10)) of the contact of ``radius`` at ``depth`` (elementwise): 0 where the radius is 0 (out of
    contact).

    Parameters
    ----------
    model : ContinuumModel
        The indenter's normal force.
    depth, radius : numpy.ndarray
        The depths and radii (m).

    Returns
    -------
    numpy.ndarray
        The normal force.
    """
    inside = radius > 0
    return np.where(inside, np.asarray(model.normal_force(depth, np.where(inside, radius, 1.0)), dtype=float), 0.0)


def _checked_times(times) -> np.ndarray:
    """``times`` as a float array of finite times (s on the path's clock); else the error naming them."""
    times = real_array("times", times, "finite times in s on the path's clock (real numbers)")
    if not np.all(np.isfinite(times)):
        raise ValueError(f"times={float(times[~np.isfinite(times)].flat[0])!r} is not allowed; allowed: finite times in "
                         "s on the path's clock")
    return times
