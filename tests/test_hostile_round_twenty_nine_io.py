"""The twenty-ninth hostile round (issue 32), the interfaces' side: each class of what failed, with the cases that
showed it.

The round's cases (the API's arguments given hostile values where a message shows them: 2-d arrays, DataFrames,
objects whose ``repr`` spans lines, strings of 100 000 characters, lists of a million items, bytes, sets and dicts;
CSV files of 20 000 columns, of a header cell of 100 000 characters or of control characters; the CLI's verbs with
odd options and paths) are listed with their outcomes in the issue's closing note; what failed is below.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

import mdr_events as me
from mdr_events.io.candidates import LISTED_CHARACTERS, read_candidate
from hostile_checks import cli_one_line, cpu_limited, one_line_naming

#: The longest message a refusal may print (characters): the value shown is cut to 80 characters
#: (``validation.shown``) and a file's columns to 200 (``io.candidates.LISTED_CHARACTERS``); the rest is the sentence.
MESSAGE_CHARACTERS = 600
#: CPU seconds in which a list of paths of a hundred thousand items is refused (it takes ~0.1 s; the labels' repeats
#: were counted in n² comparisons, 1e10 here: hours).
LONG_LIST_BUDGET = 5.0

CONTACT = me.Contact.paper()
GRID = np.full((3, 3), 20.0)
FRAME = pd.DataFrame({"a": [1.0, 2.0, 3.0], "b": [4.0, 5.0, 6.0]})


class _LinesRepr:
    """A user's object whose ``repr`` spans three lines."""

    def __repr__(self) -> str:
        return "line1\nline2\nline3"


#: Values whose ``repr`` spans lines or runs to megabytes.
HOSTILE = {"2-d array": GRID, "DataFrame": FRAME, "repr of lines": _LinesRepr(), "long string": "x" * 100_000,
           "string of lines": "time,normal_force\n0,1\n" * 1000, "million list": list(range(10**6)),
           "bytes": b"\0" * 100_000, "set": set(range(1000)), "dict": {i: i for i in range(1000)}}


def _short_line(call, named: str) -> None:
    message = one_line_naming(call, named)
    assert len(message) <= MESSAGE_CHARACTERS, (len(message), message[:200])


@pytest.mark.parametrize("value", [GRID, FRAME], ids=["array", "DataFrame"])
@pytest.mark.parametrize("named, call", [
    ("scenario", lambda value: me.phase_diagram(CONTACT, scenario=value)),
    ("scenario", lambda value: me.cross_check(CONTACT, value)),
    ("scenario", lambda value: me.critical_angle(CONTACT, value)),
    ("scheduler", lambda value: me.Engine(scheduler=value)),
], ids=["phase_diagram", "cross_check", "critical_angle", "Engine"])
def test_a_choice_given_an_array_is_refused_by_name(named, call, value):
    """Class 3/5, round 29: a choice (``scenario``, ``scheduler``) given an array or a DataFrame raised NumPy's or
    pandas's "The truth value of an array with more than one element is ambiguous" (``value in ('A', 'B')``
    compares the array with each name): refused in one line naming the argument and the choices."""
    _short_line(lambda: call(value), named)


@pytest.mark.parametrize("value", list(HOSTILE.values()), ids=list(HOSTILE))
@pytest.mark.parametrize("named, call", [
    ("units['time']", lambda value, path: me.validate(path, CONTACT, "A", 20.0, units={"time": value})),
    ("scenario", lambda value, path: me.Scenario(value)),
    ("scenario", lambda value, path: me.simulate(CONTACT, [value])),
], ids=["validate units", "Scenario", "simulate list"])
def test_a_value_shown_in_a_refusal_is_one_short_line(tmp_path, named, call, value):
    """Class 5, round 29: ``units={'time': <2-d array>}``, ``Scenario(<DataFrame>)`` or ``simulate(contact,
    [<array>])`` were refused with the value's ``repr`` written whole: four lines for a 3x3 array, 7.9 MB for a list
    of a million; now through ``validation.shown``: one line of at most 80 characters of the value."""
    path = tmp_path / "run.csv"
    path.write_text("time,normal_force\n0,0\n1,0\n", encoding="utf-8")
    _short_line(lambda: call(value, path), named)


LONG = "x" * 100_000


@pytest.mark.parametrize("named, call", [
    ("names", lambda path: me.validate(path, CONTACT, "A", 20.0, names={LONG: "time"})),
    ("units", lambda path: me.validate(path, CONTACT, "A", 20.0, units={LONG: "s"})),
    ("names['normal_force']", lambda path: me.validate(path, CONTACT, "A", 20.0, names={"normal_force": LONG})),
    ("free", lambda path: me.fit(path, CONTACT, "A", 20.0, free=[LONG])),
    ("grid", lambda path: me.sweep({LONG: [1.0]}, CONTACT, "A", 20.0)),
    ("scenario", lambda path: me.simulate(CONTACT, {LONG: me.Path.scenario_A(20.0, CONTACT.parameters(3e-4, 1e-6))}
                                          | {(LONG,): None})),
    ("resume", lambda path: me.SweepOutput(resume=GRID)),
    ("store", lambda path: me.SweepOutput(store=GRID)),
], ids=["names key", "units key", "names column", "fit free", "grid name", "scenario label", "resume", "store"])
def test_a_name_given_as_a_long_text_is_shown_cut(tmp_path, named, call):
    """Class 5, round 29: a quantity, a column, a free parameter's, a grid's or a scenario's label given as a text of
    100 000 characters was written whole into the message (100 kB on one line); a flag given an array printed its
    rows on four lines; ``SweepOutput(store=<array>)`` was accepted and raised os.fspath's raw TypeError ("expected
    str, bytes or os.PathLike object, not ndarray") once the sweep ran. Each is refused in one short line."""
    path = tmp_path / "run.csv"
    path.write_text("time,normal_force\n0,0\n1,0\n", encoding="utf-8")
    _short_line(lambda: call(path), named)


@pytest.mark.parametrize("header, listed", [
    ([f"c{index}" for index in range(20_000)], "c0, c1, c2, "),  # a DEM's dump of every particle's column
    (["x" * 100_000, "y"], "xxx"),  # one header cell of a file read as text of one line
    (["a\x1b[31mred", "b\x07"], "a\\x1b[31mred, b\\x07;"),  # a terminal's escape and bell in a header
], ids=["20000 columns", "long cell", "control characters"])
def test_the_columns_found_are_listed_short_and_printable(tmp_path, header, listed):
    """Class 5, round 29: a CSV without a time column was refused with every column found listed: 20 000 columns or a
    header cell of 100 000 characters gave a message of 100 kB, and a header's escape sequence (``\\x1b[31m``) reached
    the terminal raw, colouring what followed. The list is cut to 200 characters with the count of the columns, and
    control characters are written as ``repr`` writes them."""
    path = tmp_path / "run.csv"
    path.write_text(",".join(header) + "\n" + "\n".join(",".join("0" * len(header)) for _ in range(3)) + "\n",
                    encoding="utf-8")
    with pytest.raises(ValueError, match="no time column") as refused:
        read_candidate(path)
    message = str(refused.value)
    assert message.isprintable() and len(message) <= MESSAGE_CHARACTERS, (len(message), message[:300])
    assert f"columns found: {listed}" in message, message
    assert (f"... ({len(header)} columns)" in message) == (len(", ".join(header)) > LISTED_CHARACTERS), message


#: Lengths of a text about each cut: the parser's and a value's (80 characters) and the columns' list (200).
AROUND_THE_CUTS = (0, 1, 76, 77, 78, 79, 80, 81, 82, 196, 197, 198, 199, 200, 201, 202, 100_000)


@pytest.mark.parametrize("length", AROUND_THE_CUTS)
def test_every_message_cuts_a_long_text_alike(length):
    """Review of round 29: the parser's words, a file's columns listed and a name or value shown were each cut to N
    characters by their own copy of "the first N - 3 and '...'"; now by ``validation.cut_text``, the lowest layer's,
    one rule: a text of at most N characters whole, a longer one exactly N long, ending in "...", which the parser
    follows with the count of its words and the list with the count of the columns."""
    from mdr_events.app.cli._options import CUT_CHARACTERS, _cut
    from mdr_events.io.candidates import columns_listed
    from mdr_events.validation import SHOWN_CHARACTERS, cut_text, shown, shown_text

    text = ("word " * length)[:length]
    for characters in (CUT_CHARACTERS, SHOWN_CHARACTERS, LISTED_CHARACTERS):
        cut = cut_text(text, characters)
        assert cut == text if length <= characters else (len(cut) == characters and cut == text[:characters - 3]
                                                           + "..."), (length, characters, cut)
    words = f" ({length} words)" if length > CUT_CHARACTERS else ""
    assert _cut(text) == cut_text(text, CUT_CHARACTERS) and _cut(text, length) == cut_text(text, CUT_CHARACTERS) + words
    assert shown_text(text) == cut_text(text) and shown(text) == cut_text(repr(text))
    names = [f"c{index}" for index in range(length)]
    listed = ", ".join(names)
    assert columns_listed(names) == (listed or "none" if len(listed) <= LISTED_CHARACTERS else
                                     f"{cut_text(listed, LISTED_CHARACTERS)} ({length} columns)")


def test_a_long_list_of_paths_is_refused_in_linear_time():
    """Class 4, round 29: ``simulate(contact, [0] * 100_000)`` ran for hours before the refusal of its first item (not
    a Path): the paths' labels were checked for repeats with ``list.count`` on each (n² comparisons). Counted once
    now: refused at once, naming the item."""
    def refused():
        with pytest.raises(TypeError, match=r"scenario\[0\]=0 \(int\) is not allowed; allowed"):
            me.simulate(CONTACT, [0] * 100_000)
    cpu_limited(refused, LONG_LIST_BUDGET)


def test_a_control_character_of_a_file_s_name_is_escaped_on_the_cli_s_line(capsys, tmp_path, monkeypatch):
    """Class 5, round 29: the CLI's line joined a message's lines but printed its other control characters raw: a CSV
    or a study file named ``run\\x1b[31m.csv`` (a name a script may write) turned the terminal red and the line
    after it; a bell rang. They are written as ``repr`` writes them (``\\x1b``), on the one line."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "run\x1b[31m.csv").write_text("time,normal_force\n0,0\n1,0\n", encoding="utf-8")
    (tmp_path / "study\x07.toml").write_text("not toml\n", encoding="utf-8")
    for argv in (["validate", "--scenario", "A", "--alpha", "20", "--out", "o", "run\x1b[31m.csv"],
                 ["run", "study\x07.toml"]):
        err = cli_one_line(capsys, argv)
        assert err[:-1].isprintable() and ("run\\x1b[31m" in err or "study\\x07" in err), err


@pytest.mark.parametrize("argv", [
    ["simulate", "--scenario", "Z" * 100_000],  # argparse's "invalid choice: 'ZZZ...'", the value whole
    ["derive"] + [f"study{index}.toml" for index in range(10_000)],  # a shell's glob given to a verb of no file
    ["derive", "--key", "k" * 100_000],  # the key shown twice: 200 kB
], ids=["invalid choice", "unrecognized words", "unknown key"])
def test_the_cli_shows_a_long_value_cut(capsys, argv):
    """Class 5, round 29: the CLI wrote a value it refuses whole: a choice of 100 000 characters (argparse's
    message), ten thousand words it did not take, or a relation's key (twice): 100-200 kB on one line. Each is cut
    to 80 characters (the words with their count); derive's list of allowed keys is the rest of its line."""
    from mdr_events.app.cli._options import CUT_CHARACTERS
    from mdr_events.validation import SHOWN_CHARACTERS
    assert CUT_CHARACTERS == SHOWN_CHARACTERS  # (the parser's copy, kept free of numpy)
    err = cli_one_line(capsys, argv)
    assert "Z" * 81 not in err and "k" * 81 not in err and "study100.toml" not in err, err[:300]
    assert len(err) <= MESSAGE_CHARACTERS or argv[0] == "derive" and len(err) < 3000, len(err)


@pytest.mark.parametrize("options, given", [
    (["--layer-base", "frictionless"], "--layer-base frictionless without --h"),
    (["--h", "inf", "--layer-base", "bonded"], "--layer-base bonded with --h inf"),
], ids=["without h", "h inf"])
@pytest.mark.parametrize("verb", [["simulate", "--method", "continuum"], ["validate", "run.csv"],
                                  ["fit", "--free", "tau0", "--", "run.csv"]], ids=["simulate", "validate", "fit"])
def test_a_layer_base_on_the_half_space_is_refused(capsys, tmp_path, monkeypatch, options, given, verb):
    """Class 7, round 29: ``simulate --layer-base frictionless`` without ``--h`` ran the half-space in silence, the
    base ignored (the user asked for a layer free to slide on its base and got the paper's half-space), where
    ``--mu`` without Coulomb's law and ``--v-ref`` without the rate law are refused. Refused now, in one line naming
    the option and what is allowed, before anything runs (a sweep's ``--layer-base`` sets its study's layer's base or
    a grid's over h, as before)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "run.csv").write_text("time,normal_force\n0,0\n1,0\n", encoding="utf-8")
    argv = [verb[0], "--scenario", "A", "--alpha", "20", "--out", "out", *options, *verb[1:]]
    err = cli_one_line(capsys, argv)
    assert given in err and "allowed: --layer-base with --h H" in err, err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


OUTPUT = '[output]\ndirectory = "out"\n'


@pytest.mark.parametrize("table", [
    f'["{LONG}"]\na = 1\n',  # an unknown table
    f'[simulation]\n"{LONG}" = 1\n',  # an unknown key
    f'[limits]\n"{LONG}" = 1\n',
    '[simulation]\nscenario = "A"\nalpha = [' + ", ".join(['"x"'] * 100_000) + ']\n',  # a value of the wrong kind
    f'[phase_diagram]\nscenarios = ["{LONG}"]\n',
    '[phase_diagram]\nscenarios = [' + ", ".join(['"A"'] * 100_000) + ']\n',
    f'[validate]\nscenario = "A"\nalpha = 20\nruns = ["{LONG}"]\n',  # its stem too long, the run named twice
], ids=["table", "key", "limit", "alpha kind", "scenario", "scenarios repeated", "validate run"])
def test_a_study_file_s_refusal_shows_its_values_cut(tmp_path, table):
    """Class 5, round 29: a study file's unknown table or key, a value of the wrong kind, a [phase_diagram] scenario
    or a [validate] run were written whole into the refusal (100-500 kB on one line for a name of 100 000
    characters or a list of 100 000 items): cut by ``validation.shown`` / ``shown_text``."""
    study = tmp_path / "study.toml"
    study.write_text(table + OUTPUT, encoding="utf-8")
    with pytest.raises(ValueError) as refused:
        me.load_study(study)
    message = str(refused.value)
    assert "allowed" in message and "\n" not in message and len(message) <= MESSAGE_CHARACTERS + len(str(study)), \
        (len(message), message[:300])


def test_a_study_s_integer_of_too_many_digits_is_refused_by_its_file(capsys, tmp_path):
    """Class 3/5, round 29: ``E = 999...9`` (5000 digits) in a study made Python's own ValueError, "Exceeds the limit
    (4300 digits) for integer string conversion ... use sys.set_int_max_str_digits()", naming neither the file nor
    what is allowed (``tomllib`` converts with ``int()``): refused as the file's, in one line, exit 2."""
    study = tmp_path / "study.toml"
    study.write_text("[parameters]\nE = " + "9" * 5000 + "\n" + OUTPUT, encoding="utf-8")
    with pytest.raises(ValueError, match=r"study.toml: an integer of more than \d+ digits cannot be read; allowed"):
        me.load_study(study)
    err = cli_one_line(capsys, ["run", str(study)])
    assert "set_int_max_str_digits" not in err, err


@pytest.mark.parametrize("items", [["x" * 10_000 + "=1"], ["steps=" + "x" * 10_000], ["steps=1e8", "steps=" + "0" * 10_000 + "1"]],
                         ids=["name", "value", "twice"])
def test_a_limit_s_text_is_shown_cut(items):
    """Class 5, round 29: ``--limit`` wrote its text whole into the refusal (10 kB for a name of 10 000 characters);
    cut to 80 characters."""
    from mdr_events.app.inputs import limits
    _short_line(lambda: limits(items), "--limit")
