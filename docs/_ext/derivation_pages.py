"""The derivation notebooks as pages: ``derivations/NN_*.py`` (Jupytext percent scripts) are copied into
``docs/derivations/`` when the build starts, where MyST-NB reads them through Jupytext (``nb_custom_formats``
in ``conf.py``) and executes them like every tutorial. The copies are build products (``.gitignore``); a copy is
rewritten only when its script changed, so that an unchanged derivation is not read again."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def copy_derivations(app) -> None:
    """Copy each numbered derivation script into ``docs/derivations/`` (a copy that differs is replaced)."""
    target = Path(app.srcdir) / "derivations"
    target.mkdir(exist_ok=True)
    sources = sorted((ROOT / "derivations").glob("[0-9][0-9]_*.py"))
    for source in sources:
        copy = target / source.name
        text = source.read_text(encoding="utf-8")
        if not copy.exists() or copy.read_text(encoding="utf-8") != text:
            copy.write_text(text, encoding="utf-8")
    names = {source.name for source in sources}
    for stale in target.glob("[0-9][0-9]_*.py"):
        if stale.name not in names:
            stale.unlink()


def setup(app):
    app.connect("builder-inited", copy_derivations)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
