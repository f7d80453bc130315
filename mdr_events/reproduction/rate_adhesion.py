"""Rate-dependent adhesion: the pull-off force and the critical angle of scenario A against the speed
(``rate_adhesion``).

The paper's elastomer and sphere (R = 30 mm) with :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` of the
paper's works at rest, ``v_ref = 1 µm/s`` (the paper's speed) and ``n = 0.6`` (Maugis & Barquins' polyurethane),
in vertically to ``d_max`` and out at the same speed, over seven decades of speed
(:func:`~mdr_events.models.continuum.solve_edge`: the normal problem, the radius an ODE). The way out goes to a
multiple of the rate-independent jump-off depth, doubled until the contact comes apart on it. The critical angle of
scenario A at the same speeds (:func:`~mdr_events.analysis.rate_angles.critical_angles_at_speeds`). No dataset is
written: the tables and the figures hold what is measured.
"""

from __future__ import annotations

import math
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.rate_angles import critical_angles_at_speeds
from mdr_events.app.result_files import FileOutcome, write_figure
from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.models.continuum.rate_edge import EdgeEventKind, solve_edge
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.plotting.rate_adhesion import plot_critical_angle_against_speed, plot_pull_off_against_speed
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory import analytic

__all__ = ["RATE_ADHESION", "RATE_V_REF", "RATE_EXPONENT", "RATE_SPEEDS", "RATE_STEM", "RATE_ANGLE_STEM", "RateRow",
           "RateSection", "rate_law", "rate_rows", "rate_angles", "rate_lines"]

#: The law's reference speed (m/s) and exponent.
RATE_V_REF = 1e-6
RATE_EXPONENT = 0.6
#: The paths' speeds (m/s): seven decades around v_ref.
RATE_SPEEDS = tuple(10.0**k for k in range(-10, -3))
#: The figure's stem in ``results/``.
RATE_STEM = "rate_adhesion_pull_off"
RATE_ANGLE_STEM = "rate_adhesion_critical_angle"
#: The way out ends at this multiple of the rate-independent jump-off depth at first, doubled until the contact
#: comes apart on it, at most :data:`MAX_DOUBLINGS` times.
FIRST_EXIT_MULTIPLE = 2.0
MAX_DOUBLINGS = 12


class RateRow(NamedTuple):
    """One speed's pull-off."""

    speed: float  #: m/s
    pull_off_ratio: float  #: the magnitude of the least F_N over (3/2)πΔγ1 R
    end_depth_ratio: float  #: the depth where the contact came apart over the rate-independent jump-off depth


class RateSection(NamedTuple):
    """What the section computed."""

    rows: list[RateRow]  #: each speed's pull-off
    angles: xr.Dataset  #: the critical angle of scenario A against the speed


def rate_law(params: Parameters) -> RateDependentAdhesion:
    """The section's law for the works at rest of ``params``."""
    return RateDependentAdhesion(params.dgamma0, params.dgamma1, RATE_V_REF, RATE_EXPONENT)


def _pull_off(params: Parameters, speed: float) -> RateRow:
    law, jump_off = rate_law(params), analytic.jump_off(params, params.dgamma1)["depth"]
    multiple = FIRST_EXIT_MULTIPLE
    for _ in range(MAX_DOUBLINGS):
        path = Path(np.array([(0.0, 0.0), (0.0, params.d_max), (0.0, multiple * jump_off)]), speed=speed)
        run = solve_edge(params, path, law)
        ended = [event for event in run.events if event.kind is EdgeEventKind.CONTACT_ENDS]
        if ended:
            jkr = 1.5 * math.pi * params.dgamma1 * params.R
            return RateRow(speed, -run.pull_off_force(path) / jkr, ended[0].depth / jump_off)
        multiple *= 2.0
    raise RuntimeError(f"the contact did not come apart at {speed!r} m/s within {multiple!r} jump-off depths")


def rate_rows() -> list[RateRow]:
    """Each speed's pull-off for the paper's contact (R = 30 mm)."""
    params = Parameters.paper()
    return [_pull_off(params, speed) for speed in RATE_SPEEDS]


def rate_angles() -> xr.Dataset:
    """The critical angle of scenario A at each speed for the paper's contact (R = 30 mm)."""
    params = Parameters.paper()
    return critical_angles_at_speeds(params, rate_law(params), RATE_SPEEDS)


def rate_lines(data: RateSection) -> list[str]:
    """The section of ``results/README.md``."""
    rows, angles = data
    table = markdown_table(["v (m/s)", "v / v_ref", "pull-off / (3/2)πΔγ1R", "separation at the end / jump-off depth"],
                           [[f"{row.speed:.0e}", f"{row.speed / RATE_V_REF:g}", f"{row.pull_off_ratio:.4g}",
                             f"{row.end_depth_ratio:.4g}"] for row in rows], ["right"] * 4)
    slope = math.log10(rows[-1].pull_off_ratio / rows[-2].pull_off_ratio) / math.log10(rows[-1].speed / rows[-2].speed)
    return ["", "## Rate-dependent adhesion: pull-off against the unloading speed", "",
            "The paper's contact (R = 30 mm, its Δγ0 and Δγ1 at rest) with Maugis & Barquins' rate-dependent work of "
            f"adhesion, v_ref = {RATE_V_REF:g} m/s and n = {RATE_EXPONENT:g} (`me.RateDependentAdhesion`; the paper "
            "has no rate data: these values illustrate), vertically in to d_max and out at the same speed v until "
            "the contact comes apart; the radius is the state of an ODE (`me.continuum.solve_edge`, the normal "
            "problem). The least normal force over JKR's pull-off at Δγ1 tends to 1 as v → 0 (the paper's law) and "
            f"grows with the speed, by a factor {rows[-1].pull_off_ratio / rows[-2].pull_off_ratio:.3g} over the last "
            f"decade (slope {slope:.2f} on log–log, where the law itself has n = {RATE_EXPONENT:g}); the "
            f"contact holds to deeper separations. Figure: `{RATE_STEM}.png`.", ""] + table + [""] + _angle_lines(angles)


def _angle_lines(angles: xr.Dataset) -> list[str]:
    """The critical angle of scenario A against the speed: the report's table and what it shows."""
    values = angles["critical_angle"].values
    adhesive, hertz = angles.attrs["critical_angle_adhesive"], angles.attrs["critical_angle_hertz"]
    table = markdown_table(["v (m/s)", "v / v_ref", "critical angle of A", "share of the way from (18) to (17)"],
                           [[f"{speed:.0e}", f"{speed / RATE_V_REF:g}", f"{angle:.4f}°",
                             f"{(angle - adhesive) / (hertz - adhesive):.4f}"]
                            for speed, angle in zip(angles["speed"].values, values)], ["right"] * 4)
    return ["The critical angle of scenario A at the same speeds (`me.critical_angles_at_speeds`): slip begins at "
            "d_max where tan α K a(d_max) = d_max, with the radius the advancing edge reaches on the way in at the "
            f"vertical speed v sin α. It rises from the paper's adhesive angle (18), {adhesive:.4f}°, as v → 0 "
            f"towards the non-adhesive (17), {hertz:.4f}°: a faster edge works against less adhesion and reaches a "
            f"smaller radius. Figure: `{RATE_ANGLE_STEM}.png`. Scenario B's angle is left open: the paper's contact "
            "jumps off at a finite radius before its springs slide (21), while a rate-dependent edge comes apart over "
            "a finite time in which its radius, and with it the cap K a, falls to 0, so the exact springs slide in the "
            "last instants of every angle and the discrete ones (which let go within one step) at none: an angle "
            "needs a criterion for when the contact has let go.",
            ""] + table + [""]


def _write(data: RateSection, out: FilePath, keep_agreeing: bool) -> list[list[FileOutcome]]:
    rows, angles = data
    speeds = np.array([row.speed for row in rows]) / RATE_V_REF
    figure = plot_pull_off_against_speed(speeds, np.array([row.pull_off_ratio for row in rows]), RATE_EXPONENT)
    angle_figure = plot_critical_angle_against_speed(angles["speed"].values / RATE_V_REF,
                                                     angles["critical_angle"].values,
                                                     angles.attrs["critical_angle_adhesive"],
                                                     angles.attrs["critical_angle_hertz"])
    return [[write_figure(figure, out / f"{RATE_STEM}.png", keep_agreeing),
             write_figure(angle_figure, out / f"{RATE_ANGLE_STEM}.png", keep_agreeing)]]


RATE_ADHESION = Section(
    name="rate_adhesion",
    steps=(Step(f"rate-dependent adhesion: pull-off at {len(RATE_SPEEDS)} speeds", rate_rows),
           Step(f"rate-dependent adhesion: the critical angle of A at {len(RATE_SPEEDS)} speeds", rate_angles)),
    collect=lambda results: RateSection(*results),
    render=rate_lines,
    write=_write,
    writing="writing the rate-dependent pull-off and critical-angle figures",
    files=(f"- `{RATE_STEM}.png`: the pull-off force against the unloading speed under the rate-dependent law.",
           f"- `{RATE_ANGLE_STEM}.png`: the critical angle of scenario A against the speed under the same law."),
)
