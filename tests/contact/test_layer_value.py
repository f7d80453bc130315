"""The layer as a value (issue 34): validation in one line, attributes and their reading back."""

import math

import pytest

from mdr_events.contact.layer import HALF_SPACE, Layer, LayerBase


@pytest.mark.parametrize("thickness", [0.0, -1e-3, math.nan, -math.inf])
def test_a_thickness_not_positive_is_refused_naming_the_field(thickness):
    with pytest.raises(ValueError) as caught:
        Layer(thickness)
    text = str(caught.value)
    assert text.startswith("Layer.thickness=") and "allowed: a number > 0 (m), finite or inf" in text
    assert "\n" not in text


@pytest.mark.parametrize("thickness", ["5e-3", True, 1j])
def test_a_thickness_not_a_real_number_is_refused(thickness):
    with pytest.raises(TypeError, match="Layer.thickness"):
        Layer(thickness)


@pytest.mark.parametrize("base", ["glued", "BONDED", 1, None])
def test_a_base_not_in_the_list_is_refused_naming_the_allowed_ones(base):
    with pytest.raises(ValueError) as caught:
        Layer(1e-3, base)
    text = str(caught.value)
    assert text.startswith("Layer.base=") and "'bonded'" in text and "'frictionless'" in text and "\n" not in text


def test_the_half_space_and_a_layer_describe_themselves_and_read_back():
    assert Layer() == HALF_SPACE and HALF_SPACE.is_half_space and HALF_SPACE.describe() == "half-space"
    layer = Layer(5e-3, "frictionless")
    assert layer.base is LayerBase.FRICTIONLESS and not layer.is_half_space
    assert layer.describe() == "layer h = 0.005 m, frictionless base"
    assert layer.relative_radius(2.5e-3) == 0.5 and HALF_SPACE.relative_radius(1.0) == 0.0
    for value in (layer, HALF_SPACE):
        assert Layer.from_attrs(value.to_attrs()) == value
    assert Layer.from_attrs({"param_E": 1.0}) == HALF_SPACE
