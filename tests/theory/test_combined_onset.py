"""The combined law's critical angle of scenario A (theory.combined_onset.critical_angle_A) is the edge of the angles
where its onset depth (d_crit_A) is found by d_max: the angle reads the grid of depths alone, the angle-free parts
computed once, and must answer what d_crit_A answers on either side of it."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.theory import combined_onset

#: How far either side of the critical angle d_crit_A is read (degrees): far above the bisection's width
#: (90° 2⁻⁶⁰ ≈ 8e-17°) and the rounding of ``cot α`` there (a few ulp of ~1: ~1e-15° at most), far below any change
#: of the grid's answer a wrong grid or ring would make (the parts shift the excess by a share of d_max)
ANGLE_STEP = 1e-9

#: (Δγ0, μ, indenter): the paper's paraboloid, a power law n = 1.5 with μ = 0.05, a cone, and no adhesion (the ring
#: is the tip)
CASES = [(0.01, 0.3, None), (0.01, 0.05, PowerLaw(2e3, 1.5)), (0.1, 0.3, PowerLaw.cone(0.05)),
         (0.0, 0.3, PowerLaw(5.0, 1.2))]


@pytest.mark.parametrize("dgamma0, mu, profile", CASES, ids=["paraboloid", "n1.5", "cone", "no-adhesion"])
def test_the_critical_angle_is_the_edge_of_the_found_onsets(dgamma0, mu, profile):
    """d_crit_A finds an onset just below the critical angle and none just above it (it is an angle inside (0, 90))."""
    params = me.Parameters.paper().replace(dgamma0=dgamma0)
    profile = profile if profile is not None else PowerLaw(1.0 / (2.0 * params.R), 2.0)
    friction = FrictionLaw("tau0+coulomb", mu=mu)
    critical = combined_onset.critical_angle_A(friction, params, profile)
    assert 0.0 < critical < 90.0
    below, above = combined_onset.d_crit_A(np.array([critical - ANGLE_STEP, critical + ANGLE_STEP]), friction,
                                           params, profile)
    assert 0.0 <= below <= params.d_max and np.isnan(above), (critical, below, above)
