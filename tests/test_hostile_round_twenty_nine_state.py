"""The twenty-ninth hostile round (issue 32), the state's side: interrupts, pipes, caches and resumes; each class of
what failed, with the cases that showed it.

The round's cases (Ctrl-C and SIGTERM at 30 moments of each writing verb, ``| head -1`` after each printing verb,
the caches truncated, emptied, foreign, read-only, a directory or a file in their place, several processes filling
an empty cache at once, sweeps interrupted and resumed) are listed with their outcomes in the issue's closing note;
what failed is below.
"""

from __future__ import annotations

import os
import pickle

import pytest

from mdr_events.theory.cache_files import store_cached

#: Bytes a writer puts into the cache's temporary before it is interrupted (any non-empty part of a file).
PART_WRITTEN = b"\x80\x04partial"


class _WriterError(Exception):
    """An error of a cache's own writer (not the disk's)."""


@pytest.mark.parametrize("interruption", [KeyboardInterrupt, SystemExit, _WriterError, pickle.PicklingError],
                         ids=["Ctrl-C", "SIGTERM (SystemExit)", "writer's error", "PicklingError"])
def test_an_interrupted_cache_store_leaves_no_temporary(tmp_path, interruption):
    """Ctrl-C (or SIGTERM, or any error but the disk's) while a derivation or a layer's table was stored left its
    temporary ``.<name>.<random>`` in the cache directory, one more at every interrupted first run: only an
    ``OSError`` removed it. The interruption goes on; the directory is as it was (no file, no temporary)."""
    target = tmp_path / "relations-0123456789abcdef.pickle"

    def write(stream) -> None:
        stream.write(PART_WRITTEN)
        stream.flush()
        raise interruption()

    with pytest.raises(interruption):
        store_cached(target, write)
    assert os.listdir(tmp_path) == []


def test_an_interrupted_store_keeps_the_previous_cache_file(tmp_path):
    """An interrupted store leaves the cache file there was, whole, and nothing beside it."""
    target = tmp_path / "layer-table.npz"
    store_cached(target, lambda stream: stream.write(b"previous"))

    def write(stream) -> None:
        stream.write(PART_WRITTEN)
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        store_cached(target, write)
    assert os.listdir(tmp_path) == [target.name]
    assert target.read_bytes() == b"previous"
