"""The sliding length of a ``"tau0+coulomb"`` span with adhesion read off the span's own layouts
(``split_zones.SpanZones``: the sizes its right-hand side sums, vectorised) against the scan of every part of the
anchors the span read (``SpanMaps.sliding_length``), at every sample of every span of runs that slide partly and
wholly, grow, stay pinned and shrink, on the paraboloid, the cone and n = 3, with Δγ0 < Δγ1 and Δγ1 < Δγ0."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum.regions import RegionLayout
from mdr_events.models.continuum.solution import contact_radii
from mdr_events.models.continuum.split_zones import SpanZones
from mdr_events.models.continuum.tolerances import PIECE_SHARE

COMBINED = FrictionLaw("tau0+coulomb", mu=0.3)
#: The two sums agree to this share of the radius: a layout counts a part whose end lies within PIECE_SHARE of the
#: lengths (the radius, the positions, the caps: all of the radius's order here) beyond its level as reached, where
#: the scan cuts it at its root; the fronts' roots themselves are both to ROOT_XTOL = 2 eps of the interval (2e-14
#: of the radius is the largest difference measured on these cases).
SHARE = PIECE_SHARE
SAMPLES = 3001


def _fretting_path():
    """In to 150 µm, out to 100 µm, then along x by ±40 µm, ±40 µm and 75 µm (partial and full slip of both parts of
    the cap with τ0 = 1 kPa: the full slip shift K a + κ d is 55–60 µm), out into tension and in again (the path of
    tests/models/test_tau0_coulomb_adhesion.py)."""
    turns = np.array([0.0, 40e-6, -40e-6, 40e-6, -15e-6, 75e-6])
    points = [(0.0, -1e-6), (0.0, 150e-6)] + [(x, 100e-6) for x in turns] + [(75e-6, -2e-6), (0.0, 98e-6)]
    return me.Path(np.array(points), speed=1e-6)


def _cases():
    paper = me.Parameters.paper()
    reversed_ = paper.replace(dgamma0=0.15, dgamma1=0.01)
    return [(paper, me.Path.scenario_A(20.0, paper), None), (paper, me.Path.scenario_B(30.0, paper), None),
            (paper, me.Path.scenario_A(30.0, paper), PowerLaw.cone(0.05)),
            (paper, me.Path.scenario_B(30.0, paper), PowerLaw(2e5, 3.0)),
            (reversed_, me.Path.scenario_A(20.0, reversed_), None),
            (paper.replace(tau0=1e3), _fretting_path(), None)]


@pytest.mark.parametrize("params, path, profile", _cases(), ids=["A20", "B30", "cone A30", "n3 B30", "reversed A20", "fretting"])
def test_the_layouts_sliding_length_is_the_scans(params, path, profile):
    solution = solve_path(params, path, profile=profile, friction=COMBINED)
    times = np.linspace(0.0, solution.end_time, SAMPLES)
    owner = solution.span_index(times)
    radii = contact_radii(solution, times)
    compared = sliding = 0
    for index, span in enumerate(solution.spans):
        rows = (owner == index) & (radii > 0.0)
        if not np.any(rows) or span.zones is None:
            continue
        assert isinstance(span.zones, SpanZones)
        t = solution.t_contact + times[rows]
        x, d, a = span.segment.x(t), span.segment.d(t), radii[rows]
        read = span.zones.sliding_length(solution.model.caps, x, d, a)
        scanned = span.anchors.sliding_length(solution.model.caps, x, d, a)
        np.testing.assert_allclose(read, scanned, rtol=0, atol=SHARE * float(np.max(a)), err_msg=f"span {index}")
        compared += int(np.count_nonzero(rows))
        sliding += int(np.count_nonzero(scanned > SHARE * a))
    assert compared > 0.9 * np.count_nonzero(radii > 0.0)  # (every span in contact but those of zero length)
    assert sliding > 0.1 * compared  # (the runs slide: the zones are compared where they hold springs)


def test_sizes_are_size_at_each_instant():
    """``RegionLayout.sizes`` (vectorised) against ``size`` (one instant) on every layout of a run's spans, at levels
    and extents across each span: the same sums, the fronts' roots to the roots' tolerance (ROOT_XTOL of the
    interval, a few ulp)."""
    params = me.Parameters.paper()
    solution = solve_path(params, me.Path.scenario_B(30.0, params), friction=COMBINED)
    checked = 0
    for span in solution.spans:
        if span.zones is None:
            continue
        for (region, cap), layout in span.zones.layouts.items():
            assert isinstance(layout, RegionLayout)
            ends = [p.start for p in layout.parts] + [layout.parts[-1].end]
            lower, upper = min(ends), max(ends)
            levels = np.linspace(-1.0, 1.0, 9) * 2 * max(abs(upper), 1e-6) + float(cap) * 1e-5
            sizes = layout.sizes(levels, np.full(9, lower), np.full(9, upper))
            single = [layout.size(level, lower, upper) for level in levels]
            np.testing.assert_allclose(sizes, single, rtol=0, atol=SHARE * max(upper, 1e-12))
            checked += len(layout.fronts) + len(layout.moving_in)
    assert checked > 0
