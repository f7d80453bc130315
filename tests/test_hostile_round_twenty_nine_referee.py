"""The twenty-ninth hostile round (issue 32), the referee's side: each class of what failed, with the cases that
showed it.

The round's cases (``validate`` on crafted wrong runs of scenario A 20° — forces off by a constant or a sign, time
shifted or stretched, truncated, thinned, reordered, duplicated, units off by 1000, columns swapped, another angle,
radius or scenario — beside the right runs, the continuum resampled and the discrete at 2 µm with noise at the stated
level; ``fit`` on flat, zero, one- and two-point and noisy data; ``lammps-check`` at the edges of its parameters) are
listed with their outcomes in the issue's closing note; what failed is below.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.reports import ValidationReport
from mdr_events.dem.check import lammps_check
from mdr_events.dem.deck import check_depth_within_sphere
from mdr_events.dem.mapping import LammpsModel
from mdr_events.dem.runner import run_lammps
from hostile_checks import cli_one_line, one_line_naming

#: The paper's deepest depth (m): scenario A's path goes down to it.
D_MAX = me.Parameters.paper().d_max
#: LAMMPS's steps of the runs below: 20 a segment at least (the deck's rule) and cheap.
STEPS = 2000
#: Sphere radii (m) that the paper's path reaches or passes: 2/3 of the depth (LAMMPS ran, and the verdict failed
#: naming only "a sample left out lies 1.19 ranges from the exact value"), the depth itself (the centre on the wall)
#: and 1e-12 m (the sphere left the box: "LAMMPS: ERROR: Lost atoms").
TOO_SMALL = (2e-4, D_MAX, 1e-12)


#: The discrete spacing (m) of the candidate below: its first sample (t = 0) is out of contact where the exact
#: contact has just jumped in (``left_out`` code 2), and the run passes :data:`SPRING_TOLERANCE`.
SPRING_DX = 8e-6
#: The spring model's verdict bound at :data:`SPRING_DX` (its max error there: 0.4 % of the range).
SPRING_TOLERANCE = 2e-2
#: Spikes at the sample where the contact differs, as shares of the quantity's largest magnitude: each one more than
#: the tolerance beyond every exact value around it, each below the one range the verdict allowed there before.
SPIKES = (0.05, -0.3, 0.9)
#: The continuum resampled from this long before its first contact (s): the contact is then made between two samples,
#: and the first sample in contact straddles the jump-in (``left_out`` code 3).
BEFORE_CONTACT = 3.7
#: Its samples over the whole run (the exact run's 1202 s: ~0.8 s apart).
RESAMPLED = 1537


def _hertz(R: float) -> me.Contact:
    """The paper's elastomer without adhesion or friction, a sphere of radius ``R``."""
    return me.Contact.paper().replace(R=R, dgamma0=0.0, dgamma1=0.0, tau0=0.0)


@pytest.mark.parametrize("R", TOO_SMALL)
def test_a_path_as_deep_as_the_lammps_sphere_is_refused_before_lammps_runs(R):
    """Class 2 (refused before running, with the bound that applies): LAMMPS's sphere has its centre at ``z = R - d``
    above the wall, so a path reaching ``d >= R`` pushes it onto and through the wall, where the MDR's paraboloid goes
    on: the check ran LAMMPS and failed for no stated cause, or stopped on LAMMPS's "Lost atoms". Refused in one line
    naming R, the path's depth and the bound, by the API's both entries and the CLI."""
    contact = _hertz(R)
    model = LammpsModel("hertz/material")
    message = one_line_naming(lambda: lammps_check(contact, "A", 20.0, model=model, steps=STEPS), "R=")
    assert f"{D_MAX:.6g}" in message
    path = me.Scenario("A", [20.0]).cases(contact.parameters(D_MAX, me.Parameters.paper().v)).paths[0]
    one_line_naming(lambda: run_lammps(contact, path, "hertz/material", steps=STEPS), "R=")


def test_the_cli_refuses_a_sphere_the_path_passes_through(capsys, tmp_path):
    err = cli_one_line(capsys, ["lammps-check", "--scenario", "A", "--alpha", "20", "--normal", "hertz/material",
                                "--dgamma0", "0", "--dgamma1", "0", "--R", "2e-4", "--steps", str(STEPS),
                                "--out", str(tmp_path / "out")])
    assert "R=0.0002" in err
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_the_bound_is_the_depth_itself():
    """The bound is the deck's geometry: a sphere one ulp larger than the path's depth is taken (the overlap is the
    depth at every ``d < R``), the depth itself refused."""
    path = me.Scenario("A", [20.0]).cases(me.Parameters.paper()).paths[0]
    deepest = float(path.max_depth)
    check_depth_within_sphere(math.nextafter(deepest, math.inf), path)
    one_line_naming(lambda: check_depth_within_sphere(deepest, path), "R=")


@pytest.fixture(scope="module")
def spring_run():
    """The spring model along A 20° at :data:`SPRING_DX`, its samples written (the rows after the run's end dropped)."""
    run = me.simulate(me.Contact.paper(), me.Scenario("A", alpha=[20]),
                      me.Discrete(dx=SPRING_DX, dt=SPRING_DX / 2e-6)).sel(alpha=20)
    written = np.isfinite(run.normal_force.values)
    return {name: run[name].values[written] for name in ("time", "normal_force", "tangential_force", "contact_area")}


def _validated(candidate: dict) -> ValidationReport:
    return ValidationReport.from_dataset(me.validate(candidate, me.Contact.paper(), "A", 20.0,
                                                     tolerance=SPRING_TOLERANCE))


def test_the_honest_spring_run_passes_with_a_sample_where_the_contact_differs(spring_run):
    """The run the spikes below spoil: it passes, one sample's contact differs from the exact, and there it lies
    within the exact values around it (0 beyond them)."""
    report = _validated(spring_run)
    assert report.passed
    assert int(np.count_nonzero(report.dataset["left_out"].values == 2)) >= 1
    assert np.all(report.dataset["contact_change_max_excess"].values == 0.0)


@pytest.mark.parametrize("name", ("normal_force", "tangential_force", "contact_area"))
@pytest.mark.parametrize("spike", SPIKES)
def test_a_spike_where_the_contact_differs_fails(spring_run, name, spike):
    """Class 1 (a broken run never passes): at a sample where one run is in contact and the other not, the verdict
    bounded the candidate by one range of the exact value (``LEFT_OUT_BOUND``), so a DEM code's start-up spike of
    0.9 times the peak force at its first sample passed. A contact made or lost at another time moves the jump between
    the exact values on either side: beyond them and 0 the sample fails by the tolerance, named."""
    report = _validated(spring_run)
    where = int(np.flatnonzero(report.dataset["left_out"].values == 2)[0])
    spoiled = {key: values.copy() for key, values in spring_run.items()}
    if name == "contact_area":  # (a positive area would put the candidate in contact there: a sample compared)
        spike = -abs(spike)
    spoiled[name][where] += spike * float(np.max(np.abs(spring_run[name])))
    failed = _validated(spoiled)
    assert not failed.passed
    assert any(text.startswith(f"{name}: a sample where the contact differs or is made") for text in failed.failures), \
        failed.failures


@pytest.fixture(scope="module")
def resampled_continuum():
    """The exact run along A 20° sampled from :data:`BEFORE_CONTACT` before its first contact (0 out of contact)."""
    scenario = me.Scenario("A", alpha=[20])
    end = float(me.simulate(me.Contact.paper(), scenario, "continuum").time[-1])
    times = np.linspace(-BEFORE_CONTACT, end, RESAMPLED)
    touching = me.simulate(me.Contact.paper(), scenario, "continuum", t=times[times >= 0]).sel(alpha=20)
    before = np.zeros(np.count_nonzero(times < 0))
    return {"time": times, **{name: np.concatenate([before, touching[name].values])
                              for name in ("normal_force", "tangential_force", "contact_area")}}


@pytest.mark.parametrize("name", ("normal_force", "tangential_force", "contact_area"))
@pytest.mark.parametrize("spike", SPIKES)
def test_a_spike_at_the_first_sample_after_the_contact_is_made_fails(resampled_continuum, name, spike):
    """The same class where both runs are in contact: the first sample after a jump-in made between samples straddles
    it (code 3), and was bounded by one range too (the corners' rule covers corners and reversals only): a spike of
    0.9 times the peak passed. The honest resampled run passes at the default tolerance."""
    honest = ValidationReport.from_dataset(me.validate(resampled_continuum, me.Contact.paper(), "A", 20.0))
    assert honest.passed
    where = int(np.flatnonzero(resampled_continuum["time"] > 0)[0])
    assert honest.dataset["left_out"].values[where] == 3
    spoiled = {key: values.copy() for key, values in resampled_continuum.items()}
    spoiled[name][where] += spike * float(np.max(np.abs(resampled_continuum[name])))
    failed = ValidationReport.from_dataset(me.validate(spoiled, me.Contact.paper(), "A", 20.0))
    assert not failed.passed
    assert any(name in text for text in failed.failures), failed.failures
