"""``simulate``: one entry point for every simulation method, one result schema."""

from __future__ import annotations

import dataclasses
import math
from typing import Any, Literal, Mapping, NamedTuple, Sequence

import numpy as np
import xarray as xr

from mdr_events.io.agreement import (ExtremumTime, Integrated, Quotient, RootFound, RoundOff, force_sensitivity,
                                     register_accuracy)
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.models.continuum import Tolerances, run_continuum
from mdr_events.models.continuum.solution import EXTREMUM_XTOL
from mdr_events.models.continuum.extrema import EXTREMA_KINDS, EXTREMA_QUANTITIES, extremum_names, solution_extrema
from mdr_events.models.discrete import check_spacing, run_discrete
from mdr_events.theory.scales import check_representable
from mdr_events.models.paths import Path
from mdr_events.models import indenters
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.parameters import Parameters, check_parameters
from mdr_events.contact.friction import TAU0, FrictionLaw, as_friction_law, friction_attrs
from mdr_events.models.continuum.caps import check_supported
from mdr_events.theory import analytic
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.validation import check_choice, check_count, check_real, real_array, shown, validate_alpha

__all__ = ["simulate", "Cases", "simulation_cases", "scenario_paths", "case_dimension", "simulation_dataset",
           "event_log", "extrema_dataset", "FIGURE_ANGLES", "METHODS", "SCENARIO_NAMES", "CASE_DIMENSIONS",
           "SIMULATION_CONTENT", "SIMULATION_VARIABLES", "EVENT_VARIABLES", "PATH_VARIABLES", "EXTREMA_VARIABLES"]

#: The angles of Fig. 8 and Fig. 10.
FIGURE_ANGLES = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
METHODS = ("discrete", "continuum")
SCENARIO_NAMES = ("A", "B", "B+")
DEFAULT_DX = 1e-6
DEFAULT_STEPS = 10_000
DEFAULT_SAMPLES = 2001


#: The ``content`` attribute of a simulation.
SIMULATION_CONTENT = "simulation of indentation and detachment along straight paths"
#: The dimension of a simulation's cases: ``alpha`` (path angle, degrees) for the paper's scenarios,
#: ``case`` (a name) for custom paths.
ANGLE_DIMENSION, CUSTOM_DIMENSION = "alpha", "case"
CASE_DIMENSIONS = (ANGLE_DIMENSION, CUSTOM_DIMENSION)
#: The ``scenario`` attribute of a simulation of custom paths.
CUSTOM_SCENARIO = "custom"
#: The variables of a simulation, shared by every method (dims ``(case dimension, "time")``): name -> (units, long_name).
SIMULATION_VARIABLES: dict[str, tuple[str, str]] = {
    "indentation_depth": ("m", "indentation depth d"),
    "tangential_displacement": ("m", "tangential displacement of the indenter x"),
    "normal_force": ("N", "normal force F_N"),
    "tangential_force": ("N", "tangential force F_x"),
    "contact_radius": ("m", "contact radius a"),
    "contact_area": ("m2", "contact area A"),
    "mean_pressure": ("Pa", "mean contact pressure <p> = F_N / A"),
    "mean_shear_stress": ("Pa", "mean shear stress tau = F_x / A"),
    "sliding_fraction": ("1", "share of the springs in contact that are at the critical shift"),
}
#: The continuum method's event log (dims ``(case dimension, "event")``): name -> (units, long_name).
EVENT_VARIABLES: dict[str, tuple[str, str]] = {
    "event_time": ("s", "time of the event from first contact"),
    "event_kind": ("1", "kind of event"),
    "event_depth": ("m", "indentation depth at the event"),
    "event_radius": ("m", "contact radius at the event"),
    "event_x": ("m", "tangential displacement at the event"),
    "event_direction": ("1", "direction of the event: +1 or -1 the cap u = +ū or -ū of a slip event, or the new "
                             "direction of the tangential motion at a reversal; 0 for other events and padding"),
}
#: Custom paths: what each case's path is (dims ``("case",)``): name -> (units, long_name).
PATH_VARIABLES: dict[str, tuple[str, str]] = {
    "path_waypoints": ("m", "waypoints (x, d) of the custom path, joined by straight segments"),
    "path_speed": ("m s-1", "speed along the custom path (replaces param_v)"),
}
#: Symbols of the quantities of :data:`EXTREMA_QUANTITIES` and their units, for the long names.
EXTREMA_SYMBOLS = {"normal_force": ("F_N", "N"), "tangential_force": ("F_x", "N"), "contact_area": ("A", "m2")}
EXTREMA_WORDS = {"max": "maximum", "min": "minimum"}


def _extrema_variables() -> dict[str, tuple[str, str]]:
    """Name -> (units, long_name) of every key of :func:`solution_extrema`."""
    variables = {}
    for quantity in EXTREMA_QUANTITIES:
        symbol, units = EXTREMA_SYMBOLS[quantity]
        for kind in EXTREMA_KINDS:
            value_name, time_name = extremum_names(quantity, kind)
            word = EXTREMA_WORDS[kind]
            variables[value_name] = (units, f"{word} of {symbol} over the run, exact from the continuum solution "
                                            "(not from the samples)")
            variables[time_name] = ("s", f"time of the {word} of {symbol} from first contact, exact from the "
                                         "continuum solution")
    return variables


#: The continuum method's exact extrema (dims ``(case dimension,)``; :func:`solution_extrema`, where the
#: value 0 after a pull-off counts, at the end of the run): name -> (units, long_name).
EXTREMA_VARIABLES: dict[str, tuple[str, str]] = _extrema_variables()

register_schema(SIMULATION_CONTENT, {name: (CASE_DIMENSIONS, "time") for name in SIMULATION_VARIABLES})
register_schema(SIMULATION_CONTENT, {**{name: (CASE_DIMENSIONS, "event") for name in EVENT_VARIABLES},
                                     **{name: (CASE_DIMENSIONS,) for name in EXTREMA_VARIABLES}},
                when=("method", "continuum"))
register_schema(SIMULATION_CONTENT, {name: (CUSTOM_DIMENSION,) for name in PATH_VARIABLES},
                when=("scenario", CUSTOM_SCENARIO))

#: How each quantity of a simulation is computed (:mod:`mdr_events.io.agreement`). The discrete model: closed
#: forms of the path and sums over the springs; the means are quotients by the area.
MEANS = {"mean_pressure": Quotient("normal_force", "contact_area"),
         "mean_shear_stress": Quotient("tangential_force", "contact_area")}
register_accuracy(SIMULATION_CONTENT, {**{name: RoundOff() for name in SIMULATION_VARIABLES}, **MEANS,
                                       "time": RoundOff(), ANGLE_DIMENSION: RoundOff(), "path_speed": RoundOff()})


def _continuum_accuracy() -> dict:
    """How the continuum computes what differs from the discrete model: the path is a closed form of time; ``F_N``,
    ``a`` and ``A`` closed forms of the radius, a root found to ``radius_rtol``; ``F_x`` and the springs' slip
    integrated to ``rtol``, and so the events (crossings of integrated quantities); each extremum as accurate as
    its quantity, its time as the curvature there allows."""
    integrated = {name: Integrated() for name in EVENT_VARIABLES if name not in ("event_kind", "event_direction")}
    declared = {"normal_force": RootFound(sensitivity=force_sensitivity), "contact_radius": RootFound(),
                "contact_area": RootFound(sensitivity=2.0),
                "tangential_force": Integrated(), "sliding_fraction": Integrated(), **integrated}
    for quantity in EXTREMA_QUANTITIES:
        for kind in EXTREMA_KINDS:
            value, time = extremum_names(quantity, kind)
            declared[value] = dataclasses.replace(declared[quantity], scale_of=quantity)
            declared[time] = ExtremumTime(value, quantity, search_share=EXTREMUM_XTOL)
    return declared


CONTINUUM_ACCURACY = _continuum_accuracy()
register_accuracy(SIMULATION_CONTENT, CONTINUUM_ACCURACY, when=("method", "continuum"))


#: Relative accuracy the slip criterion needs: x − X(ξ) against ū(a) must keep this many digits.
SLIP_DIGITS = 1e-9


def check_path_extent(params: Parameters, path: Path, label: str, profile: SimulatedProfile = None) -> None:
    """Reject a path so long that ``x − X(ξ)`` cannot be compared with ``ū(a)`` in double precision.

    The positions along the path are rounded to ``eps · |x|``; the slip
    criterion compares differences of them with ``ū(a)`` (at ``d_max``) or,
    without friction, with ``d_max``. A path whose tangential extent exceeds
    ``SLIP_DIGITS · max(ū, d_max) / eps`` (about 3 km for the paper's
    parameters: a path angle of a few 1e-6 degrees) is an error, not a
    silently wrong result.
    """
    indenters.check_reach(params, path.max_depth, profile, label)
    radius = float(indenters.branch_radius(params.d_max, params, params.dgamma0, profile))
    reference = max(float(analytic.critical_shift(radius, params)), params.d_max)
    limit = SLIP_DIGITS * reference / np.finfo(float).eps
    extent = float(np.max(np.abs(path.waypoints[:, 0])))
    if extent > limit:
        raise ValueError(f"{label}: the path reaches x = {extent:.3g} m; allowed: |x| <= {limit:.3g} m, beyond "
                         f"which double precision cannot resolve the slip criterion (shift vs {reference:.3g} m)")


class Cases(NamedTuple):
    """The cases of a simulation: one path each, labelled along ``dimension`` by ``labels``."""

    paths: list[Path]
    #: ``"alpha"`` (the paper's scenarios) or ``"case"`` (custom paths)
    dimension: str
    #: the angles in degrees (float) or the case names (str), one per path
    labels: np.ndarray

    @property
    def custom(self) -> bool:
        return self.dimension == CUSTOM_DIMENSION


#: What ``scenario`` may be, for messages.
SCENARIO_ALLOWED = ("'A', 'B', 'B+', a Path, a non-empty list of Paths, or a non-empty mapping "
                    "{label (non-empty str): Path}")


def _custom_paths(scenario: Path | Sequence[Path] | Mapping[str, Path]) -> dict[str, Path]:
    """The custom paths of ``scenario`` by label; a single path or a list is labelled ``"path 1"``, ...

    Raises ``ValueError`` for an empty list or mapping or repeated labels and ``TypeError`` for an
    element that is not a :class:`Path` or a label that is not a non-empty string.
    """
    if isinstance(scenario, Path):
        return {"path 1": scenario}
    if isinstance(scenario, Mapping):
        labels, paths = list(scenario.keys()), [scenario[label] for label in scenario.keys()]
        where = [f"scenario[{label!r}]" for label in labels]
    else:
        paths = list(scenario)
        labels = [f"path {number}" for number in range(1, len(paths) + 1)]
        where = [f"scenario[{index}]" for index in range(len(paths))]
    if not paths:
        raise ValueError(f"scenario={scenario!r} is not allowed: it holds no path; allowed: {SCENARIO_ALLOWED}")
    for label in labels:
        if not isinstance(label, str) or not label:
            raise TypeError(f"scenario has the label {label!r} ({type(label).__name__}); allowed: labels that are "
                            "non-empty strings")
    repeated = sorted({label for label in labels if labels.count(label) > 1})
    if repeated:
        raise ValueError(f"scenario has the label(s) {repeated} more than once; allowed: distinct labels")
    for name, path in zip(where, paths):
        if not isinstance(path, Path):
            raise TypeError(f"{name}={path!r} ({type(path).__name__}) is not allowed; allowed: a "
                            "mdr_events.Path")
    return dict(zip(labels, paths))


def simulation_cases(params: Parameters, scenario, alpha, profile: SimulatedProfile = None) -> Cases:
    """The cases of ``simulate(params, scenario, alpha)``, each path checked by :func:`check_path_extent`
    (the scenarios' paths end below the jump-off of ``profile``'s ``Δγ1`` branch).

    A scenario name gives one path per angle along ``alpha``; custom paths (a :class:`Path`, a list
    of them or a mapping ``{label: Path}``) give one case each along ``case``, labelled by the
    mapping's keys or ``"path 1"``, ``"path 2"``, ... (``alpha`` must then be ``None``).
    """
    if isinstance(scenario, str):
        if scenario not in SCENARIO_NAMES:
            raise ValueError(f"scenario={scenario!r} is not allowed; allowed: {SCENARIO_ALLOWED}")
        angles = np.atleast_1d(validate_alpha(FIGURE_ANGLES if alpha is None else alpha))
        if angles.ndim != 1 or angles.size == 0:
            raise ValueError(f"alpha of shape {angles.shape} is not allowed; allowed: one angle or a 1-D list")
        values, counts = np.unique(angles, return_counts=True)
        if np.any(counts > 1):
            raise ValueError(f"alpha={shown(alpha)} repeats {float(values[counts > 1][0])!r}; allowed: distinct "
                             "angles (each labels one case)")
        build = {"A": Path.scenario_A, "B": Path.scenario_B, "B+": Path.scenario_B_indentation}[scenario]
        paths = []
        for angle in angles:
            label = f"alpha={float(angle)!r} (degrees) in scenario {scenario}"
            try:  # (an angle of 1e-300° makes waypoints 1e298 m apart: the path refuses them, the angle is named)
                path = build(float(angle), params, profile=profile)
            except ValueError as error:
                if str(error).startswith("alpha="):  # (the path names the angle itself)
                    raise
                raise ValueError(f"{label}: {error}") from None
            check_path_extent(params, path, label, profile)
            paths.append(path)
        return Cases(paths, ANGLE_DIMENSION, angles)
    if not isinstance(scenario, (Path, Mapping, list, tuple)):
        raise TypeError(f"scenario={scenario!r} ({type(scenario).__name__}) is not allowed; allowed: "
                        f"{SCENARIO_ALLOWED}")
    custom = _custom_paths(scenario)
    if alpha is not None:
        raise ValueError(f"alpha={alpha!r} is not allowed with custom paths (their waypoints fix the motion); "
                         "allowed: alpha=None")
    for label, path in custom.items():
        check_path_extent(params, path, f"scenario path {label!r}", profile)
    return Cases(list(custom.values()), CUSTOM_DIMENSION, np.array(list(custom), dtype=str))


def scenario_paths(params: Parameters, scenario, alpha, profile: SimulatedProfile = None) -> tuple[list[Path], np.ndarray]:
    """The paths of :func:`simulation_cases` and their labels (angles in degrees, or case names)."""
    cases = simulation_cases(params, scenario, alpha, profile)
    return cases.paths, cases.labels


def case_dimension(dataset: xr.Dataset) -> str:
    """The dimension along which a simulation's cases lie: ``"case"`` (custom paths) or ``"alpha"``."""
    found = [name for name in CASE_DIMENSIONS if name in dataset.dims]
    if len(found) != 1:
        raise ValueError(f"a simulation with the dimensions {tuple(dataset.dims)} is not allowed; allowed: "
                         f"exactly one of {CASE_DIMENSIONS}")
    return found[0]


def case_text(dimension: str, label) -> str:
    """How a case is named in messages and legends: ``α = 20°`` or its label."""
    return f"α = {float(label):g}°" if dimension == ANGLE_DIMENSION else str(label)


def _time_step(paths: list[Path], dt: float | None, n_steps: int | None) -> float:
    if dt is not None and n_steps is not None:
        raise ValueError("give dt or n_steps, not both")
    longest = max(path.duration - path.first_contact_time() for path in paths)
    if dt is not None:
        return check_real("dt", dt, "a finite time step > 0 (s)", lambda value: value > 0)
    steps = DEFAULT_STEPS if n_steps is None else check_count("n_steps", n_steps, 10)
    return longest / steps


#: The discrete model needs at least this many time steps on every path segment it is in contact on.
MIN_STEPS_PER_SEGMENT = 10


def check_time_step(paths: list[Path], step: float, dt: float | None, n_steps: int | None) -> None:
    """Reject a time step that cannot resolve a path segment after first contact.

    Every segment (from first contact on) must get :data:`MIN_STEPS_PER_SEGMENT`
    steps; otherwise, e.g. for a tiny ``d_max``, the discrete model would jump
    over the whole indentation. The error names the largest ``dt`` (or the
    smallest ``n_steps``) that would do.
    """
    shortest = math.inf
    for path in paths:
        start = path.first_contact_time()
        times = path.corner_times
        for t0, t1 in zip(times[:-1], times[1:]):
            if t1 > start:
                shortest = min(shortest, t1 - max(t0, start))
    largest = shortest / MIN_STEPS_PER_SEGMENT
    if step <= largest * (1 + 1e-12):
        return
    if dt is not None:
        raise ValueError(f"dt={dt!r} is too coarse: the shortest path segment in contact lasts {shortest:.6g} s; "
                         f"allowed: dt <= {largest:.6g} s ({MIN_STEPS_PER_SEGMENT} steps per segment)")
    longest = max(path.duration - path.first_contact_time() for path in paths)
    needed = math.ceil(longest / largest)
    given = DEFAULT_STEPS if n_steps is None else n_steps
    raise ValueError(f"n_steps={given!r} is too few: the shortest path segment in contact lasts {shortest:.6g} s of "
                     f"{longest:.6g} s; allowed: n_steps >= {needed} (or dt <= {largest:.6g} s)")


def simulate(
    params: Parameters,
    scenario: Literal["A", "B", "B+"] | Path | Sequence[Path] | Mapping[str, Path] = "A",
    alpha: float | Sequence[float] | None = None,
    method: Literal["discrete", "continuum"] = "discrete",
    dx: float | None = None,
    dt: float | None = None,
    n_steps: int | None = None,
    t: Sequence[float] | None = None,
    samples: int | None = None,
    tolerances: Tolerances | None = None,
    limits: Limits | None = None,
    profile: SimulatedProfile = None,
    friction: FrictionLaw | str | None = None,
) -> xr.Dataset:
    """Simulate indentation and detachment along straight paths.

    Parameters
    ----------
    params : Parameters
    scenario : {"A", "B", "B+"}, Path, list of Path or mapping of str to Path
        ``"A"``: eq. (14); ``"B"``: eq. (19); ``"B+"``: the "+" branch of
        Fig. 9b (:meth:`Path.scenario_B_indentation`): one case per angle.
        Custom paths: a :class:`Path`, a non-empty list of them (labelled
        ``"path 1"``, ``"path 2"``, ...) or a mapping ``{label: Path}`` (its
        keys, non-empty strings, are the labels): one case per path; the
        paths may have different speeds.
    alpha : float or sequence of float, optional
        Angles in degrees (default 10°, 20°, …, 80°, as in Fig. 8 and 10);
        not with custom paths.
    method : {"discrete", "continuum"}
        ``"discrete"``: the paper's spring array (:mod:`mdr_events.models.discrete`).
        ``"continuum"``: its Δx → 0 limit integrated between events
        (:mod:`mdr_events.models.continuum`); adds the event log along
        ``event`` and each case's exact extrema (:data:`EXTREMA_VARIABLES`).
    dx : float, optional
        Discrete method: spring spacing Δx in m (default 1 µm); at least 10
        springs per side must be in contact at ``d_max``.
    dt, n_steps :
        Discrete method: time step in s, or the number of steps of the
        longest case (default 10 000); not both. One time grid serves every case.
    t : sequence of float, optional
        Continuum method: the output times in s from first contact
        (increasing, >= 0); default ``samples`` points to the end of the longest run.
    samples : int, optional
        Continuum method without ``t``: number of output times (default 2001, at least 2).
    tolerances : mdr_events.models.continuum.Tolerances, optional
        Continuum method: solver and root-finding tolerances (default
        ``Tolerances()``: ``rtol = 1e-10``, ``atol = 1e-14`` N, ``radius_rtol = 1e-14``).
    limits : Limits, optional
        What the run may use (default ``Limits()``: 2 GiB, 2e7 discrete steps, 1e7 springs per side, 1e7
        output samples, 2000 waypoints per path for the continuum); a larger run is refused before it
        starts with :class:`~mdr_events.limits.ResourceLimitError` giving the estimate.
    profile : PowerLaw, optional
        The indenter, a power law ``f = c rⁿ`` with ``n >= 1`` (:class:`~mdr_events.contact.indenters.PowerLaw`; the
        cone is ``n = 1``); default ``None``, the paper's paraboloid of ``params.R`` (then ``R`` is the
        only use of the indenter's shape). Both methods take it; the dataset then has the attribute
        ``profile`` saying which (absent: the paraboloid).
    friction : FrictionLaw or str, optional
        The cap on the springs' shifts (:mod:`mdr_events.contact.friction`): default the paper's ``"tau0"``;
        ``FrictionLaw("coulomb", mu=0.3)`` or ``FrictionLaw("tau0+coulomb", mu=0.3)``. The discrete method takes
        every law; the continuum takes Coulomb's part for a contact without adhesion (``dgamma0 = dgamma1 = 0``).
        The dataset then has the attributes ``friction_law``, ``friction_mu`` and ``friction_cap``.

    Returns
    -------
    xarray.Dataset
        Dims ``("alpha", "time")`` for a scenario (coordinate: the angles in
        degrees), ``("case", "time")`` for custom paths (coordinate: the
        labels; per case ``path_waypoints`` and ``path_speed``); variables of
        :data:`SIMULATION_VARIABLES`, ``nan`` after a case has ended (pull-off,
        or the end of its path); time from first contact.

    Raises
    ------
    ValueError, TypeError
        Naming the argument, its value and what is allowed: e.g. an unknown
        scenario, an empty list of paths, an element that is not a Path, a
        label that is not a non-empty string or is repeated, ``alpha`` with
        custom paths.
    """
    check_parameters(params)
    check_choice("method", method, METHODS)
    if limits is None:
        limits = DEFAULT_LIMITS
    elif not isinstance(limits, Limits):
        raise TypeError(f"limits={shown(limits)} is not allowed; allowed: a mdr_events.Limits")
    profile = indenters.check_simulated_profile(profile)
    friction = as_friction_law(friction)
    check_representable(params, profile, friction)
    if method == "continuum":
        check_supported(friction, params, profile)
    cases = simulation_cases(params, scenario, alpha, profile)
    shape = {**indenters.profile_attrs(profile), **friction_attrs(friction)}
    if method == "continuum":
        for name, value in (("dx", dx), ("dt", dt), ("n_steps", n_steps)):
            if value is not None:
                raise ValueError(f"{name} is not allowed with method='continuum' (it has no springs or time "
                                 "step); allowed: t, samples, tolerances")
        return _simulate_continuum(params, scenario, cases, t, samples, tolerances, limits, profile, friction)
    dx = DEFAULT_DX if dx is None else dx
    for name, value in (("t", t), ("samples", samples), ("tolerances", tolerances)):
        if value is not None:
            raise ValueError(f"{name} is not allowed with method='discrete'; allowed: dx, dt or n_steps")
    paths = cases.paths
    for path in paths:
        path.first_contact_time()  # a path that never touches the surface is an error first
    dx = check_spacing(params, dx, depth=min(params.d_max, max(path.max_depth for path in paths)), profile=profile)
    step = _time_step(paths, dt, n_steps)
    check_time_step(paths, step, dt, n_steps)
    raw = run_discrete(params, paths, dx, step, profile=profile, limits=limits, friction=friction)
    attrs = dict(method=method, scenario=_scenario_name(scenario, cases), dx=float(dx), dt=step,
                 spring_count_per_side=int(raw["spring_count"]),
                 content=SIMULATION_CONTENT, **shape)
    return simulation_dataset(params, cases, raw["time"], raw, **attrs)


def _scenario_name(scenario, cases: Cases) -> str:
    """The ``scenario`` attribute: the scenario's name, or ``"custom"``."""
    return CUSTOM_SCENARIO if cases.custom else scenario


def _simulate_continuum(params: Parameters, scenario, cases: Cases, t, samples, tolerances,
                        limits: Limits, profile: SimulatedProfile = None, friction: FrictionLaw = TAU0) -> xr.Dataset:
    samples = DEFAULT_SAMPLES if samples is None else check_count("samples", samples, 2)
    if tolerances is None:
        tolerances = Tolerances()
    elif not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances={tolerances!r} is not allowed; allowed: a mdr_events.Tolerances")
    times = None
    if t is not None:
        times = real_array("t", t, "a strictly increasing 1-D grid of finite times >= 0 (s)")
        if times.ndim != 1 or times.size == 0 or not np.all(np.isfinite(times)) or times[0] < 0 \
                or np.any(np.diff(times) <= 0):
            raise ValueError(f"t={shown(t)} is not allowed; allowed: a non-empty, strictly "
                             "increasing 1-D grid of finite times >= 0 (s)")
    raw = run_continuum(params, cases.paths, times, samples=samples, tolerances=tolerances, limits=limits,
                        profile=profile, friction=friction)
    attrs = dict(method="continuum", scenario=_scenario_name(scenario, cases),
                 rtol=tolerances.rtol, atol=tolerances.atol, radius_rtol=tolerances.radius_rtol,
                 content=SIMULATION_CONTENT, **indenters.profile_attrs(profile), **friction_attrs(friction))
    dataset = simulation_dataset(params, cases, raw["time"], raw, **attrs)
    extrema = [solution_extrema(solution) for solution in raw["solutions"]]
    dataset = dataset.merge(event_log(raw["events"], cases.dimension)).merge(extrema_dataset(extrema, cases.dimension))
    return _coordinates_last(dataset)


def _coordinates_last(dataset: xr.Dataset) -> xr.Dataset:
    """The same dataset with its data variables first and its coordinates last, as xarray reads a file back.

    The netCDF3 writer orders variables by shape and keeps the dataset's order among equal shapes (a
    coordinate along the cases and a per-case variable); in the order a file is read back, a result read
    and written again gives the same bytes.
    """
    return xr.Dataset({name: dataset[name].variable for name in dataset.data_vars},
                      coords={name: dataset[name].variable for name in dataset.coords}, attrs=dataset.attrs)


def event_log(events: list[list[tuple]], dimension: str = ANGLE_DIMENSION) -> xr.Dataset:
    """The continuum event log: one row per event per case along ``(dimension, "event")`` (padded with
    nan / "" / direction 0); the variables of :data:`EVENT_VARIABLES`."""
    rows = max(len(case) for case in events)
    table = {name: np.full((len(events), rows), np.nan) for name in ("time", "depth", "radius", "x")}
    kinds = np.full((len(events), rows), "", dtype=object)
    directions = np.zeros((len(events), rows), dtype=np.int32)  # int32: netCDF3 has no 64-bit integers
    for i, case in enumerate(events):
        for j, (time, kind, depth, radius, x, direction) in enumerate(case):
            table["time"][i, j], table["depth"][i, j] = time, depth
            table["radius"][i, j], table["x"][i, j] = radius, x
            kinds[i, j], directions[i, j] = kind, direction
    values = {"event_time": table["time"], "event_kind": kinds.astype(str), "event_depth": table["depth"],
              "event_radius": table["radius"], "event_x": table["x"], "event_direction": directions}
    return xr.Dataset(
        {name: ((dimension, "event"), values[name], {"units": units, "long_name": long_name})
         for name, (units, long_name) in EVENT_VARIABLES.items()},
        coords={"event": ("event", np.arange(rows), {"units": "1", "long_name": "event number"})})


def extrema_dataset(extrema: list[dict[str, float]], dimension: str = ANGLE_DIMENSION) -> xr.Dataset:
    """The variables of :data:`EXTREMA_VARIABLES` along ``dimension``, one
    :func:`~mdr_events.models.continuum.extrema.solution_extrema` per case."""
    return xr.Dataset({name: ((dimension,), np.array([case[name] for case in extrema], dtype=float),
                              {"units": units, "long_name": long_name})
                       for name, (units, long_name) in EXTREMA_VARIABLES.items()})


def simulation_dataset(
    params: Parameters,
    cases: Cases,
    time: np.ndarray,
    values: dict[str, np.ndarray],
    **attrs: Any,
) -> xr.Dataset:
    """Assemble a simulation result with dims ``(cases.dimension, "time")``.

    ``values`` holds the kinematics, forces, radius and sliding fraction of
    :data:`SIMULATION_VARIABLES` (shape (n_cases, n_time), ``nan`` after a
    case has ended); the area, mean pressure and mean shear stress are
    derived here, identically for every method. Custom paths add
    :data:`PATH_VARIABLES` along ``case``. ``attrs`` go to
    :func:`mdr_events.io.datasets.stamp`.
    """
    dimension = cases.dimension
    radius = values["contact_radius"]
    area = np.pi * radius**2
    with np.errstate(invalid="ignore", divide="ignore"):
        derived = {
            "contact_area": area,
            "mean_pressure": np.where(area > 0, values["normal_force"] / area, np.nan),
            "mean_shear_stress": np.where(area > 0, values["tangential_force"] / area, np.nan),
        }
    data = {}
    for name, (units, long_name) in SIMULATION_VARIABLES.items():
        array = derived[name] if name in derived else values[name]
        data[name] = ((dimension, "time"), np.asarray(array, dtype=float), {"units": units, "long_name": long_name})
    if cases.custom:
        described = {"path_waypoints": np.array([path.describe() for path in cases.paths], dtype=str),
                     "path_speed": np.array([path.speed for path in cases.paths], dtype=float)}
        for name, (units, long_name) in PATH_VARIABLES.items():
            data[name] = ((dimension,), described[name], {"units": units, "long_name": long_name})
        attrs["note"] = "custom paths: each case's speed path_speed replaces param_v"
        label = {"units": "1", "long_name": "label of the custom path"}
        case_coordinate = np.asarray(cases.labels, dtype=str)
    else:
        label = {"units": "degree", "long_name": "path angle to the surface"}
        case_coordinate = np.asarray(cases.labels, dtype=float)
    coords = {
        dimension: (dimension, case_coordinate, label),
        "time": ("time", np.asarray(time, dtype=float), {"units": "s", "long_name": "time from first contact"}),
    }
    return stamp(xr.Dataset(data, coords=coords), params, **attrs)
