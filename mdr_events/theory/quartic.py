"""The largest real root of the depressed quartic ``s⁴ + P s + Q = 0`` (``P < 0``) in closed form (Ferrari's
resolvent cubic, solved by its hyperbolic forms), polished by one Newton step: the radius of the paraboloid's
adhesive branch (9) at many depths at once, in ``s = sqrt(a)``, without the iteration of
:func:`mdr_events.theory.roots.positive_polynomial_root` (6–15 steps over the whole array).
"""

from __future__ import annotations

import numpy as np

__all__ = ["depressed_quartic_root"]

#: ``|δ|`` below this is taken as this (of the root's sign): the resolvent's hyperbolic forms divide by ``δ``; the
#: start moves by about ``TINY_SHIFT / 3`` of the scaled root's unit, which the Newton polish removes (its error
#: squared: far below an ulp).
TINY_SHIFT = 1e-30

#: The polish's step is taken where it is at most this share of the root: the start is accurate to ``√ε`` (about
#: 1.5e-8) or better, so a larger step is the polish's own failure where ``∂/∂s`` vanishes (a depth on the fold, the
#: value's rounding over a slope of rounding size); the start is kept there.
POLISH_SHARE = 1e-6
#: The scaled root ``t`` at the fold, ``4^{-1/3}`` (where ``t⁴ − t`` is least): the largest root is never below it.
FOLD_ROOT = 4.0 ** (-1.0 / 3.0)


def depressed_quartic_root(linear: float, constant) -> np.ndarray:
    r"""The largest real root of ``s⁴ + P s + Q = 0`` with ``P = linear < 0``, elementwise over ``Q = constant``.

    Scaled by ``σ = (−P)^{1/3}``, ``s = σ t`` solves ``t⁴ − t − δ = 0`` with ``δ = −Q / σ⁴``. Ferrari's resolvent
    ``m³ + δ m − 1/8 = 0`` has one real root for ``δ`` at or above the fold ``δ_f = −(27/256)^{1/3}`` (the depth of
    jump-off), positive, from its hyperbolic forms (no cancellation, unlike Cardano's sum):

    .. math::

       m = 2\sqrt{\delta/3}\,\sinh\Big(\tfrac13\operatorname{arsinh}\tfrac{3}{16\delta}\sqrt{3/\delta}\Big)
       \ (\delta > 0), \qquad
       m = 2\sqrt{-\delta/3}\,\cosh\Big(\tfrac13\operatorname{arcosh}\tfrac{3}{16|\delta|}\sqrt{3/|\delta|}\Big)
       \ (\delta < 0),

    and the largest root is ``t = (√(2m) + √(2/√(2m) − 2m)) / 2``. One Newton step on the quartic itself polishes
    ``s`` (a step above :data:`POLISH_SHARE` of ``s``, the fold's, is not taken), never below the fold's root
    ``σ 4^{-1/3}``. Below the fold the arcosh's argument is taken as 1 (the fold's double root): the caller says where a
    depth has no root.

    Parameters
    ----------
    linear : float
        ``P`` (negative).
    constant : array_like
        ``Q``.

    Returns
    -------
    numpy.ndarray
        The root ``s``, the shape of ``constant``.

    Notes
    -----
    Accurate to a few ulp where the root is simple; within ``√ε`` of the fold, where ``∂/∂s`` of the quartic
    vanishes, to the root's conditioning there (about ``√ε`` relative, as any method).
    """
    constant = np.asarray(constant, dtype=float)
    scale = np.cbrt(-linear)
    delta = -constant / scale**4
    delta = np.where(np.abs(delta) < TINY_SHIFT, TINY_SHIFT, delta)
    size = np.abs(delta)
    argument = 3.0 / (16.0 * size) * np.sqrt(3.0 / size)
    m = 2.0 * np.sqrt(size / 3.0) * _hyperbolic(delta > 0, argument)
    root = np.sqrt(2.0 * m)
    s = scale * 0.5 * (root + np.sqrt(np.maximum(2.0 / root - 2.0 * m, 0.0)))
    cube = s * s * s
    value = (cube + linear) * s + constant
    slope = 4.0 * cube + linear
    step = np.divide(value, slope, out=np.zeros(s.shape), where=slope != 0.0)
    step = np.where(np.abs(step) <= POLISH_SHARE * s, step, 0.0)  # (at the fold: the start as it is)
    return np.maximum(s - step, scale * FOLD_ROOT)


def _hyperbolic(positive: np.ndarray, argument: np.ndarray) -> np.ndarray:
    """The resolvent's hyperbolic factor: ``sinh(arsinh(arg)/3)`` where ``positive`` (``δ > 0``), ``cosh(arcosh(max(arg,
    1))/3)`` elsewhere, each form computed only where it is taken (element by element the values of both computed
    everywhere and chosen, at half the cost)."""
    if positive.all():
        return np.sinh(np.arcsinh(argument) / 3.0)
    with np.errstate(invalid="ignore"):
        if not positive.any():
            return np.cosh(np.arccosh(np.maximum(argument, 1.0)) / 3.0)
        factor = np.empty(argument.shape)
        factor[positive] = np.sinh(np.arcsinh(argument[positive]) / 3.0)
        negative = ~positive
        factor[negative] = np.cosh(np.arccosh(np.maximum(argument[negative], 1.0)) / 3.0)
    return factor
