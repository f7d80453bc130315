"""``mdr-events reproduce``: regenerate ``results/`` and its README.

Everything in ``results/`` is written by :func:`reproduce`, deterministically
(same input, same bytes), so that a test can compare the committed report
with a fresh computation.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable

from . import analytic
from ._version import __version__
from .datasets import DOI, atomic_write
from .parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, Parameters

__all__ = ["reproduce", "report_text", "PAPER_CRITICAL_ANGLES"]

#: Critical angles stated in section 4 (R = 30 mm), degrees.
PAPER_CRITICAL_ANGLES = {"hertz": 23.59, "jkr": 22.87}
RADII = {"R30": 0.03, "R100": 0.1}


#: Discretisation of the figures in results/.
FIGURE_DX = 1e-6
FIGURE_STEPS = 10_000
FIGURE_THINNING = 5
#: Convergence study: spacings (m), steps per spacing, angles (degrees).
CONVERGENCE_SPACINGS = (16e-6, 8e-6, 4e-6, 2e-6, 1e-6)
CONVERGENCE_ANGLES = (10.0, 30.0, 60.0)


def figure_simulations() -> dict[tuple[str, str], "xarray.Dataset"]:  # noqa: F821
    """The datasets behind Fig. 8 (scenario A) and Fig. 10 (scenario B) for both radii."""
    from .simulate import simulate

    return {
        (label, scenario): simulate(Parameters.paper(R=radius), scenario, dx=FIGURE_DX, n_steps=FIGURE_STEPS)
        for label, radius in RADII.items()
        for scenario in ("A", "B")
    }


def _simulation_sections(simulations) -> list[str]:
    import math

    import numpy as np

    lines = [
        "",
        "## Pull-off force: the same for every angle (section 4.2 (1))",
        "",
        f"Discrete spring model, Δx = {FIGURE_DX * 1e6:g} µm, {FIGURE_STEPS} time steps; "
        "JKR: |F_N,min| = (3/2) π Δγ1 R.",
        "",
        "| R | scenario | JKR | min over angles | max over angles | largest relative difference |",
        "|---|---|---|---|---|---|",
    ]
    for (label, scenario), ds in simulations.items():
        params = Parameters.from_attrs(ds.attrs)
        jkr = -analytic.pull_off_force(params, params.dgamma1)
        values = -ds["normal_force"].min("time").values
        worst = np.max(np.abs(values - jkr)) / jkr
        lines.append(f"| {params.R * 1e3:g} mm | {scenario} | {jkr * 1e3:.4f} mN | {values.min() * 1e3:.4f} mN "
                     f"| {values.max() * 1e3:.4f} mN | {worst:.1e} |")
    lines += [
        "",
        "## The τ0 = 42 kPa plateau in pull-off (section 4.2 (3))",
        "",
        "The paper: \"in the pull-off phase ... the tangential stresses in all cases increase to the",
        "maximum stationary value τ0\". In the model every spring slides once ū(a) of the shrinking",
        "contact falls below the indenter's travel x1 = d_max/tan α; that happens before the jump-off",
        "only if ū(a_jump-off) < x1. Where it does not, τ stays below τ0 (scenario A, largest τ in",
        "pull-off per angle):",
        "",
        "| R | α | x1 | ū(a_jump-off) | τ_max | reaches τ0 |",
        "|---|---|---|---|---|---|",
    ]
    for (label, scenario), ds in simulations.items():
        if scenario != "A":
            continue
        params = Parameters.from_attrs(ds.attrs)
        cap = float(analytic.critical_shift(analytic.jump_off(params, params.dgamma1)["contact_radius"], params))
        for alpha in ds["alpha"].values:
            x1 = params.d_max / math.tan(math.radians(alpha))
            tau = float(ds["mean_shear_stress"].sel(alpha=alpha).max())
            lines.append(f"| {params.R * 1e3:g} mm | {alpha:g}° | {x1 * 1e6:.1f} µm | {cap * 1e6:.1f} µm "
                         f"| {tau / 1e3:.2f} kPa | {'yes' if math.isclose(tau, params.tau0, rel_tol=1e-9) else 'no'} |")
    return lines


def _convergence_section() -> list[str]:
    from .convergence import discrete_errors, observed_orders

    params = Parameters.paper()
    names = {"normal_force_min": "F_N,min", "contact_area_max": "A_max", "tangential_force_max": "F_x,max"}
    lines = [
        "",
        "## Convergence of the discrete model (scenario A, R = 30 mm)",
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
    for alpha in CONVERGENCE_ANGLES:
        errors = discrete_errors(params, alpha, CONVERGENCE_SPACINGS, steps_per_spacing=0.5)
        for key, label in names.items():
            orders = observed_orders(CONVERGENCE_SPACINGS, errors[key])
            cells = [f"{errors[key][0]:.2e}"] + [f"{e:.2e} ({o:.2f})" for e, o in zip(errors[key][1:], orders)]
            lines.append(f"| {alpha:g}° | {label} | " + " | ".join(cells) + " |")
    return lines


def report_text(simulations=None) -> str:
    """The text of ``results/README.md`` (numbers computed afresh unless ``simulations`` are given)."""
    simulations = figure_simulations() if simulations is None else simulations
    lines = [
        "# Reproduction of section 4 of Lyashenko, Popov & Borysiuk (2023)",
        "",
        f"Written by `mdr-events reproduce` (mdr_events {__version__}); do not edit by hand.",
        f"Paper: doi:{DOI}.",
        "",
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
    lines += _simulation_sections(simulations)
    lines += _convergence_section()
    params = Parameters.paper()
    lines += [
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
        "- `fig8_R30.{nc,png}`, `fig8_R100.{nc,png}`: Fig. 8 (scenario A, discrete model).",
        "- `fig10_R30.{nc,png}`, `fig10_R100.{nc,png}`: Fig. 10 (scenario B, discrete model).",
        f"  The files keep every {FIGURE_THINNING}th of the {FIGURE_STEPS} time steps the numbers above use.",
        "",
    ]
    return "\n".join(lines)


def reproduce(out: Path, progress: Callable[[str], None] = print) -> list[Path]:
    """Write every figure, dataset and the report into ``out``."""
    from .cli import _write_phase_diagram, write_simulation
    from .simulate import simulate

    out = Path(out)
    written: list[Path] = []
    jobs = [(label, radius, scenario) for label, radius in RADII.items() for scenario in ("A", "B")]
    total = 2 * len(jobs) + 1
    number = 0
    for label, radius, scenario in jobs:
        number += 1
        figure = "9a" if scenario == "A" else "9b"
        progress(f"[{number}/{total}] Fig. {figure}, R = {radius * 1e3:g} mm")
        written += _write_phase_diagram(Parameters.paper(R=radius), scenario, out, f"phase_diagram_{scenario}_{label}")
    simulations = {}
    for label, radius, scenario in jobs:
        number += 1
        figure = "8" if scenario == "A" else "10"
        progress(f"[{number}/{total}] Fig. {figure}, R = {radius * 1e3:g} mm (discrete, Δx = {FIGURE_DX * 1e6:g} µm)")
        dataset = simulate(Parameters.paper(R=radius), scenario, dx=FIGURE_DX, n_steps=FIGURE_STEPS)
        simulations[(label, scenario)] = dataset
        # the files keep every FIGURE_THINNING-th sample (plenty for the figure, a fifth of the bytes);
        # the report's numbers come from the full run
        written += write_simulation(dataset.isel(time=slice(None, None, FIGURE_THINNING)), out, f"fig{figure}_{label}")
    progress(f"[{total}/{total}] results/README.md (with the convergence study)")
    text = report_text(simulations)
    written.append(atomic_write(out / "README.md", lambda temporary: Path(temporary).write_text(text)))
    return written
