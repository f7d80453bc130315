"""The adhesion law reaches the kernels as a value: each method looks up the law's kernel by its type.

A law of another type is refused by name by each method; a law given a kernel (here a test law whose edge follows
``Δγ0`` both ways) is run by it, and gives what the paper's law of the same works gives, bit for bit.
"""

from dataclasses import dataclass

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.adhesion import Adhesion, law_of
from mdr_events.models import discrete
from mdr_events.models.continuum import edges, solve_path
from mdr_events.models.discrete import run_discrete
from mdr_events.models.kernel_model import KernelModel
from mdr_events.models.paths import Path


@dataclass(frozen=True)
class NoHysteresis(Adhesion):
    """A test law: the springs let go as they attach, with ``Δγ0`` (its works at rest stay ``Δγ0``, ``Δγ1``)."""


def _edge_without_hysteresis(adhesion, params, profile=None):
    return edges.hysteresis_edge(Adhesion(adhesion.dgamma0, adhesion.dgamma0), params, profile)


def _thresholds_without_hysteresis(adhesion, g, positions, params):
    return discrete.hysteresis_thresholds(Adhesion(adhesion.dgamma0, adhesion.dgamma0), g, positions, params)


@pytest.fixture
def registered(monkeypatch):
    monkeypatch.setitem(edges.EDGE_RULES, NoHysteresis, _edge_without_hysteresis)
    monkeypatch.setitem(discrete.THRESHOLD_RULES, NoHysteresis, _thresholds_without_hysteresis)


HYSTERETIC = me.Parameters.paper()  # Δγ1 = 15 Δγ0: the two laws differ on the way out
WITHOUT = HYSTERETIC.replace(dgamma1=HYSTERETIC.dgamma0)  # the paper's law with Δγ1 = Δγ0
PATH = Path.scenario_A(30.0, HYSTERETIC)  # (out below the jump-off of either)


@pytest.mark.parametrize("method", ["continuum", "discrete"])
def test_a_law_without_a_kernel_is_refused_by_name(method):
    contact = me.Contact.from_parameters(HYSTERETIC)
    contact = me.Contact(contact.elastomer, contact.indenter, NoHysteresis(HYSTERETIC.dgamma0, HYSTERETIC.dgamma1),
                         contact.friction)
    with pytest.raises(TypeError, match=f"adhesion=NoHysteresis.* is not allowed in the {method} method; "
                                        "allowed: Adhesion"):
        me.simulate(contact, me.Scenario("A", 30.0), method)


def test_a_law_with_a_kernel_runs_it_in_the_continuum(registered):
    law = NoHysteresis(HYSTERETIC.dgamma0, HYSTERETIC.dgamma1)
    ran = solve_path(HYSTERETIC, PATH, adhesion=law)
    same = solve_path(WITHOUT, PATH)
    other = solve_path(HYSTERETIC, PATH)
    times = np.linspace(0.0, PATH.duration - PATH.first_contact_time(), 401)
    forces = [me.continuum.evaluate(solution, times)["normal_force"] for solution in (ran, same, other)]
    np.testing.assert_array_equal(forces[0], forces[1])
    assert not np.allclose(forces[0], forces[2], equal_nan=True)  # (the law made the difference)


def test_a_law_with_a_kernel_runs_it_in_the_springs(registered):
    law = NoHysteresis(HYSTERETIC.dgamma0, HYSTERETIC.dgamma1)
    dt = (PATH.duration - PATH.first_contact_time()) / 2000
    ran = run_discrete(KernelModel(HYSTERETIC, adhesion=law), [PATH], 4e-6, dt)
    same = run_discrete(WITHOUT, [PATH], 4e-6, dt)
    other = run_discrete(HYSTERETIC, [PATH], 4e-6, dt)
    np.testing.assert_array_equal(ran["normal_force"], same["normal_force"])
    assert not np.allclose(ran["normal_force"], other["normal_force"], equal_nan=True)


def test_the_law_of_a_kernel_is_the_one_of_its_parameters():
    assert law_of(HYSTERETIC) == Adhesion(HYSTERETIC.dgamma0, HYSTERETIC.dgamma1)
    assert law_of(HYSTERETIC, Adhesion(HYSTERETIC.dgamma0, HYSTERETIC.dgamma1)) == law_of(HYSTERETIC)
    with pytest.raises(ValueError, match=r"adhesion=Adhesion\(dgamma0=0.1, dgamma1=0.1\) is not allowed with dgamma0="
                                         r".*allowed: a law whose works at rest are the parameters'"):
        solve_path(HYSTERETIC, PATH, adhesion=Adhesion(0.1, 0.1))
    with pytest.raises(TypeError, match="adhesion=0.1 \\(float\\) is not allowed; allowed: None"):
        run_discrete(KernelModel(HYSTERETIC, adhesion=0.1), [PATH], 4e-6, 1.0)


def test_a_kernel_model_is_its_parameters_with_the_paper_s_parts():
    """A ``Parameters`` alone runs as the kernel model of its values with every part at its default, bit for bit; any
    other value is refused naming what is allowed."""
    dt = (PATH.duration - PATH.first_contact_time()) / 500
    alone = run_discrete(HYSTERETIC, [PATH], 4e-6, dt)
    spelled = run_discrete(KernelModel(HYSTERETIC, None, "tau0", Adhesion(HYSTERETIC.dgamma0, HYSTERETIC.dgamma1)),
                           [PATH], 4e-6, dt)
    for name in ("normal_force", "tangential_force", "contact_radius"):
        np.testing.assert_array_equal(alone[name], spelled[name])
    with pytest.raises(TypeError, match=r"model=.* is not allowed; allowed: a KernelModel, or Parameters"):
        run_discrete({"E": 1.0}, [PATH], 4e-6, dt)
