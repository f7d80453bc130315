"""The twenty-second hostile round (issue 32): each class of what failed, with the cases that showed it.

The round's cases (the flat punch on a layer in the continuum: faces at and beyond ``a/h = 64``, ``ν = 0.5`` and
0.45 on bonded and frictionless bases, thicknesses from 1e-300 m to 1e300 m, ``Δγ1 ≫ Δγ0``, scenarios A, B and B+,
re-pressing after the recession, through ``simulate``, ``d_crit``, ``critical_angle`` and ``phase_diagram`` and the
CLI; Coulomb's law on a layer in the continuum at one, many, repeated and unordered output times) are listed with
their outcomes in the issue's closing note; what failed is below.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import mdr_events as me
from hostile_checks import cli_one_line, one_line_naming

PAPER = me.Parameters.paper()
#: The face's radius (m): a/h = 64 exactly on h = a/64 (a power of two apart), while exp(ln a) is one ulp above a.
FACE = 1e-3
#: Path angles (degrees) whose scenario-B onsets lie on the recession (past the held face's -Δl₁(a₀)), where the
#: onset is found on a logarithmic scan of the radius from the face down.
RECEDING_ANGLES = np.array([89.0, 89.5])
#: d_crit's bisection and the continuum's event root solve the same relation r(a) = tan α: they agree to ~1e-9 of
#: the depth (measured 6.3e-9 at 89°); 1e-6 leaves room for either root's tolerance while a scan stopped at a node
#: 1.2% of the radius apart (RECESSION_POINTS) is off by far more.
ONSET_RTOL = 1e-6


def _punch_on(thickness: float) -> me.Contact:
    return me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.FlatPunch(FACE), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                      me.FrictionLaw("tau0", tau0=PAPER.tau0), me.Layer(thickness))


# --- V1: a face at a/h = 64 (allowed: the tables' range is closed) refused on the recession: scenario B's d_crit
# with adhesion and phase_diagram raised "a/h=64.00000000000001 is not allowed" (the recession's scan read the
# radius as exp(ln a₀), an ulp above the face). The scan's radii are the face's at most ------------------------------


def test_a_face_at_the_tables_edge_has_its_receding_onsets():
    contact = _punch_on(FACE / 64.0)
    assert FACE / contact.layer.thickness == 64.0 and np.exp(np.log(FACE)) > FACE  # (the case the round found)
    onsets = me.d_crit(RECEDING_ANGLES, contact, "B", adhesion=True)
    run = me.simulate(contact, "B", RECEDING_ANGLES, method="continuum")
    for i, onset in enumerate(onsets):
        kinds = list(run.event_kind.values[i])
        assert onset == pytest.approx(float(run.event_depth.values[i][kinds.index("slip_onset")]), rel=ONSET_RTOL)


def test_the_phase_diagram_at_the_tables_edge_is_the_onsets():
    """Its JKR pull-off onsets are d_crit's, on the recession: below the surface, above the jump-off."""
    contact = _punch_on(FACE / 64.0)
    diagram = me.phase_diagram(contact, RECEDING_ANGLES, "B")
    onsets = diagram["d_crit_jkr"].sel(branch="pull-off").values
    np.testing.assert_array_equal(onsets, me.d_crit(RECEDING_ANGLES, contact, "B", adhesion=True))
    assert np.all((float(diagram["jump_off_depth"]) < onsets) & (onsets < 0.0)), onsets


# --- V2: a flat punch's face far beyond a/h = 64 in the continuum: `simulate --method continuum --flat-punch 1e-3
# --h 1e-300` exited 3, "internal error (ZeroDivisionError)" (ν = 0.45: OverflowError), from h = 1e-20 on; the
# continuum's reach check took the face (the punch's radius at any depth) unchecked against the tables, and the
# recession's scalar factors extrapolated. The reach check refuses it naming the punch, the largest face and the least
# thickness -----


@pytest.mark.parametrize("thickness", [1e-300, 1e-20, np.nextafter(FACE / 64.0, 0.0)])
@pytest.mark.parametrize("nu", [0.5, 0.45])
def test_a_face_beyond_the_tables_is_refused_in_the_continuum_naming_the_layer(thickness, nu):
    contact = dataclasses.replace(_punch_on(thickness), elastomer=me.Elastomer(PAPER.E, nu))
    message = one_line_naming(lambda: me.simulate(contact, "A", 20.0, method="continuum"), "contact.indenter=")
    least = float(message.split("h >= ")[1].split(" m")[0])
    assert least == pytest.approx(FACE / 64.0, rel=1e-5) and "exceeds a/h = 64" in message, message  # (6 digits)


def test_the_cli_refuses_a_face_beyond_the_tables_in_one_line(capsys, tmp_path):
    err = cli_one_line(capsys, ["simulate", "--scenario", "B", "--alpha", "20", "--method", "continuum",
                                "--flat-punch", "1e-3", "--h", "1e-300", "--out", str(tmp_path / "o")])
    assert "contact.indenter=" in err and "exceeds a/h = 64" in err and "h >= " in err, err


# --- V3: grids read before they are counted, where round twenty-one's limits.values_in did not reach. d_crit on a
# layer validated (copied) its angles before the onsets' limits refused them; simulate's angles (~7 copies: 54 MiB
# for 1e6 angles, 5 GB for 1e8 against the 2 GiB limit) and its continuum output times t (~3 copies) are read by the
# motion and the method before the run's case count was checked. simulation_job counts them first ---------

#: Values in the grid, and the least a reading of it allocates (one float per value: the conversion's copy).
GRID = 10**6
ONE_COPY = 8 * GRID
LOW = me.Limits(samples=10, steps=10, memory=2**20)
HALF_SPACE = me.Contact.from_parameters(PAPER)


def _layered() -> me.Contact:
    return me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.Paraboloid(PAPER.R), me.Adhesion(PAPER.dgamma0, PAPER.dgamma1),
                      me.FrictionLaw("tau0", tau0=PAPER.tau0), me.Layer(5e-3))


def _peak_before_refusal(call, values: np.ndarray) -> int:
    """The peak of what ``call(values)`` allocates (tracemalloc; the grid made before) until the limits refuse it."""
    import tracemalloc

    with pytest.raises(me.ResourceLimitError):  # (imports and tables loaded by a first refusal, not measured)
        call(values[:1000])
    tracemalloc.start()
    try:
        with pytest.raises(me.ResourceLimitError):
            call(values)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_d_crit_on_a_layer_counts_its_angles_before_reading_them():
    contact = _layered()
    peak = _peak_before_refusal(lambda angles: me.d_crit(angles, contact, limits=LOW), np.linspace(1.0, 80.0, GRID))
    assert peak < ONE_COPY, f"{peak / 2**20:.1f} MiB before the refusal"


@pytest.mark.parametrize("grid", ["alpha", "t"])
def test_simulate_counts_its_grids_before_reading_them(grid):
    if grid == "alpha":
        peak = _peak_before_refusal(lambda angles: me.simulate(HALF_SPACE, "A", angles, method="continuum", limits=LOW),
                                    np.linspace(1.0, 80.0, GRID))
    else:
        peak = _peak_before_refusal(lambda t: me.simulate(HALF_SPACE, "A", 20.0, method="continuum", t=t, limits=LOW),
                                    np.linspace(0.0, 1e-3, GRID))
    assert peak < ONE_COPY, f"{peak / 2**20:.1f} MiB before the refusal"


# --- V4: simulate on a layer built every case before counting them: simulate(layered, "A", 1e6 angles,
# limits=...) ran check_layer_taken (each case's path, its JKR radius and extent: ~0.1 ms an angle, minutes and
# 0.65 GB) before the run's case count refused it (the half-space counted first). simulation_job counts them first --


@pytest.mark.parametrize("method", ["continuum", "discrete"])
def test_simulate_on_a_layer_counts_its_cases_before_building_them(monkeypatch, method):
    from mdr_events.models import motion

    def built(*args, **kwargs):
        raise AssertionError("the cases were built before the limits refused their count")

    monkeypatch.setattr(motion, "_scenario_cases", built)
    with pytest.raises(me.ResourceLimitError, match="1000 case"):
        me.simulate(_layered(), "A", np.linspace(1.0, 80.0, 1000), method=method, limits=LOW)


# --- V5: a path pressed in at 20°, unloaded back along its loading line, pressed in again and pulled through the
# surface, with Δγ1 >= 5 J/m² (33 Δγ0): the continuum raised "made no progress at t = 3388.2 s after 50 event
# restarts (radius 3.1 mm, positive cap stick, negative cap stick; last event: zone_reaches (negative cap))". The
# second pressing ended an ulp before its corner with a growing span of that ulp: its growth piece, of no length, was
# kept into the pinned span after the corner (AnchorMap.truncate forgot only pieces ending beyond the radius), and its
# value at the edge was the negative cap's target there, which the layout never saw reached. Pieces starting at the
# radius are forgotten now, as the split map did ---------------------------------------------------------------------

#: The held radius is the Δγ0 branch's root at d_max as jkr_contact_radius finds it, the pinned span's normal force
#: the closed form of the held radius, the full slip's force set exactly (eq. (12)): measured equal to the last bit;
#: 1e-9 (ten times the solver's rtol) leaves room for another platform's rounding, while a radius left anywhere else
#: (the Δγ1 branch at -0.3 mm is 4.6 mm) or a force with a spring's zone left out is off by percents.
PINNED_RTOL = 1e-9


def test_a_re_pressed_path_pulled_through_under_a_large_dgamma1_runs():
    dgamma1 = 15.0
    contact = me.Contact(me.Elastomer(PAPER.E, PAPER.nu), me.Paraboloid(PAPER.R), me.Adhesion(PAPER.dgamma0, dgamma1),
                         me.FrictionLaw("tau0", tau0=PAPER.tau0))
    depth = PAPER.d_max
    x = depth / np.tan(np.radians(20.0))
    path = me.Path(np.array([[0.0, 0.0], [x, depth], [0.0, 0.0], [x, depth], [-x, -depth]]), PAPER.v)
    run = me.simulate(contact, path, method="continuum").isel(case=0)
    # the Δγ1 branch meets the held radius a_max at jkr_depth(a_max, Δγ1) = -0.50 mm, beyond the path's -0.3 mm:
    # the radius stays where the pressing left it, no pull-off, and the run reaches the path's end
    a_max = float(me.jkr_contact_radius(depth, contact, PAPER.dgamma0))
    assert float(me.jkr_depth(a_max, contact, dgamma1)) < -depth
    kinds = [kind for kind in run.event_kind.values if isinstance(kind, str)]
    assert "pull_off" not in kinds and kinds[-1] == "path_end", kinds
    end = run.isel(time=int(np.flatnonzero(np.isfinite(run.normal_force.values))[-1]))
    assert float(end.indentation_depth) == pytest.approx(-depth, rel=PINNED_RTOL)
    assert float(end.contact_radius) == pytest.approx(a_max, rel=PINNED_RTOL)
    e_star = PAPER.E / (1.0 - PAPER.nu**2)
    pinned_force = 2.0 * e_star * (a_max * -depth - a_max**3 / (3.0 * PAPER.R))  # eq. (10)'s integral at a held a
    assert float(end.normal_force) == pytest.approx(pinned_force, rel=PINNED_RTOL)
    assert float(end.tangential_force) == pytest.approx(-PAPER.tau0 * np.pi * a_max**2, rel=PINNED_RTOL)  # eq. (12)
