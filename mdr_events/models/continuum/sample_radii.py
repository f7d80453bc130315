"""The contact radii of a run's samples on the spans moving along a branch (9) (:func:`~.solution.evaluate`'s fill):
each branch's spans in one call of its :meth:`~.branch.Branch.sample_radii` (``_sampled_radii``), both of the
paraboloid's branches with adhesion in one closed-form pass (``_quartic_radii``); a sample at its span's end (to
:data:`END_ULPS`) takes the iteration's radius, that of the span's event."""

from __future__ import annotations

import math

import numpy as np

from mdr_events.memo import kept
from mdr_events.parameters import Parameters
from mdr_events.theory.quartic import depressed_quartic_root
from .branch import NEAR_FOLD, Branch
from .dense import cut
from .model import ContinuumModel
from .span_record import Span
from .state import Regime

#: A sample whose depth is within this many ulp of its span's end depth is read as that end (:func:`_sampled_radii`):
#: a time from first contact and back rounds the depth by an ulp or two.
END_ULPS = 4


def _sampled_radii(model, spans: list[Span], depths: list[np.ndarray]) -> list[np.ndarray]:
    """The sampled radii (``solution._span_radius``) of several moving spans of one branch at their depths, in one
    call of the branch's :meth:`~.branch.Branch.sample_radii` and at most one of its iteration (each element alone:
    the same values as span by span, but where the iteration runs for several elements at once, at a span's end or
    near the fold, to its stopping step)."""
    # (growing: on the Δγ0 branch, above its fold, a sample may sit below it to rounding; shrinking: the last sample
    # may sit on the fold to rounding)
    branch = model.grow if spans[0].regime is Regime.GROWING else model.shrink
    depth = [np.maximum(d, branch.jump_off_depth) for d in depths]
    # a sample at a span's end (to END_ULPS of its depth) takes the iteration's radius: that of the span's event,
    # which the pinned span after it holds
    lengths = [len(d) for d in depths] if all(np.ndim(d) == 1 for d in depths) else None
    ends = _at_ends(spans, depth, lengths)
    depth = np.concatenate(depth) if len(depth) > 1 else depth[0]
    radii = branch.sample_radii(depth)
    if ends.any():
        radii[ends] = _iterated_radii(branch, depth[ends])
    lengths = [len(d) for d in depths]
    return cut(radii, lengths) if len(lengths) > 1 else [radii]


#: How many of the paraboloid's iterated radii at one depth :func:`_iterated_radii` keeps.
ITERATED_RADII_KEPT = 64


def _iterated_radii(branch, depth: np.ndarray) -> np.ndarray:
    """``branch.radii(depth)``, the iteration's radii at a run's samples on its spans' ends; one depth alone on the
    paraboloid's branch with adhesion (a run's first sample, at first contact: the same depth at every angle and
    every run of the same material) kept by value (:func:`_paraboloid_radius`, the work a ``float``: a NumPy number has
    no key), the same number bit for bit."""
    if type(branch) is Branch and branch.work != 0.0 and depth.size == 1:
        return np.full(depth.shape, _paraboloid_radius(branch.params, float(branch.work), float(depth.flat[0])))
    return branch.radii(depth)


@kept(ITERATED_RADII_KEPT)
def _paraboloid_radius(params: Parameters, work: float, depth: float) -> float:
    """:meth:`~.branch.Branch.radii` of the paraboloid's branch of ``params`` and ``work`` at one ``depth`` (an array
    of one element: the array route's iteration, not the scalar's), kept by the exact values
    (:func:`~mdr_events.memo.kept`: a zero's sign and the type apart)."""
    return float(Branch(params, work).radii(np.array([depth]))[0])


def _at_ends(spans: list[Span], depths: list[np.ndarray], lengths: list[int] | None) -> np.ndarray:
    """Whether each depth (of each span, concatenated) lies within :data:`END_ULPS` of its span's depth at its start or
    at its end; spans of 1-D depths (``lengths``) all at once, each with its span's ends repeated over its depths."""
    ends = np.array([[span.segment.d(span.t_start), span.segment.d(span.t_end)] for span in spans], dtype=float)
    if lengths is None:  # (a span's depths of another shape: span by span)
        found = []
        for (start, end), each in zip(ends, depths):
            found.append((np.abs(each - start) <= END_ULPS * np.spacing(abs(start))) |
                         (np.abs(each - end) <= END_ULPS * np.spacing(abs(end))))
        return np.concatenate(found) if len(found) > 1 else found[0]
    tolerance = END_ULPS * np.spacing(np.abs(ends))
    depth = np.concatenate(depths) if len(depths) > 1 else depths[0]
    at_start, at_end = (np.abs(depth - np.repeat(ends[:, k], lengths)) <= np.repeat(tolerance[:, k], lengths)
                        for k in (0, 1))
    return at_start | at_end


def _quartic_radii(model: ContinuumModel, members: list[Span], d: np.ndarray, lengths: list[int],
                   a: np.ndarray) -> bool:
    """:func:`_sampled_radii` of every moving span of ``members`` on the paraboloid's branches with adhesion, both
    branches in one pass, written into ``a`` (the samples' radii, pinned ones already there; ``d`` their depths, each
    span's ``lengths`` consecutive): each sample with its branch's quartic coefficient, jump-off and floor, the
    closed form over all samples at once (:func:`~mdr_events.theory.quartic.depressed_quartic_root`, element by
    element); the iteration near the fold and at the spans' ends branch by branch over its samples, as
    :func:`_sampled_radii` runs it. ``False`` (nothing written) where a moving span's branch samples otherwise."""
    branches = ((Regime.GROWING, model.grow), (Regime.SHRINKING, model.shrink))
    of_span = [next((branch for regime, branch in branches if span.regime is regime), None) for span in members]
    used = [branch for regime, branch in branches if any(span.regime is regime for span in members)]
    if not used:
        return True
    if any(type(branch) is not Branch or branch.work == 0.0 for branch in used):
        return False
    # (P of s⁴ + P s + Q: the relation's form for floats, the same expression as its NumPy form's, the same bits)
    linears = {id(branch): branch.quartic_linear for branch in used}
    table = np.array([_radius_row(model.grow if branch is None else branch, span, branch is not None, linears)
                      for span, branch in zip(members, of_span)], dtype=float).T
    linear, jump_off, floor, start, start_tolerance, end, end_tolerance, which, is_moving = np.repeat(table, lengths,
                                                                                                   axis=1)
    inside = is_moving != 0.0
    depth = np.maximum(d, jump_off)
    root = np.maximum(depressed_quartic_root(linear, -model.params.R * depth), floor)
    radii = np.where(depth >= jump_off, root * root, np.nan)
    # (a sample at a span's end, to END_ULPS of its depth, takes the iteration's radius: _sampled_radii's rule)
    ends = np.flatnonzero(inside & ((np.abs(depth - start) <= start_tolerance) |
                                    (np.abs(depth - end) <= end_tolerance)))
    cube = root**3
    near = np.flatnonzero(inside & (4.0 * cube + linear < NEAR_FOLD * 4.0 * cube))
    # (the few samples at an end or near the fold by their indices, in order: the elements a mask picks, in its order)
    for regime, branch in branches:  # (each regime's spans together, as _sampled_radii takes them)
        mine = float(regime is Regime.SHRINKING)
        at_end, near_fold = ends[which[ends] == mine], near[which[near] == mine]
        if not set(near_fold.tolist()) - set(at_end.tolist()):  # (each an end, whose iterated radius replaces it:
            near_fold = near_fold[:0]                            # no iteration to run)
        _refine(branch, depth, radii, near_fold, at_end)
    np.copyto(a, radii, where=inside)
    return True


def _radius_row(branch: Branch, span: Span, is_moving: bool, linears: dict[int, float]) -> tuple:
    """A span's numbers for :func:`_quartic_radii`: its branch's quartic coefficient (``linears``, by the branch's
    ``id``; a pinned span's any), jump-off depth and floor, its depths at its start and end with their tolerances
    (:data:`END_ULPS` ulp, :func:`_at_ends`'), which branch (1: the shrinking one) and whether it moves."""
    linear = linears.get(id(branch), 0.0) if is_moving else next(iter(linears.values()))
    start, end = span.segment.d(span.t_start), span.segment.d(span.t_end)
    return (linear, branch.jump_off_depth, branch.root_floor, start, END_ULPS * math.ulp(abs(start)), end,
            END_ULPS * math.ulp(abs(end)), float(span.regime is Regime.SHRINKING), float(is_moving))


def _refine(branch: Branch, depth: np.ndarray, radii: np.ndarray, near: np.ndarray, ends: np.ndarray) -> None:
    """The radii of one branch's samples near its fold and at its spans' ends (``near``, ``ends``: their indices, in
    order) taken from the iteration (:meth:`~.branch.Branch.near_fold_radii`, :func:`_iterated_radii`), in place."""
    if near.size:
        radii[near] = branch.near_fold_radii(depth[near])
    if ends.size:
        radii[ends] = _iterated_radii(branch, depth[ends])
