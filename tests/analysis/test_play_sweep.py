"""A continuum sweep of Coulomb's part on a layer (issue 34): refused before (its quantities read the spans' solution),
it takes ``simulate``'s per-spring run now (``mdr_events.analysis.play_sweep``).

Checked against:

- ``simulate``'s continuum dataset of the same run (same output times): the extrema, the events and the history bit
  for bit (one run gives both);
- the half-space's continuum sweep (the spans: exact extrema, event roots at ``rtol``, the work step by step) at
  ``h = 1e9 m``: the tables differ from the half-space by ``O(a/h)`` and the routes by their quadratures
  (``tests/models/test_layer_coulomb.py``: ``LIMIT_SHARE``, events to 100 ``rtol`` of the run); the work by
  Gauss–Legendre between the breaks (``play_sweep.WORK_PIECES``: 3e-11 measured) within :data:`LIMIT_SHARE` too.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me

SERIAL = me.Engine(scheduler="serial")
LAWS = {"coulomb": me.FrictionLaw("coulomb", mu=0.3),
        "tau0+coulomb": me.FrictionLaw("tau0+coulomb", mu=0.3, tau0=42000.0)}
#: The thick layer against the half-space, relative to each quantity's scale (forces: the largest; depths: ``d_max``;
#: times: the run's duration, at 100 ``rtol``).
LIMIT_SHARE = 1e-8
EVENT_SHARE = 100.0 * me.Tolerances().rtol
FORCES = ("normal_force_min", "tangential_force_max", "pull_off_force")
DEPTHS = ("slip_onset_in_depth", "slip_onset_out_depth", "pull_off_depth")
TIMES = ("slip_onset_in_time", "slip_onset_out_time", "full_slip_time", "pull_off_time")
MOTION = me.Scenario("B", alpha=[20.0])
#: The continuum's output times per run (the per-spring route's samples: its events are searched between them, its
#: ``F_x`` extrema refined between them), few for seconds of CPU a run.
CONTINUUM = me.Continuum(samples=41)


def contact(law: str, **changes) -> me.Contact:
    return dataclasses.replace(me.Contact.paper(), friction=LAWS[law]).replace(**changes)


def close(value: float, expected: float, atol: float) -> bool:
    return (math.isnan(value) and math.isnan(expected)) or abs(value - expected) <= atol


@pytest.mark.parametrize("law, works", [("coulomb", 0.0), ("tau0+coulomb", None)],
                         ids=["coulomb, no adhesion", "tau0+coulomb, the paper's adhesion"])
def test_a_thick_layers_continuum_sweep_is_the_half_spaces(law, works):
    """Scenario B at 20° (slip onset on the way out, full slip, the contact's end or pull-off): every quantity of the
    thick layer's cell (the per-spring run) is the half-space's (the spans). (Coulomb's law alone with adhesion slides
    its tensile annulus from the first instant, which the spans log as a slip onset at the first contact and the
    per-spring route does not: ``tests/models/test_layer_coulomb.py`` compares its log under both parts alone.)"""
    changes = {} if works is None else {"dgamma0": works, "dgamma1": works}
    swept = me.sweep({"h": [1e9, math.inf]}, contact(law, **changes), MOTION, None, CONTINUUM, engine=SERIAL)
    assert int(swept["failed"].sum()) == 0
    thick, half = swept.sel(h=1e9), swept.sel(h=math.inf)
    scale = max(abs(float(half[name])) for name in FORCES)
    duration = float(MOTION.cases(me.Parameters.paper(), None, LAWS[law]).paths[0].duration)
    d_max = me.Parameters.paper().d_max
    for names, atol in ((FORCES, LIMIT_SHARE * scale), (DEPTHS, LIMIT_SHARE * d_max), (TIMES, EVENT_SHARE * duration),
                        (("contact_area_max",), LIMIT_SHARE * float(half["contact_area_max"])),
                        (("tangential_work",), LIMIT_SHARE * float(half["tangential_work"]))):
        for name in names:
            assert close(float(thick[name]), float(half[name]), atol), (name, float(thick[name]), float(half[name]))
    assert float(thick["event_count"]) == float(half["event_count"])
    assert math.isfinite(float(thick["full_slip_time"])) and math.isfinite(float(thick["slip_onset_out_time"]))


def test_a_layers_continuum_sweep_cell_is_simulates_continuum_run():
    """On the paper's 5 mm layer the cell's extrema, events and history are those of ``simulate``'s dataset (one run,
    the same output times; the path starts at first contact, so the dataset's clock is the sweep's)."""
    layered = contact("tau0+coulomb", h=5e-3)
    swept = me.sweep({"h": [5e-3]}, layered, MOTION, None, CONTINUUM, engine=SERIAL, history_samples=9).sel(h=5e-3)
    run = me.simulate(layered, MOTION, CONTINUUM).isel(alpha=0)
    assert float(swept["normal_force_min"]) == float(run["normal_force_min"])
    assert float(swept["contact_area_max"]) == float(run["contact_area_max"])
    assert float(swept["tangential_force_max"]) == max(abs(float(run["tangential_force_max"])),
                                                       abs(float(run["tangential_force_min"])))
    kinds, times = [str(kind) for kind in run["event_kind"].values], run["event_time"].values
    assert float(swept["full_slip_time"]) == float(times[kinds.index("full_slip")])
    assert float(swept["pull_off_time"]) == float(times[kinds.index("pull_off")])
    assert float(swept["event_count"]) == len(kinds)
    path = MOTION.cases(me.Parameters.paper(), None, layered.friction).paths[0]
    assert path.first_contact_time() == 0.0
    history_times = np.linspace(0.0, path.duration, 9)  # (the sweep's history: even over the path)
    inside = history_times <= times[-1]
    at = me.simulate(layered, MOTION, "continuum", t=history_times[inside]).isel(alpha=0)
    np.testing.assert_array_equal(swept["history_tangential_force"].values[inside], at["tangential_force"].values)
    np.testing.assert_array_equal(swept["history_normal_force"].values[inside], at["normal_force"].values)


def test_the_flat_punch_on_a_layer_sweeps_with_coulombs_part():
    """The flat punch (the per-spring route on its springs, ``g = 0`` under the face) in a continuum sweep over ``h``:
    the thick layer's quantities are the half-space punch's spans'."""
    punch = dataclasses.replace(contact("tau0+coulomb"), indenter=me.FlatPunch(2e-3))
    motion = me.Scenario("B", alpha=[20.0], d_max=2e-5)
    swept = me.sweep({"h": [1e9, math.inf]}, punch, motion, None, CONTINUUM, engine=SERIAL,
                     quantities=("normal_force_min", "tangential_force_max", "tangential_work", "pull_off_time"))
    assert int(swept["failed"].sum()) == 0
    thick, half = swept.sel(h=1e9), swept.sel(h=math.inf)
    for name in ("normal_force_min", "tangential_force_max", "tangential_work"):
        assert abs(float(thick[name]) - float(half[name])) <= LIMIT_SHARE * abs(float(half[name])), name
    duration = float(half["pull_off_time"])
    assert abs(float(thick["pull_off_time"]) - duration) <= EVENT_SHARE * duration
