"""The twenty-ninth hostile round (issue 32), the state's side: interrupts, pipes, caches and resumes; each class of
what failed, with the cases that showed it.

The round's cases (Ctrl-C and SIGTERM at 30 moments of each writing verb, ``| head -1`` after each printing verb,
the caches truncated, emptied, foreign, read-only, a directory or a file in their place, several processes filling
an empty cache at once, sweeps interrupted and resumed) are listed with their outcomes in the issue's closing note;
what failed is below.
"""

from __future__ import annotations

import glob
import os
import pickle
import shutil
import threading
import warnings

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.sweep import sweep
from hostile_checks import one_line_naming

from mdr_events.theory.cache_files import read_cached, store_cached
from mdr_events.theory.layer.table_store import stored_columns

#: Bytes a writer puts into the cache's temporary before it is interrupted (any non-empty part of a file).
PART_WRITTEN = b"\x80\x04partial"


#: Seconds a read of a cache file may take before it is taken for hanging (a read of a small file takes microseconds;
#: the FIFO's open blocked for ever).
READ_BUDGET = 10.0
#: A layer's table grid in ``ln(a/h)`` (any grid: the read compares the stored one with it).
GRID = np.linspace(-3.0, 3.0, 7)


#: A sweep small enough for a quick test: four continuum runs, one per chunk (each chunk a file of each variable).
SWEEP_GRID = {"alpha": [10.0, 20.0, 30.0, 40.0]}
#: The runs left undone in a store cut short (the chunks from this index on).
FIRST_UNDONE = 2


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


def _read_within_budget(path):
    """``read_cached(path, ...)``'s result, or ``"hung"`` if it took over :data:`READ_BUDGET` (the thread left
    blocked is woken by opening the FIFO for writing)."""
    outcome = ["hung"]
    reader = threading.Thread(target=lambda: outcome.__setitem__(0, read_cached(path, lambda stream: stream.read())),
                              daemon=True)
    reader.start()
    reader.join(READ_BUDGET)
    if reader.is_alive():
        os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))  # (releases the blocked open)
        reader.join(READ_BUDGET)
    return outcome[0]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs")
def test_a_fifo_in_a_cache_files_place_is_a_missed_shortcut(tmp_path):
    """A FIFO in the place of a cache file (``relations-<key>.pickle``) held every derivation at its open, for ever
    (no writer ever came): a cache file that is not a regular file is only a missed shortcut, as a directory there."""
    path = tmp_path / "relations-0123456789abcdef.pickle"
    os.mkfifo(path)
    assert _read_within_budget(path) is None


def test_a_regular_cache_file_is_still_read(tmp_path):
    """The shortcut itself: a regular cache file is read (the non-blocking open changes nothing for it)."""
    path = tmp_path / "relations-0123456789abcdef.pickle"
    path.write_bytes(PART_WRITTEN)
    assert _read_within_budget(path) == PART_WRITTEN


def _table():
    return {"s": GRID, "k0": np.array([1.0, 2.0]), "force": np.exp(GRID)}


@pytest.mark.parametrize("column", [np.arange(2.0), np.full(GRID.shape, np.nan), np.full(GRID.shape, np.inf),
                                    np.ones((GRID.size, 2)), np.arange(GRID.size)],
                         ids=["2 values on 7 nodes", "NaN", "inf", "2-d", "integers"])
def test_a_foreign_layer_table_with_the_grid_is_rebuilt(tmp_path, column):
    """A table file with the right grid ``s`` but a column not of one finite float per node (a foreign or damaged
    file) was returned as the table: a ``force`` column of 2 values on 7 nodes, or of NaN. It is rebuilt (and
    stored), as any other damaged file."""
    path = tmp_path / "layer-bonded-nu0.5-n2.0-0123456789abcdef.npz"
    with open(path, "wb") as stream:
        np.savez(stream, s=GRID, k0=np.array([1.0, 2.0]), force=column)
    built = []
    columns = stored_columns(path, ("s", "k0", "force"), GRID, lambda: built.append(1) or _table(), constants=("k0",))
    assert built == [1]
    np.testing.assert_array_equal(columns["force"], np.exp(GRID))
    assert stored_columns(path, ("s", "k0", "force"), GRID, lambda: built.append(1) or _table(),
                          constants=("k0",))["force"].shape == GRID.shape
    assert built == [1]  # (the rebuilt table is read back: the check does not refuse a good one)


def _sweep(store):
    return sweep(SWEEP_GRID, "A", base=me.Parameters.paper(), scheduler="serial", chunk_size=1, store=store)


@pytest.fixture(scope="module")
def whole_store(tmp_path_factory):
    """A store of the sweep written whole, and the sweep's result."""
    store = str(tmp_path_factory.mktemp("sweep") / "whole.zarr")
    return store, _sweep(store)


def _copy(whole_store, tmp_path) -> str:
    store = str(tmp_path / "cut.zarr")
    shutil.copytree(whole_store[0], store)
    return store


def test_a_store_without_its_consolidated_metadata_resumes_silently(whole_store, tmp_path):
    """A store whose layout was cut short before its last step (the consolidated metadata, ``.zmetadata``: Ctrl-C,
    a full disk or ``ulimit -f``) resumed with xarray's RuntimeWarning of five lines printed three times, at the check,
    the read and each chunk's write. It resumes silently, the runs left undone run, the result the whole sweep's."""
    import zarr

    store = _copy(whole_store, tmp_path)
    os.remove(os.path.join(store, ".zmetadata"))
    zarr.open_array(os.path.join(store, "done"), mode="r+", zarr_format=2)[FIRST_UNDONE:] = 0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        resumed = _sweep(store)
    xr.testing.assert_identical(resumed, whole_store[1])


def _no_variable(store: str) -> None:
    os.remove(os.path.join(store, ".zmetadata"))
    shutil.rmtree(os.path.join(store, "done"))


def _chunk_cut(store: str) -> None:
    chunk = sorted(glob.glob(os.path.join(store, "pull_off_force", "[0-9]*")))[0]
    with open(chunk, "r+b") as stream:
        stream.truncate(len(PART_WRITTEN))


@pytest.mark.parametrize("damage", [_no_variable, _chunk_cut], ids=["a variable missing", "a chunk cut short"])
def test_a_store_cut_short_is_refused_in_one_line(whole_store, tmp_path, damage):
    """A store of this sweep whose layout or a chunk's write was cut short (a variable missing, a chunk truncated)
    ended in ``No variable named 'done'. Variables on the dataset include [...]`` or the codec's error: the refusal
    names the store and what is allowed (to start it afresh)."""
    store = _copy(whole_store, tmp_path)
    damage(store)
    message = one_line_naming(lambda: _sweep(store), "store=")
    assert "resume=False" in message
