"""The friction laws' slip onsets and critical angles: scenario A (17), (18) at the angle ``α'`` of
``cot α' = cot α − κ``, scenario B's pull-off (20), (21) and its indentation branch; with adhesion and both parts of
the cap on a curved indenter, :mod:`~mdr_events.theory.combined_onset`'s search.
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import Profile
from mdr_events.theory import combined_onset, power_law
from mdr_events.theory.kinds import theory_of
from mdr_events.theory.power_law.arguments import check_onset_scales
from mdr_events.theory.mindlin.caps import _indenter, _tau0_per_radius, coulomb_cap_ratio
from mdr_events.validation import validate_alpha

__all__ = ["adhesive_onset_A_is_non_adhesive", "d_crit_A", "critical_angle_A", "d_crit_B", "critical_angle_B",
           "d_crit_B_indentation", "critical_angle_B_indentation"]


def adhesive_onset_A_is_non_adhesive(friction: FrictionLaw | str | None, profile: Profile | None) -> bool:
    """Whether scenario A's onset with adhesion (Heß's rule, any ``Δγ0``, ``Δγ1``) is the one without: Coulomb's law
    alone, whose tangential force is the compressed zone's, the contact without adhesion of the same path
    (``derive_adhesive_friction_model``), and any law on the flat punch, whose springs are all compressed while it is
    pressed in (its contact starts at ``d = 0`` with or without adhesion; ``flat_punch_friction_cap``).

    Parameters
    ----------
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter (``None``: the paraboloid).

    Returns
    -------
    bool
        ``True`` where the adhesive onset equals the non-adhesive one.
    """
    friction = as_friction_law(friction)
    return theory_of(profile).flat_face or (friction.uses_mu and not friction.uses_tau0)


def d_crit_A(alpha, friction: FrictionLaw | str | None, params: Parameters, profile: Profile | None = None,
             adhesion: bool = False):
    r"""Depth of slip onset in scenario A (m) for any friction law (module docstring).

    ``"tau0"``: (17) (:func:`mdr_events.theory.power_law.d_crit_A`; (18) with ``adhesion``). With Coulomb's part:
    ``nan`` (never) where ``cot α <= κ``; else (17) at the angle ``α'`` with ``cot α' = cot α − κ``, which for
    ``"coulomb"`` alone is 0 (from first contact). ``α = 90°`` never slides (``+inf``). With ``adhesion`` and Coulomb's
    part the onset is the one without where :func:`adhesive_onset_A_is_non_adhesive` (``"coulomb"`` alone, the flat
    punch); ``"tau0+coulomb"`` on a curved indenter has the first depth up to ``d_max`` where a spring's shift reaches
    its cap, the jump-in ring's edge, ``x_c`` or the turn of the grown springs
    (:mod:`~mdr_events.theory.combined_onset`; ``nan``: none by ``d_max``).

    Parameters
    ----------
    alpha : float or array_like
        Path angles in degrees, in (0, 90].
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material and ``τ0``; ``Δγ0`` is used with ``adhesion`` alone.
    profile : PowerLaw or FlatPunch, optional
        Default the paraboloid of ``params.R``.
    adhesion : bool, optional
        The onset with Heß's rule (``params.dgamma0``, ``dgamma1``) rather than without.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``: 0 from first contact, ``nan`` never, ``+inf`` at 90°.

    Notes
    -----
    With Coulomb's part the onset is the paper's (17) at the angle ``α'``:

    .. math:: \cot\alpha' = \cot\alpha - \kappa, \qquad
              d_\mathrm{crit} = \frac{\pi^2 \tau_0^2 R \tan^2\alpha'}{4 G^{*2}} \quad \text{(paraboloid)} \qquad (17)
    """
    friction = as_friction_law(friction)
    alpha_arr = validate_alpha(alpha)
    indenter = _indenter(profile, params)
    check_onset_scales(params, indenter, adhesion, friction)
    if adhesion and coulomb_cap_ratio(friction, params) == 0.0 and friction.uses_tau0:
        return power_law.d_crit_A(alpha, indenter, params, adhesion=True)
    if adhesion and not adhesive_onset_A_is_non_adhesive(friction, indenter):  # both parts on a curved indenter
        return _onset_output(_combined_onset(alpha_arr, friction, params, indenter), alpha_arr)
    tau0_law = params if friction.uses_tau0 else params.replace(tau0=0.0)
    kappa = coulomb_cap_ratio(friction, params)
    if kappa == 0.0:
        if friction.uses_tau0:
            return power_law.d_crit_A(alpha, indenter, params, adhesion=False)
        # no cap at all (μ = 0): every spring slides from first contact
        return _onset_output(np.where(alpha_arr >= 90.0, np.inf, 0.0), alpha_arr)
    vertical = alpha_arr >= 90.0
    effective, slides = _effective_angle(alpha_arr, kappa)  # (α = 0: cot α = +inf, sliding from first contact)
    if tau0_law.tau0 == 0.0:
        depth = np.zeros_like(effective)
    else:
        depth = np.asarray(power_law.d_crit_A(effective, indenter, tau0_law, adhesion=False), dtype=float)
    return _onset_output(np.where(vertical, np.inf, np.where(slides, depth, np.nan)), alpha_arr)


def _combined_onset(alpha_arr: np.ndarray, friction: FrictionLaw, params: Parameters, indenter: Profile) -> np.ndarray:
    """Both parts with adhesion on a curved indenter (:func:`~mdr_events.theory.combined_onset.d_crit_A`): from first
    contact along the surface (0°), never at 90° (``+inf``), ``nan`` where no onset comes by ``d_max``."""
    inside = (alpha_arr > 0.0) & (alpha_arr < 90.0)
    depth = np.where(alpha_arr >= 90.0, np.inf, 0.0)
    if np.any(inside):
        depth[inside] = combined_onset.d_crit_A(alpha_arr[inside], friction, params, indenter)
    return depth


def _combined_onset_B(alpha_arr: np.ndarray, friction: FrictionLaw, params: Parameters, indenter: Profile) -> np.ndarray:
    """Both parts with adhesion on a curved indenter, B's indentation branch
    (:func:`~mdr_events.theory.combined_onset.d_crit_B_indentation`): at once along the surface (0°), never at 90°
    (``+inf``)."""
    inside = (alpha_arr > 0.0) & (alpha_arr < 90.0)
    depth = np.where(alpha_arr >= 90.0, np.inf, params.d_max)
    if np.any(inside):
        depth[inside] = combined_onset.d_crit_B_indentation(alpha_arr[inside], friction, params, indenter)
    return depth


def _onset_output(values: np.ndarray, alpha: np.ndarray):
    return float(values) if np.ndim(alpha) == 0 else values


def critical_angle_A(friction: FrictionLaw | str | None, params: Parameters, profile: Profile | None = None,
                     adhesion: bool = False) -> float:
    r"""Scenario A's critical angle (degrees): below it the springs slide before ``d_max``.

    ``"tau0"``: ``tan α_c = d_max / ū(a(d_max))``; ``"coulomb"``: the angle of friction, ``tan α_c = 1/κ = G*/(μ E*)``,
    at any depth; ``"tau0+coulomb"``: ``cot α_c = cot α_c(τ0) + κ``. With ``adhesion`` as for :func:`d_crit_A`: the
    angle without where :func:`adhesive_onset_A_is_non_adhesive`; for ``"tau0+coulomb"`` on a curved indenter the
    angle below which :mod:`~mdr_events.theory.combined_onset` finds an onset by ``d_max``.

    .. math:: \cot\alpha_c = \cot\alpha_c(\tau_0) + \kappa, \qquad
              \tan\alpha_c(\tau_0) = \frac{d_\mathrm{max}}{\bar u(a(d_\mathrm{max}))} \qquad (17), (18)

    Parameters
    ----------
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0``, ``d_max`` and ``Δγ0``.
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    adhesion : bool, default False
        The angle with Heß's rule (the ``Δγ0`` branch (9)) rather than without.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    friction = as_friction_law(friction)
    indenter = _indenter(profile, params)
    check_onset_scales(params, indenter, adhesion, friction)
    if adhesion and coulomb_cap_ratio(friction, params) == 0.0 and friction.uses_tau0:
        return float(power_law.critical_angle_A(indenter, params, adhesion=True))
    if adhesion and not adhesive_onset_A_is_non_adhesive(friction, indenter):  # both parts on a curved indenter
        return combined_onset.critical_angle_A(friction, params, indenter)
    tau0_angle = power_law.critical_angle_A(indenter, params, adhesion=False) if friction.uses_tau0 else 90.0
    return _with_coulomb(tau0_angle, coulomb_cap_ratio(friction, params))


def _with_coulomb(tau0_angle: float, kappa: float) -> float:
    """The angle (degrees) of ``cot α = cot α(τ0) + κ`` (``α(τ0) = 90°``: no ``τ0`` part, the angle of friction)."""
    cot = 1.0 / math.tan(math.radians(tau0_angle)) if 0.0 < tau0_angle < 90.0 else (math.inf if tau0_angle <= 0.0
                                                                                     else 0.0)
    return float(math.degrees(math.atan2(1.0, cot + kappa)))


def _effective_angle(alpha_arr: np.ndarray, kappa: float) -> tuple[np.ndarray, np.ndarray]:
    """``α'`` of ``cot α' = cot α − κ`` (degrees) and where it exists (``cot α > κ``, ``α < 90°``)."""
    cot, vertical = _cotangent(alpha_arr)
    exists = (cot > kappa) & ~vertical
    return np.rad2deg(np.arctan2(1.0, np.where(exists, cot - kappa, 1.0))), exists


def d_crit_B(alpha, friction: FrictionLaw | str | None, params: Parameters, profile: Profile | None = None,
             adhesion: bool = False):
    r"""Depth of slip onset in scenario B's pull-off (m; module docstring): (20)
    (:func:`mdr_events.theory.power_law.d_crit_B`) where the law has ``τ0``'s part, ``d_max`` (at once) for Coulomb's
    alone; ``α = 90°`` never slides (``-inf``). With ``adhesion`` (the ``Δγ0``, ``Δγ1`` branches) the edge, in tension,
    holds ``K a`` alone and every spring the same shift: (21) of ``τ0`` alone, free of ``μ``
    (``symbolic.adhesive_onset_excess_B``); Coulomb's law alone still slides at once.

    The flat punch has no spring at zero compression: every cap is ``K a + κ d`` against the shift
    ``(d_max − d) cot α``, so ``d = (d_max cot α − K a)/(cot α + κ)``, ``-inf`` below the surface (it comes off
    first).

    .. math:: \frac{d_\mathrm{max} - d}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*} \qquad (20)

    Parameters
    ----------
    alpha : float or array_like
        Path angles in degrees, in [0, 90].
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``d_max``.
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    adhesion : bool, default False
        The onset with Heß's rule (``params.dgamma0``, ``dgamma1``) rather than without.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``-inf`` where it comes off first or at 90°.
    """
    friction = as_friction_law(friction)
    alpha_arr = validate_alpha(alpha)
    indenter = _indenter(profile, params)
    check_onset_scales(params, indenter, adhesion, friction)
    own = theory_of(indenter).friction_forms
    if own is not None:
        depth = own.d_crit_B(alpha_arr, _cotangent(alpha_arr)[0], _tau0_per_radius(friction, params),
                             coulomb_cap_ratio(friction, params), params, indenter, bool(adhesion and friction.uses_tau0))
        return _onset_output(depth, alpha_arr)
    if friction.uses_tau0:
        return power_law.d_crit_B(alpha, indenter, params, adhesion=adhesion)
    return _onset_output(np.where(alpha_arr >= 90.0, -np.inf, params.d_max), alpha_arr)


def _cotangent(alpha_arr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``cot α`` (``+inf`` at 0°; 1 in place of 90°) and where ``α >= 90°``."""
    vertical = alpha_arr >= 90.0
    with np.errstate(divide="ignore"):
        return 1.0 / np.tan(np.deg2rad(np.where(vertical, 45.0, alpha_arr))), vertical


def critical_angle_B(friction: FrictionLaw | str | None, params: Parameters, profile: Profile | None = None,
                     adhesion: bool = False) -> float:
    """Scenario B's critical angle (degrees): without adhesion a contact that shrinks to nothing always slides first
    (90°); the flat punch comes off whole at the surface, where its edge holds only ``K a``: ``d_max cot α_c = K a``,
    as for ``τ0`` alone (Coulomb's part is zero at ``d = 0``). With ``adhesion`` the contact comes off at the jump-off,
    its edge holding ``K a`` alone: ``τ0``'s (21) where the law has ``τ0``'s part (:func:`d_crit_B`), 90° for Coulomb's
    alone (it slides at once).

    Parameters
    ----------
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``d_max``.
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    adhesion : bool, default False
        The angle with Heß's rule (``params.dgamma0``, ``dgamma1``) rather than without.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    friction = as_friction_law(friction)
    indenter = _indenter(profile, params)
    check_onset_scales(params, indenter, adhesion, friction)
    if friction.uses_tau0 and (adhesion or theory_of(indenter).flat_face):
        return power_law.critical_angle_B(indenter, params, adhesion=adhesion)
    return 90.0


def d_crit_B_indentation(alpha, friction: FrictionLaw | str | None, params: Parameters,
                         profile: Profile | None = None, adhesion: bool = False):
    r"""Depth of slip onset on scenario B's indentation branch (m; module docstring): without adhesion ``+inf``
    (never) where ``cot α <= κ``, else (20)'s "+" branch at ``α'`` (``cot α' = cot α − κ``), ``d_max`` (at once) for
    Coulomb's law alone. The flat punch: every cap ``K a + κ d`` against ``(d − d_max) cot α``,
    ``d = (K a + d_max cot α)/(cot α − κ)``, with adhesion or without. With ``adhesion`` on a curved indenter: (21)'s
    "+" branch for ``τ0`` alone, ``d_max`` for Coulomb's alone, and for both parts the first depth a spring reaches
    its cap about the contact of ``d_max`` (:func:`~mdr_events.theory.combined_onset.d_crit_B_indentation`: ``nan``
    where none does within its reach).

    .. math:: \frac{d - d_\mathrm{max}}{\tan\alpha'} = \frac{\pi a \tau_0}{2 G^*}, \qquad
              \cot\alpha' = \cot\alpha - \kappa \qquad (20)

    Parameters
    ----------
    alpha : float or array_like
        Path angles in degrees, in [0, 90].
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``d_max``.
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    adhesion : bool, default False
        The onset with Heß's rule (the ``Δγ0`` branch) rather than without.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``+inf`` where it never slides (``nan``: not known).
    """
    friction = as_friction_law(friction)
    alpha_arr = validate_alpha(alpha)
    indenter = _indenter(profile, params)
    check_onset_scales(params, indenter, adhesion, friction)
    kappa = coulomb_cap_ratio(friction, params)
    own = theory_of(indenter).friction_forms
    if own is not None:  # (with adhesion or without)
        depth = own.d_crit_B_indentation(alpha_arr, _cotangent(alpha_arr)[0], _tau0_per_radius(friction, params),
                                         kappa, params, indenter)
        return _onset_output(depth, alpha_arr)
    if adhesion and friction.uses_tau0:
        if kappa == 0.0:
            return power_law.d_crit_B_indentation(alpha, indenter, params, adhesion=True)
        return _onset_output(_combined_onset_B(alpha_arr, friction, params, indenter), alpha_arr)
    if kappa == 0.0 and friction.uses_tau0:
        return power_law.d_crit_B_indentation(alpha, indenter, params, adhesion=False)
    effective, exists = _effective_angle(alpha_arr, kappa)
    if friction.uses_tau0:
        depth = np.asarray(power_law.d_crit_B_indentation(effective, indenter, params, adhesion=False), dtype=float)
    else:
        depth = np.full(alpha_arr.shape, params.d_max)
    return _onset_output(np.where(exists, depth, np.inf), alpha_arr)


def critical_angle_B_indentation(friction: FrictionLaw | str | None, params: Parameters,
                                 profile: Profile | None = None, final_depth: float | None = None) -> float:
    """The "+" branch's critical angle without adhesion (degrees): slip exactly at ``final_depth`` (default
    ``2 d_max``); ``cot α_c = cot α_c(τ0) + κ`` (the angle of friction for Coulomb's law alone); the flat punch's
    ``cot α_c = (K a + κ F)/(F − d_max)`` at the final depth ``F``.

    Parameters
    ----------
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``d_max``.
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    final_depth : float, optional
        The deepest point (m), > ``d_max``; default ``2 d_max``.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    friction = as_friction_law(friction)
    indenter = _indenter(profile, params)
    check_onset_scales(params, indenter, False, friction)
    kappa = coulomb_cap_ratio(friction, params)
    own = theory_of(indenter).friction_forms
    if own is not None:
        return own.critical_angle_B_indentation(_tau0_per_radius(friction, params), kappa, params, indenter,
                                                final_depth)
    tau0_angle = power_law.critical_angle_B_indentation(indenter, params, adhesion=False, final_depth=final_depth) \
        if friction.uses_tau0 else 90.0
    return _with_coulomb(tau0_angle, kappa)

