"""The rate-dependent pull-off (:mod:`mdr_events.reproduction.rate_adhesion`): the least normal force over JKR's
``(3/2)πΔγ1 R`` against the unloading speed over ``v_ref``, log–log, with the rate-independent limit drawn."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from mdr_events.plotting.figures import LEGEND_FONTSIZE

__all__ = ["plot_pull_off_against_speed", "plot_critical_angle_against_speed"]


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
