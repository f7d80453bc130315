"""A continuum sweep of the rate-dependent adhesion law (issue 29, item 4): each run is ``simulate``'s continuum run
of the same contact and path, bit for bit (extrema, events, history), the law's ``v_ref`` and ``n`` sweep as axes, the
tangential work is ``∫ F_x dx`` of the run's own curve, and the rate-independent closed-form angles are not claimed."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.sweep_runs import SweepSpec
from mdr_events.models.methods import Continuum

LAW = me.RateDependentAdhesion(0.01, 0.15, 1e-6, 0.5)
#: The grid of the bit-for-bit test: two reference speeds and two exponents of the law.
GRID = {"adhesion.v_ref": [1e-7, 1e-5], "adhesion.n": [0.4, 1.0]}
HISTORY = 7


def rate_contact(**changes) -> me.Contact:
    return dataclasses.replace(me.Contact.paper(), adhesion=dataclasses.replace(LAW, **changes))


def single_run(contact: me.Contact, motion: me.Scenario, times=None):
    """``simulate``'s continuum run of one case (at ``times`` from the first contact, if given)."""
    method = Continuum() if times is None else Continuum(t=times)
    return me.simulate(contact, motion, method).isel(alpha=0)


@pytest.mark.parametrize("scenario, alpha", [("A", 20.0), ("B", 30.0)])
def test_each_run_of_a_continuum_sweep_is_the_single_run_bit_for_bit(scenario, alpha):
    motion = me.Scenario(scenario, [alpha])
    result = me.sweep(GRID, rate_contact(), motion, method="continuum", scheduler="serial",
                      history_samples=HISTORY)
    assert result.attrs["failed_runs"] == 0, result["error"].values
    path = motion.cases(me.Parameters.paper()).paths[0]
    start = path.first_contact_time()
    for v_ref in GRID["adhesion.v_ref"]:
        for n in GRID["adhesion.n"]:
            run = result.sel({"adhesion.v_ref": v_ref, "adhesion.n": n})
            times = np.linspace(0.0, path.duration, HISTORY)
            after = times >= start
            alone = single_run(rate_contact(v_ref=v_ref, n=n), motion)
            sampled = single_run(rate_contact(v_ref=v_ref, n=n), motion, times[after] - start)
            assert float(run["normal_force_min"]) == float(alone["normal_force_min"])
            assert float(run["contact_area_max"]) == float(alone["contact_area_max"])
            assert float(run["tangential_force_max"]) == max(abs(float(alone["tangential_force_max"])),
                                                             abs(float(alone["tangential_force_min"])))
            kinds = list(alone["event_kind"].values)
            assert float(run["event_count"]) == len(kinds)
            for key, kind in (("full_slip", "full_slip"), ("pull_off", "contact_ends")):
                expected = float(alone["event_time"].values[kinds.index(kind)]) + start if kind in kinds else np.nan
                np.testing.assert_array_equal(float(run[f"{key}_time"]), expected)
            if "contact_ends" in kinds:
                assert float(run["pull_off_depth"]) == float(alone["event_depth"].values[kinds.index("contact_ends")])
            np.testing.assert_array_equal(run["history_normal_force"].values[after], sampled["normal_force"].values)
            np.testing.assert_array_equal(run["history_tangential_force"].values[after],
                                          sampled["tangential_force"].values)
            np.testing.assert_array_equal(run["history_normal_force"].values[~after], 0.0)
            assert np.isnan(float(run["critical_angle_A"]))  # (the closed forms are the rate-independent law's)
    ends = result["pull_off_time"].values
    assert scenario == "A" or np.any(np.isfinite(ends)), ends  # (B pulls out: the contact's end compared above)


def test_the_tangential_work_is_the_integral_of_the_runs_own_curve():
    """``∫ F_x dx`` by the sweep's Gauss–Legendre rule against the trapezoidal rule of ``simulate``'s samples: the
    trapezoid's error falls as the samples' spacing squared, so its value at ``N`` and ``2N`` samples brackets the
    integral within ``ORDER_MARGIN`` times their difference (Richardson: the finer one's error is a third of it)."""
    ORDER_MARGIN = 2.0
    motion = me.Scenario("A", [20.0])
    contact = rate_contact()
    swept = me.sweep({"adhesion.v_ref": [1e-6]}, contact, motion, method="continuum", scheduler="serial",
                     quantities=("tangential_work",))
    work = float(swept["tangential_work"].values[0])
    estimates = []
    for samples in (10001, 20001):
        run = me.simulate(contact, motion, Continuum(samples=samples)).isel(alpha=0)
        force, x = run["tangential_force"].values, run["tangential_displacement"].values
        kept = np.isfinite(force) & np.isfinite(x)
        estimates.append(float(np.trapezoid(force[kept], x[kept])))
    assert work > 0.0
    assert abs(work - estimates[1]) <= ORDER_MARGIN * abs(estimates[1] - estimates[0]), (work, estimates)


def test_the_closed_form_angles_alone_are_refused_under_the_rate_law():
    spec = SweepSpec(rate_contact(), me.Scenario("A", [20.0]), Continuum(), ("adhesion.v_ref",),
                     quantities=("critical_angle_A",))
    with pytest.raises(ValueError, match="the closed forms are rate independent; allowed"):
        spec.check([1e-6])


@pytest.mark.parametrize("friction", [me.FrictionLaw("coulomb", mu=0.3), me.FrictionLaw("tau0+coulomb", mu=0.3, tau0=3e4)])
def test_coulombs_part_under_the_rate_law_is_refused_before_a_continuum_sweep_runs(friction):
    """Each cell failed at run time (``solve_rate_shifts`` holds τ0's cap alone) once ``simulate``'s continuum took
    Coulomb's part under the law; the sweep now refuses it before it runs, naming what runs it."""
    contact = dataclasses.replace(rate_contact(), friction=friction)
    spec = SweepSpec(contact, me.Scenario("A", [20.0]), Continuum(), ("adhesion.v_ref",))
    with pytest.raises(ValueError, match=r"not allowed in a continuum sweep with adhesion=RateDependentAdhesion.*"
                                         r"allowed: FrictionLaw\('tau0'\)"):
        spec.check([1e-6])
