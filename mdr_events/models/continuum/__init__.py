"""The continuum (Δx → 0) limit of the spring model: an exact reference, integrated between events.

A hybrid automaton. Its continuous state is the tangential force ``F_x`` (an ODE between events)
and the stored anchors ``Y(ξ)`` of the springs in contact (:mod:`.anchors`); its discrete state is
the radius regime and, for each cap ``u = ±ū``, whether springs slide there (:mod:`.state`, where
the table of logged zone changes is).

=========================  ===================================================================
module                     one idea
=========================  ===================================================================
:mod:`.state`              regimes, caps, slip summaries, events, the zone table, the loop's state
:mod:`.tolerances`         the user's :class:`Tolerances` and the named fixed ones
:mod:`.branch`             one adhesive branch (9): depth ↔ radius, slope, integral
:mod:`.layer_branch`       the branch of a paraboloid or power law on a layer of finite thickness
:mod:`.media`              what the springs are made of, looked up by the body: the half-space's medium
:mod:`.layer_media`        a layer's medium (the cap ``K a/Φ_t``, the zones' measures ``K_t/(2G*)``, the edge's
                           weight, the branches and normal force)
:mod:`.edges`              the edge of each adhesion law: the branches a radius grows and shrinks along
:mod:`.anchors`            the stored anchors ``Y(ξ)``: zone sizes, the play operator's clip, the force
:mod:`.zones`              one cap's slip zone laid out at a span's start, continued smoothly
:mod:`.model`              the two branches and the cap ``ū = K a``; the path as linear segments
:mod:`.plan`               :func:`plan_span`: the span's regime and end in closed form
:mod:`.span`               :class:`SpanIntegrator` (right-hand side, event functions)
:mod:`.integrate`          ``integrate_span``: a span's force up to its end or first event (quadrature, knots)
:mod:`.span_panels`        a span's force as a quadrature by Gauss–Legendre panels, stored as DOP853 dense output
:mod:`.closed_form`        a moving span without a front in closed form (the branch's depth and integral)
:mod:`.layer_closed_form`  the same on a bonded layer (the cells' series of ``M``, ``ū``, ``d`` and their integrals)
:mod:`.span_march`         ``solve_ivp``'s loop for a span's DOP853 between knots without its bookkeeping (same steps)
:mod:`.solve`              :func:`solve_path`: plan → integrate → transition → log
:mod:`.compressed`         Coulomb's law alone with adhesion: the compressed zone's run beside the contact, and the
                           contact's slip events (the zone's and the tensile annulus's)
:mod:`.dense`              a span's dense output at many points at once (DOP853's steps as arrays, bit for bit)
:mod:`.formulas`           both parts with adhesion: the anchors as formulas of ``g``, ``d0`` and ``A(g)`` (value,
                           integral, turns, inverse on a monotone interval)
:mod:`.regions`            the compressed zone and the tensile annulus; one cap's zone in one region, its ends moving
:mod:`.split_map`          the stored anchors as pieces of formulas, their parts per cap and region, a span's maps
:mod:`.split_sums`         what is read off them: the springs at a cap, the clip, the algebraic force, the zones
:mod:`.split_layouts`      both regions' layouts at an instant, their ends moving; the anchors of springs crossing
                           ``x_c`` at a cap
:mod:`.split_span`         :class:`~.split_span.SplitSpanIntegrator`: the right-hand side of two regions
:mod:`.split_events`       its events, keyed by cap and region
:mod:`.split_solve`        the maps joined after a span, the slip transition of two regions
:mod:`.solution`           :class:`PathSolution` (spans and interpolants), ``evaluate``
:mod:`.span_extrema`       ``extremum``: one quantity's exact extreme over the spans (a scan of all spans at once,
                           the best points refined), the rule of ties
:mod:`.work`               ``tangential_work`` and ``algebraic_tangential_force`` (the anchors' check of ``F_x``)
:mod:`.rate_edge`          a rate-dependent adhesion law's edge: the radius as the state of an ODE (the normal problem)
:mod:`.rate_march`         ``solve_ivp``'s loop for the edge's scalar ODE without its per-step bookkeeping (same steps)
:mod:`.rate_lsoda`         LSODA's steps of the edge by its integrator's runner, dense output as rows (same steps)
:mod:`.rate_run`           ``simulate``'s continuum under the rate-dependent law: quantities, event log, extrema
:mod:`.edge_let_go`        where a receding rate-dependent edge lets go (its release rate rising as it shrinks)
:mod:`.rate_shifts`        the springs' shifts on top of it (``τ0``'s cap, ``x`` not turning back): ``F_x`` as a closed
                           form of the edge's dense output
:mod:`.extrema`            the exact extrema of ``F_N``, ``F_x`` and ``A`` over the run, not from output samples
:mod:`.stationary`         where one span's quantity is stationary: the roots of its derivative (dense output,
                           the branch's closed forms)
:mod:`.span_polynomials`   the paraboloid's spans as polynomials (moving: in ``√a``; pinned: in time): the
                           extrema's scan by Horner's rule over all of them, their stationary points
=========================  ===================================================================

On each straight path segment ``d(t)`` and ``x(t)`` are linear. The contact radius ``a(t)`` is
growing on the ``Δγ0`` branch of (9), pinned, or shrinking on the ``Δγ1`` branch; the switches
(start of growth, start of detachment, pull-off jump, end of contact, contact again) fall at times
known in closed form. A spring attaching gets ``Y = x``; the anchors are kept in the window
``[x − ū(a), x + ū(a)]`` (a play operator per spring); a spring detaching forgets its state, and a
contact after a pull-off starts afresh. Each cap's slip zone (one or more intervals) opens, grows,
reaches the centre or the edge, and re-sticks when its level turns back; these events are found by
event functions. The algebraic form ``F_x = 2G* ∫_0^a clip(x − Y, −ū, ū) dξ`` checks the
integrated force (:func:`algebraic_tangential_force`).

Friction laws: the cap ``ū(ξ) = K a + κ max(d − g(ξ), 0)`` (:mod:`.caps`); with adhesion Coulomb's law alone runs as
the compressed zone beside the contact (``PathSolution.compressed``); on the flat punch every law, with or without
adhesion, is one play operator of the face; both parts together with adhesion on a curved indenter split the contact
at the moving ``x_c`` into two regions with caps of their own (:mod:`.split_span`).
"""

from .anchors import AnchorMap, Piece
from .branch import Branch
from .model import MAX_TRAVEL_PER_CAP, ContinuumModel, Resolution, Segment, kinematics, resolution
from .plan import Action, SpanPlan, plan_span
from .rate_edge import EdgeEvent, EdgeEventKind, EdgeMode, EdgeRun, solve_edge
from .rate_shifts import RateShifts, solve_rate_shifts
from .edge_let_go import LetGo, let_go
from .solution import EVALUATED_QUANTITIES, PathSolution, evaluate, evaluate_span
from .span_extrema import EXTREMUM_QUANTITIES, extremum
from .work import algebraic_tangential_force, tangential_work
from .solve import run_continuum, solve_path
from .integrate import integrate_span
from .span import SpanIntegrator, Trigger
from .span_record import Span
from .state import (EVENT_KINDS, NO_ZONE, ZONE_EVENTS, Cap, ContactState, Event, EventKind, Regime, Slip, ZoneSummary,
                    zone_events)
from .tolerances import NEGLIGIBLE_SHARE, Tolerances
from .zones import Role, ZoneLayout, lay_out_zones

__all__ = [
    "Action", "AnchorMap", "EdgeEvent", "EdgeEventKind", "EdgeMode", "EdgeRun", "solve_edge", "RateShifts", "solve_rate_shifts", "LetGo", "let_go", "Branch", "Cap", "ContactState", "ContinuumModel", "EVALUATED_QUANTITIES", "EVENT_KINDS",
    "EXTREMUM_QUANTITIES", "Event", "EventKind", "MAX_TRAVEL_PER_CAP", "NEGLIGIBLE_SHARE", "NO_ZONE",
    "PathSolution", "Piece", "Regime", "Resolution", "Role", "Segment", "Slip", "Span", "SpanIntegrator",
    "SpanPlan", "Tolerances", "Trigger", "ZONE_EVENTS", "ZoneLayout", "ZoneSummary", "algebraic_tangential_force",
    "evaluate", "evaluate_span", "extremum", "integrate_span", "kinematics", "lay_out_zones", "plan_span",
    "resolution", "run_continuum", "solve_path", "tangential_work", "zone_events",
]
