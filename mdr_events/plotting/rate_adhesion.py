"""The rate-dependent pull-off (:mod:`mdr_events.reproduction.rate_adhesion`): the least normal force over JKR's
``(3/2)πΔγ1 R`` against the unloading speed over ``v_ref``, log–log, with the rate-independent limit drawn."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from mdr_events.plotting.figures import LEGEND_FONTSIZE

__all__ = ["plot_pull_off_against_speed", "plot_critical_angle_against_speed", "plot_critical_angle_B_against_speed",
           "plot_scenario_at_speeds", "plot_phase_diagram_at_speeds"]


def plot_pull_off_against_speed(speed_ratios: np.ndarray, pull_off_ratios: np.ndarray, exponent: float) -> Figure:
    """``|F_pull| / ((3/2)πΔγ1 R)`` against ``v / v_ref`` (markers and line), the rate-independent limit 1 (dashed),
    and the law's ``1 + (v/v_ref)^n`` for comparison (dotted).

    Parameters
    ----------
    speed_ratios : numpy.ndarray
        The path's speed over the law's ``v_ref``.
    pull_off_ratios : numpy.ndarray
        The pull-off force over JKR's at ``Δγ1``.
    exponent : float
        The law's ``n``.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    axes.loglog(speed_ratios, pull_off_ratios, marker="o", color="C0", lw=1.4,
                label="rate-dependent MDR (continuum.solve_edge)")
    axes.axhline(1.0, color="k", lw=0.9, ls="--", label="rate-independent limit (JKR, Δγ1)")
    fine = np.logspace(np.log10(speed_ratios.min()), np.log10(speed_ratios.max()), 200)
    axes.loglog(fine, 1.0 + fine**exponent, color="0.5", lw=0.9, ls=":",
                label=f"the law's Δγ/Δγ1 = 1 + (v/v_ref)^{exponent:g} at the path's speed")
    axes.set_xlabel("unloading speed v / v_ref")
    axes.set_ylabel("pull-off force |F_pull| / ((3/2) π Δγ1 R)")
    axes.legend(fontsize=LEGEND_FONTSIZE)
    axes.grid(True, which="both", lw=0.3, alpha=0.5)
    return figure


def plot_critical_angle_against_speed(speed_ratios: np.ndarray, angles: np.ndarray, adhesive: float,
                                      hertz: float) -> Figure:
    """The critical angle of scenario A against ``v / v_ref`` (markers and line, log abscissa), between the
    rate-independent adhesive angle (18) (dashed) and the non-adhesive one (17) (dotted).

    Parameters
    ----------
    speed_ratios : numpy.ndarray
        The path's speed over the law's ``v_ref``.
    angles : numpy.ndarray
        The critical angles (degrees).
    adhesive : float
        The paper's critical angle with adhesion, eq. (18) at ``d_max`` (degrees).
    hertz : float
        The critical angle without adhesion, eq. (17) at ``d_max`` (degrees).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    axes.semilogx(speed_ratios, angles, marker="o", color="C0", lw=1.4,
                  label="rate-dependent MDR (analysis.rate_angles)")
    axes.axhline(adhesive, color="k", lw=0.9, ls="--", label="rate-independent, with adhesion (18)")
    axes.axhline(hertz, color="0.4", lw=0.9, ls=":", label="without adhesion (17)")
    axes.set_xlabel("path speed v / v_ref")
    axes.set_ylabel("critical angle of scenario A (°)")
    axes.legend(fontsize=LEGEND_FONTSIZE)
    axes.grid(True, which="both", lw=0.3, alpha=0.5)
    return figure


def plot_critical_angle_B_against_speed(speed_ratios: np.ndarray, angles: np.ndarray, paper: float) -> Figure:
    """The critical angle of scenario B against ``v / v_ref`` (markers and line, log abscissa): the springs slide before
    the edge lets go below it; the paper's (21) at the jump-off (dashed), its limit ``v → 0``.

    Parameters
    ----------
    speed_ratios : numpy.ndarray
        The path's speed over the law's ``v_ref``.
    angles : numpy.ndarray
        The critical angles (degrees).
    paper : float
        The paper's critical angle of scenario B, eq. (21) at the jump-off (degrees).

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, axes = plt.subplots(figsize=(6.4, 4.6), constrained_layout=True)
    axes.semilogx(speed_ratios, angles, marker="o", color="C1", lw=1.4,
                  label="rate-dependent MDR: slip before the let-go (analysis.rate_let_go)")
    axes.axhline(paper, color="k", lw=0.9, ls="--", label="rate-independent, slip before the jump-off (21)")
    axes.set_xlabel("path speed v / v_ref")
    axes.set_ylabel("critical angle of scenario B (°)")
    axes.legend(fontsize=LEGEND_FONTSIZE)
    axes.grid(True, which="both", lw=0.3, alpha=0.5)
    return figure


def plot_scenario_at_speeds(runs: dict[str, xr.Dataset]) -> Figure:
    """``F_N`` and ``F_x`` of one scenario against the distance travelled along the path (``v t``), one line per run
    (the paper's law and the rate-dependent one at several speeds), so that runs at different speeds share an axis.

    Parameters
    ----------
    runs : dict of str to xarray.Dataset
        Label → a simulation of one case (``time``, ``normal_force``, ``tangential_force``; attribute ``param_v``).

    Returns
    -------
    matplotlib.figure.Figure
        The figure: ``F_N`` above, ``F_x`` below.
    """
    figure, (upper, lower) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True, constrained_layout=True)
    for index, (label, run) in enumerate(runs.items()):
        travelled = run["time"].values * float(run.attrs["param_v"]) * 1e3
        style = dict(color="k", lw=1.0, ls="--") if index == 0 else dict(color=f"C{index - 1}", lw=1.3)
        upper.plot(travelled, run["normal_force"].values * 1e3, label=label, **style)
        lower.plot(travelled, run["tangential_force"].values * 1e3, **style)
    upper.set_ylabel("normal force F_N (mN)")
    lower.set_ylabel("tangential force F_x (mN)")
    lower.set_xlabel("distance travelled along the path v t (mm)")
    upper.legend(fontsize=LEGEND_FONTSIZE)
    for axes in (upper, lower):
        axes.grid(True, lw=0.3, alpha=0.5)
    return figure


def plot_phase_diagram_at_speeds(diagram: xr.Dataset) -> Figure:
    """Scenario A's slip-onset depth over ``d_max`` against the angle at each speed (Fig. 9a's axes), with the
    rate-independent curves (18) (dashed) and (17) (dotted); below, each over (18), where the speeds part.

    Parameters
    ----------
    diagram : xarray.Dataset
        :func:`~mdr_events.analysis.rate_angles.phase_diagram_at_speeds`'s dataset (with ``d_crit_jkr`` and
        ``d_crit_hertz``) and the law's ``v_ref`` among its attributes.

    Returns
    -------
    matplotlib.figure.Figure
        The figure.
    """
    figure, (upper, lower) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True, constrained_layout=True)
    alpha, d_max = diagram["alpha"].values, float(diagram["d_max"])
    adhesive = diagram["d_crit_jkr"].values
    for index, speed in enumerate(diagram["speed"].values):
        depth = diagram["d_crit"].sel(speed=speed).values
        style = dict(color=f"C{index}", lw=1.3)
        upper.plot(alpha, depth / d_max, label=f"v / v_ref = {speed / diagram.attrs['v_ref']:g}", **style)
        lower.plot(alpha, depth / adhesive, **style)
    for values, style in ((adhesive, dict(color="k", lw=0.9, ls="--", label="rate-independent (18)")),
                          (diagram["d_crit_hertz"].values, dict(color="0.4", lw=0.9, ls=":", label="no adhesion (17)"))):
        upper.plot(alpha, values / d_max, **style)
        lower.plot(alpha, values / adhesive, **{k: v for k, v in style.items() if k != "label"})
    upper.axhline(1.0, color="0.7", lw=0.8)
    upper.set_ylabel("slip-onset depth d_crit / d_max")
    lower.set_ylabel("d_crit / d_crit of (18)")
    lower.set_xlabel("path angle α (°)")
    upper.legend(fontsize=LEGEND_FONTSIZE)
    for axes in (upper, lower):
        axes.grid(True, lw=0.3, alpha=0.5)
    return figure
