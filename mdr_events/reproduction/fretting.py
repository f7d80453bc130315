"""Fretting at ``d_max`` (R = 30 mm): reciprocating sliding after vertical and after oblique indentation, the energy
dissipated over the last closed loop beside its closed form, continuum and discrete (``fretting_R30``).

The study's continuum dataset carries its own variables (:data:`FRETTING_VARIABLES`), whose schema and accuracy
this module registers with :mod:`mdr_events.io` when imported (``study="fretting"``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.app.result_files import PlannedFile, dataset_plan, simulation_plans
from mdr_events.io.agreement import Integrated, RoundOff, register_accuracy
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.models.continuum import solve_path, tangential_work
from mdr_events.models.motion import CUSTOM_DIMENSION, case_dimension
from mdr_events.models.paths import Path, exit_depth
from mdr_events.models.simulate import simulate
from mdr_events.models.simulation_schema import SIMULATION_CONTENT
from mdr_events.parameters import Parameters
from mdr_events.plotting.figures import plot_fretting
from mdr_events.reproduction.common import FIGURE_DX, FIGURE_STEPS, RADII
from mdr_events.reproduction.markdown import INTEGRATED_ACCURACY, markdown_table, relative_difference_text
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory import analytic

__all__ = ["FRETTING", "FRETTING_STEM", "FrettingContact", "FrettingStudy", "FrettingRow", "fretting_contact",
           "fretting_paths", "fretting_study", "fretting_rows", "closed_loop_times", "discrete_loop_work",
           "fretting_lines", "FRETTING_VARIABLES"]

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
#: The case labels, in the order of the paths.
FRETTING_CASES = (FRETTING_VERTICAL, FRETTING_OBLIQUE)
#: The stem of the fretting study's files in ``results/``.
FRETTING_STEM = f"fretting_{FRETTING_RADIUS}"
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
                          "solution (mdr_events.models.continuum.tangential_work)"),
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
        the parallelogram (``X > ū``), :func:`mdr_events.fretting_dissipated_energy`."""
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


def _fretting_cells(row: FrettingRow) -> list[str]:
    return [row.case, f"{row.centre * 1e3:.4f} mm", f"{row.loop_start:.1f} s – {row.loop_end:.1f} s",
            f"{row.closed_form * 1e3:.6f} mJ", f"{row.continuum * 1e3:.6f} mJ",
            relative_difference_text(row.continuum_difference, INTEGRATED_ACCURACY), f"{row.discrete * 1e3:.6f} mJ",
            f"{row.discrete_difference:+.1e}"]


def fretting_lines(study: FrettingStudy) -> list[str]:
    """The report's section on the fretting study: the energy dissipated per cycle, closed form, continuum and
    discrete model, for the last closed loop of each case."""
    rows = fretting_rows(study)
    first = rows[0]
    discrete = study.discrete.attrs
    radius = study.continuum.attrs["param_R"]
    speed = float(study.continuum["path_speed"].values[0])
    oblique = next(row for row in rows if row.case == FRETTING_OBLIQUE)
    lines = [
        "",
        f"## Fretting at d_max (R = {radius * 1e3:g} mm)",
        "",
        f"Reciprocating sliding at d = d_max with the amplitude X = {first.amplitude / first.cap:g}ū(a_max) = "
        f"{first.amplitude * 1e3:.4f} mm (a_max = {first.contact_radius * 1e3:.4f} mm, the Δγ0",
        f"contact radius at d_max; ū = π a τ0/(2G*) = {first.cap * 1e3:.4f} mm): {FRETTING_CYCLES} full cycles "
        "x_c → x_c + X → x_c − X → … → x_c + X,",
        f"then out vertically; after vertical indentation (x_c = 0) and after scenario A's in-path at "
        f"{FRETTING_ANGLE:g}° (x_c = d_max/tan {FRETTING_ANGLE:g}° =",
        f"{oblique.centre * 1e3:.4f} mm). The depth, hence the contact, stays fixed while it slides, so that each "
        "loop of F_x against x",
        f"is the parallelogram of the fixed contact: plateaus ±π a² τ0, slopes 2G* a (`{FRETTING_STEM}.png`, dashed).",
        "Energy dissipated per cycle, over the last closed loop of each case (between its last two tangential",
        f"reversals of the same direction, from the event log `{FRETTING_STEM}_events.csv`). Continuum: ∫F_x dx of the",
        "solution, `mdr_events.models.continuum.tangential_work`. Discrete: the paper's spring model,",
        f"Δx = {discrete['dx'] * 1e6:g} µm, {study.discrete.sizes['time'] - 1} time steps (the indenter moves v dt = "
        f"{discrete['dt'] * speed * 1e6:.2f} µm per step), the trapezoid",
        "rule on its samples between the same two times (its ends up to one step inside the loop).",
        "",
    ]
    return lines + markdown_table(
        ["case", "x_c", "loop", "closed form 4πa²τ0(X − ū)", "continuum", "relative difference", "discrete",
         "relative difference"], [_fretting_cells(row) for row in rows])


def _plans(study: FrettingStudy, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    overlay, plan = dataset_plan(study.discrete, out / f"{FRETTING_STEM}_discrete.nc", keep_agreeing)
    return [[plan] + simulation_plans(study.continuum, out, FRETTING_STEM, overlay=overlay,
                                      keep_agreeing=keep_agreeing, plot=plot_fretting)]


def _compute() -> FrettingStudy:
    return fretting_study(Parameters.paper(R=RADII[FRETTING_RADIUS]))


FRETTING = Section(
    name="fretting",
    steps=(Step(f"fretting at d_max, R = {RADII[FRETTING_RADIUS] * 1e3:g} mm: continuum, {len(FRETTING_CASES)} "
                f"cases; discrete (Δx = {FIGURE_DX * 1e6:g} µm)", _compute),),
    collect=lambda results: results[0],
    render=fretting_lines,
    plan=_plans,
    writing="writing the fretting study (.nc, .png, events .csv)",
    files=(f"- `{FRETTING_STEM}.{{nc,png}}`: the fretting study (F_x against x), continuum method, with its event log",
           f"  in `{FRETTING_STEM}_events.csv` and the discrete model in `{FRETTING_STEM}_discrete.nc`."),
)
