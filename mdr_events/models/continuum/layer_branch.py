r"""One adhesive branch of a paraboloid or power law on a layer of finite thickness: :class:`LayerBranch`.

The generalized MDR's branch (generalised (9)) is ``d(a) = g(a) − sqrt(4π a Δγ/K'(a))`` with the layer's profile
``g = κₙ c aⁿ γₙ(a/h)`` and ``K' = 2E* Θ(1; a/h)²`` (:mod:`mdr_events.theory.layer`); its depth and slope are the
relations of :mod:`mdr_events.theory.layer_continuum_symbolic` evaluated on the tables' factors for one float
(:class:`~mdr_events.theory.layer.scalar_factors.NormalFactors`). The radius of a depth is the root on the stable part
(``a`` at or beyond the jump-off, ``∂d/∂a ≥ 0``) by Newton's iteration kept inside a bracket (bisection where a step
leaves it), started from the last root found: the continuum asks for nearby depths one after the other.
"""

from __future__ import annotations

import bisect
import functools
import math

import numpy as np

from mdr_events.contact.indenters import Paraboloid, PowerLaw
from mdr_events.contact.layer import Layer
from mdr_events.parameters import Parameters
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.relations import _abel_factor, _power_law
from mdr_events.theory.layer.scalar_factors import NormalFactors
from mdr_events.theory.layer.tables import LAMBDA_MIN
from mdr_events.theory import symbolic
from mdr_events.theory.layer_continuum_symbolic import derive_continuum_model

from .branch import FOLD_SHARE, Branch
from .hermite_start import hermite_start

__all__ = ["LayerBranch", "ROOT_ITERATIONS", "RADII_RTOL", "NEWTON_SHARE"]

#: The most steps of the radius's root (Newton's, or bisections where a step leaves the bracket): each bisection
#: halves the bracket's logarithm, which starts below 60 (doublings from the jump-off to ``a/h = 64``).
ROOT_ITERATIONS = 200
#: How many radii's depth and slope a branch remembers (:attr:`LayerBranch._values`).
VALUE_CACHE = 64
#: Points per decade of the scan whose inverse's cubic Hermite interpolant starts Newton's iteration for a radius
#: (:meth:`LayerBranch.radius`, :meth:`LayerBranch.radii`): neighbours 10^(1/128) apart (1.8%) put the start within
#: ~2e-9 of the root (measured on the paper's 5 mm layer, median; 3e-8 at 64 a decade: the cubic's error falls as
#: (Δa/a)⁴), one of Newton's steps from 1e-14, which :data:`NEWTON_SHARE` takes as the root without reading the branch
#: again (at 64 a decade a quarter of the radii needed a second reading; the chord of 10^(1/16) was ~1e-3 off, three
#: steps). The start is a function of the depth alone, so that a radius never depends on the roots asked before it (a
#: start from the last roots found made the same solution evaluated twice differ by an ulp, on some CPUs).
START_SCAN_PER_DECADE = 128
#: The start scan's lowest radius without adhesion, in layer thicknesses (the branch starts at ``a = 0`` there).
START_SCAN_FLOOR = 1e-6
#: Without adhesion, a contact below this share of the layer's thickness is the half-space's to rounding: the layer's
#: correction to ``d = κ c aⁿ`` is of the order of ``a/h`` (its tables' series), below an ulp there. Its radius is
#: then ``d^(1/n)/(κc)^(1/n)`` in closed form (each power of a double, not of their quotient, which underflows):
#: Newton's iteration from the scan's first radius (``START_SCAN_FLOOR h``) halves its way down and did not reach the radius of a subnormal first depth (1e-322 m, a run at 1 m/s) in
#: :data:`ROOT_ITERATIONS` steps, where ``d(a)`` cannot be evaluated anyway (``aⁿ`` underflows).
HALF_SPACE_SHARE = float(np.finfo(float).eps)
#: Points per decade of the scan that brackets the jump-off (where ``∂d/∂a`` turns positive; Brent's method refines).
_SCAN_PER_DECADE = 5


class LayerBranch(Branch):
    r"""The branch of work ``work`` of a paraboloid or power law on ``layer``: depth, slope, integral of a radius,
    radius of a depth.

    .. math:: d(a) = \kappa_n c\, a^n \gamma_n(a/h) - \sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}}, \qquad
              K'(a) = 2E^*\,\Theta(1; a/h)^2 \qquad (9)

    Parameters
    ----------
    params : Parameters
        The material (``E*``).
    work : float
        The work of adhesion ``Δγ`` (J/m²) of the branch (0: no adhesion, ``d = g(a)``).
    indenter : Paraboloid or PowerLaw
        The indenter.
    layer : Layer
        The layer (finite thickness).
    factors : NormalFactors
        The layer's tabulated normal factors for one float.

    Raises
    ------
    ValueError
        A jump-off beyond the tables (``a/h > 64``).
    """

    def __init__(self, params: Parameters, work: float, indenter: Paraboloid | PowerLaw, layer: Layer,
                 factors: NormalFactors):
        self.params, self.work, self.layer, self.factors = params, work, layer, factors
        c, self.n = self._power(indenter)
        self.kc = _abel_factor(self.n) * c
        relations = derive_continuum_model()
        self._pair = relations["layer_continuum_branch_pair"].scalar
        #: Heß's half-space prefactor ``c_H = sqrt(2π Δγ/E*)`` (8), ``Δl = c_H √a/Θ`` on the layer
        self.hess = float(symbolic.relation("hess_max_elongation").numeric(1.0, work, params.E_star))
        self.h = layer.thickness
        self._profile = relations["layer_continuum_profile"].scalar
        self._force_slope = relations["layer_continuum_normal_force_slope"].scalar
        self._pair_array = relations["layer_continuum_branch_pair"].numeric
        self.ceiling = self._ceiling(indenter)
        #: the tables' series meets their splines at ``a/h = LAMBDA_MIN``: the slope's derivative jumps there
        self.knots = tuple(knot for knot in (LAMBDA_MIN * layer.thickness,) if knot < self.ceiling)
        #: the depth and slope of a radius, remembered: a right-hand side asks for both at one radius
        self._values = functools.lru_cache(maxsize=VALUE_CACHE)(self._evaluate)
        self.jump_off_radius = self._jump_off_radius() if work > 0.0 else 0.0
        self.jump_off_depth = self.depth(self.jump_off_radius)
        self._floor = self.jump_off_radius
        #: the depth below which the branch is the half-space's to rounding (:data:`HALF_SPACE_SHARE`; adhesion: none)
        self._half_space_depth = self.kc * (HALF_SPACE_SHARE * self.h) ** self.n if work == 0.0 else 0.0
        self._start_scan: tuple | None = None  # (:meth:`_scans`: when asked)

    # --- what a kind of indenter sets (:class:`~.layer_punch_branch.LayerPunchBranch` the flat face's) --------------
    def _power(self, indenter) -> tuple[float, float]:
        """The profile's ``c`` and ``n`` (``f = c rⁿ``)."""
        return _power_law(indenter)

    def _ceiling(self, indenter) -> float:
        """The largest radius of the branch: the tables' ``LAMBDA_MAX h``."""
        return LAMBDA_MAX * self.layer.thickness

    def _jump_off_radius(self) -> float:
        """The jump-off's radius (:func:`_jump_off_radius`)."""
        return _jump_off_radius(self)

    def _key(self) -> tuple:
        """What the branch's values depend on (the key of the scans kept, :data:`_SCANS`)."""
        return _branch_key(self)

    # --- the branch at one radius ----------------------------------------------------------------------------
    def _evaluate(self, a: float) -> tuple[float, float]:
        """``d(a)`` and ``∂d/∂a`` (``a > 0``; ``layer_continuum_branch_pair``)."""
        theta, theta_slope, gamma, gamma_slope = self.factors.edge_and_profile(a)
        return self._pair(a, self.h, self.kc, self.n, gamma, gamma_slope, self.hess, theta, theta_slope)

    def depth(self, a: float) -> float:
        """Depth of the contact of radius ``a`` on this branch (0 at ``a = 0``).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``d`` (m).
        """
        return self._values(float(a))[0] if a > 0 else 0.0

    def slope(self, a: float) -> float:
        """``∂d/∂a`` on this branch (at ``a = 0``: ``-inf`` with adhesion, 0 without for ``n > 1``).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The slope (1).
        """
        if a > 0:
            return self._values(float(a))[1]
        if self.work > 0.0:
            return -math.inf
        return 0.0 if self.n > 1.0 else (self.kc if self.n == 1.0 else math.inf)

    def integral(self, a: float) -> float:
        """``∫₀ᵃ d(ξ) dξ`` along this branch (adaptive quadrature).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The integral (m²; 0 at ``a <= 0``).
        """
        from scipy.integrate import quad

        return float(quad(self.depth, 0.0, a, epsabs=0.0, epsrel=1e-13, limit=200)[0]) if a > 0 else 0.0

    def depth_term(self, a: float) -> float:
        """The layer's profile at the radius, ``g(a)``: the size of the branch's terms.

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``g(a)`` (m).
        """
        return self._profile(a, self.kc, self.n, self.factors.profile_factor(a)[0]) if a > 0 else 0.0

    def normal_force_slope(self, a: float) -> float:
        r"""``dF_N/da`` along the branch over ``2E*``: ``(K'(a)(d − g(a)) + K(a) d'(a))/(2E*)``
        (``layer_continuum_normal_force_slope``).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The slope over ``2E*`` (m).
        """
        if not a > 0:  # (K(0) = 0 and d = g = 0 at the first touch)
            return 0.0
        depth, slope = self._values(a)
        theta = self.factors.edge_factor(a)[0]
        return self._force_slope(a * self.factors.stiffness_factor(a), theta * theta, depth, self.depth_term(a),
                                 slope)

    # --- radius of a depth -----------------------------------------------------------------------------------
    def _scan(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The scan that starts Newton's iteration: :data:`START_SCAN_PER_DECADE` radii a decade from the jump-off (or
        :data:`START_SCAN_FLOOR` ``h`` without adhesion) to the tables' ceiling, their depths and slopes (from the
        tables' vectorised splines; made when first asked and kept per branch's values, :data:`_SCANS`: the runs of
        one contact's angles share it)."""
        return self._scans()[0]

    def _scan_lists(self) -> tuple[list[float], list[float], list[float]]:
        """:meth:`_scan` as lists of floats (the scalar start's: NumPy's scalars cost microseconds)."""
        return self._scans()[1]

    def _scans(self) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray], tuple[list[float], ...], np.ndarray,
                              list[float]]:
        """The start scan as arrays and as lists, and Newton's constant ``|d''|/(2 d')`` on each of its intervals (the
        chord of its slopes over its length and twice its least slope; ``inf`` where a slope is not positive), as an
        array and as a list."""
        if self._start_scan is None:
            key = (*self._key(), self.jump_off_radius)
            if key not in _SCANS:
                lowest = self.jump_off_radius if self.jump_off_radius > 0.0 else START_SCAN_FLOOR * self.h
                points = max(int(math.ceil(START_SCAN_PER_DECADE * math.log10(self.ceiling / lowest))), 1) + 1
                radii = np.geomspace(lowest, self.ceiling, points)
                scan = (radii, *self._arrays(radii))
                slopes = scan[2]
                least = np.minimum(slopes[:-1], slopes[1:])
                with np.errstate(divide="ignore", invalid="ignore"):
                    constants = np.where(least > 0.0, np.abs(np.diff(slopes)) / np.diff(radii) / (2.0 * least), np.inf)
                if len(_SCANS) >= _JUMP_OFFS_KEPT:
                    _SCANS.clear()
                _SCANS[key] = (scan, tuple(column.tolist() for column in scan), constants, constants.tolist())
            self._start_scan = _SCANS[key]
        return self._start_scan

    def _newton_constants(self) -> np.ndarray:
        """Newton's constant ``|d''|/(2 d')`` on each interval of the start scan (kept with it, :meth:`_scans`)."""
        return self._scans()[2]

    def _start(self, depth: float) -> tuple[float, float]:
        """Newton's start for ``depth``: the inverse's cubic Hermite interpolant on the scan (:meth:`_scan`) about it
        (:func:`~.hermite_start.hermite_start`), the scan's first or last radius outside it; and Newton's constant of
        its interval (``inf`` outside the scan). A function of ``depth`` alone."""
        radii, depths, slopes = self._scan_lists()
        index = bisect.bisect_left(depths, depth)
        if index == 0 or index == len(radii):
            return radii[min(index, len(radii) - 1)], math.inf
        return (hermite_start(depth, radii[index - 1:index + 1], depths[index - 1:index + 1],
                              slopes[index - 1:index + 1]), self._scans()[3][index - 1])

    def radius(self, depth: float, rtol: float) -> float:
        """Stable-branch radius at ``depth``, converged to ``rtol`` (``nan`` below the jump-off depth; within
        :data:`~.branch.FOLD_SHARE` of it, the jump-off radius).

        Parameters
        ----------
        depth : float
            The depth ``d`` (m).
        rtol : float
            The relative accuracy of the root.

        Returns
        -------
        float
            The radius ``a`` (m) or ``nan``.

        Raises
        ------
        ValueError
            A radius beyond the tables (``a/h > 64``).
        """
        if self.work == 0.0 and depth <= self._half_space_depth:  # (above the surface: no contact)
            return 0.0 if depth <= 0 else depth ** (1.0 / self.n) / self.kc ** (1.0 / self.n)
        if depth <= self.jump_off_depth:
            if depth < self.jump_off_depth - FOLD_SHARE * abs(self.jump_off_depth):
                return math.nan
            return self.jump_off_radius
        lower, upper = self._floor, math.inf
        depth = float(depth)
        a, constant = self._start(depth)
        for _ in range(ROOT_ITERATIONS):
            guess, step, lower, upper = self._newton_step(depth, a, lower, upper)
            if abs(step) <= rtol * a:  # (Newton's step within the tolerance: converged, wherever the bracket is)
                return guess
            if constant * step * step <= NEWTON_SHARE * rtol * a and lower < guess < min(upper, self.ceiling):
                return guess  # (the step's own bound, as radii's: the first step from the start's interval)
            constant = math.inf
            if not lower < guess < min(upper, self.ceiling):  # (outside the bracket: bisect it, or double it)
                if upper == math.inf and a >= self.ceiling:
                    raise ValueError(f"depth={depth!r} m is not allowed on {self.layer.describe()} in the continuum "
                                     f"method: its contact radius exceeds a/h = {LAMBDA_MAX:g}; allowed: depths whose "
                                     f"radius is below {self.ceiling:.6g} m")
                if upper < math.inf:
                    guess = math.sqrt(lower * upper) if lower > 0.0 else 0.5 * upper
                else:
                    guess = min(2.0 * a, self.ceiling)
            if abs(guess - a) <= rtol * a or (upper < math.inf and upper - lower <= rtol * upper):
                return guess
            a = guess
        raise RuntimeError(f"the radius of depth={depth!r} m on {self.layer.describe()} did not converge")

    def depths(self, a: np.ndarray) -> np.ndarray:
        """:meth:`depth` for an array of radii (to an ulp or two: NumPy's logarithm and exponential, not the math
        module's).

        Parameters
        ----------
        a : array_like
            The contact radii (m).

        Returns
        -------
        numpy.ndarray
            The depths (m), the shape of ``a`` (0 at ``a <= 0``).
        """
        a = np.asarray(a, dtype=float)
        positive = a > 0
        if not np.any(positive):
            return np.zeros(a.shape)
        # (the tables' vectorised splines: the scalar depth's value to an ulp or two, at a fraction of a loop's cost)
        return np.where(positive, self._arrays(np.where(positive, a, self.ceiling))[0], 0.0)

    def _arrays(self, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``d(a)`` and ``∂d/∂a`` for an array of radii (> 0), from the tables' vectorised splines."""
        theta, theta_slope, gamma, gamma_slope = self.factors.arrays(a)
        return self._pair_array(a, self.h, self.kc, self.n, gamma, gamma_slope, self.hess, theta, theta_slope)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radius` for an array of depths (to :data:`RADII_RTOL`; ``nan`` below the jump-off depth): Newton's
        iteration on all of them at once, started from a scan of the branch and kept inside its brackets.

        Parameters
        ----------
        depth : array_like
            The depths (m).

        Returns
        -------
        numpy.ndarray
            The radii (m), the shape of ``depth``.
        """
        depth = np.asarray(depth, dtype=float)
        out = np.full(depth.shape, np.nan)
        fold = self.jump_off_depth - FOLD_SHARE * abs(self.jump_off_depth)
        out[(depth <= self.jump_off_depth) & (depth >= fold)] = self.jump_off_radius
        if self.work == 0.0:  # (the half-space's below its depth: :meth:`radius` point by point)
            shallow = depth <= self._half_space_depth
            out[shallow] = [self.radius(value, RADII_RTOL) for value in depth[shallow].tolist()]
        inside = depth > (self._half_space_depth if self.work == 0.0 else self.jump_off_depth)
        count = int(np.count_nonzero(inside))
        if count > SCALAR_RADII:
            out[inside] = self._roots(depth[inside])
        elif count:  # (a few: the scalar iteration, without the arrays' fixed cost; the same root to RADII_RTOL)
            out[inside] = [self.radius(depth, RADII_RTOL) for depth in depth[inside].tolist()]
        return out

    def _roots(self, depth: np.ndarray) -> np.ndarray:
        """The radii of depths above the jump-off (:meth:`radii`), started as :meth:`_start` starts one."""
        radii, depths, slopes = self._scan()
        if float(np.max(depth)) > depths[-1]:
            self.radius(float(np.max(depth)), RADII_RTOL)  # (beyond the tables: its error, naming the layer)
        index = np.searchsorted(depths, depth)
        np.maximum(index, 1, out=index)  # (np.clip's integers, without its checks' ~10 µs)
        np.minimum(index, radii.size - 1, out=index)
        below_index = index - 1
        lower, upper = radii[below_index], radii[index]
        a = hermite_start(depth, (lower, upper), (depths[below_index], depths[index]),
                          (slopes[below_index], slopes[index]))
        if depth.size and float(np.max(depth)) >= depths[-1]:
            upper = np.where(depth >= depths[-1], 2.0 * radii[-1], upper)  # (the ceiling's root, to rounding beyond)
        below = depth <= depths[0]  # (no adhesion, below the scan: d ∝ aⁿ towards a = 0)
        q = self._newton_constants()[below_index]  # (a step δ leaves the root within q δ²: NEWTON_SHARE)
        if np.any(below):
            lower = np.where(below, 0.0, lower)
            a = np.where(below, radii[0] * np.clip(depth / depths[0], 0.0, 1.0) ** (1.0 / self.n), a)
            q = np.where(below, np.inf, q)
        out = np.empty(depth.shape)
        active = np.arange(depth.size)  # (the depths whose roots are still moving: the others are left alone)
        for _ in range(ROOT_ITERATIONS):
            value, slope = self._arrays(a)
            target = depth[active]
            above = value >= target
            upper, lower = np.where(above, np.minimum(upper, a), upper), np.where(above, lower, np.maximum(lower, a))
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(slope > 0.0, (value - target) / slope, np.inf)
            guess = a - step
            inside = (guess > lower) & (guess < upper)
            done = (np.abs(step) <= RADII_RTOL * a) | (upper - lower <= RADII_RTOL * upper)
            with np.errstate(invalid="ignore"):  # (inf · 0: no bound, the test above decides)
                done |= inside & (q * step * step <= NEWTON_SHARE * RADII_RTOL * a)  # (the step's own bound)
            guess = np.where(inside | (np.abs(step) <= RADII_RTOL * a), guess, 0.5 * (lower + upper))
            out[active[done]] = guess[done]
            moving = ~done
            if not np.any(moving):
                return out
            active, a, lower, upper, q = active[moving], guess[moving], lower[moving], upper[moving], q[moving]
            if active.size <= SCALAR_FINISH:  # (a few left, near the fold: the same steps in floats, as _finish)
                for k, start, low, high, bound in zip(active.tolist(), a.tolist(), lower.tolist(), upper.tolist(),
                                                      q.tolist()):
                    out[k] = self._finish(float(depth[k]), start, low, high, bound)
                return out
        raise RuntimeError(f"the radii of {depth.size} depths on {self.layer.describe()} did not converge")

    def _finish(self, depth: float, a: float, lower: float, upper: float, q: float) -> float:
        """The root of one of :meth:`_roots`' depths from its iterate ``a``, bracket ``[lower, upper]`` and Newton's
        constant ``q``: :meth:`_roots`' steps and stopping rules in Python floats, the branch read by :meth:`_evaluate`
        (its values to an ulp or two of the arrays'), at a few microseconds a reading where an array's costs some
        fifty however few its depths (:data:`SCALAR_FINISH`)."""
        for _ in range(ROOT_ITERATIONS):
            guess, step, lower, upper = self._newton_step(depth, a, lower, upper)
            inside, small = lower < guess < upper, abs(step) <= RADII_RTOL * a
            # (q = inf and a zero step: no bound, nan as the arrays' inf · 0, the other tests decide)
            bound = q * step * step if step != 0.0 or q != math.inf else math.nan
            done = small or upper - lower <= RADII_RTOL * upper or (inside and bound <= NEWTON_SHARE * RADII_RTOL * a)
            guess = guess if inside or small else 0.5 * (lower + upper)
            if done:
                return guess
            a = guess
        raise RuntimeError(f"the radius of depth={depth!r} m on {self.layer.describe()} did not converge")

    def _newton_step(self, depth: float, a: float, lower: float, upper: float) -> tuple[float, float, float, float]:
        """One of Newton's steps towards the radius of ``depth`` from ``a`` in floats, shared by :meth:`radius` and
        :meth:`_finish`: the bracket ``[lower, upper]`` narrowed by ``a``'s side of the root, and the guess ``a − δ``
        with the step ``δ = (d(a) − depth)/∂d/∂a`` (``inf`` where the slope is not positive). The branch is read by
        :meth:`_evaluate`, not remembered: the iterates would push out the span's radii."""
        value, slope = self._evaluate(a)
        if value >= depth:
            upper = min(upper, a)
        else:
            lower = max(lower, a)
        step = (value - depth) / slope if slope > 0.0 else math.inf
        return a - step, step, lower, upper


def _jump_off_radius(branch: LayerBranch) -> float:
    """Where the branch's ``∂d/∂a`` turns positive, its least depth: a scan brackets it, Brent's method refines it;
    kept per branch's values (:data:`_JUMP_OFFS`: the runs of one contact's angles share it)."""
    from scipy.optimize import brentq

    key = _branch_key(branch)
    if key in _JUMP_OFFS:
        return _JUMP_OFFS[key]
    scale = (2.0 * math.pi * branch.work / (branch.params.E_star * branch.kc**2)) ** (1.0 / (2.0 * branch.n - 1.0))
    radius, step = 1e-6 * scale, 10.0 ** (1.0 / _SCAN_PER_DECADE)
    while branch.slope(radius * step) < 0.0:
        radius *= step
        if radius * step > branch.ceiling:
            raise ValueError(f"the branch of work {branch.work!r} J/m² on {branch.layer.describe()} has no jump-off "
                             f"below a/h = {LAMBDA_MAX:g}; allowed: contacts within the layer's tables")
    found = float(brentq(branch.slope, radius, radius * step, xtol=1e-15 * radius, rtol=4.0 * np.finfo(float).eps))
    if len(_JUMP_OFFS) >= _JUMP_OFFS_KEPT:
        _JUMP_OFFS.clear()
    _JUMP_OFFS[key] = found
    return found


def _branch_key(branch: LayerBranch) -> tuple:
    """What a branch's values depend on: ``(E*, ν, Δγ, κₙc, n, layer)``."""
    return branch.params.E_star, branch.params.nu, branch.work, branch.kc, branch.n, branch.layer


#: The jump-off radii found, by the branch's values ``(E*, ν, Δγ, κₙc, n, layer)`` (at most :data:`_JUMP_OFFS_KEPT`).
_JUMP_OFFS: dict[tuple, float] = {}
_JUMP_OFFS_KEPT = 64
#: The start scans made (:meth:`LayerBranch._scan`), by the branch's values and its jump-off radius (as many).
_SCANS: dict[tuple, tuple] = {}


#: At most this many depths, :meth:`LayerBranch.radii` takes each one's :meth:`~LayerBranch.radius` (a run's sample at
#: a span's end, read again: the arrays' route costs some hundred microseconds however few its depths, the scalar one a
#: few each).
SCALAR_RADII = 4
#: At most this many depths still moving, :meth:`LayerBranch._roots` finishes each by :meth:`LayerBranch._finish` (the
#: same steps on one float, the branch read by ``_evaluate``, ~4 µs a reading) instead of another reading of the arrays
#: (~50 µs however few their depths): the depths near the fold, where Newton's constant is unbounded, took five more
#: readings of one or two depths each on a thin layer's receding punch (issue 34).
SCALAR_FINISH = 16
#: The accuracy of :meth:`LayerBranch.radii` (the default ``radius_rtol`` of the continuum's tolerances).
RADII_RTOL = 1e-14
#: :meth:`LayerBranch.radii` (and :meth:`LayerBranch.radius`, at its ``rtol``) takes Newton's first step ``δ`` as the
#: root, without reading the branch again, where
#: ``q δ² <= NEWTON_SHARE · RADII_RTOL · a`` (``q = |d''|/(2d')``, Newton's constant, estimated by the chord of the
#: start scan's slopes over its least one): the step's error, ``q δ²`` to leading order, then lies a hundred times
#: below the tolerance, a margin for ``d''`` varying across the scan's interval (1.8% of the radius; ``d''`` is
#: smooth there and its chord within a few per cent of it away from the jump-off, where ``q`` is infinite and the
#: iteration reads the branch again). From the Hermite start (~1e-9 of the radius) the first step is taken: one
#: reading of the branch in place of two.
NEWTON_SHARE = 1e-2
