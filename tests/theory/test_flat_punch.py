"""The flat punch's closed forms as a kind of their own (mdr_events.theory.flat_punch): power_law's and mindlin's
functions of either indenter reach them through kinds.theory_of, not by testing the type."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.parameters import Parameters
from mdr_events.theory import flat_punch, mindlin, power_law
from mdr_events.theory.kinds import theory_of

PAPER = Parameters.paper()
PUNCH = FlatPunch(1.5e-3)
ANGLES = np.linspace(0.0, 90.0, 19)
#: The onset's closed form written out here and the module's differ in the order of their few products and sums:
#: a few ulp apart (4 operations, each within half an ulp).
CLOSED_FORM_RTOL = 8 * float(np.finfo(float).eps)

#: Each power_law function of either indenter with the flat punch's arguments (after the profile's).
CALLS = [
    ("normal_force", lambda f, adhesion, profile=PUNCH: f(np.array([-1e-6, 0.0, 2e-5]), None, profile, PAPER)),
    ("jump_off", lambda f, adhesion, profile=PUNCH: f(profile, PAPER, PAPER.dgamma1 if adhesion else 0.0)),
    ("pull_off_force", lambda f, adhesion, profile=PUNCH: f(profile, PAPER, PAPER.dgamma1 if adhesion else 0.0)),
    ("d_crit_A", lambda f, adhesion, profile=PUNCH: f(ANGLES, profile, PAPER, adhesion)),
    ("d_crit_B", lambda f, adhesion, profile=PUNCH: f(ANGLES, profile, PAPER, adhesion)),
    ("d_crit_B_indentation", lambda f, adhesion, profile=PUNCH: f(ANGLES, profile, PAPER, adhesion)),
    ("critical_angle_A", lambda f, adhesion, profile=PUNCH: f(profile, PAPER, adhesion)),
    ("critical_angle_B", lambda f, adhesion, profile=PUNCH: f(profile, PAPER, adhesion)),
    ("critical_angle_B_indentation", lambda f, adhesion, profile=PUNCH: f(profile, PAPER, adhesion, 3.0 * PAPER.d_max)),
]


def _same(first, second) -> bool:
    """Equal bit for bit, ``nan`` and ``inf`` in the same places (dicts entry by entry)."""
    if isinstance(first, dict):
        return first.keys() == second.keys() and all(_same(first[key], second[key]) for key in first)
    return np.asarray(first).tobytes() == np.asarray(second).tobytes() and np.shape(first) == np.shape(second)


@pytest.mark.parametrize("adhesion", [False, True])
@pytest.mark.parametrize("name, call", CALLS, ids=[name for name, _ in CALLS])
def test_power_law_hands_the_flat_punch_to_its_own_closed_forms(name, call, adhesion):
    assert _same(call(getattr(power_law, name), adhesion), call(getattr(flat_punch, name), adhesion))


def test_the_kinds_file_the_flat_punchs_forms():
    assert theory_of(PUNCH).closed_forms is flat_punch.CLOSED_FORMS
    assert theory_of(PUNCH).friction_forms is flat_punch.FRICTION_FORMS
    assert theory_of(PowerLaw(2e3, 1.5)).closed_forms is power_law.CLOSED_FORMS
    assert theory_of(PowerLaw(2e3, 1.5)).friction_forms is None  # mindlin's own serve a curved indenter
    assert theory_of(None).closed_forms is None  # the paraboloid's are analytic's


@pytest.mark.parametrize("name", ["normal_force", "jump_off", "d_crit_A", "critical_angle_B", "tangential_force"])
def test_the_flat_punchs_forms_refuse_another_kind(name):
    arguments = {"normal_force": (1e-5, None, PowerLaw(2e3, 1.5), PAPER), "jump_off": (PowerLaw(2e3, 1.5), PAPER, 0.1),
                 "d_crit_A": (30.0, PowerLaw(2e3, 1.5), PAPER), "critical_angle_B": (PowerLaw(2e3, 1.5), PAPER),
                 "tangential_force": ([0.0, 1e-6], [1e-5, 1e-5], "tau0", PAPER, PowerLaw(2e3, 1.5))}[name]
    with pytest.raises(TypeError, match=r"profile=PowerLaw\(c=2000.0, n=1.5\) is not allowed for .*allowed: a FlatPunch"):
        getattr(flat_punch, name)(*arguments)


@pytest.mark.parametrize("mu", [0.05, 0.3])
def test_mindlin_b_onsets_of_the_punch_are_its_caps_closed_forms(mu):
    """Every spring's cap ``K a + κ d`` against the shift ``(d_max − d) cot α`` out, ``(d − d_max) cot α`` further in:
    ``d = (d_max cot α − K a)/(cot α + κ)`` (-inf below the surface) and ``(K a + d_max cot α)/(cot α − κ)`` (+inf
    where ``cot α <= κ``), written out from ``K = π τ0/(2 G*)``, ``κ = μ E*/G*``."""
    law = FrictionLaw("tau0+coulomb", mu=mu)
    angles = np.linspace(5.0, 85.0, 17)
    cot = 1.0 / np.tan(np.radians(angles))
    K, kappa = math.pi * PAPER.tau0 / (2.0 * PAPER.G_star), mu * PAPER.E_star / PAPER.G_star
    a, d_max = PUNCH.radius, PAPER.d_max
    out = (d_max * cot - K * a) / (cot + kappa)
    further_in = np.where(cot > kappa, (K * a + d_max * cot) / np.where(cot > kappa, cot - kappa, 1.0), np.inf)
    np.testing.assert_allclose(mindlin.d_crit_B(angles, law, PAPER, PUNCH), np.where(out < 0.0, -np.inf, out),
                               rtol=CLOSED_FORM_RTOL, atol=0.0)
    np.testing.assert_allclose(mindlin.d_crit_B_indentation(angles, law, PAPER, PUNCH), further_in,
                               rtol=CLOSED_FORM_RTOL, atol=0.0)
    assert np.any(np.isfinite(further_in)) and np.any(out > 0.0)  # (both closed forms are exercised)


class _MyPunch(FlatPunch):
    """A user's subclass of the flat punch: of the flat punch's kind."""


class _MyPowerLaw(PowerLaw):
    """A user's subclass of the power law: of the power law's kind."""


#: Each base indenter and a subclass of it with the same fields.
SUBCLASSES = [(PUNCH, _MyPunch(PUNCH.radius)), (PowerLaw(2e3, 1.5), _MyPowerLaw(2e3, 1.5))]
#: mindlin's functions of an indenter, called with the subclass in the base's place.
MINDLIN_CALLS = [
    ("d_crit_A", lambda f, law, profile: f(ANGLES, law, PAPER, profile, True)),
    ("d_crit_B", lambda f, law, profile: f(ANGLES, law, PAPER, profile, True)),
    ("d_crit_B_indentation", lambda f, law, profile: f(ANGLES, law, PAPER, profile, True)),
    ("critical_angle_A", lambda f, law, profile: f(law, PAPER, profile, True)),
    ("critical_angle_B", lambda f, law, profile: f(law, PAPER, profile, True)),
    ("virgin_force", lambda f, law, profile: f(np.linspace(-1e-5, 1e-5, 5), 2e-5, law, PAPER, profile)),
    ("tangential_force", lambda f, law, profile: f(np.array([0.0, 1e-6, -2e-6]), 2e-5, law, PAPER, profile)),
]


@pytest.mark.parametrize("base, subclass", SUBCLASSES, ids=["FlatPunch", "PowerLaw"])
def test_a_subclass_is_of_its_bases_kind(base, subclass):
    """kinds files a subclass as its base, so power_law's and mindlin's functions give the base's numbers bit for bit
    (an exact type lookup sent a FlatPunch subclass to the power law's forms: AttributeError 'n')."""
    assert theory_of(subclass) is theory_of(base)
    for name, call in CALLS[1:]:  # (normal_force's radius differs by kind: the first row's None is the punch's)
        for adhesion in (False, True):
            assert _same(call(getattr(power_law, name), adhesion, subclass),
                         call(getattr(power_law, name), adhesion, base)), name
    for law in (FrictionLaw("tau0"), FrictionLaw("coulomb", mu=0.3), FrictionLaw("tau0+coulomb", mu=0.3)):
        for name, call in MINDLIN_CALLS:
            assert _same(call(getattr(mindlin, name), law, subclass),
                         call(getattr(mindlin, name), law, base)), (name, law)
