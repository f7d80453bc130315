import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.plotting import plot_phase_diagram, save_figure


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_phase_diagram_schema_and_values(paper, scenario):
    alpha = np.linspace(0, 90, 91)
    ds = me.phase_diagram(paper, alpha, scenario=scenario)
    assert ds["alpha"].attrs["units"] == "degree"
    for name, var in ds.variables.items():
        assert var.attrs.get("units") and var.attrs.get("long_name"), name
    for name in ("E", "nu", "R", "tau0", "dgamma0", "dgamma1", "d_max", "v"):
        assert ds.attrs[f"param_{name}"] == getattr(paper, name)
    assert ds.attrs["program_version"] == me.__version__
    assert ds.attrs["doi"] == me.DOI
    if scenario == "A":
        assert ds["d_crit_jkr"].dims == ("alpha",)
        np.testing.assert_array_equal(ds["d_crit_hertz"].values, me.d_crit(alpha, paper, "A"))
    else:
        assert ds["d_crit_jkr"].dims == ("branch", "alpha")
        assert list(ds["branch"].values) == ["pull-off", "indentation"]
        np.testing.assert_array_equal(ds["d_crit_jkr"].sel(branch="indentation").values,
                                      me.d_crit(alpha, paper, "B", adhesion=True, branch="indentation"))
    assert float(ds["critical_angle_jkr"]) == me.critical_angle(paper, scenario, adhesion=True)


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
    ds = me.phase_diagram(paper, [10.0, 20.0])
    ds.attrs["bad"] = 1  # fine
    ds["d_crit_hertz"].attrs["bad"] = {"not": "netcdf"}
    with pytest.raises(Exception):
        me.write_netcdf(ds, tmp_path / "x.nc")
    assert list(tmp_path.iterdir()) == []


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
