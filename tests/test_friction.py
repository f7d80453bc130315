"""The friction laws as data (mdr_events.contact.friction): names, μ, what each law uses, and the attributes a result
carries; bad input named."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import TAU0, FrictionLaw, as_friction_law, friction_attrs


def test_the_default_is_the_papers_law():
    assert FrictionLaw() == TAU0 == as_friction_law(None) == as_friction_law("tau0")
    assert TAU0.uses_tau0 and not TAU0.uses_mu and TAU0.is_default and TAU0.coulomb_mu == 0.0
    assert friction_attrs(TAU0) == {}  # a result of the paper's law is as before


@pytest.mark.parametrize("law, tau0, mu", [("coulomb", False, True), ("tau0+coulomb", True, True)])
def test_laws_with_coulombs_part(law, tau0, mu):
    friction = FrictionLaw(law, mu=np.float32(0.25))
    assert (friction.uses_tau0, friction.uses_mu) == (tau0, mu)
    assert type(friction.mu) is float and friction.coulomb_mu == 0.25
    attrs = friction_attrs(friction)
    assert attrs["friction_law"] == law and attrs["friction_mu"] == 0.25 and "mu = 0.25" in attrs["friction_cap"]
    assert ("friction_note" in attrs) == (not tau0)  # param_tau0 unused only by Coulomb's law alone


@pytest.mark.parametrize("make, exception, words", [
    (lambda: FrictionLaw("amontons", mu=0.3), ValueError, ["FrictionLaw.law='amontons'", "'tau0'", "'coulomb'",
                                                          "'tau0+coulomb'"]),
    (lambda: FrictionLaw("coulomb"), ValueError, ["mu=None", "'coulomb'", ">= 0"]),
    (lambda: FrictionLaw("coulomb", mu=-0.1), ValueError, ["mu=-0.1", ">= 0"]),
    (lambda: FrictionLaw("tau0+coulomb", mu=math.nan), ValueError, ["mu=nan"]),
    (lambda: FrictionLaw("coulomb", mu=math.inf), ValueError, ["mu=inf"]),
    (lambda: FrictionLaw("coulomb", mu=True), TypeError, ["mu=True"]),
    (lambda: FrictionLaw("coulomb", mu="0.3"), TypeError, ["mu='0.3'"]),
    (lambda: FrictionLaw("tau0", mu=0.3), ValueError, ["mu=0.3", "'tau0'", "'coulomb'"]),
    (lambda: as_friction_law("coulomb"), ValueError, ["mu=None"]),
    (lambda: as_friction_law(0.3), TypeError, ["friction=0.3", "FrictionLaw", "'tau0'"]),
])
def test_bad_friction_laws_are_named(make, exception, words):
    with pytest.raises(exception) as caught:
        make()
    message = str(caught.value)
    assert "\n" not in message
    for word in words:
        assert word in message


def test_the_package_exports_the_laws():
    assert me.FrictionLaw is FrictionLaw and set(me.FRICTION_LAWS) == {"tau0", "coulomb", "tau0+coulomb"}
