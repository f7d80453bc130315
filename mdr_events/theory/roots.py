"""The one polynomial root finder of the closed forms: the unique positive root of a polynomial with one sign
change (the cubic of (18), the quartics of (9) and (21)) by a vectorised, safeguarded Newton iteration from an
upper bound (no Python loop over angles), with a path for Python floats (the continuum's hot loop) and a bracketed
fallback. Kept apart from :mod:`mdr_events.theory.analytic`, which evaluates the relations it solves.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.theory.blocks import BLOCK

__all__ = ["positive_polynomial_root"]

_EPS = np.finfo(float).eps
_FLOAT_EPS = float(_EPS)
#: Scalar types recognised at once for the Python-float path of :func:`positive_polynomial_root`
#: (``numpy.float64`` is a ``float``).
_SCALARS = (float, int)


def _ndim(value) -> int:
    """``np.ndim(value)``, read off an array's attribute without NumPy's function call (its cost, on every
    coefficient of every call, was a tenth of a small root's)."""
    return value.ndim if type(value) is np.ndarray else np.ndim(value)


def _every(flags) -> bool:
    """``bool(np.all(flags))``: a Python bool as it is, an array by its own method (no dispatch through NumPy's
    function)."""
    return flags if type(flags) is bool else bool(flags.all() if type(flags) is np.ndarray else np.all(flags))


def _horner(coefficients, x):
    """Value and derivative of the polynomial at ``x`` (Horner's scheme)."""
    value = coefficients[0] * x + coefficients[1]
    slope = coefficients[0]
    for coefficient in coefficients[2:]:
        slope = slope * x + value
        value = value * x + coefficient
    return value, slope


_ROOTS = {1: lambda v: v, 2: np.sqrt, 3: np.cbrt}
#: Elements per block of :func:`_upper_root_bound` and of Newton's steps: each block's temporaries stay small and
#: in cache (over 10⁵ elements at once, the page faults of fresh temporaries cost more than their arithmetic).
_BLOCK = BLOCK
#: Newton's steps after which :func:`_descend` looks for elements that still move (4-8 steps converge).
_LONG = 12
#: At most this many elements are iterated in Python floats (:func:`_finish_few`, :func:`_bracketed_floats`).
_FEW = 8


def _upper_root_bound(coeffs: list, out: np.ndarray | None = None) -> np.ndarray:
    """An upper bound of the positive roots of a monic polynomial, elementwise.

    For every positive term ``c_j s^j`` above which no coefficient is
    negative, ``p(s) > 0`` as soon as ``c_j s^j`` beats each of the ``m``
    lower terms ``m |c_i| s^i``, i.e. for
    ``s >= max_i (m |c_i| / c_j)^(1/(j-i))``; the smallest such bound is used.
    It is tight where one positive term dominates, e.g. ``P s²`` of (21) near
    α = 90°, where a bound on all root moduli (Fujiwara) would be orders of
    magnitude too large. Coefficients that are the scalar 0 are skipped. Over several blocks the bound is written into
    ``out`` where given (a C-contiguous array of the broadcast shape), else into a new array.
    """
    shape = np.broadcast_shapes(*[np.shape(cf) for cf in coeffs])
    size = math.prod(shape)
    if size <= _BLOCK:
        return _block_bound(coeffs)
    flat = [cf if _ndim(cf) == 0 else np.broadcast_to(cf, shape).reshape(-1) for cf in coeffs]
    bound = np.empty(shape) if out is None else out
    for first in range(0, size, _BLOCK):
        block = slice(first, first + _BLOCK)
        bound.reshape(-1)[block] = _block_bound([cf if cf.ndim == 0 else cf[block] for cf in flat])
    return bound


def _block_bound(coeffs: list) -> np.ndarray:
    """:func:`_upper_root_bound` of one block: a term's bound only where it is usable (its own coefficient
    positive, none negative above it), so none is computed where no element can use it."""
    present = [i for i, cf in enumerate(coeffs) if not (_ndim(cf) == 0 and cf == 0)]
    bound = np.inf
    nothing_negative_above = True
    above = []  # the coefficients above the term whose signs nothing_negative_above has not read yet
    for j in present[:-1]:
        cj = coeffs[j]
        lower = [i for i in present if i > j]
        if j == 0:
            usable = True
        elif _ndim(cj) == 0 and not cj > 0.0:  # (a scalar coefficient that is not positive: no element uses it)
            usable = False
        else:  # (the signs above read only where a term may be usable: no pass over a block for nothing)
            for coefficient in above:
                nothing_negative_above = nothing_negative_above & (coefficient >= 0.0)
            above = []
            usable = nothing_negative_above & (cj > 0.0)
        every = j == 0 or _every(usable)
        if every or bool(np.any(usable)):
            candidate = _term_bound(coeffs, j, lower, positive=j > 0 or _every(cj > 0.0))
            if j == 0:
                bound = candidate
            elif every:
                bound = np.minimum(bound, candidate)
            else:  # (np.where's own loop is ten times slower)
                bound = np.array(np.broadcast_to(bound, np.broadcast_shapes(np.shape(bound), usable.shape)))
                np.minimum(bound, candidate, out=bound, where=usable)
        if j != present[-2]:
            above.append(cj)
    return bound


def _term_bound(coeffs: list, j: int, lower: list[int], positive: bool):
    """``max(0, max_i (m |c_i| / c_j)^(1/(j-i)))`` over the ``m`` lower terms ``i`` of the term ``j``.

    Where ``c_j > 0`` (``positive``: everywhere it is used) every ratio is ``+0`` or more, so the first
    maximum with 0 is skipped, as is a division by a ``c_j`` that is the scalar 1: both are exact.
    """
    cj = coeffs[j]
    m = float(len(lower))
    unit = _ndim(cj) == 0 and cj == 1.0
    candidate = None
    with np.errstate(divide="ignore", invalid="ignore"):
        for i in lower:
            ratio = m * np.abs(coeffs[i])
            if not unit:
                ratio = ratio / cj
            root = _ROOTS.get(i - j, lambda v, e=1.0 / (i - j): v**e)(ratio)
            candidate = root if candidate is None and positive else np.maximum(
                0.0 if candidate is None else candidate, root)
    return candidate


def positive_polynomial_root(coefficients, lower=0.0, max_iterations: int = 100, rtol: float = 4 * _EPS,
                             out: np.ndarray | None = None):
    """Largest positive root of monic polynomials, vectorised over their coefficients.

    Parameters
    ----------
    coefficients : sequence of array_like
        ``[1, c_{n-1}, ..., c_0]`` (highest power first), each broadcastable
        to the common shape of the problem.
    lower : array_like
        A point with ``p(lower) <= 0``: the root sought is the largest root,
        which lies above it (0 where ``c_0 <= 0``; the minimum of ``p`` for a
        polynomial with two positive roots).
    max_iterations : int
        Safety bound; convergence takes 4–8 iterations in practice.
    rtol : float
        Relative step at which the iteration stops (default 4 ulp).
    out : numpy.ndarray, optional
        A C-contiguous float array of the problem's shape that the iteration runs in and the root is returned in
        (arrays only; for 10⁵ elements a fresh array costs its page faults); default a new array.

    Returns
    -------
    numpy.ndarray or float
        The root, converged to ``rtol``; a ``float`` when every coefficient and
        ``lower`` are scalars.

    Notes
    -----
    Newton's method starts from an upper bound of the roots
    (:func:`_upper_root_bound`). Where ``p`` is convex between the root and
    the start (true for every polynomial of this model), the iterates descend
    monotonically onto the largest root. An element whose iterate ever falls
    where ``p < 0`` (an overshoot, so not convex there) is solved again with
    a bracketed Newton–bisection iteration on ``[lower, bound]``.

    Scalars take the same iteration in Python floats (:func:`_scalar_root`), about
    50 times faster than NumPy on one element: the continuum method calls it from
    its right-hand side.
    """
    if len(coefficients) < 2:
        raise ValueError("positive_polynomial_root needs a polynomial of degree >= 1")
    if isinstance(lower, _SCALARS) and all(isinstance(cf, _SCALARS) for cf in coefficients) \
            or np.ndim(lower) == 0 and all(np.ndim(cf) == 0 for cf in coefficients):
        return _scalar_root([float(cf) for cf in coefficients], float(lower), max_iterations, rtol)
    coeffs = [np.asarray(cf, dtype=float) for cf in coefficients]
    shape = np.broadcast_shapes(*[cf.shape for cf in coeffs], np.shape(lower))
    lower = np.broadcast_to(np.asarray(lower, dtype=float), shape)
    if out is not None and not (out.shape == shape and out.flags.c_contiguous and out.dtype == float):
        raise ValueError(f"out of shape {out.shape} is not allowed; allowed: a C-contiguous float array of the "
                         f"problem's shape {shape}")
    x = _start(coeffs, lower, out)
    overshoot = _descend(coeffs, x, max_iterations, rtol)
    redo = overshoot | ~np.isfinite(x)
    if redo.any():  # from the same start, computed again for these elements alone (scalars kept scalars)
        start = _start([cf if cf.ndim == 0 else np.broadcast_to(cf, shape)[redo] for cf in coeffs], lower[redo])
        x[redo] = _bracketed_root([np.broadcast_to(cf, shape)[redo] for cf in coeffs], lower[redo], start,
                                  max_iterations)
    return x


def _start(coeffs: list, lower: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """Newton's start: the bound of :func:`_upper_root_bound`, not below ``lower``, raised by 8 ulp (a new array of
    the shape of ``lower``, or ``out``, which the iteration takes over)."""
    bound = _upper_root_bound(coeffs, out)
    owned = isinstance(bound, np.ndarray) and bound.shape == lower.shape and (bound.flags.owndata or bound is out)
    start = np.maximum(bound, lower, out=out if out is not None else bound if owned else None)  # (in the bound's
    # own array where it has one)
    start *= 1.0 + 8 * _EPS
    return start


def _horner_into(coeffs: list, x: np.ndarray, value: np.ndarray, slope: np.ndarray, zeros: int = 0) -> None:
    """:func:`_horner` into the buffers ``value`` and ``slope``, in place.

    A leading coefficient that is the scalar 1 (a monic polynomial) skips the products by it, which are exact, and so
    do the additions of the ``zeros`` coefficients after it that are the scalar 0 (:func:`_leading_zeros`): ``x + 0``
    is ``x``, and ``x^k + 0`` is ``x^k`` (an iterate is never -0: ``x − d`` gives +0). The values are those of
    :func:`_horner`, bit for bit, in fewer passes over the arrays.
    """
    rest = coeffs[2:]
    if zeros:
        np.multiply(x, x, out=value)
        np.add(x, x, out=slope)
        for _ in range(zeros - 1):
            slope *= x
            slope += value
            value *= x
        rest = coeffs[zeros + 1:]
        value += rest[0]
        rest = rest[1:]
    elif _ndim(coeffs[0]) == 0 and coeffs[0] == 1.0:
        np.add(x, coeffs[1], out=value)  # x·1 + c1
        if not rest:
            slope[...] = 1.0
            return
        np.add(x, value, out=slope)  # 1·x + value
        value *= x
        value += rest[0]
        rest = rest[1:]
    else:
        np.multiply(x, coeffs[0], out=value)
        value += coeffs[1]
        slope[...] = coeffs[0]
    for coefficient in rest:
        slope *= x
        slope += value
        value *= x
        value += coefficient


def _leading_zeros(coeffs: list) -> int:
    """How many coefficients after a leading scalar 1 are the scalar 0, the last one not counted (0: none, or not
    monic): the additions :func:`_horner_into` skips."""
    if not (_ndim(coeffs[0]) == 0 and coeffs[0] == 1.0):
        return 0
    count = 0
    while count + 2 < len(coeffs) and _ndim(coeffs[count + 1]) == 0 and coeffs[count + 1] == 0.0:
        count += 1
    return count


def _descend(coeffs: list, x: np.ndarray, max_iterations: int, rtol: float) -> np.ndarray:
    """Newton's iteration on ``x`` in place, every element stepping until all have converged to ``rtol``;
    returns where an element ever stepped upwards by more than ``rtol`` of itself (``p < 0`` beyond rounding,
    an overshoot).

    Each step goes over blocks of :data:`_BLOCK` elements, whose work arrays are allocated once and stay in
    cache (for large arrays allocation, not arithmetic, is the cost); the stopping rule is read block by block
    until one fails it. An iteration that has not stopped after :data:`_LONG` steps (an element at a fold, where
    Newton wanders for ever) is handed to :func:`_finish_few` once the elements still moving are few.
    """
    flat = x.reshape(-1)
    broadcast = [cf if cf.ndim == 0 else np.broadcast_to(cf, x.shape).reshape(-1) for cf in coeffs]
    if flat.size <= _FEW:  # (a few elements: the same steps in Python floats, without NumPy's cost per call)
        return _descend_floats(broadcast, flat, max_iterations, float(rtol)).reshape(x.shape)
    size = min(flat.size, _BLOCK)
    value, slope, step = (np.empty(size) for _ in range(3))
    flags = np.empty(size, dtype=bool)
    overshoot = np.zeros(flat.size, dtype=bool)
    blocks = []  # each block's iterate, coefficients, work arrays and overshoot flags (views)
    for first in range(0, flat.size, _BLOCK):
        block = slice(first, first + _BLOCK)
        n = flat[block].size
        blocks.append((flat[block], [cf if cf.ndim == 0 else cf[block] for cf in broadcast], value[:n], slope[:n],
                       step[:n], flags[:n], overshoot[block]))
    history = []  # (one block only, after _LONG steps) the last iterates and which elements' steps were within rtol
    zeros = _leading_zeros(coeffs)
    for iteration in range(max_iterations):
        converged = True
        for x_block, coefficients, v, s, d, f, upward in blocks:
            _horner_into(coefficients, x_block, v, s, zeros)
            np.divide(v, s, out=d)
            x_block -= d
            falls = np.fmin.reduce(d, initial=np.inf) < 0.0  # (an upward step, d < -rtol |x| <= 0, needs a negative one)
            if not (converged or falls):  # (the threshold serves the stopping rule, which a block before has failed,
                continue  # and the upward steps: two passes saved on most blocks of most steps)
            threshold = v  # rtol |x|, in the buffer of the value
            np.abs(x_block, out=threshold)
            threshold *= rtol
            if falls:
                upward |= np.less(d, np.negative(threshold, out=s), out=f)  # (-(rtol |x|) = (-rtol) |x| exactly)
            converged = converged and _within(d, threshold, s, f)
        if converged:
            break
        if iteration >= _LONG and len(blocks) == 1:
            history = [*history[-2:], (flat.copy(), f.copy())]
            if len(history) == 3 and _finish_few(broadcast, flat, overshoot, history, iteration, max_iterations,
                                                 rtol):
                break
    return overshoot.reshape(x.shape)


def _descend_floats(coeffs: list, x: np.ndarray, max_iterations: int, rtol: float) -> np.ndarray:
    """:func:`_descend` of at most :data:`_FEW` elements (``x`` flat, ``coeffs`` scalars or flat arrays), in Python
    floats: each step the same operations as the arrays' (:func:`_horner`, NumPy's division, the threshold
    ``rtol |x|`` of the new iterate), and the same stopping rule over all elements, so the same values; a
    one-element array near a fold (14 steps) took 0.18 ms in NumPy calls, 0.01 ms so. Returns the overshoot flags."""
    values = x.tolist()
    polynomials = [[float(cf) if np.ndim(cf) == 0 else float(cf[j]) for cf in coeffs] for j in range(len(values))]
    upward = [False] * len(values)
    for _ in range(max_iterations):
        converged = True
        for k, polynomial in enumerate(polynomials):
            value, slope = _horner(polynomial, values[k])
            step = _divide(value, slope)
            values[k] -= step
            below = abs(values[k]) * -rtol
            upward[k] = upward[k] or step < below
            converged = converged and abs(step) <= -below
        if converged:
            break
    x[:] = values
    return np.array(upward, dtype=bool)


def _finish_few(coeffs: list, x: np.ndarray, overshoot: np.ndarray, history: list, iteration: int,
                max_iterations: int, rtol: float) -> bool:
    """The rest of :func:`_descend`'s steps after step ``iteration``, in Python floats, where few elements still move.

    An element whose iterate after this step equals that of one or two steps before is periodic (Newton's step is
    a function of the iterate alone): its later iterates, steps and stopping tests repeat those of the last two
    steps, with period 1 or 2. If at most :data:`_FEW` elements are not, they alone take the remaining steps, as
    floats (the same operations, hence the same values, as the arrays'), and the stopping rule is read as before
    over all elements; ``x`` and ``overshoot`` are then set to what the whole iteration would have left (bit for
    bit) and ``True`` is returned. Otherwise nothing is changed and ``False`` is returned.
    """
    (older, _), (old, within_old), (new, within_new) = history
    same_as_old = new == old
    periodic = same_as_old | (new == older)
    moving = np.flatnonzero(~periodic)
    if moving.size > _FEW:
        return False
    # the periodic elements' stopping tests at later steps: those of this step (even distance), of the last one
    # (odd; for period 1, this step's again)
    fixed = periodic.copy()
    fixed[moving] = False
    ready = (bool(np.all(within_new[fixed])), bool(np.all(np.where(same_as_old, within_new, within_old)[fixed])))
    values = x[moving].tolist()
    upward = overshoot[moving].tolist()
    polynomials = [[float(cf) if np.ndim(cf) == 0 else float(cf[j]) for cf in coeffs] for j in moving.tolist()]
    last = iteration
    for step_index in range(iteration + 1, max_iterations):
        last = step_index
        converged = ready[(step_index - iteration) % 2]
        for k, polynomial in enumerate(polynomials):
            value, slope = _horner(polynomial, values[k])
            step = _divide(value, slope)
            values[k] -= step
            below = abs(values[k]) * -rtol
            upward[k] = upward[k] or step < below
            converged = converged and abs(step) <= -below
        if converged:
            break
    # each periodic element's iterate after the last step: this step's at an even distance, the last one's at an odd
    if (last - iteration) % 2:
        x[fixed & ~same_as_old] = old[fixed & ~same_as_old]
    x[moving] = values
    overshoot[moving] = upward
    return True


def _divide(numerator: float, denominator: float) -> float:
    """``numerator / denominator`` of two floats as NumPy divides (``±inf`` or ``nan`` by zero, no exception)."""
    if denominator != 0.0 or math.isnan(denominator):
        return numerator / denominator
    if numerator == 0.0 or math.isnan(numerator):
        return math.nan
    return math.copysign(math.inf, numerator) * math.copysign(1.0, denominator)


def _within(step: np.ndarray, threshold: np.ndarray, spare: np.ndarray, flags: np.ndarray) -> bool:
    """Whether every ``|step| <= threshold``, computed in the buffers ``spare`` and ``flags``."""
    np.abs(step, out=spare)
    return bool(np.less_equal(spare, threshold, out=flags).all())


def _scalar_root(coeffs: list[float], lower: float, max_iterations: int, rtol: float) -> float:
    """:func:`positive_polynomial_root` for one polynomial, in Python floats.

    Newton's method descends from the bound of :func:`_upper_root_bound` (here for
    floats, :func:`_scalar_upper_root_bound`) and never below ``lower``; an iterate
    where ``p < 0`` (an overshoot) hands over to the bracketed iteration on
    ``[lower, bound]``.
    """
    rtol = float(rtol)  # Python floats throughout: NumPy scalars would make every step ten times dearer
    start = max(_scalar_upper_root_bound(coeffs), lower) * (1.0 + 8 * _FLOAT_EPS)
    x = start
    for _ in range(max_iterations):
        value, slope = _horner(coeffs, x)
        step = value / slope if slope > 0.0 else -math.inf
        if step < -rtol * abs(x):  # an upward step: p < 0 beyond rounding (an overshoot), or a fold
            root = _bracketed_root([np.array([cf]) for cf in coeffs], np.array([lower]), np.array([start]),
                                   max_iterations)
            return float(root[0])
        x_new = max(x - step, lower)
        if abs(x_new - x) <= rtol * abs(x_new):
            return x_new
        x = x_new
    return x


def _scalar_upper_root_bound(coeffs: list[float]) -> float:
    """:func:`_upper_root_bound` of one polynomial, in floats (the same rule, term by term)."""
    present = [i for i, cf in enumerate(coeffs) if cf != 0.0]
    bound = math.inf
    nothing_negative_above = True
    for j in present[:-1]:
        cj = coeffs[j]
        lower = [i for i in present if i > j]
        if cj > 0.0 and (nothing_negative_above or j == 0):
            candidate = max((len(lower) * abs(coeffs[i]) / cj) ** (1.0 / (i - j)) for i in lower)
            bound = candidate if j == 0 else min(bound, candidate)
        nothing_negative_above = nothing_negative_above and cj >= 0.0
    return bound


def _bracketed_root(coeffs, lo, hi, max_iterations):
    """Newton steps kept inside ``[lo, hi]`` (``p(lo) <= 0 < p(hi)``), bisection otherwise; in Python floats for
    at most :data:`_FEW` elements (:func:`_bracketed_floats`: the same values, without NumPy's cost per call)."""
    if lo.size <= _FEW:
        return np.array(_bracketed_floats([np.broadcast_to(cf, lo.shape).tolist() for cf in coeffs], lo.tolist(),
                                          hi.tolist(), max_iterations))
    lo, hi = lo.copy(), hi.copy()
    x = hi.copy()
    for _ in range(4 * max_iterations):
        value, slope = _horner(coeffs, x)
        below = value <= 0.0
        lo = np.where(below, x, lo)
        hi = np.where(below, hi, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            candidate = x - value / slope
        inside = (candidate >= lo) & (candidate <= hi)
        candidate = np.where(inside, candidate, 0.5 * (lo + hi))
        # converged; or the bracket has closed, or p(x) is zero to its evaluation error (near a
        # double root, e.g. at the pull-off fold, Newton is slow and the root is only this accurate)
        noise, _ = _horner([np.abs(cf) for cf in coeffs], np.abs(x))
        done = np.all((np.abs(candidate - x) <= 4 * _EPS * np.abs(candidate)) | (hi - lo <= 4 * _EPS * np.abs(hi))
                      | (np.abs(value) <= 8 * _EPS * noise))
        x = candidate
        if done:
            break
    return x


def _bracketed_floats(coeffs: list[list[float]], lo: list[float], hi: list[float], max_iterations: int) -> list[float]:
    """:func:`_bracketed_root` of a few polynomials (``coeffs[i][j]``: coefficient ``i`` of polynomial ``j``) in
    Python floats: the same operations element by element, so the same values, and the same stopping rule over
    all of them."""
    eps = _FLOAT_EPS
    polynomials = [list(column) for column in zip(*coeffs)]
    magnitudes = [[abs(cf) for cf in polynomial] for polynomial in polynomials]
    x = list(hi)
    for _ in range(4 * max_iterations):
        done = True
        for j, polynomial in enumerate(polynomials):
            xj = x[j]
            value, slope = _horner(polynomial, xj)
            if value <= 0.0:
                lo[j] = xj
            else:
                hi[j] = xj
            candidate = xj - _divide(value, slope)
            if not lo[j] <= candidate <= hi[j]:
                candidate = 0.5 * (lo[j] + hi[j])
            if done:
                noise, _ = _horner(magnitudes[j], abs(xj))
                done = (abs(candidate - xj) <= 4 * eps * abs(candidate) or hi[j] - lo[j] <= 4 * eps * abs(hi[j])
                        or abs(value) <= 8 * eps * noise)
            x[j] = candidate
        if done:
            break
    return x


# ----------------------------------------------------------------------------
# normal contact, eqs. (7)-(10), (16)
