"""The fourteenth hostile round (issue 32): each class of what failed, with the cases that showed it.

The round went at the surface that had landed last: the discrete model on a layer of finite thickness, sweeps over
the thickness, the layer's slip onset, a study's ``[layer]`` table; and at a sample of everything older.
"""

from __future__ import annotations

import dataclasses
import math
import tracemalloc
import warnings

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import depth_reaching, one_line_naming
from mdr_events.analysis.layer_angles import ANGLE_RTOL
from mdr_events.app.cli import main
from mdr_events.theory.layer import LAMBDA_MAX

PAPER = me.Contact.paper()
LAYERED = PAPER.replace(h=5e-3)
A20 = me.Scenario("A", alpha=[20.0])


# --- N1: a run on a layer checked what the layer's springs take before the run's scales: the springs' check builds
# the motion's paths, whose jump-off overflowed (PowerLaw(1e3, 1e6) on a layer: OverflowError, exit 3 on the command
# line, where the half-space refused it in one line), or ended at inf with NumPy's warnings first (PowerLaw(1e-300, 2):
# "waypoints=[..., inf)] is not allowed"), or blamed --h for R = 1e308. check_layer_taken checks the scales first -----

@pytest.mark.parametrize("contact", [
    dataclasses.replace(LAYERED, indenter=me.PowerLaw(1e3, 1e6)),
    dataclasses.replace(LAYERED, indenter=me.PowerLaw(1e-300, 2.0)),
    LAYERED.replace(R=1e308),
], ids=["power-law-1e3-1e6", "power-law-1e-300", "R-1e308"])
def test_a_run_on_a_layer_checks_its_scales_before_its_springs(contact):
    one_line_naming(lambda: me.simulate(contact, A20, "discrete"), "the contact radius a at d_max")


def test_the_command_line_refuses_an_overflowing_power_law_on_a_layer_in_one_line(capsys, tmp_path):
    status = main(["simulate", "--scenario", "A", "--alpha", "20", "--h", "5e-3", "--power-law", "1e3", "1e6",
                   "--out", str(tmp_path / "out")])
    error = capsys.readouterr().err.strip()
    assert status == 2 and "\n" not in error and "the contact radius a at d_max overflows" in error, error
    assert not (tmp_path / "out").exists()


# --- N2: the scan of a layer's branch ended at the tables' last radius 64 h, and its node exp(ln 64h) rounds above it:
# a contact whose scan reached there was refused by the tables, "a/h=64.00000000000001 is not allowed" (a layer
# curve, and a run with large works of adhesion). The scans end just inside (branch_scan.scan_ceiling, the one place) ----

def test_a_scan_that_reaches_the_tables_last_radius_stays_inside_them():
    contact = dataclasses.replace(PAPER.replace(h=5e-4), adhesion=me.Adhesion(1000.0, 10000.0))
    curve = me.layer_normal_curve(contact, [3e-4])
    assert np.all(np.isfinite(curve["contact_radius"].values))
    assert np.all(curve["relative_radius"].values <= LAMBDA_MAX)


# --- N3: the discrete model on a layer probed its springs' thresholds by doubling their count (64, 128, ...) and kept
# two beyond the contact's edge, past the tables' last radius although the contact lay within it: the tables refused
# "a/h=64.001" (PowerLaw(100, 3) on 0.5 mm), "a/h=64.005" (d_max = 3 h) or "a/h=64.32" in words a user cannot act on.
# A kind of springs says how many it knows (most_springs): the probe stops there, and a contact within a spring of it
# is refused naming dx and the depth --------------------------------------------------------------------------------

@pytest.mark.parametrize("contact, motion", [
    (dataclasses.replace(PAPER.replace(h=5e-4), indenter=me.PowerLaw(100.0, 3.0)), A20),
    (PAPER.replace(h=1e-4), me.Scenario("A", alpha=[20.0], d_max=3e-4)),
], ids=["power-law-on-0.5-mm", "d_max-3h"])
def test_a_run_whose_contact_lies_within_the_tables_runs(contact, motion):
    run = me.simulate(contact, motion, "discrete", n_steps=200)
    radius = run["contact_radius"].values
    assert 0 < np.nanmax(radius) <= LAMBDA_MAX * contact.layer.thickness
    assert np.all(np.isfinite(run["normal_force"].values[np.isfinite(radius)]))


def test_the_thickest_layers_springs_are_the_half_spaces():
    """The springs a layer knows are no bound where 64 h overflows (a guard of N3's bound, which read int(inf) there:
    h = 1.8e308 is a layer, whose run is the half-space's to the rounding of the weighted sums, 3.5e-16 of the
    forces measured, taken as 1e-15)."""
    thick = me.simulate(PAPER.replace(h=1.7976931348623157e308), A20, "discrete", n_steps=200)
    half = me.simulate(PAPER, A20, "discrete", n_steps=200)
    np.testing.assert_array_equal(thick["contact_radius"].values, half["contact_radius"].values)
    for name in ("normal_force", "tangential_force"):
        scale = np.nanmax(np.abs(half[name].values))
        np.testing.assert_allclose(thick[name].values, half[name].values, rtol=0.0, atol=1e-15 * scale)


def test_a_contact_within_a_spring_of_the_tables_end_is_refused_naming_dx():
    contact = PAPER.replace(h=1e-4)
    target = 0.999 * LAMBDA_MAX * 1e-4  # (a radius 0.1 % inside the tables' last)
    low = depth_reaching(contact, target, 3e-4, 4e-4)  # (the depth of that radius on the Δγ0 branch)
    dx = LAMBDA_MAX * 1e-4 / 100  # (100 springs reach the tables' end: the edge's 100th has none beyond)
    one_line_naming(lambda: me.simulate(contact, me.Scenario("A", alpha=[20.0], d_max=low), "discrete", dx=dx,
                                        n_steps=100), "allowed: dx <= ")  # (the spacing that fits: round twenty-four)


# --- N4: the slip onset's closed forms did not check the scales they compute with, as the phase diagram of the
# half-space and the runs do: on a layer R = 1e300 was a ZeroDivisionError and R = 1e-300 an OverflowError (d_crit,
# critical_angle, phase_diagram); on the half-space E = 1e300 gave d_crit = 0, τ0 = 1e300 or E = 1e-300 inf, each
# with NumPy's warning. They check them (check_representable), the layer's in check_onset_contact ------------------

@pytest.mark.parametrize("call, named", [
    (lambda: me.critical_angle(LAYERED.replace(R=1e300)), "R=1e+300 m"),
    (lambda: me.critical_angle(LAYERED.replace(R=1e-300)), "R=1e-300 m"),
    (lambda: me.d_crit([20.0], LAYERED.replace(R=1e300)), "R=1e+300 m"),
    (lambda: me.phase_diagram(LAYERED.replace(R=1e-300)), "R=1e-300 m"),
    (lambda: me.d_crit([20.0], PAPER.replace(E=1e300)), "E=1e+300 Pa"),
    (lambda: me.d_crit([20.0], PAPER.replace(E=1e-300)), "E=1e-300 Pa"),
    (lambda: me.d_crit([20.0], PAPER.replace(tau0=1e300)), "tau0=1e+300 Pa"),
    (lambda: me.critical_angle(PAPER, d_max=1e-300), "d_max=1e-300 m"),
])
def test_the_slip_onset_checks_the_scales_it_computes_with(call, named):
    one_line_naming(call, named)


# --- N5: the check of a run's scales computed each scale with the closed forms, whose own argument checks refused an
# intermediate first: R = 1e300 was "contact_radius=4.695781686427441e+197 is not allowed" in every entry point
# (simulate, phase-diagram), not the scale it came from. A scale that cannot be computed is that scale's failure --

def test_a_scale_a_closed_form_refuses_is_named_as_the_runs_scale():
    message = one_line_naming(lambda: me.simulate(me.Parameters.paper().replace(R=1e300), "A", [20.0]),
                              "the contact radius a at d_max is 4.7e+197 m")
    assert "R=1e+300 m" in message


# --- N6: the slip onset on a layer scanned every motion to the tables' last radius 64 h: on a layer so thick that its
# square leaves the double range (h >= 1.5e152 m; the universal map's thinness 1e-300) the profile there overflowed and
# the onset was refused ("power_law_profile(...) is not finite") though the layer is the half-space there, as the
# runs and the curves find. The scan ends at SCAN_SPAN times the motion's radius at most; a thinness whose thickness
# overflows (5e-324: inf with NumPy's warning, "grid repeats a value" beside 0) is refused in one line --------------

@pytest.mark.parametrize("h", [1e200, 1.7e308])
def test_a_very_thick_layers_slip_onset_is_the_half_spaces(h):
    thick = PAPER.replace(h=h)
    for scenario in ("A", "B", "B+"):
        assert me.critical_angle(thick, scenario) == pytest.approx(me.critical_angle(PAPER, scenario),
                                                                   rel=ANGLE_RTOL)
    np.testing.assert_allclose(me.d_crit([20.0, 89.0], thick), me.d_crit([20.0, 89.0], PAPER), rtol=ANGLE_RTOL)


def test_a_thinness_next_to_zero_is_the_half_space_and_one_whose_thickness_overflows_is_refused():
    from mdr_events.analysis.universal_map import universal_map

    base = me.Parameters.paper()
    mapped = universal_map([1.0], [1.0], base, thinness=[0.0, 1e-300], scheduler="serial")
    for name in ("critical_angle_A", "critical_angle_B"):
        half, thin = mapped[name].isel(thinness=0).values, mapped[name].isel(thinness=1).values
        np.testing.assert_allclose(thin, half, rtol=ANGLE_RTOL)
    one_line_naming(lambda: universal_map([1.0], [1.0], base, thinness=[0.0, 5e-324], scheduler="serial"),
                    "thinness=5e-324 is not allowed: its thickness")


# --- N7: the layer's travel per cap at its edges: without τ0 (a documented choice: a frictionless contact) the cap is
# 0 and every node and bisection divided by it (hundreds of NumPy's warnings, nan ratios); scenario A's travel, the
# depth from the first touch, fell below 0 by round-off, and a d_max of 1e-100 m gave a critical angle of -4.5e-16 ---

def test_the_layers_slip_onset_without_tau0_slides_at_once_without_warnings():
    for contact in (PAPER, LAYERED):  # (the half-space's closed forms say what the layer's must)
        free = contact.replace(tau0=0.0)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            assert [me.critical_angle(free, scenario) for scenario in ("A", "B", "B+")] == [90.0, 90.0, 90.0]
            np.testing.assert_array_equal(me.d_crit([0.0, 20.0, 45.0], free), [0.0, 0.0, 0.0])


def test_the_critical_angles_against_thickness_without_tau0_are_90_degrees():
    """The thin-layer limit atan(G d_max/(τ0 h)) without τ0 is 90° (a ZeroDivisionError before)."""
    angles = me.critical_angles_against_thickness(PAPER.replace(tau0=0.0), [5e-3, math.inf])
    assert np.all(angles["critical_angle_jkr"].values == 90.0)
    np.testing.assert_array_equal(angles["thin_limit_A"].values, [90.0, 0.0])  # (0 on the half-space: none)


def test_a_critical_angle_on_a_layer_is_never_negative():
    angle = me.critical_angle(LAYERED, d_max=1e-100)
    assert 0.0 <= angle < 1e-12, angle  # (the half-space's is 4.9e-95 degrees)


# --- N8: a study's [layer] was dropped by its [phase_diagram]: the job handed the contact's flat record (no layer) to
# the phase diagram, which wrote the half-space's (22.87° for 25.18° on the 5 mm layer) with exit 0, and a
# frictionless base, which the layer's slip onset refuses, passed. The job keeps the contact's layer; the study
# checks it when read

def _study(folder, tables: str):
    path = folder / "study.toml"
    path.write_text(f'{tables}\n[output]\ndirectory = "out"\n')
    return path


def test_a_studys_phase_diagram_is_on_its_layer(tmp_path, capsys):
    study = _study(tmp_path, '[phase_diagram]\nscenarios = ["A"]\n[layer]\nh = 5e-3')
    assert main(["run", str(study)]) == 0
    written = me.open_result(tmp_path / "out" / "study_phase_diagram_A.nc")
    assert float(written["critical_angle_jkr"]) == me.critical_angle(LAYERED)
    assert written.attrs["param_layer_thickness"] == 5e-3 and written.attrs["param_layer_base"] == "bonded"


def test_a_studys_phase_diagram_on_a_layer_it_cannot_take_is_refused_when_read(tmp_path, capsys):
    study = _study(tmp_path, '[phase_diagram]\nscenarios = ["A"]\n[layer]\nh = 5e-3\nbase = "frictionless"')
    assert main(["run", str(study)]) == 2
    error = capsys.readouterr().err.strip()
    assert "[phase_diagram] Layer.base='frictionless' is not allowed" in error and "\n" not in error, error
    assert not (tmp_path / "out").exists()


# --- N9: a sweep of the closed-form angles on a layer checked each run by computing its angles before the first run
# (about 0.04 s each, without progress: a grid of 1e5 thicknesses was checked for over an hour, and again on every
# resume). It checks what they refuse (check_onset_contact: a few branch evaluations) and computes them once, running

def test_a_sweeps_check_of_a_layers_closed_forms_does_not_compute_them(monkeypatch):
    from mdr_events.analysis import sweep_runs
    from mdr_events.analysis.sweep import sweep_job

    computed = []
    monkeypatch.setattr(sweep_runs, "closed_form_angle", lambda *args: computed.append(args) or 0.0)
    sweep_job({"h": [2e-3, 5e-3, 1e-2, math.inf], "tau0": [3e4, 4.2e4]}, PAPER, "A", 20.0, None,
              {"output": me.SweepOutput(quantities=("critical_angle_A", "critical_angle_B")),
               "engine": me.Engine(scheduler="serial"), "limits": me.Limits()})
    assert computed == []
    with pytest.raises(ValueError, match="exceeds a/h = 64"):  # (what the angles refuse is still refused first)
        sweep_job({"h": [1e-5]}, PAPER, "A", 20.0, None,
                  {"output": me.SweepOutput(quantities=("critical_angle_A",)), "engine": me.Engine(scheduler="serial"),
                   "limits": me.Limits()})


# --- N10: the memory a discrete run on a layer was counted against Limits as the half-space's springs (256 bytes
# each), but the layer's take more (their weights and integer prefix sums: 317 bytes each measured), so a run passed
# the memory limit by a quarter. Each kind of springs counts its own ---------------------------------------------

def test_a_layer_runs_memory_estimate_covers_what_it_takes():
    arguments = (LAYERED, A20, "discrete")
    # (dx = 1e-7: about 4e4 springs, whose bytes are nearly all of the peak (12.5 MB measured; 62.1 MB at 2e-8, five
    # times the springs): the half-space's 256 bytes per spring still fall about a fifth short of it (checked: with
    # LayerSprings.bytes_per_spring = 256 the run passes its limit), at a fifth of the time traced)
    options = {"dx": 1e-7, "n_steps": 100}
    me.simulate(*arguments, dx=1e-5, n_steps=100)  # (the layer's tables read before: what is measured is the run's)
    tracemalloc.start()
    try:
        me.simulate(*arguments, **options)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    with pytest.raises(me.ResourceLimitError):  # (the estimate is at least what it took)
        me.simulate(*arguments, **options, limits=me.Limits(memory=peak))


# --- N11 (older surface, found by the quick suite's property test of Coulomb's law with adhesion, which draws it now
# and then): the continuum stopped at the shrinking edge passing two piece starts of the stored anchors within
# rounding ("made no progress ... after 50 event restarts", exit 3 on the command line): the last piece was dropped
# and the one before, a sliver starting beyond the edge, ended at it with a negative length, whose zone's target was
# met again at every restart. The edge forgets every piece it has passed (AnchorMap.drop_edge_piece) -------------
#: The integrated F_x against its algebraic form, as a share of the largest (tests/models/test_coulomb_properties.py)
FORCE_SHARE = 1e-7
#: The path the property test drew: a tangential approach to 1 µm, in to 51 µm, and straight out past the pull-off.
STALLED_PATH = [[0.0, 0.0], [-0.000182, 1e-06], [-0.000232, 5.1e-05], [-0.000232, -0.00037751593907930686]]


@pytest.mark.parametrize("nu, works", [(0.0, 0.5), (0.0, 0.0), (0.5, 0.0)], ids=["drawn", "no-adhesion", "nu-0.5"])
def test_the_continuum_passes_two_anchor_pieces_at_once(nu, works):
    from mdr_events.models import continuum

    params = me.Parameters(E=1e5, nu=nu, R=0.1, tau0=0.0, dgamma0=works, dgamma1=works, d_max=1e-3, v=1e-6)
    friction = me.FrictionLaw("coulomb", mu=1.0)
    solution = continuum.solve_path(params, me.Path(STALLED_PATH, 1e-6), friction=friction)
    ends = (continuum.EventKind.PULL_OFF, continuum.EventKind.CONTACT_ENDS)
    assert any(event.kind in ends for event in solution.events)  # (the run went past the edge's passing)
    times = np.linspace(0.0, solution.end_time, 301)[:-1]
    integrated = continuum.evaluate(solution, times)["tangential_force"]
    algebraic = continuum.algebraic_tangential_force(solution, times)
    np.testing.assert_allclose(integrated, algebraic, rtol=0.0,
                               atol=FORCE_SHARE * max(float(np.max(np.abs(algebraic))), 1e-300))


# --- N12: check_layer_taken, which the front ends call before they write anything, read its arguments' attributes
# unchecked: a contact of None or a Parameters, a motion of None, a method of None or by name were an AttributeError.
# It names them, and takes a motion and a method as simulate does --------------------------------------------------

@pytest.mark.parametrize("arguments, named", [
    ((None, A20, "discrete"), "contact=None (NoneType) is not allowed in check_layer_taken"),
    ((me.Parameters.paper(), A20, "discrete"), "(Parameters) is not allowed in check_layer_taken"),
    ((LAYERED, None, "discrete"), "scenario=None (NoneType) is not allowed"),
    ((LAYERED, A20, None), "method=None is not allowed"),
])
def test_check_layer_taken_names_what_is_not_a_contact_motion_or_method(arguments, named):
    from mdr_events.models.simulate import check_layer_taken

    one_line_naming(lambda: check_layer_taken(*arguments), named)


def test_check_layer_taken_takes_a_method_by_name():
    from mdr_events.models.simulate import check_layer_taken

    assert check_layer_taken(LAYERED, A20, "discrete") is LAYERED


# --- N13: a sweep of the model on a layer without the slip onset's closed forms (Coulomb's law, a frictionless base)
# failed every run: its default quantities hold the closed-form angles, which the layer's theory refuses there, and
# the run's own quantities were lost with them ("failed" everywhere, F_N nan) where the half-space gives the angles as
# nan. The angles are nan where the layer has no closed forms (has_closed_forms); a sweep of the angles alone is refused

@pytest.mark.parametrize("contact, alpha", [
    (dataclasses.replace(LAYERED, friction=me.FrictionLaw("coulomb", mu=0.3)), 20.0),
    (LAYERED.replace(**{"layer.base": "frictionless"}), 90.0),
], ids=["coulomb", "frictionless-base"])
def test_a_sweep_of_the_model_on_a_layer_without_closed_forms_runs(contact, alpha):
    swept = me.sweep({"E": [3e5, 4e5]}, contact, "A", alpha, method=me.Discrete(dx=5e-5, n_steps=500),
                     engine=me.Engine(scheduler="serial"))
    assert not swept["failed"].values.any(), swept["error"].values
    assert np.all(np.isfinite(swept["normal_force_min"].values))
    assert np.all(np.isnan(swept["critical_angle_A"].values)) and np.all(np.isnan(swept["critical_angle_B"].values))
    with pytest.raises(ValueError, match="is not allowed"):  # (the angles alone: nothing to compute, refused first)
        me.sweep({"E": [3e5]}, contact, "A", alpha, engine=me.Engine(scheduler="serial"),
                 quantities=("critical_angle_A",))


# --- N14: the layer's onsets were counted as the half-space's closed forms: a phase diagram on a layer counted its
# angles as samples alone (160 bytes each), but each is a bisection on the layer's tables per curve (65 µs in A, 130
# in B, 400 times the half-space's; 181 and 198 bytes measured), so 1e7 angles passed the default limits and ran for
# 20 minutes; d_crit on a layer took no limits at all. Both count ONSET_STEPS_PER_ANGLE and ONSET_BYTES_PER_ANGLE ---

@pytest.mark.parametrize("call", [
    lambda limits: me.phase_diagram(LAYERED, alpha=np.linspace(0.0, 89.0, 1000), limits=limits),
    lambda limits: me.d_crit(np.linspace(0.0, 89.0, 1000), LAYERED, limits=limits),
], ids=["phase_diagram", "d_crit"])
def test_the_onsets_on_a_layer_count_their_work(call):
    with pytest.raises(me.ResourceLimitError, match="discrete time steps"):
        call(me.Limits(steps=1e4))
    call(me.Limits(steps=1e6))  # (within: it runs)
    one_line_naming(lambda: call("x"), "limits='x' (str) is not allowed")
    one_line_naming(lambda: me.d_crit([20.0], PAPER, limits=5), "limits=5 (int) is not allowed")  # (the half-space)


def test_a_phase_diagram_on_a_layer_counts_the_memory_it_takes():
    # (2000 angles: 410 kB traced, 205 bytes an angle with the scans' own; 177 at 10_000. The half-space's 160 counted
    # fall short at either; traced, the angles' bisections cost a fifth of what 10_000 did)
    angles = np.linspace(0.0, 89.0, 2000)
    me.phase_diagram(LAYERED, alpha=angles[:10])  # (the tables read before: what is measured is the diagram's)
    tracemalloc.start()
    try:
        me.phase_diagram(LAYERED, alpha=angles)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    with pytest.raises(me.ResourceLimitError, match="memory"):
        me.phase_diagram(LAYERED, alpha=angles, limits=me.Limits(memory=peak, steps=math.inf))


def test_the_critical_angles_against_thickness_count_their_work():
    """Six critical angles per thickness, 84 ms measured: 1e4 steps counted for all six (the discrete step's 1.5 µs:
    15 ms) let 2000 thicknesses pass the default limits and run for three minutes."""
    with pytest.raises(me.ResourceLimitError, match="the critical angles at 1 thicknesses"):
        me.critical_angles_against_thickness(PAPER, [5e-3], limits=me.Limits(steps=5e4))
    with pytest.raises(me.ResourceLimitError):
        me.critical_angles_against_thickness(PAPER, np.geomspace(3e-4, 5e-2, 400))


# --- N15: the thin-layer limit of the onset, d = τ0 h tan α / G, is a bonded layer's (it shears like a Winkler
# foundation), but it gave that number on a frictionless base too, which holds the layer by no tangential stiffness.
# It takes the slip onset's kinds (a bonded base) and no depth: a layer thinner than any contact ------------------

def test_the_thin_layer_limit_is_a_bonded_layers():
    from mdr_events.theory.layer import thin_layer_onset_depth

    thin = PAPER.replace(h=1e-7)  # (far thinner than the contact at d_max: a/h about 4e4, beyond the tables)
    G = PAPER.elastomer.E / (2.0 * (1.0 + PAPER.elastomer.nu))
    assert thin_layer_onset_depth(45.0, thin) == pytest.approx(PAPER.friction.tau0 * 1e-7 / G, rel=1e-15)
    one_line_naming(lambda: thin_layer_onset_depth(45.0, thin.replace(**{"layer.base": "frictionless"})),
                    "Layer.base='frictionless' is not allowed for tangential contact")
