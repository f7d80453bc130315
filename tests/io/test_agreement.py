"""Each kind of accuracy against its closed form, on small datasets made for it; the rounded-text comparison."""

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.analysis.fit_accuracy import estimate_share, jacobian_share, spread_share
from mdr_events.io.agreement import (ROUND_OFF, ExtremumTime, Integrated, Quotient, RootFound, RoundOff,
                                     accuracy_of, register_accuracy, result_differences, rounded_text_differences,
                                     tolerance_of)

RESULTS = Path(__file__).resolve().parents[2] / "results"
CONTENT = "test of the agreement module"
#: The sampled maximum: F(t) = PEAK - CURVATURE (t - T0)^2 / 2, its time T0, on a grid of SPACING.
PEAK, CURVATURE, T0, SPACING = 2.0, 0.5, 3.3, 0.1
SEARCH_SHARE = 1e-12


def dataset(**attrs) -> xr.Dataset:
    time = np.arange(0.0, 10.0 + SPACING / 2, SPACING)
    force = np.stack([PEAK - 0.5 * CURVATURE * (time - T0) ** 2, 1.0 - np.abs(time - T0)])  # smooth; a kink
    area = np.stack([np.full(time.size, 4.0), np.full(time.size, 2.0)])
    data = {"force": (("case", "time"), force), "area": (("case", "time"), area),
            "stress": (("case", "time"), force / area),
            "force_max": (("case",), np.array([PEAK, 1.0])),
            "force_max_time": (("case",), np.array([T0, T0])),
            "depth": (("case", "time"), np.stack([time, time]) * 1e-3)}
    return xr.Dataset(data, coords={"time": time}, attrs={"content": CONTENT, "rtol": 1e-10, "radius_rtol": 1e-14,
                                                          **attrs})


register_accuracy(CONTENT, {"force": Integrated(), "area": RootFound(), "stress": Quotient("force", "area"),
                            "force_max": Integrated(scale_of="force"), "time": RoundOff(), "depth": RoundOff(),
                            "force_max_time": ExtremumTime("force_max", "force", search_share=SEARCH_SHARE)})


def test_round_off_is_its_ulps_of_the_largest_magnitude_plus_the_rounding_of_the_path():
    """Without a time dimension exactly ROUND_OFF of the largest magnitude; along time plus ROUND_OFF max|t| |dQ/dt|
    (here dQ/dt = 1e-3 m/s, t up to 10 s)."""
    ds = dataset()
    assert float(RoundOff().tolerance(ds, "force_max_time")) == ROUND_OFF * T0
    along = RoundOff().tolerance(ds, "depth")
    assert np.allclose(along, ROUND_OFF * 1e-2 + ROUND_OFF * 10.0 * 1e-3, rtol=1e-9)


def test_integrated_and_root_found_are_their_attributes_share_of_the_scale():
    ds = dataset()
    largest = np.max(np.abs(ds["force"].values))
    steepest = np.max(np.abs(np.diff(ds["force"].values) / SPACING))
    tolerance = np.asarray(Integrated().tolerance(ds, "force"))
    assert tolerance.max() == pytest.approx((1e-10 + ROUND_OFF) * largest + ROUND_OFF * 10.0 * steepest, rel=1e-9)
    assert float(Integrated(scale_of="force").tolerance(ds, "force_max")) == pytest.approx((1e-10 + ROUND_OFF) * largest)
    assert np.allclose(RootFound().tolerance(ds, "area"), (1e-14 + ROUND_OFF) * 4.0)
    with pytest.raises(ValueError, match="force.*'missing_rtol'"):
        Integrated(attribute="missing_rtol").tolerance(ds, "force")


def test_a_quotient_carries_both_tolerances():
    """tol(n/m) = tol(n)/|m| + |q| tol(m)/|m|, element by element; a change of n by its tolerance stays inside."""
    ds = dataset()
    expected = (tolerance_of(ds, "force") + np.abs(ds["stress"].values) * tolerance_of(ds, "area")) / ds["area"].values
    assert np.allclose(Quotient("force", "area").tolerance(ds, "stress"), expected)
    moved = ds.copy(deep=True)
    moved["stress"] = (moved["force"] + 0.9 * tolerance_of(ds, "force")) / moved["area"]
    assert result_differences(moved, ds) == []


def test_the_time_of_a_smooth_maximum_is_known_to_the_square_root_of_its_values_accuracy():
    """F'' = -CURVATURE: δt = sqrt(2 tol(F_max) / CURVATURE) (plus the search's share); a kink's time is sharp."""
    ds = dataset()
    tolerance = ExtremumTime("force_max", "force", search_share=SEARCH_SHARE).tolerance(ds, "force_max_time")
    value_tolerance = (1e-10 + ROUND_OFF) * np.max(np.abs(ds["force"].values))
    search = SEARCH_SHARE * 10.0
    assert tolerance[0] == pytest.approx(math.sqrt(2 * value_tolerance / CURVATURE) + search, rel=1e-6)
    # the kink: slopes +1 and -1 on both sides of T0 = 3.3, on the grid: F'' = -2/SPACING
    assert tolerance[1] == pytest.approx(math.sqrt(2 * value_tolerance / (2 / SPACING)) + search, rel=1e-6)
    assert tolerance[1] < tolerance[0] / 4
    moved = ds.copy(deep=True)
    moved["force_max_time"].values[0] += 0.9 * tolerance[0]
    assert result_differences(moved, ds) == []
    moved["force_max_time"].values[0] += 0.2 * tolerance[0]
    assert result_differences(moved, ds)


def test_at_the_end_of_the_samples_the_time_is_the_search_s_alone():
    ds = dataset()
    ds["force"].values[0, -2:] = np.nan
    ds["force_max_time"].values[0] = ds["time"].values[-1]
    tolerance = ExtremumTime("force_max", "force", search_share=SEARCH_SHARE).tolerance(ds, "force_max_time")
    assert tolerance[0] == SEARCH_SHARE * 10.0


def test_an_undeclared_variable_is_an_error_naming_it():
    ds = dataset().assign(extra=(("case",), np.zeros(2)))
    with pytest.raises(ValueError, match="'extra'.*no declared accuracy"):
        accuracy_of(ds, "extra")
    with pytest.raises(ValueError, match="'extra'"):
        result_differences(ds, ds)


def test_float_attributes_within_round_off_strings_and_integers_exactly():
    ds = dataset(scale=2.0, label="a", count=np.int32(3))
    assert result_differences(ds.assign_attrs(scale=2.0 * (1 + 10 * np.finfo(float).eps)), ds) == []
    assert result_differences(ds.assign_attrs(scale=2.0 * (1 + 1e-12)), ds)
    assert result_differences(ds.assign_attrs(label="b"), ds)
    assert result_differences(ds.assign_attrs(count=np.int32(4)), ds)


@pytest.mark.parametrize("mine, theirs, agree", [
    ("| 21.2058 mN |", "| 21.2057 mN |", True),   # one unit of the last digit: a rounding boundary
    ("| 21.2059 mN |", "| 21.2057 mN |", False),
    ("| 1.00e-04 |", "| 9.99e-05 |", True),        # the larger unit of the two
    ("| 1.45e-03 of A_max |", "| 1.47e-03 of A_max |", False),
    ("| 45 solves |", "| 46 solves |", False),      # integers are counts or labels: exact
    ("| Fig. 8 |", "| Fig. 9 |", False),
    ("| +0.071 µm |", "| +0.072 µm |", True),
    ("| 0.5 agree |", "| 0.5 disagree |", False),   # the words
    ("reduced χ² 0.995.", "reduced χ² 0.994.", True),  # a number ending a sentence is a number
    ("reduced χ² 0.995.", "reduced χ² 0.997.", False),
    ("| 0.010000 |", "| 0.020000 |", False),       # trailing zeros kept (#g): their unit is the last zero's
    ("| 41995.2 |", "| 4.1995e+04 |", False),      # another format is another text, not a rounding
    ("| < 1e-10 |", "| < 1e-12 |", False),
    ("| 0.9950 |", "| 0.995 |", False),
])
def test_rounded_text(mine, theirs, agree):
    assert (rounded_text_differences(mine, theirs) == []) is agree


def test_the_fit_s_shares_follow_its_stopping_tolerance_and_jacobian():
    """c = sqrt(ftol dof) + 2 rtol/h with the noise estimated; the spread 2 rtol/h (1 + κ); the estimates agree to a
    small share of their standard errors, so that tau0 changed by 1e-6 of itself (the issue's 'real change') is seen."""
    fit = me.open_result(RESULTS / "fit_A20_R30.nc")
    assert int(fit["noise_given"].sum()) == 0
    compared = sum(int(np.isfinite(fit[f"residual_{q}"].values).sum()) for q in fit["quantity"].values)
    dof = compared - fit.sizes["parameter"]
    jacobian = 2 * fit.attrs["continuum_rtol"] / fit.attrs["jacobian_step"]
    assert jacobian_share(fit) == pytest.approx(jacobian, rel=1e-15)
    assert estimate_share(fit) == pytest.approx(math.sqrt(fit.attrs["optimizer_tolerance"] * dof) + jacobian, rel=1e-12)
    assert spread_share(fit) == pytest.approx(jacobian * (1 + float(fit["condition_number"])), rel=1e-12)
    tolerance = tolerance_of(fit, "estimate")
    assert np.all(tolerance > 0) and np.all(tolerance < 1e-3 * fit["standard_error"].values)
    tau0 = list(fit["parameter"].values).index("tau0")
    assert tolerance[tau0] < 1e-6 * float(fit["estimate"].values[tau0])


def test_an_infinite_tolerance_accepts_nothing():
    """An unseen parameter's standard error is inf: its estimate cannot be compared, which is a difference, not a
    pass; likewise any fit whose optimizer did not converge."""
    fit = me.open_result(RESULTS / "fit_A20_R30.nc")
    unseen = fit.copy(deep=True)
    unseen["standard_error"].values[0] = np.inf
    doubled = unseen.copy(deep=True)
    doubled["estimate"].values[0] *= 2
    assert any("no finite tolerance" in line for line in result_differences(doubled, unseen))
    assert any("no finite tolerance" in line for line in result_differences(unseen, unseen))
    stopped = fit.assign_attrs(optimizer_converged=0)
    assert any(line.startswith("estimate:") for line in result_differences(stopped, stopped))


def test_at_the_start_of_the_run_an_extremum_s_time_moves_at_first_order():
    """A minimum at the first sample of a rising quantity: δt = tol / |F'| (not the square root of a curvature the
    samples do not have); beside a plateau the same."""
    ds = dataset()
    ds["force"].values[0] = 2.0 * ds["time"].values  # rises linearly from 0 at t = 0: its minimum is at the start
    ds["force_max"].values[0], ds["force_max_time"].values[0] = 0.0, 0.0
    tolerance = ExtremumTime("force_max", "force", search_share=SEARCH_SHARE).tolerance(ds, "force_max_time")
    value_tolerance = float(np.broadcast_to(tolerance_of(ds, "force_max"), (2,))[0])
    assert tolerance[0] == pytest.approx(value_tolerance / 2.0 + SEARCH_SHARE * 10.0, rel=1e-9)
    plateau = dataset()
    plateau["force"].values[0] = np.minimum(plateau["time"].values, T0)  # rises, then holds from T0 on
    plateau["force_max"].values[0] = T0
    tolerance = ExtremumTime("force_max", "force", search_share=SEARCH_SHARE).tolerance(plateau, "force_max_time")
    value_tolerance = float(np.broadcast_to(tolerance_of(plateau, "force_max"), (2,))[0])
    assert tolerance[0] <= value_tolerance / 1.0 * 1.000001 + SEARCH_SHARE * 10.0


def test_a_nan_attribute_agrees_with_itself():
    ds = dataset(measured=float("nan"))
    assert result_differences(ds, ds.copy()) == []
    assert result_differences(ds.assign_attrs(measured=1.0), ds)


def test_the_normal_force_is_as_sensitive_to_the_radius_as_its_indenter_makes_it():
    """d ln F_N / d ln a: n + 1 for c rⁿ (3 for the paraboloid), 1 for the flat punch, and for a table one more than
    its steepest local exponent (a table of r⁴ gives 5)."""
    from mdr_events.io.agreement import force_sensitivity
    assert force_sensitivity(xr.Dataset()) == 3.0
    assert force_sensitivity(xr.Dataset(attrs={"profile_n": 4.0})) == 5.0
    assert force_sensitivity(xr.Dataset(attrs={"profile_radius": 1e-3})) == 1.0
    r = np.linspace(0.0, 1e-3, 41)
    table = xr.Dataset(attrs={"profile_table_r": ", ".join(map(repr, r.tolist())),
                              "profile_table_f": ", ".join(map(repr, (r**4).tolist()))})
    assert 4.9 < force_sensitivity(table) <= 5.0 + 1e-9
