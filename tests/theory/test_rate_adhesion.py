"""The rate-dependent adhesion law (contact.adhesion.RateDependentAdhesion) as data and as derived
(symbolic.derive_rate_dependent_adhesion, theory.rate_adhesion): validated fields, attributes that round-trip, the
work of adhesion and the edge's speed inverse to each other, the band of rest, the rate-independent limit, and the
flat punch's detachment time against a quadrature of the edge's law."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

import mdr_events as me
from mdr_events.contact.adhesion import Adhesion, RateDependentAdhesion, adhesion_from_attrs
from mdr_events.contact import Contact
from mdr_events.theory import rate_adhesion, symbolic

LAW = RateDependentAdhesion(0.05, 0.15, 1e-6, 0.6)
E_STAR = me.Parameters.paper().E_star
#: A speed through its work and back: powers and roots of doubles, a few ulp each.
ROUND_TRIP_RTOL = 1e-12
#: quad's tolerance on a smooth integrand.
QUAD_RTOL = 1e-10


@pytest.mark.parametrize("values, field", [
    ((0.0, 0.15, 1e-6, 0.6), "dgamma0"), ((0.05, 0.01, 1e-6, 0.6), "dgamma1"), ((0.05, 0.15, 0.0, 0.6), "v_ref"),
    ((0.05, 0.15, math.inf, 0.6), "v_ref"), ((0.05, 0.15, 1e-6, 0.0), "n"), ((0.05, 0.15, 1e-6, 1.5), "n"),
    ((0.05, 0.15, 1e-6, math.nan), "n"), ((math.nan, 0.15, 1e-6, 0.6), "dgamma0"),
])
def test_a_value_out_of_range_is_refused_by_name(values, field):
    with pytest.raises(ValueError, match=f"RateDependentAdhesion.{field}=.*allowed"):
        RateDependentAdhesion(*values)


def test_the_law_round_trips_through_attributes_and_a_contact():
    attrs = LAW.to_attrs()
    assert adhesion_from_attrs(attrs) == LAW and adhesion_from_attrs(Adhesion(0.01, 0.15).to_attrs()) == \
        Adhesion(0.01, 0.15)
    contact = Contact(Contact.paper().elastomer, Contact.paper().indenter, LAW, Contact.paper().friction)
    assert Contact.from_attrs(contact.to_attrs()) == contact
    assert LAW.works_at_rest == (0.05, 0.15) and LAW.is_adhesive


def test_the_speed_of_a_work_is_that_work_s_speed():
    speeds = np.concatenate([-np.logspace(-12, 0, 25), np.logspace(-12, 0, 25)])
    works = rate_adhesion.work_of_adhesion(LAW, speeds)
    assert np.all(works[speeds < 0] > LAW.dgamma1) and np.all(works[speeds > 0] < LAW.dgamma0)
    np.testing.assert_allclose(rate_adhesion.edge_speed(LAW, works), speeds, rtol=ROUND_TRIP_RTOL)
    for work, speed in zip(works, speeds):
        assert rate_adhesion.edge_speed_scalar(LAW, float(work)) == pytest.approx(speed, rel=ROUND_TRIP_RTOL)


def test_the_edge_rests_in_the_band_and_starts_from_rest_continuously():
    band = np.linspace(LAW.dgamma0, LAW.dgamma1, 11)
    assert np.all(rate_adhesion.edge_speed(LAW, band) == 0.0)
    assert math.isnan(rate_adhesion.work_of_adhesion(LAW, 0.0))
    assert rate_adhesion.edge_speed_scalar(LAW, 0.0) == math.inf
    # the speed vanishes as the excess (Γ/Δγ1 − 1)^(1/n); Δγ1 (1 + excess) rounds the excess by eps/excess
    excess = np.logspace(-6, -1, 6)
    receding = -rate_adhesion.edge_speed(LAW, LAW.dgamma1 * (1 + excess))
    np.testing.assert_allclose(receding, LAW.v_ref * excess ** (1 / LAW.n), rtol=4 * np.finfo(float).eps / 1e-6 / LAW.n)
    assert np.all(np.diff(receding) > 0)


def test_a_fast_reference_speed_is_the_paper_s_law():
    """|Δγ(ȧ) − Δγ1| = Δγ1 (|ȧ|/v_ref)^n → 0 as v_ref grows, at a fixed speed; the derivation checks the limits."""
    for v_ref in (1e-6, 1e-3, 1.0, 1e3):
        law = RateDependentAdhesion(0.05, 0.15, v_ref, 0.6)
        speed = 1e-6
        assert rate_adhesion.work_of_adhesion(law, -speed) - law.dgamma1 == pytest.approx(
            law.dgamma1 * (speed / v_ref) ** law.n, rel=ROUND_TRIP_RTOL)
    assert set(symbolic.RATE_ADHESION_KEYS) <= set(symbolic.relations())


def test_the_flat_punch_detaches_when_the_law_integrated_says():
    law = RateDependentAdhesion(0.05, 0.15, 1e-6, 1.0)
    punch, depth = 1.5e-3, -8e-5
    closed = rate_adhesion.flat_punch_detachment_time(law, punch, depth, E_STAR)

    def lasting(a):  # dt/da = 1/|ȧ| with Γ = E* d² / (2π a)
        return 1.0 / -rate_adhesion.edge_speed_scalar(law, E_STAR * depth**2 / (2 * math.pi * a))
    numeric, _ = quad(lasting, 0.0, punch, epsabs=0.0, epsrel=QUAD_RTOL)
    assert closed == pytest.approx(numeric, rel=10 * QUAD_RTOL)
    with pytest.raises(ValueError, match="depth=.*Kendall"):
        rate_adhesion.flat_punch_detachment_time(law, punch, -1e-6, E_STAR)
    with pytest.raises(ValueError, match="n=0.6"):
        rate_adhesion.flat_punch_detachment_time(LAW, punch, depth, E_STAR)
