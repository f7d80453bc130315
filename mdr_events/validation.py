"""Argument checks shared by every layer, with the package's wording of an error.

Every message reads ``name=value is not allowed; allowed: ...``, so that a
user sees the same kind of sentence whichever function rejects the value.
"""

from __future__ import annotations

from typing import Any, Collection

import numpy as np

__all__ = ["check_choice", "check_flag", "validate_alpha"]


def check_choice(name: str, value: Any, allowed: Collection) -> None:
    """Raise ``ValueError`` unless ``value`` is one of ``allowed``.

    Parameters
    ----------
    name : str
        The argument's name, as the user wrote it.
    value : object
        The value given.
    allowed : collection
        The allowed values, listed (as their ``repr``) in the message.
    """
    if value not in allowed:
        raise ValueError(f"{name}={value!r} is not allowed; allowed: {', '.join(map(repr, allowed))}")


def check_flag(name: str, value: Any) -> None:
    """Raise ``TypeError`` unless ``value`` is a bool (Python's or NumPy's)."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}={value!r} is not allowed; allowed: True or False")


def validate_alpha(alpha) -> np.ndarray:
    """Path angles in degrees as a float array, every entry finite and in [0, 90].

    Parameters
    ----------
    alpha : array_like
        One angle or an array of angles in degrees.

    Returns
    -------
    numpy.ndarray
        ``alpha`` as floats, of the same shape.

    Raises
    ------
    TypeError
        If ``alpha`` is not numeric.
    ValueError
        If an angle is not finite or lies outside [0, 90] (the message names the first).
    """
    try:
        values = np.asarray(alpha, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"alpha={alpha!r} must be a number or an array of numbers in degrees") from None
    bad = ~np.isfinite(values) | (values < 0.0) | (values > 90.0)
    if np.any(bad):
        first = float(values[bad].flat[0])
        raise ValueError(f"alpha={first!r} (degrees) is not allowed; allowed: finite angles in [0, 90]")
    return values
