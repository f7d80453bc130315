"""dask settings that tests change for a block, without taking distributed's defaults with them.

``dask.config.set`` removes on exit every key it created. Setting ``distributed.comm.timeouts.connect`` before
dask.distributed is imported creates the whole ``distributed`` section; a sweep inside the block imports
distributed, which fills that section with its defaults, and the block's exit then removes them all: every later
``to_netcdf`` (xarray asks distributed's ``get_client``) of that test process failed with ``KeyError:
'distributed'`` (seen in ``make test-newest``, where the tests fell on the workers in another order).
"""
from __future__ import annotations

import contextlib


@contextlib.contextmanager
def connect_timeout(timeout: str):
    """dask's connect timeout set to ``timeout`` (e.g. ``"1s"``) for the block, distributed's defaults registered
    first and checked intact after it."""
    import dask
    import distributed  # noqa: F401  (its defaults in dask's config before the block, so the block keeps them)

    with dask.config.set({"distributed.comm.timeouts.connect": timeout}):
        yield
    assert dask.config.get("distributed.comm.timeouts.connect") != timeout, "the block's timeout outlived it"
