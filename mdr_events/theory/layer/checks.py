"""What the layer's relations take and give, checked in one place (issue 32, round twelve).

Every relation of :mod:`mdr_events.theory.layer` and of :mod:`mdr_events.theory.layer_tangential` (round thirteen:
the tangential ones had been left out) checks its arguments by their names before it runs (radii ``a`` and ``r``
finite and ≥ 0, coordinates ``x`` and depths ``d``, ``depth``, ``profile_depth`` finite, ``E_star`` and ``G_star``
> 0, ``dgamma``, ``tau0`` and ``mu`` ≥ 0, ``nu`` in ``[0, 0.5]``, a :class:`~mdr_events.Layer`, a callable slope,
arrays that broadcast) and its result after: a value that is not finite (a product beyond the double range, a slope
of ``nan``) is a one-line ``ValueError`` naming the relation and its scalar arguments, never ``nan``, ``inf`` or a
raw ``ZeroDivisionError``.
"""

from __future__ import annotations

import functools
import inspect
import math

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.compliance import _nu
from mdr_events.validation import check_real, real_array, shown

__all__ = ["finite_reals", "checked_relation"]

#: What each array argument of the relations must be: name -> (what is allowed, the test of its values or None).
_ARGUMENTS = {
    "a": ("finite numbers >= 0 (m)", lambda value: value >= 0.0),
    "x": ("finite numbers (m)", None),
    "r": ("finite numbers >= 0 (m)", lambda value: value >= 0.0),
    "d": ("finite numbers (m)", None),
    "depth": ("finite numbers (m)", None),
    "profile_depth": ("finite numbers (m)", None),
}
#: The scalar arguments of the relations: name -> (what is allowed, the test).
_SCALARS = {
    "E_star": ("a finite number > 0 (Pa)", lambda value: value > 0.0),
    "G_star": ("a finite number > 0 (Pa)", lambda value: value > 0.0),
    "dgamma": ("a finite number >= 0 (J/m²)", lambda value: value >= 0.0),
    "tau0": ("a finite number >= 0 (Pa)", lambda value: value >= 0.0),
    "mu": ("a finite number >= 0", lambda value: value >= 0.0),
}


def finite_reals(name: str, value, allowed: str, valid=None) -> np.ndarray:
    """``value`` as a float array of finite numbers for which ``valid`` holds everywhere, else a one-line
    ``TypeError``/``ValueError`` naming ``name``, the first bad entry and ``allowed``.

    Parameters
    ----------
    name : str
        The argument's name.
    value : float or array_like
        Its value.
    allowed : str
        What is allowed, in words.
    valid : callable or None, optional
        A test of the (finite) values, elementwise.

    Returns
    -------
    numpy.ndarray
        The values as floats.
    """
    array = real_array(name, value, f"{allowed}: a number or an array of numbers")
    bad = ~np.isfinite(array)
    if valid is not None:
        bad |= ~np.where(bad, True, valid(np.where(bad, 0.0, array)))
    if np.any(bad):
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = f"[{', '.join(map(str, index))}]" if array.ndim else ""
        raise ValueError(f"{name}{where}={float(array[index])!r} is not allowed; allowed: {allowed}")
    return array


def _finite_result(name: str, result, **arguments):
    """``result`` if every value of it is finite, else a ``ValueError`` naming the relation and its arguments."""
    values = np.array([getattr(result, field) for field in ("radius", "depth", "force")]) \
        if hasattr(result, "relative_radius") else result
    if not np.all(np.isfinite(values)):
        shown_arguments = ", ".join(f"{key}={shown(value)}" for key, value in arguments.items())
        raise ValueError(f"{name}({shown_arguments}) is not finite (a product left the double range); allowed: "
                         "arguments whose result is a finite double")
    return result


def _check_arguments(function_name: str, given: dict) -> None:
    """Each named argument of a relation, checked (module docstring)."""
    for name, (allowed, valid) in _ARGUMENTS.items():
        if name in given:
            finite_reals(name, given[name], allowed, valid)
    for name, (allowed, valid) in _SCALARS.items():
        if name in given:
            check_real(name, given[name], allowed, valid)
    if "nu" in given:
        _nu(given["nu"])
    if "layer" in given and not isinstance(given["layer"], Layer):
        raise TypeError(f"layer={shown(given['layer'])} ({type(given['layer']).__name__}) is not allowed; allowed: a "
                        "Layer")
    if "profile_slope" in given and not callable(given["profile_slope"]):
        raise TypeError(f"profile_slope={shown(given['profile_slope'])} is not allowed; allowed: a function of an "
                        "array of radii (m), f'(r)")
    shapes = [np.shape(given[name]) for name in _ARGUMENTS if name in given]
    try:
        np.broadcast_shapes(*shapes)
    except ValueError:
        raise ValueError(f"the arrays of {function_name} have the shapes {shapes}, which do not broadcast; allowed: "
                         "arrays of one shape (or numbers)") from None


def checked_relation(function):
    """A relation whose arguments are checked by their names before it runs and whose result is finite after
    (module docstring).

    Parameters
    ----------
    function : callable
        A relation of :mod:`mdr_events.theory.layer`.

    Returns
    -------
    callable
        The same relation, checked.
    """
    signature = inspect.signature(function)

    @functools.wraps(function)
    def checked(*args, **kwargs):
        bound = signature.bind(*args, **kwargs)
        bound.apply_defaults()
        given = bound.arguments
        _check_arguments(function.__name__, given)
        scalars = {name: value for name, value in given.items()
                   if np.ndim(value) == 0 and name not in ("layer", "limits") and not callable(value)}
        try:
            with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
                result = function(*args, **kwargs)
        except (ZeroDivisionError, OverflowError):  # (a scale that underflows to 0 or overflows on the way)
            result = math.nan
        return _finite_result(function.__name__, result, **scalars, layer=given.get("layer"))

    return checked
