"""The worked example examples/validate_your_simulator/: `validate` passes the user's right spring
simulator (first-order convergence) and flags each of its three wrong variants."""

import ast
import importlib.util
import math
import runpy
import sys
from pathlib import Path

import numpy as np
import pytest

import mdr_events as me
from mdr_events.io.rounded_text import rounded_text_differences

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "validate_your_simulator"


def _load_example():
    spec = importlib.util.spec_from_file_location("example_validate", EXAMPLE / "validate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


example = _load_example()
sim = example.sim  # my_simulator.py, as the script imports it
WRONG = ("hess_sqrt2", "stiffness_E", "no_hysteresis")


@pytest.fixture(scope="module")
def right(tmp_path_factory):
    """The right simulator's reports at the script's four spacings, {dx: report}."""
    out = tmp_path_factory.mktemp("right")
    return {dx: example.run_and_validate(me.Contact.paper(), dx, out)[0] for dx in example.SPACINGS}


@pytest.fixture(scope="module")
def variants(tmp_path_factory):
    """Every variant's reports at the script's three spacings, {variant: [report, ...]}."""
    out = tmp_path_factory.mktemp("variants")
    return {variant: [example.run_and_validate(me.Contact.paper(), dx, out, variant)[0]
                      for dx in example.WRONG_SPACINGS]
            for variant in sim.VARIANTS}


def _max_error(report, quantity):
    return float(report.max_error.sel(quantity=quantity))


def _event_error(report, event):
    return float(report.event_time_error.sel(event=event))


def test_the_simulator_stands_alone_with_the_papers_parameters(paper):
    tree = ast.parse((EXAMPLE / "my_simulator.py").read_text(encoding="utf-8"))
    imported = {alias.name.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.Import)
                for alias in node.names}
    imported |= {node.module.split(".")[0] for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)}
    assert imported <= {"math", "numpy"}, imported
    assert sim.PAPER == paper.as_dict()


def test_the_simulator_is_the_papers_spring_model(paper):
    """Written from the rules, it agrees with mdr_events' own spring model to round-off."""
    dx = 4e-6
    mine = sim.simulate(sim.PAPER, 20.0, dx, example.time_step(dx, paper))
    ours = me.simulate(paper, "A", alpha=[20.0], method="discrete", dx=dx, dt=example.time_step(dx, paper))
    n = mine["time"].size
    assert np.array_equal(mine["time"], ours["time"].values[:n])
    assert np.isnan(ours["normal_force"].sel(alpha=20.0).values[n:]).all()  # both end at the pull-off
    for name in ("normal_force", "tangential_force", "contact_area"):
        theirs = ours[name].sel(alpha=20.0).values[:n]
        assert np.max(np.abs(mine[name] - theirs)) <= 1e-13 * np.max(np.abs(theirs)), name


def test_right_passes_within_one_spring_at_every_spacing(paper, right):
    """Tolerance: the springs resolve the contact edge to one spring per side, 2 Δx / a(d_max) of the
    area π a² and of the full-slip force π a² τ0. Measured: the largest error (F_x) is 0.72 of it at
    every spacing, so 0.8 of it is the bound; at 1 µm the default tolerance 1e-3 passes too. The events
    enter the verdict too: the slip onset lags by up to slip_onset_delay_bound beyond a step (1.5 times
    2 Δx / a relative to the path's duration), which the example's tolerance takes; within it every
    event passes, the slip onset at 0.6-0.8 of it."""
    a = float(me.jkr_contact_radius(paper.d_max, paper, paper.dgamma0))
    for dx, report in right.items():
        assert report.attrs["tolerance"] == pytest.approx(example.tolerance(dx, me.Contact.paper()))
        assert 1.4 * 2 * dx / a <= report.attrs["tolerance"] <= 1.6 * 2 * dx / a  # (the slip onset's bound)
        assert report.attrs["verdict"] == "pass", dx
        assert np.all(report.max_error.values <= 0.8 * 2 * dx / a), (dx, report.max_error.values)
        onset = float(report.event_time_relative_error.sel(event="slip_onset"))
        assert 0.4 * report.attrs["tolerance"] <= onset <= report.attrs["tolerance"], (dx, onset)
        assert int(report.samples_compared) > 0.95 * report.time.size
    finest = me.validate(sim.simulate(sim.PAPER, 20.0, 1e-6, example.time_step(1e-6, paper)), paper, "A", 20.0)
    assert finest.attrs["verdict"] == "pass"


def test_right_converges_at_first_order(right):
    spacings = list(right)
    for norm in ("max_error", "rms_error", "l1_error"):
        for quantity in example.QUANTITIES:
            errors = [float(right[dx][norm].sel(quantity=quantity)) for dx in spacings]
            order = example.observed_order(spacings, errors)
            assert 0.7 < order < 1.3, (norm, quantity, order)
    onset = [abs(_event_error(right[dx], "slip_onset")) for dx in spacings]
    assert example.observed_order(spacings, onset) > 0.7, onset


def test_right_events_within_two_steps(paper, right):
    """Slip onset converges at first order (above); the other events are found within two steps;
    the pull-off force is the exact F_N at the candidate's last sample in contact (F_N(t) has an
    infinite slope at the jump itself, so the report's comparison with the jump converges slowly)."""
    for dx, report in right.items():
        for event in ("full_slip", "detachment_starts", "pull_off"):
            assert abs(_event_error(report, event)) < 2 * example.time_step(dx, paper), (dx, event)
        last = np.flatnonzero(report.candidate_contact_area.values > 0)[-1]
        exact = float(report.exact_normal_force[last])
        assert float(report.pull_off_force_candidate) == pytest.approx(exact, rel=5e-3), dx
    gaps = [abs(float(r.pull_off_force_candidate) - float(r.pull_off_force_exact)) for r in right.values()]
    assert gaps[-1] < 0.7 * gaps[0]  # ... but it does converge


def test_package_convergence_study_says_converges(paper, tmp_path):
    convergence_study = example.find_convergence_study()
    if convergence_study is None:
        pytest.skip("mdr_events.analysis.convergence_study is not in this version")
    csvs = {dx: example.run_and_validate(me.Contact.paper(), dx, tmp_path)[1] for dx in example.SPACINGS}
    study = convergence_study(csvs, paper, "A", alpha=example.ALPHA)
    assert study.attrs["verdict"] == "converges"
    assert np.all(study["max_error_order"].values > 0.7)
    wrong = {dx: example.run_and_validate(me.Contact.paper(), dx, tmp_path, "stiffness_E")[1]
             for dx in example.SPACINGS}
    assert convergence_study(wrong, paper, "A", alpha=example.ALPHA).attrs["verdict"] == "does not converge"


#: Quantities whose error does not shrink with Δx, for each variant.
FLAGGED_QUANTITIES = {"right": set(), "hess_sqrt2": {"F_N", "F_x", "A"}, "stiffness_E": {"F_x"},
                      "no_hysteresis": {"F_N", "F_x", "A"}}
#: Events more than 4 steps off, not shrinking, for each variant.
FLAGGED_EVENTS = {"right": set(), "hess_sqrt2": {"slip_onset", "full_slip", "detachment_starts", "pull_off"},
                  "stiffness_E": set(), "no_hysteresis": {"full_slip", "detachment_starts", "pull_off"}}


@pytest.mark.parametrize("variant", list(FLAGGED_QUANTITIES))
def test_flags(paper, variants, variant):
    """The script's flags: an error outside the tolerance that does not shrink with Δx."""
    reports = variants[variant]
    found = {flag.split(" ")[0] for flag in example.flags(reports[-2], reports[-1], example.WRONG_SPACINGS[-1])}
    assert found == FLAGGED_QUANTITIES[variant] | FLAGGED_EVENTS[variant]
    verdicts = {report.attrs["verdict"] for report in reports}
    assert verdicts == ({"pass"} if variant == "right" else {"fail"})


@pytest.mark.parametrize("variant", WRONG)
def test_wrong_variants_fail_far_outside_the_tolerance(paper, variants, variant):
    """Each wrong variant's largest error is at least 30 times the springs' resolution 2 Δx / a (and 20 times the
    tolerance, which also takes the slip onset's lag)."""
    a = float(me.jkr_contact_radius(paper.d_max, paper, paper.dgamma0))
    for dx, report in zip(example.WRONG_SPACINGS, variants[variant]):
        assert np.max(report.max_error.values) > 30 * 2 * dx / a
        assert np.max(report.max_error.values) > 20 * report.attrs["tolerance"]


def _area_ratio_at_first_contact(report, samples=5):
    compared = (report.left_out.values == 0) & (report.exact_contact_area.values > 0)
    first = np.flatnonzero(compared)[:samples]
    return report.candidate_contact_area.values[first] / report.exact_contact_area.values[first]


def test_hess_sqrt2_wrong_area_from_the_start(paper, variants):
    """Δl_max / √2 acts as a halved work of adhesion: the jump-in area is about 2^(-2/3) = 0.63 of
    the exact one; the contact detaches and comes off more than 3 steps early at every spacing (the
    right one: within one step, above)."""
    for dx, right, wrong in zip(example.WRONG_SPACINGS, variants["right"], variants["hess_sqrt2"]):
        assert np.all(np.abs(_area_ratio_at_first_contact(right) - 1) < 0.01)
        ratios = _area_ratio_at_first_contact(wrong)
        assert ratios[0] == pytest.approx(2 ** (-2 / 3), abs=0.05) and np.all(ratios < 0.8), ratios
        for event in ("detachment_starts", "pull_off"):
            assert _event_error(wrong, event) < -3 * example.time_step(dx, paper), (dx, event)


def test_stiffness_E_tangential_force_off_by_E_star_over_G_star(paper, variants):
    """F_x is E*/G* = 1.5 times the exact one while the springs stick; F_N, A and every event are the
    right simulator's (the cap ū is a shift: when springs slide does not depend on their stiffness)."""
    for right, wrong in zip(variants["right"], variants["stiffness_E"]):
        onset = float(wrong.event_time_exact.sel(event="slip_onset"))
        sticking = (wrong.left_out.values == 0) & (wrong.time.values > 10) & (wrong.time.values < onset)
        for report, factor in ((right, 1.0), (wrong, paper.E_star / paper.G_star)):
            ratio = report.candidate_tangential_force.values[sticking] / report.exact_tangential_force.values[sticking]
            assert np.median(ratio) == pytest.approx(factor, rel=1e-2)  # right: 0.995 at 4 µm (first order)
        assert _max_error(wrong, "tangential_force") == pytest.approx(0.5, abs=0.01)
        for name in ("normal_force", "contact_area"):
            assert _max_error(wrong, name) == _max_error(right, name)
        np.testing.assert_array_equal(wrong.event_time_candidate.values, right.event_time_candidate.values)


def test_no_hysteresis_pulls_off_early_and_weakly(paper, variants):
    """Detaching with Δγ0: detachment starts at the turning point instead of staying pinned, the
    contact comes off about 20 s early (10 steps at 4 µm, 40 at 1 µm; the right one within a step),
    at a tenth of the exact pull-off force."""
    turning = paper.d_max / math.sin(math.radians(example.ALPHA)) / paper.v
    for dx, right, wrong in zip(example.WRONG_SPACINGS, variants["right"], variants["no_hysteresis"]):
        step = example.time_step(dx, paper)
        assert float(wrong.event_time_candidate.sel(event="detachment_starts")) - turning == pytest.approx(0, abs=step)
        assert _event_error(wrong, "pull_off") < -max(5 * step, 15.0)
        assert abs(_event_error(right, "pull_off")) < step
        assert abs(float(wrong.pull_off_force_candidate)) < 0.2 * abs(float(wrong.pull_off_force_exact))
        assert _event_error(wrong, "slip_onset") == _event_error(right, "slip_onset")  # the way in is right


def test_the_script_runs_and_prints_its_findings(tmp_path, monkeypatch, capsys):
    """``python validate.py OUT`` as its ``__main__`` (run in this interpreter, whose imports of the package a fresh
    one would pay again: some 1.5 s of CPU; the script's own imports are only the package's and NumPy)."""
    monkeypatch.setattr(sys, "argv", [str(EXAMPLE / "validate.py"), str(tmp_path)])
    monkeypatch.setattr(sys, "path", list(sys.path))  # (the script puts its own folder first)
    runpy.run_path(str(EXAMPLE / "validate.py"), run_name="__main__")
    lines = capsys.readouterr().out.splitlines()
    table = lines[lines.index(next(line for line in lines if "dt/s" in line)) + 1:][:len(example.SPACINGS)]
    verdicts = [line.split()[-1] for line in table]
    assert verdicts == ["pass"] * len(example.SPACINGS)
    flagged = [line.strip() for line in lines if line.strip().startswith("flagged by:")]
    assert flagged[0] == "flagged by: nothing" and len(flagged) == 4
    assert all(line != "flagged by: nothing" for line in flagged[1:])
    expected = {f"right_dx{dx * 1e6:g}um.csv" for dx in example.SPACINGS} | {
        f"{variant}_dx{dx * 1e6:g}um.csv" for variant in sim.VARIANTS for dx in example.WRONG_SPACINGS}
    assert {path.name for path in tmp_path.glob("*.csv")} == expected
    assert _missing_from(lines, _readme_expected_output()) == []


def _readme_expected_output():
    """The lines of the README's "Expected output", without the ``...`` of lines left out there."""
    readme = (EXAMPLE / "README.md").read_text(encoding="utf-8")
    block = readme.split("## Expected output", 1)[1].split("```", 2)[1]
    return [line for line in block.strip("\n").splitlines() if line.strip() != "..."]


def _missing_from(printed, shown):
    """The lines of ``shown`` that ``printed`` does not hold in that order (a user compares them): the words verbatim,
    integers (spacings, counts) exact, each number with a decimal point or an exponent within one unit of its last
    digit shown (:func:`~mdr_events.io.rounded_text.rounded_text_differences`, as ``results/README.md`` is compared:
    a value at a rounding boundary flips its last digit on another CPU or BLAS, issue 28 item 5)."""
    missing, position = [], 0
    for line in shown:
        found = next((index for index in range(position, len(printed))
                      if not rounded_text_differences(printed[index], line)), None)
        if found is None:
            missing.append(line)
        else:
            position = found + 1
    return missing


#: Printed lines of the script (its right simulator's table, an order and a variant's line of errors) against the
#: README's form of them.
_PRINTED = ["      4     2      602   2.48e-04   1.79e-03   1.21e-03   3.81e-03  pass",
            "  max_error   F_N 0.98  F_x 1.01  A 0.97",
            "    pull-off force -0.00107 N (exact -0.01178 N)"]


@pytest.mark.parametrize(("shown", "missing"), [
    (_PRINTED, False),
    (["      4     2      602   2.49e-04   1.79e-03   1.21e-03   3.81e-03  pass"], False),  # a last digit at .5
    (["  max_error   F_N 0.98  F_x 1.01  A 0.98", "    pull-off force -0.00108 N (exact -0.01177 N)"], False),
    (["      4     2      602   2.50e-04   1.79e-03   1.21e-03   3.81e-03  pass"], True),  # two units off
    (["      4     2      603   2.48e-04   1.79e-03   1.21e-03   3.81e-03  pass"], True),  # a count
    (["  max_error   F_N 0.98  F_x 1.01  A 0.95"], True),
    (["    pull-off force -0.00107 N (exact -0.01178 mN)"], True),  # the words
    (["  l1_error    F_N 0.98  F_x 1.01  A 0.97"], True),
    (list(reversed(_PRINTED)), True),  # the order
    (["      4     2      602   2.48e-04   1.79e-03   1.21e-03   3.81e-03  pass"] * 2, True),  # a line printed once
], ids=["same", "last digit", "last digits", "two units", "count", "order of A", "words", "another line",
        "reversed", "twice"])
def test_the_readme_s_lines_agree_within_their_last_digit(shown, missing):
    """The README's expected output is checked as a user reads it, not to the last bit: a number may differ by one
    unit of the last digit it shows, no more; the words, the integers and the order of the lines are exact."""
    assert bool(_missing_from(_PRINTED, shown)) is missing, _missing_from(_PRINTED, shown)
