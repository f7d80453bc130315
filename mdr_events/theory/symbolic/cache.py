"""The on-disk cache of the derivations, keyed by the hash of the source that derives them, and the helpers
every module of derivations shares (:func:`cached_relations`, :func:`derivation_check`)."""

from __future__ import annotations

import hashlib
import pickle
from pathlib import Path
from typing import Callable

import sympy as sp

from mdr_events.theory.cache_files import cache_directory, read_cached, store_cached
from mdr_events.theory.symbolic.derived_relation import Relation

__all__ = ["cache_path", "cached_relations", "derivation_check", "sibling_cache_path", "source_digest"]


def source_digest(*source_files: str | Path) -> str:
    """The key of the relations a module (or a package) of derivations files: a hash of its source and of SymPy's
    version.

    A module takes it when it is imported, not when its cache is used, so that a process never files the derivations
    of the code it runs under the name of a source edited since.

    Parameters
    ----------
    *source_files : str or pathlib.Path
        The module's file (its ``__file__``), or every file of a package, in a fixed order.

    Returns
    -------
    str
        16 hexadecimal digits.
    """
    source = b"".join(Path(source_file).read_bytes() for source_file in source_files)
    return hashlib.sha256(source + sp.__version__.encode()).hexdigest()[:16]


#: Hash of this package's sources as they were imported (every module of :mod:`mdr_events.theory.symbolic`, by name:
#: the symbols, the :class:`Relation` whose fields the cache stores, every derivation and its helpers, so that an edit
#: to any of them cannot leave a stale cache behind), and of the SymPy version: the cache key (:func:`source_digest`).
_SOURCE_DIGEST = source_digest(*sorted(Path(__file__).parent.glob("*.py")))


def sibling_cache_path(stem: str, digest: str) -> Path | None:
    """The cache file of a sibling module of derivations, beside :func:`cache_path` (``None``: caching is off).

    Parameters
    ----------
    stem : str
        The file's name before its key (``"layer-relations"``, ...).
    digest : str
        The sibling's :func:`source_digest`.

    Returns
    -------
    pathlib.Path or None
        ``<stem>-<digest>.pickle`` in the cache directory, or ``None``.
    """
    root = cache_directory()
    return None if root is None else root / f"{stem}-{digest}.pickle"


def cache_path() -> Path | None:
    """Where derived relations are kept between processes (``None``: caching is off).

    ``$MDR_EVENTS_CACHE_DIR`` or ``$XDG_CACHE_HOME/mdr_events`` or
    ``~/.cache/mdr_events``; ``MDR_EVENTS_NO_CACHE=1`` turns it off. The file
    name carries a hash of this package's sources and the SymPy version, so a
    changed derivation is never read from an old cache.

    Returns
    -------
    pathlib.Path or None
        The cache file ``relations-<hash>.pickle`` in that directory, or ``None``.
    """
    return sibling_cache_path("relations", _SOURCE_DIGEST)


def _fields(rel: Relation) -> tuple:
    return (rel.key, rel.equation, rel.title, rel.lhs, rel.rhs, rel.args, rel.variable)


def _cached(name: str, build: Callable[[], list[Relation]],
            where: Callable[[], Path | None] | None = None) -> list[Relation]:
    """``build()``'s relations, read from the cache file if it holds ``name``, else built and stored.

    ``where`` gives the cache file (default :func:`cache_path`; a sibling module of derivations passes its own, keyed by
    its own source). Any trouble with the cache (unwritable, damaged, foreign) falls back to deriving afresh.
    """
    path = (where or cache_path)()
    store = read_cached(path, pickle.load)  # (missing, unreachable or damaged: None)
    store = store if isinstance(store, dict) else {}
    try:
        if name in store:
            return [Relation(*fields) for fields in store[name]]
    except Exception:  # noqa: BLE001 - a foreign cache file is only a missed shortcut
        store = {}
    relations_built = build()
    if path is not None:
        store[name] = [_fields(rel) for rel in relations_built]
        store_cached(path, lambda stream: pickle.dump(store, stream))
    return relations_built


def cached_relations(name: str, afresh: Callable[[], dict[str, Relation]],
                     where: Callable[[], Path | None] | None = None) -> dict[str, Relation]:
    """The relations ``afresh()`` derives, by key in derivation order, read from the cache file if it holds ``name``
    (:func:`_cached`; ``where`` gives a sibling module's own file, default :func:`cache_path`).

    Parameters
    ----------
    name : str
        The derivation's name in the cache file.
    afresh : callable
        Derives the relations with SymPy, by key.
    where : callable, optional
        The cache file (``None``: caching is off); default :func:`cache_path`.

    Returns
    -------
    dict of str to Relation
        The relations by key.
    """
    return {rel.key: rel for rel in _cached(name, lambda: list(afresh().values()), where)}


def derivation_check(what: str) -> Callable[[bool, str], None]:
    """A derivation's check of its own steps: raises ``RuntimeError("<what>: <step>")`` where a step's condition fails.

    Parameters
    ----------
    what : str
        The derivation's name in the message.

    Returns
    -------
    callable
        ``check(condition, step)``.
    """
    def check(condition: bool, step: str) -> None:
        if not condition:
            raise RuntimeError(f"{what}: {step}")
    return check
