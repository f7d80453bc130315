"""Sphinx configuration of the mdr_events documentation: ``make docs`` builds it into ``docs/_build/html``.

Built offline: no intersphinx (its inventories would be fetched), MathJax from a local copy
(sphinx-mathjax-offline), every tutorial executed by MyST-NB during the build, the derivation notebooks
read from ``derivations/*.py`` (Jupytext percent format) and executed too. ``-W --keep-going`` and
``nitpicky``: a reference into the package that does not resolve is an error; references to other packages
(numpy, xarray, the standard library, ...) cannot resolve without their inventories and are ignored by name.
numpydoc validates the docstring of every public function and class (:data:`NUMPYDOC_CHECKS`).
"""

from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE / "_ext"))

import mdr_events  # noqa: E402
from numpydoc_checks import NUMPYDOC_CHECKS, public_exclude  # noqa: E402

project = "mdr_events"
author = "mdr_events authors"
copyright = "the mdr_events authors, MIT licence"
release = version = mdr_events.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",
    "numpydoc",
    "myst_nb",
    "sphinxarg.ext",
    "study_format_page",
    "derivation_pages",
]

# ---------------------------------------------------------------------------------------------- sources
root_doc = "index"
exclude_patterns = ["_build", "_ext", "_templates", "conf.py", "**.ipynb_checkpoints", "jupyter_execute"]
templates_path = ["_templates"]
# the derivations are Jupytext percent scripts (derivations/NN_*.py), copied to docs/derivations/ by
# derivation_pages and read as notebooks
nb_custom_formats = {".py": ["jupytext.reads", {"fmt": "py:percent"}]}
suppress_warnings = [
    "mystnb.unknown_mime_type",
    # Nitpicky where references resolve: a module constant or attribute named in prose (``:data:`QUANTITIES```)
    # is often undocumented (no ``#:`` comment), and a name documented both publicly (mdr_events.Path) and on
    # its module's internals page (mdr_events.models.paths.Path) is ambiguous by design: both are let through.
    # Classes, functions, methods and modules must resolve.
    "ref.data", "ref.attr", "ref.python",
]

# ---------------------------------------------------------------------------------------------- references
nitpicky = True
# What cannot resolve without other projects' inventories (no network at build time): their names, and the
# standard library's.
_EXTERNAL = (r"(_io|numpy|np|xarray|xr|pandas|pd|scipy|matplotlib|mpl|plt|sympy|sp|dask|distributed|zarr|"
             r"concurrent|argparse|pathlib|os|io|typing|collections|enum|numbers|datetime|types|"
             r"dataclasses|fractions|decimal|abc|contextlib|threading|subprocess|tomllib|csv|functools)")
nitpick_ignore_regex = [
    (r"py:.*", _EXTERNAL + r"(\..*)?"),
    # private names and names given relative to a module that the build cannot place
    (r"py:.*", r"(.*\.)?_[A-Za-z].*"),
    (r"py:.*", r"[A-Za-z_][A-Za-z0-9_]*"),
    # an annotation that is prose, not a type (a constant's value rendered by autodoc)
    (r"py:class", r".*[ '\"(\[\]].*"),
    # the report's row types and the jobs' results, undocumented records of the app layer
    (r"py:class", r"mdr_events\.(reproduction\.differences\.\w+Row|app\.jobs\.Validated)"),
    (r"py:class", r"(array_like|array-like|path-like|file-like|callable|optional|default .*|scalar|"
                  r"ArrayLike|NDArray|PathLike|Executor|Future|Client|Dataset|DataArray|ndarray|Figure|Axes|"
                  r"Path\b.*|Sequence|Mapping|Iterable|Iterator|Callable|Any|Literal|Self)"),
]

# ---------------------------------------------------------------------------------------------- API
autosummary_generate = True
autosummary_imported_members = True
autodoc_typehints = "signature"          # type hints shown in each signature
autodoc_typehints_format = "short"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "inherited-members": False, "show-inheritance": True,
                           # NamedTuples whose generated signature autodoc cannot format
                           "exclude-members": "Reproduction, Fired, Logged"}
autodoc_preserve_defaults = False
numpydoc_show_class_members = False      # members are autodoc's (with their #: comments)
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks = NUMPYDOC_CHECKS
numpydoc_validation_exclude = public_exclude()
add_module_names = False

# A public class (mdr_events.Contact) is documented on its API page and, under the module that defines it
# (mdr_events.contact.model.Contact), on the internals' pages. autodoc would declare the second name as the
# first one's canonical name too, and the two declarations collide; each page keeps its own name instead.
try:  # Sphinx >= 9 (the lock file's): the class's properties give the canonical name
    from sphinx.ext.autodoc._property_types import _ClassDefProperties  # noqa: E402

    _ClassDefProperties.canonical_full_name = property(lambda self: None)
except ImportError:  # Sphinx < 9
    from sphinx.ext.autodoc import ClassDocumenter  # noqa: E402

    ClassDocumenter.get_canonical_fullname = lambda self: None

# ---------------------------------------------------------------------------------------------- notebooks
nb_execution_mode = "force"             # every tutorial runs during the build
nb_execution_timeout = 600
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_merge_streams = True
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence"]
myst_heading_anchors = 3

# ---------------------------------------------------------------------------------------------- HTML
html_theme = "pydata_sphinx_theme"
html_title = f"mdr_events {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
    "secondary_sidebar_items": ["page-toc"],
}
html_show_sourcelink = False

# the modules documented with the public API (docs/api/index.rst): the internals' pages point there
autosummary_context = {"public_modules": ["mdr_events", "mdr_events.theory.analytic", "mdr_events.theory.power_law",
                                          "mdr_events.theory.mindlin", "mdr_events.theory.tabulated",
                                          "mdr_events.theory.symbolic", "mdr_events.theory.rate_adhesion",
                                          "mdr_events.theory.layer", "mdr_events.theory.layer_symbolic",
                                          "mdr_events.theory.layer_tangential",
                                          "mdr_events.theory.layer_tangential_symbolic",
                                          "mdr_events.theory.layer_continuum_symbolic",
                                          "mdr_events.models.continuum",
                                          "mdr_events.dem"]}
