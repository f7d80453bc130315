"""Fretting beyond the cap's window at d_max (the paper's law, ``"tau0"``, strokes of ±1 mm against 2 K a = 1.4 mm):
why the springs' mean gap to the continuum stays at 2e-4 N over Δx = 4, 2, 1 µm, and that it is first order.

At a constant depth every spring in contact carries the same cap ``K a`` and the same anchor (all attached at
``x = 0`` on the way in), so both methods are Masing's loops of ``τ0`` (:func:`mdr_events.theory.mindlin
.tangential_force`), each of its own radius: the continuum of the ``Δγ0`` branch's ``a(d_max)``, the springs of
``m Δx`` with ``m = floor(a/Δx + 1/2)`` (the springs whose centres ``(j + 1/2) Δx`` lie inside ``a``); the normal
force likewise, the springs' the midpoint rule over ``m Δx``. The gap there is ``F(m Δx) − F(a)``, about ``2π τ0 a (m Δx − a)`` in full slip: first order in its bound ``|m Δx − a| <= Δx/2``, but
its coefficient is the lattice's phase, the fractional part of ``a/Δx``. For the paper's parameters
``a/(4 µm) = 776.107``: at 4, 2 and 1 µm the fractional part is 0.107, 0.214, 0.428, all below one half, so
``m Δx − a`` is the same −0.428 µm at each and the gap does not move; at 0.5 µm (0.855) it rounds up and drops
sixfold. At a fixed phase the gap falls at first order. Neither model is wrong.
"""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import observed_orders
from mdr_events.theory import analytic, mindlin

PAPER = me.Parameters.paper()
BASE = me.Contact.paper()
D = PAPER.d_max
PATH = me.Path(np.array([(0, 0), (0, D), (1e-3, D), (-1e-3, D), (1e-3, D), (0, -2e-4)]), speed=PAPER.v)
#: The pinned radius at d_max, on the Δγ0 branch (both methods reach d_max growing).
RADIUS = float(me.jkr_contact_radius(D, PAPER, PAPER.dgamma0))
#: A time step that divides the corners' times (300, 1300, 3300, 5300 s after first contact), halved with Δx: the
#: turning points are samples, where Masing's rules read them.
DT_AT_4_UM = 0.5
#: Masing's loops and either method sum the same shifts in another order: to rounding of forces of 1.2 N (measured
#: 6.7e-16 N).
ROUNDING = 1e-14
#: At one phase of the lattice the gap at d_max is linear in m Δx − a = −φ Δx up to the full slip's quadratic term,
#: (m Δx − a)/(2a) < 2e-4; the pull-out (a third of the gap) runs along the Δγ1 branch through every phase. Measured
#: orders 0.9995-1.0004 over Δx ≈ 4, 2, 1, 0.5 µm.
ORDER_SLACK = 0.02
#: The dyadic spacings whose offset m Δx − a is one value: the gap's observed order there is 0 to the time steps'
#: sampling of the loops (measured below 2e-4).
FLAT = 0.01


def _pinned(run) -> np.ndarray:
    """The samples at d_max (between the path's second and fifth corners)."""
    corners = PATH.corner_times
    time = run["time"].values
    return (time >= corners[1]) & (time <= corners[4])


def _runs(dx: float, dt: float):
    run = me.simulate(BASE, [PATH], "discrete", dx=dx, dt=dt).isel(case=0)
    return run, me.simulate(BASE, [PATH], "continuum", t=run["time"].values).isel(case=0)


def _lattice_radius(dx: float) -> float:
    """``m Δx`` with ``m`` the springs whose centres lie inside the pinned radius."""
    return float(np.floor(RADIUS / dx + 0.5)) * dx


@pytest.mark.parametrize("dx", [4e-6, 5e-7])
def test_at_d_max_each_method_is_masing_s_loops_of_its_own_radius(dx):
    run, continuum = _runs(dx, DT_AT_4_UM * dx / 4e-6)
    pinned = _pinned(run)
    x, _ = PATH.position(run["time"].values[pinned])
    assert np.all(run["contact_radius"].values[pinned] == _lattice_radius(dx))
    np.testing.assert_allclose(continuum["contact_radius"].values[pinned], RADIUS, rtol=ROUNDING, atol=0.0)
    springs = mindlin.tangential_force(x, D, "tau0", PAPER, radius=_lattice_radius(dx))
    exact = mindlin.tangential_force(x, D, "tau0", PAPER, radius=RADIUS)
    np.testing.assert_allclose(run["tangential_force"].values[pinned], springs, rtol=0.0, atol=ROUNDING)
    np.testing.assert_allclose(continuum["tangential_force"].values[pinned], exact, rtol=0.0, atol=ROUNDING)
    # F_N: the springs' sum is the midpoint rule of 2E* ∫ (d − ξ²/R) dξ over m Δx, short by exactly m Δx³/(12 R)
    midpoint = 2.0 * PAPER.E_star * _lattice_radius(dx) * dx ** 2 / (12.0 * PAPER.R)
    np.testing.assert_allclose(run["normal_force"].values[pinned],
                               analytic.normal_force(D, _lattice_radius(dx), PAPER) + midpoint, rtol=0.0, atol=ROUNDING)
    np.testing.assert_allclose(continuum["normal_force"].values[pinned], analytic.normal_force(D, RADIUS, PAPER), rtol=0.0,
                               atol=ROUNDING)


def _mean_gap(dx: float, dt: float, where: str = "path") -> float:
    run, continuum = _runs(dx, dt)
    gap = np.abs(run["tangential_force"].values - continuum["tangential_force"].values)
    held = np.isfinite(gap) & (_pinned(run) if where == "d_max" else True)
    return float(np.mean(gap[held]))


def test_at_the_dyadic_spacings_the_gap_is_one_offset_of_the_radius_within_its_first_order_bound():
    spacings = np.array([4e-6, 2e-6, 1e-6, 5e-7])
    offsets = np.array([_lattice_radius(dx) for dx in spacings]) - RADIUS
    np.testing.assert_allclose(offsets[:3], offsets[0], rtol=0.0, atol=ROUNDING * RADIUS)
    assert abs(offsets[3]) < abs(offsets[0]) / 5  # the phase 0.855 rounds up: 0.072 µm
    gaps = np.array([_mean_gap(dx, DT_AT_4_UM * dx / 4e-6, "d_max") for dx in spacings])
    orders = observed_orders(spacings, gaps)
    assert np.all(np.abs(orders[:2]) < FLAT) and orders[2] > 1.0, (gaps, orders)
    # |F(m Δx) − F(a)| <= τ0 π |(m Δx)² − a²| <= τ0 π (2a + Δx/2) Δx/2 at every sample (F = 2G* a clip(u, ±K a))
    assert np.all(gaps <= PAPER.tau0 * np.pi * (2 * RADIUS + spacings / 2) * spacings / 2), gaps


def test_at_a_fixed_phase_of_the_lattice_the_gap_falls_at_first_order():
    """Δx = a/(776·2^k + 1/4): the springs' radius is a − Δx/4 at each spacing, and the mean gap over the whole path
    (the measure of the report, in contact in both) halves with Δx and the time step."""
    phase, springs = 0.25, int(RADIUS / 4e-6)
    spacings = np.array([RADIUS / (springs * 2 ** k + phase) for k in range(4)])
    np.testing.assert_allclose(np.array([_lattice_radius(dx) for dx in spacings]) - RADIUS, -phase * spacings, rtol=1e-9)
    gaps = np.array([_mean_gap(dx, DT_AT_4_UM / 2 ** k) for k, dx in enumerate(spacings)])
    orders = observed_orders(spacings, gaps)
    assert np.all(np.abs(orders - 1.0) < ORDER_SLACK), (gaps, orders)
