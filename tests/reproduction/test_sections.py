"""The reproduction as sections: the one Markdown table helper and a section's steps (toy sections here)."""

import re

import pytest

from mdr_events.app.result_files import write_text
from mdr_events.reproduction.markdown import markdown_table, relative_difference_text
from mdr_events.reproduction.section import Section, Step


def test_a_table_is_its_header_its_rule_and_one_line_per_row():
    assert markdown_table(["R", "α"], [["30 mm", "20°"], ["100 mm", "—"]]) == [
        "| R | α |", "|---|---|", "| 30 mm | 20° |", "| 100 mm | — |"]


def test_a_table_aligns_its_columns_as_asked():
    lines = markdown_table(["set", "S", "inside"], [["paper", "1.0", "yes"]], ["default", "right", "centre"])
    assert lines[1] == "|---|---:|:---:|"


def test_a_table_without_rows_is_its_header_and_rule():
    assert markdown_table(["method", "max \\|F_x\\|"], []) == ["| method | max \\|F_x\\| |", "|---|---|"]


@pytest.mark.parametrize("header, rows, alignments, match", [
    (["a", "b"], [["1"]], None, "has 1 cells; allowed: one per column"),
    (["a", "b"], [["1", "2", "3"]], None, "has 3 cells"),
    (["a", "b"], [], ["right"], "has 1 entries; allowed: one per column"),
    (["a"], [], ["left"], "alignment 'left' is not allowed; allowed: default, right, centre"),
])
def test_a_table_refuses_rows_or_alignments_that_do_not_fit(header, rows, alignments, match):
    with pytest.raises(ValueError, match=re.escape(match)):
        markdown_table(header, rows, alignments)


def test_round_off_prints_as_its_bound():
    assert relative_difference_text(3e-13) == "< 1e-12" and relative_difference_text(2.5e-9) == "2.5e-09"


# ----------------------------------------------------------------------------------------------
# toy sections


def _toy_sections(log: list[str]) -> tuple[Section, ...]:
    def counted(number: int) -> int:
        log.append(f"run {number}")
        return number

    def write(total: int, out, keep_agreeing: bool) -> list[list]:
        return [[write_text(f"{total}\n", out / "total.txt", keep_agreeing)]]

    counting = Section(name="counting", steps=(Step("one", lambda: counted(1)), Step("two", lambda: counted(2))),
                       collect=sum, render=lambda total: ["", f"## Total {total}"], write=write,
                       writing="writing total.txt", files=("- `total.txt`: the total.",))
    closing = Section(name="closing", steps=(), collect=lambda results: "closed form",
                      render=lambda text: ["", f"A {text}.", ""])
    return counting, closing


def test_a_section_announces_each_step_before_it_runs():
    log = []
    counting, closing = _toy_sections(log)
    assert counting.compute(log.append) == 3 and log == ["one", "run 1", "two", "run 2"]
    assert closing.compute(log.append) == "closed form" and counting.step_count == 3 and closing.step_count == 0
