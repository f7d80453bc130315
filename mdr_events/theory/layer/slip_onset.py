r"""Slip onset on a layer: the depths (17)–(21) and the critical angles with the layer's ``K_t`` and branches.

Part of :mod:`mdr_events.theory.layer`. On a layer bonded to its base the springs' cap under the law (13) is
``ū(a) = π a² τ0 / K_t(a)`` (:func:`~mdr_events.theory.layer_tangential.sliding_cap`; ``π a τ0/(2G*)`` on the
half-space) and the depth of the contact radius ``a`` is ``d(a) = g(a) − Δl(a)`` (the layer's branch,
:func:`~mdr_events.theory.layer.branch_depth`). The oldest springs carry the path's whole tangential travel, so the
springs begin to slide where that travel reaches the cap; each onset is an equation in ``a``:

.. math:: \text{A (14):}\ \frac{d(a)}{\tan\alpha} = \bar u(a), \qquad
          \text{B (19), "−":}\ \frac{d_\mathrm{max} - d_1(a)}{\tan\alpha} = \bar u(a), \qquad
          \text{"+":}\ \frac{d_0(a) - d_\mathrm{max}}{\tan\alpha} = \bar u(a)

(``d_0``, ``d_1`` the branches of ``Δγ0`` and ``Δγ1``; the half-space's (18) and (21); without adhesion (17) and
(20)). Written as ``tan α = r(a)`` with ``r`` the travel per cap along the branch the motion follows, the onset is
the first radius at which ``r`` reaches ``tan α``: the running maximum of ``r`` along the motion is inverted (a
logarithmic scan of :data:`SCAN_POINTS` radii, then bisection in ``ln a`` to round-off). The critical angle is
``atan`` of that running maximum where the motion ends (A: at ``d_max``; B: at the jump-off on ``Δγ1``, as
(21) assumes, the radius following ``Δγ1`` from ``d_max``; B+: at ``final_depth``).

Thin bonded layer: the layer shears like a Winkler foundation, ``K_t → π a² G/h`` (derived in
:mod:`mdr_events.theory.layer_tangential_symbolic`), so ``ū → τ0 h/G`` is the same for every spring and every radius:
scenario A's onset tends to ``d = τ0 h tan α / G``, whatever the indenter and adhesion
(:func:`thin_layer_onset_depth`).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Callable, NamedTuple

import numpy as np

from mdr_events.contact.adhesion import Adhesion
from mdr_events.contact.indenters import FlatPunch, Paraboloid, PowerLaw, indenter_kind
from mdr_events.contact.layer import Layer, LayerBase
from mdr_events.contact.model import Contact
from mdr_events.limits import Limits, check_limits
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.job import rate_independent
from mdr_events.theory.layer.branch_scan import beyond_tables, branch_jump_off, layer_material, stable_radius
from mdr_events.theory.layer.onset_scan import (SCAN_POINTS, SCAN_SPAN, _motion, _onset_depths, _scan_top,
                                                first_onsets)
from mdr_events.theory.layer.punch_onset import check_punch_contact, punch_critical_angle, punch_onset_depths
from mdr_events.theory.layer.punch_recession import punch_jump_off
from mdr_events.theory.layer.relations import branch_depth
from mdr_events.theory.layer.tangential_compliance import check_bonded
from mdr_events.theory.scales import check_representable
from mdr_events.validation import check_real, shown, validate_alpha

__all__ = ["onset_depths", "critical_angle_on_layer", "pull_off_depth", "first_onsets", "thin_layer_onset_depth", "check_onset_contact",
           "has_closed_forms", "SCAN_POINTS", "SCAN_SPAN", "ONSET_STEPS_PER_ANGLE", "ONSET_BYTES_PER_ANGLE",
           "check_onset_count", "CRITICAL_ANGLE_STEPS", "LayerOnsets", "LAYER_ONSETS"]

#: What one angle of an onset curve on a layer counts against :attr:`~mdr_events.Limits.steps`: a bisection of
#: :data:`_BISECTIONS` steps on the layer's tables, about 32 µs (a phase diagram's two curves in A, four in B: 65 and
#: 130 µs per angle measured), where the discrete model's step takes about 1.5 µs; counted as the half-space's closed
#: forms (0.2 µs an angle, no steps), 1e7 angles of a phase diagram passed the default limits and ran for 20 minutes.
ONSET_STEPS_PER_ANGLE = 25.0

#: What one critical angle on a layer counts against :attr:`~mdr_events.Limits.steps`: a scan of :data:`SCAN_POINTS`
#: radii on the layer's tables and the radius at the motion's end, about 14 ms (84 ms measured for the six of one
#: thickness of :func:`~mdr_events.critical_angles_against_thickness`), at the discrete step's 1.5 µs.
CRITICAL_ANGLE_STEPS = 1e4

#: The memory of one angle of the onsets on a layer at its peak (the bisections' temporaries: 181 bytes measured with
#: tracemalloc for a phase diagram in A, 198 in B, where the half-space's 160 were counted), rounded up.
ONSET_BYTES_PER_ANGLE = 256.0


def check_onset_contact(contact: Contact, what: str, d_max: float | None = None) -> tuple[Contact, float]:
    """What the slip onset on a layer takes, checked before it runs (a few branch evaluations: what the closed forms
    would refuse, without computing them): a paraboloid or power law, the paper's adhesion law, the law (13), a
    base that holds the layer tangentially, scales within double precision
    (:func:`~mdr_events.theory.scales.check_representable`: ``R = 1e300`` was a ``ZeroDivisionError``, ``1e-300`` an
    ``OverflowError``) and a contact radius at ``d_max`` within the tables.

    Parameters
    ----------
    contact : Contact
        A contact on a layer of finite thickness.
    what : str
        The function asked, named in the errors.
    d_max : float, optional
        The motion's depth (m; ``None``: the paper's 0.3 mm).

    Returns
    -------
    tuple of (Contact, float)
        The contact and ``d_max``.

    Raises
    ------
    TypeError, ValueError
        In one line, naming what is not allowed.
    """
    return contact, _onsets_of(contact).check(contact, what, d_max)


def _curved_check(contact: Contact, what: str, d_max: float | None) -> float:
    """:func:`check_onset_contact` of a paraboloid or power law: ``d_max`` checked."""
    E_star, nu, layer = _kind_checked(contact, what)
    depth = check_real("d_max", PAPER_D_MAX if d_max is None else d_max, "a finite number > 0 (m)",
                       lambda value: value > 0.0)
    check_representable(contact.parameters(depth, PAPER_V), contact.profile,
                        dataclasses.replace(contact.friction, tau0=None))
    top = _scan_top(contact, depth)
    if float(branch_depth(top, contact.indenter, E_star, nu, contact.adhesion.dgamma0, layer)) < depth:
        raise beyond_tables(depth, layer, top)
    return depth


def _kind_checked(contact: Contact, what: str) -> tuple[float, float, Layer]:
    """``(E*, ν, layer)`` of a contact whose kind the slip onset on a layer takes (:func:`has_closed_forms`); else the
    one-line error naming what it is not."""
    E_star, nu, layer = layer_material(contact)
    rate_independent(contact, f"{what} on a layer")
    if contact.friction.law != "tau0":
        raise ValueError(f"{what} under contact.friction={contact.friction!r} is not allowed on a layer; allowed: "
                         "the law 'tau0' of eq. (13)")
    return E_star, nu, check_bonded(layer)


def has_closed_forms(contact: Contact) -> bool:
    """Whether the slip onset on the contact's layer has closed forms (:func:`check_onset_contact` would take its kind:
    a paraboloid or power law, the paper's adhesion law, the law (13), a bonded base); where it has none a run's
    closed-form angles are ``nan``, as the half-space's where a friction law has none.

    Parameters
    ----------
    contact : Contact
        A contact on a layer of finite thickness.

    Returns
    -------
    bool
        ``True`` where :func:`critical_angle_on_layer` computes them.
    """
    return (indenter_kind(contact.indenter) in LAYER_ONSETS and type(contact.adhesion) is Adhesion
            and contact.friction.law == "tau0" and contact.layer.base is LayerBase.BONDED)


def check_onset_count(count: int, layer: Layer, limits: Limits | None) -> None:
    """What the slip onsets at ``count`` angles take on ``layer`` (:data:`ONSET_STEPS_PER_ANGLE` steps and
    :data:`ONSET_BYTES_PER_ANGLE` bytes each), checked against ``limits`` (``None``: the defaults); the angles may be
    counted before they are read (:func:`~mdr_events.limits.values_in`).

    Parameters
    ----------
    count : int
        The angles.
    layer : Layer
        The layer, named in the refusal.
    limits : Limits or None
        What the onsets may take.

    Raises
    ------
    ResourceLimitError
        More than ``limits`` allows.
    """
    check_limits(limits).check(f"the slip onset at {count} angles on {layer.describe()}",
                               steps=ONSET_STEPS_PER_ANGLE * count, memory=ONSET_BYTES_PER_ANGLE * count)


def onset_depths(alpha_deg: np.ndarray, contact: Contact, scenario: str, adhesion: bool, branch: str,
                 d_max: float | None, *, past_tables: bool = False, limits: Limits | None = None) -> np.ndarray:
    r"""The depths at which the springs start to slide on the contact's layer: eqs. (17)–(21) with ``K_t`` and the
    layer's branches (module docstring); :func:`mdr_events.d_crit` of a contact on a layer, its arguments checked.

    Parameters
    ----------
    alpha_deg : numpy.ndarray
        Path angles in degrees, in ``[0, 90]``.
    contact : Contact
        A paraboloid or power law under the law (13) on a layer bonded to its base (``Contact.layer``).
    scenario : {"A", "B"}
        As :func:`mdr_events.d_crit`.
    adhesion : bool
        ``False``: without adhesion (17), (20); ``True``: Heß's rule with ``Δγ0`` in and ``Δγ1`` out, (18), (21).
    branch : {"pull-off", "indentation"}
        Scenario B's branch (ignored in A).
    d_max : float or None
        The depth scenario B starts from (m; ``None``: the paper's 0.3 mm).
    past_tables : bool, default False
        ``True``: ``nan`` where the onset lies beyond the tables (``a/h > 64``), as a phase diagram of a tabulated
        profile marks its end; ``False``: refused.
    limits : Limits or None, default None
        What the curve may take (:data:`ONSET_STEPS_PER_ANGLE` steps and :data:`ONSET_BYTES_PER_ANGLE` bytes per angle;
        ``None``: the defaults), checked before it runs.

    Returns
    -------
    numpy.ndarray
        ``d_crit`` in m, the shape of ``alpha_deg``: ``+inf`` where no spring slides going in (α = 90°), ``-inf``
        where the contact comes apart first (pull-off), as :func:`mdr_events.d_crit`.

    Raises
    ------
    ValueError
        A frictionless base (no tangential stiffness), another law or indenter, an angle whose onset lies beyond
        the tables (``a/h > 64``) without ``past_tables``, more angles than ``limits`` allows (``ResourceLimitError``).
    """
    contact, depth = check_onset_contact(contact, "d_crit", d_max)
    check_onset_count(alpha_deg.size, contact.layer, limits)
    return _onsets_of(contact).onset_depths(alpha_deg, contact, scenario, adhesion, branch, depth, past_tables)


def _curved_onset_depths(alpha_deg: np.ndarray, contact: Contact, scenario: str, adhesion: bool, branch: str,
                         depth: float, past_tables: bool) -> np.ndarray:
    """:func:`onset_depths` of a paraboloid or power law, its arguments checked."""
    vertical = alpha_deg >= 90.0
    tangent = np.where(vertical, np.inf, np.tan(np.radians(np.where(vertical, 0.0, alpha_deg))))
    pulling = scenario == "B" and branch == "pull-off"
    motion = _motion(contact, scenario, branch, adhesion, depth)
    result = _onset_depths(motion, tangent.ravel(), "d_crit", past_tables).reshape(alpha_deg.shape)
    return np.where(vertical, -math.inf if pulling else math.inf, result)


def pull_off_depth(contact: Contact) -> float:
    """Scenario B's jump-off depth on the ``Δγ1`` branch of the contact's layer (the flat punch's: where its recession
    stops, ``theory.layer.punch_recession.punch_jump_off``); 0 without adhesion.

    Parameters
    ----------
    contact : Contact
        A contact whose onsets :func:`onset_depths` computes.

    Returns
    -------
    float
        The depth (m, ≤ 0).
    """
    return _onsets_of(contact).pull_off_depth(contact)


def _curved_pull_off_depth(contact: Contact) -> float:
    """:func:`pull_off_depth` of a paraboloid or power law."""
    dgamma = contact.adhesion.dgamma1
    return branch_jump_off(contact, dgamma)[0] if dgamma > 0.0 else 0.0


def critical_angle_on_layer(contact: Contact, scenario: str, adhesion: bool, final_depth: float | None,
                            d_max: float | None) -> float:
    r"""The critical path angle in degrees on the contact's layer: :func:`mdr_events.critical_angle` of a contact on
    a layer, its choices checked.

    .. math:: \tan\alpha_c = \max_\text{motion} r(a): \quad
              \text{A: } \frac{d_\mathrm{max}\,K_t(a)}{\pi a^2\tau_0} \text{ at } d_\mathrm{max}
              \text{ (if } r \text{ rises)}, \qquad \text{B: at the jump-off on } \Delta\gamma_1

    Parameters
    ----------
    contact : Contact
        As :func:`onset_depths`.
    scenario : {"A", "B", "B+"}
        As :func:`mdr_events.critical_angle`.
    adhesion : bool
        ``True``: Heß's rule with ``Δγ0`` in and ``Δγ1`` out; ``False``: without adhesion.
    final_depth : float or None
        Scenario B+ only: the depth reached (``None``: ``2 d_max``).
    d_max : float or None
        The motion's depth (m; ``None``: the paper's 0.3 mm).

    Returns
    -------
    float
        The critical angle in degrees (90 where slip always comes first: scenario B without adhesion).

    Raises
    ------
    ValueError
        As :func:`onset_depths`; ``final_depth`` not above ``d_max``.
    """
    contact, depth = check_onset_contact(contact, "critical_angle", d_max)
    return _onsets_of(contact).critical_angle(contact, scenario, adhesion, final_depth, depth)


def _curved_critical_angle(contact: Contact, scenario: str, adhesion: bool, final_depth: float | None,
                           depth: float) -> float:
    """:func:`critical_angle_on_layer` of a paraboloid or power law, ``d_max`` (``depth``) checked."""
    if scenario == "B":
        if not adhesion or contact.adhesion.dgamma1 == 0.0:
            return 90.0
        motion = _motion(contact, "B", "pull-off", True, depth)
        return float(np.degrees(np.arctan(motion.ratio.max())))
    end = depth
    if scenario == "B+":
        end = 2.0 * depth if final_depth is None else check_real(
            "final_depth", final_depth, f"a finite depth > d_max = {depth!r} m", lambda value: value > depth)
    motion = _motion(contact, "A" if scenario == "A" else "B", "indentation", adhesion, depth)
    dgamma = contact.adhesion.dgamma0 if adhesion else 0.0
    radius = float(stable_radius(contact, dgamma, np.array([end]))[0])
    last = float(motion.ratio_of(np.array([math.log(radius)]))[0])
    before = motion.ratio[motion.logs < math.log(radius)]
    return float(np.degrees(np.arctan(max(last, float(before.max(initial=last))))))


class LayerOnsets(NamedTuple):
    """One indenter kind's slip onset on a layer (:data:`LAYER_ONSETS`): what :func:`check_onset_contact`,
    :func:`onset_depths`, :func:`pull_off_depth` and :func:`critical_angle_on_layer` hand it, ``d_max`` checked."""

    #: ``(contact, what, d_max) -> d_max`` checked, before anything runs
    check: Callable[[Contact, str, float | None], float]
    #: ``(alpha_deg, contact, scenario, adhesion, branch, d_max, past_tables) -> d_crit``
    onset_depths: Callable[..., np.ndarray]
    #: ``contact -> d_j``, scenario B's jump-off depth on ``Δγ1``
    pull_off_depth: Callable[[Contact], float]
    #: ``(contact, scenario, adhesion, final_depth, d_max) -> alpha_c``, the critical angle (degrees)
    critical_angle: Callable[..., float]


def _punch_onset_depths(alpha_deg, contact, scenario, adhesion, branch, depth, past_tables):
    """The flat punch's onsets: closed forms while the face is held, its face within the tables (``past_tables``
    unread)."""
    return punch_onset_depths(alpha_deg, contact, scenario, adhesion, branch, depth)


_CURVED = LayerOnsets(_curved_check, _curved_onset_depths, _curved_pull_off_depth, _curved_critical_angle)

#: Each kind's slip onset on a layer by the indenter's type (the paraboloid and the power law share the scan of the
#: layer's branches; the flat punch's face is held, then recedes: :mod:`~mdr_events.theory.layer.punch_onset`).
#: Another type takes the curved kinds' checks, which name what they do not take.
LAYER_ONSETS: dict[type, LayerOnsets] = {
    Paraboloid: _CURVED, PowerLaw: _CURVED,
    FlatPunch: LayerOnsets(check_punch_contact, _punch_onset_depths,
                           lambda contact: punch_jump_off(contact, contact.adhesion.dgamma1)[0], punch_critical_angle)}


def _onsets_of(contact) -> LayerOnsets:
    """The slip onset of ``contact``'s kind (the curved kinds' for anything else, whose checks name it)."""
    return LAYER_ONSETS.get(indenter_kind(getattr(contact, "indenter", None)), _CURVED)


def thin_layer_onset_depth(alpha, contact: Contact):
    r"""Scenario A's onset on a thin bonded layer: ``d = τ0 h tan α / G`` (the limit ``h → 0`` of
    :func:`onset_depths`, for any indenter and adhesion; module docstring).

    Parameters
    ----------
    alpha : float or array_like
        Path angles in degrees, in ``[0, 90]``.
    contact : Contact
        Its shear modulus ``G = E/(2(1 + ν))``, ``τ0`` and the layer's thickness ``h`` (finite).

    Returns
    -------
    float or numpy.ndarray
        The depth in m (``inf`` at 90°).

    Raises
    ------
    ValueError
        A half-space (no thin limit), another law.
    """
    from mdr_events.theory.layer_tangential_symbolic import derive_tangential_model

    if not isinstance(contact, Contact) or contact.layer.is_half_space:
        raise ValueError(f"contact={shown(contact)} is not allowed; allowed: a Contact on a layer of finite "
                         "thickness (Contact.layer)")
    _kind_checked(contact, "thin_layer_onset_depth")  # (no depth: the limit is of a layer thinner than any contact)
    alpha_deg = validate_alpha(alpha)
    elastomer = contact.elastomer
    shear_modulus = elastomer.E / (2.0 * (1.0 + elastomer.nu))
    relation = derive_tangential_model()["layer_thin_onset_depth_A"].numeric
    with np.errstate(over="ignore"):
        depth = relation(np.tan(np.radians(alpha_deg)), contact.friction.tau0, shear_modulus, contact.layer.thickness)
    depth = np.where(alpha_deg >= 90.0, math.inf, depth)
    return float(depth) if np.ndim(alpha) == 0 else depth
