"""The floor of ``k/k_t`` over ``[0, X]`` from the tables' B-spline coefficients
(:meth:`~mdr_events.theory.layer.spring_factors.SpringFactors.ratio_floor`): at or below every spring's ratio as
:meth:`~mdr_events.theory.layer.spring_factors.SpringFactors.values` reads it at every coordinate up to ``X`` (on a
dense log-uniform set, at every knot of the spline exactly and a double either side, at ``LAMBDA_MIN`` and either side
of it), near enough to the least of them to settle the per-spring route's probes, and on a spline built with a flat
piece lower than the springs before it (its coefficients all equal: the bound meets the values there to round-off);
beyond the tables, where the spline extrapolates, ``0``."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.interpolate import BSpline

import mdr_events as me
from mdr_events.contact.indenters import Paraboloid
from mdr_events.contact.layer import Layer
from mdr_events.theory.layer import LAMBDA_MAX, LAMBDA_MIN
from mdr_events.theory.layer.spring_factors import RATIO_FLOOR_ROUNDING, SpringFactors
from mdr_events.theory.layer.tangential_punch import _slope

PAPER = me.Parameters.paper()
LAYER = Layer(5e-3)
#: How far below the least ratio up to ``X`` the floor may lie where the route reads it, ``X/h <= TIGHT_EXTENT`` (the
#: paper's contacts on the 5 mm layer reach ``a/h`` 0.2). The claim tested is the bound, ``floor <= every spring``
#: (the first assertion, no tolerance but the floats' one, :data:`RATIO_FLOOR_ROUNDING`): a floor read off a wrong
#: piece, or of the coefficients' hull taken on the wrong side, fails it, and the route's decisions rest on it alone.
#: This tightness is a loose sanity check, measured, not derived: the construction promises none that is useful. On
#: one knot interval the hull lets each column's logarithm lie anywhere in its six coefficients' range ``Δ``, so the
#: bound may lie ``exp(−2Δ_Θ − 2(max(Δ_ΨL, Δ_ΨT) + Δ_ΦL + Δ_ΦT))`` below the springs there: 0.9997 at the centre
#: but 0.85 near ``λ`` 0.07 and 0.6 near 0.2 on these tables (the columns' coefficients lie far closer to their values
#: than that worst case). Measured: 1.3e-4 (ν = 0.5: the series' stretch, the ratio least at the centre) and 8e-4
#: (ν = 0.3: least near ``λ`` 0.07); 1e-3 holds both, so that a floor gone loose (the route reading the probes again,
#: slower, never wrong: ``tests/models/test_play_bound.py``'s loose floor) is noticed here. Beyond, where the columns
#: move fast (``λ`` near ``LAMBDA_MAX``), the floor holds but is loose (20 % at ``λ`` 10 with ν = 0): the route tries
#: it and reads the probes where it does not settle them.
FLOOR_SLACK = 1e-3
#: The extents (a share of the thickness) up to which the floor is held within :data:`FLOOR_SLACK`, and the Poisson's
#: ratios (the paper's and 0.3; at ν = 0 the ratio's least lies where the columns move fastest and the floor there is
#: 9 % below it at ``λ`` 0.3: valid, not tight).
TIGHT_EXTENT = 0.3
TIGHT_NU = (PAPER.nu, 0.3)
#: On a flat piece every column is its coefficients' common value and the floor that value's ratio, lowered by
#: :data:`RATIO_FLOOR_ROUNDING`; the spline's sum of six products moves the values by some ulps (under 1e-14).
FLAT_SLACK = 2 * RATIO_FLOOR_ROUNDING


def coordinates(factors: SpringFactors) -> np.ndarray:
    """Coordinates (m, sorted) from far below ``LAMBDA_MIN`` to ``LAMBDA_MAX``: log-uniform, every knot of the
    spline within the tables (``h e^s``) and a double either side of it, ``LAMBDA_MIN``'s and ``0``."""
    h = factors.h
    knots = np.exp(np.unique(factors._spline.t)) * h
    knots = knots[knots <= LAMBDA_MAX * h]
    dense = np.exp(np.linspace(np.log(1e-9), np.log(LAMBDA_MAX), 20001)) * h
    edges = np.concatenate([knots, [LAMBDA_MIN * h]])
    return np.unique(np.concatenate([[0.0], dense, edges, np.nextafter(edges, 0.0), np.nextafter(edges, np.inf)]))


def ratios(factors: SpringFactors, x: np.ndarray) -> np.ndarray:
    """``k/k_t`` as the per-spring route divides them (:func:`~mdr_events.models.continuum.play_line.spring_line`)."""
    values = factors.values(x)
    return values.normal / values.tangential


@pytest.mark.parametrize("nu", [PAPER.nu, 0.3, 0.0])
def test_the_floor_lies_below_every_spring_up_to_the_extent(nu):
    """At or below the least ratio over ``[0, x]`` at every coordinate, for the paper's ``ν`` and others."""
    factors = SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, nu, LAYER)
    x = coordinates(factors)
    least = np.minimum.accumulate(ratios(factors, x))  # (the least ratio over [0, x] on the coordinates)
    floor = factors.ratio_floor(x)
    assert np.all(floor <= least)  # (the claim: a bound)
    if nu in TIGHT_NU:  # (a loose sanity check of its tightness, measured: FLOOR_SLACK)
        tight = x <= TIGHT_EXTENT * LAYER.thickness
        np.testing.assert_array_less((1.0 - FLOOR_SLACK) * least[tight], floor[tight])


def flattened(factors: SpringFactors, high: float, drop: float) -> SpringFactors:
    """``factors`` with every column's B-spline coefficients whose support ends at ``s <= high`` (the first ones) set
    to the first coefficient's value, ``Θ``'s lowered by ``drop``: from ``LAMBDA_MIN`` on the ratio is constant, below
    the series' springs before it, the floor's least piece (no piece before it mixes its coefficients with others)."""
    spline = factors._spline
    t, k, c = spline.t, spline.k, spline.c.copy()
    inside = np.flatnonzero(t[k + 1:] <= high)
    c[inside] = c[inside[0]]
    c[inside, 1] -= drop
    factors._spline = BSpline(t, c, k)
    return factors


def test_on_a_flat_piece_the_floor_meets_the_springs_to_round_off():
    """A constant ratio from ``LAMBDA_MIN`` to ``λ`` 0.1, below the centre's (every column's coefficients equal there):
    the floor lies at or below the springs, at a knot and either side of it too, and within
    :data:`RATIO_FLOOR_ROUNDING`'s share of them (the bound meets the values in exact arithmetic there)."""
    factors = flattened(SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, PAPER.nu, LAYER),
                        np.log(1e-1), 0.05)
    x = coordinates(factors)
    ratio = ratios(factors, x)
    least = np.minimum.accumulate(ratio)
    floor = factors.ratio_floor(x)
    # (the pieces whose six coefficients and the next piece's are all flattened: s at least 7 knot spacings below)
    flat = (x >= LAMBDA_MIN * LAYER.thickness) & (x <= np.exp(np.log(1e-1) - 0.7) * LAYER.thickness)
    assert np.ptp(ratio[flat]) <= 1e-14 * ratio[flat][0] and ratio[flat][0] < 0.95 * ratio[0]
    assert np.all(floor <= least)
    np.testing.assert_array_less((1.0 - FLAT_SLACK) * least[flat], floor[flat])


#: The columns of the spline after ``γₙ`` (:meth:`SpringFactors._factors`' order).
COLUMNS = ("theta", "phi_l", "phi_t", "edge_l", "edge_t")
#: Moves of one coefficient's logarithm in some columns: ``Θ`` down or a ``Ψ`` up lowers the ratio there below the
#: centre's (its least); ``Φ_L`` and ``Φ_T``, which enter ``Σ_t`` both ways, moved either way on top of a ``Ψ``'s.
DIPS = [{"theta": -0.3}, {"edge_l": 0.6}, {"edge_t": 0.6},
        *({"edge_t": 0.6, phi: move} for phi in ("phi_l", "phi_t") for move in (-1.0, 1.0)),
        *({"edge_l": 0.6, phi: move} for phi in ("phi_l", "phi_t") for move in (-1.0, 1.0))]


@pytest.mark.parametrize("moves", DIPS, ids=[",".join(f"{name}{move:+g}" for name, move in dip.items()) for dip in DIPS])
def test_a_dip_of_one_coefficient_stays_above_the_floor(moves):
    """One coefficient moved near ``λ`` 0.05 (a bump narrower than its six pieces, its extreme between the knots, the
    ratio's least there): the floor stays at or below the springs (each column's hull on the right side, ``Σ_t``'s
    monotone parts on the right sides)."""
    factors = SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, 0.3, LAYER)
    spline = factors._spline
    c = spline.c.copy()
    for column, move in moves.items():
        c[int(np.searchsorted(spline.t, np.log(0.05))), 1 + COLUMNS.index(column)] += move
    factors._spline = BSpline(spline.t, c, spline.k)
    x = coordinates(factors)
    ratio = ratios(factors, x)
    assert np.min(ratio) < 0.95 * ratio[0]  # (the dip the least, below the centre's)
    assert np.all(factors.ratio_floor(x) <= np.minimum.accumulate(ratio))


@pytest.mark.parametrize("nu", [PAPER.nu, 0.3, 0.0, -0.5])
def test_the_slope_s_ceiling_holds_over_its_box(nu):
    """``Σ_t`` (T4) at every corner of random boxes of ``Φ_L, Φ_T, Ψ_L(1), Ψ_T(1)`` and at random points inside lies at
    or below :meth:`SpringFactors._slope_ceiling` of the box (each of its monotone parts taken at the right side): a
    side taken wrong is exceeded at a corner."""
    factors = SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, PAPER.nu, LAYER)
    factors.nu = nu
    rng = np.random.default_rng(34)
    low = np.exp(rng.uniform(-1.0, 1.0, (200, 4)))
    high = low * np.exp(rng.uniform(0.0, 1.0, (200, 4)))
    ceiling = factors._slope_ceiling(low, high)
    corners = np.array(np.meshgrid(*[[0.0, 1.0]] * 4)).reshape(4, -1).T
    shares = np.vstack([corners, rng.uniform(0.0, 1.0, (64, 4))])
    for share in shares:
        point = low + (high - low) * share
        assert np.all(_slope(nu, *point.T) <= ceiling * (1.0 + 1e-14))


#: Extents beyond the tables (shares of ``LAMBDA_MAX``): just past its knot, twice it, and ``λ`` some 1.6e7, where the
#: spline's extrapolated ratio on the paper's ``ν`` (its last quintic piece continued) has fallen far below the
#: tables' floor (some 7e-12 of it; it crosses it near ``λ`` 3.7e6).
BEYOND = (1.0 + 1e-12, 2.0, 2.5e5)


def test_beyond_the_tables_the_floor_claims_nothing():
    """Past the tables' last knot the spline extrapolates and its coefficients bound nothing: the floor is ``0`` there
    (the caller reads the springs), up to the knot the tables' floor; on the paper's ``ν`` the extrapolated springs
    fall below the tables' floor, so any other value than ``0`` there would be no floor."""
    factors = SpringFactors(Paraboloid(PAPER.R), PAPER.E_star, PAPER.G_star, PAPER.nu, LAYER)
    end = LAMBDA_MAX * LAYER.thickness
    beyond = end * np.array(BEYOND)
    assert np.all(factors.ratio_floor(beyond) == 0.0)
    assert np.all(factors.ratio_floor([np.nextafter(end, 0.0), end]) == factors.ratio_floor(0.5 * end))
    assert factors.ratio_floor(end) > 0.0
    x = np.concatenate([coordinates(factors), beyond])
    assert ratios(factors, beyond[-1:])[0] < 1e-3 * factors.ratio_floor(end)
    assert np.all(factors.ratio_floor(x) <= np.minimum.accumulate(ratios(factors, x)))
