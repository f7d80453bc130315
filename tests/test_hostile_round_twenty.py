"""The twentieth hostile round (issue 32): each class of what failed, with the cases that showed it.

The round's cases (the continuum's quadrature and closed-form spans at extreme ``R``, ``E``, angles, ``d_max``, speeds
and adhesion; paths with coincident and near-coincident waypoints; the flat punch on a layer in both methods; the
layer's thicknesses and Poisson's ratios at the edges of its tables; the rate law's extrema; the joint fit's verdicts
and noises at the ends of their range; the readers with non-finite, hexadecimal, quoted, BOM/CRLF and blank cells;
multi-value and repeated options; interrupts) are listed with their outcomes in the issue's closing note; what failed
is below.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import cli_one_line, one_line_naming

PAPER = me.Parameters.paper()


# --- T1: a Poisson's ratio the half-space takes but a layer does not: `simulate --h 5e-3 --nu -0.99` ran until the
# layer's tables refused "nu=-0.99 is not allowed; allowed: a finite number in [0, 0.5]", not saying the range is the
# layer's (the same option without --h runs). A Contact on a layer of finite thickness refuses it when made ----------


@pytest.mark.parametrize("nu", [-0.99, -1e-12])
def test_a_layer_refuses_a_negative_poisson_ratio_naming_the_layer(nu):
    elastomer = me.Elastomer(PAPER.E, nu)
    message = one_line_naming(
        lambda: me.Contact(elastomer, me.Paraboloid(PAPER.R), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                           me.FrictionLaw("tau0", tau0=PAPER.tau0), me.Layer(5e-3)), f"nu={nu!r}")
    assert "layer h = 0.005 m" in message and "[0, 0.5]" in message and "(-1, 0.5]" in message, message
    # the half-space takes it; replace() onto a layer is refused the same way
    half_space = me.Contact(elastomer, me.Paraboloid(PAPER.R), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                            me.FrictionLaw("tau0", tau0=PAPER.tau0))
    assert half_space.elastomer.nu == nu
    one_line_naming(lambda: half_space.replace(h=5e-3), "layer h = 0.005 m")


@pytest.mark.parametrize("order", [["--h", "5e-3", "--nu", "-0.99"], ["--nu", "-0.99", "--h", "5e-3"]])
def test_the_command_line_names_the_layers_range_of_nu(capsys, tmp_path, order):
    err = cli_one_line(capsys, ["simulate", "--scenario", "A", "--alpha", "20", "--method", "continuum", *order,
                                "--out", str(tmp_path / "o")])
    assert "nu=-0.99 is not allowed on layer h = 0.005 m" in err and "the half-space" in err, err
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


# --- T2: the joint fit's noise on the command line: "allowed: None or a finite number from 1.5e-154 ..." (the API's
# None: on the command line a noise is estimated by leaving --noise out) ------------------------------------------


@pytest.mark.parametrize("noise", ["-1", "0", "nan", "1e155"])
def test_the_joint_fits_noise_message_speaks_the_command_lines_words(capsys, tmp_path, noise):
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    for path in (a, b):
        path.write_text("time,normal_force\n0,0\n10,1e-3\n20,0\n")
    err = cli_one_line(capsys, ["fit", str(a), str(b), "--scenario", "A", "--alpha", "20", "--adhesion-law", "rate",
                                "--v-ref", "1e-6", "--rate-exponent", "0.6", "--free", "v_ref", "n",
                                "--speeds", "1e-6", "2e-6", "--noise", f"normal_force={noise}",
                                "--out", str(tmp_path / "o")])
    assert "the noise of normal_force (--noise, [fit] noise)" in err and "None" not in err, err
    assert "allowed: a finite number from" in err, err


# --- T3: the covariance s² (JᵀJ)⁻¹ overflowed at the large end of the joint fit's noises (1e154 N, inside its range:
# "overflow encountered in multiply", an internal error with warnings as errors); its standard errors are products of
# square roots, s (JᵀJ)^(-1/2), finite where the covariance is not -------------------------------------------------

#: A variance scale s² near the double range's top (a noise of ~1e154 N squared).
HUGE_VARIANCE = 1e308


def test_the_standard_errors_do_not_overflow_with_the_noise():
    """A diagonal Jacobian ``diag(j)`` has standard errors ``s / j`` (closed form) and no correlation; at
    ``s² = 1e308`` and ``j = 1e-3`` the covariance ``s²/j²`` is beyond the doubles, the standard errors (1e157) are
    not: the same as at ``s² = 1`` times ``s``, to rounding (a few ulps: the square roots' products)."""
    from mdr_events.analysis.fit_diagnostics import Identifiability, identifiability_of

    jacobian = np.array([[1e-3, 0.0], [0.0, 2e-3], [0.0, 0.0]])
    theta, lower, upper = np.zeros(2), np.full(2, -np.inf), np.full(2, np.inf)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, error, _, verdicts, correlation = identifiability_of(jacobian, theta, lower, upper, HUGE_VARIANCE)
        _, unit_error, _, _, unit_correlation = identifiability_of(jacobian, theta, lower, upper, 1.0)
    np.testing.assert_allclose(unit_error, [1e3, 5e2], rtol=1e-15)
    np.testing.assert_allclose(error, np.sqrt(HUGE_VARIANCE) * unit_error, rtol=1e-15)
    np.testing.assert_array_equal(correlation, unit_correlation)
    np.testing.assert_array_equal(correlation, np.eye(2))
    assert verdicts == [Identifiability.POORLY_DETERMINED] * 2  # (standard errors of 1e157 in scaled units)


# --- T4: a path with a zero-length segment: "waypoints 0 and 1 coincide; consecutive waypoints must differ" named
# neither the value nor what is allowed in the package's form (near-coincident ones were: "... are 1e-18 m apart;
# allowed: ...") --------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("waypoints, named", [
    ([(0.0, 0.0), (0.0, 0.0)], "waypoints[1]=(0.0, 0.0)"),
    ([(0.0, 0.0), (0.0, 3e-4), (0.0, 3e-4), (1e-4, 0.0)], "waypoints[2]=(0.0, 0.0003)"),
])
def test_a_zero_length_segment_is_named_with_its_value(waypoints, named):
    message = one_line_naming(lambda: me.Path(waypoints, 1e-6), named)
    assert "coincides with waypoints[" in message, message


# --- T5: long runs said nothing until their files were written (round nineteen's leftovers, measured again here:
# Coulomb's law under the rate law in the continuum 12.6 s CPU / 58 s on the shared machine, Coulomb's law with
# adhesion on a layer 14.8 s / 63 s, the rate law's phase diagram of B at two speeds over a minute): a line on stderr
# after FIRST_AFTER seconds of silence and every EVERY seconds after -------------------------------------------------


@pytest.mark.parametrize("verb", [
    ["simulate", "--scenario", "A", "--alpha", "20", "--method", "continuum"],
    ["phase-diagram", "--scenario", "A"],
])
def test_a_long_run_says_it_still_runs(capsys, tmp_path, monkeypatch, verb, without_drawing):
    """With the first line due at once, the run's stderr has it and its stdout the files, exit 0 (a run of ~0.5 s
    here: what the line is for, a run past FIRST_AFTER, would cost the suite a minute)."""
    from mdr_events.app import heartbeat
    from mdr_events.app.cli import main

    monkeypatch.setattr(heartbeat, "FIRST_AFTER", 0.0)
    assert main([*verb, "--out", str(tmp_path / "o")]) == 0
    captured = capsys.readouterr()
    assert f"{verb[0]} (" in captured.err and ": still running after 0 s" in captured.err, captured.err
    assert str(tmp_path / "o") in captured.out


def test_a_short_run_says_nothing_more():
    """The line is due after FIRST_AFTER seconds: a block that ends before says nothing, and the thread ends with
    it (no line after the block)."""
    import threading
    import time

    from mdr_events.app.heartbeat import EVERY, FIRST_AFTER, heartbeat

    assert FIRST_AFTER >= 5.0 and EVERY >= FIRST_AFTER  # (quick runs, about a second, stay silent)
    lines = []
    with heartbeat(lines.append, "x"):
        pass
    time.sleep(0.05)
    assert lines == [] and not any(t.name == "mdr-events heartbeat" for t in threading.enumerate())


# --- T6: a power law near the cone (n = 1.0000001, 1.001): its slip onset lies beyond or near the double range's top
# ((3 slope/κc)^(1/(2n − 2))), and the phase diagram's root search, depth and plot overflowed with RuntimeWarnings
# (an internal error with warnings as errors); the onset is +inf there ("never slides"), as where no root exists ---


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("n", [1.0000001, 1.001])
def test_a_power_law_near_the_cone_has_a_phase_diagram_without_warnings(capsys, tmp_path, scenario, n):
    from mdr_events.app.cli import main

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert main(["phase-diagram", "--scenario", scenario, "--power-law", "1e-3", repr(n),
                     "--out", str(tmp_path)]) == 0, capsys.readouterr().err
        diagram = me.phase_diagram(PAPER, scenario=scenario, profile=me.PowerLaw(1e-3, n))
    for name in ("d_crit_hertz", "d_crit_jkr"):  # (an onset depth or +inf; B's "+" branch may be -inf below)
        depths = diagram[name].values
        assert not np.any(np.isnan(depths)), name
        assert scenario == "B" or np.all(depths >= 0.0), name
    assert (tmp_path / f"phase_diagram_{scenario}.png").is_file()


# --- T7: a simulation of 3000 angles (within the limits) drew a legend of 600 rows that collapsed its panels:
# matplotlib's "constrained_layout not applied" UserWarnings on stderr; the legend names LEGEND_CASES of them -------


def test_a_simulation_of_many_cases_draws_its_figure_without_warnings():
    """Twice LEGEND_CASES and one cases (one run's copies; 300 took 3 s of CPU plotting the same legend): no
    warning, and the legend names LEGEND_CASES cases, the first and the last among them (the capped legend is the
    same whatever the count, the 300 cases' overflow of the figure, matplotlib's "constrained_layout not applied",
    came from naming them all; without the cap the count fails)."""
    import xarray as xr

    from mdr_events.plotting.figures import LEGEND_CASES, plot_simulation

    run = me.simulate(PAPER, "A", [20.0], method="continuum")
    cases = 2 * LEGEND_CASES + 1
    many = xr.concat([run.assign_coords(alpha=[20.0 + 1e-3 * i]) for i in range(cases)], dim="alpha")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        figure = plot_simulation(many)
        figure.canvas.draw()  # (the layout runs when drawn)
    labels = [text.get_text() for legend in figure.legends for text in legend.get_texts()]
    last = f"α = {20.0 + 1e-3 * (cases - 1):g}°"
    assert len(labels) == LEGEND_CASES and labels[0].startswith("α = 20") and labels[-1].startswith(last)


def test_the_line_counts_computing_not_waiting(monkeypatch):
    """A block that waits (a process starved of a core on a loaded machine: wall time passing, no CPU time) says
    nothing, so that a quick run's output does not depend on the machine's load; one that computes does."""
    import time

    from mdr_events.app import heartbeat

    monkeypatch.setattr(heartbeat, "FIRST_AFTER", 0.3)
    monkeypatch.setattr(heartbeat, "POLL", 0.05)
    waited, computed = [], []
    with heartbeat.heartbeat(waited.append, "x"):
        time.sleep(0.8)
    with heartbeat.heartbeat(computed.append, "x"):
        end = time.process_time() + 0.6
        while time.process_time() < end:
            pass
    assert waited == [] and len(computed) >= 1, (waited, computed)
