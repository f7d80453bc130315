"""The packaging a fresh clone installs: no deprecated metadata, the lock pins what `make` installs."""

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).parent.parent


def test_pyproject_uses_current_metadata():
    """setuptools >= 77 reads an SPDX `license` string; the table form prints a page of deprecation warnings,
    and a flat layout without `package-dir` makes the editable install an import hook with its own warning."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert project["project"]["license"] == "MIT"
    assert "setuptools>=77" in project["build-system"]["requires"]
    assert project["tool"]["setuptools"]["package-dir"] == {"": "."}
    assert project["project"]["scripts"]["mdr-events"] == "mdr_events.app.console:console_main"


def test_the_lock_pins_every_requirement_and_make_installs_with_it():
    """constraints.txt pins (==) every run-time, test and notebook requirement and the build backend, and the
    Makefile hands it to pip as PIP_CONSTRAINT (which also reaches the build's own environment)."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    pins = dict(re.findall(r"^([A-Za-z0-9_.\-]+)==(\S+)$", (ROOT / "constraints.txt").read_text(), flags=re.M))
    pinned = {name.lower().replace("_", "-") for name in pins}
    wanted = [*project["dependencies"], *[r for extra in project["optional-dependencies"].values() for r in extra],
              "setuptools", "pip"]
    for requirement in wanted:
        name = re.match(r"[A-Za-z0-9_.\-]+", requirement).group(0).lower().replace("_", "-")
        assert name in pinned, name
    makefile = (ROOT / "Makefile").read_text()
    assert "PIP_CONSTRAINT=$(CURDIR)/$(LOCK)" in makefile and "LOCK := constraints.txt" in makefile
