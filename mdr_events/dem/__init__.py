"""Discrete-element codes checked against the exact MDR: LAMMPS's granular wall models run along a path
(:func:`run_lammps`), the parameter mapping (:mod:`mdr_events.dem.mapping`), the input deck
(:mod:`mdr_events.dem.deck`) and the check against the continuum (:func:`lammps_check`)."""

from mdr_events.dem.check import lammps_check
from mdr_events.dem.mapping import NORMAL_MODELS, TANGENTIAL_MODELS, LammpsModel, wall_coefficients
from mdr_events.dem.runner import EXTRA, LammpsError, LammpsUnavailable, load_lammps, run_lammps

__all__ = ["NORMAL_MODELS", "TANGENTIAL_MODELS", "LammpsModel", "wall_coefficients", "EXTRA", "LammpsError",
           "LammpsUnavailable", "load_lammps", "run_lammps", "lammps_check"]
