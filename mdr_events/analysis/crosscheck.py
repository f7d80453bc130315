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
``pinned_radius = 1``, (21) is not expected to agree there, and the continuum is compared with that
pinned onset instead (``d_crit_pinned``): ``disagree`` flags only a difference from the closed form that applies.
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

from mdr_events.contact import Contact
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.limits import DEFAULT_LIMITS, values_in
from mdr_events.models.methods import Continuum, Discrete
from mdr_events.models.motion import Scenario, case_dimension
from mdr_events.models.simulate import simulate
from mdr_events.parameters import Parameters
from mdr_events.theory import analytic
from mdr_events.theory.job import ContactLike, paper_parameters
from mdr_events.validation import check_choice, validate_alpha

__all__ = ["cross_check", "CROSS_CHECK_CONTENT", "CROSS_CHECK_VARIABLES"]

#: The ``content`` attribute of a cross-check of the slip onset.
CROSS_CHECK_CONTENT = "slip-onset cross-check"
#: Its variables, each along ``alpha``: name -> (units, long_name). ``{equation}`` and ``{dx}`` in a long
#: name are filled in from the result's scenario and spring spacing.
CROSS_CHECK_VARIABLES: dict[str, tuple[str, str]] = {
    "d_crit_closed_form": ("m", "slip onset, eq. {equation}"),
    "d_crit_continuum": ("m", "slip onset, continuum method"),
    "d_crit_discrete": ("m", "slip onset, discrete springs (dx = {dx:g} m)"),
    "d_crit_pinned": ("m", "slip onset with the radius pinned at a(d_max; dgamma0), d_max − tan α ū(a0): the closed "
                           "form where (21) does not apply (nan elsewhere)"),
    "closed_form_minus_continuum": ("m", "closed form that applies (eq. {equation}, or the pinned onset) − continuum"),
    "discrete_minus_continuum": ("m", "discrete − continuum"),
    "discrete_tolerance": ("m", "3 K dx + one time step of depth"),
    "pinned_radius": ("1", "1: slip while the radius is pinned ((21) does not apply)"),
    "found_once_at_phase_end": ("1", "1: only one method slips, within the discrete tolerance of d_max (A) or "
                                     "the jump-off (B)"),
    "disagree": ("1", "1: a difference exceeds its tolerance"),
}
register_schema(CROSS_CHECK_CONTENT, {name: ("alpha",) for name in CROSS_CHECK_VARIABLES})


#: The closed forms (18)/(21) and the continuum's event depth agree to this share (the event's root-finding).
CLOSED_FORM_SHARE = 1e-9
#: A discrete onset one time step late, exactly at the discrete tolerance, is within it to rounding.
ROUNDING_SHARE = 1e-12


def _first_slip(ds: xr.Dataset, scenario: str, params: Parameters) -> np.ndarray:
    depths = []
    for index, alpha in enumerate(ds["alpha"].values):
        case = ds.isel(alpha=index)
        t_turn = params.d_max / (params.v * math.sin(math.radians(alpha))) if scenario == "A" else params.d_max / params.v
        phase = (case["time"] <= t_turn) if scenario == "A" else (case["time"] > t_turn)
        sliding = (case["sliding_fraction"] > 0) & phase
        index = np.flatnonzero(sliding.values)
        depths.append(float(case["indentation_depth"].values[index[0]]) if index.size else math.nan)
    return np.array(depths)


def _continuum_slip_onset(continuum_ds: xr.Dataset, scenario: str) -> np.ndarray:
    """The depth of the first ``slip_onset`` in each case's event log in the scenario's phase: before the
    corner in A, after it in B. In B a contact that already slides at the corner (τ0 = 0: every spring
    slides from first contact) slides from the phase's start: the corner's depth ``d_max``."""
    onset = []
    for i in range(continuum_ds.sizes[case_dimension(continuum_ds)]):
        kinds = continuum_ds["event_kind"].values[i]
        depths = continuum_ds["event_depth"].values[i]
        hits = np.flatnonzero(kinds == "slip_onset")
        corner = np.flatnonzero(kinds == "corner")
        if scenario == "A":  # during indentation only
            hits = hits[hits < corner[0]] if corner.size else hits
        elif corner.size:
            before = [kind for kind in kinds[: corner[0]] if kind in ("slip_onset", "re_stick")]
            if before and before[-1] == "slip_onset":
                hits = corner[:1]
            else:
                hits = hits[hits > corner[0]]
        onset.append(float(depths[hits[0]]) if hits.size else math.nan)
    return np.array(onset)


def _pinned_onset(params: Parameters, K: np.ndarray) -> np.ndarray:
    """``d_max − tan α ū(a0)``: where the springs slide with the radius pinned at ``a0 = a(d_max; Δγ0)``."""
    return params.d_max - K * float(analytic.jkr_contact_radius(params.d_max, params, params.dgamma0))


def _pinned_radius(params: Parameters, scenario: str, K: np.ndarray) -> np.ndarray:
    """1 where the springs slide while the radius is still pinned at ``a(d_max; Δγ0)`` (scenario B), else 0."""
    if scenario != "B":
        return np.zeros(len(K), dtype=int)
    a0 = float(analytic.jkr_contact_radius(params.d_max, params, params.dgamma0))
    release = float(analytic.jkr_depth(a0, params, params.dgamma1))
    return (params.d_max - K * a0 >= release).astype(int)


def _cross_check_dataset(angles: np.ndarray, values: dict[str, np.ndarray], scenario: str,
                         dx: float) -> xr.Dataset:
    """The :data:`CROSS_CHECK_VARIABLES` along ``alpha``, labelled for ``scenario`` and ``dx``."""
    fill = {"equation": "(18)" if scenario == "A" else "(21)", "dx": dx}
    variables = {name: ("alpha", values[name], {"units": units, "long_name": long_name.format(**fill)})
                 for name, (units, long_name) in CROSS_CHECK_VARIABLES.items()}
    return xr.Dataset(variables, coords={
        "alpha": ("alpha", angles, {"units": "degree", "long_name": "path angle to the surface"})})


def cross_check(contact: ContactLike, scenario: str = "A", alpha=(10.0, 15.0, 20.0), dx: float = 2e-6,
                n_steps: int = 10_000, *, d_max: float | None = None) -> xr.Dataset:
    """Slip-onset depth from (18)/(21), the continuum and the discrete model, with differences and flags.

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4) under its law (13), with adhesion (9): a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before, with its own ``d_max`` and ``v``).
    scenario : {"A", "B"}
        ``"A"``: the slip onset during indentation, eq. (18); ``"B"``: during pull-off, eq. (21).
    alpha : sequence of float
        Path angles in degrees.
    dx, n_steps : float, int
        The discrete model's spring spacing (m) and number of time steps (``None``: the discrete method's default
        step, and no attribute ``n_steps``); any real number and integer :class:`~mdr_events.Discrete` takes, kept
        as the floats and integers it runs.
    d_max : float, optional
        With a Contact: the turning depth of the scenario (m; default the paper's 0.3 mm).

    Returns
    -------
    xarray.Dataset
        The variables of :data:`CROSS_CHECK_VARIABLES` along ``alpha`` (see the module's docstring).
    """
    params = paper_parameters(contact, "cross_check", d_max)
    scenario = check_choice("scenario", scenario, analytic.SCENARIOS)
    discrete_method = Discrete(dx=dx, n_steps=n_steps)
    dx, steps = discrete_method.dx, {} if n_steps is None else {"n_steps": discrete_method.n_steps}  # (as run: floats)
    methods = Continuum(), discrete_method
    for method in methods:  # (the angles counted as the runs count their cases, before they are read: 1e7 took 1.4 GB)
        method.check_case_count(values_in(alpha), DEFAULT_LIMITS)
    angles = np.atleast_1d(validate_alpha(alpha))
    model, motion = Contact.from_parameters(params), Scenario(scenario, tuple(angles), params.d_max, params.v)
    continuum_ds, discrete_ds = (simulate(model, motion, method=method) for method in methods)
    closed = np.atleast_1d(analytic.d_crit(angles, params, scenario, adhesion=True))
    continuum = _continuum_slip_onset(continuum_ds, scenario)
    discrete = _first_slip(discrete_ds, scenario, params)
    K = np.tan(np.radians(angles)) * float(analytic.critical_shift(1.0, params))
    # the depth the path covers in one of the discrete model's time steps
    step = params.v * discrete_ds.attrs["dt"] * np.sin(np.radians(angles))
    discrete_tolerance = 3 * K * dx + step
    pinned = _pinned_radius(params, scenario, K)
    pinned_onset = np.where(pinned == 1, _pinned_onset(params, K), np.nan)
    applies = np.where(pinned == 1, pinned_onset, closed)  # the closed form that holds where the radius is pinned
    # a slip that one method finds and the other does not disagrees, unless it falls within the
    # discrete tolerance of the end of the phase (d_max in A, the jump-off in B), which the two
    # methods meet up to Δx apart
    phase_end = params.d_max if scenario == "A" else analytic.jump_off(params, params.dgamma1)["depth"]
    with np.errstate(invalid="ignore"):
        closed_vs_continuum = np.abs(applies - continuum)
        discrete_vs_continuum = np.abs(discrete - continuum)
        found_once = np.isnan(discrete) != np.isnan(continuum)
        at_phase_end = np.abs(np.where(np.isnan(continuum), discrete, continuum) - phase_end) <= discrete_tolerance
        flag = ((closed_vs_continuum > CLOSED_FORM_SHARE * np.abs(continuum))
                | (discrete_vs_continuum > discrete_tolerance * (1.0 + ROUNDING_SHARE))
                | (found_once & ~at_phase_end)).astype(int)
        at_end = (found_once & at_phase_end).astype(int)
    values = {
        "d_crit_closed_form": closed,
        "d_crit_continuum": continuum,
        "d_crit_discrete": discrete,
        "d_crit_pinned": pinned_onset,
        "closed_form_minus_continuum": applies - continuum,
        "discrete_minus_continuum": discrete - continuum,
        "discrete_tolerance": discrete_tolerance,
        "pinned_radius": pinned,
        "found_once_at_phase_end": at_end,
        "disagree": flag,
    }
    return stamp(_cross_check_dataset(angles, values, scenario, dx), params, scenario=scenario, dx=dx, **steps,
                 content=CROSS_CHECK_CONTENT)
