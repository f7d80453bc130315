"""Which modules fill the registries of the kinds of result, imported on the registry's first look-up.

The module that makes a kind of result registers its schema (:func:`mdr_events.io.datasets.register_schema`), the
accuracy of its quantities (:func:`mdr_events.io.agreement.register_accuracy`) and its figure
(:func:`mdr_events.io.datasets.register_figure`) when it is imported. The package names those modules
(:func:`declare_registrars`, in ``mdr_events/__init__.py``) without importing them; a look-up in a registry first
imports the ones not imported yet (:func:`load_registrars`). So a registry is complete whatever a user imported, and
``import mdr_events`` stays light (no NumPy, xarray or matplotlib: this module imports only the standard library).
"""

from __future__ import annotations

import importlib
import threading
from collections.abc import Sequence

__all__ = ["declare_registrars", "load_registrars"]

#: The modules whose import registers kinds of result and that are not imported yet, by registry (``"schemas"``:
#: schemas and accuracies, ``"figures"``: figures).
_REGISTRARS: dict[str, list[str]] = {"schemas": [], "figures": []}
_REGISTRARS_LOCK = threading.RLock()


def declare_registrars(schemas: Sequence[str] = (), figures: Sequence[str] = ()) -> None:
    """Name the modules that register kinds of result, imported on the first look-up in their registry.

    Parameters
    ----------
    schemas : sequence of str
        Modules registering schemas (:func:`mdr_events.io.datasets.register_schema`) and accuracies
        (:func:`mdr_events.io.agreement.register_accuracy`).
    figures : sequence of str
        Modules registering figures (:func:`mdr_events.io.datasets.register_figure`); they import the plotting library.
    """
    with _REGISTRARS_LOCK:
        for kind, modules in (("schemas", schemas), ("figures", figures)):
            _REGISTRARS[kind].extend(name for name in modules if name not in _REGISTRARS[kind])


def load_registrars(kind: str) -> None:
    """Import the modules declared for registry ``kind`` (``"schemas"`` or ``"figures"``) not imported yet."""
    with _REGISTRARS_LOCK:
        waiting = _REGISTRARS[kind]
        while waiting:
            importlib.import_module(waiting.pop(0))
