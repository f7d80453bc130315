r"""The critical angle of scenario A against the path's speed, under rate-dependent adhesion.

In scenario A (14) every spring in contact attached while the indenter moved at the angle α; the first one, at the
centre, carries the largest shift ``x(t)``, while ``τ0``'s cap ``ū = K a(t)`` (13) is the same for all. Slip begins
where ``x = K a``: with ``x = d cot α``, at ``d_max`` exactly when

.. math:: \tan\alpha_c\, K\, a(d_\mathrm{max}) = d_\mathrm{max} \qquad (17), (18)

as in the paper, but with the radius the rate-dependent edge reaches at ``d_max``
(:func:`~mdr_events.models.continuum.solve_edge`: the normal problem, which sees the depth only, ``ḋ = v sin α``).
The advancing edge's work ``Δγ0 / [1 + (ȧ/v_ref)^n]`` falls with its speed, so a faster path reaches a smaller
radius, and the angle rises from the adhesive value (18) (``v → 0``, or ``v_ref → ∞``: the paper) towards the
non-adhesive one (17) (the edge's work → 0). The angle solves one equation in α (Brent's method), each evaluation a
solve of the way in at the vertical speed ``v sin α``.

The phase diagram of scenario A at a speed (Fig. 9a's curves) is the slip-onset depth at each angle: the first depth
on the way in at which ``d = tan α K a(d; v sin α)``, found on the edge's dense output (sampled, then Brent's method
between the samples that change sign); the path goes on at the angle beyond ``d_max``, to the depth where slip
begins, as (17) and (18) do.

Scenario B's angle is not defined this way at a finite ``v_ref``: the paper's contact jumps off at a finite radius
before its springs slide (eq. (21) at the jump-off), while a rate-dependent edge comes apart over a finite time in
which its radius, and with it the cap ``K a``, falls to 0 while the indenter's shift does not. Its angle compares the
slip with the point where the edge lets go (:mod:`~mdr_events.analysis.rate_let_go`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence
from typing import Any

import numpy as np
import xarray as xr
from scipy import optimize

from mdr_events.analysis.rate_job import rate_job
from mdr_events.contact.adhesion import RateDependentAdhesion, check_rate_law
from mdr_events.contact.model import Contact
from mdr_events.io.datasets import register_schema
from mdr_events.models.continuum.rate_edge import EDGE_RTOL, solve_edge
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.limits import Limits, check_limits
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law
from mdr_events.models.indenters import check_simulated_profile
from mdr_events.theory.scales import check_representable
from mdr_events.validation import check_distinct, check_real, shown

__all__ = ["critical_angle_at_speed", "critical_angles_at_speeds", "slip_onset_depth_at_speed",
           "phase_diagram_at_speeds", "check_rate_factor", "ANGLE_XTOL", "LEAST_RATE_FACTOR", "ONSET_SAMPLES",
           "EDGE_SOLVE_STEPS", "CRITICAL_ANGLE_SOLVES", "RATE_ANGLES_CONTENT"]

#: The ``content`` attribute of the critical angles against the speed (scenario A's here, B's in
#: :mod:`~mdr_events.analysis.rate_let_go`; the schema registered below, read by ``open_result``).
RATE_ANGLES_CONTENT = "critical angle against the path's speed under a rate-dependent adhesion law"

#: Brent's tolerance on the angle (rad): the radius at ``d_max`` is known to about 1e-9 of itself (the edge's ODE at
#: its ``rtol``), which moves the angle by about as much; 1e-12 rad lies below it.
ANGLE_XTOL = 1e-12
#: The bracket of the angle (rad): a path at 1e-6 rad from the surface or the vertical (its ``v sin α`` or
#: ``cot α`` at the ends of the double range of a path's clock).
_BRACKET = (1e-6, 0.5 * math.pi - 1e-6)
#: The samples of the way in on which the slip onset's sign change is looked for (then Brent's method between two):
#: the margin ``tan α K a − d`` is concave on the way in (the radius grows ever slower with the depth), so it changes
#: sign once.
ONSET_SAMPLES = 513
#: What one solve of the edge counts against :attr:`~mdr_events.Limits.steps` (about 0.05 to 0.5 s here: the
#: discrete model's 2e7 steps, about 30 s, are 2000 solves), so that a grid of speeds and angles is checked before it
#: runs (1e5 angles ran for hours).
EDGE_SOLVE_STEPS = 1e4
#: The solves of the edge one critical angle takes (Brent's method on :data:`_BRACKET` to :data:`ANGLE_XTOL`:
#: about 40, and the radius at the angle found).
CRITICAL_ANGLE_SOLVES = 50
#: The least rate factor ``(v/v_ref)^n`` at the path's speed a law may have here: the edge's ODE reads a release rate
#: within ``BAND_SHARE`` (1e-9) of a work at rest as rest, so it does not follow a law whose works at the path's speeds
#: come that near their values at rest (n = 1 on the paper's contact: solved at 1e-8, refused at 1e-9 after 1000
#: pieces; ``v_ref = 1e300``: the solver's own failure); 100 ``BAND_SHARE`` leaves a decade's margin, and a law below
#: it is its rate-independent limit ``v_ref → ∞`` to about that share (scenario A's angle within 1e-9 of (18)
#: there).
LEAST_RATE_FACTOR = 1e-7
#: The way in reaches ``d_max`` first, and twice as deep each time no spring slid on it, at most this many times.
_MAX_DOUBLINGS = 40


def _checked(params: Parameters, law: RateDependentAdhesion, speed, profile: SimulatedProfile,
             ) -> tuple[RateDependentAdhesion, float]:
    """The law and the speed of a rate-dependent angle or onset, every argument checked before a solve: ``params`` a
    Parameters, the law, the speed finite and > 0, the profile, and the run's scales at that speed within the double
    range (:func:`~mdr_events.theory.scales.check_representable`: ``speed = 1e300`` leaves a path of 1e-304 s), and
    the law's rate factor at the speed at least :data:`LEAST_RATE_FACTOR`."""
    if not isinstance(params, Parameters):
        raise TypeError(f"params={shown(params)} ({type(params).__name__}) is not allowed; allowed: a Parameters")
    law = check_rate_law(law)
    speed = check_real("speed", speed, "a finite number > 0 (m/s)", lambda value: value > 0.0)
    profile = check_simulated_profile(profile)
    check_rate_factor(law, speed)
    try:
        check_representable(params.replace(v=speed), profile)
    except ValueError as error:
        raise ValueError(f"speed={shown(speed)} m/s: {error}") from None
    return law, speed


def _job(contact, speeds, old: tuple, law, profile, d_max, method: str, limits, what: str) -> tuple:
    """The arguments of a function of angles against speeds, checked once before a solve
    (:func:`~mdr_events.analysis.rate_job.rate_job`, the speeds' grid and each speed's scales): ``params``, the law,
    the profile, the speeds, the method and the limits."""
    job = rate_job(contact, speeds, old, law, profile, d_max, what)
    limits = job.options.get("limits", limits)
    speeds = _grid("speeds", job.speeds, "finite numbers > 0 (m/s)", lambda v: v > 0.0,
                   lambda count: _check_solves(limits, f"{what} of {count} speeds", CRITICAL_ANGLE_SOLVES * count))
    for speed in speeds:
        _checked(job.params, job.law, speed, job.profile)
    return job.params, job.law, job.profile, speeds, job.options.get("method", method), limits


def check_rate_factor(law: RateDependentAdhesion, speed: float, name: str = "law") -> None:
    """Refuse a law whose rate factor ``(speed/v_ref)^n`` at the path's ``speed`` is below
    :data:`LEAST_RATE_FACTOR` (computed in logarithms: ``speed/v_ref`` may underflow), naming the bound on ``v_ref``.

    Parameters
    ----------
    law : RateDependentAdhesion
        The adhesion law.
    speed : float
        The path's speed (m/s, finite and > 0).
    name : str, optional
        The law's name in the message.

    Raises
    ------
    ValueError
        A law at its rate-independent limit to :data:`LEAST_RATE_FACTOR`, with the largest ``v_ref`` allowed.
    """
    log_factor = law.n * (math.log(speed) - math.log(law.v_ref))
    if log_factor < math.log(LEAST_RATE_FACTOR):  # (v_ref = 1e300 ended in the edge solver's own words)
        raise ValueError(f"{name}.v_ref={law.v_ref!r} m/s is not allowed at speed={speed!r} m/s with n={law.n!r}: the "
                         f"rate factor (speed/v_ref)^n = {math.exp(log_factor):.3g} is below {LEAST_RATE_FACTOR:g}, "
                         "where the law is its rate-independent limit (v_ref -> inf); allowed: v_ref <= "
                         f"{math.exp(math.log(speed) - math.log(LEAST_RATE_FACTOR) / law.n):.6g} m/s, or that limit: "
                         "the rate-independent law Adhesion(dgamma0, dgamma1) (critical_angle, d_crit, phase_diagram, "
                         "fit)")


def _grid(name: str, values, allowed: str, valid, counted: Callable[[int], None] | None = None) -> list[float]:
    """A non-empty 1-D grid of speeds or angles, each checked (``name[i]`` named), else a one-line error; ``counted``
    is given the grid's size before any value is read (the solves it asks for counted against the limits: 1e8 speeds
    were read one by one, minutes and gigabytes, before they were refused)."""
    unordered = (str, bytes, set, dict, Iterator)  # (a generator was read as one value: "speeds[0]=<generator ...>")
    array = values if isinstance(values, np.ndarray) else np.asarray(values, dtype=object)
    if array.ndim > 1 or array.size == 0 or isinstance(values, unordered):
        raise (TypeError if isinstance(values, unordered) else ValueError)(
            f"{name}={shown(values)} is not allowed; allowed: a non-empty 1-D sequence of {allowed}")
    if counted is not None:
        counted(int(array.size))
    checked = [check_real(f"{name}[{index}]", value, allowed, valid)
               for index, value in enumerate(np.atleast_1d(array).astype(object))]
    check_distinct(name, checked, values)
    return checked


def _check_solves(limits, what: str, solves: int) -> None:
    """Count ``solves`` of the edge against ``limits`` (:data:`EDGE_SOLVE_STEPS` each) before the first."""
    check_limits(limits).check(f"{what} ({solves} solves of the edge)", steps=float(solves) * EDGE_SOLVE_STEPS)


def _onset_solves(params: Parameters, angles: list[float], profile: SimulatedProfile) -> int:
    """The solves of the edge the slip-onset depths at ``angles`` take at most, at any speed: one to ``d_max`` and one
    more each time the way in doubles, up to the rate-independent adhesive onset (18) (the phase diagram's
    ``d_crit_jkr``), which bounds the rate-dependent one from above (an advancing edge's work is below ``Δγ0``, so its
    radius lies below the ``Δγ0`` branch's and the springs slide sooner), at most :data:`_MAX_DOUBLINGS` per angle
    (a steep angle took 35 solves where one was counted: 1000 of them were allowed, for hours)."""
    from mdr_events.theory.phase import phase_diagram  # (the closed forms of every indenter the simulators take)

    bound = phase_diagram(params, np.array(angles), scenario="A", profile=profile)["d_crit_jkr"].values
    with np.errstate(divide="ignore", invalid="ignore"):
        doublings = np.ceil(np.log2(np.maximum(np.abs(bound) / params.d_max, 1.0)))
    solves = 1.0 + np.nan_to_num(doublings, nan=_MAX_DOUBLINGS, posinf=_MAX_DOUBLINGS)
    return int(np.sum(np.minimum(solves, _MAX_DOUBLINGS)))


def _bracketed_root(margin, what: str) -> float:
    """The angle (rad) in :data:`_BRACKET` where ``margin`` changes sign (Brent's method), or a one-line ``ValueError``
    saying on which side the critical angle lies when it does not change sign there (not scipy's words)."""
    known = {end: margin(end) for end in _BRACKET}  # (Brent's method starts from the ends: each solved once)
    low, high = known.values()
    if low < 0.0 <= high or high < 0.0 <= low:
        return optimize.brentq(lambda alpha: known[alpha] if alpha in known else margin(alpha), *_BRACKET,
                               xtol=ANGLE_XTOL)
    side = ("the springs slide before d_max at every angle up to 90° - 1e-6 rad: the critical angle is 90° to "
            "that precision" if high < 0.0 else "no spring slides before d_max at any angle down to 1e-6 rad: the "
            "critical angle is 0° to that precision")
    raise ValueError(f"{what}: {side}; allowed: parameters, law and speed whose critical angle lies within "
                     f"[{math.degrees(_BRACKET[0]):.3g}°, {math.degrees(_BRACKET[1]):.8g}°]")


def _law_attrs(law: RateDependentAdhesion) -> dict[str, object]:
    """A result's attributes: the scenario and the law's values."""
    return dict(scenario="A", adhesion_law="rate_dependent", v_ref=law.v_ref, n=law.n, dgamma0=law.dgamma0,
                dgamma1=law.dgamma1)


def _radius_at_depth(params: Parameters, law: RateDependentAdhesion, speed: float, alpha: float,
                     profile: SimulatedProfile, rtol: float, method: str) -> float:
    """The radius the edge reaches at ``d_max`` on the way in at the angle ``alpha`` (rad) and ``speed``."""
    path = Path(np.array([(0.0, 0.0), (params.d_max / math.tan(alpha), params.d_max)]), speed=speed)
    run = solve_edge(params, path, law, profile=profile, rtol=rtol, method=method)
    return float(run.radius(np.array([path.duration]))[0])


def critical_angle_at_speed(params: Parameters, law: RateDependentAdhesion, speed: float,
                            profile: SimulatedProfile = None, rtol: float = EDGE_RTOL, method: str = "Radau") -> float:
    r"""The critical angle of scenario A (degrees) at the path's ``speed`` under the rate-dependent ``law``.

    .. math:: \tan\alpha_c\, \frac{\pi \tau_0}{2 G^*}\, a(d_\mathrm{max};\ v \sin\alpha_c) = d_\mathrm{max}
              \qquad (13), (17), (18)

    Parameters
    ----------
    params : Parameters
        The material, ``τ0``, ``d_max`` and ``R`` (the paraboloid's); its works of adhesion are the law's at rest.
    law : RateDependentAdhesion
        The adhesion law.
    speed : float
        The path's speed ``v`` (m/s), finite and > 0.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    rtol : float, optional
        The edge's ODE tolerance (:func:`~mdr_events.models.continuum.solve_edge`).
    method : str, optional
        The edge's ``solve_ivp`` method (:data:`~mdr_events.models.continuum.rate_edge.EDGE_METHODS`; Radau, the
        reference, or LSODA, about seven times faster within 2e-9 of its radii).

    Returns
    -------
    float
        ``α_c`` in degrees: below it the springs slide before ``d_max`` (90 where ``τ0 = 0``: slip from the start).

    Raises
    ------
    ValueError
        A ``speed`` that is not a finite number > 0, or what :func:`~mdr_events.models.continuum.solve_edge` refuses.
    """
    law, speed = _checked(params, law, speed, profile)
    cap = power_law.cap_per_radius(params)
    if cap == 0.0:
        return 90.0

    def margin(alpha: float) -> float:  # K a tan α − d_max over d_max: < 0 slides before d_max
        radius = _radius_at_depth(params, law, speed, alpha, profile, rtol, method)
        return cap * radius * math.tan(alpha) / params.d_max - 1.0

    return math.degrees(_bracketed_root(margin, f"the critical angle at speed={speed!r} m/s"))


def critical_angles_at_speeds(contact: Contact | Parameters, speeds: Sequence[float] | None = None, *old: Any,
                              law: RateDependentAdhesion | None = None, profile: SimulatedProfile = None,
                              method: str = "Radau", limits: Limits | None = None, d_max: float | None = None) -> xr.Dataset:
    """:func:`critical_angle_at_speed` at each of ``speeds``, labelled, with the rate-independent limits.

    Parameters
    ----------
    contact : Contact or Parameters
        A :class:`~mdr_events.Contact` whose adhesion is a :class:`~mdr_events.RateDependentAdhesion`, its friction law
        ``"tau0"``, on the half-space (:func:`~mdr_events.analysis.rate_job.rate_job`). Or the form of before:
        :class:`~mdr_events.Parameters` (the material, ``τ0``, ``d_max``, ``R``; its works of adhesion the law's at
        rest), called ``critical_angles_at_speeds(params, law, speeds[, profile, method, limits])``.
    speeds : sequence of float
        The paths' speeds (m/s); in the form of before, by position, the law (the speeds after it).
    *old
        Only in the form of before: the speeds, then ``profile``, ``method``, ``limits`` by position.
    law : RateDependentAdhesion, optional
        Only beside Parameters (a contact holds its own).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        Only beside Parameters: the indenter (``None``: the paraboloid of ``params.R``).
    method : str, optional
        The edge's ``solve_ivp`` method (as :func:`critical_angle_at_speed`).
    limits : Limits or None, optional
        The solves of the edge allowed (:data:`CRITICAL_ANGLE_SOLVES` per speed, :data:`EDGE_SOLVE_STEPS` steps each;
        ``None``: the defaults), checked before the first.
    d_max : float, optional
        Only beside a Contact: the depth of the scenario (m, finite, > 0; default the paper's 0.3 mm).

    Returns
    -------
    xarray.Dataset
        ``critical_angle`` (degree) and ``contact_radius`` (m, at ``d_max`` on the way in at that angle) against
        ``speed``; the attributes ``critical_angle_adhesive`` (the paper's (18), the limit ``v → 0``) and
        ``critical_angle_hertz`` ((17), the edge's work → 0) where the paraboloid has them, and the law's values.

    Raises
    ------
    ValueError
        A speed that is not a finite number > 0, or what :func:`critical_angle_at_speed` refuses.
    """
    params, law, profile, speeds, method, limits = _job(contact, speeds, old, law, profile, d_max, method, limits,
                                                        "critical_angles_at_speeds")
    angles = np.array([critical_angle_at_speed(params, law, speed, profile, EDGE_RTOL, method) for speed in speeds])
    radii = np.array([_radius_at_depth(params, law, speed, math.radians(angle), profile, EDGE_RTOL, method)
                      if angle < 90.0 else math.nan for speed, angle in zip(speeds, angles)])
    dataset = xr.Dataset(
        {"critical_angle": ("speed", angles, {"units": "degree", "long_name": "critical angle of scenario A"}),
         "contact_radius": ("speed", radii, {"units": "m", "long_name": "contact radius at d_max at that angle"})},
        coords={"speed": ("speed", np.array(speeds), {"units": "m s-1", "long_name": "the path's speed"})})
    dataset.attrs.update(_law_attrs(law), edge_method=method, content=RATE_ANGLES_CONTENT)
    if profile is None:
        from mdr_events.theory.analytic import critical_angle  # (the paraboloid's closed forms)
        dataset.attrs.update(critical_angle_adhesive=critical_angle(params, "A", adhesion=True),
                             critical_angle_hertz=critical_angle(params, "A", adhesion=False))
    return dataset


def slip_onset_depth_at_speed(params: Parameters, law: RateDependentAdhesion, speed: float, alpha: float,
                              profile: SimulatedProfile = None, rtol: float = EDGE_RTOL,
                              method: str = "Radau") -> float:
    r"""The depth (m) at which the springs begin to slide on the way in of scenario A at the angle ``alpha`` and the
    path's ``speed``, under the rate-dependent ``law``: the first root of ``tan α K a(d; v sin α) = d``, the
    rate-dependent (18).

    Parameters
    ----------
    params : Parameters
        The material, ``τ0`` and ``R`` (the paraboloid's); its works of adhesion are the law's at rest.
    law : RateDependentAdhesion
        The adhesion law.
    speed : float
        The path's speed ``v`` (m/s), finite and > 0.
    alpha : float
        The angle (degrees), in (0, 90).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    rtol : float, optional
        The edge's ODE tolerance.
    method : str, optional
        The edge's ``solve_ivp`` method (:data:`~mdr_events.models.continuum.rate_edge.EDGE_METHODS`).

    Returns
    -------
    float
        The slip-onset depth (m); ``inf`` where ``τ0 = 0`` would make it 0 instead (then 0).

    Raises
    ------
    ValueError
        A ``speed`` or ``alpha`` out of range, or what :func:`~mdr_events.models.continuum.solve_edge` refuses.
    """
    law, speed = _checked(params, law, speed, profile)
    alpha = check_real("alpha", alpha, "a number of degrees in (0, 90)", lambda value: 0.0 < value < 90.0)
    cap, tangent = power_law.cap_per_radius(params), math.tan(math.radians(alpha))
    if cap == 0.0:
        return 0.0
    reach = params.d_max
    for _ in range(_MAX_DOUBLINGS):
        path = Path(np.array([(0.0, 0.0), (reach / tangent, reach)]), speed=speed)
        run = solve_edge(params, path, law, profile=profile, rtol=rtol, method=method)

        def margin(t):  # tan α K a − d (m): < 0 beyond the onset
            return tangent * cap * run.radius(t) - path.position(t)[1]
        times = np.linspace(run.pieces[0][0], path.duration, ONSET_SAMPLES)  # (from the jump-in's start)
        below = np.flatnonzero(margin(times) <= 0.0)
        if below.size:
            first = int(below[0])
            if first == 0:
                return 0.0
            when = optimize.brentq(lambda t: float(margin(np.array([t]))[0]), times[first - 1], times[first],
                                   xtol=ANGLE_XTOL * path.duration)
            return float(path.position(when)[1])
        reach *= 2.0
    raise ValueError(f"alpha={alpha!r}: no spring slid on the way in to {reach!r} m; allowed: an angle whose springs "
                     "slide within 2^40 d_max")


def phase_diagram_at_speeds(params: Parameters, law: RateDependentAdhesion, speeds: Sequence[float], alpha,
                            profile: SimulatedProfile = None, method: str = "Radau",
                            limits: Limits | None = None) -> xr.Dataset:
    """Scenario A's phase diagram (Fig. 9a) at each of ``speeds``: the slip-onset depth against the angle.

    Parameters
    ----------
    params : Parameters
        The material, ``τ0``, ``d_max`` and ``R``; its works of adhesion are the law's at rest.
    law : RateDependentAdhesion
        The adhesion law.
    speeds : sequence of float
        The paths' speeds (m/s).
    alpha : array_like
        The angles (degrees), each in (0, 90).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    method : str, optional
        The edge's ``solve_ivp`` method (Radau, the reference; LSODA about seven times faster within 2e-9).
    limits : Limits or None, optional
        The solves of the edge allowed (:data:`EDGE_SOLVE_STEPS` steps each; ``None``: the defaults), checked before
        the first: per speed and angle one to ``d_max`` and one per doubling of the way in up to the
        rate-independent onset (18), which bounds the rate-dependent one.

    Returns
    -------
    xarray.Dataset
        ``d_crit`` (m) against ``speed`` and ``alpha``; for the paraboloid also the rate-independent ``d_crit_jkr``
        (18) and ``d_crit_hertz`` (17) against ``alpha`` (the limits ``v → 0`` and the edge's work → 0), and
        ``d_max``.

    Raises
    ------
    ValueError
        A speed or angle out of range, or what :func:`slip_onset_depth_at_speed` refuses.
    """
    speeds = _grid("speeds", speeds, "finite numbers > 0 (m/s)", lambda v: v > 0.0,
                   lambda count: _check_solves(limits, f"the phase diagram at {count} speeds and an angle or more", count))
    angles = _grid("alpha", alpha, "numbers of degrees in (0, 90)", lambda a: 0.0 < a < 90.0,
                   lambda count: _check_solves(limits, f"the phase diagram at {len(speeds)} speeds and {count} "
                                               "angles, a solve each at least", len(speeds) * count))  # (at least one solve each)
    for speed in speeds:  # (every argument in its own words before the solves are counted)
        _checked(params, law, speed, profile)
    _check_solves(limits, f"the phase diagram at {len(speeds)} speeds and {len(angles)} angles",
                  len(speeds) * _onset_solves(params, angles, profile))
    depths = np.array([[slip_onset_depth_at_speed(params, law, speed, angle, profile, EDGE_RTOL, method)
                        for angle in angles] for speed in speeds])
    dataset = xr.Dataset(
        {"d_crit": (("speed", "alpha"), depths, {"units": "m", "long_name": "slip-onset depth of scenario A"}),
         "d_max": ((), params.d_max, {"units": "m", "long_name": "the deepest point of scenario A"})},
        coords={"speed": ("speed", np.array(speeds), {"units": "m s-1", "long_name": "the path's speed"}),
                "alpha": ("alpha", np.array(angles), {"units": "degree", "long_name": "path angle"})})
    dataset.attrs.update(_law_attrs(law), edge_method=method, content=RATE_ANGLES_CONTENT)
    if profile is None:
        from mdr_events.theory.phase import phase_diagram  # (the paraboloid's closed forms)
        closed = phase_diagram(params, np.array(angles), scenario="A")
        for name, text in (("d_crit_jkr", "slip-onset depth, rate-independent with adhesion (18)"),
                           ("d_crit_hertz", "slip-onset depth without adhesion (17)")):
            dataset[name] = ("alpha", closed[name].values, {"units": "m", "long_name": text})
    return dataset


register_schema(RATE_ANGLES_CONTENT, {"critical_angle": ("speed",)})
