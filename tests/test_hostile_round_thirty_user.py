"""The thirtieth hostile round (issue 32), a new user of the documentation site who referees their own simulator
(class 7, with class 5): what tripped, with the cases that showed it.

The round read the site (the tutorials, the guide's "Validate a simulator" and "Check a DEM contact law", the
errors-and-limits page), ran its code, and validated a spring array's run written as another code writes it (other
column names, ms/µm/mN, a comment header, semicolons, blanks, a ``.txt``/``.tsv``/``.dat`` name, LAMMPS's ``fix
print``, ``fix ave/time`` and dump files) through the API and the command line, with wrong variants (a pull-off 3 %
early, a flipped force, a diameter for the radius, a friction 10 % strong, a late full slip, a clock shifted by
50 s): each failed naming the quantity or the event and its time. What failed is below.
"""

from __future__ import annotations

import argparse

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import cli_one_line, one_line_naming
from mdr_events.app.cli import main
from mdr_events.app.cli.validate import spacings
from mdr_events.io.candidates import UNITS, read_candidate

#: A small run as a spring array writes it, in SI units: time (s), normal and tangential force (N), radius (m).
TIME = np.arange(6.0)
NORMAL_FORCE = np.array([0.0, -1e-3, 2e-3, 5e-3, 3e-3, 0.0])
TANGENTIAL_FORCE = np.array([0.0, 0.0, 1e-4, 3e-4, 2e-4, 0.0])
RADIUS = np.array([0.0, 1e-4, 2e-4, 4e-4, 3e-4, 0.0])
#: The columns in the lab's units (ms, mN, µm), under the lab's names.
LAB_NAMES = {"time": "t_ms", "normal_force": "Fz_mN", "tangential_force": "Fx_mN", "contact_radius": "r_um"}
LAB_UNITS = {"time": "ms", "normal_force": "mN", "tangential_force": "mN", "contact_radius": "um"}
LAB_COLUMNS = np.column_stack([TIME * 1e3, NORMAL_FORCE * 1e3, TANGENTIAL_FORCE * 1e3, RADIUS * 1e6])
#: Relative tolerance of a value read back against the one written (printed with %.12g: 12 significant digits).
READ_BACK_RTOL = 1e-11


def _write(path, separator, header_prefix="", comments=("# mysim v0.3 spring array", "# units: ms, mN, um")):
    """The lab's run as ``path``: comment lines, a header row and a row per sample, fields joined by ``separator``."""
    rows = [separator.join(f"{value:.12g}" for value in row) for row in LAB_COLUMNS]
    lines = [*comments, header_prefix + separator.join(LAB_NAMES.values()), *rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _assert_read_in_si(path, units=LAB_UNITS):
    run = read_candidate(path, LAB_NAMES, units)
    np.testing.assert_allclose(run.time, TIME, rtol=READ_BACK_RTOL)
    for name, exact in (("normal_force", NORMAL_FORCE), ("tangential_force", TANGENTIAL_FORCE),
                        ("contact_radius", RADIUS)):
        np.testing.assert_allclose(run.quantities[name], exact, rtol=READ_BACK_RTOL, atol=0)


# --- 1. a text table not named .csv was read as netCDF: "is not a readable netCDF file (it does not start as a
# netCDF file does: b'# my')"; a table aligned with blanks (LAMMPS's fix print) was one column -------------------

@pytest.mark.parametrize("name", ["run.txt", "run.tsv", "run.dat", "run", "run.out", "run.TXT"])
@pytest.mark.parametrize("separator", [",", ";", "\t", " ", "   "])
def test_a_text_table_is_read_whatever_its_name_and_separator(tmp_path, name, separator):
    """The guide reads tab-separated files, and names no suffix; ``run.tsv`` was read as netCDF and refused with its
    first bytes. A table aligned with blanks (one or several) was one column ``'t_ms Fz_mN Fx_mN r_um'``."""
    _assert_read_in_si(_write(tmp_path / name, separator))


def test_blank_separated_rows_may_be_indented_and_padded(tmp_path):
    """Fortran and LAMMPS right-align their columns: blanks before the first field and after the last are no field."""
    path = tmp_path / "aligned.txt"
    rows = ["".join(f"{value:>20.12g}" for value in row) + "  " for row in LAB_COLUMNS]
    path.write_text("\n".join(["   " + "  ".join(LAB_NAMES.values()) + " ", *rows]) + "\n", encoding="utf-8")
    _assert_read_in_si(path)


def test_a_header_of_spaces_over_rows_of_tabs_is_read(tmp_path):
    """Blanks are blanks: a header aligned with spaces over rows written with tabs (or mixed) splits the same."""
    path = tmp_path / "mixed.dat"
    rows = ["\t".join(f"{value:.12g}" for value in row) + " \t" for row in LAB_COLUMNS]
    path.write_text("\n".join([" ".join(LAB_NAMES.values()), *rows]) + "\n", encoding="utf-8")
    _assert_read_in_si(path)


def test_utf16_text_of_any_name_is_named_as_text(tmp_path):
    """A spreadsheet's "Unicode text" (UTF-16, NUL bytes in it) named ``run.txt`` is refused as text that is not
    UTF-8, as the same file named ``run.csv`` is, not as a netCDF file that does not start as one."""
    for name in ("run.txt", "run.csv"):
        path = tmp_path / name
        path.write_text("t,Fn\n0,1\n", encoding="utf-16")
        one_line_naming(lambda path=path: read_candidate(path, {"time": "t", "normal_force": "Fn"}), "not UTF-8 text")


def test_a_netcdf_file_of_any_name_is_still_read_as_netcdf(tmp_path):
    """Told apart by its first bytes, not its name: a netCDF-3 file named ``.dat`` is read as netCDF; a text file named
    ``.nc`` is still refused as no netCDF file."""
    import xarray as xr

    dataset = xr.Dataset({name: ("time", values) for name, values in
                          (("normal_force", NORMAL_FORCE), ("contact_radius", RADIUS))}, coords={"time": TIME})
    dataset.to_netcdf(tmp_path / "run.dat", engine="scipy")
    run = read_candidate(tmp_path / "run.dat")
    np.testing.assert_array_equal(run.quantities["normal_force"], NORMAL_FORCE)
    _write(tmp_path / "table.nc", ",")
    one_line_naming(lambda: read_candidate(tmp_path / "table.nc", LAB_NAMES, LAB_UNITS), "is not a readable netCDF")


# --- 2. a file without a header row, or with the header as a comment (LAMMPS's fix print without a title, fix
# ave/time's '# TimeStep v_t ...') or a LAMMPS dump: its numbers named as columns, "the header names '0.0' more than
# once", or a netCDF message -------------------------------------------------------------------------------------

LAMMPS_FILES = [
    ("fix_print.txt", "# Fix print output for fix out\n0.0 0.0 0.0\n1.0 -0.001 0.0\n", "line 2 (0.0, 0.0, 0.0) holds "
     "numbers"),
    ("ave_time.txt", "# Time-averaged data for fix 1\n# TimeStep v_t v_fz\n0 0.0 0.0\n100 1.0 -0.001\n",
     "line 3 (0, 0.0, 0.0) holds numbers"),
    ("headless.csv", "0,0\n1,2\n", "line 1 (0, 0) holds numbers"),
    ("forces.lammpstrj", "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\n", "starts a LAMMPS dump"),
]


@pytest.mark.parametrize(("name", "text", "said"), LAMMPS_FILES)
def test_a_file_without_a_header_row_says_so(tmp_path, capsys, name, text, said):
    """What to do is named (a header row; a comment header's ``#`` removed; fix print's table for a dump), in one
    line, by the API and by ``mdr-events validate`` (exit 2, nothing computed or written)."""
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    message = one_line_naming(lambda: read_candidate(path, {"time": "t"}), said)
    assert "header row" in message or "fix print" in message, message
    line = cli_one_line(capsys, ["validate", str(path), "--scenario", "A", "--alpha", "20", "--names", "time=t",
                                 "--out", str(tmp_path / "out")])
    assert said in line, line
    assert not (tmp_path / "out").exists()


# --- 3. units that look like the allowed ones: 'μm' (Greek mu, U+03BC) refused beside an allowed 'µm' (the micro
# sign, U+00B5) the user cannot tell from it; 'mm²'; and a run named run_dx2μm.csv read as dx = 2 m --------------

LOOKALIKE_UNITS = [
    ("contact_radius", "\u03bcm", "\u00b5m"),  # Greek mu: what a Greek keyboard, and Unicode's NFKC, write
    ("time", "\u03bcs", "\u00b5s"),
    ("normal_force", "\u03bcN", "\u00b5N"),
    ("contact_area", "mm\u00b2", "mm2"),  # a superscript two
    ("contact_area", "\u03bcm\u00b2", "\u00b5m2"),
    ("contact_area", "\u00b5m\u00b2", "\u00b5m2"),
]


@pytest.mark.parametrize(("quantity", "written", "listed"), LOOKALIKE_UNITS)
def test_a_unit_written_with_a_lookalike_character_is_that_unit(tmp_path, quantity, written, listed):
    """Each is read as the unit of :data:`UNITS` it shows (the same factor), by the API and on the command line."""
    factor = UNITS[{"contact_radius": "m", "time": "s", "normal_force": "N", "contact_area": "m2"}[quantity]][listed]
    path = tmp_path / "run.csv"
    path.write_text("".join(f"{row},{row / factor!r},1\n" for row in range(3)), encoding="utf-8")
    path.write_text("t,q,Fn\n" + path.read_text(), encoding="utf-8")
    names = {"time": "q", "normal_force": "Fn"} if quantity == "time" else {"time": "t", quantity: "q"}
    run = read_candidate(path, names, {quantity: written})
    read = run.time if quantity == "time" else run.quantities[quantity]
    np.testing.assert_allclose(read, [0.0, 1.0, 2.0], rtol=READ_BACK_RTOL)


def test_a_unit_that_is_none_of_them_is_still_refused(tmp_path):
    path = _write(tmp_path / "run.csv", ",")
    for unit in ("MN", "mm2", "\u03bcm2", "um "):  # (a megaNewton; an area for a radius; a blank)
        one_line_naming(lambda unit=unit: read_candidate(path, LAB_NAMES, {**LAB_UNITS, "contact_radius": unit}),
                        "units['contact_radius']")


@pytest.mark.parametrize("micro", ["\u03bc", "\u00b5", "u"])
def test_the_spacing_in_a_run_s_name_reads_either_mu(micro):
    """``run_dx8μm.csv`` (Greek mu) matched no unit and was read as 8 m: the convergence study's spacings a million
    times too large (its order, a slope in log-log, unchanged: nothing said so)."""
    runs = [f"run_dx{spacing}{micro}m.csv" for spacing in (8, 4, 2)]
    found, why = spacings(argparse.Namespace(dx=None, runs=runs))
    assert why is None
    np.testing.assert_allclose(found, [8e-6, 4e-6, 2e-6], rtol=READ_BACK_RTOL)


# --- 4. the LAMMPS bridge: the guide gives the deck LAMMPS ran (`lmp -in deck.lmp -var output forces.txt`), but its
# output had no header row and LAMMPS's sign of fx (the wall's force on the sphere): validate could not read it, and
# a user who named fx the tangential force failed by twice its range ---------------------------------------------

#: LAMMPS's steps of the bridge's run: enough for 20 a segment (the deck's least), few for a cheap test.
BRIDGE_STEPS = 600


def _bridge_run(tmp_path):
    """A contact of JKR and Coulomb's law run by ``run_lammps`` along scenario A at 20°, and the file its deck prints
    when run again (as ``lmp -in deck.lmp -var output forces.txt``); skipped without LAMMPS."""
    from mdr_events.dem import runner

    try:
        runner.load_lammps()
    except runner.LammpsUnavailable as error:
        pytest.skip(f"LAMMPS is not available: {error}")
    paper = me.Contact.paper()
    contact = me.Contact(paper.elastomer, paper.indenter, me.Adhesion(0.15, 0.15), me.FrictionLaw("coulomb", mu=0.5))
    run = me.dem.run_lammps(contact, me.Path.scenario_A(20.0, paper.parameters(3e-4, 1e-6)), "jkr", "mindlin",
                            steps=BRIDGE_STEPS)
    output = tmp_path / "forces.txt"
    runner.run_deck(run.attrs["lammps_input_deck"], output)
    return contact, run, output


def test_a_rerun_of_the_lammps_deck_is_read_as_it_stands(tmp_path):
    """The file the deck prints is read with no names and no units: the run ``run_lammps`` gives, number for number
    (17 digits: LAMMPS's doubles)."""
    _, run, output = _bridge_run(tmp_path)
    read = read_candidate(output)
    np.testing.assert_array_equal(read.time, run.time.values)
    for name in ("normal_force", "tangential_force"):
        np.testing.assert_array_equal(read.quantities[name], run[name].values)
    assert set(read.unused) == {"x", "depth", "lammps_contact"}


@pytest.mark.slow
def test_a_rerun_of_the_lammps_deck_is_refereed_as_lammps_check_referees_it(tmp_path, capsys):
    """``mdr-events validate forces.txt --time-origin path_start`` with the contact's options gives the verdict and
    the errors of ``validate`` of the run (what ``lammps_check`` reports). Slow: two continuum solves (some 10 s); its
    quick sibling, ``test_a_rerun_of_the_lammps_deck_is_read_as_it_stands``, checks the file reads as the run."""
    contact, run, output = _bridge_run(tmp_path)
    status = main(["validate", str(output), "--scenario", "A", "--alpha", "20", "--time-origin", "path_start",
                   "--dgamma0", "0.15", "--dgamma1", "0.15", "--friction", "coulomb", "--mu", "0.5",
                   "--out", str(tmp_path / "checks")])
    report = me.open_result(tmp_path / "checks" / "forces.nc")
    referee = me.validate(run, contact, "A", 20.0)
    assert status == 1 and report.attrs["verdict"] == referee.attrs["verdict"] == "fail", capsys.readouterr()
    np.testing.assert_array_equal(report["max_error"].values, referee["max_error"].values)


# --- 5. a verdict a user would misread: a tangential force in mN read as N (the guide's `--units
# time=ms,normal_force=mN` on a file whose F_x is in mN too) failed with "max error 997 of its range", a flipped sign
# with "2 of its range", a diameter written for the radius with "1 of its range": none said why ----------------

#: Relative tolerance of a least-squares scale recovered from exactly scaled samples (rounding only).
SCALE_RTOL = 1e-12
#: The exact curve of the scale tests: a loading and unloading with a tensile end, as a force's.
EXACT = np.sin(np.linspace(0.0, 3.5, 200))
EVERYWHERE = np.ones(EXACT.size, dtype=bool)


@pytest.mark.parametrize(("factor", "said"), [(1e3, "1000 times the exact throughout: its unit?"),
                                              (1e-3, "0.001 times the exact throughout: its unit?"),
                                              (1e6, "1e+06 times"), (1e-2, "0.01 times"),
                                              (-1.0, "minus the exact throughout: the other sign convention?"),
                                              (-1e3, "-1000 times the exact throughout: its unit and sign?")])
def test_a_candidate_a_unit_or_a_sign_away_is_named(factor, said):
    from mdr_events.analysis.reports import ValidationMeasures, scale_hint, validation_failures
    from mdr_events.analysis.samples import candidate_scale

    scale = candidate_scale(factor * EXACT, EXACT, EVERYWHERE)
    np.testing.assert_allclose(scale[0], factor, rtol=SCALE_RTOL)
    assert said in scale_hint(*scale)
    failures = validation_failures(ValidationMeasures(["normal_force"], [abs(factor - 1.0)], 0.0, [0.0],
                                                      scales=[scale]), 1e-3)
    assert said in failures[0] and failures[0].startswith("normal_force: max error"), failures


def test_a_diameter_is_named_for_the_radius_only():
    from mdr_events.analysis.reports import scale_hint
    from mdr_events.analysis.samples import candidate_scale

    scale = candidate_scale(2.0 * EXACT, EXACT, EVERYWHERE)
    assert "a diameter?" in scale_hint(*scale, "contact_radius")
    assert scale_hint(*scale, "normal_force") == ""


@pytest.mark.parametrize("candidate", [1.1 * EXACT,  # a model 10 % strong: its own error, no unit
                                       1e3 * EXACT + 0.2 * 1e3 * np.cos(np.linspace(0.0, 3.5, 200)),  # not a scale
                                       1.2e3 * EXACT,  # beyond SCALE_HINT_RTOL of 1000
                                       np.zeros(EXACT.size)])
def test_a_candidate_no_unit_or_sign_away_names_no_scale(candidate):
    from mdr_events.analysis.reports import scale_hint
    from mdr_events.analysis.samples import candidate_scale

    assert scale_hint(*candidate_scale(candidate, EXACT, EVERYWHERE), "contact_radius") == ""


def test_the_report_and_its_file_name_the_scale(tmp_path):
    """End to end: ``validate`` of a run whose F_x is in mN read as N and whose F_N has the other sign names both in
    its failures, and so does the report read back from its file (``ValidationReport.failures``). The candidate is the
    exact continuum's run itself, scaled."""
    contact = me.Contact.paper()
    reference = me.simulate(contact, me.Scenario("A", alpha=[20]), me.Continuum(samples=401)).sel(alpha=20)
    inside = np.isfinite(reference.normal_force.values)
    run = {"time": reference.time.values[inside], "normal_force": -reference.normal_force.values[inside],
           "tangential_force": 1e3 * reference.tangential_force.values[inside]}
    report = me.validate(run, contact, "A", 20.0)
    me.write_netcdf(report, tmp_path / "report.nc")
    for failures in (me.ValidationReport.from_dataset(report).failures,
                     me.ValidationReport.from_dataset(me.open_result(tmp_path / "report.nc")).failures):
        assert any(line.startswith("normal_force: max error") and "minus the exact" in line for line in failures)
        assert any(line.startswith("tangential_force: max error") and "1000 times" in line for line in failures)
