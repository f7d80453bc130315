"""Both simulators with a power-law indenter ``f = c rⁿ``: the paraboloid's runs unchanged, the continuum on
the power law's closed forms (pull-off, jump-in, jump-off, slip onset), the discrete model converging to it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import HISTORY_QUANTITIES, history_differences, observed_orders
from mdr_events.contact.indenters import PowerLaw
from mdr_events.theory import power_law as pl

#: Exact closed forms against the continuum: its radii and event roots are converged to about 1e-14, the
#: force integrated to rtol 1e-10.
CLOSED_FORM_RTOL = 1e-9


@pytest.fixture(scope="module")
def paper():
    return me.Parameters.paper()


def _matching(n: float, params: me.Parameters) -> PowerLaw:
    """The power law whose non-adhesive radius at d_max is the paraboloid's (comparable contacts)."""
    return pl.with_radius_at(n, math.sqrt(params.R * params.d_max), params.d_max)


def _events(ds, case: int) -> tuple[list[str], np.ndarray, np.ndarray]:
    kinds = [str(kind) for kind in ds["event_kind"].values[case]]
    return kinds, ds["event_depth"].values[case], ds["event_radius"].values[case]


def test_the_paraboloid_as_a_power_law_is_the_papers_run(paper):
    """PowerLaw.paraboloid(R) evaluates other formulas for the same indenter: the continuum's forces and events
    agree with the default run to the rounding of the radii (1e-12 of the largest force)."""
    default = me.simulate(paper, "B", alpha=[20, 60], method="continuum")
    as_power_law = me.simulate(paper, "B", alpha=[20, 60], method="continuum", profile=PowerLaw.paraboloid(paper.R))
    assert "profile" not in default.attrs and as_power_law.attrs["profile"].startswith("power law")
    for name in ("normal_force", "tangential_force", "contact_radius"):
        scale = np.nanmax(np.abs(default[name].values))
        np.testing.assert_allclose(as_power_law[name].values, default[name].values, rtol=0, atol=1e-12 * scale)
    np.testing.assert_array_equal(as_power_law["event_kind"].values, default["event_kind"].values)
    np.testing.assert_allclose(as_power_law["event_time"].values, default["event_time"].values, rtol=1e-12)


@pytest.mark.parametrize("n", [1.0, 1.5, 3.0, 6.0])
def test_the_continuum_meets_the_power_laws_closed_forms(paper, n):
    """Scenario A: first contact at the jump-in radius, slip onset at d_crit (18) where it lies before d_max,
    the least normal force is the pull-off force under force control (its minimum on the Δγ1 branch lies above
    the jump-off), and the contact comes off at the jump-off depth of the Δγ1 branch."""
    profile = _matching(n, paper)
    alpha = np.array([3.0, 10.0, 20.0])
    ds = me.simulate(paper, "A", alpha=alpha, method="continuum", profile=profile)
    onset = pl.d_crit_A(alpha, profile, paper, adhesion=True)
    fold = pl.jump_off(profile, paper, paper.dgamma1)
    checked = 0
    for case, angle in enumerate(alpha):
        kinds, depths, radii = _events(ds, case)
        assert kinds[0] == "first_contact" and "pull_off" in kinds
        assert radii[0] == pytest.approx(pl.jump_in_radius(profile, paper, paper.dgamma0), rel=CLOSED_FORM_RTOL)
        pull_off = kinds.index("pull_off")
        assert depths[pull_off] == pytest.approx(fold["depth"], rel=CLOSED_FORM_RTOL)
        assert radii[pull_off] == pytest.approx(fold["contact_radius"], rel=CLOSED_FORM_RTOL)
        assert float(ds["normal_force_min"].values[case]) == pytest.approx(
            pl.pull_off_force(profile, paper, paper.dgamma1), rel=CLOSED_FORM_RTOL)
        if onset[case] < paper.d_max:
            assert depths[kinds.index("slip_onset")] == pytest.approx(onset[case], rel=CLOSED_FORM_RTOL)
            checked += 1
    assert checked >= 2


def test_the_continuum_force_is_the_branch_force_while_growing(paper):
    """On the way in the radius follows the Δγ0 branch: F_N = (10) on the branch at the sampled radius."""
    profile = _matching(3.0, paper)
    ds = me.simulate(paper, "A", alpha=30.0, method="continuum", profile=profile, samples=401)
    depth = ds["indentation_depth"].values[0]
    kinds, _, _ = _events(ds, 0)
    corner = ds["event_time"].values[0, kinds.index("corner")]
    going_in = np.flatnonzero((ds["time"].values < corner) & (ds["contact_radius"].values[0] > 0))
    radius = ds["contact_radius"].values[0, going_in]
    np.testing.assert_allclose(ds["normal_force"].values[0, going_in],
                               pl.branch_normal_force(radius, profile, paper, paper.dgamma0), rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(radius, pl.contact_radius(depth[going_in], profile, paper, paper.dgamma0), rtol=1e-12)


@pytest.mark.parametrize("n", [1.0, 3.0])
def test_the_discrete_model_converges_to_the_continuum_at_first_order(paper, n):
    """max_t |discrete − continuum| of F_N, F_x and A (as for the paraboloid, :func:`history_differences`) falls
    at first order in Δx = 8, 4, 2 µm (dt = Δx / (2v)): observed orders above 0.7, the last within 2e-3."""
    profile = _matching(n, paper)
    spacings = (8e-6, 4e-6, 2e-6)
    differences = {name: [] for name in HISTORY_QUANTITIES}
    for dx in spacings:
        discrete = me.simulate(paper, "A", alpha=[30.0], dx=dx, dt=0.5 * dx / paper.v, profile=profile)
        exact = me.simulate(paper, "A", alpha=[30.0], method="continuum", t=discrete["time"].values, profile=profile)
        assert discrete.attrs["profile"] == exact.attrs["profile"]
        for name, values in history_differences(discrete, exact).items():
            if name in differences:
                differences[name].append(values[0])
    for name, values in differences.items():
        assert np.all(observed_orders(spacings, values) > 0.7), (name, values)
        assert values[-1] < 2e-3, (name, values)


@pytest.mark.parametrize("profile, error, message", [
    ("cone", TypeError, r"profile='cone' \(str\) is not allowed; allowed: None \(the paraboloid of R\), a PowerLaw "
                        r"with n >= 1, a FlatPunch or a TabulatedProfile"),
    (PowerLaw(1.0, 0.75), ValueError, r"PowerLaw.n=0.75 is not allowed in the simulators; allowed: n >= 1"),
])
@pytest.mark.parametrize("method", ["discrete", "continuum"])
def test_profiles_the_simulators_do_not_take_are_named(paper, profile, error, message, method):
    with pytest.raises(error, match=message):
        me.simulate(paper, "A", alpha=20.0, method=method, profile=profile)
