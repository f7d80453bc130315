"""``F_N`` and ``F_x`` of a run's samples in contact in one pass (issue 28: ``simulate`` of scenario A or B under 2 ms),
where the paper's paraboloid on the half-space makes both polynomials.

- ``F_N`` (10) of the paraboloid, ``2E* a (d − a²/(3R))``: the relation's two terms in one product;
- ``F_x`` of every span whose force is a polynomial in one variable ``v``: a closed-form span on the paraboloid's
  branches (:class:`~.closed_form.ClosedForce` of a :class:`~.closed_form.Primitive` on :class:`~.branch.Branch`), in
  ``v = s = √a``; a pinned span's :class:`~.span.LinearForce`, in ``v = t − t₀``; a constant force. Each span is one
  row of a coefficient matrix, ``F = F₀ + G (q₀ + q₁ v + … + q₆ v⁶)``, every sample reading its span's row in one
  Horner pass over all samples. Any other span (a dense output, a table's or a power law's branch, a graded span)
  keeps its own route (:func:`~.span_forces.span_forces`) for its rows.

On the paraboloid's branch (9) ``d = s⁴/R − k s`` with ``k = √(2πΔγ/E*)``, so the primitive's terms
(:class:`~.closed_form.Primitive`: ``A₀ a + A₁ a²/2 + B₀ d + B₁ (a d − ∫d) + C ∫d + C₀ ∫d₀``, ``∫d = s⁶/(3R) −
2k s³/3``) collect into

    q₁ = −B₀ k,  q₂ = A₀,  q₃ = −(B₁ k + 2C k + 2C₀ k₀)/3,  q₄ = A₁/2 + B₀/R,  q₅ = 0,  q₆ = (2B₁ + C + C₀)/(3R),

``q₀ = −P(a₀)`` (the span's origin), ``F₀`` the force at the span's start and ``G = 2G*``: ``F_x = F₀ + 2G* (P(s) −
P(s₀))`` in the order :class:`~.closed_form.ClosedForce` sums it. A linear force is the row ``F₀ + rate (0 + 1·v)``,
``F₀ + rate (t − t₀)`` bit for bit; a constant one ``F₀ + (−0)·0``, ``F₀`` bit for bit (a zero's sign kept).

The values differ from the terms' route (:data:`FillRoute.TERMS`, the spans' own calls) by rounding alone: both sum
the same terms in another order, within a few ulp times the condition of the sum (``tests/models/test_sample_forces.py``
derives the bound and checks it on every kind of run).
"""

from __future__ import annotations

import enum
import math

import numpy as np

from .branch import Branch
from .closed_form import ClosedForce, Primitive
from .media import HalfSpaceMedium
from .span import LinearForce

__all__ = ["FillRoute", "POLYNOMIAL_DEGREE", "paraboloid_on_half_space", "normal_forces", "force_rows",
           "polynomial_forces"]

#: The degree of the rows' polynomials: the paraboloid's primitive in ``s = √a`` reaches ``s⁶`` (``a³/(3R)``).
POLYNOMIAL_DEGREE = 6


class FillRoute(enum.Enum):
    """How :func:`~.solution.evaluate` computes ``F_N`` and ``F_x`` of the samples in contact."""

    #: every span's polynomial in one Horner pass, ``F_N`` in one product (this module): the default
    POLYNOMIAL = "polynomial"
    #: the spans' own terms, as each span's call sums them (:func:`~.span_forces.span_forces`, the model's ``F_N``),
    #: the reference the polynomial route is checked against
    TERMS = "terms"


def paraboloid_on_half_space(model) -> bool:
    """Whether ``model`` is the paper's paraboloid on the half-space (its ``F_N`` is :func:`normal_forces`').

    Parameters
    ----------
    model : ContinuumModel
        The continuum model.

    Returns
    -------
    bool
        ``True`` for the paraboloid of ``params.R`` (no profile) on :class:`~.media.HalfSpaceMedium` itself.
    """
    return model.profile is None and type(model.medium) is HalfSpaceMedium


def normal_forces(params, depth: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """``F_N`` (10) of the paraboloid, ``2E* a (d − a²/(3R))``, at the depths and radii given.

    Parameters
    ----------
    params : Parameters
        ``E*`` and ``R``.
    depth, radius : numpy.ndarray
        ``d`` and ``a`` (m).

    Returns
    -------
    numpy.ndarray
        ``F_N`` (N).
    """
    return (2.0 * params.E_star) * radius * (depth - radius * radius * (1.0 / (3.0 * params.R)))


def _branch_k(branch: Branch, ks: dict[int, float]) -> float:
    """``k = √(2πΔγ/E*)`` of the paraboloid's branch (9), ``d = a²/R − k√a``; kept in ``ks`` by the branch's ``id``
    (the spans of one run share their branches)."""
    k = ks.get(id(branch))
    if k is None:
        k = ks[id(branch)] = math.sqrt(2.0 * math.pi * branch.work / branch.params.E_star)
    return k


def _closed_row(force: ClosedForce, ks: dict[int, float]) -> tuple[float, float, list[float]] | None:
    """``(F₀, G, q)`` of a closed-form span on the paraboloid's branches (module docstring), ``None`` for any other
    closed form (another branch, another primitive); ``ks``: the branches' ``k`` found so far."""
    primitive = force.primitive
    if type(primitive) is not Primitive or type(primitive.branch) is not Branch or not primitive.branch.quartic_samples:
        return None
    if primitive.C0 and type(primitive.attach) is not Branch:
        return None
    R, k = primitive.branch.params.R, _branch_k(primitive.branch, ks)
    k0 = _branch_k(primitive.attach, ks) if primitive.C0 else 0.0
    A0, A1, B0, B1, C, C0 = primitive[2:]
    q = [-force.origin, -B0 * k, A0, -(B1 * k + 2.0 * C * k + 2.0 * C0 * k0) / 3.0, 0.5 * A1 + B0 / R, 0.0,
         (2.0 * B1 + C + C0) / (3.0 * R)]
    return force.force, force.G2, q


def force_rows(spans: list) -> list[tuple[bool, float, float, float, list[float]] | None]:
    """Each span's row of the Horner pass: ``(in_radius, t₀, F₀, G, q)`` (``in_radius``: ``v = √a``, else ``v = t −
    t₀``), ``None`` for a span whose force is no polynomial here (its own route reads it).

    Parameters
    ----------
    spans : list of Span
        Spans in contact.

    Returns
    -------
    list
        The rows, in the order of ``spans``.
    """
    zero = [0.0] * (POLYNOMIAL_DEGREE + 1)
    rows, ks = [], {}
    for span in spans:
        interpolant = span.interpolant
        if interpolant is None:  # (F₀ + (−0)·0: F₀ bit for bit, its zero's sign too)
            rows.append((False, 0.0, span.force, -0.0, zero))
        elif type(interpolant) is LinearForce and span.grading is None:
            rows.append((False, interpolant.t0, interpolant.force, interpolant.rate, [0.0, 1.0] + zero[2:]))
        elif type(interpolant) is ClosedForce and span.grading is None:
            row = _closed_row(interpolant, ks)
            rows.append(None if row is None else (True, 0.0, *row))
        else:
            rows.append(None)
    return rows


def polynomial_forces(rows: list, t: np.ndarray, a: np.ndarray, lengths: list[int]) -> np.ndarray:
    """``F_x`` at every sample of the spans with a row (:func:`force_rows`; a span without one gets ``nan``, for its
    own route to fill): each span's row repeated over its samples (``lengths``), one Horner pass over all.

    Parameters
    ----------
    rows : list
        Each span's row or ``None``.
    t : numpy.ndarray
        The samples' times (s, the path's: a linear force's variable).
    a : numpy.ndarray
        The samples' radii (m).
    lengths : list of int
        Each span's number of samples, in order.

    Returns
    -------
    numpy.ndarray
        ``F_x`` (N) at every sample.
    """
    nan_row = (False, 0.0, math.nan, 0.0, [0.0] * (POLYNOMIAL_DEGREE + 1))
    table = np.array([[float(row[0]), row[1], row[2], row[3], *row[4]] for row in
                      (nan_row if row is None else row for row in rows)], dtype=float).T
    in_radius, t0, force, gain, *q = np.repeat(table, lengths, axis=1)
    v = np.where(in_radius != 0.0, np.sqrt(a), t - t0)
    value = q[POLYNOMIAL_DEGREE]
    for coefficient in q[POLYNOMIAL_DEGREE - 1::-1]:
        value = value * v + coefficient
    return force + gain * value
