"""The twenty-fourth hostile round (issue 32): each class of what failed, with the cases that showed it.

The round's cases (round twenty-three's open class: the objects a user builds whose constructors read a user-sized
array before any limit: the continuum's times, a scenario's angles, a tabulated profile's columns, a path's
waypoints, the sweep's grids, ``Limits``, ``SweepOutput``, ``Engine``; the discrete model at the layer tables' edge;
fresh variants of every class of the issue) are listed with their outcomes in the issue's closing note; what failed
is below.
"""

from __future__ import annotations

import contextvars
import errno
import io
import math
import os
import re
import sys
import time

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import cli_one_line, cpu_limited, depth_reaching, one_line_naming, peak_of, refused_for_resources
from mdr_events.app.cli import main
from mdr_events.app.cli._stdout import NamedOutput
from mdr_events.models import motion
from mdr_events.models.simulate import simulation_job
from mdr_events.models.continuum import run_continuum
from mdr_events.validation import SHOWN_CHARACTERS, shown

PAPER = me.Parameters.paper()
#: Limits far below what the cases below ask: any of them refuses the run.
SMALL = me.Limits(samples=1000, steps=10**6, memory=2**20)
#: The values of the user's arrays below: a view of one value (``np.broadcast_to``) takes no memory of its own, its
#: copy 8 MB; 1e9 of them took 16 GB in round twenty-three.
VIEW_VALUES = 10**6
#: What counting them may take (tracemalloc's peak): far below one copy (8 MB); the message and the limits' check
#: take a few kB.
COUNTED_PEAK_BYTES = 2**20


def _finite_in_contact(values: np.ndarray) -> bool:
    """Every sample finite up to the loss of contact, nan after it (the results' convention), for each case."""
    for row in np.atleast_2d(values):
        lost = np.isnan(row)
        first = int(np.argmax(lost)) if lost.any() else row.size
        if first == 0 or not lost[first:].all() or not np.all(np.isfinite(row[:first])):
            return False
    return True


# --- W1 (round twenty-three V3, closed): a Continuum built by the user read its output times when made, before
# any limit (Continuum(t=np.broadcast_to(0.1, (10**9,))): 16 GB and 84 s, then refused as not increasing); the same
# times by name were counted first. The method keeps its times as given and reads them when a run starts, counted
# against the run's limits first (Continuum.output_times); run_continuum counts its times before it reads them ------

#: Output times beyond what one case may have within the default limits (``Limits.samples`` 1e7): counted, these
#: are kept as given, read only by a run whose limits take them. A view of one value: no memory of its own.
BEYOND_DEFAULT_TIMES = 10**8


def _view_times():
    return np.broadcast_to(0.1, (BEYOND_DEFAULT_TIMES,))


def test_a_continuum_is_made_without_reading_its_times():
    me.Continuum()  # (its modules imported before the trace)
    assert peak_of(lambda: me.Continuum(t=_view_times())) < COUNTED_PEAK_BYTES


def test_a_continuum_keeps_a_checked_copy_of_times_within_the_default_limits():
    """Times that one case may have within the default limits are read when the method is made: a read-only copy,
    unchanged when the caller's array changes after (a reviewer's finding: the method aliased the array), and bad
    times refused at once, naming ``t``."""
    times = np.linspace(0.0, 1.0, 5)
    method = me.Continuum(t=times)
    times[1] = -5.0
    assert np.array_equal(method.t, np.linspace(0.0, 1.0, 5))
    assert not method.t.flags.writeable
    with pytest.raises(ValueError, match=r"^t=\[3\.0, 2\.0\] is not allowed"):
        me.Continuum(t=[3.0, 2.0])


@pytest.mark.parametrize("call", [
    lambda: me.simulate(PAPER, "A", 20.0, me.Continuum(t=_view_times()), limits=SMALL),
    lambda: me.simulate(me.Contact.paper(), "B", [20.0, 30.0], method=me.Continuum(t=_view_times()), limits=SMALL),
    lambda: me.simulate(me.Contact.paper(), "A", me.Continuum(t=_view_times()), limits=SMALL),
    lambda: run_continuum(PAPER, me.Scenario("A", 20.0).cases(PAPER).paths, _view_times(), limits=SMALL),
], ids=["third argument", "method=", "in alpha's place", "run_continuum"])
def test_a_run_counts_the_continuum_s_times_before_reading_them(call):
    assert refused_for_resources(call) < COUNTED_PEAK_BYTES


@pytest.mark.parametrize("times, error", [
    ([0.0, 2.0, 1.0], ValueError), ([0.0, math.nan], ValueError), ([0.0, math.inf], ValueError),
    ([-1.0, 1.0], ValueError), (np.ones((2, 2)), ValueError), (["0", "1"], TypeError), ([0, True, 2], TypeError),
    ([], ValueError),
])
def test_a_continuum_s_bad_times_are_refused_by_the_run_naming_t(times, error):
    message = one_line_naming(lambda: me.simulate(PAPER, "A", 20.0, me.Continuum(t=times)), "t=", errors=error)
    assert message.startswith("t="), message


def test_a_continuum_s_times_are_those_given_by_name():
    """The same times, read when the run starts, give the same result as by name (the run reads them once)."""
    times = np.linspace(0.0, 300.0, 7)
    by_value = me.simulate(PAPER, "A", 20.0, me.Continuum(t=times))
    by_name = me.simulate(PAPER, "A", 20.0, "continuum", t=times)
    assert np.array_equal(by_value.normal_force.values, by_name.normal_force.values)
    assert np.array_equal(by_value.time.values, times)


def test_a_long_list_is_shown_by_its_first_items():
    """A message (and the method's repr) shows a long list cut as before, without writing it out whole: the cut text
    is the same, the time that of a short list (a million times' repr took a second and 20 MB)."""
    values = [0.1 * index for index in range(VIEW_VALUES)]
    start = time.process_time()
    text = shown(values)
    assert time.process_time() - start < 0.05  # (the first items' repr: microseconds; the whole list's: a second)
    assert text == " ".join(repr(values[:1000]).split())[: SHOWN_CHARACTERS - 3] + "..."
    assert len(repr(me.Continuum(t=values))) < 3 * SHOWN_CHARACTERS
    assert me.Continuum(t=[0.0, 1.0]) == me.Continuum(t=np.array([0.0, 1.0]))


# --- W2: a tabulated profile read its columns before their count refused them (a million points: 70 MB, 1.5 s,
# then "lengths 1000000 ... allowed: 3 to 10000"); counted first ---------------------------------------------------

def test_a_tabulated_profile_counts_its_columns_before_reading_them():
    column = np.broadcast_to(1.0, (VIEW_VALUES,))

    def refused():
        one_line_naming(lambda: me.TabulatedProfile(column, column), "lengths 1000000 and 1000000")
    assert peak_of(refused) < COUNTED_PEAK_BYTES


# --- W3: the discrete model at the layer tables' edge (a flat punch's face at a/h = 64 exactly) was told "a smaller
# dx", which cannot help there; the refusal names what applies: the spacing that fits where there is room (applied
# back: it runs), no spacing at the edge, a smaller face or a shallower depth, a thicker layer -----------------------

FACE = 1e-3


def _punch_on(thickness: float) -> me.Contact:
    return me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.FlatPunch(FACE), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                      me.FrictionLaw("tau0", tau0=PAPER.tau0), me.Layer(thickness))


def _spacing_named(message: str) -> float:
    found = re.search(r"allowed: dx <= ([0-9.e+-]+) m", message)
    assert found, message
    return float(found.group(1))


def test_a_face_at_the_tables_edge_is_told_no_spacing_helps():
    thickness = FACE / 64  # (exact: a power of two apart)
    message = one_line_naming(lambda: me.simulate(_punch_on(thickness), "B", 20.0, "discrete"), "dx=")
    assert "smaller dx" not in message and "no dx" in message, message
    assert f"a layer thicker than h = {thickness!r} m" in message and "a face's radius below" in message, message


def test_a_face_within_the_tables_is_told_the_spacing_that_runs():
    contact = _punch_on(1.001 * FACE / 64)
    message = one_line_naming(lambda: me.simulate(contact, "B", 20.0, "discrete", n_steps=100), "dx=")
    ds = me.simulate(contact, "B", 20.0, "discrete", dx=_spacing_named(message), n_steps=100)
    assert _finite_in_contact(ds.normal_force.values)


def test_a_paraboloid_near_the_tables_edge_is_told_the_spacing_that_runs():
    """Round fourteen's case (a contact radius 0.1 % inside the tables' last, 100 springs to it): the named spacing
    runs, and the depth's bound is named."""
    contact, thickness = me.Contact.paper().replace(h=1e-4), 1e-4
    target = 0.999 * 64 * thickness
    low = depth_reaching(contact, target, 3e-4, 4e-4)  # (the depth of that radius on the Δγ0 branch)
    scenario = me.Scenario("A", alpha=[20.0], d_max=low)
    message = one_line_naming(lambda: me.simulate(contact, scenario, "discrete", dx=64 * thickness / 100,
                                                  n_steps=100), "dx=")
    assert "a depth whose contact radius stays below" in message, message
    ds = me.simulate(contact, scenario, "discrete", dx=_spacing_named(message), n_steps=100)
    assert _finite_in_contact(ds.normal_force.values)


# --- W4: a Scenario built by the user read its angles when it was made (converted, checked for repeats and kept as
# a tuple of floats: a million angles 54 MB and 0.8 s, a view of 1e9 one value ~100 GB), before any limit; by name
# (simulate(contact, "A", alpha=...)) the same angles are counted first. A Scenario counts its angles first and
# refuses more than any run within the default limits takes (Limits.samples / 2: every run makes 2 output times a
# case at least), naming alpha, the count and the bound; by name, the run's limits bound them (angles_within) ------

#: Angles beyond what any run within the default limits takes (Limits.samples / 2 = 5e6 cases): a view of one value,
#: no memory of its own, refused by its count before it is read (or found repeated).
BEYOND_DEFAULT_ANGLES = 10**7


def test_a_scenario_counts_its_angles_before_reading_them():
    angles = np.broadcast_to(20.0, (BEYOND_DEFAULT_ANGLES,))
    assert refused_for_resources(lambda: me.Scenario("A", angles)) < COUNTED_PEAK_BYTES
    message = one_line_naming(lambda: me.Scenario("A", angles), "alpha of 10000000 angles", errors=me.ResourceLimitError)
    assert "at most 5e+06" in message and "limits=Limits(samples=...)" in message, message


def test_a_scenario_by_name_takes_the_angles_its_run_s_limits_take(monkeypatch):
    """By name, the run's limits (its count checked first) bound the angles, not the default limits': with the
    bound of a Scenario made alone lowered to 10 angles, 11 are refused alone and taken by name."""
    monkeypatch.setattr(motion, "_ANGLES_MAX", contextvars.ContextVar("angles_max", default=10.0))
    angles = np.linspace(10.0, 80.0, 11)
    one_line_naming(lambda: me.Scenario("A", angles), "alpha of 11 angles", errors=me.ResourceLimitError)
    job = simulation_job(PAPER, "A", angles, "continuum", {}, me.Limits())
    assert job.model.motion.alpha == tuple(angles)
    with motion.angles_within(me.Limits(samples=20)):
        one_line_naming(lambda: me.Scenario("A", angles), "at most 10", errors=me.ResourceLimitError)


# --- W5: the standard output's help, version and encoding: `mdr-events --help > /dev/full` (and --version, a
# verb's --help) ended 0 with nothing written (argparse ignores its write errors, the text was printed before the
# command's stdout was named); PYTHONIOENCODING=ascii `mdr-events derive` printed "'ascii' codec can't encode
# character '\u2320' in position 38" without naming what or what is allowed. The parsing runs with the stdout named,
# its first write error raised again when flushed; text its encoding cannot write is refused naming the encoding --

class _FullDevice(io.StringIO):
    """A standard output on a full device: every write fails as /dev/full's (ENOSPC)."""

    def write(self, text: str) -> int:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


@pytest.mark.parametrize("argv", [["--help"], ["--version"], ["derive", "--help"], ["simulate", "--help"]])
def test_cli_help_on_a_full_device_is_named(capsys, monkeypatch, argv):
    monkeypatch.setattr(sys, "stdout", _FullDevice())
    err = cli_one_line(capsys, argv)
    assert "<standard output>" in err and "No space left on device" in err and "allowed" in err, err


def test_cli_help_is_printed_with_exit_0(capsys):
    with pytest.raises(SystemExit) as stopped:
        main(["--help"])
    assert stopped.value.code == 0 and capsys.readouterr().out.startswith("usage: mdr-events")


def test_standard_output_s_write_error_is_raised_by_one_flush():
    """The first write error is raised by the next flush, then cleared: raised again by every later flush, the same
    exception object's traceback grew with each (a reviewer's finding)."""
    output = NamedOutput(_FullDevice())
    with pytest.raises(OSError, match="<standard output>"):
        output.write("text")
    with pytest.raises(OSError, match="<standard output>"):
        output.flush()
    output.flush()
    assert output.failed is None


@pytest.mark.parametrize("encoding", ["ascii", "latin-1"])
def test_cli_standard_output_of_a_narrow_encoding_is_named(capsys, monkeypatch, encoding):
    monkeypatch.setattr(sys, "stdout", io.TextIOWrapper(io.BytesIO(), encoding=encoding))
    err = cli_one_line(capsys, ["derive", "--key", "hertz_normal_force"])
    assert f"<standard output> of encoding '{encoding}' cannot write" in err and "PYTHONIOENCODING=utf-8" in err, err


# --- W6: a file's write error named no file: under `ulimit -f` (or on a full disk) `mdr-events simulate` and
# `validate` printed "mdr-events: error: [Errno 27] File too large" and write_netcdf raised it bare (the writer's
# OSError carries no file name; only the temporary's were renamed). The file being written is named, with what a
# write needs -----------------------------------------------------------------------------------------------------

#: A file size limit (bytes) below a one-angle simulation's figure (~60 kB) and above nothing else the test writes.
FILE_SIZE_LIMIT = 20_000


def test_a_writer_s_error_names_the_file(tmp_path):
    from mdr_events.io.files import atomic_write

    def writer(temporary: str) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))  # (as a full disk's write: no file name)

    target = tmp_path / "run.nc"
    with pytest.raises(OSError) as raised:
        atomic_write(target, writer)
    assert raised.value.filename == os.fspath(target) and "allowed" in str(raised.value), raised.value
    assert list(tmp_path.iterdir()) == []  # (the temporary removed, nothing placed)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="RLIMIT_FSIZE is POSIX")
def test_cli_file_too_large_names_the_file(capsys, tmp_path):
    import resource

    soft, hard = resource.getrlimit(resource.RLIMIT_FSIZE)
    resource.setrlimit(resource.RLIMIT_FSIZE, (FILE_SIZE_LIMIT, hard))  # (Python ignores SIGXFSZ: writes fail EFBIG)
    try:
        err = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", "--n-steps", "200", "--out",
                                    str(tmp_path)])
    finally:
        resource.setrlimit(resource.RLIMIT_FSIZE, (soft, hard))
    assert re.search(re.escape(str(tmp_path / "simulation_A_discrete.")) + r"(nc|png): File too large", err), err
    assert "ulimit -f" in err, err
    assert list(tmp_path.iterdir()) == []


# --- W7: fit_rate_adhesion read each measurement's samples (converted three times: 24 MB for a million) before
# their count was checked against its limits; counted first -------------------------------------------------------

def test_a_rate_fit_counts_its_samples_before_reading_them():
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.5)
    samples = np.broadcast_to(1.0, (VIEW_VALUES,))
    measured = me.RateMeasurement(me.Path([(0.0, -1e-5), (0.0, 1e-4), (1e-4, -1e-5)], 1e-6), samples, samples, 0.01)
    assert refused_for_resources(lambda: me.fit_rate_adhesion([measured], PAPER, law,
                                                               limits=SMALL)) < COUNTED_PEAK_BYTES


# --- W8: a cone on a layer under tau0+coulomb in the continuum ran for minutes: PowerLaw(0.2, 1) on
# h = 2 mm, mu = 0.5, scenario A at 45° or 89.5° (300 samples) spent over 5 min of CPU in the play springs' golden-section
# search (play_springs._golden, one section per flagged sample, 80 steps each), where the paraboloid, a power law of
# n = 3, the cone under Coulomb's law alone or the cone on a thick layer take ~2 s; PowerLaw(0.5, 1.01) likewise, in A,
# B and B+. Now one batched section per convex stretch, 45 steps (over 150 s -> ~5 s at 30 samples, ~37x the
# paraboloid's run with its tables already made: each golden step inverted the layer's radius at every point), and the
# sections read ``ū(a(t))`` from a cubic spline of each stretch (play_springs.GOLDEN_TABLE_RTOL; ~0.7 s, ~5x) -----

#: The cone's run may take this many times the paraboloid's CPU time on the same layer, law and samples, both with the
#: layer's tables made (a ratio, so the machine's speed and load cancel; measured ~5x with the stretches' splines,
#: ~37x with an inversion each golden step, over 100x before).
CONE_RUN_CPU_RATIO = 10.0
#: The runs' output samples (the cost grows with them: the sections are per sample; 30 keep the test near 3 s).
CONE_RUN_SAMPLES = 30


def _cpu_limited_run(indenter, budget: float | None):
    """Scenario A at 45° on the 2 mm layer under tau0+coulomb (:data:`CONE_RUN_SAMPLES`), stopped past ``budget`` s
    of CPU: its dataset and the CPU time it took."""
    import dataclasses

    kw = {} if indenter is None else {"indenter": indenter}
    contact = dataclasses.replace(me.Contact.paper(), friction=me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.5),
                                  layer=me.Layer(2e-3), **kw)
    return cpu_limited(lambda: me.simulate(contact, "A", [45.0], "continuum", samples=CONE_RUN_SAMPLES), budget)


@pytest.mark.slow  # (the paraboloid's ~1.5 s twice, then up to CONE_RUN_CPU_RATIO times its second run)
def test_a_cone_on_a_layer_under_both_laws_finishes():
    _cpu_limited_run(None, None)  # (the layer's tables and the relations made: the first run's cost, not the run's)
    _, paraboloid = _cpu_limited_run(None, None)
    ds, _ = _cpu_limited_run(me.PowerLaw(0.2, 1.0), CONE_RUN_CPU_RATIO * paraboloid)
    assert _finite_in_contact(ds.normal_force.values)
    tangential = np.asarray(ds.tangential_force.values).ravel()
    # (scenario A at 45°: pushed down and sideways, then back; F_x follows x's sign and vanishes with the contact)
    assert np.all(np.isfinite(tangential)) and np.all(tangential >= 0.0) and np.max(tangential) > 0.0
