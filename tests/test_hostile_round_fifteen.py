"""The fifteenth hostile round (issue 32): each class of what failed, with the cases that showed it.

The round went at every public entry point and every verb with values at and beyond the edges of what is accepted,
and at the combinations of indenter, friction law, adhesion law, layer, method and path.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest

import mdr_events as me

PAPER = me.Contact.paper()
RATE_LAW = me.RateDependentAdhesion(0.01, 0.15, 1e-6, 0.3)


def _one_line_naming(call, named: str, errors=(ValueError, TypeError)) -> str:
    """The message of what ``call`` raises with every warning an error: one line, naming ``named`` and what is
    allowed."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(errors) as caught:
            call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message, message
    return message


# --- P1: the layer's curves (layer_normal_curve, layer_indentation_cycle, layer_pull_off_curve) read a
# RateDependentAdhesion as the paper's law of its works at rest, a pull-off force at h = inf that pull_off_force
# refuses for the same contact; they refuse it as every other rate-independent computation does --------------------

@pytest.mark.parametrize("curve", [
    lambda contact: me.layer_normal_curve(contact, [1e-4]),
    lambda contact: me.layer_indentation_cycle(contact, 3e-4, samples=11),
    lambda contact: me.layer_pull_off_curve(contact, [5e-3, float("inf")]),
], ids=["normal-curve", "indentation-cycle", "pull-off-curve"])
@pytest.mark.parametrize("h", [5e-3, float("inf")], ids=["layer", "half-space"])
def test_the_layer_curves_refuse_a_rate_dependent_adhesion_as_pull_off_force_does(curve, h):
    contact = dataclasses.replace(PAPER.replace(h=h), adhesion=RATE_LAW)
    with pytest.raises(TypeError, match="RateDependentAdhesion"):
        me.pull_off_force(dataclasses.replace(PAPER, adhesion=RATE_LAW), 0.15)
    _one_line_naming(lambda: curve(contact), "contact.adhesion=RateDependentAdhesion", errors=TypeError)


# --- P2: layer_pull_off_curve of a contact without adhesion named an argument the user never gave ("dgamma=0.0 is not
# allowed"): it names contact.adhesion.dgamma1 ------------------------------------------------------------------------

@pytest.mark.parametrize("h", [5e-3, float("inf")], ids=["layer", "half-space"])
def test_a_pull_off_curve_without_adhesion_names_the_contacts_work_of_adhesion(h):
    contact = dataclasses.replace(PAPER.replace(h=h), adhesion=me.Adhesion(0.0, 0.0))
    _one_line_naming(lambda: me.layer_pull_off_curve(contact, [h]), "contact.adhesion.dgamma1=0.0")


# --- P3: fit's mapping options noise= and bounds= were read by dict(): a list, a string or a number raised Python's
# words ("cannot convert dictionary update sequence element #0 to a sequence", "'int' object is not iterable"), where
# names= and units= named the argument; one check (validation.check_mapping) reads all four -------------------------

@pytest.fixture(scope="module")
def measured():
    from mdr_events.analysis.fit_data import synthetic_measurement
    duration = me.Path.scenario_A(20.0, PAPER.parameters(3e-4, 1e-6)).duration
    return synthetic_measurement(PAPER, "A", 20.0, times=np.linspace(0.0, duration, 101), relative_noise=0.01, seed=1)


@pytest.mark.parametrize("option", ["noise", "bounds", "names", "units"])
@pytest.mark.parametrize("value", [[1, 2], "normal_force=1", 5, [("normal_force", 1.0)]],
                         ids=["list", "string", "number", "pairs"])
def test_the_fits_mapping_options_refuse_what_is_not_a_mapping_naming_it(measured, option, value):
    _one_line_naming(lambda: me.fit(measured, PAPER, "A", 20.0, free=("tau0",), time_origin="path_start",
                                    **{option: value}), f"{option}={value!r}", errors=TypeError)
