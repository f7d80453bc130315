"""``mdr-events reproduce``: regenerate ``results/`` and its README.

Everything in ``results/`` is written by :func:`reproduce`, deterministically
(same input, same bytes), so that a test can compare the committed report
with a fresh computation. The figures of the simulations come from the
continuum method, with the paper's discrete spring model overlaid for one
angle; the report puts the section's stated numbers beside ours.
"""

from __future__ import annotations

import importlib.metadata
import math
import platform
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Callable

import numpy as np
import xarray as xr

from mdr_events.theory import analytic
from mdr_events._version import __version__
from mdr_events.io.datasets import DOI, RESULT_RTOL
from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, Parameters

if TYPE_CHECKING:
    from mdr_events.app.result_files import FileOutcome

__all__ = ["reproduce", "report_text", "compute", "Reproduction", "PAPER_CRITICAL_ANGLES", "software_versions",
           "recorded_versions", "RECORDED_PACKAGES"]

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
#: Extremes of the continuum runs the report quotes (exact, from the solution: :func:`continuum.extremum`):
#: name -> (quantity, largest).
EXTREMES = {"normal_force_max": ("normal_force", True), "normal_force_min": ("normal_force", False),
            "tangential_force_max": ("tangential_force", True), "contact_area_max": ("contact_area", True),
            "mean_pressure_max": ("mean_pressure", True), "mean_shear_stress_max": ("mean_shear_stress", True)}
#: Relative differences below this are round-off, whose digits differ between machines: the report prints
#: "< 1e-12" for them, so that it stays the same text everywhere.
REPORT_ROUNDOFF = 1e-12
#: Packages whose versions ``results/README.md`` records (the lock file pins them, with the rest).
RECORDED_PACKAGES = ("numpy", "scipy", "sympy", "matplotlib", "xarray", "pandas")

#: Panels of Fig. 8 / 10 (see :data:`mdr_events.plotting.SIMULATION_PANELS`).
PANEL = {"normal_force": "a", "tangential_force": "b", "contact_area": "c", "mean_pressure": "d",
         "mean_shear_stress": "e"}


@dataclass
class Reproduction:
    """Everything the report and the figures are made of (keys ``(radius label, scenario)``)."""

    continuum: dict = field(default_factory=dict)
    discrete: dict = field(default_factory=dict)
    cross_checks: dict = field(default_factory=dict)
    extremes: dict = field(default_factory=dict)
    discrete_errors: dict = field(default_factory=dict)
    history: dict = field(default_factory=dict)


def _jobs():
    return [(label, radius, scenario) for label, radius in RADII.items() for scenario in SCENARIOS]


#: Progress messages :func:`compute` sends (one per step).
COMPUTE_STEPS = 2 * len(RADII) * len(SCENARIOS) + 2


def compute(progress: Callable[[str], None] | None = None) -> Reproduction:
    """Run every simulation and study behind ``results/`` (about 20 s on one core).

    ``progress`` hears one message per step (:data:`COMPUTE_STEPS` of them).
    """
    from mdr_events.models.continuum import extremum, solve_path
    from mdr_events.analysis.convergence import discrete_errors, discrete_minus_continuum
    from mdr_events.analysis.crosscheck import cross_check
    from mdr_events.models.simulate import scenario_paths, simulate

    say = progress or (lambda message: None)
    data = Reproduction()
    jobs = _jobs()
    for label, radius, scenario in jobs:
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
    for label, radius, scenario in jobs:
        say(f"slip-onset cross-check, scenario {scenario}, R = {radius * 1e3:g} mm "
            f"(closed form, continuum, discrete at {len(FIGURE_ANGLES)} angles)")
        data.cross_checks[(label, scenario)] = cross_check(Parameters.paper(R=radius), scenario, FIGURE_ANGLES,
                                                           dx=FIGURE_DX, n_steps=FIGURE_STEPS)
    params = Parameters.paper()
    say(f"convergence of the discrete model to the exact extrema "
        f"({len(CONVERGENCE_SPACINGS)} spacings, {len(CONVERGENCE_ANGLES)} angles)")
    for alpha in CONVERGENCE_ANGLES:
        data.discrete_errors[alpha] = discrete_errors(params, alpha, CONVERGENCE_SPACINGS, steps_per_spacing=0.5)
    say(f"convergence of the discrete model to the continuum over the whole run")
    for scenario in SCENARIOS:
        data.history[scenario] = discrete_minus_continuum(params, scenario, HISTORY_ANGLE, HISTORY_SPACINGS)
    return data


# ----------------------------------------------------------------------------
# helpers on the datasets
def _event_times(ds: xr.Dataset, alpha: float, kind: str) -> np.ndarray:
    case = ds.sel(alpha=alpha)
    kinds = case["event_kind"].values
    return case["event_time"].values[kinds == kind]


def _first(values: np.ndarray) -> float:
    return float(values[0]) if len(values) else math.nan


def _mm(value: float, digits: int = 4) -> str:
    return "—" if not math.isfinite(value) else f"{value * 1e3:.{digits}f}"


# ----------------------------------------------------------------------------
# sections
def _critical_angle_section() -> list[str]:
    lines = [
        "## Critical angles of scenario A (slip begins exactly at d_max)",
        "",
        "| R | quantity | paper | mdr_events | difference |",
        "|---|---|---|---|---|",
    ]
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        for key, adhesive, equation in (("hertz", False, "(17)"), ("jkr", True, "(18)")):
            ours = analytic.critical_angle(params, "A", adhesion=adhesive)
            paper = PAPER_CRITICAL_ANGLES[key] if label == "R30" else None
            paper_text = f"{paper:.2f}°" if paper is not None else "not stated"
            diff = f"{ours - paper:+.3f}°" if paper is not None else "—"
            lines.append(f"| {radius * 1e3:g} mm | α_c {key.upper() if key == 'jkr' else 'Hertz'} {equation} "
                         f"| {paper_text} | {ours:.3f}° | {diff} |")
    lines += [
        "",
        "## Scenario B: angle above which the contact comes apart before any spring slides",
        "",
        "From eq. (21) (pull-off branch, Δγ1) at the jump-off point; without adhesion slip",
        "always comes first (90°). Not stated in the paper.",
        "",
        "| R | α (adhesive) |",
        "|---|---|",
    ]
    for label, radius in RADII.items():
        params = Parameters.paper(R=radius)
        lines.append(f"| {radius * 1e3:g} mm | {analytic.critical_angle(params, 'B', adhesion=True):.3f}° |")
    return lines


def _cross_check_section(data: Reproduction) -> list[str]:
    lines = [
        "",
        "## Slip onset: closed form, continuum and discrete model side by side",
        "",
        "Depth d at which the first spring slides (mm): scenario A during indentation, eq. (18);",
        "scenario B during pull-off, eq. (21). Continuum: the event log of the continuum method.",
        f"Discrete: the paper's spring model, Δx = {FIGURE_DX * 1e6:g} µm, {FIGURE_STEPS} time steps; its",
        "tolerance is 3KΔx plus one time step of depth (K = π τ0 tan α / (2G*)). \"pinned\": in scenario B the",
        "radius is still pinned at a(d_max; Δγ0) when the springs slide, which (21) does not model, so the",
        "closed form is not expected to agree (see `mdr_events.cross_check`).",
        "",
        "| R | scenario | α | closed form | continuum | discrete | discrete − continuum | tolerance | note |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for (label, scenario), ds in data.cross_checks.items():
        params = Parameters.from_attrs(ds.attrs)
        for alpha in ds["alpha"].values:
            row = ds.sel(alpha=alpha)
            closed = float(row["d_crit_closed_form"])
            continuum = float(row["d_crit_continuum"])
            if scenario == "A" and closed > params.d_max:
                note = "no slip in indentation (closed form beyond d_max)"
            elif scenario == "B" and closed == -math.inf:
                note = "jump-off before any slip"
            elif int(row["found_once_at_phase_end"]):
                note = "agree: only one method slips, within tolerance of the " + (
                    "jump-off" if scenario == "B" else "d_max")
            elif int(row["pinned_radius"]):
                note = "pinned"
            elif int(row["disagree"]):
                note = "**disagree**"
            else:
                note = "agree"
            lines.append(
                f"| {params.R * 1e3:g} mm | {scenario} | {alpha:g}° | {_mm(closed, 5)} | {_mm(continuum, 5)} "
                f"| {_mm(float(row['d_crit_discrete']), 5)} | {float(row['discrete_minus_continuum']) * 1e6:+.3f} µm "
                f"| {float(row['discrete_tolerance']) * 1e6:.3f} µm | {note} |".replace("+nan µm", "—"))
    return lines


def _differences_section(data: Reproduction) -> list[str]:
    lines = [
        "",
        "## The four differences between simulation and experiment of section 4.2",
        "",
        f"Panels refer to `fig8_R30.png` (scenario A) and `fig10_R30.png` (scenario B): (a) F_N, (b) F_x,",
        f"(c) A, (d) <p>, (e) τ. Continuum method, {data.continuum[('R30', 'A')].sizes['time']} samples per run.",
        "",
        "### (1) The adhesive strength |F_N,min| is the same for every angle (panel a)",
        "",
        "The paper: normal and tangential contact are independent, so |F_N,min| does not depend on α;",
        "JKR gives |F_N,min| = (3/2) π Δγ1 R. Ours (continuum, the exact minimum of each run's solution,",
        f"`mdr_events.continuum.extremum`; the discrete model at {OVERLAY_ANGLE:g}°, Δx = {FIGURE_DX * 1e6:g} µm, "
        "for comparison):",
        "",
        "| R | scenario | (3/2)πΔγ1R | continuum, min over angles | max over angles | largest relative difference "
        f"| discrete at {OVERLAY_ANGLE:g}° |",
        "|---|---|---|---|---|---|---|",
    ]
    for (label, scenario), ds in data.continuum.items():
        params = Parameters.from_attrs(ds.attrs)
        jkr = -analytic.pull_off_force(params, params.dgamma1)
        values = -data.extremes[(label, scenario)]["normal_force_min"]
        worst = np.max(np.abs(values - jkr)) / jkr
        worst_text = f"< {REPORT_ROUNDOFF:g}" if worst < REPORT_ROUNDOFF else f"{worst:.1e}"
        discrete = -float(data.discrete[(label, scenario)]["normal_force"].min())
        lines.append(f"| {params.R * 1e3:g} mm | {scenario} | {jkr * 1e3:.4f} mN | {values.min() * 1e3:.4f} mN "
                     f"| {values.max() * 1e3:.4f} mN | {worst_text} | {discrete * 1e3:.4f} mN |")
    ds = data.continuum[("R30", "A")]
    lines += [
        "",
        "The same independence makes A and F_x constant at the start of pull-off (panels c and b): the",
        "radius stays pinned from d_max until d falls to the Δγ1 branch, and in scenario A the indenter",
        "moves only normally then. Scenario A, R = 30 mm (continuum event log):",
        "",
        "| α | d_max reached | detachment starts | interval of constant A | F_x change over it |",
        "|---|---|---|---|---|",
    ]
    for alpha in ds["alpha"].values:
        corner = _first(_event_times(ds, alpha, "corner"))
        release = _first(_event_times(ds, alpha, "detachment_starts"))
        case = ds.sel(alpha=alpha)
        inside = (case["time"] >= corner) & (case["time"] <= release)
        force = case["tangential_force"].values[inside.values]
        change = float(np.max(force) - np.min(force)) if force.size else math.nan
        lines.append(f"| {alpha:g}° | {corner:.1f} s | {release:.1f} s | {release - corner:.1f} s | {change:.1e} N |")
    lines += [
        "",
        "### (2) Maximum forces, area and pressure are below the experiment's (panels a–d)",
        "",
        "The paper: the experiment used a layer of h = 5 mm, the model is a half-space (h → ∞), whose",
        "contact is softer. The experimental values are in the paper's Fig. 5, not in the section text, so",
        "only ours are listed (scenario A, R = 30 mm, continuum, exact maxima of each run's solution):",
        "",
        "| α | F_N,max | F_x,max | A_max | <p>_max |",
        "|---|---|---|---|---|",
    ]
    extremes = data.extremes[("R30", "A")]
    for i, alpha in enumerate(ds["alpha"].values):
        lines.append(f"| {alpha:g}° | {extremes['normal_force_max'][i] * 1e3:.3f} mN "
                     f"| {extremes['tangential_force_max'][i] * 1e3:.3f} mN "
                     f"| {extremes['contact_area_max'][i] * 1e6:.3f} mm² "
                     f"| {extremes['mean_pressure_max'][i] / 1e3:.3f} kPa |")
    lines += [
        "",
        f"### (3) The τ0 = {PAPER_TAU0 / 1e3:g} kPa plateau in pull-off (panel e)",
        "",
        "The paper: \"in the pull-off phase ... the tangential stresses in all cases increase to the",
        "maximum stationary value τ0\". In the model every spring slides once ū(a) of the shrinking",
        "contact falls below the indenter's travel x1 = d_max/tan α, and that happens before the jump-off",
        "only if ū(a_jump-off) < x1. **Where it does not, τ stays below τ0**: with the inferred E, ν and v",
        "this is the case at 70° and 80° for R = 30 mm and from 50° on for R = 100 mm. Scenario A,",
        "largest τ per angle (continuum, exact maximum of each run's solution; full slip from the event log):",
        "",
        "| R | α | x1 | ū(a_jump-off) | τ_max | reaches τ0 | full slip at |",
        "|---|---|---|---|---|---|---|",
    ]
    for (label, scenario), ds_a in data.continuum.items():
        if scenario != "A":
            continue
        params = Parameters.from_attrs(ds_a.attrs)
        cap = float(analytic.critical_shift(analytic.jump_off(params, params.dgamma1)["contact_radius"], params))
        for i, alpha in enumerate(ds_a["alpha"].values):
            x1 = params.d_max / math.tan(math.radians(alpha))
            tau = float(data.extremes[(label, scenario)]["mean_shear_stress_max"][i])
            full = _event_times(ds_a, alpha, "full_slip")
            reached = math.isclose(tau, params.tau0, rel_tol=1e-9)
            lines.append(f"| {params.R * 1e3:g} mm | {alpha:g}° | {x1 * 1e6:.1f} µm | {cap * 1e6:.1f} µm "
                         f"| {tau / 1e3:.2f} kPa | {'yes' if reached else 'no'} "
                         f"| {f'{full[-1]:.1f} s' if len(full) else '—'} |")
    lines += [
        "",
        "### (4) The contact area grows smoothly (panel c)",
        "",
        "The paper: in the experiment new regions of rubber attach abruptly; in the model the area grows",
        "only through the normal JKR contact, hence smoothly. Ours: after the JKR jump-in at first contact,",
        "A changes between consecutive samples by at most the share of A_max below (it is continuous,",
        "so this share falls with the sample spacing); scenario A, R = 30 mm:",
        "",
        "| α | jump-in area πa0² | largest change between samples during indentation | sample spacing |",
        "|---|---|---|---|",
    ]
    for alpha in ds["alpha"].values:
        case = ds.sel(alpha=alpha)
        corner = _first(_event_times(ds, alpha, "corner"))
        area = case["contact_area"].values
        indentation = case["time"].values <= corner
        steps = np.abs(np.diff(area[indentation]))
        spacing = float(case["time"].values[1] - case["time"].values[0])
        lines.append(f"| {alpha:g}° | {area[0] * 1e6:.4f} mm² | {steps.max() / np.nanmax(area):.2e} of A_max "
                     f"| {spacing:.2f} s |")
    return lines


def _convergence_section(data: Reproduction) -> list[str]:
    from mdr_events.analysis.convergence import HISTORY_QUANTITIES, observed_orders

    names = {"normal_force_min": "F_N,min", "contact_area_max": "A_max", "tangential_force_max": "F_x,max"}
    lines = [
        "",
        "## Convergence of the discrete model (R = 30 mm)",
        "",
        "### To the exact extrema (scenario A)",
        "",
        "Relative error against the exact values (F_N,min = −(3/2)πΔγ1R; A_max = π a(d_max)² on the Δγ0",
        "branch; F_x,max from the stick/slip integral at d_max, `mdr_events.convergence`), with the time",
        "step refined with Δx (the indenter moves Δx/2 per step). Observed order in brackets. The paper",
        "says the solution does not depend on Δx: it does, at first order, by about 0.1 % at Δx = 1 µm.",
        "A_max is quantised to a = mΔx, so its error is bounded by Δx/a but does not fall smoothly;",
        "likewise F_N,min, whose sampled radius is off by up to Δx/2, so that its error is bounded by",
        "E* Δl_max(a_F) Δx / |F_N,min| (about 1e-3 per µm here) without falling smoothly.",
        "",
        "| α | quantity | " + " | ".join(f"Δx = {dx * 1e6:g} µm" for dx in CONVERGENCE_SPACINGS) + " |",
        "|---|---|" + "---|" * len(CONVERGENCE_SPACINGS),
    ]
    for alpha, errors in data.discrete_errors.items():
        for key, label in names.items():
            orders = observed_orders(CONVERGENCE_SPACINGS, errors[key])
            cells = [f"{errors[key][0]:.2e}"] + [f"{e:.2e} ({o:.2f})" for e, o in zip(errors[key][1:], orders)]
            lines.append(f"| {alpha:g}° | {label} | " + " | ".join(cells) + " |")
    labels = {"normal_force": "F_N", "tangential_force": "F_x", "contact_area": "A"}
    lines += [
        "",
        f"### To the continuum over the whole run (α = {HISTORY_ANGLE:g}°)",
        "",
        "max over time of |discrete − continuum| divided by max over time of |continuum|, the continuum",
        "evaluated at the discrete model's sample times (`mdr_events.convergence.discrete_minus_continuum`);",
        "observed order in brackets. Left out (their number is in the last row): the samples at which one",
        "method is in contact and the other not (the jump-in, met up to one step apart), and the sample",
        "ending the time step that straddles a path corner (the discrete model cuts the corner there).",
        "",
        "| scenario | quantity | " + " | ".join(f"Δx = {dx * 1e6:g} µm" for dx in HISTORY_SPACINGS) + " |",
        "|---|---|" + "---|" * len(HISTORY_SPACINGS),
    ]
    for scenario, differences in data.history.items():
        for name in HISTORY_QUANTITIES:
            values = differences[name]
            orders = observed_orders(HISTORY_SPACINGS, values)
            cells = [f"{values[0]:.2e}"] + [f"{e:.2e} ({o:.2f})" for e, o in zip(values[1:], orders)]
            lines.append(f"| {scenario} | {labels[name]} | " + " | ".join(cells) + " |")
        lines.append(f"| {scenario} | samples left out | "
                     + " | ".join(str(int(n)) for n in differences["samples_left_out"]) + " |")
    return lines


def _parameter_section() -> list[str]:
    params = Parameters.paper()
    lines = [
        "",
        "## Parameters (R = 30 mm; the R = 100 mm set differs only in R)",
        "",
        "| parameter | value | unit | source |",
        "|---|---|---|---|",
    ]
    for name, value in params.as_dict().items():
        source = "**inferred** (not stated in section 4)" if name in Parameters.INFERRED_FIELDS else "section 4"
        lines.append(f"| {name} ({PARAMETER_LONG_NAMES[name]}) | {value:.6g} | {PARAMETER_UNITS[name]} | {source} |")
    lines += [
        f"| E* | {params.E_star:.6g} | Pa | derived |",
        f"| G* | {params.G_star:.6g} | Pa | derived |",
        "",
        "## Files",
        "",
        "- `phase_diagram_A_R30.{nc,png}`, `phase_diagram_A_R100.{nc,png}`: Fig. 9a.",
        "- `phase_diagram_B_R30.{nc,png}`, `phase_diagram_B_R100.{nc,png}`: Fig. 9b.",
        "- `fig8_R30.{nc,png}`, `fig8_R100.{nc,png}`: Fig. 8 (scenario A), continuum method, with its event",
        "  log in `fig8_R*_events.csv` and the discrete overlay in `fig8_R*_discrete.nc`.",
        "- `fig10_R30.{nc,png}`, `fig10_R100.{nc,png}`: Fig. 10 (scenario B), likewise.",
        "",
    ]
    return lines


def software_versions() -> dict[str, str]:
    """Python's version and those of :data:`RECORDED_PACKAGES`, as installed now."""
    versions = {"Python": platform.python_version()}
    versions.update({name: importlib.metadata.version(name) for name in RECORDED_PACKAGES})
    return versions


_COMPUTED_WITH = "Computed with "


def _software_section(versions: dict[str, str]) -> list[str]:
    return [
        "## Software",
        "",
        _COMPUTED_WITH + ", ".join(f"{name} {version}" for name, version in versions.items()) + ".",
        "",
        "`make` installs these versions from the lock file `constraints.txt`. With other versions (or",
        f"another CPU) the datasets agree within {RESULT_RTOL:g} of each variable's largest magnitude",
        "(`mdr_events.datasets.result_differences`) and this report, which rounds, exactly;",
        "`mdr-events reproduce` then keeps the files as they are.",
        "",
    ]


def recorded_versions(text: str) -> dict[str, str]:
    """The versions a report's software section records (``{}`` if it has none)."""
    match = re.search(f"^{_COMPUTED_WITH}(.*)\\.$", text, flags=re.MULTILINE)
    if match is None:
        return {}
    return dict(item.rsplit(" ", 1) for item in match.group(1).split(", "))


def report_text(data: Reproduction | None = None, versions: dict[str, str] | None = None) -> str:
    """The text of ``results/README.md`` (everything computed afresh unless ``data`` is given).

    ``versions``: the software versions to record (default :func:`software_versions`).
    """
    data = compute() if data is None else data
    lines = [
        "# Reproduction of section 4 of Lyashenko, Popov & Borysiuk (2023)",
        "",
        f"Written by `mdr-events reproduce` (mdr_events {__version__}); do not edit by hand.",
        f"Paper: doi:{DOI}.",
        "",
    ]
    lines += _critical_angle_section()
    lines += _cross_check_section(data)
    lines += _differences_section(data)
    lines += _convergence_section(data)
    lines += _parameter_section()
    lines += _software_section(software_versions() if versions is None else versions)
    return "\n".join(lines)


def reproduce(out: Path, progress: Callable[[str], None] = print, keep_agreeing: bool = True) -> list[FileOutcome]:
    """Write every figure, dataset and the report into ``out``; ``progress`` hears each step.

    With ``keep_agreeing`` (the default) a file that agrees with the fresh computation is not
    rewritten (:mod:`mdr_events.output`), and the report keeps the software versions it records when
    every other file was kept and its numbers are unchanged, so that ``git status`` stays clean on a
    machine whose rounding differs.
    """
    from mdr_events.app.result_files import FileStatus, describe_outcomes, write_dataset, write_phase_diagram, write_simulation, write_text

    out = Path(out)
    outcomes: list[FileOutcome] = []
    total = len(_jobs()) + COMPUTE_STEPS + 1
    count = iter(range(1, total + 1))

    def step(message: str) -> None:
        progress(f"[{next(count)}/{total}] {message}")

    def done(new: list[FileOutcome]) -> None:
        outcomes.extend(new)
        progress(f"    {describe_outcomes(new)}")

    for label, radius, scenario in _jobs():
        figure = "9a" if scenario == "A" else "9b"
        step(f"Fig. {figure}, R = {radius * 1e3:g} mm (phase diagram)")
        done(write_phase_diagram(Parameters.paper(R=radius), scenario, out, f"phase_diagram_{scenario}_{label}",
                                 keep_agreeing=keep_agreeing))
    data = compute(step)
    step("writing Fig. 8 and 10 (.nc, .png, events .csv) and README.md")
    for (label, scenario), dataset in data.continuum.items():
        stem = f"fig{FIGURE_NUMBERS[scenario]}_{label}"
        overlay, outcome = write_dataset(data.discrete[(label, scenario)], out / f"{stem}_discrete.nc", keep_agreeing)
        done([outcome] + write_simulation(dataset, out, stem, overlay=overlay, keep_agreeing=keep_agreeing))
    text = report_text(data)
    readme = out / "README.md"
    if keep_agreeing and readme.exists() and all(o.status is FileStatus.KEPT for o in outcomes):
        existing = readme.read_text()
        recorded = recorded_versions(existing)
        if recorded and report_text(data, versions=recorded) == existing:
            text = existing  # the files on disk were written with the versions it records
    done([write_text(text, readme, keep_agreeing)])
    return outcomes
