"""Convergence of the discrete spring model to exact references (Δx, dt → 0).

The references are exact for scenario A:

- ``F_N,min = −(3/2) π Δγ1 R`` (the minimum of (10) on the ``Δγ1`` branch,
  reached while the radius shrinks, as long as the pinned radius exceeds the
  pull-off radius);
- ``A_max = π a(d_max)²`` with ``a`` on the ``Δγ0`` branch of (9);
- ``F_x,max``, reached at ``d_max``: the spring attached at radius ``ξ``
  (after the jump-in radius ``a0``, at which all central springs attach at
  ``x = 0``) carries ``x1 − X(ξ)`` with ``X(ξ) = d(ξ)/tan α`` from (9) and
  (14), capped at ``ū(a1)``; during indentation of scenario A the slip zone
  ``[0, c]`` only grows (``ū`` grows ever slower than ``x``), so
  ``F_x = 2 G* [c ū(a1) + ∫_c^{a1} (x1 − X(ξ)) dξ]`` with ``X(c) = x1 − ū(a1)``.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import integrate, optimize

from . import analytic
from .parameters import Parameters
from .paths import Path
from .discrete import run_discrete

__all__ = ["exact_references_A", "discrete_errors", "discrete_minus_continuum", "history_differences",
           "observed_orders"]

#: Quantities compared over the whole history by :func:`discrete_minus_continuum`.
HISTORY_QUANTITIES = ("normal_force", "tangential_force", "contact_area")


def exact_references_A(params: Parameters, alpha: float) -> dict[str, float]:
    """Exact ``F_N,min``, ``A_max`` and ``F_x,max`` of scenario A at angle α (degrees)."""
    p = params
    tan = math.tan(math.radians(alpha))
    a1 = float(analytic.jkr_contact_radius(p.d_max, p, p.dgamma0))
    a0 = analytic.jump_in_radius(p, p.dgamma0) if p.dgamma0 > 0 else 0.0
    x1 = p.d_max / tan
    cap = float(analytic.critical_shift(a1, p))

    def attach_position(xi):
        return max(float(analytic.jkr_depth(xi, p, p.dgamma0)), 0.0) / tan if xi > a0 else 0.0

    if x1 <= cap:  # no slip during indentation
        c = 0.0
    elif x1 - attach_position(a1) <= cap:
        c = optimize.brentq(lambda xi: attach_position(xi) - (x1 - cap), max(a0, 0.0), a1, xtol=1e-18, rtol=1e-15)
    else:
        c = a1
    stick, _ = integrate.quad(lambda xi: x1 - attach_position(xi), c, a1, epsabs=0, epsrel=1e-12, limit=200)
    tangential = 2.0 * p.G_star * (c * cap + stick)
    return {
        "normal_force_min": analytic.pull_off_force(p, p.dgamma1),
        "contact_area_max": math.pi * a1**2,
        "tangential_force_max": tangential,
    }


def discrete_errors(params: Parameters, alpha: float, spacings, steps_per_spacing: float) -> dict[str, np.ndarray]:
    """Relative errors of the discrete model against :func:`exact_references_A`.

    ``dt`` is refined with ``Δx``: ``dt = steps_per_spacing · Δx / v`` (the
    indenter moves a fixed multiple of Δx per step).
    """
    exact = exact_references_A(params, alpha)
    path = Path.scenario_A(alpha, params)
    errors = {key: [] for key in exact}
    for dx in spacings:
        raw = run_discrete(params, [path], dx, steps_per_spacing * dx / params.v)
        measured = {
            "normal_force_min": np.nanmin(raw["normal_force"]),
            "contact_area_max": math.pi * np.nanmax(raw["contact_radius"]) ** 2,
            "tangential_force_max": np.nanmax(raw["tangential_force"]),
        }
        for key in exact:
            errors[key].append(abs(measured[key] - exact[key]) / abs(exact[key]))
    return {key: np.array(values) for key, values in errors.items()}


def history_differences(discrete, continuum) -> dict[str, float]:
    """``max_t |discrete − continuum| / max_t |continuum|`` of ``F_N``, ``F_x`` and ``A``, per angle.

    ``continuum`` must be evaluated at the discrete model's times (``t=``).
    Left out, and counted in ``"samples_left_out"``:

    - samples where either method has ended (after pull-off);
    - samples at which one method is in contact and the other not: the
      jump-in and the jump-off are discontinuities in time, and the discrete
      model meets them up to one step apart (its first spring sits at
      ``Δx/2``, its radius moves in steps of ``Δx``), so that a pointwise
      difference there is the whole jump however fine ``Δx``;
    - the sample ending a time step that straddles a path corner: the
      discrete model moves straight from one sample to the next and so cuts
      the corner for that one step (where ``Δγ1 < Δγ0`` the radius jumps at
      the corner, and the cut shows as the whole jump).

    Returns
    -------
    dict
        Quantity name (:data:`HISTORY_QUANTITIES`) → array over ``alpha`` of
        relative differences; ``"samples_left_out"`` → array of counts.
    """
    times = discrete["time"].values
    out = {name: [] for name in (*HISTORY_QUANTITIES, "samples_left_out")}
    for alpha in discrete["alpha"].values:
        d, c = discrete.sel(alpha=alpha), continuum.sel(alpha=alpha)
        area_d, area_c = d["contact_area"].values, c["contact_area"].values
        finite = np.isfinite(area_d) & np.isfinite(area_c)
        excluded = finite & ((area_d > 0) != (area_c > 0))
        corners = c["event_time"].values[c["event_kind"].values == "corner"]
        straddling = np.searchsorted(times, corners, side="left")  # first sample at or after the corner
        straddling = straddling[(straddling < len(times)) & (times[np.minimum(straddling, len(times) - 1)] > corners)]
        excluded[straddling] |= finite[straddling]
        compared = finite & ~excluded
        out["samples_left_out"].append(int(np.count_nonzero(excluded)))
        for name in HISTORY_QUANTITIES:
            a, b = d[name].values[compared], c[name].values[compared]
            scale = np.max(np.abs(b)) if b.size else 0.0
            out[name].append(np.max(np.abs(a - b)) / scale if scale > 0 else float(np.max(np.abs(a), initial=0.0)))
    return {name: np.array(values) for name, values in out.items()}


def discrete_minus_continuum(params: Parameters, scenario, alpha: float, spacings,
                             steps_per_spacing: float = 0.5) -> dict[str, np.ndarray]:
    """:func:`history_differences` for one angle at several spacings.

    For each spacing ``Δx`` (with ``dt = steps_per_spacing · Δx / v``) the
    discrete model runs and the continuum is evaluated at the same times.

    Returns
    -------
    dict
        Quantity name (:data:`HISTORY_QUANTITIES`) → relative differences,
        one per spacing; ``"samples_left_out"`` → counts, one per spacing.
    """
    from .simulate import simulate

    out = {name: [] for name in (*HISTORY_QUANTITIES, "samples_left_out")}
    for dx in spacings:
        discrete = simulate(params, scenario, alpha=[alpha], dx=dx, dt=steps_per_spacing * dx / params.v)
        continuum = simulate(params, scenario, alpha=[alpha], method="continuum", t=discrete["time"].values)
        for name, values in history_differences(discrete, continuum).items():
            out[name].append(values[0])
    return {name: np.array(values) for name, values in out.items()}


def observed_orders(spacings, errors: np.ndarray) -> np.ndarray:
    """Observed orders ``log(e_i/e_{i+1}) / log(Δx_i/Δx_{i+1})`` between successive spacings."""
    spacings = np.asarray(spacings, dtype=float)
    errors = np.asarray(errors, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.log(errors[:-1] / errors[1:]) / np.log(spacings[:-1] / spacings[1:])
