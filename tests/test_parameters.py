import math

import numpy as np
import pytest

from mdr_events import Parameters

VALID = dict(E=1e6, nu=0.3, R=0.01, tau0=1e4, dgamma0=0.02, dgamma1=0.05, d_max=1e-4, v=1e-5)


def test_derived_moduli_follow_their_definitions():
    p = Parameters(**VALID)
    G = p.E / (2 * (1 + p.nu))
    assert p.G == pytest.approx(G, rel=1e-15)
    assert p.E_star == pytest.approx(p.E / (1 - p.nu**2), rel=1e-15)
    assert p.G_star == pytest.approx(4 * G / (2 - p.nu), rel=1e-15)


def test_paper_set_values_and_inferred_note():
    p = Parameters.paper()
    assert (p.R, p.d_max, p.tau0, p.dgamma0, p.dgamma1, p.nu) == (0.03, 0.3e-3, 42e3, 0.01, 0.15, 0.5)
    assert p.E_star == pytest.approx(0.432e6, rel=1e-3)
    assert p.G_star == pytest.approx(0.288e6, rel=1e-3)
    assert Parameters.paper(R=0.1).R == 0.1
    assert "inferred, not quoted" in Parameters.paper.__doc__.lower()
    for name in ("E", "nu", "v"):
        assert name in Parameters.INFERRED_FIELDS
    with pytest.raises(ValueError, match="R=0.05"):
        Parameters.paper(R=0.05)


@pytest.mark.parametrize(
    "field, value",
    [("E", 0.0), ("E", -1.0), ("nu", 0.6), ("nu", -1.0), ("R", 0.0), ("tau0", -1.0),
     ("dgamma0", -0.1), ("dgamma1", -0.1), ("d_max", 0.0), ("v", 0.0),
     ("E", math.nan), ("R", math.inf), ("v", -math.inf)],
)
def test_invalid_values_name_field_value_and_range(field, value):
    with pytest.raises(ValueError) as info:
        Parameters(**{**VALID, field: value})
    message = str(info.value)
    assert f"Parameters.{field}=" in message
    assert repr(float(value)) in message
    assert "allowed" in message


def test_wrong_type_is_a_type_error():
    with pytest.raises(TypeError, match="Parameters.E"):
        Parameters(**{**VALID, "E": "1e6"})
    with pytest.raises(TypeError, match="Parameters.nu"):
        Parameters(**{**VALID, "nu": True})


def test_boundary_values_are_allowed():
    Parameters(**{**VALID, "nu": 0.5, "tau0": 0.0, "dgamma0": 0.0, "dgamma1": 0.0})
    p = Parameters(**{**VALID, "E": np.float64(2e6)})
    assert type(p.E) is float


def test_immutable_replace_and_attrs_round_trip():
    p = Parameters(**VALID)
    with pytest.raises(AttributeError):
        p.E = 2.0
    q = p.replace(R=0.02)
    assert q.R == 0.02 and p.R == 0.01
    with pytest.raises(ValueError, match="Parameters.R"):
        p.replace(R=-1.0)
    with pytest.raises(TypeError, match="unknown field"):
        p.replace(radius=1.0)
    assert Parameters.from_attrs(p.to_attrs()) == p
    with pytest.raises(ValueError, match="param_E"):
        Parameters.from_attrs({})
