"""The twenty-third hostile round (issue 32): each class of what failed, with the cases that showed it.

The round's cases (``simulate``'s angles and output times in every form: lists, tuples, ranges, sets, generators,
0-d arrays, nan, inf, huge and empty grids, nested and ragged lists, ``np.broadcast_to`` and ``itertools.repeat``
of 1e9 values under small limits; the flat punch's face check through ``simulate`` (both methods), ``d_crit``,
``critical_angle`` and ``phase_diagram`` at and beyond ``a/h = 64``, its message's bounds applied back; layers at the
tables' reach for the paraboloid, a power law, ``ν = 0.45`` and a frictionless base, both methods, checked for nan
inside contact; round twenty-one's and twenty-two's harnesses again) are listed with their outcomes in the issue's
closing note; what failed is below.
"""

from __future__ import annotations

import errno
import io
import os
import sys

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import cli_one_line, one_line_naming
from mdr_events.app.cli import EXIT_BROKEN_PIPE, main

PAPER = me.Parameters.paper()
#: The face's radius (m); the layers below put it beyond a/h = 64 (the tables' last ratio) by a few percent and by
#: far more (h = 1e-9 m: 64 h is below one spring spacing, dx = 1 µm, so no spring lies within the tables).
FACE = 1e-3
BEYOND = [FACE / 65, 1e-7, 1e-9, 1e-300]


def _punch_on(thickness: float) -> me.Contact:
    return me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.FlatPunch(FACE), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                      me.FrictionLaw("tau0", tau0=PAPER.tau0), me.Layer(thickness))


# --- V1: a flat punch's face beyond the tables in the discrete method: h = 1e-9 and 1e-300 m raised numpy's
# "attempt to get argmin of an empty sequence" (the springs' count probed none), a face a few percent beyond was
# told "a smaller dx", which cannot help. The discrete checks the face as the continuum does (check_punch_face) ----

@pytest.mark.parametrize("thickness", BEYOND)
def test_discrete_refuses_a_face_beyond_the_tables_naming_the_bounds(thickness):
    message = one_line_naming(lambda: me.simulate(_punch_on(thickness), "B", 20.0, "discrete"), "FlatPunch")
    assert "discrete method" in message and f"a radius up to {64 * thickness:.6g} m" in message, message
    assert f"h >= {FACE / 64:.6g} m" in message, message


def test_discrete_takes_the_face_the_message_allows():
    """The least thickness the refusal names (a/64, with the 6-digit rounding up of the message: 1.5625e-05 is exact)
    is accepted but for the discrete's own spring beyond the face; one percent thicker runs."""
    ds = me.simulate(_punch_on(1.01 * FACE / 64), "B", 20.0, "discrete")
    assert np.isfinite(ds.normal_force.values[0, 0])


def test_cli_discrete_punch_on_a_thin_layer_is_one_line(capsys, tmp_path):
    err = cli_one_line(capsys, ["simulate", "--scenario", "B", "--alpha", "20", "--flat-punch", str(FACE),
                                "--h", "1e-9", "--out", str(tmp_path)])
    assert "discrete method" in err and "a/h = 64" in err, err


# --- V2: the standard output's write errors: `mdr-events derive > /dev/full` (and `simulate ... > /dev/full`, after
# its files were written) printed "mdr-events: error: [Errno 28] No space left on device", not naming what could not
# be written. The command's stdout names itself in its errors, flushed before the command ends ----------------------

class _FullDevice(io.StringIO):
    """A standard output on a full device: every write fails as /dev/full's (ENOSPC)."""

    def write(self, text: str) -> int:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


class _FullOnFlush(io.StringIO):
    """A buffered standard output whose writes succeed and whose flush fails (the text met the device there)."""

    def flush(self) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


@pytest.mark.parametrize("stream", [_FullDevice, _FullOnFlush])
def test_cli_standard_output_full_is_named(capsys, monkeypatch, stream):
    monkeypatch.setattr(sys, "stdout", stream())
    err = cli_one_line(capsys, ["derive", "--key", "hertz_normal_force"])
    assert "<standard output>" in err and "No space left on device" in err and "allowed" in err, err


def test_cli_broken_pipe_still_silent(capsys, monkeypatch):
    """The closed pipe (`| head`) stays silent with 141 (the write errors' naming leaves BrokenPipeError alone)."""

    class _Gone(io.StringIO):
        def write(self, text: str) -> int:
            raise BrokenPipeError(errno.EPIPE, os.strerror(errno.EPIPE))

    monkeypatch.setattr(sys, "stdout", _Gone())
    assert main(["derive", "--key", "hertz_normal_force"]) == EXIT_BROKEN_PIPE
    assert capsys.readouterr().err == ""


# --- V3 (open): a Continuum built by the user reads its output times when it is made, before any limit: simulate(p,
# "A", 20.0, me.Continuum(t=np.broadcast_to(0.1, (10**9,))), limits=small) peaked at 16 GB and 84 s in
# Continuum(...) (t converted, differenced and checked: ~2 copies), then refused it as not increasing; by name
# (method="continuum", t=...) the same times are counted first (check_counted_first) and refused at once. The
# method's times would be counted against the run's limits before they are read: the check of ``t`` moved from the
# method's construction to the run (the constructor has no limits) --------------------------------------------------

#: The times of V3's case: a view of one value, 800 MB if copied once; counted first, nothing of that size is made
#: (beyond the default limits' 1e7 samples, so the method keeps them as given until a run counts them).
VIEW_TIMES = 10**8
#: What counting them may take (tracemalloc's peak): far below one copy (8 MB); the message and the limits' check
#: take a few kB.
COUNTED_PEAK_BYTES = 2**20


def test_a_continuum_method_value_counts_its_times_before_reading_them():
    import tracemalloc

    times = np.broadcast_to(0.1, (VIEW_TIMES,))
    small = me.Limits(samples=1000, steps=10**6, memory=2**20)
    tracemalloc.start()
    try:
        with pytest.raises(me.ResourceLimitError):
            me.simulate(PAPER, "A", 20.0, me.Continuum(t=times), limits=small)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < COUNTED_PEAK_BYTES, peak
