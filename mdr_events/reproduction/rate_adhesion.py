"""Rate-dependent adhesion: the pull-off force and the critical angles of scenarios A and B against the speed
(``rate_adhesion``).

The paper's elastomer and sphere (R = 30 mm) with :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` of the
paper's works at rest, ``v_ref = 1 µm/s`` (the paper's speed) and ``n = 0.6`` (Maugis & Barquins' polyurethane),
in vertically to ``d_max`` and out at the same speed, over seven decades of speed
(:func:`~mdr_events.models.continuum.solve_edge`: the normal problem, the radius an ODE). The way out goes to a
multiple of the rate-independent jump-off depth, doubled until the contact comes apart on it. The critical angle of
scenario A at the same speeds (:func:`~mdr_events.analysis.rate_angles.critical_angles_at_speeds`), its phase diagram
(Fig. 9a) at three speeds (:func:`~mdr_events.analysis.rate_angles.phase_diagram_at_speeds`), and scenario A at 20° at
the same three speeds with springs and shifts (the discrete method, Δx = 1 µm) beside the paper's law, and the critical
angle of scenario B at the seven speeds (:func:`~mdr_events.analysis.rate_let_go.critical_angles_B_at_speeds`: the
springs slide before the edge lets go). No dataset is written: the tables and the figures hold what is measured.
"""

from __future__ import annotations

import math
from pathlib import Path as FilePath
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.rate_angles import critical_angles_at_speeds, phase_diagram_at_speeds
from mdr_events.analysis.rate_let_go import critical_angles_B_at_speeds
from mdr_events.app.result_files import PlannedFile, figure_plan
from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.models.continuum.rate_edge import EdgeEventKind, solve_edge
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.contact.model import Contact
from mdr_events.models.motion import Scenario
from mdr_events.models.simulate import simulate
from mdr_events.plotting.rate_adhesion import (plot_critical_angle_against_speed, plot_critical_angle_B_against_speed,
                                               plot_phase_diagram_at_speeds, plot_pull_off_against_speed,
                                               plot_scenario_at_speeds)
from mdr_events.reproduction.markdown import markdown_table
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory import analytic

__all__ = ["RATE_ADHESION", "RATE_V_REF", "RATE_EXPONENT", "RATE_SPEEDS", "RATE_STEM", "RATE_ANGLE_STEM",
           "RATE_PHASE_STEM", "RATE_SCENARIO_STEM", "RATE_ANGLE_B_STEM", "THREE_SPEEDS", "PHASE_ANGLES", "RateRow",
           "RateSection", "rate_law", "rate_rows", "rate_angles", "rate_phase_diagram", "rate_scenario_runs",
           "rate_angles_B", "rate_lines"]

#: The law's reference speed (m/s) and exponent.
RATE_V_REF = 1e-6
RATE_EXPONENT = 0.6
#: The paths' speeds (m/s): seven decades around v_ref.
RATE_SPEEDS = tuple(10.0**k for k in range(-10, -3))
#: The figure's stem in ``results/``.
RATE_STEM = "rate_adhesion_pull_off"
RATE_ANGLE_STEM = "rate_adhesion_critical_angle"
RATE_PHASE_STEM = "rate_adhesion_phase_diagram_A"
RATE_SCENARIO_STEM = "rate_adhesion_A20"
RATE_ANGLE_B_STEM = "rate_adhesion_critical_angle_B"
#: The three speeds (m/s) of the phase diagram and of scenario A at 20°: a decade either side of v_ref.
THREE_SPEEDS = (1e-7, 1e-6, 1e-5)
#: The phase diagram's angles (degrees), Fig. 9a's range.
PHASE_ANGLES = tuple(float(angle) for angle in np.arange(2.0, 45.0, 2.0))
#: The springs' spacing (m) of scenario A at 20° at three speeds.
SCENARIO_DX = 1e-6
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
    phase: xr.Dataset  #: scenario A's phase diagram at three speeds
    runs: dict[str, xr.Dataset]  #: scenario A at 20°: the paper's law, then the rate-dependent one at three speeds
    angles_B: xr.Dataset  #: the critical angle of scenario B against the speed


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


def rate_phase_diagram() -> xr.Dataset:
    """Scenario A's phase diagram at :data:`THREE_SPEEDS` (LSODA: within 1e-10 of Radau's depths, a seventh of the
    time)."""
    params = Parameters.paper()
    return phase_diagram_at_speeds(params, rate_law(params), THREE_SPEEDS, PHASE_ANGLES, method="LSODA")


def rate_scenario_runs() -> dict[str, xr.Dataset]:
    """Scenario A at 20° with springs and shifts: the paper's law, then the rate-dependent one at each speed."""
    paper = Contact.paper()
    rate = Contact(paper.elastomer, paper.indenter, rate_law(Parameters.paper()), paper.friction)
    runs = {"the paper's law (rate-independent)": simulate(paper, Scenario("A", alpha=[20.0]), "discrete",
                                                           dx=SCENARIO_DX).isel(alpha=0)}
    for speed in THREE_SPEEDS:
        runs[f"v = {speed:g} m/s (v / v_ref = {speed / RATE_V_REF:g})"] = simulate(
            rate, Scenario("A", alpha=[20.0], v=speed), "discrete", dx=SCENARIO_DX).isel(alpha=0)
    return runs


def rate_angles_B() -> xr.Dataset:
    """The critical angle of scenario B at each speed for the paper's contact (R = 30 mm); LSODA, within 1e-8° of
    Radau's angles (measured 7e-9°) at a seventh of the time."""
    params = Parameters.paper()
    return critical_angles_B_at_speeds(params, rate_law(params), RATE_SPEEDS, method="LSODA")


def rate_lines(data: RateSection) -> list[str]:
    """The section of ``results/README.md``."""
    rows, angles = data.rows, data.angles
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
            f"contact holds to deeper separations. Figure: `{RATE_STEM}.png`.", ""] + table + [""] + _angle_lines(angles) \
        + _phase_lines(data.phase) + _scenario_lines(data.runs) + _angle_B_lines(data.angles_B)


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
            f"smaller radius. Figure: `{RATE_ANGLE_STEM}.png`. Scenario B's angle, which needs a criterion for "
            "when the contact has let go, is at the end of this section.",
            ""] + table + [""]


def _phase_lines(phase: xr.Dataset) -> list[str]:
    """Scenario A's phase diagram at three speeds: what the figure shows, in numbers at 20°."""
    at = phase.sel(alpha=20.0)
    ratios = ", ".join(f"{float(at['d_crit'].sel(speed=speed)) / float(phase['d_max']):.4f} at {speed:g} m/s"
                       for speed in phase["speed"].values)
    return [f"Scenario A's phase diagram (Fig. 9a) at {', '.join(f'{s:g}' for s in THREE_SPEEDS)} m/s "
            "(`me.phase_diagram_at_speeds`): the slip-onset depth lies between the paper's (18) and the "
            "non-adhesive (17) at every angle and falls with the speed; at 20° d_crit/d_max is "
            f"{float(at['d_crit_jkr']) / float(phase['d_max']):.4f} by (18), {ratios}, "
            f"{float(at['d_crit_hertz']) / float(phase['d_max']):.4f} by (17). Figure: `{RATE_PHASE_STEM}.png`.", ""]


def _scenario_lines(runs: dict[str, xr.Dataset]) -> list[str]:
    """Scenario A at 20° at three speeds: the extremes of its forces."""
    rows = [[label, f"{float(run['normal_force'].max()) * 1e3:.2f}",
             f"{float(-run['normal_force'].min()) * 1e3:.2f}", f"{float(run['tangential_force'].max()) * 1e3:.2f}"]
            for label, run in runs.items()]
    table = markdown_table(["run", "F_N,max (mN)", "−F_N,min (mN)", "F_x,max (mN)"], rows,
                           ["default", "right", "right", "right"])
    return [f"Scenario A at 20° with springs and shifts (the discrete method, Δx = {SCENARIO_DX * 1e6:g} µm, τ0's "
            "law) at the same three speeds beside the paper's law: the advancing edge's smaller work leaves a smaller "
            "contact at d_max (F_N,max a little higher, as a contact with less adhesion, and τ0's cap K a, with it "
            "F_x,max, lower), and the receding edge's larger one pulls harder on the way out: at v_ref and above the "
            "contact has not come apart where the path ends (the paper's exit depth). Figure: "
            f"`{RATE_SCENARIO_STEM}.png` (against the distance travelled, v t).", ""] + table + [""]


def _angle_B_lines(angles: xr.Dataset) -> list[str]:
    """The critical angle of scenario B against the speed: the report's table and what it shows."""
    paper = angles.attrs["critical_angle_paper"]
    jump_off = analytic.jump_off(Parameters.paper(), Parameters.paper().dgamma1)["contact_radius"]
    table = markdown_table(["v (m/s)", "v / v_ref", "critical angle of B", "let-go radius / jump-off radius"],
                           [[f"{speed:.0e}", f"{speed / RATE_V_REF:g}", f"{angle:.4f}°", f"{radius / jump_off:.4f}"]
                            for speed, angle, radius in zip(angles["speed"].values, angles["critical_angle"].values,
                                                            angles["let_go_radius"].values)], ["right"] * 4)
    return ["The critical angle of scenario B at the same speeds (`me.critical_angles_B_at_speeds`). The paper's "
            "contact jumps off at a finite radius, the turning point of the Δγ1 branch, and (21) is the angle at which "
            "its springs slide exactly there; a rate-dependent edge has no jump: its radius, and with it the cap K a, "
            "falls to 0 over a finite time while the shift does not, so the springs slide in its last instants at "
            "every angle. It has let go once its release rate rises as it shrinks (dΓ/da <= 0 at the depth: "
            "d <= −3a²/R on the paraboloid, the branch's turning point, after which it collapses whatever the path "
            "does; `me.continuum.let_go`), and the critical angle is the one at which the springs slide exactly "
            f"there. It falls from the paper's (21), {paper:.4f}°, as the speed grows: the lagging edge lets go later, "
            "deeper and at a larger radius, after a longer way out. The continuum's springs "
            "(`me.continuum.solve_rate_shifts`) and the discrete ones slide before the let-go below the angle and "
            f"after it above. Figure: `{RATE_ANGLE_B_STEM}.png`.", ""] + table + [""]


def _plans(data: RateSection, out: FilePath, keep_agreeing: bool) -> list[list[PlannedFile]]:
    rows, angles = data.rows, data.angles
    speeds = np.array([row.speed for row in rows]) / RATE_V_REF
    figure = plot_pull_off_against_speed(speeds, np.array([row.pull_off_ratio for row in rows]), RATE_EXPONENT)
    angle_figure = plot_critical_angle_against_speed(angles["speed"].values / RATE_V_REF,
                                                     angles["critical_angle"].values,
                                                     angles.attrs["critical_angle_adhesive"],
                                                     angles.attrs["critical_angle_hertz"])
    return [[figure_plan(figure, out / f"{RATE_STEM}.png", keep_agreeing),
             figure_plan(angle_figure, out / f"{RATE_ANGLE_STEM}.png", keep_agreeing),
             figure_plan(plot_phase_diagram_at_speeds(data.phase), out / f"{RATE_PHASE_STEM}.png", keep_agreeing),
             figure_plan(plot_scenario_at_speeds(data.runs), out / f"{RATE_SCENARIO_STEM}.png", keep_agreeing),
             figure_plan(plot_critical_angle_B_against_speed(data.angles_B["speed"].values / RATE_V_REF,
                                                              data.angles_B["critical_angle"].values,
                                                              data.angles_B.attrs["critical_angle_paper"]),
                          out / f"{RATE_ANGLE_B_STEM}.png", keep_agreeing)]]


RATE_ADHESION = Section(
    name="rate_adhesion",
    steps=(Step(f"rate-dependent adhesion: pull-off at {len(RATE_SPEEDS)} speeds", rate_rows),
           Step(f"rate-dependent adhesion: the critical angle of A at {len(RATE_SPEEDS)} speeds", rate_angles),
           Step(f"rate-dependent adhesion: A's phase diagram at {len(THREE_SPEEDS)} speeds", rate_phase_diagram),
           Step(f"rate-dependent adhesion: A at 20° at {len(THREE_SPEEDS)} speeds (discrete)", rate_scenario_runs),
           Step(f"rate-dependent adhesion: the critical angle of B at {len(RATE_SPEEDS)} speeds", rate_angles_B)),
    collect=lambda results: RateSection(*results),
    render=rate_lines,
    plan=_plans,
    writing="writing the rate-dependent figures (pull-off, critical angles, phase diagram, scenario A)",
    files=(f"- `{RATE_STEM}.png`: the pull-off force against the unloading speed under the rate-dependent law.",
           f"- `{RATE_ANGLE_STEM}.png`: the critical angle of scenario A against the speed under the same law.",
           f"- `{RATE_PHASE_STEM}.png`: scenario A's phase diagram (Fig. 9a) at three speeds under the same law.",
           f"- `{RATE_SCENARIO_STEM}.png`: F_N and F_x of scenario A at 20° at three speeds and the paper's law.",
           f"- `{RATE_ANGLE_B_STEM}.png`: the critical angle of scenario B against the speed under the same law."),
)
