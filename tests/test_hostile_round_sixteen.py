"""The sixteenth hostile round (issue 32): each class of what failed, with the cases that showed it.

The round went first at what round fifteen left (Q1-Q4), then at what landed since: validate, fit, sweep and
convergence_study on a layer (``h`` free in fit, ``--h``, ``--layer-base``, a study's ``[layer]``), Coulomb's law with
adhesion in the continuum and the rate-dependent edge in the continuum, with a sample of everything older: about 630
API cases (thicknesses from 1e-300 to 1e300 m through simulate (both methods), validate, fit, convergence_study,
d_crit, critical_angle, phase_diagram, the pull-off and the curves, 170; Coulomb's and the combined law with
adhesion at μ from 1e-300 to 1e300 over 4 indenters, 3 scenarios and angles from 0.1° to 89.9999999°, both methods,
250; the rate law in the continuum and the springs (paths, speeds, indenters, laws at their edges) and the rate angles
and fit_rate_adhesion at v_ref from 1e-300 to 1e300 and n from 1e-300 to 1, 150; Contact.from_attrs, netCDF
round trips and readers' names/units, 60) and about 120 command lines (validate, fit and simulate with --h,
--layer-base, --bounds, --noise, --units and other indenters; 48 study files with [layer] and sweeps over h; the
lammps-check, phase-diagram and sweep tables with a layer). Ten classes failed (Q1-Q10 below, Q1-Q4 left by round
fifteen; Q10, the continuum under Coulomb's law at μ >= 1e5 with adhesion: no progress, exit 3, or minutes at
μ >= 1e7 near 90°, was left open by the round and closed after the split integrator's rework).
"""

from __future__ import annotations

import dataclasses
import math
import time

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import one_line_naming, cli_one_line
from mdr_events.app.cli import main
from mdr_events.theory.mindlin import coulomb_cap_ratio

PAPER = me.Parameters.paper()
CONTACT = me.Contact.paper()


# --- Q1 (left by round fifteen): the reader's refusals of names= and units= that did not say what is allowed, and a
# unit given for a quantity the run has no column of was dropped silently ----------------------------------------------

RUN = {"time": [0.0, 1.0, 2.0], "normal_force": [0.0, 1.0, 0.0]}


def test_a_column_named_that_the_run_does_not_have_says_what_is_allowed():
    from mdr_events.io.candidates import read_candidate

    message = one_line_naming(lambda: read_candidate(RUN, names={"time": "t"}), "names['time']='t'")
    assert "time, normal_force" in message


@pytest.mark.parametrize("units", [{"contact_radius": "mm"}, {"tangential_force": "mN"}])
def test_a_unit_for_a_quantity_the_run_does_not_have_is_refused(units):
    from mdr_events.io.candidates import read_candidate

    quantity, unit = next(iter(units.items()))
    one_line_naming(lambda: read_candidate(RUN, units=units), f"units[{quantity!r}]={unit!r}")
    read_candidate(RUN, units={"normal_force": "mN"})  # (a column it has: read)


def test_the_command_line_refuses_a_unit_for_an_absent_column(capsys, tmp_path):
    run = tmp_path / "run.csv"
    run.write_text("time,normal_force\n0,0\n1,1\n2,0\n")
    err = cli_one_line(capsys, ["validate", str(run), "--scenario", "A", "--alpha", "20", "--out",
                                str(tmp_path / "out"), "--units", "contact_area=mm2"])
    assert "units['contact_area']='mm2' is not allowed" in err and not (tmp_path / "out").exists()


# --- Q2 (left by round fifteen): RateMeasurement's shapes were refused as "measurements[0] is not allowed: times and
# normal_force must be ...", naming neither the part nor its value -----------------------------------------------------

@pytest.mark.parametrize("times, force, named", [
    (np.ones((2, 2)), np.ones((2, 2)), "measurements[0].times of shape (2, 2)"),
    ([0.0], [0.0], "measurements[0].times of shape (1,)"),
    ([0.0, 1.0], [0.0, 1.0, 2.0], "measurements[0].normal_force of shape (3,)"),
    ([0.0, math.nan], [0.0, 1.0], "measurements[0].times[1]=nan"),
    ([0.0, 1.0], [0.0, math.inf], "measurements[0].normal_force[1]=inf"),
])
def test_a_rate_measurement_of_the_wrong_shape_names_the_part(times, force, named):
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max)]), speed=PAPER.v)
    law = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.3)
    measurement = me.RateMeasurement(path, times, force)
    one_line_naming(lambda: me.fit_rate_adhesion([measurement], PAPER, law), named)


# --- Q3 (left by round fifteen): --limit samples= (Limits.samples, "output times (all cases)") did not bind the
# discrete method, which writes every time step --------------------------------------------------------------------

def test_the_samples_limit_binds_the_discrete_method(capsys, tmp_path):
    with pytest.raises(me.ResourceLimitError, match="output times"):
        me.simulate(CONTACT, me.Scenario("A", [20.0]), "discrete", n_steps=100, limits=me.Limits(samples=100))
    me.simulate(CONTACT, me.Scenario("A", [20.0]), "discrete", n_steps=99, limits=me.Limits(samples=100))
    with pytest.raises(me.ResourceLimitError, match="output times"):  # (a given dt: counted on the run's own grid)
        me.simulate(CONTACT, me.Scenario("A", [20.0]), "discrete", dt=1e-2, limits=me.Limits(samples=100))
    err = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", "--out", str(tmp_path / "o"),
                                "--limit", "samples=10"])
    assert "output times" in err and not (tmp_path / "o").exists()


# --- Q4 (left by round fifteen, issue 29): a rate law at its rate-independent limit (v_ref = 1e300) ended in the edge
# solver's words after seconds of solving; it is refused before, with the bound on v_ref ----------------------------

FAR = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e300, 0.3)


@pytest.mark.parametrize("call", [
    lambda law: me.critical_angle_at_speed(PAPER, law, 1e-3),
    lambda law: me.critical_angle_B_at_speed(PAPER, law, 1e-3),
    lambda law: me.slip_onset_depth_at_speed(PAPER, law, 1e-3, 20.0),
    lambda law: me.let_go_B_at_speed(PAPER, law, 1e-3, 30.0),
    lambda law: me.critical_angles_at_speeds(PAPER, law, [1e-3]),
    lambda law: me.phase_diagram_at_speeds(PAPER, law, [1e-3], [20.0]),
], ids=["A", "B", "onset", "let-go", "A-grid", "phase-diagram"])
def test_a_rate_law_at_its_rate_independent_limit_is_refused_with_the_bound(call):
    message = one_line_naming(lambda: call(FAR), "law.v_ref=1e+300")
    bound = float(message.split("allowed: v_ref <= ")[1].split(" m/s")[0])
    assert bound == pytest.approx(1e-3 * me.analysis.rate_angles.LEAST_RATE_FACTOR ** (-1.0 / FAR.n), rel=1e-5)


def test_the_bound_on_v_ref_is_the_rate_factor_s_and_survives_an_underflow():
    from mdr_events.analysis.rate_angles import LEAST_RATE_FACTOR, _checked

    bound = 1e-3 * LEAST_RATE_FACTOR ** (-1.0 / 0.3)
    _checked(PAPER, dataclasses.replace(FAR, v_ref=0.999 * bound), 1e-3, None)  # (inside: taken)
    with pytest.raises(ValueError, match="rate factor"):
        _checked(PAPER, dataclasses.replace(FAR, v_ref=1.001 * bound), 1e-3, None)
    # speed/v_ref underflows to 0 here while the factor (1e-600)^0.001 = 0.25 is not small: taken by the law's check
    with pytest.raises(ValueError, match="speed=1e-300 m/s"):  # (the path's own scales refuse it, not an overflow)
        _checked(PAPER, me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e300, 1e-3), 1e-300, None)


# --- Q5: the rate-dependent continuum let scipy's LSODA warn ("Repeated convergence failures") before its one-line
# refusal of a law its clock cannot follow --------------------------------------------------------------------------

def test_the_rate_continuum_refuses_without_a_solver_warning():
    contact = dataclasses.replace(CONTACT, adhesion=me.RateDependentAdhesion(0.01, 0.15, 1e12, 1.0))
    one_line_naming(lambda: me.simulate(contact, me.Scenario("A", [20.0]), "continuum"), "law=RateDependentAdhesion")


# --- Q6: the continuum on a layer far thinner or thicker than its contact: raw OverflowError, ZeroDivisionError,
# RuntimeError ("did not converge") or scipy's "f(a) and f(b) must have different signs" (exit 3 for validate --h) ---

@pytest.mark.parametrize("h, named", [
    (1e-10, "depth=0.0003 m is not allowed on layer h = 1e-10 m"),
    (1e-20, "depth=0.0003 m is not allowed on layer h = 1e-20 m"),
    (1e-300, "depth=0.0003 m is not allowed on layer h = 1e-300 m"),
    (1e60, "contact.layer=Layer(thickness=1e+60"),
    (1e100, "contact.layer=Layer(thickness=1e+100"),
    (1e300, "contact.layer=Layer(thickness=1e+300"),
])
def test_the_continuum_refuses_a_layer_beyond_its_scales(h, named):
    one_line_naming(lambda: me.simulate(CONTACT.replace(h=h), me.Scenario("A", [20.0]), "continuum"), named)


def test_the_continuum_runs_a_layer_just_inside_the_stated_thickness():
    message = one_line_naming(lambda: me.simulate(CONTACT.replace(h=1e300), me.Scenario("A", [20.0]), "continuum"),
                              "allowed: h <= ")
    largest = float(message.split("allowed: h <= ")[1].split(" m")[0])
    thick = me.simulate(CONTACT.replace(h=0.99 * largest), me.Scenario("A", [20.0]), "continuum", samples=51)
    half_space = me.simulate(CONTACT, me.Scenario("A", [20.0]), "continuum", samples=51)
    # a/h of 2.2e-16 moves the layer's factors by as much: the forces agree to a few rounding errors of the solve
    np.testing.assert_allclose(thick["normal_force"].values, half_space["normal_force"].values, rtol=1e-9, atol=1e-15)


@pytest.mark.parametrize("h", ["1e-300", "1e300"])
def test_validate_on_a_layer_beyond_the_scales_is_one_line(capsys, tmp_path, h):
    run = tmp_path / "run.csv"
    run.write_text("time,normal_force\n0,0\n1,1\n2,0\n")
    cli_one_line(capsys, ["validate", str(run), "--scenario", "A", "--alpha", "20", "--out", str(tmp_path / "o"),
                          "--h", h])


# --- Q7: the continuum's own output times ran one spacing past the longest run's end even where that is the path's
# end (a run that ends in contact: a custom path, or the rate law's edge holding past scenario A's exit depth), so its
# last sample wrote every quantity, the depth too, as nan -----------------------------------------------------------

RATE_CONTACT = dataclasses.replace(CONTACT, adhesion=me.RateDependentAdhesion(0.01, 0.15, 1e-6, 0.3))


@pytest.mark.parametrize("contact", [CONTACT, RATE_CONTACT], ids=["paper", "rate"])
@pytest.mark.parametrize("motion", [
    me.Paths([me.Path(np.array([(0.0, 0.0), (0.0, 3e-4)]), speed=1e-6)]),
    me.Scenario("A", [45.0]),
], ids=["ends-in-contact", "A-45"])
def test_a_continuum_run_writes_no_sample_past_its_path(contact, motion):
    run = me.simulate(contact, motion, "continuum", samples=101)
    for name in ("indentation_depth", "normal_force", "tangential_force", "contact_radius"):
        assert np.all(np.isfinite(run[name].values)), name
    path = motion.cases(contact.parameters(3e-4, 1e-6)).paths[0] if isinstance(motion, me.Paths) else None
    if path is not None:  # (the grid ends on the path's end exactly)
        assert run.time.values[-1] == path.duration - path.first_contact_time()


# --- Q8: a study table that lacks a required key, or a study without [output], said so without what is allowed ----

@pytest.mark.parametrize("text, named", [
    ("[simulation]\nscenario = 'A'\nalpha = [20]\n[layer]\nbase = 'bonded'\n[output]\ndirectory = 'o'\n",
     "[layer] lacks the required key(s) h; allowed: [layer] with h: the elastomer's thickness in m"),
    ("[output]\ndirectory = 'o'\n[fit]\nfree = ['tau0']\n", "[fit] lacks the required key(s) data; allowed: "),
    ("[phase_diagram]\nscenarios = ['A']\n",
     "the required table [output] is missing; allowed: a study with an [output]"),
])
def test_a_study_missing_a_required_key_says_what_is_allowed(tmp_path, text, named):
    from mdr_events.app.study import StudyError, load_study

    path = tmp_path / "study.toml"
    path.write_text(text)
    with pytest.raises(StudyError) as caught:
        load_study(path)
    assert named in str(caught.value) and "\n" not in str(caught.value), str(caught.value)


# --- Q9: fit's report listed every parameter of the paraboloid: a fit with another indenter (--power-law,
# --flat-punch, a study's [profile]) ended on "mdr-events: error: param_R" (a KeyError's key) after the whole fit ------

@pytest.mark.parametrize("indenter, options", [(me.PowerLaw(20.0, 2.0), ["--power-law", "20", "2"]),
                                               (me.FlatPunch(1e-3), ["--flat-punch", "1e-3"])],
                         ids=["power-law", "flat-punch"])
def test_a_fit_with_another_indenter_writes_its_report(capsys, tmp_path, indenter, options, without_drawing):
    contact = dataclasses.replace(CONTACT, indenter=indenter)
    run = me.simulate(contact, me.Scenario("A", [20.0]), "continuum", samples=201).isel(alpha=0)
    data = tmp_path / "measured.csv"
    data.write_text("time,normal_force,tangential_force\n" + "".join(
        f"{float(t)!r},{float(fn)!r},{float(fx)!r}\n" for t, fn, fx in zip(run.time.values, run.normal_force.values,
                                                     run.tangential_force.values)))
    status = main(["fit", str(data), "--scenario", "A", "--alpha", "20", "--free", "tau0", "--out",
                   str(tmp_path / "out"), *options])
    err = capsys.readouterr().err
    assert status in (0, 1) and "error" not in err, err
    report = (tmp_path / "out" / "measured_fit.md").read_text()
    assert "the other parameters as given: E = 324000 Pa" in report and "R = " not in report


def test_a_rate_fit_started_at_the_rate_independent_limit_is_refused_with_the_bound():
    path = me.Path(np.array([(0.0, 0.0), (0.0, PAPER.d_max), (0.0, -1e-4)]), speed=1e-6)
    times = np.linspace(0.0, path.duration, 20)
    measurement = me.RateMeasurement(path, times, np.zeros_like(times))
    one_line_naming(lambda: me.fit_rate_adhesion([measurement], PAPER, FAR), "start.v_ref=1e+300")


# --- Q10 (left open by round sixteen): the continuum under Coulomb's law at very large μ with adhesion. The levels
# x − cap (K a + κ d) carry κ times the depth's rounding (|v_d| ulp(t): 7e-18 m at t = 5.8e4 s, 1e-11 m at μ = 1e6),
# which the slip criterion's tolerance left out, so the same event fired at each restart ("no progress", exit 3);
# and a cap of more than 1e9 travels made the solver chase a band of slip at the compressed zone's edge below what the
# criterion separates (minutes, or without end) ----------------------------------------------------------------------

def _coulomb_contact(law: str, mu: float) -> me.Contact:
    return dataclasses.replace(CONTACT, friction=me.FrictionLaw(law, mu=mu, tau0=42e3 if "tau0" in law else None))


def _coulomb_run(law: str, mu: float, scenario: str, alpha: float) -> np.ndarray:
    run = me.simulate(_coulomb_contact(law, mu), me.Scenario(scenario, [alpha]), "continuum", samples=201)
    return run["tangential_force"].values.ravel()


#: A guard only (the checks are the results and the messages): each case ran in about 1-5 s alone
WALL_CLOCK_GUARD = 60.0


@pytest.mark.parametrize("law, mu, scenario, alpha", [
    ("coulomb", 1e6, "A", 0.3),
    # (7.9 s of CPU measured loaded, the others 1-2 s: the same limit is checked quick on Coulomb at 1e6 and both
    # parts at 1e8)
    pytest.param("coulomb", 1e8, "A", 1.0, marks=pytest.mark.slow), ("tau0+coulomb", 1e5, "A", 0.3),
    ("tau0+coulomb", 1e8, "A", 1.0), ("tau0+coulomb", 1e8, "B+", 1.0),
])
def test_a_huge_mu_runs_to_its_sticking_limit(law, mu, scenario, alpha):
    """Finite, and at the limit μ → ∞ (the compressed zone sticks): ten times μ moves F_x by at most the share of the
    springs at the cap, a band at the compressed zone's edge of ``~ travel / ū`` of it (travel ``d_max cot α``,
    ``ū = κ d_max``: ``1/(κ tan α)``, 1.4e-3 to 3.8e-7 here; measured 2.2e-5 to 1.9e-7)."""
    start = time.monotonic()
    force, stiffer = _coulomb_run(law, mu, scenario, alpha), _coulomb_run(law, 10.0 * mu, scenario, alpha)
    assert time.monotonic() - start < WALL_CLOCK_GUARD
    inside = ~np.isnan(force)
    assert np.all(np.isfinite(force[inside])) and np.array_equal(inside, ~np.isnan(stiffer))
    band_share = 1.0 / (coulomb_cap_ratio(me.FrictionLaw("coulomb", mu=mu), PAPER) * math.tan(math.radians(alpha)))
    assert np.max(np.abs(force[inside] - stiffer[inside])) <= band_share * np.max(np.abs(force[inside]))


@pytest.mark.parametrize("law, mu, alpha", [("coulomb", 1e8, 89.0), ("coulomb", 1e10, 45.0),
                                            ("tau0+coulomb", 1e8, 85.0), ("coulomb", 1e12, 45.0)])
def test_a_cap_beyond_the_travel_the_criterion_resolves_is_refused_with_the_bound(law, mu, alpha):
    message = one_line_naming(lambda: me.simulate(_coulomb_contact(law, mu), me.Scenario("A", [alpha]),
                                                  "continuum"), f"mu={mu!r}")
    assert "allowed: ū at most 1e+09 travels, mu <= " in message and "method='discrete'" in message


def test_the_largest_mu_stated_runs():
    """Just inside the stated bound the run ends with finite forces (before: 20-27 s at μ = 1e7, 89°)."""
    contact = _coulomb_contact("coulomb", 1e8)
    message = one_line_naming(lambda: me.simulate(contact, me.Scenario("A", [89.0]), "continuum"), "mu=")
    largest = float(message.split("mu <= ")[1].split(" ")[0])
    force = _coulomb_run("coulomb", 0.99 * largest, "A", 89.0)
    assert np.all(np.isfinite(force[~np.isnan(force)])) and np.any(force[~np.isnan(force)] != 0.0)


def test_the_command_line_refuses_a_huge_mu_in_one_line(capsys, tmp_path):
    cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "85", "--method", "continuum", "--friction",
                          "tau0+coulomb", "--mu", "1e8", "--tau0", "42e3", "--out", str(tmp_path / "o")])
    assert not (tmp_path / "o").exists()
