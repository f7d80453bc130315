"""Whether a run's numbers fit in double precision: its scales, checked before it runs.

The model multiplies its scales pairwise (``a²``, ``E* a d``, ``μ F_N``, ``x ± ū``), so a run whose every scale lies
within the square root of double precision's range, :data:`SCALE_MIN` to :data:`SCALE_MAX` (about 1.5e-154 to
1.3e154 in SI units), keeps every product finite and normal. A scale outside, or a relation that overflows on the way
(``Γ(n/2 + 1)`` of a power law's stretch factor beyond ``n ≈ 341``), would give ``inf`` or ``nan`` results; the run is
refused before it starts instead, naming the scale, its value and the bound (:func:`check_representable`). A scale
that is exactly 0 (no adhesion, no ``τ0``) is fine.
"""

from __future__ import annotations

import math
import warnings
from typing import Callable, NamedTuple

from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.memo import kept
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import Profile
from mdr_events.theory import analytic, mindlin
from mdr_events.theory.branches import branch_radius, jump_off
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import SCALE_MAX, SCALE_MIN

__all__ = ["SCALE_MAX", "SCALE_MIN", "Scale", "run_scales", "check_representable", "SCALES_KEPT"]

#: How many contacts :func:`check_representable` keeps as passed (those of a sweep's chunk, of a fit's last steps).
SCALES_KEPT = 64


class Scale(NamedTuple):
    """One scale of a run: what it is, its value (``nan`` if it could not be computed), its unit, and why not."""

    name: str
    value: float
    unit: str
    failure: str = ""  #: why it could not be computed ("overflows (...)", "cannot be computed (...)"), "" if it was


def _scale(name: str, unit: str, compute: Callable[[], float]) -> Scale:
    """The scale ``name`` as ``compute`` gives it, or its failure: an overflow on the way, or a closed form refusing
    what it was handed (a radius beyond ``SCALE_MAX`` from ``R = 1e300``: the relation's own message had named
    ``contact_radius=4.7e+197`` before the scale that gave it, in every entry point). Run inside :func:`run_scales`'s
    filter, where NumPy's overflow is an error, as math's is."""
    try:
        return Scale(name, float(compute()), unit)
    except (OverflowError, ZeroDivisionError, RuntimeWarning, FloatingPointError) as error:
        return Scale(name, math.nan, unit, f"overflows ({str(error) or type(error).__name__})")
    except ValueError as error:
        return Scale(name, math.nan, unit, f"cannot be computed ({error})")


def run_scales(params: Parameters, profile: Profile | None = None, friction: FrictionLaw = TAU0,
               adhesion: bool = True) -> list[Scale]:
    """The scales of a run of ``params`` with ``profile`` and ``friction``: moduli, depth, the contact radius and
    normal force at ``d_max``, the critical shift ``ū`` and Coulomb's cap there, the full-slip force, the time to
    ``d_max`` and, with adhesion, the jump-off of the ``Δγ1`` branch.

    ``adhesion=False`` reads neither work of adhesion: the radius is the non-adhesive contact's and no jump-off is
    among the scales (a slip onset without adhesion, :func:`~mdr_events.theory.power_law.arguments.check_onset_scales`), as a
    copy of ``params`` with both works 0 would give, without making one."""
    known: dict[str, object] = {}  # (each computed once: a sweep checks every value of its grid)
    work = params.dgamma0 if adhesion else 0.0

    def radius() -> float:  # (a table's reach is checked apart, with its own message: check_reach)
        if "radius" not in known:
            known["radius"] = float(branch_radius(_deepest_reached(params, profile, work), params, work, profile))
        return known["radius"]

    def jump(key: str) -> float:
        if "jump" not in known:
            known["jump"] = jump_off(params, params.dgamma1, profile)
        return known["jump"][key]

    with warnings.catch_warnings():  # (one filter for every scale: numpy's overflow is an error, as math's is)
        warnings.simplefilter("error", RuntimeWarning)
        return _scales(params, profile, friction, radius, jump if adhesion else None)


def _scales(params: Parameters, profile: Profile | None, friction: FrictionLaw, radius: Callable[[], float],
            jump: Callable[[str], float] | None) -> list[Scale]:
    """:func:`run_scales`'s list, ``radius`` and ``jump`` computing the radius at ``d_max`` and the jump-off once
    (``jump`` ``None``: no work of adhesion read)."""
    scales = [Scale("E*", params.E_star, "Pa"), Scale("G*", params.G_star, "Pa"), Scale("d_max", params.d_max, "m"),
              Scale("the time to d_max, d_max / v", params.d_max / params.v, "s"),
              _scale("the contact radius a at d_max", "m", radius),
              _scale("the normal force scale E* a d_max", "N", lambda: params.E_star * radius() * params.d_max)]
    if friction.uses_tau0:
        scales += [_scale("the critical shift ū(a) at d_max", "m",
                          lambda: float(analytic.critical_shift(radius(), params))),
                   _scale("the full-slip force τ0 π a²", "N", lambda: params.tau0 * math.pi * radius() ** 2)]
    if friction.uses_mu:
        scales.append(_scale("Coulomb's cap μ (E*/G*) d_max", "m",
                             lambda: mindlin.coulomb_cap_ratio(friction, params) * params.d_max))
    if jump is not None and params.dgamma1 > 0:
        for key, unit in (("contact_radius", "m"), ("depth", "m"), ("normal_force", "N")):
            scales.append(_scale(f"the jump-off's {key.replace('_', ' ')} on the Δγ1 branch", unit,
                                 lambda key=key: jump(key)))
    return scales


def _deepest_reached(params: Parameters, profile: Profile | None, work_of_adhesion: float) -> float:
    """``d_max``, or a table's deepest reach on the branch of ``work_of_adhesion`` if less (the depth beyond is refused
    by :func:`~mdr_events.models.indenters.check_reach`, naming the table)."""
    try:
        return min(params.d_max, theory_of(profile).deepest(profile, params, work_of_adhesion))
    except (ValueError, ArithmeticError):  # (the radius's own scale then names what fails)
        return params.d_max


def check_representable(params: Parameters, profile: Profile | None = None, friction: FrictionLaw = TAU0,
                         adhesion: bool = True) -> None:
    """Refuse a run whose scales (:func:`run_scales`) do not fit in double precision.

    Parameters
    ----------
    params : Parameters
        The run's material, ``τ0``, works of adhesion, ``d_max`` and speed.
    profile : Profile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    friction : FrictionLaw, optional
        The law, whose Coulomb part is a scale of its own (default the paper's ``"tau0"``).
    adhesion : bool, optional
        Whether the works' branches are read (default); ``False``: the non-adhesive contact's scales, the works
        named in a refusal as given (a slip onset without adhesion).

    Raises
    ------
    ValueError
        Naming the first scale that overflows or lies outside ``[SCALE_MIN, SCALE_MAX]`` (0 is fine), its value,
        the parameters and indenter it follows from, and the bound.
    """
    _check_representable(params, profile, friction, adhesion)


@kept(SCALES_KEPT)
def _check_representable(params: Parameters, profile: Profile | None, friction: FrictionLaw, adhesion: bool) -> None:
    """:func:`check_representable`, kept for the last :data:`SCALES_KEPT` contacts it passed
    (:func:`~mdr_events.memo.kept`: a run's set-up checks its contact once or twice, a benchmark's or a study's
    runs the same contact again; some 30 µs a time). A refusal is never kept: it is raised again, by name."""
    for scale in run_scales(params, profile, friction, adhesion):
        magnitude = abs(scale.value)
        if scale.failure or not math.isfinite(magnitude) or (magnitude != 0.0 and
                                                              not SCALE_MIN <= magnitude <= SCALE_MAX):
            value = (scale.failure if scale.failure else f"is not finite ({scale.value!r})"
                     if not math.isfinite(magnitude) else f"is {scale.value:.3g} {scale.unit}")
            indenter = f"R={params.R!r} m" if profile is None else f"profile={profile!r}"
            law = "" if friction.is_default else f", friction={friction!r}"
            unread = "" if adhesion else " (not read: without adhesion)"
            raise ValueError(f"E={params.E!r} Pa, nu={params.nu!r}, {indenter}, tau0={params.tau0!r} Pa, "
                             f"dgamma0={params.dgamma0!r} J/m², dgamma1={params.dgamma1!r} J/m²{unread}, "
                             f"d_max={params.d_max!r} m, v={params.v!r} m/s{law}: {scale.name} {value}; allowed: "
                             f"parameters whose scales lie within {SCALE_MIN:.2g} to {SCALE_MAX:.2g} in SI units (or "
                             "are 0), so that their products stay finite in double precision")
