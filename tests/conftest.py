import functools
import io
import os
import signal
import subprocess
import sys

import pytest
from hypothesis import settings

from mdr_events import Parameters

# CI runs the property tests on a fixed set of examples (derandomized: the same run every time, no
# example database written into the clone); HYPOTHESIS_PROFILE=explore draws fresh examples, five
# times as many (tests/quick_round.py's examples scales the counts), to hunt for new counterexamples.
settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
settings.register_profile("explore", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_configure(config):
    """The quick round (``make test``: ``-m "not slow"``) draws fewer examples of each property test
    (``quick_round.examples``); ``make test-all`` and CI all of them."""
    import quick_round

    quick_round.QUICK[0] = config.getoption("markexpr", "") == "not slow"
    # A suite started as a background job (``cmd &`` without job control) inherits Ctrl-C ignored, and so would every
    # command the tests start and interrupt: their children get Ctrl-C's default back (a handler of this process is
    # reset at their exec; SIG_IGN would be inherited). The background case itself is tested where it matters
    # (test_hostile_round_nine: a swallowed SIGTERM with SIGINT ignored).
    if signal.getsignal(signal.SIGINT) == signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


@pytest.fixture(scope="session")
def paper():
    return Parameters.paper()


@pytest.fixture(scope="session")
def paper_r100():
    return Parameters.paper(R=0.1)


@pytest.fixture(autouse=True)
def close_figures():
    """Close every matplotlib figure a test left open (only if pyplot was imported at all: importing it here
    would pick a backend for every test)."""
    yield
    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close("all")


@pytest.fixture
def command(capsys, monkeypatch):
    """``command(*args, cwd=None, fresh=False)``: ``mdr-events *args`` run in ``cwd``, as
    ``subprocess.CompletedProcess`` (``returncode``, ``stdout``, ``stderr``).

    In-process by :func:`mdr_events.app.cli.main`, the code the console script runs, without paying the package's
    imports again in a fresh interpreter (some 1.5 s of CPU a call, most of what a refused command costs);
    ``fresh=True`` runs ``python -m mdr_events.app.cli`` in a subprocess instead, as a hostile round does for one case
    of each class of what failed (the console script's own exit and stderr)."""
    def run(*args: str, cwd=None, fresh: bool = False) -> subprocess.CompletedProcess:
        if fresh:
            return subprocess.run([sys.executable, "-m", "mdr_events.app.cli", *args], capture_output=True, text=True,
                                  timeout=300, cwd=cwd)
        from mdr_events.app.cli import main

        capsys.readouterr()
        with monkeypatch.context() as patch:
            if cwd is not None:
                patch.chdir(cwd)
            status = main(list(args))
        out, err = capsys.readouterr()
        return subprocess.CompletedProcess(list(args), status, out, err)

    return run


@functools.cache
def _placeholder_png() -> bytes:
    """A 1×1 PNG (what :func:`without_drawing`'s figures are written as): read back by matplotlib as any PNG is."""
    import numpy as np
    from matplotlib import image

    buffer = io.BytesIO()
    image.imsave(buffer, np.zeros((1, 1, 4)), format="png")
    return buffer.getvalue()


@pytest.fixture
def without_drawing(monkeypatch):
    """Every figure a command or a writer makes is built (its ``plot_*`` function runs) and its texts are laid out (a
    title, label or legend entry that cannot be typeset still fails), but it is not drawn: ``figure_png`` closes it
    and gives a 1×1 PNG. For a test that checks something else than the figure's pixels (the layout and drawing of a
    figure are 0.2-0.6 s of CPU, most of a small command's; make test's time, issue 28 item 4). The figure of each kind
    of output (simulation, phase diagram, validation, fit, convergence study, LAMMPS check) is still drawn by other
    tests: tests/plotting, the console-script tests, and those that read a figure's PNG or name it."""
    from matplotlib.text import Text

    from mdr_events.app import fit_files, result_files, validation_files
    from mdr_events.plotting import figures

    def placeholder(figure) -> bytes:
        try:
            renderer = figure.canvas.get_renderer()
            for text in figure.findobj(Text):
                if text.get_visible() and text.get_text():
                    text.get_window_extent(renderer)
        finally:
            figures.plt.close(figure)
        return _placeholder_png()

    for module in (figures, fit_files, result_files, validation_files):
        monkeypatch.setattr(module, "figure_png", placeholder)


@pytest.fixture
def without_run_figures(monkeypatch):
    """``without_run_figures()``: from then on in the test, each validated run's report is rendered with its Markdown
    but an empty figure (no drawing: some 0.5 s of CPU a run), for a test that checks something else than the runs'
    figures (drawn and checked by tests/app/test_validate_cli.py's other tests; make test's time, issue 28 item 4)."""
    from mdr_events.app import validation_files

    def patch() -> None:
        monkeypatch.setattr(validation_files, "render_validation", lambda report, stem: validation_files.RenderedReport(
            stem, report, validation_markdown(report, stem), b""))

    validation_markdown = validation_files.validation_markdown
    return patch
