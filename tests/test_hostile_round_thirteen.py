"""The thirteenth hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations


import numpy as np
import pytest

import mdr_events as me

PAPER = me.Parameters.paper()


def _one_line_naming(call, named: str, errors=(ValueError, TypeError)) -> str:
    """The message of what ``call`` raises: one line, naming ``named`` and what is allowed."""
    with pytest.raises(errors) as caught:
        call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message, message
    return message


# --- N1: the caches on disk (the derivations, the layer's tables) were no mere shortcut: the existence of a cache file
# was looked up before the `try` that makes any trouble a missed shortcut, so a cache directory the system refuses to
# look into (a name too long; below a directory without search permission) failed every derivation and every layer
# table with a raw OSError ('mdr-events derive' exited 2, "File name too long"); a store that failed (the cache file's
# name taken by a directory) left its temporary behind. One module reads and stores every cache file ----------------

@pytest.fixture
def unreachable_cache(tmp_path, monkeypatch):
    """A cache directory whose files the system refuses to look at: their names are too long (ENAMETOOLONG)."""
    monkeypatch.setenv("MDR_EVENTS_CACHE_DIR", str(tmp_path / ("x" * 300)))
    monkeypatch.delenv("MDR_EVENTS_NO_CACHE", raising=False)


def test_a_cache_the_system_refuses_is_only_a_missed_shortcut(unreachable_cache):
    from mdr_events.theory import symbolic
    from mdr_events.theory.layer import table_store

    built = symbolic._cached("round-thirteen-probe", lambda: [])  # (derived afresh, not an OSError)
    assert built == []
    grid = np.linspace(0.0, 1.0, 5)
    columns = table_store.stored_columns(table_store.cache_directory() / "probe.npz", ("s", "y"), grid,
                                         lambda: {"s": grid, "y": 2.0 * grid})
    np.testing.assert_array_equal(columns["y"], 2.0 * grid)


def test_a_store_that_fails_leaves_no_temporary(tmp_path):
    from mdr_events.theory.layer import table_store

    grid = np.linspace(0.0, 1.0, 5)
    taken = tmp_path / "table.npz"
    taken.mkdir()  # (the cache file's name is a directory: the store's rename fails)
    table_store.stored_columns(taken, ("s", "y"), grid, lambda: {"s": grid, "y": grid})
    assert sorted(path.name for path in tmp_path.iterdir()) == ["table.npz"]
