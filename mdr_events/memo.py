"""What a run's set-up computes of frozen, validated values, kept for the next run of the same values.

A run checks and builds from values that cannot change once made: :class:`~mdr_events.Parameters`, the indenters and
the friction law are frozen dataclasses validated when made. A fit, a sweep or a benchmark runs the same contact again
and again, and ``simulate``'s set-up (the check of the scales, the scenarios' paths) cost as much as a third of a
paraboloid's solve each time (issue 28). :func:`kept` keeps a function's last results by the exact values of its
arguments (:func:`exact_key`): equal values of another type (``1`` and ``1.0``) or another zero (``-0.0`` and ``0.0``)
are kept apart, so that a kept result is, bit for bit, the one the function computes; arguments with a value that is
not hashable (a table's arrays) are computed each time. An error is never kept: a value refused is refused again, with
the same message.
"""

from __future__ import annotations

import dataclasses
import functools
import weakref
from typing import Any, Callable, TypeVar

__all__ = ["exact_key", "kept", "hashable", "cached"]

_Result = TypeVar("_Result")

#: The types a key holds with their type, ``(type, value)``: their equal values are the same value, and the tag
#: keeps them apart from the equal values of another type (``True == 1 == 1.0``).
_TAGGED = (str, bool, int)


class _Unkeyed(Exception):
    """A value :func:`exact_key` has no key for."""


@functools.cache
def _field_names(kind: type) -> tuple[str, ...] | None:
    """The fields of a frozen dataclass, looked up once per type; ``None`` for one that gives its own key
    (``_memo_key``: a table's digest, made once, instead of a walk over thousands of points)."""
    if hasattr(kind, "_memo_key"):
        return None
    return tuple(field.name for field in dataclasses.fields(kind))


def _exact(value: Any) -> Any:
    """The key of one value (raises :class:`_Unkeyed` for one without).

    A frozen dataclass's key is made once while it lives and kept by its ``id`` (:data:`_KEYS`, :func:`_keep_key`).
    This assumes a frozen dataclass is never changed (``object.__setattr__``) after it is first keyed: every such
    write in the package is made while the value is built, in its ``__post_init__`` or on a value just made by
    ``object.__new__`` (``Paths.named_by``), before anything keys it (``tests/test_memo.py`` checks where they are).
    A value changed so after it was keyed would keep its old key and be taken for the value it was."""
    kind = type(value)
    if kind is float:  # (as it is: every other kind's key is a tuple or None; a zero by its sign)
        return value if value else (kind, repr(value))
    if kind in _TAGGED:
        return kind, value
    if value is None:
        return None
    if kind is tuple:
        return tuple(map(_exact, value))
    params = getattr(kind, "__dataclass_params__", None)
    if params is not None and params.frozen:
        held = _KEYS.get(id(value))
        if held is not None and held[0]() is value:
            return held[1]
        names = _field_names(kind)
        key = (kind, value._memo_key) if names is None else (kind, *(_exact(getattr(value, name)) for name in names))
        _keep_key(value, key)
        return key
    raise _Unkeyed


#: The key of each frozen dataclass :func:`_exact` has met and that is alive, by its ``id`` (with a weak reference to
#: it, which tells a live value from a new one of the same ``id``): a run's Parameters and laws are keyed some six
#: times (a walk over a dozen fields each, a fifth of simulate's front end; issue 28), their values never change.
_KEYS: dict[int, tuple[weakref.ref, tuple]] = {}


def _keep_key(value: Any, key: tuple) -> None:
    """Keep ``key`` as the key of ``value`` while it lives (a value that takes no weak reference is keyed each time)."""
    identity = id(value)

    def forget(reference: weakref.ref) -> None:
        if _KEYS.get(identity, (None,))[0] is reference:  # (not a new value's of the same id)
            _KEYS.pop(identity, None)

    try:
        _KEYS[identity] = (weakref.ref(value, forget), key)
    except TypeError:  # (a dataclass of slots without a weak reference's)
        pass


def exact_key(values: tuple) -> tuple | None:
    """A key of ``values`` that tells apart what ``==`` does not.

    Parameters
    ----------
    values : tuple
        Floats, ints, strings, bools, ``None``, tuples of them and frozen dataclasses of them.

    Returns
    -------
    tuple or None
        Each value with its type (``True``, ``1``, ``1.0`` and ``"1.0"`` apart; a float zero by its sign; a frozen
        dataclass by its type and its fields' keys, or by the key it keeps, ``_memo_key``, if it has one: a table's
        digest), or ``None`` if a value is of another kind (an array, a list, a mutable object): no key.
    """
    try:
        return tuple(map(_exact, values))
    except _Unkeyed:
        return None


class _Call:
    """The arguments of one call, compared and hashed by their exact key."""

    __slots__ = ("key", "args", "hash")

    def __init__(self, key: tuple, args: tuple) -> None:
        self.key, self.args, self.hash = key, args, hash(key)

    def __hash__(self) -> int:
        return self.hash

    def __eq__(self, other: object) -> bool:
        return isinstance(other, _Call) and self.key == other.key


def kept(size: int) -> Callable[[Callable[..., _Result]], Callable[..., _Result]]:
    """A decorator keeping the last ``size`` results of a function of positional arguments by their exact values
    (:func:`exact_key`); a call whose arguments have no key is computed each time, a call that raises is not kept.

    Parameters
    ----------
    size : int
        How many results are kept (the least recently used is dropped).

    Returns
    -------
    callable
        The decorator; the function it gives has ``cache_clear()`` and ``cache_info()`` (``functools.lru_cache``'s).
    """
    def decorate(function: Callable[..., _Result]) -> Callable[..., _Result]:
        by_call = functools.lru_cache(maxsize=size)(lambda call: function(*call.args))

        @functools.wraps(function)
        def run(*args: Any) -> _Result:
            key = exact_key(args)
            return function(*args) if key is None else by_call(_Call(key, args))

        run.cache_clear, run.cache_info = by_call.cache_clear, by_call.cache_info
        return run
    return decorate


def hashable(value: Any) -> bool:
    """Whether ``value`` has a hash (``functools.lru_cache`` can key it): a user's subclass of a frozen dataclass that
    defines ``__eq__`` alone has none (Python sets its ``__hash__`` to ``None``), which a cache of the indenter's
    must compute around instead of ending in ``unhashable type`` (issue 32 round 28 A3).

    Parameters
    ----------
    value : object
        Any value.

    Returns
    -------
    bool
        ``True`` if ``hash(value)`` succeeds.
    """
    try:
        hash(value)
    except TypeError:
        return False
    return True


def cached(size: int) -> Callable[[Callable[..., _Result]], Callable[..., _Result]]:
    """A decorator keeping the last ``size`` results of a function of positional arguments, the one cache of a
    function keyed by an indenter: by the arguments' hash (``functools.lru_cache``) when they have one, else by their
    exact values (:func:`kept`: a user's subclass of an indenter type that defines ``__eq__`` alone has no hash, and
    still gets the cache), else computed each time (issue 32 round 28 A3; the call sites no longer branch).

    Parameters
    ----------
    size : int
        How many results each of the two caches keeps (the least recently used is dropped).

    Returns
    -------
    callable
        The decorator; the function it gives has ``cache_clear()`` (both caches) and ``__wrapped__``.
    """
    def decorate(function: Callable[..., _Result]) -> Callable[..., _Result]:
        by_hash, by_value = functools.lru_cache(maxsize=size)(function), kept(size)(function)

        @functools.wraps(function)
        def run(*args: Any) -> _Result:
            return by_hash(*args) if all(map(hashable, args)) else by_value(*args)

        def cache_clear() -> None:
            by_hash.cache_clear()
            by_value.cache_clear()

        run.cache_clear, run.cache_info = cache_clear, by_hash.cache_info
        return run
    return decorate
