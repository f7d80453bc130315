"""Where the power law's (or the flat punch's) adhesive contact ends: the jump-off under displacement control and the
pull-off force under force control.
"""

from __future__ import annotations

from mdr_events.parameters import Parameters
from mdr_events.theory.analytic.arguments import representable_result
from mdr_events.contact.indenters import PowerLaw, Profile
from mdr_events.theory.power_law.arguments import _check_adhesive, _check_work, _forms, _rel

__all__ = ["jump_off", "pull_off_force"]


def jump_off(profile: Profile, params: Parameters, work_of_adhesion: float) -> dict[str, float]:
    """The end of contact under displacement control: ``contact_radius``, ``depth`` and ``normal_force``.

    Power law: where ``∂d/∂a = 0`` on the branch; the flat punch: Kendall's
    (:func:`mdr_events.theory.flat_punch.jump_off`).

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.

    Returns
    -------
    dict of str to float
        ``contact_radius`` (m), ``depth`` (m) and ``normal_force`` (N) there; all 0 for a power law without
        adhesion.

    Raises
    ------
    ValueError
        ``n <= 1/2`` with adhesion.
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    return _forms(profile).jump_off(profile, params, work_of_adhesion)


def _jump_off(profile: PowerLaw, params: Parameters, work_of_adhesion: float) -> dict[str, float]:
    """The power law's :func:`jump_off`: where ``∂d/∂a = 0`` on the branch."""
    work_of_adhesion = _check_work(work_of_adhesion)
    if work_of_adhesion == 0.0:
        return {"contact_radius": 0.0, "depth": 0.0, "normal_force": 0.0}
    _check_adhesive(profile, work_of_adhesion)
    args = (profile.c, profile.n, params.E_star, work_of_adhesion)
    # near n = 1/2 the factors raised to 1/(2n − 1) overflow (n = 0.501: a depth of inf·0, nan, with NumPy's warning;
    # issue 32 round 29 B2): refused as the paraboloid's is, naming the indenter and the work
    return representable_result(lambda: {"contact_radius": float(_rel("power_law_jump_off_radius").numeric(*args)),
                                         "depth": float(_rel("power_law_jump_off_depth").numeric(*args)),
                                         "normal_force": float(_rel("power_law_jump_off_force").numeric(*args))},
                                "power_law.jump_off", profile=profile, work_of_adhesion=work_of_adhesion)


def pull_off_force(profile: Profile, params: Parameters, work_of_adhesion: float) -> float:
    """The pull-off force under force control (N, <= 0): the minimum of (10) along the branch (the paraboloid:
    JKR's ``−(3/2) π Δγ R``); the flat punch: :func:`mdr_events.theory.flat_punch.pull_off_force`.

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ1`` (J/m², >= 0), the work of adhesion of the way out.

    Returns
    -------
    float
        The pull-off force (N, <= 0; 0 without adhesion).

    Raises
    ------
    ValueError
        ``n <= 1/2`` with adhesion.
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    return _forms(profile).pull_off_force(profile, params, work_of_adhesion)


def _pull_off_force(profile: PowerLaw, params: Parameters, work_of_adhesion: float) -> float:
    """The power law's :func:`pull_off_force`: the minimum of (10) along the branch."""
    work_of_adhesion = _check_work(work_of_adhesion)
    if work_of_adhesion == 0.0:
        return 0.0
    _check_adhesive(profile, work_of_adhesion)
    return float(_rel("power_law_pull_off_force").numeric(profile.c, profile.n, params.E_star, work_of_adhesion))

