"""Argument checks shared by every layer, with the package's wording of an error.

Every message reads ``name=value is not allowed; allowed: ...``, so that a
user sees the same kind of sentence whichever function rejects the value.
"""

from __future__ import annotations

import decimal
import functools
import math
import os
import sys
import numbers
from collections.abc import Mapping
from typing import Any, Callable, Collection

import numpy as np

__all__ = ["as_float", "PLAIN_NUMBER", "PLAIN_INTEGER", "plain_number", "number_of", "MAX_COUNT", "SCALE_MAX", "SCALE_MIN", "as_name", "check_choice", "check_flag", "check_real", "check_count", "real_array", "shown", "shown_text", "shown_path", "PATH_CHARACTERS", "cut_text", "validate_alpha", "check_callback", "reads_attrs", "allowed_bound"]

#: Characters of a value's ``repr`` shown in a message (a long list or a file's content is cut).
SHOWN_CHARACTERS = 80


def cut_text(text: str, characters: int = SHOWN_CHARACTERS) -> str:
    """``text`` as a message shows it: whole if it has at most ``characters`` characters, else its first
    ``characters - 3`` and ``...`` (``characters`` in all): the one cut of every long value, name or list a message
    writes (:func:`shown`, :func:`shown_text`, a file's columns listed, the parser's words)."""
    return text if len(text) <= characters else text[: characters - 3] + "..."


def shown(value: Any) -> str:
    """``repr(value)`` on one line (an array's rows joined by single spaces), cut to :data:`SHOWN_CHARACTERS`
    characters, for a message. A list or tuple longer than that is shown by its first items (each item's ``repr``
    takes a character at least, so the cut text is the same), not written out whole (a million times' ``repr``:
    20 MB and a second, for 80 characters)."""
    if isinstance(value, (list, tuple)) and len(value) > SHOWN_CHARACTERS:
        value = type(value)(value[:SHOWN_CHARACTERS]) if type(value) in (list, tuple) else value[:SHOWN_CHARACTERS]
    return cut_text(" ".join(repr(value).split()))


def _printable(text: str) -> str:
    """``text`` with its control characters written as ``repr`` writes them (one line, no raw escape sequence)."""
    return text if text.isprintable() else "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def shown_text(text: str, characters: int = SHOWN_CHARACTERS) -> str:
    """A name written bare in a message (a table's, a file's stem, a column's): its control characters written as
    ``repr`` writes them, cut to ``characters`` characters (:func:`shown` quotes it: a value, not a name)."""
    return cut_text(_printable(str(text)), characters)


#: Characters of a file's path shown in a message: a deep path is shown whole; a text given where a path goes (a
#: CSV file's content, 40 kB) is cut in its middle.
PATH_CHARACTERS = 200
#: Characters of the start of a path cut by :func:`shown_path` (the rest of :data:`PATH_CHARACTERS` is its end).
PATH_HEAD_CHARACTERS = 60


def shown_path(path: Any, quoted: bool = False) -> str:
    """A file's path as a message names it, on one line: its text (``bytes`` decoded as the file system does) with
    its control characters written as ``repr`` writes them (or, ``quoted``, its ``repr``), and one longer than
    :data:`PATH_CHARACTERS` cut in its middle, its start and its end (the file's name) kept around ``...``."""
    text = os.fsdecode(path) if isinstance(path, (str, bytes, os.PathLike)) else str(path)
    text = repr(text) if quoted else _printable(text)
    if len(text) <= PATH_CHARACTERS:
        return text
    return text[:PATH_HEAD_CHARACTERS] + "..." + text[len(text) - (PATH_CHARACTERS - PATH_HEAD_CHARACTERS - 3):]


#: What a number written as text may be (an option's value, a string of a study file, a CSV cell): :func:`plain_number`.
PLAIN_NUMBER = "a plain decimal number (ASCII digits 0-9, an optional sign, point and exponent, e.g. 20, -1.5, 2e-6)"
#: What an integer written as text may be: :func:`plain_number` of ``int``.
PLAIN_INTEGER = "a plain decimal integer (ASCII digits 0-9, an optional sign, e.g. 2000)"


def plain_number(text: str, kind: type = float) -> float | int:
    """The number a text writes in plain decimal notation: the one rule of every number the user writes as text.

    Python's ``float()`` and ``int()`` also read digit separators (``"1_0"``: 10) and the digits of every script
    (``"２０"``, ``"٢٠"``: 20), which no option, study string or CSV file means; those are refused. ``inf``,
    ``infinity`` and ``nan`` (any case, signed) are read as ``float()`` reads them, for the checks of the value to
    name; surrounding whitespace is ignored.

    Parameters
    ----------
    text : str
        The number as written.
    kind : type, default float
        ``float`` (:data:`PLAIN_NUMBER`) or ``int`` (:data:`PLAIN_INTEGER`: no point, no exponent).

    Returns
    -------
    float or int
        Its value, of ``kind``.

    Raises
    ------
    ValueError
        If ``text`` is not a plain decimal number of ``kind`` (the message names it and what is allowed).
    """
    try:
        if not isinstance(text, str) or not text.isascii() or "_" in text:
            raise ValueError(text)
        return kind(text)
    except ValueError:
        raise ValueError(f"{shown(text)} is not allowed; allowed: "
                         f"{PLAIN_INTEGER if kind is int else PLAIN_NUMBER}") from None


def number_of(value: Any) -> float:
    """A number stored as a value or as text (a file's attribute): :func:`plain_number` of a ``str``, ``float()`` of
    anything else but a bool.

    Parameters
    ----------
    value : Any
        The stored number.

    Returns
    -------
    float
        Its value.

    Raises
    ------
    TypeError
        If ``value`` is a bool or not convertible (``None``, a list, ...).
    ValueError
        If ``value`` is text other than :data:`PLAIN_NUMBER`.
    OverflowError
        If ``value`` is an integer beyond a double.
    """
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{shown(value)} ({type(value).__name__}) is not allowed; allowed: a number")
    return plain_number(value) if isinstance(value, str) else float(value)


def as_float(value: numbers.Real) -> float:
    """A real number as a float; an integer too large for a double (``10**400``) as ``inf``, which every check then
    refuses as not finite (``float()`` raises ``OverflowError`` for it)."""
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def check_real(name: str, value: Any, allowed: str, valid=None, finite: bool = True) -> float:
    """``value`` as a Python float if it is one real number (not a bool, complex or string), finite (unless
    ``finite`` is false: then not nan) and ``valid`` (a predicate on the float) holds; else ``TypeError`` /
    ``ValueError`` naming it.

    NumPy scalars of any real type (``np.float32(2e-6)``, ``np.int64(3)``) are real numbers.
    """
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name}={shown(value)} ({type(value).__name__}) is not allowed; allowed: {allowed}")
    number = as_float(value)
    if math.isinf(number) and not isinstance(value, (float, np.floating)):  # (10**400: no double holds it; not inf)
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: {allowed} (an integer beyond the double "
                         "range is none)")
    if not ((math.isfinite(number) if finite else number == number) and (valid is None or valid(number))):
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: {allowed}")
    return number


#: The largest and smallest magnitude of a scale of a run or of a sample read: the square roots of the largest double
#: and of the smallest normal one, so that a product (or a square) of two stays finite and normal.
SCALE_MAX = math.sqrt(sys.float_info.max)
SCALE_MIN = math.sqrt(sys.float_info.min)
#: The largest count any argument takes (steps, samples, workers): far beyond every resource limit, and exactly a
#: double, so that sizes derived from it stay numbers.
MAX_COUNT = 2**53


#: How many steps of the last digit :func:`allowed_bound` takes at most towards the allowed side (one suffices but for
#: a bound whose check rounds the other way; beyond, the rounded bound is shown as it is).
BOUND_STEPS = 4


def allowed_bound(bound: float, allowed: Callable[[float], bool], upper: bool, digits: int = 6) -> str:
    """A bound of a message's "allowed: ..." in ``digits`` significant digits, rounded towards the allowed side (down
    for an upper bound, up for a lower one) and checked with ``allowed`` (a step of the last digit further while it
    fails): the number a user copies from the message is accepted (round thirty: "dx <= 2.12207e-07 m", rounded
    to nearest from 2.122066e-07, was refused with the same message).

    Parameters
    ----------
    bound : float
        The bound, finite.
    allowed : callable
        Whether a value is accepted (the check the bound comes from).
    upper : bool
        Whether the values allowed are at most ``bound`` (else at least).
    digits : int, default 6
        Significant digits shown.

    Returns
    -------
    str
        The number as ``format(value, f".{digits}g")`` writes it.
    """
    context = decimal.Context(prec=digits, rounding=decimal.ROUND_FLOOR if upper else decimal.ROUND_CEILING)
    value = context.create_decimal(bound)
    for _ in range(BOUND_STEPS):
        if allowed(float(value)):
            break
        value = context.next_minus(value) if upper else context.next_plus(value)
    if not math.isfinite(float(value)):  # (a bound within a digit of the largest double: shown whole)
        return repr(float(bound))
    return format(float(value), f".{digits}g")


def check_count(name: str, value: Any, minimum: int) -> int:
    """``value`` as a Python int if it is an integer (not a bool) ``>= minimum``; else an error naming it."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}={shown(value)} ({type(value).__name__}) is not allowed; "
                        f"allowed: an integer >= {minimum}")
    if value < minimum:
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: an integer >= {minimum}")
    if value > MAX_COUNT:  # (a count beyond any run's reach, e.g. 10**400, which no float holds)
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: an integer >= {minimum} and at most "
                         f"{MAX_COUNT:.0e}")
    return int(value)


#: How a message names the values of a NumPy array that are not real numbers.
_KIND_NAMES = {"b": "bool", "c": "complex", "U": "str", "S": "bytes", "M": "datetime", "m": "timedelta"}


def _holds_a_bool(value) -> bool:
    """Whether a (nested) list or tuple holds a bool (Python's or NumPy's) among its numbers."""
    pending = [value]
    while pending:
        items = pending.pop()
        kinds = set(map(type, items))
        if bool in kinds or np.bool_ in kinds:
            return True
        if list in kinds or tuple in kinds:
            pending.extend(item for item in items if type(item) is list or type(item) is tuple)
    return False


def real_array(name: str, value: Any, allowed: str) -> np.ndarray:
    """``value`` as a float array if every entry is a real number (integers and floats of any width;
    not bools, complex numbers, strings or objects); else ``TypeError`` naming it and ``allowed``. A masked array with
    masked entries is refused too: NumPy would read the values under the mask as if they were given."""
    if isinstance(value, np.ma.MaskedArray) and np.ma.count_masked(value):
        raise TypeError(f"{name} is a masked array with {np.ma.count_masked(value)} of {value.size} entries masked "
                        f"(their values would be read as given); allowed: {allowed}, unmasked (a missing sample as "
                        "nan, where one is allowed: value.filled(np.nan))")
    try:
        array = np.asarray(value)
    except (TypeError, ValueError):  # ragged nesting
        raise TypeError(f"{name}={shown(value)} is not allowed; allowed: {allowed}") from None
    if array.dtype.kind in "iuf" and isinstance(value, (list, tuple)) and _holds_a_bool(value):
        # (NumPy makes [True, 20] integers: the bool was read as the angle 1°, the time 1 s, the coordinate 1 m)
        raise TypeError(f"{name}={shown(value)} (holding a bool) is not allowed; allowed: {allowed}")
    if array.dtype.kind == "O":  # a list mixing Python numbers with NumPy scalars, Fractions, ...
        if not all(isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_)) for v in array.flat):
            raise TypeError(f"{name}={shown(value)} is not allowed; allowed: {allowed}")
        return np.vectorize(as_float, otypes=[float])(array) if array.size else array.astype(float)
    if array.dtype.kind not in "iuf":
        kind = _KIND_NAMES.get(array.dtype.kind, str(array.dtype))
        raise TypeError(f"{name}={shown(value)} (of {kind} values) is not allowed; allowed: {allowed}")
    return array.astype(float)


#: What a grid of output times may be (``Continuum(t=...)``, ``run_continuum(times=...)``).
OUTPUT_TIMES_ALLOWED = "a non-empty, strictly increasing 1-D grid of finite times >= 0 (s)"


def check_output_times(name: str, value: Any) -> np.ndarray:
    """``value`` as a read-only grid of output times (``OUTPUT_TIMES_ALLOWED``); else ``TypeError`` /
    ``ValueError`` naming ``name``."""
    times = real_array(name, value, "a strictly increasing 1-D grid of finite times >= 0 (s)")
    if times.ndim != 1 or times.size == 0 or not np.all(np.isfinite(times)) or times[0] < 0 \
            or np.any(np.diff(times) <= 0):
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: {OUTPUT_TIMES_ALLOWED}")
    times.setflags(write=False)
    return times


def as_name(value: Any) -> Any:
    """``value`` as a name: a 0-d array of text (``np.array("A")``, what indexing a NumPy array of names gives) read as
    its ``str``, and a subclass of ``str`` (``np.str_``, a user's) as the plain ``str`` it spells; anything else as it
    is (refused by the check that reads it)."""
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind == "U":
        return str(value[()])
    return str(value) if isinstance(value, str) else value


def check_choice(name: str, value: Any, allowed: Collection) -> str:
    """The name ``value`` gives (:func:`as_name`) if it is one of ``allowed``, else ``ValueError``.

    Parameters
    ----------
    name : str
        The argument's name, as the user wrote it.
    value : object
        The value given: a ``str`` (or a subclass of it) or a 0-d array of text.
    allowed : collection
        The allowed names, listed (as their ``repr``) in the message.

    Returns
    -------
    str
        The name, a plain ``str`` (what the caller keeps and writes in a file's attributes).
    """
    chosen = as_name(value)
    try:  # (an array compared with each name answers with an array, whose truth is ambiguous)
        known = not isinstance(chosen, np.ndarray) and chosen in allowed
    except (TypeError, ValueError):  # (a list or a dict: unhashable, in no set or mapping of names; a DataFrame)
        known = False
    if not known:
        raise ValueError(f"{name}={shown(value)} is not allowed; allowed: {', '.join(map(repr, allowed))}")
    return chosen


def check_flag(name: str, value: Any) -> None:
    """Raise ``TypeError`` unless ``value`` is a bool (Python's or NumPy's)."""
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}={shown(value)} is not allowed; allowed: True or False")


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
    values = real_array("alpha", alpha, "an angle in degrees or an array of them (real numbers, not bools)")
    bad = ~np.isfinite(values) | (values < 0.0) | (values > 90.0)
    if np.any(bad):
        first = float(values[bad].flat[0])
        raise ValueError(f"alpha={first!r} (degrees) is not allowed; allowed: finite angles in [0, 90]")
    return values


def check_callback(name: str, value: Any, called_with: str) -> Any:
    """``value`` if it is ``None`` or callable; else ``TypeError`` naming it and what it is called with."""
    if value is not None and not callable(value):
        raise TypeError(f"{name}={shown(value)} ({type(value).__name__}) is not allowed; allowed: None or a function "
                        f"called with {called_with}")
    return value


def check_distinct(name: str, values, given: Any = None) -> None:
    """Refuse an axis of labels that repeats a value (``ValueError`` naming ``name``, its values as ``given``, else
    ``values``, and the first repeated): each labels one point of a result, whose ``sel`` of a repeated label returned
    two, as ``simulate``'s angles and a sweep's values are refused."""
    labels, counts = np.unique(np.asarray(values, dtype=float), return_counts=True)
    if np.any(counts > 1):
        repeated = float(labels[counts > 1][0])
        raise ValueError(f"{name}={shown(values if given is None else given)} repeats {repeated!r}; allowed: distinct "
                         "values (each labels one point of the result)")


def check_mapping(name: str, value: Any, example: str) -> dict:
    """``value`` as a dict: ``None`` an empty one, a mapping its items; else ``TypeError`` naming ``name``, its value
    and an ``example`` of what is allowed (``dict()`` of a list or a string raised in Python's words)."""
    if value is None:
        return {}
    if not isinstance(value, Mapping):
        raise TypeError(f"{name}={shown(value)} ({type(value).__name__}) is not allowed; allowed: a mapping, "
                        f"e.g. {example}")
    return dict(value)


def reads_attrs(what: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Decorate a reader of a result's attributes (a ``from_attrs``, its last argument ``attrs``), so that what it
    cannot read is named the package's way: ``attrs`` that are not a mapping (or a Dataset) a ``TypeError``; a missing
    attribute, a value that is no number (or overflows a float) or values that describe no valid ``what`` a
    ``ValueError`` naming them, not ``KeyError``, ``AttributeError`` or ``OverflowError``.

    Parameters
    ----------
    what : str
        What the attributes describe, for the messages (e.g. ``"an elastomer"``).

    Returns
    -------
    callable
        The decorator.
    """

    def decorate(reader: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(reader)
        def read(*args: Any) -> Any:
            attrs = args[-1]
            if not isinstance(attrs, Mapping) or hasattr(attrs, "data_vars"):  # (a Dataset maps its variables)
                raise TypeError(f"attrs of type {type(attrs).__name__} are not allowed; allowed: a mapping of a "
                                "result's attributes (dataset.attrs)")
            try:
                return reader(*args)
            except KeyError as error:
                raise ValueError(f"attrs lack the attribute {error.args[0]!r}; allowed: a result's attributes "
                                 f"describing {what}") from None
            except (TypeError, ValueError, OverflowError, AttributeError) as error:
                if isinstance(error, ValueError) and "allowed" in str(error):
                    raise  # (the package's own message, naming the value: Parameters.E=inf is not allowed; ...)
                raise ValueError(f"attrs do not describe {what}: {error}; allowed: a result's attributes describing "
                                 f"{what}") from None
        return read
    return decorate
