"""Execute the derivation notebooks and write them with their outputs: ``make notebooks``.

Each ``derivations/NN_*.py`` (Jupytext percent format) is read by Jupytext, run cell by cell by
nbclient in the ``python3`` kernel of ipykernel (the Python that runs this script: jupyter_client
starts the kernel spec's ``python`` as ``sys.executable``), and written as ``OUT/NN_*.ipynb``.
Needs the ``notebooks`` extra (``pip install -e '.[notebooks]'``; ``make`` installs it).

    python derivations/execute.py --out results/derivations

Cell timings are not recorded, so that the same notebook gives the same file again.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
#: The notebooks, in order: every numbered percent-format script of this folder.
NOTEBOOKS = sorted(HERE.glob("[0-9][0-9]_*.py"))
#: Seconds a cell may run before nbclient gives up.
CELL_TIMEOUT = 600


def execute(path: Path, working_directory: Path):
    """The notebook of ``path``, executed in ``working_directory``; raises on the first failing cell."""
    import jupytext
    import nbclient
    notebook = jupytext.read(path)
    for number, cell in enumerate(notebook.cells):
        cell.id = f"cell-{number}"  # nbformat draws random ids; these make the file the same every time
    client = nbclient.NotebookClient(notebook, kernel_name="python3", timeout=CELL_TIMEOUT, record_timing=False,
                                     resources={"metadata": {"path": str(working_directory)}})
    client.execute()
    return notebook


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="folder for the executed .ipynb files")
    args = parser.parse_args(argv)
    import nbformat

    args.out.mkdir(parents=True, exist_ok=True)
    for path in NOTEBOOKS:
        notebook = execute(path, HERE)
        target = args.out / f"{path.stem}.ipynb"
        temporary = target.with_suffix(".ipynb.tmp")
        nbformat.write(notebook, temporary)
        os.replace(temporary, target)  # never a half-written notebook
        print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
