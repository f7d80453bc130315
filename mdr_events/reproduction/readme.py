"""The frame of ``results/README.md`` around the sections' parts: its title, the list of every section's files,
and the software it was computed with (whose versions a rewrite of an agreeing report keeps)."""

from __future__ import annotations

import importlib.metadata
import platform
import re
from typing import Iterable

from mdr_events._version import __version__
from mdr_events.io.datasets import DOI
from mdr_events.reproduction.section import Section

__all__ = ["RECORDED_PACKAGES", "title_lines", "file_list_lines", "software_lines", "software_versions",
           "recorded_versions"]

#: Packages whose versions ``results/README.md`` records (the lock file pins them, with the rest).
RECORDED_PACKAGES = ("numpy", "scipy", "sympy", "matplotlib", "xarray", "pandas")
#: How the software section's line of versions begins.
COMPUTED_WITH = "Computed with "


def title_lines() -> list[str]:
    """The report's title, who wrote it and the paper."""
    return [
        "# Reproduction of section 4 of Lyashenko, Popov & Borysiuk (2023)",
        "",
        f"Written by `mdr-events reproduce` (mdr_events {__version__}); do not edit by hand.",
        f"Paper: doi:{DOI}.",
        "",
    ]


def file_list_lines(sections: Iterable[Section]) -> list[str]:
    """The list of files in ``results/``: each section's lines, in the sections' order."""
    return ["## Files", "", *(line for section in sections for line in section.files), ""]


def software_versions() -> dict[str, str]:
    """Python's version and those of :data:`RECORDED_PACKAGES`, as installed now."""
    versions = {"Python": platform.python_version()}
    versions.update({name: importlib.metadata.version(name) for name in RECORDED_PACKAGES})
    return versions


def software_lines(versions: dict[str, str]) -> list[str]:
    """The software section: the versions ``results/`` was computed with, and how other versions compare."""
    return [
        "## Software",
        "",
        COMPUTED_WITH + ", ".join(f"{name} {version}" for name, version in versions.items()) + ".",
        "",
        "`make` installs these versions from the lock file `constraints.txt`. With other versions (or",
        "another CPU) each quantity of the datasets agrees within the accuracy of how it is computed",
        "(`mdr_events.io.agreement`: round-off for closed forms and sums, the integrator's rtol for F_x,",
        "the curvature at an extremum for its time, the optimizer's stopping tolerance for the fit), and",
        "each number of this report within one unit of its last digit, which is coarser than that accuracy;",
        "`mdr-events reproduce` then keeps the files as they are.",
        "",
    ]


def recorded_versions(text: str) -> dict[str, str]:
    """The versions a report's software section records (``{}`` if it has none)."""
    match = re.search(f"^{COMPUTED_WITH}(.*)\\.$", text, flags=re.MULTILINE)
    if match is None:
        return {}
    return dict(item.rsplit(" ", 1) for item in match.group(1).split(", "))
