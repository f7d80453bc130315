"""The committed results/README.md is what a fresh computation writes."""

from pathlib import Path

from mdr_events.report import report_text

RESULTS = Path(__file__).parent.parent / "results"


def test_committed_report_matches_a_fresh_computation():
    assert (RESULTS / "README.md").read_text() == report_text()


def test_report_states_the_papers_numbers_beside_ours():
    text = report_text()
    assert "| 23.59° |" in text and "| 22.87° |" in text
    assert "**inferred**" in text
