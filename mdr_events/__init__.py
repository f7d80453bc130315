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

import importlib

#: ``typing.TYPE_CHECKING`` without importing ``typing`` (and ``re``, a third of the package's import): the console
#: script's handlers of Ctrl-C are installed after this module has run (:mod:`mdr_events.app.console`), so it is kept
#: short; static tools read a module-level ``TYPE_CHECKING = False`` as they read ``typing``'s.
TYPE_CHECKING = False

from mdr_events._version import __version__
from mdr_events.io.registrars import declare_registrars as _declare_registrars

# Every public name is loaded when first used (PEP 562, as SPEC 1 lays out): ``import mdr_events`` imports none of
# the submodules below, nor NumPy, SciPy, xarray, SymPy or matplotlib (tests/test_imports.py checks it).
#: Where each public name is defined: name -> module (the module itself for the modules in ``__all__``).
_LAZY = {
    "Parameters": "mdr_events.parameters",
    **dict.fromkeys(("Adhesion", "Contact", "Elastomer", "FRICTION_LAWS", "FlatPunch", "FrictionLaw", "Layer",
                     "LayerBase", "Paraboloid", "PowerLaw", "RateDependentAdhesion", "TabulatedProfile"),
                    "mdr_events.contact"),
    **dict.fromkeys(("Limits", "ResourceLimitError"), "mdr_events.limits"),
    "DOI": "mdr_events.io.datasets",
    **dict.fromkeys(("open_result", "write_netcdf"), "mdr_events.io.files"),
    **{name: f"mdr_events.theory.{name}" for name in ("analytic", "mindlin", "power_law", "symbolic", "tabulated")},
    **dict.fromkeys(("critical_angle", "critical_shift", "d_crit", "fretting_dissipated_energy", "jkr_contact_radius",
                     "jkr_depth", "jkr_normal_force", "jump_off", "pull_off_force"), "mdr_events.theory.analytic"),
    "continuum": "mdr_events.models.continuum",
    "Tolerances": "mdr_events.models.continuum",
    "Path": "mdr_events.models.paths",
    **dict.fromkeys(("Paths", "Scenario"), "mdr_events.models.motion"),
    **dict.fromkeys(("Continuum", "Discrete"), "mdr_events.models.methods"),
    "phase_diagram": "mdr_events.theory.phase",
    **dict.fromkeys(("layer_indentation_cycle", "layer_normal_curve", "layer_pull_off_curve"),
                    "mdr_events.theory.layer.curves"),
    "simulate": "mdr_events.models.simulate",
    "cross_check": "mdr_events.analysis.crosscheck",
    "validate": "mdr_events.analysis.validate",
    **dict.fromkeys(("ConvergenceReport", "ConvergenceVerdict", "ValidationReport", "Verdict"),
                    "mdr_events.analysis.reports"),
    "convergence_study": "mdr_events.analysis.convergence_study",
    **dict.fromkeys(("FitResult", "fit"), "mdr_events.analysis.fit"),
    **dict.fromkeys(("RateMeasurement", "fit_rate_adhesion"), "mdr_events.analysis.rate_fit"),
    **dict.fromkeys(("critical_angle_at_speed", "critical_angles_at_speeds", "phase_diagram_at_speeds",
                     "slip_onset_depth_at_speed"), "mdr_events.analysis.rate_angles"),
    **dict.fromkeys(("critical_angle_B_at_speed", "critical_angles_B_at_speeds", "let_go_B_at_speed"),
                    "mdr_events.analysis.rate_let_go"),
    "critical_angles_against_thickness": "mdr_events.analysis.layer_angles",
    **dict.fromkeys(("Engine", "SweepOutput", "sweep"), "mdr_events.analysis.sweep"),
    **dict.fromkeys(("load_study", "run_study"), "mdr_events.app.study"),
    "dem": "mdr_events.dem",
    "lammps_check": "mdr_events.dem",
}
#: The names in ``__all__`` that are modules.
_MODULES = ("analytic", "mindlin", "power_law", "symbolic", "tabulated", "continuum", "dem")
#: The subpackages and modules reachable as attributes (``mdr_events.plotting``) without importing them first.
_SUBMODULES = ("analysis", "app", "contact", "io", "limits", "models", "parameters", "plotting", "reproduction",
               "theory", "validation")

# The modules that make results register their schemas (and accuracies, and figures) when imported: the first
# look-up in a registry imports them, so that open_result knows every kind of result whatever a user imports.
_declare_registrars(
    schemas=("mdr_events.theory.phase", "mdr_events.theory.layer.curves", "mdr_events.models.simulation_schema", "mdr_events.analysis.crosscheck",
             "mdr_events.analysis.validate", "mdr_events.analysis.convergence_study",
             "mdr_events.analysis.universal_map", "mdr_events.analysis.fit", "mdr_events.analysis.fit_data", "mdr_events.analysis.rate_fit", "mdr_events.analysis.rate_angles",
             "mdr_events.analysis.sweep", "mdr_events.analysis.layer_angles", "mdr_events.dem.runner"),
    figures=("mdr_events.plotting.fit", "mdr_events.plotting.universal"))


def __getattr__(name: str):
    """Load a public name (:data:`__all__`) or a subpackage on first use, and keep it (PEP 562)."""
    if name in _LAZY:
        module = importlib.import_module(_LAZY[name])
        value = module if name in _MODULES else getattr(module, name)
    elif name in _SUBMODULES:
        value = importlib.import_module(f"{__name__}.{name}")
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """The public names (:data:`__all__`) beside the module's own, for ``dir()`` and tab completion."""
    return sorted(set(globals()) | set(__all__))


if TYPE_CHECKING:  # what static tools (type checkers, IDEs) read: the same names, imported eagerly
    from mdr_events.analysis.convergence_study import convergence_study
    from mdr_events.analysis.crosscheck import cross_check
    from mdr_events.analysis.fit import FitResult, fit
    from mdr_events.analysis.layer_angles import critical_angles_against_thickness
    from mdr_events.analysis.rate_angles import (critical_angle_at_speed, critical_angles_at_speeds,
                                                 phase_diagram_at_speeds, slip_onset_depth_at_speed)
    from mdr_events.analysis.rate_let_go import critical_angle_B_at_speed, critical_angles_B_at_speeds, let_go_B_at_speed
    from mdr_events.analysis.rate_fit import RateMeasurement, fit_rate_adhesion
    from mdr_events.analysis.reports import ConvergenceReport, ConvergenceVerdict, ValidationReport, Verdict
    from mdr_events.analysis.sweep import Engine, SweepOutput, sweep
    from mdr_events.analysis.validate import validate
    from mdr_events.app.study import load_study, run_study
    from mdr_events import dem
    from mdr_events.dem import lammps_check
    from mdr_events.contact import (FRICTION_LAWS, Adhesion, Contact, Elastomer, FlatPunch, FrictionLaw, Layer,
                                    LayerBase, Paraboloid, PowerLaw, RateDependentAdhesion, TabulatedProfile)
    from mdr_events.io.datasets import DOI
    from mdr_events.io.files import open_result, write_netcdf
    from mdr_events.limits import Limits, ResourceLimitError
    from mdr_events.models import continuum
    from mdr_events.models.continuum import Tolerances
    from mdr_events.models.methods import Continuum, Discrete
    from mdr_events.models.motion import Paths, Scenario
    from mdr_events.models.paths import Path
    from mdr_events.models.simulate import simulate
    from mdr_events.parameters import Parameters
    from mdr_events.theory import analytic, mindlin, power_law, symbolic, tabulated
    from mdr_events.theory.analytic import (critical_angle, critical_shift, d_crit, fretting_dissipated_energy,
                                            jkr_contact_radius, jkr_depth, jkr_normal_force, jump_off, pull_off_force)
    from mdr_events.theory.layer.curves import layer_indentation_cycle, layer_normal_curve, layer_pull_off_curve
    from mdr_events.theory.phase import phase_diagram

__all__ = [
    "Adhesion",
    "RateDependentAdhesion",
    "Contact",
    "Elastomer",
    "Layer",
    "LayerBase",
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
    "fit_rate_adhesion",
    "RateMeasurement",
    "critical_angle_at_speed",
    "critical_angles_at_speeds",
    "phase_diagram_at_speeds",
    "slip_onset_depth_at_speed",
    "critical_angle_B_at_speed",
    "critical_angles_B_at_speeds",
    "let_go_B_at_speed",
    "convergence_study",
    "d_crit",
    "jkr_contact_radius",
    "jkr_depth",
    "jkr_normal_force",
    "jump_off",
    "layer_normal_curve",
    "layer_indentation_cycle",
    "layer_pull_off_curve",
    "critical_angles_against_thickness",
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
