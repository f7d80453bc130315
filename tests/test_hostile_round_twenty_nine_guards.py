"""The twenty-ninth hostile round (issue 32, class 4), the resource guards: a run that :class:`~mdr_events.Limits`
accepts uses, measured, no more memory than the limit allows, within the estimate's own slack, and a guard does not
refuse work that fits far under its limit.

The peaks are measured with :mod:`tracemalloc` (NumPy's arrays are traced) after a warm-up run, so the caches a first
run fills are not counted. What failed: the continuum method counted only its output (128 B per case and output
time), but each case's evaluation holds 235-447 B per output time beside it, so that a run of one case peaked at
2.6-3.5 times the memory it was checked against; the phase diagram (and the onsets) of ``tau0+coulomb`` on a curved
indenter sampled their excess on a grid of 2048 depths for every angle at once, 166 kB an angle against the 160 B
counted (1e5 angles, accepted under the default 2 GiB, peaked at 16.6 GB).
"""

from __future__ import annotations

import dataclasses
import tracemalloc

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.friction import FrictionLaw
from mdr_events.theory.phase import BYTES_PER_ANGLE

#: How far a run's measured peak may exceed the memory its guard checked (the estimate's own slack: the per-sample
#: constants are measured and rounded up, the arrays NumPy and xarray make around them are not all counted).
PEAK_SLACK = 1.5
#: How far a guard's estimate may exceed the measured peak before it refuses legitimate work.
ESTIMATE_EXCESS = 10.0
#: Output times of the runs measured: large enough for the samples' arrays to dominate the peak, cheap (~0.2 s).
SIZES = (20_000, 60_000)

PAPER = me.Contact.paper(R=0.03)
CONTACTS = {
    "paper": PAPER,
    "coulomb": dataclasses.replace(PAPER, friction=FrictionLaw("coulomb", mu=0.3)),
    "rate": dataclasses.replace(PAPER, adhesion=RateDependentAdhesion(
        dgamma0=PAPER.adhesion.dgamma0, dgamma1=PAPER.adhesion.dgamma1, v_ref=1e-6, n=0.5)),
}


def _peak(contact: me.Contact, scenario: me.Scenario, samples: int) -> int:
    """The bytes ``simulate(method=Continuum(samples))`` allocates at its peak, beyond what was held before."""
    me.simulate(contact, scenario, me.Continuum(samples=50))  # (warm-up: the caches a first run fills)
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        me.simulate(contact, scenario, me.Continuum(samples=samples))
        return tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("samples", SIZES)
@pytest.mark.parametrize("law", ["paper", "coulomb", "rate"])
def test_a_continuum_run_of_one_case_is_refused_below_its_measured_peak(law, samples):
    contact, scenario = CONTACTS[law], me.Scenario("A", alpha=[20])
    peak = _peak(contact, scenario, samples)
    with pytest.raises(me.ResourceLimitError, match="memory"):
        me.simulate(contact, scenario, me.Continuum(samples=samples), limits=me.Limits(memory=peak / PEAK_SLACK))


@pytest.mark.parametrize("cases", [1, 10])
def test_a_continuum_run_well_within_its_limit_is_accepted(cases):
    scenario = me.Scenario("B", alpha=list(range(10, 10 + cases)))
    peak = _peak(PAPER, scenario, SIZES[0])
    dataset = me.simulate(PAPER, scenario, me.Continuum(samples=SIZES[0]),
                          limits=me.Limits(memory=peak * ESTIMATE_EXCESS))
    assert dataset.sizes["time"] == SIZES[0]


#: Angles of the phase diagrams measured: a few of the combined onset's blocks of angles, cheap (~1 s).
ANGLE_COUNTS = (100, 600)
COMBINED = dataclasses.replace(PAPER, friction=FrictionLaw("tau0+coulomb", mu=0.3, tau0=PAPER.friction.tau0))


def _phase_peak(contact: me.Contact, angles: np.ndarray, scenario: str) -> int:
    """The bytes ``phase_diagram`` allocates at its peak beyond its angles, after a warm-up."""
    me.phase_diagram(contact, angles[:10], scenario=scenario)
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        me.phase_diagram(contact, angles, scenario=scenario)
        return tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("count", ANGLE_COUNTS)
@pytest.mark.parametrize("scenario", ["A", "B"])
def test_a_phase_diagram_of_the_combined_law_is_refused_below_its_measured_peak(scenario, count):
    # (on 24a0674 each angle held 166 kB against the 160 B counted: 1e5 angles, accepted, peaked at 16.6 GB)
    angles = np.linspace(0.5, 89.5, count)
    peak = _phase_peak(COMBINED, angles, scenario)
    with pytest.raises(me.ResourceLimitError, match="memory"):
        me.phase_diagram(COMBINED, angles, scenario=scenario, limits=me.Limits(memory=peak / PEAK_SLACK))
    accepted = me.phase_diagram(COMBINED, angles, scenario=scenario, limits=me.Limits(memory=peak * ESTIMATE_EXCESS))
    assert accepted.sizes["alpha"] == count


def test_the_combined_onset_s_peak_does_not_grow_with_the_angles_grid():
    # the grid's temporaries are held for GRID_ROWS angles at a time: 600 angles hold about what 100 do beside their
    # own arrays (160 B an angle counted), where on 24a0674 the peak grew as 166 kB an angle
    small, large = (_phase_peak(COMBINED, np.linspace(0.5, 89.5, count), "A") for count in ANGLE_COUNTS)
    assert large - small <= BYTES_PER_ANGLE * (ANGLE_COUNTS[1] - ANGLE_COUNTS[0])
