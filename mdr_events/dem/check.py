"""A LAMMPS granular model checked against the exact MDR: :func:`lammps_check` runs LAMMPS along the one path and
referees the run with :func:`~mdr_events.validate`.

The reference is the exact continuum of the same contact. One case it cannot solve yet: Coulomb friction with
adhesion (the continuum refuses it, issue 26). There the normal force is still checked, since the MDR's normal
problem does not depend on friction (the springs' normal and tangential stiffness are uncoupled, (5), (6)), and
the tangential force is named as not compared (it stays in the report's ``unused_columns`` as
``lammps_tangential_force``).
"""

from __future__ import annotations

import dataclasses

import xarray as xr

from mdr_events.analysis.validate import DEFAULT_TOLERANCE, one_path, one_path_job, validate
from mdr_events.contact import Contact
from mdr_events.contact.friction import FrictionLaw
from mdr_events.dem.mapping import LammpsModel
from mdr_events.dem.runner import run_lammps
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.models.motion import Paths
from mdr_events.models.paths import Path
from mdr_events.validation import shown

__all__ = ["lammps_check", "comparable", "TANGENTIAL_NOT_COMPARED"]

#: Why the tangential force of a run with adhesion and Coulomb friction is not compared.
TANGENTIAL_NOT_COMPARED = ("tangential_force not compared: the exact continuum of Coulomb friction with adhesion is "
                           "not solved yet (issue 26); the normal force is, the MDR's normal problem being the same "
                           "without friction")


def comparable(run: xr.Dataset, contact: Contact) -> tuple[xr.Dataset, Contact, str]:
    """The run and the contact :func:`~mdr_events.validate` can compare, and a note on what is left out (``""``:
    nothing): with adhesion and Coulomb friction, the run without its tangential force and the contact without
    friction."""
    if contact.adhesion.is_adhesive and contact.friction.uses_mu:
        renamed = run.rename({"tangential_force": "lammps_tangential_force"})
        return renamed, dataclasses.replace(contact, friction=FrictionLaw("tau0", tau0=0.0)), TANGENTIAL_NOT_COMPARED
    return run, contact, ""


def lammps_check(contact: Contact, motion, alpha: float | None = None, *, normal: str = "hertz/material",
                 tangential: str = "none", steps: int | None = None, dt: float | None = None,
                 tolerance: float = DEFAULT_TOLERANCE, limits: Limits = DEFAULT_LIMITS
                 ) -> tuple[xr.Dataset, xr.Dataset]:
    """Run LAMMPS's ``normal`` + ``tangential`` model for ``contact`` along the one path of ``motion`` and validate
    the run against the exact continuum.

    Parameters
    ----------
    contact : Contact
        The contact (a paraboloid; Coulomb's law with a tangential model, no friction without):
        :func:`~mdr_events.dem.mapping.wall_coefficients` gives LAMMPS's numbers.
    motion : Scenario, Paths, Path or {"A", "B", "B+"}
        One path: a Scenario of one angle, Paths of one path, a Path, or a scenario's name with ``alpha``.
    normal, tangential : str
        LAMMPS's models (:data:`~mdr_events.dem.mapping.NORMAL_MODELS`,
        :data:`~mdr_events.dem.mapping.TANGENTIAL_MODELS`).
    steps, dt : optional
        LAMMPS's number of steps or time step (default 10⁴ steps).
    tolerance : float
        The verdict's bound (:func:`~mdr_events.validate`).

    Returns
    -------
    (xarray.Dataset, xarray.Dataset)
        The LAMMPS run (:func:`~mdr_events.dem.runner.run_lammps`) and the validation report, which also carries the
        run's ``lammps_*`` attributes (the input deck among them) and ``lammps_not_compared``.
    """
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a Contact")
    LammpsModel(normal, tangential)  # (a bad name is named before anything else is checked)
    if isinstance(motion, Path):
        motion, alpha = Paths({"path": motion}), None
    path, _ = one_path(one_path_job(contact, motion, alpha, {}))
    run = run_lammps(contact, path, normal, tangential, steps=steps, dt=dt)
    candidate, reference, note = comparable(run, contact)
    report = validate(candidate, reference, motion, alpha, tolerance=tolerance, limits=limits,
                      time_origin="path_start")
    report.attrs.update({key: value for key, value in run.attrs.items() if key.startswith("lammps_")})
    report.attrs["lammps_not_compared"] = note or "none"
    return run, report

