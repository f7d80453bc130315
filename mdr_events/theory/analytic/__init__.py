"""Closed-form layer: JKR contact, slip-onset depths ``d_crit(α)``, critical angles.

Every formula is evaluated through the SymPy-derived relations of
:mod:`mdr_events.theory.symbolic` (lambdified once). Where a relation is a
polynomial (the cubic of (18), the quartics of (9) and (21)), its unique
physical root is found by :func:`~mdr_events.theory.roots.positive_polynomial_root`, a vectorised
safeguarded Newton iteration: no Python loop over angles.

Angles are in degrees, lengths in metres, forces in newtons.

Each public function takes the physical model as a :class:`~mdr_events.Contact` of the paper's paraboloid (4) under
its friction law (13) (with the depth ``d_max=`` where a relation needs the motion's depth: (20), (21) and the
critical angles), or as the keywords of before, a :class:`~mdr_events.Parameters`; both are read by
:func:`~mdr_events.theory.job.paper_parameters` and give the same numbers.
The package holds one idea per module, and this module lists the public names (``__all__``) where users and the
documentation import them: what the closed forms are given, checked (``arguments``), the normal relations (9), (10),
(16) and the jump-off (``normal``), the tangential springs (13) (``tangential``), the slip onsets (17)–(21)
(``onset``), the critical angles (``angles``) and the dimensionless groups (``groups``). Each of the paper's closed
forms is one public function with its full numpydoc sections and typeset equation; the relations themselves are
derived in ``symbolic``.
"""

from __future__ import annotations

from mdr_events.theory.analytic import angles as _angles, onset as _onset
from mdr_events.theory.analytic.angles import critical_angle
from mdr_events.theory.analytic.arguments import NONNEGATIVE, ResultOverflowError
from mdr_events.theory.analytic.groups import DimensionlessGroups, dimensionless_groups
from mdr_events.theory.analytic.normal import (JUMP_OFF_CACHE, _paraboloid_jump_off, hertz_contact_radius,
                                               jkr_contact_radius, jkr_depth, jkr_normal_force, jump_in_radius,
                                               jump_off, normal_force, pull_off_force)
from mdr_events.theory.analytic.onset import (BRANCHES, D_CRIT_ROWS_BYTES_PER_ANGLE, SCENARIOS, d_crit,
                                              d_crit_curves, d_crit_rows)
from mdr_events.theory.analytic.tangential import critical_shift, fretting_dissipated_energy
from mdr_events.theory.roots import positive_polynomial_root

# (the constants documented where the documentation reads them, their doc comments as in their modules)
#: Bytes the half-space's slip onsets allocate per angle at their peak, counted against ``Limits.memory`` before the
#: angles are read (tracemalloc at 1e6 angles: :func:`d_crit` 26 without adhesion, 42 with; :func:`d_crit_rows` 43 in
#: scenario A, 59 in B's two rows), rounded up. Round twenty-five: ``d_crit`` of 1e8 angles (a view of one value, no
#: memory of its own) took 2.4 to 4.2 GB against the default 2 GiB, accepted.
D_CRIT_BYTES_PER_ANGLE = _onset.D_CRIT_BYTES_PER_ANGLE
#: Scenarios that have a critical angle (:func:`critical_angle`).
CRITICAL_ANGLE_SCENARIOS = _angles.CRITICAL_ANGLE_SCENARIOS

__all__ = [
    "DimensionlessGroups",
    "dimensionless_groups",
    "d_crit",
    "d_crit_curves",
    "d_crit_rows",
    "D_CRIT_BYTES_PER_ANGLE",
    "D_CRIT_ROWS_BYTES_PER_ANGLE",
    "critical_angle",
    "critical_shift",
    "jkr_depth",
    "jkr_contact_radius",
    "jkr_normal_force",
    "normal_force",
    "hertz_contact_radius",
    "pull_off_force",
    "jump_off",
    "jump_in_radius",
    "positive_polynomial_root",
    "SCENARIOS",
    "BRANCHES",
    "CRITICAL_ANGLE_SCENARIOS",
]
