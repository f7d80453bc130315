r"""The scan of a motion along the layer's branch for the slip onset: the travel per cap ``r(a)`` and its running
maximum inverted.

Part of :mod:`mdr_events.theory.layer` (the onsets and critical angles that read it:
:mod:`mdr_events.theory.layer.slip_onset`). The branch the motion follows and ``r`` along it, scanned at
:data:`SCAN_POINTS` radii logarithmically spaced up to the tables' last radius or :data:`SCAN_SPAN` times the radius
at ``d_max``; the first radius at which ``r`` reaches ``tan α`` bisected in ``ln a`` to round-off.
"""

from __future__ import annotations

import math
from typing import Callable, NamedTuple

import numpy as np

from mdr_events.contact.model import Contact
from mdr_events.theory.layer.branch_scan import (branch_jump_off, half_space_radii, layer_material, scan_ceiling,
                                                 stable_radius)
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.relations import branch_depth
from mdr_events.theory.layer.tangential_relations import sliding_cap

__all__ = ["SCAN_POINTS", "SCAN_SPAN", "first_onsets"]


#: Radii of the logarithmic scan of ``r(a)`` along one motion (the running maximum is inverted on it).
SCAN_POINTS = 400

#: Bisection steps in ``ln a`` inside one scan interval: its width is at most ``ln(1e12)/SCAN_POINTS < 0.07``, and
#: ``0.07 · 2⁻⁶⁰`` is far below an ulp of ``ln a``.
_BISECTIONS = 60

#: Without adhesion the pull-off branch shrinks to ``a → 0`` (``r → ∞``): the scan goes down to this fraction of the
#: radius at ``d_max``; an angle whose onset lies below it (within about ``1e-10°`` of 90° at the paper's
#: parameters) counts as sliding there.
_SMALLEST_FRACTION = 1e-12

#: The scan of a motion ends at the tables' last radius (``branch_scan.scan_ceiling``) or at
#: this many times the radius at ``d_max``, whichever comes first: on a layer so thick that its tables' last radius
#: squared leaves the double range (``h = 1e200``: ``g(64 h)`` overflowed, and the onset was refused though the layer
#: is the half-space there), the scan still ends where the relations are finite. An onset beyond it lies beyond any
#: angle but those within about ``1e-10`` degrees of 90° (the travel per cap grows about as the radius).
SCAN_SPAN = 1e12


class _Motion(NamedTuple):
    """A motion along one branch: radii in the order the motion visits them and ``r(a)`` (travel per cap) there."""

    #: ``ln a`` of the scan, in the motion's order
    logs: np.ndarray
    #: ``r`` at ``logs``
    ratio: np.ndarray
    #: ``r`` at any ``ln a`` (for the bisection)
    ratio_of: Callable[[np.ndarray], np.ndarray]
    #: the depth of the branch at any ``a``
    depth_of: Callable[[np.ndarray], np.ndarray]
    #: where the motion does not reach the angle: ``+inf`` (A, B+: beyond the tables, refused), ``-inf`` (B: comes
    #: apart first)
    never: float
    #: the depth where the motion starts (0 in A, ``d_max`` in B): the onset at α = 0
    start_depth: float


def _scan_top(contact: Contact, d_max: float) -> float:
    """The last radius of a motion's scan: the tables' last, or :data:`SCAN_SPAN` times the half-space's radius
    scale at ``d_max`` (its radius there, or its pull-off radius of the larger work), whichever is smaller (m)."""
    pulled, hertz = half_space_radii(contact, max(contact.adhesion.dgamma0, contact.adhesion.dgamma1), d_max)
    return min(scan_ceiling(contact.layer), SCAN_SPAN * max(pulled, hertz))


def _motion(contact: Contact, scenario: str, branch: str, adhesion: bool, d_max: float) -> _Motion:
    """The branch the motion follows and ``r(a)`` along it (module docstring)."""
    E_star, nu, layer = layer_material(contact)
    tau0, G_star = contact.friction.tau0, contact.elastomer.G_star
    pulling = scenario == "B" and branch == "pull-off"
    dgamma = 0.0 if not adhesion else contact.adhesion.dgamma1 if pulling else contact.adhesion.dgamma0

    def depth_of(a):
        return branch_depth(a, contact.indenter, E_star, nu, dgamma, layer)

    def ratio_of(logs):
        a = np.exp(logs)
        # (scenario A's travel is the depth from the first touch, d >= 0: its round-off below 0 at the start made a
        # d_max of 1e-100 m an angle of -4.5e-16 degrees)
        travel = np.maximum(depth_of(a), 0.0) if scenario == "A" else (d_max - depth_of(a)) if pulling else \
            (depth_of(a) - d_max)
        cap = sliding_cap(a, tau0, G_star, nu, layer)
        # (without τ0 the cap is 0 and any travel slides: r = inf, not NumPy's warnings at every node and bisection)
        return np.divide(travel, cap, out=np.full(np.shape(travel), math.inf), where=cap > 0.0)

    ceiling = _scan_top(contact, d_max)
    at_d_max = float(stable_radius(contact, dgamma, np.array([d_max]))[0])
    if scenario == "A":
        start = float(stable_radius(contact, dgamma, np.array([0.0]))[0]) if dgamma > 0.0 else 0.0
        start = start if start > 0.0 else _SMALLEST_FRACTION * at_d_max
        ends, never = (start, ceiling), math.inf
    elif pulling:
        end = branch_jump_off(contact, dgamma)[1] if dgamma > 0.0 else _SMALLEST_FRACTION * at_d_max
        ends, never = (at_d_max, end), -math.inf
    else:
        ends, never = (at_d_max, ceiling), math.inf
    logs = np.linspace(math.log(ends[0]), math.log(ends[1]), SCAN_POINTS)
    return _Motion(logs, ratio_of(logs), ratio_of, depth_of, never, 0.0 if scenario == "A" else d_max)


def _first_reaching(logs: np.ndarray, ratio: np.ndarray, ratio_of, tangent: np.ndarray):
    """The first node at which the running maximum of ``ratio`` (``r`` at ``logs``) reaches each ``tangent``, the
    running maximum, and the ``ln a`` where ``r`` reaches it, bisected between that node and the one before."""
    reached = np.maximum.accumulate(ratio)
    first = np.searchsorted(reached, tangent, side="left")
    index = np.clip(first, 1, reached.size - 1)
    lower, upper = logs[index - 1], logs[index]
    for _ in range(_BISECTIONS):  # r(lower) < tan α ≤ r(upper) (the first node reaching it)
        middle = 0.5 * (lower + upper)
        above = ratio_of(middle) >= tangent
        lower, upper = np.where(above, lower, middle), np.where(above, middle, upper)
    return first, reached, upper


def first_onsets(logs: np.ndarray, ratio_of, depth_of, tangent: np.ndarray, never: float) -> np.ndarray:
    """The depth at which the travel per cap ``r`` first reaches each ``tangent`` along a motion scanned at ``logs``
    (``ln a`` in the motion's order; ``never`` where it does not): the running maximum of ``r`` inverted by bisection.

    Parameters
    ----------
    logs : numpy.ndarray
        ``ln a`` of the scan, in the motion's order.
    ratio_of : callable
        ``r`` at any ``ln a`` (arrays).
    depth_of : callable
        The depth of the motion's branch at any ``a`` (arrays).
    tangent : numpy.ndarray
        ``tan α`` of each angle, each above ``r`` at the motion's start.
    never : float
        The depth of an angle the motion does not reach.

    Returns
    -------
    numpy.ndarray
        The depths (m), the shape of ``tangent``.
    """
    first, reached, upper = _first_reaching(logs, ratio_of(logs), ratio_of, tangent)
    return np.where(first >= reached.size, never, depth_of(np.exp(upper)))


def _onset_depths(motion: _Motion, tangent: np.ndarray, what: str, past_tables: bool) -> np.ndarray:
    """The depth at which ``r`` first reaches each ``tangent`` along the motion (``motion.never`` where it does not;
    ``+inf`` at 90°); an onset beyond the tables is refused, or ``nan`` with ``past_tables``."""
    first, reached, upper = _first_reaching(motion.logs, motion.ratio, motion.ratio_of, tangent)
    missed = first >= reached.size
    beyond = missed & np.isfinite(tangent) if motion.never == math.inf else np.zeros(missed.shape, bool)
    if np.any(beyond) and not past_tables:
        angle = float(np.degrees(np.arctan(tangent[missed & np.isfinite(tangent)].min())))
        raise ValueError(f"alpha={angle!r} is not allowed in {what} on this layer: its onset lies beyond a/h = "
                         f"{LAMBDA_MAX:g} (the tables' reach) or {SCAN_SPAN:g} times the radius at d_max (the scan's); "
                         "allowed: angles below "
                         f"{float(np.degrees(np.arctan(reached[-1]))):.6g} degrees")
    depth = motion.depth_of(np.exp(upper))
    depth = np.where((first == 0) | (tangent == 0.0), motion.start_depth, depth)  # (α = 0: where the motion starts)
    return np.where(beyond, math.nan, np.where(missed, motion.never, depth))
