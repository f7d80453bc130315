"""Figures drawn from the datasets (never recomputed here): Fig. 8, 9a, 9b, 10, fretting loops, and the
convergence of a simulator under validation.

Each name is loaded from its module on first use (PEP 562 ``__getattr__``, as in :mod:`mdr_events`): a module that
draws one kind of figure (``from mdr_events.plotting.figures import plot_phase_diagram``) does not load the others
and what they import (the fit's figure loads the fit, and SciPy's statistics with it). The modules that register a
figure for a kind of result are named in ``mdr_events/__init__.py`` and imported on the registry's first look-up.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

__all__ = ["figure_png", "plot_convergence_study", "plot_fit", "plot_fretting", "plot_phase_diagram",
           "plot_profile_comparison", "plot_simulation", "plot_universal_map", "plot_validation", "save_figure"]

#: Where each public name is defined: name -> module.
_LAZY = {
    "plot_convergence_study": "mdr_events.plotting.convergence",
    "plot_fit": "mdr_events.plotting.fit",
    "plot_universal_map": "mdr_events.plotting.universal",
    "plot_profile_comparison": "mdr_events.plotting.profiles",
    **dict.fromkeys(("figure_png", "plot_fretting", "plot_phase_diagram", "plot_simulation", "save_figure"),
                    "mdr_events.plotting.figures"),
    "plot_validation": "mdr_events.plotting.validation",
}


def __getattr__(name: str):
    """Load a public name (:data:`__all__`) on first use, and keep it (PEP 562)."""
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_LAZY[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """The public names (:data:`__all__`) beside the module's own, for ``dir()`` and tab completion."""
    return sorted(set(globals()) | set(__all__))


if TYPE_CHECKING:  # what static tools read: the same names, imported eagerly
    from mdr_events.plotting.convergence import plot_convergence_study
    from mdr_events.plotting.figures import figure_png, plot_fretting, plot_phase_diagram, plot_simulation, save_figure
    from mdr_events.plotting.fit import plot_fit
    from mdr_events.plotting.profiles import plot_profile_comparison
    from mdr_events.plotting.universal import plot_universal_map
    from mdr_events.plotting.validation import plot_validation
