"""The twenty-ninth hostile round (issue 32, class 4), the resource guards: a run that :class:`~mdr_events.Limits`
accepts uses, measured, no more memory than the limit allows, within the estimate's own slack, and a guard does not
refuse work that fits far under its limit.

The peaks are measured with :mod:`tracemalloc` (NumPy's arrays are traced) after a warm-up run, so the caches a first
run fills are not counted. What failed: the continuum method counted only its output (128 B per case and output
time), but each case's evaluation holds 235-447 B per output time beside it, so that a run of one case peaked at
2.6-3.5 times the memory it was checked against.
"""

from __future__ import annotations

import dataclasses
import tracemalloc

import pytest

import mdr_events as me
from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.friction import FrictionLaw

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
