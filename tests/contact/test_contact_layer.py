"""The layer as a part of the physical model (issue 34): ``Contact.layer``, the half-space by default and stamped
as before; every entry point that does not take a finite layer yet refuses it in one line, naming the field, its
value and what runs the normal problem on a layer."""

from __future__ import annotations

import dataclasses

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
        "jkr_normal_force": lambda: me.jkr_normal_force(1e-4, LAYERED, 0.15),
        "critical_shift": lambda: me.critical_shift(1e-3, LAYERED),
        "the LAMMPS check": lambda: me.dem.lammps_check(LAYERED, "A", 20.0),
        "the LAMMPS check (LAMMPS has no layers)":
            lambda: me.dem.wall_coefficients(LAYERED, me.dem.LammpsModel()),
    }[where]


@pytest.mark.parametrize("where", ["jkr_normal_force", "critical_shift", "the LAMMPS check",
                                   "the LAMMPS check (LAMMPS has no layers)"])
def test_an_entry_point_without_layers_refuses_a_finite_one_in_one_line(where):
    with pytest.raises(ValueError) as caught:
        _run(where)()
    text = str(caught.value)
    assert text.startswith("Contact.layer=Layer(thickness=0.005, base='bonded') is not allowed in ")
    assert f" in {where}" in text and "allowed: the half-space" in text and "layer_normal_curve" in text
    assert "a layer runs in simulate(...) and sweep(...) with either method" in text and "validate and fit" in text
    assert "\n" not in text


#: Coulomb's part with adhesion on a layer: the continuum runs it spring by spring (issues 34 and 26).
COULOMB = dataclasses.replace(LAYERED, friction=me.FrictionLaw("tau0+coulomb", tau0=PAPER.friction.tau0, mu=0.3))


def test_every_entry_point_takes_coulombs_part_with_adhesion_on_a_layer_in_the_continuum():
    """Issues 34 and 26: nothing the discrete model runs on a layer is refused by the continuum any more (Coulomb's part
    with the paper's adhesion, spring by spring: tests/models/test_layer_coulomb.py checks its values): ``validate``,
    ``fit`` and the CLI pass the contact's check before they run (``check_layer_taken``), and ``simulate`` gives a
    finite ``F_x`` (a continuum sweep, which reads the spans, refuses it: tests/analysis/test_sweep_layer.py)."""
    from mdr_events.models.methods import Continuum
    from mdr_events.models.simulate import check_layer_taken

    motion = me.Scenario("A", alpha=[20.0])
    assert check_layer_taken(COULOMB, motion, Continuum()) is COULOMB
    run = me.simulate(COULOMB, motion, "continuum", samples=5).isel(alpha=0)
    force = run["tangential_force"].values[run["contact_radius"].values > 0.0]
    assert np.all(np.isfinite(force)) and np.max(np.abs(force)) > 0.0


def test_a_continuum_sweep_over_the_thickness_runs_each_thickness():
    """The continuum's quantities over ``h``: each run on its own layer (``inf`` the half-space's own run)."""
    swept = me.sweep({"h": [np.inf, 5e-3]}, PAPER, alpha=20.0, quantities=("contact_area_max",),
                     scheduler="serial")  # (the engines are tests/analysis/test_sweep.py's: a local cluster's worker
    # processes cost more than these two runs, ~3.5 s of CPU)
    area = swept["contact_area_max"].values.ravel()
    half = me.simulate(PAPER, me.Scenario("A", alpha=20), "continuum")
    layer = me.simulate(LAYERED, me.Scenario("A", alpha=20), "continuum")
    assert area[0] == float(half["contact_area_max"].values[0]) and area[1] == float(layer["contact_area_max"].values[0])
    assert area[1] > area[0]  # (the layer's profile g = γ x²/R, γ < 1: a larger contact at the same depth, issue 34)


def test_the_check_passes_the_half_space_through():
    assert check_half_space(PAPER, "anything") is PAPER
    ds = me.simulate(PAPER.replace(h=np.inf), me.Scenario("A", alpha=20), "continuum")
    assert ds.attrs == me.simulate(PAPER, me.Scenario("A", alpha=20), "continuum").attrs
