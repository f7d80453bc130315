"""Tolerances of the continuum method: the user's (:class:`Tolerances`) and the fixed, named ones."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mdr_events.validation import check_real, shown

#: A velocity component below this share of the speed is taken as zero (a segment that changes its
#: depth by 1e-90 m over 0.3 mm is a pinned slide: its growth ratio vx/vd would overflow the anchor map).
NEGLIGIBLE_SHARE = 1e-12
#: Depths within this share of ``d_max`` of a branch count as on it (first contact at ``d = -0``, a
#: regime switch at a depth found by a root).
DEPTH_SHARE = 1e-12
#: A depth reached at a planned time counts as reached within this many ulp of the time times the depth's
#: rate (a time of 1.7e7 s, a path at 1e-3°, is known to 4e-9 s).
TIME_ULPS = 4
#: Rising slip events cross a level this many ulp of the lengths involved above zero (see
#: :class:`~mdr_events.models.continuum.span.SpanIntegrator`).
LEVEL_ULPS = 16
#: A slip front within this share of the lengths involved of a piece's end is in the next piece. The
#: levels and piece values carry the rounding of the radius roots (``radius_rtol`` <= MAX_RADIUS_RTOL,
#: 1e-13, times the growth ratio's lever ``|v_x/v_d| d0'(a) a``, itself at most the travel of
#: :func:`~mdr_events.models.continuum.zones.indenter_travel`) and a few ulp of the positions: ten times
#: the loosest root is the smallest share that separates a front at a piece's end from the next piece.
PIECE_SHARE = 1e-12
#: Event roots this close (relative) fire together.
SIMULTANEOUS_SHARE = 1e-12
#: A radius that drops by more than this share at the start of detachment drops onto the Δγ1 branch.
RADIUS_DROP_SHARE = 1e-12
#: A path segment must last more than this share of its end time: event times are resolved to about
#: ``1e-12`` relative (the root-finding of the events, a few ulp of the time and of the lengths).
SEGMENT_RESOLUTION = 1e-10
#: A solver step covers at most this share of a span, 1/8: the smooth continuation of a slip zone past the
#: span's events ends where a front's piece meets the branch's fold, and a first step across the whole span
#: (DOP853 takes one where the force is nearly linear) can reach it (seen: 1.7e-3 of F_x off the
#: play-operator form on a pull-out with slip onset; 1e-12 with eight steps).
MIN_STEPS_PER_SPAN = 8
#: Restarts allowed at one instant before the solver reports it is stuck (each restart handles one event).
MAX_RESTARTS = 50
#: Spans in a row, each shorter than SEGMENT_RESOLUTION of the time, after which the slip zones are taken to chatter
#: and the run is refused (``RestartGuard`` of ``continuum.solve``). Runs that end were seen with
#: up to 3215 in a row (a power law c r^3 under Coulomb's law, mu = 1e5, scenario B at 80°: 4.6 s in all), the
#: chatter that did not end (a cone at mu = 1e6, scenario B at 20°) needed 4e5 to reach the pull-off: six times the
#: most seen in a run that ends, a few seconds of spans. That chatter was a zone of no width laid out at the shrinking
#: edge (``solve.edge_zone_beside_full``, round eighteen) and runs now; the guard stays, a net for any other.
MAX_CHATTER_SPANS = 20_000
#: The output times a case's solve is counted as, at least, against ``Limits.samples``: a continuum case's cost is its
#: solve, not its output (13 ms of CPU a case of the paper's scenario A here, with 11 output times as with 2001), so
#: that cases of a few output times each are counted too (1e5 angles at 11 samples each: 23 min of CPU, accepted,
#: round eighteen); the default output, 2001 times, so that runs of at least that many count as before (the default
#: 1e7 samples: 5000 cases, about a minute).
SOLVE_SAMPLES = 2001
#: Bytes one case's evaluation holds per output time beside the output (its spans' depths, radii and forces, the
#: masks, the quantities before they are stacked): the cases are evaluated one after another, so it is counted once a
#: run. Measured with tracemalloc on one case of 1e5 samples: 235-447 B (paraboloid, power law n = 1.5, flat punch;
#: tau0, coulomb, tau0+coulomb, the rate law; A and B), the run's peak 2.6-3.5 times the output's 128 B alone
#: (round twenty-nine); rounded up.
EVALUATION_BYTES_PER_SAMPLE = 512
#: Machine epsilon of the floats used.
EPS = float(np.finfo(float).eps)


#: The smallest ``rtol`` ``solve_ivp`` honours (it raises smaller ones to this, with a warning).
MIN_RTOL = 100 * EPS
#: The loosest ``radius_rtol``: the event logic separates slip fronts and piece ends to PIECE_SHARE (1e-12)
#: of the lengths, so a radius must be known better. The radius root converges quadratically: a looser
#: tolerance saves at most one Newton step.
MAX_RADIUS_RTOL = 1e-13
#: ``atol`` (N) is used up to this share of the run's force scale ``G* d_max²`` (:func:`force_atol`): 1e-12 of it
#: is above the default 1e-14 N for every run of the paper's moduli and depths (2.6e-14 N), so those are unchanged,
#: and below ``rtol``'s reach of every force of a run whose stresses are scaled down (round 29: ``E``, ``τ0``, ``Δγ``
#: times 1e-30 left the fixed 1e-14 N above every force, and Coulomb's B 20° off by 4.2e-4 of its peak).
FORCE_ATOL_SHARE = 1e-12


@dataclass(frozen=True)
class Tolerances:
    """Solver tolerances of the continuum method.

    Parameters
    ----------
    rtol : float, default 1e-10
        Relative tolerance of ``solve_ivp`` for ``F_x``, in [100 eps, 1) (default 1e-10).
    atol : float, default 1e-14
        Absolute tolerance (N) of ``solve_ivp`` for ``F_x``, finite and > 0 (default 1e-14 N).
    radius_rtol : float, default 1e-14
        Relative accuracy of the contact radius and slip front root-finding, in [eps, 1e-13]
        (default 1e-14; see :data:`MAX_RADIUS_RTOL`).

    Raises
    ------
    ValueError
        A tolerance out of its range.
    """

    rtol: float = 1e-10
    atol: float = 1e-14
    radius_rtol: float = 1e-14

    def __post_init__(self) -> None:
        allowed = {"rtol": (f"a number in [{MIN_RTOL:.3g}, 1)", lambda value: MIN_RTOL <= value < 1.0),
                   "atol": ("a finite number > 0 (N)", lambda value: value > 0.0),
                   "radius_rtol": (f"a number in [{EPS:.3g}, {MAX_RADIUS_RTOL:g}]",
                                   lambda value: EPS <= value <= MAX_RADIUS_RTOL)}
        for name, (words, valid) in allowed.items():
            object.__setattr__(self, name, check_real(f"Tolerances.{name}", getattr(self, name), words, valid))


def force_atol(tolerances: Tolerances, params) -> float:
    """The absolute tolerance (N) of a run's ``F_x``: ``tolerances.atol``, at most :data:`FORCE_ATOL_SHARE` of its
    force scale ``G* d_max²``.

    The MDR's forces scale with the stresses (``E``, ``τ0``, ``Δγ0``, ``Δγ1``) and the square of the lengths; a
    fixed absolute tolerance in N would hold a run of small stresses or lengths to nothing (every error below it
    accepted).

    Parameters
    ----------
    tolerances : Tolerances
        The user's.
    params : Parameters
        The run's (its ``G_star`` and ``d_max``).

    Returns
    -------
    float
        The ``atol`` passed to the solver, > 0.
    """
    scale = FORCE_ATOL_SHARE * params.G_star * params.d_max ** 2
    return tolerances.atol if not scale > 0.0 else min(tolerances.atol, scale)


def check_tolerances(tolerances) -> Tolerances:
    """``tolerances`` if it is a :class:`Tolerances`; else ``TypeError`` naming it (``Continuum(tolerances=...)``
    and :func:`~mdr_events.models.continuum.solve.run_continuum` take them)."""
    if not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances={shown(tolerances)} is not allowed; allowed: a mdr_events.Tolerances")
    return tolerances


def check_output(limits, cases: int, n_time: int, bytes_per_sample: float) -> None:
    """Check a continuum run of ``cases`` cases of ``n_time`` output times each against ``limits`` (a
    :class:`~mdr_events.limits.Limits`): the samples, each case's solve counted as ``SOLVE_SAMPLES`` at least, and
    the memory of the output (``bytes_per_sample`` each) with one case's evaluation (``EVALUATION_BYTES_PER_SAMPLE``).

    Parameters
    ----------
    limits : Limits
        What the run may use.
    cases : int
        The paths solved.
    n_time : int
        The output times of each.
    bytes_per_sample : float
        The output's bytes per case and time.

    Raises
    ------
    ResourceLimitError
        Samples or memory beyond ``limits``.
    """
    note = "" if n_time >= SOLVE_SAMPLES else f", each case's solve counted as {SOLVE_SAMPLES}"
    limits.check(f"the continuum run ({cases} case(s) of {n_time} output times{note})",
                 samples=max(n_time, SOLVE_SAMPLES) * cases,
                 memory=n_time * (cases * bytes_per_sample + EVALUATION_BYTES_PER_SAMPLE))
