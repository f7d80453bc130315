"""Every derivation notebook runs as a plain script (its own asserts are the checks) and, where
Jupytext and nbclient are installed, as a notebook that shows its figure."""

import runpy
from pathlib import Path

import matplotlib.pyplot as plt
import pytest

DERIVATIONS = Path(__file__).parent.parent / "derivations"
NOTEBOOKS = sorted(DERIVATIONS.glob("[0-9][0-9]_*.py"))


def test_the_readme_lists_every_notebook():
    """derivations/README.md's table names exactly the notebooks there are (seven: a renamed or new one is seen)."""
    import re
    listed = set(re.findall(r"^\| `(\d\d_\w+\.py)` \|", (DERIVATIONS / "README.md").read_text(), flags=re.MULTILINE))
    assert listed == {path.name for path in NOTEBOOKS} and len(listed) == 7


#: The notebooks whose script runs long (the rate-dependent edge's fits, ~8 s of CPU; the finite layer's tables and
#: curves, ~13 s): run by `make test-all` and CI (marked slow), their relations tested in tests/theory and tests/models.
LONG_NOTEBOOKS = ("06_rate_dependent_adhesion.py", "07_finite_layer.py")


@pytest.mark.parametrize("path", [pytest.param(path, marks=pytest.mark.slow) if path.name in LONG_NOTEBOOKS else path
                                  for path in NOTEBOOKS], ids=lambda p: p.name)
def test_notebook_runs(path, capsys):
    """The script is a Jupytext percent notebook whose cells run top to bottom and draw a figure.

    Fails when a notebook's own assert fails, when it raises, when it is no longer in the percent
    format (Jupytext would read it as one cell) or when it stops drawing with matplotlib.
    """
    text = path.read_text()
    assert "# %%" in text and "format_name: percent" in text
    plt.close("all")
    try:
        runpy.run_path(str(path), run_name="__main__")
        assert plt.get_fignums(), f"{path.name} draws no figure"
    finally:
        plt.close("all")


@pytest.mark.slow  # a kernel per notebook (~4 s each); test_notebook_runs checks the same asserts as a script
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_executes_as_a_notebook(path):
    """Executed as a notebook, each derivation shows a PNG figure and no error.

    The route of ``jupytext --to ipynb --set-kernel python3 --execute`` (whose
    ``nbconvert.preprocessors.ExecutePreprocessor`` is an ``nbclient.NotebookClient``): the
    percent script read by Jupytext, run cell by cell in an IPython kernel of this very Python
    (the ``python3`` kernel of ipykernel), in the ``derivations`` folder. Fails when a cell
    raises in a kernel (e.g. code that only works as a script), when the figure is no longer
    displayed as ``image/png`` (e.g. a backend forced in the notebook, or the figure closed before
    the cell ends), or when a cell leaves an error output. Skipped without jupytext, nbclient
    and ipykernel (not dependencies of the package; see derivations/README.md).
    """
    jupytext = pytest.importorskip("jupytext")
    pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    assert len([cell for cell in jupytext.read(path).cells if cell.cell_type == "code"]) > 1, "one cell: percent format?"
    execute = runpy.run_path(str(DERIVATIONS / "execute.py"))["execute"]  # the route of `make notebooks`
    notebook = execute(path, path.parent)
    outputs = [output for cell in notebook.cells if cell.cell_type == "code" for output in cell.outputs]
    errors = [output for output in outputs if output.output_type == "error"]
    assert not errors, [f"{error.ename}: {error.evalue}" for error in errors]
    images = [output for output in outputs if "image/png" in output.get("data", {})]
    assert images, f"{path.name} displays no image/png output"
