"""``mdr-events reproduce``: regenerate ``results/`` and its README.

Everything in ``results/`` is written by :func:`reproduce`, deterministically
(same input, same bytes), so that a test can compare the committed report
with a fresh computation.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable

from . import analytic
from ._version import __version__
from .datasets import DOI, atomic_write
from .parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, Parameters

__all__ = ["reproduce", "report_text", "PAPER_CRITICAL_ANGLES"]

#: Critical angles stated in section 4 (R = 30 mm), degrees.
PAPER_CRITICAL_ANGLES = {"hertz": 23.59, "jkr": 22.87}
RADII = {"R30": 0.03, "R100": 0.1}


def report_text() -> str:
    """The text of ``results/README.md`` (numbers computed afresh)."""
    lines = [
        "# Reproduction of section 4 of Lyashenko, Popov & Borysiuk (2023)",
        "",
        f"Written by `mdr-events reproduce` (mdr_events {__version__}); do not edit by hand.",
        f"Paper: doi:{DOI}.",
        "",
        "## Critical angles of scenario A (slip begins exactly at d_max)",
        "",
        "| R | quantity | paper | mdr_events | difference |",
        "|---|---|---|---|---|",
    ]
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        for key, adhesive, equation in (("hertz", False, "(17)"), ("jkr", True, "(18)")):
            ours = analytic.critical_angle(params, "A", adhesion=adhesive)
            paper = PAPER_CRITICAL_ANGLES[key] if label == "R30" else None
            paper_text = f"{paper:.2f}°" if paper is not None else "not stated"
            diff = f"{ours - paper:+.3f}°" if paper is not None else "—"
            lines.append(f"| {radius * 1e3:g} mm | α_c {key.upper() if key == 'jkr' else 'Hertz'} {equation} "
                         f"| {paper_text} | {ours:.3f}° | {diff} |")
    lines += [
        "",
        "## Scenario B: angle above which the contact comes apart before any spring slides",
        "",
        "From eq. (21) (pull-off branch, Δγ1) at the jump-off point; without adhesion slip",
        "always comes first (90°). Not stated in the paper.",
        "",
        "| R | α (adhesive) |",
        "|---|---|",
    ]
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        lines.append(f"| {radius * 1e3:g} mm | {analytic.critical_angle(params, 'B', adhesion=True):.3f}° |")
    params = Parameters.paper()
    lines += [
        "",
        "## Parameters (R = 30 mm; the R = 100 mm set differs only in R)",
        "",
        "| parameter | value | unit | source |",
        "|---|---|---|---|",
    ]
    for name, value in params.as_dict().items():
        source = "**inferred** (not stated in section 4)" if name in Parameters.INFERRED_FIELDS else "section 4"
        lines.append(f"| {name} ({PARAMETER_LONG_NAMES[name]}) | {value:.6g} | {PARAMETER_UNITS[name]} | {source} |")
    lines += [
        f"| E* | {params.E_star:.6g} | Pa | derived |",
        f"| G* | {params.G_star:.6g} | Pa | derived |",
        "",
        "## Files",
        "",
        "- `phase_diagram_A_R30.{nc,png}`, `phase_diagram_A_R100.{nc,png}`: Fig. 9a.",
        "- `phase_diagram_B_R30.{nc,png}`, `phase_diagram_B_R100.{nc,png}`: Fig. 9b.",
        "",
    ]
    return "\n".join(lines)


def reproduce(out: Path, progress: Callable[[str], None] = print) -> list[Path]:
    """Write every figure, dataset and the report into ``out``."""
    from .cli import _write_phase_diagram

    out = Path(out)
    written: list[Path] = []
    jobs = [(label, radius, scenario) for label, radius in RADII.items() for scenario in ("A", "B")]
    for number, (label, radius, scenario) in enumerate(jobs, start=1):
        figure = "9a" if scenario == "A" else "9b"
        progress(f"[{number}/{len(jobs) + 1}] Fig. {figure}, R = {radius * 1e3:g} mm")
        written += _write_phase_diagram(Parameters.paper(R=radius), scenario, out, f"phase_diagram_{scenario}_{label}")
    progress(f"[{len(jobs) + 1}/{len(jobs) + 1}] results/README.md")
    text = report_text()
    written.append(atomic_write(out / "README.md", lambda temporary: Path(temporary).write_text(text)))
    return written
