"""Imports point down only: no module of mdr_events imports from a layer above its own.

Layers, bottom to top: the foundation (``parameters``, ``validation``, ``limits``, ``memo``, ``_version``), ``contact`` (the
physical model as data), ``io``,
``theory``, ``models`` (with ``models/continuum``), ``analysis``, ``plotting``, ``app`` (with ``reproduction``, the
paper's reproduction, a folder of its own at the same level). A module may
import from its own layer and those below. Every import counts, also one inside a function or under
``TYPE_CHECKING``. ``mdr_events/__init__.py`` (the public API) and ``_version.py`` are exempt as
importers; importing the package itself (``from mdr_events import ...``) from a module is importing
from the top.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import mdr_events

PACKAGE = Path(mdr_events.__file__).resolve().parent

#: Layers from the bottom: the first component(s) of a module's name under mdr_events -> its layer.
LAYERS = ("foundation", "contact", "io", "theory", "models", "analysis", "plotting", "app", "package")
FOUNDATION_MODULES = ("parameters", "validation", "limits", "memo", "_version")
#: Folders that sit at the level of a layer without being named after it: folder -> its layer.
FOLDER_LAYERS = {"reproduction": "app", "dem": "analysis"}
EXEMPT_IMPORTERS = ("mdr_events", "mdr_events._version")


def layer_of(module: str) -> str:
    """The layer of a module of mdr_events (``"package"``: the package itself, above every layer)."""
    parts = module.split(".")
    if parts[0] != "mdr_events":
        raise ValueError(f"{module} is not a module of mdr_events")
    if len(parts) == 1:
        return "package"
    if parts[1] in FOUNDATION_MODULES:
        return "foundation"
    if parts[1] in LAYERS[1:-1]:
        return parts[1]
    if parts[1] in FOLDER_LAYERS:
        return FOLDER_LAYERS[parts[1]]
    raise ValueError(f"{module} belongs to no layer: add it to tests/test_layers.py")


def module_name(path: Path) -> str:
    """``mdr_events/models/continuum/solve.py`` -> ``mdr_events.models.continuum.solve``."""
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def imported_modules(source: str, module: str, is_package: bool = False) -> set[str]:
    """The mdr_events modules ``source`` (the text of ``module``) imports from, relative imports resolved."""
    found = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = module.split(".")
                base = base if is_package else base[:-1]
                base = base[:len(base) - (node.level - 1)]
                found.add(".".join(base + ([node.module] if node.module else [])))
            else:
                found.add(node.module)
    return {name for name in found if name == "mdr_events" or name.startswith("mdr_events.")}


def upward_imports(source: str, module: str, is_package: bool = False) -> list[str]:
    """The imports of ``module`` from a layer above its own, as ``"module (layer)"``."""
    own = LAYERS.index(layer_of(module))
    return sorted(f"{target} ({layer_of(target)})" for target in imported_modules(source, module, is_package)
                  if LAYERS.index(layer_of(target)) > own)


def package_modules() -> list[Path]:
    return sorted(path for path in PACKAGE.rglob("*.py") if module_name(path) not in EXEMPT_IMPORTERS)


@pytest.mark.parametrize("path", package_modules(), ids=lambda path: module_name(path))
def test_no_module_imports_from_a_higher_layer(path):
    module = module_name(path)
    found = upward_imports(path.read_text(), module, path.name == "__init__.py")
    assert not found, f"{module} ({layer_of(module)}) imports from a higher layer: {', '.join(found)}"


#: Inside ``app``, from the bottom: the shared parsers and the files of results; the typed jobs; study files; the
#: command line (a package of one module per verb). A module imports from its own level and those below.
APP_LEVELS = {
    "inputs": 0, "result_files": 0, "validation_files": 0, "fit_files": 0, "heartbeat": 0,
    "jobs": 1,
    "study_format": 2, "study": 2,
    "cli": 3, "console": 3,  # (the console script's entry point: the CLI's interrupt lines, the CLI imported late)
}


def app_level(module: str) -> int:
    """The level inside ``app`` of a module of ``mdr_events.app`` (:data:`APP_LEVELS`)."""
    parts = module.split(".")
    if parts[:2] != ["mdr_events", "app"] or len(parts) < 3:
        raise ValueError(f"{module} is not a module inside mdr_events.app")
    if parts[2] not in APP_LEVELS:
        raise ValueError(f"{module} has no level inside app: add it to APP_LEVELS in tests/test_layers.py")
    return APP_LEVELS[parts[2]]


@pytest.mark.parametrize("path", [path for path in package_modules() if module_name(path).startswith("mdr_events.app.")],
                         ids=lambda path: module_name(path))
def test_app_modules_import_down_only(path):
    """The command line and study files build jobs; jobs call the library and the writers; never the other way."""
    module = module_name(path)
    found = sorted(f"{target} (level {app_level(target)})"
                   for target in imported_modules(path.read_text(), module, path.name == "__init__.py")
                   if target.startswith("mdr_events.app.") and app_level(target) > app_level(module))
    assert not found, f"{module} (level {app_level(module)}) imports from above: {', '.join(found)}"


def test_an_upward_import_inside_app_is_found():
    source = "from mdr_events.app.cli import main\nfrom mdr_events.app.inputs import limits\n"
    above = [target for target in imported_modules(source, "mdr_events.app.jobs")
             if app_level(target) > app_level("mdr_events.app.jobs")]
    assert above == ["mdr_events.app.cli"]
    with pytest.raises(ValueError, match="no level inside app"):
        app_level("mdr_events.app.somewhere")


def test_every_layer_has_modules():
    layers = {layer_of(module_name(path)) for path in package_modules()}
    assert layers == set(LAYERS) - {"package"}


# ----------------------------------------------------------------------------------------------
# the check itself can fail


@pytest.mark.parametrize("module, source, expected", [
    ("mdr_events.io.files", "from mdr_events.plotting.figures import figure_png",
     ["mdr_events.plotting.figures (plotting)"]),
    ("mdr_events.theory.phase", "def f():\n    import mdr_events.models.simulate\n",
     ["mdr_events.models.simulate (models)"]),
    ("mdr_events.parameters", "if TYPE_CHECKING:\n    from mdr_events.io import files\n", ["mdr_events.io (io)"]),
    ("mdr_events.models.simulate", "from mdr_events import open_result", ["mdr_events (package)"]),
    ("mdr_events.models.continuum.solve", "from ...app.cli import main", ["mdr_events.app.cli (app)"]),
    ("mdr_events.models.continuum", "from .solve import run_continuum\nfrom ..paths import Path", []),
    ("mdr_events.analysis.crosscheck", "from mdr_events.models.simulate import simulate\nimport numpy", []),
    ("mdr_events.reproduction.runner", "from mdr_events.app.result_files import write_text", []),
    ("mdr_events.plotting.figures", "from mdr_events.reproduction.fretting import FRETTING_STEM",
     ["mdr_events.reproduction.fretting (app)"]),
], ids=["io-plotting", "in-function", "type-checking", "package-itself", "relative-up", "relative-down", "down",
        "reproduction-app", "plotting-reproduction"])
def test_an_upward_import_is_found(module, source, expected):
    is_package = module == "mdr_events.models.continuum"
    assert upward_imports(source, module, is_package) == expected


def test_a_module_outside_the_layers_is_an_error():
    with pytest.raises(ValueError, match="belongs to no layer"):
        layer_of("mdr_events.somewhere.new")
