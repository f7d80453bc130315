"""The LAMMPS input deck of one run: a sphere of radius ``R`` moved along a :class:`~mdr_events.Path` against a flat
wall, its forces printed by LAMMPS itself in one ``run``.

The wall is the plane ``z = 0`` (``fix wall/gran ... zplane 0 NULL``); the sphere's centre is at
``(x(t), 0, R - d(t))``, so that the overlap is the depth ``d``. The motion is prescribed (``fix move variable``):
the displacement is the path's piecewise-linear ``(x(t), d(t))`` written as a sum over its segments,

    X(t) = x_0 + Σ_i Δx_i clamp((t - t_i) / T_i, 0, 1),                                               (D1)

exact at every step wherever its corners fall, and the velocity the mean over the step just taken,
``(X(t) - X(t - dt)) / dt``, so that LAMMPS's tangential history ``Σ v_t dt`` telescopes to the path's tangential
displacement since the first step in contact (D2). Each step, ``fix print`` writes the time, the position, the
MDR's forces (the wall's force on the sphere: along z, and minus it along x) and whether the wall holds a contact
(``fix wall/gran ... contacts``), each to 17 significant digits (the file's numbers are LAMMPS's doubles), under a
header row naming them as :func:`mdr_events.validate` reads them (:data:`OUTPUT_COLUMNS`).

The output file is the index variable ``output`` (``lmp -in deck.lmp -var output forces.txt`` overrides it).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact import Contact
from mdr_events.dem.mapping import LammpsModel, WallCoefficients, wall_model_arguments
from mdr_events.models.paths import Path
from mdr_events.validation import MAX_COUNT, shown

__all__ = ["MIN_STEPS_PER_SEGMENT", "OUTPUT_COLUMNS", "DEFAULT_OUTPUT", "steps_for", "check_depth_within_sphere",
           "input_deck"]

#: The least number of time steps on each segment of the path: a corner is then resolved to 1/20 of the shortest
#: segment's duration, and a segment is no jump in LAMMPS's history (D2).
MIN_STEPS_PER_SEGMENT = 20
#: The columns ``fix print`` writes, in order, under a header row of these names (its ``title``): the time from the
#: path's start, the sphere's position, the MDR's forces (``tangential_force``: minus the wall's force on the sphere
#: along x) and LAMMPS's contact flag, as :func:`mdr_events.validate` reads them by name, so that a rerun of the deck
#: is refereed as it stands (``time_origin="path_start"``). Round 30: the file had no header and LAMMPS's sign of
#: ``fx``: a user who named ``fx`` the tangential force failed by twice its range.
OUTPUT_COLUMNS = ("time", "x", "depth", "tangential_force", "normal_force", "lammps_contact")
#: The file name the deck prints to unless ``-var output FILE`` is given.
DEFAULT_OUTPUT = "lammps_forces.txt"


def steps_for(path: Path, steps: int | None, dt: float | None) -> tuple[int, float]:
    """The number of steps and the time step (s) that cover ``path``: ``steps`` (``dt = duration/steps``) or ``dt``
    (``steps = ceil(duration/dt)``); neither: 10⁴ steps. Each segment must get :data:`MIN_STEPS_PER_SEGMENT`.

    Raises
    ------
    ValueError
        Both given, a count or a step that is not positive, or one too coarse for the path: the message names the
        step the path needs.
    """
    if steps is not None and dt is not None:
        raise ValueError(f"steps={shown(steps)} and dt={shown(dt)} are not allowed together; allowed: one of them")
    duration = path.duration
    if dt is not None:
        if isinstance(dt, bool) or not isinstance(dt, (int, float)) or not (math.isfinite(dt) and dt > 0):
            raise ValueError(f"dt={shown(dt)} is not allowed; allowed: a time step in s, finite and > 0")
        count = duration / dt * (1.0 - 1e-12)
        if not count <= MAX_COUNT:  # (a step below 1e-300 s: more steps than any count, inf beyond the doubles)
            raise ValueError(f"dt={shown(dt)} is not allowed: the path's {duration:.6g} s would take {count:.3g} steps; "
                             f"allowed: a time step in s >= {duration / MAX_COUNT:.3g} (at most {MAX_COUNT:.0e} steps)")
        steps = max(1, math.ceil(count))
    elif steps is None:
        steps = 10_000
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or not 1 <= steps <= MAX_COUNT:
        raise ValueError(f"steps={shown(steps)} is not allowed; allowed: a number of time steps, an integer >= 1 (at "
                         f"most {MAX_COUNT:.0e})")
    step = duration / int(steps) if dt is None else float(dt)
    shortest = float(np.min(path.segment_lengths)) / path.speed
    needed = shortest / MIN_STEPS_PER_SEGMENT
    if step > needed * (1.0 + 1e-12):
        given = f"dt={dt!r} s" if dt is not None else f"steps={steps!r} (dt = {step:.6g} s)"
        raise ValueError(f"{given} is too coarse for the path: its shortest segment lasts {shortest:.6g} s; allowed: "
                         f"dt <= {needed:.6g} s ({MIN_STEPS_PER_SEGMENT} steps per segment), i.e. steps >= "
                         f"{math.ceil(duration / needed)}")
    return int(steps), step


def check_depth_within_sphere(radius: float, path: Path) -> None:
    """Refuse a path deeper than the sphere LAMMPS moves along it: its centre at ``z = R - d`` reaches the wall at
    ``d = R`` and crosses it beyond, where the paraboloid of the MDR goes on. LAMMPS's overlap is then no longer the
    path's depth (R = 0.2 mm along the paper's path to 0.3 mm: the normal force 1.19 of its range off, a verdict that
    named no cause), and beyond ``d = 3R`` the sphere leaves the box (LAMMPS: "Lost atoms"). The bound is the deck's
    geometry alone: at every ``d < R`` the overlap is the depth (R = 0.31 mm there: within 1e-14 of the range).

    Raises
    ------
    ValueError
        The path's deepest depth is ``R`` or more: one line naming both and the bound.
    """
    deepest = float(path.max_depth)
    if not deepest < radius:
        raise ValueError(f"R={radius!r} m is not allowed with a path whose deepest depth is {deepest:.6g} m: LAMMPS's "
                         "sphere of radius R (its centre at z = R - d above the wall) would reach the wall there and "
                         f"cross it; allowed: R > {deepest:.6g} m, the path's deepest depth (or a shallower path)")


def _n(value: float) -> str:
    """A number as LAMMPS reads it back exactly (the shortest repr of the double)."""
    return repr(float(value))


def _clamp(time: str, start: float, length: float) -> str:
    """``clamp((time - start)/length, 0, 1)`` as a LAMMPS formula."""
    return f"ternary({time}<{_n(start)},0,ternary({time}>{_n(start + length)},1,({time}-{_n(start)})/{_n(length)}))"


def _segments(path: Path, axis: int, sign: float) -> list[tuple[float, float, float]]:
    """``(start, end, change)`` of each segment that moves along ``axis`` (the change with ``sign``)."""
    corners, points = path.corner_times, path.waypoints
    return [(float(corners[i]), float(corners[i + 1]), sign * float(points[i + 1, axis] - points[i, axis]))
            for i in range(len(points) - 1) if points[i + 1, axis] != points[i, axis]]


def _displacement(segments: list[tuple[float, float, float]]) -> str:
    """(D1): the displacement from the first waypoint, a sum of each segment's change times its share done."""
    return "+".join(f"{_n(change)}*{_clamp('time', start, end - start)}" for start, end, change in segments) or "0"


def _velocity(segments: list[tuple[float, float, float]], dt: float) -> str:
    """(D2): the mean velocity over the last step ``[t - dt, t]``, each segment's velocity times the share of the
    step spent on it, ``clamp((t - t_i)/dt) - clamp((t - t_(i+1))/dt)``: its sum over the steps is (D1)."""
    terms = [f"{_n(change / (end - start))}*({_clamp('time', start, dt)}-{_clamp('time', end, dt)})"
             for start, end, change in segments]
    return "+".join(terms) or "0"


def _motion(path: Path, dt: float) -> list[str]:
    """The variables and ``fix move`` of the prescribed motion: (D1) and the mean velocity of the last step (D2)."""
    lines = []
    for name, axis, sign in (("x", 0, 1.0), ("z", 1, -1.0)):  # (z = R - d: the depth's change with its sign turned)
        segments = _segments(path, axis, sign)
        lines += [f'variable d{name} equal "{_displacement(segments)}"',
                  f'variable v{name} equal "{_velocity(segments, dt)}"']
    return lines + ["fix motion all move variable v_dx NULL v_dz v_vx NULL v_vz"]


def _box(path: Path, radius: float) -> str:
    """A box holding the sphere along the whole path, a radius of room on every side."""
    x, d = path.waypoints[:, 0], path.waypoints[:, 1]
    margin = 2.0 * radius
    return (f"region box block {_n(x.min() - margin)} {_n(x.max() + margin)} {_n(-margin)} {_n(margin)} "
            f"{_n(-margin)} {_n(radius - d.min() + margin)} units box")


def input_deck(contact: Contact, model: LammpsModel, numbers: WallCoefficients, path: Path, steps: int,
               dt: float) -> str:
    """The LAMMPS input deck of the run (module docstring): SI units, one sphere, the wall model of
    :func:`~mdr_events.dem.mapping.wall_model_arguments`, the motion along ``path``, ``steps`` steps of ``dt``."""
    R = contact.indenter.R
    x0, d0 = path.waypoints[0]
    printed = " ".join(f"$({name}:%.17g)" for name in ("time", "v_px", "v_pd", "v_ft", "v_fn", "v_contact"))
    lines = [
        "# mdr_events: a sphere against a flat wall along a path (rerun: lmp -in this_file -var output FILE)",
        f"variable output index {DEFAULT_OUTPUT}",
        "units si", "atom_style sphere", "atom_modify map array", "dimension 3", "boundary f f f",
        _box(path, R), "create_box 1 box",
        f"create_atoms 1 single {_n(x0)} 0 {_n(R - d0)} units box",
        f"set atom 1 diameter {_n(2.0 * R)} density 1000",
        f"timestep {_n(dt)}",
        *_motion(path, dt),
        f"fix wall all wall/gran granular {wall_model_arguments(model, numbers)} zplane 0 NULL contacts",
        "compute touching all reduce sum f_wall[1]",
        "variable px equal x[1]", f"variable pd equal {_n(R)}-z[1]",
        "variable ft equal -1*fx[1]", "variable fn equal fz[1]", "variable contact equal c_touching",
        f'fix output all print 1 "{printed}" file ${{output}} screen no title "{" ".join(OUTPUT_COLUMNS)}"',
        "thermo 0",
        f"run {steps}",
    ]
    return "\n".join(lines) + "\n"
