r"""The normal–tangential coupling of a bonded layer's top that the decoupled tangential punch neglects, and its
bound on the tangential stiffness.

Part of :mod:`mdr_events.theory.layer_tangential`, which documents the problem and re-exports the public names.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.limits import DEFAULT_LIMITS
from mdr_events.theory.layer.compliance import _finite_reals
from mdr_events.theory.layer.tangential_compliance import _nu
from mdr_events.validation import check_count

__all__ = ["coupling_ratio", "coupling_bound"]

#: ``t`` beyond which :func:`coupling_ratio` takes its value at this ``t`` (equal to the limit to round-off).
_T_FAR = 30.0
#: The fewest points of :func:`coupling_bound`'s scan (its largest value with a neighbour each side), and the memory
#: one takes (``t`` and :func:`coupling_ratio`'s temporaries, counted against :class:`~mdr_events.Limits`).
_FEWEST_POINTS = 3
_BYTES_PER_POINT = 128.0


def _sinhc_minus_one(x: np.ndarray) -> np.ndarray:
    """``sinh(x)/x − 1`` without cancellation (its series below 0.5)."""
    small = np.abs(x) < 0.5
    safe = np.where(small, 1.0, x)
    series = sum(x ** (2 * k) / math.factorial(2 * k + 1) for k in range(1, 9))
    return np.where(small, series, np.sinh(safe) / safe - 1.0)


def coupling_ratio(t, nu: float) -> np.ndarray:
    r"""The normal–tangential coupling of the bonded layer's top, ``m = |C_zx| / sqrt(C_zz C_xx)`` at ``ξh = t``.

    .. math:: m(t) = \frac{|t^2 - \kappa(1-2\nu)\sinh^2 t|}
              {(1-\nu)\sqrt{(\kappa\sinh 2t)^2 - 4t^2}}, \qquad m(\infty) = \frac{1-2\nu}{2(1-\nu)}

    (``C_zz``, ``C_xx`` the normal and longitudinal compliances, ``C_zx`` the normal displacement per shear traction,
    :mod:`mdr_events.theory.layer_tangential_symbolic`). 0 on the half-space at ``ν = 0.5``; on a bonded layer at
    ``ν = 0.5`` it is ``2t²/sqrt(sinh² 2t − 4t²)``, ``→ √3/2`` as ``t → 0``.

    Parameters
    ----------
    t : float or array_like
        ``ξ h ≥ 0``.
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.

    Returns
    -------
    numpy.ndarray
        ``m(t)`` in ``[0, 1)``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``, ``t`` negative or not finite (``TypeError``: not real numbers).
    """
    nu = _nu(nu)
    t = np.minimum(_finite_reals("t", t, "finite numbers >= 0 (ξh)", lambda value: value >= 0.0), _T_FAR)
    kappa = 3.0 - 4.0 * nu
    excess = _sinhc_minus_one(2.0 * t)  # S − 1, S = sinh 2t/(2t)
    root = np.sqrt((kappa * excess + (kappa - 1.0)) * (kappa * (1.0 + excess) + 1.0))  # sqrt(κ²S² − 1)
    sinh_over_t = 1.0 + _sinhc_minus_one(t)
    numerator = np.abs(1.0 - kappa * (1.0 - 2.0 * nu) * sinh_over_t**2)  # (t² − κ(1−2ν) sinh² t)/t²
    with np.errstate(invalid="ignore", divide="ignore"):
        value = t * numerator / (2.0 * (1.0 - nu) * root)
    limit_zero = math.sqrt(3.0) / 2.0 if nu == 0.5 else 0.0
    return np.where(t == 0.0, limit_zero, value)


def coupling_bound(nu: float, points: int = 2001) -> float:
    r"""The largest coupling ``m_max = sup_t m(t)`` of :func:`coupling_ratio`, and so the bound of the decoupling.

    .. math:: K_t \le K_{t,\mathrm{coupled}} \le \frac{K_t}{1 - m_\max^2}

    (the complementary energy minimised over the shear traction alone and over shear and pressure: per Fourier
    mode the pressure lowers the longitudinal compliance by at most the factor ``1 − m²``). On the half-space
    ``m ≡ (1 − 2ν)/(2(1 − ν))``.

    Parameters
    ----------
    nu : float
        Poisson's ratio, in ``[0, 0.5]``.
    points : int, default 2001
        Points of the scan of ``t`` in ``[0, 30]`` (refined by the golden section around the largest).

    Returns
    -------
    float
        ``m_max``.

    Raises
    ------
    ValueError
        ``nu`` outside ``[0, 0.5]``, ``points`` below 3 (``TypeError``: not an integer), or beyond the default
        :class:`~mdr_events.Limits` (``ResourceLimitError``).
    """
    nu = _nu(nu)
    points = check_count("points", points, _FEWEST_POINTS)
    DEFAULT_LIMITS.check(f"the coupling's scan of {points} points", samples=float(points),
                         memory=_BYTES_PER_POINT * points)
    grid = np.linspace(0.0, _T_FAR, points)
    values = coupling_ratio(grid, nu)
    best = int(np.argmax(values))
    low, high = grid[max(best - 1, 0)], grid[min(best + 1, grid.size - 1)]
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(80):
        left, right = high - ratio * (high - low), low + ratio * (high - low)
        if coupling_ratio(left, nu) >= coupling_ratio(right, nu):
            high = right
        else:
            low = left
    return float(max(values[best], coupling_ratio((low + high) / 2.0, nu), values[0], values[-1]))
