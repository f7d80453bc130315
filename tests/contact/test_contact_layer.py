"""The layer as a part of the physical model (issue 34): ``Contact.layer``, the half-space by default and stamped
as before; every entry point that does not take a finite layer yet refuses it in one line, naming the field, its
value and what runs the normal problem on a layer."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.layer import HALF_SPACE, Layer, LayerBase
from mdr_events.contact.model import check_half_space

PAPER = me.Contact.paper()
LAYERED = PAPER.replace(h=5e-3)


def test_the_half_space_is_the_default_and_stamps_what_it_stamped_before():
    assert PAPER.layer is HALF_SPACE and me.Contact(PAPER.elastomer, PAPER.indenter).layer == HALF_SPACE
    assert not any(key.startswith("param_layer") for key in PAPER.to_attrs())
    assert "Layer" not in repr(PAPER)
    assert me.Contact.from_attrs(PAPER.to_attrs()) == PAPER  # (a result without layer attributes: the half-space)


def test_the_layer_is_read_and_changed_by_name_and_read_back_from_a_result():
    assert LAYERED.layer == Layer(5e-3, LayerBase.BONDED) and LAYERED.value("h") == 5e-3
    assert LAYERED.value("layer.thickness") == 5e-3 and LAYERED.unit("h") == "m"
    assert LAYERED.value("layer.base") is LayerBase.BONDED
    sliding = LAYERED.replace(**{"layer.base": "frictionless"})
    assert sliding.layer == Layer(5e-3, "frictionless") and "layer.thickness" in sliding.names()
    assert "Layer(thickness=0.005, base='frictionless')" in repr(sliding)
    attrs = sliding.to_attrs()
    assert attrs["param_layer_thickness"] == 5e-3 and attrs["param_layer_base"] == "frictionless"
    assert me.Contact.from_attrs(attrs) == sliding


@pytest.mark.parametrize("change, words", [({"h": 0.0}, "Layer.thickness=0.0"),
                                           ({"layer.base": "glued"}, "Layer.base='glued'")])
def test_a_bad_layer_value_is_refused_in_one_line(change, words):
    with pytest.raises(ValueError) as caught:
        PAPER.replace(**change)
    assert words in str(caught.value) and "allowed" in str(caught.value) and "\n" not in str(caught.value)


def _run(where):
    """The call of each entry point with the layered contact."""
    return {
        "simulate(method='continuum')": lambda: me.simulate(LAYERED, me.Scenario("A", alpha=20), "continuum"),
        "validate": lambda: me.validate(None, LAYERED, "A", 20.0),
        "fit": lambda: me.fit(None, LAYERED, "A", 20.0, free=["E"]),
        "sweep": lambda: me.sweep({"alpha": [10.0, 20.0]}, LAYERED),
        "pull_off_force": lambda: me.pull_off_force(LAYERED, 0.15),
        "jump_off": lambda: me.jump_off(LAYERED, 0.15),
        "the LAMMPS check": lambda: me.dem.lammps_check(LAYERED, "A", 20.0),
        "the LAMMPS check (LAMMPS has no layers)":
            lambda: me.dem.wall_coefficients(LAYERED, me.dem.LammpsModel()),
    }[where]


@pytest.mark.parametrize("where", ["simulate(method='continuum')", "validate", "fit",
                                   "sweep", "pull_off_force", "jump_off", "the LAMMPS check",
                                   "the LAMMPS check (LAMMPS has no layers)"])
def test_an_entry_point_without_layers_refuses_a_finite_one_in_one_line(where):
    with pytest.raises(ValueError) as caught:
        _run(where)()
    text = str(caught.value)
    assert text.startswith("Contact.layer=Layer(thickness=0.005, base='bonded') is not allowed in ")
    assert f" in {where}" in text and "allowed: the half-space" in text and "layer_normal_curve" in text
    assert "a layer runs in simulate(..., method='discrete')" in text
    assert "\n" not in text


def test_a_continuum_sweep_over_the_thickness_is_refused_naming_what_runs_it():
    """The continuum's quantities on a layer: refused for the grid's first finite thickness, naming the discrete
    method and the closed-form quantities (tests/analysis/test_sweep_layer.py: what runs)."""
    with pytest.raises(ValueError) as caught:
        me.sweep({"h": [np.inf, 1e-3, 5e-3]}, PAPER, alpha=20.0)
    text = str(caught.value)
    assert text.startswith("grid: Contact.layer=Layer(thickness=0.001, base='bonded') is not allowed in "
                           "sweep(method='continuum')") and "\n" not in text
    assert "sweep(..., method='discrete')" in text and "quantities=('critical_angle_A', 'critical_angle_B')" in text


def test_the_check_passes_the_half_space_through():
    assert check_half_space(PAPER, "anything") is PAPER
    ds = me.simulate(PAPER.replace(h=np.inf), me.Scenario("A", alpha=20), "continuum")
    assert ds.attrs == me.simulate(PAPER, me.Scenario("A", alpha=20), "continuum").attrs
