"""Figures (issue 10): titles by content, the discrete overlay, Fig. 9b's critical angle, the footnote on
inferred parameters, the fretting loops, and a matplotlib backend left alone on import."""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from matplotlib.colors import to_hex

import mdr_events as me
from mdr_events.parameters import Parameters
from mdr_events.reproduction.fretting import fretting_study
from mdr_events.plotting import plot_fretting
from mdr_events.plotting.figures import (FRETTING_CLOSED_FORM_LABEL, FRETTING_MARKERS_PER_CURVE, INFERRED_FOOTNOTE,
                                         OVERLAY_MARKERS_PER_CURVE, plot_phase_diagram, plot_simulation)

#: A coarse angle grid: the phase diagrams are fast to compute on it.
ANGLES = np.linspace(0.0, 90.0, 91)
#: The user's own parameters: one field away from the paper preset.
OWN = Parameters.paper().replace(tau0=30e3)
OVERLAY_ANGLE = 20.0
REPOSITORY = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def continuum_paper():
    return me.simulate(Parameters.paper(), "A", alpha=[OVERLAY_ANGLE], method="continuum", samples=101)


@pytest.fixture(scope="module")
def continuum_own():
    return me.simulate(OWN, "A", alpha=[OVERLAY_ANGLE], method="continuum", samples=101)


@pytest.fixture(scope="module")
def discrete_paper():
    return me.simulate(Parameters.paper(), "A", alpha=[OVERLAY_ANGLE], dx=4e-6, n_steps=2000)


def _figure_texts(figure) -> list[str]:
    return [text.get_text() for text in figure.texts]


# ----------------------------------------------------------------------------------------------
# titles by content


@pytest.mark.parametrize("scenario, number", [("A", "Fig. 9a"), ("B", "Fig. 9b")])
@pytest.mark.parametrize("radius", [0.03, 0.1])
def test_phase_diagram_of_a_preset_carries_the_paper_figure_number(scenario, number, radius):
    ax = plot_phase_diagram(me.phase_diagram(Parameters.paper(R=radius), alpha=ANGLES, scenario=scenario))
    assert ax.get_title().startswith(f"{number}: ")
    assert f"R = {radius * 1e3:g} mm" in ax.get_title()


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_phase_diagram_of_own_parameters_is_titled_by_content(scenario):
    title = plot_phase_diagram(me.phase_diagram(OWN, alpha=ANGLES, scenario=scenario)).get_title()
    assert "Fig." not in title
    assert title == f"Phase diagram of slip onset, scenario {scenario}, R = 30 mm"


def test_simulation_of_a_preset_carries_the_paper_figure_number(continuum_paper):
    title = plot_simulation(continuum_paper).get_suptitle()
    assert title == "Fig. 8: simulation, scenario A, R = 30 mm, continuum"


def test_simulation_of_own_parameters_is_titled_by_content(continuum_own, discrete_paper):
    title = plot_simulation(continuum_own, overlay=discrete_paper).get_suptitle()
    assert "Fig." not in title
    assert title == "Simulation, scenario A, R = 30 mm, continuum"


@pytest.mark.parametrize("scenario, content", [
    ("B+", "scenario B+"),
    (me.Path.scenario_A(OVERLAY_ANGLE, Parameters.paper()), "custom path"),
])
def test_simulation_of_a_preset_off_the_paper_scenarios_has_no_figure_number(scenario, content):
    alpha = None if isinstance(scenario, me.Path) else [OVERLAY_ANGLE]
    dataset = me.simulate(Parameters.paper(), scenario, alpha=alpha, method="continuum", samples=101)
    title = plot_simulation(dataset).get_suptitle()
    assert "Fig." not in title
    assert title == f"Simulation, {content}, R = 30 mm, continuum"


def test_simulation_of_custom_paths_labels_its_lines_by_the_case_labels():
    params = Parameters.paper()
    paths = {"straight in": me.Path([(0.0, 0.0), (0.0, params.d_max), (2e-4, -1e-4)], params.v),
             "at an angle, fast": me.Path([(0.0, 0.0), (1e-4, params.d_max), (1e-4, -1e-4)], 2 * params.v)}
    dataset = me.simulate(params, paths, method="continuum", samples=101)
    figure = plot_simulation(dataset, overlay=me.simulate(params, paths, dx=4e-6, n_steps=1000))
    for ax in figure.axes:
        assert [line.get_label() for line in ax.lines] == [*paths, *(f"discrete, {label}, Δx = 4 µm" for label in paths)]
    assert figure.get_suptitle() == "Simulation, custom paths, R = 30 mm, continuum"


# ----------------------------------------------------------------------------------------------
# the discrete overlay


def test_overlay_is_drawn_with_thinned_markers_in_a_contrasting_colour(continuum_paper, discrete_paper):
    figure = plot_simulation(continuum_paper, overlay=discrete_paper)
    panels = figure.axes
    assert len(panels) == 5
    for ax in panels:
        continuum_line, overlay_line = ax.lines  # one angle each
        assert overlay_line.get_label().startswith("discrete, α = 20°")
        assert overlay_line.get_marker() not in (None, "", "None", " ")
        step = overlay_line.get_markevery()
        assert isinstance(step, int) and step > 1
        points = np.count_nonzero(np.isfinite(overlay_line.get_ydata()))
        assert OVERLAY_MARKERS_PER_CURVE <= points // step + 1 <= 2 * OVERLAY_MARKERS_PER_CURVE
        assert to_hex(overlay_line.get_color()) != to_hex(continuum_line.get_color())
    legend_labels = [text.get_text() for text in figure.legends[0].get_texts()]
    assert any(label.startswith("discrete, α = 20°") for label in legend_labels)


def test_simulation_figure_with_overlay_is_deterministic(continuum_paper, discrete_paper, tmp_path):
    from mdr_events.plotting.figures import save_figure

    paths = [save_figure(plot_simulation(continuum_paper, overlay=discrete_paper), tmp_path / name)
             for name in ("one.png", "two.png")]
    assert paths[0].read_bytes() == paths[1].read_bytes()


# ----------------------------------------------------------------------------------------------
# fretting loops: F_x against x


@pytest.fixture(scope="module")
def fretting():
    """The fretting study of `mdr-events reproduce` at fast settings (Δx = 4 µm)."""
    return fretting_study(Parameters.paper(), samples=101, dx=4e-6, n_steps=2000)


def test_fretting_figure_draws_each_case_from_the_dataset(fretting):
    """One panel per case: the continuum as a line, the discrete model as thinned markers, the dataset's
    closed-form parallelogram dashed; x in mm, F_x in N, all taken from the datasets as they are."""
    continuum, discrete = fretting.continuum, fretting.discrete
    figure = plot_fretting(continuum, overlay=discrete)
    assert figure.get_suptitle() == "Fretting: $F_x$ against x, R = 30 mm, continuum"
    assert len(figure.axes) == 2
    for ax, case in zip(figure.axes, ["vertical", "oblique 20°"]):
        assert ax.get_title().startswith(f"{case}: $x_c$ = ")
        line, markers, closed_form = ax.lines[:3]
        assert [line.get_label(), markers.get_label(), closed_form.get_label()] == \
            ["continuum", "discrete, Δx = 4 µm", FRETTING_CLOSED_FORM_LABEL]
        selected = continuum.sel(case=case)
        np.testing.assert_array_equal(line.get_xdata(), selected["tangential_displacement"].values * 1e3)
        np.testing.assert_array_equal(line.get_ydata(), selected["tangential_force"].values)
        np.testing.assert_array_equal(markers.get_ydata(), discrete.sel(case=case)["tangential_force"].values)
        assert markers.get_linestyle() == "None" and markers.get_marker() == "o"
        step = markers.get_markevery()
        assert isinstance(step, int) and step > 1
        assert FRETTING_MARKERS_PER_CURVE <= discrete.sizes["time"] // step + 1 <= 2 * FRETTING_MARKERS_PER_CURVE
        np.testing.assert_array_equal(closed_form.get_xdata(), selected["parallelogram_x"].values * 1e3)
        np.testing.assert_array_equal(closed_form.get_ydata(), selected["parallelogram_force"].values)
        assert closed_form.get_linestyle() == "--"
    assert INFERRED_FOOTNOTE in _figure_texts(figure)


def test_fretting_figure_is_not_recomputed(fretting):
    """A changed dataset changes the figure: the closed form is the dataset's, not computed again."""
    edited = fretting.continuum.copy(deep=True)
    edited["parallelogram_force"].values *= 2.0
    closed_form, = (line for line in plot_fretting(edited).axes[0].lines
                    if line.get_label() == FRETTING_CLOSED_FORM_LABEL)
    np.testing.assert_array_equal(closed_form.get_ydata(), edited["parallelogram_force"].values[0])


def test_fretting_figure_of_a_plain_simulation_has_no_closed_form():
    params = Parameters.paper()
    path = me.Path([(0.0, 0.0), (0.0, params.d_max), (1e-3, params.d_max), (-1e-3, params.d_max)], params.v)
    figure = plot_fretting(me.simulate(params, {"back and forth": path}, method="continuum", samples=51))
    ax, = figure.axes
    assert [line.get_label() for line in ax.lines if not line.get_label().startswith("_")] == ["continuum"]
    assert ax.get_title() == "back and forth"
    assert figure.get_suptitle() == "Simulation: $F_x$ against x, R = 30 mm, continuum"


# ----------------------------------------------------------------------------------------------
# Fig. 9b: scenario B's critical angle


@pytest.mark.parametrize("params", [Parameters.paper(), Parameters.paper(R=0.1), OWN], ids=["R30", "R100", "own"])
def test_phase_diagram_B_marks_the_adhesive_critical_angle(params):
    dataset = me.phase_diagram(params, alpha=ANGLES, scenario="B")
    angle = float(dataset["critical_angle_jkr"])
    jump_off_mm = float(dataset["jump_off_depth"]) * 1e3
    ax = plot_phase_diagram(dataset)
    vertical = [line for line in ax.lines
                if len(line.get_xdata()) == 2 and np.allclose(line.get_xdata(), angle)]
    assert len(vertical) == 1
    assert vertical[0].get_linestyle() == ":"
    assert min(vertical[0].get_ydata()) == pytest.approx(jump_off_mm)
    assert any(f"{angle:.2f}°" in text.get_text() for text in ax.texts)


# ----------------------------------------------------------------------------------------------
# the footnote on inferred parameters


def test_footnote_names_the_inferred_fields():
    assert INFERRED_FOOTNOTE.startswith("E, ν, v inferred")
    assert len(Parameters.INFERRED_FIELDS) == INFERRED_FOOTNOTE.split(" inferred")[0].count(",") + 1


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("params, expected", [(Parameters.paper(), True), (Parameters.paper(R=0.1), True),
                                              (OWN, False)], ids=["R30", "R100", "own"])
def test_phase_diagram_footnote_only_for_presets(params, expected, scenario):
    figure = plot_phase_diagram(me.phase_diagram(params, alpha=ANGLES, scenario=scenario)).figure
    assert (INFERRED_FOOTNOTE in _figure_texts(figure)) is expected


def test_simulation_footnote_only_for_presets(continuum_paper, continuum_own, discrete_paper):
    assert INFERRED_FOOTNOTE in _figure_texts(plot_simulation(continuum_paper, overlay=discrete_paper))
    assert INFERRED_FOOTNOTE not in _figure_texts(plot_simulation(continuum_own, overlay=discrete_paper))


def test_footnote_stays_clear_of_the_simulation_legend(continuum_paper, discrete_paper):
    figure = plot_simulation(continuum_paper, overlay=discrete_paper)
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    footnote, = (text for text in figure.texts if text.get_text() == INFERRED_FOOTNOTE)
    legend_box = figure.legends[0].get_window_extent(renderer)
    assert footnote.get_window_extent(renderer).y1 <= legend_box.y0


# ----------------------------------------------------------------------------------------------
# the matplotlib backend


def _backend_in_fresh_interpreter(code: str) -> str:
    """Run ``code`` in a new interpreter without ``MPLBACKEND``; return the last line it prints."""
    environment = {name: value for name, value in os.environ.items() if name != "MPLBACKEND"}
    result = subprocess.run([sys.executable, "-c", code], env=environment, cwd=REPOSITORY,
                            capture_output=True, text=True, check=True)
    return result.stdout.strip().splitlines()[-1]


@pytest.mark.parametrize("user_choice", [None, "svg"], ids=["default", "chosen"])
def test_importing_plotting_leaves_the_backend_alone(user_choice):
    # "svg" stands for a backend the user chose (e.g. Jupyter's inline one) and works headless.
    choose = "" if user_choice is None else f"matplotlib.use({user_choice!r}); "
    without = _backend_in_fresh_interpreter(f"import matplotlib; {choose}print(matplotlib.get_backend())")
    with_import = _backend_in_fresh_interpreter(
        f"import matplotlib; {choose}import mdr_events.plotting; print(matplotlib.get_backend())")
    assert with_import == without
    if user_choice is not None:
        assert with_import == user_choice


def test_profile_comparison_draws_each_indenter_with_its_exponent():
    """Three panels, a line per indenter (labelled with n, from the dataset's profile attribute) and the discrete
    model's markers in the same colour."""
    from mdr_events.reproduction.profiles import matching_power_law
    from mdr_events.plotting import plot_profile_comparison

    params = Parameters.paper()
    profiles = {"cone": matching_power_law(1.0, params), "quartic": matching_power_law(4.0, params)}
    continuum = {name: me.simulate(params, "A", alpha=[20.0], method="continuum", samples=101, profile=profile)
                 for name, profile in profiles.items()}
    discrete = {"cone": me.simulate(params, "A", alpha=[20.0], dx=4e-6, n_steps=1000, profile=profiles["cone"])}
    figure = plot_profile_comparison(continuum, discrete)
    axes = figure.axes
    assert len(axes) == 3
    labels = [line.get_label() for line in axes[0].get_lines()]
    assert labels == ["cone (n = 1), continuum", "cone, discrete (Δx = 4 µm)", "quartic (n = 4), continuum"]
    lines = axes[0].get_lines()
    assert to_hex(lines[0].get_color()) == to_hex(lines[1].get_markeredgecolor()) and lines[1].get_linestyle() == "None"
    assert "scenario A at 20°" in figure._suptitle.get_text()
