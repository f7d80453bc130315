"""The paraboloid's critical path angles: scenario A's (17), (18) at ``d_max``, B's (21) at the jump-off, B+'s at the
final depth.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from mdr_events.theory.analytic.arguments import _rel, final_depth_of
from mdr_events.theory.analytic.normal import hertz_contact_radius, jkr_contact_radius, jump_off
from mdr_events.theory.analytic.onset import _onset_parameters
from mdr_events.theory.job import ContactLike, on_layer
from mdr_events.validation import check_choice, check_flag, shown

__all__ = ["critical_angle", "CRITICAL_ANGLE_SCENARIOS"]

#: Scenarios that have a critical angle (:func:`critical_angle`).
CRITICAL_ANGLE_SCENARIOS = ("A", "B", "B+")


def critical_angle(contact: ContactLike, scenario: Literal["A", "B", "B+"] = "A", adhesion: bool = True,
                   final_depth: float | None = None, *, d_max: float | None = None) -> float:
    r"""Critical path angle in degrees.

    ``contact`` is a :class:`~mdr_events.Contact` of the paraboloid (4) under the law (13), with the motion's depth
    ``d_max`` (m; default the paper's 0.3 mm), or a :class:`~mdr_events.Parameters` (the keywords of before, with its
    own ``d_max``).

    Scenario A: the angle at which slip begins exactly at ``d_max``
    (``d_crit(α_c) = d_max``); for α < α_c the springs slide during
    indentation. Non-adhesive: eq. (17) at ``d_max``; adhesive: eq. (18) with
    the JKR radius at ``d_max`` on the ``Δγ0`` branch.

    Scenario B: ``d_crit`` of the pull-off branch equals ``d_max`` only at
    α = 0, so the meaningful threshold is the other end: the angle above which
    the contact comes apart (jump-off on the ``Δγ1`` branch) before any spring
    slides, eq. (21) at the jump-off point. Without adhesion the radius
    shrinks to zero and slip always comes first: 90°.

    Scenario B+ (the "+" branch of Fig. 9b, :meth:`mdr_events.Path.scenario_B_indentation`):
    vertically to ``d_max``, then further in at angle α to ``final_depth``
    (default ``2 d_max``, as the path). Every angle below 90° slides at some
    depth beyond ``d_max``; the critical angle is the one at which slip begins
    exactly at ``final_depth`` (the "+" sign of (21), or the larger root of (20), at
    the radius of ``final_depth`` on the ``Δγ0`` branch): for α < α_c the springs
    slide before the path turns back.

    At the critical angle of scenario A the slip depth of (17) or (18) equals ``d_max``; with the contact radius
    ``a`` there,

    .. math:: \tan \alpha_c = \frac{2 G^* d_\mathrm{max}}{\pi a \tau_0}.

    In scenario B (21) at the jump-off point ``(a, d)`` of the ``Δγ1`` branch, and in B+ (21) with the "+" sign
    at ``final_depth``:

    .. math:: \tan \alpha_c = \frac{2 G^* (d_\mathrm{max} - d)}{\pi a \tau_0}, \qquad
              \tan \alpha_c = \frac{2 G^* (d - d_\mathrm{max})}{\pi a \tau_0}.

    On a layer of finite thickness bonded to its base (``Contact.layer``) the cap is ``π a² τ0/K_t(a)`` and the
    radius follows the layer's branches: ``tan α_c`` is the largest travel per cap the motion meets
    (:mod:`mdr_events.theory.layer.slip_onset`).

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4) under the law (13): a :class:`~mdr_events.Contact` (with ``d_max``; on a layer
        also a power law), or a :class:`~mdr_events.Parameters` (the keywords of before, with its own ``d_max``).
    scenario : {"A", "B", "B+"}
        The path: ``"A"`` (14), ``"B"`` (19) pulled off at the angle, ``"B+"`` pressed further in at the angle.
    adhesion : bool
        ``True`` (the default): the JKR radius (9) with ``Δγ0`` in and ``Δγ1`` out; ``False``: the Hertz radius
        (16).
    final_depth : float, optional
        Scenario B+ only: the depth (m) the path reaches (default ``2 d_max``).
    d_max : float, optional
        With a Contact: the motion's depth (m; default the paper's 0.3 mm).

    Returns
    -------
    float
        The critical angle in degrees (90 where slip always comes first).
    """
    p = None if on_layer(contact) else _onset_parameters(contact, "critical_angle", d_max)
    scenario = check_choice("scenario", scenario, CRITICAL_ANGLE_SCENARIOS)
    check_flag("adhesion", adhesion)
    if final_depth is not None and scenario != "B+":
        raise ValueError(f"final_depth={shown(final_depth)} is not allowed with scenario {scenario!r}; "
                         "allowed: None (final_depth is for scenario 'B+')")
    if p is None:
        from mdr_events.theory.layer.slip_onset import critical_angle_on_layer

        return critical_angle_on_layer(contact, scenario, adhesion, final_depth, d_max)
    if scenario == "B+":
        final = final_depth_of(p, final_depth)
        if adhesion:
            radius = jkr_contact_radius(final, p, p.dgamma0)
        else:
            radius = float(hertz_contact_radius(final, p))
        with np.errstate(divide="ignore"):
            angle = _rel("critical_angle_B_indentation").numeric(radius, final, p.d_max, p.tau0, p.G_star)
        return float(np.rad2deg(angle))
    if scenario == "A":
        if adhesion:
            radius = jkr_contact_radius(p.d_max, p, p.dgamma0)
        else:
            radius = float(hertz_contact_radius(p.d_max, p))
        with np.errstate(divide="ignore"):
            angle = _rel("critical_angle_A").numeric(radius, p.d_max, p.tau0, p.G_star)
        return float(np.rad2deg(angle))
    if not adhesion or p.dgamma1 == 0.0:
        return 90.0
    point = jump_off(p, p.dgamma1)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B").numeric(point["contact_radius"], point["depth"], p.d_max, p.tau0, p.G_star)
    return float(np.rad2deg(angle))

