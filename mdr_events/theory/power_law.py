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
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, PowerLaw, Profile
from mdr_events.theory import symbolic
from mdr_events.theory.forms import ClosedForms
from mdr_events.validation import SCALE_MAX, check_flag, check_real, validate_alpha

__all__ = ["equivalent_profile", "branch_depth", "normal_force", "branch_normal_force", "contact_radius",
           "jump_in_radius", "jump_off", "pull_off_force", "d_crit_A", "critical_angle_A", "d_crit_B",
           "critical_angle_B", "d_crit_B_indentation", "critical_angle_B_indentation", "convex_root", "branch_root",
           "with_radius_at", "prefactor", "hess_prefactor", "check_profile", "CLOSED_FORMS",
           "ADHESIVE_MIN_EXPONENT", "ROOT_RTOL"]

#: With adhesion a power law needs ``n`` above this: below it ``√a`` outgrows ``aⁿ`` and no contact is stable.
ADHESIVE_MIN_EXPONENT = 0.5
#: Relative accuracy of :func:`convex_root` (a few ulp).
ROOT_RTOL = 4 * float(np.finfo(float).eps)
#: Doublings :func:`convex_root` takes at most to get right of the root from its guess (2^2100 > 1e600).
ROOT_MAX_DOUBLINGS = 2100
#: Newton steps :func:`convex_root` takes at most (it converges quadratically once close; from its upper
#: bound, monotonically).
ROOT_MAX_ITERATIONS = 200


def _rel(key: str):
    return symbolic.relation(key)


def check_profile(profile) -> Profile:
    """``profile`` if it is a :class:`PowerLaw` or a :class:`FlatPunch`; else ``TypeError`` naming it.

    Parameters
    ----------
    profile : object
        The indenter to check.

    Returns
    -------
    PowerLaw or FlatPunch
        ``profile`` itself.

    Raises
    ------
    TypeError
        Any other type (the paraboloid and a table have their own modules).
    """
    if not isinstance(profile, (PowerLaw, FlatPunch)):  # (what this module takes; each kind's forms: _forms)
        raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed; allowed: a PowerLaw or "
                        "a FlatPunch (mdr_events.contact.indenters)")
    return profile


def check_work(work_of_adhesion) -> float:
    """``work_of_adhesion`` as a float if it is a number from 0 to ``SCALE_MAX`` (J/m²: its square stays finite);
    else ``ValueError`` naming it (a negative one gave ``nan`` and a positive pull-off force)."""
    return check_real("work_of_adhesion", work_of_adhesion, f"a finite number >= 0 (J/m²), at most {SCALE_MAX:.2g}",
                      lambda value: 0.0 <= value <= SCALE_MAX)


_check_work = check_work


def _check_adhesive(profile: PowerLaw, work_of_adhesion: float) -> None:
    if work_of_adhesion > 0.0 and not profile.n > ADHESIVE_MIN_EXPONENT:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed with adhesion (work of adhesion "
                         f"{work_of_adhesion!r} J/m²); allowed: n > {ADHESIVE_MIN_EXPONENT:g} (below it no "
                         "adhesive contact is stable)")


def _power_law_only(profile, what: str) -> PowerLaw:
    if not isinstance(check_profile(profile), PowerLaw):
        raise TypeError(f"profile={profile!r} is not allowed for {what}; allowed: a PowerLaw (a flat punch keeps "
                        "its radius while in contact)")
    return profile


def as_output(values: np.ndarray, like) -> np.ndarray | float:
    """``values`` as a float where ``like`` is a scalar, else as they are."""
    return float(values) if np.ndim(like) == 0 else values


def path_angles(alpha, adhesion) -> tuple[np.ndarray, np.ndarray]:
    """``adhesion`` checked as a flag, ``alpha`` as path angles (degrees, :func:`validate_alpha`), and where they are
    vertical (``>= 90°``: no tangential shift, never slides)."""
    check_flag("adhesion", adhesion)
    alpha_arr = validate_alpha(alpha)
    return alpha_arr, alpha_arr >= 90.0


def final_depth_of(params: Parameters, final_depth) -> float:
    """The "+" branch's deepest point: ``final_depth``, default ``2 d_max``; else ``ValueError`` naming it unless a
    finite depth beyond ``d_max``."""
    final = 2.0 * params.d_max if final_depth is None else final_depth
    if not (isinstance(final, (int, float)) and math.isfinite(final) and final > params.d_max):
        raise ValueError(f"final_depth={final!r} is not allowed; allowed: a finite depth > d_max = {params.d_max!r} m")
    return final


def _forms(profile) -> ClosedForms:
    """The closed forms of ``profile``'s kind, ``profile`` checked (a power law or the flat punch).

    Looked up by :func:`mdr_events.theory.kinds.theory_of`, imported when called: kinds files this module's functions
    (and :mod:`mdr_events.theory.flat_punch` imports this module), so it cannot be imported on this module's import.
    """
    from mdr_events.theory.kinds import theory_of

    return theory_of(check_profile(profile)).closed_forms


def convex_root(function, derivative, upper, lower, rtol: float = ROOT_RTOL):
    """The root in ``[lower, upper]`` of increasing convex functions, elementwise (Newton from ``upper``).

    ``function(s)`` and ``derivative(s)`` are vectorised; ``function(lower) <= 0`` and the function increases and
    is convex from its root on. ``upper`` is a guess of a point right of the root (a closed-form bound): where it
    is not finite (a bound whose exponent ``1/(2n − 1)`` or ``1/(2n − 2)`` overflowed near ``n = 1/2`` or ``1``) the
    search starts from 1, and a guess where the function is still negative is doubled until it is not. Newton's
    steps from the right then stay right of the root and fall monotonically onto it; an iterate is clipped to
    ``lower`` (safeguard against rounding). Stops when every step is below ``rtol`` of its iterate.

    Parameters
    ----------
    function : callable
        ``function(s)``, vectorised over an array ``s``.
    derivative : callable
        Its derivative ``derivative(s)``, vectorised.
    upper : float or array_like
        A guess right of each root (non-finite: 1).
    lower : float or array_like
        The left end of each bracket (broadcast to ``upper``), where ``function <= 0``.
    rtol : float, default ROOT_RTOL
        The relative size of the last Newton step at which the iteration stops.

    Returns
    -------
    numpy.ndarray
        The roots, the shape of ``upper``; ``nan`` where the function overflows before its root (a root beyond the
        double range).
    """
    s = np.array(upper, dtype=float, copy=True)
    lower = np.broadcast_to(np.asarray(lower, dtype=float), s.shape)
    s = np.maximum(np.where(np.isfinite(s), s, 1.0), lower)
    # a root beyond the double range (near the cone, n -> 1, the phase diagram's (3 slope/κc)^(1/(2n-2)): round
    # twenty, RuntimeWarnings of phase-diagram --power-law 1e-3 1.0000001): the doublings overflow the guess or the
    # function to inf, Newton's step is inf/inf and the root nan, which the callers read as "no root" (d_crit = +inf)
    with np.errstate(over="ignore", invalid="ignore"):
        for _ in range(ROOT_MAX_DOUBLINGS):
            short = function(s) < 0.0
            if not np.any(short):
                break
            s = np.where(short, 2.0 * np.where(s > 0.0, s, 1.0), s)
    for _ in range(ROOT_MAX_ITERATIONS):
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            step = np.where(derivative(s) > 0, function(s) / derivative(s), 0.0)
        s_next = np.maximum(s - np.maximum(step, 0.0), lower)
        done = np.all(np.abs(s_next - s) <= rtol * np.abs(s_next))
        s = s_next
        if done:
            break
    return s


def branch_root(depth: float, kc: float, hess: float, exponent: float, lower: float,
                rtol: float = ROOT_RTOL) -> float:
    """``s = √a`` on the stable branch at ``depth``, for Python floats (the continuum's hot loop):
    the root of ``kc s^exponent − hess s − depth`` at or above ``lower`` (the jump-off's ``s``),
    ``exponent = 2n``, ``kc = κ c``, ``hess = sqrt(2πΔγ/E*)``. Newton from an upper bound (as
    :func:`convex_root`, one point).

    Parameters
    ----------
    depth : float
        The depth ``d`` (m).
    kc : float
        ``κₙ c`` (:func:`prefactor`).
    hess : float
        ``sqrt(2πΔγ/E*)`` (:func:`hess_prefactor`).
    exponent : float
        ``2n``.
    lower : float
        ``s`` of the jump-off (the smallest root allowed).
    rtol : float, default ROOT_RTOL
        The relative size of the last Newton step at which the iteration stops.

    Returns
    -------
    float
        ``s = √a`` (m^(1/2)).
    """
    s = max(lower, (2.0 * abs(depth) / kc) ** (1.0 / exponent),
            (2.0 * hess / kc) ** (1.0 / (exponent - 1.0)) if hess > 0.0 else 0.0)
    for _ in range(ROOT_MAX_ITERATIONS):
        slope = exponent * kc * s ** (exponent - 1.0) - hess
        if not slope > 0.0:
            return s
        s_next = max(s - max((kc * s**exponent - hess * s - depth) / slope, 0.0), lower)
        if abs(s_next - s) <= rtol * s_next:
            return s_next
        s = s_next
    return s


def prefactor(profile: PowerLaw) -> float:
    r"""``κₙ c = g(1)``: the MDR profile is ``g(x) = κₙ c xⁿ`` (3).

    .. math:: \kappa_n = \frac{\sqrt{\pi}\, \Gamma(n/2 + 1)}{\Gamma(n/2 + 1/2)}

    Parameters
    ----------
    profile : PowerLaw
        The power law ``f = c rⁿ``.

    Returns
    -------
    float
        ``κₙ c`` (m^(1−n)).
    """
    return float(_rel("profile_power_law").numeric(1.0, profile.c, profile.n))


def cap_per_radius(params: Parameters) -> float:
    """``K``: the critical shift (13) is ``ū = K a``."""
    return float(_rel("critical_shift").numeric(1.0, params.tau0, params.G_star))


def hess_prefactor(params: Parameters, work_of_adhesion: float) -> float:
    r"""``sqrt(2π Δγ / E*)``: Heß's limit (8) is this times ``√a``.

    .. math:: \Delta l_\mathrm{max}(a) = \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (8)

    Parameters
    ----------
    params : Parameters
        The material (``E*``).
    work_of_adhesion : float
        ``Δγ`` (J/m²).

    Returns
    -------
    float
        ``sqrt(2π Δγ / E*)`` (m^(1/2)).
    """
    return float(_rel("hess_max_elongation").numeric(1.0, work_of_adhesion, params.E_star))


def with_radius_at(n: float, radius: float, depth: float) -> PowerLaw:
    """The power law ``f = c rⁿ`` whose non-adhesive contact radius at ``depth`` is ``radius``: ``c`` from
    ``κₙ c radiusⁿ = depth`` (to compare indenters of equal size, e.g. with the paraboloid's ``√(R d_max)``).

    Parameters
    ----------
    n : float
        The exponent, > 0.
    radius : float
        The contact radius (m) it should have at ``depth`` without adhesion.
    depth : float
        The depth (m).

    Returns
    -------
    PowerLaw
        The power law of exponent ``n`` and that ``c``.
    """
    return PowerLaw(depth / float(equivalent_profile(radius, PowerLaw(1.0, n))), n)


def equivalent_profile(x, profile: PowerLaw):
    r"""``g(x) = κₙ c |x|ⁿ``: the MDR profile of the power law, the Abel transform (3).

    .. math:: g(x) = |x| \int_0^{|x|} \frac{f'(r)}{\sqrt{x^2 - r^2}}\, \mathrm{d}r = \kappa_n c |x|^n \qquad (3)

    Parameters
    ----------
    x : float or array_like
        The spring's coordinate (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).

    Returns
    -------
    float or numpy.ndarray
        ``g(x)`` (m), the shape of ``x``.
    """
    profile = _power_law_only(profile, "equivalent_profile")
    return _rel("profile_power_law").numeric(np.abs(np.asarray(x, dtype=float)), profile.c, profile.n)


def branch_depth(contact_radius, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    r"""Depth of the adhesive contact of radius ``a``, ``κ c aⁿ − sqrt(2π a Δγ / E*)`` (generalised (9)).

    .. math:: d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The depth ``d`` (m), the shape of ``contact_radius``.
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    profile = _power_law_only(profile, "branch_depth")
    return _rel("power_law_depth").numeric(contact_radius, profile.c, profile.n, params.E_star, work_of_adhesion)


def normal_force(depth, contact_radius, profile: Profile, params: Parameters):
    r"""Normal force (N) of the springs in ``|x| < a`` at depth ``d`` (10); the flat punch's:
    :func:`mdr_events.theory.flat_punch.normal_force`.

    .. math:: F_N = 2 E^* \int_0^a \left(d - g(x)\right) \mathrm{d}x
              = 2 E^* \left(a d - \frac{\kappa_n c\, a^{n+1}}{n + 1}\right) \qquad (10)

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    contact_radius : float, array_like or None
        The contact radius ``a`` (m), any (e.g. pinned); for the flat punch ``None`` or its radius.
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.

    Returns
    -------
    float or numpy.ndarray
        ``F_N`` (N; negative: tensile).

    Raises
    ------
    ValueError
        A ``contact_radius`` other than the flat punch's own.
    """
    return _forms(profile).normal_force(depth, contact_radius, profile, params)


def _normal_force(depth, contact_radius, profile: PowerLaw, params: Parameters):
    """The power law's :func:`normal_force` (10)."""
    return _rel("power_law_normal_force").numeric(depth, contact_radius, profile.c, profile.n, params.E_star)


def branch_normal_force(contact_radius, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    r"""Normal force of the adhesive power-law contact of radius ``a`` on its branch (10).

    .. math:: F_N = 2 E^* \left(a d(a) - \frac{\kappa_n c\, a^{n+1}}{n + 1}\right), \qquad
              d(a) = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9), (10)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        ``F_N`` (N; negative: tensile), the shape of ``contact_radius``.
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    profile = _power_law_only(profile, "branch_normal_force")
    return _rel("power_law_branch_normal_force").numeric(contact_radius, profile.c, profile.n, params.E_star,
                                                         work_of_adhesion)


def jump_in_radius(profile: PowerLaw, params: Parameters, work_of_adhesion: float) -> float:
    """Contact radius on first touch, ``d = 0`` on the branch: ``a^(2n−1) = 2π Δγ / (E* (κ c)²)`` (0 without
    adhesion).

    Parameters
    ----------
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ0`` (J/m², >= 0), the work of adhesion of the way in.

    Returns
    -------
    float
        The radius ``a`` (m).

    Raises
    ------
    ValueError
        ``n <= 1/2`` with adhesion (no stable contact).
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    profile = _power_law_only(profile, "jump_in_radius")
    if work_of_adhesion == 0.0:
        return 0.0
    _check_adhesive(profile, work_of_adhesion)
    return float(_rel("power_law_jump_in_radius").numeric(profile.c, profile.n, params.E_star, work_of_adhesion))


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
    return {"contact_radius": float(_rel("power_law_jump_off_radius").numeric(*args)),
            "depth": float(_rel("power_law_jump_off_depth").numeric(*args)),
            "normal_force": float(_rel("power_law_jump_off_force").numeric(*args))}


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


def contact_radius(depth, profile: PowerLaw, params: Parameters, work_of_adhesion: float):
    """Contact radius on the stable branch (``a >=`` the jump-off radius) at depth ``d``; ``nan`` where the depth
    lies below the jump-off (no contact).

    Without adhesion ``a = (d / (κ c))^(1/n)`` (``nan`` above the surface, ``d < 0``). With adhesion the branch in
    ``s = √a``, ``κ c s^(2n) − sqrt(2πΔγ/E*) s − d``, increases and is convex above the jump-off (``2n >= 1``):
    :func:`convex_root` from an upper bound.

    Parameters
    ----------
    depth : float or array_like
        The depth ``d`` (m).
    profile : PowerLaw
        The power law ``f = c rⁿ`` (a flat punch is refused: it keeps its radius while in contact).
    params : Parameters
        The material (``E*``); its ``R`` is the paraboloid's and not used.
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The radius ``a`` (m) or ``nan``, the shape of ``depth``.

    Raises
    ------
    ValueError
        ``n <= 1/2`` with adhesion.
    """
    work_of_adhesion = _check_work(work_of_adhesion)
    profile = _power_law_only(profile, "contact_radius")
    depth_arr = np.asarray(depth, dtype=float)
    if work_of_adhesion == 0.0:
        with np.errstate(invalid="ignore"):
            radius = _rel("power_law_hertz_radius").numeric(np.maximum(depth_arr, 0.0), profile.c, profile.n)
        return as_output(np.where(depth_arr >= 0.0, radius, np.nan), depth_arr)
    _check_adhesive(profile, work_of_adhesion)
    kc, k = prefactor(profile), hess_prefactor(params, work_of_adhesion)
    two_n = 2.0 * profile.n
    point = _jump_off(profile, params, work_of_adhesion)
    s_fold = math.sqrt(point["contact_radius"])
    # κc s^(2n) >= k s + |d| once κc s^(2n) >= 2|d| and κc s^(2n−1) >= 2k (each half covers one term)
    with np.errstate(over="ignore", divide="ignore"):
        upper = np.maximum.reduce([np.full(depth_arr.shape, s_fold),
                                   (2.0 * np.abs(depth_arr) / kc) ** (1.0 / two_n),
                                   np.full(depth_arr.shape, (2.0 * k / kc) ** (1.0 / (two_n - 1.0)))])
    s = convex_root(lambda s: kc * s**two_n - k * s - depth_arr, lambda s: two_n * kc * s ** (two_n - 1.0) - k,
                    upper, s_fold)
    return as_output(np.where(depth_arr >= point["depth"], s * s, np.nan), depth_arr)


def d_crit_A(alpha, profile: Profile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario A (the path (14) from first contact at angle ``α`` in degrees).

    - Power law without adhesion, ``n != 1``: the closed form of (17), ``d^((n−1)/n) ∝ tan α``.
    - The cone (``n = 1``) without adhesion: the shift ``d / tan α`` and the cap ``K a = K d / (κ c)`` grow in
      proportion, so the springs slide from first contact (``d = 0``) where ``tan α < κ c / K`` and never (``nan``)
      above it: no onset depth exists in between.
    - Power law with adhesion (``Δγ0`` branch), ``n >= 1``: ``d(a) = tan α K a`` has no closed form; in ``s = √a``
      ``κ c s^(2n−1) − tan α K s − sqrt(2πΔγ0/E*)`` is increasing and convex past its minimum and has one
      positive root (:func:`convex_root`); ``nan`` where it has none.
    - Flat punch: :func:`mdr_events.theory.flat_punch.d_crit_A` (``d = tan α K a``, onset is full slip).

    Depths beyond ``d_max`` are returned as they are (the path turns back before them); ``α = 90°`` never
    slides (``+inf``). Without adhesion the onset (17), with it (18):

    .. math:: \frac{d}{\tan\alpha} = \bar u(a) = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma_0}{E^*}} \qquad (17), (18)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``nan`` where none exists, ``+inf`` at 90°.

    Raises
    ------
    ValueError
        An angle out of range, or a power law with ``n < 1`` with adhesion.
    """
    return _forms(profile).d_crit_A(alpha, profile, params, adhesion)


def _d_crit_A(alpha, profile: PowerLaw, params: Parameters, adhesion: bool = False):
    """The power law's :func:`d_crit_A`."""
    alpha_arr, vertical = path_angles(alpha, adhesion)  # straight down: never slides (+inf, as (17), (18))
    tan_alpha = np.tan(np.deg2rad(np.where(vertical, 45.0, alpha_arr)))
    K = cap_per_radius(params)
    kc = prefactor(profile)
    if not adhesion or params.dgamma0 == 0.0:
        if profile.n == 1.0:
            return as_output(np.where(vertical, np.inf, np.where(tan_alpha * K < kc, 0.0, np.nan)), alpha_arr)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # (its power 1/(n − 1) near the cone
            # overflows to +inf, "never slides", as the adhesive root beyond the doubles: round twenty)
            depth = _rel("power_law_d_crit_A_hertz").numeric(tan_alpha, profile.c, profile.n, params.tau0,
                                                             params.G_star)
        return as_output(np.where(vertical, np.inf, np.asarray(depth, dtype=float)), alpha_arr)
    if profile.n < 1.0:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed for the adhesive slip onset; allowed: n >= 1 "
                         "(below it the onset condition may have several roots)")
    k = hess_prefactor(params, params.dgamma0)
    power = 2.0 * profile.n - 1.0
    slope = tan_alpha * K
    if power == 1.0:  # the cone: linear in s
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(kc > slope, k / (kc - slope), np.nan)
    else:
        # φ(s) = κc s^p − slope s − k: negative at 0 and convex (p > 1), so it has one positive root
        with np.errstate(over="ignore", divide="ignore"):
            upper = np.maximum((2.0 * slope / kc) ** (1.0 / (power - 1.0)), (2.0 * k / kc) ** (1.0 / power))
        s = convex_root(lambda s: kc * s**power - slope * s - k, lambda s: power * kc * s ** (power - 1.0) - slope,
                        upper, 0.0)
    with np.errstate(over="ignore"):  # (a root near the double range's top: its depth +inf)
        depth = np.asarray(tan_alpha * K * (s * s), dtype=float)
    return as_output(np.where(vertical, np.inf, depth), alpha_arr)


def critical_angle_A(profile: Profile, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario A's critical angle (degrees): slip begins exactly at ``d_max``, ``tan α_c = d_max / ū(a(d_max))``;
    below it the springs slide while indenting. The radius at ``d_max`` is the branch's (``Δγ0``) with adhesion,
    the non-adhesive one without (the flat punch: :func:`mdr_events.theory.flat_punch.critical_angle_A`). The cone
    without adhesion gives ``tan α_c = κ c / K`` at any depth.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{max}}{\bar u(a(d_\mathrm{max}))}
              = \frac{2 G^* d_\mathrm{max}}{\pi a \tau_0} \qquad (17), (18)

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    return _forms(profile).critical_angle_A(profile, params, adhesion)


def _critical_angle_A(profile: PowerLaw, params: Parameters, adhesion: bool = True) -> float:
    """The power law's :func:`critical_angle_A`."""
    check_flag("adhesion", adhesion)
    radius = contact_radius(params.d_max, profile, params, params.dgamma0 if adhesion else 0.0)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_A").numeric(radius, params.d_max, params.tau0, params.G_star)
    return float(np.rad2deg(angle))


def d_crit_B(alpha, profile: Profile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset in scenario B's pull-off (the path (19): vertically in to ``d_max``, out at angle
    ``α`` in degrees), as (20), (21) take it: the radius on the pull-off branch (``Δγ1``; without adhesion the
    non-adhesive radius) from the start of the pull-off.

    - Power law: ``(d_max − d) / tan α = K a`` with ``d = d(a)`` on the branch; in ``s = √a``,
      ``κ c s^(2n) − sqrt(2πΔγ1/E*) s + tan α K s² − d_max`` increases and is convex above the jump-off
      (:func:`convex_root` from the radius at ``d_max``). A root below the jump-off radius means the contact
      comes apart before any spring slides: ``-inf`` (as :func:`mdr_events.theory.analytic.d_crit`).
    - Flat punch: :func:`mdr_events.theory.flat_punch.d_crit_B` (``d = d_max − tan α K a``).

    ``d < d_crit`` is the sliding region; ``α = 90°`` never slides (``-inf``).

    .. math:: \frac{d_\mathrm{max} - d}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma_1}{E^*}} \qquad (20), (21)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ1``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the radius of the ``Δγ1`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``-inf`` where the contact comes apart first.

    Raises
    ------
    ValueError
        An angle out of range, or ``n <= 1/2`` with adhesion.
    """
    return _forms(profile).d_crit_B(alpha, profile, params, adhesion)


def _d_crit_B(alpha, profile: PowerLaw, params: Parameters, adhesion: bool = False):
    """The power law's :func:`d_crit_B`."""
    alpha_arr, vertical = path_angles(alpha, adhesion)
    tan_alpha = np.tan(np.deg2rad(alpha_arr))
    K = cap_per_radius(params)
    work = params.dgamma1 if adhesion else 0.0
    if work > 0.0:
        _check_adhesive(profile, work)
    kc, k = prefactor(profile), hess_prefactor(params, work)
    two_n = 2.0 * profile.n
    slope = np.where(vertical, 0.0, tan_alpha * K)
    fold = _jump_off(profile, params, work)
    s_fold = math.sqrt(fold["contact_radius"])
    upper = math.sqrt(float(contact_radius(params.d_max, profile, params, work)))
    if not two_n >= 1.0:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed for the pull-off slip onset; allowed: n >= 0.5")
    s = convex_root(lambda s: kc * s**two_n - k * s + slope * s * s - params.d_max,
                    lambda s: two_n * kc * s ** (two_n - 1.0) - k + 2.0 * slope * s,
                    np.full(alpha_arr.shape, upper), s_fold)
    radius = s * s
    depth = params.d_max - slope * radius
    # the root lies below the fold where the function is still negative at it: the contact comes apart first
    apart = (kc * s_fold**two_n - k * s_fold + slope * s_fold**2 - params.d_max > 0.0) if work > 0.0 else False
    return as_output(np.where(vertical | apart, -np.inf, depth), alpha_arr)


def critical_angle_B(profile: Profile, params: Parameters, adhesion: bool = True) -> float:
    r"""Scenario B's critical angle (degrees): above it the contact comes apart (the jump-off of the ``Δγ1``
    branch; the flat punch: :func:`mdr_events.theory.flat_punch.critical_angle_B`) before any spring slides,
    ``tan α_c = (d_max − d_j) / ū(a_j)`` at the jump-off ``(a_j, d_j)`` ((21) there). Without adhesion: 90°.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{max} - d_j}{\bar u(a_j)} = \frac{2 G^* (d_\mathrm{max} - d_j)}{\pi a_j \tau_0}
              \qquad (21)

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ1``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the radius of the ``Δγ1`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float
        ``α_c`` in degrees.
    """
    return _forms(profile).critical_angle_B(profile, params, adhesion)


def _critical_angle_B(profile: PowerLaw, params: Parameters, adhesion: bool = True) -> float:
    """The power law's :func:`critical_angle_B`."""
    check_flag("adhesion", adhesion)
    if not adhesion or params.dgamma1 == 0.0:
        return 90.0
    point = _jump_off(profile, params, params.dgamma1)
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B").numeric(point["contact_radius"], point["depth"], params.d_max, params.tau0,
                                                 params.G_star)
    return float(np.rad2deg(angle))


def d_crit_B_indentation(alpha, profile: Profile, params: Parameters, adhesion: bool = False):
    r"""Depth of slip onset on scenario B's indentation branch (the "+" sign of (20), (21); the path
    :meth:`~mdr_events.Path.scenario_B_indentation`: vertically in to ``d_max``, further in at angle ``α``):
    ``(d − d_max) / tan α = K a(d)`` on the ``Δγ0`` branch (without adhesion the non-adhesive radius).

    - Power law, ``n >= 1``: in ``s = √a``, ``κ c s^(2n) − sqrt(2πΔγ0/E*) s − tan α K s² − d_max`` falls, then
      rises convexly through its one positive root (:func:`convex_root` from above); the cone (``n = 1``) is a
      quadratic with a root only where ``tan α K < κ c`` (else ``+inf``: it never slides).
    - Flat punch: :func:`mdr_events.theory.flat_punch.d_crit_B_indentation` (``d = d_max + tan α K a``).

    ``d > d_crit`` is the sliding region; ``α = 90°`` never slides (``+inf``).

    .. math:: \frac{d - d_\mathrm{max}}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*}, \qquad
              d = \kappa_n c\, a^n - \sqrt{\frac{2 \pi a \Delta\gamma_0}{E^*}} \qquad (20), (21)

    Parameters
    ----------
    alpha : float or array_like
        The path angle in degrees, in [0, 90].
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default False
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.

    Returns
    -------
    float or numpy.ndarray
        The onset depth ``d_crit`` (m), the shape of ``alpha``; ``+inf`` where it never slides.

    Raises
    ------
    ValueError
        An angle out of range, or a power law with ``n < 1``.
    """
    return _forms(profile).d_crit_B_indentation(alpha, profile, params, adhesion)


def _d_crit_B_indentation(alpha, profile: PowerLaw, params: Parameters, adhesion: bool = False):
    """The power law's :func:`d_crit_B_indentation`."""
    alpha_arr, vertical = path_angles(alpha, adhesion)
    slope = np.where(vertical, 0.0, np.tan(np.deg2rad(alpha_arr))) * cap_per_radius(params)
    if profile.n < 1.0:
        raise ValueError(f"PowerLaw.n={profile.n!r} is not allowed for the indentation branch's slip onset; allowed: "
                         "n >= 1")
    work = params.dgamma0 if adhesion else 0.0
    kc, k, two_n = prefactor(profile), hess_prefactor(params, work), 2.0 * profile.n
    if two_n == 2.0:  # the cone: (κc − slope) s² − k s − d_max = 0
        lead = kc - slope
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(lead > 0.0, (k + np.sqrt(k * k + 4.0 * lead * params.d_max)) / (2.0 * lead), np.nan)
    else:
        # κc s^(2n) is at least three times each other term beyond this: the function is positive there
        with np.errstate(over="ignore", divide="ignore"):
            upper = np.maximum.reduce([np.full(alpha_arr.shape, (3.0 * k / kc) ** (1.0 / (two_n - 1.0))),
                                       (3.0 * slope / kc) ** (1.0 / (two_n - 2.0)),
                                       np.full(alpha_arr.shape, (3.0 * params.d_max / kc) ** (1.0 / two_n))])
        s = convex_root(lambda s: kc * s**two_n - k * s - slope * s * s - params.d_max,
                        lambda s: two_n * kc * s ** (two_n - 1.0) - k - 2.0 * slope * s, upper, 0.0)
    with np.errstate(over="ignore"):  # (a root near the double range's top, n -> 1: its depth +inf, as no root's)
        depth = params.d_max + slope * s * s
    return as_output(np.where(vertical | np.isnan(s), np.inf, depth), alpha_arr)


def critical_angle_B_indentation(profile: Profile, params: Parameters, adhesion: bool = True,
                                 final_depth: float | None = None) -> float:
    r"""The "+" branch's critical angle (degrees): slip begins exactly at ``final_depth`` (default ``2 d_max``, as
    :meth:`~mdr_events.Path.scenario_B_indentation`), ``tan α_c = (final − d_max) / ū(a(final))`` with the ``Δγ0``
    branch's radius there (the flat punch: :func:`mdr_events.theory.flat_punch.critical_angle_B_indentation`);
    below it the springs slide before the path turns back.

    .. math:: \tan\alpha_c = \frac{d_\mathrm{final} - d_\mathrm{max}}{\bar u(a(d_\mathrm{final}))} \qquad (21)

    Parameters
    ----------
    profile : PowerLaw or FlatPunch
        The indenter.
    params : Parameters
        The material (``E*``, ``G*``, ``τ0``, ``Δγ0``, ``d_max``); its ``R`` is the paraboloid's and not used.
    adhesion : bool, default True
        With adhesion: the radius of the ``Δγ0`` branch (9); without: the non-adhesive radius.
    final_depth : float, optional
        The deepest point (m), > ``d_max``; default ``2 d_max``.

    Returns
    -------
    float
        ``α_c`` in degrees.

    Raises
    ------
    ValueError
        A ``final_depth`` not beyond ``d_max``.
    """
    return _forms(profile).critical_angle_B_indentation(profile, params, adhesion, final_depth)


def _critical_angle_B_indentation(profile: PowerLaw, params: Parameters, adhesion: bool = True,
                                  final_depth: float | None = None) -> float:
    """The power law's :func:`critical_angle_B_indentation`."""
    check_flag("adhesion", adhesion)
    final = final_depth_of(params, final_depth)
    radius = float(contact_radius(final, profile, params, params.dgamma0 if adhesion else 0.0))
    with np.errstate(divide="ignore"):
        angle = _rel("critical_angle_B_indentation").numeric(radius, final, params.d_max, params.tau0, params.G_star)
    return float(np.rad2deg(angle))


#: The power law's closed forms behind this module's functions of either indenter.
CLOSED_FORMS = ClosedForms(normal_force=_normal_force, jump_off=_jump_off, pull_off_force=_pull_off_force,
                           d_crit_A=_d_crit_A, critical_angle_A=_critical_angle_A, d_crit_B=_d_crit_B,
                           critical_angle_B=_critical_angle_B, d_crit_B_indentation=_d_crit_B_indentation,
                           critical_angle_B_indentation=_critical_angle_B_indentation)
