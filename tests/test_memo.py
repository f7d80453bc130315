"""``mdr_events.memo``: results kept by the exact values of frozen arguments, and where ``simulate``'s set-up keeps
them (the check of the scales, the scenarios' paths; issue 28)."""

from __future__ import annotations

import dataclasses
import gc
import hashlib
import weakref

import numpy as np
import pytest

import mdr_events as me
from mdr_events.memo import cached, exact_key, kept
from mdr_events.models import motion
from mdr_events.theory import scales

PAPER = me.Parameters.paper()


def test_an_exact_key_tells_apart_what_equality_does_not():
    """-0.0 and 0.0, 1 and 1.0, a frozen dataclass and another of equal fields but another type: each its own key;
    equal values of the same kinds one key."""
    assert exact_key((0.0,)) != exact_key((-0.0,))
    assert exact_key((1,)) != exact_key((1.0,))
    assert exact_key((True,)) != exact_key((1.0,)) and exact_key((True,)) != exact_key((1,))
    assert exact_key(("0.0",)) != exact_key((0.0,)) and exact_key(("-0.0",)) != exact_key((-0.0,))
    assert exact_key(("1.0",)) != exact_key((1.0,)) and exact_key((None,)) != exact_key(("None",))
    assert exact_key((PAPER.replace(tau0=0.0),)) != exact_key((PAPER.replace(tau0=-0.0),))
    assert exact_key((PAPER, None, "B", (20.0, 30.0))) == exact_key((me.Parameters.paper(), None, "B", (20.0, 30.0)))
    assert exact_key((me.PowerLaw(1e3, 2.0),)) != exact_key((me.FlatPunch(1e3),))


def test_an_exact_key_has_no_key_for_what_may_change():
    """An array, a list or a frozen dataclass holding an array has no key: computed each time. A table holds its
    points as tuples: keyed by every value."""

    @dataclasses.dataclass(frozen=True)
    class Holder:
        values: np.ndarray

    for values in [(np.zeros(3),), ([1.0],), (PAPER, Holder(np.zeros(3)))]:
        assert exact_key(values) is None
    r = np.linspace(0.0, 4e-3, 41)
    table, other = me.TabulatedProfile(r, r**2 / 0.06), me.TabulatedProfile(r, r**2 / 0.0600000001)
    assert exact_key((table,)) == exact_key((me.TabulatedProfile(r, r**2 / 0.06),)) != exact_key((other,))


@dataclasses.dataclass(frozen=True)
class _Pair:
    first: float
    second: float


def test_a_frozen_values_key_is_made_once_while_it_lives_and_never_given_to_another(monkeypatch):
    """A frozen dataclass is keyed once while it lives (its fields walked once: a run's Parameters were walked some six
    times a simulate, a fifth of its front end; issue 28), the same key as walking its fields; a key kept under the
    ``id`` of a value that is gone (its weak reference dead, or another value's) is never given to the value that has
    that ``id`` now, and its entry dies with its value."""
    from mdr_events import memo

    walked = []
    names = memo._field_names
    monkeypatch.setattr(memo, "_field_names", lambda kind: walked.append(kind) or names(kind))
    params = PAPER.replace(tau0=123.0)
    first = exact_key((params, None))
    assert exact_key((params, 1.0)) == (first[0], 1.0) and exact_key((params,)) == first[:1]
    assert walked.count(type(params)) == 1  # (walked once, kept while it lives)
    assert first == exact_key((PAPER.replace(tau0=123.0), None))  # (another value, walked: the same key)
    gone, kept_alive = _Pair(1.0, -1.0), _Pair(2.0, -1.0)
    dead = weakref.ref(gone)
    del gone
    gc.collect()
    assert dead() is None
    for stale in (dead, weakref.ref(kept_alive)):  # (a key left under the id the new value has: forced, no allocator)
        other = _Pair(1.0, 1.0)
        monkeypatch.setitem(memo._KEYS, id(other), (stale, ((_Pair, 1.0, -1.0),)))
        assert exact_key((other,)) == ((_Pair, 1.0, 1.0),)
        assert memo._KEYS[id(other)][0]() is other  # (its own key kept in its place)
        identity = id(other)
        del other
        gc.collect()
        assert identity not in memo._KEYS  # (the entry dies with its value)


#: How many values are made and freed, at most, for one to be given the ``id`` of one freed before it.
ID_REUSE_TRIES = 1000


def test_a_new_value_given_a_freed_values_id_gets_its_own_key():
    """The allocator's own reuse of an ``id`` (CPython gives a freed value's memory to the next value of its size):
    values are made and freed until one is given the ``id`` of the one freed before it (at most
    :data:`ID_REUSE_TRIES`); it gets its own key, never the freed one's. An allocator that never reuses an ``id`` in
    as many tries (``PYTHONMALLOC=malloc``, a debug or free-threaded build may not) leaves nothing to check: skipped."""
    for index in range(ID_REUSE_TRIES):
        pair = _Pair(index + 1.0, -1.0)
        identity, key = id(pair), exact_key((pair,))
        del pair
        other = _Pair(index + 1.0, 1.0)
        assert exact_key((other,)) == ((_Pair, index + 1.0, 1.0),) != key
        if id(other) == identity:
            break
    else:
        pytest.skip(f"no id of a freed value was given to a new one in {ID_REUSE_TRIES} tries: nothing to check")


def test_a_tables_key_is_made_once_whatever_its_points(monkeypatch):
    """A table's key is a digest of its columns made once: a key of 10 000 points reads as few values as one of 3
    (counted: the keys of its parts), the second key digests nothing, and a change of one bit of one point (a zero's
    sign) is another key."""
    from mdr_events import memo

    parts, digests = [], []
    exact, blake2b = memo._exact, hashlib.blake2b
    monkeypatch.setattr(memo, "_exact", lambda value: parts.append(value) or exact(value))
    monkeypatch.setattr(hashlib, "blake2b", lambda *args, **kw: digests.append(args) or blake2b(*args, **kw))
    counts = []
    for points in (3, 10_000):
        r = np.linspace(0.0, 4e-3, points)
        table = me.TabulatedProfile(r, r**2 / 0.06)
        parts.clear()
        assert exact_key((table,)) == exact_key((table,)) == exact_key((me.TabulatedProfile(r, r**2 / 0.06),))
        counts.append(len(parts))
    assert counts[0] == counts[1] and len(digests) == 4  # (two tables of each size, each digested once)
    flipped = me.TabulatedProfile((0.0, 1e-3, 2e-3), (0.0, 1e-6, 4e-6))
    assert exact_key((flipped,)) != exact_key((me.TabulatedProfile((-0.0, 1e-3, 2e-3), (0.0, 1e-6, 4e-6)),))


def test_kept_results_are_computed_once_and_errors_never():
    """A call of the same exact values computes once; a refusal is computed, and raised, every time; a call without
    a key every time."""
    calls = []

    @kept(2)
    def square(value):
        calls.append(value)
        if value < 0:
            raise ValueError(f"value={value!r} is not allowed")
        return value * value

    assert square(3.0) == square(3.0) == 9.0 and calls == [3.0]
    assert square(3) == 9 and type(square(3)) is int and calls == [3.0, 3]  # (an int is not the float)
    for _ in range(2):
        with pytest.raises(ValueError, match=r"value=-1\.0 is not allowed"):
            square(-1.0)
    assert calls == [3.0, 3, -1.0, -1.0]
    assert square(np.float64(2.0)) == 4.0 and square(np.float64(2.0)) == 4.0 and calls[-2:] == [2.0, 2.0]


def test_a_kept_scenario_path_is_the_one_built(monkeypatch):
    """The paths ``simulate`` keeps are those it builds: the same waypoints, speed and angle bit for bit as the
    function unkept, for each scenario; a refused angle is named every time."""
    for name in ("A", "B", "B+"):
        kept_path = motion._scenario_path(name, 20.0, PAPER, None, None)
        built = motion._scenario_path.__wrapped__(name, 20.0, PAPER, None, None)
        assert kept_path is motion._scenario_path(name, 20.0, PAPER, None, None)
        assert kept_path.waypoints.tobytes() == built.waypoints.tobytes()
        assert (kept_path.speed, kept_path.alpha) == (built.speed, built.alpha)
    for _ in range(2):
        with pytest.raises(ValueError, match="alpha=0.0 in scenario A"):
            me.simulate(PAPER, "A", alpha=[0.0], method="continuum")


def test_a_refused_scale_is_refused_every_time():
    """check_representable keeps what it passed, never what it refused: the same message twice."""
    huge = PAPER.replace(E=1e308)
    messages = []
    for _ in range(2):
        with pytest.raises(ValueError, match="E\\* is 1.33e\\+308 Pa") as error:
            scales.check_representable(huge)
        messages.append(str(error.value))
    assert messages[0] == messages[1]


def _writes_to_frozen_values() -> list[tuple[str, int, str, str]]:
    """Each ``object.__setattr__(target, ...)`` in the package: its file, line, function and target."""
    import ast
    import pathlib

    package = pathlib.Path(me.__file__).parent
    writes = []
    for path in sorted(package.rglob("*.py")):
        text = path.read_text()
        if "object.__setattr__" not in text:  # (a cheap filter: the walk below reads what it finds)
            continue
        for function in ast.walk(ast.parse(text)):
            if not isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            made = {target.id for node in ast.walk(function) if isinstance(node, ast.Assign)
                    and ast.unparse(node.value).startswith("object.__new__(") for target in node.targets
                    if isinstance(target, ast.Name)}
            for call in ast.walk(function):
                func = getattr(call, "func", None)
                if (isinstance(call, ast.Call) and isinstance(func, ast.Attribute) and func.attr == "__setattr__"
                        and isinstance(func.value, ast.Name) and func.value.id == "object" and call.args):
                    target = ast.unparse(call.args[0])
                    where = "new" if target in made else function.name
                    writes.append((str(path.relative_to(package)), call.lineno, where, target))
    return writes


def test_frozen_values_are_written_only_while_they_are_made():
    """memo keeps a frozen dataclass's key by its ``id`` while it lives (``_exact``): a value changed after it was
    first keyed would keep its old key. Every ``object.__setattr__`` in the package writes ``self`` in a
    ``__post_init__`` or ``__init__``, or a value its function has just made with ``object.__new__``."""
    writes = _writes_to_frozen_values()
    assert writes  # (the walk finds them: some thirty-nine today)
    late = [write for write in writes if not (write[2] == "new" or (write[2] in ("__post_init__", "__init__")
                                                                    and write[3] == "self"))]
    assert late == []


class _EqualityPowerLaw(me.PowerLaw):
    """A user's power law comparing by its own ``__eq__`` (so Python sets its ``__hash__`` to ``None``)."""

    def __eq__(self, other):
        return super().__eq__(other)


def test_cached_keeps_a_hashable_call_by_hash_an_unhashable_one_by_value_and_computes_the_rest():
    """``memo.cached``, the one cache of a function keyed by an indenter (issue 32 round 28 A3): a hashable indenter
    is computed once (``lru_cache``), a user's subclass that defines ``__eq__`` alone (no hash; it ended in
    ``unhashable type``) once too, by its exact value, and an argument with neither (a list) each time."""
    calls = []

    @cached(4)
    def exponent(indenter, extra):
        calls.append(indenter)
        return indenter.n

    user = _EqualityPowerLaw(0.2, 1.5)
    assert user.__hash__ is None
    for indenter in (me.PowerLaw(0.2, 1.5), user):
        calls.clear()
        assert [exponent(indenter, 1.0) for _ in range(3)] == [1.5] * 3 and len(calls) == 1
    calls.clear()
    assert [exponent(me.PowerLaw(0.2, 1.5), [1.0]) for _ in range(2)] == [1.5] * 2 and len(calls) == 2
