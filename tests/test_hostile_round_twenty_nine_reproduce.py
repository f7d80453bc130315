"""Hostile round twenty-nine (issue 32, class 6: all files of one run are replaced together or not at all):
``mdr-events reproduce`` is one run. It computed every section first but then wrote one group of files at a time (a
figure with its datasets), so that an interrupt during the writes left some sections' new files beside the others'
old ones, and ``results/README.md``, which describes them all, old beside new figures. Every section's files are now
planned (drawn, checked, kept or not) and the report too, then all written in one commit.

The runner is driven here on toy sections (``runner.reproduce(..., sections=...)``, the same runner, sections and
commit as ``mdr-events reproduce``, in milliseconds): a previous run, then a new one whose every file differs,
interrupted late in three places.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mdr_events.app.result_files import FileStatus, PlannedFile, text_plan
from mdr_events.io.files import PendingFile
from mdr_events.reproduction import runner
from mdr_events.reproduction.section import Section, Step

#: The files of the toy reproduction: the first section's two groups, the last section's one, the report.
FILES = {"first_a.txt", "first_b.txt", "second.txt", "last.txt", "README.md"}
PREVIOUS, NEW = 1, 2


def _interrupt(*args, **kwargs):
    raise KeyboardInterrupt


def _sections(version: dict, interrupt: str | None = None) -> tuple[Section, ...]:
    """Two sections with files, the last interrupted at ``interrupt``: ``"plan"`` (its files being planned),
    ``"report"`` (its part of the report rendered: after every file is planned) or ``"commit"`` (while the commit
    writes its file, after the first section's files are written to their temporaries)."""
    def first_plans(number: int, out: Path, keep_agreeing: bool) -> list[list[PlannedFile]]:
        return [[text_plan(f"a {number}\n", out / "first_a.txt", keep_agreeing),
                 text_plan(f"b {number}\n", out / "first_b.txt", keep_agreeing)],
                [text_plan(f"second {number}\n", out / "second.txt", keep_agreeing)]]

    def last_plans(number: int, out: Path, keep_agreeing: bool) -> list[list[PlannedFile]]:
        if interrupt == "plan":
            raise KeyboardInterrupt
        if interrupt == "commit":
            return [[PlannedFile(out / "last.txt", PendingFile(out / "last.txt", _interrupt, ".txt"))]]
        return [[text_plan(f"last {number}\n", out / "last.txt", keep_agreeing)]]

    def last_lines(number: int) -> list[str]:
        if interrupt == "report":
            raise KeyboardInterrupt
        return ["", f"Last {number}."]

    first = Section(name="first", steps=(Step("first", lambda: version["number"]),), collect=lambda results: results[0],
                    render=lambda number: ["", f"First {number}."], plan=first_plans, writing="writing first",
                    files=("- `first_*.txt`, `second.txt`",))
    last = Section(name="last", steps=(Step("last", lambda: version["number"]),), collect=lambda results: results[0],
                   render=last_lines, plan=last_plans, writing="writing last", files=("- `last.txt`",))
    return first, last


def _contents(directory: Path) -> dict[str, bytes]:
    """Every file in ``directory`` (hidden temporaries too) -> its bytes."""
    return {path.name: path.read_bytes() for path in sorted(directory.iterdir())}


@pytest.fixture
def previous_run(tmp_path: Path) -> dict[str, bytes]:
    """The output directory as the previous run left it."""
    runner.reproduce(tmp_path / "out", progress=lambda message: None, sections=_sections({"number": PREVIOUS}))
    before = _contents(tmp_path / "out")
    assert set(before) == FILES
    return before


@pytest.mark.parametrize("interrupt", ["plan", "report", "commit"])
def test_an_interrupted_reproduction_leaves_every_previous_file_as_it_was(previous_run, tmp_path, interrupt):
    messages = []
    with pytest.raises(KeyboardInterrupt):
        runner.reproduce(tmp_path / "out", progress=messages.append,
                         sections=_sections({"number": NEW}, interrupt))
    assert _contents(tmp_path / "out") == previous_run, messages
    assert not any("written" in message for message in messages)


@pytest.mark.parametrize("keep_agreeing", [True, False])
def test_a_whole_reproduction_replaces_every_file_and_says_when_it_writes_them(previous_run, tmp_path, keep_agreeing):
    messages = []
    outcomes = runner.reproduce(tmp_path / "out", progress=messages.append, keep_agreeing=keep_agreeing,
                                sections=_sections({"number": NEW}))
    after = _contents(tmp_path / "out")
    assert set(after) == FILES and all(after[name] != previous_run[name] for name in FILES)
    assert {outcome.path.name for outcome in outcomes} == FILES
    assert {outcome.status for outcome in outcomes} == {FileStatus.WRITTEN}
    committing = next(at for at, message in enumerate(messages) if message.startswith("    writing 5 of the 5 files"))
    assert messages[committing - 1].endswith(runner.README_STEP)
    assert [message.split(": ")[1] for message in messages[committing + 1:]] == [
        "first_a.txt, first_b.txt", "second.txt", "last.txt", "README.md"]


def test_a_reproduction_that_agrees_keeps_every_file_and_says_so(previous_run, tmp_path):
    messages = []
    outcomes = runner.reproduce(tmp_path / "out", progress=messages.append, sections=_sections({"number": PREVIOUS}))
    assert _contents(tmp_path / "out") == previous_run
    assert {outcome.status for outcome in outcomes} == {FileStatus.KEPT}
    assert any(message.startswith("    writing 0 of the 5 files") for message in messages)
