"""The pieces of the continuum's ``"tau0+coulomb"`` with adhesion (models.continuum.formulas, regions, split_map,
split_span) against the derivations they implement: a growth's turn as a compressed cap sees it
(``adhesive_seen_piece_turn``), the anchors of a crossing (``adhesive_crossing_anchor``), the two regions' levels
(``adhesive_compressed_level``, ``adhesive_tensile_level``); a formula's integral against quadrature, its inverse
against its value; materialising the play operators leaves the force as it is."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum.anchors import Piece
from mdr_events.models.continuum.branch import make_branch
from mdr_events.models.continuum.caps import caps_of
from mdr_events.models.continuum.formulas import Formula, Shape
from mdr_events.models.continuum.model import Segment
from mdr_events.models.continuum.regions import Region
from mdr_events.models.continuum.split_map import SplitAnchorMap
from mdr_events.models.continuum.split_layouts import crossing_formula
from mdr_events.models.continuum.state import Cap, Regime
from mdr_events.theory import mindlin, symbolic

PARAMS = me.Parameters.paper()
COMBINED = FrictionLaw("tau0+coulomb", mu=0.3)
#: A root of brentq at 4 eps relative, evaluated through the branches' closed forms: a few ulp
ROOT_RTOL = 1e-13
#: Gauss–Legendre against adaptive quadrature (epsrel 1e-13) of a smooth function: their tolerances
QUADRATURE_RTOL = 1e-12


def _shape(profile=None):
    branches = [make_branch(PARAMS, work, profile) for work in (0.0, PARAMS.dgamma0, PARAMS.dgamma1)]
    return Shape(*branches, rtol=1e-14, reach=8e-3)


@pytest.mark.parametrize("profile", [None, PowerLaw(2e5, 3.0)], ids=["paraboloid", "n3"])
@pytest.mark.parametrize("ratio", [2.7, -1.3, 0.2])
def test_a_growth_turns_where_the_derivation_says(profile, ratio):
    """Anchors laid along the Δγ0 branch, ``x0 + r (d0 − d_ref)``, as each compressed cap sees them
    (``Y − σ κ g``): the turns Formula finds are the derived ``adhesive_seen_piece_turn`` (one where r/(r − σκ) > 0,
    none otherwise), to the root's tolerance."""
    shape = _shape(profile)
    kappa = mindlin.coulomb_cap_ratio(COMBINED, PARAMS)
    indenter = profile or PowerLaw.paraboloid(PARAMS.R)
    growth = Formula(shape, 1e-5, beta=ratio, d_ref=1e-4)
    for cap in Cap:
        sigma = float(cap) * kappa
        seen = growth.seen(sigma)
        turn = float(symbolic.relation("adhesive_seen_piece_turn").numeric(ratio, sigma, PARAMS.dgamma0, indenter.c,
                                                                            indenter.n, PARAMS.E_star))
        expected = [turn] if ratio / (ratio - sigma) > 0 and turn < shape.reach else []
        np.testing.assert_allclose(seen.turns(), expected, rtol=ROOT_RTOL)
        for low, high in zip((0.0,) + seen.turns(), seen.turns() + (shape.reach,)):  # monotone between them
            values = seen.values(np.linspace(low, high, 401)[1:-1])
            assert np.all(np.diff(values) >= 0) or np.all(np.diff(values) <= 0)


@pytest.mark.parametrize("regime", [Regime.PINNED, Regime.GROWING, Regime.SHRINKING])
def test_the_anchors_of_a_crossing_are_the_derived_ones(regime):
    """crossing_formula on a segment (in at 2 µm/s, aside at −0.7 µm/s) is ``adhesive_crossing_anchor`` with the radius
    ``a`` the regime gives at the depth ``g(ξ)``: the pinned radius, or the branch's; seen by the compressed cap ``σ``
    at ``ξ``, it is the compressed level of that instant (``adhesive_compressed_level`` at ``d = g(ξ)``)."""
    shape = _shape()
    anchors = SplitAnchorMap(shape)
    caps = caps_of(COMBINED, PARAMS)
    segment = Segment(10.0, 90.0, 3e-5, 5e-5, -0.7e-6, 2e-6)
    pinned = 2.4e-3
    anchor, level = (symbolic.relation(key) for key in ("adhesive_crossing_anchor", "adhesive_compressed_level"))
    for cap in Cap:
        formula = crossing_formula(anchors, segment, regime, pinned, cap, caps.K)
        for xi in (4e-4, 1.1e-3, 2.2e-3):
            depth = shape.hertz.depth(xi)
            radius = {Regime.PINNED: pinned, Regime.GROWING: shape.grow.radius(depth, 1e-14),
                      Regime.SHRINKING: make_branch(PARAMS, PARAMS.dgamma1).radius(depth, 1e-14)}[regime]
            c, n = 1.0 / (2.0 * PARAMS.R), 2.0  # the paraboloid as the power law of the derivation
            expected = float(anchor.numeric(xi, segment.xs, segment.ds, segment.vx, segment.vd, float(cap), radius,
                                            PARAMS.tau0, c, n, PARAMS.G_star))
            assert formula.value(xi) == pytest.approx(expected, rel=0, abs=ROOT_RTOL * abs(expected) + 1e-20)
            x = segment.xs + segment.vx / segment.vd * (depth - segment.ds)
            seen = formula.seen(float(cap) * caps.kappa).value(xi)
            at_crossing = float(level.numeric(x, float(cap), depth, radius, PARAMS.tau0, COMBINED.mu, PARAMS.E_star,
                                              PARAMS.G_star))
            assert seen == pytest.approx(at_crossing, rel=0, abs=ROOT_RTOL * abs(at_crossing) + 1e-20)


def test_the_regions_levels_are_the_derived_ones():
    caps = caps_of(COMBINED, PARAMS)
    compressed, tensile = (symbolic.relation(key) for key in ("adhesive_compressed_level", "adhesive_tensile_level"))
    x, radius, depth = 4e-5, 2.1e-3, 1.2e-4
    for cap in Cap:
        assert Region.COMPRESSED.level(cap, x, caps.K, caps.kappa, radius, depth) == pytest.approx(
            float(compressed.numeric(x, float(cap), depth, radius, PARAMS.tau0, COMBINED.mu, PARAMS.E_star,
                                     PARAMS.G_star)), rel=1e-15)
        assert Region.TENSILE.level(cap, x, caps.K, caps.kappa, radius, depth) == pytest.approx(
            float(tensile.numeric(x, float(cap), radius, PARAMS.tau0, PARAMS.G_star)), rel=1e-15)


@pytest.mark.parametrize("table", [False, True], ids=["paraboloid", "table"])
def test_a_formula_integrates_and_inverts(table):
    """A crossing's anchors seen by a compressed cap (every term: g, d0 and A(g)): the integral against adaptive
    quadrature, the inverse against the value, on each monotone interval (a table of the paraboloid: its knots)."""
    profile = None
    if table:
        r = np.linspace(0.0, 1.2e-2, 41)
        profile = me.TabulatedProfile(r, r**2 / (2 * PARAMS.R))
    shape = _shape(profile)
    formula = Formula(shape, 3e-5, alpha=0.7, beta=-0.4, d_ref=1e-4, gamma=-0.004, radius_of="shrink")
    for low, high in ((1e-4, 1.5e-3), (6e-4, 2.9e-3)):
        quadrature = integrate.quad(formula.value, low, high, epsabs=0, epsrel=1e-13, limit=200,
                                    points=[k for k in shape.knots() if low < k < high] or None)[0]
        assert formula.integral(low, high) == pytest.approx(quadrature, rel=QUADRATURE_RTOL)
    for low, high in zip((1e-6,) + formula.turns(), formula.turns() + (shape.limit(formula.radius_of),)):
        points = np.linspace(low, high, 7)[1:-1]
        levels = formula.values(points)
        found = [formula.inverse(level, low, high) for level in levels]
        np.testing.assert_allclose(found, points, rtol=ROOT_RTOL)
        np.testing.assert_allclose(formula.inverses(levels, low, high), points, rtol=ROOT_RTOL)


def test_materialising_the_play_operators_keeps_the_force():
    """The anchors of a growth and a crossing clipped at every spring's cap (``clip_caps``, both regions) give the
    algebraic force they gave before, and a second clip changes nothing."""
    shape = _shape()
    caps = caps_of(COMBINED, PARAMS)
    anchors = SplitAnchorMap(shape)
    anchors.extend(0.0, Piece(0.0, 8e-4, 2e-5))
    anchors.extend(8e-4, Piece(8e-4, 2.6e-3, -1e-5, 0.8, 5e-5))
    anchors = anchors.replaced(1.2e-3, 1.5e-3, Formula(shape, 4e-5, alpha=-2.0, d_ref=1e-4, gamma=caps.K,
                                                         radius_of="grow"))
    x, depth, radius = 6e-5, 9e-5, 2.6e-3
    before = anchors.tangential_force(caps, PARAMS.G_star, x, radius, depth)
    anchors.clip_caps(x, caps, depth, radius)
    after = anchors.tangential_force(caps, PARAMS.G_star, x, radius, depth)
    assert after == pytest.approx(before, rel=1e-12)
    pieces = list(anchors.pieces)
    anchors.clip_caps(x, caps, depth, radius)
    assert anchors.pieces == pieces


@pytest.mark.parametrize("profile", [None, PowerLaw(2e5, 3.0)], ids=["paraboloid", "n3"])
def test_a_parts_roots_depend_on_the_level_alone(profile):
    """``Part.inverse`` of a growth as a compressed cap sees it (``x0 + α (g − d_ref) + β (d0 − d_ref)``, Newton's
    iteration): the same levels asked in three orders of one part give the same roots bit for bit (its start is the
    chord of the part's scan about the level, not the roots asked before), each a root to ROOT_RTOL."""
    from mdr_events.models.continuum.regions import Part
    shape = _shape(profile)
    formula = Formula(shape, 1e-5, alpha=-0.45, beta=2.75, d_ref=0.0)
    low, high = formula.monotone_interval(2e-4, 2e-3)
    part = Part(formula, 2e-4, 2e-3, low, high)
    levels = formula.values(np.linspace(2.5e-4, 1.9e-3, 40))
    orders = [np.arange(40), np.arange(40)[::-1], np.random.default_rng(3).permutation(40)]
    roots = []
    for order in orders:
        found = np.empty(40)
        for index in order:
            found[index] = part.inverse(float(levels[index]))
        roots.append(found)
    np.testing.assert_array_equal(roots[0], roots[1])
    np.testing.assert_array_equal(roots[0], roots[2])
    np.testing.assert_allclose(formula.values(roots[0]), levels, rtol=ROOT_RTOL, atol=0)
