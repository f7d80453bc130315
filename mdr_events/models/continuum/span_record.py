"""A span as the solution keeps it (:class:`Span`): an interval of one radius regime, its integration variable
(:class:`Variable`) and the force's interpolant in it, and the key of the radius roots it keeps (:func:`root_key`).
:mod:`.span` integrates a span; :mod:`.solution` and :mod:`.span_extrema` read the spans kept.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import Callable

from .anchors import AnchorMap
from .graded import Grading
from .model import Segment
from .state import Regime

__all__ = ["Span", "Variable", "root_key"]


class Variable(enum.Enum):
    """The integration variable of a span."""

    TIME = "time"
    RADIUS = "radius"


@dataclass
class Span:
    """An interval with one radius regime, as the solution keeps it.

    Parameters
    ----------
    t_start : float
        The span's start (s on the path's clock).
    t_end : float
        Its end (s).
    segment : Segment
        The path segment it lies on.
    regime : Regime
        How the radius moves: growing, shrinking or pinned.
    pinned_radius : float, default 0.0
        The radius (m) of a pinned span.
    interpolant : callable, optional
        ``solve_ivp``'s dense output of ``F_x`` in :attr:`variable` (the time, or the radius over :attr:`scale`);
        ``None`` where the force is the constant :attr:`force`.
    force : float, default 0.0
        ``F_x`` (N) at the start (the span's force where it is constant).
    anchors : AnchorMap, optional
        The anchor map during the span.
    variable : Variable, default Variable.TIME
        The integration variable.
    scale : float, default 1.0
        The length (m) the radius is measured in as the integration variable (the time: 1).
    grading : Grading, optional
        The integration variable graded towards the span's stop (:mod:`.graded`): the interpolant is in ``u``.
    zones : SpanZones, optional
        The layouts of a span of ``"tau0+coulomb"`` with adhesion (:mod:`.split_zones`): its sliding length is read
        off them (``None``: off :attr:`anchors`).
    roots : dict, optional
        The radius roots the solve took on a moving span's branch, :func:`root_key` of ``(depth, rtol)`` ->
        ``Branch.radius(depth, rtol)`` (its ends': the extrema's scan reads them instead of finding them again, the
        same numbers; default none).
    """

    t_start: float
    t_end: float
    segment: Segment
    regime: Regime
    pinned_radius: float = 0.0
    interpolant: Callable | None = None
    force: float = 0.0
    anchors: AnchorMap | None = None
    variable: Variable = Variable.TIME
    #: the integration variable is the radius over this length (the time: 1)
    scale: float = 1.0
    # (the variable graded towards the span's stop, :mod:`.graded`; ``None``: not. Documented in the class's
    # docstring alone: numpydoc reads a documented attribute's value, and ``None`` has no docstring)
    grading: Grading | None = None
    # (the layouts of a split span, :mod:`.split_zones`; ``None``: none. Documented in the class's docstring alone)
    zones: object = None
    # (the solve's radius roots by depth, a memo of the span's own branch — ``model.branch(regime)``, the one its
    # integrator and the extrema's scan both read — so not part of what the span is: not compared. Documented in the
    # class's docstring alone)
    roots: dict[tuple[float, float, float], float] = field(default_factory=dict, compare=False)


def root_key(depth: float, rtol: float) -> tuple[float, float, float]:
    """The key of ``Branch.radius(depth, rtol)`` in :attr:`Span.roots`: the depth, the tolerance and the depth's sign
    (``0.0`` and ``-0.0`` are one key of a dict alone, and a branch's root may tell them apart).

    Parameters
    ----------
    depth : float
        The depth (m).
    rtol : float
        The root's relative accuracy.

    Returns
    -------
    tuple of float
        ``(depth, rtol, ±1.0)``.
    """
    return depth, rtol, math.copysign(1.0, depth)
