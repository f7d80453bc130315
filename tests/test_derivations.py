"""Every derivation notebook runs as a plain script (its own asserts are the checks)."""

import runpy
from pathlib import Path

import pytest

NOTEBOOKS = sorted((Path(__file__).parent.parent / "derivations").glob("*.py"))


def test_there_are_three_notebooks():
    assert len(NOTEBOOKS) == 3


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, capsys):
    text = path.read_text()
    assert "# %%" in text and "format_name: percent" in text
    runpy.run_path(str(path), run_name="__main__")
