"""Layers of finite thickness (:mod:`mdr_events.reproduction.finite_layer`, :mod:`mdr_events.reproduction.layer_figures`):
the pull-off force against ``a/h`` with the half-space's and the thin limits drawn, ``F_N(d)`` of an indentation cycle
on a layer beside the half-space's, and the discrete model's forces and area along Fig. 8's and 10's paths on a layer
beside the half-space's."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.plotting.figures import LEGEND_FONTSIZE

__all__ = ["plot_pull_off_against_thickness", "plot_layer_cycles", "plot_layer_simulations",
           "plot_critical_angles_against_thickness"]

#: What :func:`plot_layer_simulations` draws: variable, axis label, scale to the axis' unit.
_SIMULATION_PANELS = (("normal_force", "normal force F_N (N)", 1.0), ("tangential_force", "tangential force F_x (N)", 1.0),
                      ("contact_area", "contact area A (mm²)", 1e6))


def plot_pull_off_against_thickness(curves: dict[str, xr.Dataset], limits: dict[str, float]) -> Figure:
    """``|F_po| / ((3/2)πΔγ1 R)`` against ``a/h`` at pull-off, log–log, one line per curve, with the half-space (1)
    and each thin limit (dashed) drawn.

    Parameters
    ----------
    curves : dict of str to xarray.Dataset
        Label -> :func:`~mdr_events.layer_pull_off_curve` (finite thicknesses).
    limits : dict of str to float
        Label -> a thin limit over ``(3/2)πΔγ1 R``.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    for index, (label, curve) in enumerate(curves.items()):
        scale = 1.5 * np.pi * curve.attrs["param_dgamma1"] * curve.attrs["param_R"]
        axes.loglog(curve.relative_radius.values, -curve.pull_off_force.values / scale, color=f"C{index // 2}",
                    ls="-" if index % 2 == 0 else "--", marker="o" if index % 2 == 0 else "x", ms=3, lw=1.3,
                    label=label)
    axes.axhline(1.0, color="k", lw=0.9, ls=":", label="half-space (JKR, Δγ1)")
    for index, (label, value) in enumerate(limits.items()):
        axes.axhline(value, color="0.4", lw=0.9, ls=(0, (5, 2 + 2 * index)), label=label)
    axes.set_xlabel("contact radius at pull-off over the thickness, a/h")
    axes.set_ylabel("pull-off force |F_po| / ((3/2) π Δγ1 R)")
    axes.legend(fontsize=LEGEND_FONTSIZE)
    axes.grid(True, which="both", lw=0.3, alpha=0.5)
    return figure


def plot_layer_cycles(cycles: dict[str, xr.Dataset]) -> Figure:
    """``F_N(d)`` of :func:`~mdr_events.layer_indentation_cycle` for each label (loading on Δγ0, pinned, shrinking on
    Δγ1 to the jump-off).

    Parameters
    ----------
    cycles : dict of str to xarray.Dataset
        Label -> an indentation cycle.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    for index, (label, cycle) in enumerate(cycles.items()):
        stages = cycle.stage.values
        for number, stage in enumerate(dict.fromkeys(stages)):
            chosen = np.flatnonzero(stages == stage)
            if stage == "pinned":  # (exactly linear in d: its ends alone, no joins of collinear segments, whose
                chosen = chosen[[0, -1]]  # direction is the rounding's and moves pixels between machines)
            axes.plot(cycle.depth.values[chosen] * 1e3, cycle.normal_force.values[chosen], color=f"C{index}",
                      lw=1.4, label=label if number == 0 else None)
    axes.axhline(0.0, color="k", lw=0.6)
    axes.set_xlabel("depth d (mm)")
    axes.set_ylabel("normal force F_N (N)")
    axes.legend(fontsize=LEGEND_FONTSIZE)
    axes.grid(True, lw=0.3, alpha=0.5)
    return figure


def plot_layer_simulations(runs: dict[str, xr.Dataset], angles: tuple[float, ...]) -> Figure:
    """``F_N``, ``F_x`` and ``A`` against time of simulations over the same angles (a scenario's), one line style per
    label (the half-space, a layer) and one colour per angle.

    Parameters
    ----------
    runs : dict of str to xarray.Dataset
        Label -> a simulation with the dimension ``alpha`` (:func:`~mdr_events.simulate`).
    angles : tuple of float
        The angles drawn (degrees), each in every run.

    Returns
    -------
    matplotlib.figure.Figure
        The figure: three panels side by side.
    """
    figure, axes = plt.subplots(1, len(_SIMULATION_PANELS), figsize=(13.0, 4.2), constrained_layout=True)
    styles = ("-", "--", ":", "-.")
    for panel, (name, label, scale) in zip(axes, _SIMULATION_PANELS):
        for number, (run_label, run) in enumerate(runs.items()):
            for index, angle in enumerate(angles):
                case = run.sel(alpha=angle)
                panel.plot(case.time.values, case[name].values * scale, color=f"C{index}", ls=styles[number % 4],
                           lw=1.2, label=f"{run_label}, α = {angle:g}°")
        panel.set_xlabel("time from first contact (s)")
        panel.set_ylabel(label)
        panel.grid(True, lw=0.3, alpha=0.5)
    axes[0].legend(fontsize=LEGEND_FONTSIZE)
    return figure


def plot_critical_angles_against_thickness(curves: dict[str, xr.Dataset]) -> Figure:
    """The critical angles of scenarios A, B and B+ against the layer's thickness (log axis), adhesive (solid) and
    not (dotted), each half-space's as a mark at the right edge, and scenario A's thin-layer limit (dashed).

    Parameters
    ----------
    curves : dict of str to xarray.Dataset
        Label -> :func:`~mdr_events.critical_angles_against_thickness` (its last thickness ``inf``).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    for index, (label, curve) in enumerate(curves.items()):
        finite = np.isfinite(curve.thickness.values)
        h_mm = curve.thickness.values[finite] * 1e3
        for row, scenario in enumerate(curve.scenario.values):
            color = f"C{3 * index + row}"
            adhesive = curve.critical_angle_jkr.values[row]
            axes.semilogx(h_mm, adhesive[finite], color=color, lw=1.4, label=f"{label}, {scenario}")
            if scenario != "B":  # (90° without adhesion: slip always comes first)
                axes.semilogx(h_mm, curve.critical_angle_hertz.values[row][finite], color=color, lw=1.0, ls=":")
            axes.plot([h_mm.max() * 1.6], adhesive[~finite], marker="<", color=color, ms=6, ls="none")
        axes.semilogx(h_mm, curve.thin_limit_A.values[finite], color=f"C{3 * index}", lw=0.9, ls="--",
                      label=f"{label}, A on a thin layer")
    axes.set_xlabel("layer thickness h (mm); ◀ the half-space; dotted: without adhesion")
    axes.set_ylabel("critical angle α_c (degree)")
    axes.set_ylim(0.0, 90.0)
    axes.legend(fontsize=LEGEND_FONTSIZE, ncol=2, loc="upper right")
    axes.grid(True, which="both", lw=0.3, alpha=0.5)
    return figure
