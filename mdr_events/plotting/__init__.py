"""Figures drawn from the datasets (never recomputed here): Fig. 8, 9a, 9b, 10."""

from mdr_events.plotting.figures import figure_png, plot_phase_diagram, plot_simulation, save_figure

__all__ = ["figure_png", "plot_phase_diagram", "plot_simulation", "save_figure"]
