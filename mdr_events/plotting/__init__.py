"""Figures drawn from the datasets (never recomputed here): Fig. 8, 9a, 9b, 10, and fretting loops."""

from mdr_events.plotting.figures import figure_png, plot_fretting, plot_phase_diagram, plot_simulation, save_figure

__all__ = ["figure_png", "plot_fretting", "plot_phase_diagram", "plot_simulation", "save_figure"]
