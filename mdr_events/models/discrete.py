"""The paper's own numerical model: a row of independent springs (Fig. 7b).

Springs sit at ``x_j = ±(j + 1/2) Δx`` over the MDR profile ``g(x)``, with
normal stiffness ``E* Δx`` (5) and tangential stiffness ``G* Δx`` (6). The
contact is symmetric, so one half (``x > 0``) is simulated and the sums (15)
are doubled.

Rules, applied at every time step:

- **Heß's rule (8) with hysteresis.** The contact is ``m`` springs per side,
  contiguous from the centre, radius ``a = m Δx`` (``a = (n/2) Δx``).
  While the indenter goes in, the first spring attaches when touched
  (``d >= g(x_0)``) and then every spring with
  ``d >= g(x_j) − Δl_max(x_j; Δγ0)``; while it comes out, boundary springs
  detach, from the edge inwards, while ``d < g(x_j) − Δl_max(x_j; Δγ1)``.
  The threshold ``g − Δl_max`` falls to a minimum and then rises, so the
  contact stays contiguous: growth beyond the minimum and detachment from it
  are a ``searchsorted`` on the rising part; a boundary spring inside the
  minimum takes every spring up to it along (jump-in) or, detaching, the
  whole contact off (jump-off). Per step this is a comparison with one
  threshold (the counts are found for a block of samples at once).
- **Tangential springs.** A spring's shift is 0 when it attaches and then
  follows the indenter's tangential motion; where ``|u| > ū(a)`` (13) it is
  set to ``±ū(a)``; a detached spring forgets its shift.
- **Forces (15).** ``F_N = 2 Σ E* Δx (d − g(x_j))`` (from prefix sums of
  ``g``) and ``F_x = 2 Σ G* Δx u_j`` over the springs in contact.

Stepping (:class:`~mdr_events.models.spring_groups.SpringGroups`): a spring's shift is ``u = x − Y`` with its
anchor ``Y`` (``Y = x`` when it attaches; clipping moves ``Y`` with the window
``[x − ū, x + ū]``), so a step moves no spring that sticks. Springs that reach
a cap share its anchor from then on and are kept as one group; the anchors
are exact integers in units of ``2**-bits`` m, so ``Σ u = m x − Σ Y`` comes
from a running sum that is exact (no drift over any number of steps) and is
rounded once per sample. A step costs the groups that change (attach, detach,
the caps and the free groups the window reaches), O(1) where nothing is
clipped; one Python loop per case (a case in a batch gives what it gives
alone, bit for bit), no work per spring. Against the shifts stepped spring by
spring as the rules state them (:func:`_run_case_per_spring`: ``u += Δx``,
clip, sum), ``F_x`` differs by round-off only (about 1e-14 of its largest
magnitude); the springs in contact (``a``, ``F_N``) are the same, and so are
the springs at a cap unless round-off decides a tie of ``|u|`` with ``ū``.

On a layer of finite thickness (:mod:`~mdr_events.models.spring_media`) the springs differ: their normal
stiffness ``k(x_j) Δx`` enters ``F_N`` through prefix sums of ``k`` and ``k g``, their tangential stiffness
``k_t(x_j) Δx`` through integer weights the groups carry (``Σ w_j u_j = W_m x − Σ w_j Y_j``, exact as well), and
the threshold and cap of each are the layer's; the stepping is the same.

A run starts at the path's first entry into the elastomer
(:meth:`~mdr_events.models.paths.Path.entry_times`) and may go through any
number of contact cycles. When a contact comes apart (the pull-off jump), the
run goes on if the path enters the elastomer again later than the last sample
in contact: out of contact ``F_N = F_x = a = 0`` (sliding fraction ``nan``),
and the next contact starts afresh (springs attach with zero shift). If the
path never enters again, the run ends at that first sample without contact
(kept; ``nan`` after it). In any case a run ends when its path ends.
"""

from __future__ import annotations

import math
from array import array
import sys
from typing import Callable, NamedTuple, Sequence

import numpy as np

from mdr_events.io.agreement import ROUND_OFF
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.validation import check_real

from mdr_events.parameters import Parameters
from mdr_events.models.paths import Path
from mdr_events.models.spring_groups import SpringGroups, scale_bits, scaled, unscaled
from mdr_events.models import indenters
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.contact.adhesion import Adhesion, AdhesionLaw, RateDependentAdhesion, kernel_of, law_of
from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.models.rate_springs import rate_edge_counts
from mdr_events.models.spring_media import HalfSpaceSprings, Springs, springs_of
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.theory.kinds import theory_of
from mdr_events.models.kernel_model import KernelModel, as_kernel_model, check_kernel_run

__all__ = ["run_discrete", "paraboloid_profile", "MIN_SPRINGS_IN_CONTACT", "Thresholds", "THRESHOLD_RULES",
           "EDGE_RULES", "spring_thresholds", "check_thresholds_known", "threshold_counts"]

#: Fewer springs than this per side at ``d_max`` is too coarse (an error).
MIN_SPRINGS_IN_CONTACT = 10


def paraboloid_profile(params: Parameters) -> Callable[[np.ndarray], np.ndarray]:
    r"""``g(x) = x²/R``, eq. (4), as derived by :mod:`mdr_events.theory.symbolic`.

    .. math:: f(r) = \frac{r^2}{2R} \;\Rightarrow\; g(x) = \frac{x^2}{R} \qquad (4)
    """
    return indenters.spring_profile(params, None)


class _Threshold:
    """Depths at which each spring can be in contact: ``g(x_j) − Δl_max(x_j; Δγ)``.

    ``count(d)`` is the number of springs (from the centre) that satisfy
    ``depth >= threshold``; the set is contiguous because the threshold
    falls to its minimum and then rises.
    """

    def __init__(self, g: np.ndarray, elongation: np.ndarray):
        threshold = g - elongation
        self.threshold = np.append(threshold, np.inf)  # a spring beyond the array never qualifies
        self.lowest = int(np.argmin(threshold))
        self.minimum = float(threshold[self.lowest])
        self.rising = threshold[self.lowest + 1:]

    def count(self, depth: np.ndarray) -> np.ndarray:
        above = self.lowest + 1 + np.searchsorted(self.rising, depth, side="right")
        return np.where(depth >= self.minimum, above, 0)

    def grow(self, m: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Going in: the next spring attaches if ``depth`` reaches its threshold, then all that follow.

        If the next spring is inside the minimum of the threshold, every spring up to
        the minimum has a lower threshold and attaches with it (a jump-in).
        """
        return np.where(depth >= self.threshold[m], np.maximum(m, self.count(depth)), m)

    def shrink(self, m: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Going out: the boundary spring detaches if ``depth`` falls below its threshold, then
        the next inner one, and so on. On the falling side of the threshold every inner spring
        has a higher threshold, so the whole contact comes off (a jump-off)."""
        boundary = np.maximum(m - 1, 0)
        holds = (m == 0) | (depth >= self.threshold[boundary])
        inner = np.where(boundary > self.lowest, np.minimum(m, self.count(depth)), 0)
        return np.where(holds, m, inner)


class Thresholds(NamedTuple):
    """The springs' thresholds of an adhesion law: attaching on the way in, letting go on the way out."""

    attach: _Threshold
    detach: _Threshold


def hysteresis_thresholds(adhesion: Adhesion, g: np.ndarray, positions: np.ndarray, springs: Springs) -> Thresholds:
    r"""The paper's rate-independent law: Heß's limit (8) with ``Δγ0`` to attach and ``Δγ1`` to let go.

    .. math:: \Delta l_\mathrm{max}(x) = \sqrt{\frac{2 \pi |x| \Delta\gamma}{E^*}} \qquad (8)

    on the half-space; on a layer ``sqrt(4π |x| Δγ / K'(|x|))`` (``springs.elongation``,
    :mod:`mdr_events.models.spring_media`).
    """
    return Thresholds(_Threshold(g, springs.elongation(positions, adhesion.dgamma0)),
                      _Threshold(g, springs.elongation(positions, adhesion.dgamma1)))


def rate_thresholds(adhesion: RateDependentAdhesion, g: np.ndarray, positions: np.ndarray,
                    springs: Springs) -> Thresholds:
    """A rate-dependent law: the thresholds of its works at rest, which size the springs (an advancing edge stays
    inside the ``Δγ0`` branch's radius) and give the first touch; its edge moves by
    :func:`~mdr_events.models.rate_springs.rate_edge_counts`.

    Parameters
    ----------
    adhesion : RateDependentAdhesion
        The law.
    g : numpy.ndarray
        The profile at the springs (m).
    positions : numpy.ndarray
        The springs' centres (m).
    springs : HalfSpaceSprings
        The springs' kind (their Heß elongation).

    Returns
    -------
    Thresholds
        Those of :func:`hysteresis_thresholds` with the works at rest.
    """
    return hysteresis_thresholds(Adhesion(*adhesion.works_at_rest), g, positions, springs)


#: The springs' thresholds of each adhesion law, by its type.
THRESHOLD_RULES: dict[type, Callable[..., Thresholds]] = {Adhesion: hysteresis_thresholds,
                                                          RateDependentAdhesion: rate_thresholds}


def _edge_by_thresholds(adhesion: AdhesionLaw, run: "_Setup", params: Parameters, depth: np.ndarray, time: np.ndarray,
                        last: int) -> None:
    """A law of thresholds (the paper's, any law of :data:`THRESHOLD_RULES` not in :data:`EDGE_RULES`): the stepping
    counts the springs by them itself (:func:`threshold_counts`, or the rule of :func:`_run_case_per_spring`)."""
    return None


def _edge_at_its_speed(adhesion: RateDependentAdhesion, run: "_Setup", params: Parameters, depth: np.ndarray,
                       time: np.ndarray, last: int) -> np.ndarray:
    """A rate-dependent law: its edge moves at a speed, counted before the stepping
    (:func:`~mdr_events.models.rate_springs.rate_edge_counts`)."""
    return rate_edge_counts(adhesion, run.positions, run.grid.g, params.E_star, depth, time, last,
                            run.grid.first_touch)


#: The laws whose springs in contact are counted otherwise than by their thresholds (:data:`THRESHOLD_RULES`, which
#: the stepping reads itself), by type: the counts per sample.
EDGE_RULES: dict[type, Callable[..., np.ndarray | None]] = {RateDependentAdhesion: _edge_at_its_speed}


def check_thresholds_known(adhesion: AdhesionLaw) -> None:
    """Refuse an adhesion law without thresholds in :data:`THRESHOLD_RULES`, naming those with them."""
    kernel_of(adhesion, THRESHOLD_RULES, "discrete")


def spring_thresholds(adhesion: AdhesionLaw, g: np.ndarray, positions: np.ndarray, springs: Springs) -> Thresholds:
    """The thresholds of ``adhesion`` for springs at ``positions`` on the profile ``g`` of the springs' kind
    (:mod:`~mdr_events.models.spring_media`: its Heß elongation)."""
    return kernel_of(adhesion, THRESHOLD_RULES, "discrete")(adhesion, g, positions, springs)


def _spring_count(springs: Springs, dx: float, max_depth: float, adhesion: AdhesionLaw) -> int:
    """Springs per side needed to hold the largest contact of the path, with margin: the springs probed and kept
    are those the kind's relations know (:meth:`~mdr_events.models.spring_media.LayerSprings.most_springs`: on a
    layer within the tables, whose last radius a contact near it passed by its margin, ``a/h = 64.001`` refused
    by the tables); a contact that needs more is refused in one line."""
    most, count = springs.most_springs(dx), 64
    while True:
        probed = min(count, most)
        positions = (np.arange(probed) + 0.5) * dx
        attach = spring_thresholds(adhesion, springs.profile(positions), positions, springs).attach
        needed = int(attach.count(np.array([max_depth]))[0])
        if needed < probed - 1:
            return needed + 2
        if probed == most:
            raise _beyond_the_tables(springs, dx, max_depth, needed, most)
        count *= 2


#: The springs a finer spacing keeps between the contact's edge and the tables' last radius: the count rounds up by
#: one at the edge, the tables' reach down by one, one spring beyond the edge is needed (3), with one of margin.
SPRINGS_TO_THE_TABLES_EDGE = 4


def _beyond_the_tables(springs: Springs, dx: float, max_depth: float, needed: int, most: int) -> ValueError:
    """The refusal of a contact whose springs, one beyond its edge, pass the layer's tables (``a/h = 64``) at ``dx``,
    naming what applies: a spacing that fits ``SPRINGS_TO_THE_TABLES_EDGE`` springs between the contact's radius and
    ``64 h`` where there is room (none at ``a/h = 64``, round twenty-four: "a smaller dx" was suggested there, which
    cannot help), a shallower depth (a flat punch: a smaller face, whose radius no depth changes), a thicker layer."""
    from mdr_events.theory.layer.compliance import LAMBDA_MAX

    thickness = springs.layer.thickness  # (only a layer's springs are bounded: the half-space's most is sys.maxsize)
    reach, radius = LAMBDA_MAX * thickness, springs.branch_radius(max_depth)
    finer = (reach - radius) / SPRINGS_TO_THE_TABLES_EDGE
    spacing = (f"dx <= {finer:.3g} m (the contact radius {radius:.6g} m is {reach - radius:.3g} m within the tables' "
               f"64 h = {reach:.6g} m), " if finer > 0 else
               f"no dx (the contact radius {radius:.6g} m reaches the tables' 64 h = {reach:.6g} m), but ")
    smaller = (f"a face's radius below {reach:.6g} m (with a dx that fits {SPRINGS_TO_THE_TABLES_EDGE} springs "
               "between them)" if theory_of(springs.indenter).flat_face else  # (no depth changes a face's radius)
               f"a depth whose contact radius stays below {(most - 1) * dx:.6g} m")
    return ValueError(f"dx={dx!r} m: the contact at the depth {max_depth!r} m takes {needed} springs per side and the "
                      f"layer's tables reach {most} (a/h = 64), too few for one spring beyond its edge; allowed: "
                      f"{spacing}{smaller}, or a layer thicker than h = {thickness!r} m")


def check_spacing(params: Parameters, dx: float, depth: float | None = None, profile: SimulatedProfile = None,
                  layer: Layer = HALF_SPACE) -> float:
    """``dx`` as a float; reject a spring spacing that puts fewer than 10 springs per side in contact at
    the deepest point (``d_max``, or the given ``depth`` of a custom path) of ``profile`` (``None``: the paraboloid)
    on ``layer`` (default the half-space)."""
    dx = check_real("dx", dx, "a finite spring spacing > 0 (m)", lambda value: value > 0)
    depth = params.d_max if depth is None else depth
    radius = springs_of(params, profile, None, layer).branch_radius(depth)
    if not radius / dx >= MIN_SPRINGS_IN_CONTACT:
        raise ValueError(
            f"dx={dx!r} m puts {int(radius // dx) if radius == radius else 0} springs per side in contact "
            f"at the deepest point d = {depth!r} m; "
            f"allowed: at least {MIN_SPRINGS_IN_CONTACT}, i.e. dx <= {radius / MIN_SPRINGS_IN_CONTACT:.6g} m"
        )
    return dx


class _Grid:
    """What every case of a run shares: the springs' thresholds, the caps ``ū(m Δx)`` and the integer
    scale of the positions (:class:`~mdr_events.models.spring_groups.SpringGroups`: units of ``2**-bits`` m; ``None``
    where the springs are stepped one by one, :func:`_run_case_per_spring`), Coulomb's ratio per spring and how the
    shifts add up (:mod:`~mdr_events.models.spring_media`: a plain sum on the half-space, weighted on a layer)."""

    def __init__(self, attach: _Threshold, detach: _Threshold, first_touch: float, caps: np.ndarray, bits: int | None,
                 g: np.ndarray | None = None, coulomb: float | np.ndarray = 0.0,
                 sum_shifts: Callable[[np.ndarray], float] = np.sum, weight_prefix: Sequence[int] = range(sys.maxsize),
                 weight_bits: int = 0):
        self.attach, self.detach = attach, detach
        #: Coulomb's part of the caps, ``κ_j max(d − g(x_j), 0)`` with ``κ_j = μ k(x_j)/k_t(x_j)`` (``μ E*/G*`` on the
        #: half-space; 0: the caps are ``caps``), one per spring
        self.g = g
        self.coulomb = np.broadcast_to(np.asarray(coulomb, dtype=float), np.shape(caps[1:]))
        self.has_coulomb = bool(np.any(self.coulomb > 0.0))
        self.sum_shifts = sum_shifts
        #: the groups' integer weights (:class:`~mdr_events.models.spring_groups.SpringGroups`: every spring weighs 1
        #: on the half-space; ``k_t(x_j)/G*`` in units of ``2**-weight_bits`` on a layer), summed below each index
        self.weight_prefix, self.weight_bits = weight_prefix, weight_bits
        self.first_touch = float(first_touch)
        self.attach_threshold = attach.threshold.tolist()
        self.detach_threshold = detach.threshold.tolist()
        self.detach_lowest = detach.lowest
        self.caps = caps.tolist()
        self.n_springs = len(self.caps) - 1
        self.bits = bits
        self.caps_scaled = None if bits is None else scaled(caps, bits)

    def to_float(self, value: int) -> float:
        """An integer in units of ``2**-bits`` m as the nearest float (m)."""
        return unscaled(value, self.bits)

    def sum_to_float(self, value: int) -> float:
        """A weighted sum of shifts in units of ``2**-(bits + weight_bits)`` m as the nearest float (m)."""
        return unscaled(value, self.bits + self.weight_bits)


#: Samples per block of a case: the per-sample Python values live for one block only.
_BLOCK = 8192


def threshold_counts(grid: _Grid, d: np.ndarray, last: int) -> np.ndarray:
    """The springs in contact per side at each sample up to ``last`` under Heß's rule with hysteresis: going in, a
    contact grows where the depth passes the ``Δγ0`` thresholds (:class:`_Threshold`'s ``grow``), coming out it shrinks
    below the ``Δγ1`` ones (``shrink``), and it comes apart whole below the lowest; a contact that has come apart
    starts afresh at the first touch. It depends on the depths alone, so it is counted before the tangential stepping
    (as a rate-dependent edge is, :func:`~mdr_events.models.rate_springs.rate_edge_counts`).

    Parameters
    ----------
    grid : _Grid
        The springs' thresholds.
    d : numpy.ndarray
        The case's depths (m) at every sample.
    last : int
        The last sample counted.

    Returns
    -------
    numpy.ndarray
        The counts (int64), ``last + 1`` of them.
    """
    attach_threshold, detach_threshold = grid.attach_threshold, grid.detach_threshold
    detach_lowest, first_touch = grid.detach_lowest, grid.first_touch
    counts = np.zeros(last + 1, dtype=np.int64)
    m = counts[0] = _first_count(grid, d, None)
    depth_before = float(d[0])
    for first in range(1, last + 1, _BLOCK):
        block = slice(first, min(last, first + _BLOCK - 1) + 1)
        grows, shrinks = grid.attach.count(d[block]).tolist(), grid.detach.count(d[block]).tolist()
        block_counts = array("q")
        for i, depth in enumerate(d[block].tolist()):
            step = depth - depth_before
            if step > 0.0:  # going in: Heß's rule with Δγ0 (_Threshold.grow)
                if m:
                    m = max(m, grows[i]) if depth >= attach_threshold[m] else m
                else:
                    m = grows[i] if depth >= first_touch else 0
            elif step < 0.0 and m and depth < detach_threshold[m - 1]:  # coming out: Δγ1 (_Threshold.shrink)
                m = min(m, shrinks[i]) if m - 1 > detach_lowest else 0
            block_counts.append(m)
            depth_before = depth
        counts[block] = block_counts
    return counts


def _run_case(grid: _Grid, x: np.ndarray, d: np.ndarray, time: np.ndarray, last: int, last_entry: float,
              counts: np.ndarray, sums: np.ndarray, sliding: np.ndarray, springs: SpringGroups | None = None,
              edge: np.ndarray | None = None) -> int:
    """Step one case from sample 0 to ``last``, or to its pull-off if its path does not enter again.

    Writes, per sample, the springs in contact per side to ``counts``, ``Σ w_j u_j`` over them (m; the weights
    ``w_j = k_t(x_j)/G*`` of ``grid.weight_prefix``, 1 on the half-space) to ``sums`` and the springs at a cap (every spring in contact where ``ū = 0``) to ``sliding``;
    returns the last sample. ``springs`` ends holding the final state (for inspection). ``edge``: the springs in
    contact per sample, counted before (:func:`threshold_counts` where not given; a rate-dependent law's
    :func:`~mdr_events.models.rate_springs.rate_edge_counts`).
    """
    springs = SpringGroups(grid.weight_prefix) if springs is None else springs
    edge = threshold_counts(grid, d, last) if edge is None else edge
    caps, caps_scaled, bits, to_float = grid.caps, grid.caps_scaled, grid.bits, grid.sum_to_float
    totals = grid.weight_prefix
    m, total, at_caps = _first_sample(grid, x, d, springs, counts, sums, sliding, edge)
    x_before = float(x[0])
    k = 1
    while k <= last:
        block = slice(k, min(last, k + _BLOCK - 1) + 1)
        xs, positions, moved = x[block].tolist(), scaled(x[block], bits), edge[block].tolist()
        block_counts, block_sums, block_sliding = array("q"), array("d"), array("q")
        for i, m_new in enumerate(moved):
            position = xs[i]
            if m_new != m or position != x_before:  # else nothing moves: the sums stay
                if m_new < m:
                    if m_new:
                        springs.detach(m, m_new)
                    else:
                        springs.reset()
                elif m_new > m:
                    springs.attach(m, m_new, positions[i])
                if m_new:
                    anchor, cap = positions[i], caps_scaled[m_new]
                    at_caps = springs.clip(anchor - cap, anchor + cap)
                    total = to_float(totals[m_new] * anchor - springs.anchor_sum)
                    if not caps[m_new] > 0.0:
                        at_caps = m_new  # ū = 0: every spring in contact slides
                else:
                    total, at_caps = 0.0, 0
            block_counts.append(m_new)
            block_sums.append(total)
            block_sliding.append(at_caps)
            x_before = position
            # the pull-off jump ends the case (keeping this first sample without contact) unless its path
            # enters again after the last sample in contact; then the next contact starts afresh
            apart = m and not m_new and last_entry <= time[k - 1]
            m = m_new
            k += 1
            if apart:
                last = k - 1
                break
        written = slice(block.start, block.start + len(block_counts))
        counts[written], sums[written], sliding[written] = block_counts, block_sums, block_sliding
    return last


def _first_sample(grid: _Grid, x: np.ndarray, d: np.ndarray, springs: SpringGroups, counts: np.ndarray,
                  sums: np.ndarray, sliding: np.ndarray, edge: np.ndarray | None = None) -> tuple[int, float, int]:
    """Attach the springs the first sample touches and record it (``edge``: counted before, for a rate-dependent
    law); returns the springs in contact per side, ``Σ u`` (0) and the springs at a cap."""
    m = _first_count(grid, d, edge)
    if m:
        springs.attach(0, m, scaled(x[:1], grid.bits)[0])
    # every spring has just attached (u = 0): at a cap only where ū = 0, though sample 0 records none
    total, at_caps = 0.0, (m if m and not grid.caps[m] > 0.0 else 0)
    counts[0], sums[0], sliding[0] = m, total, 0
    return m, total, at_caps


def _first_count(grid: _Grid, d: np.ndarray, edge: np.ndarray | None) -> int:
    """The springs the first sample touches: counted before (``edge``), or by the attach threshold."""
    if edge is not None:
        return int(edge[0])
    return int(grid.attach.count(d[:1])[0]) if float(d[0]) >= grid.first_touch else 0


def _run_case_per_spring(grid: _Grid, x: np.ndarray, d: np.ndarray, time: np.ndarray, last: int,
                         last_entry: float, counts: np.ndarray, sums: np.ndarray, sliding: np.ndarray,
                         edge: np.ndarray | None = None) -> int:
    """The rules stepped spring by spring, as stated (module docstring): the reference of :func:`_run_case`.

    Same arguments and outputs; every spring's shift is a float moved by each step and clipped,
    and ``Σ u`` a plain sum: O(springs) numpy work per step, where :func:`_run_case` is O(1). It also
    runs the friction laws with Coulomb's part (``grid.has_coulomb``), whose caps differ from spring to
    spring: ``ū_j = ū(m Δx) + κ_j max(d − g(x_j), 0)``; a spring whose cap is 0 slides. On a layer of finite
    thickness (:class:`~mdr_events.models.spring_media.LayerSprings`) the springs differ and ``sums`` is their
    weighted sum ``Σ (k_t(x_j)/G*) u_j`` (``grid.sum_shifts``).
    """
    shift = np.zeros(grid.n_springs)
    m = _first_count(grid, d, edge)
    counts[0], sums[0], sliding[0] = m, 0.0, 0
    k = 1
    while k <= last:
        depth = d[k:k + 1]
        if edge is not None:  # a rate-dependent edge: counted before
            m_new = int(edge[k])
        elif d[k] > d[k - 1]:
            if m:
                m_new = int(grid.attach.grow(np.array([m]), depth)[0])
            else:
                m_new = int(grid.attach.count(depth)[0]) if d[k] >= grid.first_touch else 0
        elif d[k] < d[k - 1]:
            m_new = int(grid.detach.shrink(np.array([m]), depth)[0])
        else:
            m_new = m
        kept = min(m, m_new)
        shift[:kept] += x[k] - x[k - 1]
        shift[kept:] = 0.0  # detached springs forget their shift, new ones attach with none
        cap = grid.caps[m_new]
        if grid.has_coulomb:
            cap = cap + grid.coulomb[:m_new] * np.maximum(d[k] - grid.g[:m_new], 0.0)
        in_contact = shift[:m_new]
        np.minimum(in_contact, cap, out=in_contact)
        np.maximum(in_contact, -cap, out=in_contact)
        counts[k], sums[k] = m_new, grid.sum_shifts(in_contact)
        if grid.has_coulomb:
            sliding[k] = np.count_nonzero((np.abs(in_contact) >= cap) | ~(cap > 0.0))
        else:
            sliding[k] = np.count_nonzero(np.abs(in_contact) >= cap) if cap > 0.0 else m_new
        if m and not m_new and last_entry <= time[k - 1]:
            last = k
        m = m_new
        k += 1
    return last


class _Setup(NamedTuple):
    """A run laid out before stepping: the common time grid, each case's samples, the springs."""

    time: np.ndarray  # (n_time,) from each path's first contact
    x: np.ndarray  # (n_time, n_cases) tangential position of each case's indenter
    d: np.ndarray  # (n_time, n_cases) depth
    last_sample: np.ndarray  # (n_cases,) the sample at the end of each path
    last_entries: np.ndarray  # (n_cases,) each path's last entry into the elastomer, from first contact
    grid: _Grid
    g_prefix: np.ndarray  # (n_springs + 1,) Σ w_j g(x_j) over the first m springs
    positions: np.ndarray  # (n_springs,) the springs' centres
    weight_prefix: np.ndarray  # (n_springs + 1,) Σ w_j over the first m springs (m on the half-space)


def _prepare(params: Parameters, paths: list[Path], dx: float, dt: float,
             profile: Callable[[np.ndarray], np.ndarray] | None, friction: FrictionLaw, adhesion: AdhesionLaw,
             springs: Springs | None = None) -> _Setup:
    """The time grid, every case's samples and the springs of :func:`run_discrete`: those of ``springs``
    (:mod:`~mdr_events.models.spring_media`; default the half-space's on the profile ``profile``), with the normal
    weights ``w_j = k(x_j)/E*`` of the sums (15) (1 on the half-space)."""
    springs = HalfSpaceSprings(params, given_profile=profile) if springs is None else springs
    starts, durations, n_time = _time_grid_size(paths, dt)
    # the last entry into the elastomer, in time from first contact (0 for a path with one entry)
    last_entries = np.array([path.entry_times()[-1] for path in paths]) - starts
    time = np.arange(n_time) * dt
    positions = np.empty((2, n_time, len(paths)))
    for case, path in enumerate(paths):
        positions[0, :, case], positions[1, :, case] = path.position(starts[case] + time)
    x_path, d_path = positions
    last_sample = np.minimum(np.floor(durations / dt + 0.5).astype(np.int64), n_time - 1)

    n_springs = _spring_count(springs, dx, max(path.max_depth for path in paths), adhesion)
    xi = (np.arange(n_springs) + 0.5) * dx
    g = springs.profile(xi)
    weights = springs.normal_weights(xi)
    g_prefix = np.concatenate([[0.0], np.cumsum(weights * g)])
    weight_prefix = np.concatenate([[0.0], np.cumsum(weights)])
    attach, detach = spring_thresholds(adhesion, g, xi, springs)
    caps = springs.caps(n_springs, dx, friction)  # ū(m Δx) for m springs per side
    bits = scale_bits(x_path, caps) if springs.grouped else None  # (the groups' integer scale)
    grid = _Grid(attach, detach, g[0], caps, bits, g, springs.coulomb_ratios(xi, friction), springs.shift_sum(xi),
                 *(springs.weight_prefix(xi) if springs.grouped else ()))
    return _Setup(time, x_path, d_path, last_sample, last_entries, grid, g_prefix, xi, weight_prefix)


#: Bytes a discrete run allocates per case and time sample (the path, the kernel's output, the dataset),
#: and per spring of the half-space (thresholds, caps, the kernel's groups): measured with tracemalloc, rounded up;
#: each kind of springs counts its own (:attr:`~mdr_events.models.spring_media.HalfSpaceSprings.bytes_per_spring`).
BYTES_PER_SAMPLE = 160
BYTES_PER_SPRING = HalfSpaceSprings.bytes_per_spring


def _time_grid_size(paths: list[Path], dt: float) -> tuple[np.ndarray, np.ndarray, int]:
    """Each path's first contact and its duration from then on (s), and the samples ``k dt`` of the shared
    time grid that covers the longest. A duration that is a whole number of steps to the round-off of the division
    (``dt = duration / n_steps``) takes that number, whichever way another CPU rounds it."""
    starts = np.array([path.first_contact_time() for path in paths])
    durations = np.array([path.duration for path in paths]) - starts
    return starts, durations, int(math.ceil(durations.max() / dt * (1.0 - ROUND_OFF))) + 1


def check_discrete_size(params: Parameters, paths: list[Path], dx: float, dt: float, limits: Limits,
                        profile: SimulatedProfile = None, layer: Layer = HALF_SPACE) -> None:
    """Estimate a discrete run's time steps, springs and memory before anything is allocated, and refuse it
    past ``limits`` (:class:`~mdr_events.limits.ResourceLimitError` saying the estimate and how to raise it)."""
    _, _, n_time = _time_grid_size(paths, dt)
    deepest = max(path.max_depth for path in paths)
    kind = springs_of(params, profile, None, layer)
    springs = kind.branch_radius(deepest) / dx + 2
    limits.check(f"the discrete run (dx={dx!r} m, dt={dt:.6g} s, {len(paths)} case(s))",
                 steps=n_time * len(paths), samples=n_time * len(paths), springs=springs,
                 memory=len(paths) * n_time * BYTES_PER_SAMPLE + springs * kind.bytes_per_spring)


def run_discrete(
    model: KernelModel | Parameters,
    paths: list[Path],
    dx: float,
    dt: float,
    limits: Limits = DEFAULT_LIMITS,
) -> dict[str, np.ndarray]:
    r"""Run the spring model for several paths on a common time grid.

    The springs of width ``Δx`` have the stiffnesses (5), (6); a spring at ``x`` in contact is compressed by
    (7), its tangential shift follows the indenter from its attachment and is capped by (13), and the forces
    are the sums (15):

    .. math:: \Delta k_z = E^* \Delta x \quad (5), \qquad \Delta k_x = G^* \Delta x \quad (6), \qquad
              u_z(x) = d - g(x) \quad (7)

    .. math:: |u_x| \le \bar u(a) = \frac{\pi a \tau_0}{2 G^*} \quad (13), \qquad
              F_N = \sum \Delta k_z u_z(x_i), \quad F_x = \sum \Delta k_x u_x(x_i) \quad (15)

    Parameters
    ----------
    model : KernelModel or Parameters
        The physical model (:class:`~mdr_events.models.kernel_model.KernelModel`; a :class:`~mdr_events.Parameters`
        alone is the paper's model of its values), its parts read as follows.

        - ``params``: the material, ``R``, ``τ0``, the works of adhesion.
        - ``profile``: a :class:`~mdr_events.contact.indenters.PowerLaw` (``n >= 1``), a flat punch, a table, or the
          springs' profile ``g(x)`` (vectorised); default the paraboloid (4).
        - ``friction``: the cap on the springs' shifts (:mod:`mdr_events.contact.friction`); default the paper's
          ``"tau0"``. A law with Coulomb's part gives every spring its own cap and is stepped spring by spring
          (:func:`_run_case_per_spring`).
        - ``adhesion``: the law whose thresholds the springs follow (:data:`THRESHOLD_RULES`); default the paper's
          law of ``params.dgamma0`` and ``params.dgamma1`` (:func:`~mdr_events.contact.adhesion.law_of`).
        - ``layer``: the elastomer's body (default the half-space). On a layer of finite thickness the springs are
          those of the generalized MDR (:mod:`~mdr_events.models.spring_media`): ``k(x_j) Δx`` and ``k_t(x_j) Δx``
          over the layer's ``g(x)``, Heß's rule with ``Δl = sqrt(4π a Δγ/K'(a))``, the caps ``π a² τ0/K_t(a)`` and
          ``μ (k/k_t)(d − g)``, ``F_N = 2Σ k(x_j) Δx (d − g(x_j))``, ``F_x = 2Σ k_t(x_j) Δx u_j`` (the groups' sums
          weighted by integer ``k_t(x_j)/G*``). It takes the paraboloid or a power law and the paper's adhesion law;
          on a frictionless base only paths without tangential motion.
    paths : list of Path
        One case per path; time runs from each path's first contact. A path
        may enter the elastomer several times (see the module docstring).
    dx : float
        Spring spacing Δx in m.
    dt : float
        Time step in s (the grid is ``k dt``, shared by all cases).
    limits : Limits, optional
        Refuse, before allocating, a run whose steps, springs or memory exceed them (:func:`check_discrete_size`).

    Returns
    -------
    dict
        ``time`` (n_time,) and, each of shape (n_cases, n_time) with ``nan``
        after a case has ended (pull-off with no later entry, or the end of
        its path): ``indentation_depth``,
        ``tangential_displacement``, ``normal_force``, ``tangential_force``,
        ``contact_radius``, ``sliding_fraction``, ``springs_in_contact``.
    """
    params, profile, friction, adhesion, layer = as_kernel_model(model)
    paths, limits = check_kernel_run(paths, limits)
    dx = check_real("dx", dx, "a spacing > 0 (m)", lambda value: value > 0)
    dt = check_real("dt", dt, "a finite time step > 0 (s)", lambda value: value > 0)
    indenter = indenters.check_simulated_profile(profile) if not callable(profile) else None
    friction, adhesion = as_friction_law(friction), law_of(params, adhesion)
    check_thresholds_known(adhesion)
    springs = springs_of(params, indenter, profile if callable(profile) else None, layer)
    springs.check(adhesion, paths)
    for index, path in enumerate(paths):
        indenters.check_reach(params, path.max_depth, indenter, f"path {index}")
    check_discrete_size(params, paths, dx, dt, limits, indenter, layer)
    run = _prepare(params, paths, dx, dt, None, friction, adhesion, springs)
    step_case = _run_case if springs.grouped and not run.grid.has_coulomb else _run_case_per_spring
    time, x_path, d_path, last_sample = run.time, run.x, run.d, run.last_sample.copy()
    n_cases, n_time = len(paths), time.size
    out_m = np.zeros((n_cases, n_time), dtype=np.int64)
    out_sum = np.zeros((n_cases, n_time))
    out_sliding = np.zeros((n_cases, n_time), dtype=np.int64)
    for case in range(n_cases):
        edge = EDGE_RULES.get(type(adhesion), _edge_by_thresholds)(adhesion, run, params, d_path[:, case], time,
                                                                    int(last_sample[case]))
        last_sample[case] = step_case(run.grid, x_path[:, case], d_path[:, case], time, int(last_sample[case]),
                                      float(run.last_entries[case]), out_m[case], out_sum[case], out_sliding[case],
                                      edge=edge)

    valid = np.arange(n_time)[None, :] <= last_sample[:, None]
    radius = out_m * dx
    with np.errstate(invalid="ignore", divide="ignore"):
        normal = 2.0 * params.E_star * dx * (run.weight_prefix[out_m] * d_path.T - run.g_prefix[out_m])
        tangential = 2.0 * params.G_star * dx * out_sum
        sliding = np.where(out_m > 0, out_sliding / out_m, np.nan)
    result = {
        "time": time,
        "indentation_depth": d_path.T,
        "tangential_displacement": x_path.T,
        "normal_force": normal,
        "tangential_force": tangential,
        "contact_radius": radius.astype(float),
        "sliding_fraction": sliding,
        "springs_in_contact": out_m.astype(float),
    }
    for key, values in result.items():
        if key != "time":
            result[key] = np.where(valid, values, np.nan)
    result["spring_count"] = run.grid.n_springs
    return result
