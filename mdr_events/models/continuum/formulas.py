"""The anchors of ``"tau0+coulomb"`` with adhesion as functions of ``ξ``: what they are made of and how each is read.

With adhesion and both parts of the cap (:mod:`.regions`) the stored anchors are no longer pieces of one kind. A
spring attaching along the ``Δγ0`` branch gets ``x0 + r (d0(ξ) − d_ref)``; a compressed spring materialised at a cap
``σ`` gets the level plus ``σ κ g(ξ)``; a spring that crosses the compression boundary ``x_c`` (``g(x_c) = d``) at a
cap keeps the window of that instant, ``x(τ) − σ K a(τ)`` with ``d(τ) = g(ξ)``: along a path segment
``x0 + (v_x/v_d)(g(ξ) − d_s) − σ K A(g(ξ))``, ``A`` the radius of a depth on the branch the radius follows
(``symbolic.derive_adhesive_friction_model``: ``adhesive_crossing_anchor``); and a cap in the compressed zone compares
``Y − σ κ g(ξ)`` with its level. Every one of them is

    ``Y(ξ) = x0 + α (g(ξ) − d_ref) + β (d0(ξ) − d_ref) + γ A(g(ξ))``

(:class:`Formula`), read through the three functions of a :class:`Shape`: ``g`` (the branch without adhesion), ``d0``
and ``A``. Such a function need not be monotone in ``ξ`` (``adhesive_seen_piece_turn``): its turns are found once per
kind (:meth:`Formula.turns`), and on each monotone interval it is inverted by a bracketed root, continued up to the
neighbouring turns so that a slip front moves smoothly past a piece's end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from .branch import Branch
from .tolerances import EPS

__all__ = ["Shape", "Formula", "FormulaPiece", "TURN_GRID", "QUADRATURE_NODES", "RADIUS_CACHE_SIZE"]

#: Points (log-spaced over the shape's reach) at which a formula's slope is sampled for a change of sign: its turns
#: lie between them (a sum of three smooth terms of ``ξ`` changes sign once or twice at most; 1e-9 of the reach is
#: far below any spring of a contact).
TURN_GRID = 241
#: Gauss–Legendre nodes of the integral of ``A(g(ξ))`` on one interval (between the knots of a table's ``g``): the
#: radius of a depth is analytic there, and the rule exact to rounding.
QUADRATURE_NODES = 24
#: A root in ``ξ`` (a front, a turn) is found to this share of its interval's far end besides ``4 eps`` of itself:
#: a front at ``ξ = 0`` (every spring of a part at one value to rounding) has no relative tolerance of its own
ROOT_XTOL = 2 * EPS
#: Points of the grid :meth:`Formula.inverses` brackets its roots on before its regula falsi (a monotone interval)
INVERSE_GRID = 33
#: A value of :meth:`Formula.inverses`'s regula falsi this many ulp of the values' size from its target is a root
VALUE_ULPS = 8
#: Steps of :meth:`Formula.inverses` at most (as many halvings would take a monotone interval below its ulp).
BISECTION_STEPS = 64
#: Radii :meth:`Shape.radius` remembers at most (then it forgets them all): a run asks a few dozen depths more than
#: once, and the events a new one at each evaluation
RADIUS_CACHE_SIZE = 1024
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(QUADRATURE_NODES)


class Shape:
    """The functions of ``ξ`` that anchors are made of, for one contact.

    Parameters
    ----------
    hertz : Branch
        The branch without adhesion: its depth is the profile ``g(ξ)``, its radius ``g⁻¹`` (the compression boundary).
    grow, shrink : Branch
        The ``Δγ0`` and ``Δγ1`` branches: ``d0(ξ)``, and the radius ``A(d)`` a moving contact has at a depth.
    rtol : float
        The relative accuracy of the radius roots.
    reach : float
        The largest ``ξ`` any anchor is read at (m): the turns are looked for below it.
    """

    def __init__(self, hertz: Branch, grow: Branch, shrink: Branch, rtol: float, reach: float):
        self.hertz, self.grow, self.rtol, self.reach = hertz, grow, rtol, reach
        self.branches = {"grow": grow, "shrink": shrink}
        #: the radii of depths asked, by branch and depth (:meth:`radius`; at most :data:`RADIUS_CACHE_SIZE`)
        self.radius_cache: dict[tuple[str, float], float] = {}
        #: the turns of each kind of formula, by its coefficients (:meth:`Formula.turns`)
        self.turn_cache: dict[tuple, tuple[float, ...]] = {}
        #: the grid the turns are bracketed on and the slopes there, by the radius's branch (:meth:`turn_grid`)
        self.turn_grids: dict[str | None, tuple] = {}

    def boundary(self, depth: float) -> float:
        """The compression boundary ``x_c`` of a depth, ``g(x_c) = d`` (0 at ``d <= 0``: every spring in tension).

        Parameters
        ----------
        depth : float
            The depth ``d`` (m).

        Returns
        -------
        float
            ``x_c`` (m).
        """
        return self.hertz.radius(depth, self.rtol) if depth > 0.0 else 0.0

    def boundaries(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`boundary` of an array of depths.

        Parameters
        ----------
        depth : numpy.ndarray
            The depths (m).

        Returns
        -------
        numpy.ndarray
            ``x_c`` of each (m).
        """
        depth = np.asarray(depth, dtype=float)
        return np.where(depth > 0.0, self.hertz.radii(np.maximum(depth, 0.0)), 0.0)

    def radius(self, name: str, depth: float) -> float:
        """``A(d)``: the radius of ``depth`` on the branch ``name`` (``"grow"`` or ``"shrink"``).

        Parameters
        ----------
        name : str
            ``"grow"`` or ``"shrink"``.
        depth : float
            The depth (m).

        Returns
        -------
        float
            The radius (m; ``nan`` below the branch's fold; remembered: a part's ends, read by the layouts of a span
            and of the transition before it and by the sliding fraction, ask for the same depths again, each a root).
        """
        key = (name, depth)
        found = self.radius_cache.get(key)
        if found is None:
            if len(self.radius_cache) >= RADIUS_CACHE_SIZE:  # (the events' moving extents ask new depths each time)
                self.radius_cache.clear()
            found = self.radius_cache[key] = self.branches[name].radius(depth, self.rtol)
        return found

    def turn_grid(self, name: str | None) -> tuple[np.ndarray, tuple]:
        """The grid of :data:`TURN_GRID` points (and the knots of ``g``) up to :meth:`limit` on which a formula's turns
        are bracketed, with the slopes its own are a sum of there: of ``g``, of ``d0``, and of the branch ``name`` at
        ``A(g)`` (``None``: no radius); worked out once per branch, shared by every formula (the radii's roots were
        the cost of each).

        Parameters
        ----------
        name : str or None
            The branch of the formula's ``A`` (``"grow"``, ``"shrink"``; ``None``: none).

        Returns
        -------
        tuple
            The grid (m) and the slopes ``(g', d0', d_A'(A(g)))`` there (the last ``None`` without a branch).
        """
        if name not in self.turn_grids:
            reach = self.limit(name)
            grid = reach * np.geomspace(1e-9, 1.0, TURN_GRID)
            grid = np.union1d(grid, [k for k in self.knots() if 0.0 < k < reach])
            branch = self.branches.get(name)
            radius = branch.slopes(branch.radii(self.hertz.depths(grid))) if branch is not None else None
            self.turn_grids[name] = (grid, (self.hertz.slopes(grid), self.grow.slopes(grid), radius))
        return self.turn_grids[name]

    def knots(self) -> tuple[float, ...]:
        """Where ``g`` is not smooth (a table's grid; none for a power law).

        Returns
        -------
        tuple of float
            The knots (m), increasing.
        """
        return self.hertz.knots

    def limit(self, name: str | None) -> float:
        """The largest ``ξ`` a formula with the radius of the branch ``name`` is read at: the reach, or where ``g``
        passes the deepest depth that branch has a radius of (a table's, past which ``A`` is undefined).

        Parameters
        ----------
        name : str or None
            The branch of the formula's ``A`` (``None``: none).

        Returns
        -------
        float
            The largest ``ξ`` (m).
        """
        deepest = getattr(getattr(self.branches.get(name), "line", None), "deepest", None)
        if deepest is None:
            return self.reach
        return min(self.reach, self.hertz.radius(deepest, self.rtol))


@dataclass(frozen=True)
class Formula:
    """``Y(ξ) = x0 + α (g(ξ) − d_ref) + β (d0(ξ) − d_ref) + γ A(g(ξ))`` (module docstring).

    Parameters
    ----------
    shape : Shape
        The functions it is made of (not compared).
    x0 : float
        The value (m) where both ``g`` and ``d0`` are ``d_ref`` and ``γ = 0``.
    alpha : float, default 0.0
        The coefficient of ``g(ξ) − d_ref`` (1).
    beta : float, default 0.0
        The coefficient of ``d0(ξ) − d_ref`` (1): ``v_x/v_d`` of a growth.
    d_ref : float, default 0.0
        The reference depth (m).
    gamma : float, default 0.0
        The coefficient of ``A(g(ξ))`` (1): ``−σ K`` of a crossing at a cap.
    radius_of : str or None, default None
        The branch of ``A`` (``"grow"``, ``"shrink"``; ``None`` with ``γ = 0``).
    """

    shape: Shape = field(compare=False, repr=False)
    x0: float
    alpha: float = 0.0
    beta: float = 0.0
    d_ref: float = 0.0
    gamma: float = 0.0
    radius_of: str | None = None

    @property
    def constant(self) -> bool:
        """Whether ``Y`` is the same for every ``ξ``.

        Returns
        -------
        bool
            ``True`` if ``α = β = γ = 0``.
        """
        return self.alpha == 0.0 and self.beta == 0.0 and self.gamma == 0.0

    def seen(self, shift: float) -> "Formula":
        """``Y − shift g(ξ)``: as a cap ``σ`` of the compressed zone sees the anchors (``shift = σ κ``).

        Parameters
        ----------
        shift : float
            ``σ κ`` of the cap (0: the anchors as they are).

        Returns
        -------
        Formula
            The anchors as the cap sees them.
        """
        if shift == 0.0:
            return self
        return Formula(self.shape, self.x0 - shift * self.d_ref, self.alpha - shift, self.beta, self.d_ref, self.gamma,
                       self.radius_of)

    # --- values --------------------------------------------------------------------------------
    def value(self, xi: float) -> float:
        """``Y(ξ)`` for one float (m).

        Parameters
        ----------
        xi : float
            The spring's coordinate ``ξ`` (m).

        Returns
        -------
        float
            ``Y(ξ)`` (m).
        """
        shape = self.shape
        total = self.x0
        g = shape.hertz.depth(xi) if (self.alpha or self.gamma) else 0.0
        if self.alpha:
            total += self.alpha * (g - self.d_ref)
        if self.beta:
            total += self.beta * (shape.grow.depth(xi) - self.d_ref)
        if self.gamma:
            total += self.gamma * shape.radius(self.radius_of, g)
        return total

    def values(self, xi: np.ndarray) -> np.ndarray:
        """``Y(ξ)`` of an array (m).

        Parameters
        ----------
        xi : numpy.ndarray
            The springs' coordinates (m).

        Returns
        -------
        numpy.ndarray
            ``Y`` at each (m).
        """
        shape = self.shape
        xi = np.asarray(xi, dtype=float)
        total = np.full(xi.shape, self.x0)
        g = shape.hertz.depths(xi) if (self.alpha or self.gamma) else None
        if self.alpha:
            total = total + self.alpha * (g - self.d_ref)
        if self.beta:
            total = total + self.beta * (shape.grow.depths(xi) - self.d_ref)
        if self.gamma:
            total = total + self.gamma * shape.branches[self.radius_of].radii(g)
        return total

    def slope(self, xi: float) -> float:
        """``dY/dξ`` at one ``ξ > 0``: ``α g' + β d0' + γ g'/d_A'(A)`` (the branches' derived slopes).

        Parameters
        ----------
        xi : float
            The spring's coordinate ``ξ`` (m).

        Returns
        -------
        float
            ``dY/dξ`` (1).
        """
        shape = self.shape
        total = 0.0
        rate = shape.hertz.slope(xi) if (self.alpha or self.gamma) else 0.0
        if self.alpha:
            total += self.alpha * rate
        if self.beta:
            total += self.beta * shape.grow.slope(xi)
        if self.gamma:
            branch = shape.branches[self.radius_of]
            total += self.gamma * rate / branch.slope(branch.radius(shape.hertz.depth(xi), shape.rtol))
        return total

    def value_and_slope(self, xi: float) -> tuple[float, float]:
        """:meth:`value` and :meth:`slope` at one ``ξ > 0`` at once, each as those give it (Newton's iteration reads
        both at every step).

        Parameters
        ----------
        xi : float
            The spring's coordinate ``ξ`` (m).

        Returns
        -------
        tuple of float
            ``Y(ξ)`` (m) and ``dY/dξ`` (1).
        """
        if self.gamma:
            return self.value(xi), self.slope(xi)
        shape, alpha, beta, d_ref = self.shape, self.alpha, self.beta, self.d_ref
        total, rising = self.x0, 0.0
        if alpha:
            total += alpha * (shape.hertz.depth(xi) - d_ref)
            rising += alpha * shape.hertz.slope(xi)
        if beta:
            grow = shape.grow
            total += beta * (grow.depth(xi) - d_ref)
            rising += beta * grow.slope(xi)
        return total, rising

    def slopes(self, xi: np.ndarray) -> np.ndarray:
        """:meth:`slope` at an array of ``ξ > 0``, the radii ``A(g(ξ))`` found at once (the branches' vectorised
        roots, to double precision as the scalar ones), the branches' slopes too (:meth:`~.branch.Branch.slopes`).

        Parameters
        ----------
        xi : numpy.ndarray
            The springs' coordinates (m), 1-D.

        Returns
        -------
        numpy.ndarray
            ``dY/dξ`` at each (1).
        """
        shape = self.shape
        if self.constant:
            return np.zeros(len(xi))
        rate = shape.hertz.slopes(xi) if (self.alpha or self.gamma) else None
        grow = shape.grow.slopes(xi) if self.beta else None
        if self.gamma:
            branch = shape.branches[self.radius_of]
            return self._slopes_of(rate, grow, branch.slopes(branch.radii(shape.hertz.depths(xi))))
        return self._slopes_of(rate, grow, None)

    def _slopes_of(self, rate: np.ndarray | None, grow: np.ndarray | None,
                   radius: np.ndarray | None) -> np.ndarray:
        """:meth:`slopes` from the slopes of ``g``, ``d0`` and the radius's branch at ``A(g)`` at the points (each
        ``None`` where the formula has no such term; :meth:`Shape.turn_grid` keeps them for every formula)."""
        total = np.zeros(len(rate if rate is not None else grow))
        if self.alpha or self.gamma:
            total += self.alpha * rate if self.alpha else 0.0
        if self.beta:
            total += self.beta * grow
        if self.gamma:
            total += self.gamma * rate / radius
        return total

    def integral(self, lower: float, upper: float) -> float:
        """``∫ Y dξ`` over ``[lower, upper]`` (m²): the branches' derived integrals, and Gauss–Legendre for ``A(g)``
        between the knots of ``g``.

        Parameters
        ----------
        lower : float
            The lower bound (m).
        upper : float
            The upper bound (m).

        Returns
        -------
        float
            The integral (m²; 0 where ``upper <= lower``).
        """
        if upper <= lower:
            return 0.0
        shape, width = self.shape, upper - lower
        total = self.x0 * width
        if self.alpha:
            total += self.alpha * (shape.hertz.integral(upper) - shape.hertz.integral(lower) - self.d_ref * width)
        if self.beta:
            total += self.beta * (shape.grow.integral(upper) - shape.grow.integral(lower) - self.d_ref * width)
        if self.gamma:
            edges = [lower] + [k for k in shape.knots() if lower < k < upper] + [upper]
            for low, high in zip(edges[:-1], edges[1:]):
                nodes = 0.5 * (low + high) + 0.5 * (high - low) * _NODES
                radii = shape.branches[self.radius_of].radii(shape.hertz.depths(nodes))
                total += self.gamma * 0.5 * (high - low) * float(np.dot(_WEIGHTS, radii))
        return total

    # --- monotone intervals and inverses ---------------------------------------------------------
    def turns(self) -> tuple[float, ...]:
        """Where ``dY/dξ`` changes sign on ``(0, reach)``, increasing (``adhesive_seen_piece_turn`` for a growth as the
        compressed zone sees it): sign changes on a grid of :data:`TURN_GRID` points, each refined by ``brentq``.
        Computed once per kind (the coefficients but ``x0``).

        Returns
        -------
        tuple of float
            The turns (m), increasing (none for a constant or ``α g`` alone).
        """
        if self.constant or (not self.beta and not self.gamma):  # a constant, or α g: g increases
            return ()
        key = (self.alpha, self.beta, self.gamma, self.radius_of)
        cached = self.shape.turn_cache.get(key)
        if cached is None:
            cached = self.shape.turn_cache[key] = self._find_turns()
        return cached

    def _find_turns(self) -> tuple[float, ...]:
        grid, slopes = self.shape.turn_grid(self.radius_of)
        slopes = self._slopes_of(*slopes).tolist()  # (the sign changes bracket the turns; each refined by the slope)
        found = []
        for low, high, s_low, s_high in zip(grid[:-1], grid[1:], slopes[:-1], slopes[1:]):
            if s_low == 0.0:
                found.append(float(low))
            elif s_low * s_high < 0.0:
                found.append(optimize.brentq(self.slope, float(low), float(high), xtol=ROOT_XTOL * float(high),
                                             rtol=4 * EPS))
        return tuple(found)

    def monotone_interval(self, lower: float, upper: float) -> tuple[float, float]:
        """The interval between turns (or ``0`` and the reach) that holds ``[lower, upper]``, on which ``Y`` is
        monotone: where a front inside ``[lower, upper]`` is continued.

        Parameters
        ----------
        lower : float
            The start of the springs (m).
        upper : float
            Their end (m): no turn lies between.

        Returns
        -------
        tuple of float
            The interval's ends (m).
        """
        turns = self.turns()
        middle = 0.5 * (lower + upper)
        low = max((t for t in turns if t <= middle), default=0.0)
        high = min((t for t in turns if t > middle), default=max(self.shape.limit(self.radius_of), upper))
        return low, high

    def inverse(self, level: float, lower: float, upper: float, guess: float | None = None,
                ends: tuple[float, float] | None = None) -> float:
        """The ``ξ`` in ``[lower, upper]`` (a monotone interval) where ``Y = level``; the nearer end where ``level``
        lies beyond the values there.

        Parameters
        ----------
        level : float
            The anchor value (m).
        lower : float
            The monotone interval's start (m).
        upper : float
            Its end (m).
        guess : float, optional
            A ``ξ`` near the root (the last one found on the interval): Newton's iteration from it, kept inside the
            bracket (:func:`warm_root`), where the formula's slope is a sum of the branches' (no ``A(g)``).
        ends : tuple of float, optional
            ``Y(lower)``, ``Y(upper)`` where known.

        Returns
        -------
        float
            ``ξ`` (m): the branch's radius where the formula is one branch's depth, else the root to
            ``ROOT_XTOL · upper`` and ``4 eps`` of itself (Newton's from ``guess``, or ``brentq``'s).
        """
        f_low, f_high = ends if ends is not None else (self.value(lower), self.value(upper))
        if (f_low - level) * (f_high - level) > 0.0:
            return lower if abs(f_low - level) < abs(f_high - level) else upper
        if f_low == level:
            return lower
        if f_high == level:
            return upper
        closed = self._branch_inverse(level)
        if closed is not None and lower <= closed <= upper:
            return closed
        if guess is not None and not self.gamma and lower < guess < upper:
            root = warm_root(self, level, (lower, upper), f_low > level, guess)
            if root is not None:
                return root
        return optimize.brentq(lambda xi: self.value(xi) - level, lower, upper, xtol=ROOT_XTOL * upper,
                               rtol=4 * EPS)

    def _branch_inverse(self, level: float) -> float | None:
        """The ``ξ`` of ``level`` where the formula is one branch's depth, ``x0 + α (g − d_ref)`` or
        ``x0 + β (d0 − d_ref)``: that branch's radius of a depth (its closed form or safeguarded root); or where it is a
        radius alone, ``x0 + γ A(g)`` (:meth:`_radius_inverse`); else ``None``."""
        if self.gamma and not (self.alpha or self.beta):
            xi = self._radius_inverse(level)
            return xi if xi == xi else None
        if self.gamma or (self.alpha and self.beta):
            return None
        branch, ratio = (self.shape.hertz, self.alpha) if self.alpha else (self.shape.grow, self.beta)
        xi = branch.radius(self.d_ref + (level - self.x0) / ratio, self.shape.rtol)
        return xi if xi == xi else None

    def inverses(self, levels: np.ndarray, lower: float, upper: float) -> np.ndarray:
        """:meth:`inverse` of an array of levels: vectorised regula falsi with Illinois' halving (superlinear, a
        dozen steps where bisection took :data:`BISECTION_STEPS`), each bracket down to :meth:`inverse`'s tolerance;
        a level beyond the values at the ends gives the nearer end.

        Parameters
        ----------
        levels : numpy.ndarray
            The anchor values (m).
        lower : float
            The monotone interval's start (m).
        upper : float
            Its end (m).

        Returns
        -------
        numpy.ndarray
            ``ξ`` of each level (m).
        """
        levels = np.asarray(levels, dtype=float)
        sign = 1.0 if self.value(upper) >= self.value(lower) else -1.0
        targets = sign * levels
        at_lower, at_upper = sign * self.value(lower), sign * self.value(upper)
        out = np.where(targets <= at_lower, lower, upper)
        inside = (targets > at_lower) & (targets < at_upper)
        if np.any(inside):
            found = self._branch_inverses(levels[inside])
            if found is not None:  # (the branch's vectorised radius, where it lies in the interval)
                out[inside] = found
                inside[inside] = ~((found >= lower) & (found <= upper))
            if np.any(inside):
                out[inside] = self._illinois(sign, targets[inside], lower, upper, at_lower, at_upper)
        return out

    def _branch_inverses(self, levels: np.ndarray) -> np.ndarray | None:
        """:meth:`_branch_inverse` of an array of levels: the branch's radii of the depths at once (``nan`` where
        none); ``None`` for a formula that is neither one branch's depth nor a radius alone."""
        if self.gamma and not (self.alpha or self.beta):
            return self._radius_inverse(levels)
        if self.gamma or (self.alpha and self.beta) or not (self.alpha or self.beta):
            return None
        branch, ratio = (self.shape.hertz, self.alpha) if self.alpha else (self.shape.grow, self.beta)
        return np.asarray(branch.radii(self.d_ref + (levels - self.x0) / ratio), dtype=float)

    def _radius_inverse(self, level):
        """The ``ξ`` of ``level`` (a float or an array) where the formula is a radius alone, ``x0 + γ A(g(ξ))``: the
        radius ``A = (level − x0)/γ``, its depth on its branch, eq. (9), and the ``ξ`` of that depth on ``g``, each a
        closed form (or the profile's own inverse) where the regula falsi took a root of (9) at each of its steps
        (``nan``: a radius below the branch's fold, which no ``ξ`` holds)."""
        branch, radius = self.shape.branches[self.radius_of], (level - self.x0) / self.gamma
        if np.ndim(level) == 0:
            return self.shape.boundary(branch.depth(radius)) if radius >= branch.jump_off_radius else math.nan
        radius = np.asarray(radius, dtype=float)
        return np.where(radius >= branch.jump_off_radius, self.shape.boundaries(branch.depths(radius)), np.nan)

    def _illinois(self, sign: float, targets: np.ndarray, lower: float, upper: float, at_lower: float,
                  at_upper: float) -> np.ndarray:
        """:meth:`inverses` of ``targets`` strictly between the rising values ``sign Y`` at the ends, each bracketed
        first between two of :data:`INVERSE_GRID` points of the interval (one vectorised evaluation: the regula falsi
        then starts where ``Y`` is nearly linear, in a few steps where it took twenty from the whole interval)."""
        grid = np.linspace(lower, upper, INVERSE_GRID)
        seen = sign * self.values(grid)
        seen[0], seen[-1] = at_lower, at_upper
        cell = np.clip(np.searchsorted(seen, targets, side="right"), 1, INVERSE_GRID - 1)
        low, high = grid[cell - 1], grid[cell]
        f_low, f_high = seen[cell - 1] - targets, seen[cell] - targets
        kept = np.zeros(targets.shape, dtype=int)  # the end kept by the last step: -1 low, +1 high
        # a value within the rounding of Y's size of the target is the root (where Y's terms cancel, its rounding is
        # wider than a few ulp of ξ: the regula falsi's signs there are noise, and it went on as a bisection)
        settled = VALUE_ULPS * EPS * np.maximum(np.maximum(abs(at_lower), abs(at_upper)), np.abs(targets))
        for _ in range(BISECTION_STEPS):
            if not np.any(high - low > ROOT_XTOL * upper + 4 * EPS * high):
                break
            with np.errstate(invalid="ignore", divide="ignore"):
                xi = low - f_low * (high - low) / (f_high - f_low)
            xi = np.where((xi > low) & (xi < high), xi, 0.5 * (low + high))
            f_xi = sign * self.values(xi) - targets
            exact = np.abs(f_xi) <= settled
            right = (f_xi < 0.0) & ~exact
            # Illinois: an end kept twice in a row has its value halved, so that it moves too
            f_high = np.where(right & (kept == 1), 0.5 * f_high, f_high)
            f_low = np.where(~right & (kept == -1), 0.5 * f_low, f_low)
            low, f_low = np.where(right | exact, xi, low), np.where(right, f_xi, f_low)
            high, f_high = np.where(~right | exact, xi, high), np.where(~right, f_xi, f_high)
            kept = np.where(right, 1, -1)
        return 0.5 * (low + high)


#: Newton's steps :func:`warm_root` takes at most before it leaves the root to ``brentq``
NEWTON_STEPS = 8
#: A Newton step this share of ``ξ`` or less settles the root: the next would be its square times the formula's
#: relative curvature (about ``(n − 1)/2``, of the power ``ξⁿ`` of ``g``), below the rounding
NEWTON_SETTLED = 1e-8


def warm_root(formula: Formula, level: float, bracket: tuple[float, float], above_at_lower: bool,
              guess: float) -> float | None:
    """The ``ξ`` in ``bracket`` where ``formula`` equals ``level``, by Newton's iteration from ``guess`` (a front's
    last position: two or three steps where brentq takes fifteen evaluations), a step leaving the bracket replaced by
    a bisection, and the bracket narrowed by each value's sign.

    Parameters
    ----------
    formula : Formula
        The anchors (monotone on ``bracket``, without an ``A(g)`` part).
    level : float
        The anchor value (m).
    bracket : tuple of float
        ``(lower, upper)`` (m), the values there on either side of ``level``.
    above_at_lower : bool
        Whether the value at ``lower`` lies above ``level``.
    guess : float
        The start, inside the bracket (m).

    Returns
    -------
    float or None
        The root to ``ROOT_XTOL · upper`` and ``4 eps`` of itself (brentq's tolerance); ``None`` where
        :data:`NEWTON_STEPS` steps do not settle it.
    """
    low, high = bracket
    tolerance = ROOT_XTOL * high
    xi = guess
    for _ in range(NEWTON_STEPS):
        value, slope = formula.value_and_slope(xi)
        excess = value - level
        if excess == 0.0:
            return xi
        if (excess > 0.0) == above_at_lower:
            low = xi
        else:
            high = xi
        step = excess / slope if slope else math.inf
        following = xi - step
        if not low <= following <= high:  # (a step of zero from an iterate the bracket just closed on is inside)
            following = 0.5 * (low + high)
        if abs(following - xi) <= max(tolerance + 4 * EPS * abs(following), NEWTON_SETTLED * abs(xi)):
            return following
        xi = following
    return None


@dataclass(frozen=True)
class FormulaPiece:
    """The springs on ``[start, end]`` with the anchors ``formula``.

    Parameters
    ----------
    start : float
        The first spring's ``ξ`` (m).
    end : float
        The last's (m; ``inf``: a growth still going on).
    formula : Formula
        Their anchors ``Y(ξ)``.
    """

    start: float
    end: float
    formula: Formula


def growth_formula(shape: Shape, x0: float, ratio: float, d_ref: float) -> Formula:
    """The anchors of springs attaching along the ``Δγ0`` branch on a segment, ``x0 + ratio (d0(ξ) − d_ref)`` (a
    constant for ``ratio = 0``): the :class:`~.anchors.Piece` of the planner as a :class:`Formula`.

    Parameters
    ----------
    shape : Shape
        The functions of the contact.
    x0 : float
        The anchor at ``d_ref`` (m).
    ratio : float
        ``v_x/v_d`` of the segment (0: a constant).
    d_ref : float
        The reference depth (m).

    Returns
    -------
    Formula
        The anchors.
    """
    return Formula(shape, x0, beta=ratio, d_ref=d_ref if ratio else 0.0)
