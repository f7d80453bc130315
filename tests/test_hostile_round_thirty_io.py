"""The thirtieth hostile round (issue 32), the interfaces' side: the API's arguments given the values a NumPy user
writes (0-d arrays, NumPy scalars, subclasses of ``str``), paths that are long texts, and the CLI's verbs: each class
of what failed, with the cases that showed it (the round's other cases, which held, are listed in the issue's closing
note)."""

from __future__ import annotations

import math
import os
import warnings
from fractions import Fraction

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io.candidates import read_profile_table
from mdr_events.validation import check_choice
from hostile_checks import cli_one_line, one_line_naming

CONTACT = me.Contact.paper()


class _Name(str):
    """A user's subclass of ``str``."""


#: A name as a NumPy user holds it: a 0-d array of text (``np.asarray("A")``, ``names[i, ...]`` of an array of names),
#: NumPy's scalar of text (``names[i]``), and a user's subclass of ``str``.
NAME_FORMS = {"0-d array": np.array, "np.str_": np.str_, "str subclass": _Name}


@pytest.mark.parametrize("form", list(NAME_FORMS.values()), ids=list(NAME_FORMS))
@pytest.mark.parametrize("name, call, read", [
    ("A", lambda value: me.critical_angle(CONTACT, value), lambda result: result),
    ("B", lambda value: me.phase_diagram(CONTACT, scenario=value, alpha=[10.0, 20.0]), lambda result: result.attrs),
    ("A", lambda value: me.cross_check(CONTACT, value, alpha=[20.0]), lambda result: result.attrs),
    ("coulomb", lambda value: me.FrictionLaw(value, mu=0.3), lambda result: (result.law, type(result.law))),
    ("frictionless", lambda value: me.Layer(0.005, value), lambda result: result.base),
    ("A", lambda value: me.Scenario(value, alpha=(20.0,)), lambda result: (result.name, type(result.name))),
    ("A", lambda value: me.simulate(CONTACT, value, alpha=20.0, method="continuum"), lambda result: result.attrs),
], ids=["critical_angle", "phase_diagram", "cross_check", "FrictionLaw", "Layer", "Scenario", "simulate"])
def test_a_name_given_as_numpy_text_is_the_name(name, call, read, form):
    """NIT (b) of round 29's review: ``check_choice`` refused ``np.array("A")`` (round 29's guard against arrays),
    which d540130 accepted in ``critical_angle`` and ``phase_diagram`` (where it then failed writing its attributes:
    "array('A') is not netCDF-safe") and refused in ``FrictionLaw``, ``Scenario`` and ``simulate``. A 0-d array of text
    is what a NumPy user holds for a name (``np.asarray(names)[i]`` keeps the array): it is read as its ``str``, and
    the name kept (in a result's attributes too) is a plain ``str``, whichever form it came in; the result is the
    plain name's, bit for bit."""
    plain, given = read(call(name)), read(call(form(name)))
    if isinstance(plain, dict):
        assert {key: (value, type(value)) for key, value in given.items()} \
            == {key: (value, type(value)) for key, value in plain.items()}
    else:
        assert given == plain


@pytest.mark.parametrize("value", [np.array(["A"]), np.array(b"A"), np.array("C"), np.array(1.0), np.array(["A", "B"])],
                         ids=["1-d", "bytes", "unknown", "number", "two names"])
def test_an_array_that_is_not_one_known_name_is_still_refused(value):
    """The 0-d text array alone is read as a name: a 1-d array, bytes, an unknown name or a number stay refused in one
    line naming the argument (round 29's class 1)."""
    one_line_naming(lambda: me.critical_angle(CONTACT, value), "scenario")
    one_line_naming(lambda: me.FrictionLaw(value), "FrictionLaw.law")


def test_check_choice_returns_the_plain_name():
    """``check_choice`` returns the name as a plain ``str``: what its callers keep."""
    for form in NAME_FORMS.values():
        chosen = check_choice("scenario", form("B"), ("A", "B"))
        assert chosen == "B" and type(chosen) is str


#: A CSV file's text given where its path goes (40 kB: what ``validate(open(f).read(), ...)`` passes).
CSV_TEXT = "time,normal_force\n" + "0.1,1e-3\n" * 4000
#: The longest message naming a path that is not one: the path is cut to ``validation.PATH_CHARACTERS`` (200) and
#: each value shown to 80; the rest is the sentence.
PATH_MESSAGE_CHARACTERS = 700


def _names_the_path_short(message: str, path: str) -> None:
    """One line of at most PATH_MESSAGE_CHARACTERS that still names the path: its start and its end."""
    start, end = path[:20].replace("\n", "\\n"), path[-20:].replace("\n", "\\n")
    assert "\n" not in message and len(message) <= PATH_MESSAGE_CHARACTERS, (len(message), message[:300])
    assert start in message and end in message, message[:300]


@pytest.mark.parametrize("path", [CSV_TEXT, "d/" * 2000 + "run.csv", "a\nb" * 100 + ".csv"],
                         ids=["CSV text", "deep path", "newlines"])
@pytest.mark.parametrize("call", [
    lambda path: me.validate(path, CONTACT, "A", 20.0),
    lambda path: me.fit(path, CONTACT, "A", 20.0, free=["tau0"]),
    lambda path: me.open_result(path),
    lambda path: me.load_study(path),
    lambda path: read_profile_table(path),
], ids=["validate", "fit", "open_result", "load_study", "read_profile_table"])
def test_a_missing_file_is_named_short(call, path):
    """NIT (c) of round 29's review, class 5: "no such file" showed the path whole, so a CSV file's text passed as its
    path (``validate(open("run.csv").read(), ...)``) printed a line of 40 kB, and a study file's name with newlines
    printed 2000 lines (``load_study``). A path is now shown by ``validation.shown_path``: on one line (control
    characters escaped), cut in its middle to 200 characters, its start and end (the file's name) kept."""
    with pytest.raises((ValueError, TypeError)) as caught:
        call(path)
    _names_the_path_short(str(caught.value), path)
    if isinstance(path, str) and len(path) < 200:
        assert path.replace("\n", "\\n") in str(caught.value)


def test_a_bad_file_is_named_short(tmp_path):
    """A file that exists but is wrong (empty, a bad row) under a name of control characters: named on one line."""
    path = tmp_path / ("run\x1b[31m\n" * 3 + ".csv")
    path.write_text("time,normal_force\n0,1\n1,x\n", encoding="utf-8")
    message = one_line_naming(lambda: me.validate(path, CONTACT, "A", 20.0), "line 3")
    assert "\x1b" not in message and str(path).replace("\n", "\\n").replace("\x1b", "\\x1b") in message


@pytest.mark.parametrize("argv", [
    lambda path: ["validate", path, "--scenario", "A", "--alpha", "20", "--out", "o"],
    lambda path: ["fit", "--free", "tau0", "--scenario", "A", "--alpha", "20", "--out", "o", path],
    lambda path: ["run", path],
    lambda path: ["simulate", "--scenario", "A", "--alpha", "20", "--out", "o", "--table", path],
    lambda path: ["phase-diagram", "--scenario", "A", "--out", "o", "--table", path],
    lambda path: ["validate", "x.csv", "--params", path, "--scenario", "A", "--alpha", "20", "--out", "o"],
], ids=["validate", "fit", "run", "simulate --table", "phase-diagram --table", "validate --params"])
@pytest.mark.parametrize("path", [CSV_TEXT, "d/" * 2000 + "x.csv"], ids=["CSV text", "deep path"])
def test_the_command_line_names_a_long_path_short(capsys, tmp_path, monkeypatch, argv, path):
    """The CLI's own messages of a path: ``the run <path> would be written as <stem>.*`` (54 kB for the CSV text),
    ``--table <path>: table='<path>': no such file`` (57 kB): one line, the path cut."""
    monkeypatch.chdir(tmp_path)
    _names_the_path_short(cli_one_line(capsys, argv(path)).rstrip("\n"), path)


#: New directory levels below an output's or a cache's path: pathlib's ``mkdir(parents=True)`` and ``os.makedirs``
#: call themselves once a level, and Python's recursion limit is 1000 (the path, 2.4 kB, is within Linux's 4096).
DEEP_LEVELS = 1200


def _remove_deep(top) -> None:
    """Remove the tree at ``top`` without recursion: pytest's own clean-up of its temporary directories
    (``shutil.rmtree``) recurses once a level and ended a later session in ``RecursionError`` on these trees."""
    stack = [str(top)]
    while stack:
        below = []
        with os.scandir(stack[-1]) as entries:
            for entry in entries:
                if entry.is_dir(follow_symlinks=False):
                    below.append(entry.path)
                else:
                    os.unlink(entry.path)
        if below:
            stack.extend(below)
        else:
            os.rmdir(stack.pop())


def test_an_output_many_levels_deep_is_written(tmp_path, monkeypatch):
    """Class 3, round 30: ``mdr-events simulate --out d/d/.../d`` (1000 new levels) ran the simulation, then ended in
    ``RecursionError`` (exit 3) creating the directory: ``io.paths.make_directories`` makes them one by one."""
    monkeypatch.chdir(tmp_path)
    result = me.phase_diagram(CONTACT, scenario="A", alpha=[10.0, 20.0])
    deep = "d/" * DEEP_LEVELS + "diagram.nc"
    try:
        me.write_netcdf(result, deep)
        assert (tmp_path / deep).is_file()
    finally:
        if (tmp_path / "d").exists():
            _remove_deep(tmp_path / "d")


def test_a_cache_many_levels_deep_is_stored(tmp_path):
    """The caches' store (``$MDR_EVENTS_CACHE_DIR`` any depth) likewise: it swallowed an ``OSError`` but not the
    ``RecursionError``, which ended the derivation that asked for it."""
    from mdr_events.theory.cache_files import store_cached

    path = tmp_path.joinpath(*["c"] * DEEP_LEVELS, "relations.pickle")
    try:
        store_cached(path, lambda stream: stream.write(b"cached"))
        assert path.read_bytes() == b"cached"
    finally:
        if (tmp_path / "c").exists():
            _remove_deep(tmp_path / "c")


def test_an_output_directory_beyond_a_path_s_length_is_refused_before_the_run(capsys, tmp_path, monkeypatch):
    """Class 5, round 30: an output directory whose path is longer than a path may be (18 levels of 240 bytes: 4.3 kB)
    was accepted, the run computed (12 s of a simulation), then refused at the write ("File name too long"). It is
    refused with the verb's options, the bound stated."""
    monkeypatch.chdir(tmp_path)
    out = "/".join(["f" * 240] * 18)
    message = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", "--out", out])
    assert "--out" in message and "3839" in message and "4096" in message, message
    message = one_line_naming(lambda: me.write_netcdf(me.phase_diagram(CONTACT, alpha=[20.0]), out + "/x.nc"), "path")
    assert "3839" in message


#: Scenario B+'s deepest point, twice the paper's d_max (m).
FINAL_DEPTH = 6e-4


class _Depth(float):
    """A user's subclass of ``float``."""


def _b_plus_angle(indenter):
    """Scenario B+'s critical angle of ``final_depth`` on ``indenter`` (``None``: the paper's paraboloid, by
    ``critical_angle``; a power law or a flat punch by ``power_law.critical_angle_B_indentation``)."""
    if indenter is None:
        return lambda final_depth: me.critical_angle(CONTACT, "B+", final_depth=final_depth)
    return lambda final_depth: me.power_law.critical_angle_B_indentation(indenter, me.Parameters.paper(),
                                                                          final_depth=final_depth)


@pytest.mark.parametrize("indenter", [None, me.PowerLaw(2.0e3, 1.5), me.FlatPunch(1e-3)],
                         ids=["paraboloid", "power law", "flat punch"])
@pytest.mark.parametrize("form", [np.float32, Fraction, _Depth, np.int64], ids=["np.float32", "Fraction", "float subclass",
                                                                             "np.int64"])
def test_final_depth_is_any_real_number(indenter, form):
    """Class 5, round 30: ``critical_angle(contact, "B+", final_depth=...)`` took a ``float`` or an ``int`` alone
    (``isinstance(final, (int, float))``) and refused ``np.float32(6e-4)`` or ``Fraction(3, 5000)``, which
    ``Scenario(final_depth=...)`` and every other depth take; now read by ``check_real``: the angle of the float."""
    angle = _b_plus_angle(indenter)
    value = form(3 if form is np.int64 else FINAL_DEPTH) if form is not Fraction else Fraction(3, 5000)
    deepest = float(value)
    try:  # (3 m lies beyond what some indenters reach: refused as the float is, by name)
        expected = angle(deepest)
    except ValueError:
        one_line_naming(lambda: angle(value), "final_depth")
        return
    assert angle(value) == expected


@pytest.mark.parametrize("indenter", [None, me.PowerLaw(2.0e3, 1.5), me.FlatPunch(1e-3)],
                         ids=["paraboloid", "power law", "flat punch"])
@pytest.mark.parametrize("value", [10**400, -10**400, True, np.bool_(True), "6e-4"],
                         ids=["huge int", "-huge int", "True", "np.True_", "str"])
def test_final_depth_that_is_no_depth_is_refused_by_its_name(indenter, value):
    """``final_depth=10**400`` raised ``OverflowError: int too large to convert to float`` (an internal error, class
    3) and ``final_depth=True`` was refused as ``depth=True``, another argument's name: one line naming
    ``final_depth``."""
    angle = _b_plus_angle(indenter)
    one_line_naming(lambda: angle(value), "final_depth")


@pytest.mark.parametrize("value", [10**400, math.inf, True, "6e-4"], ids=["huge int", "inf", "True", "str"])
def test_the_b_plus_path_reads_its_final_depth_as_the_closed_forms_do(value):
    """The re-read's twin of the two fixes above: ``Path.scenario_B_indentation`` read ``final_depth`` by ``float()``
    on its own: ``True`` made a path to 1 m, ``inf`` and ``10**400`` a path of infinite waypoints refused by another
    name. It reads it as ``critical_angle`` does (``final_depth_of``): refused by its name, and a ``Fraction`` is its
    float's path."""
    params = me.Parameters.paper()
    one_line_naming(lambda: me.Path.scenario_B_indentation(30.0, params, value), "final_depth")
    assert np.array_equal(me.Path.scenario_B_indentation(30.0, params, Fraction(3, 5000)).waypoints,
                          me.Path.scenario_B_indentation(30.0, params, 6e-4).waypoints)


def test_cross_check_takes_the_spacing_and_steps_discrete_takes(tmp_path):
    """Class 3/5, round 30: ``cross_check(..., dx=Fraction(1, 500000))`` ended in ``TypeError: unsupported format
    string passed to Fraction.__format__`` (its labels wrote ``dx`` as given) and ``n_steps=None``, which ``Discrete``
    takes as its default step, in "attribute value None ... is not netCDF-safe" at the end of both runs: the
    values are the ones ``Discrete`` runs (a float ``dx``; no ``n_steps`` attribute without one)."""
    plain = me.cross_check(CONTACT, "A", alpha=[20.0], dx=2e-6, n_steps=2000)
    exact = me.cross_check(CONTACT, "A", alpha=[20.0], dx=Fraction(1, 500000), n_steps=np.int64(2000))
    xr.testing.assert_identical(exact, plain)
    default = me.cross_check(CONTACT, "A", alpha=[20.0], n_steps=None)
    assert "n_steps" not in default.attrs and np.isfinite(default["d_crit_discrete"].values).all()
    me.write_netcdf(default, tmp_path / "default.nc")


@pytest.mark.parametrize("argv, unknown", [
    (["simulate", "--scen", "A", "--alpha", "20", "--out", "o"], "--scen"),
    (["simulate", "--scenari=A", "--alpha", "20"], "--scenari"),
    (["validate", "run.csv", "--scenario", "A", "--alpha", "20", "--ou", "o"], "--ou"),
    (["fit", "--fre", "tau0", "--scenario", "A", "--alpha", "20", "--out", "o", "run.csv"], "--fre"),
], ids=["--scen", "--scenari=", "--ou", "--fre"])
def test_an_abbreviated_required_option_is_named(capsys, tmp_path, monkeypatch, argv, unknown):
    """Class 7, round 30: options are not abbreviated (``allow_abbrev=False``), and a required one written short
    (``--scen A``) was answered only "the following arguments are required: --scenario", which the user believes
    given; the line now names the word that is no option and says how options are written."""
    monkeypatch.chdir(tmp_path)
    message = cli_one_line(capsys, argv)
    assert "required" in message and f"({unknown} is no option of this command" in message, message


def test_a_named_unknown_option_is_not_named_twice(capsys):
    """An unknown option argparse names itself (``--methd``: unrecognized) gets no second mention."""
    message = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", "--out", "o", "--methd", "x"])
    assert message.count("--methd") == 1 and "is no option" not in message, message


#: Contact radii and depths (m) of the closed forms' arrays.
LENGTHS = [1e-4, 2e-4]


@pytest.mark.parametrize("call", [
    lambda value: me.critical_shift(value, CONTACT),
    lambda value: me.jkr_contact_radius(value, CONTACT, 0.05),
    lambda value: me.jkr_normal_force(value, CONTACT, 0.05),
    lambda value: me.fretting_dissipated_energy(value, 1e-6, CONTACT),
], ids=["critical_shift", "jkr_contact_radius", "jkr_normal_force", "fretting_dissipated_energy"])
def test_a_closed_form_reads_float32_as_its_float64(call):
    """Class 3, round 30: a float32 array went to the closed forms as given: its check against the bound 1.3e154
    cast the bound to float32 (NumPy's "RuntimeWarning: overflow encountered in cast") and the result was computed in
    float32. It is read as the float64 array of its values, as a list or an int array is: the same result."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        given = call(np.array(LENGTHS, dtype=np.float32))
    expected = call(np.array(LENGTHS, dtype=np.float32).astype(np.float64))
    assert given.dtype == np.float64 and np.array_equal(given, expected)


@pytest.mark.parametrize("call, named", [
    (lambda value: me.critical_shift(value, CONTACT), "contact_radius"),
    (lambda value: me.jkr_contact_radius(value, CONTACT, 0.05), "depth"),
    (lambda value: me.jkr_normal_force(value, CONTACT, 0.05), "contact_radius"),
], ids=["critical_shift", "jkr_contact_radius", "jkr_normal_force"])
def test_a_closed_form_refuses_masked_entries(call, named):
    """A masked array with masked entries went past ``real_array``'s refusal (a float array was taken as given):
    ``jkr_contact_radius`` read the value under the mask as given, ``critical_shift`` returned a masked array; refused
    by name, as every other argument refuses it."""
    one_line_naming(lambda: call(np.ma.masked_array(LENGTHS, mask=[False, True])), named, errors=(TypeError,))
