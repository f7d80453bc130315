r"""A moving span's force in closed form on a bonded layer (issue 34), as :mod:`.closed_form` has it on the half-space:
where no front moves through the anchors, the springs at each cap are whole pieces, and each zone's measure is a
constant plus, where the edge piece is at the cap, ``M(a) − M(ξ_e)`` (``M(ξ) = K_t(ξ)/(2G*)``,
:class:`~.layer_media.LayerMedium`).

The right-hand side of :meth:`~.span.SpanIntegrator.rhs` under ``τ0``'s law (``κ = 0``) is then

    dF_x/da = 2G* [(D₀ + D₁ M) ū' + (E₀ + E₁ M) d' + (U ū + A + C d + C₀ d₀) w],

``D`` the zones' difference, ``E = (v_x/v_d) S`` the sticking measure's drive, and on a shrinking span the edge's shift
weighed by ``w = M'``: ``U = ±1`` at a cap, else ``x − Y(a) = A + C d(a) + C₀ d₀(a)`` (:func:`~.closed_form.span_primitive`'s
terms). By parts (``(M ū)' = w ū + M ū'``, ``(M d)' = w d + M d'``) its primitive is

    P(a) = D₀ ū + D₁ (M ū − J_u) + E₀ d + E₁ (M d − J_d) + U J_u + A M + C J_d + C₀ J₀,

with three integrals of the radius alone, ``J_u = K ∫ w ū/K``, ``J_d = ∫ w d`` along the span's branch and
``J₀ = ∫ w d₀`` along the anchors' one. These have no closed form (``w``, ``ū`` and ``d`` are the tables' quintic
splines of ``ln λ`` under exponentials, and Heß's square root), but every function here is analytic between the
splines' breaks: :class:`BranchIntegrals` reads ``M``, ``ū/K``, ``d``, ``w ū/K`` and ``w d`` at a
:data:`CELL_NODES`-point Gauss–Legendre rule on each cell between two breaks (at most :data:`CELL_WIDTH` wide in
``ln a``), once per branch (the runs of one contact's angles share it), and holds their interpolants through the nodes
as Legendre series per cell (the integrands' integrated, plus the cells below): ``P`` at any radius is one cell's
series, the same Clenshaw recurrence for one radius and for many (the same values bit for bit). The series are within
~1e-14 of the functions (:data:`CELL_NODES`), ``rtol = 1e-10`` being what the quadrature by panels held each panel
to; the span's rate (:meth:`LayerPrimitive.rate`) is the right-hand side's own terms, read as it reads them.

On the paper's 5 mm layer this takes the place of the quadrature on every span the half-space has in closed form
(``benchmarks/bench_layer_continuum.py``: scenario B at eight angles, 138 panels of 8 readings before).

``tests/models/test_closed_form.py`` compares the closed form with the quadrature on the layer as on the half-space.
"""

from __future__ import annotations

import bisect
import math
from typing import NamedTuple

import numpy as np
from numpy.polynomial import legendre

from mdr_events.theory.layer.scalar_factors import piece_index
from mdr_events.theory.layer.tables import LAMBDA_MIN
from mdr_events.theory.layer.tangential_tables import LAMBDA_MIN as TANGENTIAL_LAMBDA_MIN

from .state import Cap

__all__ = ["BranchIntegrals", "LayerPrimitive", "layer_span_primitive", "branch_integrals", "CELL_NODES"]

#: Gauss–Legendre points per cell between two breaks of the tables' splines (cells ``Δ ln a <= CELL_WIDTH``). Within a
#: cell the functions are analytic, their nearest singularity ``a = 0`` (``√a`` of Heß's term, ``ln a`` of the
#: splines) ``2/0.1 = 20`` half-widths away or more, so the interpolant through the nodes is within ``~ρ^-n`` of the
#: function, ``ρ ≈ 40`` (Bernstein's ellipse): ``40^-8 ≈ 1.5e-13`` of its size at ``n = 8``, the rule's integral
#: ``ρ^-2n``; measured on the paper's 5 mm and a 1 mm layer, 5e-14 of each function's largest value and the
#: integrals within 2e-13 of SciPy's ``quad`` (``tests/models/test_layer_closed_form.py``).
CELL_NODES = 8
#: The widest cell in ``ln a`` (the tables' step, :data:`~mdr_events.theory.layer.tables.TABLE_STEP`): where the
#: breaks are farther apart (below the tables' least ``λ``), the cell is cut.
CELL_WIDTH = 0.1
#: How many branches' integrals are kept (:data:`_INTEGRALS`: the runs of one contact's angles share them).
_KEPT = 64


class BranchIntegrals:
    """``M``, ``ū/K`` and the branch's ``d`` along one branch on one medium, with ``J_u(a) = ∫ w ū/K dξ`` and
    ``J_d(a) = ∫ w d dξ``, from the branch's lowest radius (its jump-off, or a floor without adhesion) to the tables'
    ceiling: per cell between two breaks of the tables' splines, each function's interpolant through the cell's
    :data:`CELL_NODES` Gauss–Legendre points as a Legendre series (the integrals' integrated from the cell's start,
    plus the cumulative sum of the cells below: the rule's value at its end), evaluated all at once (module docstring).

    Parameters
    ----------
    medium : LayerMedium
        The bonded layer's springs (``M``, ``w``, ``ū``).
    branch : LayerBranch
        The branch (``d``).
    """

    #: The functions held, in their rows' order: ``M``, ``ū/K``, ``d``, ``J_u``, ``J_d``.
    NAMES = ("M", "u", "d", "J_u", "J_d")

    def __init__(self, medium, branch):
        from .layer_branch import START_SCAN_FLOOR

        h = branch.h
        breaks = set(medium.tangential.columns.breaks) | set(branch.factors.both.breaks)
        breaks |= {math.log(LAMBDA_MIN), math.log(TANGENTIAL_LAMBDA_MIN)}
        self.floor = branch.jump_off_radius if branch.jump_off_radius > 0.0 else START_SCAN_FLOOR * h
        self.ceiling = branch.ceiling
        inner = sorted(h * math.exp(s) for s in breaks if self.floor < h * math.exp(s) < self.ceiling)
        self.ends = _cells([self.floor, *inner, self.ceiling])
        ends = np.array(self.ends)
        points, weights = legendre.leggauss(CELL_NODES)
        low, width = ends[:-1], np.diff(ends)
        radii = (low[:, None] + 0.5 * width[:, None] * (points[None, :] + 1.0)).ravel()
        w, u = medium.weights_and_caps(radii)
        M = medium.measures_and_shifts(1.0, radii)[0]
        d = branch.depths(radii)
        # each cell's interpolant through its nodes as Legendre coefficients (the rule's projection, exact for it)
        basis = legendre.legvander(points, CELL_NODES - 1)  # (node, degree)
        project = (basis * weights[:, None]).T * ((2.0 * np.arange(CELL_NODES) + 1.0) / 2.0)[:, None]
        series = []
        for values in (M, u, d):
            coefficients = project @ values.reshape(width.size, CELL_NODES).T  # (degree, cell)
            series.append(np.vstack([coefficients, np.zeros((1, width.size))]))
        for values in (w * u, w * d):
            coefficients = project @ values.reshape(width.size, CELL_NODES).T
            primitive = 0.5 * width * legendre.legint(coefficients, lbnd=-1.0, axis=0)  # (degree + 1, cell)
            primitive[0] += np.concatenate([[0.0], np.cumsum(legendre.legval(1.0, primitive))])[:-1]
            series.append(primitive)
        #: the series, ``(function, degree + 1, cell)``, and per cell as lists (the scalar route's)
        self.series = np.array(series)
        self.lists = self.series.transpose(2, 0, 1).tolist()
        self.width, self._ends = width, ends
        self._by_degree = np.ascontiguousarray(self.series.transpose(1, 0, 2))  # (degree + 1, function, cell)
        #: :attr:`_by_degree`'s rows of a few functions (:meth:`values` of a tuple of rows), made when first asked
        self._rows: dict[tuple[int, ...], np.ndarray] = {}

    def covers(self, low: float, high: float) -> bool:
        """Whether ``[low, high]`` lies within the cells.

        Parameters
        ----------
        low, high : float
            The radii (m).

        Returns
        -------
        bool
            ``floor <= low`` and ``high <= ceiling``.
        """
        return self.floor <= low and high <= self.ceiling

    def values(self, a: np.ndarray, rows: slice = slice(None)) -> np.ndarray:
        """The functions of :data:`NAMES` (``rows`` of them) at the radii ``a`` within the cells.

        Parameters
        ----------
        a : numpy.ndarray
            The radii (m), one-dimensional, or one radius (0-d).
        rows : slice or tuple of int, optional
            Which of the functions (default all): a slice, or their indices in :data:`NAMES`' order.

        Returns
        -------
        numpy.ndarray
            ``(function, radius)``; ``(function,)`` at one radius given 0-d.
        """
        a = np.asarray(a, dtype=float)
        if a.size <= SCALAR_RADII and isinstance(rows, tuple):  # (a few radii: :meth:`value`'s, the same numbers)
            read = [self.value(radius, rows) for radius in a.reshape(-1).tolist()]
            return np.array(read, dtype=float).reshape(a.size, len(self.NAMES))[:, list(rows)].T.reshape(
                (len(rows),) + a.shape)
        cell = piece_index(self._ends, a, len(self.ends) - 2)
        t = 2.0 * (a - self._ends[cell]) / self.width[cell] - 1.0
        if isinstance(rows, tuple):  # (a few rows: their coefficients kept apart, the same numbers)
            if rows not in self._rows:
                self._rows[rows] = np.ascontiguousarray(self._by_degree[:, list(rows)])
            coefficients = self._rows[rows][:, :, cell]
        else:
            coefficients = self._by_degree[:, rows, cell]  # (degree + 1, function, radius)
        return _clenshaw(coefficients, t)

    def value(self, a: float, rows: tuple[int, ...] | None = None) -> list[float]:
        """:meth:`values` at one radius, every function, in Python floats (Clenshaw's recurrence).

        Parameters
        ----------
        a : float
            The radius (m).
        rows : tuple of int, optional
            Only these functions (indices in :data:`NAMES`' order); the others ``0.0``. Default all.

        Returns
        -------
        list of float
            The functions of :data:`NAMES`.
        """
        cell = min(max(bisect.bisect_right(self.ends, a) - 1, 0), len(self.ends) - 2)
        low, high = self.ends[cell], self.ends[cell + 1]
        t = 2.0 * (a - low) / (high - low) - 1.0
        out = []
        for index, coefficients in enumerate(self.lists[cell]):
            if rows is not None and index not in rows:
                out.append(0.0)
                continue
            b1 = b2 = 0.0
            for k in range(CELL_NODES, 0, -1):  # (P_{k+1} = ((2k+1) t P_k − k P_{k−1})/(k+1))
                b1, b2 = coefficients[k] + _ALPHA[k] * t * b1 - _BETA[k] * b2, b1
            out.append(coefficients[0] + t * b1 - 0.5 * b2)
        return out


#: Clenshaw's coefficients of Legendre's recurrence, ``(2k+1)/(k+1)`` and ``(k+1)/(k+2)`` at ``k``
_ALPHA = [(2.0 * k + 1.0) / (k + 1.0) for k in range(CELL_NODES + 1)]
_BETA = [(k + 1.0) / (k + 2.0) for k in range(CELL_NODES + 1)]
_ALPHA_ARRAY = np.array(_ALPHA)
#: At most this many radii, :meth:`BranchIntegrals.values` of a few rows reads each radius as
#: :meth:`~BranchIntegrals.value` does (the same numbers bit for bit, ``tests/models/test_layer_closed_form.py``): an
#: array's recurrence costs some forty NumPy calls whatever its length (~50 µs), one radius in Python floats ~6 µs.
SCALAR_RADII = 4


def _clenshaw(coefficients: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Legendre's series of ``coefficients`` ``(degree + 1, function, radius)`` at ``t`` ``(radius,)`` by
    Clenshaw's recurrence (``P_{k+1} = ((2k+1) t P_k − k P_{k−1})/(k+1)``), each step's operations those of
    :meth:`~BranchIntegrals.value` in its order (``c_k + (α_k t) b₁ − β_k b₂``: the same numbers bit for bit), into
    two buffers kept over the steps: the ``α_k t`` of every step at once, no array made per operation (a run's few
    hundred radii cost the operations' calls, not their length)."""
    scaled = np.multiply.outer(_ALPHA_ARRAY, t)  # (each α_k t: the products α_k · t of the steps' own)
    b1, b2 = np.zeros(coefficients.shape[1:]), np.zeros(coefficients.shape[1:])
    term = np.empty(coefficients.shape[1:])
    for k in range(CELL_NODES, 0, -1):
        np.multiply(scaled[k], b1, out=term)
        np.add(coefficients[k], term, out=term)
        np.multiply(_BETA[k], b2, out=b2)
        np.subtract(term, b2, out=b2)  # (the new b₁, in the old b₂'s buffer)
        b1, b2 = b2, b1
    return coefficients[0] + t * b1 - 0.5 * b2


def _cells(ends: list[float]) -> list[float]:
    """``ends`` with every cell wider than :data:`CELL_WIDTH` in ``ln a`` cut into equal parts of ``ln a`` (below
    the tables' least ``λ``, on a thick layer, the series' range has no breaks)."""
    out = [ends[0]]
    for low, high in zip(ends[:-1], ends[1:]):
        parts = math.ceil(math.log(high / low) / CELL_WIDTH)
        out += [low * math.exp(k * math.log(high / low) / parts) for k in range(1, parts)] + [high]
    return out


def branch_integrals(medium, branch) -> BranchIntegrals:
    """The :class:`BranchIntegrals` of ``branch`` on ``medium``, made once per branch's values (and kept)."""
    from .layer_branch import _branch_key

    key = (*_branch_key(branch), branch.jump_off_radius)
    found = _INTEGRALS.get(key)
    if found is None:
        if len(_INTEGRALS) >= _KEPT:
            _INTEGRALS.clear()
        found = _INTEGRALS[key] = BranchIntegrals(medium, branch)
    return found


#: The integrals made, by the branch's values and its jump-off radius (at most :data:`_KEPT`).
_INTEGRALS: dict[tuple, BranchIntegrals] = {}


class LayerPrimitive(NamedTuple):
    """``P(a)`` of a moving span without a front on a bonded layer (module docstring), with ``dP/da`` its
    right-hand side over ``2G*``; called as :class:`~.closed_form.Primitive` is (:class:`~.closed_form.ClosedForce`).

    Parameters
    ----------
    medium : LayerMedium
        The springs (``M``, ``w``, ``ū``).
    K : float
        The half-space's cap per radius (``ū = K a/Φ_t``).
    branch, attach : LayerBranch
        The span's branch ``d(a)``, the edge's springs' ``d₀``.
    own, anchors : BranchIntegrals
        The integrals along ``branch`` and ``attach``.
    D0, D1, E0, E1, U, A, C, C0 : float
        The coefficients.
    """

    medium: object
    K: float
    branch: object
    attach: object
    own: BranchIntegrals
    anchors: BranchIntegrals
    D0: float
    D1: float
    E0: float
    E1: float
    U: float
    A: float
    C: float
    C0: float

    @property
    def still(self) -> bool:
        """Every coefficient zero: ``P ≡ 0`` (no spring holds a shift and nothing drives one: a vertical path's
        receding punch), read without the cells' series."""
        return not (self.D0 or self.D1 or self.E0 or self.E1 or self.U or self.A or self.C or self.C0)

    @property
    def linear(self) -> bool:
        """Whether :meth:`rate` is monotone in floats for :meth:`~.closed_form.ClosedForce.stationary`'s proof
        (:attr:`~.closed_form.Primitive.linear`): where :attr:`still` alone (the rate 0 throughout)."""
        return self.still

    @property
    def rows(self) -> tuple[int, ...]:
        """The functions of :data:`BranchIntegrals.NAMES` whose terms in ``P`` have a coefficient other than zero
        (``M`` for ``D₁``, ``E₁``, ``A``; ``ū`` for ``D₀``, ``D₁``; ``d`` for ``E₀``, ``E₁``; ``J_u`` for ``D₁``,
        ``U``; ``J_d`` for ``E₁``, ``C``)."""
        needed = (self.D1 or self.E1 or self.A, self.D0 or self.D1, self.E0 or self.E1, self.D1 or self.U,
                  self.E1 or self.C)
        return tuple(index for index, need in enumerate(needed) if need)

    def __call__(self, a: np.ndarray) -> np.ndarray:
        """``P`` at the radii ``a`` (m), vectorised: the cells' series of :attr:`rows` alone, the others' terms
        ``0 · 0`` (:meth:`all_rows`' values bit for bit where ``P`` is not zero); zeros where :attr:`still`."""
        a = np.asarray(a, dtype=float)
        if self.still:
            return np.zeros(a.shape)
        rows = self.rows
        values = [0.0] * len(BranchIntegrals.NAMES)
        for index, row in zip(rows, self.own.values(np.reshape(a, -1), rows)):
            values[index] = row
        return np.reshape(self.combine(*values, self.anchors.values(np.reshape(a, -1), slice(4, 5))[0]
                                        if self.C0 else 0.0), a.shape)

    def all_rows(self, a: np.ndarray) -> np.ndarray:
        """``P`` at the radii ``a`` (m) from every function's series (the route before :meth:`__call__` read
        :attr:`rows` alone; kept for the test that compares both).

        Parameters
        ----------
        a : numpy.ndarray
            The radii (m).

        Returns
        -------
        numpy.ndarray
            ``P``, the shape of ``a``.
        """
        a = np.asarray(a, dtype=float)
        M, u, depth, J_u, J_d = self.own.values(np.reshape(a, -1))
        return np.reshape(self.combine(M, u, depth, J_u, J_d, self.anchors.values(np.reshape(a, -1), slice(4, 5))[0]
                                        if self.C0 else 0.0), a.shape)

    def at(self, a: float) -> float:
        """``P`` at one radius ``a`` (m), in Python floats (the same series, Clenshaw's recurrence; 0 where
        :attr:`still`)."""
        if self.still:
            return 0.0
        return self.combine(*self.own.value(a, self.rows), self.anchors.value(a, (4,))[4] if self.C0 else 0.0)

    def combine(self, M, u, depth, J_u, J_d, J_0):
        """``P`` of the functions' values (module docstring): what :meth:`__call__` sums, for a caller that read
        the series itself (``span_forces``: several spans' radii in one call).

        Parameters
        ----------
        M, u, depth, J_u, J_d : numpy.ndarray or float
            The functions of :data:`BranchIntegrals.NAMES` along the span's branch (``0.0`` where :attr:`rows` does
            not read them).
        J_0 : numpy.ndarray or float
            ``J_d`` along the anchors' branch (``0.0`` where ``C0`` is 0).

        Returns
        -------
        numpy.ndarray or float
            ``P``.
        """
        cap, J_u = self.K * u, self.K * J_u
        value = self.D0 * cap + self.D1 * (M * cap - J_u) + self.E0 * depth + self.E1 * (M * depth - J_d)
        return value + self.U * J_u + self.A * M + self.C * J_d + self.C0 * J_0

    def rate(self, a: float) -> float:
        """``dP/da`` at the radius ``a`` (m): the span's right-hand side over ``2G*``, term by term (0 where
        :attr:`still`)."""
        if self.still:
            return 0.0
        M, cap, cap_slope, weight = self.medium.rate_parts(self.K, a)
        value = (self.D0 + self.D1 * M) * cap_slope
        value += (self.E0 + self.E1 * M) * self.branch.slope(a)
        if self.U or self.A or self.C or self.C0:
            edge = self.U * cap + self.A + self.C * self.branch.depth(a)
            if self.C0:
                edge += self.C0 * self.attach.depth(a)
            value += edge * weight
        return value


def layer_span_primitive(integrator) -> LayerPrimitive | None:
    """``P`` of a moving span without a front on a bonded layer under ``τ0``'s law (the caller checks that it has no
    front and moves), or ``None`` where the span leaves the integrals' cells (a contact from ``a = 0`` without
    adhesion) or carries Coulomb's part.

    Parameters
    ----------
    integrator : SpanIntegrator
        The span's zones, anchors, segment, branch and caps.

    Returns
    -------
    LayerPrimitive or None
        ``P``, with ``dF_x/da = 2G* dP/da``.
    """
    if integrator.kappa:
        return None
    medium, branch, attach = integrator.medium, integrator.branch, integrator.anchors.attach
    low, high = sorted((integrator.radius_of(integrator.start), integrator.radius_of(integrator.stop)))
    own = branch_integrals(medium, branch)
    anchors = own if attach is branch else branch_integrals(medium, attach)
    if not (own.covers(low, high) and anchors.covers(low, high)):
        return None
    segment, zones = integrator.segment, integrator.zones
    constant, linear = {}, {}
    for cap in Cap:
        zone = zones[cap]
        linear[cap] = 1.0 if zone.edge_in else 0.0
        constant[cap] = zone.inner_length - (medium.measure(0.0, zone.pieces[zone.edge].start) if zone.edge_in else 0.0)
    ratio = segment.vx / segment.vd
    D0, D1 = constant[Cap.POSITIVE] - constant[Cap.NEGATIVE], linear[Cap.POSITIVE] - linear[Cap.NEGATIVE]
    S0 = -constant[Cap.POSITIVE] - constant[Cap.NEGATIVE]
    S1 = 1.0 - linear[Cap.POSITIVE] - linear[Cap.NEGATIVE]
    U = A = C = C0 = 0.0
    if integrator.shrinking:  # the edge's shift: ±ū at a cap, else x − Y(a)
        at_cap = [cap for cap in Cap if zones[cap].edge_in_zone]
        edge = integrator.anchors.pieces[-1]
        if at_cap:
            U = float(at_cap[0])
        else:  # x = X₀ + (v_x/v_d) d on the segment; Y = x₀ + r (d₀(a) − d_ref) on the edge's piece
            r = 0.0 if edge.constant else edge.ratio
            A, C, C0 = segment.xs - ratio * segment.ds - edge.x0 + r * edge.d_ref, ratio, -r
    return LayerPrimitive(medium, integrator.K, branch, attach, own, anchors, D0, D1, ratio * S0, ratio * S1,
                          U, A, C, C0)
