"""``mdr-events reproduce``: compute every section, write its files into ``results/``, then ``results/README.md``.

Everything in ``results/`` is written deterministically (same input, same bytes), so that a test can compare the
committed report with a fresh computation. The runner knows the sections only as :class:`Section` values, in the
order of :data:`SECTIONS` (the report's order): it computes each (announcing every step), plans each section's
files (one step each: drawn, checked, kept or not), then the report, writes them all in one commit (an interrupt
or an error leaves ``results/`` as it was, never new figures beside an old report) and numbers the steps out of a
total it counts from the sections.
"""

from __future__ import annotations

from pathlib import Path
from typing import Iterable

from mdr_events.app.result_files import FileOutcome, PlannedFile, commit_groups, describe_outcomes, text_plan
from mdr_events.io.agreement import rounded_text_differences
from mdr_events.io.files import prepare_output_directory
from mdr_events.reproduction.critical_angles import CRITICAL_ANGLES
from mdr_events.reproduction.convergence import CONVERGENCE
from mdr_events.reproduction.cross_check import CROSS_CHECK
from mdr_events.reproduction.figures import FIGURES
from mdr_events.reproduction.finite_layer import FINITE_LAYER
from mdr_events.reproduction.layer_angles import LAYER_ANGLES
from mdr_events.reproduction.layer_figures import LAYER_FIGURES
from mdr_events.reproduction.fit_demo import FIT
from mdr_events.reproduction.fretting import FRETTING
from mdr_events.reproduction.lammps import LAMMPS
from mdr_events.reproduction.mindlin import MINDLIN
from mdr_events.reproduction.mindlin_adhesive import MINDLIN_ADHESIVE
from mdr_events.reproduction.parameter_table import PARAMETERS
from mdr_events.reproduction.phase_diagrams import PHASE_DIAGRAMS
from mdr_events.reproduction.profiles import PROFILES
from mdr_events.reproduction.rate_adhesion import RATE_ADHESION
from mdr_events.reproduction.readme import (file_list_lines, recorded_versions, software_lines, software_versions,
                                            title_lines)
from mdr_events.reproduction.section import Progress, Reproduction, Section
from mdr_events.reproduction.universal import UNIVERSAL

__all__ = ["SECTIONS", "COMPUTE_STEPS", "step_count", "compute", "report_text", "reproduce", "README_STEP"]

#: The sections in the report's order, which is also the order they are computed and written in.
SECTIONS: tuple[Section, ...] = (PHASE_DIAGRAMS, CRITICAL_ANGLES, CROSS_CHECK, FIGURES, CONVERGENCE, FRETTING, FIT,
                                 UNIVERSAL, PROFILES, MINDLIN, MINDLIN_ADHESIVE, LAMMPS, RATE_ADHESION, FINITE_LAYER,
                                 LAYER_FIGURES, LAYER_ANGLES, PARAMETERS)
#: Progress messages :func:`compute` sends: one per step of every section.
COMPUTE_STEPS = sum(len(section.steps) for section in SECTIONS)
#: The progress message of the last step, writing the report.
README_STEP = "writing README.md"


def step_count(sections: Iterable[Section] = SECTIONS) -> int:
    """The steps :func:`reproduce` numbers: every section's (its computations and, if it has files, writing them)
    and writing the report."""
    return sum(section.step_count for section in sections) + 1


def compute(progress: Progress | None = None, sections: Iterable[Section] = SECTIONS) -> Reproduction:
    """Compute every section (a few minutes on one core); ``progress`` hears one message per step
    (:data:`COMPUTE_STEPS` of them for :data:`SECTIONS`)."""
    say = progress or (lambda message: None)
    return {section.name: section.compute(say) for section in sections}


def report_text(data: Reproduction | None = None, versions: dict[str, str] | None = None,
                sections: Iterable[Section] = SECTIONS) -> str:
    """The text of ``results/README.md``: the title, each section's part, the list of files and the software.

    Parameters
    ----------
    data : Reproduction, optional
        What the sections computed (default: computed afresh).
    versions : dict, optional
        The software versions to record (default :func:`~mdr_events.reproduction.readme.software_versions`).
    sections : iterable of Section
        Default :data:`SECTIONS`.
    """
    sections = tuple(sections)
    data = compute(sections=sections) if data is None else data
    lines = title_lines()
    for section in sections:
        lines += section.render(data[section.name])
    lines += file_list_lines(sections)
    lines += software_lines(software_versions() if versions is None else versions)
    return "\n".join(lines)


def _report_to_write(data: Reproduction, sections: tuple[Section, ...], readme: Path, keep_agreeing: bool,
                     plans: list[PlannedFile]) -> str:
    """The report's text; the one on disk if every other file is kept and only its software versions differ, so
    that ``git status`` stays clean on a machine whose rounding or versions differ."""
    text = report_text(data, sections=sections)
    if keep_agreeing and readme.exists() and all(plan.pending is None for plan in plans):
        existing = readme.read_text()
        recorded = recorded_versions(existing)
        if recorded and not rounded_text_differences(report_text(data, recorded, sections), existing):
            return existing  # the files on disk were written with the versions it records
    return text


def reproduce(out: Path, progress: Progress = print, keep_agreeing: bool = True,
              sections: Iterable[Section] = SECTIONS) -> list[FileOutcome]:
    """Write every section's files and the report into ``out``, all in one commit; ``progress`` hears each step,
    numbered, then when the files are written and what became of each (one line per group of files).

    Every section is computed and its files planned (drawn, checked, kept or not) before the first file is written,
    and they are written together (:func:`~mdr_events.app.result_files.commit_groups`): an interrupt or an error
    leaves ``out`` as it was. With ``keep_agreeing`` (the default) a file that agrees with the fresh computation is
    not rewritten (:mod:`mdr_events.app.result_files`), and the report keeps the software versions it records when
    every other file is kept and its numbers are unchanged. ``out`` is checked before anything is computed.
    """
    out = prepare_output_directory(out, "out")
    sections = tuple(sections)
    total = step_count(sections)
    count = iter(range(1, total + 1))
    groups: list[list[PlannedFile]] = []

    def step(message: str) -> None:
        progress(f"[{next(count)}/{total}] {message}")

    data = compute(step, sections)
    for section in sections:
        if section.plan is not None:
            step(section.writing)
            groups += section.plan(data[section.name], out, keep_agreeing)
    step(README_STEP)
    readme = out / "README.md"
    others = [plan for group in groups for plan in group]
    groups.append([text_plan(_report_to_write(data, sections, readme, keep_agreeing, others), readme,
                             keep_agreeing, rounded=True)])
    progress(_committing(groups, out))
    outcomes = commit_groups(groups)
    for group in outcomes:
        progress(f"    {describe_outcomes(group)}")
    return [outcome for group in outcomes for outcome in group]


def _committing(groups: list[list[PlannedFile]], out: Path) -> str:
    """The progress line said just before the files are written: how many, together, and how many are kept."""
    plans = [plan for group in groups for plan in group]
    kept = sum(plan.pending is None for plan in plans)
    return (f"    writing {len(plans) - kept} of the {len(plans)} files into {out} together ({kept} agree and are "
            "kept); what became of each:")
