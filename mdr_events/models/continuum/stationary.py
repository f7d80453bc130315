"""Where a quantity of one span is stationary: :func:`~.span_extrema.extremum`'s refinement of a bracketed extremum by
the roots of the quantity's derivative, from the span's own closed forms and dense output (no generic minimisation,
no radius root per evaluation).

- ``F_x``: the span's interpolant is a polynomial on each solver step in its variable (DOP853's dense output, degree
  :data:`DENSE_DEGREE`; the time, or the radius over the span's scale, which is monotone in time on a moving span).
  Each step's polynomial is read off at ``DENSE_DEGREE + 1`` Chebyshev points (exactly: the interpolant *is* that
  polynomial), differentiated, and the real roots of the derivative in the bracket are the stationary points. A
  force in closed form (:class:`~.closed_form.ClosedForce`) gives the roots of its primitive's rate
  (:meth:`~.closed_form.ClosedForce.stationary`). A force linear in time (:class:`~.span.LinearForce`) or constant
  has none inside a span.
- ``F_N`` on a moving radius: along the branch ``F_N(a) = 2E* (a d(a) − ∫_0^a g)`` (10), so
  ``dF_N/da = 2E* (d(a) + a d'(a) − g(a))`` (the branch's depth, slope and profile term,
  :meth:`~.branch.Branch.depth_term`); its root in the bracket is found by ``brentq`` in the radius, and the time is that of the depth
  (linear in time on a segment). On a pinned radius ``F_N`` is linear in the depth, hence in time: no stationary
  point inside a span (its extremes are the span's ends, which the scan holds).
- The contact radius and area are monotone on a span.

The reading of a polynomial at Chebyshev points and the roots of its derivative (:func:`derivative_roots`) also refine
the extrema of the rate-dependent law's run (:func:`~mdr_events.models.continuum.rate_run.rate_extrema`), where the
radius of each interval between the scan's times is one step of the edge's dense output.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.polynomial import chebyshev
from scipy import optimize
from scipy.integrate import OdeSolution

from .closed_form import ClosedForce
from .dense import force_values
from .graded import natural_variable, span_variable
from .span import LinearForce
from .span_record import Variable
from .state import Regime
from .tolerances import EPS

__all__ = ["DENSE_DEGREE", "stationary_points", "never_stationary", "interpolant_roots", "chebyshev_nodes",
           "derivative_roots"]

#: Degree of the polynomial of one step of DOP853's dense output (``solve_ivp``'s interpolant of ``F_x``).
DENSE_DEGREE = 7
#: A root of the derivative counts as real where its imaginary part is below this share of the step (the companion
#: matrix's rounding: a double root at a flat extremum splits into a complex pair of about sqrt(eps)).
IMAGINARY_SHARE = 1e-6


@functools.lru_cache(maxsize=None)
def _chebyshev_reading(degree: int) -> tuple[np.ndarray, np.ndarray]:
    """The Chebyshev points of the first kind on [-1, 1] (``degree + 1``) and the matrix taking a polynomial's values
    there to the Chebyshev coefficients of its derivative (the interpolation followed by the derivative)."""
    nodes = np.cos(np.pi * (np.arange(degree + 1) + 0.5) / (degree + 1))
    nodes.setflags(write=False)
    return nodes, chebyshev.chebder(np.linalg.inv(chebyshev.chebvander(nodes, degree)))


#: The Chebyshev points of a step of DOP853's dense output (degree :data:`DENSE_DEGREE`) and the matrix taking its values
#: there to its derivative's Chebyshev coefficients (:func:`_chebyshev_reading`).
_NODES, _DERIVATIVE = _chebyshev_reading(DENSE_DEGREE)


def chebyshev_nodes(degree: int = DENSE_DEGREE) -> np.ndarray:
    """The points on [-1, 1] at which :func:`derivative_roots` reads a polynomial of ``degree``.

    Parameters
    ----------
    degree : int, optional
        The polynomial's degree.

    Returns
    -------
    numpy.ndarray
        The ``degree + 1`` Chebyshev points of the first kind (read-only: shared).
    """
    return _chebyshev_reading(degree)[0]


def derivative_roots(values: np.ndarray, degree: int = DENSE_DEGREE) -> list[float]:
    """The real roots of the derivative of the polynomial of ``degree`` through ``values`` at
    :func:`chebyshev_nodes`, in the nodes' variable on [-1, 1] (not clipped to it; roots with an imaginary part above
    :data:`IMAGINARY_SHARE` left out): a step's stationary points, exact where the step is that polynomial (a dense
    output's step), else those of its Chebyshev interpolant.

    Parameters
    ----------
    values : numpy.ndarray
        The ``degree + 1`` values at :func:`chebyshev_nodes`.
    degree : int, optional
        The polynomial's degree.

    Returns
    -------
    list of float
        The real roots (any order).
    """
    return [float(root.real) for root in chebyshev.chebroots(_chebyshev_reading(degree)[1] @ values)
            if abs(root.imag) <= IMAGINARY_SHARE]


#: A step's derivative ``Σ c_k T_k`` (degree ``n = DENSE_DEGREE − 1``) has no root that :func:`_dense_output_roots`
#: keeps where ``|c₀| > ROOT_FREE_MARGIN Σ_{k≥1} |c_k|``: on the Bernstein ellipse of ``ρ = 1.01`` every
#: ``|T_k| ≤ ρ^k ≤ ρⁿ = 1.0615``, so the sum cannot vanish inside it, and the ellipse (half-axes 1.00005 and 0.00995)
#: holds every root kept (imaginary part within :data:`IMAGINARY_SHARE`, real part within the step, ``[-1, 1]`` to
#: rounding); the 3.5 % left covers the eigenvalue solver's backward error (some ulp of the coefficients). Such a step's
#: roots are not sought (an eigenvalue problem each).
ROOT_FREE_MARGIN = 1.1

#: ``brentq``'s relative tolerance on the stationary radius of ``F_N`` (a few ulp).
RADIUS_RTOL = 4 * EPS


def stationary_points(solution, index: int, quantity: str, times: tuple[float, float],
                      radii: tuple[float, float]) -> list[tuple[float, float]] | None:
    """The points of span ``index`` inside the bracket where ``quantity`` is stationary, with its values there.

    Parameters
    ----------
    solution : PathSolution
    index : int
        The span.
    quantity : str
        ``"normal_force"``, ``"tangential_force"``, ``"contact_radius"`` or ``"contact_area"``.
    times : tuple of float
        The bracket's ends (s from first contact), increasing, within the span.
    radii : tuple of float
        The contact radius at those times (m).

    Returns
    -------
    list of (float, float) or None
        ``(time, value)`` of each stationary point inside the bracket (times from first contact; none: the
        extremes are the bracket's ends); ``None`` where the quantity has no derivative route here (the caller
        refines otherwise).
    """
    span = solution.spans[index]
    if never_stationary(solution, index, quantity):
        return []
    if quantity == "normal_force":
        return _normal_force_points(solution, span, times, radii)
    if quantity != "tangential_force" or solution.compressed is not None:
        return None
    if span.interpolant is None:  # a constant force
        return []
    if span.variable is Variable.TIME:
        bracket = (solution.t_contact + times[0], solution.t_contact + times[1])
    else:
        bracket = (radii[0] / span.scale, radii[1] / span.scale)
    bracket = tuple(span_variable(span, end) for end in bracket)  # (u on a graded span: dv/du > 0 inside)
    points = []
    for var in interpolant_roots(span.interpolant, min(bracket), max(bracket)):
        value = float(span.interpolant(var)[0])
        natural = natural_variable(span, var)
        if span.variable is Variable.TIME:
            time = natural - solution.t_contact
        else:
            time = _time_of_radius(solution, span, natural * span.scale)
        points.append((min(max(time, times[0]), times[1]), value))
    return points


def never_stationary(solution, index: int, quantity: str) -> bool:
    """Whether :func:`stationary_points` finds no point of span ``index`` in any bracket: out of contact, the radius
    and the area (monotone on a span), ``F_N`` on a pinned radius (linear in the depth), ``F_x`` constant, linear in
    time or a still closed form (:attr:`~.closed_form.Primitive.still`: its rate is zero at every reading, so
    :meth:`~.closed_form.ClosedForce.stationary` finds no change of sign) (the compressed zone's aside, whose spans
    are another run's).

    Parameters
    ----------
    solution : PathSolution
    index : int
        The span.
    quantity : str
        A quantity of :data:`~.span_extrema.EXTREMUM_QUANTITIES`.

    Returns
    -------
    bool
        ``True`` where none can be found (:func:`~.span_extrema.extremum` keeps the scan's point without asking).
    """
    span = solution.spans[index]
    if span.regime is Regime.NONE or quantity in ("contact_radius", "contact_area"):
        return True
    if quantity == "normal_force":
        return span.regime is Regime.PINNED
    if quantity != "tangential_force" or solution.compressed is not None:
        return False  # (no derivative route: the caller searches)
    interpolant = span.interpolant
    # (a still closed form's rate is 0, or nan where the slope is infinite, at every reading: no change of sign)
    return interpolant is None or type(interpolant) is LinearForce \
        or (type(interpolant) is ClosedForce and interpolant.primitive.still)


@functools.singledispatch
def interpolant_roots(interpolant, low: float, high: float) -> list[float]:
    """The roots in ``[low, high]`` of the derivative of a span's interpolant of ``F_x``, by its type: ``solve_ivp``'s
    dense output (DOP853's steps, or the panels stored as such), a force in closed form
    (:meth:`~.closed_form.ClosedForce.stationary`) or one linear in time (none).

    Parameters
    ----------
    interpolant : OdeSolution, ClosedForce or LinearForce
        The span's interpolant.
    low, high : float
        The interval (the span's variable), ``low <= high``.

    Returns
    -------
    list of float
        The roots (none: the force is monotone there).

    Raises
    ------
    TypeError
        An interpolant of another type: none is made, since every source of ``span.interpolant``
        (:func:`~.integrate.integrate_span`) gives one of the three (the panels of :mod:`.span_panels` and the steps of
        :mod:`.span_march` an ``OdeSolution``, :func:`~.closed_form.closed_span` a ``ClosedForce``, a linear span a
        ``LinearForce``; a constant force none, which :func:`stationary_points` skips); the error is a bug, raised
        through :func:`~.span_extrema.extremum`.
    """
    raise TypeError(f"interpolant={interpolant!r} is not allowed; allowed: an OdeSolution, a ClosedForce or a "
                    "LinearForce")


@interpolant_roots.register
def _(interpolant: OdeSolution, low: float, high: float) -> list[float]:
    return _dense_output_roots(interpolant, low, high)


@interpolant_roots.register
def _(interpolant: ClosedForce, low: float, high: float) -> list[float]:
    return interpolant.stationary(low, high)


@interpolant_roots.register
def _(interpolant: LinearForce, low: float, high: float) -> list[float]:
    return []


def _dense_output_roots(interpolant, low: float, high: float) -> list[float]:
    """The real roots in ``[low, high]`` of the derivative of ``solve_ivp``'s dense output, step by step: the steps
    that meet the bracket picked at once, and the polynomials of several read off at their nodes in one evaluation
    (:func:`~.dense.force_values`: each node lies inside its own step, so the values are its step's, bit for bit)."""
    ts = np.asarray(interpolant.ts, dtype=float)
    starts, ends = np.minimum(ts[:-1], ts[1:]), np.maximum(ts[:-1], ts[1:])
    lowers, uppers = np.maximum(starts, low), np.minimum(ends, high)
    steps = np.flatnonzero(uppers > lowers)
    if not steps.size:
        return []
    centres, halves = 0.5 * (starts[steps] + ends[steps]), 0.5 * (ends[steps] - starts[steps])
    nodes = centres[:, None] + halves[:, None] * chebyshev_nodes()
    if steps.size == 1:  # (the step's own interpolant: one call)
        values = interpolant.interpolants[int(steps[0])](nodes[0])
    else:
        values = force_values(interpolant, nodes.reshape(-1)).reshape(nodes.shape)
    coefficients = values @ _DERIVATIVE.T  # (each step's derivative, for the test of ROOT_FREE_MARGIN)
    # (a step whose derivative is not finite is sought, as before: its eigenvalue problem refuses it)
    sought = ~(np.abs(coefficients[:, 0]) > ROOT_FREE_MARGIN * np.sum(np.abs(coefficients[:, 1:]), axis=1))
    roots = []
    for centre, half, lower, upper, row in zip(centres[sought].tolist(), halves[sought].tolist(),
                                               lowers[steps][sought].tolist(), uppers[steps][sought].tolist(),
                                               values[sought]):
        for root in derivative_roots(row):
            var = centre + half * root
            if lower <= var <= upper:
                roots.append(var)
    return roots


def _normal_force_points(solution, span, times: tuple[float, float],
                         radii: tuple[float, float]) -> list[tuple[float, float]] | None:
    """The radius in the bracket where ``dF_N/da = 2E* (d + a d' − g)`` vanishes along the span's branch."""
    model = solution.model
    branch = model.branch(span.regime)

    slope = branch.normal_force_slope  # dF_N/da over 2E* (on a layer: K'(d − g) + K d', over 2E*)

    low, high = min(radii), max(radii)
    ends = (slope(low), slope(high))
    if not all(math.isfinite(value) for value in ends):
        return None
    if ends[0] * ends[1] > 0.0 or not high > low:
        return []
    radius = optimize.brentq(slope, low, high, xtol=RADIUS_RTOL * high, rtol=RADIUS_RTOL)
    value = float(model.normal_force(branch.depth(radius), radius))
    return [(min(max(_time_of_radius(solution, span, radius), times[0]), times[1]), value)]


def _time_of_radius(solution, span, radius: float) -> float:
    """The time (s from first contact) at which a moving radius of ``span`` is ``radius``: that of its depth."""
    depth = solution.model.branch(span.regime).depth(radius)
    time = span.segment.time_at_depth(depth) - solution.t_contact
    return min(max(time, span.t_start - solution.t_contact), span.t_end - solution.t_contact)
