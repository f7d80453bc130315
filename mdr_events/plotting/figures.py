"""Figures drawn from the datasets (never recomputed here): Fig. 8, 9a, 9b, 10, and fretting loops.

A figure carries the paper's number (Fig. 8, 9a, 9b, 10) only when its
dataset was computed with one of the paper's parameter sets
(:meth:`mdr_events.parameters.Parameters.preset_name`); otherwise its title
says what it shows. This module leaves the matplotlib backend alone (the CLI
selects Agg itself).
"""

from __future__ import annotations

import io
import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import xarray as xr
from matplotlib.layout_engine import ConstrainedLayoutEngine

from mdr_events.io.files import atomic_write
from mdr_events.models.motion import case_dimension, case_text
from mdr_events.parameters import Parameters
from mdr_events.theory.phase import PHASE_DIAGRAM_CONTENT

__all__ = ["add_inferred_footnote", "figure_png", "plot_phase_diagram", "plot_simulation", "plot_fretting", "save_figure"]

_MM = 1e3

#: Figure numbers of the paper, used only for datasets of a paper preset.
PHASE_DIAGRAM_FIGURES = {"A": "Fig. 9a", "B": "Fig. 9b"}
SIMULATION_FIGURES = {"A": "Fig. 8", "B": "Fig. 10"}

#: Symbols of the parameter fields, for the footnote on inferred values.
PARAMETER_SYMBOLS = {"E": "E", "nu": "ν", "R": "R", "tau0": "τ0", "dgamma0": "Δγ0", "dgamma1": "Δγ1",
                     "d_max": "d_max", "v": "v"}
INFERRED_FOOTNOTE = (f"{', '.join(PARAMETER_SYMBOLS[name] for name in Parameters.INFERRED_FIELDS)} "
                     "inferred (not stated in section 4)")
#: Footnote position (figure fraction, bottom left) and size; below a constrained layout a strip
#: this high (points) is kept free for it.
FOOTNOTE_POSITION = (0.01, 0.005)
FOOTNOTE_FONTSIZE = 7
FOOTNOTE_STRIP_POINTS = 2.0 * FOOTNOTE_FONTSIZE
POINTS_PER_INCH = 72.0

#: The simulation legend below the panels: font size (points) and gap to the figure's edge (in font sizes).
LEGEND_FONTSIZE = 8
LEGEND_BORDER_PAD = 0.5
#: The most cases the simulation legend names (six rows of five): beyond, it names that many spread evenly, the
#: first and the last among them (round twenty: 3000 angles' legend of 600 rows collapsed the panels to nothing,
#: matplotlib's "constrained_layout not applied" warnings on stderr).
LEGEND_CASES = 30

#: The overlay (e.g. the discrete model) in a colour that stands out against viridis, with
#: open markers thinned to about this many per curve.
OVERLAY_STYLE = dict(color="crimson", lw=0.8, ls=(0, (4, 3)), marker="o", ms=4.5, mfc="none", mew=1.0, zorder=3)
OVERLAY_MARKERS_PER_CURVE = 30


def _preset_name(dataset: xr.Dataset) -> str | None:
    """The paper preset the dataset was computed with (``"paper-R30"``, ...), else ``None``."""
    return Parameters.from_attrs(dataset.attrs).preset_name()


def add_inferred_footnote(figure, dataset: xr.Dataset) -> float:
    """Say on ``figure`` that the preset's inferred fields are not quoted in the paper (once).

    A constrained layout is moved up to leave the footnote a strip of its own. Returns the
    height of that strip in points (0 when the dataset is not a paper preset).
    """
    if _preset_name(dataset) is None:
        return 0.0
    if not any(text.get_text() == INFERRED_FOOTNOTE for text in figure.texts):
        layout = figure.get_layout_engine()
        if isinstance(layout, ConstrainedLayoutEngine):
            strip = FOOTNOTE_STRIP_POINTS / POINTS_PER_INCH / figure.get_figheight()
            layout.set(rect=(0.0, strip, 1.0, 1.0 - strip))
        figure.text(*FOOTNOTE_POSITION, INFERRED_FOOTNOTE, ha="left", va="bottom",
                    fontsize=FOOTNOTE_FONTSIZE, color="0.35")
    return FOOTNOTE_STRIP_POINTS


def _numbered(title: str, dataset: xr.Dataset, figure_numbers: dict[str, str]) -> str:
    """``title`` prefixed by the paper's figure number for a preset's scenario A or B, else capitalised."""
    number = figure_numbers.get(dataset.attrs.get("scenario"))
    if number is not None and _preset_name(dataset) is not None:
        return f"{number}: {title}"
    return title[:1].upper() + title[1:]


def _marker_step(values: np.ndarray) -> int:
    """Every how many points a marker goes so that a curve shows about :data:`OVERLAY_MARKERS_PER_CURVE`."""
    return max(1, int(np.count_nonzero(np.isfinite(values))) // OVERLAY_MARKERS_PER_CURVE)


def _law_words(dataset: xr.Dataset) -> str:
    """``", friction law 'coulomb' (mu = 0.3)"`` for a result of another law than the paper's, else ``""``."""
    if "friction_law" not in dataset.attrs:
        return ""
    return f", friction law {dataset.attrs['friction_law']!r} (mu = {float(dataset.attrs['friction_mu']):g})"


def _label(ax, alpha, depth_mm, text):
    ax.text(alpha, depth_mm, text, ha="center", va="center", fontsize=10,
            bbox={"boxstyle": "round", "facecolor": "white", "edgecolor": "0.7", "alpha": 0.85})


def plot_phase_diagram(dataset: xr.Dataset, ax=None):
    """Draw the phase diagram of scenario A (Fig. 9a) or B (Fig. 9b) from :func:`phase_diagram` output.

    Solid: non-adhesive curves (17)/(20); dashed: adhesive curves (18)/(21);
    the ``d_max`` line, the critical angles (scenario B: the adhesive one,
    standing on the jump-off depth) and the regions ("sliding-ind",
    "no-sliding-ind", "sliding-det", "no-sliding-det"). Axes in degrees and
    millimetres.

    Parameters
    ----------
    dataset : xarray.Dataset
        Output of :func:`mdr_events.phase_diagram`.
    ax : matplotlib.axes.Axes, optional
        Where to draw; default a new figure.

    Returns
    -------
    matplotlib.axes.Axes
        Titled "Fig. 9a: ..." / "Fig. 9b: ..." only for a paper preset
        (whose figure then says which parameters are inferred), else
        "Phase diagram of slip onset, scenario ..., R = ... mm".
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 4.8), constrained_layout=True)
    scenario = dataset.attrs["scenario"]
    d_max = float(dataset["d_max"]) * _MM
    if scenario == "A":
        _draw_phase_diagram_A(ax, dataset, d_max)
    else:
        _draw_phase_diagram_B(ax, dataset, d_max)
    ax.axhline(d_max, color="tab:blue", lw=1.0, ls="--", label="$d_{max}$")
    ax.set_xlim(0, 90)
    ax.set_xticks(np.arange(0, 91, 10))
    ax.set_xlabel("path angle α (°)")
    ax.set_ylabel("indentation depth d (mm)")
    ax.set_title(_phase_diagram_title(dataset, scenario), **({"fontsize": 9} if _is_other_model(dataset) else {}))
    ax.legend(loc="upper right" if scenario == "A" else "center right", fontsize=8)
    add_inferred_footnote(ax.figure, dataset)
    return ax


#: How the phase diagram draws its curves: non-adhesive solid, adhesive dashed.
_PHASE_STYLE = {"hertz": dict(color="k", ls="-", label="non-adhesive"),
                "jkr": dict(color="tab:red", ls="--", label="adhesive")}


def _is_other_model(dataset: xr.Dataset) -> bool:
    """Another indenter or friction law than the paper's: the paper's equation numbers are the paraboloid's with
    ``τ0``, and the figure is not the paper's."""
    return "profile" in dataset.attrs or "friction_law" in dataset.attrs


def _draw_phase_diagram_A(ax, dataset: xr.Dataset, d_max: float) -> None:
    """Scenario A's curves (17), (18), its critical angles at ``d_max`` (mm) and its regions."""
    alpha = dataset["alpha"].values
    other = _is_other_model(dataset)
    for key, eq in (("hertz", "" if other else "(17)"), ("jkr", "(Heß)" if other else "(18)")):
        depths = dataset[f"d_crit_{key}"].values
        if np.all(np.isnan(depths)):  # no closed form (a friction law with Coulomb's part, adhesive)
            continue
        ax.plot(alpha, _depths_in_mm(depths), **{**_PHASE_STYLE[key],
                                                  "label": f"{_PHASE_STYLE[key]['label']} {eq}".strip()})
    top = 2.0 * d_max
    shown = [key for key in ("hertz", "jkr") if np.isfinite(float(dataset[f"critical_angle_{key}"]))]
    for key in shown:  # (an adhesive angle without closed form, nan, is not drawn)
        angle = float(dataset[f"critical_angle_{key}"])
        ax.plot([angle, angle], [0, d_max], color=_PHASE_STYLE[key]["color"], ls=":", lw=1)
        ax.plot(angle, d_max, "o", color=_PHASE_STYLE[key]["color"], ms=4)
    names = {"hertz": "Hertz", "jkr": "JKR"}
    ax.annotate(
        "\n".join(f"$\\alpha_c^{{{names[key]}}}$ = {float(dataset[f'critical_angle_{key}']):.2f}°" for key in shown),
        xy=(float(dataset["critical_angle_hertz"]), d_max), xytext=(40, 0.55 * top),
        arrowprops={"arrowstyle": "->", "color": "0.4"}, fontsize=9)
    _label(ax, 9.0, 0.85 * top, "sliding-ind")
    # right of the critical angles (another law's may lie past the paper's 23°: Coulomb's 66°)
    angles = [float(dataset[f"critical_angle_{key}"]) for key in shown]
    _label(ax, min(max([65.0] + [angle + 8.0 for angle in angles]), 84.0), 0.25 * top, "no-sliding-ind")
    ax.set_ylim(0, top)


def _depths_in_mm(depths: np.ndarray) -> np.ndarray:
    """Onset depths in mm; ``inf`` (off the plot, as "never slides") where a depth near the double range's top
    overflows in mm (round twenty: a power law near the cone, ``n = 1.0000001``, whose onset lies at ~1e306 m)."""
    with np.errstate(over="ignore"):
        return depths * _MM


def _draw_phase_diagram_B(ax, dataset: xr.Dataset, d_max: float) -> None:
    """Scenario B's curves (20), (21) on both branches, the jump-off depth, its regions and the critical angle
    standing on the jump-off depth (``d_max`` in mm)."""
    alpha = dataset["alpha"].values
    other = _is_other_model(dataset)
    branches = list(dataset["branch"].values)
    for key, eq in (("hertz", "" if other else "(20)"), ("jkr", "(Heß)" if other else "(21)")):
        if np.all(np.isnan(dataset[f"d_crit_{key}"].values)):  # no closed form (another law, adhesive)
            continue
        for i, branch in enumerate(branches):
            values = _depths_in_mm(dataset[f"d_crit_{key}"].sel(branch=branch).values)
            ax.plot(alpha, values, **{**_PHASE_STYLE[key],
                                      "label": f"{_PHASE_STYLE[key]['label']} {eq}".strip() if i == 0 else None})
    jump_off = float(dataset["jump_off_depth"]) * _MM
    ax.axhline(0.0, color="0.5", lw=0.8)
    if jump_off != 0.0:  # (without adhesion the contact ends at the surface)
        ax.axhline(jump_off, color="tab:red", lw=0.8, ls="-.", label="jump-off depth (Δγ1)")
    top = 3.0 * d_max
    _label(ax, 60.0, 0.85 * top, "no-sliding-ind")
    _label(ax, 10.0, 0.9 * top, "sliding-ind")
    _label(ax, 62.0, 0.55 * d_max, "no-sliding-det")
    _label(ax, 8.0, 0.35 * d_max, "sliding-det")
    critical_angle, kind = float(dataset["critical_angle_jkr"]), "JKR"  # the Hertz one is 90°: nothing to mark
    if not np.isfinite(critical_angle):  # another law's, without adhesion: the non-adhesive one
        critical_angle, kind = float(dataset["critical_angle_hertz"]), "Hertz"
    ax.plot([critical_angle, critical_angle], [jump_off, d_max], color=_PHASE_STYLE["jkr"]["color"], ls=":", lw=1)
    ax.plot(critical_angle, jump_off, "o", color=_PHASE_STYLE["jkr"]["color"], ms=4)
    annotation_position = (75.0, 0.5 * d_max)  # free space right of "no-sliding-det"
    ax.annotate(f"$\\alpha_c^{{{kind}}}$ = {critical_angle:.2f}°", xy=(critical_angle, jump_off),
                xytext=annotation_position, arrowprops={"arrowstyle": "->", "color": "0.4"}, fontsize=9)
    ax.set_ylim(min(2.0 * jump_off, -0.1 * d_max), top)


def _phase_diagram_title(dataset: xr.Dataset, scenario: str) -> str:
    """The phase diagram's title: the paper's figure number only for a paper preset's own model."""
    R_mm = dataset.attrs.get("param_R", np.nan) * _MM  # (another indenter's result may have no R)
    if _is_other_model(dataset):  # not the paper's figure
        subject = dataset.attrs.get("profile", f"R = {R_mm:g} mm")
        return f"{PHASE_DIAGRAM_CONTENT}, scenario {scenario},\n{subject}{_law_words(dataset)}"
    return _numbered(f"{PHASE_DIAGRAM_CONTENT}, scenario {scenario}, R = {R_mm:g} mm", dataset, PHASE_DIAGRAM_FIGURES)


#: Resolution of the PNG files (dots per inch).
PNG_DPI = 120


def figure_png(figure) -> bytes:
    """The figure as PNG bytes, reproducibly (no software or time stamp), then close it.

    Parameters
    ----------
    figure : matplotlib.figure.Figure

    Returns
    -------
    bytes
        The same bytes for the same figure on the same machine.
    """
    buffer = io.BytesIO()
    try:
        figure.savefig(buffer, format="png", dpi=PNG_DPI, metadata={"Software": None})
    finally:
        plt.close(figure)
    return buffer.getvalue()


def save_figure(figure, path: str | os.PathLike) -> Path:
    """Save a figure as PNG (:func:`figure_png`) atomically, then close it."""
    data = figure_png(figure)
    return atomic_write(path, lambda temporary: Path(temporary).write_bytes(data), suffix=".png")


#: Panels of Fig. 8 / Fig. 10: variable, scale to display units, axis label.
SIMULATION_PANELS = (
    ("normal_force", 1e3, "$F_N$ (mN)"),
    ("tangential_force", 1e3, "$F_x$ (mN)"),
    ("contact_area", 1e6, "$A$ (mm²)"),
    ("mean_pressure", 1e-3, "$\\langle p \\rangle$ (kPa)"),
    ("mean_shear_stress", 1e-3, "$\\tau$ (kPa)"),
)


def plot_simulation(dataset: xr.Dataset, overlay: xr.Dataset | None = None, title: str | None = None):
    """Panels a–e of a simulation against time, one line per case (Fig. 8 for A, Fig. 10 for B).

    The lines are labelled by their angle (``α = 20°``) or, for custom paths, by the case's label.

    Parameters
    ----------
    dataset : xarray.Dataset
        Output of :func:`mdr_events.simulate`.
    overlay : xarray.Dataset, optional
        Another simulation (e.g. the discrete model for one angle), drawn on
        top in crimson, dashed, with open markers (about
        :data:`OVERLAY_MARKERS_PER_CURVE` per curve) and its own legend entry.
    title : str, optional
        Default: "Fig. 8: ..." / "Fig. 10: ..." only for scenario A / B of a
        paper preset, else "Simulation, scenario ..." (or "custom paths"),
        with the radius and the method.

    Returns
    -------
    matplotlib.figure.Figure
        For a paper preset, with a footnote naming the inferred parameters.
    """
    figure, axes = plt.subplots(5, 1, figsize=(7.0, 12.0), sharex=True, constrained_layout=True)
    dimension = case_dimension(dataset)
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, dataset.sizes[dimension]))
    time = dataset["time"].values
    cases = dataset.sizes[dimension]
    named = set(np.linspace(0, cases - 1, min(cases, LEGEND_CASES)).round().astype(int).tolist())
    for letter, ax, (name, scale, label) in zip("abcde", axes, SIMULATION_PANELS):
        for index, (colour, case) in enumerate(zip(colours, dataset[dimension].values)):
            values = dataset[name].sel({dimension: case}).values * scale
            ax.plot(time, values, color=colour, lw=1.4,
                    label=case_text(dimension, case) if index in named else "_nolegend_")
        if overlay is not None:
            overlay_dimension = case_dimension(overlay)
            for case in overlay[overlay_dimension].values:
                text = f"{overlay.attrs.get('method', 'overlay')}, {case_text(overlay_dimension, case)}"
                if "dx" in overlay.attrs:
                    text += f", Δx = {overlay.attrs['dx'] * 1e6:g} µm"
                values = overlay[name].sel({overlay_dimension: case}).values * scale
                ax.plot(overlay["time"].values, values, markevery=_marker_step(values), label=text,
                        **OVERLAY_STYLE)
        ax.set_ylabel(label)
        ax.text(0.01, 0.92, f"({letter})", transform=ax.transAxes, fontsize=10, va="top")
        ax.grid(alpha=0.3)
    footnote_strip = add_inferred_footnote(figure, dataset)
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncol=5, fontsize=LEGEND_FONTSIZE,
                  borderaxespad=LEGEND_BORDER_PAD + footnote_strip / LEGEND_FONTSIZE)  # above the footnote
    axes[-1].set_xlabel("time t (s)")
    if title is None:
        scenario = dataset.attrs.get("scenario", "")
        path = ("custom path" if dataset.sizes[dimension] == 1 else "custom paths") if scenario == "custom" \
            else f"scenario {scenario}"
        law = _law_words(dataset)
        if "profile" in dataset.attrs or law:  # another indenter or law than the paper's: not the paper's figure
            subject = dataset.attrs["profile"] if "profile" in dataset.attrs else \
                f"R = {dataset.attrs['param_R'] * _MM:g} mm"  # (another indenter's result may have no R)
            title = f"Simulation, {path}, {subject}{law}, {dataset.attrs.get('method', '')}"
        else:
            title = _numbered(f"simulation, {path}, R = {dataset.attrs['param_R'] * _MM:g} mm, "
                              f"{dataset.attrs.get('method', '')}", dataset, SIMULATION_FIGURES)
    figure.suptitle(title)
    return figure


#: Fretting loops: the simulation as lines, an overlay (e.g. the discrete model) as open markers only (about
#: :data:`FRETTING_MARKERS_PER_CURVE` per curve: a loop has several legs), the closed form dashed.
FRETTING_LINE_STYLE = dict(color="tab:blue", lw=1.3, zorder=2)
FRETTING_OVERLAY_STYLE = dict(color="crimson", ls="none", marker="o", ms=3.5, mfc="none", mew=0.8, zorder=3)
FRETTING_CLOSED_FORM_STYLE = dict(color="k", ls="--", lw=1.0, zorder=4)
FRETTING_MARKERS_PER_CURVE = 150
#: Label of the closed-form loop of the fixed contact.
FRETTING_CLOSED_FORM_LABEL = "fixed contact, closed form: ±π a² τ0, slope 2G* a"


def plot_fretting(dataset: xr.Dataset, overlay: xr.Dataset | None = None, title: str | None = None):
    """The tangential force against the tangential displacement, one panel per case (fretting loops).

    Parameters
    ----------
    dataset : xarray.Dataset
        Output of :func:`mdr_events.simulate` (any method, usually the continuum), drawn as lines. If it holds
        ``parallelogram_x`` and ``parallelogram_force`` (dims ``(case dimension, "corner")``: the corners of the
        closed-form loop of each case, as the fretting study of ``mdr-events reproduce`` writes them), these
        are drawn dashed; with ``fretting_centre`` and ``fretting_amplitude`` the panel titles state them.
    overlay : xarray.Dataset, optional
        Another simulation of the same cases (e.g. the discrete model), drawn as open crimson markers, about
        :data:`FRETTING_MARKERS_PER_CURVE` per case.
    title : str, optional
        Default: the dataset's ``study`` attribute (else "simulation"), "F_x against x", the radius and method.

    Returns
    -------
    matplotlib.figure.Figure
        x in mm, F_x in N; for a paper preset, with a footnote naming the inferred parameters.
    """
    dimension = case_dimension(dataset)
    cases = dataset[dimension].values
    figure, axes = plt.subplots(1, len(cases), figsize=(5.2 * len(cases), 5.0), sharey=True, squeeze=False,
                                constrained_layout=True)
    method = dataset.attrs.get("method", "simulation")
    for ax, case in zip(axes[0], cases):
        selected = dataset.sel({dimension: case})
        ax.plot(selected["tangential_displacement"].values * _MM, selected["tangential_force"].values,
                label=method, **FRETTING_LINE_STYLE)
        if overlay is not None:
            other = overlay.sel({case_dimension(overlay): case})
            force = other["tangential_force"].values
            text = overlay.attrs.get("method", "overlay")
            if "dx" in overlay.attrs:
                text += f", Δx = {overlay.attrs['dx'] * 1e6:g} µm"
            ax.plot(other["tangential_displacement"].values * _MM, force, label=text,
                    markevery=max(1, int(np.count_nonzero(np.isfinite(force))) // FRETTING_MARKERS_PER_CURVE),
                    **FRETTING_OVERLAY_STYLE)
        if "parallelogram_x" in dataset:
            ax.plot(selected["parallelogram_x"].values * _MM, selected["parallelogram_force"].values,
                    label=FRETTING_CLOSED_FORM_LABEL, **FRETTING_CLOSED_FORM_STYLE)
        panel = case_text(dimension, case)
        if "fretting_centre" in dataset and "fretting_amplitude" in dataset:
            panel += (f": $x_c$ = {float(selected['fretting_centre']) * _MM:.3f} mm, "
                      f"X = {float(selected['fretting_amplitude']) * _MM:.3f} mm")
        ax.set_title(panel, fontsize=10)
        ax.set_xlabel("tangential displacement x (mm)")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.grid(alpha=0.3)
    axes[0, 0].set_ylabel("tangential force $F_x$ (N)")
    footnote_strip = add_inferred_footnote(figure, dataset)
    handles, labels = axes[0, 0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncol=3, fontsize=LEGEND_FONTSIZE,
                  borderaxespad=LEGEND_BORDER_PAD + footnote_strip / LEGEND_FONTSIZE)
    if title is None:
        study = dataset.attrs.get("study", "simulation")
        title = (f"{study[:1].upper()}{study[1:]}: $F_x$ against x, R = {dataset.attrs['param_R'] * _MM:g} mm, "
                 f"{method}")
    figure.suptitle(title)
    return figure
