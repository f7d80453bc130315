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

from array import array
from typing import Callable, NamedTuple

import numpy as np

from mdr_events.contact.adhesion import AdhesionLaw, RateDependentAdhesion, law_of
from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.models import indenters
# (the run's parts, one idea a module; their names kept here, where the tests, benchmarks and users import them)
from mdr_events.models.discrete_grid import _first_count, _Grid
from mdr_events.models.discrete_per_spring import _run_case_per_spring
from mdr_events.models.discrete_size import (BYTES_PER_SAMPLE, BYTES_PER_SPRING, MIN_SPRINGS_IN_CONTACT,  # noqa: F401
                                             SPRINGS_TO_THE_TABLES_EDGE, _spring_count, _time_grid_size,
                                             check_discrete_size, check_spacing)
from mdr_events.models.kernel_model import KernelModel, as_kernel_model, check_kernel_run
from mdr_events.models.paths import Path
from mdr_events.models.rate_springs import rate_edge_counts
from mdr_events.models.spring_groups import SpringGroups, scale_bits, scaled
from mdr_events.models.spring_media import HalfSpaceSprings, Springs, springs_of
from mdr_events.models.spring_thresholds import (THRESHOLD_RULES, Thresholds, check_thresholds_known,  # noqa: F401
                                                 hysteresis_thresholds, rate_thresholds, spring_thresholds)
from mdr_events.parameters import Parameters
from mdr_events.validation import check_real

__all__ = ["run_discrete", "paraboloid_profile", "MIN_SPRINGS_IN_CONTACT", "Thresholds", "THRESHOLD_RULES",
           "EDGE_RULES", "spring_thresholds", "check_thresholds_known", "threshold_counts"]


def paraboloid_profile(params: Parameters) -> Callable[[np.ndarray], np.ndarray]:
    r"""``g(x) = x²/R``, eq. (4), as derived by :mod:`mdr_events.theory.symbolic`.

    .. math:: f(r) = \frac{r^2}{2R} \;\Rightarrow\; g(x) = \frac{x^2}{R} \qquad (4)
    """
    return indenters.spring_profile(params, None)


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
