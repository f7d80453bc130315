"""The reproduction as sections: the one Markdown table helper, a section's steps, and the runner that counts them,
computes, writes and renders in the sections' order (toy sections here: the real ones in test_report.py)."""

import re

import pytest

from mdr_events.app.result_files import FileStatus, text_plan
from mdr_events.reproduction import runner
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


def test_the_step_count_is_the_sections_steps_their_writes_and_the_report():
    sections = runner.SECTIONS
    assert runner.COMPUTE_STEPS == sum(len(section.steps) for section in sections)
    assert runner.step_count() == runner.COMPUTE_STEPS + sum(section.writes_files for section in sections) + 1
    assert runner.step_count() == sum(section.step_count for section in sections) + 1
    assert len({section.name for section in sections}) == len(sections)
    for section in sections:
        assert bool(section.writing) == section.writes_files, section.name
        assert all(isinstance(step.message, str) and step.message for step in section.steps), section.name


def test_the_report_lists_the_files_of_every_section_in_order():
    files = [line for section in runner.SECTIONS for line in section.files]
    assert files[0].startswith("- `phase_diagram_A_R30") and files[-2].startswith("- `finite_layer_critical_angles")
    assert files[-4].startswith("- `fig8_R30_layer.png`") and files[-6].startswith("- `finite_layer_pull_off.png`")
    assert files[-7].startswith("- `rate_adhesion_critical_angle_B.png`")
    assert files[-8].startswith("- `rate_adhesion_A20.png`") and files[-11].startswith("- `rate_adhesion_pull_off.png`")
    assert files[-12] == "  exact MDR and its figure (where LAMMPS is installed)."


# ----------------------------------------------------------------------------------------------
# the runner, on toy sections


def _toy_sections(log: list[str]) -> tuple[Section, ...]:
    def counted(number: int) -> int:
        log.append(f"run {number}")
        return number

    def plan(total: int, out, keep_agreeing: bool) -> list[list]:
        return [[text_plan(f"{total}\n", out / "total.txt", keep_agreeing)]]

    counting = Section(name="counting", steps=(Step("one", lambda: counted(1)), Step("two", lambda: counted(2))),
                       collect=sum, render=lambda total: ["", f"## Total {total}"], plan=plan,
                       writing="writing total.txt", files=("- `total.txt`: the total.",))
    closing = Section(name="closing", steps=(), collect=lambda results: "closed form",
                      render=lambda text: ["", f"A {text}.", ""])
    return counting, closing


def test_a_section_announces_each_step_before_it_runs():
    log = []
    counting, closing = _toy_sections(log)
    assert counting.compute(log.append) == 3 and log == ["one", "run 1", "two", "run 2"]
    assert closing.compute(log.append) == "closed form" and counting.step_count == 3 and closing.step_count == 0


def test_the_runner_numbers_every_step_out_of_the_count_and_writes_the_report_last(tmp_path):
    sections = _toy_sections([])
    messages = []
    outcomes = runner.reproduce(tmp_path / "out", progress=messages.append, sections=sections)
    total = runner.step_count(sections)
    assert total == 2 + 1 + 1
    numbered = [message for message in messages if message.startswith("[")]
    assert numbered == [f"[1/{total}] one", f"[2/{total}] two", f"[3/{total}] writing total.txt",
                        f"[4/{total}] {runner.README_STEP}"]
    assert [outcome.path.name for outcome in outcomes] == ["total.txt", "README.md"]
    text = (tmp_path / "out" / "README.md").read_text()
    assert "\n## Total 3\n\nA closed form.\n\n## Files\n\n- `total.txt`: the total.\n\n## Software\n" in text
    assert text == runner.report_text(runner.compute(sections=sections), sections=sections)
    again = runner.reproduce(tmp_path / "out", progress=lambda message: None, sections=sections)
    assert {outcome.status for outcome in again} == {FileStatus.KEPT}


def test_the_runner_checks_the_output_directory_before_computing(tmp_path):
    log = []
    (tmp_path / "a_file").write_text("precious")
    with pytest.raises(ValueError, match="it is a file"):
        runner.reproduce(tmp_path / "a_file", progress=log.append, sections=_toy_sections(log))
    assert log == []
