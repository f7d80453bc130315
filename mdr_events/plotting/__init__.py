"""Figures drawn from the datasets (never recomputed here): Fig. 8, 9a, 9b, 10, fretting loops, and the
convergence of a simulator under validation."""

from mdr_events.plotting.convergence import plot_convergence_study
from mdr_events.plotting.fit import plot_fit
from mdr_events.plotting.universal import plot_universal_map
from mdr_events.plotting.profiles import plot_profile_comparison
from mdr_events.plotting.figures import figure_png, plot_fretting, plot_phase_diagram, plot_simulation, save_figure
from mdr_events.plotting.validation import plot_validation

__all__ = ["figure_png", "plot_convergence_study", "plot_fit", "plot_fretting", "plot_phase_diagram",
           "plot_profile_comparison", "plot_simulation", "plot_universal_map", "plot_validation", "save_figure"]
