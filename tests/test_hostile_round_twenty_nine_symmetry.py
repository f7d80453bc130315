"""Hostile round 29, second wave (issue 32, class 2): the symmetries of the MDR beyond the closed forms.

The stress scaling ``(E, τ0, Δγ0, Δγ1) → λ(...)`` leaves depths, radii, times and angles unchanged and multiplies
forces by ``λ`` (EQUATIONS.md (5)–(21)); the length scaling ``(R, d_max, dx, Δγ) → L(...)`` (stresses fixed) multiplies
lengths and times by ``L``, forces by ``L²``. The discrete model holds both to round-off. The continuum integrated
``F_x`` with a fixed absolute tolerance of 1e-14 N: at ``λ = 1e-30`` every force lay below it, the solver accepted
any error, and Coulomb's scenario B at 20° came out 4.2e-4 of its peak off the unscaled run (before
:func:`mdr_events.models.continuum.tolerances.force_atol`).
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mdr_events as me
from mdr_events import FlatPunch, FrictionLaw, Parameters, PowerLaw

#: Round-off of the discrete model under a scaling: each spring's force and slip test rounds a few times per step
#: (64 ulps of 1), and a spring's indentation ``d − g(x_i)`` cancels near the contact's edge, up to 1e3 times in the
#: last samples before the contact ends (measured: 1.3e-15 of each variable's largest magnitude over 192 runs of the
#: stress scaling, 3.1e-13 of the mean pressure at one sample of a length scaling by 1e-3).
DISCRETE_RTOL = 64 * float(np.finfo(float).eps) * 1e3
#: The continuum's integration of ``F_x`` is held to ``rtol`` = 1e-10 per step, and a scaled run takes other steps:
#: measured up to 3.5e-9 of each variable's largest magnitude over a run; 1000 times ``rtol``.
INTEGRATION_RTOL = 1000 * me.Tolerances().rtol
#: The variables in these units scale as forces (N, Pa: ``λ``) and lengths (m, s, m²: ``L``, ``L²``).
FORCE_UNITS = {"N": 1, "Pa": 1}
LENGTH_POWERS = {"N": 2, "m": 1, "m2": 2, "s": 1}

PAPER = Parameters.paper()
NO_ADHESION = dataclasses.replace(PAPER, dgamma0=0.0, dgamma1=0.0)
LAWS = [FrictionLaw("tau0"), FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.3)]
PROFILES = {"paraboloid": None, "power 1.5": PowerLaw(c=3.0, n=1.5), "flat punch": FlatPunch(radius=1e-3)}
DISCRETE = {"method": "discrete", "dx": 2e-5, "n_steps": 600}


def _stresses_scaled(params: Parameters, scale: float) -> Parameters:
    return dataclasses.replace(params, E=params.E * scale, tau0=params.tau0 * scale, dgamma0=params.dgamma0 * scale,
                               dgamma1=params.dgamma1 * scale)


def _lengths_scaled(params: Parameters, scale: float) -> Parameters:
    return dataclasses.replace(params, R=params.R * scale, d_max=params.d_max * scale,
                               dgamma0=params.dgamma0 * scale, dgamma1=params.dgamma1 * scale)


def _simulate(params: Parameters, scenario: str, **options):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return me.simulate(params, scenario, alpha=[20.0, 60.0], **options)


def _assert_scaled(reference, run, factor_of, rtol: float) -> None:
    """Every variable of ``run`` is ``reference``'s times ``factor_of(units)`` within ``rtol`` of its largest
    magnitude (its ``nan`` where they are); the texts equal."""
    for name, variable in reference.variables.items():
        expected, got = variable.values, run[name].values
        if expected.dtype.kind != "f":
            np.testing.assert_array_equal(got, expected, err_msg=name)
            continue
        size = np.nanmax(np.abs(expected), initial=0.0)
        np.testing.assert_allclose(got / factor_of(variable.attrs.get("units")), expected, rtol=0.0,
                                   atol=rtol * size, equal_nan=True, err_msg=name)


stress_scales = st.sampled_from([1e-140, 2.0 ** -333, 3.7e5, 1e148])


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scale=stress_scales, law=st.sampled_from(LAWS), profile=st.sampled_from(sorted(PROFILES)),
       adhesion=st.booleans(), scenario=st.sampled_from(["A", "B"]))
def test_discrete_runs_are_free_of_the_stress_scale(scale, law, profile, adhesion, scenario):
    """The spring array: forces and stresses ``λ`` times, the rest unchanged, to round-off."""
    params, options = (PAPER if adhesion else NO_ADHESION), dict(DISCRETE, friction=law)
    if PROFILES[profile] is not None:
        options["profile"] = PROFILES[profile]
    reference = _simulate(params, scenario, **options)
    run = _simulate(_stresses_scaled(params, scale), scenario, **options)
    _assert_scaled(reference, run, lambda units: scale ** FORCE_UNITS.get(units, 0), DISCRETE_RTOL)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scale=st.sampled_from([1e-3, 2.0 ** 10, 7.3]), law=st.sampled_from(LAWS), adhesion=st.booleans(),
       scenario=st.sampled_from(["A", "B"]))
def test_discrete_runs_are_free_of_the_length_scale(scale, law, adhesion, scenario):
    """``R``, ``d_max``, ``dx`` and the works ``L`` times (stresses fixed): lengths and times ``L``, forces ``L²``."""
    params, options = (PAPER if adhesion else NO_ADHESION), dict(DISCRETE, friction=law)
    reference = _simulate(params, scenario, **options)
    run = _simulate(_lengths_scaled(params, scale), scenario, **dict(options, dx=DISCRETE["dx"] * scale))
    _assert_scaled(reference, run, lambda units: scale ** LENGTH_POWERS.get(units, 0), DISCRETE_RTOL)


@pytest.mark.parametrize("scale", [1e-140, 1e-30])
@pytest.mark.parametrize("law", [FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.3)])
@pytest.mark.parametrize("scenario", ["A", "B"])
def test_continuum_coulomb_runs_are_free_of_small_stress_scales(scale, law, scenario):
    """The case that showed it: Coulomb's part integrated (no adhesion), the stresses ``1e-30`` times. Before,
    ``F_x`` was held to 1e-14 N, above every force of the run: off by 4.2e-4 of the peak (B 20°)."""
    reference = _simulate(NO_ADHESION, scenario, method="continuum", friction=law)
    run = _simulate(_stresses_scaled(NO_ADHESION, scale), scenario, method="continuum", friction=law)
    _assert_scaled(reference, run, lambda units: scale ** FORCE_UNITS.get(units, 0), INTEGRATION_RTOL)


def test_the_papers_force_scale_keeps_the_default_tolerance():
    """The paper's runs keep ``atol`` = 1e-14 N as given (bit-identical), a run of stresses 1e-30 times gets 1e-30
    of its force scale's share."""
    from mdr_events.models.continuum.tolerances import FORCE_ATOL_SHARE, force_atol

    tolerances = me.Tolerances()
    assert force_atol(tolerances, PAPER) == tolerances.atol
    small = _stresses_scaled(PAPER, 1e-30)
    assert force_atol(tolerances, small) == FORCE_ATOL_SHARE * small.G_star * small.d_max ** 2


def _rate_contact(stress: float) -> me.Contact:
    return me.Contact(me.Elastomer(PAPER.E * stress, PAPER.nu), me.Paraboloid(PAPER.R),
                      me.RateDependentAdhesion(PAPER.dgamma0 * stress, PAPER.dgamma1 * stress, v_ref=1e-6, n=0.3),
                      FrictionLaw("tau0", tau0=PAPER.tau0 * stress))


@pytest.mark.parametrize(("stress", "speed"), [(1.0, 1e-3), (1.0, 1e6), (1e148, 1.0), (1e-140, 1.0)])
def test_rate_runs_read_a_plateau_at_its_start_under_every_scaling(stress, speed):
    """The rate law (``v_ref`` 1 µm/s, ``n = 0.3``), A 20°: ``F_x`` is held in stick after the corner, a plateau whose
    samples differ by rounding. Its largest value's time is the plateau's start (the earliest tie, as the paper's law
    reports it) at every scaling: the speeds ``s`` times (``v`` and ``v_ref``: times ``1/s``) or the stresses ``λ``
    times. Before, the scan's rounding-largest sample: 4e-4 of the run later at ``s = 1e-3``."""
    def simulate(stress: float, speed: float):
        contact = dataclasses.replace(_rate_contact(stress), adhesion=dataclasses.replace(
            _rate_contact(stress).adhesion, v_ref=1e-6 * speed))
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            return me.simulate(contact, me.Scenario("A", alpha=[20.0], d_max=PAPER.d_max, v=PAPER.v * speed),
                               method="continuum")

    reference, run = simulate(1.0, 1.0), simulate(stress, speed)
    factors = {"N": stress, "Pa": stress, "m2": 1.0, "m": 1.0, "s": 1.0 / speed}
    _assert_scaled(reference, run, lambda units: factors.get(units, 1.0), INTEGRATION_RTOL)
