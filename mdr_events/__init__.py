"""mdr_events: adhesive indentation and detachment at an angle with the MDR.

Reproduces and extends section 4 of Lyashenko, Popov & Borysiuk,
Biomimetics 2023, 8(6), 477 (doi:10.3390/biomimetics8060477): a rigid
paraboloid pressed into and pulled off an elastomer along a straight path at
an angle, with Heß's adhesion rule (two works of adhesion) and a
spring-slip criterion.

Layers, bottom to top (a module imports only from its own layer or those
below; ``tests/test_layers.py`` checks it): ``parameters``, ``validation`` and ``limits`` → ``contact`` (the
physical model as data: ``Contact`` of an ``Elastomer``, an indenter, ``Adhesion`` and a ``FrictionLaw``) → ``io`` (``datasets``: stamp, result schemas, comparison; ``files``: netCDF
in and out) → ``theory`` (``symbolic`` SymPy derivations, ``analytic`` closed
forms, ``power_law`` those of other indenters, ``tabulated`` a table's, ``mindlin`` tangential loading at a constant depth, ``phase``
diagrams) → ``models`` (``paths``, ``discrete`` springs,
``continuum`` event-driven and exact, ``simulate``) → ``analysis``
(``crosscheck``, ``convergence``, ``validate``, ``fit``, ``sweep``) → ``plotting`` → ``app`` (``cli``,
``study``, ``result_files``; beside it ``reproduction``, the sections of ``results/``).
"""

from mdr_events._version import __version__
from mdr_events.parameters import Parameters
from mdr_events.contact import (Adhesion, Contact, Elastomer, FRICTION_LAWS, FlatPunch, FrictionLaw, Paraboloid,
                                PowerLaw, TabulatedProfile)
from mdr_events.limits import Limits, ResourceLimitError
from mdr_events.io.datasets import DOI
from mdr_events.io.files import open_result, write_netcdf
from mdr_events.theory import analytic, mindlin, power_law, symbolic, tabulated
from mdr_events.theory.analytic import (
    critical_angle,
    critical_shift,
    d_crit,
    fretting_dissipated_energy,
    jkr_contact_radius,
    jkr_depth,
    jkr_normal_force,
    jump_off,
    pull_off_force,
)
from mdr_events.models import continuum
from mdr_events.models.continuum import Tolerances
from mdr_events.models.paths import Path
from mdr_events.models.motion import Paths, Scenario
from mdr_events.models.methods import Continuum, Discrete
# The three modules that make results register their schemas when imported, so that open_result
# knows every kind of result whatever a user imports (any import of mdr_events.* runs this file first).
from mdr_events.theory.phase import phase_diagram
from mdr_events.models.simulate import simulate
from mdr_events.analysis.crosscheck import cross_check
from mdr_events.analysis.validate import validate
from mdr_events.analysis.reports import ConvergenceReport, ConvergenceVerdict, ValidationReport, Verdict
from mdr_events.analysis.convergence_study import convergence_study
from mdr_events.analysis.fit import FitResult, fit
from mdr_events.analysis.sweep import Engine, SweepOutput, sweep
from mdr_events import plotting  # noqa: F401 - registers the figures of the result objects (FitResult.plot)
from mdr_events.app.study import load_study, run_study
from mdr_events import dem  # noqa: F401 - LAMMPS's granular models against the MDR (the extra [lammps] runs them)
from mdr_events.dem import lammps_check

__all__ = [
    "Adhesion",
    "Contact",
    "Elastomer",
    "Paraboloid",
    "Limits",
    "ResourceLimitError",
    "__version__",
    "DOI",
    "FitResult",
    "FlatPunch",
    "FrictionLaw",
    "FRICTION_LAWS",
    "Parameters",
    "PowerLaw",
    "TabulatedProfile",
    "Path",
    "Paths",
    "Scenario",
    "Continuum",
    "Discrete",
    "Engine",
    "ConvergenceReport",
    "ConvergenceVerdict",
    "ValidationReport",
    "Verdict",
    "SweepOutput",
    "Tolerances",
    "analytic",
    "power_law",
    "mindlin",
    "tabulated",
    "continuum",
    "critical_angle",
    "critical_shift",
    "fretting_dissipated_energy",
    "cross_check",
    "validate",
    "fit",
    "convergence_study",
    "d_crit",
    "jkr_contact_radius",
    "jkr_depth",
    "jkr_normal_force",
    "jump_off",
    "dem",
    "lammps_check",
    "load_study",
    "open_result",
    "phase_diagram",
    "pull_off_force",
    "run_study",
    "simulate",
    "sweep",
    "symbolic",
    "write_netcdf",
]
