"""The documentation site is wired (``make docs``; docs/conf.py): numpydoc's validation of the public API and the
pages that list it, checked in seconds without a Sphinx build.

The full build (every tutorial and derivation executed, warnings as errors) runs in ``tests/test_docs_build.py``,
with the smoke tests of the built site. These tests catch what most often breaks it: an undocumented or misnamed
parameter, a public name without an API page, a derivation without its page.
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
    documented with a type, a Returns section, ...): there is no list of known failures."""
    pytest.importorskip("numpydoc")
    checks = _checks()
    failures = checks.failures()
    assert len(checks.public_objects()) > 300
    assert not failures, "\n".join(f"{name}: {'; '.join(errors)}" for name, errors in failures.items())
    assert not (DOCS / "_ext" / "numpydoc_known_failures.txt").exists()


def test_the_functions_the_paper_numbers_are_validated():
    """The top-level functions a user calls first are among the objects validated, none excluded from the build's
    validation."""
    pytest.importorskip("numpydoc")
    checks = _checks()
    first = {"simulate", "validate", "fit", "sweep", "convergence_study", "critical_angle", "d_crit", "jkr_depth",
             "jkr_normal_force", "jkr_contact_radius", "pull_off_force", "jump_off", "critical_shift",
             "fretting_dissipated_energy", "phase_diagram", "cross_check", "open_result", "write_netcdf",
             "load_study", "run_study"}
    names = {f"mdr_events.{name}" for name in first}
    assert names <= set(checks.public_objects())
    excluded = re.compile("|".join(checks.public_exclude()))
    assert not {name for name in names if excluded.search(name)}


def test_the_functions_of_the_paper_s_equations_typeset_them():
    """Each of the paper's equations (3)-(21) that a function evaluates is typeset (``:math:`` or ``.. math::``)
    with its number in that function's docstring."""
    from mdr_events.contact import friction
    from mdr_events.models import discrete
    from mdr_events.models.continuum import anchors, branch, model
    from mdr_events.models.paths import Path
    from mdr_events.theory import analytic, mindlin, phase, power_law, symbolic, tabulated

    typeset = {
        "(3)": [symbolic.abel_transform, power_law.equivalent_profile, tabulated.equivalent_profile],
        "(4)": [discrete.paraboloid_profile],
        "(5)": [discrete.run_discrete],
        "(6)": [discrete.run_discrete],
        "(7)": [discrete.run_discrete],
        "(8)": [power_law.hess_prefactor, discrete.hysteresis_thresholds],
        "(9)": [analytic.jkr_depth, power_law.branch_depth, tabulated.contact_radius, branch.Branch],
        "(10)": [analytic.jkr_normal_force, analytic.normal_force, power_law.normal_force, tabulated.normal_force,
                 model.ContinuumModel.normal_force],
        "(13)": [analytic.critical_shift, friction.FrictionLaw, discrete.run_discrete],
        "(14)": [Path.scenario_A],
        "(15)": [anchors.AnchorMap.tangential_force, discrete.run_discrete],
        "(16)": [analytic.hertz_contact_radius],
        "(17)": [power_law.d_crit_A, mindlin.d_crit_A, tabulated.d_crit_A, phase.phase_diagram],
        "(18)": [power_law.critical_angle_A, tabulated.critical_angle_A, phase.phase_diagram],
        "(19)": [Path.scenario_B],
        "(20)": [power_law.d_crit_B, mindlin.d_crit_B, mindlin.d_crit_B_indentation, phase.phase_diagram],
        "(21)": [power_law.critical_angle_B, power_law.d_crit_B_indentation, phase.phase_diagram],
    }
    missing = []
    for number, functions in typeset.items():
        for function in functions:
            doc = function.__doc__ or ""
            maths = re.findall(r"\.\. math::(.*?\S.*?)(?:\n\s*\n|$)", doc, flags=re.DOTALL)
            maths += re.findall(r":math:`([^`]*)`", doc)
            if not any(number in block or re.search(r"\(\d+\), " + re.escape(number), block) for block in maths):
                missing.append(f"{function.__qualname__} {number}")
    assert not missing, missing


def test_the_study_format_names_every_indenter_and_friction_law():
    """The study docstring's [profile] and [friction] tables, and the reference page's notes
    (study_format.KEY_NOTES), name every key the reader takes and every friction law."""
    from mdr_events.app import study, study_format
    from mdr_events.contact.friction import FRICTION_LAWS

    doc = study.__doc__
    profile = doc.split("[profile]", 1)[1].split("[output]", 1)[0]
    for key in study_format.SCHEMA["profile"]:
        assert re.search(rf"\b{key}\b", profile), key
        assert ("profile", key) in study_format.KEY_NOTES
    for key in study_format.SCHEMA["friction"]:
        assert ("friction", key) in study_format.KEY_NOTES
    for law in FRICTION_LAWS:
        assert f'"{law}"' in profile and f"'{law}'" in study_format.KEY_NOTES["friction", "law"], law


def test_the_readme_is_a_front_page_whose_sections_live_in_the_docs():
    """The README is short and links into docs/ with relative links that resolve; the pages it links hold what it
    held before (the model, the Python interface, the errors, the install and tests)."""
    readme = (DOCS.parent / "README.md").read_text()
    assert len(readme.splitlines()) <= 150
    links = re.findall(r"\]\(((?:docs/|results/|ARCHITECTURE)[^)#]*)\)", readme)
    assert {"docs/install.md", "docs/model.md", "docs/guide.md", "docs/errors_and_limits.md"} <= set(links)
    assert all((DOCS.parent / link).is_file() for link in links), links
    for page, heading in (("install.md", "## Testing"), ("model.md", "# The model and its assumptions"),
                          ("guide.md", "### Fit to your measurements"), ("errors_and_limits.md", "# Errors and limits")):
        assert heading in (DOCS / page).read_text(), (page, heading)
    index = (DOCS / "index.md").read_text()
    assert all(re.search(rf"^{page}$", index, flags=re.MULTILINE) for page in ("install", "model", "guide",
                                                                               "errors_and_limits"))


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


def test_no_cross_reference_is_split_across_lines():
    """A role's target broken at a dot (``:func:`~a.b.`` then ``c``` on the next line) resolves to nothing: the
    documentation build (slow) fails on it; this finds it in every module at once."""
    split = re.compile(r":(?:func|class|meth|mod|data|attr|obj|exc):`[~.\w]*\.\s*$", re.MULTILINE)
    package = Path(mdr_events.__file__).parent
    found = [f"{path.relative_to(package)}:{text[:match.start()].count(chr(10)) + 1}"
             for path in sorted(package.rglob("*.py")) for text in [path.read_text(encoding="utf-8")]
             for match in split.finditer(text)]
    assert not found, found


def test_no_control_character_hides_in_a_module():
    r"""A formula written through a string that is not raw (``"\frac"``, ``"\text"``) leaves a form feed or a tab in
    the file: the page shows ``rac`` and the math fails; the documentation build (slow) only warns about the markup."""
    package = Path(mdr_events.__file__).parent
    found = [str(path.relative_to(package)) for path in sorted(package.rglob("*.py"))
             if re.search(r"[\x00-\x08\x0b\x0c\x0e-\x1f\t]", path.read_text(encoding="utf-8"))]
    assert not found, found
