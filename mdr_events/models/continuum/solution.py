"""The continuum solution of a path: spans with their interpolants and the event log, and its quantities at any
times (:func:`evaluate`); its extrema are :mod:`.span_extrema`'s, its tangential work :mod:`.work`'s."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from mdr_events.contact.adhesion import Adhesion
from mdr_events.parameters import Parameters
from .dense import cut, force_values
from .span_forces import span_forces
from .span_sliding import span_sliding_lengths, takes_batch
from .graded import span_variable
from .first_touch import first_segment_middle, first_touch_fraction, first_touch_rows
from .model import ContinuumModel
from .sample_forces import FillRoute, force_rows, normal_forces, paraboloid_on_half_space, polynomial_forces
from .sample_radii import _quartic_radii, _sampled_radii
from .span_record import Span, Variable
from .span_rows import _sorted_span_rows, _span_rows
from .state import CONTACT_ENDING, Event, Regime
from .time_grid import check_times


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


#: How :func:`evaluate` computes ``F_N`` and ``F_x`` of the samples in contact (:class:`~.sample_forces.FillRoute`):
#: the spans' polynomials in one pass; ``FillRoute.TERMS``, the spans' own terms, is the reference the tests compare
#: it with.
FILL_ROUTE = FillRoute.POLYNOMIAL


def _span_radius(model, span: Span, d: np.ndarray, sampled: bool = False) -> np.ndarray:
    """The contact radius of a span in contact at the depths ``d``: on its branch of (9), or pinned; ``sampled``: by
    the branch's :meth:`~.branch.Branch.sample_radii` (a run's samples: the closed form where there is one)."""
    if span.regime is not Regime.GROWING and span.regime is not Regime.SHRINKING:
        return np.full(np.shape(d), span.pinned_radius)
    if not sampled:
        branch = model.grow if span.regime is Regime.GROWING else model.shrink
        return branch.radii(np.maximum(d, branch.jump_off_depth))
    return _sampled_radii(model, [span], [d])[0]


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


def evaluate(solution: PathSolution, times: np.ndarray) -> dict[str, np.ndarray]:
    """Fill a time grid (s from first contact) span by span (:func:`evaluate_span`).

    Samples before the first contact are out of contact (the path's depth and position, forces and radius 0, the
    sliding fraction ``nan``); samples after the end of the run are ``nan``, except the first sample after a pull-off
    if it lies on the pull-off's path segment, which shows the contact gone (forces and radius 0). Times before the
    path's start (that of ``solution.path``, else the first contact), or that are no finite numbers, are refused
    (:func:`~.time_grid.check_times`).

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
    _fill_pull_off(solution, times, np.flatnonzero(~inside & ~before), out)
    spans_rows = _sorted_span_rows(solution, times) if FILL_ROUTE is FillRoute.POLYNOMIAL else None
    if spans_rows is None:
        spans_rows = _span_rows(solution.span_index(times), inside, len(solution.spans))
    if solution.compressed is None:
        _fill_spans(solution, times, spans_rows, out)
        _fill_first_touch(solution, times, out)
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
    _fill_first_touch(solution, times, out)
    return out


def _fill_first_touch(solution: PathSolution, times: np.ndarray, out: dict[str, np.ndarray]) -> None:
    """:func:`evaluate`'s sliding fraction at a flat face's first touch (:mod:`.first_touch`: 0/0 there), its limit as
    the contact starts, written into ``out``."""
    rows = first_touch_rows(solution.model.profile, times, out["indentation_depth"], out["contact_radius"])
    if np.any(rows):
        middle = first_segment_middle(solution)
        out["sliding_fraction"][rows] = first_touch_fraction(
            solution.model.K, lambda: evaluate(solution, np.array([middle]))["sliding_fraction"][0])


def _fill_pull_off(solution: PathSolution, times: np.ndarray, after_end: np.ndarray,
                   out: dict[str, np.ndarray]) -> None:
    """:func:`evaluate`'s first sample after the end of the run (``after_end``: the rows after it), written into
    ``out``, where the run ended by a pull-off and the sample lies on the pull-off's path segment: the contact gone
    (the segment's depth and position, forces and radius 0)."""
    last = solution.spans[-1].segment
    if solution.ended_by_contact and after_end.size and solution.t_contact + times[after_end[0]] <= last.t1:
        first = after_end[0]
        t = solution.t_contact + times[first]
        out["indentation_depth"][first] = last.d(t)
        out["tangential_displacement"][first] = last.x(t)
        for name in ("normal_force", "tangential_force", "contact_radius"):
            out[name][first] = 0.0


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
    t, d, x, a, lengths = _kinematics(solution, members, [times[rows] for _, rows in contact])
    bounds = np.cumsum([0] + lengths)
    where = [slice(int(lower), int(upper)) for lower, upper in zip(bounds[:-1], bounds[1:])]
    if not (FILL_ROUTE is FillRoute.POLYNOMIAL and _quartic_radii(model, members, d, lengths, a)):
        for regime in (Regime.GROWING, Regime.SHRINKING):
            moving = [k for k, span in enumerate(members) if span.regime is regime]
            if moving:
                for k, radii in zip(moving, _sampled_radii(model, [members[k] for k in moving],
                                                           [d[where[k]] for k in moving])):
                    a[where[k]] = radii
    polynomial = FILL_ROUTE is FillRoute.POLYNOMIAL
    filled = {"indentation_depth": d, "tangential_displacement": x, "contact_radius": a,
              "normal_force": (normal_forces(model.params, d, a) if polynomial and paraboloid_on_half_space(model)
                               else np.asarray(model.normal_force(d, a), dtype=float)),  # (10)
              "tangential_force": (_polynomial_forces if polynomial else _tangential_forces)(members, t, a, where),
              "sliding_fraction": _sliding_fractions(model, members, x, d, a, where)}
    target = _rows_of(contact)
    for name, values in filled.items():
        out[name][target] = values


def _kinematics(solution: PathSolution, members: list[Span],
                parts: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, list[int]]:
    """The times (s, from the path's start), depths, positions and pinned radii of the spans ``members`` at their
    times ``parts`` (s from first contact), one array each: each span's segment's numbers repeated over its times,
    ``Segment.d`` and ``Segment.x`` element by element; and the number of each span's times."""
    lengths = [len(part) for part in parts]
    t = solution.t_contact + (np.concatenate(parts) if len(parts) > 1 else parts[0])
    # (each span's numbers, a row each, repeated over its times in one call: row by row the values of a call each)
    numbers = np.array([(span.segment.t0, span.segment.ds, span.segment.vd, span.segment.xs, span.segment.vx,
                         span.pinned_radius) for span in members], dtype=float).T
    t0, ds, vd, xs, vx, pinned = np.repeat(numbers, lengths, axis=1)
    elapsed = t - t0
    d = ds + vd * elapsed
    x = xs + vx * elapsed
    return t, d, x, pinned, lengths


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


def _polynomial_forces(spans: list[Span], t: np.ndarray, a: np.ndarray, where: list[slice]) -> np.ndarray:
    """:func:`_tangential_forces` by :data:`FillRoute.POLYNOMIAL`: the spans whose force is a polynomial in one pass
    (:func:`~.sample_forces.polynomial_forces`), the others by their kinds (:func:`~.span_forces.span_forces`)."""
    rows = force_rows(spans)
    if all(row is None or not row[0] for row in rows):  # (no span in √a: a table's, a layer's: their own calls)
        return _tangential_forces(spans, t, a, where)
    force = polynomial_forces(rows, t, a, [part.stop - part.start for part in where])
    read = [k for k, row in enumerate(rows) if row is None]
    if read:
        values = span_forces([spans[k].interpolant for k in read],
                             [_force_variable(spans[k], t[where[k]], a[where[k]]) for k in read])
        for k, value in zip(read, values):
            force[where[k]] = value
    return force


def _sliding_fractions(model: ContinuumModel, spans: list[Span], x: np.ndarray, d: np.ndarray, a: np.ndarray,
                       where: list[slice]) -> np.ndarray:
    """:func:`_sliding_fraction` of spans in contact at their samples (each span's ``where``): the spans whose anchor
    maps share one attachment branch together (:func:`~.span_sliding.span_sliding_lengths`), any other alone."""
    batched = [k for k, span in enumerate(spans) if takes_batch(span)]
    # (the attachment branch of the first span that takes the batch: a span before it may have no anchor map at all)
    together = [k for k in batched if spans[k].anchors.attach is spans[batched[0]].anchors.attach]
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
    _, d, x, a, lengths = _kinematics(solution, [spans[index] for index in members],
                                      [grids[index] for index in members])
    columns = {"indentation_depth": d, "tangential_displacement": x, "contact_radius": a}
    parts = {name: _split(values, lengths) for name, values in columns.items()}
    out = {}
    for k, index in enumerate(members):
        out[index] = {name: parts[name][k] for name in columns}
        if spans[index].interpolant is None:
            out[index]["tangential_force"] = np.full(lengths[k], spans[index].force)
    return out
