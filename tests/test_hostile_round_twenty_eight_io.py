"""The twenty-eighth hostile round (issue 32), the interfaces' side: each class of what failed, with the cases that
showed it.

The round's cases (round twenty-seven's interface harnesses again, and rounds 23-26's; fresh variants of classes 1,
4, 5, 6 and 7 of the issue: non-finite and DEM-like samples in every reader, sizes against ``Limits``, the API's
errors, outputs replaced together, new users' trips through the README, the docs and the study files, weighted on
what the last sessions changed: the theory packages' façades, user subclasses of the indenters, works of adhesion
given as many, the flat punch through every verb) are listed with their outcomes in the issue's closing note; what
failed is below.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.io.candidates import read_candidate, read_profile_table

#: Samples of the small run the readers are given (enough for a time axis; no simulation is run).
SAMPLES = 6


def _write_csv(path, header, rows):
    path.write_text("\n".join([",".join(header)] + [",".join(map(str, row)) for row in rows]) + "\n", encoding="utf-8")
    return path


def _run_rows():
    time = np.linspace(0.0, 1.0, SAMPLES)
    return time, 1e-3 * np.sin(np.pi * time), 5e-4 * time


def test_a_column_of_text_that_is_not_read_is_left_unread(tmp_path):
    """Class 7 (a new user's trip), round 28: a DEM's CSV output with a column of text beside its numbers (a particle's
    or a phase's label) was refused whole, "line 2, column 'particle': 'p0' is not a number", although the column is
    none of the quantities and the report lists such columns as "columns not read". A column no quantity reads is
    not parsed: the run is read, the column named among those not read; a quantity's column of text is still
    refused by name."""
    time, force, tangential = _run_rows()
    rows = [(t, f, x, f"p{i}") for i, (t, f, x) in enumerate(zip(time, force, tangential))]
    path = _write_csv(tmp_path / "dem.csv", ("time", "normal_force", "tangential_force", "particle"), rows)
    candidate = read_candidate(path)
    np.testing.assert_array_equal(candidate.time, time)
    np.testing.assert_array_equal(candidate.quantities["normal_force"], force)
    np.testing.assert_array_equal(candidate.quantities["tangential_force"], tangential)
    assert candidate.unused == ("particle",)
    # the same column named as a quantity's is read, and refused by its line and name
    with pytest.raises(ValueError, match=r"line 2, column 'particle': 'p0' is not a number; allowed"):
        read_candidate(path, names={"contact_radius": "particle"})
    # a quantity's own column of text, as before
    rows[3] = (time[3], "abc", tangential[3], "p3")
    bad = _write_csv(tmp_path / "bad.csv", ("time", "normal_force", "tangential_force", "particle"), rows)
    with pytest.raises(ValueError, match=r"line 5, column 'normal_force': 'abc' is not a number; allowed"):
        read_candidate(bad)


def test_a_profile_table_s_column_of_notes_is_left_unread(tmp_path):
    """Class 7, round 28: a tabulated indenter's CSV with a column of notes beside ``r`` and ``f`` was refused whole
    (the same reader): the table is read from ``r`` and ``f`` alone."""
    r = np.linspace(0.0, 3e-4, 20)
    f = r**2 / (2 * 30e-3)
    rows = [(a, b, "measured" if i % 2 else "") for i, (a, b) in enumerate(zip(r, f))]
    table = read_profile_table(_write_csv(tmp_path / "tip.csv", ("r", "f", "note"), rows))
    reference = me.TabulatedProfile(tuple(r), tuple(f))
    np.testing.assert_array_equal(table.r, reference.r)
    np.testing.assert_array_equal(table.f, reference.f)


@pytest.mark.parametrize("table, limits", [
    ('[simulation]\nscenario = "A"\nalpha = [45]\nmethod = "discrete"\n', "steps = 100"),
    ('[path]\nwaypoints = [[0, 0], [1e-9, 1e-6], [2e-9, 0], [3e-9, 1e-6]]\nspeed = 1e-6\n'
     '[simulation]\nmethod = "continuum"\n', "waypoints = 3"),
])
def test_a_study_s_limit_says_how_to_raise_it_in_the_study(tmp_path, table, limits):
    """Class 7, round 28: a study over one of its limits was told "raise the limit with limits=Limits(steps=...)
    (command line: --limit steps=...)", where ``mdr-events run`` and ``sweep`` take no ``--limit`` and the study file
    sets no ``Limits``: the message names the study's ``[limits]`` table, with the limit's key."""
    study = tmp_path / "study.toml"
    study.write_text(f"[limits]\n{limits}\n{table}[output]\ndirectory = \"out\"\n", encoding="utf-8")
    name = limits.split()[0]
    with pytest.raises(ValueError) as refused:  # (refused before anything runs or is written)
        me.run_study(me.load_study(study), progress=lambda message: None)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())
    message = str(refused.value)
    assert f"raise the limit in the study's [limits] table ({name} = ...)" in message, message
    assert "--limit" not in message and "Limits(" not in message, message
    assert "\n" not in message


#: An array where one number goes: its repr spans three lines.
GRID = np.full((3, 3), 20.0)
PARAMS = me.Contact.paper().parameters(3e-4, 1e-6)
PATH_A = me.Path.scenario_A(20.0, PARAMS)


@pytest.mark.parametrize("call", [
    lambda: dataclasses.replace(PARAMS, tau0=GRID),
    lambda: me.critical_angle(me.Contact.paper(), "A", final_depth=GRID, d_max=3e-4),
    lambda: me.critical_angle(me.Contact.paper(), "B+", final_depth=GRID, d_max=3e-4),
    lambda: me.Path.scenario_A(GRID, PARAMS),
    lambda: me.simulate(me.Contact.paper(), [PATH_A], alpha=GRID, method="continuum"),
    lambda: me.validate({"time": [0.0, 1.0], "normal_force": [0.0, 1.0]}, me.Contact.paper(), "A", alpha=GRID),
    lambda: me.validate({"time": [0.0, 1.0], "normal_force": [0.0, 1.0]}, me.Contact.paper(), "A", alpha=20.0,
                        time_origin=GRID),
    lambda: me.fit({"time": [0.0, 1.0], "normal_force": [0.0, 1.0]}, me.Contact.paper(), "A", alpha=GRID,
                   free=["tau0"]),
], ids=["Parameters", "critical_angle A", "critical_angle B+", "Path.scenario_A", "simulate paths", "validate alpha",
        "validate time_origin", "fit alpha"])
def test_an_array_where_one_number_goes_is_named_on_one_line(call):
    """Class 5 (the API's errors are the CLI's: one line), round 28: a 2-d array where one number goes was written
    with its repr, three lines (``Parameters.tau0=array([[20., 20., 20.],\\n [20., ...``), by the parameters' type
    check, ``critical_angle``'s final depth, a path's angle, ``simulate``'s angle beside custom paths, ``validate``'s
    and ``fit``'s angle and time origin (and the like in the discrete method's and the deck's step checks, the layer's
    radius and Poisson's ratio, ``mindlin``'s shift, the rate law's speed). Each names it on one line."""
    with pytest.raises((ValueError, TypeError)) as refused:
        call()
    message = str(refused.value)
    assert "\n" not in message, message
    assert "allowed: " in message, message
