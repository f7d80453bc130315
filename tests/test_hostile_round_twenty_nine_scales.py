"""Hostile round 29 (issue 32, class 2): the closed forms are invariant under the stress scaling across the accepted
range.

The MDR's relations depend on the stresses ``(E, τ0, Δγ0, Δγ1)`` (``ν`` fixed, so ``E*`` and ``G*`` follow ``E``)
only through their ratios: ``Δl = √(2π a Δγ/E*)``, ``ū = π a τ0/(2G*)``, the Coulomb cap ratio ``κ = μ E*/G*``
(``μ`` dimensionless), ``F_N ∝ E*``. Scaling all four by ``λ`` leaves every depth, radius, angle, shift and onset
unchanged and multiplies every force by ``λ`` (EQUATIONS.md (5)–(21)). So over ``log10 λ`` in [-150, 150] each
function either returns the same lengths and angles and ``λ`` times the forces, within round-off, or refuses in one
line naming the scale (:func:`mdr_events.theory.scales.check_representable`). Silently different is a finding: with
``E = 1e154`` Pa ``G*² cot² α`` of :mod:`~mdr_events.theory.combined_onset`'s turn ``ξ*`` overflowed at 20° and 60°
and its excess changed sign (a cone, ``μ = 0.3``, 59°: +1.0e-10 m became −1.4e-8 m).
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from mdr_events import Parameters
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.theory import analytic, combined_onset, flat_punch, mindlin, power_law
from mdr_events.theory.phase import phase_diagram

#: Round-off of a closed form evaluated at scaled stresses: each of its few dozen operations rounds once, ``eps/2``
#: relative, in either evaluation (64 ulps of 1).
CLOSED_FORM_RTOL = 64 * float(np.finfo(float).eps)
#: Round-off of a root (power_law's convex roots to ``ROOT_RTOL``, 4 eps) or of a bisection on the sign of an excess
#: (combined_onset's onset to 2⁻⁶⁰ ``d_max``; a critical angle to 2⁻⁶⁰ 90°): the excess's terms (``d cot α``,
#: ``K a``, ``κ (d − g)``) round to 64 eps each, and where they nearly cancel the sign test flips within that
#: round-off over its slope, the condition of the root: up to 1e4 on the angles drawn (the slowest crossing, the
#: onset near ``d_max`` at a critical angle). 64 eps times 1e4.
ROOT_RTOL = CLOSED_FORM_RTOL * 1e4
#: The range of ``log10 λ`` drawn: beyond it every scale of the paper's set lies outside ``SCALE_MIN``..``SCALE_MAX``.
LOG_SCALE = 150.0
#: The angles (degrees) of the onsets compared: ordinary ones and both sides of the paper's critical angles.
ANGLES = np.array([5.0, 20.0, 45.0, 59.0, 60.0, 80.0])

PAPER = Parameters.paper()
INDENTERS = {"paraboloid": PowerLaw(c=1.0 / (2 * PAPER.R), n=2.0), "cone": PowerLaw(c=1.0, n=1.0),
             "power 1.5": PowerLaw(c=3.0, n=1.5)}


def _scaled(params: Parameters, scale: float) -> Parameters:
    """``params`` with its stresses (``E``, ``τ0``, ``Δγ0``, ``Δγ1``) times ``scale``."""
    return dataclasses.replace(params, E=params.E * scale, tau0=params.tau0 * scale, dgamma0=params.dgamma0 * scale,
                               dgamma1=params.dgamma1 * scale)


def _refused_or(compute, scale: float):
    """``compute(scale)`` with every warning an error, or ``None`` where it refuses in one line naming what is allowed
    (a scale beyond the representable range)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            return compute(scale)
        except ValueError as error:
            message = str(error)
            assert "\n" not in message and ("allowed" in message or "representable" in message), message
            return None


def _assert_invariant(compute, scale: float, rtol: float, force_power: int = 0) -> None:
    """``compute(scale)`` is ``compute(1)`` times ``scale ** force_power`` within ``rtol`` (its ``nan`` and ``inf``
    where they are), or refused in one line."""
    reference = np.asarray(compute(1.0), dtype=float)
    result = _refused_or(compute, scale)
    if result is None:
        return
    result = np.asarray(result, dtype=float) / scale ** force_power
    np.testing.assert_allclose(result, reference, rtol=rtol, atol=0.0, equal_nan=True,
                               err_msg=f"scale {scale!r}")


scales = st.floats(-LOG_SCALE, LOG_SCALE).map(lambda exponent: 10.0 ** exponent)
laws = st.sampled_from([FrictionLaw("tau0"), FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.05),
                        FrictionLaw("tau0+coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=3.0)])
QUICK = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@QUICK
@given(scale=scales, law=laws, indenter=st.sampled_from(sorted(INDENTERS)), adhesion=st.booleans())
def test_slip_onsets_of_every_law_are_scale_free(scale, law, indenter, adhesion):
    """mindlin's onsets of scenarios A and B (both branches) and the critical angles: unchanged by ``λ``."""
    assume(adhesion or law.uses_mu or indenter == "paraboloid")
    profile = INDENTERS[indenter]
    onsets = (mindlin.d_crit_A, mindlin.d_crit_B, mindlin.d_crit_B_indentation)
    for onset in onsets:
        _assert_invariant(lambda s: onset(ANGLES, law, _scaled(PAPER, s), profile, adhesion=adhesion), scale,
                          ROOT_RTOL)
    _assert_invariant(lambda s: mindlin.critical_angle_A(law, _scaled(PAPER, s), profile, adhesion=adhesion), scale,
                      ROOT_RTOL)


@pytest.mark.parametrize("indenter", sorted(INDENTERS))
@pytest.mark.parametrize("mu", [0.05, 0.3, 1.0])
def test_combined_onset_excess_is_scale_free_at_the_largest_moduli(indenter, mu):
    """The case that showed it: ``E = 1e154`` Pa (accepted), ``"tau0+coulomb"`` with adhesion. The excess of scenario
    A's springs over their caps on a grid of depths and angles is the paper's (lengths), not the turn dropped where
    ``G*² cot² α`` overflowed (before: off by up to 150 times, of the other sign, on the cone at 59°)."""
    law, profile = FrictionLaw("tau0+coulomb", mu=mu), INDENTERS[indenter]
    depth = PAPER.d_max * np.linspace(0.01, 1.0, 100)[None, :]
    cot = 1.0 / np.tan(np.radians(np.arange(1.0, 90.0)))[:, None]
    for dgamma0, tau0 in ((0.01, PAPER.tau0), (1.0, PAPER.tau0), (0.01, PAPER.tau0 / 10), (0.01, PAPER.tau0 / 100)):
        params = dataclasses.replace(PAPER, dgamma0=dgamma0, tau0=tau0)
        _assert_invariant(lambda s: combined_onset.onset_excess_A(depth, cot, law, _scaled(params, s), profile),
                          1e154 / PAPER.E, ROOT_RTOL)
        _assert_invariant(lambda s: mindlin.d_crit_A(np.arange(1.0, 90.0), law, _scaled(params, s), profile,
                                                     adhesion=True), 1e154 / PAPER.E, ROOT_RTOL)


@QUICK
@given(scale=scales, law=laws)
def test_tangential_forces_scale_with_the_stresses(scale, law):
    """Full slip's shift unchanged, its force and the virgin curve's ``λ`` times (``μ F_N``, ``τ0 π a²``)."""
    depth, shifts = PAPER.d_max, PAPER.d_max * np.array([1e-3, 0.1, 1.0, 3.0])
    _assert_invariant(lambda s: mindlin.full_slip_shift(depth, law, _scaled(PAPER, s)), scale, CLOSED_FORM_RTOL)
    _assert_invariant(lambda s: mindlin.full_slip_force(depth, law, _scaled(PAPER, s)), scale, CLOSED_FORM_RTOL, 1)
    _assert_invariant(lambda s: mindlin.virgin_force(shifts, depth, law, _scaled(PAPER, s)), scale, ROOT_RTOL, 1)


@QUICK
@given(scale=scales, adhesion=st.booleans(), scenario=st.sampled_from(["A", "B"]))
def test_paper_closed_forms_are_scale_free(scale, adhesion, scenario):
    """(17)–(21) (``analytic.d_crit`` on both branches of B), the critical angles, and the jump-off and pull-off
    (depth, radius unchanged; forces ``λ`` times)."""
    branches = ["pull-off", "indentation"] if scenario == "B" else [None]
    for branch in branches:
        _assert_invariant(lambda s: analytic.d_crit(ANGLES, _scaled(PAPER, s), scenario, adhesion, branch), scale,
                          ROOT_RTOL)
    _assert_invariant(lambda s: analytic.critical_angle(_scaled(PAPER, s), scenario, adhesion), scale, ROOT_RTOL)
    for work in ("dgamma0", "dgamma1"):
        jump = lambda s, work=work: _jump_off_row(power_law.jump_off(
            INDENTERS["paraboloid"], _scaled(PAPER, s), getattr(_scaled(PAPER, s), work)))
        _assert_invariant(lambda s: jump(s)[:2], scale, ROOT_RTOL)
        _assert_invariant(lambda s: jump(s)[2:], scale, ROOT_RTOL, 1)


@settings(max_examples=3, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scale=scales, scenario=st.sampled_from(["A", "B"]), law=st.sampled_from([None, "tau0+coulomb"]))
def test_phase_diagrams_are_scale_free(scale, scenario, law):
    """Fig. 9's phase diagrams (the paper's law on the paraboloid; both parts, ``μ = 0.3``, on the cone): every
    variable a depth or an angle, unchanged."""
    friction, profile = (None, None) if law is None else (FrictionLaw(law, mu=0.3), INDENTERS["cone"])

    def variables(s):
        diagram = phase_diagram(_scaled(PAPER, s), ANGLES, scenario, profile, friction)
        return np.concatenate([np.ravel(diagram[name].values) for name in sorted(diagram.data_vars)])

    _assert_invariant(variables, scale, ROOT_RTOL)


def _jump_off_row(jump: dict[str, float]) -> list[float]:
    return [jump["contact_radius"], jump["depth"], jump["normal_force"]]


@QUICK
@given(scale=scales, indenter=st.sampled_from(sorted(INDENTERS)), work=st.sampled_from([0.0, 0.01, 0.15]))
def test_power_law_branches_are_scale_free(scale, indenter, work):
    """The branch's radius at a depth and its jump-in radius unchanged, its normal force and pull-off ``λ`` times."""
    profile, depths = INDENTERS[indenter], PAPER.d_max * np.array([0.01, 0.5, 1.0])
    _assert_invariant(lambda s: power_law.contact_radius(depths, profile, _scaled(PAPER, s), work * s), scale,
                      ROOT_RTOL)
    radius = np.asarray(power_law.contact_radius(depths, profile, PAPER, work), dtype=float)
    _assert_invariant(lambda s: power_law.normal_force(depths, radius, profile, _scaled(PAPER, s)), scale,
                      CLOSED_FORM_RTOL, 1)
    assume(work > 0)
    _assert_invariant(lambda s: power_law.jump_in_radius(profile, _scaled(PAPER, s), work * s), scale, ROOT_RTOL)
    _assert_invariant(lambda s: power_law.pull_off_force(profile, _scaled(PAPER, s), work * s), scale, ROOT_RTOL, 1)


@QUICK
@given(scale=scales, adhesion=st.booleans())
def test_flat_punch_is_scale_free(scale, adhesion):
    """The flat punch's onset of A and critical angle unchanged, its normal force and pull-off ``λ`` times."""
    punch = FlatPunch(radius=1e-3)
    _assert_invariant(lambda s: flat_punch.d_crit_A(ANGLES, punch, _scaled(PAPER, s), adhesion), scale, ROOT_RTOL)
    _assert_invariant(lambda s: flat_punch.critical_angle_A(punch, _scaled(PAPER, s), adhesion), scale, ROOT_RTOL)
    _assert_invariant(lambda s: flat_punch.normal_force(PAPER.d_max, punch.radius, punch, _scaled(PAPER, s)), scale,
                      CLOSED_FORM_RTOL, 1)
    _assert_invariant(lambda s: flat_punch.pull_off_force(punch, _scaled(PAPER, s), PAPER.dgamma1 * s), scale,
                      ROOT_RTOL, 1)


def test_combined_onset_at_the_largest_moduli_is_the_papers():
    """The onset itself was wrong, not only the excess: the paraboloid, ``τ0`` = 4.2 kPa, ``μ = 1``, ``E = 1e154`` Pa
    with the paper's ratios slid at 28° at 4.886e-5 m, not 4.786e-5 m (2 % deeper: the turn's springs dropped)."""
    law, params = FrictionLaw("tau0+coulomb", mu=1.0), dataclasses.replace(PAPER, tau0=PAPER.tau0 / 10)
    _assert_invariant(lambda s: mindlin.d_crit_A(np.array([27.0, 28.0, 29.0, 30.0]), law, _scaled(params, s),
                                                 INDENTERS["paraboloid"], adhesion=True), 1e154 / PAPER.E, ROOT_RTOL)


def test_largest_moduli_are_near_the_bound():
    """The regression case's moduli are accepted and ``G*² cot² 20°`` of them overflows (what the test above needs)."""
    params = _scaled(PAPER, 1e154 / PAPER.E)
    assert math.isinf(params.G_star ** 2 * (1.0 / math.tan(math.radians(20.0))) ** 2)
    assert np.isfinite(mindlin.d_crit_A(20.0, FrictionLaw("tau0+coulomb", mu=0.3), params, INDENTERS["cone"],
                                        adhesion=True))


#: The continuum's event times are roots to a few ulps (measured: 1.2e-15 relative under the scaling); a force or
#: stress then moves by its slope times that, up to 1e5 times its largest magnitude's round-off near a slip onset
#: (measured: 2.7e-11 of the largest tangential force). Compared against each variable's largest magnitude, as its
#: near-zero values (a force through 0) carry the round-off of the largest.
SIMULATION_RTOL = CLOSED_FORM_RTOL * 1e5
#: The stress scalings of the simulated runs: near both ends of the accepted range and a power of two.
SIMULATED_SCALES = [1e-140, 2.0 ** -333, 1e148]


@pytest.mark.slow
@pytest.mark.parametrize("scenario", ["A", "B"])
def test_continuum_runs_are_scale_free(scenario):
    """``simulate(..., method="continuum")``: every variable in N or Pa ``λ`` times, every other one unchanged (the
    event kinds equal), at each of :data:`SIMULATED_SCALES`."""
    import mdr_events as me

    reference = me.simulate(PAPER, scenario, alpha=[20.0], method="continuum")
    for scale in SIMULATED_SCALES:
        run = _refused_or(lambda s: me.simulate(_scaled(PAPER, s), scenario, alpha=[20.0], method="continuum"), scale)
        assert run is not None, scale  # (the paper's set scaled so is accepted: every scale within the range)
        for name, variable in reference.variables.items():
            expected, got = variable.values, run[name].values
            if expected.dtype.kind in "USO":
                np.testing.assert_array_equal(got, expected, err_msg=name)
                continue
            factor = scale if variable.attrs.get("units") in ("N", "Pa") else 1.0
            size = np.nanmax(np.abs(expected), initial=0.0)
            np.testing.assert_allclose(got / factor, expected, rtol=0.0, atol=SIMULATION_RTOL * size, equal_nan=True,
                                       err_msg=f"{name} at scale {scale!r}")
