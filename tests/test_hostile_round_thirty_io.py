"""The thirtieth hostile round (issue 32), the interfaces' side: the API's arguments given the values a NumPy user
writes (0-d arrays, NumPy scalars, subclasses of ``str``), paths that are long texts, and the CLI's verbs: each class
of what failed, with the cases that showed it (the round's other cases, which held, are listed in the issue's closing
note)."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.validation import check_choice
from hostile_checks import one_line_naming

CONTACT = me.Contact.paper()


class _Name(str):
    """A user's subclass of ``str``."""


#: A name as a NumPy user holds it: a 0-d array of text (``np.asarray("A")``, ``names[i, ...]`` of an array of names),
#: NumPy's scalar of text (``names[i]``), and a user's subclass of ``str``.
NAME_FORMS = {"0-d array": np.array, "np.str_": np.str_, "str subclass": _Name}


@pytest.mark.parametrize("form", list(NAME_FORMS.values()), ids=list(NAME_FORMS))
@pytest.mark.parametrize("name, call, read", [
    ("A", lambda value: me.critical_angle(CONTACT, value), lambda result: result),
    ("B", lambda value: me.phase_diagram(CONTACT, scenario=value, alpha=[10.0, 20.0]), lambda result: result.attrs),
    ("A", lambda value: me.cross_check(CONTACT, value, alpha=[20.0]), lambda result: result.attrs),
    ("coulomb", lambda value: me.FrictionLaw(value, mu=0.3), lambda result: (result.law, type(result.law))),
    ("frictionless", lambda value: me.Layer(0.005, value), lambda result: result.base),
    ("A", lambda value: me.Scenario(value, alpha=(20.0,)), lambda result: (result.name, type(result.name))),
    ("A", lambda value: me.simulate(CONTACT, value, alpha=20.0, method="continuum"), lambda result: result.attrs),
], ids=["critical_angle", "phase_diagram", "cross_check", "FrictionLaw", "Layer", "Scenario", "simulate"])
def test_a_name_given_as_numpy_text_is_the_name(name, call, read, form):
    """NIT (b) of round 29's review: ``check_choice`` refused ``np.array("A")`` (round 29's guard against arrays),
    which d540130 accepted in ``critical_angle`` and ``phase_diagram`` (where it then failed writing its attributes:
    "array('A') is not netCDF-safe") and refused in ``FrictionLaw``, ``Scenario`` and ``simulate``. A 0-d array of text
    is what a NumPy user holds for a name (``np.asarray(names)[i]`` keeps the array): it is read as its ``str``, and
    the name kept (in a result's attributes too) is a plain ``str``, whichever form it came in; the result is the
    plain name's, bit for bit."""
    plain, given = read(call(name)), read(call(form(name)))
    if isinstance(plain, dict):
        assert {key: (value, type(value)) for key, value in given.items()} \
            == {key: (value, type(value)) for key, value in plain.items()}
    else:
        assert given == plain


@pytest.mark.parametrize("value", [np.array(["A"]), np.array(b"A"), np.array("C"), np.array(1.0), np.array(["A", "B"])],
                         ids=["1-d", "bytes", "unknown", "number", "two names"])
def test_an_array_that_is_not_one_known_name_is_still_refused(value):
    """The 0-d text array alone is read as a name: a 1-d array, bytes, an unknown name or a number stay refused in one
    line naming the argument (round 29's class 1)."""
    one_line_naming(lambda: me.critical_angle(CONTACT, value), "scenario")
    one_line_naming(lambda: me.FrictionLaw(value), "FrictionLaw.law")


def test_check_choice_returns_the_plain_name():
    """``check_choice`` returns the name as a plain ``str``: what its callers keep."""
    for form in NAME_FORMS.values():
        chosen = check_choice("scenario", form("B"), ("A", "B"))
        assert chosen == "B" and type(chosen) is str

