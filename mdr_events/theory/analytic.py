"""Closed-form layer: JKR contact, slip-onset depths ``d_crit(α)``, critical angles.

Every formula is evaluated through the SymPy-derived relations of
:mod:`mdr_events.theory.symbolic` (lambdified once). Where a relation is a
polynomial (the cubic of (18), the quartics of (9) and (21)), its unique
physical root is found by :func:`~mdr_events.theory.roots.positive_polynomial_root`, a vectorised
safeguarded Newton iteration: no Python loop over angles.

Angles are in degrees, lengths in metres, forces in newtons.

Each public function takes the physical model as a :class:`~mdr_events.Contact` of the paper's paraboloid (4) under
its friction law (13) (with the depth ``d_max=`` where a relation needs the motion's depth: (20), (21) and the
critical angles), or as the keywords of before, a :class:`~mdr_events.Parameters`; both are read by
:func:`~mdr_events.theory.job.paper_parameters` and give the same numbers.

The module is over 500 lines because each of the paper's closed forms (9)–(21) is one public function here with its
full numpydoc sections and typeset equation; the relations themselves are derived in ``symbolic``.
"""

from __future__ import annotations

import functools
import math
from typing import Literal, NamedTuple

import numpy as np

from mdr_events.limits import Limits, check_limits, values_in
from mdr_events.theory import symbolic
from mdr_events.theory.blocks import blockwise
from mdr_events.theory.roots import positive_polynomial_root
from mdr_events.theory.job import ContactLike, on_layer, paper_parameters
from mdr_events.validation import SCALE_MAX, check_choice, check_flag, real_array, shown, validate_alpha

__all__ = [
    "DimensionlessGroups",
    "dimensionless_groups",
    "d_crit",
    "d_crit_curves",
    "d_crit_rows",
    "D_CRIT_BYTES_PER_ANGLE",
    "D_CRIT_ROWS_BYTES_PER_ANGLE",
    "critical_angle",
    "critical_shift",
    "jkr_depth",
    "jkr_contact_radius",
    "jkr_normal_force",
    "normal_force",
    "hertz_contact_radius",
    "pull_off_force",
    "jump_off",
    "jump_in_radius",
    "positive_polynomial_root",
    "SCENARIOS",
    "BRANCHES",
    "CRITICAL_ANGLE_SCENARIOS",
]

SCENARIOS = ("A", "B")
BRANCHES = ("pull-off", "indentation")
#: Bytes the half-space's slip onsets allocate per angle at their peak, counted against ``Limits.memory`` before the
#: angles are read (tracemalloc at 1e6 angles: :func:`d_crit` 26 without adhesion, 42 with; :func:`d_crit_rows` 43 in
#: scenario A, 59 in B's two rows), rounded up. Round twenty-five: ``d_crit`` of 1e8 angles (a view of one value, no
#: memory of its own) took 2.4 to 4.2 GB against the default 2 GiB, accepted.
D_CRIT_BYTES_PER_ANGLE = 48
D_CRIT_ROWS_BYTES_PER_ANGLE = 64

def _rel(key: str):
    return symbolic.relation(key)


#: Degrees to radians: the factor of ``numpy.deg2rad``, whose own loop (one product by it) is ten times slower.
_RADIANS_PER_DEGREE = np.pi / 180.0


class _Tangent(NamedTuple):
    """tan α of validated angles for the closed forms: ``finite`` (1 where α = 90°) and ``vertical`` (α = 90°)."""

    finite: np.ndarray
    vertical: np.ndarray

    @classmethod
    def of(cls, alpha_deg: np.ndarray) -> "_Tangent":
        return cls(*blockwise(_tangent, alpha_deg))


def _tangent(alpha_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The fields of :class:`_Tangent`."""
    vertical = alpha_deg == 90.0
    return np.where(vertical, 1.0, np.tan(alpha_deg * _RADIANS_PER_DEGREE)), vertical


#: Arguments of the closed forms that are lengths or works of their physics, never negative (the parameters refuse a
#: negative work of adhesion; a negative radius gave a negative critical shift and a positive pull-off force).
NONNEGATIVE = ("contact_radius", "work_of_adhesion", "amplitude")


def _finite(**arguments) -> None:
    """Refuse an argument with an entry that is no finite real number (``10**400`` read as inf), beyond
    ``±SCALE_MAX`` (its square would overflow) or, of :data:`NONNEGATIVE`, below 0, naming it."""
    for name, value in arguments.items():
        low = 0.0 if name in NONNEGATIVE else -SCALE_MAX
        if type(value) is float:
            if low <= value <= SCALE_MAX:
                continue
            values = np.asarray(value)
        elif isinstance(value, np.ndarray) and value.dtype.kind == "f":
            values = value
        else:
            values = real_array(name, value, "real numbers")
        if not (values.size == 0 or (low <= values.min() and values.max() <= SCALE_MAX)):
            raise ValueError(f"{name}={shown(value)} is not allowed; allowed: finite real numbers "
                             f"{'from 0' if low == 0.0 else f'from {low:.2g}'} to {SCALE_MAX:.2g} (SI units)")


class ResultOverflowError(ValueError, OverflowError):
    """A closed form's result overflows double precision for the arguments and parameters given: a ``ValueError``
    (the input asks too much), and an ``OverflowError``, so that :mod:`mdr_events.theory.scales` names the parameter
    scale behind it as it does for math's overflows."""


def _representable(compute, function: str, **arguments):
    """``compute()`` if every entry is finite (computed without a RuntimeWarning); else ``ValueError``: the arguments'
    result overflows double precision."""
    with np.errstate(over="ignore", invalid="ignore"):
        result = compute()
    if np.all(np.isfinite(list(result.values()) if isinstance(result, dict) else result)):
        return result
    given = ", ".join(f"{name}={shown(value)}" for name, value in arguments.items())
    raise ResultOverflowError(f"{function}({given}) is not allowed: its result overflows double precision; allowed: "
                              "arguments and parameters whose result is a finite number")


def _as_output(values: np.ndarray, like: np.ndarray):
    return float(values) if np.ndim(like) == 0 else values


# ----------------------------------------------------------------------------
# polynomial roots
def jkr_depth(contact_radius, contact: ContactLike, work_of_adhesion: float):
    r"""Indentation depth of the adhesive contact of radius ``a``, eq. (9).

    .. math:: d = \frac{a^2}{R} - \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (9)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The depth ``d`` (m), the shape of ``contact_radius``.
    """
    _finite(contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)
    params = paper_parameters(contact, "jkr_depth")
    relation = _rel("jkr_depth").numeric
    return _representable(lambda: relation(contact_radius, params.R, params.E_star, work_of_adhesion), "jkr_depth",
                          contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)


def jkr_normal_force(contact_radius, contact: ContactLike, work_of_adhesion: float):
    r"""Normal force of the adhesive contact of radius ``a``, eq. (10).

    .. math:: F_N = \frac{4 E^* a^3}{3 R} - \sqrt{8 \pi E^* \Delta\gamma\, a^3} \qquad (10)

    (the force (10) at the depth (9)).

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The normal force ``F_N`` (N; negative: tensile), the shape of ``contact_radius``.
    """
    _finite(contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)
    params = paper_parameters(contact, "jkr_normal_force")
    relation = _rel("jkr_normal_force").numeric
    return _representable(lambda: relation(contact_radius, params.R, params.E_star, work_of_adhesion),
                          "jkr_normal_force", contact_radius=contact_radius, work_of_adhesion=work_of_adhesion)


def normal_force(depth, contact_radius, contact: ContactLike):
    r"""Normal force of the springs in ``|x| < a`` at depth ``d`` (any, e.g. pinned ``a``), eq. (10).

    .. math:: F_N = 2 E^* a d - \frac{2 E^* a^3}{3 R} \qquad (10)

    Parameters
    ----------
    depth : float or array_like
        The indentation depth ``d`` (m).
    contact_radius : float or array_like
        The contact radius ``a`` (m), any (e.g. pinned).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The normal force ``F_N`` (N).
    """
    _finite(depth=depth, contact_radius=contact_radius)
    params = paper_parameters(contact, "normal_force")
    return _rel("normal_force").numeric(depth, contact_radius, params.R, params.E_star)


def hertz_contact_radius(depth, contact: ContactLike):
    r"""Non-adhesive contact radius ``a = sqrt(R d)``, eq. (16).

    .. math:: a = \sqrt{R d} \qquad (16)

    Parameters
    ----------
    depth : float or array_like
        The indentation depth ``d`` (m); negative depths give ``a = 0``.
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The contact radius ``a`` (m).
    """
    _finite(depth=depth)
    params = paper_parameters(contact, "hertz_contact_radius")
    return _rel("hertz_radius").numeric(np.maximum(depth, 0.0), params.R)


#: How many paraboloids' jump-off points :func:`jump_off` keeps (a sweep of ``R`` or ``Δγ`` asks each once).
JUMP_OFF_CACHE = 64


def jump_off(contact: ContactLike, work_of_adhesion: float) -> dict[str, float]:
    r"""Jump-off point under displacement control (``∂d/∂a = 0`` on the branch (9)).

    Returns ``contact_radius``, ``depth`` and ``normal_force`` (10) at the jump-off.

    .. math::

       a = \frac{1}{2} \left(\frac{\pi R^2 \Delta\gamma}{E^*}\right)^{1/3}, \quad
       d = -\frac{3}{4} \left(\frac{\pi^2 R \Delta\gamma^2}{E^{*2}}\right)^{1/3}, \quad
       F_N = -\frac{5}{6} \pi R \Delta\gamma

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before). A contact on a layer of finite thickness
        (``Contact.layer``; a paraboloid or power law, either base): the least depth on the layer's branch, found in
        ``a`` (:func:`~mdr_events.theory.layer.branch_points.layer_jump_off`; one beyond the tables, ``a/h > 64``, is
        refused).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    dict of str to float
        ``contact_radius`` (m), ``depth`` (m) and ``normal_force`` (N) at the jump-off.
    """
    _finite(work_of_adhesion=work_of_adhesion)
    if on_layer(contact):
        from mdr_events.theory.layer.branch_points import layer_jump_off

        return layer_jump_off(contact, work_of_adhesion)
    params = paper_parameters(contact, "jump_off")
    # (a fresh dict each call: the caller may change it)
    return dict(_paraboloid_jump_off(params.R, params.E_star, work_of_adhesion, math.copysign(1.0, work_of_adhesion)))


@functools.lru_cache(maxsize=JUMP_OFF_CACHE, typed=True)
def _paraboloid_jump_off(R: float, E_star: float, work_of_adhesion: float, sign: float) -> tuple:
    """:func:`jump_off` of the paraboloid as ``(name, value)`` pairs, kept for the last :data:`JUMP_OFF_CACHE`
    arguments: a run asks it of the same contact at every step of its set-up (the checks of scales, the paths, each
    branch), some 40 µs a time. ``sign``: that of the work, so that ``-0.0`` and ``0.0``, equal as keys, are kept
    apart; the arguments' types too (``typed``: an ``int`` ``R`` computes as it did)."""
    args = (R, E_star, work_of_adhesion)
    point = _representable(lambda: {
        "contact_radius": float(_rel("jump_off_radius").numeric(*args)),
        "depth": float(_rel("jump_off_depth").numeric(*args)),
        "normal_force": float(_rel("jump_off_force").numeric(R, work_of_adhesion)),
    }, "jump_off", work_of_adhesion=work_of_adhesion)
    return tuple(point.items())


def jump_in_radius(contact: ContactLike, work_of_adhesion: float) -> float:
    r"""Contact radius on first touch (``d = 0`` on the stable branch of (9)).

    .. math:: a = \left(\frac{2 \pi R^2 \Delta\gamma}{E^*}\right)^{1/3}

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before). A contact on a layer of finite thickness
        (``Contact.layer``; a paraboloid or power law, either base): the stable radius at ``d = 0`` on the layer's
        branch, found in ``a`` (:func:`~mdr_events.theory.layer.branch_points.layer_jump_in_radius`; one beyond the
        tables, ``a/h > 64``, is refused).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float
        The contact radius (m) at first touch.
    """
    _finite(work_of_adhesion=work_of_adhesion)
    if on_layer(contact):
        from mdr_events.theory.layer.branch_points import layer_jump_in_radius

        return layer_jump_in_radius(contact, work_of_adhesion)
    params = paper_parameters(contact, "jump_in_radius")
    return _representable(lambda: float(_rel("jump_in_radius").numeric(params.R, params.E_star, work_of_adhesion)),
                          "jump_in_radius", work_of_adhesion=work_of_adhesion)


def pull_off_force(contact: ContactLike, work_of_adhesion: float) -> float:
    r"""JKR pull-off force ``−(3/2) π Δγ R``: the minimum of (10) along the branch (9).

    .. math:: F_\mathrm{pull\text{-}off} = -\frac{3}{2} \pi \Delta\gamma R

    Parameters
    ----------
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before). A contact on a layer of finite thickness
        (``Contact.layer``; a paraboloid or power law, either base): the least force on the layer's branch, found in
        ``a`` (:func:`~mdr_events.theory.layer.branch_points.layer_pull_off_force`; one beyond the tables, ``a/h > 64``,
        is refused).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float
        The pull-off force (N, negative) under force control.
    """
    _finite(work_of_adhesion=work_of_adhesion)
    if on_layer(contact):
        from mdr_events.theory.layer.branch_points import layer_pull_off_force

        return layer_pull_off_force(contact, work_of_adhesion)
    params = paper_parameters(contact, "pull_off_force")
    return _representable(lambda: float(_rel("pull_off_force").numeric(params.R, work_of_adhesion)), "pull_off_force",
                          work_of_adhesion=work_of_adhesion)


def jkr_contact_radius(depth, contact: ContactLike, work_of_adhesion: float):
    """Contact radius on the stable branch of (9) for a depth ``d``.

    The stable branch is ``a >= a_jump-off`` (``∂d/∂a >= 0``). Depths below the
    jump-off depth have no contact: the result is ``nan`` there.

    Parameters
    ----------
    depth : float or array_like
        The indentation depth ``d`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4), its elastomer and adhesion: a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before).
    work_of_adhesion : float
        ``Δγ`` (J/m²): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float or numpy.ndarray
        The contact radius ``a`` (m) on the stable branch of (9), ``nan`` below the jump-off depth; the shape of
        ``depth``.
    """
    _finite(depth=depth, work_of_adhesion=work_of_adhesion)
    params = paper_parameters(contact, "jkr_contact_radius")
    depth_arr = np.asarray(depth, dtype=float)
    if work_of_adhesion == 0.0:
        return _as_output(np.where(depth_arr >= 0, hertz_contact_radius(depth_arr, params), np.nan), depth_arr)
    rel = _rel("jkr_radius_quartic")
    coefficients = rel.coefficients(depth_arr, params.R, params.E_star, work_of_adhesion)
    point = jump_off(params, work_of_adhesion)
    s_min = np.sqrt(point["contact_radius"])
    root = positive_polynomial_root(coefficients, lower=s_min)
    radius = np.where(depth_arr >= point["depth"], root**2, np.nan)
    return _as_output(radius, depth_arr)


# ----------------------------------------------------------------------------
# tangential springs, eq. (13)
def critical_shift(contact_radius, contact: ContactLike):
    r"""Critical spring shift ``ū(a) = π a τ0 / (2 G*)``, eq. (13).

    .. math:: \bar u(a) = \frac{\pi a \tau_0}{2 G^*} \qquad (13)

    Parameters
    ----------
    contact_radius : float or array_like
        The contact radius ``a`` (m).
    contact : Contact or Parameters
        The paper's paraboloid (4) under the law (13) (its ``τ0`` and ``G*``): a :class:`~mdr_events.Contact`, or
        a :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The critical shift ``ū`` (m) of a spring: beyond it the spring slides.
    """
    _finite(contact_radius=contact_radius)
    params = paper_parameters(contact, "critical_shift")
    relation = _rel("critical_shift").numeric
    return _representable(lambda: relation(contact_radius, params.tau0, params.G_star), "critical_shift",
                          contact_radius=contact_radius)


def fretting_dissipated_energy(contact_radius, amplitude, contact: ContactLike):
    r"""Energy dissipated per cycle ``x: −X → X → −X`` by a fixed contact of radius ``a`` (J): the area
    ``4 π a² τ0 (X − ū)`` of the parallelogram ``F_x = 2G* a (x − Y)``, ``Y`` clipped to
    ``[x − ū, x + ū]`` (plateaus ``±π a² τ0``, (13)); for ``X > ū`` (smaller loops stick and dissipate nothing).

    .. math:: W = 4 \pi a^2 \tau_0 (X - \bar u), \qquad \bar u = \frac{\pi a \tau_0}{2 G^*} \quad (13)

    Parameters
    ----------
    contact_radius : float or array_like
        The fixed contact radius ``a`` (m).
    amplitude : float or array_like
        The amplitude ``X`` (m) of the tangential motion, ``X > ū``.
    contact : Contact or Parameters
        The paper's paraboloid (4) under the law (13) (its ``τ0`` and ``G*``): a :class:`~mdr_events.Contact`, or
        a :class:`~mdr_events.Parameters` (the keywords of before).

    Returns
    -------
    float or numpy.ndarray
        The energy dissipated per cycle ``W`` (J).
    """
    _finite(contact_radius=contact_radius, amplitude=amplitude)
    params = paper_parameters(contact, "fretting_dissipated_energy")
    relation = _rel("fretting_dissipated_energy").numeric
    return _representable(lambda: relation(contact_radius, amplitude, params.tau0, params.G_star),
                          "fretting_dissipated_energy", contact_radius=contact_radius, amplitude=amplitude)


# ----------------------------------------------------------------------------
# slip onset, eqs. (17), (18), (20), (21)
def d_crit(
    alpha,
    contact: ContactLike,
    scenario: Literal["A", "B"] = "A",
    adhesion: bool = False,
    branch: Literal["pull-off", "indentation"] | None = None,
    *,
    d_max: float | None = None,
    limits: Limits | None = None,
):
    """Indentation depth at which the springs start to slide, eqs. (17)–(21).

    Parameters
    ----------
    alpha : float or array_like
        Path angle to the surface in degrees, in [0, 90].
    contact : Contact or Parameters
        Material, indenter (the paraboloid (4)), adhesion and ``τ0`` (13): a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before, with its own ``d_max``). A contact on a layer of
        finite thickness bonded to its base (``Contact.layer``; a paraboloid or power law): the same equations with
        the layer's cap ``π a² τ0/K_t(a)`` and branches, solved in ``a``
        (:mod:`mdr_events.theory.layer.slip_onset`; an onset beyond the tables, ``a/h > 64``, is refused); the flat
        punch there: closed forms while its face is held, the root on its receding contact
        (:mod:`mdr_events.theory.layer.punch_onset`).
    scenario : {"A", "B"}
        ``"A"``: indentation at angle α from first contact, eqs. (14), (17),
        (18). ``"B"``: vertical indentation to ``d_max`` then motion at angle α,
        eqs. (19)–(21).
    adhesion : bool
        ``False``: non-adhesive contact radius (16), eqs. (17) and (20).
        ``True``: JKR radius (9), eqs. (18) and (21) with ``Δγ0`` on the way
        in and ``Δγ1`` on the way out.
    branch : {"pull-off", "indentation"}, optional
        Scenario B only (default "pull-off"): from ``d_max`` out at angle α (the "−" sign of (21),
        smaller root of (20)) or further in at angle α (the "+" sign, larger
        root of (20)).
    d_max : float, optional
        With a Contact: the depth of the motion (m; default the paper's 0.3 mm), which scenario B's (20), (21)
        start from.
    limits : Limits, optional
        What the onsets may take, checked before the angles are read (``None``: the defaults). On a layer each angle
        is a bisection on the layer's tables, :data:`~mdr_events.theory.layer.slip_onset.ONSET_STEPS_PER_ANGLE`
        steps; the half-space's closed forms take no steps, :data:`D_CRIT_BYTES_PER_ANGLE` of memory each.

    Returns
    -------
    float or numpy.ndarray
        ``d_crit`` in metres, the same shape as ``alpha``.

    Notes
    -----
    Root choice: each reduced polynomial (the cubic of (18) and the quartics
    of (21) in ``s = sqrt(a)``) has exactly one sign change, hence exactly one
    positive root (Descartes), and that is the one returned. In scenario A it
    lies on the stable JKR branch (``d = K a > 0``). On the pull-off branch of
    scenario B it may lie on the unstable branch ``a < a_jump-off(Δγ1)``: the
    contact then comes apart (jump-off at depth ``d_jump-off < 0``) before any
    spring slides, and ``-inf`` is returned.

    "Never slides" is encoded so that ``d > d_crit`` (indentation) or
    ``d < d_crit`` (pull-off) is the sliding region: α = 90° gives ``+inf``
    for scenario A and the indentation branch, ``-inf`` for the pull-off
    branch. α → 0 gives ``d_crit → 0`` (A) and ``→ d_max`` (B).

    Scenario B (21) assumes the contact radius follows (9) with ``Δγ1`` from
    the start of pull-off; in the model it is pinned first (see
    :mod:`mdr_events` docs on the continuum method).
    """
    params = None if on_layer(contact) else _onset_parameters(contact, "d_crit", d_max)
    check_choice("scenario", scenario, SCENARIOS)
    if scenario == "A" and branch is not None:
        raise ValueError(f"branch={branch!r} is not allowed with scenario 'A'; allowed: None (branch is for scenario B)")
    branch = "pull-off" if branch is None else branch
    check_choice("branch", branch, BRANCHES)
    check_flag("adhesion", adhesion)
    if params is None:
        from mdr_events.theory.layer.slip_onset import check_onset_count, onset_depths

        check_onset_count(values_in(alpha), contact.layer, limits)  # (before the angles are read: a copy each)
        alpha_deg = validate_alpha(alpha)
        return _as_output(onset_depths(alpha_deg, contact, scenario, adhesion, branch, d_max, limits=limits),
                          alpha_deg)
    _check_onset_memory(values_in(alpha), limits, D_CRIT_BYTES_PER_ANGLE)  # (counted before they are read)
    alpha_deg = validate_alpha(alpha)
    return _as_output(_slip_onset(_Tangent.of(alpha_deg), params, scenario, adhesion, branch), alpha_deg)


def _check_onset_memory(count: int, limits: Limits | None, bytes_per_angle: int) -> None:
    """The memory of the half-space's slip onsets at ``count`` angles (``bytes_per_angle`` each: their closed forms
    take no steps) checked against ``limits`` (``None``: the defaults; anything else not a Limits named)."""
    check_limits(limits).check(f"the slip onset at {count} angles", memory=bytes_per_angle * count)


def _onset_parameters(contact: ContactLike, what: str, d_max: float | None) -> "Parameters":
    """:func:`~mdr_events.theory.job.paper_parameters` of a slip onset on the half-space, its scales checked as the
    phase diagram's and the runs' are (:func:`~mdr_events.theory.scales.check_representable`): ``E = 1e300`` gave
    ``d_crit = 0``, ``τ0 = 1e300`` or ``E = 1e-300`` ``inf``, each with NumPy's warning, and the layer's onsets hand
    theirs to :func:`~mdr_events.theory.layer.slip_onset.check_onset_contact`."""
    from mdr_events.theory.scales import check_representable  # (scales imports this module)

    params = paper_parameters(contact, what, d_max)
    check_representable(params)
    return params


def d_crit_curves(alpha, contact: ContactLike, scenario: Literal["A", "B"] = "A", *, d_max: float | None = None,
                  limits: Limits | None = None) -> dict[tuple[bool, str | None], np.ndarray]:
    """Every curve of :func:`d_crit` of a scenario at the same angles, their tangent computed once.

    Parameters
    ----------
    alpha : array_like
        Path angles in degrees, in [0, 90].
    contact : Contact or Parameters
        As for :func:`d_crit`.
    scenario : {"A", "B"}
        As for :func:`d_crit`.
    d_max : float, optional
        As for :func:`d_crit`.
    limits : Limits, optional
        As for :func:`d_crit_rows`.

    Returns
    -------
    dict
        ``(adhesion, branch)`` -> ``d_crit`` (m), an array of the shape of ``alpha``, each equal to
        :func:`d_crit` of those arguments: ``adhesion`` ``False`` and ``True``, ``branch`` ``None`` in scenario A,
        each of :data:`BRANCHES` in B (the rows of :func:`d_crit_rows`).
    """
    rows = d_crit_rows(alpha, contact, scenario, d_max=d_max, limits=limits)
    branches = (None,) if scenario == "A" else BRANCHES
    return {(adhesion, branch): rows[adhesion][row, ...] for row, branch in enumerate(branches)
            for adhesion in (False, True)}


def d_crit_rows(alpha, contact: ContactLike, scenario: Literal["A", "B"] = "A", *,
                d_max: float | None = None, limits: Limits | None = None) -> dict[bool, np.ndarray]:
    """The curves of :func:`d_crit_curves` as one array per adhesion, a row per branch, each computed into its row.

    Parameters
    ----------
    alpha : array_like
        The angles (degrees, 0 to 90) of every row.
    contact : Contact or Parameters
        The paraboloid under the paper's law (:func:`~mdr_events.theory.job.paper_parameters` reads it).
    scenario : {"A", "B"}
        Fig. 9a (one row, (17) and (18)) or 9b (two rows, (20) and (21)).
    d_max : float, optional
        With a Contact: the motion's depth (m).
    limits : Limits, optional
        What the rows may take (``None``: the defaults): :data:`D_CRIT_ROWS_BYTES_PER_ANGLE` of memory per angle,
        counted before the angles are read.

    Returns
    -------
    dict of bool to numpy.ndarray
        ``adhesion`` (``False``, ``True``) -> ``d_crit`` (m) of shape ``(branches, *alpha.shape)``: one row in
        scenario A, the rows of :data:`BRANCHES` in B, each equal to :func:`d_crit` of that branch (a phase diagram's
        variable as it is, without stacking 10⁵ angles' curves afresh).
    """
    params = _onset_parameters(contact, "d_crit", d_max)
    check_choice("scenario", scenario, SCENARIOS)
    _check_onset_memory(values_in(alpha), limits, D_CRIT_ROWS_BYTES_PER_ANGLE)  # (counted before they are read)
    alpha_deg = validate_alpha(alpha)
    tangent = _Tangent.of(alpha_deg)
    branches = (None,) if scenario == "A" else BRANCHES
    rows = {adhesion: np.empty((len(branches), *alpha_deg.shape)) for adhesion in (False, True)}
    for row, branch in enumerate(branches):
        for adhesion in (False, True):
            _slip_onset(tangent, params, scenario, adhesion, branch or "pull-off", out=rows[adhesion][row, ...])
    return rows


def _unless_vertical(vertical: np.ndarray, value: float, depth: np.ndarray) -> np.ndarray:
    """``np.where(vertical, value, depth)``: ``depth`` itself where no path is vertical (a block of 10⁵ angles holds
    90° at most once: no pass of three arrays for nothing)."""
    return np.where(vertical, value, depth) if vertical.any() else depth


def _slip_onset(tangent: _Tangent, p, scenario: str, adhesion: bool, branch: str,
                out: np.ndarray | None = None) -> np.ndarray:
    """:func:`d_crit` of checked arguments, at the angles of ``tangent`` (written into ``out`` where given)."""
    vertical, tan_finite = tangent.vertical, tangent.finite
    if scenario == "A":
        if not adhesion:
            def onset(tan_finite, vertical):
                depth = _rel("d_crit_A_hertz").numeric(tan_finite, p.R, p.tau0, p.G_star)
                return _unless_vertical(vertical, np.inf, depth)

            return blockwise(onset, tan_finite, vertical, out=out)
        coefficients = blockwise(lambda tan_finite: _rel("slip_A_jkr_cubic").coefficients(
            tan_finite, p.R, p.tau0, p.G_star, p.E_star, p.dgamma0), tan_finite)
        with np.errstate(invalid="ignore", divide="ignore"):  # 0/0 at the double root s = 0 (α = 0, Δγ = 0)
            root = positive_polynomial_root(coefficients, out=out)  # (the onset then replaces it, block by block)

        def onset(root, tan_finite, vertical):
            radius = np.where(np.isfinite(root), root, 0.0) ** 2
            depth = _rel("slip_depth_A").numeric(radius, tan_finite, p.tau0, p.G_star)
            return _unless_vertical(vertical, np.inf, depth)

        return blockwise(onset, root, tan_finite, vertical, out=out)

    pulling = branch == "pull-off"
    never = -np.inf if pulling else np.inf
    key = "pull_off" if pulling else "indentation"
    if not adhesion:
        def onset(tan_finite, vertical):
            k = _rel("slip_B_hertz_k").numeric(tan_finite, p.R, p.tau0, p.G_star)
            depth = _rel(f"d_crit_B_hertz_{key}").numeric(p.d_max, k)
            return _unless_vertical(vertical, never, depth)

        return blockwise(onset, tan_finite, vertical, out=out)
    work = p.dgamma1 if pulling else p.dgamma0
    coefficients = blockwise(lambda tan_finite: _rel(f"slip_B_jkr_quartic_{key}").coefficients(
        tan_finite, p.d_max, p.R, p.tau0, p.G_star, p.E_star, work), tan_finite)
    root = positive_polynomial_root(coefficients, out=out)  # (the onset then replaces it, block by block)
    unstable_below = jump_off(p, work)["contact_radius"] if pulling and work > 0.0 else None

    def onset(root, tan_finite, vertical):
        radius = root ** 2
        depth = _rel(f"slip_depth_B_{key}").numeric(radius, tan_finite, p.d_max, p.tau0, p.G_star)
        if unstable_below is not None:
            depth = np.where(radius < unstable_below, never, depth)
        return _unless_vertical(vertical, never, depth)

    return blockwise(onset, root, tan_finite, vertical, out=out)


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
    check_choice("scenario", scenario, CRITICAL_ANGLE_SCENARIOS)
    check_flag("adhesion", adhesion)
    if final_depth is not None and scenario != "B+":
        raise ValueError(f"final_depth={final_depth!r} is not allowed with scenario {scenario!r}; "
                         "allowed: None (final_depth is for scenario 'B+')")
    if p is None:
        from mdr_events.theory.layer.slip_onset import critical_angle_on_layer

        return critical_angle_on_layer(contact, scenario, adhesion, final_depth, d_max)
    if scenario == "B+":
        final = 2.0 * p.d_max if final_depth is None else final_depth
        if not (isinstance(final, (int, float)) and math.isfinite(final) and final > p.d_max):
            raise ValueError(f"final_depth={final!r} is not allowed; allowed: a finite depth > d_max = {p.d_max!r} m")
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


class DimensionlessGroups(NamedTuple):
    r"""The three numbers the model's dimensionless results depend on (:func:`dimensionless_groups`).

    Parameters
    ----------
    slip : float
        The slip parameter :math:`S = \pi \tau_0 \sqrt{R} / (2 G^* \sqrt{d_\mathrm{max}})`.
    adhesion_in : float
        The adhesion parameter of the way in,
        :math:`\Gamma_0 = 2 \pi \Delta\gamma_0 \sqrt{R} / (E^* d_\mathrm{max}^{3/2})`.
    adhesion_out : float
        The adhesion parameter of the way out,
        :math:`\Gamma_1 = 2 \pi \Delta\gamma_1 \sqrt{R} / (E^* d_\mathrm{max}^{3/2})`.
    """

    slip: float  #: S = π τ0 √R / (2 G* √d_max)
    adhesion_in: float  #: Γ0 = 2π Δγ0 √R / (E* d_max^(3/2))
    adhesion_out: float  #: Γ1 = 2π Δγ1 √R / (E* d_max^(3/2))


def dimensionless_groups(contact: ContactLike, *, d_max: float | None = None) -> DimensionlessGroups:
    r"""The slip parameter and the two adhesion parameters of the model.

    Measure depths in ``d_max`` (``d = d_max d̂``), radii in ``√(R d_max)`` (``a = √(R d_max) â``) and tangential
    lengths in ``d_max`` (the paths (14), (19) move ``x = d / tan α``). Then the branch (9) reads
    ``d̂ = â² − √(Γ â)`` with ``Γ = 2π Δγ √R / (E* d_max^(3/2))``, one per work of adhesion, and the cap (13)
    ``ū/d_max = S â`` with ``S = π τ0 √R / (2 G* √d_max)`` (the slip parameter ``k/(tan α √d_max)`` of (20)).
    The springs' forces scale as ``E* (R d_max)^(1/2) d_max`` (normal) and ``τ0 R d_max`` (tangential), so
    every angle, every depth over ``d_max`` and every ratio such as ``F_x / (π a² τ0)`` depends on
    ``(S, Γ0, Γ1)`` and the path's angle alone: two parameter sets with the same groups have the same
    critical angles (17), (18), (21).

    ``contact``: a :class:`~mdr_events.Contact` of the paraboloid under the law (13) with the depth ``d_max`` (m;
    default the paper's 0.3 mm), or a :class:`~mdr_events.Parameters` (its own ``d_max``).

    .. math:: S = \frac{\pi \tau_0 \sqrt{R}}{2 G^* \sqrt{d_\mathrm{max}}}, \qquad
              \Gamma_{0,1} = \frac{2 \pi \Delta\gamma_{0,1} \sqrt{R}}{E^* d_\mathrm{max}^{3/2}}

    Parameters
    ----------
    contact : Contact or Parameters
        A :class:`~mdr_events.Contact` of the paraboloid under the law (13), or a :class:`~mdr_events.Parameters`
        (its own ``d_max``).
    d_max : float, optional
        With a Contact: the motion's depth (m; default the paper's 0.3 mm).

    Returns
    -------
    DimensionlessGroups
        ``(S, Γ0, Γ1)``.
    """
    params = paper_parameters(contact, "dimensionless_groups", d_max)
    root = math.sqrt(params.R)
    scale = params.E_star * params.d_max**1.5
    return DimensionlessGroups(math.pi * params.tau0 * root / (2.0 * params.G_star * math.sqrt(params.d_max)),
                               2.0 * math.pi * params.dgamma0 * root / scale,
                               2.0 * math.pi * params.dgamma1 * root / scale)
