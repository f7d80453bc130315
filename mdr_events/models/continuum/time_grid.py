"""A run's times (s from first contact): the output grid of a run of so many samples (:func:`sample_times`) and the
check of the times a solution is asked at (:func:`check_times`)."""

from __future__ import annotations

import numpy as np

from mdr_events.validation import real_array, shown

__all__ = ["sample_times", "check_times"]


def sample_times(ends: list[float], path_ends: list[float], samples: int) -> np.ndarray:
    """The output times of a run of ``samples`` (s from first contact): to the longest run's end and one spacing
    beyond (a sample after the contact has ended), but not beyond its path's end (a run that ended in contact wrote
    every quantity, the depth too, as ``nan`` there).

    Parameters
    ----------
    ends : list of float
        Each case's end (s from its first contact).
    path_ends : list of float
        Each case's path's end (s from its first contact).
    samples : int
        The number of times.

    Returns
    -------
    numpy.ndarray
        The times.
    """
    last = max(min(end * (1.0 + 1.0 / samples), path_end) for end, path_end in zip(ends, path_ends))
    return np.linspace(0.0, last, samples)


def check_times(name: str, times, earliest: float = 0.0) -> np.ndarray:
    """``times`` (s from first contact) as a float array of one dimension at most, every entry finite and from
    ``earliest`` on; else ``TypeError`` or ``ValueError`` naming the argument (a time before the path's start was
    extrapolated to, a string or a 2-D grid was a raw error of NumPy's)."""
    values = real_array(name, times, "times in s from first contact (real numbers)")
    if values.ndim > 1 or not np.all(np.isfinite(values)) or np.any(values < earliest):
        raise ValueError(f"{name}={shown(times)} is not allowed; allowed: one time or a 1-D array of finite times "
                         f">= {earliest:.9g} (s from first contact: the path's start; the solution says nothing "
                         "before it)")
    return values
