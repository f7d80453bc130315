"""The continuum solution of a path: spans with their interpolants and the event log, and what is read
off them (:func:`evaluate`, :func:`extremum`, :func:`algebraic_tangential_force`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np
from scipy import optimize

from mdr_events.contact.adhesion import Adhesion
from mdr_events.parameters import Parameters
from mdr_events.validation import check_real, real_array, shown
from .dense import cut, force_values
from .span_forces import span_forces
from .span_sliding import span_sliding_lengths, takes_batch
from .graded import natural_variable, span_variable
from .model import ContinuumModel
from .span import Span, Variable
from .state import CONTACT_ENDING, Event, Regime
from .stationary import never_stationary, stationary_points


@dataclass
class PathSolution:
    """The continuum solution of one path.

    Parameters
    ----------
    model : ContinuumModel
        The branches and the cap the spans are evaluated with.
    spans : list of Span, optional
        Consecutive spans, each with one radius regime and the interpolant of ``F_x`` (default none yet).
    events : list of Event, optional
        The event log (times from first contact; default none yet).
    t_contact : float, default 0.0
        Time of first contact on the path (s); the solution's times count from it.
    end_time : float, default 0.0
        End of the run (s from first contact): the pull-off, or the end of the path.
    path : Path, optional
        The path solved (a referee checks that a solution at hand is of the path it judges).
    compressed : PathSolution, optional
        Coulomb's law alone with adhesion (:func:`~.caps.compressed_zone_alone`): the run of the compressed zone, the
        same path without adhesion, whose tangential force, work and slip are the contact's (its springs in tension
        slide with no shift); ``None`` otherwise.
    """

    model: ContinuumModel
    spans: list[Span] = field(default_factory=list)
    events: list[Event] = field(default_factory=list)
    t_contact: float = 0.0
    end_time: float = 0.0
    path: object = None
    compressed: "PathSolution | None" = None

    @property
    def params(self) -> Parameters:
        """The parameters of the model solved (``model.params``)."""
        return self.model.params

    @property
    def ended_by_contact(self) -> bool:
        """The run ended because the contact came apart (not at the end of the path)."""
        return bool(self.events) and self.events[-1].kind in CONTACT_ENDING

    @property
    def events_not_timed(self) -> dict[str, str]:
        """The events whose time a sampled run cannot show at the order of its resolution, with why: none (the
        paper's radius leaves its events at a finite rate)."""
        return {}

    @property
    def profile(self):
        """The indenter solved (``model.profile``; ``None``: the paraboloid of ``params.R``)."""
        return self.model.profile

    @property
    def friction(self):
        """The friction law solved (``model.friction``)."""
        return self.model.friction

    @property
    def adhesion(self) -> Adhesion:
        """The adhesion law solved: the paper's, of the parameters' works of adhesion."""
        return Adhesion(self.params.dgamma0, self.params.dgamma1)

    def evaluate_at(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The quantities at ``times`` (s from first contact): :func:`evaluate` of this solution.

        Parameters
        ----------
        times : numpy.ndarray
            The times (s from first contact).

        Returns
        -------
        dict of str to numpy.ndarray
            Each of :data:`EVALUATED_QUANTITIES` at ``times``.
        """
        return evaluate(self, times)

    def normal_force_at(self, event: Event) -> float:
        """``F_N`` at ``event``, of its depth and radius.

        Parameters
        ----------
        event : Event
            An event of :attr:`events`.

        Returns
        -------
        float
            The normal force (N).
        """
        return float(self.model.normal_force(event.depth, event.radius))

    def span_index(self, times: np.ndarray) -> np.ndarray:
        """Index of the span that holds each time (s from first contact): the first span ending at or
        after it (the last span for times beyond the run), except that the instant a contact is made
        belongs to the span after the approach.

        Parameters
        ----------
        times : array_like
            Times (s from first contact).

        Returns
        -------
        numpy.ndarray of int
            The index into :attr:`spans` of each time.
        """
        times = np.asarray(times, dtype=float)
        ends = np.array([span.t_end for span in self.spans]) - self.t_contact
        index = np.minimum(np.searchsorted(ends, times, side="left"), len(self.spans) - 1)
        # at the instant of a (re-)contact the contact is made: the span after an approach holds it
        approach = np.array([span.regime is Regime.NONE for span in self.spans])
        at_contact = approach[index] & (index < len(self.spans) - 1) & (times == ends[index])
        return np.where(at_contact, index + 1, index)


#: Quantities :func:`evaluate` fills, in its output order.
EVALUATED_QUANTITIES = ("indentation_depth", "tangential_displacement", "normal_force", "tangential_force",
                        "contact_radius", "sliding_fraction")


#: A sample whose depth is within this many ulp of its span's end depth is read as that end (:func:`_span_radius`): a
#: time from first contact and back rounds the depth by an ulp or two.
END_ULPS = 4


def _span_radius(model, span: Span, d: np.ndarray, sampled: bool = False) -> np.ndarray:
    """The contact radius of a span in contact at the depths ``d``: on its branch of (9), or pinned; ``sampled``: by
    the branch's :meth:`~.branch.Branch.sample_radii` (a run's samples: the closed form where there is one)."""
    if span.regime is not Regime.GROWING and span.regime is not Regime.SHRINKING:
        return np.full(np.shape(d), span.pinned_radius)
    if not sampled:
        branch = model.grow if span.regime is Regime.GROWING else model.shrink
        return branch.radii(np.maximum(d, branch.jump_off_depth))
    return _sampled_radii(model, [span], [d])[0]


def _sampled_radii(model, spans: list[Span], depths: list[np.ndarray]) -> list[np.ndarray]:
    """The sampled radii (:func:`_span_radius`) of several moving spans of one branch at their depths, in one call of
    the branch's :meth:`~.branch.Branch.sample_radii` and at most one of its iteration (each element alone: the same
    values as span by span, but where the iteration runs for several elements at once, at a span's end or near the
    fold, to its stopping step)."""
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
        radii[ends] = branch.radii(depth[ends])
    return _split(radii, [len(d) for d in depths])


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


def _split(values: np.ndarray, lengths: list[int]) -> list[np.ndarray]:
    """``values`` cut into consecutive parts of ``lengths`` (views)."""
    return cut(values, lengths) if len(lengths) > 1 else [values]


def contact_radii(solution: PathSolution, times: np.ndarray) -> np.ndarray:
    """The contact radius at ``times`` (s from first contact, within the run), as :func:`evaluate` gives it, alone."""
    times = np.asarray(times, dtype=float)
    out = np.zeros(times.shape)
    owner = solution.span_index(times)
    for index in np.unique(owner):
        span, rows = solution.spans[index], owner == index
        if span.regime is not Regime.NONE:
            out[rows] = _span_radius(solution.model, span, span.segment.d(solution.t_contact + times[rows]),
                                     sampled=True)
    return out


def evaluate_span(solution: PathSolution, index: int, times: np.ndarray, sliding: bool = True,
                  zone: dict[str, np.ndarray] | None = None, radii: np.ndarray | None = None,
                  normal: bool = True, tangential: bool = True) -> dict[str, np.ndarray]:
    """Every quantity of :data:`EVALUATED_QUANTITIES` at ``times`` (s from first contact) within span
    ``index``, as a vectorised function of time: the kinematics are linear, the radius follows its
    branch of (9) (or is pinned; ``radii``, where given, are the radii at ``times``), ``F_N`` is (10), ``F_x`` is
    the span's interpolant and the sliding fraction is the slip front of the span's anchor map. ``zone``: the
    compressed zone's run already evaluated at ``times`` (:func:`evaluate` fills it once for every span).

    Parameters
    ----------
    solution : PathSolution
        The solution.
    index : int
        The span's index in ``solution.spans``.
    times : numpy.ndarray
        Times within the span (s from first contact).
    sliding : bool, default True
        Whether to evaluate the sliding fraction (the slip fronts of the span's anchor map); without it a span in
        contact leaves ``sliding_fraction`` out.
    zone : dict of str to numpy.ndarray, optional
        The compressed zone's run evaluated at ``times`` (Coulomb's law alone with adhesion).
    radii : numpy.ndarray, optional
        The contact radii at ``times`` (m), where already known.
    normal : bool, default True
        Whether to evaluate ``F_N``; without it a span in contact leaves ``normal_force`` out (:func:`evaluate` and
        :func:`scan_spans` fill it for every span at once, :func:`_fill_normal_force`).
    tangential : bool, default True
        Whether to read ``F_x`` off the span's interpolant; without it a span in contact whose force is not constant
        (and not the compressed zone's) leaves ``tangential_force`` out (:func:`evaluate` and :func:`scan_spans` read
        every span's at once, :func:`_fill_tangential_force`).

    Returns
    -------
    dict of str to numpy.ndarray
        The quantities of :data:`EVALUATED_QUANTITIES` at ``times`` (SI units; ``sliding_fraction`` and
        ``normal_force`` as above).
    """
    model = solution.model
    span = solution.spans[index]
    t = solution.t_contact + np.asarray(times, dtype=float)
    d, x = span.segment.d(t), span.segment.x(t)
    out = {"indentation_depth": d, "tangential_displacement": x}
    if span.regime is Regime.NONE:
        zero = np.zeros(t.shape)
        out.update(normal_force=zero, tangential_force=zero, contact_radius=zero,
                   sliding_fraction=np.full(t.shape, np.nan))
        return out
    a = np.asarray(radii, dtype=float) if radii is not None else _span_radius(model, span, d, sampled=True)
    out["contact_radius"] = a
    if normal:
        out["normal_force"] = np.asarray(model.normal_force(d, a), dtype=float)  # (10)
    if span.interpolant is None:
        out["tangential_force"] = np.full(t.shape, span.force)
    elif tangential or solution.compressed is not None:  # (the compressed zone's replaces it below)
        out["tangential_force"] = force_values(span.interpolant, _force_variable(span, t, a))
    if solution.compressed is not None:
        out["tangential_force"], zone_sliding = _compressed_zone(solution.compressed, times, a, zone)
        if sliding:
            out["sliding_fraction"] = zone_sliding
        return out
    if sliding:
        out["sliding_fraction"] = _sliding_fraction(model, span, x, d, a)
    return out


def _sliding_fraction(model: ContinuumModel, span: Span, x: np.ndarray, d: np.ndarray, a: np.ndarray) -> np.ndarray:
    """The share of a span's contact whose springs slide at the positions ``x``, depths ``d`` and radii ``a``: the slip
    fronts of its anchor map (or its layouts), ``min(length / a, 1)`` where ``a > 0``, ``nan`` elsewhere."""
    return _fraction(_sliding_length(model, span, x, d, a), a)


def _sliding_length(model: ContinuumModel, span: Span, x: np.ndarray, d: np.ndarray, a: np.ndarray) -> np.ndarray:
    """The length (m) of a span's springs at either cap (its zones' or its anchor map's ``sliding_length``)."""
    return (span.zones if span.zones is not None else span.anchors).sliding_length(model.caps, x, d, a)


def _fraction(zones: np.ndarray, a: np.ndarray) -> np.ndarray:
    """``min(zones / a, 1)`` where ``a > 0``, ``nan`` elsewhere."""
    # (computed only where a > 0: no warning to silence)
    fraction, positive = np.full(np.shape(a), np.nan), a > 0
    np.divide(zones, a, out=fraction, where=positive)
    return np.minimum(fraction, 1.0, out=fraction, where=positive)


def _force_variable(span: Span, t: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """The variable a span's interpolant of ``F_x`` is read at, at the path's times ``t`` and the radii there: the
    time, or the radius over the span's scale (on a graded span its ``u``)."""
    return span_variable(span, radius / span.scale if span.variable is Variable.RADIUS else t)


def _fill_tangential_force(solution: PathSolution, indices: list[int], times: list[np.ndarray],
                           filled: list[dict[str, np.ndarray]]) -> None:
    """``F_x`` of the spans ``indices`` evaluated without it (:func:`evaluate_span`'s ``tangential=False``) at their
    ``times`` (s from first contact), all at once by the kinds of their interpolants (:func:`~.span_forces.span_forces`:
    the values of a call per span, bit for bit); each span's dict of ``filled`` gains it."""
    missing = [k for k, values in enumerate(filled) if "tangential_force" not in values]
    if not missing:
        return
    spans = [solution.spans[indices[k]] for k in missing]
    points = [_force_variable(span, solution.t_contact + np.asarray(times[k], dtype=float),
                              filled[k]["contact_radius"]) for span, k in zip(spans, missing)]
    for k, force in zip(missing, span_forces([span.interpolant for span in spans], points)):
        filled[k]["tangential_force"] = force


def _compressed_zone(zone: PathSolution, times: np.ndarray, radius: np.ndarray,
                     filled: dict[str, np.ndarray] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The tangential force of the compressed zone's run ``zone`` at ``times`` (0 where the zone has no contact) and
    the sliding fraction of the contact of radius ``radius``: the zone's sliding springs and every spring in tension
    (``x_c < ξ < a``: a zero cap); ``filled``: the zone's run evaluated at ``times`` already."""
    if filled is None:
        filled = evaluate(zone, np.atleast_1d(np.asarray(times, dtype=float)))
    force = np.nan_to_num(filled["tangential_force"])
    x_c = np.nan_to_num(filled["contact_radius"])
    sliding_springs = np.nan_to_num(filled["sliding_fraction"]) * x_c + (radius - x_c)
    with np.errstate(invalid="ignore", divide="ignore"):
        return force, np.where(radius > 0, np.clip(sliding_springs / radius, 0.0, 1.0), np.nan)


def sample_times(ends: list[float], path_ends: list[float], samples: int) -> np.ndarray:
    """The output times of a run of ``samples`` (s from first contact): to the longest run's end and one spacing
    beyond (a sample after the contact has ended), but not beyond its path's end (a run that ended in contact wrote
    every quantity, the depth too, as ``nan`` there).

    Parameters
    ----------
    ends : list of float
        Each case's end (s from its first contact).
    path_ends : list of float
        Each case's path's end (s from its first contact).
    samples : int
        The number of times.

    Returns
    -------
    numpy.ndarray
        The times.
    """
    last = max(min(end * (1.0 + 1.0 / samples), path_end) for end, path_end in zip(ends, path_ends))
    return np.linspace(0.0, last, samples)


def check_times(name: str, times, earliest: float = 0.0) -> np.ndarray:
    """``times`` (s from first contact) as a float array of one dimension at most, every entry finite and from
    ``earliest`` on; else ``TypeError`` or ``ValueError`` naming the argument (a time before the path's start was
    extrapolated to, a string or a 2-D grid was a raw error of NumPy's)."""
    values = real_array(name, times, "times in s from first contact (real numbers)")
    if values.ndim > 1 or not np.all(np.isfinite(values)) or np.any(values < earliest):
        raise ValueError(f"{name}={shown(times)} is not allowed; allowed: one time or a 1-D array of finite times "
                         f">= {earliest:.9g} (s from first contact: the path's start; the solution says nothing "
                         "before it)")
    return values


def evaluate(solution: PathSolution, times: np.ndarray) -> dict[str, np.ndarray]:
    """Fill a time grid (s from first contact) span by span (:func:`evaluate_span`).

    Samples before the first contact are out of contact (the path's depth and position, forces and radius 0, the
    sliding fraction ``nan``); samples after the end of the run are ``nan``, except the first sample after a pull-off
    if it lies on the pull-off's path segment, which shows the contact gone (forces and radius 0). Times before the
    path's start (that of ``solution.path``, else the first contact), or that are no finite numbers, are refused
    (:func:`check_times`).

    Parameters
    ----------
    solution : PathSolution
        The solution.
    times : array_like
        The time grid (s from first contact).

    Returns
    -------
    dict of str to numpy.ndarray
        Each of :data:`EVALUATED_QUANTITIES` at ``times`` (SI units).

    Raises
    ------
    ValueError
        Times before the path's start, or not finite.
    """
    start = -solution.t_contact if solution.path is not None else 0.0
    times = np.atleast_1d(check_times("times", times, start))
    out = {name: np.full(len(times), np.nan) for name in EVALUATED_QUANTITIES}
    before = times < 0.0
    if np.any(before):  # (the spans begin at the first contact: the first one was extrapolated back)
        out["tangential_displacement"][before], out["indentation_depth"][before] = \
            solution.path.position(solution.t_contact + times[before])
        for name in ("normal_force", "tangential_force", "contact_radius"):
            out[name][before] = 0.0
    inside = (times <= solution.end_time) & ~before
    owner = solution.span_index(times)
    after_end = np.flatnonzero(~inside & ~before)
    last = solution.spans[-1].segment
    if solution.ended_by_contact and after_end.size and solution.t_contact + times[after_end[0]] <= last.t1:
        first = after_end[0]
        t = solution.t_contact + times[first]
        out["indentation_depth"][first] = last.d(t)
        out["tangential_displacement"][first] = last.x(t)
        for name in ("normal_force", "tangential_force", "contact_radius"):
            out[name][first] = 0.0
    spans_rows = _span_rows(owner, inside, len(solution.spans))
    if solution.compressed is None:
        _fill_spans(solution, times, spans_rows, out)
        return out
    # the compressed zone's run (Coulomb's law alone with adhesion) evaluated once, not span by span
    zone = evaluate(solution.compressed, times)
    radii = _moving_radii(solution, times, spans_rows)
    filled = [evaluate_span(solution, index, times[rows], zone={name: values[rows] for name, values in zone.items()},
                            radii=radii.get(index), normal=False, tangential=False) for index, rows in spans_rows]
    _fill_tangential_force(solution, [index for index, _ in spans_rows], [times[rows] for _, rows in spans_rows],
                           filled)
    _fill_normal_force(solution.model, filled)
    for (_, rows), span in zip(spans_rows, filled):
        for name, values in span.items():
            out[name][rows] = values
    return out


def _fill_spans(solution: PathSolution, times: np.ndarray, spans_rows: list[tuple[int, slice | np.ndarray]],
                out: dict[str, np.ndarray]) -> None:
    """:func:`evaluate`'s quantities of the spans ``spans_rows`` (:func:`_span_rows`) written into ``out``, the spans in
    contact all at once: their kinematics with each span's segment's numbers over its samples, the radii of each
    branch in one call (:func:`_sampled_radii`), ``F_N`` in one call, ``F_x`` by the kinds of the interpolants
    (:func:`~.span_forces.span_forces`) and the sliding fraction of the spans' anchor maps together
    (:func:`~.span_sliding.span_sliding_lengths`); each value the one :func:`evaluate_span` gives the span alone (the
    same operations, element by element). An approach (no contact) is its own call."""
    spans, model = solution.spans, solution.model
    contact = []
    for index, rows in spans_rows:
        if spans[index].regime is Regime.NONE:
            for name, values in evaluate_span(solution, index, times[rows]).items():
                out[name][rows] = values
        else:
            contact.append((index, rows))
    if not contact:
        return
    members = [spans[index] for index, _ in contact]
    parts = [times[rows] for _, rows in contact]
    lengths = [len(part) for part in parts]
    t = solution.t_contact + (np.concatenate(parts) if len(parts) > 1 else parts[0])
    segments = [span.segment for span in members]

    def each(values: list[float]) -> np.ndarray:  # (a span's number over its samples)
        return np.repeat(np.array(values, dtype=float), lengths)

    elapsed = t - each([segment.t0 for segment in segments])
    d = each([segment.ds for segment in segments]) + each([segment.vd for segment in segments]) * elapsed  # Segment.d
    x = each([segment.xs for segment in segments]) + each([segment.vx for segment in segments]) * elapsed  # Segment.x
    a = each([span.pinned_radius for span in members])
    bounds = np.cumsum([0] + lengths)
    where = [slice(int(lower), int(upper)) for lower, upper in zip(bounds[:-1], bounds[1:])]
    for regime in (Regime.GROWING, Regime.SHRINKING):
        moving = [k for k, span in enumerate(members) if span.regime is regime]
        if moving:
            for k, radii in zip(moving, _sampled_radii(model, [members[k] for k in moving],
                                                       [d[where[k]] for k in moving])):
                a[where[k]] = radii
    filled = {"indentation_depth": d, "tangential_displacement": x, "contact_radius": a,
              "normal_force": np.asarray(model.normal_force(d, a), dtype=float),  # (10)
              "tangential_force": _tangential_forces(members, t, a, where),
              "sliding_fraction": _sliding_fractions(model, members, x, d, a, where)}
    target = _rows_of(contact)
    for name, values in filled.items():
        out[name][target] = values


def _tangential_forces(spans: list[Span], t: np.ndarray, a: np.ndarray, where: list[slice]) -> np.ndarray:
    """``F_x`` of spans in contact at their samples (each span's ``where`` in ``t`` and ``a``): a constant force where
    a span has no interpolant, the others' interpolants by their kinds (:func:`~.span_forces.span_forces`)."""
    force = np.repeat(np.array([span.force for span in spans], dtype=float), [part.stop - part.start
                                                                               for part in where])
    read = [k for k, span in enumerate(spans) if span.interpolant is not None]
    values = span_forces([spans[k].interpolant for k in read],
                         [_force_variable(spans[k], t[where[k]], a[where[k]]) for k in read])
    for k, value in zip(read, values):
        force[where[k]] = value
    return force


def _sliding_fractions(model: ContinuumModel, spans: list[Span], x: np.ndarray, d: np.ndarray, a: np.ndarray,
                       where: list[slice]) -> np.ndarray:
    """:func:`_sliding_fraction` of spans in contact at their samples (each span's ``where``): the spans whose anchor
    maps share one attachment branch together (:func:`~.span_sliding.span_sliding_lengths`), any other alone."""
    together = [k for k, span in enumerate(spans) if takes_batch(span) and span.anchors.attach is
                spans[0].anchors.attach]
    zones = np.empty(a.shape)
    for k in sorted(set(range(len(spans))) - set(together)):
        zones[where[k]] = _sliding_length(model, spans[k], x[where[k]], d[where[k]], a[where[k]])
    if together:
        rows = _rows_of([(k, where[k]) for k in together])
        zones[rows] = span_sliding_lengths(model.caps, [spans[k].anchors for k in together], x[rows], d[rows], a[rows],
                                           [where[k].stop - where[k].start for k in together])
    return _fraction(zones, a)


def _rows_of(spans_rows: list[tuple[int, slice | np.ndarray]]) -> slice | np.ndarray:
    """The rows of several spans (:func:`_span_rows`) together, in order: one slice where they are consecutive
    slices, else their indices."""
    parts = [rows for _, rows in spans_rows]
    if all(type(rows) is slice for rows in parts) and all(lower.stop == upper.start for lower, upper in
                                                          zip(parts[:-1], parts[1:])):
        return slice(parts[0].start, parts[-1].stop)
    return np.concatenate([np.arange(rows.start, rows.stop) if type(rows) is slice else rows for rows in parts])


def _fill_normal_force(model: ContinuumModel, filled: list[dict[str, np.ndarray]]) -> list[np.ndarray]:
    """``F_N`` (10) of spans evaluated without it (:func:`evaluate_span`'s ``normal=False``), in one call of the model's
    normal force over all their samples in contact (element by element: the same values as span by span); each span's
    dict gains it, and the list of each span's is returned."""
    contact = [span for span in filled if "normal_force" not in span]
    if contact:
        depth, radius = (np.concatenate([span[name] for span in contact])
                         for name in ("indentation_depth", "contact_radius"))
        force = np.asarray(model.normal_force(depth, radius), dtype=float)  # (10)
        for span, part in zip(contact, _split(force, [len(span["contact_radius"]) for span in contact])):
            span["normal_force"] = part
    return [span["normal_force"] for span in filled]


def _moving_radii(solution: PathSolution, times: np.ndarray,
                  spans_rows: list[tuple[int, slice | np.ndarray]]) -> dict[int, np.ndarray]:
    """The radii at ``times`` of each moving span of ``spans_rows`` (:func:`_span_rows`) by its index, each branch's
    spans at once (:func:`_sampled_radii`: its closed form called once, not once per span)."""
    found = {}
    for regime in (Regime.GROWING, Regime.SHRINKING):
        members = [(index, rows) for index, rows in spans_rows if solution.spans[index].regime is regime]
        if not members:
            continue
        spans = [solution.spans[index] for index, _ in members]
        depths = [span.segment.d(solution.t_contact + times[rows]) for span, (_, rows) in zip(spans, members)]
        found.update(zip([index for index, _ in members], _sampled_radii(solution.model, spans, depths)))
    return found


def _span_rows(owner: np.ndarray, inside: np.ndarray, count: int) -> list[tuple[int, slice | np.ndarray]]:
    """The rows of each of ``count`` spans that holds a time ``inside`` the run (``owner``: the span of each time), in
    the spans' order: slices where the times inside are one block with their spans in order (increasing times, as
    a run's samples are: views, not copies gathered and scattered back), else the indices of each span's rows."""
    rows = np.flatnonzero(inside)
    if not rows.size:
        return []
    owners = owner[rows]
    if rows[-1] - rows[0] == rows.size - 1 and np.all(owners[1:] >= owners[:-1]):
        edges = rows[0] + np.searchsorted(owners, np.arange(count + 1))
        return [(index, slice(int(lower), int(upper))) for index, (lower, upper) in enumerate(zip(edges[:-1],
                                                                                                  edges[1:]))
                if upper > lower]
    return [(index, rows[owners == index]) for index in range(count) if np.any(owners == index)]


#: Quantities :func:`extremum` finds the extremes of; the means are per contact area ``π a²``.
EXTREMUM_QUANTITIES = ("normal_force", "tangential_force", "contact_radius", "contact_area",
                       "mean_pressure", "mean_shear_stress")
#: Points per span at which :func:`extremum` brackets an extremum before refining it.
EXTREMUM_GRID = 65
#: Values within this share of the extremum are ties (rounding), of which :func:`extremum` reports the earliest.
EXTREMUM_TIE = 1e-12
#: Span-relative time accuracy of the refined extremum; the value is then exact to rounding
#: (it is flat there: its error is second order in the time error).
EXTREMUM_XTOL = 1e-12


def within_tie(value: float, best: float, size: float) -> bool:
    """Whether ``value`` ties ``best`` to rounding: within :data:`EXTREMUM_TIE` of the quantity's ``size`` along the
    run (or of ``|best|``, the larger), so that a value near 0 is held to its run's rounding, not to its own. The one
    rule of :func:`extremum` (the earliest of the spans' ties; a stationary point replaces a span's best scanned point
    only where that point does not tie it) and of the rate run's refinement
    (:func:`~mdr_events.models.continuum.rate_run.rate_extrema`: a stationary point that the scan's point ties leaves
    the scan's point).

    Parameters
    ----------
    value, best : float
        The value and the best one, signed so that larger is better.
    size : float
        The quantity's largest magnitude along the run.

    Returns
    -------
    bool
        ``True`` if ``value >= best − EXTREMUM_TIE · max(size, |best|)``.
    """
    return value >= best - EXTREMUM_TIE * max(size, abs(best))


def _quantity(filled: dict[str, np.ndarray], quantity: str) -> np.ndarray:
    if quantity in filled:
        return filled[quantity]
    area = np.pi * filled["contact_radius"] ** 2
    if quantity == "contact_area":
        return area
    force = filled["normal_force" if quantity == "mean_pressure" else "tangential_force"]
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(area > 0, force / area, np.nan)


class ExtremumScan(NamedTuple):
    """Every span sampled at :data:`EXTREMUM_GRID` times (s from first contact), with the quantities
    :func:`extremum` reads (the sliding fraction left out); ``matrices``: each quantity's scan as one matrix with what
    both extremes read of it (:class:`ScanMatrix`), filled as :func:`extremum` asks (``None``: none kept)."""

    times: list[np.ndarray]
    values: list[dict[str, np.ndarray]]
    matrices: dict[str, "ScanMatrix"] | None = None


class ScanMatrix(NamedTuple):
    """One quantity of an :class:`ExtremumScan`, every span a row padded with ``nan``: what the maximum and the minimum
    both read (the sign applied to ``matrix`` alone, each change and magnitude the same for either)."""

    matrix: np.ndarray
    largest: np.ndarray
    reach: np.ndarray
    size: float


def scan_spans(solution: PathSolution) -> ExtremumScan:
    """Sample every span for :func:`extremum` (one scan serves every quantity and both extremes): evenly in
    time on a pinned radius, evenly in the radius on a moving one (the variable of its interpolant; the time
    of each radius that of its depth on the branch, which needs no root).

    The grids of all spans are built at once (:func:`_scan_grids`: each branch's depths in one call, the grids as the
    rows of one matrix), then each span's kinematics (:func:`evaluate_span`), ``F_x`` of all of them by the kinds of
    their interpolants (:func:`_fill_tangential_force`) and ``F_N`` in one call (:func:`_fill_normal_force`); every
    value is the one a span alone would give."""
    grids, radii = _scan_grids(solution)
    pinned = _pinned_kinematics(solution, dict(enumerate(grids))) if solution.compressed is None else {}
    values = [pinned[index] if index in pinned else
              evaluate_span(solution, index, grid, sliding=False, radii=radius, normal=False, tangential=False)
              for index, (grid, radius) in enumerate(zip(grids, radii))]
    _fill_tangential_force(solution, list(range(len(grids))), grids, values)
    _fill_normal_force(solution.model, values)
    return ExtremumScan(grids, values, {})


def _scan_grids(solution: PathSolution) -> tuple[list[np.ndarray], list[np.ndarray | None]]:
    """Each span's scan times (s from first contact) and, on a moving span, the radii there (``None`` elsewhere):
    :data:`EXTREMUM_GRID` points on a span of positive length, its start alone on one of none. A pinned span's times
    evenly spaced (``np.linspace``); a moving span's radii evenly spaced from the radius at its start to that at its
    end (roots of their depths: :meth:`~.branch.Branch.radius`, each depth once, a span's end being the next span's
    start) and the time of each radius that of its depth on the branch, made non-decreasing, as
    :func:`_radius_grid` gives them span by span (``tests/models/test_extremum_scan.py`` compares the two)."""
    spans, t_contact = solution.spans, solution.t_contact
    bounds = [(span.t_start - t_contact, span.t_end - t_contact) for span in spans]
    grids: list = [None] * len(spans)
    radii: list = [None] * len(spans)
    roots: dict = {}  # (the branch, the depth) -> the radius
    for regime in (Regime.GROWING, Regime.SHRINKING):
        members = [index for index, span in enumerate(spans) if span.regime is regime]
        if not members:
            continue
        branch, rtol = solution.model.branch(regime), solution.model.tolerances.radius_rtol

        def root(index: int, t: float) -> float:
            depth = max(float(spans[index].segment.d(t_contact + t)), branch.jump_off_depth)
            if depth not in roots:
                roots[depth] = branch.radius(depth, rtol)
            return roots[depth]

        whole = [index for index in members if bounds[index][1] > bounds[index][0]]
        for index in members:
            if index not in whole:  # (a span of no length: its start alone)
                grids[index], radii[index] = np.array([bounds[index][0]]), np.array([root(index, bounds[index][0])])
        if whole:
            _moving_grids(solution, branch, whole, [[root(index, t) for t in bounds[index]] for index in whole],
                          grids, radii)
        roots.clear()  # (the other branch's radii are other roots)
    rest = [index for index in range(len(spans)) if grids[index] is None and bounds[index][1] > bounds[index][0]]
    if rest:  # (the pinned spans and the approach: their times evenly spaced, as the rows of one matrix)
        lower, upper = (np.array([bounds[index][k] for index in rest]) for k in (0, 1))
        for index, row in zip(rest, _linspace_rows(lower, upper, EXTREMUM_GRID)):
            grids[index] = row
    for index in range(len(spans)):
        if grids[index] is None:  # (a span of no length: its start alone)
            grids[index] = np.array([bounds[index][0]])
    return grids, radii


def _moving_grids(solution: PathSolution, branch, members: list[int], ends: list[list[float]], grids: list,
                  radii: list) -> None:
    """:func:`_scan_grids` of the moving spans ``members`` of one branch with the radii at their ``ends``: their radii
    and times as the rows of two matrices, the depths of all their inner radii in one call of the branch's
    :meth:`~.branch.Branch.depths` (element by element: the values of a call per span); each row stored in ``grids``
    and ``radii`` at its span's index."""
    spans, t_contact = solution.spans, solution.t_contact
    start, stop = (np.array([end[k] for end in ends]) for k in (0, 1))
    matrix = _linspace_rows(start, stop, EXTREMUM_GRID)
    depths = branch.depths(np.ascontiguousarray(matrix[:, 1:-1]).reshape(-1)).reshape(len(members), -1)
    segments = [spans[index].segment for index in members]
    t0, ds, vd = (np.array([getattr(segment, name) for segment in segments])[:, None] for name in ("t0", "ds", "vd"))
    lower = np.array([spans[index].t_start - t_contact for index in members])[:, None]
    upper = np.array([spans[index].t_end - t_contact for index in members])[:, None]
    inner = (t0 + (depths - ds) / vd) - t_contact  # (Segment.time_at_depth, row by row)
    times = np.concatenate([lower, np.clip(inner, lower, upper), upper], axis=1)
    np.maximum.accumulate(times, axis=1, out=times)
    for row, index in enumerate(members):
        grids[index], radii[index] = times[row], matrix[row]


def _pinned_kinematics(solution: PathSolution, grids: dict[int, np.ndarray]) -> dict[int, dict[str, np.ndarray]]:
    """:func:`evaluate_span` (``sliding``, ``normal`` and ``tangential`` off) of the pinned spans among ``grids`` (a
    span's index -> its times, s from first contact), all at once: the depth ``ds + vd (t − t0)``, the position
    ``xs + vx (t − t0)`` with each span's segment's numbers over its times, the pinned radius, and a constant force;
    each value the one of a call per span (the same operations, element by element). By the span's index; none where
    there is one pinned span alone (its own call costs less)."""
    spans = solution.spans
    members = [index for index in grids if spans[index].regime is Regime.PINNED]
    if len(members) < 2:  # (one span alone: evaluate_span's own call)
        return {}
    lengths = [len(grids[index]) for index in members]

    def each(values: list[float]) -> np.ndarray:  # (a span's number over its times)
        return np.repeat(np.array(values, dtype=float), lengths)

    segments = [spans[index].segment for index in members]
    t = solution.t_contact + np.concatenate([grids[index] for index in members])
    elapsed = t - each([segment.t0 for segment in segments])
    columns = {"indentation_depth": each([segment.ds for segment in segments]) + each([segment.vd for segment in
                                                                                       segments]) * elapsed,
               "tangential_displacement": each([segment.xs for segment in segments]) + each([segment.vx for segment
                                                                                             in segments]) * elapsed,
               "contact_radius": each([spans[index].pinned_radius for index in members])}
    parts = {name: _split(values, lengths) for name, values in columns.items()}
    out = {}
    for k, index in enumerate(members):
        out[index] = {name: parts[name][k] for name in columns}
        if spans[index].interpolant is None:
            out[index]["tangential_force"] = np.full(lengths[k], spans[index].force)
    return out


def _linspace_rows(start: np.ndarray, stop: np.ndarray, count: int) -> np.ndarray:
    """``np.linspace(start[i], stop[i], count)`` as the rows of one matrix, each row the values ``np.linspace`` gives
    it alone (its own step: ``np.linspace`` of arrays takes the denormal route for every row if any row's step is 0)."""
    delta = stop - start
    positions = np.arange(count, dtype=float)
    step = delta / (count - 1)
    rows = positions[None, :] * step[:, None]
    zero = step == 0
    if zero.any():  # (np.linspace's route for a step of 0: the positions over the divisions, times the difference)
        rows[zero] = (positions / (count - 1))[None, :] * delta[zero][:, None]
    rows += start[:, None]
    rows[:, -1] = stop
    return rows


def _radius_grid(solution: PathSolution, span: Span, lower: float, upper: float,
                 count: int) -> tuple[np.ndarray, np.ndarray]:
    """``count`` radii evenly from the radius at ``lower`` to that at ``upper`` (s from first contact; the
    span's ends, whose radii are roots of their depths) along the span's branch, and their times (in
    ``[lower, upper]``, non-decreasing): a moving span's scan alone (:func:`_scan_grids` builds every span's at once;
    this one its reference in the tests)."""
    branch, rtol = solution.model.branch(span.regime), solution.model.tolerances.radius_rtol
    ends = [branch.radius(max(float(span.segment.d(solution.t_contact + t)), branch.jump_off_depth), rtol)
            for t in (lower, upper)]
    radii = np.linspace(ends[0], ends[1], count)
    inner = span.segment.time_at_depth(branch.depths(radii[1:-1])) - solution.t_contact
    grid = np.concatenate([[lower], np.clip(inner, lower, upper), [upper]]) if count > 1 else np.array([lower])
    return np.maximum.accumulate(grid), radii


def extremum(solution: PathSolution, quantity: str, largest: bool = True,
             scan: ExtremumScan | None = None) -> tuple[float, float]:
    """The largest (or smallest) value of ``quantity`` along the run and the time it is reached
    (s from first contact), from the solution itself, not from samples.

    Each span's quantities are smooth in time; the extremum of a span is at one of its ends or
    inside it. A scan of :data:`EXTREMUM_GRID` points per span (:func:`scan_spans`) brackets it
    (within one grid interval of the best point, at an end too); the spans that can hold the
    extremum (their best scanned value, raised by their largest change between neighbouring scan
    points, reaches the best scanned value of the run) are refined within one grid interval of the
    best point by the roots of the quantity's derivative (:func:`~.stationary.stationary_points`: the
    span's dense output and the branch's closed forms), the means by a bounded Brent search to
    :data:`EXTREMUM_XTOL` of the span's length; a refined point replaces the scanned one where it is better beyond
    the tie (:func:`within_tie`). Of values equal to :data:`EXTREMUM_TIE` (a plateau) the
    earliest time is reported, so that the time does not hang on rounding. The means (``mean_pressure``, ``mean_shear_stress``)
    are taken over the spans in contact.

    Parameters
    ----------
    solution : PathSolution
    quantity : str
        One of :data:`EXTREMUM_QUANTITIES`.
    largest : bool
        ``True`` for the maximum, ``False`` for the minimum.
    scan : ExtremumScan, optional
        :func:`scan_spans` of ``solution``, to share between several calls.

    Returns
    -------
    value : float
        The extremum (in the quantity's SI unit).
    time : float
        The earliest time it is reached (s from first contact).

    Raises
    ------
    ValueError
        A quantity not in :data:`EXTREMUM_QUANTITIES`.
    """
    if quantity not in EXTREMUM_QUANTITIES:
        raise ValueError(f"quantity={quantity!r} is not allowed; allowed: {', '.join(EXTREMUM_QUANTITIES)}")
    if quantity == "tangential_force" and solution.compressed is not None:  # the compressed zone's spans hold F_x
        return extremum(solution.compressed, quantity, largest)
    scan = scan_spans(solution) if scan is None else scan
    sign = 1.0 if largest else -1.0
    best, reach, first, size = _scanned_extremes(scan, quantity, sign)
    spans = np.flatnonzero(np.isfinite(best))
    if not spans.size:
        return math.nan, math.nan
    best_scanned = float(np.max(best[spans]))
    # the radius is monotone on a span: the area's extremes are at the span's ends, which the scan holds
    monotone = quantity in ("contact_radius", "contact_area")
    results = []
    for index in spans.tolist():
        times, i, value = scan.times[index], int(first[index]), float(best[index])
        time = float(times[i])
        if len(times) > 1 and value + reach[index] >= best_scanned and not monotone \
                and not never_stationary(solution, index, quantity):  # (else the scan's point stays)
            time, value = _refined(solution, scan, index, quantity, sign, (i, value), size)
        results.append((time, value))
    best_value = max(value for _, value in results)
    # the earliest time at which the extremum is reached, to rounding of the quantity's size along the run (a
    # plateau such as F_x in full slip, or a quantity that stays at zero, has ties that rounding would pick)
    best_time, best_value = min((time, value) for time, value in results
                                if within_tie(value, best_value, size))
    return best_time, sign * best_value


def _refined(solution: PathSolution, scan: ExtremumScan, index: int, quantity: str, sign: float,
             scanned: tuple[int, float], size: float) -> tuple[float, float]:
    """:func:`extremum`'s refinement of span ``index`` about its best scan point (``scanned``: its index and signed
    value): ``(time, signed value)`` of the stationary point (:func:`~.stationary.stationary_points`, or a bounded
    search for the means) better than it beyond the tie (:func:`within_tie`), else of the scan's point."""
    times, (i, value) = scan.times[index], scanned
    time = float(times[i])
    ends = (max(i - 1, 0), min(i + 1, len(times) - 1))
    radii = scan.values[index]["contact_radius"]
    points = stationary_points(solution, index, quantity, (float(times[ends[0]]), float(times[ends[1]])),
                               (float(radii[ends[0]]), float(radii[ends[1]])))
    if points is None:
        points = [_bounded_search(solution, index, quantity, sign, times, i)]
    for found_time, found in points:
        # (better beyond rounding alone, by the rule of ties: a point the scan's ties stays)
        if sign * found > value and not within_tie(value, sign * found, size):
            time, value = found_time, sign * found
    return time, value


def _scanned_extremes(scan: ExtremumScan, quantity: str,
                      sign: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Per span of ``scan``, of ``sign`` times ``quantity``: the best scanned value (``nan`` where none is finite), its
    largest change between neighbouring scan points (0 for one point), the index of the earliest scan point within
    :data:`EXTREMUM_TIE` of it; and the quantity's largest magnitude over the run. All spans at once, from the
    quantity's :func:`_scan_matrix` (kept in ``scan`` for the other extreme)."""
    kept = scan.matrices.get(quantity) if scan.matrices is not None else None
    if kept is None:
        kept = _scan_matrix(scan, quantity)
        if scan.matrices is not None:
            scan.matrices[quantity] = kept
    matrix = kept.matrix * sign  # (exact: a change of sign)
    with np.errstate(invalid="ignore"):
        best = np.fmax.reduce(matrix, axis=1)
        first = np.argmax(matrix >= (best - EXTREMUM_TIE * kept.largest)[:, None], axis=1)  # earliest tie
    return best, kept.reach, first, kept.size


def _scan_matrix(scan: ExtremumScan, quantity: str) -> ScanMatrix:
    """``quantity``'s scan as a matrix (a row per span, padded with ``nan``), each row's largest magnitude and largest
    change between neighbouring points (0 for one point; ``|Δ(−q)| = |Δq|`` exactly, so both extremes share it) and
    the largest magnitude over the run."""
    width = max(len(times) for times in scan.times)
    matrix = np.full((len(scan.times), width), np.nan)
    for row, filled in enumerate(scan.values):
        values = _quantity(filled, quantity)
        matrix[row, :len(values)] = values
    with np.errstate(invalid="ignore"):
        largest = np.fmax.reduce(np.abs(matrix), axis=1)
        reach = np.fmax(np.fmax.reduce(np.abs(np.diff(matrix, axis=1)), axis=1), 0.0) if width > 1 \
            else np.zeros(len(largest))
    size = float(np.fmax.reduce(largest[np.isfinite(largest)], initial=0.0))
    return ScanMatrix(matrix, largest, reach, size)


def _bounded_search(solution: PathSolution, index: int, quantity: str, sign: float, times: np.ndarray,
                    i: int) -> tuple[float, float]:
    """:func:`extremum`'s refinement of a quantity without a derivative route (:func:`~.stationary.stationary_points`:
    the means): a bounded Brent search of the time around scan point ``i``, to :data:`EXTREMUM_XTOL` of the span.
    Searched in the time from the bracket's start: the bounded search adds sqrt(eps) of the variable's size to its
    tolerance, 0.26 s at t = 1.7e7 s (a path at 1e-3°), where a force minimum lasts 0.03 s."""
    origin = float(times[max(i - 1, 0)])

    def objective(s: float) -> float:
        return -sign * _scalar_quantity(solution, index, origin + s, quantity)

    bracket = (0.0, float(times[min(i + 1, len(times) - 1)]) - origin)
    refined = optimize.minimize_scalar(objective, bounds=bracket, method="bounded",
                                       options={"xatol": EXTREMUM_XTOL * (times[-1] - times[0])})
    return origin + float(refined.x), -sign * float(refined.fun)


def _scalar_quantity(solution: PathSolution, index: int, time: float, quantity: str) -> float:
    """One quantity of span ``index`` at one time (s from first contact), with the scalar radius roots:
    :func:`extremum`'s objective (the same values as :func:`evaluate_span`, to the root's accuracy)."""
    span, model = solution.spans[index], solution.model
    if span.regime is Regime.NONE:
        return 0.0 if quantity in ("normal_force", "tangential_force") else math.nan
    d = span.segment.d(solution.t_contact + time)
    rtol = model.tolerances.radius_rtol
    if span.regime is Regime.GROWING:
        a = model.grow.radius(max(d, model.grow.jump_off_depth), rtol)
    elif span.regime is Regime.SHRINKING:
        a = model.shrink.radius(max(d, model.shrink.jump_off_depth), rtol)
    else:
        a = span.pinned_radius
    if solution.compressed is not None:
        force = float(_compressed_zone(solution.compressed, np.array([time]), np.array([a]))[0][0])
    elif span.interpolant is None:
        force = span.force
    else:
        force = float(span.interpolant(span_variable(span, a / span.scale if span.variable is Variable.RADIUS
                                                     else solution.t_contact + time))[0])
    normal = float(model.normal_force(d, a))
    area = math.pi * a * a
    values = {"normal_force": normal, "tangential_force": force, "contact_radius": a, "contact_area": area,
              "mean_pressure": normal / area if area > 0 else math.nan,
              "mean_shear_stress": force / area if area > 0 else math.nan}
    return values[quantity]


def algebraic_tangential_force(solution: PathSolution, times: np.ndarray) -> np.ndarray:
    """``F_x = 2G* ∫_0^a clip(x − Y, −ū, ū) dξ`` from each span's stored anchors, without integration.

    The independent check of :func:`evaluate`'s integrated ``F_x`` (same time convention, s from
    first contact; ``nan`` after the end of the run).

    Parameters
    ----------
    solution : PathSolution
        The solution.
    times : array_like
        Times (s from first contact).

    Returns
    -------
    numpy.ndarray
        ``F_x`` (N) at each time.
    """
    model = solution.model
    times = np.asarray(times, dtype=float)
    if solution.compressed is not None:  # the compressed zone's anchors (0 where it has no contact)
        zone = np.nan_to_num(algebraic_tangential_force(solution.compressed, times))
        return np.where(times <= solution.end_time, zone, np.nan)
    filled = evaluate(solution, times)
    owner = solution.span_index(times)
    out = np.full(len(times), np.nan)
    for i, t_rel in enumerate(times):
        if not t_rel <= solution.end_time:
            continue
        span = solution.spans[owner[i]]
        a = filled["contact_radius"][i]
        if span.regime is Regime.NONE or not a > 0:
            out[i] = 0.0
            continue
        x = filled["tangential_displacement"][i]
        out[i] = span.anchors.tangential_force(model.caps, solution.params.G_star, x, a,
                                               filled["indentation_depth"][i])
    return out


#: Gauss–Legendre nodes per step of a span's dense output in :func:`tangential_work`: exact for the
#: polynomial pieces of DOP853's interpolant (degree 7) times a linear ``dx/dt``.
WORK_NODES = 8


def tangential_work(solution: PathSolution, start: float | None = None, end: float | None = None) -> float:
    """The work of the tangential force on the indenter's tangential motion, ``W = ∫ F_x dx`` (J), over
    ``[start, end]`` (s from first contact; default the whole run).

    Over a closed tangential cycle at a fixed contact (a fretting loop) it is the energy dissipated by the
    springs sliding at the caps, ``4 π a² τ0 (X − ū)`` for a loop ``x: −X → X`` with ``X > ū`` (the area of
    the parallelogram). Evaluated from each span's interpolant, step by step, with
    :data:`WORK_NODES`-point Gauss–Legendre quadrature: in time on pinned spans (``dx = v_x dt``), in the
    radius on moving ones (``dx = v_x (∂d/∂a)/v_d da``).

    Parameters
    ----------
    solution : PathSolution
        The solution.
    start : float, optional
        The lower end (s from first contact); default 0.
    end : float, optional
        The upper end (s from first contact), at most the run's end; default the run's end.

    Returns
    -------
    float
        ``W`` (J).

    Raises
    ------
    ValueError
        A bound before the path's start, or not finite.
    """
    earliest = -solution.t_contact if solution.path is not None else 0.0
    allowed = f"a finite time >= {earliest:.9g} (s from first contact: the path's start) or None"
    lower = 0.0 if start is None else check_real("start", start, allowed, lambda value: value >= earliest)
    upper = solution.end_time if end is None else min(check_real("end", end, allowed, lambda value: value >= earliest),
                                                      solution.end_time)
    if start is not None and end is not None and not lower <= upper:  # (reversed: 0 J, silently)
        raise ValueError(f"start={shown(start)} and end={shown(end)} are not allowed; allowed: start <= end (s from "
                         "first contact)")
    if solution.compressed is not None:  # the compressed zone's force (none after its run: no contact)
        return tangential_work(solution.compressed, lower, upper) if upper > lower else 0.0
    nodes, weights = np.polynomial.legendre.leggauss(WORK_NODES)
    total = 0.0
    for span in solution.spans:
        t0 = max(span.t_start - solution.t_contact, lower)
        t1 = min(span.t_end - solution.t_contact, upper)
        if t1 <= t0 or span.regime is Regime.NONE or span.segment.vx == 0.0:
            continue
        segment = span.segment
        if span.interpolant is None:
            total += span.force * segment.vx * (t1 - t0)
            continue
        t_path = (solution.t_contact + t0, solution.t_contact + t1)
        if span.variable is Variable.TIME:
            bounds = t_path
        else:
            rtol = solution.model.tolerances.radius_rtol
            bounds = tuple(solution.model.branch(span.regime).radius(segment.d(t), rtol) / span.scale for t in t_path)
        bounds = tuple(span_variable(span, bound) for bound in bounds)
        low, high = min(bounds), max(bounds)
        sign = 1.0 if bounds[1] >= bounds[0] else -1.0
        breaks = np.asarray(span.interpolant.ts)
        edges = np.unique(np.concatenate([[low, high], breaks[(breaks > low) & (breaks < high)]]))
        for a, b in zip(edges[:-1], edges[1:]):
            var = 0.5 * (a + b) + 0.5 * (b - a) * nodes
            rate = _tangential_rate(solution.model, span, var)
            total += sign * 0.5 * (b - a) * float(np.sum(weights * span.interpolant(var)[0] * rate))
    return total


def _tangential_rate(model: ContinuumModel, span: Span, var: np.ndarray) -> np.ndarray:
    """``dx/d(var)`` of a span: ``v_x`` in time, ``v_x (∂d/∂a)/v_d`` times the scale in the radius over
    :attr:`Span.scale`; on a graded span (:mod:`.graded`) times ``dv/du``."""
    segment = span.segment
    graded = 1.0 if span.grading is None else span.grading.rate(np.asarray(var, dtype=float))  # (dv/du, graded)
    natural = natural_variable(span, var)
    if span.variable is Variable.TIME:
        return np.full(np.shape(var), segment.vx) * graded
    branch = model.branch(span.regime)
    return segment.vx * span.scale * np.array([branch.slope(float(v) * span.scale) for v in natural]) / segment.vd \
        * graded
