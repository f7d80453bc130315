"""Closed forms of the power-law indenter ``f = c rⁿ``, vectorised.

Every formula is the derived relation of :func:`mdr_events.theory.symbolic.derive_power_law_model`
(Heß's rule (8) for the profile's Abel transform (3)); the paraboloid ``n = 2, c = 1/(2R)`` gives the
functions of :mod:`mdr_events.theory.analytic` (the tests compare them). Where the relations have no
closed form (the radius at a given depth with adhesion, the slip onset (18)) the functions solve for it
with a safeguarded, vectorised Newton iteration on a convex function (:func:`convex_root`).

The material, the friction and the works of adhesion come from :class:`~mdr_events.Parameters` (its ``R``
is the paraboloid's and is not used here); the indenter from the profile. The functions that take either indenter (a
power law or the flat punch: :func:`normal_force`, :func:`jump_off`, :func:`pull_off_force`, the slip onsets and
critical angles) hand it to its kind's :class:`~mdr_events.theory.forms.ClosedForms`, filed by
:func:`mdr_events.theory.kinds.theory_of`: the power law's here (:data:`CLOSED_FORMS`), the flat punch's in
:mod:`mdr_events.theory.flat_punch`.

The package holds one idea per module, and this module lists the public names (``__all__``) where users and the
documentation import them: what the functions are given, checked (``arguments``), the root finder
(``convex_roots``), the relations' scales (``prefactors``), the normal relations (``normal``), the jump-off and
pull-off (``detachment``), the slip onsets and critical angles (``onset``).
"""

from __future__ import annotations

from mdr_events.theory.forms import ClosedForms
from mdr_events.theory.power_law import arguments as _arguments, convex_roots as _convex_roots
from mdr_events.theory.power_law.arguments import as_output, check_profile, check_work, final_depth_of, path_angles
from mdr_events.theory.power_law.convex_roots import ROOT_MAX_DOUBLINGS, ROOT_MAX_ITERATIONS, branch_root, convex_root
from mdr_events.theory.power_law.detachment import _jump_off, _pull_off_force, jump_off, pull_off_force
from mdr_events.theory.power_law.normal import (_normal_force, branch_depth, branch_normal_force, contact_radius,
                                                equivalent_profile, jump_in_radius, normal_force, with_radius_at)
from mdr_events.theory.power_law.onset import (_critical_angle_A, _critical_angle_B, _critical_angle_B_indentation,
                                               _d_crit_A, _d_crit_B, _d_crit_B_indentation, critical_angle_A,
                                               critical_angle_B, critical_angle_B_indentation, d_crit_A, d_crit_B,
                                               d_crit_B_indentation)
from mdr_events.theory.power_law.prefactors import cap_per_radius, hess_prefactor, prefactor

# (the constants documented where the documentation reads them, their doc comments as in their modules)
#: With adhesion a power law needs ``n`` above this: below it ``√a`` outgrows ``aⁿ`` and no contact is stable.
ADHESIVE_MIN_EXPONENT = _arguments.ADHESIVE_MIN_EXPONENT
#: Relative accuracy of :func:`convex_root` (a few ulp).
ROOT_RTOL = _convex_roots.ROOT_RTOL

__all__ = ["equivalent_profile", "branch_depth", "normal_force", "branch_normal_force", "contact_radius",
           "jump_in_radius", "jump_off", "pull_off_force", "d_crit_A", "critical_angle_A", "d_crit_B",
           "critical_angle_B", "d_crit_B_indentation", "critical_angle_B_indentation", "convex_root", "branch_root",
           "with_radius_at", "prefactor", "hess_prefactor", "check_profile", "CLOSED_FORMS",
           "ADHESIVE_MIN_EXPONENT", "ROOT_RTOL"]


#: The power law's closed forms behind the package's functions of either indenter.
CLOSED_FORMS = ClosedForms(normal_force=_normal_force, jump_off=_jump_off, pull_off_force=_pull_off_force,
                           d_crit_A=_d_crit_A, critical_angle_A=_critical_angle_A, d_crit_B=_d_crit_B,
                           critical_angle_B=_critical_angle_B, d_crit_B_indentation=_d_crit_B_indentation,
                           critical_angle_B_indentation=_critical_angle_B_indentation)
