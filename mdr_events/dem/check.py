"""A LAMMPS granular model checked against the exact MDR: :func:`lammps_check` runs LAMMPS along the one path and
referees the run with :func:`~mdr_events.validate`.

The reference is the exact continuum of the same contact: LAMMPS's models use Coulomb's law alone (``μ``), which
the continuum solves with and without adhesion (its tensile springs hold no Coulomb shift).
"""

from __future__ import annotations

import xarray as xr

from mdr_events.theory.job import rate_independent
from mdr_events.analysis.validate import (BYTES_PER_VALIDATED_SAMPLE, DEFAULT_TOLERANCE, one_path, one_path_job,
                                          validate)
from mdr_events.contact import Contact
from mdr_events.dem.mapping import LammpsModel, check_model
from mdr_events.dem.runner import BYTES_PER_RUN_SAMPLE, check_run_limits, run_lammps
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.models.motion import Paths
from mdr_events.models.paths import Path
from mdr_events.validation import shown

__all__ = ["lammps_check"]

def lammps_check(contact: Contact, motion, alpha: float | None = None, *, model: LammpsModel = LammpsModel(),
                 steps: int | None = None, dt: float | None = None, tolerance: float = DEFAULT_TOLERANCE,
                 limits: Limits = DEFAULT_LIMITS) -> tuple[xr.Dataset, xr.Dataset]:
    """Run LAMMPS's ``model`` for ``contact`` along the one path of ``motion`` and validate the run against the exact
    continuum.

    Parameters
    ----------
    contact : Contact
        The contact (a paraboloid; Coulomb's law with a tangential model, no friction without):
        :func:`~mdr_events.dem.mapping.wall_coefficients` gives LAMMPS's numbers.
    motion : Scenario, Paths, Path or {"A", "B", "B+"}
        One path: a Scenario of one angle, Paths of one path, a Path, or a scenario's name with ``alpha``.
    alpha : float, optional
        With a scenario's name: its angle in degrees.
    model : LammpsModel
        LAMMPS's normal and tangential models by name (:data:`~mdr_events.dem.mapping.NORMAL_MODELS`,
        :data:`~mdr_events.dem.mapping.TANGENTIAL_MODELS`); default Hertz without friction.
    steps, dt : optional
        LAMMPS's number of steps or time step (default 10⁴ steps).
    tolerance : float
        The verdict's bound (:func:`~mdr_events.validate`).
    limits : Limits
        What the LAMMPS run (:func:`~mdr_events.dem.runner.run_lammps`: its steps, checked before it starts) and the
        continuum run (:func:`~mdr_events.validate`) may use.

    Returns
    -------
    (xarray.Dataset, xarray.Dataset)
        The LAMMPS run (:func:`~mdr_events.dem.runner.run_lammps`) and the validation report, which also carries the
        run's ``lammps_*`` attributes (the input deck among them).
    """
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a Contact")
    check_model(model)
    if isinstance(motion, Path):
        motion, alpha = Paths({"path": motion}), None
    # (LAMMPS's granular models hold a work of adhesion that does not depend on the edge's speed)
    rate_independent(contact, "the LAMMPS check (its granular models are rate independent)")
    path, _ = one_path(one_path_job(contact, motion, alpha, {}, caller="the LAMMPS check"))
    # (the run's own limits first, then its samples validated beside it: counted before LAMMPS runs, not refused by
    # validate after it)
    limits = check_limits(limits)
    count = check_run_limits(path, steps, dt, limits)[0] + 1
    limits.check(f"validating the LAMMPS run's {count} samples",
                 memory=count * (BYTES_PER_VALIDATED_SAMPLE + BYTES_PER_RUN_SAMPLE))
    run = run_lammps(contact, path, model.normal, model.tangential, steps=steps, dt=dt, limits=limits)
    report = validate(run, contact, motion, alpha, tolerance=tolerance, limits=limits, time_origin="path_start")
    report.attrs.update({key: value for key, value in run.attrs.items() if key.startswith("lammps_")})
    return run, report

