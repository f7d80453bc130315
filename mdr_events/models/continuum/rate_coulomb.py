r"""The continuum method under a rate-dependent adhesion law with Coulomb's part of the friction law.

Under :class:`~mdr_events.contact.adhesion.RateDependentAdhesion` with ``"coulomb"`` or ``"tau0+coulomb"`` each
spring's cap is ``ū(a) + μ (E*/G*) max(d − g(ξ), 0)``: the springs in tension (the adhesive annulus beyond ``x_c``,
``g(x_c) = d``) hold ``ū(a)`` alone (nothing under ``"coulomb"``), the compressed ones more the more they are pressed.
Which route is exact, and simpler:

- the closed-form play of :mod:`.rate_shifts` / :mod:`.rate_play` needs one window ``x ± K a`` shared by every
  spring. The compressed springs share one up to a shift (``x − K a − μρ d`` plus ``μρ g(ξ)``), the tensile ones
  another, and a spring changes from one to the other where ``d`` crosses ``g(ξ)``: its anchor is composed across
  those crossings, each spring at its own times, which no shared level carries. Extending it means the per-spring
  composition anyway.
- the per-spring route (:mod:`.play_springs`) composes each spring's play operator exactly in time for any cap and
  any radius history, with the crossings of ``d = g(ξ)`` in each spring's chain. It needs the radius as a history
  (:class:`~.rate_history.RateHistory`: the edge's pieces, its jumps in and off, each spring's attachment) and is
  exact where ``ū(a(t))`` is concave between the clamp times, sampled on every run (the edge's pieces are, on the
  paths of the tests; where they are not each spring gains its own extremes).

So the second: :func:`run_rate_coulomb` runs the normal problem as :func:`~.rate_run.run_rate_continuum` does (the
radius an ODE state; the springs' ``τ0`` part on top, whose tangential results it then replaces), and replaces
``F_x``, the sliding fraction, the springs' events and the extrema of ``F_x`` by the per-spring route's on the
edge's history, as :func:`~.play_run.run_play_springs` does on the spans' (the same sampling, events and extrema).
As ``v_ref → ∞`` it is the rate-independent continuum of the works at rest; at ``μ = 0`` the rate continuum of
``"tau0"``; in full slip ``F_x = τ0 π a² + μ F_N^H(d)`` (``F_N^H`` the compressed springs' normal force, Hertz's
``(4/3) E* R^(1/2) d^(3/2)`` on the paraboloid).
"""

from __future__ import annotations

import numpy as np

from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.friction import FrictionLaw
from mdr_events.limits import Limits
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.validation import shown

from .play_run import _SPRING_EVENTS, spring_run
from .play_springs import PlaySprings, spring_line
from .rate_edge import EdgeEventKind
from .rate_history import RateHistory
from .rate_run import run_rate_continuum
from .state import Event, EventKind
from .tolerances import Tolerances

__all__ = ["run_rate_coulomb", "check_rate_friction_law", "takes_rate_coulomb"]


def takes_rate_coulomb(friction: FrictionLaw) -> bool:
    """Whether the rate-dependent continuum runs ``friction`` spring by spring (a law with Coulomb's part, ``μ = 0``
    included: it was refused inside the run before).

    Parameters
    ----------
    friction : FrictionLaw
        The friction law.

    Returns
    -------
    bool
        Whether :func:`run_rate_coulomb` runs it.
    """
    return friction.law != "tau0"  # (μ = 0 too: the route is exact there; solve_rate_shifts takes τ0's cap alone)


def check_rate_friction_law(friction: FrictionLaw, law: RateDependentAdhesion | None = None) -> None:
    """What the continuum takes under a rate-dependent adhesion law: every friction law (``"tau0"`` by the closed-form
    play, the laws with Coulomb's part spring by spring).

    Parameters
    ----------
    friction : FrictionLaw
        The friction law.
    law : RateDependentAdhesion or None, optional
        The adhesion law (every one is taken).

    Raises
    ------
    TypeError
        Not a :class:`~mdr_events.contact.friction.FrictionLaw`.
    """
    if not isinstance(friction, FrictionLaw):
        raise TypeError(f"friction={shown(friction)} ({type(friction).__name__}) is not allowed; allowed: a "
                        "FrictionLaw")


def _normal_law(friction: FrictionLaw) -> FrictionLaw:
    """The law of the normal run: ``τ0``'s part alone (0 under ``"coulomb"``), whose tangential results are
    replaced."""
    return FrictionLaw("tau0", tau0=friction.tau0 if friction.uses_tau0 and friction.tau0 is not None else 0.0)


def _run_end(run, path: Path, start: float) -> Event:
    """A mark at the run's end (s from first contact): where its contact ended, else the path's end. The springs'
    events are searched in each contact up to its end or, where it lasts, the log's last event
    (:func:`~.play_run.run_play_springs`'s rule): the mark makes that the path's end, not its last corner."""
    end = run.edge.events[-1].time if run.edge.events[-1].kind is EdgeEventKind.CONTACT_ENDS else path.duration
    return Event(float(end - start), EventKind.CORNER, 0.0, 0.0, 0.0, 0)


def run_rate_coulomb(params: Parameters, paths: list[Path], times: np.ndarray | int, tolerances: Tolerances,
                     limits: Limits, profile: SimulatedProfile, friction: FrictionLaw,
                     law: RateDependentAdhesion) -> dict:
    """Solve every path under ``law`` with Coulomb's part, spring by spring (module docstring).

    Parameters
    ----------
    params : Parameters
        The material, ``τ0`` and the works of adhesion at rest (the law's).
    paths : list of Path
        One path per case.
    times : numpy.ndarray or int
        The output times (s from first contact), or the number of samples to the end of the longest run.
    tolerances : Tolerances
        Its ``rtol`` is the edge's ODE tolerance.
    limits : Limits
        The resource limits the output is checked against first.
    profile : PowerLaw, TabulatedProfile or None
        The indenter.
    friction : FrictionLaw
        ``"coulomb"`` or ``"tau0+coulomb"``.
    law : RateDependentAdhesion
        The adhesion law.

    Returns
    -------
    dict
        As :func:`~.rate_run.run_rate_continuum`.
    """
    if friction.uses_tau0 and friction.tau0 is None:
        friction = FrictionLaw(friction.law, mu=friction.mu, tau0=params.tau0)
    raw = run_rate_continuum(params, paths, times, tolerances, limits, profile, _normal_law(friction), law)
    line = spring_line(params, profile, friction)
    for case, (path, run) in enumerate(zip(paths, raw["runs"])):
        play = PlaySprings(line, path, RateHistory(run.edge))
        start = path.first_contact_time()
        radius = raw["contact_radius"][case]
        log = raw["events"][case]
        kept = [event for event in log if event.kind not in _SPRING_EVENTS]
        end = _run_end(run, path, start)
        searched = kept + [end]  # (a contact that lasts to the path's end is searched to it)
        springs = spring_run(play, raw["time"], radius, path, searched, end.time,
                             lambda scan: play.history.radii(scan + start), limits)
        raw["tangential_force"][case] = np.where(np.isnan(raw["tangential_force"][case]), np.nan, springs.force)
        raw["sliding_fraction"][case] = np.where(radius > 0, springs.sliding, np.nan)
        raw["events"][case] = sorted(kept + springs.events, key=lambda event: event.time)
        raw["extrema"][case].update(springs.extrema)
    return raw
