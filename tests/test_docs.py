"""The documentation site is wired (``make docs``; docs/conf.py): numpydoc's validation of the public API and the
pages that list it, checked in seconds without a Sphinx build.

The full build (every tutorial and derivation executed, warnings as errors) is ``make docs``; it takes a few
minutes, so it is not part of ``make test``. These tests catch what most often breaks it: an undocumented or
misnamed parameter, a public name without an API page, a derivation without its page.
"""

import importlib.util
import re
from pathlib import Path

import pytest

import mdr_events

DOCS = Path(__file__).resolve().parent.parent / "docs"


def _checks():
    spec = importlib.util.spec_from_file_location("numpydoc_checks", DOCS / "_ext" / "numpydoc_checks.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_public_docstring_passes_numpydoc_validation():
    """Each public function, class, method and property passes the checks of NUMPYDOC_CHECKS (every parameter
    documented with a type, a Returns section, ...), but the known failures, which may only shrink."""
    pytest.importorskip("numpydoc")
    checks = _checks()
    failures = checks.failures()
    known = checks.known_failures()
    new = {name: errors for name, errors in failures.items() if name not in known}
    assert not new, "\n".join(f"{name}: {'; '.join(errors)}" for name, errors in new.items())
    fixed = sorted(known - set(failures))
    assert not fixed, f"these now pass numpydoc's validation: remove them from {checks.KNOWN_FAILURES_FILE.name}: {fixed}"


def test_the_functions_the_paper_numbers_pass_in_full():
    """The top-level functions a user calls first pass every check, none of them on the list of known failures."""
    pytest.importorskip("numpydoc")
    known = _checks().known_failures()
    first = {"simulate", "validate", "fit", "sweep", "convergence_study", "critical_angle", "d_crit", "jkr_depth",
             "jkr_normal_force", "jkr_contact_radius", "pull_off_force", "jump_off", "critical_shift",
             "fretting_dissipated_energy", "phase_diagram", "cross_check", "open_result", "write_netcdf",
             "load_study", "run_study"}
    assert not {f"mdr_events.{name}" for name in first} & known


def test_the_api_reference_lists_every_public_name():
    """docs/api/index.rst names every entry of mdr_events.__all__ (a new public name needs its page)."""
    text = (DOCS / "api" / "index.rst").read_text()
    listed = set(re.findall(r"^\s+([A-Za-z_][\w.]*)\s*$", text, flags=re.MULTILINE))
    listed |= set(re.findall(r"^\.\. autodata:: (\w+)", text, flags=re.MULTILINE))
    modules = {"analytic": "theory.analytic", "power_law": "theory.power_law", "mindlin": "theory.mindlin",
               "tabulated": "theory.tabulated", "symbolic": "theory.symbolic", "continuum": "models.continuum"}
    missing = [name for name in mdr_events.__all__ if modules.get(name, name) not in listed]
    assert not missing, f"not in docs/api/index.rst: {missing}"


def test_every_derivation_and_tutorial_has_its_page():
    """The derivations' index names each derivations/NN_*.py, and the tutorials' index each tutorial file."""
    derivations = sorted(path.stem for path in (DOCS.parent / "derivations").glob("[0-9][0-9]_*.py"))
    index = (DOCS / "derivations" / "index.md").read_text()
    assert derivations and all(re.search(rf"^{stem}$", index, flags=re.MULTILINE) for stem in derivations)
    tutorials = sorted(path.stem for path in (DOCS / "tutorials").glob("*.md") if path.stem != "index")
    index = (DOCS / "tutorials" / "index.md").read_text()
    assert tutorials and all(re.search(rf"^{stem}$", index, flags=re.MULTILINE) for stem in tutorials)


def test_the_makefile_builds_the_docs_with_warnings_as_errors():
    makefile = (DOCS.parent / "Makefile").read_text()
    assert re.search(r"^docs: ", makefile, flags=re.MULTILINE)
    assert "-W --keep-going" in makefile and "docs/_build/html" in makefile


def test_the_notebooks_keep_their_inline_figures():
    """Neither the Makefile's docs target nor docs/conf.py forces a matplotlib backend: the kernels that execute the
    tutorials inherit the environment, and MPLBACKEND=Agg there would leave every page without its figures."""
    recipe = (DOCS.parent / "Makefile").read_text().split("\ndocs:", 1)[1].split("\n\n", 1)[0]
    assert "env -u MPLBACKEND" in recipe and "MPLBACKEND=" not in recipe
    assert "MPLBACKEND" not in (DOCS / "conf.py").read_text()
