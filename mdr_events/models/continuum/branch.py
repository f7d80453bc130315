"""One adhesive branch (9) of the contact radius, evaluated for Python floats and arrays: the paper's
paraboloid (:class:`Branch`), a power law ``f = c rⁿ`` (:class:`PowerLawBranch`) or the flat punch
(:class:`FlatPunchBranch`)."""

from __future__ import annotations

import math

import numpy as np

from mdr_events.theory import analytic, flat_punch, power_law, symbolic, tabulated
# (the closed forms unchecked: a branch's work is checked once when it is made, its depths and radii are the run's own)
from mdr_events.theory.power_law.normal import _branch_depth as _power_law_depth, _contact_radius as _power_law_radius
from mdr_events.theory.quartic import depressed_quartic_root
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, PowerLaw, TabulatedProfile, indenter_kind

#: :meth:`Branch.sample_radii` keeps the iteration of :meth:`Branch.radii` where the quartic's slope in ``s`` is below
#: this share of its leading term's, ``p'(s) < NEAR_FOLD · 4 s³``: near the jump-off fold, where the root's
#: conditioning amplifies rounding over a thousandfold, the two routes agree only to it (``√ε`` on the fold), and a
#: run that ends at pull-off ends there: its last radius is then the one its events and extrema read (both iterate).
NEAR_FOLD = 1e-3
#: A depth this share below the jump-off depth still gives the jump-off radius: a radius pinned just
#: outside the fold is released at a depth that rounds below it.
FOLD_SHARE = 1e-9


class Branch:
    r"""The branch (9) of the contact radius with work of adhesion ``work``: depth, slope and integral
    of a radius, radius of a depth.

    The scalar methods use the derived relations compiled for Python floats
    (:attr:`mdr_events.symbolic.Relation.scalar`): the right-hand side and the event functions of
    the continuum method call them thousands of times per run. The radius of a depth is the largest
    positive root of the quartic in ``s = sqrt(a)`` (:func:`mdr_events.theory.roots.positive_polynomial_root`),
    above the jump-off radius (the stable branch).

    .. math:: d = \frac{a^2}{R} - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9)

    Parameters
    ----------
    params : Parameters
        The material and ``R`` of the paraboloid.
    work : float
        The work of adhesion ``Δγ`` (J/m²) of the branch (0: Hertz).
    """

    #: whether every spring in contact rests on ``g = 0`` (the flat punch's face): Coulomb's caps ``K a + κ max(d, 0)``
    #: are then the same for all of them, and the anchors are compared with the levels as they are
    #: (:meth:`~.anchors.AnchorMap.seen_by`)
    flat = False
    #: the radii, increasing, where the branch's depth is not smooth (a derivative of some order jumps): a solver
    #: integrating along the radius restarts there instead of shrinking its steps against a kink (none: smooth)
    knots: tuple[float, ...] = ()
    #: the power ``n`` of the profile at its tip, ``g ∝ ξⁿ`` (the paraboloid's 2; ``None``: not a power there):
    #: ``g⁻¹(d) ∝ d^(1/n)`` near the surface (:mod:`.graded`)
    tip_power: float | None = 2.0
    #: the depth at which a growing radius reaches the indenter's edge and stops there (a flat face's on a layer,
    #: :class:`~.layer_punch_branch.LayerPunchBranch`; ``+inf``: it grows on): the planner ends a growing span there
    edge_depth = math.inf
    #: the largest radius the branch holds (m): none on the half-space; a layer's tables end at ``a/h = 64``
    ceiling = math.inf
    #: whether :meth:`sample_radii` is the paraboloid's quartic in closed form: this class's own (the paraboloid's
    #: branch); every subclass is ``False`` unless it sets it in its own body (:meth:`__init_subclass__`), so that
    #: a branch of another indenter samples by its own :meth:`radii`
    quartic_samples = True
    #: whether ``d(a)`` is convex above the jump-off (the paraboloid's ``a²/R − k√a``: both terms convex), so that the
    #: radius is concave in the depth and a closed-form span's readings of its events settle them
    #: (:mod:`.closed_form`); ``False`` for every subclass unless it sets it (:meth:`__init_subclass__`; a power law
    #: sets ``n >= 1`` for its instance)
    convex = True
    #: the NumPy form of ``dd/da`` (:meth:`slopes`; ``None``: a branch without one, read point by point)
    _slopes = None
    #: whether :meth:`radii` is element by element (each radius the one of a call on its depth alone, whatever else is
    #: in the array: a table's, :meth:`~mdr_events.theory.tabulated.TabulatedBranch.radii`), so that
    #: :meth:`grouped_sample_radii` calls it once for all groups; ``False`` where an iteration's last step depends on
    #: the elements it runs for; ``False`` for every subclass unless its own body sets it (:meth:`__init_subclass__`)
    elementwise_radii = False

    def __init_subclass__(cls, **kwargs):
        """A subclass's :attr:`quartic_samples`, :attr:`convex` and :attr:`elementwise_radii` are ``False`` unless its
        own body declares them (fails closed: a new branch type never inherits the paraboloid's closed form, nor its
        convexity, nor a table's element-by-element radii)."""
        super().__init_subclass__(**kwargs)
        cls.quartic_samples = bool(cls.__dict__.get("quartic_samples", False))
        cls.convex = bool(cls.__dict__.get("convex", False))
        cls.elementwise_radii = bool(cls.__dict__.get("elementwise_radii", False))
    #: the NumPy form of ``∫_0^a d dξ`` (:meth:`integrals`; ``None``: a branch without one, read point by point)
    _integrals = None

    def __init__(self, params: Parameters, work: float):
        self.params = params
        self.work = work
        self._arguments = (params.R, params.E_star, work)
        self._depth = symbolic.relation("jkr_depth").scalar
        self._slope = symbolic.relation("jkr_depth_slope").scalar
        self._slopes = symbolic.relation("jkr_depth_slope").numeric
        self._integral = symbolic.relation("jkr_depth_integral").scalar
        self._integrals = symbolic.relation("jkr_depth_integral").numeric
        self._coefficients = symbolic.relation("jkr_radius_quartic").scalar_coefficients
        self._array_coefficients = symbolic.relation("jkr_radius_quartic").coefficients
        # (the NumPy forms with the branch's constants bound once: a run reads them at every fill and scan)
        self._quartic_of = symbolic.relation("jkr_radius_quartic").bound_coefficients(*self._arguments)
        self._depths_of = symbolic.relation("jkr_depth").bound_numeric(*self._arguments)
        self._integrals_of = symbolic.relation("jkr_depth_integral").bound_numeric(*self._arguments)
        if work > 0:
            point = analytic.jump_off(params, work)
            self.jump_off_radius, self.jump_off_depth = point["contact_radius"], point["depth"]
        else:
            self.jump_off_radius = self.jump_off_depth = 0.0
        self._floor = math.sqrt(self.jump_off_radius)

    def depth(self, a: float) -> float:
        """Depth of the contact of radius ``a`` on this branch, eq. (9) (0 at ``a = 0``).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The depth ``d`` (m).
        """
        return self._depth(a, *self._arguments) if a > 0 else 0.0

    def growth_depth(self, a: float) -> float:
        """The depth beyond which a contact of radius ``a`` grows along this (``Δγ0``) branch: :meth:`depth`.

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The depth (m).
        """
        return self.depth(a)

    def slope(self, a: float) -> float:
        """``dd/da`` on this branch; its limits at ``a → 0``: 0 for Hertz, ``-inf`` with adhesion.

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
            return self._slope(a, *self._arguments)
        return 0.0 if self.work == 0.0 else -math.inf

    def slopes(self, a: np.ndarray) -> np.ndarray:
        """:meth:`slope` of an array of radii: the relation's NumPy form at once where the branch has one (eq. (9)'s, a
        power law's), each radius ``<= 0`` (or ``nan``) and any other branch point by point.

        Parameters
        ----------
        a : numpy.ndarray
            The contact radii (m), 1-D.

        Returns
        -------
        numpy.ndarray
            ``dd/da`` at each (1).
        """
        a = np.asarray(a, dtype=float)
        if self._slopes is None:
            return np.array([self.slope(float(v)) for v in a])
        inside = a > 0
        out = np.asarray(self._slopes(np.where(inside, a, 1.0), *self._arguments), dtype=float) * np.ones(a.shape)
        for index in np.flatnonzero(~inside):
            out[index] = self.slope(float(a[index]))
        return out

    def integral(self, a: float) -> float:
        """``∫_0^a d(ξ) dξ`` along this branch.

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The integral (m²; 0 at ``a <= 0``).
        """
        return self._integral(a, *self._arguments) if a > 0 else 0.0

    def integrals(self, a: np.ndarray) -> np.ndarray:
        """:meth:`integral` of an array of radii: the relation's NumPy form at once where the branch has one (eq.
        (9)'s, a power law's, a table's), any other branch point by point.

        Parameters
        ----------
        a : numpy.ndarray
            The contact radii (m).

        Returns
        -------
        numpy.ndarray
            ``∫_0^a d(ξ) dξ`` at each (m²; 0 at ``a <= 0``), the shape of ``a``.
        """
        a = np.asarray(a, dtype=float)
        if self._integrals is None:
            return np.reshape([self.integral(float(v)) for v in a.ravel()], a.shape)
        value = np.asarray(self._integrals_of(np.where(a > 0, a, 1.0)), dtype=float)
        return np.where(a > 0, value, 0.0)

    def depth_term(self, a: float) -> float:
        """The size of the terms of (9) at radius ``a``: the profile's ``g(a) = a²/R`` (the depth they cancel to
        near first contact of an adhesive indenter is far smaller: tolerances are shares of this).

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``g(a)`` (m).
        """
        return a**2 / self.params.R

    def normal_force_slope(self, a: float) -> float:
        """``dF_N/da`` along this branch over ``2E*``: ``d + a d' − g(a)`` (10), the springs all alike.

        Parameters
        ----------
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The slope over ``2E*`` (m).
        """
        return self.depth(a) + a * self.slope(a) - self.depth_term(a)

    def depths(self, a: np.ndarray) -> np.ndarray:
        """:meth:`depth` for an array of radii (vectorised).

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
        value = self._depths_of(np.where(a > 0, a, 1.0))
        return np.where(a > 0, value, 0.0)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radius` for an array of depths (vectorised; ``nan`` below the jump-off depth).

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
        if self.work == 0.0:
            return np.asarray(analytic.jkr_contact_radius(depth, self.params, self.work))
        # (jkr_contact_radius's own steps, its checks and the jump-off point taken once, in __init__)
        root = analytic.positive_polynomial_root(self._quartic_of(depth), lower=self._floor)
        return np.where(depth >= self.jump_off_depth, root**2, np.nan)

    def sample_radii(self, depth: np.ndarray) -> np.ndarray:
        """:meth:`radii` at a run's samples: on the paraboloid with adhesion (:attr:`quartic_samples`), the quartic's
        root in closed form (:func:`mdr_events.theory.quartic.depressed_quartic_root`, a few ulp from :meth:`radii`'s
        iteration, within the root's conditioning at the fold); Hertz's and any other branch's, :meth:`radii` itself.

        Parameters
        ----------
        depth : array_like
            The depths (m).

        Returns
        -------
        numpy.ndarray
            The radii (m), the shape of ``depth`` (``nan`` below the jump-off depth).
        """
        if self.work == 0.0 or not self.quartic_samples:  # (Hertz, or another indenter: its own)
            return self.radii(depth)
        depth = np.asarray(depth, dtype=float)
        root, linear, constant = self._closed_roots(depth)
        self._iterate_near_fold(root, linear, constant)
        return np.where(depth >= self.jump_off_depth, root.reshape(depth.shape)**2, np.nan)

    def grouped_sample_radii(self, depths: list[np.ndarray]) -> list[np.ndarray]:
        """:meth:`sample_radii` of each group of depths (1-D arrays), bit for bit: the quartic's closed form, element by
        element, in one call over all of them; the iteration near the fold (:data:`NEAR_FOLD`) group by group, as each
        group's own call runs it (an iteration's last step depends on the elements it runs for). A branch whose
        :meth:`radii` is element by element (:attr:`elementwise_radii`): one call for all; any other: its call per
        group.

        Parameters
        ----------
        depths : list of numpy.ndarray
            The groups of depths (m), each 1-D.

        Returns
        -------
        list of numpy.ndarray
            The radii (m) of each group (``nan`` below the jump-off depth).
        """
        if len(depths) > 1 and self.elementwise_radii and (self.work == 0.0 or not self.quartic_samples):
            radii, begin = self.sample_radii(np.concatenate(depths)), 0
            parts = []
            for depth in depths:
                parts.append(radii[begin:begin + len(depth)])
                begin += len(depth)
            return parts
        if self.work == 0.0 or not self.quartic_samples or len(depths) < 2:
            return [self.sample_radii(depth) for depth in depths]
        depth = np.concatenate(depths)
        root, linear, constant = self._closed_roots(depth)
        radii, begin = [], 0
        for group in depths:
            part = slice(begin, begin + len(group))
            self._iterate_near_fold(root[part], linear, constant[part])
            radii.append(np.where(group >= self.jump_off_depth, root[part]**2, np.nan))
            begin = part.stop
        return radii

    @property
    def root_floor(self) -> float:
        """The lower bound of the quartic's root ``s = √a`` (9): ``√a`` at the jump-off (0 for Hertz)."""
        return self._floor

    @property
    def quartic_linear(self) -> float:
        """The linear coefficient ``P`` of the paraboloid's quartic in ``s = √a``, ``s⁴ + P s − R d`` (9), by the
        relation's form for floats (the same bits as its NumPy form's)."""
        return float(self._coefficients(0.0, *self._arguments)[3])

    def near_fold_radii(self, depth: np.ndarray) -> np.ndarray:
        """The paraboloid's radii (9) at ``depth`` by the iteration, as :meth:`sample_radii` takes them near the fold
        (:data:`NEAR_FOLD`): the quartic's largest root not below :attr:`root_floor`, squared.

        Parameters
        ----------
        depth : numpy.ndarray
            The depths (m), 1-D.

        Returns
        -------
        numpy.ndarray
            The radii (m) (``nan`` below the jump-off depth).
        """
        linear, constant = self._quartic_of(depth)[3:]
        root = analytic.positive_polynomial_root([1.0, 0.0, 0.0, float(linear), constant], lower=self._floor)
        return np.where(depth >= self.jump_off_depth, root * root, np.nan)

    def _closed_roots(self, depth: np.ndarray) -> tuple[np.ndarray, float, np.ndarray]:
        """The quartic's root ``s = √a`` of each depth in closed form (not below the jump-off's), flat, with the
        quartic's linear and constant coefficients (:meth:`sample_radii`)."""
        linear, constant = self._quartic_of(depth)[3:]
        linear, constant = float(linear), np.broadcast_to(constant, depth.shape)
        root = np.atleast_1d(np.maximum(depressed_quartic_root(linear, constant), self._floor))
        return root, linear, np.atleast_1d(constant)

    def _iterate_near_fold(self, root: np.ndarray, linear: float, constant: np.ndarray) -> None:
        """The roots ``root`` (flat, changed in place) near the fold taken from the iteration instead: where the
        quartic's slope is below :data:`NEAR_FOLD` of its leading term's."""
        cube = root**3
        near = (4.0 * cube + linear < NEAR_FOLD * 4.0 * cube).reshape(root.shape)
        if near.any():  # (the iteration's own radius at the fold: that of the events and of the extrema there)
            root[near] = analytic.positive_polynomial_root([1.0, 0.0, 0.0, linear, constant[near]], lower=self._floor)

    def radius(self, depth: float, rtol: float) -> float:
        """Stable-branch radius at ``depth``, converged to ``rtol``.

        ``nan`` below the jump-off depth; within :data:`FOLD_SHARE` of it, the jump-off radius.

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
        """
        if self.work == 0.0:  # Hertz: no contact above the surface (d <= 0, to rounding at first contact)
            return math.sqrt(self.params.R * depth) if depth > 0 else 0.0
        if depth < self.jump_off_depth:
            if depth < self.jump_off_depth * (1.0 + FOLD_SHARE):
                return math.nan
            return self.jump_off_radius
        coefficients = self._coefficients(depth, *self._arguments)
        root = analytic.positive_polynomial_root(coefficients, lower=self._floor, rtol=rtol)
        return root * root


class PowerLawBranch(Branch):
    """The branch of the power law ``f = c rⁿ`` (:class:`~mdr_events.contact.indenters.PowerLaw`):
    ``d = κ c aⁿ − sqrt(2π a Δγ / E*)`` (:mod:`mdr_events.theory.power_law`); the radius of a depth is the root of
    a convex function of ``s = √a`` above the jump-off (:func:`~mdr_events.theory.power_law.branch_root`)."""

    def __init__(self, params: Parameters, work: float, profile: PowerLaw):
        self.params, self.work, self.profile = params, work, profile
        self._arguments = (profile.c, profile.n, params.E_star, work)
        self._depth = symbolic.relation("power_law_depth").scalar
        self._slope = symbolic.relation("power_law_depth_slope").scalar
        self._slopes = symbolic.relation("power_law_depth_slope").numeric
        self._integral = symbolic.relation("power_law_depth_integral").scalar
        self._integrals = symbolic.relation("power_law_depth_integral").numeric
        self._integrals_of = symbolic.relation("power_law_depth_integral").bound_numeric(*self._arguments)
        point = power_law.jump_off(profile, params, work)
        self.jump_off_radius, self.jump_off_depth = point["contact_radius"], point["depth"]
        self._floor = math.sqrt(self.jump_off_radius)
        self._kc = power_law.prefactor(profile)
        self._hess = power_law.hess_prefactor(params, work)
        self._exponent = 2.0 * profile.n
        self.tip_power = float(profile.n)
        # (κ c aⁿ is convex for n >= 1, and −k√a always: d convex; below 1 the tip's aⁿ is concave)
        self.convex = profile.n >= 1.0

    def slope(self, a: float) -> float:
        if a > 0:
            return self._slope(a, *self._arguments)
        if self.work > 0.0:
            return -math.inf
        n = self.profile.n  # n κ c a^(n−1) at a = 0
        return 0.0 if n > 1.0 else (self._kc if n == 1.0 else math.inf)

    def depth_term(self, a: float) -> float:
        return self._kc * a**self.profile.n

    def depths(self, a: np.ndarray) -> np.ndarray:
        a = np.asarray(a, dtype=float)
        value = _power_law_depth(np.where(a > 0, a, 1.0), self.profile, self.params, self.work)
        return np.where(a > 0, value, 0.0)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        return np.asarray(_power_law_radius(np.asarray(depth, dtype=float), self.profile, self.params, self.work))

    def radius(self, depth: float, rtol: float) -> float:
        if self.work == 0.0:  # no contact above the surface
            return (depth / self._kc) ** (1.0 / self.profile.n) if depth > 0 else 0.0
        if depth < self.jump_off_depth:
            if depth < self.jump_off_depth * (1.0 + FOLD_SHARE):
                return math.nan
            return self.jump_off_radius
        root = power_law.branch_root(depth, self._kc, self._hess, self._exponent, self._floor, rtol)
        return root * root


class FlatPunchBranch(Branch):
    """The flat punch of radius ``R_p`` (:class:`~mdr_events.contact.indenters.FlatPunch`): every spring under it has
    ``g = 0``, so the contact is the punch's whole face from the first touch (``d >= 0``) on and never grows
    beyond it (:meth:`growth_depth` is ``+inf``); its edge springs reach Heß's limit (8) at
    ``d = −sqrt(2π R_p Δγ / E*)``, the jump-off, where every spring lets go at once (Kendall's pull-off).

    The radius of any depth down to the jump-off is ``R_p``; the branch's depth at ``R_p`` is the jump-off's
    (where detachment starts); no span ever moves the radius (the planner pins it).
    """

    flat = True

    tip_power = None

    def __init__(self, params: Parameters, work: float, profile: FlatPunch):
        self.params, self.work, self.profile = params, work, profile
        point = flat_punch.jump_off(profile, params, work)
        self.jump_off_radius, self.jump_off_depth = point["contact_radius"], point["depth"]
        self._floor = math.sqrt(self.jump_off_radius)

    def depth(self, a: float) -> float:
        return self.jump_off_depth if a > 0 else 0.0

    def growth_depth(self, a: float) -> float:
        return math.inf if a >= self.jump_off_radius else 0.0

    def slope(self, a: float) -> float:
        return 0.0

    def integral(self, a: float) -> float:
        """``∫_0^a g dξ``: the springs under the punch rest on a flat face (``g = 0``)."""
        return 0.0

    def integrals(self, a: np.ndarray) -> np.ndarray:
        """:meth:`integral` of each radius: 0."""
        return np.zeros(np.shape(a))

    def depth_term(self, a: float) -> float:
        return 0.0

    def depths(self, a: np.ndarray) -> np.ndarray:
        a = np.asarray(a, dtype=float)
        return np.where(a > 0, self.jump_off_depth, 0.0)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        return np.asarray(flat_punch._radius(depth, self.profile, self.params, self.work, FOLD_SHARE))

    def radius(self, depth: float, rtol: float) -> float:
        return float(flat_punch._radius(depth, self.profile, self.params, self.work, FOLD_SHARE))


class TabulatedBranch(Branch):
    """The branch of a tabulated profile (:class:`~mdr_events.contact.indenters.TabulatedProfile`): ``d = g(a) − sqrt(2π a
    Δγ / E*)`` with ``g`` the table's numerical Abel transform (:mod:`mdr_events.theory.tabulated`); the radius of a
    depth a bracketed root above the jump-off."""

    tip_power = None  # (a table's g need not be a power at its first point)
    elementwise_radii = True

    def __init__(self, params: Parameters, work: float, profile: TabulatedProfile):
        self.params, self.work, self.profile = params, work, profile
        self.line = tabulated.branch(profile, params, work)
        # the scalar three straight from the table's branch, bound once (the methods below say the same; the
        # continuum reads them some 5000 times a run, where each call through this class cost a frame)
        self.depth, self.slope, self.integral = self.line.depth, self.line.slope, self.line.integral
        self.jump_off_radius, self.jump_off_depth = self.line.jump_off_radius, self.line.jump_off_depth
        self._floor = math.sqrt(self.jump_off_radius)
        self._g = self.line.shape.g
        #: the breaks of the interpolated ``g`` (a PCHIP: its second derivative jumps at each)
        self.knots = tuple(float(x) for x in self.line.shape.grid)

    def depth(self, a: float) -> float:
        return self.line.depth(a)

    def slope(self, a: float) -> float:
        return self.line.slope(a)

    def integral(self, a: float) -> float:
        return self.line.integral(a)

    def integrals(self, a: np.ndarray) -> np.ndarray:
        a = np.asarray(a, dtype=float)
        inside = self.line.shape.inside_all(a)  # (the table's end within END_SHARE, nan beyond: as integral)
        value = self.line.shape.g_integral(inside) - 2.0 / 3.0 * self.line.k * inside**1.5
        return np.where(a > 0, value, 0.0)

    def depth_term(self, a: float) -> float:
        return float(self._g(min(a, self.line.shape.x_max))) if a > 0 else 0.0

    def depths(self, a: np.ndarray) -> np.ndarray:
        return self.line.depths(a)

    def radii(self, depth: np.ndarray) -> np.ndarray:
        return self.line.radii(depth)

    def radius(self, depth: float, rtol: float) -> float:
        if self.work == 0.0 and depth <= 0:  # no contact above the surface
            return 0.0
        if depth < self.jump_off_depth and depth >= self.jump_off_depth * (1.0 + FOLD_SHARE):
            return self.jump_off_radius
        return self.line.radius(depth, rtol)


def make_branch(params: Parameters, work: float, profile: PowerLaw | FlatPunch | TabulatedProfile | None = None) -> Branch:
    """The branch of ``work`` for ``profile`` (``None``: the paraboloid of ``params.R``, the paper's)."""
    if profile is None:
        return Branch(params, work)
    return _BRANCH_CLASSES.get(indenter_kind(profile), PowerLawBranch)(params, work, profile)


#: The branch class of each kind of indenter but the paper's paraboloid, by its type (anything else is handed to
#: :class:`PowerLawBranch`, whose relations name what they take).
_BRANCH_CLASSES: dict[type, type[Branch]] = {PowerLaw: PowerLawBranch, FlatPunch: FlatPunchBranch,
                                             TabulatedProfile: TabulatedBranch}
