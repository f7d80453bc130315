"""What the paraboloid's closed forms are given and give, checked: finite real arguments (lengths and works never
negative), results that fit in double precision (:class:`ResultOverflowError`), a scalar's result as a float.
"""

from __future__ import annotations

from typing import Callable, TypeVar

import numpy as np

from mdr_events.theory import symbolic
from mdr_events.validation import SCALE_MAX, check_real, real_array, shown

__all__ = ["NONNEGATIVE", "ResultOverflowError", "representable_result", "final_depth_of"]

_Result = TypeVar("_Result")


def _rel(key: str):
    return symbolic.relation(key)


#: Arguments of the closed forms that are lengths or works of their physics, never negative (the parameters refuse a
#: negative work of adhesion; a negative radius gave a negative critical shift and a positive pull-off force).
NONNEGATIVE = ("contact_radius", "work_of_adhesion", "amplitude")


def final_depth_of(params, final_depth) -> float:
    """Scenario B+'s deepest point: ``final_depth``, default ``2 d_max`` of ``params``; else ``ValueError`` naming it
    unless a finite depth beyond ``d_max`` (any real number, as :func:`~mdr_events.validation.check_real` reads it:
    ``np.float32``, a 0-d array, a ``Fraction``, as ``Scenario(final_depth=...)`` takes them; an integer beyond a
    double refused, not an ``OverflowError``; a bool refused by its own name)."""
    if final_depth is None:
        return 2.0 * params.d_max
    return check_real("final_depth", final_depth, f"a finite depth > d_max = {params.d_max!r} m",
                      lambda value: value > params.d_max)


def check_work(work_of_adhesion) -> float:
    """``work_of_adhesion`` as a float if it is a number from 0 to ``SCALE_MAX`` (J/m²: its square stays finite);
    else ``TypeError`` (no number: an array or a list of them) or ``ValueError`` naming it (a negative one gave
    ``nan`` and a positive pull-off force). The scalar closed forms' work, here and in
    :mod:`mdr_events.theory.power_law` and :mod:`mdr_events.theory.tabulated`."""
    return check_real("work_of_adhesion", work_of_adhesion, f"a finite number >= 0 (J/m²), at most {SCALE_MAX:.2g}",
                      lambda value: 0.0 <= value <= SCALE_MAX)


def _one_work(work_of_adhesion) -> float:
    """``work_of_adhesion`` of a scalar closed form as a float: checked by :func:`_finite` (its message for a
    negative or non-finite work), then one number (a 0-d array's), else ``TypeError`` naming it (an array or a list
    ended in NumPy's or Python's own error)."""
    _finite(work_of_adhesion=work_of_adhesion)
    if isinstance(work_of_adhesion, np.ndarray) and work_of_adhesion.ndim == 0:
        work_of_adhesion = work_of_adhesion[()]
    return check_work(work_of_adhesion)


def _finite(**arguments) -> list:
    """Refuse an argument with an entry that is no finite real number (``10**400`` read as inf), beyond
    ``±SCALE_MAX`` (its square would overflow) or, of :data:`NONNEGATIVE`, below 0, naming it; the arguments checked,
    in order: a float or a float64 array as given, one other number (an ``int``, ``np.int64``, a 0-d int array) as a
    float, any other (a list, an int array) as the float array it reads (a closed form of ``array_like`` arguments
    computes on those: a list ended in Python's own ``TypeError``, issue 32 round 28 A2; an ``np.int64`` was computed
    in int64 and overflowed silently)."""
    checked = []
    for name, value in arguments.items():
        low = 0.0 if name in NONNEGATIVE else -SCALE_MAX
        if type(value) is float:
            checked.append(value)
            if low <= value <= SCALE_MAX:
                continue
            values = np.asarray(value)
        elif type(value) is np.ndarray and value.dtype == np.float64:  # (as given; float32 and masked arrays below:
            values = value  # float32 compared with the bound overflowed in NumPy's cast, a RuntimeWarning, and was
            checked.append(value)  # computed in float32; a mask was dropped or kept by chance, issue 32 round 30)
        else:
            values = real_array(name, value, "real numbers")
            checked.append(values if np.ndim(value) else float(values))  # (one number: a float, an int's too)
        if not (values.size == 0 or (low <= values.min() and values.max() <= SCALE_MAX)):
            raise ValueError(f"{name}={shown(value)} is not allowed; allowed: finite real numbers "
                             f"{'from 0' if low == 0.0 else f'from {low:.2g}'} to {SCALE_MAX:.2g} (SI units)")
    return checked


class ResultOverflowError(ValueError, OverflowError):
    """A closed form's result overflows double precision for the arguments and parameters given: a ``ValueError``
    (the input asks too much), and an ``OverflowError``, so that :mod:`mdr_events.theory.scales` names the parameter
    scale behind it as it does for math's overflows."""


def representable_result(compute: Callable[[], _Result], function: str, **arguments) -> _Result:
    """The result of a closed form if it fits in double precision, else a refusal naming the arguments.

    The paraboloid's closed forms here and the power law's jump-off (:mod:`mdr_events.theory.power_law.detachment`)
    compute through it.

    Parameters
    ----------
    compute : callable
        The closed form, called once with NumPy's overflow and invalid results silenced (they are read below).
    function : str
        The closed form's name, for the message.
    **arguments
        The arguments it was given, named in the message (``shown``).

    Returns
    -------
    float, numpy.ndarray or dict
        ``compute()`` as it is, if every entry (a dict's values) is finite.

    Raises
    ------
    ResultOverflowError
        An entry is not finite: the arguments' result overflows double precision.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        result = compute()
    if np.all(np.isfinite(list(result.values()) if isinstance(result, dict) else result)):
        return result
    given = ", ".join(f"{name}={shown(value)}" for name, value in arguments.items())
    raise ResultOverflowError(f"{function}({given}) is not allowed: its result overflows double precision; allowed: "
                              "arguments and parameters whose result is a finite number")


def _as_output(values: np.ndarray, like: np.ndarray):
    return float(values) if np.ndim(like) == 0 else values

