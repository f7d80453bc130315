"""How one span of ``"tau0+coulomb"`` with adhesion is stepped (:class:`SplitSpanSteps`, a mixin of
:class:`~.split_span.SplitSpanIntegrator`): the solver's longest step and the variable's grading, and the spans that
need no integration (a force constant or linear in time) with the outcome they hand on.
"""

from __future__ import annotations

import math

from .graded import Grading, grading_power
from .regions import Region, combined_summary
from .span import SpanOutcome, Trigger
from .split_zones import SpanZones
from .state import Cap, Slip
from .tolerances import MIN_STEPS_PER_SPAN

__all__ = ["SplitSpanSteps", "FRONT_STEPS_PER_SPAN"]

#: A solver step covers at most 1/this of a span with a front reaching the centre (it moves as ``g⁻¹`` of a level,
#: ``∝ (t_end − t)^(1/n)``, whose end DOP853's error estimate can miss in one long step) or with ``x_c`` moving at the
#: surface: the τ0 integrator's share (:data:`~.tolerances.MIN_STEPS_PER_SPAN`). It was 32 (twice the solver's steps
#: of scenario A at 20°); at 8 the integrated F_x stays within 5e-10 of its run at rtol 1e-13 on scenarios A and B
#: at 20–70°, fretting, the cone, n = 1.5 and n = 3 with and without Δγ0, and within 9e-9 of the algebraic form on
#: 60 random paths of the property test, as at 32 (the 3e-7 once seen at 8 steps on n = 3 predates the roots taken
#: to an absolute share of their interval).
FRONT_STEPS_PER_SPAN = MIN_STEPS_PER_SPAN
#: The same share on a profile whose tip no whole power smooths (a table, the flat punch: no span is graded,
#: :func:`~.graded.grading_power`): 32 as before the grading, since at 8 a table's F_x on scenario B at 30° with
#: adhesion went from 2.0e-9 to 1.35e-8 of its run at rtol 1e-13 (the review of the graded spans).
UNGRADED_FRONT_STEPS_PER_SPAN = 32
#: A span whose depth at one end is this share of the other's starts or ends at the surface (the planner ends spans
#: where the depth crosses 0; the depth there carries the rounding of the time)
SURFACE_SHARE = 1e-6


class SplitSpanSteps:
    """The steps of :class:`~.split_span.SplitSpanIntegrator` (a mixin: its layouts, depths, levels and rates are
    the integrator's): the solver's longest step, the grading, and the spans without integration."""

    # --- spans without integration ----------------------------------------------------------------
    def has_fronts(self) -> bool:
        """Whether a slip front lies inside a part of some region.

        Returns
        -------
        bool
            ``True`` if a layout holds a front.
        """
        return any(layout.fronts for layout in self.layouts.values())

    def max_step(self) -> float:
        """The longest step of the solver: with a front in a part, or ``x_c`` moving on a span that starts or ends at
        the surface (``x_c ∝ d^(1/n)``, steep there, where a long step reaches: 2e-6 of F_x with four steps over a
        span ending at ``d = 0`` that an event stopped far before), a share 1/:data:`FRONT_STEPS_PER_SPAN` of the
        span (the τ0 integrator's).

        Returns
        -------
        float
            The step (``inf``: none).
        """
        depths = abs(self.depth_of(self.start)), abs(self.depth_of(self.stop))
        at_surface = min(depths) <= SURFACE_SHARE * max(depths)
        centre = any(layout.parts[index].low == 0.0 for layout in self.layouts.values() for index, _ in layout.fronts)
        graded = self.graded
        towards_centre = graded is not None and graded.event is not None  # (else graded towards the surface)
        limited = (centre and not towards_centre) or (self.direction != 0.0 and at_surface
                                                      and not (graded is not None and not towards_centre))
        steps = FRONT_STEPS_PER_SPAN if grading_power(self.shape.hertz.tip_power) is not None \
            else UNGRADED_FRONT_STEPS_PER_SPAN
        return abs(self.stop - self.start) / steps if limited else math.inf

    def grading(self) -> Grading | None:
        """The variable graded towards the span's stop where ``x_c`` moves and the stop is at the surface
        (:mod:`.graded`: ``x_c ∝ d^(1/n)`` steep there), or towards the time a front reaches the centre of its part on
        a pinned span (``∝ (t_e − t)^(1/n)``; the span ends there with that event).

        Returns
        -------
        Grading or None
            ``v = origin + (start − origin) u^p``; ``None`` for any other span, or a profile whose tip is not a
            power that a whole ``p`` smooths (:func:`~.graded.grading_power`).
        """
        return self.graded

    def _grading(self) -> Grading | None:
        """:meth:`grading`, found once at the span's start: towards the surface, else towards a front reaching the
        centre (:meth:`_centre_grading`)."""
        power = grading_power(self.shape.hertz.tip_power)
        if power is None:
            return None
        first, last = abs(self.depth_of(self.start)), abs(self.depth_of(self.stop))
        if self.direction != 0.0 and first > 0.0 and last <= SURFACE_SHARE * first:
            return Grading(self.stop, self.start - self.stop, power)
        return self._centre_grading(power)

    def _centre_grading(self, power: int) -> Grading | None:
        """On a pinned span, the earliest time a pushing level reaches the fixed target of a front moving to the centre
        of its part (the level linear in time: a closed form, inside the span), the variable graded towards it."""
        if self.moving:
            return None
        found = []
        for key, layout in self.layouts.items():
            rate = self.rate(key[0], key[1], self.start)  # (σ d(level)/dt, constant on a pinned span)
            if not rate > 0.0:
                continue
            centre = [index for index, at_start in layout.fronts if not at_start and layout.parts[index].start == 0.0]
            if any(layout.fixed_target == layout.sign * layout.parts[index].value(0.0) for index in centre):
                # (a moving end's target reached first stops the span before: solve_ivp finds it)
                excess = layout.sign * self.region_level(key, self.start) - layout.fixed_target - self.offset
                found.append((self.start - excess / rate, key))
        inside = [(time, key) for time, key in found if self.start < time < self.stop]
        if not inside:
            return None
        time, key = min(inside)
        return Grading(time, self.start - time, power, (Trigger.ZONE_REACHES, key[1], key[0]))

    def _still(self) -> bool:
        """A pinned span whose caps and regions keep still: ``x_c`` does not move (no Coulomb part follows a depth)."""
        return not self.moving and self.direction == 0.0

    def force_is_constant(self) -> bool:
        """A span of zero extent, or a still one (:meth:`_still`) without tangential motion or with every spring at one
        cap.

        Returns
        -------
        bool
            ``True`` if ``F_x`` stays what it is.
        """
        if self.start == self.stop:
            return True
        full = any(combined_summary(*(self.layouts[(region, cap)].summary() if (region, cap) in self.layouts else None
                                      for region in Region)).slip is Slip.FULL for cap in Cap)
        return self._still() and (self.segment.vx == 0.0 or full)

    def force_is_linear(self) -> bool:
        """A still span (:meth:`_still`) without fronts: ``dF_x/dt = 2G* (a − n₊ − n₋) v_x`` until an event.

        Returns
        -------
        bool
            ``True`` for a still span without fronts.
        """
        return self._still() and not self.has_fronts()

    def linear_rate(self) -> float:
        """:meth:`force_is_linear`: ``dF_x/dt = 2G* (a − n₊ − n₋) v_x``, the zones' sizes at the span's start (the
        first level reaching its target in closed form: :meth:`~.span.SpanIntegrator.linear_span`; the caps keep
        still, ``κ ḋ = 0``).

        Returns
        -------
        float
            The rate (N/s).
        """
        return self.G2 * (self.span.pinned_radius - sum(self.sizes(self.start).values())) * self.segment.vx

    def finish(self, outcome: SpanOutcome) -> SpanOutcome:
        """``outcome`` with the maps the span read and the slip it laid out (:class:`~.span.SpanOutcome`).

        Parameters
        ----------
        outcome : SpanOutcome
            How the span ended.

        Returns
        -------
        SpanOutcome
            With :attr:`~.span.SpanOutcome.maps` and :attr:`~.span.SpanOutcome.sliding` (the span keeps its layouts:
            ``Span.zones``, what its sliding fraction is read off).
        """
        self.span.zones = SpanZones(self.layouts, self.shape, self.pressed, self.x_c_is_edge)
        return outcome._replace(maps=self.maps, sliding=dict(self.sliding))
