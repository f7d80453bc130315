"""The documentation site builds as ``make docs`` builds it, and what it shows renders: part of ``make test-all``,
which CI runs (``.ci/run``), so that a broken docstring, reference or tutorial fails CI.

The build (every tutorial and derivation notebook executed, warnings as errors, nitpicky) runs once for the module,
into a temporary directory, in about a minute (three on a loaded 2-core machine); pytest-xdist (``--dist
loadscope``) gives this module a worker of its own, so the rest of the suite runs beside it. The smoke tests then
read the built site: its front page and an API page exist, the front page's figure is referenced and present, an
executed tutorial shows its figures, and the equations are typeset by a MathJax served from the site itself (no
network). Where a headless Chromium is installed (Debian: ``chromium-headless-shell``), it opens the front page and
an API page offline and checks that MathJax rendered the equations without an error and the figure was decoded.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

#: The whole build (about a minute quiet): `make test-all` and CI run it, `make test` leaves it out.
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
#: An API page whose docstring typesets one of the paper's equations, eq. (9).
API_PAGE = Path("api") / "generated" / "mdr_events.jkr_depth.html"
#: The front page's figure (docs/index.md).
FIGURE = "phase_diagram_A_R30.png"
#: A tutorial executed during the build, which draws figures.
TUTORIAL = Path("tutorials") / "reproduce_the_paper.html"

# looked up, not imported: importing Sphinx and its theme costs every pytest-xdist worker about a second at collection,
# for a module that `make test` deselects (slow); the build imports them in its own process
if any(importlib.util.find_spec(_module) is None
       for _module in ("sphinx", "numpydoc", "myst_nb", "sphinxarg", "pydata_sphinx_theme")):
    pytest.skip("the extra 'docs' is not installed (make installs it)", allow_module_level=True)


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """The site built as ``make docs`` builds it (the Makefile's recipe: autosummary's stubs made afresh,
    MPLBACKEND unset so that the tutorials' figures are inline), into a temporary directory."""
    for stubs in (DOCS / "api" / "generated", DOCS / "api" / "internals"):
        shutil.rmtree(stubs, ignore_errors=True)
    out = tmp_path_factory.mktemp("docs")
    env = {name: value for name, value in os.environ.items() if name != "MPLBACKEND"}
    result = subprocess.run([sys.executable, "-m", "sphinx", "-b", "html", "-W", "--keep-going", "-n", "-q",
                             "-d", str(out / "doctrees"), "docs", str(out / "html")],
                            cwd=ROOT, env=env, capture_output=True, text=True, timeout=3600)
    warnings = [line for line in result.stderr.splitlines() if "IPKernelApp" not in line]
    assert result.returncode == 0, "the documentation build failed:\n" + "\n".join(warnings[-60:])
    return out / "html"


def _local(page: Path, reference: str) -> Path:
    """The file a page's relative ``src`` points at."""
    return (page.parent / reference.split("?")[0]).resolve()


def test_the_site_has_its_front_page_and_an_api_page(site):
    assert (site / "index.html").is_file()
    assert (site / API_PAGE).is_file()
    generated = {path.stem for path in (site / "api" / "generated").glob("mdr_events.*.html")}
    assert {"mdr_events.simulate", "mdr_events.Contact", "mdr_events.theory.power_law"} <= generated
    module = (site / "api" / "generated" / "mdr_events.theory.power_law.html").read_text(encoding="utf-8")
    assert 'id="mdr_events.theory.power_law.d_crit_A"' in module


def test_the_front_page_shows_its_figure(site):
    index = site / "index.html"
    sources = re.findall(r'<img [^>]*src="([^"]+)"', index.read_text(encoding="utf-8"))
    figure = [source for source in sources if source.endswith(FIGURE)]
    assert figure, f"{FIGURE} is not referenced by index.html: {sources}"
    path = _local(index, figure[0])
    assert path.is_file() and path.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_an_executed_tutorial_shows_its_figures(site):
    """The tutorials run during the build: their figures are in the page (inline PNG images of their outputs)."""
    page = site / TUTORIAL
    html = page.read_text(encoding="utf-8")
    images = [source for source in re.findall(r'<img [^>]*src="([^"]+)"', html) if source.endswith(".png")]
    assert images, f"{TUTORIAL} shows no figure"
    assert all(_local(page, source).is_file() for source in images)


def test_the_equations_are_typeset_by_a_local_mathjax(site):
    """The API page of jkr_depth holds its equation (9) as math for MathJax, whose script is the site's own copy
    (the build needs no network, nor does reading the site)."""
    page = site / API_PAGE
    html = page.read_text(encoding="utf-8")
    assert re.search(r'class="math[^"]*"[^>]*>\s*\\\[.*\\qquad \(9\)', html, flags=re.DOTALL)
    scripts = re.findall(r'<script [^>]*src="([^"]*(?:mathjax|MathJax)[^"]*)"', html)
    assert scripts and not any(source.startswith(("http:", "https:", "//")) for source in scripts), scripts
    assert all(_local(page, source).is_file() for source in scripts)


def _browser() -> str | None:
    return next((found for name in ("chromium-headless-shell", "chromium", "chromium-browser")
                 if (found := shutil.which(name))), None)


#: Run in the page once it has loaded (and MathJax has had its time): the equations MathJax typeset, its errors,
#: and each image's decoded width, written as attributes of <html> for the DOM that Chromium dumps.
PROBE = """<script>window.addEventListener("load", function () { setTimeout(function () {
  var root = document.documentElement;
  root.setAttribute("data-smoke-math", document.querySelectorAll("mjx-container").length);
  root.setAttribute("data-smoke-math-errors", document.querySelectorAll("mjx-merror").length);
  root.setAttribute("data-smoke-images", Array.from(document.images).map(function (image) {
    return image.getAttribute("src").split("/").pop() + "=" + image.naturalWidth; }).join(" "));
}, 3000); });</script>"""


def _rendered(site: Path, page: Path) -> dict[str, str]:
    """The probe's attributes after Chromium opened a copy of ``page`` (beside it, so that its relative links hold)
    with every host name unresolvable: what renders, renders offline."""
    source = site / page
    copy = source.with_name("_smoke_" + source.name)
    copy.write_text(source.read_text(encoding="utf-8").replace("</head>", PROBE + "</head>", 1), encoding="utf-8")
    result = subprocess.run([_browser(), "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                             "--host-resolver-rules=MAP * ~NOTFOUND", "--allow-file-access-from-files",
                             "--virtual-time-budget=30000", "--dump-dom", copy.as_uri()],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-3000:]
    return dict(re.findall(r'data-smoke-([a-z-]+)="([^"]*)"', result.stdout))


@pytest.mark.skipif(_browser() is None, reason="no headless Chromium (Debian: apt-get install chromium-headless-shell)")
def test_a_browser_renders_the_math_and_the_figure(site):
    api = _rendered(site, API_PAGE)
    assert int(api.get("math", 0)) >= 1 and api.get("math-errors") == "0", api
    front = _rendered(site, Path("index.html"))
    widths = dict(item.split("=") for item in front.get("images", "").split())
    assert int(widths.get(FIGURE, 0)) > 0, front
