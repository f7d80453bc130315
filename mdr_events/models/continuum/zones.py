"""One cap's slip zone, laid out at a span's start and continued smoothly through the span.

At the start of a span every piece of the anchor map is classified for each :class:`Cap`: wholly in
the slip zone (:attr:`Role.IN`), holding a front (:attr:`Role.FRONT`: a growth piece part of whose
springs sit at the cap), or out of it. Through the span the zone's size follows this layout, the
fronts following their pieces' inverses *past* the pieces' ends, so that the right-hand side of the
force is smooth; the layout stops being right when the level reaches a value where a front leaves its
piece or a new piece starts to slide (:meth:`ZoneLayout.target`), or when the shrinking edge
passes a front or a piece boundary. Those are the span's internal events; the next span lays the
zone out again.
"""

from __future__ import annotations

import enum
from collections.abc import Callable

from .anchors import AnchorMap, Piece
from .caps import Caps
from .media import HALF_SPACE_MEDIUM, HalfSpaceMedium
from .model import Segment
from .state import Cap, Slip, ZoneSummary
from .tolerances import PIECE_SHARE


#: A zone at the edge has left through the shrinking edge once the edge's anchor is this many
#: classification tolerances beyond the level (more than one: the next layout must see it gone).
EDGE_LEAVING_TOLERANCES = 2.0


class Role(enum.Enum):
    """How a piece of the anchor map takes part in one cap's slip zone."""

    OUT = "out"      #: none of its springs is at the cap
    FRONT = "front"  #: a front inside the (growth) piece: the springs on one side of it are at the cap
    IN = "in"        #: all its springs are at the cap


class ZoneLayout:
    """One cap's slip zone at a span's start, continued smoothly through the span.

    Parameters
    ----------
    anchors : AnchorMap
        The stored anchors; its pieces are the springs in contact (the last may be a growth piece that
        starts at the radius).
    cap : Cap
    level : float
        The cap's level at the start, ``x − cap · ū(a)``.
    radius : float
        The contact radius at the start.
    sliding : bool
        Whether springs slide at this cap. A cap that does not slide has every piece out (after a
        re-stick the anchors sit exactly at the level, which then moves away).
    tolerance : float
        A piece value this close beyond the level counts as reached (a front at a piece's end to the
        rounding of the root that put it there is in the next piece; a zone leaving through the edge
        is found :data:`EDGE_LEAVING_TOLERANCES` of it beyond the level, so that it has left).
    medium : HalfSpaceMedium, default the half-space
        What the springs are made of: the zone's size is its springs' measure (:meth:`~.media.HalfSpaceMedium.measure`,
        the length on the half-space).
    fresh : bool, default False
        The edge is growing with a cap ``K a > 0`` there: its springs attach with no shift, short of every cap, so
        the edge piece's value at the radius is never reached (a constant edge piece, all at the edge's value, never
        at all); at ``a → 0`` every value would lie within ``tolerance`` and the piece count wholly at the cap.
    """

    def __init__(self, anchors: AnchorMap, cap: Cap, level: float, radius: float, sliding: bool, tolerance: float,
                 medium: HalfSpaceMedium = HALF_SPACE_MEDIUM, fresh: bool = False):
        self.anchors, self.cap = anchors, cap
        self.measure = measure = medium.measure
        self.sign = float(cap)
        self.pieces: list[Piece] = list(anchors.pieces)
        self.edge = len(self.pieces) - 1
        sign = self.sign
        reached = sign * level + tolerance  # a piece value up to here counts as reached
        roles, fixed_targets = [], []
        self.edge_is_target = False
        out, front, inside = Role.OUT, Role.FRONT, Role.IN  # (an Enum member lookup per piece is not free)
        for index, p in enumerate(self.pieces):
            end = min(p.end, radius)
            start_value, end_value = anchors.end_values(p, end)
            start_value, end_value = sign * start_value, sign * end_value
            role = out
            if sliding and end > p.start:
                at_edge = fresh and index == self.edge
                start_reached = start_value <= reached and not (at_edge and p.constant)
                end_reached = end_value <= reached and not at_edge
                if start_reached and end_reached:
                    role = inside
                elif start_reached or end_reached:
                    role = front if not p.constant else inside
            roles.append(role)
            if role is inside:
                continue
            # the value whose reaching changes the layout: a front's far end, an out piece's nearest value
            towards_end = p.constant or p.rises_towards(cap)
            if (role is front) == towards_end:
                if index == self.edge:
                    self.edge_is_target = True
                else:
                    fixed_targets.append(end_value)
            else:
                fixed_targets.append(start_value)
        self.roles = roles
        self.fixed_target = min(fixed_targets, default=float("inf"))
        #: the fronts as (piece, zone towards the piece's start, the piece's end or None for the edge)
        self.fronts = [(p, p.rises_towards(cap), None if index == self.edge else p.end)
                       for index, (p, role) in enumerate(zip(self.pieces, roles)) if role is Role.FRONT]
        self.inner_length = sum(measure(p.start, min(p.end, radius)) for index, (p, role)
                                in enumerate(zip(self.pieces, roles)) if role is Role.IN and index != self.edge)
        edge_piece = self.pieces[self.edge]
        self.edge_in = roles[self.edge] is Role.IN
        #: the edge piece holds a front with its slip zone on the edge's side (``[ξ*, a]``)
        self.edge_front_outward = roles[self.edge] is Role.FRONT and not edge_piece.rises_towards(cap)

    # --- through the span -----------------------------------------------------------------------
    def size(self, level: float, radius: float) -> float:
        """The zone's size (its springs' measure), continued smoothly from the layout (fronts past their pieces' ends).

        Parameters
        ----------
        level : float
            The cap's level (m), in the coordinates the cap sees the anchors in.
        radius : float
            The contact radius (m).

        Returns
        -------
        float
            The size (m).
        """
        total = self.inner_length
        measure = self.measure
        if self.edge_in:
            total += measure(self.pieces[self.edge].start, radius)
        for p, from_start, end in self.fronts:
            xi = self.anchors.inverse(p, level)
            total += max(measure(p.start, xi) if from_start else measure(xi, radius if end is None else end), 0.0)
        return total

    def edge_value(self, radius: float) -> float:
        """``cap · Y`` at the edge of a contact of radius ``radius``.

        Parameters
        ----------
        radius : float
            The contact radius (m).

        Returns
        -------
        float
            ``cap · Y(radius)`` (m).
        """
        return self.sign * self.anchors.piece_value(self.pieces[self.edge], radius)

    def target(self, radius: float) -> float:
        """The value of ``cap · level`` at which the layout stops being right as the level pushes on.

        Parameters
        ----------
        radius : float
            The contact radius (m).

        Returns
        -------
        float
            The target (m; ``inf``: none).
        """
        return min(self.fixed_target, self.edge_value(radius)) if self.edge_is_target else self.fixed_target

    @property
    def edge_in_zone(self) -> bool:
        """Whether the spring at the edge is at the cap (its shift leaving with it is ``cap · ū``)."""
        return self.edge_in or self.edge_front_outward

    # --- what is logged --------------------------------------------------------------------------
    def summary(self, radius: float) -> ZoneSummary:
        """The zone's extent and whether it holds the centre and the edge (pieces of zero length ignored).

        Parameters
        ----------
        radius : float
            The contact radius (m).

        Returns
        -------
        ZoneSummary
            Stick, partial or full slip, and whether the centre and the edge are in the zone.
        """
        present = [(p, role) for p, role in zip(self.pieces, self.roles) if min(p.end, radius) > p.start]
        if not present or all(role is Role.OUT for _, role in present):
            return ZoneSummary(Slip.STICK, False, False)
        slip = Slip.FULL if all(role is Role.IN for _, role in present) else Slip.PARTIAL
        first, first_role = present[0]
        last, last_role = present[-1]
        centre = first_role is Role.IN or (first_role is Role.FRONT and first.rises_towards(self.cap))
        edge = last_role is Role.IN or (last_role is Role.FRONT and not last.rises_towards(self.cap))
        return ZoneSummary(slip, centre, edge)


def length_scale(anchors: AnchorMap, cap_shift: float, x: float, travel: float, kappa: float = 0.0) -> float:
    """The lengths a span's slip criterion compares and resolves; the tolerances of the levels are shares of it.

    The largest of the centre's cap ``cap_shift`` (``K a + κ d``), the indenter's and the anchors' positions as
    Coulomb's caps see them (``x0 − cap κ d_ref`` and its slope's term, :meth:`~.anchors.AnchorMap.seen_by`: each
    seen value is a difference of terms up to ``|x0| + κ d_ref``, rounded as much, whatever the depth has become),
    and ``travel``: how far the
    indenter moves tangentially over the rounding of the variables a level is computed from
    (:func:`indenter_travel`). Not the depth scale ``d_max``: on a stiff elastomer the cap is 1e-13 m
    while ``d_max`` is 0.3 mm, and a tolerance of ``d_max`` would put every spring at the cap.
    """
    largest_anchor = max((abs(p.x0) + kappa * abs(p.d_ref) for p in anchors.pieces), default=0.0)
    return max(cap_shift, abs(x), largest_anchor, travel)


def indenter_travel(segment: Segment, t: float, radius: float, depth_term: Callable[[float], float]) -> float:
    """The tangential travel over which a level ``x − cap ū`` is computed on ``segment`` at time ``t``: ``|v_x| t``
    (the level's time is known to its rounding) and, on a segment that changes the depth, ``|v_x / v_d| g(a)``
    (a moving radius is the integration variable: the level's time comes from the depth of the branch, (9),
    whose terms are of the size ``depth_term(a) = g(a)``, ``a²/R`` for the paraboloid: near first contact of an
    adhesive indenter they cancel to a depth far smaller). A share of it is what the level can be resolved to."""
    travel = abs(segment.vx) * abs(t)
    if segment.vd != 0.0:
        travel = max(travel, abs(segment.vx / segment.vd) * depth_term(radius))
    return travel


def cap_travel(kappa: float, segment: Segment, t: float) -> float:
    """How far Coulomb's cap at the centre, ``κ d``, moves over the rounding of the depth ``d(t) = ds + v_d (t − t0)``
    a level ``x − cap (K a + κ d)`` is computed from: ``κ (|ds| + |v_d t|)`` (a level's analogue of
    :func:`indenter_travel`). The depth is known to a few ulp of those terms (on a pull-out at 1e-6 m/s at
    ``t = 5.8e4`` s, 7e-18 m), and ``κ`` magnifies it in the level (1e-11 m at ``μ = 1e6``): a slip criterion with
    a tolerance below that met the same event again at each restart. 0 without Coulomb's part.

    Parameters
    ----------
    kappa : float
        ``κ = μ E*/G*`` (1).
    segment : Segment
        The path segment.
    t : float
        The time (s on the path's clock).

    Returns
    -------
    float
        The length (m).
    """
    return kappa * (abs(segment.ds) + abs(segment.vd * t)) if kappa else 0.0


def lay_out_zones(anchors: AnchorMap, caps: Caps, segment: Segment, t: float, radius: float, sliding: dict[Cap, bool],
                  depth_term: Callable[[float], float], growing: bool = False) -> dict[Cap, ZoneLayout]:
    """Both caps' slip zones with the indenter at ``segment.x(t)`` and the radius ``radius`` (levels
    ``x ∓ (K a + κ d)``, each cap seeing the anchors as :meth:`~.anchors.AnchorMap.seen_by` it), a piece value
    within :data:`PIECE_SHARE` of the :func:`length_scale` beyond a level counting as reached.

    Parameters
    ----------
    anchors : AnchorMap
        The stored anchors of the springs in contact.
    caps : Caps
        The friction law's caps.
    segment : Segment
        The path segment.
    t : float
        The time (s on the path's clock).
    radius : float
        The contact radius (m).
    sliding : dict of Cap to bool
        Whether springs slide at each cap.
    depth_term : callable
        ``g(a)`` of the branch (:meth:`~.branch.Branch.depth_term`), the size of the depth's terms.
    growing : bool, default False
        Whether the edge grows (its springs attach with no shift: with ``K > 0`` never at a cap, ``fresh`` of
        :class:`ZoneLayout`).

    Returns
    -------
    dict of Cap to ZoneLayout
        Each cap's layout.
    """
    x = segment.x(t)
    shift = caps.centre_shift(radius, segment.d(t))
    travel = max(indenter_travel(segment, t, radius, depth_term), cap_travel(caps.kappa, segment, t))
    tolerance = PIECE_SHARE * length_scale(anchors, shift, x, travel, caps.kappa)
    fresh = growing and caps.K > 0.0
    return {cap: ZoneLayout(anchors.seen_by(cap, caps.kappa), cap, x - cap * shift, radius, sliding[cap], tolerance,
                            caps.medium, fresh) for cap in Cap}
