"""The tabulated indenter (:class:`~mdr_events.contact.indenters.TabulatedProfile`): the Abel transform (3) of a table
``f(r)`` computed numerically, and Heß's relations on it where no closed form exists.

The table is interpolated by a monotone cubic (PCHIP, continuously differentiable). With ``r = x sin θ`` the
Abel transform (3) reads (:func:`mdr_events.theory.symbolic.relation` ``"abel_transform_angular"``)

    ``g(x) = x ∫_0^{π/2} f'(x sin θ) dθ``,

whose integrand has no singularity. On each θ-interval between the table's radii ``f'`` is a quadratic in
``r = x sin θ``, a quadratic in ``sin θ``, whose integral is elementary: ``g`` is exact (to round-off, for the
PCHIP of the table) at :data:`SUBDIVISIONS` points per table interval, which a PCHIP then interpolates
(:class:`EquivalentProfile`). ``g`` must increase (a profile that rises steeply and then flattens
may give a falling ``g``: refused, naming where), and so must each adhesive branch ``d(a) = g(a) − sqrt(2π a Δγ/E*)``
beyond its minimum, the jump-off (:class:`TabulatedBranch`): then the radius of a depth is a bracketed root.

The simulators and the functions below share this ``g``, so the continuum and the discrete model of a table are
each other's exact reference; against the power law a table was sampled from they agree to the table's
interpolation error: its largest value falls at second order in the table's spacing ``h`` (order ``n`` for
``1 < n < 2``), while next to the tip, where the PCHIP's slope is only first-order accurate, the relative error of
``g`` falls as ``h`` (the tests measure both).
"""

from __future__ import annotations

import bisect
import math
from typing import NamedTuple

import numpy as np
from scipy import interpolate, optimize

from mdr_events.memo import cached
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import TabulatedProfile
from mdr_events.theory import power_law, symbolic
from mdr_events.theory.analytic.arguments import _finite
from mdr_events.validation import validate_alpha

__all__ = ["SUBDIVISIONS", "GRID_POINTS", "END_SHARE", "EquivalentProfile", "TabulatedBranch", "equivalent", "branch",
           "equivalent_profile", "normal_force", "contact_radius", "jump_off", "pull_off_force", "d_crit_A",
           "critical_angle_A"]

#: Points of ``g`` computed per interval of the table (besides its radii), fewer for a long table: at most
#: :data:`GRID_POINTS` in all (a measured tip of thousands of points is fine enough as it is; the quadrature's cost
#: grows as the square of the points).
SUBDIVISIONS = 4
GRID_POINTS = 4000
#: How far past a table's end (a share of its last radius ``x_max``) a radius is its end: a radius of the continuum
#: reaches the end as ``var · scale`` of ``var = a / scale`` (two roundings, an ulp each) or a root within
#: :data:`RADIUS_RTOL`; four ulp hold both. Beyond it the branch's depth, slope and integral are ``nan``, scalar and
#: array alike (no caller reads past the end: the radius of a depth is ``nan`` there; the springs' ``g`` is ``inf``).
END_SHARE = 4 * float(np.finfo(float).eps)
#: The relative accuracy of a radius root (a few ulp).
RADIUS_RTOL = 4 * float(np.finfo(float).eps)
#: A Newton step ends an inversion where its own error, by Newton's rule ``(|d''|/2 Δ² + |d'''|/3 |Δ|³) / d'`` from the
#: step ``Δ`` (the derivatives at the root; read at the iterate, ``d''`` is off by ``d''' Δ``: the bound taken is
#: ``(|d''| + 2 |d'''| |Δ|) Δ² / (2 d')``), is at most this share of the asked accuracy: from the Hermite start (~1e-9
#: of the radius on a 41-point table) one step leaves ~1e-18, where the step after it only confirmed it. The ``Δ³``
#: term keeps the rule where ``d''`` vanishes (an inflection of the piece's cubic minus ``k √a``), where ``Δ²`` alone
#: would let a step of 1e-4 of the radius end it with an error of ~1e-12
NEWTON_SHARE = 0.01
#: The largest step (a share of the radius) the rule ends on: the piece's cubic has no terms past ``d'''``, and
#: ``k √a``'s next term is ``Δ/a`` of its ``Δ³`` one, within the rule's margin (2 for 5/3) where ``Δ <= 1 %`` of ``a``
#: (settled steps in the tests: at most 2e-6)
NEWTON_REACH = 0.01
#: Steps allowed to invert a depth on one piece of ``g``: Newton's converge in a few, the bisections that keep them
#: in the bracket halve it each (60 of them take any piece to ``RADIUS_RTOL``).
MAX_INVERSION_STEPS = 100


def _check(profile) -> TabulatedProfile:
    if not isinstance(profile, TabulatedProfile):
        raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed; allowed: a TabulatedProfile")
    return profile


class EquivalentProfile:
    """``g(x)`` of a table on ``[0, r_max]`` (PCHIP through the quadrature's values), its slope and its integral.

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``; ``g`` is its Abel transform (3), computed when made (:func:`equivalent` caches it).

    Raises
    ------
    ValueError
        A table whose ``g`` does not increase, naming where.
    """

    def __init__(self, profile: TabulatedProfile):
        self.profile = profile
        r, f = np.array(profile.r), np.array(profile.f)
        self.x_max = float(r[-1])
        slope = interpolate.PchipInterpolator(r, f).derivative()  # on [r_k, r_k+1]: c2 (r − r_k)² + c1 (r − r_k) + c0
        c2, c1, c0 = slope.c
        subdivisions = max(1, min(SUBDIVISIONS, GRID_POINTS // (len(r) - 1)))
        shares = np.arange(subdivisions) / subdivisions
        grid = np.append((r[:-1, None] + np.diff(r)[:, None] * shares).ravel(), r[-1])
        values = np.zeros_like(grid)
        for index, x in enumerate(grid[1:], start=1):
            # the θ-intervals between the table's radii below x; on each, with s = sin θ, f'(x s) = A + B s + C s²,
            # whose integral over θ is exact: A Δθ − B Δcos θ + C Δ(θ/2 − sin 2θ / 4)
            pieces = int(np.searchsorted(r, x, side="left"))
            start = r[:pieces]
            lower = np.arcsin(np.minimum(start / x, 1.0))
            upper = np.append(lower[1:], 0.5 * math.pi)
            A = c2[:pieces] * start**2 - c1[:pieces] * start + c0[:pieces]
            B = (c1[:pieces] - 2.0 * c2[:pieces] * start) * x
            C = c2[:pieces] * x * x
            integral = (A * (upper - lower) - B * (np.cos(upper) - np.cos(lower))
                        + C * (0.5 * (upper - lower) - 0.25 * (np.sin(2.0 * upper) - np.sin(2.0 * lower))))
            values[index] = x * math.fsum(integral)
        falling = np.flatnonzero(np.diff(values) <= 0.0)
        if falling.size:
            at = grid[falling[0] + 1]
            raise ValueError(f"profile={profile.describe()!r} is not allowed: its Abel transform g(x) does not increase "
                             f"at x = {at:.6g} m; allowed: a profile whose MDR profile g increases (one that does not "
                             "flatten after a steep rise)")
        self.grid, self.values = grid, values
        self.g = interpolate.PchipInterpolator(grid, values, extrapolate=False)
        self.g_slope = self.g.derivative()
        self.g_integral = self.g.antiderivative()
        #: the same three for one Python float (:class:`ScalarPiecewise`)
        self.scalar_g, self.scalar_slope, self.scalar_integral = (ScalarPiecewise(poly) for poly in
                                                                  (self.g, self.g_slope, self.g_integral))

    def inside(self, a: float) -> float:
        """The radius ``a`` as the table reads it (one float; :meth:`inside_all` for an array).

        Parameters
        ----------
        a : float
            The radius (m).

        Returns
        -------
        float
            ``a`` up to ``x_max``, ``x_max`` within :data:`END_SHARE` past it, ``nan`` beyond.
        """
        if a <= self.x_max:
            return a
        return self.x_max if a <= self.x_max * (1.0 + END_SHARE) else math.nan

    def inside_all(self, a: np.ndarray) -> np.ndarray:
        """:meth:`inside` of each radius.

        Parameters
        ----------
        a : numpy.ndarray
            The radii (m).

        Returns
        -------
        numpy.ndarray
            :meth:`inside` of each, and 0 for one below 0.
        """
        return np.where(a <= self.x_max * (1.0 + END_SHARE), np.clip(a, 0.0, self.x_max), np.nan)

    def __call__(self, x):
        """``g(|x|)``; ``+inf`` beyond the table (no spring there is ever touched)."""
        magnitude = np.abs(np.asarray(x, dtype=float))
        return np.where(magnitude <= self.x_max, self.g(np.minimum(magnitude, self.x_max)), np.inf)


class ScalarPiecewise:
    """A :class:`scipy.interpolate.PPoly` evaluated for one Python float in pure Python (Horner on its piece): the
    continuum's right-hand side and event functions call the branch thousands of times, where a SciPy call on a
    scalar costs some 10 µs."""

    def __init__(self, poly: interpolate.PPoly):
        self.breaks = [float(value) for value in poly.x]
        self.pieces = [tuple(float(c) for c in column) for column in poly.c.T]
        self._count = len(self.pieces)

    def index(self, a: float) -> int:
        """The piece of ``a``.

        Parameters
        ----------
        a : float
            The abscissa.

        Returns
        -------
        int
            The index of its piece: the first below the breaks' start, the last beyond their end (and at ``nan``).
        """
        # (bisection between the second break and the last piece's start: the clamped index without min/max)
        return bisect.bisect_right(self.breaks, a, 1, self._count) - 1

    def __call__(self, a: float) -> float:
        breaks = self.breaks
        index = bisect.bisect_right(breaks, a, 1, self._count) - 1
        offset = a - breaks[index]
        value = 0.0
        for coefficient in self.pieces[index]:
            value = value * offset + coefficient
        return value


@cached(32)  # (an unhashable user subclass of the table by its exact value, issue 32 round 28 A3)
def equivalent(profile: TabulatedProfile) -> EquivalentProfile:
    """The :class:`EquivalentProfile` of ``profile``, computed once per process.

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``.

    Returns
    -------
    EquivalentProfile
        Its ``g``, cached (the last 32 tables).
    """
    return EquivalentProfile(_check(profile))


def equivalent_profile(x, profile: TabulatedProfile):
    r"""``g(x)``, the Abel transform (3) of the table (``+inf`` beyond its last radius).

    .. math:: g(x) = |x| \int_0^{|x|} \frac{f'(r)}{\sqrt{x^2 - r^2}}\, \mathrm{d}r
              = |x| \int_0^{\pi/2} f'(|x| \sin\theta)\, \mathrm{d}\theta \qquad (3)

    Parameters
    ----------
    x : float or array_like
        The spring's coordinate (m).
    profile : TabulatedProfile
        The table ``f(r)``.

    Returns
    -------
    float or numpy.ndarray
        ``g(x)`` (m), the shape of ``x``.
    """
    (x,) = _finite(x=x)
    values = equivalent(profile)(x)
    return float(values) if np.ndim(x) == 0 else values


class TabulatedBranch:
    """The branch ``d(a) = g(a) − k √a`` of a work of adhesion (``k = sqrt(2π Δγ/E*)``, (8)) on ``[0, r_max]``: its
    minimum (the jump-off, or ``a = 0`` without adhesion), and the radius of a depth above it.

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``).
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0) of the branch.

    Raises
    ------
    ValueError
        If the branch does not increase from its minimum to the table's end (a contact radius would not be one
        function of the depth).
    """

    def __init__(self, profile: TabulatedProfile, params: Parameters, work_of_adhesion: float):
        self.profile = profile
        self.shape = equivalent(profile)
        self.k = power_law.hess_prefactor(params, work_of_adhesion)
        self.E_star = params.E_star
        self._x_max = self.shape.x_max
        # g's pieces as ScalarPiecewise holds them, read by depth and slope in place of its call (the same steps: the
        # continuum reads a table's depth some 3000 times a run, where the call cost a frame each)
        g, slope = self.shape.scalar_g, self.shape.scalar_slope
        self._breaks, self._count, self._g_pieces, self._slope_pieces = g.breaks, g._count, g.pieces, slope.pieces
        grid = self.shape.grid
        depths = self.shape.values - self.k * np.sqrt(grid)
        lowest = int(np.argmin(depths))
        if self.k > 0.0 and lowest < len(grid) - 1:  # refine the minimum between its grid neighbours (at the tip
            # too: a cone-like tip, g' > 0 at 0, has its minimum at a radius far below the first grid point)
            found = optimize.minimize_scalar(self.depth, bounds=(grid[max(lowest - 1, 0)], grid[lowest + 1]),
                                             method="bounded", options={"xatol": 1e-14 * grid[-1]})
            self.jump_off_radius = float(found.x)
        else:
            self.jump_off_radius = float(grid[lowest])
        self.jump_off_depth = self.depth(self.jump_off_radius)
        rising = depths[lowest:]
        if np.any(np.diff(rising) <= 0.0):
            at = grid[lowest + int(np.flatnonzero(np.diff(rising) <= 0.0)[0]) + 1]
            raise ValueError(f"profile={profile.describe()!r} is not allowed with the work of adhesion "
                             f"{work_of_adhesion!r} J/m²: its branch d(a) = g(a) - sqrt(2 pi a dgamma / E*) falls again at "
                             f"a = {at:.6g} m beyond its jump-off; allowed: a profile whose branch rises from its minimum")
        self.deepest = self.depth(self.shape.x_max)
        # the branch's depths at the grid radii above the jump-off, increasing: a depth's bracket by bisection
        self._radii = [self.jump_off_radius] + [float(a) for a in grid[grid > self.jump_off_radius]]
        self._depths = [self.depth(a) for a in self._radii]
        self._last = len(self._depths) - 1
        # each bracket's numbers for _invert, by the index ``above`` of its upper end (None at 0): its radii and
        # depths, the start of the piece of g it lies on and that piece's coefficients of g and g', looked up once
        # here instead of at every inversion (the same numbers: a table's run inverts some thousand depths), and the
        # tangents of its Hermite start (_tangents)
        self._cells, pieces, tangents = [None], [0], [(math.nan, math.nan)]
        for above in range(1, len(self._radii)):
            index = g.index(self._radii[above - 1])
            pieces.append(index)
            tangents.append(self._tangents(above))
            self._cells.append((self._radii[above - 1], self._radii[above], self._depths[above - 1],
                                self._depths[above], g.breaks[index], g.pieces[index], slope.pieces[index],
                                *tangents[-1]))
        # the same as arrays for radii and _invert_all (made once: converting the lists cost more than a run's
        # iteration; read-only), each bracket's piece's start and coefficients by its ``above``
        self._arrays = _BracketArrays(*(_read_only(np.asarray(values, dtype=float)) for values in (
            self._radii, self._depths, [g.breaks[index] for index in pieces], [g.pieces[index] for index in pieces],
            [slope.pieces[index] for index in pieces], tangents)))

    def _tangents(self, above: int) -> tuple[float, float]:
        """The tangents ``Δd / d'(a)`` at the ends of the bracket ``above`` (the inverse ``a(d)``'s slopes times the
        bracket's rise in depth) of :meth:`_invert`'s Hermite start; ``nan`` where the branch's slope at an end is not
        positive and finite (at the jump-off, where ``d`` rises from its minimum: the start in the chord's square)."""
        low, high = self._radii[above - 1], self._radii[above]
        rise = self._depths[above] - self._depths[above - 1]
        at_low, at_high = self.slope(low), self.slope(high)
        if (above == 1 and self.k > 0.0) or not (0.0 < at_low < math.inf and 0.0 < at_high < math.inf):
            return math.nan, math.nan
        return rise / at_low, rise / at_high

    def depth(self, a: float) -> float:
        """The branch's depth ``d(a) = g(a) − k √a`` at the radius ``a``, one Python float.

        Parameters
        ----------
        a : float
            The radius (m); one within :data:`END_SHARE` past the table is its end, as in :meth:`depths`.

        Returns
        -------
        float
            The depth (m); 0 at ``a <= 0``, ``nan`` further past the table.
        """
        if not a > 0:
            return 0.0
        if a > self._x_max:  # (the end check only past the table: most radii are inside)
            a = self.shape.inside(a)
        # ScalarPiecewise's call on g written out: its piece (a cubic) by bisection, Horner's steps from 0.0
        breaks = self._breaks
        index = bisect.bisect_right(breaks, a, 1, self._count) - 1
        offset = a - breaks[index]
        c0, c1, c2, c3 = self._g_pieces[index]
        return (((0.0 * offset + c0) * offset + c1) * offset + c2) * offset + c3 - self.k * math.sqrt(a)

    def depths(self, a: np.ndarray) -> np.ndarray:
        """The branch's depths at the radii ``a``, vectorised.

        Parameters
        ----------
        a : array_like
            The radii (m); those within :data:`END_SHARE` past the table are its end.

        Returns
        -------
        numpy.ndarray
            The depths (m), the shape of ``a``; 0 at ``a <= 0``, ``nan`` further past the table.
        """
        a = np.asarray(a, dtype=float)
        inside = self.shape.inside_all(a)
        return np.where(a > 0, self.shape.g(inside) - self.k * np.sqrt(inside), 0.0)

    def slope(self, a: float) -> float:
        """``∂d/∂a`` of the branch at the radius ``a``, one Python float.

        Parameters
        ----------
        a : float
            The radius (m); one within :data:`END_SHARE` past the table is its end.

        Returns
        -------
        float
            The slope (1); at ``a <= 0``: ``-inf`` with adhesion, ``g'(0)`` without; ``nan`` further past the table.
        """
        if a > 0:
            if a > self._x_max:
                a = self.shape.inside(a)
            # ScalarPiecewise's call on g' written out (a quadratic; g's breaks), as in depth
            breaks = self._breaks
            index = bisect.bisect_right(breaks, a, 1, self._count) - 1
            offset = a - breaks[index]
            s0, s1, s2 = self._slope_pieces[index]
            return ((0.0 * offset + s0) * offset + s1) * offset + s2 - 0.5 * self.k / math.sqrt(a)
        return -math.inf if self.k > 0 else self.shape.scalar_slope(0.0)

    def integral(self, a: float) -> float:
        """``∫_0^a d(ξ) dξ`` along the branch.

        Parameters
        ----------
        a : float
            The radius (m); one within :data:`END_SHARE` past the table is its end, as in :meth:`depths` and
            :meth:`~mdr_events.models.continuum.branch.TabulatedBranch.integrals`.

        Returns
        -------
        float
            The integral (m²; 0 at ``a <= 0``, ``nan`` further past the table).
        """
        if not a > 0:
            return 0.0
        if a > self._x_max:
            a = self.shape.inside(a)
        return self.shape.scalar_integral(a) - 2.0 / 3.0 * self.k * a**1.5

    def radius(self, depth: float, rtol: float = RADIUS_RTOL) -> float:
        """The radius above the jump-off at ``depth``; ``nan`` below the jump-off or beyond the table's end.

        Parameters
        ----------
        depth : float
            The depth ``d`` (m).
        rtol : float, default RADIUS_RTOL
            The relative accuracy of the root (at least :data:`RADIUS_RTOL`).

        Returns
        -------
        float
            The radius ``a`` (m) or ``nan``.
        """
        if not self.jump_off_depth <= depth <= self.deepest:
            return math.nan
        if depth == self.jump_off_depth:
            return self.jump_off_radius
        above = bisect.bisect_left(self._depths, depth, 0, self._last)  # (at most the last: no min)
        if self._depths[above] == depth:
            return self._radii[above]
        return self._invert(depth, max(above, 1), max(rtol, RADIUS_RTOL))

    def _invert(self, depth: float, above: int, rtol: float) -> float:
        """The root of ``d(a) = depth`` between the radii ``above − 1`` and ``above`` of the bracket's grid (one
        piece of ``g``): Newton's steps on the piece's cubic, kept in the bracket by bisection (``d`` increases
        there), until a step is below ``rtol`` of the radius, or its own error by Newton's rule is below
        :data:`NEWTON_SHARE` of it (the step after it would only confirm it). They start from the cubic Hermite
        interpolant of the inverse ``a(d)`` through the bracket's ends (their radii, depths and slopes ``d'``: its error
        falls as the fourth power of the bracket, ~1e-9 of the radius on a 41-point table, where the chord's falls as
        the square, ~1e-4; one step, not three), else (it would leave the bracket, or a slope is not positive) from the
        chord's root, or next to the jump-off, where ``d`` rises from a minimum as the square of the distance, from the chord's in
        that square. Pure Python: the continuum inverts thousands of depths per run."""
        low, high, d_low, d_high, start, (c0, c1, c2, c3), (s0, s1, s2), m0, m1 = self._cells[above]
        k = self.k
        share = (depth - d_low) / (d_high - d_low)
        a = low + (math.sqrt(share) if above == 1 and k > 0.0 else share) * (high - low)
        if m0 == m0:  # (the Hermite start, where it lies inside the bracket; the chord's root else)
            rest = 1.0 - share
            hermite = (((1.0 + 2.0 * share) * rest * rest) * low + (share * rest * rest) * m0
                       + (share * share * (3.0 - 2.0 * share)) * high + (share * share * (share - 1.0)) * m1)
            if low < hermite < high:
                a = hermite
        # a PCHIP's piece is a cubic, its slope's a quadratic: Horner's steps written out, as ScalarPiecewise's loop
        # takes them from 0.0 (the same operations, bit for bit)
        half_k, quarter_k = 0.5 * k, 0.25 * k
        for _ in range(MAX_INVERSION_STEPS):
            offset, root = a - start, math.sqrt(a)
            value = (((0.0 * offset + c0) * offset + c1) * offset + c2) * offset + c3
            rate = ((0.0 * offset + s0) * offset + s1) * offset + s2
            excess = value - k * root - depth
            if excess == 0.0:
                return a
            if excess > 0.0:
                high = a
            else:
                low = a
            if k:
                rate -= half_k / root
            step = a - excess / rate if rate > 0.0 else low
            if abs(step - a) <= rtol * a:  # (a converged step may round onto the bracket's end)
                return step if low <= step <= high else a
            if rate > 0.0 and low < step < high:  # (the step's own error by Newton's rule: NEWTON_SHARE of rtol)
                bend, third = 2.0 * s0 * offset + s1, 2.0 * s0
                if k:
                    bend += quarter_k / (a * root)
                    third -= 1.5 * quarter_k / (a * a * root)
                change = abs(step - a)
                if (change <= NEWTON_REACH * a
                        and (abs(bend) + 2.0 * abs(third) * change) * change * change
                        <= 2.0 * NEWTON_SHARE * rtol * a * rate):
                    return step
            a = step if low < step < high else 0.5 * (low + high)
        return a

    def radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radius` of each depth of an array, elementwise: the same cases and, for each depth, the same steps of
        :meth:`_invert` in the same floating-point operations, taken by the array (:meth:`_invert_all`), so that
        every radius is :meth:`radius`'s bit for bit.

        Parameters
        ----------
        depth : array_like
            The depths (m).

        Returns
        -------
        numpy.ndarray
            The radii (m) or ``nan``, the shape of ``depth``.
        """
        depth = np.asarray(depth, dtype=float)
        out = np.full(depth.shape, np.nan)
        flat, values = out.reshape(-1), depth.reshape(-1)
        inside = np.flatnonzero((self.jump_off_depth <= values) & (values <= self.deepest))
        wanted = values[inside]
        depths = self._arrays.depths
        above = np.minimum(np.searchsorted(depths, wanted, side="left"), len(depths) - 1)
        on_grid = depths[above] == wanted
        flat[inside[on_grid]] = self._arrays.radii[above[on_grid]]
        rest = ~on_grid
        flat[inside[rest]] = self._invert_all(wanted[rest], np.maximum(above[rest], 1), RADIUS_RTOL)
        flat[inside[wanted == self.jump_off_depth]] = self.jump_off_radius
        return out

    def _invert_all(self, depth: np.ndarray, above: np.ndarray, rtol: float) -> np.ndarray:
        """:meth:`_invert` of every depth of an array (with its ``above``): each element takes the scalar iteration's
        steps, the same operations in the same order (NumPy's IEEE arithmetic and square root are Python's), and
        leaves the iteration where the scalar one returns."""
        radii, depths, starts, g_pieces, slope_pieces, tangents = self._arrays
        low, high = radii[above - 1], radii[above]
        d_low, d_high = depths[above - 1], depths[above]
        share = (depth - d_low) / (d_high - d_low)
        chord = np.where(above == 1, np.sqrt(share), share) if self.k > 0.0 else share
        a = low + chord * (high - low)
        m0, m1 = tangents[above].T
        rest = 1.0 - share
        hermite = (((1.0 + 2.0 * share) * rest * rest) * low + (share * rest * rest) * m0
                   + (share * share * (3.0 - 2.0 * share)) * high + (share * share * (share - 1.0)) * m1)
        a = np.where((m0 == m0) & (low < hermite) & (hermite < high), hermite, a)
        # (the bracket's piece of g, as _invert reads it from its cell)
        start, values, rates = starts[above], g_pieces[above].T, slope_pieces[above].T
        out = np.empty(depth.shape)
        iterating = _Iterating(np.arange(depth.size), a, low, high, start, depth, values, rates)
        with np.errstate(divide="ignore", invalid="ignore"):  # (a step by a zero rate is not taken: np.where)
            return self._iterate(out, iterating, rtol)

    def _iterate(self, out: np.ndarray, iterating: _Iterating, rtol: float) -> np.ndarray:
        """The steps of :meth:`_invert_all` (the elements ``iterating``), into ``out``."""
        left, a, low, high, start, depth, values, rates = iterating
        for _ in range(MAX_INVERSION_STEPS):
            offset, root = a - start, np.sqrt(a)
            value, rate = np.zeros(a.shape), np.zeros(a.shape)
            for coefficient in values:
                value = value * offset + coefficient
            for coefficient in rates:
                rate = rate * offset + coefficient
            excess = value - self.k * root - depth
            exact = excess == 0.0
            high = np.where(excess > 0.0, a, high)
            low = np.where(excess > 0.0, low, a)
            if self.k:
                rate = rate - 0.5 * self.k / root
            else:
                rate = rate - 0.0
            step = np.where(rate > 0.0, a - excess / rate, low)
            converged = ~exact & (np.abs(step - a) <= rtol * a)
            bend, third = 2.0 * rates[0] * offset + rates[1], 2.0 * rates[0]
            if self.k:
                bend = bend + 0.25 * self.k / (a * root)
                third = third - 1.5 * (0.25 * self.k) / (a * a * root)
            change = np.abs(step - a)
            inside = (low < step) & (step < high)
            settled = (~exact & ~converged & (rate > 0.0) & inside & (change <= NEWTON_REACH * a)
                       & ((np.abs(bend) + 2.0 * np.abs(third) * change) * change * change
                          <= 2.0 * NEWTON_SHARE * rtol * a * rate))
            out[left[exact]] = a[exact]
            out[left[converged]] = np.where((low <= step) & (step <= high), step, a)[converged]
            out[left[settled]] = step[settled]
            a = np.where(inside, step, 0.5 * (low + high))
            going = ~(exact | converged | settled)
            if not going.all():
                left, a, low, high, start, depth, values, rates = _Iterating(left, a, low, high, start, depth, values,
                                                                             rates).kept(going)
            if not left.size:
                return out
        out[left] = a
        return out


class _BracketArrays(NamedTuple):
    """A :class:`TabulatedBranch`'s brackets as arrays for its array inversion: the grid's radii and depths above the
    jump-off (increasing), and by each bracket's upper index ``above`` the start of its piece of ``g``, that piece's
    coefficients of ``g`` and ``g'`` and the Hermite start's two tangents (a row each; index 0 unused)."""

    radii: np.ndarray
    depths: np.ndarray
    starts: np.ndarray
    g_pieces: np.ndarray
    slope_pieces: np.ndarray
    tangents: np.ndarray


def _read_only(array: np.ndarray) -> np.ndarray:
    """``array``, marked read-only (shared by every call that reads it)."""
    array.setflags(write=False)
    return array


class _Iterating(NamedTuple):
    """The elements of :meth:`TabulatedBranch._invert_all` still iterating: their indices in the output, radius,
    bracket, piece's start and depth (one value each), and their pieces' coefficients of ``g`` and ``g'`` (a column
    each)."""

    left: np.ndarray
    a: np.ndarray
    low: np.ndarray
    high: np.ndarray
    start: np.ndarray
    depth: np.ndarray
    values: np.ndarray
    rates: np.ndarray

    def kept(self, going: np.ndarray) -> _Iterating:
        """The elements where ``going`` is true."""
        return _Iterating(*(array[going] for array in self[:6]), self.values[:, going], self.rates[:, going])


def branch(profile: TabulatedProfile, params: Parameters, work_of_adhesion: float) -> TabulatedBranch:
    """The :class:`TabulatedBranch` of ``profile`` for ``params`` and a work of adhesion, built once per process.

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    TabulatedBranch
        The branch, cached (the last 64).
    """
    return _branch(profile, params, power_law.check_work(work_of_adhesion))


@cached(64)
def _branch(profile: TabulatedProfile, params: Parameters, work_of_adhesion: float) -> TabulatedBranch:
    """:func:`branch` of a work checked (a float: the cache's key, which an array or a list cannot be)."""
    return TabulatedBranch(_check(profile), params, work_of_adhesion)


def normal_force(depth, contact_radius, profile: TabulatedProfile, params: Parameters):
    r"""``F_N = 2 E* (d a − ∫_0^a g)`` (10) of the springs in ``|x| < a`` at depth ``d``.

    .. math:: F_N = 2 E^* \int_0^a \left(d - g(x)\right) \mathrm{d}x \qquad (10)

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    contact_radius : float or array_like
        The contact radius ``a`` (m), any (clipped to the table).
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.

    Returns
    -------
    float or numpy.ndarray
        ``F_N`` (N; negative: tensile).
    """
    depth, contact_radius = _finite(depth=depth, contact_radius=contact_radius)
    return _normal_force(depth, contact_radius, profile, params)


def _normal_force(depth, contact_radius, profile: TabulatedProfile, params: Parameters):
    """:func:`normal_force` unchecked (the simulators' depths and radii, their own)."""
    shape = equivalent(profile)
    a = np.asarray(contact_radius, dtype=float)
    force = 2.0 * params.E_star * (np.asarray(depth, dtype=float) * a - shape.g_integral(np.clip(a, 0.0, shape.x_max)))
    return float(force) if np.ndim(force) == 0 else force


def contact_radius(depth, profile: TabulatedProfile, params: Parameters, work_of_adhesion: float):
    r"""The radius on the branch of ``work_of_adhesion`` at ``depth`` (``nan`` below its jump-off or past the table).

    .. math:: d = g(a) - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9)

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The radius ``a`` (m) or ``nan``, the shape of ``depth``.
    """
    (depth,) = _finite(depth=depth)
    radii = branch(profile, params, work_of_adhesion).radii(depth)
    return float(radii) if np.ndim(depth) == 0 else radii


def jump_off(profile: TabulatedProfile, params: Parameters, work_of_adhesion: float) -> dict[str, float]:
    """The end of contact under displacement control: the branch's minimum (``contact_radius``, ``depth``,
    ``normal_force``).

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.

    Returns
    -------
    dict of str to float
        ``contact_radius`` (m), ``depth`` (m) and ``normal_force`` (N) there.
    """
    line = branch(profile, params, work_of_adhesion)
    return {"contact_radius": line.jump_off_radius, "depth": line.jump_off_depth,
            "normal_force": normal_force(line.jump_off_depth, line.jump_off_radius, profile, params)}


def pull_off_force(profile: TabulatedProfile, params: Parameters, work_of_adhesion: float) -> float:
    """The pull-off force under force control (N): the least normal force along the branch above its jump-off.

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.

    Returns
    -------
    float
        The pull-off force (N, <= 0; 0 without adhesion).
    """
    line = branch(profile, params, work_of_adhesion)
    if line.k == 0.0:
        return 0.0
    grid = line.shape.grid[line.shape.grid >= line.jump_off_radius]
    grid = np.concatenate([[line.jump_off_radius], grid])
    forces = normal_force(line.depths(grid), grid, profile, params)
    lowest = int(np.argmin(forces))
    bounds = (grid[max(lowest - 1, 0)], grid[min(lowest + 1, len(grid) - 1)])

    def force(a):
        return normal_force(line.depth(a), a, profile, params)

    found = optimize.minimize_scalar(force, bounds=bounds, method="bounded", options={"xatol": 1e-14 * grid[-1]})
    return float(min(found.fun, forces[lowest]))


def d_crit_A(alpha, profile: TabulatedProfile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario A (the path (14) from first contact at ``α`` in degrees): the first depth on
    the branch (``Δγ0`` with adhesion) where ``d = tan α K a``; no closed form exists, so the root of
    ``d(a) − tan α K a`` rising through zero above the jump-off is bracketed on the table's grid and refined.
    ``nan`` where there is none within the table; ``α = 90°`` never slides (``+inf``). Without adhesion an onset inside
    the table's first interval is the interpolant's: its tip has the slope ``g'(0)`` of the PCHIP, and at angles whose
    ``tan α K`` lies below it the springs slide from first contact (0), as they do in the simulators of the table.

    .. math:: \frac{d}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = g(a) - \sqrt{\frac{2 \pi a \Delta\gamma_0}{E^*}} \qquad (17), (18)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the ``Δγ0`` branch (9); without: the non-adhesive one.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``nan`` where none lies within the table, ``+inf``
        at 90°.
    """
    alpha_arr = validate_alpha(alpha)
    line = branch(profile, params, params.dgamma0 if adhesion else 0.0)
    K = power_law.cap_per_radius(params)
    # from the jump-off (whose depth lies above the surface, where the gap below is negative) or from the first
    # radius past a = 0 without adhesion (where d and K a both vanish)
    start = [line.jump_off_radius] if line.k > 0 else []
    grid = np.concatenate([start, line.shape.grid[line.shape.grid > line.jump_off_radius]])
    depths = line.depths(grid)
    out = np.empty(alpha_arr.shape)
    for index, angle in np.ndenumerate(alpha_arr):
        if angle >= 90.0:
            out[index] = math.inf
            continue
        slope = math.tan(math.radians(angle)) * K
        gap = depths - slope * grid  # the shift d / tan α minus the cap K a, times tan α
        ahead = np.flatnonzero(gap >= 0.0)
        if not ahead.size:
            out[index] = math.nan
            continue
        if ahead[0] > 0:
            bracket = grid[ahead[0] - 1], grid[ahead[0]]
        elif line.shape.scalar_slope(0.0) > slope:  # (no adhesion) ahead from the tip: slides from first contact
            out[index] = 0.0
            continue
        else:  # (no adhesion) a tip flatter than the path: the root lies inside the first cell
            bracket = RADIUS_RTOL * grid[0], grid[0]
            if line.depth(bracket[0]) > slope * bracket[0]:  # below even that: slides from first contact (0) within
                out[index] = 0.0  # RADIUS_RTOL of the first radius (a dense table's flat tip at 1e-20°: brentq's
                continue  # "f(a) and f(b) must have different signs", issue 32 round 29 B3)
        a = optimize.brentq(lambda a: line.depth(a) - slope * a, *bracket, xtol=1e-300, rtol=RADIUS_RTOL)
        out[index] = slope * a
    return float(out) if np.ndim(alpha) == 0 else out


def critical_angle_A(profile: TabulatedProfile, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario A's critical angle (degrees): ``tan α_c = d_max / (K a(d_max))`` on the ``Δγ0`` branch (with
    adhesion) or the non-adhesive one.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{max}}{\bar u(a(d_\mathrm{max}))}
              = \frac{2 G^* d_\mathrm{max}}{\pi a \tau_0} \qquad (17), (18)

    Parameters
    ----------
    profile : TabulatedProfile
        The table ``f(r)``.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the ``Δγ0`` branch (9); without: the non-adhesive one.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    radius = contact_radius(params.d_max, profile, params, params.dgamma0 if adhesion else 0.0)
    angle = symbolic.relation("critical_angle_A").numeric(radius, params.d_max, params.tau0, params.G_star)
    return float(np.rad2deg(angle))
