"""The nineteenth hostile round (issue 32): each class of what failed, with the cases that showed it.

The round's cases (the rate-dependent law on the command line and in the API, the phase diagram at speeds, the joint
fit, validate under the rate law, Coulomb's law with adhesion on a half-space and a layer, layers, the tabulated
indenter and the readers) are listed with their outcomes in the issue's closing note; what failed is below.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import one_line_naming
from mdr_events.analysis.rate_fit import RateMeasurement, fit_rate_adhesion
from mdr_events.models.continuum import solve_edge

PAPER = me.Parameters.paper()
LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)
START = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1.2e-6, 0.65)
WAYPOINTS = np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -200e-6)])


def _curve(speed: float, noise: float | None, samples: int = 25) -> RateMeasurement:
    """The law's normal force along the vertical path at ``speed`` (no noise added), with ``noise`` declared."""
    path = me.Path(WAYPOINTS, speed=speed)
    times = np.linspace(path.first_contact_time(), path.duration, samples)
    return RateMeasurement(path, times, solve_edge(PAPER, path, LAW).normal_force(times, path), noise)


# --- N1: the joint fit's weights 1/σ entered least_squares at their own scale: a noise of 1e-100 N ran SciPy's trust
# region out of the double range (five RuntimeWarnings, a fit stopped where it started, exit 0); 1e-300 N ended in
# SciPy's "array must not contain infs or NaNs"; 1e-320 N blamed the start's edge. The optimum of Σ r² does not move
# with a common factor of the weights: the fit now weighs by their ratios and scales the covariance back ---------------

#: A common factor of the noises far beyond what SciPy's products of the weighted residuals took (1e-100 N failed).
TINY = 1e-120


def test_the_joint_fit_does_not_depend_on_the_noises_scale():
    """The same curves with their noises 1e-120 times smaller: the same estimates bit for bit (the same weights'
    ratios, the same steps), standard errors 1e-120 times smaller (cov = σ² (JᵀJ)⁻¹) and no warning."""
    sigma = 1e-6
    found = {}
    for factor in (1.0, TINY):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            found[factor] = fit_rate_adhesion([_curve(speed, sigma * factor) for speed in (1e-6, 4e-6)], PAPER, START)
    np.testing.assert_array_equal(found[TINY]["estimate"].values, found[1.0]["estimate"].values)
    np.testing.assert_allclose(found[TINY]["standard_error"].values, TINY * found[1.0]["standard_error"].values,
                               rtol=1e-12)  # (rounding of the rescaled covariance: a few ulps)
    np.testing.assert_allclose(found[1.0]["estimate"].values, [LAW.v_ref, LAW.n], rtol=1e-6)


@pytest.mark.parametrize("noise", [1e-300, 5e-324])
def test_a_noise_whose_weight_overflows_is_named(noise):
    """Its weight 1/σ is beyond the double range: refused naming the noise (1e-320 blamed the start's edge)."""
    message = one_line_naming(lambda: fit_rate_adhesion([_curve(1e-6, noise)], PAPER, START), "measurements[0].noise")
    assert "1.5e-154" in message, message
