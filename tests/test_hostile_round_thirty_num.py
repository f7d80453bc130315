"""The thirtieth hostile round (issue 32), numbers across the model space: each class of what failed, with the cases
that showed it.

The round's cases combine the edges of every accepted range at once (indenters: paraboloids, cones, power laws to
n = 12, flat punches, tables with three points, plateaus, dense ones; every friction law; adhesion off, equal,
reversed, rate-dependent; the half-space and layers, thin and thick, bonded and frictionless, ν = 0 and 0.5; both
methods, the discrete at its stated spacing; scenarios at 0°, 1e-6°, 89.999°, 90°) and are listed with their outcomes
in the issue's closing note; what failed is below.
"""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

import mdr_events as me

PAPER = me.Parameters.paper()
SOFT = me.Elastomer(1e3, 0.5)
#: The rate law of the cases (the paper's works, v_ref 1 µm/s, n = 0.5).
RATE = me.RateDependentAdhesion(0.01, 0.15, v_ref=1e-6, n=0.5)


def _every_variable_finite_in_contact(ds) -> None:
    alive = np.isfinite(ds["indentation_depth"].values)
    touching = alive & (ds["contact_area"].values > 0)
    for name, variable in ds.data_vars.items():
        if variable.dims == ds["indentation_depth"].dims and variable.dtype.kind == "f":
            where = touching if name in ("mean_pressure", "mean_shear_stress", "sliding_fraction") else alive
            assert np.all(np.isfinite(variable.values[where])), name


# -- C1: an advancing piece of the rate law's edge overshot its end radius: a spring there matched no attachment ------

@pytest.mark.slow
@pytest.mark.parametrize("indenter, scenario", [
    (me.Paraboloid(0.03), "B+"),
    (me.TabulatedProfile((0.0, 1e-3, 4e-3), (0.0, 1e-5, 1e-3)), "A"),
], ids=["paraboloid-B+", "three-point-table-A"])
@pytest.mark.parametrize("friction", [me.FrictionLaw("coulomb", mu=0.3),
                                      me.FrictionLaw("tau0+coulomb", mu=0.3, tau0=PAPER.tau0)],
                         ids=["coulomb", "tau0+coulomb"])
def test_the_rate_law_s_springs_run_where_the_edge_stops(indenter, scenario, friction):
    """C1: under the rate law with Coulomb's part, a vertical path on a soft elastomer (E = 1 kPa, d_max = 1 µm) ended
    in ``RuntimeError: springs at xi = [...] match no attachment of the radius's history ...: a bug to report``: the
    steps' polynomial of the advancing piece where the edge stops rose 2e-10 of itself above the piece's end radius,
    beyond which no attachment is looked for. A vertical path moves nothing tangentially: ``F_x`` is 0 throughout."""
    contact = me.Contact(SOFT, indenter, RATE, friction)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = me.simulate(contact, me.Scenario(scenario, 90.0, 1e-6, 1e-6), method="continuum")
    _every_variable_finite_in_contact(ds)
    force = ds["tangential_force"].values
    assert np.all(force[np.isfinite(force)] == 0.0)


# -- C2: the bound a refusal states, rounded to nearest, was itself refused ------------------------------------------

def _stated(pattern: str, call) -> float:
    with pytest.raises(ValueError) as error:
        call()
    message = str(error.value)
    assert "\n" not in message, message
    found = re.search(pattern, message)
    assert found, message
    return float(found.group(1))


@pytest.mark.parametrize("contact, scenario", [
    (me.Contact(me.Elastomer(1e9, 0.3), me.PowerLaw(0.3, 1.0), me.Adhesion(0.0, 0.15)), me.Scenario("B", 45.0, 1e-6)),
    (me.Contact(SOFT, me.PowerLaw(0.3, 1.0)), me.Scenario("A", 10.0, 1e-6)),
    (me.Contact(me.Elastomer(PAPER.E, 0.0), me.TabulatedProfile(tuple(np.linspace(0, 3e-3, 7)),
                                                              tuple(np.linspace(0, 3e-3, 7) ** 2 / 0.06))),
     me.Scenario("A", 45.0, 3e-4)),
    (me.Contact(me.Elastomer(PAPER.E, 0.0), me.PowerLaw(0.3, 1.0 + 1e-9), me.Adhesion(0.2, 0.05),
                me.FrictionLaw("coulomb", mu=1e3)), me.Scenario("B", 20.0, 3e-4)),
], ids=["cone-stiff", "cone-soft", "table", "cone-reversed-works"])
def test_the_stated_spacing_and_time_step_are_accepted(contact, scenario):
    """C2: ``dx=1.0`` is refused with "allowed: at least 10, i.e. dx <= 2.12207e-07 m" (the bound 2.122066e-07 rounded
    to nearest, up), and ``dx=2.12207e-07`` was then refused with the same message (56 of 232 stated bounds on
    random contacts); the same for the time step's "dt <= ...". The number stated is rounded towards the allowed side."""
    largest = _stated(r"i\.e\. dx <= ([0-9.e+-]+) m", lambda: me.simulate(contact, scenario, method=me.Discrete(dx=1.0)))
    ds = me.simulate(contact, scenario, method=me.Discrete(dx=largest))
    _every_variable_finite_in_contact(ds)
    step = _stated(r"dt <= ([0-9.e+-]+) s",
                   lambda: me.simulate(contact, scenario, method=me.Discrete(dx=largest, dt=1e3)))
    me.simulate(contact, scenario, method=me.Discrete(dx=largest, dt=step))


#: How far a bound written in allowed_bound's 6 significant digits lies from the bound: one unit of the last digit.
SIX_DIGITS = 1e-5


@pytest.mark.parametrize("bound", [2.1220659078919376e-07, 7.513241e-05, 1.0, 9.9999995e-3, 5e-324, 1.7976931348623157e308])
@pytest.mark.parametrize("upper", [True, False])
def test_a_stated_bound_is_on_its_allowed_side(bound, upper):
    """C2's helper: the text is within one unit of its last digit of the bound, on the allowed side of it."""
    text = me.validation.allowed_bound(bound, (lambda value: value <= bound) if upper else (lambda value: value >= bound),
                                       upper)
    value = float(text)
    assert (value <= bound) if upper else (value >= bound), text
    assert abs(value - bound) <= SIX_DIGITS * bound or bound < 1e-300, text


# -- C3: a span stopped a rounding before the contact's end dropped onto radius 0: an IndexError ---------------------

@pytest.mark.parametrize("layer, scenario, tau0", [(me.Layer(), "A", 1e10), (me.Layer(1.0), "B", 1e10),
                                                   (me.Layer(), "B", 1e12), (me.Layer(1.0), "A", 1e12)],
                         ids=["half-space-A-1e10", "thick-layer-B-1e10", "half-space-B-1e12", "thick-layer-A-1e12"])
def test_a_contact_that_ends_a_rounding_after_a_slip_event_ends(layer, scenario, tau0):
    """C3: E = 1 kPa and τ0 = 1e10 Pa (τ0/E = 1e7; the caps ``π a τ0 / (2 G*)`` far above every shift until ``a``
    nearly vanishes) without adhesion: the last span in contact stopped on the springs' full slip at a = 2e-11 m, a
    rounding before the depth's 0, and the next plan dropped the radius onto the branch's 0 and laid out the slip zones
    of no springs: ``IndexError: list index out of range`` (zones.py). The contact ends there, its event logged, every
    variable finite, the extrema bounding the samples, and the run ends as a τ0 a thousand times smaller does."""
    contact = me.Contact(SOFT, me.Paraboloid(0.03), friction=me.FrictionLaw("tau0", tau0=tau0), layer=layer)
    ds = me.simulate(contact, me.Scenario(scenario, 45.0, 3e-4, 1e-6), method="continuum")
    _every_variable_finite_in_contact(ds)
    kinds = [str(kind) for kind in ds["event_kind"].values[0] if str(kind)]
    assert kinds[-1] == "contact_ends", kinds
    for name in ("normal_force", "tangential_force", "contact_area"):
        samples = ds[name].values[0][np.isfinite(ds[name].values[0])]
        assert ds[f"{name}_max"].values[0] >= samples.max() and ds[f"{name}_min"].values[0] <= samples.min(), name
    reference = me.simulate(contact.replace(tau0=tau0 / 1e3),
                            me.Scenario(scenario, 45.0, 3e-4, 1e-6), method="continuum")
    ended = ds["event_time"].values[0][len(kinds) - 1]
    assert ended == pytest.approx(reference["event_time"].values[0][list(reference["event_kind"].values[0]).index(
        "contact_ends")], rel=1e-9)


# -- C4: the flat punch's critical angle on a layer divided by its cap, 0 at τ0 = 0: ZeroDivisionError ---------------

@pytest.mark.parametrize("layer", [me.Layer(5e-3), me.Layer(1e-4)], ids=["5mm", "0.1mm"])
@pytest.mark.parametrize("scenario", ["A", "B", "B+"])
@pytest.mark.parametrize("adhesion", [True, False])
def test_the_punch_s_critical_angle_without_tau0_is_a_right_angle(layer, scenario, adhesion):
    """C4: ``critical_angle`` (and so ``phase_diagram``) of a FlatPunch on a bonded layer under ``τ0 = 0`` raised
    ``ZeroDivisionError: float division by zero`` (punch_onset.punch_critical_angle: the travel over the cap ``ū = 0``).
    Without a cap every spring slides at once on any path with a tangential part: 90°, as the paraboloid's closed forms on a
    layer give."""
    punch = me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.FlatPunch(1e-3), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                       me.FrictionLaw("tau0", tau0=0.0), layer)
    # (the paraboloid on the 5 mm layer: at 0.6 mm on 0.1 mm its radius passes the layer's tables, refused)
    paraboloid = me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.Paraboloid(0.03), punch.adhesion, punch.friction,
                            me.Layer(5e-3))
    assert me.critical_angle(punch, scenario, adhesion=adhesion) == 90.0
    assert me.critical_angle(paraboloid, scenario, adhesion=adhesion) == 90.0


def test_the_punch_s_phase_diagram_without_tau0_runs():
    """C4: the phase diagram of the case that showed it (scenario A, 5 mm layer, the paper's works) runs, its critical
    angle 90°."""
    punch = me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.FlatPunch(1e-3), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                       me.FrictionLaw("tau0", tau0=0.0), me.Layer(5e-3))
    diagram = me.phase_diagram(punch, scenario="A")
    critical = [name for name in diagram.data_vars if "critical" in name]
    assert critical and all(np.all(diagram[name].values == 90.0) for name in critical), critical


#: A table flat (1e-15 m rises) to 1 mm, then steep: its reach depends on the works of adhesion.
PLATEAU = me.TabulatedProfile((0.0, 2.5e-4, 5e-4, 7.5e-4, 1e-3, 1.5e-3, 2e-3, 3e-3),
                              (0.0, 1e-15, 2e-15, 3e-15, 4e-15, 1e-4, 3e-4, 1e-3))


@pytest.mark.parametrize("works", [(0.1, 0.1), (5.0, 20.0)], ids=["equal", "large"])
def test_the_stated_reach_of_a_table_is_accepted(works):
    """C2 (the table's reach): a path deeper than the table reaches is refused with "allowed ...: at most 0.00222153 m",
    the reach rounded to nearest; that depth was refused again (22 of 48 tables x works x moduli). The depth stated
    now runs."""
    contact = me.Contact(me.Elastomer(PAPER.E, PAPER.nu), PLATEAU, me.Adhesion(*works))
    deepest = _stated(r"at most ([0-9.e+-]+) m", lambda: me.simulate(contact, me.Scenario("A", 45.0, 5e-2), "discrete"))
    ds = me.simulate(contact, me.Scenario("A", 45.0, deepest), method=me.Discrete(n_steps=50))
    _every_variable_finite_in_contact(ds)


#: The shear strengths (Pa) of a soft layer's run that never slides: the caps ``ū`` lie far beyond every shift.
UNREACHED_TAU0 = (1e9, 1e12)
#: How closely two all-stick runs of different (unreached) caps agree: the solver's own relative tolerance.
ALL_STICK_RTOL = 1e-9


def test_a_cap_deeper_than_the_layers_tables_is_past_every_spring():
    """The review's case (r10, 9): E = 1 kPa on a 5 mm bonded layer with τ0 = 1e9 Pa along A 30° to 1 µm: the springs'
    fronts were looked up at the depth where a piece reaches its cap, 230 m, beyond the layer's tables (a/h = 64),
    and the run was refused ("depth=229.57 m is not allowed") though it never goes deeper than 1 µm. A level reached
    beyond the branch's largest radius lies past every spring of the piece; the run sticks throughout, so its
    ``F_x`` does not depend on the (unreached) cap."""
    forces = []
    for tau0 in UNREACHED_TAU0:
        contact = me.Contact(SOFT, me.Paraboloid(0.03), me.Adhesion(1e-6, 5e-7), me.FrictionLaw("tau0", tau0=tau0),
                             me.Layer(5e-3))
        run = me.simulate(contact, me.Scenario("A", 30, 1e-6), method="continuum")
        in_contact = run["contact_area"].values > 0
        assert all(np.all(np.isfinite(run[name].values[in_contact])) for name in run.data_vars
                   if run[name].dims == run["contact_area"].dims)  # (the means: undefined out of contact)
        assert in_contact.any() and float(run["sliding_fraction"].max()) == 0.0
        forces.append(run["tangential_force"].values)
    np.testing.assert_allclose(forces[0], forces[1], rtol=ALL_STICK_RTOL, atol=0.0)
