"""Scenarios A's and B's slip onsets with adhesion under both parts of the cap (``"tau0+coulomb"``) on a power law.

Along ``x = d cot α`` from the first contact at ``d = 0`` every spring sticks until the first reaches its cap: the
springs under the jump-in radius ``a_J`` hold ``d cot α``, those grown since along the ``Δγ0`` branch
``(d − d0(ξ)) cot α``, against ``K a + κ max(d − g(ξ), 0)``. The largest excess of shift over cap lies at ``a_J``, at
the compression boundary ``x_c`` (``g(x_c) = d``) or at the turn ``ξ*`` of the compressed grown springs
(``symbolic.derive_adhesive_friction_model``: ``adhesive_onset_excess_A``, ``adhesive_onset_turn_A``), wherever they
lie in the contact (:func:`onset_excess_A`); the onset is the least depth where it reaches 0 (:func:`d_crit_A`), found
on a grid of :data:`GRID` depths to ``d_max`` and refined by bisection to :data:`BISECTIONS` halvings. No spring slides
on the negative side: every shift is ``>= 0``. The critical angle (slip at ``d_max``) is where that first depth is
``d_max`` (:func:`critical_angle_A`): the excess grows with ``cot α`` at every spring and depth, so the angles that
slide before ``d_max`` are those below it.

Scenario B's indentation branch (further in at ``α`` from ``d_max``, ``x = (d − d_max) cot α``) is the same about the
contact of ``d_max``: its springs, all anchored at ``x = 0``, are the ring (radius ``a(d_max)``, anchored at the depth
``d_max`` in place of ``a_J`` at 0), the springs grown since the same (:func:`d_crit_B_indentation`, searched up to
:data:`INDENTATION_REACH` ``d_max``). Its pull-off branch needs no search: the edge, in tension, slides first, at (21)
(``adhesive_onset_excess_B``).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import PowerLaw
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law, symbolic
# (the closed forms unchecked: their radii here are computed, an angle near 0° may take them to inf)
from mdr_events.theory.power_law.normal import (_branch_depth as _power_law_depth,
                                                _equivalent_profile as _power_law_profile)

__all__ = ["GRID", "BISECTIONS", "INDENTATION_REACH", "onset_excess_A", "d_crit_A", "critical_angle_A",
           "d_crit_B_indentation"]

#: Depths to ``d_max`` at which the excess is sampled for its first change of sign (its parts are smooth in the depth)
GRID = 2048
#: Angles whose excess is sampled on the grid at once. Sampled all at once, each angle held some 166 kB of the grid's
#: temporaries (81 B a depth: a dozen arrays of ``GRID``), so that a phase diagram of 1e5 angles peaked at 16.6 GB
#: where ``Limits.memory`` counted 160 B an angle (issue 32, round 29). Each row is its angle's alone: the same numbers
#: in any grouping, and 16 rows at once (~2 of :data:`~mdr_events.theory.blocks.BLOCK`) are faster than all at once.
GRID_ROWS = 16
#: The grid's temporaries of :data:`GRID_ROWS` angles at its peak (96 B a depth: 81 measured, rounded up), whatever the
#: number of angles: what a run of this module's onsets holds beside the angles' own arrays.
GRID_WORKING_BYTES = 96 * GRID * GRID_ROWS
#: Halvings of a bracketing grid interval: the onset to 2⁻⁶⁰ of ``d_max``, below its rounding
BISECTIONS = 60
#: How deep scenario B's indentation branch is searched for its onset, in ``d_max`` (on a geometric grid: each step
#: 0.7 % deeper); where none is found it never comes if ``cot α <= κ`` (below), else it is not known (``nan``)
INDENTATION_REACH = 2.0**20
#: What NumPy may meet in the excess's parts of a path near the surface (``α`` down to the least double, ``cot α`` up
#: to ~1e308; issue 32 round 29: the overflow's ``RuntimeWarning`` leaked from ``d_crit_A`` at 1e-300°). In the bound
#: on ``x_c`` ``cot α`` squared overflows to ``inf``, a bound beyond every depth. In the turn ``ξ*`` it overflows in
#: ``G*² cot α²`` above and below (the moduli taken to order 1 first, :func:`_unit_moduli`): ``0`` (the denominator
#: first), then ``inf/inf``, ``nan``, neither of which a comparison reads as inside the contact (the turn's own limit
#: is finite, 3.4e-4 m on the paper's paraboloid), and needs not: where it overflows so (``cot α`` beyond ~1e154) the
#: ring's edge alone, ``d cot α``, exceeds its cap at the least depth bisected (onset 0 in A, ``d_max`` in B's
#: indentation, as at 1e-50°).
_UNREAD = {"over": "ignore", "divide": "ignore", "invalid": "ignore"}


def onset_excess_A(depth, cot: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> np.ndarray:
    """The largest excess of shift over cap (m) of scenario A's springs at ``depth`` (array) on the path of
    ``cot α`` (array, broadcast with it), before any slides (module docstring).

    Parameters
    ----------
    depth : array_like
        Depths ``d > 0`` (m).
    cot : array_like
        ``cot α`` of the paths.
    friction : FrictionLaw
        ``"tau0+coulomb"`` (its ``μ``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0``.
    profile : PowerLaw
        The indenter.

    Returns
    -------
    numpy.ndarray
        ``max_ξ [(d − d_ξ) cot α − ū(ξ)]`` (m), the broadcast shape.
    """
    return _onset_excess(depth, cot, friction, params, profile, _jump_in_ring(params, profile))


class _Ring(NamedTuple):
    """The springs that attached together (all anchored at the same ``x``, at the depth ``depth``) out to ``radius``:
    scenario A's jump-in ring at ``d = 0``, scenario B's contact of ``d_max`` before it goes on at the angle."""

    radius: float
    depth: float


def _jump_in_ring(params: Parameters, profile: PowerLaw) -> _Ring:
    """Scenario A's ring: the springs of the jump-in (its radius on the ``Δγ0`` branch, none without adhesion), at
    depth 0."""
    jump_in = power_law.jump_in_radius(profile, params, params.dgamma0) if params.dgamma0 > 0 else 0.0
    return _Ring(jump_in, 0.0)


class _UnitModuli(NamedTuple):
    """The stresses of the turn and its excess (Pa, J/m²: ``Δγ0``, ``E*``, ``G*``, ``τ0``) times one power of four,
    ``G*`` then in [0.5, 2)."""

    dgamma0: float
    E_star: float
    G_star: float
    tau0: float


def _unit_moduli(params: Parameters) -> _UnitModuli:
    """:class:`_UnitModuli` of ``params``. The turn ``ξ*`` and the excess (lengths) are invariant under the stress
    scaling ``(Δγ0, E*, G*, τ0) → λ (…)``, and a power of four scales every product of the relations exactly: the
    same doubles bit for bit wherever the moduli as given stay finite, and no ``G*² cot α²`` overflow at ordinary
    angles where ``G*`` is near :data:`~mdr_events.validation.SCALE_MAX` (issue 32 round 29: ``E = 1e154`` at 20° and
    60° dropped the turn, a wrong onset)."""
    exponent = -2 * (math.frexp(params.G_star)[1] // 2)  # (even: ``√Δγ0/√E*`` of the excess exact as well)
    return _UnitModuli(*(math.ldexp(value, exponent)
                         for value in (params.dgamma0, params.E_star, params.G_star, params.tau0)))


def _cot(alpha) -> np.ndarray:
    """``cot α`` of the angles ``alpha`` (degrees)."""
    return 1.0 / np.tan(np.radians(np.asarray(alpha, dtype=float)))


def _scenario_A_depths(params: Parameters) -> np.ndarray:
    """Scenario A's grid: :data:`GRID` depths evenly to ``d_max``."""
    return params.d_max * np.arange(1, GRID + 1) / GRID


class _DepthParts(NamedTuple):
    """The parts of the excess free of the angle at the depths ``depth`` (m): the contact radius ``a`` on the
    ``Δγ0`` branch and the compression boundary ``x_c`` (``g(x_c) = d``), computed once for many angles."""

    depth: np.ndarray
    radius: np.ndarray
    boundary: np.ndarray


def _depth_parts(depth: np.ndarray, params: Parameters, profile: PowerLaw) -> _DepthParts:
    """:class:`_DepthParts` at ``depth`` (array)."""
    return _DepthParts(depth, np.asarray(power_law.contact_radius(depth, profile, params, params.dgamma0), dtype=float),
                       np.asarray(power_law.contact_radius(depth, profile, params, 0.0), dtype=float))


def _onset_excess(depth, cot, friction: FrictionLaw, params: Parameters, profile: PowerLaw, ring: _Ring) -> np.ndarray:
    """:func:`onset_excess_A` about the ``ring`` (its edge, ``x_c`` and the turn beyond it, where in the contact)."""
    depth, cot = np.broadcast_arrays(np.asarray(depth, dtype=float), np.asarray(cot, dtype=float))
    return _excess_of(_depth_parts(depth, params, profile), cot, friction, params, profile, ring)


def _excess_of(parts: _DepthParts, cot: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw,
               ring: _Ring) -> np.ndarray:
    """:func:`_onset_excess` from the depths' :class:`_DepthParts` and ``cot α`` (broadcast to their shape)."""
    depth, radius, boundary = parts
    cot = np.broadcast_to(cot, depth.shape)
    K, kappa = power_law.cap_per_radius(params), friction.coulomb_mu * params.E_star / params.G_star
    jump_in = ring.radius
    g_jump_in = float(_power_law_profile(jump_in, profile))
    best = (depth - ring.depth) * cot - K * radius - kappa * np.maximum(depth - g_jump_in, 0.0)  # the ring's edge
    hess = power_law.hess_prefactor(params, params.dgamma0)
    at_boundary = cot * hess * np.sqrt(boundary) - K * radius  # (d − d0(x_c) = Δl0(x_c))
    best = np.where((boundary > jump_in) & (boundary < radius), np.maximum(best, at_boundary), best)
    turning = cot > kappa  # the compressed grown springs' excess has its one maximum at ξ* (free of d)
    if np.any(turning) and params.dgamma0 > 0:
        unit = _unit_moduli(params)
        arguments = (friction.coulomb_mu, unit.dgamma0, profile.c, profile.n, unit.E_star, unit.G_star)
        with np.errstate(**_UNREAD):
            turn = np.asarray(symbolic.relation("adhesive_onset_turn_A").numeric(cot, *arguments), dtype=float)
            at_turn = np.asarray(symbolic.relation("adhesive_onset_excess_A").numeric(
                turn, depth, radius, cot, unit.tau0, *arguments), dtype=float)
        inside = turning & (turn > jump_in) & (turn < boundary)
        best = np.where(inside, np.maximum(best, at_turn), best)
    return best


def d_crit_A(alpha: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> np.ndarray:
    """The onset depth (m) of scenario A at the angles ``alpha`` (degrees, in (0, 90)): the least depth up to
    ``d_max`` where :func:`onset_excess_A` reaches 0; 0 where it is reached at the least depth bisected (the springs
    slide from first contact: a cone without adhesion), ``nan`` where none is by ``d_max``.

    Parameters
    ----------
    alpha : numpy.ndarray
        Path angles (degrees), in (0, 90).
    friction : FrictionLaw
        ``"tau0+coulomb"``.
    params : Parameters
        The material, ``τ0``, ``Δγ0`` and ``d_max``.
    profile : PowerLaw
        The indenter.

    Returns
    -------
    numpy.ndarray
        The onset depths (m), the shape of ``alpha``.
    """
    return _first_depth(lambda depth, cot: onset_excess_A(depth, cot, friction, params, profile), _cot(alpha),
                        0.0, _scenario_A_depths(params)).reshape(np.shape(alpha))


def _first_depth(excess, cot: np.ndarray, start: float, depths: np.ndarray) -> np.ndarray:
    """The least depth beyond ``start`` where ``excess(depth, cot)`` reaches 0 for each ``cot`` (flat array): the
    first grid depth of ``depths`` where it is reached, refined by :data:`BISECTIONS` halvings; ``start`` where it is
    reached at the least depth bisected (at once), ``nan`` where it is not by the last depth."""
    flat = np.asarray(cot, dtype=float).reshape(-1)
    first, found = _first_reached(excess, flat, depths)
    low = np.where(first > 0, depths[np.maximum(first - 1, 0)], start)
    high = depths[first]
    for _ in range(BISECTIONS):  # the excess is < 0 at low (or at the start: −K a of the ring) and >= 0 at high
        middle = 0.5 * (low + high)
        up = excess(middle, flat) >= 0.0
        low, high = np.where(up, low, middle), np.where(up, middle, high)
    # an excess already reached at the smallest depth bisected: the springs slide at once
    at_once = found & (low == start) & (excess(high, flat) >= 0.0)
    return np.where(at_once, start, np.where(found, high, np.nan))


def _first_reached(excess, flat: np.ndarray, depths: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For each ``cot`` of ``flat``, the index of the first of ``depths`` where ``excess`` reaches 0 (0 where none
    does) and whether one does: the grid sampled :data:`GRID_ROWS` angles at a time."""
    first, found = np.zeros(len(flat), dtype=np.intp), np.zeros(len(flat), dtype=bool)
    for start in range(0, len(flat), GRID_ROWS):
        rows = slice(start, start + GRID_ROWS)
        reached = excess(depths[None, :], flat[rows].reshape(-1, 1)) >= 0.0
        first[rows] = np.argmax(reached, axis=1)
        found[rows] = reached[np.arange(len(reached)), first[rows]]
    return first, found


def d_crit_B_indentation(alpha: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> np.ndarray:
    """The onset depth (m) of scenario B's indentation branch at the angles ``alpha`` (degrees, in (0, 90)): the
    least depth beyond ``d_max`` where the excess about the contact of ``d_max`` (its springs the ring, anchored at
    ``x = 0``) reaches 0 (module docstring), on a geometric grid of :data:`GRID` depths to :data:`INDENTATION_REACH`
    ``d_max``; ``d_max`` where a spring slides at once; where none does within the reach ``+inf`` (never) if
    ``cot α <= κ`` and the depth beyond which none can (:func:`_never_beyond`) lies within it, else ``nan``.

    Parameters
    ----------
    alpha : numpy.ndarray
        The angles of the stroke from ``d_max`` further in (degrees), in (0, 90).
    friction : FrictionLaw
        ``"tau0+coulomb"`` (its ``μ``).
    params : Parameters
        The material, ``τ0``, ``d_max`` and ``Δγ0``, the branch the radius grows on.
    profile : PowerLaw
        The curved indenter.

    Returns
    -------
    numpy.ndarray
        The onset depths (m; ``+inf`` never, ``nan`` not known), the shape of ``alpha``.
    """
    cot = _cot(alpha).reshape(-1)
    ring = _Ring(float(power_law.contact_radius(params.d_max, profile, params, params.dgamma0)), params.d_max)
    depths = params.d_max * INDENTATION_REACH ** (np.arange(1, GRID + 1) / GRID)
    onset = _first_depth(lambda depth, cot: _onset_excess(depth, cot, friction, params, profile, ring), cot,
                         params.d_max, depths)
    return np.where(np.isnan(onset) & (_never_beyond(cot, friction, params, profile, ring) <= depths[-1]), np.inf,
                    onset).reshape(np.shape(alpha))


def _never_beyond(cot: np.ndarray, friction: FrictionLaw, params: Parameters, profile: PowerLaw,
                  ring: _Ring) -> np.ndarray:
    """A depth beyond which no spring of scenario B's indentation branch reaches its cap, where ``cot α <= κ``
    (``inf`` elsewhere). There the compressed grown springs' excess ``(d − d0)(cot α − κ) + κ Δl0 − K a`` is largest at
    ``x_c``, where it is ``cot α Δl0(x_c) − K a <= cot α k √x_c − K x_c``, below 0 once ``x_c > (cot α k/K)²`` (``k``
    Heß's prefactor); the ring's edge falls once compressed (``d > g(a(d_max))``: its slope ``cot α − κ − K ȧ < 0``)."""
    kappa = friction.coulomb_mu * params.E_star / params.G_star
    K, hess = power_law.cap_per_radius(params), power_law.hess_prefactor(params, params.dgamma0)
    with np.errstate(**_UNREAD):
        boundary = np.asarray(_power_law_profile((cot * hess / K) ** 2, profile), dtype=float)
    compressed_ring = float(_power_law_profile(ring.radius, profile))
    bound = np.where(cot <= kappa, np.maximum(boundary, compressed_ring), np.inf)
    if profile.n == 1.0:
        bound = np.minimum(bound, _cone_never_beyond(cot, kappa, K, friction, params, profile, ring, boundary))
    return bound


def _cone_never_beyond(cot: np.ndarray, kappa: float, K: float, friction: FrictionLaw, params: Parameters,
                       profile: PowerLaw, ring: _Ring, boundary: np.ndarray) -> np.ndarray:
    """:func:`_never_beyond` of the cone where ``s = cot α − κ − K/(κ₁ c) < 0``: on the ``Δγ0`` branch
    ``κ₁ c a = d + k √a >= d``, so the ring's compressed edge's excess is at most ``s d + κ g(a_R) − d_max cot α`` and
    the grown springs' turn's ``s d + κ Δl0(ξ*) − d0(ξ*)(cot α − κ)``: both below 0 beyond their constant over ``−s``;
    ``x_c`` as for ``cot α <= κ``."""
    prefactor = float(_power_law_profile(1.0, profile))  # κ₁ c
    slope = cot - kappa - K / prefactor
    g_ring = float(_power_law_profile(ring.radius, profile))
    constants = [kappa * g_ring - params.d_max * cot]
    unit = _unit_moduli(params)
    arguments = (friction.coulomb_mu, unit.dgamma0, profile.c, profile.n, unit.E_star, unit.G_star)
    if params.dgamma0 > 0:
        with np.errstate(**_UNREAD):
            turn = np.asarray(symbolic.relation("adhesive_onset_turn_A").numeric(cot, *arguments), dtype=float)
            grown = np.asarray(_power_law_depth(turn, profile, params, params.dgamma0), dtype=float)
        hess = power_law.hess_prefactor(params, params.dgamma0)
        constants.append(np.where(cot > kappa, kappa * hess * np.sqrt(turn) - grown * (cot - kappa), -np.inf))
    with np.errstate(**_UNREAD):
        linear = np.maximum.reduce([np.maximum(np.asarray(c, dtype=float), 0.0) for c in constants]) / -slope
    return np.where(slope < 0.0, np.maximum.reduce([linear, boundary, np.full(cot.shape, g_ring)]), np.inf)


def critical_angle_A(friction: FrictionLaw, params: Parameters, profile: PowerLaw) -> float:
    """The angle (degrees) below which scenario A slides before ``d_max``: bisection on whether :func:`d_crit_A`
    finds an onset (monotone in the angle: module docstring); 90° where even a path along the surface slides, 0 where
    none does.

    Parameters
    ----------
    friction : FrictionLaw
        ``"tau0+coulomb"``.
    params : Parameters
        The material, ``τ0``, ``Δγ0`` and ``d_max``.
    profile : PowerLaw
        The indenter.

    Returns
    -------
    float
        ``α_c`` (degrees).
    """
    # d_crit_A is nan exactly where no grid depth reaches the excess (its refinement only places a found onset): the
    # angle-free parts of the excess on that grid are computed once, each angle then reads the grid alone
    ring, parts = _jump_in_ring(params, profile), _depth_parts(_scenario_A_depths(params)[None, :], params, profile)
    low, high = 0.0, 90.0
    for _ in range(BISECTIONS):
        middle = 0.5 * (low + high)
        if not np.any(_excess_of(parts, _cot([middle]).reshape(-1, 1), friction, params, profile, ring) >= 0.0):
            high = middle
        else:
            low = middle
    return 0.5 * (low + high)
