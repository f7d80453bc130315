"""The continuum (Δx → 0) limit of the spring model: an exact reference, integrated between events.

A hybrid automaton. Its continuous state is the tangential force ``F_x`` (an ODE between events)
and the anchor map ``Y(ξ)`` of the springs in contact (:mod:`.anchors`); its discrete state is the
radius regime and the slip state (:mod:`.state`, where the transition table is).

=========================  ===================================================================
module                     one idea
=========================  ===================================================================
:mod:`.state`              regimes, slip states, events, the transition table, the loop's state
:mod:`.tolerances`         the user's :class:`Tolerances` and the named fixed ones
:mod:`.branch`             one adhesive branch (9): depth ↔ radius, slope, integral
:mod:`.anchors`            the anchor map ``Y(ξ)``, slip fronts, re-sticking, its force
:mod:`.model`              the two branches and the cap ``ū = K a``; the path as linear segments
:mod:`.plan`               :func:`plan_span`: the span's regime and end in closed form
:mod:`.span`               :class:`SpanIntegrator` (right-hand side, event functions), ``integrate_span``
:mod:`.solve`              :func:`solve_path`: plan → integrate → transition → log
:mod:`.solution`           :class:`PathSolution` (spans and interpolants), ``evaluate``, ``extremum``
=========================  ===================================================================

On each straight path segment ``d(t)`` and ``x(t)`` are linear. The contact radius ``a(t)`` is
growing on the ``Δγ0`` branch of (9), pinned, or shrinking on the ``Δγ1`` branch; the switches
(start of growth, start of detachment, pull-off jump, end of contact) fall at times known in closed
form. Slip onset (``x − Y(0) = ū``), full slip (``x − Y(a) = ū``) and re-sticking
(``dx/dt = dū/dt`` while sliding) are found by event functions. The algebraic form
``F_x = 2G* [c ū + ∫_c^a (x − Y) dξ]`` checks the integrated force
(:func:`algebraic_tangential_force`).

Limits: the profile is the paraboloid (4); the tangential motion along the path must not reverse
(``x`` monotone; a non-increasing ``x`` is mirrored).
"""

from .anchors import AnchorMap, Piece
from .branch import Branch
from .model import ContinuumModel, Segment, kinematics
from .plan import Action, SpanPlan, plan_span
from .solution import (EVALUATED_QUANTITIES, EXTREMUM_QUANTITIES, PathSolution, algebraic_tangential_force, evaluate,
                       evaluate_span, extremum)
from .solve import run_continuum, solve_path
from .span import Span, SpanIntegrator, integrate_span
from .state import (EVENT_KINDS, SLIP_TRANSITIONS, ContactState, Event, EventKind, Regime, Slip, next_slip)
from .tolerances import NEGLIGIBLE_SHARE, Tolerances

__all__ = [
    "Action", "AnchorMap", "Branch", "ContactState", "ContinuumModel", "EVALUATED_QUANTITIES", "EVENT_KINDS",
    "EXTREMUM_QUANTITIES", "Event", "EventKind", "NEGLIGIBLE_SHARE", "PathSolution", "Piece", "Regime",
    "SLIP_TRANSITIONS", "Segment", "Slip", "Span", "SpanIntegrator", "SpanPlan", "Tolerances",
    "algebraic_tangential_force", "evaluate", "evaluate_span", "extremum", "integrate_span", "kinematics",
    "next_slip", "plan_span", "run_continuum", "solve_path",
]
