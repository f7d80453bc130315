"""The twenty-ninth hostile round (issue 32), a new user's first day (class 7): what tripped, with the cases that
showed it.

The round followed the README, the guide's and the tutorials' code, the worked example, every verb's ``--help`` and
the CLI's lines of the guide from a fresh clone, then read, plotted, validated and fitted what they wrote (class 7's
earlier trips held: a CSV with a byte-order mark, a run ending at its last sample in contact, ``--free``/``--dx``
before the file, ``--alpha`` selecting a run of a multi-angle ``simulate``). What failed is below; the example's
expected output against what it prints is checked in ``tests/test_example_validate.py`` (its run of the script).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from hostile_checks import cli_one_line, one_line_naming
from mdr_events.app.cli import build_parser
from mdr_events.io.candidates import UnnamedColumnError, read_candidate

#: Samples of the small hand-written CSV files (enough for a time axis; no simulation is run).
SAMPLES = 6
A20 = ["--scenario", "A", "--alpha", "20"]


def _write_csv(path, header, rows=SAMPLES):
    """A CSV file as a user writes one: a header row, then ``rows`` rows of increasing numbers."""
    lines = [",".join(header)] + [",".join(str(float(row + column)) for column in range(len(header)))
                                  for row in range(rows)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


#: (columns of the file, the option the command line's message shows how to write)
UNNAMED = [
    (["t", "Fn"], "--names time=<your column>"),  # a lab's names: no time column
    (["zeit", "normal_force"], "--names time=<your column>"),
    (["time", "Fn", "Ft"], "--names normal_force=<your column>"),  # a time, and no quantity by its name
    (["time", "force"], "--names normal_force=<your column>"),
]


@pytest.mark.parametrize("verb", ["validate", "fit"])
@pytest.mark.parametrize(("header", "how"), UNNAMED)
def test_a_file_of_unnamed_columns_is_told_how_to_name_them_on_the_command_line(tmp_path, capsys, verb, header, how):
    """``mdr-events validate run.csv`` with the columns ``t, Fn`` said "allowed: ... names={'time': <your column>}",
    Python a command-line user cannot write (as the multi-angle file's ``.isel(alpha=0)`` of round 28): the line
    shows the option too."""
    run = _write_csv(tmp_path / "run.csv", header)
    free = ["--free", "tau0"] if verb == "fit" else []
    line = cli_one_line(capsys, [verb, str(run), *A20, *free, "--out", str(tmp_path / "out")])
    assert how in line and ", ".join(header) in line, line
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


@pytest.mark.parametrize(("header", "how"), UNNAMED)
def test_the_api_still_says_names_as_python_writes_it(tmp_path, header, how):
    """The API's message keeps ``names={...}`` (what a Python caller writes), and only that: the io layer does not
    spell the command line's option (review of round 29: layers point down, and so does what they know); its error
    carries the quantity to name, from which the CLI writes ``--names`` (the test above)."""
    run = _write_csv(tmp_path / "run.csv", header)
    message = one_line_naming(lambda: read_candidate(run), "names={", errors=UnnamedColumnError)
    assert "--names" not in message and "command line" not in message and str(run) in message, message
    with pytest.raises(UnnamedColumnError) as refused:
        read_candidate(run)
    assert f"--names {refused.value.quantities[0]}=" in how


def test_the_readme_s_command_line_is_its_python_line():
    """The README's ten lines simulate the continuum ("exact, event-driven") and call
    ``mdr-events simulate --scenario A --alpha 10 20 30 --out out`` "the same": that ran the discrete springs (the
    command line's default), another method, file name and numbers. Its command now parses to the Python line's
    scenario, angles and method."""
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    python = re.search(r'me\.simulate\(contact, me\.Scenario\("(\w+)", alpha=\[([^\]]*)\]\), "(\w+)"\)', readme)
    assert python, "the README's ten lines no longer simulate as this test reads them"
    command = re.search(r"The same from the command line: `mdr-events ([^`]*)`", readme)
    assert command, "the README no longer gives the ten lines' command line"
    parsed = build_parser().parse_args(command.group(1).split())
    assert parsed.command == "simulate" and parsed.scenario == python.group(1)
    assert parsed.alpha == [float(angle) for angle in python.group(2).split(",")]
    assert parsed.method == python.group(3), (parsed.method, python.group(3))


#: The separators a spreadsheet or a script writes between the fields of a "CSV" file, beside the comma.
SEPARATORS = [";", "\t", "; ", " ;", "\t "]


def _twins(tmp_path, separator, rows=SAMPLES):
    """A comma-separated file and its twin with ``separator`` between the fields (same numbers and columns)."""
    commas = _write_csv(tmp_path / "commas.csv", ["t", "Fn", "Ft"], rows)
    other = tmp_path / "other.csv"
    other.write_text(commas.read_text(encoding="utf-8").replace(",", separator), encoding="utf-8")
    return commas, other


@pytest.mark.parametrize("separator", SEPARATORS, ids=repr)
def test_a_csv_separated_by_semicolons_or_tabs_is_read_as_its_comma_twin(tmp_path, separator):
    """A spreadsheet with a decimal comma saves "CSV" with semicolons (``t;Fn;Ft``), a script often with tabs: both
    were read as one column named ``'t;Fn;Ft'`` and refused with "names['time']='t' is not a column; ... columns
    found: t;Fn;Ft". They read as the comma-separated file of the same numbers and columns."""
    commas, other = _twins(tmp_path, separator)
    names = {"time": "t", "normal_force": "Fn", "tangential_force": "Ft"}
    expected, read = read_candidate(commas, names=names), read_candidate(other, names=names)
    assert read.quantities.keys() == expected.quantities.keys() and (read.time == expected.time).all()
    assert all((read.quantities[q] == expected.quantities[q]).all() for q in expected.quantities)


def test_a_decimal_comma_is_refused_naming_its_line_and_the_decimal_point(tmp_path):
    """Semicolons read, a decimal comma is not guessed at: one line naming the file's line, the column, the field and
    what a number is (a decimal point)."""
    run = tmp_path / "run.csv"
    run.write_text("t;Fn\n0;0\n1;1,5\n", encoding="utf-8")
    message = one_line_naming(lambda: read_candidate(run, names={"time": "t", "normal_force": "Fn"}), "'1,5'")
    assert "line 3" in message and "'Fn'" in message and "point" in message


@pytest.mark.parametrize("separator", [";", "\t"], ids=repr)
def test_the_cli_answers_a_semicolon_csv_as_its_comma_twin(tmp_path, capsys, separator):
    """``mdr-events validate`` of the file a spreadsheet saved gets the comma twin's answer (here: the twin's one
    line, too few samples in contact), not a refusal of its columns."""
    commas, other = _twins(tmp_path, separator)
    names = ["--names", "time=t,normal_force=Fn,tangential_force=Ft"]
    answers = [cli_one_line(capsys, ["validate", str(run), *A20, *names, "--out", str(tmp_path / "o")])
               for run in (commas, other)]
    assert answers[1] == answers[0].replace(str(commas), str(other)), answers
