"""The thirtieth hostile round (issue 32), numbers across the model space, second wave: the continuum's failures the
round's first wave found and left open (a flat punch's first touch under Coulomb's law, a slip zone's event firing
again at a corner, a layer's springs whose kinks were never all found), each class with the cases that showed it."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import mdr_events as me
from mdr_events.theory.mindlin.caps import coulomb_cap_ratio

PAPER = me.Parameters.paper()
#: How far the first-touch sample's sliding fraction may lie from its limit (a share of the springs): the fraction
#: is constant along the first segment (every spring's cap and level of degree one in the time), so the run's samples
#: after the touch give it to the rounding of the springs' fronts.
LIMIT_ATOL = 1e-12


# -- O1: a flat punch's first touch under Coulomb's law: cap and level both 0, the sliding fraction 0/0 -----------------

@pytest.mark.parametrize("layer", [me.Layer(), me.Layer(5e-3, "bonded")], ids=["half-space", "5mm"])
@pytest.mark.parametrize("friction", [me.FrictionLaw("coulomb", mu=0.3),
                                      me.FrictionLaw("tau0+coulomb", mu=0.3, tau0=PAPER.tau0)],
                         ids=["coulomb", "tau0+coulomb"])
@pytest.mark.parametrize("scenario, alpha", [("A", 60.0), ("A", 89.0), ("B", 30.0)])
@pytest.mark.parametrize("adhesion", [me.Adhesion(0.0, 0.0), me.Adhesion(0.01, 0.15)], ids=["none", "paper"])
def test_a_flat_punch_s_first_touch_slides_as_the_contact_starts(layer, friction, scenario, alpha, adhesion):
    contact = me.Contact(me.Elastomer(PAPER.E, 0.5), me.FlatPunch(1e-3), adhesion, friction, layer)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = me.simulate(contact, me.Scenario(scenario, alpha, 3e-4, 1e-6), method="continuum")
    sliding, depth = ds["sliding_fraction"].values[0], ds["indentation_depth"].values[0]
    assert depth[0] == 0.0 and ds["contact_area"].values[0, 0] > 0.0
    assert np.isfinite(sliding[0])
    assert abs(sliding[0] - sliding[1]) <= LIMIT_ATOL  # (the limit: sample 1 lies on the first segment)
    if friction.uses_tau0:
        assert sliding[0] == 0.0  # (every cap at least tau0's, every level 0)
    elif layer.is_half_space:  # (every spring slides iff |dx/dd| >= kappa on the first segment)
        first = 90.0 if scenario == "B" else alpha
        assert sliding[0] == float(1.0 / math.tan(math.radians(first)) >= coulomb_cap_ratio(friction, PAPER))


# -- R1: at a corner the other cap's zone, reached only at the edge beside a full slip, was met again for ever ---------

#: How far F_x / F_N may lie from mu in full slip (relative): F_x is set to mu F_N (10) where every spring reaches
#: the cap, then carried by the span's interpolant, some ulps a step.
FULL_SLIP_RTOL = 1e-12


@pytest.mark.parametrize("n", [9.0, 12.0])
@pytest.mark.parametrize("alpha", [10.0, 30.0, 45.0])
@pytest.mark.parametrize("mu, nu", [(0.3, 0.5), (1.0, 0.3), (0.1, -0.9)])
def test_a_corner_in_full_slip_under_coulomb_s_law_is_passed(n, alpha, mu, nu):
    contact = me.Contact(me.Elastomer(PAPER.E, nu), me.PowerLaw(3e-4 / 1e-3 ** n, n), me.Adhesion(0.0, 0.0),
                         me.FrictionLaw("coulomb", mu=mu))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = me.simulate(contact, me.Scenario("A", alpha, 3e-4, 1e-6), method="continuum")
    kinds = [str(kind) for kind in ds["event_kind"].values[0]]
    assert kinds.index("corner") < kinds.index("contact_ends")
    corner = 3e-4 / (1e-6 * math.sin(math.radians(alpha)))
    k = int(np.searchsorted(ds["time"].values, corner)) - 1
    ratio = ds["tangential_force"].values[0, k:k + 2] / ds["normal_force"].values[0, k:k + 2]
    if "full_slip" in kinds[:kinds.index("corner")]:  # (every spring at the cap either side of the corner)
        np.testing.assert_allclose(ratio, mu, rtol=FULL_SLIP_RTOL)
    else:  # (mu = 1 at 45 deg: the slip zone stops short of the centre, |F_x| below mu F_N)
        assert np.all(np.abs(ratio) < mu)
    alive = np.isfinite(ds["indentation_depth"].values)
    for name in ("normal_force", "tangential_force", "contact_area"):
        assert np.all(np.isfinite(ds[name].values[alive])), name


# -- R2: with dgamma0 = 0 a spring attaches at its crossing of d = g: a crossing a rounding later relabelled it --------

@pytest.mark.parametrize("mu", [0.3, 1e3])
def test_springs_attached_uncompressed_keep_their_provenance(mu):
    contact = me.Contact(me.Elastomer(PAPER.E, 0.5), me.PowerLaw(3e-4 / 1e-36, 12.0), me.Adhesion(0.0, 0.15),
                         me.FrictionLaw("coulomb", mu=mu), me.Layer(5e-3, "bonded"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = me.simulate(contact, me.Scenario("A", 90.0, 1e-6, 1e-6), method="continuum", samples=101)
    kinds = [str(kind) for kind in ds["event_kind"].values[0]]
    assert kinds[-1] == "pull_off"
    alive = np.isfinite(ds["indentation_depth"].values)
    assert np.all(np.isfinite(ds["normal_force"].values[alive]))
    assert np.all(ds["tangential_force"].values[alive] == 0.0)  # (a vertical path: every anchor at x = 0)
