"""The friction laws in closed form: tangential loading at a constant depth (Cattaneo–Mindlin, Masing's loops) and
the slip onset of proportional loading (scenario A).

At a constant depth ``d`` without adhesion every spring in contact keeps its cap (the friction law's,
:mod:`mdr_events.contact.friction`): ``ū(ξ) = K a + κ (d − g(ξ))`` with ``K a`` the part of ``τ0`` (13) and
``κ = μ E*/G*`` Coulomb's (:func:`coulomb_cap_ratio`). Each spring is then a play operator of its own cap,
and, from rest, a tangential shift ``u_x`` of the indenter gives the *virgin curve*

    ``F₀(u_x) = 2G* a min(u_x, K a) + μ (F_N(d) − F_N(d − max(u_x − K a, 0)/κ))``

(:func:`virgin_force`; the Coulomb part is Cattaneo–Mindlin's, in the form of Jäger and Ciavarella, derived
in :func:`mdr_events.theory.symbolic.derive_friction_model`; the two parts add because the Coulomb caps all
sit above ``K a``). Any back-and-forth motion from rest then follows Masing's rules with memory
(:func:`tangential_force`): after a reversal at ``(x_r, F_r)`` the force is ``F_r + 2 F₀((x − x_r)/2)``
until the branch reaches the point its predecessor started from, where that one resumes; the first
unloading from ``(X, F₀(X))`` runs to ``(−X, −F₀(X))`` and rejoins the virgin curve (Mindlin & Deresiewicz
1953; the loops of a fretting contact).

With adhesion (Heß's rule, (8)–(9)) the springs beyond ``x_c``, where ``g(x_c) = d``, are in tension and hold no
Coulomb shift: the cap is ``K a + κ max(d − g(ξ), 0)``, with ``a >= x_c`` the contact radius that the history pins
between the branches (the ``radius`` argument; default the ``Δγ0`` branch's, indented to ``d``). The virgin curve is
then ``2G* a min(u_x, K a) + μ (F_N^H(d) − F_N^H(d − max(u_x − K a, 0)/κ))`` with ``F_N^H`` the force of the
compressed zone alone, the non-adhesive one of the depth (derived in
:func:`mdr_events.theory.symbolic.derive_adhesive_friction_model`): Coulomb's part does not depend on ``Δγ`` at all,
and full slip is ``τ0 π a² + μ F_N^H(d)``, not ``μ F_N``, which the tensile springs lower.

Along scenario A's path (14), ``x = d / tan α`` from first contact without adhesion, a spring attached at depth
``d_ξ`` holds the shift ``(d − d_ξ)/tan α`` against the cap ``K a + κ (d − d_ξ)``: the Coulomb part grows with the
shift, so where ``cot α <= κ`` no spring ever slides, and where ``cot α > κ`` the centre's spring slides first, when
``(cot α − κ) d = K a(d)``: the paper's (17) at the angle ``α'`` of ``cot α' = cot α − κ`` (:func:`d_crit_A`,
:func:`critical_angle_A`). Coulomb's law alone (``K = 0``) then slides from first contact (the angle of friction
``tan α = 1/κ = G*/(μ E*)``).

Scenario B without adhesion (in vertically to ``d_max``, every spring anchored at ``x = 0``): out at ``α`` all
springs share the shift ``(d_max − d)/tan α``, and the edge's cap is the smallest, ``K a`` (its compression is
zero): the onset is the paper's (20) for any ``τ0`` part, at once (``d_max``) for Coulomb's alone
(:func:`d_crit_B`). Further in at ``α`` the old edge's cap is ``K a + κ (d − d_max)`` against the shift
``(d − d_max)/tan α``: (20)'s "+" branch at ``α'`` (:func:`d_crit_B_indentation`).

One closed form per function for each friction law (virgin curves, Masing's loops, full slip, the onsets of scenarios
A and B), each with its numpydoc sections; the flat punch's own (every spring compressed by ``d`` alike: one play
operator, :func:`flat_punch_force`) are :mod:`mdr_events.theory.flat_punch`'s, filed by
:func:`mdr_events.theory.kinds.theory_of` (``friction_forms``).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import integrate

from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import PowerLaw, Profile
from mdr_events.theory import combined_onset, power_law, symbolic
from mdr_events.theory.flat_punch import tangential_force as flat_punch_force
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import check_real, real_array, validate_alpha

__all__ = ["coulomb_cap_ratio", "full_slip_shift", "full_slip_force", "virgin_force", "tangential_force", "loop_energy",
           "flat_punch_force", "adhesive_onset_A_is_non_adhesive",
           "d_crit_A", "critical_angle_A", "d_crit_B", "critical_angle_B", "d_crit_B_indentation",
           "critical_angle_B_indentation"]


def coulomb_cap_ratio(friction: FrictionLaw, params: Parameters) -> float:
    r"""``κ = μ E*/G*``: Coulomb's cap is ``κ`` times the spring's compression (0 without Coulomb's part).

    .. math:: \bar u(\xi) = \kappa \max(d - g(\xi), 0), \qquad \kappa = \mu \frac{E^*}{G^*}

    Parameters
    ----------
    friction : FrictionLaw or str
        The friction law; its ``μ`` (0 for ``"tau0"``).
    params : Parameters
        The material (``E*``, ``G*``).

    Returns
    -------
    float
        ``κ`` (1).
    """
    friction = as_friction_law(friction)
    return float(symbolic.relation("coulomb_critical_shift").numeric(1.0, friction.coulomb_mu, params.E_star,
                                                                     params.G_star))


def _checked(depth, friction, params: Parameters, profile) -> tuple[float, FrictionLaw, Profile]:
    depth = check_real("depth", depth, "a finite number > 0 (m)", lambda value: value > 0.0)
    return depth, as_friction_law(friction), _indenter(profile, params)


def _contact_radius(depth: float, params: Parameters, profile: Profile, radius) -> float:
    """The radius ``a`` of the contact at ``depth`` (m): ``radius`` checked, or without it the radius indented to
    ``depth`` (the ``Δγ0`` branch (9); without adhesion the compressed zone's ``x_c``). A radius below ``x_c`` (where
    ``g(x_c) = d``) is no contact at that depth: every spring under the indenter is in contact."""
    zone = _radius(depth, profile)
    if radius is None:
        if params.dgamma0 == 0.0:
            return zone
        return float(theory_of(profile).branch_radius(depth, profile, params, params.dgamma0))
    allowed = f"a finite radius >= the compressed zone's x_c = {zone!r} m at depth {depth!r} m, or None"
    return check_real("radius", radius, allowed, lambda value: value >= zone * (1.0 - _RADIUS_SHARE))


#: A given contact radius may lie this share below the compressed zone's ``x_c`` (the rounding of a radius found
#: by a root of (9) at a depth whose zone it equals, without adhesion).
_RADIUS_SHARE = 1e-12


def _indenter(profile: Profile | None, params: Parameters) -> Profile:
    """``profile``, checked; ``None`` is the paraboloid of ``params.R``."""
    return PowerLaw.paraboloid(params.R) if profile is None else power_law.check_profile(profile)


def _tau0_per_radius(friction: FrictionLaw, params: Parameters) -> float:
    """``K`` of the law's ``τ0`` part, ``ū = K a`` (13); 0 without it."""
    return power_law.cap_per_radius(params) if friction.uses_tau0 else 0.0


def _radius(depth: float, profile: Profile) -> float:
    """The contact radius at ``depth`` (> 0) without adhesion (the flat punch's own)."""
    return float(theory_of(profile).branch_radius(depth, profile, _NO_ADHESION, 0.0))


#: The non-adhesive radius needs no material (any valid parameters serve :func:`power_law.contact_radius`).
_NO_ADHESION = Parameters(E=1.0, nu=0.0, R=1.0, tau0=0.0, dgamma0=0.0, dgamma1=0.0, d_max=1.0, v=1.0)


def full_slip_shift(depth: float, friction: FrictionLaw | str | None, params: Parameters,
                    profile: Profile | None = None, radius: float | None = None) -> float:
    """The shift ``u_x`` from rest at which every spring slides: the centre's cap ``K a + κ d`` (m)
    (``adhesive_full_slip_shift``; ``radius`` as for :func:`virgin_force`).

    Parameters
    ----------
    depth : float
        The indentation depth ``d`` (m, > 0).
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0`` (the default radius).
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    radius : float, optional
        The contact radius ``a`` (m, at least the compressed zone's ``x_c``); default the ``Δγ0`` branch's at
        ``d``, ``x_c`` without adhesion.

    Returns
    -------
    float
        The shift ``K a + κ d`` (m).
    """
    depth, friction, profile = _checked(depth, friction, params, profile)
    contact = _contact_radius(depth, params, profile, radius)
    return _tau0_per_radius(friction, params) * contact + coulomb_cap_ratio(friction, params) * depth


def full_slip_force(depth: float, friction: FrictionLaw | str | None, params: Parameters,
                    profile: Profile | None = None, radius: float | None = None) -> float:
    r"""The force of full slip, ``τ0 π a² + μ F_N^H(d)`` (N; either part as the law has it; ``F_N^H`` the compressed
    springs' push, ``F_N`` itself without adhesion: ``adhesive_full_slip_force``; ``radius`` as for
    :func:`virgin_force`).

    .. math:: F_x = \tau_0 \pi a^2 + \mu F_N^H(d)

    Parameters
    ----------
    depth : float
        The indentation depth ``d`` (m, > 0).
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0`` (the default radius).
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    radius : float, optional
        The contact radius ``a`` (m, at least the compressed zone's ``x_c``); default the ``Δγ0`` branch's at
        ``d``, ``x_c`` without adhesion.

    Returns
    -------
    float
        The force of full slip (N, >= 0).
    """
    return float(virgin_force(np.inf, depth, friction, params, profile, radius))


def _virgin_curve(depth: float, friction: FrictionLaw, params: Parameters, profile: Profile, contact=None):
    """``F₀`` as a function of arrays of shifts (checked arguments): the ``τ0`` part over the contact of radius
    ``contact`` (:func:`_contact_radius`), Coulomb's over the compressed zone ``x_c``."""
    radius = _radius(depth, profile)  # x_c: every spring of a contact without adhesion
    contact = _contact_radius(depth, params, profile, contact)
    cap = _tau0_per_radius(friction, params) * contact
    kappa = coulomb_cap_ratio(friction, params)
    coulomb = _coulomb_part(depth, friction, params, profile, radius)

    def curve(values: np.ndarray) -> np.ndarray:
        magnitude = np.abs(values)
        force = 2.0 * params.G_star * contact * np.minimum(magnitude, cap)
        if kappa > 0.0:
            sliding = np.minimum(np.maximum(magnitude - cap, 0.0), kappa * depth)  # the centre's cap: full slip
            force = force + coulomb(sliding, kappa)
        return np.sign(values) * force

    return curve


def _coulomb_part(depth: float, friction: FrictionLaw, params: Parameters, profile: Profile, radius: float):
    """Coulomb's part of the virgin curve as a function of the shift beyond ``K a`` and ``κ``: Cattaneo–Mindlin's over
    the compressed zone ``x_c = radius``, ``μ F_N`` from full slip on, or the kind's own (the flat punch's)."""
    own = theory_of(profile).friction_forms
    if own is not None:
        return lambda sliding, kappa: own.coulomb_force(sliding, params, radius)
    full = friction.coulomb_mu * float(power_law.normal_force(depth, radius, profile, params))

    def cattaneo_mindlin(sliding: np.ndarray, kappa: float) -> np.ndarray:
        with np.errstate(invalid="ignore"):
            coulomb = symbolic.relation("cattaneo_mindlin_force").numeric(
                sliding, depth, friction.coulomb_mu, profile.c, profile.n, params.E_star, params.G_star)
        return np.where(sliding >= kappa * depth, full, coulomb)

    return cattaneo_mindlin


def virgin_force(shift, depth: float, friction: FrictionLaw | str | None, params: Parameters,
                 profile: Profile | None = None, radius: float | None = None):
    """``F₀``: the tangential force (N) at a shift ``u_x`` of the indenter from rest (m, any sign: ``F₀`` is odd),
    at the constant depth ``d`` (module docstring; with adhesion ``adhesive_virgin_force``: the ``τ0`` part over the
    contact of radius ``a``, Coulomb's part Cattaneo–Mindlin's of the compressed zone ``x_c``, free of ``Δγ``).

    Parameters
    ----------
    shift : array_like
        The tangential shift from the position at which the springs were at rest (m).
    depth : float
        The indentation depth (m, > 0).
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0`` (the default radius).
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    radius : float, optional
        The contact radius ``a`` (m, at least the compressed zone's ``x_c``): an adhesive contact's radius is pinned
        by its history between the branches (9). Default: the ``Δγ0`` branch's at ``d`` (indented to ``d``), ``x_c``
        without adhesion.

    Returns
    -------
    float or numpy.ndarray
        ``F₀`` (N), odd in the shift, the shape of ``shift``.

    Raises
    ------
    ValueError
        A shift that is ``nan``, a depth not > 0, or a radius below ``x_c``.
    """
    depth, friction, profile = _checked(depth, friction, params, profile)
    values = real_array("shift", shift, "real numbers (m)")
    if np.any(np.isnan(values)):
        raise ValueError(f"shift={shift!r} is not allowed; allowed: real numbers, not nan (m)")
    force = _virgin_curve(depth, friction, params, profile, radius)(values)
    return float(force) if np.ndim(shift) == 0 else force


def tangential_force(x, depth: float, friction: FrictionLaw | str | None, params: Parameters,
                     profile: Profile | None = None, radius: float | None = None) -> np.ndarray:
    """The tangential force (N) along a tangential path at a constant depth, springs at rest at ``x[0]``.

    Masing's rules with memory (module docstring) on the samples ``x`` (m): a reversal is where the motion
    turns, so the samples should hold the path's turning points (a path sampled between them turns early).

    Parameters
    ----------
    x : array_like
        The indenter's tangential position at successive instants (1-D, m).
    depth : float
        The indentation depth ``d`` (m, > 0).
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0`` (the default radius).
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    radius : float, optional
        The contact radius ``a`` (m, at least the compressed zone's ``x_c``); default the ``Δγ0`` branch's at
        ``d``, ``x_c`` without adhesion.

    Returns
    -------
    numpy.ndarray
        ``F_x`` (N) at each sample, the shape of ``x`` (0 at the first).

    Raises
    ------
    ValueError
        ``x`` empty, not 1-D or not finite; a depth not > 0, or a radius below ``x_c``.
    """
    positions = real_array("x", x, "a 1-D array of finite tangential positions (m)")
    if positions.ndim != 1 or positions.size == 0 or not np.all(np.isfinite(positions)):
        bad = f" ({np.count_nonzero(~np.isfinite(positions))} not finite: nan after a simulation's end?)" \
            if positions.size and not np.all(np.isfinite(positions)) else ""
        raise ValueError(f"x of shape {positions.shape}{bad} is not allowed; allowed: a non-empty 1-D array of finite "
                         "tangential positions (m)")
    depth, friction, profile = _checked(depth, friction, params, profile)
    curve = _virgin_curve(depth, friction, params, profile, radius)
    shifts = positions - positions[0]
    force = np.empty_like(shifts)
    turns: list[tuple[float, float]] = []  # reversal points (shift, force), the last the current branch's start
    direction = 0.0
    for k, shift in enumerate(shifts):
        step = shift - shifts[k - 1] if k else 0.0
        if step != 0.0 and direction != 0.0 and np.sign(step) != direction:
            turns.append((float(shifts[k - 1]), float(force[k - 1])))
        if step != 0.0:
            direction = float(np.sign(step))
        while turns:  # memory: a branch that passes its predecessor's start closes that loop
            start = turns[-1][0]
            target = turns[-2][0] if len(turns) > 1 else -start  # the first branch rejoins the virgin curve at −x_r
            if (shift - start) * (target - start) > 0.0 and abs(shift - start) > abs(target - start):
                del turns[-2:]  # (the first branch's only start: back on the virgin curve)
                continue
            break
        if turns:
            start, start_force = turns[-1]
            force[k] = start_force + 2.0 * float(curve(np.array(0.5 * (shift - start))))
        else:
            force[k] = float(curve(np.array(shift)))
    return force


def loop_energy(amplitude, depth: float, friction: FrictionLaw | str | None, params: Parameters,
                profile: Profile | None = None, radius: float | None = None):
    """Energy dissipated per cycle ``x: −X → X → −X`` at a constant depth once the loop is closed (J; Mindlin &
    Deresiewicz 1953 for the sphere's Coulomb law):

        ``W = 8 ∫_0^X F₀(u) du − 4 X F₀(X)``,

    the area between Masing's branches ``−F₀(X) + 2 F₀((x + X)/2)`` (moving towards ``+X``, above) and
    ``F₀(X) − 2 F₀((X − x)/2)`` (moving back, below), with the virgin
    curve ``F₀`` of :func:`virgin_force` (integrated between its kinks by adaptive quadrature, to 1e-12). For ``τ0``
    alone it is the parallelogram's ``4 π a² τ0 (X − ū)`` (:func:`mdr_events.fretting_dissipated_energy`);
    a loop within the stick range dissipates nothing under ``τ0``, and always a little under Coulomb's law (whose
    edge springs hold no shift).

    Parameters
    ----------
    amplitude : float or array_like
        The loop's half-width ``X`` (m, >= 0).
    depth : float
        The indentation depth ``d`` (m, > 0).
    friction : FrictionLaw or str or None
        The friction law (``None``: the paper's ``"tau0"``).
    params : Parameters
        The material, ``τ0`` and ``Δγ0`` (the default radius).
    profile : PowerLaw or FlatPunch, optional
        The indenter; default the paraboloid of ``params.R``.
    radius : float, optional
        The contact radius ``a`` (m, at least the compressed zone's ``x_c``); default the ``Δγ0`` branch's at
        ``d``, ``x_c`` without adhesion.

    Returns
    -------
    float or numpy.ndarray
        ``W`` (J, >= 0), the shape of ``amplitude``.

    Raises
    ------
    ValueError
        An amplitude that is negative or not finite.
    """
    depth, friction, profile = _checked(depth, friction, params, profile)
    values = real_array("amplitude", amplitude, "finite numbers >= 0 (m)")
    if not np.all(np.isfinite(values) & (values >= 0.0)):
        raise ValueError(f"amplitude={amplitude!r} is not allowed; allowed: finite numbers >= 0 (m)")
    curve = _virgin_curve(depth, friction, params, profile, radius)
    kinks = [full_slip_shift(depth, friction, params, profile, radius)]
    if friction.uses_tau0 and friction.uses_mu:
        kinks.append(_tau0_per_radius(friction, params) * _contact_radius(depth, params, profile, radius))

    def energy(X: float) -> float:
        if X == 0.0:
            return 0.0
        points = sorted(k for k in kinks if 0.0 < k < X)
        area, _ = integrate.quad(lambda u: float(curve(np.array(u))), 0.0, X, points=points or None, limit=200,
                                 epsabs=0.0, epsrel=1e-13)
        return 8.0 * area - 4.0 * X * float(curve(np.array(X)))

    out = np.array([energy(float(X)) for X in values.ravel()]).reshape(values.shape)
    return float(out) if np.ndim(amplitude) == 0 else out



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
    kappa = coulomb_cap_ratio(friction, params)
    own = theory_of(indenter).friction_forms
    if own is not None:
        return own.critical_angle_B_indentation(_tau0_per_radius(friction, params), kappa, params, indenter,
                                                final_depth)
    tau0_angle = power_law.critical_angle_B_indentation(indenter, params, adhesion=False, final_depth=final_depth) \
        if friction.uses_tau0 else 90.0
    return _with_coulomb(tau0_angle, kappa)
