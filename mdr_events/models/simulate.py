"""``simulate``: one entry point for every simulation method, one result schema."""

from __future__ import annotations

import math
from typing import Any, Literal, Sequence

import numpy as np
import xarray as xr

from mdr_events.io.datasets import register_schema, stamp
from mdr_events.models.continuum import Tolerances, run_continuum
from mdr_events.models.discrete import check_spacing, run_discrete
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory import analytic
from mdr_events.validation import check_choice

__all__ = ["simulate", "scenario_paths", "simulation_dataset", "event_log", "FIGURE_ANGLES", "METHODS",
           "SCENARIO_NAMES", "SIMULATION_CONTENT", "SIMULATION_VARIABLES", "EVENT_VARIABLES"]

#: The angles of Fig. 8 and Fig. 10.
FIGURE_ANGLES = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
METHODS = ("discrete", "continuum")
SCENARIO_NAMES = ("A", "B", "B+")
DEFAULT_DX = 1e-6
DEFAULT_STEPS = 10_000
DEFAULT_SAMPLES = 2001


#: The ``content`` attribute of a simulation.
SIMULATION_CONTENT = "simulation of indentation and detachment along straight paths"
#: The variables of a simulation, shared by every method (dims ``("alpha", "time")``): name -> (units, long_name).
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
#: The continuum method's event log (dims ``("alpha", "event")``): name -> (units, long_name).
EVENT_VARIABLES: dict[str, tuple[str, str]] = {
    "event_time": ("s", "time of the event from first contact"),
    "event_kind": ("1", "kind of event"),
    "event_depth": ("m", "indentation depth at the event"),
    "event_radius": ("m", "contact radius at the event"),
    "event_x": ("m", "tangential displacement at the event"),
}
register_schema(SIMULATION_CONTENT, {name: ("alpha", "time") for name in SIMULATION_VARIABLES})
register_schema(SIMULATION_CONTENT, {name: ("alpha", "event") for name in EVENT_VARIABLES},
                when=("method", "continuum"))


#: Relative accuracy the slip criterion needs: x − X(ξ) against ū(a) must keep this many digits.
SLIP_DIGITS = 1e-9


def check_path_extent(params: Parameters, path: Path, label: str) -> None:
    """Reject a path so long that ``x − X(ξ)`` cannot be compared with ``ū(a)`` in double precision.

    The positions along the path are rounded to ``eps · |x|``; the slip
    criterion compares differences of them with ``ū(a)`` (at ``d_max``) or,
    without friction, with ``d_max``. A path whose tangential extent exceeds
    ``SLIP_DIGITS · max(ū, d_max) / eps`` (about 3 km for the paper's
    parameters: a path angle of a few 1e-6 degrees) is an error, not a
    silently wrong result.
    """
    radius = float(analytic.jkr_contact_radius(params.d_max, params, params.dgamma0))
    reference = max(float(analytic.critical_shift(radius, params)), params.d_max)
    limit = SLIP_DIGITS * reference / np.finfo(float).eps
    extent = float(np.max(np.abs(path.waypoints[:, 0])))
    if extent > limit:
        raise ValueError(f"{label}: the path reaches x = {extent:.3g} m; allowed: |x| <= {limit:.3g} m, beyond "
                         f"which double precision cannot resolve the slip criterion (shift vs {reference:.3g} m)")


def scenario_paths(params: Parameters, scenario: str | Path, alpha) -> tuple[list[Path], np.ndarray]:
    """The paths of a scenario for each angle (or the one custom path), checked by :func:`check_path_extent`."""
    if isinstance(scenario, Path):
        if alpha is not None:
            raise ValueError("alpha is not allowed with a custom path (its waypoints fix the motion)")
        check_path_extent(params, scenario, "scenario=Path")
        return [scenario], np.array([scenario.alpha])
    if scenario not in SCENARIO_NAMES:
        raise ValueError(f"scenario={scenario!r} is not allowed; allowed: 'A', 'B', 'B+' or a Path")
    angles = np.atleast_1d(np.asarray(FIGURE_ANGLES if alpha is None else alpha, dtype=float))
    if angles.ndim != 1 or angles.size == 0:
        raise ValueError(f"alpha of shape {angles.shape} is not allowed; allowed: one angle or a 1-D list")
    build = {"A": Path.scenario_A, "B": Path.scenario_B, "B+": Path.scenario_B_indentation}[scenario]
    paths = [build(float(angle), params) for angle in angles]
    for angle, path in zip(angles, paths):
        check_path_extent(params, path, f"alpha={float(angle)!r} (degrees) in scenario {scenario}")
    return paths, angles


def _time_step(paths: list[Path], dt: float | None, n_steps: int | None) -> float:
    if dt is not None and n_steps is not None:
        raise ValueError("give dt or n_steps, not both")
    longest = max(path.duration - path.first_contact_time() for path in paths)
    if dt is not None:
        if not (isinstance(dt, (int, float)) and math.isfinite(dt) and dt > 0):
            raise ValueError(f"dt={dt!r} is not allowed; allowed: a finite time step > 0 (s)")
        return float(dt)
    steps = DEFAULT_STEPS if n_steps is None else n_steps
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 10:
        raise ValueError(f"n_steps={steps!r} is not allowed; allowed: an integer >= 10")
    return longest / int(steps)


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
    scenario: Literal["A", "B", "B+"] | Path = "A",
    alpha: float | Sequence[float] | None = None,
    method: Literal["discrete", "continuum"] = "discrete",
    dx: float | None = None,
    dt: float | None = None,
    n_steps: int | None = None,
    t: Sequence[float] | None = None,
    samples: int | None = None,
    tolerances: Tolerances | None = None,
) -> xr.Dataset:
    """Simulate indentation and detachment along straight paths.

    Parameters
    ----------
    params : Parameters
    scenario : {"A", "B", "B+"} or Path
        ``"A"``: eq. (14); ``"B"``: eq. (19); ``"B+"``: the "+" branch of
        Fig. 9b (:meth:`Path.scenario_B_indentation`); or any :class:`Path`.
    alpha : float or sequence of float, optional
        Angles in degrees (default 10°, 20°, …, 80°, as in Fig. 8 and 10);
        not with a custom path.
    method : {"discrete", "continuum"}
        ``"discrete"``: the paper's spring array (:mod:`mdr_events.models.discrete`).
        ``"continuum"``: its Δx → 0 limit integrated between events
        (:mod:`mdr_events.models.continuum`); adds the event log along ``event``.
    dx : float, optional
        Discrete method: spring spacing Δx in m (default 1 µm); at least 10
        springs per side must be in contact at ``d_max``.
    dt, n_steps :
        Discrete method: time step in s, or the number of steps of the
        longest case (default 10 000); not both.
    t : sequence of float, optional
        Continuum method: the output times in s from first contact
        (increasing, >= 0); default ``samples`` points to the end of the longest run.
    samples : int, optional
        Continuum method without ``t``: number of output times (default 2001, at least 2).
    tolerances : mdr_events.models.continuum.Tolerances, optional
        Continuum method: solver and root-finding tolerances (default
        ``Tolerances()``: ``rtol = 1e-10``, ``atol = 1e-14`` N, ``radius_rtol = 1e-14``).

    Returns
    -------
    xarray.Dataset
        Dims ``("alpha", "time")``; variables of
        :data:`SIMULATION_VARIABLES`, ``nan`` after a case
        has ended (pull-off, or the end of its path); time from first contact.
    """
    check_choice("method", method, METHODS)
    paths, angles = scenario_paths(params, scenario, alpha)
    if method == "continuum":
        for name, value in (("dx", dx), ("dt", dt), ("n_steps", n_steps)):
            if value is not None:
                raise ValueError(f"{name} is not allowed with method='continuum' (it has no springs or time "
                                 "step); allowed: t, samples, tolerances")
        return _simulate_continuum(params, scenario, paths, angles, t, samples, tolerances)
    dx = DEFAULT_DX if dx is None else dx
    for name, value in (("t", t), ("samples", samples), ("tolerances", tolerances)):
        if value is not None:
            raise ValueError(f"{name} is not allowed with method='discrete'; allowed: dx, dt or n_steps")
    for path in paths:
        path.first_contact_time()  # a path that never touches the surface is an error first
    check_spacing(params, dx, depth=min(params.d_max, max(path.max_depth for path in paths)))
    step = _time_step(paths, dt, n_steps)
    check_time_step(paths, step, dt, n_steps)
    raw = run_discrete(params, paths, dx, step)
    scenario_name = "custom" if isinstance(scenario, Path) else scenario
    attrs = dict(method=method, scenario=scenario_name, dx=float(dx), dt=step,
                 spring_count_per_side=int(raw["spring_count"]),
                 content=SIMULATION_CONTENT)
    if isinstance(scenario, Path):
        attrs["path_waypoints"] = scenario.describe()
        attrs["path_speed"] = scenario.speed
        attrs["path_speed_units"] = "m s-1"
        attrs["note"] = "custom path: its speed path_speed replaces param_v"
    return simulation_dataset(params, angles, raw["time"], raw, **attrs)


def _simulate_continuum(params, scenario, paths, angles, t, samples, tolerances) -> xr.Dataset:
    samples = DEFAULT_SAMPLES if samples is None else samples
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 2:
        raise ValueError(f"samples={samples!r} is not allowed; allowed: an integer >= 2")
    if tolerances is None:
        tolerances = Tolerances()
    elif not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances={tolerances!r} is not allowed; allowed: a mdr_events.Tolerances")
    times = None
    if t is not None:
        times = np.asarray(t, dtype=float)
        if times.ndim != 1 or times.size == 0 or not np.all(np.isfinite(times)) or times[0] < 0 \
                or np.any(np.diff(times) <= 0):
            raise ValueError(f"t of shape {times.shape} is not allowed; allowed: a non-empty, strictly "
                             "increasing 1-D grid of finite times >= 0 (s)")
    raw = run_continuum(params, paths, times, samples=int(samples), tolerances=tolerances)
    attrs = dict(method="continuum", scenario="custom" if isinstance(scenario, Path) else scenario,
                 rtol=tolerances.rtol, atol=tolerances.atol, radius_rtol=tolerances.radius_rtol,
                 content=SIMULATION_CONTENT)
    if isinstance(scenario, Path):
        attrs.update(path_waypoints=scenario.describe(), path_speed=scenario.speed, path_speed_units="m s-1")
    dataset = simulation_dataset(params, angles, raw["time"], raw, **attrs)
    return dataset.merge(event_log(raw["events"]))


def event_log(events: list[list[tuple]]) -> xr.Dataset:
    """The continuum event log: one row per event per case along ``event`` (padded with nan / "")."""
    rows = max(len(case) for case in events)
    table = {name: np.full((len(events), rows), np.nan) for name in ("time", "depth", "radius", "x")}
    kinds = np.full((len(events), rows), "", dtype=object)
    for i, case in enumerate(events):
        for j, (time, kind, depth, radius, x, _direction) in enumerate(case):
            table["time"][i, j], table["depth"][i, j] = time, depth
            table["radius"][i, j], table["x"][i, j] = radius, x
            kinds[i, j] = kind
    values = {"event_time": table["time"], "event_kind": kinds.astype(str), "event_depth": table["depth"],
              "event_radius": table["radius"], "event_x": table["x"]}
    return xr.Dataset(
        {name: (("alpha", "event"), values[name], {"units": units, "long_name": long_name})
         for name, (units, long_name) in EVENT_VARIABLES.items()},
        coords={"event": ("event", np.arange(rows), {"units": "1", "long_name": "event number"})})


def simulation_dataset(
    params: Parameters,
    alpha: np.ndarray,
    time: np.ndarray,
    values: dict[str, np.ndarray],
    **attrs: Any,
) -> xr.Dataset:
    """Assemble a simulation result with dims ``("alpha", "time")``.

    ``values`` holds the kinematics, forces, radius and sliding fraction of
    :data:`SIMULATION_VARIABLES` (shape (n_alpha, n_time), ``nan`` after a
    case has ended); the area, mean pressure and mean shear stress are
    derived here, identically for every method. ``attrs`` go to
    :func:`mdr_events.io.datasets.stamp`.
    """
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
        data[name] = (("alpha", "time"), np.asarray(array, dtype=float), {"units": units, "long_name": long_name})
    coords = {
        "alpha": ("alpha", np.asarray(alpha, dtype=float), {"units": "degree", "long_name": "path angle to the surface"}),
        "time": ("time", np.asarray(time, dtype=float), {"units": "s", "long_name": "time from first contact"}),
    }
    return stamp(xr.Dataset(data, coords=coords), params, **attrs)
