"""A section of the reproduction: what it computes (in steps, one progress message each), the files it writes
into ``results/`` and its part of ``results/README.md``.

A new section is one module that builds a :class:`Section` and one entry in
:data:`mdr_events.reproduction.runner.SECTIONS`: the runner computes it, plans its files and renders it in that
order, writes every section's files in one commit, and counts its steps.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

from mdr_events.app.result_files import FileOutcome, PlannedFile, commit_groups

__all__ = ["Progress", "Step", "Section", "Reproduction", "FilePlanner"]

#: What hears the progress messages (``print`` on the command line).
Progress = Callable[[str], None]
#: Plans a section's files from its data in a directory (``keep_agreeing``: a file that agrees is planned kept),
#: nothing written: one list of planned files per progress line.
FilePlanner = Callable[[Any, Path, bool], list[list[PlannedFile]]]
#: Everything the report and the files are made of: each section's name -> what it computed.
Reproduction = dict[str, Any]


@dataclass(frozen=True)
class Step:
    """One computation of a section and the progress message that announces it.

    Attributes
    ----------
    message : str
        Sent before it runs.
    run : Callable[[], Any]
        The computation; it reads the parameters when it runs (``Parameters.paper()``), not when defined.
    """

    message: str
    run: Callable[[], Any]


@dataclass(frozen=True)
class Section:
    """One part of ``results/``: its computation, its files, its Markdown.

    Attributes
    ----------
    name : str
        Its key in a :data:`Reproduction`.
    steps : tuple of Step
        What it computes, in order, one progress message each (none: what it reports are closed forms, which
        ``collect`` evaluates).
    collect : Callable[[list], Any]
        The section's data from the results of its steps, in their order.
    render : Callable[[Any], list[str]]
        Its lines of ``results/README.md`` from its data.
    plan : FilePlanner, optional
        Plans its files, drawn and checked but not written (default: it has none); the runner writes every
        section's files in one commit.
    writing : str
        The progress message of its write step, when its files are planned (one step, only if it has files).
    files : tuple of str
        Its lines of the report's list of files.
    """

    name: str
    steps: tuple[Step, ...]
    collect: Callable[[list[Any]], Any]
    render: Callable[[Any], list[str]]
    plan: FilePlanner | None = None
    writing: str = ""
    files: tuple[str, ...] = ()

    @property
    def writes_files(self) -> bool:
        """Whether it writes files (then its write step is one more progress message)."""
        return self.plan is not None

    def write(self, data: Any, out: Path, keep_agreeing: bool) -> list[list[FileOutcome]]:
        """Write its files (planned from ``data``) into ``out``, all in one commit; what became of each, one list
        per progress line."""
        return commit_groups(self.plan(data, out, keep_agreeing)) if self.plan is not None else []

    @property
    def step_count(self) -> int:
        """Its progress messages: one per step, and one for writing its files if it has any."""
        return len(self.steps) + int(self.writes_files)

    def compute(self, progress: Progress) -> Any:
        """Run its steps in order, announcing each to ``progress``, and collect their results."""
        results = []
        for step in self.steps:
            progress(step.message)
            results.append(step.run())
        return self.collect(results)
