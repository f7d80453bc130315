"""The sliding fraction at a flat face's first touch: the sample at the first contact (``t = 0``) where the depth is 0
and the contact radius already the face's (``a > 0``).

There every spring's compression ``d − g(ξ) = 0`` and its shift ``x − x_c = 0``: Coulomb's cap ``κ (d − g)`` and the
level are both 0, and the sliding fraction is 0/0 (the springs' own reading gives ``nan`` on a layer, a tie read as
sliding on the half-space, whatever the path). Its value is the limit as the contact starts (``t → 0+``), the one the
samples after it approach:

- with ``τ0``'s part (``K > 0``) every spring's cap is at least ``ū(a) > 0`` while its level ``|x − x_c| → 0``: every
  spring sticks, the fraction is 0;
- with Coulomb's part alone (``K = 0``), on the first path segment ``x − x_c`` and ``d`` are ``v_x t`` and
  ``v_d t``, and every spring's cap ``κ(ξ) d`` and level are of degree one in ``t`` (``g = 0`` under the face, the
  radius constant): which springs stick and which slide does not change along the segment, so the fraction is the
  one the run gives anywhere on it, read at the segment's middle (:func:`first_segment_middle`).

The route that reads the springs (the spans' anchor maps, :func:`~.solution.evaluate`; every spring's play operator,
:mod:`.play_run`) gives that value; this module says where and which.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from mdr_events.theory.kinds import theory_of

__all__ = ["first_touch_rows", "first_touch_fraction", "first_segment_middle"]


def first_touch_rows(profile, times: np.ndarray, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """The samples at a flat face's first touch: at the first contact (``times == 0``, s from first contact), the
    depth 0 and the radius > 0, on an indenter with a flat face (every other indenter's radius is 0 there).

    Parameters
    ----------
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter.
    times, depth, radius : numpy.ndarray
        The samples' times (s from first contact), depths and contact radii (m).

    Returns
    -------
    numpy.ndarray of bool
        Which samples.
    """
    times = np.asarray(times, dtype=float)
    if not theory_of(profile).flat_face:
        return np.zeros(times.shape, dtype=bool)
    return (times == 0.0) & (np.asarray(depth) == 0.0) & (np.asarray(radius) > 0.0)


def first_touch_fraction(tau0_cap: float, along_first_segment: Callable[[], float]) -> float:
    """The sliding fraction at a flat face's first touch, its limit as the contact starts (module docstring).

    Parameters
    ----------
    tau0_cap : float
        ``K``, the cap per radius of ``τ0``'s part (0 with Coulomb's part alone).
    along_first_segment : callable
        The run's sliding fraction at a time inside the first path segment in contact (called only for ``K = 0``).

    Returns
    -------
    float
        0 with ``τ0``'s part, else the fraction along the first segment.
    """
    return 0.0 if tau0_cap > 0.0 else float(along_first_segment())


def first_segment_middle(solution) -> float:
    """The middle of the path segment in contact at the first contact (s from first contact).

    Parameters
    ----------
    solution : PathSolution
        The run: its span holding the first contact gives the segment (its ``t1`` on the path's clock).

    Returns
    -------
    float
        ``(t1 − t_contact) / 2``.
    """
    segment = solution.spans[int(solution.span_index(np.zeros(1))[0])].segment
    return 0.5 * (segment.t1 - solution.t_contact)
