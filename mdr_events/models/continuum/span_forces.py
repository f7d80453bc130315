"""``F_x`` of several spans at their points at once, grouped by the kind of their interpolants (issue 28: one pass over
the spans): the values each span's own call gives, bit for bit, in a call per group instead of one per span.

- DOP853 steps (``solve_ivp``'s dense output, and the panels stored as such): every span's steps gathered into one
  table (``dense._gathered``), each point with the step its own span's ``OdeSolution`` picks, and the
  interpolant's sequence of products and sums over all points at once (``dense._step_values``);
- closed forms on one branch (:class:`~.closed_form.ClosedForce` of a :class:`~.closed_form.Primitive`): the branch's
  depths and integrals of all their radii in one call each, the primitive's terms with each span's coefficients
  repeated over its points, in the order ``Primitive.__call__`` sums them;
- forces linear in time (:class:`~.span.LinearForce`, a pinned span's): ``F0 + rate (t − t0)`` with each span's
  numbers repeated over its points;
- a bonded layer's closed forms on one branch (each a :class:`~.layer_closed_form.LayerPrimitive`, sharing their
  cells' series): the series of every row any of them reads at all their radii in one call (each row and radius a lane of
  Clenshaw's recurrence of its own), each span's ``P`` of its own rows (the others ``0.0``, as its call leaves them);
- anything else (another dense output, a layer's closed form of at most ``SCALAR_RADII`` points or ``P ≡ 0``), and a
  group of one span: its own call, :func:`~.dense.force_values`.

Each value is the same whether it is computed among other spans' or alone: the branch's NumPy forms and the products
and sums act element by element (``tests/models/test_extremum_scan.py`` compares both routes).
"""

from __future__ import annotations

import numpy as np

from .closed_form import ClosedForce, Primitive
from .layer_closed_form import SCALAR_RADII, BranchIntegrals, LayerPrimitive
from .dense import _gathered, _step_values, cut, force_values
from .span import LinearForce

__all__ = ["span_forces"]


def span_forces(interpolants: list, points: list[np.ndarray]) -> list[np.ndarray]:
    """``interpolant(points)[0]`` of each span's interpolant at its points (1-D arrays), bit for bit, by groups.

    Parameters
    ----------
    interpolants : list
        The spans' interpolants of ``F_x`` (``OdeSolution``, ``ClosedForce``, ``LinearForce``, ...).
    points : list of numpy.ndarray
        Each span's points in its variable (time, or radius over the span's scale), 1-D.

    Returns
    -------
    list of numpy.ndarray
        ``F_x`` (N) at each span's points, in the order given.
    """
    out: list = [None] * len(interpolants)
    steps, closed, layered, linear = [], {}, {}, []
    for index, (interpolant, where) in enumerate(zip(interpolants, points)):
        gathered = _gathered(interpolant) if np.ndim(where) == 1 else None
        if gathered is not None:
            steps.append((index, gathered))
        elif type(interpolant) is ClosedForce and type(interpolant.primitive) is Primitive and np.ndim(where) == 1:
            primitive = interpolant.primitive
            closed.setdefault((id(primitive.branch), id(primitive.attach)), []).append(index)
        elif type(interpolant) is ClosedForce and type(interpolant.primitive) is LayerPrimitive \
                and np.ndim(where) == 1 and np.size(where) > SCALAR_RADII and not interpolant.primitive.still:
            primitive = interpolant.primitive
            layered.setdefault((id(primitive.own), id(primitive.anchors)), []).append(index)
        elif type(interpolant) is LinearForce and np.ndim(where) == 1:
            linear.append(index)
        else:
            out[index] = force_values(interpolant, where)
    alone = [index for index, _ in steps] if len(steps) == 1 else []  # (a group of one: its own call)
    if len(steps) > 1:
        _fill(out, [index for index, _ in steps], _step_values([found for _, found in steps],
                                                                [points[index] for index, _ in steps]))
    for members, values in [*((members, _closed_values) for members in closed.values()),
                            *((members, _layer_closed_values) for members in layered.values())]:
        if len(members) > 1:
            _fill(out, members, values([interpolants[index] for index in members], [points[index] for index in members]))
        else:
            alone += members
    if len(linear) > 1:
        _fill(out, linear, _linear_values([interpolants[index] for index in linear],
                                          [points[index] for index in linear]))
    else:
        alone += linear
    for index in alone:
        out[index] = force_values(interpolants[index], points[index])
    return out


def _linear_values(forces: list[LinearForce], points: list[np.ndarray]) -> list[np.ndarray]:
    """``LinearForce.__call__`` of several forces linear in time at their times: ``F0 + rate (t − t0)``
    with each span's numbers over its times, element by element."""
    lengths = [len(where) for where in points]

    def each(values: list[float]) -> np.ndarray:
        return np.repeat(np.array(values, dtype=float), lengths)

    t = np.concatenate([np.asarray(where, dtype=float) for where in points])
    values = each([f.force for f in forces]) + each([f.rate for f in forces]) * (t - each([f.t0 for f in forces]))
    return cut(values, lengths)


def _fill(out: list, members: list[int], values: list[np.ndarray]) -> None:
    for index, value in zip(members, values):
        out[index] = value


def _closed_values(forces: list[ClosedForce], points: list[np.ndarray]) -> list[np.ndarray]:
    """``ClosedForce.__call__`` of closed forms on one branch (and one branch of attachment) at their points: the
    depths and integrals of all radii in one call each (the branch's NumPy forms, element by element), then each
    span's terms with its own coefficients, in the order ``Primitive.__call__`` sums them."""
    radii = [np.reshape(np.asarray(where, dtype=float), -1) * force.scale for force, where in zip(forces, points)]
    lengths = [len(each) for each in radii]
    branch, attach = forces[0].primitive.branch, forces[0].primitive.attach
    together = np.concatenate(radii)
    depths, integrals = (cut(values, lengths) for values in (branch.depths(together), branch.integrals(together)))
    attached = [radii[k] for k, force in enumerate(forces) if force.primitive.C0]
    if attached:  # (the integrals on the branch of attachment, of the spans whose C0 is not 0, in their order)
        found = iter(cut(attach.integrals(np.concatenate(attached)), [len(a) for a in attached]))
    out = []
    for force, a, depth, integral in zip(forces, radii, depths, integrals):
        value = force.primitive.combine(a, depth, integral, next(found) if force.primitive.C0 else None)
        out.append(force.force + force.G2 * (value - force.origin))
    return out


def _layer_closed_values(forces: list[ClosedForce], points: list[np.ndarray]) -> list[np.ndarray]:
    """``ClosedForce.__call__`` of a bonded layer's closed forms sharing their cells' series (each
    :class:`~.layer_closed_form.LayerPrimitive`'s ``own`` and ``anchors``, every span more than ``SCALAR_RADII``
    points, ``P`` not zero) at their points: the series of every row any of them reads at all their radii in one call
    (each row and radius a lane of Clenshaw's recurrence: the values a call per span gives), then each span's ``P`` of
    its own rows, the others ``0.0`` as :meth:`~.layer_closed_form.LayerPrimitive.__call__` leaves them."""
    radii = [np.reshape(np.asarray(where, dtype=float), -1) * force.scale for force, where in zip(forces, points)]
    lengths = [len(each) for each in radii]
    primitives = [force.primitive for force in forces]
    rows = tuple(sorted({row for primitive in primitives for row in primitive.rows}))
    series = [cut(values, lengths) for values in primitives[0].own.values(np.concatenate(radii), rows)]
    attached = [radii[k] for k, primitive in enumerate(primitives) if primitive.C0]
    if attached:  # (the anchors' J_d of the spans whose C0 is not 0, in their order)
        found = iter(cut(primitives[0].anchors.values(np.concatenate(attached), slice(4, 5))[0],
                         [len(a) for a in attached]))
    out = []
    for k, (force, primitive) in enumerate(zip(forces, primitives)):
        values = [0.0] * len(BranchIntegrals.NAMES)
        for index in primitive.rows:
            values[index] = series[rows.index(index)][k]
        value = primitive.combine(*values, next(found) if primitive.C0 else 0.0)
        out.append(force.force + force.G2 * (value - force.origin))
    return out
