"""mdr_events: adhesive indentation and detachment at an angle with the MDR.

Reproduces and extends section 4 of Lyashenko, Popov & Borysiuk,
Biomimetics 2023, 8(6), 477 (doi:10.3390/biomimetics8060477): a rigid
paraboloid pressed into and pulled off an elastomer along a straight path at
an angle, with Heß's adhesion rule (two works of adhesion) and a
spring-slip criterion.

Layers (data flows one way):
``parameters`` → ``symbolic`` (SymPy derivations) → ``analytic`` (closed
forms, phase diagrams) / ``continuum`` (event-driven, exact) / ``discrete``
(the paper's springs) → ``simulate``, ``crosscheck`` → ``datasets`` (xarray,
netCDF) → ``output``, ``plotting``, ``report``, ``study`` and ``cli``.
"""

from ._version import __version__
from .analytic import (
    critical_angle,
    critical_shift,
    d_crit,
    jkr_contact_radius,
    jkr_depth,
    jkr_normal_force,
    jump_off,
    pull_off_force,
)
from .crosscheck import cross_check
from .datasets import DOI, open_result, write_netcdf
from .parameters import Parameters
from .paths import Path
from .phase import phase_diagram
from .simulate import simulate
from .study import load_study, run_study

__all__ = [
    "__version__",
    "DOI",
    "Parameters",
    "Path",
    "critical_angle",
    "critical_shift",
    "cross_check",
    "d_crit",
    "jkr_contact_radius",
    "jkr_depth",
    "jkr_normal_force",
    "jump_off",
    "load_study",
    "open_result",
    "phase_diagram",
    "pull_off_force",
    "run_study",
    "simulate",
    "write_netcdf",
]
