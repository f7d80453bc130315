"""The physical model as one value (issue 35): each part validated, a short repr, round trips through a result's
attributes and through Parameters, values changed by dotted or short name."""

from __future__ import annotations

import math
import re

import pytest

import mdr_events as me
from mdr_events.contact import NO_ADHESION, SHORT_NAMES, indenter_from_attrs

PAPER = me.Parameters.paper()
INDENTERS = [me.Paraboloid(0.03), me.PowerLaw.cone(0.1), me.PowerLaw(40.0, 4.0), me.FlatPunch(2e-3),
             me.TabulatedProfile((0.0, 1e-3, 2e-3, 3e-3), (0.0, 1e-5, 4e-5, 9e-5))]
LAWS = [me.FrictionLaw("tau0", tau0=42e3), me.FrictionLaw("coulomb", mu=0.3),
        me.FrictionLaw("tau0+coulomb", mu=0.3, tau0=42e3)]


def test_the_elastomer_s_moduli_are_those_of_parameters_bit_for_bit():
    elastomer = me.Elastomer(PAPER.E, PAPER.nu)
    assert (elastomer.E_star, elastomer.G_star, elastomer.G) == (PAPER.E_star, PAPER.G_star, PAPER.G)


@pytest.mark.parametrize("make, words", [
    (lambda: me.Elastomer(0.0, 0.5), "Elastomer.E=0.0 is not allowed; allowed: a finite number > 0 (Pa)"),
    (lambda: me.Elastomer(1e6, 0.6), "Elastomer.nu=0.6 is not allowed; allowed: a finite number in (-1, 0.5]"),
    (lambda: me.Elastomer(math.inf, 0.5), "Elastomer.E=inf"),
    (lambda: me.Adhesion(-0.1, 0.0), "Adhesion.dgamma0=-0.1 is not allowed; allowed: a finite number >= 0 (J m-2)"),
    (lambda: me.Paraboloid(-1.0), "Paraboloid.R=-1.0 is not allowed; allowed: a finite number > 0 (m)"),
    (lambda: me.FrictionLaw("coulomb", mu=0.3, tau0=1.0), "tau0=1.0 is not allowed with the friction law 'coulomb'"),
    (lambda: me.FrictionLaw("tau0", tau0=-1.0), "tau0=-1.0 is not allowed; allowed: a finite number >= 0 (Pa"),
    (lambda: me.Contact(me.Elastomer(1e6, 0.5), me.Paraboloid(0.03), friction=me.FrictionLaw("tau0")),
     "the law 'tau0' uses tau0; allowed: a law with its values"),
    (lambda: me.Contact(PAPER, me.Paraboloid(0.03)), "Contact.elastomer=Parameters("),
    (lambda: me.Contact(me.Elastomer(1e6, 0.5), None), "Contact.indenter=None (NoneType) is not allowed; allowed: "
                                                        "Paraboloid or PowerLaw or FlatPunch or TabulatedProfile"),
])
def test_each_part_is_validated_when_made_naming_the_value(make, words):
    with pytest.raises((TypeError, ValueError), match=re.escape(words)):
        make()


def test_the_paper_s_contact_is_its_parameters_without_the_motion():
    contact = me.Contact.paper()
    assert contact == me.Contact(me.Elastomer(0.324e6, 0.5), me.Paraboloid(0.03), me.Adhesion(0.01, 0.15),
                                 me.FrictionLaw("tau0", tau0=42e3))
    assert repr(contact) == ("Contact(Elastomer(E=324000.0, nu=0.5), Paraboloid(R=0.03), Adhesion(dgamma0=0.01, "
                             "dgamma1=0.15), FrictionLaw('tau0', tau0=42000.0))")
    assert me.Contact.paper(0.1).indenter == me.Paraboloid(0.1)
    # its attributes are those of the paper's Parameters but the motion's (d_max, v)
    legacy = {key: value for key, value in PAPER.to_attrs().items() if not key.startswith(("param_d_max", "param_v"))}
    assert contact.to_attrs() == legacy


@pytest.mark.parametrize("indenter", INDENTERS, ids=lambda indenter: type(indenter).__name__)
@pytest.mark.parametrize("law", LAWS, ids=lambda law: law.law)
def test_a_contact_round_trips_through_its_attributes(indenter, law):
    contact = me.Contact(me.Elastomer(1.5e6, 0.45), indenter, me.Adhesion(0.02, 0.05), law)
    attrs = contact.to_attrs()
    assert me.Contact.from_attrs(attrs) == contact
    assert ("param_R" in attrs) == isinstance(indenter, me.Paraboloid)  # no unused radius
    assert ("param_tau0" in attrs) == law.uses_tau0 and ("friction_mu" in attrs) == law.uses_mu


@pytest.mark.parametrize("indenter", INDENTERS[1:], ids=lambda indenter: type(indenter).__name__)
def test_the_files_written_with_parameters_give_their_contact(indenter):
    """A result of Parameters with profile= and friction= (param_R and param_tau0 unused, with notes) reads back as
    the contact it was computed for."""
    coulomb = me.FrictionLaw("coulomb", mu=0.3)
    attrs = {**PAPER.to_attrs(), **me.contact.profile_attrs(indenter), **me.contact.friction_attrs(coulomb)}
    assert me.Contact.from_attrs(attrs) == me.Contact.from_parameters(PAPER, indenter, coulomb)
    assert me.Contact.from_attrs(PAPER.to_attrs()) == me.Contact.paper()
    assert indenter_from_attrs(attrs) == indenter


@pytest.mark.parametrize("law", [None, "tau0", me.FrictionLaw("coulomb", mu=0.2),
                                 me.FrictionLaw("tau0+coulomb", mu=0.2)])
def test_from_parameters_takes_tau0_from_the_parameters_where_the_law_uses_it(law):
    contact = me.Contact.from_parameters(PAPER, friction=law)
    assert contact.friction.tau0 == (PAPER.tau0 if contact.friction.uses_tau0 else None)
    given = me.FrictionLaw("tau0", tau0=1e3)
    assert me.Contact.from_parameters(PAPER, friction=given).friction is given  # a law with its value keeps it


def test_values_are_read_and_changed_by_dotted_or_short_name():
    contact = me.Contact.from_parameters(PAPER, friction=me.FrictionLaw("tau0+coulomb", mu=0.3))
    changed = contact.replace(**{"elastomer.E": 1e6, "friction.mu": 0.4}, dgamma1=0.2, R=0.05)
    assert changed.elastomer == me.Elastomer(1e6, PAPER.nu) and changed.friction.mu == 0.4
    assert changed.adhesion == me.Adhesion(PAPER.dgamma0, 0.2) and changed.indenter == me.Paraboloid(0.05)
    for short, dotted in SHORT_NAMES.items():
        if dotted in changed.names():
            assert changed.value(short) == changed.value(dotted)
    assert contact.replace() == contact and contact.names() == ["elastomer.E", "elastomer.nu", "indenter.R",
                                                               "adhesion.dgamma0", "adhesion.dgamma1",
                                                               "friction.mu", "friction.tau0",
                                                               "layer.thickness"]


@pytest.mark.parametrize("name, words", [
    ("c", "'c' is not a value of this contact; allowed: elastomer.E, elastomer.nu, indenter.R, adhesion.dgamma0"),
    ("elastomer.G", "'elastomer.G' is not a value of this contact"),
    ("friction.law", "'friction.law' is not a value of this contact"),
    ("nothing", "'nothing' is not a value"),
])
def test_a_name_the_contact_does_not_hold_is_refused_listing_those_it_does(name, words):
    with pytest.raises(ValueError, match=re.escape(words)):
        me.Contact.paper().replace(**{name: 1.0})
    with pytest.raises(ValueError, match=re.escape(words)):
        me.Contact.paper().value(name)


def test_a_changed_value_is_validated_again():
    with pytest.raises(ValueError, match=re.escape("Elastomer.nu=0.7 is not allowed")):
        me.Contact.paper().replace(nu=0.7)
    with pytest.raises(ValueError, match=re.escape("mu=0.3 is not allowed with the friction law 'tau0'")):
        me.Contact.paper().replace(mu=0.3)


def test_no_adhesion_is_hertz_s_contact():
    assert not NO_ADHESION.is_adhesive and me.Adhesion(0.0, 0.1).is_adhesive
    assert me.Contact(me.Elastomer(1e6, 0.5), me.Paraboloid(0.01)).adhesion is NO_ADHESION


def test_every_value_of_every_part_has_a_unit():
    """Contact.unit: each dotted name of each kind of part (a sweep labels its coordinates with it)."""
    import dataclasses

    from mdr_events.contact.model import PARTS, UNITS
    numbers = {f"{part}.{field.name}" for part, kinds in PARTS.items() for kind in kinds
               for field in dataclasses.fields(kind) if field.type in ("float", "float | None")}
    assert numbers == set(UNITS)
    contact = me.Contact.paper()
    assert contact.unit("E") == contact.unit("elastomer.E") == "Pa" and contact.unit("dgamma1") == "J m-2"
    assert contact.holds("tau0") and contact.holds("friction.tau0") and not contact.holds("mu")
    with pytest.raises(ValueError, match="'mu' is not a value of this contact"):
        contact.unit("mu")
