"""The rate-dependent angles against speed take a Contact like every other entry point (analysis.rate_job): the
contact's form gives the same numbers as the form of before, (params, law, speeds), which keeps working; what is
not allowed beside either form is named. The continuum's rate run refuses a layer by name."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.kernel_model import KernelModel
from mdr_events.analysis.rate_angles import critical_angles_at_speeds
from mdr_events.analysis.rate_job import rate_job
from mdr_events.analysis.rate_let_go import critical_angles_B_at_speeds
from mdr_events.models.methods import _rate_run

PAPER = me.Parameters.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
SPEEDS = [1e-6]


def _contact():
    return dataclasses.replace(me.Contact.paper(), adhesion=LAW)


@pytest.mark.parametrize("angles", [critical_angles_at_speeds, critical_angles_B_at_speeds])
def test_a_contact_gives_the_numbers_of_the_form_of_before_bit_for_bit(angles):
    new = angles(_contact(), SPEEDS, method="LSODA")
    old = angles(PAPER, LAW, SPEEDS, method="LSODA")
    by_keyword = angles(PAPER, law=LAW, speeds=SPEEDS, method="LSODA")
    for name in new.data_vars:
        assert np.array_equal(new[name].values, old[name].values, equal_nan=True), name
        assert np.array_equal(by_keyword[name].values, old[name].values, equal_nan=True), name
    assert new.attrs == old.attrs


def test_a_contact_s_depth_is_its_motion_s():
    deeper = critical_angles_at_speeds(_contact(), SPEEDS, method="LSODA", d_max=2.0 * PAPER.d_max)
    old = critical_angles_at_speeds(PAPER.replace(d_max=2.0 * PAPER.d_max), LAW, SPEEDS, method="LSODA")
    assert np.array_equal(deeper["critical_angle"].values, old["critical_angle"].values)


def test_the_form_of_before_takes_its_tail_by_position():
    job = rate_job(PAPER, LAW, (SPEEDS, None, "LSODA"), what="f")
    assert job.params is PAPER and job.law is LAW and job.speeds is SPEEDS and job.options == {"method": "LSODA"}


@pytest.mark.parametrize("call, kind, words", [
    (lambda: rate_job(_contact(), SPEEDS, (), law=LAW, what="f"), ValueError, "law=.*beside a Contact"),
    (lambda: rate_job(_contact(), SPEEDS, (), profile=me.PowerLaw(1.0, 3.0), what="f"), ValueError,
     "profile=.*beside a Contact"),
    (lambda: rate_job(_contact(), SPEEDS, ("LSODA",), what="f"), TypeError, "speeds alone by position"),
    (lambda: rate_job(me.Contact.paper(), SPEEDS, (), what="f"), TypeError,
     r"contact.adhesion=Adhesion.*RateDependentAdhesion"),
    (lambda: rate_job(dataclasses.replace(_contact(), friction=me.FrictionLaw("coulomb", mu=0.3)), SPEEDS, (),
                      what="f"),
     ValueError, "contact.friction=.*coulomb.*tau0"),
    (lambda: rate_job(_contact(), SPEEDS, (), d_max=-1.0, what="f"), ValueError, "d_max=-1.0"),
    (lambda: rate_job(PAPER, LAW, (SPEEDS,), d_max=1e-4, what="f"), ValueError, "d_max=.*beside Parameters"),
    (lambda: rate_job(PAPER, LAW, (SPEEDS, None, "LSODA", None, 1), what="f"), TypeError, "at most 6 positional"),
    (lambda: rate_job(PAPER, "law", (SPEEDS,), what="f"), TypeError, "law="),
    (lambda: rate_job(PAPER, me.RateDependentAdhesion(0.02, PAPER.dgamma1, 1e-6, 0.6), (SPEEDS,), what="f"),
     ValueError,
     "works at rest are the parameters'"),
    (lambda: rate_job("paper", SPEEDS, (), what="f"), TypeError, "contact='paper'"),
    (lambda: critical_angles_at_speeds(_contact(), [1e-6, -1.0]), ValueError, r"speeds\[1\]=-1.0"),
])
def test_what_either_form_does_not_allow_is_named(call, kind, words):
    with pytest.raises(kind, match=words):
        call()


def test_the_continuum_s_rate_run_refuses_a_layer_by_name_before_it_runs():
    path = me.Path.scenario_A(20.0, PAPER)
    with pytest.raises(ValueError, match=r"layer=Layer\(.*not allowed with a rate-dependent law in the continuum"):
        _rate_run(KernelModel(PAPER, None, me.FrictionLaw("tau0", tau0=PAPER.tau0), LAW, me.Layer(5e-3)), [path], 11,
                  me.Tolerances(), me.Limits())
