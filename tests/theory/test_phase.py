import math

import numpy as np
import pytest
import xarray as xr
from scipy import optimize

import mdr_events as me
from mdr_events.plotting.figures import plot_phase_diagram, save_figure

# ----------------------------------------------------------------------------
# The model's statements in plain math, independent of mdr_events.symbolic / analytic: the
# effective moduli next to (5), (6), the critical shift (13), the JKR depth (9) and its stable
# branch, the Hertz radius (16). The phase diagram's values are checked against these.


def _moduli(p):
    """(E*, G*) from E and ν: E* = E/(1 − ν²), G* = 4G/(2 − ν), G = E/(2(1 + ν))."""
    shear = p.E / (2.0 * (1.0 + p.nu))
    return p.E / (1.0 - p.nu**2), 4.0 * shear / (2.0 - p.nu)


def _shift(a, p):
    """ū(a) = π a τ0 / (2 G*), eq. (13)."""
    return math.pi * a * p.tau0 / (2.0 * _moduli(p)[1])


def _jkr_depth(a, p, dgamma):
    """d(a) = a²/R − sqrt(2π a Δγ / E*), eq. (9)."""
    return a * a / p.R - math.sqrt(2.0 * math.pi * a * dgamma / _moduli(p)[0])


def _jump_off_radius(p, dgamma):
    """∂d/∂a = 0 of (9): a³ = π Δγ R² / (8 E*); the stable branch is a above it."""
    return (math.pi * dgamma * p.R**2 / (8.0 * _moduli(p)[0])) ** (1.0 / 3.0)


def _jkr_radius(d, p, dgamma):
    """Contact radius at depth d on the stable branch of (9), by bracketing (brentq)."""
    lo = _jump_off_radius(p, dgamma)
    assert _jkr_depth(lo, p, dgamma) <= d, "no contact at this depth"
    hi = 2.0 * lo
    while _jkr_depth(hi, p, dgamma) < d:
        hi *= 2.0
    return optimize.brentq(lambda a: _jkr_depth(a, p, dgamma) - d, lo, hi, xtol=1e-300, rtol=1e-15)


def _tan(alpha):
    return math.tan(math.radians(alpha))


def _check_slip_onset(alpha, depths, travel, radius, p):
    """At each interior angle, the path's tangential travel at the returned depth equals ū(a)."""
    for angle, d in zip(alpha, depths):
        if 0.0 < angle < 90.0 and np.isfinite(d):
            assert travel(d) / _tan(angle) == pytest.approx(_shift(radius(d), p), rel=1e-9), angle


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_phase_diagram_schema_and_values(paper, scenario):
    """The dataset's labels, provenance and, above all, its numbers.

    The values are checked against the slip-onset statements written out in plain math above
    (not against :func:`mdr_events.d_crit`, which the dataset wraps): on the path (14) or (19)
    the tangential travel at ``d_crit`` equals ``ū(a)`` with the Hertz radius ``sqrt(R d)`` or
    the JKR radius of (9) on the right branch (``Δγ0`` in, ``Δγ1`` out). It fails when a relation
    of the derivation, the root choice (unstable branch, wrong root of (20)), the work of adhesion
    of a branch, the ``branch`` order, the ±inf encoding of "never slides", a critical angle or
    the jump-off depth is wrong, and when a variable loses its ``units``/``long_name``.
    """
    alpha = np.linspace(0, 90, 91)
    ds = me.phase_diagram(paper, alpha, scenario=scenario)
    assert ds["alpha"].attrs["units"] == "degree"
    np.testing.assert_array_equal(ds["alpha"].values, alpha)
    for name, var in ds.variables.items():
        assert var.attrs.get("units") and var.attrs.get("long_name"), name
    for name in ("E", "nu", "R", "tau0", "dgamma0", "dgamma1", "d_max", "v"):
        assert ds.attrs[f"param_{name}"] == getattr(paper, name)
    assert ds.attrs["program_version"] == me.__version__
    assert ds.attrs["doi"] == me.DOI
    p, d_max = paper, paper.d_max
    assert float(ds["d_max"]) == d_max
    hertz = lambda d: math.sqrt(p.R * d)  # noqa: E731  (16)
    if scenario == "A":
        assert ds["d_crit_jkr"].dims == ("alpha",) and ds["d_crit_hertz"].dims == ("alpha",)
        for key, radius in (("hertz", hertz), ("jkr", lambda d: _jkr_radius(d, p, p.dgamma0))):
            values = ds[f"d_crit_{key}"].values
            assert values[0] == 0.0 and values[-1] == np.inf  # α = 0: slides at once; 90°: never
            assert np.all(np.isfinite(values[1:-1])) and np.all(values[1:-1] > 0)
            _check_slip_onset(alpha, values, lambda d: d, radius, p)  # (14): x = d / tan α
            # the critical angle: d_crit(α_c) = d_max, i.e. tan α_c = d_max / ū(a(d_max))
            expected = math.degrees(math.atan(d_max / _shift(radius(d_max), p)))
            angle = float(ds[f"critical_angle_{key}"])
            assert angle == pytest.approx(expected, rel=1e-9)
            assert np.all((values < d_max) == (alpha < angle))  # slides during indentation below α_c
        # the paper's two numbers (section 4): 23.59° without, 22.87° with adhesion
        assert float(ds["critical_angle_hertz"]) == pytest.approx(23.59, abs=0.02)
        assert float(ds["critical_angle_jkr"]) == pytest.approx(22.87, abs=0.02)
    else:
        assert ds["d_crit_jkr"].dims == ("branch", "alpha")
        assert list(ds["branch"].values) == ["pull-off", "indentation"]
        pull = {key: ds[f"d_crit_{key}"].sel(branch="pull-off").values for key in ("hertz", "jkr")}
        push = {key: ds[f"d_crit_{key}"].sel(branch="indentation").values for key in ("hertz", "jkr")}
        for values, never in ((pull["hertz"], -np.inf), (pull["jkr"], -np.inf),
                              (push["hertz"], np.inf), (push["jkr"], np.inf)):
            assert values[0] == d_max and values[-1] == never  # α = 0: at once; 90°: never
        # (19)-(20), no adhesion: (d_max − d)/tan α = ū(sqrt(R d)) below d_max, (d − d_max)/tan α above
        assert np.all(np.isfinite(pull["hertz"][:-1])) and np.all(pull["hertz"][1:-1] < d_max)
        assert np.all(pull["hertz"][1:-1] > 0) and np.all(push["hertz"][1:-1] > d_max)
        _check_slip_onset(alpha, pull["hertz"], lambda d: d_max - d, hertz, p)
        _check_slip_onset(alpha, push["hertz"], lambda d: d - d_max, hertz, p)
        # (21), adhesion: Δγ1 radius on the way out, Δγ0 radius on the way in
        assert np.all(push["jkr"][1:-1] > d_max)
        _check_slip_onset(alpha, push["jkr"], lambda d: d - d_max, lambda d: _jkr_radius(d, p, p.dgamma0), p)
        _check_slip_onset(alpha, pull["jkr"], lambda d: d_max - d, lambda d: _jkr_radius(d, p, p.dgamma1), p)
        # pulling out, a shrinks along the stable branch down to the jump-off point (a_j, d_j) and
        # the mismatch (d_max − d)/tan α − ū(a) grows monotonically: no spring slides before the
        # jump-off (d_crit = −inf) exactly when the mismatch is still negative there
        a_j = _jump_off_radius(p, p.dgamma1)
        d_j = _jkr_depth(a_j, p, p.dgamma1)
        assert float(ds["jump_off_depth"]) == pytest.approx(d_j, rel=1e-12)
        angle = math.degrees(math.atan((d_max - d_j) / _shift(a_j, p)))
        assert float(ds["critical_angle_jkr"]) == pytest.approx(angle, rel=1e-9)
        assert float(ds["critical_angle_hertz"]) == 90.0  # the Hertz radius shrinks to 0: slip first
        separates = pull["jkr"] == -np.inf
        assert np.all(separates == (alpha > angle)) and 0 < separates.sum() < alpha.size - 1
        assert np.all(pull["jkr"][~separates] >= d_j)


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_netcdf_round_trip_is_identical(paper, scenario, tmp_path):
    ds = me.phase_diagram(paper, scenario=scenario)
    path = me.write_netcdf(ds, tmp_path / "sub" / "pd.nc")
    back = me.open_result(path)
    xr.testing.assert_identical(back, ds)
    assert [p.name for p in path.parent.iterdir()] == ["pd.nc"], "no temporary file left behind"
    assert me.Parameters.from_attrs(back.attrs) == paper


def test_open_result_rejects_foreign_files(tmp_path):
    path = tmp_path / "foreign.nc"
    xr.Dataset({"x": ("t", np.arange(3.0))}).to_netcdf(path, engine="scipy")
    with pytest.raises(ValueError, match="program"):
        me.open_result(path)


def test_failed_write_leaves_no_file(paper, tmp_path):
    """A write that the netCDF backend refuses leaves no file behind and an earlier file intact.

    A dict attribute is not netCDF-serialisable: xarray raises ``TypeError`` ("Invalid value for
    attr ...", named in a ``ValueError`` of the writer's) inside the writer, after :func:`mdr_events.io.files.atomic_write` has created its
    temporary file. Fails if the temporary file is not removed, if the target is written or
    truncated before the writer succeeds, if the error is swallowed, or if something else goes
    wrong first (a ``NameError``, a ``ValueError`` ... would not match).
    """
    ds = me.phase_diagram(paper, [10.0, 20.0])
    ds.attrs["fine"] = 1  # an int attribute is netCDF-safe
    ds["d_crit_hertz"].attrs["bad"] = {"not": "netcdf"}
    refused = r"dataset cannot be written as netCDF-3 \(TypeError: Invalid value for attr 'bad': \{'not': 'netcdf'\}"
    with pytest.raises(ValueError, match=refused):
        me.write_netcdf(ds, tmp_path / "x.nc")
    assert list(tmp_path.iterdir()) == []
    good = me.write_netcdf(me.phase_diagram(paper, [10.0]), tmp_path / "x.nc")
    before = good.read_bytes()
    with pytest.raises(ValueError, match=refused):
        me.write_netcdf(ds, good)
    assert list(tmp_path.iterdir()) == [good] and good.read_bytes() == before


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_figures_are_drawn_and_deterministic(paper, scenario, tmp_path):
    ds = me.phase_diagram(paper, scenario=scenario)
    paths = []
    for name in ("one.png", "two.png"):
        ax = plot_phase_diagram(ds)
        labels = {t.get_text() for t in ax.texts}
        expected = {"sliding-ind", "no-sliding-ind"} | ({"sliding-det", "no-sliding-det"} if scenario == "B" else set())
        assert expected <= labels
        assert ax.get_xlabel().endswith("(°)") and "(mm)" in ax.get_ylabel()
        paths.append(save_figure(ax.figure, tmp_path / name))
    assert paths[0].read_bytes() == paths[1].read_bytes()


def test_same_input_same_bytes(paper, tmp_path):
    first = me.write_netcdf(me.phase_diagram(paper, scenario="B"), tmp_path / "a.nc").read_bytes()
    second = me.write_netcdf(me.phase_diagram(paper, scenario="B"), tmp_path / "b.nc").read_bytes()
    assert first == second


def test_phase_diagram_of_another_friction_law():
    """Scenario A without adhesion for Coulomb's and the combined law: mindlin's onsets (+inf where no spring
    slides while indenting); the adhesive variables Coulomb's alone the same (the compressed zone's onset), the
    combined law's the same to its bisection (theory.combined_onset: without adhesion the centre's spring, (17) at α');
    the law named; a table's scenario B refused."""
    hertz = me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)
    angles = np.array([10.0, 40.0, 70.0, 90.0])
    for friction in (me.FrictionLaw("coulomb", mu=0.3), me.FrictionLaw("tau0+coulomb", mu=0.2)):
        ds = me.phase_diagram(hertz, angles, friction=friction)
        expected = me.mindlin.d_crit_A(angles, friction, hertz)
        np.testing.assert_array_equal(ds["d_crit_hertz"].values, np.where(np.isnan(expected), np.inf, expected))
        if friction.law == "coulomb":
            np.testing.assert_array_equal(ds["d_crit_jkr"].values, ds["d_crit_hertz"].values)
            assert float(ds["critical_angle_jkr"]) == float(ds["critical_angle_hertz"])
        else:  # (the bisection's 2⁻⁶⁰ of d_max and of 90°, and the roots' rounding)
            indenting = np.where(ds["d_crit_hertz"].values <= hertz.d_max, ds["d_crit_hertz"].values, np.inf)
            np.testing.assert_allclose(ds["d_crit_jkr"].values, indenting, rtol=0, atol=1e-13 * hertz.d_max)
            assert float(ds["critical_angle_jkr"]) == pytest.approx(float(ds["critical_angle_hertz"]), rel=1e-12)
        assert float(ds["critical_angle_hertz"]) == me.mindlin.critical_angle_A(friction, hertz)
        assert ds.attrs["friction_law"] == friction.law
    r = np.linspace(0.0, 4e-3, 41)
    with pytest.raises(ValueError, match=r"scenario='B' is not allowed for the phase diagram of a tabulated profile"):
        me.phase_diagram(hertz, angles, scenario="B", profile=me.TabulatedProfile(r, r**2 / 0.06))
    with pytest.raises(ValueError, match=r"friction='coulomb' is not allowed with a tabulated profile's phase diagram"):
        me.phase_diagram(hertz, angles, profile=me.TabulatedProfile(r, r**2 / 0.06),
                         friction=me.FrictionLaw("coulomb", mu=0.3))


def test_phase_diagram_of_a_table_of_the_paraboloid():
    """A table of the paper's paraboloid (161 points) gives Fig. 9a to its interpolation error: the depths to 1e-5 of
    d_max (g is off by 4e-6 of its largest value), the angles to 1e-5."""
    paper = me.Parameters.paper()
    r = np.linspace(0.0, 4e-3, 161)
    table = me.TabulatedProfile(r, r**2 / (2 * paper.R))
    angles = np.array([5.0, 15.0, 22.0, 90.0])
    ds, reference = me.phase_diagram(paper, angles, profile=table), me.phase_diagram(paper, angles)
    for name in ("d_crit_hertz", "d_crit_jkr"):
        np.testing.assert_allclose(ds[name].values, reference[name].values, rtol=0, atol=1e-5 * paper.d_max)
    for name in ("critical_angle_hertz", "critical_angle_jkr"):
        np.testing.assert_allclose(ds[name].values, reference[name].values, rtol=1e-5)
    assert ds.attrs["profile"].startswith("tabulated profile")


def test_phase_diagram_b_of_another_friction_law():
    hertz = me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)
    friction = me.FrictionLaw("tau0+coulomb", mu=0.2)
    angles = np.array([10.0, 50.0, 89.0])
    ds = me.phase_diagram(hertz, angles, scenario="B", friction=friction)
    np.testing.assert_array_equal(ds["d_crit_hertz"].sel(branch="pull-off").values,
                                  me.mindlin.d_crit_B(angles, friction, hertz))
    np.testing.assert_array_equal(ds["d_crit_hertz"].sel(branch="indentation").values,
                                  me.mindlin.d_crit_B_indentation(angles, friction, hertz))
    np.testing.assert_array_equal(ds["d_crit_jkr"].sel(branch="pull-off").values,
                                  me.mindlin.d_crit_B(angles, friction, hertz, adhesion=True))
    np.testing.assert_array_equal(ds["d_crit_jkr"].sel(branch="indentation").values,
                                  me.mindlin.d_crit_B_indentation(angles, friction, hertz, adhesion=True))
    assert not np.any(np.isnan(ds["d_crit_jkr"].values)) and ds.attrs["friction_law"] == "tau0+coulomb"
    me.plotting.plot_phase_diagram(ds)


def test_a_law_with_mu_zero_draws_the_papers_diagram_for_a_punch():
    """tau0+coulomb with μ = 0 is the paper's law: scenario B's non-adhesive curves and critical angle of a flat punch
    are the τ0 diagram's (a punch comes off whole at the surface: its angle is not 90°)."""
    hertz = me.Parameters.paper().replace(dgamma0=0.0, dgamma1=0.0)
    punch = me.FlatPunch(1e-3)
    angles = np.array([10.0, 40.0, 70.0])
    law = me.phase_diagram(hertz, angles, scenario="B", profile=punch, friction=me.FrictionLaw("tau0+coulomb", mu=0.0))
    paper = me.phase_diagram(hertz, angles, scenario="B", profile=punch)
    np.testing.assert_allclose(law["d_crit_hertz"].values, paper["d_crit_hertz"].values, rtol=1e-14)
    assert float(law["critical_angle_hertz"]) == pytest.approx(float(paper["critical_angle_hertz"]), rel=1e-14)
    assert float(law["critical_angle_hertz"]) < 90.0


@pytest.mark.parametrize("name", ["A", "B"])
def test_a_scenario_given_where_the_angles_go_points_to_scenario(name):
    """phase_diagram(contact, "B") read "B" as the angles: the one line now says to write scenario="B"."""
    with pytest.raises(TypeError, match=f"alpha='{name}' is not allowed.*scenario='{name}'"):
        me.phase_diagram(me.Contact.paper(), name)


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("preset", [True, False])
def test_the_assembled_phase_diagram_is_the_one_xarray_merges(scenario, preset, monkeypatch, tmp_path):
    """The paper's phase diagram is laid out by io.datasets.assembled, without xarray's merge (issue 28): the dataset
    (its variables, their order, classes and types, the dimensions' order, the coordinates and their indexes, the
    attributes) and the netCDF file written of it are those of xarray.Dataset(variables, coords=coords)."""
    from mdr_events.io.files import write_netcdf
    from mdr_events.theory import phase

    params = me.Parameters.paper() if preset else me.Parameters.paper().replace(tau0=30e3)
    angles = np.linspace(0.0, 90.0, 181)
    fast = me.phase_diagram(params, angles, scenario=scenario)
    monkeypatch.setattr(phase, "assembled", lambda data, coords: xr.Dataset(data, coords=coords))
    merged = me.phase_diagram(params, angles, scenario=scenario)
    xr.testing.assert_identical(fast, merged)
    assert list(fast.variables) == list(merged.variables) and list(fast.dims) == list(merged.dims)
    assert set(fast.coords) == set(merged.coords) and list(fast.xindexes) == list(merged.xindexes)
    assert all(fast.xindexes[name].equals(merged.xindexes[name]) for name in merged.xindexes)
    assert [(type(variable), variable.dtype) for variable in fast.variables.values()] == \
        [(type(variable), variable.dtype) for variable in merged.variables.values()]
    assert fast.attrs == merged.attrs and list(fast.attrs) == list(merged.attrs)
    write_netcdf(fast, tmp_path / "fast.nc")
    write_netcdf(merged, tmp_path / "merged.nc")
    assert (tmp_path / "fast.nc").read_bytes() == (tmp_path / "merged.nc").read_bytes()
