r"""Slip onset of the flat punch on a layer: the depths (17)–(21) and the critical angles with the face held, then
receding under it.

Part of :mod:`mdr_events.theory.layer` (:mod:`~mdr_events.theory.layer.slip_onset` hands a flat punch here). The
contact is the face's radius ``a₀`` from the first touch on, its springs all attached then with no shift, so they
carry the path's whole tangential travel and slide together where it reaches the cap ``ū(a₀) = π a₀² τ0/K_t(a₀)``:

.. math:: \text{A (17), (18):}\ d = \bar u(a_0)\tan\alpha, \qquad
          \text{B "+":}\ d = d_\mathrm{max} + \bar u(a_0)\tan\alpha, \qquad
          \text{B "−" (20), (21):}\ d = d_\mathrm{max} - \bar u(a_0)\tan\alpha \ \text{ while } d \ge -\Delta l_1(a_0)

(closed forms, with or without adhesion alike going in). Going out beyond ``−Δl₁(a₀)`` the face is held no longer:
where the contact recedes (:mod:`~mdr_events.theory.layer.punch_recession`) the onset is the first radius of the
recession whose travel per cap ``r(a) = (d_max + Δl₁(a))/ū(a)`` reaches ``tan α`` (root-finding: the running maximum
of ``r`` on a scan, inverted by bisection, :func:`~mdr_events.theory.layer.slip_onset.first_onsets`); past the
jump-off ``a_j`` the contact comes apart first (``−inf``). The critical angle is ``atan`` of the travel per cap where
the motion ends: ``d_max/ū(a₀)`` in A, ``(d_max − d_j)/ū(a_j)`` at the jump-off ``(d_j, a_j)`` in B (``d_j = 0``
without adhesion, the half-space's flat punch's, ``mdr_events.power_law.critical_angle_B``): along the recession
``d_max + Δl(a)`` grows as ``a`` falls while ``ū(a)`` shrinks (``ū`` rises with ``a`` on every bonded layer of the
tables, ``d ln Φ_t/d ln λ < 1``), so the travel per cap is largest at ``a_j``.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from mdr_events.contact.indenters import FlatPunch
from mdr_events.contact.layer import Layer
from mdr_events.contact.model import Contact
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.job import rate_independent
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.punch_recession import punch_jump_off
from mdr_events.theory.layer.relations import hess_elongation
from mdr_events.theory.layer.tangential_compliance import check_bonded
from mdr_events.theory.layer.tangential_relations import sliding_cap
from mdr_events.theory.scales import check_representable
from mdr_events.validation import check_real

__all__ = ["check_punch_contact", "check_punch_face", "punch_onset_depths", "punch_critical_angle", "RECESSION_POINTS"]

#: Radii of the logarithmic scan of the travel per cap along the recession, from the face to the jump-off (a span of
#: at most ``ln(a₀/a_j)``, below ln 100 on the layers of the tables: nodes 1.2% apart, refined by bisection).
RECESSION_POINTS = 400


def check_punch_contact(contact: Contact, what: str, d_max: float | None) -> float:
    """What the slip onset of a flat punch on a layer takes, checked before it runs: the paper's adhesion law, the law
    (13), a bonded base, scales within double precision and the face within the tables.

    Parameters
    ----------
    contact : Contact
        A flat punch on a layer of finite thickness.
    what : str
        The function asked, named in the errors.
    d_max : float or None
        The motion's depth (m; ``None``: the paper's 0.3 mm).

    Returns
    -------
    float
        ``d_max``.

    Raises
    ------
    TypeError, ValueError
        In one line, naming what is not allowed.
    """
    rate_independent(contact, f"{what} on a layer")
    if contact.friction.law != "tau0":
        raise ValueError(f"{what} under contact.friction={contact.friction!r} is not allowed on a layer; allowed: "
                         "the law 'tau0' of eq. (13)")
    check_bonded(contact.layer)
    depth = check_real("d_max", PAPER_D_MAX if d_max is None else d_max, "a finite number > 0 (m)",
                       lambda value: value > 0.0)
    check_representable(contact.parameters(depth, PAPER_V), contact.profile,
                        dataclasses.replace(contact.friction, tau0=None))
    check_punch_face(contact.indenter, contact.layer, what)
    return depth


def check_punch_face(indenter: FlatPunch, layer: Layer, what: str) -> None:
    """Refuse a punch whose face lies beyond the layer's tables, ``a₀/h > LAMBDA_MAX``, before anything runs.

    Parameters
    ----------
    indenter : FlatPunch
        The punch.
    layer : Layer
        The layer (the half-space passes).
    what : str
        What is asked (a function, a method), named in the error.

    Raises
    ------
    ValueError
        In one line, naming the punch, the layer, ``what``, the largest radius and the least thickness allowed.
    """
    if float(indenter.radius) > LAMBDA_MAX * layer.thickness:
        raise ValueError(f"contact.indenter={indenter!r} is not allowed in {what} on {layer.describe()}: its "
                         f"face exceeds a/h = {LAMBDA_MAX:g} (the layer's tables); allowed: a radius up to "
                         f"{LAMBDA_MAX * layer.thickness:.6g} m, or a layer h >= {indenter.radius / LAMBDA_MAX:.6g} "
                         f"m, or h = inf (the half-space)")


def _cap(contact: Contact, a):
    """``ū(a) = π a² τ0/K_t(a)`` (13) on the contact's layer (m)."""
    elastomer = contact.elastomer
    return sliding_cap(a, contact.friction.tau0, elastomer.G_star, elastomer.nu, contact.layer)


def _elongation(contact: Contact, a, dgamma: float):
    """Heß's limit ``Δl(a)`` of ``dgamma`` on the contact's layer (m)."""
    return hess_elongation(a, dgamma, contact.elastomer.E_star, contact.elastomer.nu, contact.layer)


def _scanned_radius(log_radius, face: float):
    """The radius at ``ln a`` on the recession's scan, at most the face's: ``exp(ln a₀)`` rounds up to an ulp beyond
    ``a₀``, off the tables' range when the face is at ``a/h = 64`` (round twenty-two)."""
    return np.minimum(np.exp(log_radius), face)


def punch_onset_depths(alpha_deg: np.ndarray, contact: Contact, scenario: str, adhesion: bool, branch: str,
                       d_max: float | None) -> np.ndarray:
    """The depths at which the punch's springs start to slide (module docstring): ``+inf`` at 90° going in, ``-inf``
    where the contact comes apart first going out.

    Parameters
    ----------
    alpha_deg : numpy.ndarray
        Path angles in degrees, in ``[0, 90]``.
    contact : Contact
        A flat punch under the law (13) on a bonded layer.
    scenario : {"A", "B"}
        As :func:`mdr_events.d_crit`.
    adhesion : bool
        ``True``: Heß's rule with ``Δγ1`` on the way out; ``False``: the face comes off at the surface.
    branch : {"pull-off", "indentation"}
        Scenario B's branch (ignored in A).
    d_max : float or None
        The depth scenario B starts from (m; ``None``: the paper's 0.3 mm).

    Returns
    -------
    numpy.ndarray
        ``d_crit`` (m), the shape of ``alpha_deg``.
    """
    from mdr_events.theory.layer.slip_onset import first_onsets

    depth = check_punch_contact(contact, "d_crit", d_max)
    vertical = alpha_deg >= 90.0
    tangent = np.tan(np.radians(np.where(vertical, 0.0, alpha_deg)))
    face = float(contact.indenter.radius)
    cap = float(_cap(contact, face))
    if scenario == "A" or branch != "pull-off":
        start = 0.0 if scenario == "A" else depth
        return np.where(vertical, math.inf, start + cap * tangent)
    work = contact.adhesion.dgamma1 if adhesion else 0.0
    held_depth = -float(_elongation(contact, face, work)) if work > 0.0 else 0.0
    held = depth - cap * tangent
    out = np.where(held >= held_depth, held, -math.inf)
    pull_radius = punch_jump_off(contact, work)[1]
    receding = (held < held_depth) & ~vertical
    if pull_radius < face and np.any(receding):
        logs = np.linspace(math.log(face), math.log(pull_radius), RECESSION_POINTS)

        def ratio_of(log_radius):
            a = _scanned_radius(log_radius, face)
            return (depth + _elongation(contact, a, work)) / _cap(contact, a)

        def depth_of(a):
            return -_elongation(contact, np.minimum(a, face), work)

        out[receding] = first_onsets(logs, ratio_of, depth_of, tangent[receding], -math.inf)
    return np.where(vertical, -math.inf, out)


def punch_critical_angle(contact: Contact, scenario: str, adhesion: bool, final_depth: float | None,
                         d_max: float | None) -> float:
    """The critical path angle (degrees) of the punch on the layer: the travel per cap where the motion ends (module
    docstring).

    Parameters
    ----------
    contact : Contact
        As :func:`punch_onset_depths`.
    scenario : {"A", "B", "B+"}
        As :func:`mdr_events.critical_angle`.
    adhesion : bool
        ``True``: Heß's rule with ``Δγ1`` on the way out.
    final_depth : float or None
        Scenario B+ only: the depth reached (``None``: ``2 d_max``).
    d_max : float or None
        The motion's depth (m; ``None``: the paper's 0.3 mm).

    Returns
    -------
    float
        The critical angle in degrees.
    """
    depth = check_punch_contact(contact, "critical_angle", d_max)
    face = float(contact.indenter.radius)
    if scenario == "A":
        return _angle(depth, float(_cap(contact, face)))
    if scenario == "B+":
        end = 2.0 * depth if final_depth is None else check_real(
            "final_depth", final_depth, f"a finite depth > d_max = {depth!r} m", lambda value: value > depth)
        return _angle(end - depth, float(_cap(contact, face)))
    # (the travel per cap r(a) = (d_max + Δl(a))/ū(a) falls with a on [a_j, a₀]: Δl falls there (the recession) and
    # ū = π a τ0/(2G* Φ_t(a/h)) rises with a on every bonded layer of the tables; its maximum is r(a_j))
    jump_depth, jump_radius = punch_jump_off(contact, contact.adhesion.dgamma1 if adhesion else 0.0)
    return _angle(depth - jump_depth, float(_cap(contact, jump_radius)))


def _angle(travel: float, cap: float) -> float:
    """The path angle (degrees) whose tangent is the depth travelled per cap, ``travel / ū``; 90° where the cap is 0
    (``τ0 = 0``: every spring slides at once on any path with a tangential part, as the closed forms of the other
    indenters give; round thirty: ``ZeroDivisionError`` in a phase diagram of the punch on a layer)."""
    return 90.0 if cap == 0.0 else float(np.degrees(np.arctan(travel / cap)))
