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

from mdr_events.io.agreement import ROUND_OFF
from mdr_events.theory import analytic
from mdr_events.parameters import Parameters
from mdr_events.models.paths import Path
from mdr_events.models.continuum import NEGLIGIBLE_SHARE, evaluate, solve_path
from mdr_events.models.continuum.extrema import solution_extrema
from mdr_events.models.discrete import run_discrete
from mdr_events.models.motion import case_dimension
from mdr_events.models.simulate import simulate

__all__ = ["exact_references_A", "discrete_errors", "discrete_minus_continuum", "history_differences",
           "compared_samples", "first_order_error_bound", "slip_onset_delay_bound", "observed_orders"]

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


#: The extrema :func:`discrete_errors` compares.
COMPARED_EXTREMA = ("normal_force_min", "contact_area_max", "tangential_force_max")


def discrete_errors(params: Parameters, path: Path | float, spacings, steps_per_spacing: float) -> dict[str, np.ndarray]:
    """Relative errors of the discrete model's ``F_N,min``, ``A_max`` and ``F_x,max`` against the exact
    extrema of the continuum solution on the same path
    (:func:`mdr_events.models.continuum.extrema.solution_extrema`: any scenario or path; for scenario A
    they equal the closed forms of :func:`exact_references_A`).

    ``path``: a :class:`~mdr_events.models.paths.Path`, or an angle (degrees) of scenario A. ``dt`` is
    refined with ``Δx``: ``dt = steps_per_spacing · Δx / v`` (the indenter moves a fixed multiple of Δx
    per step).
    """
    path = path if isinstance(path, Path) else Path.scenario_A(path, params)
    extrema = solution_extrema(solve_path(params, path))
    exact = {key: extrema[key] for key in COMPARED_EXTREMA}
    errors = {key: [] for key in exact}
    for dx in spacings:
        raw = run_discrete(params, [path], dx, steps_per_spacing * dx / path.speed)
        measured = {
            "normal_force_min": np.nanmin(raw["normal_force"]),
            "contact_area_max": math.pi * np.nanmax(raw["contact_radius"]) ** 2,
            "tangential_force_max": np.nanmax(raw["tangential_force"]),
        }
        for key in exact:
            errors[key].append(abs(measured[key] - exact[key]) / abs(exact[key]))
    return {key: np.array(values) for key, values in errors.items()}


def history_differences(discrete, continuum) -> dict[str, float]:
    """``max_t |discrete − continuum| / max_t |continuum|`` of ``F_N``, ``F_x`` and ``A``, per case.

    The cases lie along ``alpha`` (a scenario) or ``case`` (custom paths), the same in both datasets.

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
        Quantity name (:data:`HISTORY_QUANTITIES`) → array over the cases of
        relative differences; ``"samples_left_out"`` → array of counts.
    """
    compared = compared_samples(discrete, continuum)
    dimension = case_dimension(discrete)
    out = {name: [] for name in (*HISTORY_QUANTITIES, "samples_left_out")}
    for row, case in enumerate(discrete[dimension].values):
        d, c = discrete.sel({dimension: case}), continuum.sel({dimension: case})
        finite = np.isfinite(d["contact_area"].values) & np.isfinite(c["contact_area"].values)
        out["samples_left_out"].append(int(np.count_nonzero(finite & ~compared[row])))
        for name in HISTORY_QUANTITIES:
            a, b = d[name].values[compared[row]], c[name].values[compared[row]]
            scale = np.max(np.abs(b)) if b.size else 0.0
            out[name].append(np.max(np.abs(a - b)) / scale if scale > 0 else float(np.max(np.abs(a), initial=0.0)))
    return {name: np.array(values) for name, values in out.items()}


def compared_samples(discrete, continuum) -> np.ndarray:
    """The samples :func:`history_differences` compares, shape ``(n_cases, n_time)``.

    A sample is compared where both methods are still running and it is not
    left out (one method in contact and the other not; the sample ending a
    time step that straddles a path corner): see :func:`history_differences`.
    """
    times = discrete["time"].values
    dimension = case_dimension(discrete)
    rows = []
    for case in discrete[dimension].values:
        d, c = discrete.sel({dimension: case}), continuum.sel({dimension: case})
        area_d, area_c = d["contact_area"].values, c["contact_area"].values
        finite = np.isfinite(area_d) & np.isfinite(area_c)
        excluded = finite & ((area_d > 0) != (area_c > 0))
        corners = c["event_time"].values[c["event_kind"].values == "corner"]
        # a sample within the times' round-off of a corner is at it (no step straddles that corner): another CPU's
        # rounding must not decide whether a sample lies just after a corner that falls on the grid
        tie = ROUND_OFF * float(np.max(np.abs(times), initial=0.0))
        first = np.searchsorted(times, corners - tie, side="left")  # first sample not before the corner
        inside = first < len(times)
        first, corners = first[inside], corners[inside]
        straddling = first[times[first] > corners + tie]
        excluded[straddling] |= finite[straddling]
        rows.append(finite & ~excluded)
    return np.array(rows, dtype=bool).reshape(discrete.sizes[dimension], len(times))


#: The quantisation share of the discrete model's radius error, in spacings: spring ``j`` sits at
#: ``(j + 1/2) Δx`` and is in contact exactly when ``x_j <= a`` (its threshold ``g − Δl_max`` rises
#: beyond its minimum, and the continuum's edge ``a`` is where the threshold meets ``d``), so
#: ``a_d = m Δx`` is ``a`` rounded to a multiple of Δx: ``|a_d − a| <= Δx/2``.
QUANTISATION_SPACINGS = 0.5


def _corner_lag(continuum) -> float:
    """The largest growth of the radius between the last sample before a path corner and the corner.

    The discrete model moves straight from that sample to the next and so misses this growth; a
    radius pinned after the corner keeps the lag until it shrinks onto its branch again.
    """
    times = continuum["time"].values
    radius = continuum["contact_radius"].values
    kinds = continuum["event_kind"].values
    lags = [0.0]
    for when, at_corner in zip(continuum["event_time"].values[kinds == "corner"],
                               continuum["event_radius"].values[kinds == "corner"]):
        before = int(np.searchsorted(times, when, side="left")) - 1  # the last sample before the corner
        if 0 <= before < len(times) - 1 and times[before + 1] > when:
            lag = abs(at_corner - radius[before])
            if np.isfinite(lag):
                lags.append(float(lag))
    return max(lags)


def first_order_error_bound(continuum, params: Parameters, dx: float, compared=None,
                            discrete=None) -> dict[str, np.ndarray]:
    r"""Bounds on ``max_t |discrete − continuum|`` of ``F_N``, ``F_x`` and ``A`` at spacing ``Δx``.

    The discrete model's first-order error is its contact radius: ``a_d = m Δx``
    differs from the continuum's ``a`` by at most

    ``δ = Δx/2 + δ_corner``,

    ``Δx/2`` from rounding (:data:`QUANTISATION_SPACINGS`) and ``δ_corner``, the
    growth of the continuum's radius between the last sample before a path
    corner and the corner (from the event log): where a time step straddles a
    corner, the discrete model cuts it and misses that growth (at most one
    step's, which ``dt`` keeps to a fraction of Δx), and a radius pinned after
    the corner keeps the lag. Everything else is evaluated at the same depth ``d`` and
    tangential position ``x`` as the continuum (the same sample times), so each
    quantity differs by its change with the radius at fixed ``d``, over ``δ``:

    - ``F_N = 2E* ∫_0^a (d − x²/R) dx`` (10): the springs between ``a`` and
      ``a_d`` carry ``d − x²/R``, so ``|ΔF_N| <= 2E* δ (|d − a²/R| + (2aδ + δ²)/R)``
      (``∂F_N/∂a = 2E*(d − a²/R)``; the second-order term matters where that
      vanishes, without adhesion), plus the midpoint-rule error of the springs'
      sum of ``g``, ``2E* a_d Δx²/(12R)``.
    - ``A = π a²``: ``|ΔA| <= π δ (2a + δ)``.
    - ``F_x = 2G* ∫_0^a u dξ``: the springs between ``a`` and ``a_d`` carry
      ``|u| <= min(ū(a + δ), s)`` (``ū = K a``, ``K = π τ0/(2G*)``, (13); ``s``
      the tangential travel since first contact, which no shift exceeds), and the
      cap ``K a_d`` of every spring that slides in either method (or has slid: the
      shift it was cut to stays) is off by ``K δ``, so
      ``|ΔF_x| <= 2G* δ [min(K (a + δ), s) + K c_slid]`` with ``c_slid`` the
      widest slip zone of either method so far, at most ``a``. With ``discrete``
      given, that is read from both methods' sliding fractions; without it, any
      spring may slide in the discrete model once the travel reaches its smallest
      possible cap ``K (a − δ)``, and ``c_slid = a`` from then on. A full slip has
      ``∂F_x/∂a = 4G* K a``, twice the boundary term alone. The time step adds one
      error of its own:
      a spring attaching during a step does so at the step's end with ``u = 0``,
      where it attached within the step in the continuum, so each spring still
      sticking carries at most the travel ``Δs`` of the step it attached in:
      ``2G* (a − c) max Δs`` over the steps into the elastomer so far.
      Last, the continuum takes a velocity component below ``1e-12`` of the
      speed as zero (``x`` of a path at 90° is ``cos 90° ≈ 6e-17`` of its
      length) where the springs follow it: ``2G* a · 1e-12 v t`` (``v`` the
      path's speed: ``path_speed`` of a custom path, else ``param_v``).

    The continuum's radius is accurate to its ``radius_rtol`` (an attribute of
    the dataset), which is added to ``δ``.

    Each bound is taken at every compared sample and its maximum returned (the
    error is compared as ``max_t``, and an error made at the largest radius, e.g.
    the cap of a sliding spring, is kept).

    Compared with the former ``4 Δx/a_max · max_t |Q|``: that assumes the
    largest ``Q`` sits at the largest radius. ``F_x`` of scenario B peaks after
    the corner, on a radius that (with ``Δγ1 < Δγ0``) jumped far below
    ``a_max``, so its relative error ``≈ 2δ/a`` is several times ``Δx/a_max``;
    this bound follows the radius at which the error is made.

    Parameters
    ----------
    continuum : xarray.Dataset
        ``simulate(..., method="continuum", t=discrete["time"].values)``.
    params : Parameters
    dx : float
        The discrete model's spacing Δx (m).
    compared : numpy.ndarray of bool, optional
        Samples to take the maximum over, shape ``(n_cases, n_time)`` (default:
        every sample in contact); :func:`compared_samples` gives those of
        :func:`history_differences`.
    discrete : xarray.Dataset, optional
        The discrete run on the same times: its slip zone tightens the ``F_x``
        bound (without it the bound holds before the discrete model is run).

    Returns
    -------
    dict
        Quantity name (:data:`HISTORY_QUANTITIES`) → array over the cases
        (``alpha`` or ``case``) of absolute bounds (N, N, m²); ``"radius"`` →
        ``δ`` per case (m).
    """
    p = params
    K = float(analytic.critical_shift(1.0, p))
    dimension = case_dimension(continuum)
    out = {name: [] for name in (*HISTORY_QUANTITIES, "radius")}
    for row, case in enumerate(continuum[dimension].values):
        c = continuum.sel({dimension: case})
        speed = float(c["path_speed"]) if "path_speed" in c else p.v  # a custom path has its own speed
        a = c["contact_radius"].values
        d = c["indentation_depth"].values
        x = c["tangential_displacement"].values
        contact = np.isfinite(a) & (a > 0)
        use = contact if compared is None else compared[row] & contact
        # the continuum's own radius is accurate to its radius_rtol (1e-14 by default)
        delta = (QUANTISATION_SPACINGS * dx + _corner_lag(c)
                 + float(continuum.attrs.get("radius_rtol", 0.0)) * float(np.max(a[contact], initial=0.0)))
        with np.errstate(invalid="ignore"):
            travel_steps = np.abs(np.diff(x))
            travel = np.concatenate([[0.0], np.nancumsum(travel_steps)])
            attaching = np.concatenate([[0.0], np.where(np.diff(d) > 0, travel_steps, 0.0)])
            attach_travel = np.fmax.accumulate(np.nan_to_num(attaching))
            slid = np.where(contact, np.nan_to_num(c["sliding_fraction"].values) * a, 0.0)
            if discrete is not None:
                d_run = discrete.sel({dimension: case})
                slid = np.fmax(slid, np.nan_to_num(d_run["sliding_fraction"].values * d_run["contact_radius"].values))
            else:
                slid = np.where(contact & (travel >= K * (a - delta)), a, slid)
            slid = np.minimum(np.fmax.accumulate(slid), a)
            slip = np.nan_to_num(c["sliding_fraction"].values) * a
            normal = 2 * p.E_star * (delta * (np.abs(d - a**2 / p.R) + (2 * a * delta + delta**2) / p.R)
                                     + (a + delta) * dx**2 / (12 * p.R))
            area = np.pi * delta * (2 * a + delta)
            snapped = NEGLIGIBLE_SHARE * speed * c["time"].values  # tangential travel the continuum drops
            tangential = 2 * p.G_star * (delta * (np.minimum(K * (a + delta), travel) + K * slid)
                                         + (a - slip) * attach_travel + a * snapped)
        for name, bound in zip(HISTORY_QUANTITIES, (normal, tangential, area)):
            out[name].append(float(np.max(bound[use], initial=0.0)))
        out["radius"].append(delta)
    return {name: np.array(values) for name, values in out.items()}


def slip_onset_delay_bound(solution, params: Parameters, dx: float, dt: float) -> float:
    r"""Bound on how much later than the continuum's the spring model's slip onset is seen, beyond one time step (s).

    The springs that reach the cap first are the oldest: those attached at the first contact (with adhesion, the
    whole jump-in radius at once), whose shift is the tangential travel ``s(t)`` since the first contact and whose cap
    is ``ū = K a(t)`` (13), ``K = π τ0/(2G*)``. The exact onset ``t*`` solves ``s(t*) = K a(t*)``. The spring model

    - attaches them at the end of the step in which it touches (``d ≥ g(Δx/2)``), so their shift lacks up to one
      step's travel ``Δs = |ẋ| dt``;
    - caps them at ``K a_d``, ``a_d = m Δx`` within ``Δx/2`` (:data:`QUANTISATION_SPACINGS`) of ``a``;
    - shows the onset at its first sample past it (the referee forgives one sample spacing:
      :func:`mdr_events.analysis.samples.event_time_errors`).

    The gap ``s − K a`` closes at the rate ``r = |ẋ| − K ȧ`` at ``t*``, so to first order the onset moves by at most

    ``Δt = (|ẋ| dt + K Δx/2) / r``

    beyond that sample spacing. ``r`` is below ``|ẋ|`` (the cap grows with the radius): the delay is amplified by
    ``|ẋ|/r`` (1.88 for scenario A at 20°, where the time step's share dominates: 80 % with ``dt = Δx/(2v)``); near
    a critical angle ``r → 0`` and the onset is ill-conditioned (``inf`` when ``r <= 0``). First order in ``Δx`` and
    ``dt``.

    Parameters
    ----------
    solution : PathSolution
        The continuum's solution of the path (:func:`~mdr_events.models.continuum.solve_path`), with a slip onset.
    params : Parameters
        The paper's contact (a paraboloid, the law of ``τ0``).
    dx, dt : float
        The spring model's spacing (m) and time step (s).

    Returns
    -------
    float
        ``Δt`` (s); ``nan`` where the exact run has no slip onset.
    """
    onsets = [event.time for event in solution.events if event.kind.value == "slip_onset"]
    if not onsets:
        return math.nan
    onset, path = onsets[0], solution.path
    start = path.first_contact_time()
    h = 1e-6 * path.duration  # (a central difference: the radius and the travel are smooth at an onset)
    radius = evaluate(solution, np.array([onset - h, onset + h]))["contact_radius"]
    travel = abs(float(path.position(start + onset + h)[0] - path.position(start + onset - h)[0])) / (2 * h)
    K = float(analytic.critical_shift(1.0, params))
    rate = travel - K * float(radius[1] - radius[0]) / (2 * h)
    return (travel * dt + K * QUANTISATION_SPACINGS * dx) / rate if rate > 0 else math.inf


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
