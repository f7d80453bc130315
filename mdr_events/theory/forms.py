"""The tables of closed forms a kind of indenter files with :func:`mdr_events.theory.kinds.theory_of`.

:class:`ClosedForms` is what :mod:`mdr_events.theory.power_law`'s functions of either indenter hand the indenter to
(the power law's :data:`mdr_events.theory.power_law.CLOSED_FORMS`, the flat punch's
:data:`mdr_events.theory.flat_punch.CLOSED_FORMS`); :class:`FrictionForms` what :mod:`mdr_events.theory.mindlin`'s
friction laws hand a kind whose own closed forms replace a curved indenter's (the flat punch's
:data:`mdr_events.theory.flat_punch.FRICTION_FORMS`). Each entry takes the arguments of the function of its name,
the profile one of its kind, and checks the others itself.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["ClosedForms", "FrictionForms"]


@dataclass(frozen=True)
class ClosedForms:
    """One kind's closed forms behind :mod:`mdr_events.theory.power_law`'s functions of either indenter.

    Parameters
    ----------
    normal_force, jump_off, pull_off_force : callable
        The normal force (10) at a depth and radius, the jump-off and the pull-off force.
    d_crit_A, d_crit_B, d_crit_B_indentation : callable
        The slip-onset depths of scenario A (17), (18), B's pull-off and B's indentation branch (20), (21).
    critical_angle_A, critical_angle_B, critical_angle_B_indentation : callable
        Their critical angles (degrees).
    """

    normal_force: Callable[..., object]
    jump_off: Callable[..., dict[str, float]]
    pull_off_force: Callable[..., float]
    d_crit_A: Callable[..., object]
    d_crit_B: Callable[..., object]
    d_crit_B_indentation: Callable[..., object]
    critical_angle_A: Callable[..., float]
    critical_angle_B: Callable[..., float]
    critical_angle_B_indentation: Callable[..., float]


@dataclass(frozen=True)
class FrictionForms:
    """A kind's own closed forms under the friction laws' caps ``K a + κ (d − g)``, where those of a curved indenter
    (:mod:`mdr_events.theory.mindlin`) do not serve it.

    Parameters
    ----------
    coulomb_force : callable
        ``(sliding, params, contact_radius)``: Coulomb's part of the virgin curve.
    d_crit_B, d_crit_B_indentation, critical_angle_B_indentation : callable
        Scenario B's onsets and the "+" branch's critical angle under the capped law.
    """

    coulomb_force: Callable[..., object]
    d_crit_B: Callable[..., np.ndarray]
    d_crit_B_indentation: Callable[..., np.ndarray]
    critical_angle_B_indentation: Callable[..., float]
