"""The continuum's sampled evaluation (issue 28: ``simulate`` at most 1.5x its ``solve_path``): the sliding length at
many instants at once (``AnchorMap.sliding_length``, which shares the pieces' extents between both caps) is the plain
per-cap, per-piece sum bit for bit, and equals the per-sample zone sizes (``AnchorMap.zone_size``, one instant at a
time) to the accuracy of the slip front's root."""

import numpy as np
import pytest

import mdr_events as me
from continuum_maps import reversing_anchors
from mdr_events.models.continuum import AnchorMap, Cap, ContinuumModel, Tolerances, solve_path
from mdr_events.models.continuum.caps import Caps
from mdr_events.models.continuum.time_grid import sample_times
from mdr_events.models.continuum.state import Regime

RTOL = 1e-14
EPS = float(np.finfo(float).eps)
#: Agreement of a slip front found among many instants with the same front found alone (m, over the radius): the
#: front is ``ξ = s²`` with ``s`` the root of Newton's iteration, stopped once a step is within 4 eps of ``s``
#: (``positive_polynomial_root``'s default); alone or among others it stops after a different number of steps, each
#: within 4 eps of the root, so the two ``s`` differ by at most 8 eps, ``ξ`` by 16 eps of itself (<= a), and the
#: sum of both caps' zones by 32 eps of ``a``; a factor 2 for the rounding of the sums.
FRONT_SHARE = 64 * EPS


def reference_sliding_length(anchors: AnchorMap, caps: Caps, x, depth, radius) -> np.ndarray:
    """The sliding length as the plain sum over both caps and every piece (``np.where`` of each piece's springs at the
    cap), each cap's anchors as it sees them, the front's root taken of the same levels: the computation that
    ``sliding_length`` streamlines."""
    shift = caps.centre_shift(radius, depth)
    out = 0
    for cap in Cap:
        seen, levels = anchors.seen_by(cap, caps.kappa), x - int(cap) * shift
        total = np.zeros(levels.shape)
        for p in seen.pieces:
            ends = np.minimum(p.end, radius)
            length = np.maximum(ends - p.start, 0.0)
            if p.constant:
                total += np.where(cap * p.x0 <= cap * levels, length, 0.0)
                continue
            bounds = cap * np.array([seen.piece_value(p, p.start), seen.piece_value(p, float(np.max(ends)))])
            reached = cap * levels
            inside = (reached >= bounds.min()) & (reached < bounds.max())
            total += np.where(reached >= bounds.max(), length, 0.0)
            if np.any(inside):
                xi = seen.inverses(p, levels[inside])
                part = xi - p.start if p.rises_towards(cap) else ends[inside] - xi
                total[inside] += np.clip(part, 0.0, length[inside])
        out = out + total
    return out


@pytest.fixture(scope="module")
def model(paper):
    return ContinuumModel(paper, Tolerances())


@pytest.fixture(scope="module")
def anchors(model):
    """:func:`continuum_maps.reversing_anchors`: constant, rising and falling pieces."""
    return reversing_anchors(model, RTOL)


def instants(anchors: AnchorMap, radii: int = 7, positions: int = 61):
    """Positions, depths and radii (a grid of both, flattened): at each radius the position sweeps the anchors' values
    with both caps' levels, from below the lowest to above the highest (stick, partial and full slip at either cap)."""
    radius = np.linspace(0.6e-3, 4.2e-3, radii)
    top = anchors.value(3e-3)
    x = np.linspace(-0.3 * top, 1.3 * top, positions)
    radius, x = (grid.ravel() for grid in np.meshgrid(radius, x))
    return x, anchors.attach.depths(radius), radius


@pytest.mark.parametrize("kappa", [0.0, 0.4])
def test_sliding_length_is_the_plain_sum_over_caps_and_pieces_bit_for_bit(paper, model, anchors, kappa):
    """Both caps' zones over a map with constant, rising and falling pieces, with Coulomb's part (κ > 0: each cap sees
    its own pieces, of the same extents) and without: the shared extents and the in-place sums give the plain
    computation's values exactly (the same operations on the same numbers, the same roots of the same levels)."""
    caps = Caps(model.caps.K, kappa, model.caps.medium)
    x, depth, radius = instants(anchors)
    found = anchors.sliding_length(caps, x, depth, radius)
    expected = reference_sliding_length(anchors, caps, x, depth, radius)
    assert np.count_nonzero((found > 0) & (found < radius)) > 20  # (partial slip sampled, not only the extremes)
    np.testing.assert_array_equal(found, expected)


def test_sliding_length_equals_each_instant_alone(model, anchors):
    """The vectorised sliding length against each instant's zone sizes found alone (``zone_size`` of both caps, one
    root at a time): equal to :data:`FRONT_SHARE` of the radius."""
    x, depth, radius = instants(anchors, 5, 31)
    found = anchors.sliding_length(model.caps, x, depth, radius)
    shift = model.caps.centre_shift(radius, depth)
    alone = np.array([sum(anchors.zone_size(cap, float(x[i] - int(cap) * shift[i]), float(radius[i])) for cap in Cap)
                      for i in range(len(x))])
    np.testing.assert_allclose(found, alone, rtol=0.0, atol=FRONT_SHARE * float(np.max(radius)))


@pytest.mark.parametrize("scenario, angle", [("A", 20.0), ("B", 30.0)])
def test_evaluated_sliding_fraction_equals_each_sample_alone(paper, scenario, angle):
    """A solved run's sliding fraction at 2001 samples (``evaluate``: each span's instants at once) against each
    sample's zones found alone from the same span's anchors, radius, depth and position: equal to
    :data:`FRONT_SHARE` (a share of the radius: the fraction's own unit)."""
    path = getattr(me.Path, f"scenario_{scenario}")(angle, paper)
    solution = solve_path(paper, path)
    times = sample_times([solution.end_time], [path.duration - path.first_contact_time()], 2001)
    filled = solution.evaluate_at(times)
    owner, caps = solution.span_index(times), solution.model.caps
    checked = 0
    for i in np.flatnonzero((times <= solution.end_time) & (filled["contact_radius"] > 0))[::7]:
        span = solution.spans[owner[i]]
        if span.regime is Regime.NONE:
            continue
        a, d, x = (float(filled[name][i]) for name in ("contact_radius", "indentation_depth",
                                                         "tangential_displacement"))
        anchors = span.zones if span.zones is not None else span.anchors
        shift = caps.centre_shift(a, d)
        zones = sum(anchors.seen_by(cap, caps.kappa).zone_size(cap, x - int(cap) * shift, a) for cap in Cap)
        assert filled["sliding_fraction"][i] == pytest.approx(min(zones / a, 1.0), rel=0.0, abs=FRONT_SHARE)
        checked += 1
    assert checked > 200


@pytest.mark.parametrize("scenario, angle", [("A", 20.0), ("B", 30.0)])
def test_evaluate_in_any_order_is_evaluate_in_order(paper, scenario, angle):
    """``evaluate`` reads each span's rows of increasing times as slices, of any other order as gathered indices: the
    same values bit for bit (the times shuffled, with some before the first contact and after the run's end)."""
    path = getattr(me.Path, f"scenario_{scenario}")(angle, paper)
    solution = solve_path(paper, path)
    end = solution.end_time
    times = np.concatenate([np.linspace(0.0, end, 401), [-0.25 * solution.t_contact, end * (1 + 1e-4)]])
    times.sort()
    shuffled = np.random.default_rng(7).permutation(len(times))
    in_order, any_order = solution.evaluate_at(times), solution.evaluate_at(times[shuffled])
    for name, values in in_order.items():
        np.testing.assert_array_equal(any_order[name], values[shuffled], err_msg=name)



#: Horner's rounding of the branch's quartic in ``s = √ξ``, relative to the sum of its terms' magnitudes: ``2n u = 4 ε``
#: (``n = 4`` multiply-adds; Higham, Accuracy and Stability, 5.1). A root moves by that change over ``|p'(s)|``.
HORNER_ROUNDING = 4 * EPS
#: What each route adds to the conditioning: the iteration stops on a step of 4 ε of ``s`` (``positive_polynomial_root``'s
#: default, ``Branch.radii``), the closed form's Newton polish leaves a few ulp, and ``ξ = s²`` rounds by half an ulp.
ROUTE_SHARE = 8 * EPS


def test_inverses_at_samples_are_the_iterations_fronts_to_the_roots_conditioning(anchors):
    """``AnchorMap.inverses`` (a run's samples: the branch's closed-form quartic root, ``sample_radii``) against the
    route it replaced, the iteration over the whole array (``Branch.radii``, a level with no radius the piece's start),
    level by level on a rising and a falling piece, the levels from beyond the fold to deep: the same levels unreached,
    the others within twice each route's distance from the true root, the polynomial's rounding over its slope plus
    :data:`ROUTE_SHARE` (the fold itself: both iterate there)."""
    branch = anchors.attach
    checked = 0
    for piece in anchors.pieces[1:]:
        fold, deepest = branch.jump_off_depth, branch.depth(1.2 * piece.end)
        depths = np.concatenate([fold * (1.0 - np.logspace(-16.0, -1.0, 40)), [fold, 1.5 * fold],
                                 np.linspace(fold, deepest, 400)])
        levels = piece.x0 + piece.ratio * (depths - piece.d_ref)
        found = anchors.inverses(piece, levels)
        depths = piece.d_ref + (levels - piece.x0) / piece.ratio  # (as inverses reads them back)
        iterated = branch.radii(depths)
        reached = ~np.isnan(iterated)
        assert np.count_nonzero(~reached) > 0 and np.all(found[~reached] == piece.start)
        s = np.sqrt(iterated[reached])
        linear, constant = (np.broadcast_to(c, depths.shape)[reached] for c in
                            branch._array_coefficients(depths, *branch._arguments)[3:])
        with np.errstate(divide="ignore"):
            shift = HORNER_ROUNDING * (s**4 + np.abs(linear) * s + np.abs(constant)) / np.abs(4.0 * s**3 + linear)
        allowed = 2.0 * 2.0 * (np.minimum(shift, s) + ROUTE_SHARE * s) * s  # (dξ = 2 s ds)
        excess = np.abs(found[reached] - iterated[reached]) / allowed
        assert np.max(excess) <= 1.0, np.max(excess)
        checked += np.count_nonzero(found[reached] != iterated[reached])
    assert checked > 0  # (the closed form is not the iteration: the comparison compares)


@pytest.mark.parametrize("label", ["A 20°", "B 30°", "zigzag", "reciprocating"])
def test_evaluate_at_once_is_evaluate_span_by_span(paper, label, monkeypatch):
    """``evaluate`` takes each branch's radii of all its spans in one call (``_sampled_radii``) and ``F_N`` of every
    span in one (``_fill_normal_force``): the values of each span evaluated alone (``evaluate_span`` with its own radii
    and force) bit for bit, on runs of a few spans and of many (a zigzag, ten fretting cycles); the forces by the
    spans' own terms (``FillRoute.TERMS``: the polynomials' route is ``test_sample_forces.py``'s, within rounding)."""
    from mdr_events.models.continuum import solution as solution_module
    from mdr_events.models.continuum.sample_forces import FillRoute
    from mdr_events.models.continuum.solution import evaluate_span
    from mdr_events.models.continuum.span_rows import _span_rows

    monkeypatch.setattr(solution_module, "FILL_ROUTE", FillRoute.TERMS)

    if label == "zigzag":
        path = me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], paper.v)
    elif label == "reciprocating":
        x_c, amplitude = paper.d_max / np.tan(np.radians(20.0)), 2e-5
        turns = [(x_c + amplitude * (1 if i % 2 == 0 else -1), paper.d_max) for i in range(20)]
        path = me.Path([(0.0, 0.0), (x_c, paper.d_max), *turns, (x_c, paper.d_max), (x_c, -1e-4)], paper.v)
    else:
        path = getattr(me.Path, f"scenario_{label[0]}")(float(label.split()[1].rstrip("°")), paper)
    solution = solve_path(paper, path)
    times = sample_times([solution.end_time], [path.duration - path.first_contact_time()], 2001)
    at_once = solution.evaluate_at(times)
    spans = _span_rows(solution.span_index(times), times <= solution.end_time, len(solution.spans))
    assert sum(solution.spans[index].regime is not Regime.PINNED for index, _ in spans) >= 3
    for index, rows in spans:
        for name, values in evaluate_span(solution, index, times[rows]).items():
            np.testing.assert_array_equal(at_once[name][rows], values, err_msg=f"{name}, span {index}")
