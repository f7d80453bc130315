"""What ``results/README.md`` reports, as values: the computations behind it and the rows of its tables.

:func:`compute` runs every simulation and study (a :class:`Reproduction`); the
functions below turn it into the rows of the report's tables (named tuples of
plain numbers in SI units). :mod:`mdr_events.app.report` only formats them.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field
from typing import Callable, NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.convergence import (HISTORY_QUANTITIES, discrete_errors, discrete_minus_continuum,
                                             observed_orders)
from mdr_events.analysis.crosscheck import CROSS_CHECK_CONTENT, cross_check
from mdr_events.analysis.fit import FitResult, fit, synthetic_measurement
from mdr_events.analysis.universal_map import universal_map
from mdr_events.analysis.validate import resolve_path
from mdr_events.io.agreement import Integrated, RoundOff, register_accuracy
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.models.continuum import extremum, solve_path, tangential_work
from mdr_events.models.paths import Path, exit_depth
from mdr_events.models.motion import CUSTOM_DIMENSION, case_dimension, scenario_paths
from mdr_events.models.simulate import simulate
from mdr_events.models.simulation_schema import SIMULATION_CONTENT
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.contact.friction import FrictionLaw
from mdr_events.theory import analytic, mindlin, power_law

__all__ = ["Reproduction", "compute", "jobs", "COMPUTE_STEPS", "critical_angles_A", "critical_angles_B",
           "cross_check_rows", "differences", "extremum_convergence", "history_convergence", "FrettingContact",
           "FrettingStudy", "FrettingRow", "fretting_contact", "fretting_paths", "fretting_study", "fretting_rows",
           "closed_loop_times", "discrete_loop_work", "FRETTING_VARIABLES", "FitDemonstration", "fit_demonstration",
           "FIT_DEMO_FREE", "FIT_DEMO_NOISE", "MAP_SLIP", "MAP_ADHESION", "FIT_DEMO_SEED", "FIT_DEMO_SAMPLES", "FIT_DEMO_ANGLE"]

#: Critical angles stated in section 4 (R = 30 mm), degrees.
PAPER_CRITICAL_ANGLES = {"hertz": 23.59, "jkr": 22.87}
#: The stated plateau of the mean shear stress in pull-off, Pa.
PAPER_TAU0 = 42e3
RADII = {"R30": 0.03, "R100": 0.1}
SCENARIOS = ("A", "B")
FIGURE_NUMBERS = {"A": "8", "B": "10"}
#: Angles of Fig. 8 and 10 (degrees).
FIGURE_ANGLES = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)

#: The discrete model overlaid on the figures and used in the cross-check.
OVERLAY_ANGLE = 20.0
FIGURE_DX = 1e-6
FIGURE_STEPS = 10_000
#: Convergence studies: spacings (m) and angles (degrees); the time step moves the indenter Δx/2.
CONVERGENCE_SPACINGS = (16e-6, 8e-6, 4e-6, 2e-6, 1e-6)
CONVERGENCE_ANGLES = (10.0, 30.0, 60.0)
HISTORY_SPACINGS = (8e-6, 4e-6, 2e-6, 1e-6)
HISTORY_ANGLE = 30.0
#: Extrema of the discrete model whose convergence the report shows, in its order.
CONVERGENCE_EXTREMA = ("normal_force_min", "contact_area_max", "tangential_force_max")
#: Extremes of the continuum runs the report quotes (exact, from the solution: :func:`continuum.extremum`):
#: name -> (quantity, largest).
EXTREMES = {"normal_force_max": ("normal_force", True), "normal_force_min": ("normal_force", False),
            "tangential_force_max": ("tangential_force", True), "contact_area_max": ("contact_area", True),
            "mean_pressure_max": ("mean_pressure", True), "mean_shear_stress_max": ("mean_shear_stress", True)}
#: The case whose event log and extremes the differences (1)–(4) show in detail: (radius label, scenario).
DETAIL_CASE = ("R30", "A")

#: The fretting study: reciprocating sliding at ``d_max`` for the radius :data:`FRETTING_RADIUS` (a label of
#: :data:`RADII`), with the amplitude ``X`` this many critical shifts ``ū(a_max)``, :data:`FRETTING_CYCLES` full
#: cycles, after vertical indentation and after scenario A's in-path at :data:`FRETTING_ANGLE` (degrees).
FRETTING_RADIUS = "R30"
FRETTING_AMPLITUDE_IN_CAPS = 3.0
FRETTING_CYCLES = 3
FRETTING_ANGLE = 20.0
#: The case labels of the fretting study: after vertical indentation, after oblique indentation.
FRETTING_VERTICAL = "vertical"
FRETTING_OBLIQUE = f"oblique {FRETTING_ANGLE:g}°"
#: The ``study`` attribute of the fretting study's continuum dataset (it selects :data:`FRETTING_VARIABLES`).
FRETTING_STUDY = "fretting"
#: Corners of the closed-form loop (a parallelogram, closed: the first corner again at the end).
PARALLELOGRAM_CORNERS = 5
#: The variables the fretting study adds to its continuum dataset: name -> (dims, units, long_name).
FRETTING_VARIABLES: dict[str, tuple[tuple[str, ...], str, str]] = {
    "fretting_centre": ((CUSTOM_DIMENSION,), "m", "centre x_c of the reciprocating sliding"),
    "fretting_amplitude": ((CUSTOM_DIMENSION,), "m", "amplitude X of the reciprocating sliding: x_c - X to x_c + X"),
    "fretting_contact_radius": ((CUSTOM_DIMENSION,), "m",
                                "contact radius a_max at d_max on the dgamma0 branch, fixed while sliding"),
    "fretting_critical_shift": ((CUSTOM_DIMENSION,), "m", "critical shift u_bar(a_max) = pi a_max tau0 / (2 G*)"),
    "fretting_loop_start": ((CUSTOM_DIMENSION,), "s",
                            "time from first contact of the tangential reversal starting the last closed loop"),
    "fretting_loop_end": ((CUSTOM_DIMENSION,), "s", "time from first contact of the next tangential reversal of the "
                                                    "same direction, ending the last closed loop"),
    "dissipated_energy": ((CUSTOM_DIMENSION,), "J",
                          "energy dissipated over the last closed loop, integral of F_x dx from the continuum "
                          "solution (mdr_events.models.continuum.solution.tangential_work)"),
    "dissipated_energy_closed_form": ((CUSTOM_DIMENSION,), "J",
                                      "energy dissipated per cycle by the fixed contact, 4 pi a_max^2 tau0 (X - u_bar)"),
    "parallelogram_x": ((CUSTOM_DIMENSION, "corner"), "m",
                        "tangential displacement at the corners of the closed-form loop of the fixed contact"),
    "parallelogram_force": ((CUSTOM_DIMENSION, "corner"), "N",
                            "tangential force at the corners of the closed-form loop of the fixed contact "
                            "(plateaus +-pi a_max^2 tau0, slopes 2 G* a_max)"),
}
register_schema(SIMULATION_CONTENT, {name: dims for name, (dims, _, _) in FRETTING_VARIABLES.items()},
                when=("study", FRETTING_STUDY))
#: How the fretting study computes them: the loop's energy integrates the continuum's F_x; the rest are closed forms
#: (the reversals are the path's corners).
register_accuracy(SIMULATION_CONTENT, {**{name: RoundOff() for name in FRETTING_VARIABLES},
                                       "dissipated_energy": Integrated()}, when=("study", FRETTING_STUDY))


@dataclass
class Reproduction:
    """Everything the report and the figures are made of (keys ``(radius label, scenario)``)."""

    continuum: dict = field(default_factory=dict)
    discrete: dict = field(default_factory=dict)
    cross_checks: dict = field(default_factory=dict)
    extremes: dict = field(default_factory=dict)
    discrete_errors: dict = field(default_factory=dict)
    history: dict = field(default_factory=dict)
    fretting: FrettingStudy | None = None  #: the fretting study at :data:`FRETTING_RADIUS`
    fitting: "FitDemonstration | None" = None  #: the fit to synthetic measurements (:func:`fit_demonstration`)
    universal: xr.Dataset | None = None  #: the critical angles over the dimensionless groups (:func:`universal_map`)
    profiles: "ProfileComparison | None" = None  #: other indenters, scenario A (:func:`profile_comparison`)
    mindlin: "MindlinCheck | None" = None  #: Coulomb's law at a constant depth (:func:`mindlin_check`)


def jobs() -> list[tuple[str, float, str]]:
    """Every (radius label, radius in m, scenario) the report covers."""
    return [(label, radius, scenario) for label, radius in RADII.items() for scenario in SCENARIOS]


#: Progress messages :func:`compute` sends (one per step).
COMPUTE_STEPS = 2 * len(RADII) * len(SCENARIOS) + 7


def compute(progress: Callable[[str], None] | None = None) -> Reproduction:
    """Run every simulation and study behind ``results/`` (about 20 s on one core).

    ``progress`` hears one message per step (:data:`COMPUTE_STEPS` of them).
    """
    say = progress or (lambda message: None)
    data = Reproduction()
    for label, radius, scenario in jobs():
        params = Parameters.paper(R=radius)
        say(f"Fig. {FIGURE_NUMBERS[scenario]}, R = {radius * 1e3:g} mm: continuum, "
            f"{len(FIGURE_ANGLES)} angles; discrete overlay at {OVERLAY_ANGLE:g}° (Δx = {FIGURE_DX * 1e6:g} µm)")
        data.continuum[(label, scenario)] = simulate(params, scenario, alpha=FIGURE_ANGLES, method="continuum")
        data.discrete[(label, scenario)] = simulate(params, scenario, alpha=[OVERLAY_ANGLE], dx=FIGURE_DX,
                                                    n_steps=FIGURE_STEPS)
        solutions = [solve_path(params, path) for path in scenario_paths(params, scenario, FIGURE_ANGLES)[0]]
        data.extremes[(label, scenario)] = {
            name: np.array([extremum(solution, quantity, largest)[1] for solution in solutions])
            for name, (quantity, largest) in EXTREMES.items()}
    for label, radius, scenario in jobs():
        say(f"{CROSS_CHECK_CONTENT}, scenario {scenario}, R = {radius * 1e3:g} mm "
            f"(closed form, continuum, discrete at {len(FIGURE_ANGLES)} angles)")
        data.cross_checks[(label, scenario)] = cross_check(Parameters.paper(R=radius), scenario, FIGURE_ANGLES,
                                                           dx=FIGURE_DX, n_steps=FIGURE_STEPS)
    params = Parameters.paper()
    say(f"convergence of the discrete model to the exact extrema "
        f"({len(CONVERGENCE_SPACINGS)} spacings, {len(CONVERGENCE_ANGLES)} angles)")
    for alpha in CONVERGENCE_ANGLES:
        data.discrete_errors[alpha] = discrete_errors(params, alpha, CONVERGENCE_SPACINGS, steps_per_spacing=0.5)
    say("convergence of the discrete model to the continuum over the whole run")
    for scenario in SCENARIOS:
        data.history[scenario] = discrete_minus_continuum(params, scenario, HISTORY_ANGLE, HISTORY_SPACINGS)
    say(f"fretting at d_max, R = {RADII[FRETTING_RADIUS] * 1e3:g} mm: continuum, {len(fretting_paths(params))} "
        f"cases; discrete (Δx = {FIGURE_DX * 1e6:g} µm)")
    data.fretting = fretting_study(Parameters.paper(R=RADII[FRETTING_RADIUS]))
    say(f"fit of {len(FIT_DEMO_FREE)} parameters to synthetic measurements (scenario A at {FIT_DEMO_ANGLE:g}°, "
        f"{FIT_DEMO_NOISE:.0%} noise)")
    data.fitting = fit_demonstration(Parameters.paper())
    say(f"universal map: critical angles over {MAP_SLIP.size} × {MAP_ADHESION.size} values of the dimensionless "
        "groups (the sweep on a local dask cluster)")
    data.universal = universal_map(MAP_SLIP, MAP_ADHESION, Parameters.paper(),
                                   marked={label: Parameters.paper(R=radius) for label, radius in RADII.items()})
    say(f"other indenters: cone, paraboloid, quartic and flat punch, scenario A at {PROFILE_ANGLE:g}° (continuum; discrete at "
        f"Δx = {FIGURE_DX * 1e6:g} µm)")
    data.profiles = profile_comparison(Parameters.paper())
    say(f"Cattaneo–Mindlin: Coulomb's law (μ = {MINDLIN_FRICTION.mu:g}) at a constant depth, continuum and discrete "
        f"(Δx = {FIGURE_DX * 1e6:g} µm) against the closed form")
    data.mindlin = mindlin_check(Parameters.paper())
    return data


#: The universal map's grid: the slip parameter S (log-spaced) and the adhesion parameters Γ.
MAP_SLIP = np.geomspace(0.3, 15.0, 121)
MAP_ADHESION = np.linspace(0.0, 0.3, 121)


# ----------------------------------------------------------------------------
# fitting to measurements
#: The fit demonstration: scenario A at this angle, R = 30 mm ...
FIT_DEMO_ANGLE = 20.0
#: ... these parameters free, started 30 % off (alternately above and below) ...
FIT_DEMO_FREE = ("E", "tau0", "dgamma0", "dgamma1")
FIT_DEMO_START_FACTORS = (1.3, 0.7, 1.3, 0.7)
#: ... on F_N, F_x and A at this many samples to 1.02 times the path's duration, with white noise of this share of
#: each quantity's largest magnitude, drawn with this seed.
FIT_DEMO_SAMPLES = 2001
FIT_DEMO_NOISE = 0.01
FIT_DEMO_SEED = 2023


class FitDemonstration(NamedTuple):
    """Synthetic measured curves from known parameters, and the fit that recovers them."""

    truth: Parameters
    start: Parameters
    measured: xr.Dataset
    result: FitResult


def fit_demonstration(truth: Parameters) -> FitDemonstration:
    """Fit :data:`FIT_DEMO_FREE` to synthetic measurements of scenario A at :data:`FIT_DEMO_ANGLE` (noise
    :data:`FIT_DEMO_NOISE`, seed :data:`FIT_DEMO_SEED`) from a start 30 % off."""
    duration = resolve_path(truth, "A", FIT_DEMO_ANGLE).duration
    times = np.linspace(0.0, 1.02 * duration, FIT_DEMO_SAMPLES)
    measured = synthetic_measurement(truth, "A", FIT_DEMO_ANGLE, times=times, relative_noise=FIT_DEMO_NOISE,
                                     seed=FIT_DEMO_SEED)
    start = truth.replace(**{name: getattr(truth, name) * factor
                             for name, factor in zip(FIT_DEMO_FREE, FIT_DEMO_START_FACTORS)})
    result = fit(measured, "A", FIT_DEMO_ANGLE, free=FIT_DEMO_FREE, start=start, time_origin="path_start")
    return FitDemonstration(truth, start, measured, result)


# ----------------------------------------------------------------------------
# other indenters
#: The power laws compared with the paper's paraboloid (scenario A at :data:`PROFILE_ANGLE`, R = 30 mm): each
#: with the paraboloid's non-adhesive contact radius at d_max; and the flat punch of that radius.
PROFILE_EXPONENTS = {"cone": 1.0, "paraboloid": 2.0, "quartic": 4.0}
PROFILE_PUNCH = "flat_punch"
PROFILE_ANGLE = 20.0


class ProfileComparison(NamedTuple):
    """Scenario A at :data:`PROFILE_ANGLE` for the indenters of :data:`PROFILE_EXPONENTS`, by name."""

    profiles: dict  #: name → PowerLaw or FlatPunch
    continuum: dict  #: name → simulation (continuum)
    discrete: dict  #: name → simulation (discrete, Δx = FIGURE_DX, FIGURE_STEPS steps)


def matching_power_law(n: float, params: Parameters) -> PowerLaw:
    """The power law ``f = c rⁿ`` whose non-adhesive contact radius at ``d_max`` is the paraboloid's, ``√(R d_max)``
    (the paraboloid itself for ``n = 2``)."""
    if n == 2.0:
        return PowerLaw.paraboloid(params.R)
    return power_law.with_radius_at(n, math.sqrt(params.R * params.d_max), params.d_max)


def profile_comparison(params: Parameters) -> ProfileComparison:
    """Continuum and discrete runs of scenario A at :data:`PROFILE_ANGLE` for each of :data:`PROFILE_EXPONENTS` and the
    flat punch of the paraboloid's radius at d_max (:data:`PROFILE_PUNCH`)."""
    profiles = {name: matching_power_law(n, params) for name, n in PROFILE_EXPONENTS.items()}
    profiles[PROFILE_PUNCH] = FlatPunch(math.sqrt(params.R * params.d_max))
    continuum = {name: simulate(params, "A", alpha=[PROFILE_ANGLE], method="continuum", profile=profile)
                 for name, profile in profiles.items()}
    discrete = {name: simulate(params, "A", alpha=[PROFILE_ANGLE], dx=FIGURE_DX, n_steps=FIGURE_STEPS, profile=profile)
                for name, profile in profiles.items()}
    return ProfileComparison(profiles, continuum, discrete)


class ProfileRow(NamedTuple):
    """One indenter of the comparison: its closed forms against the continuum's, and the discrete model's gap."""

    name: str
    profile: PowerLaw | FlatPunch
    pull_off_closed_form: float  #: pull-off force under force control (N)
    pull_off_continuum: float  #: the continuum's least normal force (N)
    onset_closed_form: float  #: slip-onset depth (18) (m; nan: none before d_max)
    onset_continuum: float  #: the continuum's first slip onset while indenting (m; nan: none)
    tangential_force_max: float  #: the continuum's largest F_x (N)
    discrete_difference: float  #: max_t |discrete − continuum| of F_x over its largest value


def profile_rows(comparison: ProfileComparison, params: Parameters) -> list[ProfileRow]:
    """The rows of the report's table of :func:`profile_comparison`."""
    rows = []
    for name, profile in comparison.profiles.items():
        exact, springs = comparison.continuum[name], comparison.discrete[name]
        onset = float(power_law.d_crit_A(PROFILE_ANGLE, profile, params, adhesion=True))
        found = event_times(exact, PROFILE_ANGLE, "slip_onset")
        corner = _first(event_times(exact, PROFILE_ANGLE, "corner"))
        kinds = list(exact["event_kind"].values[0])
        onset_continuum = float(exact["event_depth"].values[0, kinds.index("slip_onset")]) \
            if len(found) and found[0] < corner else math.nan
        on_grid = exact if np.array_equal(exact["time"].values, springs["time"].values) else simulate(
            params, "A", alpha=[PROFILE_ANGLE], method="continuum", t=springs["time"].values, profile=profile)
        largest = float(exact["tangential_force_max"].values[0])
        difference = float(np.nanmax(np.abs(springs["tangential_force"].values - on_grid["tangential_force"].values)))
        rows.append(ProfileRow(name, profile, power_law.pull_off_force(profile, params, params.dgamma1),
                               float(exact["normal_force_min"].values[0]), onset if onset < params.d_max else math.nan,
                               onset_continuum, largest, difference / largest))
    return rows


# ----------------------------------------------------------------------------
# Coulomb's law at a constant depth: Cattaneo–Mindlin
#: The check: the paper's material without adhesion, Coulomb's law with this μ, ...
MINDLIN_FRICTION = FrictionLaw("coulomb", mu=0.3)
#: ... vertically in to this share of d_max, then along x through these shares of the full-slip shift κ d: the
#: virgin curve, a Mindlin loop (unloading and reloading), and on to full slip.
MINDLIN_DEPTH_SHARE = 1.0 / 3.0
MINDLIN_TURNS = (0.0, 0.6, -0.6, 0.6, 1.3)
MINDLIN_SAMPLES = 2001
#: The case label and the ``study`` attribute of its datasets (which selects :data:`MINDLIN_VARIABLES`).
MINDLIN_CASE = "cattaneo-mindlin"
MINDLIN_STUDY = "cattaneo_mindlin"
MINDLIN_VARIABLES: dict[str, tuple[tuple[str, ...], str, str]] = {
    "cattaneo_mindlin_force": ((CUSTOM_DIMENSION, "time"), "N",
                               "tangential force of the closed form at the constant depth: Cattaneo-Mindlin's virgin "
                               "curve and Masing's rules (mdr_events.mindlin.tangential_force); nan off that depth"),
}
register_schema(SIMULATION_CONTENT, {name: dims for name, (dims, _, _) in MINDLIN_VARIABLES.items()},
                when=("study", MINDLIN_STUDY))
#: The closed form on the samples (round-off).
register_accuracy(SIMULATION_CONTENT, {name: RoundOff() for name in MINDLIN_VARIABLES}, when=("study", MINDLIN_STUDY))


class MindlinCheck(NamedTuple):
    """The continuum and the discrete run of :func:`mindlin_path`, each with the closed form on its samples."""

    continuum: xr.Dataset
    discrete: xr.Dataset


def mindlin_path(params: Parameters) -> tuple[Path, float]:
    """The path of the check and its constant depth (m)."""
    depth = MINDLIN_DEPTH_SHARE * params.d_max
    full = mindlin.full_slip_shift(depth, MINDLIN_FRICTION, params)
    waypoints = [(0.0, 0.0)] + [(share * full, depth) for share in MINDLIN_TURNS]
    return Path(np.array(waypoints), speed=params.v), depth


def _with_closed_form(dataset: xr.Dataset, path: Path, depth: float, params: Parameters) -> xr.Dataset:
    """``dataset`` with :data:`MINDLIN_VARIABLES` on its samples at ``depth``: from the corner where ``path`` reached
    it on (the springs were at rest there, ``x = 0``), by time, half a sample before it, not by the sampled depth's
    equality with ``depth`` (which the rounding of another CPU may break at the corner)."""
    times = dataset["time"].values
    reached = path.corner_times[1] - path.first_contact_time()
    running = np.isfinite(dataset["indentation_depth"].values[0])
    held = (times > reached - 0.5 * float(np.min(np.diff(times)))) & running
    x = dataset["tangential_displacement"].values[0][held]
    closed = np.full(dataset.sizes["time"], np.nan)
    closed[held] = mindlin.tangential_force(np.concatenate([[0.0], x]), depth, MINDLIN_FRICTION, params)[1:]
    (dims, units, long_name), = MINDLIN_VARIABLES.values()
    dataset = dataset.assign(cattaneo_mindlin_force=(dims, closed[None, :], {"units": units, "long_name": long_name}))
    dataset.attrs.update(study=MINDLIN_STUDY, mindlin_depth=depth)
    return dataset


def mindlin_check(params: Parameters) -> MindlinCheck:
    """Coulomb's law (:data:`MINDLIN_FRICTION`) along :func:`mindlin_path` without adhesion: the continuum at
    :data:`MINDLIN_SAMPLES` times and the path's corners, the discrete model at Δx = FIGURE_DX (dt = Δx/(2v))."""
    hertz = params.replace(dgamma0=0.0, dgamma1=0.0)
    path, depth = mindlin_path(hertz)
    start = path.first_contact_time()
    times = np.union1d(np.linspace(0.0, path.duration - start, MINDLIN_SAMPLES), path.corner_times[1:] - start)
    continuum = simulate(hertz, {MINDLIN_CASE: path}, method="continuum", t=times, friction=MINDLIN_FRICTION)
    discrete = simulate(hertz, {MINDLIN_CASE: path}, dx=FIGURE_DX, dt=0.5 * FIGURE_DX / hertz.v,
                        friction=MINDLIN_FRICTION)
    return MindlinCheck(_with_closed_form(continuum, path, depth, hertz),
                        _with_closed_form(discrete, path, depth, hertz))


class MindlinRow(NamedTuple):
    """One method's largest difference from the closed form, over μ F_N."""

    method: str
    max_difference: float


def mindlin_rows(check: MindlinCheck) -> list[MindlinRow]:
    """The rows of the report's table of :func:`mindlin_check`."""
    rows = []
    for method, dataset in (("continuum", check.continuum), (f"discrete, Δx = {FIGURE_DX * 1e6:g} µm", check.discrete)):
        full = MINDLIN_FRICTION.mu * float(np.nanmax(dataset["normal_force"].values))
        difference = dataset["tangential_force"].values - dataset["cattaneo_mindlin_force"].values
        rows.append(MindlinRow(method, float(np.nanmax(np.abs(difference))) / full))
    return rows


# ----------------------------------------------------------------------------
# helpers on the datasets
def event_times(ds: xr.Dataset, label: float | str, kind: str) -> np.ndarray:
    """The times of every event of ``kind`` in the event log of the case ``label`` (its angle, or a custom
    path's label)."""
    case = ds.sel({case_dimension(ds): label})
    kinds = case["event_kind"].values
    return case["event_time"].values[kinds == kind]


def _first(values: np.ndarray) -> float:
    return float(values[0]) if len(values) else math.nan


# ----------------------------------------------------------------------------
# critical angles
class CriticalAngleRow(NamedTuple):
    """A critical angle of scenario A (slip begins exactly at ``d_max``), ours and the paper's."""

    radius: float
    model: str  #: "hertz" (eq. (17)) or "jkr" (eq. (18))
    equation: str
    computed: float  #: degrees
    paper: float | None  #: degrees; None where the paper states none


class ScenarioBAngleRow(NamedTuple):
    """The angle above which, in scenario B, the contact comes apart before any spring slides."""

    radius: float
    angle: float  #: degrees, adhesive (eq. (21) at the jump-off)


def critical_angles_A() -> list[CriticalAngleRow]:
    """The critical angles of scenario A for each radius, non-adhesive and adhesive."""
    rows = []
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        for model, adhesive, equation in (("hertz", False, "(17)"), ("jkr", True, "(18)")):
            paper = PAPER_CRITICAL_ANGLES[model] if label == "R30" else None
            rows.append(CriticalAngleRow(radius, model, equation,
                                         analytic.critical_angle(params, "A", adhesion=adhesive), paper))
    return rows


def critical_angles_B() -> list[ScenarioBAngleRow]:
    """The adhesive critical angle of scenario B for each radius."""
    return [ScenarioBAngleRow(radius, analytic.critical_angle(Parameters.paper(R=radius), "B", adhesion=True))
            for radius in RADII.values()]


# ----------------------------------------------------------------------------
# slip onset, three ways
class SlipOnsetVerdict(enum.Enum):
    """How the slip onsets of a cross-check row compare (the first that applies)."""

    NO_SLIP_IN_INDENTATION = "the closed form lies beyond d_max (scenario A)"
    JUMP_OFF_FIRST = "the contact jumps off before any slip (scenario B)"
    FOUND_ONCE_AT_PHASE_END = "only one method slips, within tolerance of the end of the phase"
    PINNED = "the radius is pinned when the springs slide: (21) does not apply"
    DISAGREE = "a difference exceeds its tolerance"
    AGREE = "agree"


class CrossCheckRow(NamedTuple):
    """Slip-onset depths (m) of one angle of a cross-check (:func:`mdr_events.cross_check`)."""

    radius: float
    scenario: str
    alpha: float
    closed_form: float
    continuum: float
    discrete: float
    discrete_minus_continuum: float
    tolerance: float
    verdict: SlipOnsetVerdict


def _slip_onset_verdict(row: xr.Dataset, scenario: str, params: Parameters) -> SlipOnsetVerdict:
    closed = float(row["d_crit_closed_form"])
    if scenario == "A" and closed > params.d_max:
        return SlipOnsetVerdict.NO_SLIP_IN_INDENTATION
    if scenario == "B" and closed == -math.inf:
        return SlipOnsetVerdict.JUMP_OFF_FIRST
    if int(row["found_once_at_phase_end"]):
        return SlipOnsetVerdict.FOUND_ONCE_AT_PHASE_END
    if int(row["pinned_radius"]):
        return SlipOnsetVerdict.PINNED
    if int(row["disagree"]):
        return SlipOnsetVerdict.DISAGREE
    return SlipOnsetVerdict.AGREE


def cross_check_rows(data: Reproduction) -> list[CrossCheckRow]:
    """One row per angle of every cross-check, in the order computed."""
    rows = []
    for (label, scenario), ds in data.cross_checks.items():
        params = Parameters.from_attrs(ds.attrs)
        for alpha in ds["alpha"].values:
            row = ds.sel(alpha=alpha)
            rows.append(CrossCheckRow(
                params.R, scenario, alpha, float(row["d_crit_closed_form"]), float(row["d_crit_continuum"]),
                float(row["d_crit_discrete"]), float(row["discrete_minus_continuum"]),
                float(row["discrete_tolerance"]), _slip_onset_verdict(row, scenario, params)))
    return rows


# ----------------------------------------------------------------------------
# the four differences between simulation and experiment (section 4.2)
class AdhesiveStrengthRow(NamedTuple):
    """|F_N,min| (N) of one (radius, scenario): JKR, the continuum over the angles, the discrete model."""

    radius: float
    scenario: str
    jkr: float  #: (3/2) π Δγ1 R
    continuum_min: float
    continuum_max: float
    largest_relative_difference: float  #: of the continuum from JKR
    discrete: float  #: at :data:`OVERLAY_ANGLE`


class PinnedIntervalRow(NamedTuple):
    """The interval (s) after ``d_max`` during which the radius stays pinned, and ``F_x``'s change (N) over it."""

    alpha: float
    d_max_time: float
    detachment_time: float
    tangential_force_change: float

    @property
    def duration(self) -> float:
        return self.detachment_time - self.d_max_time


class MaximaRow(NamedTuple):
    """Exact maxima of one continuum run (SI units)."""

    alpha: float
    normal_force: float
    tangential_force: float
    contact_area: float
    mean_pressure: float


class ShearPlateauRow(NamedTuple):
    """Whether the mean shear stress of a scenario-A run reaches ``τ0`` before the jump-off."""

    radius: float
    alpha: float
    travel: float  #: x1 = d_max / tan α (m)
    shift_at_jump_off: float  #: ū(a_jump-off) (m)
    largest_shear_stress: float  #: Pa
    reaches_tau0: bool
    full_slip_time: float | None  #: s, the last full slip; None if none


class AreaGrowthRow(NamedTuple):
    """How smoothly the contact area grows during indentation in one run."""

    alpha: float
    jump_in_area: float  #: π a0² (m²)
    largest_step_share: float  #: largest change between samples, as a share of A_max
    sample_spacing: float  #: s


@dataclass
class Differences:
    """The tables of the four differences between simulation and experiment of section 4.2."""

    samples_per_run: int
    adhesive_strength: list[AdhesiveStrengthRow]
    pinned_intervals: list[PinnedIntervalRow]
    maxima: list[MaximaRow]
    shear_plateau: list[ShearPlateauRow]
    area_growth: list[AreaGrowthRow]


def adhesive_strength_rows(data: Reproduction) -> list[AdhesiveStrengthRow]:
    """|F_N,min| against JKR's (3/2) π Δγ1 R for every (radius, scenario)."""
    rows = []
    for (label, scenario), ds in data.continuum.items():
        params = Parameters.from_attrs(ds.attrs)
        jkr = -analytic.pull_off_force(params, params.dgamma1)
        values = -data.extremes[(label, scenario)]["normal_force_min"]
        worst = np.max(np.abs(values - jkr)) / jkr
        discrete = -float(data.discrete[(label, scenario)]["normal_force"].min())
        rows.append(AdhesiveStrengthRow(params.R, scenario, jkr, values.min(), values.max(), worst, discrete))
    return rows


def pinned_interval_rows(ds: xr.Dataset) -> list[PinnedIntervalRow]:
    """From ``d_max`` (the corner) to the start of detachment, per angle of a continuum run."""
    rows = []
    for alpha in ds["alpha"].values:
        corner = _first(event_times(ds, alpha, "corner"))
        release = _first(event_times(ds, alpha, "detachment_starts"))
        case = ds.sel(alpha=alpha)
        inside = (case["time"] >= corner) & (case["time"] <= release)
        force = case["tangential_force"].values[inside.values]
        change = float(np.max(force) - np.min(force)) if force.size else math.nan
        rows.append(PinnedIntervalRow(alpha, corner, release, change))
    return rows


def maxima_rows(ds: xr.Dataset, extremes: dict[str, np.ndarray]) -> list[MaximaRow]:
    """The exact maxima of each angle's run (``extremes``: :attr:`Reproduction.extremes` of its case)."""
    return [MaximaRow(alpha, extremes["normal_force_max"][i], extremes["tangential_force_max"][i],
                      extremes["contact_area_max"][i], extremes["mean_pressure_max"][i])
            for i, alpha in enumerate(ds["alpha"].values)]


def shear_plateau_rows(data: Reproduction) -> list[ShearPlateauRow]:
    """Every scenario-A angle of every radius: does τ reach τ0 in pull-off?"""
    rows = []
    for (label, scenario), ds in data.continuum.items():
        if scenario != "A":
            continue
        params = Parameters.from_attrs(ds.attrs)
        cap = float(analytic.critical_shift(analytic.jump_off(params, params.dgamma1)["contact_radius"], params))
        for i, alpha in enumerate(ds["alpha"].values):
            x1 = params.d_max / math.tan(math.radians(alpha))
            tau = float(data.extremes[(label, scenario)]["mean_shear_stress_max"][i])
            full = event_times(ds, alpha, "full_slip")
            rows.append(ShearPlateauRow(params.R, alpha, x1, cap, tau, math.isclose(tau, params.tau0, rel_tol=1e-9),
                                        float(full[-1]) if len(full) else None))
    return rows


def area_growth_rows(ds: xr.Dataset) -> list[AreaGrowthRow]:
    """The jump-in area and the largest change of A between samples before ``d_max``, per angle."""
    rows = []
    for alpha in ds["alpha"].values:
        case = ds.sel(alpha=alpha)
        corner = _first(event_times(ds, alpha, "corner"))
        area = case["contact_area"].values
        indentation = case["time"].values <= corner
        steps = np.abs(np.diff(area[indentation]))
        spacing = float(case["time"].values[1] - case["time"].values[0])
        rows.append(AreaGrowthRow(alpha, area[0], steps.max() / np.nanmax(area), spacing))
    return rows


def differences(data: Reproduction) -> Differences:
    """The tables of the four differences (the detailed ones of :data:`DETAIL_CASE`)."""
    detail = data.continuum[DETAIL_CASE]
    return Differences(
        samples_per_run=detail.sizes["time"],
        adhesive_strength=adhesive_strength_rows(data),
        pinned_intervals=pinned_interval_rows(detail),
        maxima=maxima_rows(detail, data.extremes[DETAIL_CASE]),
        shear_plateau=shear_plateau_rows(data),
        area_growth=area_growth_rows(detail),
    )


# ----------------------------------------------------------------------------
# convergence of the discrete model
class ConvergenceRow(NamedTuple):
    """Relative errors of one quantity, one per spacing, and the observed orders between neighbours."""

    case: float | str  #: the angle (degrees) or the scenario
    quantity: str
    errors: np.ndarray
    orders: np.ndarray


def extremum_convergence(data: Reproduction) -> list[ConvergenceRow]:
    """Errors of the :data:`CONVERGENCE_EXTREMA` against their exact values, per angle and spacing."""
    return [ConvergenceRow(alpha, key, errors[key], observed_orders(CONVERGENCE_SPACINGS, errors[key]))
            for alpha, errors in data.discrete_errors.items() for key in CONVERGENCE_EXTREMA]


class HistoryConvergence(NamedTuple):
    """The discrete model against the continuum over a whole run of one scenario."""

    rows: list[ConvergenceRow]  #: one per quantity of :data:`HISTORY_QUANTITIES`
    samples_left_out: list[int]  #: one per spacing


def history_convergence(data: Reproduction) -> dict[str, HistoryConvergence]:
    """Per scenario: ``max |discrete − continuum| / max |continuum|`` over :data:`HISTORY_SPACINGS`."""
    result = {}
    for scenario, history in data.history.items():
        rows = [ConvergenceRow(scenario, name, history[name], observed_orders(HISTORY_SPACINGS, history[name]))
                for name in HISTORY_QUANTITIES]
        result[scenario] = HistoryConvergence(rows, [int(n) for n in history["samples_left_out"]])
    return result


# ----------------------------------------------------------------------------
# fretting at d_max
class FrettingContact(NamedTuple):
    """The contact the fretting study slides: indented to ``d_max`` on the ``Δγ0`` branch, then fixed (SI units)."""

    radius: float  #: a_max, the Δγ0 contact radius at d_max
    cap: float  #: ū(a_max) = π a_max τ0 / (2G*), eq. (13)
    amplitude: float  #: X = :data:`FRETTING_AMPLITUDE_IN_CAPS` ū(a_max)
    sliding_force: float  #: π a_max² τ0, the plateau of F_x in full slip
    params: Parameters  #: the parameters (τ0, G*) of the closed forms

    @property
    def stiffness(self) -> float:
        """The slope ``2G* a_max`` of F_x against x while every spring sticks (N/m): the plateaus' gap ``2π a² τ0``
        over the travel ``2ū`` between them."""
        return self.sliding_force / self.cap

    @property
    def dissipated_energy(self) -> float:
        """The energy dissipated per cycle ``x_c − X → x_c + X → x_c − X``: ``4 π a² τ0 (X − ū)`` (J), the area of
        the parallelogram (``X > ū``), :func:`mdr_events.theory.analytic.fretting_dissipated_energy`."""
        return float(analytic.fretting_dissipated_energy(self.radius, self.amplitude, self.params))

    def parallelogram(self, centre: float) -> tuple[np.ndarray, np.ndarray]:
        """The corners ``(x, F_x)`` of the closed loop about ``centre``, closed (the first corner again last):
        ``(x_c + X, +P) → (x_c + X − 2ū, −P) → (x_c − X, −P) → (x_c − X + 2ū, +P) → (x_c + X, +P)``,
        ``P = π a² τ0``."""
        X, travel, plateau = self.amplitude, 2.0 * self.cap, self.sliding_force
        x = centre + np.array([X, X - travel, -X, -X + travel, X])
        force = plateau * np.array([1.0, -1.0, -1.0, 1.0, 1.0])
        return x, force


def fretting_contact(params: Parameters) -> FrettingContact:
    """The fixed contact at ``d_max`` of the fretting study and its amplitude (:class:`FrettingContact`)."""
    radius = float(analytic.jkr_contact_radius(params.d_max, params, params.dgamma0))
    cap = float(analytic.critical_shift(radius, params))
    return FrettingContact(radius, cap, FRETTING_AMPLITUDE_IN_CAPS * cap, math.pi * radius**2 * params.tau0, params)


def fretting_paths(params: Parameters) -> dict[str, Path]:
    """The fretting study's paths by case label: in to ``d_max`` (vertically to ``x_c = 0``, or along scenario A's
    in-path at :data:`FRETTING_ANGLE` to ``x_c = d_max / tan α``), then :data:`FRETTING_CYCLES` full cycles
    ``x_c → x_c + X → x_c − X → … → x_c + X`` at ``d_max``, then out vertically to
    :func:`~mdr_events.models.paths.exit_depth`."""
    amplitude = fretting_contact(params).amplitude
    approaches = {FRETTING_VERTICAL: (0.0, params.d_max),
                  FRETTING_OBLIQUE: tuple(Path.scenario_A(FRETTING_ANGLE, params).waypoints[1])}
    paths = {}
    for label, (centre, depth) in approaches.items():
        points = [(0.0, 0.0), (centre, depth)]
        points += [(centre + (amplitude if k % 2 == 0 else -amplitude), depth) for k in range(2 * FRETTING_CYCLES + 1)]
        points.append((points[-1][0], exit_depth(params)))
        paths[label] = Path(points, params.v)
    return paths


#: The event kind that marks a tangential reversal (its ``event_direction``: the new direction, ±1).
REVERSAL_KIND = "tangential_reversal"


def closed_loop_times(dataset: xr.Dataset, label: str) -> tuple[float, float]:
    """The last closed loop of a case: the times (s from first contact) of its last tangential reversal and of
    the one before it in the same direction (the continuum event log).

    Raises
    ------
    ValueError
        If the case has no two reversals of the same direction.
    """
    case = dataset.sel({case_dimension(dataset): label})
    kinds = case["event_kind"].values.astype(str)
    reversals = kinds == REVERSAL_KIND
    times = case["event_time"].values[reversals]
    directions = case["event_direction"].values[reversals]
    earlier = np.flatnonzero(directions[:-1] == directions[-1]) if len(times) else np.array([], dtype=int)
    if len(earlier) == 0:
        raise ValueError(f"case {label!r} has {len(times)} tangential reversal(s) and no two of the same direction; "
                         "allowed: a path that closes a tangential loop")
    return float(times[earlier[-1]]), float(times[-1])


def discrete_loop_work(dataset: xr.Dataset, label: str, start: float, end: float) -> float:
    """``∫ F_x dx`` (J) of a sampled simulation over ``[start, end]`` (s): the trapezoid rule on the samples
    in it (its ends lie up to one time step inside the interval)."""
    case = dataset.sel({case_dimension(dataset): label})
    inside = (case["time"].values >= start) & (case["time"].values <= end)
    x = case["tangential_displacement"].values[inside]
    force = case["tangential_force"].values[inside]
    return float(np.sum(0.5 * (force[1:] + force[:-1]) * np.diff(x)))


@dataclass
class FrettingStudy:
    """The fretting study's results: the continuum (with :data:`FRETTING_VARIABLES`) and the discrete model."""

    continuum: xr.Dataset
    discrete: xr.Dataset


def _with_fretting_variables(dataset: xr.Dataset, params: Parameters, values: dict[str, np.ndarray]) -> xr.Dataset:
    """``dataset`` with the :data:`FRETTING_VARIABLES` ``values`` added (data variables first, coordinates last,
    as a file reads back) and stamped as the fretting study."""
    data = {name: dataset[name].variable for name in dataset.data_vars}
    for name, (dims, units, long_name) in FRETTING_VARIABLES.items():
        data[name] = xr.Variable(dims, np.asarray(values[name], dtype=float), {"units": units, "long_name": long_name})
    coords = {name: dataset[name].variable for name in dataset.coords}
    coords["corner"] = xr.Variable(("corner",), np.arange(PARALLELOGRAM_CORNERS),
                                   {"units": "1", "long_name": "corner of the closed-form loop (the first again last)"})
    return stamp(xr.Dataset(data, coords=coords, attrs=dataset.attrs), params, study=FRETTING_STUDY,
                 fretting_cycles=FRETTING_CYCLES, fretting_amplitude_in_caps=FRETTING_AMPLITUDE_IN_CAPS)


def fretting_study(params: Parameters, samples: int | None = None, dx: float = FIGURE_DX,
                   n_steps: int = FIGURE_STEPS) -> FrettingStudy:
    """Run the fretting study (:func:`fretting_paths`) with the continuum method and the discrete model.

    Parameters
    ----------
    params : Parameters
    samples : int, optional
        Output times of the continuum (default that of :func:`~mdr_events.models.simulate.simulate`).
    dx, n_steps : float, int
        The discrete model's spring spacing (m) and time steps (of the longest case).

    Returns
    -------
    FrettingStudy
        The continuum dataset carries, per case, the contact, the amplitude, the last closed loop's times
        (:func:`closed_loop_times`), the energy dissipated over it (``tangential_work`` of the solution) beside
        the closed form, and the closed-form parallelogram (:data:`FRETTING_VARIABLES`).
    """
    paths = fretting_paths(params)
    contact = fretting_contact(params)
    continuum = simulate(params, paths, method="continuum", samples=samples)
    values: dict[str, list] = {name: [] for name in FRETTING_VARIABLES}
    for label, path in paths.items():
        start, end = closed_loop_times(continuum, label)
        centre = float(path.waypoints[1, 0])
        corners_x, corners_force = contact.parallelogram(centre)
        for name, value in (("fretting_centre", centre), ("fretting_amplitude", contact.amplitude),
                            ("fretting_contact_radius", contact.radius), ("fretting_critical_shift", contact.cap),
                            ("fretting_loop_start", start), ("fretting_loop_end", end),
                            ("dissipated_energy", tangential_work(solve_path(params, path), start, end)),
                            ("dissipated_energy_closed_form", contact.dissipated_energy),
                            ("parallelogram_x", corners_x), ("parallelogram_force", corners_force)):
            values[name].append(value)
    arrays = {name: np.array(value, dtype=float) for name, value in values.items()}
    discrete = simulate(params, paths, dx=dx, n_steps=n_steps)
    return FrettingStudy(_with_fretting_variables(continuum, params, arrays), discrete)


class FrettingRow(NamedTuple):
    """The energy dissipated over the last closed loop of one fretting case (J), three ways."""

    case: str
    centre: float  #: x_c (m)
    amplitude: float  #: X (m)
    cap: float  #: ū(a_max) (m)
    contact_radius: float  #: a_max (m)
    loop_start: float  #: s from first contact
    loop_end: float  #: s from first contact
    closed_form: float  #: 4 π a² τ0 (X − ū)
    continuum: float  #: tangential_work over the loop
    discrete: float  #: trapezoid of the discrete model's samples over the loop

    @property
    def continuum_difference(self) -> float:
        """``|continuum − closed form| / closed form``."""
        return abs(self.continuum - self.closed_form) / self.closed_form

    @property
    def discrete_difference(self) -> float:
        """``(discrete − closed form) / closed form`` (signed)."""
        return (self.discrete - self.closed_form) / self.closed_form


def fretting_rows(study: FrettingStudy) -> list[FrettingRow]:
    """One row per case of the fretting study, read from its datasets."""
    rows = []
    continuum = study.continuum
    for label in continuum[CUSTOM_DIMENSION].values:
        case = continuum.sel({CUSTOM_DIMENSION: label})
        start, end = float(case["fretting_loop_start"]), float(case["fretting_loop_end"])
        rows.append(FrettingRow(
            str(label), float(case["fretting_centre"]), float(case["fretting_amplitude"]),
            float(case["fretting_critical_shift"]), float(case["fretting_contact_radius"]), start, end,
            float(case["dissipated_energy_closed_form"]), float(case["dissipated_energy"]),
            discrete_loop_work(study.discrete, str(label), start, end)))
    return rows
