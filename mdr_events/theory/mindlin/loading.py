"""Tangential loading at a constant depth under the friction laws: the virgin curve ``F₀`` (``τ0``'s part over the
contact, Cattaneo–Mindlin's over the compressed zone), full slip, Masing's rules with memory along any tangential path
and the energy a closed loop dissipates.
"""

from __future__ import annotations

import numpy as np
from scipy import integrate

from mdr_events.contact.friction import FrictionLaw
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import Profile
from mdr_events.theory import power_law, symbolic
from mdr_events.theory.kinds import theory_of
from mdr_events.theory.mindlin.caps import _checked, _contact_radius, _radius, _tau0_per_radius, coulomb_cap_ratio
from mdr_events.validation import real_array, shown

__all__ = ["full_slip_shift", "full_slip_force", "virgin_force", "tangential_force", "loop_energy"]


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
        raise ValueError(f"shift={shown(shift)} is not allowed; allowed: real numbers, not nan (m)")
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

