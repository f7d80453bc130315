"""Slip onset three ways: closed form, continuum, discrete springs, side by side.

Scenario A: the continuum slip onset equals (18) to solver tolerance
(1e-9 relative), because its assumptions hold exactly (the central springs,
attached at x = 0 during the jump-in, are the first to reach ``ū(a)`` on the
``Δγ0`` branch).

Scenario B: (21) assumes that the radius follows the ``Δγ1`` branch from
``d_max`` on. In the model it stays pinned at ``a0 = a(d_max; Δγ0)`` until
``d`` falls to ``d_1(a0) = g(a0) − Δl_max(a0; Δγ1)``. Where the springs slide
before that (small α: ``d_max − tan α ū(a0) >= d_1(a0)``) the slip onset is
``d_max − tan α ū(a0)``, earlier than (21) says; the rows are flagged
``pinned_radius = 1`` and the closed form is not expected to agree there.
Elsewhere the three agree (the discrete model within ``3 K Δx`` plus one
time step of depth, ``K = π τ0 tan α / (2G*)``). A slip that only one
method finds is a disagreement, unless it lies within that tolerance of the
end of the phase (``d_max`` in A, the jump-off depth in B): the discrete
model reaches those up to ``Δx`` apart (``found_once_at_phase_end``).
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from mdr_events.theory import analytic
from mdr_events.io.datasets import stamp
from mdr_events.parameters import Parameters
from mdr_events.models.simulate import simulate

__all__ = ["cross_check"]


def _first_slip(ds: xr.Dataset, scenario: str, params: Parameters) -> np.ndarray:
    depths = []
    for alpha in ds["alpha"].values:
        case = ds.sel(alpha=alpha)
        t_turn = params.d_max / (params.v * math.sin(math.radians(alpha))) if scenario == "A" else params.d_max / params.v
        phase = (case["time"] <= t_turn) if scenario == "A" else (case["time"] > t_turn)
        sliding = (case["sliding_fraction"] > 0) & phase
        index = np.flatnonzero(sliding.values)
        depths.append(float(case["indentation_depth"].values[index[0]]) if index.size else math.nan)
    return np.array(depths)


def cross_check(params: Parameters, scenario: str = "A", alpha=(10.0, 15.0, 20.0), dx: float = 2e-6,
                n_steps: int = 10_000) -> xr.Dataset:
    """Slip-onset depth from (18)/(21), the continuum and the discrete model, with differences and flags."""
    analytic._check_choice("scenario", scenario, analytic.SCENARIOS)
    angles = np.atleast_1d(np.asarray(alpha, dtype=float))
    closed = np.atleast_1d(analytic.d_crit(angles, params, scenario, adhesion=True))
    continuum_ds = simulate(params, scenario, alpha=angles, method="continuum")
    onset = []
    for i in range(len(angles)):
        kinds = continuum_ds["event_kind"].values[i]
        hits = np.flatnonzero(kinds == "slip_onset")
        if scenario == "A":  # during indentation only
            corner = np.flatnonzero(kinds == "corner")
            hits = hits[hits < corner[0]] if corner.size else hits
        onset.append(float(continuum_ds["event_depth"].values[i, hits[0]]) if hits.size else math.nan)
    continuum = np.array(onset)
    discrete = _first_slip(simulate(params, scenario, alpha=angles, dx=dx, n_steps=n_steps), scenario, params)
    K = np.tan(np.radians(angles)) * float(analytic.critical_shift(1.0, params))
    step = params.v * (np.nanmax(continuum_ds["time"].values) / n_steps) * np.sin(np.radians(angles))
    discrete_tolerance = 3 * K * dx + step
    pinned = np.zeros(len(angles), dtype=int)
    if scenario == "B":
        a0 = float(analytic.jkr_contact_radius(params.d_max, params, params.dgamma0))
        release = float(analytic.jkr_depth(a0, params, params.dgamma1))
        pinned = (params.d_max - K * a0 >= release).astype(int)
    # a slip that one method finds and the other does not disagrees, unless it falls within the
    # discrete tolerance of the end of the phase (d_max in A, the jump-off in B), which the two
    # methods meet up to Δx apart
    phase_end = params.d_max if scenario == "A" else analytic.jump_off(params, params.dgamma1)["depth"]
    with np.errstate(invalid="ignore"):
        closed_vs_continuum = np.abs(closed - continuum)
        discrete_vs_continuum = np.abs(discrete - continuum)
        found_once = np.isnan(discrete) != np.isnan(continuum)
        at_phase_end = np.abs(np.where(np.isnan(continuum), discrete, continuum) - phase_end) <= discrete_tolerance
        flag = ((closed_vs_continuum > 1e-9 * np.abs(continuum)) | (discrete_vs_continuum > discrete_tolerance)
                | (found_once & ~at_phase_end)).astype(int)
        at_end = (found_once & at_phase_end).astype(int)
    dim = "alpha"
    ds = xr.Dataset(
        {
            "d_crit_closed_form": (dim, closed, {"units": "m", "long_name": f"slip onset, eq. {'(18)' if scenario == 'A' else '(21)'}"}),
            "d_crit_continuum": (dim, continuum, {"units": "m", "long_name": "slip onset, continuum method"}),
            "d_crit_discrete": (dim, discrete, {"units": "m", "long_name": f"slip onset, discrete springs (dx = {dx:g} m)"}),
            "closed_form_minus_continuum": (dim, closed - continuum, {"units": "m", "long_name": "closed form − continuum"}),
            "discrete_minus_continuum": (dim, discrete - continuum, {"units": "m", "long_name": "discrete − continuum"}),
            "discrete_tolerance": (dim, discrete_tolerance, {"units": "m", "long_name": "3 K dx + one time step of depth"}),
            "pinned_radius": (dim, pinned, {"units": "1", "long_name": "1: slip while the radius is pinned ((21) does not apply)"}),
            "found_once_at_phase_end": (dim, at_end, {"units": "1", "long_name": "1: only one method slips, within "
                                                       "the discrete tolerance of d_max (A) or the jump-off (B)"}),
            "disagree": (dim, flag, {"units": "1", "long_name": "1: a difference exceeds its tolerance"}),
        },
        coords={dim: (dim, angles, {"units": "degree", "long_name": "path angle to the surface"})},
    )
    return stamp(ds, params, scenario=scenario, dx=dx, n_steps=n_steps, content="slip-onset cross-check")
